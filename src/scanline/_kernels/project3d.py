"""Transforming and projecting many 3-D points and segments (Hearn & Baker,
sections 12-2 to 12-5): world coordinates -> homogeneous clip coordinates (one 4x4
matrix) -> clipping in homogeneous coordinates -> perspective divide -> the 3-D
viewport on the device.

``m`` is the camera's 4x4 world -> clip matrix; the view volume is the unit cube
0 <= x/w, y/w, z/w <= 1 of normalized device coordinates (NDC), and device
coordinates are ``ndc * scale + offset`` per axis (the 3-D viewport).
"""

import numpy as np

from ._jit import helper, kernel
from .clip import BLOCK
from .clip3d import parametric_six


@helper
def to_clip_row(m, x, y, z, out, i):
    """Row i of ``out`` (N, 4): m @ (x, y, z, 1)."""
    for r in range(4):
        out[i, r] = m[r, 0] * x + m[r, 1] * y + m[r, 2] * z + m[r, 3]


@kernel
def to_clip(m, pts, out):
    """Clip coordinates ``out`` (N, 4) of the points ``pts`` (N, 3): m @ (x, y, z, 1)."""
    for i in range(pts.shape[0]):
        to_clip_row(m, pts[i, 0], pts[i, 1], pts[i, 2], out, i)


@kernel
def project_points(m, scale, offset, pts, out):
    """Device coordinates (x, y, depth) of the points ``pts`` (N, 3) into ``out``
    (N, 3): (x_h, y_h, z_h, w) = m @ (x, y, z, 1), then (x_h / w, y_h / w, z_h / w)
    * scale + offset.  Points with w <= 0 (at or behind the eye of a perspective
    view) or a coordinate that is not finite get NaN: dividing by a negative w would
    mirror them through the eye."""
    m00, m01, m02, m03 = m[0, 0], m[0, 1], m[0, 2], m[0, 3]
    m10, m11, m12, m13 = m[1, 0], m[1, 1], m[1, 2], m[1, 3]
    m20, m21, m22, m23 = m[2, 0], m[2, 1], m[2, 2], m[2, 3]
    m30, m31, m32, m33 = m[3, 0], m[3, 1], m[3, 2], m[3, 3]
    sx, sy, sz = scale[0], scale[1], scale[2]
    ox, oy, oz = offset[0], offset[1], offset[2]
    for i in range(pts.shape[0]):
        x = pts[i, 0]
        y = pts[i, 1]
        z = pts[i, 2]
        w = m30 * x + m31 * y + m32 * z + m33
        if w > 0.0 and w < np.inf:
            r = 1.0 / w
            out[i, 0] = (m00 * x + m01 * y + m02 * z + m03) * r * sx + ox
            out[i, 1] = (m10 * x + m11 * y + m12 * z + m13) * r * sy + oy
            out[i, 2] = (m20 * x + m21 * y + m22 * z + m23) * r * sz + oz
        else:
            out[i, 0] = np.nan
            out[i, 1] = np.nan
            out[i, 2] = np.nan


@helper
def device_segment(seg, i, u1, u2, scale, offset, out, depth, j, limit):
    """The part u1 <= t <= u2 of the homogeneous segment ``seg[i : i + 8]``
    (x0, y0, z0, w0, x1, y1, z1, w1), divided and mapped to the device: row j of
    ``out`` (x0, y0, x1, y1) and of ``depth`` (z0, z1).  Returns False (and the row
    is not to be used) when round-off with enormous coordinates left an endpoint at
    w <= 0 or beyond +-``limit`` on the device."""
    ok = True
    for e in range(2):
        t = u1 if e == 0 else u2
        x = seg[i] + t * (seg[i + 4] - seg[i])
        y = seg[i + 1] + t * (seg[i + 5] - seg[i + 1])
        z = seg[i + 2] + t * (seg[i + 6] - seg[i + 2])
        w = seg[i + 3] + t * (seg[i + 7] - seg[i + 3])
        r = 1.0 / w if w > 0.0 else 0.0
        dx = x * r * scale[0] + offset[0]
        dy = y * r * scale[1] + offset[1]
        ok &= (w > 0.0) & (abs(dx) <= limit) & (abs(dy) <= limit)
        out[j, 2 * e] = dx
        out[j, 2 * e + 1] = dy
        if depth.shape[0] > 0:
            depth[j, e] = z * r * scale[2] + offset[2]
    return ok


@kernel
def project_edges(scale, offset, planes, clip, edges, out, depth, which, limit):
    """The edges ``edges`` (E, 2) of the vertices whose clip coordinates are ``clip``
    (V, 4) (:func:`to_clip`), clipped in homogeneous coordinates against the six
    ``planes``
    (Liang-Barsky, :func:`scanline._kernels.clip3d.parametric_six`, in blocks),
    divided and mapped to the device.  The visible parts are written one after
    another: row r of ``out`` (x0, y0, x1, y1) and of ``depth`` (z0, z1) comes from
    edge ``which[r]``; ``depth`` and ``which`` may be empty when not wanted.
    Returns the number of rows written.

    Edge indices must be in range (the API layer checks them); an edge with a
    non-finite vertex, or whose divided endpoints round-off put beyond +-``limit``
    (coordinates near the float64 range), is not visible."""
    dim = (0, 0, 0, 0)
    block = np.empty(8 * BLOCK)
    u1 = np.empty(BLOCK)
    u2 = np.empty(BLOCK)
    outside = np.empty(BLOCK, np.bool_)
    log = np.empty((0, 7))
    rows = 0
    total = edges.shape[0]
    for start in range(0, total, BLOCK):
        n = min(BLOCK, total - start)
        for j in range(n):
            a = edges[start + j, 0]
            b = edges[start + j, 1]
            for c in range(4):
                block[8 * j + c] = clip[a, c]
                block[8 * j + 4 + c] = clip[b, c]
        parametric_six(dim, block, planes, 0, n, u1, u2, outside, log)
        for j in range(n):
            finite = True
            for c in range(8):
                finite &= abs(block[8 * j + c]) < np.inf
            if (finite and (not outside[j]) and u1[j] <= u2[j]
                    and device_segment(block, 8 * j, u1[j], u2[j], scale, offset, out,
                                       depth, rows, limit)):
                if which.shape[0] > 0:
                    which[rows] = start + j
                rows += 1
    return rows
