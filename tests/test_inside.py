"""sl.geometry.inside and winding_number: the two inside-outside rules against
shapely and an angle-sum winding number, the boundary (top-left) convention,
several contours, shapes and bad input.
"""

import math

import numpy as np
import pytest
import shapely
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from tests.reference import HYPOTHESIS


def angle_winding(p, poly):
    """Winding number as the total turning angle / 2 pi (a point off the boundary)."""
    total = 0.0
    n = len(poly)
    for i in range(n):
        ax, ay = poly[i][0] - p[0], poly[i][1] - p[1]
        bx, by = poly[(i + 1) % n][0] - p[0], poly[(i + 1) % n][1] - p[1]
        total += math.atan2(ax * by - ay * bx, ax * bx + ay * by)
    return round(total / (2 * math.pi))


def star(rng, n, r=10.0):
    ang = np.sort(rng.uniform(0, 2 * np.pi, n))
    rad = rng.uniform(0.3 * r, r, n)
    return np.stack([rad * np.cos(ang), rad * np.sin(ang)], axis=1)


def off_boundary(points, poly, margin=1e-6):
    ring = shapely.LinearRing(poly)
    return shapely.distance(shapely.points(points), ring) > margin


def test_pentagram_rules_and_winding():
    pent = [(0, 3), (8, 3), (1, -3), (4, 7), (7, -3)]
    center, tip, outside = (4, 1.2), (4, 5), (-1, -1)
    assert sl.geometry.inside([center, tip, outside], pent).tolist() == [False, True, False]
    assert sl.geometry.inside([center, tip, outside], pent, "nonzero").tolist() == [True, True, False]
    w = sl.geometry.winding_number([center, tip, outside], pent)
    assert w.tolist() == [angle_winding(center, pent), angle_winding(tip, pent), 0]
    assert abs(w[0]) == 2 and abs(w[1]) == 1


def test_simple_polygons_match_shapely():
    rng = np.random.default_rng(1)
    for _ in range(30):
        poly = star(rng, int(rng.integers(3, 25))) + rng.uniform(-5, 5, 2)
        pts = rng.uniform(-16, 16, (400, 2))
        keep = off_boundary(pts, poly)
        want = shapely.contains_xy(shapely.Polygon(poly), pts[:, 0], pts[:, 1])
        for rule in ("even-odd", "nonzero"):
            got = sl.geometry.inside(pts, poly, rule)
            np.testing.assert_array_equal(got[keep], want[keep])


def test_self_intersecting_winding_matches_angle_sum():
    rng = np.random.default_rng(2)
    for _ in range(20):
        poly = rng.uniform(-10, 10, (int(rng.integers(3, 10)), 2))
        pts = rng.uniform(-11, 11, (60, 2))
        keep = off_boundary(pts, poly)
        w = sl.geometry.winding_number(pts, poly)
        ref = np.array([angle_winding(p, poly) for p in pts])
        np.testing.assert_array_equal(w[keep], ref[keep])
        np.testing.assert_array_equal(sl.geometry.inside(pts, poly, "nonzero"), w != 0)
        np.testing.assert_array_equal(sl.geometry.inside(pts, poly), (w % 2) == 1)


def test_boundary_follows_the_top_left_rule():
    sq = [(0, 0), (4, 0), (4, 4), (0, 4)]
    pts = [(0, 2), (4, 2), (2, 4), (2, 0), (0, 4), (4, 4), (0, 0), (4, 0)]
    #      left    right   top     bottom  corners: top-left in, the others out
    assert sl.geometry.inside(pts, sq).tolist() == [True, False, True, False,
                                                    True, False, False, False]
    # the same points with float edges (a square 0.5 .. 4.5) give the same answers
    sq2 = [(0.5, 0.5), (4.5, 0.5), (4.5, 4.5), (0.5, 4.5)]
    pts2 = [(x + 0.5, y + 0.5) for x, y in pts]
    assert sl.geometry.inside(pts2, sq2).tolist() == sl.geometry.inside(pts, sq).tolist()


def test_tiling_points_inside_exactly_one():
    from scipy.spatial import Delaunay
    rng = np.random.default_rng(4)
    verts = np.vstack([[(0, 0), (20, 0), (20, 20), (0, 20)], rng.integers(0, 21, (30, 2))])
    verts = np.unique(verts, axis=0).astype(float)
    tri = Delaunay(verts)
    yy, xx = np.mgrid[1:21, 0:20]               # the square's pixel centers (top-left rule)
    pts = np.stack([xx.ravel(), yy.ravel()], axis=1)
    count = sum(sl.geometry.inside(pts, verts[s]).astype(int) for s in tri.simplices)
    assert (count == 1).all()


def test_several_contours_add_up():
    outer = [(0, 0), (10, 0), (10, 10), (0, 10)]
    inner = [(3, 3), (7, 3), (7, 7), (3, 7)]
    p = [(5, 5), (1, 1)]
    assert sl.geometry.winding_number(p, [outer, inner]).tolist() == [2, 1]
    assert sl.geometry.winding_number(p, [outer, inner[::-1]]).tolist() == [0, 1]
    assert sl.geometry.inside(p, [outer, inner]).tolist() == [False, True]
    assert sl.geometry.inside(p, [outer, inner], "nonzero").tolist() == [True, True]


def test_shapes_and_empty_inputs():
    sq = np.array([(0, 0), (4, 0), (4, 4), (0, 4)])
    grid = np.zeros((3, 5, 2)) + 2
    assert sl.geometry.inside(grid, sq).shape == (3, 5)
    assert sl.geometry.winding_number(np.empty((0, 2)), sq).shape == (0,)
    assert not sl.geometry.inside([(1, 1)], []).any()
    assert not sl.geometry.inside([(1, 1)], [(0, 0), (2, 2)]).any()


def test_bad_input_names_the_argument():
    sq = [(0, 0), (4, 0), (4, 4)]
    with pytest.raises(sl.ArgumentValueError, match="rule"):
        sl.geometry.inside([(1, 1)], sq, rule="winding")
    with pytest.raises(sl.ArgumentValueError, match="points"):
        sl.geometry.inside([(1, np.nan)], sq)
    with pytest.raises(sl.ArgumentValueError, match="points"):
        sl.geometry.inside([(1, 2, 3)], sq)
    with pytest.raises(sl.ArgumentTypeError, match="points"):
        sl.geometry.inside([("a", "b")], sq)
    with pytest.raises(sl.ArgumentValueError, match="polygon"):
        sl.geometry.winding_number([(1, 1)], [(0, 0), (np.inf, 0), (4, 4)])


@HYPOTHESIS
@given(st.lists(st.tuples(st.integers(-20, 20), st.integers(-20, 20)), min_size=0, max_size=8),
       st.lists(st.tuples(st.integers(-22, 22), st.integers(-22, 22)), min_size=1, max_size=10))
def test_fuzz_integer_polygons_against_exact_reference(poly, pts):
    """Integer polygons, integer points (many on edges and vertices): the exact
    definition with the infinitesimal shift (x + e, y - e**2)."""
    from fractions import Fraction
    want = []
    for px, py in pts:
        s = 0
        for i in range(len(poly)):
            (xa, ya), (xb, yb) = poly[i], poly[(i + 1) % len(poly)]
            if ya != yb and min(ya, yb) < py <= max(ya, yb):
                if xa + Fraction((py - ya) * (xb - xa), yb - ya) <= px:
                    s += 1 if yb > ya else -1
        want.append(-s)
    assert sl.geometry.winding_number(pts, poly).tolist() == want
