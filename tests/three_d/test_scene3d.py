"""Scene files, version 2: cameras, 3-D steps, meshes by generator and by file, 3-D
polylines; version 1 still read; the display file's 3-D primitives re-projected at
each interpretation; errors with key paths; fuzzed version-2 scenes.  (The example
scenes, version 2 ones included, are rendered, round-tripped and fuzzed by
tests/scene/test_scene.py.)"""

import math
import os

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from scanline.cli import main
from scanline.scene import Scene, SceneError, load, loads
from scanline.scene import schema3d
from tests.reference import HYPOTHESIS

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENES = os.path.join(ROOT, "src", "scanline", "data", "scenes")

BASE = """
version = 2
canvas = {width = 64, height = 48, background = "black"}
[[cameras]]
name = "cam"
eye = [3, 2, 4]
target = [0, 0, 0]
projection = {type = "perspective", fov = {degrees = 50}, near = 1, far = 20}
[[segments]]
name = "s"
primitives = [PRIMS]
"""


def scene(prims, base=BASE):
    return loads(base.replace("PRIMS", prims))


def test_an_example_per_projection_ships():
    names = set(os.listdir(SCENES))
    assert {"perspective.toml", "orthographic.toml", "oblique.toml", "axonometric.toml"} <= names
    kinds = set()
    for name in ("perspective", "orthographic", "oblique", "axonometric"):
        data = load(os.path.join(SCENES, f"{name}.toml")).data
        kinds |= {c["projection"]["type"] for c in data["cameras"]}
    assert {"perspective", "orthographic", "isometric", "oblique", "dimetric", "trimetric"} <= kinds


def test_a_mesh_scene_draws_what_the_wireframe_draws():
    s = scene('{type = "mesh", generator = "cube", size = 2, color = "white"}')
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0),
                    projection=sl.projection.perspective(fov=math.radians(50), near=1, far=20))
    fb = sl.FrameBuffer(64, 48)
    sl.draw3d.wireframe(fb, sl.mesh.cube(2), cam)
    assert (s.raster().to_array() == fb.to_array()).all()


def test_every_generator_and_projection_builds():
    gens = ['{type = "mesh", generator = "cube", size = 1, center = [0, 0, 0]}',
            '{type = "mesh", generator = "box", lo = [0, 0, 0], hi = [1, 2, 1]}',
            '{type = "mesh", generator = "sphere", radius = 1, resolution = [8, 4]}',
            '{type = "mesh", generator = "ellipsoid", radii = [1, 2, 1], resolution = 8}',
            '{type = "mesh", generator = "torus", major = 1, minor = 0.3, resolution = [8, 4]}',
            '{type = "mesh", generator = "superellipsoid", s1 = 0.5, s2 = 1.5, resolution = 8}',
            '{type = "mesh", generator = "supertoroid", s1 = 0.5, s2 = 1.5, r = 3}',
            '{type = "mesh", generator = "sweep", kind = "rotational", profile = [[0, 0], [1, 0], '
            '[0.5, 1]], angle = {degrees = 270}, steps = 6}',
            '{type = "mesh", generator = "sweep", kind = "translational", profile = [[0, 0], '
            '[1, 0], [0, 1]], vector = [0, 0, 1], closed = true}',
            '{type = "mesh", generator = "teapot", n = 2, parts = ["lid"]}',
            '{type = "polyline3d", points = [[0, 0, 0], [1, 1, 1], [2, 0, 1]], closed = true, '
            'dash = [3, 1]}']
    s = scene(", ".join(gens))
    assert len(s.display_file.segment("s").primitives) == len(gens)
    assert s.raster().to_array().any()
    projections = ['{type = "perspective", z_prp = 6, z_vp = 0, window = [-1, -1, 1, 1], back = -10}',
                   '{type = "frustum", prp = [0.5, 0, 6], window = [-1, -1, 2, 1]}',
                   '{type = "orthographic", view = "top", window = [-2, -2, 2, 2]}',
                   '{type = "isometric", window = [-2, -2, 2, 2]}',
                   '{type = "dimetric", fz = 0.6}', '{type = "trimetric", phi = {degrees = -20}, '
                   'theta = {degrees = 30}}',
                   '{type = "oblique", kind = "cabinet", phi = {degrees = 30}}',
                   '{type = "oblique", alpha = {degrees = 60}, phi = {radians = 0.5}}',
                   '{type = "parallel", direction = [0.2, 0.1, -1]}']
    for proj in projections:
        oriented = any(k in proj for k in ('"top"', "isometric", "dimetric", "trimetric"))
        where = "target = [0, 0, 0]" if oriented else \
            'view_reference_point = [0, 0, 0]\nview_plane_normal = [1, 1, 2]\nview_up = [0, 1, 0]'
        text = BASE.replace('eye = [3, 2, 4]\ntarget = [0, 0, 0]', where).replace(
            '{type = "perspective", fov = {degrees = 50}, near = 1, far = 20}', proj)
        s = loads(text.replace("PRIMS", '{type = "mesh", generator = "cube", size = 1}'))
        assert s.raster().to_array().any(), proj


