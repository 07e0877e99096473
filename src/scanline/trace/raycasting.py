"""The ray-casting method's step table (Hearn & Baker, section 13-10): along one row
of the z-buffer's scene (:data:`scanline.trace.zbuffer.SCENE`), the ray through each
pixel center, every triangle it meets with the depth of the meeting, and the
nearest, which the pixel shows.

The rows come from the ray-casting kernel (:mod:`scanline._kernels.raycast`) run as
Python: once with each triangle alone (the depths where its ray meets it) and once
with all (the nearest), so the hits and the winner are the kernel's own."""

from typing import Any, Dict, List, Tuple

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from .table import Table
from .zbuffer import HEIGHT, SCENE, WIDTH


class RayCastingTable(Table):
    """The table of :func:`ray_casting`, with the scene's triangles."""

    #: The triangles of :data:`SCENE` in device (x, y).
    triangles: List[List[List[float]]]


def _cast(tri: NDArray[np.float64]) -> Tuple[NDArray[np.float64], NDArray[np.int32]]:
    """The kernel's depth and triangle per pixel for the triangles ``tri`` (N, 3, 3)
    alone, on the :data:`WIDTH` x :data:`HEIGHT` device."""
    from .._kernels import raycast as k
    from .._kernels._jit import python

    n = len(tri)
    boxes = np.empty((n, 4), np.int64)
    pairs = python(k.tile_boxes)(tri, WIDTH, HEIGHT, boxes)
    tiles_x = ((WIDTH - 1) >> k.TILE_SHIFT) + 1
    tiles_y = ((HEIGHT - 1) >> k.TILE_SHIFT) + 1
    starts = np.empty(tiles_x * tiles_y + 1, np.int64)
    order = np.empty(pairs, np.int64)
    python(k.bin_tiles)(boxes, tiles_x, starts, order)
    g, ok, rank = np.empty((n, 2, 3)), np.empty(n, np.bool_), np.empty((n, 3), np.int64)
    python(k.setups)(tri, np.ones((n, 3)), np.zeros((n, 3, 0)), g, ok, rank)
    depth = np.full((HEIGHT, WIDTH), np.inf)
    ids = np.full((HEIGHT, WIDTH), -1, np.int32)
    python(k.cast_rays)(tri, np.arange(n, dtype=np.int64), g, ok, rank, tiles_x, starts, order,
                        depth, np.zeros((HEIGHT, WIDTH, 0)), ids)
    return depth, ids


def ray_casting(row: int = 4) -> RayCastingTable:
    """Ray casting along scan line ``row`` of the z-buffer's three triangles (device
    x, y, depth on 16 x 10; the rays run along the depth axis, as after the
    projection normalization): one row per pixel ``x``: ``hits``, each triangle the
    ray meets with its depth (``T1 0.3``, in triangle order), and the ``nearest``
    with its ``depth`` (none: the background).

    Parameters
    ----------
    row : int
        The scan line, 0 .. 9 (default 4).

    Returns
    -------
    RayCastingTable
        Columns x, hits, nearest, depth: one row per pixel of the row; its
        ``triangles`` attribute holds the triangles in device (x, y).

    Raises
    ------
    ArgumentValueError
        ``row`` is not an integer scan line of the device.

    References
    ----------
    A. Appel, "Some techniques for shading machine renderings of solids", AFIPS
    Spring Joint Computer Conference, 1968.

    Examples
    --------
    The pixels of the z-buffer's example (:func:`scanline.trace.z_buffer`): at
    x = 5 the ray meets T0 at 0.6 and T2 at 0.354545 (T2's plane, z = 0.1 +
    4.5 x 0.8/13.2 - 0.24/13.2); at x = 6 T1 at 0.3 is nearer than both:

    >>> for r in ray_casting(4).rows[4:7]:
    ...     print(r["x"], "|", r["hits"], "|", r["nearest"], r["depth"])
    4 | T0 0.6, T2 0.293939 | T2 0.293939
    5 | T0 0.6, T2 0.354545 | T2 0.354545
    6 | T0 0.6, T1 0.3, T2 0.415152 | T1 0.3
    """
    if isinstance(row, bool) or not isinstance(row, (int, np.integer)) \
            or not 0 <= row < HEIGHT:
        raise ArgumentValueError(f"row must be a scan line 0..{HEIGHT - 1}, got {v._show(row)}")
    tri = v.kernel_array(SCENE)
    alone = [_cast(tri[t:t + 1]) for t in range(len(tri))]
    depth, ids = _cast(tri)
    rows: List[Dict[str, Any]] = []
    for x in range(WIDTH):
        hits = [(t, float(d[row, x])) for t, (d, i) in enumerate(alone) if i[row, x] >= 0]
        near = int(ids[row, x])
        rows.append({"x": x, "hits": ", ".join(f"T{t} {z:.6g}" for t, z in hits) or "none",
                     "nearest": f"T{near}" if near >= 0 else "none",
                     "depth": round(float(depth[row, x]), 6) if near >= 0 else None})
    notes = [f"triangle T{t}: " + " ".join(f"({x:g}, {y:g}, {z:g})" for x, y, z in p.tolist())
             for t, p in enumerate(SCENE)]
    notes += [f"{WIDTH} x {HEIGHT} device; the ray through pixel (x, {row}) runs along the "
              "depth axis and meets a triangle whose scan conversion covers the pixel, at "
              "z = -(A x + B y + D) / C; the smallest z is nearest"]
    t = RayCastingTable(f"ray casting, scan line y = {row}", ["x", "hits", "nearest", "depth"], rows,
              notes)
    t.triangles = SCENE[:, :, :2].tolist()
    return t
