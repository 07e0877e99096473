"""An independent reference for the tests of :mod:`scanline.mpl`: which 3-D polygon a
pixel of a matplotlib canvas sees, found by casting the pixel's ray through the
axes' own projection (``ax.M`` inverted, ``ax.transData`` inverted) against the
scene's planar polygons given analytically in data coordinates -- no scanline code.

Also: the canvas as labels (each pixel the nearest of a palette of colors).
"""

import numpy as np


def canvas(fig):
    """The Agg canvas as an (H, W, 3) uint8 array (draws the figure)."""
    fig.canvas.draw()
    return np.asarray(fig.canvas.buffer_rgba())[..., :3].copy()


def labels(image, palette, tolerance=40.0):
    """Each pixel of ``image`` as the index of the nearest color of ``palette`` ((L, 3)
    0..255), or -1 when none is within ``tolerance``."""
    pal = np.asarray(palette, np.float64)
    d = np.linalg.norm(image[:, :, None, :].astype(np.float64) - pal[None, None], axis=3)
    out = d.argmin(axis=2)
    out[d.min(axis=2) > tolerance] = -1
    return out


def _project(M, xyz):
    h = np.c_[xyz, np.ones(len(xyz))] @ M.T
    return h[:, :3] / h[:, 3:4]


def pixel_rays(ax, fig, rows, cols):
    """World-space points (N, 3) twice, two points of the ray of each pixel (row,
    col) of the canvas (pixel centers), by inverting matplotlib's projection."""
    H = fig.canvas.get_width_height(physical=True)[1]
    disp = np.stack([cols + 0.5, H - (rows + 0.5)], axis=1)
    xy = ax.transData.inverted().transform(disp)
    invM = np.linalg.inv(ax.M)
    ends = []
    for z in (-0.5, 0.5):
        h = np.c_[xy, np.full(len(xy), z), np.ones(len(xy))] @ invM.T
        ends.append(h[:, :3] / h[:, 3:4])
    return ends[0], ends[1]


def seen(ax, fig, polygons, rows, cols):
    """For each pixel (row, col), the label of the nearest polygon its ray meets, or
    -1; and the projected depth of that hit (inf where none).  ``polygons`` is a list
    of (label, (K, 3) world vertices of a convex planar polygon)."""
    p0, p1 = pixel_rays(ax, fig, rows, cols)
    d = p1 - p0
    H = fig.canvas.get_width_height(physical=True)[1]
    best = np.full(len(rows), np.inf)
    label = np.full(len(rows), -1)
    for lab, poly in polygons:
        poly = np.asarray(poly, np.float64)
        # only the pixels near the polygon's projection (its box, a pixel wider)
        disp = ax.transData.transform(_project(ax.M, poly)[:, :2])
        r0, r1 = H - disp[:, 1].max() - 1.5, H - disp[:, 1].min() + 0.5
        c0, c1 = disp[:, 0].min() - 1.5, disp[:, 0].max() + 0.5
        near = np.flatnonzero((rows >= r0) & (rows <= r1) & (cols >= c0) & (cols <= c1))
        if not len(near):
            continue
        a, e = p0[near], d[near]
        n = np.cross(poly[1] - poly[0], poly[2] - poly[0])
        for k in range(3, len(poly)):           # a robust normal for longer polygons
            n = n + np.cross(poly[k - 1] - poly[0], poly[k] - poly[0])
        with np.errstate(invalid="ignore", divide="ignore"):
            t = ((poly[0] - a) @ n) / (e @ n)
        hit = a + t[:, None] * e
        drop = int(np.argmax(np.abs(n)))
        keep = [i for i in range(3) if i != drop]
        q = poly[:, keep]
        h = hit[:, keep]
        edge = np.roll(q, -1, axis=0) - q
        cross = edge[None, :, 0] * (h[:, None, 1] - q[None, :, 1]) - edge[None, :, 1] * (
            h[:, None, 0] - q[None, :, 0])
        inside = ((cross >= 0).all(axis=1) | (cross <= 0).all(axis=1)) & np.isfinite(t)
        z = np.full(len(near), np.inf)
        if inside.any():
            z[inside] = _project(ax.M, hit[inside])[:, 2]
        nearer = inside & (z < best[near])
        best[near[nearer]] = z[nearer]
        label[near[nearer]] = lab
    return label, best


