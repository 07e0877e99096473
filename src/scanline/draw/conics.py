"""Circles and ellipses by the midpoint method (notes, chapter 2, Q.4-Q.6)."""

from typing import TYPE_CHECKING, Optional, Tuple, Union, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._kernels import conics as k
from .._kernels._jit import call_typed
from .._kernels._threads import call_in_bands
from .._kernels.variants import layout
from ..errors import ArgumentValueError
from ..geometry import guard
from . import _far_conics as far
from . import strokes
from ._common import band_order, colors, target
from .._typing import Cap, Color, Colors, Dash, Join, PenLike

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer
    from ..linestyle import LineStyle


#: Ellipse limits: the decision parameters stay exact in 64-bit integers while
#: r_x * r_y <= 2**29, and one ellipse takes at most r_x + r_y steps.
ELLIPSE_AXIS_LIMIT = 2**24
ELLIPSE_PRODUCT_LIMIT = 2**29


def _big(xc: float, yc: float, rx: float, ry: float) -> bool:
    """Whether a conic's parameters may be beyond the exact limits (not all ints of
    at most 2**14), so that :func:`scanline.geometry.guard.conic_outside` is asked
    first.  (Written out: a generator costs more than a short circle's kernel.)"""
    small = 1 << 14
    return not (type(xc) is type(yc) is type(rx) is type(ry) is int
                and -small <= xc <= small and -small <= yc <= small
                and -small <= rx <= small and -small <= ry <= small)


def _outside(fb: "FrameBuffer", xc: float, yc: float, rx: float, ry: float,
             attrs: Optional["LineStyle"]) -> bool:
    """Whether a conic beyond the exact limits (far center, huge radii) misses the
    frame buffer and so draws nothing (:func:`scanline.geometry.guard.conic_outside`,
    reach: the stroke's margin)."""
    if not _big(xc, yc, rx, ry):
        return False
    reach = 1.0 if attrs is None else float(strokes._margin(attrs))
    return guard.conic_outside(fb, xc, yc, rx, ry, reach)


def exact(xc: int, yc: int, rx: int, ry: int, circle: bool) -> bool:
    """Whether the kernels take this conic (integers): center within +-2**30 and
    radius <= 2**30 (a circle) or the midpoint ellipse's limits (an ellipse).
    Anything else is drawn by :mod:`scanline.draw._far_conics`."""
    if abs(xc) > v.COORD_LIMIT or abs(yc) > v.COORD_LIMIT:
        return False
    if circle:
        return rx <= v.COORD_LIMIT
    return max(rx, ry) <= ELLIPSE_AXIS_LIMIT and rx * ry <= ELLIPSE_PRODUCT_LIMIT


def _exact_rows(arr: NDArray[np.float64], circle: bool) -> NDArray[np.bool_]:
    """:func:`exact` for the float rows (xc, yc, rx, ry) of a batch, rounded."""
    a = np.floor(arr + 0.5)
    ok: NDArray[np.bool_] = np.abs(a[:, :2]).max(axis=1, initial=0) <= v.COORD_LIMIT
    if circle:
        return ok & (a[:, 2] <= v.COORD_LIMIT)
    with np.errstate(over="ignore"):                   # inf is beyond the limit too
        # (ndarray.max(axis=...) is Any to numpy's stubs)
        return cast("NDArray[np.bool_]", ok & (a[:, 2:].max(axis=1, initial=0) <= ELLIPSE_AXIS_LIMIT)
                    & (a[:, 2] * a[:, 3] <= ELLIPSE_PRODUCT_LIMIT))


def _far(fb: "FrameBuffer", xc: int, yc: int, rx: int, ry: int, color: far.Spec,
         attrs: Optional["LineStyle"], antialias: bool, circle: bool) -> None:
    """A conic beyond the kernels' limits (:mod:`scanline.draw._far_conics`)."""
    if attrs is None:
        target(fb)
        far.outline(fb, xc, yc, rx, ry, fb.pixel(color), circle)
    else:
        far.stroke(fb, xc, yc, rx, ry, color, attrs, antialias, circle)


