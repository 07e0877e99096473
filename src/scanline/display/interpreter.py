"""The display-file interpreter: walks a display file and drives a device.

For each visible segment, in increasing priority (ties in order of creation), and
each of its primitives in order, the interpreter

1. maps the NDC geometry by the segment transformation and then by the workstation
   transformation (NDC unit square -> the device's frame): M = W · S;
2. clips it to the primitive's clipping rectangle (its viewport, mapped by W) and to
   the device's frame (the workstation window is always clipped, as in GKS);
3. sends the result to the device as strokes and fills.

Runs of similar primitives (thin solid polylines of one color, solid polygons of one
color) are mapped, clipped and drawn in batches (:mod:`scanline.display.batch`).

A highlighted segment gets a frame in the highlight color around what it drew.
"""

from typing import TYPE_CHECKING, Any, Optional, Sequence

import numpy as np
from numpy.typing import NDArray

from ..errors import ArgumentTypeError, ArgumentValueError, ScanlineError
from ..geometry import guard
from . import batch, pipeline, text, three_d
from .batch import Key
from .pipeline import Rect, Window
from .primitives import THIN, Primitive
from .viewing import device_rectangle, workstation

if TYPE_CHECKING:
    from .._typing import Color
    from .file import DisplayFile, Segment

F64 = NDArray[np.float64]

_UNIT = (0.0, 0.0, 1.0, 1.0)

#: How far (device units) outside its clipping rectangle a point may lie and still
#: count as inside: a few hundred times the rounding error of the mappings.
CLIP_TOLERANCE = 1e-9

#: Gap (device units) between a highlighted segment and its frame.
HIGHLIGHT_MARGIN = 2.0


def _finite(points: F64) -> F64:
    """``points`` (device coordinates) when finite; a mapping that overflowed is
    refused by name."""
    if points.size and not np.isfinite(points).all():
        raise ArgumentValueError(
            "maps to device coordinates that overflow (for example "
            f"{points[~np.isfinite(points).all(axis=1)][0].tolist()}); use a smaller "
            "segment transformation or window")
    return points


def _guarded_contour(c: F64) -> F64:
    """A fill contour reaching beyond the kernels' exact range (+-2**30) clipped to
    the guard square first (:func:`scanline.geometry.guard.ring`: exact crossings,
    windings kept inside it), so that any finite device coordinate is drawn."""
    return guard.ring(c) if guard.far(_finite(c)) else c


def _clip_polyline(points: F64, closed: bool, rect: Window) -> tuple[list[F64], bool]:
    """:func:`pipeline.polylines` of a polyline, whose far parts are cut at the guard
    square first (:func:`scanline.geometry.guard.paths`)."""
    if not guard.far(_finite(points)):
        return pipeline.polylines(points, closed, rect)
    verts, offsets, _, _ = guard.paths(points, np.array([0, len(points)]),
                                       np.array([closed]))
    pieces = [q for a, b in zip(offsets[:-1], offsets[1:])
              for q in pipeline.polylines(verts[a:b], False, rect)[0]]
    return pieces, False


def _line(color: Optional["Color"]) -> dict[str, Any]:
    return {"color": color, "style": THIN}


def _area(prim: Primitive, rect: Window, device: Any) -> list[F64]:
    """Fill (and edge) an area given as contours; return the pieces drawn."""
    a = prim.attributes
    cs = prim.geometry["contours"]
    clipped = pipeline.contours([_guarded_contour(c) for c in cs], rect)
    if not clipped:
        return []
    device.fill(clipped, a)
    if a.get("edge") is not None:  # the area's own boundary, clipped as lines: no
        for c in cs:                 # edges along the clip window
            pieces, closed = _clip_polyline(c, True, rect)
            if pieces:
                device.stroke(pieces, closed, a["edge"])
    return clipped


