"""The depth-sorting method (Newell, Newell and Sancha 1972; Hearn & Baker, section
13-6) as one resumable kernel: the list sorted by greatest depth, the five overlap
tests, reordering with the loop flag, and splitting.

The list is ordered by keys (rank, piece): the head of the list is the least key
alive; moving a surface to the head gives it a rank below every other; the two
pieces of a split surface take its rank (the farther piece gets the lower number, so
it comes first).  :func:`prepare` numbers the pieces given by their rank in the
initial sort (so that surfaces near in depth lie near in memory; ``byz`` maps the
numbers back), and they keep their ranks, read from a cursor; moved and split
pieces go to a binary heap of (rank, piece), and the head is the lesser of the two
fronts (stale entries are skipped).  The numbering changes no order: the keys of
the pieces given are distinct, and the pieces of splits are numbered after them in
the order they are made, as before.

A uniform grid over the screen lists the pieces whose bounding boxes meet each cell,
so that the surfaces compared with the head are found among those sharing its cells
(or, for a step table, among every surface alive).  The pieces given are bucketed
once (:func:`bucket`), each cell's by rank with their boxes and
greatest depths beside them: a cell is read in sequence, up to the first surface
that lies wholly in front of the head (the rest of the cell lies in front too, and
cannot fail the tests against it).  The pieces of splits are linked into the cells
as they are made.  Painted surfaces leave the cells as the cells are read.

When S has moved a surface to the head (or split one), it is compared again later
with the same surfaces: the step keeps S's list of surfaces to compare with, in the
order compared, those that passed the tests marked (a *memo* in ``memo``, rows
``it[S, 4:8]``).  When S is at the head again, its list is the memo's surfaces still
alive and the pieces made since that share its box and depth (geometry does not
change, surfaces only die), and those that passed are not tested again (the tests
depend on the two polygons alone): the same pairs, in the same order, decided the
same way, without reading the grid.  The pieces of a split surface inherit its memo
(those that lie within its box and depth, in floats): a piece's surfaces to compare
with are among the surface's and the pieces made since, filtered by the piece's own
box and depth, and tested anew.  The step tables (LOGGED) keep no memo.

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
holds the first vertex in ``pv`` and the vertex count (0, 1), the face (2), flagged
(3), and its memo: first entry in ``memo`` (-1: none), entry count, the piece
count when it was written and the piece whose memo it is (its own, or that of the
surface it was split from: 4-7); ``tag[p]`` is :data:`DEAD` once it is painted or
split, else the stamp of the last step that listed it (or, in a step that reads a
memo, that found it passed): one compact array read for every entry of the grid's
cells, apart from the wider rows of ``it``.
"""

import numpy as np

from ._jit import helper, kernel, slow_to_compile
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
LIST = 16       # the first piece given that may still be alive with its rank
BUCKETED = 17   # 1 once the pieces given are bucketed in the grid
BUCKETS = 18    # entries of the buckets (rows of ``cent`` needed)
MEMO = 19       # memo entries used
GIVEN = 20      # the pieces given (numbered 0 .. GIVEN - 1 by rank)
PAUSE = 21      # pause once this many pieces are in drawing order (0: never)
WORK = 22       # surfaces compared so far (one more a step): the work bound's count
STATE = 23

#: Columns of ``it``.
IT = 8

#: ``tag`` of a piece painted or split (alive: the stamp of the last step that listed
#: it, -1 before any).
DEAD = -2

#: At most this many cells a side in the grid (:func:`prepare`).
GRID = 1000

#: A memo is used while at most this many pieces were made since it was written
#: (each is compared with S directly); beyond, the grid is read.
MEMO_NEW = 32

