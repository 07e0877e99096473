"""Shading a visibility buffer with texture maps (Hearn & Baker 14-9): the compiled
form of :func:`scanline.shading.intensities` for textured materials (the numpy form
is the reference; :mod:`scanline.shading.surface` says what is computed).

Per drawn triangle, :func:`attribute_table` makes the screen-space linear functions
of 1/w and of K attributes times 1/w (the rasterizer's
:func:`~scanline._kernels.raster3d.planes`); per pixel, :func:`textured_pixels`
evaluates them and divides by 1/w's (perspective-correct), so that the texture
coordinates u, v and their screen derivatives (du/dx = (d(u/w)/dx - u d(1/w)/dx) /
(1/w), which choose a trilinear texture's levels) are exact for the pixel's point.
The attributes are, with the :data:`~scanline._kernels.shade.PHONG` token, the
point, the normal (turned toward the viewer on a back face), the surface color and
(u, v): the texel scales the color and the illumination runs per pixel
(:func:`~scanline._kernels.shade.light_chunk`); with
:data:`~scanline._kernels.shade.VERTEX`, the vertex intensities' part A that the
surface color scales, the part S it does not (the highlight) and (u, v): I = T A +
S.  Rows are shared out in bands as in :mod:`scanline._kernels.shade`, whose
chunked lighting and store this kernel calls.
"""

import numpy as np

from ._jit import kernel
from .raster3d import SETUP_BATCH
from .shade import (BAND, CHUNK, CR, FIELDS, IR, NX, PHONG, PX, light_chunk, light_setup,
                    store_chunk, table_starts, triangle_run)
from .texture import sample_run

#: Scratch fields after the lighting's: u, v, du/dx, dv/dx, du/dy, dv/dy and w (the
#: reciprocal of 1/w).
TU = FIELDS
TDX = FIELDS + 2
TW = FIELDS + 6
TEX_FIELDS = FIELDS + 7


