"""Wireframes: 3-D lines and mesh edges drawn on a frame buffer through a camera
(Hearn & Baker, section 9-1, "wireframe" displays and depth cueing).

Each line goes world -> homogeneous clip coordinates -> clipped against the view
volume before the divide (:func:`scanline.clip.homogeneous`'s Liang-Barsky, in one
compiled pass: :func:`scanline._kernels.project3d.project_edges`) -> divided ->
device coordinates, and is then drawn by the 2-D batch kernels
(:func:`scanline.draw.lines`, :func:`scanline.draw.polylines`), so every line
attribute (width, caps, joins, dashes, pens) and antialiasing apply.
"""

from typing import (TYPE_CHECKING, Any, List, Literal, Optional, Sequence, Tuple, TypeVar, Union,
                    overload)

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._typing import Color, Colors, LineMethod
from ..clip.volumes import UNIT_CUBE
from ..color.spec import Channels
from ..draw import lines as draw_lines
from ..draw import polylines as draw_polylines
from ..draw._common import target
from ..errors import ArgumentTypeError, ArgumentValueError
from ..mesh.convert import as_meshes
from ..projection import Camera
from ..transform3d.arrays import real_array

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer
    from ..mesh import Mesh

Floats = NDArray[np.float64]

#: Intensities at the nearest and the farthest drawn depth for ``depth_cue=True``.
DEPTH_CUE = (1.0, 0.25)

_S = TypeVar("_S", bound=np.generic)


def _camera(camera: object) -> Camera:
    if not isinstance(camera, Camera):
        raise ArgumentTypeError(f"camera must be a scanline.Camera, got {v._show(camera)}")
    return camera


def project_edges(vertices: ArrayLike, edges: ArrayLike, camera: Camera, width: int,
                  height: int) -> Tuple[Floats, Floats, NDArray[np.int64]]:
    """Project and clip the line segments ``edges`` (E, 2), index pairs into the
    world-coordinate ``vertices`` (V, 3), onto a ``width`` x ``height`` device:
    :func:`project_edges_into` the whole device.  Returns ``(segments, depth,
    which)``.

    Parameters
    ----------
    vertices : array_like (V, 3)
        World coordinates.
    edges : array_like of int (E, 2)
        Vertex index pairs.
    camera : Camera
        The viewer.
    width, height : int
        The device's size.

    Returns
    -------
    segments : ndarray (K, 4)
        The visible parts in device coordinates.
    depth : ndarray (K, 2)
        Their endpoints' device depths.
    which : ndarray of int64 (K,)
        The edge of each row.

    Raises
    ------
    ArgumentTypeError
        ``camera`` not a Camera.
    ArgumentValueError
        Vertices not (V, 3), or edges not (E, 2) indices of them.

    Examples
    --------
    World x, y in -1..1 land on device 0..8 of a 9 x 9 frame buffer: x_d = 4 (x + 1).

    >>> import numpy as np, scanline as sl
    >>> cam = sl.Camera(projection=sl.projection.orthographic(window=(-1, -1, 1, 1)))
    >>> segments, depth, which = sl.draw3d.project_edges([(-1, -1, 0), (1, 1, 0)], [(0, 1)],
    ...                                                  cam, 9, 9)
    >>> segments.tolist(), which.tolist()
    ([[0.0, 0.0, 8.0, 8.0]], [0])
    """
    return project_edges_into(vertices, edges, camera, _camera(camera)._device_box(width, height))


@overload
def project_edges_into(vertices: ArrayLike, edges: ArrayLike, camera: Camera,
                       box: Sequence[float], aspect: Optional[float] = None,
                       details: Literal[True] = True
                       ) -> Tuple[Floats, Floats, NDArray[np.int64]]: ...


@overload
def project_edges_into(vertices: ArrayLike, edges: ArrayLike, camera: Camera,
                       box: Sequence[float], aspect: Optional[float] = None,
                       details: bool = True
                       ) -> Tuple[Floats, Optional[Floats], Optional[NDArray[np.int64]]]: ...


