"""``scanline draw`` area items: polygons with --rule, filled conics, arcs, chords,
pies, fill styles, flood and boundary fills."""

import math

import numpy as np
import pytest
from PIL import Image

import scanline as sl

STAR = [(32, 60), (13, 4), (62, 40), (2, 40), (51, 4)]


def _draw(call, tmp_path, *words):
    out = tmp_path / "out.png"
    result = call("draw", "--size", "64x64", *words, "-o", out)
    assert (result.code, result.err) == (0, ""), result
    return np.array(Image.open(out))


def _api(build):
    fb = sl.FrameBuffer(64, 64)
    build(fb)
    return fb.to_array()


@pytest.mark.parametrize("rule", ["even-odd", "nonzero"])
def test_polygon_with_rule_matches_the_api(call, tmp_path, rule):
    got = _draw(call, tmp_path, "--rule", rule, "color", "gold", "polygon",
                *[c for p in STAR for c in p])
    expected = _api(lambda fb: sl.draw.polygon(fb, STAR, color="gold", rule=rule))
    assert np.array_equal(got, expected)
    center_lit = bool(got[63 - 32, 32].any())
    assert center_lit == (rule == "nonzero")  # the pentagram's center


def test_rule_item_overrides_the_option(call, tmp_path):
    got = _draw(call, tmp_path, "rule", "nonzero", "polygon", *[c for p in STAR for c in p])
    assert got[63 - 32, 32].any()


def test_conic_areas_and_arcs_match_the_api(call, tmp_path):
    got = _draw(call, tmp_path, "fill-circle", 20, 20, 10, "color", "red",
                "fill-ellipse", 45, 45, 12, 6, "color", "blue", "arc", 45, 15, 10, 10, 0, 90,
                "chord", 15, 48, 10, 10, 30, 200, "pie", 48, 30, 8, 8, -45, 45)

    def build(fb):
        sl.draw.fill_circle(fb, 20, 20, 10)
        sl.draw.fill_ellipse(fb, 45, 45, 12, 6, color="red")
        sl.draw.arc(fb, 45, 15, 10, 10, 0, math.pi / 2, color="blue")
        sl.draw.chord(fb, 15, 48, 10, 10, math.radians(30), math.radians(200), color="blue")
        sl.draw.pie(fb, 48, 30, 8, 8, math.radians(-45), math.radians(45), color="blue")

    assert np.array_equal(got, _api(build))


def test_styles_apply_to_the_following_areas(call, tmp_path):
    got = _draw(call, tmp_path, "style", "crosshatch:45:6", "fill-circle", 32, 32, 25,
                "style", "hollow", "polygon", 5, 5, 20, 5, 12, 20)

    def build(fb):
        sl.draw.fill_circle(fb, 32, 32, 25, style=sl.FillStyle.parse("crosshatch:45:6"))
        sl.draw.polygon(fb, [(5, 5), (20, 5), (12, 20)], style=sl.FillStyle.hollow())

    expected = _api(build)
    assert np.array_equal(got, expected)
    solid = _api(lambda fb: sl.draw.fill_circle(fb, 32, 32, 25))
    assert 0 < expected.any(axis=2).sum() < solid.any(axis=2).sum()  # a hatch, not solid


@pytest.mark.parametrize("items, fragments", [
    (["polygon", "1", "2", "3"], ["word 1", "polygon"]),
    (["style", "zigzag", "fill-circle", "5", "5", "3"], ["word 1", "style"]),
    (["rule", "odd", "polygon", "0", "0", "5", "0", "0", "5"], ["word 1", "rule"]),
    (["connectivity", "6", "flood", "1", "1"], ["word 1", "connectivity"]),
])
def test_bad_area_items_exit_2(call, one_line_error, tmp_path, items, fragments):
    out = tmp_path / "out.png"
    result = call("draw", *items, "-o", out)
    one_line_error(result, *fragments)
    assert not out.exists()


def test_flood_boundary_and_soft_fills_match_the_api(call, tmp_path):
    got = _draw(call, tmp_path, "circle", 20, 20, 10, "color", "green", "flood", 20, 20,
                "color", "white", "circle", 45, 45, 10, "line", 35, 45, 55, 45,
                "color", "red", "boundary", 45, 50,
                "color", "white", "fill-circle", 45, 15, 8,
                "color", "blue", "soft", 45, 15, "white", "black")

    def build(fb):
        sl.draw.circle(fb, 20, 20, 10)
        sl.draw.flood_fill(fb, 20, 20, "green")
        sl.draw.circle(fb, 45, 45, 10)
        sl.draw.line(fb, 35, 45, 55, 45)
        sl.draw.boundary_fill(fb, 45, 50, "red", boundary="white")
        sl.draw.fill_circle(fb, 45, 15, 8)
        sl.draw.soft_fill(fb, 45, 15, "blue", "white", "black")

    expected = _api(build)
    assert np.array_equal(got, expected)
    assert got[63 - 20, 20].tolist() == [0, 128, 0]      # inside the flooded circle
    assert got[63 - 50, 45].tolist() == [255, 0, 0]      # the boundary-filled half
    assert got[63 - 40, 45].tolist() == [0, 0, 0]        # below the line: not reached
    assert got[63 - 15, 45].tolist() == [0, 0, 255]      # soft fill recolored the disk


def test_tolerance_widens_a_flood(call, tmp_path):
    got = _draw(call, tmp_path, "--background", "#101010", "color", "#141414",
                "fill-circle", 32, 32, 10, "color", "red", "tolerance", 4, "flood", 1, 1)
    assert got[63 - 32, 32].tolist() == [255, 0, 0]      # within 4 levels of the seed
