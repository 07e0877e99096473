"""Reflected and refracted directions against the law of reflection and Snell's law
written here; total internal reflection past the critical angle; the Fresnel
reflectance against its closed forms."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentValueError

rt = sl.raytrace


def angle(a, b):
    return math.acos(max(-1.0, min(1.0, float(np.dot(a, b) / np.linalg.norm(a)
                                              / np.linalg.norm(b)))))


def random_incidence(rng):
    n = rng.normal(size=3)
    n /= np.linalg.norm(n)
    d = rng.normal(size=3)
    d -= 2 * max(0.0, float(d @ n)) * n        # travel against the normal
    return d / np.linalg.norm(d), n


def test_reflection_angle_equals_incidence_angle_in_the_plane_of_incidence():
    rng = np.random.default_rng(2)
    for _ in range(200):
        d, n = random_incidence(rng)
        r = rt.reflect(d, n)
        assert np.linalg.norm(r) == pytest.approx(1.0)
        assert angle(-d, n) == pytest.approx(angle(r, n), abs=1e-9)
        assert np.dot(np.cross(d, n), r) == pytest.approx(0.0, abs=1e-9)   # coplanar


@pytest.mark.parametrize("n1, n2", [(1.0, 1.5), (1.5, 1.0), (1.0, 2.42), (1.33, 1.0)])
def test_refraction_obeys_snells_law(n1, n2):
    rng = np.random.default_rng(5)
    critical = math.asin(n2 / n1) if n2 < n1 else math.pi / 2
    for _ in range(200):
        d, n = random_incidence(rng)
        i = angle(-d, n)
        t = rt.refract(d, n, n1, n2)
        if i >= critical - 1e-9:
            assert t is None or i == pytest.approx(critical, abs=1e-6)
            continue
        assert t is not None
        theta = angle(t, -n)
        assert n1 * math.sin(i) == pytest.approx(n2 * math.sin(theta), abs=1e-9)
        assert np.dot(np.cross(d, n), t) == pytest.approx(0.0, abs=1e-9)
        assert np.dot(t, n) < 0                  # through the surface
        assert np.linalg.norm(t) == pytest.approx(1.0)


def test_total_internal_reflection_past_the_critical_angle():
    n1, n2 = 1.5, 1.0
    critical = math.asin(n2 / n1)                 # 41.81 degrees
    normal = np.array([0.0, 1.0, 0.0])
    for a in (critical - 0.01, critical - 1e-4):
        d = np.array([math.sin(a), -math.cos(a), 0.0])
        t = rt.refract(d, normal, n1, n2)
        assert t is not None
        assert math.asin(abs(t[0])) == pytest.approx(math.asin(n1 * math.sin(a) / n2))
    for a in (critical + 1e-4, critical + 0.01, 1.4):
        d = np.array([math.sin(a), -math.cos(a), 0.0])
        assert rt.refract(d, normal, n1, n2) is None
        assert rt.fresnel(math.cos(a), n1, n2) == 1.0
    # from the rare side every angle passes
    d = np.array([math.sin(1.5), -math.cos(1.5), 0.0])
    assert rt.refract(d, normal, n2, n1) is not None


def test_fresnel_closed_forms():
    # head on: ((n1 - n2) / (n1 + n2))^2
    for n1, n2 in ((1.0, 1.5), (1.5, 1.0), (1.0, 2.42)):
        assert rt.fresnel(1.0, n1, n2) == pytest.approx(((n1 - n2) / (n1 + n2)) ** 2)
    # at Brewster's angle tan(i) = n2 / n1 the p-polarized part vanishes: F = r_s^2 / 2,
    # r_s = -sin(i - t) / sin(i + t)
    n1, n2 = 1.0, 1.5
    i = math.atan(n2 / n1)
    t = math.asin(n1 * math.sin(i) / n2)
    rs = -math.sin(i - t) / math.sin(i + t)
    assert rt.fresnel(math.cos(i), n1, n2) == pytest.approx(rs * rs / 2)
    # grazing incidence reflects everything; equal indices nothing
    assert rt.fresnel(0.0, 1.0, 1.5) == pytest.approx(1.0)
    assert rt.fresnel(0.6, 1.3, 1.3) == 0.0


@pytest.mark.parametrize("call, name", [
    (lambda: rt.refract((0, -1, 0), (0, 1, 0), 0, 1.5), "n1"),
    (lambda: rt.refract((0, -1, 0), (0, 1, 0), 1.0, -1.5), "n2"),
    (lambda: rt.refract((0, -1, 0), (0, 0, 0), 1.0, 1.5), "normal"),
    (lambda: rt.reflect((np.nan, -1, 0), (0, 1, 0)), "direction"),
    (lambda: rt.fresnel(1.5, 1.0, 1.5), "cos_i"),
    (lambda: rt.fresnel(float("nan"), 1.0, 1.5), "cos_i"),
])
def test_bad_input_names_the_argument(call, name):
    with pytest.raises(ArgumentValueError, match=name):
        call()
