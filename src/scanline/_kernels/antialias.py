"""Antialiased thin lines and conic outlines after Wu (1991): along the major axis,
each column's intensity is split between the pixels that straddle the ideal curve
in proportion to how much of the 1-pixel-wide curve falls in each.

The *column span.*  A line of slope m (|m| <= 1 against its major axis u) and
width 1 cuts the column of pixels at u in a segment of length
``k = sqrt(1 + m**2)`` along the minor axis w, centered on the ideal line.  Each
pixel of the column receives the part of that segment inside it: for an
axis-aligned line (k = 1) exactly Wu's two intensities ``1 - f`` and ``f`` (f the
fractional distance past the nearer pixel center); for a steeper line the segment
is longer and may touch three pixels.  This corrects the classic algorithm's one
defect, diagonal lines drawn dimmer than axis-aligned ones (Wu's unit intensity
per column gives a 45-degree line 1/sqrt(2) of its length): the intensities of a
column add up to k times the column's share of the line, so the total intensity of
a line is its length, at every slope.

*Endpoints* are real numbers.  Column u covers [u - 1/2, u + 1/2); the segment's
part in it is ``[max(u0, u - 1/2), min(u1, u + 1/2)]``, whose length scales the
column's intensities (Wu's end-point "gap" factors, exact) and whose midpoint is
where the ideal line is evaluated.  A line of zero length draws nothing.

*Conics* (circles are ellipses with rx = ry) are split where the slope is +-1,
at x = +-rx**2 / sqrt(rx**2 + ry**2) (and y = +-ry**2 / sqrt(rx**2 + ry**2)):
between those points the top and bottom arcs are x-major and stepped by columns,
the left and right arcs y-major and stepped by rows, each column or row getting the
column span of the local slope.  The total intensity is the ellipse's perimeter up
to the midpoint rule's error.

Each pixel is composited with :func:`scanline._kernels.blend.over` (effective
alpha = intensity x the color's alpha), inlined with the frame-buffer mode as a
constant (the kernels branch on the mode once, outside the loops).  Loops run over
the columns (rows) inside the raster only and clamp the rows of each column span
to it: nothing is written outside ``buf`` whatever the coordinates.

References
----------
X. Wu, "An efficient antialiasing technique", SIGGRAPH '91, Computer Graphics
25(4), 143-152, 1991.
"""

import math

import numpy as np

from ._jit import helper, inline, kernel
from .blend import GRAY, INDEXED, RGB, RGBA, over
from .raster import band_sorted


@inline
def column(buf, mode, table, width, height, swap, u, wc, half, weight, src):
    """Composite the column span [wc - half, wc + half] of column (row, if
    ``swap``) ``u``, intensities scaled by ``weight``."""
    a = wc - half
    b = wc + half
    j0 = max(math.floor(a + 0.5), 0)
    j1 = min(math.ceil(b + 0.5) - 1, (width if swap else height) - 1)
    for j in range(j0, j1 + 1):
        cover = (min(b, j + 0.5) - max(a, j - 0.5)) * weight
        if swap:
            over(buf, mode, table, j, u, src, cover)
        else:
            over(buf, mode, table, u, j, src, cover)


@inline
def wu_line(buf, mode, table, width, height, x0, y0, x1, y1, src):
    """Composite the antialiased line (x0, y0)-(x1, y1) (real coordinates)."""
    swap = abs(y1 - y0) > abs(x1 - x0)
    if swap:
        u0, w0, u1, w1 = y0, x0, y1, x1
        umax, wmax = height, width
    else:
        u0, w0, u1, w1 = x0, y0, x1, y1
        umax, wmax = width, height
    if u0 > u1:
        u0, w0, u1, w1 = u1, w1, u0, w0
    du = u1 - u0
    if not du > 0.0:
        return
    m = (w1 - w0) / du
    half = 0.5 * math.sqrt(1.0 + m * m)
    # the part of [u0, u1] over the raster's columns and within reach of its rows
    ua = max(u0, -0.5)
    ub = min(u1, umax - 0.5)
    if m != 0.0:
        ta = u0 + (-1.0 - half - w0) / m
        tb = u0 + (wmax + half - w0) / m
        ua = max(ua, min(ta, tb))
        ub = min(ub, max(ta, tb))
    elif not (-1.0 - half < w0 < wmax + half):
        return
    if not ua < ub:
        return
    i0 = max(math.floor(ua + 0.5), 0)
    i1 = min(math.ceil(ub + 0.5) - 1, umax - 1)
    if swap:
        columns(buf, mode, table, width, height, True, i0, i1, ua, ub, u0, w0, m, half, src)
    else:
        columns(buf, mode, table, width, height, False, i0, i1, ua, ub, u0, w0, m, half, src)


@inline
def columns(buf, mode, table, width, height, swap, i0, i1, ua, ub, u0, w0, m, half, src):
    """The columns i0..i1 of a line (``swap`` a constant: one loop per major axis)."""
    alpha = src[3]
    for i in range(i0, i1 + 1):
        lo = max(ua, i - 0.5)
        hi = min(ub, i + 0.5)
        if hi > lo:
            wc = w0 + (0.5 * (lo + hi) - u0) * m
            column(buf, mode, table, width, height, swap, i, wc, half, (hi - lo) * alpha, src)


