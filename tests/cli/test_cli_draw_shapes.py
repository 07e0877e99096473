"""``scanline draw`` items for Pillow's shapes: rectangle, rounded-rectangle and
regular-polygon (outlines with the line attributes), their fill- forms (areas with
the fill style), the rotation setting, and point drawn as sl.draw.point draws it."""

import math

import numpy as np
from PIL import Image

import scanline as sl


def _draw(call, tmp_path, *words, mode="RGB"):
    out = tmp_path / "out.png"
    result = call("draw", "--size", "48x40", "--mode", mode, *words, "-o", out)
    assert (result.code, result.err) == (0, ""), result
    return np.array(Image.open(out).convert("RGB" if mode != "L" else "L"))


def _api(build, mode="RGB"):
    fb = sl.FrameBuffer(48, 40, mode=mode)
    build(fb)
    return np.array(fb.to_pil().convert("RGB" if mode != "L" else "L"))


def test_outlines_with_line_attributes_match_the_api(call, tmp_path):
    got = _draw(call, tmp_path, "color", "red", "width", 3, "dash", "6,2",
                "rectangle", 2, 2, 30, 20, "join", "round", "rounded-rectangle", 5, 22, 45, 37, 6,
                "width", 1, "dash", "solid", "rotation", 90, "regular-polygon", 38, 10, 8, 5)

    def build(fb):
        sl.draw.rectangle(fb, 2, 2, 30, 20, color="red", width=3, dash=(6, 2))
        sl.draw.rounded_rectangle(fb, 5, 22, 45, 37, 6, color="red", width=3, dash=(6, 2),
                                  join="round")
        sl.draw.regular_polygon(fb, 38, 10, 8, 5, math.radians(90), color="red", join="round")

    assert np.array_equal(got, _api(build))


def test_areas_with_the_fill_style_match_the_api(call, tmp_path):
    got = _draw(call, tmp_path, "color", "gold", "fill-rectangle", 1, 1, 20, 12,
                "style", "hatch:45:4", "fill-rounded-rectangle", 22, 1, 46, 30, 8,
                "style", "solid", "color", "blue", "fill-regular-polygon", 12, 28, 10, 6)

    def build(fb):
        sl.draw.rectangle(fb, 1, 1, 20, 12, color="gold", fill=True)
        sl.draw.rounded_rectangle(fb, 22, 1, 46, 30, 8, color="gold", fill=True,
                                  fill_style=sl.FillStyle.hatch("45deg", spacing=4))
        sl.draw.regular_polygon(fb, 12, 28, 10, 6, color="blue", fill=True)

    assert np.array_equal(got, _api(build))


def test_point_is_sl_draw_point(call, tmp_path):
    got = _draw(call, tmp_path, "point", 3, 4, "color", "red", "point", 5.5, 1.4)
    expected = _api(lambda fb: [sl.draw.point(fb, 3, 4), sl.draw.point(fb, 6, 1, "red")])
    assert np.array_equal(got, expected) and tuple(got[40 - 1 - 1, 6]) == (255, 0, 0)


def test_bad_shape_items_are_one_line(call, tmp_path):
    out = tmp_path / "x.png"
    for words, fragment in [(["regular-polygon", 5, 5, 4, 3.5], "SIDES must be a whole number"),
                            (["regular-polygon", 5, 5, 4, 2], "sides must be >= 3"),
                            (["rotation", "abc"], "rotation must be a number of degrees"),
                            (["rounded-rectangle", 0, 0, 9, 9, -2], "radius must be >= 0"),
                            (["rectangle", 0, 0, 9], "rectangle needs X0 Y0 X1 Y1")]:
        result = call("draw", *words, "-o", out)
        assert result.code == 2 and fragment in result.err, (words, result)
        assert len(result.err.strip().splitlines()) == 1
    assert not out.exists()


def test_help_lists_the_shapes(call):
    result = call("draw", "--help")
    for word in ("rectangle X0 Y0 X1 Y1", "fill-rounded-rectangle X0 Y0 X1 Y1 R",
                 "regular-polygon XC YC R SIDES", "rotation DEG"):
        assert word in result.out
