"""Polylines with line attributes: ``polyline`` and ``polylines``, and the stroking
shared by ``line``, ``lines``, ``circle(s)`` and ``ellipse(s)`` when they are given
a width, a line type, a pen or ``antialias=True`` (notes, syllabus: "Line
attributes"; Hearn & Baker, section 4-1).

How a stroke is drawn:

* width 1 (or any pen): the Bresenham pixels of each segment, numbered along the
  path, drawn or skipped by the line type, each drawn pixel stamping the pen
  (``_kernels/linetype.py``);
* width > 1: the outline -- segment rectangles, joins and caps, cut into dashes
  first -- filled by the scan-line polygon fill with the nonzero rule
  (``_kernels/strokes.py``);
* ``antialias=True``: the same geometry handed to :mod:`scanline.draw.antialias`
  (Wu lines for width 1, area coverage of the outline for thick strokes);
* a translucent color is composited once per stroke (:mod:`scanline.draw._blend`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, Optional, Sequence, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._kernels import linetype as kl
from .._kernels import polygon as kp
from .._kernels.polygon import NONZERO
from .._kernels import strokes as ks
from .._kernels._jit import call
from .._kernels.variants import layout
from ..errors import ArgumentTypeError, ArgumentValueError
from ..geometry import contours as parse
from ..geometry import guard
from ..linestyle import LineStyle
from . import _blend
from . import _far_conics as far
from ._common import area_work, colors, target

if TYPE_CHECKING:
    from .._typing import Cap, Colors, Dash, Join, PenLike, Points
    from ..framebuffer import FrameBuffer

#: ``draw(buf, packed, width, height, ox, oy, values, a, b)`` of :func:`_painter`.
Painter = Callable[[NDArray[np.uint8], bool, int, int, int, int, NDArray[np.uint8], int, int],
                   None]
#: An inclusive device box ``(xmin, ymin, xmax, ymax)``.
Box = Tuple[int, int, int, int]

CAPS = {"butt": ks.CAP_BUTT, "round": ks.CAP_ROUND, "square": ks.CAP_SQUARE}
JOINS = {"miter": ks.JOIN_MITER, "round": ks.JOIN_ROUND, "bevel": ks.JOIN_BEVEL}

_DEFAULT = LineStyle()
_NO_DASHES = np.zeros(0, np.float64)


def resolve(style: Optional[LineStyle], width: Optional[float] = None,
            cap: Optional[Cap] = None, join: Optional[Join] = None,
            miter_limit: Optional[float] = None, dash: Optional[Dash] = None,
            dash_phase: Optional[float] = None, pen: Optional[PenLike] = None) -> LineStyle:
    """The LineStyle of a drawing call: ``style`` (default: a plain width-1 line)
    with the keywords that are not None replacing its attributes."""
    if style is None:
        style = _DEFAULT
    elif not isinstance(style, LineStyle):
        raise ArgumentTypeError(f"style must be a scanline.LineStyle or None, got {v._show(style)}")
    changes = {name: value for name, value in (
        ("width", width), ("cap", cap), ("join", join), ("miter_limit", miter_limit),
        ("dash", dash), ("dash_phase", dash_phase), ("pen", pen)) if value is not None}
    return style.replace(**changes) if changes else style


def styled(style: Optional[LineStyle], antialias: bool, width: Optional[float] = None,
           cap: Optional[Cap] = None, join: Optional[Join] = None,
           miter_limit: Optional[float] = None, dash: Optional[Dash] = None,
           dash_phase: Optional[float] = None,
           pen: Optional[PenLike] = None) -> Optional[LineStyle]:
    """The LineStyle of a drawing call, or None when the call draws a plain width-1
    solid line, which the classic kernels draw.  A call that names no attribute
    returns at once: it is the common case, and single-primitive loops pay for every
    microsecond here."""
    if (style is None and not antialias and width is None and cap is None and join is None
            and miter_limit is None and dash is None and dash_phase is None and pen is None):
        return None
    style = resolve(style, width, cap, join, miter_limit, dash, dash_phase, pen)
    if not antialias and style.width == 1 and style.dash is None and style.pen is None:
        return None
    return style


def _closed_flags(closed: Union[bool, ArrayLike], n: int) -> NDArray[np.bool_]:
    if isinstance(closed, (bool, np.bool_)):
        return np.full(n, bool(closed))
    a = np.asarray(closed)
    if a.dtype != bool or a.shape != (n,):
        raise ArgumentValueError(
            f"closed must be True, False or one bool per polyline ({n}), got {v._show(closed)}")
    return np.ascontiguousarray(a)


def _points(name: str, points: Points) -> NDArray[np.float64]:
    """One polyline as a float64 (N, 2) array."""
    try:
        a = np.asarray(points)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"{name} must be an (N, 2) array of vertices, got {v._show(points)}") from None
    if a.size == 0:
        return np.empty((0, 2), np.float64)
    if a.ndim != 2 or a.shape[1] != 2 or a.dtype == bool or a.dtype.kind not in "iuf":
        raise ArgumentValueError(
            f"{name} must be an (N, 2) array of vertices (x, y), got {v._show(points)}")
    a = np.ascontiguousarray(a, np.float64)
    parse.check_vertices(name, a, far=True)
    return a


def batch(name: str, polylines: object,
          counts: Optional[ArrayLike]) -> Tuple[NDArray[np.float64], NDArray[np.int64]]:
    """A batch of polylines as ``(verts, offsets)``."""
    if counts is None:
        verts, offsets, polys = parse.batch(name, polylines, far=True)
        if len(polys) != len(offsets):
            raise ArgumentValueError(
                f"{name} must be a list of polylines, each one (N, 2) array of vertices")
        return verts, offsets
    verts, offsets, _ = parse.flat(name, polylines, counts, far=True)
    return verts, offsets


def _bbox(verts: NDArray[np.float64], margin: float) -> Box:
    if len(verts) == 0:
        return (0, 0, -1, -1)
    lo = np.floor(verts.min(axis=0) - margin) - 1
    hi = np.ceil(verts.max(axis=0) + margin) + 1
    return (int(lo[0]), int(lo[1]), int(hi[0]), int(hi[1]))


def _margin(style: LineStyle) -> float:
    """How far (pixels) the stroke can reach beyond its vertices."""
    if style.width == 1 or style.pen is not None:
        return int(np.abs(style.footprint()).max())
    reach: float = 0.5 * style.width
    if style.join == "miter":
        reach *= style.miter_limit
    if style.cap == "square":
        reach *= 1.5
    return reach + 1


def _line_type(style: LineStyle) -> Tuple[int, int, NDArray[np.float64], float]:
    """``(kind, mask, dashes, phase)`` of the pixel-sequence kernels for a width-1 or
    pen line."""
    mask = style.mask()
    if style.dash is None:
        return kl.SOLID, 0, _NO_DASHES, 0.0
    if mask is not None:
        return kl.MASK, mask, _NO_DASHES, float(np.floor(style.dash_phase) % 16)
    return kl.LENGTHS, 0, np.array(style.dash, np.float64), float(style.dash_phase)


def path_work(points: NDArray[Any], width: int, height: int) -> float:
    """Work units of drawing the width-1 path through ``points``: its steps, each
    segment's at most width + height once clipped (:func:`scanline._kernels._jit.call`)."""
    if len(points) < 2:
        return len(points)
    d = np.abs(np.diff(points, axis=0)).max(axis=1)
    return float(np.minimum(d, width + height).sum()) + len(points)


