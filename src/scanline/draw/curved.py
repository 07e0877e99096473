"""Curved boundary areas: filled circles and ellipses, arcs, chords and pie slices
(notes, chapter 2, Q.8; syllabus "Scan-Line fill of curved Boundary Areas").

Angles are in radians, counterclockwise from +x with y up, and are *polar* angles:
the angle of a pixel (x, y) is atan2(y - yc, x - xc), also on an ellipse (so a pie's
straight edges leave the center at exactly the angles given; OpenCV's ``ellipse``
uses the parametric angle instead, which differs unless rx = ry).  An arc, chord or
pie runs counterclockwise from ``start`` to ``end``: ``end - start`` is taken modulo
2 pi, except that a difference of 2 pi or more is the whole ellipse.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import TYPE_CHECKING, Callable, Optional, Sequence, Tuple, Union, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._kernels import curved as k
from .._kernels._jit import call
from .._kernels.variants import layout, token
from . import _blend
from ._common import colors, target
from ..geometry import guard
from . import _far_conics as far
from .conics import _big, _exact_rows, circle, ellipse, exact
from .lines import lines

if TYPE_CHECKING:
    from .._typing import Angle, Color, Colors
    from ..attributes import FillStyle
    from ..framebuffer import FrameBuffer
    from ._area import Outline

#: A point relative to a conic's center: floats, or exact Fractions for a far conic.
PlanePoint = Tuple[Union[float, Fraction], Union[float, Fraction]]
#: A straight edge of an outline, its ends relative to the center.
Segment = Tuple[PlanePoint, PlanePoint]
#: What a chord or pie keeps: its region of the kernels and its straight edges.
Cut = Tuple[far.Region, list[Segment]]

TAU = 2 * math.pi

#: Direction vectors and normals are integers of this length (exact int64 tests for
#: coordinates within +-2**30; an angle is resolved to about 1e-9 radians).
UNIT = 2**30

#: The half-plane holding every pixel (0 x + 0 y + 0 = 0, tie).
EVERYWHERE = (0, 0, 0, 1)


def _top_left(nx: int, ny: int) -> bool:
    """Does a pixel center exactly on the edge belong to the area whose inward
    normal is (nx, ny)?  Yes for a left edge (area to the right: nx > 0) and a top
    edge (horizontal, area below), as in the polygon fill."""
    return nx > 0 or (nx == 0 and ny < 0)


def region_work(rx: ArrayLike, ry: ArrayLike, width: int, height: int) -> float:
    """Work units of filling ellipses of semi-axes ``rx``, ``ry`` (numbers or arrays):
    each its box, at most the raster, plus a row table per shape
    (:func:`scanline._kernels._jit.call`)."""
    a, b = np.asarray(rx, np.float64), np.asarray(ry, np.float64)
    area = np.minimum((2 * a + 1) * (2 * b + 1), width * height) / 4 + height
    return float(area.sum())


def _shape(is_circle: bool) -> tuple[int, ...]:
    """The kernels' shape token of a circle or an ellipse."""
    return cast("Tuple[int, ...]", token(k.CIRCLE if is_circle else k.ELLIPSE))


def _paint(fb: FrameBuffer, color: Optional[Color], style: Optional[FillStyle], xc: int,
           yc: int, rx: int, ry: int, is_circle: bool, hp: far.HalfPlanes, combine: int,
           outline: Outline) -> None:
    def draw(buf: NDArray[np.uint8], packed: bool, width: int, height: int, ox: int, oy: int,
             pixel: NDArray[np.uint8]) -> None:
        call(k.draw_region, region_work(rx, ry, width, height), buf, layout(packed), width,
             height, xc - ox, yc - oy, rx, ry, _shape(is_circle), False, hp, combine, pixel)

    _blend.fill(fb, color, style, (xc - rx, yc - ry, xc + rx, yc + ry), draw, outline)


def _whole() -> tuple[NDArray[np.int64], int]:
    return np.array([EVERYWHERE, EVERYWHERE], np.int64), k.BOTH


