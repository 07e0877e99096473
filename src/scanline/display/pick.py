"""The pick and locator input devices on a display file (Hearn & Baker, chapter 8;
GKS's logical input devices).

A *locator* reports a position: the pointer's device coordinates mapped back through
the inverse of the workstation transformation (device -> NDC) and of the
normalization transformation (NDC -> world).  A *pick* reports which segment is
under the pointer, and the pick identifier of the primitive hit.  As Hearn & Baker
describe it (section 8-1, "Pick devices"), the pointer position is the center of a
small *pick window* (the aperture); a primitive is a candidate when what it draws
meets that window, which is tested with the clipping routines (a stroke is hit when
Liang-Barsky keeps part of it inside the window; an area when the window's center
is inside it by its fill rule, or its boundary crosses the window).  Of the
candidates, the one drawn last (the highest priority, then the last primitive) is
picked, since it is the one the viewer sees.

The primitives are walked by the interpreter's own code
(:func:`scanline.display.interpreter.draw_primitive`), with a device that tests
instead of drawing: a pick sees exactly the geometry the raster and vector devices
draw, after the segment transformation and the viewport clip.
"""

from typing import TYPE_CHECKING, Any, NamedTuple, Optional, Sequence

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .. import transform as tf
from ..errors import ArgumentTypeError, ArgumentValueError
from .interpreter import clip_rectangle, device_frame, draw_primitive, drawing_order
from .pipeline import Rect
from .viewing import workstation

if TYPE_CHECKING:
    from .file import DisplayFile

F64 = NDArray[np.float64]


class Pick(NamedTuple):
    """What a pick reports: the segment's name and the primitive's pick identifier."""

    segment: str
    pick_id: int

#: Largest pick aperture, in device units.
MAX_APERTURE = 1 << 16


def device_size(device: Any) -> tuple[int, int]:
    """(width, height) of a device: a FrameBuffer, a device object or a pair."""
    if hasattr(device, "width") and hasattr(device, "height"):
        size = (device.width, device.height)
    elif isinstance(device, (tuple, list)) and len(device) == 2:
        size = tuple(device)
    else:
        raise ArgumentTypeError(
            f"device must be a FrameBuffer, a display device or a (width, height) pair, "
            f"got {v._show(device)}")
    return (v.positive_int("device width", size[0], 2),
            v.positive_int("device height", size[1], 2))


def _position(x: object, y: object) -> tuple[float, float]:
    px, py = v.number("x", x), v.number("y", y)
    for name, c in (("x", px), ("y", py)):
        if not abs(c) <= v.COORD_LIMIT:
            raise ArgumentValueError(f"{name}={c} must be finite and within +-{v.COORD_LIMIT}")
    return px, py


def locate(display_file: "DisplayFile", x: float, y: float, device: Any) -> tuple[float, float]:
    """The world coordinates of the device position (x, y): the locator's inverse
    mapping W⁻¹ then N⁻¹ (workstation, then normalization transformation).

    Parameters
    ----------
    display_file : DisplayFile
    x, y : float
        A device position (pixel centers at integers, y up), such as a pointer's.
    device : FrameBuffer, device or (width, height)
        The workstation the file is drawn on.

    Returns
    -------
    (float, float)
        The position in world coordinates of the current normalization
        transformation; drawing a point there puts it back at (x, y).

    >>> import scanline as sl
    >>> df = sl.DisplayFile()
    >>> df.set_viewing(window=(0, 0, 100, 50), viewport=(0, 0, 1, 0.5))
    >>> df.locate(100, 25, (201, 101))
    (50.0, 25.0)
    """
    x, y = _position(x, y)
    width, height = device_size(device)
    m = tf.compose(tf.inverse(display_file.normalization), tf.inverse(workstation(width, height)))
    wx, wy = tf.apply(m, [(x, y)])[0]
    return float(wx), float(wy)


#: Up to this many segments a pick runs the Liang-Barsky kernel as Python (its
#: twin, :func:`scanline._kernels._jit.python`): a pick on a small picture then
#: never waits for a compilation; more go to the compiled batch (``sl.clip.lines``).
PY_SEGMENTS = 512


