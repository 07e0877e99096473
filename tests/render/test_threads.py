"""The triangle paths' pixels do not depend on the thread count (issue 31, item 2):
the batch kernels split the frame into bands, one band set per thread, and every
band's pixels come out as one thread draws them."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline._kernels import _threads

W, H = 83, 131      # bands cut at odd rows, and triangles across band edges


def _split(draw, threads, monkeypatch):
    """``draw()`` with the kernels split over ``threads`` threads, however small the
    work (the twin's threshold lowered)."""
    with monkeypatch.context() as m:
        m.setattr(_threads, "threads", lambda: threads)
        m.setattr(_threads, "TWIN_WORK", -1)
        return draw()


def _triangles(rng, n):
    centers = rng.uniform([-10, -10], [W + 10, H + 10], (n, 1, 2))
    xy = centers + rng.uniform(-12, 12, (n, 3, 2))
    xy[: n // 10] = rng.uniform([-20, -20], [W + 20, H + 20], (n // 10, 3, 2))   # tall ones
    z = rng.uniform(0.05, 0.95, (n, 3, 1))
    return np.concatenate([xy, z], axis=2)


@pytest.mark.parametrize("mode", ["L", "RGB", "RGBA"])
def test_triangles_on_any_thread_count_match_one_at_a_time(mode, monkeypatch):
    """The batch call on 1, 2, 3 and 5 threads against the triangles drawn one call
    each, in order, through the same depth buffer (each call a single band)."""
    rng = np.random.default_rng(ord(mode[0]))
    tris = _triangles(rng, 600)
    channels = {"L": 1, "RGB": 3, "RGBA": 4}[mode]
    colors = rng.integers(0, 256, (len(tris), 3, channels)).astype(np.float64)
    if mode == "RGBA":
        colors[:, :, 3] = 255.0

    def batch():
        fb = sl.FrameBuffer(W, H, mode=mode)
        sl.draw.triangles(fb, tris, colors=colors, depth=sl.DepthBuffer.like(fb))
        return fb.to_array()

    fb = sl.FrameBuffer(W, H, mode=mode)
    depth = sl.DepthBuffer.like(fb)
    for t, c in zip(tris, colors):
        sl.draw.triangles(fb, t[None], colors=c[None], depth=depth)
    expected = fb.to_array()
    assert len(np.unique(expected.reshape(-1, channels), axis=0)) > 100
    for threads in (1, 2, 3, 5):
        np.testing.assert_array_equal(_split(batch, threads, monkeypatch), expected,
                                      err_msg=f"{threads} threads")


@pytest.mark.parametrize("shading", ["gouraud", "phong"])
def test_rendered_teapot_does_not_depend_on_threads(shading, monkeypatch):
    """``sl.render`` (preparation, visible surfaces, shading) on 2, 3 and 5 threads
    gives one thread's pixels."""
    teapot = sl.mesh.teapot(6).transformed(sl.transform3d.rotation(-math.pi / 2, "x"))
    cam = sl.Camera(eye=(0, 2.5, 6.5), target=(0, 0.7, 0),
                    projection=sl.projection.perspective(fov=math.radians(32), near=1,
                                                         far=30))
    lights = [sl.lighting.AmbientLight(0.2),
              sl.lighting.DirectionalLight((0.45, -0.55, -1.0), 0.9)]

    def render():
        fb = sl.FrameBuffer(W, H)
        sl.render(fb, teapot, cam, shading=shading, lights=lights)
        return fb.to_array()

    one = _split(render, 1, monkeypatch)
    assert (one != one[0, 0]).any(axis=2).sum() > W * H // 8, "the teapot is not in view"
    for threads in (2, 3, 5):
        np.testing.assert_array_equal(_split(render, threads, monkeypatch), one,
                                      err_msg=f"{shading} on {threads} threads")
