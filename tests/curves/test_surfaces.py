"""Tensor-product Bezier and B-spline surfaces: evaluation against independent
computations (explicit Bernstein sums, scipy), derivatives against finite
differences, normals, tessellation, meshes, bad input."""

import math

import numpy as np
import pytest
from scipy.interpolate import BPoly
from scipy.interpolate import BSpline as ScipyBSpline

import scanline as sl
from scanline.curves.surfaces import bspline_basis, obj_text, weld, write_obj

rng = np.random.default_rng(20261122)


def bernstein_sum(net, u, v, weights=None):
    """P(u, v) by the notes' eq. 10 written out: a double sum of products of
    binomial coefficients and powers (pure Python, one point)."""
    m, n = net.shape[0] - 1, net.shape[1] - 1
    w = np.ones(net.shape[:2]) if weights is None else weights
    num = np.zeros(net.shape[2])
    den = 0.0
    for i in range(m + 1):
        bu = math.comb(m, i) * u**i * (1 - u) ** (m - i)
        for j in range(n + 1):
            bv = math.comb(n, j) * v**j * (1 - v) ** (n - j)
            num += bu * bv * w[i, j] * net[i, j]
            den += bu * bv * w[i, j]
    return num / den


def random_net(m, n, dim=3):
    return rng.uniform(-5, 5, (m + 1, n + 1, dim))


@pytest.mark.parametrize("m,n", [(1, 1), (3, 3), (2, 5), (6, 1), (4, 2)])
def test_bezier_surface_matches_explicit_double_sum(m, n):
    net = random_net(m, n)
    s = sl.curves.BezierSurface(net)
    u, v = rng.random(25), rng.random(25)
    got = s.evaluate(u, v)
    want = np.array([bernstein_sum(net, a, b) for a, b in zip(u, v)])
    np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12)


def test_bezier_surface_matches_scipy_bpoly_tensor_product():
    net = random_net(3, 4)
    s = sl.curves.BezierSurface(net)
    us, vs = np.linspace(0, 1, 7), np.linspace(0, 1, 9)
    # along v for each row i (scipy BPoly: coefficients (k, intervals, ...)), then along u
    rows = BPoly(net.transpose(1, 0, 2)[:, None], [0, 1])(vs)       # (9, 4, 3)
    want = BPoly(rows.transpose(1, 0, 2)[:, None], [0, 1])(us)      # (7, 9, 3)
    np.testing.assert_allclose(s.grid(us, vs), want, rtol=1e-12, atol=1e-12)


def test_rational_bezier_surface_matches_explicit_sum():
    net = random_net(2, 3)
    w = rng.uniform(0.2, 3, net.shape[:2])
    s = sl.curves.BezierSurface(net, weights=w)
    u, v = rng.random(20), rng.random(20)
    want = np.array([bernstein_sum(net, a, b, w) for a, b in zip(u, v)])
    np.testing.assert_allclose(s.evaluate(u, v), want, rtol=1e-12, atol=1e-12)


def test_rational_sphere_octant_lies_on_the_sphere():
    # a biquadratic rational patch: the quarter circle (weights 1, 1/sqrt2, 1) swept
    # by another quarter circle gives an exact octant of the unit sphere
    c = np.array([[1, 0], [1, 1], [0, 1]], float)
    wc = np.array([1, 1 / np.sqrt(2), 1])
    net = np.empty((3, 3, 3))
    for i in range(3):        # latitude: (r, z) = c[i]
        for j in range(3):    # longitude: (x, y) = c[j]
            net[i, j] = [c[i, 0] * c[j, 0], c[i, 0] * c[j, 1], c[i, 1]]
    s = sl.curves.BezierSurface(net, weights=np.outer(wc, wc))
    u, v = np.meshgrid(np.linspace(0, 1, 11), np.linspace(0, 1, 11))
    p = s.evaluate(u, v)
    np.testing.assert_allclose(np.linalg.norm(p, axis=-1), 1.0, rtol=1e-13)
    inner = (slice(None, -1),) * 2  # v = 1 row is the pole: normals there are nudged
    normals = s.normal(u, v)
    np.testing.assert_allclose(np.abs((normals * p).sum(-1))[inner], 1.0, rtol=1e-9)


