"""The bounding volume hierarchy and its ray-triangle intersections: exact
intersections written here, and the nearest hit of a brute-force test of every
triangle (numpy, written here) over random rays."""

from fractions import Fraction

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentValueError

UNIT = [[(0, 0, 0), (1, 0, 0), (0, 1, 0)]]


@pytest.mark.parametrize("origin, direction, t, uv", [
    ((0.25, 0.25, 1), (0, 0, -1), 1.0, (0.25, 0.25)),       # straight down onto the face
    ((0.25, 0.25, -2), (0, 0, 1), 2.0, (0.25, 0.25)),       # from behind: both sides hit
    ((0, 0, 3), (0, 0, -0.5), 6.0, (0, 0)),                 # t in the direction's units
    ((1, 1, 1), (-0.5, -0.5, -1), 1.0, (0.5, 0.5)),          # slanted, onto the hypotenuse
])
def test_hits_a_triangle_where_the_plane_equation_says(origin, direction, t, uv):
    hits = sl.raytrace.BVH(UNIT).intersect([origin], [direction])
    assert hits.triangle.tolist() == [0]
    assert hits.t[0] == pytest.approx(t, abs=1e-12)
    assert hits.uv[0] == pytest.approx(uv, abs=1e-12)


@pytest.mark.parametrize("origin, direction", [
    ((0.75, 0.75, 1), (0, 0, -1)),     # beyond the hypotenuse (u + v = 1.5)
    ((-0.1, 0.5, 1), (0, 0, -1)),      # left of the edge u = 0
    ((0.2, 0.2, 1), (1, 0, 0)),        # parallel to the plane
    ((0.2, 0.2, 1), (0, 0, 1)),        # pointing away (t < 0)
])
def test_misses(origin, direction):
    hits = sl.raytrace.BVH(UNIT).intersect([origin], [direction])
    assert hits.triangle.tolist() == [-1] and hits.t[0] == np.inf


def test_random_exact_hits():
    """Points v0 + u e1 + v e2 with rational u, v inside, reached from o = P - t d:
    the tree finds t, u and v (exact fractions written here) to rounding."""
    rng = np.random.default_rng(1)
    tri = rng.uniform(-5, 5, (200, 3, 3))
    tree = sl.raytrace.BVH(tri)
    for i in rng.choice(200, 50, replace=False):
        u, w = Fraction(int(rng.integers(1, 50)), 101), Fraction(int(rng.integers(1, 50)), 101)
        p = tri[i, 0] + float(u) * (tri[i, 1] - tri[i, 0]) + float(w) * (tri[i, 2] - tri[i, 0])
        normal = np.cross(tri[i, 1] - tri[i, 0], tri[i, 2] - tri[i, 0])
        d = normal / np.linalg.norm(normal)
        o = p + 1e-3 * d                   # just off the triangle: nothing can come between
        hits = tree.intersect([o], [-d])
        assert hits.triangle[0] == i
        assert hits.t[0] == pytest.approx(1e-3, rel=1e-6)
        assert hits.uv[0] == pytest.approx([float(u), float(w)], abs=1e-6)


def brute_force(tri, o, d):
    """The nearest hit of each ray against every triangle (Moller-Trumbore in numpy)."""
    v0, e1, e2 = tri[:, 0], tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]
    best_t = np.full(len(o), np.inf)
    best = np.full(len(o), -1)
    for r in range(len(o)):
        p = np.cross(d[r], e2)
        det = (e1 * p).sum(1)
        with np.errstate(divide="ignore", invalid="ignore"):
            tv = o[r] - v0
            u = (tv * p).sum(1) / det
            q = np.cross(tv, e1)
            w = (q @ d[r]) / det
            t = (e2 * q).sum(1) / det
        ok = (det != 0) & (u >= 0) & (w >= 0) & (u + w <= 1) & (t > 0)
        if ok.any():
            j = np.flatnonzero(ok)[np.argmin(t[ok])]
            best_t[r], best[r] = t[j], j
    return best_t, best


