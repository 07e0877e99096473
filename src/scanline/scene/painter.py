"""Drawing a display file on a frame buffer in few draw calls, with the pixels of
:func:`scanline.display.interpret`.

The interpreter sends every primitive to the device on its own (only runs of alike
primitives inside one segment are batched), and each ``sl.draw`` call checks its
arguments again: for a frame of a few hundred small primitives that costs far more
than the pixels.  Here each primitive is first turned into what the interpreter
would send the raster device -- an area to fill, thin line segments, or strokes in
one line style -- computed by the same functions on the same arrays (the segment
and workstation mapping, :func:`scanline.display.pipeline.polylines`, Sutherland–
Hodgman for areas that cross their clipping rectangle), together with the box of
the pixels it can touch.  Then the items are gathered into batches, each drawn by
one ``sl.draw.polygons``, ``sl.draw.lines`` or ``sl.draw.polylines`` call with one
color per item:

an item joins a batch of its kind drawn before it when no item drawn between that
batch and itself can touch one of its pixels (their boxes are apart), so moving it
forward changes no pixel; otherwise it starts a new batch.  Inside a batch the
items keep their order, and each is painted as its own call paints it (one fill
per polygon, one outline per polyline, each segment by Bresenham's algorithm).

Only opaque solid items are batched; the rest (translucent colors, fill styles,
area edges, text, markers, runs the interpreter batches itself, highlighted or
3-D segments, antialiased devices, color-table frame buffers whose table grows in
drawing order) are drawn by the interpreter's own functions, in their place.
"""

import math
from collections.abc import Callable, Hashable, Iterable, Sequence
from typing import TYPE_CHECKING, Any, Union, cast

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .. import draw
from ..clip.window import _ring, signed_area
from ..display import batch, pipeline, three_d
from ..display.devices import RasterDevice, _segments, _simple
from ..display.interpreter import clip_rectangle, device_frame, draw_run, draw_segment
from ..display.viewing import workstation
from ..draw._blend import translucent

if TYPE_CHECKING:
    from .._typing import Color
    from ..display.file import DisplayFile, Segment
    from ..display.primitives import Primitive
    from ..framebuffer import FrameBuffer
    from ..linestyle import LineStyle

#: An item's box: (x0, y0, x1, y1).
_Box = tuple[float, float, float, float]
#: (lo, hi) corners of points, as [x, y] lists.
_Extent = tuple[list[float], list[float]]
#: A primitive's item, None (drawn by the interpreter) or () (nothing to draw).
_MaybeItem = Union["_Item", tuple[()], None]
#: The attributes of a call item (none).
_NO_ATTRIBUTES: dict[str, Any] = {}

_LIMIT = v.COORD_LIMIT
#: Everything: the box of an item that may touch any pixel.
_ANYWHERE: _Box = (-math.inf, -math.inf, math.inf, math.inf)


class _Item:
    """What one primitive sends the raster device.

    ``kind``: "area" (``geometry``: contours), "lines" or "stroke" (``geometry``:
    pieces, ``closed``), or "call" (``geometry``: a function of the device that
    draws it as the interpreter does).  ``key``: items of equal keys can share a
    draw call (None: drawn alone).  ``box``: (x0, y0, x1, y1) holding every pixel it
    can touch.
    """

    __slots__ = ("kind", "key", "box", "geometry", "closed", "attributes")

    kind: str
    key: Hashable | None
    box: _Box
    geometry: Any
    closed: bool
    attributes: dict[str, Any]

    def __init__(self, kind: str, key: Hashable | None, box: _Box, geometry: Any,
                 closed: bool = False, attributes: dict[str, Any] = _NO_ATTRIBUTES) -> None:
        self.kind, self.key, self.box = kind, key, box
        self.geometry, self.closed, self.attributes = geometry, closed, attributes


def _box(lo: Sequence[float], hi: Sequence[float], margin: float) -> _Box:
    return (lo[0] - margin, lo[1] - margin, hi[0] + margin, hi[1] + margin)


