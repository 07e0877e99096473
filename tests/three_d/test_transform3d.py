"""3-D transformations (scanline.transform3d): matrices written out by hand from
Hearn & Baker, chapter 11; rotations about any axis against scipy's Rotation and
against Rodrigues' formula written here; invariants; bad input."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

import scanline as sl
from scanline.transform3d import (apply, axis_alignment, compose, inverse, reflection,
                                  rotation, rotation_steps, scaling, shear, translation)
from tests.reference import HYPOTHESIS

coord = st.floats(-50, 50, allow_nan=False, allow_infinity=False)
point = st.tuples(coord, coord, coord)
angle = st.floats(-7, 7, allow_nan=False, allow_infinity=False)


def close(a, b, tol=1e-9):
    np.testing.assert_allclose(a, b, rtol=0, atol=tol)


def rodrigues(theta, p1, p2, pts):
    """Rodrigues' rotation of ``pts`` by theta about the axis p1 -> p2 (right hand)."""
    k = np.subtract(p2, p1, dtype=float)
    k /= np.linalg.norm(k)
    v = np.asarray(pts, float) - p1
    c, s = math.cos(theta), math.sin(theta)
    return (v * c + np.cross(k, v) * s + np.outer(v @ k, k) * (1 - c)) + p1


def test_translation_and_scaling_by_hand():
    assert translation(1, -2, 3).tolist() == [[1, 0, 0, 1], [0, 1, 0, -2], [0, 0, 1, 3],
                                              [0, 0, 0, 1]]
    assert scaling(2, 3, 4).tolist() == [[2, 0, 0, 0], [0, 3, 0, 0], [0, 0, 4, 0], [0, 0, 0, 1]]
    # about (1, 1, 1): x' = 1 + (x - 1) * 2
    assert apply(scaling(2, fixed=(1, 1, 1)), [(3, 0, 1)]).tolist() == [[5.0, -1.0, 1.0]]
    assert apply(scaling(2, 3, 4, fixed=(1, 2, 3)), (1, 2, 3)).tolist() == [1.0, 2.0, 3.0]


