"""The depth-sorting method (Newell, Newell and Sancha 1972; Hearn & Baker, section
13-6): sort by depth, test the overlaps, reorder, split where nothing else works.

*Object precision* ordering and splitting (polygon against polygon, in device
space), painted at image precision.
"""

import heapq

import numpy as np

from .. import _validate as v
from ..errors import DepthSortLoopError
from .polygons import MIN_AREA, ScreenPolygons, as_screen, signed_area

#: The overlap tests, in the order they are tried (each "yes" means: no reordering
#: is needed for this pair).
TESTS = ("x extents apart", "y extents apart", "S behind plane of S'",
         "S' in front of plane of S", "projections apart")

#: Relative tolerance of the plane and separation tests.
TOLERANCE = 1e-9


class _Pieces:
    """The polygons being sorted: vertices, planes (normalized: |(A, B, C)| = 1) and
    extents of each piece, growing as pieces are split off."""

    def __init__(self, sp):
        self.poly = [sp.polygon(p).copy() for p in range(len(sp))]
        self.face = sp.face.tolist()
        norm = np.linalg.norm(sp.planes[:, :3], axis=1, keepdims=True)
        self.plane = list(sp.planes / np.where(norm > 0, norm, 1.0))
        ext = sp.extents()
        cap = max(16, 2 * len(sp))
        self.ext = np.empty((cap, 6))
        self.ext[:len(sp)] = ext
        self.n = len(sp)
        self.eps = TOLERANCE * max(sp.width, sp.height, 1.0)

    def add(self, verts, face, plane):
        if self.n == len(self.ext):
            self.ext = np.concatenate([self.ext, np.empty_like(self.ext)])
        self.poly.append(verts)
        self.face.append(face)
        self.plane.append(plane)
        self.ext[self.n] = (verts[:, 0].min(), verts[:, 0].max(), verts[:, 1].min(),
                            verts[:, 1].max(), verts[:, 2].min(), verts[:, 2].max())
        self.n += 1
        return self.n - 1

    def side(self, plane, p):
        """Signed distances of piece ``p``'s vertices to ``plane`` (> 0: behind)."""
        return self.poly[p] @ plane[:3] + plane[3]


