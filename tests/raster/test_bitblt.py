"""Block transfers: the 16 raster operations against numpy's bitwise operators."""

import numpy as np
import pytest

import scanline as sl
from scanline.raster import OPS, XorSprite, bitblt, op_code

RNG = np.random.default_rng(3)

# each raster operation written with numpy's bitwise operators, by its meaning
NUMPY = {
    "clear": lambda s, d: np.zeros_like(d), "and": np.bitwise_and,
    "and-reverse": lambda s, d: s & np.invert(d), "copy": lambda s, d: s,
    "and-inverted": lambda s, d: np.invert(s) & d, "noop": lambda s, d: d,
    "xor": np.bitwise_xor, "or": np.bitwise_or,
    "nor": lambda s, d: np.invert(s | d), "equiv": lambda s, d: np.invert(s ^ d),
    "invert": lambda s, d: np.invert(d), "or-reverse": lambda s, d: s | np.invert(d),
    "copy-inverted": lambda s, d: np.invert(s), "or-inverted": lambda s, d: np.invert(s) | d,
    "nand": lambda s, d: np.invert(s & d), "set": lambda s, d: np.full_like(d, 255),
}


def truth_table(code, s, d):
    """Bit by bit: bit 3 - (2 s + d) of the X11 code is the result."""
    out = np.zeros_like(d)
    for bit in range(8):
        sb, db = (s >> bit) & 1, (d >> bit) & 1
        out |= (((code >> (3 - (2 * sb + db))) & 1) << bit).astype(np.uint8)
    return out


def test_sixteen_ops_in_x11_order():
    assert len(OPS) == 16 and len(set(OPS)) == 16 and set(NUMPY) == set(OPS)
    assert op_code("not") == op_code("copy-inverted") == 12 and op_code("xnor") == 9


@pytest.mark.parametrize("op", OPS)
@pytest.mark.parametrize("mode", ["L", "RGB", "RGBA"])
def test_op_against_numpy(op, mode):
    shape = {"L": (20, 30), "RGB": (20, 30, 3), "RGBA": (20, 30, 4)}[mode]
    s = RNG.integers(0, 256, shape, dtype=np.uint8)
    d = RNG.integers(0, 256, shape, dtype=np.uint8)
    dst = sl.FrameBuffer.from_array(d)
    bitblt(dst, sl.FrameBuffer.from_array(s), (0, 0, 30, 20), (0, 0), op=op)
    np.testing.assert_array_equal(dst.to_array(), NUMPY[op](s, d))
    np.testing.assert_array_equal(dst.to_array(), truth_table(OPS.index(op), s, d))


@pytest.mark.parametrize("op", OPS)
def test_op_on_bits(op):
    s = RNG.integers(0, 2, (9, 37)).astype(bool)
    d = RNG.integers(0, 2, (9, 37)).astype(bool)
    dst = sl.FrameBuffer.from_array(d)
    # an unaligned block: source x = 3..24 to destination x = 11..32, rows 2..7
    bitblt(dst, sl.FrameBuffer.from_array(s), (3, 1, 22, 6), (11, 2), op=op)
    s8, d8 = s.astype(np.uint8), d.astype(np.uint8)
    want = d8.copy()
    rows_d = slice(9 - 2 - 6, 9 - 2)             # image order: y up
    rows_s = slice(9 - 1 - 6, 9 - 1)
    want[rows_d, 11:33] = NUMPY[op](s8[rows_s, 3:25], d8[rows_d, 11:33]) & 1
    np.testing.assert_array_equal(dst.to_array(), want.astype(bool))


