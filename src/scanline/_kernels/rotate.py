"""Rotating a block of pixels with area coverage (notes, chapter 6, Q3: "for the
rotation of a block of pixels, we need to determine the percentage of area covered
... for that pixel that overlaps the rotated block").

Each source pixel is a unit square; rotated, it is a square tilted by the angle.  The
destination pixel (x, y) receives from it the area of the intersection of the two
squares times its value: the intersection is the tilted square clipped to the pixel
[x - 1/2, x + 1/2] x [y - 1/2, y + 1/2] by the four boundaries in turn
(Sutherland–Hodgman), its area the shoelace sum.  ``acc`` gathers area x value per
channel and ``cover`` the area; all writes are bounded by the arrays' shapes.
"""

import math

import numpy as np

from ._jit import helper, kernel


@helper
def _clip_edge(xs, ys, n, outx, outy, axis, bound, keep_above):
    """Clip polygon (xs, ys)[:n] to coordinate ``axis`` >= bound (keep_above) or <=
    bound; returns the new vertex count in (outx, outy)."""
    m = 0
    if n == 0:
        return 0
    px = xs[n - 1]
    py = ys[n - 1]
    pv = px if axis == 0 else py
    p_in = pv >= bound if keep_above else pv <= bound
    for i in range(n):
        cx = xs[i]
        cy = ys[i]
        cv = cx if axis == 0 else cy
        c_in = cv >= bound if keep_above else cv <= bound
        if c_in != p_in:
            f = (bound - pv) / (cv - pv)
            outx[m] = px + f * (cx - px)
            outy[m] = py + f * (cy - py)
            m += 1
        if c_in:
            outx[m] = cx
            outy[m] = cy
            m += 1
        px = cx
        py = cy
        pv = cv
        p_in = c_in
    return m


@helper
def overlap(qx, qy, x0, y0, x1, y1, ax, ay, bx, by):
    """Area of convex quadrilateral (qx, qy)[:4] inside the box [x0, x1] x [y0, y1];
    ax, ay, bx, by are scratch arrays of at least 8 entries."""
    for i in range(4):
        ax[i] = qx[i]
        ay[i] = qy[i]
    # typed values, not literals: _clip_edge compiles once (the compile-time rule of
    # scanline._kernels, rule 6)
    x_axis, y_axis, above, below = np.int64(0), np.int64(1), np.bool_(True), np.bool_(False)
    n = _clip_edge(ax, ay, np.int64(4), bx, by, x_axis, x0, above)
    n = _clip_edge(bx, by, n, ax, ay, x_axis, x1, below)
    n = _clip_edge(ax, ay, n, bx, by, y_axis, y0, above)
    n = _clip_edge(bx, by, n, ax, ay, y_axis, y1, below)
    area = 0.0
    for i in range(n):
        j = i + 1 if i + 1 < n else 0
        area += ax[i] * ay[j] - ax[j] * ay[i]
    return abs(area) * 0.5


@kernel
def rotate_area(src, x0, y0, w, h, cx, cy, px, py, cos_a, sin_a, acc, cover,
                qx, qy, ax, ay, bx, by):
    """Accumulate the rotated block ``src[y0:y0+h, x0:x0+w]`` into ``acc``/``cover``.

    Source pixel (i, j) (center (x0 + i, y0 + j)) goes to
    (px, py) + R(angle) ((x0 + i, y0 + j) - (cx, cy)); ``acc`` and ``cover`` are
    indexed [y, x] in destination coordinates.
    """
    height, width = cover.shape[0], cover.shape[1]
    channels = src.shape[2]
    cornx = (-0.5, 0.5, 0.5, -0.5)
    corny = (-0.5, -0.5, 0.5, 0.5)
    for j in range(h):
        for i in range(w):
            sx = x0 + i - cx
            sy = y0 + j - cy
            lox = 1e300
            hix = -1e300
            loy = 1e300
            hiy = -1e300
            for k in range(4):
                ux = sx + cornx[k]
                uy = sy + corny[k]
                qx[k] = px + cos_a * ux - sin_a * uy
                qy[k] = py + sin_a * ux + cos_a * uy
                lox = min(lox, qx[k])
                hix = max(hix, qx[k])
                loy = min(loy, qy[k])
                hiy = max(hiy, qy[k])
            gx0 = max(int(math.floor(lox + 0.5)), 0)
            gx1 = min(int(math.floor(hix + 0.5)), width - 1)
            gy0 = max(int(math.floor(loy + 0.5)), 0)
            gy1 = min(int(math.floor(hiy + 0.5)), height - 1)
            for gy in range(gy0, gy1 + 1):
                for gx in range(gx0, gx1 + 1):
                    a = overlap(qx, qy, gx - 0.5, gy - 0.5, gx + 0.5, gy + 0.5, ax, ay, bx, by)
                    if a > 0.0:
                        cover[gy, gx] += a
                        for c in range(channels):
                            acc[gy, gx, c] += a * src[y0 + j, x0 + i, c]
