"""Octrees (Hearn & Baker, section 10-17): a cubic region divided into octants
recursively, each node empty, full or split, made from a solid, a closed mesh or a
grid of voxels, combined by set operations node by node, and turned back into voxels
or into the mesh of its boundary faces."""

from typing import TYPE_CHECKING, Any, Optional, Sequence, Tuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..budget import check
from ..errors import ArgumentTypeError, ArgumentValueError
from .tree import FULL, SPLIT, Tree, build, check_depth

if TYPE_CHECKING:
    from ..mesh import Mesh

#: Samples per cell of :meth:`Octree.from_solid`: the eight corners and the center.
_SAMPLES = np.array([[(j >> a) & 1 for a in range(3)] for j in range(8)] + [[0.5] * 3])

#: Cells are decided by their samples only in the last levels: a cell more than this
#: many levels above the finest is split whatever its samples say, so a feature can
#: be missed only where it passes between the samples of a cell at most 2**3
#: finest cells a side (a torus's hole, a CSG difference through the center, seen
#: from the root's nine samples, would otherwise leave the tree empty).
SAMPLED_LEVELS = 3

#: Cells whose samples are tested in one call of a solid's ``contains``.
_CHUNK = 1 << 15


def _region(bounds: Any, name: str) -> Tuple[NDArray[np.float64], float]:
    """(origin, side) of the cube with its low corner at ``bounds``' low corner and the
    side of its largest extent."""
    try:
        lo, hi = (np.asarray(b, np.float64).reshape(3) for b in bounds)
    except (TypeError, ValueError):
        raise ArgumentValueError(f"{name} must be two 3-D points (low, high), got "
                                 f"{v._show(bounds)}") from None
    if not (np.isfinite(lo).all() and np.isfinite(hi).all()):
        raise ArgumentValueError(f"{name} must be finite, got low {tuple(lo)}, high "
                                 f"{tuple(hi)}: an octree needs a bounded region")
    side = float((hi - lo).max())
    if not side > 0 or (hi < lo).any():
        raise ArgumentValueError(f"{name} must have high > low on some axis and high >= low "
                                 f"on every axis, got low {tuple(lo)}, high {tuple(hi)}")
    return lo, side