def test_corners_are_interpolated():
    net = random_net(3, 2)
    s = sl.curves.BezierSurface(net)
    for (u, v), (i, j) in {(0, 0): (0, 0), (1, 0): (-1, 0), (0, 1): (0, -1), (1, 1): (-1, -1)}.items():
        np.testing.assert_allclose(s.evaluate(u, v), net[i, j], atol=1e-14)
    b = sl.curves.BSplineSurface(random_net(6, 5), 4, 3)
    lo_u, hi_u = b.domain[0]
    lo_v, hi_v = b.domain[1]
    np.testing.assert_allclose(b.evaluate(lo_u, lo_v), b.net[0, 0], atol=1e-13)
    np.testing.assert_allclose(b.evaluate(hi_u, hi_v), b.net[-1, -1], atol=1e-13)


def test_boundary_curves_are_the_nets_boundary_bezier_curves():
    net = random_net(3, 4)
    s = sl.curves.BezierSurface(net)
    t = np.linspace(0, 1, 13)
    np.testing.assert_allclose(s.evaluate(0.0, t), sl.curves.Bezier(s.boundary("u0")).evaluate(t),
                               atol=1e-13)
    np.testing.assert_allclose(s.evaluate(t, 1.0), sl.curves.Bezier(s.boundary("v1")).evaluate(t),
                               atol=1e-13)


def test_surface_lies_in_the_bounding_box_of_its_net():
    net = random_net(4, 4)
    p = sl.curves.BezierSurface(net).grid(np.linspace(0, 1, 30), np.linspace(0, 1, 30))
    assert (p >= net.reshape(-1, 3).min(0) - 1e-12).all()
    assert (p <= net.reshape(-1, 3).max(0) + 1e-12).all()


def finite_difference(s, u, v, du, dv, h=1e-5):
    if (du, dv) == (1, 0):
        return (s.evaluate(u + h, v) - s.evaluate(u - h, v)) / (2 * h)
    if (du, dv) == (0, 1):
        return (s.evaluate(u, v + h) - s.evaluate(u, v - h)) / (2 * h)
    if (du, dv) == (1, 1):
        return (s.evaluate(u + h, v + h) - s.evaluate(u + h, v - h)
                - s.evaluate(u - h, v + h) + s.evaluate(u - h, v - h)) / (4 * h * h)
    if (du, dv) == (2, 0):
        return (s.evaluate(u + h, v) - 2 * s.evaluate(u, v) + s.evaluate(u - h, v)) / (h * h)
    raise AssertionError


def surfaces_to_differentiate():
    net = random_net(3, 4)
    w = rng.uniform(0.5, 2, net.shape[:2])
    yield sl.curves.BezierSurface(net)
    yield sl.curves.BezierSurface(net, weights=w)
    yield sl.curves.BSplineSurface(random_net(6, 5), 4, 3)
    yield sl.curves.BSplineSurface(random_net(5, 5), 3, 4, weights=rng.uniform(0.5, 2, (6, 6)))


@pytest.mark.parametrize("index", range(4))
def test_partial_derivatives_match_finite_differences(index):
    s = list(surfaces_to_differentiate())[index]
    (u0, u1), (v0, v1) = s.domain
    # inside one knot span for the B-splines (derivatives jump at knots otherwise)
    u = u0 + (u1 - u0) * np.array([0.13, 0.41, 0.77])
    v = v0 + (v1 - v0) * np.array([0.21, 0.55, 0.9])
    for du, dv, tol in ((1, 0, 1e-6), (0, 1, 1e-6), (1, 1, 1e-4), (2, 0, 1e-3)):
        got = s.derivative(u, v, du, dv)
        want = finite_difference(s, u, v, du, dv, h=1e-5 if du + dv == 1 else 1e-4)
        np.testing.assert_allclose(got, want, rtol=tol, atol=tol * np.abs(want).max())
    su, sv = s.partials(u, v)
    np.testing.assert_allclose(su, s.derivative(u, v, 1, 0))
    np.testing.assert_allclose(sv, s.derivative(u, v, 0, 1))


