"""The frame plan of an animated scene: the display file of each frame without checking
and building the whole scene again.

The base scene is built once.  A frame changes only what its tracks touch, so when
every track writes into a segment's ``transform`` or into one of its 2-D primitives,
a frame is the base display file with

- the segment transformations of the segments whose ``transform`` is animated,
  computed again from the frame's steps (:func:`scanline.scene.schema.transformation`
  and the display file's own world-to-NDC conjugation), and
- the animated primitives built again from the frame's data
  (:func:`scanline.scene.schema._primitive`),

each checked as the full build checks it, with the same key path in its messages;
the other segments and primitives are shared with the base display file.  Scenes
whose tracks reach anything else (the canvas, the window, the viewports, a
segment's priority or visibility, cameras, lights) have no plan: their frames are
built in full.
"""

from typing import TYPE_CHECKING, Any, Iterable, Sequence

import numpy as np
from numpy.typing import NDArray

from .. import transform as tf
from ..display.file import DisplayFile, Segment
from ..display.interpreter import drawing_order
from ..display.viewing import aspect
from .schema import V2_KEYS, _call, _primitive, _viewports, build, transformation

if TYPE_CHECKING:
    from .animated import _Token


class FramePlan:
    """The base display file of ``data`` (a version-2 scene without its animation
    table) and where the tracks ``targets`` (parsed key paths) write into it.

    Use :func:`plan` to make one: it returns None for scenes it cannot patch.

    Parameters
    ----------
    data : dict
        The base scene's data, checked.
    targets : iterable of token sequences
        The tracks' key paths (:func:`scanline.scene.animated.parse_target`).
    base : str, optional
        The scene file's folder.

    Attributes
    ----------
    canvas : Canvas
    display_file : DisplayFile
        The base scene's.
    moved : set of int
        The indices of the segments whose transformation is animated.
    changed : dict
        Segment index -> the indices of its animated primitives.

    Raises
    ------
    SceneError
        If the base scene is invalid.

    Examples
    --------
    One track moves the segment ``dot``:

    >>> from scanline.scene.animated import parse_target
    >>> from scanline.scene.plan import plan
    >>> data = {"version": 2, "canvas": {"width": 6, "height": 3}, "segments": [{"name": "dot",
    ...     "transform": [{"translate": [0, 0]}], "primitives": [{"type": "polygon",
    ...     "points": [[0.5, 0.5], [2.5, 0.5], [2.5, 2.5], [0.5, 2.5]]}]}]}
    >>> p = plan(data, [parse_target("segments[dot].transform[0].translate", "target")])
    >>> p.moved, p.changed
    ({0}, {})
    """

    def __init__(self, data: dict[str, Any], targets: "Iterable[Sequence[_Token]]",
                 base: str | None = None) -> None:
        self.canvas, self.display_file = build(data, base)
        width, height = self.canvas.width, self.canvas.height
        default_window = data.get("window", (0, 0, width - 1, height - 1))
        viewports = _viewports(data.get("viewports"), default_window,
                               DisplayFile(aspect(width, height)))
        names = list(viewports)
        self.segments: list[dict[str, Any]] = data.get("segments", [])
        # one scratch display file per viewport, its viewing set, holding an open
        # segment: transformations and primitives are made there as build makes them
        self._scratch: dict[str, DisplayFile] = {}
        self._normalization: dict[str, tuple[NDArray[np.float64], NDArray[np.float64]]] = {}
        for name, viewport in viewports.items():
            df = DisplayFile(aspect(width, height))
            df.set_viewing(**viewport["viewing"])
            df.create_segment("frame")
            self._scratch[name] = df
            self._normalization[name] = (df.normalization, tf.inverse(df.normalization))
        self._context: dict[str, Any] = {"version": data["version"], "cameras": [], "base": base,
                         "background": self.canvas.background, "shading": None,
                         "segment_transform": None}
        # data segment index -> [(display-file segment name, viewport name)]
        self._shown: dict[int, list[tuple[str, str]]] = {}
        for i, seg in enumerate(self.segments):
            shown = seg.get("viewport", names[0])
            several = isinstance(shown, list)
            self._shown[i] = [(f"{seg['name']}@{vp}" if several else seg["name"], vp)
                              for vp in (shown if several else [shown])]
        self.moved: set[int] = set()      # data segment indices whose transform is animated
        self.changed: dict[int, set[int]] = {}  # data segment index -> primitive indices animated
        for tokens in targets:
            i, j = _where(tokens, self.segments)
            if j is None:
                self.moved.add(i)
            else:
                self.changed.setdefault(i, set()).add(j)
        self.order = drawing_order(self.display_file)

    def segments_at(self, data: dict[str, Any]) -> list[Segment]:
        """The segments of the frame whose scene data is ``data`` (the base data with
        the animated values written in), in drawing order: display-file
        :class:`~scanline.display.file.Segment` objects, shared with the base where
        nothing changed.

        Parameters
        ----------
        data : dict
            The frame's scene data.

        Returns
        -------
        list of Segment

        Raises
        ------
        SceneError
            If an animated value is invalid (with its key path).

        Examples
        --------
        The square of 2 x 2 pixels moved 2 to the right, drawn by
        :func:`scanline.scene.painter.paint`:

        >>> import copy
        >>> import scanline as sl
        >>> from scanline.scene.painter import paint
        >>> from scanline.scene.animated import parse_target
        >>> from scanline.scene.plan import plan
        >>> data = {"version": 2, "canvas": {"width": 6, "height": 3}, "segments": [{"name": "dot",
        ...     "transform": [{"translate": [0, 0]}], "primitives": [{"type": "polygon",
        ...     "points": [[0.5, 0.5], [2.5, 0.5], [2.5, 2.5], [0.5, 2.5]]}]}]}
        >>> p = plan(data, [parse_target("segments[dot].transform[0].translate", "target")])
        >>> frame = copy.deepcopy(data)
        >>> frame["segments"][0]["transform"][0]["translate"] = [2, 0]
        >>> fb = sl.FrameBuffer(6, 3)
        >>> paint(fb, p.segments_at(frame), p.display_file)
        >>> print(sl.text_image(fb))
        ---##-
        ---##-
        ------
        """
        replaced: dict[str, Segment] = {}
        for i in sorted(self.moved | set(self.changed)):
            seg = data["segments"][i]
            path = f"segments[{i}]"
            for name, vp in self._shown[i]:
                base = self.display_file.segment(name)
                scratch = self._scratch[vp]
                out = Segment(name, base._order)
                out.priority, out.visible = base.priority, base.visible
                out.highlighted, out.detectable = base.highlighted, base.detectable
                out.transformation = base.transformation
                out.primitives = base.primitives
                if i in self.moved:
                    m = transformation(seg.get("transform", []), f"{path}.transform")
                    # DisplayFile.world_transformation and set_transformation: N m N^-1
                    # (N^-1 kept), checked finite as set_transformation checks it (the
                    # product of affine steps is affine)
                    n, n_inv = self._normalization[vp]
                    out.transformation = _call(f"{path}.transform", tf.compose,
                                               n @ m @ n_inv)
                if i in self.changed:
                    out.primitives = list(base.primitives)
                    held = scratch.segment("frame").primitives
                    for j in sorted(self.changed[i]):
                        _primitive(seg["primitives"][j], f"{path}.primitives[{j}]", scratch,
                                   self._context)
                        out.primitives[j] = held.pop()
                replaced[name] = out
        return [replaced.get(s.name, s) for s in self.order]


