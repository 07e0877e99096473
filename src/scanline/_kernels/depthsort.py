"""The depth-sorting method (Newell, Newell and Sancha 1972; Hearn & Baker, section
13-6) as one resumable kernel: the list sorted by greatest depth, the five overlap
tests, reordering with the loop flag, and splitting.

The list is ordered by keys (rank, piece): the head of the list is the least key
alive; moving a surface to the head gives it a rank below every other; the two
pieces of a split surface take its rank (the farther piece gets the lower number, so
it comes first).  The pieces given keep their ranks in ``byz`` (the initial sort),
read from a cursor; moved and split pieces go to a binary heap of (rank, piece), and
the head is the lesser of the two fronts (stale entries are skipped).

A uniform grid over the screen lists the pieces whose bounding boxes meet each cell,
so that the surfaces compared with the head are found among those sharing its cells
(or, for a step table, among every surface alive).  The pieces given are bucketed
once (:func:`bucket`), each cell's in the order of ``byz`` with their boxes and
greatest depths beside them: a cell is read in sequence, up to the first surface
that lies wholly in front of the head (the rest of the cell lies in front too, and
cannot fail the tests against it).  The pieces of splits are linked into the cells
as they are made.  Painted surfaces leave the cells as the cells are read.

The inner loops are written in the kernel and in helpers that pass no array on to
another helper: numba counts the references of the arrays of a helper that does (and
of an inlined helper), two atomic operations per array per call, which once took
most of the sort's time.

All state lives in arrays the caller allocates (:mod:`scanline.visible.depth_sort`),
and the scalars in ``st`` (indices below).  When an array has too little room for
the next step the kernel returns :data:`NEED_ROOM` *before* changing anything; the
caller enlarges the arrays and calls again, and the sort resumes where it stopped.

Per piece ``p``: ``fl[p]`` holds the extents xmin, xmax, ymin, ymax, zmin, zmax
(columns 0-5), the normalized plane A, B, C, D (6-9), the rank (10) and the
orientation of its (x, y) projection (11: 1 counterclockwise, -1 clockwise); ``it[p]``
holds the first vertex in ``pv`` and the vertex count (0, 1), the face (2), alive
(3), flagged (4), and the stamp of the last step that listed it (5).
"""

import numpy as np

from ._jit import helper, kernel
from .planecut import plane_part
from .sort import sort_keys
from .variants import token

# -- indices into the state array ``st`` -------------------------------------------------
PIECES = 0      # pieces so far
VERTS = 1       # vertices used in pv
HEAP = 2        # heap entries (moved and split pieces)
ENTRIES = 3     # grid entries of split pieces
DRAWN = 4       # pieces in drawing order
ROWS = 5        # log rows
STEPS = 6       # steps taken
STATUS = 7      # see the codes below
S = 8           # the pair of an error
T = 9
LOW = 10        # the next rank below every other (negative)
STAMP = 11      # the last stamp handed out
ALIVE = 12      # pieces alive
MAXK = 13       # most vertices of a piece
MAXCELLS = 14   # most grid cells of a piece
OUT = 15        # vertices written to ``out``
LIST = 16       # the first position of ``byz`` that may still be alive with its rank
BUCKETED = 17   # 1 once the pieces given are bucketed in the grid
BUCKETS = 18    # entries of the buckets (rows of ``cent`` needed)
STATE = 19

# -- status codes ------------------------------------------------------------------------
DONE = 0
NEED_ROOM = 1   # st[T] says which array: one of the ROOM codes
TOO_LONG = 2    # the step bound was reached
TOO_MANY = 3    # max_pieces would be exceeded
CYCLE = 4       # a cycle and splitting is off
UNCUT = 5       # a cycle neither plane cuts, nor a plane across the middle

# which array lacks room
ROOM_PIECES = 0
ROOM_VERTS = 1
ROOM_HEAP = 2
ROOM_ENTRIES = 3
ROOM_ROWS = 4
ROOM_OUT = 5
ROOM_BUCKETS = 6

# -- the trace tokens (:mod:`scanline._kernels.variants`): the sort alone, or compared
# with every surface alive and logged (step tables): only the variant used is compiled
SILENT = 1
LOGGED = 2
TRACE = {False: token(SILENT), True: token(LOGGED)}