def test_derivatives_beyond_the_degree_are_zero():
    s = sl.curves.BezierSurface(random_net(2, 1))
    np.testing.assert_array_equal(s.derivative(0.3, 0.6, 3, 0), 0.0)
    np.testing.assert_array_equal(s.derivative(0.3, 0.6, 0, 2), 0.0)


@pytest.mark.parametrize("index", range(4))
def test_normals_are_unit_and_perpendicular_to_both_partials(index):
    s = list(surfaces_to_differentiate())[index]
    (u0, u1), (v0, v1) = s.domain
    u = rng.uniform(u0, u1, 40)
    v = rng.uniform(v0, v1, 40)
    n = s.normal(u, v)
    su, sv = s.partials(u, v)
    np.testing.assert_allclose(np.linalg.norm(n, axis=-1), 1.0, rtol=1e-12)
    assert np.abs((n * su).sum(-1)).max() <= 1e-9 * np.linalg.norm(su, axis=-1).max()
    assert np.abs((n * sv).sum(-1)).max() <= 1e-9 * np.linalg.norm(sv, axis=-1).max()
    assert ((n * np.cross(su, sv)).sum(-1) > 0).all()  # the S_u x S_v side


def test_normal_at_a_collapsed_edge_is_the_limit_normal():
    # a cone apex: the whole u = 0 row is the apex (0, 0, 1); the cone opens downward
    ring = np.array([[1, 0, 0], [1, 1, 0], [-1, 1, 0], [-1, 0, 0]], float)
    net = np.array([[[0, 0, 1]] * 4, ring * [0.5, 0.5, 1] + [0, 0, 0.5], ring])
    s = sl.curves.BezierSurface(net)
    n = s.normal(0.0, 0.0)      # apex, v = 0: the direction toward +x of the cone
    near = s.normal(1e-4, 0.0)
    assert np.isfinite(n).all()
    np.testing.assert_allclose(n, near, atol=1e-3)


def test_bspline_surface_matches_scipy_tensor_product():
    net = random_net(6, 4)
    kv = np.array([0, 0, 0, 1, 2, 4, 4, 4.0])             # order 3, non-uniform
    s = sl.curves.BSplineSurface(net, 3, 3, knots_u=np.array([0, 0, 0, 1, 1.5, 2, 3, 4, 4, 4.0]),
                                 knots_v=kv)
    us = np.linspace(*s.domain[0], 9)
    vs = np.linspace(*s.domain[1], 8)
    along_v = ScipyBSpline(kv, net.transpose(1, 0, 2), 2)(vs)                     # (8, 7, 3)
    want = ScipyBSpline(s.knots[0], along_v.transpose(1, 0, 2), 2)(us)           # (9, 8, 3)
    np.testing.assert_allclose(s.grid(us, vs), want, rtol=1e-12, atol=1e-12)


