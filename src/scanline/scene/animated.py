"""Animated scenes: the scene file as the notes' "animation language" (schema version
2, the ``animation`` table; docs/scene-format.md and docs/animation.md).

A version-2 scene is a static scene plus an ``animation`` table whose tracks change
any numeric value of the scene over time — a translation, an angle, a radius, a
color, a polygon's points, a window (and, once 3-D lands, a camera's eye point) —
named by the key path that error messages use, with segments and viewports also
addressable by name (``segments[ball].transform[0].translate``):

- ``tracks``: key frames ``{time, value, ease}`` with an interpolation (linear,
  step, catmull-rom, cardinal, kochanek-bartels);
- ``paths``: motion along a curve by arc length, eased, optionally turning an angle
  to face along the path;
- ``morphs``: a polygon's points through key shapes, equalized as Hearn & Baker do;
- ``rotations``: key orientations of a 3-D ``rotate = {quaternion = [w, x, y, z]}``
  step (given as quaternions, axis and angle, or Euler angles), in-betweens by
  quaternion slerp or squad (Shoemake 1985);
- ``storyboard``: captions at times, for ``scanline storyboard``.

Each frame is the base scene with the values of that time written in, checked and
drawn like any scene.
"""

import copy
import math
import os
import re
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, Callable, TypeVar, Union, cast, overload

import numpy as np

from ..errors import ScanlineError
from . import files
from .files import SceneError
from .locate import line_of
from .scene import Scene
from .schema import _fail, _real, _table

if TYPE_CHECKING:
    from PIL import Image

    from ..animation import Animation, MotionPath, Timeline
    from ..color.spec import RGBA
    from ..curves import Curve
    from ..framebuffer import FrameBuffer
    from ..transform3d.quaternion import Quaternion
    from .plan import FramePlan

_T = TypeVar("_T")
#: A token of a parsed target: a key, an index, or ("name", NAME) for ``[NAME]``.
_Token = Union[str, int, tuple[str, str]]

_ANIMATION = {"fps", "duration", "start", "title", "storyboard", "tracks", "paths", "morphs",
              "rotations"}
_TRACK = {"target", "keys", "interpolation", "ease", "tension", "continuity", "bias"}
_KEY = {"time", "value", "ease"}
_PATH = {"target", "curve", "start", "end", "ease", "orient", "arc_length"}
_CURVE = {"type", "points", "order", "closed", "tension"}
_MORPH = {"target", "keys", "interpolation", "ease", "closed", "align"}
_MORPH_KEY = {"time", "points", "ease"}
_STORY = {"time", "caption"}
_ROTATION = {"target", "keys", "interpolation", "ease"}
_ROTATION_KEY = {"time", "quaternion", "axis", "degrees", "radians", "euler", "ease"}
_EULER = {"seq", "degrees", "radians"}
CURVES = ("polyline", "bezier", "bspline", "catmull-rom", "cardinal")

class _UNPLANNED:
    """The frame plan not made yet (a class: it keeps its identity through pickling)."""


_TOKEN = re.compile(r"([A-Za-z_][A-Za-z0-9_-]*)|\[([^\]]+)\]|(\.)")


def _list(value: object, path: str, minimum: int = 0) -> list[Any]:
    if not isinstance(value, list) or len(value) < minimum:
        _fail(path, f"must be an array of at least {minimum} entries, got {value!r}"[:200])
    return value


def _wrap(path: str, call: Callable[..., _T], *args: Any, **kwargs: Any) -> _T:
    """Call a package function; its error becomes a SceneError at ``path``."""
    try:
        return call(*args, **kwargs)
    except SceneError:
        raise
    except ScanlineError as error:
        raise SceneError(f"{path}: {error}", path=path) from None


