"""``scanline draw`` with line attributes: settings, the polyline items, errors."""

import numpy as np
import pytest

import scanline as sl
from scanline.cli.draw import parse_items, render


def draw(words, size=(64, 48)):
    return render(parse_items(words.split()), *size).to_array()


def api(build, size=(64, 48)):
    fb = sl.FrameBuffer(*size)
    build(fb)
    return fb.to_array()


def test_attributes_apply_to_the_following_items():
    got = draw("width 5 cap round join round dash 12,6 polyline 5 5 30 40 58 10 "
               "color red width 1 dash 0b1111000011110000 circle 32 24 15 "
               "antialias on width 3 closed-polyline 2 2 60 2 60 45")

    def build(fb):
        style = sl.LineStyle(width=5, cap="round", join="round", dash=(12, 6))
        sl.draw.polyline(fb, [(5, 5), (30, 40), (58, 10)], style=style)
        sl.draw.circle(fb, 32, 24, 15, color="red", style=style, width=1, dash=0xF0F0)
        sl.draw.polyline(fb, [(2, 2), (60, 2), (60, 45)], color="red", closed=True,
                         style=style, width=3, dash=0xF0F0, antialias=True)
    assert np.array_equal(got, api(build))


def test_pen_miter_limit_and_phase():
    got = draw("pen round width 3 line 4 4 40 30 pen none width 6 miter-limit 1.2 "
               "dash dashed dash-phase 3 polyline 10 40 50 40 30 10")

    def build(fb):
        sl.draw.line(fb, 4, 4, 40, 30, pen="circle", width=3)
        sl.draw.polyline(fb, [(10, 40), (50, 40), (30, 10)], width=6, miter_limit=1.2,
                         dash="dashed", dash_phase=3)
    assert np.array_equal(got, api(build))


@pytest.mark.parametrize("words,message", [
    ("width 0 line 1 1 5 5", "width"),
    ("width x line 1 1 5 5", "width"),
    ("cap rounded line 1 1 5 5", "cap"),
    ("join mitre line 1 1 5 5", "join"),
    ("miter-limit 0.5 line 1 1 5 5", "miter_limit"),
    ("dash foo line 1 1 5 5", "dash"),
    ("dash 0 line 1 1 5 5", "dash"),
    ("dash 3,-1 line 1 1 5 5", "dash"),
    ("pen star line 1 1 5 5", "pen"),
    ("antialias maybe line 1 1 5 5", "antialias"),
    ("polyline 1 2 3 4 5", "x y pairs"),
])
def test_bad_settings_name_the_word(words, message):
    with pytest.raises(sl.ArgumentValueError, match=message) as info:
        draw(words)
    assert "ITEMS word" in str(info.value)


def test_cli_writes_the_image(run, tmp_path):
    result = run("draw", "--size", "32x24", "width", "3", "cap", "square", "polyline",
                 "4", "4", "28", "4", "28", "20", "-o", "out.png", cwd=tmp_path)
    assert (result.code, result.err) == (0, "")
    from PIL import Image
    got = np.array(Image.open(tmp_path / "out.png"))
    want = api(lambda fb: sl.draw.polyline(fb, [(4, 4), (28, 4), (28, 20)], width=3,
                                           cap="square"), size=(32, 24))
    assert np.array_equal(got, want)
