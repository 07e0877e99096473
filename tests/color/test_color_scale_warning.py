"""Colors written as 0/1 integers (issue, part 6, item 1): ``(1, 0, 0)`` is read as
0..255 -- nearly black -- and warns once per distinct color, naming the float form
that was probably meant; black, 0..255 colors, floats, single integers and data
(arrays, values scanline read from pixels) stay silent."""

import warnings

import numpy as np
import pytest
from PIL import Image

import scanline as sl
from scanline.color import spec


@pytest.fixture(autouse=True)
def fresh(monkeypatch):
    """Each test starts with no color warned about yet."""
    monkeypatch.setattr(spec, "_SCALE_WARNED", set())


@pytest.fixture
def silent():
    """Turn the warning into an error inside the block."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", sl.ColorScaleWarning)
        yield


def test_a_0_1_integer_tuple_warns_naming_the_float_form():
    fb = sl.FrameBuffer(4, 4)
    with pytest.warns(sl.ColorScaleWarning) as record:
        sl.draw.line(fb, 0, 0, 3, 3, color=(1, 0, 0))
    message = str(record[0].message)
    assert "color=(1, 0, 0)" in message and "nearly black" in message
    assert "color=(1.0, 0.0, 0.0)" in message
    assert record[0].filename == __file__          # reported at the caller's line
    assert fb.get_pixel(0, 0) == (1, 0, 0)         # still read as 0..255, as documented
    assert issubclass(sl.ColorScaleWarning, sl.ScanlineWarning)


def test_once_per_distinct_color():
    fb = sl.FrameBuffer(4, 4)
    with pytest.warns(sl.ColorScaleWarning):
        fb.set_pixel(0, 0, (0, 1, 0))
    with warnings.catch_warnings():
        warnings.simplefilter("error", sl.ColorScaleWarning)
        sl.draw.circle(sl.FrameBuffer(4, 4), 1, 1, 1, color=(0, 1, 0))   # seen: silent
    with pytest.warns(sl.ColorScaleWarning, match=r"\(0\.0, 0\.0, 1\.0\)"):
        fb.set_pixel(0, 0, (0, 0, 1))


@pytest.mark.parametrize("color, words", [
    ((1, 1, 1), ["rgb(1, 1, 1)", "(1.0, 1.0, 1.0)"]),
    ([1, 0, 1], ["[1, 0, 1]", "(1.0, 0.0, 1.0)"]),
    ((0, 0, 0, 1), ["rgba(0, 0, 0, 1)", "nearly transparent", "(0.0, 0.0, 0.0, 1.0)"]),
    ((1, 0, 0, 1), ["nearly black and nearly transparent"]),
])
def test_forms_that_warn(color, words):
    with pytest.warns(sl.ColorScaleWarning) as record:
        sl.color.rgba(color, "fill")
    assert all(w in str(record[0].message) for w in words), str(record[0].message)
    assert "fill=" in str(record[0].message)


def test_the_argument_is_named():
    with pytest.warns(sl.ColorScaleWarning, match=r"background=\(1, 1, 0\)"):
        sl.FrameBuffer(2, 2, background=(1, 1, 0))


@pytest.mark.parametrize("mode", ["1", "L", "RGB", "RGBA", "P"])
def test_every_mode_warns_for_a_tuple(mode):
    with pytest.warns(sl.ColorScaleWarning):
        sl.FrameBuffer(2, 2, mode=mode).set_pixel(0, 0, (1, 0, 1))


@pytest.mark.parametrize("color", [
    (0, 0, 0), (0, 0, 0, 0), (255, 0, 0), (1, 2, 0), (0, 1, 2), (1.0, 0.0, 0.0),
    (1, 0.0, 0), (0.0, 1.0, 1.0, 1.0), np.array([1, 0, 0]), np.array([1, 1, 1], np.uint8),
    "red", 1,
])
def test_silent_forms(color, silent):
    sl.color.rgba(color)


@pytest.mark.parametrize("mode", ["1", "L", "P"])
def test_single_integers_are_silent(mode, silent):
    fb = sl.FrameBuffer(3, 1, mode=mode, background=0 if mode != "P" else "black")
    if mode == "P":
        fb.set_table_entry(1, "red")
    fb.set_pixel(0, 0, 1)          # a bit, a gray level, a color-table index
    sl.draw.line(fb, 0, 0, 2, 0, color=1)
    assert fb.get_pixel(1, 0) == 1


def test_values_scanline_reads_back_are_silent(silent):
    # a palette entry (1, 1, 1) of a real image: data, not a typed literal
    image = Image.new("P", (2, 1))
    image.putpalette([0, 0, 0, 1, 1, 1])
    image.putpixel((1, 0), 1)
    fb = sl.FrameBuffer.from_pil(image)
    assert fb.color_table.tolist() == [[0, 0, 0], [1, 1, 1]]
    # integer color arrays of a batch, in a mode where each row is converted
    gray = sl.FrameBuffer(4, 4, mode="L")
    sl.draw.lines(gray, [(0, 0, 3, 0), (0, 1, 3, 1)], color=np.array([[0, 1, 0], [1, 1, 1]]))
    sl.draw.lines(gray, [(0, 0, 3, 0), (0, 1, 3, 1)],
                  color=np.array([[0, 1, 0, 128], [1, 1, 1, 255]]))
    sl.draw.circles(sl.FrameBuffer(8, 8, mode="L"), [(3, 3, 2), (4, 4, 2)],
                    color=np.array([[1, 0, 0], [0, 0, 1]]), width=2)
    sl.draw.polygons(sl.FrameBuffer(8, 8, mode="P"), [[(0, 0), (5, 0), (0, 5)]] * 2,
                     color=np.array([[1, 0, 0, 200], [0, 1, 0, 255]]))


def test_a_list_written_in_0_255_is_not_questioned(silent):
    fb = sl.FrameBuffer(8, 8)
    sl.draw.polygons(fb, [[(0, 0), (5, 0), (0, 5)]] * 2, [(10, 200, 30, 100), (0, 0, 0, 1)])
    sl.draw.lines(fb, [(0, 0, 7, 0), (0, 1, 7, 1)], color=[(0, 1, 0), (255, 128, 0)])
    ramp = sl.FrameBuffer(2, 2, mode="P", color_table=[(i, 0, 0) for i in range(256)])
    ramp.color_table = [(0, 0, 0), (1, 1, 1), (2, 2, 2)]
    assert sl.color.tables.color_table([(0, 0, 1), (0, 0, 255)]).tolist() == [[0, 0, 1],
                                                                              [0, 0, 255]]


def test_a_list_of_only_0_1_tuples_warns_for_each_distinct_one():
    fb = sl.FrameBuffer(8, 8)
    with pytest.warns(sl.ColorScaleWarning) as record:
        sl.draw.lines(fb, [(0, 0, 7, 0), (0, 1, 7, 1), (0, 2, 7, 2)],
                      color=[(1, 0, 0), (0, 1, 0), (1, 0, 0)])
    assert [str(w.message).split(" is ")[0] for w in record] == ["color[0]=(1, 0, 0)",
                                                                 "color[1]=(0, 1, 0)"]
