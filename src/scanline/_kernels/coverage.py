"""Antialiased areas: the fraction of each pixel covered by a shape, composited
with that fraction as alpha.

Coverage is measured on ``SUB`` = 16 sub-scan-lines per pixel row, at heights
``y - 1/2 + (s + 1/2) / 16``, and *exactly* along each of them: a sub-scan-line
crosses the shape's edges at real x positions, the fill rule (even-odd or nonzero
winding, counted per sub-scan-line over every contour of the shape) turns the
sorted crossings into spans, and each span adds ``1/16`` times the exact length of
its overlap with every pixel it meets.  This is the method of Cairo's image
rasterizer (15 sub-scan-lines, 256 x positions) and Skia's supersampler: unlike
signed-area accumulation ("exact area" for one non-overlapping contour) it applies
either fill rule exactly wherever contours overlap or cross themselves, because the
rule is evaluated on each sub-scan-line rather than on accumulated areas; the price
is a vertical resolution of 1/16 pixel (a coverage error below 1/32 per pixel where
an edge ends inside a row, zero on average).

Spans are accumulated as differences (four additions per span, whatever its
length) in a row buffer whose running sum, taken once per pixel row, is the
coverage.

*Exact rows.*  Most rows of most shapes are simpler: every edge that meets the row
crosses it from bottom to top, no two cross inside it, and the winding numbers
between them are 0 and one other value.  There both rules fill the same regions and
the signed area to the right of each edge, accumulated in the same row buffer (as
font rasterizers do), is the exact coverage; such rows skip the sub-scan-lines.  Rows and spans are clipped to the raster before anything is added, so
no store leaves ``buf``.

References
----------
T. Duff, "Polygon scan conversion by exact convolution", Raster Imaging and Digital
Typography, 1989 (coverage as the box-filtered area).
K. Packard, C. Worth, Cairo's "tor" scan converter (sub-scan-line coverage), 2008.
J. D. Foley, A. van Dam, S. K. Feiner, J. F. Hughes, "Computer Graphics: Principles
and Practice", 2nd ed., 1990, section 3.17 (unweighted area sampling).
"""

import math

import numpy as np

from ._jit import helper, inline, kernel
from .blend import composite_row
from .polygon import EVEN_ODD, NONZERO  # noqa: F401  (the rule codes of the aliased fill)
from .sort import insertion_budget, sort_keys

#: Sub-scan-lines per pixel row.
SUB = 16


@inline
def add_span(acc, xlo, xhi, xa, xb, weight):
    """Add ``weight`` x the overlap of [xa, xb) with each pixel, clipped to pixels
    xlo..xhi, to the difference buffer ``acc`` (index 0 is pixel xlo)."""
    xa = max(xa, xlo - 0.5)
    xb = min(xb, xhi + 0.5)
    if xb > xa:
        ia = math.floor(xa + 0.5)
        fa = ia + 0.5 - xa
        ib = min(math.floor(xb + 0.5), xhi + 1)
        fb = xb - (ib - 0.5)
        ia -= xlo
        ib -= xlo
        acc[ia] += weight * fa
        acc[ia + 1] += weight * (1.0 - fa)
        acc[ib] -= weight * (1.0 - fb)
        acc[ib + 1] -= weight * fb


@helper
def flush_row(buf, mode, table, y, acc, xlo, xhi, src):
    """Composite the coverage of row y (the running sum of ``acc``, turned into
    alphas in place) and clear ``acc``."""
    alpha = src[3]
    run = 0.0
    n = xhi - xlo + 1
    for i in range(n):
        run += acc[i]
        cover = abs(run)    # negative for a trapezoid row of a clockwise contour
        acc[i] = min(cover, 1.0) * alpha if cover > 1e-9 else 0.0
    composite_row(buf, mode, table, y, xlo, acc, n, src)
    for i in range(n + 2):
        acc[i] = 0.0