def _antialiased(fb: FrameBuffer, name: str, rows: ArrayLike, columns: int,
                 color: Optional[Colors], style: Optional[FillStyle]) -> None:
    """antialias=True: the ideal disks / ellipses, unrounded, by coverage."""
    from .antialias import _reals, filled_ellipses
    from .polygon import _solid_only

    _solid_only(style)
    arr = _reals(name, rows, columns, radius_columns=tuple(range(2, columns)), far=True)
    filled_ellipses(fb, arr if columns == 4 else arr[:, [0, 1, 2, 2]], color)


def _far_fill(fb: FrameBuffer, xc: int, yc: int, rx: int, ry: int, color: far.Spec,
              style: Optional[FillStyle], is_circle: bool) -> None:
    """A filled conic beyond the kernels' limits (:func:`scanline.draw._far_conics.fill`)."""
    outline = (lambda: circle(fb, xc, yc, rx, color)) if is_circle else (
        lambda: ellipse(fb, xc, yc, rx, ry, color))
    far.fill(fb, xc, yc, rx, ry, color, style, is_circle, outline)


def _translucent_batch(fb: FrameBuffer, arr: NDArray[np.int64], circle: bool,
                       color: Optional[Colors]) -> None:
    """Composite a batch of filled circles / ellipses (rounded rows of ``arr``)
    one by one."""
    def draw(i: int, buf: NDArray[np.uint8], packed: bool, width: int, height: int, ox: int,
             oy: int, value: NDArray[np.uint8]) -> None:
        row = arr[i:i + 1].copy()
        row[0, 0] -= ox
        row[0, 1] -= oy
        call(k.fill_regions, region_work(row[0, 2], row[0, -1], width, height), buf,
             layout(packed), width, height, row, _shape(circle), value.reshape(1, -1))

    ry = arr[:, 2] if circle else arr[:, 3]
    boxes = np.stack([arr[:, 0] - arr[:, 2], arr[:, 1] - ry, arr[:, 0] + arr[:, 2],
                      arr[:, 1] + ry], axis=1)
    _blend.paint_each(fb, color, len(arr), boxes.tolist(), draw)


def fill_circle(fb: FrameBuffer, xc: float, yc: float, r: float, color: Optional[Color] = None,
                style: Optional[FillStyle] = None, antialias: bool = False) -> None:
    """Fill the disk bounded by the midpoint circle of radius ``r`` about ``(xc, yc)``.

    Parameters
    ----------
    fb : FrameBuffer
    xc, yc : number
        Center, rounded to the nearest pixel center; any finite value.
    r : number
        Radius >= 0, rounded; r = 0 fills the center pixel.  Any finite value:
        beyond the kernel's limits (center within +-2**30, r <= 2**30) the spans
        of the visible rows come from the same midpoint outline computed exactly
        in Python integers (:mod:`scanline.geometry.far_conics`).
    color : color
        A translucent color is composited (:mod:`scanline.draw._blend`).
    style : FillStyle, optional
        None fills solid; see :func:`scanline.draw._area.fill_area`.
    antialias : bool
        True: the ideal disk of center (xc, yc) and radius r, none of them
        rounded, each pixel composited with the fraction of it inside
        (:func:`scanline.draw.antialias.filled_ellipses`; solid fills only).

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer, or a coordinate is not a number.
    ArgumentValueError
        For a negative radius, a value that is not finite, a bad color, or
        ``antialias=True`` with a style that is not solid.

    Notes
    -----
    Notes, chapter 2, Q.8 (scan-line fill of curved boundary areas): each scan line
    is filled from the left-most to the right-most pixel that
    :func:`scanline.draw.circle` draws on it, so the disk holds exactly the outline
    and everything between.  The extents come from the same midpoint stepping as the
    outline (Q.4): the octant point (x, y) bounds rows yc +- y and, by symmetry,
    rows yc +- x.  One span per scan line, each pixel written once; only visible
    rows are computed (a closed form replaces the stepping for huge radii).

    References
    ----------
    D. Hearn and M. P. Baker, *Computer Graphics*, 2nd ed., section 3-11 (scan-line
    fill of curved boundary areas); J. E. Bresenham, "A linear algorithm for
    incremental digital display of circular arcs", CACM 20(2), 100-106, 1977.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(7, 7, mode="1")
    >>> sl.draw.fill_circle(fb, 3, 3, 3)
    >>> print(sl.text_image(fb))
    --###--
    -#####-
    #######
    #######
    #######
    -#####-
    --###--
    """
    if antialias:
        _antialiased(fb, "(xc, yc, r)", [(xc, yc, r)], 3, far.one(color), style)
        return
    if _big(xc, yc, r, r) and guard.conic_outside(fb, xc, yc, r, r, fill=True):
        return
    xc, yc = v.any_coordinate("xc", xc), v.any_coordinate("yc", yc)
    r = v.any_radius("r", r)
    if not exact(xc, yc, r, r, True):
        _far_fill(fb, xc, yc, r, r, color, style, True)
        return
    hp, combine = _whole()
    _paint(fb, color, style, xc, yc, r, r, True, hp, combine, lambda: circle(fb, xc, yc, r, color))


