"""Bad fonts and bad attributes get clear errors; missing characters never raise."""

import math
import shutil

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanline as sl
from scanline.errors import ArgumentTypeError, ArgumentValueError
from scanline.text import catalog

TTF = catalog.DATA / "DejaVuSans.ttf"


@pytest.fixture
def fb():
    return sl.FrameBuffer(40, 20)


def test_unknown_font_name(fb):
    with pytest.raises(ArgumentValueError, match=r"font='helvetica' .*'sans'"):
        sl.draw.text(fb, 0, 0, "x", font="helvetica")


def test_missing_font_file(fb, tmp_path):
    with pytest.raises(ArgumentValueError, match="does not exist"):
        sl.draw.text(fb, 0, 0, "x", font=str(tmp_path / "nothing.ttf"))


@pytest.mark.parametrize("content", [b"", b"garbage" * 100, b"\x00\x01\x00\x00" + b"\xff" * 64,
                                     b"OTTO" + bytes(200)])
def test_garbage_font_files(tmp_path, content):
    path = tmp_path / "bad.ttf"
    path.write_bytes(content)
    with pytest.raises(ArgumentValueError, match="not a readable TrueType/OpenType font"):
        sl.text.load_font(path)


@pytest.mark.parametrize("keep", [0.05, 0.3, 0.6, 0.95])
def test_truncated_font_file(tmp_path, keep):
    data = TTF.read_bytes()
    path = tmp_path / "cut.ttf"
    path.write_bytes(data[:int(len(data) * keep)])
    with pytest.raises(ArgumentValueError, match="cut.ttf"):
        sl.text.load_font(path)


def test_corrupt_glyph_draws_a_box_not_a_traceback(tmp_path):
    """A glyph whose data is garbage (but inside the file) is drawn as the box."""
    from fontTools.ttLib import TTFont
    font = TTFont(TTF)
    name = font.getBestCmap()[ord("A")]
    path = tmp_path / "copy.ttf"
    shutil.copy(TTF, path)
    f = sl.text.load_font(path)
    glyf = f._font["glyf"]
    glyf.glyphs[name] = type(glyf.glyphs[name])(b"\x00\x05\xff\xff" + b"\x07" * 9)
    fb = sl.FrameBuffer(40, 30, mode="1")
    sl.draw.text(fb, 2, 2, "A", font=f, height=20)
    box = sl.FrameBuffer(40, 30, mode="1")
    sl.draw.text(box, 2, 2, "\uffff", font=f, height=20)
    assert (fb.to_array() == box.to_array()).all() and box.to_array().sum() > 0


@pytest.mark.parametrize("height", [0, -3, math.nan, math.inf, 2.0 ** 21])
def test_bad_height_values(fb, height):
    with pytest.raises(ArgumentValueError, match="height"):
        sl.draw.text(fb, 0, 0, "x", height=height)


@pytest.mark.parametrize("height", ["12", True, [12]])
def test_bad_height_types(fb, height):
    with pytest.raises(ArgumentTypeError, match="height"):
        sl.draw.text(fb, 0, 0, "x", height=height)


@pytest.mark.parametrize("kw, name", [
    ({"path": "sideways"}, "path"), ({"align": ("middle", "base")}, "horizontal"),
    ({"align": ("left", "middle")}, "vertical"), ({"align": 3}, "align"),
    ({"expansion": 0}, "expansion"), ({"spacing": math.nan}, "spacing"),
    ({"angle": math.inf}, "angle"), ({"up": (0, 0)}, "up"), ({"up": "north"}, "up"),
    ({"angle": 1.0, "up": (0, 1)}, "angle or up"), ({"antialias": "yes"}, "antialias"),
    ({"color": "nocolor"}, "color"), ({"font": 12}, "font"), ({"style": "bold"}, "style"),
])
def test_bad_attributes_name_the_argument(fb, kw, name):
    with pytest.raises((ArgumentValueError, ArgumentTypeError), match=name):
        sl.draw.text(fb, 0, 0, "x", **kw)


def test_bad_text_and_target(fb):
    with pytest.raises(ArgumentTypeError, match="text"):
        sl.draw.text(fb, 0, 0, 42)
    with pytest.raises(ArgumentTypeError, match="fb"):
        sl.draw.text(np.zeros((4, 4)), 0, 0, "x")
    with pytest.raises(ArgumentValueError, match="x"):
        sl.draw.text(fb, math.nan, 0, "x")


@pytest.mark.parametrize("font", ["sans", "bitmap", "stroke"])
def test_missing_characters_are_boxes(font):
    text = "a\u4e00\U00020000\ud800b"       # CJK, CJK extension B, a lone surrogate
    glyphs = sl.text.layout(text, 0, 0, font=font, height=14)
    f = sl.text.fonts()[font]
    assert [g.glyph == f.replacement for g in glyphs] == [False, True, True, True, False]
    fb = sl.FrameBuffer(120, 30, mode="1")
    sl.draw.text(fb, 2, 8, text, font=font, height=14)
    for g in glyphs[1:4]:
        x0, y0, x1, y1 = g.box
        region = fb.to_array()[::-1][int(y0):int(y1) + 1, int(x0):int(x1) + 1]
        assert region.sum() > 10          # the box is visible


@settings(max_examples=60, deadline=None)
@given(st.text(max_size=12), st.floats(allow_nan=True, allow_infinity=True),
       st.floats(-1e12, 1e12), st.sampled_from(["sans", "bitmap", "stroke"]),
       st.floats(0.5, 300), st.floats(-10, 10), st.booleans())
def test_fuzz_never_crashes(text, x, y, font, height, angle, antialias):
    fb = sl.FrameBuffer(16, 8, mode="RGB")
    try:
        sl.draw.text(fb, x, y, text, font=font, height=height, angle=angle,
                     antialias=antialias)
    except ArgumentValueError as exc:
        assert "x" in str(exc) or "y" in str(exc)


def test_astral_characters_the_font_has_are_found():
    sans = sl.text.fonts()["sans"]
    assert sans.has_glyph("\U0001f600") and not sans.has_glyph("\U00020000")
