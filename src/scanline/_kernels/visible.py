"""Image-space visible-surface kernels on screen-space convex polygons
(:class:`scanline.screen.ScreenPolygons`): the scan-line method (Hearn &
Baker, section 13-5) and area subdivision (Warnock; section 13-8), and the
hidden-line test of visible-line detection (section 13-10).

Sampling is the 2-D fill's (:mod:`scanline._kernels.polygon`): scan line ``y``
crosses the edge from (xlo, ylo) up to (xhi, yhi) when ylo < y <= yhi, at
``xc = xlo + ((y - ylo) * (xhi - xlo)) / (yhi - ylo)`` (the same expression, so the
same float), and pixel ``x`` is inside a polygon when an odd number of its crossings
has ``xc <= x`` (a span ``ceil(xl) <= x < ceil(xr)``).  The image-space methods thus
see exactly the pixels :func:`scanline.draw.polygons` paints for the object-order
methods.  Depth at a pixel center is the plane's, z = -(A x + B y + D) / C.
"""

import numpy as np

from ._jit import helper, kernel, slow_to_compile
from .curves import clamped_index
from .raster import put_bit
from .variants import PACKED


@helper
def crossing(verts, i, j, y):
    """The crossing x of edge i -> j with scan line ``y``, or nan when the edge is not
    active there (ylo < y <= yhi)."""
    ya = verts[i, 1]
    yb = verts[j, 1]
    if ya < yb:
        lo, hi = i, j
    elif yb < ya:
        lo, hi = j, i
    else:
        return np.nan
    ylo = verts[lo, 1]
    yhi = verts[hi, 1]
    if not (ylo < y <= yhi):
        return np.nan
    xlo = verts[lo, 0]
    return xlo + ((y - ylo) * (verts[hi, 0] - xlo)) / (yhi - ylo)


@helper
def covers(verts, start, end, x, y):
    """Whether pixel center (x, y) is inside polygon ``verts[start:end]`` by the fill
    rule (odd count of crossings with xc <= x)."""
    odd = False
    for i in range(start, end):
        j = i + 1 if i + 1 < end else start
        xc = crossing(verts, i, j, y)
        if xc <= x:            # False for nan
            odd = not odd
    return odd


#: Bands of 2**PAINT_BAND_SHIFT rows share the painting between threads.
PAINT_BAND_SHIFT = 5


@helper
def bands_of(r0, r1, band, step):
    """The first band of rows r0..r1 that thread ``band`` of ``step`` paints and the
    band after the last (its bands are every ``step``-th from the first): band ``k``
    holds rows k * 2**PAINT_BAND_SHIFT to (k + 1) * 2**PAINT_BAND_SHIFT - 1, so a
    thread visits its own rows only."""
    k0 = r0 >> PAINT_BAND_SHIFT
    return k0 + (band - k0) % step, (r1 >> PAINT_BAND_SHIFT) + 1


@helper
def rows_of(k, r0, r1):
    """The rows of band ``k`` within r0..r1, as a range's start and stop."""
    return max(r0, k << PAINT_BAND_SHIFT), min(r1 + 1, (k + 1) << PAINT_BAND_SHIFT)


@helper
def fill_ids(ids, r, x0, x1, number):
    """``ids[r, x0:x1] = number`` (0 <= x0 <= x1 <= the row's length) in stores of 8,
    4, 2 and 1 that overlap rather than loop to the end: a span's length is not
    predictable, and each loop ending a span at its own length costs a mispredicted
    branch (unsigned indices: no wraparound test, so the stores of 8 are one vector
    store)."""
    n = x1 - x0
    u0 = np.uint64(x0)
    u1 = np.uint64(x1)
    if n >= 8:
        x = u0
        while x + np.uint64(8) < u1:
            for c in range(8):
                ids[r, x + np.uint64(c)] = number
            x += np.uint64(8)
        for c in range(8):
            ids[r, u1 - np.uint64(8 - c)] = number
    elif n >= 4:
        for c in range(4):
            ids[r, u0 + np.uint64(c)] = number
            ids[r, u1 - np.uint64(4 - c)] = number
    elif n >= 2:
        ids[r, u0] = number
        ids[r, u0 + np.uint64(1)] = number
        ids[r, u1 - np.uint64(2)] = number
        ids[r, u1 - np.uint64(1)] = number
    elif n == 1:
        ids[r, u0] = number


