"""Scan conversion of triangles with depth and perspective-correct attributes
(Hearn & Baker, section 13-3, "Depth-buffer method"; the fill rule of
:mod:`scanline._kernels.polygon`).

Coverage.  Scan line ``Y`` samples the pixel centers ``(x, Y)``.  An edge from its
lower endpoint ``(xlo, ylo)`` to its upper one is active on the rows ``ylo < Y <=
yhi`` and crosses them at ``xc = xlo + ((Y - ylo) * (xhi - xlo)) / (yhi - ylo)`` --
the very expression, with the endpoints in the same canonical order, that the 2-D
polygon fill evaluates -- and a row's span runs from ``ceil(xc_left)`` inclusive to
``ceil(xc_right)`` exclusive.  So a triangle covers exactly the pixels that
``sl.draw.polygon`` fills for it (the top-left rule), and triangles that share an
edge cover each pixel on it once.  Horizontal edges are never active.

Depth.  The triangle's plane in device space, ``A x + B y + C z + D = 0``, gives the
depth ``z = (-A x - B y - D) / C``; along a scan line it changes by ``-A / C`` per
pixel, and Hearn & Baker's incremental step ``z' = z - A / C`` is what the inner
loop does.  The first pixel of each span is evaluated from the plane (Hearn &
Baker's step down the left edge, ``z' = z + (A / m + B) / C``, computed exactly
rather than accumulated, so both triangles of a shared edge agree there).  With a
depth test a fragment is written when ``z < depth(x, y)`` (the notes' glossary: the
closer the point, the smaller its z), and then ``depth(x, y) = z``.

Perspective-correct attributes.  After the perspective divide an attribute ``a`` is
not linear in screen space, but ``a / w`` and ``1 / w`` are (both are linear in the
homogeneous clip coordinates); each pixel interpolates them linearly and divides
(Blinn, "Hyperbolic interpolation", 1992; Heckbert & Moreton 1991).  With ``1 / w``
equal at the three vertices (a parallel projection) this is plain linear
interpolation.

Parallelism.  Triangles are binned into bands of :data:`BAND` rows, each band keeps
the triangles' input order, and the bands are shared out between calls on several
threads (:mod:`scanline._kernels._threads`): a pixel is only ever written by the call
of its band, and the result is identical to drawing the triangles one after another.
The binning copies each triangle's data into its bands' slots (:func:`bin_pack`), so
a band reads its triangles from consecutive memory: read in place, a band's
triangles lie about as many triangles apart as there are bands, every one on cache
lines of its own, and a million small triangles took three times as long to draw
(324 ms against 103 ms on one core, the copy 100 ms more, measured 2026-12-06).

Occlusion.  A drawing order can put some triangles last (the z-buffer pass of
:func:`scanline.visible.zbuffer.nearest` draws the faces turned away from the viewer
after the others); those are skipped where they lie behind every depth of the tiles
they meet (:func:`behind`), and exact depth ties go to the smaller id, so the pixels
stay those of drawing in input order.
"""

import math

import numpy as np
from ._jit import helper, inline, kernel

#: Rows per band (a power of two) and its shift.
BAND_SHIFT = 5
BAND = 1 << BAND_SHIFT

#: The widest box (pixels) the work estimate of :func:`bin_count` counts: a
#: triangle's x extent is not clipped to the raster there.
WIDEST = 4096.0

#: Output tokens (``len(out)``): write 0..255 attribute values rounded into the frame
#: buffer's bytes; write the float attributes and the triangle's id into attribute
#: and id buffers (a visibility buffer, for deferred shading); write the id alone
#: (the attributes are found again from the triangle's functions where the pixel is
#: shaded, :func:`scanline._kernels.shade.triangle_attributes`).
COLOR = 1
ATTRIBUTES = 2
IDS = 3

