"""Line scan conversion: DDA and Bresenham (notes, chapter 2, Q.1-Q.3).

Both kernels work in every octant by naming the axes: ``u`` is the major axis (the one
stepped by one pixel per iteration) and ``w`` the minor axis.  Lines are clipped to
the frame buffer before the loop starts, so a line from -10**9 to 10**9 costs only the
pixels that can be seen; the per-pixel bounds check in ``put`` makes any error in that
clipping harmless.
"""

import math

import numpy as np

from ._jit import helper, inline, kernel
from .raster import channels, put, store_flat
from .spans import strip
from .variants import PACKED

#: Methods (token lengths, :mod:`scanline._kernels.variants`).
BRESENHAM = 1
DDA = 2

#: A DDA line clipped at its start replays up to this many invisible steps, so that
#: its pixels carry exactly the round-off of the unclipped line (and of its trace);
#: beyond it the start is computed as x0 + lo * dx/steps.
DDA_REPLAY = 1 << 22


@helper
def step_range(u0, su, du, w0, sw, dw, umax, wmax):
    """Steps ``i`` in [0, du] whose pixel (u0 + su*i, w0 + sw*i*dw/du) may lie in
    [0, umax] x [0, wmax]; a conservative ``(lo, hi)``, empty when ``lo > hi``."""
    if su > 0:
        lo = max(0, -u0)
        hi = min(du, umax - u0)
    else:
        lo = max(0, u0 - umax)
        hi = min(du, u0)
    if lo > hi:
        return 1, 0
    if dw == 0:
        if w0 < 0 or w0 > wmax:
            return 1, 0
        return lo, hi
    slope = du / dw
    if sw > 0:
        a = (-w0 - 1) * slope
        b = (wmax - w0 + 1) * slope
    else:
        a = (w0 - wmax - 1) * slope
        b = (w0 + 1) * slope
    a = max(a, -1.0)
    b = min(b, du + 1.0)
    lo = max(lo, int(math.floor(a)) - 1)
    hi = min(hi, int(math.ceil(b)) + 1)
    return lo, hi


@inline
def bresenham_setup(x0, y0, x1, y1):
    """Name the axes as the notes' algorithm needs them.

    Returns ``(swap, u0, w0, du, dw, sw)``: the line starts at its left endpoint when
    x is the major axis (|dy| <= |dx|, notes: "store the left end point in (x0, y0)")
    and at its lower endpoint when y is (``swap``); ``du >= dw >= 0`` and ``sw`` is the
    direction (+1 or -1) of the minor axis.
    """
    swap = abs(y1 - y0) > abs(x1 - x0)
    # selects, not branches: the axis and the endpoint order of random lines are
    # coin flips, which a branch predictor misses half the time
    a0 = y0 if swap else x0
    a1 = y1 if swap else x1
    b0 = x0 if swap else y0
    b1 = x1 if swap else y1
    rev = a0 > a1
    u0 = a1 if rev else a0
    w0 = b1 if rev else b0
    w1 = b0 if rev else b1
    return swap, u0, w0, abs(a1 - a0), abs(w1 - w0), 1 if w1 >= w0 else -1


@helper
def bresenham_decide(p, two_dw, two_dw_minus_two_du):
    """One step of the notes' decision: if p_k < 0 keep the minor coordinate and
    add 2dy, otherwise advance it and add 2dy - 2dx.  Returns (p_k+1, advance)."""
    if p < 0:
        return p + two_dw, 0
    return p + two_dw_minus_two_du, 1


@inline
def bresenham_state(i, du, dw):
    """The loop's state after ``i`` steps, in closed form: the minor offset
    j_i = floor((2*dw*i + du) / (2*du)) and p_i = 2dw(i+1) - du - 2du*j_i, computed
    without overflow for du, dw, i < 2**31."""
    if du == 0:
        return 0, 2 * dw - du
    q = (dw * i) // du
    r = dw * i - q * du
    t = (2 * r + du) // (2 * du)
    return q + t, 2 * dw + 2 * r - 2 * du * t - du


@helper
def bresenham_first(target, du, dw):
    """Smallest step i in [0, du] with j_i >= target (du + 1 if there is none)."""
    if target <= 0:
        return 0
    if target > dw:
        return du + 1
    # j_i >= J  <=>  i >= (2 du J - du) / (2 dw); estimate in floating point (the
    # exact product can reach 2**63), then settle it with the exact j_i.
    i = min(max(int(math.ceil((target - 0.5) * du / dw)), 0), du)
    while i > 0 and bresenham_state(i - 1, du, dw)[0] >= target:
        i -= 1
    while bresenham_state(i, du, dw)[0] < target:
        i += 1
    return i


