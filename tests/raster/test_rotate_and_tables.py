"""Block rotation with area coverage, and color-table animation."""

import math

import numpy as np
import pytest
import shapely

import scanline as sl
from scanline.raster import ColorTableAnimation, rotate_block

RNG = np.random.default_rng(8)


def shapely_rotation(src_values, x0, y0, center, angle, size):
    """Each destination pixel: the areas shapely finds for the rotated source squares."""
    h, w = src_values.shape
    cx, cy = x0 + (w - 1) / 2, y0 + (h - 1) / 2
    c, s = math.cos(angle), math.sin(angle)
    acc = np.zeros(size[::-1])
    cover = np.zeros(size[::-1])
    pixels = [[shapely.box(x - 0.5, y - 0.5, x + 0.5, y + 0.5) for x in range(size[0])]
              for y in range(size[1])]
    for j in range(h):
        for i in range(w):
            corners = [(x0 + i + dx - cx, y0 + j + dy - cy)
                       for dx, dy in ((-.5, -.5), (.5, -.5), (.5, .5), (-.5, .5))]
            quad = shapely.Polygon([(center[0] + c * u - s * v, center[1] + s * u + c * v)
                                    for u, v in corners])
            for y in range(size[1]):
                for x in range(size[0]):
                    a = quad.intersection(pixels[y][x]).area
                    acc[y, x] += a * src_values[j, i]
                    cover[y, x] += a
    return acc, cover


@pytest.mark.parametrize("angle", [0.3, math.pi / 5, 2.0, -1.1])
def test_area_coverage_against_shapely(angle):
    values = RNG.integers(0, 256, (4, 5)).astype(np.uint8)        # storage rows, y up
    src = sl.FrameBuffer.from_array(values[::-1].copy())
    dst = sl.FrameBuffer(12, 12, mode="L", background=40)
    rotate_block(dst, src, (0, 0, 5, 4), angle, center=(5.3, 6.1))
    acc, cover = shapely_rotation(values.astype(float), 0, 0, (5.3, 6.1), angle, (12, 12))
    want = np.where(cover > 0, np.floor(acc + (1 - np.minimum(cover, 1)) * 40 + 0.5), 40)
    got = dst.to_array()[::-1].astype(float)
    assert np.abs(got - want).max() <= 1          # rounding at exact halves only


def test_identity_and_quarter_turns_are_exact():
    a = RNG.integers(0, 256, (6, 6, 3), dtype=np.uint8)
    src = sl.FrameBuffer.from_array(a)
    same = sl.FrameBuffer(6, 6)
    rotate_block(same, src, (0, 0, 6, 6), 0.0)
    np.testing.assert_array_equal(same.to_array(), a)
    turned = sl.FrameBuffer(6, 6)
    rotate_block(turned, src, (0, 0, 6, 6), math.pi / 2)
    np.testing.assert_array_equal(turned.to_array(), np.rot90(a))   # counterclockwise


def test_area_is_conserved():
    src = sl.FrameBuffer(10, 6, mode="L", background=200)
    dst = sl.FrameBuffer(30, 30, mode="L", background=0)
    rotate_block(dst, src, (0, 0, 10, 6), 0.7, center=(15, 15))
    total = dst.to_array().astype(float).sum()
    assert total == pytest.approx(200 * 60, rel=0.01)


@pytest.mark.parametrize("mode", ["1", "P"])
def test_nearest_in_modes_without_levels(mode):
    color = 1 if mode == "1" else "red"
    src = sl.FrameBuffer(4, 2, mode=mode, **({} if mode == "1" else {"color_table": ["black", "red"]}))
    sl.draw.line(src, 0, 0, 3, 0, color=color)
    dst = sl.FrameBuffer(8, 8, mode=mode, **({} if mode == "1" else {"color_table": ["black", "red"]}))
    rotate_block(dst, src, (0, 0, 4, 2), math.pi / 2, center=(4.5, 4.5))
    lit = {(int(x), 7 - int(r)) for r, x in zip(*np.nonzero(dst.to_array()))}
    # destination (x, y) reads source (1.5 + (y - 4.5), 0.5 - (x - 4.5)) = (y - 3, 5 - x):
    # the source row j = 0 is x = 5, and i = 0..3 is y = 3..6
    assert lit == {(5, y) for y in range(3, 7)}
    with pytest.raises(sl.ScanlineError, match="method='nearest'"):
        rotate_block(dst, src, (0, 0, 4, 2), 0.5, method="area")


def _disk(fb, x, color):
    sl.draw.fill_circle(fb, x, 10, 6, color=color)


@pytest.mark.parametrize("method,step", [("entries", 14), ("bit-planes", 14), ("bit-planes", 5)])
def test_color_table_frames_equal_direct_drawing(method, step):
    # step 14: positions apart (both methods exact); step 5: they overlap (bit planes only)
    n = 8 if method == "bit-planes" else 12
    cta = ColorTableAnimation(12 + step * n, 21, steps=n, color="orange", background="navy",
                              method=method)
    for k in range(n):
        cta.draw(k, lambda fb, color, k=k: _disk(fb, 8 + step * k, color))
    for k in range(n):
        direct = sl.FrameBuffer(12 + step * n, 21, background="navy")
        _disk(direct, 8 + step * k, "orange")
        frame = cta.frame(k)
        assert frame.mode == "P"
        np.testing.assert_array_equal(np.asarray(frame.to_pil().convert("RGB")), direct.to_array())
        np.testing.assert_array_equal(frame.to_array(), cta.fb.to_array())  # same indices
    np.testing.assert_array_equal(cta.table(n + 2), cta.table(2))            # cycling


def test_color_table_entries_overlap_keeps_the_later_position():
    cta = ColorTableAnimation(40, 21, steps=2, color="white", method="entries")
    cta.draw(0, lambda fb, color: _disk(fb, 15, color))
    cta.draw(1, lambda fb, color: _disk(fb, 20, color))
    direct = sl.FrameBuffer(40, 21)
    _disk(direct, 15, "white")
    first = np.asarray(cta.frame(0).to_pil().convert("RGB"))
    assert (first != direct.to_array()).any()          # the overlap belongs to position 1


def test_color_table_animation_saves_a_gif(tmp_path):
    from PIL import Image
    cta = ColorTableAnimation(60, 21, steps=4, color="yellow", background="black")
    for k in range(4):
        cta.draw(k, lambda fb, color, k=k: _disk(fb, 8 + 14 * k, color))
    cta.animation(fps=10).save(tmp_path / "cycle.gif")
    with Image.open(tmp_path / "cycle.gif") as im:
        assert im.n_frames == 4


@pytest.mark.parametrize("call,words", [
    (lambda: ColorTableAnimation(10, 10, steps=9, method="bit-planes"), "more than"),
    (lambda: ColorTableAnimation(10, 10, steps=256), "more than"),
    (lambda: ColorTableAnimation(10, 10, steps=3, method="planes"), "method must be one of"),
    (lambda: ColorTableAnimation(10, 10, steps=3).draw(3, lambda fb, c: None), "positions are"),
    (lambda: ColorTableAnimation(10, 10, steps=3).draw(0, "circle"), "draw must be a function"),
    (lambda: rotate_block(sl.FrameBuffer(4, 4), sl.FrameBuffer(4, 4, mode="L"), (0, 0, 2, 2), 1.0),
     "one mode"),
    (lambda: rotate_block(sl.FrameBuffer(4, 4), sl.FrameBuffer(4, 4), (0, 0, 2, 2), float("nan")),
     "angle must be a finite"),
])
def test_bad_input(call, words):
    with pytest.raises(sl.ScanlineError, match=words):
        call()
