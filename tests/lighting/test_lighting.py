"""The illumination model at single points, computed by hand (Hearn & Baker, 14-2)."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.lighting import (AmbientLight, DirectionalLight, Material, PointLight, SpotLight,
                               intensity)


def test_ambient_only():
    m = Material(ka=0.4, kd=0.5, ks=0.5, color=(255, 0, 255))
    out = intensity((1, 2, 3), (0, 1, 0), (0, 0, 10), [AmbientLight((0.5, 1.0, 0.25))], m)
    assert out.tolist() == pytest.approx([0.2, 0.0, 0.1])


def test_lambert_at_sixty_degrees():
    # light from 60 degrees off the normal: N . L = cos 60 = 1/2
    m = Material(ka=0, kd=0.8, ks=0)
    d = (-math.sin(math.radians(60)), 0, -math.cos(math.radians(60)))   # travels toward -z
    out = intensity((0, 0, 0), (0, 0, 1), (0, 0, 5), [DirectionalLight(d, 1.0)], m)
    assert out == pytest.approx(np.full(3, 0.4))


def test_phong_specular_by_hand():
    # point light at (0, 3, 4) seen from the surface point (0, 0, 0) with N = +z:
    # d = 5, L = (0, .6, .8), N.L = .8, R = 2 (N.L) N - L = (0, -.6, .8);
    # eye at (0, -3, 4): V = (0, -.6, .8), V.R = 1; attenuation 1 / (1 + 0.1 d) = 2/3
    m = Material(ka=0, kd=0.5, ks=0.4, shininess=7)
    light = PointLight((0, 3, 4), intensity=(1.0, 0.5, 0.0), attenuation=(1, 0.1, 0))
    out = intensity((0, 0, 0), (0, 0, 2), (0, -3, 4), [light], m)
    f = 1 / 1.5
    expect = f * np.array([1.0, 0.5, 0.0]) * (0.5 * 0.8 + 0.4 * 1.0)
    assert out == pytest.approx(expect)
    # eye elsewhere: V = (0, 0, 1), V.R = .8 -> .8^7; Blinn: H = (L + V)/|L + V|
    out = intensity((0, 0, 0), (0, 0, 1), (0, 0, 9), [light], m)
    assert out[0] == pytest.approx(f * (0.4 + 0.4 * 0.8 ** 7))
    h = np.array([0, 0.6, 1.8]) / np.linalg.norm([0, 0.6, 1.8])
    out = intensity((0, 0, 0), (0, 0, 1), (0, 0, 9), [light], m, specular="blinn")
    assert out[0] == pytest.approx(f * (0.4 + 0.4 * h[2] ** 7))


def test_behind_the_surface_and_attenuation_limit():
    m = Material(ka=0, kd=1, ks=1)
    # light below the surface: nothing
    assert intensity((0, 0, 0), (0, 0, 1), (0, 0, 5), [PointLight((0, 0, -2))], m).max() == 0
    # f(d) = min(1, 1 / (a0 + a1 d + a2 d^2)) is limited to 1
    assert sl.lighting.attenuation(0.5, (0.25, 0, 0)) == 1.0
    assert sl.lighting.attenuation(2.0, (1, 1, 1)) == pytest.approx(1 / 7)


def test_spotlight_cone_and_falloff():
    m = Material(ka=0, kd=1, ks=0)
    spot = SpotLight((0, 0, 10), direction=(0, 0, -1), angle=math.radians(20), exponent=2)
    on_axis = intensity((0, 0, 0), (0, 0, 1), (0, 0, 20), [spot], m)[0]
    assert on_axis == pytest.approx(1.0)
    # 10 degrees off the axis: cos^2(10) Warn falloff times N . L = cos 10
    x = 10 * math.tan(math.radians(10))
    off = intensity((x, 0, 0), (0, 0, 1), (0, 0, 20), [spot], m)[0]
    assert off == pytest.approx(math.cos(math.radians(10)) ** 3)
    # outside the 20-degree cone: dark
    x = 10 * math.tan(math.radians(25))
    assert intensity((x, 0, 0), (0, 0, 1), (0, 0, 20), [spot], m)[0] == 0


def test_shininess_extremes_and_colored_sources():
    light = DirectionalLight((0, 0, -1), intensity=(0.2, 0.4, 0.8))
    for n in (0, 1e6):
        m = Material(ka=0, kd=0, ks=1, shininess=n)
        out = intensity((0, 0, 0), (0, 0, 1), (0, 0, 5), [light], m)
        assert out == pytest.approx([0.2, 0.4, 0.8])      # V = R: (V.R)^n = 1
        out = intensity((0, 0, 0), (0, 0, 1), (3, 0, 4), [light], m)
        assert np.isfinite(out).all()
        assert out[2] == pytest.approx(0.8 * (0.8 ** n if n else 1.0))


def test_depth_cue_and_transparency():
    i = np.array([[1.0, 1.0, 1.0]] * 3)
    out = sl.lighting.depth_cue(i, [2.0, 6.0, 4.0], 2.0, 6.0, (1.0, 0.2), (0, 0, 0))
    assert out[:, 0] == pytest.approx([1.0, 0.2, 0.6])
    assert sl.lighting.transparency([1, 0, 0], [0, 0, 1], 0.25).tolist() == [0.75, 0, 0.25]


@pytest.mark.parametrize("make, match", [
    (lambda: AmbientLight(-0.1), ">= 0"),
    (lambda: DirectionalLight((0, 0, 0)), "direction"),
    (lambda: PointLight((0, 0, 1), intensity=(1, 2)), "triple"),
    (lambda: PointLight((0, 0, 1), attenuation=(0, 0, 0)), "not all zero"),
    (lambda: PointLight((0, 0, 1), intensity=float("nan")), "finite"),
    (lambda: SpotLight((0, 0, 1), (0, 0, -1), angle=2.0), "angle"),
    (lambda: Material(kd=1.5), "kd"),
    (lambda: Material(shininess=-1), "shininess"),
    (lambda: intensity((0, 0, 0), (0, 0, 1), (0, 0, 1), ["sun"], Material()), "lights"),
    (lambda: intensity((0, 0, 0), (0, 0, 1), (0, 0, 1), [], "m"), "material"),
    (lambda: intensity((0, 0, 0), (0, 0, 1), (0, 0, 1), [], Material(), specular="x"),
     "specular"),
])
def test_bad_lights_and_materials(make, match):
    with pytest.raises(sl.ScanlineError, match=match):
        make()


def test_vertex_intensities_take_each_mesh_material_whatever_the_face_order():
    # three meshes of three materials, their faces asked for in a shuffled order: each
    # face is lit with its own mesh's material (the faces are grouped by one stable
    # sort, not selected mesh by mesh), the same values as in mesh order
    from scanline.screen import prepare
    from scanline.shading import ShadingOptions, vertex_intensities

    meshes = [sl.mesh.cube(1.0), sl.mesh.sphere(0.5, (1.5, 0, 0), resolution=(8, 4)),
              sl.mesh.torus(0.6, 0.2, resolution=(8, 4))]
    mats = [sl.lighting.Material(ka=0.2, kd=0.7, ks=0.0, shininess=1),
            sl.lighting.Material(ka=0.0, kd=0.3, ks=0.6, shininess=40),
            sl.lighting.Material(ka=0.5, kd=0.1, ks=0.2, shininess=5)]
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0))
    scene = prepare(meshes, cam, 64, 48, mats)
    lights = ShadingOptions(lights=[sl.lighting.AmbientLight(0.3),
                                    sl.lighting.DirectionalLight(direction=(-1, -1, -1),
                                                                 intensity=0.8)])
    facets = np.arange(scene.facet_count)
    shuffled = np.random.default_rng(3).permutation(facets)
    ordered = vertex_intensities(scene, facets, lights)
    assert len(np.unique(scene.facet_mesh)) == 3
    np.testing.assert_array_equal(vertex_intensities(scene, shuffled, lights),
                                  ordered[shuffled])
    for m in range(3):                     # each mesh alone: its own material
        own = facets[scene.facet_mesh == m]
        np.testing.assert_array_equal(vertex_intensities(scene, own, lights), ordered[own])
    means = [ordered[scene.facet_mesh == m].mean() for m in range(3)]
    assert not np.allclose(means[0], means[1])
