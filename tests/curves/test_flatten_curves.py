"""Adaptive flattening: the polyline stays within the tolerance of the curve (measured
on dense samples), includes the endpoints, grows as the tolerance shrinks; bad input."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanline as sl
from scanline.curves.flatten import flatten, spline_pieces

rng = np.random.default_rng(7)


def distance_to_polyline(points, polyline):
    """Largest distance from ``points`` (N, dim) to the polyline (K, dim), brute force."""
    a, b = polyline[:-1], polyline[1:]
    ab = b - a
    len2 = (ab * ab).sum(1)
    best = np.full(len(points), np.inf)
    for start in range(0, len(points), 2000):
        p = points[start:start + 2000, None, :]
        t = np.clip(((p - a) * ab).sum(2) / np.where(len2 > 0, len2, 1), 0, 1)
        d = np.linalg.norm(p - (a + t[..., None] * ab), axis=2).min(axis=1)
        best[start:start + 2000] = d
    return best.max()


def dense(curve, n=20001):
    lo, hi = curve.domain
    return curve.evaluate(np.linspace(lo, hi, n))


def curves():
    yield "line", sl.curves.Bezier([(0, 0), (30, 40)])
    yield "quadratic", sl.curves.Bezier([(0, 0), (50, 100), (100, 0)])
    yield "cubic loop", sl.curves.Bezier([(0, 0), (120, 80), (-20, 80), (100, 0)])
    yield "cusp", sl.curves.Bezier([(0, 0), (100, 100), (0, 100), (100, 0)])
    yield "degree 7, 3-D", sl.curves.Bezier(rng.uniform(-100, 100, (8, 3)))
    yield "rational", sl.curves.Bezier(rng.uniform(0, 200, (4, 2)), weights=[1, 5, 0.2, 2])
    yield "nurbs circle", sl.curves.nurbs_circle((60, 50), 45)
    yield "bspline", sl.curves.BSpline(rng.uniform(0, 300, (9, 2)), 4)
    yield "bspline nonuniform", sl.curves.BSpline(
        rng.uniform(0, 300, (7, 2)), 3, knots=[0, 0, 0, 1, 1, 3, 6, 6, 6, 6.0][:10])
    yield "periodic bspline", sl.curves.BSpline(rng.uniform(0, 200, (6, 2)), 4, knots="periodic")
    yield "catmull-rom", sl.curves.CatmullRom(rng.uniform(0, 200, (6, 2)))
    yield "hermite", sl.curves.Hermite([(0, 0), (100, 0)], [(0, 300), (0, 300)])


CURVES = dict(curves())


@pytest.mark.parametrize("name", list(CURVES))
@pytest.mark.parametrize("tolerance", [2.0, 0.25, 0.01])
def test_every_curve_point_is_within_the_tolerance(name, tolerance):
    curve = CURVES[name]
    poly = flatten(curve, tolerance)
    assert poly.shape[1] == curve.dimension and len(poly) >= 2
    assert distance_to_polyline(dense(curve), poly) <= tolerance * (1 + 1e-9)
    # the ends are the curve's ends, exactly as evaluated
    lo, hi = curve.domain
    np.testing.assert_allclose(poly[0], curve.evaluate(lo), rtol=0, atol=1e-9)
    np.testing.assert_allclose(poly[-1], curve.evaluate(hi), rtol=0, atol=1e-9)
    # the vertices are points of the curve (within the dense samples' spacing)
    spacing = np.linalg.norm(np.diff(dense(curve), axis=0), axis=1).max()
    assert distance_to_polyline(poly, dense(curve)) <= spacing


@pytest.mark.parametrize("name", ["quadratic", "cubic loop", "degree 7, 3-D", "bspline"])
def test_wang_steps_are_within_the_tolerance_too(name):
    curve = CURVES[name]
    for tolerance in (1.0, 0.1):
        poly = flatten(curve, tolerance, method="wang")
        assert distance_to_polyline(dense(curve), poly) <= tolerance * (1 + 1e-9)


def test_a_generic_curve_is_flattened_by_samples():
    class Spiral(sl.curves.Curve):
        domain = (0.0, 6 * np.pi)
        dimension = 2

        def _evaluate(self, u):
            return np.stack([u * np.cos(u), u * np.sin(u)], axis=1) * 5

    poly = flatten(Spiral(), 0.25)
    assert distance_to_polyline(dense(Spiral(), 50001), poly) <= 0.25
    np.testing.assert_allclose(poly[[0, -1]], Spiral().evaluate([0, 6 * np.pi]), atol=1e-12)
    with pytest.raises(sl.ArgumentValueError, match="Bezier form"):
        flatten(Spiral(), 0.25, method="wang")


@pytest.mark.parametrize("name", ["cubic loop", "nurbs circle", "bspline", "catmull-rom"])
def test_more_points_for_a_smaller_tolerance(name):
    counts = [len(flatten(CURVES[name], t)) for t in (8, 2, 0.5, 0.125, 0.03)]
    assert counts == sorted(counts) and counts[-1] > counts[0]


def test_closed_curve_returns_to_its_start():
    poly = flatten(CURVES["nurbs circle"], 0.25)
    np.testing.assert_allclose(poly[0], poly[-1], atol=1e-12)
    radius = np.linalg.norm(poly - [60, 50], axis=1)
    np.testing.assert_allclose(radius, 45, atol=1e-9)   # the vertices are on the circle
    poly = flatten(CURVES["periodic bspline"], 0.25)
    np.testing.assert_allclose(poly[0], poly[-1], atol=1e-9)


def test_a_straight_curve_is_one_segment_and_no_points_repeat():
    poly = flatten(sl.curves.Bezier([(0, 0), (1, 1), (2, 2), (3, 3)]), 0.25)
    assert poly.tolist() == [[0.0, 0.0], [3.0, 3.0]]
    poly = flatten(sl.curves.CatmullRom([(0, 0), (10, 0), (20, 5), (30, 0)]), 0.1)
    assert (np.linalg.norm(np.diff(poly, axis=0), axis=1) > 0).all()


def test_degenerate_curves():
    point = flatten(sl.curves.Bezier([(3, 4), (3, 4), (3, 4)]), 0.25)
    assert point.tolist() == [[3.0, 4.0], [3.0, 4.0]]
    assert flatten(sl.curves.Bezier([(5, 6)]), 0.25).tolist() == [[5.0, 6.0], [5.0, 6.0]]


def test_spline_pieces_reproduce_the_spline():
    curve = CURVES["bspline nonuniform"]
    pieces = spline_pieces(curve.homogeneous(), curve.knots, curve.order, curve.domain)
    breaks = np.unique(curve.knots[(curve.knots >= curve.domain[0]) & (curve.knots <= curve.domain[1])])
    assert len(pieces) == len(breaks) - 1
    t = np.linspace(0, 1, 11)
    for (a, b), piece in zip(zip(breaks[:-1], breaks[1:]), pieces):
        want = curve.evaluate(a + (b - a) * t)
        got = sl.curves.Bezier(piece[:, :-1] / piece[:, -1:]).evaluate(t)
        np.testing.assert_allclose(got, want, atol=1e-9)


@pytest.mark.parametrize("tolerance,error", [
    (0, sl.ArgumentValueError), (-1, sl.ArgumentValueError), (np.nan, sl.ArgumentValueError),
    (np.inf, sl.ArgumentValueError), ("0.5", sl.ArgumentTypeError), (None, sl.ArgumentTypeError),
])
def test_bad_tolerance(tolerance, error):
    with pytest.raises(error, match="tolerance"):
        flatten(CURVES["cubic loop"], tolerance)


def test_bad_arguments():
    with pytest.raises(sl.ArgumentTypeError, match="curve"):
        flatten([(0, 0), (1, 1)], 0.25)
    with pytest.raises(sl.ArgumentValueError, match="method"):
        flatten(CURVES["quadratic"], 0.25, method="uniform")
    with pytest.raises(sl.ArgumentValueError, match="weights"):
        flatten(CURVES["rational"], 0.25, method="wang")
    with pytest.raises(sl.ArgumentValueError, match="too small"):
        flatten(sl.curves.Bezier([(0, 0), (2**30, 2**30), (2**30, 0)]), 1e-6)
    with pytest.raises(sl.ArgumentValueError, match="finite"):
        sl.curves.Bezier([(0, 0), (np.nan, 1)])


def test_curve_method_is_flatten():
    curve = CURVES["catmull-rom"]
    np.testing.assert_array_equal(curve.flatten(0.3), flatten(curve, 0.3))


coordinate = st.floats(-1e9, 1e9, allow_nan=False)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(coordinate, coordinate), min_size=2, max_size=6),
       st.floats(1e-3, 1e3))
def test_fuzz_finite_polyline_or_clear_error(points, tolerance):
    curve = sl.curves.Bezier(points)
    try:
        poly = flatten(curve, tolerance)
    except sl.ArgumentValueError as e:
        assert "too small" in str(e)
        return
    assert np.isfinite(poly).all() and len(poly) >= 2
    np.testing.assert_array_equal(poly[0], curve.points[0])
    np.testing.assert_array_equal(poly[-1], curve.points[-1])


@pytest.mark.parametrize("method", ["subdivision", "wang"])
def test_flatten_all_equals_one_by_one(method):
    from scanline.curves.flatten import flatten_all

    plain = [c for name, c in CURVES.items() if name not in ("rational", "nurbs circle")]
    batch = plain + list(CURVES.values()) if method == "subdivision" else plain
    got = flatten_all(batch, 0.3, method)
    assert len(got) == len(batch)
    for curve, poly in zip(batch, got):
        np.testing.assert_array_equal(poly, flatten(curve, 0.3, method))
    assert flatten_all([], 0.3) == []
    with pytest.raises(sl.ArgumentTypeError, match=r"curves\[1\]"):
        flatten_all([CURVES["line"], "not a curve"], 0.3)
    with pytest.raises(sl.ArgumentTypeError, match="list"):
        flatten_all(CURVES["line"], 0.3)
