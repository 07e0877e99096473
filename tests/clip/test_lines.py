"""Point, line and polyline clipping: the notes' region codes and Table 1, the three
line clippers against each other, against shapely and against an exact rational
reference, on random, touching, along-the-edge and degenerate segments."""

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from tests.clip.shapes import convex_polygon, same_segments, shapely, shapely_segments
from tests.reference import HYPOTHESIS

METHODS = ("cohen-sutherland", "liang-barsky", "cyrus-beck")
WINDOW = (0.0, 0.0, 10.0, 10.0)


def exact_clip(seg, window):
    """Independent reference: the visible parameter interval of the segment in
    rational arithmetic (half-plane by half-plane), or None."""
    x0, y0, x1, y1 = (Fraction(c) for c in seg)
    xmin, ymin, xmax, ymax = (Fraction(c) for c in window)
    lo, hi = Fraction(0), Fraction(1)
    for a0, d, low, high in ((x0, x1 - x0, xmin, xmax), (y0, y1 - y0, ymin, ymax)):
        if d == 0:
            if not low <= a0 <= high:
                return None
            continue
        ta, tb = (low - a0) / d, (high - a0) / d
        lo, hi = max(lo, min(ta, tb)), min(hi, max(ta, tb))
    if lo > hi:
        return None
    return tuple(float(v) for v in (x0 + lo * (x1 - x0), y0 + lo * (y1 - y0),
                                    x0 + hi * (x1 - x0), y0 + hi * (y1 - y0)))


# -- the notes ----------------------------------------------------------------------
@pytest.mark.parametrize("point, code", [
    ((5, 5), "0000"), ((-1, 5), "0001"), ((11, 5), "0010"), ((5, -1), "0100"),
    ((5, 11), "1000"), ((-1, -1), "0101"), ((11, -1), "0110"), ((-1, 11), "1001"),
    ((11, 11), "1010"), ((0, 10), "0000"), ((10, 0), "0000"),
])
def test_region_codes_as_the_notes_number_the_bits(point, code):
    # bit 1 left (x < xwmin), 2 right (x > xwmax), 3 below, 4 above; written 4..1
    t = sl.trace.cohen_sutherland(*point, 5, 5, window=WINDOW)
    assert t.rows[0]["code0"] == code


def test_trivial_accept_and_trivial_reject():
    accept = sl.trace.cohen_sutherland(1, 1, 9, 9, window=WINDOW)
    assert [r["decision"] for r in accept.rows] == ["accept: both codes 0000"]
    # like the notes' P3 P4: both endpoints above the window -> AND = 1000
    reject = sl.trace.cohen_sutherland(-3, 12, 14, 15, window=WINDOW)
    assert [(r["code0"], r["code1"], r["and"]) for r in reject.rows] == [("1001", "1010", "1000")]
    assert reject.result is None
    # both outside, AND = 0000, but the line misses the window: clipped, then rejected
    miss = sl.trace.cohen_sutherland(-5, 8, 4, 17, window=WINDOW)
    assert miss.rows[0]["and"] == "0000" and miss.result is None


def test_cyrus_beck_table_1_t_values():
    """The notes' Table 1 for a rectangle: t_left = -(x0 - xmin) / (x1 - x0)
    (the notes print the denominator as x - x0, erratum E30), t_right =
    (x0 - xmax) / -(x1 - x0), t_bottom = -(y0 - ymin) / (y1 - y0), t_top =
    (y0 - ymax) / -(y1 - y0); normals (-1, 0), (1, 0), (0, -1), (0, 1)."""
    x0, y0, x1, y1 = -4.0, 1.0, 12.0, 13.0
    xmin, ymin, xmax, ymax = 0.0, 2.0, 10.0, 9.0
    t = sl.trace.cyrus_beck(x0, y0, x1, y1, window=(xmin, ymin, xmax, ymax))
    by_normal = {r["N"]: r for r in t.rows}
    expected = {
        "(-1, 0)": -(x0 - xmin) / (x1 - x0),
        "(1, 0)": (x0 - xmax) / -(x1 - x0),
        "(0, -1)": -(y0 - ymin) / (y1 - y0),
        "(0, 1)": (y0 - ymax) / -(y1 - y0),
    }
    assert set(by_normal) == set(expected)
    for n, tv in expected.items():
        assert by_normal[n]["t"] == pytest.approx(tv, abs=1e-15)
    # N.D < 0: potentially entering; N.D > 0: potentially leaving
    assert by_normal["(-1, 0)"]["kind"].startswith("PE")
    assert by_normal["(0, -1)"]["kind"].startswith("PE")
    assert by_normal["(1, 0)"]["kind"].startswith("PL")
    assert by_normal["(0, 1)"]["kind"].startswith("PL")
    # t_E = max(0, PE t's) = 0.25, t_L = min(1, PL t's) = 2/3
    assert t.rows[-1]["t_E"] == pytest.approx(0.25)
    assert t.rows[-1]["t_L"] == pytest.approx(2 / 3)
    assert t.result == pytest.approx((0.0, 4.0, 6.666666666666667, 9.0))


