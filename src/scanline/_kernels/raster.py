"""Writing pixels into frame-buffer storage.

Storage is a uint8 array ``buf[y, x, channel]`` with rows bottom-up (row ``y`` is
scan line ``y``).  In bitmap mode (``packed``) ``buf[y, x >> 3, 0]`` holds 8 pixels,
the leftmost in the most significant bit, as Pillow's mode "1" does.
"""

from ._jit import inline


@inline
def put(buf, packed, width, height, x, y, color):
    """Set pixel (x, y) to ``color`` (uint8 channel values); outside the
    ``width`` x ``height`` raster nothing is written."""
    if x < 0 or y < 0 or x >= width or y >= height:
        return
    if packed:
        bit = 0x80 >> (x & 7)
        byte = buf[y, x >> 3, 0]
        if color[0]:
            buf[y, x >> 3, 0] = byte | bit
        else:
            buf[y, x >> 3, 0] = byte & (0xFF ^ bit)
    else:
        for c in range(buf.shape[2]):
            buf[y, x, c] = color[c]
