"""FrameBuffer.copy, crop, resize, show and fb[x, y] (issue, part 6, item 2): device
coordinates throughout (x right, y up), checked against numpy slicing of to_array()
and against Pillow's crop and resize."""

import copy

import numpy as np
import pytest
from PIL import Image

import scanline as sl
from scanline import FrameBuffer
from tests.reference import MODES


def drawn(mode, width=13, height=9):
    """A frame buffer of ``mode`` with a few colored shapes in it."""
    fb = FrameBuffer(width, height, mode=mode, background="navy")
    sl.draw.line(fb, 0, 0, width - 1, height - 1, color="white")
    sl.draw.fill_circle(fb, 4, 5, 3, color="orange")
    sl.draw.polygon(fb, [(6, 0), (12, 2), (9, 8)], color="red")
    return fb


# -- fb[x, y] ----------------------------------------------------------------------------

def test_index_is_device_coordinates():
    fb = FrameBuffer(4, 3, mode="L")
    fb[3, 0] = 200                         # bottom-right pixel
    assert fb[3, 0] == 200 == fb.get_pixel(3, 0)
    assert fb.to_array()[2, 3] == 200      # image order: row height - 1 - y
    fb[np.int64(1), np.int32(2)] = 7
    assert fb[1, 2] == 7 and fb.to_array()[0, 1] == 7


@pytest.mark.parametrize("mode", MODES)
def test_index_agrees_with_get_pixel_and_set_pixel(mode):
    fb = drawn(mode)
    twin = FrameBuffer(fb.width, fb.height, mode=mode, background="navy")
    if mode == "P":
        twin.color_table = [tuple(c) for c in fb.color_table]
    for y in range(fb.height):
        for x in range(fb.width):
            assert fb[x, y] == fb.get_pixel(x, y)
            twin[x, y] = fb[x, y] if mode in ("1", "L", "P") else tuple(fb[x, y])
    assert np.array_equal(twin.to_array(), fb.to_array())


@pytest.mark.parametrize("key, name, words", [
    ((4, 0), "x", ["x=4", "0..3", "width 4"]),
    ((0, 3), "y", ["y=3", "0..2", "height 3"]),
    ((-1, 0), "x", ["x=-1", "0..3"]),          # not counted from the end: left of the frame
    ((0, -1), "y", ["y=-1"]),
])
def test_index_outside_is_an_index_error_naming_the_coordinate(key, name, words):
    fb = FrameBuffer(4, 3, mode="L")
    for action in (lambda: fb[key], lambda: fb.__setitem__(key, 1)):
        with pytest.raises(IndexError) as e:
            action()
        assert isinstance(e.value, sl.ScanlineError)
        assert all(w in str(e.value) for w in words), str(e.value)
    assert not fb.to_array().any()


@pytest.mark.parametrize("key, words", [
    ((1.5, 0), ["x must be an integer", "1.5"]),
    ((0, True), ["y must be an integer"]),
    (3, ["fb[x, y]"]),
    ((1, 2, 3), ["fb[x, y]"]),
    ((slice(0, 2), 1), ["crop", "0:2"]),
    (slice(None), ["crop"]),
])
def test_index_of_the_wrong_kind_is_a_type_error(key, words):
    fb = FrameBuffer(4, 3, mode="L")
    with pytest.raises(TypeError) as e:
        fb[key]
    assert isinstance(e.value, sl.ScanlineError)
    assert all(w in str(e.value) for w in words), str(e.value)


def test_a_frame_buffer_is_not_iterable():
    with pytest.raises(TypeError):
        iter(FrameBuffer(2, 2))
    assert np.asarray(FrameBuffer(2, 2, mode="L")).shape == (2, 2)   # the array protocol stays


def test_setitem_checks_the_color():
    fb = FrameBuffer(2, 2)
    with pytest.raises(sl.ArgumentValueError, match="color"):
        fb[0, 0] = "no such color"
    with pytest.raises(TypeError, match="color=None"):
        fb[0, 0] = None


