"""Motion paths: arc-length parameterization checked against dense sampling."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.animation import MotionPath


def dense_length(curve, n=200_001):
    lo, hi = curve.domain
    pts = curve.evaluate(np.linspace(lo, hi, n))
    seg = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    return np.concatenate([[0.0], np.cumsum(seg)]), pts


CURVES = {
    "bezier": sl.curves.Bezier([(0, 0), (0, 100), (100, 100), (100, 0)]),
    "bunched bezier": sl.curves.Bezier([(0, 0), (1, 1), (2, 0), (200, 50)]),
    "bspline": sl.curves.BSpline([(0, 0), (40, 80), (90, -30), (150, 60), (200, 0)], order=4),
    "catmull-rom": sl.curves.CatmullRom([(0, 0), (10, 30), (50, 20), (60, 80), (100, 90)]),
    "nurbs circle": sl.curves.nurbs_circle((0, 0), 10.0),
    "space bezier": sl.curves.Bezier([(0, 0, 0), (10, 0, 30), (20, 40, 0), (0, 50, 10)]),
}


@pytest.mark.parametrize("name", sorted(CURVES))
def test_equal_steps_cover_equal_distances(name):
    curve = CURVES[name]
    path = MotionPath(curve)
    cumulative, pts = dense_length(curve)
    assert path.length == pytest.approx(cumulative[-1], rel=1e-8)
    s = np.linspace(0, 1, 41)[:-1]                # (a closed curve ends where it starts)
    points = path.point(s)
    # where the dense polyline says each point lies along the curve
    nearest = np.array([np.argmin(np.linalg.norm(pts - p, axis=1)) for p in points])
    along = cumulative[nearest] / cumulative[-1]
    np.testing.assert_allclose(along, s, atol=2e-5)
    np.testing.assert_allclose(path.distance(s), s * path.length, rtol=1e-12)


def test_circle_speed_is_uniform():
    path = MotionPath(sl.curves.nurbs_circle((5, -2), 3.0))
    assert path.length == pytest.approx(2 * math.pi * 3, rel=1e-10)
    p = path.point(np.linspace(0, 1, 9)[:-1])
    chords = np.linalg.norm(np.diff(np.vstack([p, p[:1]]), axis=0), axis=1)
    np.testing.assert_allclose(chords, 2 * 3 * math.sin(math.pi / 8), rtol=1e-8)


def test_curve_parameter_mode_differs():
    curve = CURVES["bunched bezier"]
    by_u = MotionPath(curve, arc_length=False)
    np.testing.assert_allclose(by_u.point(0.5), curve.evaluate(0.5))
    assert not np.allclose(MotionPath(curve).point(0.5), curve.evaluate(0.5), atol=1.0)


def test_polyline_exact_and_tangent():
    path = MotionPath([(0, 0), (30, 0), (30, 40)])
    assert path.length == 70.0
    np.testing.assert_allclose(path.point([0, 3 / 7, 0.5, 1]), [(0, 0), (30, 0), (30, 5), (30, 40)])
    np.testing.assert_allclose(path.tangent(0.2), (1, 0))
    assert path.heading(0.9) == pytest.approx(math.pi / 2)


def test_tangent_and_transform_face_along_the_path():
    path = MotionPath(sl.curves.nurbs_circle((0, 0), 10.0))
    s = np.linspace(0, 0.99, 12)
    t = path.tangent(s)
    radial = path.point(s)
    np.testing.assert_allclose((t * radial).sum(axis=1), 0, atol=1e-8)     # perpendicular
    np.testing.assert_allclose(np.linalg.norm(t, axis=1), 1)
    m = path.transform(0.25)                      # a quarter turn: at (0, 10) facing -x
    np.testing.assert_allclose(sl.transform.apply(m, [(0, 0), (1, 0)]), [(0, 10), (-1, 10)],
                               atol=1e-8)


def test_stalled_derivative_still_has_a_direction():
    # control points doubled at the start: P'(0) = 0, the direction comes from nearby
    path = MotionPath(sl.curves.Bezier([(0, 0), (0, 0), (10, 0), (10, 10)]))
    np.testing.assert_allclose(path.tangent(0.0), (1, 0), atol=1e-5)


def test_eased_trip():
    path = MotionPath([(0, 0), (100, 0)])
    assert path.at(0.5, 0, 1, "ease-in-quad").tolist() == [25.0, 0.0]
    assert path.at(-1, 0, 1).tolist() == [0.0, 0.0] and path.at(9, 0, 1).tolist() == [100.0, 0.0]
    assert path.at([0.0, 2.0, 4.0], start=0, end=4).tolist() == [[0, 0], [50, 0], [100, 0]]


@pytest.mark.parametrize("call,words", [
    (lambda: MotionPath([(1, 1), (1, 1), (1, 1)]), "length 0.0"),
    (lambda: MotionPath(sl.curves.Bezier([(2, 2), (2, 2)])), "positive, finite length"),
    (lambda: MotionPath([(0, 0)]), r"shape \(N >= 2, dim\)"),
    (lambda: MotionPath([(0, 0), (float("nan"), 1)]), "finite points"),
    (lambda: MotionPath("circle"), "curve must be"),
    (lambda: MotionPath([(0, 0), (1, 0)]).point(1.5), "s must lie in"),
    (lambda: MotionPath([(0, 0), (1, 0)]).at(0.5, 1, 1), "start must come before end"),
    (lambda: MotionPath(CURVES["space bezier"]).heading(0.5), "2-D paths"),
])
def test_bad_input(call, words):
    with pytest.raises(sl.ScanlineError, match=words):
        call()