def draw_primitive(prim: Primitive, rect: Window, device: Any) -> list[F64]:
    """Draw one primitive (already in device coordinates) clipped to ``rect`` (a
    rectangle or a convex polygon, see :func:`pipeline.inside`); return the point
    arrays drawn, for the highlight frame.

    Parameters
    ----------
    prim : Primitive
        The primitive, its geometry in device coordinates.
    rect : tuple or numpy.ndarray
        The clip region: (xmin, ymin, xmax, ymax), or a convex (M, 2) polygon.
    device : RasterDevice, VectorDevice or SVGDevice
        Or any object with ``stroke`` and ``fill``.

    Returns
    -------
    list of numpy.ndarray
        The (K, 2) point arrays sent to the device.

    Raises
    ------
    ArgumentValueError
        When the geometry's device coordinates overflow.

    Examples
    --------
    >>> import numpy as np
    >>> import scanline as sl
    >>> from scanline.display.primitives import Primitive, line_attributes
    >>> from scanline.display.interpreter import draw_primitive
    >>> beam = sl.display.VectorDevice(10, 10)
    >>> prim = Primitive("polyline", {"points": np.array([[0.0, 5.0], [20.0, 5.0]])},
    ...                  {**line_attributes(), "closed": False}, None)
    >>> [piece.tolist() for piece in draw_primitive(prim, (0, 0, 9, 9), beam)]   # clipped at x = 9
    [[[0.0, 5.0], [9.0, 5.0]]]
    """
    kind, g, a = prim.kind, prim.geometry, prim.attributes
    if kind == "ellipse":
        ring = pipeline.ellipse_points(g["center"], g["axes"])
        if a["fill"]:
            return _area(Primitive("polygon", {"contours": [ring]}, a, None), rect, device)
        g, kind = {"points": ring}, "polyline"
    if kind == "polyline":
        pieces, closed = _clip_polyline(g["points"], a["closed"], rect)
        if pieces:
            device.stroke(pieces, closed, a)
        return pieces
    if kind == "polygon":
        return _area(prim, rect, device)
    if kind == "markers":
        pts = _finite(g["points"])
        segments = pipeline.marker_segments(pts[pipeline.inside(pts, rect)], a["kind"],
                                            a["size"])
        pieces = [s.reshape(2, 2) for s in segments]
        pieces = [q for s in pieces for q in pipeline.polylines(s, False, rect)[0]]
        if pieces:
            device.stroke(pieces, False, _line(a["color"]))
        return pieces
    _finite(g["anchor"][None])
    return text.draw(prim, rect, device)


def interpret(display_file: "DisplayFile", device: Any, highlight: "Color" = "magenta") -> None:
    """Draw ``display_file`` on ``device``.

    Parameters
    ----------
    display_file : DisplayFile
        The picture.
    device : RasterDevice, VectorDevice or SVGDevice
        Or any object with ``width``, ``height``, ``stroke`` and ``fill`` (see
        :mod:`scanline.display.devices`), and optionally ``begin_segment(name)`` and
        ``end_segment()``, called around each segment.
    highlight : color
        The color of the frame drawn around highlighted segments.

    Notes
    -----
    The notes' display-file interpreter (syllabus of chapter 2) and the refresh cycle
    of a random-scan display (chapter 1, Q.3): the picture is regenerated from the
    stored commands, so changing a segment's attributes and interpreting again
    redraws it.  The order of segments by priority follows GKS (ISO 7942, 4.7.6).

    Raises
    ------
    ArgumentTypeError
        When ``display_file`` is not a DisplayFile or ``device`` not a device.
    ArgumentValueError
        For a bad highlight color, or geometry that overflows the device coordinates.

    Examples
    --------
    >>> import scanline as sl
    >>> df = sl.DisplayFile()
    >>> df.set_viewing(window=(0, 0, 4, 2))
    >>> df.create_segment("base")
    >>> df.polyline([(0, 0), (4, 0)])
    >>> df.close_segment()
    >>> fb = sl.FrameBuffer(5, 3, mode="1")
    >>> sl.display.interpret(df, sl.display.RasterDevice(fb))
    >>> print(sl.text_image(fb))
    -----
    -----
    #####
    """
    from .file import DisplayFile
    from .primitives import color

    if not isinstance(display_file, DisplayFile):
        raise ArgumentTypeError(f"display_file must be a scanline.DisplayFile, got "
                                f"{type(display_file).__name__}")
    missing = [a for a in ("width", "height", "stroke", "fill") if not hasattr(device, a)]
    if missing:
        raise ArgumentTypeError(
            f"device must be a RasterDevice, VectorDevice or SVGDevice (or have width, height, "
            f"stroke and fill); got {type(device).__name__}, which lacks {', '.join(missing)}")
    color("highlight", highlight)
    ws = workstation(device.width, device.height)
    frame = device_frame(ws)
    for seg in drawing_order(display_file):
        draw_segment(seg, display_file, ws, frame, device, highlight)


