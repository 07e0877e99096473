"""Compiled form-factor kernels: rows of the form-factor matrix by the hemicube
(Cohen and Greenberg 1985) and by ray casting (Wallace, Elmquist and Haines 1989).

Every write goes to ``out[r, j]`` with ``r`` a row of the loop and ``j`` a patch
number of the loop (0 <= j < P), or to the local buffers at pixel indices clamped to
their shape: nothing outside the arrays, whatever the coordinates (NaN corners are
refused by the API layer; a NaN projection fails every comparison and draws nothing).
"""

import math

import numpy as np
from ._jit import helper, kernel, slow_to_compile
from .bvh import STACK, transmittance


@helper
def _view(normal, edge, g, f, view):
    """``view`` (3, 3) := the axes of face ``f`` of the hemicube on source ``g``:
    looking direction, the image's horizontal and vertical.  The cube's axes are n
    (the source's ``normal``), u (its ``edge`` made perpendicular to n) and w = n x u;
    face 0 is the top (looking along n; image axes u, w), faces 1-4 the half sides
    looking along +u, -u, +w, -w (horizontal the other tangent, vertical n)."""
    nx, ny, nz = normal[g, 0], normal[g, 1], normal[g, 2]
    ex, ey, ez = edge[g, 0], edge[g, 1], edge[g, 2]
    d = ex * nx + ey * ny + ez * nz
    if not (ex - d * nx) ** 2 + (ey - d * ny) ** 2 + (ez - d * nz) ** 2 > 0.0:
        # (a patch's edge is never along its normal; a group's mean normal may be)
        ex, ey, ez = (1.0, 0.0, 0.0) if abs(nx) < 0.9 else (0.0, 1.0, 0.0)
        d = ex * nx + ey * ny + ez * nz
    ux, uy, uz = ex - d * nx, ey - d * ny, ez - d * nz
    length = math.sqrt(ux * ux + uy * uy + uz * uz)
    ux /= length
    uy /= length
    uz /= length
    wx, wy, wz = ny * uz - nz * uy, nz * ux - nx * uz, nx * uy - ny * ux
    sign = -1.0 if f == 2 or f == 4 else 1.0
    if f == 0:
        view[0, 0], view[0, 1], view[0, 2] = nx, ny, nz
        view[1, 0], view[1, 1], view[1, 2] = ux, uy, uz
        view[2, 0], view[2, 1], view[2, 2] = wx, wy, wz
    elif f <= 2:
        view[0, 0], view[0, 1], view[0, 2] = sign * ux, sign * uy, sign * uz
        view[1, 0], view[1, 1], view[1, 2] = wx, wy, wz
        view[2, 0], view[2, 1], view[2, 2] = nx, ny, nz
    else:
        view[0, 0], view[0, 1], view[0, 2] = sign * wx, sign * wy, sign * wz
        view[1, 0], view[1, 1], view[1, 2] = ux, uy, uz
        view[2, 0], view[2, 1], view[2, 2] = nx, ny, nz


@helper
def _clip_project(quads, j, cx, cy, cz, view, near, half, ylo, px, py):
    """Patch ``j`` in the face's view: its corners relative to the eye (cx, cy, cz),
    clipped to depth > ``near`` (Sutherland-Hodgman against one plane) and projected
    to pixel coordinates (x / depth, y / depth scaled by ``half`` cells per unit,
    pixel centres at integers; ``ylo`` the image's lowest y).  Returns the number of
    vertices written to ``px``, ``py`` (0 when nothing is in front)."""
    a = np.empty(4)
    h = np.empty(4)
    g = np.empty(4)
    ahead = 0
    for k in range(4):
        dx = quads[j, k, 0] - cx
        dy = quads[j, k, 1] - cy
        dz = quads[j, k, 2] - cz
        a[k] = dx * view[0, 0] + dy * view[0, 1] + dz * view[0, 2]
        h[k] = dx * view[1, 0] + dy * view[1, 1] + dz * view[1, 2]
        g[k] = dx * view[2, 0] + dy * view[2, 1] + dz * view[2, 2]
        if a[k] > near:
            ahead += 1
    if ahead == 0:
        return 0
    m = 0
    for k in range(4):
        n = (k + 1) % 4
        if a[k] > near:
            px[m] = h[k] / a[k]
            py[m] = g[k] / a[k]
            m += 1
        if (a[k] > near) != (a[n] > near):
            t = (near - a[k]) / (a[n] - a[k])
            px[m] = (h[k] + t * (h[n] - h[k])) / near
            py[m] = (g[k] + t * (g[n] - g[k])) / near
            m += 1
    for k in range(m):
        px[k] = (px[k] + 1.0) * half - 0.5
        py[k] = (py[k] - ylo) * half - 0.5
    return m


