"""B-splines and NURBS: against scipy.interpolate.BSpline and a slow Cox-de Boor
reference written here, and the notes' properties (partition of unity, endpoint
interpolation, local control, convex hull)."""

import numpy as np
import pytest
import scipy.interpolate as si
from shapely.geometry import MultiPoint, Point

import scanline as sl


def close(a, b, scale):
    np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-12 * scale)


def slow_basis(knots, k, d, u):
    """The notes' recursion, literally, for one u (half-open base case)."""
    if d == 1:
        return 1.0 if knots[k] <= u < knots[k + 1] else 0.0
    a = b = 0.0
    if knots[k + d - 1] > knots[k]:
        a = (u - knots[k]) / (knots[k + d - 1] - knots[k]) * slow_basis(knots, k, d - 1, u)
    if knots[k + d] > knots[k + 1]:
        b = (knots[k + d] - u) / (knots[k + d] - knots[k + 1]) * slow_basis(knots, k + 1, d - 1, u)
    return a + b


def random_knots(rng, count, order, repeats=True):
    t = np.sort(rng.uniform(-5, 5, count + order))
    if repeats:  # make a few knots coincide (non-uniform with multiplicities)
        i = rng.integers(1, len(t) - 1, 2)
        t[i] = t[i - 1]
        t = np.sort(t)
    return t


@pytest.mark.parametrize("order", [1, 2, 3, 4, 5, 7])
@pytest.mark.parametrize("method", ["de-boor", "cox-de-boor", "matrix", None])
def test_against_scipy_bspline_random(order, method):
    rng = np.random.default_rng(order)
    for trial in range(8):
        n1 = rng.integers(order, order + 12)
        P = rng.uniform(-100, 100, (n1, 2 + trial % 2))
        t = random_knots(rng, n1, order, repeats=trial % 2 == 1)
        c = sl.curves.BSpline(P, order, knots=t)
        lo, hi = c.domain
        assert (lo, hi) == (t[order - 1], t[n1])
        u = np.concatenate([rng.uniform(lo, hi, 300), t[(t >= lo) & (t < hi)]])
        ref = si.BSpline(t, P, order - 1, extrapolate=False)(u)
        close(c.evaluate(u, method=method), ref, 100)
        # the right end u_(n+1) closes the last non-empty span (a left limit; scipy
        # jumps to 0 there when u_(n+1) is a repeated knot)
        end = c.evaluate(hi, method=method)
        last = t[t < hi].max()
        np.testing.assert_allclose(end, c.evaluate(hi - 1e-9 * (hi - last)), atol=1e-6)


@pytest.mark.parametrize("order", [2, 3, 4, 6])
def test_derivatives_against_scipy(order):
    rng = np.random.default_rng(10 + order)
    P = rng.uniform(-10, 10, (12, 2))
    t = random_knots(rng, 12, order, repeats=False)
    c = sl.curves.BSpline(P, order, knots=t)
    ref = si.BSpline(t, P, order - 1)
    u = rng.uniform(*c.domain, 200)
    for k in range(1, order):
        close(c.derivative(k).evaluate(u), ref.derivative(k)(u), 10 * 10 ** (2 * k))
    assert np.all(c.derivative(order).evaluate(u) == 0)


def test_basis_against_the_literal_recursion():
    rng = np.random.default_rng(2)
    for order in (1, 2, 3, 4):
        t = random_knots(rng, 8, order)
        u = rng.uniform(t[0], t[-1], 50)
        ref = np.array([[slow_basis(t, k, order, x) for k in range(8)] for x in u])
        np.testing.assert_allclose(sl.curves.basis(t, order, u), ref, atol=1e-13)


