"""Device-space geometry for :mod:`scanline.mpl`: matplotlib's polygons made into the
convex planar polygons the visible-surface methods take, points tested against
them, line parts joined into polylines, and the parts of split pieces' outlines
that lie on their polygon's own edges.

All of it is vectorized over the polygons (grouped by vertex count); only a planar
polygon that is not convex (rare: a user's L-shaped face) is cut into triangles by a
Python loop over its vertices.
"""

from typing import Any, List, Optional, Tuple, Union

import numpy as np
from numpy.typing import NDArray

from ..screen import ScreenPolygons, newell_planes

#: The arrays of :mod:`scanline.mpl`: coordinates, depths and colors; counts, offsets
#: and indices; masks.
Floats = NDArray[np.float64]
Ints = NDArray[np.int64]
Bools = NDArray[np.bool_]

#: Polygons and triangles whose projected area (square device units) is at most this
#: are dropped, as :class:`~scanline.visible.ScreenPolygons` drops them.
MIN_AREA = 1e-9
#: A polygon whose vertices leave its plane by at most this fraction of its size is
#: planar.
PLANAR = 1e-9


def _over(op: np.ufunc, a: NDArray[Any]) -> NDArray[Any]:
    """``a`` (N, K, ...) reduced over its short axis 1 by the ufunc ``op``, one column
    at a time (numpy's reductions over a short axis are several times slower)."""
    out: NDArray[Any] = a[:, 0].copy()
    for j in range(1, a.shape[1]):
        op(out, a[:, j], out=out)
    return out


def _newell(p: Floats) -> Tuple[Floats, Floats]:
    """Newell normals (N, 3) and centroids (N, 3) of polygons ``p`` (N, K, 3)."""
    n = np.zeros((len(p), 3))
    k = p.shape[1]
    for j in range(k):
        a, b = p[:, j], p[:, (j + 1) % k]
        n[:, 0] += (a[:, 1] - b[:, 1]) * (a[:, 2] + b[:, 2])
        n[:, 1] += (a[:, 2] - b[:, 2]) * (a[:, 0] + b[:, 0])
        n[:, 2] += (a[:, 0] - b[:, 0]) * (a[:, 1] + b[:, 1])
    return n, _over(np.add, p) / k


def _areas(xy: Floats) -> Floats:
    """Signed areas of polygons ``xy`` (N, K, 2) (> 0 counterclockwise)."""
    k = xy.shape[1]
    s = np.zeros(len(xy))
    for j in range(k):
        a, b = xy[:, j], xy[:, (j + 1) % k]
        s += a[:, 0] * b[:, 1] - b[:, 0] * a[:, 1]
    return 0.5 * s


def _convex(xy: Floats) -> Bools:
    """Whether each polygon ``xy`` (N, K, 2) is convex and simple as projected: every
    turn one way (collinear and repeated vertices allowed) and one turn in all (a
    pentagram turns twice)."""
    e = np.roll(xy, -1, axis=1) - xy
    f = np.roll(e, -1, axis=1)
    cross = e[..., 0] * f[..., 1] - e[..., 1] * f[..., 0]
    tol = 1e-12 * (_over(np.maximum, np.abs(e).reshape(len(e), -1)) ** 2)[:, None]
    one_way: Bools = (_over(np.logical_and, cross >= -tol) | _over(np.logical_and, cross <= tol))
    if xy.shape[1] <= 4:          # four turns one way: at most one turn in all
        return one_way
    dot = (e * f).sum(axis=2)
    turning: Floats = np.abs(np.arctan2(cross, dot).sum(axis=1))
    return one_way & (np.abs(turning - 2 * np.pi) < 1e-6)


