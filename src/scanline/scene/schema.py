"""The scene schema, versions 1 and 2: checking a scene's data and building its display
file.  Version 2 adds cameras and 3-D primitives (:mod:`scanline.scene.schema3d`) and
top-level keys read by other modules (:data:`V2_KEYS`).

See docs/scene-format.md for the format.  Every error is a :class:`SceneError` whose
message starts with the key path of the offending value
(``segments[2].primitives[0].points must be ...``).
"""

import math
import numbers
import re
from typing import TYPE_CHECKING, Any, Callable, Collection, Iterable, NoReturn, TypeVar

import numpy as np
from numpy.typing import NDArray

from .. import transform as tf
from ..display import DisplayFile
from ..display.viewing import aspect
from ..errors import ScanlineError
from ..framebuffer import check_image_size
from .files import SceneError

if TYPE_CHECKING:
    from .shaded import Shading

_T = TypeVar("_T")

#: The schema versions this module reads.
VERSIONS = (1, 2)

#: Top-level keys of version 2 that other modules read; :func:`build` lets them
#: through (``animation``: key frames, motion paths and morphs,
#: :mod:`scanline.scene.animated`; ``lights``, ``materials``, ``method``, ``shading``:
#: :mod:`scanline.scene.shaded`).
V2_KEYS = {"animation", "lights", "materials", "method", "shading", "radiosity"}

#: Largest canvas side, in pixels.
MAX_SIZE = 16384

#: Bytes per pixel of the frame buffer, by mode (mode "1" is kept as one byte a pixel
#: while it is drawn).
_PIXEL_BYTES = {"1": 1, "L": 1, "P": 1, "RGB": 3, "RGBA": 4}
#: Bytes per pixel that 3-D surfaces need besides the frame buffer: the z-buffer's
#: face ids (4) and depths (8).
SURFACE_BYTES_PER_PIXEL = 12

_CANVAS = {"width", "height", "background", "mode", "highlight", "antialias"}
_VIEWPORT = {"name", "window", "viewport", "view_up", "keep_aspect", "clip", "border", "camera"}
_SEGMENT = {"name", "viewport", "priority", "visible", "highlighted", "transform",
            "primitives", "camera"}
_LINE = {"color", "width", "cap", "join", "miter_limit", "dash", "dash_phase"}
_AREA = {"color", "rule", "style"}
#: Keys of each primitive type besides ``type``.
PRIMITIVES = {
    "polyline": {"points", "closed"} | _LINE,
    "polygon": {"points", "edge"} | _AREA | (_LINE - {"color"}),
    "circle": {"center", "radius", "fill"} | _AREA | _LINE,
    "ellipse": {"center", "rx", "ry", "angle", "fill"} | _AREA | _LINE,
    "text": {"position", "string", "height", "angle", "color", "font", "align",
             "expansion", "spacing", "path", "clip"},
    "markers": {"points", "kind", "size", "color"},
}
#: The keys each primitive type needs.
REQUIRED = {"polyline": ("points",), "polygon": ("points",), "circle": ("center", "radius"),
            "ellipse": ("center", "rx", "ry"), "text": ("position", "string"),
            "markers": ("points",)}
_STEPS = ("translate", "rotate", "scale", "reflect", "shear", "matrix")


def _fail(path: str, message: str) -> NoReturn:
    raise SceneError(f"{path} {message}", path=path)


def _table(value: object, path: str, known: Collection[str],
           required: Iterable[str] = ()) -> dict[str, Any]:
    if not isinstance(value, dict):
        _fail(path, f"must be a table (an object), got {_kind(value)}")
    for k in value:
        if k not in known:
            _fail(f"{path}.{k}" if path else k,
                  f"is not a known key here; known keys: {', '.join(sorted(known))}")
    for k in required:
        if k not in value:
            _fail(path or "the scene", f"needs the key {k!r}")
    return value


def _kind(value: object) -> str:
    return {dict: "a table", list: "an array", str: "a string", bool: "a boolean",
            int: "an integer", float: "a number"}.get(type(value), f"a {type(value).__name__}")


