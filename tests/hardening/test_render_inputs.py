"""Hostile input to the 3-D pipeline's public doors: hand-built screen polygons that
would make the kernels read past their arrays, empty and degenerate scenes, a viewer
no float can place, encodings without a gamma, and sizes past the memory budget --
each a clear ScanlineError naming what is wrong, or a picture; never a crash."""

import tracemalloc

import numpy as np
import pytest

import scanline as sl
from scanline.visible import ScreenPolygons

W, H = 40, 30
VERTS = np.random.default_rng(0).uniform(0, 30, (60, 3))
METHODS = [sl.visible.depth_sort, sl.visible.scan_line, sl.visible.area_subdivision,
           sl.visible.painter, sl.visible.painted_depth_sort]


def hand_built(offsets, verts=VERTS, planes=None, width=W, height=H, face=None):
    n = max(len(offsets) - 1, 0)
    return ScreenPolygons(verts, np.asarray(offsets), np.arange(n) if face is None else face,
                          np.ones((n, 4)) if planes is None else planes, width, height)


@pytest.mark.parametrize("method", METHODS, ids=lambda m: m.__name__)
@pytest.mark.parametrize("offsets, message", [
    ([0, 10**9], "end at the vertex count 60"),         # SIGSEGV before
    ([0, 61], "end at the vertex count 60"),            # out of bounds by one
    ([0, -3, 60], "polygon 0 has -3 vertices"),          # read before the array
    ([5, 30, 60], "must start at 0"),
    ([0, 2, 60], "polygon 0 has 2 vertices"),
    ([], "polygons.offsets must hold integers"),
])
def test_offsets_that_overrun_the_vertices_are_refused(method, offsets, message):
    with pytest.raises(sl.ArgumentValueError, match=message):
        method(hand_built(offsets))


@pytest.mark.parametrize("method", METHODS, ids=lambda m: m.__name__)
def test_other_hand_built_arrays_are_checked_or_converted(method):
    with pytest.raises(sl.ArgumentValueError, match=r"polygons.face must have shape \(2\)"):
        method(hand_built([0, 30, 60], face=np.arange(3)))
    with pytest.raises(sl.ArgumentValueError, match=r"polygons.planes must have shape"):
        method(hand_built([0, 30, 60], planes=np.ones((2, 3))))
    with pytest.raises(sl.ArgumentValueError, match="polygons.vertices must be finite"):
        method(hand_built([0, 30, 60], verts=np.where(VERTS > 29, np.nan, VERTS)))
    with pytest.raises(sl.ArgumentValueError, match="polygons.vertices must hold numbers"):
        method(hand_built([0, 30, 60], verts=VERTS.astype(object)))
    with pytest.raises(sl.ScanlineError, match="polygons.width"):
        method(hand_built([0, 30, 60], width=0))
    # float32 vertices, int32 offsets: converted, and the method runs
    tri = np.array([[1, 1, 0.5], [20, 2, 0.5], [5, 25, 0.5]], np.float32)
    sp = ScreenPolygons(tri, np.array([0, 3], np.int32), np.array([0], np.int32),
                        np.array([[0, 0, 1, -0.5]], np.float32), W, H)
    assert method(sp) is not None


def test_hidden_lines_check_their_polygons_too():
    with pytest.raises(sl.ArgumentValueError, match="end at the vertex count"):
        sl.visible.hidden_lines([[0, 0, 10, 10]], [[0.5, 0.5]], hand_built([0, 61]))


def test_a_huge_device_is_refused_before_its_buffers_are_made(monkeypatch):
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "64M")
    with pytest.raises(sl.errors.MemoryBudgetError, match="polygons.width x polygons.height"):
        sl.visible.scan_line(hand_built([0, 30, 60], width=9000, height=9000))


def test_empty_and_degenerate_scenes_render_nothing():
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0))
    flat = sl.mesh.Mesh(np.zeros((3, 3)), [[0, 1, 2]])            # no area
    for method in sorted(sl.visible.METHODS):
        for meshes in ([], flat):
            fb = sl.FrameBuffer(8, 8)
            r = sl.render(fb, meshes, cam, method=method, shading="phong")
            assert (r.faces == -1).all() and not fb.to_array().any(), method


def test_a_viewer_no_float_can_place_is_a_clear_error():
    cam = sl.Camera(eye=(1e300, 0, 0), target=(0, 0, 0))
    with pytest.raises(sl.ArgumentValueError, match="camera: its projection cannot be inverted"):
        sl.render(sl.FrameBuffer(8, 8), sl.mesh.cube(), cam, method="bsp")
    with pytest.raises(sl.ArgumentValueError, match="camera"):
        sl.visible.bsp(sl.mesh.cube(), cam, 8, 8)


@pytest.mark.parametrize("gamma", [0, -1, 1e300, float("nan")])
def test_encode_and_decode_need_a_gamma(gamma):
    with pytest.raises(sl.ArgumentValueError, match="gamma must be"):
        sl.shading.encode(0.5, gamma=gamma)
    with pytest.raises(sl.ArgumentValueError, match="gamma must be"):
        sl.shading.decode(0.5, gamma=gamma)
    assert sl.shading.encode([np.nan, 2.0, -1.0], 2.2).tolist() == [0, 255, 0]


def test_a_render_past_the_memory_budget_is_refused_up_front(monkeypatch):
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "100M")
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0))
    fb = sl.FrameBuffer(2000, 2000)
    with pytest.raises(sl.errors.MemoryBudgetError,
                       match=r"width x height: the per-pixel buffers of a 2000 x 2000 render "
                             r".*SCANLINE_MEMORY_LIMIT"):
        sl.render(fb, sl.mesh.cube(), cam)
    assert not fb.to_array().any()
    sphere = sl.mesh.sphere(1, resolution=128)
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "4M")
    with pytest.raises(sl.errors.MemoryBudgetError, match="meshes: 16,128 triangles"):
        sl.render(sl.FrameBuffer(20, 20), sphere, cam)


def test_the_budget_reads_its_limit():
    assert sl.budget.parse("8G") == 8 << 30 and sl.budget.parse("1.5K") == 1536
    assert sl.budget.parse("100") == 100 and sl.budget.parse("64MiB") == 64 << 20
    with pytest.raises(sl.ArgumentValueError, match="is not a size"):
        sl.budget.parse("lots")
    assert sl.budget.limit() > 0


def test_the_a_buffer_works_in_bounded_memory():
    # 1000 x 1000 at 8 x 8 samples is 64 million samples (several GB at once); band by
    # band it stays within a few hundred MB
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0))
    fb = sl.FrameBuffer(1000, 1000)
    tracemalloc.start()
    try:
        r = sl.render(fb, sl.mesh.cube(), cam, method="a-buffer", samples=8, shading="flat")
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 400 << 20, peak
    assert (r.faces >= 0).sum() > 100_000