# -- log rows: S, S', decided by (1-5; 0: every test failed), action, cut, by, new ----
NONE = 0
MOVE = 1
SPLIT = 2        # by the plane of ``by``
HALVE = 3        # by a plane across the middle of ``cut``


@helper
def heap_push(heap, n, fl, p):
    """Push piece ``p`` with its rank onto the heap of ``n`` entries (rank, piece);
    returns the new count."""
    i = n
    heap[i, 0] = fl[p, 10]
    heap[i, 1] = p
    while i > 0:
        up = (i - 1) // 2
        if heap[up, 0] < heap[i, 0] or (heap[up, 0] == heap[i, 0] and heap[up, 1] <= heap[i, 1]):
            break
        for c in range(2):
            tmp = heap[up, c]
            heap[up, c] = heap[i, c]
            heap[i, c] = tmp
        i = up
    return n + 1


@helper
def heap_pop(heap, n):
    """Remove the least entry of the heap of ``n``; returns the new count."""
    n -= 1
    heap[0, 0] = heap[n, 0]
    heap[0, 1] = heap[n, 1]
    i = 0
    while True:
        least = i
        for child in (2 * i + 1, 2 * i + 2):
            if child < n and (heap[child, 0] < heap[least, 0] or (
                    heap[child, 0] == heap[least, 0] and heap[child, 1] < heap[least, 1])):
                least = child
        if least == i:
            return n
        for c in range(2):
            tmp = heap[least, c]
            heap[least, c] = heap[i, c]
            heap[i, c] = tmp
        i = least


@helper
def cell_span(lo, hi, origin, size, count):
    """The first and last grid cell along one axis that the extent lo..hi meets
    (cells of ``size`` from ``origin``, ``count`` of them), clipped to the grid (a
    NaN or infinite extent to its first or last cell).  (np.floor of the quotient,
    not ``//``: numba's floor division goes through fmod, several times slower; any
    monotonic choice of cells finds the same overlapping boxes.)"""
    last = count - 1.0
    a = np.floor((lo - origin) / size)
    b = np.floor((hi - origin) / size)
    return int(min(a, last) if a >= 0.0 else 0.0), int(min(b, last) if b >= 0.0 else 0.0)


@helper
def cell_range(fl, p, grid):
    """The grid cells (i0, i1, j0, j1) that piece ``p``'s bounding box meets
    (:func:`cell_span`); ``grid`` is (x0, y0, cell, nx, ny)."""
    i0, i1 = cell_span(fl[p, 0], fl[p, 1], grid[0], grid[2], grid[3])
    j0, j1 = cell_span(fl[p, 2], fl[p, 3], grid[1], grid[2], grid[4])
    return i0, i1, j0, j1


@helper
def grid_add(cells, ent, ne, fl, p, grid):
    """List piece ``p`` in the cells it meets; returns the new entry count."""
    i0, i1, j0, j1 = cell_range(fl, p, grid)
    nx = int(grid[3])
    for j in range(j0, j1 + 1):
        for i in range(i0, i1 + 1):
            c = j * nx + i
            ent[ne, 0] = cells[c]
            ent[ne, 1] = p
            cells[c] = ne
            ne += 1
    return ne


@helper
def bucket(fl, byz, grid, first, low, cent, st):
    """Bucket the pieces given by the cells their boxes meet (a counting sort): cell
    ``c`` lists ``cent[first[c]:first[c + 1]]``, in the order of ``byz``, each entry
    the piece's xmin, xmax, ymin, ymax, zmax and the piece; ``low[c]`` starts at
    ``first[c]``; ``st[MAXCELLS]`` becomes the most cells of a piece.  Returns the
    entries needed; nothing is written to ``cent`` when it has fewer rows."""
    nx = int(grid[3])
    cells = low.shape[0]
    for c in range(cells + 1):
        first[c] = 0
    for r in range(byz.shape[0]):
        i0, i1, j0, j1 = cell_range(fl, byz[r], grid)
        st[MAXCELLS] = max(st[MAXCELLS], (i1 - i0 + 1) * (j1 - j0 + 1))
        for j in range(j0, j1 + 1):
            for i in range(i0, i1 + 1):
                first[j * nx + i + 1] += 1
    for c in range(cells):
        first[c + 1] += first[c]
        low[c] = first[c]
    if first[cells] > cent.shape[0]:
        return first[cells]
    for r in range(byz.shape[0]):
        p = byz[r]
        i0, i1, j0, j1 = cell_range(fl, p, grid)
        for j in range(j0, j1 + 1):
            for i in range(i0, i1 + 1):
                e = low[j * nx + i]
                for c in range(4):
                    cent[e, c] = fl[p, c]
                cent[e, 4] = fl[p, 5]
                cent[e, 5] = p
                low[j * nx + i] = e + 1
    for c in range(cells):
        low[c] = first[c]
    return first[cells]


