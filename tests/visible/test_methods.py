"""Every visible-surface method against ray casting at pixel centers."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.visible import (ScreenPolygons, area_subdivision, depth_sort, painter,
                              scan_line)
from scanline.shading import paint
from scanline.visible.visibility import piece_numbers
from tests.reference import lit

from .reference import ray_cast

W, H = 40, 30


def random_scene(rng, n=7, intersecting=False):
    """Random convex polygons (quads and triangles) in device space; without
    ``intersecting``, each lies in its own depth slab, so none intersect."""
    polys = []
    slabs = rng.permutation(n)
    for i in range(n):
        c = rng.uniform(0, [W, H])
        r = rng.uniform(4, 14)
        k = int(rng.integers(3, 6))
        ang = np.sort(rng.uniform(0, 2 * np.pi, k))
        xy = c + r * np.c_[np.cos(ang), np.sin(ang) * rng.uniform(0.5, 1.5)]
        tilt = rng.uniform(-0.02, 0.02, 2)
        if intersecting:
            z0 = rng.uniform(0.3, 0.7)
            tilt = rng.uniform(-0.03, 0.03, 2)
            z = z0 + tilt[0] * (xy[:, 0] - c[0]) + tilt[1] * (xy[:, 1] - c[1])
        else:
            lo = (slabs[i] + 0.05) / n
            hi = (slabs[i] + 0.95) / n
            z = lo + (hi - lo) * rng.uniform(0, 1) + 0 * xy[:, 0]
            span = (xy[:, 0] - xy[:, 0].min()) / (np.ptp(xy[:, 0]) or 1.0)
            z = lo + (hi - lo) * span * rng.uniform(0, 1)
            z = z + 0 * tilt[0]
        polys.append(np.c_[xy, z])
    return polys


def faces_of(result, width=W, height=H):
    """Face index per pixel of a method's result (object order: painted in order)."""
    if isinstance(result, ScreenPolygons):
        fb = sl.FrameBuffer(width, height, mode="RGB", background="black")
        n = int(result.face.max()) + 2 if len(result) else 1
        values = np.array([[(f + 1) % 256, (f + 1) // 256, 0] for f in range(n)], np.uint8)
        paint(fb, piece_numbers(result), values[result.face])
        buf = fb._raster()[0].astype(np.int64)
        return buf[:, :, 0] + 256 * buf[:, :, 1] - 1
    return result.face


def compare(result, polys, faces=None):
    faces = list(range(len(polys))) if faces is None else faces
    ref, tie = ray_cast([p.tolist() for p in polys], faces, W, H)
    got = faces_of(result)
    bad = [(x, y, got[y, x], ref[y][x]) for y in range(H) for x in range(W)
           if not tie[y][x] and got[y, x] != ref[y][x]]
    return bad


METHODS = {"depth-sort": depth_sort, "scan-line": scan_line,
           "area-subdivision": area_subdivision}


@pytest.mark.parametrize("seed", range(8))
@pytest.mark.parametrize("method", sorted(METHODS))
def test_random_scenes_without_intersections(method, seed):
    polys = random_scene(np.random.default_rng(seed))
    sp = ScreenPolygons.from_device(polys, W, H)
    assert compare(METHODS[method](sp), polys) == []


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("method", sorted(METHODS))
def test_random_scenes_with_intersections(method, seed):
    polys = random_scene(np.random.default_rng(100 + seed), n=5, intersecting=True)
    sp = ScreenPolygons.from_device(polys, W, H)
    assert compare(METHODS[method](sp), polys) == []


def test_painter_fails_where_depth_sort_succeeds():
    # a long tilted quad whose far end is behind a small square but whose near end
    # covers it: by greatest depth the long one is painted first, then hidden.
    long = np.array([[2, 10, 0.1], [38, 10, 0.9], [38, 20, 0.9], [2, 20, 0.1]], float)
    small = np.array([[5, 5, 0.5], [12, 5, 0.5], [12, 25, 0.5], [5, 25, 0.5]], float)
    polys = [long, small]
    sp = ScreenPolygons.from_device(polys, W, H)
    assert len(compare(painter(sp), polys)) > 20
    assert compare(depth_sort(sp), polys) == []


def scene_meshes(rng):
    meshes = []
    for _ in range(3):
        c = rng.uniform(-1.2, 1.2, 3)
        meshes.append(sl.mesh.box(tuple(c - rng.uniform(0.2, 0.6, 3)),
                                  tuple(c + rng.uniform(0.2, 0.6, 3))))
    return meshes


@pytest.mark.parametrize("seed", range(3))
def test_bsp_any_eye_agrees_with_ray_casting(seed):
    rng = np.random.default_rng(seed)
    meshes = scene_meshes(rng)       # boxes may intersect: the tree splits them
    tree = sl.visible.BSPTree(meshes)
    for eye in [(5, 3, 6), (-6, 2, -4), (1, -7, 2)]:
        cam = sl.Camera(eye=eye, target=(0, 0, 0),
                        projection=sl.projection.perspective(fov=math.radians(50), near=1))
        sp = sl.visible.screen_polygons(meshes, cam, W, H)
        polys = [sp.polygon(p) for p in range(len(sp))]
        pieces = sl.visible.bsp(tree, cam, W, H)
        assert compare(pieces, polys, sp.face.tolist()) == []


def test_bsp_parallel_projection():
    meshes = scene_meshes(np.random.default_rng(7))
    cam = sl.Camera(target=(0, 0, 0), projection=sl.projection.isometric(window=(-2, -2, 2, 2)))
    sp = sl.visible.screen_polygons(meshes, cam, W, H)
    polys = [sp.polygon(p) for p in range(len(sp))]
    assert compare(sl.visible.bsp(meshes, cam, W, H), polys, sp.face.tolist()) == []


@pytest.mark.parametrize("method", sorted(sl.visible.METHODS))
def test_render_every_method_same_image(method):
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0),
                    projection=sl.projection.perspective(fov=0.8, near=1))
    meshes = [sl.mesh.cube(), sl.mesh.sphere(0.6, (0.8, 0.5, 0.8), resolution=8)]
    colors = [(i * 7 % 256, i * 13 % 256, 200) for i in range(6 + 32)]
    ref = sl.FrameBuffer(60, 45)
    sl.render(ref, meshes, cam, method="scan-line", shading="none", colors=colors)
    fb = sl.FrameBuffer(60, 45)
    sl.render(fb, meshes, cam, method=method, shading="none", colors=colors,
              **({"samples": 1} if method == "a-buffer" else {}))
    differ = int((fb.to_array() != ref.to_array()).any(axis=2).sum())
    if method == "painter":
        assert differ > 0          # the sphere pierces the cube: one key cannot do it
    else:
        assert differ == 0


def test_scan_line_compares_depths_only_where_spans_overlap():
    a = np.array([[0, 0, 0.5], [10, 0, 0.5], [10, 10, 0.5], [0, 10, 0.5]], float)
    b = np.array([[20, 0, 0.2], [30, 0, 0.2], [30, 10, 0.2], [20, 10, 0.2]], float)
    assert scan_line(ScreenPolygons.from_device([a, b], W, H)).compared == 0
    c = np.array([[5, 0, 0.2], [15, 0, 0.2], [15, 10, 0.2], [5, 10, 0.2]], float)
    r = scan_line(ScreenPolygons.from_device([a, c], W, H))
    assert r.compared == 5 * 10          # columns 5..9 on scan lines 1..10


def test_warnock_cases_recorded():
    a = np.array([[-5, -5, 0.5], [50, -5, 0.5], [50, 40, 0.5], [-5, 40, 0.5]], float)
    b = np.array([[3, 3, 0.2], [9, 3, 0.2], [9, 9, 0.2], [3, 9, 0.2]], float)
    r = area_subdivision(ScreenPolygons.from_device([a], W, H), record=10)
    assert r.areas == 1 and r.regions[0, 4] == 2 - 1     # one polygon, surrounding
    r = area_subdivision(ScreenPolygons.from_device([a, b], W, H), record=1000)
    assert set(r.regions[:, 4].tolist()) >= {1, 2}
    assert (r.face == np.where(np.isin(np.arange(W)[None], range(3, 9))
                               & np.isin(np.arange(H)[:, None], range(4, 10)), 1, 0)).all()


@pytest.mark.parametrize("tri", [[(1.07374182e9, 1.0, 0.0), (0.0, -1e300, 0.0), (0.0, 0.0, 0.0)],
                                 [(3.0, 1e300, 0.5), (12.0, 2.0, 0.5), (-1e300, 5.0, 0.5)]])
def test_scan_line_method_takes_crossings_beyond_the_integers(tri):
    # an edge whose crossing overflows to inf (or a scan-line bound beyond int64) was
    # converted to an integer unclamped: undefined in compiled code, and it crashed
    # the interpreter; the spans are the 2-D fill's, as for any triangle
    v = np.array(tri)
    result = scan_line(ScreenPolygons.from_device([v], 16, 12))
    fb = sl.FrameBuffer(16, 12, mode="1")
    sl.draw.polygon(fb, v[:, :2], color=1)
    assert {(x, y) for y, x in zip(*np.nonzero(result.face >= 0))} == lit(fb)