@helper
def bresenham_clip(u0, w0, du, dw, sw, umax, wmax):
    """The exact range of steps ``(lo, hi)`` whose pixels lie in [0, umax] x
    [0, wmax] (empty when lo > hi).  Both coordinates are monotone along the line,
    so the pixels between two visible pixels are visible too."""
    lo = max(0, -u0)
    hi = min(du, umax - u0)
    if sw > 0:
        j_lo, j_hi = -w0, wmax - w0
    else:
        j_lo, j_hi = w0 - wmax, w0
    if j_lo > j_hi or lo > hi:
        return 1, 0
    lo = max(lo, bresenham_first(j_lo, du, dw))
    hi = min(hi, bresenham_first(j_hi + 1, du, dw) - 1)
    return lo, hi


@helper
def bresenham_checked(buf, layout, width, height, swap, u0, w0, sw, lo, hi, j, p,
                      two_dw, two_dw_minus_two_du, color):
    """The Bresenham loop over steps lo..hi, each pixel written through ``put``."""
    for i in range(lo, hi + 1):
        if swap:
            put(buf, layout, width, height, w0 + sw * j, u0 + i, color)
        else:
            put(buf, layout, width, height, u0 + i, w0 + sw * j, color)
        p, advance = bresenham_decide(p, two_dw, two_dw_minus_two_du)
        j += advance


#: Lines of at most this many pixels end their loop at the last pixel's byte, longer
#: ones after a count (:func:`bresenham_walk`).  In turn in one process on one core
#: (2026-12-08): a million short lines (up to 32 pixels) 1.07-1.13x as fast with the
#: loop that ends at the byte, 10,000 long ones (endpoints anywhere on 4096 x 4096)
#: 0.74-0.79x, hence the count for those.
SHORT_LINE = 32


@inline
def bresenham_pixel(flat, k, p, two_dw, two_dw_minus_two_du, su, sv, n, c0, c1, c2, c3):
    """Store the pixel at byte ``k`` and take one step: ``(k, p)`` of the next."""
    store_flat(flat, k, n, c0, c1, c2, c3)
    keep = p < 0
    return k + (su if keep else su + sv), p + (two_dw if keep else two_dw_minus_two_du)


@helper
def bresenham_walk(flat, k, steps, klast, p, two_dw, two_dw_minus_two_du, su, sv, n,
                   c0, c1, c2, c3):
    """The Bresenham loop over unpacked storage seen as one flat array: ``steps``
    pixels of ``n`` channels (1, 3 or 4) from byte ``k``, unchecked (the caller has
    proved the first and last pixels inside, and the pixels between them are
    inside by monotonicity).

    A step along the major axis adds ``su`` bytes (one pixel, or one row when y
    is the major axis), an advance of the minor axis ``sv`` more.  The decision is
    :func:`bresenham_decide`'s, written as two selects that compile without a
    branch: a branch on the sign of p_k is mispredicted about once in three pixels
    of a random line.  The pixel is stored by :func:`~scanline._kernels.raster.store_flat`
    (unsigned offsets, no wrap-around of negative indices).  The color comes as
    scalars, so that the per-line loop of :func:`draw_lines` holds no array but
    ``flat`` (an array used anywhere in that loop, even in a branch not taken, cost a
    reference-count increment and decrement per line: atomic operations that took
    30% of the time of a million short lines).

    A line of up to :data:`SHORT_LINE` pixels ends at its last pixel's byte, ``k +
    (steps - 1) * su + klast`` (``klast``: the minor axis's share of the way in
    bytes, signed), not after a count: LLVM unrolls a counted loop by eight behind a
    remainder loop, and a short line then ends two loops whose exits the branch
    predictor misses.  A line's pixels are distinct, so the last byte is met once,
    where the count would have ended.  A longer line keeps the counted loop."""
    if steps > SHORT_LINE:
        for _ in range(steps):
            k, p = bresenham_pixel(flat, k, p, two_dw, two_dw_minus_two_du, su, sv, n,
                                   c0, c1, c2, c3)
        return
    if steps <= 0:
        return
    last = k + (steps - 1) * su + klast
    while k != last:
        k, p = bresenham_pixel(flat, k, p, two_dw, two_dw_minus_two_du, su, sv, n,
                               c0, c1, c2, c3)
    store_flat(flat, last, n, c0, c1, c2, c3)


