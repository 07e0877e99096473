"""Small defects a new user met (issue 16, item 9), each pinned: the step tables'
notes, the closed last knot span, ``is_convex``, one pen vocabulary, the textbook's
name of ordered dithering, and one clipping rule for reading and writing pixels."""

import math
import re

import numpy as np
import pytest

import scanline as sl
from scanline.cli.draw import parse_items, render

LINES = [(0, 0, 3, 7), (0, 0, 7, 3), (5, 1, -2, 9), (3, 3, 3, -4), (-4, 2, 6, 2),
         (0, 0, 5, 5), (9, 0, 0, 4), (20, 10, 30, 18)]


@pytest.mark.parametrize("x0, y0, x1, y1", LINES)
def test_bresenham_note_states_the_true_inequality(call, x0, y0, x1, y1):
    out = call("trace", "bresenham", x0, y0, x1, y1).out
    major, minor, op, major2 = re.search(
        r"major axis (x|y) \(\|d(x|y)\| (<=|<|>=|>) \|d(x|y)\|\)", out).groups()
    assert major == major2 != minor
    d = {"x": abs(x1 - x0), "y": abs(y1 - y0)}
    holds = {"<": d[minor] < d[major], "<=": d[minor] <= d[major],
             ">": d[minor] > d[major], ">=": d[minor] >= d[major]}[op]
    assert holds and d[major] >= d[minor], out.splitlines()[1]


@pytest.mark.parametrize("x0, y0, x1, y1", LINES + [(7, 10, 0, 0), (0, 0, 10, 7)])
def test_dda_printed_reals_round_to_the_printed_pixels(call, x0, y0, x1, y1):
    """A reader who rounds the printed x_real half up must get the printed x."""
    lines = call("trace", "dda", x0, y0, x1, y1, "--format", "csv").out.splitlines()
    header = lines[0].split(",")
    for line in lines[1:]:
        row = dict(zip(header, line.split(",")))
        for axis in "xy":
            assert math.floor(float(row[f"{axis}_real"]) + 0.5) == int(row[axis]), row


def test_dda_the_issue_row(call):
    out = call("trace", "dda", 7, 10, 0, 0).out
    row5 = next(line.split() for line in out.splitlines() if line.split()[:1] == ["5"])
    assert row5[2:] == ["5", "3", "5"] and float(row5[1]) < 3.5 and row5[1] != "3.5"


def test_cox_de_boor_shows_the_closed_last_span(call):
    at_end = call("trace", "cox-de-boor", "--knots", "0,0,0,0,1,2,2,2,2", "--order", "4",
                  "--u", "2").out
    assert "u = 2 in span 4: [1, 2]" in at_end and "[1, 2)" not in at_end
    inside = call("trace", "cox-de-boor", "--knots", "0,0,0,0,1,2,2,2,2", "--order", "4",
                  "--u", "1.5").out
    assert "u = 1.5 in span 4: [1, 2)" in inside and "[1, 2]" not in inside
    # the basis at the end is the interpolated last control point's: B_4,4(2) = 1
    table = sl.trace.cox_de_boor([0, 0, 0, 0, 1, 2, 2, 2, 2], 4, 2)
    assert [r["B"] for r in table.rows if r["r"] == 4] == [0, 0, 0, 1]


@pytest.mark.parametrize("ring, convex", [
    ([(0, 0), (4, 0), (1, 1), (0, 4)], False),       # the issue's dart
    ([(0, 0), (4, 0), (0, 4)], True),                 # counterclockwise
    ([(0, 0), (0, 4), (4, 0)], True),                 # clockwise
    ([(0, 0), (2, 0), (4, 0), (4, 4), (0, 4)], True),   # a collinear vertex
    ([(0, 0), (4, 4), (4, 0), (0, 4)], False),        # a bow tie
    ([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)], False),
])
def test_is_convex(ring, convex):
    assert sl.clip.window.is_convex(ring) is convex
    assert sl.clip.window.is_convex(np.array(ring, dtype=float)) is convex


@pytest.mark.parametrize("ring", [[(0, 0), (1, 1)], "square", [(0, 0), (1, float("nan")), (2, 0)]])
def test_is_convex_refuses_what_is_no_polygon(ring):
    with pytest.raises(sl.ScanlineError, match="ring"):
        sl.clip.window.is_convex(ring)


def test_one_pen_vocabulary_in_python_and_on_the_command_line():
    def python(pen):
        fb = sl.FrameBuffer(24, 16)
        sl.draw.line(fb, 3, 3, 20, 12, width=5, pen=pen)
        return fb.to_array()

    def cli(pen):
        return render(parse_items(f"width 5 pen {pen} line 3 3 20 12".split()), 24, 16).to_array()

    disc = python("circle")
    assert not np.array_equal(disc, python("square"))
    for pen in ("circle", "round"):
        assert np.array_equal(python(pen), disc) and np.array_equal(cli(pen), disc)
    assert np.array_equal(cli("square"), python("square"))
    for bad in (lambda: python("disc"), lambda: cli("disc")):
        with pytest.raises(sl.ArgumentValueError, match=r"pen.*'circle'.*'round'.*'disc'"):
            bad()


def test_ordered_dithering_is_bayer4():
    ramp = sl.FrameBuffer.from_array(np.tile(np.linspace(0, 255, 32).astype(np.uint8), (8, 1)))
    ordered = sl.color.dither(ramp, method="ordered")
    assert np.array_equal(ordered.to_array(), sl.color.dither(ramp, method="bayer4").to_array())
    # the textbook's D4 pattern: a mid gray turns on half of each 4 x 4 tile
    gray = sl.FrameBuffer.from_array(np.full((4, 4), 128, np.uint8))
    assert sl.color.dither(gray, method="ordered").to_array().astype(bool).sum() == 8
    with pytest.raises(sl.ArgumentValueError, match="method.*'ordered'"):
        sl.color.dither(ramp, method="orderd")


def test_ordered_on_the_command_line(call, tmp_path):
    from PIL import Image
    Image.fromarray(np.tile(np.arange(0, 256, 8, dtype=np.uint8), (8, 1))).save(tmp_path / "in.png")
    for method in ("ordered", "bayer4"):
        assert call("dither", tmp_path / "in.png", tmp_path / f"{method}.png",
                    "--method", method).code == 0
    a, b = (np.array(Image.open(tmp_path / f"{m}.png")) for m in ("ordered", "bayer4"))
    assert np.array_equal(a, b)


@pytest.mark.parametrize("mode", ["1", "L", "RGB", "RGBA", "P"])
def test_reading_and_writing_outside_follow_one_rule(mode):
    fb = sl.FrameBuffer(3, 2, mode=mode)
    before = fb.to_array().copy()
    for x, y in [(-1, 0), (3, 0), (0, 2), (0, -1), (10**9, -10**9)]:
        fb.set_pixel(x, y, "white")                # clipped: nothing happens
        assert fb.get_pixel(x, y) is None          # clipped: no pixel, no error
        assert fb.get_pixel(x, y, default="outside") == "outside"
    assert np.array_equal(fb.to_array(), before)
    fb.set_pixel(2, 1, "white")
    assert fb.get_pixel(2, 1) not in (None, fb.get_pixel(0, 0))
    with pytest.raises(sl.ScanlineError, match="x"):
        fb.get_pixel("a", 0)
