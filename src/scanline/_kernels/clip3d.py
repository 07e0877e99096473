"""Clipping in three dimensions and in homogeneous coordinates (Hearn & Baker,
section 12-5; Blinn & Newell 1978).

A clip volume is a convex region given by K planes, each a row (a, b, c, d) of a
(K, 4) array: a point P = (x, y, z, w) is inside plane k when its *boundary value*
``d_k(P) = a x + b y + c z + d w`` is >= 0 (closed volumes: the boundary is inside).
Ordinary 3-D points have w = 1, so the rows are the usual plane equations; in
homogeneous clip coordinates the unit cube 0 <= x/w, y/w, z/w <= 1 is the six rows
x >= 0, w - x >= 0, y >= 0, w - y >= 0, z >= 0, w - z >= 0, which clip a segment
*before* the perspective divide: points behind the eye (w < 0) fail them, so no
part of a segment is mirrored through the eye or sent to infinity.

Points are rows of ``dim`` numbers: a *dimension token* (:func:`dim_token`) of
length 3 reads (x, y, z) with w = 1, of length 4 reads (x, y, z, w).  Segments are
flat arrays, segment i = ``seg[2 dim i : 2 dim (i + 1)]``.  The line clippers are
chosen by a *method token* (:mod:`scanline._kernels.variants`):

- Cohen-Sutherland, six-bit region codes: bit k + 1 set when d_k < 0 (for the
  volumes of :mod:`scanline.clip.volumes`: 1 left, 2 right, 3 below, 4 above,
  5 front, 6 back, as Hearn & Baker number them); trivial accept when both codes
  are 0, trivial reject when their AND is not 0, otherwise the outside endpoint
  (P0 first) moves to the crossing with the first plane its code names;
- Liang-Barsky: p_k = d_k(P0) - d_k(P1), q_k = d_k(P0) (for a box these are Hearn
  & Baker's p1 = -dx, q1 = x0 - xmin, ..., p6 = dz, q6 = zmax - z0), through the
  2-D clippers' :func:`scanline._kernels.clip.parametric_edge`.

Step tables run these functions uncompiled (:func:`scanline._kernels._jit.python`)
with ``trace`` set.
"""

import numpy as np

from ._jit import helper, kernel
from .clip import PARAM_COLUMNS, parametric_edge

COHEN_SUTHERLAND = 1
LIANG_BARSKY = 2

#: Cohen-Sutherland log columns: endpoint (0 or 1, -1 for the decision), code0,
#: code1, code0 AND code1, action, plane (1-based, 0 for none), x, y, z, w.
CS_ACCEPT = 0
CS_REJECT = 1
CS_CLIP = 2
CS_COLUMNS = 10
#: Each clip moves an endpoint onto one more plane: at most 6 per endpoint.
CS_MAX_STEPS = 12

__all__ = ["PARAM_COLUMNS"]


def dim_token(dim):
    """The token of points with ``dim`` (3 or 4) coordinates."""
    return (0,) * dim


@helper
def boundary(planes, k, x, y, z, w):
    """d_k(P) = a x + b y + c z + d w for plane row k."""
    return planes[k, 0] * x + planes[k, 1] * y + planes[k, 2] * z + planes[k, 3] * w


@helper
def region_code(planes, x, y, z, w):
    """The region code of P: bit k set when d_k(P) < 0 (a NaN sets every bit)."""
    code = 0
    for k in range(planes.shape[0]):
        if not boundary(planes, k, x, y, z, w) >= 0.0:
            code |= 1 << k
    return code


@helper
def endpoint(dim, seg, i, e, ends):
    """Endpoint e (0 or 1) of segment i of ``seg`` into ``ends[e]`` (x, y, z, w)."""
    n = len(dim)
    base = 2 * n * i + n * e
    ends[e, 0] = seg[base]
    ends[e, 1] = seg[base + 1]
    ends[e, 2] = seg[base + 2]
    ends[e, 3] = seg[base + 3] if len(dim) == 4 else 1.0


@helper
def store_segment(dim, out, i, ends):
    """``ends`` (2, 4) into segment i of ``out``."""
    n = len(dim)
    base = 2 * n * i
    for e in range(2):
        for c in range(n):
            out[base + n * e + c] = ends[e, c]