# -- targets --------------------------------------------------------------------------------
def parse_target(text: object, path: str) -> list[_Token]:
    """``segments[ball].transform[0].translate`` -> ["segments", ("name", "ball"),
    "transform", 0, "translate"] (a bracketed name picks the array entry whose
    ``name`` it is).

    Parameters
    ----------
    text : object
        A track's ``target``.
    path : str
        Its key path, named in error messages.

    Returns
    -------
    list
        Keys (str), indices (int) and ``("name", NAME)`` for ``[NAME]``.

    Raises
    ------
    SceneError
        If ``text`` is not a key path.

    Examples
    --------
    >>> from scanline.scene.animated import parse_target
    >>> parse_target("segments[ball].transform[0].translate", "animation.tracks[0].target")
    ['segments', ('name', 'ball'), 'transform', 0, 'translate']
    >>> parse_target("segments[ball] transform", "animation.tracks[0].target")
    Traceback (most recent call last):
    ...
    scanline.scene.files.SceneError: animation.tracks[0].target cannot read the key path 'segments[ball] transform' at ' transform'
    """
    if not isinstance(text, str) or not text:
        _fail(path, f"must be a key path such as 'segments[ball].transform[0].translate', got {text!r}")
    tokens: list[_Token] = []
    pos, expect_name = 0, True
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None:
            _fail(path, f"cannot read the key path {text!r} at {text[pos:]!r}")
        name, index, dot = m.groups()
        if dot:
            expect_name = True
        elif name is not None:
            if not expect_name:
                _fail(path, f"cannot read the key path {text!r}: a '.' must come before {name!r}")
            tokens.append(name)
            expect_name = False
        else:
            inner = index.strip().strip("'\"")
            tokens.append(int(inner) if re.fullmatch(r"-?\d+", inner) else ("name", inner))
            expect_name = False
        pos = m.end()
    return tokens


def _step(node: Any, token: _Token, text: str, path: str) -> Any:
    if isinstance(token, tuple):                 # [name]
        if not isinstance(node, list):
            _fail(path, f"{text!r}: [{token[1]}] needs an array here")
        for item in node:
            if isinstance(item, dict) and item.get("name") == token[1]:
                return item
        _fail(path, f"{text!r}: no entry named {token[1]!r}")
    if isinstance(token, int):
        if not isinstance(node, list) or not -len(node) <= token < len(node):
            _fail(path, f"{text!r}: index [{token}] is not in an array of "
                  f"{len(node) if isinstance(node, list) else 0} entries")
        return node[token]
    if not isinstance(node, dict) or token not in node:
        _fail(path, f"{text!r}: the scene has no key {token!r} there (animate values the "
              "scene gives)")
    return node[token]


def locate(data: dict[str, Any], tokens: list[_Token], text: str,
           path: str) -> tuple[Any, str | int]:
    """(container, key) of the value at ``tokens`` in ``data``.

    Parameters
    ----------
    data : dict
        Scene data.
    tokens : list
        A parsed target (:func:`parse_target`).
    text : str
        The target as written, named in error messages.
    path : str
        The target's key path, named in error messages.

    Returns
    -------
    (dict or list, str or int)
        The value is ``container[key]``.

    Raises
    ------
    SceneError
        If the scene has no value there, or the target names an entry.

    Examples
    --------
    >>> from scanline.scene.animated import locate, parse_target
    >>> data = {"segments": [{"name": "ball", "transform": [{"translate": [1, 2]}]}]}
    >>> target = "segments[ball].transform[0].translate"
    >>> locate(data, parse_target(target, "target"), target, "target")
    ({'translate': [1, 2]}, 'translate')
    >>> locate(data, parse_target("segments[box]", "target"), "segments[box]", "target")
    Traceback (most recent call last):
    ...
    scanline.scene.files.SceneError: target 'segments[box]': no entry named 'box'
    """
    node: Any = data
    for token in tokens[:-1]:
        node = _step(node, token, text, path)
    last = tokens[-1]
    _step(node, last, text, path)
    if isinstance(last, tuple):
        _fail(path, f"{text!r} names an entry, not a value to animate")
    return node, last


def _numeric_shape(value: object, path: str, text: str) -> tuple[int, ...] | str:
    if isinstance(value, str):
        return "color"
    try:
        a = np.array(value, dtype=np.float64)
    except (TypeError, ValueError, OverflowError):
        _fail(path, f"{text!r} holds {value!r}, which is not numbers (nor a color)"[:300])
    return a.shape


#: Keys whose values name things (a segment's name is how ``[name]`` finds it): never
#: animated, whatever they hold.
_NAMES = {"name", "type", "viewport", "camera", "version"}


def _animatable(tokens: list[_Token], current: object, path: str, text: str) -> None:
    """Refuse a target that holds something other than numbers or a color: a name or
    a kind (animating ``segments[ball].name`` would lose the segment that
    ``segments[ball]`` finds), or a string that is not a color."""
    last = tokens[-1]
    if isinstance(last, str) and last in _NAMES:
        _fail(path, f"{text!r} is the scene's {last!r}, which names or picks a part of the "
              "scene; animate numbers or colors (a position, an angle, a radius, a color)")
    if isinstance(current, str):
        from ..color.spec import rgba

        try:
            rgba(current, "value")
        except ScanlineError:
            _fail(path, f"{text!r} holds {current!r}, which is neither numbers nor a color; "
                  "animate numbers or colors"[:300])
    elif isinstance(current, (bool, dict)) or current is None:
        _fail(path, f"{text!r} holds {current!r}, which is not numbers (nor a color)"[:300])


