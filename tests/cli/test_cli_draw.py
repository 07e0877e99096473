"""``scanline draw``: the ITEMS language, the image written, and its errors."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from PIL import Image

import scanline as sl
from scanline.cli import draw, main
from scanline.cli.draw import parse_items
from scanline.framebuffer import MODES


def _api_image(size, mode="RGB", background="black", build=lambda fb: None):
    fb = sl.FrameBuffer(*size, mode=mode, background=background)
    build(fb)
    return fb


def _read(path):
    return np.array(Image.open(path))


def test_the_issue_example_matches_the_api(run, tmp_path):
    result = run("draw", "--size", "64x48", "line", "2", "3", "60", "40",
                 "circle", "32", "24", "15", "-o", "out.png", cwd=tmp_path)
    assert (result.code, result.out, result.err) == (0, "", "")

    def build(fb):
        sl.draw.line(fb, 2, 3, 60, 40)
        sl.draw.circle(fb, 32, 24, 15)

    expected = _api_image((64, 48), build=build).to_array()  # image order, top row first
    assert np.array_equal(_read(tmp_path / "out.png"), expected)
    assert expected[47 - 3, 2].tolist() == [255, 255, 255]  # (2, 3) lit, seen bottom-up


def _everything(fb, colors):
    """The API calls that ITEMS_EVERYTHING stands for, in ``colors`` (two of them)."""
    sl.draw.line(fb, -5, 3, 40, -2)
    sl.draw.line(fb, 0, 0, 14, 7, color=colors[0], method="dda")
    sl.draw.ellipse(fb, 20, 12, 15, 8, color=colors[0])
    sl.draw.circle(fb, 2.5, 30.4, 6, color=colors[1])
    fb.set_pixel(39, 31, colors[1])
    sl.draw.line(fb, 39, 0, 0, 31, color=colors[1], method="dda")


def _everything_items(colors):
    return ("line -5 3 40 -2 "
            f"color {colors[0]} method dda line 0 0 14 7 ellipse 20 12 15 8 "
            f"color {colors[1]} circle 2.5 30.4 6 point 39 31 line 39 0 0 31").split()


@pytest.mark.parametrize("mode, colors, background", [
    ("RGB", ("red", "#00a0ff"), "navy"),
    ("RGBA", ("red", "#00a0ff80"), "black"),
    ("L", ("128", "gray"), "black"),
    ("1", ("0", "1"), "white"),
    ("P", ("red", "#00a0ff"), "black"),
])
def test_pixels_match_the_api(call, tmp_path, mode, colors, background):
    out = tmp_path / "x.png"
    result = call("draw", "--size", "40x32", "--mode", mode, "--background", background,
                  *_everything_items(colors), "-o", out)
    assert (result.code, result.err) == (0, "")
    parsed = [int(c) if c.isdigit() else c for c in colors]
    fb = _api_image((40, 32), mode, background, lambda fb: _everything(fb, parsed))
    image = Image.open(out)
    assert image.mode == mode
    assert np.array_equal(np.array(image), fb.to_array())
    if mode == "P":
        assert image.getpalette()[:3 * len(fb.color_table)] == fb.color_table.ravel().tolist()


@pytest.mark.parametrize("suffix", [".png", ".gif", ".bmp"])
def test_scale_and_format(call, tmp_path, suffix):
    out = tmp_path / f"x{suffix}"
    assert call("draw", "--size", "9x5", "--scale", "3", "--mode", "L", "line", "0", "0",
                "8", "4", "-o", out).code == 0
    fb = _api_image((9, 5), "L", build=lambda fb: sl.draw.line(fb, 0, 0, 8, 4))
    expected = np.repeat(np.repeat(fb.to_array(), 3, axis=0), 3, axis=1)
    assert np.array_equal(np.array(Image.open(out).convert("L")), expected)


def test_options_may_come_first_or_last(call, tmp_path):
    first, last = tmp_path / "first.png", tmp_path / "last.png"
    assert call("draw", "-o", first, "--size", "8x8", "circle", "4", "4", "3").code == 0
    assert call("draw", "circle", "4", "4", "3", "--size", "8x8", "-o", last).code == 0
    assert np.array_equal(_read(first), _read(last))


def test_modes_are_those_of_the_frame_buffer():
    assert draw.MODES == MODES


def test_parse_items():
    assert parse_items("color 7 method dda line 1 -2 3.5 4 point 0 -1e3".split()) == [
        ("color", (7,), 1, "color 7"), ("method", ("dda",), 3, "method dda"),
        ("line", (1, -2, 3.5, 4), 5, "line 1 -2 3.5 4"),
        ("point", (0, -1000.0), 10, "point 0 -1e3"),
    ]


@pytest.mark.parametrize("items, fragments", [
    ("circle 1 2", ["ITEMS word 1", "circle needs XC YC R", "'circle 1 2'"]),
    ("line 0 0 5 5 circle 1 2 point 3 3", ["ITEMS word 6", "circle needs XC YC R"]),
    ("cirle 1 2 3", ["ITEMS word 1", "'cirle'", "line, circle, ellipse"]),
    ("line 1 2 3 x", ["ITEMS word 5", "Y1 of line must be a number", "'x'"]),
    ("line 1 2 3 4 5", ["ITEMS word 6", "'5'", "'line 1 2 3 4' takes only X0 Y0 X1 Y1"]),
    ("point 1 1 color", ["ITEMS word 4", "color needs NAME"]),
])
def test_parse_errors_name_the_item_and_position(items, fragments):
    with pytest.raises(ValueError) as info:
        parse_items(items.split())
    for fragment in fragments:
        assert fragment in str(info.value)


@pytest.mark.parametrize("items, fragments", [
    ("circle 1 2", ["ITEMS word 1", "circle needs XC YC R"]),
    ("point 1 1 circle 1 2 -3", ["ITEMS word 4 (circle 1 2 -3)", "r must be >= 0"]),
    ("color nosuch line 0 0 1 1", ["ITEMS word 1 (color nosuch)", "not a known color"]),
    ("method fast line 0 0 1 1", ["ITEMS word 1 (method fast)", "'bresenham', 'dda'"]),
    ("line 0 0 nan 1", ["ITEMS word 1 (line 0 0 nan 1)", "finite"]),
    ("circle -1e400 0 3", ["ITEMS word 1 (circle -1e400 0 3)", "xc must be a finite number"]),
    ("ellipse 0 0 -3 5", ["ITEMS word 1", "rx must be >= 0"]),
])
def test_bad_items_exit_2_and_write_nothing(cli, one_line_error, tmp_path, items, fragments):
    result = cli("draw", "--size", "16x16", *items.split(), "-o", tmp_path / "out.png")
    one_line_error(result, *fragments)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("args, fragments", [
    (["-o", "{tmp}/out.xyz"], ["-o/--output", "'.xyz'", ".png, .jpg"]),   # .jpg written since issue 16
    (["-o", "{tmp}/missing/out.png"], ["-o/--output", "does not exist"]),
    (["--background", "nosuch", "-o", "{tmp}/out.png"], ["background='nosuch'"]),
    (["--size", "0x5", "-o", "{tmp}/out.png"], ["width must be >= 1"]),
])
def test_bad_options_exit_2_and_write_nothing(call, one_line_error, tmp_path, args, fragments):
    args = [a.format(tmp=tmp_path) for a in args]
    one_line_error(call("draw", "point", "1", "1", *args), *fragments)
    assert list(tmp_path.iterdir()) == []


def test_a_failed_write_leaves_the_old_file(call, tmp_path, monkeypatch):
    out = tmp_path / "out.png"
    out.write_bytes(b"old")

    def full_disk(self, fp, *args, **kwargs):
        fp.write(b"partial")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(Image.Image, "save", full_disk)
    result = call("draw", "point", "1", "1", "-o", out)
    assert result.code == 2 and "No space left on device" in result.err
    assert out.read_bytes() == b"old"
    assert [p.name for p in tmp_path.iterdir()] == ["out.png"]


_WORDS = ["line", "circle", "ellipse", "point", "color", "method", "red", "dda", "x", "-1",
          "0", "3", "2.5", "1e9", "nan", "-0.5", "#fff", "999999999999"]


@settings(max_examples=150, deadline=None)
@given(st.lists(st.sampled_from(_WORDS), min_size=1, max_size=12))
def test_any_items_draw_or_fail_cleanly(tmp_path_factory, words):
    out = tmp_path_factory.mktemp("fuzz") / "out.png"
    try:
        parse_items(words)
    except ValueError as exc:
        assert str(exc).startswith("ITEMS word ")
    code = main(["draw", "--size", "12x9", *words, "-o", str(out)])
    assert code in (0, 2)
    assert out.exists() == (code == 0)