class Octree(Tree):
    """An octree of a cubic region ``origin + [0, side]**3``, ``depth`` levels deep
    (cells of side ``side / 2**depth`` at the finest level).

    Made by :meth:`from_solid`, :meth:`from_mesh` or :meth:`from_voxels`; combined by
    :meth:`union`, :meth:`intersection`, :meth:`difference` (also ``|``, ``&``,
    ``-``).  An octree is also a mesh-like object: :attr:`vertices` and
    :attr:`faces` are its boundary faces (:meth:`to_mesh`), so ``sl.render(fb, tree,
    camera)`` draws its cubes by any visible-surface method.

    Attributes
    ----------
    kind : ndarray of int8
        Per node: 0 empty, 1 full, 2 split.
    child : ndarray of int64
        Per node: the first of its 8 consecutive children (octant ``j``: bit 0 of ``j``
        the upper half in x, bit 1 in y, bit 2 in z), -1 for a leaf.
    depth : int
    origin : ndarray (3,)
    side : float

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> v = np.zeros((4, 4, 4), bool); v[:2, :2, :2] = True; v[3, 3, 3] = True
    >>> t = sl.octree.Octree.from_voxels(v)
    >>> t
    <Octree depth 2: 17 nodes, 2 full leaves>
    >>> t.volume()
    9.0
    """
    dims = 3
    noun = "octree"

    @classmethod
    def from_voxels(cls, voxels: ArrayLike, origin: Sequence[float] = (0.0, 0.0, 0.0),
                    voxel_size: float = 1.0) -> "Octree":
        """The octree of a boolean array indexed [x, y, z] (nonzero: inside), padded
        with empty voxels to a cube of 2**depth a side; voxel (i, j, k) is the cube
        ``origin + voxel_size * ([i, i + 1] x [j, j + 1] x [k, k + 1])``.

        Parameters
        ----------
        voxels : array_like (X, Y, Z)
            Nonzero or True: inside.
        origin : 3-vector
            The low corner of voxel (0, 0, 0).
        voxel_size : float
            A voxel's side, > 0.

        Returns
        -------
        Octree
            The merged tree (Hearn & Baker 10-17).

        Raises
        ------
        ArgumentValueError
            An array that is not 3-D, a size not > 0, or a tree too large.

        Examples
        --------
        Eight full voxels of side 0.5 merge into one full root of volume 1:

        >>> import numpy as np, scanline as sl
        >>> block = sl.octree.Octree.from_voxels(np.ones((2, 2, 2), bool), voxel_size=0.5)
        >>> block, block.volume()
        (<Octree depth 1: 1 nodes, 1 full leaves>, 1.0)
        """
        grid, depth = cls._padded(voxels, "voxels")
        size = v.number("voxel_size", voxel_size)
        if not size > 0:
            raise ArgumentValueError(f"voxel_size must be positive, got {v._show(voxel_size)}")
        corner, _ = _region((origin, np.asarray(origin, float) + size), "origin")
        return cls._grid_tree(grid, corner, size * (1 << depth))

    @classmethod
    def from_solid(cls, solid: Any, depth: int,
                   bounds: Optional[Tuple[ArrayLike, ArrayLike]] = None) -> "Octree":
        """The octree of a solid: anything with ``contains(points) -> bool array`` and
        ``bounds() -> (low, high)`` (the primitives and CSG trees of
        :mod:`scanline.solids` and :mod:`scanline.csg`).

        Each cell, from the root down, is sampled at its eight corners and its center:
        full where all nine are inside, empty where none is, else split -- down to
        ``depth`` levels, where a cell is full when its center is inside.  Cells more
        than :data:`SAMPLED_LEVELS` levels above the finest are split whatever their
        samples (the root's nine samples alone would miss a torus).  A feature that
        passes between the samples of a cell is missed: the method's limit, as
        sampling cannot see it.

        Parameters
        ----------
        solid : solid
            Anything with ``contains`` and ``bounds``.
        depth : int
            Levels below the root, 1..20; refused up front where a full tree that deep
            would not fit in the memory budget.
        bounds : (low, high), optional
            The region (its cube: the low corner and the largest extent); default the
            solid's ``bounds()``.

        Returns
        -------
        Octree
            The tree.

        Raises
        ------
        ArgumentTypeError
            ``solid`` without ``contains`` and ``bounds``.
        ArgumentValueError
            An unbounded solid without ``bounds``, or a depth too large.

        Examples
        --------
        A box is its own bounds: every sample inside, the root full.

        >>> import scanline as sl
        >>> tree = sl.octree.Octree.from_solid(sl.solids.Box((0, 0, 0), (1, 1, 1)), 2)
        >>> tree, tree.volume()
        (<Octree depth 2: 1 nodes, 1 full leaves>, 1.0)
        """
        if not (callable(getattr(solid, "contains", None))
                and callable(getattr(solid, "bounds", None))):
            raise ArgumentTypeError(f"solid must have contains(points) and bounds() (a "
                                    f"scanline.solids primitive or CSG tree), got "
                                    f"{v._show(solid)}")
        depth = check_depth(depth, 8, "an octree")
        if bounds is None:
            origin, side = _region(solid.bounds(), "solid.bounds()")
        else:
            origin, side = _region(bounds, "bounds")

        def classify(level: int, coords: NDArray[np.int64]) -> NDArray[np.int8]:
            size = side / (1 << level)
            samples = _SAMPLES[8:] if level == depth else _SAMPLES
            kinds = np.empty(len(coords), np.int8)
            for a in range(0, len(coords), _CHUNK):
                c = coords[a:a + _CHUNK]
                points = origin + size * (c[:, None, :] + samples[None])
                inside = np.asarray(solid.contains(points.reshape(-1, 3)))
                if inside.shape != (points.shape[0] * points.shape[1],):
                    raise ArgumentValueError(
                        f"solid.contains returned shape {inside.shape} for "
                        f"{points.shape[0] * points.shape[1]} points: it must return one "
                        f"boolean per point")
                inside = inside.astype(bool).reshape(len(c), len(samples))
                every, some = inside.all(axis=1), inside.any(axis=1)
                kinds[a:a + _CHUNK] = np.where(every, FULL, np.where(some, SPLIT, 0))
            if level < depth - SAMPLED_LEVELS:
                kinds[:] = SPLIT
            return kinds

        kind, child = build(classify, depth, 3)
        return cls(kind, child, depth, origin, side)

    @classmethod
    def from_mesh(cls, mesh: Any, depth: int,
                  bounds: Optional[Tuple[ArrayLike, ArrayLike]] = None) -> "Octree":
        """The octree of the solid a closed mesh bounds, voxelized at ``depth``
        (2**depth voxels a side over ``bounds``, default the mesh's bounding box).

        A voxel is inside when its center is: ray parity along z (a point is inside a
        closed surface when a ray from it crosses the surface an odd number of times).
        Every column of voxel centers is one ray; the triangles are projected on the
        x-y plane and scan-converted onto the columns they cover with the top-left
        rule (:func:`scanline._kernels.octree.column_crossings`), so a ray through a
        shared edge or vertex crosses the surface once -- a ray tested against each
        triangle on its own (through a BVH) can count such a crossing twice or not at
        all -- and each column's crossings, sorted, fill its voxels.  The voxels then
        merge bottom-up into the octree.

        Parameters
        ----------
        mesh : Mesh
            A closed mesh.
        depth : int
            Voxels per side: 2**depth.
        bounds : (low, high), optional
            The region (default: the mesh's bounding box).

        Returns
        -------
        Octree
            The voxelized solid.

        Raises
        ------
        ArgumentValueError
            For a mesh that is not closed (``scanline.solids.meshsolid.check_closed``),
            or a depth beyond the memory budget.

        Examples
        --------
        A cube fills its own bounding box: every voxel center is inside.

        >>> import scanline as sl
        >>> sl.octree.Octree.from_mesh(sl.mesh.cube(2), 2).volume()
        8.0
        """
        from .._kernels import octree as k
        from .._kernels._jit import call
        from ..mesh.convert import as_meshes
        from ..solids.meshsolid import check_closed

        (m,) = as_meshes(mesh, "mesh")
        check_closed(m, "mesh")
        depth = check_depth(depth, 8, "an octree")
        n = 1 << depth
        if bounds is None:
            bounds = (m.vertices.min(axis=0), m.vertices.max(axis=0))
        origin, side = _region(bounds, "bounds")
        check(2 * n ** 3 + 16 * n * n + 72 * m.face_count, "depth",
              f"voxels {n} a side of a mesh")
        t = m.triangulated()
        tri = (t.vertices[t.face_indices.reshape(-1, 3)] - origin) / (side / n) - 0.5
        tri = np.ascontiguousarray(tri, np.float64)
        work = 4 * len(tri) + 4 * n * n
        counts = np.zeros(n * n, np.int64)
        call(k.column_crossings, work, tri, n, counts, np.empty(0))
        offsets = np.zeros(n * n + 1, np.int64)
        np.cumsum(counts, out=offsets[1:])
        check(8 * int(offsets[-1]), "depth", f"{int(offsets[-1]):,} crossings of voxel "
              "columns with the mesh")
        zs = np.empty(int(offsets[-1]))
        call(k.column_crossings, work, tri, n, offsets[:-1].copy(), zs)
        grid = np.empty((n, n, n), np.uint8)
        call(k.fill_columns, n ** 3 + len(zs), offsets, zs, grid)
        return cls._grid_tree(grid, origin, side)

    def volume(self) -> float:
        """The full cells' total volume.

        Returns
        -------
        float
            Sum of the full leaves' side**3.

        Examples
        --------
        >>> import numpy as np, scanline as sl
        >>> block = sl.octree.Octree.from_voxels(np.ones((2, 2, 2), bool), voxel_size=0.5)
        >>> block.volume()
        1.0
        """
        return self._measure()

    def to_voxels(self) -> NDArray[np.bool_]:
        """The full cells as a boolean array (2**depth a side, indexed [x, y, z]).

        Returns
        -------
        ndarray of bool (n, n, n)
            n = 2**depth.

        Examples
        --------
        >>> import numpy as np, scanline as sl
        >>> v = np.zeros((4, 4, 4), bool); v[:2, :2, :2] = True; v[3, 3, 3] = True
        >>> bool((sl.octree.Octree.from_voxels(v).to_voxels() == v).all())
        True
        """
        return self._grid().astype(bool)

    def cells(self, direction: Optional[ArrayLike] = None
              ) -> Tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_]]:
        """The leaves as (low corners (M, 3), sides (M,), full (M,) bool) in world
        coordinates, depth first; with ``direction`` (the viewing direction, a
        3-vector) front to back for a parallel view along it (Hearn & Baker 13-10):
        each node's octants in the order of their centers' distances along the
        direction, so a cell comes before every cell it can hide.

        Parameters
        ----------
        direction : 3-vector, optional
            The viewing direction (None: depth-first order).

        Returns
        -------
        corners : ndarray (M, 3)
            The leaves' low corners.
        sides : ndarray (M,)
            Their sides.
        full : ndarray of bool (M,)
            Whether each is full.

        Examples
        --------
        >>> import numpy as np, scanline as sl
        >>> block = sl.octree.Octree.from_voxels(np.ones((2, 2, 2), bool), voxel_size=0.5)
        >>> corners, sides, full = block.cells()
        >>> corners.tolist(), sides.tolist(), full.tolist()
        ([[0.0, 0.0, 0.0]], [1.0], [True])
        """
        order = None
        if direction is not None:
            d = v.real_array("direction", direction, "a 3-vector").reshape(-1)
            if d.shape != (3,) or not np.isfinite(d).all() or not d.any():
                raise ArgumentValueError(f"direction must be a finite nonzero 3-vector, got "
                                         f"{v._show(direction)}")
            keys = _SAMPLES[:8] @ d
            order = np.argsort(keys, kind="stable").astype(np.int64)
        rows = self._cells(order)
        h = self.cell_size
        return (self.origin + h * rows[:, :3], h * rows[:, 3].astype(float),
                rows[:, 4] == FULL)

    def to_mesh(self) -> "Mesh":
        """The boundary of the full cells: one square face, outward, for each side of
        a full cell on empty space (or outside the region), or for each side of a
        finer empty neighbor's leaves along it.  A :class:`~scanline.mesh.Mesh`.

        Returns
        -------
        Mesh
            The boundary faces (quadrilaterals).

        Examples
        --------
        One full root: a cube's six faces on its eight corners.

        >>> import numpy as np, scanline as sl
        >>> block = sl.octree.Octree.from_voxels(np.ones((2, 2, 2), bool), voxel_size=0.5)
        >>> block.to_mesh()
        <Mesh: 8 vertices, 6 faces, 12 edges>
        """
        from ..mesh import Mesh

        vertices, faces = self._boundary
        if not len(faces):
            raise ArgumentValueError("this octree has no full cell beside an empty one: its "
                                     "boundary mesh would have no faces")
        return Mesh(vertices, faces)

    @property
    def vertices(self) -> NDArray[np.float64]:
        """The vertices of :meth:`to_mesh` (an octree is a mesh-like object)."""
        return self._boundary[0]

    @property
    def faces(self) -> NDArray[np.int64]:
        """The faces of :meth:`to_mesh` (F, 4)."""
        return self._boundary[1]

    @property
    def _boundary(self) -> Tuple[NDArray[np.float64], NDArray[np.int64]]:
        cached: Optional[Tuple[NDArray[np.float64], NDArray[np.int64]]] = self.__dict__.get("_boundary_cache")
        if cached is None:
            cached = self.__dict__["_boundary_cache"] = self._faces()
        return cached

    def _faces(self) -> Tuple[NDArray[np.float64], NDArray[np.int64]]:
        from .._kernels import octree as k
        from .._kernels._jit import call

        cells = self._cells()
        cap = 6 * len(cells)
        check(200 * cap, "depth", f"up to {cap:,} boundary faces of an octree")
        out = np.empty((cap, 6), np.int64)
        count = call(k.boundary_faces, 20 * cap, self.kind, self.child, self.depth, cells, out)
        rows = out[:count]
        axis, sign, plane, u0, v0, s = rows.T
        corners = np.empty((count, 4, 3), np.int64)
        du = np.array([0, 1, 1, 0])
        dv = np.array([0, 0, 1, 1])
        for a in range(3):
            on = axis == a
            corners[on, :, a] = plane[on, None]
            corners[on, :, (a + 1) % 3] = u0[on, None] + s[on, None] * du
            corners[on, :, (a + 2) % 3] = v0[on, None] + s[on, None] * dv
        back = sign < 0
        corners[back] = corners[back][:, ::-1]
        unique, inverse = np.unique(corners.reshape(-1, 3), axis=0, return_inverse=True)
        return (self.origin + self.cell_size * unique.astype(np.float64),
                inverse.reshape(-1, 4).astype(np.int64))


__all__ = ["Octree"]
