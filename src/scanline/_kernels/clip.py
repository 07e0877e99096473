"""Line and polygon clipping (notes, chapter 4, Q.3-Q.4).

Each line clipper is one helper that clips one segment and can log its steps into
an array: the batch kernels pass a log with no rows, the step tables
(:mod:`scanline.trace.clip`) pass a log with room for every step.  The table and the
clipped segments therefore come from the same code.

Windows are closed: a point on the boundary is inside (the notes' inequalities
``xwmin <= x <= xwmax``).  Convex polygon windows are given counterclockwise, so the
outward normal of the edge from ``a`` to ``b`` is ``(by - ay, -(bx - ax))``.
"""

import numpy as np

from ._jit import helper, inline, kernel

#: Region-code bits, numbered 1 to 4 from the right as in the notes.
LEFT = 1
RIGHT = 2
BELOW = 4
ABOVE = 8

#: Cohen-Sutherland log columns: endpoint (0 or 1, -1 for the final decision),
#: code0, code1, code0 AND code1, action, boundary bit, new x, new y.
CS_ACCEPT = 0
CS_REJECT = 1
CS_CLIP = 2
CS_COLUMNS = 8
#: At most two clips per boundary and endpoint, even with round-off near a corner.
CS_MAX_STEPS = 16

#: Liang-Barsky / Cyrus-Beck log columns: k, p (= -N.D), q (= N.(P0 - PE)) sign as
#: the notes' t formula, t, kind, u1 (t_E), u2 (t_L).
KIND_PARALLEL_INSIDE = 0
KIND_PARALLEL_OUTSIDE = 1
KIND_ENTERING = 2
KIND_LEAVING = 3
PARAM_COLUMNS = 7


@inline
def region_code(x, y, xmin, ymin, xmax, ymax):
    """The notes' 4-bit region code: bit 1 left, 2 right, 3 below, 4 above (the
    sign bits of x - xwmin, xwmax - x, y - ywmin, ywmax - y)."""
    return (LEFT * (x < xmin) | RIGHT * (x > xmax) | BELOW * (y < ymin)
            | ABOVE * (y > ymax))


@inline
def write_segment(out, row, x0, y0, x1, y1):
    out[row, 0] = x0
    out[row, 1] = y0
    out[row, 2] = x1
    out[row, 3] = y1


@inline
def cs_log(log, n, end, c0, c1, both, action, bit, x, y):
    """Row n of a Cohen-Sutherland log (nothing when the log has no row n)."""
    if n < log.shape[0]:
        log[n, 0] = end
        log[n, 1] = c0
        log[n, 2] = c1
        log[n, 3] = both
        log[n, 4] = action
        log[n, 5] = bit
        log[n, 6] = x
        log[n, 7] = y


@inline
def cohen_sutherland(x0, y0, x1, y1, xmin, ymin, xmax, ymax, out, row, log):
    """Clip one segment; write the visible part (or, if none, the segment as
    given) into ``out[row]``; return True if any part is visible.  Logs one row per
    step when ``log`` has rows.

    The outside endpoint is moved to its crossing with the first boundary its code
    names, in the order left, right, below, above, using the notes' formulas
    y = y0 + m (x - x0) for a vertical boundary and x = x0 + (y - y0) / m for a
    horizontal one (m from the original endpoints).
    """
    ax, ay, bx, by = x0, y0, x1, y1
    dx = x1 - x0
    dy = y1 - y0
    c0 = region_code(ax, ay, xmin, ymin, xmax, ymax)
    c1 = region_code(bx, by, xmin, ymin, xmax, ymax)
    n = 0
    for _ in range(CS_MAX_STEPS):
        both = c0 & c1
        if (c0 | c1) == 0 or both != 0:
            action = CS_ACCEPT if (c0 | c1) == 0 else CS_REJECT
            cs_log(log, n, -1, c0, c1, both, action, 0, np.nan, np.nan)
            if action == CS_ACCEPT:
                write_segment(out, row, ax, ay, bx, by)
            else:
                write_segment(out, row, x0, y0, x1, y1)
            return action == CS_ACCEPT
        end = 0 if c0 != 0 else 1
        code = c0 if end == 0 else c1
        if code & LEFT:
            bit = LEFT
            x = xmin
            y = y0 + dy * ((xmin - x0) / dx)
        elif code & RIGHT:
            bit = RIGHT
            x = xmax
            y = y0 + dy * ((xmax - x0) / dx)
        elif code & BELOW:
            bit = BELOW
            y = ymin
            x = x0 + dx * ((ymin - y0) / dy)
        else:
            bit = ABOVE
            y = ymax
            x = x0 + dx * ((ymax - y0) / dy)
        cs_log(log, n, end, c0, c1, both, CS_CLIP, bit, x, y)
        n += 1
        if end == 0:
            ax, ay = x, y
            c0 = region_code(ax, ay, xmin, ymin, xmax, ymax)
        else:
            bx, by = x, y
            c1 = region_code(bx, by, xmin, ymin, xmax, ymax)
    # Round-off near a corner made the endpoints chase each other: the segment
    # only grazes the corner.  Accept what is left if it is inside.
    if (c0 | c1) == 0:
        write_segment(out, row, ax, ay, bx, by)
    else:
        write_segment(out, row, x0, y0, x1, y1)
    return (c0 | c1) == 0