#: Depth tokens: test and write the depth buffer; draw in the given order; peel
#: (write where the depth lies strictly between ``floor[y, x]`` and the depth
#: buffer: the next layer behind the one already taken, for the A-buffer); or clear
#: each band of the depth buffer to +inf (and of the id buffer to -1) before testing
#: in it (a new frame: the clear runs on every core, on rows about to be drawn).
TEST = 1
NO_TEST = 2
PEEL = 3
CLEAR_TEST = 4


@inline
def rows_of(y0, y1, y2, height):
    """The first and last raster rows (``0 .. height - 1``) whose scan lines meet the
    triangle whose vertices lie at heights ``y0``, ``y1``, ``y2``: ``ylo < Y <= yhi``
    (first > last: none, also for NaN)."""
    low = min(min(y0, y1), y2)         # (min of two, as elsewhere: one compiled form)
    high = max(max(y0, y1), y2)
    if not (low == low and high == high):           # NaN
        return 1, 0
    flo = math.floor(max(min(low, height + 1.0), -2.0))     # (an int, in range)
    fhi = math.floor(max(min(high, height + 1.0), -2.0))
    return max(flo + 1, 0), min(fhi, height - 1)


@kernel
def bin_count(tri, order, first, height, lo, hi, counts):
    """The first pass of binning triangles by band (a counting sort; the chunks of a
    batch run on every core, and :func:`scanline.draw.triangles.bin_bands` joins
    them): the triangles at positions ``lo .. hi - 1`` of the drawing order
    ``order`` (position p draws triangle ``order[p]``; no entries: triangle p).  Adds
    to ``counts[0, b]`` (zeros, (2, bands), made by the caller: numpy's allocation
    compiled into the kernel costs 0.1 s of a first call) how many of them meet band
    ``b``, and to ``counts[1, b]`` how many of those lie at position ``first`` or
    after (the tile-tested triangles, :func:`raster_triangles`); returns the
    summed areas of their boxes (rows met times their whole x extent plus one, the
    extent counted up to :data:`WIDEST` pixels), the work estimate of
    :func:`raster_triangles`."""
    bands = counts.shape[1]
    area = 0                # (whole numbers: a float sum made the pass 25% slower)
    for p in range(lo, hi):
        t = order[p] if order.shape[0] != 0 else p
        r0, r1 = rows_of(tri[t, 0, 1], tri[t, 1, 1], tri[t, 2, 1], height)
        if r0 <= r1:
            for b in range(r0 >> BAND_SHIFT, min((r1 >> BAND_SHIFT) + 1, bands)):
                counts[0, b] += 1
                if p >= first:
                    counts[1, b] += 1
            wide = (max(max(tri[t, 0, 0], tri[t, 1, 0]), tri[t, 2, 0])
                    - min(min(tri[t, 0, 0], tri[t, 1, 0]), tri[t, 2, 0]))
            area += (r1 - r0 + 1) * ((int(wide) if wide < WIDEST else int(WIDEST)) + 1)
    return area


@kernel
def bin_pack(tri, q, att, ids, order, height, lo, hi, fill, ptri, pq, patt, pids):
    """The second pass: copy each triangle at positions ``lo .. hi - 1`` of the
    drawing order ``order`` (:func:`bin_count`) -- its vertices, 1/w, attributes and
    id -- to entry ``fill[b]`` of ``ptri``, ``pq``, ``patt`` and ``pids`` for every
    band ``b`` its rows meet, advancing ``fill[b]`` (so each band lists its triangles
    in drawing order, one after another in memory).  The arrays
    come flat, one row a triangle: ``tri`` (N, 9) and ``ptri`` (E, 9), ``q`` (N, 3)
    and ``pq`` (E, 3), ``att`` (N, 3 K) and ``patt`` (E, 3 K), ``ids`` (N,) and
    ``pids`` (E,) (a row is then one loop: less to compile); ``pq`` or ``pids``
    without rows are left out (1/w = 1 everywhere; no ids needed).  The indices are
    unsigned (no wrap-around of negative indices: 2% of a million small triangles'
    time, measured 2026-12-07)."""
    for p in range(lo, hi):
        tu = np.uint64(order[p] if order.shape[0] != 0 else p)
        r0, r1 = rows_of(tri[tu, 1], tri[tu, 4], tri[tu, 7], height)
        for b in range(r0 >> BAND_SHIFT, (r1 >> BAND_SHIFT) + 1 if r0 <= r1 else 0):
            e = fill[b]
            if not 0 <= e < ptri.shape[0]:
                continue        # (only if ``tri`` changed since the count: never write out)
            fill[b] = e + 1
            eu = np.uint64(e)
            for j in range(9):
                ptri[eu, j] = tri[tu, j]
            for j in range(patt.shape[1]):
                patt[eu, j] = att[tu, j]
            for j in range(pq.shape[1] if pq.shape[0] != 0 else 0):
                pq[eu, j] = q[tu, j]
            if pids.shape[0] != 0:
                pids[eu] = ids[tu]


