"""The ray-casting method (Hearn & Baker, section 13-10): an image-space method
("image precision"): for each pixel, the ray from the viewer through its center,
intersected with every surface whose bounding rectangle contains the pixel; the
nearest intersection is visible.  The kernel is :mod:`scanline._kernels.raycast`."""

from typing import TYPE_CHECKING, Optional

import numpy as np

from .visibility import Layer

if TYPE_CHECKING:
    from ..screen.scene import ScreenScene
    from .methods import MethodOptions


def raycast(scene: "ScreenScene", options: Optional["MethodOptions"] = None) -> Layer:
    """The :class:`Layer` of the nearest triangle along each pixel's ray."""
    from .._kernels import raycast as k
    from .._kernels._jit import call

    h, w = scene.height, scene.width
    ids = np.full((h, w), -1, np.int32)
    depth = np.full((h, w), np.inf)
    n = len(scene.triangles)
    if n == 0:
        return Layer(ids, depth)
    tri = np.ascontiguousarray(scene.triangles)
    boxes = np.empty((n, 4), np.int64)
    pairs = call(k.tile_boxes, 4 * n, tri, w, h, boxes)
    tiles_x = ((w - 1) >> k.TILE_SHIFT) + 1
    tiles_y = ((h - 1) >> k.TILE_SHIFT) + 1
    starts = np.empty(tiles_x * tiles_y + 1, np.int64)
    order = np.empty(pairs, np.int64)
    call(k.bin_tiles, 2 * pairs + n, boxes, tiles_x, starts, order)
    g = np.empty((n, 4, 3))
    ok = np.empty(n, np.bool_)
    rank = np.empty((n, 3), np.int64)
    call(k.setups, 10 * n, tri, np.ascontiguousarray(scene.inv_w),
         np.ascontiguousarray(scene.bary), g, ok, rank)
    call(k.cast_rays, 3 * pairs * k.TILE * k.TILE + h * w, tri, np.arange(n, dtype=np.int64),
         g, ok, rank, tiles_x, starts, order, depth, np.zeros((h, w, 2)), ids)
    return Layer(ids, depth)
