"""Thick lines as filled outlines: segment quadrilaterals, joins and caps (notes,
syllabus: "Line attributes - Line type. Line width"; Hearn & Baker, section 4-1).

A stroke of half-width ``r`` along a polyline is the union of simple pieces, each
winding once counterclockwise:

* one rectangle per segment (its sides offset by ``r`` along the segment's normal);
* one join per interior vertex (every vertex of a closed polyline), on the *outer*
  side of the turn: a *miter* (pivot, the two outer corners and the tip where the
  offset sides meet; a *bevel* when the tip is farther than ``miter_limit * r``
  from the pivot), a *bevel* triangle, or a *round* sector;
* one cap at each end of an open polyline: *butt* (none), *square* (the end
  segments extended by ``r``) or *round* (a half disc).

Adding the boundaries of all the pieces, the edges through the vertices cancel and
what is left is ONE contour (two for a closed polyline): the right side of the
polyline forward, with the outer join at each left turn and a detour through the
vertex at each right turn, the end cap, then the right side of the reversed polyline
and the start cap (:func:`right_side`).  Its winding number at any point is the sum
of the pieces' -- positive exactly on their union, zero outside.  (Where both
segments of a right turn are long enough, the detour is replaced by the inner
corner where the offset sides cross: the overlap of the two rectangles, which the
detour counts twice, then counts once -- still positive.)  So the scan-line
fill (``_kernels/polygon.py``) with the nonzero rule paints the union, each pixel
once (translucent colors blend once, as they must), from about half the edges the
separate pieces would have.

Arcs (round joins and caps) are regular polygons whose vertices lie at radius
``r * sqrt(d / sin d)`` for an angular step ``d``: the polygon then has the area of
the circular sector it replaces, and its vertices stay within ``TOLERANCE`` pixel of
the true circle.

Dashes are made first: :func:`dash_pieces` cuts each polyline into the open
polylines ("pieces") where the dash pattern is on, carrying the pattern's phase
across the vertices, and each piece is stroked with caps and joins of its own.  It
is a kernel of its own (:func:`dashed_polylines`), called before the stroke, so
that solid strokes do not compile it.
"""

import math

import numpy as np

from ._jit import helper, kernel

CAP_BUTT = 0
CAP_ROUND = 1
CAP_SQUARE = 2

JOIN_MITER = 0
JOIN_ROUND = 1
JOIN_BEVEL = 2

#: Largest distance (pixels) between an arc and the polygon that replaces it.
TOLERANCE = 0.1

#: Most polygon steps per half turn of an arc (huge widths).
MAX_ARC_STEPS = 256

#: A zero-length dash is stored as a piece this long, so that its caps know the
#: direction of the path.
EPSILON_DASH = 1e-6


@helper
def arc_step(r):
    """The angular step of arcs of radius ``r``: chords within TOLERANCE."""
    if r <= TOLERANCE:
        return math.pi / 2
    step = 2.0 * math.acos(1.0 - TOLERANCE / r)
    return max(step, math.pi / MAX_ARC_STEPS)


@helper
def arc_capacity(r):
    """Most vertices one arc of radius ``r`` can take."""
    return int(math.ceil(2.0 * math.pi / arc_step(r))) + 3


@helper
def arc(out, nv, px, py, ux, uy, sweep, r, ends):
    """Append the arc of radius ~``r`` about (px, py) from unit direction (ux, uy)
    turning by ``sweep`` radians (counterclockwise if positive): its inner vertices
    (at the area-preserving radius), and both ends too when ``ends``."""
    steps = max(1, int(math.ceil(abs(sweep) / arc_step(r) - 1e-9)))
    d = sweep / steps
    rr = r * math.sqrt(abs(d) / math.sin(abs(d)))
    first = 0 if ends else 1
    last = steps if ends else steps - 1
    for i in range(first, last + 1):
        c = math.cos(i * d)
        s = math.sin(i * d)
        out[nv, 0] = px + rr * (c * ux - s * uy)
        out[nv, 1] = py + rr * (s * ux + c * uy)
        nv += 1
    return nv