@kernel
def attribute_table(lo, hi, tri, q, bary, tface, attributes, k, uv, table):
    """Per triangle ``t`` in ``lo .. hi - 1``: ``table[t]`` = x0, y0 (its vertex 0),
    (value at vertex 0, d/dx, d/dy) of 1/w, then of each of the first ``k``
    attributes of its facet times 1/w (``attributes`` (G, 3, K >= k) at the facet's
    vertices), then of u and v times 1/w (``uv`` (G, 3, 2)); an attribute is A_0 +
    lambda_1 (A_1 - A_0) + lambda_2 (A_2 - A_0).  NaN for a triangle covering no pixel
    or of no facet."""
    nf = min(attributes.shape[0], uv.shape[0])
    k = min(max(k, 0), attributes.shape[2], (table.shape[1] - 11) // 3)
    g = np.empty((SETUP_BATCH, 4, 3))
    ok = np.empty(SETUP_BATCH, np.bool_)
    for t in range(lo, hi):
        s = (t - lo) % SETUP_BATCH
        if s == 0:
            table_starts(tri, q, bary, tface, nf, t, min(t + SETUP_BATCH, hi), g, ok, table)
        if not ok[s]:
            continue
        f = tface[t]
        for a in range(k + 2):
            if a < k:
                v0 = attributes[f, 0, a]
                d1 = attributes[f, 1, a] - v0
                d2 = attributes[f, 2, a] - v0
            else:
                v0 = uv[f, 0, a - k]
                d1 = uv[f, 1, a - k] - v0
                d2 = uv[f, 2, a - k] - v0
            for c in range(3):
                table[t, 5 + 3 * a + c] = v0 * g[s, 1, c] + d1 * g[s, 2, c] + d2 * g[s, 3, c]


@kernel
def textured_pixels(start, step, faces, table, tface, face_mat, mats, mat_tex, texels, levels,
                    slopes, ambient, sources, eye, gamma_table, thresholds, raster, shading,
                    spec, mode):
    """Shade every pixel with a visible triangle into ``raster``, bands of :data:`BAND`
    rows ``start``, ``start + step`` ...; the arguments as
    :func:`scanline._kernels.shade.shade_pixels` takes them, ``table`` from
    :func:`attribute_table`, and per material ``mat_tex`` (M, 4): its texture's first
    level in ``levels`` (-1: none), level count, filter and wrap
    (:mod:`scanline._kernels.texture`; ``texels``, ``levels``: every texture's
    levels, one after the other); ``slopes``: whether a trilinear texture needs the
    screen derivatives of u and v.  VERTEX tables of 5 attributes hold A and (u, v)
    only (no highlight: S = 0).

    Each row, chunk after chunk of :data:`CHUNK` covered pixels: the attributes of
    each pixel into the chunk's fields, then the texels T, the lighting (PHONG) and
    the store.  One function rather than a chain of helpers: numba optimizes a
    caller again with every helper it links, so each level of helpers added compile
    time."""
    height = faces.shape[0]
    width = faces.shape[1]
    if len(shading) == PHONG:
        far, expo = light_setup(sources, mats, ambient)[:2]      # (own colors: not gray)
    else:
        far, expo = np.empty((0, 4)), -1
    s = np.empty(TEX_FIELDS * CHUNK)
    xs = np.empty(CHUNK, np.int64)
    ms = np.empty(CHUNK, np.int64)
    nf = face_mat.shape[0]
    nm = mats.shape[0]
    nl = levels.shape[0]
    k = (table.shape[1] - 5) // 3
    for lo in range(start * BAND, height, max(step, 1) * BAND):
        for y in range(lo, min(lo + BAND, height)):
            x = np.int64(0)
            while x < width:
                n = np.int64(0)
                while n < CHUNK and x < width:
                    x, end, t, f = triangle_run(faces, tface, nf, y, x, CHUNK - n)
                    if f < 0:
                        x = end
                        continue
                    m = min(max(face_mat[f], 0), nm - 1)
                    x0 = table[t, 0]
                    fy = y - table[t, 1]
                    q0 = table[t, 2] + table[t, 4] * fy
                    qx = table[t, 3]
                    qy = table[t, 4]
                    # the attributes: PHONG fields P, N, C then u, v; VERTEX fields A
                    # (0 .. 2), S (3 .. 5) then u, v.  First 1/(1/w), u, v and the
                    # first three
                    u0 = table[t, 5 + 3 * (k - 2)] + table[t, 7 + 3 * (k - 2)] * fy
                    ux = table[t, 6 + 3 * (k - 2)]
                    v0 = table[t, 5 + 3 * (k - 1)] + table[t, 7 + 3 * (k - 1)] * fy
                    vx = table[t, 6 + 3 * (k - 1)]
                    a0 = table[t, 5] + table[t, 7] * fy
                    ax = table[t, 6]
                    b0 = table[t, 8] + table[t, 10] * fy
                    bx = table[t, 9]
                    c0 = table[t, 11] + table[t, 13] * fy
                    cx = table[t, 12]
                    i = n
                    for px in range(x, end):
                        fx = px - x0
                        r = 1.0 / (q0 + qx * fx)
                        s[TW * CHUNK + i] = r
                        s[TU * CHUNK + i] = (u0 + ux * fx) * r
                        s[(TU + 1) * CHUNK + i] = (v0 + vx * fx) * r
                        s[i] = (a0 + ax * fx) * r
                        s[CHUNK + i] = (b0 + bx * fx) * r
                        s[2 * CHUNK + i] = (c0 + cx * fx) * r
                        xs[i] = px
                        ms[i] = m
                        i += 1
                    for a in range(3, k - 2):       # then the other attributes
                        a0 = table[t, 5 + 3 * a] + table[t, 7 + 3 * a] * fy
                        ax = table[t, 6 + 3 * a]
                        i = n
                        for px in range(x, end):
                            s[a * CHUNK + i] = (a0 + ax * (px - x0)) * s[TW * CHUNK + i]
                            i += 1
                    if slopes:
                        uy = table[t, 7 + 3 * (k - 2)]
                        vy = table[t, 7 + 3 * (k - 1)]
                        i = n
                        for px in range(x, end):
                            r = s[TW * CHUNK + i]
                            u = s[TU * CHUNK + i]
                            v = s[(TU + 1) * CHUNK + i]
                            s[TDX * CHUNK + i] = (ux - u * qx) * r
                            s[(TDX + 1) * CHUNK + i] = (vx - v * qx) * r
                            s[(TDX + 2) * CHUNK + i] = (uy - u * qy) * r
                            s[(TDX + 3) * CHUNK + i] = (vy - v * qy) * r
                            i += 1
                    n += end - x
                    x = end
                if n == 0:
                    continue
                # each pixel's texel T into fields TDX .. TDX + 2 (1 without a texture),
                # a run of one material sampled by one call
                i = np.int64(0)
                while i < n:
                    m = ms[i]
                    j = i + 1
                    while j < n and ms[j] == m:
                        j += 1
                    first = mat_tex[m, 0]
                    if first >= 0 and first < nl:
                        sample_run(texels, levels, first, min(mat_tex[m, 1], nl - first),
                                   mat_tex[m, 2], mat_tex[m, 3], s, np.int64(TU * CHUNK),
                                   np.int64(CHUNK), i, j)
                    else:
                        for p in range(i, j):
                            s[TDX * CHUNK + p] = 1.0
                            s[(TDX + 1) * CHUNK + p] = 1.0
                            s[(TDX + 2) * CHUNK + p] = 1.0
                    i = j
                # the texels are in fields TDX .. TDX + 2 (where the derivatives were):
                # PHONG scales the surface color by T, VERTEX makes I = T A + S
                to = CR if len(shading) == PHONG else 0
                for ch in range(3):
                    for p in range(n):
                        s[(to + ch) * CHUNK + p] *= s[(TDX + ch) * CHUNK + p]
                    if k > 5 and len(shading) != PHONG:
                        for p in range(n):
                            s[ch * CHUNK + p] += s[(3 + ch) * CHUNK + p]
                if len(shading) == PHONG:
                    light_chunk(n, s, ms, np.bool_(True), mats, ambient, sources, far, eye,
                                expo, spec, np.bool_(False), np.bool_(False))
                store_chunk(y, n, s, xs, gamma_table, thresholds, raster, shading, mode,
                            np.bool_(False))


@kernel
def vertex_light(lo, hi, points, normals, colors, material, mats, ambient, sources, eye, spec,
                 highlight, out):
    """The illumination model at points ``lo .. hi - 1`` of ``points``, ``normals``
    (unit, or normalized here) and surface ``colors`` (N, 3; or (1, 3): one color
    for all) of materials
    ``material`` (N,) (rows of ``mats``), in two parts: ``out[i, :3]`` = A, the part
    the surface color scales (ambient and diffuse), ``out[i, 3:6]`` = S, the highlight
    (the model with the color 0; only with ``highlight`` and six columns in ``out``):
    Gouraud's vertex intensities for a textured surface, through the per-pixel
    lighting's :func:`~scanline._kernels.shade.light_chunk`, a chunk of points at a
    time."""
    far, expo = light_setup(sources, mats, ambient)[:2]          # (own colors: not gray)
    s = np.empty(TEX_FIELDS * CHUNK)
    ms = np.empty(CHUNK, np.int64)
    nm = mats.shape[0]
    one = colors.shape[0] == 1
    hi = min(hi, points.shape[0], normals.shape[0], material.shape[0], out.shape[0],
             colors.shape[0] if not one else hi)
    highlight = highlight and out.shape[1] >= 6
    for c0 in range(lo, hi, CHUNK):
        n = min(CHUNK, hi - c0)
        for part in range(2 if highlight else 1):
            for i in range(n):
                p = c0 + i
                ms[i] = min(max(material[p], 0), nm - 1)
                for ch in range(3):
                    s[(PX + ch) * CHUNK + i] = points[p, ch]
                    s[(NX + ch) * CHUNK + i] = normals[p, ch]
                    s[(CR + ch) * CHUNK + i] = colors[0 if one else p, ch] if part == 0 else 0.0
            light_chunk(n, s, ms, np.bool_(True), mats, ambient, sources, far, eye, expo, spec,
                        np.bool_(False), np.bool_(False))
            for i in range(n):
                for ch in range(3):
                    value = s[(IR + ch) * CHUNK + i]
                    if part == 0:
                        out[c0 + i, ch] = value
                    else:
                        out[c0 + i, 3 + ch] = value
                        out[c0 + i, ch] -= value