def test_liang_barsky_p_and_q():
    t = sl.trace.liang_barsky(2, 3, 12, 8, window=WINDOW)
    pq = [(r["p"], r["q"]) for r in t.rows]
    # p1 = -dx, q1 = x0 - xmin; p2 = dx, q2 = xmax - x0; p3 = -dy, q3 = y0 - ymin;
    # p4 = dy, q4 = ymax - y0
    assert pq == [(-10, 2), (10, 8), (-5, 3), (5, 7)]
    assert t.result == pytest.approx((2, 3, 10, 7))


def test_parallel_outside_rejected_in_the_parametric_clippers():
    for method in ("liang-barsky", "cyrus-beck"):
        assert sl.clip.line(-5, 12, 15, 12, WINDOW, method=method) is None
    t = sl.trace.liang_barsky(-5, 12, 15, 12, window=WINDOW)
    assert [r["kind"] for r in t.rows].count("parallel, outside: reject") == 1


# -- cross-checks -------------------------------------------------------------------
def _random_segments(rng, n):
    seg = rng.uniform(-15, 25, (n, 4))
    return seg


@pytest.mark.parametrize("method", METHODS)
def test_random_segments_match_shapely_intersection(method):
    rng = np.random.default_rng(1)
    seg = _random_segments(rng, 4000)
    ours, ok = sl.clip.lines(seg, WINDOW, method=method)
    ref, rok = shapely_segments(seg, shapely.box(*WINDOW))
    np.testing.assert_array_equal(ok, rok)
    assert same_segments(ours[ok], ref[ok], 1e-9).all()
    # the direction is the one given
    d_in = seg[ok, 2:] - seg[ok, :2]
    d_out = ours[ok, 2:] - ours[ok, :2]
    assert (np.einsum("ij,ij->i", d_in, d_out) >= 0).all()


def test_random_segments_match_shapely_clip_by_rect():
    rng = np.random.default_rng(2)
    seg = _random_segments(rng, 4000)
    lines = shapely.linestrings(seg.reshape(-1, 2, 2))
    res = shapely.clip_by_rect(lines, *WINDOW)
    rok = ~shapely.is_empty(res)
    ours, ok = sl.clip.lines(seg, WINDOW)
    np.testing.assert_array_equal(ok, rok)
    coords, index = shapely.get_coordinates(res, return_index=True)
    ref = np.array([np.r_[coords[index == i][0], coords[index == i][-1]]
                    for i in np.nonzero(rok)[0]])
    assert same_segments(ours[ok], ref, 1e-9).all()


@pytest.mark.parametrize("method", METHODS)
def test_integer_segments_touching_and_along_edges_match_exact_reference(method):
    """Small integer coordinates: many segments along an edge, through a corner,
    touching at one point, and zero-length segments."""
    rng = np.random.default_rng(3)
    seg = rng.integers(-3, 14, (3000, 4)).astype(float)
    seg[:300, 2:] = seg[:300, :2]                       # points
    seg[300:600, [1, 3]] = 10                           # along the top edge line
    seg[600:900, [0, 2]] = 0                            # along the left edge line
    ours, ok = sl.clip.lines(seg, WINDOW, method=method)
    for i, s in enumerate(seg):
        ref = exact_clip(s, WINDOW)
        assert ok[i] == (ref is not None), (s, ours[i])
        if ref is not None:
            assert ours[i] == pytest.approx(ref, abs=1e-9), s


