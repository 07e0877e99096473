"""Bad input to the maps: a clear error naming the argument, or a bounded result."""

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentTypeError, ArgumentValueError


@pytest.mark.parametrize("kw, error, name", [
    (dict(texture=42), ArgumentTypeError, "texture"),
    (dict(bump="no-such-file.png"), sl.ImageFileError, "bump"),
    (dict(environment=np.zeros((2, 2, 5))), ArgumentValueError, "environment"),
    (dict(texture=np.full((2, 2), np.nan)), ArgumentValueError, "texture"),
    (dict(bump_scale=float("nan")), ArgumentValueError, "bump_scale"),
    (dict(bump_scale="big"), ArgumentTypeError, "bump_scale"),
    (dict(reflectivity=1.5), ArgumentValueError, "reflectivity"),
])
def test_material_maps_are_checked_by_name(kw, error, name):
    with pytest.raises(error, match=name):
        sl.lighting.Material(**kw)


def test_an_image_becomes_a_bilinear_repeated_texture():
    m = sl.lighting.Material(texture=np.zeros((3, 4, 3), np.uint8))
    assert isinstance(m.texture, sl.Texture)
    assert (m.texture.filter, m.texture.wrap) == ("bilinear", "repeat")


@pytest.mark.parametrize("scale", [1e300, -1e300, 2.0 ** 62, 1e-300])
@pytest.mark.parametrize("filter", ["nearest", "bilinear", "trilinear"])
def test_huge_texture_coordinates_draw_a_bounded_picture(scale, filter):
    quad = sl.mesh.Mesh([(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)], [[0, 1, 2, 3]],
                        uv=np.array([(0, 0), (1, 0), (1, 1), (0, 1)]) * scale)
    mat = sl.lighting.Material(texture=sl.texture.checker(16, 4, filter=filter,
                                                          wrap="mirror"))
    for shading in ("gouraud", "phong"):
        fb = sl.FrameBuffer(24, 24, background="red")
        sl.render(fb, quad, sl.Camera(eye=(0, 0, 3), target=(0, 0, 0)), materials=mat,
                  shading=shading)
        assert (fb.to_array() != (255, 0, 0)).any()


def test_a_mesh_refuses_nan_texture_coordinates():
    with pytest.raises(ArgumentValueError, match="uv"):
        sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [[0, 1, 2]],
                     uv=[(0, 0), (np.nan, 0), (0, 1)])


def test_texture_mapping_is_checked():
    with pytest.raises(ArgumentValueError, match="texture_mapping"):
        sl.render(sl.FrameBuffer(4, 4), sl.mesh.cube(), sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)),
                  texture_mapping="projective")
