"""Plain-Python references for the visible-surface tests: ray casting at pixel
centers, written independently of scanline's kernels."""

import math

#: A pixel center closer than this (pixels) to a polygon edge is a tie on a
#: shared edge: the methods may legitimately differ there.
EDGE_TIE = 1e-6
#: Two depths closer than this at a pixel center are a tie (intersection lines).
DEPTH_TIE = 1e-7


def _inside(poly, x, y):
    """Strictly inside the convex polygon (list of (x, y, z)), and the distance of
    (x, y) to its boundary."""
    n = len(poly)
    area = sum(poly[i][0] * poly[(i + 1) % n][1] - poly[(i + 1) % n][0] * poly[i][1]
               for i in range(n))
    sign = 1.0 if area > 0 else -1.0
    dmin = math.inf
    inside = True
    for i in range(n):
        (x0, y0, _), (x1, y1, _) = poly[i], poly[(i + 1) % n]
        ex, ey = x1 - x0, y1 - y0
        length = math.hypot(ex, ey)
        d = sign * (ex * (y - y0) - ey * (x - x0)) / length
        if d <= 0:
            inside = False
        # distance to the segment
        t = max(0.0, min(1.0, ((x - x0) * ex + (y - y0) * ey) / (length * length)))
        dmin = min(dmin, math.hypot(x - x0 - t * ex, y - y0 - t * ey))
    return inside, dmin


def _plane(poly):
    (x0, y0, z0), (x1, y1, z1), (x2, y2, z2) = poly[0], poly[1], poly[2]
    # a robust normal: Newell
    n = len(poly)
    a = sum((poly[i][1] - poly[(i + 1) % n][1]) * (poly[i][2] + poly[(i + 1) % n][2])
            for i in range(n))
    b = sum((poly[i][2] - poly[(i + 1) % n][2]) * (poly[i][0] + poly[(i + 1) % n][0])
            for i in range(n))
    c = sum((poly[i][0] - poly[(i + 1) % n][0]) * (poly[i][1] + poly[(i + 1) % n][1])
            for i in range(n))
    return a, b, c, -(a * x0 + b * y0 + c * z0)


def ray_cast(polygons, faces, width, height):
    """``(face, ambiguous)``: the face index nearest along the ray through each
    pixel center (-1: none), as lists of rows (row y = scan line y), and whether the
    pixel is a tie (a center near some edge, or two depths within DEPTH_TIE)."""
    planes = [_plane(p) for p in polygons]
    face = [[-1] * width for _ in range(height)]
    tie = [[False] * width for _ in range(height)]
    for y in range(height):
        for x in range(width):
            hits = []
            near_edge = False
            for poly, (a, b, c, d), f in zip(polygons, planes, faces):
                xs = [p[0] for p in poly]
                ys = [p[1] for p in poly]
                if x < min(xs) - 1 or x > max(xs) + 1 or y < min(ys) - 1 or y > max(ys) + 1:
                    continue
                inside, dist = _inside(poly, x, y)
                if dist < EDGE_TIE:
                    near_edge = True
                if inside:
                    hits.append((-(a * x + b * y + d) / c, f))
            hits.sort()
            if hits:
                face[y][x] = hits[0][1]
                if len(hits) > 1 and hits[1][0] - hits[0][0] < DEPTH_TIE:
                    tie[y][x] = True
            tie[y][x] = tie[y][x] or near_edge
    return face, tie