def fill_ellipse(fb: FrameBuffer, xc: float, yc: float, rx: float, ry: float,
                 color: Optional[Color] = None, style: Optional[FillStyle] = None,
                 antialias: bool = False) -> None:
    """Fill the area bounded by the midpoint ellipse with semi-axes ``rx``, ``ry``.

    Parameters
    ----------
    fb : FrameBuffer
    xc, yc : number
        Center, rounded to the nearest pixel center.
    rx, ry : number
        Semi-axes >= 0, rounded; any finite center and semi-axes (beyond the
        kernel's limits, those of :func:`scanline.draw.ellipse`, computed exactly
        as it computes them).
    color : color
        A translucent color is composited.
    style : FillStyle, optional
    antialias : bool
        True: the ideal ellipse, unrounded, by coverage (as :func:`fill_circle`).

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer, or a coordinate is not a number.
    ArgumentValueError
        For a negative semi-axis, a value that is not finite, a bad color, or
        ``antialias=True`` with a style that is not solid.

    Notes
    -----
    Notes, chapter 2, Q.8 with the midpoint ellipse of Q.6: the first and last
    quadrant points of each row y give the extents of rows yc +- y; each scan line
    is one span from the left-most to the right-most pixel of
    :func:`scanline.draw.ellipse`.

    References
    ----------
    D. Hearn and M. P. Baker, *Computer Graphics*, 2nd ed., sections 3-7 and 3-11;
    M. L. V. Pitteway, "Algorithm for drawing ellipses or hyperbolae with a digital
    plotter", Computer Journal 10(3), 282-289, 1967.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(9, 5, mode="1")
    >>> sl.draw.fill_ellipse(fb, 4, 2, 4, 2)
    >>> print(sl.text_image(fb))
    --#####--
    -#######-
    #########
    -#######-
    --#####--
    """
    if antialias:
        _antialiased(fb, "(xc, yc, rx, ry)", [(xc, yc, rx, ry)], 4, far.one(color), style)
        return
    if _big(xc, yc, rx, ry) and guard.conic_outside(fb, xc, yc, rx, ry, fill=True):
        return
    xc, yc = v.any_coordinate("xc", xc), v.any_coordinate("yc", yc)
    rx = v.any_radius("rx", rx)
    ry = v.any_radius("ry", ry)
    if not exact(xc, yc, rx, ry, False):
        _far_fill(fb, xc, yc, rx, ry, color, style, False)
        return
    hp, combine = _whole()
    _paint(fb, color, style, xc, yc, rx, ry, False, hp, combine,
           lambda: ellipse(fb, xc, yc, rx, ry, color))