@inline
def crossing(xlo, ylo, xhi, yhi, y):
    """Where the edge from ``(xlo, ylo)`` (the lower end) to ``(xhi, yhi)`` crosses
    scan line ``y``: the 2-D polygon fill's expression."""
    return xlo + ((y - ylo) * (xhi - xlo)) / (yhi - ylo)


@inline
def frame(x0, y0, x1, y1, x2, y2):
    """The edges from vertex 0 of the triangle ``(x0, y0)``, ``(x1, y1)``, ``(x2,
    y2)`` and one over the doubled signed area they span: ``(ex1, ey1, ex2, ey2,
    r)``, with ``r`` = 0 for a triangle that covers no pixel (zero area, or a
    coordinate that is not finite)."""
    ex1 = x1 - x0
    ey1 = y1 - y0
    ex2 = x2 - x0
    ey2 = y2 - y0
    area = ex1 * ey2 - ex2 * ey1
    if not (area != 0.0 and math.isfinite(area)):
        return ex1, ey1, ex2, ey2, 0.0
    return ex1, ey1, ex2, ey2, 1.0 / area


@inline
def linear(f0, f1, f2, ex1, ey1, ex2, ey2, r):
    """The function of the screen that takes the values ``f0``, ``f1``, ``f2`` at a
    triangle's vertices (its :func:`frame` ``ex1 .. r``): ``(value at vertex 0,
    d/dx, d/dy)``; for the depth, the plane A x + B y + C z + D = 0 gives d/dx =
    -A / C and d/dy = -B / C (Hearn & Baker, section 13-3)."""
    d1 = f1 - f0
    d2 = f2 - f0
    return f0, (d1 * ey2 - d2 * ey1) * r, (d2 * ex1 - d1 * ex2) * r


@helper
def planes(tri, q, att, e0, e1, g, ok):
    """The linear functions of triangles ``e0 .. e1 - 1`` in screen space: row ``j``
    of ``g[e - e0]`` holds (value at vertex 0, d/dx, d/dy) of the depth (j = 0), of
    1/w (j = 1; 1 everywhere where ``q`` has no rows) and of each attribute times
    1/w (j = 2 ...); ``ok[e - e0]`` is False for a triangle that covers no pixel:
    zero area, or a coordinate that is not finite.

    Triangles are set up in batches: a helper handed an array updates its reference
    count twice per call (an atomic ``NRT_incref``/``NRT_decref`` pair), and for the
    four arrays of one triangle that was 45 ns a triangle, more than the setup itself
    (measured 2026-12-06).  The per-triangle helpers below take numbers."""
    k = att.shape[2]
    affine = q.shape[0] == 0
    for t in range(e0, e1):
        s = t - e0
        ex1, ey1, ex2, ey2, r = frame(tri[t, 0, 0], tri[t, 0, 1], tri[t, 1, 0], tri[t, 1, 1],
                                      tri[t, 2, 0], tri[t, 2, 1])
        if r == 0.0:
            ok[s] = False
            continue
        q0 = 1.0 if affine else q[t, 0]
        q1 = 1.0 if affine else q[t, 1]
        q2 = 1.0 if affine else q[t, 2]
        finite = 0.0
        for j in range(k + 2):
            if j == 0:
                f0 = tri[t, 0, 2]
                f1 = tri[t, 1, 2]
                f2 = tri[t, 2, 2]
            elif j == 1:
                f0 = q0
                f1 = q1
                f2 = q2
            else:
                f0 = att[t, 0, j - 2] * q0
                f1 = att[t, 1, j - 2] * q1
                f2 = att[t, 2, j - 2] * q2
            value, gx, gy = linear(f0, f1, f2, ex1, ey1, ex2, ey2, r)
            g[s, j, 0] = value
            g[s, j, 1] = gx
            g[s, j, 2] = gy
            finite += 0.0 * (value + gx + gy)                # NaN if any is not finite
        ok[s] = finite == 0.0


