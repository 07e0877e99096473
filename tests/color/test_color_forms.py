"""Colors as users write them (issue 16, item 2): float tuples in [0, 1], matplotlib's
names through matplotlib's own tables, and the mode "1" rule.  Expected values are
matplotlib's and Pillow's, or written out by hand."""

import sys

import numpy as np
import pytest

import scanline as sl
from scanline.color import rgba
from tests.reference import peer


@pytest.mark.parametrize("color, expected", [
    ((1.0, 0.5, 0.0), (255, 128, 0, 255)),                 # 127.5 rounds half up
    ((0.0, 0.0, 1.0, 0.5), (0, 0, 255, 128)),
    ((1, 0.0, 0), (255, 0, 0, 255)),                       # any float: the 0..1 form
    ([0.2, 0.4, 0.6], (51, 102, 153, 255)),
    (np.array([0.1, 0.2, 0.3]), (26, 51, 77, 255)),        # 25.5 -> 26, 76.5 -> 77
    (np.float32(1.0) * np.ones(3, np.float32), (255, 255, 255, 255)),
    ((255, 128, 0), (255, 128, 0, 255)),                   # integers stay 0..255
    (np.array([1, 0, 0]), (1, 0, 0, 255)),
])
def test_tuples_of_floats_are_unit_range(color, expected):
    assert rgba(color) == expected


@pytest.mark.parametrize("color", [(255.0, 0.0, 0.0), (1.5, 0, 0), (-0.1, 0, 0),
                                   (float("nan"), 0, 0), (0.5, 0.5), (0.1, 0.2, 0.3, 0.4, 0.5)])
def test_float_tuples_out_of_range_are_refused(color):
    with pytest.raises(sl.ArgumentValueError) as e:
        rgba(color, "fill")
    assert "fill=" in str(e.value)
    assert "0..1" in str(e.value) or "3 or 4" in str(e.value)


def test_a_float_tuple_that_looks_like_0_255_says_how_to_write_it():
    with pytest.raises(sl.ArgumentValueError, match=r"as integers, e.g. \(255, 128, 0\)"):
        rgba((255.0, 128.0, 0.0))


@pytest.mark.parametrize("name", ["tab:blue", "tab:orange", "C0", "C3", "xkcd:sky blue",
                                  "k", "r", "0.25", "rebeccapurple", "lightgoldenrodyellow"])
def test_matplotlib_names_match_matplotlib(name):
    colors = peer("matplotlib.colors")
    expected = tuple(int(np.floor(c * 255 + 0.5)) for c in colors.to_rgba(name))
    assert rgba(name) == expected


def test_pillow_forms_still_come_first():
    assert rgba("#ff800080") == (255, 128, 0, 128)
    assert rgba("hsl(120, 100%, 50%)") == (0, 255, 0, 255)
    assert rgba("green") == (0, 128, 0, 255)        # CSS green, in both tables


def test_matplotlib_names_without_matplotlib_say_so(monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)     # import matplotlib fails
    monkeypatch.setitem(sys.modules, "matplotlib.colors", None)
    with pytest.raises(sl.ArgumentValueError, match="matplotlib is not installed"):
        rgba("tab:blue")
    with pytest.raises(sl.ArgumentValueError, match="not a known color"):
        rgba("no-such-colour")
    assert rgba("red") == (255, 0, 0, 255)


def test_colors_reach_every_mode_and_drawing():
    peer("matplotlib")                  # "tab:blue" is read from matplotlib's table
    fb = sl.FrameBuffer(4, 2, mode="RGB")
    sl.draw.line(fb, 0, 0, 3, 0, color="tab:blue")
    sl.draw.line(fb, 0, 1, 3, 1, color=(0.0, 1.0, 0.5))
    assert fb.get_pixel(0, 0) == (31, 119, 180) and fb.get_pixel(0, 1) == (0, 255, 128)
    p = sl.FrameBuffer(2, 1, mode="P")
    p.set_pixel(0, 0, (1.0, 0.0, 0.0))
    assert p.color_table[p.get_pixel(0, 0)].tolist() == [255, 0, 0]


@pytest.mark.parametrize("color, bit", [
    ("white", 1), ("yellow", 1), ("tab:orange", 1), ((0.6, 0.6, 0.6), 1), ("lime", 1),
    ("black", 0), ("red", 0), ("navy", 0), ("tab:blue", 0), ((0.4, 0.4, 0.4), 0),
])
def test_mode_1_maps_named_colors_by_luma(color, bit):
    # ITU-R 601 luma >= 128 is on: red 76, lime 150, tab:blue 98, tab:orange 150,
    # gray 0.6 -> 153, 0.4 -> 102
    if isinstance(color, str) and color.startswith("tab:"):
        peer("matplotlib")
    fb = sl.FrameBuffer(1, 1, mode="1", background=1 - bit)
    fb.set_pixel(0, 0, color)
    assert fb.get_pixel(0, 0) == bit
    assert sl.color.pixel_value(color, "1") == (bit,)


def test_mode_1_integer_colors_are_bits_and_others_refused():
    fb = sl.FrameBuffer(1, 1, mode="1")
    fb.set_pixel(0, 0, 1)
    assert fb.get_pixel(0, 0) == 1
    with pytest.raises(sl.ArgumentValueError, match="bit, 0 or 1"):
        fb.set_pixel(0, 0, 200)
