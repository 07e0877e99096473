"""Fractal kernels (Hearn & Baker, sections 10-18 and 10-19): the escape-time loop of
the self-squaring fractals (Mandelbrot and Julia sets), the chaos game of an iterated
function system, and the turtle that draws an L-system's string.

Every loop bound comes from the arrays' own shapes, and every index into a table is
taken modulo its length or checked by the API layer first (:mod:`scanline.fractals`):
no input reaches outside the arrays.
"""

import math

from ._jit import helper, kernel


@helper
def escape_step(zr, zi, cr, ci):
    """One step of z -> z² + c: (z', False), or (z, True) when |z|² > 4 already."""
    zr2 = zr * zr
    zi2 = zi * zi
    if zr2 + zi2 > 4.0:
        return zr, zi, True
    return zr2 - zi2 + cr, 2.0 * zr * zi + ci, False


@kernel
def escape_times(start, step, xs, ys, cr, ci, julia, max_iterations, out):
    """Iteration counts of z -> z² + c on rows ``start``, ``start + step``, ... (one
    call per thread, :func:`scanline._kernels._threads.call_in_bands`: interleaved
    rows share the slow rows near the set among the threads).

    Pixel (row r, column k) stands for the complex number xs[k] + i ys[r].  For the
    Mandelbrot set (``julia`` false) c is that number and z starts at 0; for a
    Julia set c = cr + i ci and z starts at the pixel.  ``out[r, k]`` is the number
    of iterations made while |z| <= 2 (|z|² <= 4), at most ``max_iterations``:
    max_iterations means "did not escape" (in the set, as far as this count can
    tell).

    Four neighboring pixels of a row iterate together, each in its own variables
    (a pixel that escaped stops): one pixel's steps are a chain of dependent
    multiplications, and four independent chains keep the processor's pipelines
    full (4x the one-pixel loop, measured).  Each pixel's arithmetic is the
    one-pixel loop's, so the counts are the same, and the same whatever the number
    of threads.
    """
    height = min(ys.shape[0], out.shape[0])
    width = min(xs.shape[0], out.shape[1])
    for r in range(start, height, step):
        y = ys[r]
        for k0 in range(0, width, 4):
            m = min(4, width - k0)
            x0 = xs[k0]
            x1 = xs[min(k0 + 1, width - 1)]
            x2 = xs[min(k0 + 2, width - 1)]
            x3 = xs[min(k0 + 3, width - 1)]
            if julia:
                zr0, zr1, zr2, zr3 = x0, x1, x2, x3
                zi0 = zi1 = zi2 = zi3 = y
                cr0 = cr1 = cr2 = cr3 = cr
                c_i = ci
            else:
                zr0 = zr1 = zr2 = zr3 = 0.0
                zi0 = zi1 = zi2 = zi3 = 0.0
                cr0, cr1, cr2, cr3 = x0, x1, x2, x3
                c_i = y
            a0, a1, a2, a3 = True, m > 1, m > 2, m > 3
            n0 = n1 = n2 = n3 = max_iterations
            n = 0
            while n < max_iterations and (a0 or a1 or a2 or a3):
                if a0:
                    zr0, zi0, escaped = escape_step(zr0, zi0, cr0, c_i)
                    if escaped:
                        a0 = False
                        n0 = n
                if a1:
                    zr1, zi1, escaped = escape_step(zr1, zi1, cr1, c_i)
                    if escaped:
                        a1 = False
                        n1 = n
                if a2:
                    zr2, zi2, escaped = escape_step(zr2, zi2, cr2, c_i)
                    if escaped:
                        a2 = False
                        n2 = n
                if a3:
                    zr3, zi3, escaped = escape_step(zr3, zi3, cr3, c_i)
                    if escaped:
                        a3 = False
                        n3 = n
                n += 1
            out[r, k0] = n0
            if m > 1:
                out[r, k0 + 1] = n1
            if m > 2:
                out[r, k0 + 2] = n2
            if m > 3:
                out[r, k0 + 3] = n3


@kernel
def chaos_game(maps, choices, x0, y0, skip, out):
    """Barnsley's chaos game: from (x0, y0), apply the affine map ``maps[choices[i]]``
    (rows a b e / c d f: x' = a x + b y + e, y' = c x + d y + f) for each i in turn;
    the points after the first ``skip`` go to ``out`` in order.  A choice outside
    the maps is taken modulo their number."""
    m = maps.shape[0]
    x, y = x0, y0
    j = 0
    for i in range(choices.shape[0]):
        t = choices[i] % m
        nx = maps[t, 0, 0] * x + maps[t, 0, 1] * y + maps[t, 0, 2]
        ny = maps[t, 1, 0] * x + maps[t, 1, 1] * y + maps[t, 1, 2]
        x, y = nx, ny
        if i >= skip and j < out.shape[0]:
            out[j, 0] = x
            out[j, 1] = y
            j += 1
    return j


@kernel
def turtle(codes, step, angle, x0, y0, heading, cosines, sines, points, starts, stack):
    """Draw an L-system string with a turtle (Prusinkiewicz & Lindenmayer, chapter 1).

    ``codes``: 1 = move forward drawing, 2 = move forward without drawing (a new
    polyline starts), 3 = turn left by ``angle``, 4 = turn right, 5 = push the state,
    6 = pop it (a new polyline starts at the popped point), 7 = turn around,
    0 = do nothing.  Headings are counted in turns of ``angle`` from ``heading``:
    where ``cosines`` has entries (the angle divides the full turn into
    len(cosines) directions), the direction of turn count t is the table's entry t
    mod len(cosines), exact for the right angles; otherwise it is computed.

    Points go to ``points``; polyline p is points[starts[p]:starts[p + 1]].
    ``stack`` holds (x, y, turn count) of the open branches.  The API layer sizes
    the arrays from the string; writes past them are skipped all the same.
    Returns (number of points, number of polylines).
    """
    n_dirs = cosines.shape[0]
    half = n_dirs // 2
    x, y = x0, y0
    t = 0
    depth = 0
    count = 0
    lines = 0
    fresh = True                      # the next F begins a polyline at (x, y)
    for i in range(codes.shape[0]):
        c = codes[i]
        if c == 1 or c == 2:
            if n_dirs > 0:
                d = t % n_dirs
                dx, dy = cosines[d], sines[d]
            else:
                a = heading + t * angle
                dx, dy = math.cos(a), math.sin(a)
            if c == 2:
                x += step * dx
                y += step * dy
                fresh = True
                continue
            if fresh:
                if lines < starts.shape[0] and count < points.shape[0]:
                    starts[lines] = count
                    points[count, 0] = x
                    points[count, 1] = y
                    lines += 1
                    count += 1
                fresh = False
            x += step * dx
            y += step * dy
            if count < points.shape[0]:
                points[count, 0] = x
                points[count, 1] = y
                count += 1
        elif c == 3:
            t += 1
        elif c == 4:
            t -= 1
        elif c == 7:
            t += half if n_dirs > 0 else 0
            if n_dirs == 0:
                heading += math.pi
        elif c == 5:
            if depth < stack.shape[0]:
                stack[depth, 0] = x
                stack[depth, 1] = y
                stack[depth, 2] = t
            depth += 1
        elif c == 6:
            if depth > 0:
                depth -= 1
                if depth < stack.shape[0]:
                    x = stack[depth, 0]
                    y = stack[depth, 1]
                    t = int(stack[depth, 2])
                fresh = True
    if lines < starts.shape[0]:
        starts[lines] = count
    return count, lines