@inline
def rising(y0, y1, y2):
    """The vertices (0, 1, 2) at heights ``y0``, ``y1``, ``y2`` by rising y (ties keep
    index order, so that the horizontal edge is skipped): ``(low, mid, high)``."""
    swap = y1 < y0
    low = 1 if swap else 0
    mid = 0 if swap else 1
    ylow = y1 if swap else y0
    ymid = y0 if swap else y1
    swap = y2 < ymid
    high = mid if swap else 2
    mid = 2 if swap else mid
    ymid = y2 if swap else ymid
    swap = ymid < ylow
    low, mid = (mid, low) if swap else (low, mid)
    return low, mid, high


@inline
def span_limits(y, xa, ya, xb, yb, xc, yc, width):
    """The span ``kl <= x < kr`` on scan line ``y`` of the triangle with vertices
    ``(xa, ya)``, ``(xb, yb)``, ``(xc, yc)`` by rising y, clamped to ``0 ..
    width``."""
    xl = crossing(xa, ya, xc, yc, y)                    # the long edge
    lower = y <= yb
    xs = xa if lower else xb
    ys = ya if lower else yb
    xe = xb if lower else xc
    ye = yb if lower else yc
    xr = crossing(xs, ys, xe, ye, y)
    xl, xr = min(xl, xr), max(xl, xr)
    if not (xl <= xr):                                  # NaN
        return 0, 0
    xl = min(max(xl, -1.0), width + 1.0)
    xr = min(max(xr, -1.0), width + 1.0)
    kl = max(math.ceil(xl), 0)                        # (math.ceil gives an int)
    kr = min(math.ceil(xr), width)
    return kl, kr


#: Columns per tile of the tile test (a power of two, its shift): a band's rows
#: times this many columns.
TILE_SHIFT = 5

#: The unit roundoff of float64 (2^-53), for the bound of :func:`behind`.
ROUNDOFF = 2.0 ** -53


@helper
def tile_max(zbuf, lo, hi, j):
    """The largest depth in rows ``lo .. hi`` of tile ``j``'s columns (``j <<``
    :data:`TILE_SHIFT` on, at most ``1 <<`` :data:`TILE_SHIFT` of them).  Four
    columns at a time, each with its own running maximum: one maximum carried from
    pixel to pixel waits on the last at every step."""
    width = zbuf.shape[1]
    x0 = j << TILE_SHIFT
    x1 = min(x0 + (1 << TILE_SHIFT), width)
    m0 = m1 = m2 = m3 = -math.inf
    for y in range(lo, hi + 1):
        row = np.uint64(y)
        x = x0
        while x + 4 <= x1:
            xu = np.uint64(x)
            a = zbuf[row, xu]
            b = zbuf[row, xu + np.uint64(1)]
            c = zbuf[row, xu + np.uint64(2)]
            d = zbuf[row, xu + np.uint64(3)]
            m0 = a if a > m0 else m0
            m1 = b if b > m1 else m1
            m2 = c if c > m2 else m2
            m3 = d if d > m3 else m3
            x += 4
        while x < x1:
            a = zbuf[row, np.uint64(x)]
            m0 = a if a > m0 else m0
            x += 1
    return max(max(m0, m1), max(m2, m3))


