"""Quaternions (Hearn & Baker 11-2; Shoemake 1985) against scipy's Rotation and Slerp
on random inputs: conversions from and to matrices, axis-angle and Euler angles (all
sequences, extrinsic and intrinsic), products, rotation of vectors, slerp; squad's
smoothness at the keys; q and -q as one rotation; bad input named."""

import math

import numpy as np
import pytest

from scanline.errors import ArgumentTypeError, ArgumentValueError
from scanline.transform3d import Quaternion, slerp, squad, squad_controls

scipy_rotation = pytest.importorskip("scipy.spatial.transform")
Rotation, Slerp = scipy_rotation.Rotation, scipy_rotation.Slerp

SEEDS = range(40)


def random_rotations(seed, n=1):
    return Rotation.random(n, random_state=seed)


def quaternion_of(r):
    """scipy's rotation as a Quaternion, through scipy's (x, y, z, w) components."""
    x, y, z, w = r.as_quat()
    return Quaternion(w, x, y, z)


@pytest.mark.parametrize("seed", SEEDS)
def test_matrices_agree_with_scipy_both_ways(seed):
    r = random_rotations(seed)[0]
    q = Quaternion.from_matrix(r.as_matrix())
    np.testing.assert_allclose(q.matrix3(), r.as_matrix(), atol=1e-12)
    assert q.w >= 0
    expected = r.as_quat()               # the same rotation: equal up to the sign
    np.testing.assert_allclose(abs(q.xyzw @ expected), 1.0, atol=1e-12)
    np.testing.assert_allclose(quaternion_of(r).matrix3(), r.as_matrix(), atol=1e-12)
    four = Quaternion.from_matrix(np.block([[r.as_matrix(), np.zeros((3, 1))],
                                            [np.zeros((1, 3)), np.ones((1, 1))]]))
    np.testing.assert_allclose(four.matrix(), np.block(
        [[r.as_matrix(), np.zeros((3, 1))], [np.zeros((1, 3)), np.ones((1, 1))]]), atol=1e-12)


@pytest.mark.parametrize("axis", [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (1, -2, 3)])
@pytest.mark.parametrize("angle", [math.pi, math.pi - 1e-9, 1e-12, 0.0, 2.5])
def test_shepperd_is_exact_near_a_half_turn_and_the_identity(axis, angle):
    """Each branch of Shepperd's method (largest of w, x, y, z) against scipy."""
    u = np.array(axis, float) / np.linalg.norm(axis)
    r = Rotation.from_rotvec(u * angle)
    q = Quaternion.from_matrix(r.as_matrix())
    np.testing.assert_allclose(q.matrix3(), r.as_matrix(), atol=1e-12)
    np.testing.assert_allclose(abs(q.xyzw @ r.as_quat()), 1.0, atol=1e-9)


@pytest.mark.parametrize("seed", SEEDS)
def test_axis_angle_agrees_with_scipy_rotvec(seed):
    rng = np.random.default_rng(seed)
    axis = rng.normal(size=3) * 10 ** rng.uniform(-3, 3)
    angle = rng.uniform(-2 * math.pi, 2 * math.pi)
    q = Quaternion.from_axis_angle(axis, angle)
    r = Rotation.from_rotvec(axis / np.linalg.norm(axis) * angle)
    np.testing.assert_allclose(q.matrix3(), r.as_matrix(), atol=1e-12)
    assert q.angle == pytest.approx(r.magnitude(), abs=1e-9)
    np.testing.assert_allclose(q.angle * q.axis, r.as_rotvec(), atol=1e-9)


SEQUENCES = ["xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx", "yxy", "yzy", "zxz",
             "zyz"]


@pytest.mark.parametrize("seq", SEQUENCES + [s.upper() for s in SEQUENCES] + ["x", "YX"])
def test_euler_angles_agree_with_scipy(seq):
    rng = np.random.default_rng(len(seq) * 1000 + sum(map(ord, seq)))
    for _ in range(10):
        angles = rng.uniform(-math.pi, math.pi, len(seq))
        q = Quaternion.from_euler(seq, angles.tolist())
        np.testing.assert_allclose(q.matrix3(), Rotation.from_euler(seq, angles).as_matrix(),
                                   atol=1e-12)


