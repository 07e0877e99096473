"""The compiled textured shading (scanline._kernels.surface) against the numpy path
(scanline.shading.models.intensities, the reference), pixel for pixel."""

import numpy as np
import pytest

import scanline as sl
import scanline.shading.compose as compose

FLOOR = sl.mesh.Mesh([(-1, 0, 0), (1, 0, 0), (1, 0, -8), (-1, 0, -8)], [[0, 1, 2, 3]],
                     uv=[(0, 0), (1, 0), (1, 4), (0, 4)])
BOX = sl.mesh.cube(0.8).transformed(sl.transform3d.translation(0.3, 0.5, -2.5))
CAMERA = sl.Camera(eye=(0, 0.6, 1.5), target=(0, 0, -2), up=(0, 1, 0))
LIGHTS = [sl.lighting.AmbientLight(0.3), sl.lighting.DirectionalLight((0.2, -1, -0.5)),
          sl.lighting.PointLight((0.5, 2, -1), 0.6)]


def pictures(monkeypatch, materials, meshes, **kw):
    out = []
    mode = kw.pop("mode", "RGB")
    for compiled in (True, False):
        if not compiled:
            monkeypatch.setattr(compose, "texturable", lambda *a: False)
        fb = sl.FrameBuffer(96, 72, mode=mode, background="gray")
        sl.render(fb, meshes, CAMERA, materials=materials, lights=LIGHTS, **kw)
        out.append(fb.to_array().astype(int))
    return out


@pytest.mark.parametrize("filter", ["nearest", "bilinear", "trilinear"])
@pytest.mark.parametrize("shading", ["none", "flat", "gouraud", "phong"])
def test_compiled_textures_equal_the_reference(monkeypatch, filter, shading):
    tex = sl.texture.marble(64, filter=filter, wrap="mirror")
    mats = [sl.lighting.Material(ks=0.5, shininess=7, texture=tex, color=(250, 200, 150)),
            sl.lighting.Material(color="tomato")]
    a, b = pictures(monkeypatch, mats, [FLOOR, BOX], shading=shading)
    assert (a != 128).any()
    assert np.abs(a - b).max() <= 1


@pytest.mark.parametrize("mode", ["L", "RGBA"])
def test_compiled_textures_in_other_modes(monkeypatch, mode):
    mat = sl.lighting.Material(texture=sl.texture.checker(32, 4))
    a, b = pictures(monkeypatch, mat, FLOOR, shading="phong", specular="blinn", mode=mode)
    assert np.abs(a - b).max() <= 1
