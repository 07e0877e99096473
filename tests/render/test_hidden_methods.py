"""sl.render by the polygon methods (painter, depth sort, BSP tree, scan-line, area
subdivision), shaded: against the plain-Python per-pixel reference
of tests/render/test_render.py and against the depth buffer's image."""

import numpy as np
import pytest

import scanline as sl
from scanline.screen import prepare

from .test_render import H, W, camera, random_scene, reference_faces

#: Methods that resolve intersecting and cyclically overlapping faces (by splitting,
#: or per pixel); area subdivision and the painter's one-key sort are tested on
#: scenes without them.
RESOLVING = ("depth-sort", "bsp", "scan-line")


def separate_scene(rng, n=10):
    """Random triangles, each in its own depth slab: no two intersect or overlap
    cyclically."""
    tris = rng.uniform(-2, 2, size=(n, 3, 3))
    for i in range(n):
        tris[i, :, 2] = -2 + 0.4 * i + rng.uniform(0, 0.3, 3)
    return sl.mesh.Mesh(tris.reshape(-1, 3), np.arange(3 * n).reshape(n, 3))


def mismatches(mesh, method, cam):
    scene = prepare(mesh, cam, W, H)
    ref, gap = reference_faces(scene)
    clear = gap > 1e-6                            # ties on shared points excluded
    r = sl.render(sl.FrameBuffer(W, H), mesh, cam, method=method)
    return int((r.faces[clear] != ref[clear]).sum()), int((ref >= 0).sum())


@pytest.mark.parametrize("method", RESOLVING)
@pytest.mark.parametrize("seed", [1, 2])
def test_resolving_methods_agree_with_the_reference_on_intersecting_faces(method, seed):
    bad, covered = mismatches(random_scene(np.random.default_rng(seed)), method, camera())
    assert covered > 200
    assert bad == 0, (method, bad)


@pytest.mark.parametrize("method", RESOLVING + ("painter", "area-subdivision"))
@pytest.mark.parametrize("seed", [3, 4])
def test_every_method_agrees_on_separate_faces(method, seed):
    bad, covered = mismatches(separate_scene(np.random.default_rng(seed)), method, camera())
    assert covered > 200
    assert bad == 0, (method, bad)


def test_shaded_images_equal_the_depth_buffers():
    meshes = [sl.mesh.cube(), sl.mesh.sphere(0.6, (0.8, 0.5, 0.8))]
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0))
    images = {}
    for method in ("z-buffer",) + RESOLVING + ("area-subdivision",):
        fb = sl.FrameBuffer(64, 48)
        sl.render(fb, meshes, cam, method=method, shading="phong")
        images[method] = np.asarray(fb).astype(int)
    assert (images["z-buffer"].sum(axis=2) > 0).sum() > 500
    for method, image in images.items():
        # the sphere pierces the cube: the face buffers agree off the intersection
        # curve, where equal depths make either face right
        assert (np.abs(image - images["z-buffer"]).max(axis=2) > 2).sum() <= 4, method


def test_the_painters_one_key_sort_fails_where_depth_sort_does_not():
    # two long strips crossing each other in depth (each in front of the other at one
    # end): one key per polygon cannot order them, depth sort splits one
    a = [(-2, -0.3, -1), (2, -0.3, 1), (2, 0.3, 1), (-2, 0.3, -1)]
    b = [(-0.3, -2, 1), (0.3, -2, 1), (0.3, 2, -1), (-0.3, 2, -1)]
    mesh = sl.mesh.Mesh(np.array(a + b, float), [[0, 1, 2, 3], [4, 5, 6, 7]])
    cam = camera(eye=(0.0, 0.0, 6.0))
    bad_painter, _ = mismatches(mesh, "painter", cam)
    bad_sort, covered = mismatches(mesh, "depth-sort", cam)
    assert covered > 100
    assert bad_sort == 0 and bad_painter > 0


def test_object_and_image_precision_are_stated():
    from scanline.visible import METHODS, PRECISION

    assert set(PRECISION) == set(METHODS)
    assert {PRECISION[m] for m in ("painter", "depth-sort", "bsp")} == {"object"}
    assert {PRECISION[m] for m in ("scan-line", "area-subdivision", "z-buffer", "a-buffer",
                                   "ray-casting")} == {"image"}