# -- values ----------------------------------------------------------------------------------
class _Color:
    """Colors interpolated as RGBA, written back as [r, g, b, a] integers."""

    @staticmethod
    def encode(value: object, path: str) -> "RGBA":
        from ..color.spec import rgba

        return _wrap(path, rgba, value, path)

    @staticmethod
    def decode(value: Any) -> list[int]:
        return [int(c) for c in np.clip(np.floor(np.asarray(value) + 0.5), 0, 255)]


def _plain(value: Any) -> float | list[Any]:
    a = np.asarray(value, dtype=np.float64)
    return float(a) if a.ndim == 0 else a.tolist()


class _Writer:
    """Writes one track's value into frame data."""

    def __init__(self, target: str, tokens: list[_Token], decode: Callable[[Any], Any]) -> None:
        self.target, self.tokens, self.decode = target, tokens, decode
        self._indices: list[str | int] | None = None      # the tokens with [name] resolved, found on first write

    def write(self, data: dict[str, Any], value: Any, copied: set[int]) -> None:
        """Write ``value`` into ``data`` (a shallow copy of the base scene), copying
        each container on the way that is not yet in ``copied`` (ids of copies), so
        that the base scene is never changed and untouched parts are shared."""
        node: Any = data
        if self._indices is None:     # every frame starts from the same base: the
            indices: list[str | int] = []     # entry of a name is found once
            for token in self.tokens[:-1]:
                if isinstance(token, tuple):
                    found = next((k for k, item in enumerate(node)
                                  if isinstance(item, dict) and item.get("name") == token[1]),
                                 None)
                    if found is None:          # (_animatable keeps names unchanged)
                        raise SceneError(f"{self.target!r}: no entry named "
                                         f"{token[1]!r} in this frame",
                                         path=self.target)
                    token = found
                indices.append(token)
                node = node[token]
            self._indices, node = indices, data
        for index in self._indices:
            child = node[index]
            if id(child) not in copied:
                child = list(child) if isinstance(child, list) else dict(child)
                copied.add(id(child))
                node[index] = child
            node = child
        node[self.tokens[-1]] = self.decode(value)