def test_order_one_is_half_open_so_interior_knots_count_once():
    # the notes' closed interval u_k <= u <= u_k+1 would make B_1,1(1) = B_2,1(1) = 1 and
    # the sum 2 at every interior knot (erratum E43)
    knots = [0, 0, 1, 2, 3, 3]
    b = sl.curves.basis(knots, 1, [0.0, 1.0, 2.0, 2.5, 3.0])
    assert b.tolist() == [[0, 1, 0, 0, 0], [0, 0, 1, 0, 0], [0, 0, 0, 1, 0],
                          [0, 0, 0, 1, 0], [0, 0, 0, 1, 0]]
    closed = [[float(knots[k] <= u <= knots[k + 1]) for k in range(5)] for u in (1.0, 2.0)]
    assert [sum(row) for row in closed] == [2, 2]


def test_the_notes_open_uniform_knot_vectors():
    assert sl.curves.open_uniform_knots(4, 2).tolist() == [0, 0, 1, 2, 3, 3]
    assert sl.curves.open_uniform_knots(5, 4).tolist() == [0, 0, 0, 0, 1, 2, 2, 2, 2]
    c = sl.curves.BSpline(np.zeros((5, 2)), 4)
    assert c.knots.tolist() == [0, 0, 0, 0, 1, 2, 2, 2, 2] and c.domain == (0.0, 2.0)
    assert sl.curves.BSpline(np.zeros((4, 2)), 2, knots=None).knots.tolist() == [0, 0, 1, 2, 3, 3]


@pytest.mark.parametrize("knots", ["open", "uniform", "periodic", "random"])
@pytest.mark.parametrize("order", [2, 3, 4, 5])
def test_partition_of_unity_on_the_valid_range(knots, order):
    rng = np.random.default_rng(order)
    n1 = 9
    kv = random_knots(rng, n1, order) if knots == "random" else knots
    c = sl.curves.BSpline(rng.normal(size=(n1, 2)), order, knots=kv)
    u = np.linspace(*c.domain, 301)
    np.testing.assert_allclose(c.basis(u).sum(axis=-1), 1.0, atol=1e-13)
    assert (c.basis(u) >= -1e-15).all()


def test_partition_of_unity_fails_outside_the_valid_range():
    # u_(d-1) .. u_(n+1) is the valid range (notes: property 5, not u_(n-1): erratum E44)
    t = np.arange(9.0)  # d = 4, n = 4: u_(d-1) = 3, u_(n+1) = 5, but u_(n-1) = 3 too
    inside = sl.curves.basis(t, 4, np.linspace(3, 5, 41)).sum(-1)
    np.testing.assert_allclose(inside, 1.0, atol=1e-14)
    outside = sl.curves.basis(t, 4, np.array([0.5, 2.5, 2.9, 5.1, 5.5, 7.5])).sum(-1)
    assert (outside < 1 - 1e-4).all()


@pytest.mark.parametrize("order", [2, 3, 4, 6])
def test_open_uniform_interpolates_the_end_points(order):
    rng = np.random.default_rng(order)
    P = rng.normal(size=(8, 3))
    c = sl.curves.BSpline(P, order)
    close(c.evaluate([c.domain[0], c.domain[1]]), P[[0, -1]], 1)
    # and is tangent to the first and last legs of the control polygon
    d0, d1 = c.derivative().evaluate([c.domain[0], c.domain[1]])
    assert abs(np.linalg.norm(np.cross(d0, P[1] - P[0]))) < 1e-9
    assert abs(np.linalg.norm(np.cross(d1, P[-1] - P[-2]))) < 1e-9


def test_local_control():
    rng = np.random.default_rng(4)
    order, n1 = 4, 10
    P = rng.normal(size=(n1, 2))
    t = np.sort(rng.uniform(0, 10, n1 + order))
    a = sl.curves.BSpline(P, order, knots=t)
    u = np.linspace(*a.domain, 2001)
    for k in range(n1):
        Q = P.copy()
        Q[k] += (3.0, -2.0)
        moved = np.any(sl.curves.BSpline(Q, order, knots=t).evaluate(u) != a.evaluate(u), axis=1)
        # P_k acts only on [u_k, u_(k+d)]: the d spans of B_k,d
        assert moved.any()
        assert np.all((u[moved] >= t[k]) & (u[moved] <= t[k + order]))


