"""Text clipping: all-or-none string, all-or-none character, strokes/contours and
pixels of each character, for the three kinds of font."""

import numpy as np
import pytest

import scanline as sl
from tests.clip.shapes import area, shapely

WINDOW = (5.0, 0.0, 40.0, 30.0)


def glyphs(font):
    return sl.text.layout("Clip it", 0, 8, font=font, height=14)


def inside(box, window):
    return (box[0] >= window[0] and box[1] >= window[1] and box[2] <= window[2]
            and box[3] <= window[3])


@pytest.mark.parametrize("font", ["bitmap", "stroke", "sans"])
def test_all_or_none(font):
    g = glyphs(font)
    kept = sl.clip.text(g, WINDOW, mode="character")
    assert [k.char for k in kept] == [k.char for k in g if inside(k.cell, WINDOW)]
    assert 0 < len(kept) < len(g)
    assert sl.clip.text(g, WINDOW, mode="string") == []
    big = (-100, -100, 400, 100)
    assert sl.clip.text(g, big, mode="string") == g


def test_strokes_clipped_like_shapely():
    g = glyphs("stroke")
    clipped = sl.clip.text(g, WINDOW, mode="stroke")
    box = shapely.box(*WINDOW)
    want = sum(shapely.LineString(s).intersection(box).length
               for k in g if k.strokes for s in k.strokes if len(s) > 1)
    got = sum(np.hypot(*np.diff(p, axis=0).T).sum() for k in clipped for p in k.strokes)
    assert got == pytest.approx(want, rel=1e-9)
    for k in clipped:
        for p in k.strokes:
            assert inside((*p.min(0), *p.max(0)), WINDOW)


@pytest.mark.parametrize("font", ["bitmap", "sans"])
def test_contours_clipped_like_shapely(font):
    g = glyphs(font)
    clipped = sl.clip.text(g, WINDOW, mode="stroke")
    box = shapely.box(*WINDOW)
    # each contour keeps its orientation: signed areas add up under the nonzero rule
    want = sum(np.sign(area([c])) * shapely.Polygon(c).intersection(box).area
               for k in g if k.contours for c in k.contours)
    assert area([c for k in clipped for c in k.contours]) == pytest.approx(want, rel=1e-9)
    assert {k.char for k in clipped} <= {k.char for k in g}


@pytest.mark.parametrize("font", ["bitmap", "stroke", "sans"])
def test_pixels_clipped(font):
    g = glyphs(font)
    clipped = {k.index: k for k in sl.clip.text(g, WINDOW, mode="pixel")}
    for k in g:
        if k.box is None or k.bitmap.size == 0:
            continue
        x0, y0 = k.bitmap_origin
        h = k.bitmap.shape[0]
        want = {(x0 + c, y0 + h - 1 - r) for r, c in zip(*np.nonzero(k.bitmap))
                if WINDOW[0] <= x0 + c <= WINDOW[2] and WINDOW[1] <= y0 + h - 1 - r <= WINDOW[3]}
        if not want:
            assert k.index not in clipped
            continue
        m = clipped[k.index].bitmap          # in the clipped glyph's own image
        cx0, cy0 = clipped[k.index].bitmap_origin
        got = {(cx0 + c, cy0 + m.shape[0] - 1 - r) for r, c in zip(*np.nonzero(m))}
        assert got == want


def test_a_stroke_glyph_far_larger_than_the_window_is_clipped_in_bounded_memory():
    """A stroke glyph scaled 3000 times (an image of 6e8 pixels) clipped to a 21 x 16
    window: rasterized only where the window is (the pixels the whole glyph sets there,
    compared on a 200-times glyph whose whole image is small), and one scaled beyond
    any image is refused with an error naming the text, never allocated."""
    def placed(scale):
        return sl.text.layout("A", 0, 0, font="stroke", height=7 * scale)

    window = (0, 0, 20, 15)
    for scale in (200, 3000):
        (g,) = placed(scale)
        (c,) = sl.clip.text([g], window, mode="stroke")
        m = c.bitmap
        assert m.shape[0] * m.shape[1] <= 22 * 17
        cx0, cy0 = c.bitmap_origin
        got = {(cx0 + col, cy0 + m.shape[0] - 1 - row) for row, col in zip(*np.nonzero(m))}
        if scale == 200:     # the whole glyph's image (1400 px high) is small enough
            full, (x0, y0) = g.bitmap, g.bitmap_origin
            want = {(x0 + col, y0 + full.shape[0] - 1 - row)
                    for row, col in zip(*np.nonzero(full))
                    if 0 <= x0 + col <= 20 and 0 <= y0 + full.shape[0] - 1 - row <= 15}
            assert got == want and want
    from scanline.text.glyphcache import stroke_bitmap
    with pytest.raises(sl.ArgumentValueError, match="text: a stroke glyph's image"):
        stroke_bitmap([np.array([[0.0, 0.0], [1e5, 1e5]])])


def test_bad_text_input():
    with pytest.raises(sl.ArgumentValueError, match="mode"):
        sl.clip.text(glyphs("bitmap"), WINDOW, mode="word")
    with pytest.raises(sl.ArgumentTypeError, match="layout"):
        sl.clip.text("Clip it", WINDOW)
    with pytest.raises(sl.ArgumentValueError, match="window"):
        sl.clip.text(glyphs("bitmap"), (0, 0, 0, 1))
