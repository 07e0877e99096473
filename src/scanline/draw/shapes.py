"""Pillow's shapes on scanline's primitives: ``point``, ``points``, ``rectangle``,
``rectangles``, ``rounded_rectangle`` and ``regular_polygon``.

Nothing here has a kernel of its own (DESIGN.md: a rectangle is a polygon): a point
is a zero-length line, an outline is a closed polyline (with every line attribute),
an area is a polygon filled by the scan-line fill.

*Outline or area.*  As :func:`scanline.draw.curve` does, ``fill=False`` (the default)
draws the outline in ``color``, ``fill=True`` fills the area with ``color`` instead.
As Pillow's ``ImageDraw`` does, ``fill`` may also be a color: the area is filled with
it, and the outline is drawn over it in ``color`` when ``color`` is given
(``fill="red"`` alone is a red area; ``color="black", fill="red"`` a red area with
a black outline).

*Corners are pixels.*  ``rectangle(fb, x0, y0, x1, y1)`` names its corner pixels, as
:func:`scanline.draw.line` names its end pixels and :meth:`FrameBuffer.crop` its
corners: the filled rectangle covers columns x0..x1 and rows y0..y1, both ends
included, exactly Pillow's ``rectangle`` once its y axis is flipped; the outline is
the ring of pixels along its border, the centers of the outline's stroke.  As a
polygon, a filled rectangle is the union of those pixels' squares,
[x0 - 1/2, x1 + 1/2] x [y0 - 1/2, y1 + 1/2].
"""

import math
from typing import TYPE_CHECKING, Any, Optional, TypeVar, Union

import numpy as np

from .. import _validate as v
from .._typing import Angle, ArrayLike, Cap, Color, Colors, Dash, Join, NDArray, PenLike
from ..errors import ArgumentTypeError, ArgumentValueError
from . import strokes
from ._common import target
from .lines import lines
from .polygon import polygon, polygons

if TYPE_CHECKING:
    from ..attributes import FillStyle
    from ..framebuffer import FrameBuffer
    from ..linestyle import LineStyle

#: Corner radii up to this many pixels follow the midpoint circle pixel by pixel;
#: larger ones follow the ideal arcs (:data:`scanline.draw.strokes.SEQUENCE_LIMIT`).
MIDPOINT_LIMIT = strokes.SEQUENCE_LIMIT

#: Most sides a regular polygon may have.
MAX_SIDES = 1 << 20

#: The outline color of one shape (a Color) or of a batch (Colors).
_C = TypeVar("_C", bound=Optional[Colors])


# -- arguments -------------------------------------------------------------------------

def _fill(fb: "FrameBuffer", fill: Union[bool, Color, None], color: _C
          ) -> tuple[bool, Union[_C, Color, None], bool, Optional[_C]]:
    """``(filled, area_color, outline, outline_color)`` of the ``fill`` / ``color``
    pair: whether the area is filled and in what, whether the outline is drawn and
    in what (None: the foreground).  A fill color is checked here, so that an error
    names ``fill``."""
    if isinstance(fill, (bool, np.bool_)):
        return (True, color, False, None) if fill else (False, None, True, color)
    if fill is None:
        raise ArgumentTypeError(
            "fill=None: use fill=False (outline only), fill=True (the area in color) or a "
            "color for the area")
    if not isinstance(fill, (list, np.ndarray)):
        target(fb)
        fb.pixel(fill, "fill")
    return True, fill, color is not None, color


def _distinct(path: NDArray[Any]) -> NDArray[Any]:
    """``path`` without repeated consecutive vertices (nor a last one equal to the
    first)."""
    keep = np.ones(len(path), bool)
    keep[1:] = (path[1:] != path[:-1]).any(axis=1)
    path = path[keep]
    if len(path) > 1 and (path[-1] == path[0]).all():
        path = path[:-1]
    return path


def _hollow(fill_style: Optional["FillStyle"]) -> bool:
    return getattr(fill_style, "kind", None) == "hollow"


def _corners(x0: float, y0: float, x1: float, y1: float) -> tuple[int, int, int, int]:
    """The corner pixels, rounded to pixel centers, as (left, bottom, right, top)."""
    x0, y0 = v.coordinate("x0", x0), v.coordinate("y0", y0)
    x1, y1 = v.coordinate("x1", x1), v.coordinate("y1", y1)
    return min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1)


