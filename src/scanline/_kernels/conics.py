"""Midpoint circle and midpoint ellipse scan conversion (notes, chapter 2, Q.4-Q.6).

The circle is computed in the octant from (0, r) to the diagonal x = y and mirrored
eight ways; the ellipse in two regions of the first quadrant (slope above and below -1)
and mirrored four ways.  Each mirrored pixel is written once (points on the axes and on
the diagonal are their own mirror images), so the kernels can later serve XOR and
blending writes.
"""

import math

import numpy as np

from ._jit import helper, inline, kernel
from .raster import channels, put, store, store_flat
from .spans import strip
from .variants import BYTES

#: Ellipse region labels in traces; TIP is the run along y = 0 that completes flat
#: ellipses (see ``ellipse_tip``).
REGION_1 = 1
REGION_2 = 2
TIP = 3


@inline
def mirror4(k, a, b):
    """The k-th (0..3) of the four mirror images (+-a, +-b), and whether it is a
    new pixel: images on an axis coincide and are plotted once."""
    if k == 0:
        return a, b, True
    if k == 1:
        return -a, b, a != 0
    if k == 2:
        return a, -b, b != 0
    return -a, -b, a != 0 and b != 0


@inline
def mirror8(k, x, y):
    """The k-th (0..7) of the eight-way images of (x, y) (notes, Q.4: "determine
    symmetry points in other seven octants"), and whether it is a new pixel."""
    if k < 4:
        return mirror4(k, x, y)
    a, b, new = mirror4(k - 4, y, x)
    return a, b, new and x != y


@inline
def circle_step(x, y, p):
    """One step of the notes' midpoint circle: x_k+1 = x_k + 1; if p_k < 0 keep y
    and p += 2x_k+1 + 1, else y -= 1 and p += 2x_k+1 + 1 - 2y_k+1."""
    x += 1
    if p < 0:
        return x, y, p + 2 * x + 1
    y -= 1
    return x, y, p + 2 * x + 1 - 2 * y


@inline
def isqrt(n):
    """floor(sqrt(n)) for 0 <= n < 2**62, exact."""
    s = int(math.sqrt(n))
    while s * s > n:
        s -= 1
    while (s + 1) * (s + 1) <= n:
        s += 1
    return s


@helper
def circle_state(x, r):
    """The midpoint circle's (y, p) at column ``x`` (0 <= x < r), in closed form.

    The loop keeps the invariant (2y - 1)**2 < 4(r**2 - x**2) <= (2y + 1)**2: the
    midpoint below the chosen pixel is inside the circle and the one above is not
    (they can never lie on it, as 4(x+1)**2 + (2y-1)**2 is odd).  So
    y = floor((isqrt(4s - 1) + 1) / 2) with s = r**2 - x**2, and
    p = (x + 1)**2 + y**2 - y - r**2, the notes' integer p_k = f(x + 1, y - 1/2) - 1/4.
    """
    s = r * r - x * x
    y = (isqrt(4 * s - 1) + 1) // 2
    return y, (x + 1) * (x + 1) + y * y - y - r * r


@inline
def run_start(a, b, x, start):
    """Fold the run [a, b] into ``start``, the first column >= x of any run."""
    if b >= x and a <= b:
        s = max(a, x)
        if start < 0 or s < start:
            return s
    return start


@inline
def run_end(a, b, end):
    """Extend ``end`` through the run [a, b] if it overlaps or touches it."""
    if a <= end + 1 and b > end:
        return b
    return end


@helper
def next_run(xc, yc, width, height, x):
    """The next run of octant columns, from column ``x`` on, in which one of the
    eight mirrored pixels can lie on the raster: a column x is needed only if xc + x,
    xc - x, yc + x or yc - x is in range.  Returns ``(start, end)``, or (-1, -1)."""
    a0, b0 = -xc, width - 1 - xc
    a1, b1 = xc - width + 1, xc
    a2, b2 = -yc, height - 1 - yc
    a3, b3 = yc - height + 1, yc
    start = run_start(a3, b3, x, run_start(a2, b2, x, run_start(a1, b1, x, run_start(a0, b0, x, -1))))
    if start < 0:
        return -1, -1
    end = start
    for _ in range(4):  # each pass merges at least one more run, if any is left
        end = run_end(a3, b3, run_end(a2, b2, run_end(a1, b1, run_end(a0, b0, end))))
    return start, end


