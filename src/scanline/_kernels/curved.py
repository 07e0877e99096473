"""Scan-line fill of curved boundary areas: filled circles and ellipses, arcs, chords
and pie slices (notes, chapter 2, Q.8; syllabus "Scan-Line fill of curved Boundary
Areas").

Two stages, one truth.  *Extents*: the midpoint circle or ellipse of ``conics`` is
stepped, and each step tells the x extent of the scan lines it touches (an octant
point (x, y) of a circle gives rows +-y and, mirrored, rows +-x), so ``w[d]`` is the
right-most outline pixel of row offset d and ``a[d]`` the left-most outline pixel of
the right half.  Only the row offsets d = |Y - yc| of visible scan lines Y are kept,
so the tables hold at most height + 2 entries.  *Spans*: each visible scan line gets
the span [-w, w] (a filled area) or the outline runs [a, w] and [-w, -a] (an arc),
intersected with at most two half-planes (a pie's radii, a chord's line), and is
written with ``span``: every pixel once.

Half-planes are integers ``(nx, ny, c, tie)``: the pixel (x, y), relative to the
center, is inside when nx x + ny y + c > 0, or = 0 and ``tie``.  The API layer
chooses ``tie`` by the top-left rule, so that areas sharing a straight edge cover
each pixel on it exactly once.
"""

import numpy as np

from ._jit import helper, inline, kernel
from .conics import REGION_1, circle_state, circle_step, ellipse_next, ellipse_region1_start, isqrt
from .raster import band_sorted
from .spans import span

#: Beyond every coordinate: the open end of a half-line.
FAR = 1 << 62

#: Shapes (token lengths, :mod:`scanline._kernels.variants`): a fill compiles the
#: extents of its own shape only.
CIRCLE = 1
ELLIPSE = 2

#: How two half-planes combine: both (a convex sector, a chord) or either (a sector
#: wider than a half-turn).
BOTH = 0
EITHER = 1


@inline
def row_band(yc, ry, height):
    """The visible scan lines y0..y1 of a shape spanning yc - ry .. yc + ry, and the
    row offsets dlo..dhi (d = |Y - yc|) they need; y0 > y1 when none is visible."""
    y0 = max(0, yc - ry)
    y1 = min(height - 1, yc + ry)
    if yc < y0:
        return y0, y1, y0 - yc, y1 - yc
    if yc > y1:
        return y0, y1, yc - y1, yc - y0
    return y0, y1, 0, max(yc - y0, y1 - yc)


@helper
def circle_rows_stepped(r, dlo, dhi, w):
    """w[d - dlo] for dlo <= d <= dhi + 1 by the notes' midpoint circle: the octant
    point (x, y) is the right-most pixel of row y (the last one with that y) and,
    mirrored in the diagonal, the only pixel of row x in its octant."""
    x = 0
    y = r
    p = 1 - r
    while x <= y and (x <= dhi + 1 or y >= dlo):
        if dlo <= x <= dhi + 1:
            w[x - dlo] = y
        if dlo <= y <= dhi + 1:
            w[y - dlo] = x
        x, y, p = circle_step(x, y, p)