@helper
def span_ends(lo, hi, width):
    """The pixels ``x0 <= x < x1`` of the span between the crossings lo and hi (the
    2-D fill's ``ceil(lo) <= x < ceil(hi)``), clipped to 0 .. width."""
    x0 = int(min(max(np.ceil(lo), 0.0), float(width)))
    x1 = int(max(min(np.ceil(hi), float(width)), 0.0))
    return x0, x1


@helper
def paint_triangle(ids, width, height, verts, start, number, top, bottom):
    """The spans of triangle ``verts[start:start + 3]`` (finite) on rows ``top`` ..
    ``bottom``, as :func:`paint_polygon` finds them for any convex polygon, without its
    arrays: the vertices a, b, c by rising y, each row r (y_a < r <= y_c) crosses the
    edge a-c and the edge a-b (r <= y_b) or b-c, each crossing the expression of
    :func:`crossing` for its edge (a horizontal edge crosses no row)."""
    a = start
    b = start + 1
    c = start + 2
    if verts[b, 1] < verts[a, 1]:
        a, b = b, a
    if verts[c, 1] < verts[b, 1]:
        b, c = c, b
        if verts[b, 1] < verts[a, 1]:
            a, b = b, a
    ya = verts[a, 1]
    yb = verts[b, 1]
    yc = verts[c, 1]
    if not ya < yc:
        return
    r0 = int(min(max(np.floor(ya) + 1.0, 0.0), float(height)))
    r1 = int(max(min(np.floor(yc), height - 1.0), -1.0))
    rm = int(max(min(np.floor(yb), float(r1)), float(r0) - 1.0))    # rows <= y_b
    xa = verts[a, 0]
    dxl = verts[c, 0] - xa
    dyl = yc - ya
    for half in range(2):
        if half == 0:
            s0 = max(r0, top)
            s1 = min(rm, bottom)
            xe = xa
            ye = ya
            dxe = verts[b, 0] - xa
            dye = yb - ya
        else:
            s0 = max(rm + 1, top)
            s1 = min(r1, bottom)
            xe = verts[b, 0]
            ye = yb
            dxe = verts[c, 0] - xe
            dye = yc - yb
        for r in range(max(s0, 0), s1 + 1):
            u = xa + ((r - ya) * dxl) / dyl
            w = xe + ((r - ye) * dxe) / dye
            lo = min(u, w)
            hi = max(u, w)
            if lo < hi:
                x0, x1 = span_ends(lo, hi, width)
                fill_ids(ids, r, x0, x1, number)


@helper
def paint_polygon(ids, width, height, verts, start, end, number, top, bottom, xl, xr):
    """The spans of the convex polygon ``verts[start:end]`` (finite) on rows ``top``
    .. ``bottom`` (``xl``, ``xr``: scratch by row - top): each edge adds its crossings
    to the lowest and highest x of its rows."""
    lo = np.inf
    hi = -np.inf
    for i in range(start, end):
        lo = min(lo, verts[i, 1])
        hi = max(hi, verts[i, 1])
    # rows clipped to the raster in floats first (np.floor: math.floor would
    # convert a huge coordinate to an integer that does not exist)
    r0 = max(int(min(max(np.floor(lo) + 1.0, 0.0), float(height))), top)
    r1 = min(int(max(min(np.floor(hi), height - 1.0), -1.0)), bottom)
    for r in range(r0, r1 + 1):
        xl[r - top] = np.inf
        xr[r - top] = -np.inf
    for i in range(start, end):
        j = i + 1 if i + 1 < end else start
        a = i if verts[i, 1] < verts[j, 1] else j
        b = j if a == i else i
        ylo = verts[a, 1]
        yhi = verts[b, 1]
        if ylo == yhi:
            continue
        xlo = verts[a, 0]
        dx = verts[b, 0] - xlo
        dy = yhi - ylo
        # the rows ylo < r <= yhi within r0..r1
        first = int(min(max(np.floor(ylo) + 1.0, float(r0)), float(height)))
        last = int(max(min(np.floor(yhi), float(r1)), -1.0))
        for r in range(max(first, top), last + 1):
            xc = xlo + ((r - ylo) * dx) / dy
            if xc == xc:             # not NaN (inf - inf over a huge edge)
                xl[r - top] = min(xl[r - top], xc)
                xr[r - top] = max(xr[r - top], xc)
    for r in range(r0, r1 + 1):
        if xl[r - top] < xr[r - top]:
            x0, x1 = span_ends(xl[r - top], xr[r - top], width)
            fill_ids(ids, r, x0, x1, number)


