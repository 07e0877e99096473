"""Procedural textures: Perlin's improved noise against a transcription of his
reference code (Perlin 2002) on the same permutation, and the checker, marble and
wood textures."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentValueError
from scanline.texture.noise import permutation


def reference_noise(x, y, z, p):
    """Ken Perlin's reference ImprovedNoise.noise (2002), line by line."""
    def fade(t):
        return t * t * t * (t * (t * 6 - 15) + 10)

    def lerp(t, a, b):
        return a + t * (b - a)

    def grad(hash_, x, y, z):
        h = hash_ & 15
        u = x if h < 8 else y
        v = y if h < 4 else (x if h in (12, 14) else z)
        return (u if h & 1 == 0 else -u) + (v if h & 2 == 0 else -v)

    X, Y, Z = int(math.floor(x)) & 255, int(math.floor(y)) & 255, int(math.floor(z)) & 255
    x -= math.floor(x)
    y -= math.floor(y)
    z -= math.floor(z)
    u, v, w = fade(x), fade(y), fade(z)
    A = p[X] + Y
    AA = p[A] + Z
    AB = p[A + 1] + Z
    B = p[X + 1] + Y
    BA = p[B] + Z
    BB = p[B + 1] + Z
    return lerp(w, lerp(v, lerp(u, grad(p[AA], x, y, z), grad(p[BA], x - 1, y, z)),
                        lerp(u, grad(p[AB], x, y - 1, z), grad(p[BB], x - 1, y - 1, z))),
                lerp(v, lerp(u, grad(p[AA + 1], x, y, z - 1), grad(p[BA + 1], x - 1, y, z - 1)),
                     lerp(u, grad(p[AB + 1], x, y - 1, z - 1),
                          grad(p[BB + 1], x - 1, y - 1, z - 1))))


@pytest.mark.parametrize("seed", [0, 7])
def test_noise_is_perlins_reference_improved_noise(seed):
    pts = np.random.default_rng(seed).uniform(-40, 300, (300, 3))
    p = permutation(seed).tolist()
    expect = [reference_noise(*pt, p) for pt in pts]
    np.testing.assert_allclose(sl.texture.noise(pts, seed), expect, atol=1e-12)


def test_noise_vanishes_on_the_lattice_and_stays_within_one():
    lattice = np.random.default_rng(1).integers(-50, 50, (100, 3)).astype(float)
    assert np.abs(sl.texture.noise(lattice, 3)).max() == 0
    values = sl.texture.noise(np.random.default_rng(2).uniform(0, 20, (20000, 3)), 3)
    assert np.abs(values).max() <= 1.1 and values.std() > 0.1


def test_textures_are_deterministic_with_a_seed():
    for make in (sl.texture.marble, sl.texture.wood):
        a, b, c = make(32, seed=4), make(32, seed=4), make(32, seed=5)
        np.testing.assert_array_equal(a.image, b.image)
        assert not np.array_equal(a.image, c.image)


def test_turbulence_sums_octaves_of_absolute_noise():
    pts = np.random.default_rng(3).uniform(0, 5, (50, 3))
    expect = sum(np.abs([reference_noise(*(pt * 2 ** k), permutation(0).tolist())
                         for pt in pts]) / 2 ** k for k in range(3))
    np.testing.assert_allclose(sl.texture.turbulence(pts, octaves=3), expect, atol=1e-12)


def test_checker_squares():
    t = sl.texture.checker(8, 4, colors=("red", "blue"), filter="nearest")
    squares = t.sample([[0.1, 0.1], [0.35, 0.1], [0.35, 0.35], [0.1, 0.9]])
    np.testing.assert_array_equal(squares, [[1, 0, 0], [0, 0, 1], [1, 0, 0], [0, 0, 1]])
    assert t.filter == "nearest" and t.width == t.height == 8


