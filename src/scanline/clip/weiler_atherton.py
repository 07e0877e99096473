"""Weiler-Atherton polygon clipping: concave subjects, concave windows, holes.

Both polygons are oriented so that their inside lies to the left of every edge
(outer contours counterclockwise, holes clockwise).  Every crossing of a subject
edge with a window edge is inserted, with the very same coordinates, into both
vertex lists, which splits each boundary into pieces that lie wholly inside,
wholly outside or wholly on the other polygon's boundary.  The traversal of
Weiler & Atherton then follows the subject boundary while it is inside the window;
at a crossing where the subject leaves the window it turns onto the window boundary
and follows it, in the same orientation, while that is inside the subject; at the
next crossing it turns back onto the subject; and so on until it returns to its
start.  Each return closes one output contour, so a concave result comes out as
separate pieces.

Keeping the pieces as directed edges between shared crossing points makes the
degenerate cases of the original algorithm (a vertex on the other boundary, edges
that overlap, a contour that touches without crossing) ordinary: a piece on the
other boundary is kept once if both insides lie on the same side of it and dropped
if they lie on opposite sides; where several kept pieces leave one point (two
pieces that touch at a corner), the traversal takes the sharpest turn into its own
inside, which keeps touching pieces apart.  A subject with no crossings is inside
the window (kept whole), contains it (the window is the result) or misses it.
"""

import math
from typing import Optional

import numpy as np
from numpy.typing import NDArray

#: A point (x, y), a directed piece of an edge, an edge's split points (param, point).
Pt = tuple[float, float]
Piece = tuple[Pt, Pt]
Splits = list[tuple[float, Pt]]

#: Pairs of edges (or points x edges) handled at once by the vectorized tests.
CHUNK = 1 << 18

#: Relative tolerance, in units of the coordinates' extent, for snapping a crossing
#: onto a vertex and for calling a point "on" a boundary.
EPS = 1e-11


def orient(rings: list[NDArray[np.float64]]) -> list[NDArray[np.float64]]:
    """The rings of one polygon, outer contours counterclockwise and holes
    (contours inside an odd number of others) clockwise."""
    out: list[NDArray[np.float64]] = []
    for i, r in enumerate(rings):
        others = [q for j, q in enumerate(rings) if j != i]
        depth = int(inside_even_odd(r[:1], others)[0]) if others else 0
        area = _area(r)
        ccw = area > 0
        out.append(r if ccw != bool(depth) else r[::-1].copy())
    return out