def fill_circles(fb: FrameBuffer, circles: ArrayLike, color: Optional[Colors] = None,
                 antialias: bool = False) -> None:
    """Fill N disks in one compiled call; ``circles`` has rows ``(xc, yc, r)``.

    Any finite centers and radii, as for :func:`scanline.draw.circles`.

    Parameters
    ----------
    fb : FrameBuffer
    circles : array_like, shape (N, 3)
        Rows ``(xc, yc, r)``, rounded as :func:`fill_circle` rounds them; radii >= 0.
    color : color, list of colors or integer array, optional
        One color for all, or one per disk (see :func:`scanline.draw.lines`);
        translucent colors are composited disk after disk.
    antialias : bool
        True: the ideal disks (unrounded) by coverage, as :func:`fill_circle` fills
        one.

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer, or ``circles`` does not hold numbers.
    ArgumentValueError
        For rows that are not (N, 3), a negative radius, a value that is not
        finite, a list of colors whose length is not N, or a bad color.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(9, 5, mode="1")
    >>> sl.draw.fill_circles(fb, [(2, 2, 2), (7, 2, 1)])
    >>> print(sl.text_image(fb))
    -###-----
    #####--#-
    #####-###
    #####--#-
    -###-----
    """
    if antialias:
        _antialiased(fb, "circles", circles, 3, color, None)
        return
    target(fb)
    rows = v.coordinate_array("circles", circles, 3, radius_columns=(2,), far=True)
    rows = np.ascontiguousarray(rows[:, [0, 1, 2, 2]])
    far.batch(fb, rows, color, _exact_rows(rows, True),
              lambda arr, c: _fill_batch(fb, np.ascontiguousarray(arr[:, :3]), True, c),
              lambda x, y, a, b, c: _far_fill(fb, x, y, a, b, c, None, True), fill=True)


def _fill_batch(fb: FrameBuffer, arr: NDArray[np.int64], is_circle: bool,
                color: Optional[Colors]) -> None:
    """Fill the rounded rows ``arr`` within the kernels' limits in one compiled
    call (translucent colors: one by one)."""
    buf, packed, width, height = target(fb)
    if _blend.translucent(color):
        _translucent_batch(fb, arr, is_circle, color)
        return
    call(k.fill_regions, lambda: region_work(arr[:, 2], arr[:, -1], width, height), buf,
         layout(packed), width, height, arr, _shape(is_circle), colors(fb, color, len(arr)))


def fill_ellipses(fb: FrameBuffer, ellipses: ArrayLike, color: Optional[Colors] = None,
                  antialias: bool = False) -> None:
    """Fill N ellipses in one compiled call; ``ellipses`` has rows ``(xc, yc, rx, ry)``.

    Any finite centers and radii, as for :func:`scanline.draw.ellipses`.

    Parameters
    ----------
    fb : FrameBuffer
    ellipses : array_like, shape (N, 4)
        Rows ``(xc, yc, rx, ry)``, rounded as :func:`fill_ellipse` rounds them;
        semi-axes >= 0.
    color : color, list of colors or integer array, optional
        One color for all, or one per ellipse (translucent ones are composited).
    antialias : bool
        True: the ideal ellipses (unrounded) by coverage.

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer, or ``ellipses`` does not hold numbers.
    ArgumentValueError
        For rows that are not (N, 4), a negative semi-axis, a value that is not
        finite, a list of colors whose length is not N, or a bad color.

    Examples
    --------
    Each row is one span from the left-most to the right-most pixel of
    :func:`scanline.draw.ellipses`' outline:

    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(9, 5, mode="1")
    >>> sl.draw.fill_ellipses(fb, [(2, 2, 2, 1), (7, 2, 1, 2)])
    >>> print(sl.text_image(fb))
    -------#-
    -###--###
    #####-###
    -###--###
    -------#-
    """
    if antialias:
        _antialiased(fb, "ellipses", ellipses, 4, color, None)
        return
    target(fb)
    rows = v.coordinate_array("ellipses", ellipses, 4, radius_columns=(2, 3), far=True)
    far.batch(fb, rows, color, _exact_rows(rows, False),
              lambda arr, c: _fill_batch(fb, arr, False, c),
              lambda x, y, a, b, c: _far_fill(fb, x, y, a, b, c, None, False), fill=True)


# -- arcs, chords and pies ----------------------------------------------------------------
def _sweep(start: Angle, end: Angle) -> tuple[float, float, Optional[float]]:
    """(a, b, sweep): the angles modulo 2 pi and the counterclockwise sweep from a to
    b, or sweep = None for the whole turn."""
    a = v.angle("start", start)
    b = v.angle("end", end)
    if b - a >= TAU:
        return a % TAU, b % TAU, None
    return a % TAU, b % TAU, (b - a) % TAU


def _direction(angle: float) -> tuple[int, int]:
    return round(math.cos(angle) * UNIT), round(math.sin(angle) * UNIT)


