"""Copying cached glyph images into the frame buffer (the text engine's glyph
cache: each character rasterized once per size and orientation, then stamped).

A glyph image is a uint8 coverage mask, rows bottom-up: 255 is a pixel inside the
glyph (0 outside); antialiased masks hold the covered fraction of the pixel times
255.  Every glyph mask lives in one flat ``atlas`` array, described by a row of
``masks``: its offset, width, height, the position of its bottom-left pixel
relative to the glyph's origin, and its runs of nonzero pixels (so that only the
glyph's pixels are visited).

Writing a pixel of coverage ``c`` with a color of alpha ``a`` (both 0..255) uses the
weight ``w = c * a / 255**2``: ``w = 1`` stores the color; otherwise gray and RGB
channels are mixed ``dst + (src - dst) * w`` and RGBA composites "over"
(Porter & Duff 1984); bitmaps (mode "1") and color-table images (mode "P") cannot
mix, so they store the color where ``w >= 1/2``.
"""

import numpy as np

from ._jit import helper, kernel
from .raster import put_bit


@helper
def _over(buf, y, x, value, w):
    """RGBA "over": the color at opacity ``w`` (0..1) over the stored pixel."""
    da = buf[y, x, 3] / 255.0
    oa = w + da * (1.0 - w)
    for ch in range(3):
        out = (value[ch] * w + buf[y, x, ch] * da * (1.0 - w)) / oa
        buf[y, x, ch] = int(out + 0.5)
    buf[y, x, 3] = int(oa * 255.0 + 0.5)


@helper
def _stamp(buf, packed, width, height, atlas, masks, runs, mids, gx, gy, value, alpha,
           threshold, solid):
    n = value.shape[0]
    for g in range(mids.shape[0]):
        m = mids[g]
        if m < 0:
            continue
        w = masks[m, 1]
        x0 = gx[g] + masks[m, 3]
        y0 = gy[g] + masks[m, 4]
        for r in range(masks[m, 5], masks[m, 5] + masks[m, 6]):
            j = runs[r, 0]
            y = y0 + j
            if y < 0 or y >= height:
                continue
            lo = max(x0 + runs[r, 1], 0)
            hi = min(x0 + runs[r, 2], width)
            if solid:  # a binary mask in an opaque color: store the run
                for x in range(lo, hi):
                    if packed:
                        put_bit(buf, x, y, value[0])
                    else:
                        for ch in range(n):
                            buf[y, x, ch] = value[ch]
                continue
            row = masks[m, 0] + j * w - x0
            for x in range(lo, hi):
                weight = atlas[row + x] * alpha  # coverage x alpha, 0 .. 255 * 255
                if packed:
                    if weight >= 32513:  # >= 1/2
                        put_bit(buf, x, y, value[0])
                elif weight == 65025:
                    for ch in range(n):
                        buf[y, x, ch] = value[ch]
                elif threshold:
                    if weight >= 32513:
                        buf[y, x, 0] = value[0]
                elif n == 4:
                    _over(buf, y, x, value, weight / 65025.0)
                else:  # dst + (src - dst) * weight / 255**2, rounded (in float: an
                    # integer floor division per channel measured slower)
                    f = weight * (1.0 / 65025.0)
                    for ch in range(n):
                        d = float(buf[y, x, ch])
                        buf[y, x, ch] = np.uint8(d + (value[ch] - d) * f + 0.5)


@kernel
def stamp_glyphs(buf, packed, width, height, atlas, masks, runs, mids, gx, gy, value,
                 alpha, threshold, solid):
    """Stamp glyph masks ``mids[g]`` with origins ``(gx[g], gy[g])`` (mask ids < 0
    are skipped).  ``masks[m]`` = (offset in ``atlas``, width, height, x and y of the
    bottom-left pixel from the origin, first run, run count); ``runs[r]`` = (row,
    first column, last column + 1) of a run of nonzero pixels.  ``value``: the
    color's channel values; ``alpha``: its alpha (0..255); ``threshold``: store
    instead of mixing (mode "P"); ``solid``: every mask pixel is 255 and alpha is
    255, so runs are stored without reading the mask.  Pixels outside the
    ``width`` x ``height`` raster are never written: each run is clipped to it
    (origins must lie within +-2**30)."""
    if packed:
        _stamp(buf, True, width, height, atlas, masks, runs, mids, gx, gy, value, alpha,
               threshold, solid)
    else:
        _stamp(buf, False, width, height, atlas, masks, runs, mids, gx, gy, value, alpha,
               threshold, solid)