@helper
def distinct(src, a, b, closed, pts):
    """Copy the vertices ``src[a:b]`` into ``pts`` without consecutive repeats (and,
    when ``closed``, without a last vertex repeating the first); return the count."""
    m = 0
    for i in range(a, b):
        x = src[i, 0]
        y = src[i, 1]
        if m > 0:
            if pts[m - 1, 0] == x:
                if pts[m - 1, 1] == y:
                    continue
        pts[m, 0] = x
        pts[m, 1] = y
        m += 1
    if closed:
        while m > 1:
            if pts[m - 1, 0] != pts[0, 0] or pts[m - 1, 1] != pts[0, 1]:
                break
            m -= 1
    return m


@helper
def vertex(pts, m, i, reverse):
    """Vertex i of the polyline, or of the polyline reversed."""
    j = m - 1 - i if reverse else i
    return pts[j, 0], pts[j, 1]


@helper
def direction(pts, m, i, reverse):
    """Unit direction of segment i -> i+1 (indices mod m) of the (reversed) polyline."""
    x0, y0 = vertex(pts, m, i, reverse)
    x1, y1 = vertex(pts, m, i + 1 if i + 1 < m else 0, reverse)
    dx = x1 - x0
    dy = y1 - y0
    n = math.hypot(dx, dy)
    return dx / n, dy / n


@helper
def outer_join(out, nv, px, py, ax, ay, bx, by, r, kind, miter_limit, phi):
    """Append the vertices of the join at (px, py) strictly between the right-side
    corners (px + r*ay, py - r*ax) and (px + r*by, py - r*bx) of a left turn ``phi``
    from unit direction a to b: the miter tip, or the inner vertices of the arc (a
    bevel adds none)."""
    if kind == JOIN_ROUND:
        return arc(out, nv, px, py, ay, -ax, phi, r, False)
    half = math.cos(0.5 * phi)
    if kind == JOIN_MITER and half > 0 and 1.0 / half <= miter_limit:
        mx = ay + by
        my = -ax - bx
        k = r / (half * math.hypot(mx, my))
        out[nv, 0] = px + k * mx
        out[nv, 1] = py + k * my
        nv += 1
    return nv


@helper
def right_side(pts, m, closed, reverse, r, cap, join_kind, miter_limit, out, nv):
    """Append the right side of the stroke of the (reversed) polyline: each segment
    offset by ``r`` to its right; at a left turn the outer join; at a right turn the
    point where the two offset sides cross (the inner corner), or, when that point
    lies beyond half of either segment, a detour through the vertex itself.  Open
    polylines end with the cap at their last vertex (the square cap extends the end
    segments)."""
    nseg = m if closed else m - 1
    extend = r if (cap == CAP_SQUARE and not closed) else 0.0
    trimmed = False                     # segment i starts at the inner corner already out
    for i in range(nseg):
        x0, y0 = vertex(pts, m, i, reverse)
        x1, y1 = vertex(pts, m, i + 1 if i + 1 < m else 0, reverse)
        dx, dy = direction(pts, m, i, reverse)
        before = extend if i == 0 else 0.0
        after = extend if i == nseg - 1 else 0.0
        if not trimmed:
            out[nv, 0] = x0 - before * dx + r * dy
            out[nv, 1] = y0 - before * dy - r * dx
            nv += 1
        out[nv, 0] = x1 + after * dx + r * dy
        out[nv, 1] = y1 + after * dy - r * dx
        nv += 1
        trimmed = False
        if i == nseg - 1 and not closed:
            if cap == CAP_ROUND:
                nv = arc(out, nv, x1, y1, dy, -dx, math.pi, r, False)
            break
        bx, by = direction(pts, m, i + 1 if i + 1 < m else 0, reverse)
        cross = dx * by - dy * bx
        dot = dx * bx + dy * by
        phi = math.atan2(cross, dot)
        if phi == -math.pi:
            phi = math.pi       # a reversal (cross -0.0): both sides are outer, joined
        if phi > 0:
            nv = outer_join(out, nv, x1, y1, dx, dy, bx, by, r, join_kind, miter_limit, phi)
        elif phi < 0:
            # the offset sides cross t = r tan(|phi| / 2) before and after the vertex
            t = r * math.tan(-0.5 * phi)
            xn, yn = vertex(pts, m, i + 2 if i + 2 < m else i + 2 - m, reverse)
            if 2.0 * t <= math.hypot(x1 - x0, y1 - y0) and 2.0 * t <= math.hypot(xn - x1, yn - y1):
                out[nv - 1, 0] = x1 - t * dx + r * dy
                out[nv - 1, 1] = y1 - t * dy - r * dx
                trimmed = i + 1 < nseg      # (a closed ring's first corner stays: a spur)
            else:
                out[nv, 0] = x1
                out[nv, 1] = y1
                nv += 1
    return nv


