"""Ray casting of constructive solid geometry (Hearn & Baker 10-16; Roth 1982, "Ray
casting for modeling solids"; Requicha 1980): each ray's inside intervals of the
primitives (:mod:`scanline._kernels.solids`) combined up the CSG tree by Roth's rules.

The tree arrives flattened to a postfix program, rows (op, argument): ``PUSH k`` puts
primitive k's intervals on a stack of interval lists; ``UNION``, ``INTERSECTION`` and
``DIFFERENCE`` replace the top two lists L (below) and R by their combination.  Roth's
combination merges the two sorted lists' ends as events along the ray, keeping whether
the ray is inside L and inside R; the result is inside where L or R (union), L and R
(intersection), L and not R (difference), and each result interval's ends keep the
labels of the events that open and close it -- for a difference, R's labels with their
flip bit set, as R's surface bounds the result from the other side.  Touching intervals
of the result are joined (no surface inside a solid).

Lists hold at most ``ts.shape[1]`` intervals (the caller's fixed maximum); a ray that
would need more is counted in ``status`` (the API layer raises a clear error) and its
list is cut.
"""

import math

import numpy as np

from ._jit import helper, kernel
from .solids import MESH, crossings, mesh_intervals, primitive_intervals, surface_normal

#: Program operations.
PUSH = 0
UNION = 1
INTERSECTION = 2
DIFFERENCE = 3

#: Rays per chunk of the kernels (chunks are dealt out to the threads).
CHUNK = 64


@helper
def _inside(op, a, b):
    if op == UNION:
        return a or b
    if op == INTERSECTION:
        return a and b
    return a and not b


@helper
def combine(op, ts, cs, counts, left, right, out):
    """Roth's combination of lists ``left`` and ``right`` into list ``out`` (all
    slots of ``ts`` (S, N, 2) and ``cs``); returns its count, or -1 past N."""
    na = counts[left]
    nb = counts[right]
    i = 0
    j = 0
    in_a = False
    in_b = False
    was = False
    n = 0
    flip = 1 if op == DIFFERENCE else 0
    while i < 2 * na or j < 2 * nb:
        ta = ts[left, i >> 1, i & 1] if i < 2 * na else math.inf
        tb = ts[right, j >> 1, j & 1] if j < 2 * nb else math.inf
        if i < 2 * na and (j >= 2 * nb or ta <= tb):
            t = ta
            code = cs[left, i >> 1, i & 1]
            in_a = not in_a
            i += 1
        else:
            t = tb
            code = cs[right, j >> 1, j & 1] ^ flip
            in_b = not in_b
            j += 1
        now = _inside(op, in_a, in_b)
        if now == was:
            continue
        was = now
        if now:
            if n > 0 and ts[out, n - 1, 1] >= t:        # touching the last one: join
                n -= 1
                continue
            if n >= ts.shape[1]:
                return -1
            ts[out, n, 0] = t
            cs[out, n, 0] = code
        else:
            ts[out, n, 1] = t
            cs[out, n, 1] = code
            if t > ts[out, n, 0]:
                n += 1
    return n


@helper
def evaluate(ox, oy, oz, dx, dy, dz, program, prims, bounds, links, table, verts, tri_prim, ts,
             cs, counts, hit_t, hit_row, stack, u):
    """The inside intervals of the program's solid along the line o + t d: returns
    their count in list 0 of ``ts`` / ``cs`` (S = the program's stack depth + 1
    lists), or -1 when a list would pass its length (or the crossings their buffer)."""
    hits = np.int64(0)
    if table.shape[0] > 0:
        hits = crossings(ox, oy, oz, dx, dy, dz, bounds, links, verts, hit_t, hit_row, stack)
        if hits < 0:
            return -1
    slots = ts.shape[0]
    top = np.int64(0)
    base = 8 * prims.shape[0]
    for p in range(program.shape[0]):
        op = program[p, 0]
        if op == PUSH:
            k = program[p, 1]
            if top >= slots - 1 or not (0 <= k < prims.shape[0]):
                return -1
            if int(prims[k, 0]) == MESH:
                n = mesh_intervals(k, dx, dy, dz, table, tri_prim, base, hit_t, hit_row, hits,
                                   ts, cs, top)
            else:
                n = primitive_intervals(prims, k, ox, oy, oz, dx, dy, dz, u, ts, cs, top)
            if n < 0:
                return -1
            counts[top] = n
            top += 1
        else:
            if top < 2:
                return -1
            n = combine(op, ts, cs, counts, top - 2, top - 1, slots - 1)
            if n < 0:
                return -1
            for e in range(n):
                for s in range(2):
                    ts[top - 2, e, s] = ts[slots - 1, e, s]
                    cs[top - 2, e, s] = cs[slots - 1, e, s]
            counts[top - 2] = n
            top -= 1
    return counts[0] if top == 1 else 0