def project_edges_into(vertices: ArrayLike, edges: ArrayLike, camera: Camera,
                       box: Sequence[float], aspect: Optional[float] = None,
                       details: bool = True
                       ) -> Tuple[Floats, Optional[Floats], Optional[NDArray[np.int64]]]:
    """Project and clip line segments given as vertex pairs into the rectangle
    ``box`` (see :meth:`scanline.Camera.mapping`).

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
        World coordinates.
    edges : array_like of int, shape (E, 2)
        Vertex index pairs.
    camera : Camera
    box : (x0, y0, x1, y1)
        Where NDC (0, 0) and (1, 1) land.
    aspect : float, optional
        The displayed width / height of ``box``.
    details : bool
        False: return only the segments (``depth`` and ``which`` are None).

    Returns
    -------
    segments : ndarray, shape (K, 4)
        The visible parts (x0, y0, x1, y1) in device coordinates.
    depth : ndarray, shape (K, 2)
        The device depth of their endpoints.
    which : ndarray of int64, shape (K,)
        The edge each row comes from.
    """
    from .._kernels import project3d as k
    from .._kernels._jit import call
    from .._kernels._threads import call_in_chunks

    camera = _camera(camera)
    verts = real_array("vertices", vertices, "(V, 3)")
    if verts.ndim != 2 or verts.shape[1] != 3:
        raise ArgumentValueError(f"vertices must have shape (V, 3), got {verts.shape}")
    e = v.index_array("edges", edges, shape=(None, 2), high=len(verts) - 1,
                      bound_text=f" (larger is out of range: there are {len(verts)} vertices)",
                      what="an integer array of shape (E, 2) (vertex indices)")
    clip, scale, offset = camera.mapping(box, aspect)
    out = np.empty((len(e), 4))
    depth = np.empty((len(e) if details else 0, 2))
    which = np.empty(len(e) if details else 0, np.int64)
    h = np.empty((len(verts), 4))
    call(k.to_clip, 4 * len(verts), np.ascontiguousarray(clip), np.ascontiguousarray(verts),
         h)                                                         # once per vertex
    parts = call_in_chunks(
        k.project_edges, 20 * len(e), len(e),
        lambda lo, hi: (scale, offset, UNIT_CUBE.planes, h, e[lo:hi], out[lo:hi],
                        depth[lo:hi], which[lo:hi], float(v.COORD_LIMIT)))
    # the visible rows of each chunk, joined in the order of the edges (a chunk's
    # ``which`` counts from its first edge)
    if details:
        for lo, rows in parts:
            which[lo:lo + rows] += lo

    def keep(a: NDArray[_S]) -> NDArray[_S]:
        return (a[:parts[0][1]] if len(parts) == 1 else
                np.concatenate([a[lo:lo + rows] for lo, rows in parts]))

    if not details:
        return keep(out), None, None
    return keep(out), keep(depth), keep(which)


