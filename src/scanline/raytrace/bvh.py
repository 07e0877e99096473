"""A bounding volume hierarchy over triangles, and rays cast against it (Hearn &
Baker 14-6, "reducing object-intersection calculations"): the kernels and the
construction by the surface-area heuristic are :mod:`scanline._kernels.bvh`."""

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentValueError

#: Bytes per triangle of a tree: the input copy, the boxes and centroids of the
#: construction, the reordered table, two nodes' bounds and links.
TRIANGLE_BYTES = 72 + 72 + 72 + 2 * 64 + 16


@dataclass(frozen=True)
class Hits:
    """The nearest hit of each ray, one row per ray (:meth:`BVH.intersect`).

    Parameters
    ----------
    t : ndarray (R,) float64
        The ray parameter of the hit (inf: none).
    triangle : ndarray (R,) int64
        The index of the triangle hit in the triangles the tree was built from (-1:
        none).
    uv : ndarray (R, 2) float64
        The barycentric coordinates of vertices 1 and 2 at the hit.

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> hits = sl.raytrace.Hits(np.array([np.inf]), np.array([-1]), np.zeros((1, 2)))
    >>> bool(np.isinf(hits.t[0])), hits.triangle.tolist()
    (True, [-1])
    """
    t: NDArray[np.float64]
    triangle: NDArray[np.int64]
    uv: NDArray[np.float64]


class BVH:
    """A bounding volume hierarchy of ``triangles`` (N, 3, 3) world coordinates,
    built by the binned surface-area heuristic in compiled code
    (:mod:`scanline._kernels.bvh`): flat node arrays, traversed iteratively (Hearn &
    Baker 14-6, "reducing object-intersection calculations").

    Parameters
    ----------
    triangles : array_like (N, 3, 3)
        Finite world coordinates of each triangle's three vertices.

    Raises
    ------
    ArgumentValueError
        Triangles not (N, 3, 3) or not finite.

    Attributes
    ----------
    bounds : ndarray (nodes, 6)
        Each node's box: xmin, ymin, zmin, xmax, ymax, zmax.
    links : ndarray of int64 (nodes, 2)
        (first child, 0) for an inner node (the children are ``first`` and ``first +
        1``), (first triangle, count) for a leaf, triangles in leaf order.
    order : ndarray of int64 (N,)
        The triangle (its index in ``triangles``) at each place of the leaf order.
    table : ndarray (N, 9)
        The triangles in leaf order as v0, v1 - v0, v2 - v0.

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> tree = sl.raytrace.BVH([[(0, 0, 0), (1, 0, 0), (0, 1, 0)]])
    >>> hits = tree.intersect([(0.25, 0.25, 1)], [(0, 0, -1)])
    >>> hits.t.tolist(), hits.triangle.tolist(), hits.uv.tolist()
    ([1.0], [0], [[0.25, 0.25]])
    """

    def __init__(self, triangles: ArrayLike) -> None:
        from .._kernels._jit import call
        from ..budget import check
        from .._kernels import bvh as _bvh

        tri = v.real_array("triangles", triangles, "(N, 3, 3)")
        if tri.ndim != 3 or tri.shape[1:] != (3, 3):
            raise ArgumentValueError(f"triangles must have shape (N, 3, 3) (three vertices "
                                     f"x, y, z each), got {tri.shape}")
        if not np.isfinite(tri).all():
            raise ArgumentValueError("triangles must be finite (a NaN or infinite "
                                     "coordinate cannot be bounded)")
        n = len(tri)
        check(TRIANGLE_BYTES * n, "triangles", f"a bounding volume hierarchy of {n:,} "
              "triangles", "trace fewer triangles")
        self.order = np.empty(n, np.int64)
        bounds = np.empty((max(2 * n, 1), 6))
        links = np.zeros((max(2 * n, 1), 2), np.int64)
        self.table = np.empty((n, 9))
        nodes = call(_bvh.build, 40 * n + 1, v.kernel_array(tri), self.order, bounds, links,
                     self.table)
        self.bounds = np.ascontiguousarray(bounds[:nodes])
        self.links = np.ascontiguousarray(links[:nodes])

    def __len__(self) -> int:
        return len(self.order)

    def intersect(self, origins: ArrayLike, directions: ArrayLike, tmin: float = 0.0,
                  tmax: float = math.inf) -> Hits:
        """The nearest hit of each ray o + t d with t in (tmin, tmax): rows of
        ``origins`` and ``directions`` (R, 3; directions need not be unit vectors, t
        is in their units) -> :class:`Hits`.

        Parameters
        ----------
        origins, directions : array_like (R, 3)
            The rays, finite; no direction zero.
        tmin, tmax : float
            The open range of t where hits count.

        Returns
        -------
        Hits
            The nearest hit of each ray (Moller-Trumbore intersections).

        Raises
        ------
        ArgumentValueError
            Shapes other than (R, 3), values not finite, or a zero direction.

        Examples
        --------
        Two rays down onto the unit right triangle in z = 0: one at (0.5, 0.25) hits
        it at t = 2 with (u, v) = (0.5, 0.25); one at (1, 1) misses.

        >>> import scanline as sl
        >>> tree = sl.raytrace.BVH([[(0, 0, 0), (1, 0, 0), (0, 1, 0)]])
        >>> hits = tree.intersect([(0.5, 0.25, 2), (1, 1, 2)], [(0, 0, -1), (0, 0, -1)])
        >>> hits.t.tolist(), hits.triangle.tolist(), hits.uv[0].tolist()
        ([2.0, inf], [0, -1], [0.5, 0.25])
        """
        from .._kernels._threads import call_in_bands
        from .._kernels import bvh as _bvh

        o = v.real_array("origins", origins, "(R, 3)")
        d = v.real_array("directions", directions, "(R, 3)")
        if o.ndim != 2 or o.shape[1] != 3 or d.shape != o.shape:
            raise ArgumentValueError(f"origins and directions must both have shape (R, 3), "
                                     f"got {o.shape} and {d.shape}")
        if not (np.isfinite(o).all() and np.isfinite(d).all()):
            raise ArgumentValueError("origins and directions must be finite")
        if not (d != 0).any(axis=1).all():
            raise ArgumentValueError("directions must not be zero vectors")
        lo, hi = v.number("tmin", tmin), tmax if tmax == math.inf else v.number("tmax", tmax)
        r = len(o)
        t = np.empty(r)
        row = np.empty(r, np.int64)
        uv = np.empty((r, 2))
        call_in_bands(_bvh.cast, 50 * r + 1, v.kernel_array(o), v.kernel_array(d), lo,
                      float(hi), self.bounds, self.links, self.table, t, row, uv)
        found = np.full(r, -1, np.int64)
        found[row >= 0] = self.order[row[row >= 0]]
        return Hits(t, found, uv)

    def __repr__(self) -> str:
        return f"<BVH of {len(self)} triangles, {len(self.bounds)} nodes>"