def draw_segment(seg: "Segment", display_file: "DisplayFile", ws: F64, frame: Rect, device: Any,
                 highlight: "Color") -> None:
    """Draw one segment (with its highlight frame) as :func:`interpret` does: ``ws``
    is the workstation matrix, ``frame`` the device frame (:func:`device_frame`)."""
    groups = hasattr(device, "begin_segment")
    m = ws @ seg.transformation
    drawn: list[F64] = []
    if groups:
        device.begin_segment(seg.name)
    prims = seg.primitives
    if any(q.kind in three_d.KINDS for q in prims):
        prims = three_d.expand(prims, display_file, device.width, device.height)
    for start, run, same in batch.runs(prims):
        rect = clip_rectangle(run[0], ws, frame)
        if rect is not None:
            drawn += draw_run(seg, start, run, same, m, rect, device)
    if seg.highlighted and drawn:
        _frame(np.vstack(drawn), frame, device, highlight)
    if groups:
        device.end_segment()


def draw_run(seg: "Segment", start: int, run: Sequence[Primitive], same: Key, m: F64,
             rect: Window, device: Any) -> list[F64]:
    """Draw one run of :func:`batch.runs` (``run`` starts at primitive ``start`` of
    ``seg``), mapped by ``m`` and clipped to ``rect``; return the point arrays drawn."""
    drawn: list[F64] = []
    if len(run) > 1:
        assert same is not None  # a run of several shares a key
        pts, far = (batch.lines if same[0] == "lines" else batch.areas)(run, m, rect, device)
        if far is None:
            return pts
        # a primitive reaches beyond the exact range: the run drawn one by one, in
        # order, each far one through the guard (nothing of the run was drawn yet)
    for i, prim in enumerate(run):
        where = f"segment {seg.name!r}, primitive {start + i} ({prim.kind})"
        try:
            drawn += draw_primitive(prim.transformed(m), rect, device)
        except ScanlineError as error:
            if str(error).startswith(where):
                raise
            raise type(error)(f"{where}: {error}") from None
    return drawn


def drawing_order(display_file: "DisplayFile") -> list["Segment"]:
    """The visible segments in the order they are drawn: increasing priority, ties
    in order of creation (GKS, ISO 7942, 4.7.6)."""
    return sorted((s for s in display_file.segments if s.visible),
                  key=lambda s: (s.priority, s._order))


def device_frame(ws: F64) -> Rect:
    """The device's frame under the workstation matrix ``ws``, as a clip rectangle."""
    return _padded(device_rectangle(ws, _UNIT))


def clip_rectangle(prim: Primitive, ws: F64, frame: Rect) -> Optional[Rect]:
    """The device rectangle a primitive is clipped to: its viewport mapped by ``ws``
    and intersected with ``frame``, or None when that is empty."""
    if prim.clip is None:
        return frame
    return pipeline.intersect(_padded(device_rectangle(ws, prim.clip)), frame)


def _padded(rect: Sequence[float]) -> Rect:
    """``rect`` grown by :data:`CLIP_TOLERANCE`: a point on a viewport's edge stays
    inside although mapping it and the edge may round differently."""
    return (rect[0] - CLIP_TOLERANCE, rect[1] - CLIP_TOLERANCE,
            rect[2] + CLIP_TOLERANCE, rect[3] + CLIP_TOLERANCE)


def _frame(points: F64, frame: Rect, device: Any, color: "Color") -> None:
    """The highlight frame around ``points``, clipped to the device frame."""
    x0, y0 = points.min(axis=0) - HIGHLIGHT_MARGIN
    x1, y1 = points.max(axis=0) + HIGHLIGHT_MARGIN
    box = np.array([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
    pieces, closed = pipeline.polylines(box, True, frame)
    if pieces:
        device.stroke(pieces, closed, _line(color))
