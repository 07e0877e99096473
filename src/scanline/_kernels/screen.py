"""Triangles of world coordinates to the screen (the per-face part of
:func:`scanline.screen.prepare`; Hearn & Baker, sections 12-3 and 13-2): one pass over
the vertices, then one over the faces.

Per vertex: its viewing coordinates, its homogeneous clip coordinates and the test
against the clip volume's planes, the perspective divide with the device mapping (a
vertex is projected once, however many faces share it: about six in a closed mesh).
Per triangle: its vertices' results gathered, the back-face test in viewing
coordinates (V . N > 0, V from the center of projection to the first vertex, or the
direction of projection), and the plane A x + B y + C z + D = 0 of the device triangle
by Newell's method (the triangles cut by the volume are clipped by the caller, which
owns the rare case).  Projected per face instead (each of the teapot's 18,529 vertices
about six times), the teapot's 36,672 triangles took 1.52 ms on one core against 0.64
ms (0.20 the vertices, 0.44 the faces; cProfile, 2026-12-07).
"""

import math

from ._jit import kernel


#: Vertices or triangles per block: calls of :func:`project_points` or
#: :func:`project_faces` on several threads share the blocks.
BLOCK = 1024


@kernel
def project_points(start, step, points, view, clip, planes, scale, offset, eye, dev, inv_w,
                   inside, good):
    """Project the vertices ``points`` (V, 3), the blocks of :data:`BLOCK` numbered
    ``start``, ``start + step`` ...: each vertex once, whatever the number of faces
    that share it (:func:`project_faces` then reads them per face).

    ``view`` (4, 4) world to viewing coordinates; ``clip`` (4, 4) world to
    homogeneous clip coordinates; ``planes`` (P, 4) the clip volume (a x + b y + c z
    + d w >= 0 inside); ``scale``, ``offset`` (3,) the device mapping of x / w, y /
    w, z / w.  Writes ``eye`` (V, 3) the viewing coordinates, ``dev`` (V, 3) the
    device coordinates, ``inv_w`` (V,) 1 / w, ``inside`` (V,) in the volume and
    ``good`` (V,) w > 0 and the device coordinates finite."""
    n = points.shape[0]
    for first in range(start * BLOCK, n, max(step, 1) * BLOCK):
        for p in range(first, min(first + BLOCK, n)):
            x = points[p, 0]
            y = points[p, 1]
            z = points[p, 2]
            h0 = clip[0, 0] * x + clip[0, 1] * y + clip[0, 2] * z + clip[0, 3]
            h1 = clip[1, 0] * x + clip[1, 1] * y + clip[1, 2] * z + clip[1, 3]
            h2 = clip[2, 0] * x + clip[2, 1] * y + clip[2, 2] * z + clip[2, 3]
            h3 = clip[3, 0] * x + clip[3, 1] * y + clip[3, 2] * z + clip[3, 3]
            inside[p] = True
            for j in range(planes.shape[0]):
                if not (planes[j, 0] * h0 + planes[j, 1] * h1 + planes[j, 2] * h2
                        + planes[j, 3] * h3 >= 0):
                    inside[p] = False
            q = 1.0 / h3
            inv_w[p] = q
            dev[p, 0] = h0 * q * scale[0] + offset[0]
            dev[p, 1] = h1 * q * scale[1] + offset[1]
            dev[p, 2] = h2 * q * scale[2] + offset[2]
            good[p] = (h3 > 0 and math.isfinite(dev[p, 0]) and math.isfinite(dev[p, 1])
                       and math.isfinite(dev[p, 2]))
            for r in range(3):
                eye[p, r] = view[r, 0] * x + view[r, 1] * y + view[r, 2] * z + view[r, 3]


@kernel
def project_faces(start, step, corners, eye, pdev, pinv_w, pinside, pgood, toward, back,
                  inside, good, dev, inv_w, plane):
    """The triangles whose vertices are rows ``corners`` (F, 3) of the projected
    points (:func:`project_points`: ``eye``, ``pdev``, ``pinv_w``, ``pinside``,
    ``pgood``), the blocks of :data:`BLOCK` numbered ``start``, ``start + step`` ...

    ``toward`` (4,): the vector V of the back-face test is ``toward[3] p0 -
    toward[:3]`` (the center of projection with w = 1, or minus the direction of
    projection with w = 0).  Writes ``back`` (F,) the back-face test, ``inside``
    (F,) all three vertices in the volume, ``good`` (F,) all three good (a corner
    that is not a row of the points is not: nothing is read outside them), ``dev``
    (F, 3, 3), ``inv_w`` (F, 3) and ``plane`` (F, 4)."""
    n = corners.shape[0]
    count = pdev.shape[0]
    for first in range(start * BLOCK, n, max(step, 1) * BLOCK):
        for f in range(first, min(first + BLOCK, n)):
            p0 = corners[f, 0]
            p1 = corners[f, 1]
            p2 = corners[f, 2]
            if not (0 <= p0 < count and 0 <= p1 < count and 0 <= p2 < count):
                inside[f] = False           # (nothing is read outside the points)
                good[f] = False
                back[f] = False
                for i in range(3):
                    inv_w[f, i] = math.nan
                    for r in range(3):
                        dev[f, i, r] = math.nan
                for r in range(4):
                    plane[f, r] = math.nan
                continue
            inside[f] = pinside[p0] and pinside[p1] and pinside[p2]
            good[f] = pgood[p0] and pgood[p1] and pgood[p2]
            inv_w[f, 0] = pinv_w[p0]
            inv_w[f, 1] = pinv_w[p1]
            inv_w[f, 2] = pinv_w[p2]
            for r in range(3):
                dev[f, 0, r] = pdev[p0, r]
                dev[f, 1, r] = pdev[p1, r]
                dev[f, 2, r] = pdev[p2, r]
            # the back-face test in viewing coordinates
            ax = eye[p1, 0] - eye[p0, 0]
            ay = eye[p1, 1] - eye[p0, 1]
            az = eye[p1, 2] - eye[p0, 2]
            bx = eye[p2, 0] - eye[p0, 0]
            by = eye[p2, 1] - eye[p0, 1]
            bz = eye[p2, 2] - eye[p0, 2]
            vx = toward[3] * eye[p0, 0] - toward[0]
            vy = toward[3] * eye[p0, 1] - toward[1]
            vz = toward[3] * eye[p0, 2] - toward[2]
            dot = vx * (ay * bz - az * by) + vy * (az * bx - ax * bz) + vz * (ax * by - ay * bx)
            back[f] = dot > 0
            # Newell's normal of the device triangle, D through its centroid
            a = 0.0
            b = 0.0
            c = 0.0
            for i in range(3):
                j = (i + 1) % 3
                a += (dev[f, i, 1] - dev[f, j, 1]) * (dev[f, i, 2] + dev[f, j, 2])
                b += (dev[f, i, 2] - dev[f, j, 2]) * (dev[f, i, 0] + dev[f, j, 0])
                c += (dev[f, i, 0] - dev[f, j, 0]) * (dev[f, i, 1] + dev[f, j, 1])
            mx = (dev[f, 0, 0] + dev[f, 1, 0] + dev[f, 2, 0]) / 3.0
            my = (dev[f, 0, 1] + dev[f, 1, 1] + dev[f, 2, 1]) / 3.0
            mz = (dev[f, 0, 2] + dev[f, 1, 2] + dev[f, 2, 2]) / 3.0
            plane[f, 0] = a
            plane[f, 1] = b
            plane[f, 2] = c
            plane[f, 3] = -(a * mx + b * my + c * mz)