@pytest.mark.parametrize("layout", ["cloud", "mesh"])
def test_traversal_finds_the_brute_force_nearest_hit(layout):
    rng = np.random.default_rng(7)
    if layout == "cloud":
        centers = rng.uniform(-10, 10, (3000, 1, 3))
        tri = centers + rng.normal(0, 0.6, (3000, 3, 3))
    else:
        m = sl.mesh.torus(8.0, 3.0, resolution=(40, 20)).triangulated()
        tri = m.vertices[m.faces]
    o = rng.uniform(-12, 12, (1500, 3))
    d = rng.normal(size=(1500, 3))
    hits = sl.raytrace.BVH(tri).intersect(o, d)
    t, row = brute_force(tri, o, d)
    assert (hits.triangle >= 0).sum() > 100
    same = hits.triangle == row
    # where two triangles are hit at the same t (shared edges of the mesh) either is right
    assert np.all(same | np.isclose(hits.t, t, rtol=1e-12))
    assert np.allclose(hits.t[np.isfinite(t)], t[np.isfinite(t)], rtol=1e-10)
    assert np.array_equal(np.isfinite(hits.t), np.isfinite(t))


def test_tree_is_a_hierarchy_of_boxes():
    rng = np.random.default_rng(3)
    tri = rng.uniform(-1, 1, (500, 3, 3))
    tree = sl.raytrace.BVH(tri)
    assert sorted(tree.order.tolist()) == list(range(500))
    covered = np.zeros(500, int)
    for node, (first, count) in enumerate(tree.links):
        box = tree.bounds[node]
        if count:
            pts = tri[tree.order[first:first + count]].reshape(-1, 3)
            assert (pts >= box[:3]).all() and (pts <= box[3:]).all()
            covered[first:first + count] += 1
        else:
            for child in (first, first + 1):
                assert (tree.bounds[child, :3] >= box[:3]).all()
                assert (tree.bounds[child, 3:] <= box[3:]).all()
    assert (covered == 1).all()
    assert len(tree.bounds) < 500        # leaves hold several triangles (the SAH's leaves)


@pytest.mark.parametrize("triangles", [np.full((2, 3, 3), np.nan), np.zeros((2, 3)),
                                       [[(0, 0, 0), (1, 0, 0), (0, np.inf, 0)]]])
def test_bad_triangles(triangles):
    with pytest.raises(ArgumentValueError, match="triangles"):
        sl.raytrace.BVH(triangles)


def test_bad_rays():
    tree = sl.raytrace.BVH(UNIT)
    with pytest.raises(ArgumentValueError, match="directions"):
        tree.intersect([(0, 0, 1)], [(0, 0, 0)])
    with pytest.raises(ArgumentValueError, match="finite"):
        tree.intersect([(0, 0, np.nan)], [(0, 0, 1)])


def test_empty_tree_misses():
    hits = sl.raytrace.BVH(np.zeros((0, 3, 3))).intersect([(0, 0, 1)], [(0, 0, -1)])
    assert hits.triangle.tolist() == [-1]


def test_degenerate_layouts_stay_correct_and_bounded():
    """Hundreds of identical triangles (one centroid: no split) and triangles at
    exponentially spaced places (a tree that would grow deeper than the traversal's
    stack): the nearest hits are still the brute force's."""
    base = np.array([[(0, 0, 0), (1, 0, 0), (0, 1, 0)]], float)
    same = np.repeat(base, 300, axis=0)
    far = base + (2.0 ** np.arange(120))[:, None, None] * np.array([1e-30, 0, 1.0])
    for tri in (same, np.concatenate([same, far])):
        tree = sl.raytrace.BVH(tri)
        rng = np.random.default_rng(0)
        o = np.c_[rng.uniform(0, 0.5, 200), rng.uniform(0, 0.5, 200), np.full(200, -1.0)]
        d = np.tile([0.0, 0.0, 1.0], (200, 1))
        t, _ = brute_force(tri, o, d)
        hits = tree.intersect(o, d)
        assert np.allclose(hits.t, t)
        assert (tree.links[:, 1] >= 0).all() and len(tree.bounds) <= 2 * len(tri)
