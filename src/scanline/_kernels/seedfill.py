"""Scan-line seed fill with an explicit stack: flood fill, boundary fill, soft fill
(notes, chapter 2, Q.8: "start from a given interior position and paint outward from
this point until we specify the boundary conditions").

One loop serves the three fills; they differ only in the test that says whether a
pixel belongs to the region (``kind``, a token of :mod:`scanline._kernels.variants`:
each fill compiles its own test only) and in how a span is painted:

``FLOOD``
    the pixel's channels lie within ``ref[0]..ref[1]`` (the seed's value minus and
    plus the tolerance, per channel);
``BOUNDARY``
    the pixel is none of the colors in the rows of ``ref``;
``SOFT``
    the pixel is a blend P = t*F + (1 - t)*B of ``F = ref[0]`` and ``B = ref[1]``
    with t > 0 (least-squares t, residual at most ``SOFT_RESIDUAL`` per channel);
    it is repainted t*F' + (1 - t)*B with ``F' = ref[2]``.

Visited pixels are marked in ``mask`` (one byte per pixel), never recognized by their
color: a pixel that already has the fill color, or that still passes the test after
painting, is filled once and the loop ends.
"""

import numpy as np

from ._jit import helper, inline, kernel
from .spans import span
from .variants import PACKED

#: Fill kinds (token lengths).
FLOOD = 1
BOUNDARY = 2
SOFT = 3

#: ``tracing`` tokens: the drawing kernel compiles no step log.
QUIET = 1
TRACING = 2
QUIET_TOKEN = (0,)

#: Soft fill: largest distance, in levels per channel, between a pixel and the blend
#: t*F + (1 - t)*B that best explains it (each stored channel is rounded, so exact
#: blends are within half a level; a level more absorbs the error of t).
SOFT_RESIDUAL = 1.0

#: Columns of a trace step: popped seed x, y; span x_left, x_right (-1, -1 when
#: the seed was already filled); number of seeds pushed.
STEP_COLUMNS = 5


@inline
def bit(buf, x, y):
    """The bit of pixel (x, y) in packed storage."""
    return (buf[y, x >> 3, 0] >> (7 - (x & 7))) & 1


@helper
def classify_row(buf, layout, kind, width, y, ref, todo):
    """Set ``todo[y, x]`` to 1 for the pixels of scan line y that belong to the
    region (see the module doc), 0 for the others."""
    if len(layout) == PACKED:
        for x in range(width):
            v = bit(buf, x, y)
            if len(kind) == BOUNDARY:
                t = 1
                for k in range(ref.shape[0]):
                    if v == ref[k, 0]:
                        t = 0
                todo[y, x] = t
            else:
                todo[y, x] = ref[0, 0] <= v and v <= ref[1, 0]
        return
    n = buf.shape[2]
    if len(kind) == FLOOD:
        flood_row(buf, y, ref, todo)
        return
    for x in range(width):
        t = 1
        if len(kind) == BOUNDARY:
            for k in range(ref.shape[0]):
                same = True
                for c in range(n):
                    if buf[y, x, c] != ref[k, c]:
                        same = False
                if same:
                    t = 0
        else:
            t = blend_fraction(buf, x, y, ref) > 0.0
        todo[y, x] = t