class AnimatedScene:
    """A version-2 scene with an ``animation`` table: a render function of the frame
    index (for :class:`scanline.animation.Animation`), a timeline, a storyboard.

    Parameters
    ----------
    data : dict
        Scene data (``version = 2``).
    file, text, format
        As for :class:`~scanline.scene.Scene`: named in error messages, which then
        give the line of the bad value.

    Raises
    ------
    SceneError
        If the scene or its animation table is invalid (with the key path, and the
        line when ``text`` is given).

    Notes
    -----
    The scene file as the notes' animation language: key frames and in-betweens
    (Hearn & Baker, section 16-2).

    Examples
    --------
    A square moved 2 units right in one second, at 2 frames per second:

    >>> import scanline as sl
    >>> anim = sl.scene.AnimatedScene({"version": 2, "canvas": {"width": 6, "height": 3},
    ...     "segments": [{"name": "dot", "transform": [{"translate": [0, 0]}], "primitives": [
    ...         {"type": "polygon", "points": [[0.5, 0.5], [2.5, 0.5], [2.5, 2.5], [0.5, 2.5]]}]}],
    ...     "animation": {"fps": 2, "tracks": [{"target": "segments[dot].transform[0].translate",
    ...         "keys": [{"time": 0, "value": [0, 0]}, {"time": 1, "value": [2, 0]}]}]}})
    >>> for i in range(len(anim)):
    ...     print(sl.text_image(anim.frame(i)).splitlines()[0])
    -##---
    --##--
    ---##-
    """

    def __init__(self, data: dict[str, Any], file: str | None = None,
                 text: str | None = None, format: str = "toml") -> None:
        self.scene = Scene(data, file, text, format)       # the static scene, checked
        self.canvas = self.scene.canvas
        self.file = file
        self._plan: FramePlan | None | type[_UNPLANNED] = _UNPLANNED
        try:
            self._build(copy.deepcopy(data))
            self.frame(0)                                 # the first and last frames check
            self.frame(len(self) - 1)                     # the animated values
        except SceneError as error:
            line = None
            if text is not None and error.path is not None:
                line = line_of(text, format, error.path)
            raise SceneError(error.message, file=file, line=line, path=error.path) from None

    # -- reading the animation table ------------------------------------------------------
    def _build(self, data: dict[str, Any]) -> None:
        from .. import animation as an

        if data.get("version") != 2 or "animation" not in data:
            _fail("animation", "is missing: an animated scene is version 2 with an "
                  "[animation] table (fps, tracks, paths, morphs)")
        a = _table(data["animation"], "animation", _ANIMATION)
        self.base = data
        self.base.pop("animation")
        fps = a.get("fps", 24)
        duration = a.get("duration")
        self.title = a.get("title", "")
        if not isinstance(self.title, str):
            _fail("animation.title", f"must be a string, got {self.title!r}")
        timeline = _wrap("animation", an.Timeline, fps=_real(fps, "animation.fps"),
                         duration=None if duration is None else _real(duration, "animation.duration"),
                         start=_real(a.get("start", 0.0), "animation.start"))
        self.writers: dict[str, _Writer] = {}
        for i, t in enumerate(_list(a.get("tracks", []), "animation.tracks")):
            self._track(t, f"animation.tracks[{i}]", timeline, data)
        for i, p in enumerate(_list(a.get("paths", []), "animation.paths")):
            self._path(p, f"animation.paths[{i}]", timeline, data)
        for i, m in enumerate(_list(a.get("morphs", []), "animation.morphs")):
            self._morph(m, f"animation.morphs[{i}]", timeline, data)
        for i, r in enumerate(_list(a.get("rotations", []), "animation.rotations")):
            self._rotation(r, f"animation.rotations[{i}]", timeline, data)
        if not timeline.tracks:
            _fail("animation", "animates nothing: give tracks, paths, morphs or rotations")
        self.timeline = timeline
        self.storyboard: list[tuple[float, str]] = []
        for i, s in enumerate(_list(a.get("storyboard", []), "animation.storyboard")):
            here = f"animation.storyboard[{i}]"
            s = _table(s, here, _STORY, ("time",))
            caption = s.get("caption", "")
            if not isinstance(caption, str):
                _fail(f"{here}.caption", f"must be a string, got {caption!r}")
            self.storyboard.append((_real(s["time"], f"{here}.time"), caption))

    def _target(self, value: Any, path: str,
                data: dict[str, Any]) -> tuple[list[_Token], Any]:
        tokens = parse_target(value, f"{path}.target")
        node, key = locate(data, tokens, value, f"{path}.target")
        if value in self.writers:
            _fail(f"{path}.target", f"{value!r} is animated twice; give each value one track")
        _animatable(tokens, node[key], f"{path}.target", value)
        return tokens, node[key]

    def _add(self, timeline: "Timeline", target: str, tokens: list[_Token], track: Any,
             decode: Callable[[Any], Any], path: str) -> None:
        self.writers[target] = _Writer(target, tokens, decode)
        timeline.add(target, track)

    def _keys_times(self, keys: list[dict[str, Any]], path: str) -> list[float]:
        times: list[float] = []
        for k, key in enumerate(keys):
            t = _real(key["time"], f"{path}.keys[{k}].time")
            if times and t <= times[-1]:
                _fail(f"{path}.keys[{k}].time", f"is {t:g}, not after the previous key's "
                      f"{times[-1]:g}; key frames must be in order, at different times")
            times.append(t)
        return times

    def _eases(self, keys: list[dict[str, Any]], default: Any, path: str) -> Any:
        eases = []
        from ..animation.easing import resolve

        for k, key in enumerate(keys[:-1]):
            name = key.get("ease", default)
            _wrap(f"{path}.keys[{k}].ease" if "ease" in key else f"{path}.ease", resolve, name)
            eases.append(name)
        return eases or default

    def _track(self, t: object, path: str, timeline: "Timeline", data: dict[str, Any]) -> None:
        from .. import animation as an

        t = _table(t, path, _TRACK, ("target", "keys"))
        tokens, current = self._target(t["target"], path, data)
        keys = [_table(k, f"{path}.keys[{i}]", _KEY, ("time", "value"))
                for i, k in enumerate(_list(t["keys"], f"{path}.keys", 1))]
        times = self._keys_times(keys, path)
        shape = _numeric_shape(current, f"{path}.target", t["target"])
        if shape == "color" or any(isinstance(k["value"], str) for k in keys):
            values: list[Any] = [_Color.encode(k["value"], f"{path}.keys[{i}].value")
                                 for i, k in enumerate(keys)]
            decode: Callable[[Any], Any] = _Color.decode
        else:
            values = []
            for i, k in enumerate(keys):
                here = f"{path}.keys[{i}].value"
                got = _numeric_shape(k["value"], here, t["target"])
                if got != shape:
                    _fail(here, f"has shape {got}, but {t['target']!r} holds a value of shape "
                          f"{shape} ({current!r})"[:300])
                values.append(k["value"])
            decode = _plain
        track = _wrap(path, an.KeyFrames, times, values,
                      interpolation=t.get("interpolation", "linear"),
                      ease=self._eases(keys, t.get("ease", "linear"), path),
                      tension=t.get("tension", 0.0), continuity=t.get("continuity", 0.0),
                      bias=t.get("bias", 0.0))
        self._add(timeline, t["target"], tokens, track, decode, path)

    def _curve(self, c: object, path: str) -> "list[Any] | Curve":
        from .. import curves

        c = _table(c, path, _CURVE, ("type", "points"))
        kind = c["type"]
        if kind not in CURVES:
            _fail(f"{path}.type", f"must be one of {', '.join(CURVES)}; got {kind!r}")
        points: list[Any] = c["points"]
        if kind == "polyline":
            return points
        if kind == "bezier":
            return _wrap(path, curves.Bezier, points)
        if kind == "bspline":
            return _wrap(path, curves.BSpline, points, order=c.get("order", 4),
                         knots="periodic" if c.get("closed", False) else "open")
        closed = c.get("closed", False)
        if kind == "catmull-rom":
            return _wrap(path, curves.CatmullRom, points, closed=closed)
        return _wrap(path, curves.CardinalSpline, points, tension=c.get("tension", 0.0),
                     closed=closed)

    def _path(self, p: object, path: str, timeline: "Timeline", data: dict[str, Any]) -> None:
        from .. import animation as an

        p = _table(p, path, _PATH, ("target", "curve"))
        tokens, current = self._target(p["target"], path, data)
        curve = self._curve(p["curve"], f"{path}.curve")
        motion = _wrap(f"{path}.curve", an.MotionPath, curve,
                       arc_length=p.get("arc_length", True))
        shape = _numeric_shape(current, f"{path}.target", p["target"])
        if shape != (motion.dimension,):
            _fail(f"{path}.target", f"{p['target']!r} holds {current!r}; a path gives "
                  f"{motion.dimension} coordinates")
        start = _real(p.get("start", timeline.start), f"{path}.start")
        end = _real(p.get("end", start + 1.0), f"{path}.end")
        ease = p.get("ease", "linear")
        _wrap(f"{path}.ease", an.easing.resolve, ease)
        if not start < end:
            _fail(f"{path}.end", f"must come after start ({start:g}), got {end:g}")
        self._add(timeline, p["target"], tokens, _Along(motion, start, end, ease), _plain, path)
        if "orient" in p:
            tokens, current = self._target(p["orient"], f"{path}.orient", data)
            if _numeric_shape(current, f"{path}.orient", p["orient"]) != ():
                _fail(f"{path}.orient", f"{p['orient']!r} must hold one number (an angle)")
            radians = tokens[-1] == "radians"
            self._add(timeline, p["orient"], tokens,
                      _Heading(motion, start, end, ease, radians), _plain, f"{path}.orient")

    def _morph(self, m: object, path: str, timeline: "Timeline", data: dict[str, Any]) -> None:
        from .. import animation as an

        m = _table(m, path, _MORPH, ("target", "keys"))
        tokens, current = self._target(m["target"], path, data)
        keys = [_table(k, f"{path}.keys[{i}]", _MORPH_KEY, ("time", "points"))
                for i, k in enumerate(_list(m["keys"], f"{path}.keys", 2))]
        times = self._keys_times(keys, path)
        closed = m.get("closed", True)
        if not isinstance(closed, bool):
            _fail(f"{path}.closed", f"must be true or false, got {closed!r}")
        shapes = _wrap(path, an.equalize, *[k["points"] for k in keys], closed=closed,
                       align=bool(m.get("align", False)))
        track = _wrap(path, an.KeyFrames, times, np.stack(shapes),
                      interpolation=m.get("interpolation", "linear"),
                      ease=self._eases(keys, m.get("ease", "linear"), path))
        self._add(timeline, m["target"], tokens, track, _plain, path)

    def _rotation(self, r: object, path: str, timeline: "Timeline",
                  data: dict[str, Any]) -> None:
        from .. import animation as an

        r = _table(r, path, _ROTATION, ("target", "keys"))
        tokens, current = self._target(r["target"], path, data)
        if _numeric_shape(current, f"{path}.target", r["target"]) != (4,):
            _fail(f"{path}.target", f"{r['target']!r} holds {current!r}; a rotation track "
                  "animates a quaternion [w, x, y, z]: target a 3-D step's "
                  "rotate.quaternion")
        keys = [_table(k, f"{path}.keys[{i}]", _ROTATION_KEY, ("time",))
                for i, k in enumerate(_list(r["keys"], f"{path}.keys", 1))]
        times = self._keys_times(keys, path)
        rotations = [_orientation(k, f"{path}.keys[{i}]") for i, k in enumerate(keys)]
        track = _wrap(path, an.RotationKeyFrames, times, rotations,
                      interpolation=r.get("interpolation", "slerp"),
                      ease=self._eases(keys, r.get("ease", "linear"), path))
        self._add(timeline, r["target"], tokens, track, _quaternion, path)

    # -- frames ---------------------------------------------------------------------------
    def __getstate__(self) -> dict[str, Any]:
        """Pickled for worker processes without the static scene's display file (the
        frames are rebuilt from the data)."""
        state = dict(self.__dict__)
        state["scene"] = None
        state["_plan"] = _UNPLANNED
        return state

    def __len__(self) -> int:
        return len(self.timeline)

    @property
    def fps(self) -> float:
        """Frames per second."""
        return self.timeline.fps

    def set_fps(self, fps: float) -> None:
        """Sample the animation at ``fps`` frames per second instead (the key times
        stay: a higher rate makes more in-betweens).

        Parameters
        ----------
        fps : float
            Frames per second, > 0.

        Raises
        ------
        ArgumentValueError
            If ``fps`` is not a positive number.

        Examples
        --------
        Three seconds at 12 frames per second are 36 frames; at 4, 12:

        >>> import scanline as sl
        >>> anim = sl.scene.load_animated(sl.scene.example("bouncing_ball"))
        >>> len(anim), anim.set_fps(4), len(anim)
        (36, None, 12)
        """
        from ..animation.timing import _fps

        self.timeline.fps = _fps(fps)

    def data_at(self, frame: int) -> dict[str, Any]:
        """The scene data of ``frame``: the base scene with the animated values.

        Parameters
        ----------
        frame : int
            The frame index.

        Returns
        -------
        dict
            Scene data (version 2, without the animation table); the parts that are
            not animated are shared with the base data.

        Examples
        --------
        The ball starts at its path's first control point:

        >>> import scanline as sl
        >>> anim = sl.scene.load_animated(sl.scene.example("bouncing_ball"))
        >>> anim.data_at(0)["segments"][1]["transform"][1]
        {'translate': [20.0, 22.0]}
        """
        data = dict(self.base)
        copied = {id(data)}
        for name, value in self.timeline.values(frame).items():
            self.writers[name].write(data, value, copied)
        return data

    def _frame_plan(self) -> "FramePlan | None":
        """The :class:`~scanline.scene.plan.FramePlan` of the frames, or None when each
        frame is built in full (made on first use, in each process)."""
        made = self._plan
        if isinstance(made, type):                        # _UNPLANNED
            from .plan import plan

            folder = None if self.file is None else os.path.dirname(os.path.abspath(self.file))
            made = self._plan = plan(self.base, [w.tokens for w in self.writers.values()],
                                     folder)
        return made

    def frame(self, index: int) -> "FrameBuffer":
        """Frame ``index`` drawn: a :class:`~scanline.FrameBuffer`.

        The pixels are those of ``Scene(self.data_at(index)).raster()``; when the
        tracks only move segments and change 2-D primitives, the frame is the base
        display file with those parts made again (:mod:`scanline.scene.plan`), drawn
        in batches (:mod:`scanline.scene.painter`).

        Parameters
        ----------
        index : int
            The frame index.

        Returns
        -------
        FrameBuffer

        Raises
        ------
        SceneError
            If the frame's values make an invalid scene (naming the frame and time).

        Examples
        --------
        Below the ball's center (20, 22), inside its radius of 12 and away from the
        white stripe, the ball is crimson:

        >>> import scanline as sl
        >>> anim = sl.scene.load_animated(sl.scene.example("bouncing_ball"))
        >>> anim.frame(0).get_pixel(20, 16)
        (220, 20, 60)
        """
        data = self.data_at(index)
        plan = self._frame_plan()
        try:
            if plan is None:
                return Scene(data).raster()
            segments = plan.segments_at(data)
        except SceneError as error:
            raise SceneError(f"frame {index} (t = {self.timeline.time(index):g} s): "
                             f"{error.message}", path=error.path) from None
        from ..framebuffer import FrameBuffer
        from .painter import paint

        c = plan.canvas
        fb = FrameBuffer(c.width, c.height, mode=c.mode, background=c.background)
        paint(fb, segments, plan.display_file, c.antialias, c.highlight)
        return fb

    __call__ = frame

    def animation(self) -> "Animation":
        """The frames as an :class:`~scanline.animation.Animation`.

        Returns
        -------
        Animation

        Examples
        --------
        >>> import scanline as sl
        >>> anim = sl.scene.load_animated(sl.scene.example("bouncing_ball"))
        >>> anim.animation()
        Animation(36 frames at 12 fps, 3 s)
        """
        from ..animation import Animation

        return Animation(self, fps=self.fps)

    def storyboard_frames(self) -> list[tuple[int, str, str]]:
        """(frame, label, caption) of each storyboard panel: the storyboard's times
        when the file gives them, else the key frames.

        Returns
        -------
        list of (int, str, str)

        Examples
        --------
        The file's storyboard times 0, 1.5 and 2.9 s at 12 fps:

        >>> import scanline as sl
        >>> anim = sl.scene.load_animated(sl.scene.example("bouncing_ball"))
        >>> [(frame, label) for frame, label, _ in anim.storyboard_frames()]
        [(0, '1. t = 0.00 s, frame 0'), (18, '2. t = 1.50 s, frame 18'), (35, '3. t = 2.90 s, frame 35')]
        """
        tl = self.timeline
        if self.storyboard:
            times = [(t, c) for t, c in self.storyboard]
        else:
            times = [(float(t), "") for t in tl.key_times()]
        out: list[tuple[int, str, str]] = []
        for k, (t, caption) in enumerate(times):
            frame = int(min(max(math.floor((t - tl.start) * tl.fps + 0.5), 0), len(self) - 1))
            out.append((frame, f"{k + 1}. t = {t:.2f} s, frame {frame}", caption))
        return out

    def storyboard_sheet(self, columns: int = 4,
                         panel: tuple[int, int] = (240, 180)) -> "Image.Image":
        """The storyboard as a contact sheet (a Pillow image).

        Parameters
        ----------
        columns : int, default 4
            Panels per row.
        panel : (int, int), default (240, 180)
            The size each frame is shown at.

        Returns
        -------
        PIL.Image.Image

        Raises
        ------
        ArgumentValueError
            If ``columns`` or ``panel`` is not positive.

        Examples
        --------
        >>> import scanline as sl
        >>> anim = sl.scene.load_animated(sl.scene.example("bouncing_ball"))
        >>> anim.storyboard_sheet(columns=3, panel=(80, 50)).mode
        'RGB'
        """
        from ..animation import contact_sheet

        panels = self.storyboard_frames()
        title = self.title or (os.path.basename(self.file) if self.file else "storyboard")
        title += f"  ({len(self)} frames at {self.fps:g} fps, {self.timeline.duration:g} s)"
        return contact_sheet(_Frames(self, [f for f, _, _ in panels]), [p[1] for p in panels],
                             [p[2] for p in panels], columns=columns, panel=panel, title=title)