def dash_work(points: NDArray[np.float64], lengths: Sequence[float]) -> float:
    """Work units of cutting the path through ``points`` into dashes of ``lengths``:
    a few per vertex and per dash."""
    if len(points) < 2:
        return len(points)
    length = float(np.hypot(*np.diff(points, axis=0).T).sum())
    return 2 * len(points) + length / max(sum(lengths), 1e-9) * len(lengths)


def outline_work(points: NDArray[np.float64], r: float) -> float:
    """Work units of the stroke outline of half-width ``r`` along ``points``: a join
    (at most half a turn of arc) and a few corners per vertex."""
    arc = np.pi / np.arccos(1 - min(ks.TOLERANCE / max(r, ks.TOLERANCE), 1.0))
    return len(points) * (2 + float(arc) / 5)


def _painter(style: LineStyle, verts: NDArray[np.float64], offsets: NDArray[np.int64],
             closed: NDArray[np.bool_], one: bool = False) -> Painter:
    """``draw(buf, packed, width, height, ox, oy, values, a, b)``: draws polylines
    a .. b-1 with the (1 or b-a rows of) channel values (``one``: solid thick
    polylines as one shape, each pixel once)."""
    if style.width == 1 or style.pen is not None:
        iverts = np.floor(verts + 0.5).astype(np.int64)
        kind, mask, dashes, phase = _line_type(style)
        pen = style.footprint()
        margin = int(np.abs(pen).max())

        def draw(buf: NDArray[np.uint8], packed: bool, width: int, height: int, ox: int,
                 oy: int, values: NDArray[np.uint8], a: int, b: int) -> None:
            o = offsets[a:b + 1]
            pts = iverts[o[0]:o[-1]] - np.array([ox, oy], np.int64)
            call(kl.draw_patterned, lambda: 2 * path_work(pts, width, height) * len(pen), buf,
                 layout(packed), width, height, pts, o - o[0], closed[a:b], values, kind, mask,
                 dashes, phase, pen, margin)
        return draw
    lengths, phase = style.lengths()
    cap, join = CAPS[style.cap], JOINS[style.join]
    r = 0.5 * style.width

    def thick(buf: NDArray[np.uint8], packed: bool, width: int, height: int, ox: int, oy: int,
              values: NDArray[np.uint8], a: int, b: int) -> None:
        o = offsets[a:b + 1]
        pieces = verts[o[0]:o[-1]], o - o[0], closed[a:b]
        if lengths is None:
            owner = np.zeros(b - a, np.int64) if one else np.arange(b - a)
        else:   # the dashes that can reach the raster, widened by the reach of joins
            reach = r * max(style.miter_limit, 2.0) + 2.0
            box = np.array([ox - reach, oy - reach, ox + width - 1 + reach,
                            oy + height - 1 + reach])
            *pieces, owner = call(ks.dashed_polylines, lambda: dash_work(pieces[0], lengths),
                                  *pieces, np.array(lengths, np.float64), float(phase), box)
        out, contours, polys, most = call(ks.stroke_outlines, lambda: outline_work(pieces[0], r),
                                          *pieces, owner, 1 if one else b - a, r, cap, join,
                                          style.miter_limit)
        work = area_work(width, height, out - (ox, oy), b - a) / 4 if len(out) else 0
        if len(values) == 1 and b - a > 1:   # one color: any order gives the same image
            out, contours, polys = call(kp.band_reordered, len(out), out, contours, polys, oy,
                                        height)
        call(kp.fill_polygons, work, buf, layout(packed), width, height, ox, oy, out, contours,
             polys, values, NONZERO, most)
    return thick