@kernel
def paint_numbers(band, step, width, height, verts, offsets, first, ids):
    """Paint the numbers ``first + p`` of convex polygons ``p`` (``verts[offsets[p]:
    offsets[p + 1]]``) in order into ``ids`` (int32, height x width), later over
    earlier: the raster half of the object-order methods (the pixels then take the
    colors of what they show, :func:`color_ids`).  A convex polygon has two crossings
    on each scan line it covers, and the span between them is the 2-D fill's
    (``ceil(xl) <= x < ceil(xr)``, each crossing the expression of :func:`crossing`;
    :func:`paint_polygon`, :func:`paint_triangle`).  The rows of this call are those
    of the bands of 2**PAINT_BAND_SHIFT rows numbered ``band``, ``band + step``, ...
    (:func:`bands_of`; :mod:`scanline._kernels._threads`: one call per thread),
    painted band after band: the polygons are listed by the bands they cover (in
    order), so that a band's rows are read and written while they are in the cache.
    Pixels no polygon covers keep their values."""
    n = offsets.shape[0] - 1
    size = 1 << PAINT_BAND_SHIFT
    bands = (height + size - 1) >> PAINT_BAND_SHIFT
    top = np.empty(n, np.int64)         # each polygon's rows (top > bottom: none)
    bottom = np.empty(n, np.int64)
    count = np.zeros(bands + 1, np.int64)
    for p in range(n):
        r0, r1 = piece_rows(verts, offsets[p], offsets[p + 1], height)
        top[p] = 1
        bottom[p] = 0
        k0, k1 = bands_of(r0, r1, band, step)
        if r0 > r1 or k0 >= k1:
            continue
        top[p] = r0
        bottom[p] = r1
        for k in range(k0, k1, step):
            count[k + 1] += 1
    for k in range(bands):
        count[k + 1] += count[k]
    listed = np.empty(max(count[bands], 1), np.int64)
    at = np.empty(bands, np.int64)
    for k in range(bands):
        at[k] = count[k]
    for p in range(n):
        if top[p] <= bottom[p]:
            k0, k1 = bands_of(top[p], bottom[p], band, step)
            for k in range(k0, k1, step):
                listed[at[k]] = p
                at[k] += 1
    xl = np.empty(size)
    xr = np.empty(size)
    zero = np.int64(0)               # (typed: a literal argument compiles the helpers again)
    k0, k1 = bands_of(zero, height - 1, band, step)
    for k in range(k0, k1, step):
        first_row, stop_row = rows_of(k, zero, height - 1)
        for e in range(count[k], count[k + 1]):
            p = listed[e]
            start = offsets[p]
            end = offsets[p + 1]
            number = np.int32(first + p)
            if end - start == 3:
                paint_triangle(ids, width, height, verts, start, number, first_row,
                               stop_row - 1)
            else:
                paint_polygon(ids, width, height, verts, start, end, number, first_row,
                              stop_row - 1, xl, xr)


