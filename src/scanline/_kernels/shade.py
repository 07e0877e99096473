"""Shading a visibility buffer (Hearn & Baker, sections 14-2 and 14-5): every pixel
whose visible face and barycentric coordinates are known gets its intensity and is
stored, gamma-encoded, in the frame buffer.  The rows are shared out in bands
between calls running on several threads (:func:`shade_pixels` takes every
step-th band; the API layer starts the threads, the kernel releases the GIL): a
``prange`` kernel took 1.5 s more to compile.  Per pixel the illumination is written
out in one row helper (a helper called per pixel with the light and material arrays
cost 3x in reference counting), and a light at infinity's direction and attenuation
are computed once per call.

Variants (tokens, one specialization each):

* the polygon rendering method: :data:`VERTEX` interpolates intensities already
  computed at the face's vertices (Gouraud; flat shading gives all three vertices
  the face's one intensity), I = sum lambda_i I_i; :data:`PHONG` interpolates the
  normal, the point and the surface color, N = sum lambda_i N_i normalized, and
  evaluates the illumination model there (Phong 1975);
* the specular term: :data:`SPEC_PHONG`, (V . R)^n_s with R = 2 (N . L) N - L, or
  :data:`SPEC_BLINN`, (N . H)^n_s with H = (L + V) / |L + V| (Blinn 1977);
* the frame buffer's mode (:data:`scanline._kernels.variants.MODE`, "L", "RGB" or
  "RGBA"): "L" stores the luminance 0.299 R + 0.587 G + 0.114 B.

The model, per component (:func:`scanline.lighting.intensity` is its numpy form):
I = ka S_d I_a + sum_l f_l I_l [kd S_d max(N . L, 0) + ks S_s shine], shine = s^n_s
for s = min(V . R, 1) (or N . H) where N . L > 0 and s > 0, else 0.  Sources are
rows of ``sources`` (see :func:`scanline.shading.buffer.source_rows`): a homogeneous
position P (w = 0 for a directional light, P = -direction: L = unit(P - w p)), the
attenuation a0, a1, a2 (f = min(1, 1 / (a0 + a1 d + a2 d^2))), a spot axis, the
cosine of its half angle and its exponent (spot flag 1), and the RGB intensity.
The viewer is homogeneous too: V = unit(E - w p) (w = 0: a viewer at infinity in
direction E).  Faces seen from behind have their normals turned toward the viewer.
"""

import math

import numpy as np

from ._jit import helper, kernel
from .variants import GRAY, RGBA, token

#: Rows per band of :func:`shade_pixels` (the bands are shaded in parallel).
BAND = 32

VERTEX = 1
PHONG = 2
SPEC_PHONG = 1
SPEC_BLINN = 2

#: Tokens of the shading method and of the specular term.
SHADING = {"vertex": token(VERTEX), "phong": token(PHONG)}
SPECULAR = {"phong": token(SPEC_PHONG), "blinn": token(SPEC_BLINN)}


#: The smallest highlight factor s^n_s evaluated: for s below SHINE_FLOOR^(1/n_s) the
#: power (the costliest step of a pixel) is skipped and the term taken as 0, an error
#: below 1e-12 of full intensity (a millionth of the smallest step between two stored
#: values near black at gamma 2.2).
SHINE_FLOOR = 1e-12

#: Entries of the gamma table (:func:`encode`).
GAMMA_STEPS = 4096


@helper
def encode(value, table, thresholds):
    """round(255 clamp(I, 0, 1)^(1/gamma)) without a power: ``table[j]`` is the stored
    value of I = j / (GAMMA_STEPS - 1), a lower bound for any I in the step, raised
    while I reaches the next value's threshold ``thresholds[v + 1]`` = ((v + 1/2) /
    255)^gamma (``thresholds[256]`` = inf); NaN stores 0."""
    i = value
    if not i > 0.0:
        i = 0.0
    if i > 1.0:
        i = 1.0
    j = min(int(i * (GAMMA_STEPS - 1)), GAMMA_STEPS - 1)
    v = table[j]
    while v < 255 and i >= thresholds[v + 1]:
        v += 1
    return np.uint8(v)