@pytest.mark.parametrize("seed", SEEDS)
def test_products_inverses_and_rotated_vectors_agree_with_scipy(seed):
    r1, r2 = random_rotations(seed, 2)
    rng = np.random.default_rng(seed)
    # any nonzero multiple stands for the same rotation
    q1 = Quaternion(*(quaternion_of(r1).wxyz * rng.uniform(0.01, 100)))
    q2 = quaternion_of(r2)
    np.testing.assert_allclose((q1 * q2).matrix3(), (r1 * r2).as_matrix(), atol=1e-12)
    np.testing.assert_allclose(q1.inverse().matrix3(), r1.inv().as_matrix(), atol=1e-12)
    identity = q1 * q1.inverse()
    np.testing.assert_allclose(identity.wxyz, [1, 0, 0, 0], atol=1e-12)
    np.testing.assert_allclose(q1.conjugate().normalize().wxyz, q1.inverse().normalize().wxyz,
                               atol=1e-12)
    assert q1.normalize().norm == pytest.approx(1.0, abs=1e-15)
    vectors = rng.normal(size=(7, 3))
    np.testing.assert_allclose(q1.rotate(vectors), r1.apply(vectors), atol=1e-12)
    np.testing.assert_allclose(q1.rotate(vectors[0]), r1.apply(vectors[0]), atol=1e-12)


def test_the_product_is_hamiltons():
    """i j = k, j k = i, k i = j, i² = -1 (Hamilton's rules)."""
    i, j, k = Quaternion(0, 1, 0, 0), Quaternion(0, 0, 1, 0), Quaternion(0, 0, 0, 1)
    assert i * j == k and j * k == i and k * i == j
    assert j * i == -k
    assert i * i == Quaternion(-1, 0, 0, 0)


@pytest.mark.parametrize("seed", SEEDS)
def test_q_and_minus_q_are_the_same_rotation(seed):
    q = quaternion_of(random_rotations(seed)[0])
    np.testing.assert_allclose((-q).matrix(), q.matrix(), atol=1e-15)
    p = quaternion_of(random_rotations(seed + 1000)[0])
    # slerp toward -p is slerp toward p: the short way both times
    np.testing.assert_allclose(slerp(q, -p, 0.3).matrix3(), slerp(q, p, 0.3).matrix3(),
                               atol=1e-12)


@pytest.mark.parametrize("seed", SEEDS)
def test_slerp_agrees_with_scipy_slerp(seed):
    keys = random_rotations(seed, 2)
    scipy_slerp = Slerp([0.0, 1.0], keys)
    q1, q2 = quaternion_of(keys[0]), quaternion_of(keys[1])
    for t in np.linspace(0, 1, 9):
        np.testing.assert_allclose(q1.slerp(q2, t).matrix3(),
                                   scipy_slerp([t]).as_matrix()[0], atol=1e-10)


def test_slerp_turns_at_a_constant_rate_the_short_way():
    a = Quaternion.from_axis_angle((0, 0, 1), 0.0)
    b = Quaternion.from_axis_angle((0, 0, 1), math.radians(300))   # = -60 degrees
    for t in (0.25, 0.5, 0.75):
        r = Rotation.from_matrix(slerp(a, b, t).matrix3())
        assert r.as_rotvec()[2] == pytest.approx(math.radians(-60) * t, abs=1e-12)
    same = slerp(a, Quaternion(1, 0, 0, 1e-12), 0.5)       # nearly equal keys: no 0/0
    assert np.isfinite(same.wxyz).all() and same.norm == pytest.approx(1.0)


def angular_velocity(f, t, h):
    """(log(f(t)⁻¹ f(t + h)) ) / h as a body-frame angular velocity, through scipy."""
    a = Rotation.from_matrix(f(t).matrix3())
    b = Rotation.from_matrix(f(t + h).matrix3())
    return (a.inv() * b).as_rotvec() / h