def test_segments_along_edges_match_shapely_intersection():
    seg = np.array([(0, 0, 10, 0), (-5, 0, 15, 0), (10, -3, 10, 4), (-2, 10, 3, 10),
                    (-5, 5, 5, -5), (-5, 15, 15, -5), (12, 0, 10, 0)], float)
    ref, rok = shapely_segments(seg, shapely.box(*WINDOW))
    for method in METHODS:
        ours, ok = sl.clip.lines(seg, WINDOW, method=method)
        np.testing.assert_array_equal(ok, rok)
        assert same_segments(ours[ok], ref[ok], 1e-12).all()


def test_all_three_clippers_agree_on_many_segments():
    rng = np.random.default_rng(4)
    seg = np.concatenate([rng.uniform(-1e3, 1e3, (50_000, 4)),
                          rng.integers(-2, 13, (50_000, 4)).astype(float)])
    window = (-100.5, 2.0, 300.0, 450.25)
    a, oka = sl.clip.lines(seg, window, method="cohen-sutherland")
    b, okb = sl.clip.lines(seg, window, method="liang-barsky")
    c, okc = sl.clip.lines(seg, window, method="cyrus-beck")
    np.testing.assert_array_equal(oka, okb)
    np.testing.assert_array_equal(okb, okc)
    np.testing.assert_allclose(a[oka], b[okb], atol=1e-9)
    np.testing.assert_allclose(b, c, atol=1e-9)
    # rejected rows are left as given
    np.testing.assert_array_equal(a[~oka], seg[~oka])


def test_cyrus_beck_convex_windows_match_shapely():
    rng = np.random.default_rng(5)
    for trial in range(20):
        win = convex_polygon(rng, 8, radius=6)
        seg = rng.uniform(-15, 15, (500, 4))
        ours, ok = sl.clip.lines(seg, win, method="cyrus-beck")
        ref, rok = shapely_segments(seg, shapely.Polygon(win))
        np.testing.assert_array_equal(ok, rok)
        assert same_segments(ours[ok], ref[ok], 1e-9).all()
        # either orientation of the window gives the same result
        rev, okr = sl.clip.lines(seg, win[::-1], method="cyrus-beck")
        np.testing.assert_array_equal(ok, okr)
        np.testing.assert_allclose(rev[ok], ours[ok], atol=1e-12)


def test_line_and_lines_agree():
    assert sl.clip.line(-5, 5, 15, 5, WINDOW) == (0.0, 5.0, 10.0, 5.0)
    assert sl.clip.line(15, 5, -5, 5, WINDOW, method="cohen-sutherland") == (10.0, 5.0, 0.0, 5.0)
    assert sl.clip.line(3, 3, 3, 3, WINDOW) == (3.0, 3.0, 3.0, 3.0)
    assert sl.clip.line(11, 3, 11, 3, WINDOW) is None
    assert sl.clip.line(-5, 5, 5, -5, WINDOW) == (0.0, 0.0, 0.0, 0.0)   # touches a corner


# -- points and polylines -------------------------------------------------------------
def test_point_clipping_closed_window():
    pts = np.array([(0, 0), (10, 10), (5, 10.000001), (-1e-12, 5), (3, 4)])
    assert sl.clip.points(pts, WINDOW).tolist() == [True, True, False, False, True]
    tri = [(0, 0), (10, 0), (0, 10)]
    assert sl.clip.points([(5, 5), (5.1, 5), (1, 1)], tri).tolist() == [True, False, True]
    assert sl.clip.points([(5, 5), (5.1, 5)], tri[::-1]).tolist() == [True, False]


def test_polyline_matches_shapely_length_and_pieces():
    rng = np.random.default_rng(6)
    for _ in range(30):
        pts = rng.uniform(-5, 15, (12, 2))
        pieces = sl.clip.polyline(pts, WINDOW)
        ref = shapely.LineString(pts).intersection(shapely.box(*WINDOW))
        length = sum(np.hypot(*np.diff(p, axis=0).T).sum() for p in pieces)
        assert length == pytest.approx(ref.length, rel=1e-9, abs=1e-12)
        for p in pieces:
            assert sl.clip.points(p, (-1e-9, -1e-9, 10 + 1e-9, 10 + 1e-9)).all()


