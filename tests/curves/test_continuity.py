"""continuity(a, b): C0/C1/C2 and G0/G1/G2 of the join of two sections (notes, Q.5)."""

import numpy as np
import pytest

import scanline as sl

Join = sl.curves.Join
B = sl.curves.Bezier
A = B([(0, 0), (1, 1), (2, 1), (3, 0)])  # ends at (3, 0), P' = (3, -3), P'' = (0, -6)


def test_not_joined():
    assert sl.curves.continuity(A, B([(3, 1), (4, 0), (5, 0)])) == Join(-1, -1)
    assert str(Join(-1, -1)) == "not joined"


def test_c0_only_a_corner():
    assert sl.curves.continuity(A, B([(3, 0), (4, 1), (5, 0), (6, 0)])) == Join(0, 0)


def test_c1_and_c2_by_the_bezier_conditions():
    # C1: b1 = 2 a3 - a2; C2 as well: b2 = a1 - 4 a2 + 4 a3
    c1 = B([(3, 0), (4, -1), (5, -1), (6, 0)])
    assert sl.curves.continuity(A, c1) == Join(1, 1)
    c2 = B([(3, 0), (4, -1), (5, -3), (7, 0)])
    assert sl.curves.continuity(A, c2) == Join(2, 2)
    assert str(Join(2, 2)) == "C2 G2"


def test_g1_proportional_tangents():
    g1 = B([(3, 0), (5, -2), (6, -1), (7, 0)])  # tangent (6, -6): twice A's
    assert sl.curves.continuity(A, g1) == Join(0, 1)
    opposite = B([(3, 0), (2, 1), (0, 0)])  # same line, reversed direction: a cusp
    assert sl.curves.continuity(A, opposite) == Join(0, 0)


def test_g2_reparameterized_but_same_curvature():
    # the C2 continuation of A, reparameterized u -> u/2 on its first half: tangent
    # halves, curvature vector unchanged -> G2 but only C0
    c2 = B([(3, 0), (4, -1), (5, -3), (7, 0)])
    first_half, _ = c2.subdivide(0.5)
    assert sl.curves.continuity(A, first_half) == Join(0, 2)


def test_tolerance_and_other_curve_types():
    c1 = B([(3, 1e-7), (4, -1), (5, -1), (6, 0)])
    assert sl.curves.continuity(A, c1) == Join(-1, -1)
    assert sl.curves.continuity(A, c1, tol=1e-6) == Join(1, 1)
    # a cubic B-spline with knots [0 0 0 0 1 2 2 2 2] is C2 at u = 1; inserting 1 twice
    # (Boehm) makes its two sections Bezier curves: P0..P3 and P3..P6
    bs = sl.curves.BSpline(np.random.default_rng(0).normal(size=(5, 2)), 4)
    ins = bs.insert_knot(1.0, 2)
    assert ins.knots.tolist() == [0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2]
    a, b = B(ins.points[:4]), B(ins.points[3:])
    np.testing.assert_allclose(a.evaluate(1.0), bs.evaluate(1.0), atol=1e-12)
    assert sl.curves.continuity(a, b, tol=1e-8) == Join(2, 2)


def test_bad_arguments():
    with pytest.raises(TypeError, match="a must be"):
        sl.curves.continuity([(0, 0)], A)
    with pytest.raises(ValueError, match="dimension"):
        sl.curves.continuity(A, B([(3, 0, 0), (4, 0, 0)]))
    with pytest.raises(ValueError, match="tol"):
        sl.curves.continuity(A, A, tol=-1)