def expected_image(ax, fig, polygons, step=2):
    """The reference labels on a grid of pixels every ``step`` over the axes:
    ``(rows, cols, label)`` with rows, cols 2-D index grids."""
    W, H = fig.canvas.get_width_height(physical=True)
    bb = ax.bbox
    c = np.arange(int(bb.x0), int(bb.x1), step)
    r = np.arange(int(H - bb.y1), int(H - bb.y0), step)
    R, C = np.meshgrid(r, c, indexing="ij")
    lab, _ = seen(ax, fig, polygons, R.ravel(), C.ravel())
    return R, C, lab.reshape(R.shape)


def interior(label, margin=2):
    """Grid points whose label is the same ``margin`` grid steps around (away from
    edges and intersection lines, where antialiasing and rounding decide)."""
    ok = label >= 0
    for dy in range(-margin, margin + 1):
        for dx in range(-margin, margin + 1):
            shifted = np.full_like(label, -2)
            ys = slice(max(dy, 0), label.shape[0] + min(dy, 0))
            yd = slice(max(-dy, 0), label.shape[0] + min(-dy, 0))
            xs = slice(max(dx, 0), label.shape[1] + min(dx, 0))
            xd = slice(max(-dx, 0), label.shape[1] + min(-dx, 0))
            shifted[yd, xd] = label[ys, xs]
            ok &= shifted == label
    return ok


def agreement(image, palette, ax, fig, polygons, step=2, margin=2):
    """The fraction of interior reference pixels where the rendered ``image`` shows
    the polygon the reference sees, and how many pixels were compared."""
    R, C, lab = expected_image(ax, fig, polygons, step)
    mask = interior(lab, margin)
    got = labels(image, palette)[R, C]
    return float((got[mask] == lab[mask]).mean()), int(mask.sum())


def box(x, y, z, dx, dy, dz):
    """The six faces of an axis-aligned box, as (K, 3) arrays."""
    X, Y, Z = x + dx, y + dy, z + dz
    return [np.array(f, np.float64) for f in (
        [(x, y, z), (X, y, z), (X, Y, z), (x, Y, z)],
        [(x, y, Z), (X, y, Z), (X, Y, Z), (x, Y, Z)],
        [(x, y, z), (X, y, z), (X, y, Z), (x, y, Z)],
        [(x, Y, z), (X, Y, z), (X, Y, Z), (x, Y, Z)],
        [(x, y, z), (x, Y, z), (x, Y, Z), (x, y, Z)],
        [(X, y, z), (X, Y, z), (X, Y, Z), (X, y, Z)])]


def point_hidden(ax, fig, polygons, xyz):
    """Whether each world point is hidden by one of ``polygons`` (its pixel's ray meets
    a polygon nearer than the point), with the point's pixel (row, col), rounded."""
    H = fig.canvas.get_width_height(physical=True)[1]
    p = _project(ax.M, np.asarray(xyz, np.float64))
    disp = ax.transData.transform(p[:, :2])
    # the ray through the point itself (not the pixel center)
    invM = np.linalg.inv(ax.M)
    ends = []
    for z in (-0.5, 0.5):
        h = np.c_[p[:, :2], np.full(len(p), z), np.ones(len(p))] @ invM.T
        ends.append(h[:, :3] / h[:, 3:4])
    rows = H - disp[:, 1]
    cols = disp[:, 0]
    best = np.full(len(p), np.inf)
    d = ends[1] - ends[0]
    for _, poly in polygons:
        poly = np.asarray(poly, np.float64)
        n = np.cross(poly[1] - poly[0], poly[2] - poly[0])
        with np.errstate(invalid="ignore", divide="ignore"):
            t = ((poly[0] - ends[0]) @ n) / (d @ n)
        hit = ends[0] + t[:, None] * d
        drop = int(np.argmax(np.abs(n)))
        keep = [i for i in range(3) if i != drop]
        q, h = poly[:, keep], hit[:, keep]
        e = np.roll(q, -1, axis=0) - q
        cross = e[None, :, 0] * (h[:, None, 1] - q[None, :, 1]) - e[None, :, 1] * (
            h[:, None, 0] - q[None, :, 0])
        inside = ((cross >= 0).all(axis=1) | (cross <= 0).all(axis=1)) & np.isfinite(t)
        z = np.full(len(p), np.inf)
        if inside.any():
            z[inside] = _project(ax.M, hit[inside])[:, 2]
        best = np.minimum(best, z)
    return best < p[:, 2] - 1e-9, rows, cols