def stroke(fb: FrameBuffer, verts: NDArray[np.float64], offsets: NDArray[np.int64],
           closed: NDArray[np.bool_], color: Optional[Colors], style: LineStyle,
           antialias: bool = False, one: bool = False) -> None:
    """Draw polylines ``verts[offsets[i]:offsets[i + 1]]`` (``closed[i]``) in
    ``style`` with ``color`` (one, or one per polyline); ``one``: the polylines
    are the dashes of one path, cut already (solid ``style``, one color, within
    the exact range), stroked as one shape, so each pixel is covered once, as the
    pieces of a dashed polyline are."""
    buf, packed, width, height = target(fb)
    given = len(offsets) - 1
    verts, offsets, closed, owner = guard.paths(verts, offsets, closed)
    if isinstance(color, (list, np.ndarray)) and len(color) == given != len(owner):
        color = _per_piece(color, owner)        # far polylines were cut into pieces
    n = len(offsets) - 1
    if n == 0:
        return
    if antialias:
        _antialiased(fb, verts, offsets, closed, color, style, one)
        return
    draw = _painter(style, verts, offsets, closed, one)
    if not _blend.translucent(color):
        draw(buf, packed, width, height, 0, 0, colors(fb, color, n), 0, n)
        return
    # translucent: each polyline composited on its own (once, however often it
    # crosses itself), later ones over earlier ones
    margin = _margin(style)
    if one:
        assert not isinstance(color, (list, np.ndarray))    # ``one``: one color
        _blend.paint(fb, color, _bbox(verts, margin),
                     lambda b, p, w, h, ox, oy, value: draw(b, p, w, h, ox, oy, value[None, :], 0, n))
        return
    boxes = [_bbox(verts[offsets[i]:offsets[i + 1]], margin) for i in range(n)]
    _blend.paint_each(fb, color, n, boxes,
                      lambda i, b, p, w, h, ox, oy, value: draw(b, p, w, h, ox, oy,
                                                                value[None, :], i, i + 1))


