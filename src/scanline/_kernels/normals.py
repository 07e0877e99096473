"""Vertex normals split at a crease angle, weighted by the faces' angles: the normal
at each corner of each face (:func:`scanline.screen.meshes.corner_normals`)."""

import math

from ._jit import kernel


@kernel
def crease_normals(corner_face, face_normals, angles, order, starts, cos_crease, out):
    """The normal at every face corner c (``out[c]``, unit): the sum of the unit
    normals of the faces around its vertex whose normals lie within the crease angle
    of its own face's (n_g . n_f >= ``cos_crease``), each weighted by that face's
    angle at the vertex (``angles``; Thurmer & Wuthrich 1998), normalized.
    ``corner_face`` (C,) the face of each corner; ``order`` (C,) the corners sorted by
    vertex and ``starts`` (V + 1,) where each vertex's run begins in it.  A corner of
    a face without a normal (no area) takes the plain weighted sum around it; a zero
    sum gives a zero normal."""
    nv = starts.shape[0] - 1
    nc = order.shape[0]
    for v in range(nv):
        s = max(starts[v], 0)
        e = min(starts[v + 1], nc)
        for i in range(s, e):
            c = order[i]
            f = corner_face[c]
            fx = face_normals[f, 0]
            fy = face_normals[f, 1]
            fz = face_normals[f, 2]
            flat = fx == 0.0 and fy == 0.0 and fz == 0.0
            sx = 0.0
            sy = 0.0
            sz = 0.0
            for j in range(s, e):
                d = order[j]
                g = corner_face[d]
                gx = face_normals[g, 0]
                gy = face_normals[g, 1]
                gz = face_normals[g, 2]
                if flat or gx * fx + gy * fy + gz * fz >= cos_crease:
                    w = angles[d]
                    sx += w * gx
                    sy += w * gy
                    sz += w * gz
            n = math.sqrt(sx * sx + sy * sy + sz * sz)
            r = 1.0 / n if n > 0.0 else 0.0
            out[c, 0] = sx * r
            out[c, 1] = sy * r
            out[c, 2] = sz * r
