"""Bad input: clear errors naming the argument, never a crash (hypothesis fuzz)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanline as sl
from scanline.errors import ArgumentTypeError, ArgumentValueError, ScanlineError


@pytest.mark.parametrize("points, match", [
    ([], "points must hold at least 1"),
    ([1, 2, 3], r"points must be an array of points of shape"),
    ("abc", "points must be an array"),
    ([(0, 0), (np.nan, 1)], r"points must be finite; point 1"),
    ([(0, 0), (np.inf, 1)], r"points must be finite; point 1"),
])
def test_bezier_points(points, match):
    with pytest.raises((ArgumentValueError, ArgumentTypeError), match=match):
        sl.curves.Bezier(points)


def test_bezier_other_arguments():
    c = sl.curves.Bezier([(0, 0), (1, 1), (2, 0)])
    for u in (1.5, -0.1, np.nan, [0.2, np.nan]):
        with pytest.raises(ArgumentValueError, match=r"u must lie in the curve's domain \[0, 1\]"):
            c.evaluate(u)
    with pytest.raises(ArgumentTypeError, match="u must be a number"):
        c.evaluate("half")
    with pytest.raises(ArgumentValueError, match="method must be one of"):
        c.evaluate(0.5, method="horner")
    with pytest.raises(ArgumentValueError, match="weights must be finite and > 0"):
        sl.curves.Bezier([(0, 0), (1, 1)], weights=[1, -1])
    with pytest.raises(ArgumentValueError, match="one weight per control point"):
        sl.curves.Bezier([(0, 0), (1, 1)], weights=[1, 1, 1])
    with pytest.raises(ArgumentValueError, match="k must be an integer >= 0"):
        c.derivative(-1)
    with pytest.raises(ArgumentValueError, match="u must lie"):
        c.subdivide(2.0)


@pytest.mark.parametrize("args, error, match", [
    (([0, 1], 3, 0.5), ArgumentValueError, r"knots must be at least order \+ 1 = 4"),
    (([3, 2, 1, 0], 2, 0.5), ArgumentValueError, "non-decreasing"),
    (([1, 1, 1, 1], 2, 1.0), ArgumentValueError, "not all equal"),
    (([0, np.nan, 2, 3], 2, 0.5), ArgumentValueError, "finite"),
    (("abc", 2, 0.5), ArgumentTypeError, "knots must be an array of numbers"),
    (([0, 1, 2, 3], 0, 0.5), ArgumentValueError, "order must be an integer >= 1, got 0"),
    (([0, 1, 2, 3], "2", 0.5), ArgumentTypeError, "order must be an integer"),
    (([0, 1, 2, 3], 2, np.nan), ArgumentValueError, r"u must lie in .*\[0, 3\]; got nan"),
    (([0, 1, 2, 3], 2, 100), ArgumentValueError, "u must lie"),
])
def test_basis_checks_its_arguments(args, error, match):
    """sl.curves.basis is public: bad knots, orders and parameters are named (they
    gave empty arrays, zeros, NaN or a raw IndexError)."""
    with pytest.raises(error, match=match):
        sl.curves.basis(*args)
    with pytest.raises(ArgumentValueError, match="last must be the index of a knot span"):
        sl.curves.basis([0, 1, 2, 3], 2, 0.5, last=10)


def test_derived_matrices_refuse_degrees_too_high_for_the_power_form():
    with pytest.raises(ArgumentValueError, match="degree=41 is above 40"):
        sl.curves.bezier_matrix(41)
    with pytest.raises(ArgumentValueError, match="order=42 is above 41"):
        sl.curves.bspline_matrix(42)
    high = sl.curves.Bezier(np.random.default_rng(7).random((60, 2)))
    with pytest.raises(ArgumentValueError, match="degrees above 40"):
        high.evaluate(0.5, method="matrix")
    assert high.evaluate(0.5).shape == (2,)      # the default picks de Casteljau


def test_high_degrees_are_refused_clearly_not_by_overflow_or_a_long_loop():
    big = sl.curves.Bezier(np.random.default_rng(5).random((2000, 2)))
    with pytest.raises(ArgumentValueError, match="degree=1999: the binomial coefficients"):
        big.evaluate(0.3, method="bernstein")
    # the other methods still evaluate it, and agree
    np.testing.assert_allclose(big.evaluate(0.3, method="recursive"),
                               big.evaluate(0.3, method="de-casteljau"), atol=1e-12)
    with pytest.raises(ArgumentValueError, match="times=1000000000 would raise degree 1999"):
        big.elevate(10**9)
    # the highest degree the binomials allow still works: C(1029, k) is finite
    edge = sl.curves.Bezier(np.random.default_rng(6).random((1030, 2)))
    np.testing.assert_allclose(edge.evaluate(0.4, method="bernstein"),
                               edge.evaluate(0.4, method="de-casteljau"), atol=1e-12)


def test_huge_control_points_fall_back_to_de_casteljau():
    c = sl.curves.Bezier([(1e308, 0), (-1e308, 1), (1e308, 2), (0, 0)])
    np.testing.assert_array_equal(c.evaluate([0, 0.5]), c.evaluate([0, 0.5], method="de-casteljau"))
    assert np.isfinite(c.evaluate(0.5)).all()
    with pytest.raises(ArgumentValueError, match="method='matrix' cannot represent"):
        c.evaluate(0.5, method="matrix")


def test_subnormal_knot_span_falls_back_to_de_boor():
    knots = [0.0, 0.0, 0.0, 2.2250738585e-313, 1.0, 1.0]  # found by the fuzz test below
    c = sl.curves.BSpline([(1, 2), (3, 4), (5, 6)], 3, knots=knots)
    u = [0.0, c.domain[1]]
    ref = c.evaluate(u, method="cox-de-boor")
    np.testing.assert_allclose(c.evaluate(u), ref)
    np.testing.assert_allclose(c.evaluate(u, method="de-boor"), ref)
    with pytest.raises(ArgumentValueError, match="use method='de-boor'"):
        c.evaluate(u, method="matrix")


def test_bspline_arguments():
    P = np.zeros((4, 2))
    with pytest.raises(ArgumentValueError, match=r"order must satisfy 1 <= order <= number "
                       r"of control points \(4\).*order=5"):
        sl.curves.BSpline(P, 5)
    with pytest.raises(ArgumentTypeError, match="order must be an integer"):
        sl.curves.BSpline(P, 2.5)
    with pytest.raises(ArgumentValueError, match=r"knots must hold n \+ d \+ 1 = 8 values"):
        sl.curves.BSpline(P, 4, knots=[0, 1, 2])
    with pytest.raises(ArgumentValueError, match=r"knots must be non-decreasing; knots\[2\] = 5"):
        sl.curves.BSpline(P, 4, knots=[0, 1, 5, 3, 4, 5, 6, 7])
    with pytest.raises(ArgumentValueError, match="knots must be finite"):
        sl.curves.BSpline(P, 4, knots=[0, 1, 2, 3, np.nan, 5, 6, 7])
    with pytest.raises(ArgumentValueError, match="empty parameter range"):
        sl.curves.BSpline(P, 4, knots=[0] * 8)
    with pytest.raises(ArgumentValueError, match="knots must be one of"):
        sl.curves.BSpline(P, 4, knots="clamped")
    with pytest.raises(ArgumentValueError, match=r"points must be finite; point 2"):
        sl.curves.BSpline([(0, 0), (1, 1), (np.nan, 0)], 2)
    c = sl.curves.BSpline(np.random.default_rng(0).normal(size=(6, 2)), 3, knots="uniform")
    assert c.domain == (2.0, 6.0)
    with pytest.raises(ArgumentValueError, match=r"u must lie in the curve's domain \[2, 6\]; got 1.0"):
        c.evaluate([2.5, 1.0])
    with pytest.raises(ArgumentValueError, match=r"u must lie in \[2, 6\) to insert"):
        c.insert_knot(6.0)


def test_hermite_family_arguments():
    with pytest.raises(ArgumentValueError, match="tangents must have the shape of points"):
        sl.curves.Hermite([(0, 0), (1, 1)], [(0, 0, 0), (1, 1, 1)])
    with pytest.raises(ArgumentValueError, match="points must hold at least 4"):
        sl.curves.CatmullRom([(0, 0), (1, 1), (2, 0)])
    with pytest.raises(ArgumentValueError, match="tension must be a finite number or one per point"):
        sl.curves.KochanekBartels(np.zeros((5, 2)), tension=[0, 1])
    with pytest.raises(ArgumentValueError, match="continuity must be one of"):
        sl.curves.piecewise_bezier([(0, 0), (1, 1)], continuity="C3")


def test_trace_arguments():
    with pytest.raises(ArgumentValueError, match=r"u must lie in \[0, 3\]"):
        sl.trace.cox_de_boor([0, 0, 1, 2, 3, 3], 2, 3.5)
    with pytest.raises(ArgumentValueError, match="knots must be non-decreasing"):
        sl.trace.cox_de_boor([0, 2, 1, 3], 2, 1.0)
    with pytest.raises(ArgumentValueError, match="knots must be at least"):
        sl.trace.cox_de_boor([0, 1], 2, 0.5)
    with pytest.raises(ArgumentValueError, match="u must lie"):
        sl.trace.de_casteljau([(0, 0), (1, 1)], u=2)


floats = st.floats(allow_nan=True, allow_infinity=True, width=64)


@settings(max_examples=200, deadline=None)
@given(points=st.lists(st.lists(floats, min_size=2, max_size=2), min_size=1, max_size=7),
       order=st.integers(-1, 8),
       knots=st.one_of(st.sampled_from(["open", "uniform", "periodic"]),
                       st.lists(floats, min_size=0, max_size=14)),
       u=st.lists(floats, min_size=1, max_size=5),
       weights=st.one_of(st.none(), st.lists(floats, min_size=1, max_size=7)))
def test_fuzz_bspline(points, order, knots, u, weights):
    try:
        c = sl.curves.BSpline(points, order, knots=knots, weights=weights)
    except ScanlineError as e:
        assert isinstance(e, (ArgumentValueError, ArgumentTypeError))
        assert any(name in str(e) for name in ("points", "order", "knots", "weights"))
        return
    try:
        p = c.evaluate(u)
    except ArgumentValueError as e:
        assert str(e).startswith("u must lie")
        return
    assert p.shape == (len(u), 2)
    q = c.evaluate(u, method="cox-de-boor")
    # same algorithmic answer up to round-off where values are finite
    ok = np.isfinite(p) & np.isfinite(q)
    np.testing.assert_allclose(p[ok], q[ok], rtol=1e-6, atol=1e-6 * (1 + np.abs(p[ok]).max(initial=0)))


@settings(max_examples=200, deadline=None)
@given(points=st.lists(st.lists(floats, min_size=3, max_size=3), min_size=0, max_size=8),
       u=st.one_of(floats, st.lists(floats, max_size=5)),
       method=st.sampled_from(["de-casteljau", "bernstein", "recursive", "matrix", "x"]))
def test_fuzz_bezier(points, u, method):
    try:
        c = sl.curves.Bezier(points)
        p = c.evaluate(u, method=method)
    except ScanlineError as e:
        assert str(e).startswith(("points ", "u ", "method"))
        return
    assert p.shape == np.shape(u) + (3,)


@settings(max_examples=150, deadline=None)
@given(data=st.data(), order=st.integers(1, 6), count=st.integers(1, 9))
def test_fuzz_valid_knot_vectors_all_methods_agree(data, order, count):
    """Sorted knot vectors with repeats and wide ranges: every method answers the same
    inside the domain (the kernels index only inside their arrays)."""
    if order > count:
        return
    finite = st.floats(-1e6, 1e6, allow_nan=False)
    knots = sorted(data.draw(st.lists(st.sampled_from([0.0, 1.0, 2.5]) | finite,
                                      min_size=count + order, max_size=count + order)))
    points = data.draw(st.lists(st.tuples(finite, finite), min_size=count, max_size=count))
    if not knots[order - 1] < knots[count]:
        with pytest.raises(ArgumentValueError, match="empty parameter range"):
            sl.curves.BSpline(points, order, knots=knots)
        return
    c = sl.curves.BSpline(points, order, knots=knots)
    lo, hi = c.domain
    u = np.array(data.draw(st.lists(st.floats(lo, hi), min_size=1, max_size=6)) + [lo, hi])
    ref = c.evaluate(u, method="cox-de-boor")
    scale = 1 + np.abs(np.asarray(points)).max()
    for method in ("de-boor", None):
        np.testing.assert_allclose(c.evaluate(u, method=method), ref, rtol=1e-6, atol=1e-6 * scale)
    try:
        m = c.evaluate(u, method="matrix")
    except ArgumentValueError as e:  # spans too narrow for the power form
        assert "use method='de-boor'" in str(e)
    else:
        np.testing.assert_allclose(m, ref, rtol=1e-6, atol=1e-6 * scale)
