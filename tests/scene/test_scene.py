"""Scene files: the examples render, TOML and JSON round trips, errors with file, line
and key path, no partial output, the render/check commands, and fuzzed scenes."""

import glob
import json
import math
import os
import re
import sys

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from scanline.cli import main
from scanline.scene import Scene, SceneError, dumps, load, loads, parse, read
from tests.reference import HYPOTHESIS

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLES = sorted(glob.glob(os.path.join(ROOT, "examples", "scenes", "*.toml")))

MINIMAL = """
version = 1
canvas = {width = 20, height = 10, background = "black"}
[[segments]]
name = "a"
primitives = [{type = "polyline", points = [[0, 0], [19, 9]]}]
"""


# -- examples ---------------------------------------------------------------------------------
def test_there_are_examples():
    names = {os.path.basename(p) for p in EXAMPLES}
    assert {"translation.toml", "rotation.toml", "line_clipping.toml",
            "polygon_clipping.toml", "viewports.toml"} <= names


@pytest.mark.parametrize("path", EXAMPLES, ids=os.path.basename)
def test_every_example_renders(path, tmp_path):
    scene = load(path)
    shaded = scene.canvas.shading is not None and scene.canvas.shading.surfaces
    for ext in (".png", ".svg", ".txt"):
        out = tmp_path / ("out" + ext)
        if shaded and ext != ".png":
            # shaded surfaces draw on raster devices only: a clear error, no file
            assert main(["render", path, "-o", str(out)]) != 0
            assert not out.exists()
            continue
        assert main(["render", path, "-o", str(out)]) == 0
        assert out.stat().st_size > 100
    fb = scene.raster()
    assert len(np.unique(fb.to_array().reshape(-1, 3), axis=0)) > 2


@pytest.mark.parametrize("path", EXAMPLES, ids=os.path.basename)
def test_round_trip_toml_json(path, tmp_path):
    data = read(path)
    as_json = dumps(data, "json")
    assert json.loads(as_json) == data
    as_toml = dumps(data, "toml")
    assert tomllib.loads(as_toml) == data
    (tmp_path / "s.json").write_text(as_json)
    (tmp_path / "s.toml").write_text(as_toml)
    a = load(path).raster().to_array()
    assert (load(tmp_path / "s.json").raster().to_array() == a).all()
    assert (load(tmp_path / "s.toml").raster().to_array() == a).all()


def test_translation_example_moves_by_the_vector():
    """The 'after' segment is the 'before' polygon moved by (-5.5, 3.75) world units."""
    scene = load(os.path.join(ROOT, "examples", "scenes", "translation.toml"))
    df = scene.display_file
    before = df.segment("before").primitives[0].geometry["contours"][0]
    after = df.segment("after")
    moved = sl.transform.apply(after.transformation, before)
    n = df.normalization  # world -> NDC of the (single) viewport
    shift = sl.transform.apply(n, (-5.5, 3.75)) - sl.transform.apply(n, (0, 0))
    assert np.allclose(moved - before, shift, atol=1e-12)


def test_rotation_example_turns_about_the_pivot():
    scene = load(os.path.join(ROOT, "examples", "scenes", "rotation.toml"))
    df = scene.display_file
    world = np.array([(10, 3), (14, 4), (11, 7)], float)
    n = df.normalization
    got = sl.transform.apply(df.segment("rotated").transformation, sl.transform.apply(n, world))
    # the notes' equations (chapter 3, Q.2) with xr, yr = 6, 4 and 60 degrees
    c, s = math.cos(math.radians(60)), math.sin(math.radians(60))
    x, y = world[:, 0], world[:, 1]
    expected = np.column_stack([6 + (x - 6) * c - (y - 4) * s, 4 + (x - 6) * s + (y - 4) * c])
    assert np.allclose(got, sl.transform.apply(n, expected), atol=1e-12)


# -- the schema ---------------------------------------------------------------------------------
def test_minimal_scene_draws():
    fb = loads(MINIMAL).raster()
    assert fb.size == (20, 10)
    assert fb.get_pixel(0, 0) == (255, 255, 255) and fb.get_pixel(19, 9) == (255, 255, 255)


