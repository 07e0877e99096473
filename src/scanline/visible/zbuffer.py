"""The depth-buffer (z-buffer) method (Hearn & Baker, section 13-3; Catmull 1974):
an image-space method ("image precision": visibility is decided at each pixel).

Two buffers: the depth buffer, cleared to infinity, and the refresh buffer.  Each
surface is scan-converted; at each pixel (x, y) it covers, its depth z is computed
(incrementally along the scan line, z' = z - A/C) and, if z < depth(x, y), depth(x,
y) = z and the pixel takes the surface's "intensity".  Here what is written is the
index of the device triangle (a visibility buffer): the shading lights each pixel
once afterwards, so a covered-over fragment costs no lighting.
"""

from typing import TYPE_CHECKING, Any, Optional, Tuple

import numpy as np
from numpy.typing import NDArray

from .._pool import recycled
from ..draw.triangles import rasterize
from .visibility import Layer

if TYPE_CHECKING:
    from ..screen.scene import ScreenScene
    from .methods import MethodOptions


def nearest(scene: "ScreenScene", zbuf: Optional[NDArray[np.float64]] = None,
            floor: Optional[NDArray[np.float64]] = None,
            triangles: Optional[NDArray[np.float64]] = None,
            size: Optional[Tuple[int, int]] = None,
            select: Optional[NDArray[np.integer[Any]]] = None) -> Layer:
    """The z-buffer pass over the scene's device triangles: the :class:`Layer` of the
    nearest triangle at each pixel center (its ``ids`` number the scene's triangles).

    ``zbuf``: a depth buffer (H, W) to test against, updated in place (only fragments
    in front of it are drawn); default a new one cleared to +inf.  ``floor``: depth
    peeling, only fragments strictly behind ``floor`` count.  ``triangles`` and
    ``size`` = (width, height): the scene's triangles mapped to another raster (the
    A-buffer's samples) instead of its own.  ``select``: the numbers of the triangles
    to draw (default all).

    All of them drawn, without peeling: the triangles facing the viewer are drawn
    first, and the others only where they are not behind the depths the first left
    in each tile (:func:`~scanline._kernels.raster3d.behind`): on a closed surface
    the faces turned away are hidden by the ones facing the viewer, and most are
    skipped whole.  The pixels are those of drawing in input order (equal depths go
    to the smaller triangle number, the first drawn).  Back-face culling's idea
    (Hearn & Baker, section 13-2), kept exact for the surfaces it does not hold
    for."""
    w, h = size if size is not None else (scene.width, scene.height)
    tri = scene.triangles if triangles is None else triangles
    q = scene.inv_w
    ids = None
    if select is not None:
        tri, q, ids = tri[select], q[select], np.ascontiguousarray(select, np.int64)
    n = len(tri)
    clear = zbuf is None
    if zbuf is None:
        out = recycled("faces", (h, w), np.int32)
        depth = recycled("depth", (h, w))
    else:
        out = np.full((h, w), -1, np.int32)
        depth = zbuf
    order = first = None
    if n and ids is None and floor is None:
        front = scene.front[scene.facet]
        facing = int(np.count_nonzero(front))
        if 0 < facing < n:
            order = np.concatenate([np.flatnonzero(front), np.flatnonzero(~front)])
            first = facing
    if n:
        rasterize(w, h, np.ascontiguousarray(tri), np.ascontiguousarray(q),
                  np.empty((n, 3, 0)), np.arange(n, dtype=np.int64) if ids is None else ids,
                  zbuf=depth, idbuf=out, floor=floor, clear=clear,
                  order=order, first=first)
    elif clear:
        out.fill(-1)
        depth.fill(np.inf)
    return Layer(out, depth)


def zbuffer(scene: "ScreenScene", options: Optional["MethodOptions"] = None) -> Layer:
    """The visible triangle at each pixel by the depth-buffer method."""
    return nearest(scene)
