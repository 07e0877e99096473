"""Exact ray-solid intersections (Hearn & Baker 14-6, "ray-surface intersections";
10-3, quadric surfaces): every primitive gives the intervals of the ray's parameter t
where the ray o + t d is inside it, each end labelled with the surface it crosses there.

A primitive is a row of ``prims`` (:data:`COLUMNS` reals): its kind, the affine map W
(3 x 4, world -> the primitive's own coordinates), a symmetric 4 x 4 quadric Q and six
slab limits (lo x, y, z, hi x, y, z; +-inf where unbounded).  In its own coordinates
the solid is

    { u : (u, 1)^T Q (u, 1) <= 0 } (kinds with a quadric)  n  { lo <= u <= hi }.

A ray maps to u(t) = W (o, 1) + t W_lin d with the same t, so

    f(t) = A t^2 + 2 B t + C,  A = d'^T Q d',  B = d'^T Q o',  C = o'^T Q o'

(d' = (W_lin d, 0), o' = (W o, 1)), and the roots are taken by the numerically careful
form (Press et al., *Numerical Recipes*, 2nd ed., section 5.6): q = -(B + sgn(B)
sqrt(B^2 - A C)), t_1 = q / A, t_2 = C / q -- no difference of nearly equal numbers,
so a far-away ray keeps the accuracy of its near root.  A > 0 gives one interval
between the roots (none when B^2 - A C <= 0: a tangent ray grazes, it does not enter);
A < 0 the two outside them (a hyperboloid's or a cone's nappes); A = 0 a half line.
The slabs clip by the slab method (Kay & Kajiya 1986).  A closed mesh gives the
intervals where the winding number of its crossings is positive (a crossing against
the outward normal counts +1, along it -1), from every crossing of the whole line
found through the bounding volume hierarchy of :mod:`scanline._kernels.bvh` by the
watertight ray-triangle test of Woop, Benthin and Wald (2013).

A surface label (a *code*) is ``2 * (8 * primitive + surface) + flip``: surface 0 the
quadric, 1 .. 6 the slab faces (lo x, hi x, lo y, hi y, lo z, hi z); a mesh triangle is
``2 * (8 * P + row) + flip`` (P primitives, ``row`` of the triangle table); ``flip``
turns the normal inside out (the surface of B in A - B).  Normals are gradients:
grad (f o W) = W_lin^T grad f (:func:`surface_normal`).
"""

import math

from ._jit import helper

#: Kinds of primitives.
QUADRIC = 0
SLABS = 1
MESH = 2

#: Columns of a primitive row: kind, W (12, row-major 3 x 4), Q (16), lo (3), hi (3).
COLUMNS = 35
W0 = 1
Q0 = 13
LO = 29
HI = 32


@helper
def _local(prims, k, ox, oy, oz, dx, dy, dz, u):
    """The ray in primitive ``k``'s coordinates into ``u`` (6,): origin, direction."""
    for r in range(3):
        w = W0 + 4 * r
        u[r] = prims[k, w] * ox + prims[k, w + 1] * oy + prims[k, w + 2] * oz + prims[k, w + 3]
        u[3 + r] = prims[k, w] * dx + prims[k, w + 1] * dy + prims[k, w + 2] * dz


@helper
def _slabs(prims, k, u, code):
    """The slab method on primitive ``k``'s limits: ``(t_near, t_far, code_near,
    code_far)``; t_near > t_far when the ray misses."""
    near = -math.inf
    far = math.inf
    cn = -1
    cf = -1
    for a in range(3):
        lo = prims[k, LO + a]
        hi = prims[k, HI + a]
        if lo == -math.inf and hi == math.inf:
            continue
        o = u[a]
        d = u[3 + a]
        if d == 0.0:
            if not (lo <= o and o <= hi):
                return math.inf, -math.inf, cn, cf
            continue
        t0 = (lo - o) / d
        t1 = (hi - o) / d
        c0 = 2 * (code + 1 + 2 * a)
        c1 = 2 * (code + 2 + 2 * a)
        if t0 > t1:
            t0, t1 = t1, t0
            c0, c1 = c1, c0
        if t0 > near:
            near = t0
            cn = c0
        if t1 < far:
            far = t1
            cf = c1
    return near, far, cn, cf