def test_transform_steps_apply_in_listed_order():
    text = MINIMAL.replace('name = "a"', 'name = "a"\ntransform = [{scale = 2}, {translate = [1, 0]}]')
    m = loads(text).display_file.segment("a").transformation
    n = loads(MINIMAL).display_file.normalization
    world = sl.transform.compose(sl.transform.translation(1, 0), sl.transform.scaling(2))
    assert np.allclose(m, n @ world @ sl.transform.inverse(n))


def test_several_viewports_copy_the_segment():
    text = """
version = 1
canvas = {width = 20, height = 10}
[[viewports]]
name = "l"
viewport = [0, 0, 0.5, 1]
[[viewports]]
name = "r"
viewport = [0.5, 0, 1, 1]
[[segments]]
name = "s"
viewport = ["l", "r"]
primitives = [{type = "markers", points = [[5, 5]]}]
"""
    df = loads(text).display_file
    assert [s.name for s in df.segments] == ["s@l", "s@r"]


_C30, _S30 = math.sqrt(3) / 2, 0.5
_C05, _S05 = math.cos(0.5), math.sin(0.5)


@pytest.mark.parametrize("step, expected", [
    ("{rotate = {degrees = 30}}", [[_C30, -_S30, 0], [_S30, _C30, 0]]),
    # T(1, 2) R(0.5) T(-1, -2)
    ("{rotate = {radians = 0.5, pivot = [1, 2]}}",
     [[_C05, -_S05, 1 - _C05 + 2 * _S05], [_S05, _C05, 2 - _S05 - 2 * _C05]]),
    ("{scale = [2, 3]}", [[2, 0, 0], [0, 3, 0]]),
    ("{scale = {factors = [2, 1], fixed = [3, 3]}}", [[2, 0, -3], [0, 1, 0]]),
    ("{reflect = \"y=x\"}", [[0, 1, 0], [1, 0, 0]]),
    # about the line y = x + 1: (x, y) -> (y - 1, x + 1)
    ("{reflect = {point = [0, 1], direction = [1, 1]}}", [[0, 1, -1], [1, 0, 1]]),
    # x' = x + 0.5 (y - 2)
    ("{shear = {x = 0.5, reference = [0, 2]}}", [[1, 0.5, -1], [0, 1, 0]]),
    ("{matrix = [[1, 0, 2], [0, 1, 3], [0, 0, 1]]}", [[1, 0, 2], [0, 1, 3]]),
])
def test_every_transformation_step_gives_its_matrix(step, expected):
    """Each step becomes the segment transformation derived by hand (in world
    coordinates: the display file stores N·M·N⁻¹ for the normalization N)."""
    df = loads(MINIMAL.replace('name = "a"', f'name = "a"\ntransform = [{step}]')).display_file
    n = df.normalization
    world = np.linalg.inv(n) @ df.segment("a").transformation @ n
    np.testing.assert_allclose(world, np.array(expected + [[0, 0, 1]], float), atol=1e-12)


BAD = [
    # (replace this, with this, expected key path, expected words)
    ("version = 1", "version = 3", "version", "must be 1 or 2"),
    ("version = 1", "", None, "needs the key 'version'"),
    ('name = "a"', 'name = "a"\ncolour = 3', "segments[0].colour", "not a known key"),
    ("[[0, 0], [19, 9]]", "[[0, 0], [19]]", "segments[0].primitives[0].points", "points"),
    ("[[0, 0], [19, 9]]", '"many"', "segments[0].primitives[0].points", "points"),
    ('type = "polyline"', 'type = "spline"', "segments[0].primitives[0].type", "must be one of"),
    ('type = "polyline", points = [[0, 0], [19, 9]]', 'type = "polyline"',
     "segments[0].primitives[0]", "needs the key 'points'"),
    ("[19, 9]]}", '[19, 9]], color = "octarine"}', "segments[0].primitives[0].color",
     "not a known color"),
    ("[19, 9]]}", "[19, 9]], width = -2}", "segments[0].primitives[0].width", "width"),
    ("[19, 9]]}", '[19, 9]], dash = "wavy"}', "segments[0].primitives[0].dash", "dash"),
    ('name = "a"', 'name = "a"\ntransform = [{rotate = 30}]', "segments[0].transform[0].rotate",
     "must say its unit"),
    ('name = "a"', 'name = "a"\ntransform = [{rotate = {angle = 30}}]',
     "segments[0].transform[0].rotate.angle", "not a known key"),
    ('name = "a"', 'name = "a"\ntransform = [{spin = 1}]', "segments[0].transform[0]",
     "unknown transformation 'spin'"),
    ('name = "a"', 'name = "a"\ntransform = [{scale = {factors = [0, 1], fixed = "x"}}]',
     "segments[0].transform[0].scale.fixed", "point"),
    ('name = "a"', 'name = "a"\nviewport = "side"', "segments[0].viewport", "names no viewport"),
    ('name = "a"', 'name = "a"\npriority = "high"', "segments[0].priority", "real number"),
    ('name = "a"', 'name = "a"\nvisible = 1', "segments[0].visible", "true or false"),
    ("width = 20", "width = 0", "canvas.width", "from 2 to"),
    ("width = 20", "width = 100000", "canvas.width", "from 2 to"),
    ('background = "black"', 'background = "nope"', "canvas.background", "not a known color"),
    ("[[segments]]", "window = [0, 0, 0, 5]\n[[segments]]", "viewports[0].window", "degenerate"),
]


