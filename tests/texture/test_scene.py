"""Scene files: materials take textures -- procedural ones by name, image files
relative to the scene file -- on meshes read with texture coordinates."""

import numpy as np
import pytest
from PIL import Image

import scanline as sl

OBJ = """v -1 -1 0
v 1 -1 0
v 1 1 0
v -1 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
f 1/1 2/2 3/3 4/4
"""

SCENE = """version = 2
shading = "gouraud"
[canvas]
width = 40
height = 40
background = "black"
[[cameras]]
name = "eye"
eye = [0, 0, 3]
target = [0, 0, 0]
[[lights]]
type = "ambient"
intensity = 1.0
[materials.tiles]
ka = 1.0
kd = 0.0
ks = 0.0
texture = {texture}
[[segments]]
name = "quad"
primitives = [{{type = "mesh", file = "quad.obj", material = "tiles"}}]
"""


def render(tmp_path, texture):
    (tmp_path / "quad.obj").write_text(OBJ)
    path = tmp_path / "scene.toml"
    path.write_text(SCENE.format(texture=texture))
    return sl.scene.load(path).raster().to_array()


def test_a_procedural_checker_textures_a_mesh_from_a_file(tmp_path):
    img = render(tmp_path, '{procedural = "checker", size = 8, squares = 2, '
                           'colors = ["red", "blue"], filter = "nearest"}')
    red = (img == (255, 0, 0)).all(axis=2)
    blue = (img == (0, 0, 255)).all(axis=2)
    assert red.sum() > 100 and blue.sum() > 100
    # the bottom-left quarter of the quad is the first color, the bottom-right the second
    assert red[28, 12] and blue[28, 28] and blue[12, 12] and red[12, 28]


def test_an_image_file_next_to_the_scene(tmp_path):
    Image.new("RGB", (4, 4), (0, 200, 0)).save(tmp_path / "green.png")
    img = render(tmp_path, '"green.png"')
    assert ((img == (0, 200, 0)).all(axis=2)).sum() > 300


@pytest.mark.parametrize("texture, words", [
    ('{procedural = "bricks"}', "procedural"),
    ('{procedural = "marble", veins = "many"}', "veins"),
    ('{procedural = "marble", hue = 3}', "hue"),
    ('"missing.png"', "missing.png"),
    ("42", "texture"),
])
def test_bad_texture_keys_name_the_key(tmp_path, texture, words):
    with pytest.raises(sl.scene.SceneError, match=words) as error:
        render(tmp_path, texture)
    assert "materials.tiles.texture" in str(error.value)


MIRROR_SCENE = """version = 2
shading = "phong"
[canvas]
width = 21
height = 21
background = "black"
[[cameras]]
name = "eye"
eye = [0, 0, 3]
target = [0, 0, 0]
[[lights]]
type = "ambient"
intensity = 1.0
[materials.mirror]
ka = 0.0
kd = 0.0
ks = 0.0
reflectivity = 1.0
environment = {environment}
[[segments]]
name = "quad"
primitives = [{{type = "mesh", file = "quad.obj", material = "mirror"}}]
"""

#: Face colors +x, -x, +y, -y, +z, -z.
FACES = [(255, 0, 0), (0, 255, 255), (0, 255, 0), (255, 0, 255), (0, 0, 255), (255, 255, 0)]


def mirror(tmp_path, environment):
    (tmp_path / "quad.obj").write_text(OBJ)
    path = tmp_path / "scene.toml"
    path.write_text(MIRROR_SCENE.format(environment=environment))
    return sl.scene.load(path).raster().to_array()


def test_a_cube_map_from_six_files(tmp_path):
    """The mirror faces the eye (+z): the reflected view at its center is +z, the +z
    face (blue)."""
    names = []
    for name, color in zip(("px", "nx", "py", "ny", "pz", "nz"), FACES):
        Image.new("RGB", (4, 4), color).save(tmp_path / f"{name}.png")
        names.append(f'"{name}.png"')
    a = mirror(tmp_path, "{cube = [" + ", ".join(names) + '], filter = "nearest"}')
    assert a[10, 10].tolist() == [0, 0, 255]


def test_a_cube_map_from_a_cross_image(tmp_path):
    cross = Image.new("RGB", (16, 12), (0, 0, 0))
    for color, (col, row) in zip(FACES, [(2, 1), (0, 1), (1, 0), (1, 2), (1, 1), (3, 1)]):
        cross.paste(color, (4 * col, 4 * row, 4 * col + 4, 4 * row + 4))
    cross.save(tmp_path / "cross.png")
    assert mirror(tmp_path, '{cube = "cross.png"}')[10, 10].tolist() == [0, 0, 255]


@pytest.mark.parametrize("environment, words", [
    ('{cube = ["a.png", "b.png"]}', r"environment\.cube.*six"),
    ('{cube = 3}', r"environment\.cube.*image file"),
    ('{cube = "cross.png", wrap = "repeat"}', r"environment\.wrap"),
    ('{cube = "cross.png", filter = "trilinear"}', r"environment.*filter"),
    ('{cube = "missing.png"}', r"environment.*missing"),
])
def test_bad_cube_maps_name_the_key(tmp_path, environment, words):
    Image.new("RGB", (16, 12)).save(tmp_path / "cross.png")
    with pytest.raises(sl.scene.SceneError, match=words) as error:
        mirror(tmp_path, environment)
    assert "materials.mirror.environment" in str(error.value)


def test_a_tileable_procedural_texture_from_a_scene(tmp_path):
    a = render(tmp_path, '{procedural = "marble", size = 16, tileable = false, veins = 2.5}')
    assert a.std() > 0