def test_clipping_at_every_edge():
    src = sl.FrameBuffer.from_array(RNG.integers(1, 256, (10, 10), dtype=np.uint8))
    for rect, at in [((-5, -5, 20, 20), (3, 3)), ((2, 2, 5, 5), (-3, 7)), ((0, 0, 10, 10), (8, -8)),
                     ((0, 0, 10, 10), (100, 100)), ((0, 0, 0, 4), (0, 0))]:
        dst = sl.FrameBuffer(12, 12, mode="L")
        bitblt(dst, src, rect, at)
        x, y, w, h = rect
        # the slow way: each source pixel inside both rasters
        want = sl.FrameBuffer(12, 12, mode="L")
        for j in range(h):
            for i in range(w):
                sx, sy, dx, dy = x + i, y + j, at[0] + i, at[1] + j
                if 0 <= sx < 10 and 0 <= sy < 10 and 0 <= dx < 12 and 0 <= dy < 12:
                    want.set_pixel(dx, dy, src.get_pixel(sx, sy))
        np.testing.assert_array_equal(dst.to_array(), want.to_array())


def test_overlapping_move_within_one_frame_buffer():
    a = RNG.integers(0, 256, (8, 8), dtype=np.uint8)
    fb = sl.FrameBuffer.from_array(a)
    bitblt(fb, fb, (0, 0, 6, 6), (2, 2))           # shift up-right by 2 over itself
    want = a.copy()
    want[0:6, 2:8] = a[2:8, 0:6]                   # image order: rows 2..7 from the bottom
    np.testing.assert_array_equal(fb.to_array(), want)


def test_xor_sprite_restores_the_background():
    background = RNG.integers(0, 256, (30, 40, 3), dtype=np.uint8)
    fb = sl.FrameBuffer.from_array(background)
    sprite = sl.FrameBuffer(6, 6, background="black")
    sl.draw.fill_circle(sprite, 3, 3, 2, color="white")
    ball = XorSprite(sprite)
    ball.show(fb, (0, 0))
    for x in range(0, 38, 3):
        ball.move(fb, (x, x // 2))
        assert not np.array_equal(fb.to_array(), background)
    ball.hide(fb)
    np.testing.assert_array_equal(fb.to_array(), background)


def test_color_table_indices():
    src = sl.FrameBuffer(4, 1, mode="P", color_table=["black", "red", "green", "blue"])
    src.set_pixel(1, 0, 1)
    src.set_pixel(2, 0, 3)
    dst = sl.FrameBuffer(4, 1, mode="P", color_table=["black", "red", "green", "blue"])
    dst.set_pixel(2, 0, 2)
    bitblt(dst, src, (0, 0, 4, 1), (0, 0), op="or")
    assert dst.to_array().tolist() == [[0, 1, 3, 0]]            # 3 | 2 = 3
    with pytest.raises(sl.ScanlineError, match="table has 4 entries"):
        bitblt(dst, src, (0, 0, 4, 1), (0, 0), op="invert")     # ~0 = 255: no such entry
    assert dst.to_array().tolist() == [[0, 1, 3, 0]]            # unchanged


@pytest.mark.parametrize("call,words", [
    (lambda: bitblt(sl.FrameBuffer(4, 4), sl.FrameBuffer(4, 4, mode="L"), (0, 0, 2, 2), (0, 0)),
     "modes must match"),
    (lambda: bitblt(sl.FrameBuffer(4, 4), sl.FrameBuffer(4, 4), (0, 0, 2, 2), (0, 0), op="blend"),
     "op must be one of"),
    (lambda: bitblt(sl.FrameBuffer(4, 4), sl.FrameBuffer(4, 4), (0, 0, -2, 2), (0, 0)),
     "width and height >= 0"),
    (lambda: bitblt(sl.FrameBuffer(4, 4), sl.FrameBuffer(4, 4), (0, 0, 2, 2), (float("nan"), 0)),
     "finite"),
    (lambda: bitblt(sl.FrameBuffer(4, 4), np.zeros((4, 4)), (0, 0, 2, 2), (0, 0)), "FrameBuffer"),
    (lambda: bitblt(sl.FrameBuffer(4, 4), sl.FrameBuffer(4, 4), (0, 0, 2), (0, 0)), "rect must be"),
])
def test_bad_input(call, words):
    with pytest.raises(sl.ScanlineError, match=words):
        call()
