"""Random test shapes and the shapely side of the clipping cross-checks."""

import numpy as np

import shapely


def star_polygon(rng, n, center=(0.0, 0.0), r=(2.0, 10.0), integer=False):
    """A simple polygon, star-shaped about ``center``: n vertices at increasing
    angles with random radii (concave for most draws)."""
    for _ in range(100):
        ang = np.sort(rng.uniform(0, 2 * np.pi, n))
        rad = rng.uniform(r[0], r[1], n)
        p = np.stack([center[0] + rad * np.cos(ang), center[1] + rad * np.sin(ang)], axis=1)
        if integer:
            p = np.round(p)
            # keep vertices at strictly increasing angles about a non-lattice center
            c = np.array(center) + 0.123456
            a = np.arctan2(p[:, 1] - c[1], p[:, 0] - c[0])
            order = np.argsort(a)
            p, a = p[order], a[order]
            keep = np.concatenate([[True], np.diff(a) > 1e-9])
            p = p[keep]
        if len(p) >= 3 and shapely.Polygon(p).is_valid and shapely.Polygon(p).area > 0:
            return p
    raise RuntimeError("no valid polygon drawn")


def convex_polygon(rng, n, center=(0.0, 0.0), radius=8.0):
    """A convex polygon: the hull of random points."""
    pts = rng.normal(size=(n + 3, 2)) * radius + np.asarray(center)
    hull = shapely.MultiPoint(pts).convex_hull
    return np.asarray(hull.exterior.coords)[:-1]


def area(contours):
    """Total signed (shoelace) area of contours."""
    total = 0.0
    for c in contours:
        x, y = c[:, 0], c[:, 1]
        total += 0.5 * (np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))
    return total


def shapely_segments(segments, window_geom):
    """Each segment intersected with a closed window by shapely: (N, 4) endpoints
    (a point result repeats the point) and an accepted mask."""
    lines = shapely.linestrings(segments.reshape(-1, 2, 2))
    res = shapely.intersection(lines, window_geom)
    out = np.full(segments.shape, np.nan)
    ok = ~shapely.is_empty(res)
    coords, index = shapely.get_coordinates(res, return_index=True)
    for i in np.nonzero(ok)[0]:
        c = coords[index == i]
        out[i] = [c[0, 0], c[0, 1], c[-1, 0], c[-1, 1]]
    return out, ok


def same_segments(a, b, atol):
    """Whether rows of a and b are the same segments (either direction)."""
    fwd = np.abs(a - b).max(axis=1) <= atol
    rev = np.abs(a - b[:, [2, 3, 0, 1]]).max(axis=1) <= atol
    return fwd | rev
