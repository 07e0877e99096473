"""Visible-line detection for wireframes (Hearn & Baker, section 13-10): the edges
of a mesh with the parts hidden by its faces removed, or drawn dashed.

*Object precision*: each edge is compared with each face in device space, and the
hidden parameter intervals are computed exactly (up to rounding).
"""

from typing import TYPE_CHECKING, Any, Literal, Optional, Sequence, Tuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._typing import Color
from ..errors import ArgumentValueError
from ..draw._common import target
from ..screen.meshes import meshes_list
from ..screen.polygons import as_screen
from ..screen.prepare import screen_polygons

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer
    from ..projection import Camera
    from ..screen.polygons import ScreenPolygons

#: Depth tolerance: an edge lying in a face's plane (its own faces) is not hidden
#: by it.
DEPTH_TOLERANCE = 1e-7
#: Parts shorter than this (pixels) are dropped: the slivers rounding leaves where a
#: hidden edge meets a visible one.
MIN_PIECE = 1e-3


def hidden_lines(segments: ArrayLike, depth: ArrayLike, polygons: "ScreenPolygons"
                 ) -> Tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.int64],
                            NDArray[np.int64]]:
    """Split device-space segments into visible and hidden parts.

    Parameters
    ----------
    segments : array_like, shape (N, 4)
        (x0, y0, x1, y1) per segment, device coordinates.
    depth : array_like, shape (N, 2)
        The depth of each endpoint.
    polygons : ScreenPolygons
        The faces that may hide them.

    Returns
    -------
    visible, hidden : ndarray, shape (K, 4)
        The parts of the segments in front of every face, and the parts behind some
        face.
    visible_of, hidden_of : ndarray of int64
        The segment each part comes from.

    Raises
    ------
    ArgumentValueError
        Segments and depths that are not (N, 4) and (N, 2) finite numbers of one length.

    Notes
    -----
    Hearn & Baker, section 13-10: "the most direct approach ... compare each line to
    each surface": for every face whose projection overlaps the segment's, the part
    of the segment inside the face's projection is found by Cyrus-Beck clipping
    against the face's edges, and of it the part that lies behind the face's plane
    (depth along the segment and along the plane are both linear in the segment's
    parameter, so the crossing is found exactly).  The union of those intervals is
    hidden; the rest is visible.  An edge of a face lies in the face's plane and is
    not hidden by it (:data:`DEPTH_TOLERANCE`).  The segment-face pairs run in a
    compiled kernel (:func:`scanline._kernels.visible.hidden_intervals`).  Object
    precision.

    Examples
    --------
    A segment across a cube seen head on: behind it (depth 1) the part over the
    faces' projection, x from 0.75 to 2.25, is hidden; in front (depth 0) none is.

    >>> import scanline as sl
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> sp = sl.screen.screen_polygons(sl.mesh.cube(2), cam, 4, 4)
    >>> sorted(set(sp.vertices[:, 0].tolist()))
    [0.75, 2.25]
    >>> visible, hidden, _, _ = sl.visible.hidden_lines([(0, 1.5, 3, 1.5)], [(1.0, 1.0)], sp)
    >>> visible.tolist(), hidden.tolist()
    ([[0.0, 1.5, 0.75, 1.5], [2.25, 1.5, 3.0, 1.5]], [[0.75, 1.5, 2.25, 1.5]])
    >>> len(sl.visible.hidden_lines([(0, 1.5, 3, 1.5)], [(0.0, 0.0)], sp)[1])
    0
    """
    from .._kernels import visible as k
    from .._kernels._jit import call

    sp = as_screen(polygons)
    segs = v.real_array("segments", segments, "(N, 4)").reshape(-1, 4)
    dep = v.real_array("depth", depth, "(N, 2)").reshape(-1, 2)
    if len(dep) != len(segs):
        raise ArgumentValueError(
            f"depth must have one row per segment ({len(segs)}), got {len(dep)}")
    if not (np.isfinite(segs).all() and np.isfinite(dep).all()):
        raise ArgumentValueError("segments and depth must be finite (no NaN or inf)")
    segs = np.ascontiguousarray(segs)
    dep = np.ascontiguousarray(dep)
    ext = np.ascontiguousarray(sp.extents())
    out = np.empty((4 * len(segs) + 16, 3))
    while True:
        n = call(k.hidden_intervals, 2 * len(segs) * len(sp) + 1, segs, dep, sp.vertices,
                 sp.offsets, sp.planes, ext, DEPTH_TOLERANCE, out)
        if n <= len(out):
            break
        out = np.empty((n, 3))
    rows = out[:n]
    vis: list[NDArray[np.float64]] = []
    hid: list[NDArray[np.float64]] = []
    vis_of: list[int] = []
    hid_of: list[int] = []
    order = np.lexsort((rows[:, 1], rows[:, 0]))
    rows = rows[order]
    bounds = np.searchsorted(rows[:, 0], np.arange(len(segs) + 1))
    for e in range(len(segs)):
        t = 0.0
        pieces: list[Tuple[float, float, bool]] = []
        for a, b in rows[bounds[e]:bounds[e + 1], 1:]:      # sorted by start
            if b <= t:
                continue
            if a > t + 1e-12:
                pieces.append((t, a, True))
                pieces.append((a, b, False))
            elif pieces and not pieces[-1][2]:
                pieces[-1] = (pieces[-1][0], b, False)   # runs on: one hidden part
            else:
                pieces.append((t, b, False))
            t = b
        if t < 1.0:
            pieces.append((t, 1.0, True))
        p0, d = segs[e, :2], segs[e, 2:] - segs[e, :2]
        length = float(np.hypot(*d))
        for a, b, seen in pieces:
            if (b - a) * length < MIN_PIECE:
                continue
            row = np.concatenate([p0 + a * d, p0 + b * d])
            (vis if seen else hid).append(row)
            (vis_of if seen else hid_of).append(e)
    return _rows4(vis), _rows4(hid), np.array(vis_of, np.int64), np.array(hid_of, np.int64)