def _list(value: object, path: str) -> list[Any]:
    if not isinstance(value, list):
        _fail(path, f"must be an array, got {_kind(value)}")
    return value


def _join(path: str, key: str) -> str:
    return f"{path}.{key}" if path else key


def _call(where: str, function: Callable[..., _T], /, *args: Any, **kwargs: Any) -> _T:
    """Call a display-file function; its errors name the argument, which is the scene
    key, so the message gets the key path ``where`` in front.  (Positional-only: a
    text primitive passes its own ``path`` keyword, the text path, through.)"""
    try:
        return function(*args, **kwargs)
    except ScanlineError as error:
        message = f"{where}.{error}" if where else str(error)
        named = re.match(r"\w+(\[\d+\])*(\.\w+(\[\d+\])*)*", message)
        raise SceneError(message, path=named.group() if named else where) from None


def angle(value: object, path: str) -> float:
    """An angle given as ``{degrees = x}`` or ``{radians = x}`` -> radians.

    Parameters
    ----------
    value : object
        The scene's value: a table of one key, ``degrees`` or ``radians``.
    path : str
        Its key path, named in error messages.

    Returns
    -------
    float
        The angle in radians.

    Raises
    ------
    SceneError
        If the value does not say its unit, or is not a finite number.

    Examples
    --------
    >>> from scanline.scene.schema import angle
    >>> angle({"degrees": 180}, "angle")
    3.141592653589793
    >>> angle(30, "segments[0].primitives[0].angle")
    Traceback (most recent call last):
    ...
    scanline.scene.files.SceneError: segments[0].primitives[0].angle must say its unit: {degrees = 30} or {radians = 0.5}, got 30
    """
    if isinstance(value, dict) and len(value) == 1 and set(value) <= {"degrees", "radians"}:
        (unit, x), = value.items()
        if isinstance(x, numbers.Real) and not isinstance(x, bool) and math.isfinite(x):
            return math.radians(x) if unit == "degrees" else float(x)
        _fail(_join(path, unit), f"must be a finite number, got {x!r}")
    _fail(path, f"must say its unit: {{degrees = 30}} or {{radians = 0.5}}, got {value!r}")


def _real(value: object, path: str) -> float:
    if isinstance(value, numbers.Real) and not isinstance(value, bool) and math.isfinite(value):
        return float(value)
    _fail(path, f"must be a finite number, got {value!r}")


def _step(step: object, path: str) -> NDArray[np.float64]:
    """One transformation step -> its 3x3 matrix (in world coordinates)."""
    if not isinstance(step, dict) or len(step) != 1:
        _fail(path, "must be a table with one key: " + ", ".join(_STEPS)
              + " (e.g. {translate = [10, 5]})")
    (name, arg), = step.items()
    here = _join(path, name)
    if name == "translate":
        pair = _list(arg, here)
        if len(pair) != 2:
            _fail(here, f"must be [tx, ty], got {arg!r}")
        return tf.translation(_real(pair[0], f"{here}[0]"), _real(pair[1], f"{here}[1]"))
    if name == "rotate":
        if isinstance(arg, (int, float)) and not isinstance(arg, bool):
            _fail(here, f"must say its unit: {{degrees = {arg}}} or {{radians = {arg}}}")
        a = _table(arg, here, {"degrees", "radians", "pivot"})
        unit = {k: a[k] for k in a if k != "pivot"}
        return _call(here, tf.rotation, angle(unit, here), pivot=a.get("pivot"))
    if name == "scale":
        if isinstance(arg, dict):
            a = _table(arg, here, {"factors", "fixed"}, ("factors",))
            factors, fixed = a["factors"], a.get("fixed")
        else:
            factors, fixed = arg, None
        f = [factors] if isinstance(factors, numbers.Real) else _list(factors, here)
        if len(f) not in (1, 2):
            _fail(here, f"must be a factor or [sx, sy], got {factors!r}")
        return _call(here, tf.scaling, *f, fixed=fixed)
    if name == "reflect":
        if isinstance(arg, dict):
            a = _table(arg, here, {"point", "direction"}, ("point", "direction"))
            return _call(here, tf.reflection_about_line, a["point"], a["direction"])
        return _call(here, tf.reflection, arg)
    if name == "shear":
        a = _table(arg, here, {"x", "y", "reference"})
        return _call(here, tf.shear, a.get("x", 0.0), a.get("y", 0.0), a.get("reference"))
    if name == "matrix":
        m = _call(here, tf.compose, arg)
        _call(here, tf.apply, m, (0.0, 0.0))
        return m
    _fail(path, f"has an unknown transformation {name!r}; use one of {', '.join(_STEPS)}")


