"""Shading a visibility buffer (Hearn & Baker, sections 14-2 and 14-5): every pixel
whose visible face and barycentric coordinates are known gets its intensity and is
stored, gamma-encoded, in the frame buffer.  The rows are shared out in bands
between calls running on several threads (:func:`shade_pixels` takes every
step-th band; the API layer starts the threads, the kernel releases the GIL): a
``prange`` kernel took 1.5 s more to compile.  A row is shaded in chunks of
:data:`CHUNK` covered pixels: a first loop finds each pixel's face and barycentric
coordinates and interpolates its attributes into a planar scratch array (one field
after the other, :data:`FIELDS` of them), then the illumination runs over the chunk
field by field, light after light, in loops without branches that the compiler
turns into vector instructions (several pixels per instruction); the encoding and
the store come last.  A light at infinity's direction and attenuation are computed
once per call, and where every material has the same whole-number exponent n_s
below 256 (the common case) s^n_s is found by repeated squaring inside the lighting
loop instead of a power (equal to the power to a few units in the last place);
other exponents are raised by the power in a pass of their own.

What is shaded: a buffer of the drawn triangles' indices (a visibility buffer:
the z-buffer's id buffer, :data:`scanline._kernels.raster3d.IDS`, or any method's
:class:`~scanline.visible.visibility.Layer`), with per triangle the screen-space
functions of its attributes times 1/w and of 1/w (:func:`triangle_attributes`) and
its facet: the attributes are evaluated where the pixel is shaded, once, for the
visible triangle only, and the facet's index replaces the triangle's in the buffer.

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

from ._jit import helper, inline, kernel
from .raster3d import SETUP_BATCH, planes
from .variants import GRAY, RGBA, token

#: Rows per band of :func:`shade_pixels` (the bands are shaded in parallel, every
#: step-th band by one thread).  Narrow bands share uneven work evenly: with the
#: teapot's measured cost of each row (2026-12-07, benchmarks' teapot at 1920 x 1080),
#: 16 threads would each shade at most 1/15.0 of the frame with bands of 8 rows,
#: against 1/12.8 with 32 (a model: no 16-core machine was at hand); a band costs
#: nothing of its own, as a row is shaded alone.
BAND = 8

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

#: Covered pixels shaded together.  Each chunk calls the lighting and the store once,
#: and a call takes the reference counts of the arrays it is handed; with 256 the
#: fields of a chunk (FIELDS x CHUNK reals, 57 KB) leave the first-level cache for
#: the second, and the teapot's shading took about 5% less time than with 128 (four
#: runs against two; 512: no gain), in turn in one process on one core, measured
#: 2026-12-07.
CHUNK = 256

#: The scratch fields of a chunk (field f of pixel i at ``f * CHUNK + i``): the
#: point, the normal, the surface color (a mesh's own colors), the direction to the
#: viewer, kd S_d, ks S_s, the intensity summed so far, the direction to the light
#: and its factor f_l, N . L (0 where not lit), the highlight (0 where it does not
#: count; before the power, its base s), and 1/w (:func:`shade_row` leaves the point
#: and the normal times 1/w: see :func:`light_chunk`).  Flat and Gouraud shading
#: interpolate the vertex intensities into the first three.
PX, PY, PZ = 0, 1, 2
NX, NY, NZ = 3, 4, 5
CR, CG, CB = 6, 7, 8
VX, VY, VZ = 9, 10, 11
DR, DG, DB = 12, 13, 14
SR, SG, SB = 15, 16, 17
IR, IG, IB = 18, 19, 20
LX, LY, LZ, FL = 21, 22, 23, 24
NL, POW = 25, 26
QW = 27
FIELDS = 28

#: The bits of the whole exponents n_s raised by repeated squaring inside the
#: lighting loop (larger ones, fractions and exponents that differ between the
#: materials are raised by the power, in a pass of their own).
SMALL_BITS = 8


@inline
def encode(value, table, thresholds):
    """round(255 clamp(I, 0, 1)^(1/gamma)) without a power: ``table[j]`` is the stored
    value of I = j / (GAMMA_STEPS - 1), a lower bound for any I in the step (as -2 -
    that value where the step spans more than one stored value: the fast path of
    :func:`store_chunk` is wrong there), raised while I reaches the next value's
    threshold ``thresholds[v + 1]`` = ((v + 1/2) / 255)^gamma (``thresholds[256]`` =
    inf); NaN stores 0."""
    i = value
    if not i > 0.0:
        i = 0.0
    if i > 1.0:
        i = 1.0
    j = min(int(i * (GAMMA_STEPS - 1)), GAMMA_STEPS - 1)
    v = table[j]
    v = v if v >= 0 else -2 - v
    while v < 255 and i >= thresholds[v + 1]:
        v += 1
    return np.uint8(v)


@helper
def table_starts(tri, q, bary, tface, nf, e0, e1, g, ok, table):
    """The start of rows ``e0 .. e1 - 1`` of an attribute table: x0, y0 (the
    triangle's vertex 0) and the (value, d/dx, d/dy) of 1/w, with the rasterizer's
    functions of triangle ``t`` in ``g[t - e0]``
    (:func:`~scanline._kernels.raster3d.planes`).  ``ok[t - e0]`` False, the row
    all NaN, for a triangle that covers no pixel or whose facet is not below
    ``nf``."""
    planes(tri, q, bary, e0, e1, g, ok)
    for t in range(e0, e1):
        s = t - e0
        f = tface[t]
        if not (ok[s] and f >= 0 and f < nf):
            ok[s] = False
            for j in range(table.shape[1]):
                table[t, j] = math.nan
            continue
        table[t, 0] = tri[t, 0, 0]
        table[t, 1] = tri[t, 0, 1]
        for c in range(3):
            table[t, 2 + c] = g[s, 1, c]


@kernel
def triangle_attributes(lo, hi, tri, q, bary, tface, world, normals, colors, front, table,
                        shading):
    """Per drawn triangle ``t`` in ``lo .. hi - 1`` the
    screen-space functions of its attributes times 1/w, so that a pixel's attributes
    are (their functions at (x - x0, y - y0)) / (1/w's): ``table[t]`` = x0, y0 (its
    vertex 0), (value, d/dx, d/dy) of 1/w, then of each attribute: PHONG the point,
    the normal (turned toward the viewer on a back face) and, where ``colors`` has
    rows, the surface color (5 + 3 x 9 columns, or 5 + 3 x 6 without colors); VERTEX
    the vertex intensities of ``colors`` (5 + 3 x 3).  ``tri``, ``q`` and ``bary``
    (T, 3, 2) as the rasterizer takes them (:mod:`scanline._kernels.raster3d`, the
    barycentrics as the attributes), ``tface`` (T,) the triangles' faces.  The
    rasterizer's :func:`~scanline._kernels.raster3d.planes` gives the functions of
    1/w, lambda_1 / w and lambda_2 / w; an attribute A is A_0 + lambda_1 (A_1 - A_0)
    + lambda_2 (A_2 - A_0), so its function times 1/w is A_0 (1/w) + (A_1 - A_0)
    (lambda_1 / w) + (A_2 - A_0) (lambda_2 / w).  A triangle that covers no pixel,
    or of no face, gets NaN."""
    nf = front.shape[0]
    kk = (table.shape[1] - 5) // 3
    g = np.empty((SETUP_BATCH, 4, 3))
    ok = np.empty(SETUP_BATCH, np.bool_)
    for t in range(lo, hi):
        s = (t - lo) % SETUP_BATCH
        if s == 0:
            table_starts(tri, q, bary, tface, nf, t, min(t + SETUP_BATCH, hi), g, ok, table)
        if not ok[s]:
            continue
        f = tface[t]
        flip = 1.0 if front[f] else -1.0
        for a in range(kk):
            ch = a % 3
            if len(shading) == VERTEX:
                v0 = colors[f, 0, ch]
                v1 = colors[f, 1, ch]
                v2 = colors[f, 2, ch]
            elif a < 3:
                v0 = world[f, 0, ch]
                v1 = world[f, 1, ch]
                v2 = world[f, 2, ch]
            elif a < 6:
                v0 = flip * normals[f, 0, ch]
                v1 = flip * normals[f, 1, ch]
                v2 = flip * normals[f, 2, ch]
            else:
                v0 = colors[f, 0, ch]
                v1 = colors[f, 1, ch]
                v2 = colors[f, 2, ch]
            d1 = v1 - v0
            d2 = v2 - v0
            for c in range(3):
                table[t, 5 + 3 * a + c] = v0 * g[s, 1, c] + d1 * g[s, 2, c] + d2 * g[s, 3, c]


@kernel
def shade_pixels(start, step, faces, table, tface, face_mat, mats, ambient, sources, eye,
                 gamma_table, thresholds, raster, shading, spec, mode):
    """Shade every pixel (y, x) with a visible triangle into ``raster[y, x]``, on the
    bands of :data:`BAND` rows numbered ``start``, ``start + step`` ... (calls with
    ``start`` = 0 .. step - 1 share the work: each pixel is written by one of them).

    ``faces[y, x]`` is the triangle drawn there (-1: none), ``table`` its
    attributes' functions (:func:`triangle_attributes`) and ``tface`` (T,) its
    facet, which replaces it in ``faces``.  ``face_mat`` (G,) the material row of
    each facet in ``mats`` (M, 11: :func:`scanline.shading.buffer.material_rows`);
    ``ambient`` (3,) the summed ambient intensity; ``sources`` (S, 16); ``eye`` (4,)
    homogeneous; ``gamma_table`` (GAMMA_STEPS,) int64 and ``thresholds`` (257 +
    GAMMA_STEPS,) the gamma encoding (:func:`encode`, :func:`store_chunk`).  PHONG
    without the surface color among the attributes (a table of 5 + 3 x 6 columns):
    each facet takes its material's color."""
    height = faces.shape[0]
    far, expo, gray = light_setup(sources, mats, ambient)
    # zeros, not uninitialized memory: the lighting's vectorized loops may compute a
    # field they then discard (a gray light's green and blue sums, never written), and
    # memory left as it was can hold subnormal numbers, whose arithmetic takes the
    # processor's slow microcode path (the teapot at 3840 x 2160 shaded 5x slower in
    # half the processes, measured 2026-12-08)
    scratch = np.zeros(FIELDS * CHUNK)
    xs = np.empty(CHUNK, np.int64)
    ms = np.empty(CHUNK, np.int64)
    for lo in range(start * BAND, height, max(step, 1) * BAND):
        for y in range(lo, min(lo + BAND, height)):
            shade_row(y, faces, table, tface, face_mat, mats, ambient, sources, far, eye, expo,
                      gray, gamma_table, thresholds, raster, scratch, xs, ms, shading, spec,
                      mode)


@helper
def light_setup(sources, mats, ambient):
    """What every pixel's lighting shares: per source the unit vector toward a light
    at infinity (w = 0) and its attenuation, the same at every point (the per-point
    formula's values), (S, 4); the one whole exponent n_s below
    2^:data:`SMALL_BITS` of every material, raised by repeated squaring (-1: the
    materials' exponents differ, or are not whole or not that small); and whether
    the light is gray (:func:`light_chunk`): the S_d and S_s of every material have
    three equal components, as have the ambient intensity and every source's."""
    ns = sources.shape[0]
    far = np.empty((ns, 4))
    for s in range(ns):
        d = math.sqrt(sources[s, 0] * sources[s, 0] + sources[s, 1] * sources[s, 1]
                      + sources[s, 2] * sources[s, 2])
        far[s, 3] = min(1.0, 1.0 / (sources[s, 4] + sources[s, 5] * d + sources[s, 6] * d * d))
        r = 1.0 / d if d > 0 else 0.0
        for ch in range(3):
            far[s, ch] = sources[s, ch] * r
    # one small whole exponent for every material: raised by squaring (-1: not)
    expo = -1
    if mats.shape[0] > 0:
        n0 = mats[0, 3]
        same = n0 >= 0.0 and n0 < (1 << SMALL_BITS) and n0 == math.floor(n0)
        for m in range(1, mats.shape[0]):
            if mats[m, 3] != n0:
                same = False
        if same:
            expo = int(n0)
    gray = ambient[0] == ambient[1] == ambient[2]
    for m in range(mats.shape[0]):
        if not (mats[m, 8] == mats[m, 9] == mats[m, 10] and mats[m, 4] == mats[m, 5] == mats[m, 6]):
            gray = False
    for s in range(ns):
        if not sources[s, 13] == sources[s, 14] == sources[s, 15]:
            gray = False
    return far, expo, gray


@helper
def shade_row(y, faces, table, tface, face_mat, mats, ambient, sources, far, eye, expo,
              gray, gamma_table, thresholds, raster, s, xs, ms, shading, spec, mode):
    """Row ``y``, chunk after chunk of :data:`CHUNK` covered pixels: each pixel's
    facet and attributes (the point, the normal and the color; VERTEX: the
    interpolated intensity, I = sum lambda_i I_i), then the illumination
    (:func:`light_chunk`), the encoding and the store.  A run of pixels of one
    triangle loads its functions once."""
    width = faces.shape[1]
    nf = face_mat.shape[0]
    # the attributes interpolated: PHONG fields PX .. NZ (and CR .. CB), VERTEX 0 .. 2
    kk = (table.shape[1] - 5) // 3
    own = kk > 6
    x = np.int64(0)
    while x < width:
        n = np.int64(0)    # (a literal 0 would compile store_chunk twice)
        while n < CHUNK and x < width:
            x, end, t, f = triangle_run(faces, tface, nf, y, x, CHUNK - n)
            if f < 0:
                x = end
                continue
            m = face_mat[f]
            x0 = table[t, 0]
            fy = y - table[t, 1]
            q0 = table[t, 2] + table[t, 4] * fy
            qx = table[t, 3]
            # PHONG: P, N (and C); VERTEX: I (fields 0 .. 2)
            a0 = table[t, 5] + table[t, 7] * fy
            ax = table[t, 6]
            b0 = table[t, 8] + table[t, 10] * fy
            bx = table[t, 9]
            c0 = table[t, 11] + table[t, 13] * fy
            cx = table[t, 12]
            if kk > 3:
                d0 = table[t, 14] + table[t, 16] * fy
                dx = table[t, 15]
                e0 = table[t, 17] + table[t, 19] * fy
                ex = table[t, 18]
                g0 = table[t, 20] + table[t, 22] * fy
                gx = table[t, 21]
            else:
                d0 = dx = e0 = ex = g0 = gx = 0.0
            for at in range(x, end):
                i = np.uint64(n + at - x)
                fx = at - x0
                qw = q0 + qx * fx
                if len(shading) == PHONG:
                    # P and N times 1/w, and 1/w (no division: light_chunk)
                    s[i] = a0 + ax * fx
                    s[np.uint64(CHUNK) + i] = b0 + bx * fx
                    s[np.uint64(2 * CHUNK) + i] = c0 + cx * fx
                    s[np.uint64(3 * CHUNK) + i] = d0 + dx * fx
                    s[np.uint64(4 * CHUNK) + i] = e0 + ex * fx
                    s[np.uint64(5 * CHUNK) + i] = g0 + gx * fx
                    s[np.uint64(QW * CHUNK) + i] = qw
                else:
                    r = 1.0 / qw
                    s[i] = (a0 + ax * fx) * r
                    s[np.uint64(CHUNK) + i] = (b0 + bx * fx) * r
                    s[np.uint64(2 * CHUNK) + i] = (c0 + cx * fx) * r
                xs[i] = at
                ms[i] = m
            if kk > 6:
                a0 = table[t, 23] + table[t, 25] * fy
                ax = table[t, 24]
                b0 = table[t, 26] + table[t, 28] * fy
                bx = table[t, 27]
                c0 = table[t, 29] + table[t, 31] * fy
                cx = table[t, 30]
                for at in range(x, end):
                    i = np.uint64(n + at - x)
                    fx = at - x0
                    r = 1.0 / (q0 + qx * fx)
                    s[np.uint64(CR * CHUNK) + i] = (a0 + ax * fx) * r
                    s[np.uint64(CG * CHUNK) + i] = (b0 + bx * fx) * r
                    s[np.uint64(CB * CHUNK) + i] = (c0 + cx * fx) * r
            n += end - x
            x = end
        if n == 0:
            continue
        if len(shading) == PHONG:
            light_chunk(n, s, ms, own, mats, ambient, sources, far, eye, expo, spec,
                        np.bool_(True), gray and not own)
        store_chunk(y, n, s, xs, gamma_table, thresholds, raster, shading, mode,
                    gray and not own)


@inline
def triangle_run(faces, tface, nf, y, x, room):
    """The next run of row ``y`` of ``faces`` from column ``x`` that one triangle
    covers, at most ``room`` pixels: ``(start, end, t, f)``, the triangle t and its
    facet f (-1 when t has none below ``nf``), which replaces t in ``faces`` along the
    run; pixels of no triangle (-1) before it are skipped (start = end = the width
    when none is left).  Inlined: called once a run, about 90,000 times in the
    teapot's frame, it took the reference counts of its two arrays each time (the
    shading about 3% less time on one core, in turn in one process, measured
    2026-12-07)."""
    width = faces.shape[1]
    row = np.uint64(y)
    while x < width and faces[row, np.uint64(x)] < 0:
        x += 1
    if x >= width:
        return width, width, -1, -1
    t = faces[row, np.uint64(x)]
    f = tface[t] if t < tface.shape[0] else -1
    if f >= nf:
        f = -1
    end = x
    most = min(width, x + room)
    while end < most and faces[row, np.uint64(end)] == t:
        faces[row, np.uint64(end)] = f
        end += 1
    return x, end, t, f


@helper
def store_chunk(y, n, s, xs, gamma_table, thresholds, raster, shading, mode, gray):
    """The chunk's intensities encoded (:func:`encode`) and stored at row ``y``,
    columns ``xs``: the table's value and one step up without a branch where the
    table's step spans at most one stored value (its entry is not negative), the
    rest of :func:`encode`'s climb only where it spans more (near black).  The
    threshold of that one step up is read from the step's own copy of it
    (``thresholds[257 + step]``, :func:`scanline.shading.buffer.gamma_tables`):
    both reads then depend on the intensity only, not the second on the first (the
    teapot's frame 3-5% less time on one core, measured 2026-12-07).  The scratch is
    read at unsigned offsets (the teapot's shading kernel 17.0 -> 16.1 ms on one
    core, measured 2026-12-07; the same in the lighting loops changed nothing).
    ``gray`` with PHONG: the intensity is field :data:`IR` alone (:func:`light_chunk`),
    encoded once a pixel and stored into each channel."""
    first = IR if len(shading) == PHONG else 0
    one = gray and len(shading) == PHONG        # (here: the argument stays a value)
    second = first if one else first + 1
    third = first if one else first + 2
    channels = 1 if len(mode) == GRAY or one else 3
    top = GAMMA_STEPS - 1
    row = np.uint64(y)
    for j in range(n):
        i = np.uint64(j)            # (unsigned: no wrap-around of negative indices)
        at = np.uint64(xs[i])
        for ch in range(channels):
            if len(mode) == GRAY:
                value = (0.299 * s[np.uint64(first * CHUNK) + i]
                         + 0.587 * s[np.uint64(second * CHUNK) + i]
                         + 0.114 * s[np.uint64(third * CHUNK) + i])
            else:
                value = s[np.uint64((first + ch) * CHUNK) + i]
            iv = value if value > 0.0 else 0.0
            iv = min(iv, 1.0)
            step = np.uint64(int(iv * top))
            e = gamma_table[step]
            if e < 0:
                v = encode(value, gamma_table, thresholds)
            else:
                v = np.uint8(e + (iv >= thresholds[np.uint64(257) + step]))
            raster[row, at, ch] = v
            if one and len(mode) != GRAY:
                raster[row, at, 1] = v
                raster[row, at, 2] = v
        if len(mode) == RGBA:
            raster[row, at, 3] = 255


@helper
def light_chunk(n, s, ms, own, mats, ambient, sources, far, eye, expo, spec, scaled, gray):
    """The illumination of the ``n`` pixels of a chunk (fields of ``s``, materials
    ``ms``): the normals made unit vectors (N = 0 stays 0), the directions to the
    viewer and the material's terms, then light after light N . L, the highlight and
    their sum into the intensity fields.

    ``scaled``: the fields hold the point and the normal times q = 1/w, and q in
    field :data:`QW`, as the triangles' functions give them (perspective-correct
    interpolation without its division, Blinn 1992).  A direction does not change when
    multiplied by q > 0: N q is normalized as it is, and V = unit(E - e_w p) =
    unit(E q - e_w (p q)); only a light at a point (:func:`light_fields`) needs the
    point itself, p = (p q) / q.  (Saves a division a pixel, the costliest step with
    the square roots: measured 2026-12-07.)  The loops have no branches (a condition
    selects a value), so the compiler vectorizes them; a spot light's cone and a
    non-whole exponent are the loops it cannot.  With one material and no colors of
    the mesh's own the material's terms are constants; with a light at infinity its
    direction is; with a whole exponent below 2^:data:`SMALL_BITS` the highlight is
    raised in the same loop, bit after bit, else its base is kept and raised by the
    power in a loop of its own.  (One per-light loop serves both: the loop of the
    highlight raised in place and the three of the power each had their own copy of
    N . L and of the specular term, and took 2 of the kernel's 10 s of compilation,
    measured 2026-12-07.)

    ``gray`` (:func:`light_setup`; never with colors of the mesh's own): the three
    components of every term are equal, so are the three sums, and only the red one
    is computed (field :data:`IR`, which :func:`store_chunk` then encodes once and
    stores into the three channels): the same values, a third of the work of the
    sums and of the encoding.  A white light on a gray material is the common case
    (the benchmarks' teapot: its frame 1.09-1.12x as fast on two threads, the
    shading alone 1.18-1.21x, the same pixels, in turn in one process,
    2026-12-08)."""
    e0 = eye[0]
    e1 = eye[1]
    e2 = eye[2]
    e3 = eye[3]
    last = mats.shape[0] - 1
    one = last == 0 and not own
    if last >= 0:
        ar = mats[0, 0] * ambient[0] * mats[0, 8]
        ag = mats[0, 0] * ambient[1] * mats[0, 9]
        ab = mats[0, 0] * ambient[2] * mats[0, 10]
    else:
        ar = ag = ab = 0.0
    for i in range(n):
        nx = s[NX * CHUNK + i]
        ny = s[NY * CHUNK + i]
        nz = s[NZ * CHUNK + i]
        nn = math.sqrt(nx * nx + ny * ny + nz * nz)
        r = 1.0 / nn if nn != 0 else 0.0
        s[NX * CHUNK + i] = nx * r
        s[NY * CHUNK + i] = ny * r
        s[NZ * CHUNK + i] = nz * r
        qw = s[QW * CHUNK + i] if scaled else 1.0
        vx = e0 * qw - e3 * s[PX * CHUNK + i]
        vy = e1 * qw - e3 * s[PY * CHUNK + i]
        vz = e2 * qw - e3 * s[PZ * CHUNK + i]
        vl = math.sqrt(vx * vx + vy * vy + vz * vz)
        r = 1.0 / vl if vl > 0 else 0.0
        s[VX * CHUNK + i] = vx * r
        s[VY * CHUNK + i] = vy * r
        s[VZ * CHUNK + i] = vz * r
        s[IR * CHUNK + i] = ar
        if not gray:
            s[IG * CHUNK + i] = ag
            s[IB * CHUNK + i] = ab
    kd = ks = 0.0
    if one:
        kd = mats[0, 1]
        ks = mats[0, 2]
    elif last == 0:
        for ch in range(3):
            ka = mats[0, 0] * ambient[ch]
            kd = mats[0, 1]
            spec_ch = mats[0, 2] * mats[0, 4 + ch]
            for i in range(n):
                cc = s[(CR + ch) * CHUNK + i]
                s[(DR + ch) * CHUNK + i] = kd * cc
                s[(SR + ch) * CHUNK + i] = spec_ch
                s[(IR + ch) * CHUNK + i] = ka * cc
    else:
        for i in range(n):
            m = min(max(ms[i], 0), last)
            ms[i] = m
            for ch in range(1 if gray else 3):
                cc = s[(CR + ch) * CHUNK + i] if own else mats[m, 8 + ch]
                s[(DR + ch) * CHUNK + i] = mats[m, 1] * cc
                s[(SR + ch) * CHUNK + i] = mats[m, 2] * mats[m, 4 + ch]
                s[(IR + ch) * CHUNK + i] = mats[m, 0] * ambient[ch] * cc
    # the constant terms (one material): kd S_d and ks S_s
    dr = dg = db = sr = sg = sb = 0.0
    if one:
        dr = kd * mats[0, 8]
        dg = kd * mats[0, 9]
        db = kd * mats[0, 10]
        sr = ks * mats[0, 4]
        sg = ks * mats[0, 5]
        sb = ks * mats[0, 6]
    # the highlight counts where s > SHINE_FLOOR^(1/n_s) (mats[:, 7]); the materials'
    # own thresholds are applied where the power is raised
    small = expo >= 0
    gate = mats[0, 7] if last >= 0 and (small or last == 0) else 0.0
    for src in range(sources.shape[0]):
        cx = far[src, 0]
        cy = far[src, 1]
        cz = far[src, 2]
        cf = far[src, 3]
        # a light at a point, or a spot light: its direction and factor per pixel
        per = sources[src, 3] != 0.0 or sources[src, 9] > 0
        if per:
            light_fields(n, s, sources, far, src, scaled)
        ir = sources[src, 13]
        ig = sources[src, 14]
        ib = sources[src, 15]
        for i in range(n):
            nx = s[NX * CHUNK + i]
            ny = s[NY * CHUNK + i]
            nz = s[NZ * CHUNK + i]
            vx = s[VX * CHUNK + i]
            vy = s[VY * CHUNK + i]
            vz = s[VZ * CHUNK + i]
            # fields read whether used or not: a select, not a branch, in the loop
            px = s[LX * CHUNK + i]
            py = s[LY * CHUNK + i]
            pz = s[LZ * CHUNK + i]
            lx = px if per else cx
            ly = py if per else cy
            lz = pz if per else cz
            nl = nx * lx + ny * ly + nz * lz
            if len(spec) == SPEC_PHONG:
                sv = (vx * (2.0 * nl * nx - lx) + vy * (2.0 * nl * ny - ly)
                      + vz * (2.0 * nl * nz - lz))
            else:
                hx = lx + vx
                hy = ly + vy
                hz = lz + vz
                hl = math.sqrt(hx * hx + hy * hy + hz * hz)
                sv = (nx * hx + ny * hy + nz * hz) / hl if hl > 0 else 0.0
            lit = nl > 0
            on = lit and sv > gate
            base = min(sv, 1.0)
            # the highlight: s^n_s by repeated squaring (one small whole exponent); else
            # the base, raised in the next loop (a power would keep this one from
            # being vectorized)
            shine = 1.0
            for bit in range(SMALL_BITS):
                if (expo >> bit) & 1 and small:
                    shine *= base
                base *= base
            shine = shine if small else min(sv, 1.0)
            s[POW * CHUNK + i] = shine if on else 0.0
            s[NL * CHUNK + i] = nl if lit else 0.0
        if not small:
            for i in range(n):
                m = 0 if last == 0 else ms[i]
                b = s[POW * CHUNK + i]
                s[POW * CHUNK + i] = b ** mats[m, 3] if b > mats[m, 7] else 0.0
        for i in range(n):
            shine = s[POW * CHUNK + i]
            nl = s[NL * CHUNK + i]
            pf = s[FL * CHUNK + i]
            fl = pf if per else cf
            pr = s[DR * CHUNK + i]
            pg = s[DG * CHUNK + i]
            pb = s[DB * CHUNK + i]
            qr = s[SR * CHUNK + i]
            qg = s[SG * CHUNK + i]
            qb = s[SB * CHUNK + i]
            s[IR * CHUNK + i] += fl * ir * (nl * (dr if one else pr) + shine * (sr if one else qr))
            if not gray:
                s[IG * CHUNK + i] += fl * ig * (nl * (dg if one else pg)
                                                + shine * (sg if one else qg))
                s[IB * CHUNK + i] += fl * ib * (nl * (db if one else pb)
                                                + shine * (sb if one else qb))


@helper
def light_fields(n, s, sources, far, src, scaled):
    """The direction to light ``src`` and its factor f_l at each pixel of a chunk
    (fields LX, LY, LZ, FL): L = unit(P - w p), f_l = min(1, 1 / (a0 + a1 d + a2
    d^2)), times a spot light's cone factor (``scaled``: the point p is (p q) / q,
    :func:`light_chunk`)."""
    if sources[src, 3] == 0.0:
        lx = far[src, 0]
        ly = far[src, 1]
        lz = far[src, 2]
        fl = far[src, 3]
        for i in range(n):
            s[LX * CHUNK + i] = lx
            s[LY * CHUNK + i] = ly
            s[LZ * CHUNK + i] = lz
            s[FL * CHUNK + i] = fl
    else:
        qx = sources[src, 0]
        qy = sources[src, 1]
        qz = sources[src, 2]
        qw = sources[src, 3]
        a0 = sources[src, 4]
        a1 = sources[src, 5]
        a2 = sources[src, 6]
        for i in range(n):
            w = 1.0 / s[QW * CHUNK + i] if scaled else 1.0
            lx = qx - qw * (s[PX * CHUNK + i] * w)
            ly = qy - qw * (s[PY * CHUNK + i] * w)
            lz = qz - qw * (s[PZ * CHUNK + i] * w)
            d = math.sqrt(lx * lx + ly * ly + lz * lz)
            s[FL * CHUNK + i] = min(1.0, 1.0 / (a0 + a1 * d + a2 * d * d))
            r = 1.0 / d if d > 0 else 0.0
            s[LX * CHUNK + i] = lx * r
            s[LY * CHUNK + i] = ly * r
            s[LZ * CHUNK + i] = lz * r
    if sources[src, 9] > 0:                     # a spot light's cone
        for i in range(n):
            cos = -(s[LX * CHUNK + i] * sources[src, 10] + s[LY * CHUNK + i] * sources[src, 11]
                    + s[LZ * CHUNK + i] * sources[src, 12])
            if cos >= sources[src, 7]:
                s[FL * CHUNK + i] *= min(max(cos, 0.0), 1.0) ** sources[src, 8]
            else:
                s[FL * CHUNK + i] = 0.0