@helper
def flood_row(buf, y, ref, todo):
    """The flood fill's test on scan line y of byte storage: ``todo[y, x]`` = 1 where
    every channel lies within ``ref[0]..ref[1]``.  The bounds are read once, into
    numbers (a store to ``todo`` could alias ``ref`` for all LLVM knows: read in the
    loop, they were loaded again at every pixel), the test has no branch and the
    indices are unsigned (no wrap-around of negative indices)."""
    n = buf.shape[2]
    lo0 = ref[0, 0]
    hi0 = ref[1, 0]
    lo1 = ref[0, 1] if n > 1 else lo0
    hi1 = ref[1, 1] if n > 1 else hi0
    lo2 = ref[0, 2] if n > 2 else lo0
    hi2 = ref[1, 2] if n > 2 else hi0
    lo3 = ref[0, 3] if n > 3 else lo0
    hi3 = ref[1, 3] if n > 3 else hi0
    row = np.uint64(y)
    for x in range(np.uint64(todo.shape[1])):
        v = buf[row, x, 0]
        t = (v >= lo0) & (v <= hi0)
        if n > 1:
            v = buf[row, x, 1]
            t &= (v >= lo1) & (v <= hi1)
            v = buf[row, x, 2]
            t &= (v >= lo2) & (v <= hi2)
        if n > 3:
            v = buf[row, x, 3]
            t &= (v >= lo3) & (v <= hi3)
        todo[row, x] = t


@helper
def blend_fraction(buf, x, y, ref):
    """Soft fill: t = (P - B).(F - B) / |F - B|**2 clipped to 1 for pixel P, if
    t > 0 and P is within SOFT_RESIDUAL of t*F + (1 - t)*B in every channel; else 0."""
    n = buf.shape[2]
    dot = 0.0
    norm = 0.0
    for c in range(n):
        d = float(ref[0, c] - ref[1, c])
        dot += (float(buf[y, x, c]) - ref[1, c]) * d
        norm += d * d
    if dot <= 0.0:
        return 0.0
    t = min(dot / norm, 1.0)
    for c in range(n):
        r = float(buf[y, x, c]) - ref[1, c] - t * (ref[0, c] - ref[1, c])
        if abs(r) > SOFT_RESIDUAL:
            return 0.0
    return t


@helper
def soft_span(buf, y, x0, x1, ref):
    """Repaint pixels x0..x1 of scan line y as round(t*F' + (1 - t)*B), t each
    pixel's blend fraction (all of them are members: t > 0)."""
    n = buf.shape[2]
    for x in range(x0, x1 + 1):
        t = blend_fraction(buf, x, y, ref)
        for c in range(n):
            buf[y, x, c] = np.uint8(np.floor(ref[1, c] + t * (ref[2, c] - ref[1, c]) + 0.5))


@helper
def classify_near(buf, layout, kind, width, height, y, ref, todo, ready):
    """Classify scan lines y - 1, y and y + 1 (those on the raster) on first use;
    ``ready[y]`` records that row y is done.  Each row is tested once, before any of
    its pixels is painted, in one tight loop."""
    for r in range(max(y - 1, 0), min(y + 1, height - 1) + 1):
        if ready[r] == 0:
            ready[r] = 1
            classify_row(buf, layout, kind, width, r, ref, todo)


@helper
def enlarged(a, used, need):
    """``a`` if it has at least ``need`` rows, else a copy with twice as many (or
    ``need``) rows, its first ``used`` rows kept: the stack and the trace logs have no
    fixed limit.  (Called once per span, outside the pixel loops: reassigning an array
    inside them made the loop five times slower.)"""
    if need <= a.shape[0]:
        return a
    b = np.empty((max(2 * a.shape[0], need), a.shape[1]), a.dtype)
    for i in range(used):     # (element by element: slice assignments compile an error
        for c in range(a.shape[1]):   # message, seconds of first-call compilation)
            b[i, c] = a[i, c]
    return b