def _box(x0: int, y0: int, x1: int, y1: int) -> NDArray[np.float64]:
    """The union of the pixels (x0..x1) x (y0..y1) as a counterclockwise polygon."""
    return np.array([(x0 - 0.5, y0 - 0.5), (x1 + 0.5, y0 - 0.5), (x1 + 0.5, y1 + 0.5),
                     (x0 - 0.5, y1 + 0.5)], np.float64)


def _ring(x0: float, y0: float, x1: float, y1: float) -> NDArray[np.float64]:
    """The rectangle's outline path, counterclockwise from the bottom-left pixel."""
    return np.array([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], np.float64)


def _draw_outline(fb: "FrameBuffer", path: NDArray[np.float64], color: Optional[Colors],
                  style: Optional["LineStyle"], antialias: bool) -> None:
    """Stroke the closed ``path``; a path of zero width or height is the segment
    between its extreme points, stroked open."""
    lo, hi = path.min(axis=0), path.max(axis=0)
    if lo[0] == hi[0] or lo[1] == hi[1]:
        path = np.array([lo, hi])
        strokes.polyline(fb, path, color, closed=False, style=style, antialias=antialias)
        return
    strokes.polyline(fb, path, color, closed=True, style=style, antialias=antialias)


# -- points ------------------------------------------------------------------------------

def point(fb: "FrameBuffer", x: float, y: float, color: Optional[Color] = None) -> None:
    """Draw the pixel nearest to ``(x, y)``.

    Parameters
    ----------
    fb : FrameBuffer
    x, y : number
        Device coordinates, rounded to the nearest pixel center (halves up); within
        +-2**30.  A point outside ``fb`` is clipped.
    color : color, optional
        Default: the frame buffer's foreground.

    Notes
    -----
    The notes' first output primitive, "point plotting": a zero-length line
    (:func:`scanline.draw.line`), with the rules of drawing (the default color,
    rounding, clipping).  Like the width-1 line it stores the color's value, a
    translucent one too (:meth:`FrameBuffer.set_pixel` does the same); to
    composite a translucent color over one pixel, fill it:
    ``fill_circle(fb, x, y, 0, color)``.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(4, 3, mode="1")
    >>> sl.draw.point(fb, 1, 0)
    >>> sl.draw.point(fb, 2.6, 1.5)
    >>> print(sl.text_image(fb))
    ---#
    ----
    -#--
    """
    x, y = v.number("x", x), v.number("y", y)
    lines(fb, np.array([[x, y, x, y]], np.float64), color)


def points(fb: "FrameBuffer", points: ArrayLike, color: Optional[Colors] = None) -> None:
    """Draw N points in one compiled call.

    Parameters
    ----------
    fb : FrameBuffer
    points : array_like, shape (N, 2)
        Rows ``(x, y)``, rounded to pixel centers as :func:`point` rounds them.
    color : color or list/array of N colors
        One color for all, or one per point (later points paint over earlier ones).

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(4, 2, mode="L")
    >>> sl.draw.points(fb, [(0, 0), (3, 1)], color=[255, 128])
    >>> fb.to_array()
    array([[  0,   0,   0, 128],
           [255,   0,   0,   0]], dtype=uint8)
    """
    pts = strokes._points("points", points)
    lines(fb, np.hstack([pts, pts]), color)


# -- rectangles --------------------------------------------------------------------------

