"""Ray casting (Hearn & Baker, section 13-10): one ray per pixel, the nearest
surface it meets.

After the projection normalization every ray through a pixel center runs parallel
to the depth axis, so the ray through (x, y) meets a triangle's plane at the depth
z = (-A x - B y - D) / C, and it meets the triangle iff (x, y) is inside it.  The
inside test is the crossing test of the scan-line fill (the edges crossing the row
through the center, ``ceil(xc_left) <= x < ceil(xc_right)``:
:func:`scanline._kernels.raster3d.span_limits`), so a ray hits exactly the
triangles whose scan conversion covers its pixel.  The loop runs pixel by pixel,
over the triangles whose bounding boxes meet the pixel's tile (the "bounding
rectangle" speed-up the section describes), tiles in parallel.
"""

import math

import numpy as np
from numba import prange

from ._jit import kernel, parallel_kernel, slow_to_compile
from .raster3d import planes, rising, span_limits

#: Tile size (pixels, a power of two) and its shift.
TILE_SHIFT = 4
TILE = 1 << TILE_SHIFT


@kernel
def tile_boxes(tri, width, height, boxes):
    """Each triangle's tile box (c0, r0, c1, r1), pixels clamped to the raster then
    shifted to tiles; a triangle that covers no pixel gets the empty box (1, 1, 0, 0),
    all four written (``boxes`` may come uninitialized: a row range left as garbage
    made :func:`bin_tiles` loop for hours over rows of an empty column range).
    Returns the number of (triangle, tile) pairs."""
    total = 0
    for t in range(tri.shape[0]):
        xlo = min(tri[t, 0, 0], tri[t, 1, 0], tri[t, 2, 0])
        xhi = max(tri[t, 0, 0], tri[t, 1, 0], tri[t, 2, 0])
        ylo = min(tri[t, 0, 1], tri[t, 1, 1], tri[t, 2, 1])
        yhi = max(tri[t, 0, 1], tri[t, 1, 1], tri[t, 2, 1])
        boxes[t, 0] = 1
        boxes[t, 1] = 1
        boxes[t, 2] = 0
        boxes[t, 3] = 0
        if not (xlo <= xhi and ylo <= yhi):
            continue
        c0 = max(int(max(min(math.floor(xlo), width + 1.0), -2.0)), 0)
        c1 = min(int(max(min(math.ceil(xhi), width + 1.0), -2.0)), width - 1)
        r0 = max(int(max(min(math.floor(ylo), height + 1.0), -2.0)), 0)
        r1 = min(int(max(min(math.ceil(yhi), height + 1.0), -2.0)), height - 1)
        if c0 > c1 or r0 > r1:
            continue
        boxes[t, 0] = c0 >> TILE_SHIFT
        boxes[t, 1] = r0 >> TILE_SHIFT
        boxes[t, 2] = c1 >> TILE_SHIFT
        boxes[t, 3] = r1 >> TILE_SHIFT
        total += (boxes[t, 2] - boxes[t, 0] + 1) * (boxes[t, 3] - boxes[t, 1] + 1)
    return total


@kernel
def bin_tiles(boxes, tiles_x, starts, order):
    """Bucket triangles by tile, in input order: ``order[starts[i]:starts[i + 1]]``
    for tile ``i = row * tiles_x + column`` (the boxes of :func:`tile_boxes`; an empty
    one is skipped)."""
    tiles = starts.shape[0] - 1
    for i in range(tiles + 1):
        starts[i] = 0
    for t in range(boxes.shape[0]):
        if boxes[t, 0] > boxes[t, 2]:
            continue
        for r in range(boxes[t, 1], boxes[t, 3] + 1):
            for c in range(boxes[t, 0], boxes[t, 2] + 1):
                starts[r * tiles_x + c + 1] += 1
    for i in range(tiles):
        starts[i + 1] += starts[i]
    fill = np.empty(tiles, np.int64)
    for i in range(tiles):
        fill[i] = starts[i]
    for t in range(boxes.shape[0]):
        if boxes[t, 0] > boxes[t, 2]:
            continue
        for r in range(boxes[t, 1], boxes[t, 3] + 1):
            for c in range(boxes[t, 0], boxes[t, 2] + 1):
                i = r * tiles_x + c
                order[fill[i]] = t
                fill[i] += 1


@kernel
def setups(tri, q, att, g, ok, rank):
    """Every triangle's linear functions (:func:`raster3d.planes`) into ``g`` (N, K +
    2, 3), ``ok[t]`` whether it covers anything, and ``rank[t]`` its vertices by
    rising y."""
    planes(tri, q, att, np.int64(0), tri.shape[0], g, ok)   # (a literal 0: a second compile)
    for t in range(tri.shape[0]):
        low, mid, high = rising(tri[t, 0, 1], tri[t, 1, 1], tri[t, 2, 1])
        rank[t, 0] = low
        rank[t, 1] = mid
        rank[t, 2] = high


@parallel_kernel
def cast_rays(tri, ids, g, ok, rank, tiles_x, starts, order, zbuf, abuf, idbuf):
    """Cast the ray of every pixel: the nearest triangle (the first in input order
    among equals) writes its depth, id and attributes."""
    height, width = zbuf.shape
    tiles = starts.shape[0] - 1
    k = abuf.shape[2]
    for i in prange(tiles):
        cx = (i % tiles_x) << TILE_SHIFT
        cy = (i // tiles_x) << TILE_SHIFT
        for y in range(cy, min(cy + TILE, height)):
            for x in range(cx, min(cx + TILE, width)):
                best = zbuf[y, x]
                hit = -1
                for e in range(starts[i], starts[i + 1]):
                    t = order[e]
                    if not ok[t]:
                        continue
                    low = rank[t, 0]
                    high = rank[t, 2]
                    if not (tri[t, low, 1] < y and y <= tri[t, high, 1]):
                        continue
                    mid = rank[t, 1]
                    kl, kr = span_limits(y, tri[t, low, 0], tri[t, low, 1], tri[t, mid, 0],
                                         tri[t, mid, 1], tri[t, high, 0], tri[t, high, 1],
                                         width)
                    if not (kl <= x and x < kr):
                        continue
                    fx = x - tri[t, 0, 0]
                    fy = y - tri[t, 0, 1]
                    z = g[t, 0, 0] + g[t, 0, 1] * fx + g[t, 0, 2] * fy
                    if z < best:
                        best = z
                        hit = t
                if hit >= 0:
                    zbuf[y, x] = best
                    idbuf[y, x] = ids[hit]
                    fx = x - tri[hit, 0, 0]
                    fy = y - tri[hit, 0, 1]
                    qx = g[hit, 1, 0] + g[hit, 1, 1] * fx + g[hit, 1, 2] * fy
                    for c in range(k):
                        abuf[y, x, c] = (g[hit, c + 2, 0] + g[hit, c + 2, 1] * fx
                                         + g[hit, c + 2, 2] * fy) / qx


#: The ray caster takes about 2 s to compile (benchmarks/compile.py): its twin answers
#: a small scene first (0.5 microsecond a work unit as Python, its estimate cautious).
slow_to_compile(cast_rays, 2.0)
