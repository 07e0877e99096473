"""What :mod:`scanline.mpl` reads from matplotlib's 3-D artists: world-space polygons,
polylines and points, with the colors matplotlib computed for them (its colormap,
its shading, its depth shading of scatter markers), and their projection by the
axes' own matrix.

Everything here mirrors what ``mpl_toolkits.mplot3d.art3d`` does in
``do_3d_projection`` -- the same attributes, the same projection -- but keeps the
polygons in the order the user gave them: the drawing order is scanline's business.
The attributes read are private ones of matplotlib (``_faces``, ``_segments3d``,
``_offsets3d`` ...); each is read in one place, here.
"""

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, List, Optional, Sequence, Tuple, Union

import numpy as np
from matplotlib import colors as mcolors
from matplotlib.artist import Artist
from mpl_toolkits.mplot3d import art3d
from numpy.typing import ArrayLike, DTypeLike, NDArray

from ._geometry import Bools, Floats, Ints

if TYPE_CHECKING:
    from mpl_toolkits.mplot3d import Axes3D

#: An artist drawn by scanline (one of :data:`KINDS`; mplot3d has no type hints).
Artist3D = Union[art3d.Poly3DCollection, art3d.Line3DCollection, art3d.Line3D,
                 art3d.Path3DCollection, art3d.Patch3D]
#: A line style as matplotlib's artists store it: a name, or (offset, dashes) with
#: dashes None for a solid line.
LineStyle = Union[str, Tuple[float, Optional[Sequence[float]]]]

#: The kinds of artist drawn by scanline, by class (subclasses too).
KINDS = ((art3d.Poly3DCollection, "polygons"), (art3d.Line3DCollection, "lines"),
         (art3d.Line3D, "line"), (art3d.Path3DCollection, "points"), (art3d.Patch3D, "patch"))


def kind_of(artist: Artist) -> Optional[str]:
    """``"polygons"``, ``"lines"``, ``"line"``, ``"points"``, ``"patch"`` or None (left
    to matplotlib): a Poly3DCollection whose paths carry codes (several subpaths, as
    ``contourf`` makes them) and a PathPatch3D of curves or several subpaths (text)
    are left to matplotlib."""
    for cls, kind in KINDS:
        if isinstance(artist, cls):
            if kind == "polygons" and getattr(artist, "_codes3d", None) is not None and len(
                    artist._codes3d):
                return None
            if kind == "patch" and not _simple_codes(getattr(artist, "_code3d", None)):
                return None
            return kind
    return None


def _simple_codes(codes: Optional[ArrayLike]) -> bool:
    """Whether path ``codes`` describe one polygon (None, or one MOVETO then LINETOs
    and perhaps CLOSEPOLY)."""
    if codes is None:
        return True
    a = np.asarray(codes)
    from matplotlib.path import Path

    return bool(len(a) and a[0] == Path.MOVETO and np.isin(
        a[1:], (Path.LINETO, Path.CLOSEPOLY)).all())


def shown(artist: Artist) -> bool:
    """Whether ``artist`` is visible, by its own flag (``get_visible`` of an adopted
    artist is replaced: see :func:`scanline.mpl.render_axes`)."""
    return Artist.get_visible(artist)


def _rgba(values: Any, n: int) -> Optional[Floats]:
    """(n, 4) float RGBA from matplotlib's color array of length 1 or n (0: None)."""
    c = mcolors.to_rgba_array(values) if len(values) else np.empty((0, 4))
    if len(c) == n:
        return c
    if len(c) == 1:
        return np.repeat(c, n, axis=0)
    if len(c) == 0:
        return None
    return np.resize(c, (n, 4))        # matplotlib cycles shorter property lists


def _per(values: ArrayLike, n: int, dtype: DTypeLike = np.float64) -> NDArray[Any]:
    """A per-item property of length 1 or n (cycled as matplotlib does) as n values."""
    a = np.asarray(values, dtype)
    if a.ndim == 0:
        a = a[None]
    if len(a) == n:
        return a
    if len(a) == 0:
        return np.zeros(n, dtype)
    return np.resize(a, n)


