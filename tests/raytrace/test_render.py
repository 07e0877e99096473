"""sl.render(method="ray-tracing"): equal to ray casting where nothing reflects,
refracts or casts a shadow; mirrors, clear glass and shadows against values worked
out here; soft shadows reproducible by seed; bad options named."""

import math
import os

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentValueError

L = sl.lighting


def quad(corners):
    return sl.mesh.Mesh(corners, [(0, 1, 2, 3)])


def scene_without_shadows():
    """A sphere and a cube lit from the eye itself (no point the eye sees is in
    shadow), seen in perspective."""
    eye = (0.5, 1.0, 6.0)
    cam = sl.Camera(eye=eye, target=(0, 0, 0))
    meshes = [sl.mesh.sphere(1.0, center=(-1.0, 0, 0), resolution=16),
              sl.mesh.cube(1.2).translated((1.3, 0.0, 0.3))]
    mats = [L.Material(color=(220, 90, 60), shininess=30),
            L.Material(color=(80, 160, 220), ks=0.5, shininess=8)]
    lights = [L.AmbientLight(0.2), L.PointLight(eye, intensity=0.8)]
    return meshes, cam, mats, lights


@pytest.mark.parametrize("mode, antialias", [("RGB", 1), ("L", 1), ("RGB", 2)])
def test_without_mirrors_glass_or_shadows_equals_ray_casting(mode, antialias):
    meshes, cam, mats, lights = scene_without_shadows()
    images = []
    for method in ("ray-casting", "ray-tracing"):
        fb = sl.FrameBuffer(64, 48, mode=mode, background=(10, 20, 30))
        r = sl.render(fb, meshes, cam, method=method, materials=mats, lights=lights,
                      shading="phong", antialias=antialias)
        images.append((fb.to_array(), r.faces))
    assert (images[0][1] >= 0).sum() > 400
    assert np.array_equal(images[0][1], images[1][1])
    assert np.array_equal(images[0][0], images[1][0])


def ortho(size=2.0):
    return sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
                     projection=sl.projection.orthographic(window=(-size, -size, size, size)))


def test_a_mirror_shows_what_it_reflects():
    """A mirror tilted 45 degrees about y sends the view rays (-z) toward +x, onto a
    red wall lit by ambient light only: the mirror's pixels are the wall's color."""
    mirror = quad([(-1, -1, 1), (1, -1, -1), (1, 1, -1), (-1, 1, 1)])
    wall = quad([(3, -5, -5), (3, -5, 5), (3, 5, 5), (3, 5, -5)])
    mats = [L.Material(ka=0, kd=0, ks=0, reflectivity=1.0),
            L.Material(ka=1.0, kd=0, ks=0, color=(200, 40, 40))]
    fb = sl.FrameBuffer(21, 21, background="black")
    sl.render(fb, [mirror, wall], ortho(), method="ray-tracing", materials=mats,
              lights=[L.AmbientLight(1.0)], shading="phong", gamma=1)
    a = fb.to_array()
    assert a[10, 10].tolist() == [200, 40, 40]
    # half as reflective: half the wall's intensity (gamma 1: linear values)
    mats[0] = L.Material(ka=0, kd=0, ks=0, reflectivity=0.5)
    fb = sl.FrameBuffer(21, 21, background="black")
    sl.render(fb, [mirror, wall], ortho(), method="ray-tracing", materials=mats,
              lights=[L.AmbientLight(1.0)], shading="phong", gamma=1)
    assert fb.to_array()[10, 10].tolist() == [100, 20, 20]
    # max_depth=1: no reflected rays, the mirror is black
    fb = sl.FrameBuffer(21, 21, background=(0, 0, 255))
    sl.render(fb, [mirror, wall], ortho(), method="ray-tracing", materials=mats,
              lights=[L.AmbientLight(1.0)], shading="phong", gamma=1, max_depth=1)
    assert fb.to_array()[10, 10].tolist() == [0, 0, 0]