@inline
def behind(zbuf, tiles, lo, hi, r0, r1, xmin, xmax, x0, y0, g0, gx, gy):
    """Whether a triangle lies behind every depth of the tiles it meets, so that none
    of its fragments can win the depth test (the tile test of a hierarchical z-buffer,
    Greene, Kass & Miller, "Hierarchical Z-buffer visibility", SIGGRAPH 1993, on one
    level): its rows ``r0 .. r1`` of band ``lo .. hi``, its x extent ``xmin ..
    xmax``, its depth function ``(g0, gx, gy)`` at ``(x - x0, y - y0)``.

    Exact: the bound is the depth function's least value over the box of the pixels
    the span loop can reach (columns ``floor(xmin) .. ceil(xmax)``, clamped to the
    raster), less what rounding can take from the depths the loop computes and from
    the bound itself: the loop's first value is three operations on terms at most
    ``size``, each step of ``z' = z - A / C`` one more (steps: at most ``kb - ka +
    1``), the bound three more, so at most ``kb - ka + 7`` unit roundoffs of
    ``size``, taken as ``kb - ka + 8`` and twice over.  A tile's depths only fall,
    so the largest depth once found (``tiles[j]``, NaN: not yet) stays an upper
    bound while the band is drawn.  A triangle skipped this way would have written
    nothing."""
    width = zbuf.shape[1]
    ka = max(math.floor(min(max(xmin, -1.0), width + 1.0)), 0)     # (ints, in range)
    kb = min(math.ceil(min(max(xmax, -1.0), width + 1.0)), width - 1)
    if ka > kb:
        return True
    fxa = ka - x0
    fxb = kb - x0
    fya = r0 - y0
    fyb = r1 - y0
    low = g0 + min(gx * fxa, gx * fxb) + min(gy * fya, gy * fyb)
    size = (abs(g0) + max(abs(gx * fxa), abs(gx * fxb)) + max(abs(gy * fya), abs(gy * fyb)))
    low -= 2.0 * (kb - ka + 8) * ROUNDOFF * size
    for j in range(ka >> TILE_SHIFT, (kb >> TILE_SHIFT) + 1):
        most = tiles[j]
        if most != most:
            most = tile_max(zbuf, lo, hi, j)
            tiles[j] = most
        if not low > most:
            return False
    return True


#: The most channels of a frame buffer (RGBA): the channel loop of the bytes written
#: (out COLOR) runs this many times at most, a trip count known when compiling.
#: With the attributes' count alone (known only at run time) LLVM vectorized that
#: loop of three, tested the arrays for overlap on every scan line and kept the
#: pixel loop's values on the stack; 100k medium triangles took 1.12-1.14x the time on
#: one core (in turn in one process, 2026-12-07), the same pixels.
CHANNELS = 4

#: Triangles set up per call of :func:`planes` in :func:`raster_entries`.
SETUP_BATCH = 64

#: Reading ahead.  A band's triangles reach its rows in scattered order, and a line
#: of the depth or frame buffer not yet in the core's cache stalls the depth test
#: that reads it; so :func:`raster_triangles` first reads one value in every cache
#: line of the band's rows of both, in order, and they stream in at the memory's
#: speed (the processor's prefetcher).  Measured 2026-12-06, 100k triangles of 50
#: pixels at 1920 x 1080 on one core after a ``DepthBuffer.clear()``: 36.3 ms
#: without, 25.9 ms with.  (A band cleared by the kernel, CLEAR_TEST, is in the cache
#: already.)  A band is read ahead when it holds at least one triangle per this many
#: pixels of its width: fewer touch too little of it to pay.
READ_AHEAD = 8