def transformation(steps: object, path: str) -> NDArray[np.float64]:
    """A list of steps, applied in the order listed (the first acts first).

    Parameters
    ----------
    steps : object
        The segment's ``transform``: a list of one-key tables (``translate``,
        ``rotate``, ``scale``, ``reflect``, ``shear``, ``matrix``).
    path : str
        Its key path, named in error messages.

    Returns
    -------
    numpy.ndarray
        The 3x3 matrix ``M = S_n ... S_2 S_1`` (column vectors, ``p' = M p``).

    Raises
    ------
    SceneError
        If a step is unknown or its arguments are invalid (naming the step's path).

    Examples
    --------
    Scaling by 2 first, then moving 1 to the right, takes (1, 1) to (3, 2):

    >>> from scanline.scene.schema import transformation
    >>> transformation([{"scale": 2}, {"translate": [1, 0]}], "transform") @ [1, 1, 1]
    array([3., 2., 1.])
    """
    m = np.eye(3)
    for i, step in enumerate(_list(steps, path)):
        # (each step is a finite matrix made by sl.transform: the product needs no
        # second check, which tf.compose would make of every factor, every frame)
        m = _step(step, f"{path}[{i}]") @ m
    return m


def _flag(value: object, path: str) -> bool:
    if isinstance(value, bool):
        return value
    _fail(path, f"must be true or false, got {value!r}")