# -- status codes ------------------------------------------------------------------------
DONE = 0
NEED_ROOM = 1   # st[T] says which array: one of the ROOM codes
TOO_LONG = 2    # the work bound was reached
TOO_MANY = 3    # max_pieces would be exceeded
CYCLE = 4       # a cycle and splitting is off
UNCUT = 5       # a cycle neither plane cuts, nor a plane across the middle
PAUSED = 6      # st[PAUSE] pieces are in drawing order: call again to go on

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
def cell_span(lo, hi, origin, inverse, count):
    """The first and last grid cell along one axis that the extent lo..hi meets
    (cells of 1 / ``inverse`` from ``origin``, ``count`` of them), clipped to the
    grid (a NaN or infinite extent to its first or last cell).  (np.floor of the
    product, not ``//`` nor a quotient: numba's floor division goes through fmod,
    and a division is slower than a product; any monotonic choice of cells finds the
    same overlapping boxes.)"""
    last = count - 1.0
    a = np.floor((lo - origin) * inverse)
    b = np.floor((hi - origin) * inverse)
    return int(min(a, last) if a >= 0.0 else 0.0), int(min(b, last) if b >= 0.0 else 0.0)


@helper
def cell_range(fl, p, grid):
    """The grid cells (i0, i1, j0, j1) that piece ``p``'s bounding box meets
    (:func:`cell_span`); ``grid`` is (x0, y0, cell, nx, ny, 1 / cell)."""
    i0, i1 = cell_span(fl[p, 0], fl[p, 1], grid[0], grid[5], grid[3])
    j0, j1 = cell_span(fl[p, 2], fl[p, 3], grid[1], grid[5], grid[4])
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
def bucket(fl, n, grid, first, low, cent, st):
    """Bucket the ``n`` pieces given by the cells their boxes meet (a counting sort):
    cell ``c`` lists ``cent[first[c]:first[c + 1]]``, by rank (number), each entry
    the piece's xmin, xmax, ymin, ymax, zmax and the piece; ``low[c]`` starts at
    ``first[c]``; ``st[MAXCELLS]`` becomes the most cells of a piece.  Returns the
    entries needed; nothing is written to ``cent`` when it has fewer rows."""
    nx = int(grid[3])
    cells = low.shape[0]
    for c in range(cells + 1):
        first[c] = 0
    for r in range(n):
        i0, i1, j0, j1 = cell_range(fl, r, grid)
        st[MAXCELLS] = max(st[MAXCELLS], (i1 - i0 + 1) * (j1 - j0 + 1))
        for j in range(j0, j1 + 1):
            for i in range(i0, i1 + 1):
                first[j * nx + i + 1] += 1
    for c in range(cells):
        first[c + 1] += first[c]
        low[c] = first[c]
    if first[cells] > cent.shape[0]:
        return first[cells]
    for p in range(n):
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
    see the module's docstring; unsigned indices: no test for negative ones.)"""
    one = np.uint64(1)
    for side in range(2):        # 3: S behind the plane of S'; 4: S' in front of S's
        p = np.uint64(s if side == 0 else t)
        q = np.uint64(t if side == 0 else s)
        sign = 1.0 if side == 0 else -1.0
        a = fl[q, 6]
        b = fl[q, 7]
        c = fl[q, 8]
        d0 = fl[q, 9]
        k = np.uint64(it[p, 0])
        end = k + np.uint64(it[p, 1])
        on = True
        while k < end:
            d = pv[k, 0] * a + pv[k, 1] * b + pv[k, 2] * c + d0
            if d * sign < -eps:
                on = False
                break
            k += one
        if on:
            return 3 + side
    # 5: the projections are apart: some edge of one convex piece has all of the
    # other's (x, y) projection on its outer side (or within eps of it)
    for side in range(2):
        p = np.uint64(s if side == 0 else t)
        q = np.uint64(t if side == 0 else s)
        a0 = np.uint64(it[p, 0])
        n = np.uint64(it[p, 1])
        b0 = np.uint64(it[q, 0])
        b1 = b0 + np.uint64(it[q, 1])
        orient = fl[p, 11]
        k = np.uint64(0)
        while k < n:
            m = a0 + k + one if k + one < n else a0
            x0 = pv[a0 + k, 0]
            y0 = pv[a0 + k, 1]
            ex = pv[m, 0] - x0
            ey = pv[m, 1] - y0
            tol2 = eps * eps * (ex * ex + ey * ey)
            apart = True
            j = b0
            while j < b1:
                inner = (ex * (pv[j, 1] - y0) - ey * (pv[j, 0] - x0)) * orient
                if inner > 0.0 and inner * inner > tol2:
                    apart = False
                    break
                j += one
            if apart:
                return 5
            k += one
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
    it[q, 3] = 0
    it[q, 4] = -1
    it[q, 5] = 0
    it[q, 6] = 0
    it[q, 7] = -1
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
def split_pair(pv, fl, it, tag, heap, cells, ent, st, grid, s, t, eps, min_area, limit,
               plane, log, trace):
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
        tag[q] = -1
        tag[q + 1] = -1
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
            # a piece lies within the surface split: its surfaces to compare with are
            # among the surface's (its memo) and the pieces made since, when its box
            # and depth lie within the surface's in floats too
            if it[p, 4] >= 0 and fl[r, 0] >= fl[p, 0] and fl[r, 1] <= fl[p, 1] and (
                    fl[r, 2] >= fl[p, 2] and fl[r, 3] <= fl[p, 3] and fl[r, 4] >= fl[p, 4]):
                for c in range(4, 8):
                    it[r, c] = it[p, c]
            fl[r, 10] = fl[p, 10]
            st[HEAP] = heap_push(heap, st[HEAP], fl, r)
            ne = grid_add(cells, ent, st[ENTRIES], fl, r, grid)
            st[MAXCELLS] = max(st[MAXCELLS], ne - st[ENTRIES])
            st[ENTRIES] = ne
        tag[p] = DEAD
        it[p, 3] = 0
        st[ALIVE] += 1
        return DONE
    st[S] = s
    st[T] = t
    return UNCUT


