"""Polygon clipping: Sutherland-Hodgman (convex windows, batch kernel) and
Weiler-Atherton (concave windows and subjects, holes), against shapely's
intersection; the separate pieces of Weiler-Atherton versus the connecting edges
of Sutherland-Hodgman; degenerate cases."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from tests.clip.shapes import area, convex_polygon, shapely, star_polygon
from tests.reference import HYPOTHESIS

U_SHAPE = [(0, 0), (6, 0), (6, 6), (4, 6), (4, 2), (2, 2), (2, 6), (0, 6)]


def shapely_area(subject, window):
    return shapely.Polygon(subject).intersection(shapely.Polygon(window)).area


def rect_ring(r):
    x0, y0, x1, y1 = r
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def close(a, b):
    return abs(a - b) <= 1e-9 * max(abs(b), 1.0)


# -- the concave case of the figure ------------------------------------------------------
def test_sutherland_hodgman_joins_the_pieces_with_degenerate_edges():
    (c,) = sl.clip.polygon(U_SHAPE, (-1, 3, 7, 5))
    # one contour: both legs of the U, joined along the window's lower edge y = 3
    assert c.tolist() == [[0, 5], [0, 3], [6, 3], [6, 5], [4, 5], [4, 3], [2, 3], [2, 5]]
    assert area([c]) == pytest.approx(8.0)
    # the joining edges (2, 3) -> (4, 3) run twice, in opposite directions: no area
    edges = list(zip(map(tuple, c), map(tuple, np.roll(c, -1, axis=0))))
    assert ((4.0, 3.0), (2.0, 3.0)) in edges and ((0.0, 3.0), (6.0, 3.0)) in edges


def test_weiler_atherton_gives_separate_pieces():
    pieces = sl.clip.polygon(U_SHAPE, (-1, 3, 7, 5), method="weiler-atherton")
    assert sorted(c.tolist() for c in pieces) == [
        [[0, 3], [2, 3], [2, 5], [0, 5]], [[4, 3], [6, 3], [6, 5], [4, 5]]]
    assert all(area([c]) == pytest.approx(4.0) for c in pieces)


def test_concave_window_cuts_a_convex_subject_into_pieces():
    window = [(0, 0), (10, 0), (10, 10), (7, 10), (7, 2), (3, 2), (3, 10), (0, 10)]
    subject = [(-1, 5), (11, 5), (11, 8), (-1, 8)]
    pieces = sl.clip.polygon(subject, window, method="weiler-atherton")
    assert sorted(c.tolist() for c in pieces) == [
        [[0, 5], [3, 5], [3, 8], [0, 8]], [[7, 5], [10, 5], [10, 8], [7, 8]]]
    with pytest.raises(sl.ArgumentValueError, match="weiler-atherton"):
        sl.clip.polygon(subject, window)        # Sutherland-Hodgman needs convex


# -- against shapely ---------------------------------------------------------------------
def test_sutherland_hodgman_areas_match_shapely_rectangles():
    rng = np.random.default_rng(10)
    for _ in range(200):
        subject = star_polygon(rng, int(rng.integers(3, 15)), center=rng.uniform(-5, 5, 2))
        x0, y0 = rng.uniform(-8, 4, 2)
        window = (x0, y0, x0 + rng.uniform(0.5, 12), y0 + rng.uniform(0.5, 12))
        got = abs(area(sl.clip.polygon(subject, window)))
        assert close(got, shapely_area(subject, rect_ring(window)))


def test_sutherland_hodgman_areas_match_shapely_convex_windows():
    rng = np.random.default_rng(11)
    for _ in range(200):
        subject = star_polygon(rng, int(rng.integers(3, 15)))
        window = convex_polygon(rng, int(rng.integers(3, 10)), radius=5)
        got = abs(area(sl.clip.polygon(subject, window)))
        assert close(got, shapely_area(subject, window))
        # either orientation of the subject: same area, sign follows the subject
        assert close(area(sl.clip.polygon(subject[::-1], window[::-1])),
                     -area(sl.clip.polygon(subject, window)))


def test_batch_equals_one_at_a_time_and_flat_counts():
    rng = np.random.default_rng(12)
    polys = [star_polygon(rng, int(rng.integers(3, 12)), center=rng.uniform(-8, 8, 2))
             for _ in range(300)]
    window = (-3, -2, 5, 6)
    batch = sl.clip.polygons(polys, window)
    for p, b in zip(polys, batch):
        one = sl.clip.polygon(p, window)
        if len(b):
            np.testing.assert_array_equal(one[0], b)
        else:
            assert one == []
        assert close(abs(area([b])) if len(b) else 0.0, shapely_area(p, rect_ring(window)))
    flat, counts = sl.clip.polygons(np.concatenate(polys), window,
                                    counts=[len(p) for p in polys])
    assert counts.tolist() == [len(b) for b in batch]
    np.testing.assert_array_equal(flat, np.concatenate(batch))


def test_saw_with_many_crossings():
    # 60 teeth, each crossing the window's top edge twice: twice as many vertices out
    comb = [(0.0, 0.0), (60.0, 0.0)]
    for x in range(60, 0, -1):
        comb += [(x, 10.0), (x - 0.5, 1.0)]
    comb.append((0.0, 10.0))
    window = (-1, 0, 61, 5)
    (out,) = sl.clip.polygons([np.array(comb)], window)
    assert len(out) > 2 * 60
    assert close(abs(area([out])), shapely_area(comb, rect_ring(window)))
    pieces = sl.clip.polygon(comb, window, method="weiler-atherton")
    assert len(pieces) == 1 and close(area(pieces), shapely_area(comb, rect_ring(window)))


def test_weiler_atherton_areas_and_pieces_match_shapely_concave_windows():
    rng = np.random.default_rng(13)
    for _ in range(150):
        subject = star_polygon(rng, int(rng.integers(3, 14)), center=rng.uniform(-3, 3, 2))
        window = star_polygon(rng, int(rng.integers(3, 14)), center=rng.uniform(-3, 3, 2))
        pieces = sl.clip.polygon(subject, window, method="weiler-atherton")
        ref = shapely.Polygon(subject).intersection(shapely.Polygon(window))
        assert close(area(pieces), ref.area)
        parts = [g for g in getattr(ref, "geoms", [ref]) if g.area > 0]
        assert len(pieces) == len(parts)
        for c in pieces:                     # every piece counterclockwise (no holes here)
            assert area([c]) > 0


def test_weiler_atherton_on_integer_grids_with_vertices_on_edges():
    """Small integer polygons: vertices on the other boundary, shared vertices,
    overlapping collinear edges, touching corners."""
    rng = np.random.default_rng(14)
    for _ in range(300):
        subject = star_polygon(rng, int(rng.integers(3, 10)), center=(0, 0), r=(1, 5),
                               integer=True)
        window = star_polygon(rng, int(rng.integers(3, 10)), center=(0.5, -0.5), r=(1, 5),
                              integer=True)
        pieces = sl.clip.polygon(subject, window, method="weiler-atherton")
        ref = shapely.Polygon(subject).intersection(shapely.Polygon(window))
        assert close(area(pieces), ref.area), (subject.tolist(), window.tolist())
        for c in pieces:
            assert len(c) >= 3


def test_weiler_atherton_rectangles_equal_sutherland_hodgman_areas():
    rng = np.random.default_rng(15)
    for _ in range(100):
        subject = star_polygon(rng, int(rng.integers(3, 14)))
        window = (-4, -3, 5, 2)
        wa = sl.clip.polygon(subject, window, method="weiler-atherton")
        sh = sl.clip.polygon(subject, window)
        assert close(area(wa), abs(area(sh)))


# -- degenerate cases --------------------------------------------------------------------
def test_subject_inside_outside_and_window_inside_subject():
    square = [(0, 0), (10, 0), (10, 10), (0, 10)]
    inner = (2, 2, 4, 4)
    for method in ("sutherland-hodgman", "weiler-atherton"):
        (c,) = sl.clip.polygon(square, inner, method=method)     # window inside subject
        assert abs(area([c])) == pytest.approx(4.0)
        assert sl.clip.polygon(square, (20, 20, 30, 30), method=method) == []
        (c,) = sl.clip.polygon(square, (-5, -5, 15, 15), method=method)  # subject inside
        assert sorted(map(tuple, c.tolist())) == sorted(square)


def test_subject_sharing_edges_with_the_window():
    square = [(0, 0), (10, 0), (10, 10), (0, 10)]
    for method in ("sutherland-hodgman", "weiler-atherton"):
        (c,) = sl.clip.polygon(square, (0, 0, 10, 10), method=method)
        assert sorted(map(tuple, c.tolist())) == sorted(square)
        (c,) = sl.clip.polygon(square, (0, 0, 5, 10), method=method)
        assert abs(area([c])) == pytest.approx(50.0)
        # touching from outside along an edge: nothing
        assert sl.clip.polygon(square, (10, 0, 20, 10), method=method) == []
    # a triangle with a vertex on the window edge, otherwise outside
    assert sl.clip.polygon([(10, 5), (15, 0), (15, 10)], (0, 0, 10, 10),
                           method="weiler-atherton") == []
    assert sl.clip.polygon([(10, 5), (15, 0), (15, 10)], (0, 0, 10, 10)) == []


def test_holes():
    shell = [(0, 0), (10, 0), (10, 10), (0, 10)]
    hole = [(3, 3), (7, 3), (7, 7), (3, 7)]
    ref = shapely.Polygon(shell, [hole])
    for window in [(5, -1, 12, 11), (-1, -1, 11, 11), (4, 4, 6, 6), (2, 2, 8, 5)]:
        want = ref.intersection(shapely.box(*window))
        wa = sl.clip.polygon([shell, hole], window, method="weiler-atherton")
        assert close(area(wa), want.area)
        sh = sl.clip.polygon([shell, hole[::-1]], window)    # hole clockwise: areas add
        assert close(area(sh), want.area)
    # the window entirely inside the hole: nothing; around the hole: a ring
    assert sl.clip.polygon([shell, hole], (4, 4, 6, 6), method="weiler-atherton") == []
    ring = sl.clip.polygon([shell, hole], (1, 1, 9, 9), method="weiler-atherton")
    assert sorted(np.sign([area([c]) for c in ring]).tolist()) == [-1.0, 1.0]
    # a concave window with a hole in the subject cut into two pieces
    window = [(-1, 4), (11, 4), (11, 6), (-1, 6)]
    pieces = sl.clip.polygon([shell, hole], window, method="weiler-atherton")
    assert len(pieces) == 2 and close(area(pieces), 12.0)


def test_window_with_a_hole():
    frame = [[(0, 0), (10, 0), (10, 10), (0, 10)], [(3, 3), (7, 3), (7, 7), (3, 7)]]
    ref = shapely.Polygon(frame[0], [frame[1]])
    rng = np.random.default_rng(16)
    for _ in range(40):
        subject = star_polygon(rng, int(rng.integers(3, 12)), center=rng.uniform(2, 8, 2),
                               r=(1, 7))
        pieces = sl.clip.polygon(subject, frame, method="weiler-atherton")
        assert close(area(pieces), ref.intersection(shapely.Polygon(subject)).area)
    with pytest.raises(sl.ArgumentValueError, match="one polygon contour"):
        sl.clip.polygon(U_SHAPE, frame)          # Sutherland-Hodgman: one convex contour


# -- bad input ---------------------------------------------------------------------------
def test_bad_polygon_input():
    with pytest.raises(sl.ArgumentValueError, match="window"):
        sl.clip.polygon(U_SHAPE, (0, 0, 0, 5))
    with pytest.raises(sl.ArgumentValueError, match="degenerate"):
        sl.clip.polygon(U_SHAPE, [(0, 0), (1, 1), (2, 2)], method="weiler-atherton")
    with pytest.raises(sl.ArgumentValueError, match="points"):
        sl.clip.polygon([(0, 0), (1, float("nan")), (0, 1)], (0, 0, 1, 1))
    with pytest.raises(sl.ArgumentValueError, match="method"):
        sl.clip.polygon(U_SHAPE, (0, 0, 1, 1), method="cohen-sutherland")
    with pytest.raises(sl.ArgumentValueError, match="counts"):
        sl.clip.polygons(np.zeros((5, 2)), (0, 0, 1, 1), counts=[2, 2])
    assert sl.clip.polygon([(0, 0), (1, 1), (2, 2)], (0, 0, 5, 5)) == []   # zero area
    assert sl.clip.polygons([], (0, 0, 1, 1)) == []


small = st.floats(-50, 50, allow_nan=False)


@HYPOTHESIS
@given(st.lists(st.tuples(small, small), min_size=3, max_size=12),
       st.tuples(small, small, st.floats(0.01, 60), st.floats(0.01, 60)))
def test_fuzzed_sutherland_hodgman_never_leaves_the_window(pts, win):
    x0, y0, w, h = win
    window = (x0, y0, x0 + w, y0 + h)
    for c in sl.clip.polygons([np.array(pts)], window):
        if len(c):
            assert (c[:, 0] >= window[0] - 1e-9).all() and (c[:, 0] <= window[2] + 1e-9).all()
            assert (c[:, 1] >= window[1] - 1e-9).all() and (c[:, 1] <= window[3] + 1e-9).all()
    poly = shapely.Polygon(pts)
    # GEOS, the reference, goes wrong at subnormal coordinates (see the test below)
    subnormal = any(0 < abs(v) < np.finfo(float).tiny for v in (*np.ravel(pts), *window))
    if poly.is_valid and not subnormal:
        got = area(sl.clip.polygon(pts, window))
        assert abs(abs(got) - poly.intersection(shapely.box(*window)).area) <= 1e-9 * max(1, poly.area)


def test_a_window_edge_at_a_subnormal_coordinate():
    # found by the fuzzed test above: the triangle (0, 0), (1, 0), (-1, 1/4) meets x = 0
    # at (0, 0) and (0, 1/8), so the part right of x = 0 is the triangle (0, 0), (1, 0),
    # (0, 1/8) of area 1/16; a left edge a subnormal 2.2e-313 further right cuts it at
    # y = 1/8 - 2.2e-313 / 8 = 1/8 in float64.  (shapely 2 / GEOS gives 0.125 here, the
    # area of a quadrilateral through (2.2e-313, 1/4), a point outside the triangle,
    # and 0.0625 for a left edge at 0, 1e-300 or the least normal float.)
    pts = [(0.0, 0.0), (1.0, 0.0), (-1.0, 0.25)]
    for x0 in (0.0, 2.2250738585e-313, 1e-300):
        (piece,) = sl.clip.polygon(pts, (x0, 0.0, 1.0, 0.25))
        assert sorted(map(tuple, piece.tolist())) == [(x0, 0.0), (x0, 0.125), (1.0, 0.0)]
        assert area([piece]) == 0.0625


grid = st.integers(-6, 6).map(float)


@HYPOTHESIS
@given(st.lists(st.tuples(grid, grid), min_size=3, max_size=9),
       st.lists(st.tuples(grid, grid), min_size=3, max_size=9))
def test_fuzzed_weiler_atherton(subject, window):
    """Any vertex lists (self-intersecting ones too) never crash or hang; valid
    simple polygons give shapely's area."""
    try:
        pieces = sl.clip.polygon(subject, window, method="weiler-atherton")
    except sl.ArgumentValueError as e:
        assert "window" in str(e)
        return
    s, c = shapely.Polygon(subject), shapely.Polygon(window)
    if s.is_valid and c.is_valid and s.area > 0 and c.area > 0:
        assert close(area(pieces), s.intersection(c).area)