@helper
def seed_loop(buf, layout, kind, width, height, x0, y0, eight, ref, color, tracing):
    """Fill the region of seed (x0, y0); return the number of pixels filled and, when
    ``tracing`` is the TRACING token, the step log (rows of STEP_COLUMNS: popped seed
    x, y; span x_left, x_right, or -1, -1 when the seed was filled already; number of
    seeds pushed) and the seeds pushed, in order.

    ``todo[y, x]`` is 1 for a region pixel not yet filled.  Pop a seed; if it is
    still to be filled, extend it left and right to the ends of its span, paint the
    span and clear its ``todo``, then scan the row above and the row below over
    x_left..x_right (one pixel further each way when ``eight``) and push the
    rightmost pixel of each run still to be filled.

    The steps are written out in this one loop: moved into a helper (inlined either
    way) they ran 2.5 to 3 times slower.  One step pushes at most ``width + 2``
    seeds, so the inner loop runs while that much room is left in the stack (and in
    the logs) and the arrays are enlarged between its runs: reassigning an array
    inside the inner loop, even in a branch never taken, made it 25% slower.  The
    span is painted here too, by the fill's own painting (its token folds the
    other away): through a helper, a call a span that passed some thirty numbers,
    the flood fill of a 4096 x 4096 maze took 1.10x the time in RGB and 1.27x in gray
    (in turn in one process, 2026-12-07).
    """
    todo = np.zeros((height, width), np.uint8)
    ready = np.zeros(height, np.uint8)
    stack = np.empty((width + 256, 2), np.int64)
    stack[0, 0] = x0
    stack[0, 1] = y0
    top = np.int64(1)     # (int64s, not literals: ``enlarged`` compiles once)
    count = 0
    logging = len(tracing) == TRACING
    steps = np.empty((16 if logging else 0, STEP_COLUMNS), np.int64)
    pushed = np.empty((16 if logging else 0, 2), np.int64)
    nsteps = np.int64(0)
    npushed = np.int64(0)
    while top > 0:
        stack = enlarged(stack, top, top + width + 2)
        if len(tracing) == TRACING:
            steps = enlarged(steps, nsteps, nsteps + 1)
            pushed = enlarged(pushed, npushed, npushed + width + 2)
        room = stack.shape[0] - width - 2
        while 0 < top <= room and (not logging or (
                nsteps < steps.shape[0] and npushed + width + 2 <= pushed.shape[0])):
            top -= 1
            before = top
            x = stack[top, 0]
            y = stack[top, 1]
            if ready[max(y - 1, 0)] == 0 or ready[y] == 0 or ready[min(y + 1, height - 1)] == 0:
                classify_near(buf, layout, kind, width, height, y, ref, todo, ready)
            xl = -1
            xr = -1
            if todo[y, x] != 0:
                xl = x
                while xl > 0 and todo[y, xl - 1] != 0:
                    xl -= 1
                xr = x
                while xr < width - 1 and todo[y, xr + 1] != 0:
                    xr += 1
                if len(kind) == SOFT:
                    soft_span(buf, y, xl, xr, ref)
                else:
                    span(buf, layout, width, height, y, xl, xr, color)
                for i in range(xl, xr + 1):
                    todo[y, i] = 0
                count += xr - xl + 1
                a = max(xl - eight, 0)
                b = min(xr + eight, width - 1)
                for side in range(2):
                    ny = y + 1 - 2 * side
                    if ny < 0 or ny >= height:
                        continue
                    i = a
                    while i <= b:
                        if todo[ny, i] != 0:
                            while i < b and todo[ny, i + 1] != 0:
                                i += 1
                            stack[top, 0] = i
                            stack[top, 1] = ny
                            top += 1
                        i += 1
            if len(tracing) == TRACING:
                steps[nsteps, 0] = x
                steps[nsteps, 1] = y
                steps[nsteps, 2] = xl
                steps[nsteps, 3] = xr
                steps[nsteps, 4] = top - before
                nsteps += 1
                for i in range(before, top):
                    pushed[npushed, 0] = stack[i, 0]
                    pushed[npushed, 1] = stack[i, 1]
                    npushed += 1
    return count, steps[:nsteps], pushed[:npushed]


@kernel
def seed_fill(buf, layout, kind, width, height, x0, y0, eight, ref, color):
    """The seed fill ``kind`` (a fill token) from seed (x0, y0), which must be on the
    raster; return the number of pixels filled.  (The step tables run
    :func:`seed_loop` as Python with the TRACING token.)"""
    return seed_loop(buf, layout, kind, width, height, x0, y0, eight, ref, color, QUIET_TOKEN)[0]