def _extent(arrays: Sequence[NDArray[np.float64]]) -> _Extent | None:
    """(lo, hi) of the points of ``arrays`` as [x, y] lists, or None when one is
    beyond the coordinate limit or not finite (the interpreter then reports it)."""
    if len(arrays) == 1:
        lo, hi = arrays[0].min(axis=0).tolist(), arrays[0].max(axis=0).tolist()
    else:
        lo = np.minimum.reduce([a.min(axis=0) for a in arrays]).tolist()
        hi = np.maximum.reduce([a.max(axis=0) for a in arrays]).tolist()
    if not (-_LIMIT <= lo[0] and -_LIMIT <= lo[1] and hi[0] <= _LIMIT and hi[1] <= _LIMIT):
        return None
    return lo, hi


def _inside(lo: Sequence[float], hi: Sequence[float], rect: Sequence[float]) -> bool:
    return rect[0] <= lo[0] and rect[1] <= lo[1] and hi[0] <= rect[2] and hi[1] <= rect[3]


def _reach(style: "LineStyle", pieces: Sequence[NDArray[np.float64]], closed: bool) -> float:
    """How far (device units) a stroke of ``style`` along ``pieces`` can paint from
    its path: the half width, times the miter limit where mitered joins can reach
    (a miter's tip is at most miter_limit half widths from its vertex), or times
    sqrt(2) at square caps; plus 2 for rounding."""
    factor = math.sqrt(2.0) if style.cap == "square" else 1.0
    joins = closed or any(len(p) > 2 for p in pieces)
    if joins and style.join == "miter":
        factor = max(factor, style.miter_limit)
    reach: float = 0.5 * style.width * factor + 2.0
    return reach


def _opaque(color: Any, fb: "FrameBuffer") -> bool:
    return fb.mode != "P" and not translucent(color, one=True)


def _number(style: "LineStyle", styles: dict[object, int]) -> int:
    """A number for ``style``, the same for equal styles (cheap to compare);
    ``styles`` holds the numbers given, by identity and by value."""
    number = styles.get(id(style))
    if number is None:
        number = styles[id(style)] = styles.setdefault(style, len(styles))
    return number


def _stroke_item(points: NDArray[np.float64], closed: bool, attributes: dict[str, Any],
                 rect: Sequence[float], fb: "FrameBuffer", styles: dict[object, int]) -> _MaybeItem:
    """The item of a polyline in device coordinates (None: out of range, ``()``:
    clipped away)."""
    extent = _extent([points])
    if extent is None:
        return None
    lo, hi = extent
    if len(points) and _inside(lo, hi, rect):
        pieces = [points]                   # what pipeline.polylines returns inside
    else:
        pieces, closed = pipeline.polylines(points, closed, rect)
        if not pieces:
            return ()
        lo, hi = cast(_Extent, _extent(pieces))    # clipped to rect: in range
    color, style = attributes["color"], attributes["style"]
    simple = _simple(style)
    kind = "lines" if simple else "stroke"
    key = (kind, 0 if simple else _number(style, styles)) if _opaque(color, fb) else None
    margin = 1.0 if simple else _reach(style, pieces, closed)
    return _Item(kind, key, _box(lo, hi, margin), pieces, closed, attributes)


def _area_item(contours: Sequence[NDArray[np.float64]], attributes: dict[str, Any],
               rect: Sequence[float], fb: "FrameBuffer") -> _MaybeItem:
    """The item of a fill area in device coordinates (None: out of range, ``()``:
    nothing to fill)."""
    extent = _extent(contours)
    if extent is None:
        return None
    lo, hi = extent
    if _inside(lo, hi, rect):
        # Sutherland-Hodgman returns a contour inside the window as it is, without
        # repeated vertices, and drops the rings of no area
        rings = [_ring(c) for c in contours]
        clipped = [r for r in rings if len(r) >= 3 and signed_area(r) != 0.0]
    else:
        clipped = pipeline.contours(contours, rect)
        if clipped:
            lo, hi = cast(_Extent, _extent(clipped))    # clipped to rect: in range
    if not clipped:
        return ()
    color = attributes["color"]
    key = ("area", attributes["rule"]) if len(clipped) == 1 and _opaque(color, fb) else None
    return _Item("area", key, _box(lo, hi, 1.0), clipped, attributes=attributes)