def _sector(start: Angle, end: Angle, closed: bool) -> Optional[tuple[NDArray[np.int64], int]]:
    """Half-planes and their combination for the angular sector from ``start`` to
    ``end``; None when it is empty.

    A pixel belongs to the sector when its angle is in it.  ``closed`` (arcs) keeps
    the pixels on both bounding rays; otherwise (pies) a pixel center exactly on a
    ray goes by the top-left rule, so that slices sharing a ray cover it once, and
    the center pixel belongs to the slice holding the direction just below +x.
    """
    a, b, sweep = _sweep(start, end)
    if sweep is None:
        return _whole()
    ua, ub = _direction(a), _direction(b)
    if ua == ub:  # less than the angular resolution apart
        return _whole() if sweep >= math.pi else None
    na = (-ua[1], ua[0])  # counterclockwise of ray a
    nb = (ub[1], -ub[0])  # clockwise of ray b
    cross = ua[0] * ub[1] - ua[1] * ub[0]
    convex = cross > 0 or (cross == 0 and ua[0] * ub[0] + ua[1] * ub[1] < 0)
    hp = np.array([(*n, 0, 1 if closed else int(_top_left(*n))) for n in (na, nb)], np.int64)
    return hp, k.BOTH if convex else k.EITHER


def _polar_point(rx: float, ry: float, angle: float) -> tuple[float, float]:
    """The point of the ideal ellipse at polar ``angle``, relative to the center."""
    c, s = math.cos(angle), math.sin(angle)
    h = math.hypot(ry * c, rx * s)
    rho = rx * ry / h if h else 0.0
    return rho * c, rho * s


#: Fixed-point bits of a far chord's or pie's ends: integers times 2**-64 pixel.
END_BITS = 64