@helper
def extents_apart(lo, hi, s_lo, s_hi, eps):
    """Whether the extents lo..hi and s_lo..s_hi do not overlap (by more than
    ``eps``): tests 1 and 2 on one axis."""
    return hi <= s_lo + eps or lo >= s_hi - eps


#: Lists longer than this are sorted by merging (:func:`scanline._kernels.sort.sort_keys`).
SHORT = 32


@helper
def by_key_short(cand, n, fl):
    """Sort ``cand[:n]`` by key (rank, number) by insertion (a short list)."""
    for i in range(1, n):
        q = cand[i]
        j = i
        while j > 0 and (fl[q, 10] < fl[cand[j - 1], 10] or (
                fl[q, 10] == fl[cand[j - 1], 10] and q < cand[j - 1])):
            cand[j] = cand[j - 1]
            j -= 1
        cand[j] = q


@helper
def by_key(cand, n, fl, keys, tkeys, titems):
    """Sort ``cand[:n]`` by key (rank, number): a short list by insertion
    (:func:`by_key_short`, which the kernel calls directly: this helper passes arrays
    on, and pays for counting their references), a long one by number and then
    stably by rank."""
    if n <= SHORT:
        by_key_short(cand, n, fl)
        return
    for i in range(n):
        keys[i] = cand[i]
    sort_keys(keys, cand, n, tkeys, titems)
    for i in range(n):
        keys[i] = fl[cand[i], 10]
    sort_keys(keys, cand, n, tkeys, titems)


@helper
def decide(pv, it, fl, s, t, eps):
    """Tests 3 to 5 for the pair (S, S') whose depths and boxes overlap: the number of
    the test that says yes, or 0 when all fail (S may hide S').  (It calls no helper:
    see the module's docstring.)"""
    for side in range(2):        # 3: S behind the plane of S'; 4: S' in front of S's
        p = s if side == 0 else t
        q = t if side == 0 else s
        sign = 1.0 if side == 0 else -1.0
        on = True
        for k in range(it[p, 0], it[p, 0] + it[p, 1]):
            d = pv[k, 0] * fl[q, 6] + pv[k, 1] * fl[q, 7] + pv[k, 2] * fl[q, 8] + fl[q, 9]
            if d * sign < -eps:
                on = False
                break
        if on:
            return 3 + side
    # 5: the projections are apart: some edge of one convex piece has all of the
    # other's (x, y) projection on its outer side (or within eps of it)
    for side in range(2):
        p = s if side == 0 else t
        q = t if side == 0 else s
        a0 = it[p, 0]
        n = it[p, 1]
        orient = fl[p, 11]
        for k in range(n):
            m = a0 + k + 1 if k + 1 < n else a0
            x0 = pv[a0 + k, 0]
            y0 = pv[a0 + k, 1]
            ex = pv[m, 0] - x0
            ey = pv[m, 1] - y0
            tol2 = eps * eps * (ex * ex + ey * ey)
            apart = True
            for j in range(it[q, 0], it[q, 0] + it[q, 1]):
                inner = (ex * (pv[j, 1] - y0) - ey * (pv[j, 0] - x0)) * orient
                if inner > 0.0 and inner * inner > tol2:
                    apart = False
                    break
            if apart:
                return 5
    return 0


