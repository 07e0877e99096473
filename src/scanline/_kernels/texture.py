"""Texture sampling (Hearn & Baker, section 14-9, "Texture mapping"): the texel color
at texture coordinates (u, v), nearest, bilinear or trilinear (mipmapped, Williams
1983), with the coordinates wrapped (repeat, mirror) or clamped.

A texture's mipmap pyramid is one array ``texels`` (3 N,) float32, the R, G and B of
N texels one after the other (level after level, each row after row from the
bottom: row j holds v in [j/h, (j+1)/h)), and a table ``levels`` (L, 3) int64 of
each level's first texel, width and height.  Texel (i, j)
of a w x h level covers u in [i/w, (i+1)/w): its center is at ((i + 1/2)/w, (j +
1/2)/h).

No index leaves its array whatever the coordinates: a coordinate is first brought
into a small range as a real (its fraction for ``REPEAT``, modulo 2 for ``MIRROR``,
clamped for ``CLAMP``; NaN and infinities become 0) before it becomes an integer,
and every integer index is then wrapped or clamped into 0 .. n - 1 (a float too
large for an integer is never converted).
"""

import math

import numpy as np

from ._jit import helper, inline, kernel

#: Wrap modes (:data:`scanline.texture.WRAPS`).
REPEAT = 0
CLAMP = 1
MIRROR = 2

#: Filters (:data:`scanline.texture.FILTERS`).
NEAREST = 0
BILINEAR = 1
TRILINEAR = 2


#: Above this magnitude every double is a whole number (2^52): its fraction is 0.
WHOLE = 4503599627370496.0


@helper
def floor_of(t):
    """floor(t) as an integer for |t| < :data:`WHOLE` (a truncation and a step, cheaper
    than the library's floor)."""
    i = int(t)
    return i - 1 if t < i else i


@helper
def reduced(t, wrap):
    """Texture coordinate ``t`` brought into [0, 1) (repeat), [0, 2) (mirror: the
    period of a mirrored texture) or [-1, 2] (clamp) as a real; NaN and infinities
    give 0, and so do coordinates past 2^52 for the wraps (whole numbers there)."""
    if not abs(t) < WHOLE:              # NaN, infinite, or no fraction left
        return min(max(t, -1.0), 2.0) if wrap == CLAMP and math.isfinite(t) else 0.0
    if wrap == REPEAT:
        r = t - floor_of(t)
        return r if r < 1.0 else 0.0
    if wrap == MIRROR:
        r = t - 2.0 * floor_of(0.5 * t)
        return r if r < 2.0 else 0.0
    return min(max(t, -1.0), 2.0)


@helper
def wrapped(i, n, wrap):
    """Integer texel index ``i`` (any value) wrapped or clamped into 0 .. n - 1."""
    if i >= 0 and i < n:
        return i
    if wrap == REPEAT:
        i = i % n
    elif wrap == MIRROR:
        p = i % (2 * n)
        i = p if p < n else 2 * n - 1 - p
    return min(max(i, 0), n - 1)


@inline
def nearest(texels, levels, level, u, v, wrap):
    """The texel whose square holds (u, v) at ``level``: (r, g, b)."""
    base = levels[level, 0]
    w = levels[level, 1]
    h = levels[level, 2]
    i = wrapped(floor_of(reduced(u, wrap) * w), w, wrap)
    j = wrapped(floor_of(reduced(v, wrap) * h), h, wrap)
    k = 3 * (base + j * w + i)
    return texels[k], texels[k + 1], texels[k + 2]


