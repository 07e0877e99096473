"""Horizontal spans: the unit of work of every area fill (notes, chapter 2, Q.8:
"determine the overlap intervals for scan lines that cross the area").
"""

import numpy as np

from ._jit import inline
from .raster import put_bit
from .variants import PACKED


@inline
def span(buf, layout, width, height, y, x0, x1, color):
    """Fill pixels x0..x1 (inclusive) of scan line y with ``color``, clipped to the
    raster; nothing is written when x0 > x1 or the span is off the raster."""
    if y < 0 or y >= height:
        return
    if x0 < 0:
        x0 = 0
    if x1 > width - 1:
        x1 = width - 1
    if len(layout) == PACKED:
        for x in range(x0, x1 + 1):
            put_bit(buf, x, y, color[0])
        return
    # (the channel writes of raster.store, repeated: calling it here made the flood
    # fill, whose spans come from a big helper, 2.5 times slower).  The indices are
    # unsigned, the end never below the start (x0 >= 0 here): numba then leaves out
    # the wrap-around of negative indices, which made LLVM turn the gray loop into
    # scatters and the color loops into a multiply per pixel; in turn in one process
    # on one core (2026-12-07), 10k polygons 1.23-1.34x as fast in gray and 1.06-1.08x
    # in RGB, 100k filled circles 1.19x, the maze's flood fill 1.03x
    n = color.shape[0]
    row = np.uint64(y)
    for x in range(np.uint64(x0), np.uint64(max(x1 + 1, x0))):
        buf[row, x, 0] = color[0]
        if n > 1:
            buf[row, x, 1] = color[1]
            buf[row, x, 2] = color[2]
            if n > 3:
                buf[row, x, 3] = color[3]


@inline
def strip(band, step, height):
    """The rows ``(top, rows)`` of strip ``band`` of ``step``: the raster's rows cut
    into ``step`` contiguous strips of nearly equal height, one per thread
    (:func:`scanline._kernels._threads.call_in_bands`; DESIGN.md, "Parallel work").
    A batch kernel given one strip draws each primitive that reaches it into a view
    of the strip's rows, the primitive moved down by ``top``: its pixels move with
    it, so each pixel is written by one thread, by the primitives in the batch's
    order, whatever the thread count.  Contiguous strips, not interleaved bands:
    a primitive smaller than a strip is then drawn whole, once, by one thread (a
    circle clipped to a band of rows still steps through its whole octant)."""
    top = height * band // step
    return top, height * (band + 1) // step - top