@helper
def cs_log(log, n, end, c0, c1, action, plane, ends, which):
    """Row n of a Cohen-Sutherland log (nothing when the log has no row n)."""
    if n < log.shape[0]:
        log[n, 0] = end
        log[n, 1] = c0
        log[n, 2] = c1
        log[n, 3] = c0 & c1
        log[n, 4] = action
        log[n, 5] = plane
        for c in range(4):
            log[n, 6 + c] = ends[which, c] if which >= 0 else np.nan


@helper
def cohen_sutherland(planes, start, ends, trace, log):
    """Cohen-Sutherland on one segment: ``start`` (2, 4) holds the original
    endpoints and ``ends`` (2, 4) receives the clipped ones.  Returns whether the
    segment is visible.

    At each step: accept if both codes are 0, reject if code0 AND code1 != 0,
    otherwise move the outside endpoint (P0 first) to the crossing with the first
    plane k its code names, at t = d_k(P0) / (d_k(P0) - d_k(P1)) along the original
    segment (Hearn & Baker's x = x0 + (x1 - x0) u, ... with u from the boundary), and
    give it the code of its new position with bit k cleared (it lies on plane k)."""
    for e in range(2):
        for c in range(4):
            ends[e, c] = start[e, c]
    c0 = region_code(planes, ends[0, 0], ends[0, 1], ends[0, 2], ends[0, 3])
    c1 = region_code(planes, ends[1, 0], ends[1, 1], ends[1, 2], ends[1, 3])
    for n in range(CS_MAX_STEPS + 1):
        if (c0 | c1) == 0:
            if trace:
                cs_log(log, n, -1, c0, c1, CS_ACCEPT, 0, ends, -1)
            return True
        if (c0 & c1) != 0 or n == CS_MAX_STEPS:
            if trace:
                cs_log(log, n, -1, c0, c1, CS_REJECT, 0, ends, -1)
            return False
        e = 0 if c0 != 0 else 1
        code = c0 if e == 0 else c1
        k = 0
        while (code >> k) & 1 == 0:
            k += 1
        d0 = boundary(planes, k, start[0, 0], start[0, 1], start[0, 2], start[0, 3])
        d1 = boundary(planes, k, start[1, 0], start[1, 1], start[1, 2], start[1, 3])
        t = d0 / (d0 - d1)
        for c in range(4):
            ends[e, c] = start[0, c] + t * (start[1, c] - start[0, c])
        new = region_code(planes, ends[e, 0], ends[e, 1], ends[e, 2], ends[e, 3])
        new &= ~(1 << k)
        if trace:
            cs_log(log, n, e, c0, c1, CS_CLIP, k + 1, ends, e)
        if e == 0:
            c0 = new
        else:
            c1 = new
    return False


@helper
def liang_barsky(planes, start, ends, trace, log):
    """Liang-Barsky on one segment (``start``, ``ends`` as in
    :func:`cohen_sutherland`): for each plane k, p_k = d_k(P0) - d_k(P1) and
    q_k = d_k(P0); p_k < 0 enters (u1 = max(u1, q_k / p_k)), p_k > 0 leaves
    (u2 = min(u2, q_k / p_k)), p_k = 0 with q_k < 0 is parallel and outside.
    Visible from u1 to u2 when no parallel plane has it outside and u1 <= u2."""
    u1 = 0.0
    u2 = 1.0
    outside = False
    for k in range(planes.shape[0]):
        d0 = boundary(planes, k, start[0, 0], start[0, 1], start[0, 2], start[0, 3])
        d1 = boundary(planes, k, start[1, 0], start[1, 1], start[1, 2], start[1, 3])
        out, u1, u2 = parametric_edge(d0 - d1, d0, k, u1, u2, trace, log)
        outside |= out
    ok = (not outside) & (u1 <= u2)
    for c in range(4):
        delta = start[1, c] - start[0, c]
        ends[0, c] = start[0, c] + u1 * delta if u1 > 0.0 else start[0, c]
        ends[1, c] = start[0, c] + u2 * delta if u2 < 1.0 else start[1, c]
    return ok


@helper
def clip_one(method, planes, start, ends, trace, log):
    """One segment through the clipper ``method`` (a token)."""
    if len(method) == COHEN_SUTHERLAND:
        return cohen_sutherland(planes, start, ends, trace, log)
    return liang_barsky(planes, start, ends, trace, log)