@inline
def bilinear(texels, levels, level, u, v, wrap):
    """The four texels around (u, v) at ``level`` weighted by their distances
    (bilinear interpolation between texel centers): (r, g, b)."""
    base = levels[level, 0]
    w = levels[level, 1]
    h = levels[level, 2]
    x = reduced(u, wrap) * w - 0.5
    y = reduced(v, wrap) * h - 0.5
    fx = floor_of(x)
    fy = floor_of(y)
    ax = x - fx
    ay = y - fy
    i0 = 3 * wrapped(fx, w, wrap)
    i1 = 3 * wrapped(fx + 1, w, wrap)
    j0 = 3 * (base + wrapped(fy, h, wrap) * w)
    j1 = 3 * (base + wrapped(fy + 1, h, wrap) * w)
    w00 = (1.0 - ax) * (1.0 - ay)
    w10 = ax * (1.0 - ay)
    w01 = (1.0 - ax) * ay
    w11 = ax * ay
    k00 = j0 + i0
    k10 = j0 + i1
    k01 = j1 + i0
    k11 = j1 + i1
    r = w00 * texels[k00] + w10 * texels[k10] + w01 * texels[k01] + w11 * texels[k11]
    g = (w00 * texels[k00 + 1] + w10 * texels[k10 + 1] + w01 * texels[k01 + 1]
         + w11 * texels[k11 + 1])
    b = (w00 * texels[k00 + 2] + w10 * texels[k10 + 2] + w01 * texels[k01 + 2]
         + w11 * texels[k11 + 2])
    return r, g, b


@helper
def level_of_detail(levels, first, count, dudx, dvdx, dudy, dvdy):
    """The mipmap level (a real in 0 .. count - 1) for a pixel whose texture
    coordinates change by (dudx, dvdx) and (dudy, dvdy) per pixel: log2 of the longer
    of the pixel's two sides measured in texels of the finest level (Williams 1983;
    NaN derivatives give 0)."""
    w = levels[first, 1]
    h = levels[first, 2]
    a = (dudx * w) ** 2 + (dvdx * h) ** 2
    b = (dudy * w) ** 2 + (dvdy * h) ** 2
    rho2 = max(a, b)
    if not rho2 > 1.0:                  # magnified (or NaN): the finest level
        return 0.0
    lod = 0.5 * math.log2(rho2)
    return min(lod, count - 1.0)


@inline
def sample(texels, levels, first, count, filter, wrap, u, v, dudx, dvdx, dudy, dvdy):
    """The filtered color (r, g, b) of the texture whose levels are ``first`` ..
    ``first + count - 1`` of ``levels`` at (u, v), the screen derivatives choosing the
    mipmap levels of ``TRILINEAR`` (linear between the two nearest levels)."""
    if filter == NEAREST:
        return nearest(texels, levels, first, u, v, wrap)
    level = first
    t = 0.0
    if filter == TRILINEAR and count > 1:
        lod = level_of_detail(levels, first, count, dudx, dvdx, dudy, dvdy)
        step = min(int(lod), count - 1)
        level = first + step
        t = lod - step if step + 1 < count else 0.0
    r = g = b = 0.0
    for j in range(2 if t > 0.0 else 1):   # one compiled copy of the bilinear step
        weight = 1.0 - t if j == 0 else t
        rj, gj, bj = bilinear(texels, levels, level + j, u, v, wrap)
        r += weight * rj
        g += weight * gj
        b += weight * bj
    return r, g, b


@helper
def sample_run(texels, levels, first, count, filter, wrap, s, at, stride, lo, hi):
    """Items ``lo .. hi - 1`` of planar fields in ``s``: field k of item i at ``s[at + k
    stride + i]``, fields 0 and 1 the coordinates u and v, 2 .. 5 the screen
    derivatives du/dx, dv/dx, du/dy, dv/dy; each item's color (r, g, b) replaces its
    fields 2 .. 4.  One compiled copy of the sampling serves every caller (a call per
    run of items, not per item); bilinear repeated textures, the common case, take
    :func:`repeat_bilinear_run` (fields 0 and 1 are then overwritten)."""
    if filter == BILINEAR and wrap == REPEAT:
        repeat_bilinear_run(texels, levels, first, s, at, stride, lo, hi)
        return
    u_at = at
    v_at = at + stride
    d_at = at + 2 * stride
    for i in range(lo, hi):
        r, g, b = sample(texels, levels, first, count, filter, wrap, s[u_at + i], s[v_at + i],
                         s[d_at + i], s[d_at + stride + i], s[d_at + 2 * stride + i],
                         s[d_at + 3 * stride + i])
        s[d_at + i] = r
        s[d_at + stride + i] = g
        s[d_at + 2 * stride + i] = b


