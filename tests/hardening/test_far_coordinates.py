"""Any finite coordinate is drawn, clipped (issue 11, item 2): geometry beyond the
exact range +-2**30 is clipped in floating point to the guard square before the
integer kernels (:mod:`scanline.geometry.guard`); the pixels are those of the same
primitive given with its visible part in range."""

import numpy as np
import pytest

import scanline as sl
from scanline.geometry import guard
from tests.reference import lit, peer

W, H = 40, 30
BIG = [1e12, -1e12, 1e300, -1e300, 2.0**31, 9.007199254740993e15]


def fb(mode="L"):
    return sl.FrameBuffer(W, H, mode=mode)


def same(draw_far, draw_near):
    a, b = fb(), fb()
    draw_far(a)
    draw_near(b)
    assert b.to_array().any()
    np.testing.assert_array_equal(a.to_array(), b.to_array())


@pytest.mark.parametrize("big", [1e12, 1e300, 2.0**31])
def test_lines_and_polylines_beyond_the_range(big):
    # a horizontal line through the frame from -big to +big is the in-range line
    same(lambda f: sl.draw.line(f, -big, 15, big, 15), lambda f: sl.draw.line(f, -5, 15, 50, 15))
    same(lambda f: sl.draw.lines(f, [[-big, 7, big, 7], [3, -big, 3, big]]),
         lambda f: sl.draw.lines(f, [[-9, 7, 60, 7], [3, -9, 3, 60]]))
    same(lambda f: sl.draw.antialias.lines(f, [[-big, 7.3, big, 7.3]]),
         lambda f: sl.draw.antialias.lines(f, [[-2**20, 7.3, 2**20, 7.3]]))
    same(lambda f: sl.draw.polyline(f, [(-big, 5), (20, 5), (20, big)]),
         lambda f: sl.draw.polyline(f, [(-50, 5), (20, 5), (20, 80)]))
    same(lambda f: sl.draw.polyline(f, [(-big, 5), (20, 5), (20, big)], width=3),
         lambda f: sl.draw.polyline(f, [(-50, 5), (20, 5), (20, 80)], width=3))
    same(lambda f: sl.draw.polyline(f, [(-big, 5), (20, 5), (20, big)], width=3, antialias=True),
         lambda f: sl.draw.polyline(f, [(-50, 5), (20, 5), (20, 80)], width=3, antialias=True))


def test_a_diagonal_from_far_away_keeps_its_slope_exactly():
    # (-1e300, -1e300)-(1e300, 1e300): the diagonal y = x; float interpolation from
    # the far endpoint would be off by 1e284
    same(lambda f: sl.draw.line(f, -1e300, -1e300, 1e300, 1e300),
         lambda f: sl.draw.line(f, -100, -100, 100, 100))
    same(lambda f: sl.draw.polygon(f, [(-1e300, -1e300), (1e300, 1e300), (1e300, -1e300)]),
         lambda f: sl.draw.polygon(f, [(-100, -100), (100, 100), (100, -100)]))


@pytest.mark.parametrize("big", [1e12, 1e300])
def test_fills_beyond_the_range(big):
    tri = [(-big, -big), (big, -big), (0, big)]
    # everything of the frame inside: the full frame
    a = fb()
    sl.draw.polygon(a, tri)
    assert a.to_array().all()
    # a half plane y < 12.5 with far corners, both fill rules and antialiased
    far_rect = [(-big, -big), (big, -big), (big, 12.5), (-big, 12.5)]
    near = [(-9, -9), (60, -9), (60, 12.5), (-9, 12.5)]
    for rule in ("even-odd", "nonzero"):
        same(lambda f: sl.draw.polygon(f, far_rect, rule=rule),
             lambda f: sl.draw.polygon(f, near, rule=rule))
    same(lambda f: sl.draw.polygon(f, far_rect, antialias=True),
         lambda f: sl.draw.polygon(f, near, antialias=True))
    same(lambda f: sl.draw.polygons(f, [far_rect, [(2, 20), (8, 20), (5, 26)]], color=["red", "blue"]),
         lambda f: sl.draw.polygons(f, [near, [(2, 20), (8, 20), (5, 26)]], color=["red", "blue"]))