@kernel
def clip_segments(method, dim, seg, planes, out, accepted):
    """Clip every segment of the flat array ``seg`` against the convex volume
    ``planes`` (K, 4) with the clipper ``method``; write the visible part of
    segment i (or the segment as given) into ``out`` and whether any part is
    visible into ``accepted[i]``.  A segment with a NaN or an infinite coordinate
    is not accepted (its region code has every bit set)."""
    log = np.empty((0, CS_COLUMNS))
    start = np.empty((2, 4))
    ends = np.empty((2, 4))
    for i in range(accepted.shape[0]):
        endpoint(dim, seg, i, 0, start)
        endpoint(dim, seg, i, 1, start)
        finite = True
        for e in range(2):
            for c in range(4):
                finite &= abs(start[e, c]) < np.inf
        ok = finite and clip_one(method, planes, start, ends, False, log)
        accepted[i] = ok
        store_segment(dim, out, i, ends if ok else start)


def trace_segment(method, start, planes, log):
    """One segment ``start`` (2, 4) through ``method`` with its steps in ``log``:
    ``(visible, ends)``.  Run as Python by the step tables (no compilation)."""
    from ._jit import python

    ends = np.empty((2, 4))
    ok = python(clip_one)(method, planes, start, ends, True, log)
    return bool(ok), ends


@helper
def polygon_stage(dim_n, src, n, dst, planes, k):
    """One Sutherland-Hodgman stage: the ``n`` vertices (rows of ``src``, the first
    ``dim_n`` columns the point, the rest attributes interpolated with it) clipped by
    plane k into ``dst``.  Returns the number of rows written, or -1 when ``dst`` is
    too small.  For each polygon edge S -> P: both inside, output P; leaving,
    output the crossing I; entering, output I and P; both outside, nothing."""
    cap = dst.shape[0]
    cols = src.shape[1]
    m = 0
    if n == 0:
        return 0
    ws = src[n - 1, 3] if dim_n == 4 else 1.0
    ds = boundary(planes, k, src[n - 1, 0], src[n - 1, 1], src[n - 1, 2], ws)
    s = n - 1
    for i in range(n):
        wp = src[i, 3] if dim_n == 4 else 1.0
        dp = boundary(planes, k, src[i, 0], src[i, 1], src[i, 2], wp)
        if (ds >= 0.0) != (dp >= 0.0) and ds != 0.0 and dp != 0.0:
            # (a crossing at t = 0 or 1 is S or P itself, written once)
            if m >= cap:
                return -1
            t = ds / (ds - dp)
            for c in range(cols):
                dst[m, c] = src[s, c] + t * (src[i, c] - src[s, c])
            m += 1
        if dp >= 0.0:
            if m >= cap:
                return -1
            for c in range(cols):
                dst[m, c] = src[i, c]
            m += 1
        s = i
        ds = dp
    return m


@kernel
def clip_polygons(dim, verts, counts, planes, out, out_counts, scratch):
    """Sutherland-Hodgman: clip each polygon (``counts[p]`` consecutive rows of
    ``verts`` (V, C), C >= ``len(dim)``) against each plane of ``planes`` in turn.

    The results go one after another into ``out`` with their vertex counts in
    ``out_counts`` (0 when fewer than three vertices are left).  Returns the rows
    of ``out`` used, or -1 when ``out`` or ``scratch`` ((2, M, C) ping-pong buffers)
    is too small.  A polygon with a NaN or infinite coordinate is dropped."""
    start = 0
    used = 0
    cap = scratch.shape[1]
    cols = verts.shape[1]
    n_dim = len(dim)
    for p in range(counts.shape[0]):
        n = counts[p]
        if n > cap:
            return -1
        a = scratch[0]
        b = scratch[1]
        finite = True
        for i in range(n):
            for c in range(cols):
                a[i, c] = verts[start + i, c]
                finite &= abs(a[i, c]) < np.inf
        start += n
        if not finite:
            n = 0
        for k in range(planes.shape[0]):
            n = polygon_stage(n_dim, a, n, b, planes, k)
            if n < 0:
                return -1
            a, b = b, a
        if n < 3:
            n = 0
        if used + n > out.shape[0]:
            return -1
        for i in range(n):
            for c in range(cols):
                out[used + i, c] = a[i, c]
        out_counts[p] = n
        used += n
    return used