@kernel
def resolve_labels(start, step, polygons, table, fan, facet_triangle, triangles, planes, ids,
                   depth, with_depth):
    """The rows of the bands of 2**PAINT_BAND_SHIFT rows numbered ``start``, ``start +
    step`` ...: each pixel's polygon p in ``polygons`` (H, W; -1 none), labeled g =
    ``table[p]``, turned into the device triangle of the facet under the pixel
    center, in ``ids`` (H, W; -1 none), and with ``with_depth`` that facet's plane's
    depth there, in ``depth``.

    A label is a facet (G of them: ``facet_triangle`` (G,) its stand-in triangle of
    ``triangles`` (T, 3, 3), ``planes`` (G, 4) its device plane) or, where ``fan[g]``
    = n > 1, the first of the n facets of a face taken whole, the fan (v0, v_(i+1),
    v_(i+2)) of facets g .. g + n - 1: the pixel lies in facet g + j, j the number of
    diagonals v0 -> v_(i+1), i = 1 .. n - 1, it is to the left of as the face turns
    (corner 1 of facet g + i is v_(i+1)).  Polygons and labels out of range give -1."""
    height, width = polygons.shape
    p_count = table.shape[0]
    g_count = fan.shape[0]
    t_count = triangles.shape[0]
    zero = np.int64(0)
    k0, k1 = bands_of(zero, height - 1, start, step)
    for k in range(k0, k1, step):
        first_row, stop_row = rows_of(k, zero, height - 1)
        for y in range(first_row, stop_row):
            for x in range(width):
                p = polygons[y, x]
                g = table[p] if p >= 0 and p < p_count else -1
                t = -1
                f = g
                if g >= 0 and g < g_count:
                    n = fan[g]
                    if n > 1 and g + n <= g_count:
                        t0 = facet_triangle[g]
                        if t0 >= 0 and t0 < t_count:
                            x0 = triangles[t0, 0, 0]
                            y0 = triangles[t0, 0, 1]
                            turn = ((triangles[t0, 1, 0] - x0) * (triangles[t0, 2, 1] - y0)
                                    - (triangles[t0, 2, 0] - x0) * (triangles[t0, 1, 1] - y0))
                            for i in range(1, n):
                                ti = facet_triangle[g + i]
                                if ti < 0 or ti >= t_count:
                                    continue
                                side = ((triangles[ti, 1, 0] - x0) * (float(y) - y0)
                                        - (triangles[ti, 1, 1] - y0) * (float(x) - x0))
                                if side * turn > 0.0:
                                    f += 1
                    t = facet_triangle[f]
                    if t >= t_count:
                        t = -1
                ids[y, x] = t
                if with_depth:
                    depth[y, x] = plane_depth(planes, f, float(x), float(y)) if t >= 0 \
                        else np.inf


@kernel
def color_ids(band, step, buf, layout, width, height, colors, ids, facets):
    """Each pixel of the bands of rows ``band``, ``band + step``, ... (as in
    :func:`paint_numbers`) whose ``ids`` number p is not negative takes ``colors[p]``;
    the others keep theirs.  Where ``facets`` has entries, the number p is replaced by
    ``facets[p]`` in ``ids`` (a device triangle by its facet, for the renderer)."""
    zero = np.int64(0)
    nf = facets.shape[0]
    k0, k1 = bands_of(zero, height - 1, band, step)
    for k in range(k0, k1, step):
        first_row, stop_row = rows_of(k, zero, height - 1)
        for r in range(first_row, stop_row):
            color_row(buf, layout, width, ids, colors, r)
            if nf > 0:
                for x in range(width):
                    p = ids[r, x]
                    if p >= 0:
                        ids[r, x] = facets[p] if p < nf else -1


@helper
def piece_rows(verts, start, end, height):
    """The rows ``r0 .. r1`` that the spans of convex piece ``verts[start:end]``
    may cover (the 2-D fill's y_min < r <= y_max, clipped to the raster); r0 > r1
    when there are none, or when the piece has fewer than three vertices or one
    that is not finite (clipped in floats: a huge coordinate has no integer)."""
    lo = np.inf
    hi = -np.inf
    finite = end - start >= 3
    for i in range(start, end):
        finite = finite and abs(verts[i, 0]) < np.inf and abs(verts[i, 1]) < np.inf
        lo = min(lo, verts[i, 1])
        hi = max(hi, verts[i, 1])
    if not finite:
        return 1, 0
    return (int(min(max(np.floor(lo) + 1.0, 0.0), float(height))),
            int(max(min(np.floor(hi), height - 1.0), -1.0)))


@helper
def color_row(buf, layout, width, ids, colors, r):
    """Row ``r``'s pixels painted in ``ids`` (number p >= 0) take ``colors[p]`` (the
    channel writes of :func:`scanline._kernels.spans.span`); numbers beyond the rows
    of ``colors`` paint nothing."""
    n = colors.shape[0]
    if len(layout) == PACKED:
        for x in range(width):
            p = ids[r, x]
            if p >= 0 and p < n:
                put_bit(buf, x, r, colors[p, 0])
        return
    nc = colors.shape[1]
    for x in range(width):
        p = ids[r, x]
        if p >= 0 and p < n:
            buf[r, x, 0] = colors[p, 0]
            if nc > 1:
                buf[r, x, 1] = colors[p, 1]
                buf[r, x, 2] = colors[p, 2]
                if nc > 3:
                    buf[r, x, 3] = colors[p, 3]


