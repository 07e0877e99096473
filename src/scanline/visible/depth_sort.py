"""The depth-sorting method (Newell, Newell and Sancha 1972; Hearn & Baker, section
13-6): sort by depth, test the overlaps, reorder, split where nothing else works.

*Object precision* ordering and splitting (polygon against polygon, in device
space), painted at image precision.
"""

import numpy as np

from .. import _validate as v
from .._kernels import depthsort as k
from .._kernels._jit import call
from ..errors import DepthSortLoopError
from .polygons import MIN_AREA, ScreenPolygons, as_screen

#: The overlap tests, in the order they are tried (each "yes" means: no reordering
#: is needed for this pair).
TESTS = ("x extents apart", "y extents apart", "S behind plane of S'",
         "S' in front of plane of S", "projections apart")

#: Relative tolerance of the plane and separation tests.
TOLERANCE = 1e-9


#: At most this many grid cells a side.
GRID = 1000


def _grid(ext):
    """The grid of the candidate search: (x0, y0, cell, nx, ny), cells of twice the
    median piece size (at most :data:`GRID` a side; one cell when the extents are too
    large to subtract), and each piece's cell count."""
    with np.errstate(all="ignore"):
        size = np.maximum(ext[:, 1] - ext[:, 0], ext[:, 3] - ext[:, 2])
        x0, y0 = float(ext[:, 0].min()), float(ext[:, 2].min())
        wide, high = float(ext[:, 1].max()) - x0, float(ext[:, 3].max()) - y0
        cell = max(float(np.median(size)) * 2.0, max(wide, high) / GRID, 1e-6)
        if not np.isfinite(cell):
            return np.array([x0, y0, np.inf, 1.0, 1.0]), np.ones(len(ext), np.int64)
        nx, ny = int(wide // cell) + 1, int(high // cell) + 1
        i = np.clip(np.floor((ext[:, 0:2] - x0) / cell), 0, nx - 1)
        j = np.clip(np.floor((ext[:, 2:4] - y0) / cell), 0, ny - 1)
    cells = (i[:, 1] - i[:, 0] + 1) * (j[:, 1] - j[:, 0] + 1)
    return np.array([x0, y0, cell, nx, ny], np.float64), cells.astype(np.int64)


def _grown(a, rows):
    """``a`` with room for at least ``rows`` rows (doubling), the rows kept."""
    out = np.empty((max(rows, 2 * len(a)),) + a.shape[1:], a.dtype)
    out[:len(a)] = a
    return out


def _describe(log, rows):
    """The kernel's log rows as the dicts of :func:`depth_sort`'s ``log``."""
    for s, t, decided, action, piece, by, new in log[:rows].tolist():
        row = {"S": s, "S'": t}
        outcomes = ("no",) * (decided - 1) + ("yes",) if decided else ("no",) * 5
        row.update(zip(TESTS, outcomes))
        if action == k.MOVE:
            row["action"] = f"move {t} to the head (flag it)"
        elif action in (k.SPLIT, k.HALVE):
            plane = f"the plane of {by}" if action == k.SPLIT else "a plane across its middle"
            row["action"] = f"{t} is flagged: split {piece} by {plane} into {new} and {new + 1}"
        else:
            row["action"] = "none"
        yield row


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
    n = len(sp)
    if n == 0:
        return sp.subset([])
    ext = sp.extents()
    grid, cells = _grid(ext)
    cap = 2 * n + 16
    norm = np.linalg.norm(sp.planes[:, :3], axis=1, keepdims=True)
    fl = np.empty((cap, 12))
    fl[:n, :6] = ext
    fl[:n, 6:10] = sp.planes / np.where(norm > 0, norm, 1.0)
    x, y = sp.vertices[:, 0], sp.vertices[:, 1]
    nxt = np.arange(1, len(x) + 1)
    nxt[sp.offsets[1:] - 1] = sp.offsets[:-1]
    fl[:n, 11] = np.where(np.add.reduceat(x * y[nxt] - x[nxt] * y, sp.offsets[:-1]) > 0,
                          1.0, -1.0)
    order = np.argsort(-ext[:, 5], kind="stable")
    fl[order, 10] = np.arange(n, dtype=np.float64)
    counts = sp.counts
    it = np.zeros((cap, 6), np.int64)
    it[:n, 0] = sp.offsets[:-1]
    it[:n, 1] = counts
    it[:n, 2] = sp.face
    it[:n, 3] = 1
    it[:n, 5] = -1
    pv = np.empty((2 * len(sp.vertices) + 64, 3))
    pv[:len(sp.vertices)] = sp.vertices
    heap = np.empty((cap, 2))
    ent = np.empty((int(cells.sum()) + 4 * int(cells.max()) + 256, 2), np.int64)
    out = np.empty_like(pv)
    st = np.zeros(k.STATE, np.int64)
    st[[k.PIECES, k.VERTS, k.ALIVE]] = n, len(sp.vertices), n
    st[k.LOW] = -1
    st[k.MAXK] = counts.max()
    st[k.MAXCELLS] = 1
    drawn, cand, titems = (np.empty(cap, np.int64) for _ in range(3))
    keys, tkeys = np.empty(cap), np.empty(cap)
    rows = np.empty((4 * n + 16 if log is not None else 1, 7), np.int64)
    heads = np.full(int(grid[3] * grid[4]), -1, np.int64)
    first, low = np.empty(len(heads) + 1, np.int64), np.empty(len(heads), np.int64)
    cent = np.empty((int(cells.sum()), 6))
    max_steps = 4 * limit + 10 * n * n + 100
    while True:
        status = call(k.depth_sort, 300 * n + 10, pv, fl, it, heap, heads, ent, grid, first,
                      low, cent, order, drawn, out, cand, keys, tkeys, titems, rows,
                      np.empty(4), st, tolerance(sp), MIN_AREA * 1e-3, limit + n, max_steps,
                      split_cycles, k.TRACE[log is not None])
        if status != k.NEED_ROOM:
            break
        short = st[k.T]
        if short == k.ROOM_PIECES:
            fl, it = _grown(fl, len(fl) + 2), _grown(it, len(it) + 2)
            drawn, cand, titems = (_grown(a, len(fl)) for a in (drawn, cand, titems))
            keys, tkeys = _grown(keys, len(fl)), _grown(tkeys, len(fl))
        elif short == k.ROOM_VERTS:
            pv = _grown(pv, st[k.VERTS] + 4 * st[k.MAXK])
        elif short == k.ROOM_HEAP:
            heap = _grown(heap, st[k.HEAP] + 2)
        elif short == k.ROOM_ENTRIES:
            ent = _grown(ent, st[k.ENTRIES] + 2 * st[k.MAXCELLS])
        elif short == k.ROOM_BUCKETS:
            cent = np.empty((st[k.BUCKETS], 6))
        elif short == k.ROOM_ROWS:
            rows = _grown(rows, st[k.ROWS] + st[k.ALIVE] + 1)
        else:
            out = _grown(out, st[k.OUT] + st[k.MAXK])
    if log is not None:
        log.extend(_describe(rows, st[k.ROWS]))
    s, t = int(st[k.S]), int(st[k.T])
    if status == k.TOO_LONG:
        raise DepthSortLoopError(
            f"depth sort did not finish after {st[k.STEPS] - 1} steps on {n} polygons; "
            "the input holds an overlap the tests cannot order (nearly coincident "
            "polygons?)")
    if status == k.TOO_MANY:
        raise DepthSortLoopError(
            f"depth sort needs more than max_pieces={limit} pieces to resolve the "
            f"overlaps of {n} polygons; raise max_pieces")
    if status in (k.CYCLE, k.UNCUT):
        faces = f"polygons {s} and {t} (faces {it[s, 2]} and {it[t, 2]})"
        raise DepthSortLoopError(
            f"{faces} overlap cyclically or intersect: no drawing order exists without "
            "splitting; use split_cycles=True" if status == k.CYCLE else
            f"{faces} cannot be ordered and neither plane cuts the other polygon (nearly "
            "coincident polygons?); the loop flag stopped the sort")
    drawn = drawn[:st[k.DRAWN]]
    offsets = np.zeros(len(drawn) + 1, np.int64)
    np.cumsum(it[drawn, 1], out=offsets[1:])
    return ScreenPolygons(out[:st[k.OUT]], offsets, it[drawn, 2],
                          np.ascontiguousarray(fl[drawn, 6:10]), sp.width, sp.height)


def tolerance(sp):
    """The absolute tolerance of the plane and separation tests on ``sp``'s device."""
    return TOLERANCE * max(sp.width, sp.height, 1.0)
