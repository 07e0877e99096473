"""The recursive ray tracer as a compiled kernel with an explicit stack (Whitted
1980; Hearn & Baker 14-6, "basic ray-tracing algorithm").

Each sample's primary ray has its first surface already (the ray-casting method's,
the same ray) and its local intensity (the shading stage's, with this module's
shadow rays as its shadow test: :func:`shadow_all`); from there the binary ray tree
is walked depth first with a stack of rays instead of recursion.  At every further
hit point p the local intensity is the basic illumination model (Hearn & Baker 14-2,
as Phong shading evaluates it: the normal interpolated, the viewer along the
incoming ray), with every light's term multiplied by what a shadow ray from p toward
it lets through (0 behind an opaque surface, the product of the k_t of transparent
ones); an area light's term is its center's, times the mean of jittered shadow rays
to each cell of its grid (Cook, Porter and Carpenter 1984).  Then

    I = (1 - k_t) I_local + (k_r S_s + k_t F) I_reflected + k_t (1 - F) I_transmitted

(per color component: the reflected term of the recursive model has the specular
coefficient, here k_r, and is tinted by the specular color S_s, as a highlight is),
with F the Fresnel reflectance of the interface (the full Fresnel equations for
unpolarized light, :func:`fresnel`), the reflected ray in the mirror direction R =
d + 2 (N . -d) N, spread over a cone of half-angle ``roughness`` for glossy
surfaces (distributed ray tracing), and the transmitted ray bent by Snell's law,
T = (eta_i / eta_t) d + ((eta_i / eta_t) cos i - cos t) N, cos t = sqrt(1 - (eta_i /
eta_t)^2 (1 - cos^2 i)) (Hearn & Baker eq. 14-33); when the root is imaginary the
light is totally reflected (F = 1).  A ray entering a surface against its outward
normal goes from air (1) into the material's ``refractive_index``; one leaving it,
back.  A ray that leaves the scene brings the color of the environment map
(:mod:`scanline._kernels.environment`) of the surface it left in its direction, or
the background's intensity.  Every hit, after the first bounce too, takes its
material's texture as its color S_d and its bump map's perturbed normal (Blinn 1978,
as :mod:`scanline.shading.surface` computes them; the primary hit's bumped normal
also turns its reflected and transmitted rays).  The tree stops
at ``max_depth`` levels (the primary ray is level 1), where a ray's weight falls
below :data:`MIN_WEIGHT`, or after :data:`MAX_RAYS` rays of one sample.

Random numbers (the jitter of area lights and glossy reflection) come from a
counter-based generator (SplitMix64, Steele, Lea and Flood 2014) seeded by the
user's seed and the sample's number, so an image is the same on any number of
threads.
"""

import math

import numpy as np

from ._jit import helper, kernel, slow_to_compile
from .shade import encode
from .bvh import STACK, moller_trumbore, nearest, transmittance
from .csg import code_primitive, first_surface, solid_scratch, solid_transmittance
from .environment import environment_color
from .texture import sample_run

#: Weight below which a ray is not traced (a quarter of one step of 255).
MIN_WEIGHT = 1.0 / 1024.0

#: Most rays of the ray tree of one sample (shadow rays not counted).
MAX_RAYS = 1024

#: Columns of a material row: ka, kd, ks, n_s, S_s (3), the least highlight base,
#: S_d (3) (:func:`scanline.shading.buffer.material_rows`), then k_r, k_t, eta,
#: roughness, bump scale.
KR, KT, ETA, ROUGH, BUMP_SCALE = 11, 12, 13, 14, 15

#: Rows of a material's maps (``maps`` (M, 3, 5)): its texture, bump map and
#: environment map, each as the row of ``levels`` where it begins (-1: none), its
#: levels (a face's, for a cube map), filter, wrap and kind of environment map.
TEXTURE, BUMP, ENVIRONMENT = 0, 1, 2