class Canvas:
    """The device: size, background, raster mode, highlight color.

    Parameters
    ----------
    data : object
        The scene's ``canvas`` table: ``width``, ``height`` (2 to :data:`MAX_SIZE`),
        ``background``, ``mode``, ``highlight``, ``antialias``.
    path : str, default "canvas"
        Its key path, named in error messages.

    Attributes
    ----------
    width, height : int
    background, highlight
        The colors, checked.
    mode : str
        "1", "L", "RGB", "RGBA" or "P".
    antialias : bool
    shading : Shading or None
        The scene's shaded surfaces (set by :func:`build`).

    Raises
    ------
    SceneError
        If a key is unknown or a value invalid.

    Examples
    --------
    >>> from scanline.scene.schema import Canvas
    >>> c = Canvas({"width": 4, "height": 3, "mode": "L"})
    >>> c.width, c.height, c.mode, c.antialias
    (4, 3, 'L', False)
    """

    def __init__(self, data: object, path: str = "canvas") -> None:
        from ..display.primitives import color

        d = _table(data, path, _CANVAS)
        self.width = _size(d.get("width", 400), f"{path}.width")
        self.height = _size(d.get("height", 300), f"{path}.height")
        try:
            check_image_size(self.width, self.height, 1,
                             f"{path}.width x {path}.height = {self.width} x {self.height}")
        except ScanlineError as error:
            raise SceneError(str(error), path=f"{path}.width") from None
        self.background = _call(path, color, "background", d.get("background", "white"))
        self.highlight = _call(path, color, "highlight", d.get("highlight", "magenta"))
        mode = d.get("mode", "RGB")
        if mode not in ("1", "L", "RGB", "RGBA", "P"):
            _fail(f"{path}.mode", f"must be one of '1', 'L', 'RGB', 'RGBA', 'P'; got {mode!r}")
        self.mode = mode
        self.antialias = _flag(d.get("antialias", False), f"{path}.antialias")
        self.path = path
        self.shading: "Shading | None" = None

    def nbytes(self, three_d: bool = False) -> int:
        """The bytes drawing this canvas takes: its frame buffer, and with
        ``three_d`` what 3-D surfaces need per pixel (:data:`SURFACE_BYTES_PER_PIXEL`).

        Parameters
        ----------
        three_d : bool, default False
            Count the z-buffer of 3-D surfaces too.

        Returns
        -------
        int

        Examples
        --------
        12 pixels of one byte, and with 12 bytes more each for the z-buffer:

        >>> from scanline.scene.schema import Canvas
        >>> c = Canvas({"width": 4, "height": 3, "mode": "L"})
        >>> c.nbytes(), c.nbytes(three_d=True)
        (12, 156)
        """
        per_pixel = _PIXEL_BYTES[self.mode] + (SURFACE_BYTES_PER_PIXEL if three_d else 0)
        return self.width * self.height * per_pixel

    def check_budget(self, three_d: bool = False) -> None:
        """Refuse, before anything is drawn, a canvas whose :meth:`nbytes` passes the
        memory budget (:mod:`scanline.budget`): a SceneError naming
        ``canvas.width x canvas.height``.

        Parameters
        ----------
        three_d : bool, default False
            Count the z-buffer of 3-D surfaces too.

        Raises
        ------
        SceneError
            If the canvas does not fit the memory budget.

        Examples
        --------
        >>> from scanline.scene.schema import Canvas
        >>> Canvas({"width": 4, "height": 3}).check_budget(three_d=True)
        """
        from .. import budget
        from ..errors import MemoryBudgetError

        path = self.path
        what = (f"a {self.width} x {self.height} canvas in mode {self.mode!r}"
                + (" with 3-D surfaces (a z-buffer of 12 bytes a pixel)" if three_d else ""))
        try:
            budget.check(self.nbytes(three_d), f"{path}.width x {path}.height", what,
                         hint="use a smaller canvas")
        except MemoryBudgetError as error:
            raise SceneError(str(error), path=f"{path}.width") from None


def _size(value: object, path: str) -> int:
    if isinstance(value, int) and not isinstance(value, bool) and 2 <= value <= MAX_SIZE:
        return value
    _fail(path, f"must be an integer from 2 to {MAX_SIZE}, got {value!r}")


def build(data: object, base: str | None = None) -> tuple[Canvas, DisplayFile]:
    """Check scene data (a dict) and build it: returns (Canvas, DisplayFile).  ``base``
    is the folder that mesh files are named relative to (the scene file's).

    Parameters
    ----------
    data : object
        The scene's data as parsed from TOML or JSON.
    base : str, optional
        The scene file's folder.

    Returns
    -------
    (Canvas, DisplayFile)

    Raises
    ------
    SceneError
        If the data is not a valid scene; the message starts with the key path.

    Examples
    --------
    >>> from scanline.scene.schema import build
    >>> canvas, df = build({"version": 1, "canvas": {"width": 8, "height": 6}, "segments": [
    ...     {"name": "box", "primitives": [{"type": "polyline", "points": [[0, 0], [7, 5]]}]}]})
    >>> canvas.width, [s.name for s in df.segments]
    (8, ['box'])
    >>> build({"version": 3})
    Traceback (most recent call last):
    ...
    scanline.scene.files.SceneError: version must be 1 or 2 (the schemas this scanline reads), got 3
    """
    from . import schema3d

    keys = {"version", "canvas", "window", "viewports", "segments", "cameras"}
    if isinstance(data, dict) and data.get("version") == 2:
        keys |= V2_KEYS
    d = _table(data, "", keys, ("version",))
    if d["version"] not in VERSIONS or isinstance(d["version"], bool):
        _fail("version", f"must be 1 or 2 (the schemas this scanline reads), got "
              f"{d['version']!r}")
    if d["version"] == 1 and "cameras" in d:
        _fail("cameras", "need version = 2 (the 3-D schema)")
    canvas = Canvas(d.get("canvas", {}))
    three_d = d["version"] == 2 and "cameras" in d
    canvas.check_budget(three_d)
    default_window = d.get("window", (0, 0, canvas.width - 1, canvas.height - 1))
    df = DisplayFile(aspect(canvas.width, canvas.height))
    cameras = schema3d.cameras(d["cameras"], df) if "cameras" in d else []
    from .shaded import shading

    canvas.shading = shading(d, base) if d["version"] == 2 else None
    context = {"version": d["version"], "cameras": cameras, "base": base,
               "background": canvas.background, "shading": canvas.shading,
               # the memory the scene keeps: the canvas, then each mesh primitive's
               # (schema3d checks the sum against the budget, mesh by mesh)
               "totals": {"bytes": canvas.nbytes(three_d), "meshes": 0, "vertices": 0,
                          "faces": 0}}
    viewports = _viewports(d.get("viewports"), default_window, df)
    names = list(viewports)
    for i, seg in enumerate(_list(d.get("segments", []), "segments")):
        _segment(seg, f"segments[{i}]", df, viewports, names[0], context)
    bottom = min((seg.priority for seg in df.segments), default=0.0) - 1.0
    for name, v in viewports.items():
        if v["border"] is not None:
            _border(df, name, v, bottom)
    return canvas, df