# -- copy --------------------------------------------------------------------------------

@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("how", [FrameBuffer.copy, copy.copy, copy.deepcopy])
def test_copy_is_independent(mode, how):
    fb = drawn(mode)
    twin = how(fb)
    assert type(twin) is FrameBuffer and twin is not fb
    assert (twin.size, twin.mode, twin.foreground) == (fb.size, fb.mode, fb.foreground)
    assert np.array_equal(twin.to_array(), fb.to_array())
    before = fb.to_array()
    sl.draw.line(twin, 0, 8, 12, 0, color="lime")
    twin.clear()
    assert np.array_equal(fb.to_array(), before)
    if mode == "P":
        twin.set_table_entry(0, "yellow")
        assert fb.color_table.tolist()[0] != [255, 255, 0]
        assert twin.get_pixel(0, 0) == fb.get_pixel(0, 8)       # the background index


# -- crop --------------------------------------------------------------------------------

def test_crop_tiny():
    fb = FrameBuffer(5, 4, mode="1")
    sl.draw.line(fb, 0, 0, 4, 3)
    part = fb.crop(1, 1, 3, 2)
    assert part.size == (3, 2) and part.mode == "1"
    assert sl.text_image(part) == "-##\n#--"
    assert sl.text_image(fb.crop(3, 2, 1, 1)) == "-##\n#--"      # corners in either order


@pytest.mark.parametrize("mode", MODES)
def test_crop_is_the_block_of_to_array_and_pillows_crop(mode):
    fb = drawn(mode)
    rng = np.random.default_rng(3)
    image = fb.to_array()
    for _ in range(40):
        x0, x1 = sorted(rng.integers(0, fb.width, 2))
        y0, y1 = sorted(rng.integers(0, fb.height, 2))
        part = fb.crop(x0, y0, x1, y1)
        rows = slice(fb.height - 1 - y1, fb.height - y0)
        assert np.array_equal(part.to_array(), image[rows, x0:x1 + 1])
        box = (x0, fb.height - 1 - y1, x1 + 1, fb.height - y0)   # the formula of the docstring
        assert np.array_equal(part.to_array(), np.asarray(fb.to_pil().crop(box)))
        assert part.mode == mode and part.foreground == fb.foreground
        if mode == "P":
            assert np.array_equal(part.color_table, fb.color_table)


@pytest.mark.parametrize("mode", MODES)
def test_crop_outside_is_background(mode):
    fb = drawn(mode)
    big = fb.crop(-3, -2, fb.width + 1, fb.height)
    assert big.size == (fb.width + 5, fb.height + 3)
    assert np.array_equal(big.crop(3, 2, fb.width + 2, fb.height + 1).to_array(), fb.to_array())
    blank = FrameBuffer(fb.width + 5, fb.height + 3, mode=mode, background="navy")
    assert big[0, 0] == blank[0, 0] == fb.crop(100, 100, 100, 100)[0, 0]
    assert sl.text_image(fb.crop(-10, -10, -5, -8)) == "\n".join(["------"] * 3)


def test_crop_takes_the_pixels_a_filled_rectangle_covers():
    fb = FrameBuffer(12, 10, mode="L")
    sl.draw.rectangle(fb, 3, 2, 8, 6, color=255, fill=True)
    assert (fb.crop(3, 2, 8, 6).to_array() == 255).all()
    assert int((fb.to_array() == 255).sum()) == 6 * 5


def test_crop_errors():
    fb = FrameBuffer(4, 4)
    with pytest.raises(sl.ArgumentValueError, match="x0"):
        fb.crop(float("nan"), 0, 1, 1)
    with pytest.raises(sl.ArgumentValueError, match="crop"):
        fb.crop(0, 0, 2**30, 2**30)                   # more memory than the machine has