def _item(prim: "Primitive", lin: NDArray[np.float64], t: NDArray[np.float64],
          rect: Sequence[float], fb: "FrameBuffer", styles: dict[object, int]) -> _MaybeItem:
    """The item of one primitive (mapped by the linear part ``lin`` and the
    translation ``t`` of the device matrix, as ``Primitive.transformed`` maps it):
    None when the interpreter's own function has to draw it, ``()`` when nothing is
    drawn."""
    kind, a = prim.kind, prim.attributes
    if kind not in ("polyline", "polygon", "ellipse"):
        return None
    if kind == "polygon" and (a["style"] is not None or a["edge"] is not None):
        return None
    if kind == "ellipse" and a["fill"] and a["style"] is not None:
        return None
    g = prim._moved(lin, t)
    if kind == "polyline":
        return _stroke_item(g["points"], a["closed"], a, rect, fb, styles)
    if kind == "polygon":
        return _area_item(g["contours"], a, rect, fb)
    ring = pipeline.ellipse_points(g["center"], g["axes"])
    if a["fill"]:
        return _area_item([ring], a, rect, fb)
    return _stroke_item(ring, True, a, rect, fb, styles)


def _call(function: Callable[..., object], *args: Any, **kwargs: Any) -> _Item:
    """An item that ``function(*args, device=device, **kwargs)`` draws."""
    return _Item("call", None, _ANYWHERE,
                 lambda device: function(*args, device=device, **kwargs))


def items(segments: Iterable["Segment"], display_file: "DisplayFile", fb: "FrameBuffer",
          device: RasterDevice, highlight: "Color") -> list[_Item]:
    """The items of ``segments`` (in drawing order), in drawing order.

    Parameters
    ----------
    segments : iterable of Segment
        Display-file segments in drawing order.
    display_file : DisplayFile
        Their display file.
    fb : FrameBuffer
        The frame buffer they are drawn on.
    device : RasterDevice
        The device on ``fb``.
    highlight : color
        The highlight color of highlighted segments.

    Returns
    -------
    list of _Item
        Each with its ``kind`` ("area", "lines", "stroke" or "call"), ``key`` and
        ``box``.

    Examples
    --------
    Two squares and a line: areas, and thin lines:

    >>> import scanline as sl
    >>> from scanline.display.interpreter import drawing_order
    >>> scene = sl.scene.Scene({"version": 1, "canvas": {"width": 24, "height": 4,
    ...     "background": "black"},
    ...     "segments": [{"name": "a", "primitives": [
    ...         {"type": "polygon", "points": [[0.5, 0.5], [2.5, 0.5], [2.5, 2.5], [0.5, 2.5]]},
    ...         {"type": "polyline", "points": [[4, 0], [6, 0]]},
    ...         {"type": "polygon", "points": [[16.5, 0.5], [18.5, 0.5], [18.5, 2.5],
    ...                                        [16.5, 2.5]]}]}]})
    >>> df = scene.display_file
    >>> fb = sl.FrameBuffer(24, 4)
    >>> todo = items(drawing_order(df), df, fb, RasterDevice(fb), "magenta")
    >>> [(it.kind, it.key) for it in todo]
    [('area', ('area', 'even-odd')), ('lines', ('lines', 0)), ('area', ('area', 'even-odd'))]
    """
    with np.errstate(all="ignore"):      # overflow -> inf, refused by _extent
        return _items(segments, display_file, fb, device, highlight)