@helper
def shape_edges(verts, contours, c0, c1, edges, order, fkeys, tkeys, titems):
    """Store the non-horizontal edges of contours c0..c1-1 in ``edges`` as rows
    (ylo, yhi, x at ylo, dx/dy, direction) and in ``order`` their indices sorted by
    ylo: by insertion, or past :func:`scanline._kernels.sort.insertion_budget` by
    :func:`scanline._kernels.sort.sort_keys` (O(n log n); ``fkeys``, ``tkeys``,
    ``titems`` its scratch); return their count and the shape's bounds (xmin, ymin,
    xmax, ymax)."""
    n = np.int64(0)     # (not a literal 0: the sort helpers compile once)
    xmin = ymin = math.inf
    xmax = ymax = -math.inf
    for c in range(c0, c1):
        start, stop = contours[c], contours[c + 1]
        for i in range(start, stop):
            x0, y0 = verts[i, 0], verts[i, 1]
            j = i + 1 if i + 1 < stop else start
            x1, y1 = verts[j, 0], verts[j, 1]
            xmin = min(xmin, x0)
            xmax = max(xmax, x0)
            ymin = min(ymin, y0)
            ymax = max(ymax, y0)
            if y0 == y1:
                continue
            d = 1.0
            if y0 > y1:
                x0, y0, x1, y1 = x1, y1, x0, y0
                d = -1.0
            edges[n, 0] = y0
            edges[n, 1] = y1
            edges[n, 2] = x0
            edges[n, 3] = (x1 - x0) / (y1 - y0)
            edges[n, 4] = d
            fkeys[n] = y0
            order[n] = n
            n += 1
    # insertion by ylo (the edges of a contour arrive nearly sorted), or past the
    # budget the merge sort
    budget = insertion_budget(n)
    for i in range(1, n):
        y = fkeys[i]
        e = order[i]
        j = i
        while j > 0 and fkeys[j - 1] > y:
            fkeys[j] = fkeys[j - 1]
            order[j] = order[j - 1]
            j -= 1
        fkeys[j] = y
        order[j] = e
        budget -= i - j
        if budget < 0:
            break
    if budget < 0:
        sort_keys(fkeys, order, n, tkeys, titems)
    return n, xmin, ymin, xmax, ymax


@inline
def trapezoid_edge(acc, xlo, xb, xt, d):
    """Add the signed area to the right of the edge crossing the whole row from x =
    ``xb`` (bottom) to ``xt`` (top), times its direction ``d``, to the difference
    buffer ``acc``: piece by piece over the pixels it crosses, pixel k gets
    ``h (1 - m)`` and the pixels right of it ``h`` (h the piece's height, m its
    mean x within the pixel)."""
    lo = min(xb, xt) - (xlo - 0.5)       # pixel xlo + k covers [k, k + 1)
    hi = max(xb, xt) - (xlo - 0.5)
    k = math.floor(lo)
    if hi - lo < 1e-12:
        f = lo - k
        acc[k] += d * (1.0 - f)
        acc[k + 1] += d * f
        return
    per_x = d / (hi - lo)
    x = lo
    while x < hi:
        xe = min(hi, k + 1.0)
        h = (xe - x) * per_x
        m = 0.5 * (x + xe) - k
        acc[k] += h * (1.0 - m)
        acc[k + 1] += h * m
        x = xe
        k += 1


@helper
def simple_row(edges, active, na, bottom, acc, xlo, xhi, xs, ws):
    """The fast path for a row whose active edges all span its whole height, do not
    cross each other inside it, stay within the raster columns xlo..xhi and leave
    winding numbers 0 and one other value (+1 or -1) between them: there either
    rule fills exactly the regions of nonzero winding, and the exact area of each
    edge (:func:`trapezoid_edge`) adds up to the coverage.  Add them to ``acc`` and
    return True; else return False having added nothing."""
    top = bottom + 1.0
    for t in range(na):
        e = active[t]
        if edges[e, 0] > bottom or edges[e, 1] < top:
            return False
    budget = insertion_budget(na)
    for t in range(na):      # x at the bottom (xs[j]) and top (xs[na + j]), sorted
        e = active[t]
        xb = edges[e, 2] + (bottom - edges[e, 0]) * edges[e, 3]
        j = t
        while j > 0 and xs[j - 1] > xb:
            xs[j] = xs[j - 1]
            xs[na + j] = xs[na + j - 1]
            ws[j] = ws[j - 1]
            j -= 1
        budget -= t - j
        if budget < 0:       # many edges out of order: not a simple row (the general
            return False     # path sorts its crossings in O(n log n))
        xs[j] = xb
        xs[na + j] = xb + edges[e, 3]
        ws[j] = edges[e, 4]
    winding = 0
    sign = 0
    for j in range(na):
        xt = xs[na + j]
        if xs[j] < xlo - 0.5 or xs[j] > xhi + 0.5 or xt < xlo - 0.5 or xt > xhi + 0.5:
            return False
        if j > 0 and xt < xs[na + j - 1]:
            return False
        winding += int(ws[j])
        if winding != 0:
            if sign == 0:
                sign = winding
            elif winding != sign:
                return False
    for j in range(na):
        trapezoid_edge(acc, xlo, xs[j], xs[na + j], ws[j])
    return True