def _per_piece(color: Optional[Colors], owner: NDArray[np.int64]) -> Optional[Colors]:
    """One color per piece when ``color`` gives one per polyline."""
    if isinstance(color, np.ndarray):
        return color[owner]
    if isinstance(color, list):
        return [color[i] for i in owner]
    return color


def _view(fb: FrameBuffer, margin: float) -> NDArray[np.float64]:
    """The frame buffer's area widened by ``margin`` pixels, as a float box."""
    return np.array([-margin, -margin, fb.width - 1 + margin, fb.height - 1 + margin],
                    np.float64)


def _antialiased(fb: FrameBuffer, verts: NDArray[np.float64], offsets: NDArray[np.int64],
                 closed: NDArray[np.bool_], color: Optional[Colors], style: LineStyle,
                 one: bool = False) -> None:
    from . import antialias as aa

    if style.pen is not None:
        raise ArgumentValueError(
            "antialias=True draws ideal strokes; a pen footprint is a raster stamp and is "
            "not antialiased (use width= with cap= and join= instead of pen=)")
    lengths, phase = style.lengths()
    if style.width == 1:
        if lengths is not None:
            verts, offsets, closed, owner = call(
                ks.dashed_polylines, lambda: dash_work(verts, lengths), verts, offsets, closed,
                np.array(lengths, np.float64), float(phase), _view(fb, 3.0))
        else:
            owner = np.arange(len(offsets) - 1)
        segs, seg_owner = [], []
        for i in range(len(offsets) - 1):
            ring = verts[offsets[i]:offsets[i + 1]]
            if owner[i] < 0 or len(ring) == 0:
                continue
            if len(ring) == 1:
                ring = np.vstack([ring, ring])
            if closed[i] and len(ring) > 2:
                ring = np.vstack([ring, ring[:1]])
            segs.append(np.hstack([ring[:-1], ring[1:]]))
            seg_owner.append(np.full(len(ring) - 1, owner[i]))
        if segs:
            owners = np.concatenate(seg_owner)
            aa.lines(fb, np.concatenate(segs), _per_piece(color, owners))
        return
    npoly = 1 if one else len(offsets) - 1
    if lengths is None:
        owner = np.zeros(len(offsets) - 1, np.int64) if one else np.arange(npoly)
    else:
        verts, offsets, closed, owner = call(
            ks.dashed_polylines, lambda: dash_work(verts, lengths), verts, offsets, closed,
            np.array(lengths, np.float64), float(phase), _view(fb, _margin(style)))
    out, contours, polys, _ = call(
        ks.stroke_outlines, lambda: outline_work(verts, 0.5 * style.width), verts, offsets,
        closed, owner, npoly, 0.5 * style.width, CAPS[style.cap], JOINS[style.join],
        style.miter_limit)
    # the outlines are already flat arrays (vertices, contour offsets, shape offsets):
    # hand them over as they are rather than as lists of contours
    aa.fills_flat(fb, out, contours, polys, color, "nonzero")