def test_clear_glass_of_index_one_shows_the_background_unchanged():
    """k_t = 1 and eta = 1: no bending and a Fresnel reflectance of 0, so a slab of
    such glass passes the background through untouched."""
    slab = sl.mesh.cube(1.0)
    mats = L.Material(ka=0, kd=0, ks=0, transparency=1.0, refractive_index=1.0)
    fb = sl.FrameBuffer(21, 21, background=(30, 140, 90))
    r = sl.render(fb, slab, ortho(), method="ray-tracing", materials=mats,
                  lights=[L.AmbientLight(1.0)], shading="phong", gamma=1)
    assert (r.faces >= 0).sum() > 20
    assert (fb.to_array() == [30, 140, 90]).all()


def test_glass_bends_light_and_reflects_by_fresnel():
    """Head on through a slab of index 1.5 over a white background: each of the two
    faces reflects F = 0.04 and passes 0.96; the light that ends in the background
    (through, or back out toward the viewer) is all of it, minus nothing: white."""
    slab = sl.mesh.cube(1.0)
    mats = L.Material(ka=0, kd=0, ks=0, transparency=1.0, refractive_index=1.5)
    fb = sl.FrameBuffer(21, 21, background=(255, 255, 255))
    sl.render(fb, slab, ortho(), method="ray-tracing", materials=mats,
              lights=[L.AmbientLight(1.0)], shading="phong", gamma=1, max_depth=64)
    assert (fb.to_array() >= 254).all()
    # two levels only: the light through both faces is lost past the depth limit,
    # and the pixel holds the first face's reflection F = 0.04 of white
    fb = sl.FrameBuffer(21, 21, background=(255, 255, 255))
    sl.render(fb, slab, ortho(), method="ray-tracing", materials=mats,
              lights=[L.AmbientLight(1.0)], shading="phong", gamma=1, max_depth=2)
    assert fb.to_array()[10, 10].tolist() == [round(255 * 0.04)] * 3


def test_shadow_leaves_only_the_ambient_term():
    floor = quad([(-3, -3, 0), (3, -3, 0), (3, 3, 0), (-3, 3, 0)])
    blocker = quad([(-0.5, -0.5, 2), (0.5, -0.5, 2), (0.5, 0.5, 2), (-0.5, 0.5, 2)])
    mats = [L.Material(ka=0.5, kd=0.5, ks=0, color="white"), L.Material(color="black")]
    lights = [L.AmbientLight(0.4), L.DirectionalLight(direction=(0, 0, -1), intensity=1.0)]
    cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
                    projection=sl.projection.orthographic(window=(-3, -3, 3, 3)))
    # the light slanted: the blocker's shadow falls beside it
    lights[1] = L.DirectionalLight(direction=(1, 0, -1), intensity=1.0)
    fb = sl.FrameBuffer(31, 31, mode="L", background="black")
    sl.render(fb, [floor, blocker], cam, method="ray-tracing", materials=mats, lights=lights,
              shading="phong", gamma=1)
    a = fb.to_array()
    # the shadow falls 2 units toward +x of the blocker: device x 15 + 10 = 25, row 15
    assert a[15, 25] == round(255 * 0.5 * 0.4)                  # ka Ia only
    assert a[15, 5] == round(255 * (0.5 * 0.4 + 0.5 * math.cos(math.pi / 4)))