#: Columns of the ray stack: origin (3), direction (3), weight per color component
#: (3), depth, parent, kind, material of the surface the ray leaves (-1: none).
WEIGHT, DEPTH, PARENT, KIND, LEFT = 6, 9, 10, 11, 12
RAY_COLUMNS = 13

#: Columns of a light row: the shading's 16 (:func:`scanline.shading.buffer.source_rows`),
#: then an area light's corner, edges and samples per side (0: not an area light).
CORNER, EDGE_U, EDGE_V, GRID = 16, 19, 22, 25

#: ``first`` of a sample whose primary ray meets a solid (:mod:`scanline.solids`) first.
SOLID = -2

#: Kinds of ray in the log.
PRIMARY, REFLECTED, REFRACTED, SHADOW = 0, 1, 2, 3

#: Columns of a log row: ray, parent, kind, depth, origin (3), direction (3), t of its
#: hit, facet hit (-1: none), weight (red), local intensity (3), its contribution (3),
#: light (shadow rays), transmittance (shadow rays), weight (green, blue).
LOG_COLUMNS = 23

#: Samples per chunk of :func:`trace_all` (chunks are dealt out to the threads).
CHUNK = 64

#: Codes of the tokens (:mod:`scanline._kernels.variants`) of the tracer's optional
#: parts, ``maps_token`` (texture, bump and environment maps), ``with_solids`` (the
#: solids of :mod:`scanline._kernels.csg`) and ``logging`` (the ray tree's log, written
#: by the step table's Python twin only): a scene without them compiles none of
#: their code (measured: the lookups and the solids were most of the tracer's compile
#: time on an empty cache).
WITHOUT, WITH = 1, 2


