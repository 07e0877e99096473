"""Ray casting's work is bounded by its bounding rectangles: a 10k-triangle scene
with triangles outside the raster bins each triangle into the tiles its box meets
and nothing more (a regression: the row range of an empty box was left
uninitialized, and binning looped over garbage rows for hours)."""

import math

import numpy as np

import scanline as sl
from scanline._kernels import raycast as k
from scanline.screen import prepare

W, H = 320, 200


def spheres():
    rng = np.random.default_rng(7)
    # 44 spheres of 240 triangles, several partly or wholly outside the window
    return [sl.mesh.sphere(0.5, center=tuple(rng.uniform(-5, 5, 3)), resolution=(24, 6))
            for _ in range(44)]


def expected_pairs(tri):
    """Per triangle, the number of TILE x TILE tiles its pixel box (clamped to the
    raster) meets; 0 for a box outside the raster."""
    lo, hi = tri[..., :2].min(axis=1), tri[..., :2].max(axis=1)
    c0 = np.clip(np.floor(lo[:, 0]), 0, None)
    c1 = np.clip(np.ceil(hi[:, 0]), None, W - 1)
    r0 = np.clip(np.floor(lo[:, 1]), 0, None)
    r1 = np.clip(np.ceil(hi[:, 1]), None, H - 1)
    empty = (c0 > c1) | (r0 > r1)
    count = ((c1.astype(int) // k.TILE - c0.astype(int) // k.TILE + 1)
             * (r1.astype(int) // k.TILE - r0.astype(int) // k.TILE + 1))
    return np.where(empty, 0, count)


def test_ray_casting_bins_each_triangle_into_its_own_tiles_only():
    scene = prepare(spheres(), sl.Camera(eye=(0, 0, 9), target=(0, 0, 0)), W, H)
    tri = np.ascontiguousarray(scene.triangles)
    n = len(tri)
    assert n >= 10_000
    per = expected_pairs(tri)
    assert (per == 0).sum() > 100           # triangles outside the raster are there
    boxes = np.full((n, 4), 2 ** 40, np.int64)   # what an uninitialized array may hold
    pairs = k.tile_boxes(tri, W, H, boxes)
    assert pairs == per.sum()
    # the loops of bin_tiles: rows x columns of each non-empty box, nothing for an empty
    cols = boxes[:, 2] - boxes[:, 0] + 1
    rows = boxes[:, 3] - boxes[:, 1] + 1
    live = cols > 0
    assert (rows[~live] <= 0).all() and (per[~live] == 0).all()
    assert (rows[live] * cols[live]).sum() == pairs
    tiles_x = ((W - 1) >> k.TILE_SHIFT) + 1
    tiles_y = ((H - 1) >> k.TILE_SHIFT) + 1
    assert boxes[live, 2].max() < tiles_x and boxes[live, 3].max() < tiles_y
    # triangle tests made by the rays: TILE^2 per (triangle, tile) pair, a small
    # multiple of the scene's own size here (each tiny triangle meets 1-4 tiles)
    assert pairs * k.TILE * k.TILE <= 4 * n * k.TILE * k.TILE
    starts = np.empty(tiles_x * tiles_y + 1, np.int64)
    order = np.empty(pairs, np.int64)
    k.bin_tiles(boxes, tiles_x, starts, order)
    assert starts[-1] == pairs
    assert np.array_equal(np.bincount(order, minlength=n), per)


def test_ray_casting_a_10k_scene_matches_the_z_buffer():
    meshes = spheres()
    cam = sl.Camera(eye=(0, 0, 9), target=(0, 0, 0))
    a = sl.render(sl.FrameBuffer(W, H), meshes, cam, method="ray-casting")
    b = sl.render(sl.FrameBuffer(W, H), meshes, cam, method="z-buffer")
    assert (a.faces >= 0).sum() > 1000
    assert np.array_equal(a.faces, b.faces)