@dataclass
class Polygons:
    """World-space polygons of the adopted collections, padded: ``xyz`` (N, K, 3)
    with ``count`` (N,) vertices each (the rest repeat the last vertex), their face
    and edge colors (N, 4) (edges None: none drawn), edge widths (points) and
    antialiasing, and ``same_edge`` (N,) where the edge is drawn in the face's color
    (matplotlib's ``edgecolor="face"`` or equal colors)."""

    xyz: Floats
    count: Ints
    face: Floats
    edge: Floats
    width: Floats
    antialiased: Bools

    def __len__(self) -> int:
        return len(self.count)


def _faces_of(coll: "art3d.Poly3DCollection") -> Tuple[Floats, Ints]:
    """(N, K, 3) world vertices and (N,) counts of a Poly3DCollection (matplotlib >= 3.9
    keeps ``_faces`` and ``_invalid_vertices``; earlier ones ``_vec`` and
    ``_segslices``)."""
    if hasattr(coll, "_faces"):
        faces = np.asarray(coll._faces, np.float64)
        if faces.ndim != 3 or not faces.size:
            return np.empty((0, 3, 3)), np.empty(0, np.int64)
        invalid = np.broadcast_to(np.asarray(coll._invalid_vertices, bool), faces.shape[:2])
    else:                                             # matplotlib < 3.9
        vec = np.asarray(coll._vec, np.float64)
        slices = coll._segslices
        if not len(slices):
            return np.empty((0, 3, 3)), np.empty(0, np.int64)
        k = max(s.stop - s.start for s in slices)
        faces = np.zeros((len(slices), k, 3))
        invalid = np.ones((len(slices), k), bool)
        for i, s in enumerate(slices):
            faces[i, :s.stop - s.start] = vec[:3, s].T
            invalid[i, :s.stop - s.start] = False
    if not invalid.any():
        return faces, np.full(len(faces), faces.shape[1], np.int64)
    # the valid vertices first, in order, then the last valid one repeated
    order = np.argsort(invalid, axis=1, kind="stable")
    faces = np.take_along_axis(faces, order[:, :, None], axis=1)
    count = (~invalid).sum(axis=1).astype(np.int64)
    k = faces.shape[1]
    last = np.maximum(count - 1, 0)
    pad = np.arange(k)[None, :] >= count[:, None]
    if pad.any():
        faces = np.where(pad[:, :, None], faces[np.arange(len(faces)), last][:, None, :], faces)
    return faces, count


def polygons(coll: "art3d.Poly3DCollection") -> Polygons:
    """The polygons of one adopted Poly3DCollection, as matplotlib colors them now."""
    faces, count = _faces_of(coll)
    n = len(count)
    if getattr(coll, "_A", None) is not None:          # as do_3d_projection does
        coll.update_scalarmappable()
        if getattr(coll, "_face_is_mapped", False):
            coll._facecolor3d = coll._facecolors
        if getattr(coll, "_edge_is_mapped", False):
            coll._edgecolor3d = coll._edgecolors
    face = _rgba(coll._facecolor3d, n)
    if face is None:
        face = np.zeros((n, 4))
    edge_is_face = isinstance(coll._edgecolors, str) and coll._edgecolors == "face"
    edge = face.copy() if edge_is_face else _rgba(coll._edgecolor3d, n)
    width = _per(coll.get_linewidth(), n)
    if edge is None:
        edge = np.zeros((n, 4))
        width = np.zeros(n)
    return Polygons(faces, count, face, edge, width, _per(coll.get_antialiased(), n, bool))