@helper
def circle_run(buf, layout, width, height, xc, yc, x, y, p, end, color):
    """The notes' loop over octant columns x .. end (or to the diagonal), each
    point plotted eight ways.  Returns the state (x, y, p) after it."""
    while x <= end and x <= y:
        for k in range(8):  # one call site of put keeps the loop fast
            a, b, new = mirror8(k, x, y)
            if new:
                put(buf, layout, width, height, xc + a, yc + b, color)
        x, y, p = circle_step(x, y, p)
    return x, y, p


@helper
def circle_walk(flat, base, r, n, row, c0, c1, c2, c3):
    """The notes' loop for a circle wholly inside unpacked storage, seen as one
    flat array of ``row`` bytes per row and ``n`` per pixel, with its center at
    byte ``base``: each of the eight images written with no bounds checks.

    The images on the axes and the diagonal, which :func:`mirror8` plots once, are
    written twice here, with the same value: the pixels are the same and the loop
    has no branch on them.  The step is :func:`circle_step`'s with the decision as
    selects (no branch to mispredict), and the loop holds no array but ``flat``
    (:func:`scanline._kernels.raster.channels`)."""
    x = 0
    y = r
    p = 1 - r
    while x <= y:
        xn = x * n
        yn = y * n
        xr = x * row
        yr = y * row
        store_flat(flat, base + xn + yr, n, c0, c1, c2, c3)
        store_flat(flat, base - xn + yr, n, c0, c1, c2, c3)
        store_flat(flat, base + xn - yr, n, c0, c1, c2, c3)
        store_flat(flat, base - xn - yr, n, c0, c1, c2, c3)
        store_flat(flat, base + yn + xr, n, c0, c1, c2, c3)
        store_flat(flat, base - yn + xr, n, c0, c1, c2, c3)
        store_flat(flat, base + yn - xr, n, c0, c1, c2, c3)
        store_flat(flat, base - yn - xr, n, c0, c1, c2, c3)
        x += 1
        down = p >= 0
        y -= 1 if down else 0
        p += 2 * x + 1 - (2 * y if down else 0)


@kernel
def draw_circle(buf, layout, width, height, xc, yc, r, color):
    """Draw the midpoint circle of radius r >= 0 about (xc, yc).

    Only the columns x of the octant for which one of the eight mirrored pixels can
    lie in the frame buffer are visited (at most 2(width + height) of them); the loop
    jumps to each such run with ``circle_state``, so a circle of radius 10**9 costs
    what its visible part costs.
    """
    if xc + r < 0 or xc - r > width - 1 or yc + r < 0 or yc - r > height - 1:
        return
    if len(layout) == BYTES and xc - r >= 0 and xc + r < width and yc - r >= 0 and yc + r < height:
        n = buf.shape[2]
        row = buf.shape[1] * n
        c0, c1, c2, c3 = channels(color.reshape(1, n), np.int64(0))   # (not a literal 0)
        circle_walk(buf.reshape(-1), yc * row + xc * n, r, n, row, c0, c1, c2, c3)
        return
    x = np.int64(0)   # (not a literal 0: next_run would be compiled for it too)
    y = r
    p = 1 - r
    while x <= y:
        start, end = next_run(xc, yc, width, height, x)
        if start < 0:
            return
        if start != x:
            if start >= r:  # y(x) <= 0 < x: past the diagonal
                return
            x = start
            y, p = circle_state(x, r)
        x, y, p = circle_run(buf, layout, width, height, xc, yc, x, y, p, end, color)


