"""Midpoint circle and midpoint ellipse scan conversion (notes, chapter 2, Q.4-Q.6).

The circle is computed in the octant from (0, r) to the diagonal x = y and mirrored
eight ways; the ellipse in two regions of the first quadrant (slope above and below -1)
and mirrored four ways.  Each mirrored pixel is written once (points on the axes and on
the diagonal are their own mirror images), so the kernels can later serve XOR and
blending writes.
"""

import math

from ._jit import inline, kernel
from .raster import put

#: Ellipse region labels in traces; TIP is the run along y = 0 that completes flat
#: ellipses (see ``ellipse_tip``).
REGION_1 = 1
REGION_2 = 2
TIP = 3


@inline
def plot4(buf, packed, width, height, xc, yc, a, b, color):
    """Plot (xc +- a, yc +- b), each distinct pixel once."""
    put(buf, packed, width, height, xc + a, yc + b, color)
    if a != 0:
        put(buf, packed, width, height, xc - a, yc + b, color)
    if b != 0:
        put(buf, packed, width, height, xc + a, yc - b, color)
        if a != 0:
            put(buf, packed, width, height, xc - a, yc - b, color)


@inline
def plot8(buf, packed, width, height, xc, yc, x, y, color):
    """Eight-way symmetry: plot (x, y) mirrored into all octants, once each."""
    plot4(buf, packed, width, height, xc, yc, x, y, color)
    if x != y:
        plot4(buf, packed, width, height, xc, yc, y, x, color)


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


@inline
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
def midpoint_circle(buf, packed, width, height, xc, yc, r, color):
    """Draw the circle of radius r >= 0 about (xc, yc).

    Only the columns x of the octant for which one of the eight mirrored pixels can
    lie in the frame buffer are visited (at most 2(width + height) of them); the loop
    jumps to each such run with ``circle_state``, so a circle of radius 10**9 costs
    what its visible part costs.
    """
    if xc + r < 0 or xc - r > width - 1 or yc + r < 0 or yc - r > height - 1:
        return
    # runs of x in which xc + x, xc - x, yc + x or yc - x is on the raster
    runs = (-xc, width - 1 - xc, xc - width + 1, xc, -yc, height - 1 - yc, yc - height + 1, yc)
    x = 0
    y = r
    p = 1 - r
    while x <= y:
        start = -1
        for k in range(4):
            a = runs[2 * k]
            b = runs[2 * k + 1]
            if b >= x and a <= b:
                s = max(a, x)
                if start < 0 or s < start:
                    start = s
        if start < 0:
            return
        end = start
        for k in range(4):
            if runs[2 * k] <= start and runs[2 * k + 1] > end:
                end = runs[2 * k + 1]
        if start != x:
            x = start
            if x >= r:  # y(x) <= 0 < x: past the diagonal
                return
            y, p = circle_state(x, r)
        while x <= end and x <= y:
            plot8(buf, packed, width, height, xc, yc, x, y, color)
            x, y, p = circle_step(x, y, p)


@kernel
def draw_circle(buf, packed, width, height, xc, yc, r, color):
    """Draw one midpoint circle."""
    midpoint_circle(buf, packed, width, height, xc, yc, r, color)


@kernel
def draw_circles(buf, packed, width, height, circles, colors):
    """Draw N circles, ``circles[i] = (xc, yc, r)``, with ``colors[i]`` (or
    ``colors[0]`` for all)."""
    one = colors.shape[0] == 1
    for i in range(circles.shape[0]):
        c = circles[i]
        midpoint_circle(buf, packed, width, height, c[0], c[1], c[2], colors[0] if one else colors[i])


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
    px = 2 r_y^2 x, py = 2 r_x^2 y."""
    rx2 = rx * rx
    ry2 = ry * ry
    return 0, ry, 4 * ry2 - 4 * rx2 * ry + rx2, 0, 2 * rx2 * ry


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


@inline
def midpoint_ellipse(buf, packed, width, height, xc, yc, rx, ry, color):
    """Draw the axis-aligned ellipse with semi-axes rx, ry >= 0 about (xc, yc).

    Region 1 runs while 2 r_y^2 x < 2 r_x^2 y, region 2 while y > 0.  When the
    ellipse is so flat that region 2 reaches y = 0 before x = r_x (region 2 can
    advance x by at most one per row), the run along y = 0 is completed to x = r_x
    (the "tip"); for r_y = 0 the ellipse is the segment from xc - rx to xc + rx.
    """
    if xc + rx < 0 or xc - rx > width - 1 or yc + ry < 0 or yc - ry > height - 1:
        return
    rx2 = rx * rx
    ry2 = ry * ry
    x, y, p, px, py = ellipse_region1_start(rx, ry)
    plot4(buf, packed, width, height, xc, yc, x, y, color)
    while px < py:
        x, y, p, px, py = ellipse_region1_step(x, y, p, px, py, rx2, ry2)
        plot4(buf, packed, width, height, xc, yc, x, y, color)
    p = ellipse_region2_start(x, y, rx2, ry2)
    while y > 0:
        x, y, p, px, py = ellipse_region2_step(x, y, p, px, py, rx2, ry2)
        plot4(buf, packed, width, height, xc, yc, x, y, color)
    while x < rx:
        x += 1
        plot4(buf, packed, width, height, xc, yc, x, 0, color)


@kernel
def draw_ellipse(buf, packed, width, height, xc, yc, rx, ry, color):
    """Draw one midpoint ellipse."""
    midpoint_ellipse(buf, packed, width, height, xc, yc, rx, ry, color)


@kernel
def draw_ellipses(buf, packed, width, height, ellipses, colors):
    """Draw N ellipses, ``ellipses[i] = (xc, yc, rx, ry)``, with ``colors[i]`` (or
    ``colors[0]`` for all)."""
    one = colors.shape[0] == 1
    for i in range(ellipses.shape[0]):
        e = ellipses[i]
        midpoint_ellipse(buf, packed, width, height, e[0], e[1], e[2], e[3],
                         colors[0] if one else colors[i])


@kernel
def ellipse_trace(rx, ry, out):
    """Fill ``out`` (int64, at least rx + ry + 1 rows) with the notes' tables: per
    row the region, 4 p_k (the decision parameter times 4; 0 for the tip), the
    point (x_k+1, y_k+1), 2 r_y^2 x_k+1 and 2 r_x^2 y_k+1.  Returns the row count."""
    rx2 = rx * rx
    ry2 = ry * ry
    x, y, p, px, py = ellipse_region1_start(rx, ry)
    n = 0
    while px < py:
        p_k = p
        x, y, p, px, py = ellipse_region1_step(x, y, p, px, py, rx2, ry2)
        out[n, 0] = REGION_1
        out[n, 1] = p_k
        out[n, 2] = x
        out[n, 3] = y
        out[n, 4] = px
        out[n, 5] = py
        n += 1
    p = ellipse_region2_start(x, y, rx2, ry2)
    while y > 0:
        p_k = p
        x, y, p, px, py = ellipse_region2_step(x, y, p, px, py, rx2, ry2)
        out[n, 0] = REGION_2
        out[n, 1] = p_k
        out[n, 2] = x
        out[n, 3] = y
        out[n, 4] = px
        out[n, 5] = py
        n += 1
    while x < rx:
        x += 1
        px += 2 * ry2
        out[n, 0] = TIP
        out[n, 1] = 0
        out[n, 2] = x
        out[n, 3] = 0
        out[n, 4] = px
        out[n, 5] = 0
        n += 1
    return n
