"""Alpha compositing ("over", Porter & Duff 1984) in every frame-buffer mode.

Expected values are computed by hand in the comments (a = alpha / 255), or come
from Pillow's ``Image.alpha_composite`` (an independent implementation).
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from PIL import Image

import scanline as sl
from scanline.draw import _blend

SQUARE = [(-0.5, -0.5), (3.5, -0.5), (3.5, 3.5), (-0.5, 3.5)]   # covers pixels 0..3 fully


def paint_all(fb, color):
    """A non-antialiased polygon over the whole 4x4 frame buffer."""
    sl.draw.polygon(fb, [(-1, -1), (5, -1), (5, 5), (-1, 5)], color)


def test_rgb_over_by_hand():
    fb = sl.FrameBuffer(4, 4, mode="RGB", background=(10, 200, 30))
    paint_all(fb, (250, 0, 100, 64))
    # a = 64/255 = 0.25098: R = 10 + 240 a = 70.24, G = 200 - 200 a = 149.80,
    # B = 30 + 70 a = 47.57
    assert fb.get_pixel(2, 2) == (70, 150, 48)


def test_rgb_half_alpha_hex_string():
    fb = sl.FrameBuffer(4, 4, mode="RGB", background="white")
    paint_all(fb, "#0000ff80")
    # a = 128/255: R = G = 255 - 255 a = 127.0; B stays 255
    assert fb.get_pixel(0, 0) == (127, 127, 255)


def test_gray_over_by_hand():
    fb = sl.FrameBuffer(4, 4, mode="L", background=200)
    paint_all(fb, "#ff000080")
    # red's luma (ITU-R 601) is 76; 200 + (76 - 200) * 128/255 = 137.76
    assert fb.get_pixel(1, 1) == 138


def test_rgba_over_with_destination_alpha_by_hand():
    fb = sl.FrameBuffer(4, 4, mode="RGBA", background=(0, 0, 255, 128))
    paint_all(fb, (255, 0, 0, 128))
    # a = da = 0.50196; keep = da (1 - a) = 0.25000; ao = a + keep = 0.75196
    # R = 255 a / ao = 170.22; B = 255 keep / ao = 84.78; alpha = 255 ao = 191.75
    assert fb.get_pixel(3, 3) == (170, 0, 85, 192)


def test_rgba_over_transparent_keeps_the_color():
    fb = sl.FrameBuffer(4, 4, mode="RGBA", background=(0, 0, 0, 0))
    paint_all(fb, (255, 10, 20, 77))
    assert fb.get_pixel(0, 3) == (255, 10, 20, 77)


@pytest.mark.parametrize("dst,src", [((0, 0, 255, 128), (255, 0, 0, 128)),
                                     ((30, 60, 90, 200), (200, 100, 0, 50)),
                                     ((255, 255, 255, 255), (0, 128, 64, 10)),
                                     ((12, 34, 56, 0), (99, 88, 77, 254))])
def test_rgba_matches_pillow_alpha_composite(dst, src):
    fb = sl.FrameBuffer(4, 4, mode="RGBA", background=dst)
    paint_all(fb, src)
    ref = Image.alpha_composite(Image.new("RGBA", (1, 1), dst), Image.new("RGBA", (1, 1), src))
    assert np.abs(np.subtract(fb.get_pixel(0, 0), ref.getpixel((0, 0)))).max() <= 1


def test_indexed_blends_the_table_colors_then_takes_the_nearest_entry():
    table = [(0, 0, 0), (255, 255, 255), (128, 128, 128), (255, 0, 0), (255, 128, 128)]
    fb = sl.FrameBuffer(4, 4, mode="P", color_table=table)
    fb.set_pixel(0, 0, 3)                       # red
    paint_all(fb, "#ffffff80")                  # white at a = 0.50196
    # over black: (128.0, 128.0, 128.0) -> gray, entry 2
    assert fb.get_pixel(1, 1) == 2
    # over red: (255, 128.0, 128.0) -> the pink entry 4
    assert fb.get_pixel(0, 0) == 4
    assert len(fb.color_table) == 5             # white was already in the table


def test_bitmap_sets_pixels_where_alpha_reaches_one_half():
    fb = sl.FrameBuffer(4, 4, mode="1")
    paint_all(fb, (255, 255, 255, 127))         # 127/255 < 1/2: unchanged
    assert fb.get_pixel(0, 0) == 0
    paint_all(fb, (255, 255, 255, 128))         # 128/255 >= 1/2: the color's bit
    assert fb.get_pixel(0, 0) == 1
    paint_all(fb, (0, 0, 0, 200))               # black: clears
    assert fb.get_pixel(2, 3) == 0


def test_opaque_colors_still_replace():
    fb = sl.FrameBuffer(4, 4, mode="RGBA", background=(1, 2, 3, 4))
    paint_all(fb, "red")
    assert fb.get_pixel(0, 0) == (255, 0, 0, 255)


def test_each_pixel_composited_once_per_primitive():
    # two identical contours under the nonzero rule: one area, blended once
    once = sl.FrameBuffer(4, 4, mode="L", background=0)
    twice = sl.FrameBuffer(4, 4, mode="L", background=0)
    sl.draw.polygon(once, SQUARE, (255, 255, 255, 128), rule="nonzero")
    sl.draw.polygon(twice, [SQUARE, SQUARE], (255, 255, 255, 128), rule="nonzero")
    assert once.get_pixel(1, 1) == 128
    assert np.array_equal(once.to_array(), twice.to_array())


def test_translucent_batch_equals_primitives_in_order():
    shapes = [[(0, 0), (8, 0), (8, 6)], [(2, 1), (9, 3), (1, 7)], [(0, 7), (9, 7), (4, 0)]]
    colors = [(255, 0, 0, 100), "blue", (0, 255, 0, 180)]
    batch = sl.FrameBuffer(10, 8, mode="RGB", background="white")
    sl.draw.polygons(batch, shapes, colors)
    one_by_one = sl.FrameBuffer(10, 8, mode="RGB", background="white")
    for s, c in zip(shapes, colors):
        sl.draw.polygon(one_by_one, s, c)
    assert np.array_equal(batch.to_array(), one_by_one.to_array())


def test_translucent_filled_circles_batch_and_single():
    batch = sl.FrameBuffer(16, 16, mode="RGB")
    sl.draw.fill_circles(batch, [(5, 5, 4), (9, 8, 5)], [(255, 0, 0, 120), (0, 0, 255, 90)])
    single = sl.FrameBuffer(16, 16, mode="RGB")
    sl.draw.fill_circle(single, 5, 5, 4, (255, 0, 0, 120))
    sl.draw.fill_circle(single, 9, 8, 5, (0, 0, 255, 90))
    assert np.array_equal(batch.to_array(), single.to_array())
    # the overlap: red (a = 120/255) then blue (a = 90/255) over black
    r = 255 * 120 / 255
    assert single.get_pixel(7, 6) == (round(r * (1 - 90 / 255)), 0, round(255 * 90 / 255))


def test_translucent_fill_covers_the_same_pixels_as_opaque():
    for mode in ("1", "L", "RGB", "RGBA", "P"):
        opaque = sl.FrameBuffer(12, 9, mode=mode)
        clear = sl.FrameBuffer(12, 9, mode=mode)
        sl.draw.pie(opaque, 6, 4, 5, 4, 0.3, 4.0, "white")
        sl.draw.pie(clear, 6, 4, 5, 4, 0.3, 4.0, (255, 255, 255, 200))
        assert sl.text_image(opaque) == sl.text_image(clear), mode


def test_paint_helper_composites_a_primitive_through_a_mask():
    from scanline._kernels.lines import BRESENHAM, draw_line
    from scanline._kernels.variants import layout, token

    fb = sl.FrameBuffer(6, 3, mode="RGB", background="white")
    seen = []

    def draw(buf, packed, width, height, ox, oy, value):
        seen.append((width, height, ox, oy, packed))
        draw_line(buf, layout(packed), width, height, -10 - ox, 1 - oy, 20 - ox, 1 - oy, value,
                  token(BRESENHAM))

    _blend.paint(fb, (0, 0, 0, 255 // 2), (-10, 0, 20, 2), draw)
    assert seen == [(6, 3, 0, 0, False)]                  # the box clipped to fb
    assert fb.to_array()[1].tolist() == [[128, 128, 128]] * 6
    assert fb.to_array()[0].tolist() == [[255, 255, 255]] * 6


def test_sources_accepts_arrays_with_alpha_in_every_mode():
    for mode in ("1", "L", "RGB", "RGBA", "P"):
        fb = sl.FrameBuffer(2, 2, mode=mode)
        src = _blend.sources(fb, np.array([[255, 0, 0, 51], [0, 0, 255, 255]]), 2)
        assert src.shape == (2, 4)
        assert src[:, 3].tolist() == [0.2, 1.0]


def test_translucent_detection():
    assert not _blend.translucent("red")
    assert _blend.translucent("#f008")
    assert _blend.translucent((1, 2, 3, 254))
    assert not _blend.translucent(7)
    assert _blend.translucent(np.array([[1, 2, 3, 255], [1, 2, 3, 0]]))
    assert not _blend.translucent(np.array([[1, 2, 3], [1, 2, 3]]))


def test_bad_colors_are_named():
    fb = sl.FrameBuffer(4, 4)
    with pytest.raises(sl.ArgumentValueError, match="color"):
        sl.draw.polygon(fb, SQUARE, "#12345g80")
    with pytest.raises(sl.ArgumentValueError, match="2 colors"):
        sl.draw.polygons(fb, [SQUARE], ["red", (0, 0, 0, 9)])


def test_blending_is_a_weighted_average_not_a_sum():
    # erratum E20: the glossary's "adding them" would give 200 here
    fb = sl.FrameBuffer(4, 4, mode="L", background=100)
    paint_all(fb, (100, 100, 100, 128))
    assert fb.get_pixel(0, 0) == 100
    fb = sl.FrameBuffer(4, 4, mode="RGB", background=(100, 0, 0))
    paint_all(fb, (0, 0, 100, 128))
    # 0.502 * (0, 0, 100) + 0.498 * (100, 0, 0) = (49.8, 0, 50.2)
    assert fb.get_pixel(0, 0) == (50, 0, 50)


coords = st.one_of(st.integers(-2**30, 2**30), st.integers(-20, 30))


@settings(max_examples=40, deadline=None)
@given(pts=st.lists(st.tuples(coords, coords), min_size=3, max_size=6),
       r=st.integers(0, 2**20), mode=st.sampled_from(["1", "L", "RGB", "RGBA", "P"]))
def test_fuzz_translucent_areas_stay_inside(pts, r, mode):
    fb = sl.FrameBuffer(9, 7, mode=mode)
    buf = fb._buf
    big = np.full((buf.shape[0] + 4,) + buf.shape[1:], 77, np.uint8)
    big[2:-2] = buf
    fb._buf = big[2:-2]
    sl.draw.polygon(fb, pts, (10, 200, 30, 100))
    sl.draw.polygons(fb, [pts, pts[::-1]], [(10, 200, 30, 100), (0, 0, 0, 1)])
    sl.draw.fill_circle(fb, pts[0][0] % 50 - 20, pts[0][1] % 50 - 20, r, "#ff000080")
    assert (big[:2] == 77).all() and (big[-2:] == 77).all()


@pytest.mark.parametrize("mode", ["1", "L", "RGB", "RGBA", "P"])
def test_translucent_seed_fills_composite_over_the_region(mode):
    def scene():
        fb = sl.FrameBuffer(12, 8, mode=mode, background="white")
        sl.draw.circle(fb, 5, 4, 3, "black")
        sl.draw.line(fb, 9, 0, 9, 7, (128, 128, 128))
        return fb

    def changed(fb):
        a = fb.to_array() != scene().to_array()
        return a if a.ndim == 2 else a.any(axis=2)

    for fill, kwargs in ((sl.draw.flood_fill, {}), (sl.draw.boundary_fill, {"boundary": "black"})):
        opaque, clear = scene(), scene()
        n = fill(opaque, 5, 4, "red", **kwargs)
        assert fill(clear, 5, 4, (255, 0, 0, 200), **kwargs) == n > 0
        # the disk inside the circle, and nothing else, was composited (red at
        # a = 0.78 changes every white pixel in every mode, as opaque red does)
        assert np.array_equal(changed(clear), changed(opaque))
        assert changed(clear).sum() == n


def test_translucent_flood_fill_by_hand_with_full_tolerance():
    fb = sl.FrameBuffer(3, 1, mode="L", background=0)
    fb.set_pixel(1, 0, 100)
    fb.set_pixel(2, 0, 200)
    assert sl.draw.flood_fill(fb, 0, 0, (255, 255, 255, 51), tolerance=255) == 3
    # a = 0.2: 0 -> 51, 100 -> 131, 200 -> 211
    assert fb.to_array().tolist() == [[51, 131, 211]]


def test_a_list_is_one_color_for_one_primitive():
    fb = sl.FrameBuffer(4, 4, mode="RGB", background="white")
    paint_all(fb, [0, 0, 255, 128])
    assert fb.get_pixel(0, 0) == (127, 127, 255)
