"""Writing pixels into frame-buffer storage.

Storage is a uint8 array ``buf[y, x, channel]`` with rows bottom-up (row ``y`` is
scan line ``y``).  In bitmap mode (``packed``) ``buf[y, x >> 3, 0]`` holds 8 pixels,
the leftmost in the most significant bit, as Pillow's mode "1" does.
"""

from ._jit import inline


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
def put(buf, packed, width, height, x, y, color):
    """Set pixel (x, y) to ``color`` (uint8 channel values); outside the
    ``width`` x ``height`` raster nothing is written.

    Kernels call their pixel loops with a literal ``packed`` (``if packed:
    loop(..., True) else: loop(..., False)``): once inlined, the branch below folds
    away, and the loop runs about three times faster than with a run-time test.
    """
    if x < 0 or y < 0 or x >= width or y >= height:
        return
    if packed:
        put_bit(buf, x, y, color[0])
        return
    n = color.shape[0]
    buf[y, x, 0] = color[0]
    if n > 1:
        buf[y, x, 1] = color[1]
        buf[y, x, 2] = color[2]
        if n > 3:
            buf[y, x, 3] = color[3]