def polyline(fb: FrameBuffer, points: Points, color: Optional[Colors] = None,
             closed: bool = False, *, style: Optional[LineStyle] = None,
             antialias: bool = False, width: Optional[float] = None, cap: Optional[Cap] = None,
             join: Optional[Join] = None, miter_limit: Optional[float] = None,
             dash: Optional[Dash] = None, dash_phase: Optional[float] = None,
             pen: Optional[PenLike] = None) -> None:
    """Draw a polyline (open, or closed: a polygon outline) with line attributes.

    Parameters
    ----------
    fb : FrameBuffer
    points : array_like, shape (N, 2)
        The vertices in device coordinates, finite and within +-2**30.  Width-1 and
        pen lines round them to pixel centers; thick lines use them as given.
    color : color or list of colors
    closed : bool
        Join the last vertex to the first (a polygon outline, with a join there and
        no caps).
    style : LineStyle, optional
        The line attributes; the keywords below override its fields.
    antialias : bool
        Draw with :mod:`scanline.draw.antialias` (Wu lines at width 1, area
        coverage of the outline for thick lines).
    width, cap, join, miter_limit, dash, dash_phase, pen
        See :class:`scanline.LineStyle`.  None keeps the style's value (default: a
        width-1 solid line, butt caps, miter joins, miter limit 10).

    Notes
    -----
    Notes, syllabus: "Line attributes - Line type. Line width. Pen and Brush
    options".  A width-1 polyline is the Bresenham pixels of its segments (the same
    pixels as :func:`scanline.draw.line`), each vertex pixel once; the line type is
    applied to the pixels numbered along the path (Hearn & Baker's pixel masks), so a
    pattern runs on across the vertices.  A thick polyline is the union of segment
    rectangles, joins and caps, filled with the scan-line fill by the nonzero rule
    (every pixel once: translucent colors blend once).  Dash lengths are measured
    along the path from ``dash_phase`` and carry across vertices and around closed
    polylines.

    References
    ----------
    D. Hearn and M. P. Baker, "Computer Graphics", 2nd ed., 1994, section 4-1.
    J. E. Bresenham, "Algorithm for computer control of a digital plotter", IBM
    Systems Journal 4(1), 25-30, 1965.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(8, 5, mode="1")
    >>> sl.draw.polyline(fb, [(0, 0), (7, 0), (7, 4)], color=1, dash=0b1100110011001100)
    >>> print(sl.text_image(fb))
    --------
    --------
    -------#
    -------#
    ##--##--

    (Pixels 0-7 of the path run along y = 0, pixels 8-11 up x = 7: the mask 1100...
    continues round the corner.)

    A thick polyline with round caps and joins:

    >>> fb = sl.FrameBuffer(9, 7, mode="1")
    >>> sl.draw.polyline(fb, [(1, 1), (7, 1), (7, 5)], color=1, width=3, cap="round", join="round")
    >>> print(sl.text_image(fb))
    ------###
    ------###
    ------###
    ------###
    #########
    #########
    #########
    """
    style = resolve(style, width, cap, join, miter_limit, dash, dash_phase, pen)
    verts = _points("points", points)
    offsets = np.array([0, len(verts)], np.int64)
    stroke(fb, verts, offsets, _closed_flags(closed, 1), color, style, antialias)


