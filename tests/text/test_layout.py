"""Text attributes: path, spacing, expansion, orientation and alignment, checked
with plain arithmetic on the fonts' metrics; layout agrees with drawing."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanline as sl


def origins(text, **kw):
    return np.array([g.origin for g in sl.text.layout(text, 100, 100, **kw)])


def test_path_right_advances_by_the_glyph_advances():
    # bitmap font: 6 dots a character, height 14 -> scale 2
    o = origins("abcd", font="bitmap", height=14)
    assert o.tolist() == [[100, 100], [112, 100], [124, 100], [136, 100]]


def test_spacing_and_expansion():
    o = origins("abc", font="bitmap", height=14, spacing=0.5, expansion=1.5)
    # advance 6 dots x 2 px x 1.5 + spacing 0.5 x 14
    assert o[:, 0].tolist() == [100, 125, 150]
    e = sl.text.extents("abc", font="bitmap", height=14, spacing=0.5, expansion=1.5)
    assert e.width == 3 * 18 + 2 * 7
    assert e.advance == (100 - 100 + 3 * 25, 0)


def test_path_left_mirrors_the_order():
    for font in ("bitmap", "sans", "stroke"):
        left = origins("Wavy!", font=font, height=20, path="left")
        right = origins("!yvaW", font=font, height=20, path="right")
        assert (left == right[::-1]).all()


@pytest.mark.parametrize("path, sign", [("up", 1), ("down", -1)])
def test_vertical_paths_stack_centered_characters(path, sign):
    f = sl.text.fonts()["sans"]
    h = 30.0
    s = h / f.cap_height
    glyphs = sl.text.layout("Wil", 100, 100, font="sans", height=h, path=path,
                            align=("center", "base"))
    step = f.line_height * s
    ys = [g.origin[1] for g in glyphs]
    assert all(np.diff(ys) * sign > 0)
    assert max(abs(np.diff(ys) - sign * step)) <= 1
    for g in glyphs:   # each character's advance box is centered on x = 100
        adv = f.advances[g.glyph] * s
        assert abs(g.origin[0] + adv / 2 - 100) <= 0.5


def test_path_up_base_alignment_puts_the_first_baseline_on_the_point():
    g = sl.text.layout("AB", 50, 40, font="bitmap", height=7, path="up",
                       align=("center", "base"))
    assert g[0].origin == (47, 40)          # a 6-dot advance centered: 50 - 3
    assert g[1].origin == (47, 40 + 11)     # line height 11 dots


def test_path_down_top_alignment():
    g = sl.text.layout("AB", 50, 40, font="bitmap", height=7, path="down",
                       align=("left", "top"))
    # top line of the first character (ascent 7) on y = 40; then 11 dots down
    assert [x.origin for x in g] == [(50, 33), (50, 22)]


@pytest.mark.parametrize("valign, dy", [("top", -7), ("cap", -7), ("half", -3.5),
                                         ("base", 0), ("bottom", 2)])
@pytest.mark.parametrize("halign", ["left", "center", "right"])
def test_alignment_arithmetic(halign, valign, dy):
    # bitmap font at height 7: the extent of "abc" runs over the three advances of
    # 6 dots (18); cap line and top line 7, bottom line -2
    e = sl.text.extents("abc", 0, 0, font="bitmap", align=(halign, valign))
    dx = {"left": 0, "center": -9, "right": -18}[halign]
    assert e.box == (dx, -2 + dy, dx + 18, 7 + dy)
    g = sl.text.layout("abc", 0, 0, font="bitmap", align=(halign, valign))
    assert g[0].origin == (dx, math.floor(dy + 0.5))


def test_multiline_alignment():
    f = sl.text.fonts()["bitmap"]
    g = sl.text.layout("ab\ncdef", 0, 0, font="bitmap", align=("right", "base"))
    assert [x.char for x in g] == list("abcdef")
    assert g[0].origin == (-12, 0) and g[2].origin == (-24, -f.line_height)
    e = sl.text.extents("ab\ncdef", 0, 0, font="bitmap", align=("center", "half"))
    # half: between the first cap line (7) and the last baseline (-11)
    assert e.box[1] == pytest.approx(-11 - 2 - (7 - 11) / 2)


@pytest.mark.parametrize("angle", [0.3, 1.0, math.pi / 2, 2.5, -2.0])
def test_rotation_turns_the_origins_about_the_reference_point(angle):
    flat = sl.text.layout("Rotate me", 0, 0, font="sans", height=16)
    turned = sl.text.layout("Rotate me", 200, 100, font="sans", height=16, angle=angle)
    c, s = math.cos(angle), math.sin(angle)
    for a, b in zip(flat, turned):
        # flat origins are rounded too: compare with half a pixel of slack each
        x, y = a.origin
        want = (200 + c * x - s * y, 100 + s * x + c * y)
        assert abs(b.origin[0] - want[0]) <= 1.01 and abs(b.origin[1] - want[1]) <= 1.01


def test_up_vector_is_the_angle_plus_a_right_angle():
    a = sl.text.layout("Up", 50, 50, font="stroke", up=(-1, 0))
    b = sl.text.layout("Up", 50, 50, font="stroke", angle=math.pi / 2)
    assert [g.origin for g in a] == [g.origin for g in b]
    assert sl.TextStyle(up=(1, 1)).angle == pytest.approx(-math.pi / 4)


def crop(a):
    ys, xs = np.nonzero(a)
    return a[ys.min():ys.max() + 1, xs.min():xs.max() + 1]


@pytest.mark.parametrize("font", ["bitmap", "sans"])
def test_a_quarter_turn_rotates_the_image(font):
    flat = sl.FrameBuffer(80, 80, mode="1")
    sl.draw.text(flat, 10, 30, "F7", font=font, height=14)
    turned = sl.FrameBuffer(80, 80, mode="1")
    sl.draw.text(turned, 50, 10, "F7", font=font, height=14, angle=math.pi / 2)
    a, b = crop(flat.to_array()), crop(turned.to_array())
    # bitmap dots have edges on pixel centers, where the top-left rule is not
    # symmetric: the shape may differ by one row/column of the outline
    assert b.shape == a.shape[::-1]
    assert (np.rot90(a) == b).mean() > 0.97


@pytest.mark.parametrize("font", ["bitmap", "sans", "stroke"])
@pytest.mark.parametrize("angle", [0.0, 0.4])
def test_layout_bitmaps_are_the_drawn_pixels(font, angle):
    fb = sl.FrameBuffer(120, 80, mode="1")      # large enough for every glyph
    sl.draw.text(fb, 5, 20, "Ag&j!", font=font, height=16, angle=angle)
    union = np.zeros((80, 120), bool)
    for g in sl.text.layout("Ag&j!", 5, 20, font=font, height=16, angle=angle):
        x0, y0 = g.bitmap_origin
        h, w = g.bitmap.shape
        assert x0 >= 0 and y0 >= 0 and x0 + w <= 120 and y0 + h <= 80
        rows = slice(80 - (y0 + h), 80 - y0)
        union[rows, x0:x0 + w] |= g.bitmap
        ys, xs = np.nonzero(g.bitmap[::-1])
        # every set pixel center lies in the glyph's box (lines round their ends to
        # the nearest pixel: half a pixel more for strokes)
        e = 0.5 if font == "stroke" else 0.0
        if len(xs):
            assert g.box[0] - e <= x0 + xs.min() and x0 + xs.max() <= g.box[2] + e
            assert g.box[1] - e <= y0 + ys.min() and y0 + ys.max() <= g.box[3] + e
    assert (union == fb.to_array()).all()
    assert union.sum() > 100


def test_layout_contours_fill_to_the_drawn_pixels():
    fb = sl.FrameBuffer(120, 60, mode="1")
    sl.draw.text(fb, 5, 20, "B%", font="sans", height=20, angle=0.2)
    ref = sl.FrameBuffer(120, 60, mode="1")
    for g in sl.text.layout("B%", 5, 20, font="sans", height=20, angle=0.2):
        sl.draw.polygon(ref, g.contours, 1, rule="nonzero")
    assert (ref.to_array() == fb.to_array()).all()


def test_stroke_text_is_the_layout_strokes_drawn_as_lines():
    fb = sl.FrameBuffer(150, 60, mode="1")
    sl.draw.text(fb, 5, 20, "Stroke 42", font="stroke", height=18, angle=0.1)
    ref = sl.FrameBuffer(150, 60, mode="1")
    for g in sl.text.layout("Stroke 42", 5, 20, font="stroke", height=18, angle=0.1):
        assert g.contours is None
        for s in g.strokes:
            sl.draw.lines(ref, np.hstack([s[:-1], s[1:]]), color=1)
    assert (ref.to_array() == fb.to_array()).all()
    assert fb.to_array().sum() > 100


def test_layout_reports_cells_and_blank_boxes():
    g = sl.text.layout("a b", 0, 0, font="bitmap", height=14)
    assert g[1].char == " " and g[1].box is None
    assert g[1].cell == (12.0, -4.0, 24.0, 14.0)
    assert g[0].box == (0.0, 0.0, 10.0, 10.0)       # 'a': x-height 5 dots


def test_text_style_is_immutable_and_copies():
    import copy
    import pickle

    s = sl.TextStyle(font="bitmap", height=14, align="center half", up=(-1, 0))
    with pytest.raises(AttributeError, match="immutable"):
        s.height = 3
    assert copy.deepcopy(s) is s and pickle.loads(pickle.dumps(s)) == s
    t = s.replace(height=7, path="down")
    assert (t.height, t.path, t.font, s.height) == (7.0, "down", "bitmap", 14.0)
    assert t.up == pytest.approx((-1, 0))


@settings(max_examples=40, deadline=None)
@given(st.text(st.characters(min_codepoint=32, max_codepoint=0x2FF), min_size=1, max_size=20),
       st.sampled_from(["sans", "bitmap", "stroke"]), st.floats(4, 60),
       st.floats(0.25, 3), st.floats(-0.3, 1))
def test_extent_is_the_sum_of_the_advances(text, font, height, expansion, spacing):
    f = sl.text.fonts()[font]
    scale = height / f.cap_height
    advances = [f.advances[f.glyph_ids(np.array([ord(c)]))[0]] * scale * expansion
                for c in text]
    e = sl.text.extents(text, font=font, height=height, expansion=expansion,
                        spacing=spacing)
    assert e.width == pytest.approx(sum(advances) + spacing * height * (len(text) - 1),
                                    rel=1e-9, abs=1e-9)
    left = origins(text, font=font, height=height, expansion=expansion, spacing=spacing,
                   path="left")
    right = origins(text[::-1], font=font, height=height, expansion=expansion,
                    spacing=spacing)
    assert np.abs(left - right[::-1]).max() <= 1      # the same places, rounded


def test_extents_ink_box():
    # 'H' fills columns 0-4 of its cell, 'i' columns 1-3 of the next (at 6 dots);
    # scale 2: x from 0 to 2 * (6 + 4) = 20, y over the 7 rows above the baseline
    assert sl.text.extents("Hi", font="bitmap", height=14).ink == (0.0, 0.0, 20.0, 14.0)
    assert sl.text.extents("  ", font="bitmap").ink is None
