"""Bezier flattening: Wang's bound keeps every flattened polyline within the
tolerance of its curve (checked by dense sampling, independently of the bound)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanline.errors import ArgumentValueError
from scanline.geometry import flatten


def bezier(controls, u):
    n = len(controls) - 1
    u = np.asarray(u)[:, None]
    return sum(math.comb(n, k) * u ** k * (1 - u) ** (n - k) * controls[k]
               for k in range(n + 1))


def distance_to_polyline(points, poly):
    a, b = poly[:-1], poly[1:]
    d = b - a
    worst = 0.0
    for p in points:
        t = np.clip(((p - a) * d).sum(1) / np.maximum((d * d).sum(1), 1e-300), 0, 1)
        worst = max(worst, np.sqrt((((a + t[:, None] * d) - p) ** 2).sum(1)).min())
    return worst


coordinate = st.floats(-500, 500, allow_nan=False)
point = st.tuples(coordinate, coordinate)


@settings(max_examples=60, deadline=None)
@given(st.lists(point, min_size=3, max_size=4), st.sampled_from([0.05, 0.25, 1.0]))
def test_polyline_stays_within_tolerance(ctrl, tol):
    c = np.array(ctrl, float)
    fn = flatten.quadratic if len(c) == 3 else flatten.cubic
    pts, counts = fn(c, tol)
    poly = np.vstack([c[:1], pts])
    assert counts.sum() == len(pts)
    assert np.allclose(poly[-1], c[-1])
    assert distance_to_polyline(bezier(c, np.linspace(0, 1, 801)), poly) <= tol * (1 + 1e-9) + 1e-9


def test_steps_follow_wangs_formula():
    # quadratic: m = ceil(sqrt(L / (4 tol))), L = |P0 - 2 P1 + P2|
    c = np.array([[[0, 0], [50, 80], [100, 0]]], float)
    L = math.hypot(0 - 100 + 100, 0 - 160 + 0)
    assert flatten.steps(c, 0.25)[0] == math.ceil(math.sqrt(L / (4 * 0.25)))
    # cubic: m = ceil(sqrt(3 L / (4 tol)))
    c = np.array([[[0, 0], [0, 100], [100, 100], [100, 0]]], float)
    L = max(math.hypot(0 - 0 + 100, 0 - 200 + 100), math.hypot(0 - 200 + 100, 100 - 200 + 0))
    assert flatten.steps(c, 0.1)[0] == math.ceil(math.sqrt(3 * L / (4 * 0.1)))


def test_straight_and_degenerate_segments_take_one_step():
    pts, counts = flatten.cubic([[[0, 0], [1, 1], [2, 2], [3, 3]], [[5, 5]] * 4], 0.01)
    assert counts.tolist() == [1, 1]
    assert pts.tolist() == [[3, 3], [5, 5]]


def test_a_quarter_circle_gets_more_steps_at_a_finer_tolerance():
    k = 0.5522847498
    c = np.array([[1, 0], [1, k], [k, 1], [0, 1]], float) * 1000
    steps = [int(flatten.cubic(c, t)[1][0]) for t in (4, 1, 0.25)]
    assert steps[0] < steps[1] < steps[2]
    assert steps[2] == pytest.approx(2 * steps[1], abs=1)   # m ~ 1 / sqrt(tol)


@pytest.mark.parametrize("tol", [0, -1, float("nan"), float("inf")])
def test_bad_tolerance(tol):
    with pytest.raises(ArgumentValueError, match="tolerance"):
        flatten.quadratic([[0, 0], [1, 1], [2, 0]], tol)


@pytest.mark.parametrize("controls", [[[0, 0], [1, 1]], [[0, 0, 0]] * 3,
                                      [[0, 0], [1, float("nan")], [2, 0]]])
def test_bad_controls(controls):
    with pytest.raises(ArgumentValueError, match="controls"):
        flatten.quadratic(controls, 0.25)
