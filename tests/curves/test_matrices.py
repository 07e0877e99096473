"""The characteristic matrices, derived, checked against the blending functions written
out by hand (errata E40, E41) and against the notes' boundary conditions."""

import numpy as np
import pytest

import scanline as sl
from scanline.curves import matrices

U = np.linspace(0.0, 1.0, 41)


def powers(u):
    return np.stack([u**3, u**2, u, np.ones_like(u)], axis=-1)


def test_bezier_matrix_is_pinned_and_not_the_notes_matrix():
    right = np.array([[-1, 3, -3, 1], [3, -6, 3, 0], [-3, 3, 0, 0], [1, 0, 0, 0]])
    notes = np.array([[1, 0, -3, 1], [3, -6, 3, 0], [-3, 3, 0, 0], [1, 0, 0, 0]])
    assert np.array_equal(sl.curves.bezier_matrix(), right)
    assert not np.array_equal(sl.curves.bezier_matrix(), notes)


def test_bezier_matrix_times_powers_is_the_bernstein_polynomials():
    by_hand = np.stack([(1 - U) ** 3, 3 * U * (1 - U) ** 2, 3 * U**2 * (1 - U), U**3], axis=-1)
    np.testing.assert_allclose(powers(U) @ sl.curves.bezier_matrix(), by_hand, atol=1e-14)
    # the notes' printed matrix does not give them
    notes = np.array([[1, 0, -3, 1], [3, -6, 3, 0], [-3, 3, 0, 0], [1, 0, 0, 0]])
    assert np.abs(powers(U) @ notes - by_hand).max() > 0.5


@pytest.mark.parametrize("degree", [1, 2, 4, 5, 7])
def test_bezier_matrix_any_degree(degree):
    p = U[:, None] ** np.arange(degree, -1, -1)
    np.testing.assert_allclose(p @ sl.curves.bezier_matrix(degree),
                               sl.curves.bernstein(degree, U), atol=1e-12)


def test_bspline_matrix_is_pinned_and_gives_the_uniform_cubic_blending_functions():
    right = np.array([[-1, 3, -3, 1], [3, -6, 3, 0], [-3, 0, 3, 0], [1, 4, 1, 0]]) / 6
    np.testing.assert_array_equal(sl.curves.bspline_matrix(), right)
    # the uniform cubic B-spline basis pieces, written out (Hearn & Baker 10-9)
    by_hand = np.stack([(1 - U) ** 3 / 6, (3 * U**3 - 6 * U**2 + 4) / 6,
                        (-3 * U**3 + 3 * U**2 + 3 * U + 1) / 6, U**3 / 6], axis=-1)
    np.testing.assert_allclose(powers(U) @ right, by_hand, atol=1e-14)
    # ... and Cox-de Boor on the integer knots 0..7 over the span [3, 4]
    cox = sl.curves.basis(np.arange(8.0), 4, U + 3)
    np.testing.assert_allclose(cox, by_hand, atol=1e-14)
    notes = np.array([[1, 0, -3, 1], [3, -6, 3, 0], [-3, 3, 0, 0], [1, 0, 0, 0]]) / 6
    assert np.abs(powers(U) @ notes - by_hand).max() > 0.1


@pytest.mark.parametrize("order", [2, 3, 5])
def test_bspline_matrix_other_orders_match_cox_de_boor(order):
    p = U[:, None] ** np.arange(order - 1, -1, -1)
    cox = sl.curves.basis(np.arange(2.0 * order), order, U + order - 1)
    np.testing.assert_allclose(p @ sl.curves.bspline_matrix(order), cox, atol=1e-13)


def test_periodic_cubic_boundary_conditions_of_the_notes():
    rng = np.random.default_rng(1)
    P = rng.normal(size=(4, 2))
    M = sl.curves.bspline_matrix()
    at = lambda row: np.array(row, float) @ M @ P  # noqa: E731
    np.testing.assert_allclose(at([0, 0, 0, 1]), (P[0] + 4 * P[1] + P[2]) / 6, atol=1e-14)
    np.testing.assert_allclose(at([1, 1, 1, 1]), (P[1] + 4 * P[2] + P[3]) / 6, atol=1e-14)
    np.testing.assert_allclose(at([0, 0, 1, 0]), (P[2] - P[0]) / 2, atol=1e-14)
    np.testing.assert_allclose(at([3, 2, 1, 0]), (P[3] - P[1]) / 2, atol=1e-14)


def test_hermite_matrix_inverts_the_constraints_and_gives_H0_to_H3():
    MH = sl.curves.hermite_matrix()
    np.testing.assert_array_equal(
        MH, [[2, -2, 1, 1], [-3, 3, -2, -1], [0, 0, 1, 0], [1, 0, 0, 0]])
    np.testing.assert_array_equal(np.array(matrices.HERMITE_CONSTRAINTS) @ MH, np.eye(4))
    by_hand = np.stack([2 * U**3 - 3 * U**2 + 1, -2 * U**3 + 3 * U**2,
                        U**3 - 2 * U**2 + U, U**3 - U**2], axis=-1)
    np.testing.assert_allclose(powers(U) @ MH, by_hand, atol=1e-14)
    np.testing.assert_allclose(sl.curves.hermite_blending(U), by_hand, atol=1e-14)


def test_cardinal_matrix_catmull_rom_is_the_textbook_matrix():
    np.testing.assert_allclose(
        2 * sl.curves.cardinal_matrix(0.0),
        [[-1, 3, -3, 1], [2, -5, 4, -1], [-1, 0, 1, 0], [0, 2, 0, 0]], atol=1e-15)
