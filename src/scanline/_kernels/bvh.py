"""Compiled kernels of the bounding volume hierarchy: its construction by the
surface-area heuristic, ray-triangle intersection, and the nearest-hit and shadow
traversals (Hearn & Baker 14-6, "reducing object-intersection calculations":
bounding volumes grouped into a hierarchy, a ray tested against a group's volume
before its contents).

The tree is flat: node ``i`` has bounds ``bounds[i] = (xmin, ymin, zmin, xmax,
ymax, zmax)`` and ``links[i] = (first, count)``: a leaf (count > 0) holds the
triangles ``first .. first + count - 1`` of the reordered triangle table, an inner
node (count = 0) has its children at ``first`` and ``first + 1``.  Triangles are
rows (v0, e1 = v1 - v0, e2 = v2 - v0) of a (N, 9) table, in leaf order.

Construction (Goldsmith & Salmon 1987; MacDonald & Booth 1990, the surface-area
heuristic; binned as Wald 2007): a node's triangles are binned by their centroids
into :data:`BINS` equal slabs of each axis of the centroids' box; the split between
two bins that minimizes A_left N_left + A_right N_right (A the surface area of a
side's box, N its triangles) is taken when it costs less than keeping the node a
leaf, C_t A + C_i (A_l N_l + A_r N_r) < C_i N A (with C_t = C_i), or when the node
holds more than :data:`LEAF_MOST` triangles.  Nodes deeper than :data:`DEPTH` are
leaves, so the traversal's stack is bounded.

Intersection: Moller & Trumbore (1997): for a ray o + t d and a triangle v0, e1, e2,
P = d x e2, det = e1 . P, T = o - v0, u = (T . P) / det, Q = T x e1, v = (d . Q) /
det, t = (e2 . Q) / det; a hit when det != 0, u >= 0, v >= 0, u + v <= 1 and t in
the ray's interval.  Both sides of a triangle are hit.
"""

import math

import numpy as np

from ._jit import helper, kernel

#: Centroid bins per axis of the binned surface-area heuristic.
BINS = 16

#: Triangles a leaf holds at most, unless the tree is :data:`DEPTH` deep.
LEAF_MOST = 8

#: The deepest node; deeper ones are leaves.  The traversal stack holds at most
#: DEPTH + 2 entries.
DEPTH = 60

#: Entries of a traversal stack (:func:`nearest`, :func:`transmittance`).
STACK = DEPTH + 4


@helper
def _area(b0, b1, b2, b3, b4, b5):
    """The surface area of a box (0 for an empty one)."""
    dx = b3 - b0
    dy = b4 - b1
    dz = b5 - b2
    if not (dx >= 0 and dy >= 0 and dz >= 0):
        return 0.0
    return 2.0 * (dx * dy + dy * dz + dz * dx)


@helper
def _empty(box):
    """Make ``box`` (6,) the empty box."""
    for c in range(3):
        box[c] = math.inf
        box[3 + c] = -math.inf


@helper
def _grow(box, boxes, k):
    """Grow ``box`` (6,) to hold ``boxes[k]``; returns its surface area."""
    for c in range(3):
        box[c] = min(box[c], boxes[k, c])
        box[3 + c] = max(box[3 + c], boxes[k, 3 + c])
    return _area(box[0], box[1], box[2], box[3], box[4], box[5])