@helper
def stroke_piece(pts, m, closed, r, cap, join_kind, miter_limit, out, nv, contours, nc):
    """Append the outline of the stroke of one polyline ``pts[:m]`` (distinct
    consecutive vertices): one contour (two for a closed polyline, its right and
    its left side) whose winding number is the sum of those of the segment
    rectangles, joins and caps -- positive exactly on their union.  Returns
    ``(nv, nc)``."""
    if m == 0:
        return nv, nc
    if m == 1:  # a point: a disc for round caps, an axis-aligned square for square ones
        if cap == CAP_BUTT:
            return nv, nc
        contours[nc] = nv
        x = pts[0, 0]
        y = pts[0, 1]
        if cap == CAP_ROUND:
            nv = arc(out, nv, x, y, 1.0, 0.0, 2.0 * math.pi, r, False)
        else:
            out[nv, 0] = x - r
            out[nv, 1] = y - r
            out[nv + 1, 0] = x + r
            out[nv + 1, 1] = y - r
            out[nv + 2, 0] = x + r
            out[nv + 2, 1] = y + r
            out[nv + 3, 0] = x - r
            out[nv + 3, 1] = y + r
            nv += 4
        return nv, nc + 1
    contours[nc] = nv
    # (``reverse`` as typed values, not literals: one specialization of the side)
    nv = right_side(pts, m, closed, np.bool_(False), r, cap, join_kind, miter_limit, out, nv)
    nc += 1
    if closed:
        contours[nc] = nv
        nc += 1
    nv = right_side(pts, m, closed, np.bool_(True), r, cap, join_kind, miter_limit, out, nv)
    return nv, nc


@helper
def pattern_period(dashes):
    total = 0.0
    for i in range(dashes.shape[0]):
        total += dashes[i]
    return total


@helper
def visible_part(x0, y0, dx, dy, box):
    """The parameters ``(t0, t1)`` of the part of the segment (x0, y0) + t (dx, dy),
    0 <= t <= 1, inside ``box`` = (xmin, ymin, xmax, ymax) (Liang-Barsky); t0 > t1
    when it misses the box."""
    t0 = 0.0
    t1 = 1.0
    for q in range(4):
        if q == 0:
            pq, qq = -dx, x0 - box[0]
        elif q == 1:
            pq, qq = dx, box[2] - x0
        elif q == 2:
            pq, qq = -dy, y0 - box[1]
        else:
            pq, qq = dy, box[3] - y0
        if pq == 0.0:
            if qq < 0:
                return 1.0, 0.0
        else:
            t = qq / pq
            if pq < 0:
                t0 = max(t0, t)
            else:
                t1 = min(t1, t)
    return t0, t1


@helper
def advance(dashes, period, k, left, distance):
    """The pattern state (entry k, length left in it) ``distance`` further on.  A
    boundary reached exactly stays in the entry that ends there (left = 0), so a
    zero-length dash at the very start is still drawn."""
    if distance <= left:
        return k, left - distance
    nd = dashes.shape[0]
    distance -= left
    k = (k + 1) % nd
    distance = distance % period   # whole periods change nothing
    left = dashes[k]
    while distance > left:
        distance -= left
        k = (k + 1) % nd
        left = dashes[k]
    return k, left - distance