class _Frames(Sequence["FrameBuffer"]):
    """Frames of a scene drawn when the contact sheet asks for them, one at a time (a
    storyboard of many panels never holds every frame)."""

    def __init__(self, scene: AnimatedScene, numbers: list[int]) -> None:
        self.scene, self.numbers = scene, numbers

    def __len__(self) -> int:
        return len(self.numbers)

    @overload
    def __getitem__(self, k: int) -> "FrameBuffer": ...

    @overload
    def __getitem__(self, k: slice) -> "_Frames": ...

    def __getitem__(self, k: int | slice) -> "FrameBuffer | _Frames":
        if isinstance(k, slice):
            return _Frames(self.scene, self.numbers[k])
        return self.scene.frame(self.numbers[k])


class _Along:
    """A motion path's point at time t."""

    def __init__(self, motion: "MotionPath", start: float, end: float, ease: Any) -> None:
        self.motion, self.start, self.end, self.ease = motion, start, end, ease

    def __call__(self, t: float) -> Any:
        return self.motion.at(t, self.start, self.end, self.ease)


class _Heading(_Along):
    """A motion path's heading at time t, in degrees or radians."""

    def __init__(self, motion: "MotionPath", start: float, end: float, ease: Any,
                 radians: bool) -> None:
        super().__init__(motion, start, end, ease)
        self.radians = radians

    def __call__(self, t: float) -> Any:
        angle = self.motion.heading(self.motion.progress(t, self.start, self.end, self.ease))
        return angle if self.radians else math.degrees(angle)


