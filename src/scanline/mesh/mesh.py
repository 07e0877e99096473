"""The polygon mesh: a vertex list and polygon faces (Hearn & Baker, section 10-1,
"polygon surfaces").

Faces are polygons of any number (>= 3) of vertex indices, counterclockwise seen
from outside (then the plane equations' normals point outward).  They are stored
flat -- ``face_indices`` with ``face_offsets`` -- so that meshes of millions of
faces stay arrays; :attr:`Mesh.faces` gives them back as an (F, n) array when all
faces have n vertices, else as a list.
"""

import os
from collections.abc import Iterable, Sized
from typing import TYPE_CHECKING, List, Literal, Optional, Protocol, Tuple, TypedDict, TypeVar, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._typing import Color

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..transform3d.arrays import finite, real_array

if TYPE_CHECKING:
    from .materials import MaterialRecord
    from .tables import PolygonTables

#: Default tolerance of the planarity test, relative to a face's size.
PLANAR_TOLERANCE = 1e-9


class Flat:
    """Faces already in flat form -- ``indices`` (K,) and ``sizes`` (F,), int64 --
    as the generators make them: :class:`Mesh` checks them with array operations
    only (no per-face Python), so a generated mesh of millions of faces is built in
    time proportional to numpy's work."""

    __slots__ = ("indices", "sizes")

    def __init__(self, indices: ArrayLike, sizes: ArrayLike) -> None:
        self.indices = np.ascontiguousarray(indices, np.int64).reshape(-1)
        self.sizes = np.ascontiguousarray(sizes, np.int64).reshape(-1)


class SurfaceMaterial(Protocol):
    """What a mesh's material offers: the reflection coefficients and color of Hearn
    & Baker section 14-2 (:class:`scanline.lighting.Material` has them; geometry names no
    lighting class, docs/architecture.md)."""

    @property
    def ka(self) -> float: ...
    @property
    def kd(self) -> float: ...
    @property
    def ks(self) -> float: ...
    @property
    def shininess(self) -> float: ...
    @property
    def color(self) -> NDArray[np.float64]: ...


class MeshOptions(TypedDict, total=False):
    """The keywords of :class:`Mesh` that the generators (:func:`~scanline.mesh.sphere`,
    :func:`~scanline.mesh.sweep` ...) pass on to it."""
    colors: Union[Color, ArrayLike, None]
    color_on: Optional[Literal["face", "vertex"]]
    name: Optional[str]
    uv: Optional[ArrayLike]
    material: Union["SurfaceMaterial", "MaterialRecord", None]


#: Bytes of memory a mesh takes per vertex, per face and per face index while it
#: is made and checked (positions, normals, the index arrays, and the temporaries of
#: the checks and of a generator's formulas: measured on the generators, rounded
#: up).  The memory budget (:mod:`scanline.budget`) is checked against
#: :func:`mesh_bytes` before a generator allocates.
BYTES_PER_VERTEX = 400
BYTES_PER_FACE = 64
BYTES_PER_INDEX = 80


def mesh_bytes(n_vertices: int, n_faces: int, n_indices: int) -> int:
    """The estimated peak bytes of making a mesh of ``n_vertices`` vertices and
    ``n_faces`` faces holding ``n_indices`` vertex indices together (Python ints:
    exact at any size)."""
    return (int(n_vertices) * BYTES_PER_VERTEX + int(n_faces) * BYTES_PER_FACE
            + int(n_indices) * BYTES_PER_INDEX)


def check_mesh_budget(argument: str, n_vertices: int, n_faces: int, n_indices: int, what: str,
                      hint: Optional[str] = None) -> None:
    """Refuse, before anything is allocated, a mesh whose :func:`mesh_bytes` passes
    the memory budget: a :class:`~scanline.errors.MemoryBudgetError` naming
    ``argument`` (the argument that sets the size)."""
    from .. import budget

    budget.check(mesh_bytes(n_vertices, n_faces, n_indices), argument,
                 f"{what} ({int(n_vertices):,} vertices, {int(n_faces):,} faces)",
                 hint=hint or f"give a smaller {argument}")


