"""Slow pure-Python reference implementations, written from the notes (chapter 2),
plus small helpers shared by the tests.

Nothing here imports scanline's drawing or tracing code: the references are the
independent side of every cross-check.
"""

import math
import os
from fractions import Fraction

import numpy as np
from hypothesis import HealthCheck, settings

#: Settings for hypothesis tests: no deadline (the first call of a numba kernel may
#: load it from the cache), no example database in the working tree.  Under CI
#: (``CI`` set) the examples are derandomized -- the same sequence on every run, so a
#: CI result can be reproduced; runs by hand draw new examples each time.
HYPOTHESIS = settings(
    max_examples=200,
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.too_slow],
    derandomize=bool(os.environ.get("CI")),
)


def gl_context():
    """A headless OpenGL context (moderngl on Mesa's EGL, llvmpipe): the peer of the
    rasterizer tests.  Outside CI a missing driver skips the test; in CI
    (``CI=true``) it fails, as a reference that cannot start must."""
    try:
        import moderngl

        return moderngl.create_standalone_context(backend="egl")
    except Exception as error:            # no moderngl, no EGL, no Mesa driver
        import pytest

        if os.environ.get("CI") == "true":
            pytest.fail(f"moderngl / Mesa EGL cannot start in CI: {error}")
        pytest.skip(f"moderngl / Mesa EGL unavailable: {error}")


def peer(module):
    """Import the independent reference ``module`` (a peer library named in the test
    extras).  Outside CI a missing peer skips the test; in CI (``CI=true``) it fails,
    as a reference that cannot start must."""
    import importlib

    import pytest

    try:
        return importlib.import_module(module)
    except ImportError as error:
        if os.environ.get("CI") == "true":
            pytest.fail(f"the reference {module} cannot be imported in CI: {error}")
        pytest.skip(f"the reference {module} is not installed: {error}")


MODES = ("1", "L", "RGB", "RGBA", "P")


# -- reading a frame buffer back ------------------------------------------------------
def lit(fb, background=None):
    """The set of (x, y) device pixels whose value differs from ``background``
    (default: the value of a freshly cleared black frame buffer).

    Works from ``to_array()`` only: row r of the image is y = height - 1 - r.
    """
    a = fb.to_array()
    h = a.shape[0]
    if a.ndim == 3:
        bg = np.zeros(a.shape[2], a.dtype) if background is None else np.asarray(background, a.dtype)
        if fb.mode == "RGBA" and background is None:
            bg[3] = 255
        mask = (a != bg).any(axis=2)
    else:
        bg = 0 if background is None else background
        mask = a != bg
    rows, cols = np.nonzero(mask)
    return {(int(c), int(h - 1 - r)) for r, c in zip(rows, cols)}


def in_frame(pixels, width, height):
    """The pixels of ``pixels`` that lie inside a width x height frame buffer."""
    return {(x, y) for x, y in pixels if 0 <= x < width and 0 <= y < height}


def shift(pixels, dx, dy):
    return {(x + dx, y + dy) for x, y in pixels}


def eight_connected(pixels):
    """True if ``pixels`` form one 8-connected component (or are empty)."""
    pixels = set(pixels)
    if not pixels:
        return True
    start = next(iter(pixels))
    seen = {start}
    stack = [start]
    while stack:
        x, y = stack.pop()
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                q = (x + dx, y + dy)
                if q in pixels and q not in seen:
                    seen.add(q)
                    stack.append(q)
    return len(seen) == len(pixels)


def round_half_up(v):
    """The notes' rounding to the nearest integer, halves up, for Fractions/ints."""
    return math.floor(v + Fraction(1, 2))


# -- lines ----------------------------------------------------------------------------
def bresenham(x0, y0, x1, y1):
    """Bresenham's line algorithm as the notes give it (Q.2), generalised to all
    octants the way the notes describe: sample the major axis at unit steps starting
    from the left endpoint (x major, |m| <= 1) or the lower endpoint (y major);
    p0 = 2*dminor - dmajor; p < 0 keeps the minor coordinate and adds 2*dminor,
    otherwise the minor coordinate steps (towards the other endpoint) and p adds
    2*dminor - 2*dmajor.  Returns the list of pixels in drawing order, and the list of
    decision parameters p_0 .. p_{n-1}."""
    if abs(y1 - y0) <= abs(x1 - x0):  # x is the major axis
        if x0 > x1:
            x0, y0, x1, y1 = x1, y1, x0, y0
        dx, dy = x1 - x0, abs(y1 - y0)
        sy = 1 if y1 >= y0 else -1
        p = 2 * dy - dx
        x, y = x0, y0
        pts, ps = [(x, y)], []
        for _ in range(dx):
            ps.append(p)
            x += 1
            if p < 0:
                p += 2 * dy
            else:
                y += sy
                p += 2 * dy - 2 * dx
            pts.append((x, y))
        return pts, ps
    if y0 > y1:  # y is the major axis: start from the lower endpoint
        x0, y0, x1, y1 = x1, y1, x0, y0
    dy, dx = y1 - y0, abs(x1 - x0)
    sx = 1 if x1 >= x0 else -1
    p = 2 * dx - dy
    x, y = x0, y0
    pts, ps = [(x, y)], []
    for _ in range(dy):
        ps.append(p)
        y += 1
        if p < 0:
            p += 2 * dx
        else:
            x += sx
            p += 2 * dx - 2 * dy
        pts.append((x, y))
    return pts, ps


