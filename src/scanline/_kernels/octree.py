"""Octrees and quadtrees as flat arrays (Hearn & Baker, section 10-17), and the octree
visible-surface method (section 13-10).

A tree is two arrays: ``kind[i]`` (int8: :data:`EMPTY`, :data:`FULL` or
:data:`SPLIT`) and ``child[i]`` (int64: the index of the first of the ``nchild``
consecutive children of a split node, 8 for an octree and 4 for a quadtree; -1 for a
leaf).  Node 0 is the root; children always come after their parent.  Child ``j`` of
a node is the octant with bit 0 of ``j`` the upper half in x, bit 1 in y, bit 2 in z.
Cells are addressed by integer coordinates at the finest level (``2**depth`` units a
side) and their size in those units.

Every index read from the arrays is checked against their lengths before use, so a
malformed tree gives a wrong answer, never a read or write outside an array.
"""

import math

import numpy as np

from ._jit import helper, kernel
from .raster3d import frame, linear, rising, rows_of, span_limits

EMPTY = 0
FULL = 1
SPLIT = 2

#: Operations of :func:`combine`.
UNION = 0
INTERSECTION = 1
DIFFERENCE = 2


@kernel
def compact(kind, child, nchild, out_kind, out_child):
    """The canonical tree of ``kind``/``child`` into ``out_kind``/``out_child`` (each
    as long as ``kind``): a split node whose children are all full (all empty)
    becomes one full (empty) leaf -- bottom-up, so merges climb -- and the nodes left
    reachable are renumbered breadth first.  ``kind`` is changed.  Returns the number
    of nodes."""
    n = kind.shape[0]
    for i in range(n - 1, -1, -1):
        if kind[i] != SPLIT:
            continue
        c = child[i]
        if c <= i or c + nchild > n:            # malformed: an empty leaf
            kind[i] = EMPTY
            continue
        first = kind[c]
        same = first != SPLIT
        for j in range(1, nchild):
            if kind[c + j] != first:
                same = False
        if same:
            kind[i] = first
    source = np.empty(n, np.int64)
    source[0] = 0
    nxt = 1
    o = 0
    while o < nxt:
        s = source[o]
        out_kind[o] = kind[s]
        out_child[o] = -1
        if kind[s] == SPLIT and nxt + nchild <= n:
            out_child[o] = nxt
            for j in range(nchild):
                source[nxt + j] = child[s] + j
            nxt += nchild
        elif kind[s] == SPLIT:
            out_kind[o] = EMPTY
        o += 1
    return nxt


@helper
def decide(op, a, b):
    """The value of two nodes' set operation where it is decided without their
    children (EMPTY or FULL), else SPLIT (look at the children)."""
    if op == UNION:
        if a == FULL or b == FULL:
            return FULL
        if a == EMPTY and b == EMPTY:
            return EMPTY
    elif op == INTERSECTION:
        if a == EMPTY or b == EMPTY:
            return EMPTY
        if a == FULL and b == FULL:
            return FULL
    else:
        if a == EMPTY or b == FULL:
            return EMPTY
        if a == FULL and b == EMPTY:
            return FULL
    return SPLIT


@kernel
def combine(ka, ca, kb, cb, op, nchild, out_kind, out_child):
    """The set operation ``op`` (:data:`UNION`, :data:`INTERSECTION`,
    :data:`DIFFERENCE`) of trees a and b, node by node (Hearn & Baker 10-17): two
    nodes at the same place are decided by their values where that is possible, else
    their children are paired (a leaf pairs with each child of a split node), breadth
    first.  The result is not yet canonical (:func:`compact` it).  Capacity: the two
    trees' node counts together.  Returns the number of nodes."""
    cap = out_kind.shape[0]
    ia = np.empty(cap, np.int64)
    ib = np.empty(cap, np.int64)
    na = ka.shape[0]
    nb = kb.shape[0]
    ia[0] = 0
    ib[0] = 0
    nxt = 1
    o = 0
    while o < nxt:
        a = ia[o]
        b = ib[o]
        va = ka[a]
        vb = kb[b]
        r = decide(op, va, vb)
        out_child[o] = -1
        if r != SPLIT:
            out_kind[o] = r
        elif nxt + nchild > cap:
            out_kind[o] = EMPTY
        else:
            out_kind[o] = SPLIT
            out_child[o] = nxt
            for j in range(nchild):
                ja = a
                if va == SPLIT:
                    ja = ca[a] + j
                    if ja <= a or ja >= na:
                        ja = a
                jb = b
                if vb == SPLIT:
                    jb = cb[b] + j
                    if jb <= b or jb >= nb:
                        jb = b
                ia[nxt + j] = ja
                ib[nxt + j] = jb
            nxt += nchild
        o += 1
    return nxt


