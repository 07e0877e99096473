"""The depth-sorting method (Newell, Newell and Sancha 1972; Hearn & Baker, section
13-6): sort by depth, test the overlaps, reorder, split where nothing else works.

*Object precision* ordering and splitting (polygon against polygon, in device
space), painted at image precision.
"""

import threading
from collections.abc import Iterator
from typing import Any, Callable, Dict, List, Optional, Tuple, TypeVar, Union

import numpy as np
from numpy.typing import DTypeLike, NDArray

from .. import _validate as v
from .._kernels import depthsort as k
from .._kernels._jit import call
from ..errors import DepthSortLoopError
from ..screen.polygons import MIN_AREA, ScreenPolygons, as_screen

#: The overlap tests, in the order they are tried (each "yes" means: no reordering
#: is needed for this pair).
TESTS = ("x extents apart", "y extents apart", "S behind plane of S'",
         "S' in front of plane of S", "projections apart")

#: Relative tolerance of the plane and separation tests.
TOLERANCE = 1e-9

#: What ``drawn`` of :func:`depth_sort` is called with: a run's vertices, offsets, faces.
Drawn = Callable[[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]], object]

_S = TypeVar("_S", bound=np.generic)


def _bucket_room(entries: int) -> int:
    """Rows of the grid's buckets allocated for ``entries`` entries (the kernel asks
    for more when they are too few)."""
    return entries


#: Most bytes of working arrays a thread keeps from one sort to the next.
KEEP = 64 << 20

_KEPT = threading.local()


def _work(name: str, shape: Tuple[int, ...], dtype: DTypeLike = np.float64) -> NDArray[Any]:
    """An uninitialized working array of ``shape``: the first rows of the array
    ``name`` the calling thread kept from an earlier sort when it has enough of them
    (megabytes of new memory cost the sort of 10,000 polygons more in page faults
    than the sort itself, as the kept buffers of :mod:`scanline._pool`),
    else a new one, kept while the thread keeps at most :data:`KEEP` bytes in all.
    The arrays seen by the kernels have the rows asked for, kept or not."""
    kept: Optional[Dict[str, NDArray[Any]]] = getattr(_KEPT, "arrays", None)
    if kept is None:
        kept = _KEPT.arrays = {}
    a = kept.get(name)
    if a is not None and a.shape[0] >= shape[0] and a.shape[1:] == shape[1:] and (
            a.dtype == dtype):
        return a[:shape[0]]
    a = np.empty(shape, dtype)
    kept.pop(name, None)
    if a.nbytes + sum(b.nbytes for b in kept.values()) <= KEEP:
        kept[name] = a
    return a


def _grown(a: NDArray[_S], rows: int, name: Optional[str] = None) -> NDArray[_S]:
    """``a`` with room for at least ``rows`` rows (doubling), the rows kept (a
    working array ``name`` of :func:`_work`, or a new array)."""
    shape = (max(rows, 2 * len(a)),) + a.shape[1:]
    out: NDArray[_S] = np.empty(shape, a.dtype) if name is None else _work(name, shape, a.dtype)
    out[:len(a)] = a
    return out


def _describe(log: NDArray[np.int64], rows: int,
              byz: NDArray[np.int64]) -> Iterator[Dict[str, Union[int, str]]]:
    """The kernel's log rows as the dicts of :func:`depth_sort`'s ``log``, the pieces
    numbered as given (the kernel numbers the pieces given by rank: ``byz``)."""
    n = len(byz)
    for s, t, decided, action, piece, by, new in log[:rows].tolist():
        s, t, piece, by = (int(byz[x]) if 0 <= x < n else x for x in (s, t, piece, by))
        row: Dict[str, Union[int, str]] = {"S": s, "S'": t}
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


#: Pieces in a run handed to ``drawn`` (:func:`depth_sort`).
RUN = 1024


def _hand(drawn: Optional[Drawn], out: NDArray[np.float64], doff: NDArray[np.int64],
          dface: NDArray[np.int64], lo: int, hi: int) -> int:
    """``drawn`` called with the pieces ``lo .. hi - 1`` in drawing order (views of
    the sort's arrays); returns ``hi``."""
    if hi > lo and drawn is not None:
        a = doff[lo]
        drawn(out[a:doff[hi]], doff[lo:hi + 1] - a, dface[lo:hi])
    return hi