@helper
def repeat_bilinear_run(texels, levels, level, s, at, stride, lo, hi):
    """:func:`bilinear` with ``REPEAT`` at ``level`` for items ``lo .. hi - 1`` of
    :func:`sample_run`'s fields, in two passes with the same arithmetic: first, without
    a branch (so that the compiler vectorizes it), each item's weights (ax, ay) into
    fields 0 and 1 and its four texels' places (the first texel's index and the steps
    to its right and upper neighbours, wrapped) into fields 2 .. 4; then the texel
    lookups, whose colors replace fields 2 .. 4.  Every index is clamped into the
    level whatever the coordinates (NaN and infinities give 0, as :func:`reduced`)."""
    n = hi - lo
    if n <= 0:
        return
    base = float(levels[level, 0])
    w = float(levels[level, 1])
    h = float(levels[level, 2])
    u = s[at + lo:at + lo + n]
    v = s[at + stride + lo:at + stride + lo + n]
    k = s[at + 2 * stride + lo:at + 2 * stride + lo + n]
    kx = s[at + 3 * stride + lo:at + 3 * stride + lo + n]
    ky = s[at + 4 * stride + lo:at + 4 * stride + lo + n]
    for i in range(n):
        ax, i0, di = repeat_axis(u[i], w)
        ay, j0, dj = repeat_axis(v[i], h)
        u[i] = ax
        v[i] = ay
        k[i] = 3.0 * (base + j0 * w + i0)
        kx[i] = 3.0 * di
        ky[i] = 3.0 * w * dj
    for i in range(n):
        ax = u[i]
        ay = v[i]
        k00 = int(k[i])
        k10 = k00 + int(kx[i])
        k01 = k00 + int(ky[i])
        k11 = k01 + int(kx[i])
        w00 = (1.0 - ax) * (1.0 - ay)
        w10 = ax * (1.0 - ay)
        w01 = (1.0 - ax) * ay
        w11 = ax * ay
        k[i] = (w00 * texels[k00] + w10 * texels[k10] + w01 * texels[k01]
                + w11 * texels[k11])
        kx[i] = (w00 * texels[k00 + 1] + w10 * texels[k10 + 1] + w01 * texels[k01 + 1]
                 + w11 * texels[k11 + 1])
        ky[i] = (w00 * texels[k00 + 2] + w10 * texels[k10 + 2] + w01 * texels[k01 + 2]
                 + w11 * texels[k11 + 2])


@inline
def repeat_axis(t, n):
    """One axis of a repeated bilinear lookup in a level ``n`` texels wide, as reals
    without a branch: the weight of the upper texel, the lower texel's index and the
    step to the upper one (1, or 1 - n where it wraps), as :func:`bilinear` computes
    them (t reduced as :func:`reduced`: its fraction, 0 for NaN, infinities and
    coordinates past 2^52)."""
    r = t - np.floor(t)
    r = r if abs(t) < WHOLE and r < 1.0 else 0.0
    x = r * n - 0.5
    f = min(max(np.floor(x), -1.0), n - 1.0)
    a = x - f
    i0 = f if f >= 0.0 else n - 1.0
    d = 1.0 if i0 + 1.0 < n else 1.0 - n
    return a, i0, d


@kernel
def sample_points(texels, levels, first, count, filter, wrap, uv, derivatives, out):
    """``out[m]`` = the texture's color at ``uv[m]`` (M, 2) with screen derivatives
    ``derivatives[m]`` = du/dx, dv/dx, du/dy, dv/dy (M, 4; read by ``TRILINEAR``
    only), through :func:`sample_run`."""
    n = min(uv.shape[0], derivatives.shape[0], out.shape[0])
    s = np.empty(6 * n)
    for m in range(n):
        s[m] = uv[m, 0]
        s[n + m] = uv[m, 1]
        for k in range(4):
            s[(2 + k) * n + m] = derivatives[m, k]
    sample_run(texels, levels, first, count, filter, wrap, s, np.int64(0), n, np.int64(0), n)
    for m in range(n):
        for c in range(3):
            out[m, c] = s[(2 + c) * n + m]