@kernel
def draw_circles(band, step, buf, layout, width, height, circles, colors):
    """Draw N circles, ``circles[i] = (xc, yc, r)``, with ``colors[i]`` (or
    ``colors[0]`` for all), in order, into strip ``band`` of ``step`` of the rows
    (:func:`scanline._kernels.spans.strip`: one call per thread, the pixels
    independent of the thread count)."""
    top, rows = strip(band, step, height)
    if rows <= 0:
        return
    view = buf[top:top + rows]
    flat = view.reshape(-1)
    n = buf.shape[2]
    row = buf.shape[1] * n
    one = colors.shape[0] == 1
    c0, c1, c2, c3 = channels(colors, np.int64(0))   # (not a literal 0: compiled once)
    for i in range(circles.shape[0]):
        xc = circles[i, 0]
        yc = circles[i, 1] - top
        r = circles[i, 2]
        if yc + r < 0 or yc - r >= rows:
            continue
        if not one:
            c0, c1, c2, c3 = channels(colors, i)
        if (len(layout) == BYTES and xc - r >= 0 and xc + r < width and yc - r >= 0
                and yc + r < rows):
            circle_walk(flat, yc * row + xc * n, r, n, row, c0, c1, c2, c3)
        else:
            draw_circle(view, layout, width, rows, xc, yc, r, colors[0 if one else i])


@kernel
def circle_trace(r, out):
    """Fill ``out`` (int64, at least r + 1 rows) with the notes' table: p_k and the
    point (x_k+1, y_k+1) it selects, for k = 0 until x >= y.  Returns the row count."""
    x = 0
    y = r
    p = 1 - r
    n = 0
    while x < y:
        p_k = p
        x, y, p = circle_step(x, y, p)
        out[n, 0] = p_k
        out[n, 1] = x
        out[n, 2] = y
        n += 1
    return n


# -- ellipse ------------------------------------------------------------------------
# Decision parameters are kept multiplied by 4 (P = 4p), which makes the notes'
# quarter terms (r_x**2 / 4 in p1_0, (x + 1/2)**2 in p2_0) exact integers, so no
# rounding changes a decision.  |P| < 8 r_x**2 r_y**2 < 2**63 for r_x r_y <= 2**29.


@inline
def ellipse_region1_start(rx, ry):
    """(x, y, P, px, py) at (0, r_y): P = 4 p1_0 = 4 r_y^2 - 4 r_x^2 r_y + r_x^2,
    px = 2 r_y^2 x, py = 2 r_x^2 y (int64 values, not literals, so that the helpers
    they reach are compiled once)."""
    rx2 = rx * rx
    ry2 = ry * ry
    zero = np.int64(0)
    return zero, ry, 4 * ry2 - 4 * rx2 * ry + rx2, zero, 2 * rx2 * ry


@inline
def ellipse_region1_step(x, y, p, px, py, rx2, ry2):
    """Region 1: x += 1; if p1_k < 0 then p += 2 r_y^2 x_k+1 + r_y^2, else y -= 1 and
    p += 2 r_y^2 x_k+1 - 2 r_x^2 y_k+1 + r_y^2 (all times 4)."""
    x += 1
    px += 2 * ry2
    if p < 0:
        p += 4 * (ry2 + px)
    else:
        y -= 1
        py -= 2 * rx2
        p += 4 * (ry2 + px - py)
    return x, y, p, px, py


@inline
def ellipse_region2_start(x, y, rx2, ry2):
    """P = 4 p2_0 = r_y^2 (2x + 1)^2 + 4 r_x^2 (y - 1)^2 - 4 r_x^2 r_y^2."""
    return ry2 * (2 * x + 1) * (2 * x + 1) + 4 * rx2 * (y - 1) * (y - 1) - 4 * rx2 * ry2


@inline
def ellipse_region2_step(x, y, p, px, py, rx2, ry2):
    """Region 2: y -= 1; if p2_k > 0 then p += r_x^2 - 2 r_x^2 y_k+1, else x += 1 and
    p += 2 r_y^2 x_k+1 - 2 r_x^2 y_k+1 + r_x^2 (all times 4)."""
    y -= 1
    py -= 2 * rx2
    if p > 0:
        p += 4 * (rx2 - py)
    else:
        x += 1
        px += 2 * ry2
        p += 4 * (rx2 - py + px)
    return x, y, p, px, py


