"""A solid (a primitive or a CSG tree) made ready for the ray kernels once: the tree
flattened to a postfix program, the primitives' rows, and one bounding volume
hierarchy over the triangles of every mesh primitive (Roth 1982: ray casting a CSG
tree; :mod:`scanline._kernels.csg`)."""

from typing import TYPE_CHECKING, List, Optional, Tuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError

#: Intervals one ray's list may hold at any node of the tree (Roth's lists are
#: bounded here so that each thread's lists are allocated once).
MAX_INTERVALS = 32

if TYPE_CHECKING:
    from ..lighting.material import Material
    from .base import Solid

#: A program's BVH over its meshes' triangles: bounds, links, table, triangles, owners.
Tree = Tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.float64], NDArray[np.float64],
             NDArray[np.int64]]
#: The kernels' arguments of a program: its rows, primitives, tree, lists and length.
Arguments = Tuple[NDArray[np.int64], NDArray[np.float64], NDArray[np.float64], NDArray[np.int64],
                  NDArray[np.float64], NDArray[np.float64], NDArray[np.int64], int, int]
#: The ray tracer's ``solids``: :data:`Arguments` with the materials' numbers and k_t.
TracerSolids = Tuple[NDArray[np.int64], NDArray[np.float64], NDArray[np.float64],
                     NDArray[np.int64], NDArray[np.float64], NDArray[np.float64],
                     NDArray[np.int64], int, int, NDArray[np.int64], NDArray[np.float64]]

_OPS = {"union": 1, "intersection": 2, "difference": 3}


def flatten(solid: "Solid") -> Tuple[NDArray[np.int64], List["Solid"], int]:
    """The postfix program of ``solid`` (rows (op, primitive)), its primitives in
    program order, and the most lists the program's stack holds.  Iterative, so a
    deep tree cannot exhaust Python's recursion."""
    from ..csg import CSG
    from .base import is_solid

    program: List[Tuple[int, int]] = []
    leaves: List["Solid"] = []
    todo: List[Tuple[object, bool]] = [(solid, False)]
    depth = most = 0
    while todo:
        node, expanded = todo.pop()
        if isinstance(node, CSG):
            if expanded:
                program.append((_OPS[node.op], 0))
                depth -= 1
            else:
                todo += [(node, True), (node.right, False), (node.left, False)]
        elif is_solid(node):
            program.append((0, len(leaves)))
            leaves.append(node)
            depth += 1
            most = max(most, depth)
        else:
            raise ArgumentValueError(f"a CSG tree's operands must be solids, got "
                                     f"{v._show(node)}")
    return np.array(program, np.int64).reshape(-1, 2), leaves, most


