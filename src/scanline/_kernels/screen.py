"""Triangles of world coordinates to the screen, one pass per face (the per-face part of
:func:`scanline.screen.prepare`; Hearn & Baker, sections 12-3 and 13-2).

Per triangle: the back-face test in viewing coordinates (V . N > 0, V from the center
of projection to the first vertex, or the direction of projection), the homogeneous
clip coordinates of the vertices and the test of each against the clip volume's
planes, the perspective divide with the device mapping, and the plane A x + B y + C z
+ D = 0 of the device triangle by Newell's method (the triangles cut by the volume
are clipped by the caller, which owns the rare case).
"""

import math

import numpy as np

from ._jit import inline, kernel


#: Triangles per block: calls of :func:`project_faces` on several threads share the
#: blocks.
BLOCK = 1024


@kernel
def project_faces(start, step, world, view, toward, clip, planes, scale, offset, back, inside,
                  good, dev, inv_w, plane):
    """Project the triangles ``world`` (F, 3, 3), the blocks of :data:`BLOCK` numbered
    ``start``, ``start + step`` ...

    ``view`` (4, 4) world to viewing coordinates; ``toward`` (4,): the vector V of
    the back-face test is ``toward[3] p0 - toward[:3]`` (the center of projection with
    w = 1, or minus the direction of projection with w = 0); ``clip`` (4, 4) world to
    homogeneous clip coordinates; ``planes`` (P, 4) the clip volume (a x + b y + c z +
    d w >= 0 inside); ``scale``, ``offset`` (3,) the device mapping of x / w, y / w, z
    / w.  Writes ``back`` (F,) the back-face test, ``inside`` (F,) all three vertices
    in the volume, ``good`` (F,) every w > 0 and the device coordinates finite,
    ``dev`` (F, 3, 3), ``inv_w`` (F, 3) and ``plane`` (F, 4)."""
    e = np.empty((3, 3))
    n = world.shape[0]
    for first in range(start * BLOCK, n, max(step, 1) * BLOCK):
        for f in range(first, min(first + BLOCK, n)):
            project_face(f, world, view, toward, clip, planes, scale, offset, back, inside,
                         good, dev, inv_w, plane, e)


@inline
def project_face(f, world, view, toward, clip, planes, scale, offset, back, inside, good, dev,
                 inv_w, plane, e):
    """Triangle ``f`` of :func:`project_faces` (``e`` (3, 3) scratch)."""
    inside[f] = True
    good[f] = True
    for i in range(3):
        x = world[f, i, 0]
        y = world[f, i, 1]
        z = world[f, i, 2]
        h0 = clip[0, 0] * x + clip[0, 1] * y + clip[0, 2] * z + clip[0, 3]
        h1 = clip[1, 0] * x + clip[1, 1] * y + clip[1, 2] * z + clip[1, 3]
        h2 = clip[2, 0] * x + clip[2, 1] * y + clip[2, 2] * z + clip[2, 3]
        h3 = clip[3, 0] * x + clip[3, 1] * y + clip[3, 2] * z + clip[3, 3]
        for j in range(planes.shape[0]):
            if not (planes[j, 0] * h0 + planes[j, 1] * h1 + planes[j, 2] * h2
                    + planes[j, 3] * h3 >= 0):
                inside[f] = False
        q = 1.0 / h3
        inv_w[f, i] = q
        dev[f, i, 0] = h0 * q * scale[0] + offset[0]
        dev[f, i, 1] = h1 * q * scale[1] + offset[1]
        dev[f, i, 2] = h2 * q * scale[2] + offset[2]
        if not (h3 > 0 and math.isfinite(dev[f, i, 0]) and math.isfinite(dev[f, i, 1])
                and math.isfinite(dev[f, i, 2])):
            good[f] = False
    # the back-face test in viewing coordinates
    for i in range(3):
        x = world[f, i, 0]
        y = world[f, i, 1]
        z = world[f, i, 2]
        for r in range(3):
            e[i, r] = view[r, 0] * x + view[r, 1] * y + view[r, 2] * z + view[r, 3]
    ax = e[1, 0] - e[0, 0]
    ay = e[1, 1] - e[0, 1]
    az = e[1, 2] - e[0, 2]
    bx = e[2, 0] - e[0, 0]
    by = e[2, 1] - e[0, 1]
    bz = e[2, 2] - e[0, 2]
    vx = toward[3] * e[0, 0] - toward[0]
    vy = toward[3] * e[0, 1] - toward[1]
    vz = toward[3] * e[0, 2] - toward[2]
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