wide = st.one_of(st.floats(-2.0**30, 2.0**30), st.integers(-3, 3).map(float))


@HYPOTHESIS
@given(st.lists(st.lists(st.tuples(wide, wide), min_size=0, max_size=8), min_size=1,
                max_size=6),
       st.tuples(st.floats(-2.0**29, 2.0**29), st.floats(-2.0**29, 2.0**29),
                 st.floats(1e-6, 2.0**29), st.floats(1e-6, 2.0**29)))
def test_fuzzed_batch_with_huge_and_degenerate_polygons(polys, win):
    """Huge, tiny, empty and self-intersecting polygons: the kernel never writes out of
    its buffers, and each result stays in the window."""
    x0, y0, w, h = win
    window = (x0, y0, x0 + w, y0 + h)
    flat = np.array([p for poly in polys for p in poly], float).reshape(-1, 2)
    verts, counts = sl.clip.polygons(flat, window, counts=[len(p) for p in polys])
    assert counts.sum() == len(verts) and len(counts) == len(polys)
    assert ((counts == 0) | (counts >= 3)).all()
    # round-off of a crossing grows with the coordinates; coordinates set by an edge
    # of the upright window are exact
    scale = max(1.0, abs(x0) + w, abs(y0) + h, float(np.abs(flat).max(initial=0.0)))
    tol = 1e-12 * scale
    assert (verts[:, 0] >= window[0] - tol).all() and (verts[:, 0] <= window[2] + tol).all()
    assert (verts[:, 1] >= window[1] - tol).all() and (verts[:, 1] <= window[3] + tol).all()


def test_a_thin_window_far_from_the_origin_keeps_its_orientation():
    # the shoelace products about the origin cancel for a small window far out
    # (found by test_fuzzed_batch_with_huge_and_degenerate_polygons)
    x0, y0 = 129078211.23632824, 531605824.58740246
    window = (x0, y0, x0 + 0.49392618405547467, y0 + 5.789799812184172)
    square = [(x0 - 1, y0 - 1), (x0 + 1, y0 - 1), (x0 + 1, y0 + 1), (x0 - 1, y0 + 1)]
    verts, counts = sl.clip.polygons(np.array(square), window, counts=[4])
    assert counts.tolist() == [4]
    assert np.all(verts[:, 0] >= window[0]) and np.all(verts[:, 0] <= window[2])
