"""The octree method of visible-surface detection (Hearn & Baker, section 13-10):
``sl.render(fb, meshes, camera, method="octree")``.

Hearn & Baker: "When an octree representation is used for the viewing volume,
hidden-surface elimination is accomplished by projecting octree nodes onto the
quadtree of the viewing surface in a front-to-back order. ... Any node that is found
to be completely obscured is eliminated from further processing, so that its
subtrees are not accessed."  Here the viewing volume is the prepared scene's device
space (x, y in pixels, depth), where after the perspective transformation every view
is a parallel one along the depth axis, so the four octants nearer the viewer (the
lower half in depth) come before the four behind them in every node, in any order
among themselves (they do not overlap on the screen).

What the octree holds: the scene's device triangles, each listed in every node its
box meets; a node is split while it lists more than :data:`LEAF` triangles, down to
``max_depth`` levels (default :data:`DEPTH`; a split that would list more than twice
as many triangles is not made: they are too large to be separated).  The traversal
keeps a coverage mask of the pixels already decided: a node whose pixels are all
decided is passed by with its subtree; a leaf scan-converts its triangles at its
undecided pixels (the z-buffer's coverage rule and plane depths,
:mod:`scanline._kernels.raster3d`), keeping at each pixel the nearest fragment that
lies within the leaf's depth range, and then the pixels it wrote are decided, never
written again: the first leaf along a pixel's line of sight that holds a surface
holds the nearest one.  The result is the z-buffer's, pixel for pixel.

Meshes are drawn as they are, not voxelized: a user asking for the octree method
wants the picture of the meshes given, which the method finds exactly.  To see an
octree's cubes, give the :class:`~scanline.octree.Octree` itself (of a solid, of a
mesh at a chosen depth, of voxels): it is a mesh-like object whose faces are its
boundary, rendered by this method or any other.
"""

from typing import TYPE_CHECKING, Optional, cast

import numpy as np
from numpy.typing import NDArray

from ..budget import check
from .visibility import Layer

if TYPE_CHECKING:
    from ..screen.scene import ScreenScene
    from .methods import MethodOptions

#: Most triangles a leaf lists before it is split.
LEAF = 16

#: Nodes narrower and lower than this many pixels are not split: the depth test within
#: a leaf sorts out its few pixels sooner than more levels would.
SMALLEST = 4.0

#: The default deepest level of the scene's octree.
DEPTH = 10

#: Bytes per node (box, child, list start and length, level) and per list entry.
NODE_BYTES = 88
ENTRY_BYTES = 8


def octree(scene: "ScreenScene", options: Optional["MethodOptions"] = None) -> Layer:
    """The visible triangle at each pixel by the octree method (module docstring);
    ``options.max_depth`` (1..64, default :data:`DEPTH`) bounds the octree's
    depth."""
    from .._kernels import octree as k
    from .._kernels._jit import call

    w, h = scene.width, scene.height
    tri = np.ascontiguousarray(scene.triangles, np.float64)
    n = len(tri)
    depth_limit = DEPTH if options is None or options.max_depth is None else options.max_depth
    node_cap = 8 * (4 * n // LEAF + 1) + 1
    entry_cap = 8 * n + 64
    check(NODE_BYTES * node_cap + ENTRY_BYTES * (entry_cap + w * h) + 24 * w * h, "meshes",
          f"the octree of {n:,} triangles and a {w} x {h} coverage mask",
          "render fewer triangles or a smaller image")
    ids = np.full((h, w), -1, np.int32)
    depth = np.full((h, w), np.inf)
    if n == 0:
        return Layer(ids, depth)
    # numpy's stub: all(axis=) may be a scalar; here always (n,)
    finite = cast("NDArray[np.bool_]", np.isfinite(tri).all(axis=(1, 2)))
    lo = np.where(finite[:, None], tri.min(axis=1), np.inf)
    hi = np.where(finite[:, None], tri.max(axis=1), -np.inf)
    # a hair wider, so that a fragment's depth rounded past its triangle's box still
    # falls in a node that lists the triangle
    pad = 1e-9 * (1.0 + np.maximum(np.abs(lo), np.abs(hi)))
    pad[~finite] = 0.0
    lo, hi = np.ascontiguousarray(lo - pad), np.ascontiguousarray(hi + pad)
    if finite.any():
        z0, z1 = float(lo[finite, 2].min()), float(hi[finite, 2].max())
    else:
        z0, z1 = 0.0, 1.0
    box = np.array([-0.5, w - 0.5, -0.5, h - 0.5, z0, z1])
    nbox = np.empty((node_cap, 6))
    nchild = np.empty(node_cap, np.int64)
    nstart = np.empty(node_cap, np.int64)
    ncount = np.empty(node_cap, np.int64)
    entries = np.empty(entry_cap, np.int64)
    call(k.scene_octree, 20 * n, box, lo, hi, int(depth_limit), LEAF, SMALLEST, nbox,
         nchild, nstart, ncount, entries)
    final = np.zeros((h, w), np.uint8)
    call(k.octree_visible, 20 * n + 3 * w * h, tri, nbox, nchild, nstart, ncount, entries,
         ids, depth, final)
    return Layer(ids, depth)