@kernel
def build(tri, order, bounds, links, table):
    """Build the tree over ``tri`` (N, 3, 3) world triangles (finite): ``order`` (N,)
    receives the triangles in leaf order, ``bounds`` (2N, 6) and ``links`` (2N, 2) the
    nodes, ``table`` (N, 9) the reordered triangles (v0, e1, e2).  Returns the number
    of nodes."""
    n = tri.shape[0]
    if n == 0:
        return 0
    lo = np.empty((n, 3))
    hi = np.empty((n, 3))
    cent = np.empty((n, 3))
    for t in range(n):
        order[t] = t
        for c in range(3):
            a = min(tri[t, 0, c], tri[t, 1, c], tri[t, 2, c])
            b = max(tri[t, 0, c], tri[t, 1, c], tri[t, 2, c])
            lo[t, c] = a
            hi[t, c] = b
            cent[t, c] = 0.5 * (a + b)
    st_node = np.empty(2 * DEPTH + 8, np.int64)
    st_start = np.empty(2 * DEPTH + 8, np.int64)
    st_end = np.empty(2 * DEPTH + 8, np.int64)
    st_depth = np.empty(2 * DEPTH + 8, np.int64)
    bin_box = np.empty((BINS, 6))
    bin_n = np.empty(BINS, np.int64)
    right_area = np.empty(BINS)
    right_n = np.empty(BINS, np.int64)
    cb = np.empty(6)
    grown = np.empty(6)
    top = 0
    st_node[0] = 0
    st_start[0] = 0
    st_end[0] = n
    st_depth[0] = 0
    top = 1
    nodes = 1
    cap = bounds.shape[0]
    while top > 0:
        top -= 1
        node = st_node[top]
        start = st_start[top]
        end = st_end[top]
        depth = st_depth[top]
        b = bounds[node]
        _empty(b)
        _empty(cb)
        for i in range(start, end):
            t = order[i]
            for c in range(3):
                b[c] = min(b[c], lo[t, c])
                b[3 + c] = max(b[3 + c], hi[t, c])
                cb[c] = min(cb[c], cent[t, c])
                cb[3 + c] = max(cb[3 + c], cent[t, c])
        count = end - start
        links[node, 0] = start
        links[node, 1] = count
        if count <= 2 or depth >= DEPTH or nodes + 2 > cap or top + 2 > st_node.shape[0]:
            continue
        best_cost = math.inf
        best_axis = -1
        best_bin = -1
        for axis in range(3):
            extent = cb[3 + axis] - cb[axis]
            if not extent > 0:
                continue
            scale = BINS / extent
            for k in range(BINS):
                bin_n[k] = 0
                _empty(bin_box[k])
            for i in range(start, end):
                t = order[i]
                k = min(max(int((cent[t, axis] - cb[axis]) * scale), 0), BINS - 1)
                bin_n[k] += 1
                for c in range(3):
                    bin_box[k, c] = min(bin_box[k, c], lo[t, c])
                    bin_box[k, 3 + c] = max(bin_box[k, 3 + c], hi[t, c])
            # sweep from the right: the area and count of bins k .. BINS - 1
            _empty(grown)
            rn = 0
            for k in range(BINS - 1, 0, -1):
                right_area[k] = _grow(grown, bin_box, k)
                rn += bin_n[k]
                right_n[k] = rn
            _empty(grown)
            ln = 0
            for k in range(BINS - 1):          # split between bins k and k + 1
                left_area = _grow(grown, bin_box, k)
                ln += bin_n[k]
                if ln == 0 or right_n[k + 1] == 0:
                    continue
                cost = left_area * ln + right_area[k + 1] * right_n[k + 1]
                if cost < best_cost:
                    best_cost = cost
                    best_axis = axis
                    best_bin = k
        area = _area(b[0], b[1], b[2], b[3], b[4], b[5])
        if best_axis < 0 or (best_cost >= area * (count - 1) and count <= LEAF_MOST):
            continue
        # partition: bins 0 .. best_bin to the left
        scale = BINS / (cb[3 + best_axis] - cb[best_axis])
        i = start
        j = end - 1
        while i <= j:
            t = order[i]
            k = min(max(int((cent[t, best_axis] - cb[best_axis]) * scale), 0), BINS - 1)
            if k <= best_bin:
                i += 1
            else:
                order[i] = order[j]
                order[j] = t
                j -= 1
        mid = i
        if mid == start or mid == end:
            mid = (start + end) // 2
        left = nodes
        nodes += 2
        links[node, 0] = left
        links[node, 1] = 0
        for child, s0, s1 in ((left, start, mid), (left + 1, mid, end)):
            st_node[top] = child
            st_start[top] = s0
            st_end[top] = s1
            st_depth[top] = depth + 1
            top += 1
    for i in range(n):
        t = order[i]
        for c in range(3):
            table[i, c] = tri[t, 0, c]
            table[i, 3 + c] = tri[t, 1, c] - tri[t, 0, c]
            table[i, 6 + c] = tri[t, 2, c] - tri[t, 0, c]
    return nodes


@helper
def moller_trumbore(ox, oy, oz, dx, dy, dz, table, i):
    """The ray o + t d against triangle ``i`` of ``table`` (v0, e1, e2): ``(t, u, v)``
    of the plane's crossing, u and v the barycentric coordinates of v1 and v2
    (Moller & Trumbore 1997); t = inf when the ray runs parallel to the plane."""
    e1x = table[i, 3]
    e1y = table[i, 4]
    e1z = table[i, 5]
    e2x = table[i, 6]
    e2y = table[i, 7]
    e2z = table[i, 8]
    px = dy * e2z - dz * e2y
    py = dz * e2x - dx * e2z
    pz = dx * e2y - dy * e2x
    det = e1x * px + e1y * py + e1z * pz
    if det == 0.0:
        return math.inf, -1.0, -1.0
    inv = 1.0 / det
    tx = ox - table[i, 0]
    ty = oy - table[i, 1]
    tz = oz - table[i, 2]
    u = (tx * px + ty * py + tz * pz) * inv
    qx = ty * e1z - tz * e1y
    qy = tz * e1x - tx * e1z
    qz = tx * e1y - ty * e1x
    v = (dx * qx + dy * qy + dz * qz) * inv
    t = (e2x * qx + e2y * qy + e2z * qz) * inv
    return t, u, v


@helper
def inside(t, u, v, tmin, tmax):
    """Whether :func:`moller_trumbore`'s ``(t, u, v)`` is a hit: inside the triangle
    (u, v >= 0, u + v <= 1) and the interval (tmin, tmax)."""
    return t > tmin and t < tmax and u >= 0.0 and v >= 0.0 and u + v <= 1.0


