"""Random fractal terrain: the increments of midpoint displacement have the variance
of fractional Brownian motion, σ² d^(2H) (a closed form: exact for the increments
between the grid points of each level, Voss's construction), the slope of log
variance against log lag is 2H; the surfaces' slopes follow H; seeds repeat; the
height field is a mesh facing up."""

import numpy as np
import pytest

from scanline.errors import ArgumentValueError
from scanline.fractals import (fbm_surface, height_field, midpoint_displacement,
                               midpoint_profile, terrain)

LEVELS = 12
N = 2 ** LEVELS
LAGS = 2 ** np.arange(0, 10)


@pytest.mark.parametrize("H", [0.2, 0.5, 0.8])
def test_profile_increments_have_the_variance_of_fbm(H):
    var = np.zeros(len(LAGS))
    seeds = 200
    for seed in range(seeds):
        x = midpoint_profile(LEVELS, H, seed=seed)
        var += [np.mean((x[lag::lag] - x[:-lag:lag]) ** 2) for lag in LAGS]
    var /= seeds
    expected = (LAGS / N) ** (2 * H)               # σ = 1, t in [0, 1]
    np.testing.assert_allclose(var, expected, rtol=0.06)
    slope = np.polyfit(np.log(LAGS), np.log(var), 1)[0]
    assert slope == pytest.approx(2 * H, abs=0.03)


def surface_slope(make, H):
    lags = 2 ** np.arange(2, 7)       # 4 to 64 samples: past the grid's finest scale
    var = np.zeros(len(lags))
    for seed in range(4):
        z = make(9, H, seed=seed)
        var += [np.mean((z[:, lag:] - z[:, :-lag]) ** 2) + np.mean((z[lag:] - z[:-lag]) ** 2)
                for lag in lags]
    return np.polyfit(np.log(lags), np.log(var), 1)[0]


@pytest.mark.parametrize("make", [midpoint_displacement, fbm_surface])
def test_surface_increments_scale_with_H(make):
    # on a grid both methods approximate fBm: the slope is 2H within 0.2 (measured,
    # seeds 0-3: diamond-square 0.46, 0.96, 1.50 and spectral 0.51, 0.97, 1.42 for
    # 2H = 0.4, 1.0, 1.6; the periodic spectral surface flattens at large lags)
    slopes = [surface_slope(make, H) for H in (0.2, 0.5, 0.8)]
    for H, slope in zip((0.2, 0.5, 0.8), slopes):
        assert slope == pytest.approx(2 * H, abs=0.2)
    assert slopes[0] < slopes[1] < slopes[2]


def test_seeds_repeat_and_differ():
    a = midpoint_displacement(5, 0.7, seed=11)
    np.testing.assert_array_equal(a, midpoint_displacement(5, 0.7, seed=11))
    assert not np.array_equal(a, midpoint_displacement(5, 0.7, seed=12))
    assert a.shape == (33, 33)
    assert fbm_surface(5, 0.7, seed=1).shape == (32, 32)


def test_height_field_mesh_faces_up_over_the_square():
    z = np.arange(12.0).reshape(3, 4)
    mesh = height_field(z, size=3.0, height=0.5)
    assert len(mesh.vertices) == 12 and mesh.face_count == 2 * 2 * 3
    np.testing.assert_allclose(mesh.vertices[5], (1.0, 1.0, 2.5))
    assert (mesh.plane_equations()[:, 2] > 0).all()        # normals toward +z
    t = terrain(4, H=0.6, seed=2, method="spectral")
    assert len(t.vertices) == 16 * 16


@pytest.mark.parametrize("call, match", [
    (lambda: midpoint_profile(4, H=1.0), "H must lie strictly between 0 and 1"),
    (lambda: midpoint_displacement(4, H=float("nan")), "H must be a finite"),
    (lambda: midpoint_displacement(30), "levels=30 is more than the limit of 24"),
    (lambda: midpoint_displacement(20), "levels: .*limits.MAX_POINTS"),
    (lambda: fbm_surface(20), "levels: .*limit"),
    (lambda: height_field(np.ones(5)), "z must be a 2-D grid"),
    (lambda: height_field([[0, 1], [np.nan, 1]]), "z must be finite"),
    (lambda: terrain(method="perlin"), "method must be one of"),
])
def test_bad_input_is_named(call, match):
    with pytest.raises(ArgumentValueError, match=match):
        call()