def _flat_faces(faces: object, n_vertices: int
                ) -> Tuple[NDArray[np.int64], NDArray[np.int64]]:
    """``(indices, offsets)`` of faces given as an (F, n) array, a list of index
    sequences or a :class:`Flat`, checked: integers in range, at least three per
    face, none repeated within a face."""
    top = max(n_vertices - 1, 0)
    bound = f" (larger is out of range: the mesh has {n_vertices} vertices)"
    if isinstance(faces, Flat):
        indices, sizes = faces.indices, faces.sizes
        if (sizes < 0).any() or v.exact_sum(sizes) != len(indices):
            raise ArgumentValueError("faces: the face sizes do not add up to the indices given")
        offsets = np.zeros(len(sizes) + 1, np.int64)
        np.cumsum(sizes, out=offsets[1:])
    elif isinstance(faces, np.ndarray) and faces.ndim == 2 and faces.size:
        arr = v.index_array("faces", faces, shape=(None, None), high=top, bound_text=bound,
                            what="an (F, n) integer array of vertex indices")
        indices = arr.reshape(-1)
        offsets = np.arange(0, arr.size + 1, max(arr.shape[1], 1), dtype=np.int64)[:len(arr) + 1]
        sizes = np.full(len(arr), arr.shape[1])
    else:
        if isinstance(faces, (str, bytes)) or not hasattr(faces, "__len__") \
                or not hasattr(faces, "__iter__") or (isinstance(faces, np.ndarray)
                                                      and faces.ndim == 0):
            raise ArgumentTypeError(
                f"faces must be an (F, n) array or a list of vertex-index lists, got "
                f"{v._show(faces)}")
        parts = []
        for i, f in enumerate(faces):
            parts.append(v.index_array(f"faces[{i}]", f, high=top, bound_text=bound,
                                       what="a list of integer vertex indices"))
        sizes = np.array([len(p) for p in parts], np.int64)
        indices = np.concatenate(parts) if parts else np.zeros(0, np.int64)
        offsets = np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)
    if len(sizes) == 0:
        raise ArgumentValueError("a mesh needs at least one face; got none (an empty mesh "
                                 "has nothing to draw or to check)")
    small = np.flatnonzero(sizes < 3)
    if len(small):
        raise ArgumentValueError(
            f"face {int(small[0])} has {int(sizes[small[0]])} vertices; a polygon face needs "
            "at least 3")
    bad = np.flatnonzero((indices < 0) | (indices >= n_vertices))
    if len(bad):
        face = int(np.searchsorted(offsets, bad[0], side="right") - 1)
        raise ArgumentValueError(
            f"face {face} refers to vertex {int(indices[bad[0]])}, out of range: the mesh "
            f"has {n_vertices} vertices (indices 0 to {n_vertices - 1})")
    face = _repeated_vertex(indices, sizes, offsets, n_vertices)
    if face >= 0:
        raise ArgumentValueError(
            f"face {face} repeats a vertex ({indices[offsets[face]:offsets[face + 1]].tolist()}): "
            "a polygon face visits each vertex once")
    return np.ascontiguousarray(indices), offsets


#: Faces of at most this many vertices are checked for a repeated vertex by comparing
#: each corner with the next ones (n - 1 array comparisons); larger ones by sorting.
PAIRWISE_CHECK = 8


