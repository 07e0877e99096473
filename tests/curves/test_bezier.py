"""Bezier curves: against scipy's BPoly and hand formulas, the notes' properties."""

from math import comb

import numpy as np
import pytest
from scipy.interpolate import BPoly
from shapely.geometry import MultiPoint, Point

import scanline as sl

METHODS = ["de-casteljau", "bernstein", "recursive", "matrix", None]


def close(a, b, scale):
    np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-12 * scale)


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("degree,dim", [(0, 2), (1, 2), (2, 3), (3, 2), (3, 3), (6, 2), (9, 3)])
def test_against_scipy_bpoly(method, degree, dim):
    rng = np.random.default_rng(degree * 10 + dim)
    for _ in range(5):
        P = rng.uniform(-100, 100, size=(degree + 1, dim))
        u = rng.uniform(0, 1, size=200)
        ref = BPoly(P[:, None, :], [0.0, 1.0])(u)
        close(sl.curves.Bezier(P).evaluate(u, method=method), ref, 100)


@pytest.mark.parametrize("degree", [1, 2, 3, 5])
def test_derivatives_against_scipy(degree):
    rng = np.random.default_rng(degree)
    P = rng.uniform(-10, 10, size=(degree + 1, 2))
    u = rng.uniform(0, 1, 100)
    bp = BPoly(P[:, None, :], [0.0, 1.0])
    c = sl.curves.Bezier(P)
    for k in range(1, degree + 2):
        close(c.derivative(k).evaluate(u), bp.derivative(k)(u), 10 * 10**k)


def test_bernstein_and_recursive_blending_by_hand():
    u = np.linspace(0, 1, 11)
    for n in range(0, 7):
        by_hand = np.stack([comb(n, k) * u**k * (1 - u) ** (n - k) for k in range(n + 1)], -1)
        np.testing.assert_allclose(sl.curves.bernstein(n, u), by_hand, atol=1e-15)
        np.testing.assert_allclose(sl.curves.bernstein_recursive(n, u), by_hand, atol=1e-15)
        np.testing.assert_allclose(by_hand.sum(-1), 1.0, atol=1e-14)


def test_shapes_scalar_and_grid():
    c = sl.curves.Bezier([(0, 0, 0), (1, 2, 3), (2, 0, 1)])
    assert c.evaluate(0.5).shape == (3,)
    assert c.evaluate(np.zeros((4, 5))).shape == (4, 5, 3)
    assert c(0.25).tolist() == c.evaluate(0.25).tolist()
    assert c.dimension == 3 and c.domain == (0.0, 1.0)


def test_endpoints_and_end_tangents():
    P = np.array([(0, 0), (1, 3), (4, 3), (5, 1), (7, 0)], float)
    c = sl.curves.Bezier(P)
    assert c.evaluate(0).tolist() == P[0].tolist()
    assert c.evaluate(1).tolist() == P[-1].tolist()
    np.testing.assert_allclose(c.derivative().evaluate([0, 1]), [4 * (P[1] - P[0]), 4 * (P[4] - P[3])])


def test_convex_hull_property():
    rng = np.random.default_rng(5)
    for _ in range(20):
        P = rng.uniform(-50, 50, size=(rng.integers(3, 9), 2))
        hull = MultiPoint([tuple(p) for p in P]).convex_hull.buffer(1e-9)
        pts = sl.curves.Bezier(P).evaluate(np.linspace(0, 1, 101))
        assert all(hull.contains(Point(*p)) for p in pts)


def test_de_casteljau_triangle_by_hand():
    tri = sl.curves.Bezier([(0, 0), (0, 4), (4, 4), (4, 0)]).de_casteljau(0.5)
    assert [lvl.tolist() for lvl in tri] == [
        [[0, 0], [0, 4], [4, 4], [4, 0]], [[0, 2], [2, 4], [4, 2]], [[1, 3], [3, 3]], [[2, 3]]]


