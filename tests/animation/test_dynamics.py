"""Particle dynamics: closed forms, energy, collisions, blow-ups."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.animation import (DynamicsError, Drag, Force, Gravity, Particles, Plane, Spring,
                                ballistic, bouncing_ball)

METHODS = ["euler", "semi-implicit-euler", "verlet", "rk4"]


@pytest.mark.parametrize("method", ["verlet", "rk4"])
def test_projectile_matches_closed_form(method):
    p0, v0, g = np.array([0.0, 2.0, 1.0]), np.array([3.0, 10.0, -1.0]), np.array([0, 0, -9.81])
    ball = Particles([p0], velocities=[v0], forces=[Gravity(g)])
    path = ball.run(2.0, dt=0.01, method=method)
    t = np.arange(len(path)) * 0.01
    np.testing.assert_allclose(path[:, 0], ballistic(t, p0, v0, g), atol=1e-9)


def test_euler_orders():
    # explicit Euler lags the closed form by g t dt / 2 in position
    ball = Particles([(0.0, 0.0)], velocities=[(0.0, 0.0)], forces=[Gravity((0, -10))])
    ball.run(1.0, dt=0.1, method="euler")
    assert ball.positions[0, 1] == pytest.approx(-5.0 + 0.5, abs=1e-9)
    ball = Particles([(0.0, 0.0)], forces=[Gravity((0, -10))])
    ball.run(1.0, dt=0.1, method="semi-implicit-euler")
    assert ball.positions[0, 1] == pytest.approx(-5.0 - 0.5, abs=1e-9)


def test_verlet_conserves_a_springs_energy():
    k, m = 40.0, 2.0
    system = Particles([(1.5, 0.0)], velocities=[(0.0, 0.7)], masses=m,
                       forces=[Spring([0], k, rest_length=0.0, anchors=[(0.0, 0.0)])])
    e0 = system.energy()["total"]
    omega_dt = math.sqrt(k / m) * 0.01
    worst = 0.0
    for _ in range(20_000):                       # ~ 140 periods
        system.step(0.01, "verlet")
        worst = max(worst, abs(system.energy()["total"] - e0) / e0)
    assert worst < omega_dt ** 2                  # bounded, no drift (second order)
    explicit = Particles([(1.5, 0.0)], velocities=[(0.0, 0.7)], masses=m,
                         forces=[Spring([0], k, rest_length=0.0, anchors=[(0.0, 0.0)])])
    explicit.run(20.0, 0.01, "euler")
    assert explicit.energy()["total"] > 2 * e0    # explicit Euler gains energy


def test_harmonic_oscillator_period_rk4():
    system = Particles([(1.0, 0.0)], forces=[Spring([0], 1.0, rest_length=0.0,
                                                    anchors=[(0.0, 0.0)])])
    system.run(2 * math.pi, dt=2 * math.pi / 1000, method="rk4")
    np.testing.assert_allclose(system.positions[0], (1.0, 0.0), atol=1e-9)


def test_two_body_spring_conserves_momentum():
    system = Particles([(0, 0), (2, 0)], velocities=[(0, 1), (0, -1)], masses=[1, 3],
                       forces=[Spring([(0, 1)], 10.0, damping=0.5)])
    p0 = (system.masses[:, None] * system.velocities).sum(axis=0)
    system.run(5.0, 0.005, "verlet")
    np.testing.assert_allclose((system.masses[:, None] * system.velocities).sum(axis=0), p0,
                               atol=1e-10)


def test_drag_and_user_force():
    falling = Particles([(0, 0)], forces=[Gravity((0, -9.81)), Drag(linear=0.5)])
    falling.run(30.0, 0.01, "rk4")
    assert falling.velocities[0, 1] == pytest.approx(-9.81 / 0.5, rel=1e-6)   # terminal speed
    wind = Force(lambda t, x, v: np.tile([1.0, 0.0], (len(x), 1)),
                 potential=lambda x: -float(x[:, 0].sum()))
    pushed = Particles([(0, 0)], forces=[wind])
    pushed.run(2.0, 0.01, "verlet")
    assert pushed.positions[0, 0] == pytest.approx(2.0)
    assert pushed.energy()["total"] == pytest.approx(0.0, abs=1e-9)


def test_bounce_with_restitution():
    e = 0.8
    ball = Particles([(0.0, 1.0)], forces=[Gravity((0, -10))],
                     obstacles=[Plane((0, 0), (0, 1), restitution=e)])
    heights, top, rising = [], 0.0, False
    for _ in range(6000):
        ball.step(0.0005, "verlet")
        y, vy = ball.positions[0, 1], ball.velocities[0, 1]
        assert y >= 0
        if vy > 0:
            rising, top = True, max(top, y)
        elif rising:
            heights.append(top)
            rising, top = False, 0.0
    assert ball.contacts > 0 and len(heights) >= 3
    ratios = np.array(heights[1:4]) / np.array(heights[:3])
    np.testing.assert_allclose(ratios, e * e, rtol=0.02)    # h_{k+1} = e^2 h_k
    assert heights[0] == pytest.approx(e * e, rel=0.02)


def test_friction_slows_sliding():
    puck = Particles([(0.0, 0.0)], velocities=[(5.0, -1.0)],
                     obstacles=[Plane((0, 0.0), (0, 1), restitution=0.0, friction=0.5)])
    puck.step(0.1, "semi-implicit-euler")
    assert puck.velocities[0].tolist() == pytest.approx([4.5, 0.0])


def test_blow_up_is_reported_with_the_step():
    stiff = Particles([(1.0, 0.0)], forces=[Spring([0], 1e6, rest_length=0.0,
                                                   anchors=[(0.0, 0.0)])])
    with pytest.raises(DynamicsError, match=r"blew up at step \d+ .*dt \(got 0.1\)") as info:
        stiff.run(1000.0, 0.1, "euler")
    assert 1 < info.value.step < 10_000 and stiff.steps == info.value.step - 1
    assert np.isfinite(stiff.positions).all()      # the last good state is kept


def test_bouncing_ball_direct_motion():
    A, w, k = 10.0, math.pi, 0.2
    x = np.array([0.0, 0.5, 1.0, 1.5, 2.5])
    np.testing.assert_allclose(bouncing_ball(x, A, w, damping=k),
                               A * np.abs(np.sin(w * x)) * np.exp(-k * x))
    assert bouncing_ball(1.0, A, w) == pytest.approx(0, abs=1e-12)   # touches the ground


@pytest.mark.parametrize("call,words", [
    (lambda: Particles([(0, 0, 0, 0)]), "2-D or 3-D"),
    (lambda: Particles([(0, 0)], velocities=[(0, 0), (1, 1)]), r"shape \(1, 2\)"),
    (lambda: Particles([(0, 0)], masses=0), "masses must be finite and > 0"),
    (lambda: Particles([(0, 0)], forces=[Gravity((0, 0, -1))]), "Gravity g has 3"),
    (lambda: Particles([(0, 0)]).step(0), "dt must be > 0"),
    (lambda: Particles([(0, 0)]).step(0.1, "leapfrog"), "method must be one of"),
    (lambda: Particles([(0, 0)], forces=[Spring([(0, 1)], 1.0)]), "spring pairs name"),
    (lambda: Plane((0, 0), (0, 0)), "zero vector"),
    (lambda: Plane((0, 0), (0, 1), restitution=2), "restitution must lie in"),
    (lambda: bouncing_ball(1.0, amplitude=-1), "amplitude > 0"),
    (lambda: Particles([(0, float("inf"))]), "positions must be finite"),
])
def test_bad_input(call, words):
    with pytest.raises(sl.ScanlineError, match=words):
        call()