def test_winding_is_kept_inside_the_guard():
    # a far square wound twice (nonzero: inside; even-odd: outside) around the frame
    big = 1e15
    sq = [(-big, -big), (big, -big), (big, big), (-big, big)]
    twice = sq + sq
    a, b = fb(), fb()
    sl.draw.polygon(a, twice, rule="nonzero")
    sl.draw.polygon(b, twice, rule="even-odd")
    assert a.to_array().all() and not b.to_array().any()


def test_off_screen_ellipse_at_1e9_with_ry_1e8_draws_nothing():
    for draw in (lambda f: sl.draw.ellipse(f, 1e9, 15, 3e8, 1e8),
                 lambda f: sl.draw.ellipse(f, 1e9, 15, 1e8, 1e8, width=3),
                 lambda f: sl.draw.fill_ellipse(f, 1e9, 15, 3e8, 1e8),
                 lambda f: sl.draw.circle(f, 1e12, 15, 5),
                 lambda f: sl.draw.circle(f, 20, 15, 1e12),          # the frame in the hole
                 lambda f: sl.draw.circle(f, 20, 15, 1e12, dash=(2, 1))):
        f = fb()
        draw(f)
        assert not f.to_array().any()


def test_nan_and_inf_are_still_refused():
    for bad in (np.nan, np.inf, -np.inf):
        with pytest.raises(sl.ArgumentValueError, match="finite"):
            sl.draw.polygon(fb(), [(0, 0), (bad, 3), (5, 5)])
        with pytest.raises(sl.ArgumentValueError, match="finite"):
            sl.draw.lines(fb(), [[0, 0, bad, 3]])
        with pytest.raises(sl.ArgumentValueError, match="finite"):
            sl.draw.polyline(fb(), [(0, 0), (bad, 3)], width=2)


@pytest.mark.parametrize("dtype", [np.float16, np.float32, np.float64])
def test_inf_in_a_narrow_float_array_is_refused_too(dtype):
    # against a float16 array the range check compared with the limit cast to
    # float16 (inf), so inf passed it and reached the exact clipping as a raw error
    for bad in (np.nan, np.inf, -np.inf):
        for call in (lambda s: sl.draw.antialias.lines(fb(), s, "white"),
                     lambda s: sl.draw.lines(fb(), s)):
            with pytest.raises(sl.ArgumentValueError, match="finite"):
                call(np.array([[0, 0, 0, bad]], dtype))
    sl.draw.antialias.lines(fb(), np.array([[0, 0, 0, 60000]], np.float16), "white")


def test_guard_ring_matches_shapely_inside_the_guard():
    shapely = peer("shapely")
    from shapely.geometry import Polygon, box
    rng = np.random.default_rng(5)
    for _ in range(20):
        hull = Polygon(rng.normal(0, 2**31, (9, 2))).convex_hull   # a valid convex ring
        pts = np.array(hull.exterior.coords[:-1])
        ours = guard.ring(pts)
        ref = Polygon(pts).intersection(box(-guard.GUARD, -guard.GUARD, guard.GUARD, guard.GUARD))
        assert abs(Polygon(ours).area - ref.area) <= 1e-9 * max(ref.area, 1.0)


def test_far_segments_outside_the_guard_keep_their_colors():
    f = fb("RGB")
    sl.draw.lines(f, [[-1e300, -5e299, -1e300, 5e299], [0, 3, 39, 3]], color=["red", "blue"])
    assert (f.to_array()[H - 1 - 3] == (0, 0, 255)).all()


def test_far_paths_clip_each_segment_as_the_exact_clipping_does():
    # the guard's fast paths (segments within the guard kept, segments beyond one of
    # its sides dropped, without exact arithmetic) give what clipping every segment
    # exactly gives, joined into the same runs
    g = guard.GUARD
    rng = np.random.default_rng(11)
    special = np.array([0.0, g, -g, 2 * g, -2 * g, g + 0.5, -g - 0.5, 3e9, 1e12, -1e300])
    for _ in range(300):
        k = int(rng.integers(2, 12))
        p = np.where(rng.random((k, 2)) < 0.5, rng.choice(special, (k, 2)),
                     rng.uniform(-3 * g, 3 * g, (k, 2)))
        p[0] = (3e9, 0.0)                                       # far, so it is clipped
        verts, offsets, closed, owner = guard.paths(p, np.array([0, k]), np.array([False]))
        want, run = [], []
        for e in np.hstack([p[:-1], p[1:]]):
            s = guard._clip_segment(e)
            if s is None:
                continue
            if run and not np.array_equal(run[-1], s[:2]):
                want.append(np.array(run))
                run = []
            run = run or [s[:2]]
            run.append(s[2:])
        want += [np.array(run)] if run else []
        got = [verts[a:b] for a, b in zip(offsets[:-1], offsets[1:])]
        assert len(got) == len(want) and all(np.array_equal(a, b) for a, b in zip(got, want))
        assert not closed.any() and (owner == 0).all()


