"""sl.draw.soft_fill: recoloring an antialiased disk keeps its soft edge.

The disk is made here with numpy: each pixel's coverage t is computed by
supersampling, and the pixel is round(t*F + (1 - t)*B).
"""

import numpy as np
import pytest

import scanline as sl

F = np.array([200, 40, 30])
B = np.array([20, 60, 220])
NEW = np.array([250, 250, 0])


def coverage(size=41, center=(20.3, 19.6), radius=12.4, samples=8):
    """Fraction of each pixel inside the circle, image order (row 0 on top)."""
    offsets = (np.arange(samples) + 0.5) / samples - 0.5
    rows, cols = np.mgrid[0:size, 0:size]
    t = np.zeros((size, size))
    for dy in offsets:
        for dx in offsets:
            t += (cols + dx - center[0]) ** 2 + (rows + dy - center[1]) ** 2 <= radius ** 2
    return t / samples ** 2


def blend(t, fg, bg):
    return np.floor(t[..., None] * fg + (1 - t[..., None]) * bg + 0.5).astype(np.uint8)


@pytest.mark.parametrize("mode", ["RGB", "RGBA"])
def test_soft_fill_keeps_the_antialiased_edge(mode):
    t = coverage()
    image = blend(t, F, B)
    if mode == "RGBA":
        image = np.dstack([image, np.full(t.shape, 255, np.uint8)])
    fb = sl.FrameBuffer.from_array(image, mode=mode)
    n = sl.draw.soft_fill(fb, 20, 20, tuple(NEW), tuple(F), tuple(B))
    out = fb.to_array()[..., :3].astype(int)
    assert n == int((t > 0).sum())
    expected = blend(t, NEW, B).astype(int)
    assert np.abs(out - expected).max() <= 1
    assert np.array_equal(out[t == 0], image[..., :3][t == 0])
    fringe = (t > 0) & (t < 1)
    assert fringe.sum() > 50 and len(np.unique(out[fringe], axis=0)) > 10


def test_plain_flood_fill_would_leave_the_fringe():
    t = coverage()
    image = blend(t, F, B)
    fb = sl.FrameBuffer.from_array(image, mode="RGB")
    n = sl.draw.flood_fill(fb, 20, 20, tuple(NEW))
    out = fb.to_array()
    assert n == int((t == 1).sum())
    fringe = (t > 0) & (t < 1)
    assert np.array_equal(out[fringe], image[fringe])  # the old color's fringe stays


def test_gray_by_hand_and_a_new_color_that_is_itself_a_blend():
    fb = sl.FrameBuffer.from_array(np.array([[0, 64, 255, 255, 128, 0, 255]], np.uint8))
    assert sl.draw.soft_fill(fb, 2, 0, color=128, foreground=255, background=0) == 4
    assert fb.to_array().tolist() == [[0, 32, 128, 128, 64, 0, 255]]


def test_region_stops_at_pixels_that_are_not_blends():
    # (90, 90, 90) is far from the F-B segment: not part of the area
    image = np.array([[F, (F + B) // 2, (90, 90, 90), F]], np.uint8)
    fb = sl.FrameBuffer.from_array(image, mode="RGB")
    assert sl.draw.soft_fill(fb, 0, 0, tuple(NEW), tuple(F), tuple(B)) == 2
    assert fb.to_array()[0, 2:].tolist() == image[0, 2:].tolist()


@pytest.mark.parametrize("mode", ["1", "P"])
def test_modes_without_levels_are_refused(mode):
    fb = sl.FrameBuffer(3, 3, mode=mode)
    with pytest.raises(sl.ArgumentValueError, match="intensity levels"):
        sl.draw.soft_fill(fb, 1, 1, 1, 1, 0)


def test_bad_arguments():
    fb = sl.FrameBuffer(3, 3, mode="RGB")
    with pytest.raises(sl.ArgumentValueError, match="foreground and background must differ"):
        sl.draw.soft_fill(fb, 1, 1, "red", "blue", "blue")
    with pytest.raises(sl.ArgumentValueError, match="connectivity"):
        sl.draw.soft_fill(fb, 1, 1, "red", "white", "black", connectivity=6)
    with pytest.raises(sl.ArgumentValueError, match=r"\bx=3\b"):
        sl.draw.soft_fill(fb, 3, 1, "red", "white", "black")
    with pytest.raises(sl.ArgumentTypeError, match="fb"):
        sl.draw.soft_fill(None, 1, 1, "red", "white", "black")