def _viewports(data: object, default_window: object,
               df: DisplayFile) -> dict[str, dict[str, Any]]:
    if data is None:
        data = [{"name": "main"}]
    out = {}
    for i, v in enumerate(_list(data, "viewports")):
        path = f"viewports[{i}]"
        t = _table(v, path, _VIEWPORT)
        name = t.get("name", f"viewport{i}")
        if not isinstance(name, str) or not name:
            _fail(f"{path}.name", f"must be a non-empty string, got {name!r}")
        if name in out:
            _fail(f"{path}.name", f"repeats the viewport name {name!r}")
        window = t.get("window", default_window)
        keep = _flag(t.get("keep_aspect", False), f"{path}.keep_aspect")
        clip = _flag(t.get("clip", True), f"{path}.clip")
        viewing = dict(window=window, viewport=t.get("viewport", (0.0, 0.0, 1.0, 1.0)),
                       view_up=t.get("view_up", (0.0, 1.0)), keep_aspect=keep, clip=clip)
        _call(path, df.set_viewing, **viewing)
        border = t.get("border")
        if border is not None:
            from ..display.primitives import color

            _call(path, color, "border", border)
        out[name] = {"viewing": viewing, "border": border, "camera": t.get("camera"),
                     "path": path}
    if not out:
        _fail("viewports", "must hold at least one viewport")
    return out


def _segment(data: object, path: str, df: DisplayFile, viewports: dict[str, dict[str, Any]],
             default: str, context: dict[str, Any]) -> None:
    """Build one scene segment: one display-file segment per viewport it is shown in
    (``name`` alone, or ``name@viewport`` when ``viewport`` lists several)."""
    s = _table(data, path, _SEGMENT, ("name",))
    name = s["name"]
    if not isinstance(name, str) or not name:
        _fail(f"{path}.name", f"must be a non-empty string, got {name!r}")
    shown = s.get("viewport", default)
    several = isinstance(shown, list)
    if several and not shown:
        _fail(f"{path}.viewport", "must name at least one viewport")
    for k, vp in enumerate(shown if several else [shown]):
        here = f"{path}.viewport[{k}]" if several else f"{path}.viewport"
        if not isinstance(vp, str) or vp not in viewports:
            _fail(here, f"names no viewport: {vp!r}; viewports: "
                  + ", ".join(repr(k) for k in viewports))
        _fill_segment(s, f"{name}@{vp}" if several else name, path, df, viewports[vp],
                      context)