@helper
def dash_pieces(verts, offsets, closed, dashes, phase, box):
    """Cut polylines into dashes.

    ``dashes`` holds on/off lengths (even count, sum >= 1); the pattern starts at arc
    length ``phase`` on every polyline and runs on across its vertices (and around a
    closed polyline, whose last dash joins its first when the pattern is on at the
    start).  Only dashes that can reach ``box`` (xmin, ymin, xmax, ymax) are made: a
    dash is cut where the path leaves the box, and the pattern skips the invisible
    stretches arithmetically, so a path of 2**31 pixels costs only its visible dashes.
    Returns ``(pverts, poffsets, pclosed, powner)``: open polylines (a closed one if
    the pattern never turns off), each with the index of its polyline.
    """
    n = offsets.shape[0] - 1
    period = pattern_period(dashes)
    nd = dashes.shape[0]
    shortest = period
    for i in range(0, nd, 2):
        shortest = min(shortest, dashes[i] + dashes[i + 1])
    # capacity: each dash period in view adds at most 2 * nd vertices
    visible = 0.0
    cap_v = 8
    for p in range(n):
        a = offsets[p]
        b = offsets[p + 1]
        count = b - a
        nseg = count if (closed[p] and count > 1) else count - 1
        for s in range(nseg):
            i = a + s
            j = i + 1 if i + 1 < b else a
            dx = verts[j, 0] - verts[i, 0]
            dy = verts[j, 1] - verts[i, 1]
            t0, t1 = visible_part(verts[i, 0], verts[i, 1], dx, dy, box)
            if t0 <= t1:
                visible += (t1 - t0) * math.hypot(dx, dy)
        cap_v += 3 * count + 8
    cap_v += int(2 * nd * (visible / period + 2.0 * n + 1.0))
    pv = np.empty((cap_v, 2), np.float64)
    po = np.empty(cap_v + 1, np.int64)
    pc = np.zeros(cap_v, np.bool_)
    pw = np.empty(cap_v, np.int64)
    nv = np.int64(0)      # (int64, not a literal 0: the helpers compile once)
    npc = 0
    for p in range(n):
        a = offsets[p]
        b = offsets[p + 1]
        if b - a == 0:
            continue
        k, left = advance(dashes, period, np.int64(0), dashes[0], phase % period)
        first_piece = -1
        starts_on = k % 2 == 0
        is_open = False                     # a piece is being laid down
        count = b - a
        nseg = count if (closed[p] and count > 1) else count - 1
        if count == 1 and starts_on:        # a single point: a dot if it is on
            po[npc] = nv
            pw[npc] = p
            npc += 1
            pv[nv, 0] = verts[a, 0]
            pv[nv, 1] = verts[a, 1]
            nv += 1
        for s in range(nseg):
            i = a + s
            j = i + 1 if i + 1 < b else a
            x0 = verts[i, 0]
            y0 = verts[i, 1]
            dx = verts[j, 0] - x0
            dy = verts[j, 1] - y0
            seg = math.hypot(dx, dy)
            t0, t1 = visible_part(x0, y0, dx, dy, box)
            if t0 > t1 or seg == 0.0:
                is_open = False
                k, left = advance(dashes, period, k, left, seg)
                continue
            pos = t0 * seg
            end = t1 * seg
            if pos > 0.0:                   # an invisible stretch first
                is_open = False
                k, left = advance(dashes, period, k, left, pos)
            if k % 2 == 0 and not is_open:  # on: a piece starts here
                if s == 0 and pos == 0.0:
                    first_piece = npc
                po[npc] = nv
                pw[npc] = p
                npc += 1
                pv[nv, 0] = x0 + pos / seg * dx
                pv[nv, 1] = y0 + pos / seg * dy
                nv += 1
                is_open = True
            while end - pos > left and nv < cap_v - 4:
                pos += left
                f = pos / seg
                x = x0 + f * dx
                y = y0 + f * dy
                if k % 2 == 0:  # the dash ends here
                    if dashes[k] == 0.0:  # a zero-length dash: give it a direction
                        x += EPSILON_DASH * dx / seg
                        y += EPSILON_DASH * dy / seg
                    pv[nv, 0] = x
                    pv[nv, 1] = y
                    nv += 1
                    is_open = False
                else:           # a dash starts here
                    po[npc] = nv
                    pw[npc] = p
                    npc += 1
                    pv[nv, 0] = x
                    pv[nv, 1] = y
                    nv += 1
                    is_open = True
                k = (k + 1) % nd
                left = dashes[k]
            left -= end - pos
            if is_open and nv < cap_v - 2:
                pv[nv, 0] = x0 + t1 * dx if t1 < 1.0 else verts[j, 0]
                pv[nv, 1] = y0 + t1 * dy if t1 < 1.0 else verts[j, 1]
                nv += 1
            if t1 < 1.0:                    # an invisible stretch last
                is_open = False
                k, left = advance(dashes, period, k, left, seg - end)
        if closed[p] and count > 1 and is_open and starts_on and first_piece >= 0:
            if first_piece == npc - 1:      # never off: the whole ring, closed
                pc[first_piece] = True
                nv -= 1                      # the ring's start vertex, repeated
            else:                            # the last dash runs on into the first
                fa = po[first_piece]
                fb = po[first_piece + 1]
                for q in range(fa + 1, min(fb, fa + 1 + cap_v - 1 - nv)):
                    pv[nv, 0] = pv[q, 0]
                    pv[nv, 1] = pv[q, 1]
                    nv += 1
                pw[first_piece] = -1         # emptied: skipped by the stroker
    po[npc] = nv
    return pv, po[:npc + 1], pc[:npc], pw[:npc]