@inline
def parametric_edge(p, q, k, u1, u2, log):
    """One boundary of the parametric clippers (Liang-Barsky's p_k, q_k; Cyrus-Beck
    with p = N.D, q = -N.(P0 - PE), so t = q / p): p < 0 enters, u1 = max(u1, t);
    p > 0 leaves, u2 = min(u2, t); p = 0 is parallel, outside when q < 0.

    Returns ``(outside, u1, u2)``.  Written without branches on the data (random
    segments made the branches mispredict): the batch kernels run 2x faster.
    """
    r = q / (p if p != 0.0 else 1.0)
    nu1 = max(u1, r) if p < 0.0 else u1
    nu2 = min(u2, r) if p > 0.0 else u2
    outside = (p == 0.0) & (q < 0.0)
    if k < log.shape[0]:
        log[k, 0] = k + 1
        log[k, 1] = p
        log[k, 2] = q
        log[k, 3] = r if p != 0.0 else np.nan
        log[k, 4] = (KIND_ENTERING if p < 0.0 else KIND_LEAVING if p > 0.0
                     else KIND_PARALLEL_OUTSIDE if outside else KIND_PARALLEL_INSIDE)
        log[k, 5] = nu1
        log[k, 6] = nu2
    return outside, nu1, nu2


@inline
def parametric_result(x0, y0, x1, y1, outside, u1, u2, out, row):
    """Decide: visible iff no parallel boundary had the segment outside and
    u1 <= u2; write the segment from t = u1 to t = u2 (or, if not visible, the
    segment as given) into ``out[row]``; return the decision."""
    ok = (not outside) & (u1 <= u2)
    if ok:
        dx = x1 - x0
        dy = y1 - y0
        write_segment(out, row,
                      x0 + u1 * dx if u1 > 0.0 else x0, y0 + u1 * dy if u1 > 0.0 else y0,
                      x0 + u2 * dx if u2 < 1.0 else x1, y0 + u2 * dy if u2 < 1.0 else y1)
    else:
        write_segment(out, row, x0, y0, x1, y1)
    return ok


@inline
def liang_barsky(x0, y0, x1, y1, xmin, ymin, xmax, ymax, out, row, log):
    """Liang-Barsky: p1 = -dx, q1 = x0 - xmin; p2 = dx, q2 = xmax - x0;
    p3 = -dy, q3 = y0 - ymin; p4 = dy, q4 = ymax - y0; u1 = max(0, q/p for p < 0),
    u2 = min(1, q/p for p > 0); visible iff no p_k = 0 has q_k < 0 and u1 <= u2.
    All four boundaries are evaluated, then the decision is made."""
    dx = x1 - x0
    dy = y1 - y0
    out1, u1, u2 = parametric_edge(-dx, x0 - xmin, 0, 0.0, 1.0, log)
    out2, u1, u2 = parametric_edge(dx, xmax - x0, 1, u1, u2, log)
    out3, u1, u2 = parametric_edge(-dy, y0 - ymin, 2, u1, u2, log)
    out4, u1, u2 = parametric_edge(dy, ymax - y0, 3, u1, u2, log)
    return parametric_result(x0, y0, x1, y1, out1 | out2 | out3 | out4, u1, u2, out, row)


@inline
def cyrus_beck(x0, y0, x1, y1, win, normals, out, row, log):
    """Cyrus-Beck against the convex polygon ``win`` (M, 2) with the outward normals
    ``normals`` (M, 2) of its edges (edge i runs from PE_i = win[i] to win[i+1]).

    N_i.D < 0 marks a potentially entering (PE) crossing, N_i.D > 0 a potentially
    leaving (PL) one, and t = N_i.(P0 - PE_i) / -N_i.D.  :func:`parametric_edge`
    gets p = N_i.D and q = -N_i.(P0 - PE_i), so that t = q / p and p < 0 is
    entering, as in Liang-Barsky.  As in the notes, every edge's t is computed,
    then t_E = max(0, PE t's) and t_L = min(1, PL t's) decide.
    """
    dx = x1 - x0
    dy = y1 - y0
    u1 = 0.0
    u2 = 1.0
    outside = False
    for i in range(win.shape[0]):
        nx = normals[i, 0]
        ny = normals[i, 1]
        o, u1, u2 = parametric_edge(nx * dx + ny * dy,
                                    -(nx * (x0 - win[i, 0]) + ny * (y0 - win[i, 1])),
                                    i, u1, u2, log)
        outside |= o
    return parametric_result(x0, y0, x1, y1, outside, u1, u2, out, row)


@inline
def bad_row(seg, i, limit):
    """Whether row i holds a NaN or a coordinate beyond +-limit."""
    bad = False
    for j in range(4):
        if not abs(seg[i, j]) <= limit:
            bad = True
    return bad


#: Line clippers, as the batch kernel's ``method``.
COHEN_SUTHERLAND = 0
LIANG_BARSKY = 1
CYRUS_BECK = 2