@pytest.mark.parametrize("split", [0.5, 0.3, 0.9])
def test_subdivision_reproduces_both_halves(split):
    rng = np.random.default_rng(7)
    P = rng.normal(size=(5, 3))
    c = sl.curves.Bezier(P)
    left, right = c.subdivide(split)
    t = np.linspace(0, 1, 33)
    np.testing.assert_allclose(left.evaluate(t), c.evaluate(split * t), atol=1e-13)
    np.testing.assert_allclose(right.evaluate(t), c.evaluate(split + (1 - split) * t), atol=1e-13)


def test_degree_elevation_keeps_the_curve():
    rng = np.random.default_rng(8)
    P = rng.normal(size=(4, 2))
    c = sl.curves.Bezier(P)
    e = c.elevate(3)
    assert e.degree == 6
    t = np.linspace(0, 1, 50)
    np.testing.assert_allclose(e.evaluate(t), c.evaluate(t), atol=1e-13)
    # elevating a quadratic once by hand: Q = [P0, (P0 + 2P1)/3, (2P1 + P2)/3, P2]
    q = sl.curves.Bezier([(0, 0), (3, 3), (6, 0)]).elevate().points
    np.testing.assert_allclose(q, [(0, 0), (2, 2), (4, 2), (6, 0)])


def rational_by_hand(P, w, u):
    n = len(P) - 1
    B = np.stack([comb(n, k) * u**k * (1 - u) ** (n - k) for k in range(n + 1)], -1)
    return (B * w) @ P / (B @ w)[:, None]


@pytest.mark.parametrize("method", METHODS)
def test_rational_against_formula(method):
    rng = np.random.default_rng(9)
    P = rng.normal(size=(5, 2))
    w = rng.uniform(0.2, 3, 5)
    u = rng.uniform(0, 1, 100)
    close(sl.curves.Bezier(P, weights=w).evaluate(u, method=method), rational_by_hand(P, w, u), 10)


def test_rational_quadratic_is_an_exact_quarter_circle():
    c = sl.curves.Bezier([(1, 0), (1, 1), (0, 1)], weights=[1, np.sqrt(0.5), 1])
    p = c.evaluate(np.linspace(0, 1, 101))
    np.testing.assert_allclose(np.hypot(p[:, 0], p[:, 1]), 1.0, atol=1e-15)


def test_rational_derivative_against_finite_differences_and_split():
    c = sl.curves.Bezier([(0, 0), (1, 2), (3, 2), (4, 0)], weights=[1, 3, 0.5, 2])
    u = np.linspace(0.05, 0.95, 19)
    h = 1e-5
    for k, tol in ((1, 1e-6), (2, 1e-3)):
        fd = (c.derivative(k - 1).evaluate(u + h) - c.derivative(k - 1).evaluate(u - h)) / (2 * h)
        np.testing.assert_allclose(c.derivative(k).evaluate(u), fd, rtol=tol, atol=tol)
    left, right = c.subdivide(0.4)
    t = np.linspace(0, 1, 21)
    np.testing.assert_allclose(left.evaluate(t), c.evaluate(0.4 * t), atol=1e-13)
    np.testing.assert_allclose(right.evaluate(t), c.evaluate(0.4 + 0.6 * t), atol=1e-13)
    np.testing.assert_allclose(c.elevate(2).evaluate(t), c.evaluate(t), atol=1e-13)


def test_equal_weights_give_the_plain_curve():
    P = [(0, 0), (2, 5), (6, 1)]
    u = np.linspace(0, 1, 9)
    np.testing.assert_allclose(sl.curves.Bezier(P, weights=[2, 2, 2]).evaluate(u),
                               sl.curves.Bezier(P).evaluate(u), atol=1e-14)


def test_kernel_many_points_matches_bernstein():
    rng = np.random.default_rng(3)
    P = rng.uniform(-1e3, 1e3, size=(4, 2))
    u = rng.uniform(0, 1, 100_000)
    c = sl.curves.Bezier(P)
    close(c.evaluate(u), c.evaluate(u, method="bernstein"), 1e3)
