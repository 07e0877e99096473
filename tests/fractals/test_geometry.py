"""Self-similar curves, box counting, L-systems, the turtle, Hilbert's curve and
Barnsley's fern, against closed forms: the Koch curve's dimension log 4 / log 3, a
filled square's 2 and a line's 1; segment counts and lengths; the L-system lengths
by recurrence; Hilbert's curve visiting each cell once; the fern inside its known
bounding box; the limits named."""

import math

import numpy as np
import pytest

from scanline.errors import ArgumentValueError, MemoryBudgetError
from scanline.fractals import (LSystem, box_counts, dimension, dragon, example, fern, hilbert,
                               ifs, koch, plant, self_similar, turtle)


def test_koch_dimension_is_log4_over_log3():
    assert abs(dimension(koch(8)) - math.log(4) / math.log(3)) < 0.05


def test_box_counting_a_filled_square_a_line_and_a_point_set():
    square = np.ones((256, 256), bool)
    assert dimension(square) == pytest.approx(2.0, abs=1e-9)
    line = np.eye(256, dtype=bool)
    assert dimension(line) == pytest.approx(1.0, abs=1e-9)
    t = np.linspace(0, 1, 200_001)
    assert dimension(np.stack([t, 0.5 * t], axis=1)) == pytest.approx(1.0, abs=0.03)
    sizes, counts = box_counts(square, [1, 2, 4])
    assert counts.tolist() == [65536, 16384, 4096]


@pytest.mark.parametrize("depth", [0, 1, 2, 5])
def test_koch_curve_segments_and_length(depth):
    p = koch(depth)
    assert len(p) == 4 ** depth + 1
    np.testing.assert_allclose(p[[0, -1]], [(0, 0), (1, 0)], atol=1e-12)
    lengths = np.hypot(*np.diff(p, axis=0).T)
    np.testing.assert_allclose(lengths, 3.0 ** -depth, rtol=1e-9)
    snowflake = koch(depth, closed=True)
    np.testing.assert_allclose(snowflake[0], snowflake[-1], atol=1e-12)
    # the snowflake grows outward: its area only increases, toward 8/5 of the triangle's
    x, y = snowflake.T
    area = 0.5 * abs(np.dot(x[:-1], y[1:]) - np.dot(x[1:], y[:-1]))
    triangle = math.sqrt(3) / 4
    expected = triangle * (1 + 3 / 9 * sum((4 / 9) ** k for k in range(depth)))
    assert area == pytest.approx(expected, rel=1e-9)


def test_dragon_turns_a_right_angle_at_every_vertex_and_never_retraces():
    p = dragon(10)
    d = np.diff(p, axis=0)
    assert len(d) == 2 ** 10
    np.testing.assert_allclose(np.hypot(*d.T), 2 ** -5, rtol=1e-9)
    np.testing.assert_allclose(np.einsum("ij,ij->i", d[:-1], d[1:]), 0, atol=1e-12)
    edges = {tuple(sorted((tuple(a), tuple(b)))) for a, b in
             zip(np.round(p[:-1] * 2 ** 5).astype(int).tolist(),
                 np.round(p[1:] * 2 ** 5).astype(int).tolist())}
    assert len(edges) == 2 ** 10


@pytest.mark.parametrize("order", [1, 2, 3, 6])
def test_hilbert_curve_visits_every_cell_once_by_unit_steps(order):
    p = hilbert(order)
    side = 2 ** order
    cells = np.floor(p).astype(int)
    assert len(p) == side * side
    assert len({tuple(c) for c in cells.tolist()}) == side * side
    assert cells.min() == 0 and cells.max() == side - 1
    np.testing.assert_allclose(np.abs(np.diff(p, axis=0)).sum(axis=1), 1.0, atol=0)


def test_lsystem_lengths_follow_the_recurrence():
    # Koch's grammar F -> F+F--F+F: F(n) = 4^n, signs S(n+1) = S(n) + 4 F(n)
    k = example("koch")
    for n in range(7):
        closed_form = 4 ** n + 4 * (4 ** n - 1) // 3
        assert k.length(n) == closed_form == len(k.string(n))
    algae = LSystem("A", {"A": "AB", "B": "A"})
    fib = [1, 2]
    while len(fib) < 40:
        fib.append(fib[-1] + fib[-2])
    assert [algae.length(n) for n in range(40)] == fib
    h = example("hilbert")
    for n in range(6):
        assert h.length(n) == len(h.string(n))
        assert h.string(n).count("F") == 4 ** n - 1