@helper
def _form(prims, k, a0, a1, a2, a3, b0, b1, b2, b3):
    """a^T Q b for homogeneous 4-vectors a and b (w = 1 for a point, 0 for a
    direction) and primitive ``k``'s Q."""
    s = 0.0
    for r in range(4):
        a = a0 if r == 0 else a1 if r == 1 else a2 if r == 2 else a3
        q = Q0 + 4 * r
        s += a * (prims[k, q] * b0 + prims[k, q + 1] * b1 + prims[k, q + 2] * b2
                  + prims[k, q + 3] * b3)
    return s


@helper
def quadric_roots(qa, qb, qc):
    """The intervals of t where qa t^2 + 2 qb t + qc < 0: ``(count, a0, b0, a1, b1)``,
    count 0, 1 or 2 (ends may be +-inf), by the careful root formula of the module
    docstring."""
    if qa == 0.0:
        if qb == 0.0:
            if qc < 0.0:
                return 1, -math.inf, math.inf, 0.0, 0.0
            return 0, 0.0, 0.0, 0.0, 0.0
        root = -qc / (2.0 * qb)
        if qb > 0.0:
            return 1, -math.inf, root, 0.0, 0.0
        return 1, root, math.inf, 0.0, 0.0
    disc = qb * qb - qa * qc
    if not disc > 0.0:
        if qa < 0.0:
            return 1, -math.inf, math.inf, 0.0, 0.0
        return 0, 0.0, 0.0, 0.0, 0.0
    q = -(qb + math.copysign(math.sqrt(disc), qb))
    r1 = q / qa
    r2 = qc / q if q != 0.0 else -r1
    if r1 > r2:
        r1, r2 = r2, r1
    if qa > 0.0:
        return 1, r1, r2, 0.0, 0.0
    return 2, -math.inf, r1, r2, math.inf


@helper
def primitive_intervals(prims, k, ox, oy, oz, dx, dy, dz, u, ts, cs, slot):
    """The inside intervals of analytic primitive ``k`` along the ray into list
    ``slot`` of ``ts`` (S, N, 2) / ``cs`` (S, N, 2) codes; returns their count (0..2)."""
    _local(prims, k, ox, oy, oz, dx, dy, dz, u)
    near, far, cn, cf = _slabs(prims, k, u, 8 * k)
    if not near < far:
        return 0
    if int(prims[k, 0]) == SLABS:
        ts[slot, 0, 0] = near
        ts[slot, 0, 1] = far
        cs[slot, 0, 0] = cn
        cs[slot, 0, 1] = cf
        return 1
    qa = _form(prims, k, u[3], u[4], u[5], 0.0, u[3], u[4], u[5], 0.0)
    qb = _form(prims, k, u[3], u[4], u[5], 0.0, u[0], u[1], u[2], 1.0)
    qc = _form(prims, k, u[0], u[1], u[2], 1.0, u[0], u[1], u[2], 1.0)
    count, a0, b0, a1, b1 = quadric_roots(qa, qb, qc)
    n = 0
    quad = 2 * (8 * k)
    for i in range(count):
        a = a0 if i == 0 else a1
        b = b0 if i == 0 else b1
        ca = quad
        cb = quad
        if near > a:
            a = near
            ca = cn
        if far < b:
            b = far
            cb = cf
        if a < b and n < ts.shape[1]:
            ts[slot, n, 0] = a
            ts[slot, n, 1] = b
            cs[slot, n, 0] = ca
            cs[slot, n, 1] = cb
            n += 1
    return n


@helper
def _meets_line(bounds, node, ox, oy, oz, ix, iy, iz):
    """Whether the whole line o + t d (``ix`` = 1 / d_x ...) meets the box of ``node``."""
    t0 = (bounds[node, 0] - ox) * ix
    t1 = (bounds[node, 3] - ox) * ix
    near = min(t0, t1)
    far = max(t0, t1)
    t0 = (bounds[node, 1] - oy) * iy
    t1 = (bounds[node, 4] - oy) * iy
    near = max(near, min(t0, t1))
    far = min(far, max(t0, t1))
    t0 = (bounds[node, 2] - oz) * iz
    t1 = (bounds[node, 5] - oz) * iz
    near = max(near, min(t0, t1))
    far = min(far, max(t0, t1))
    return far >= near


