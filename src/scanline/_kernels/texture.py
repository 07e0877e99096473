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
clamped for ``CLAMP``; NaN and infinities become 0), and every texel index, a real
until the lookup, is then wrapped or clamped into 0 .. n - 1 (a float too large for
an integer is never converted).
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
def axis(t, n, wrap, half):
    """One axis of a lookup in a level ``n`` texels wide (a real), every wrap by
    selects rather than branches: ``(a, i0, d)``, the weight of the upper
    texel, the lower texel's index and the step from it to the upper one's, as reals.
    ``t`` is first brought into [0, 1) (``REPEAT``: its fraction), [0, 2)
    (``MIRROR``: the period of a mirrored texture) or [-1, 2] (``CLAMP``); NaN and
    infinities give 0, and so do coordinates past 2^52 for the wraps (whole numbers
    there).  ``half`` = 1/2: bilinear, the two texel centers around r n - 1/2; 0:
    nearest, the texel holding r n (the upper one's weight 0)."""
    rep = t - np.floor(t)
    mir = t - 2.0 * np.floor(0.5 * t)
    clamped = min(max(t, -1.0), 2.0) if abs(t) < math.inf else 0.0
    r = (rep if rep < 1.0 else 0.0) if wrap == REPEAT else \
        (mir if mir < 2.0 else 0.0) if wrap == MIRROR else clamped
    r = r if abs(t) < WHOLE or wrap == CLAMP else 0.0
    x = r * n - half
    f = np.floor(x)
    a = x - f if half > 0.0 else 0.0
    i0 = wrapped(f, n, wrap)
    return a, i0, wrapped(f + 1.0, n, wrap) - i0


@helper
def wrapped(i, n, wrap):
    """Whole number ``i`` (a real, -n - 1 .. 2 n as :func:`axis` makes them) wrapped
    (repeat: modulo n; mirror: modulo 2 n, reflected) or clamped into 0 .. n - 1,
    without a branch; whatever ``i``, the result is in 0 .. n - 1."""
    twice = 2.0 * n
    p = i + twice if i < 0.0 else i - twice if i >= twice else i
    i = (i + n if i < 0.0 else i - n if i >= n else i) if wrap == REPEAT else \
        (p if p < n else twice - 1.0 - p) if wrap == MIRROR else i
    return min(max(i, 0.0), n - 1.0)


@inline
def lookup(texels, k, kx, ky, ax, ay):
    """The four texels from index ``k`` (its right neighbour ``kx`` further, its upper
    one ``ky``; reals) weighted by ``ax``, ``ay`` (bilinear interpolation between
    texel centers; 0, 0: the first texel alone): (r, g, b)."""
    k00 = int(k)
    k10 = k00 + int(kx)
    k01 = k00 + int(ky)
    k11 = k01 + int(kx)
    w00 = (1.0 - ax) * (1.0 - ay)
    w10 = ax * (1.0 - ay)
    w01 = (1.0 - ax) * ay
    w11 = ax * ay
    r = w00 * texels[k00] + w10 * texels[k10] + w01 * texels[k01] + w11 * texels[k11]
    g = (w00 * texels[k00 + 1] + w10 * texels[k10 + 1] + w01 * texels[k01 + 1]
         + w11 * texels[k11 + 1])
    b = (w00 * texels[k00 + 2] + w10 * texels[k10 + 2] + w01 * texels[k01 + 2]
         + w11 * texels[k11 + 2])
    return r, g, b


@inline
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


