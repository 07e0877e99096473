"""Scan-line polygon fill: a sorted edge table and an active edge list (notes,
chapter 2, Q.8, approach (1): "determine the overlap intervals for scan lines that
cross the area"; Hearn & Baker, "Computer Graphics", section 3-11).

Sampling and the coverage rule (DESIGN.md, convention 2).  Scan line ``Y`` samples
the pixel centers ``(x, Y)``.  A non-horizontal edge from ``(xlo, ylo)`` up to
``(xhi, yhi)`` is *active* on the scan lines ``ylo < Y <= yhi`` and crosses them at
``xc(Y) = xlo + (Y - ylo) * dx / dy``; it contributes the crossing *key*
``ceil(xc)``, the first pixel center at or right of the crossing.  Pixel ``x`` of the
scan line then sees the crossings with ``key <= x``: it is inside when their count
is odd (even-odd rule) or their signed sum (+1 for an upward edge, -1 for a
downward one) is not zero (nonzero rule).  So a span runs from one key (inclusive)
to the next (exclusive): ``xleft <= x < xright``.

Why this is the top-left rule, and why it is the textbook vertex rule: testing
``ylo < Y <= yhi`` and ``xc <= x`` is testing the point ``(x + e, Y - e**2)`` for an
infinitesimal ``e``: a point on no edge, so every pixel of a tiling lies in exactly
one tile.  A center exactly on a left edge is in (a right edge: out); a center on a
horizontal edge is in when the area lies below the edge (a *top* edge, y being up).
At a vertex joining an edge going up to one going further up (a *monotone* vertex)
the half-open intervals meet without overlapping: the scan line through the vertex
counts one crossing, as when the textbook splits the edges by shortening one of them
by a scan line.  At a local extremum both edges end (a minimum: zero crossings) or
both begin (a maximum: two crossings) on that scan line, which is the textbook's
"count the vertex twice" (the parity is the same as counting it twice; at a minimum
the vertex pixel belongs to the area below, which is empty).  Horizontal edges are
never active, as the textbook prescribes.

Arithmetic.  Edges whose four coordinates are integers are stepped exactly, as
Hearn & Baker's integer version of the incremental algorithm does: the key is kept
as an integer plus a remainder in units of 1/dy, and moving up one scan line adds
the inverse slope dx/dy as a quotient and a remainder (int64 throughout: exact for
coordinates within +-2**30).  Other edges evaluate ``xc(Y)`` from the edge equation
on every scan line in float64, with the endpoints in a canonical order (lower
first), so two polygons sharing an edge compute bit-identical keys and a tiling
still covers each pixel once.

References
----------
D. Hearn, M. P. Baker, "Computer Graphics", 2nd ed., Prentice Hall, 1994, section
3-11 ("Scan-line polygon fill algorithm").
W. M. Newman, R. F. Sproull, "Principles of Interactive Computer Graphics", 2nd ed.,
McGraw-Hill, 1979, chapter 16 (the edge list, y-x ordering).
J. D. Foley, A. van Dam, S. K. Feiner, J. F. Hughes, "Computer Graphics: Principles
and Practice", 2nd ed., 1990, section 3.6 (filling polygons, the edge table and
active-edge table, the half-open rule for shared edges and vertices).
"""

import math

import numpy as np

from ._jit import helper, inline, kernel
from .raster import BAND_SHIFT
from .sort import insertion_budget, sort_keys
from .spans import span

EVEN_ODD = 0
NONZERO = 1


@inline
def rule_mask(rule):
    """``winding & rule_mask(rule) != 0`` is the inside test: the parity bit for
    the even-odd rule, every bit for the nonzero rule."""
    return 1 if rule == EVEN_ODD else -1


