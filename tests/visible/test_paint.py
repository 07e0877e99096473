"""The object-order methods paint their convex pieces' numbers with a span kernel of
their own, and the shading colors the numbers; the pixels must be the 2-D fill's
(sl.draw.polygons), piece for piece, in every mode."""

import numpy as np
import pytest

import scanline as sl
from scanline.shading import paint as paint_ids
from scanline.visible import ScreenPolygons
from scanline.visible.visibility import piece_numbers

W, H = 37, 23


def paint(fb, sp, values):
    """The pieces ``sp`` painted in order in their faces' ``values``."""
    paint_ids(fb, piece_numbers(sp), values[sp.face])


def convex(rng, integer):
    """A random convex polygon (3 to 7 vertices, either orientation), partly off the
    frame at times; ``integer``: vertices on pixel centers, so crossings fall exactly
    on scan lines and on pixel centers (the top-left rule decides)."""
    c = rng.uniform([-5, -5], [W + 5, H + 5])
    r = rng.uniform(0.5, 15)
    k = int(rng.integers(3, 8))
    ang = np.sort(rng.uniform(0, 2 * np.pi, k))
    if rng.uniform() < 0.5:
        ang = ang[::-1]
    xy = c + r * np.c_[np.cos(ang), np.sin(ang)]
    if integer:
        xy = np.round(xy)
        hull = [p for i, p in enumerate(xy) if not np.allclose(p, xy[i - 1])]
        xy = np.array(hull)
    return np.c_[xy, np.full(len(xy), 0.5)]


@pytest.mark.parametrize("mode", ["1", "L", "RGB", "RGBA", "P"])
@pytest.mark.parametrize("integer", [False, True])
def test_pieces_paint_exactly_as_the_polygon_fill(mode, integer):
    rng = np.random.default_rng(7 if integer else 8)
    polys = []
    while len(polys) < 60:
        p = convex(rng, integer)
        try:                                  # a rounded polygon may lose its area
            ScreenPolygons.from_device([p], W, H)
        except sl.ArgumentValueError:
            continue
        polys.append(p)
    sp = ScreenPolygons.from_device(polys, W, H)
    ours = sl.FrameBuffer(W, H, mode=mode)
    theirs = sl.FrameBuffer(W, H, mode=mode)
    palette = ["red", "lime", "blue", "white", "yellow", "gray"]
    values = np.array([ours.pixel(palette[f % len(palette)]) for f in range(len(polys))],
                      np.uint8).reshape(len(polys), -1)
    paint(ours, sp, values)
    for p in range(len(sp)):
        sl.draw.polygon(theirs, sp.polygon(p)[:, :2], color=palette[int(sp.face[p]) % 6])
    assert np.array_equal(ours.to_array(), theirs.to_array())


def test_far_pieces_paint_nothing_outside_and_the_rest_right():
    # a frame-covering triangle with far vertices, a sliver far below the frame and one
    # far to the right: the kernel clips rows and columns before converting them
    big = np.array([[-1e12, -1e12, 0.5], [1e12, -1e12, 0.5], [0.0, 1e12, 0.5]])
    below = np.array([[0, -3e15, 0.5], [10, -3e15, 0.5], [5, -2e15, 0.5]])
    right = np.array([[4e15, 2, 0.5], [5e15, 2, 0.5], [4e15, 9, 0.5]])
    sp = ScreenPolygons.from_device([below, right, big], W, H)
    fb = sl.FrameBuffer(W, H, mode="L")
    paint(fb, sp, np.array([[10], [20], [200]], np.uint8))
    a = fb.to_array()
    inside = sl.FrameBuffer(W, H, mode="L")
    sl.draw.polygon(inside, big[:, :2], color=200)
    assert np.array_equal(a, inside.to_array()) and (a == 200).sum() > 0


def test_threads_share_the_rows_and_keep_the_order(monkeypatch):
    # a frame large enough that the painting is shared by threads (three here, each
    # taking every third band of rows); overlapping pieces, so a band painted out of
    # order would show
    from scanline._kernels import _threads

    monkeypatch.setattr(_threads, "threads", lambda: 3)
    rng = np.random.default_rng(11)
    w, h = 640, 480
    polys = []
    for _ in range(150):
        c = rng.uniform([0, 0], [w, h])
        ang = np.sort(rng.uniform(0, 2 * np.pi, 5))
        xy = c + rng.uniform(8, 96) * np.c_[np.cos(ang), np.sin(ang)]
        polys.append(np.c_[xy, np.full(5, 0.5)])
    sp = ScreenPolygons.from_device(polys, w, h)
    ours = sl.FrameBuffer(w, h, mode="RGB")
    theirs = sl.FrameBuffer(w, h, mode="RGB")
    values = rng.integers(0, 256, (len(polys), 3)).astype(np.uint8)
    assert w * h > sl._kernels._jit.TWIN_WORK          # (smaller work: one call)
    paint(ours, sp, values)
    for p in range(len(sp)):
        sl.draw.polygon(theirs, sp.polygon(p)[:, :2],
                        color=tuple(int(c) for c in values[sp.face[p]]))
    assert np.array_equal(ours.to_array(), theirs.to_array())