def polylines(fb: FrameBuffer, polylines: Union[Sequence[Points], ArrayLike],
              color: Optional[Colors] = None, closed: Union[bool, ArrayLike] = False, *,
              counts: Optional[ArrayLike] = None, style: Optional[LineStyle] = None,
              antialias: bool = False, width: Optional[float] = None,
              cap: Optional[Cap] = None, join: Optional[Join] = None,
              miter_limit: Optional[float] = None, dash: Optional[Dash] = None,
              dash_phase: Optional[float] = None, pen: Optional[PenLike] = None) -> None:
    """Draw M polylines with line attributes in one compiled call.

    Parameters
    ----------
    fb : FrameBuffer
    polylines : list of (N_i, 2) array_like, or (M, K, 2) array
        The polylines; with ``counts``, one (V, 2) array of all their vertices.
    color : color or list/array of M colors
        One color for all, or one per polyline (later ones paint over earlier ones).
    closed : bool or array of M bools
    counts : array_like of int, optional
        Vertices per polyline for the flat form.
    style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen
        As :func:`polyline`; one style for the whole batch.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(6, 4, mode="1")
    >>> sl.draw.polylines(fb, [[(0, 0), (5, 0)], [(0, 3), (5, 3)]], color=1, dash=(2, 1))
    >>> print(sl.text_image(fb))
    ##-##-
    ------
    ------
    ##-##-
    """
    style = resolve(style, width, cap, join, miter_limit, dash, dash_phase, pen)
    verts, offsets = batch("polylines", polylines, counts)
    n = len(offsets) - 1
    stroke(fb, verts, offsets, _closed_flags(closed, n), color, style, antialias)


def segment_array(name: str, segments: ArrayLike) -> NDArray[np.float64]:
    """(N, 4) float64 segments, finite and within +-2**30 (not rounded)."""
    try:
        if np.asarray(segments).dtype.kind in "cbSUV":    # complex, bool, text
            raise TypeError
        a = np.asarray(segments, dtype=np.float64)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"{name} must be a numeric array of shape (N, 4), got {v._show(segments)}") from None
    if a.size == 0:
        a = a.reshape(0, 4)
    if a.ndim == 1 and a.size == 4:
        a = a.reshape(1, 4)
    if a.ndim != 2 or a.shape[1] != 4:
        raise ArgumentValueError(f"{name} must have shape (N, 4), got shape {a.shape}")
    a = np.ascontiguousarray(a)
    parse.check_vertices(name, a.reshape(-1, 2), far=True)
    return a


# -- conics -------------------------------------------------------------------------

#: Largest radius of a patterned or pen-drawn width-1 conic whose whole pixel
#: sequence is built in memory; larger ones number only their visible pixels
#: (:func:`scanline.geometry.far_conics.sequence_runs`).
SEQUENCE_LIMIT = 1 << 16


def _quadrant(rx: int, ry: int) -> NDArray[np.int64]:
    """The midpoint pixels of the first quadrant in order, from (0, ry) clockwise to
    (rx, 0), as offsets from the center."""
    from .._kernels import conics as kc

    if rx == ry:
        out = np.zeros((rx + 1, 3), np.int64)
        n = call(kc.circle_trace, rx, rx, out)
        octant = np.vstack([[[0, rx]], out[:n, 1:3]])
        octant = octant[octant[:, 0] <= octant[:, 1]]
        quadrant = np.vstack([octant, octant[::-1, ::-1]])
    else:
        out = np.zeros((rx + ry + 1, 6), np.int64)
        n = call(kc.ellipse_trace, rx + ry, rx, ry, out)
        quadrant = np.vstack([[[0, ry]], out[:n, 2:4]])
    return quadrant


