"""Forward and inverse kinematics of articulated chains."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.animation import Chain, UnreachableTarget

RNG = np.random.default_rng(16)


def test_forward_planar_by_hand():
    arm = Chain([3.0, 2.0, 1.0], base=(1, 1))
    a = [math.pi / 2, -math.pi / 2, math.pi / 2]
    np.testing.assert_allclose(arm.forward(a), [(1, 1), (1, 4), (3, 4), (3, 5)], atol=1e-12)
    poses = arm.forward(RNG.uniform(-3, 3, (5, 3)))       # a batch
    assert poses.shape == (5, 4, 2)
    links = np.linalg.norm(np.diff(poses, axis=1), axis=2)
    np.testing.assert_allclose(links, np.tile([3, 2, 1], (5, 1)))


def test_forward_spatial_matches_planar_about_z():
    lengths = [1.0, 2.0, 0.5]
    flat, space = Chain(lengths), Chain(lengths, axes=[(0, 0, 1)] * 3)
    a = RNG.uniform(-3, 3, 3)
    np.testing.assert_allclose(space.forward(a)[:, :2], flat.forward(a), atol=1e-12)
    np.testing.assert_allclose(space.forward(a)[:, 2], 0, atol=1e-12)


def test_jacobian_by_finite_differences():
    for chain in (Chain([1, 2, 1.5]), Chain([1, 1, 1], axes=[(0, 0, 1), (0, 1, 0), (1, 0, 1)])):
        a = RNG.uniform(-2, 2, 3)
        j = chain.jacobian(a)
        eps = 1e-6
        numeric = np.stack([(chain.end(a + eps * np.eye(3)[i]) - chain.end(a - eps * np.eye(3)[i]))
                            / (2 * eps) for i in range(3)], axis=1)
        np.testing.assert_allclose(j, numeric, atol=1e-7)


@pytest.mark.parametrize("method", ["analytic", "ccd", "dls"])
def test_two_link_reaches_reachable_targets(method):
    arm = Chain([2.0, 1.2])
    for _ in range(40):
        r = RNG.uniform(0.85, 3.15)                      # inside the annulus [0.8, 3.2]
        target = r * np.array([math.cos(th := RNG.uniform(-math.pi, math.pi)), math.sin(th)])
        reach = arm.inverse(target, method=method, max_iterations=2000)
        assert reach.reached, (target, reach)
        np.testing.assert_allclose(arm.end(reach), target, atol=1e-8)


def test_two_link_elbow_branches():
    arm = Chain([1.0, 1.0])
    up, down = arm.inverse((1, 1), elbow="up"), arm.inverse((1, 1), elbow="down")
    np.testing.assert_allclose(up.angles, (0, math.pi / 2), atol=1e-12)
    np.testing.assert_allclose(down.angles, (math.pi / 2, -math.pi / 2), atol=1e-12)


@pytest.mark.parametrize("method", ["ccd", "dls"])
def test_n_link_planar_and_spatial(method):
    planar = Chain([1.0, 0.8, 0.6, 0.4, 0.3])
    spatial = Chain([1.0, 1.0, 0.7], axes=[(0, 0, 1), (0, 1, 0), (0, 1, 0)])
    for chain, dim in ((planar, 2), (spatial, 3)):
        for _ in range(10):
            target = chain.end(RNG.uniform(-math.pi, math.pi, chain.joints))   # reachable
            reach = chain.inverse(target, method=method, max_iterations=3000)
            assert reach.reached, (chain, target, reach)
            assert np.linalg.norm(chain.end(reach.angles) - target) <= 1e-8 * chain.reach


@pytest.mark.parametrize("method", ["analytic", "ccd", "dls"])
def test_unreachable_targets_are_reported(method):
    arm = Chain([2.0, 1.0])
    far = arm.inverse((5, 0), method=method)
    assert not far.reached and "beyond the chain's reach of 3" in far.reason
    assert far.error == pytest.approx(2.0, abs=1e-6)       # stretched toward it
    near = arm.inverse((0.5, 0), method=method)
    assert not near.reached and "inside the radius 1" in near.reason
    with pytest.raises(UnreachableTarget, match=r"target=\[5.0, 0.0\] cannot be reached"):
        arm.inverse((5, 0), method=method, strict=True)


def test_joint_limits_are_respected():
    lim = [(-0.5, 0.5), (0.0, 2.0), (0.0, 2.0)]
    chain = Chain([1, 1, 1], limits=lim)
    for method in ("ccd", "dls"):
        for _ in range(10):
            reach = chain.inverse(RNG.uniform(-3, 3, 2), method=method, max_iterations=300)
            a = reach.angles
            assert ((a >= np.array(lim)[:, 0] - 1e-12) & (a <= np.array(lim)[:, 1] + 1e-12)).all()
    # a target only reachable with the base turned past its limit
    blocked = chain.inverse((-2.5, 0.0), method="dls")
    assert not blocked.reached and "joint limits block it" in blocked.reason
    # the analytic solution falls back to the iterative one when a branch breaks a limit
    arm = Chain([1, 1], limits=[(-3.2, 3.2), (0.0, 3.2)])
    r = arm.inverse((1, 1), elbow="down")
    assert r.reached and r.angles[1] >= 0


def test_follow_is_smooth():
    arm = Chain([1.0, 0.8, 0.5])
    s = np.linspace(0, 1, 30)
    targets = np.stack([1.2 + 0.3 * np.cos(2 * np.pi * s), 0.8 + 0.3 * np.sin(2 * np.pi * s)], 1)
    angles, results = arm.follow(targets)
    assert all(r.reached for r in results)
    assert np.abs(np.diff(angles, axis=0)).max() < 0.5     # no jumps between frames


@pytest.mark.parametrize("call,words", [
    (lambda: Chain([]), "at least one length"),
    (lambda: Chain([1, -1]), "finite and > 0"),
    (lambda: Chain([1, 1], axes=[(0, 0, 1)]), r"axes must have shape \(2, 3\)"),
    (lambda: Chain([1, 1], axes=[(0, 0, 1), (0, 0, 0)]), r"axes\[1\] is zero"),
    (lambda: Chain([1, 1], limits=[(1, 0), (0, 1)]), "lower <= upper"),
    (lambda: Chain([1, 1]).forward([0.0]), "one angle per joint"),
    (lambda: Chain([1, 1]).forward([0.0, float("nan")]), "angles must be finite"),
    (lambda: Chain([1, 1]).inverse((float("nan"), 0)), "target must be a finite 2-D point"),
    (lambda: Chain([1, 1, 1]).inverse((1, 0), method="analytic"), "planar two-link"),
    (lambda: Chain([1, 1]).inverse((1, 0), method="jacobian"), "method must be one of"),
])
def test_bad_input(call, words):
    with pytest.raises(sl.ScanlineError, match=words):
        call()
