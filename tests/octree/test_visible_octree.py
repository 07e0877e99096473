"""The octree visible-surface method (H&B 13-10) against the z-buffer: the same
picture, pixel for pixel."""

import numpy as np
import pytest

import scanline as sl
from scanline.octree import Octree


def render_both(meshes, cam, width=96, height=72, max_depth=None):
    out = {}
    for method in ("z-buffer", "octree"):
        fb = sl.FrameBuffer(width, height, mode="RGB")
        extra = {"max_depth": max_depth} if method == "octree" else {}
        r = sl.render(fb, meshes, cam, method=method, **extra)
        out[method] = (fb.to_array(), r.faces)
    return out["z-buffer"], out["octree"]


CAMERAS = [
    sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)),
    sl.Camera(eye=(-2, 3, -3), target=(0, 0, 0),
              projection=sl.projection.orthographic(window=(-2, -1.5, 2, 1.5))),
    sl.Camera(eye=(0.2, 0.3, 0.5), target=(0, 0, 0)),               # inside the scene
]


@pytest.mark.parametrize("cam", CAMERAS)
def test_an_octree_of_a_csg_solid_renders_as_by_the_z_buffer(cam):
    solid = sl.csg.difference(sl.solids.Sphere(radius=1.0),
                              sl.solids.Box((0, 0, 0), (1.2, 1.2, 1.2)))
    tree = Octree.from_solid(solid, 4)
    (zimage, zfaces), (oimage, ofaces) = render_both(tree, cam)
    assert (zfaces >= 0).sum() > 500
    assert (zimage == oimage).all() and (zfaces == ofaces).all()


@pytest.mark.parametrize("seed", range(3))
def test_random_cubes_and_spheres_render_as_by_the_z_buffer(seed):
    rng = np.random.default_rng(seed)
    meshes = []
    for _ in range(12):
        shape = sl.mesh.cube(rng.uniform(0.2, 0.8)) if rng.random() < 0.5 \
            else sl.mesh.sphere(rng.uniform(0.1, 0.5))
        meshes.append(shape.translated(rng.uniform(-1.5, 1.5, size=3)))
    for depth in (1, 3, None):
        (zimage, zfaces), (oimage, ofaces) = render_both(meshes, CAMERAS[0], max_depth=depth)
        assert (zfaces == ofaces).all() and (zimage == oimage).all()


def test_an_empty_view_and_a_scene_outside_it():
    cam = CAMERAS[0]
    far = sl.mesh.cube(1).translated((50, 0, 0))
    (_, zfaces), (_, ofaces) = render_both(far, cam)
    assert (ofaces == -1).all() and (zfaces == -1).all()


def test_octree_is_a_registered_image_method():
    method = sl.visible.METHODS["octree"]
    assert method.precision == "image" and "max_depth" in method.options