def test_rotations_about_the_axes_by_hand():
    q = math.pi / 2
    # Rz: x -> y; Rx: y -> z; Ry: z -> x (counterclockwise looking toward the origin)
    close(apply(rotation(q, "z"), (1, 0, 0)), (0, 1, 0))
    close(apply(rotation(q, "x"), (0, 1, 0)), (0, 0, 1))
    close(apply(rotation(q, "y"), (0, 0, 1)), (1, 0, 0))
    t = 0.3
    c, s = math.cos(t), math.sin(t)
    close(rotation(t, "x"), [[1, 0, 0, 0], [0, c, -s, 0], [0, s, c, 0], [0, 0, 0, 1]])
    close(rotation(t, "y"), [[c, 0, s, 0], [0, 1, 0, 0], [-s, 0, c, 0], [0, 0, 0, 1]])
    close(rotation(t, "z"), [[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])


def test_rotation_about_a_parallel_axis_keeps_the_pivot():
    m = rotation(1.1, "y", pivot=(2, 5, -1))
    close(apply(m, (2, 5, -1)), (2, 5, -1))
    close(apply(m, (2, 0, -1)), (2, 0, -1))       # on the axis x = 2, z = -1


@given(angle, point, point)
@HYPOTHESIS
def test_rotation_about_any_axis_matches_rodrigues_and_scipy(theta, p1, p2):
    if np.linalg.norm(np.subtract(p2, p1)) < 1e-3:
        return
    m = rotation(theta, (p1, p2))
    pts = np.array([(1, 2, 3), (-4, 0.5, 2), p1, p2], float)
    close(apply(m, pts), rodrigues(theta, p1, p2, pts), 1e-8)
    k = np.subtract(p2, p1, dtype=float)
    r = Rotation.from_rotvec(theta * k / np.linalg.norm(k)).as_matrix()
    close(m[:3, :3], r, 1e-9)


def test_the_seven_steps_compose_to_the_rotation_and_align_the_axis():
    p1, p2 = (1, 2, 3), (4, -2, 5)
    steps = rotation_steps(0.7, (p1, p2))
    assert [s.name for s in steps] == ["T", "Rx(alpha)", "Ry(beta)", "Rz(theta)",
                                       "Ry(beta)^-1", "Rx(alpha)^-1", "T^-1"]
    close(compose(*(s.matrix for s in reversed(steps))), rotation(0.7, (p1, p2)))
    # after T, Rx(alpha), Ry(beta) the axis lies along +z with P1 at the origin
    a = axis_alignment((p1, p2))
    close(apply(a, p1), (0, 0, 0))
    d = math.dist(p1, p2)
    close(apply(a, p2), (0, 0, d))
    # Hearn & Baker: cos alpha = c / d, sin alpha = b / d, cos beta = d, sin beta = -a
    u = np.subtract(p2, p1) / d
    dd = math.hypot(u[1], u[2])
    close(steps[1].matrix[1:3, 1:3], [[u[2] / dd, -u[1] / dd], [u[1] / dd, u[2] / dd]])
    close(steps[2].matrix[[0, 0, 2, 2], [0, 2, 0, 2]], [dd, -u[0], u[0], dd])


def test_an_axis_along_x_skips_the_rotation_about_x():
    steps = rotation_steps(0.4, ((0, 0, 0), (2, 0, 0)))
    close(steps[1].matrix, np.eye(4))
    close(rotation(0.4, ((0, 0, 0), (2, 0, 0))), rotation(0.4, "x"))


def test_reflections_by_hand_and_involutions():
    assert apply(reflection("xy"), (1, 2, 3)).tolist() == [1, 2, -3]
    assert apply(reflection("yz"), (1, 2, 3)).tolist() == [-1, 2, 3]
    assert apply(reflection("zx"), (1, 2, 3)).tolist() == [1, -2, 3]
    m = reflection((1, 1, 1), (1, 1, 0))     # the plane x + y = 2
    close(apply(m, (0, 0, 5)), (2, 2, 5))
    close(m @ m, np.eye(4))
    assert np.linalg.det(m) == pytest.approx(-1)


def test_shears_by_hand():
    assert apply(shear("z", 2, 3), (1, 1, 1)).tolist() == [3, 4, 1]
    assert apply(shear("z", 2, 3, reference=1), (1, 1, 1)).tolist() == [1, 1, 1]
    assert apply(shear("x", 2, 3), (1, 0, 0)).tolist() == [1, 2, 3]
    assert apply(shear("y", 2, 3), (0, 1, 0)).tolist() == [2, 1, 3]
    assert np.linalg.det(shear("y", 5, -2)) == pytest.approx(1)


@given(point, angle, st.floats(0.2, 5), point)
@HYPOTHESIS
def test_inverse_undoes_composites(t, theta, s, p):
    m = compose(translation(*t), rotation(theta, "x"), scaling(s, 1 / s, 2), shear("z", .3, .2))
    close(apply(inverse(m), apply(m, p)), p, 1e-7)
    close(inverse(m) @ m, np.eye(4), 1e-9)


def test_composition_reads_right_to_left():
    m = compose(translation(1, 0, 0), rotation(math.pi / 2, "z"))   # rotate, then move
    close(apply(m, (1, 0, 0)), (1, 1, 0))


def test_apply_divides_by_h_for_a_perspective_matrix_and_keeps_homogeneous_points():
    p = np.array(sl.projection.perspective(z_prp=4, z_vp=0))
    # x_p = x (z_prp - z_vp) / (z_prp - z): (2, 2, -4) -> (1, 1, 0)
    close(apply(p, (2, 2, -4)), (1, 1, 0))
    h = apply(p, (2, 2, -4, 1))
    close(h, (2, 2, 0, 2))
    with pytest.raises(sl.ArgumentValueError, match="infinity"):
        apply(p, (1, 1, 4))          # in the plane of the center of projection
    assert apply(translation(1, 2, 3), []).shape == (0, 3)


@pytest.mark.parametrize("call, match", [
    (lambda: rotation(1, "w"), "axis"),
    (lambda: rotation(1, ((0, 0, 0), (0, 0, 0))), "differ"),
    (lambda: rotation(float("nan"), "x"), "finite"),
    (lambda: rotation(1, "x", pivot=(0, 0)), "3-vector"),
    (lambda: scaling(1, 2), "both sy and sz"),
    (lambda: reflection("xx"), "plane"),
    (lambda: reflection((0, 0, 0), (0, 0, 0)), "zero vector"),
    (lambda: inverse(scaling(0, 1, 1)), "singular"),
    (lambda: inverse(np.array(sl.projection.perspective(z_prp=1, z_vp=0))), "singular"),
    (lambda: compose(np.eye(3)), "4x4"),
    (lambda: apply(np.eye(4), [(1, 2)]), r"\(N, 3\) or \(N, 4\)"),
    (lambda: apply(np.eye(4), [(1, 2, float("inf"))]), "finite"),
    (lambda: apply(np.eye(4), "abc"), "real numbers"),
])
def test_bad_input_is_a_clear_error(call, match):
    with pytest.raises(sl.ScanlineError, match=match):
        call()