@helper
def band_order(segments, height):
    """The segments' indices sorted by band of scan lines of their lower end
    (:func:`scanline._kernels.raster.band_sorted`, a stable counting sort).

    For a batch of one color the order of compositing changes nothing but the
    rounding (each "over" of the same color commutes), and drawing band by band
    keeps the rows being blended in the cache."""
    n = segments.shape[0]
    keyed = np.empty((n, 2), np.int64)
    for i in range(n):
        keyed[i, 0] = int(min(max(min(segments[i, 1], segments[i, 3]), 0.0), height - 1.0))
        keyed[i, 1] = i
    return band_sorted(keyed, 0, height)[:, 1].copy()


@inline
def lines_loop(buf, mode, table, width, height, segments, srcs, order):
    one = srcs.shape[0] == 1
    for t in range(segments.shape[0]):
        n = order[t]
        wu_line(buf, mode, table, width, height, segments[n, 0], segments[n, 1],
                segments[n, 2], segments[n, 3], srcs[0] if one else srcs[n])


@kernel
def draw_lines(buf, mode, width, height, table, segments, srcs):
    """Composite antialiased lines, rows (x0, y0, x1, y1) of ``segments``, with
    the source rows ``srcs`` (one per segment, in order; or one for all, in bands
    of scan lines except in mode "P", where the nearest-entry rounding makes the
    order visible)."""
    if srcs.shape[0] == 1 and mode != INDEXED:
        order = band_order(segments, height)
    else:
        order = np.arange(segments.shape[0])
    if mode == RGB:
        lines_loop(buf, RGB, table, width, height, segments, srcs, order)
    elif mode == GRAY:
        lines_loop(buf, GRAY, table, width, height, segments, srcs, order)
    elif mode == RGBA:
        lines_loop(buf, RGBA, table, width, height, segments, srcs, order)
    else:
        lines_loop(buf, mode, table, width, height, segments, srcs, order)


@inline
def conic_arcs(buf, mode, table, width, height, swap, uc, wc, ru, rw, src):
    """Composite the two arcs of the ellipse with center (uc, wc) and semi-axes ru
    (along u) and rw that are stepped along u: |u - uc| <= ru**2 / sqrt(ru**2 +
    rw**2), where |slope| <= 1."""
    reach = ru / math.hypot(1.0, rw / ru)   # ru**2 / sqrt(ru**2 + rw**2), no underflow
    umax = height if swap else width
    wmax = width if swap else height
    ua = max(uc - reach, -0.5)
    ub = min(uc + reach, umax - 0.5)
    if not ua < ub or wc + rw < -2.0 or wc - rw > wmax + 1.0:
        return
    i0 = max(math.floor(ua + 0.5), 0)
    i1 = min(math.ceil(ub + 0.5) - 1, umax - 1)
    alpha = src[3]
    for i in range(i0, i1 + 1):
        lo = max(ua, i - 0.5)
        hi = min(ub, i + 0.5)
        if hi > lo:
            t = (0.5 * (lo + hi) - uc) / ru
            off = rw * math.sqrt(max(1.0 - t * t, 0.0))
            # |slope| = rw**2 |t| / (ru off), at most 1 here (clamped against round-off)
            m = min(rw / ru * abs(t) * (rw / off), 1.0) if off > 0.0 else 0.0
            half = 0.5 * math.sqrt(1.0 + m * m)
            weight = (hi - lo) * alpha
            column(buf, mode, table, width, height, swap, i, wc + off, half, weight, src)
            column(buf, mode, table, width, height, swap, i, wc - off, half, weight, src)


@inline
def ellipses_loop(buf, mode, table, width, height, ellipses, srcs):
    one = srcs.shape[0] == 1
    for n in range(ellipses.shape[0]):
        xc, yc, rx, ry = ellipses[n, 0], ellipses[n, 1], ellipses[n, 2], ellipses[n, 3]
        src = srcs[0] if one else srcs[n]
        if rx > 0.0:
            conic_arcs(buf, mode, table, width, height, False, xc, yc, rx, ry, src)
        if ry > 0.0:
            conic_arcs(buf, mode, table, width, height, True, yc, xc, ry, rx, src)


@kernel
def draw_ellipses(buf, mode, width, height, table, ellipses, srcs):
    """Composite antialiased ellipse outlines, rows (xc, yc, rx, ry) of
    ``ellipses`` (rx = ry: a circle), with ``srcs``, in order."""
    if mode == RGB:
        ellipses_loop(buf, RGB, table, width, height, ellipses, srcs)
    elif mode == GRAY:
        ellipses_loop(buf, GRAY, table, width, height, ellipses, srcs)
    elif mode == RGBA:
        ellipses_loop(buf, RGBA, table, width, height, ellipses, srcs)
    else:
        ellipses_loop(buf, mode, table, width, height, ellipses, srcs)
