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
from scanline.text.outline import OutlineFont

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


def tiny_ttf():
    """A small TrueType font: 'A' a triangle, 'B' a square, quadratic 'O'."""
    from fontTools.fontBuilder import FontBuilder
    from fontTools.pens.ttGlyphPen import TTGlyphPen

    fb = FontBuilder(1000, isTTF=True)
    names = [".notdef", "A", "B", "O"]
    fb.setupGlyphOrder(names)
    fb.setupCharacterMap({ord("A"): "A", ord("B"): "B", ord("O"): "O"})
    glyphs = {}
    for name in names:
        pen = TTGlyphPen(None)
        if name == "A":
            pen.moveTo((0, 0)); pen.lineTo((500, 700)); pen.lineTo((1000, 0)); pen.closePath()
        elif name == "B":
            pen.moveTo((0, 0)); pen.lineTo((0, 700)); pen.lineTo((600, 700))
            pen.lineTo((600, 0)); pen.closePath()
        elif name == "O":
            pen.moveTo((300, 0)); pen.qCurveTo((600, 0), (600, 350))
            pen.qCurveTo((600, 700), (300, 700)); pen.qCurveTo((0, 700), (0, 350))
            pen.qCurveTo((0, 0), (300, 0)); pen.closePath()
        glyphs[name] = pen.glyph()
    fb.setupGlyf(glyphs)
    fb.setupHorizontalMetrics({n: (700, 0) for n in names})
    fb.setupHorizontalHeader(ascent=800, descent=-200)
    fb.setupNameTable({"familyName": "Tiny", "styleName": "Regular"})
    fb.setupOS2(sTypoAscender=800, usWinAscent=800, usWinDescent=200)
    fb.setupPost()
    import io
    out = io.BytesIO()
    fb.save(out)
    return out.getvalue()


TINY = tiny_ttf()


def test_tiny_font_loads_and_draws(tmp_path):
    path = tmp_path / "tiny.ttf"
    path.write_bytes(TINY)
    f = sl.text.load_font(path)
    assert f.cap_height == 700        # no OS/2 cap height and no 'H': 0.7 em
    fb = sl.FrameBuffer(60, 30, mode="1")
    sl.draw.text(fb, 0, 0, "BAO?", font=f, height=14)
    assert fb.to_array()[::-1][1:15, 0:12].all()      # 'B' is a 12 x 14 block


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.integers(0, len(TINY) - 1), st.integers(0, 255)),
                min_size=1, max_size=8))
def test_fuzz_corrupted_font_files(tmp_path_factory, edits):
    data = bytearray(TINY)
    for pos, value in edits:
        data[pos] = value
    path = tmp_path_factory.mktemp("fuzz") / "bad.ttf"
    path.write_bytes(bytes(data))
    try:
        f = OutlineFont(str(path))     # not load_font: it caches by path
    except ArgumentValueError as exc:
        assert "bad.ttf" in str(exc)
        return
    fb = sl.FrameBuffer(40, 20, mode="L")
    for text in ("ABO", "x\u4e00"):
        try:
            sl.draw.text(fb, 1, 3, text, font=f, height=12)
            sl.draw.text(fb, 1, 3, text, font=f, height=12, antialias=True)
            sl.text.extents(text, font=f, height=12)
        except ArgumentValueError:
            pass   # e.g. metrics so wild that the layout leaves the coordinate range