def edge_colors(mesh: "Mesh", edges: NDArray[np.int64]) -> NDArray[np.uint8]:
    """RGBA (E, 4) colors of a mesh's edges from its face or vertex colors: an edge
    takes the color of the first face it borders, or the mean of its two vertices'."""
    colors = mesh.colors
    assert colors is not None
    if mesh.color_on == "vertex":
        return ((colors[edges[:, 0]].astype(np.int64)
                 + colors[edges[:, 1]]) // 2).astype(np.uint8)
    faces, _ = mesh.edge_faces()
    return colors[faces[:, 0]]


def _channel_values(fb: "FrameBuffer", rgba: NDArray[np.uint8]) -> NDArray[np.uint8]:
    """Pixel values (N, channels) of RGBA rows for ``fb``: one ``fb.pixel`` per
    distinct color."""
    uniq, inverse = np.unique(rgba, axis=0, return_inverse=True)
    values = np.array([fb.pixel(Channels(int(c) for c in row)) for row in uniq], np.uint8)
    return values[inverse.reshape(-1)]


def cue_factor(camera: Camera, depth: Floats, cue: Tuple[float, float]) -> Floats:
    """Hearn & Baker's depth-cueing factor per segment: f = (d_max - d) / (d_max -
    d_min) of the midpoints' distances (linear in viewing coordinates), mapped to
    the intensities ``cue`` = (near, far)."""
    near, far = cue
    d = camera.linear_depth(depth.mean(axis=1))
    lo, hi = (float(d.min()), float(d.max())) if len(d) else (0.0, 1.0)
    f = (hi - d) / (hi - lo) if hi > lo else np.ones_like(d)
    return far + (near - far) * f


def depth_cue_intensities(depth_cue: Union[None, bool, Tuple[float, float]]
                          ) -> Optional[Tuple[float, float]]:
    """(near, far) intensities of a ``depth_cue`` argument, or None."""
    if depth_cue is None or depth_cue is False:
        return None
    if depth_cue is True:
        return DEPTH_CUE
    if isinstance(depth_cue, (tuple, list)) and len(depth_cue) == 2:
        pair = (v.number("depth_cue[0]", depth_cue[0]), v.number("depth_cue[1]", depth_cue[1]))
        if all(0.0 <= x <= 1.0 for x in pair):
            return pair
    raise ArgumentValueError(
        f"depth_cue must be True, False or (near, far) intensities in 0..1, got "
        f"{v._show(depth_cue)}")


def wireframe(fb: "FrameBuffer", meshes: Any, camera: Camera,
              color: Union[None, Color, List[Optional[Color]]] = None, *,
              depth_cue: Union[None, bool, Tuple[float, float]] = None,
              background: Optional[Color] = None, method: LineMethod = "bresenham",
              **line: Any) -> Floats:
    """Draw the edges of one mesh or several through ``camera``.

    Parameters
    ----------
    fb : FrameBuffer
        Drawn into.
    meshes : Mesh or list of Mesh
        Or any mesh object :meth:`~scanline.mesh.Mesh.from_any` takes (a trimesh,
        meshio or Open3D mesh).
    camera : Camera
        The viewer.
    color : color, list of colors (one per mesh), or None
        None: each mesh's own colors (an edge takes the color of its first face, or
        the mean of its vertices' colors), white for a mesh without colors.
    depth_cue : bool or (near, far), optional
        Depth cueing (Hearn & Baker, section 9-1): each edge's intensity falls
        linearly with its distance from the viewer, from ``near`` (1.0 for True) at
        the nearest drawn edge to ``far`` (0.25) at the farthest, blending its color
        toward ``background``.  Modes "L", "RGB", "RGBA".
    background : color, optional
        The color depth cueing fades to (default: the frame buffer's background).
    method : {"bresenham", "dda"}
        The line algorithm.
    style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen
        Line attributes, as :func:`scanline.draw.lines` takes them.

    Returns
    -------
    ndarray, shape (K, 4)
        The device segments drawn (after clipping), for inspection.

    Raises
    ------
    ArgumentTypeError
        ``fb`` not a FrameBuffer, or ``meshes`` not mesh-like.
    ArgumentValueError
        A list of colors of another length than the meshes', ``depth_cue`` that is not
        True, False or (near, far) in 0..1, depth cueing into a mode other than L, RGB,
        RGBA, or a line attribute of :func:`scanline.draw.lines` out of its range.

    Notes
    -----
    Every edge is clipped in homogeneous coordinates against the view volume before
    the perspective divide, so edges that pass behind the eye are cut at the front
    plane rather than wrapped round; the visible parts are drawn as one batch of
    :func:`scanline.draw.lines` (their pixels are exactly those of
    ``sl.draw.lines(fb, segments)``).  No hidden lines are removed: see the
    visible-surface methods for that.

    Examples
    --------
    >>> import math, scanline as sl
    >>> fb = sl.FrameBuffer(9, 9, mode="1")
    >>> cam = sl.Camera(projection=sl.projection.orthographic(window=(-1, -1, 1, 1)))
    >>> _ = sl.draw3d.wireframe(fb, sl.mesh.cube(1.5), cam)
    >>> print(sl.text_image(fb))
    ---------
    -#######-
    -#-----#-
    -#-----#-
    -#-----#-
    -#-----#-
    -#-----#-
    -#######-
    ---------
    """
    target(fb)
    camera = _camera(camera)
    group = as_meshes(meshes)
    if isinstance(color, list) and len(color) != len(group):
        raise ArgumentValueError(
            f"color holds {len(color)} colors for {len(group)} meshes; give one per mesh "
            "or one for all")
    cue = depth_cue_intensities(depth_cue)
    if cue is not None and fb.mode not in ("L", "RGB", "RGBA"):
        raise ArgumentValueError(
            f"depth_cue needs intensity levels: use a frame buffer of mode 'L', 'RGB' or "
            f"'RGBA', not {fb.mode!r}")
    specs = [color[i] if isinstance(color, list) else color for i in range(len(group))]
    shared = cue is None and len(set(map(repr, specs))) == 1 and (
        specs[0] is not None or all(m.colors is None for m in group))
    segs: List[Floats] = []
    depths: List[Floats] = []
    values: List[NDArray[np.uint8]] = []
    for mesh, spec in zip(group, specs):
        s, d, which = project_edges_into(mesh.vertices, mesh.edges, camera,
                                         camera._device_box(fb.width, fb.height),
                                         details=not shared)
        segs.append(s)
        if not shared:                       # details: depth and which
            assert d is not None and which is not None
            depths.append(d)
            if spec is None and mesh.colors is not None:
                values.append(_channel_values(fb, edge_colors(mesh, mesh.edges)[which]))
            else:
                pixel = fb.pixel("white" if spec is None else spec)
                values.append(np.repeat(pixel[None], len(s), axis=0))
    segments = segs[0] if len(segs) == 1 else np.concatenate(segs)
    if not len(segments):
        return segments
    if shared:
        draw_lines(fb, segments, color="white" if specs[0] is None else specs[0],
                   method=method, **line)
        return segments
    value = np.concatenate(values)
    if cue is not None:
        bg = fb._background if background is None else fb.pixel(background, "background")
        f = cue_factor(camera, np.concatenate(depths), cue)
        value = np.clip(np.rint(bg + f[:, None] * (value.astype(np.float64) - bg)), 0, 255)
    per_edge = (value[:, 0] if value.shape[1] == 1 else value).astype(np.int64)
    draw_lines(fb, segments, color=per_edge, method=method, **line)
    return segments


def _segments3d(name: str, segments: ArrayLike) -> Floats:
    a = real_array(name, segments, "(N, 6) or (N, 2, 3)")
    if a.size == 0:
        a = a.reshape(0, 6)
    if a.ndim == 3 and a.shape[1:] == (2, 3):
        a = a.reshape(-1, 6)
    if a.ndim == 1 and a.size == 6:
        a = a.reshape(1, 6)
    if a.ndim != 2 or a.shape[1] != 6:
        raise ArgumentValueError(f"{name} must have shape (N, 6) or (N, 2, 3), got {a.shape}")
    return a


def lines(fb: "FrameBuffer", segments: ArrayLike, camera: Camera, color: Colors = "white",
          **line: Any) -> Floats:
    """Draw 3-D line segments (N, 6) -- rows (x0, y0, z0, x1, y1, z1) -- through
    ``camera``, clipped in homogeneous coordinates, with any line attributes of
    :func:`scanline.draw.lines`.  Returns the device segments drawn.

    Parameters
    ----------
    fb : FrameBuffer
        Drawn into.
    segments : array_like (N, 6) or (N, 2, 3)
        World segments.
    camera : Camera
        The viewer.
    color : color, or one per segment
        The lines' color.
    **line
        Line attributes of :func:`scanline.draw.lines`.

    Returns
    -------
    ndarray (K, 4)
        The device segments drawn (after clipping).

    Raises
    ------
    ArgumentValueError
        Segments of another shape.

    Examples
    --------
    World x, y in -1..1 land on device 0..8 of a 9 x 9 frame buffer: x_d = 4 (x + 1).

    >>> import numpy as np, scanline as sl
    >>> cam = sl.Camera(projection=sl.projection.orthographic(window=(-1, -1, 1, 1)))
    >>> fb = sl.FrameBuffer(9, 9, mode="1")
    >>> sl.draw3d.lines(fb, [(-0.5, 0, 0, 0.5, 0, 0)], cam).tolist()
    [[2.0, 4.0, 6.0, 4.0]]
    """
    target(fb)
    a = _segments3d("segments", segments)
    verts = a.reshape(-1, 3)
    edges = np.arange(len(verts), dtype=np.int64).reshape(-1, 2)
    segs, _, which = project_edges(verts, edges, _camera(camera), fb.width, fb.height)
    if isinstance(color, (list, np.ndarray)) and len(color) == len(a):
        color = [color[i] for i in which] if isinstance(color, list) else color[which]
    if len(segs):
        draw_lines(fb, segs, color=color, **line)
    return segs


def polyline_pieces(points: ArrayLike, camera: Camera, width: int, height: int,
                    closed: bool = False) -> List[Floats]:
    """The visible pieces of a 3-D polyline on a ``width`` x ``height`` device: a list
    of (K, 2) arrays (consecutive visible segments that were not cut at their shared
    vertex stay one piece, so joins and dash patterns run on).

    Parameters
    ----------
    points : array_like (N, 3)
        The polyline's world points.
    camera : Camera
        The viewer.
    width, height : int
        The device's size.
    closed : bool
        Join the last point to the first.

    Returns
    -------
    list of ndarray (K, 2)
        Device points of each visible piece.

    Examples
    --------
    World x, y in -1..1 land on device 0..8 of a 9 x 9 frame buffer: x_d = 4 (x + 1).

    >>> import numpy as np, scanline as sl
    >>> cam = sl.Camera(projection=sl.projection.orthographic(window=(-1, -1, 1, 1)))
    >>> pts = [(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0)]
    >>> [piece.tolist() for piece in sl.draw3d.polyline_pieces(pts, cam, 9, 9)]
    [[[2.0, 2.0], [6.0, 2.0], [6.0, 6.0]]]
    """
    return pieces_into(points, camera, _camera(camera)._device_box(width, height), closed)


def pieces_into(points: ArrayLike, camera: Camera, box: Sequence[float], closed: bool = False,
                aspect: Optional[float] = None) -> List[Floats]:
    """:func:`polyline_pieces` into the rectangle ``box`` (see
    :func:`project_edges_into`)."""
    from ..transform3d.arrays import points as point_array

    p, _ = point_array("points", points)
    if closed and len(p) > 2:
        p = np.vstack([p, p[:1]])
    if len(p) < 2:
        return []
    edges = np.stack([np.arange(len(p) - 1), np.arange(1, len(p))], axis=1)
    segs, _, which = project_edges_into(p, edges, camera, box, aspect)
    pieces: List[List[Floats]] = []
    last: Optional[Tuple[int, Floats]] = None
    for s, i in zip(segs, which.tolist()):
        a, b = s[:2], s[2:]
        if last is not None and last[0] == i - 1 and np.array_equal(last[1], a):
            pieces[-1].append(b)
        else:
            pieces.append([a, b])
        last = (i, b)
    return [np.array(piece) for piece in pieces]


def polylines(fb: "FrameBuffer", polylines_: Any, camera: Camera, color: Colors = "white",
              closed: bool = False, **line: Any) -> List[Floats]:
    """Draw 3-D polylines (a list of (N_i, 3) arrays) through ``camera``, clipped in
    homogeneous coordinates, with the attributes of :func:`scanline.draw.polylines`
    (joins and dashes run on along each visible piece).

    Parameters
    ----------
    fb : FrameBuffer
        Drawn into.
    polylines_ : list of array_like (N_i, 3), or array_like (M, N, 3)
        World polylines.
    camera : Camera
        The viewer.
    color : color, or one per polyline
        Their color.
    closed : bool
        Close each polyline.
    **line
        Line attributes of :func:`scanline.draw.polylines`.

    Returns
    -------
    list of ndarray (K, 2)
        The visible pieces drawn, in device coordinates.

    Raises
    ------
    ArgumentTypeError
        ``fb`` not a FrameBuffer.
    ArgumentValueError
        Points that are not (N, 3) finite numbers, or a line attribute of
        :func:`scanline.draw.polylines` out of its range.

    Examples
    --------
    World x, y in -1..1 land on device 0..8 of a 9 x 9 frame buffer: x_d = 4 (x + 1).

    >>> import numpy as np, scanline as sl
    >>> cam = sl.Camera(projection=sl.projection.orthographic(window=(-1, -1, 1, 1)))
    >>> fb = sl.FrameBuffer(9, 9, mode="1")
    >>> pts = np.array([(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0)])
    >>> _ = sl.draw3d.polylines(fb, [pts], cam)
    >>> print(sl.text_image(fb))
    ---------
    ---------
    ------#--
    ------#--
    ------#--
    ------#--
    --#####--
    ---------
    ---------
    """
    target(fb)
    _camera(camera)
    if not isinstance(polylines_, (list, tuple)):
        polylines_ = list(real_array("polylines", polylines_, "(M, N, 3)"))
    pieces: List[Floats] = []
    owner: List[int] = []
    for i, pl in enumerate(polylines_):
        got = polyline_pieces(pl, camera, fb.width, fb.height, closed)
        pieces += got
        owner += [i] * len(got)
    if isinstance(color, list) and len(color) == len(polylines_):
        color = [color[i] for i in owner]
    if pieces:
        draw_polylines(fb, pieces, color=color, **line)
    return pieces


def view_volume(fb: "FrameBuffer", volume_camera: Camera, camera: Camera, color: Color = "white",
                size: Optional[Tuple[int, int]] = None, **line: Any) -> Floats:
    """Draw the 12 edges of ``volume_camera``'s view volume as ``camera`` sees it;
    ``size`` = (width, height) of the device ``volume_camera`` widens its window for
    (default: the window as it is).

    Parameters
    ----------
    fb : FrameBuffer
        Drawn into.
    volume_camera : Camera
        Whose view volume (Hearn & Baker 12-3) is drawn.
    camera : Camera
        The viewer.
    color : color
        The edges' color.
    size : (int, int), optional
        The device ``volume_camera`` is fitted to.
    **line
        Line attributes.

    Returns
    -------
    ndarray (K, 4)
        The device segments drawn.

    Examples
    --------
    A parallel view volume seen by its own camera: its front and back rectangles
    fall on the window's border, its four side edges on its corners.

    >>> import numpy as np, scanline as sl
    >>> cam = sl.Camera(projection=sl.projection.orthographic(window=(-1, -1, 1, 1)))
    >>> fb = sl.FrameBuffer(9, 9, mode="1")
    >>> len(sl.draw3d.view_volume(fb, cam, cam))
    12
    >>> print(sl.text_image(fb))
    #########
    #-------#
    #-------#
    #-------#
    #-------#
    #-------#
    #-------#
    #-------#
    #########
    """
    corners = _camera(volume_camera).volume_corners(*(size or (None, None)))
    ring = [(0, 1), (1, 2), (2, 3), (3, 0)]
    edges = np.array(ring + [(a + 4, b + 4) for a, b in ring] + [(k, k + 4) for k in range(4)])
    segs, _, _ = project_edges(corners, edges, _camera(camera), fb.width, fb.height)
    if len(segs):
        draw_lines(fb, segs, color=color, **line)
    return segs


def axes(fb: "FrameBuffer", camera: Camera, length: float = 1.0,
         origin: Sequence[float] = (0.0, 0.0, 0.0),
         colors: Sequence[Color] = ("red", "green", "blue"), **line: Any) -> Floats:
    """Draw the x, y and z axes from ``origin``, ``length`` long, in ``colors``.

    Parameters
    ----------
    fb : FrameBuffer
        Drawn into.
    camera : Camera
        The viewer.
    length : float
        Of each axis.
    origin : 3-vector
        Where they start.
    colors : three colors
        Of x, y and z.
    **line
        Line attributes.

    Returns
    -------
    ndarray (3, 4)
        The device segments of x, y and z.

    Raises
    ------
    ArgumentTypeError
        ``fb`` not a FrameBuffer, or ``length`` not a number.
    ArgumentValueError
        ``length`` not finite, or a line attribute of :func:`scanline.draw.lines` out of
        its range.

    Examples
    --------
    Looking down z, the z axis is a point at the origin's pixel:

    >>> import numpy as np, scanline as sl
    >>> cam = sl.Camera(projection=sl.projection.orthographic(window=(-1, -1, 1, 1)))
    >>> fb = sl.FrameBuffer(9, 9, mode="RGB")
    >>> sl.draw3d.axes(fb, cam, length=0.5).tolist()
    [[4.0, 4.0, 6.0, 4.0], [4.0, 4.0, 4.0, 6.0], [4.0, 4.0, 4.0, 4.0]]
    """
    from ..transform3d.arrays import vector

    o = np.array(vector("origin", origin))
    n = v.number("length", length)
    segs = np.array([np.concatenate([o, o + n * np.eye(3)[k]]) for k in range(3)])
    return lines(fb, segs, camera, color=list(colors), **line)