@helper
def _draw(j, px, py, m, plane, ids, depth, rows, cols, half, ylo):
    """Scan-convert the convex polygon (``px``, ``py``, ``m`` vertices) of patch ``j``
    into the item buffer ``ids`` with the z-buffer ``depth`` (rows x cols used):
    a pixel centre inside (edge functions of one sign) takes ``j`` where the patch's
    plane (``plane``: its normal in the view's axes and its offset) is nearer along
    the pixel's ray than what the buffer holds."""
    area = 0.0
    for k in range(m):
        n = (k + 1) % m
        area += px[k] * py[n] - px[n] * py[k]
    if not abs(area) > 1e-12:
        return
    s = 1.0 if area > 0 else -1.0
    x0 = px[0]
    x1 = px[0]
    y0 = py[0]
    y1 = py[0]
    for k in range(1, m):
        x0 = min(x0, px[k])
        x1 = max(x1, px[k])
        y0 = min(y0, py[k])
        y1 = max(y1, py[k])
    if not (x1 >= 0.0 and y1 >= 0.0 and x0 <= cols - 1.0 and y0 <= rows - 1.0):
        return
    c0 = int(math.ceil(max(x0, 0.0)))
    c1 = int(math.floor(min(x1, cols - 1.0)))
    r0 = int(math.ceil(max(y0, 0.0)))
    r1 = int(math.floor(min(y1, rows - 1.0)))
    for r in range(r0, r1 + 1):
        y = float(r)
        yv = (y + 0.5) / half + ylo
        for c in range(c0, c1 + 1):
            x = float(c)
            inside = True
            for k in range(m):
                n = (k + 1) % m
                if s * ((px[n] - px[k]) * (y - py[k]) - (py[n] - py[k]) * (x - px[k])) < 0.0:
                    inside = False
                    break
            if not inside:
                continue
            xv = (x + 0.5) / half - 1.0
            den = plane[0] + plane[1] * xv + plane[2] * yv
            if den == 0.0:
                continue
            t = plane[3] / den
            if t > 0.0 and t < depth[r, c]:
                depth[r, c] = t
                ids[r, c] = j


@kernel
def hemicube_rows(start, step, sources, source, snormal, sedge, group, quads, centre, normal,
                  near, res, top, side, out):
    """Rows start, start + step, ... of ``sources`` by the hemicube into ``out`` (R, P)
    (one band of interleaved rows per thread of the API layer).  Row r holds the form
    factors from source g = sources[r] (its centre ``source[g]``, normal
    ``snormal[g]``, first edge ``sedge[g]``: a patch, or a group of patches that shoots
    together) to every patch: the five faces of its hemicube drawn as item buffers of
    patch numbers by the z-buffer (the patches of ``group`` g, the source itself, left
    out), each pixel's delta form factor (``top`` (res, res), ``side`` (res / 2, res))
    added to ``out[r, j]`` of the patch j seen there, if j faces the source (a back
    face hides what is behind it but sends nothing)."""
    p = quads.shape[0]
    view = np.empty((3, 3))
    plane = np.empty(4)
    px = np.empty(8)
    py = np.empty(8)
    ids = np.empty((res, res), np.int64)
    depth = np.empty((res, res))
    half = res / 2.0
    for r in range(start, sources.shape[0], step):
        g = sources[r]
        if g < 0 or g >= source.shape[0]:
            continue
        cx, cy, cz = source[g, 0], source[g, 1], source[g, 2]
        for j in range(p):
            out[r, j] = 0.0
        for f in range(5):
            _view(snormal, sedge, g, f, view)
            rows = res if f == 0 else res // 2
            ylo = -1.0 if f == 0 else 0.0
            for y in range(rows):
                for x in range(res):
                    ids[y, x] = -1
                    depth[y, x] = np.inf
            for j in range(p):
                if group[j] == g:
                    continue
                m = _clip_project(quads, j, cx, cy, cz, view, near, half, ylo, px, py)
                if m < 3:
                    continue
                for k in range(3):
                    plane[k] = (normal[j, 0] * view[k, 0] + normal[j, 1] * view[k, 1]
                                + normal[j, 2] * view[k, 2])
                plane[3] = (normal[j, 0] * (centre[j, 0] - cx)
                            + normal[j, 1] * (centre[j, 1] - cy)
                            + normal[j, 2] * (centre[j, 2] - cz))
                _draw(j, px, py, m, plane, ids, depth, rows, res, half, ylo)
            for y in range(rows):
                for x in range(res):
                    j = ids[y, x]
                    if j < 0 or j >= p:
                        continue
                    facing = (normal[j, 0] * (cx - centre[j, 0])
                              + normal[j, 1] * (cy - centre[j, 1])
                              + normal[j, 2] * (cz - centre[j, 2]))
                    if facing > 0.0:
                        out[r, j] += top[y, x] if f == 0 else side[y, x]


