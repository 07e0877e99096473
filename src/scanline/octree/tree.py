"""What octrees and quadtrees share (Hearn & Baker, section 10-17): the flat storage,
the canonical form, the set operations node by node, the leaves in an order, the
measure, and the conversions from and to a grid of cells.

A region (a cube, or a square) is divided into 2**d octants (quadrants) recursively;
each node is empty, full, or split into its 2**d children.  Storage: ``kind`` (int8)
and ``child`` (int64, the first of a split node's consecutive children, -1 for a
leaf), node 0 the root, children after their parents
(:mod:`scanline._kernels.octree`).  Trees are kept canonical -- no split node has
children all full or all empty, and the nodes are numbered breadth first -- so two
trees of the same set have the same arrays.
"""

import math
from typing import Any, Callable, Optional, Tuple, Type, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..budget import check
from ..errors import ArgumentTypeError, ArgumentValueError

EMPTY, FULL, SPLIT = 0, 1, 2

#: The deepest level any tree may have (cell coordinates are int64 at the finest level).
MAX_DEPTH = 20

#: Bytes a node costs while a tree is made: its kind and child index, the copies the
#: canonical form makes, the cell coordinates of its level and the samples of a
#: solid's cells (evaluated in chunks).  The memory budget's estimate.
NODE_BYTES = 64

_T = TypeVar("_T", bound="Tree")


def worst_nodes(depth: int, nchild: int) -> int:
    """The most nodes a tree ``depth`` levels deep can have: a full tree."""
    leaves: int = nchild ** (depth + 1)       # int ** int is Any to the checker
    return (leaves - 1) // (nchild - 1)


def check_depth(depth: Any, nchild: int, what: str) -> int:
    """``depth`` as an int 1..MAX_DEPTH, refused up front (the memory budget) when a
    tree that deep could hold more nodes than fit (``worst_nodes``)."""
    if isinstance(depth, bool) or not isinstance(depth, (int, np.integer)) \
            or not 1 <= depth <= MAX_DEPTH:
        raise ArgumentValueError(f"depth must be an integer 1..{MAX_DEPTH} (the levels below "
                                 f"the root), got {v._show(depth)}")
    levels = int(depth)
    check(NODE_BYTES * worst_nodes(levels, nchild), "depth",
          f"{what} of depth {levels} (up to {worst_nodes(levels, nchild):,} nodes)",
          f"use a depth of {_deepest(nchild)} or less")
    return levels


def _deepest(nchild: int) -> int:
    """The deepest level whose worst case fits the budget."""
    from ..budget import limit

    d = 1
    while d < MAX_DEPTH and NODE_BYTES * worst_nodes(d + 1, nchild) <= limit():
        d += 1
    return d


def pyramid_kinds(grid: ArrayLike, dims: int) -> list[NDArray[np.int8]]:
    """The kind of every cell of every level, finest (the 0/1 ``grid``, 2**depth a
    side) to the root: a cell is full or empty where its children all are, else
    split (the bottom-up merge of Hearn & Baker 10-17)."""
    levels = [np.asarray(grid, np.int8)]
    while levels[-1].shape[0] > 1:
        a = levels[-1]
        m = a.shape[0] // 2
        blocks = a.reshape(sum(((m, 2) for _ in range(dims)), ()))
        axes = tuple(range(1, 2 * dims, 2))
        low, high = blocks.min(axis=axes), blocks.max(axis=axes)
        levels.append(np.where((low == high) & (low != SPLIT), low, SPLIT).astype(np.int8))
    return levels[::-1]