@kernel
def stroke_outlines(verts, offsets, closed, owner, npoly, r, cap, join_kind, miter_limit):
    """The outlines of the strokes of half-width ``r`` of the polylines
    ``verts[offsets[i]:offsets[i + 1]]`` (``closed[i]``; ``owner[i]``: the stroke
    ``q < npoly`` polyline ``i`` belongs to, ascending, -1 to skip), as ``(outline
    vertices, contour offsets, polygon offsets, max_edges)``: stroke ``q`` is filled
    by the nonzero rule over contours ``polys[q] .. polys[q + 1] - 1``.  Dashed polylines are cut into their
    dashes first (:func:`dashed_polylines`, whose owners map the dashes to strokes).

    The API layer fills the outlines with
    :func:`scanline._kernels.polygon.fill_polygons`: composed in Python rather than
    in one kernel, each kernel is compiled once for every entry point that needs it."""
    n = offsets.shape[0] - 1
    arcs = arc_capacity(r)
    longest = 1
    nverts = 0
    for i in range(n):
        longest = max(longest, offsets[i + 1] - offsets[i])
        nverts += offsets[i + 1] - offsets[i]
    # per vertex: two corners on each side, one join (at most a half turn of arc)
    # and one detour point; per polyline: two caps, or one disc
    half = (arcs + 1) // 2 + 1
    cap_v = nverts * (half + 6) + n * (arcs + 8) + 8
    cap_c = 2 * n + 2
    out = np.empty((cap_v, 2), np.float64)
    contours = np.empty(cap_c + 1, np.int64)
    polys = np.zeros(npoly + 1, np.int64)
    pts = np.empty((longest, 2), np.float64)
    nv = np.int64(0)      # (int64s, not literals: the helpers compile once)
    nc = np.int64(0)
    q = 0
    for i in range(n):
        o = owner[i]
        if o < 0:
            continue
        while q < o:
            q += 1
            polys[q] = nc
        m = distinct(verts, offsets[i], offsets[i + 1], closed[i], pts)
        nv, nc = stroke_piece(pts, m, closed[i], r, cap, join_kind, miter_limit, out, nv,
                              contours, nc)
    while q < npoly:
        q += 1
        polys[q] = nc
    contours[nc] = nv
    max_edges = 0
    for p in range(npoly):
        max_edges = max(max_edges, contours[polys[p + 1]] - contours[polys[p]])
    return out[:nv], contours[:nc + 1], polys, max_edges


@kernel
def dashed_polylines(verts, offsets, closed, dashes, phase, box):
    """The dashes of polylines as polylines: ``(vertices, offsets, closed, owner)``
    (see :func:`dash_pieces`; an owner of -1 marks an emptied piece)."""
    return dash_pieces(verts, offsets, closed, dashes, phase, box)
