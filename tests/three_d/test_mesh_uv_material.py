"""Texture coordinates and a material carried by a Mesh (H&B 14-9)."""
import numpy as np
import pytest

import scanline as sl

SQUARE = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
UV = [(0, 0), (1, 0), (1, 1), (0, 1)]


def test_uv_kept_through_transforms_triangulation_and_merge():
    m = sl.mesh.Mesh(SQUARE, [[0, 1, 2, 3]], uv=UV)
    assert m.uv.shape == (4, 2) and m.uv.dtype == np.float64
    moved = m.transformed(sl.transform3d.scaling(2, 3, 4))
    np.testing.assert_array_equal(moved.uv, UV)
    np.testing.assert_array_equal(m.triangulated().uv, UV)
    both = sl.mesh.merge([m, m.translated((2, 0, 0))])
    np.testing.assert_array_equal(both.uv, np.vstack([UV, UV]))
    plain = sl.mesh.Mesh(SQUARE, [[0, 1, 2, 3]])
    assert sl.mesh.merge([m, plain]).uv is None


@pytest.mark.parametrize("uv, word", [([(0, 0)] * 3, "one (u, v) row per vertex"),
                                      ([(0, 0, 0)] * 4, "one (u, v) row per vertex"),
                                      ([(np.nan, 0)] * 4, "uv"),
                                      ("abc", "uv")])
def test_bad_uv_names_the_argument(uv, word):
    with pytest.raises((ValueError, TypeError), match="uv") as e:
        sl.mesh.Mesh(SQUARE, [[0, 1, 2, 3]], uv=uv)
    assert word in str(e.value)


def test_material_must_be_a_material():
    with pytest.raises(TypeError, match="material must be a scanline.lighting.Material"):
        sl.mesh.Mesh(SQUARE, [[0, 1, 2, 3]], material="red")


def test_render_uses_each_meshs_material_when_given_none():
    """A mesh's own material shades it; materials= still overrides it."""
    cam = sl.Camera(eye=(0.5, 0.5, 3), target=(0.5, 0.5, 0), up=(0, 1, 0),
                    projection=sl.projection.orthographic(window=(-1, -1, 1, 1)))
    lights = [sl.lighting.AmbientLight(1.0)]
    dark = sl.lighting.Material(ka=0.25, kd=0, ks=0)
    own = sl.mesh.Mesh(SQUARE, [[0, 1, 2, 3]], colors="white", material=dark)
    fb1 = sl.FrameBuffer(20, 20, mode="L")
    sl.render(fb1, [own], cam, shading="flat", lights=lights, gamma=1)
    fb2 = sl.FrameBuffer(20, 20, mode="L")
    sl.render(fb2, [own], cam, shading="flat", lights=lights, gamma=1,
              materials=sl.lighting.Material(ka=1.0, kd=0, ks=0))
    assert fb1.get_pixel(10, 10) == round(0.25 * 255)
    assert fb2.get_pixel(10, 10) == 255