class Program:
    """``solid`` ready for ray casting.

    Attributes
    ----------
    program : ndarray of int64 (L, 2)
    primitives : list
        The leaves, numbered as the program numbers them.
    materials : list of Material
        Each primitive's.
    """

    def __init__(self, solid: "Solid", max_intervals: int = MAX_INTERVALS) -> None:
        from ..raytrace import BVH
        from .meshsolid import MeshSolid
        from .primitives import Primitive
        from .._kernels.solids import COLUMNS, MESH

        self.length = v.positive_int("max_intervals", max_intervals)
        if self.length > 4096:
            raise ArgumentValueError(f"max_intervals must be at most 4096, got {max_intervals}")
        self.program, self.primitives, depth = flatten(solid)
        self.lists = depth + 1
        rows = np.zeros((len(self.primitives), COLUMNS))
        triangles: List[NDArray[np.float64]] = []
        owner: List[NDArray[np.int64]] = []
        for k, leaf in enumerate(self.primitives):
            if isinstance(leaf, MeshSolid):
                rows[k, 0] = MESH
                t = leaf.triangles()
                triangles.append(t)
                owner.append(np.full(len(t), k, np.int64))
            elif isinstance(leaf, Primitive):
                rows[k] = leaf.row()
            else:
                raise ArgumentTypeError(
                    f"the ray kernels cast rays at the primitives of scanline.solids and at "
                    f"MeshSolid, not at {type(leaf).__name__} (a Solid subclass of its own); "
                    f"convert it to a mesh (sl.solids.MeshSolid) first")
        self.prims = np.ascontiguousarray(rows)
        self.materials: List["Material"] = [leaf.material for leaf in self.primitives]
        if triangles:
            every = np.concatenate(triangles)
            tree = BVH(every)
            self.tree: Tree = (tree.bounds, tree.links, tree.table,
                         np.ascontiguousarray(every[tree.order]),
                         np.ascontiguousarray(np.concatenate(owner)[tree.order]))
        else:
            self.tree = (np.zeros((0, 6)), np.zeros((0, 2), np.int64), np.zeros((0, 9)),
                         np.zeros((0, 3, 3)), np.zeros(0, np.int64))

    def _arguments(self) -> Arguments:
        return (self.program, self.prims, *self.tree, self.lists, self.length)

    def _work(self, rays: int) -> int:
        return 5 * rays * (len(self.program) + 4) + 1

    def _check(self, status: NDArray[np.int64], what: str) -> None:
        if status.sum():
            raise ArgumentValueError(
                f"{int(status.sum()):,} {what} cross the solid more than max_intervals="
                f"{self.length} times (or a mesh more than {8 * self.length} times): pass a "
                f"larger max_intervals")

    def cast(self, origins: NDArray[np.float64], directions: NDArray[np.float64],
             tmin: float = 0.0
             ) -> Tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.float64]]:
        """The first surface beyond ``tmin`` along each ray (origins and directions
        (R, 3) float64): ``(t (inf: none), code (-1: none), unit normals (R, 3))``."""
        from .._kernels._threads import call_in_bands
        from .._kernels import csg as k

        r = len(origins)
        t = np.empty(r)
        code = np.empty(r, np.int64)
        normal = np.empty((r, 3))
        status = np.zeros(64, np.int64)
        call_in_bands(k.cast, self._work(r), v.kernel_array(origins), v.kernel_array(directions),
                      float(tmin), *self._arguments(), t, code, normal, status)
        self._check(status, "rays")
        return t, code, normal

    def primitive(self, code: ArrayLike) -> NDArray[np.int64]:
        """The primitive each surface code (-1: none) belongs to (-1: none)."""
        c = np.asarray(code) >> 1
        k = c >> 3
        mesh = k >= len(self.primitives)
        rows = np.clip(c - 8 * len(self.primitives), 0, max(len(self.tree[4]) - 1, 0))
        owner = self.tree[4][rows] if len(self.tree[4]) else np.zeros_like(c)
        return np.where(np.asarray(code) < 0, -1, np.where(mesh, owner, k))

    def inside(self, points: ArrayLike) -> NDArray[np.bool_]:
        """Whether each point of a bounded solid is inside: whether the first surface
        its ray meets (along a direction no mesh edge is likely to hold) is one the
        ray leaves by (its outward normal along the ray), by the same kernels."""
        from .base import point_rows

        p = point_rows(points)
        d = np.array([0.5783502691896258, 0.5751502691896257, 0.5780502691896259])
        d /= np.linalg.norm(d)
        t, _, normal = self.cast(p, np.broadcast_to(d, p.shape).copy(), tmin=0.0)
        inside: NDArray[np.bool_] = np.isfinite(t) & (normal @ d > 0)
        return inside

    def moments(self, origins: NDArray[np.float64]) -> NDArray[np.float64]:
        """Per ray up +z from ``origins`` (R, 3), the integrals of 1, z and z^2 over
        its inside (:func:`scanline._kernels.csg.moments`), (R, 3)."""
        from .._kernels._threads import call_in_bands
        from .._kernels import csg as k

        out = np.empty((len(origins), 3))
        status = np.zeros(64, np.int64)
        call_in_bands(k.moments, self._work(len(origins)), v.kernel_array(origins),
                      *self._arguments(), out, status)
        self._check(status, "rays")
        return out


def tracer_solids(program: Optional[Program], first_material: int) -> TracerSolids:
    """The ray tracer's ``solids`` tuple (:mod:`scanline._kernels.csg`) of ``program``
    (None: no solids), the primitives' materials numbered from ``first_material`` in
    the tracer's material table."""
    if program is None:
        return (np.zeros((0, 2), np.int64), np.zeros((0, 35)), np.zeros((0, 6)),
                np.zeros((0, 2), np.int64), np.zeros((0, 9)), np.zeros((0, 3, 3)),
                np.zeros(0, np.int64), 1, 1, np.zeros(0, np.int64), np.zeros(0))
    count = len(program.primitives)
    kt = np.array([m.transparency for m in program.materials], np.float64)
    return (*program._arguments()[:7], program.lists, program.length,
            first_material + np.arange(count, dtype=np.int64), kt)