@helper
def raster_triangle(out, depth, tri, q, att, ids, t, r0, r1, zbuf, floor, buf, abuf, idbuf):
    """Scan-convert triangle ``t`` on its rows within ``r0 .. r1``: the step tables
    run it for one triangle and one row (:mod:`scanline.trace.zbuffer`)."""
    raster_entries(out, depth, tri, q, att, ids, t, t + 1, t + 1, False, r0, r1, zbuf, floor,
                   buf, abuf, idbuf, np.empty((SETUP_BATCH, att.shape[2] + 2, 3)),
                   np.empty(SETUP_BATCH, np.bool_),
                   np.empty((2, max(r1 - r0 + 1, 0)), np.int64), np.empty(0),
                   np.empty(zbuf.shape[1]))


@helper
def raster_entries(out, depth, tri, q, att, ids, e0, e1, es, ordered, lo, hi, zbuf, floor,
                   buf, abuf, idbuf, g, ok, spans, tiles, inverse):
    """Scan-convert triangles ``e0 .. e1 - 1``, each on its rows within ``lo .. hi``
    (one band): one call per band, the variants (the tokens ``out`` and ``depth``)
    folded here, set up in batches (:func:`planes`) into ``g`` (:data:`SETUP_BATCH`,
    K + 2, 3) and ``ok`` (:data:`SETUP_BATCH`,).

    Triangles ``es`` on are drawn only where they are not :func:`behind` the tiles
    they meet (``tiles``: the band's tile maxima, NaN where not yet found).
    ``ordered``: an id buffer is written, the triangles before ``es`` and those from
    it each come in the order of their ids, but not the two parts together; a
    fragment of the later part then also wins where its depth equals the buffer's
    and its id is the smaller.  Each pixel takes the least (depth, id), which
    drawing in the order of the ids with ``z < depth`` gives too (the first of equal
    depths wins).

    A triangle's spans are found on all its rows first, into ``spans`` (2, at least
    ``hi - lo + 1``), and then filled: the two divisions of each row's edge crossings
    no longer wait for the fill of the row before it (each fill ends in a branch the
    predictor misses, and the division after it started only then).  The same spans;
    on one core, in turn in one process (2026-12-07): the teapot's frame 6-10% less
    time in four runs, 100k medium triangles 2% more to 25% less (noisy), 1M small
    ones within 3% either way.

    In perspective the attributes divided by 1/w need 1 / (1/w) at each pixel: a
    span's reciprocals are found into ``inverse`` (at least W) before it is filled,
    and an affine triangle (1/w = 1 everywhere) skips them.  In the pixel loop the
    choice had been a select after a division made at every pixel, affine or not;
    in turn in one process on two threads (2026-12-08), the same pixels: 100k large
    affine triangles 1.02-1.06x as fast, medium 1.01-1.02x, in perspective 0.98-1.02x."""
    height, width = zbuf.shape
    k = att.shape[2]
    kc = min(k, buf.shape[2]) if len(out) == COLOR else k          # (never past a pixel)
    for c0 in range(e0, e1, SETUP_BATCH):
        c1 = min(c0 + SETUP_BATCH, e1)
        planes(tri, q, att, c0, c1, g, ok)
        for t in range(c0, c1):
            s = t - c0
            if not ok[s]:
                continue
            r0, r1 = rows_of(tri[t, 0, 1], tri[t, 1, 1], tri[t, 2, 1], height)
            r0 = max(r0, lo)
            r1 = min(min(r1, hi), r0 + spans.shape[1] - 1)   # (spans: a band's rows)
            x0 = tri[t, 0, 0]
            y0 = tri[t, 0, 1]
            # the tile test where an id buffer is drawn with a depth test (the other
            # variants fold it away and compile without it: about 0.9 s of a COLOR
            # variant's compilation, measured 2026-12-07)
            if (len(out) != COLOR and (len(depth) == TEST or len(depth) == CLEAR_TEST)
                    and t >= es and behind(zbuf, tiles, lo, hi, r0, r1,
                                           min(min(x0, tri[t, 1, 0]), tri[t, 2, 0]),
                                           max(max(x0, tri[t, 1, 0]), tri[t, 2, 0]), x0, y0,
                                           g[s, 0, 0], g[s, 0, 1], g[s, 0, 2])):
                continue
            low, mid, high = rising(tri[t, 0, 1], tri[t, 1, 1], tri[t, 2, 1])
            xa = tri[t, low, 0]
            ya = tri[t, low, 1]
            xb = tri[t, mid, 0]
            yb = tri[t, mid, 1]
            xc = tri[t, high, 0]
            yc = tri[t, high, 1]
            dzdx = g[s, 0, 1]
            dqdx = g[s, 1, 1]
            # 1/w = 1 everywhere (no w given): the attributes are linear on the screen,
            # and the division a/w / (1/w) is skipped (ids alone: no attributes)
            affine = len(out) == IDS or (g[s, 1, 0] == 1.0 and dqdx == 0.0
                                         and g[s, 1, 2] == 0.0)
            face = 0 if len(out) == COLOR else ids[t]
            # before es: drawn first, in the order of the ids (no ids: folded away)
            tie = len(out) != COLOR and ordered and t >= es
            for y in range(r0, r1 + 1):
                kl, kr = span_limits(y, xa, ya, xb, yb, xc, yc, width)
                spans[0, y - r0] = kl
                spans[1, y - r0] = kr
            for y in range(r0, r1 + 1):
                kl = spans[0, y - r0]
                kr = spans[1, y - r0]
                if kl >= kr:
                    continue
                fx = kl - x0
                fy = y - y0
                z = g[s, 0, 0] + g[s, 0, 1] * fx + g[s, 0, 2] * fy   # the left end
                if not affine:                  # 1/(1/w) at each pixel of the span
                    qs = g[s, 1, 0] + g[s, 1, 1] * fx + g[s, 1, 2] * fy
                    for i in range(kr - kl):
                        inverse[i] = 1.0 / (qs + dqdx * i)
                # without a branch on the depth test (random depths mispredict it): every
                # pixel of the span is written, with its old value where the test fails.
                # The indices are unsigned: numba then leaves out the wrap-around of
                # negative indices, a compare and a move per access (they lie in the
                # raster: span_limits and rows_of clamp them); the teapot's id raster
                # took 5% less time (measured 2026-12-07)
                yu = np.uint64(y)
                for xi in range(kl, kr):
                    x = np.uint64(xi)
                    win = True
                    iold = idbuf[yu, x] if len(out) != COLOR else 0
                    if len(depth) == TEST or len(depth) == CLEAR_TEST:
                        zold = zbuf[yu, x]
                        win = z < zold
                        if tie and z == zold:                   # (rare: a branch)
                            win = face < iold
                        zbuf[yu, x] = z if win else zold
                    elif len(depth) == PEEL:
                        zold = zbuf[yu, x]
                        win = (z < zold) & (z > floor[yu, x])
                        zbuf[yu, x] = z if win else zold
                    z += dzdx                                      # z' = z - A / C
                    if len(out) != COLOR:
                        idbuf[yu, x] = face if win else iold
                    if len(out) == IDS:
                        continue
                    i = xi - kl
                    r = 1.0 if affine else inverse[i]                  # a * 1.0 is exact
                    for c in range(CHANNELS if len(out) == COLOR else k):
                        if c >= kc:
                            break
                        a = (g[s, c + 2, 0] + g[s, c + 2, 1] * (fx + i)
                             + g[s, c + 2, 2] * fy) * r
                        if len(out) == COLOR:
                            a = min(max(a, 0.0), 255.0)
                            v = np.uint8(int(a + 0.5))
                            old = buf[yu, x, c]
                            buf[yu, x, c] = v if win else old
                        else:
                            old = abuf[yu, x, c]
                            abuf[yu, x, c] = a if win else old