@kernel
def cast(start, step, origins, directions, tmin, program, prims, bounds, links, table, verts,
         tri_prim, lists, length, t_out, code_out, normal_out, status):
    """The first surface of the solid each ray meets beyond ``tmin``
    (:func:`first_surface`): ``t_out`` (inf: none), ``code_out`` (-1: none) and the
    unit outward normal ``normal_out`` (R, 3); an interval that began before ``tmin``
    shows its exit (a ray from inside).  ``lists``: the program's stack depth + 1,
    ``length``: intervals per list; rays past them add 1 to ``status[start]``.  Chunks
    ``start``, ``start + step`` ..."""
    n = origins.shape[0]
    none = np.zeros(prims.shape[0])
    solids = (program, prims, bounds, links, table, verts, tri_prim, lists, length,
              none.astype(np.int64), none)
    work = solid_scratch(solids)
    for c in range(start, (n + CHUNK - 1) // CHUNK, max(step, 1)):
        for r in range(c * CHUNK, min(n, (c + 1) * CHUNK)):
            t, code = first_surface(origins[r, 0], origins[r, 1], origins[r, 2],
                                    directions[r, 0], directions[r, 1], directions[r, 2], tmin,
                                    math.inf, solids, work, normal_out[r])
            if work[2][0] < 0:
                status[start % status.shape[0]] += 1
            t_out[r] = t
            code_out[r] = code
            if code < 0:
                for k in range(3):
                    normal_out[r, k] = 0.0


@kernel
def moments(start, step, origins, program, prims, bounds, links, table, verts, tri_prim, lists,
            length, out, status):
    """Volume integrals along rays parallel to the z axis (Hearn & Baker 10-16, volume
    by ray casting): per ray from ``origins`` (R, 3) in direction +z, the sums over its
    inside intervals [z_a, z_b] of z_b - z_a, (z_b^2 - z_a^2) / 2 and (z_b^3 - z_a^3) /
    3 into ``out`` (R, 3) -- the integrals of 1, z and z^2 along the ray.  An infinite
    interval gives inf; rays past the lists add 1 to ``status[start]``."""
    n = origins.shape[0]
    ts = np.empty((lists, length, 2))
    cs = np.empty((lists, length, 2), np.int64)
    counts = np.zeros(lists, np.int64)
    hit_t = np.empty(8 * length)
    hit_row = np.empty(8 * length, np.int64)
    stack = np.empty(64, np.int64)
    u = np.empty(6)
    for c in range(start, (n + CHUNK - 1) // CHUNK, max(step, 1)):
        for r in range(c * CHUNK, min(n, (c + 1) * CHUNK)):
            z0 = origins[r, 2]
            m = evaluate(origins[r, 0], origins[r, 1], z0, 0.0, 0.0, 1.0, program, prims,
                         bounds, links, table, verts, tri_prim, ts, cs, counts, hit_t, hit_row,
                         stack, u)
            if m < 0:
                status[start % status.shape[0]] += 1
                m = 0
            s0 = 0.0
            s1 = 0.0
            s2 = 0.0
            for e in range(m):
                a = z0 + ts[0, e, 0]
                b = z0 + ts[0, e, 1]
                s0 += b - a
                s1 += (b * b - a * a) / 2.0
                s2 += (b * b * b - a * a * a) / 3.0
            out[r, 0] = s0
            out[r, 1] = s1
            out[r, 2] = s2


# -- solids in the ray tracer (:mod:`scanline._kernels.raytrace`) -------------------------
#
# The tracer takes the solids as one tuple ``solids`` = (program, prims, bounds, links,
# table, verts, tri_prim, lists, length, prim_material, prim_kt): a program as above
# (possibly empty: no solids), each primitive's row of the tracer's material table and
# its transparency k_t.


@helper
def solid_scratch(solids):
    """Per-thread work arrays for :func:`first_surface` (a tuple)."""
    lists = solids[7]
    length = solids[8]
    return (np.empty((lists, length, 2)), np.empty((lists, length, 2), np.int64),
            np.zeros(lists, np.int64), np.empty(8 * length), np.empty(8 * length, np.int64),
            np.empty(64, np.int64), np.empty(6), np.empty(3))


@helper
def code_primitive(code, prims, tri_prim):
    """The primitive a surface code belongs to (a mesh triangle's owner)."""
    c = code >> 1
    k = c >> 3
    if k < prims.shape[0]:
        return k
    row = c - 8 * prims.shape[0]
    if 0 <= row < tri_prim.shape[0]:
        return tri_prim[row]
    return 0


@helper
def first_surface(ox, oy, oz, dx, dy, dz, tmin, tmax, solids, work, normal):
    """The first surface of the solids along o + t d with t in (tmin, tmax): ``(t,
    code)`` (code -1: none; t = tmax) and its unit outward normal into ``normal`` (3,);
    a ray from inside meets its exit.  A ray past the lists' length sees nothing and
    leaves -1 in ``work[2][0]``."""
    program = solids[0]
    prims = solids[1]
    if program.shape[0] == 0:
        return tmax, np.int64(-1)
    ts = work[0]
    cs = work[1]
    m = evaluate(ox, oy, oz, dx, dy, dz, program, prims, solids[2], solids[3], solids[4],
                 solids[5], solids[6], ts, cs, work[2], work[3], work[4], work[5], work[6])
    if m < 0:
        work[2][0] = -1
    t = tmax
    code = np.int64(-1)
    for e in range(max(m, 0)):
        if ts[0, e, 0] > tmin:
            if ts[0, e, 0] < tmax:
                t = ts[0, e, 0]
                code = cs[0, e, 0]
            break
        if ts[0, e, 1] > tmin:
            if ts[0, e, 1] < tmax:
                t = ts[0, e, 1]
                code = cs[0, e, 1]
            break
    if code < 0:
        return tmax, np.int64(-1)
    surface_normal(prims, solids[4], code, ox + t * dx, oy + t * dy, oz + t * dz, normal)
    return t, code


@helper
def solid_transmittance(ox, oy, oz, dx, dy, dz, tmin, tmax, solids, work):
    """The fraction of light the solids let through along o + t d for t in (tmin,
    tmax): the product of the k_t of every surface crossed (0: opaque), as the
    triangles' shadow test takes it."""
    through = 1.0
    normal = work[7]
    t = tmin
    for _ in range(64):
        t, code = first_surface(ox, oy, oz, dx, dy, dz, t, tmax, solids, work, normal)
        if code < 0:
            break
        through *= solids[10][code_primitive(code, solids[1], solids[6])]
        if through <= 0.0:
            break
    return through