@pytest.mark.parametrize("step, matrix", [
    ('{translate = [1, 2, 3]}', sl.transform3d.translation(1, 2, 3)),
    ('{rotate = {degrees = 90, axis = "x"}}', sl.transform3d.rotation(math.pi / 2, "x")),
    ('{rotate = {radians = 0.5, axis = [[0, 0, 0], [1, 1, 0]]}}',
     sl.transform3d.rotation(0.5, ((0, 0, 0), (1, 1, 0)))),
    ('{rotate = {degrees = 30, axis = "y", pivot = [1, 0, 1]}}',
     sl.transform3d.rotation(math.pi / 6, "y", pivot=(1, 0, 1))),
    ('{scale = 2}', sl.transform3d.scaling(2)),
    ('{scale = {factors = [1, 2, 3], fixed = [1, 1, 1]}}',
     sl.transform3d.scaling(1, 2, 3, fixed=(1, 1, 1))),
    ('{reflect = "xy"}', sl.transform3d.reflection("xy")),
    ('{reflect = {point = [0, 0, 1], normal = [0, 1, 1]}}',
     sl.transform3d.reflection((0, 0, 1), (0, 1, 1))),
    ('{shear = {axis = "z", a = 0.5, b = -1, reference = 2}}',
     sl.transform3d.shear("z", 0.5, -1, 2)),
    ('{matrix = [[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}',
     sl.transform3d.translation(1, 0, 0)),
])
def test_every_3d_step_gives_its_matrix(step, matrix):
    from scanline.scene import parse

    m = schema3d.transformation(parse(f"t = [{step}]")["t"], "t")
    np.testing.assert_allclose(m, matrix, atol=1e-12)


def test_steps_apply_in_order_to_the_mesh():
    s = scene('{type = "mesh", generator = "cube", size = 2, transform = '
              '[{scale = 0.5}, {translate = [3, 0, 0]}]}')
    mesh = s.display_file.segment("s").primitives[0].geometry["mesh"]
    np.testing.assert_allclose(mesh.bounds[0], (2.5, -0.5, -0.5))


def test_mesh_files_are_named_relative_to_the_scene(tmp_path):
    (tmp_path / "models").mkdir()
    sl.mesh.torus(1, 0.3, resolution=(8, 4)).save(tmp_path / "models" / "ring.ply")
    text = BASE.replace("PRIMS", '{type = "mesh", file = "models/ring.ply", color = "red"}')
    (tmp_path / "s.toml").write_text(text)
    out = tmp_path / "s.svg"
    assert main(["render", str(tmp_path / "s.toml"), "-o", str(out)]) == 0
    assert out.read_text().count("<polyline") + out.read_text().count("<path") > 0
    (tmp_path / "models" / "ring.ply").write_bytes(b"ply\ngarbage")
    with pytest.raises(SceneError, match=r"segments\[0\]\.primitives\[0\]\.file: .*ring.ply"):
        load(tmp_path / "s.toml")