@pytest.mark.parametrize("old, new, path, words", BAD)
def test_errors_name_the_key_path(old, new, path, words, tmp_path):
    assert old in MINIMAL
    text = MINIMAL.replace(old, new, 1)
    f = tmp_path / "bad.toml"
    f.write_text(text)
    with pytest.raises(SceneError) as info:
        load(f)
    message = str(info.value)
    where = re.match(re.escape(str(f)) + r"(:\d+)?: ", message)
    assert where, message
    if path is not None:
        after = message[where.end():]
        assert after.startswith(path) and after[len(path)] in " .=[", message
    assert words in message


def test_value_errors_give_the_line_too(tmp_path):
    """The line of a bad value is found again in the text: TOML and JSON."""
    text = """version = 1
[[segments]]
name = "a"

[[segments.primitives]]
type = "polyline"
points = [[0, 0], [19, 9]]

[[segments]]
name = "b"

[[segments.primitives]]
type = "polyline"
points = [[0, 0], [19, 9]]

[[segments.primitives]]
type = "circle"
center = [1, 2]
radius = -3
"""
    f = tmp_path / "s.toml"
    f.write_text(text)
    with pytest.raises(SceneError) as info:
        load(f)
    lines = text.splitlines()
    assert "radius = -3" in lines[info.value.line - 1]
    assert info.value.line == 19
    assert "segments[1].primitives[1].radius must be >= 0" in str(info.value)
    j = tmp_path / "s.json"
    j.write_text(dumps(tomllib.loads(text), "json"))
    with pytest.raises(SceneError) as info:
        load(j)
    assert '"radius": -3' in j.read_text().splitlines()[info.value.line - 1]


def test_a_bad_point_is_named():
    text = MINIMAL.replace("[[0, 0], [19, 9]]", "[[0, 0], [19, 9], [4]]")
    with pytest.raises(SceneError, match=r"points\[2\] must be a point \[x, y\]"):
        loads(text)
    text = MINIMAL.replace('type = "polyline", points = [[0, 0], [19, 9]]',
                           'type = "polygon", points = [[0, 0], [19, 9], [4, "a"]]')
    with pytest.raises(SceneError, match=r"points\[2\] must be a point"):
        loads(text)


@pytest.mark.parametrize("old, new, path, words", BAD[:6])
def test_json_errors_name_the_key_path_too(old, new, path, words):
    data = tomllib.loads(MINIMAL.replace(old, new, 1))
    with pytest.raises(SceneError, match=words):
        loads(json.dumps(data), "json", file="s.json")


@pytest.mark.parametrize("name, text, kind", [
    ("bad.toml", "version = 1\n\n[canvas]\nwidth = = 3\n", "TOML"),
    ("bad.json", '{\n  "version": 1,\n  "segments": [\n    {"name": "a",}\n  ]\n}\n', "JSON"),
])
def test_syntax_errors_name_the_line(tmp_path, name, text, kind):
    f = tmp_path / name
    f.write_text(text)
    with pytest.raises(SceneError) as info:
        load(f)
    assert str(info.value).startswith(f"{f}:4: invalid {kind}")
    assert info.value.line == 4


def test_json_nan_is_refused():
    with pytest.raises(SceneError, match="NaN"):
        loads('{"version": 1, "canvas": {"width": NaN}}', "json")


