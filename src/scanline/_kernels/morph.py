"""Beier–Neely feature-based morphing: every pixel warped by line pairs, both images
sampled bilinearly and cross-dissolved in one pass.

Images are uint8 storage ``img[y, x, channel]`` with rows bottom-up (row y is scan
line y, as in the frame buffer); lines are float64 rows (x0, y0, x1, y1) in the same
device coordinates.  Every read is clamped to the image, every write is inside
``out``'s own loop bounds.
"""

import math

from ._jit import helper, kernel


@helper
def _sample(img, x, y, channel):
    """Bilinear sample of ``img`` at (x, y), edges clamped."""
    h, w = img.shape[0], img.shape[1]
    if x < 0.0:
        x = 0.0
    elif x > w - 1.0:
        x = w - 1.0
    if y < 0.0:
        y = 0.0
    elif y > h - 1.0:
        y = h - 1.0
    x0 = int(math.floor(x))
    y0 = int(math.floor(y))
    fx = x - x0
    fy = y - y0
    x1 = x0 + 1 if x0 + 1 < w else x0
    y1 = y0 + 1 if y0 + 1 < h else y0
    top = img[y0, x0, channel] * (1.0 - fx) + img[y0, x1, channel] * fx
    bottom = img[y1, x0, channel] * (1.0 - fx) + img[y1, x1, channel] * fx
    return top * (1.0 - fy) + bottom * fy


@kernel
def field_morph(src_a, src_b, lines, lines_a, lines_b, t, a, b, p, out):
    """Beier & Neely's field morph at time ``t``.

    For each pixel X of ``out`` and each line pair i (destination line ``lines[i]``
    = P Q at time t, source lines in A and B), with d = Q - P, n = perp(d) / |d|:
    u = (X - P)·d / |d|², v = (X - P)·n; the source point is
    X'ᵢ = P' + u d' + v n', written as X + (P' - P) + u (d' - d) + v (n' - n) so that
    identical lines give X' = X exactly.  The weight is
    wᵢ = (|d|^p / (a + distᵢ))^b, distᵢ the distance from X to the segment PQ.
    out = (1 - t) A(X'_A) + t B(X'_B), rounded half up.
    """
    h, w, channels = out.shape[0], out.shape[1], out.shape[2]
    n = lines.shape[0]
    for y in range(h):
        for x in range(w):
            sax = 0.0
            say = 0.0
            sbx = 0.0
            sby = 0.0
            total = 0.0
            for i in range(n):
                px = lines[i, 0]
                py = lines[i, 1]
                dx = lines[i, 2] - px
                dy = lines[i, 3] - py
                length2 = dx * dx + dy * dy
                length = math.sqrt(length2)
                rx = x - px
                ry = y - py
                u = (rx * dx + ry * dy) / length2
                v = (rx * -dy + ry * dx) / length
                if u < 0.0:
                    dist = math.sqrt(rx * rx + ry * ry)
                elif u > 1.0:
                    qx = x - lines[i, 2]
                    qy = y - lines[i, 3]
                    dist = math.sqrt(qx * qx + qy * qy)
                else:
                    dist = abs(v)
                weight = (length ** p / (a + dist)) ** b
                nx = -dy / length
                ny = dx / length
                # image A
                ax = lines_a[i, 2] - lines_a[i, 0]
                ay = lines_a[i, 3] - lines_a[i, 1]
                la = math.sqrt(ax * ax + ay * ay)
                sax += weight * ((lines_a[i, 0] - px) + u * (ax - dx) + v * (-ay / la - nx))
                say += weight * ((lines_a[i, 1] - py) + u * (ay - dy) + v * (ax / la - ny))
                # image B
                bx = lines_b[i, 2] - lines_b[i, 0]
                by = lines_b[i, 3] - lines_b[i, 1]
                lb = math.sqrt(bx * bx + by * by)
                sbx += weight * ((lines_b[i, 0] - px) + u * (bx - dx) + v * (-by / lb - nx))
                sby += weight * ((lines_b[i, 1] - py) + u * (by - dy) + v * (bx / lb - ny))
                total += weight
            xa = x + sax / total
            ya = y + say / total
            xb = x + sbx / total
            yb = y + sby / total
            for c in range(channels):
                value = (1.0 - t) * _sample(src_a, xa, ya, c)
                if t > 0.0:
                    value += t * _sample(src_b, xb, yb, c)
                level = math.floor(value + 0.5)
                if level < 0.0:
                    level = 0.0
                elif level > 255.0:
                    level = 255.0
                out[y, x, c] = int(level)