@helper
def plane_depth(planes, p, x, y):
    """Depth of polygon ``p``'s plane at (x, y) (floats: callers with integer pixel
    coordinates convert them, so the helper is compiled once)."""
    return -(planes[p, 0] * x + planes[p, 1] * y + planes[p, 3]) / planes[p, 2]


# -- the scan-line method ---------------------------------------------------------------

@helper
def scan_edges(verts, offsets, height, ef, ei):
    """The edge table: every non-horizontal polygon edge active on some scan line
    0..height-1.  Row ``n`` of ``ef``: xlo, ylo, xhi - xlo, yhi - ylo; of ``ei``:
    first and last scan line, polygon.  Returns the count."""
    n = 0
    for p in range(len(offsets) - 1):
        start = offsets[p]
        end = offsets[p + 1]
        for i in range(start, end):
            j = i + 1 if i + 1 < end else start
            ya = verts[i, 1]
            yb = verts[j, 1]
            if ya == yb:
                continue
            lo, hi = (i, j) if ya < yb else (j, i)
            # (clamped before the conversion: a float beyond int64 or NaN converts
            # to anything in compiled code, and the compiler may assume it does not)
            r0 = clamped_index(np.floor(verts[lo, 1]) + 1.0, height)
            r1 = clamped_index(np.floor(verts[hi, 1]) + 1.0, height) - 1
            if r0 > r1:
                continue
            ef[n, 0] = verts[lo, 0]
            ef[n, 1] = verts[lo, 1]
            ef[n, 2] = verts[hi, 0] - verts[lo, 0]
            ef[n, 3] = verts[hi, 1] - verts[lo, 1]
            ei[n, 0] = r0
            ei[n, 1] = r1
            ei[n, 2] = p
            n += 1
    return n


@helper
def scan_row(y, ef, ei, nxt, end, order, nact, active, xs):
    """Move the active edge list to scan line ``y``: drop the edges that ended, add
    those that begin (``order[nxt:end]``), and keep the list sorted by crossing x by
    insertion (coherence: the order changes little from one scan line to the next).
    Returns ``(nact, nxt)``."""
    k = 0
    for a in range(nact + end - nxt):
        if a < nact:
            e = active[a]
            if ei[e, 1] < y:
                continue
        else:
            e = order[nxt]
            nxt += 1
        xc = ef[e, 0] + ((y - ef[e, 1]) * ef[e, 2]) / ef[e, 3]
        b = k
        while b > 0:
            if xs[b - 1] <= xc:
                break
            xs[b] = xs[b - 1]
            active[b] = active[b - 1]
            b -= 1
        xs[b] = xc
        active[b] = e
        k += 1
    return k, nxt


@helper
def scan_spans(y, width, planes, ei, nact, active, xs, inside, on, onpos, face, depth):
    """Walk scan line ``y``'s crossings left to right, turning each polygon's in/out
    flag at its crossings, and fill the span up to the next crossing: nothing when
    no flag is on, the one polygon whose flag is on, or -- only where spans overlap
    -- the nearest of the polygons that are on, by their depths at each pixel.
    Returns the number of pixels where depths were compared."""
    non = 0
    compared = 0
    for k in range(nact):
        p = ei[active[k], 2]
        if inside[p]:
            inside[p] = False
            last = on[non - 1]
            on[onpos[p]] = last
            onpos[last] = onpos[p]
            non -= 1
        else:
            inside[p] = True
            on[non] = p
            onpos[p] = non
            non += 1
        if non == 0 or k + 1 >= nact:
            continue
        x0 = clamped_index(np.ceil(xs[k]), width)       # (crossings may be +-inf, NaN)
        x1 = clamped_index(np.ceil(xs[k + 1]), width)
        for x in range(x0, x1):
            best = on[0]
            zbest = plane_depth(planes, best, np.float64(x), np.float64(y))
            for m in range(1, non):
                q = on[m]
                z = plane_depth(planes, q, np.float64(x), np.float64(y))
                if z < zbest:
                    best = q
                    zbest = z
            if non > 1:
                compared += 1
            face[y, x] = best
            depth[y, x] = zbest
    for m in range(non):       # a polygon left on (never, for closed polygons)
        inside[on[m]] = False
    return compared