@kernel
def leaves(kind, child, order, depth, out):
    """The leaves depth first, the children of each node in ``order`` (a permutation
    of 0 .. nchild - 1: a front-to-back order, Hearn & Baker 13-10): rows (x, y, z,
    size, kind) of ``out`` in units of the finest level (``2**depth`` a side).
    Returns the number of rows (at most ``len(out)``)."""
    n = kind.shape[0]
    nchild = order.shape[0]
    cap = depth * nchild + 2
    node = np.empty(cap, np.int64)
    pos = np.empty((cap, 4), np.int64)
    sp = 1
    node[0] = 0
    pos[0, 0] = 0
    pos[0, 1] = 0
    pos[0, 2] = 0
    pos[0, 3] = np.int64(1) << depth
    count = 0
    while sp > 0:
        sp -= 1
        i = node[sp]
        x = pos[sp, 0]
        y = pos[sp, 1]
        z = pos[sp, 2]
        size = pos[sp, 3]
        c = child[i]
        if kind[i] == SPLIT and size > 1 and c > i and c + nchild <= n \
                and sp + nchild <= cap:
            half = size >> 1
            for r in range(nchild - 1, -1, -1):
                j = order[r]
                node[sp] = c + j
                pos[sp, 0] = x + half * (j & 1)
                pos[sp, 1] = y + half * ((j >> 1) & 1)
                pos[sp, 2] = z + half * ((j >> 2) & 1)
                pos[sp, 3] = half
                sp += 1
        elif count < out.shape[0]:
            out[count, 0] = x
            out[count, 1] = y
            out[count, 2] = z
            out[count, 3] = size
            out[count, 4] = kind[i] if kind[i] != SPLIT else EMPTY
            count += 1
    return count


@kernel
def fill_cells(cells, grid):
    """Set the cells of rows (x, y, z, size, kind) whose kind is FULL in ``grid``
    (uint8, indexed [x, y, z]; a quadtree's grid has one z layer), clipped to it."""
    nx, ny, nz = grid.shape
    for r in range(cells.shape[0]):
        if cells[r, 4] != FULL:
            continue
        s = cells[r, 3]
        x0 = max(cells[r, 0], 0)
        y0 = max(cells[r, 1], 0)
        z0 = max(cells[r, 2], 0)
        x1 = min(cells[r, 0] + s, nx)
        y1 = min(cells[r, 1] + s, ny)
        z1 = min(cells[r, 2] + s, nz)
        for x in range(x0, x1):
            for y in range(y0, y1):
                for z in range(z0, z1):
                    grid[x, y, z] = 1


