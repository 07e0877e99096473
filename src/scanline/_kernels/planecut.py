"""Cutting a convex polygon by a plane (Sutherland and Hodgman's clipper against one
plane, Hearn & Baker section 6-8, in 3-D): the part on one side, for the methods
that split polygons -- depth sort (section 13-6) and BSP trees (13-7)."""

from ._jit import helper


@helper
def plane_part(verts, start, k, plane, eps, sign, dst):
    """The part of the convex polygon ``verts[start:start + k]`` on the side of
    ``plane`` (A, B, C, D) where ``sign`` * distance >= -``eps`` (1.0: the positive
    side, -1.0: the negative one; points within ``eps`` of the plane belong to both),
    with a vertex where an edge crosses from beyond ``eps`` on one side to beyond it
    on the other; written to ``verts[dst:]`` (room for 2 k rows).  Returns its
    vertex count."""
    m = 0
    for i in range(k):
        a = start + i
        b = start + i + 1 if i + 1 < k else start
        da = verts[a, 0] * plane[0] + verts[a, 1] * plane[1] + verts[a, 2] * plane[2] + plane[3]
        db = verts[b, 0] * plane[0] + verts[b, 1] * plane[1] + verts[b, 2] * plane[2] + plane[3]
        if da * sign >= -eps:
            for c in range(3):
                verts[dst + m, c] = verts[a, c]
            m += 1
        if da > eps and db < -eps or da < -eps and db > eps:
            u = da / (da - db)
            for c in range(3):
                verts[dst + m, c] = verts[a, c] + (verts[b, c] - verts[a, c]) * u
            m += 1
    return m
