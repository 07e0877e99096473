"""sl.render(antialias=n): every pixel the mean of n x n samples, for every method --
the same picture by every method but the painter, a coverage that converges on the
exact area of what is drawn, the front faces at the pixels' central samples."""

import math

import numpy as np
import pytest
from shapely.geometry import Polygon

import scanline as sl

CAM = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0))
MESHES = [sl.mesh.cube(), sl.mesh.sphere(0.6, (1, 0.5, 0.3), resolution=(16, 8))]


# (the ray tracer adds shadows; tests/raytrace compares it with ray casting)
@pytest.mark.parametrize("method", sorted(set(sl.visible.METHODS) - {"painter", "ray-tracing"}))
def test_every_method_supersamples_to_the_same_picture(method):
    ref, fb = sl.FrameBuffer(60, 45), sl.FrameBuffer(60, 45)
    sl.render(ref, MESHES, CAM, antialias=3)
    r = sl.render(fb, MESHES, CAM, method=method, antialias=3,
                  **({"samples": 1} if method == "a-buffer" else {}))
    assert np.array_equal(fb.to_array(), ref.to_array()), method
    assert r.faces.shape == (45, 60) and r.depth.array.shape == (45, 60)


def test_the_coverage_converges_on_the_exact_area():
    # a white quad on black, unlit, gamma 1: the sum of the pixels is the area the
    # samples saw; the exact area is the projected quad's (shapely)
    quad = sl.mesh.Mesh([(-1.1, -0.7, 0), (1.3, -0.9, 0), (0.9, 1.2, 0), (-0.8, 0.9, 0)],
                        [[0, 1, 2, 3]])
    cam = sl.Camera(eye=(0.3, -0.5, 4), target=(0, 0, 0))
    corners = cam.project(quad.vertices, 40, 30)[:, :2]
    area = Polygon(corners).area
    errors = []
    for n in (1, 2, 4, 8):
        fb = sl.FrameBuffer(40, 30, mode="L")
        r = sl.render(fb, quad, cam, shading="none", colors="white", gamma=1, antialias=n)
        a = fb.to_array().astype(float) / 255
        errors.append(abs(a.sum() - area))
        inner = (r.faces >= 0)
        assert a.max() == 1.0 and a.min() == 0.0
        if n > 1:
            assert ((a > 0) & (a < 1)).sum() > 20          # edge pixels blended
        assert inner.sum() <= (a > 0).sum()
    assert errors[-1] < 0.5 and errors[-1] < errors[0], errors


def test_the_front_faces_are_the_central_samples():
    fb = sl.FrameBuffer(50, 40)
    plain = sl.render(sl.FrameBuffer(50, 40), MESHES, CAM)
    r = sl.render(fb, MESHES, CAM, antialias=3)     # odd n: the central sample is the center
    assert np.array_equal(r.faces, plain.faces)
    assert np.allclose(r.depth.array[r.faces >= 0], plain.depth.array[plain.faces >= 0])


def test_samples_composite_over_what_the_frame_buffer_holds():
    fb = sl.FrameBuffer(40, 30, background="red")
    sl.render(fb, sl.mesh.cube(0.5), CAM, shading="none", colors="white", antialias=4)
    a = fb.to_array().astype(int)
    edge = (a[..., 1] > 0) & (a[..., 1] < 255)
    assert edge.any() and (a[edge][:, 0] == 255).all()     # white over red keeps red 255
    assert (a[0, 0] == [255, 0, 0]).all()


@pytest.mark.parametrize("bad, match", [(0, "antialias must be an integer in 1..8"),
                                        (9, "in 1..8"), (2.0, "integer"), (True, "integer")])
def test_bad_antialias(bad, match):
    with pytest.raises(sl.ScanlineError, match=match):
        sl.render(sl.FrameBuffer(8, 8), sl.mesh.cube(), CAM, antialias=bad)


def test_antialiasing_needs_a_mode_that_averages(monkeypatch):
    with pytest.raises(sl.ScanlineError, match="antialias=2 averages samples"):
        sl.render(sl.FrameBuffer(8, 8, mode="1"), sl.mesh.cube(), CAM, shading="none",
                  antialias=2)
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "50M")
    with pytest.raises(sl.errors.MemoryBudgetError, match="antialias: 8 x 8 samples"):
        sl.render(sl.FrameBuffer(400, 300), sl.mesh.cube(), CAM, antialias=8)
    assert math.isfinite(sl.budget.limit())
