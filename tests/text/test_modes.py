"""Text in every frame-buffer mode, opaque and translucent, with and without
antialiasing; the glyph cache changes nothing."""

from collections import OrderedDict

import numpy as np
import pytest

import scanline as sl
from scanline.text import glyphcache


def test_every_mode_sets_the_same_pixels():
    masks = []
    for mode, color in (("1", 1), ("L", 200), ("RGB", "red"), ("RGBA", "red"), ("P", "red")):
        fb = sl.FrameBuffer(60, 20, mode=mode)
        sl.draw.text(fb, 2, 5, "Mode&", color=color, height=11)
        a = fb.to_array()
        masks.append(a.any(axis=2) if a.ndim == 3 and mode != "RGBA" else
                     a[..., 0] > 0 if a.ndim == 3 else a > 0)
    for m in masks[1:]:
        assert (m == masks[0]).all()
    assert masks[0].sum() > 50


def test_translucent_color_composites_over():
    fb = sl.FrameBuffer(30, 20, mode="RGB", background=(0, 0, 200))
    sl.draw.text(fb, 2, 2, "I", color=(255, 0, 0, 64), font="bitmap", height=14)
    inside = fb.to_array()[20 - 1 - 8, 2 + 4]        # a pixel of the I's stem
    w = 64 / 255
    expected = (round(255 * w), 0, round(200 * (1 - w)))
    assert tuple(int(c) for c in inside) == pytest.approx(expected, abs=1)
    fb = sl.FrameBuffer(30, 20, mode="RGBA", background=(0, 0, 0, 0))
    sl.draw.text(fb, 2, 2, "I", color=(255, 0, 0, 64), font="bitmap", height=14)
    assert tuple(int(c) for c in fb.to_array()[20 - 1 - 8, 6]) == (255, 0, 0, 64)


def test_antialiased_text_in_gray_bitmap_and_palette():
    gray = sl.FrameBuffer(60, 24, mode="L")
    sl.draw.text(gray, 2.3, 6.6, "aA", color=255, height=13, antialias=True)
    g = gray.to_array()
    assert ((g > 0) & (g < 255)).sum() > 20
    bits = sl.FrameBuffer(60, 24, mode="1")
    sl.draw.text(bits, 2.3, 6.6, "aA", color=1, height=13, antialias=True)
    assert (bits.to_array() == (g >= 128)).mean() > 0.99
    pal = sl.FrameBuffer(60, 24, mode="P", color_table=["black", "white"])
    sl.draw.text(pal, 2.3, 6.6, "aA", color="red", height=13, antialias=True)
    p = pal.to_array()
    assert len(pal.color_table) == 3 and set(np.unique(p)) == {0, 2}


@pytest.mark.parametrize("mode, antialias", [("1", False), ("L", True), ("RGB", True)])
def test_cached_and_direct_fills_agree(monkeypatch, mode, antialias):
    """Huge glyphs are filled directly instead of cached: same pixels either way
    (antialiased: coverage quantized to 1/255 once either way)."""
    cached = sl.FrameBuffer(200, 120, mode=mode)
    sl.draw.text(cached, 3, 20, "Sg", height=70, angle=0.1, antialias=antialias)
    monkeypatch.setattr(glyphcache, "MAX_CACHED", 1)
    monkeypatch.setattr(glyphcache, "_CACHES", OrderedDict())    # forget the cached size
    direct = sl.FrameBuffer(200, 120, mode=mode)
    sl.draw.text(direct, 3, 20, "Sg", height=70, angle=0.1, antialias=antialias)
    assert [images for _, images in glyphcache._CACHES.values()] == [None]   # filled directly
    a, b = cached.to_array().astype(int), direct.to_array().astype(int)
    assert np.abs(a - b).max() <= (1 if antialias else 0)
    assert (a > 0).sum() > 1000


def test_text_far_outside_is_clipped():
    fb = sl.FrameBuffer(20, 20)
    sl.draw.text(fb, -5000, 10, "clipped " * 20, height=12)
    sl.draw.text(fb, 2**30, -2**30, "far", height=12, angle=1)
    assert fb.to_array().sum() == 0
    sl.draw.text(fb, -3, 5, "W", height=12)            # partly inside
    assert fb.to_array().sum() > 0


@pytest.mark.parametrize("font", ["sans", "stroke", "bitmap"])
def test_text_at_any_finite_reference_point(font):
    # refused beyond +-2**30 before (issue 11: any finite coordinate is drawn): far
    # away, nothing of it reaches the frame; the same string near it does
    fb = sl.FrameBuffer(40, 20)
    for x, y in ((1e12, 5), (-1e12, 5), (3, 1e300), (-1e300, -1e300), (2**31, 2**31)):
        for angle in (0.0, 0.7):
            sl.draw.text(fb, x, y, "far text", font=font, height=12, angle=angle)
    assert fb.to_array().sum() == 0
    sl.draw.text(fb, 2, 5, "far text", font=font, height=12)
    assert fb.to_array().sum() > 0


@pytest.mark.parametrize("font", ["sans", "stroke", "bitmap"])
@pytest.mark.parametrize("antialias", [False, True])
def test_huge_text_at_the_edge_of_the_coordinate_range(font, antialias):
    fb = sl.FrameBuffer(30, 30, mode="L")
    sl.draw.text(fb, 2**30, 2**30, "far", font=font, height=2**20, antialias=antialias)
    sl.draw.text(fb, -2**30, 5, "far " * 5, font=font, height=5000, angle=2.0,
                 antialias=antialias)
    assert fb.to_array().sum() == 0
    sl.draw.text(fb, -100, -300, "H", font=font, height=600, antialias=antialias)
    assert fb.to_array().sum() > 0           # part of a huge H (its stem or crossbar)


def test_glyph_image_runs():
    mask = np.array([[0, 255, 255, 0, 9],
                     [0, 0, 0, 0, 0],
                     [255, 255, 255, 255, 255]], np.uint8)
    assert glyphcache._runs(mask).tolist() == [[0, 1, 3], [0, 4, 5], [2, 0, 5]]
    assert glyphcache._runs(np.zeros((0, 0), np.uint8)).shape == (0, 3)