def _repeated_vertex(indices: NDArray[np.int64], sizes: NDArray[np.int64],
                     offsets: NDArray[np.int64], n_vertices: int) -> int:
    """The first face that visits a vertex twice, or -1."""
    most = int(sizes.max())
    if most <= PAIRWISE_CHECK and int(sizes.min()) == most:     # all of one size: columns
        table = indices.reshape(-1, most)
        bad = np.zeros(len(table), bool)
        for i in range(most):
            for j in range(i + 1, most):
                bad |= table[:, i] == table[:, j]
        return int(np.argmax(bad)) if bad.any() else -1
    if most <= PAIRWISE_CHECK:
        # corner q and corner q + d of the same face (d < the face's size - its place)
        place = np.arange(len(indices), dtype=np.int64) - np.repeat(offsets[:-1], sizes)
        left = np.repeat(sizes, sizes) - place
        first = len(sizes)
        for d in range(1, most):
            q = np.flatnonzero((left[:-d] > d) & (indices[:-d] == indices[d:])) \
                if d < len(indices) else np.zeros(0, np.int64)
            if len(q):
                first = min(first, int(np.searchsorted(offsets, q[0], side="right") - 1))
        return first if first < len(sizes) else -1
    owner = np.repeat(np.arange(len(sizes), dtype=np.int64), sizes)
    # one key per (face, vertex) pair: a vertex repeated within a face repeats a key
    # (len(sizes) * n_vertices stays far below 2**63 for any mesh that fits in memory)
    keys = owner * max(n_vertices, 1) + indices
    keys.sort()
    dup = keys[1:] == keys[:-1]
    return int(keys[1:][np.argmax(dup)] // max(n_vertices, 1)) if dup.any() else -1


def _colors(name: str, colors: Iterable[object], count: int) -> NDArray[np.uint8]:
    """(count, 4) uint8 RGBA from one color spec per item (or an (count, 3|4) array)."""
    from ..color.spec import rgba

    if isinstance(colors, np.ndarray) and colors.ndim == 2 and colors.shape[1] in (3, 4) \
            and colors.dtype.kind in "iu":
        if (colors < 0).any() or (colors > 255).any():
            raise ArgumentValueError(f"{name} values must be in 0..255")
        out = np.full((len(colors), 4), 255, np.uint8)
        out[:, :colors.shape[1]] = colors
        return out
    return np.array([rgba(c if not isinstance(c, np.ndarray) else tuple(c.tolist()),
                          f"{name}[{i}]") for i, c in enumerate(colors)], np.uint8).reshape(-1, 4)


_M = TypeVar("_M")


def _material(material: _M) -> _M:
    """``material`` checked: None, a :class:`scanline.lighting.Material` (recognized
    by its coefficients: geometry does not import the lighting, docs/architecture.md)
    or a mesh file's :class:`~scanline.mesh.materials.MaterialRecord`."""
    from .materials import MaterialRecord

    if material is None or isinstance(material, MaterialRecord):
        return material
    if not all(hasattr(material, k) for k in ("ka", "kd", "ks", "shininess", "color")):
        raise ArgumentTypeError(f"material must be a scanline.lighting.Material, a "
                                f"scanline.mesh.MaterialRecord or None, got {v._show(material)}")
    return material


class Mesh:
    """A polygon mesh.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
        Finite vertex positions.
    faces : (F, n) array_like of int, or list of index lists
        Polygons of at least three distinct vertex indices each, counterclockwise
        seen from outside.
    colors : optional
        One color per face (F of them) or per vertex (V): color specs (``"red"``,
        ``(r, g, b)``) or an (F|V, 3|4) integer array.  When F == V, ``color_on``
        says which is meant.
    normals : array_like, shape (V, 3), optional
        Vertex normals (the generators give the exact ones of their surfaces).
    color_on : {"face", "vertex"}, optional
    name : str, optional
    uv : array_like, shape (V, 2), optional
        Texture coordinates (u, v) of each vertex (Hearn & Baker 14-9), as OBJ's ``vt``
        and glTF's ``TEXCOORD_0`` give them; v = 0 is the bottom of the image.
    material : scanline.lighting.Material or scanline.mesh.MaterialRecord, optional
        The surface's material, used by :func:`scanline.render` when it is given no
        ``materials`` (a mesh file's ``usemtl`` or glTF material arrives as a
        :class:`~scanline.mesh.materials.MaterialRecord`, which the render converts).

    Examples
    --------
    >>> import scanline as sl
    >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
    >>> square
    <Mesh: 4 vertices, 1 faces, 4 edges>
    >>> square.plane_equations().tolist()
    [[0.0, 0.0, 2.0, 0.0]]
    """

    vertices: NDArray[np.float64]
    face_indices: NDArray[np.int64]
    face_offsets: NDArray[np.int64]
    normals: Optional[NDArray[np.float64]]
    colors: Optional[NDArray[np.uint8]]
    color_on: Optional[Literal["face", "vertex"]]
    uv: Optional[NDArray[np.float64]]
    material: Union["SurfaceMaterial", "MaterialRecord", None]
    name: Optional[str]
    _edges: Optional[NDArray[np.int64]]

    def __init__(self, vertices: ArrayLike, faces: Union[ArrayLike, "Flat"],
                 colors: Union[Color, ArrayLike, None] = None, normals: Optional[ArrayLike] = None,
                 color_on: Optional[Literal["face", "vertex"]] = None, name: Optional[str] = None,
                 uv: Optional[ArrayLike] = None,
                 material: Union["SurfaceMaterial", "MaterialRecord", None] = None) -> None:
        verts = real_array("vertices", vertices, "(V, 3)")
        if verts.ndim == 1 and verts.size == 0:
            verts = verts.reshape(0, 3)
        if verts.ndim != 2 or verts.shape[1] != 3:
            raise ArgumentValueError(
                f"vertices must have shape (V, 3), got shape {verts.shape}")
        self.vertices = finite("vertices", np.array(verts, order="C"))    # a copy
        self.face_indices, self.face_offsets = _flat_faces(faces, len(verts))
        self.normals = None
        if normals is not None:
            nrm = finite("normals", real_array("normals", normals, "(V, 3)"))
            if nrm.shape != self.vertices.shape:
                raise ArgumentValueError(
                    f"normals must have one row per vertex, shape {self.vertices.shape}, got "
                    f"{nrm.shape}")
            self.normals = np.array(nrm, order="C")
        self.colors, self.color_on = None, None
        if colors is not None:
            self._set_colors(colors, color_on)
        self.uv = None
        if uv is not None:
            tex = finite("uv", real_array("uv", uv, "(V, 2)"))
            if tex.shape != (len(self.vertices), 2):
                raise ArgumentValueError(
                    f"uv must have one (u, v) row per vertex, shape ({len(self.vertices)}, 2), "
                    f"got {tex.shape}")
            self.uv = np.array(tex, np.float64, order="C")
        self.material = _material(material)
        self.name = name
        self._edges = None

    def _set_colors(self, colors: object, color_on: Optional[str]) -> None:
        nf, nv = self.face_count, len(self.vertices)
        if isinstance(colors, (str, tuple)) or (isinstance(colors, int)
                                                and not isinstance(colors, bool)):
            colors = [colors] * nf
            color_on = "face"
        if isinstance(colors, (bytes, dict)) or not isinstance(colors, Sized) \
                or not isinstance(colors, Iterable) or (isinstance(colors, np.ndarray)
                                                        and colors.ndim == 0):
            raise ArgumentTypeError(
                f"colors must be one color (a name or (r, g, b)) or one color per face or per "
                f"vertex, got {v._show(colors)}")
        n = len(colors)
        if color_on is None:
            if n == nf:
                color_on = "face"
            elif n == nv:
                color_on = "vertex"
        else:
            v.choice("color_on", color_on, ("face", "vertex"))
        if color_on is None or n != (nf if color_on == "face" else nv):
            raise ArgumentValueError(
                f"colors holds {n} colors; give one per face ({nf}) or one per vertex ({nv})")
        self.colors = _colors("colors", colors, n)
        self.color_on = "face" if color_on == "face" else "vertex"

    # -- structure ------------------------------------------------------------------------
    @property
    def face_count(self) -> int:
        """The number of faces, F.

        Returns
        -------
        int

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> square.face_count
        1
        """
        return len(self.face_offsets) - 1

    @property
    def face_sizes(self) -> NDArray[np.int64]:
        """The number of vertices of each face, (F,) int64.

        Returns
        -------
        numpy.ndarray

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> square.face_sizes.tolist()
        [4]
        """
        return np.diff(self.face_offsets)

    def face(self, i: int) -> NDArray[np.int64]:
        """The vertex indices of face ``i`` (negative: counted from the end).

        Parameters
        ----------
        i : int
            A face number, 0 to F - 1, or -F to -1 counted from the end.

        Returns
        -------
        numpy.ndarray
            The face's vertex indices, (n,) int64, in their counterclockwise order.

        Raises
        ------
        ArgumentTypeError
            If ``i`` is not an integer.
        ArgumentValueError
            If ``i`` is not a face number of this mesh.

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> square.face(-1).tolist()
        [0, 1, 2, 3]
        """
        n = self.face_count
        if isinstance(i, (bool, np.bool_)) or not isinstance(i, (int, np.integer)):
            raise ArgumentTypeError(f"i must be an integer face number, got {v._show(i)}")
        if not -n <= i < n:
            raise ArgumentValueError(f"i={i} is not a face number: the mesh has {n} faces "
                                     f"(0 to {n - 1}, or -{n} to -1 from the end)")
        i = int(i) % n
        return self.face_indices[self.face_offsets[i]:self.face_offsets[i + 1]]

    @property
    def faces(self) -> Union[NDArray[np.int64], List[NDArray[np.int64]]]:
        """The faces: an (F, n) int64 array when every face has n vertices, else a
        list of index arrays.

        Returns
        -------
        numpy.ndarray or list of numpy.ndarray

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> square.faces.tolist()
        [[0, 1, 2, 3]]
        """
        sizes = self.face_sizes
        if (sizes == sizes[0]).all():
            return self.face_indices.reshape(-1, int(sizes[0]))
        return [self.face(i) for i in range(self.face_count)]

    def _half_edges(self) -> Tuple[NDArray[np.int64], NDArray[np.int64]]:
        """Every face edge (a, b) in face order, (K, 2), and the face of each."""
        idx, off = self.face_indices, self.face_offsets
        nxt = np.arange(1, len(idx) + 1)
        nxt[off[1:] - 1] = off[:-1]
        owner = np.repeat(np.arange(self.face_count), self.face_sizes)
        return np.stack([idx, idx[nxt]], axis=1), owner

    @property
    def edges(self) -> NDArray[np.int64]:
        """The distinct edges, (E, 2) int64, each (i, j) with i < j, sorted.  Computed
        once (the edge table of :meth:`polygon_tables`).

        Returns
        -------
        numpy.ndarray

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> square.edges.tolist()
        [[0, 1], [0, 3], [1, 2], [2, 3]]
        """
        if self._edges is None:
            half, _ = self._half_edges()
            self._edges = np.unique(np.sort(half, axis=1), axis=0)
        return self._edges

    def edge_faces(self) -> Tuple[NDArray[np.int64], NDArray[np.int64]]:
        """For each edge of :attr:`edges`, the faces it borders: an (E, 2) array, -1
        where an edge borders one face only, and the count of faces per edge.

        Returns
        -------
        faces : numpy.ndarray
            (E, 2) int64: the first two faces bordering each edge, -1 where none.
        count : numpy.ndarray
            (E,) int64: how many faces border each edge.

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> pairs, count = square.edge_faces()
        >>> pairs.tolist(), count.tolist()
        ([[0, -1], [0, -1], [0, -1], [0, -1]], [1, 1, 1, 1])
        """
        half, owner = self._half_edges()
        key = np.sort(half, axis=1)
        edges = self.edges
        which = _rows_in(edges, key)
        count = np.bincount(which, minlength=len(edges))
        first = np.full(len(edges), -1, np.int64)
        second = np.full(len(edges), -1, np.int64)
        order = np.argsort(which, kind="stable")
        starts = np.concatenate([[0], np.cumsum(count)[:-1]])
        first[:] = owner[order[starts]] if len(order) else first
        has2 = count >= 2
        second[has2] = owner[order[starts[has2] + 1]]
        return np.stack([first, second], axis=1), count

    def __len__(self) -> int:
        return self.face_count

    def __repr__(self) -> str:
        name = f" {self.name!r}" if self.name else ""
        return (f"<Mesh{name}: {len(self.vertices)} vertices, {self.face_count} faces, "
                f"{len(self.edges)} edges>")

    # -- geometry ---------------------------------------------------------------------------
    def plane_equations(self, tolerance: float = PLANAR_TOLERANCE) -> NDArray[np.float64]:
        """The plane coefficients (A, B, C, D) of each face, (F, 4).

        (A, B, C) is Newell's normal, Σ over the face's edges (i, j = i + 1) of
        ((y_i - y_j)(z_i + z_j), (z_i - z_j)(x_i + x_j), (x_i - x_j)(y_i + y_j)),
        and D = -(A x̄ + B ȳ + C z̄) at the face's centroid.  For a triangle this is
        Hearn & Baker's A = y1 (z2 - z3) + y2 (z3 - z1) + y3 (z1 - z2), B = ..., C =
        ..., D = -x1 (y2 z3 - y3 z2) - x2 (y3 z1 - y1 z3) - x3 (y1 z2 - y2 z1) (twice
        the triangle's area as the normal's length); for a polygon it is twice the
        area vector, exact for planar faces and least-squares for slightly bent
        ones.  Faces counterclockwise seen from outside give outward normals: a point
        (x, y, z) is inside (behind) the plane when A x + B y + C z + D < 0 and in
        front when > 0.

        Parameters
        ----------
        tolerance : float, optional
            The largest distance of a vertex from its face's plane, relative to the
            face's size (>= 0).

        Returns
        -------
        numpy.ndarray
            (F, 4) float64: (A, B, C, D) of each face.

        Raises
        ------
        ArgumentValueError
            If a face is degenerate (zero area: its vertices on a line) or not planar
            (a vertex farther from the plane than ``tolerance`` times the face's
            size).

        Notes
        -----
        Hearn & Baker, section 10-1, "plane equations" (eqs. 10-1 to 10-5).  Newell's
        method is Sutherland, Sproull and Schumacker's (1974) for polygons with more
        than three vertices.

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> square.plane_equations().tolist()
        [[0.0, 0.0, 2.0, 0.0]]
        """
        t = v.number("tolerance", tolerance)
        if t < 0:
            raise ArgumentValueError(f"tolerance must be >= 0 (relative to a face's size), got "
                                     f"{tolerance!r}")
        with np.errstate(over="ignore", invalid="ignore"):
            planes = _newell(self.vertices, self.face_indices, self.face_offsets)
            length = np.sqrt((planes[:, :3] ** 2).sum(axis=1))
        if not np.isfinite(planes).all():
            f = int(np.argmax(~np.isfinite(planes).all(axis=1)))
            raise ArgumentValueError(
                f"face {f} ({self.face(f).tolist()}) is too large for its plane equation: its "
                "coefficients overflow float64 (coordinates near 1e154 or beyond); scale the "
                "mesh down")
        size = _face_sizes(self.vertices, self.face_indices, self.face_offsets)
        flat = ~(length > 1e-14 * np.maximum(size, 1e-300) ** 2)
        if flat.any():
            f = int(np.argmax(flat))
            raise ArgumentValueError(
                f"face {f} ({self.face(f).tolist()}) is degenerate: its vertices lie on a "
                "line (zero area), so it has no plane equation")
        dist = self.planarity(planes)
        bent = dist > t * size
        if bent.any():
            f = int(np.argmax(bent / np.maximum(size, 1e-300)))
            raise ArgumentValueError(
                f"face {f} ({self.face(f).tolist()}) is not planar: a vertex lies "
                f"{dist[f]:.3g} from its plane (face size {size[f]:.3g}); split it into "
                "triangles (Mesh.triangulated()) or pass a larger tolerance")
        return planes + 0.0

    def planarity(self, planes: Optional[NDArray[np.float64]] = None) -> NDArray[np.float64]:
        """Each face's largest vertex distance from its (Newell) plane, (F,).

        Parameters
        ----------
        planes : numpy.ndarray, shape (F, 4), optional
            The faces' planes (A, B, C, D); Newell's planes when None.

        Returns
        -------
        numpy.ndarray
            (F,) float64 distances (0 for a degenerate face).

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> square.planarity().tolist()
        [0.0]
        """
        if planes is None:
            planes = _newell(self.vertices, self.face_indices, self.face_offsets)
        length = np.sqrt((planes[:, :3] ** 2).sum(axis=1))
        owner = np.repeat(np.arange(self.face_count), self.face_sizes)
        p = self.vertices[self.face_indices]
        with np.errstate(divide="ignore", invalid="ignore"):
            d = np.abs((p * planes[owner, :3]).sum(axis=1) + planes[owner, 3]) / length[owner]
        out = np.zeros(self.face_count)
        np.maximum.at(out, owner, np.nan_to_num(d, nan=0.0))
        return out

    def face_normals(self) -> NDArray[np.float64]:
        """Unit outward normals of the faces, (F, 3).

        Returns
        -------
        numpy.ndarray
            (F, 3) float64: each face's plane normal (A, B, C) scaled to length 1.

        Raises
        ------
        ArgumentValueError
            If a face is degenerate or not planar (see :meth:`plane_equations`).

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> square.face_normals().tolist()
        [[0.0, 0.0, 1.0]]
        """
        p = self.plane_equations()[:, :3]
        unit: NDArray[np.float64] = p / np.sqrt((p * p).sum(axis=1))[:, None]
        return unit

    def inside(self, points: ArrayLike) -> Union[bool, NDArray[np.bool_]]:
        """Whether each point is inside the mesh, by Hearn & Baker's test: behind
        every face plane (A x + B y + C z + D < 0).  Exact for closed convex meshes.

        Parameters
        ----------
        points : array_like, shape (3,) or (N, 3)
            One point (x, y, z) or N of them.

        Returns
        -------
        bool or numpy.ndarray
            A bool for one point, else an (N,) bool array.

        Raises
        ------
        ArgumentValueError
            If a face is degenerate or not planar (see :meth:`plane_equations`).

        Notes
        -----
        Hearn & Baker, section 10-1, "plane equations".

        Examples
        --------
        The square's plane is 2 z = 0, its normal +z: below it is behind.

        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> square.inside((0.5, 0.5, -1))
        True
        >>> square.inside([(0, 0, -1), (0, 0, 1)]).tolist()
        [True, False]
        """
        from ..transform3d.arrays import points as point_array

        p, single = point_array("points", points)
        planes = self.plane_equations()
        inside = (p @ planes[:, :3].T + planes[:, 3] < 0).all(axis=1)
        return bool(inside[0]) if single else inside

    @property
    def bounds(self) -> Tuple[NDArray[np.float64], NDArray[np.float64]]:
        """``(lo, hi)``: the corners of the bounding box, two (3,) arrays.

        Returns
        -------
        tuple of numpy.ndarray

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> [corner.tolist() for corner in square.bounds]
        [[0.0, 0.0, 0.0], [1.0, 1.0, 0.0]]
        """
        return self.vertices.min(axis=0), self.vertices.max(axis=0)

    def polygon_tables(self) -> "PolygonTables":
        """Hearn & Baker's polygon tables of this mesh (:class:`PolygonTables`).

        Returns
        -------
        PolygonTables

        Notes
        -----
        Hearn & Baker, section 10-1, "polygon tables".

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> square.polygon_tables()
        <PolygonTables: 4 vertices, 4 edges, 1 surfaces>
        """
        from .tables import PolygonTables

        return PolygonTables.from_mesh(self)

    # -- new meshes -------------------------------------------------------------------------
    def _like(self, vertices: NDArray[np.float64],
              normals: Optional[NDArray[np.float64]] = None) -> "Mesh":
        new = object.__new__(Mesh)
        new.__dict__.update(self.__dict__)
        new.vertices = np.ascontiguousarray(vertices)
        new.normals = normals
        return new

    def transformed(self, matrix: ArrayLike) -> "Mesh":
        """This mesh moved by a 4x4 transformation (:mod:`scanline.transform3d`);
        normals follow by the inverse transpose of its linear part.  A reflection
        turns the faces inside out, so their order is reversed to stay
        counterclockwise from outside.

        Parameters
        ----------
        matrix : array_like, shape (4, 4)
            A homogeneous transformation (or what :func:`scanline.transform3d.compose`
            takes).

        Returns
        -------
        Mesh
            A new mesh; this one is unchanged.

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> up = square.transformed(sl.transform3d.translation(0, 0, 5))
        >>> up.vertices[:, 2].tolist()
        [5.0, 5.0, 5.0, 5.0]
        """
        from .. import transform3d as t3

        m = t3.compose(matrix)
        verts = t3.apply(m, self.vertices)
        normals = None
        with np.errstate(all="ignore"):
            det = np.linalg.det(m[:3, :3])
            if self.normals is not None:
                try:
                    lin = np.linalg.inv(m[:3, :3]).T if abs(det) > 0 else m[:3, :3]
                except np.linalg.LinAlgError:      # singular after all: flattens space
                    lin = m[:3, :3]
                n = self.normals @ lin.T
                normals = n / np.maximum(np.sqrt((n * n).sum(axis=1)), 1e-300)[:, None]
                if not np.isfinite(normals).all():     # the squares overflowed: rescale
                    n = n / np.abs(n).max(axis=1, initial=1e-300)[:, None]
                    normals = n / np.maximum(np.sqrt((n * n).sum(axis=1)), 1e-300)[:, None]
                if not np.isfinite(normals).all():
                    normals = None     # a transformation too degenerate to carry normals
        new = self._like(verts, normals)
        if det < 0:
            new.face_indices = _reversed_faces(self.face_indices, self.face_offsets)
        return new

    def translated(self, offset: ArrayLike) -> "Mesh":
        """This mesh moved by ``offset`` (dx, dy, dz).

        Parameters
        ----------
        offset : array_like, shape (3,)
            The displacement (dx, dy, dz).

        Returns
        -------
        Mesh
            A new mesh; this one is unchanged.

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> square.translated((1, 2, 3)).bounds[0].tolist()
        [1.0, 2.0, 3.0]
        """
        from .. import transform3d as t3
        from ..transform3d.arrays import vector

        return self.transformed(t3.translation(*vector("offset", offset)))

    def colored(self, colors: Union[Color, ArrayLike],
                color_on: Optional[Literal["face", "vertex"]] = None) -> "Mesh":
        """A copy with other colors (see the constructor).

        Parameters
        ----------
        colors : color or sequence of colors or array_like
            One color for every face, or one per face or per vertex.
        color_on : {"face", "vertex"}, optional
            Which elements the colors belong to, when F == V.

        Returns
        -------
        Mesh
            A new mesh; this one is unchanged.

        Raises
        ------
        ArgumentValueError
            If the number of colors is neither F nor V.

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> red = square.colored("red")
        >>> red.colors.tolist(), red.color_on
        ([[255, 0, 0, 255]], 'face')
        """
        new = self._like(self.vertices, self.normals)
        new._set_colors(colors, color_on)
        return new

    def triangulated(self) -> "Mesh":
        """The mesh with every face split into a fan of triangles from its first
        vertex (exact for convex faces); face colors go to each face's triangles.

        Returns
        -------
        Mesh
            A new mesh of triangles; this one is unchanged.

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> square.triangulated().faces.tolist()
        [[0, 1, 2], [0, 2, 3]]
        """
        idx, off = self.face_indices, self.face_offsets
        sizes = self.face_sizes
        tri_per = sizes - 2
        owner = np.repeat(np.arange(self.face_count), tri_per)
        k = np.arange(len(owner)) - np.repeat(np.cumsum(tri_per) - tri_per, tri_per)
        first = off[owner]
        tris = np.stack([idx[first], idx[first + k + 1], idx[first + k + 2]], axis=1)
        new = self._like(self.vertices, self.normals)
        new.face_indices = np.ascontiguousarray(tris.reshape(-1))
        new.face_offsets = np.arange(0, 3 * len(tris) + 1, 3, dtype=np.int64)
        new._edges = None
        if self.colors is not None and self.color_on == "face":
            new.colors = self.colors[owner]
        return new

    @staticmethod
    def from_any(obj: object, name: Optional[str] = None) -> "Mesh":
        """A mesh of ``obj``: a trimesh ``Trimesh`` or ``Scene``, a meshio ``Mesh``, an
        Open3D ``TriangleMesh`` or any object with ``vertices`` and ``faces`` arrays
        (their normals, colors and uv where they have them); a Mesh as it is.  The
        packages are not imported unless ``obj`` is theirs
        (:func:`scanline.mesh.convert.from_any`).

        Parameters
        ----------
        obj : object
            The mesh-like object.
        name : str, optional
            The new mesh's name.

        Returns
        -------
        Mesh

        Examples
        --------
        >>> import types, scanline as sl
        >>> sl.mesh.Mesh.from_any(types.SimpleNamespace(
        ...     vertices=[(0, 0, 0), (1, 0, 0), (0, 1, 0)], faces=[(0, 1, 2)]))
        <Mesh: 3 vertices, 1 faces, 3 edges>
        """
        from .convert import from_any

        return from_any(obj, name)

    def save(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Write the mesh to an OBJ, PLY, STL, glTF or GLB file (see
        :func:`scanline.mesh.save`).

        Parameters
        ----------
        path : str or os.PathLike
            The file; its extension chooses the format.

        Returns
        -------
        None

        Examples
        --------
        >>> import os, tempfile
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> path = os.path.join(tempfile.mkdtemp(), "square.obj")
        >>> square.save(path)
        >>> sl.mesh.load(path).faces.tolist()
        [[0, 1, 2, 3]]
        """
        from .files import save

        save(self, path)


def _rows_in(table: NDArray[np.int64], rows: NDArray[np.int64]) -> NDArray[np.intp]:
    """For each row of ``rows`` (K, 2), its index in the sorted unique ``table``."""
    big = max(int(table.max()) + 1, 1) if len(table) else 1
    keys = table[:, 0] * big + table[:, 1]
    return np.searchsorted(keys, rows[:, 0] * big + rows[:, 1])


def _reversed_faces(indices: NDArray[np.int64], offsets: NDArray[np.int64]
                    ) -> NDArray[np.int64]:
    """The flat face indices with every face's vertices in reverse order."""
    sizes = np.diff(offsets)
    owner = np.repeat(np.arange(len(sizes)), sizes)
    # position q of face f (offsets[f] <= q < offsets[f + 1]) takes the vertex at
    # offsets[f] + offsets[f + 1] - 1 - q
    q = np.arange(len(indices))
    out: NDArray[np.int64] = indices[offsets[owner] + offsets[owner + 1] - 1 - q]
    return out


def _newell(vertices: NDArray[np.float64], indices: NDArray[np.int64],
            offsets: NDArray[np.int64]) -> NDArray[np.float64]:
    """Newell's plane (A, B, C, D) of each face, (F, 4)."""
    n = len(offsets) - 1
    sizes = np.diff(offsets)
    nxt = np.arange(1, len(indices) + 1)
    nxt[offsets[1:] - 1] = offsets[:-1]
    p = vertices[indices]
    q = vertices[indices[nxt]]
    terms = np.stack([(p[:, 1] - q[:, 1]) * (p[:, 2] + q[:, 2]),
                      (p[:, 2] - q[:, 2]) * (p[:, 0] + q[:, 0]),
                      (p[:, 0] - q[:, 0]) * (p[:, 1] + q[:, 1])], axis=1)
    owner = np.repeat(np.arange(n), sizes)
    normal = np.zeros((n, 3))
    np.add.at(normal, owner, terms)
    centroid = np.zeros((n, 3))
    np.add.at(centroid, owner, p)
    centroid /= sizes[:, None]
    d = -(normal * centroid).sum(axis=1)
    return np.hstack([normal, d[:, None]])


def _face_sizes(vertices: NDArray[np.float64], indices: NDArray[np.int64],
                offsets: NDArray[np.int64]) -> NDArray[np.float64]:
    """The largest extent of each face's bounding box, (F,)."""
    n = len(offsets) - 1
    owner = np.repeat(np.arange(n), np.diff(offsets))
    p = vertices[indices]
    lo = np.full((n, 3), np.inf)
    hi = np.full((n, 3), -np.inf)
    np.minimum.at(lo, owner, p)
    np.maximum.at(hi, owner, p)
    extent: NDArray[np.float64] = (hi - lo).max(axis=1)
    return extent


def merge(meshes: Union[Mesh, Iterable[Mesh]], name: Optional[str] = None) -> Mesh:
    """One mesh holding all of ``meshes`` (their vertices renumbered); colors are
    kept when every mesh has them on the same kind of element.

    Parameters
    ----------
    meshes : Mesh or iterable of Mesh
        The meshes, at least one.
    name : str, optional
        The merged mesh's name.

    Returns
    -------
    Mesh

    Raises
    ------
    ArgumentTypeError
        If ``meshes`` is not a non-empty list of meshes.

    Examples
    --------
    >>> import scanline as sl
    >>> tri = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [[0, 1, 2]])
    >>> both = sl.mesh.merge([tri, tri.translated((0, 0, 1))])
    >>> both.faces.tolist()
    [[0, 1, 2], [3, 4, 5]]
    """
    if isinstance(meshes, Mesh):
        meshes = [meshes]
    if isinstance(meshes, (str, bytes)) or not hasattr(meshes, "__iter__"):
        raise ArgumentTypeError(f"meshes must be a list of scanline.mesh.Mesh, got "
                                f"{v._show(meshes)}")
    meshes = list(meshes)
    if not meshes or not all(isinstance(m, Mesh) for m in meshes):
        raise ArgumentTypeError("merge needs a non-empty list of scanline.mesh.Mesh")
    base = np.cumsum([0] + [len(m.vertices) for m in meshes[:-1]])
    verts = np.concatenate([m.vertices for m in meshes])
    indices = np.concatenate([m.face_indices + b for m, b in zip(meshes, base)])
    fbase = np.cumsum([0] + [len(m.face_indices) for m in meshes[:-1]])
    offsets = np.concatenate([[0]] + [m.face_offsets[1:] + b for m, b in zip(meshes, fbase)])
    out = object.__new__(Mesh)
    out.vertices = np.ascontiguousarray(verts)
    out.face_indices = np.ascontiguousarray(indices)
    out.face_offsets = offsets.astype(np.int64)
    out.normals = (np.concatenate([m.normals for m in meshes])
                   if all(m.normals is not None for m in meshes) else None)
    out.uv = (np.concatenate([m.uv for m in meshes])
              if all(m.uv is not None for m in meshes) else None)
    materials = {id(m.material) for m in meshes}
    out.material = meshes[0].material if len(materials) == 1 else None
    kinds = {m.color_on for m in meshes}
    if len(kinds) == 1 and None not in kinds:
        out.colors, out.color_on = np.concatenate([m.colors for m in meshes]), kinds.pop()
    else:
        out.colors, out.color_on = None, None
    out.name = name
    out._edges = None
    return out
