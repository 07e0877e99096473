"""Color tables, nearest-color lookup, indexed frame buffers and gray-scale levels."""

import numpy as np
import pytest
from PIL import Image

import scanline as sl

RNG = np.random.default_rng(332)


def test_gray_tables():
    assert sl.color.gray_table(2).tolist() == [[0, 0, 0], [255, 255, 255]]
    # 2 bits per pixel: 4 levels
    assert sl.color.gray_table(4)[:, 0].tolist() == [0, 85, 170, 255]
    assert sl.color.gray_table(256)[:, 0].tolist() == list(range(256))
    t = sl.color.gray_table(7)
    assert (t[:, 0] == t[:, 1]).all() and (t[:, 1] == t[:, 2]).all()
    assert t[:, 0].tolist() == [0, 43, 85, 128, 170, 213, 255]   # 42.5 and 212.5 round up


def test_rgb332_table():
    t = sl.color.rgb332_table()
    assert t.shape == (256, 3) and len({tuple(c) for c in t}) == 256
    for index in (0, 1, 0b001_000_00, 0b000_001_00, 0b101_110_10, 255):
        r, g, b = index >> 5, (index >> 2) & 7, index & 3
        assert t[index].tolist() == [round(r * 255 / 7), round(g * 255 / 7), round(b * 255 / 3)]


def test_web_safe_table():
    t = sl.color.web_safe_table()
    assert t.shape == (216, 3) and len({tuple(c) for c in t}) == 216
    assert set(np.unique(t).tolist()) == {0, 51, 102, 153, 204, 255}
    assert t[36 * 5 + 6 * 2 + 1].tolist() == [255, 102, 51]


def test_median_cut_by_hand():
    # one axis: 4 pixels 0, 10, 200, 250 -> the median cut puts two in each box
    line = np.array([[[0, 0, 0], [10, 0, 0], [200, 0, 0], [250, 0, 0]]], np.uint8)
    assert sl.color.median_cut_table(line, 2).tolist() == [[5, 0, 0], [225, 0, 0]]
    assert sl.color.median_cut_table(line, 1).tolist() == [[115, 0, 0]]   # 460 / 4
    # pixel counts weigh: 6 pixels of 0, one of 100, one of 102 along green -> the
    # median pixel is a 0, so the cut leaves {0} and {100, 102}
    weighted = np.zeros((1, 8, 3), np.uint8)
    weighted[0, 6, 1], weighted[0, 7, 1] = 100, 102
    assert sl.color.median_cut_table(weighted, 2).tolist() == [[0, 0, 0], [0, 101, 0]]
    # the longest side is cut: blue spans 0..200, red only 0..20
    box = np.array([[[0, 0, 0], [20, 0, 0], [0, 0, 200], [20, 0, 200]]], np.uint8)
    assert sl.color.median_cut_table(box, 2).tolist() == [[10, 0, 0], [10, 0, 200]]
    # as many entries as colors when the image has fewer; from a frame buffer too
    assert sorted(map(tuple, sl.color.median_cut_table(line, 16).tolist())) == [
        (0, 0, 0), (10, 0, 0), (200, 0, 0), (250, 0, 0)]
    two = sl.FrameBuffer(4, 4, background="red")
    two.set_pixel(0, 0, "blue")
    assert sorted(map(tuple, sl.color.median_cut_table(two, 16).tolist())) == [(0, 0, 255), (255, 0, 0)]