def test_soft_shadows_from_an_area_light_are_reproducible():
    floor = quad([(-3, -3, 0), (3, -3, 0), (3, 3, 0), (-3, 3, 0)])
    blocker = quad([(-0.5, -0.5, 1), (0.5, -0.5, 1), (0.5, 0.5, 1), (-0.5, 0.5, 1)])
    area = L.AreaLight((-1, -1, 3), (2, 0, 0), (0, 2, 0), intensity=1.0, samples=4)
    mats = [L.Material(ka=0.0, kd=1.0, ks=0, color="white"), L.Material(color="black")]
    cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
                    projection=sl.projection.orthographic(window=(-3, -3, 3, 3)))
    shots = []
    for seed in (0, 0, 1):
        fb = sl.FrameBuffer(61, 61, mode="L", background="black")
        sl.render(fb, [floor, blocker], cam, method="ray-tracing", materials=mats,
                  lights=[area], shading="phong", gamma=1, seed=seed)
        shots.append(fb.to_array().astype(int))
    assert np.array_equal(shots[0], shots[1])
    assert not np.array_equal(shots[0], shots[2])
    # x = 0.7 (column 37) beside the blocker's edge at 0.5: a point light at the area
    # light's center (height 3) puts it in full shadow (the edge's shadow reaches 0.5 x
    # 3 / 2 = 0.75); the area light lights part of it: a penumbra
    row = shots[0][30]
    assert 0 < row[37] < 0.6 * row[43]
    assert row[36] < row[39] < row[42]              # rising across the penumbra
    fb = sl.FrameBuffer(61, 61, mode="L", background="black")
    sl.render(fb, [floor, blocker], cam, method="ray-tracing", materials=mats,
              lights=[L.PointLight((0, 0, 3))], shading="phong", gamma=1)
    assert fb.to_array()[30, 37] == 0


@pytest.mark.parametrize("value", [0, 65, 10**6, -1, 2.5, float("nan"), True])
def test_bad_max_depth(value):
    meshes, cam, mats, lights = scene_without_shadows()
    with pytest.raises(ArgumentValueError, match="max_depth"):
        sl.render(sl.FrameBuffer(8, 8), meshes, cam, method="ray-tracing", max_depth=value)


def test_bad_seed_and_options_of_other_methods():
    meshes, cam, _, _ = scene_without_shadows()
    with pytest.raises(ArgumentValueError, match="seed"):
        sl.render(sl.FrameBuffer(8, 8), meshes, cam, method="ray-tracing", seed=-1)
    with pytest.raises(ArgumentValueError, match="max_depth"):
        sl.render(sl.FrameBuffer(8, 8), meshes, cam, method="z-buffer", max_depth=3)


@pytest.mark.parametrize("value", [0, -1.5, float("nan"), float("inf")])
def test_bad_refractive_index(value):
    with pytest.raises(ArgumentValueError, match="refractive_index"):
        L.Material(transparency=0.5, refractive_index=value)


def test_deep_glass_is_bounded():
    """A glass sphere inside a glass sphere at the deepest tree: the ray budget per
    sample keeps it finite."""
    meshes = [sl.mesh.sphere(1.0, resolution=12), sl.mesh.sphere(0.6, resolution=12)]
    mats = L.Material(ka=0, kd=0, ks=0, transparency=1.0, refractive_index=2.4)
    fb = sl.FrameBuffer(24, 24, background="white")
    r = sl.render(fb, meshes, ortho(1.2), method="ray-tracing", materials=mats,
                  shading="phong", max_depth=64)
    assert (r.faces >= 0).sum() > 100


def test_supersampled_mirror_brings_the_frame_buffers_background():
    """With antialias=n the samples are traced on a finer frame buffer: rays that leave
    the scene still bring the frame buffer's own background."""
    mirror = quad([(-1, -1, 1), (1, -1, -1), (1, 1, -1), (-1, 1, 1)])
    fb = sl.FrameBuffer(9, 9, background=(0, 120, 240))
    sl.render(fb, mirror, ortho(), method="ray-tracing", shading="phong", gamma=1,
              materials=L.Material(ka=0, kd=0, ks=0, reflectivity=1.0),
              lights=[L.AmbientLight(1.0)], antialias=2)
    assert (fb.to_array() == [0, 120, 240]).all()


def test_example_scene_glass_spheres_renders():
    scene = sl.scene.load(os.path.join(os.path.dirname(sl.__file__), "data", "scenes",
                                       "glass_spheres.toml"))
    assert scene.canvas.shading.options["method"] == "ray-tracing"
    assert scene.canvas.shading.options["max_depth"] == 6


