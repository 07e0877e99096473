"""The output primitives a display file stores, with their attributes.

A primitive holds its geometry in normalized device coordinates (NDC: the unit square
(0, 0)-(1, 1), x right, y up), the attributes that were current when it was created,
and the clipping rectangle of the normalization transformation it came through.
Geometry that an affine matrix maps exactly is stored so that it stays exact under a
segment transformation:

* polylines, fill areas and markers as points;
* circles and ellipses as a center ``c`` and a 2x2 matrix ``A`` whose columns are the
  two semi-axis vectors: the curve is ``c + A (cos t, sin t)``, and a matrix ``M``
  (linear part ``L``) maps it to ``M c + L A (cos t, sin t)``;
* text as an anchor point and a 2x2 *frame* whose columns are the baseline direction
  and the up vector, each as long as the character height.

Attributes are validated when the primitive is made, so that a bad value is reported
where it was given (the scene loader adds the key path), not when the file is drawn.
"""

import functools
import math
import numbers
from typing import Any, Optional

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..attributes import FillStyle
from ..linestyle import LineStyle
from ..color.spec import rgba
from ..errors import ArgumentTypeError, ArgumentValueError

#: The primitive kinds, as scene files name them.
KINDS = ("polyline", "polygon", "ellipse", "text", "markers")

RULES = ("even-odd", "nonzero")
#: GKS polymarker types 1-5.
MARKERS = ("dot", "plus", "asterisk", "circle", "cross")
#: Fonts a display file can hold (each glyph is strokes or contours, which a vector
#: device can draw too).
FONTS = ("stroke", "sans", "bitmap")
HORIZONTAL = ("left", "center", "right")
VERTICAL = ("top", "cap", "half", "base", "bottom")
TEXT_PATHS = ("right", "left", "up", "down")
#: Largest marker, in device units.
MAX_MARKER = 4096.0

#: How text is clipped: the whole string, whole characters, or strokes and pixels.
TEXT_CLIPS = ("string", "character", "stroke")


def color(name: str, value: Any) -> Any:
    """Check a color spec (anything ``FrameBuffer.pixel`` takes); return it, a list or
    array as a tuple (so that colors compare and hash).  None stays None: the
    device's foreground (``FrameBuffer.foreground`` on a raster device)."""
    if value is None:
        return None
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, list):
        value = tuple(value)
    rgba(value, name)
    return value


def _nonnegative(name: str, value: object) -> float:
    x = v.number(name, value)
    if x < 0:
        raise ArgumentValueError(f"{name} must be >= 0, got {x}")
    return x


def _positive(name: str, value: object) -> float:
    x = v.number(name, value)
    if x <= 0:
        raise ArgumentValueError(f"{name} must be > 0, got {x}")
    return x


def line_attributes(color_: Any = None, color_name: str = "color", **style: Any) -> dict[str, Any]:
    """Line attributes as a dict: ``color`` and ``style``, a :class:`scanline.LineStyle`
    made from ``style`` (width, cap, join, miter_limit, dash, dash_phase);
    ``color_name`` is the color's name in messages."""
    if "pen" in style:
        raise ArgumentValueError("pen is not a display-file attribute: a vector device "
                                 "cannot stamp a footprint; use width and cap")
    known = ("width", "cap", "join", "miter_limit", "dash", "dash_phase")
    unknown = [k for k in style if k not in known]
    if unknown:
        raise ArgumentTypeError(
            f"unknown line attribute {unknown[0]!r}; the line attributes are {color_name}, "
            f"{', '.join(known)}")
    return {"color": color(color_name, color_), "style": LineStyle(**style)}


#: The line attributes of a plain one-pixel line.
THIN = LineStyle()


def marker_attributes(kind: str = "plus", size: float = 7.0,
                      color_: Any = None) -> dict[str, Any]:
    """The validated polymarker attributes as a dict."""
    size = _positive("size", size)
    if size > MAX_MARKER:
        raise ArgumentValueError(f"size={size} is too large; the limit is {MAX_MARKER}")
    return {"color": color("color", color_), "kind": v.choice("kind", kind, MARKERS),
            "size": size}


