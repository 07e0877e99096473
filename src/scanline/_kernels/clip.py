"""Line and polygon clipping (notes, chapter 4, Q.3-Q.4).

The line clippers work on blocks of segments: each step of the notes' algorithm is
one loop over the block, written with arithmetic selects instead of branches on
the data, so that the compiler runs it on several segments at once (SIMD) and
random segments cost no mispredicted branches.  Each segment still goes through
exactly the notes' steps in the notes' order.  The step tables
(:mod:`scanline.trace.clip`) run the same helpers on a block of one segment with
``trace`` set and a log that has room for every step (in the batch kernel
``trace`` is a constant False, so the logging compiles away).  The table and the
clipped segments therefore come from the same code.

Segments are flat float64 arrays: segment i is ``seg[4 i : 4 i + 4]`` =
(x0, y0, x1, y1).

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

#: Segments per block: the block's state (at most six numbers per segment) stays in L1.
BLOCK = 256


@inline
def region_code(x, y, xmin, ymin, xmax, ymax):
    """The notes' 4-bit region code: bit 1 left, 2 right, 3 below, 4 above (the
    sign bits of x - xwmin, xwmax - x, y - ywmin, ywmax - y)."""
    return (LEFT * (x < xmin) | RIGHT * (x > xmax) | BELOW * (y < ymin)
            | ABOVE * (y > ymax))


@inline
def out_of_range(x0, y0, x1, y1, limit):
    """Whether a coordinate is NaN or beyond +-limit."""
    return ((not abs(x0) <= limit) | (not abs(y0) <= limit) | (not abs(x1) <= limit)
            | (not abs(y1) <= limit))


@inline
def write_segment(out, i, x0, y0, x1, y1):
    out[i] = x0
    out[i + 1] = y0
    out[i + 2] = x1
    out[i + 3] = y1


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
def cs_crossing(code, x0, y0, dx, dy, xmin, ymin, xmax, ymax):
    """The crossing of the line through (x0, y0) with direction (dx, dy) and the
    first boundary that ``code`` names, in the order left, right, below, above:
    ``(bit, x, y)``.  The notes' formulas y = y0 + m (x - x0) for a vertical
    boundary and x = x0 + (y - y0) / m for a horizontal one; both are computed and
    one is selected (a vertical boundary is only chosen when dx != 0, a horizontal
    one only when dy != 0)."""
    left = (code & LEFT) != 0
    right = (code & RIGHT) != 0
    below = (code & BELOW) != 0
    vertical = left | right
    xb = xmin if left else xmax
    yb = ymin if below else ymax
    yv = y0 + dy * ((xb - x0) / (dx if dx != 0.0 else 1.0))
    xh = x0 + dx * ((yb - y0) / (dy if dy != 0.0 else 1.0))
    bit = LEFT if left else RIGHT if right else BELOW if below else ABOVE
    return bit, (xb if vertical else xh), (yv if vertical else yb)


@inline
def cohen_sutherland(seg, xmin, ymin, xmax, ymax, limit, ends, codes, out, accepted,
                     trace, log):
    """Clip the block of segments ``seg`` (see :func:`clip_block`).  ``ends``
    (4, block) and ``codes`` (2, block) hold the moving endpoints and their region
    codes.  Returns whether a coordinate was NaN or beyond +-``limit``.

    At each step a segment is accepted if both codes are 0000, rejected if
    code0 AND code1 != 0000, and otherwise its outside endpoint (P0 first) is moved
    to its crossing with the first boundary its code names (:func:`cs_crossing`,
    with m from the original endpoints); the bits of the boundaries an endpoint was
    moved onto are kept cleared in its code (the upper bits of ``codes`` record
    them): the part left lies inside those boundaries, and round-off at a corner
    would otherwise move a denormal or huge endpoint back and forth.  The block steps until every segment is
    decided (or, after round-off near a corner made the endpoints chase each other,
    after ``CS_MAX_STEPS`` clips: then a segment that only grazes the corner is
    accepted if what is left is inside).
    """
    m = accepted.shape[0]
    for j in range(m):
        i = 4 * j
        x0 = seg[i]
        y0 = seg[i + 1]
        x1 = seg[i + 2]
        y1 = seg[i + 3]
        ends[0, j] = x0
        ends[1, j] = y0
        ends[2, j] = x1
        ends[3, j] = y1
        codes[0, j] = region_code(x0, y0, xmin, ymin, xmax, ymax)
        codes[1, j] = region_code(x1, y1, xmin, ymin, xmax, ymax)
    for n in range(CS_MAX_STEPS):
        undecided = False
        for j in range(m):
            i = 4 * j
            c0 = codes[0, j] & 15
            c1 = codes[1, j] & 15
            done0 = codes[0, j] >> 4
            done1 = codes[1, j] >> 4
            both = c0 & c1
            clip = ((c0 | c1) != 0) & (both == 0)
            first = c0 != 0
            bit, x, y = cs_crossing(c0 if first else c1, seg[i], seg[i + 1],
                                    seg[i + 2] - seg[i], seg[i + 3] - seg[i + 1],
                                    xmin, ymin, xmax, ymax)
            # the new endpoint lies on every boundary its end was clipped at (and
            # stays inside them as it moves toward the other end): those bits stay
            # cleared, so round-off at a corner cannot send it back and forth
            done = (done0 if first else done1) | bit
            code = (region_code(x, y, xmin, ymin, xmax, ymax) & ~done) | (done << 4)
            move0 = clip & first
            move1 = clip & (not first)
            ends[0, j] = x if move0 else ends[0, j]
            ends[1, j] = y if move0 else ends[1, j]
            ends[2, j] = x if move1 else ends[2, j]
            ends[3, j] = y if move1 else ends[3, j]
            codes[0, j] = code if move0 else codes[0, j]
            codes[1, j] = code if move1 else codes[1, j]
            undecided |= clip
            if trace:
                if clip:
                    cs_log(log, n, 0 if first else 1, c0, c1, both, CS_CLIP, bit, x, y)
                else:
                    cs_log(log, n, -1, c0, c1, both,
                           CS_ACCEPT if (c0 | c1) == 0 else CS_REJECT, 0, np.nan, np.nan)
        if not undecided:
            break
    bad = False
    for j in range(m):
        i = 4 * j
        x0 = seg[i]
        y0 = seg[i + 1]
        x1 = seg[i + 2]
        y1 = seg[i + 3]
        ok = ((codes[0, j] | codes[1, j]) & 15) == 0
        write_segment(out, i, ends[0, j] if ok else x0, ends[1, j] if ok else y0,
                      ends[2, j] if ok else x1, ends[3, j] if ok else y1)
        accepted[j] = ok
        bad |= out_of_range(x0, y0, x1, y1, limit)
    return bad


@inline
def parametric_edge(p, q, k, u1, u2, trace, log):
    """One boundary of the parametric clippers (Liang-Barsky's p_k, q_k; Cyrus-Beck
    with p = N.D, q = -N.(P0 - PE), so t = q / p): p < 0 enters, u1 = max(u1, t);
    p > 0 leaves, u2 = min(u2, t); p = 0 is parallel, outside when q < 0.

    Returns ``(outside, u1, u2)``.  With ``trace``, logs row k when ``log`` has one.
    """
    r = q / (p if p != 0.0 else 1.0)
    nu1 = max(u1, r) if p < 0.0 else u1
    nu2 = min(u2, r) if p > 0.0 else u2
    outside = (p == 0.0) & (q < 0.0)
    if trace:
        param_log(log, k, p, q, r, outside, nu1, nu2)
    return outside, nu1, nu2


@inline
def param_log(log, k, p, q, r, outside, u1, u2):
    """Row k of a Liang-Barsky / Cyrus-Beck log (nothing when the log has no row k)."""
    if k < log.shape[0]:
        log[k, 0] = k + 1
        log[k, 1] = p
        log[k, 2] = q
        log[k, 3] = r if p != 0.0 else np.nan
        log[k, 4] = (KIND_ENTERING if p < 0.0 else KIND_LEAVING if p > 0.0
                     else KIND_PARALLEL_OUTSIDE if outside else KIND_PARALLEL_INSIDE)
        log[k, 5] = u1
        log[k, 6] = u2


@inline
def parametric_result(seg, i, outside, u1, u2, limit, out):
    """Decide segment ``seg[i : i + 4]``: visible iff no parallel boundary had it
    outside and u1 <= u2; write the segment from t = u1 to t = u2 (or, if not
    visible, the segment as given) into ``out[i : i + 4]``.  Returns
    ``(visible, bad)``, bad if a coordinate was NaN or beyond +-``limit``."""
    x0 = seg[i]
    y0 = seg[i + 1]
    x1 = seg[i + 2]
    y1 = seg[i + 3]
    dx = x1 - x0
    dy = y1 - y0
    ok = (not outside) & (u1 <= u2)
    write_segment(out, i,
                  x0 + u1 * dx if ok & (u1 > 0.0) else x0,
                  y0 + u1 * dy if ok & (u1 > 0.0) else y0,
                  x0 + u2 * dx if ok & (u2 < 1.0) else x1,
                  y0 + u2 * dy if ok & (u2 < 1.0) else y1)
    return ok, out_of_range(x0, y0, x1, y1, limit)


@inline
def liang_barsky(seg, xmin, ymin, xmax, ymax, limit, out, accepted, trace, log):
    """Liang-Barsky on the block of segments ``seg``: p1 = -dx,
    q1 = x0 - xmin; p2 = dx, q2 = xmax - x0; p3 = -dy, q3 = y0 - ymin; p4 = dy,
    q4 = ymax - y0; u1 = max(0, q/p for p < 0), u2 = min(1, q/p for p > 0); visible
    iff no p_k = 0 has q_k < 0 and u1 <= u2.  All four boundaries are evaluated,
    then the decision is made (:func:`parametric_result`).  Returns whether a
    coordinate was NaN or beyond +-``limit``."""
    bad = False
    for j in range(accepted.shape[0]):
        i = 4 * j
        x0 = seg[i]
        y0 = seg[i + 1]
        dx = seg[i + 2] - x0
        dy = seg[i + 3] - y0
        out1, u1, u2 = parametric_edge(-dx, x0 - xmin, 0, 0.0, 1.0, trace, log)
        out2, u1, u2 = parametric_edge(dx, xmax - x0, 1, u1, u2, trace, log)
        out3, u1, u2 = parametric_edge(-dy, y0 - ymin, 2, u1, u2, trace, log)
        out4, u1, u2 = parametric_edge(dy, ymax - y0, 3, u1, u2, trace, log)
        ok, b = parametric_result(seg, i, out1 | out2 | out3 | out4, u1, u2, limit, out)
        accepted[j] = ok
        bad |= b
    return bad


@inline
def cyrus_beck(seg, win, normals, limit, params, outside, out, accepted, trace, log):
    """Cyrus-Beck on the block of segments ``seg`` against the convex
    polygon ``win`` (M, 2) with the outward normals ``normals`` (M, 2) of its edges
    (edge e runs from PE_e = win[e] to win[e + 1]); ``params`` (2, block) holds each
    segment's t_E and t_L, ``outside`` (block,) whether a parallel edge had it
    outside.  Returns whether a coordinate was NaN or beyond +-``limit``.

    N_e.D < 0 marks a potentially entering (PE) crossing, N_e.D > 0 a potentially
    leaving (PL) one, and t = N_e.(P0 - PE_e) / -N_e.D.  :func:`parametric_edge`
    gets p = N_e.D and q = -N_e.(P0 - PE_e), so that t = q / p and p < 0 is
    entering, as in Liang-Barsky.  As in the notes, every edge's t is computed
    (one edge at a time for the whole block), then t_E = max(0, PE t's) and
    t_L = min(1, PL t's) decide.
    """
    m = accepted.shape[0]
    for j in range(m):
        params[0, j] = 0.0
        params[1, j] = 1.0
        outside[j] = False
    for e in range(win.shape[0]):
        nx = normals[e, 0]
        ny = normals[e, 1]
        ex = win[e, 0]
        ey = win[e, 1]
        for j in range(m):
            i = 4 * j
            x0 = seg[i]
            y0 = seg[i + 1]
            o, u1, u2 = parametric_edge(nx * (seg[i + 2] - x0) + ny * (seg[i + 3] - y0),
                                        -(nx * (x0 - ex) + ny * (y0 - ey)), e, params[0, j],
                                        params[1, j], trace, log)
            params[0, j] = u1
            params[1, j] = u2
            outside[j] |= o
    bad = False
    for j in range(m):
        ok, b = parametric_result(seg, 4 * j, outside[j], params[0, j],
                                  params[1, j], limit, out)
        accepted[j] = ok
        bad |= b
    return bad


#: Line clippers: the batch kernel's ``method`` is a token of one of these lengths
#: (:mod:`scanline._kernels.variants`), so a clipper compiles its own code only.
COHEN_SUTHERLAND = 1
LIANG_BARSKY = 2
CYRUS_BECK = 3


@helper
def clip_block(method, seg, rect, win, normals, limit, state, codes, flags, out,
               accepted, trace, log):
    """Clip a block of segments ``seg`` (4 m,) with clipper ``method``: write the
    visible part of segment j (or, if none, the segment as given) into
    ``out[4 j : 4 j + 4]`` and whether any part is visible into ``accepted[j]``
    (``accepted`` has m entries, m <= the block size).  The block is indexed from
    0, so the compiler sees the loops' array accesses as consecutive.

    ``rect`` is (xmin, ymin, xmax, ymax) for Cohen-Sutherland and Liang-Barsky,
    ``win`` and ``normals`` the polygon and its outward normals for Cyrus-Beck;
    ``state`` (4, block), ``codes`` (2, block) and ``flags`` (block,) are scratch.
    With ``trace`` (a block of one segment) the steps are logged into ``log``.
    Returns whether a coordinate was NaN or beyond +-``limit`` (checked in the
    same pass).  A compiled helper (called once per block), so that the test of the
    method token folds here."""
    if len(method) == COHEN_SUTHERLAND:
        return cohen_sutherland(seg, rect[0], rect[1], rect[2], rect[3], limit,
                                state, codes, out, accepted, trace, log)
    if len(method) == LIANG_BARSKY:
        return liang_barsky(seg, rect[0], rect[1], rect[2], rect[3], limit, out,
                            accepted, trace, log)
    return cyrus_beck(seg, win, normals, limit, state, flags, out, accepted, trace,
                      log)


@kernel
def clip_lines(method, seg, rect, win, normals, limit, out, accepted):
    """Clip every segment of the flat array ``seg`` (4 N,) with clipper ``method``
    (see :func:`clip_block`) into ``out`` (4 N,); ``accepted[i]`` says whether
    segment i is visible (rejected segments are written as given).

    Returns -1, or the first segment with a NaN or a coordinate beyond +-``limit``
    (then ``out`` and ``accepted`` are not meaningful; nothing is written outside
    them whatever the values).
    """
    log = np.empty((0, CS_COLUMNS))
    state = np.empty((4, BLOCK))
    codes = np.empty((2, BLOCK), np.int64)
    flags = np.empty(BLOCK, np.bool_)
    n = accepted.shape[0]
    bad = False
    for start in range(0, n, BLOCK):
        stop = min(start + BLOCK, n)
        bad |= clip_block(method, seg[4 * start:4 * stop], rect, win, normals, limit, state,
                          codes, flags, out[4 * start:4 * stop], accepted[start:stop], False,
                          log)
    if bad:
        for i in range(n):
            if out_of_range(seg[4 * i], seg[4 * i + 1], seg[4 * i + 2], seg[4 * i + 3],
                            limit):
                return i
    return -1


@kernel
def trace_line(method, seg, rect, win, normals, out, log):
    """One segment ``seg`` (4,) through clipper ``method`` with its steps logged
    into ``log`` and the result in ``out[0]`` (see :func:`clip_block`)."""
    accepted = np.empty(1, np.bool_)
    clip_block(method, seg, rect, win, normals, np.inf, np.empty((4, 1)),
               np.empty((2, 1), np.int64), np.empty(1, np.bool_), out[0], accepted, True,
               log)
    return accepted[0]


#: Sutherland-Hodgman log columns, one row per edge S -> P of the stage's input:
#: index of P, S inside, P inside, intersection output (1 or 0), its x, y, P output.
SH_COLUMNS = 7


@helper
def clip_stage(src, n, dst, ax, ay, bx, by, log):
    """One Sutherland-Hodgman stage: the ``n`` vertices of ``src`` clipped by the
    half-plane left of (or on) the directed line a -> b, into ``dst``.

    Returns the number of vertices written, or -1 if ``dst`` is too small.
    Consecutive duplicate vertices (a vertex on the boundary) are written once.
    Row i of ``log`` (when it has one; the batch kernel passes an empty log) records
    the edge from S = vertex i - 1 to P = vertex i: the four cases of Hearn & Baker's
    section 6-8 (out -> in: the intersection and P; in -> in: P; in -> out: the
    intersection; out -> out: nothing), as what was output.
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
        before = m
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
        crossing = m
        if pd >= 0.0:
            if m >= cap:
                return -1
            dst[m, 0] = px
            dst[m, 1] = py
            if m == 0 or px != dst[m - 1, 0] or py != dst[m - 1, 1]:
                m += 1
        if i < log.shape[0]:
            log[i, 0] = i
            log[i, 1] = sd >= 0.0
            log[i, 2] = pd >= 0.0
            log[i, 3] = crossing - before
            log[i, 4] = dst[before, 0] if crossing > before else np.nan
            log[i, 5] = dst[before, 1] if crossing > before else np.nan
            log[i, 6] = m - crossing
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
    log = np.empty((0, SH_COLUMNS))
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
            n = clip_stage(a, n, b, win[e, 0], win[e, 1], win[f, 0], win[f, 1], log)
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
