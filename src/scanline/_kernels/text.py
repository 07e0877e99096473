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
from .variants import PACKED


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
def _stamp(buf, layout, width, height, atlas, masks, runs, mids, gx, gy, value, alpha,
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
                    if len(layout) == PACKED:
                        put_bit(buf, x, y, value[0])
                    else:
                        for ch in range(n):
                            buf[y, x, ch] = value[ch]
                continue
            row = masks[m, 0] + j * w - x0
            for x in range(lo, hi):
                weight = np.int64(atlas[row + x]) * alpha  # coverage x alpha, 0 .. 255 * 255
                if len(layout) == PACKED:
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
def stamp_glyphs(buf, layout, width, height, atlas, masks, runs, mids, gx, gy, value,
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
    _stamp(buf, layout, width, height, atlas, masks, runs, mids, gx, gy, value, alpha,
           threshold, solid)


@kernel
def stamp_line(buf, layout, width, height, atlas, masks, runs, mask_of, table, advances,
               codes, x, y, line, value, alpha, threshold, solid):
    """Place and stamp one line of upright text: code points ``codes`` through
    ``table`` (code point -> glyph id), ``advances`` (font units per glyph id) and
    ``mask_of`` (glyph id -> mask id, < 0: not cached yet), reference point
    ``(x, y)``.  ``line`` = (sx, gap, horizontal alignment 0 left / 1 center /
    2 right, 1 for path right / 0 for left, dv, the larger distance of the bottom
    and top lines from the reference, coordinate limit); the other arguments are
    those of :func:`stamp_glyphs`.

    The origins are computed with the operations of the layout's ``_horizontal``
    and ``place`` in the same order (so the pixels are identical): advances
    ``a = advances * sx (+ gap)``, running sum ``r``, ``u = r - a`` (path right) or
    ``gap - r`` (left), plus the alignment shift, plus ``x + 0.5``, floored; the
    baseline row ``floor(dv + y + 0.5)``; origins clipped to the coordinate limit
    when the line reaches beyond it.

    Returns 0 when drawn, 1 when nothing was drawn because a code point is beyond
    ``table`` or a glyph is not in the cache (the caller places such strings the
    general way)."""
    n = codes.shape[0]
    sx, gap, halign, right, dv = line[0], line[1], line[2], line[3] != 0.0, line[4]
    mids = np.empty(n, np.int64)
    u = np.empty(n)
    run = 0.0
    for k in range(n):
        c = codes[k]
        if c >= table.shape[0]:
            return 1
        g = table[c]
        m = mask_of[g]
        if m < 0:
            return 1
        mids[k] = m
        a = advances[g] * sx
        if gap != 0.0:
            a += gap
        run = a if k == 0 else run + a
        u[k] = run - a if right else gap - run
    span = run - gap if n > 0 else 0.0
    if right:
        lo, hi = 0.0 * span, span
    else:
        lo, hi = -span, 0.0 * span
    if halign == 0.0:
        shift = -lo
    elif halign == 2.0:
        shift = -hi
    else:
        shift = -(lo + hi) / 2
    lim = line[6]
    reach = max(abs(x), abs(y)) + max(max(abs(lo + shift), abs(hi + shift)), line[5])
    clip = reach > lim
    fy = dv + y + 0.5
    if clip:
        fy = min(max(fy, -lim), lim)
    gy = np.full(n, np.int64(np.floor(fy)))
    gx = np.empty(n, np.int64)
    xh = x + 0.5
    for k in range(n):
        fx = (u[k] + shift) + xh
        if clip:
            fx = min(max(fx, -lim), lim)
        gx[k] = np.int64(np.floor(fx))
    stamp_glyphs(buf, layout, width, height, atlas, masks, runs, mids, gx, gy, value,
                 alpha, threshold, solid)
    return 0