def _quaternion(q: "Quaternion") -> list[float]:
    """A rotation track's value as the scene writes it: [w, x, y, z]."""
    return cast("list[float]", q.wxyz.tolist())


def _orientation(key: dict[str, Any], path: str) -> "Quaternion":
    """A rotation key's orientation: ``quaternion = [w, x, y, z]``, ``axis = [x, y, z]``
    with ``degrees`` or ``radians``, or ``euler = {seq = "xyz", degrees = [...]}``."""
    from ..transform3d.quaternion import Quaternion
    from .schema import angle

    given = [k for k in ("quaternion", "axis", "euler") if k in key]
    if len(given) != 1:
        _fail(path, "must give its orientation one way: quaternion = [w, x, y, z], axis = "
              "[x, y, z] with degrees or radians, or euler = {seq = \"xyz\", degrees = [...]}")
    unit = {k: key[k] for k in ("degrees", "radians") if k in key}
    how = given[0]
    if how != "axis" and unit:
        _fail(f"{path}.{next(iter(unit))}", f"goes with axis, not with {how}")
    if how == "quaternion":
        q = key["quaternion"]
        if not isinstance(q, list) or len(q) != 4:
            _fail(f"{path}.quaternion", f"must be four numbers [w, x, y, z], got {q!r}")
        return _wrap(f"{path}.quaternion", Quaternion.from_array,
                     [_real(c, f"{path}.quaternion[{i}]") for i, c in enumerate(q)],
                     "quaternion")
    if how == "axis":
        axis = key["axis"]
        if not isinstance(axis, list) or len(axis) != 3:
            _fail(f"{path}.axis", f"must be [x, y, z], got {axis!r}")
        axis = [_real(c, f"{path}.axis[{i}]") for i, c in enumerate(axis)]
        return _wrap(f"{path}.axis", Quaternion.from_axis_angle, axis, angle(unit, path))
    e = _table(key["euler"], f"{path}.euler", _EULER, ("seq",))
    units = [k for k in ("degrees", "radians") if k in e]
    if len(units) != 1:
        _fail(f"{path}.euler", "must give its angles in degrees or in radians: "
              "{seq = \"xyz\", degrees = [10, 20, 30]}")
    values = e[units[0]]
    if not isinstance(values, list):
        _fail(f"{path}.euler.{units[0]}", f"must be a list of angles, got {values!r}")
    angles = [angle({units[0]: x}, f"{path}.euler.{units[0]}[{i}]") for i, x in enumerate(values)]
    return _wrap(f"{path}.euler", Quaternion.from_euler, e["seq"], angles)