def _items(segments: Iterable["Segment"], display_file: "DisplayFile", fb: "FrameBuffer",
           device: RasterDevice, highlight: "Color") -> list[_Item]:
    ws = workstation(device.width, device.height)
    frame = device_frame(ws)
    rects: dict[object, Any] = {}                # clip rectangle of each viewport
    styles: dict[object, int] = {}               # line style -> its number
    out: list[_Item] = []
    for seg in segments:
        prims = seg.primitives
        if seg.highlighted or device.antialias or any(q.kind in three_d.KINDS for q in prims):
            out.append(_call(draw_segment, seg, display_file, ws, frame,
                             highlight=highlight))
            continue
        m = ws @ seg.transformation
        lin, t = m[:2, :2], m[:2, 2]
        for start, run, same in batch.runs(prims):
            clip = run[0].clip
            if clip not in rects:
                rects[clip] = clip_rectangle(run[0], ws, frame)
            rect = rects[clip]
            if rect is None:
                continue
            item = _item(run[0], lin, t, rect, fb, styles) if len(run) == 1 else None
            if item is None:
                out.append(_call(draw_run, seg, start, run, same, m, rect))
            elif isinstance(item, _Item):          # not (): nothing to draw
                out.append(item)
    return out


#: Side (pixels) of the cells in which :func:`batches` notes what was drawn where.
CELL = 8