@helper
def ellipse_next(region, x, y, p, px, py, rx, rx2, ry2):
    """Advance the midpoint ellipse by one point.

    Returns ``(region, x, y, p_k, p, px, py)``: the region of the new point, the
    point, the decision parameter p_k that chose it (times 4; 0 in the tip) and the
    state after it.  ``region`` 0 means the quadrant is complete.  Region 1 runs
    while 2 r_y^2 x < 2 r_x^2 y, region 2 while y > 0; then the tip completes a
    flat ellipse along y = 0 up to x = r_x (region 2 advances x by at most one per
    row, so a very flat ellipse reaches y = 0 early).
    """
    if region == REGION_1 and px >= py:
        region = REGION_2
        p = ellipse_region2_start(x, y, rx2, ry2)
    if region == REGION_2 and y <= 0:
        region = TIP
    p_k = p
    if region == REGION_1:
        x, y, p, px, py = ellipse_region1_step(x, y, p, px, py, rx2, ry2)
    elif region == REGION_2:
        x, y, p, px, py = ellipse_region2_step(x, y, p, px, py, rx2, ry2)
    elif x < rx:
        x += 1
        px += 2 * ry2
        p_k = 0
    else:
        region = 0
    return region, x, y, p_k, p, px, py


@helper
def ellipse_inside(buf, width, xc, yc, rx, ry, color):
    """The midpoint ellipse wholly inside unpacked storage: each of the four images
    is written with no bounds checks.  This loop repeats ``draw_ellipse``'s with
    ``store`` for ``put``: one loop with a run-time choice ran twice as slow."""
    rx2 = rx * rx
    ry2 = ry * ry
    x, y, p, px, py = ellipse_region1_start(rx, ry)
    region = np.int64(REGION_1)
    while region != 0:
        for k in range(4):
            a, b, new = mirror4(k, x, y)
            if new:
                store(buf, yc + b, xc + a, color)
        region, x, y, _, p, px, py = ellipse_next(region, x, y, p, px, py, rx, rx2, ry2)


@kernel
def draw_ellipse(buf, layout, width, height, xc, yc, rx, ry, color):
    """Draw the axis-aligned midpoint ellipse with semi-axes rx, ry >= 0 about (xc, yc)
    (for r_y = 0 the segment from xc - rx to xc + rx)."""
    if xc + rx < 0 or xc - rx > width - 1 or yc + ry < 0 or yc - ry > height - 1:
        return
    if len(layout) == BYTES and xc - rx >= 0 and xc + rx < width and yc - ry >= 0 and yc + ry < height:
        ellipse_inside(buf, width, xc, yc, rx, ry, color)
        return
    rx2 = rx * rx
    ry2 = ry * ry
    x, y, p, px, py = ellipse_region1_start(rx, ry)
    region = np.int64(REGION_1)
    while region != 0:
        for k in range(4):
            a, b, new = mirror4(k, x, y)
            if new:
                put(buf, layout, width, height, xc + a, yc + b, color)
        region, x, y, _, p, px, py = ellipse_next(region, x, y, p, px, py, rx, rx2, ry2)


@kernel
def draw_ellipses(band, step, buf, layout, width, height, ellipses, colors):
    """Draw N ellipses, ``ellipses[i] = (xc, yc, rx, ry)``, with ``colors[i]`` (or
    ``colors[0]`` for all), in order, into strip ``band`` of ``step`` of the rows (as
    :func:`draw_circles`)."""
    top, rows = strip(band, step, height)
    if rows <= 0:
        return
    view = buf[top:top + rows]
    one = colors.shape[0] == 1
    for i in range(ellipses.shape[0]):
        yc = ellipses[i, 1] - top
        ry = ellipses[i, 3]
        if yc + ry >= 0 and yc - ry < rows:
            draw_ellipse(view, layout, width, rows, ellipses[i, 0], yc, ellipses[i, 2], ry,
                         colors[0 if one else i])


@kernel
def ellipse_trace(rx, ry, out):
    """Fill ``out`` (int64, at least rx + ry + 1 rows) with the notes' tables: per
    row the region, 4 p_k (the decision parameter times 4; 0 for the tip), the
    point (x_k+1, y_k+1), 2 r_y^2 x_k+1 and 2 r_x^2 y_k+1.  Returns the row count."""
    rx2 = rx * rx
    ry2 = ry * ry
    x, y, p, px, py = ellipse_region1_start(rx, ry)
    region = np.int64(REGION_1)
    n = 0
    while True:
        region, x, y, p_k, p, px, py = ellipse_next(region, x, y, p, px, py, rx, rx2, ry2)
        if region == 0:
            return n
        out[n, 0] = region
        out[n, 1] = p_k
        out[n, 2] = x
        out[n, 3] = y
        out[n, 4] = px
        out[n, 5] = py
        n += 1