def _fill_segment(s: dict[str, Any], name: str, path: str, df: DisplayFile,
                  viewport: dict[str, Any], context: dict[str, Any]) -> None:
    if name in df:
        _fail(f"{path}.name", f"repeats the segment name {name!r}")
    for where, owner in ((f"{path}.camera", s), (f"{viewport['path']}.camera", viewport)):
        if owner.get("camera") is None:
            continue
        if context["version"] < 2:
            _fail(where, "needs version = 2 (the 3-D schema)")
        if owner["camera"] not in context["cameras"]:
            _fail(where, f"names no camera: {owner['camera']!r}; cameras: "
                  + (", ".join(repr(c) for c in context["cameras"]) or "none"))
    if context["cameras"]:
        camera = s.get("camera") or viewport["camera"] or context["cameras"][0]
        df.set_camera(df.camera(camera), camera)
    df.set_viewing(**viewport["viewing"])
    m = transformation(s.get("transform", []), f"{path}.transform")
    context["segment_transform"] = m
    df.create_segment(name)
    _call(path, df.set_priority, name, s.get("priority", 0.0))
    _call(path, df.set_visibility, name, _flag(s.get("visible", True), f"{path}.visible"))
    _call(path, df.set_highlighting, name,
          _flag(s.get("highlighted", False), f"{path}.highlighted"))
    _call(f"{path}.transform", df.set_transformation, name, df.world_transformation(m))
    try:
        for j, prim in enumerate(_list(s.get("primitives", []), f"{path}.primitives")):
            _primitive(prim, f"{path}.primitives[{j}]", df, context)
    finally:
        df.close_segment()


def _primitive(data: object, path: str, df: DisplayFile, context: dict[str, Any]) -> None:
    from . import schema3d

    if not isinstance(data, dict):
        _fail(path, f"must be a table (an object), got {_kind(data)}")
    kind = data.get("type")
    if isinstance(kind, str) and kind in schema3d.PRIMITIVES:
        if context["version"] < 2:
            _fail(f"{path}.type", f"{kind!r} is a 3-D primitive: it needs version = 2")
        if not context["cameras"]:
            _fail(f"{path}.type", f"a {kind} is seen through a camera: add [[cameras]]")
        schema3d.primitive(kind, data, path, df, context["background"], context["base"],
                           context["shading"], context["segment_transform"],
                           totals=context.get("totals"))
        return
    if not isinstance(kind, str) or kind not in PRIMITIVES:
        known = list(PRIMITIVES) + (list(schema3d.PRIMITIVES) if context["version"] >= 2 else [])
        _fail(f"{path}.type", f"must be one of {', '.join(known)}; got {kind!r}")
    _table(data, path, PRIMITIVES[kind] | {"type"}, REQUIRED[kind])
    args = {k: x for k, x in data.items() if k != "type"}
    if "angle" in args:
        args["angle"] = angle(args["angle"], f"{path}.angle")
    if "fill" in args:
        args["fill"] = _flag(args["fill"], f"{path}.fill")
    if "closed" in args:
        args["closed"] = _flag(args["closed"], f"{path}.closed")
    if "align" in args and isinstance(args["align"], list):
        args["align"] = tuple(args["align"])
    methods: dict[str, Callable[..., object]] = {
        "polyline": df.polyline, "polygon": df.polygon, "circle": df.circle,
        "ellipse": df.ellipse, "text": df.text, "markers": df.markers}
    _call(path, methods[kind], **args)


def _border(df: DisplayFile, name: str, viewport: dict[str, Any], priority: float) -> None:
    """A segment with the viewport's outline, drawn under everything else."""
    seg = f"viewport:{name}"
    if seg in df:
        raise SceneError(f"the segment name {seg!r} is reserved for the border of "
                         f"viewport {name!r}", path="segments")
    view = viewport["viewing"]
    df.set_viewing(window=(0.0, 0.0, 1.0, 1.0), viewport=(0.0, 0.0, 1.0, 1.0), clip=False)
    df.create_segment(seg, priority=priority)
    x0, y0, x1, y1 = (float(c) for c in view["viewport"])
    df.polyline([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], color=viewport["border"], closed=True)
    df.close_segment()