@helper
def pairwise_sum(t, a, n):
    """The sum of ``t[a:a + n]`` added as numpy's pairwise summation adds up to 128
    terms (runs of fewer than 8 in sequence, blocks with 8 partial sums), so that the
    orientation here is the sign numpy's ``add.reduceat`` gave (polygons of up to 129
    vertices; longer ones are summed block after block: their orientation is the sign
    of an area far from zero, whose rounding cannot change it)."""
    res = 0.0
    if n < 8:
        for i in range(a, a + n):
            res += t[i]
        return res
    done = 0
    while done < n:
        m = min(n - done, 128)
        b = a + done
        if m < 8:
            part = 0.0
            for i in range(b, b + m):
                part += t[i]
        else:
            r0 = t[b]
            r1 = t[b + 1]
            r2 = t[b + 2]
            r3 = t[b + 3]
            r4 = t[b + 4]
            r5 = t[b + 5]
            r6 = t[b + 6]
            r7 = t[b + 7]
            i = 8
            while i < m - m % 8:
                r0 += t[b + i]
                r1 += t[b + i + 1]
                r2 += t[b + i + 2]
                r3 += t[b + i + 3]
                r4 += t[b + i + 4]
                r5 += t[b + i + 5]
                r6 += t[b + i + 6]
                r7 += t[b + i + 7]
                i += 8
            part = ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7))
            while i < m:
                part += t[b + i]
                i += 1
        res = part if done == 0 else res + part
        done += m
    return res