def build(classify: Callable[[int, NDArray[np.int64]], ArrayLike], depth: int,
          dims: int) -> Tuple[NDArray[np.int8], NDArray[np.int64]]:
    """A canonical tree made level by level, breadth first: ``classify(level,
    coords)`` gives the kinds (int8) of the cells at integer ``coords`` (M, dims) of
    ``level`` (2**level a side); the children of the split ones are classified next
    (at ``depth`` every cell must be a leaf).  Returns (kind, child)."""
    nchild = 1 << dims
    bits = np.array([[(j >> a) & 1 for a in range(dims)] for j in range(nchild)], np.int64)
    coords = np.zeros((1, dims), np.int64)
    kinds: list[NDArray[np.int8]] = []
    children: list[NDArray[np.int64]] = []
    start = 0
    for level in range(depth + 1):
        kind = np.asarray(classify(level, coords), np.int8)
        if level == depth:
            kind = np.where(kind == SPLIT, EMPTY, kind).astype(np.int8)
        split = kind == SPLIT
        child = np.full(len(kind), -1, np.int64)
        start += len(kind)                       # the next level's first node
        child[split] = start + nchild * np.arange(int(split.sum()))
        kinds.append(kind)
        children.append(child)
        coords = (2 * coords[split][:, None, :] + bits[None]).reshape(-1, dims)
        if not len(coords):
            break
    return canonical(np.concatenate(kinds), np.concatenate(children), nchild)


def canonical(kind: ArrayLike, child: ArrayLike, nchild: int) -> Tuple[NDArray[np.int8],
              NDArray[np.int64]]:
    """The canonical form (:func:`scanline._kernels.octree.compact`)."""
    from .._kernels import octree as k
    from .._kernels._jit import call

    kind = np.array(kind, np.int8)
    out_kind = np.empty(len(kind), np.int8)
    out_child = np.empty(len(kind), np.int64)
    count = call(k.compact, 4 * len(kind), kind, np.ascontiguousarray(child, np.int64),
                 nchild, out_kind, out_child)
    return out_kind[:count].copy(), out_child[:count].copy()