@helper
def _inverse(dx, dy, dz):
    """1 / d per axis for the slab test, 1e300 for a zero component: 1 / 0 = inf would
    give 0 x inf = NaN for a ray lying in a box's face, and a finite huge number gives
    the same answer everywhere else."""
    return (1.0 / dx if dx != 0 else 1e300, 1.0 / dy if dy != 0 else 1e300,
            1.0 / dz if dz != 0 else 1e300)


@helper
def _entry(bounds, node, ox, oy, oz, ix, iy, iz, tmax):
    """Where the ray o + t d (``ix`` = 1 / d_x ...) enters the box of ``node`` (the
    slab method, Kay & Kajiya 1986), inf when it misses it before ``tmax``."""
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
    if far >= max(near, 0.0) and near <= tmax:
        return max(near, 0.0)
    return math.inf


@helper
def nearest(ox, oy, oz, dx, dy, dz, tmin, tmax, bounds, links, table, stack):
    """The nearest hit of the ray o + t d with t in (tmin, tmax): ``(t, row, u, v)``
    (row -1: none), the row in the leaf-ordered ``table``.  ``stack``: STACK int64s.
    The nearer child is visited first, and a subtree entered beyond the best hit so far
    is skipped."""
    best = tmax
    row = -1
    bu = 0.0
    bv = 0.0
    if bounds.shape[0] == 0:
        return best, row, bu, bv
    ix, iy, iz = _inverse(dx, dy, dz)
    if _entry(bounds, np.int64(0), ox, oy, oz, ix, iy, iz, best) == math.inf:
        return best, row, bu, bv
    top = 1
    stack[0] = 0
    while top > 0:
        top -= 1
        node = stack[top]
        count = links[node, 1]
        first = links[node, 0]
        if count > 0:
            for i in range(first, first + count):
                t, u, v = moller_trumbore(ox, oy, oz, dx, dy, dz, table, i)
                if inside(t, u, v, tmin, best):
                    best = t
                    row = i
                    bu = u
                    bv = v
            continue
        a = _entry(bounds, first, ox, oy, oz, ix, iy, iz, best)
        b = _entry(bounds, first + 1, ox, oy, oz, ix, iy, iz, best)
        if top + 2 > stack.shape[0]:
            continue
        if a <= b:
            if b < math.inf:
                stack[top] = first + 1
                top += 1
            if a < math.inf:
                stack[top] = first
                top += 1
        else:
            if a < math.inf:
                stack[top] = first
                top += 1
            stack[top] = first + 1
            top += 1
    return best, row, bu, bv


@helper
def transmittance(ox, oy, oz, dx, dy, dz, tmin, tmax, bounds, links, table, clear, stack):
    """The fraction of light that passes along o + t d for t in (tmin, tmax): the
    product of ``clear[row]`` (a surface's transparency k_t; 0: opaque) over every
    triangle the segment crosses; stops at 0 (a shadow ray, Hearn & Baker 14-6)."""
    through = 1.0
    if bounds.shape[0] == 0:
        return through
    ix, iy, iz = _inverse(dx, dy, dz)
    top = 1
    stack[0] = 0
    while top > 0 and through > 0.0:
        top -= 1
        node = stack[top]
        if _entry(bounds, node, ox, oy, oz, ix, iy, iz, tmax) == math.inf:
            continue
        count = links[node, 1]
        first = links[node, 0]
        if count > 0:
            for i in range(first, first + count):
                t, u, v = moller_trumbore(ox, oy, oz, dx, dy, dz, table, i)
                if inside(t, u, v, tmin, tmax):
                    through *= clear[i]
            continue
        if top + 2 > stack.shape[0]:
            continue
        stack[top] = first
        stack[top + 1] = first + 1
        top += 2
    return through


#: Rays per chunk of :func:`cast` (chunks are dealt out to the threads).
CHUNK = 256


@kernel
def cast(start, step, origins, directions, tmin, tmax, bounds, links, table, t_out, row_out,
         uv_out):
    """The nearest hit of every ray (rows of ``origins`` and ``directions``, (R, 3))
    in (tmin, tmax): ``t_out`` (inf: none), ``row_out`` (-1: none), ``uv_out`` (R, 2);
    the chunks of :data:`CHUNK` rays numbered ``start``, ``start + step`` ... (one call
    per thread, start = 0 .. step - 1)."""
    n = origins.shape[0]
    stack = np.empty(STACK, np.int64)
    for c in range(start, (n + CHUNK - 1) // CHUNK, max(step, 1)):
        for r in range(c * CHUNK, min(n, (c + 1) * CHUNK)):
            t, row, u, v = nearest(origins[r, 0], origins[r, 1], origins[r, 2],
                                   directions[r, 0], directions[r, 1], directions[r, 2], tmin,
                                   tmax, bounds, links, table, stack)
            t_out[r] = t if row >= 0 else math.inf
            row_out[r] = row
            uv_out[r, 0] = u
            uv_out[r, 1] = v