def bresenham_pixels(x0, y0, x1, y1):
    return set(bresenham(x0, y0, x1, y1)[0])


def bresenham_minor(i, du, dw):
    """Closed form of Bresenham's minor-axis offset after i steps (0 <= dw <= du):
    the ideal line is at w = i*dw/du; the pixel chosen is the nearest one, and at an
    exact tie (half-way) the one farther from the start.  I.e. round half up."""
    if du == 0:
        return 0
    return (2 * dw * i + du) // (2 * du)


def bresenham_visible(x0, y0, x1, y1, width, height):
    """The in-frame part of the Bresenham line, for any endpoints (even +-10**9):
    only the major-axis positions inside the frame are visited, each with the closed
    form ``bresenham_minor``."""
    out = set()
    if abs(y1 - y0) <= abs(x1 - x0):
        if x0 > x1:
            x0, y0, x1, y1 = x1, y1, x0, y0
        du, dw, sw = x1 - x0, abs(y1 - y0), (1 if y1 >= y0 else -1)
        for x in range(max(x0, 0), min(x1, width - 1) + 1):
            y = y0 + sw * bresenham_minor(x - x0, du, dw)
            if 0 <= y < height:
                out.add((x, y))
        return out
    if y0 > y1:
        x0, y0, x1, y1 = x1, y1, x0, y0
    du, dw, sw = y1 - y0, abs(x1 - x0), (1 if x1 >= x0 else -1)
    for y in range(max(y0, 0), min(y1, height - 1) + 1):
        x = x0 + sw * bresenham_minor(y - y0, du, dw)
        if 0 <= x < width:
            out.add((x, y))
    return out


def tie_steps(x0, y0, x1, y1):
    """Major-axis positions where the ideal line passes exactly half-way between two
    pixels of the minor axis (where tie rules matter).  Returned as a set of major
    coordinates (x for x-major lines, y for y-major lines)."""
    dx, dy = x1 - x0, y1 - y0
    if abs(dy) <= abs(dx):
        if dx == 0:
            return set()
        return {x for x in range(min(x0, x1), max(x0, x1) + 1)
                if (Fraction(dy, dx) * (x - x0)).denominator == 2}
    return {y for y in range(min(y0, y1), max(y0, y1) + 1)
            if (Fraction(dx, dy) * (y - y0)).denominator == 2}


def dda(x0, y0, x1, y1):
    """The notes' DDA (Q.1): steps = max(|dx|, |dy|); x and y start at the first
    endpoint and are incremented in floating point by dx/steps and dy/steps; each
    point is rounded to the nearest pixel, halves up (floor(v + 0.5))."""
    dx, dy = x1 - x0, y1 - y0
    steps = max(abs(dx), abs(dy))
    if steps == 0:
        return [(x0, y0)]
    xinc, yinc = dx / steps, dy / steps
    x, y = float(x0), float(y0)
    pts = []
    for _ in range(steps + 1):
        pts.append((math.floor(x + 0.5), math.floor(y + 0.5)))
        x += xinc
        y += yinc
    return pts


def exact_line(x0, y0, x1, y1):
    """The DDA in exact arithmetic: pixel k is round_half_up(p0 + k/steps * (p1 - p0))."""
    dx, dy = x1 - x0, y1 - y0
    steps = max(abs(dx), abs(dy))
    if steps == 0:
        return [(x0, y0)]
    return [(round_half_up(x0 + Fraction(dx * k, steps)), round_half_up(y0 + Fraction(dy * k, steps)))
            for k in range(steps + 1)]


# -- circles --------------------------------------------------------------------------
def circle_octant(r):
    """The notes' midpoint circle (Q.4): start at (0, r) with p0 = 1 - r; at each step
    x + 1; p < 0 keeps y and adds 2x_{k+1} + 1, otherwise y - 1 and adds
    2x_{k+1} + 1 - 2y_{k+1}; plot while x <= y.  Returns octant points and p_k's."""
    x, y, p = 0, r, 1 - r
    pts, ps = [], []
    while x <= y:
        pts.append((x, y))
        ps.append(p)
        x += 1
        if p < 0:
            p += 2 * x + 1
        else:
            y -= 1
            p += 2 * x + 1 - 2 * y
    return pts, ps