def batches(todo: Iterable[_Item], width: int, height: int) -> list[list[_Item]]:
    """``todo`` (items in drawing order) gathered into batches that draw the same
    pixels on a ``width`` x ``height`` frame buffer: a list of lists of items, drawn
    one after the other.

    A grid of :data:`CELL`-pixel cells holds the last batch that paints in each
    cell; an item must be drawn after the last batch in the cells its box covers,
    and joins the first batch of its kind from there on (or starts one).

    Parameters
    ----------
    todo : iterable of _Item
        Items in drawing order (:func:`items`).
    width, height : int
        The frame buffer's size.

    Returns
    -------
    list of list of _Item

    Examples
    --------
    The second square is far from the line drawn before it: it joins the first
    square's batch.

    >>> import scanline as sl
    >>> from scanline.display.interpreter import drawing_order
    >>> scene = sl.scene.Scene({"version": 1, "canvas": {"width": 24, "height": 4,
    ...     "background": "black"},
    ...     "segments": [{"name": "a", "primitives": [
    ...         {"type": "polygon", "points": [[0.5, 0.5], [2.5, 0.5], [2.5, 2.5], [0.5, 2.5]]},
    ...         {"type": "polyline", "points": [[4, 0], [6, 0]]},
    ...         {"type": "polygon", "points": [[16.5, 0.5], [18.5, 0.5], [18.5, 2.5],
    ...                                        [16.5, 2.5]]}]}]})
    >>> df = scene.display_file
    >>> fb = sl.FrameBuffer(24, 4)
    >>> todo = items(drawing_order(df), df, fb, RasterDevice(fb), "magenta")
    >>> [[it.kind for it in batch] for batch in batches(todo, 24, 4)]
    [['area', 'area'], ['lines']]
    """
    out: list[list[_Item]] = []
    keys: list[Hashable | None] = []
    cols, rows = -(-width // CELL), -(-height // CELL)
    latest = np.full((rows, cols), -1, np.int64)
    right, bottom = width - 1.0, height - 1.0
    for item in todo:
        x0, y0, x1, y1 = item.box
        cells = latest[int(min(max(y0, 0.0), bottom)) // CELL:int(min(max(y1, 0.0), bottom)) // CELL + 1,
                       int(min(max(x0, 0.0), right)) // CELL:int(min(max(x1, 0.0), right)) // CELL + 1]
        last = int(cells.max())
        join = None
        if item.key is not None:
            join = next((b for b in range(max(last, 0), len(out)) if keys[b] == item.key),
                        None)
        if join is None:
            join = len(out)
            out.append([])
            keys.append(item.key)
        out[join].append(item)
        np.maximum(cells, join, out=cells)
    return out


def _colors(fb: "FrameBuffer", group: Sequence[_Item]) -> tuple[Any, NDArray[Any] | None]:
    """(one color spec for the batch, None), or (None, one pixel value per item)."""
    first = group[0].attributes["color"]
    if all(it.attributes["color"] == first and type(it.attributes["color"]) is type(first)
           for it in group):
        return first, None
    values = np.vstack([fb.pixel(it.attributes["color"]) for it in group])
    return None, values if values.shape[1] > 1 else values[:, 0]


def _draw(fb: "FrameBuffer", device: RasterDevice, group: Sequence[_Item]) -> None:
    """Draw one batch."""
    item = group[0]
    if item.kind == "call":
        item.geometry(device)
    elif len(group) == 1 and item.kind == "area":
        device.fill(item.geometry, item.attributes)
    elif len(group) == 1:
        device.stroke(item.geometry, item.closed, item.attributes)
    elif item.kind == "area":
        one, values = _colors(fb, group)
        draw.polygons(fb, [it.geometry[0] for it in group], color=one if values is None else values,
                      rule=item.attributes["rule"])
    elif item.kind == "lines":
        segs = [_segments(it.geometry, it.closed) for it in group]
        one, values = _colors(fb, group)
        if values is not None:
            values = np.repeat(values, [len(s) for s in segs], axis=0)
        draw.lines(fb, np.vstack(segs), color=one if values is None else values)
    else:
        pieces = [p for it in group for p in it.geometry]
        closed = np.array([it.closed for it in group for _ in it.geometry])
        one, values = _colors(fb, group)
        if values is not None:
            values = np.repeat(values, [len(it.geometry) for it in group], axis=0)
        draw.polylines(fb, pieces, color=one if values is None else values, closed=closed,
                       style=item.attributes["style"])


def paint(fb: "FrameBuffer", segments: Iterable["Segment"], display_file: "DisplayFile",
          antialias: bool = False, highlight: "Color" = "magenta") -> None:
    """Draw ``segments`` (a display file's segments in drawing order, or a frame's
    from :class:`~scanline.scene.plan.FramePlan`) on ``fb`` as
    :func:`scanline.display.interpret` draws them on a ``RasterDevice(fb,
    antialias)``.

    Parameters
    ----------
    fb : FrameBuffer
    segments : iterable of Segment
        The segments in drawing order.
    display_file : DisplayFile
        Their display file.
    antialias : bool, default False
    highlight : color, default "magenta"
        The color of highlighted segments.

    Examples
    --------
    The same pixels as the scene's own raster (on the same black background):

    >>> import scanline as sl
    >>> from scanline.display.interpreter import drawing_order
    >>> scene = sl.scene.Scene({"version": 1, "canvas": {"width": 24, "height": 4,
    ...     "background": "black"},
    ...     "segments": [{"name": "a", "primitives": [
    ...         {"type": "polygon", "points": [[0.5, 0.5], [2.5, 0.5], [2.5, 2.5], [0.5, 2.5]]},
    ...         {"type": "polyline", "points": [[4, 0], [6, 0]]},
    ...         {"type": "polygon", "points": [[16.5, 0.5], [18.5, 0.5], [18.5, 2.5],
    ...                                        [16.5, 2.5]]}]}]})
    >>> df = scene.display_file
    >>> fb = sl.FrameBuffer(24, 4)
    >>> paint(fb, drawing_order(df), df)
    >>> print(sl.text_image(fb))
    ------------------------
    -##--------------##-----
    -##--------------##-----
    ----###-----------------
    >>> fb.to_array().tolist() == scene.raster().to_array().tolist()
    True
    """
    device = RasterDevice(fb, antialias)
    for group in batches(items(segments, display_file, fb, device, highlight), fb.width,
                         fb.height):
        _draw(fb, device, group)