def patch(artist: "art3d.Patch3D") -> Polygons:
    """The polygon of an adopted Patch3D (``ax.bar``'s bars, ``pathpatch_2d_to_3d``),
    with its colors (no face where it is not filled)."""
    xyz = np.array([tuple(p) for p in artist._segment3d], np.float64).reshape(-1, 3)
    codes = getattr(artist, "_code3d", None)
    if codes is not None and len(codes) == len(xyz):
        from matplotlib.path import Path

        xyz = xyz[np.asarray(codes) != Path.CLOSEPOLY]   # its vertex is not a point
    if len(xyz) > 1 and np.array_equal(xyz[0], xyz[-1]):
        xyz = xyz[:-1]                                   # closed by repeating the first
    n = len(xyz)
    face = np.array([mcolors.to_rgba(artist.get_facecolor())]) if artist.get_fill() else \
        np.zeros((1, 4))
    edge = np.array([mcolors.to_rgba(artist.get_edgecolor())])
    width = np.array([artist.get_linewidth() or 0.0])
    if n < 3:
        return Polygons(np.empty((0, 3, 3)), np.empty(0, np.int64), face[:0], edge[:0],
                        width[:0], np.empty(0, bool))
    return Polygons(xyz[None], np.array([n]), face, edge, width,
                    np.array([bool(artist.get_antialiased())]))


def markevery(line: "art3d.Line3D", n: int) -> Ints:
    """The indices of a Line3D's ``n`` points that carry markers (its ``markevery``:
    None, an int, an (int, int) pair, a slice, a list of indices or a mask; the
    fractions of the screen distance matplotlib also takes mark every point)."""
    every = line.get_markevery()
    idx = np.arange(n)
    if every is None:
        return idx
    if isinstance(every, (int, np.integer)) and not isinstance(every, bool):
        return idx[::max(int(every), 1)]
    if (isinstance(every, tuple) and len(every) == 2
            and all(isinstance(x, (int, np.integer)) for x in every)):
        return idx[int(every[0])::max(int(every[1]), 1)]
    if isinstance(every, slice):
        return idx[every]
    a = np.asarray(every)
    picked: Ints = idx
    if a.dtype == bool and a.shape == (n,):
        picked = idx[a]
    elif a.dtype.kind in "iu" and a.ndim == 1:
        picked = idx[a[(a >= -n) & (a < n)]]
    return picked


def line_data(line: "art3d.Line3D") -> Floats:
    """(V, 3) world points of a Line3D (NaN where masked)."""
    xs, ys, zs = (np.ma.filled(np.ma.asarray(a, np.float64).ravel(), np.nan)
                  for a in line.get_data_3d())
    n = min(len(xs), len(ys), len(zs))
    if n and (len(xs) != n or len(ys) != n or len(zs) != n):
        xs, ys, zs = (np.broadcast_to(a, n) if len(a) == 1 else a[:n] for a in (xs, ys, zs))
    return np.stack([xs[:n], ys[:n], zs[:n]], axis=1)


def collection_lines(coll: "art3d.Line3DCollection") -> List[Floats]:
    """The polylines of a Line3DCollection: a list of (N_i, 3) world arrays (NaN where
    masked)."""
    segs = coll._segments3d
    out: List[Floats] = []
    for s in segs:
        a = np.ma.filled(np.ma.asarray(s, np.float64), np.nan).reshape(-1, 3)
        out.append(a)
    return out


def line_colors(coll: "art3d.Line3DCollection", n: int
                ) -> Tuple[Floats, Floats, Bools, List[LineStyle]]:
    """Per-line RGBA, widths, antialiasing and line styles of a LineCollection."""
    if getattr(coll, "_A", None) is not None:
        coll.update_scalarmappable()
    color = _rgba(coll.get_edgecolor(), n)
    if color is None:
        color = np.zeros((n, 4))
    styles = coll.get_linestyle()
    styles = [styles[i % len(styles)] for i in range(n)] if len(styles) else [(0, None)] * n
    return color, _per(coll.get_linewidth(), n), _per(coll.get_antialiased(), n, bool), styles


