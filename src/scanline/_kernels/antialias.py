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
alpha = intensity x the color's alpha); the frame-buffer mode is a token
(:mod:`scanline._kernels.variants`), so a kernel is compiled for the modes it is
called with only.  In modes "RGB" and "L" the lines take the same arithmetic in two
passes per line (:func:`fixed_point_columns`).  Loops run over
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
from .blend import fixed, mix, over
from .variants import GRAY, RGB

#: Scan lines per band of :func:`band_lists` (256).  Measured on 100 000 random
#: lines of up to 64 pixels in 2048 x 2048 RGB: 32-line bands listed each line in
#: 1.7 bands on average and 256-line bands (1.5 MiB of RGB, held by the L3 cache)
#: were about 1.3x faster; 128 and 512 lines did about as well as 256, a single
#: band worse.
BAND_SHIFT = 8


@inline
def column(buf, mode, table, swap, u, wc, half, weight, src, wlo, whi):
    """Composite the column span [wc - half, wc + half] of column (row, if
    ``swap``) ``u``, intensities scaled by ``weight``, on the rows (columns)
    wlo..whi only."""
    a = wc - half
    b = wc + half
    j0 = max(math.floor(a + 0.5), wlo)
    j1 = min(math.ceil(b + 0.5) - 1, whi)
    for j in range(j0, j1 + 1):
        cover = (min(b, j + 0.5) - max(a, j - 0.5)) * weight
        if swap:
            over(buf, mode, table, j, u, src, cover)
        else:
            over(buf, mode, table, u, j, src, cover)


@helper
def wu_line(buf, mode, table, width, x0, y0, x1, y1, src, alpha, ylo, yhi, rows, weights):
    """Composite the pixels of rows ylo..yhi of the antialiased line (x0, y0)-(x1,
    y1) (real coordinates) in a raster ``width`` pixels wide, with the channels
    ``src`` (integers in modes "RGB" and "L", else a source row of
    :mod:`scanline._kernels.blend`) at opacity ``alpha``; ``rows`` and ``weights``
    are scratch for :func:`fixed_point_columns`.  (A compiled helper: its test of
    the mode token folds here.)"""
    swap = abs(y1 - y0) > abs(x1 - x0)
    if swap:   # u: the major axis, w: the minor one; [ulo, uhi] x [wlo, whi] pixels
        u0, w0, u1, w1 = y0, x0, y1, x1
        ulo, uhi, wlo, whi = ylo, yhi, 0, width - 1
    else:
        u0, w0, u1, w1 = x0, y0, x1, y1
        ulo, uhi, wlo, whi = 0, width - 1, ylo, yhi
    if u0 > u1:
        u0, w0, u1, w1 = u1, w1, u0, w0
    du = u1 - u0
    if not du > 0.0:
        return
    m = (w1 - w0) / du
    half = 0.5 * math.sqrt(1.0 + m * m)
    # the part of [u0, u1] over columns ulo..uhi whose spans can reach rows wlo..whi:
    # cut where the line is 1 + half beyond them, so that a column cut short has no
    # pixel in wlo..whi (|m| <= 1)
    ua = max(u0, ulo - 0.5)
    ub = min(u1, uhi + 0.5)
    if m != 0.0:
        ta = u0 + (wlo - 1.5 - half - w0) / m
        tb = u0 + (whi + 1.5 + half - w0) / m
        ua = max(ua, min(ta, tb))
        ub = min(ub, max(ta, tb))
    elif not (wlo - 1.5 - half < w0 < whi + 1.5 + half):
        return
    if not ua < ub:
        return
    i0 = max(math.floor(ua + 0.5), ulo)
    i1 = min(math.ceil(ub + 0.5) - 1, uhi)
    if len(mode) == RGB or len(mode) == GRAY:
        if swap:
            fixed_point_columns(buf, mode, True, i0, i1, ua, ub, u0, w0, m, half, src, alpha,
                                wlo, whi, rows, weights)
        else:
            fixed_point_columns(buf, mode, False, i0, i1, ua, ub, u0, w0, m, half, src, alpha,
                                wlo, whi, rows, weights)
    elif swap:
        columns(buf, mode, table, True, i0, i1, ua, ub, u0, w0, m, half, src, alpha, wlo, whi)
    else:
        columns(buf, mode, table, False, i0, i1, ua, ub, u0, w0, m, half, src, alpha, wlo, whi)


@inline
def columns(buf, mode, table, swap, i0, i1, ua, ub, u0, w0, m, half, src, alpha, wlo, whi):
    """The columns i0..i1 of a line (``swap`` a constant: one loop per major axis)."""
    for i in range(i0, i1 + 1):
        lo = max(ua, i - 0.5)
        hi = min(ub, i + 0.5)
        if hi > lo:
            wc = w0 + (0.5 * (lo + hi) - u0) * m
            column(buf, mode, table, swap, i, wc, half, (hi - lo) * alpha, src, wlo, whi)