def text_attributes(color_: Any = None, font: Any = "stroke",
                    align: Any = ("left", "base"), expansion: float = 1.0,
                    spacing: float = 0.0, path: str = "right",
                    clip: str = "character") -> dict[str, Any]:
    """The validated text attributes (besides height and angle) as a dict."""
    if not (isinstance(align, (tuple, list)) and len(align) == 2):
        raise ArgumentValueError(
            f"align must be a pair (horizontal, vertical) such as ('left', 'base'), "
            f"got {v._show(align)}"
        )
    return {
        "color": color("color", color_),
        "font": v.choice("font", font, FONTS),
        "align": (v.choice("align[0]", align[0], HORIZONTAL),
                  v.choice("align[1]", align[1], VERTICAL)),
        "expansion": _positive("expansion", expansion),
        "spacing": v.number("spacing", spacing),
        "path": v.choice("path", path, TEXT_PATHS),
        "clip": v.choice("clip", clip, TEXT_CLIPS),
    }


def fill_style(name: str, value: Any) -> Optional[FillStyle]:
    """None, a :class:`FillStyle` or its one-word spelling (``"hatch:45:8"``)."""
    if value is None or isinstance(value, FillStyle):
        return value
    if isinstance(value, str):
        style = FillStyle.parse(value)
        return None if style.kind == "solid" else style
    raise ArgumentTypeError(
        f"{name} must be a FillStyle or a word such as 'hollow' or 'hatch:45:8', "
        f"got {v._show(value)}"
    )


def points(name: str, value: Any, minimum: int = 1) -> NDArray[np.float64]:
    """An (N, 2) float64 array of finite points, N >= minimum (booleans are not
    numbers here, though numpy would convert them)."""
    if isinstance(value, np.ndarray) and value.dtype == bool:
        raise ArgumentTypeError(f"{name} must hold numbers, got an array of booleans")
    if isinstance(value, (list, tuple)):
        for i, p in enumerate(value):
            if isinstance(p, (bool, np.bool_)) or (
                    isinstance(p, (list, tuple)) and any(isinstance(c, (bool, np.bool_)) for c in p)):
                raise ArgumentTypeError(f"{name}[{i}] must be a point [x, y] of numbers, got "
                                        f"{v._show(p)} (true and false are not numbers)")
    try:
        a = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError, OverflowError):
        _bad_point(name, value)
        raise ArgumentTypeError(
            f"{name} must be a list of points [x, y], got {v._show(value)}"
        ) from None
    if a.ndim == 1 and a.size == 0:
        a = a.reshape(0, 2)
    if a.ndim != 2 or a.shape[1] != 2:
        raise ArgumentValueError(
            f"{name} must be a list of points [x, y] (shape (N, 2)), got {v._show(value)}"
        )
    if len(a) < minimum:
        raise ArgumentValueError(f"{name} needs at least {minimum} points, got {len(a)}")
    if not np.isfinite(a).all():
        row = int(np.argwhere(~np.isfinite(a))[0][0])
        raise ArgumentValueError(f"{name} must be finite; point {row} is {a[row].tolist()}")
    return a


def _bad_point(name: str, value: object) -> None:
    """Raise an error naming the first element of a list that is not a point [x, y] of
    two numbers; return when there is none."""
    if isinstance(value, (list, tuple)):
        for i, pt in enumerate(value):
            ok = isinstance(pt, (list, tuple)) and len(pt) == 2 and all(
                isinstance(c, numbers.Real) and not isinstance(c, bool) for c in pt)
            if not ok:
                raise ArgumentValueError(
                    f"{name}[{i}] must be a point [x, y] of two numbers, got {v._show(pt)}")


def _is_point(value: object) -> bool:
    return (isinstance(value, (list, tuple, np.ndarray)) and len(value) > 0
            and isinstance(value[0], numbers.Real))