@kernel
def scan_line_method(verts, offsets, planes, width, height, face, depth, ef, ei, order,
                     counts, active, xs, inside, on, onpos):
    """Hearn & Baker's scan-line method over all polygons at once: the edge table
    bucket-sorted by first scan line, the polygon table's in/out flags, one active
    edge list for every polygon, depths compared only where spans overlap.  Fills
    ``face`` (polygon index, -1 left where nothing is) and ``depth``; returns the
    number of pixels where depths were compared."""
    n = scan_edges(verts, offsets, height, ef, ei)
    for r in range(height + 1):
        counts[r] = 0
    for e in range(n):
        counts[ei[e, 0] + 1] += 1
    for r in range(height):
        counts[r + 1] += counts[r]
    for e in range(n):
        b = ei[e, 0]
        order[counts[b]] = e
        counts[b] += 1
    # counts[r] is now the end of scan line r's bucket (the start of r + 1's)
    nact = np.int64(0)
    nxt = np.int64(0)
    compared = 0
    for y in range(height):
        nact, nxt = scan_row(y, ef, ei, nxt, counts[y], order, nact, active, xs)
        compared += scan_spans(y, width, planes, ei, nact, active, xs, inside, on, onpos,
                               face, depth)
    return compared


# -- area subdivision ----------------------------------------------------------------------

OUTSIDE = 0
SURROUNDING = 1
INSIDE = 2
OVERLAPPING = 3


@helper
def classify(verts, start, end, box, x0, y0, x1, y1):
    """How polygon ``verts[start:end]`` (bounding box ``box`` = xmin, xmax, ymin,
    ymax) relates to the area of pixel centers [x0, x1] x [y0, y1]: OUTSIDE (no
    center of the area can be inside it), SURROUNDING (it contains the whole area),
    INSIDE (it lies within the area) or OVERLAPPING (intersecting: partly in)."""
    if box[1] < x0 or box[0] > x1 or box[3] < y0 or box[2] > y1:
        return OUTSIDE
    if box[0] >= x0 and box[1] <= x1 and box[2] >= y0 and box[3] <= y1:
        return INSIDE
    if (covers(verts, start, end, x0, y0) and covers(verts, start, end, x1, y0)
            and covers(verts, start, end, x0, y1) and covers(verts, start, end, x1, y1)):
        return SURROUNDING
    area = 0.0
    for i in range(start, end):
        j = i + 1 if i + 1 < end else start
        area += verts[i, 0] * verts[j, 1] - verts[j, 0] * verts[i, 1]
    for i in range(start, end):     # an edge with the whole area on its outer side
        j = i + 1 if i + 1 < end else start
        ex = verts[j, 0] - verts[i, 0]
        ey = verts[j, 1] - verts[i, 1]
        out = 0
        for c in range(4):
            cx = x0 if c == 0 or c == 3 else x1
            cy = y0 if c < 2 else y1
            side = (ex * (cy - verts[i, 1]) - ey * (cx - verts[i, 0])) * area
            if side < 0:
                out += 1
        if out == 4:
            return OUTSIDE
    return OVERLAPPING


@helper
def fill_area(verts, offsets, planes, p, x0, y0, x1, y1, whole, face, depth):
    """Paint polygon ``p`` over the area: every pixel (``whole``: it surrounds the
    area) or the pixels whose centers it covers."""
    start = offsets[p]
    end = offsets[p + 1]
    for y in range(y0, y1 + 1):
        for x in range(x0, x1 + 1):
            if whole or covers(verts, start, end, x, y):
                face[y, x] = p
                depth[y, x] = plane_depth(planes, p, np.float64(x), np.float64(y))


@helper
def min_depth_in(planes, ext, p, x0, y0, x1, y1):
    """A lower bound of polygon ``p``'s depth over the area: its plane's least depth
    at the area's corners, or its own least depth if that is larger."""
    fx0, fy0, fx1, fy1 = np.float64(x0), np.float64(y0), np.float64(x1), np.float64(y1)
    z = plane_depth(planes, p, fx0, fy0)
    z = min(z, plane_depth(planes, p, fx1, fy0))
    z = min(z, plane_depth(planes, p, fx0, fy1))
    z = min(z, plane_depth(planes, p, fx1, fy1))
    return max(z, ext[p, 4])


