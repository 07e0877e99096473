"""The 2-D viewing pipeline: the window-to-viewport formulas, the viewing frame
(R . T with a view-up vector), NDC, aspect ratio, several viewports, round trips."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from tests.reference import HYPOTHESIS

tf = sl.transform


def test_window_to_viewport_formulas():
    xw0, yw0, xw1, yw1 = -3.0, 2.0, 7.0, 6.0
    xv0, yv0, xv1, yv1 = 10.0, 20.0, 110.0, 60.0
    m = sl.viewing.window_to_viewport((xw0, yw0, xw1, yw1), (xv0, yv0, xv1, yv1))
    sx = (xv1 - xv0) / (xw1 - xw0)
    sy = (yv1 - yv0) / (yw1 - yw0)
    rng = np.random.default_rng(0)
    pts = rng.uniform(-10, 10, (50, 2))
    want = np.stack([xv0 + (pts[:, 0] - xw0) * sx, yv0 + (pts[:, 1] - yw0) * sy], axis=1)
    np.testing.assert_allclose(tf.apply(m, pts), want, atol=1e-12)
    # the matrix is T(xv0, yv0) S(sx, sy) T(-xw0, -yw0)
    np.testing.assert_allclose(m, tf.compose(tf.translation(xv0, yv0), tf.scaling(sx, sy),
                                             tf.translation(-xw0, -yw0)), atol=1e-15)


def test_keep_aspect_letterboxes_and_centers():
    m = sl.viewing.window_to_viewport((0, 0, 4, 2), (0, 0, 100, 100), keep_aspect=True)
    corners = tf.apply(m, [(0, 0), (4, 0), (4, 2), (0, 2)])
    np.testing.assert_allclose(corners, [(0, 25), (100, 25), (100, 75), (0, 75)])
    m = sl.viewing.window_to_viewport((0, 0, 2, 4), (0, 0, 100, 100), keep_aspect=True,
                                      align="lower-left")
    np.testing.assert_allclose(tf.apply(m, [(2, 4)]), [(50, 100)])
    # not kept: stretched to fill
    m = sl.viewing.window_to_viewport((0, 0, 4, 2), (0, 0, 100, 100))
    np.testing.assert_allclose(tf.apply(m, [(4, 2)]), [(100, 100)])
    # a square in the window stays a square with keep_aspect
    m = sl.viewing.window_to_viewport((0, 0, 3, 1), (0, 0, 50, 80), keep_aspect=True)
    a, b = tf.apply(m, [(1, 0), (0, 1)]) - tf.apply(m, [(0, 0), (0, 0)])
    assert np.hypot(*a) == pytest.approx(np.hypot(*b))


def test_viewing_matrix_rotates_view_up_onto_y():
    for angle in np.linspace(-3, 3, 13):
        v = (math.cos(angle), math.sin(angle))
        m = sl.viewing.viewing_matrix((2.0, -1.0), (3 * v[0], 3 * v[1]))
        assert tf.apply(m, (2.0, -1.0)) == pytest.approx((0, 0), abs=1e-12)
        up = tf.apply(m, (2.0 + v[0], -1.0 + v[1]))
        assert up == pytest.approx((0, 1), abs=1e-12)
        # the viewing x axis is V turned clockwise by 90 degrees
        right = tf.apply(m, (2.0 + v[1], -1.0 - v[0]))
        assert right == pytest.approx((1, 0), abs=1e-12)
        # M = R . T, R a rotation by (pi/2 - angle)
        r = tf.rotation(math.pi / 2 - angle)
        np.testing.assert_allclose(m, tf.compose(r, tf.translation(-2.0, 1.0)), atol=1e-12)


def test_rotated_window_corners_and_clipping():
    w = sl.viewing.Window(-1, -1, 1, 1, origin=(5, 5), view_up=(-1, 1))
    corners = w.corners()
    # a square turned by 45 degrees about (5, 5): corners on the axes through it
    d = corners - (5, 5)
    np.testing.assert_allclose(np.sort(np.hypot(d[:, 0], d[:, 1])), [math.sqrt(2)] * 4)
    np.testing.assert_allclose(np.sort(np.abs(d).max(axis=1)), [math.sqrt(2)] * 4, atol=1e-12)
    view = sl.viewing.View(w, (0, 0, 100, 100))
    # a world line through the center along x: inside the turned square between the
    # corners (5 +- sqrt(2), 5)
    seg, ok = view.clip_lines([(0, 5, 10, 5)])
    assert ok[0]
    world = view.to_world(seg.reshape(2, 2))
    np.testing.assert_allclose(np.sort(world[:, 0]), [5 - math.sqrt(2), 5 + math.sqrt(2)])
    np.testing.assert_allclose(world[:, 1], [5, 5], atol=1e-12)


def test_ndc_and_device():
    m = sl.viewing.ndc_to_device(640, 480)
    np.testing.assert_allclose(tf.apply(m, [(0, 0), (1, 1)]), [(0, 0), (639, 479)])
    vp = sl.viewing.device_viewport((0.5, 0, 1, 0.5), 101, 101)
    assert vp.bounds == (50.0, 0.0, 100.0, 50.0)
    m = sl.viewing.window_to_ndc((10, 10, 20, 30))
    np.testing.assert_allclose(tf.apply(m, [(10, 10), (20, 30), (15, 20)]),
                               [(0, 0), (1, 1), (0.5, 0.5)])


def test_several_viewports_on_one_frame_buffer():
    fb = sl.FrameBuffer(64, 32, mode="1")
    window = (0, 0, 10, 10)
    square = [(0, 0, 10, 0), (10, 0, 10, 10), (10, 10, 0, 10), (0, 10, 0, 0)]
    tiles = sl.viewing.tile(1, 2, gap=0.1)
    for vp in tiles:
        view = sl.viewing.View(window, sl.viewing.device_viewport(vp, fb.width, fb.height),
                               keep_aspect=True)
        seg, ok = view.clip_lines(square + [(-5, 5, 15, 5)])
        assert ok.all()
        sl.draw.lines(fb, seg)
    img = np.asarray(fb.to_array(), bool)[::-1]          # row y = scan line y
    cols = np.nonzero(img.any(axis=0))[0]
    # two separate squares, one in each half, with the gap between them empty
    left = cols[cols < 32]
    right = cols[cols >= 32]
    assert len(left) and len(right)
    assert left.max() < 64 * 0.45 + 1 and right.min() > 64 * 0.55 - 2
    assert img[:, int(64 * 0.45) + 2:int(64 * 0.55) - 2].sum() == 0


def test_tile_layout():
    vps = sl.viewing.tile(2, 3, bounds=(0, 0, 300, 200), gap=0)
    assert [vp.bounds for vp in vps[:3]] == [(0, 100, 100, 200), (100, 100, 200, 200),
                                            (200, 100, 300, 200)]
    assert vps[3].bounds == (0, 0, 100, 100)


finite = st.floats(-1e6, 1e6, allow_nan=False)
size = st.floats(1e-3, 1e6)


@HYPOTHESIS
@given(finite, finite, size, size, finite, finite, size, size, st.booleans(),
       st.floats(-math.pi, math.pi), st.lists(st.tuples(finite, finite), min_size=1, max_size=8))
def test_round_trips(wx, wy, ww, wh, vx, vy, vw, vh, keep, angle, pts):
    window = sl.viewing.Window(wx, wy, wx + ww, wy + wh, origin=(wx, wy),
                               view_up=(math.cos(angle), math.sin(angle)))
    view = sl.viewing.View(window, (vx, vy, vx + vw, vy + vh), keep_aspect=keep)
    p = np.array(pts)
    back = view.to_world(view.to_viewport(p))
    scale = max(1.0, np.abs(p).max(), abs(wx), abs(wy), ww, wh)
    cond = max(ww / vw, vw / ww, wh / vh, vh / wh)
    assert np.abs(back - p).max() <= 1e-9 * scale * max(1.0, cond)
    # the window's corners land inside the viewport
    c = view.window_to_viewport @ np.array([[wx, wx + ww], [wy, wy + wh], [1, 1]])
    # (the matrix form adds sx * xwmin to a translation: round-off grows with it)
    tol = 1e-12 * (max(1.0, abs(vx), abs(vy), vw, vh) + vw / ww * abs(wx) + vh / wh * abs(wy))
    assert (c[0] >= vx - tol).all() and (c[0] <= vx + vw + tol).all()
    assert (c[1] >= vy - tol).all() and (c[1] <= vy + vh + tol).all()


@pytest.mark.parametrize("call, words", [
    (lambda: sl.viewing.Window(0, 0, 0, 1), "window=(0.0, 0.0, 0.0, 1.0) is degenerate"),
    (lambda: sl.viewing.Viewport(0, 1, 1, 1), "viewport=(0.0, 1.0, 1.0, 1.0) is degenerate"),
    (lambda: sl.viewing.window_to_viewport((0, 0, 1, 1), (0, 0, 1, float("nan"))),
     "viewport[3] must be a finite number"),
    (lambda: sl.viewing.viewing_matrix((0, 0), (0, 0)), "view_up must be a nonzero vector"),
    (lambda: sl.viewing.window_to_viewport((0, 0, 1, 1), (0, 0, 1, 1), align="middle"),
     "align must be one of"),
    (lambda: sl.viewing.tile(2, 2, gap=1.2), "gap=1.2"),
    (lambda: sl.viewing.ndc_to_device(0, 10), "width must be >= 2"),
    # scale factors that overflow or vanish (they gave "sx must be a finite number")
    (lambda: sl.viewing.window_to_viewport((0, 0, 1e-300, 1e-300), (0, 0, 1e300, 1e300)),
     "cannot be mapped to viewport"),
    (lambda: sl.viewing.window_to_viewport((-1e308, 0, 1e308, 1), (0, 0, 1, 1)),
     "cannot be mapped to viewport"),
])
def test_bad_input(call, words):
    with pytest.raises(sl.ArgumentValueError) as info:
        call()
    assert words in str(info.value)