@inline
def bresenham_span(x0, y0, x1, y1, width, height, n, row):
    """The state of :func:`bresenham_walk` for the line (x0, y0)-(x1, y1) clipped
    exactly to a raster of ``width`` x ``height`` pixels of ``n`` bytes, ``row``
    bytes per row: ``(k, steps, klast, p, two_dw, two_dw_minus_two_du, su, sv)``,
    with ``steps`` 0 when no pixel is visible.  Scalars only (see
    :func:`bresenham_walk`), chosen by selects, not branches (as in
    :func:`bresenham_setup`; with it, 1.05-1.10x as fast on a million short lines)."""
    swap, u0, w0, du, dw, sw = bresenham_setup(x0, y0, x1, y1)
    if 0 <= min(x0, x1) and max(x0, x1) < width and 0 <= min(y0, y1) and max(y0, y1) < height:
        # wholly inside (most lines): no clipping, no divisions (the values unify
        # with the other branch's into int64 variables)
        lo, hi, j, p, w_last = 0, du, 0, 2 * dw - du, w0 + sw * dw
    else:
        if swap:
            lo, hi = bresenham_clip(u0, w0, du, dw, sw, height - 1, width - 1)
        else:
            lo, hi = bresenham_clip(u0, w0, du, dw, sw, width - 1, height - 1)
        if lo > hi:
            lo, hi = 0, -1
        j, p = bresenham_state(lo, du, dw)
        w_last = w0 + sw * bresenham_state(hi, du, dw)[0]
    w_first = w0 + sw * j
    wlim = width if swap else height
    ulim = height if swap else width
    if not (lo <= hi and 0 <= u0 + lo < ulim and 0 <= u0 + hi < ulim and 0 <= w_first < wlim
            and 0 <= w_last < wlim):
        return 0, 0, 0, p, 2 * dw, 2 * dw - 2 * du, 0, 0
    su = row if swap else n         # (selects: see bresenham_setup)
    sv = n if swap else row
    k = (u0 + lo) * su + w_first * sv
    return (k, hi - lo + 1, (w_last - w_first) * sv, p, 2 * dw, 2 * dw - 2 * du, su,
            sw * sv)


@helper
def bresenham_line(buf, layout, width, height, x0, y0, x1, y1, colors, ci):
    """Draw the line (x0, y0)-(x1, y1), both endpoints included, with Bresenham's
    integer decision parameter, clipped exactly to the frame buffer, in color
    ``colors[ci]``."""
    if len(layout) == PACKED:
        swap, u0, w0, du, dw, sw = bresenham_setup(x0, y0, x1, y1)
        if swap:
            lo, hi = bresenham_clip(u0, w0, du, dw, sw, height - 1, width - 1)
        else:
            lo, hi = bresenham_clip(u0, w0, du, dw, sw, width - 1, height - 1)
        if lo <= hi:
            j, p = bresenham_state(lo, du, dw)
            bresenham_checked(buf, layout, width, height, swap, u0, w0, sw, lo, hi, j, p,
                              2 * dw, 2 * dw - 2 * du, colors[ci])
        return
    n = buf.shape[2]
    k, steps, klast, p, a, b, su, sv = bresenham_span(x0, y0, x1, y1, width, height, n,
                                                      buf.shape[1] * n)
    c0, c1, c2, c3 = channels(colors, ci)
    bresenham_walk(buf.reshape(-1), k, steps, klast, p, a, b, su, sv, n, c0, c1, c2, c3)


@inline
def nearest(v):
    """Round half up to the nearest integer: the notes' round()."""
    return int(math.floor(v + 0.5))


@helper
def dda_setup(x0, y0, x1, y1):
    """Steps and increments of the DDA: ``steps = max(|dx|, |dy|)`` and the
    per-step increments dx/steps, dy/steps (one of them is +-1)."""
    dx = x1 - x0
    dy = y1 - y0
    steps = max(abs(dx), abs(dy))
    if steps == 0:
        return 0, 0.0, 0.0
    return steps, dx / steps, dy / steps


@helper
def dda_line(buf, layout, width, height, x0, y0, x1, y1, color):
    """Draw the line (x0, y0)-(x1, y1) with the DDA: x and y are real numbers
    incremented by dx/steps and dy/steps from the first endpoint, and each point is
    rounded to the nearest pixel."""
    steps, xinc, yinc = dda_setup(x0, y0, x1, y1)
    if abs(x1 - x0) >= abs(y1 - y0):
        lo, hi = step_range(x0, 1 if x1 >= x0 else -1, steps, y0, 1 if y1 >= y0 else -1,
                            abs(y1 - y0), width - 1, height - 1)
    else:
        lo, hi = step_range(y0, 1 if y1 >= y0 else -1, steps, x0, 1 if x1 >= x0 else -1,
                            abs(x1 - x0), height - 1, width - 1)
    if lo > hi:
        return
    x = float(x0)
    y = float(y0)
    if lo <= DDA_REPLAY:  # replay the invisible steps: the same round-off as unclipped
        for _ in range(lo):
            x += xinc
            y += yinc
    else:  # a start far outside: jump (round-off may then differ at exact halves)
        x += lo * xinc
        y += lo * yinc
    for _ in range(lo, hi + 1):
        put(buf, layout, width, height, nearest(x), nearest(y), color)
        x += xinc
        y += yinc


