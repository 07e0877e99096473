"""Curves drawn into a frame buffer: ``curve`` and ``curves`` (notes, chapter 5).

A curve (any :class:`scanline.curves.Curve` in 2-D device coordinates) is flattened
to a polyline within ``tolerance`` device units (:func:`scanline.curves.flatten.flatten`)
and then drawn as a polyline with every line attribute
(:func:`scanline.draw.polyline`), or filled as a closed outline
(:func:`scanline.draw.polygon`, either fill rule).  ``window=`` clips the polyline
(:func:`scanline.clip.polyline`) or the outline (:func:`scanline.clip.polygon`) first.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable, Iterable, Literal, Optional, Sequence, TypedDict

import numpy as np
from numpy.typing import NDArray

from ..curves.base import Curve
from ..curves.flatten import flatten_all
from ..errors import ArgumentTypeError, ArgumentValueError

if TYPE_CHECKING:
    from .._typing import Cap, Color, Colors, Dash, Join, PenLike, Rule
    from ..clip.window import WindowLike
    from ..framebuffer import FrameBuffer
    from ..linestyle import LineStyle

#: Flattening methods (:func:`scanline.curves.flatten.flatten`).
Flattening = Literal["subdivision", "wang"]


class _LineAttributes(TypedDict):
    """The line attributes a stroke passes on to :func:`scanline.draw.polyline`."""
    style: Optional[LineStyle]
    antialias: bool
    width: Optional[float]
    cap: Optional[Cap]
    join: Optional[Join]
    miter_limit: Optional[float]
    dash: Optional[Dash]
    dash_phase: Optional[float]
    pen: Optional[PenLike]


def _outlines(curves: Sequence[Curve], tolerance: float, method: Flattening,
              name: Callable[[int], str]) -> list[NDArray[np.float64]]:
    """The flattened polylines of 2-D curves (``name(i)`` names curve i in errors)."""
    for i, c in enumerate(curves):
        if not isinstance(c, Curve):
            raise ArgumentTypeError(
                f"{name(i)} must be a scanline.curves.Curve (Bezier, BSpline, NURBS, "
                f"Hermite ...), got {type(c).__name__}"
            )
        if c.dimension != 2:
            raise ArgumentValueError(
                f"{name(i)} must be a 2-D curve in device coordinates, got a "
                f"{c.dimension}-D curve; project its control points to (x, y) first"
            )
    return flatten_all(curves, tolerance, method)


def _is_closed(curve: Curve, points: NDArray[np.float64], closed: Optional[bool]) -> bool:
    """``closed`` if given, else: the curve says so (periodic B-splines, closed
    Hermite-family splines) or its two ends coincide."""
    if closed is not None:
        if not isinstance(closed, (bool, np.bool_)):
            raise ArgumentTypeError(f"closed must be True, False or None, got {closed!r}")
        return bool(closed)
    if getattr(curve, "closed", False):
        return True
    extent = float(np.abs(points).max()) if len(points) else 0.0
    return bool(np.abs(points[-1] - points[0]).max() <= 1e-9 * (1.0 + extent))


def _ring(points: NDArray[np.float64]) -> NDArray[np.float64]:
    """A closed polyline without its repeated end point."""
    if len(points) > 2 and np.array_equal(points[0], points[-1]):
        return points[:-1]
    return points


def curve(fb: FrameBuffer, curve: Curve, color: Optional[Color] = None,
          tolerance: float = 0.25, fill: bool = False, closed: Optional[bool] = None, *,
          rule: Rule = "nonzero", window: Optional[WindowLike] = None,
          antialias: bool = False, method: Flattening = "subdivision",
          style: Optional[LineStyle] = None, width: Optional[float] = None,
          cap: Optional[Cap] = None, join: Optional[Join] = None,
          miter_limit: Optional[float] = None, dash: Optional[Dash] = None,
          dash_phase: Optional[float] = None, pen: Optional[PenLike] = None) -> None:
    """Draw a curve: flattened within ``tolerance`` device units, then stroked or filled.

    Parameters
    ----------
    fb : FrameBuffer
    curve : scanline.curves.Curve
        A 2-D curve whose coordinates are device coordinates (x right, y up, pixel
        centers at integers).
    color : color
    tolerance : float
        Largest distance between the curve and the drawn polyline, in pixels
        (default a quarter pixel).  > 0.
    fill : bool
        Fill the area the curve encloses (the polyline closed by a straight segment
        if the curve is open) instead of stroking it.
    closed : bool, optional
        Stroke the outline closed (a join where the ends meet, no caps).  Default:
        closed if the curve is periodic / ``closed`` or its ends coincide.
    rule : {"nonzero", "even-odd"}
        Fill rule, when ``fill``.
    window : (xmin, ymin, xmax, ymax) or polygon, optional
        Clip to this window first: the stroke by :func:`scanline.clip.polyline`
        (Liang-Barsky; a piece that leaves and re-enters the window is drawn as
        separate polylines, each with its own caps and dash phase), the filled area
        by :func:`scanline.clip.polygon` (Sutherland-Hodgman).  Without a window,
        drawing is clipped to the frame buffer as always.
    antialias : bool
        Antialiased stroke (:func:`scanline.draw.polyline`) or fill
        (:func:`scanline.draw.antialias.fill`).
    method : {"subdivision", "wang"}
        Flattening method, see :func:`scanline.curves.flatten.flatten`.
    style, width, cap, join, miter_limit, dash, dash_phase, pen
        Line attributes of the stroke, as :func:`scanline.draw.polyline` takes them
        (:class:`scanline.LineStyle`).

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer, ``curve`` not a :class:`scanline.curves.Curve`,
        or ``closed`` not a bool or None.
    ArgumentValueError
        For a curve that is not 2-D, a ``tolerance`` that is not > 0, an unknown
        ``rule`` or ``method``, a bad window, color or line attribute.

    Notes
    -----
    Notes, chapter 5: curves are displayed as polylines close to them.  For Bezier,
    B-spline, NURBS and Hermite-family curves the tolerance is guaranteed (convex
    hull property, see :mod:`scanline.curves.flatten`); the polyline's vertices are
    points of the curve.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(9, 5, mode="1")
    >>> sl.draw.curve(fb, sl.curves.Bezier([(0, 0), (4, 8), (8, 0)]), color=1)
    >>> print(sl.text_image(fb))
    ---###---
    --#---#--
    -#-----#-
    -#-----#-
    #-------#
    """
    from . import antialias as aa
    from .polygon import polygon
    from .strokes import polyline

    points = _outlines([curve], tolerance, method, lambda i: "curve")[0]
    is_closed = _is_closed(curve, points, closed)
    if fill:
        if rule not in ("nonzero", "even-odd"):
            from .._validate import choice
            choice("rule", rule, ("nonzero", "even-odd"))
        contours = [_ring(points)]
        if window is not None:
            from ..clip import polygon as clip_polygon
            contours = clip_polygon(contours[0], window)
            if not contours:
                return
        if antialias:
            aa.fill(fb, contours, color, rule)
        else:
            polygon(fb, contours, color, rule=rule)
        return
    attributes = _LineAttributes(style=style, antialias=antialias, width=width, cap=cap, join=join,
                      miter_limit=miter_limit, dash=dash, dash_phase=dash_phase, pen=pen)
    if window is None:
        polyline(fb, _ring(points) if is_closed else points, color, closed=is_closed,
                 **attributes)
        return
    from ..clip import polyline as clip_polyline
    from .strokes import polylines

    if is_closed and not np.array_equal(points[0], points[-1]):
        points = np.vstack([points, points[:1]])
    pieces = clip_polyline(points, window)
    if pieces:
        polylines(fb, pieces, color, closed=False, **attributes)


def curves(fb: FrameBuffer, curves: Iterable[Curve], color: Optional[Colors] = None,
           tolerance: float = 0.25, closed: Optional[bool] = None, *,
           antialias: bool = False, method: Flattening = "subdivision",
           style: Optional[LineStyle] = None, width: Optional[float] = None,
           cap: Optional[Cap] = None, join: Optional[Join] = None,
           miter_limit: Optional[float] = None, dash: Optional[Dash] = None,
           dash_phase: Optional[float] = None, pen: Optional[PenLike] = None) -> None:
    """Stroke many curves in one call of :func:`scanline.draw.polylines`.

    The curves are flattened together (:func:`scanline.curves.flatten.flatten_all`:
    one compiled call per degree).

    Parameters
    ----------
    fb : FrameBuffer
    curves : iterable of scanline.curves.Curve
        2-D curves in device coordinates, as :func:`curve` takes one.
    color : color, list of colors or integer array, optional
        One color for all, or one per curve (see :func:`scanline.draw.lines`).
    tolerance : float
        Largest distance between a curve and its polyline, in pixels; > 0.
    closed : bool, optional
        One value for all curves; None: decided per curve, as by :func:`curve`.
    antialias, method, style, width, cap, join, miter_limit, dash, dash_phase, pen
        As for :func:`curve`, for every curve.

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer, ``curves`` is one curve or not iterable, or
        an item is not a :class:`scanline.curves.Curve`.
    ArgumentValueError
        As for :func:`curve`; also for a list of colors whose length is not the
        number of curves.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(9, 3, mode="1")
    >>> arcs = [sl.curves.Bezier([(0, 0), (2, 4), (4, 0)]),
    ...         sl.curves.Bezier([(4, 2), (6, -2), (8, 2)])]
    >>> sl.draw.curves(fb, arcs, color=1)
    >>> print(sl.text_image(fb))
    -####---#
    -#-#-#-#-
    #---#-#--
    """
    from .strokes import polylines

    if isinstance(curves, Curve) or not hasattr(curves, "__iter__"):
        raise ArgumentTypeError(
            f"curves must be a list of scanline.curves.Curve, got {type(curves).__name__}; "
            "use sl.draw.curve for one curve"
        )
    items = list(curves)
    pieces: list[NDArray[np.float64]] = []
    flags: list[bool] = []
    for c, points in zip(items, _outlines(items, tolerance, method, lambda i: f"curves[{i}]")):
        is_closed = _is_closed(c, points, closed)
        pieces.append(_ring(points) if is_closed else points)
        flags.append(is_closed)
    if not pieces:
        return
    polylines(fb, pieces, color, closed=np.array(flags), style=style, antialias=antialias,
              width=width, cap=cap, join=join, miter_limit=miter_limit, dash=dash,
              dash_phase=dash_phase, pen=pen)