def _rows4(rows: list[NDArray[np.float64]]) -> NDArray[np.float64]:
    return np.array(rows, np.float64).reshape(-1, 4)


def visible_lines(fb: "FrameBuffer", meshes: Any, camera: "Camera", color: Color = "white",
                  hidden: Literal["remove", "dash"] = "remove",
                  hidden_color: Optional[Color] = None,
                  dash: Sequence[int] = (4, 4),
                  **line: Any) -> Tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Draw the wireframe of ``meshes`` with hidden lines removed or dashed.

    Parameters
    ----------
    fb : FrameBuffer
        Drawn into.
    meshes : Mesh or list of Mesh
        The scene.
    camera : Camera
        The viewer.
    color : color
        The visible lines.
    hidden : {"remove", "dash"}
        Leave the hidden parts out, or draw them dashed (``dash`` pattern, in
        ``hidden_color``, default ``color``).
    hidden_color : color, optional
        Of the dashed hidden parts.
    dash : sequence of int
        The hidden parts' dash pattern.
    **line
        Line attributes of :func:`scanline.draw.lines` (width, antialias ...).

    Returns
    -------
    visible, hidden : ndarray, shape (K, 4)
        The device segments drawn solid and the hidden ones.

    Raises
    ------
    ArgumentTypeError
        ``fb`` not a FrameBuffer, or ``meshes`` not mesh-like.
    ArgumentValueError
        ``hidden`` neither "remove" nor "dash", or a line attribute of
        :func:`scanline.draw.lines` out of its range.

    Notes
    -----
    The edges are clipped and projected as :func:`scanline.draw3d.wireframe` does,
    the faces as the visible-surface methods see them
    (:func:`~scanline.visible.screen_polygons`), and each edge is split by
    :func:`hidden_lines`.  Object precision.

    Examples
    --------
    A cube seen in perspective from the front: its front square's 4 edges are
    visible; the back square and the 4 edges running back lie behind the front face.

    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(32, 32)
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
    >>> visible, hidden = sl.visible.visible_lines(fb, sl.mesh.cube(2), cam, hidden="dash")
    >>> len(visible), len(hidden)
    (4, 8)
    """
    from ..draw import lines as draw_lines
    from ..draw3d.wireframe import project_edges

    target(fb)
    v.choice("hidden", hidden, ("remove", "dash"))
    group = meshes_list(meshes)
    sp = screen_polygons(group, camera, fb.width, fb.height)
    segs: list[NDArray[np.float64]] = []
    deps: list[NDArray[np.float64]] = []
    for m in group:
        s, d, _ = project_edges(m.vertices, m.edges, camera, fb.width, fb.height)
        segs.append(s)
        deps.append(d)
    seen, unseen, _, _ = hidden_lines(np.concatenate(segs), np.concatenate(deps), sp)
    if hidden == "dash" and len(unseen):
        draw_lines(fb, unseen, color=color if hidden_color is None else hidden_color,
                   dash=dash, **line)
    if len(seen):
        draw_lines(fb, seen, color=color, **line)
    return seen, unseen