@helper
def row_crossings(edges, active, na, bottom, xs, ws, counts, cap):
    """Record where the active edges cross the row's sub-scan-lines: sub-line s
    (at height ``bottom + (s + 1/2) / SUB``) gets ``counts[s]`` crossings in
    ``xs[s * cap:]`` (x) and ``ws[s * cap:]`` (+1 for an upward edge, -1 for a
    downward one).  An edge crosses the heights ylo <= y < yhi, so edges meeting
    at a vertex count it once."""
    for s in range(SUB):
        counts[s] = 0
    for t in range(na):
        e = active[t]
        ylo = edges[e, 0]
        s0 = max(math.ceil((ylo - bottom) * SUB - 0.5), 0)
        s1 = min(math.ceil((edges[e, 1] - bottom) * SUB - 0.5), SUB)
        for s in range(s0, s1):
            x = edges[e, 2] + (bottom + (s + 0.5) / SUB - ylo) * edges[e, 3]
            k = s * cap + counts[s]
            xs[k] = x
            ws[k] = edges[e, 4]
            counts[s] += 1


@helper
def sort_crossings(xs, ws, start, k, fkeys, items, tkeys, titems, wcopy):
    """Sort the ``k`` crossings at ``xs[start:]`` (with their directions ``ws``) by
    :func:`scanline._kernels.sort.sort_keys`; the other arguments are scratch."""
    for i in range(k):
        fkeys[i] = xs[start + i]
        items[i] = i
        wcopy[i] = ws[start + i]
    sort_keys(fkeys, items, k, tkeys, titems)
    for i in range(k):
        xs[start + i] = fkeys[i]
        ws[start + i] = wcopy[items[i]]


@helper
def sub_line_spans(xs, ws, start, k, acc, xlo, xhi, rule, fkeys, items, tkeys, titems,
                   wcopy):
    """Sort the ``k`` crossings at ``xs[start:]`` and add the spans the fill rule
    makes of them to ``acc``.  A few crossings are sorted by insertion; past
    :func:`scanline._kernels.sort.insertion_budget` moves, by
    :func:`scanline._kernels.sort.sort_keys` (the other arguments: its scratch)."""
    budget = insertion_budget(k)
    for i in range(start + 1, start + k):  # insertion sort: usually a few crossings
        x = xs[i]
        w = ws[i]
        j = i
        while j > start and xs[j - 1] > x:
            xs[j] = xs[j - 1]
            ws[j] = ws[j - 1]
            j -= 1
        xs[j] = x
        ws[j] = w
        budget -= i - j
        if budget < 0:
            break
    if budget < 0:
        sort_crossings(xs, ws, start, k, fkeys, items, tkeys, titems, wcopy)
    winding = 0
    enter = 0.0
    for j in range(start, start + k):
        before = winding != 0 if rule == NONZERO else (winding & 1) == 1
        winding += int(ws[j])
        after = winding != 0 if rule == NONZERO else (winding & 1) == 1
        if after and not before:
            enter = xs[j]
        elif before and not after:
            add_span(acc, xlo, xhi, enter, xs[j], 1.0 / SUB)