@helper
def _owns(e, ex, ey):
    """Whether a point whose edge function is ``e`` for the edge (ex, ey) (the
    triangle turned counterclockwise) is inside on that edge's side: e > 0, or on the
    edge (e = 0) of a top-left edge -- the rule of scan conversion, which gives a
    point on an edge shared by two triangles to exactly one of them."""
    return e > 0.0 or (e == 0.0 and (ey > 0.0 or (ey == 0.0 and ex < 0.0)))


@helper
def watertight(ox, oy, oz, kx, ky, kz, sx, sy, sz, verts, i):
    """The line's crossing of triangle ``i`` of ``verts`` (T, 3, 3) by the watertight
    test of Woop, Benthin and Wald (2013): the vertices relative to o, sheared so the
    ray runs along the axis kz, and 2-D edge functions U, V, W that two triangles
    sharing an edge compute from the same two vertices, so a line through an edge is
    never lost between them; the top-left rule (:func:`_owns`) gives it to exactly one
    of them, as the scan-line fill's pixels on a shared edge.  Returns t, or NaN for a
    miss."""
    a0 = verts[i, 0, kx] - (ox if kx == 0 else oy if kx == 1 else oz)
    a1 = verts[i, 0, ky] - (ox if ky == 0 else oy if ky == 1 else oz)
    a2 = verts[i, 0, kz] - (ox if kz == 0 else oy if kz == 1 else oz)
    b0 = verts[i, 1, kx] - (ox if kx == 0 else oy if kx == 1 else oz)
    b1 = verts[i, 1, ky] - (ox if ky == 0 else oy if ky == 1 else oz)
    b2 = verts[i, 1, kz] - (ox if kz == 0 else oy if kz == 1 else oz)
    c0 = verts[i, 2, kx] - (ox if kx == 0 else oy if kx == 1 else oz)
    c1 = verts[i, 2, ky] - (ox if ky == 0 else oy if ky == 1 else oz)
    c2 = verts[i, 2, kz] - (ox if kz == 0 else oy if kz == 1 else oz)
    ax = a0 - sx * a2
    ay = a1 - sy * a2
    bx = b0 - sx * b2
    by = b1 - sy * b2
    cx = c0 - sx * c2
    cy = c1 - sy * c2
    u = cx * by - cy * bx
    v = ax * cy - ay * cx
    w = bx * ay - by * ax
    det = u + v + w
    if det == 0.0:
        return math.nan
    turn = 1.0 if det > 0.0 else -1.0
    if not (_owns(turn * u, turn * (cx - bx), turn * (cy - by))
            and _owns(turn * v, turn * (ax - cx), turn * (ay - cy))
            and _owns(turn * w, turn * (bx - ax), turn * (by - ay))):
        return math.nan
    return (u * sz * a2 + v * sz * b2 + w * sz * c2) / det


@helper
def crossings(ox, oy, oz, dx, dy, dz, bounds, links, verts, hit_t, hit_row, stack):
    """Every triangle (rows of ``verts``, in the tree's leaf order) the whole line o +
    t d crosses (:func:`watertight`), sorted by t into ``hit_t`` / ``hit_row``:
    returns the count, or -1 when there were more than the buffers hold."""
    n = 0
    if bounds.shape[0] == 0:
        return n
    ix = 1.0 / dx if dx != 0 else 1e300
    iy = 1.0 / dy if dy != 0 else 1e300
    iz = 1.0 / dz if dz != 0 else 1e300
    # the ray's dominant axis kz, the other two in an order that keeps the winding
    kz = 0
    if abs(dy) > abs(dx) and abs(dy) >= abs(dz):
        kz = 1
    elif abs(dz) > abs(dx) and abs(dz) > abs(dy):
        kz = 2
    kx = (kz + 1) % 3
    ky = (kx + 1) % 3
    dkz = dx if kz == 0 else dy if kz == 1 else dz
    if dkz < 0:
        kx, ky = ky, kx
    dkx = dx if kx == 0 else dy if kx == 1 else dz
    dky = dx if ky == 0 else dy if ky == 1 else dz
    sx = dkx / dkz
    sy = dky / dkz
    sz = 1.0 / dkz
    top = 1
    stack[0] = 0
    while top > 0:
        top -= 1
        node = stack[top]
        if not _meets_line(bounds, node, ox, oy, oz, ix, iy, iz):
            continue
        count = links[node, 1]
        first = links[node, 0]
        if count > 0:
            for i in range(first, first + count):
                t = watertight(ox, oy, oz, kx, ky, kz, sx, sy, sz, verts, i)
                if not (t == t):
                    continue
                if n >= hit_t.shape[0]:
                    return -1
                j = n                                  # insertion into the sorted buffer
                while j > 0 and hit_t[j - 1] > t:
                    hit_t[j] = hit_t[j - 1]
                    hit_row[j] = hit_row[j - 1]
                    j -= 1
                hit_t[j] = t
                hit_row[j] = i
                n += 1
            continue
        if top + 2 > stack.shape[0]:
            continue
        stack[top] = first
        stack[top + 1] = first + 1
        top += 2
    return n


