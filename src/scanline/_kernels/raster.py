"""Writing pixels into frame-buffer storage.

Storage is a uint8 array ``buf[y, x, channel]`` with rows bottom-up (row ``y`` is
scan line ``y``).  In bitmap mode (the ``PACKED`` layout) ``buf[y, x >> 3, 0]`` holds 8 pixels,
the leftmost in the most significant bit, as Pillow's mode "1" does.
"""

import numpy as np

from ._jit import helper, inline
from .variants import PACKED


@inline
def put_bit(buf, x, y, on):
    """Set (on) or clear the bit of pixel (x, y) in packed storage."""
    bit = 0x80 >> (x & 7)
    byte = buf[y, x >> 3, 0]
    if on:
        buf[y, x >> 3, 0] = byte | bit
    else:
        buf[y, x >> 3, 0] = byte & (0xFF ^ bit)


@inline
def put(buf, layout, width, height, x, y, color):
    """Set pixel (x, y) to ``color`` (uint8 channel values); outside the
    ``width`` x ``height`` raster nothing is written.

    ``layout`` is a layout token (:mod:`scanline._kernels.variants`): its length is
    a constant of the caller's specialization, so once inlined the branch below
    folds away (the loop ran about three times slower with a run-time test).
    """
    if x < 0 or y < 0 or x >= width or y >= height:
        return
    if len(layout) == PACKED:
        put_bit(buf, x, y, color[0])
        return
    n = color.shape[0]
    buf[y, x, 0] = color[0]
    if n > 1:
        buf[y, x, 1] = color[1]
        buf[y, x, 2] = color[2]
        if n > 3:
            buf[y, x, 3] = color[3]


@inline
def store(buf, y, x, color):
    """Write the channels of ``color`` at pixel (x, y) of unpacked storage, unchecked:
    the caller has proved (x, y) inside.  (``put`` repeats these writes rather than
    calling this: nesting the inlined helpers made the circle loop twice as slow.)"""
    n = color.shape[0]
    buf[y, x, 0] = color[0]
    if n > 1:
        buf[y, x, 1] = color[1]
        buf[y, x, 2] = color[2]
        if n > 3:
            buf[y, x, 3] = color[3]


@helper
def channels(colors, i):
    """Row ``i`` of the (N, n) uint8 ``colors`` as four scalars (the missing ones
    0): the color of a loop that writes a flat view of unpacked storage
    (:func:`store_flat`) and holds no array but that view (each array used in a
    loop over primitives costs an atomic reference-count increment and decrement
    per primitive)."""
    n = colors.shape[1]
    return (colors[i, 0], colors[i, 1] if n > 1 else 0, colors[i, 2] if n > 2 else 0,
            colors[i, 3] if n > 3 else 0)


@inline
def store_flat(flat, k, n, c0, c1, c2, c3):
    """Write the ``n`` channels (1, 3 or 4) ``c0``.. of one pixel at byte ``k`` of
    the flat view of unpacked storage, unchecked: the caller has proved it inside.
    The offset is made unsigned: numba then leaves out the wrap-around of a negative
    index, a compare and a move per byte stored (a million short lines drew in 66 ms
    instead of 88, 100k circles in 30 ms instead of 52, on one core; measured
    2026-12-07)."""
    u = np.uint64(k)
    flat[u] = c0
    if n > 1:
        flat[u + np.uint64(1)] = c1
        flat[u + np.uint64(2)] = c2
        if n > 3:
            flat[u + np.uint64(3)] = c3


#: Rows per band in ``band_order``: 32 rows of a 2048-pixel RGB raster are 192 KiB,
#: which stay in a core's L2 cache while the primitives of one band are drawn.
BAND_SHIFT = 5


@inline
def band_of(y, height):
    """The band of scan lines of row ``y`` clamped to the raster."""
    return min(max(y, 0), height - 1) >> BAND_SHIFT


@helper
def band_counts(items, height, lo, hi):
    """How many of ``items[lo:hi]`` fall in each band (``band_of`` their column 1)."""
    counts = np.zeros(((height - 1) >> BAND_SHIFT) + 1, np.int64)
    for i in range(lo, hi):
        counts[band_of(items[i, 1], height)] += 1
    return counts


@helper
def band_scatter(items, height, lo, hi, slots, out):
    """Copy each of ``items[lo:hi]`` to row ``slots[b]`` of ``out``, ``b`` its band,
    and advance that slot: the second pass of a counting sort, stable."""
    for i in range(lo, hi):
        b = band_of(items[i, 1], height)
        k = slots[b]
        for c in range(items.shape[1]):   # (a row assignment compiles an error message:
            out[k, c] = items[i, c]       # seconds of first-call compilation)
        slots[b] = k + 1


@helper
def band_sorted(items, height):
    """A copy of ``items`` sorted by band of scan lines (``items[:, 1] >> 5``, the y
    of each primitive's first point, clamped to the raster), stable within a band:
    a counting sort, O(N).

    When every primitive of a batch has the same color the drawing order cannot
    change the image, and drawing band by band keeps the rows being written in the
    cache.  The rows are copied (not just indexed) so that reading them stays
    sequential too.  (:func:`scanline.draw._common.band_order` runs the two passes
    on every core.)
    """
    first = np.int64(0)     # (not a literal 0: the passes compile once)
    counts = band_counts(items, height, first, items.shape[0])
    slots = np.zeros_like(counts)
    for b in range(1, counts.shape[0]):
        slots[b] = slots[b - 1] + counts[b - 1]
    out = np.empty_like(items)
    band_scatter(items, height, first, items.shape[0], slots, out)
    return out
