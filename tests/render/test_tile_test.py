"""The z-buffer pass's tile test (:func:`scanline._kernels.raster3d.behind`): the
faces turned away from the viewer are drawn last and skipped where they lie behind
every depth of the tiles they meet, and the pixels stay those of drawing every
triangle in input order -- on exact depth ties too (the smaller triangle number
wins, as the first drawn does), whatever the thread count; the bound the test uses
is never above a depth the span loop computes."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline._kernels import _threads
from scanline._kernels import raster3d as k
from scanline.draw.triangles import rasterize
from scanline.screen import prepare
from scanline.visible.zbuffer import nearest


def soup(rng, n, width, height, size, levels):
    """Random triangles whose depths take ``levels`` values (a third of them flat):
    many exact depth ties between overlapping triangles."""
    c = rng.uniform(0, [width, height], size=(n, 1, 2))
    xy = c + rng.uniform(-size, size, size=(n, 3, 2))
    z = rng.integers(0, levels, size=(n, 3, 1)) / levels
    z[::3] = z[::3, :1]
    return np.ascontiguousarray(np.concatenate([xy, z], axis=2))


def id_pass(tri, width, height, order=None, first=None, attributes=False):
    n = len(tri)
    zbuf = np.empty((height, width))
    ids = np.empty((height, width), np.int32)
    att = np.ascontiguousarray(tri[:, :, :2]) if attributes else np.empty((n, 3, 0))
    abuf = np.zeros((height, width, 2)) if attributes else None
    rasterize(width, height, tri, np.ones((n, 3)), att, np.arange(n, dtype=np.int64),
              zbuf=zbuf, abuf=abuf, idbuf=ids, clear=True, order=order, first=first)
    return ids, zbuf, abuf


@pytest.mark.parametrize("threads", [1, 2, 3])
@pytest.mark.parametrize("attributes", [False, True])
def test_drawing_a_part_last_with_the_tile_test_gives_the_input_order_s_pixels(
        threads, attributes, monkeypatch):
    # any part of the triangles drawn last (each part in input order), tile-tested:
    # the same ids, depths and attributes as drawing them all in input order, with
    # thousands of exact ties decided (the depths take four values)
    monkeypatch.setattr(_threads, "threads", lambda: threads)
    rng = np.random.default_rng(11)
    w, h = 150, 110
    tri = soup(rng, 3000, w, h, 14.0, 4)
    want = id_pass(tri, w, h, attributes=attributes)
    last = rng.uniform(size=len(tri)) < 0.6
    order = np.concatenate([np.flatnonzero(~last), np.flatnonzero(last)])
    got = id_pass(tri, w, h, order, int((~last).sum()), attributes)
    assert np.array_equal(got[0], want[0]) and np.array_equal(got[1], want[1])
    if attributes:
        assert np.array_equal(got[2], want[2])
    # the ties were there to decide: without the smaller id winning them, drawing
    # the later part first gives other pixels
    assert (want[0] >= 0).mean() > 0.9
    swapped = np.concatenate([np.flatnonzero(last), np.flatnonzero(~last)])
    plain = np.empty((h, w), np.int32)
    rasterize(w, h, tri[swapped], np.ones((len(tri), 3)), np.empty((len(tri), 3, 0)),
              swapped.astype(np.int64), zbuf=np.empty((h, w)), idbuf=plain, clear=True)
    assert (plain != want[0]).sum() > 100


def test_the_tile_test_skips_what_is_hidden_and_keeps_what_shows():
    # one band, two tiles: the left one covered at depth 0.5, the right one empty
    w, h = 64, 32
    zbuf = np.full((h, w), np.inf)
    zbuf[:, :32] = 0.5
    tiles = np.full(2, np.nan)

    def behind(xs, z):
        return k.behind(zbuf, tiles, 0, h - 1, 5, 20, min(xs), max(xs), xs[0], 5.0, z, 0.0, 0.0)

    assert behind((3.0, 20.0), 0.6)               # behind the left tile: skipped
    assert tiles[0] == 0.5 and math.isnan(tiles[1])       # (the maximum, found once)
    assert not behind((3.0, 20.0), 0.5)           # an equal depth: an id may win the tie
    assert not behind((3.0, 20.0), 0.4)
    assert not behind((20.0, 40.0), 0.6)          # reaches the empty tile
    assert tiles[1] == np.inf
    assert behind((70.0, 90.0), 0.0)              # right of the raster: no pixel at all


def test_the_tile_test_bound_is_below_every_depth_the_spans_compute():
    # the span loop's depths are z' = z - A / C, rounded at every step: on a depth
    # far from 0 that changes little across a long span the rounding outweighs the
    # change, and the least depth a pixel gets is where the steps put it, not where
    # the plane does.  A buffer of one depth just above that least depth (found by
    # drawing the triangle alone) must never let the test skip the triangle.
    rng = np.random.default_rng(3)
    w, h = 256, 32
    for _ in range(300):
        xy = rng.uniform([0, 0], [w, h], size=(3, 2))
        slope = -(10.0 ** rng.uniform(-11, -7)) * rng.choice([-1, 1], p=[0.2, 0.8])
        z = 1e6 * (1 + rng.uniform(-0.5, 0.5)) + slope * xy[:, 0] + 1e-9 * xy[:, 1]
        tri = np.ascontiguousarray(np.concatenate([xy, z[:, None]], axis=1)[None])
        own, depth, _ = id_pass(tri, w, h)
        drawn = own >= 0
        if not drawn.any():
            continue
        g = np.empty((k.SETUP_BATCH, 2, 3))
        ok = np.empty(k.SETUP_BATCH, np.bool_)
        k.planes(tri, np.ones((1, 3)), np.empty((1, 3, 0)), 0, 1, g, ok)
        rows = np.flatnonzero(drawn.any(axis=1))
        buffer = np.full((h, w), np.nextafter(depth[drawn].min(), np.inf))
        assert not k.behind(buffer, np.full(w // 32, np.nan), 0, h - 1, rows[0], rows[-1],
                            xy[:, 0].min(), xy[:, 0].max(), xy[0, 0], xy[0, 1], *g[0, 0])


@pytest.mark.parametrize("reverse", [False, True])
def test_the_z_buffer_pass_gives_the_input_order_s_pixels(reverse):
    # a closed surface (its hidden back faces skipped) and a two-sided sheet whose
    # front and back faces tie at every pixel: the pass equals drawing every
    # triangle in input order (select: no reordering)
    sheet = sl.mesh.Mesh([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]],
                         [[0, 1, 2], [0, 2, 3], [0, 2, 1], [0, 3, 2]][::-1 if reverse else 1])
    teapot = sl.mesh.teapot(6)
    cam = sl.Camera(eye=(0.4, 2.0, 3.5), target=(0, 0.3, 0))
    for mesh in (sheet, teapot):
        scene = prepare(mesh, cam, 160, 120)
        front = scene.front[scene.facet]
        assert front.any() and not front.all()
        got = nearest(scene)
        want = nearest(scene, select=np.arange(len(scene.triangles)))
        assert np.array_equal(got.ids, want.ids) and np.array_equal(got.depth, want.depth)
        assert (got.ids >= 0).sum() > 1000


def test_a_drawing_order_without_an_id_buffer_is_refused():
    # only ids can break the depth ties the way input order would: a frame buffer
    # (or depth peeling) with a reordered draw is an error, not other pixels
    tri = soup(np.random.default_rng(1), 4, 20, 20, 5.0, 4)
    with pytest.raises(ValueError, match="id buffer"):
        rasterize(20, 20, tri, np.ones((4, 3)), np.zeros((4, 3, 3)), np.arange(4),
                  zbuf=np.full((20, 20), np.inf), buf=np.zeros((20, 20, 3), np.uint8),
                  order=np.arange(4)[::-1].copy(), first=2)
