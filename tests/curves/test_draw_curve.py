"""sl.draw.curve / curves: the pixels are those of the flattened polyline, filled
closed curves cover the right area, windows clip, nothing is written out of bounds."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanline as sl
from scanline.curves.flatten import flatten


def lit(fb):
    return fb.to_array() != 0


def fresh(w=64, h=48):
    return sl.FrameBuffer(w, h, mode="L")


S_CURVE = sl.curves.Bezier([(3, 5), (70, 10), (-10, 40), (60, 44)])
CIRCLE = sl.curves.nurbs_circle((32, 24), 17)


@pytest.mark.parametrize("attributes", [
    {}, {"width": 3, "cap": "round", "join": "round"}, {"dash": "dashed"},
    {"width": 2.5, "join": "bevel", "cap": "square"}, {"pen": "circle"},
])
def test_pixels_are_the_flattened_polyline(attributes):
    a, b = fresh(), fresh()
    sl.draw.curve(a, S_CURVE, color=255, tolerance=0.2, **attributes)
    sl.draw.polyline(b, flatten(S_CURVE, 0.2), color=255, **attributes)
    np.testing.assert_array_equal(a.to_array(), b.to_array())
    assert lit(a).sum() > 30


def test_closed_curve_is_stroked_closed():
    a, b = fresh(), fresh()
    sl.draw.curve(a, CIRCLE, color=255, width=3)
    ring = flatten(CIRCLE, 0.25)[:-1]
    sl.draw.polyline(b, ring, color=255, closed=True, width=3)
    np.testing.assert_array_equal(a.to_array(), b.to_array())
    c = fresh()   # closed=False forces caps at the seam
    sl.draw.curve(c, CIRCLE, color=255, width=3, closed=False)
    d = fresh()
    sl.draw.polyline(d, flatten(CIRCLE, 0.25), color=255, width=3)
    np.testing.assert_array_equal(c.to_array(), d.to_array())


def test_width_one_circle_is_close_to_the_midpoint_circle():
    a, b = fresh(), fresh()
    sl.draw.curve(a, CIRCLE, color=255)
    sl.draw.circle(b, 32, 24, 17, color=255)
    ours, theirs = np.argwhere(lit(a)), np.argwhere(lit(b))
    # every pixel of one is within one pixel (8-neighbourhood) of the other
    for p, q in ((ours, theirs), (theirs, ours)):
        d = np.abs(p[:, None, :] - q[None, :, :]).max(axis=2).min(axis=1)
        assert d.max() <= 1


@pytest.mark.parametrize("radius", [10, 23.5, 60])
def test_filled_nurbs_circle_has_the_circles_area(radius):
    size = int(2 * radius + 8)
    fb = sl.FrameBuffer(size, size, mode="L")
    sl.draw.curve(fb, sl.curves.nurbs_circle((size / 2, size / 2), radius), color=255, fill=True)
    area = np.pi * radius**2
    # pixel centers inside a disk: the count is within a perimeter's worth of the area
    assert abs(lit(fb).sum() - area) <= 2 * np.pi * radius * 0.5


@pytest.mark.parametrize("radius", [10, 23.5, 60])
def test_filled_nurbs_circle_lights_the_pixel_centers_inside_the_circle(radius):
    """Flattened to 0.01 pixel, the fill lights exactly the pixel centers inside the
    circle (counted here from x² + y² < r²), except centers within 2 × 0.01 of it."""
    size = int(2 * radius + 8)
    fb = sl.FrameBuffer(size, size, mode="L")
    c = size / 2
    sl.draw.curve(fb, sl.curves.nurbs_circle((c, c), radius), color=255, fill=True,
                  tolerance=0.01)
    y, x = np.mgrid[size - 1:-1:-1, 0:size]      # to_array() is top row first (y up)
    distance = np.hypot(x - c, y - c)
    inside, unsure = distance < radius, np.abs(distance - radius) < 0.02
    assert not (lit(fb) ^ inside)[~unsure].any()


def test_filled_bezier_circle_matches_polygon_fill_of_its_polyline():
    k = 4 / 3 * (np.sqrt(2) - 1)       # four cubic arcs approximating a circle of radius 20
    r, c = 20, np.array([30.0, 22.0])
    arcs = []
    for q in range(4):
        rot = np.array([[np.cos(q * np.pi / 2), -np.sin(q * np.pi / 2)],
                        [np.sin(q * np.pi / 2), np.cos(q * np.pi / 2)]])
        pts = np.array([[r, 0], [r, k * r], [k * r, r], [0, r]]) @ rot.T + c
        arcs.append(pts)
    # power-form sections [u^3 u^2 u 1] M_bez P of the four arcs
    spline = sl.curves.PiecewisePolynomial([sl.curves.bezier_matrix(3) @ a for a in arcs])
    fb, ref = fresh(), fresh()
    sl.draw.curve(fb, spline, color=255, fill=True)
    sl.draw.polygon(ref, flatten(spline, 0.25)[:-1], color=255, rule="nonzero")
    np.testing.assert_array_equal(fb.to_array(), ref.to_array())
    assert abs(lit(fb).sum() - np.pi * r * r) <= np.pi * r


def test_fill_rules_differ_on_a_self_overlapping_outline():
    # a closed B-spline going twice around: nonzero fills the middle, even-odd not
    t = np.linspace(0, 4 * np.pi, 16, endpoint=False)
    radius = np.where(np.arange(16) % 2 == 0, 18, 12)
    pts = np.stack([32 + radius * np.cos(t), 24 + radius * np.sin(t)], axis=1)
    spline = sl.curves.BSpline(pts, 3, knots="periodic")
    a, b = fresh(), fresh()
    sl.draw.curve(a, spline, color=255, fill=True, rule="nonzero")
    sl.draw.curve(b, spline, color=255, fill=True, rule="even-odd")
    assert lit(a)[48 - 1 - 24, 32] and not lit(b)[48 - 1 - 24, 32]


def test_window_clips_the_stroke():
    window = (10, 8, 40, 30)
    fb = fresh()
    sl.draw.curve(fb, S_CURVE, color=255, window=window, width=1)
    ys, xs = np.nonzero(lit(fb))
    y = 47 - ys
    assert len(xs) > 10
    assert xs.min() >= 10 and xs.max() <= 40 and y.min() >= 8 and y.max() <= 30
    ref = fresh()
    pieces = sl.clip.polyline(flatten(S_CURVE, 0.25), window)
    sl.draw.polylines(ref, pieces, color=255)
    np.testing.assert_array_equal(fb.to_array(), ref.to_array())


def test_window_clips_the_filled_area():
    window = (20, 10, 45, 30)
    fb = fresh()
    sl.draw.curve(fb, CIRCLE, color=255, fill=True, window=window)
    full = fresh()
    sl.draw.curve(full, CIRCLE, color=255, fill=True)
    inside = np.zeros_like(lit(full))
    inside[47 - 30:47 - 10 + 1, 20:46] = True
    # the clipped fill is the full fill within the window (up to the window's edges)
    assert not (lit(fb) & ~inside).any()
    core = np.zeros_like(inside)
    core[47 - 29:47 - 11 + 1, 21:45] = True
    np.testing.assert_array_equal(lit(fb) & core, lit(full) & core)
    empty = fresh()
    sl.draw.curve(empty, CIRCLE, color=255, fill=True, window=(100, 100, 120, 120))
    assert not lit(empty).any()


def test_curves_batch_equals_one_by_one():
    arcs = [sl.curves.Bezier([(0, 0), (20, 40), (40, 0)]), CIRCLE,
            sl.curves.CatmullRom([(5, 40), (20, 30), (40, 45), (60, 30)])]
    a, b = fresh(), fresh()
    sl.draw.curves(a, arcs, color=[100, 200, 255], width=2)
    for c, color in zip(arcs, [100, 200, 255]):
        sl.draw.curve(b, c, color=color, width=2)
    np.testing.assert_array_equal(a.to_array(), b.to_array())


def test_antialiased_curve_and_fill_draw_something_within_the_shape():
    a = fresh()
    sl.draw.curve(a, CIRCLE, color=255, antialias=True)
    assert 0 < lit(a).sum() and (a.to_array() < 255).any()
    b = fresh()
    sl.draw.curve(b, CIRCLE, color=255, fill=True, antialias=True)
    solid = fresh()
    sl.draw.curve(solid, CIRCLE, color=255, fill=True)
    assert abs(b.to_array().sum() / 255 - lit(solid).sum()) < 0.02 * lit(solid).sum()


def test_bad_input():
    fb = fresh()
    with pytest.raises(sl.ArgumentTypeError, match="curve"):
        sl.draw.curve(fb, [(0, 0), (1, 1)])
    with pytest.raises(sl.ArgumentValueError, match="2-D"):
        sl.draw.curve(fb, sl.curves.Bezier([(0, 0, 0), (1, 1, 1)]))
    with pytest.raises(sl.ArgumentValueError, match="tolerance"):
        sl.draw.curve(fb, S_CURVE, tolerance=0)
    with pytest.raises(sl.ArgumentTypeError, match="closed"):
        sl.draw.curve(fb, S_CURVE, closed="yes")
    with pytest.raises(sl.ArgumentValueError, match="rule"):
        sl.draw.curve(fb, CIRCLE, fill=True, rule="odd")
    with pytest.raises(sl.ArgumentTypeError, match="curves"):
        sl.draw.curves(fb, S_CURVE)
    with pytest.raises(sl.ArgumentValueError, match="curves\\[1\\]"):
        sl.draw.curves(fb, [S_CURVE, sl.curves.Bezier([(0, 0, 0), (1, 1, 1)])])
    with pytest.raises(sl.ArgumentTypeError, match="FrameBuffer"):
        sl.draw.curve(np.zeros((4, 4)), S_CURVE)
    assert not lit(fb).any()


coordinate = st.floats(-3e5, 3e5, allow_nan=False)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(coordinate, coordinate), min_size=2, max_size=5),
       st.sampled_from([{}, {"width": 3}, {"fill": True}, {"dash": "dotted"}]),
       st.sampled_from(["1", "L", "RGB"]))
def test_fuzz_nothing_out_of_bounds(points, attributes, mode):
    fb = sl.FrameBuffer(16, 12, mode=mode)
    before = fb._raster()[0].shape
    try:
        sl.draw.curve(fb, sl.curves.Bezier(points), color="white", tolerance=0.5, **attributes)
    except sl.ArgumentValueError as e:
        assert "too small" in str(e)
    assert fb._raster()[0].shape == before