@helper
def cut(pv, nv, it, p, plane, eps, min_area):
    """Split piece ``p`` by ``plane`` (Sutherland-Hodgman against the plane and its
    opposite) into a part in front written at ``pv[nv:]`` and a part behind after it.
    Returns (front count, behind count), or (0, 0) when the plane does not cut the
    piece or a part would have no area."""
    a0 = it[p, 0]
    k = it[p, 1]
    ahead = False
    back = False
    for i in range(k):
        d = pv[a0 + i, 0] * plane[0] + pv[a0 + i, 1] * plane[1] + pv[a0 + i, 2] * plane[2] \
            + plane[3]
        ahead = ahead or d < -eps
        back = back or d > eps
    if not (ahead and back):
        return 0, 0
    nf = np.int64(0)
    for side in range(2):            # in front: distance <= eps; behind: >= -eps
        start = nv + nf
        m = plane_part(pv, a0, k, plane, eps, -1.0 if side == 0 else 1.0, start)
        area = 0.0
        for i in range(m):
            j = start + i + 1 if i + 1 < m else start
            area += pv[start + i, 0] * pv[j, 1] - pv[j, 0] * pv[start + i, 1]
        if m < 3 or abs(0.5 * area) <= min_area:
            return 0, 0
        if side == 0:
            nf = m
        else:
            return nf, m
    return 0, 0


@helper
def new_piece(pv, start, n, fl, it, q, face, source):
    """Piece ``q``: the ``n`` vertices at ``pv[start:]``, lying in the plane of piece
    ``source``, of face ``face``; its extents computed."""
    it[q, 0] = start
    it[q, 1] = n
    it[q, 2] = face
    it[q, 3] = 1
    it[q, 4] = 0
    it[q, 5] = -1
    for c in range(3):
        lo = pv[start, c]
        hi = pv[start, c]
        for k in range(start + 1, start + n):
            lo = min(lo, pv[k, c])
            hi = max(hi, pv[k, c])
        fl[q, 2 * c] = lo
        fl[q, 2 * c + 1] = hi
    for c in range(4):
        fl[q, 6 + c] = fl[source, 6 + c]
    fl[q, 11] = fl[source, 11]           # clipping keeps the order of the vertices


@helper
def log_row(log, st, s, t, decided, action, piece, by, new):
    """Append a log row: the pair, the test that decided it (0: none), the action,
    and for a split the piece cut, the piece whose plane cut it (-1: a plane across
    the middle) and the first of the two new pieces."""
    r = st[ROWS]
    log[r, 0] = s
    log[r, 1] = t
    log[r, 2] = decided
    log[r, 3] = action
    log[r, 4] = piece
    log[r, 5] = by
    log[r, 6] = new
    st[ROWS] = r + 1


@helper
def split_pair(pv, fl, it, heap, cells, ent, st, grid, s, t, eps, min_area, limit, plane,
               log, trace):
    """Resolve the flagged pair (S, S'): split S' by the plane of S, else S by the plane
    of S', else the wider on screen across its middle; the pieces take the place of the
    surface split.  Returns a status code."""
    for attempt in range(3):
        if attempt == 0:
            p = t
            by = s
        elif attempt == 1:
            p = s
            by = t
        else:
            ws = max(fl[s, 1] - fl[s, 0], fl[s, 3] - fl[s, 2])
            wt = max(fl[t, 1] - fl[t, 0], fl[t, 3] - fl[t, 2])
            p = s if ws >= wt else t
            by = -1
        if by >= 0:
            for c in range(4):
                plane[c] = fl[by, 6 + c]
        else:
            wide = fl[p, 1] - fl[p, 0] >= fl[p, 3] - fl[p, 2]
            plane[0] = 1.0 if wide else 0.0
            plane[1] = 0.0 if wide else 1.0
            plane[2] = 0.0
            plane[3] = -0.5 * (fl[p, 0] + fl[p, 1]) if wide else -0.5 * (fl[p, 2] + fl[p, 3])
        nv = st[VERTS]
        nf, nb = cut(pv, nv, it, p, plane, eps, min_area)
        if nf == 0:
            continue
        if st[PIECES] + 2 > limit:
            return TOO_MANY
        q = st[PIECES]
        new_piece(pv, nv, nf, fl, it, q, it[p, 2], p)
        new_piece(pv, nv + nf, nb, fl, it, q + 1, it[p, 2], p)
        if fl[q + 1, 5] > fl[q, 5]:          # the farther piece first
            for c in range(6):
                tmp = fl[q, c]
                fl[q, c] = fl[q + 1, c]
                fl[q + 1, c] = tmp
            for c in range(2):
                tmp2 = it[q, c]
                it[q, c] = it[q + 1, c]
                it[q + 1, c] = tmp2
        st[PIECES] = q + 2
        st[VERTS] = nv + nf + nb
        st[MAXK] = max(st[MAXK], max(nf, nb))
        if len(trace) == LOGGED:
            log_row(log, st, s, t, np.int64(0), np.int64(SPLIT if by >= 0 else HALVE), p,
                    by, q)
        for r in (q, q + 1):
            fl[r, 10] = fl[p, 10]
            st[HEAP] = heap_push(heap, st[HEAP], fl, r)
            ne = grid_add(cells, ent, st[ENTRIES], fl, r, grid)
            st[MAXCELLS] = max(st[MAXCELLS], ne - st[ENTRIES])
            st[ENTRIES] = ne
        it[p, 3] = 0
        it[p, 4] = 0
        st[ALIVE] += 1
        return DONE
    st[S] = s
    st[T] = t
    return UNCUT