def test_convex_hull_of_the_active_control_points():
    rng = np.random.default_rng(6)
    order = 4
    P = rng.uniform(-10, 10, (9, 2))
    c = sl.curves.BSpline(P, order, knots="uniform")
    for span in range(order - 1, 9):
        hull = MultiPoint([tuple(p) for p in P[span - order + 1: span + 1]]).convex_hull
        for p in c.evaluate(np.linspace(span, span + 1, 21)):
            assert hull.buffer(1e-9).contains(Point(*p))


def test_periodic_cubic_matrix_form_boundary_conditions_and_closure():
    rng = np.random.default_rng(11)
    P = rng.normal(size=(6, 2))
    c = sl.curves.BSpline(P, 4, knots="periodic")
    assert c.domain == (0.0, 6.0) and c.closed
    M = sl.curves.bspline_matrix()
    u = np.linspace(0, 1, 17)
    T = np.stack([u**3, u**2, u, np.ones_like(u)], -1)
    for k in range(6):
        G = P[[(k + j) % 6 for j in range(4)]]
        close(c.evaluate(k + u), T @ M @ G, 10)
    close(c.evaluate(0.0), (P[0] + 4 * P[1] + P[2]) / 6, 1)
    close(c.evaluate(1.0), (P[1] + 4 * P[2] + P[3]) / 6, 1)
    close(c.derivative().evaluate(0.0), (P[2] - P[0]) / 2, 1)
    close(c.derivative().evaluate(1.0), (P[3] - P[1]) / 2, 1)
    close(c.evaluate(6.0), c.evaluate(0.0), 1)
    close(c.derivative(2).evaluate(6.0), c.derivative(2).evaluate(0.0), 10)


def test_three_equal_control_points_pull_the_periodic_cubic_through_them():
    P = np.array([(0, 0), (5, 5), (5, 5), (5, 5), (10, 0), (5, -5)], float)
    c = sl.curves.BSpline(P, 4, knots="periodic")
    close(c.evaluate(1.0), [5, 5], 10)


@pytest.mark.parametrize("order", [2, 3, 4])
def test_knot_insertion_keeps_the_curve(order):
    rng = np.random.default_rng(20 + order)
    P = rng.normal(size=(7, 2))
    c = sl.curves.BSpline(P, order)
    u = np.linspace(*c.domain, 200)
    for x, times in ((0.37, 1), (2.0, order - 1), (c.domain[1] - 0.001, order)):
        d = c.insert_knot(x, times)
        assert len(d.points) == len(P) + times and len(d.knots) == len(c.knots) + times
        np.testing.assert_allclose(d.evaluate(u), c.evaluate(u), atol=1e-13)
    with pytest.raises(ValueError, match="at most order"):
        c.insert_knot(c.domain[0])  # already repeated d times in open knots
    c = sl.curves.BSpline(P, order, knots="uniform")
    u = np.linspace(*c.domain, 200)
    np.testing.assert_allclose(c.insert_knot(c.domain[0]).evaluate(u), c.evaluate(u), atol=1e-13)


def test_knot_insertion_by_hand():
    # Boehm on the notes' open knots [0 0 1 2 3 3] (d = 2): a polyline gains a vertex
    c = sl.curves.BSpline([(0, 0), (2, 0), (2, 2), (0, 2)], 2, knots=[0, 0, 1, 2, 3, 3])
    d = c.insert_knot(1.5)
    assert d.knots.tolist() == [0, 0, 1, 1.5, 2, 3, 3]
    assert d.points.tolist() == [[0, 0], [2, 0], [2, 1], [2, 2], [0, 2]]