@helper
def sample_run(texels, levels, first, count, filter, wrap, s, at, stride, lo, hi):
    """Items ``lo .. hi - 1`` of planar fields in ``s``: field k of item i at ``s[at + k
    stride + i]``, fields 0 and 1 the coordinates u and v, 2 .. 5 the screen
    derivatives du/dx, dv/dx, du/dy, dv/dy; each item's color (r, g, b) replaces its
    fields 2 .. 4 (fields 0 and 1 are overwritten).  The texture's levels are
    ``first .. first + count - 1`` of ``levels``.

    ``NEAREST`` and ``BILINEAR`` read the first level in two passes: first each
    item's weights (:func:`axis`) into its fields 0 and 1 and its four texels' places
    into 2 .. 4 (:func:`places`), then the lookups (:func:`lookup`).  ``TRILINEAR``
    reads, item by item, the two levels nearest the pixel's size (the screen
    derivatives choose them: :func:`level_of_detail`) and interpolates linearly
    between them.  One compiled copy of the sampling serves every caller, a call per
    run of items; items whose fields would lie past the end of ``s`` are left."""
    n = hi - lo
    if n <= 0:
        return
    u = s[at + lo:at + lo + n]
    v = s[at + stride + lo:at + stride + lo + n]
    k = s[at + 2 * stride + lo:at + 2 * stride + lo + n]
    kx = s[at + 3 * stride + lo:at + 3 * stride + lo + n]
    ky = s[at + 4 * stride + lo:at + 4 * stride + lo + n]
    n = min(len(u), len(v), len(k), len(kx), len(ky))     # fields past the end: fewer
    if filter == TRILINEAR and count > 1:
        dvdy = s[at + 5 * stride + lo:at + 5 * stride + lo + n]
        for i in range(min(n, len(dvdy))):
            lod = level_of_detail(levels, first, count, k[i], kx[i], ky[i], dvdy[i])
            step = min(int(lod), count - 1)
            t = lod - step if step + 1 < count else 0.0
            r = g = b = 0.0
            for j in range(2 if t > 0.0 else 1):   # one compiled copy of a level's lookup
                weight = 1.0 - t if j == 0 else t
                level = first + step + j
                w = float(levels[level, 1])
                ax, i0, di = axis(u[i], w, wrap, 0.5)
                ay, j0, dj = axis(v[i], float(levels[level, 2]), wrap, 0.5)
                rj, gj, bj = lookup(texels, 3.0 * (levels[level, 0] + j0 * w + i0), 3.0 * di,
                                    3.0 * w * dj, ax, ay)
                r += weight * rj
                g += weight * gj
                b += weight * bj
            k[i] = r
            kx[i] = g
            ky[i] = b
        return
    places(u, v, k, kx, ky, n, levels, first, wrap, 0.0 if filter == NEAREST else 0.5)
    for i in range(n):
        k[i], kx[i], ky[i] = lookup(texels, k[i], kx[i], ky[i], u[i], v[i])


@inline
def places(u, v, k, kx, ky, n, levels, level, wrap, half):
    """:func:`sample_run`'s first pass at ``level``: each of ``n`` items' weights into
    ``u``, ``v`` and its four texels' places into ``k``, ``kx``, ``ky``
    (:func:`lookup`'s arguments).  Bilinear repeated textures, the common case, take
    :func:`repeat_axis`, whose loop the compiler vectorizes."""
    base = float(levels[level, 0])
    w = float(levels[level, 1])
    h = float(levels[level, 2])
    fast = wrap == REPEAT and half > 0.0
    for i in range(n):
        if fast:
            ax, i0, di = repeat_axis(u[i], w)
            ay, j0, dj = repeat_axis(v[i], h)
        else:
            ax, i0, di = axis(u[i], w, wrap, half)
            ay, j0, dj = axis(v[i], h, wrap, half)
        u[i] = ax
        v[i] = ay
        k[i] = 3.0 * (base + j0 * w + i0)
        kx[i] = 3.0 * di
        ky[i] = 3.0 * w * dj


@inline
def repeat_axis(t, n):
    """:func:`axis` for a bilinear repeated texture, without a call: the fraction of
    ``t`` (0 for NaN, infinities and past 2^52), and an index that wraps by one
    step (1 - n)."""
    r = t - np.floor(t)
    r = r if abs(t) < WHOLE and r < 1.0 else 0.0
    x = r * n - 0.5
    f = np.floor(x)
    i0 = f if f >= 0.0 else n - 1.0
    return x - f, i0, 1.0 if i0 + 1.0 < n else 1.0 - n


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