@helper
def next_random(state):
    """A uniform number in [0, 1) from the SplitMix64 generator whose state is
    ``state[0]`` (uint64), advanced."""
    state[0] += np.uint64(0x9E3779B97F4A7C15)
    z = state[0]
    z = (z ^ (z >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
    z = (z ^ (z >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
    z = z ^ (z >> np.uint64(31))
    return float(z >> np.uint64(11)) * (1.0 / 9007199254740992.0)


@helper
def fresnel(cos_i, n1, n2):
    """The reflectance of unpolarized light meeting the interface from index ``n1``
    to ``n2`` at an angle whose cosine is ``cos_i`` (the Fresnel equations: the mean
    of r_s^2 and r_p^2), and the cosine of the transmitted angle; ``(1.0, -1.0)``
    past the critical angle (total internal reflection)."""
    ratio = n1 / n2
    k = 1.0 - ratio * ratio * (1.0 - cos_i * cos_i)
    if k < 0.0:
        return 1.0, -1.0
    cos_t = math.sqrt(k)
    rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t)
    rp = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t)
    return 0.5 * (rs * rs + rp * rp), cos_t


@helper
def mirror(d, n, cos_i, out):
    """The mirror direction of ``d`` about the unit normal ``n`` (facing the incoming
    ray, cos_i = N . -d) into ``out``: R = d + 2 cos_i N (Hearn & Baker 14-6)."""
    for c in range(3):
        out[c] = d[c] + 2.0 * cos_i * n[c]


@helper
def bend(d, n, ratio, cos_i, cos_t, out):
    """The transmitted direction of the unit ``d`` through the unit normal ``n``
    (facing the incoming ray) into ``out`` by Snell's law (Hearn & Baker eq. 14-33):
    T = (eta_i / eta_t) d + ((eta_i / eta_t) cos_i - cos_t) N, ``ratio`` = eta_i /
    eta_t, ``cos_t`` from :func:`fresnel`."""
    for c in range(3):
        out[c] = ratio * d[c] + (ratio * cos_i - cos_t) * n[c]


@helper
def _log(log, count, ray, parent, kind, depth, o, d, t, facet, weight, local, light, through):
    """Append a row to ``log`` (when it has room; ``count[0]`` rows so far)."""
    k = count[0]
    if k >= log.shape[0]:
        return
    log[k, 0] = ray
    log[k, 1] = parent
    log[k, 2] = kind
    log[k, 3] = depth
    for c in range(3):
        log[k, 4 + c] = o[c]
        log[k, 7 + c] = d[c]
        log[k, 13 + c] = local[c]
        log[k, 16 + c] = weight[c] * local[c]
    log[k, 10] = t
    log[k, 11] = facet
    log[k, 12] = weight[0]
    log[k, 21] = weight[1]
    log[k, 22] = weight[2]
    log[k, 19] = light
    log[k, 20] = through
    count[0] = k + 1


@helper
def _seen(ox, oy, oz, tmin, s, lights, bounds, links, table, clear, solids, work, with_solids,
          stack, state):
    """What reaches (ox, oy, oz) of light ``s``: the transmittance of the shadow ray
    toward it (:func:`scanline._kernels.bvh.transmittance`; from ``tmin`` on), or for
    an area light the mean over its grid of cells of the shadow rays to a jittered
    point of each (Cook, Porter and Carpenter 1984).  Returns ``(through, distance
    to the light (inf at infinity), direction x, y, z)`` of the last ray."""
    grid = int(lights[s, GRID])
    cells = grid * grid if grid > 0 else 1
    total = 0.0
    dist = math.inf
    lx = ly = lz = 0.0
    for cell in range(cells):
        if grid > 0:
            a = (cell % grid + next_random(state)) / grid
            b = (cell // grid + next_random(state)) / grid
            tx = lights[s, CORNER] + a * lights[s, EDGE_U] + b * lights[s, EDGE_V] - ox
            ty = (lights[s, CORNER + 1] + a * lights[s, EDGE_U + 1] + b * lights[s, EDGE_V + 1]
                  - oy)
            tz = (lights[s, CORNER + 2] + a * lights[s, EDGE_U + 2] + b * lights[s, EDGE_V + 2]
                  - oz)
        else:
            w = lights[s, 3]
            tx = lights[s, 0] - w * ox
            ty = lights[s, 1] - w * oy
            tz = lights[s, 2] - w * oz
        dist = math.sqrt(tx * tx + ty * ty + tz * tz)
        if not dist > 0:
            total += 1.0
            continue
        lx = tx / dist
        ly = ty / dist
        lz = tz / dist
        if grid == 0 and lights[s, 3] == 0.0:
            dist = math.inf
        through = transmittance(ox, oy, oz, lx, ly, lz, tmin, dist - tmin, bounds, links, table,
                                clear, stack)
        if len(with_solids) == WITH:
            if through > 0.0:
                through *= solid_transmittance(ox, oy, oz, lx, ly, lz, tmin, dist - tmin, solids,
                                               work)
        total += through
    return total / cells, dist, lx, ly, lz


@kernel
def shadow_all(start, step, points, seed, eps, lights, bounds, links, table, clear, solids,
               with_solids, out):
    """Per point (rows of ``points``) and light (rows of ``lights``) what reaches the
    point (:func:`_seen`, shadow rays from ``eps`` along them on) into ``out`` (S,
    P): the shading's shadow test for the primary rays' hits; the points numbered
    ``start``, ``start + step`` ... (one call per thread)."""
    stack = np.empty(STACK, np.int64)
    state = np.empty(1, np.uint64)
    work = np.empty(0)           # (no solids: not used)
    if len(with_solids) == WITH:
        work = solid_scratch(solids)
    for i in range(start, points.shape[0], max(step, 1)):
        state[0] = np.uint64(seed) * np.uint64(0xD1B54A32D192ED03) + np.uint64(i)
        next_random(state)
        for s in range(lights.shape[0]):
            out[s, i] = _seen(points[i, 0], points[i, 1], points[i, 2], eps, s, lights, bounds,
                              links, table, clear, solids, work, with_solids, stack, state)[0]


@helper
def _lit(p, n, ng, v, sd, m, mats, lights, ambient, blinn, eps, bounds, links, table, clear,
         solids, work, with_solids, stack, state, out, logging, log, count, ray, depth):
    """The local intensity at ``p`` (normal ``n``, geometric normal ``ng``, both facing
    the viewer ``v``; color ``sd``; material row ``m``) into ``out`` (3,): ambient plus
    every light's diffuse and specular terms (an area light's from its center), each
    times what its shadow rays let through (:func:`_seen`) -- the model of
    :func:`scanline.lighting.intensity` with shadow maps' visibility."""
    for c in range(3):
        out[c] = mats[m, 0] * ambient[c] * sd[c]
    kd = mats[m, 1]
    ks = mats[m, 2]
    shin = mats[m, 3]
    cut = mats[m, 7]
    zero = np.zeros(3)
    o = np.empty(3)
    d3 = np.empty(3)
    for s in range(lights.shape[0]):
        w = lights[s, 3]
        tx = lights[s, 0] - w * p[0]
        ty = lights[s, 1] - w * p[1]
        tz = lights[s, 2] - w * p[2]
        dist = math.sqrt(tx * tx + ty * ty + tz * tz)
        if not dist > 0:
            continue
        lx = tx / dist
        ly = ty / dist
        lz = tz / dist
        # f = min(1, 1 / (a0 + a1 d + a2 d^2)); a light at infinity: d = 1, f = 1
        f = min(1.0, 1.0 / (lights[s, 4] + lights[s, 5] * dist + lights[s, 6] * dist * dist))
        if lights[s, 9] > 0:
            cos = -(lx * lights[s, 10] + ly * lights[s, 11] + lz * lights[s, 12])
            if cos >= lights[s, 7]:
                f *= min(max(cos, 0.0), 1.0) ** lights[s, 8]
            else:
                f = 0.0
        nl = n[0] * lx + n[1] * ly + n[2] * lz
        if not (nl > 0 and f > 0):
            continue
        side = 1.0 if ng[0] * lx + ng[1] * ly + ng[2] * lz >= 0 else -1.0
        for c in range(3):
            o[c] = p[c] + side * eps * ng[c]
        through, far, d3[0], d3[1], d3[2] = _seen(o[0], o[1], o[2], 0.0, s, lights, bounds,
                                                  links, table, clear, solids, work,
                                                  with_solids, stack, state)
        if len(logging) == WITH:
            _log(log, count, np.int64(-1), ray, np.int64(SHADOW), depth + 1, o, d3, far,
                 np.int64(-1), zero, zero, s, through)
        if through <= 0.0:
            continue
        if blinn:
            hx = lx + v[0]
            hy = ly + v[1]
            hz = lz + v[2]
            hl = math.sqrt(hx * hx + hy * hy + hz * hz)
            sv = (n[0] * hx + n[1] * hy + n[2] * hz) / hl if hl > 0 else 0.0
        else:
            sv = (v[0] * (2.0 * nl * n[0] - lx) + v[1] * (2.0 * nl * n[1] - ly)
                  + v[2] * (2.0 * nl * n[2] - lz))
        shine = min(sv, 1.0) ** shin if sv > cut else 0.0
        g = f * through
        for c in range(3):
            out[c] += g * lights[s, 13 + c] * (nl * kd * sd[c] + shine * ks * mats[m, 4 + c])


@helper
def _cone(r, angle, state):
    """``r`` (unit, (3,)) turned to a direction uniformly distributed over the cone of
    half-angle ``angle`` around it (in place)."""
    cos_t = 1.0 - next_random(state) * (1.0 - math.cos(angle))
    sin_t = math.sqrt(max(0.0, 1.0 - cos_t * cos_t))
    phi = 2.0 * math.pi * next_random(state)
    if abs(r[0]) < 0.9:
        ux, uy, uz = 0.0, r[2], -r[1]
    else:
        ux, uy, uz = -r[2], 0.0, r[0]
    ul = math.sqrt(ux * ux + uy * uy + uz * uz)
    ux /= ul
    uy /= ul
    uz /= ul
    wx = r[1] * uz - r[2] * uy
    wy = r[2] * ux - r[0] * uz
    wz = r[0] * uy - r[1] * ux
    cp = math.cos(phi) * sin_t
    sp = math.sin(phi) * sin_t
    r0 = cos_t * r[0] + cp * ux + sp * wx
    r1 = cos_t * r[1] + cp * uy + sp * wy
    r2 = cos_t * r[2] + cp * uz + sp * wz
    r[0] = r0
    r[1] = r1
    r[2] = r2


@helper
def _push(rays, top, p, offset, ng, weight, factor, depth, parent, kind, left):
    """Row ``top`` of the ray stack (its direction already written): the origin ``p``
    moved ``offset`` along the normal ``ng`` (off the surface, to the side the ray
    goes), the weights ``weight`` (3,) times ``factor`` (3,), depth, parent ray, kind
    and the material ``left``."""
    for c in range(3):
        rays[top, c] = p[c] + offset * ng[c]
        rays[top, WEIGHT + c] = weight[c] * factor[c]
    rays[top, DEPTH] = depth
    rays[top, PARENT] = parent
    rays[top, KIND] = kind
    rays[top, LEFT] = left


@helper
def _sampled(texels, levels, at, s, items):
    """``items`` planar items of ``s`` (u, v, then four derivatives, ``items`` apart)
    sampled by the texture described by ``at`` (a row of ``maps``): each item's color
    replaces its first three derivatives (:func:`scanline._kernels.texture.sample_run`)."""
    sample_run(texels, levels, at[0], at[1], at[2], at[3], s, np.int64(0), items, np.int64(0),
               items)


@helper
def _detail(f, m, a, b, secondary, uvs, tangents, maps, mats, texels, levels, sd, n, s):
    """The texture and bump maps of material ``m`` at the point of facet ``f`` with
    barycentric coordinates (1 - a - b, a, b): a secondary hit's color ``sd`` (3,)
    scaled by the texel (Hearn & Baker 14-9), the unit normal ``n`` (3,) perturbed by
    Blinn's bump mapping, N' = (N . n) n + B_u (n x P_v) - B_v (n x P_u), N = P_u x
    P_v, turned to n's side (``tangents[f]``: P_u, P_v; B_u, B_v central differences
    one texel apart); ``s``: scratch of 24 reals."""
    if f < 0 or f >= uvs.shape[0] or f >= tangents.shape[0]:
        return
    a0 = 1.0 - a - b
    tu = a0 * uvs[f, 0, 0] + a * uvs[f, 1, 0] + b * uvs[f, 2, 0]
    tv = a0 * uvs[f, 0, 1] + a * uvs[f, 1, 1] + b * uvs[f, 2, 1]
    if secondary and maps[m, TEXTURE, 0] >= 0:
        s[0] = tu
        s[1] = tv
        for k in range(2, 6):
            s[k] = 0.0
        _sampled(texels, levels, maps[m, TEXTURE], s, np.int64(1))
        for c in range(3):
            sd[c] *= s[2 + c]
    first = maps[m, BUMP, 0]
    if first < 0:
        return
    du = 1.0 / levels[first, 1]
    dv = 1.0 / levels[first, 2]
    for k in range(4):
        s[k] = tu + (du if k == 0 else -du if k == 1 else 0.0)
        s[4 + k] = tv + (dv if k == 2 else -dv if k == 3 else 0.0)
    for k in range(8, 24):
        s[k] = 0.0
    _sampled(texels, levels, maps[m, BUMP], s, np.int64(4))
    scale = mats[m, BUMP_SCALE]
    bu = (s[8] - s[9]) * scale / (2.0 * du)
    bv = (s[10] - s[11]) * scale / (2.0 * dv)
    px, py, pz = tangents[f, 0], tangents[f, 1], tangents[f, 2]
    qx, qy, qz = tangents[f, 3], tangents[f, 4], tangents[f, 5]
    side = ((py * qz - pz * qy) * n[0] + (pz * qx - px * qz) * n[1]
            + (px * qy - py * qx) * n[2])
    ox = side * n[0] + bu * (n[1] * qz - n[2] * qy) - bv * (n[1] * pz - n[2] * py)
    oy = side * n[1] + bu * (n[2] * qx - n[0] * qz) - bv * (n[2] * px - n[0] * pz)
    oz = side * n[2] + bu * (n[0] * qy - n[1] * qx) - bv * (n[0] * py - n[1] * px)
    length = math.sqrt(ox * ox + oy * oy + oz * oz)
    if not length > 0:
        return
    r = (-1.0 if side < 0 else 1.0) / length
    n[0] = ox * r
    n[1] = oy * r
    n[2] = oz * r


@kernel
def trace_all(start, step, origins, directions, firsts, givens, samples, seed, max_depth, eps,
              blinn, bounds, links, table, prim_facet, facet_row, clear, world_n,
              vertex_normals, colors, facet_mat, front, mats, lights, ambient, background, uvs,
              tangents, maps, texels, levels, maps_token, solids, with_solids, out, logging, log,
              count):
    """Walk the ray tree of every sample (rows of ``origins``, ``directions`` (unit),
    ``firsts``, ``givens`` and ``samples``, the samples' numbers for the random
    numbers) into ``out`` (P, 3): the sample's primary ray meets facet ``first`` (-1:
    nothing, the output is NaN; :data:`SOLID`: a solid), where the shading stage found
    the local intensity ``given`` (3,).  ``rays``: a (MAX_RAYS + 1,
    :data:`RAY_COLUMNS`) stack of rays; ``uvs`` (G, 3, 2) and ``tangents`` (G, 6) the
    facets' texture coordinates and P_u, P_v (empty: no maps), ``maps`` (M, 3, 5) each
    material's maps in ``texels`` and ``levels``; ``solids``
    (:mod:`scanline._kernels.csg`) the solids, met as exactly as the triangles.  The
    chunks of :data:`CHUNK` samples numbered ``start``, ``start +
    step`` ... (calls with start = 0 .. step - 1 on as many threads share the work,
    the costly chunks of glass and mirrors spread among them).  ``log`` (L,
    :data:`LOG_COLUMNS`) receives the rays when ``logging`` says so (one sample at a
    time)."""
    total = origins.shape[0]
    stack = np.empty(STACK, np.int64)
    rays = np.empty((MAX_RAYS + 1, RAY_COLUMNS))
    work = np.empty(0)           # (no solids: not used)
    if len(with_solids) == WITH:
        work = solid_scratch(solids)
    state = np.empty(1, np.uint64)
    p = np.empty(3)
    n = np.empty(3)
    ng = np.empty(3)
    v = np.empty(3)
    sd = np.empty(3)
    local = np.empty(3)
    o = np.empty(3)
    d = np.empty(3)
    weight = np.empty(3)
    tint = np.empty(3)
    scratch = np.empty(24)
    sn = np.empty(3)
    for j in range(total):          # this thread's samples, chunk after chunk
        i = (start + (j // CHUNK) * max(step, 1)) * CHUNK + j % CHUNK
        if i >= total:
            break
        origin = origins[i]
        direction = directions[i]
        first = firsts[i]
        given = givens[i]
        sample = samples[i]
        pixel = out[i]
        if first < 0 and first != SOLID:
            for c in range(3):
                pixel[c] = math.nan
            continue
        state[0] = np.uint64(seed) * np.uint64(0xD1B54A32D192ED03) + np.uint64(sample)
        next_random(state)
        for c in range(3):
            pixel[c] = 0.0
            rays[0, c] = origin[c]
            rays[0, 3 + c] = direction[c]
            rays[0, WEIGHT + c] = 1.0
        rays[0, DEPTH] = 1.0
        rays[0, PARENT] = -1.0
        rays[0, KIND] = PRIMARY
        rays[0, LEFT] = -1.0
        top = 1
        made = 1
        ray = -1
        while top > 0:
            top -= 1
            ray += 1
            for c in range(3):
                o[c] = rays[top, c]
                d[c] = rays[top, 3 + c]
                weight[c] = rays[top, WEIGHT + c]
            depth = int(rays[top, DEPTH])
            parent = int(rays[top, PARENT])
            kind = int(rays[top, KIND])
            left = int(rays[top, LEFT])
            code = np.int64(-1)
            if parent < 0 and first >= 0:
                row = facet_row[first]
                t, u, w = moller_trumbore(o[0], o[1], o[2], d[0], d[1], d[2], table, row)
            elif parent < 0:                 # the primary ray's first surface is a solid's
                t, row, u, w = math.inf, np.int64(-1), 0.0, 0.0
            else:
                t, row, u, w = nearest(o[0], o[1], o[2], d[0], d[1], d[2], 0.0, math.inf, bounds,
                                       links, table, stack)
            if len(with_solids) == WITH:
                if not (parent < 0 and first >= 0):
                    t, code = first_surface(o[0], o[1], o[2], d[0], d[1], d[2], 0.0,
                                            t if row >= 0 else math.inf, solids, work, sn)
            if row < 0 and code < 0:
                # leaving the scene: the environment map of the surface left, if any
                for c in range(3):
                    local[c] = background[c]
                if len(maps_token) == WITH:
                    if 0 <= left < maps.shape[0] and maps[left, ENVIRONMENT, 0] >= 0:
                        at = maps[left, ENVIRONMENT]
                        local[0], local[1], local[2] = environment_color(
                            texels, levels, at[0], at[1], at[2], at[3], at[4], d[0], d[1], d[2],
                            scratch)
                for c in range(3):
                    pixel[c] += weight[c] * local[c]
                if len(logging) == WITH:
                    _log(log, count, ray, parent, kind, depth, o, d, math.inf, np.int64(-1),
                         weight, local, np.int64(-1), 0.0)
                continue
            f = np.int64(-1)
            m = np.int64(0)
            if len(with_solids) == WITH:
                if code >= 0:          # a solid's surface: its exact normal and material
                    m = solids[9][code_primitive(code, solids[1], solids[6])]
                    for c in range(3):
                        p[c] = o[c] + t * d[c]
                        n[c] = sn[c]
                        ng[c] = sn[c]
                        sd[c] = mats[m, 8 + c]
                        v[c] = -d[c]
            if code < 0:
                f = prim_facet[row]
                m = facet_mat[f]
                for c in range(3):
                    p[c] = table[row, c] + u * table[row, 3 + c] + w * table[row, 6 + c]
                    n[c] = ((1.0 - u - w) * vertex_normals[f, 0, c] + u * vertex_normals[f, 1, c]
                            + w * vertex_normals[f, 2, c])
                    sd[c] = ((1.0 - u - w) * colors[f, 0, c] + u * colors[f, 1, c]
                             + w * colors[f, 2, c])
                    ng[c] = world_n[f, c]
                    v[c] = -d[c]
            # which side the ray meets: the primary ray the side the back-face test saw
            entering = ng[0] * d[0] + ng[1] * d[1] + ng[2] * d[2] < 0
            toward = front[f] if parent < 0 and f >= 0 else entering
            nn = math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])
            r = (1.0 if toward else -1.0) / nn if nn != 0 else 0.0
            for c in range(3):
                n[c] *= r
                if not entering:
                    ng[c] = -ng[c]
            if len(maps_token) == WITH:
                _detail(f, m, u, w, parent >= 0, uvs, tangents, maps, mats, texels, levels, sd, n,
                        scratch)
            if parent < 0:
                for c in range(3):
                    local[c] = given[c]
            else:
                _lit(p, n, ng, v, sd, m, mats, lights, ambient, blinn, eps, bounds, links, table,
                     clear, solids, work, with_solids, stack, state, local, logging, log, count,
                     ray, depth)
            kt = mats[m, KT]
            kr = mats[m, KR]
            for c in range(3):
                pixel[c] += weight[c] * (1.0 - kt) * local[c]
            if len(logging) == WITH:
                for c in range(3):
                    local[c] *= 1.0 - kt
                _log(log, count, ray, parent, kind, depth, o, d, t, f, weight, local, np.int64(-1),
                     0.0)
            if depth >= max_depth or (kr <= 0.0 and kt <= 0.0):
                continue
            # the normal for the new directions: the shading normal unless it faces away
            cos_i = -(d[0] * n[0] + d[1] * n[1] + d[2] * n[2])
            if not cos_i > 0:
                for c in range(3):
                    n[c] = ng[c]
                cos_i = -(d[0] * n[0] + d[1] * n[1] + d[2] * n[2])
            eta = mats[m, ETA]
            big_f = 0.0
            cos_t = -1.0
            if kt > 0.0:
                big_f, cos_t = fresnel(cos_i, 1.0 if entering else eta, eta if entering else 1.0)
            most = max(weight[0], weight[1], weight[2])
            for c in range(3):
                tint[c] = kt * (1.0 - big_f)
            if most * tint[0] >= MIN_WEIGHT and cos_t >= 0.0 and made < MAX_RAYS \
                    and top < rays.shape[0]:
                bend(d, n, 1.0 / eta if entering else eta, cos_i, cos_t, rays[top, 3:6])
                _push(rays, top, p, -eps, ng, weight, tint, depth + 1, ray, np.int64(REFRACTED), m)
                top += 1
                made += 1
            for c in range(3):
                tint[c] = kr * mats[m, 4 + c] + kt * big_f
            if most * max(tint[0], tint[1], tint[2]) >= MIN_WEIGHT and made < MAX_RAYS \
                    and top < rays.shape[0]:
                mirror(d, n, cos_i, rays[top, 3:6])
                rough = mats[m, ROUGH]
                if rough > 0:
                    _cone(rays[top, 3:6], rough, state)
                if (rays[top, 3] * ng[0] + rays[top, 4] * ng[1] + rays[top, 5] * ng[2]) <= 0:
                    mirror(d, ng, -(d[0] * ng[0] + d[1] * ng[1] + d[2] * ng[2]), rays[top, 3:6])
                _push(rays, top, p, eps, ng, weight, tint, depth + 1, ray, np.int64(REFLECTED), m)
                top += 1
                made += 1


#: The tracer and its helpers take 5-12 s to compile (benchmarks/compile.py; its maps
#: the most): its twin answers a small scene first (the first-use cases of
#: ``render ray-tracing``, 96 x 64 pixels: 0.5-0.8 s as Python).
slow_to_compile(trace_all, 8.0)


@kernel
def store(ys, xs, linear, gamma_table, thresholds, raster, gray, alpha):
    """Linear intensities (P, 3) encoded with the shading's gamma tables
    (:func:`scanline._kernels.shade.encode`) at pixels (``xs``, ``ys``) of ``raster``:
    mode "L" (``gray``) the luminance 0.299 R + 0.587 G + 0.114 B, ``alpha``: 255 in
    the fourth channel."""
    h = raster.shape[0]
    w = raster.shape[1]
    for i in range(ys.shape[0]):
        y = ys[i]
        x = xs[i]
        if not (0 <= y < h and 0 <= x < w):
            continue
        if gray:
            raster[y, x, 0] = encode(0.299 * linear[i, 0] + 0.587 * linear[i, 1]
                                     + 0.114 * linear[i, 2], gamma_table, thresholds)
        else:
            for c in range(3):
                raster[y, x, c] = encode(linear[i, c], gamma_table, thresholds)
            if alpha:
                raster[y, x, 3] = 255