# -- the step tables are the algorithm --------------------------------------------------
def reference_cohen_sutherland_codes(seg, window):
    """The region codes (code0, code1) before each step of the notes' procedure,
    written independently in Python (endpoint with a nonzero code first; boundaries
    left, right, below, above)."""
    xmin, ymin, xmax, ymax = window

    def code(x, y):
        return ((x < xmin) * 1 | (x > xmax) * 2 | (y < ymin) * 4 | (y > ymax) * 8)

    x0, y0, x1, y1 = (Fraction(c) for c in seg)
    p = [[x0, y0], [x1, y1]]
    out = []
    while True:
        c = [code(*p[0]), code(*p[1])]
        out.append((format(c[0], "04b"), format(c[1], "04b")))
        if c[0] | c[1] == 0 or c[0] & c[1]:
            return out
        e = 0 if c[0] else 1
        if c[e] & 1:
            p[e] = [Fraction(xmin), y0 + (y1 - y0) * (xmin - x0) / (x1 - x0)]
        elif c[e] & 2:
            p[e] = [Fraction(xmax), y0 + (y1 - y0) * (xmax - x0) / (x1 - x0)]
        elif c[e] & 4:
            p[e] = [x0 + (x1 - x0) * (ymin - y0) / (y1 - y0), Fraction(ymin)]
        else:
            p[e] = [x0 + (x1 - x0) * (ymax - y0) / (y1 - y0), Fraction(ymax)]


def test_traces_agree_with_the_batch_clippers_on_random_segments():
    rng = np.random.default_rng(7)
    seg = np.concatenate([rng.uniform(-15, 25, (1500, 4)),
                          rng.integers(-4, 15, (1500, 4)).astype(float)])
    batch = {m: sl.clip.lines(seg, WINDOW, method=m) for m in METHODS}
    tracers = {"cohen-sutherland": sl.trace.cohen_sutherland,
               "liang-barsky": sl.trace.liang_barsky, "cyrus-beck": sl.trace.cyrus_beck}
    for i, s in enumerate(seg):
        for m, fn in tracers.items():
            out, ok = batch[m]
            r = fn(*s, window=WINDOW).result
            assert (r is not None) == ok[i]
            if r is not None:
                assert r == tuple(out[i])
    # and the codes of the Cohen-Sutherland table are the notes' procedure's codes
    for s in seg[1500:2500]:
        rows = sl.trace.cohen_sutherland(*s, window=WINDOW).rows
        assert [(r["code0"], r["code1"]) for r in rows] == reference_cohen_sutherland_codes(s, WINDOW)


# -- bad input --------------------------------------------------------------------------
@pytest.mark.parametrize("window", [(0, 0, 0, 10), (0, 5, 10, 5), (10, 0, 0, 10),
                                    (0, 0, float("nan"), 1), (0, 0, 1)])
def test_degenerate_windows_are_refused(window):
    with pytest.raises(sl.ArgumentValueError, match="window"):
        sl.clip.lines([(0, 0, 1, 1)], window)


def test_non_convex_window_refused_by_cyrus_beck():
    notch = [(0, 0), (10, 0), (10, 10), (5, 3), (0, 10)]
    with pytest.raises(sl.ArgumentValueError, match="convex.*weiler-atherton"):
        sl.clip.line(0, 0, 1, 1, notch, method="cyrus-beck")
    star = [(0, 0), (2, 6), (4, 0), (-1, 4), (5, 4)]       # turns one way, winds twice
    with pytest.raises(sl.ArgumentValueError, match="convex"):
        sl.clip.lines([(0, 0, 1, 1)], star, method="cyrus-beck")
    with pytest.raises(sl.ArgumentValueError, match="degenerate"):
        sl.clip.lines([(0, 0, 1, 1)], [(0, 0), (1, 1), (2, 2)], method="cyrus-beck")


