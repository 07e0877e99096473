"""Solids drawn by sl.render: a sphere solid's silhouette against the z-buffer of a
fine tessellated sphere, its Lambert shading against the closed form, occlusion with
meshes both ways, the classic CSG tree's holes, solids refused by methods that do
not cast rays."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentValueError

S = sl.solids
L = sl.lighting


def ring(mask):
    """The pixels within one pixel (8-neighbourhood) of the mask's boundary."""
    p = np.pad(mask, 1, mode="edge")
    h, w = mask.shape
    shifted = [p[1 + dy:1 + dy + h, 1 + dx:1 + dx + w] for dy in (-1, 0, 1) for dx in (-1, 0, 1)]
    return np.any([s != mask for s in shifted], axis=0)


def test_sphere_silhouette_agrees_with_a_fine_tessellated_sphere_within_one_pixel():
    cam = sl.Camera(eye=(0.7, 1.1, 4.0), target=(0.1, 0, 0))
    a = sl.FrameBuffer(120, 90, mode="RGB")
    r_solid = sl.render(a, S.Sphere((0.2, 0.1, 0), 1.2), cam, method="ray-casting")
    b = sl.FrameBuffer(120, 90, mode="RGB")
    r_mesh = sl.render(b, sl.mesh.sphere(1.2, center=(0.2, 0.1, 0), resolution=(256, 128)),
                       cam, method="z-buffer")
    ours, ref = r_solid.solids >= 0, r_mesh.faces >= 0
    assert 2000 < ours.sum() < 0.9 * ours.size
    differ = ours != ref
    assert not (differ & ~ring(ref)).any()
    assert differ.sum() < 0.05 * ring(ref).sum()


def test_lambert_shading_of_a_sphere_solid_follows_the_normal():
    # orthographic view down -z, a directional light along the view: I = kd cos = n_z
    cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
                    projection=sl.projection.orthographic(window=(-1.5, -1.5, 1.5, 1.5)))
    fb = sl.FrameBuffer(31, 31, mode="L")
    white = L.Material(ka=0.0, kd=1.0, ks=0.0, color="white")
    r = sl.render(fb, S.Sphere((0, 0, 0), 1.0, material=white), cam, method="ray-casting",
                  lights=[L.DirectionalLight(direction=(0, 0, -1))], gamma=1.0)
    clip, scale, offset = cam.mapping(cam._device_box(31, 31))
    # device x, y of world (x, y): linear; its inverse for pixel centers
    xs = ((np.arange(31) - offset[0]) / scale[0] - clip[0, 3]) / clip[0, 0]
    ys = ((np.arange(31) - offset[1]) / scale[1] - clip[1, 3]) / clip[1, 1]
    gx, gy = np.meshgrid(xs, ys)
    rho2 = gx ** 2 + gy ** 2
    inside = rho2 < 1 - 1e-9
    expect = np.round(255 * np.sqrt(np.clip(1 - rho2, 0, None)))
    values = fb._raster()[0][..., 0].astype(float)          # rows bottom-up, as ys
    assert np.array_equal(r.solids >= 0, inside)
    assert np.abs(values[inside] - expect[inside]).max() <= 1


def test_solids_and_meshes_hide_each_other():
    cam = sl.Camera(eye=(0, 0, 6), target=(0, 0, 0))
    front = sl.mesh.Mesh([(-0.3, -0.3, 2), (0.3, -0.3, 2), (0.3, 0.3, 2), (-0.3, 0.3, 2)],
                         [(0, 1, 2, 3)])
    behind = sl.mesh.cube(1.0, center=(0, 0, -3))
    fb = sl.FrameBuffer(41, 41, mode="RGB")
    r = sl.render(fb, [front, S.Sphere((0, 0, 0), 1.0), behind], cam, method="ray-casting")
    assert r.faces[20, 20] >= 0 and r.solids[20, 20] == -1       # the quad in front
    assert r.solids[20, 28] == 0 and r.faces[20, 28] == -1       # the sphere over the cube
    assert (r.meshes == 1).sum() == 0                             # the cube is all hidden
    depth = r.depth.to_array()[::-1]                              # rows bottom-up
    assert np.array_equal(np.isfinite(depth), (r.solids >= 0) | (r.faces >= 0))
    assert depth[20, 20] < depth[20, 28]                          # the quad nearer


def test_the_classic_csg_tree_has_holes_through_it():
    box = S.Box((-1, -1, -1), (1, 1, 1))
    ball = S.Sphere((0, 0, 0), 1.35)
    holes = sl.csg.union(*[S.Cylinder((0, 0, 0), 0.5, 3.0, axis=a)
                           for a in ((1, 0, 0), (0, 1, 0), (0, 0, 1))])
    tree = (box & ball) - holes
    cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
                    projection=sl.projection.orthographic(window=(-1.5, -1.5, 1.5, 1.5)))
    fb = sl.FrameBuffer(31, 31, mode="RGB")
    r = sl.render(fb, tree, cam, method="ray-casting")
    assert r.solids[15, 15] == -1                         # straight through the z hole
    assert r.solids[15, 24] == 0                          # the box's face beside it
    assert tree.contains([(0, 0, 0)]).tolist() == [False]