def test_a_long_far_path_clips_only_the_segments_crossing_the_guard(monkeypatch):
    # an antialiased dashed circle of radius 2**30 centered at y = 2**30: its polygon
    # of 230,000 segments reaches 2**31 and was clipped one exact segment at a time
    # (18 s); only the few that cross the guard's boundary need exact arithmetic
    exact = []
    clip = guard._clip_segment
    monkeypatch.setattr(guard, "_clip_segment", lambda e: exact.append(1) or clip(e))
    fb_ = sl.FrameBuffer(1, 1, mode="1")
    sl.draw.circle(fb_, 0, 2**30, 2**30, width=3, dash=(2, 1), antialias=True)
    assert 0 < len(exact) < 100


FAR_TRIANGLES = [[(0, 0), (1e300, 5), (5, 1e300)], [(3, -1e12), (40, 1e12), (-3e9, 7)],
                 [(-1e300, -1e300), (1e300, -1e300), (0, 1e300)],
                 [(5, 5), (2**31, 9), (9, 2**31)], [(1e15, 1e15), (2e15, 1e15), (1e15, 3e15)]]


@pytest.mark.parametrize("xy", FAR_TRIANGLES)
def test_far_triangles_are_drawn_with_their_depth_and_perspective_colors(xy):
    # pixels: the 2-D polygon fill's; depth and colors: the plane and the
    # perspective-correct interpolation of the whole triangle, evaluated exactly at
    # each pixel center (Fractions), so the guard's cut edges change nothing inside
    from fractions import Fraction

    w, h = 16, 12
    z, ws = (0.25, 0.5, 0.75), (1.0, 2.0, 4.0)
    cols = np.array([[255, 0, 0], [0, 255, 0], [0, 0, 255]], float)
    tri = np.array([[(x, y, zz) for (x, y), zz in zip(xy, z)]])
    fb = sl.FrameBuffer(w, h)
    depth = sl.DepthBuffer(w, h)
    sl.draw.triangles(fb, tri, colors=cols[None], depth=depth, w=np.array([ws]))
    ref = sl.FrameBuffer(w, h, mode="1")
    sl.draw.polygon(ref, np.array(xy, float), color=1)
    got = fb.to_array()[::-1]                                    # [y, x]
    assert {(x, y) for y, x in zip(*np.nonzero(got.any(axis=2)))} == lit(ref)
    (x0, y0), (x1, y1), (x2, y2) = [(Fraction(a), Fraction(b)) for a, b in xy]
    area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    # and independently: every pixel center strictly inside the exact triangle is
    # drawn, every one strictly outside is not (centers on an edge: the tie rule)
    for x in range(w):
        for y in range(h):
            l1 = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / area
            l2 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / area
            lam = (1 - l1 - l2, l1, l2)
            if min(lam) != 0:
                assert got[y, x].any() == (min(lam) > 0), (x, y)
    zs = depth.to_array()[::-1]
    for x, y in lit(ref):
        l1 = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / area
        l2 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / area
        lam = (1 - l1 - l2, l1, l2)
        assert zs[y, x] == pytest.approx(float(sum(a * Fraction(b) for a, b in zip(lam, z))),
                                         abs=1e-6)
        q = [lam[i] / Fraction(ws[i]) for i in range(3)]
        want = [float(sum(q[i] * Fraction(cols[i, c]) for i in range(3)) / sum(q)) for c in range(3)]
        assert np.abs(got[y, x].astype(float) - want).max() <= 1.0, (x, y)