def circle(fb: "FrameBuffer", xc: float, yc: float, r: float, color: Optional[Color] = None,
           *, style: Optional["LineStyle"] = None, antialias: bool = False, width: Optional[float] = None,
           cap: Optional[Cap] = None, join: Optional[Join] = None, miter_limit: Optional[float] = None,
           dash: Optional[Dash] = None, dash_phase: Optional[float] = None,
           pen: Optional[PenLike] = None) -> None:
    """Draw the circle of radius ``r`` about ``(xc, yc)`` by the midpoint algorithm.

    Parameters
    ----------
    fb : FrameBuffer
    xc, yc : number
        Center, rounded to the nearest pixel center; any finite value.
    r : number
        Radius >= 0, rounded to an integer; r = 0 draws the center pixel.  Any
        finite value: beyond a center within +-2**30 and r <= 2**30 (the kernel's
        64-bit limits) the visible part is computed exactly in Python integers
        (:mod:`scanline.geometry.far_conics`), the same midpoint pixels.
    color : color
    style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen
        Line attributes (see :func:`scanline.draw.polyline`).  Width 1: the
        midpoint pixels, numbered counterclockwise from (xc + r, yc) for a line type,
        each stamping the pen.  Thicker: the stroke of a closed polygon within 0.1
        pixel of the circle, filled by the scan-line fill.

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer, or a coordinate is not a number.
    ArgumentValueError
        For a negative radius, a value that is not finite, or a bad color or line
        attribute.

    Notes
    -----
    Notes, chapter 2, Q.4-Q.5: the octant from (0, r) to the diagonal is computed
    with p_0 = 1 - r and the increments 2x_k+1 + 1 (p_k < 0) or 2x_k+1 + 1 - 2y_k+1,
    and mirrored into the other seven octants; each pixel is written once.  Only the
    part of a large circle that can be visible is computed: its octant columns
    x are those of the visible columns and rows, and y(x) has a closed form, so any
    circle costs O(width + height).  A width-1 dashed or pen-drawn circle beyond
    them numbers its visible pixels exactly as the whole sequence would; wide or
    antialiased dashed ones measure their dashes along the ideal circle from
    (xc + r, yc), the arc length to the visible part in decimals
    (:func:`scanline.geometry.far_conics.arc_length`).

    References
    ----------
    D. Hearn and M. P. Baker, *Computer Graphics*, C version, 2nd ed., section 3-5
    (the midpoint circle algorithm); J. E. Bresenham, "A linear algorithm for incremental digital display of circular
    arcs", Communications of the ACM 20(2), 100-106, 1977.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(7, 7, mode="1")
    >>> sl.draw.circle(fb, 3, 3, 3)
    >>> print(sl.text_image(fb))
    --###--
    -#---#-
    #-----#
    #-----#
    #-----#
    -#---#-
    --###--
    """
    attrs = strokes.styled(style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen)
    if _big(xc, yc, r, r) or r < 0:         # (small ints, r >= 0: nothing to check)
        if _outside(fb, xc, yc, r, r, attrs):
            return
        xc, yc, r = v.any_coordinate("xc", xc), v.any_coordinate("yc", yc), v.any_radius("r", r)
        if not exact(xc, yc, r, r, True):
            _far(fb, xc, yc, r, r, color, attrs, antialias, True)
            return
    if attrs is not None:
        strokes.conics(fb, np.array([[xc, yc, r, r]], np.int64), color, attrs, antialias)
        return
    buf, packed, width, height = target(fb)
    call_typed(k.draw_circle, packed, 4 * (width + height), _circle_work, buf, layout(packed),
               width, height, xc, yc, r, fb.pixel(color))


def _circle_work(buf: NDArray[np.uint8], layout: Tuple[int, ...], width: int, height: int, xc: int, yc: int,
                 r: int, color: NDArray[np.uint8]) -> int:
    """Work units of one circle (its pixels, at most twice the frame buffer's
    perimeter)."""
    return min(8 * r, 4 * (width + height))


def circles(fb: "FrameBuffer", circles: ArrayLike, color: Optional[Colors] = None, *,
            style: Optional["LineStyle"] = None, antialias: bool = False,
            width: Optional[float] = None, cap: Optional[Cap] = None,
            join: Optional[Join] = None, miter_limit: Optional[float] = None,
            dash: Optional[Dash] = None, dash_phase: Optional[float] = None,
            pen: Optional[PenLike] = None) -> None:
    """Draw N circles in one compiled call; ``circles`` has rows ``(xc, yc, r)``.

    Any finite centers and radii: rows within the kernel's limits are drawn in one
    compiled call, the others as :func:`circle` draws them (colors stay with their
    rows).

    Parameters
    ----------
    fb : FrameBuffer
    circles : array_like, shape (N, 3)
        Rows ``(xc, yc, r)``, rounded as :func:`circle` rounds them; radii >= 0.
    color : color, list of colors or integer array, optional
        One color for all, or one per circle (see :func:`scanline.draw.line` and
        :func:`scanline.draw.lines`).
    style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen
        Line attributes, those of :func:`circle`, for every circle.

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer, or ``circles`` does not hold numbers.
    ArgumentValueError
        For rows that are not (N, 3), a negative radius, a value that is not
        finite, a list of colors whose length is not N, or a bad color or line
        attribute.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(9, 5, mode="1")
    >>> sl.draw.circles(fb, [(2, 2, 2), (7, 2, 1)])
    >>> print(sl.text_image(fb))
    -###-----
    #---#--#-
    #---#-#-#
    #---#--#-
    -###-----
    """
    attrs = strokes.styled(style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen)
    target(fb)                       # (fb is checked before the rows)
    exact = None if attrs is not None else v.exact_coordinates("circles", circles, 3, (2,))
    if exact is not None:
        # integers in range (the common large batch): every row is exact, drawn as is
        _near_circles(fb, exact, color)
        return
    rows = v.coordinate_array("circles", circles, 3, radius_columns=(2,), far=True)
    rows = np.ascontiguousarray(rows[:, [0, 1, 2, 2]])
    if attrs is not None:
        far.batch(fb, rows, color, _exact_rows(rows, True),
                  lambda arr, c: strokes.conics(fb, arr, c, attrs, antialias),
                  lambda x, y, a, b, c: _far(fb, x, y, a, b, c, attrs, antialias, True),
                  float(strokes._margin(attrs)))
        return
    far.batch(fb, rows, color, _exact_rows(rows, True),
              lambda arr, c: _near_circles(fb, arr, c),
              lambda x, y, a, b, c: _far(fb, x, y, a, b, c, None, False, True))


