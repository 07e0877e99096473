"""The visible part of a midpoint circle or ellipse of any size and position, exactly.

The conic kernels (:mod:`scanline._kernels.conics`, :mod:`scanline._kernels.curved`)
keep their decision parameters in 64-bit integers, which holds for centers within
+-2**30, circles of radius up to 2**30 and ellipses with r_x r_y <= 2**29.  Beyond
that (a circle of radius 2**40 whose outline crosses the frame, a center at x = -1e12
with a radius reaching in) this module computes the same pixels in Python integers,
with the decision rule of the notes (chapter 2, Q.4-Q.6; Hearn & Baker, sections 3-5
and 3-6) in closed form per visible column and row, so that a conic costs
O(width + height) whatever its radius, never O(r).

Circle.  The octant loop (x from 0, y from r, p_0 = 1 - r) keeps the invariant
(2y - 1)**2 < 4(r**2 - x**2) <= (2y + 1)**2, so the octant point of column x is
y(x) = (isqrt(4 (r**2 - x**2) - 1) + 1) // 2, for x <= y(x) (the kernel's
``circle_state``, here without its 2**62 bound).

Ellipse.  With f(x, y) = r_y^2 x^2 + r_x^2 y^2 - r_x^2 r_y^2, region 1 moves to
column x + 1 and keeps y while f(x + 1, y - 1/2) < 0, region 2 moves to row y - 1 and
keeps x while f(x + 1/2, y - 1) > 0.  Written as recurrences these are, exactly,

* region 1: y_{k+1} = max(Y1(x_{k+1}), y_k - 1), Y1(x) = the least y with
  f(x, y + 1/2) >= 0;
* region 2: x_{k+1} = max(x_k, min(X2(y_{k+1}), x_k + 1)), X2(y) = the greatest x
  with f(x - 1/2, y) <= 0.

Y1 drops by at most one per column up to x* = r_x^2 / sqrt(r_x^2 + r_y^2), where the
ellipse's slope is -1, so region 1 is y = Y1(x) there (it ends where
r_y^2 x >= r_x^2 Y1(x), a monotone test found by bisection); X2 grows by at most one
per row below y* = r_y^2 / sqrt(r_x^2 + r_y^2), so once region 2 is at a row y_e
below y*, x(y) = max(x_e, min(X2(y), x_e + y_e - y)) (x behind X2 catches up one
column a row; x ahead of it waits for it).  Between the two the kernel's own step
(``ellipse_next``, run as Python on Python integers) is followed, a few steps; a flat
ellipse's tip (the run along y = 0 to x = r_x) closes the quadrant.

References
----------
D. Hearn and M. P. Baker, *Computer Graphics*, C version, 2nd ed., sections 3-5 (the
midpoint circle algorithm) and 3-6 (the midpoint ellipse algorithm); J. E. Bresenham,
"A linear algorithm for incremental digital display of circular arcs", CACM 20(2),
1977; M. L. V. Pitteway, "Algorithm for drawing ellipses or hyperbolae with a digital
plotter", Computer Journal 10(3), 1967.
"""

from decimal import Decimal, localcontext
from fractions import Fraction
from math import isqrt
from typing import Sequence, Union

import numpy as np
from numpy.typing import NDArray

from .._kernels import conics as kc
from .._kernels._jit import python
from .guard import Exact, clip_parameters

#: A window or box (x0, y0, x1, y1) of integers.
Window = tuple[int, int, int, int]
#: A point of a conic or a path, exact.
Pixel = tuple[int, int]
#: (index, axial steps, diagonal steps) of a point in a conic's pixel sequence.
Steps = tuple[int, int, int]
#: A leg of an axis-parallel path: start, end, path length at the start, length.
Leg = tuple[Pixel, Pixel, int, int]
#: A real number of any size.
Real = Union[int, float, Fraction]

_next = python(kc.ellipse_next)


