"""``scanline draw ... text X Y STRING`` with the font, height, angle and align
settings: the same pixels as the API."""

import math

from PIL import Image
import pytest

import scanline as sl
from scanline.cli import main


def drawn(tmp_path, *items, size="120x40"):
    out = tmp_path / "out.png"
    assert main(["draw", "--size", size, "--mode", "L", *items, "-o", str(out)]) == 0
    return sl.FrameBuffer.from_pil(Image.open(out)).to_array()


def api(*calls, size=(120, 40)):
    fb = sl.FrameBuffer(*size, mode="L")
    for args, kw in calls:
        sl.draw.text(fb, *args, color=255, **kw)
    return fb.to_array()


def test_text_item_with_settings(tmp_path):
    got = drawn(tmp_path, "font", "stroke", "height", "12", "angle", "15", "align",
                "center,half", "text", "60", "20", "Hi there")
    want = api(((60, 20, "Hi there"), dict(font="stroke", height=12, angle=math.radians(15),
                                          align=("center", "half"))))
    assert (got == want).all() and want.sum() > 0


def test_string_may_be_an_item_word_and_settings_persist(tmp_path):
    got = drawn(tmp_path, "font", "bitmap", "text", "2", "2", "line", "antialias", "on",
                "text", "40", "20", "circle")
    want = api(((2, 2, "line"), dict(font="bitmap")),
               ((40, 20, "circle"), dict(font="bitmap", antialias=True)))
    assert (got == want).all()


@pytest.mark.parametrize("items, message", [
    (["text", "1", "2"], "text needs X Y STRING"),
    (["text", "x", "2", "a"], "X of text must be a number"),
    (["height", "-1", "text", "1", "2", "a"], "height must be > 0"),
    (["height", "big"], "height must be a number"),
    (["font", "nope"], "font='nope'"),
    (["align", "left,middle"], "vertical alignment"),
])
def test_bad_text_items(tmp_path, capsys, items, message):
    assert main(["draw", *items, "-o", str(tmp_path / "x.png")]) == 2
    assert message in capsys.readouterr().err
    assert not (tmp_path / "x.png").exists()