def _near_circles(fb: "FrameBuffer", rows: NDArray[np.int64], color: Optional[Colors]) -> None:
    """The compiled batch of :func:`circles`: int64 rows (xc, yc, r, ...) within the
    kernels' range."""
    buf, packed, width, height = target(fb)
    values = colors(fb, color, len(rows))
    arr = band_order(np.ascontiguousarray(rows[:, :3]), values, height)
    call_in_bands(k.draw_circles, conic_work(arr[:, 2], arr[:, 2], width, height), buf,
                  layout(packed), width, height, arr, values)


def conic_work(rx: NDArray[Union[np.int64, np.float64]], ry: NDArray[Union[np.int64, np.float64]],
               width: int, height: int) -> float:
    """Work units of drawing conic outlines of semi-axes ``rx``, ``ry`` (arrays): about
    4 (rx + ry) pixels each, at most 4 (width + height) on the raster
    (:func:`scanline._kernels._jit.call`)."""
    return float(np.minimum(4 * (rx + ry), 4 * (width + height)).sum()) + len(rx)


def _check_ellipse(rx: int, ry: int, name: str = "rx * ry") -> None:
    if max(rx, ry) > ELLIPSE_AXIS_LIMIT or rx * ry > ELLIPSE_PRODUCT_LIMIT:
        raise ArgumentValueError(
            f"ellipse radii rx={rx}, ry={ry} are too large: the midpoint ellipse needs "
            f"rx, ry <= {ELLIPSE_AXIS_LIMIT} and rx * ry <= {ELLIPSE_PRODUCT_LIMIT} for exact "
            "64-bit decision parameters"
        )


def ellipse(fb: "FrameBuffer", xc: float, yc: float, rx: float, ry: float,
            color: Optional[Color] = None,
            *, style: Optional["LineStyle"] = None, antialias: bool = False, width: Optional[float] = None,
            cap: Optional[Cap] = None, join: Optional[Join] = None, miter_limit: Optional[float] = None,
            dash: Optional[Dash] = None, dash_phase: Optional[float] = None,
            pen: Optional[PenLike] = None) -> None:
    """Draw the axis-aligned ellipse with semi-axes ``rx``, ``ry`` about ``(xc, yc)``
    by the midpoint algorithm.

    Parameters
    ----------
    fb : FrameBuffer
    xc, yc : number
        Center, rounded to the nearest pixel center.
    rx, ry : number
        Semi-axes >= 0, rounded to integers.  ``ry = 0`` or ``rx = 0`` draws the
        degenerate ellipse, a segment; both 0 the center pixel.  Any finite center
        and radii: beyond a center within +-2**30, rx, ry <= 2**24 and
        rx * ry <= 2**29 (the kernel's exact 64-bit decision parameters) the visible
        part is computed exactly in Python integers
        (:mod:`scanline.geometry.far_conics`), the same midpoint pixels.
    color : color
    style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen
        Line attributes, as for :func:`circle`.

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer, or a coordinate is not a number.
    ArgumentValueError
        For a negative semi-axis, a value that is not finite, or a bad color or
        line attribute.

    Notes
    -----
    Notes, chapter 2, Q.6: region 1 (|slope| < 1) steps x from (0, r_y) with
    p1_0 = r_y^2 - r_x^2 r_y + r_x^2/4 until 2 r_y^2 x >= 2 r_x^2 y; region 2 steps y
    down to 0 with p2_0 = r_y^2 (x + 1/2)^2 + r_x^2 (y - 1)^2 - r_x^2 r_y^2; four-way
    symmetry gives the other quadrants.  Decision parameters are kept times 4, so
    they are exact integers (the notes round them).  One addition to the notes: a very
    flat ellipse can leave region 2 at y = 0 before x reaches r_x; the remaining run
    to (r_x, 0) is drawn (shown as region "tip" by ``scanline trace``).

    References
    ----------
    D. Hearn and M. P. Baker, *Computer Graphics*, C version, 2nd ed., section 3-6
    (the midpoint ellipse algorithm); M. L. V. Pitteway, "Algorithm for drawing ellipses
    or hyperbolae with a digital plotter", Computer Journal 10(3), 282-289, 1967.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(9, 5, mode="1")
    >>> sl.draw.ellipse(fb, 4, 2, 4, 2)
    >>> print(sl.text_image(fb))
    --#####--
    -#-----#-
    #-------#
    -#-----#-
    --#####--
    """
    attrs = strokes.styled(style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen)
    if _big(xc, yc, rx, ry) or rx < 0 or ry < 0:     # (small ints: nothing to check)
        if _outside(fb, xc, yc, rx, ry, attrs):
            return
        rx = v.any_radius("rx", rx)
        ry = v.any_radius("ry", ry)
        xc, yc = v.any_coordinate("xc", xc), v.any_coordinate("yc", yc)
        if not exact(xc, yc, rx, ry, False):
            _far(fb, xc, yc, rx, ry, color, attrs, antialias, False)
            return
    if attrs is not None:
        strokes.conics(fb, np.array([[xc, yc, rx, ry]], np.int64), color, attrs, antialias)
        return
    buf, packed, width, height = target(fb)
    call_typed(k.draw_ellipse, packed, 4 * (width + height), _ellipse_work, buf, layout(packed),
               width, height, xc, yc, rx, ry, fb.pixel(color))


