"""A closed polygon mesh as a solid (Hearn & Baker 10-16: boundary representations
as CSG primitives).  Its inside along a ray comes from the sorted crossings of the ray
with its triangles (:func:`scanline._kernels.solids.mesh_intervals`)."""

from typing import TYPE_CHECKING, Optional

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import ArgumentTypeError, ArgumentValueError
from .base import Bounds, Solid, material_of

if TYPE_CHECKING:
    from ..lighting import Material
    from ..mesh import Mesh


def check_closed(mesh: "Mesh", argument: str = "mesh") -> None:
    """Refuse a mesh that does not bound a solid: every edge must be shared by exactly
    two faces that run along it in opposite directions (an oriented 2-manifold
    without boundary), so a ray going in also comes out."""
    half, _ = mesh._half_edges()
    if len(half) == 0:
        raise ArgumentValueError(f"{argument} has no faces: a solid needs a closed mesh")
    key = half[:, 0].astype(np.int64) * (len(mesh.vertices) + 1) + half[:, 1]
    rev = half[:, 1].astype(np.int64) * (len(mesh.vertices) + 1) + half[:, 0]
    keys, counts = np.unique(key, return_counts=True)
    if (counts > 1).any():
        a, b = divmod(int(keys[counts > 1][0]), len(mesh.vertices) + 1)
        raise ArgumentValueError(f"{argument} is not a closed, consistently oriented mesh: "
                                 f"edge ({a}, {b}) runs the same way in two faces (flip one "
                                 f"face's vertex order, or fix a non-manifold edge)")
    missing = ~np.isin(rev, keys)
    if missing.any():
        a, b = half[np.argmax(missing)]
        raise ArgumentValueError(f"{argument} is not closed: edge ({a}, {b}) borders one face "
                                 f"only (a hole); a solid needs every edge shared by two faces "
                                 f"(trimesh's fill_holes may close it)")


class MeshSolid(Solid):
    """The solid a closed, outward-oriented polygon mesh bounds.

    Parameters
    ----------
    mesh : scanline.mesh.Mesh
        Closed: every edge shared by two faces running along it in opposite
        directions (checked; a mesh with a hole is refused).
    material : Material, optional
        Else the mesh's own material, else the default.

    Raises
    ------
    ArgumentTypeError
        ``mesh`` not a Mesh.
    ArgumentValueError
        A mesh that is not closed and consistently oriented.

    Examples
    --------
    >>> import scanline as sl
    >>> cube = sl.solids.MeshSolid(sl.mesh.cube(2.0))
    >>> cube.volume(), cube.contains([(0, 0, 0), (2, 0, 0)]).tolist()
    (8.0, [True, False])
    """

    def __init__(self, mesh: "Mesh", *, material: Optional["Material"] = None) -> None:
        from ..lighting import Material
        from ..mesh import Mesh

        if not isinstance(mesh, Mesh):
            raise ArgumentTypeError(f"mesh must be a scanline.mesh.Mesh, got "
                                    f"{type(mesh).__name__}")
        check_closed(mesh)
        self.mesh = mesh
        own = mesh.material if isinstance(mesh.material, Material) else None
        self.material = material_of(material if material is not None else own)

    def triangles(self) -> NDArray[np.float64]:
        """The faces as triangle fans, (T, 3, 3) world coordinates.

        Returns
        -------
        ndarray (T, 3, 3)
            Each face of k vertices as k - 2 triangles from its first vertex.

        Examples
        --------
        >>> import scanline as sl
        >>> sl.solids.MeshSolid(sl.mesh.cube(2.0)).triangles().shape     # 6 squares
        (12, 3, 3)
        """
        idx, off = self.mesh.face_indices, self.mesh.face_offsets
        sizes = np.diff(off)
        first = np.repeat(idx[off[:-1]], sizes - 2)
        start = np.repeat(off[:-1], sizes - 2)
        k = np.arange(len(first)) - np.repeat(np.cumsum(sizes - 2) - (sizes - 2), sizes - 2)
        tri = np.stack([first, idx[start + k + 1], idx[start + k + 2]], axis=1)
        corners: NDArray[np.float64] = self.mesh.vertices[tri]
        return corners

    def contains(self, points: ArrayLike) -> NDArray[np.bool_]:
        """Whether each point is inside, by ray parity through the same kernels that
        cast the solid's rays.

        Parameters
        ----------
        points : array_like (N, 3) or (3,)
            World points.

        Returns
        -------
        ndarray (N,) bool
            True inside.

        Examples
        --------
        >>> import scanline as sl
        >>> sl.solids.MeshSolid(sl.mesh.cube(2.0)).contains([(0.5, 0.5, 0.9), (0, 0, 1.5)]).tolist()
        [True, False]
        """
        from .program import Program

        return Program(self).inside(points)

    def bounds(self) -> Bounds:
        """The mesh's bounding box.

        Returns
        -------
        lo, hi : ndarray (3,)
            Copies of the mesh's bounds.

        Examples
        --------
        >>> import scanline as sl
        >>> [c.tolist() for c in sl.solids.MeshSolid(sl.mesh.cube(2.0)).bounds()]
        [[-1.0, -1.0, -1.0], [1.0, 1.0, 1.0]]
        """
        lo, hi = self.mesh.bounds
        return lo.copy(), hi.copy()

    def volume(self) -> float:
        """Exact for the polyhedron: the divergence theorem over its triangles,
        V = sum of v0 . (v1 x v2) / 6.

        Returns
        -------
        float
            The volume.

        Examples
        --------
        >>> import scanline as sl
        >>> sl.solids.MeshSolid(sl.mesh.cube(3.0)).volume()
        27.0
        """
        t = self.triangles()
        return float(np.einsum("ij,ij->i", t[:, 0], np.cross(t[:, 1], t[:, 2])).sum() / 6.0)

    def __repr__(self) -> str:
        return f"<MeshSolid: {self.mesh!r}>"
