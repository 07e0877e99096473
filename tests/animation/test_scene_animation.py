"""Animated scene files (schema version 2) and the animate / storyboard commands."""

import math
import os

import numpy as np
import pytest
from PIL import Image

import scanline as sl
from scanline.cli import main
from scanline.scene import SceneError, loads_animated

EXAMPLE = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "scenes",
                       "bouncing_ball.toml")

BASE = """
version = 2
canvas = {width = 40, height = 20, background = "black"}

[[segments]]
name = "dot"
transform = [{translate = [0, 0]}]
primitives = [{type = "circle", center = [5, 10], radius = 3, fill = true, color = "white"}]

[animation]
fps = 10
"""

TRACK = BASE + """
[[animation.tracks]]
target = "segments[dot].transform[0].translate"
keys = [{time = 0, value = [0, 0], ease = "ease-in-quad"}, {time = 1, value = [30, 0]},
        {time = 2, value = [30, 5]}]
"""


def test_track_frames_match_a_static_scene():
    anim = loads_animated(TRACK)
    assert len(anim) == 21 and anim.fps == 10
    data = anim.data_at(5)
    # a key's ease shapes the segment that leaves it (as in CSS): 30 * 0.5**2
    assert data["segments"][0]["transform"][0]["translate"] == [7.5, 0.0]
    assert anim.data_at(15)["segments"][0]["transform"][0]["translate"] == [30.0, 2.5]
    static = sl.scene.loads(BASE.replace("version = 2", "version = 1")
                            .replace("[animation]\nfps = 10\n", "")
                            .replace("translate = [0, 0]", "translate = [7.5, 0.0]"))
    np.testing.assert_array_equal(anim.frame(5).to_array(), static.raster().to_array())
    assert anim.data_at(20)["segments"][0]["transform"][0]["translate"] == [30.0, 5.0]


def test_example_scene_paths_colors_and_morphs():
    anim = sl.scene.load_animated(EXAMPLE)
    assert len(anim) == 36
    first, last = anim.data_at(0), anim.data_at(35)
    ball = first["segments"][1]
    assert ball["transform"][1]["translate"] == pytest.approx([20, 22])
    heading = math.degrees(math.atan2(208, 80))               # the Bezier's first leg
    assert ball["transform"][0]["rotate"]["degrees"] == pytest.approx(heading, abs=1e-6)
    assert first["segments"][1]["primitives"][0]["color"] == [220, 20, 60, 255]   # crimson
    assert last["segments"][2]["primitives"][0]["points"][3] != [250, 180]
    # the morph equalizes the triangle to four vertices (the longest edge split)
    mid = anim.data_at(18)["segments"][2]["primitives"][0]["points"]
    assert len(mid) == 4
    assert len(anim.storyboard_frames()) == 3


def test_animate_command(tmp_path, capsys):
    out = tmp_path / "ball.gif"
    assert main(["animate", EXAMPLE, "-o", str(out), "--frames", "2:8"]) == 0
    assert "wrote" in capsys.readouterr().out
    with Image.open(out) as im:
        assert im.n_frames == 6 and im.size == (320, 200)
    jobs = tmp_path / "jobs.gif"
    assert main(["animate", EXAMPLE, "-o", str(jobs), "--frames", "2:8", "--jobs", "2"]) == 0
    assert jobs.read_bytes() == out.read_bytes()
    assert main(["animate", EXAMPLE, "-o", str(tmp_path / "fast.png"), "--fps", "24",
                 "--frames", ":3"]) == 0
    with Image.open(tmp_path / "fast.png") as im:
        assert im.n_frames == 3 and im.info["duration"] == pytest.approx(1000 / 24)
    assert main(["animate", EXAMPLE, "-o", str(tmp_path / "frames") + "/", "--frames", "0:3"]) == 0
    assert sorted(os.listdir(tmp_path / "frames")) == [f"frame-0000{i}.png" for i in range(3)]


def test_storyboard_command(tmp_path):
    board = tmp_path / "board.png"
    assert main(["storyboard", EXAMPLE, "-o", str(board), "--columns", "2",
                 "--panel", "160x100"]) == 0
    with Image.open(board) as im:
        assert im.width == 16 + 2 * (160 + 16)
        assert im.height > 2 * 100


@pytest.mark.parametrize("argv,words", [
    (["animate", EXAMPLE, "-o", "x.avi"], "no writer for '.avi'"),
    (["animate", EXAMPLE, "-o", "x.gif", "--frames", "9:3"], "0 <= A < B <= 36"),
    (["animate", EXAMPLE, "-o", "x.gif", "--jobs", "0"], "--jobs must be >= 1"),
    (["animate", EXAMPLE, "-o", "x.gif", "--jobs", "2", "--scheduler", "tcp://h:1"], "not both"),
    (["storyboard", EXAMPLE, "-o", "x.png", "--panel", "big"], "must be WxH"),
])
def test_command_errors(tmp_path, capsys, monkeypatch, argv, words):
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("scanline: error:") and words in err and len(err.splitlines()) == 1
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("replace,by,path,words", [
    ('{time = 1, value = [30, 0]}', '{time = 0, value = [30, 0]}',
     "animation.tracks[0].keys[1].time", "not after the previous key's 0"),
    ('ease = "ease-in-quad"', 'ease = "ease-in-wobble"', "animation.tracks[0].keys[0].ease",
     "not an easing"),
    ("segments[dot].transform[0].translate", "segments[dash].transform[0].translate",
     "animation.tracks[0].target", "no entry named 'dash'"),
    ("segments[dot].transform[0].translate", "segments[dot].transform[3].translate",
     "animation.tracks[0].target", "index [3]"),
    ("value = [30, 5]", "value = [30, 5, 1]", "animation.tracks[0].keys[2].value", "shape (3,)"),
    ("value = [30, 5]", "value = [30, nan]", "animation.tracks[0]", "finite"),
    ("keys = [", "kees = [", "animation.tracks[0].kees", "not a known key"),
    ("fps = 10", "fps = 0", "animation", "fps must be > 0"),
])
def test_scene_errors_name_the_key_and_line(replace, by, path, words):
    text = TRACK.replace(replace, by)
    assert text != TRACK
    with pytest.raises(SceneError) as info:
        loads_animated(text, file="film.toml")
    error = info.value
    assert error.path == path or error.path.startswith(path)
    assert words in str(error) and error.line is not None and str(error).startswith("film.toml:")


def test_version_one_has_no_animation_and_version_two_needs_it():
    with pytest.raises(SceneError, match="animation is not a known key"):
        sl.scene.loads(TRACK.replace("version = 2", "version = 1"))
    with pytest.raises(SceneError, match="animates nothing"):
        loads_animated(BASE)
    assert sl.scene.loads(TRACK).canvas.width == 40        # a static render ignores it
