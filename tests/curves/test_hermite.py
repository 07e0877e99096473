"""Hermite, cardinal, Catmull-Rom and Kochanek-Bartels splines; C1/C2 piecewise cubics."""

import numpy as np
import pytest
from scipy.interpolate import CubicHermiteSpline, CubicSpline

import scanline as sl


def close(a, b, scale):
    np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-12 * scale)


@pytest.mark.parametrize("dim", [2, 3])
def test_hermite_against_scipy(dim):
    rng = np.random.default_rng(dim)
    for m in (2, 3, 7, 20):
        P = rng.uniform(-100, 100, (m, dim))
        D = rng.uniform(-100, 100, (m, dim))
        h = sl.curves.Hermite(P, D)
        ref = CubicHermiteSpline(np.arange(m), P, D)
        u = np.concatenate([rng.uniform(0, m - 1, 300), np.arange(m)])
        close(h.evaluate(u), ref(u), 100)
        for k in (1, 2, 3):
            close(h.derivative(k).evaluate(u), ref.derivative(k)(u), 1e3)


def test_hermite_boundary_conditions_and_blending_functions():
    rng = np.random.default_rng(1)
    P, D = rng.normal(size=(2, 2)), rng.normal(size=(2, 2))
    h = sl.curves.Hermite(P, D)
    close(h.evaluate([0, 1]), P, 1)
    close(h.derivative().evaluate([0, 1]), D, 1)
    u = np.linspace(0, 1, 21)
    H = sl.curves.hermite_blending(u)
    close(h.evaluate(u), H @ np.vstack([P, D]), 10)


def test_hermite_sections_are_bezier_curves_with_thirds_of_the_tangents():
    P = np.array([(0, 0), (3, 3), (6, 0)], float)
    D = np.array([(3, 0), (0, -3), (3, 3)], float)
    s = sl.curves.Hermite(P, D).sections
    close(s[0].points, [P[0], P[0] + D[0] / 3, P[1] - D[1] / 3, P[1]], 1)
    close(s[1].points, [P[1], P[1] + D[1] / 3, P[2] - D[2] / 3, P[2]], 1)


@pytest.mark.parametrize("tension", [0.0, 0.5, -0.5, 1.0])
def test_cardinal_spline_matrix_form(tension):
    rng = np.random.default_rng(2)
    P = rng.normal(size=(7, 2))
    c = sl.curves.CardinalSpline(P, tension=tension)
    assert c.domain == (0.0, 4.0)  # sections P1-P2 ... P4-P5
    M = sl.curves.cardinal_matrix(tension)
    u = np.linspace(0, 1, 11)
    T = np.stack([u**3, u**2, u, np.ones_like(u)], -1)
    for k in range(1, 5):
        close(c.evaluate(k - 1 + u), T @ M @ P[k - 1:k + 3], 10)


def test_catmull_rom_interpolates_with_central_difference_tangents():
    P = np.array([(0, 0), (1, 2), (3, 3), (4, 1), (6, 0)], float)
    c = sl.curves.CatmullRom(P)
    close(c.evaluate([0, 1, 2]), P[1:4], 1)
    close(c.derivative().evaluate([0, 1, 2]), (P[2:] - P[:-2]) / 2, 1)
    cl = sl.curves.CatmullRom(P, closed=True)
    assert cl.domain == (0.0, 5.0)
    close(cl.evaluate(np.arange(6.0)), np.vstack([P, P[:1]]), 1)
    d = cl.derivative()
    close(d.evaluate(0.0), d.evaluate(5.0), 1)
    close(d.evaluate(0.0), (P[1] - P[-1]) / 2, 1)


def test_kochanek_bartels_reduces_to_catmull_rom_and_makes_corners():
    rng = np.random.default_rng(3)
    P = rng.normal(size=(6, 2))
    u = np.linspace(0, 3, 31)
    close(sl.curves.KochanekBartels(P).evaluate(u), sl.curves.CatmullRom(P).evaluate(u), 1)
    kb = sl.curves.KochanekBartels(P, tension=0.3)
    close(kb.evaluate(u), sl.curves.CardinalSpline(P, tension=0.3).evaluate(u), 1)
    # continuity c = -1: tangents are the chords on each side: a corner, G0 only
    kb = sl.curves.KochanekBartels(P, continuity=-1.0)
    s = kb.sections
    assert sl.curves.continuity(s[0], s[1]) == sl.curves.Join(0, 0)
    close(s[0].derivative().evaluate(1.0), P[2] - P[1], 1)
    close(s[1].derivative().evaluate(0.0), P[3] - P[2], 1)
    # bias b = 1: the tangent is (P_k - P_k-1), the chord before
    kb = sl.curves.KochanekBartels(P, bias=1.0)
    close(kb.derivative().evaluate([0.0, 1.0]), P[1:3] - P[0:2], 1)
    # per-point parameters
    t = np.linspace(0, 0.5, 6)
    kb = sl.curves.KochanekBartels(P, tension=t)
    close(kb.derivative().evaluate(1.0), (1 - t[2]) * (P[3] - P[1]) / 2, 1)


def test_piecewise_bezier_c1_and_c2():
    rng = np.random.default_rng(4)
    P = rng.uniform(-10, 10, (8, 2))
    c1 = sl.curves.piecewise_bezier(P, continuity="C1")
    c2 = sl.curves.piecewise_bezier(P, continuity="C2")
    close(c1.evaluate(np.arange(8.0)), P, 10)
    close(c2.evaluate(np.arange(8.0)), P, 10)
    for a, b in zip(c1.sections, c1.sections[1:]):
        assert sl.curves.continuity(a, b).C >= 1
    for a, b in zip(c2.sections, c2.sections[1:]):
        assert sl.curves.continuity(a, b, tol=1e-9).C == 2
    u = np.linspace(0, 7, 301)
    close(c2.evaluate(u), CubicSpline(np.arange(8), P, bc_type="natural")(u), 10)