@kernel
def raster_triangles(start, step, out, depth, tri, q, att, ids, starts, split, ordered, zbuf,
                     floor, buf, abuf, idbuf, g, ok, spans, tiles):
    """Draw the binned triangles band by band: the bands ``start``, ``start + step``
    ... (calls with start = 0 .. step - 1 on as many threads share the raster, each
    pixel written by its band's call only).

    ``tri`` (E, 3, 3) device x, y, depth per vertex; ``q`` (E, 3) 1/w per vertex
    (or no rows: 1 everywhere); ``att`` (E, 3, K) attributes per vertex; ``ids``
    (E,) the value each triangle writes into ``idbuf`` (not read for out COLOR):
    the entries of :func:`bin_pack`, band ``b``'s triangles at ``starts[b] ..
    starts[b + 1] - 1``, those from ``split[b]`` on drawn only where they are not
    behind the band's tiles as the triangles before them left them (:func:`behind`;
    ``split[b]`` = ``starts[b + 1]``: none).  ``ordered``: the entries are not in
    the order of their ids (:func:`raster_entries`).  Writes ``zbuf`` (H, W) (depth
    token TEST; PEEL: only between ``floor`` (H, W) and ``zbuf``; CLEAR_TEST: each
    band cleared first, with ``idbuf``), and ``buf`` (H, W', K) bytes (out COLOR) or
    ``abuf`` (H, W, K) and ``idbuf`` (H, W) (out ATTRIBUTES), or ``idbuf`` alone
    (out IDS).  ``g`` (T, :data:`SETUP_BATCH`, K + 2, 3) and ``ok`` (T,
    :data:`SETUP_BATCH`) are the setup's scratch, ``spans`` (T, 2, :data:`BAND`) the
    spans' (:func:`raster_entries`) and ``tiles`` (T, at least W /
    2^:data:`TILE_SHIFT`) the tile maxima's, row ``start % T`` this call's (one row
    per thread; made by the caller: numpy's allocation compiled into the kernel
    costs 0.1 s of a first call).  Returns a number of no meaning: the sum of the
    values read ahead (:data:`READ_AHEAD`; summed so that the reads are kept)."""
    height, width = zbuf.shape
    mine = start % g.shape[0]
    inverse = np.empty(width)               # (raster_entries: a span's 1 / (1/w))
    read = 0.0
    bands = starts.shape[0] - 1
    for b in range(start, bands, max(step, 1)):
        lo = b << BAND_SHIFT
        hi = min(lo + BAND - 1, height - 1)
        # a new frame: the band cleared on the core about to draw it; else the band's
        # lines read in order (READ_AHEAD)
        ahead = (starts[b + 1] - starts[b]) * READ_AHEAD >= width
        for y in range(lo, hi + 1):
            if len(depth) == CLEAR_TEST:
                for x in range(width):
                    zbuf[y, x] = math.inf
                if len(out) != COLOR:
                    for x in range(idbuf.shape[1]):
                        idbuf[y, x] = -1
            elif ahead and len(depth) != NO_TEST:
                for i in range(width >> 3):                  # 8 float64 a 64-byte line
                    read += zbuf[y, i << 3]
            if ahead and len(out) == COLOR:
                for i in range(buf.shape[1] >> 4):           # 16 pixels: 16 to 64 bytes
                    read += buf[y, i << 4, 0]
        if split[b] < starts[b + 1]:
            tiles[mine, :] = math.nan                       # no tile's maximum found yet
        raster_entries(out, depth, tri, q, att, ids, starts[b], starts[b + 1], split[b],
                       ordered, lo, hi, zbuf, floor, buf, abuf, idbuf, g[mine], ok[mine],
                       spans[mine], tiles[mine], inverse)
    return read