def _area(r: NDArray[np.float64]) -> float:
    x, y = r[:, 0], r[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def _edges(rings: list[NDArray[np.float64]]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    a = np.concatenate([r for r in rings])
    b = np.concatenate([np.roll(r, -1, axis=0) for r in rings])
    return a, b


def inside_even_odd(pts: NDArray[np.float64], rings: list[NDArray[np.float64]]) -> NDArray[np.bool_]:
    """Even-odd inside test of the (P, 2) points against the rings (ray to +x)."""
    if not rings:
        return np.zeros(len(pts), bool)
    a, b = _edges(rings)
    px, py = pts[:, 0:1], pts[:, 1:2]
    ay, by = a[None, :, 1], b[None, :, 1]
    straddle = (ay > py) != (by > py)
    with np.errstate(divide="ignore", invalid="ignore"):
        xc = a[None, :, 0] + (py - ay) * (b[None, :, 0] - a[None, :, 0]) / (by - ay)
    odd: NDArray[np.bool_] = ((straddle & (xc > px)).sum(axis=1) % 2) == 1
    return odd


def _distance_to_boundary(pts: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64]) -> NDArray[np.float64]:
    """Distance from each point to the nearest of the segments a -> b."""
    d = b - a
    ll = np.einsum("ij,ij->i", d, d)
    rel = pts[:, None, :] - a[None, :, :]
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip(np.einsum("pij,ij->pi", rel, d) / ll, 0.0, 1.0)
    t = np.where(ll > 0, t, 0.0)
    near = a[None] + t[..., None] * d[None]
    dist: NDArray[np.float64] = np.sqrt(((pts[:, None, :] - near) ** 2).sum(axis=2)).min(axis=1)
    return dist


def _splits(sa: NDArray[np.float64], sb: NDArray[np.float64], ca: NDArray[np.float64], cb: NDArray[np.float64], tol: float
            ) -> tuple[list[Splits], list[Splits]]:
    """Crossing points of every subject edge with every window edge, as split lists:
    ``(subject_splits, window_splits)``, for each edge a list of (param, point).

    Works on blocks of subject edges so that the pairwise arrays stay small."""
    s_splits: list[Splits] = [[] for _ in range(len(sa))]
    c_splits: list[Splits] = [[] for _ in range(len(ca))]
    step = max(1, CHUNK // max(1, len(ca)))
    for lo in range(0, len(sa), step):
        _block_splits(sa[lo:lo + step], sb[lo:lo + step], ca, cb, tol,
                      s_splits[lo:lo + step], c_splits)
    return s_splits, c_splits


def _block_splits(sa: NDArray[np.float64], sb: NDArray[np.float64], ca: NDArray[np.float64], cb: NDArray[np.float64], tol: float, s_splits: list[Splits],
                  c_splits: list[Splits]) -> None:
    """:func:`_splits` for one block of subject edges (appends to the lists)."""
    r = sb - sa
    s = cb - ca
    rlen = np.hypot(r[:, 0], r[:, 1])
    slen = np.hypot(s[:, 0], s[:, 1])
    qp = ca[None, :, :] - sa[:, None, :]                    # (ns, nc, 2)
    denom = r[:, None, 0] * s[None, :, 1] - r[:, None, 1] * s[None, :, 0]
    qxr = qp[..., 0] * r[:, None, 1] - qp[..., 1] * r[:, None, 0]
    qxs = qp[..., 0] * s[None, :, 1] - qp[..., 1] * s[None, :, 0]
    scale = rlen[:, None] * slen[None, :]
    parallel = np.abs(denom) <= EPS * scale
    with np.errstate(divide="ignore", invalid="ignore"):
        t = qxs / denom
        u = qxr / denom
    teps = tol / np.maximum(rlen, tol)[:, None]
    ueps = tol / np.maximum(slen, tol)[None, :]
    hit = (~parallel & (t >= -teps) & (t <= 1 + teps) & (u >= -ueps) & (u <= 1 + ueps))
    for i, j in zip(*np.nonzero(hit)):
        ti, uj = float(t[i, j]), float(u[i, j])
        if abs(ti) <= teps[i, 0]:
            ti, p = 0.0, sa[i]
        elif abs(ti - 1) <= teps[i, 0]:
            ti, p = 1.0, sb[i]
        elif abs(uj) <= ueps[0, j]:
            p = ca[j]
        elif abs(uj - 1) <= ueps[0, j]:
            p = cb[j]
        else:
            p = sa[i] + ti * r[i]
        uj = min(max(uj, 0.0), 1.0)
        at = (float(p[0]), float(p[1]))
        s_splits[i].append((ti, at))
        c_splits[j].append((uj, at))
    # Collinear overlaps: each segment's endpoints that lie on the other split it.
    line_dist = np.abs(qxr) / np.maximum(rlen[:, None], tol)
    for i, j in zip(*np.nonzero(parallel & (line_dist <= tol))):
        for p in (ca[j], cb[j]):
            tt = float(np.dot(p - sa[i], r[i]) / max(rlen[i] ** 2, tol * tol))
            if 0.0 <= tt <= 1.0:
                s_splits[i].append((tt, (float(p[0]), float(p[1]))))
        for p in (sa[i], sb[i]):
            uu = float(np.dot(p - ca[j], s[j]) / max(slen[j] ** 2, tol * tol))
            if 0.0 <= uu <= 1.0:
                c_splits[j].append((uu, (float(p[0]), float(p[1]))))


def _pieces(a: NDArray[np.float64], b: NDArray[np.float64], splits: list[Splits], owners: Optional[list[int]] = None
            ) -> list[Piece]:
    """The directed pieces of the edges a -> b cut at their split points (and, in
    ``owners`` when it is a list, the index of the edge each piece lies on)."""
    out: list[Piece] = []
    for i in range(len(a)):
        pts = [(0.0, (float(a[i, 0]), float(a[i, 1])))]
        pts += sorted(splits[i])
        pts.append((1.0, (float(b[i, 0]), float(b[i, 1]))))
        chain = [pts[0][1]]
        for _, p in pts[1:]:
            if p != chain[-1]:
                chain.append(p)
        out += list(zip(chain[:-1], chain[1:]))
        if owners is not None:
            owners += [i] * (len(chain) - 1)
    return out


def _classify(pieces: list[Piece], rings: list[NDArray[np.float64]], a: NDArray[np.float64], b: NDArray[np.float64], tol: float
              ) -> NDArray[np.int_]:
    """-1 outside, 0 on the boundary, 1 inside ``rings`` for each piece's midpoint."""
    if not pieces:
        return np.zeros(0, int)
    p = np.array(pieces, np.float64)
    mid = 0.5 * (p[:, 0] + p[:, 1])
    out = np.empty(len(mid), int)
    step = max(1, CHUNK // max(1, len(a)))
    for lo in range(0, len(mid), step):
        m = mid[lo:lo + step]
        on = _distance_to_boundary(m, a, b) <= tol
        out[lo:lo + step] = np.where(on, 0, np.where(inside_even_odd(m, rings), 1, -1))
    return out


#: Rings longer than this drop their straight vertices all at once.
BATCH_DROP = 256

#: Above this many (piece, edge) pairs, pieces are classified along their own edge's
#: line (:func:`_classify_along`) instead of against every edge.
PAIRWISE = 1 << 22


def _classify_along(pieces: list[Piece], owners: list[int], la: NDArray[np.float64], lb: NDArray[np.float64], a: NDArray[np.float64],
                    b: NDArray[np.float64], tol: float) -> NDArray[np.int_]:
    """:func:`_classify` in O((P + E) log E) per line: piece k lies on the line
    through ``la[owners[k]]`` -> ``lb[owners[k]]``, so its midpoint's even-odd count is
    taken along a ray on that line (the parity is the same for any ray): the other
    polygon's edges a -> b that straddle the line (half-open, as the y-ray test)
    cross it at sorted parameters, and a binary search counts those beyond the
    midpoint.  The midpoint is on the boundary (0) when an edge lying along the line
    within ``tol``, or one of the crossings nearest to it, is within ``tol``."""
    p = np.array(pieces, np.float64)
    mid = 0.5 * (p[:, 0] + p[:, 1])
    owner = np.asarray(owners)
    out = np.empty(len(mid), int)
    e = b - a
    for j in np.unique(owner):
        sel = np.flatnonzero(owner == j)
        o, d = la[j], lb[j] - la[j]
        length2 = float(d @ d) or 1.0
        sa = (a[:, 0] - o[0]) * d[1] - (a[:, 1] - o[1]) * d[0]      # signed distances (x |d|)
        sb = (b[:, 0] - o[0]) * d[1] - (b[:, 1] - o[1]) * d[0]
        cross = (sa > 0) != (sb > 0)
        with np.errstate(divide="ignore", invalid="ignore"):
            f = sa[cross] / (sa[cross] - sb[cross])
        cpts = a[cross] + f[:, None] * e[cross]
        t = np.sort(((cpts - o) @ d) / length2)
        tm = ((mid[sel] - o) @ d) / length2
        inside = (len(t) - np.searchsorted(t, tm, side="right")) % 2 == 1
        # on the boundary: near an edge along the line, or near a crossing edge
        scale = math.sqrt(length2)
        along = np.flatnonzero((np.abs(sa) <= tol * scale) | (np.abs(sb) <= tol * scale))
        on = np.zeros(len(sel), bool)
        if len(along):
            on |= _distance_to_boundary(mid[sel], a[along], b[along]) <= tol
        order = np.argsort(((cpts - o) @ d) / length2)
        crossing = np.flatnonzero(cross)[order]
        k = np.searchsorted(t, tm)
        for shift in (-2, -1, 0, 1):
            idx = np.clip(k + shift, 0, max(len(t) - 1, 0))
            if len(t):
                edge = crossing[idx]
                on |= _point_segment_distance(mid[sel], a[edge], b[edge]) <= tol
        out[sel] = np.where(on, 0, np.where(inside, 1, -1))
    return out


def _point_segment_distance(pts: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64]) -> NDArray[np.float64]:
    """Distance from each point i to the segment a[i] -> b[i]."""
    d = b - a
    ll = np.einsum("ij,ij->i", d, d)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip(np.einsum("ij,ij->i", pts - a, d) / ll, 0.0, 1.0)
    t = np.where(ll > 0, t, 0.0)
    dist: NDArray[np.float64] = np.hypot(*(pts - (a + t[:, None] * d)).T)
    return dist


def _snap_vertices(rings: list[NDArray[np.float64]], targets: list[NDArray[np.float64]], tol: float) -> list[NDArray[np.float64]]:
    """Move window vertices lying within ``tol`` of a subject vertex onto it, so that
    shared corners are one point."""
    t = np.concatenate(targets)
    out: list[NDArray[np.float64]] = []
    for r in rings:
        d = np.hypot(r[:, None, 0] - t[None, :, 0], r[:, None, 1] - t[None, :, 1])
        near = d.min(axis=1) <= tol
        r = r.copy()
        r[near] = t[d.argmin(axis=1)[near]]
        out.append(r)
    return out


def _angle_cw(incoming: Pt, outgoing: Pt) -> float:
    """Clockwise angle in (0, 2 pi] from the reversed incoming direction to the
    outgoing one."""
    back = math.atan2(-incoming[1], -incoming[0])
    ang = math.atan2(outgoing[1], outgoing[0])
    cw = (back - ang) % (2 * math.pi)
    return cw if cw > 0 else 2 * math.pi


def _traverse(kept: list[Piece]) -> list[NDArray[np.float64]]:
    """Link the kept directed pieces into closed contours."""
    starts: dict[Pt, list[int]] = {}
    for idx, (p, q) in enumerate(kept):
        starts.setdefault(p, []).append(idx)
    used = [False] * len(kept)
    contours: list[NDArray[np.float64]] = []
    for first in range(len(kept)):
        if used[first]:
            continue
        used[first] = True
        chain = [kept[first][0]]
        cur = first
        for _ in range(len(kept) + 1):
            p, q = kept[cur]
            chain.append(q)
            cand = [i for i in starts.get(q, []) if not used[i] or i == first]
            if not cand:
                break
            d_in = (q[0] - p[0], q[1] - p[1])
            nxt = min(cand, key=lambda i: _angle_cw(
                d_in, (kept[i][1][0] - q[0], kept[i][1][1] - q[1])))
            if nxt == first:
                break
            used[nxt] = True
            cur = nxt
        ring = _drop_collinear(np.array(chain[:-1] if chain[-1] == chain[0] else chain))
        if len(ring) >= 3:
            low = int(np.lexsort((ring[:, 0], ring[:, 1]))[0])   # start lowest, leftmost
            contours.append(np.roll(ring, -low, axis=0))
    return contours


def _drop_collinear(r: NDArray[np.float64]) -> NDArray[np.float64]:
    """Remove vertices that lie on the straight line through their neighbors (the
    split points that turned out not to be corners): one at a time in small rings,
    all of them at once, pass after pass, in rings of more than BATCH_DROP vertices
    (a run of straight vertices lies along one line, so removing it at once leaves
    that line; one at a time was quadratic in the run's length)."""
    changed = True
    while changed and len(r) > 3:
        prev, nxt = np.roll(r, 1, axis=0), np.roll(r, -1, axis=0)
        d1, d2 = r - prev, nxt - r
        cross = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
        scale = np.hypot(*d1.T) * np.hypot(*d2.T)
        dot = np.einsum("ij,ij->i", d1, d2)
        straight = (np.abs(cross) <= 1e-12 * scale) & (dot > 0)
        changed = bool(straight.any())
        if changed:
            keep = ~straight
            if keep.sum() < 3 or len(r) <= BATCH_DROP:
                keep = np.ones(len(r), bool)
                keep[int(np.argmax(straight))] = False
            r = r[keep]
    return r


def clip(subject: list[NDArray[np.float64]], window: list[NDArray[np.float64]]) -> list[NDArray[np.float64]]:
    """Intersection of two polygons given as lists of (N, 2) rings (even-odd
    inside); returns a list of contours (outer CCW, holes CW)."""
    subject = orient(subject)
    allpts = np.concatenate(subject + window)
    extent = float(np.max(allpts.max(axis=0) - allpts.min(axis=0))) or 1.0
    tol = EPS * max(extent, float(np.abs(allpts).max()))
    window = orient(_snap_vertices(window, subject, tol))
    sa, sb = _edges(subject)
    ca, cb = _edges(window)
    s_splits, c_splits = _splits(sa, sb, ca, cb, tol)
    s_owner: list[int] = []
    c_owner: list[int] = []
    s_pieces = _pieces(sa, sb, s_splits, s_owner)
    c_pieces = _pieces(ca, cb, c_splits, c_owner)
    # pairwise where that is small; along each edge's line where it would be quadratic
    s_class = (_classify(s_pieces, window, ca, cb, tol) if len(s_pieces) * len(ca) <= PAIRWISE
               else _classify_along(s_pieces, s_owner, sa, sb, ca, cb, tol))
    c_class = (_classify(c_pieces, subject, sa, sb, tol) if len(c_pieces) * len(sa) <= PAIRWISE
               else _classify_along(c_pieces, c_owner, ca, cb, sa, sb, tol))
    c_on = {piece for piece, c in zip(c_pieces, c_class) if c == 0}
    kept = [piece for piece, c in zip(s_pieces, s_class)
            if c == 1 or (c == 0 and piece in c_on)]
    kept += [piece for piece, c in zip(c_pieces, c_class) if c == 1]
    return _traverse(kept)