@helper
def point_to_patch(cx, cy, cz, nx, ny, nz, j, quads, normal, k, bounds, links, table, clear,
                   stack):
    """The form factor from the differential area at (cx, cy, cz) with normal n to
    patch j: k x k points y on j (centres of the cells of its bilinear parameters,
    each of area dA = |dP/ds x dP/dt| / k**2), the sum of cos(theta_i) cos(theta_j)
    dA / (pi r**2 + dA) over the points seen from the differential area (a shadow
    ray through the bounding volume hierarchy): Wallace, Elmquist and Haines 1989,
    equation 4."""
    total = 0.0
    for a in range(k):
        t = (a + 0.5) / k
        for b in range(k):
            s = (b + 0.5) / k
            w0 = (1 - s) * (1 - t)
            w1 = s * (1 - t)
            w2 = s * t
            w3 = (1 - s) * t
            yx = (w0 * quads[j, 0, 0] + w1 * quads[j, 1, 0] + w2 * quads[j, 2, 0]
                  + w3 * quads[j, 3, 0])
            yy = (w0 * quads[j, 0, 1] + w1 * quads[j, 1, 1] + w2 * quads[j, 2, 1]
                  + w3 * quads[j, 3, 1])
            yz = (w0 * quads[j, 0, 2] + w1 * quads[j, 1, 2] + w2 * quads[j, 2, 2]
                  + w3 * quads[j, 3, 2])
            dx = yx - cx
            dy = yy - cy
            dz = yz - cz
            r2 = dx * dx + dy * dy + dz * dz
            if not r2 > 0.0:
                continue
            rn = math.sqrt(r2)
            ci = (dx * nx + dy * ny + dz * nz) / rn
            cj = -(dx * normal[j, 0] + dy * normal[j, 1] + dz * normal[j, 2]) / rn
            if ci <= 0.0 or cj <= 0.0:
                continue
            # dP/ds and dP/dt of the bilinear patch at (s, t)
            sx = ((1 - t) * (quads[j, 1, 0] - quads[j, 0, 0])
                  + t * (quads[j, 2, 0] - quads[j, 3, 0]))
            sy = ((1 - t) * (quads[j, 1, 1] - quads[j, 0, 1])
                  + t * (quads[j, 2, 1] - quads[j, 3, 1]))
            sz = ((1 - t) * (quads[j, 1, 2] - quads[j, 0, 2])
                  + t * (quads[j, 2, 2] - quads[j, 3, 2]))
            tx = ((1 - s) * (quads[j, 3, 0] - quads[j, 0, 0])
                  + s * (quads[j, 2, 0] - quads[j, 1, 0]))
            ty = ((1 - s) * (quads[j, 3, 1] - quads[j, 0, 1])
                  + s * (quads[j, 2, 1] - quads[j, 1, 1]))
            tz = ((1 - s) * (quads[j, 3, 2] - quads[j, 0, 2])
                  + s * (quads[j, 2, 2] - quads[j, 1, 2]))
            ax = sy * tz - sz * ty
            ay = sz * tx - sx * tz
            az = sx * ty - sy * tx
            da = math.sqrt(ax * ax + ay * ay + az * az) / (k * k)
            if transmittance(cx, cy, cz, dx, dy, dz, 1e-6, 1.0 - 1e-6, bounds, links, table,
                             clear, stack) <= 0.0:
                continue
            total += ci * cj * da / (math.pi * r2 + da)
    return total


@helper
def raycast_row(i, quads, centre, normal, k, bounds, links, table, clear, stack, row,
                column):
    """Row ``i`` of the form factors by ray casting, from the centre of patch i to
    every patch j (``column`` False); or column ``i``, from the centre of every patch
    j to patch i (``column`` True: what each receiver j gets of what i shoots, area to
    differential area, as progressive refinement by ray casting wants it)."""
    for j in range(quads.shape[0]):
        row[j] = 0.0
        if j == i:
            continue
        if column:
            row[j] = point_to_patch(centre[j, 0], centre[j, 1], centre[j, 2], normal[j, 0],
                                    normal[j, 1], normal[j, 2], i, quads, normal, k, bounds,
                                    links, table, clear, stack)
        else:
            row[j] = point_to_patch(centre[i, 0], centre[i, 1], centre[i, 2], normal[i, 0],
                                    normal[i, 1], normal[i, 2], j, quads, normal, k, bounds,
                                    links, table, clear, stack)


@kernel
def raycast_rows(start, step, sources, quads, centre, normal, k, bounds, links, table, clear,
                 column, out):
    """Rows (or with ``column`` columns) ``sources`` of the form-factor matrix by ray
    casting into ``out`` (R, P): rows start, start + step, ... (one band per thread)."""
    stack = np.empty(STACK, np.int64)
    for r in range(start, sources.shape[0], step):
        i = sources[r]
        if i < 0 or i >= quads.shape[0]:
            continue
        raycast_row(i, quads, centre, normal, k, bounds, links, table, clear, stack, out[r],
                    column)


#: The ray-cast form factors take about 2.2 s to compile (benchmarks/compile.py): the
#: twin computes a small box's rows first (the first-use case, a Cornell box of
#: subdivisions=1: 80 calls, 0.3 s as Python, past a twin's default time).
slow_to_compile(raycast_rows, 2.2)