def _ear_clip(xy: Floats) -> Ints:
    """Triangles (T, 3) of vertex indices cutting the simple polygon ``xy`` (K, 2) by
    ear clipping (Meisters 1975); what is left when no ear is found (a
    self-intersecting outline) is fanned."""
    idx = list(range(len(xy)))
    sign = 1.0 if _areas(xy[None])[0] >= 0 else -1.0
    out: List[Tuple[int, int, int]] = []

    def cross(a: int, b: int, c: int) -> float:
        return sign * float((xy[b, 0] - xy[a, 0]) * (xy[c, 1] - xy[a, 1])
                             - (xy[b, 1] - xy[a, 1]) * (xy[c, 0] - xy[a, 0]))

    while len(idx) > 3:
        for i in range(len(idx)):
            a, b, c = idx[i - 1], idx[i], idx[(i + 1) % len(idx)]
            if cross(a, b, c) <= 0:
                continue                       # a reflex (or flat) corner
            if any(cross(a, b, p) >= 0 and cross(b, c, p) >= 0 and cross(c, a, p) >= 0
                   for p in idx if p not in (a, b, c)):
                continue                       # another vertex inside: not an ear
            out.append((a, b, c))
            del idx[i]
            break
        else:
            break
    out += [(idx[0], idx[j], idx[j + 1]) for j in range(1, len(idx) - 1)]
    return np.array(out, np.int64).reshape(-1, 3)