def test_unknown_extension_and_missing_file(tmp_path):
    with pytest.raises(SceneError, match="use .toml or .json"):
        load(tmp_path / "scene.yaml")
    with pytest.raises(SceneError, match="cannot read"):
        load(tmp_path / "nothing.toml")


def test_not_utf8(tmp_path):
    f = tmp_path / "s.toml"
    f.write_bytes(b"version = 1\n# caf\xe9\n")
    with pytest.raises(SceneError, match="not UTF-8") as info:
        load(f)
    assert info.value.line == 2


# -- the command line -----------------------------------------------------------------------------
def test_check_command(tmp_path, capsys):
    good = tmp_path / "good.toml"
    good.write_text(MINIMAL)
    assert main(["check", str(good)]) == 0
    assert "good.toml: ok (20x10, 1 segments, 1 primitives)" in capsys.readouterr().out
    bad = tmp_path / "bad.toml"
    bad.write_text(MINIMAL.replace("version = 1", "version = 9"))
    assert main(["check", str(good), str(bad)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("scanline: error: ") and "bad.toml:2: version must be 1" in err
    assert len(err.strip().splitlines()) == 1


@pytest.mark.parametrize("ext", [".png", ".svg", ".txt", ".gif"])
def test_render_error_leaves_no_output(tmp_path, capsys, ext):
    bad = tmp_path / "bad.toml"
    bad.write_text(MINIMAL.replace("[19, 9]]}", '[19, 9]], color = "octarine"}'))
    out = tmp_path / ("out" + ext)
    assert main(["render", str(bad), "-o", str(out)]) == 2
    assert "segments[0].primitives[0].color" in capsys.readouterr().err
    assert not out.exists()
    assert os.listdir(tmp_path) == ["bad.toml"]  # no temporary file left either


def test_render_error_keeps_an_existing_output(tmp_path):
    good, bad = tmp_path / "good.toml", tmp_path / "bad.toml"
    good.write_text(MINIMAL)
    bad.write_text(MINIMAL.replace('"black"', '"nope"'))
    out = tmp_path / "out.png"
    assert main(["render", str(good), "-o", str(out)]) == 0
    before = out.read_bytes()
    assert main(["render", str(bad), "-o", str(out)]) == 2
    assert out.read_bytes() == before


def test_render_to_unknown_type(tmp_path, capsys):
    good = tmp_path / "good.toml"
    good.write_text(MINIMAL)
    assert main(["render", str(good), "-o", str(tmp_path / "out.jpg")]) == 2
    assert "cannot write" in capsys.readouterr().err
    assert not (tmp_path / "out.jpg").exists()


def test_text_path_key_reaches_the_text():
    """A text primitive's ``path`` (its direction) is passed to the display file (it
    collided with the error helper's own ``path`` argument: a raw TypeError)."""
    scene = MINIMAL.replace(
        "[{type = \"polyline\", points = [[0, 0], [19, 9]]}]",
        "[{type = \"text\", position = [2, 1], string = \"AB\", height = 3, "
        "font = \"bitmap\", path = \"PATH\"}]")
    up = loads(scene.replace("PATH", "up")).raster().to_array()
    right = loads(scene.replace("PATH", "right")).raster().to_array()
    rows_up, cols_up = np.nonzero(up.any(axis=2))
    rows_right, cols_right = np.nonzero(right.any(axis=2))
    # "up" stacks the two characters: taller than wide; "right" the other way round
    assert np.ptp(rows_up) > np.ptp(cols_up) and np.ptp(cols_right) > np.ptp(rows_right)


@pytest.mark.parametrize("ext", [".png", ".svg"])
def test_render_to_a_folder_names_it(tmp_path, capsys, ext):
    good = tmp_path / "good.toml"
    good.write_text(MINIMAL)
    (tmp_path / ("out" + ext)).mkdir()
    assert main(["render", str(good), "-o", str(tmp_path / ("out" + ext))]) == 2
    err = capsys.readouterr().err
    assert f"out{ext}': it is a folder" in err and ".tmp" not in err
    assert sorted(os.listdir(tmp_path)) == ["good.toml", "out" + ext]


def test_render_listing_is_the_vector_device(tmp_path):
    good = tmp_path / "good.toml"
    good.write_text(MINIMAL)
    out = tmp_path / "out.txt"
    assert main(["render", str(good), "-o", str(out)]) == 0
    assert out.read_text().splitlines()[1:] == ["COLOR 255 255 255 255", "MOVE 0 0", "LINE 19 9"]


# -- fuzzing -----------------------------------------------------------------------------------------
scalars = st.one_of(
    st.none(), st.booleans(), st.integers(-10**20, 10**20),
    st.floats(allow_nan=True, allow_infinity=True), st.text(max_size=8),
    st.sampled_from(["red", "polyline", "polygon", "text", "circle", "x", "main", "hatch:45:4",
                     "dashed", "round", "nonzero", "y=x", "#ff000080", "up", "left", "sans",
                     "bitmap", "stroke", "center", "half", "hollow", "character", "string",
                     "RGBA", "P", "1", "markers", "ellipse", "asterisk", "origin"]),
)
values = st.recursive(
    scalars,
    lambda children: st.one_of(st.lists(children, max_size=5),
                               st.dictionaries(st.sampled_from(
                                   ["type", "points", "name", "color", "width", "center",
                                    "radius", "rx", "ry", "string", "position", "height",
                                    "degrees", "pivot", "translate", "rotate", "scale",
                                    "viewport", "window", "fill", "style", "dash", "edge",
                                    "align", "angle", "kind", "size", "primitives",
                                    "transform", "priority", "clip", "view_up", "x",
                                    # every other key of the schema (a text's "path"
                                    # once raised a raw TypeError)
                                    "path", "font", "expansion", "spacing", "rule",
                                    "closed", "cap", "join", "miter_limit", "dash_phase",
                                    "visible", "highlighted", "keep_aspect", "border",
                                    "background", "mode", "antialias", "highlight",
                                    "reflect", "shear", "matrix", "factors", "fixed",
                                    "point", "direction", "reference", "radians", "y",
                                    "version", "canvas", "segments", "viewports"]),
                                   children, max_size=5)),
    max_leaves=20,
)


def _render(data):
    try:
        scene = Scene(data)
        scene.raster()
        scene.svg()
        scene.vector()
    except sl.ScanlineError:
        pass


@HYPOTHESIS
@given(st.dictionaries(st.sampled_from(["version", "canvas", "window", "viewports",
                                        "segments", "extra"]), values, max_size=5))
def test_fuzzed_scene_structures_never_crash(data):
    _render(data)


def _small_example(draw):
    """One of the example scenes, on a small canvas."""
    data = tomllib.loads(open(EXAMPLES[draw(st.integers(0, len(EXAMPLES) - 1))]).read())
    data["canvas"] = {"width": 24, "height": 16}
    return data


@st.composite
def mutated_scenes(draw):
    """A valid scene with one value somewhere replaced by a random one."""
    data = _small_example(draw)
    node = data
    while True:
        keys = list(node) if isinstance(node, dict) else list(range(len(node)))
        if not keys:
            return data
        k = draw(st.sampled_from(keys))
        child = node[k]
        if isinstance(child, (dict, list)) and child and draw(st.booleans()):
            node = child
            continue
        node[k] = draw(values)
        return data


@HYPOTHESIS
@given(st.text(max_size=200))
def test_fuzzed_text_never_crashes(text):
    for fmt in ("toml", "json"):
        try:
            loads(text, fmt)
        except sl.ScanlineError:
            pass


def test_dumps_refuses_what_toml_cannot_hold():
    with pytest.raises(sl.ArgumentValueError):
        dumps({"x": float("nan")})
    with pytest.raises(sl.ArgumentValueError):
        dumps({"x": object()})
    assert parse(dumps({"a b": [1, {"c": "d"}], "t": {"u": True}})) == {
        "a b": [1, {"c": "d"}], "t": {"u": True}}


def test_drawing_error_names_the_segment_and_leaves_no_output(tmp_path, capsys):
    """An error found only while drawing (text 10^9 pixels high) names the segment
    and the primitive, and the output file is not written."""
    f = tmp_path / "big.toml"
    f.write_text(MINIMAL.replace(
        "[{type = \"polyline\", points = [[0, 0], [19, 9]]}]",
        "[{type = \"polyline\", points = [[0, 0], [19, 9]]},"
        " {type = \"text\", position = [1, 1], string = \"x\", height = 1e9}]"))
    assert main(["check", str(f)]) == 0
    out = tmp_path / "big.png"
    assert main(["render", str(f), "-o", str(out)]) == 2
    assert "segment 'a', primitive 1 (text): height" in capsys.readouterr().err
    assert not out.exists()


extreme = st.one_of(
    st.sampled_from([0, -0.0, 1e-300, -1e-300, 1e300, -1e300, 2**31, -2**31, 1e9, 1e15,
                     2**63, 10**30]),
    st.floats(-1e6, 1e6), st.integers(-10**6, 10**6))


def _numbers(node, prefix=()):
    """Key paths of the numbers in scene data."""
    if isinstance(node, dict):
        for k, x in node.items():
            yield from _numbers(x, prefix + (k,))
    elif isinstance(node, list):
        for i, x in enumerate(node):
            yield from _numbers(x, prefix + (i,))
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        yield prefix


@st.composite
def perturbed_scenes(draw):
    """A valid example with one to three of its numbers made extreme (radii of 1e300,
    scale factors of 0, coordinates of 2**63 ...)."""
    data = _small_example(draw)
    paths = [p for p in _numbers(data) if p[0] != "canvas"]
    for _ in range(draw(st.integers(1, 3))):
        *parents, last = draw(st.sampled_from(paths))
        node = data
        for k in parents:
            node = node[k]
        node[last] = draw(extreme)
    return data


@HYPOTHESIS
@given(st.one_of(mutated_scenes(), perturbed_scenes()))
def test_changed_examples_never_crash(data):
    _render(data)


@pytest.mark.parametrize("text, fmt", [("a = " + "[" * 50000 + "]" * 50000, "toml"),
                                       ("[" * 50000 + "]" * 50000, "json")])
def test_deep_nesting_is_an_error(text, fmt):
    with pytest.raises(SceneError, match="nested too deeply"):
        loads(text, fmt)


def test_deep_nesting_in_python_data_is_an_error():
    deep = []
    for _ in range(50000):
        deep = [deep]
    data = {"version": 1, "segments": [{"name": "a", "primitives": [
        {"type": "polyline", "points": [[0, 0], [1, 1]], "color": deep}]}]}
    with pytest.raises(SceneError, match="nested too deeply"):
        Scene(data)


def _keys(node, prefix=""):
    """Key paths (strings) of every table key in scene data."""
    if isinstance(node, dict):
        for k, x in node.items():
            here = f"{prefix}.{k}" if prefix else k
            yield here, k
            yield from _keys(x, here)
    elif isinstance(node, list):
        for i, x in enumerate(node):
            yield from _keys(x, f"{prefix}[{i}]")


@pytest.mark.parametrize("path", EXAMPLES, ids=os.path.basename)
def test_every_key_is_located_on_its_line(path):
    from scanline.scene.locate import line_of

    text = open(path).read()
    data = tomllib.loads(text)
    for fmt, source in (("toml", text), ("json", dumps(data, "json")),
                        ("toml", dumps(data, "toml"))):
        rows = source.splitlines()
        for key_path, key in _keys(data):
            line = line_of(source, fmt, key_path)
            assert line is not None, key_path
            row = rows[line - 1]
            assert key in row, (key_path, row)


def test_line_clipping_example_clips_p1_p2_as_the_notes_say():
    """P1 = (45, 5) below the window (20, 20)-(70, 60), P2 = (10, 90) left of and above
    it: the visible part runs from P1' = (45 - 35 * 15/85, 20) on the bottom edge to
    P2'' = (45 - 35 * 55/85, 60) on the top edge (the left-edge intersection, at
    y = 5 + 85 * 25/35 = 65.7, is still above the window)."""
    scene = load(os.path.join(ROOT, "examples", "scenes", "line_clipping.toml"))
    df = scene.display_file
    for seg in df.segments:  # show only the clipped lines
        df.set_visibility(seg.name, seg.name == "lines-clipped")
    first = scene.vector().lines()[0]
    ws = sl.viewing.ndc_to_device(scene.canvas.width, scene.canvas.height)
    n = ws @ sl.viewing.window_to_viewport((20, 20, 70, 60), (0.6, 0.2, 0.85, 0.6))
    expected = sl.transform.apply(n, [(45 - 35 * 15 / 85, 20), (45 - 35 * 55 / 85, 60)])
    assert 5 + 85 * 25 / 35 > 60
    assert np.allclose(first.reshape(2, 2), expected, atol=1e-6)