@kernel
def shade_pixels(start, step, faces, bary, world, normals, colors, front, face_mat, mats,
                 ambient, sources, eye, table, thresholds, raster, shading, spec, mode):
    """Shade every pixel (y, x) with ``faces[y, x] >= 0`` into ``raster[y, x]``, on the
    bands of :data:`BAND` rows numbered ``start``, ``start + step`` ... (calls with
    ``start`` = 0 .. step - 1 share the work: each pixel is written by one of them).

    ``world``, ``normals``, ``colors``: (F, 3, 3) per face vertex (VERTEX: ``colors``
    holds the vertex intensities and the other two are not read); ``front`` (F,) the
    back-face test; ``face_mat`` (F,) the material row of each face in ``mats`` (M, 8:
    :func:`scanline.shading.buffer.material_rows`); ``ambient`` (3,) the summed
    ambient intensity; ``sources`` (S, 16); ``eye`` (4,) homogeneous; ``table``
    (GAMMA_STEPS,) int64 and ``thresholds`` (257,) the gamma encoding
    (:func:`encode`).  Each row's linear intensities go to a row
    buffer first, then are encoded and stored."""
    height, width = faces.shape
    nf = colors.shape[0]
    lin = np.empty((width, 3))
    # per source: the unit vector toward a light at infinity (w = 0) and its
    # attenuation, the same at every point (the per-point formula's values)
    ns = sources.shape[0]
    far = np.empty((ns, 4))
    for s in range(ns):
        d = math.sqrt(sources[s, 0] * sources[s, 0] + sources[s, 1] * sources[s, 1]
                      + sources[s, 2] * sources[s, 2])
        far[s, 3] = min(1.0, 1.0 / (sources[s, 4] + sources[s, 5] * d + sources[s, 6] * d * d))
        r = 1.0 / d if d > 0 else 0.0
        for ch in range(3):
            far[s, ch] = sources[s, ch] * r
    for lo in range(start * BAND, height, max(step, 1) * BAND):
        for y in range(lo, min(lo + BAND, height)):
            if len(shading) == VERTEX:
                vertex_row(y, faces, bary, colors, lin)
            else:
                phong_row(y, faces, bary, world, normals, colors, front, face_mat, mats,
                          ambient, sources, far, eye, lin, spec)
            for x in range(width):
                f = faces[y, x]
                if f < 0 or f >= nf:
                    continue
                if len(mode) == GRAY:
                    raster[y, x, 0] = encode(0.299 * lin[x, 0] + 0.587 * lin[x, 1]
                                             + 0.114 * lin[x, 2], table, thresholds)
                else:
                    for ch in range(3):
                        raster[y, x, ch] = encode(lin[x, ch], table, thresholds)
                    if len(mode) == RGBA:
                        raster[y, x, 3] = 255


@helper
def vertex_row(y, faces, bary, colors, lin):
    """Row ``y`` of the interpolated vertex intensities, I = sum lambda_i I_i."""
    nf = colors.shape[0]
    for x in range(faces.shape[1]):
        f = faces[y, x]
        if f < 0 or f >= nf:
            continue
        l1 = bary[y, x, 0]
        l2 = bary[y, x, 1]
        l0 = 1.0 - l1 - l2
        for ch in range(3):
            lin[x, ch] = l0 * colors[f, 0, ch] + l1 * colors[f, 1, ch] + l2 * colors[f, 2, ch]


