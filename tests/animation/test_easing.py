"""The easing catalog against Penner's published definitions, written out here."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.animation import EASINGS, cubic_bezier, ease

C1 = 1.70158
C3 = C1 + 1


def bounce_out(t):
    n1, d1 = 7.5625, 2.75
    if t < 1 / d1:
        return n1 * t * t
    if t < 2 / d1:
        t -= 1.5 / d1
        return n1 * t * t + 0.75
    if t < 2.5 / d1:
        t -= 2.25 / d1
        return n1 * t * t + 0.9375
    t -= 2.625 / d1
    return n1 * t * t + 0.984375


REFERENCE = {   # Penner's equations as easings.net lists them, for t strictly in (0, 1)
    "linear": lambda t: t,
    "ease-in-quad": lambda t: t * t,
    "ease-out-quad": lambda t: 1 - (1 - t) * (1 - t),
    "ease-in-out-quad": lambda t: 2 * t * t if t < 0.5 else 1 - (-2 * t + 2) ** 2 / 2,
    "ease-in-cubic": lambda t: t ** 3,
    "ease-out-cubic": lambda t: 1 - (1 - t) ** 3,
    "ease-in-out-cubic": lambda t: 4 * t ** 3 if t < 0.5 else 1 - (-2 * t + 2) ** 3 / 2,
    "ease-in-quart": lambda t: t ** 4,
    "ease-out-quart": lambda t: 1 - (1 - t) ** 4,
    "ease-in-out-quart": lambda t: 8 * t ** 4 if t < 0.5 else 1 - (-2 * t + 2) ** 4 / 2,
    "ease-in-quint": lambda t: t ** 5,
    "ease-out-quint": lambda t: 1 - (1 - t) ** 5,
    "ease-in-out-quint": lambda t: 16 * t ** 5 if t < 0.5 else 1 - (-2 * t + 2) ** 5 / 2,
    "ease-in-sine": lambda t: 1 - math.cos(t * math.pi / 2),
    "ease-out-sine": lambda t: math.sin(t * math.pi / 2),
    "ease-in-out-sine": lambda t: -(math.cos(math.pi * t) - 1) / 2,
    "ease-in-expo": lambda t: 2 ** (10 * t - 10),
    "ease-out-expo": lambda t: 1 - 2 ** (-10 * t),
    "ease-in-out-expo": lambda t: 2 ** (20 * t - 10) / 2 if t < 0.5 else (2 - 2 ** (-20 * t + 10)) / 2,
    "ease-in-circ": lambda t: 1 - math.sqrt(1 - t ** 2),
    "ease-out-circ": lambda t: math.sqrt(1 - (t - 1) ** 2),
    "ease-in-out-circ": lambda t: ((1 - math.sqrt(1 - (2 * t) ** 2)) / 2 if t < 0.5
                                   else (math.sqrt(1 - (-2 * t + 2) ** 2) + 1) / 2),
    "ease-in-back": lambda t: C3 * t ** 3 - C1 * t ** 2,
    "ease-out-back": lambda t: 1 + C3 * (t - 1) ** 3 + C1 * (t - 1) ** 2,
    "ease-in-out-back": lambda t: (((2 * t) ** 2 * ((C1 * 1.525 + 1) * 2 * t - C1 * 1.525)) / 2
                                   if t < 0.5 else ((2 * t - 2) ** 2 * ((C1 * 1.525 + 1) * (t * 2 - 2)
                                                                       + C1 * 1.525) + 2) / 2),
    "ease-in-elastic": lambda t: -(2 ** (10 * t - 10)) * math.sin((t * 10 - 10.75) * 2 * math.pi / 3),
    "ease-out-elastic": lambda t: 2 ** (-10 * t) * math.sin((t * 10 - 0.75) * 2 * math.pi / 3) + 1,
    "ease-in-out-elastic": lambda t: (-(2 ** (20 * t - 10) * math.sin((20 * t - 11.125) * 2 * math.pi / 4.5)) / 2
                                      if t < 0.5 else
                                      (2 ** (-20 * t + 10) * math.sin((20 * t - 11.125) * 2 * math.pi / 4.5)) / 2 + 1),
    "ease-in-bounce": lambda t: 1 - bounce_out(1 - t),
    "ease-out-bounce": bounce_out,
    "ease-in-out-bounce": lambda t: ((1 - bounce_out(1 - 2 * t)) / 2 if t < 0.5
                                     else (1 + bounce_out(2 * t - 1)) / 2),
}
POINTS = [0.05, 0.2, 1 / 3, 0.49, 0.5, 0.51, 0.7, 0.9, 0.999]


def test_catalog_is_the_penner_set_and_hearn_baker():
    penner = {n for n in EASINGS if n.startswith("ease-")}
    assert len(penner) == 30
    assert set(REFERENCE) == penner | {"linear"}
    assert set(sl.animation.SPACINGS) <= set(EASINGS)


@pytest.mark.parametrize("name", sorted(REFERENCE))
def test_against_published_definition(name):
    got = ease(name, POINTS)
    want = [REFERENCE[name](t) for t in POINTS]
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)


@pytest.mark.parametrize("name", sorted(EASINGS))
def test_boundary_values_exact(name):
    assert ease(name, 0.0) == 0.0
    assert ease(name, 1.0) == 1.0
    assert ease(name, [0.0, 1.0]).tolist() == [0.0, 1.0]


def test_hearn_baker_laws_are_the_sine_easings():
    t = np.linspace(0, 1, 101)
    for law, penner in (("accelerate", "ease-in-sine"), ("decelerate", "ease-out-sine"),
                        ("accelerate-decelerate", "ease-in-out-sine"), ("constant", "linear")):
        np.testing.assert_array_equal(ease(law, t), ease(penner, t))


def test_known_values():
    assert ease("ease-out-bounce", 0.5) == pytest.approx(0.765625, abs=1e-15)
    assert ease("ease-in-back", 0.5) == pytest.approx(C3 / 8 - C1 / 4)   # below zero first
    assert min(ease("ease-in-back", np.linspace(0, 1, 201))) < -0.09      # 10% overshoot
    assert max(ease("ease-out-elastic", np.linspace(0, 1, 201))) > 1.3


def test_cubic_bezier_css_keywords():
    # CSS's ease-in-out is cubic-bezier(0.42, 0, 0.58, 1): symmetric about (0.5, 0.5)
    f = cubic_bezier(0.42, 0, 0.58, 1)
    assert ease(f, 0.5) == pytest.approx(0.5, abs=1e-12)
    t = np.linspace(0.01, 0.99, 50)
    np.testing.assert_allclose(ease(f, t) + ease(f, 1 - t), 1, atol=1e-12)
    # linear control points give the identity
    np.testing.assert_allclose(ease(cubic_bezier(1 / 3, 1 / 3, 2 / 3, 2 / 3), t), t, atol=1e-12)
    with pytest.raises(sl.ScanlineError, match="x1 must lie in"):
        cubic_bezier(1.5, 0, 0.5, 1)


@pytest.mark.parametrize("name,t,words", [
    ("ease-in-wobble", 0.5, "not an easing"),
    ("ease_in_quad", 0.5, "did you mean 'ease-in-quad'"),
    (3, 0.5, "easing name or a function"),
    ("linear", 1.5, "must lie in"),
    ("linear", float("nan"), "must lie in"),
    ("linear", "half", "must be a number"),
    (lambda t: t * 2, 0.5, "must map 0 to 0 and 1 to 1"),
])
def test_bad_input(name, t, words):
    with pytest.raises(sl.ScanlineError, match=words):
        ease(name, t)