class Tree:
    """The shared part of :class:`~scanline.octree.Octree` and
    :class:`~scanline.octree.Quadtree`: a region ``origin`` + [0, side]**dims divided
    ``depth`` levels deep, stored as the flat arrays ``kind`` and ``child``."""
    dims = 3
    noun = "tree"

    def __init__(self, kind: ArrayLike, child: ArrayLike, depth: int, origin: NDArray[np.float64],
                 side: float) -> None:
        kind = np.ascontiguousarray(kind, np.int8)
        child = np.ascontiguousarray(child, np.int64)
        if kind.ndim != 1 or not len(kind) or child.shape != kind.shape:
            raise ArgumentValueError(f"kind and child must be 1-D arrays of one length (a "
                                     f"node each, the root first), got shapes {kind.shape} "
                                     f"and {child.shape}")
        self.kind = kind
        self.child = child
        self.depth = depth
        self.origin = origin
        self.side = side

    @property
    def nchild(self) -> int:
        return 1 << self.dims

    @property
    def node_count(self) -> int:
        """The number of nodes."""
        return len(self.kind)

    @property
    def cell_size(self) -> float:
        """The side of the finest cells (``side / 2**depth``)."""
        return self.side / (1 << self.depth)

    @classmethod
    def _grid_tree(cls: Type[_T], grid: NDArray[np.uint8], origin: NDArray[np.float64],
                   side: float) -> _T:
        """The canonical tree of a 0/1 ``grid`` (2**depth a side, indexed by axis)."""
        depth = int(round(math.log2(grid.shape[0])))
        levels = pyramid_kinds(grid, cls.dims)
        kind, child = build(lambda level, c: levels[level][tuple(c.T)], depth, cls.dims)
        return cls(kind, child, depth, origin, side)

    @classmethod
    def _padded(cls, array: ArrayLike, name: str) -> Tuple[NDArray[np.uint8], int]:
        """A boolean array (any shape of ``dims`` axes, each at least 1) padded with
        empty cells to a cube of 2**depth, depth >= 1: (grid uint8, depth)."""
        a = np.asarray(array)
        if a.ndim != cls.dims or a.size == 0 or a.dtype.kind not in "biuf":
            raise ArgumentValueError(f"{name} must be a non-empty {cls.dims}-D array of "
                                     f"booleans (or numbers, nonzero inside), got "
                                     f"{v._show(array)}")
        if a.dtype.kind == "f" and not np.isfinite(a).all():
            raise ArgumentValueError(f"{name} holds NaN or infinite values")
        depth = max(1, int(math.ceil(math.log2(max(a.shape)))))
        check_depth(depth, 1 << cls.dims, f"a {cls.noun} of a {'x'.join(map(str, a.shape))} "
                    f"{name}")
        check((1 << depth) ** cls.dims * 3, name, f"a {cls.noun} grid {1 << depth} a side")
        grid = np.zeros((1 << depth,) * cls.dims, np.uint8)
        grid[tuple(slice(0, s) for s in a.shape)] = a != 0
        return grid, depth

    def _same_region(self, other: object, name: str) -> None:
        if not isinstance(other, type(self)):
            raise ArgumentTypeError(f"{name} must be a {type(self).__name__}, got "
                                    f"{v._show(other)}")
        if not (np.array_equal(self.origin, other.origin) and self.side == other.side):
            raise ArgumentValueError(
                f"{name} covers another region (origin {tuple(other.origin)}, side "
                f"{other.side}) than this {self.noun} (origin {tuple(self.origin)}, side "
                f"{self.side}): build both over the same bounds")

    def _combined(self: _T, other: _T, op: int, name: str) -> _T:
        from .._kernels import octree as k
        from .._kernels._jit import call

        self._same_region(other, name)
        cap = self.node_count + other.node_count
        out_kind = np.empty(cap, np.int8)
        out_child = np.empty(cap, np.int64)
        count = call(k.combine, 4 * cap, self.kind, self.child, other.kind, other.child, op,
                     self.nchild, out_kind, out_child)
        kind, child = canonical(out_kind[:count], out_child[:count], self.nchild)
        return type(self)(kind, child, max(self.depth, other.depth), self.origin, self.side)

    def union(self: _T, other: _T) -> _T:
        """The cells in either tree (Hearn & Baker 10-17: node by node, a full node
        decides, an empty one takes the other's subtree)."""
        from .._kernels.octree import UNION
        return self._combined(other, UNION, "other")

    def intersection(self: _T, other: _T) -> _T:
        """The cells in both trees."""
        from .._kernels.octree import INTERSECTION
        return self._combined(other, INTERSECTION, "other")

    def difference(self: _T, other: _T) -> _T:
        """The cells of this tree not in ``other``."""
        from .._kernels.octree import DIFFERENCE
        return self._combined(other, DIFFERENCE, "other")

    __or__ = union
    __and__ = intersection
    __sub__ = difference

    def __eq__(self, other: object) -> bool:
        return (isinstance(other, type(self)) and np.array_equal(self.kind, other.kind)
                and np.array_equal(self.child, other.child)
                and np.array_equal(self.origin, other.origin) and self.side == other.side)

    __hash__ = None      # type: ignore[assignment]

    def _cells(self, order: Optional[NDArray[np.int64]] = None) -> NDArray[np.int64]:
        """Leaf rows (x, y, z, size, kind) in finest-level units, depth first with the
        children in ``order`` (default 0, 1, ...)."""
        from .._kernels import octree as k
        from .._kernels._jit import call

        order = np.arange(self.nchild, dtype=np.int64) if order is None else order
        leaves = self.node_count - (self.kind == SPLIT).sum() * 1
        out = np.empty((leaves, 5), np.int64)
        count = call(k.leaves, 3 * self.node_count, self.kind, self.child, order,
                     self.depth, out)
        return out[:count]

    def _measure(self) -> float:
        """The full cells' total length**dims: volume or area."""
        cells = self._cells()
        full = cells[cells[:, 4] == FULL, 3].astype(np.float64)
        return float((full ** self.dims).sum()) * self.cell_size ** self.dims

    def _grid(self) -> NDArray[np.uint8]:
        """The 0/1 grid (2**depth a side, indexed by axis) of the full cells."""
        from .._kernels import octree as k
        from .._kernels._jit import call

        n = 1 << self.depth
        check(n ** self.dims, "depth", f"a grid {n} a side of a {self.noun} of depth "
              f"{self.depth}")
        grid = np.zeros((n, n, n if self.dims == 3 else 1), np.uint8)
        cells = self._cells()
        call(k.fill_cells, n ** self.dims, cells, grid)
        return grid if self.dims == 3 else grid[:, :, 0]

    def __repr__(self) -> str:
        full = int((self.kind == FULL).sum())
        return (f"<{type(self).__name__} depth {self.depth}: {self.node_count} nodes, "
                f"{full} full leaves>")