def mirror8(points, xc=0, yc=0):
    out = set()
    for x, y in points:
        for a, b in ((x, y), (y, x)):
            for sa in (1, -1):
                for sb in (1, -1):
                    out.add((xc + sa * a, yc + sb * b))
    return out


def mirror4(points, xc=0, yc=0):
    return {(xc + sa * x, yc + sb * y) for x, y in points for sa in (1, -1) for sb in (1, -1)}


def circle_pixels(xc, yc, r):
    return mirror8(circle_octant(r)[0], xc, yc)


def circle_y(x, r):
    """The midpoint circle's y at column x of the octant, in closed form.

    The algorithm keeps the midpoint below the chosen pixel inside the circle and the
    midpoint above it not inside: (2y-1)**2 < 4(r**2 - x**2) <= (2y+1)**2, whose
    integer solution is y = floor((isqrt(4s - 1) + 1) / 2), s = r**2 - x**2 > 0.
    Returns -1 when x >= r > 0 (no octant point there)."""
    if r == 0:
        return 0
    s = r * r - x * x
    if s <= 0:
        return -1
    y = (math.isqrt(4 * s - 1) + 1) // 2
    assert (2 * y - 1) ** 2 < 4 * s <= (2 * y + 1) ** 2
    return y


def circle_visible(xc, yc, r, width, height):
    """The in-frame pixels of the midpoint circle, for any size (r up to 10**9):
    every pixel is (xc +- x, yc +- y) or (xc +- y, yc +- x) for an octant point
    (x, y(x)), x <= y(x); the first kind is found by scanning the frame's columns
    (x = |X - xc|), the second by scanning its rows (x = |Y - yc|)."""
    out = set()
    for X in range(width):
        a = abs(X - xc)
        y = circle_y(a, r)
        if a <= y:
            out |= {(X, yc + y), (X, yc - y)}
    for Y in range(height):
        a = abs(Y - yc)
        y = circle_y(a, r)
        if a <= y:
            out |= {(xc + y, Y), (xc - y, Y)}
    return in_frame(out, width, height)


# -- ellipses -------------------------------------------------------------------------
def ellipse_quadrant(rx, ry):
    """The notes' midpoint ellipse (Q.6) in exact Fractions, first quadrant.

    Region 1 from (0, ry): p1_0 = ry^2 - rx^2 ry + rx^2/4; x + 1 each step; p1 < 0
    keeps y and adds 2ry^2 x_{k+1} + ry^2, otherwise y - 1 and adds
    2ry^2 x_{k+1} - 2rx^2 y_{k+1} + ry^2; continue until 2ry^2 x >= 2rx^2 y.
    Region 2 from the last point: p2_0 = ry^2 (x + 1/2)^2 + rx^2 (y - 1)^2 - rx^2 ry^2;
    y - 1 each step; p2 > 0 keeps x and adds rx^2 - 2rx^2 y_{k+1}, otherwise x + 1
    and adds 2ry^2 x_{k+1} - 2rx^2 y_{k+1} + rx^2; until y = 0.
    Then scanline's documented "tip": if x < rx at y = 0, the run to (rx, 0).

    Returns a list of rows (region, p_k, x_{k+1}, y_{k+1}, 2ry^2 x_{k+1}, 2rx^2 y_{k+1})
    and the start point is (0, ry)."""
    rx2, ry2 = rx * rx, ry * ry
    x, y = 0, ry
    p = Fraction(ry2) - rx2 * ry + Fraction(rx2, 4)
    rows = []
    while 2 * ry2 * x < 2 * rx2 * y:
        pk = p
        x += 1
        if p < 0:
            p += 2 * ry2 * x + ry2
        else:
            y -= 1
            p += 2 * ry2 * x - 2 * rx2 * y + ry2
        rows.append(("1", pk, x, y, 2 * ry2 * x, 2 * rx2 * y))
    p = ry2 * (x + Fraction(1, 2)) ** 2 + rx2 * (y - 1) ** 2 - rx2 * ry2
    while y > 0:
        pk = p
        y -= 1
        if p > 0:
            p += rx2 - 2 * rx2 * y
        else:
            x += 1
            p += 2 * ry2 * x - 2 * rx2 * y + rx2
        rows.append(("2", pk, x, y, 2 * ry2 * x, 2 * rx2 * y))
    while x < rx:
        x += 1
        rows.append(("tip", None, x, 0, 2 * ry2 * x, 0))
    return rows


def ellipse_pixels(xc, yc, rx, ry):
    pts = [(0, ry)] + [(r[2], r[3]) for r in ellipse_quadrant(rx, ry)]
    return mirror4(pts, xc, yc)
