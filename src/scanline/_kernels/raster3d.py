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


@kernel
def bin_count(tri, height, lo, hi, rows):
    """The first pass of binning triangles ``lo .. hi - 1`` by band (a counting
    sort; the chunks of a batch run on every core, and
    :func:`scanline.draw.triangles.bin_bands` joins them): ``rows[t]`` = (first
    row, last row) of triangle ``t`` clamped to the raster (first > last: none).
    Returns ``(counts, area)``: how many of the triangles meet each band, and the
    summed areas of their boxes (rows met times their x extent plus one, at most
    :data:`WIDEST` pixels), the work estimate of :func:`raster_triangles`."""
    counts = np.zeros(((height - 1) >> BAND_SHIFT) + 1, np.int64)
    area = 0.0
    for t in range(lo, hi):
        low = min(tri[t, 0, 1], tri[t, 1, 1], tri[t, 2, 1])
        high = max(tri[t, 0, 1], tri[t, 1, 1], tri[t, 2, 1])
        r0 = 1
        r1 = 0
        if low == low and high == high:            # not NaN
            flo = max(min(math.floor(low), height + 1.0), -2.0)
            fhi = max(min(math.floor(high), height + 1.0), -2.0)
            r0 = max(int(flo) + 1, 0)
            r1 = min(int(fhi), height - 1)
        rows[t, 0] = r0
        rows[t, 1] = r1
        if r0 <= r1:
            for b in range(r0 >> BAND_SHIFT, (r1 >> BAND_SHIFT) + 1):
                counts[b] += 1
            wide = (max(tri[t, 0, 0], tri[t, 1, 0], tri[t, 2, 0])
                    - min(tri[t, 0, 0], tri[t, 1, 0], tri[t, 2, 0]) + 1.0)
            area += (r1 - r0 + 1) * min(wide, WIDEST)
    return counts, area


@kernel
def bin_scatter(rows, lo, hi, fill, order):
    """The second pass: list each of triangles ``lo .. hi - 1`` at ``order[fill[b]]``
    for every band ``b`` its rows meet, advancing ``fill[b]`` (so each band lists
    its triangles in input order)."""
    for t in range(lo, hi):
        if rows[t, 0] <= rows[t, 1]:
            for b in range(rows[t, 0] >> BAND_SHIFT, (rows[t, 1] >> BAND_SHIFT) + 1):
                order[fill[b]] = t
                fill[b] += 1


@inline
def crossing(tri, t, lo, hi, y):
    """Where the edge from vertex ``lo`` (the lower) to ``hi`` of triangle ``t``
    crosses scan line ``y``: the 2-D polygon fill's expression."""
    xlo = tri[t, lo, 0]
    ylo = tri[t, lo, 1]
    return xlo + ((y - ylo) * (tri[t, hi, 0] - xlo)) / (tri[t, hi, 1] - ylo)


@inline
def setup(tri, q, att, t, g):
    """The linear functions of triangle ``t`` in screen space: row ``j`` of ``g``
    holds (value at vertex 0, d/dx, d/dy) of the depth (j = 0), of 1/w (j = 1) and
    of each attribute times 1/w (j = 2 ...).  Returns False for a triangle that
    covers no pixel: zero area, or a coordinate that is not finite."""
    x0 = tri[t, 0, 0]
    y0 = tri[t, 0, 1]
    ex1 = tri[t, 1, 0] - x0
    ey1 = tri[t, 1, 1] - y0
    ex2 = tri[t, 2, 0] - x0
    ey2 = tri[t, 2, 1] - y0
    area = ex1 * ey2 - ex2 * ey1
    if not (area != 0.0 and math.isfinite(area)):
        return False
    k = att.shape[2]
    r = 1.0 / area
    finite = 0.0
    for j in range(k + 2):
        if j == 0:
            f0 = tri[t, 0, 2]
            f1 = tri[t, 1, 2]
            f2 = tri[t, 2, 2]
        elif j == 1:
            f0 = q[t, 0]
            f1 = q[t, 1]
            f2 = q[t, 2]
        else:
            f0 = att[t, 0, j - 2] * q[t, 0]
            f1 = att[t, 1, j - 2] * q[t, 1]
            f2 = att[t, 2, j - 2] * q[t, 2]
        d1 = f1 - f0
        d2 = f2 - f0
        g[j, 0] = f0
        g[j, 1] = (d1 * ey2 - d2 * ey1) * r          # -A / C for the depth
        g[j, 2] = (d2 * ex1 - d1 * ex2) * r          # -B / C
        finite += 0.0 * (g[j, 0] + g[j, 1] + g[j, 2])  # NaN when any is not finite
    return finite == 0.0


@inline
def rising(tri, t):
    """Triangle ``t``'s vertices by rising y (ties keep index order, so that the
    horizontal edge is skipped): ``(low, mid, high)``."""
    low = 0
    mid = 1
    high = 2
    if tri[t, mid, 1] < tri[t, low, 1]:
        low, mid = mid, low
    if tri[t, high, 1] < tri[t, mid, 1]:
        mid, high = high, mid
        if tri[t, mid, 1] < tri[t, low, 1]:
            low, mid = mid, low
    return low, mid, high


@inline
def span_limits(tri, t, y, low, mid, high, width):
    """The span ``kl <= x < kr`` of triangle ``t`` (vertices ``low``, ``mid``,
    ``high`` by rising y) on scan line ``y``, clamped to ``0 .. width``."""
    xa = crossing(tri, t, low, high, y)                 # the long edge
    if y <= tri[t, mid, 1]:
        xb = crossing(tri, t, low, mid, y)
    else:
        xb = crossing(tri, t, mid, high, y)
    xl = min(xa, xb)
    xr = max(xa, xb)
    if not (xl <= xr):                                  # NaN
        return 0, 0
    xl = min(max(xl, -1.0), width + 1.0)
    xr = min(max(xr, -1.0), width + 1.0)
    kl = max(int(math.ceil(xl)), 0)
    kr = min(int(math.ceil(xr)), width)
    return kl, kr


