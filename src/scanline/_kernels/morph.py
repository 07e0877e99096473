"""Beier–Neely feature-based morphing: every pixel warped by line pairs, both images
sampled bilinearly and cross-dissolved in one pass.

Images are uint8 storage ``img[y, x, channel]`` with rows bottom-up (row y is scan
line y, as in the frame buffer); coordinates are device coordinates.  Every read is
clamped to the image, every write is inside ``out``'s own loop bounds, whatever the
input: a sample point that is not finite (a NaN from a degenerate line or from weights
that overflow, which the API layer refuses) is clamped like any other before it becomes
an index, and a table or an image too small for what the kernel reads draws nothing.
"""

import math

import numpy as np

from ._jit import helper, kernel

#: Columns of the per-line table :func:`field_morph` reads (one row per line pair;
#: :func:`scanline.animation.morph.line_table` fills it).
PX, PY, QX, QY, DX, DY, INV_LENGTH2, INV_LENGTH, LENGTH_P, NX, NY = range(11)
#: For image A (then image B at +6): P' - P, d' - d, n' - n.
A_OFFSET = 11
COLUMNS = 23


@helper
def _weight(lp, a, b, dist):
    w = lp / (a + dist)
    if b == 2.0:
        return w * w
    if b == 1.0:
        return w
    return w ** b


@helper
def _blend(src, x, y, weight, acc, channels, first):
    """Add ``weight`` times the bilinear sample of ``src`` at (x, y) (edges clamped)
    to ``acc[:channels]`` (or store it there when ``first``)."""
    h, w = src.shape[0], src.shape[1]
    # clamped before the conversion to an index: written so that NaN takes the first
    # branch (every comparison with NaN is false) and +-inf the first or the second
    if not x > 0.0:
        x = 0.0
    elif not x < w - 1.0:
        x = w - 1.0
    if not y > 0.0:
        y = 0.0
    elif not y < h - 1.0:
        y = h - 1.0
    x0 = int(x)
    y0 = int(y)
    fx = x - x0
    fy = y - y0
    x1 = x0 + 1 if x0 + 1 < w else x0
    y1 = y0 + 1 if y0 + 1 < h else y0
    for c in range(channels):
        top = src[y0, x0, c] * (1.0 - fx) + src[y0, x1, c] * fx
        bottom = src[y1, x0, c] * (1.0 - fx) + src[y1, x1, c] * fx
        value = weight * (top * (1.0 - fy) + bottom * fy)
        if first:
            acc[c] = value
        else:
            acc[c] += value


@kernel
def field_morph(src_a, src_b, table, t, a, b, out):
    """Beier & Neely's field morph at time ``t``.

    For each pixel X and each line pair i (destination line P Q at time t, source
    lines in A and B; ``table`` from :func:`line_table`), with d = Q - P and
    n = perp(d) / |d|: u = (X - P)·d / |d|², v = (X - P)·n; the source point is
    X'ᵢ = P' + u d' + v n', written as X + (P' - P) + u (d' - d) + v (n' - n) so that
    identical lines give X' = X exactly.  The weight is wᵢ = (|d|^p / (a + distᵢ))^b,
    distᵢ the distance from X to the segment PQ.  ``out`` receives
    (1 - t) A(X'_A) + t B(X'_B), rounded half up (at most 4 channels).
    """
    h, w, channels = out.shape[0], out.shape[1], min(out.shape[2], 4)
    channels = min(channels, src_a.shape[2], src_b.shape[2])
    n = table.shape[0]
    if (table.shape[1] < COLUMNS or src_a.shape[0] < 1 or src_a.shape[1] < 1
            or src_b.shape[0] < 1 or src_b.shape[1] < 1):
        return
    acc = np.zeros(4)
    for y in range(h):
        for x in range(w):
            sax = 0.0
            say = 0.0
            sbx = 0.0
            sby = 0.0
            total = 0.0
            for i in range(n):
                rx = x - table[i, PX]
                ry = y - table[i, PY]
                u = (rx * table[i, DX] + ry * table[i, DY]) * table[i, INV_LENGTH2]
                v = rx * table[i, NX] + ry * table[i, NY]
                if u < 0.0:
                    dist = math.sqrt(rx * rx + ry * ry)
                elif u > 1.0:
                    qx = x - table[i, QX]
                    qy = y - table[i, QY]
                    dist = math.sqrt(qx * qx + qy * qy)
                else:
                    dist = abs(v)
                weight = _weight(table[i, LENGTH_P], a, b, dist)
                sax += weight * (table[i, 11] + u * table[i, 13] + v * table[i, 15])
                say += weight * (table[i, 12] + u * table[i, 14] + v * table[i, 16])
                sbx += weight * (table[i, 17] + u * table[i, 19] + v * table[i, 21])
                sby += weight * (table[i, 18] + u * table[i, 20] + v * table[i, 22])
                total += weight
            _blend(src_a, x + sax / total, y + say / total, 1.0 - t, acc, channels, True)
            if t > 0.0:
                _blend(src_b, x + sbx / total, y + sby / total, t, acc, channels, False)
            for c in range(channels):
                # rounded half up and clamped to 0..255 before the conversion (NaN: 0)
                level = acc[c] + 0.5
                if not level >= 1.0:
                    out[y, x, c] = 0
                elif level >= 255.0:
                    out[y, x, c] = 255
                else:
                    out[y, x, c] = int(level)