@inline
def build_edges(verts, contours, c0, c1, ox, oy, height, et, ef):
    """Fill the edge table ``et`` (int64 rows) with the non-horizontal edges of
    contours ``c0 .. c1-1`` that are active on some raster row; return their count.

    Row ``i`` of ``et``: first row, last row, direction (+1 up, -1 down), integer
    flag, then for an integer edge its key (raster x) and remainder at the first
    row, the per-row quotient and remainder of dx / dy, and dy.  Row ``i`` of
    ``ef`` (float64): the lower endpoint (xlo, ylo), xhi - xlo and yhi - ylo, from
    which the other edges evaluate their crossing on every row (kept beside the
    table: reading them from ``verts`` through vertex indices was slower).
    """
    n = 0
    for c in range(c0, c1):
        start = contours[c]
        end = contours[c + 1]
        for i in range(start, end):
            j = i + 1 if i + 1 < end else start
            ya = verts[i, 1]
            yb = verts[j, 1]
            if ya == yb:
                continue  # horizontal: never crossed at a sample point
            if ya < yb:
                lo, hi, d = i, j, 1
            else:
                lo, hi, d = j, i, -1
            ylo = verts[lo, 1]
            yhi = verts[hi, 1]
            r0 = max(int(math.floor(ylo)) + 1 - oy, 0)
            r1 = min(int(math.floor(yhi)) - oy, height - 1)
            if r0 > r1:
                continue
            xlo = verts[lo, 0]
            xhi = verts[hi, 0]
            exact = (xlo == math.floor(xlo) and xhi == math.floor(xhi)
                     and ylo == math.floor(ylo) and yhi == math.floor(yhi))
            et[n, 0] = r0
            et[n, 1] = r1
            et[n, 2] = d
            et[n, 3] = 1 if exact else 0
            ef[n, 0] = xlo
            ef[n, 1] = ylo
            ef[n, 2] = xhi - xlo
            ef[n, 3] = yhi - ylo
            if exact:
                x0 = int(xlo)
                dx = int(xhi) - x0
                dy = int(yhi) - int(ylo)
                num = (r0 + oy - int(ylo)) * dx
                q = -((-num) // dy)           # ceil(num / dy)
                et[n, 4] = x0 + q - ox
                et[n, 5] = q * dy - num       # 0 <= remainder < dy
                qd = dx // dy
                et[n, 6] = qd
                et[n, 7] = dx - qd * dy
                et[n, 8] = dy
            n += 1
    return n


@inline
def sort_by_row(et, n, counts, order):
    """The edge table bucket-sorted by first row: ``order[k]`` lists edge indices,
    those of row ``r`` starting at ``counts[r - rmin]``.  Returns ``(rmin, rmax)``."""
    rmin = et[0, 0]
    rmax = et[0, 1]
    for i in range(1, n):
        rmin = min(rmin, et[i, 0])
        rmax = max(rmax, et[i, 1])
    rows = rmax - rmin + 1
    for r in range(rows + 2):
        counts[r] = 0
    for i in range(n):
        counts[et[i, 0] - rmin + 1] += 1
    for r in range(rows + 1):
        counts[r + 1] += counts[r]
    for i in range(n):
        b = et[i, 0] - rmin
        order[counts[b]] = i
        counts[b] += 1
    # counts[b] is now the end of bucket b, i.e. the start of bucket b + 1
    return rmin, rmax


@helper
def step_active(et, ef, r, oy, ox, end, nxt, nact, order, active, keys, dirs):
    """Move the active edge list to raster row ``r``: one pass over the list, then
    over the edges entering on this row (``order[nxt:end]``): drop the edges that
    ended below, step the others up one row, and insert each crossing key in order
    (the list stays nearly sorted between rows).  Returns ``(nact, nxt, sorted)``:
    the new length of the list, the next edge of ``order`` to enter it, and whether
    the list is sorted.

    The insertion is O(n) while the list stays nearly sorted; once it has moved
    more than :func:`scanline._kernels.sort.insertion_budget` keys (edges that cross
    between rows: a self-intersecting polygon of many vertices), the remaining keys
    are appended unsorted and the caller sorts the row with :func:`sort_active`, so
    that a row costs O(n log n) at worst instead of O(n**2).

    This is one step of the scan-line fill, as the step table
    (:func:`scanline.trace.scan_line_fill`) runs it."""
    y = r + oy
    k = 0
    budget = insertion_budget(nact + end - nxt)
    for a in range(nact + end - nxt):
        if a < nact:
            e = active[a]
            if et[e, 1] < r:
                continue
        else:
            e = order[nxt]
            nxt += 1
        if et[e, 3] == 1:
            if et[e, 0] < r:  # exact step by dx/dy: a quotient and a remainder
                # (without a branch: ``borrow`` is -1 when the remainder went
                # negative, else 0; the unpredictable ``if`` cost 15% of the fill)
                rem = et[e, 5] - et[e, 7]
                borrow = rem >> 63
                et[e, 4] += et[e, 6] - borrow
                et[e, 5] = rem + (et[e, 8] & borrow)
            key = et[e, 4]
        else:
            xc = ef[e, 0] + ((y - ef[e, 1]) * ef[e, 2]) / ef[e, 3]
            key = int(math.ceil(xc)) - ox
        b = k
        if budget > 0:
            while b > 0:  # (an ``and`` in this test compiled to much slower code)
                if keys[b - 1] <= key:
                    break
                keys[b] = keys[b - 1]
                dirs[b] = dirs[b - 1]
                active[b] = active[b - 1]
                b -= 1
            budget -= k - b
        keys[b] = key
        dirs[b] = et[e, 2]
        active[b] = e
        k += 1
    return k, nxt, budget > 0


@helper
def sort_active(et, active, keys, dirs, n, fkeys, tkeys, titems):
    """Sort the active edge list (``n`` keys, their edges and directions) by key,
    in O(n log n) (:func:`scanline._kernels.sort.sort_keys`; ``fkeys``, ``tkeys``,
    ``titems`` its scratch)."""
    for i in range(n):
        fkeys[i] = keys[i]
    sort_keys(fkeys, active, n, tkeys, titems)
    for i in range(n):
        keys[i] = int(fkeys[i])
        dirs[i] = et[active[i], 2]


@inline
def fill_row(buf, layout, width, height, r, keys, dirs, nact, mask, color):
    """Fill the spans of raster row ``r`` between the sorted crossing keys of the
    active edge list: from a key to the next wherever the winding number so far
    passes the rule (``winding & mask != 0``).  Inlined into its one caller: a call
    a row passed some forty numbers, and 10k polygons took 1.08-1.17x the time in
    RGB (in turn in one process, one and two threads, 2026-12-07; compiled in the
    same time, one function fewer)."""
    winding = 0
    for a in range(nact - 1):
        winding += dirs[a]
        if (winding & mask) != 0 and keys[a] < keys[a + 1]:
            span(buf, layout, width, height, r, keys[a], keys[a + 1] - 1, color)


@inline
def fill_polygon(buf, layout, width, height, ox, oy, verts, contours, c0, c1, color,
                 rule, et, ef, counts, order, active, keys, dirs, fkeys, tkeys, titems):
    """Scan-convert one polygon (contours ``c0 .. c1-1``) into the raster.  Inlined
    into its one caller: called once a polygon, it took the reference counts of its
    twelve arrays each time (an atomic increment and decrement each), and every
    thread's strip calls it for every polygon; 10k polygons 1.02-1.14x as fast on one
    thread and 1.07-1.10x on two (in turn in one process, 2026-12-07), compiled in the
    same time."""
    n = build_edges(verts, contours, c0, c1, ox, oy, height, et, ef)
    if n == 0:
        return
    rmin, rmax = sort_by_row(et, n, counts, order)
    mask = rule_mask(rule)
    nact = np.int64(0)     # (typed, not literal 0s: step_active compiles once)
    nxt = np.int64(0)      # next edge of ``order`` to enter the active list
    for r in range(rmin, rmax + 1):
        nact, nxt, ordered = step_active(et, ef, r, oy, ox, counts[r - rmin], nxt, nact,
                                         order, active, keys, dirs)
        if not ordered:
            sort_active(et, active, keys, dirs, nact, fkeys, tkeys, titems)
        fill_row(buf, layout, width, height, r, keys, dirs, nact, mask, color)


@kernel
def band_reordered(verts, contours, polys, oy, height):
    """The polygons re-laid out in order of their lowest raster row, by bands of
    ``1 << BAND_SHIFT`` rows (a stable counting sort), as new ``(verts, contours,
    polys)`` arrays.  With one color for all, the order cannot change the image;
    polygons drawn band by band, their vertices read in memory order, write rows that
    are still in the cache (measured 13% faster on 10k polygons on 2048 x 2048).  A
    kernel of its own, which the API layer calls before :func:`fill_polygons` for
    batches, so that a single polygon does not compile it."""
    m = polys.shape[0] - 1
    bands = ((height - 1) >> BAND_SHIFT) + 1
    band = np.empty(m, np.int64)
    start = np.zeros(bands + 1, np.int64)
    for p in range(m):
        low = np.inf
        for v in range(contours[polys[p]], contours[polys[p + 1]]):
            low = min(low, verts[v, 1])
        row = 0 if low == np.inf else int(min(max(math.floor(low) - oy, 0), height - 1))
        band[p] = row >> BAND_SHIFT
        start[band[p] + 1] += 1
    for b in range(bands):
        start[b + 1] += start[b]
    order = np.empty(m, np.int64)
    for p in range(m):
        order[start[band[p]]] = p
        start[band[p]] += 1
    new_verts = np.empty_like(verts)
    new_contours = np.empty_like(contours)
    new_polys = np.empty_like(polys)
    nv = 0
    nc = 0
    new_polys[0] = 0
    for q in range(m):
        p = order[q]
        for c in range(polys[p], polys[p + 1]):
            new_contours[nc] = nv
            for v in range(contours[c], contours[c + 1]):
                new_verts[nv, 0] = verts[v, 0]
                new_verts[nv, 1] = verts[v, 1]
                nv += 1
            nc += 1
        new_polys[q + 1] = nc
    new_contours[nc] = nv
    return new_verts, new_contours, new_polys


@kernel
def fill_polygons(buf, layout, width, height, ox, oy, verts, contours, polys, colors,
                  rule, max_edges):
    """Fill P polygons.

    ``verts`` (V, 2) float64 holds every vertex; contour ``c`` is
    ``verts[contours[c]:contours[c + 1]]`` (closed implicitly); polygon ``p`` is made
    of contours ``polys[p] .. polys[p + 1] - 1`` and painted with ``colors[p]`` (or
    ``colors[0]`` for all when ``colors`` has one row); ``rule`` is EVEN_ODD or
    NONZERO; ``max_edges`` bounds the vertex count of one polygon.  Raster pixel
    (0, 0) is device pixel (ox, oy).  Vertices must be finite and within +-2**30.
    """
    size = max(max_edges, 1)
    et = np.empty((size, 9), np.int64)
    ef = np.empty((size, 4), np.float64)
    counts = np.empty(height + 2, np.int64)
    order = np.empty(size, np.int64)
    active = np.empty(size, np.int64)
    keys = np.empty(size, np.int64)
    dirs = np.empty(size, np.int64)
    fkeys = np.empty(size, np.float64)     # sort_keys' scratch
    tkeys = np.empty(size, np.float64)
    titems = np.empty(size, np.int64)
    one = colors.shape[0] == 1
    for p in range(polys.shape[0] - 1):
        fill_polygon(buf, layout, width, height, ox, oy, verts, contours, polys[p],
                     polys[p + 1], colors[0 if one else p], rule, et, ef, counts, order,
                     active, keys, dirs, fkeys, tkeys, titems)


#: The vertex coordinates :func:`fill_ring` takes (+-2**30, as the API checks).
RING_LIMIT = float(1 << 30)


@kernel
def fill_ring(buf, layout, width, height, verts, color, rule):
    """Fill one contour, ``verts`` (N, 2) float64, with ``color`` (the single-call
    path of :func:`scanline.draw.polygon`).  Returns False, having drawn nothing,
    unless every vertex is finite and within +-2**30 (the API then takes its
    general path, which clips far geometry or names the bad vertex)."""
    n = verts.shape[0]
    for i in range(n):
        if not (abs(verts[i, 0]) <= RING_LIMIT and abs(verts[i, 1]) <= RING_LIMIT):
            return False            # (NaN fails the comparison too)
    contours = np.empty(2, np.int64)
    contours[0] = 0
    contours[1] = n
    polys = np.empty(2, np.int64)
    polys[0] = 0
    polys[1] = 1
    origin = np.int64(0)    # (typed, not literal 0s: the helpers compile once)
    fill_polygons(buf, layout, width, height, origin, origin, verts, contours, polys,
                  color.reshape((1, color.shape[0])), rule, n)
    return True