@helper
def max_depth_in(planes, p, x0, y0, x1, y1):
    """Polygon ``p``'s greatest plane depth at the area's corners."""
    fx0, fy0, fx1, fy1 = np.float64(x0), np.float64(y0), np.float64(x1), np.float64(y1)
    z = plane_depth(planes, p, fx0, fy0)
    z = max(z, plane_depth(planes, p, fx1, fy0))
    z = max(z, plane_depth(planes, p, fx0, fy1))
    return max(z, plane_depth(planes, p, fx1, fy1))


@helper
def decide_area(verts, offsets, planes, ext, cand, level, n, x0, y0, x1, y1, face, depth):
    """Warnock's tests for one area whose relevant polygons are ``cand[level, :n]``,
    with their classes in ``cand[level + 1, :n]``.  Returns the case: 0 nothing there
    (background), 1 a single polygon (painted), 2 a surrounding polygon in front of
    all others (painted), 3 one pixel resolved by depth, or -1: subdivide."""
    if n == 0:
        return 0
    if n == 1:
        p = cand[level, 0]
        fill_area(verts, offsets, planes, p, x0, y0, x1, y1,
                  cand[level + 1, 0] == SURROUNDING, face, depth)
        return 1
    front = -1
    zfront = np.inf
    for m in range(n):
        if cand[level + 1, m] == SURROUNDING:
            z = max_depth_in(planes, cand[level, m], x0, y0, x1, y1)
            if z < zfront:
                front = m
                zfront = z
    if front >= 0:
        ahead = True
        for m in range(n):
            if m != front and min_depth_in(planes, ext, cand[level, m], x0, y0, x1,
                                           y1) <= zfront:
                ahead = False
                break
        if ahead:
            fill_area(verts, offsets, planes, cand[level, front], x0, y0, x1, y1,
                      np.bool_(True), face, depth)
            return 2
    if x0 == x1 and y0 == y1:
        best = -1
        zbest = np.inf
        for m in range(n):
            p = cand[level, m]
            if cand[level + 1, m] == SURROUNDING or covers(verts, offsets[p],
                                                           offsets[p + 1], x0, y0):
                z = plane_depth(planes, p, np.float64(x0), np.float64(y0))
                if z < zbest:
                    best = p
                    zbest = z
        if best >= 0:
            face[y0, x0] = best
            depth[y0, x0] = zbest
        return 3
    return -1


@kernel
def area_subdivision(verts, offsets, planes, ext, width, height, face, depth, cand, ncand,
                     stack, regions):
    """Warnock's area subdivision of the whole raster: an area is painted when its
    relevant polygons make the answer obvious (:func:`decide_area`), else split into
    four quadrants, down to single pixels.  Depth first: ``cand`` (2 L, P) holds, for
    the area being examined at each level ``lv`` of subdivision, the polygons not
    outside it (row 2 lv, ``ncand[lv]`` of them, chosen among its parent's) and their
    classes (row 2 lv + 1); ``stack`` (S, 5) the areas waiting (x0, y0, x1, y1, lv);
    ``regions`` (R, 5) records each decided area (x0, y0, x1, y1, case) while it has
    room.  Returns the number of areas decided (which may exceed R)."""
    stack[0, 0] = 0
    stack[0, 1] = 0
    stack[0, 2] = width - 1
    stack[0, 3] = height - 1
    stack[0, 4] = 0
    top = 1
    decided = 0
    npoly = len(offsets) - 1
    while top > 0:
        top -= 1
        x0 = stack[top, 0]
        y0 = stack[top, 1]
        x1 = stack[top, 2]
        y1 = stack[top, 3]
        lv = stack[top, 4]
        level = 2 * lv
        count = npoly if lv == 0 else ncand[lv - 1]
        n = np.int64(0)
        for m in range(count):
            p = m if lv == 0 else cand[level - 2, m]
            c = classify(verts, offsets[p], offsets[p + 1], ext[p], x0, y0, x1, y1)
            if c != OUTSIDE:
                cand[level, n] = p
                cand[level + 1, n] = c
                n += 1
        ncand[lv] = n
        case = decide_area(verts, offsets, planes, ext, cand, level, n, x0, y0, x1, y1,
                           face, depth)
        if case >= 0:
            if decided < len(regions):
                regions[decided, 0] = x0
                regions[decided, 1] = y0
                regions[decided, 2] = x1
                regions[decided, 3] = y1
                regions[decided, 4] = case
            decided += 1
            continue
        xm = (x0 + x1) // 2
        ym = (y0 + y1) // 2
        for q in range(4):
            qx0 = x0 if q % 2 == 0 else xm + 1
            qx1 = xm if q % 2 == 0 else x1
            qy0 = y0 if q < 2 else ym + 1
            qy1 = ym if q < 2 else y1
            if qx0 > qx1 or qy0 > qy1:
                continue
            stack[top, 0] = qx0
            stack[top, 1] = qy0
            stack[top, 2] = qx1
            stack[top, 3] = qy1
            stack[top, 4] = lv + 1
            top += 1
    return decided