#: Most rows a step table's ``log`` may take (each a pair examined, a dict in ``log``).
LOG_ROWS = 200_000


def default_work(n: int) -> int:
    """The default bound of a sort's work, in surfaces gathered to compare with the
    heads (one more per step), for ``n`` polygons: 2,000,000 + 100 n.  Scenes of
    whole objects need a few times n (the 10k random triangles of the benchmark
    72,845; 100k triangles of 40 spheres 276,898; the teapot's 36k 264,478); a
    scene of thousands of large triangles at random depths, each cutting hundreds of
    others, would go on for minutes, and stops instead after a few seconds."""
    return 2_000_000 + 100 * n


def depth_sort(polygons: ScreenPolygons, split_cycles: bool = True,
               log: Optional[List[Dict[str, Any]]] = None, max_pieces: Optional[int] = None,
               drawn: Optional[Drawn] = None,
               max_work: Optional[int] = None) -> ScreenPolygons:
    """Order (and split where needed) polygons back to front by the depth-sorting
    method.

    Parameters
    ----------
    polygons : ScreenPolygons
        The polygons (:func:`scanline.screen.screen_polygons`).
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
    drawn : callable, optional
        Called on this thread with each run of pieces (:data:`RUN`, the last one
        shorter) as soon as their drawing order is fixed, while the sort of the rest
        waits: ``drawn(vertices, offsets, face)`` (as in :class:`ScreenPolygons`;
        views of the sort's working arrays, valid until the sort returns: copy what
        must outlive it).  Every piece is handed over once, in drawing order, before
        the sort returns (not after an error).  :func:`painted_depth_sort` paints
        beside the sort this way.
    max_work : int, optional
        The bound of the sort's time: the most surfaces all its steps may gather to
        compare with their heads (default :func:`default_work`); beyond it
        :class:`~scanline.errors.DepthSortLoopError` is raised (a scene this tangled
        is drawn in a fraction of the time by the depth buffer).

    Returns
    -------
    ScreenPolygons
        The pieces in drawing order, farthest first; a split piece lies in its
        face's plane and keeps its face index (``planes`` are normalized).

    Raises
    ------
    ArgumentTypeError
        ``split_cycles`` not a bool, or ``drawn`` not callable.
    ArgumentValueError
        A ``max_pieces`` or ``max_work`` that is not a positive integer.
    DepthSortLoopError
        A cycle or an intersection with ``split_cycles=False``, more pieces than
        ``max_pieces``, or more work than ``max_work``.
    MemoryBudgetError
        A ``log`` that would pass :data:`LOG_ROWS` rows.

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

    Examples
    --------
    >>> import scanline as sl
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> sp = sl.screen.screen_polygons(sl.mesh.cube(2), cam, 4, 4)
    >>> sp.face.tolist()                  # the back and front faces; the sides are edge-on
    [4, 5]
    >>> sl.visible.depth_sort(sp).face.tolist()       # no overlap in depth: back, front
    [4, 5]
    """
    sp = as_screen(polygons)
    if not isinstance(split_cycles, bool):
        raise v.ArgumentTypeError(f"split_cycles must be True or False, got {split_cycles!r}")
    limit = 16 * len(sp) + 1000 if max_pieces is None else v.positive_int("max_pieces",
                                                                          max_pieces)
    if drawn is not None and not callable(drawn):
        raise v.ArgumentTypeError(f"drawn must be a function of (vertices, offsets, face) "
                                  f"or None, got {v._show(drawn)}")
    n = len(sp)
    if n == 0:
        return sp.subset([])
    nv = len(sp.vertices)
    cap = 2 * n + 16
    fl = _work("fl", (cap, 12))
    it = _work("it", (cap, k.IT), np.int64)
    tag = _work("tag", (cap,), np.int64)
    pv = _work("pv", (2 * nv + 64, 3))
    byz = _work("byz", (n,), np.int64)
    keys, tkeys = _work("keys", (cap,)), _work("tkeys", (cap,))
    cand, titems = _work("cand", (cap,), np.int64), _work("titems", (cap,), np.int64)
    grid = np.empty(6)
    st = np.zeros(k.STATE, np.int64)
    # work: the Python twin's microseconds (about 50 a polygon, and the radix sort's
    # counts)
    call(k.prepare, 40 * n + 10 * nv + 3000, np.ascontiguousarray(sp.vertices, np.float64),
         np.ascontiguousarray(sp.offsets, np.int64),
         np.ascontiguousarray(sp.planes, np.float64), np.ascontiguousarray(sp.face, np.int64),
         fl, it, tag, pv, byz, keys, tkeys, titems, grid, st)
    cells = int(grid[3]) * int(grid[4])
    heads = _work("heads", (cells,), np.int64)
    heads.fill(-1)
    first, low = _work("first", (cells + 1,), np.int64), _work("low", (cells,), np.int64)
    cent = _work("cent", (_bucket_room(int(st[k.BUCKETS])), 6))
    ent = _work("ent", (int(st[k.BUCKETS]) // 2 + 4 * int(st[k.MAXCELLS]) + 256, 2), np.int64)
    heap = _work("heap", (cap, 2))
    out = _work("out", pv.shape)
    dface, dplane = _work("dface", (cap,), np.int64), _work("dplane", (cap, 4))
    doff = _work("doff", (cap + 1,), np.int64)
    doff[0] = 0
    memo = _work("memo", (8 * n + 1024,), np.int64)
    rows = np.empty((4 * n + 16 if log is not None else 1, 7), np.int64)
    work = default_work(n) if max_work is None else v.positive_int("max_work", max_work)
    run = RUN if drawn is not None else 0
    st[k.PAUSE] = run
    handed = 0
    while True:
        status = call(k.depth_sort, 300 * n + 10, pv, fl, it, tag, heap, heads, ent, grid, first,
                      low, cent, dface, dplane, doff, out, cand, keys, tkeys, titems, memo,
                      rows, np.empty(4), st, tolerance(sp), MIN_AREA * 1e-3, limit + n,
                      work, split_cycles, k.TRACE[log is not None])
        if status == k.PAUSED:
            handed = _hand(drawn, out, doff, dface, handed, int(st[k.DRAWN]))
            st[k.PAUSE] += run
            continue
        if status != k.NEED_ROOM:
            break
        short = st[k.T]
        if short == k.ROOM_PIECES:
            fl, it = _grown(fl, len(fl) + 2, "fl"), _grown(it, len(it) + 2, "it")
            tag = _grown(tag, len(fl), "tag")
            cand, titems = _grown(cand, len(fl), "cand"), _grown(titems, len(fl), "titems")
            keys, tkeys = _grown(keys, len(fl), "keys"), _grown(tkeys, len(fl), "tkeys")
            dface, dplane = _grown(dface, len(fl), "dface"), _grown(dplane, len(fl), "dplane")
            doff = _grown(doff, len(fl) + 1, "doff")
        elif short == k.ROOM_VERTS:
            pv = _grown(pv, st[k.VERTS] + 4 * st[k.MAXK], "pv")
        elif short == k.ROOM_HEAP:
            heap = _grown(heap, st[k.HEAP] + 2, "heap")
        elif short == k.ROOM_ENTRIES:
            ent = _grown(ent, st[k.ENTRIES] + 2 * st[k.MAXCELLS], "ent")
        elif short == k.ROOM_BUCKETS:
            cent = _work("cent", (st[k.BUCKETS], 6))
        elif short == k.ROOM_ROWS:
            need = st[k.ROWS] + st[k.ALIVE] + 1
            if need > LOG_ROWS:
                from ..errors import MemoryBudgetError

                raise MemoryBudgetError(
                    f"log: the step table of {n} polygons passes {LOG_ROWS:,} rows (a row per "
                    "pair examined); log a smaller scene, or sort without log=")
            rows = _grown(rows, need)
        else:
            out = _grown(out, st[k.OUT] + st[k.MAXK], "out")
    if log is not None:
        log.extend(_describe(rows, st[k.ROWS], byz))
    s, t = int(st[k.S]), int(st[k.T])
    if status == k.TOO_LONG:
        raise DepthSortLoopError(
            f"depth sort gave up after comparing {work:,} surfaces in {st[k.STEPS]:,} steps "
            f"on {n} polygons ({st[k.PIECES]:,} pieces so far): they overlap and cut one "
            "another too much for an order to be found in bounded time (the depth buffer, "
            "method='z-buffer', draws such scenes at once); raise max_work to go on")
    if status == k.TOO_MANY:
        raise DepthSortLoopError(
            f"depth sort needs more than max_pieces={limit} pieces to resolve the "
            f"overlaps of {n} polygons; raise max_pieces")
    if status in (k.CYCLE, k.UNCUT):
        named = [int(byz[x]) if x < n else x for x in (s, t)]
        faces = f"polygons {named[0]} and {named[1]} (faces {it[s, 2]} and {it[t, 2]})"
        raise DepthSortLoopError(
            f"{faces} overlap cyclically or intersect: no drawing order exists without "
            "splitting; use split_cycles=True" if status == k.CYCLE else
            f"{faces} cannot be ordered and neither plane cuts the other polygon (nearly "
            "coincident polygons?); the loop flag stopped the sort")
    count = int(st[k.DRAWN])
    _hand(drawn, out, doff, dface, handed, count)
    # copies of the working arrays: new arrays, no larger than needed
    return ScreenPolygons(out[:st[k.OUT]].copy(), doff[:count + 1].copy(),
                          dface[:count].copy(), dplane[:count].copy(), sp.width, sp.height)


def tolerance(sp: ScreenPolygons) -> float:
    """The absolute tolerance of the plane and separation tests on ``sp``'s device."""
    return TOLERANCE * max(sp.width, sp.height, 1.0)


def painted_depth_sort(polygons: ScreenPolygons, split_cycles: bool = True,
                       max_pieces: Optional[int] = None, max_work: Optional[int] = None
                       ) -> Tuple[ScreenPolygons, NDArray[np.int32]]:
    """:func:`depth_sort` with the pieces painted as the sort goes:
    ``(pieces, numbers)``, ``numbers`` (int32, height x width of the polygons' device)
    the number of the piece seen at each pixel (-1: none), the pieces painted in
    drawing order by the spans of the 2-D polygon fill, later over earlier.

    The sort hands over each run of pieces as soon as their order is fixed (its
    ``drawn``); a second thread paints the runs' piece numbers while the sort orders
    the next pieces.  Painting numbers, not colors, the result says what is seen
    (the shading colors it).

    Parameters
    ----------
    polygons : ScreenPolygons
        The polygons.
    split_cycles, max_pieces, max_work
        As :func:`depth_sort` takes them.

    Returns
    -------
    pieces : ScreenPolygons
        The pieces in drawing order.
    numbers : ndarray of int32 (height, width)
        The piece seen at each pixel (-1: none), rows bottom-up.

    Raises
    ------
    DepthSortLoopError
        As :func:`depth_sort`.

    Examples
    --------
    >>> import scanline as sl
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> sp = sl.screen.screen_polygons(sl.mesh.cube(2), cam, 4, 4)
    >>> sp.face.tolist()                  # the back and front faces; the sides are edge-on
    [4, 5]
    >>> pieces, numbers = sl.visible.painted_depth_sort(sp)
    >>> numbers.tolist()                  # piece 1, the front face, painted last
    [[-1, -1, -1, -1], [-1, 1, 1, -1], [-1, 1, 1, -1], [-1, -1, -1, -1]]
    """
    import queue

    from .._kernels._jit import call
    from .._kernels._threads import _submit
    from .._kernels.visible import paint_numbers

    from .._pool import recycled

    sp = as_screen(polygons)
    w, h = sp.width, sp.height
    numbers = recycled("piece numbers", (h, w), np.int32)
    runs: "queue.SimpleQueue[Optional[Tuple[NDArray[np.float64], NDArray[np.int64], int]]]" = (
        queue.SimpleQueue())
    count = [0]

    def painter() -> None:
        numbers.fill(-1)
        while (run := runs.get()) is not None:
            verts, offsets, first = run
            # work: a row per piece and ten units a vertex, as the fills count them
            call(paint_numbers, h + 10 * len(verts) + len(offsets), 0, 1, w, h, verts,
                 offsets, first, numbers)

    def drawn(verts: NDArray[np.float64], offsets: NDArray[np.int64],
              face: NDArray[np.int64]) -> None:
        runs.put((verts, offsets, count[0]))
        count[0] += len(face)

    wait = _submit(painter)
    try:
        pieces = depth_sort(sp, split_cycles, max_pieces=max_pieces, drawn=drawn,
                            max_work=max_work)
    finally:
        runs.put(None)
        wait()
    return pieces, numbers