@helper
def mesh_intervals(k, dx, dy, dz, table, tri_prim, base, hit_t, hit_row, hits, ts, cs, slot):
    """The inside intervals of mesh primitive ``k`` from the line's sorted crossings
    (``hits`` of them): where the winding number is positive.  ``base``: 8 P, the
    first triangle code.  Returns the count (at most the list's length, then -1)."""
    n = 0
    wind = 0
    for e in range(hits):
        row = hit_row[e]
        if tri_prim[row] != k:
            continue
        # the outward normal e1 x e2 against the direction: entering when negative
        nx = table[row, 4] * table[row, 8] - table[row, 5] * table[row, 7]
        ny = table[row, 5] * table[row, 6] - table[row, 3] * table[row, 8]
        nz = table[row, 3] * table[row, 7] - table[row, 4] * table[row, 6]
        step = 1 if nx * dx + ny * dy + nz * dz < 0 else -1
        was = wind
        wind += step
        if was <= 0 and wind > 0:
            if n >= ts.shape[1]:
                return -1
            ts[slot, n, 0] = hit_t[e]
            cs[slot, n, 0] = 2 * (base + row)
        elif was > 0 and wind <= 0:
            ts[slot, n, 1] = hit_t[e]
            cs[slot, n, 1] = 2 * (base + row)
            if ts[slot, n, 1] > ts[slot, n, 0]:
                n += 1
    return n


@helper
def surface_normal(prims, table, code, px, py, pz, out):
    """The unit outward normal (3,) of the surface ``code`` at the world point p (the
    gradient of the quadric, the slab face's axis, the triangle's e1 x e2), turned
    inside out when the code's flip bit is set."""
    flip = code & 1
    c = code >> 1
    k = c >> 3
    s = c & 7
    if k >= prims.shape[0]:
        row = c - 8 * prims.shape[0]
        if 0 <= row < table.shape[0]:
            out[0] = table[row, 4] * table[row, 8] - table[row, 5] * table[row, 7]
            out[1] = table[row, 5] * table[row, 6] - table[row, 3] * table[row, 8]
            out[2] = table[row, 3] * table[row, 7] - table[row, 4] * table[row, 6]
        else:
            out[0] = out[1] = out[2] = 0.0
    else:
        gx = gy = gz = 0.0
        if s == 0:
            w = W0
            ux = prims[k, w] * px + prims[k, w + 1] * py + prims[k, w + 2] * pz + prims[k, w + 3]
            w = W0 + 4
            uy = prims[k, w] * px + prims[k, w + 1] * py + prims[k, w + 2] * pz + prims[k, w + 3]
            w = W0 + 8
            uz = prims[k, w] * px + prims[k, w + 1] * py + prims[k, w + 2] * pz + prims[k, w + 3]
            q = Q0
            gx = prims[k, q] * ux + prims[k, q + 1] * uy + prims[k, q + 2] * uz + prims[k, q + 3]
            q = Q0 + 4
            gy = prims[k, q] * ux + prims[k, q + 1] * uy + prims[k, q + 2] * uz + prims[k, q + 3]
            q = Q0 + 8
            gz = prims[k, q] * ux + prims[k, q + 1] * uy + prims[k, q + 2] * uz + prims[k, q + 3]
        else:
            sign = 1.0 if (s - 1) & 1 else -1.0
            a = (s - 1) >> 1
            if a == 0:
                gx = sign
            elif a == 1:
                gy = sign
            else:
                gz = sign
        for c3 in range(3):
            out[c3] = (prims[k, W0 + c3] * gx + prims[k, W0 + 4 + c3] * gy
                       + prims[k, W0 + 8 + c3] * gz)
    length = math.sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2])
    scale = (-1.0 if flip else 1.0) / length if length > 0 else 0.0
    for c3 in range(3):
        out[c3] *= scale