def simplify(dev: Floats, proj: Floats, count: Ints, eps: float) -> Tuple[Floats, Floats, Ints]:
    """Drop the vertices of polygons (N, K, 3) that lie within ``eps`` (device units)
    of the chord joining their neighbours (and are not next to another such vertex):
    the middle points that ``plot_surface`` puts on the sides of each polygon when it
    strides over the data (``rstride``, ``cstride`` > 1, its default for more than
    50 rows) make every polygon slightly non-convex, and would cut it into six
    triangles.  Two polygons sharing a side drop its middle points alike, so the
    surface stays without gaps; its outline moves by at most ``eps``.

    Returns the polygons and counts, compacted (the last vertex repeated)."""
    n, k, _ = dev.shape
    if k <= 4 or not n:          # middle points come with five points or more
        return dev, proj, count
    j = np.arange(k)[None, :]
    valid = j < count[:, None]
    prev = np.where(j == 0, count[:, None] - 1, j - 1)
    nxt = np.where(j + 1 < count[:, None], j + 1, 0)
    rows = np.arange(n)[:, None]
    a, b, m = dev[rows, prev, :2], dev[rows, nxt, :2], dev[..., :2]
    chord = b - a
    length = np.hypot(chord[..., 0], chord[..., 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        dist = np.abs(chord[..., 0] * (m[..., 1] - a[..., 1])
                      - chord[..., 1] * (m[..., 0] - a[..., 0])) / length
        along = ((m - a) * chord).sum(axis=2) / length ** 2
    near = valid & (((length > 0) & (dist <= eps) & (along > 0) & (along < 1))
                    | (np.hypot(*(m - a).transpose(2, 0, 1)) == 0))
    near &= (count >= 4)[:, None]
    # the flattest corner of three goes (a corner of the grid stays, the middle
    # points on either side of it go), never two neighbours at once
    dist = np.where(valid, np.nan_to_num(dist, nan=0.0), np.inf)
    before = np.take_along_axis(dist, prev, axis=1)
    after = np.take_along_axis(dist, nxt, axis=1)
    drop = near & (dist < before) & (dist <= after)
    left = count - drop.sum(axis=1)
    drop &= (left >= 3)[:, None]
    if not drop.any():
        return dev, proj, count
    order = np.argsort(drop | ~valid, axis=1, kind="stable")
    dev = np.take_along_axis(dev, order[:, :, None], axis=1)
    proj = np.take_along_axis(proj, order[:, :, None], axis=1)
    count = count - drop.sum(axis=1)
    last = np.maximum(count - 1, 0)
    pad = j >= count[:, None]
    dev = np.where(pad[:, :, None], dev[np.arange(n), last][:, None, :], dev)
    proj = np.where(pad[:, :, None], proj[np.arange(n), last][:, None, :], proj)
    kk = int(count.max())
    return dev[:, :kk], proj[:, :kk], count


def _fan_start(xy: Floats) -> Ints:
    """For each polygon ``xy`` (N, K, 2), a vertex from which its fan of triangles
    covers it exactly (every triangle turning as the polygon turns: the vertex sees
    the whole polygon), or -1 where there is none."""
    n, k, _ = xy.shape
    sign = np.where(_areas(xy) >= 0, 1.0, -1.0)
    scale = np.abs(xy - xy[:, :1]).max(axis=(1, 2)) ** 2 + 1e-300
    start = np.full(n, -1, np.int64)
    j = np.arange(1, k - 1)
    for v in range(k):
        a = xy[:, v]
        b = xy[:, (v + j) % k]
        c = xy[:, (v + j + 1) % k]
        cross = ((b[..., 0] - a[:, None, 0]) * (c[..., 1] - a[:, None, 1])
                 - (b[..., 1] - a[:, None, 1]) * (c[..., 0] - a[:, None, 0]))
        good = ((cross * sign[:, None]) >= -1e-12 * scale[:, None]).all(axis=1)
        start[(start < 0) & good] = v
        if (start >= 0).all():
            break
    return start


def units(dev: Floats, proj: Floats, count: Ints,
          flatness: float) -> Tuple[Floats, Ints, Ints, Floats]:
    """The convex planar polygons standing for matplotlib's polygons.

    Parameters
    ----------
    dev : ndarray (N, K, 3)
        Device x, y and depth of each polygon's vertices, padded (see ``count``).
    proj : ndarray (N, K, 3)
        The same vertices in matplotlib's projected coordinates, where x, y and depth
        have one unit: the bend of a polygon is measured there.
    count : ndarray (N,)
        The vertices of each polygon.
    flatness : float
        A convex polygon bent out of its plane by at most this fraction of its size
        is kept whole, on its plane (its depths moved onto the plane, its outline as
        matplotlib draws it); one bent more, or not convex, is cut into triangles: a
        fan from a vertex that sees the whole polygon (so the triangles cover what
        matplotlib fills), else, for a planar polygon, by ear clipping, else a fan
        from its first vertex.

    Returns
    -------
    vertices (V, 3), counts (U,), owner (U,), bent (U,)
        The polygons flat, the source polygon of each, in source order, and how far
        (in depth) the vertices of each one's source polygon leave its plane: the
        uncertainty of the surface there (0 for planar polygons).
    """
    out_v: List[Floats] = []
    out_n: List[Ints] = []
    out_o: List[Ints] = []
    out_b: List[Floats] = []
    for k in np.unique(count):
        if k < 3:
            continue
        sel = np.flatnonzero(count == k)
        D = dev[sel, :k]
        P = proj[sel, :k]
        with np.errstate(invalid="ignore", over="ignore"):
            ok = np.isfinite(_over(np.add, D.reshape(len(D), -1))
                             + _over(np.add, P.reshape(len(P), -1)))
        sel, D, P = sel[ok], D[ok], P[ok]
        if not len(sel):
            continue
        if k == 3:
            keep = np.abs(_areas(D[..., :2])) > MIN_AREA
            out_v.append(D[keep].reshape(-1, 3))
            out_n.append(np.full(int(keep.sum()), 3, np.int64))
            out_o.append(sel[keep])
            out_b.append(np.zeros(int(keep.sum())))
            continue
        n, c = _newell(P)
        norm = np.sqrt(n[:, 0] ** 2 + n[:, 1] ** 2 + n[:, 2] ** 2)
        ext = _over(np.maximum, P) - _over(np.minimum, P)
        size = np.maximum(np.maximum(ext[:, 0], ext[:, 1]), ext[:, 2])
        with np.errstate(invalid="ignore", divide="ignore"):
            bend = _over(np.maximum, np.abs(np.einsum("nkj,nj->nk", P - c[:, None], n))) / (
                norm * np.where(size > 0, size, 1.0))
        real = norm > 0                       # polygons of no area at all are dropped
        planar = real & (bend <= PLANAR)
        # the device plane's depth under each vertex
        dn, dc = _newell(D)
        with np.errstate(invalid="ignore", divide="ignore"):
            onto = dc[:, None, 2] - (dn[:, None, 0] * (D[..., 0] - dc[:, None, 0])
                                     + dn[:, None, 1] * (D[..., 1] - dc[:, None, 1])
                                     ) / dn[:, None, 2]
            dz = np.where(planar, 0.0, _over(np.maximum, np.abs(onto - D[..., 2])))
        dz = np.where(np.isfinite(dz), dz, 0.0)
        convex = _convex(D[..., :2])
        area = np.abs(_areas(D[..., :2]))
        whole = (real & convex & (bend <= max(flatness, PLANAR)) & (area > MIN_AREA)
                 & (planar | np.isfinite(_over(np.add, onto))))
        if whole.any():
            W = D[whole].copy()
            flat = ~planar[whole]
            W[flat, :, 2] = onto[whole][flat]            # depths onto the device plane
            out_v.append(W.reshape(-1, 3))
            out_n.append(np.full(len(W), k, np.int64))
            out_o.append(sel[whole])
            out_b.append(dz[whole])
        cut = np.flatnonzero(real & ~whole)
        if not len(cut):
            continue
        start = _fan_start(D[cut, :, :2])
        ears = cut[(start < 0) & planar[cut]]
        fans = cut[(start >= 0) | ~planar[cut]]
        first = np.maximum(start[(start >= 0) | ~planar[cut]], 0)
        tri_parts: List[Floats] = []
        owner_parts: List[Ints] = []
        bent_parts: List[Floats] = []
        if len(fans):
            j = np.arange(1, k - 1)
            idx = np.stack([np.broadcast_to(first[:, None], (len(fans), k - 2)),
                            (first[:, None] + j) % k, (first[:, None] + j + 1) % k], axis=2)
            tri_parts.append(np.take_along_axis(D[fans][:, None, :, :], idx[..., None], axis=2)
                        .reshape(-1, 3, 3))
            owner_parts.append(np.repeat(sel[fans], k - 2))
            bent_parts.append(np.repeat(dz[fans], k - 2))
        for i in ears:
            t = _ear_clip(D[i, :, :2])
            tri_parts.append(D[i][t])
            owner_parts.append(np.full(len(t), sel[i]))
            bent_parts.append(np.full(len(t), dz[i]))
        tris = np.concatenate(tri_parts)
        owner = np.concatenate(owner_parts)
        bent = np.concatenate(bent_parts)
        keep = np.abs(_areas(tris[..., :2])) > MIN_AREA
        out_v.append(tris[keep].reshape(-1, 3))
        out_n.append(np.full(int(keep.sum()), 3, np.int64))
        out_o.append(owner[keep])
        out_b.append(bent[keep])
    if not out_n:
        return np.empty((0, 3)), np.empty(0, np.int64), np.empty(0, np.int64), np.empty(0)
    verts, counts, owner, bent = (np.concatenate(out_v), np.concatenate(out_n),
                                  np.concatenate(out_o), np.concatenate(out_b))
    order = np.argsort(owner, kind="stable")
    if (order != np.arange(len(order))).any():
        offsets = np.concatenate([[0], np.cumsum(counts)])
        ordered = counts[order]
        idx = np.repeat(offsets[:-1][order] - np.concatenate([[0], np.cumsum(ordered)[:-1]]),
                        ordered) + np.arange(int(ordered.sum()))
        verts, counts, owner, bent = verts[idx], ordered, owner[order], bent[order]
    return verts, counts, owner, bent


def screen_polygons(verts: Floats, counts: Ints, owner: Ints, width: int,
                    height: int) -> ScreenPolygons:
    """:class:`~scanline.visible.ScreenPolygons` of the flat convex planar polygons,
    each labeled with its source polygon (``face``), planes by Newell's method
    oriented with C > 0."""
    offsets = np.zeros(len(counts) + 1, np.int64)
    np.cumsum(counts, out=offsets[1:])
    verts = np.ascontiguousarray(verts, np.float64)
    planes = newell_planes(verts, offsets) if len(counts) else np.empty((0, 4))
    planes[planes[:, 2] < 0] *= -1.0
    return ScreenPolygons(verts, offsets, np.ascontiguousarray(owner, np.int64),
                          np.ascontiguousarray(planes), int(width), int(height))


def padded(sp: ScreenPolygons, rows: Optional[Ints] = None) -> Tuple[Floats, Ints]:
    """The polygons ``rows`` (default all) of ``sp`` as (R, K, 3), the last vertex
    repeated, with their counts."""
    rows = np.arange(len(sp)) if rows is None else rows
    counts = np.diff(sp.offsets)[rows]
    k = int(counts.max()) if len(counts) else 3
    idx = sp.offsets[rows][:, None] + np.minimum(np.arange(k)[None, :], counts[:, None] - 1)
    return sp.vertices[idx], counts


def hidden_points(x: Floats, y: Floats, z: Floats, sp: ScreenPolygons,
                  eps: Union[float, Floats]) -> Bools:
    """Whether each point (x, y, depth) lies behind a polygon of ``sp`` whose
    projection holds it (its plane's depth there less than ``z - eps``): the
    polygons binned in a grid of cells, each point tested against the polygons of
    its cell (object precision).  ``eps``: a number, or one per polygon."""
    n = len(x)
    hidden = np.zeros(n, bool)
    if not n or not len(sp):
        return hidden
    poly, _ = padded(sp)
    lo = poly[..., :2].min(axis=1)
    hi = poly[..., :2].max(axis=1)
    inside = ((x >= lo[:, 0].min()) & (x <= hi[:, 0].max()) & (y >= lo[:, 1].min())
              & (y <= hi[:, 1].max()) & np.isfinite(z))
    pts = np.flatnonzero(inside)
    if not len(pts):
        return hidden
    origin = lo.min(axis=0)
    span = np.maximum(hi.max(axis=0) - origin, 1e-9)
    typical = float(np.median((hi - lo).max(axis=1)))
    cell = max(typical, float(span.max()) / 1024, 1e-9)
    while True:
        gx, gy = (np.floor(span / cell).astype(np.int64) + 1)
        i0 = np.floor((lo - origin) / cell).astype(np.int64)
        i1 = np.floor((hi - origin) / cell).astype(np.int64)
        w = i1[:, 0] - i0[:, 0] + 1
        cells = w * (i1[:, 1] - i0[:, 1] + 1)
        if int(cells.sum()) <= 8 * len(poly) + 4_000_000:
            break
        cell *= 2.0
    rep = np.repeat(np.arange(len(poly)), cells)
    local = np.arange(int(cells.sum())) - np.repeat(np.cumsum(cells) - cells, cells)
    key = (i0[rep, 1] + local // w[rep]) * gx + i0[rep, 0] + local % w[rep]
    order = np.argsort(key, kind="stable")
    key, rep = key[order], rep[order]
    px, py, pz = x[pts], y[pts], z[pts]
    pc = (np.minimum(((py - origin[1]) / cell).astype(np.int64), gy - 1) * gx
          + np.minimum(((px - origin[0]) / cell).astype(np.int64), gx - 1))
    first = np.searchsorted(key, pc, side="left")
    last = np.searchsorted(key, pc, side="right")
    many = last - first
    planes = sp.planes
    eps = np.broadcast_to(np.asarray(eps, np.float64), (len(poly),))
    area = _areas(poly[..., :2])
    orient = np.where(area >= 0, 1.0, -1.0)
    chunk = 2_000_000
    starts = np.concatenate([[0], np.cumsum(many)])
    # pairs in chunks of points, so that no more than about `chunk` are live
    bounds = np.searchsorted(starts, np.arange(0, starts[-1] + chunk, chunk))
    bounds = np.unique(np.clip(bounds, 0, len(pts)))
    for a, b in zip(bounds[:-1], bounds[1:]):
        m = many[a:b]
        if not m.sum():
            continue
        which = np.repeat(np.arange(a, b), m)
        slot = np.repeat(first[a:b] - (np.cumsum(m) - m), m) + np.arange(int(m.sum()))
        p = rep[slot]
        qx, qy, qz = px[which], py[which], pz[which]
        A, B, C, D = planes[p].T
        with np.errstate(invalid="ignore", divide="ignore"):
            depth = -(A * qx + B * qy + D) / C
        front = depth < qz - eps[p]
        v = poly[p, :, :2]
        e = np.roll(v, -1, axis=1) - v
        cr = e[..., 0] * (qy[:, None] - v[..., 1]) - e[..., 1] * (qx[:, None] - v[..., 0])
        tol = 1e-9 * (np.abs(e).max(axis=(1, 2)) + 1.0) ** 2
        within = ((cr * orient[p][:, None]) >= -tol[:, None]).all(axis=1)
        hit = front & within
        hidden[pts[np.unique(which[hit])]] = True
    return hidden


def polylines(parts: Floats, of: Ints, line_of: Ints, scale: float) -> Tuple[Floats, Ints, Ints]:
    """Join line parts into polylines.

    ``parts`` (K, 4) are pieces (x0, y0, x1, y1) of segments ``of`` (K,), in
    segment order and along each segment; segment ``s`` belongs to polyline
    ``line_of[s]``, and segments ``s`` and ``s + 1`` of one polyline meet.  Parts
    that continue one another (the end of one at the start of the next, within
    ``1e-9 * scale``) join.  Returns the vertices (V, 2), the offsets of the joined
    polylines (M + 1,) and the source polyline of each (M,)."""
    if not len(parts):
        return np.empty((0, 2)), np.zeros(1, np.int64), np.empty(0, np.int64)
    gap = np.hypot(parts[1:, 0] - parts[:-1, 2], parts[1:, 1] - parts[:-1, 3])
    joins = (gap <= 1e-9 * max(scale, 1.0)) & (line_of[of[1:]] == line_of[of[:-1]])
    begins = np.concatenate([[True], ~joins])
    # each part gives its end; a part beginning a polyline gives its start first
    counts = 1 + begins
    verts = np.empty((int(counts.sum()), 2))
    pos = np.cumsum(counts) - 1                        # where each part's end goes
    verts[pos] = parts[:, 2:]
    verts[pos[begins] - 1] = parts[begins, :2]
    firsts = np.flatnonzero(begins)
    offsets = np.concatenate([pos[firsts] - 1, [len(verts)]]).astype(np.int64)
    return verts, offsets, line_of[of[firsts]]


def original_edges(verts: Floats, offsets: Ints, owner: Ints, src: Floats,
                   src_count: Ints) -> Bools:
    """Whether each edge of each piece (vertex ``i`` to the next of its piece;
    ``verts`` (V, 2), ``offsets`` (P + 1,)) lies on an edge of the piece's source
    polygon ``src[owner[p]]`` ((N, K, 2), ``src_count`` (N,) vertices each): the
    outline matplotlib strokes, as opposed to the cuts of triangulation and
    splitting."""
    nxt = np.arange(1, len(verts) + 1)
    nxt[offsets[1:] - 1] = offsets[:-1]
    piece = np.repeat(np.arange(len(offsets) - 1), np.diff(offsets))
    s = owner[piece]
    a, b = verts, verts[nxt]
    on = np.zeros(len(verts), bool)
    k = src.shape[1]
    cnt = src_count[s]
    for j in range(k):
        valid = j < cnt
        u = src[s, j]
        v = src[s, np.where(j + 1 < cnt, j + 1, 0)]
        d = v - u
        length = np.hypot(d[:, 0], d[:, 1])
        good = valid & (length > 0)
        with np.errstate(invalid="ignore", divide="ignore"):
            tol = 1e-7 * (length + 1.0)
            da = np.abs(d[:, 0] * (a[:, 1] - u[:, 1]) - d[:, 1] * (a[:, 0] - u[:, 0])) / length
            db = np.abs(d[:, 0] * (b[:, 1] - u[:, 1]) - d[:, 1] * (b[:, 0] - u[:, 0])) / length
            ta = ((a - u) * d).sum(axis=1) / length ** 2
            tb = ((b - u) * d).sum(axis=1) / length ** 2
        e = 1e-7
        on |= good & (da <= tol) & (db <= tol) & (ta >= -e) & (ta <= 1 + e) & (tb >= -e) & (
            tb <= 1 + e)
    return on


def depth_along(parts: Floats, of: Ints, segments: Floats, depth: Floats) -> Floats:
    """The depths (K, 2) of the ends of ``parts`` (K, 4) of ``segments`` (depth linear
    along each segment on the screen: a projective map keeps lines straight)."""
    s = segments[of]
    d = s[:, 2:] - s[:, :2]
    length2 = np.maximum((d * d).sum(axis=1), 1e-300)
    t0 = ((parts[:, :2] - s[:, :2]) * d).sum(axis=1) / length2
    t1 = ((parts[:, 2:] - s[:, :2]) * d).sum(axis=1) / length2
    z0, z1 = depth[of, 0], depth[of, 1]
    return np.stack([z0 + t0 * (z1 - z0), z0 + t1 * (z1 - z0)], axis=1)