def test_bspline_surface_derivative_matches_scipy():
    net = random_net(5, 5)
    s = sl.curves.BSplineSurface(net, 4, 4)
    u, v = 1.3, 0.7
    dv_rows = ScipyBSpline(s.knots[1], net.transpose(1, 0, 2), 3).derivative(1)(v)   # (6, 3)
    want = ScipyBSpline(s.knots[0], dv_rows, 3).derivative(1)(u)
    np.testing.assert_allclose(s.derivative(u, v, 1, 1), want, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("order", [2, 3, 4, 5])
def test_bspline_blending_functions_are_a_partition_of_unity(order):
    knots = np.concatenate([[0] * order, np.sort(rng.uniform(0, 5, 6 - order + 1)), [5] * order])
    count = len(knots) - order
    t = np.linspace(knots[order - 1], knots[count], 101)
    b = bspline_basis(knots, order, t)
    np.testing.assert_allclose(b.sum(axis=1), 1.0, rtol=1e-13)
    assert (b >= -1e-15).all()
    np.testing.assert_allclose(bspline_basis(knots, order, t, 1).sum(axis=1), 0.0, atol=1e-10)
    # a constant net gives a constant surface
    s = sl.curves.BSplineSurface(np.full((count, 4, 3), 2.5), order, 3,
                                 knots_u=knots)
    np.testing.assert_allclose(s.grid(t, np.linspace(0, 2, 5)), 2.5, rtol=1e-13)


def test_bspline_surface_of_bezier_order_is_the_bezier_surface():
    net = random_net(3, 2)
    b = sl.curves.BSplineSurface(net, 4, 3)
    assert b.domain == ((0.0, 1.0), (0.0, 1.0))
    u, v = rng.random(15), rng.random(15)
    np.testing.assert_allclose(b.evaluate(u, v), sl.curves.BezierSurface(net).evaluate(u, v),
                               atol=1e-13)


def test_evaluate_broadcasts_and_keeps_shapes():
    s = sl.curves.BezierSurface(random_net(2, 2))
    assert s.evaluate(0.5, 0.5).shape == (3,)
    assert s.evaluate(np.zeros((4, 1)), np.zeros(5)).shape == (4, 5, 3)
    assert s.normal([0.1, 0.2], 0.3).shape == (2, 3)
    assert s(0.2, 0.4).tolist() == s.evaluate(0.2, 0.4).tolist()


def height_net(m, n):
    """A net over a grid in x, y with small random heights: a graph z = f(x, y), so
    every normal has z > 0 and no fold can flip a coarse triangle."""
    x, y = np.meshgrid(np.arange(m + 1.0), np.arange(n + 1.0), indexing="ij")
    return np.stack([x, y, rng.uniform(-0.3, 0.3, x.shape)], axis=-1)


@pytest.mark.parametrize("s", [
    sl.curves.BezierSurface(height_net(3, 4)),
    sl.curves.BezierSurface(height_net(2, 2), weights=rng.uniform(0.5, 2, (3, 3))),
    sl.curves.BSplineSurface(height_net(6, 5), 4, 3),
], ids=["bezier", "rational", "bspline"])
def test_tessellation(s):
    nu, nv = 5, 7
    verts, tris, normals = s.tessellate(nu, nv)
    assert verts.shape == ((nu + 1) * (nv + 1), 3) and normals.shape == verts.shape
    assert tris.shape == (2 * nu * nv, 3) and tris.dtype == np.int64
    assert tris.min() == 0 and tris.max() == len(verts) - 1
    us = np.linspace(*s.domain[0], nu + 1)
    vs = np.linspace(*s.domain[1], nv + 1)
    np.testing.assert_allclose(verts, s.grid(us, vs).reshape(-1, 3), atol=1e-13)
    uu, vv = np.meshgrid(us, vs, indexing="ij")
    np.testing.assert_allclose(normals, s.normal(uu, vv).reshape(-1, 3), atol=1e-12)
    # every triangle winds counterclockwise seen from its normals' side
    face = np.cross(verts[tris[:, 1]] - verts[tris[:, 0]], verts[tris[:, 2]] - verts[tris[:, 0]])
    assert ((face * normals[tris].mean(axis=1)).sum(-1) > 0).all()
    # each interior grid edge is used once in each direction
    edges = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    assert len({tuple(e) for e in edges.tolist()}) == len(edges)


def test_weld_merges_shared_boundaries_and_drops_collapsed_triangles():
    a = sl.curves.BezierSurface(random_net(3, 3))
    net = a.net.copy()
    shifted = random_net(3, 3)
    shifted[0] = net[-1]          # shares a's u = 1 boundary row
    b = sl.curves.BezierSurface(shifted)
    va, ta, na = a.tessellate(4, 4)
    vb, tb, nb = b.tessellate(4, 4)
    v, t, n = weld(np.vstack([va, vb]), np.vstack([ta, tb + len(va)]), np.vstack([na, nb]))
    assert len(v) == len(va) + len(vb) - 5      # the 5 vertices of the shared edge
    assert len(t) == len(ta) + len(tb)
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1.0)