def points(coll: "art3d.Path3DCollection", M: Floats
           ) -> Tuple[Floats, Floats, Floats, Floats, Floats]:
    """A Path3DCollection's markers: world offsets (N, 3) in matplotlib's drawing
    order (far to near) and, in that order, face and edge RGBA (depth-shaded as
    matplotlib shades them), sizes and line widths.  Runs the collection's own
    ``do_3d_projection`` (which reads ``coll.axes.M``) for the colors."""
    xs, ys, zs = (np.ma.filled(np.ma.asarray(a, np.float64).ravel(), np.nan)
                  for a in coll._offsets3d)
    n = max(len(xs), len(ys), len(zs))
    xs, ys, zs = (np.broadcast_to(a, n) if len(a) == 1 else a for a in (xs, ys, zs))
    xyz = np.stack([xs, ys, zs], axis=1)
    if not n:
        return xyz, np.zeros((0, 4)), np.zeros((0, 4)), np.zeros(0), np.zeros(0)
    coll.do_3d_projection()
    order = getattr(coll, "_z_markers_idx", None)
    order = np.arange(n) if not isinstance(order, np.ndarray) or len(order) != n else order
    face = _rgba(coll.get_facecolor(), n)
    edge = _rgba(coll.get_edgecolor(), n)
    face = np.zeros((n, 4)) if face is None else face
    edge = np.zeros((n, 4)) if edge is None else edge
    sizes = _per(coll._sizes if len(coll._sizes) else [0.0], n)
    widths = _per(coll._linewidths if len(coll._linewidths) else [0.0], n)
    return xyz[order], face, edge, sizes, widths


def project(ax: "Axes3D", M: ArrayLike, xyz: ArrayLike) -> Floats:
    """Project world points ``xyz`` (..., 3) by the axes' scales and matrix ``M``:
    (..., 3) of matplotlib's projected x, y (the axes' 2-D data coordinates) and
    depth (greater: farther; matplotlib paints the greatest first)."""
    xyz = np.asarray(xyz, np.float64)
    flat = xyz.reshape(-1, 3)
    axes = (ax.xaxis, ax.yaxis, ax.zaxis)
    if any(a.get_scale() != "linear" for a in axes):
        flat = flat.copy()
        with np.errstate(invalid="ignore", divide="ignore"):
            for j, a in enumerate(axes):
                if a.get_scale() != "linear":
                    col = a.get_transform().transform(flat[:, j])
                    ok = a._scale.val_in_range(flat[:, j]) if hasattr(
                        a._scale, "val_in_range") else np.isfinite(col)
                    flat[:, j] = np.where(ok, col, np.nan)
    M = np.asarray(M, np.float64)
    with np.errstate(invalid="ignore", divide="ignore"):
        h = flat @ M[:, :3].T + M[:, 3]
        p: Floats = h[:, :3] / h[:, 3:4]
    return p.reshape(xyz.shape)


def to_display(ax: "Axes3D", p: Floats) -> Floats:
    """Display coordinates (pixels of the canvas, y up; points for vector backends) of
    projected points ``p`` (..., 3): x, y through ``ax.transData``, depth kept."""
    flat = p.reshape(-1, 3)
    out = np.empty_like(flat)
    if ax.transData.is_affine:              # (an Axes3D's 2-D transform is affine)
        A = ax.transData.get_affine().get_matrix()
        out[:, 0] = A[0, 0] * flat[:, 0] + A[0, 1] * flat[:, 1] + A[0, 2]
        out[:, 1] = A[1, 0] * flat[:, 0] + A[1, 1] * flat[:, 1] + A[1, 2]
    else:
        ok = np.isfinite(flat[:, 0]) & np.isfinite(flat[:, 1])
        out[:, :2] = np.nan
        if ok.any():
            out[ok, :2] = ax.transData.transform(flat[ok, :2])
    out[:, 2] = flat[:, 2]
    return out.reshape(p.shape)


def outside_limits(ax: "Axes3D", xyz: Floats) -> Bools:
    """Whether each world point (..., 3) lies outside the axes' view limits (for the
    artists made with ``axlim_clip=True``)."""
    x0, x1 = sorted(ax.get_xlim())
    y0, y1 = sorted(ax.get_ylim())
    z0, z1 = sorted(ax.get_zlim())
    x, y, z = xyz[..., 0], xyz[..., 1], xyz[..., 2]
    outside: Bools = (x < x0) | (x > x1) | (y < y0) | (y > y1) | (z < z0) | (z > z1)
    return outside