def _visible(segments: F64, window: Rect) -> bool:
    """Whether Liang-Barsky keeps some part of any of the (N, 4) ``segments`` in the
    rectangle ``window``."""
    from .. import clip
    from .._kernels import clip as k
    from .._kernels._jit import python
    from .._kernels.variants import token
    from ..clip import window as w

    if len(segments) > PY_SEGMENTS:
        return bool(clip.lines(segments, window, method="liang-barsky")[1].any())
    rect = np.array(w.rectangle(window))
    ring = w.rectangle_polygon(*rect)
    seg = np.ascontiguousarray(segments, np.float64).reshape(-1)
    out, accepted = np.empty(seg.shape), np.empty(len(segments), np.bool_)
    python(k.clip_lines)(token(k.LIANG_BARSKY), seg, rect, ring, w.outward_normals(ring),
                         float(v.COORD_LIMIT), out, accepted)
    return bool(accepted.any())


class _Probe:
    """A device that draws nothing and records whether anything it is given meets
    the pick window (xmin, ymin, xmax, ymax)."""

    def __init__(self, width: int, height: int, x: float, y: float, aperture: float) -> None:
        self.width, self.height = width, height
        self.x, self.y, self.aperture = x, y, aperture
        self.hit = False

    def _window(self, grow: float) -> Rect:
        a = self.aperture + grow
        return (self.x - a, self.y - a, self.x + a, self.y + a)

    def _meets(self, pieces: Sequence[F64], closed: bool, grow: float) -> bool:
        segments: list[F64] = []
        for p in pieces:
            q = np.vstack([p, p[:1]]) if closed and len(p) > 2 else p
            q = np.vstack([q, q]) if len(q) == 1 else q
            segments.append(np.hstack([q[:-1], q[1:]]))
        if not segments:
            return False
        return _visible(np.vstack(segments), self._window(grow))

    def stroke(self, pieces: Sequence[F64], closed: bool, attributes: dict[str, Any]) -> None:
        # a wide line is hit within half its width of its path
        self.hit |= self._meets(pieces, closed, attributes["style"].width / 2)

    def fill(self, contours: Sequence[F64], attributes: dict[str, Any]) -> None:
        from ..geometry import inside

        style = attributes["style"]
        if style is not None and style.kind == "hollow":
            return
        self.hit |= self._meets(contours, True, 0.0) or bool(
            inside([(self.x, self.y)], list(contours), rule=attributes["rule"])[0])


def pick(display_file: "DisplayFile", x: float, y: float, aperture: float, device: Any
         ) -> Optional[Pick]:
    """The segment under the device position (x, y), as a pick device reports it.

    Parameters
    ----------
    display_file : DisplayFile
    x, y : float
        The pointer's device position (pixel centers at integers, y up).
    aperture : float
        Half the side of the square pick window around (x, y), in device units,
        > 0 (0.5: the pixel under the pointer).
    device : FrameBuffer, device or (width, height)
        The workstation the file is drawn on (its workstation transformation maps
        NDC to these device coordinates).

    Returns
    -------
    Pick or None
        ``Pick(segment, pick_id)``: the name of the segment hit and the pick
        identifier of its primitive, for the topmost primitive (last drawn) whose
        drawing meets the pick window; None when nothing visible and detectable is
        there.

    Notes
    -----
    Hearn & Baker, section 8-1 ("Pick devices": the pick window around the cursor,
    tested with clipping) and 8-2 (the pick input functions); GKS (ISO 7942)
    section 5.7, segment detectability and pick identifiers.

    Examples
    --------
    >>> import scanline as sl
    >>> df = sl.DisplayFile()
    >>> df.set_viewing(window=(0, 0, 100, 100))
    >>> df.create_segment("roof")
    >>> df.set_pick_identifier(7)
    >>> df.polyline([(10, 50), (50, 90), (90, 50)])
    >>> df.close_segment()
    >>> df.pick(50, 89, 2, (101, 101))
    Pick(segment='roof', pick_id=7)
    >>> df.pick(50, 80, 2, (101, 101)) is None
    True
    """
    x, y = _position(x, y)
    aperture = v.number("aperture", aperture)
    if not 0 < aperture <= MAX_APERTURE:
        raise ArgumentValueError(
            f"aperture={aperture} must be > 0 and at most {MAX_APERTURE} device units "
            "(0.5: the pixel under the pointer)")
    width, height = device_size(device)
    ws = workstation(width, height)
    frame = device_frame(ws)
    probe = _Probe(width, height, x, y, aperture)
    for seg in reversed(drawing_order(display_file)):
        if not seg.detectable:
            continue
        m = ws @ seg.transformation
        for i in range(len(seg.primitives) - 1, -1, -1):
            prim = seg.primitives[i]
            rect = clip_rectangle(prim, ws, frame)
            if rect is None:
                continue
            draw_primitive(prim.transformed(m), rect, probe)
            if probe.hit:
                return Pick(seg.name, prim.pick_id)
    return None
