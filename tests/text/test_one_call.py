"""One line of upright text is placed and stamped by one compiled call
(``stamp_line``); it must set exactly the pixels of the general path
(``layout.place`` + ``stamp_glyphs``), which the layout tests pin."""

import importlib

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanline as sl
from scanline.text import glyphcache

draw_text = importlib.import_module("scanline.draw.text")

MODES = {"1": 1, "L": 200, "RGB": (200, 30, 10), "RGBA": (200, 30, 10, 150), "P": "red"}
BACKGROUNDS = {"1": 0, "L": 60, "RGB": (0, 0, 200), "RGBA": (0, 90, 0, 100), "P": "black"}


def _both(mode, color, x, y, text, **kw):
    """The frame buffers drawn by the one-call path and by the general path."""
    warm = sl.FrameBuffer(8, 8, mode=mode)
    sl.draw.text(warm, x, y, text, color=color, **kw)     # caches the glyphs
    fast = sl.FrameBuffer(90, 40, mode=mode, background=BACKGROUNDS[mode])
    calls = []
    stamp_line = draw_text.stamp_line

    def spy(*args):
        calls.append(1)
        return stamp_line(*args)

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(draw_text, "stamp_line", spy)
        sl.draw.text(fast, x, y, text, color=color, **kw)
    general = sl.FrameBuffer(90, 40, mode=mode, background=BACKGROUNDS[mode])
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(draw_text, "_line", lambda *args: False)
        sl.draw.text(general, x, y, text, color=color, **kw)
    return fast.to_array(), general.to_array(), calls


@settings(max_examples=80, deadline=None)
@given(text=st.text(st.characters(min_codepoint=32, max_codepoint=0x2FF), max_size=10),
       x=st.one_of(st.floats(-40, 100), st.sampled_from([2.0**30, -2.0**30, 2**30 - 5])),
       y=st.floats(-20, 50), font=st.sampled_from(["sans", "bitmap"]),
       height=st.floats(3, 30), expansion=st.floats(0.3, 3), spacing=st.floats(-0.5, 1),
       path=st.sampled_from(["right", "left"]),
       halign=st.sampled_from(["left", "center", "right"]),
       valign=st.sampled_from(["top", "cap", "half", "base", "bottom"]),
       mode=st.sampled_from(sorted(MODES)), antialias=st.booleans())
def test_one_call_path_sets_the_pixels_of_the_general_path(
        text, x, y, font, height, expansion, spacing, path, halign, valign, mode, antialias):
    fast, general, calls = _both(mode, MODES[mode], x, y, text, font=font, height=height,
                                 expansion=expansion, spacing=spacing, path=path,
                                 align=(halign, valign), antialias=antialias)
    assert calls == [1]
    assert (fast == general).all()


@pytest.mark.parametrize("halign", ["left", "center", "right"])
@pytest.mark.parametrize("path", ["right", "left"])
def test_one_call_path_draws_visible_text(halign, path):
    fast, general, calls = _both("RGB", "white", 45.3, 12.7, "Align Wg", height=11,
                                 path=path, align=(halign, "half"), spacing=0.1)
    assert calls == [1]
    assert (fast == general).all() and (fast != 0).sum() > 100


def test_other_text_takes_the_general_path():
    """Newlines, rotation, vertical paths, the stroke font, astral characters and
    glyphs too large to cache are placed by the layout: the compiled line either
    is not called or declines (returns 1, nothing drawn)."""
    for text, kw in (("two\nlines", {}), ("tilted", {"angle": 0.2}), ("up", {"path": "up"}),
                     ("stroke", {"font": "stroke"}), ("huge", {"height": 400}),
                     ("astral \U00020000", {})):
        for _ in range(2):
            fast, general, calls = _both("L", 255, 3, 10, text, **kw)
            assert (fast == general).all() and (fast != BACKGROUNDS["L"]).any()
            assert calls == [] or text.startswith("astral")


def test_memo_keeps_bool_and_number_apart():
    fb = sl.FrameBuffer(20, 10)
    sl.draw.text(fb, 0, 0, "x", height=1)
    with pytest.raises(sl.errors.ArgumentTypeError, match="height"):
        sl.draw.text(fb, 0, 0, "x", height=True)
    sl.draw.text(fb, 0, 0, "x", antialias=True)
    with pytest.raises(sl.errors.ArgumentTypeError, match="antialias"):
        sl.draw.text(fb, 0, 0, "x", antialias=1)


def test_first_use_of_a_glyph_renders_it():
    """A glyph not yet cached makes the compiled line decline (nothing drawn); the
    general path renders it, and the next call stamps it in one call -- also when
    the size's glyph images were dropped from the cache meanwhile."""
    results = []
    stamp_line = draw_text.stamp_line

    def spy(*args):
        results.append(stamp_line(*args))
        return results[-1]

    fbs = [sl.FrameBuffer(40, 20, mode="L") for _ in range(4)]
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(draw_text, "stamp_line", spy)
        sl.draw.text(fbs[0], 2, 5, "Q", height=9.37)
        glyphcache._CACHES.clear()              # as the cache does with old sizes
        sl.draw.text(fbs[1], 2, 5, "z", height=9.37)
        sl.draw.text(fbs[2], 2, 5, "z", height=9.37)
        mp.setattr(draw_text, "_line", lambda *args: False)
        sl.draw.text(fbs[3], 2, 5, "z", height=9.37)
    assert results == [1, 1, 0]
    a = [fb.to_array() for fb in fbs]
    assert (a[1] == a[2]).all() and (a[2] == a[3]).all() and np.count_nonzero(a[2]) > 10