def test_squad_runs_through_the_keys_with_a_continuous_tangent():
    keys = [quaternion_of(r) for r in random_rotations(7, 5)]
    aligned, controls = squad_controls(keys)

    def curve(u):
        i = min(int(u), len(aligned) - 2)
        return squad(aligned[i], aligned[i + 1], controls[i], controls[i + 1], u - i)

    for i, key in enumerate(keys):
        np.testing.assert_allclose(curve(float(i)).matrix3(), key.matrix3(), atol=1e-12)
    h = 1e-6
    for i in (1, 2, 3):
        before = angular_velocity(curve, i - h, h)
        after = angular_velocity(curve, i, h)
        np.testing.assert_allclose(before, after, atol=1e-4 * max(1, np.abs(after).max()))
    # plain slerp between the same keys has a corner there: the test can fail
    def piecewise(u):
        k = min(int(u), len(aligned) - 2)
        return slerp(aligned[k], aligned[k + 1], u - k)
    assert np.abs(angular_velocity(piecewise, 2 - h, h)
                  - angular_velocity(piecewise, 2, h)).max() > 1e-2


def test_log_and_exp_are_inverse():
    q = Quaternion.from_axis_angle((1, 2, 2), 1.2)
    np.testing.assert_allclose(q.log(), [0, 0.2, 0.4, 0.4], atol=1e-12)
    np.testing.assert_allclose(Quaternion.exp(q.log()).wxyz, q.wxyz, atol=1e-12)


def test_quaternions_are_immutable_and_picklable():
    import pickle

    q = Quaternion(1, 2, 3, 4)
    with pytest.raises(AttributeError):
        q.w = 0
    with pytest.raises(ValueError):
        q.wxyz[0] = 5
    assert pickle.loads(pickle.dumps(q)) == q


@pytest.mark.parametrize("call, match", [
    (lambda: Quaternion(0, 0, 0, 0), "zero quaternion"),
    (lambda: Quaternion(0.0, -0.0, 0.0, 0.0), "zero quaternion"),
    (lambda: Quaternion.from_array([0, 0, 0, 0]), "q is the zero quaternion"),
    (lambda: Quaternion.from_xyzw([0, 0, 0, 0], "rotation"), "rotation is the zero"),
    (lambda: Quaternion(math.nan, 0, 0, 1), "w must be a finite number"),
    (lambda: Quaternion(1, math.inf, 0, 0), "x must be a finite number"),
    (lambda: Quaternion.from_array([1, 2, 3]), "q must be four numbers"),
    (lambda: Quaternion.from_axis_angle((0, 0, 0), 1.0), "axis must not be the zero vector"),
    (lambda: Quaternion.from_axis_angle((0, 0, 1), math.nan), "angle"),
    (lambda: Quaternion.from_matrix(np.diag([2.0, 1, 1])), "not a rotation matrix"),
    (lambda: Quaternion.from_matrix(np.diag([-1.0, 1, 1])), "reflection"),
    (lambda: Quaternion.from_matrix(np.eye(2)), "3x3 or 4x4"),
    (lambda: Quaternion.from_matrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]),
     "translation"),
    (lambda: Quaternion.from_matrix(np.full((3, 3), np.nan)), "m must be finite"),
    (lambda: Quaternion.from_euler("xxy", [1, 2, 3]), "same axis twice"),
    (lambda: Quaternion.from_euler("xYz", [1, 2, 3]), "lower case .* or all upper case"),
    (lambda: Quaternion.from_euler("xyz", [1, 2]), "one angle per axis"),
    (lambda: slerp(Quaternion(), (1, 0, 0, 0), 0.5), "q2 must be a scanline"),
    (lambda: slerp(Quaternion(), Quaternion(), math.nan), "t must be a finite"),
    (lambda: Quaternion(1e300, 1e300, 0, 0) * Quaternion(1e300, 0, 1e300, 0), "overflows"),
    (lambda: Quaternion(1e-200, 0, 0, 0) * Quaternion(1e-200, 0, 0, 0), "underflowed"),
])
def test_bad_input_is_named(call, match):
    with pytest.raises((ArgumentValueError, ArgumentTypeError), match=match):
        call()


def test_extreme_but_valid_components_give_rotations():
    for q in (Quaternion(1e-300, 0, 0, 1e-300), Quaternion(1e300, 0, 1e300, 0)):
        m = q.matrix3()
        np.testing.assert_allclose(m @ m.T, np.eye(3), atol=1e-12)
        assert q.normalize().norm == pytest.approx(1.0)