@kernel
def depth_sort(pv, fl, it, heap, cells, ent, grid, first, low, cent, byz, order, out,
               cand, keys, tkeys, titems, log, plane, st, eps, min_area, limit, max_steps,
               split_cycles, trace):
    """Run (or resume) the depth sort: pieces go to ``order`` as they are painted, and
    their vertices to ``out``.  ``byz``: the pieces given, by decreasing greatest
    depth (the initial list; in the grid, :func:`bucket`, they are cut off where the
    sort has not reached their depths); ``cells``, ``ent``: the split pieces linked
    in the grid cells; ``limit``: most pieces in all; ``max_steps``: the loop bound;
    ``trace``: a :data:`TRACE` token (LOGGED: compare with every surface alive and
    log each pair).  Returns the status (also in ``st[STATUS]``)."""
    none = np.int64(NONE)         # typed, not literal, arguments of log_row
    nil = np.int64(-1)
    if st[BUCKETED] == 0:
        st[BUCKETS] = bucket(fl, byz, grid, first, low, cent, st)
        if st[BUCKETS] > cent.shape[0]:
            st[STATUS] = NEED_ROOM
            st[T] = ROOM_BUCKETS
            return NEED_ROOM
        st[BUCKETED] = 1
    while st[ALIVE] > 0:
        short = -1                   # which array lacks room for one more step
        if st[PIECES] + 2 > fl.shape[0]:
            short = ROOM_PIECES
        elif st[VERTS] + 4 * st[MAXK] > pv.shape[0]:   # each part: <= k vertices, k cuts
            short = ROOM_VERTS
        elif st[HEAP] + 2 > heap.shape[0]:
            short = ROOM_HEAP
        elif st[ENTRIES] + 2 * st[MAXCELLS] > ent.shape[0]:
            short = ROOM_ENTRIES
        elif len(trace) == LOGGED and st[ROWS] + st[ALIVE] + 1 > log.shape[0]:
            short = ROOM_ROWS
        elif st[OUT] + st[MAXK] > out.shape[0]:
            short = ROOM_OUT
        if short >= 0:
            st[STATUS] = NEED_ROOM
            st[T] = short
            return NEED_ROOM
        st[STEPS] += 1
        if st[STEPS] > max_steps:
            st[STATUS] = TOO_LONG
            return TOO_LONG
        while st[LIST] < byz.shape[0]:   # the head: the least key (rank, piece) alive
            p = byz[st[LIST]]            # (stale entries off): the front of ``byz``,
            if it[p, 3] == 1 and fl[p, 10] == st[LIST]:
                break
            st[LIST] += 1
        while st[HEAP] > 0:              # or of the heap of moved and split pieces
            h = int(heap[0, 1])
            if it[h, 3] == 1 and heap[0, 0] == fl[h, 10]:
                break
            st[HEAP] = heap_pop(heap, st[HEAP])
        s = byz[min(st[LIST], byz.shape[0] - 1)]
        if st[HEAP] > 0 and (st[LIST] == byz.shape[0] or heap[0, 0] < fl[s, 10] or (
                heap[0, 0] == fl[s, 10] and heap[0, 1] < s)):
            s = int(heap[0, 1])
        st[STAMP] += 1
        stamp = st[STAMP]
        x0 = fl[s, 0]
        x1 = fl[s, 1]
        y0 = fl[s, 2]
        y1 = fl[s, 3]
        near = fl[s, 4] + eps            # S' reaching no farther lies wholly in front
        m = np.int64(0)
        if len(trace) == LOGGED:
            n = np.int64(0)
            for q in range(st[PIECES]):
                if q != s and it[q, 3] == 1:
                    cand[n] = q
                    n += 1
            by_key(cand, n, fl, keys, tkeys, titems)
            # the pairs whose depths overlap (S' not wholly in front of S) by the boxes
            for i in range(n):
                q = cand[i]
                if fl[q, 5] <= near:
                    continue
                if extents_apart(fl[q, 0], fl[q, 1], x0, x1, eps):
                    log_row(log, st, s, q, np.int64(1), none, nil, nil, nil)
                elif extents_apart(fl[q, 2], fl[q, 3], y0, y1, eps):
                    log_row(log, st, s, q, np.int64(2), none, nil, nil, nil)
                else:
                    cand[m] = q
                    m += 1
        else:       # the pieces alive sharing a cell with S whose depths and boxes
            # overlap its own (written out here: see the module's docstring)
            i0, i1, j0, j1 = cell_range(fl, s, grid)
            for j in range(j0, j1 + 1):
                for i in range(i0, i1 + 1):
                    c = j * int(grid[3]) + i
                    # the pieces given (bucket): the painted ones at the front leave
                    # the cell; read up to the first that lies wholly in front of S
                    e = low[c]
                    while e < first[c + 1] and cent[e, 4] > near and it[int(cent[e, 5]),
                                                                         3] == 0:
                        e += 1
                    low[c] = e
                    while e < first[c + 1] and cent[e, 4] > near:
                        q = int(cent[e, 5])
                        if not (extents_apart(cent[e, 0], cent[e, 1], x0, x1, eps)
                                or extents_apart(cent[e, 2], cent[e, 3], y0, y1, eps)) and (
                                it[q, 3] == 1 and q != s and it[q, 5] != stamp):
                            it[q, 5] = stamp
                            cand[m] = q
                            m += 1
                        e += 1
                    # the pieces of splits, linked (dead ones unlinked)
                    prev = -1
                    e = cells[c]
                    while e >= 0:
                        q = ent[e, 1]
                        nxt = ent[e, 0]
                        if it[q, 3] == 0:
                            if prev < 0:
                                cells[c] = nxt
                            else:
                                ent[prev, 0] = nxt
                        else:
                            if q != s and it[q, 5] != stamp and fl[q, 5] > near and not (
                                    extents_apart(fl[q, 0], fl[q, 1], x0, x1, eps)
                                    or extents_apart(fl[q, 2], fl[q, 3], y0, y1, eps)):
                                it[q, 5] = stamp
                                cand[m] = q
                                m += 1
                            prev = e
                        e = nxt
            if m <= SHORT:
                by_key_short(cand, m, fl)
            else:
                by_key(cand, m, fl, keys, tkeys, titems)
        mover = -1
        for i in range(m):
            q = cand[i]
            decided = decide(pv, it, fl, s, q, eps)
            if decided == 0:
                mover = q
                break
            if len(trace) == LOGGED:
                log_row(log, st, s, q, decided, none, nil, nil, nil)
        if mover < 0:                # S hides nothing behind it: paint it
            order[st[DRAWN]] = s
            st[DRAWN] += 1
            for k in range(it[s, 0], it[s, 0] + it[s, 1]):
                for c in range(3):
                    out[st[OUT], c] = pv[k, c]
                st[OUT] += 1
            it[s, 3] = 0
            it[s, 4] = 0
            st[ALIVE] -= 1
            continue
        t = mover
        if it[t, 4] == 0:            # move S' to the head of the list and flag it
            if len(trace) == LOGGED:
                log_row(log, st, s, t, none, np.int64(MOVE), nil, nil, nil)
            it[t, 4] = 1
            fl[t, 10] = float(st[LOW])
            st[LOW] -= 1
            st[HEAP] = heap_push(heap, st[HEAP], fl, t)
            continue
        if not split_cycles:
            st[S] = s
            st[T] = t
            st[STATUS] = CYCLE
            return CYCLE
        status = split_pair(pv, fl, it, heap, cells, ent, st, grid, s, t, eps, min_area,
                            limit, plane, log, trace)
        if status != DONE:
            st[S] = s
            st[T] = t
            st[STATUS] = status
            return status
    st[STATUS] = DONE
    return DONE
