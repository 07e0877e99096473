"""Supersampling's resolve (Hearn & Baker 4-8, supersampling; 14: area sampling): each
pixel the mean of its n x n samples, averaged as light."""

from ._jit import kernel
from .shade import encode


@kernel
def resolve_samples(start, step, fine, covered, n, linear, gamma_table, thresholds, raster):
    """The pixels of the bands of 32 rows numbered ``start``, ``start + step`` ...: where
    any of its n x n samples in ``fine`` (H n, W n, K) is ``covered`` (H n, W n), the
    pixel of ``raster`` (H, W, K) takes the mean of the samples' linear values (the
    ``linear`` table of the 256 stored values, an uncovered sample counting as the
    pixel's own present value), encoded back with the gamma tables of
    :func:`scanline._kernels.shade.encode`; a fourth channel (alpha) is averaged as
    it is.  Pixels with no covered sample keep their values."""
    height = raster.shape[0]
    width = raster.shape[1]
    channels = raster.shape[2]
    inverse = 1.0 / (n * n)
    for lo in range(start * 32, height, max(step, 1) * 32):
        for y in range(lo, min(lo + 32, height)):
            for x in range(width):
                hits = 0
                for j in range(n):
                    for i in range(n):
                        if covered[y * n + j, x * n + i]:
                            hits += 1
                if hits == 0:
                    continue
                for ch in range(channels):
                    old = raster[y, x, ch]
                    total = 0.0
                    for j in range(n):
                        for i in range(n):
                            v = fine[y * n + j, x * n + i, ch] if covered[y * n + j, x * n + i] \
                                else old
                            total += float(v) if ch == 3 else linear[v]
                    if ch == 3:
                        raster[y, x, ch] = min(255, int(total * inverse + 0.5))
                    else:
                        raster[y, x, ch] = encode(total * inverse, gamma_table, thresholds)
