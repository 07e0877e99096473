"""Every area primitive refuses a fill style that is not a FillStyle (a kind's name, a
number, a list) with an error naming the argument, before it draws anything (the name
"hatch" reached ``style.paint`` as a bare AttributeError)."""

import numpy as np
import pytest

import scanline as sl

TRI = [(2, 2), (15, 3), (8, 14)]
CALLS = {
    "fill_circle": lambda fb, s: sl.draw.fill_circle(fb, 10, 10, 5, "red", style=s),
    "fill_ellipse": lambda fb, s: sl.draw.fill_ellipse(fb, 10, 10, 6, 4, "red", style=s),
    "pie": lambda fb, s: sl.draw.pie(fb, 10, 10, 6, 4, 0, "120deg", "red", style=s),
    "chord": lambda fb, s: sl.draw.chord(fb, 10, 10, 6, 4, 0, "120deg", "red", style=s),
    "polygon": lambda fb, s: sl.draw.polygon(fb, TRI, "red", style=s),
    "rectangle": lambda fb, s: sl.draw.rectangle(fb, 2, 2, 15, 12, "red", fill=True,
                                                 fill_style=s),
    "rounded_rectangle": lambda fb, s: sl.draw.rounded_rectangle(fb, 2, 2, 15, 12, 3, "red",
                                                                 fill=True, fill_style=s),
    "regular_polygon": lambda fb, s: sl.draw.regular_polygon(fb, 10, 10, 6, 5, 0, "red",
                                                             fill=True, fill_style=s),
}


@pytest.mark.parametrize("name", sorted(CALLS))
@pytest.mark.parametrize("style", ["hatch", 3, [1, 2], np.zeros(2)])
def test_a_style_that_is_not_a_fill_style_is_named(name, style):
    fb = sl.FrameBuffer(20, 20, mode="RGB", background="white")
    before = fb.to_array().copy()
    with pytest.raises(sl.ScanlineError, match="style"):
        CALLS[name](fb, style)
    assert np.array_equal(fb.to_array(), before)


def test_the_name_of_a_kind_is_answered_with_the_style_to_write():
    fb = sl.FrameBuffer(20, 20)
    with pytest.raises(sl.ArgumentTypeError, match=r"style=sl\.FillStyle\('hatch'\)"):
        sl.draw.fill_circle(fb, 10, 10, 5, style="hatch")
    sl.draw.fill_circle(fb, 10, 10, 5, style=sl.FillStyle("hatch"))     # as the error says


@pytest.mark.parametrize("name", sorted(CALLS))
def test_a_fill_style_is_still_painted(name):
    fb = sl.FrameBuffer(20, 20, mode="RGB", background="white")
    CALLS[name](fb, sl.FillStyle.hatch("45deg", 3))
    assert (fb.to_array() != 255).any()