def loads(text: str, format: str = "toml", file: str | None = None) -> AnimatedScene:
    """An :class:`AnimatedScene` from TOML or JSON text.

    Parameters
    ----------
    text : str
        The scene file's text (version 2 with an animation table).
    format : {"toml", "json"}, default "toml"
    file : str, optional
        The file it came from, named in error messages.

    Returns
    -------
    AnimatedScene

    Raises
    ------
    SceneError
        If the text does not parse or is not a valid animated scene (with the line).

    Examples
    --------
    >>> import scanline as sl
    >>> text = sl.scene.example("bouncing_ball").read_text()
    >>> len(sl.scene.loads_animated(text))
    36
    """
    return AnimatedScene(files.loads(text, format, file), file, text, format)


def load(path: "str | os.PathLike[str]", format: str | None = None) -> AnimatedScene:
    """An :class:`AnimatedScene` from a ``.toml`` or ``.json`` file.

    Parameters
    ----------
    path : str or os.PathLike
        The scene file.
    format : {"toml", "json"}, optional
        The format; by default from the extension.

    Returns
    -------
    AnimatedScene

    Raises
    ------
    SceneError
        If the file cannot be read or is not a valid animated scene.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.scene.load_animated(sl.scene.example("bouncing_ball")).fps
    12.0
    """
    name = os.fspath(path)
    fmt = files.format_of(name, format)
    return loads(files.read_text(name), fmt, name)