def test_nurbs_circle_is_exact():
    c = sl.curves.nurbs_circle(center=(3, -2), radius=5)
    p = c.evaluate(np.linspace(0, 1, 10_001))
    np.testing.assert_allclose(np.hypot(p[:, 0] - 3, p[:, 1] + 2), 5.0, rtol=1e-15, atol=2e-15)
    # it goes once around, counterclockwise
    ang = np.unwrap(np.arctan2(p[:, 1] + 2, p[:, 0] - 3))
    assert ang[-1] - ang[0] == pytest.approx(2 * np.pi) and (np.diff(ang) > 0).all()
    # derivatives: the velocity is tangent (perpendicular to the radius)
    v = c.derivative().evaluate(np.linspace(0, 1, 101))
    q = c.evaluate(np.linspace(0, 1, 101)) - (3, -2)
    np.testing.assert_allclose(np.einsum("ij,ij->i", v, q), 0, atol=1e-10)


def test_nurbs_against_the_rational_formula_and_insertion():
    rng = np.random.default_rng(12)
    P = rng.normal(size=(8, 3))
    w = rng.uniform(0.3, 3, 8)
    t = np.sort(rng.uniform(0, 4, 12))
    c = sl.curves.NURBS(P, 4, knots=t, weights=w)
    u = rng.uniform(*c.domain, 100)
    B = sl.curves.basis(t, 4, u)
    ref = (B * w) @ P / (B @ w)[:, None]
    for method in ("de-boor", "cox-de-boor", "matrix"):
        close(c.evaluate(u, method=method), ref, 10)
    np.testing.assert_allclose(c.insert_knot(float(np.mean(c.domain))).evaluate(u), ref, atol=1e-12)
    h = 1e-6
    fd = (c.evaluate(u.clip(c.domain[0] + h, c.domain[1] - h) + h)
          - c.evaluate(u.clip(c.domain[0] + h, c.domain[1] - h) - h)) / (2 * h)
    dd = c.derivative().evaluate(u.clip(c.domain[0] + h, c.domain[1] - h))
    np.testing.assert_allclose(dd, fd, rtol=1e-5, atol=1e-5)


def test_bspline_with_one_span_and_full_multiplicity_is_bezier():
    rng = np.random.default_rng(13)
    P = rng.normal(size=(5, 2))
    u = np.linspace(0, 1, 50)
    close(sl.curves.BSpline(P, 5).evaluate(u), sl.curves.Bezier(P).evaluate(u), 1)


def test_kernel_unsorted_many_points():
    rng = np.random.default_rng(14)
    P = rng.normal(size=(100, 2))
    c = sl.curves.BSpline(P, 4, knots="uniform")
    u = rng.uniform(*c.domain, 50_000)
    close(c.evaluate(u), si.BSpline(c.knots, P, 3)(u), 10)


def test_uniform_blending_functions_are_shifted_copies():
    # the notes: B_k,d(u) = B_k+1,d(u + du) = B_k+2,d(u + 2 du)
    knots = np.arange(10.0) * 0.5
    u = np.linspace(0, 2.0, 81)
    b0 = sl.curves.basis(knots, 4, u)[..., 0]
    np.testing.assert_allclose(sl.curves.basis(knots, 4, u + 0.5)[..., 1], b0, atol=1e-14)
    np.testing.assert_allclose(sl.curves.basis(knots, 4, u + 1.0)[..., 2], b0, atol=1e-14)


@pytest.mark.parametrize("order", [2, 3, 4, 5])
def test_continuity_c_d_minus_2_at_simple_knots(order):
    # the notes' property 1: degree d - 1 and C^(d-2) continuity
    rng = np.random.default_rng(30 + order)
    c = sl.curves.BSpline(rng.normal(size=(9, 2)), order, knots="uniform")
    knot = c.domain[0] + 3.0
    h = 1e-7
    for k in range(order):
        d = c.derivative(k)
        jump = np.abs(d.evaluate(knot + h) - d.evaluate(knot - h)).max()
        if k <= order - 2:
            assert jump < 1e-4
        else:
            assert jump > 1e-3  # the (d-1)-th derivative is piecewise constant and jumps