def test_too_many_shadow_rays_is_an_error_naming_lights():
    meshes, cam, mats, _ = scene_without_shadows()
    many = [L.PointLight((0, 5, i)) for i in range(1025)]
    with pytest.raises(ArgumentValueError, match="lights"):
        sl.render(sl.FrameBuffer(8, 8), meshes, cam, method="ray-tracing", lights=many)


@pytest.mark.parametrize("case", ["empty", "mode-1", "huge", "inside-glass", "culled"])
def test_hostile_scenes_give_a_picture_or_a_clear_error(case):
    cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
    glass = L.Material(transparency=1.0, refractive_index=1.5, ka=0, kd=0)
    if case == "empty":
        r = sl.render(sl.FrameBuffer(8, 8), [], cam, method="ray-tracing")
        assert (r.faces == -1).all()
    elif case == "mode-1":
        with pytest.raises(ArgumentValueError, match="mode"):
            sl.render(sl.FrameBuffer(8, 8, mode="1"), sl.mesh.cube(), cam, method="ray-tracing")
    elif case == "huge":
        big = sl.mesh.cube(1e60)
        fb = sl.FrameBuffer(16, 16)
        sl.render(fb, big, sl.Camera(eye=(0, 0, 5e60), target=(0, 0, 0)), materials=glass,
                  method="ray-tracing", max_depth=64)
    elif case == "inside-glass":
        fb = sl.FrameBuffer(16, 16, background="white")
        r = sl.render(fb, sl.mesh.sphere(3.0, resolution=12), sl.Camera(eye=(0, 0, 0.5),
                      target=(0, 0, 0)), materials=glass, method="ray-tracing", max_depth=64)
        assert (r.faces >= 0).all()
    else:
        fb = sl.FrameBuffer(16, 16)
        sl.render(fb, [sl.mesh.cube(), sl.mesh.sphere(0.3, center=(0, 0, 1))], cam,
                  method="ray-tracing", cull_back_faces=True,
                  materials=[L.Material(reflectivity=1.0), L.Material()])


@pytest.mark.parametrize("projection", [None, "orthographic", "oblique"])
def test_primary_rays_pass_through_the_points_the_camera_projects_there(projection):
    from scanline.raytrace.render import primary_rays
    from scanline.screen import prepare

    kind = {None: {}, "orthographic": {"projection": sl.projection.orthographic(
        window=(-3, -3, 3, 3))}, "oblique": {"projection": sl.projection.oblique(
            "cabinet", window=(-3, -3, 3, 3))}}[projection]
    cam = sl.Camera(eye=(1, 2, 6), target=(0, 0, 0), **kind)
    scene = prepare(sl.mesh.cube(), cam, 64, 48)
    rng = np.random.default_rng(4)
    points = rng.uniform(-1, 1, (50, 3))
    device = cam.project(points, 64, 48)
    o, d = primary_rays(scene, device[:, 0], device[:, 1])
    to = points - o
    along = (to * d).sum(axis=1)
    assert (along > 0).all()                                  # ahead of the origin
    assert np.allclose(to - along[:, None] * d, 0, atol=1e-9)  # on the ray


def test_an_environment_map_gives_way_to_the_reflected_rays():
    """A mirror with an environment map: ray traced, its pixels are what its reflected
    rays meet (the red wall), not the map (green) plus the wall."""
    mirror = quad([(-1, -1, 1), (1, -1, -1), (1, 1, -1), (-1, 1, 1)])
    wall = quad([(3, -5, -5), (3, -5, 5), (3, 5, 5), (3, 5, -5)])
    sky = np.zeros((8, 16, 3))
    sky[...] = (0.0, 1.0, 0.0)
    mats = [L.Material(ka=0, kd=0, ks=0, reflectivity=1.0, environment=sl.Texture(sky)),
            L.Material(ka=1.0, kd=0, ks=0, color=(200, 40, 40))]
    fb = sl.FrameBuffer(21, 21, background="black")
    sl.render(fb, [mirror, wall], ortho(), method="ray-tracing", materials=mats,
              lights=[L.AmbientLight(1.0)], shading="phong", gamma=1)
    assert fb.to_array()[10, 10].tolist() == [200, 40, 40]