@helper
def locate(kind, child, depth, x, y, z, size):
    """The node at the cube of ``size`` at (x, y, z), or the leaf above it."""
    n = kind.shape[0]
    i = 0
    s = np.int64(1) << depth
    while kind[i] == SPLIT and s > size:
        c = child[i]
        if c <= i or c + 8 > n:
            break
        s >>= 1
        i = c + ((x // s) & 1) + 2 * ((y // s) & 1) + 4 * ((z // s) & 1)
    return i


@helper
def put_face(out, count, axis, sign, plane, u, v, size):
    """Row ``count`` of ``out`` set to the face (axis, sign, plane, u, v, size) where
    there is room; returns the rows now used."""
    if count >= out.shape[0]:
        return count
    out[count, 0] = axis
    out[count, 1] = sign
    out[count, 2] = plane
    out[count, 3] = u
    out[count, 4] = v
    out[count, 5] = size
    return count + 1


@kernel
def boundary_faces(kind, child, depth, cells, out):
    """The faces between full and empty space: for each full cell of ``cells`` (rows
    x, y, z, size, kind) and each of its six sides, the side itself where the neighbor
    there is an empty leaf or outside the region, or the sides of the empty leaves of
    a finer neighbor that touch it.  Rows of ``out``: (axis, sign, plane, u, v, size),
    the face on the plane ``axis = plane`` with outward normal ``sign`` (+1 or -1)
    spanning [u, u + size] x [v, v + size] in the two other axes (in order).  Returns
    the number of rows (at most ``len(out)``)."""
    n = kind.shape[0]
    full = np.int64(1) << depth
    cap = 8 * depth + 9
    stack = np.empty(cap, np.int64)
    spos = np.empty((cap, 4), np.int64)
    p = np.empty(3, np.int64)
    count = np.int64(0)
    for r in range(cells.shape[0]):
        if cells[r, 4] != FULL:
            continue
        s = cells[r, 3]
        for axis in range(3):
            u = (axis + 1) % 3
            v = (axis + 2) % 3
            for sign in (-1, 1):
                for k in range(3):
                    p[k] = cells[r, k]
                plane = p[axis] + s if sign > 0 else p[axis]
                p[axis] = p[axis] + s if sign > 0 else p[axis] - s
                if p[axis] < 0 or p[axis] >= full:
                    m = -1
                else:
                    m = locate(kind, child, depth, p[0], p[1], p[2], s)
                if m < 0 or kind[m] == EMPTY:
                    count = put_face(out, count, axis, sign, plane, cells[r, u], cells[r, v], s)
                    continue
                if kind[m] == FULL:
                    continue
                # a finer neighbor: its leaves that touch the side
                sp = 1
                stack[0] = m
                spos[0, 0] = p[0]
                spos[0, 1] = p[1]
                spos[0, 2] = p[2]
                spos[0, 3] = s
                touch = 0 if sign > 0 else 1
                while sp > 0:
                    sp -= 1
                    i = stack[sp]
                    h = spos[sp, 3]
                    if kind[i] == EMPTY:
                        count = put_face(out, count, axis, sign, plane, spos[sp, u],
                                         spos[sp, v], h)
                        continue
                    c = child[i]
                    if kind[i] != SPLIT or h < 2 or c <= i or c + 8 > n or sp + 8 > cap:
                        continue
                    x = spos[sp, 0]
                    y = spos[sp, 1]
                    z = spos[sp, 2]
                    half = h >> 1
                    for j in range(8):
                        if ((j >> axis) & 1) != touch:
                            continue
                        stack[sp] = c + j
                        spos[sp, 0] = x + half * (j & 1)
                        spos[sp, 1] = y + half * ((j >> 1) & 1)
                        spos[sp, 2] = z + half * ((j >> 2) & 1)
                        spos[sp, 3] = half
                        sp += 1
    return count


@helper
def edge_value(ax, ay, bx, by, px, py):
    """(b - a) x (p - a), evaluated with the edge's endpoints in one canonical order
    (the lesser (x, y) first) whichever way round it is given, so that the two
    triangles sharing an edge compute the same number (of opposite sign)."""
    if ax < bx or (ax == bx and ay < by):
        return (bx - ax) * (py - ay) - (by - ay) * (px - ax)
    return -((ax - bx) * (py - by) - (ay - by) * (px - bx))


@helper
def takes(e, ax, ay, bx, by):
    """Whether a point with edge value ``e`` for the counterclockwise edge a -> b is
    inside: e > 0, or on the edge and the edge a left (going down) or top (going
    left) one -- the top-left rule, so that triangles sharing an edge take each point
    on it once."""
    if e > 0.0:
        return True
    if e < 0.0:
        return False
    return by < ay or (by == ay and bx < ax)


@kernel
def column_crossings(tri, n, cursor, zs):
    """Where each column of voxel centers (i, j), 0 <= i, j < n, crosses the triangles
    ``tri`` (T, 3, 3) given in grid units (voxel centers at integer coordinates): the
    ray parity test of voxelization, each triangle projected on the x-y plane and
    scan-converted onto the columns it covers by the top-left rule, so that a column
    through a shared edge or vertex of a closed mesh crosses it once.  With ``zs``
    empty, counts into ``cursor[i * n + j]``; else writes each crossing's z at
    ``zs[cursor[column]]`` and advances the cursor (start it at the offsets of the
    counts)."""
    count_only = zs.shape[0] == 0
    for t in range(tri.shape[0]):
        ax = tri[t, 0, 0]
        ay = tri[t, 0, 1]
        bx = tri[t, 1, 0]
        by = tri[t, 1, 1]
        cx = tri[t, 2, 0]
        cy = tri[t, 2, 1]
        az = tri[t, 0, 2]
        bz = tri[t, 1, 2]
        cz = tri[t, 2, 2]
        area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
        if not (area != 0.0 and math.isfinite(area) and math.isfinite(az + bz + cz)):
            continue
        if area < 0.0:
            bx, cx = cx, bx
            by, cy = cy, by
            bz, cz = cz, bz
            area = -area
        i0 = max(int(math.ceil(max(min(ax, bx, cx), -1.0))), 0)
        i1 = min(int(math.floor(min(max(ax, bx, cx), n + 1.0))), n - 1)
        j0 = max(int(math.ceil(max(min(ay, by, cy), -1.0))), 0)
        j1 = min(int(math.floor(min(max(ay, by, cy), n + 1.0))), n - 1)
        for i in range(i0, i1 + 1):
            for j in range(j0, j1 + 1):
                ea = edge_value(bx, by, cx, cy, i, j)        # opposite a
                eb = edge_value(cx, cy, ax, ay, i, j)
                ec = edge_value(ax, ay, bx, by, i, j)
                if not (takes(ea, bx, by, cx, cy) and takes(eb, cx, cy, ax, ay)
                        and takes(ec, ax, ay, bx, by)):
                    continue
                col = i * n + j
                if count_only:
                    cursor[col] += 1
                elif cursor[col] < zs.shape[0]:
                    zs[cursor[col]] = (ea * az + eb * bz + ec * cz) / area
                    cursor[col] += 1


@kernel
def fill_columns(offsets, zs, grid):
    """Each column's crossings (``zs[offsets[c]:offsets[c + 1]]``, c = i * n + j) put
    in order, and the voxels (i, j, k) of ``grid`` (uint8, n x n x n) whose center
    k lies past an odd number of them set: inside by ray parity."""
    n = grid.shape[0]
    m = zs.shape[0]
    for col in range(min(n * n, offsets.shape[0] - 1)):
        a = max(offsets[col], 0)
        b = min(offsets[col + 1], m)
        for q in range(a + 1, b):                    # insertion sort: few crossings
            value = zs[q]
            r = q - 1
            while r >= a and zs[r] > value:
                zs[r + 1] = zs[r]
                r -= 1
            zs[r + 1] = value
        i = col // n
        j = col % n
        q = a
        inside = 0
        for k in range(n):
            while q < b and zs[q] < k:
                inside ^= 1
                q += 1
            grid[i, j, k] = inside


@helper
def meets(lo, hi, t, boxes, j):
    """Whether triangle ``t``'s box (``lo[t]``, ``hi[t]``) meets ``boxes[j]`` (x0, x1,
    y0, y1, z0, z1), boundaries included."""
    for a in range(3):
        if lo[t, a] > boxes[j, 2 * a + 1] or hi[t, a] < boxes[j, 2 * a]:
            return False
    return True


@kernel
def scene_octree(box, lo, hi, max_depth, leaf, smallest, nbox, nchild, nstart, ncount,
                 entries):
    """The octree of a screen-space scene's triangles (Hearn & Baker 13-10: the
    octree of the viewing volume, after the perspective transformation, so the view
    looks along its depth axis): node 0 is ``box`` (x0, x1, y0, y1, z0, z1); a node
    whose triangles (boxes ``lo``, ``hi`` (T, 3), all given to the root) number more
    than ``leaf`` is split at its middle into 8, each child listing the triangles
    whose boxes meet its own, unless it is ``max_depth`` levels down, narrower and
    lower than ``smallest`` (pixels), the split would list more than twice as many,
    or the arrays are full.  Node ``i``: ``nbox[i]``,
    first child ``nchild[i]`` (-1 for a leaf), its triangles ``entries[nstart[i]:
    nstart[i] + ncount[i]]``.  Returns (nodes, entries used)."""
    cap = nbox.shape[0]
    ecap = entries.shape[0]
    level = np.zeros(cap, np.int64)
    t_all = lo.shape[0]
    for k in range(6):
        nbox[0, k] = box[k]
    used = min(t_all, ecap)
    for t in range(used):
        entries[t] = t
    nstart[0] = 0
    ncount[0] = used
    nchild[0] = -1
    nxt = 1
    counts = np.zeros(8, np.int64)
    cb = np.empty((8, 6))
    o = 0
    while o < nxt:
        nchild[o] = -1
        cnt = ncount[o]
        if (cnt <= leaf or level[o] >= max_depth or nxt + 8 > cap
                or max(nbox[o, 1] - nbox[o, 0], nbox[o, 3] - nbox[o, 2]) < smallest):
            o += 1
            continue
        xm = 0.5 * (nbox[o, 0] + nbox[o, 1])
        ym = 0.5 * (nbox[o, 2] + nbox[o, 3])
        zm = 0.5 * (nbox[o, 4] + nbox[o, 5])
        for j in range(8):
            cb[j, 0] = xm if j & 1 else nbox[o, 0]
            cb[j, 1] = nbox[o, 1] if j & 1 else xm
            cb[j, 2] = ym if (j >> 1) & 1 else nbox[o, 2]
            cb[j, 3] = nbox[o, 3] if (j >> 1) & 1 else ym
            cb[j, 4] = zm if (j >> 2) & 1 else nbox[o, 4]
            cb[j, 5] = nbox[o, 5] if (j >> 2) & 1 else zm
            counts[j] = 0
        s0 = nstart[o]
        total = 0
        for e in range(s0, s0 + cnt):
            t = entries[e]
            for j in range(8):
                if meets(lo, hi, t, cb, j):
                    counts[j] += 1
                    total += 1
        if total > 2 * cnt or used + total > ecap:
            o += 1
            continue
        nchild[o] = nxt
        for j in range(8):
            c = nxt + j
            for k in range(6):
                nbox[c, k] = cb[j, k]
            level[c] = level[o] + 1
            nstart[c] = used
            ncount[c] = 0
            nchild[c] = -1
            used += counts[j]
        for e in range(s0, s0 + cnt):
            t = entries[e]
            for j in range(8):
                if meets(lo, hi, t, cb, j):
                    c = nxt + j
                    entries[nstart[c] + ncount[c]] = t
                    ncount[c] += 1
        nxt += 8
        o += 1
    return nxt, used


@helper
def pixel_range(a, b, size):
    """The pixel centers c with a <= c < b, clamped to 0 .. size - 1: (first, last)."""
    if not (a == a and b == b):
        return 0, -1
    first = max(int(math.ceil(min(max(a, -1.0), size + 1.0))), 0)
    last = min(int(math.ceil(min(max(b, -1.0), size + 1.0))) - 1, size - 1)
    return first, last


@helper
def covered(final, x0, x1, y0, y1):
    """Whether every pixel of the rectangle is final (an empty one is)."""
    for y in range(y0, y1 + 1):
        for x in range(x0, x1 + 1):
            if final[y, x] == 0:
                return False
    return True


@helper
def depth_plane(tri, t, g):
    """The depth of triangle ``t`` as a function of the screen, (value at vertex 0,
    d/dx, d/dy) into ``g``, by the z-buffer's own steps
    (:func:`scanline._kernels.raster3d.frame` and ``linear``, the first row of its
    ``planes``) so both find the same depths; False where the triangle covers no
    pixel (zero area, not finite)."""
    ex1, ey1, ex2, ey2, r = frame(tri[t, 0, 0], tri[t, 0, 1], tri[t, 1, 0], tri[t, 1, 1],
                                  tri[t, 2, 0], tri[t, 2, 1])
    if r == 0.0:
        return False
    g[0], g[1], g[2] = linear(tri[t, 0, 2], tri[t, 1, 2], tri[t, 2, 2], ex1, ey1, ex2, ey2, r)
    return math.isfinite(g[0] + g[1] + g[2])


@helper
def draw_leaf(tri, entries, e0, e1, px0, px1, py0, py1, z0, z1, ids, depth, final, touched,
              g):
    """Scan-convert the triangles ``entries[e0:e1]`` at the pixels of the rectangle
    px0..px1 x py0..py1 that are not final, keeping the nearest fragment with a depth
    in z0..z1; the pixels written the first time are listed in ``touched``.  Returns
    how many."""
    height, width = ids.shape
    ntri = tri.shape[0]
    nt = 0
    for e in range(e0, e1):
        t = entries[e]
        if t < 0 or t >= ntri or not depth_plane(tri, t, g):
            continue
        low, mid, high = rising(tri[t, 0, 1], tri[t, 1, 1], tri[t, 2, 1])
        r0, r1 = rows_of(tri[t, 0, 1], tri[t, 1, 1], tri[t, 2, 1], height)
        r0 = max(r0, py0)
        r1 = min(r1, py1)
        xt = tri[t, 0, 0]
        yt = tri[t, 0, 1]
        for y in range(r0, r1 + 1):
            kl, kr = span_limits(y, tri[t, low, 0], tri[t, low, 1], tri[t, mid, 0],
                                 tri[t, mid, 1], tri[t, high, 0], tri[t, high, 1], width)
            for x in range(max(kl, px0), min(kr, px1 + 1)):
                if final[y, x]:
                    continue
                z = g[0] + g[1] * (x - xt) + g[2] * (y - yt)
                if z0 <= z and z <= z1 and z < depth[y, x]:
                    if depth[y, x] == math.inf:
                        touched[nt] = y * width + x
                        nt += 1
                    depth[y, x] = z
                    ids[y, x] = t
    return nt


@kernel
def octree_visible(tri, nbox, nchild, nstart, ncount, entries, ids, depth, final):
    """The octree visible-surface method (Hearn & Baker 13-10) over the octree of
    :func:`scene_octree`: nodes depth first, front to back (the four octants nearer
    the viewer, then the four behind, within each node), and a node whose pixels are
    all final already is passed by with its subtree ("any node that is found to be
    completely obscured is eliminated from further processing").  A leaf
    scan-converts its triangles (the z-buffer's coverage rule and plane depths,
    :mod:`scanline._kernels.raster3d`) at the pixels of its cell that are not final,
    keeping the nearest fragment that lies within the cell's depth range; then every
    pixel it wrote is final, never written again.  Writes ``ids`` (H, W int32,
    cleared to -1), ``depth`` (H, W, cleared to inf) and ``final`` (H, W uint8,
    cleared to 0).  Returns the number of leaves drawn."""
    height, width = ids.shape
    n = nbox.shape[0]
    ecount = entries.shape[0]
    g = np.empty(3)
    cap = 8 * 64 + 1
    stack = np.empty(cap, np.int64)
    touched = np.empty(height * width, np.int64)
    sp = 1
    stack[0] = 0
    drawn = 0
    while sp > 0:
        sp -= 1
        o = stack[sp]
        px0, px1 = pixel_range(nbox[o, 0], nbox[o, 1], width)
        py0, py1 = pixel_range(nbox[o, 2], nbox[o, 3], height)
        if px0 > px1 or py0 > py1 or covered(final, px0, px1, py0, py1):
            continue
        c = nchild[o]
        if c > o and c + 8 <= n and sp + 8 <= cap:
            for j in range(7, -1, -1):        # octants 0-3 (front) popped first
                stack[sp] = c + j
                sp += 1
            continue
        s0 = max(nstart[o], 0)
        nt = draw_leaf(tri, entries, s0, min(s0 + ncount[o], ecount), px0, px1, py0, py1,
                       nbox[o, 4], nbox[o, 5], ids, depth, final, touched, g)
        for k in range(nt):
            final[touched[k] // width, touched[k] % width] = 1
        drawn += 1
    return drawn