def test_bad_segments_and_methods():
    with pytest.raises(sl.ArgumentValueError, match="segments row 1"):
        sl.clip.lines([(0, 0, 1, 1), (0, float("nan"), 1, 1)], WINDOW)
    with pytest.raises(sl.ArgumentValueError, match="shape"):
        sl.clip.lines([(0, 0, 1)], WINDOW)
    with pytest.raises(sl.ArgumentTypeError):
        sl.clip.lines("abc", WINDOW)
    with pytest.raises(sl.ArgumentValueError, match="method"):
        sl.clip.lines([(0, 0, 1, 1)], WINDOW, method="bresenham")
    with pytest.raises(sl.ArgumentValueError, match="cyrus-beck"):
        sl.clip.lines([(0, 0, 1, 1)], [(0, 0), (5, 0), (0, 5)], method="liang-barsky")
    with pytest.raises(sl.ArgumentValueError, match="x0"):
        sl.clip.line(float("inf"), 0, 1, 1, WINDOW)
    out, ok = sl.clip.lines(np.empty((0, 4)), WINDOW)
    assert out.shape == (0, 4) and ok.shape == (0,)


coord = st.one_of(st.floats(-2.0**30, 2.0**30), st.integers(-12, 22).map(float))


@HYPOTHESIS
@given(st.lists(st.tuples(coord, coord, coord, coord), min_size=1, max_size=20),
       st.sampled_from(METHODS))
def test_fuzzed_segments_stay_in_the_window(rows, method):
    seg = np.array(rows, float)
    out, ok = sl.clip.lines(seg, WINDOW, method=method)
    ref, rok = sl.clip.lines(seg, WINDOW, method="liang-barsky")
    tol = 1e-9 * max(1.0, float(np.abs(seg).max()))
    assert np.isfinite(out).all()
    lo, hi = np.array([0, 0, 0, 0]) - tol, np.array([10, 10, 10, 10]) + tol
    assert ((out[ok] >= lo) & (out[ok] <= hi)).all()
    # the three clippers agree except on segments that only graze the window
    differ = ok != rok
    if differ.any():
        for s in seg[differ]:
            r = exact_clip(s, WINDOW)
            assert r is None or np.hypot(r[2] - r[0], r[3] - r[1]) <= tol


def test_entering_before_the_start():
    """Erratum E31: t = 0 is a lower bound of t_E."""
    t = sl.trace.cyrus_beck(5, 2, 15, 12, window=WINDOW)
    entering = [r for r in t.rows if r["kind"].startswith("PE")]
    assert min(r["t"] for r in entering) < 0
    assert t.rows[-1]["t_E"] == 0.0
    assert t.result == (5.0, 2.0, 10.0, 7.0)


def test_notes_example_p1_below_p2_left_and_above():
    """Erratum E34: P1 below (one intersection P1'), P2 left and, after its first
    intersection P2', still outside above: a second intersection P2''."""
    t = sl.trace.cohen_sutherland(6, -2, -2, 15, window=WINDOW)
    steps = [(r["code0"], r["code1"], r["decision"]) for r in t.rows]
    assert steps == [("0100", "1001", "clip P0 at below (y = 0)"),
                     ("0000", "1001", "clip P1 at left (x = 0)"),
                     ("0000", "1000", "clip P1 at above (y = 10)"),
                     ("0000", "0000", "accept: both codes 0000")]
    assert (t.rows[0]["x"], t.rows[0]["y"]) == pytest.approx((6 - 8 * 2 / 17, 0))
    assert (t.rows[1]["x"], t.rows[1]["y"]) == pytest.approx((0, 10.75))
    assert (t.rows[2]["x"], t.rows[2]["y"]) == pytest.approx((6 - 8 * 12 / 17, 10))


def test_cohen_sutherland_round_off_at_a_corner_does_not_reject():
    # a denormal start just outside the corner (0, 0): each crossing rounds to a point
    # just outside the other boundary; the boundaries an end was moved onto stay
    # cleared, so the segment is accepted instead of chasing the corner until the
    # step limit rejects it (found by test_fuzzed_segments_stay_in_the_window)
    tiny = -2.225073858507e-311
    out, ok = sl.clip.lines([(tiny, tiny, 4.0, 4.0)], WINDOW, method="cohen-sutherland")
    assert ok.tolist() == [True]
    assert np.allclose(out, [[0, 0, 4, 4]], atol=1e-300)
    t = sl.trace.cohen_sutherland(tiny, tiny, 4.0, 4.0, window=WINDOW)
    assert [r["decision"].split(" (")[0] for r in t.rows] == [
        "clip P0 at left", "clip P0 at below", "accept: both codes 0000"]