def test_version_1_is_still_read_and_cannot_hold_3d():
    v1 = BASE.replace("version = 2", "version = 1")
    with pytest.raises(SceneError, match="cameras need version = 2"):
        loads(v1.replace("PRIMS", ""))
    plain = """
version = 1
[[segments]]
name = "a"
primitives = [{type = "mesh", generator = "cube"}]
"""
    with pytest.raises(SceneError, match="3-D primitive: it needs version = 2"):
        loads(plain)
    no_camera = plain.replace("version = 1", "version = 2")
    with pytest.raises(SceneError, match="add \\[\\[cameras\\]\\]"):
        loads(no_camera)
    assert loads(plain.replace('{type = "mesh", generator = "cube"}',
                               '{type = "polyline", points = [[0, 0], [5, 5]]}')).raster()


@pytest.mark.parametrize("change, path, words", [
    (('fov = {degrees = 50}', 'fov = {degrees = 0}'), "cameras[0].projection", "fov"),
    (('near = 1, far = 20', 'near = 5, far = 2'), "cameras[0].projection", "far must be greater"),
    (('eye = [3, 2, 4]', 'eye = [0, 0, 0]'), "cameras[0]", "same point"),
    (('eye = [3, 2, 4]', 'eye = [0, 5, 0]\nup = [0, 2, 0]'), "cameras[0]", "parallel"),
    (('type = "perspective"', 'type = "fisheye"'), "cameras[0].projection.type", "one of"),
    (('PRIMS', '{type = "mesh", generator = "cone"}'), "segments[0].primitives[0].generator",
     "one of"),
    (('PRIMS', '{type = "mesh", generator = "cube", radius = 2}'),
     "segments[0].primitives[0].radius", "not a key of the cube"),
    (('PRIMS', '{type = "mesh", generator = "sphere", resolution = [100000, 4]}'),
     "segments[0].primitives[0].resolution[0]", "at most"),
    (('PRIMS', '{type = "mesh", generator = "teapot", n = 1000}'),
     "segments[0].primitives[0].n", "at most"),
    (('PRIMS', '{type = "mesh"}'), "segments[0].primitives[0]", "either file"),
    (('PRIMS', '{type = "mesh", generator = "cube", transform = [{rotate = {degrees = 9, '
               'axis = "w"}}]}'), "segments[0].primitives[0].transform[0].rotate", "axis"),
    (('PRIMS', '{type = "polyline3d", points = [[0, 0]]}'),
     "segments[0].primitives[0].points[0]", "3 numbers"),
    (('name = "s"', 'name = "s"\ncamera = "other"'), "segments[0].camera", "names no camera"),
    (('PRIMS', '{type = "mesh", file = "missing.obj"}'), "segments[0].primitives[0].file",
     "cannot read"),
])
def test_errors_name_the_key_path(change, path, words):
    text = BASE.replace(*change).replace("PRIMS", '{type = "mesh", generator = "cube"}')
    with pytest.raises(SceneError) as info:
        loads(text)
    assert info.value.path.startswith(path) or str(info.value).startswith(path), str(info.value)
    assert words in str(info.value)


def test_display_file_cameras_are_looked_up_at_each_interpretation():
    df = sl.DisplayFile()
    df.set_camera(sl.Camera(eye=(0, 0, 5), target=(0, 0, 0)))
    df.create_segment("a")
    df.mesh(sl.mesh.cube())
    df.close_segment()
    first = sl.FrameBuffer(40, 40)
    df.draw(first)
    df.set_camera(sl.Camera(eye=(4, 3, 3), target=(0, 0, 0)))     # replaces "camera"
    second = sl.FrameBuffer(40, 40)
    df.draw(second)
    ref = sl.FrameBuffer(40, 40)
    sl.draw3d.wireframe(ref, sl.mesh.cube(), sl.Camera(eye=(4, 3, 3), target=(0, 0, 0)))
    assert (second.to_array() == ref.to_array()).all()
    assert (first.to_array() != second.to_array()).any()
    with pytest.raises(sl.ScanlineError, match="set_camera"):
        d2 = sl.DisplayFile()
        d2.create_segment("x")
        d2.mesh(sl.mesh.cube())