def _ray_point(rx: int, ry: int, angle: float) -> tuple[Fraction, Fraction]:
    """The point of the ideal ellipse (integer semi-axes of any size) on the ray of
    the sector's direction :func:`_direction` (``angle`` resolved as arcs and pies
    resolve it), relative to the center, as Fractions: t u with
    t = rx ry / sqrt(ry**2 ux**2 + rx**2 uy**2), each coordinate rounded toward the
    center to a multiple of 2**-64 (exact integer square roots,
    floor(sqrt(n / s)) = isqrt(n // s))."""
    u = _direction(angle)
    s = (ry * u[0]) ** 2 + (rx * u[1]) ** 2
    if s == 0:
        return Fraction(0), Fraction(0)

    def part(c: int) -> Fraction:
        m = math.isqrt(((abs(c) * rx * ry) << END_BITS) ** 2 // s)
        return Fraction(m if c >= 0 else -m, 1 << END_BITS)

    return part(u[0]), part(u[1])


def _oriented(pa: PlanePoint, pb: PlanePoint,
              plane: Callable[[PlanePoint, PlanePoint], tuple[int, int, int]]
              ) -> list[tuple[int, int, int, int]]:
    """The half-plane ``plane(p, q)`` = (nx, ny, c) right of p -> q for the chord's
    ends sorted (a fixed order, so that the chords (a, b) and (b, a) get exactly
    opposite half-planes), turned to the right of P_a -> P_b (the arc's side)."""
    p, q = sorted((pa, pb))
    nx, ny, c = plane(p, q)
    if (p, q) != (pa, pb):
        nx, ny, c = -nx, -ny, -c
    return [(nx, ny, c, int(_top_left(nx, ny))), EVERYWHERE]


def _float_plane(p: PlanePoint, q: PlanePoint) -> tuple[int, int, int]:
    """The kernels' chord line: its unit normal in integers of length UNIT (an
    angle resolved to about 1e-9 radians), the offset rounded; (0, 0, 0) when the
    ends are closer than that resolution."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    length = math.hypot(dx, dy)
    n = (round(dy / length * UNIT), round(-dx / length * UNIT)) if length else (0, 0)
    return n[0], n[1], -round(n[0] * p[0] + n[1] * p[1])


def _exact_plane(p: PlanePoint, q: PlanePoint) -> tuple[int, int, int]:
    """The exact line through the Fraction points p and q (multiples of 2**-64) as
    an integer half-plane n . (x, y) + c > 0 of pixel centers (x, y)."""
    one = 1 << END_BITS
    px, py, qx, qy = (int(c * one) for c in (*p, *q))
    nx, ny = qy - py, px - qx
    return nx * one, ny * one, -(nx * px + ny * py)


def _chord_region(rx: int, ry: int, start: Angle, end: Angle, far: bool = False
                  ) -> Optional[Cut]:
    """The half-plane on the arc's side of the chord (right of P_a -> P_b) and the
    chord as a segment; None when the chord cuts off nothing.

    Within the kernels' limits P_a, P_b are the float points at the angles and the
    line is :func:`_float_plane` (int64); ``far`` (any size): they are the exact
    :func:`_ray_point` ends and the line through them is exact (Python integers)."""
    a, b, sweep = _sweep(start, end)
    point: Callable[[int, int, float], PlanePoint]
    plane: Callable[[PlanePoint, PlanePoint], tuple[int, int, int]]
    point, plane = (_ray_point, _exact_plane) if far else (_polar_point, _float_plane)
    pa, pb = point(rx, ry, a), point(rx, ry, b)
    if sweep is None:
        return _whole(), [(pa, pb)]
    hp = _oriented(pa, pb, plane)
    if hp[0][:2] == (0, 0):
        return (_whole(), [(pa, pb)]) if sweep > math.pi else None
    return (hp if far else np.array(hp, np.int64), k.BOTH), [(pa, pb)]


def _pie_region(rx: int, ry: int, start: Angle, end: Angle, far: bool = False
                ) -> Optional[Cut]:
    """The sector from ``start`` to ``end`` and its two radii as segments; None when
    it is empty (``far``: the radii end at the exact :func:`_ray_point`)."""
    region = _sector(start, end, closed=False)
    if region is None:
        return None
    a, b, _ = _sweep(start, end)
    point: Callable[[int, int, float], PlanePoint] = _ray_point if far else _polar_point
    return region, [((0, 0), point(rx, ry, a)), ((0, 0), point(rx, ry, b))]


def _segments(xc: int, yc: int, segments: Sequence[Segment]) -> list[list[float]]:
    """The outline's straight edges ``segments`` (ends relative to the center) as
    (x0, y0, x1, y1) rows for :func:`scanline.draw.lines`: exact sums rounded once
    to floats while within ``guard.EXACT_FROM`` (2**36: an error below 2**-16
    pixel, and :func:`scanline.draw.lines` clips them itself), clipped exactly to
    the guard square beyond (:func:`scanline.geometry.guard.clip_segment`), so that
    far ends lose nothing."""
    rows: list[list[float]] = []
    for p, q in segments:
        ends = [Fraction(xc) + Fraction(p[0]), Fraction(yc) + Fraction(p[1]),
                Fraction(xc) + Fraction(q[0]), Fraction(yc) + Fraction(q[1])]
        if max(abs(c) for c in ends) <= guard.EXACT_FROM:
            rows.append([float(c) for c in ends])
        else:
            piece = guard.clip_segment(*ends)
            if piece is not None:
                rows.append(piece.tolist())
    return rows


def _cut(fb: FrameBuffer, xc: float, yc: float, rx: float, ry: float, start: Angle,
         end: Angle, color: Optional[Color], style: Optional[FillStyle],
         shape: Callable[[int, int, Angle, Angle, bool], Optional[Cut]]) -> None:
    """Paint the part of the filled ellipse (circle) that ``shape(rx, ry, start,
    end, far)`` keeps; its straight edges and the arc are the hollow outline.
    Within the kernels' limits the curved-area kernel paints it; beyond them
    :func:`_far_cut`, with the exact far region."""
    target(fb)
    xc, yc = v.any_coordinate("xc", xc), v.any_coordinate("yc", yc)
    rx, ry = v.any_radius("rx", rx), v.any_radius("ry", ry)
    is_circle = rx == ry
    is_far = not exact(xc, yc, rx, ry, is_circle)
    found = shape(rx, ry, start, end, is_far)
    if found is None:
        return
    if is_far:
        _far_cut(fb, xc, yc, rx, ry, start, end, color, style, found)
        return
    region, segments = found
    _paint(fb, color, style, xc, yc, rx, ry, is_circle, *region,
           lambda: _outline(fb, xc, yc, rx, ry, start, end, color, segments))


def _outline(fb: FrameBuffer, xc: int, yc: int, rx: int, ry: int, start: Angle, end: Angle,
             color: Optional[Color], segments: Sequence[Segment]) -> None:
    """The hollow outline of a chord or pie: its arc and its straight edges."""
    arc(fb, xc, yc, rx, ry, start, end, color)
    rows = _segments(xc, yc, segments)
    if rows:
        lines(fb, rows, color)


def _far_cut(fb: FrameBuffer, xc: int, yc: int, rx: int, ry: int, start: Angle, end: Angle,
             color: Optional[Color], style: Optional[FillStyle], found: Cut) -> None:
    """A chord or pie of any size: the far filled conic's spans (the midpoint
    outline's, in Python integers) within ``found``'s region,
    :func:`scanline.draw._far_conics.fill`; O(height) rows whatever the radii."""
    region, segments = found
    far.fill(fb, xc, yc, rx, ry, color, style, rx == ry,
             lambda: _outline(fb, xc, yc, rx, ry, start, end, color, segments), region)


def arc(fb: FrameBuffer, xc: float, yc: float, rx: float, ry: float, start: Angle, end: Angle,
        color: Optional[Color] = None) -> None:
    """Draw the pixels of the midpoint ellipse (circle when rx = ry) whose polar
    angle lies in [start, end], counterclockwise.

    Parameters
    ----------
    fb : FrameBuffer
    xc, yc : number
        Center, rounded to the nearest pixel center.
    rx, ry : number
        Semi-axes; rx = ry draws part of :func:`scanline.draw.circle`, otherwise
        part of :func:`scanline.draw.ellipse`; any finite center and semi-axes (beyond
        the kernels' limits the same pixels, computed as those functions compute them).
    start, end : float
        Angles in radians (see the module notes); an arc is closed, both bounding
        rays included, so the arcs [a, b] and [b, c] together are [a, c].  Angles
        closer than ~1e-9 radians draw nothing unless end - start >= 2 pi.  A
        string gives the unit (``"30deg"``, ``"0.25turn"``).
    color : color
        A translucent color is composited.

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer, a coordinate is not a number, or an angle is
        neither a number nor a string.
    ArgumentValueError
        For a negative semi-axis, a value that is not finite, an angle string
        without a known unit, or a bad color.

    Notes
    -----
    Notes, chapter 2, Q.4-Q.6: the outline's runs on each scan line come from the
    same midpoint stepping as the filled areas and are clipped to the angular sector.

    Examples
    --------
    >>> import math
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(7, 7, mode="1")
    >>> sl.draw.arc(fb, 3, 3, 3, 3, 0, math.pi / 2)
    >>> print(sl.text_image(fb))
    ---##--
    -----#-
    ------#
    ------#
    -------
    -------
    -------
    """
    target(fb)
    xc, yc = v.any_coordinate("xc", xc), v.any_coordinate("yc", yc)
    rx, ry = v.any_radius("rx", rx), v.any_radius("ry", ry)
    is_circle = rx == ry
    region = _sector(start, end, closed=True)
    if region is None:
        return
    if not exact(xc, yc, rx, ry, is_circle):
        far.arc(fb, xc, yc, rx, ry, region, color, is_circle)
        return

    def draw(buf: NDArray[np.uint8], packed: bool, width: int, height: int, ox: int, oy: int,
             value: NDArray[np.uint8]) -> None:
        call(k.draw_region, region_work(rx, ry, width, height), buf, layout(packed), width,
             height, xc - ox, yc - oy, rx, ry, _shape(is_circle), True, *region, value)

    _blend.paint(fb, color, (xc - rx, yc - ry, xc + rx, yc + ry), draw)


def pie(fb: FrameBuffer, xc: float, yc: float, rx: float, ry: float, start: Angle, end: Angle,
        color: Optional[Color] = None, style: Optional[FillStyle] = None) -> None:
    """Fill the pie slice of the ellipse (circle when rx = ry) between the rays at
    ``start`` and ``end``, counterclockwise.

    A pixel is in the slice iff it is in :func:`fill_ellipse` (:func:`fill_circle`)
    and its center's polar angle is in the sector.  A center exactly on a bounding
    ray follows the top-left rule (it belongs to the slice on its right, or below a
    horizontal ray), and the center pixel belongs to the slice holding the direction
    just below +x; so slices that share rays, e.g. 0..a, a..b, b..2 pi, cover the
    disk exactly once.  Angles as for :func:`arc`; any finite center and semi-axes
    (beyond the kernels' limits the far fill's spans within the sector,
    :mod:`scanline.draw._far_conics`).

    Parameters
    ----------
    fb : FrameBuffer
    xc, yc : number
        Center, rounded to the nearest pixel center.
    rx, ry : number
        Semi-axes >= 0, rounded; rx = ry: a slice of :func:`fill_circle`.
    start, end : float or str
        Angles of the bounding rays, as for :func:`arc`.
    color : color
        A translucent color is composited.
    style : FillStyle, optional
        None fills solid; see :func:`scanline.draw._area.fill_area`.  The hollow
        style draws the arc and the straight edges.

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer, a coordinate is not a number, or an angle is
        neither a number nor a string.
    ArgumentValueError
        For a negative semi-axis, a value that is not finite, an angle string
        without a known unit, or a bad color.

    Examples
    --------
    The first quadrant: its +x ray is a bottom edge, so the pixels on it (and the
    center) belong to the fourth quadrant's slice; its +y ray is a left edge.

    >>> import math
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(7, 7, mode="1")
    >>> sl.draw.pie(fb, 3, 3, 3, 3, 0, math.pi / 2)
    >>> print(sl.text_image(fb))
    ---##--
    ---###-
    ---####
    -------
    -------
    -------
    -------
    """
    _cut(fb, xc, yc, rx, ry, start, end, color, style, _pie_region)


def chord(fb: FrameBuffer, xc: float, yc: float, rx: float, ry: float, start: Angle,
          end: Angle, color: Optional[Color] = None, style: Optional[FillStyle] = None
          ) -> None:
    """Fill the region between the arc from ``start`` to ``end`` and the chord
    joining its end points.

    A pixel is in the chord iff it is in :func:`fill_ellipse` (:func:`fill_circle`)
    and its center is on the arc's side of the straight line through the ideal
    ellipse's points at the two angles; centers exactly on that line follow the
    top-left rule, so the chords (a, b) and (b, a) cover the disk exactly once.
    Angles as for :func:`arc`; any finite center and semi-axes.

    Within the kernels' limits (those of :func:`fill_circle` / :func:`fill_ellipse`)
    the ends are the float points at the angles and the line an int64 half-plane
    whose normal is resolved to 2**-30 (the curved-area kernel).  Beyond them the
    spans are the far filled conic's (:mod:`scanline.draw._far_conics`, Python
    integers, O(height) rows) and the line is exact: through the ideal ellipse's
    points on the rays that :func:`arc` and :func:`pie` use for the angles
    (directions resolved to about 1e-9 radians), computed to 2**-64 pixel; the
    hollow outline's chord is clipped exactly to the guard square
    (:func:`scanline.geometry.guard.clip_segment`).  The two agree except for pixel
    centers within about 1.4e-9 (r + d) pixel of the line, d their distance from
    the chord's ends.

    Parameters
    ----------
    fb : FrameBuffer
    xc, yc : number
        Center, rounded to the nearest pixel center.
    rx, ry : number
        Semi-axes >= 0, rounded; rx = ry: part of :func:`fill_circle`.
    start, end : float or str
        Angles of the arc's ends, as for :func:`arc`.
    color : color
        A translucent color is composited.
    style : FillStyle, optional
        None fills solid; see :func:`scanline.draw._area.fill_area`.  The hollow
        style draws the arc and the chord.

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer, a coordinate is not a number, or an angle is
        neither a number nor a string.
    ArgumentValueError
        For a negative semi-axis, a value that is not finite, an angle string
        without a known unit, or a bad color.

    Examples
    --------
    The upper half disk: the diameter is its bottom edge, so its pixels belong to
    the lower half.

    >>> import math
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(7, 7, mode="1")
    >>> sl.draw.chord(fb, 3, 3, 3, 3, 0, math.pi)
    >>> print(sl.text_image(fb))
    --###--
    -#####-
    #######
    -------
    -------
    -------
    -------
    """
    _cut(fb, xc, yc, rx, ry, start, end, color, style, _chord_region)