def _ceil_div(a: int, b: int) -> int:
    return -(-a // b)


def circle_y(x: int, r: int) -> int:
    """The octant point's row y(x) of the midpoint circle of radius r at column
    0 <= x < r (r = 0: 0)."""
    if r == 0:
        return 0
    return (isqrt(4 * (r * r - x * x) - 1) + 1) // 2


def circle_half_width(d: int, r: int) -> int:
    """The right-most outline pixel (offset from the center) of row offset d of the
    midpoint circle, or -1 beyond it (the kernel's ``circle_half_width``): rows up to
    the diagonal are the octant's columns; above it, the last column x with
    y(x) >= d, 4 x**2 < 4 r**2 - (2d - 1)**2."""
    if d > r:
        return -1
    if r == 0:
        return 0
    if d < r:
        y = circle_y(d, r)
        if d <= y:
            return y
    t = 4 * r * r - (2 * d - 1) * (2 * d - 1)
    return isqrt((t - 1) // 4)


class Quadrant:
    """The first-quadrant points (x, y), x, y >= 0, of the midpoint ellipse with
    integer semi-axes ``rx``, ``ry``, queried per column (region 1) and per row
    (region 2) without stepping the whole quadrant."""

    def __init__(self, rx: int, ry: int) -> None:
        self.rx, self.ry = rx, ry
        self.rx2, self.ry2 = rx * rx, ry * ry
        self.points: list[Pixel] = []          # the stepped part, (x, y) pairs
        self.m = -1               # region 1 is (x, Y1(x)) for 0 <= x <= m
        self.ye, self.xe = 0, 0   # region 2 is (x(y), y) for 0 <= y < ye
        self.tip = rx             # the tip is (x, 0) for tip < x <= rx
        # (index, axial steps, diagonal steps) from (0, ry), in the kernel's order, of
        # the point before region 2's closed form and of the point before the tip
        self.steps: list[Steps] = []           # of self.points
        self.end: Steps = (-1, -1, 0)
        self.before_tip: Steps = self.end
        if rx == 0:               # the segment x = 0, 0 <= y <= ry (region 2 only)
            self.ye, self.xe, self.tip = ry + 1, 0, 0
            return
        if ry == 0:               # the segment y = 0, 0 <= x <= rx (the tip only)
            self.tip = -1
            return
        self._setup()

    # -- closed forms ----------------------------------------------------------------
    def y1(self, x: int) -> int:
        """Y1(x): the least y >= 0 with f(x, y + 1/2) >= 0, 0 <= x <= rx."""
        n = _ceil_div(4 * self.ry2 * (self.rx2 - x * x), self.rx2)
        c = isqrt(n - 1) + 1 if n > 0 else 0
        return c // 2

    def x2(self, y: int) -> int:
        """X2(y): the greatest x >= 0 with f(x - 1/2, y) <= 0, 0 <= y <= ry."""
        s = isqrt(4 * self.rx2 * (self.ry2 - y * y) // self.ry2)
        return (s + 1) // 2

    def _setup(self) -> None:
        rx, ry, rx2, ry2 = self.rx, self.ry, self.rx2, self.ry2
        lo, hi = 0, rx            # the first x where region 1 would end without lag
        while lo < hi:
            mid = (lo + hi) // 2
            if ry2 * mid >= rx2 * self.y1(mid):
                hi = mid
            else:
                lo = mid + 1
        xstar = isqrt(rx2 * rx2 // (rx2 + ry2))
        ystar = isqrt(ry2 * ry2 // (rx2 + ry2))
        m = max(min(lo, xstar) - 1, 0)
        self.m = m
        # step the kernel's loop from (m, Y1(m)) until the closed forms take over
        x, y = m, self.y1(m)
        p = 4 * ry2 * (m + 1) * (m + 1) + rx2 * (2 * y - 1) * (2 * y - 1) - 4 * rx2 * ry2
        px, py = 2 * ry2 * m, 2 * rx2 * y
        region = kc.REGION_1
        last = (m, m - (ry - y), ry - y)
        while True:
            prev = (x, y)
            region, x, y, _, p, px, py = _next(region, x, y, p, px, py, rx, rx2, ry2)
            if region == 0:               # x reached rx on y = 0
                self.tip, self.ye = rx, 0
                return
            before = last
            diagonal = x != prev[0] and y != prev[1]
            last = (last[0] + 1, last[1] + (not diagonal), last[2] + diagonal)
            self.points.append((x, y))
            self.steps.append(last)
            if region == kc.TIP:
                self.tip, self.ye, self.before_tip = x - 1, 0, before
                return
            if region == kc.REGION_2 and y <= ystar:
                self.xe, self.ye, self.end = x, y, last
                if y == 0:
                    self.tip, self.before_tip = x, last
                else:
                    self.tip = self.x2_closed(0)
                    self.before_tip = self._region2(self.tip, 0)
                return

    def _region2(self, x: int, y: int) -> Steps:
        """(index, axial, diagonal) of region 2's closed-form point (x, y), y < ye."""
        i, a, d = self.end
        n, dd = self.ye - y, x - self.xe
        return i + n, a + n - dd, d + dd

    def x2_closed(self, y: int) -> int:
        """Region 2's column at row 0 <= y < ye."""
        if self.rx == 0:
            return 0
        return max(self.xe, min(self.x2(y), self.xe + self.ye - y))

    # -- queries ---------------------------------------------------------------------
    def locate(self, a: int, b: int) -> Steps | None:
        """(i, axial, diagonal) of the quadrant point (a, b): its index in the kernel's
        order from (0, ry) and the axial and diagonal steps that reach it; or None
        when (a, b) is not a point of the quadrant."""
        if 0 <= a <= self.m and self.y1(a) == b:
            return a, a - (self.ry - b), self.ry - b
        for p, st in zip(self.points, self.steps):
            if p == (a, b):
                return st
        if 0 <= b < self.ye and self.x2_closed(b) == a:
            return self._region2(a, b)
        if b == 0 and self.tip < a <= self.rx:
            i, ax, d = self.before_tip
            return i + a - self.tip, ax + a - self.tip, d
        return None

    def column_points(self, x: int) -> int | None:
        """The region-1 point's row in column x (0 <= x <= m), else None."""
        if 0 <= x <= self.m:
            return self.y1(x)
        return None

    def row_point(self, y: int) -> int | None:
        """The region-2 point's column in row y (0 <= y < ye), else None."""
        if 0 <= y < self.ye:
            return self.x2_closed(y)
        return None

    def half_width(self, y: int) -> int:
        """The right-most quadrant point of row y (the fill's extent), or -1."""
        if y < 0 or y > self.ry:
            return -1
        if y == 0 and self.tip < self.rx:
            return self.rx
        best = -1
        if y < self.ye:
            best = self.x2_closed(y)
        for px, py in self.points:
            if py == y and px > best:
                best = px
        if self.m >= 0:
            ym = self.y1(self.m)
            if y == ym:
                best = max(best, self.m)
            elif y > ym:              # the last column of region 1 with Y1(x) >= y
                r = self.rx2 * (4 * self.ry2 - (2 * y - 1) * (2 * y - 1))
                best = max(best, isqrt(_ceil_div(r, 4 * self.ry2) - 1))
        return best


def _in(lo: int, hi: int, v: int) -> bool:
    return lo <= v <= hi


def circle_pixels(xc: int, yc: int, r: int, window: Window) -> NDArray[np.int64]:
    """The pixels of the midpoint circle (integers of any size) inside ``window``
    (x0, y0, x1, y1), as an (N, 2) int64 array of (x, y), each once."""
    x0, y0, x1, y1 = window
    out: set[Pixel] = set()
    if r == 0:
        if _in(x0, x1, xc) and _in(y0, y1, yc):
            out.add((xc, yc))
        return _array(out)
    for swap in (False, True):          # the images (+-x, +-y) by columns, (+-y, +-x) by rows
        a0, a1, ca, b0, b1, cb = (y0, y1, yc, x0, x1, xc) if swap else (x0, x1, xc, y0, y1, yc)
        for a in range(a0, a1 + 1):
            x = abs(a - ca)
            if x < r:
                y = circle_y(x, r)
                if x <= y:
                    for b in (cb + y, cb - y):
                        if _in(b0, b1, b):
                            out.add((b, a) if swap else (a, b))
    return _array(out)


def ellipse_pixels(xc: int, yc: int, rx: int, ry: int, window: Window) -> NDArray[np.int64]:
    """The pixels of the midpoint ellipse (integers of any size) inside ``window``
    (x0, y0, x1, y1), as an (N, 2) int64 array, each once."""
    x0, y0, x1, y1 = window
    q = Quadrant(rx, ry)
    out: set[Pixel] = set()

    def put(a: int, b: int) -> None:
        for col in (xc + a, xc - a):
            for row in (yc + b, yc - b):
                if _in(x0, x1, col) and _in(y0, y1, row):
                    out.add((col, row))

    for col in range(x0, x1 + 1):       # region 1: one point per column
        x = abs(col - xc)
        y = q.column_points(x)
        if y is not None:
            put(x, y)
    for row in range(y0, y1 + 1):       # region 2: one point per row
        y = abs(row - yc)
        xr = q.row_point(y)
        if xr is not None:
            put(xr, y)
    for a, b in q.points:
        put(a, b)
    if _in(y0, y1, yc) and q.tip < rx:   # the tip's run along y = 0
        for col in range(x0, x1 + 1):
            if q.tip < abs(col - xc) <= rx:
                out.add((col, yc))
    return _array(out)


def half_widths(yc: int, rx: int, ry: int, height: int, circle: bool
                ) -> list[tuple[int, int, int]]:
    """The right-most outline pixel w (offset from the center) of each visible scan
    line that the conic reaches: a list of (row, y - yc, w), the filled area's span
    being xc - w .. xc + w (the kernels' ``w`` table)."""
    q = None if circle else Quadrant(rx, ry)
    out: list[tuple[int, int, int]] = []
    for row in range(height):
        d = abs(row - yc)
        w = circle_half_width(d, rx) if q is None else q.half_width(d)
        if w >= 0:
            out.append((row, row - yc, w))
    return out


def spans(xc: int, yc: int, rx: int, ry: int, width: int, height: int,
          circle: bool) -> NDArray[np.int64]:
    """The filled conic's span of each visible scan line: an (N, 3) int64 array of
    rows (y, x0, x1), from the left-most to the right-most outline pixel, clipped to
    columns -3 .. width + 2 (see :func:`clipped`)."""
    rows: list[tuple[int, int, int]] = []
    for row, _, w in half_widths(yc, rx, ry, height, circle):
        rows += clipped(row, xc - w, xc + w, width)
    return np.array(rows, np.int64).reshape(-1, 3)


def clipped(row: int, x0: int, x1: int, width: int) -> list[tuple[int, int, int]]:
    """The span x0 .. x1 of ``row`` (integers of any size) clipped to columns
    -3 .. width + 2 as spans (row, a, b) with b - a even (the kernels draw a span as
    a flat ellipse about an integer center): a clipped end moves one column further
    out, or an odd span inside the frame is split in two.  [] when it misses the
    frame."""
    if x1 < 0 or x0 > width - 1 or x0 > x1:
        return []
    a, b = max(x0, -2), min(x1, width + 1)
    if (b - a) % 2 == 0:
        return [(row, a, b)]
    if a > x0:
        return [(row, a - 1, b)]
    if b < x1:
        return [(row, a, b + 1)]
    return [(row, a, a), (row, a + 1, b)]


class CircleQuadrant:
    """The midpoint circle's first quadrant in the order of its pixel sequence (the
    octant from (0, r), then its mirror image in the diagonal back to (r, 0), the
    diagonal pixel once), with :meth:`Quadrant.locate`."""

    def __init__(self, r: int) -> None:
        self.r = r
        lo, hi = 0, max(r - 1, 0)         # the octant's last column: x <= y(x)
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if mid <= circle_y(mid, r):
                lo = mid
            else:
                hi = mid - 1
        self.xd = lo
        self.yd = circle_y(lo, r)
        self.dup = self.yd == lo

    def locate(self, a: int, b: int) -> Steps | None:
        """As :meth:`Quadrant.locate`: (i, axial, diagonal) of the point (a, b), or
        None when it is not a point of the quadrant."""
        r, xd, yd = self.r, self.xd, self.yd
        if r == 0:
            return (0, 0, 0) if a == b == 0 else None
        if a <= b:
            if a <= xd and circle_y(a, r) == b:
                return a, a - (r - b), r - b
            return None
        if b <= xd and circle_y(b, r) == a:
            n, d = xd - b, a - yd
            join = 0 if self.dup else 1           # one diagonal step across x = y
            return (xd + 1 + n - self.dup, xd - (r - yd) + n - d,
                    r - yd + join + d)
        return None


#: The four quadrants of a conic's pixel sequence (counterclockwise from (rx, 0)):
#: signs, and whether the quadrant runs against the kernel's order.
_PIECES = (((1, 1), True), ((-1, 1), False), ((-1, -1), True), ((1, -1), False))


def sequence_runs(xc: int, yc: int, rx: int, ry: int, circle: bool, window: Window
                  ) -> list[tuple[NDArray[np.int64], int, int, int]]:
    """The visible part of the conic's pixel sequence (the order in which a line
    type numbers the midpoint pixels: counterclockwise from (xc + rx, yc), each
    quadrant's pixels once, :func:`scanline.draw.strokes.conic_pixels`), as runs of
    consecutive pixels inside ``window``: a list of ((K, 2) int64 array, k, axial,
    diagonal) with k the index of the run's first pixel in the whole sequence and
    axial, diagonal the unit and diagonal steps before it (its arc length is
    axial + diagonal sqrt 2).  Integers of any size; O(window) work."""
    q: CircleQuadrant | Quadrant = CircleQuadrant(rx) if circle else Quadrant(rx, ry)
    last = q.locate(rx, 0)          # the quadrant's last point
    assert last is not None
    n, total_a, total_d = last
    found: dict[int, tuple[int, int, int, int]] = {}
    for x, y in (circle_pixels(xc, yc, rx, window) if circle
                 else ellipse_pixels(xc, yc, rx, ry, window)).tolist():
        for piece, ((sx, sy), backwards) in enumerate(_PIECES):
            at = q.locate(sx * (x - xc), sy * (y - yc)) if sx * (x - xc) >= 0 <= sy * (y - yc) \
                else None
            if at is None:
                continue
            i, a, d = at
            if backwards:
                i, a, d = n - i, total_a - a, total_d - d
            k = piece * n + i
            if k < 4 * n or n == 0:
                found[k] = (x, y, piece * total_a + a, piece * total_d + d)
    runs: list[tuple[list[Pixel], int, int, int]] = []
    for k in sorted(found):
        x, y, a, d = found[k]
        if runs and runs[-1][1] + len(runs[-1][0]) == k:
            runs[-1][0].append((x, y))
        else:
            runs.append(([(x, y)], k, a, d))
    return [(np.array(p, np.int64).reshape(-1, 2), k, a, d) for p, k, a, d in runs]


def _array(pixels: set[Pixel]) -> NDArray[np.int64]:
    return np.array(sorted(pixels), np.int64).reshape(-1, 2)


# -- the ideal conic near the frame (strokes, antialiasing) -------------------------

#: Fixed-point scale of the local samples: coordinates are integers times 2**-40.
_BITS = 40
_ONE = 1 << _BITS
#: Bisection depth of a chord, at most (each halving quarters its deviation).
_DEPTH = 24


def _branch(a: int, b: int, t: int) -> int:
    """b sqrt(1 - t**2 / a**2) for fixed-point a > 0, b and |t| <= a."""
    n = b * b * (a * a - t * t)
    return isqrt(n // (a * a)) if n > 0 else 0


def _fixed(value: Real) -> int:
    """A real number (int, float, Fraction) in fixed point, to the nearest 2**-40."""
    return round(Fraction(value) * _ONE)


_SIGNS = ((1, 1), (-1, 1), (-1, -1), (1, -1))   # quadrants I..IV, counterclockwise


def _quadrant(u: Exact, v: Exact) -> int:
    """The quadrant (0..3) a point (u, v) relative to the center belongs to; an axis
    point starts the quadrant that leaves it counterclockwise."""
    if v == 0:
        return 0 if u > 0 else 2
    if u == 0:
        return 1 if v > 0 else 3
    return (0 if u > 0 else 1) if v > 0 else (2 if u < 0 else 3)


def _key(q: int, u: int, v: int) -> tuple[int, int, int]:
    """The counterclockwise order of points of quadrant q: x falls in I and II and
    rises in III and IV, y the other way round in II and IV."""
    su, sv = _SIGNS[q]
    return (q, -sv * u, su * v)


def local_runs(xc: Real, yc: Real, rx: Real, ry: Real, window: Window, tolerance: float = 0.025
               ) -> list[tuple[NDArray[np.float64], bool, tuple[Fraction, Fraction]]]:
    """The ideal ellipse (xc, yc, rx, ry) (reals of any size, rx, ry > 0) inside
    the ``window`` (x0, y0, x1, y1) of integers, as polylines within ``tolerance``
    pixel of it, counterclockwise: a list of ((K, 2) float64 array, closed, start),
    ``start`` the first vertex exactly, relative to the center (two Fractions).

    The ellipse is sampled exactly (fixed point, 2**-40 pixel) at the window's
    integer columns where its slope is at most 1 and at its integer rows where it is
    at least 1, and at its axis points; each quadrant's part inside the window is one
    piece (the quadrant's arc is monotone in x and y), pieces meet at axis points
    inside the window, and chords are halved until their deviation is within
    ``tolerance``.  Cost O(window width + height) samples, whatever the radii.
    """
    x0, y0, x1, y1 = window
    xc, yc, rx, ry = (_fixed(c) for c in (xc, yc, rx, ry))
    if rx <= 0 or ry <= 0:
        return []
    pts: dict[Pixel, tuple[int, int, int]] = {}

    def add(u: int, v: int) -> None:
        pts[(u, v)] = _key(_quadrant(u, v), u, v)

    for swap in (False, True):    # by columns where |slope| <= 1, by rows where >= 1
        a0, a1, ca, ra, b0, b1, cb, rb = ((y0, y1, yc, ry, x0, x1, xc, rx) if swap
                                          else (x0, x1, xc, rx, y0, y1, yc, ry))
        for a in range(a0, a1 + 1):
            t = a * _ONE - ca
            if abs(t) <= ra:
                o = _branch(ra, rb, abs(t))
                if rb * rb * abs(t) <= ra * ra * o:
                    for s in (o, -o):
                        if b0 * _ONE <= cb + s <= b1 * _ONE:
                            add(*((s, t) if swap else (t, s)))
    for u, v in ((rx, 0), (0, ry), (-rx, 0), (0, -ry)):
        if x0 * _ONE <= xc + u <= x1 * _ONE and y0 * _ONE <= yc + v <= y1 * _ONE:
            add(u, v)
    order = sorted(pts, key=lambda p: pts[p])
    if not order:
        return []

    def starts_quadrant(p: Pixel) -> bool:
        return p[0] == 0 or p[1] == 0

    def linked(p: Pixel, q: Pixel) -> bool:
        a, b = pts[p][0], pts[q][0]
        return a == b or ((a + 1) % 4 == b and starts_quadrant(q))

    # cut the cyclic sequence where it leaves the window (and between its last and
    # first point when all of them are in one quadrant: that is no way round)
    cuts = [i for i in range(len(order)) if not linked(order[i - 1], order[i])
            or i == 0 and pts[order[-1]][0] == pts[order[0]][0]]
    if not cuts:
        runs, closed = [order], True
    else:
        twice = order + order               # the last run wraps round to the first
        runs = [twice[a:b] for a, b in zip(cuts, cuts[1:] + [cuts[0] + len(order)])]
        runs = [r for r in runs if len(r) > 1]    # a point that only grazes it
        closed = False

    def bisect(p: Pixel, q: Pixel, depth: int, out: list[Pixel]) -> None:
        du, dv = q[0] - p[0], q[1] - p[1]
        su, sv = _SIGNS[pts[p][0]]      # the arc from p on is in p's quadrant
        if abs(du) >= abs(dv):
            mu = (p[0] + q[0]) // 2
            m = (mu, sv * _branch(rx, ry, abs(mu)))
        else:
            mv = (p[1] + q[1]) // 2
            m = (su * _branch(ry, rx, abs(mv)), mv)
        length = (du * du + dv * dv) ** 0.5
        dev = abs(du * (m[1] - p[1]) - dv * (m[0] - p[0])) / length if length else 0.0
        if depth < _DEPTH and dev > tolerance * _ONE:
            pts.setdefault(m, pts[p])
            bisect(p, m, depth + 1, out)
            out.append(m)
            bisect(m, q, depth + 1, out)

    out_runs = []
    for run in runs:
        seq = run + [run[0]] if closed else run
        fine = [seq[0]]
        for p, q in zip(seq, seq[1:]):
            bisect(p, q, 0, fine)
            fine.append(q)
        if closed:
            fine.pop()
        xy = np.array([[(xc + u) / _ONE, (yc + v) / _ONE] for u, v in fine], np.float64)
        out_runs.append((xy, closed, (Fraction(fine[0][0], _ONE), Fraction(fine[0][1], _ONE))))
    return out_runs


# -- arc length (the dashes of wide and antialiased far conics) ---------------------

def _carlson(x: Decimal, y: Decimal, z: Decimal, r: Decimal, rd: bool) -> Decimal:
    """Carlson's symmetric elliptic integral R_F(x, y, z) (``rd`` False) or
    R_D(x, y, z) (``rd`` True, z > 0) in the current decimal context, relative error
    about ``r``: the duplication theorem until the arguments agree to r**(1/6), then
    the fifth-order series (B. C. Carlson, "Numerical computation of real or complex
    elliptic integrals", Numerical Algorithms 10, 13-26, 1995)."""
    a0 = (x + y + (3 * z if rd else z)) / (5 if rd else 3)
    q = max(abs(a0 - x), abs(a0 - y), abs(a0 - z)) / ((r / 4 if rd else 3 * r) ** (Decimal(1) / 6))
    x0, y0, a, f, total = x, y, a0, Decimal(1), Decimal(0)
    while f * q >= abs(a):
        sx, sy, sz = x.sqrt(), y.sqrt(), z.sqrt()
        lam = sx * sy + sy * sz + sz * sx
        if rd:
            total += f / (sz * (z + lam))
        f /= 4
        x, y, z, a = (x + lam) / 4, (y + lam) / 4, (z + lam) / 4, (a + lam) / 4
    X, Y = (a0 - x0) * f / a, (a0 - y0) * f / a
    if not rd:
        Z = -X - Y
        e2, e3 = X * Y - Z * Z, X * Y * Z
        return (1 - e2 / 10 + e3 / 14 + e2 * e2 / 24 - 3 * e2 * e3 / 44) / a.sqrt()
    Z = -(X + Y) / 3
    xy, z2 = X * Y, Z * Z
    e2, e3, e4, e5 = xy - 6 * z2, (3 * xy - 8 * z2) * Z, 3 * (xy - z2) * z2, xy * z2 * Z
    series = (1 - 3 * e2 / 14 + e3 / 6 + 9 * e2 * e2 / 88 - 3 * e4 / 22 - 9 * e2 * e3 / 52
              + 3 * e5 / 26)
    return f * series / (a * a.sqrt()) + 3 * total


def _from_minor(major: Decimal, minor: Decimal, t: Decimal, w: Decimal, r: Decimal) -> Decimal:
    """The arc length of the ellipse of semi-axes ``major`` >= ``minor`` > 0 from its
    minor-axis point to the point at (t, w) >= 0 along the (major, minor) axes:
    major E(psi | m), m = 1 - minor**2 / major**2, with sin psi : cos psi =
    t / major : w / minor (no cancellation near either axis), by
    E = s R_F(c**2, c**2 + k**2 s**2, 1) - m s**3 R_D(...) / 3, k = minor / major."""
    k2 = (minor / major) ** 2
    sr, cr = t / major, w / minor
    n = sr * sr + cr * cr
    s2, c2 = sr * sr / n, cr * cr / n
    if s2 == 0:
        return Decimal(0)
    y = c2 + k2 * s2
    s = s2.sqrt()
    one = Decimal(1)
    return major * (s * _carlson(c2, y, one, r, False)
                    - (1 - k2) * s * s2 * _carlson(c2, y, one, r, True) / 3)


def arc_length(rx: int, ry: int, u: Fraction, v: Fraction) -> Fraction:
    """The arc length of the ideal ellipse (integer semi-axes rx, ry > 0 of any
    size) counterclockwise from (rx, 0) to its point (u, v) (relative to the center,
    exact Fractions within 2**-40 of the curve, e.g. a sample of
    :func:`local_runs`), as a Fraction: whole quadrants of the complete integral
    and the incomplete one in the point's quadrant, by Carlson's R_F and R_D in
    decimals of as many digits as the length has plus 30 (so the length is exact to
    about 10**-30 pixel beyond the point's own 2**-40)."""
    major, minor = max(rx, ry), min(rx, ry)
    q = _quadrant(u, v)
    a, b = abs(u), abs(v)                       # its image in quadrant I
    t, w = (a, b) if rx >= ry else (b, a)       # along the major and the minor axis
    # quadrants II and IV start on the y-axis point: the minor one when rx >= ry
    starts_minor = (q % 2 == 1) == (rx >= ry)
    with localcontext() as ctx:
        ctx.prec = len(str(major)) + 30
        r = Decimal(10) ** (-ctx.prec)
        big, small = Decimal(major), Decimal(minor)
        part = _from_minor(big, small, _dec(t), _dec(w), r)
        quarter = _from_minor(big, small, big, Decimal(0), r)
        return Fraction(q * quarter + (part if starts_minor else quarter - part))


def _dec(c: Fraction) -> Decimal:
    """A Fraction as a decimal of the current precision."""
    return Decimal(c.numerator) / Decimal(c.denominator)


# -- dashes along a degenerate ellipse ---------------------------------------------------

def degenerate_path(xc: int, yc: int, rx: int, ry: int) -> list[Pixel]:
    """The turning points, in order, of the closed path a degenerate ellipse (integers,
    rx = 0 or ry = 0) is stroked along: its curve (xc + rx cos t, yc + ry sin t) from
    t = 0, as the kernels' polygon (:func:`scanline.draw.strokes.conic_polyline`)
    runs it -- for ry = 0 from (xc + rx, yc) to (xc - rx, yc) and back, for rx = 0
    from (xc, yc) up to (xc, yc + ry), down to (xc, yc - ry) and back to (xc, yc)."""
    if ry == 0:
        return [(xc + rx, yc), (xc - rx, yc)]
    return [(xc, yc), (xc, yc + ry), (xc, yc - ry)]


def _legs(path: Sequence[Pixel]) -> tuple[list[Leg], int]:
    """The legs of the closed axis-parallel path: (start, end, path length at the
    start, length), exact, and the path's whole length."""
    legs: list[Leg] = []
    at = 0
    for i, p in enumerate(path):
        q = path[(i + 1) % len(path)]
        n = abs(q[0] - p[0]) + abs(q[1] - p[1])
        legs.append((p, q, at, n))
        at += n
    return legs, at


def _visible(legs: list[Leg], box: tuple[Exact, Exact, Exact, Exact]
             ) -> list[tuple[Fraction, Fraction]]:
    """The path-length intervals (u, v) of the path inside ``box``, in path order,
    those meeting at a vertex inside it merged (exact Liang-Barsky per leg)."""
    out: list[tuple[Fraction, Fraction]] = []
    for p, q, at, n in legs:
        t = clip_parameters(*p, *q, box) if n else None
        if t is None:
            continue
        u, v = at + t[0] * n, at + t[1] * n
        if out and out[-1][1] == u:
            out[-1] = (out[-1][0], v)
        else:
            out.append((u, v))
    return out


def _on(u: Fraction, v: Fraction, lengths: list[Fraction], period: Fraction,
        phase: Real) -> list[tuple[Fraction, Fraction]]:
    """The path-length intervals (a, b) within [u, v] where the dash pattern (on/off
    ``lengths``, exact Fractions, repeating every ``period`` from path length
    -``phase``) is on, in order: a < b, or a = b for a zero-length dash."""
    phase = Fraction(phase) % period
    starts = [sum(lengths[:k], Fraction(0)) for k in range(len(lengths))]
    out = []
    q = (phase + u) // period
    while q * period - phase <= v:
        base = q * period - phase
        for k in range(0, len(lengths), 2):
            a, b = base + starts[k], base + min(starts[k] + lengths[k], period)
            lo, hi = max(a, u), min(b, v)
            if lo < hi or (a == b and u <= a <= v):
                out.append((lo, hi))
        q += 1
    return out


def _point(legs: list[Leg], total: int, s: Fraction
           ) -> tuple[tuple[Fraction, Fraction], tuple[int, int]]:
    """The point at path length s (taken modulo the path's length) and the
    direction (dx, dy) of the leg it is on (the one that starts there at a vertex)."""
    s %= total
    for p, q, at, n in legs:
        if n and at <= s < at + n:
            d = ((q[0] - p[0]) // n, (q[1] - p[1]) // n)
            return (p[0] + (s - at) * d[0], p[1] + (s - at) * d[1]), d
    raise AssertionError("a path length beyond the path")


def _piece(legs: list[Leg], total: int, a: Fraction, b: Fraction, epsilon: float) -> NDArray[np.float64]:
    """The polyline from path length a to b >= a (b may run past the end into the
    start): its ends and the vertices between, as floats; a zero-length dash is
    given the length ``epsilon`` along its leg, as the kernels give it."""
    start, d = _point(legs, total, a)
    pts: list[tuple[float | Fraction, float | Fraction]]
    if a == b:
        pts = [start, (start[0] + epsilon * d[0], start[1] + epsilon * d[1])]
    else:
        turns = [p for lap in (0, total) for p, _, at, _ in legs if a < at + lap < b]
        pts = [start, *turns, _point(legs, total, b)[0]]
    return np.array([[float(x), float(y)] for x, y in pts], np.float64)


def path_dashes(path: list[Pixel], lengths: Sequence[float], period: Fraction, phase: Real,
                box: tuple[Exact, Exact, Exact, Exact], epsilon: float
                ) -> list[tuple[NDArray[np.float64], bool]]:
    """The dashes of the closed axis-parallel path ``path`` (exact vertices of any
    size, :func:`degenerate_path`) that lie in ``box`` (xmin, ymin, xmax, ymax), as
    the kernels' dasher cuts a closed polygon (``dash_pieces``): the pattern (on/off
    ``lengths``, floats, its ``period`` a Fraction) starts at ``phase`` at the first
    vertex and runs on across the turns; a dash on at the end joins the one on at
    the start when both are in the box; a dash that never ends is the whole ring.
    Dash ends are exact (Fractions, rounded once to floats); the work is the box's
    perimeter over the period, whatever the path's size.  Returns a list of
    ``(polyline, closed)``."""
    legs, total = _legs(path)
    if total == 0:
        return []
    exact = [Fraction(c) for c in lengths]
    runs = [r for u, v in _visible(legs, box) for r in _on(u, v, exact, period, phase)]
    if runs and runs[0] == (Fraction(0), Fraction(total)):
        return [(np.array(path, np.float64), True)]
    if len(runs) > 1 and runs[0][0] == 0 and runs[-1][1] == total:
        runs = runs[1:-1] + [(runs[-1][0], total + runs[0][1])]
    return [(_piece(legs, total, a, b, epsilon), False) for a, b in runs]