@inline
def fixed_point_columns(buf, mode, swap, i0, i1, ua, ub, u0, w0, m, half, src, alpha, wlo,
                        whi, rows, weights):
    """:func:`columns` for the modes whose composite is a fixed-point weight per
    channel ("RGB", "L"), in two passes: the first computes,
    for every column, its first row and the weights (:func:`scanline._kernels.blend.fixed`)
    of the three pixels a column span can touch (0 past its last one) with no
    data-dependent branch, so that LLVM vectorizes it; the second blends the
    pixels of nonzero weight.  The arithmetic is :func:`column`'s and
    :func:`scanline._kernels.blend.over`'s, operation for operation (a weight of 0
    leaves a pixel as it is), so the pixels are the same; measured, about 1.2x
    faster than :func:`columns` on 100 000 random short lines."""
    n = i1 - i0 + 1
    flo = float(wlo)
    fhi = float(whi)
    for k in range(n):
        i = i0 + k
        lo = max(ua, i - 0.5)
        hi = min(ub, i + 0.5)
        wc = w0 + (0.5 * (lo + hi) - u0) * m
        weight = (hi - lo) * alpha if hi > lo else 0.0
        a = wc - half
        b = wc + half
        f0 = max(np.floor(a + 0.5), flo)            # the first and last rows, as floats
        f1 = min(np.ceil(b + 0.5) - 1.0, fhi)
        rows[k] = int(f0)
        for t in range(3):                          # a span 1..sqrt(2) long: <= 3 pixels
            jf = f0 + t
            cover = (min(b, jf + 0.5) - max(a, jf - 0.5)) * weight if jf <= f1 else 0.0
            weights[t, k] = fixed(min(max(cover, 0.0), 1.0))
    flat = buf.reshape(-1)
    channels = buf.shape[2]
    stride = buf.shape[1] * channels
    step = np.uint64(channels if swap else stride)      # from pixel t to pixel t + 1
    for k in range(n):
        i = i0 + k
        j = rows[k]
        # unsigned offsets: no negative-index wraparound code (i, j >= 0); a nonzero
        # weight is on a row <= whi (the pass above zeroed the others)
        p = np.uint64(i * stride + j * channels if swap else j * stride + i * channels)
        for t in range(3):
            f = weights[t, k]
            if f != 0:
                for c in range(3 if len(mode) == RGB else 1):
                    q = p + np.uint64(c)
                    flat[q] = mix(flat[q], src[c], f)
            p += step


@helper
def band_lists(segments, height):
    """For each band of ``1 << BAND_SHIFT`` scan lines, the segments that can have
    pixels in it, in their given order: segment indices ``items[starts[b]:starts[b
    + 1]]`` for band b (a stable counting sort; a segment is listed in every band
    its rows [min y - 1.25, max y + 1.25] meet: a column span reaches at most
    sqrt(2) / 2 + 1/2 < 1.25 beyond the segment's y range)."""
    n = segments.shape[0]
    bands = ((height - 1) >> BAND_SHIFT) + 1
    starts = np.zeros(bands + 1, np.int64)
    first = np.empty(n, np.int64)
    last = np.empty(n, np.int64)
    for i in range(n):
        lo = min(segments[i, 1], segments[i, 3]) - 1.25
        hi = max(segments[i, 1], segments[i, 3]) + 1.25
        first[i] = int(max(lo, 0.0)) >> BAND_SHIFT
        last[i] = int(min(hi, height - 1.0)) >> BAND_SHIFT if hi >= 0.0 else -1
        for b in range(first[i], last[i] + 1):
            starts[b + 1] += 1
    for b in range(bands):
        starts[b + 1] += starts[b]
    items = np.empty(starts[bands], np.int64)
    fill = np.empty(bands, np.int64)
    for b in range(bands):
        fill[b] = starts[b]
    for i in range(n):
        for b in range(first[i], last[i] + 1):
            items[fill[b]] = i
            fill[b] += 1
    return starts, items


@kernel
def draw_lines(buf, mode, width, height, table, segments, srcs):
    """Composite antialiased lines, rows (x0, y0, x1, y1) of ``segments``, with
    the source rows ``srcs`` (one, or one per segment), in order (``mode`` a mode
    token).

    The raster is drawn band by band of scan lines (:func:`band_lists`), each band
    compositing its part of every segment that meets it, in the segments' order:
    every pixel sees the same composites in the same order as segment after
    segment would give it, while the rows being blended stay in the cache."""
    starts, items = band_lists(segments, height)
    one = srcs.shape[0] == 1
    channels = np.empty((srcs.shape[0], 3), np.int64)   # hoisted float -> int
    for k in range(srcs.shape[0]):
        for c in range(3):
            channels[k, c] = int(srcs[k, c])
    rows = np.empty(max(width, height), np.int64)       # fixed_point_columns' scratch
    weights = np.empty((3, max(width, height)), np.int64)
    for b in range(starts.shape[0] - 1):
        ylo = b << BAND_SHIFT
        yhi = min(ylo + (1 << BAND_SHIFT) - 1, height - 1)
        for t in range(starts[b], starts[b + 1]):
            n = items[t]
            k = 0 if one else n
            # fixed-point modes take the channels as integers, the others "over"'s
            # float source row (one type per mode: one specialization of "over")
            src = channels[k] if len(mode) == RGB or len(mode) == GRAY else srcs[k]
            wu_line(buf, mode, table, width, segments[n, 0], segments[n, 1], segments[n, 2],
                    segments[n, 3], src, srcs[k, 3], ylo, yhi, rows, weights)


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
            column(buf, mode, table, swap, i, wc + off, half, weight, src, 0, wmax - 1)
            column(buf, mode, table, swap, i, wc - off, half, weight, src, 0, wmax - 1)


@kernel
def draw_ellipses(buf, mode, width, height, table, ellipses, srcs):
    """Composite antialiased ellipse outlines, rows (xc, yc, rx, ry) of
    ``ellipses`` (rx = ry: a circle), with ``srcs``, in order (``mode`` a mode
    token)."""
    one = srcs.shape[0] == 1
    for n in range(ellipses.shape[0]):
        xc, yc, rx, ry = ellipses[n, 0], ellipses[n, 1], ellipses[n, 2], ellipses[n, 3]
        src = srcs[0] if one else srcs[n]
        if rx > 0.0:
            conic_arcs(buf, mode, table, width, height, False, xc, yc, rx, ry, src)
        if ry > 0.0:
            conic_arcs(buf, mode, table, width, height, True, yc, xc, ry, rx, src)