# -- resize ------------------------------------------------------------------------------

@pytest.mark.parametrize("mode", MODES)
def test_resize_nearest_by_whole_factors_makes_blocks(mode):
    fb = drawn(mode)
    big = fb.resize(fb.width * 3, fb.height * 2)
    assert big.mode == mode and big.size == (39, 18)
    expected = np.repeat(np.repeat(fb.to_array(), 2, axis=0), 3, axis=1)
    assert np.array_equal(big.to_array(), expected)
    if mode == "P":
        assert np.array_equal(big.color_table, fb.color_table)


@pytest.mark.parametrize("mode", ["L", "RGB", "RGBA"])
@pytest.mark.parametrize("resample", ["nearest", "bilinear", "bicubic", "lanczos", "box",
                                      "hamming"])
def test_resize_is_pillows_resize(mode, resample):
    fb = drawn(mode)
    if mode == "RGBA":
        sl.draw.fill_circle(fb, 8, 3, 2, color=(0, 255, 0, 90))
    for size in [(5, 4), (20, 31)]:
        expected = fb.to_pil().resize(size, getattr(Image.Resampling, resample.upper()))
        assert np.array_equal(fb.resize(*size, resample=resample).to_array(), np.asarray(expected))


def test_resize_mode_1_filters_gray_levels_and_thresholds():
    fb = FrameBuffer(8, 8, mode="1")
    sl.draw.fill_circle(fb, 4, 4, 3)
    gray = Image.fromarray(fb.to_array().astype(np.uint8) * 255)
    for resample in ("bilinear", "lanczos"):
        small = fb.resize(3, 5, resample=resample)
        assert small.mode == "1"
        flt = getattr(Image.Resampling, resample.upper())
        assert np.array_equal(small.to_array(), np.asarray(gray.resize((3, 5), flt)) >= 128)
    assert np.array_equal(fb.resize(5, 3).to_array(),
                          np.asarray(fb.to_pil().resize((5, 3), Image.Resampling.NEAREST)))


def test_resize_mode_p_keeps_the_table_and_maps_to_the_nearest_entry():
    fb = drawn("P", 16, 12)
    table = fb.color_table.astype(int)
    for resample in ("bilinear", "bicubic"):
        small = fb.resize(7, 5, resample=resample)
        assert small.mode == "P" and np.array_equal(small.color_table, fb.color_table)
        rgb = np.asarray(fb.to_pil().convert("RGB").resize(
            (7, 5), getattr(Image.Resampling, resample.upper()))).astype(int)
        for (row, col), index in np.ndenumerate(small.to_array()):
            d = ((table - rgb[row, col]) ** 2).sum(axis=1)
            assert index == int(np.argmin(d))     # nearest entry, the lower one on ties


def test_resize_errors():
    fb = FrameBuffer(4, 4)
    with pytest.raises(sl.ArgumentValueError, match=r"resample.*bilinear"):
        fb.resize(2, 2, resample="cubic")
    with pytest.raises(sl.ArgumentValueError, match="width"):
        fb.resize(0, 2)
    with pytest.raises(sl.ArgumentTypeError, match="height"):
        fb.resize(2, 2.5)


# -- show --------------------------------------------------------------------------------

def test_show_hands_the_enlarged_image_to_pillow(monkeypatch):
    shown = []
    monkeypatch.setattr(Image.Image, "show", lambda image, title=None: shown.append((image, title)))
    fb = FrameBuffer(16, 8, mode="L")
    fb[0, 0] = 255
    fb.show()
    fb.show(title="frame", scale=1)
    (big, none), (one, title) = shown
    assert big.size == (256, 128) and none is None          # 16x: as in a notebook
    assert np.asarray(big)[-16:, :16].min() == 255 and np.asarray(big)[:-16].max() == 0
    assert one.size == (16, 8) and title == "frame"
    assert np.array_equal(np.asarray(one), fb.to_array())