def contours(name: str, value: Any) -> list[NDArray[np.float64]]:
    """A fill area: one list of points or a list of such lists -> list of (K, 2) arrays."""
    try:
        flat = np.asarray(value, dtype=np.float64).ndim == 2
    except (TypeError, ValueError, OverflowError):
        # ragged: several contours of different lengths, or a bad point in one contour
        flat = isinstance(value, (list, tuple)) and len(value) > 0 and _is_point(value[0])
    if flat:
        return [points(name, value, 3)]
    if not isinstance(value, (list, tuple)) or not value:
        raise ArgumentValueError(
            f"{name} must be a list of points [x, y] or a list of such contours, "
            f"got {v._show(value)}"
        )
    return [points(f"{name}[{i}]", c, 3) for i, c in enumerate(value)]


class Primitive:
    """One output primitive of a segment (see the module docstring).

    Attributes
    ----------
    kind : str
        One of :data:`KINDS`.
    geometry : dict
        The NDC geometry: ``points`` (polyline, markers), ``contours`` (polygon),
        ``center`` and ``axes`` (ellipse), ``anchor``, ``frame`` and ``string`` (text).
    attributes : dict
        The validated attributes.
    clip : tuple of 4 floats or None
        The NDC clipping rectangle (xmin, ymin, xmax, ymax), or None for no clipping.
    pick_id : int
        The pick identifier current when the primitive was made (GKS's SET PICK
        IDENTIFIER): what a pick reports besides the segment's name.
    """

    __slots__ = ("kind", "geometry", "attributes", "clip", "pick_id")

    def __init__(self, kind: str, geometry: dict[str, Any], attributes: dict[str, Any],
                 clip: Optional[tuple[float, float, float, float]], pick_id: int = 0) -> None:
        self.kind = kind
        self.geometry = geometry
        self.attributes = attributes
        self.clip = clip
        self.pick_id = pick_id

    def transformed(self, m: NDArray[np.float64]) -> "Primitive":
        """This primitive with its geometry mapped by the affine 3x3 matrix ``m``
        (the clipping rectangle is not moved: GKS clips after the segment
        transformation)."""
        with np.errstate(all="ignore"):  # overflow -> inf, refused when drawn
            return Primitive(self.kind, self._moved(m[:2, :2], m[:2, 2]), self.attributes,
                             self.clip, self.pick_id)

    def _moved(self, lin: NDArray[np.float64], t: NDArray[np.float64]) -> dict[str, Any]:
        g = self.geometry
        move = functools.partial(_move, lin.T, t)
        if self.kind in ("polyline3d", "mesh"):   # projected when interpreted
            return g
        if self.kind in ("polyline", "markers"):
            geometry = {**g, "points": move(g["points"])}
        elif self.kind == "polygon":
            geometry = {**g, "contours": [move(c) for c in g["contours"]]}
        elif self.kind == "ellipse":
            geometry = {**g, "center": move(g["center"]), "axes": lin @ g["axes"]}
        else:
            geometry = {**g, "anchor": move(g["anchor"]), "frame": lin @ g["frame"]}
        return geometry

    def __repr__(self) -> str:
        return f"<{self.kind} primitive>"


def _move(lin_t: NDArray[np.float64], t: NDArray[np.float64],
          points: NDArray[np.float64]) -> NDArray[np.float64]:
    """``points`` (rows) mapped by the linear part whose transpose is ``lin_t``, then
    moved by ``t``.  (A module-level function: the annotations of a function defined
    in a method are evaluated at every call, and a subscripted NDArray costs
    microseconds there.)"""
    moved: NDArray[np.float64] = points @ lin_t + t
    return moved


def text_frame(height: float, angle: float) -> NDArray[np.float64]:
    """The 2x2 text frame: columns baseline (cos, sin) and up (-sin, cos), times height."""
    c, s = math.cos(angle), math.sin(angle)
    return height * np.array([[c, -s], [s, c]])