@helper
def fill_shape(buf, mode, width, height, table, verts, contours, c0, c1, src, rule,
               edges, active, xs, ws, counts, acc, order, fkeys, items, tkeys, titems, wcopy):
    """Composite one shape (contours c0..c1-1, combined by ``rule``); the arrays
    after ``acc`` are the edge order and the sorts' scratch."""
    n, xmin, ymin, xmax, ymax = shape_edges(verts, contours, c0, c1, edges, order, fkeys,
                                            tkeys, titems)
    if n == 0 or not src[3] > 0.0:
        return
    xlo = max(math.floor(xmin + 0.5), 0)
    xhi = min(math.ceil(xmax + 0.5) - 1, width - 1)
    ylo = max(math.floor(ymin + 0.5), 0)
    yhi = min(math.ceil(ymax + 0.5) - 1, height - 1)
    if xlo > xhi or ylo > yhi:
        return
    cap = active.shape[0]
    nxt = 0
    na = np.int64(0)   # (a literal 0 would compile the row helpers twice)
    for y in range(ylo, yhi + 1):
        bottom = y - 0.5
        top = y + 0.5
        while nxt < n and edges[order[nxt], 0] < top:   # edges starting below the row's top
            active[na] = order[nxt]
            na += 1
            nxt += 1
        keep = np.int64(0)
        for t in range(na):                      # drop edges ending below the row
            if edges[active[t], 1] > bottom:
                active[keep] = active[t]
                keep += 1
        na = keep
        if na == 0:
            continue
        if simple_row(edges, active, na, bottom, acc, xlo, xhi, xs, ws):
            flush_row(buf, mode, table, y, acc, xlo, xhi, src)
            continue
        row_crossings(edges, active, na, bottom, xs, ws, counts, cap)
        for s in range(SUB):
            k = counts[s]
            if k == 2:   # the usual case: one span whatever the rule
                a = xs[s * cap]
                b = xs[s * cap + 1]
                add_span(acc, xlo, xhi, min(a, b), max(a, b), 1.0 / SUB)
            elif k > 2:
                sub_line_spans(xs, ws, s * cap, k, acc, xlo, xhi, rule, fkeys, items, tkeys,
                               titems, wcopy)
        flush_row(buf, mode, table, y, acc, xlo, xhi, src)


@kernel
def fill_shapes(buf, mode, width, height, table, verts, contours, shapes, srcs, rule,
                max_edges):
    """Composite the antialiased shapes ``shapes[p] .. shapes[p+1]-1`` (contour
    indices; contour c is ``verts[contours[c]:contours[c+1]]``), in order, each
    with its source row (``srcs`` has one row, or one per shape).  ``max_edges`` is
    the most vertices of any shape."""
    cap = max(max_edges, 1)
    edges = np.empty((cap, 5), np.float64)
    active = np.empty(cap, np.int64)
    xs = np.empty(SUB * cap, np.float64)
    ws = np.empty(SUB * cap, np.float64)
    counts = np.zeros(SUB, np.int64)
    acc = np.zeros(width + 3, np.float64)
    order = np.empty(cap, np.int64)        # the edges by ylo, and the sorts' scratch
    fkeys = np.empty(cap, np.float64)
    items = np.empty(cap, np.int64)
    tkeys = np.empty(cap, np.float64)
    titems = np.empty(cap, np.int64)
    wcopy = np.empty(cap, np.float64)
    one = srcs.shape[0] == 1
    for p in range(shapes.shape[0] - 1):
        fill_shape(buf, mode, width, height, table, verts, contours, shapes[p],
                   shapes[p + 1], srcs[0] if one else srcs[p], rule, edges, active, xs, ws,
                   counts, acc, order, fkeys, items, tkeys, titems, wcopy)


@kernel
def fill_ellipses(buf, mode, width, height, table, ellipses, srcs):
    """Composite antialiased filled ellipses, rows (xc, yc, rx, ry) of ``ellipses``
    (a circle when rx = ry): on each sub-scan-line the span ``xc +- rx sqrt(1 -
    ((y - yc) / ry)**2)``."""
    acc = np.zeros(width + 3, np.float64)
    one = srcs.shape[0] == 1
    for n in range(ellipses.shape[0]):
        xc, yc, rx, ry = ellipses[n, 0], ellipses[n, 1], ellipses[n, 2], ellipses[n, 3]
        src = srcs[0] if one else srcs[n]
        if not (rx > 0.0 and ry > 0.0 and src[3] > 0.0):
            continue
        xlo = max(math.floor(xc - rx + 0.5), 0)
        xhi = min(math.ceil(xc + rx + 0.5) - 1, width - 1)
        ylo = max(math.floor(yc - ry + 0.5), 0)
        yhi = min(math.ceil(yc + ry + 0.5) - 1, height - 1)
        if xlo > xhi:
            continue
        for y in range(ylo, yhi + 1):
            for s in range(SUB):
                t = (y - 0.5 + (s + 0.5) / SUB - yc) / ry
                if t * t < 1.0:
                    half = rx * math.sqrt(1.0 - t * t)
                    add_span(acc, xlo, xhi, xc - half, xc + half, 1.0 / SUB)
            flush_row(buf, mode, table, y, acc, xlo, xhi, src)