@helper
def phong_row(y, faces, bary, world, normals, colors, front, face_mat, mats, ambient, sources,
              far, eye, lin, spec):
    """Row ``y`` of Phong shading: the model at each pixel's point with the
    interpolated, renormalized normal (``far``: the lights at infinity, see
    :func:`shade_pixels`)."""
    nf = colors.shape[0]
    last = mats.shape[0] - 1
    for x in range(faces.shape[1]):
        f = faces[y, x]
        if f < 0 or f >= nf:
            continue
        l1 = bary[y, x, 0]
        l2 = bary[y, x, 1]
        l0 = 1.0 - l1 - l2
        px = l0 * world[f, 0, 0] + l1 * world[f, 1, 0] + l2 * world[f, 2, 0]
        py = l0 * world[f, 0, 1] + l1 * world[f, 1, 1] + l2 * world[f, 2, 1]
        pz = l0 * world[f, 0, 2] + l1 * world[f, 1, 2] + l2 * world[f, 2, 2]
        nx = l0 * normals[f, 0, 0] + l1 * normals[f, 1, 0] + l2 * normals[f, 2, 0]
        ny = l0 * normals[f, 0, 1] + l1 * normals[f, 1, 1] + l2 * normals[f, 2, 1]
        nz = l0 * normals[f, 0, 2] + l1 * normals[f, 1, 2] + l2 * normals[f, 2, 2]
        cr = l0 * colors[f, 0, 0] + l1 * colors[f, 1, 0] + l2 * colors[f, 2, 0]
        cg = l0 * colors[f, 0, 1] + l1 * colors[f, 1, 1] + l2 * colors[f, 2, 1]
        cb = l0 * colors[f, 0, 2] + l1 * colors[f, 1, 2] + l2 * colors[f, 2, 2]
        nn = math.sqrt(nx * nx + ny * ny + nz * nz)
        if not front[f]:
            nn = -nn
        r = 1.0 / nn if nn != 0 else 0.0
        nx *= r
        ny *= r
        nz *= r
        m = min(max(face_mat[f], 0), last)
        ka = mats[m, 0]
        kd = mats[m, 1]
        ks = mats[m, 2]
        shininess = mats[m, 3]
        ir = ka * cr * ambient[0]
        ig = ka * cg * ambient[1]
        ib = ka * cb * ambient[2]
        vx = eye[0] - eye[3] * px
        vy = eye[1] - eye[3] * py
        vz = eye[2] - eye[3] * pz
        vl = math.sqrt(vx * vx + vy * vy + vz * vz)
        r = 1.0 / vl if vl > 0 else 0.0
        vx *= r
        vy *= r
        vz *= r
        for s in range(sources.shape[0]):
            if sources[s, 3] == 0.0:
                lx = far[s, 0]
                ly = far[s, 1]
                lz = far[s, 2]
                fl = far[s, 3]
            else:
                lx = sources[s, 0] - sources[s, 3] * px
                ly = sources[s, 1] - sources[s, 3] * py
                lz = sources[s, 2] - sources[s, 3] * pz
                d = math.sqrt(lx * lx + ly * ly + lz * lz)
                fl = min(1.0, 1.0 / (sources[s, 4] + sources[s, 5] * d + sources[s, 6] * d * d))
                r = 1.0 / d if d > 0 else 0.0
                lx *= r
                ly *= r
                lz *= r
            if sources[s, 9] > 0:
                cos = -(lx * sources[s, 10] + ly * sources[s, 11] + lz * sources[s, 12])
                if cos >= sources[s, 7]:
                    fl *= min(max(cos, 0.0), 1.0) ** sources[s, 8]
                else:
                    fl = 0.0
            nl = nx * lx + ny * ly + nz * lz
            if not nl > 0:
                continue
            if len(spec) == SPEC_PHONG:
                sv = (vx * (2.0 * nl * nx - lx) + vy * (2.0 * nl * ny - ly)
                      + vz * (2.0 * nl * nz - lz))
            else:
                hx = lx + vx
                hy = ly + vy
                hz = lz + vz
                hl = math.sqrt(hx * hx + hy * hy + hz * hz)
                sv = (nx * hx + ny * hy + nz * hz) / hl if hl > 0 else 0.0
            shine = ks * min(sv, 1.0) ** shininess if sv > mats[m, 7] else 0.0
            diffuse = kd * nl
            ir += fl * sources[s, 13] * (diffuse * cr + shine * mats[m, 4])
            ig += fl * sources[s, 14] * (diffuse * cg + shine * mats[m, 5])
            ib += fl * sources[s, 15] * (diffuse * cb + shine * mats[m, 6])
        lin[x, 0] = ir
        lin[x, 1] = ig
        lin[x, 2] = ib