def rectangle(fb: "FrameBuffer", x0: float, y0: float, x1: float, y1: float,
              color: Optional[Color] = None, fill: Union[bool, Color] = False, *,
              fill_style: Optional["FillStyle"] = None, style: Optional["LineStyle"] = None,
              antialias: bool = False, width: Optional[float] = None, cap: Optional[Cap] = None,
              join: Optional[Join] = None, miter_limit: Optional[float] = None, dash: Optional[Dash] = None,
              dash_phase: Optional[float] = None, pen: Optional[PenLike] = None) -> None:
    """Draw the axis-aligned rectangle with corner pixels ``(x0, y0)`` and
    ``(x1, y1)``: its outline, its area, or both.

    Parameters
    ----------
    fb : FrameBuffer
    x0, y0, x1, y1 : number
        Two opposite corner pixels, in either order, rounded to pixel centers;
        within +-2**30.  What falls outside ``fb`` is clipped.
    color : color, optional
        The outline's color (default: the frame buffer's foreground); with
        ``fill=True``, the area's.
    fill : bool or color
        False: the outline only.  True: the area in ``color``, no outline.  A color:
        the area in that color, and the outline over it in ``color`` if ``color``
        is given (see the module docstring).
    fill_style : FillStyle, optional
        The area's fill style (solid by default; hollow, pattern, hatch ...).
    style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen
        The outline's line attributes, as :func:`scanline.draw.polyline` takes them;
        ``antialias`` applies to the area too (its edges are on pixel borders, so
        only a translucent color shows it).

    Notes
    -----
    The area is every pixel from x0 to x1 and from y0 to y1, both included: the
    polygon [x0 - 1/2, x1 + 1/2] x [y0 - 1/2, y1 + 1/2] filled by
    :func:`scanline.draw.polygon`.  The outline is the closed polyline through the
    four corner pixels, counterclockwise from ``(min x, min y)`` (where a dash
    pattern starts), so at width 1 it is the border ring of the area and draws
    each pixel once.  A rectangle of zero width or height is the segment between
    its corners.

    *Differences from Pillow.*  ``ImageDraw.rectangle((x0, y0, x1, y1), fill=...)``
    covers exactly the same pixels once the y axis is flipped (image row
    ``height - 1 - y``), and so does its width-1 outline.  A thicker outline differs:
    Pillow grows it inward from the border ring, scanline centers the stroke on the
    ring, as every scanline stroke is centered on its path (width 3 covers the
    ring and one pixel on each side of it), with the caps, joins and dashes of
    :class:`scanline.LineStyle`.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(7, 5, mode="1")
    >>> sl.draw.rectangle(fb, 1, 0, 5, 3)
    >>> print(sl.text_image(fb))
    -------
    -#####-
    -#---#-
    -#---#-
    -#####-

    Filled with a color, outlined in another (mode "L": gray levels):

    >>> fb = sl.FrameBuffer(6, 4, mode="L")
    >>> sl.draw.rectangle(fb, 0, 0, 4, 2, color=255, fill=100)
    >>> fb.to_array()
    array([[  0,   0,   0,   0,   0,   0],
           [255, 255, 255, 255, 255,   0],
           [255, 100, 100, 100, 255,   0],
           [255, 255, 255, 255, 255,   0]], dtype=uint8)
    """
    x0, y0, x1, y1 = _corners(x0, y0, x1, y1)
    filled, area, outline, line_color = _fill(fb, fill, color)
    attrs = strokes.resolve(style, width, cap, join, miter_limit, dash, dash_phase, pen)
    if filled:
        if _hollow(fill_style):
            _draw_outline(fb, _ring(x0, y0, x1, y1), area, None, antialias)
        else:
            polygon(fb, _box(x0, y0, x1, y1), area, rule="nonzero", style=fill_style,
                    antialias=antialias)
    if outline:
        _draw_outline(fb, _ring(x0, y0, x1, y1), line_color, attrs, antialias)


