"""Radiosity in scene files: the radiosity table, a mesh's emission and reflectance,
polygons given by their vertices, and the Cornell box example."""

import numpy as np
import pytest

import scanline as sl
from scanline.scene import SceneError, load, loads

ROOM = """
version = 2
radiosity = {subdivisions = 3, resolution = 48}

[canvas]
width = 60
height = 45
background = "black"

[[cameras]]
name = "eye"
eye = [0, -0.9, -0.3]
target = [0, 1, 0]
up = [0, 0, 1]
projection = {type = "perspective", fov = {radians = 1.4}, near = 0.05}

[materials.white]
color = "white"

[[segments]]
name = "room"
primitives = [
  {type = "mesh", generator = "polygons", vertices = VERTICES, faces = [[0, 3, 2, 1]], material = "white", reflectance = [0.7, 0.1, 0.1]},
  {type = "mesh", generator = "polygons", vertices = VERTICES, faces = [[4, 5, 6, 7]], material = "white", reflectance = 0.7},
  {type = "mesh", generator = "polygons", vertices = VERTICES, faces = [[0, 1, 5, 4]], material = "white", reflectance = 0.7},
  {type = "mesh", generator = "polygons", vertices = VERTICES, faces = [[1, 2, 6, 5]], material = "white", reflectance = [0.1, 0.7, 0.1]},
  {type = "mesh", generator = "polygons", vertices = VERTICES, faces = [[2, 3, 7, 6]], material = "white", reflectance = 0.7},
  {type = "mesh", generator = "polygons", vertices = VERTICES, faces = [[3, 0, 4, 7]], material = "white", reflectance = 0.7, emission = [1.0, 0.9, 0.8]},
]
"""
CORNERS = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
           (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]
FACES = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]


def room_text():
    return ROOM.replace("VERTICES", str([list(c) for c in CORNERS]))


def test_a_radiosity_scene_draws_what_solve_and_render_draw():
    got = loads(room_text()).raster()
    room = [sl.mesh.Mesh(CORNERS, [f]) for f in FACES]
    emission = [0, 0, 0, 0, 0, (1.0, 0.9, 0.8)]
    reflectance = [(0.7, 0.1, 0.1), 0.7, 0.7, (0.1, 0.7, 0.1), 0.7, 0.7]
    solution = sl.radiosity.solve(room, emission, reflectance, subdivisions=3, resolution=48)
    want = sl.FrameBuffer(60, 45, mode="RGB", background="black")
    camera = sl.Camera(eye=(0, -0.9, -0.3), target=(0, 1, 0), up=(0, 0, 1),
                       projection=sl.projection.perspective(fov=1.4, near=0.05))
    solution.render(want, camera)
    assert got.to_array().any()
    assert (got.to_array() == want.to_array()).all()


def test_the_default_reflectance_is_the_materials():
    text = room_text().replace(', reflectance = [0.7, 0.1, 0.1]', '').replace(
        'color = "white"', 'color = "white"\nkd = 0.5')
    scene = loads(text)
    fb = scene.raster()
    assert fb.to_array().any()


@pytest.mark.parametrize("change, path, words", [
    (("radiosity = {subdivisions = 3, resolution = 48}", ""), "segments[0].primitives[0]",
     "radiosity table"),
    (("resolution = 48}", "resolution = 48, colour = 1}"), "radiosity", "colour"),
    ((', faces = [[0, 3, 2, 1]]', ''), "segments[0].primitives[0]", "faces"),
    (('reflectance = [0.7, 0.1, 0.1]', 'reflectance = [0.7, 0.1, "x"]'),
     "segments[0].primitives[0].reflectance", "reflectance"),
])
def test_errors_name_the_key(change, path, words):
    with pytest.raises(SceneError) as info:
        loads(room_text().replace(*change)).raster()
    assert path in str(info.value) and words in str(info.value), str(info.value)


def test_no_emitter_is_an_error_naming_emission():
    text = room_text().replace(', emission = [1.0, 0.9, 0.8]', '')
    with pytest.raises(SceneError, match="emission"):
        loads(text).raster()


def test_the_cornell_box_example_shows_red_and_green_walls():
    fb = load(sl.scene.example("cornell_box")).raster()
    a = fb.to_array().astype(int)
    h, w = a.shape[:2]
    left, right = a[h // 2, w // 20], a[h // 2, w - 1 - w // 20]
    assert left[0] > left[1] + 30 and right[1] > right[0] + 15