class _Grid:
    """A uniform grid over the screen, each cell listing the pieces whose bounding
    boxes meet it: the surfaces that can fail tests 1 and 2 against a surface are
    found among those sharing its cells, not by scanning the whole list."""

    def __init__(self, pieces):
        ext = pieces.ext[:pieces.n]
        self.pieces = pieces
        size = np.maximum(ext[:, 1] - ext[:, 0], ext[:, 3] - ext[:, 2]) if pieces.n else [1.0]
        self.cell = max(float(np.median(size)) * 2.0, 1e-6)
        span = max(float(ext[:, 1].max() - ext[:, 0].min()) if pieces.n else 1.0,
                   float(ext[:, 3].max() - ext[:, 2].min()) if pieces.n else 1.0)
        self.cell = max(self.cell, span / 1000.0)      # at most 1000 x 1000 cells
        self.x0 = float(ext[:, 0].min()) if pieces.n else 0.0
        self.y0 = float(ext[:, 2].min()) if pieces.n else 0.0
        self.cells = {}
        for p in range(pieces.n):
            self.add(p)

    def _range(self, p):
        e = self.pieces.ext[p]
        c = self.cell
        return (int((e[0] - self.x0) // c), int((e[1] - self.x0) // c),
                int((e[2] - self.y0) // c), int((e[3] - self.y0) // c))

    def add(self, p):
        i0, i1, j0, j1 = self._range(p)
        for i in range(i0, i1 + 1):
            for j in range(j0, j1 + 1):
                self.cells.setdefault((i, j), []).append(p)

    def near(self, p, alive):
        """The pieces alive sharing a cell with ``p`` (p excluded)."""
        i0, i1, j0, j1 = self._range(p)
        found = set()
        for i in range(i0, i1 + 1):
            for j in range(j0, j1 + 1):
                found.update(self.cells.get((i, j), ()))
        found.discard(p)
        return np.array([q for q in found if q in alive], np.int64)


def behind_plane(pieces, s, t):
    """Test 3: every vertex of ``s`` is behind (or on) the plane of ``t``."""
    return bool((pieces.side(pieces.plane[t], s) >= -pieces.eps).all())


def in_front_of_plane(pieces, t, s):
    """Test 4: every vertex of ``t`` is in front of (or on) the plane of ``s``."""
    return bool((pieces.side(pieces.plane[s], t) <= pieces.eps).all())


def projections_apart(a, b, eps):
    """Test 5: the (x, y) projections of the convex polygons ``a`` and ``b`` do not
    overlap (they may touch): some edge of either separates them.  Plain Python: the
    polygons have a handful of vertices, where numpy's per-call cost dominates."""
    pa = a[:, :2].tolist()
    pb = b[:, :2].tolist()
    for p, q in ((pa, pb), (pb, pa)):
        n = len(p)
        area = sum(p[k][0] * p[(k + 1) % n][1] - p[(k + 1) % n][0] * p[k][1]
                   for k in range(n))
        orient = 1.0 if area > 0 else -1.0
        for k in range(n):
            x0, y0 = p[k]
            x1, y1 = p[(k + 1) % n]
            ex, ey = x1 - x0, y1 - y0
            tol = eps * (ex * ex + ey * ey) ** 0.5
            # q wholly on the outer side of edge k (or on it): a separating line
            if all((ex * (y - y0) - ey * (x - x0)) * orient <= tol for x, y in q):
                return True
    return False


def split(pieces, p, plane):
    """Split piece ``p`` by ``plane`` into the part in front and the part behind
    (Sutherland-Hodgman against the plane and its opposite); each part keeps ``p``'s
    face and plane.  Returns ``(front, behind)`` vertex arrays, or None when the
    plane does not cut the piece."""
    d = pieces.side(plane, p)
    if not ((d < -pieces.eps).any() and (d > pieces.eps).any()):
        return None
    verts = pieces.poly[p]
    front, back = [], []
    k = len(verts)
    for i in range(k):
        j = (i + 1) % k
        a, b = verts[i], verts[j]
        da, db = d[i], d[j]
        if da <= pieces.eps:
            front.append(a)
        if da >= -pieces.eps:
            back.append(a)
        if (da < -pieces.eps and db > pieces.eps) or (da > pieces.eps and db < -pieces.eps):
            cut = a + (b - a) * (da / (da - db))
            front.append(cut)
            back.append(cut)
    parts = [np.array(part) for part in (front, back)]
    if any(len(part) < 3 or abs(signed_area(part)) <= MIN_AREA * 1e-3 for part in parts):
        return None
    return parts


def _halving(pieces, s, t):
    """The wider of pieces ``s`` and ``t`` on screen and the plane x = const or
    y = const through its middle (perpendicular to the screen, so each part stays in
    the piece's plane): the last resort when neither polygon's plane cuts the other."""
    es, et = pieces.ext[s], pieces.ext[t]
    ws = max(es[1] - es[0], es[3] - es[2])
    wt = max(et[1] - et[0], et[3] - et[2])
    cut, e = (s, es) if ws >= wt else (t, et)
    if e[1] - e[0] >= e[3] - e[2]:
        return cut, None, np.array([1.0, 0.0, 0.0, -0.5 * (e[0] + e[1])])
    return cut, None, np.array([0.0, 1.0, 0.0, -0.5 * (e[2] + e[3])])


def _row(log, s, t, outcomes, action):
    if log is None:
        return
    row = {"S": s, "S'": t}
    for name, value in zip(TESTS, outcomes):
        row[name] = value
    row["action"] = action
    log.append(row)


def depth_sort(polygons, split_cycles=True, log=None, max_pieces=None):
    """Order (and split where needed) polygons back to front by the depth-sorting
    method.

    Parameters
    ----------
    polygons : ScreenPolygons
    split_cycles : bool
        Split a polygon by another's plane when the loop flag shows that no order
        exists (cyclic overlap, intersecting polygons).  False: raise
        :class:`~scanline.errors.DepthSortLoopError` instead.
    log : list, optional
        Receives one dict per pair examined: ``S``, ``S'`` (piece numbers), the
        outcome of each test of :data:`TESTS` tried ("yes"/"no"), and the action.
    max_pieces : int, optional
        Most pieces the splitting may create (default 16 P + 1000); beyond it
        :class:`~scanline.errors.DepthSortLoopError` is raised.

    Returns
    -------
    ScreenPolygons
        The pieces in drawing order, farthest first; a split piece lies in its
        face's plane and keeps its face index (``planes`` are normalized).

    Notes
    -----
    Hearn & Baker, section 13-6 (Newell, Newell and Sancha 1972).  The polygons are
    sorted by decreasing greatest depth.  The first surface S of the list is
    compared with every other surface S' whose depth extent overlaps its own (or,
    once reordering has moved S forward, lies wholly behind it); for
    each, the tests below are tried in order of increasing cost, and one "yes" is
    enough (S cannot hide S'):

    1. their x extents do not overlap;
    2. their y extents do not overlap (1 and 2: Hearn & Baker's "bounding
       rectangles do not overlap");
    3. S is completely behind the plane of S' (every vertex on the far side);
    4. S' is completely in front of the plane of S;
    5. their projections on the view plane do not overlap.

    When S passes against every S', it is painted and removed.  When all five tests
    fail for some S', S' is moved to the head of the list and examined next, and it
    is *flagged*.  A flagged surface that would have to move again reveals a cycle
    (cyclic overlap, or surfaces that intersect): it is split by the plane of S (or,
    when that plane does not cut it, S by the plane of S'), and the pieces take its
    place.  Each piece lies wholly on one side of the plane, so the tests then
    succeed.  Planes are device-space planes: after the perspective divide every
    projector is parallel to z, so "in front" means smaller z.  Object precision.

    References
    ----------
    M. E. Newell, R. G. Newell and T. L. Sancha, "A solution to the hidden surface
    problem", Proceedings of the ACM Annual Conference, 1972, 443-450.
    """
    sp = as_screen(polygons)
    if not isinstance(split_cycles, bool):
        raise v.ArgumentTypeError(f"split_cycles must be True or False, got {split_cycles!r}")
    limit = 16 * len(sp) + 1000 if max_pieces is None else v.positive_int("max_pieces",
                                                                          max_pieces)
    pieces = _Pieces(sp)
    eps = pieces.eps
    grid = _Grid(pieces)
    # the list, kept as keys (rank, sequence) in a heap: the head is the least key
    # alive; moving a surface to the head gives it a key below every other
    key = {}
    heap = []
    alive = set()
    for rank, p in enumerate(np.argsort(-pieces.ext[:pieces.n, 5], kind="stable").tolist()):
        key[p] = (float(rank), p)
        heap.append((key[p], p))
        alive.add(p)
    heapq.heapify(heap)
    low = -1.0
    flagged = set()
    out = []
    steps = 0
    while alive:
        steps += 1
        if steps > 4 * limit + 10 * len(sp) ** 2 + 100:
            raise DepthSortLoopError(
                f"depth sort did not finish after {steps} steps on {len(sp)} polygons; "
                "the input holds an overlap the tests cannot order (nearly coincident "
                "polygons?)")
        while heap[0][1] not in alive or heap[0][0] != key[heap[0][1]]:
            heapq.heappop(heap)
        s = heap[0][1]
        es = pieces.ext[s]
        if log is None:
            near = grid.near(s, alive)
        else:                 # small scenes: every surface, to log tests 1 and 2 too
            near = np.array(sorted((q for q in alive if q != s), key=key.__getitem__),
                            np.int64)
        mover = None
        if len(near):
            e = pieces.ext[near]
            # not wholly in front of S: a depth overlap, or (after reordering moved
            # S ahead) wholly behind it
            depth = e[:, 5] > es[4] + eps
            xa = (e[:, 1] <= es[0] + eps) | (e[:, 0] >= es[1] - eps)
            ya = (e[:, 3] <= es[2] + eps) | (e[:, 2] >= es[3] - eps)
            if log is not None:
                for t in near[depth & xa].tolist():
                    _row(log, s, t, ("yes",), "none")
                for t in near[depth & ~xa & ya].tolist():
                    _row(log, s, t, ("no", "yes"), "none")
            for t in sorted(near[depth & ~xa & ~ya].tolist(), key=key.__getitem__):
                if behind_plane(pieces, s, t):
                    _row(log, s, t, ("no", "no", "yes"), "none")
                elif in_front_of_plane(pieces, t, s):
                    _row(log, s, t, ("no", "no", "no", "yes"), "none")
                elif projections_apart(pieces.poly[s], pieces.poly[t], eps):
                    _row(log, s, t, ("no", "no", "no", "no", "yes"), "none")
                else:
                    mover = t
                    break
        if mover is None:
            out.append(s)
            alive.discard(s)
            flagged.discard(s)
            continue
        t = mover
        if t not in flagged:
            _row(log, s, t, ("no",) * 5, f"move {t} to the head (flag it)")
            flagged.add(t)
            key[t] = (low, t)
            low -= 1.0
            heapq.heappush(heap, (key[t], t))
            continue
        if not split_cycles:
            raise DepthSortLoopError(
                f"polygons {s} and {t} (faces {pieces.face[s]} and {pieces.face[t]}) "
                "overlap cyclically or intersect: no drawing order exists without "
                "splitting; use split_cycles=True")
        done = False
        for cut, by in ((t, s), (s, t), (None, None)):
            if cut is None:      # neither plane cuts: halve the wider piece on screen
                cut, by, plane = _halving(pieces, s, t)
            else:
                plane = pieces.plane[by]
            parts = split(pieces, cut, plane)
            if parts is None:
                continue
            if pieces.n + 2 > limit + len(sp):
                raise DepthSortLoopError(
                    f"depth sort needs more than max_pieces={limit} pieces to resolve the "
                    f"overlaps of {len(sp)} polygons; raise max_pieces")
            new = [pieces.add(part, pieces.face[cut], pieces.plane[cut]) for part in parts]
            _row(log, s, t, ("no",) * 5,
                 f"{t} is flagged: split {cut} by " + (f"the plane of {by}" if by is not None else
                                                      "a plane across its middle")
                 + f" into {new[0]} and {new[1]}")
            # the pieces take the place of the polygon split, farther piece first
            rank = key[cut][0]
            for q in sorted(new, key=lambda q: -pieces.ext[q, 5]):
                key[q] = (rank, q)
                heapq.heappush(heap, (key[q], q))
                alive.add(q)
                grid.add(q)
            alive.discard(cut)
            flagged.discard(cut)
            done = True
            break
        if not done:
            raise DepthSortLoopError(
                f"polygons {s} and {t} (faces {pieces.face[s]} and {pieces.face[t]}) "
                "cannot be ordered and neither plane cuts the other polygon (nearly "
                "coincident polygons?); the loop flag stopped the sort")
    verts = [pieces.poly[p] for p in out]
    counts = np.array([len(p) for p in verts], np.int64)
    return ScreenPolygons(
        np.ascontiguousarray(np.concatenate(verts) if verts else np.empty((0, 3))),
        np.concatenate([[0], np.cumsum(counts)]).astype(np.int64),
        np.array([pieces.face[p] for p in out], np.int64),
        np.array([pieces.plane[p] for p in out], np.float64).reshape(-1, 4),
        sp.width, sp.height)