def rectangles(fb: "FrameBuffer", rectangles: ArrayLike, color: Optional[Colors] = None,
               fill: Union[bool, Colors] = False, *, style: Optional["LineStyle"] = None,
               antialias: bool = False, width: Optional[float] = None, cap: Optional[Cap] = None,
               join: Optional[Join] = None, miter_limit: Optional[float] = None,
               dash: Optional[Dash] = None, dash_phase: Optional[float] = None,
               pen: Optional[PenLike] = None) -> None:
    """Draw N rectangles in one compiled call per kind (areas, outlines).

    Parameters
    ----------
    fb : FrameBuffer
    rectangles : array_like, shape (N, 4)
        Rows ``(x0, y0, x1, y1)`` of corner pixels, as :func:`rectangle` takes them.
    color : color or list/array of N colors
        The outlines' colors (with ``fill=True``, the areas').
    fill : bool, color, or list/array of N colors
        As :func:`rectangle`'s: False, True, or the areas' colors (one, or one per
        rectangle).
    style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen
        The outlines' line attributes, one style for the whole batch.

    Notes
    -----
    Every area is filled first (:func:`scanline.draw.polygons`), then every outline
    is drawn (:func:`scanline.draw.polylines`), each kind in the order given.  Each
    rectangle is drawn exactly as :func:`rectangle` draws it, but for one case: an
    outline of zero width or height is a closed polyline there and back (the same
    pixels at width 1).

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(8, 3, mode="1")
    >>> sl.draw.rectangles(fb, [(0, 0, 2, 2), (4, 0, 7, 1)], fill=True)
    >>> print(sl.text_image(fb))
    ###-----
    ###-####
    ###-####
    """
    a = v.coordinate_array("rectangles", rectangles, 4)
    n = len(a)
    if n == 0:
        return
    lo_x, hi_x = np.minimum(a[:, 0], a[:, 2]), np.maximum(a[:, 0], a[:, 2])
    lo_y, hi_y = np.minimum(a[:, 1], a[:, 3]), np.maximum(a[:, 1], a[:, 3])
    filled, area, outline, line_color = (
        _fill(fb, fill, color) if not isinstance(fill, (list, np.ndarray))
        else (True, fill, color is not None, color))
    attrs = strokes.resolve(style, width, cap, join, miter_limit, dash, dash_phase, pen)
    if filled:
        boxes = np.stack([np.stack([lo_x - 0.5, lo_y - 0.5], 1), np.stack([hi_x + 0.5, lo_y - 0.5], 1),
                          np.stack([hi_x + 0.5, hi_y + 0.5], 1), np.stack([lo_x - 0.5, hi_y + 0.5], 1)],
                         axis=1).astype(np.float64)
        polygons(fb, boxes, area, rule="nonzero", antialias=antialias)
    if outline:
        rings = np.stack([np.stack([lo_x, lo_y], 1), np.stack([hi_x, lo_y], 1),
                          np.stack([hi_x, hi_y], 1), np.stack([lo_x, hi_y], 1)],
                         axis=1).astype(np.float64)
        strokes.polylines(fb, rings.reshape(-1, 2), line_color, closed=True,
                          counts=np.full(n, 4), style=attrs, antialias=antialias)


# -- rounded rectangles ------------------------------------------------------------------

def _quadrant(r: int) -> NDArray[np.int64]:
    """The midpoint circle's first-quadrant pixels, counterclockwise from (r, 0) to
    (0, r), each once (offsets from the center)."""
    q = strokes._quadrant(r, r)[::-1]
    keep = np.ones(len(q), bool)
    keep[1:] = (q[1:] != q[:-1]).any(axis=1)
    return q[keep].astype(np.int64)


def _pixel_path(x0: int, y0: int, x1: int, y1: int, r: int) -> NDArray[np.float64]:
    """The width-1 outline of the rounded rectangle as its pixels' sequence (the
    midpoint circle's quadrants moved to the corners; straight runs between them
    are implied), counterclockwise from (x0 + r, y0)."""
    q = _quadrant(r)
    parts = [q[::-1] * (1, -1) + (x1 - r, y0 + r),       # bottom-right: (x1 - r, y0) .. (x1, y0 + r)
             q + (x1 - r, y1 - r),                       # top-right: (x1, y1 - r) .. (x1 - r, y1)
             q[::-1] * (-1, 1) + (x0 + r, y1 - r),       # top-left: (x0 + r, y1) .. (x0, y1 - r)
             q * (-1, -1) + (x0 + r, y0 + r)]            # bottom-left: (x0, y0 + r) .. (x0 + r, y0)
    path = np.concatenate([parts[3][-1:], *parts[:3], parts[3][:-1]])
    return _distinct(path).astype(np.float64)


def _staircase(x0: int, y0: int, x1: int, y1: int, r: int) -> NDArray[np.float64]:
    """The filled rounded rectangle as a polygon whose edges lie on pixel borders:
    on each row, every pixel from the outline's left-most to its right-most
    (as :func:`scanline.draw.fill_circle` fills its outline)."""
    q = _quadrant(r)
    reach = np.full(r + 1, -1, np.int64)
    np.maximum.at(reach, q[:, 1], q[:, 0])       # the outline's extent on row dy
    dy = np.arange(r + 1)
    rows = np.concatenate([y0 + r - dy[::-1], y1 - r + dy])
    half = np.concatenate([reach[::-1], reach]) + (x1 - x0 - 2 * r) / 2
    rows, first = np.unique(rows, return_index=True)
    half = half[first]
    mid = (x0 + x1) / 2
    right = np.empty((2 * len(rows), 2))
    right[0::2, 0] = right[1::2, 0] = mid + half + 0.5
    right[0::2, 1], right[1::2, 1] = rows - 0.5, rows + 0.5
    left = right[::-1].copy()
    left[:, 0] = 2 * mid - left[:, 0]
    return np.concatenate([right, left])