@inline
def clip_one(method, x0, y0, x1, y1, rect, win, normals, out, row, log):
    """Clip one segment with clipper ``method``; ``rect`` is (xmin, ymin, xmax, ymax)
    for Cohen-Sutherland and Liang-Barsky, ``win`` and ``normals`` the polygon and
    its outward normals for Cyrus-Beck."""
    if method == COHEN_SUTHERLAND:
        return cohen_sutherland(x0, y0, x1, y1, rect[0], rect[1], rect[2], rect[3], out,
                                row, log)
    if method == LIANG_BARSKY:
        return liang_barsky(x0, y0, x1, y1, rect[0], rect[1], rect[2], rect[3], out, row,
                            log)
    return cyrus_beck(x0, y0, x1, y1, win, normals, out, row, log)


@kernel
def clip_lines(method, seg, rect, win, normals, limit, out, accepted):
    """Clip every row (x0, y0, x1, y1) of ``seg`` with clipper ``method`` (see
    :func:`clip_one`) into ``out``; ``accepted[i]`` says whether row i is visible
    (rejected rows hold the segment as given).

    Returns -1, or the first row with a NaN or a coordinate beyond +-``limit``
    (then nothing after it was clipped).
    """
    log = np.empty((0, CS_COLUMNS))
    for i in range(seg.shape[0]):
        if bad_row(seg, i, limit):
            return i
        accepted[i] = clip_one(method, seg[i, 0], seg[i, 1], seg[i, 2], seg[i, 3], rect,
                               win, normals, out, i, log)
    return -1


@kernel
def trace_line(method, seg, rect, win, normals, out, log):
    """One segment through clipper ``method`` with its steps logged into ``log`` and
    the result in ``out[0]`` (see :func:`clip_one`)."""
    return clip_one(method, seg[0], seg[1], seg[2], seg[3], rect, win, normals, out, 0, log)


@helper
def clip_stage(src, n, dst, ax, ay, bx, by):
    """One Sutherland-Hodgman stage: the ``n`` vertices of ``src`` clipped by the
    half-plane left of (or on) the directed line a -> b, into ``dst``.

    Returns the number of vertices written, or -1 if ``dst`` is too small.
    Consecutive duplicate vertices (a vertex on the boundary) are written once.
    """
    ex = bx - ax
    ey = by - ay
    cap = dst.shape[0]
    m = 0
    if n == 0:
        return 0
    sx = src[n - 1, 0]
    sy = src[n - 1, 1]
    sd = ex * (sy - ay) - ey * (sx - ax)
    for i in range(n):
        px = src[i, 0]
        py = src[i, 1]
        pd = ex * (py - ay) - ey * (px - ax)
        if (sd >= 0.0) != (pd >= 0.0):
            # The edge s -> p crosses the boundary: emit the intersection.
            t = sd / (sd - pd)
            if m >= cap:
                return -1
            # on a horizontal or vertical boundary, the crossing lies exactly on it
            dst[m, 0] = sx + t * (px - sx) if ex != 0.0 else ax
            dst[m, 1] = sy + t * (py - sy) if ey != 0.0 else ay
            if m == 0 or dst[m, 0] != dst[m - 1, 0] or dst[m, 1] != dst[m - 1, 1]:
                m += 1
        if pd >= 0.0:
            if m >= cap:
                return -1
            dst[m, 0] = px
            dst[m, 1] = py
            if m == 0 or px != dst[m - 1, 0] or py != dst[m - 1, 1]:
                m += 1
        sx = px
        sy = py
        sd = pd
    if m > 1 and dst[0, 0] == dst[m - 1, 0] and dst[0, 1] == dst[m - 1, 1]:
        m -= 1
    return m


@kernel
def sutherland_hodgman(verts, counts, win, out, out_counts, scratch):
    """Clip each polygon (``counts[i]`` consecutive rows of ``verts``) by the convex
    CCW window ``win``, one window edge after another.

    The results are written one after another into ``out`` with their vertex counts
    in ``out_counts``.  Returns the number of rows of ``out`` used, or -1 if ``out``
    or ``scratch`` (two ping-pong buffers, shape (2, K, 2)) was too small.
    """
    m = win.shape[0]
    start = 0
    used = 0
    cap = scratch.shape[1]
    for p in range(counts.shape[0]):
        n = counts[p]
        if n > cap:
            return -1
        a = scratch[0]
        b = scratch[1]
        for i in range(n):
            a[i, 0] = verts[start + i, 0]
            a[i, 1] = verts[start + i, 1]
        start += n
        for e in range(m):
            f = e + 1 if e + 1 < m else 0
            n = clip_stage(a, n, b, win[e, 0], win[e, 1], win[f, 0], win[f, 1])
            if n < 0:
                return -1
            a, b = b, a
        if n < 3:
            n = 0
        if used + n > out.shape[0]:
            return -1
        for i in range(n):
            out[used + i, 0] = a[i, 0]
            out[used + i, 1] = a[i, 1]
        out_counts[p] = n
        used += n
    return used