def test_svg_and_vector_listing_of_a_3d_scene(tmp_path):
    path = os.path.join(SCENES, "oblique.toml")
    for ext in (".svg", ".txt"):
        out = tmp_path / ("o" + ext)
        assert main(["render", path, "-o", str(out)]) == 0
        text = out.read_text()
        assert text.count("LINE") >= 24 if ext == ".txt" else "<svg" in text


# -- fuzzing ---------------------------------------------------------------------------------
scalars = st.one_of(
    st.none(), st.booleans(), st.integers(-10**6, 10**6), st.floats(allow_nan=True),
    st.text(max_size=6),
    st.sampled_from(["mesh", "polyline3d", "cube", "sphere", "torus", "teapot", "sweep", "box",
                     "superellipsoid", "supertoroid", "ellipsoid", "perspective", "frustum",
                     "orthographic", "isometric", "dimetric", "trimetric", "oblique",
                     "parallel", "cabinet", "cavalier", "top", "side", "x", "y", "z", "xy",
                     "rotational", "translational", "cam", "red", "missing.obj"]))
keys = ["type", "generator", "file", "transform", "depth_cue", "color", "width", "dash",
        "points", "closed", "size", "center", "lo", "hi", "radius", "radii", "resolution",
        "major", "minor", "s1", "s2", "r", "kind", "profile", "vector", "axis", "angle",
        "steps", "caps", "n", "parts", "name", "eye", "target", "up", "view_reference_point",
        "view_plane_normal", "view_up", "projection", "viewport", "keep_aspect", "fov",
        "aspect", "near", "far", "z_prp", "z_vp", "window", "front", "back", "prp", "view",
        "fz", "phi", "theta", "alpha", "direction", "degrees", "radians", "translate",
        "rotate", "scale", "reflect", "shear", "matrix", "factors", "fixed", "point",
        "normal", "a", "b", "reference", "pivot", "camera", "primitives"]
values = st.recursive(scalars, lambda c: st.one_of(st.lists(c, max_size=4),
                                                   st.dictionaries(st.sampled_from(keys), c,
                                                                   max_size=4)),
                      max_leaves=16)


def _render(data):
    try:
        s = Scene(data)
        s.raster()
        s.svg()
    except sl.ScanlineError:
        pass


@HYPOTHESIS
@given(st.lists(values, max_size=3), st.lists(values, max_size=3))
def test_fuzzed_version_2_scenes_never_crash(cams, prims):
    _render({"version": 2, "canvas": {"width": 24, "height": 16}, "cameras": cams,
             "segments": [{"name": "s", "primitives": prims}]})


@HYPOTHESIS
@given(st.sampled_from(["cube", "sphere", "torus", "teapot", "sweep"]),
       st.dictionaries(st.sampled_from(keys), values, max_size=3))
def test_fuzzed_generators_never_crash(gen, extra):
    prim = {"type": "mesh", "generator": gen, **extra}
    if gen == "sweep":
        prim.setdefault("profile", [[0, 0], [1, 0], [1, 1]])
    _render({"version": 2, "canvas": {"width": 24, "height": 16},
             "cameras": [{"eye": [3, 2, 4], "target": [0, 0, 0]}],
             "segments": [{"name": "s", "primitives": [prim]}]})


def test_display_file_meshes_take_other_libraries_meshes():
    import trimesh
    box = trimesh.creation.box(extents=(2, 2, 2))
    cam = sl.Camera(eye=(4, 3, 3), target=(0, 0, 0))
    df = sl.DisplayFile()
    df.set_camera(cam)
    df.create_segment("a")
    df.mesh(box)
    df.close_segment()
    got = sl.FrameBuffer(40, 40)
    df.draw(got)
    ref = sl.FrameBuffer(40, 40)
    sl.draw3d.wireframe(ref, sl.mesh.Mesh(np.asarray(box.vertices), np.asarray(box.faces)), cam)
    assert (got.to_array() == ref.to_array()).all() and got.to_array().any()
    with pytest.raises(TypeError, match="trimesh"):
        df.mesh("cube.obj")