def _ellipse_work(buf: NDArray[np.uint8], layout: Tuple[int, ...], width: int, height: int, xc: int,
                  yc: int, rx: int, ry: int, color: NDArray[np.uint8]) -> int:
    """Work units of one ellipse (its pixels, at most twice the frame buffer's
    perimeter)."""
    return min(4 * (rx + ry), 4 * (width + height))


def ellipses(fb: "FrameBuffer", ellipses: ArrayLike, color: Optional[Colors] = None, *,
             style: Optional["LineStyle"] = None, antialias: bool = False,
             width: Optional[float] = None, cap: Optional[Cap] = None,
             join: Optional[Join] = None, miter_limit: Optional[float] = None,
             dash: Optional[Dash] = None, dash_phase: Optional[float] = None,
             pen: Optional[PenLike] = None) -> None:
    """Draw N ellipses in one compiled call; ``ellipses`` has rows ``(xc, yc, rx, ry)``.

    Any finite centers and radii, as for :func:`circles`.

    Parameters
    ----------
    fb : FrameBuffer
    ellipses : array_like, shape (N, 4)
        Rows ``(xc, yc, rx, ry)``, rounded as :func:`ellipse` rounds them; semi-axes
        >= 0.
    color : color, list of colors or integer array, optional
        One color for all, or one per ellipse.
    style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen
        Line attributes, those of :func:`circle`, for every ellipse.

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer, or ``ellipses`` does not hold numbers.
    ArgumentValueError
        For rows that are not (N, 4), a negative semi-axis, a value that is not
        finite, a list of colors whose length is not N, or a bad color or line
        attribute.

    Examples
    --------
    A wide and a tall ellipse (the midpoint ellipse of semi-axes 1 and 2 has its
    side pixels at x = xc +- 1 on three rows):

    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(9, 5, mode="1")
    >>> sl.draw.ellipses(fb, [(2, 2, 2, 1), (7, 2, 1, 2)])
    >>> print(sl.text_image(fb))
    -------#-
    -###--#-#
    #---#-#-#
    -###--#-#
    -------#-
    """
    attrs = strokes.styled(style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen)
    rows = v.coordinate_array("ellipses", ellipses, 4, radius_columns=(2, 3), far=True)
    ok = _exact_rows(rows, False)
    if attrs is not None:
        far.batch(fb, rows, color, ok,
                  lambda arr, c: strokes.conics(fb, arr, c, attrs, antialias),
                  lambda x, y, a, b, c: _far(fb, x, y, a, b, c, attrs, antialias, False),
                  float(strokes._margin(attrs)))
        return
    buf, packed, width, height = target(fb)

    def near(arr: NDArray[np.int64], c: Optional[Colors]) -> None:
        values = colors(fb, c, len(arr))
        arr = band_order(arr, values, height)
        call_in_bands(k.draw_ellipses, conic_work(arr[:, 2], arr[:, 3], width, height), buf,
                      layout(packed), width, height, arr, values)

    far.batch(fb, rows, color, ok, near,
              lambda x, y, a, b, c: _far(fb, x, y, a, b, c, None, False, False))
