"""Scene files (version 2) with lights, materials, method and shading, rendered by
``scanline render``; their errors name the key."""

import os

import numpy as np
import pytest

import scanline as sl
from scanline.scene import SceneError, loads

SCENE = os.path.join(os.path.dirname(sl.__file__), "data", "scenes", "shaded_teapot.toml")

BASE = """
version = 2
{top}
[canvas]
width = 60
height = 40
background = "black"
[[cameras]]
eye = [0, 0, 5]
target = [0, 0, 0]
[[segments]]
name = "s"
primitives = [{{type = "mesh", generator = "sphere", radius = 1, {prim}}}]
"""


def scene(top="", prim='material = "m"', materials='[materials.m]\nkd = 0.8\ncolor = "red"\n'):
    return loads(BASE.format(top=top + "\n" + materials, prim=prim))


def test_the_example_scene_renders_shaded(tmp_path, capsys):
    from PIL import Image

    from scanline.cli import main

    out = tmp_path / "teapot.png"
    assert main(["render", SCENE, "-o", str(out)]) == 0
    assert "wrote" in capsys.readouterr().out
    img = np.asarray(Image.open(out).convert("RGB")).astype(int)
    # the teapot's body (blue, shaded: many levels) around the picture's center
    body = img[130:230, 180:300]
    assert (body[..., 2] > body[..., 0] + 30).mean() > 0.8
    assert len(np.unique(body[..., 2])) > 40
    # the red line is drawn over the floor
    assert ((img[..., 0] > 180) & (img[..., 1] < 120)).sum() > 100


def test_the_scene_renders_what_sl_render_draws():
    fb = scene('shading = "phong"\n[[lights]]\ntype = "ambient"\nintensity = 0.3\n'
               '[[lights]]\ntype = "point"\nposition = [2, 2, 4]\n').raster()
    want = sl.FrameBuffer(60, 40, background="black")
    cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
    sl.render(want, sl.mesh.sphere(1), cam, shading="phong",
              lights=[sl.lighting.AmbientLight(0.3), sl.lighting.PointLight((2, 2, 4))],
              materials=sl.lighting.Material(kd=0.8, color="red"))
    assert np.array_equal(fb.to_array(), want.to_array())
    assert (fb.to_array()[..., 0] > 0).sum() > 200


def test_a_mesh_without_material_stays_a_wireframe():
    sc = scene('method = "ray-casting"', prim='color = "white"')
    assert sc.canvas.shading.surfaces == []
    assert len(sc.display_file.segments[0].primitives) == 1


@pytest.mark.parametrize("top, prim, materials, where", [
    ('method = "magic"', 'material = "m"', None, "method"),
    ('shading = "glossy"', 'material = "m"', None, "shading"),
    ('shading = {model = "phong", specular = "cook"}', 'material = "m"', None,
     "shading.specular"),
    ('shading = {gamma = 0}', 'material = "m"', None, "shading.gamma"),
    ('[[lights]]\ntype = "laser"', 'material = "m"', None, "lights[0].type"),
    ('[[lights]]\ntype = "point"', 'material = "m"', None, "lights[0]"),
    ('[[lights]]\ntype = "ambient"\nintensity = -1', 'material = "m"', None, "lights[0]"),
    ("", 'material = "gold"', None, "segments[0].primitives[0].material"),
    ("", 'material = "m"', '[materials.m]\nks = 2\n', "materials.m"),
    ("", 'material = "m"', '[materials.m]\nglow = 1\n', "materials.m.glow"),
    ("", 'material = "m"', "", "segments[0].primitives[0].material"),
])
def test_bad_shading_keys_name_the_key(top, prim, materials, where):
    kw = {} if materials is None else {"materials": materials}
    with pytest.raises(SceneError) as info:
        scene(top, prim, **kw)
    assert where in str(info.value), str(info.value)


def test_shaded_surfaces_refuse_vector_outputs(tmp_path):
    sc = scene()
    with pytest.raises(SceneError, match="raster files only"):
        sc.render(tmp_path / "x.svg")
    assert not (tmp_path / "x.svg").exists()
