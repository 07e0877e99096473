"""The dot-matrix font: golden images, pixel replication, dots stamped as squares."""

import numpy as np
import pytest

import scanline as sl
from scanline.text import catalog

DATA = catalog.DATA / "dotmatrix-5x7.txt"


def read_dots():
    """An independent reader of the font file: {char: bool array 9 x 5}."""
    lines = DATA.read_text().splitlines()
    out = {}
    for i, line in enumerate(lines):
        if line.startswith("chars "):
            chars = [" " if t == "SP" else t for t in line.split()[1:]]
            rows = [r.split() for r in lines[i + 1:i + 10]]
            for n, ch in enumerate(chars):
                out[ch] = np.array([[s == "@" for s in row[n]] for row in rows])
    return out


def pixels(fb):
    return sl.text_image(fb).splitlines()


def test_file_holds_every_printable_ascii_character():
    dots = read_dots()
    assert sorted(dots) == [chr(c) for c in range(32, 127)]
    assert all(d.shape == (9, 5) for d in dots.values())
    # descenders only where the design puts them
    below = {ch for ch, d in dots.items() if d[7:].any()}
    assert below == set("gjpqy,_")


def test_golden_hi():
    fb = sl.FrameBuffer(18, 9, mode="1")
    sl.draw.text(fb, 0, 0, "Hi!", font="bitmap")
    assert pixels(fb) == [
        "------------------",
        "#---#---#-----#---",
        "#---#---------#---",
        "#---#--##-----#---",
        "#####---#-----#---",
        "#---#---#-----#---",
        "#---#---#---------",
        "#---#--###----#---",
        "------------------",
    ]


def test_golden_descenders_hang_below_the_baseline():
    fb = sl.FrameBuffer(12, 10, mode="1")
    sl.draw.text(fb, 0, 2, "gy", font="bitmap")
    assert pixels(fb) == [
        "------------",      # y = 9: rows 1 and 2 of g and y are blank
        "------------",
        "-####-#---#-",
        "#---#-#---#-",
        "#---#-#---#-",
        "#---#-#---#-",
        "-####--####-",      # y = 3, the row just above the baseline
        "----#-----#-",      # y = 2, the baseline's row: the first descender row
        "-###---###--",
        "------------",
    ]


@pytest.mark.parametrize("k", [2, 3])
def test_integer_heights_replicate_pixels(k):
    small = sl.FrameBuffer(30, 10, mode="1")
    sl.draw.text(small, 0, 2, "Ag5?", font="bitmap")
    big = sl.FrameBuffer(30 * k, 10 * k, mode="1")
    sl.draw.text(big, 0, 2 * k, "Ag5?", font="bitmap", height=7 * k)
    a = small.to_array()[::-1]           # row y = scan line y
    b = big.to_array()[::-1]
    # dot (c, r) covers [k c, k c + k] x [k r, k r + k] and so the pixel centers
    # x in k c .. k c + k - 1, y in k r + 1 .. k r + k (above the origin's row);
    # at k = 1 that is pixel (c, r + 1)
    ys, xs = np.nonzero(a)
    assert ys.min() == 1                 # g's lowest dot row, r = -2: y = 2 - 2 + 1
    expected = np.zeros_like(b)
    for y, x in zip(ys, xs):
        r = y - 2 - 1
        expected[2 * k + k * r + 1:2 * k + k * r + k + 1, k * x:k * x + k] = True
    assert (b == expected).all()


def test_other_heights_stamp_each_dot_as_a_square():
    dots = read_dots()
    s = 10.5 / 7
    fb = sl.FrameBuffer(20, 16, mode="1")
    sl.draw.text(fb, 2, 3, "R", font="bitmap", height=10.5)
    got = fb.to_array()[::-1]
    expected = np.zeros_like(got)
    for row, line in enumerate(dots["R"]):
        r = 6 - row
        for c, on in enumerate(line):
            if not on:
                continue
            x0, x1 = 2 + s * c, 2 + s * (c + 1)
            y0, y1 = 3 + s * r, 3 + s * (r + 1)
            for y in range(16):
                for x in range(20):
                    # pixel center inside, by the fill's top-left rule
                    if x0 <= x < x1 and y0 < y <= y1:
                        expected[y, x] = True
    assert (got == expected).all()
    assert got.sum() > 0


def test_missing_character_is_a_hollow_box():
    fb = sl.FrameBuffer(12, 9, mode="1")
    sl.draw.text(fb, 0, 0, "\u20ac!", font="bitmap")
    assert pixels(fb) == [
        "------------",
        "#####---#---",
        "#---#---#---",
        "#---#---#---",
        "#---#---#---",
        "#---#---#---",
        "#---#-------",
        "#####---#---",
        "------------",
    ]
