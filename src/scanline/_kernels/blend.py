"""Alpha compositing: the "over" operator of Porter & Duff (1984) in every
frame-buffer mode.

The frame-buffer mode reaches these functions as a mode token
(:data:`scanline._kernels.variants.MODE`), so a kernel compiles the arithmetic of
the modes it is called with only.

A *source* is one color as a float64 row ``(c0, c1, c2, alpha)`` (rows of an
(N, 4) array ``srcs``, one per primitive or a single one) prepared by
``scanline.draw._blend.sources``: the channels in the frame buffer's terms (RGB for
modes "RGB", "RGBA" and "P"; the gray level in ``c0`` for "L"; the bit in ``c0`` for
"1") and the color's alpha in 0..1.  A pixel is composited with an *effective
alpha* ``a`` = coverage x alpha, in 0..1:

====== ====================================================================
mode   result
====== ====================================================================
"L"    ``d + (s - d) a``, rounded to the nearest level (a in 16-bit fixed
       point: the product is off by at most 255/65536 before rounding)
"RGB"  the same per channel
"RGBA" Porter-Duff over with destination alpha, straight (non-premultiplied)
       storage: ``ao = a + ad (1 - a)``,
       ``co = (s a + d ad (1 - a)) / ao``; a fully transparent result is left as is
"P"    the table colors blended as in "RGB", then the nearest table entry
       (least squared RGB distance, the first of equals)
"1"    the pixel takes the source bit when ``a >= 1/2``, else it is unchanged
====== ====================================================================

References
----------
T. Porter, T. Duff, "Compositing digital images", SIGGRAPH '84, Computer Graphics
18(3), 253-259, 1984.
"""

import numpy as np

from ._jit import helper, inline, kernel
from .raster import put_bit
from .variants import GRAY, INDEXED, RGB, RGBA


@helper
def nearest(table, r, g, b):
    """The index of the table entry nearest to (r, g, b) (squared distance; the
    first of equals)."""
    best = 0
    best_d = 1e300
    for i in range(table.shape[0]):
        dr = table[i, 0] - r
        dg = table[i, 1] - g
        db = table[i, 2] - b
        d = dr * dr + dg * dg + db * db
        if d < best_d:
            best_d = d
            best = i
    return best


@inline
def level(v):
    """A channel value in 0..255 rounded half up to uint8."""
    return np.uint8(int(v + 0.5))


@inline
def fixed(a):
    """An effective alpha ``a`` in [0, 1] as a 16-bit fixed-point weight 0..65536,
    exact to 255 / 65536 after :func:`mix`."""
    return int(a * 65536.0 + 0.5)


@inline
def mix(d, s, f):
    """Channel value ``d`` blended toward ``s`` (0..255) by the fixed-point weight
    ``f`` (:func:`fixed`), rounded to the nearest level; ``f = 0`` returns ``d``."""
    d = np.int64(d)
    return np.uint8(d + (((np.int64(s) - d) * f + 32768) >> 16))


@helper
def over(buf, mode, table, x, y, src, a):
    """Composite the source row ``src`` with effective alpha ``a`` over pixel
    (x, y) of ``buf`` (``mode`` a mode token).

    The caller has proved (x, y) inside; ``a`` is clamped to [0, 1] here, and
    ``a <= 0`` (or NaN) changes nothing.  A compiled helper, not inlined into the
    caller's IR: the mode tests fold only here (:mod:`scanline._kernels.variants`),
    and what is left of one mode is small enough for LLVM to inline."""
    if not a > 0.0:
        return
    if a > 1.0:
        a = 1.0
    # Each mode's stores sit in a loop over the channels (of one pass for "L" and
    # "1"): measured, straight-line stores made the antialiased line kernel four to
    # five times slower in those modes (LLVM apparently transforms the caller's
    # short column loop differently).
    if len(mode) == RGB or len(mode) == GRAY:
        f = fixed(a)
        for c in range(3 if len(mode) == RGB else 1):
            buf[y, x, c] = mix(buf[y, x, c], src[c], f)
    elif len(mode) == RGBA:
        da = buf[y, x, 3] / 255.0
        keep = da * (1.0 - a)
        oa = a + keep
        for c in range(4):
            if c < 3:
                buf[y, x, c] = level((src[c] * a + buf[y, x, c] * keep) / oa)
            else:
                buf[y, x, c] = level(oa * 255.0)
    elif len(mode) == INDEXED:
        i = buf[y, x, 0]
        r = table[i, 0] + (src[0] - table[i, 0]) * a
        g = table[i, 1] + (src[1] - table[i, 1]) * a
        b = table[i, 2] + (src[2] - table[i, 2]) * a
        buf[y, x, 0] = nearest(table, r, g, b)
    else:
        for _ in range(1 if a >= 0.5 else 0):
            put_bit(buf, x, y, src[0] != 0.0)


@helper
def composite_row(buf, mode, table, y, x0, cover, n, src):
    """Composite ``src`` over pixels x0 .. x0 + n - 1 of row y with alphas
    ``cover[0:n]`` (already multiplied by the source's alpha)."""
    for i in range(n):
        over(buf, mode, table, x0 + i, y, src, cover[i])


@kernel
def composite(buf, mode, width, height, table, mask, ox, oy, src):
    """Composite the source row ``src`` through the coverage ``mask`` (uint8,
    255 = covered; pixel (0, 0) of the mask is device pixel (ox, oy)) over
    ``buf``.  Mask pixels outside the ``width`` x ``height`` raster are skipped."""
    h, w = mask.shape[0], mask.shape[1]
    j0 = max(0, -oy)
    j1 = min(h, height - oy)
    i0 = max(0, -ox)
    i1 = min(w, width - ox)
    cover = np.empty(max(i1 - i0, 0), np.float64)
    alpha = src[3] / 255.0  # mask levels 0..255 to coverage 0..1, times alpha
    for j in range(j0, j1):
        for i in range(i0, i1):
            cover[i - i0] = mask[j, i, 0] * alpha
        composite_row(buf, mode, table, oy + j, ox + i0, cover, i1 - i0, src)