@helper
def raster_triangle(out, depth, tri, q, att, ids, t, r0, r1, g, zbuf, floor, buf, abuf,
                    idbuf):
    """Scan-convert triangle ``t`` on rows ``r0 .. r1`` (already clamped): the step
    tables run it for one triangle and one row (:mod:`scanline.trace.zbuffer`)."""
    order = np.empty(1, np.int64)
    order[0] = t
    rows = np.empty((t + 1, 2), np.int64)
    rows[t, 0] = r0
    rows[t, 1] = r1
    raster_entries(out, depth, tri, q, att, ids, order, 0, 1, rows, r0, r1, g, zbuf, floor,
                   buf, abuf, idbuf)


@helper
def raster_entries(out, depth, tri, q, att, ids, order, e0, e1, rows, lo, hi, g, zbuf, floor,
                   buf, abuf, idbuf):
    """Scan-convert the triangles ``order[e0:e1]``, each on its rows ``rows[t]``
    within ``lo .. hi`` (one band): one call per band, the variants (the tokens
    ``out`` and ``depth``) folded here, the per-triangle steps inlined."""
    width = zbuf.shape[1]
    for e in range(e0, e1):
        t = order[e]
        r0 = max(rows[t, 0], lo)
        r1 = min(rows[t, 1], hi)
        if not setup(tri, q, att, t, g):
            continue
        k = att.shape[2]
        low, mid, high = rising(tri, t)
        x0 = tri[t, 0, 0]
        y0 = tri[t, 0, 1]
        dzdx = g[0, 1]
        dqdx = g[1, 1]
        # 1/w = 1 everywhere (no w given): the attributes are linear on the screen, and
        # the division a/w / (1/w) is skipped
        affine = g[1, 0] == 1.0 and dqdx == 0.0 and g[1, 2] == 0.0
        face = ids[t]
        for y in range(r0, r1 + 1):
            kl, kr = span_limits(tri, t, y, low, mid, high, width)
            if kl >= kr:
                continue
            fx = kl - x0
            fy = y - y0
            z = g[0, 0] + g[0, 1] * fx + g[0, 2] * fy          # the left end, from the plane
            qs = g[1, 0] + g[1, 1] * fx + g[1, 2] * fy
            for x in range(kl, kr):
                if len(depth) == TEST or len(depth) == CLEAR_TEST:
                    if not (z < zbuf[y, x]):
                        z += dzdx                              # z' = z - A / C
                        continue
                    zbuf[y, x] = z
                elif len(depth) == PEEL:
                    if not (z < zbuf[y, x] and z > floor[y, x]):
                        z += dzdx
                        continue
                    zbuf[y, x] = z
                if len(out) == IDS:
                    idbuf[y, x] = face
                    z += dzdx
                    continue
                i = x - kl
                r = 1.0 if affine else 1.0 / (qs + dqdx * i)      # a * 1.0 is exact
                if len(out) == COLOR:
                    for c in range(k):
                        a = (g[c + 2, 0] + g[c + 2, 1] * (fx + i) + g[c + 2, 2] * fy) * r
                        a = min(max(a, 0.0), 255.0)
                        buf[y, x, c] = np.uint8(int(a + 0.5))
                else:
                    for c in range(k):
                        abuf[y, x, c] = (g[c + 2, 0] + g[c + 2, 1] * (fx + i)
                                         + g[c + 2, 2] * fy) * r
                    idbuf[y, x] = face
                z += dzdx


@kernel
def raster_triangles(start, step, out, depth, tri, q, att, ids, rows, starts, order, zbuf,
                     floor, buf, abuf, idbuf):
    """Draw the binned triangles band by band: the bands ``start``, ``start + step``
    ... (calls with start = 0 .. step - 1 on as many threads share the raster, each
    pixel written by its band's call only).

    ``tri`` (N, 3, 3) device x, y, depth per vertex; ``q`` (N, 3) 1/w per vertex;
    ``att`` (N, 3, K) attributes per vertex; ``ids`` (N,) the value each triangle
    writes into ``idbuf``; ``rows``, ``starts``, ``order`` from
    :func:`scanline.draw.triangles.bin_bands`.  Writes ``zbuf`` (H, W) (depth token TEST; PEEL: only
    between ``floor`` (H, W) and ``zbuf``; CLEAR_TEST: each band cleared first, with
    ``idbuf``), and ``buf`` (H, W', K) bytes (out COLOR)
    or ``abuf`` (H, W, K) and ``idbuf`` (H, W) (out ATTRIBUTES), or ``idbuf`` alone
    (out IDS)."""
    height = zbuf.shape[0]
    bands = starts.shape[0] - 1
    g = np.empty((att.shape[2] + 2, 3))
    for b in range(start, bands, max(step, 1)):
        lo = b << BAND_SHIFT
        hi = min(lo + BAND - 1, height - 1)
        if len(depth) == CLEAR_TEST:
            for y in range(lo, hi + 1):
                for x in range(zbuf.shape[1]):
                    zbuf[y, x] = math.inf
                if len(out) != COLOR:
                    for x in range(idbuf.shape[1]):
                        idbuf[y, x] = -1
        raster_entries(out, depth, tri, q, att, ids, order, starts[b], starts[b + 1], rows, lo,
                       hi, g, zbuf, floor, buf, abuf, idbuf)

