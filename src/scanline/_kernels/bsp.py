"""Binary space-partitioning trees (Fuchs, Kedem and Naylor 1980; Hearn & Baker,
section 13-7): the build, one resumable kernel, and the back-to-front traversal.

Pieces are convex polygons in world coordinates: piece ``p`` is the ``pc[p, 1]``
vertices of ``verts`` from ``pc[p, 0]``, of face ``pc[p, 2]``.  The sets still to
partition are segments of ``pool`` listed on ``stack`` (start, length, parent
node, side: 1 front, 0 back).  Node ``n`` has the plane ``planes[n]`` (A, B, C, D;
unit normal, > 0 in front), the children ``nodes[n, 0]`` (front) and ``nodes[n, 1]``
(back), -1 for none, and the pieces lying in its plane, ``members[nodes[n, 2]:]``
(``nodes[n, 3]`` of them).

When an array has too little room for the next set the kernel returns
:data:`NEED_ROOM` before changing anything (``st[WHICH]`` says which array); the
caller enlarges it and calls again.
"""

import numpy as np

from ._jit import helper, kernel
from .planecut import plane_part

# -- the state array ``st`` ---------------------------------------------------------------
VERTS = 0
PIECES = 1
STACK = 2
POOL = 3
NODES = 4
MEMBERS = 5
SPLITS = 6
STATUS = 7
WHICH = 8
STATE = 9

DONE = 0
NEED_ROOM = 1
TOO_MANY = 2

ROOM_VERTS = 0
ROOM_PIECES = 1
ROOM_STACK = 2
ROOM_POOL = 3
ROOM_NODES = 4
ROOM_MEMBERS = 5


@helper
def face_plane(verts, pc, p, plane):
    """Newell's plane of piece ``p`` into ``plane``, its normal of unit length (left
    as is when the piece has no area)."""
    a = 0.0
    b = 0.0
    c = 0.0
    cx = 0.0
    cy = 0.0
    cz = 0.0
    s = pc[p, 0]
    k = pc[p, 1]
    for i in range(k):
        j = s + i + 1 if i + 1 < k else s
        x0, y0, z0 = verts[s + i, 0], verts[s + i, 1], verts[s + i, 2]
        x1, y1, z1 = verts[j, 0], verts[j, 1], verts[j, 2]
        a += (y0 - y1) * (z0 + z1)
        b += (z0 - z1) * (x0 + x1)
        c += (x0 - x1) * (y0 + y1)
        cx += x0
        cy += y0
        cz += z0
    norm = (a * a + b * b + c * c) ** 0.5
    if norm == 0.0:
        norm = 1.0
    plane[0] = a / norm
    plane[1] = b / norm
    plane[2] = c / norm
    plane[3] = -(plane[0] * cx + plane[1] * cy + plane[2] * cz) / k


@helper
def extent(verts, pc, p, plane):
    """The least and greatest signed distance of piece ``p``'s vertices to ``plane``."""
    lo = np.inf
    hi = -np.inf
    for i in range(pc[p, 0], pc[p, 0] + pc[p, 1]):
        d = verts[i, 0] * plane[0] + verts[i, 1] * plane[1] + verts[i, 2] * plane[2] + plane[3]
        lo = min(lo, d)
        hi = max(hi, d)
    return lo, hi


@helper
def split_piece(verts, pc, st, p, plane, eps, sign):
    """The part of piece ``p`` in front of ``plane`` (``sign`` 1.0) or behind it
    (-1.0), by :func:`~scanline._kernels.planecut.plane_part`, appended to ``verts``
    as a new piece of ``p``'s face; returns the new piece, or -1 when the part has
    fewer than three vertices."""
    start = st[VERTS]
    m = plane_part(verts, pc[p, 0], pc[p, 1], plane, eps, sign, start)
    if m < 3:
        return -1
    q = st[PIECES]
    pc[q, 0] = start
    pc[q, 1] = m
    pc[q, 2] = pc[p, 2]
    st[PIECES] = q + 1
    st[VERTS] = start + m
    return q


