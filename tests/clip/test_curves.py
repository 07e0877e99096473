"""Circle, ellipse and curve clipping: the visible arcs against sampled points and
against shapely's intersection of a finely flattened outline."""

import math

import numpy as np
import pytest

import scanline as sl
from tests.clip.shapes import convex_polygon, shapely


def in_intervals(t, intervals):
    t = np.mod(t, 2 * math.pi)
    hit = np.zeros(t.shape, bool)
    for a, b in intervals:
        hit |= ((t >= a) & (t <= b)) | ((t + 2 * math.pi >= a) & (t + 2 * math.pi <= b))
    return hit


def test_notes_style_cases():
    two_pi = 2 * math.pi
    assert sl.clip.circle(5, 5, 2, (0, 0, 10, 10)) == [(0.0, two_pi)]   # inside
    assert sl.clip.circle(50, 5, 2, (0, 0, 10, 10)) == []                # outside
    assert sl.clip.circle(5, 5, 100, (0, 0, 10, 10)) == []               # around the window
    (a, b), = sl.clip.circle(0, 0, 1, (0, -5, 5, 5))                      # right half
    assert (a, b) == pytest.approx((1.5 * math.pi, 2.5 * math.pi))
    # tangent to the window from outside: only a point touches, no arc
    assert sl.clip.circle(-1, 5, 1, (0, 0, 10, 10)) == []


@pytest.mark.parametrize("seed", range(6))
def test_visible_arcs_match_sampled_points_and_shapely(seed):
    rng = np.random.default_rng(seed)
    for _ in range(10):
        xc, yc = rng.uniform(-6, 6, 2)
        rx, ry = rng.uniform(0.5, 9, 2)
        window = (convex_polygon(rng, 6, radius=5) if seed % 2
                  else (-4.0, -3.0, rng.uniform(0, 6), rng.uniform(0, 6)))
        arcs = sl.clip.ellipse(xc, yc, rx, ry, window)
        for a, b in arcs:
            assert 0 <= a < 2 * math.pi and a < b <= a + 2 * math.pi
        t = rng.uniform(0, 2 * math.pi, 20000)
        pts = np.stack([xc + rx * np.cos(t), yc + ry * np.sin(t)], axis=1)
        inside = sl.clip.points(pts, window)
        got = in_intervals(t, arcs)
        # disagreement only within round-off of the boundary
        bad = got != inside
        if bad.any():
            ring = np.asarray(window if seed % 2 else
                              [(window[0], window[1]), (window[2], window[1]),
                               (window[2], window[3]), (window[0], window[3])])
            dist = shapely.distance(shapely.points(pts[bad]), shapely.Polygon(ring).exterior)
            assert dist.max() < 1e-9
        # visible length versus shapely on a fine outline
        k = 200_000
        tt = np.linspace(0, 2 * math.pi, k + 1)
        outline = shapely.LineString(np.stack([xc + rx * np.cos(tt), yc + ry * np.sin(tt)], 1))
        geom = (shapely.Polygon(window) if seed % 2 else shapely.box(*window))
        ref = outline.intersection(geom).length
        mine = sum(np.hypot(*np.diff(p, axis=0).T).sum()
                   for p in sl.clip.arcs(xc, yc, rx, ry, arcs, tolerance=1e-7))
        assert mine == pytest.approx(ref, rel=1e-6, abs=1e-9)


def test_arcs_flatten_within_tolerance():
    (p,) = sl.clip.arcs(0, 0, 10, 10, [(0.0, math.pi)], tolerance=0.1)
    mid = (p[1:] + p[:-1]) / 2
    sagitta = 10 - np.hypot(mid[:, 0], mid[:, 1])
    assert sagitta.max() <= 0.1 + 1e-12
    assert np.hypot(p[:, 0], p[:, 1]) == pytest.approx(10)


def test_curve_through_its_polyline():
    class Parabola:
        def flatten(self, tolerance):
            x = np.linspace(-5, 5, 101)
            return np.stack([x, x * x / 2], axis=1)

    pieces = sl.clip.curve(Parabola(), (-3, 0, 3, 2))
    assert len(pieces) == 1
    assert pieces[0][0] == pytest.approx((-2, 2)) and pieces[0][-1] == pytest.approx((2, 2))


def test_bad_curve_input():
    with pytest.raises(sl.ArgumentValueError, match="rx"):
        sl.clip.ellipse(0, 0, 0, 1, (0, 0, 1, 1))
    with pytest.raises(sl.ArgumentValueError, match="convex"):
        sl.clip.circle(0, 0, 1, [(0, 0), (4, 0), (2, 1), (4, 4), (0, 4)])
    with pytest.raises(sl.ArgumentValueError, match="tolerance"):
        sl.clip.arcs(0, 0, 1, 1, [(0, 1)], tolerance=0)
    with pytest.raises(sl.ArgumentValueError):
        sl.clip.circle(float("nan"), 0, 1, (0, 0, 1, 1))
