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
  (P0 first) moves to the crossing with the first plane its code names, exactly
  onto that plane; the crossing's code comes from the boundary values at the
  original endpoints, and the bits of the planes an endpoint was moved onto stay
  cleared (round-off at an edge or a corner cannot send it back and forth); at
  most 64 planes, one bit each;
- Liang-Barsky: p_k = d_k(P0) - d_k(P1), q_k = d_k(P0) (for a box these are Hearn
  & Baker's p1 = -dx, q1 = x0 - xmin, ..., p6 = dz, q6 = zmax - z0), through the
  2-D clippers' :func:`scanline._kernels.clip.parametric_edge`.

Step tables run these functions uncompiled (:func:`scanline._kernels._jit.python`)
with ``trace`` set.
"""

import numpy as np

from ._jit import helper, kernel
from .clip import BLOCK, PARAM_COLUMNS, parametric_edge

COHEN_SUTHERLAND = 1
LIANG_BARSKY = 2

#: Cohen-Sutherland log columns: endpoint (0 or 1, -1 for the decision), code0,
#: code1, code0 AND code1, action, plane (1-based, 0 for none), x, y, z, w.
CS_ACCEPT = 0
CS_REJECT = 1
CS_CLIP = 2
CS_COLUMNS = 10


def cs_steps(planes):
    """Most rows of a Cohen-Sutherland log for a volume of ``planes`` (K) planes:
    each clip moves an endpoint onto one more plane, at most K per endpoint, and one
    row for the decision."""
    return 2 * planes + 1

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
def snap(planes, k, ends, e):
    """Put endpoint e of ``ends`` exactly on plane k: solve a x + b y + c z + d w = 0
    for the coordinate with the largest coefficient among a, b, c (x = xmin, x = w,
    x = z ... exactly for the planes of a box, the homogeneous unit cube and the
    frustum, whose coefficients are 0 and +-1)."""
    i = 0
    for c in range(1, 3):
        if abs(planes[k, c]) > abs(planes[k, i]):
            i = c
    rest = planes[k, 3] * ends[e, 3]
    for c in range(3):
        if c != i:
            rest += planes[k, c] * ends[e, c]
    ends[e, i] = 0.0 - rest / planes[k, i]     # (0.0 -: x = 0, not -0, on x >= 0)


@helper
def crossing_code(planes, start, k, d0, d1, ends, e):
    """The region code of the crossing of the segment ``start`` with plane k (d0, d1:
    d_k at its endpoints), from the boundary values at the endpoints rather than from
    the rounded coordinates of the point: d_m at the crossing, times d0 - d1, is
    d0 d_m(P1) - d1 d_m(P0), whose sign is exact where the boundary values and their
    products are (a segment through an edge or a corner given in short binary
    fractions).  Where a product overflows, bit m is that of the point ``ends[e]``."""
    code = 0
    for m in range(planes.shape[0]):
        a0 = boundary(planes, m, start[0, 0], start[0, 1], start[0, 2], start[0, 3])
        a1 = boundary(planes, m, start[1, 0], start[1, 1], start[1, 2], start[1, 3])
        det = d0 * a1 - d1 * a0
        if det == det:
            outside = det < 0.0 if d0 > d1 else det > 0.0
        else:
            outside = not boundary(planes, m, ends[e, 0], ends[e, 1], ends[e, 2],
                                   ends[e, 3]) >= 0.0
        if outside:
            code |= 1 << m
    return code


@helper
def cohen_sutherland(planes, start, ends, trace, log):
    """Cohen-Sutherland on one segment: ``start`` (2, 4) holds the original
    endpoints and ``ends`` (2, 4) receives the clipped ones.  Returns whether the
    segment is visible.

    At each step: accept if both codes are 0, reject if code0 AND code1 != 0,
    otherwise move the outside endpoint (P0 first) to the crossing with the first
    plane k its code names, at t = d_k(P0) / (d_k(P0) - d_k(P1)) along the original
    segment (Hearn & Baker's x = x0 + (x1 - x0) u, ... with u from the boundary),
    put it exactly on plane k (:func:`snap`), and give it the region code of the
    crossing (:func:`crossing_code`) with the bits of plane k *and of every plane
    this endpoint was moved onto before* cleared.

    In exact arithmetic those bits are 0 anyway: the endpoint only moves toward the
    other one, so it stays inside each plane it has crossed.  In floating point a
    point computed on one plane where the segment enters through an edge or a corner
    can land an ulp outside the other plane; recomputing that bit from the rounded
    coordinates sent the endpoint back and forth between the two planes until a step
    limit rejected a visible segment.  Now each endpoint is moved at most once per
    plane: at most 2 K clips for K planes, after which both codes are 0.  A moved
    endpoint that round-off puts outside a plane its code says it is inside (or on)
    is put on that plane; for a box and the homogeneous unit cube, whose planes each
    fix one coordinate, an accepted segment lies in the closed volume exactly, and
    one that enters through an edge ends exactly on both planes.  The endpoints'
    parameters stay in order (t0 <= t1), so a crossing that round-off puts beyond
    the other endpoint moves no endpoint backward.

    Decisions: with exactly representable boundary values and products (coordinates
    in short binary fractions), the region codes of the crossings are exact, so a
    segment is accepted exactly when some point of it lies in the closed volume --
    also one that only touches an edge or a corner from outside, accepted as that
    point.  Otherwise a segment that touches the volume, or misses it, by round-off
    may go either way, as with Liang-Barsky's u1 <= u2."""
    for e in range(2):
        for c in range(4):
            ends[e, c] = start[e, c]
    c0 = region_code(planes, ends[0, 0], ends[0, 1], ends[0, 2], ends[0, 3])
    c1 = region_code(planes, ends[1, 0], ends[1, 1], ends[1, 2], ends[1, 3])
    done0 = 0                       # the planes each endpoint was moved onto
    done1 = 0
    t0 = 0.0                        # and where the endpoints are on the segment
    t1 = 1.0
    steps = 2 * planes.shape[0]
    for n in range(steps + 1):
        if (c0 | c1) == 0:
            if trace:
                cs_log(log, n, np.int64(-1), c0, c1, CS_ACCEPT, np.int64(0), ends, np.int64(-1))
            return True
        if (c0 & c1) != 0 or n == steps:              # (n == steps: cannot happen)
            if trace:
                cs_log(log, n, np.int64(-1), c0, c1, CS_REJECT, np.int64(0), ends, np.int64(-1))
            return False
        e = 0 if c0 != 0 else 1
        code = c0 if e == 0 else c1
        k = 0
        while (code >> k) & 1 == 0:
            k += 1
        d0 = boundary(planes, k, start[0, 0], start[0, 1], start[0, 2], start[0, 3])
        d1 = boundary(planes, k, start[1, 0], start[1, 1], start[1, 2], start[1, 3])
        crossing = d0 / (d0 - d1) if d0 != d1 else np.nan   # (parallel: by round-off)
        here = t0 if e == 0 else t1
        t = min(max(crossing, t0), t1) if crossing == crossing else here
        # (beyond the other endpoint, or NaN: only by round-off or overflow)
        if t != here:
            for c in range(4):
                ends[e, c] = start[0, c] + t * (start[1, c] - start[0, c])
        done = (done0 if e == 0 else done1) | (1 << k)
        snap(planes, k, ends, e)
        if t == crossing:
            new = crossing_code(planes, start, k, d0, d1, ends, e) & ~done
        else:
            new = region_code(planes, ends[e, 0], ends[e, 1], ends[e, 2], ends[e, 3]) & ~done
        for m in range(planes.shape[0]):  # inside (or on) a plane, outside by round-off:
            if (new >> m) & 1 == 0 and m != k and \
                    boundary(planes, m, ends[e, 0], ends[e, 1], ends[e, 2], ends[e, 3]) < 0.0:
                snap(planes, m, ends, e)  # put it on the plane
        finite = True
        for c in range(4):
            finite &= abs(ends[e, c]) < np.inf
        if not finite:                    # (overflow: finite coordinates near 1e308)
            if trace:
                cs_log(log, n, np.int64(-1), c0, c1, CS_REJECT, np.int64(0), ends,
                       np.int64(-1))
            return False
        if trace:
            cs_log(log, n, e, c0, c1, CS_CLIP, k + 1, ends, e)
        if e == 0:
            c0 = new
            done0 = done
            t0 = t
        else:
            c1 = new
            done1 = done
            t1 = t
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
    if len(method) == LIANG_BARSKY:
        parametric_segments(dim, seg, planes, out, accepted, log)
        return
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


@helper
def parametric_step(p, q, u1, u2, log):
    """One plane of Liang-Barsky without the step log: the 2-D clippers'
    :func:`scanline._kernels.clip.parametric_edge`, inlined once here and called
    by the block loops (a single inlined copy compiles faster than one per plane)."""
    return parametric_edge(p, q, 0, u1, u2, False, log)


@helper
def parametric_block(dim, seg, planes, start, m, u1, u2, outside, log):
    """Liang-Barsky's u1, u2 and parallel-outside flags for segments start ..
    start + m - 1, one plane at a time over the whole block: the inner loop runs over
    the segments with selects instead of branches (as the 2-D clippers'), so the
    compiler can process several at once."""
    n = len(dim)
    seg = seg[2 * n * start:2 * n * (start + m)]
    for j in range(m):
        u1[j] = 0.0
        u2[j] = 1.0
        outside[j] = False
    for k in range(planes.shape[0]):
        a = planes[k, 0]
        b = planes[k, 1]
        c = planes[k, 2]
        d = planes[k, 3]
        for j in range(m):
            base = 2 * n * j
            w0 = seg[base + 3] if n == 4 else 1.0
            w1 = seg[base + n + 3] if n == 4 else 1.0
            d0 = a * seg[base] + b * seg[base + 1] + c * seg[base + 2] + d * w0
            d1 = a * seg[base + n] + b * seg[base + n + 1] + c * seg[base + n + 2] + d * w1
            out, v1, v2 = parametric_step(d0 - d1, d0, u1[j], u2[j], log)
            u1[j] = v1
            u2[j] = v2
            outside[j] |= out


@helper
def parametric_six(dim, seg, planes, start, m, u1, u2, outside, log):
    """:func:`parametric_block` for the six planes of a box or a frustum, with the
    plane coefficients held in registers and the six steps written out, so that the
    loop over the segments runs without branches."""
    n = len(dim)
    seg = seg[2 * n * start:2 * n * (start + m)]   # indexed from 0: no wraparound checks
    a0, b0, c0, e0 = planes[0, 0], planes[0, 1], planes[0, 2], planes[0, 3]
    a1, b1, c1, e1 = planes[1, 0], planes[1, 1], planes[1, 2], planes[1, 3]
    a2, b2, c2, e2 = planes[2, 0], planes[2, 1], planes[2, 2], planes[2, 3]
    a3, b3, c3, e3 = planes[3, 0], planes[3, 1], planes[3, 2], planes[3, 3]
    a4, b4, c4, e4 = planes[4, 0], planes[4, 1], planes[4, 2], planes[4, 3]
    a5, b5, c5, e5 = planes[5, 0], planes[5, 1], planes[5, 2], planes[5, 3]
    for j in range(m):
        base = 2 * n * j
        x0 = seg[base]
        y0 = seg[base + 1]
        z0 = seg[base + 2]
        w0 = seg[base + 3] if n == 4 else 1.0
        x1 = seg[base + n]
        y1 = seg[base + n + 1]
        z1 = seg[base + n + 2]
        w1 = seg[base + n + 3] if n == 4 else 1.0
        q = a0 * x0 + b0 * y0 + c0 * z0 + e0 * w0
        o0, v1, v2 = parametric_step(q - (a0 * x1 + b0 * y1 + c0 * z1 + e0 * w1), q,
                                            0.0, 1.0, log)
        q = a1 * x0 + b1 * y0 + c1 * z0 + e1 * w0
        o1, v1, v2 = parametric_step(q - (a1 * x1 + b1 * y1 + c1 * z1 + e1 * w1), q,
                                            v1, v2, log)
        q = a2 * x0 + b2 * y0 + c2 * z0 + e2 * w0
        o2, v1, v2 = parametric_step(q - (a2 * x1 + b2 * y1 + c2 * z1 + e2 * w1), q,
                                            v1, v2, log)
        q = a3 * x0 + b3 * y0 + c3 * z0 + e3 * w0
        o3, v1, v2 = parametric_step(q - (a3 * x1 + b3 * y1 + c3 * z1 + e3 * w1), q,
                                            v1, v2, log)
        q = a4 * x0 + b4 * y0 + c4 * z0 + e4 * w0
        o4, v1, v2 = parametric_step(q - (a4 * x1 + b4 * y1 + c4 * z1 + e4 * w1), q,
                                            v1, v2, log)
        q = a5 * x0 + b5 * y0 + c5 * z0 + e5 * w0
        o5, v1, v2 = parametric_step(q - (a5 * x1 + b5 * y1 + c5 * z1 + e5 * w1), q,
                                            v1, v2, log)
        u1[j] = v1
        u2[j] = v2
        outside[j] = o0 | o1 | o2 | o3 | o4 | o5


@helper
def parametric_segments(dim, seg, planes, out, accepted, log):
    """The Liang-Barsky batch of :func:`clip_segments`, in blocks of
    :data:`scanline._kernels.clip.BLOCK` segments (:func:`parametric_block`; the
    wireframe kernel uses :func:`parametric_six`, which is faster but takes longer to
    compile)."""
    n = len(dim)
    total = accepted.shape[0]
    u1 = np.empty(BLOCK)
    u2 = np.empty(BLOCK)
    outside = np.empty(BLOCK, np.bool_)
    for start in range(0, total, BLOCK):
        m = min(BLOCK, total - start)
        parametric_block(dim, seg, planes, start, m, u1, u2, outside, log)
        s = seg[2 * n * start:2 * n * (start + m)]     # indexed from 0, as the block
        o = out[2 * n * start:2 * n * (start + m)]
        acc = accepted[start:start + m]
        for j in range(m):
            base = 2 * n * j
            finite = True
            for c in range(2 * n):
                finite &= abs(s[base + c]) < np.inf
            ok = finite and (not outside[j]) and u1[j] <= u2[j]
            acc[j] = ok
            t0 = u1[j] if ok else 0.0
            t1 = u2[j] if ok else 1.0
            for c in range(n):
                a = s[base + c]
                b = s[base + n + c]
                o[base + c] = a + t0 * (b - a) if t0 > 0.0 else a
                o[base + n + c] = a + t1 * (b - a) if t1 < 1.0 else b


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