@kernel
def draw_line(buf, layout, width, height, x0, y0, x1, y1, color, method):
    """Draw one line; ``layout`` and ``method`` (BRESENHAM or DDA) are tokens
    (:mod:`scanline._kernels.variants`): only the method used is compiled."""
    if len(method) == DDA:
        dda_line(buf, layout, width, height, x0, y0, x1, y1, color)
    else:
        bresenham_line(buf, layout, width, height, x0, y0, x1, y1,
                       color.reshape(1, color.shape[0]), np.int64(0))   # (not a literal 0)


@kernel
def draw_lines(band, step, buf, layout, width, height, segments, colors, method):
    """Draw N lines, ``segments[i] = (x0, y0, x1, y1)``, with ``colors[i]`` (or
    ``colors[0]`` for all when ``colors`` has one row), in order.

    Bresenham's lines are drawn into strip ``band`` of ``step`` of the rows only
    (:func:`scanline._kernels.spans.strip`; one call per thread,
    :func:`scanline._kernels._threads.call_in_bands`): each line that reaches the
    strip is drawn into a view of ``buf`` whose row 0 is the strip's first row, the
    line moved up by as many rows and clipped exactly to the strip -- Bresenham's
    pixels move with the endpoints, so the pixels kept are the line's own.  Every
    pixel is written by one call, in the batch's order.  The DDA is one call
    (``step`` 1): its round-off depends on the absolute coordinates."""
    one = colors.shape[0] == 1
    if len(method) == DDA:
        for i in range(segments.shape[0]):
            dda_line(buf, layout, width, height, segments[i, 0], segments[i, 1],
                     segments[i, 2], segments[i, 3], colors[0 if one else i])
        return
    top, rows = strip(band, step, height)
    if rows <= 0:
        return
    view = buf[top:top + rows]
    if len(layout) == PACKED:
        for i in range(segments.shape[0]):
            y0 = segments[i, 1] - top
            y1 = segments[i, 3] - top
            if max(y0, y1) >= 0 and min(y0, y1) < rows:
                bresenham_line(view, layout, width, rows, segments[i, 0], y0, segments[i, 2],
                               y1, colors, 0 if one else i)
        return
    # unpacked storage: the loop hands bresenham_walk no array but the strip's
    # (an array in any branch of the loop costs reference counting on every line)
    flat = view.reshape(-1)
    n = buf.shape[2]
    row = buf.shape[1] * n
    c0, c1, c2, c3 = channels(colors, np.int64(0))   # (not a literal 0: compiled once)
    for i in range(segments.shape[0]):
        y0 = segments[i, 1] - top
        y1 = segments[i, 3] - top
        if max(y0, y1) < 0 or min(y0, y1) >= rows:
            continue
        if not one:
            c0, c1, c2, c3 = channels(colors, i)
        k, steps, klast, p, a, b, su, sv = bresenham_span(segments[i, 0], y0, segments[i, 2],
                                                          y1, width, rows, n, row)
        bresenham_walk(flat, k, steps, klast, p, a, b, su, sv, n, c0, c1, c2, c3)


@kernel
def bresenham_trace(x0, y0, x1, y1, out):
    """Fill ``out`` (shape (du, 4), int64) with the notes' table: for k = 0 ..
    du-1 the decision parameter p_k, the pixel (x_k+1, y_k+1) it selects, and the
    increment added to p.  Returns ``(swap, u0, w0, du, dw, sw)``."""
    swap, u0, w0, du, dw, sw = bresenham_setup(x0, y0, x1, y1)
    j, p = bresenham_state(0, du, dw)
    two_dw = 2 * dw
    two_dw_minus_two_du = 2 * dw - 2 * du
    for k in range(du):
        p_next, advance = bresenham_decide(p, two_dw, two_dw_minus_two_du)
        j += advance
        u = u0 + k + 1
        w = w0 + sw * j
        out[k, 0] = p
        out[k, 1] = w if swap else u
        out[k, 2] = u if swap else w
        out[k, 3] = p_next - p
        p = p_next
    return swap, u0, w0, du, dw, sw


@kernel
def dda_trace(x0, y0, x1, y1, out):
    """Fill ``out`` (shape (steps + 1, 4), float64) with the DDA's real x and y at
    k = 0 .. steps (k = 0 is the first endpoint) and the pixel they round to.
    Returns (steps, xinc, yinc)."""
    steps, xinc, yinc = dda_setup(x0, y0, x1, y1)
    x = float(x0)
    y = float(y0)
    for k in range(steps + 1):
        out[k, 0] = x
        out[k, 1] = y
        out[k, 2] = nearest(x)
        out[k, 3] = nearest(y)
        x += xinc
        y += yinc
    return steps, xinc, yinc