@pytest.mark.parametrize("colors", [2, 8, 64, 256])
def test_median_cut_is_as_good_as_pillows(colors):
    """Pillow's median cut (a peer) on a random image and a smooth gradient: the
    nearest-entry squared error of our table is no worse than 1.1 times Pillow's."""
    y, x = np.mgrid[0:60, 0:80]
    gradient = np.dstack([x * 255 // 79, y * 255 // 59, (x + y) * 255 // 138]).astype(np.uint8)
    for image in (RNG.integers(0, 256, (40, 50, 3), dtype=np.uint8), gradient):
        ours = sl.color.median_cut_table(image, colors)
        pil = Image.fromarray(image).quantize(colors, method=Image.Quantize.MEDIANCUT)
        theirs = np.array(pil.getpalette()[:3 * colors]).reshape(-1, 3)
        assert len(ours) == len(theirs) == colors

        def error(table):
            d = image.reshape(-1, 1, 3).astype(float) - table[None].astype(float)
            return (d ** 2).sum(-1).min(axis=1).mean()

        assert error(ours) <= 1.1 * error(theirs)


def test_nearest_against_brute_force():
    table = RNG.integers(0, 256, (37, 3), dtype=np.uint8)
    colors = RNG.integers(0, 256, (20, 30, 3), dtype=np.uint8)
    got = sl.color.nearest(colors, table)
    assert got.shape == (20, 30)
    d = ((colors[:, :, None, :].astype(int) - table[None, None].astype(int)) ** 2).sum(axis=3)
    best = d.min(axis=2)
    # the chosen entry is a nearest one (float32 cannot break exact integer ties wrongly)
    assert (np.take_along_axis(d, got[..., None].astype(int), axis=2)[..., 0] == best).all()
    # floats in [0, 1] and a single color work too
    assert sl.color.nearest(colors / 255.0, table).tolist() == got.tolist()
    assert sl.color.nearest(np.array([1.0, 0.0, 0.0]), ["black", "red"]).tolist() == 1


def test_nearest_ties_take_the_lowest_index():
    assert sl.color.nearest(np.array([[128, 128, 128]], np.uint8), ["black", "white"]).tolist() == [1]
    assert sl.color.nearest(np.array([[0, 0, 0]], np.uint8), ["black", "black"]).tolist() == [0]


def test_indexed_frame_buffer_and_recoloring():
    image = np.zeros((3, 4, 3), np.uint8)
    image[0, :2] = (250, 5, 5)        # top row, left: reddish
    fb = sl.color.indexed(image, ["black", "red", "white"])
    assert fb.mode == "P" and fb.color_table.tolist() == [[0, 0, 0], [255, 0, 0], [255, 255, 255]]
    assert fb.to_array().tolist() == [[1, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]
    assert fb.get_pixel(0, 2) == 1    # device y up: the top row is y = 2
    # editing the table recolors without touching the indices (the notes' color-table
    # animation)
    fb.set_table_entry(1, "lime")
    assert fb.to_pil().convert("RGB").getpixel((0, 0)) == (0, 255, 0)
    assert fb.to_array()[0, 0] == 1
    # drawing by index still works on the result
    sl.draw.line(fb, 0, 0, 3, 0, color=2)
    assert fb.to_array()[2].tolist() == [2, 2, 2, 2]


def test_indexed_with_standard_tables_is_exact_on_table_colors():
    for table in (sl.color.web_safe_table(), sl.color.rgb332_table(), sl.color.gray_table(16)):
        image = table[RNG.integers(0, len(table), (10, 12))]
        fb = sl.color.indexed(image, table)
        assert (fb.color_table[fb.to_array()] == image).all()


def test_gray_levels():
    ramp = np.arange(256, dtype=np.uint8)[None]
    two_bits = sl.color.gray_levels(ramp, bits=2)
    assert sorted(set(two_bits[0].tolist())) == [0, 85, 170, 255]
    # nearest level: |value - level| <= half a step
    assert (np.abs(two_bits.astype(int) - ramp) <= 85 / 2).all()
    assert (sl.color.gray_levels(ramp, 256) == ramp).all()
    assert sl.color.gray_levels(ramp, 2)[0, :128].max() == 0
    assert sl.color.gray_levels(ramp, 2)[0, 128:].min() == 255
    # a frame buffer gives a frame buffer; color is reduced to its luminance
    # (3 levels: 0, 128, 255, i.e. 0, 1/2, 1)
    fb = sl.FrameBuffer(3, 1, mode="RGB", background="blue")
    out = sl.color.gray_levels(fb, 3)
    assert out.mode == "L" and out.to_array().tolist() == [[0, 0, 0]]   # luma .114 -> 0
    out = sl.color.gray_levels(sl.FrameBuffer(3, 1, background="red"), 3)
    assert out.to_array().tolist() == [[128, 128, 128]]               # luma .299 -> 1/2
    out = sl.color.gray_levels(sl.FrameBuffer(3, 1, background="yellow"), 3)
    assert out.to_array().tolist() == [[255, 255, 255]]               # luma 226 -> 255


@pytest.mark.parametrize("call, words", [
    (lambda: sl.color.gray_table(1), "n=1"),
    (lambda: sl.color.gray_table(300), "n=300"),
    (lambda: sl.color.gray_levels(np.zeros((2, 2)), 1), "n=1"),
    (lambda: sl.color.gray_levels(np.zeros((2, 2))), "exactly one"),
    (lambda: sl.color.gray_levels(np.zeros((2, 2)), 4, bits=2), "exactly one"),
    (lambda: sl.color.gray_levels(np.zeros((2, 2)), bits=9), "bits=9"),
    (lambda: sl.color.gray_levels(np.zeros((2, 2)), bits=0), "bits"),
    (lambda: sl.color.median_cut_table(np.zeros((2, 2)), 0), "colors=0"),
    (lambda: sl.color.color_table([]), "1 to 256"),
    (lambda: sl.color.color_table(np.full((2, 3), 1.5)), "[0, 1]"),
    (lambda: sl.color.color_table(np.full((2, 3), 300)), "0..255"),
    (lambda: sl.color.color_table(5), "sequence"),
    (lambda: sl.color.nearest(np.zeros((2, 2)), ["red"]), "3 components"),
    (lambda: sl.color.nearest(np.zeros((2, 3)), []), "table must have"),
    (lambda: sl.color.indexed(np.zeros((2, 2)), []), "palette must have"),
])
def test_bad_input(call, words):
    with pytest.raises((sl.ArgumentValueError, sl.ArgumentTypeError)) as info:
        call()
    assert words in str(info.value)


def test_nearest_with_the_cell_grid_against_brute_force():
    # enough colors that the search uses the 16^3 grid of candidate lists; values on
    # cell boundaries (multiples of 1/8 over [-1/2, 3/2]) and duplicate entries too
    from scanline.color.tables import search_cells

    table = np.vstack([RNG.integers(0, 256, (40, 3)), [[0, 0, 0], [255, 255, 255]] * 2,
                       [[32, 64, 96]]]).astype(np.uint8)
    colors = np.vstack([RNG.integers(0, 256, (60000, 3)),
                        np.floor(RNG.integers(0, 9, (5000, 3)) * 255 / 8 + 0.5)]).astype(np.uint8)
    assert search_cells(table.astype(np.float32) / 255, len(colors))[2] == 16
    got = sl.color.nearest(colors, table)
    d = ((colors[:, None, :].astype(int) - table[None].astype(int)) ** 2).sum(axis=2)
    chosen = d[np.arange(len(colors)), got]
    assert (chosen == d.min(axis=1)).all()
    # exact ties go to the lowest index: compare with the first minimum where the
    # float32 distances cannot tie differently (integer distances differ by >= 1/255^2)
    assert (got == d.argmin(axis=1)).mean() > 0.999
    # rows 42 and 43 repeat rows 40 and 41 exactly: they are never chosen
    assert not np.isin(got, [42, 43]).any() and np.isin(got, [40, 41]).any()


def test_palette_dithering_is_the_same_with_and_without_the_grid():
    from scanline._kernels import dither as kernels
    from scanline.color.tables import search_cells

    y, x = np.mgrid[0:160, 0:200]
    image = np.stack([x / 199, y / 159, (x + y) % 37 / 36], axis=2).astype(np.float32)
    palette = sl.color.web_safe_table().astype(np.float32) / 255
    grid = search_cells(palette, image.shape[0] * image.shape[1])
    exhaustive = search_cells(palette, 1)
    assert grid[2] == 16 and exhaustive[2] == 1
    for serpentine in (False, True):
        a = np.empty(image.shape[:2], np.uint8)
        b = np.empty(image.shape[:2], np.uint8)
        kernels.diffuse_palette(image, palette, *grid, serpentine, a)
        kernels.diffuse_palette(image, palette, *exhaustive, serpentine, b)
        assert (a == b).all()