@kernel
def prepare(verts, offsets, planes, face, fl, it, tag, pv, byz, keys, tkeys, titems, grid,
            st):
    """The pieces given, numbered by rank: sorted by decreasing greatest depth (stably),
    piece ``r`` is polygon ``byz[r]``: its extents, normalized plane, rank and
    orientation in ``fl[r]``, its vertices copied to ``pv`` in that order, ``it[r]``
    set (alive, no memo).  Then the grid of the candidate search in ``grid`` (x0, y0,
    cell, nx, ny, 1 / cell: cells of twice the median piece size, at most
    :data:`GRID` a side; one cell when the extents are too large to subtract), and
    in ``st`` the pieces, vertices, most vertices of a piece, grid entries of the
    pieces (BUCKETS) and most cells of a piece."""
    n = offsets.shape[0] - 1
    nv = offsets[n]
    for p in range(n):
        hi = verts[offsets[p], 2]
        for k in range(offsets[p] + 1, offsets[p + 1]):
            hi = max(hi, verts[k, 2])
        keys[p] = -hi
    by_depth(keys, n, byz, titems)
    # the orientation: the sign of the (x, y) area, summed as numpy sums it
    terms = np.empty(max(nv, 1))
    for p in range(n):
        a = offsets[p]
        b = offsets[p + 1]
        for k in range(a, b):
            j = k + 1 if k + 1 < b else a
            terms[k] = verts[k, 0] * verts[j, 1] - verts[j, 0] * verts[k, 1]
    at = np.int64(0)
    most = np.int64(0)
    for r in range(n):
        p = byz[r]
        a = offsets[p]
        b = offsets[p + 1]
        for c in range(3):
            lo = verts[a, c]
            hi = verts[a, c]
            for k in range(a + 1, b):
                lo = min(lo, verts[k, c])
                hi = max(hi, verts[k, c])
            fl[r, 2 * c] = lo
            fl[r, 2 * c + 1] = hi
        norm = np.sqrt((planes[p, 0] * planes[p, 0] + planes[p, 1] * planes[p, 1])
                       + planes[p, 2] * planes[p, 2])
        if not norm > 0.0:
            norm = 1.0
        for c in range(4):
            fl[r, 6 + c] = planes[p, c] / norm
        fl[r, 10] = float(r)
        area = terms[a] + pairwise_sum(terms, a + 1, b - a - 1)
        fl[r, 11] = 1.0 if area > 0.0 else -1.0
        it[r, 0] = at
        it[r, 1] = b - a
        it[r, 2] = face[p]
        it[r, 3] = 0
        it[r, 4] = -1
        it[r, 5] = 0
        it[r, 6] = 0
        it[r, 7] = -1
        tag[r] = -1
        for k in range(a, b):
            for c in range(3):
                pv[at, c] = verts[k, c]
            at += 1
        most = max(most, b - a)
    # the grid: the median size of at most 255 pieces, evenly spread
    x0 = np.inf
    y0 = np.inf
    x1 = -np.inf
    y1 = -np.inf
    for r in range(n):
        x0 = min(x0, fl[r, 0])
        x1 = max(x1, fl[r, 1])
        y0 = min(y0, fl[r, 2])
        y1 = max(y1, fl[r, 3])
    m = min(n, 255)
    for i in range(m):
        r = i * n // m
        keys[i] = max(fl[r, 1] - fl[r, 0], fl[r, 3] - fl[r, 2])
        titems[i] = i
    by_size(keys, m)
    wide = x1 - x0
    high = y1 - y0
    cell = max(keys[m // 2] * 2.0, max(wide, high) / GRID, 1e-6) if m > 0 else 1.0
    grid[0] = x0
    grid[1] = y0
    if not (np.isfinite(cell) and np.isfinite(x0) and np.isfinite(y0)):
        grid[2] = np.inf
        grid[3] = 1.0
        grid[4] = 1.0
        grid[5] = 0.0
    else:
        grid[2] = cell
        grid[3] = np.floor(wide / cell) + 1.0
        grid[4] = np.floor(high / cell) + 1.0
        grid[5] = 1.0 / cell
    total = np.int64(0)
    widest = np.int64(1)
    for r in range(n):
        i0, i1, j0, j1 = cell_range(fl, r, grid)
        cells = (i1 - i0 + 1) * (j1 - j0 + 1)
        total += cells
        widest = max(widest, cells)
    st[PIECES] = n
    st[VERTS] = nv
    st[ALIVE] = n
    st[GIVEN] = n
    st[LOW] = -1
    st[MAXK] = most
    st[MAXCELLS] = widest
    st[BUCKETS] = total


#: Bits of a digit of :func:`by_depth`'s radix sort.
DIGIT = 11


@helper
def by_depth(keys, n, order, tmp):
    """``order[:n]``: 0 .. n - 1 sorted stably by ``keys[:n]`` ascending (as
    ``np.argsort(keys[:n], kind="stable")``: finite keys, -0.0 equal to 0.0), by a
    radix sort of their bits on digits of :data:`DIGIT` bits (the digits where all
    keys agree are skipped): no comparison to mispredict, where merging random
    depths costs a mispredicted branch an element.  ``keys`` is overwritten."""
    bits = keys[:n].view(np.uint64)
    top = np.uint64(1) << np.uint64(63)
    for i in range(n):
        keys[i] = keys[i] + 0.0              # -0.0 to 0.0
        b = bits[i]
        bits[i] = ~b if b & top else b | top   # the floats' order as unsigned ints
        order[i] = i
    size = 1 << DIGIT
    passes = (64 + DIGIT - 1) // DIGIT
    counts = np.zeros((passes, size + 1), np.int64)
    mask = np.uint64(size - 1)
    for i in range(n):
        b = bits[i]
        for d in range(passes):
            counts[d, ((b >> np.uint64(d * DIGIT)) & mask) + np.uint64(1)] += 1
    swapped = False                          # the order is in tmp
    for d in range(passes):
        shift = np.uint64(d * DIGIT)
        if counts[d, ((bits[0] >> shift) & mask) + np.uint64(1)] == n:
            continue                         # every key has this digit
        for c in range(size):
            counts[d, c + 1] += counts[d, c]
        for i in range(n):
            j = tmp[i] if swapped else order[i]
            c = (bits[j] >> shift) & mask
            if swapped:
                order[counts[d, c]] = j
            else:
                tmp[counts[d, c]] = j
            counts[d, c] += 1
        swapped = not swapped
    if swapped:
        for i in range(n):
            order[i] = tmp[i]


@helper
def by_size(keys, m):
    """Sort ``keys[:m]`` ascending by insertion (the grid's sample of sizes)."""
    for i in range(1, m):
        k = keys[i]
        j = i
        while j > 0 and keys[j - 1] > k:
            keys[j] = keys[j - 1]
            j -= 1
        keys[j] = k


@kernel
def depth_sort(pv, fl, it, tag, heap, cells, ent, grid, first, low, cent, dface, dplane,
               doff, out, cand, keys, tkeys, titems, memo, log, plane, st, eps, min_area,
               limit, max_work, split_cycles, trace):
    """Run (or resume) the depth sort on the pieces :func:`prepare` set: the pieces
    painted go to ``dface``, ``dplane`` (their faces and planes) and their vertices
    to ``out`` (piece ``d`` from ``doff[d]`` to ``doff[d + 1]``); ``cells``, ``ent``:
    the split pieces linked in the grid cells; ``memo``: the memo entries;
    ``limit``: most pieces in all; ``max_work``: the most surfaces all the steps
    may gather to compare with their heads (``st[WORK]``: one more per step), the
    bound of the sort's time however tangled the scene; ``trace``: a
    :data:`TRACE` token (LOGGED: compare with every surface alive and log each pair).
    Returns the status (also in ``st[STATUS]``): :data:`PAUSED` when the piece just
    put in drawing order is the ``st[PAUSE]``-th and others remain (the caller may
    paint the pieces ordered so far while the sort goes on, and calls again)."""
    none = np.int64(NONE)         # typed, not literal, arguments of log_row
    nil = np.int64(-1)
    given = st[GIVEN]
    if st[BUCKETED] == 0:
        st[BUCKETS] = bucket(fl, given, grid, first, low, cent, st)
        if st[BUCKETS] > cent.shape[0]:
            st[STATUS] = NEED_ROOM
            st[T] = ROOM_BUCKETS
            return NEED_ROOM
        st[BUCKETED] = 1
    nx = int(grid[3])
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
        st[WORK] += 1
        if st[WORK] > max_work:
            st[STATUS] = TOO_LONG
            return TOO_LONG
        while st[LIST] < given:          # the head: the least key (rank, piece) alive
            p = st[LIST]                 # (stale entries off): the first piece given
            if tag[p] != DEAD and fl[p, 10] == p:    # alive with its rank,
                break
            st[LIST] += 1
        while st[HEAP] > 0:              # or of the heap of moved and split pieces
            h = int(heap[0, 1])
            if tag[h] != DEAD and heap[0, 0] == fl[h, 10]:
                break
            st[HEAP] = heap_pop(heap, st[HEAP])
        s = min(st[LIST], given - 1)
        if st[HEAP] > 0 and (st[LIST] == given or heap[0, 0] < fl[s, 10] or (
                heap[0, 0] == fl[s, 10] and heap[0, 1] < s)):
            s = int(heap[0, 1])
        st[STAMP] += 1
        stamp = st[STAMP]
        x0 = fl[s, 0]
        x1 = fl[s, 1]
        y0 = fl[s, 2]
        y1 = fl[s, 3]
        xa = x0 + eps                    # S' overlaps S's box: xmax > xa, xmin < xb,
        xb = x1 - eps                    # ymax > ya, ymin < yb (tests 1 and 2 fail)
        ya = y0 + eps
        yb = y1 - eps
        near = fl[s, 4] + eps            # S' reaching no farther lies wholly in front
        m = np.int64(0)
        own = False
        recall = len(trace) != LOGGED and it[s, 4] >= 0 and (
            st[PIECES] - it[s, 6] <= MEMO_NEW)
        if len(trace) == LOGGED:
            n = np.int64(0)
            for q in range(st[PIECES]):
                if q != s and tag[q] != DEAD:
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
        elif recall:    # S's memo: its surfaces still alive (those that passed marked
            # with this stamp) and the pieces made since that overlap S; a memo
            # inherited from the surface S was split from: those that overlap S
            own = it[s, 7] == s
            for e in range(it[s, 4], it[s, 4] + it[s, 5]):
                v = memo[e]
                q = v if v >= 0 else -1 - v
                if tag[q] != DEAD and (own or (q != s and fl[q, 5] > near and not (
                        (fl[q, 1] <= xa) | (fl[q, 0] >= xb) | (fl[q, 3] <= ya)
                        | (fl[q, 2] >= yb)))):
                    if v < 0 and own:
                        tag[q] = stamp
                    cand[m] = q
                    m += 1
            for q in range(it[s, 6], st[PIECES]):
                if tag[q] != DEAD and q != s and fl[q, 5] > near and not (
                        (fl[q, 1] <= xa) | (fl[q, 0] >= xb) | (fl[q, 3] <= ya)
                        | (fl[q, 2] >= yb)):
                    cand[m] = q
                    m += 1
        else:       # the pieces alive sharing a cell with S whose depths and boxes
            # overlap its own (written out here: see the module's docstring)
            i0, i1, j0, j1 = cell_range(fl, s, grid)
            for j in range(j0, j1 + 1):
                for i in range(i0, i1 + 1):
                    c = j * nx + i
                    # the pieces given (bucket): the painted ones at the front leave
                    # the cell; read up to the first that lies wholly in front of S
                    # (unsigned indices: no test for negative ones)
                    uc = np.uint64(c)
                    e = np.uint64(low[uc])
                    end = np.uint64(first[uc + np.uint64(1)])
                    while e < end and cent[e, 4] > near and tag[np.uint64(int(
                            cent[e, 5]))] == DEAD:
                        e += np.uint64(1)
                    low[uc] = np.int64(e)
                    um = np.uint64(m)
                    while e < end:
                        if cent[e, 4] <= near:
                            break
                        q = int(cent[e, 5])
                        uq = np.uint64(q)
                        seen = tag[uq]
                        apart = ((cent[e, 1] <= xa) | (cent[e, 0] >= xb)
                                 | (cent[e, 3] <= ya) | (cent[e, 2] >= yb))
                        ok = (not apart) & (seen != DEAD) & (q != s) & (seen != stamp)
                        tag[uq] = stamp if ok else seen
                        cand[um] = q
                        um += np.uint64(ok)
                        e += np.uint64(1)
                    m = np.int64(um)
                    # the pieces of splits, linked (dead ones unlinked)
                    prev = -1
                    e = cells[c]
                    while e >= 0:
                        q = ent[e, 1]
                        nxt = ent[e, 0]
                        if tag[q] == DEAD:
                            if prev < 0:
                                cells[c] = nxt
                            else:
                                ent[prev, 0] = nxt
                        else:
                            if q != s and tag[q] != stamp and fl[q, 5] > near and not (
                                    (fl[q, 1] <= xa) | (fl[q, 0] >= xb) | (fl[q, 3] <= ya)
                                    | (fl[q, 2] >= yb)):
                                tag[q] = stamp
                                cand[m] = q
                                m += 1
                            prev = e
                        e = nxt
        st[WORK] += m
        if len(trace) != LOGGED:
            if m <= SHORT:
                by_key_short(cand, m, fl)
            else:
                by_key(cand, m, fl, keys, tkeys, titems)
        mover = -1
        at = m
        for i in range(m):
            q = cand[i]
            if recall and own and tag[q] == stamp:
                continue                 # passed when S was compared with it before
            decided = decide(pv, it, fl, s, q, eps)
            if decided == 0:
                mover = q
                at = i
                break
            if len(trace) == LOGGED:
                log_row(log, st, s, q, decided, none, nil, nil, nil)
        if mover < 0:                # S hides nothing behind it: paint it
            d = st[DRAWN]
            dface[d] = it[s, 2]
            for c in range(4):
                dplane[d, c] = fl[s, 6 + c]
            o = max(st[OUT], 0)          # (clamped: no test for a negative index)
            k0 = max(it[s, 0], 0)
            for k in range(k0, k0 + it[s, 1]):
                for c in range(3):
                    out[o, c] = pv[k, c]
                o += 1
            st[OUT] = o
            doff[d + 1] = o
            st[DRAWN] = d + 1
            tag[s] = DEAD
            it[s, 3] = 0
            st[ALIVE] -= 1
            if d + 1 == st[PAUSE] and st[ALIVE] > 0:
                st[STATUS] = PAUSED
                return PAUSED
            continue
        if len(trace) != LOGGED:     # S's memo: those before the mover passed
            if st[MEMO] + m <= memo.shape[0]:
                e0 = st[MEMO]
                for i in range(m):
                    memo[e0 + i] = -1 - cand[i] if i < at else cand[i]
                it[s, 4] = e0
                it[s, 5] = m
                it[s, 6] = st[PIECES]
                it[s, 7] = s
                st[MEMO] = e0 + m
            else:
                it[s, 4] = -1
        t = mover
        if it[t, 3] == 0:            # move S' to the head of the list and flag it
            if len(trace) == LOGGED:
                log_row(log, st, s, t, none, np.int64(MOVE), nil, nil, nil)
            it[t, 3] = 1
            fl[t, 10] = float(st[LOW])
            st[LOW] -= 1
            st[HEAP] = heap_push(heap, st[HEAP], fl, t)
            continue
        if not split_cycles:
            st[S] = s
            st[T] = t
            st[STATUS] = CYCLE
            return CYCLE
        status = split_pair(pv, fl, it, tag, heap, cells, ent, st, grid, s, t, eps,
                            min_area, limit, plane, log, trace)
        if status != DONE:
            st[S] = s
            st[T] = t
            st[STATUS] = status
            return status
    st[STATUS] = DONE
    return DONE


#: The depth sort and its helpers take about 9 s to compile (benchmarks/compile.py):
#: its twin sorts a small scene first (the first-use case, 294 faces: two calls, 0.5 s
#: as Python, past a twin's default time).
slow_to_compile(depth_sort, 9.0)