def conic_pixels(xc: int, yc: int, rx: int, ry: int) -> NDArray[np.int64]:
    """The pixels of the midpoint circle (rx == ry) or ellipse in path order:
    counterclockwise from (xc + rx, yc), each once -- the pixel sequence a line type
    numbers (radii up to SEQUENCE_LIMIT)."""
    q = _quadrant(rx, ry)[::-1]                   # (rx, 0) .. (0, ry): counterclockwise
    loop = np.vstack([q, q[::-1] * [-1, 1], q * [-1, -1], q[::-1] * [1, -1]])
    keep = np.ones(len(loop), bool)
    keep[1:] = (loop[1:] != loop[:-1]).any(axis=1)
    loop = loop[keep]
    if len(loop) > 1 and (loop[-1] == loop[0]).all():
        loop = loop[:-1]
    return np.ascontiguousarray(loop + [xc, yc], dtype=np.int64)


def conic_polyline(xc: float, yc: float, rx: float, ry: float) -> NDArray[np.float64]:
    """A closed polygon following the ellipse (xc, yc, rx, ry), counterclockwise
    from (xc + rx, yc), with chords within ``TOLERANCE`` of it and the area of the
    ellipse (its vertices at sqrt(t / sin t) times the radii, t the angular step)."""
    r = max(rx, ry, 1)
    n = min(max(8, int(np.ceil(np.pi / np.arccos(1 - min(ks.TOLERANCE / r, 1.0))))), 1 << 20)
    t = 2 * np.pi / n
    scale = np.sqrt(t / np.sin(t))
    a = np.arange(n) * t
    return np.stack([xc + scale * rx * np.cos(a), yc + scale * ry * np.sin(a)], axis=1)


def conics(fb: FrameBuffer, rows: NDArray[np.int64], color: Optional[Colors], style: LineStyle,
           antialias: bool) -> None:
    """Draw conics ``rows`` (N, 4) int: (xc, yc, rx, ry) with line attributes."""
    n = len(rows)
    if n == 0:
        return
    if antialias and style.width == 1 and style.dash is None and style.pen is None:
        from . import antialias as aa
        if (rows[:, 2] == rows[:, 3]).all():
            aa.circles(fb, rows[:, :3].astype(np.float64), color)
        else:
            aa.ellipses(fb, rows.astype(np.float64), color)
        return
    if antialias or style.width > 1 and style.pen is None:
        polys = [conic_polyline(*row) for row in rows.tolist()]
        verts = np.concatenate(polys)
        offsets = np.zeros(n + 1, np.int64)
        offsets[1:] = np.cumsum([len(p) for p in polys])
        stroke(fb, verts, offsets, np.ones(n, bool), color, style, antialias)
        return
    kind, mask, dashes, phase = _line_type(style)
    pen = style.footprint()
    values = colors(fb, color, n) if not _blend.translucent(color) else None
    margin = int(np.abs(pen).max())
    for i, (xc, yc, rx, ry) in enumerate(rows.tolist()):
        if max(rx, ry) > SEQUENCE_LIMIT:                 # only its visible pixels
            far.stroke(fb, xc, yc, rx, ry, far.spec(color, i), style, False, rx == ry)
            continue
        pixels = conic_pixels(xc, yc, rx, ry)

        def draw(buf: NDArray[np.uint8], packed: bool, width: int, height: int, ox: int,
                 oy: int, value: NDArray[np.uint8], pixels: NDArray[np.int64] = pixels) -> None:
            call(kl.draw_sequence, len(pixels) * len(pen), buf, layout(packed), width, height,
                 pixels - np.array([ox, oy], np.int64), kind, mask, dashes, phase, pen, value)
        if values is not None:
            buf, packed, width, height = target(fb)
            draw(buf, packed, width, height, 0, 0, values[i if len(values) > 1 else 0])
        else:
            _blend.paint(fb, far.spec(color, i), (xc - rx - margin - 1, yc - ry - margin - 1,
                                    xc + rx + margin + 1, yc + ry + margin + 1), draw)