#: Warnock's kernel and its helpers take about 2.5 s to compile (benchmarks/compile.py):
#: its twin may answer a small scene first.
slow_to_compile(area_subdivision, 2.5)


# -- visible-line detection ---------------------------------------------------------------

@helper
def hidden_part(segs, sdepth, e, verts, start, end, planes, p, eps, t):
    """The parameter interval of segment ``e`` hidden by polygon ``p``: the part
    whose projection is inside the polygon (Cyrus-Beck against its edges) and that
    lies behind its plane by more than ``eps``.  Writes ``t[0], t[1]``; returns
    whether it is not empty."""
    x0 = segs[e, 0]
    y0 = segs[e, 1]
    dx = segs[e, 2] - x0
    dy = segs[e, 3] - y0
    area = 0.0
    for i in range(start, end):
        j = i + 1 if i + 1 < end else start
        area += verts[i, 0] * verts[j, 1] - verts[j, 0] * verts[i, 1]
    lo = 0.0
    hi = 1.0
    for i in range(start, end):
        j = i + 1 if i + 1 < end else start
        ex = verts[j, 0] - verts[i, 0]
        ey = verts[j, 1] - verts[i, 1]
        # inside: (ex * (y - yi) - ey * (x - xi)) * area > 0
        f0 = (ex * (y0 - verts[i, 1]) - ey * (x0 - verts[i, 0])) * area
        df = (ex * dy - ey * dx) * area
        if df == 0.0:
            if f0 <= 0.0:
                return False
        elif df > 0.0:
            lo = max(lo, -f0 / df)
        else:
            hi = min(hi, -f0 / df)
        if lo >= hi:
            return False
    # behind: z(t) - plane depth(t) > eps, linear in t
    g0 = sdepth[e, 0] - plane_depth(planes, p, x0, y0)
    g1 = sdepth[e, 1] - plane_depth(planes, p, x0 + dx, y0 + dy)
    dg = g1 - g0
    if dg == 0.0:
        if g0 <= eps:
            return False
    elif dg > 0.0:
        lo = max(lo, (eps - g0) / dg)
    else:
        hi = min(hi, (eps - g0) / dg)
    if lo >= hi:
        return False
    t[0] = lo
    t[1] = hi
    return True


@kernel
def hidden_intervals(segs, sdepth, verts, offsets, planes, ext, eps, out):
    """Every (segment, polygon) pair where the polygon hides part of the segment:
    rows (segment, t0, t1) of ``out`` while there is room.  Returns the number of
    rows there are (more than ``len(out)``: call again with a larger ``out``)."""
    n = 0
    t = np.empty(2)
    for e in range(len(segs)):
        sx0 = min(segs[e, 0], segs[e, 2])
        sx1 = max(segs[e, 0], segs[e, 2])
        sy0 = min(segs[e, 1], segs[e, 3])
        sy1 = max(segs[e, 1], segs[e, 3])
        sz = max(sdepth[e, 0], sdepth[e, 1])
        for p in range(len(offsets) - 1):
            if ext[p, 0] > sx1 or ext[p, 1] < sx0 or ext[p, 2] > sy1 or ext[p, 3] < sy0:
                continue
            if ext[p, 4] >= sz - eps:        # the polygon lies wholly behind the segment
                continue
            if hidden_part(segs, sdepth, e, verts, offsets[p], offsets[p + 1], planes, p,
                           eps, t):
                if n < len(out):
                    out[n, 0] = e
                    out[n, 1] = t[0]
                    out[n, 2] = t[1]
                n += 1
    return n
