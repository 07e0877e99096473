"""The compiled textured shading draws the same pixels whatever the thread count: the
rows are shared out in bands of rows (scanline._kernels._threads.call_in_bands) and
the triangles in chunks (call_in_chunks), and each pixel is computed by one call
from the same inputs, however many calls share the work."""

import numpy as np
import pytest

import scanline as sl
import scanline._kernels._threads as threads


def grid(n=24, size=8.0, repeats=3.0):
    """An n x n grid of quads on y = 0 (x in -size/2 .. size/2, z in 0 .. -size),
    texture coordinates 0 .. repeats: many triangles, from magnified to minified."""
    t = np.linspace(0.0, 1.0, n + 1)
    x, z = np.meshgrid(t, t)
    vertices = np.stack([(x - 0.5) * size, np.zeros_like(x), -z * size], -1).reshape(-1, 3)
    i = np.arange(n)
    a = (i[:, None] * (n + 1) + i[None, :]).reshape(-1)
    quads = np.stack([a, a + 1, a + n + 2, a + n + 1], 1)
    return sl.mesh.Mesh(vertices, quads, uv=np.stack([x, z], -1).reshape(-1, 2) * repeats)


GRID = grid()
CAMERA = sl.Camera(eye=(0, 1.2, 1.0), target=(0, 0, -3))
LIGHTS = [sl.lighting.AmbientLight(0.25), sl.lighting.DirectionalLight((0.3, -1, -0.4), 0.8),
          sl.lighting.PointLight((1, 2, -2), 0.5)]


@pytest.mark.parametrize("shading", ["gouraud", "phong"])
@pytest.mark.parametrize("wrap", ["repeat", "clamp", "mirror"])
@pytest.mark.parametrize("filter", ["nearest", "bilinear", "trilinear"])
def test_pixels_do_not_depend_on_the_thread_count(monkeypatch, filter, wrap, shading):
    tex = sl.texture.marble(64, seed=2, filter=filter, wrap=wrap)
    mat = sl.lighting.Material(ks=0.4, shininess=9, texture=tex)
    drawn = []
    for count in (1, 2, 3):
        monkeypatch.setattr(threads, "threads", lambda count=count: count)
        fb = sl.FrameBuffer(240, 160)
        r = sl.render(fb, GRID, CAMERA, materials=mat, lights=LIGHTS, shading=shading)
        drawn.append((fb.to_array(), r.facets.copy()))
    image, facets = drawn[0]
    assert (facets >= 0).mean() > 0.5                      # the grid fills most rows
    assert len(np.unique(image[facets >= 0].reshape(-1, 3), axis=0)) > 100   # textured
    for other, other_facets in drawn[1:]:
        assert np.array_equal(other, image)
        assert np.array_equal(other_facets, facets)