@inline
def circle_half_width(d, r):
    """w[d] of the midpoint circle in closed form, for a huge circle's visible rows.

    Rows d up to the diagonal are the octant's columns: w = y(d) of ``circle_state``.
    Above it w is the last column x with y(x) >= d; ``circle_state``'s invariant
    gives y(x) >= d iff 4 x**2 < 4 r**2 - (2d - 1)**2 =: t, so x = isqrt((t - 1) // 4).
    """
    if d > r:
        return -1
    if r == 0:
        return 0
    if d < r:
        y, _ = circle_state(d, r)
        if d <= y:
            return y
    t = 4 * r * r - (2 * d - 1) * (2 * d - 1)
    return isqrt((t - 1) // 4)


@helper
def circle_rows(r, dlo, dhi, w):
    """w[d - dlo] for dlo <= d <= dhi + 1; the octant is stepped unless it is much
    longer than the band of rows needed."""
    for i in range(dhi - dlo + 2):
        w[i] = -1
    if r <= 4 * (dhi - dlo + 2) + 64:
        circle_rows_stepped(r, dlo, dhi, w)
    else:
        for d in range(dlo, dhi + 2):
            w[d - dlo] = circle_half_width(d, r)


@helper
def circle_runs(dlo, dhi, a, w):
    """a[d] of the circle's outline: a run of row d starts one past the end of row
    d + 1 (a diagonal step) or is the single pixel w[d] (a vertical step)."""
    for i in range(dhi - dlo + 1):
        a[i] = min(w[i + 1] + 1, w[i])


@helper
def ellipse_rows(rx, ry, dlo, dhi, a, w):
    """a[d - dlo], w[d - dlo] for dlo <= d <= dhi + 1 by the notes' midpoint
    ellipse: the first and last quadrant points of each row (y never rises, and
    drops by at most one per step, so every row 0..ry has points)."""
    for i in range(dhi - dlo + 2):
        w[i] = -1
    rx2 = rx * rx
    ry2 = ry * ry
    x, y, p, px, py = ellipse_region1_start(rx, ry)
    region = np.int64(REGION_1)
    last = -1
    while region != 0 and y >= dlo:
        if y <= dhi + 1:
            if y != last:
                a[y - dlo] = x
            w[y - dlo] = x
        last = y
        region, x, y, _, p, px, py = ellipse_next(region, x, y, p, px, py, rx, rx2, ry2)


@inline
def half_plane(nx, ny, c, tie, y):
    """The x-interval (s, e) of row y where nx x + ny y + c > 0 (or >= 0 with
    ``tie``), in exact integer arithmetic; s > e when it is empty."""
    k = ny * y + c
    if nx > 0:
        return (-(k // nx) if tie else (-k) // nx + 1), FAR
    if nx < 0:
        m = -nx
        return -FAR, (k // m if tie else -((-k) // m) - 1)
    if k > 0 or (k == 0 and tie):
        return -FAR, FAR
    return FAR, -FAR


@inline
def pick(k, l0, h0, l1, h1, s0, e0, s1, e1):
    """The k-th (0..3) intersection of a base run (l, h) with an angular interval
    (s, e)."""
    if k < 2:
        l, h = l0, h0
    else:
        l, h = l1, h1
    if k & 1:
        return max(l, s1), min(h, e1)
    return max(l, s0), min(h, e0)


@helper
def region_spans(buf, layout, width, height, xc, yc, y0, y1, dlo, a, w, outline, hp, combine, color):
    """Write scan lines y0..y1: the span [-w, w] or (``outline``) the runs [a, w] and
    [-w, -a], intersected with the half-planes ``hp`` combined by ``combine``."""
    for yy in range(y0, y1 + 1):
        y = yy - yc
        i = abs(y) - dlo
        wd = w[i]
        if outline:
            l0, h0, l1, h1 = a[i], wd, -wd, -max(a[i], 1)
        else:
            l0, h0, l1, h1 = -wd, wd, 1, 0
        s0, e0 = half_plane(hp[0, 0], hp[0, 1], hp[0, 2], hp[0, 3] != 0, y)
        s1, e1 = half_plane(hp[1, 0], hp[1, 1], hp[1, 2], hp[1, 3] != 0, y)
        if combine == BOTH:
            s0, e0, s1, e1 = max(s0, s1), min(e0, e1), 1, 0
        elif s0 > e0:
            s0, e0, s1, e1 = s1, e1, 1, 0
        elif s1 <= e1 and s1 <= e0 + 1 and s0 <= e1 + 1:  # touching: one interval
            s0, e0, s1, e1 = min(s0, s1), max(e0, e1), 1, 0
        for k in range(4):  # one call site of span keeps the loop fast
            lo, hi = pick(k, l0, h0, l1, h1, s0, e0, s1, e1)
            if lo <= hi:
                span(buf, layout, width, height, yy, xc + lo, xc + hi, color)


@helper
def curved_region(buf, layout, width, height, xc, yc, rx, ry, shape, outline, hp, combine, color, a, w):
    """Extents of one circle (``shape`` the CIRCLE token: rx = ry = r) or ellipse,
    then its spans; ``a`` and ``w`` are scratch tables of at least height + 2
    entries."""
    y0, y1, dlo, dhi = row_band(yc, ry, height)
    if y0 > y1 or xc + rx < 0 or xc - rx > width - 1:
        return
    if len(shape) == CIRCLE:
        circle_rows(rx, dlo, dhi, w)
        if outline:
            circle_runs(dlo, dhi, a, w)
    else:
        ellipse_rows(rx, ry, dlo, dhi, a, w)
    region_spans(buf, layout, width, height, xc, yc, y0, y1, dlo, a, w, outline, hp, combine, color)


@kernel
def draw_region(buf, layout, width, height, xc, yc, rx, ry, shape, outline, hp, combine, color):
    """One filled circle or ellipse (``outline`` False) or its outline, clipped by the
    half-planes ``hp`` (int64, shape (2, 4)) combined by ``combine``."""
    a = np.empty(height + 2, np.int64)
    w = np.empty(height + 2, np.int64)
    curved_region(buf, layout, width, height, xc, yc, rx, ry, shape, outline, hp, combine, color, a, w)


@kernel
def fill_regions(buf, layout, width, height, shapes, shape, colors):
    """Fill N circles (``shape`` the CIRCLE token: rows (xc, yc, r)) or ellipses
    (rows (xc, yc, rx, ry)) with ``colors[i]`` (or ``colors[0]`` for all)."""
    a = np.empty(height + 2, np.int64)
    w = np.empty(height + 2, np.int64)
    whole = np.zeros((2, 4), np.int64)
    whole[0, 3] = 1  # 0 x + 0 y + 0 = 0, tie: every pixel
    whole[1, 3] = 1
    last = shapes.shape[1] - 1
    area = np.bool_(False)    # outline False, BOTH: typed values, not literals, so that
    both = np.int64(BOTH)     # curved_region compiles once for draw_region and this
    one = colors.shape[0] == 1
    if one:  # one color: any order gives the same image
        shapes = band_sorted(shapes, height)
    color = colors[0]
    for i in range(shapes.shape[0]):
        if not one:
            color = colors[i]
        curved_region(buf, layout, width, height, shapes[i, 0], shapes[i, 1], shapes[i, 2],
                      shapes[i, last], shape, area, whole, both, color, a, w)