def test_turtle_branches_and_moves():
    lines = turtle("F[+F]F", "90deg")
    np.testing.assert_allclose(lines[0], [(0, 0), (0, 1), (-1, 1)], atol=1e-15)
    np.testing.assert_allclose(lines[1], [(0, 1), (0, 2)], atol=1e-15)
    lines = turtle("FfF|F", math.pi / 2, step=2, start=(1, 1), heading=0.0)
    np.testing.assert_allclose(lines[0], [(1, 1), (3, 1)])
    np.testing.assert_allclose(lines[1], [(5, 1), (7, 1), (5, 1)])
    odd = turtle("F+F", "25deg")                          # no exact table: computed
    np.testing.assert_allclose(odd[0][-1], [-math.sin(math.radians(25)),
                                            1 + math.cos(math.radians(25))])
    branches = plant(3)
    string = example("plant").string(3)
    # every F is one unit segment of one polyline
    assert sum(len(b) - 1 for b in branches) == string.count("F")
    for b in branches:
        np.testing.assert_allclose(np.hypot(*np.diff(b, axis=0).T), 1.0, rtol=1e-12)


def test_fern_points_stay_in_the_known_bounding_box():
    # the attractor lies in -2.1820 < x < 2.6558, 0 <= y < 9.9983 (Barnsley's fern)
    p = fern(100_000, seed=3)
    assert (p[:, 0] > -2.1820).all() and (p[:, 0] < 2.6558).all()
    assert (p[:, 1] >= 0).all() and (p[:, 1] < 9.9983).all()
    np.testing.assert_array_equal(p, fern(100_000, seed=3))
    assert not np.array_equal(p, fern(100_000, seed=4))


def test_a_one_map_ifs_converges_to_the_maps_fixed_point():
    # x' = x/2 + 1, y' = y/2 - 1: the fixed point (2, -2)
    p = ifs([[0.5, 0, 0, 0.5, 1, -1]], [1.0], 10, seed=0, start=(50.0, 50.0))
    np.testing.assert_allclose(p[-1], (2, -2), atol=1e-6)


@pytest.mark.parametrize("call, error, match", [
    (lambda: koch(30), ArgumentValueError, "depth: .* more than the limit of 67,108,864"),
    (lambda: dragon(40), ArgumentValueError, "depth: .*limits.MAX_POINTS"),
    (lambda: hilbert(20), ArgumentValueError, "order: .* limit"),
    (lambda: example("plant").string(40), ArgumentValueError, "n: .* limit"),
    (lambda: fern(10 ** 12), ArgumentValueError, "n: .* limit"),
    (lambda: self_similar([(0, 0), (1, 0)], [(0, 0), (1, 1)], 2), ArgumentValueError,
     "generator must run from"),
    (lambda: self_similar([(0, 0), (1, 0)], [(0, 0), (1, 0)], 2, sides=[2]),
     ArgumentValueError, "sides"),
    (lambda: turtle("F]F", 1.0), ArgumentValueError, "no '\\[' open"),
    (lambda: LSystem("F", {"FF": "F"}), ArgumentValueError, "one character"),
    (lambda: ifs([[1, 0, 0, 1, 0, 0]], [0.5], 10), ArgumentValueError, "summing to 1"),
    (lambda: ifs([[np.nan, 0, 0, 1, 0, 0]], [1.0], 10), ArgumentValueError, "maps must be finite"),
    (lambda: dimension(np.zeros((8, 8), bool)), ArgumentValueError, "no nonzero pixel"),
    (lambda: dimension([(1, 1), (1, 1)]), ArgumentValueError, "the same point"),
])
def test_bad_input_and_limits_are_named(call, error, match):
    with pytest.raises(error, match=match):
        call()


def test_the_memory_budget_refuses_before_allocating(monkeypatch):
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "1M")
    with pytest.raises(MemoryBudgetError, match="depth"):
        koch(9)