def _where(tokens: "Sequence[_Token]",
           segments: list[dict[str, Any]]) -> tuple[int, int | None]:
    """(data segment index, primitive index) of a track's key path, the primitive
    index None for the segment's transform; raises _NoPlan for a path elsewhere."""
    if len(tokens) < 3 or tokens[0] != "segments" or tokens[2] not in ("transform",
                                                                         "primitives"):
        raise _NoPlan()
    token = tokens[1]
    if isinstance(token, tuple):
        index = next((k for k, s in enumerate(segments) if s.get("name") == token[1]), None)
        if index is None:            # (the full build finds, or refuses, the name)
            raise _NoPlan()
    elif isinstance(token, int):
        index = token
    else:                            # (the scene's check refuses a key here)
        raise _NoPlan()
    i = index % len(segments)
    if tokens[2] == "transform":
        return i, None
    if len(tokens) < 5 or not isinstance(tokens[3], int):
        raise _NoPlan()
    prims = segments[i]["primitives"]
    return i, tokens[3] % len(prims)


class _NoPlan(Exception):
    """The tracks reach values that the plan does not patch."""


#: Primitive types a plan builds again (one display-file primitive each).
_FLAT = ("polyline", "polygon", "circle", "ellipse", "text", "markers")


def plan(data: dict[str, Any], targets: "Iterable[Sequence[_Token]]",
         base: str | None = None) -> FramePlan | None:
    """A :class:`FramePlan` of ``data`` (already checked) for the tracks ``targets``
    (parsed key paths), or None when a frame has to be built in full: a scene with
    cameras, lights or shading, or tracks that reach other values than segment
    transformations and 2-D primitives.

    Parameters
    ----------
    data : dict
        The base scene's data, checked.
    targets : iterable of token sequences
        The tracks' key paths (:func:`scanline.scene.animated.parse_target`).
    base : str, optional
        The scene file's folder.

    Returns
    -------
    FramePlan or None

    Raises
    ------
    SceneError
        If the base scene is invalid.

    Examples
    --------
    >>> from scanline.scene.animated import parse_target
    >>> from scanline.scene.plan import plan
    >>> data = {"version": 2, "canvas": {"width": 6, "height": 3}, "segments": [{"name": "dot",
    ...     "transform": [{"translate": [0, 0]}], "primitives": [{"type": "polygon",
    ...     "points": [[0.5, 0.5], [2.5, 0.5], [2.5, 2.5], [0.5, 2.5]]}]}]}
    >>> p = plan(data, [parse_target("segments[dot].transform[0].translate", "target")])
    >>> sorted(p.moved)
    [0]
    >>> plan(dict(data, lights=[]), []) is None      # lights: frames built in full
    True
    """
    if "cameras" in data or any(k in data for k in V2_KEYS - {"animation"}):
        return None
    for seg in data.get("segments", []):
        if any(p.get("type") not in _FLAT for p in seg.get("primitives", [])):
            return None
    try:
        made = FramePlan(data, targets, base)
    except _NoPlan:
        return None
    return made if made.canvas.shading is None else None