@kernel
def build(verts, pc, stack, pool, scratch, planes, nodes, members, st, eps, limit):
    """Partition the sets on ``stack`` until none is left (Hearn & Baker 13-7): the
    first piece of a set gives the node's plane; the others lie in it, in front of
    it, behind it, or across it (split in two).  ``limit``: most pieces in all.
    Returns the status (also ``st[STATUS]``)."""
    plane = np.empty(4)
    while st[STACK] > 0:
        e = st[STACK] - 1
        a = stack[e, 0]
        m = stack[e, 1]
        short = -1                   # room for this set (known once it is classified)
        if 4 * m > scratch.shape[0]:
            short = ROOM_POOL
        else:
            # classify the set by the plane of its first piece: 0 in the plane (the
            # first always), 1 wholly in front, 2 wholly behind, 3 across (split)
            face_plane(verts, pc, pool[a], plane)
            across = 0
            cut_verts = 0
            for i in range(m):
                p = pool[a + i]
                lo, hi = extent(verts, pc, p, plane)
                code = 0 if i == 0 or lo >= -eps and hi <= eps else (
                    1 if lo >= -eps else (2 if hi <= eps else 3))
                scratch[3 * m + i] = code
                if code == 3:
                    across += 1
                    cut_verts += 4 * pc[p, 1]         # each part: <= k vertices, k cuts
            if st[VERTS] + cut_verts > verts.shape[0]:
                short = ROOM_VERTS
            elif st[PIECES] + 2 * across > pc.shape[0]:
                short = ROOM_PIECES
            elif e + 2 > stack.shape[0]:
                short = ROOM_STACK
            elif a + m + across > pool.shape[0]:
                short = ROOM_POOL
            elif st[NODES] + 1 > planes.shape[0]:
                short = ROOM_NODES
            elif st[MEMBERS] + m > members.shape[0]:
                short = ROOM_MEMBERS
        if short >= 0:
            st[STATUS] = NEED_ROOM
            st[WHICH] = short
            return NEED_ROOM
        parent = stack[e, 2]
        side = stack[e, 3]
        st[STACK] = e
        for i in range(m):
            scratch[i] = pool[a + i]
        node = st[NODES]
        st[NODES] = node + 1
        if parent >= 0:
            nodes[parent, 1 - side] = node
        nodes[node, 0] = -1
        nodes[node, 1] = -1
        for c in range(4):
            planes[node, c] = plane[c]
        nodes[node, 2] = st[MEMBERS]
        # first pass: the pieces in the plane, wholly in front, wholly behind
        nf = 0
        nb = 0
        for i in range(m):
            p = scratch[i]
            code = scratch[3 * m + i]
            if code == 0:
                members[st[MEMBERS]] = p
                st[MEMBERS] += 1
            elif code == 1:
                pool[a + nf] = p
                nf += 1
            elif code == 2:
                scratch[m + nb] = p
                nb += 1
        # second pass: the pieces across the plane, split, their parts after the others
        for i in range(m):
            if scratch[3 * m + i] != 3:
                continue
            p = scratch[i]
            if st[PIECES] + 2 > limit:
                st[STATUS] = TOO_MANY
                return TOO_MANY
            st[SPLITS] += 1
            q = split_piece(verts, pc, st, p, plane, eps, 1.0)
            if q >= 0:
                pool[a + nf] = q
                nf += 1
            q = split_piece(verts, pc, st, p, plane, eps, -1.0)
            if q >= 0:
                scratch[m + nb] = q
                nb += 1
        nodes[node, 3] = st[MEMBERS] - nodes[node, 2]
        for i in range(nb):
            pool[a + nf + i] = scratch[m + i]
        top = st[STACK]
        if nf > 0:                   # the back set is pushed last: partitioned first
            stack[top, 0] = a
            stack[top, 1] = nf
            stack[top, 2] = node
            stack[top, 3] = 1
            top += 1
        if nb > 0:
            stack[top, 0] = a + nf
            stack[top, 1] = nb
            stack[top, 2] = node
            stack[top, 3] = 0
            top += 1
        st[STACK] = top
    st[STATUS] = DONE
    return DONE


@kernel
def back_to_front(planes, nodes, members, eye, out, stack):
    """The pieces of the tree in drawing order from the homogeneous ``eye`` into
    ``out``: at each node the subtree on the far side, the node's own pieces, then
    the subtree on the eye's side.  ``stack``: scratch of two entries per node.
    Returns the count written."""
    n = 0
    top = 0
    if planes.shape[0] == 0:
        return n
    stack[0, 0] = 0
    stack[0, 1] = 0
    top = 1
    while top > 0:
        top -= 1
        node = stack[top, 0]
        if stack[top, 1] == 1:
            for i in range(nodes[node, 2], nodes[node, 2] + nodes[node, 3]):
                out[n] = members[i]
                n += 1
            continue
        side = (planes[node, 0] * eye[0] + planes[node, 1] * eye[1] + planes[node, 2] * eye[2]
                + planes[node, 3] * eye[3])
        near = nodes[node, 0] if side >= 0 else nodes[node, 1]
        far = nodes[node, 1] if side >= 0 else nodes[node, 0]
        if near >= 0:
            stack[top, 0] = near
            stack[top, 1] = 0
            top += 1
        stack[top, 0] = node
        stack[top, 1] = 1
        top += 1
        if far >= 0:
            stack[top, 0] = far
            stack[top, 1] = 0
            top += 1
    return n