def test_marble_and_wood_stay_within_their_colors():
    light, dark = np.array([235, 232, 225]) / 255, np.array([70, 70, 90]) / 255
    img = sl.texture.marble(64).image
    assert (img >= np.minimum(light, dark) - 1e-12).all()
    assert (img <= np.maximum(light, dark) + 1e-12).all()
    assert img.std() > 0.05
    assert sl.texture.wood(64).image.std() > 0.03


@pytest.mark.parametrize("period", [3, (2, 5, 7), (4, None, 1)])
def test_noise_with_a_period_repeats(period):
    pts = np.random.default_rng(5).uniform(-20, 20, (500, 3))
    base = sl.texture.noise(pts, 4, period)
    each = [period] * 3 if isinstance(period, int) else period
    for axis, p in enumerate(each):
        if p is None:
            continue
        for k in (1, -2):
            shifted = pts.copy()
            shifted[:, axis] += k * p
            np.testing.assert_allclose(sl.texture.noise(shifted, 4, period), base, atol=1e-12)
    shifted = pts + 0.5
    assert np.abs(sl.texture.noise(shifted, 4, period) - base).max() > 0.1


def test_periodic_noise_is_perlins_inside_one_period():
    """Where no lattice coordinate reaches the period (cells 0 .. P - 2), the wrap
    changes nothing: the reference noise itself."""
    pts = np.random.default_rng(6).uniform(0, 5, (200, 3))
    p = permutation(2).tolist()
    expect = [reference_noise(*pt, p) for pt in pts]
    np.testing.assert_allclose(sl.texture.noise(pts, 2, period=6), expect, atol=1e-12)


def test_periodic_turbulence_repeats_with_the_first_octaves_period():
    pts = np.random.default_rng(7).uniform(0, 4, (300, 3))
    base = sl.texture.turbulence(pts, octaves=4, seed=1, period=4)
    np.testing.assert_allclose(sl.texture.turbulence(pts + [4, -8, 12], octaves=4, seed=1,
                                                     period=4), base, atol=1e-12)


@pytest.mark.parametrize("make", [sl.texture.marble, sl.texture.wood])
def test_tileable_marble_and_wood_have_no_seams(make):
    """Repeated side by side (and one above the other), a tileable texture's last
    column meets its first about as any two neighboring columns meet (the mean
    difference of the pair, against the mean over the neighboring pairs); the
    texture made without the period has a seam there, twice the change or more."""
    def seams(img):
        across = np.abs(np.diff(img, axis=1)).mean()
        up = np.abs(np.diff(img, axis=0)).mean()
        return (np.abs(img[:, 0] - img[:, -1]).mean() / across,
                np.abs(img[0] - img[-1]).mean() / up)

    assert max(seams(make(128, seed=3).image)) < 1.25
    assert min(seams(make(128, seed=3, tileable=False).image)) > 1.5


@pytest.mark.parametrize("period", [0, -2, 2.5, True, (1, 2), "4", (1, 0, 1)])
def test_bad_period_is_refused(period):
    with pytest.raises(ArgumentValueError, match="period"):
        sl.texture.noise(np.zeros((1, 3)), period=period)
    with pytest.raises(ArgumentValueError, match="period"):
        sl.texture.turbulence(np.zeros((1, 3)), period=period)


def test_a_tileable_marble_needs_whole_veins():
    with pytest.raises(ArgumentValueError, match="veins"):
        sl.texture.marble(16, veins=2.5)
    assert sl.texture.marble(16, veins=2.5, tileable=False).width == 16


@pytest.mark.parametrize("call", [
    lambda: sl.texture.checker(0), lambda: sl.texture.checker(8, 9),
    lambda: sl.texture.marble(16, seed=-1), lambda: sl.texture.wood(10 ** 6),
    lambda: sl.texture.turbulence(np.zeros((1, 3)), octaves=40),
    lambda: sl.texture.noise([[np.nan, 0, 0]]),
])
def test_bad_arguments_are_refused(call):
    with pytest.raises(ArgumentValueError):
        call()