def test_obj_export_round_trip(tmp_path):
    s = sl.curves.BezierSurface(random_net(2, 2))
    verts, tris, normals = s.tessellate(3, 2)
    path = tmp_path / "patch.obj"
    write_obj(path, verts, tris, normals)
    lines = path.read_text().splitlines()
    v = np.array([[float(x) for x in l.split()[1:]] for l in lines if l.startswith("v ")])
    f = np.array([[int(x.split("//")[0]) for x in l.split()[1:]] for l in lines if l.startswith("f ")])
    np.testing.assert_allclose(v, verts, rtol=1e-8, atol=1e-8)
    np.testing.assert_array_equal(f - 1, tris)
    assert sum(l.startswith("vn ") for l in lines) == len(verts)


def test_obj_export_failure_leaves_no_file(tmp_path):
    path = tmp_path / "bad.obj"
    with pytest.raises(sl.ArgumentValueError, match="triangles"):
        write_obj(path, np.zeros((3, 3)), [[0, 1, 5]])
    assert list(tmp_path.iterdir()) == []
    with pytest.raises(sl.ArgumentValueError, match="folder"):
        write_obj(tmp_path / "missing" / "x.obj", np.zeros((3, 3)), [[0, 1, 2]])
    assert obj_text(np.zeros((0, 3)), np.zeros((0, 3), int)) == "\n"


@pytest.mark.parametrize("net,match", [
    (np.full((3, 3, 3), np.nan), "finite"),
    (np.zeros((4, 3)), "shape"),
    (np.zeros((1, 3, 3)), "m, n >= 1"),
    (np.zeros((3, 3, 4)), "shape"),
    ("abc", "grid of control points"),
])
def test_bad_nets(net, match):
    with pytest.raises((sl.ArgumentValueError, sl.ArgumentTypeError), match=match):
        sl.curves.BezierSurface(net)


def test_bad_arguments():
    net = random_net(3, 3)
    with pytest.raises(sl.ArgumentValueError, match="weights"):
        sl.curves.BezierSurface(net, weights=np.zeros((4, 4)))
    with pytest.raises(sl.ArgumentValueError, match="weights"):
        sl.curves.BezierSurface(net, weights=np.ones((3, 4)))
    with pytest.raises(sl.ArgumentValueError, match="order_u"):
        sl.curves.BSplineSurface(net, 5, 2)
    with pytest.raises(sl.ArgumentValueError, match="order_v"):
        sl.curves.BSplineSurface(net, 2, 1)
    with pytest.raises(sl.ArgumentValueError, match="knots_u.*non-decreasing"):
        sl.curves.BSplineSurface(net, 2, 2, knots_u=[0, 1, 3, 2, 4, 5])
    with pytest.raises(sl.ArgumentValueError, match="knots_v.*6 values"):
        sl.curves.BSplineSurface(net, 2, 2, knots_v=[0, 1, 2])
    s = sl.curves.BezierSurface(net)
    with pytest.raises(sl.ArgumentValueError, match="u must lie"):
        s.evaluate(1.5, 0.5)
    with pytest.raises(sl.ArgumentValueError, match="v must lie"):
        s.evaluate(0.5, np.nan)
    with pytest.raises(sl.ArgumentValueError, match="broadcast"):
        s.evaluate([0.1, 0.2], [0.1, 0.2, 0.3])
    with pytest.raises(sl.ArgumentValueError, match="du"):
        s.derivative(0.5, 0.5, -1, 0)
    with pytest.raises(sl.ArgumentValueError, match="nu"):
        s.tessellate(0, 3)
    with pytest.raises(sl.ArgumentValueError, match="nu=100000, nv=100000 ask for"):
        s.tessellate(10**5, 10**5)      # 10^10 vertices: refused, not a MemoryError
    flat = sl.curves.BezierSurface(np.zeros((2, 2, 2)))
    with pytest.raises(sl.ArgumentValueError, match="3-D"):
        flat.normal(0.5, 0.5)
    with pytest.raises(sl.ArgumentValueError, match="3-D"):
        flat.tessellate(2, 2)
    with pytest.raises(sl.ArgumentValueError, match="tolerance"):
        weld(np.zeros((3, 3)), [[0, 1, 2]], tolerance=0)