def _arcs(x0: float, y0: float, x1: float, y1: float, r: float, radius: float
          ) -> NDArray[np.float64]:
    """The ideal rounded outline: arcs of ``radius`` about the corner centers
    (x0 + r, y0 + r) ... (chords within ``TOLERANCE`` of them), counterclockwise
    from the bottom edge."""
    from .._kernels.strokes import TOLERANCE

    if radius <= 0:
        return _ring(x0, y0, x1, y1)
    step = 2 * np.arccos(1 - min(TOLERANCE / radius, 1.0))
    m = int(min(max(2, np.ceil(np.pi / 2 / step)), 1 << 18))
    t = np.linspace(0, np.pi / 2, m + 1)
    centers = [(x1 - r, y0 + r), (x1 - r, y1 - r), (x0 + r, y1 - r), (x0 + r, y0 + r)]
    pieces = [np.stack([cx + radius * np.cos(t + (k - 1) * np.pi / 2),
                        cy + radius * np.sin(t + (k - 1) * np.pi / 2)], axis=1)
              for k, (cx, cy) in enumerate(centers)]
    # from the bottom-left arc's end, (x0 + r, y0 + r - radius), as the pixel path
    return _distinct(np.roll(np.concatenate(pieces), 1, axis=0))


def rounded_rectangle(fb: "FrameBuffer", x0: float, y0: float, x1: float, y1: float,
                      radius: float, color: Optional[Color] = None,
                      fill: Union[bool, Color] = False, *,
                      fill_style: Optional["FillStyle"] = None,
                      style: Optional["LineStyle"] = None, antialias: bool = False,
                      width: Optional[float] = None, cap: Optional[Cap] = None,
                      join: Optional[Join] = None, miter_limit: Optional[float] = None,
                      dash: Optional[Dash] = None, dash_phase: Optional[float] = None,
                      pen: Optional[PenLike] = None) -> None:
    """Draw the rectangle with corner pixels ``(x0, y0)`` and ``(x1, y1)`` whose
    corners are rounded with quarter circles of ``radius``.

    Parameters
    ----------
    fb : FrameBuffer
    x0, y0, x1, y1 : number
        Opposite corner pixels, as :func:`rectangle` takes them.
    radius : number
        The corners' radius >= 0, rounded to an integer and limited to half the
        shorter side, rounded down (Pillow stretches the corners instead, see
        below); 0 is :func:`rectangle`.
    color, fill, fill_style
        As :func:`rectangle`.
    style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen
        The outline's line attributes (:func:`scanline.draw.polyline`).

    Notes
    -----
    Each corner is a quadrant of the midpoint circle of ``radius`` (notes,
    chapter 2, Q.4) about the corner center (x0 + r, y0 + r) ..., joined by the
    straight sides: at width 1 the outline is that pixel sequence, counterclockwise
    from (x0 + r, y0), and ``rounded_rectangle(fb, 0, 0, 2 r, 2 r, r)`` draws the
    pixels of ``circle(fb, r, r, r)``.  The area is, on each scan line, every pixel
    from the outline's left-most to its right-most, as
    :func:`scanline.draw.fill_circle` fills: the square above fills the disk of
    ``fill_circle(fb, r, r, r)``.  A thick or antialiased outline strokes the ideal
    arcs of ``radius`` (chords within 0.1 pixel), an antialiased area is the
    rectangle's pixel squares with arcs of ``radius + 1/2`` at the corners, and so is
    any area or outline whose radius exceeds :data:`MIDPOINT_LIMIT`.

    Pillow's ``rounded_rectangle((x0, y0, x1, y1), radius)`` covers the same pixels,
    filled and outlined at width 1, once its y axis is flipped, wherever its sides
    are longer than their two corners (``x1 - x0 >= 2 radius + 2``, and likewise
    in y; a test checks radii up to 30).  Where they are not, Pillow stretches the
    corners into half ellipses across the short side, and scanline limits the
    radius to half the side, rounded down.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(9, 6, mode="1")
    >>> sl.draw.rounded_rectangle(fb, 0, 0, 8, 5, 2)
    >>> print(sl.text_image(fb))
    -#######-
    #-------#
    #-------#
    #-------#
    #-------#
    -#######-

    Filled, the same pixels and every pixel between them on each row:

    >>> fb = sl.FrameBuffer(9, 6, mode="1")
    >>> sl.draw.rounded_rectangle(fb, 0, 0, 8, 5, 2, fill=True)
    >>> print(sl.text_image(fb))
    -#######-
    #########
    #########
    #########
    #########
    -#######-
    """
    x0, y0, x1, y1 = _corners(x0, y0, x1, y1)
    r = min(v.any_radius("radius", radius), min(x1 - x0, y1 - y0) // 2)
    filled, area, outline, line_color = _fill(fb, fill, color)
    attrs = strokes.resolve(style, width, cap, join, miter_limit, dash, dash_phase, pen)
    exact = r <= MIDPOINT_LIMIT
    if filled:
        if _hollow(fill_style):
            path = (_pixel_path(x0, y0, x1, y1, r) if exact and not antialias
                    else _arcs(x0, y0, x1, y1, r, r))
            _draw_outline(fb, path, area, None, antialias)
        else:
            shape = (_staircase(x0, y0, x1, y1, r) if exact and not antialias
                     else _arcs(x0 - 0.5, y0 - 0.5, x1 + 0.5, y1 + 0.5, r + 0.5, r + 0.5))
            polygon(fb, shape, area, rule="nonzero", style=fill_style, antialias=antialias)
    if outline:
        pixels = exact and not antialias and (attrs.width == 1 or attrs.pen is not None)
        path = _pixel_path(x0, y0, x1, y1, r) if pixels else _arcs(x0, y0, x1, y1, r, r)
        _draw_outline(fb, path, line_color, attrs, antialias)


# -- regular polygons ----------------------------------------------------------------------

def regular_polygon_vertices(xc: float, yc: float, r: float, sides: int,
                             rotation: Angle = 0.0) -> NDArray[np.float64]:
    """The vertices of :func:`regular_polygon`, an (n, 2) float64 array,
    counterclockwise.

    Vertex k is at polar angle ``rotation - pi/2 + pi/n + 2 pi k / n`` from the
    center: unrotated, the bottom side is horizontal (a triangle points up, a
    square is axis-aligned), as in Pillow's ``regular_polygon`` once its y axis is
    flipped.

    Parameters
    ----------
    xc, yc : number
        The center.
    r : number
        The radius of the circumscribed circle (>= 0; 0 puts every vertex at the center).
    sides : int
        The number of sides, 3 to :data:`MAX_SIDES`.
    rotation : Angle, optional
        Turns the polygon counterclockwise about its center (radians, or a string such
        as ``"30deg"``).

    Returns
    -------
    numpy.ndarray
        (sides, 2) float64, counterclockwise; the coordinates are rounded to a grid of
        2**-24 pixel, so that cos and sin round-off do not decide which boundary pixels
        are inside.

    Raises
    ------
    ArgumentValueError
        A negative radius, fewer than 3 or more than :data:`MAX_SIDES` sides, a vertex
        beyond +-2**30.
    ArgumentTypeError
        A non-numeric argument.

    Examples
    --------
    A square of circumradius 2: its vertices at -45, 45, 135 and 225 degrees, at
    2 cos 45deg = sqrt 2 from the center on each axis:

    >>> regular_polygon_vertices(0, 0, 2, 4).round(3).tolist()
    [[1.414, -1.414], [1.414, 1.414], [-1.414, 1.414], [-1.414, -1.414]]

    A triangle about (10, 10) pointing up: the apex straight above the center, the base
    r / 2 below it (sin 30deg = 1/2) and r cos 30deg to each side:

    >>> regular_polygon_vertices(10, 10, 4, 3).round(3).tolist()
    [[13.464, 8.0], [10.0, 14.0], [6.536, 8.0]]
    """
    xc, yc = v.number("xc", xc), v.number("yc", yc)
    given, r = r, v.number("r", r)
    if r < 0:
        raise ArgumentValueError(f"r must be >= 0 (the circumscribed circle's radius), got "
                                 f"{v._show(given)}")
    n = v.positive_int("sides", sides, minimum=3)
    if n > MAX_SIDES:
        raise ArgumentValueError(f"sides={n} is more than {MAX_SIDES:,}; for a circle use "
                                 "scanline.draw.circle or fill_circle")
    a = v.angle("rotation", rotation) - math.pi / 2 + math.pi / n + 2 * math.pi * np.arange(n) / n
    # on a grid of 2**-24 pixel: cos and sin round-off (4 + 4 sin(pi) = 4 + 5e-16) would
    # otherwise decide which boundary pixels are inside
    out = np.round(np.stack([xc + r * np.cos(a), yc + r * np.sin(a)], axis=1) * 2.0**24) / 2.0**24
    if not np.isfinite(out).all() or np.abs(out).max() > v.COORD_LIMIT:
        raise ArgumentValueError(
            f"regular polygon about ({xc:g}, {yc:g}) with r={r:g} reaches beyond +-2**30; "
            "use a nearer center or a smaller radius")
    return out


def regular_polygon(fb: "FrameBuffer", xc: float, yc: float, r: float, sides: int,
                    rotation: Angle = 0.0, color: Optional[Color] = None,
                    fill: Union[bool, Color] = False, *,
                    fill_style: Optional["FillStyle"] = None,
                    style: Optional["LineStyle"] = None, antialias: bool = False,
                    width: Optional[float] = None, cap: Optional[Cap] = None,
                    join: Optional[Join] = None, miter_limit: Optional[float] = None,
                    dash: Optional[Dash] = None, dash_phase: Optional[float] = None,
                    pen: Optional[PenLike] = None) -> None:
    """Draw the regular polygon of ``sides`` sides inscribed in the circle of radius
    ``r`` about ``(xc, yc)``.

    Parameters
    ----------
    fb : FrameBuffer
    xc, yc : number
        The center, device coordinates (not rounded).
    r : number
        The circumscribed circle's radius >= 0.
    sides : int
        3 or more.
    rotation : angle
        Radians counterclockwise (or a string with its unit, ``"30deg"``); at 0 the
        bottom side is horizontal (see :func:`regular_polygon_vertices`).
    color, fill, fill_style
        As :func:`rectangle`.
    style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen
        The outline's line attributes (:func:`scanline.draw.polyline`).

    Notes
    -----
    The outline is the closed polyline through the vertices (a dash pattern starts
    at the bottom side's right end); the area is :func:`scanline.draw.polygon` of
    the vertices: the pixels whose centers are inside, by the top-left rule.  The
    two are different pixel sets, as for any polygon: a pixel the width-1 outline
    passes through may have its center just outside the area.  Draw both
    (``color=..., fill=...``) for an area with its edge.

    Pillow's ``regular_polygon(bounding_circle, n_sides, rotation)`` places the
    same vertices once its y axis is flipped (its ``rotation`` is in degrees); its
    filled pixels follow its own edge rule.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(11, 9, mode="1")
    >>> sl.draw.regular_polygon(fb, 5, 4, 4, 6)
    >>> print(sl.text_image(fb))
    -----------
    ---#####---
    --#-----#--
    --#-----#--
    -#-------#-
    --#-----#--
    --#-----#--
    ---#####---
    -----------

    The area of the same hexagon: the pixel centers inside it.  Its corners
    (1, 4) and (9, 4) lie on its boundary: by the top-left rule the left one is
    inside, the right one is not.

    >>> fb = sl.FrameBuffer(11, 9, mode="1")
    >>> sl.draw.regular_polygon(fb, 5, 4, 4, 6, fill=True)
    >>> print(sl.text_image(fb))
    -----------
    ---#####---
    ---#####---
    --#######--
    -########--
    --#######--
    ---#####---
    ---#####---
    -----------
    """
    vertices = regular_polygon_vertices(xc, yc, r, sides, rotation)
    filled, area, outline, line_color = _fill(fb, fill, color)
    attrs = strokes.resolve(style, width, cap, join, miter_limit, dash, dash_phase, pen)
    if filled:
        if _hollow(fill_style):
            strokes.polyline(fb, vertices, area, closed=True, antialias=antialias)
        else:
            polygon(fb, vertices, area, style=fill_style, antialias=antialias)
    if outline:
        strokes.polyline(fb, vertices, line_color, closed=True, style=attrs,
                         antialias=antialias)