def test_antialiased_edges_and_a_camera_inside_a_solid():
    cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
    fb = sl.FrameBuffer(40, 40, mode="L", background="black")
    sl.render(fb, S.Sphere((0, 0, 0), 1.0), cam, method="ray-casting", antialias=3,
              shading="none")
    values = np.unique(fb._raster()[0])
    assert len(values) > 3 and values.min() == 0 and values.max() == 255
    fb = sl.FrameBuffer(20, 20, mode="L")
    r = sl.render(fb, S.Sphere((0, 0, 5), 3.0), cam, method="ray-casting")
    assert (r.solids == 0).all()                          # the inside of the ball seen


@pytest.mark.parametrize("method", ["z-buffer", "scan-line", "painter", "a-buffer"])
def test_methods_that_do_not_cast_rays_refuse_solids(method):
    fb = sl.FrameBuffer(8, 8, mode="RGB")
    with pytest.raises(ArgumentValueError, match="ray-casting"):
        sl.render(fb, [S.Sphere(), sl.mesh.cube()], sl.Camera(eye=(0, 0, 5), target=(0, 0, 0)),
                  method=method)


def ortho(size=31):
    cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
                    projection=sl.projection.orthographic(window=(-1.5, -1.5, 1.5, 1.5)))
    clip, scale, offset = cam.mapping(cam._device_box(size, size))
    world_x = ((np.arange(size) - offset[0]) / scale[0] - clip[0, 3]) / clip[0, 0]
    return cam, world_x


def test_ray_traced_mirror_sphere_solid_reflects_a_wall_at_the_mirror_angle():
    # orthographic rays down -z meet the unit sphere at normal (x, 0, sqrt(1 - x^2));
    # at x = 1/sqrt(2) the mirror direction is +x exactly, onto a wall at x = 3 lit by
    # ambient light alone: the pixel shows the wall's color; at the center the ray
    # goes straight back and leaves the scene: the background
    cam, wx = ortho(41)
    mirror = L.Material(ka=0.0, kd=0.0, ks=0.0, reflectivity=1.0)
    wall = sl.mesh.Mesh([(3, -9, -9), (3, 9, -9), (3, 9, 9), (3, -9, 9)], [(0, 1, 2, 3)])
    fb = sl.FrameBuffer(41, 41, mode="RGB", background=(10, 20, 30))
    r = sl.render(fb, [wall, S.Sphere((0, 0, 0), 1.0, material=mirror)], cam,
                  method="ray-tracing", materials=L.Material(ka=1.0, kd=0, ks=0,
                                                             color=(200, 120, 40)),
                  lights=[L.AmbientLight(1.0)])
    px = fb._raster()[0]
    at45 = int(np.argmin(np.abs(wx - 1 / math.sqrt(2))))
    assert r.solids[20, at45] == 0 and r.solids[20, 20] == 0
    assert np.abs(px[20, at45].astype(int) - [200, 120, 40]).max() <= 1
    assert px[20, 20].tolist() == [10, 20, 30]
    # the same sphere by ray casting shows its own (black) local color there
    fb2 = sl.FrameBuffer(41, 41, mode="RGB", background=(10, 20, 30))
    sl.render(fb2, [wall, S.Sphere((0, 0, 0), 1.0, material=mirror)], cam,
              method="ray-casting", lights=[L.AmbientLight(1.0)])
    assert fb2._raster()[0][20, at45].tolist() == [0, 0, 0]


def test_a_solid_casts_a_ray_traced_shadow_on_a_mesh():
    # a point light straight above a small box above the floor; the eye between box
    # and floor sees the floor only: under the box, ambient light alone
    floor = sl.mesh.Mesh([(-3, -3, -1), (3, -3, -1), (3, 3, -1), (-3, 3, -1)], [(0, 1, 2, 3)])
    blocker = S.Box((-0.25, -0.25, 2.0), (0.25, 0.25, 2.5))
    m = L.Material(ka=1.0, kd=0.5, ks=0.0, color="white")
    lights = [L.AmbientLight(0.2), L.PointLight((0, 0, 4.5))]
    fb = sl.FrameBuffer(31, 31, mode="L")
    cam = sl.Camera(eye=(0, -0.01, 1.9), target=(0, 0, -1))
    r = sl.render(fb, [floor, blocker], cam, method="ray-tracing", materials=m, lights=lights,
                  gamma=1.0, shading="phong")
    px = fb._raster()[0][..., 0]
    assert (r.solids == -1).all() and (r.faces >= 0).all()
    assert px[15, 15] == round(255 * 0.2)            # under the box: ambient only
    assert px[15, 1] > px[15, 15] + 60                # beyond its shadow: lit
