"""sl.draw.point(s), rectangle(s), rounded_rectangle and regular_polygon (issue, part
6, item 3): exact tiny images, the primitives they are built on, Pillow's ImageDraw
where the conventions agree (its y axis flipped), line and fill attributes, batches,
modes, huge and bad input."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from PIL import Image, ImageDraw

import scanline as sl
from tests.reference import HYPOTHESIS, MODES


def lit(fb):
    """The text image of ``fb`` (``#`` where a pixel differs from the background)."""
    return sl.text_image(fb)


def pillow(width, height, draw):
    """A mode "1" Pillow image drawn by ``draw(ImageDraw, flip)``, ``flip(y)`` the
    image row of device row y, as a bool array in image order."""
    image = Image.new("1", (width, height))
    draw(ImageDraw.Draw(image), lambda y: height - 1 - y)
    return np.asarray(image)


def mine(width, height, draw):
    fb = sl.FrameBuffer(width, height, mode="1")
    draw(fb)
    return fb.to_array()


# -- points --------------------------------------------------------------------------------

def test_point_rounds_and_clips():
    fb = sl.FrameBuffer(4, 3, mode="1")
    sl.draw.point(fb, 0, 0)
    sl.draw.point(fb, 2.5, 1.49)            # halves round up: (3, 1)
    sl.draw.point(fb, -1, 0)
    sl.draw.point(fb, 4, 2)
    sl.draw.point(fb, 1e12, -1e12)
    assert lit(fb) == "----\n---#\n#---"


@pytest.mark.parametrize("mode", MODES)
def test_point_is_a_zero_length_line(mode):
    for color in (None, "red", (0, 0, 255, 128)):
        fb = sl.FrameBuffer(3, 2, mode=mode, background="white")
        sl.draw.point(fb, 1, 1, color)
        ref = sl.FrameBuffer(3, 2, mode=mode, background="white")
        sl.draw.line(ref, 1, 1, 1, 1, color)
        assert np.array_equal(fb.to_array(), ref.to_array())
        assert lit(fb) == "-#-\n---"


def test_points_is_a_loop_of_point():
    rng = np.random.default_rng(0)
    pts = rng.uniform(-5, 25, size=(60, 2))
    colors = [tuple(int(c) for c in rng.integers(0, 256, 3)) for _ in range(60)]
    a = sl.FrameBuffer(20, 20)
    sl.draw.points(a, pts, color=colors)
    b = sl.FrameBuffer(20, 20)
    for (x, y), c in zip(pts, colors):
        sl.draw.point(b, x, y, c)
    assert np.array_equal(a.to_array(), b.to_array())
    sl.draw.points(a, np.empty((0, 2)))


# -- rectangles ----------------------------------------------------------------------------

def test_rectangle_tiny():
    fb = sl.FrameBuffer(7, 5, mode="1")
    sl.draw.rectangle(fb, 5, 3, 1, 0)                # corners in either order
    assert lit(fb) == "-------\n-#####-\n-#---#-\n-#---#-\n-#####-"
    fb = sl.FrameBuffer(7, 5, mode="1")
    sl.draw.rectangle(fb, 1, 0, 5, 3, fill=True)
    assert lit(fb) == "-------\n-#####-\n-#####-\n-#####-\n-#####-"
    fb = sl.FrameBuffer(4, 3, mode="1")
    sl.draw.rectangle(fb, 1.4, 0.5, 1.6, 0.5, fill=True)   # rounded: (1, 1) .. (2, 1)
    assert lit(fb) == "----\n-##-\n----"


def test_rectangle_fill_and_outline_colors():
    fb = sl.FrameBuffer(6, 4, mode="L")
    sl.draw.rectangle(fb, 0, 0, 4, 2, color=255, fill=100)
    assert fb.to_array().tolist() == [[0] * 6, [255] * 5 + [0], [255, 100, 100, 100, 255, 0],
                                      [255] * 5 + [0]]
    only_fill = sl.FrameBuffer(6, 4, mode="L")
    sl.draw.rectangle(only_fill, 0, 0, 4, 2, fill=100)      # no color: no outline
    assert set(only_fill.to_array()[1:, :5].ravel()) == {100}
    in_color = sl.FrameBuffer(6, 4, mode="L")
    sl.draw.rectangle(in_color, 0, 0, 4, 2, color=7, fill=True)
    assert set(in_color.to_array()[1:, :5].ravel()) == {7}
    default = sl.FrameBuffer(6, 4, mode="L", background="white")
    sl.draw.rectangle(default, 0, 0, 4, 2)                  # the foreground: black
    assert default.get_pixel(0, 0) == 0 and default.get_pixel(1, 1) == 255


def test_rectangle_is_pillows_rectangle_with_y_flipped():
    rng = np.random.default_rng(1)
    w, h = 21, 16
    for _ in range(150):
        x0, x1 = sorted(int(c) for c in rng.integers(-4, w + 4, 2))
        y0, y1 = sorted(int(c) for c in rng.integers(-4, h + 4, 2))
        filled = mine(w, h, lambda fb: sl.draw.rectangle(fb, x0, y0, x1, y1, fill=True))
        assert np.array_equal(filled, pillow(w, h, lambda d, f: d.rectangle(
            (x0, f(y1), x1, f(y0)), fill=1)))
        if x1 > x0 and y1 > y0:     # (Pillow draws a stray pixel on degenerate outlines)
            outline = mine(w, h, lambda fb: sl.draw.rectangle(fb, x0, y0, x1, y1))
            assert np.array_equal(outline, pillow(w, h, lambda d, f: d.rectangle(
                (x0, f(y1), x1, f(y0)), outline=1)))


def test_rectangle_area_is_the_polygon_of_its_pixel_squares():
    fb = sl.FrameBuffer(10, 8, mode="1")
    sl.draw.rectangle(fb, 2, 1, 6, 5, fill=True)
    ref = sl.FrameBuffer(10, 8, mode="1")
    sl.draw.polygon(ref, [(1.5, 0.5), (6.5, 0.5), (6.5, 5.5), (1.5, 5.5)])
    assert np.array_equal(fb.to_array(), ref.to_array())


def test_rectangle_outline_is_the_border_ring_and_each_pixel_once():
    fb = sl.FrameBuffer(9, 7, mode="RGB")
    sl.draw.rectangle(fb, 1, 1, 7, 5, color=(255, 0, 0, 128))
    a = fb.to_array()
    ring = np.zeros((7, 9), bool)
    ring[1:6, 1:8] = True
    ring[2:5, 2:7] = False
    assert (a[ring] == (128, 0, 0)).all()          # composited once, corners too
    assert not a[~ring].any()


def test_thick_outline_is_centered_on_the_ring():
    fb = sl.FrameBuffer(12, 9, mode="1")
    sl.draw.rectangle(fb, 2, 2, 9, 6, width=3)
    assert lit(fb) == "\n".join(["------------", "-##########-", "-##########-", "-##########-",
                                 "-###----###-", "-##########-", "-##########-", "-##########-",
                                 "------------"])
    styled = sl.FrameBuffer(12, 9, mode="1")
    sl.draw.rectangle(styled, 2, 2, 9, 6, style=sl.LineStyle(width=3))
    assert np.array_equal(styled.to_array(), fb.to_array())


def test_outline_line_attributes_are_the_closed_polylines():
    for kw in [dict(dash=(3, 2)), dict(width=2.5, join="round"), dict(pen="circle", width=3),
               dict(width=4, join="bevel", dash="dash-dot"), dict(antialias=True),
               dict(width=3, antialias=True)]:
        fb = sl.FrameBuffer(20, 14, mode="L")
        sl.draw.rectangle(fb, 3, 2, 16, 11, color=255, **kw)
        ref = sl.FrameBuffer(20, 14, mode="L")
        sl.draw.polyline(ref, [(3, 2), (16, 2), (16, 11), (3, 11)], color=255, closed=True, **kw)
        assert np.array_equal(fb.to_array(), ref.to_array()), kw


def test_degenerate_rectangles_are_segments_and_points():
    fb = sl.FrameBuffer(6, 4, mode="1")
    sl.draw.rectangle(fb, 1, 0, 1, 3)
    sl.draw.rectangle(fb, 3, 2, 5, 2)
    sl.draw.rectangle(fb, 4, 0, 4, 0, fill=True)
    assert lit(fb) == "-#----\n-#-###\n-#----\n-#--#-"
    translucent = sl.FrameBuffer(4, 3)
    sl.draw.rectangle(translucent, 1, 0, 1, 2, color=(255, 255, 255, 128))
    assert translucent.get_pixel(1, 1) == (128, 128, 128)      # once, not there and back


def test_fill_styles():
    hatch = sl.FillStyle.hatch("45deg", spacing=3)
    fb = sl.FrameBuffer(12, 10, mode="1")
    sl.draw.rectangle(fb, 1, 1, 10, 8, fill=True, fill_style=hatch)
    ref = sl.FrameBuffer(12, 10, mode="1")
    sl.draw.polygon(ref, [(0.5, 0.5), (10.5, 0.5), (10.5, 8.5), (0.5, 8.5)], style=hatch)
    assert np.array_equal(fb.to_array(), ref.to_array()) and fb.to_array().any()
    hollow = sl.FrameBuffer(12, 10, mode="1")
    sl.draw.rectangle(hollow, 1, 1, 10, 8, fill=True, fill_style=sl.FillStyle.hollow())
    outline = sl.FrameBuffer(12, 10, mode="1")
    sl.draw.rectangle(outline, 1, 1, 10, 8)
    assert np.array_equal(hollow.to_array(), outline.to_array())


def test_rectangles_is_a_loop_of_rectangle():
    rng = np.random.default_rng(2)
    rects = rng.integers(-3, 24, size=(25, 4))
    rects = rects[(rects[:, 0] != rects[:, 2]) & (rects[:, 1] != rects[:, 3])]
    colors = [tuple(int(c) for c in rng.integers(0, 256, 3)) for _ in range(len(rects))]
    for fill, kw in [(False, {}), (True, {}), (False, dict(width=3, dash=(4, 2)))]:
        a = sl.FrameBuffer(22, 20)
        sl.draw.rectangles(a, rects, color=colors, fill=fill, **kw)
        b = sl.FrameBuffer(22, 20)
        for r, c in zip(rects, colors):
            sl.draw.rectangle(b, *r, color=c, fill=fill, **kw)
        assert np.array_equal(a.to_array(), b.to_array()), (fill, kw)
    both = sl.FrameBuffer(10, 6, mode="L")
    sl.draw.rectangles(both, [(0, 0, 3, 3), (5, 1, 9, 5)], color=255, fill=[60, 90])
    assert both.to_array()[3, 1] == 60 and both.to_array()[2, 6] == 90
    assert both.get_pixel(0, 0) == 255 == both.get_pixel(9, 5)
    sl.draw.rectangles(both, [])


# -- rounded rectangles --------------------------------------------------------------------

def test_rounded_rectangle_tiny():
    fb = sl.FrameBuffer(9, 6, mode="1")
    sl.draw.rounded_rectangle(fb, 0, 0, 8, 5, 2)
    assert lit(fb) == "\n".join(["-#######-", "#-------#", "#-------#", "#-------#",
                                 "#-------#", "-#######-"])


@pytest.mark.parametrize("r", range(0, 24))
def test_a_rounded_square_of_side_2r_is_the_midpoint_circle(r):
    n = 2 * r + 5
    outline = mine(n, n, lambda fb: sl.draw.rounded_rectangle(fb, 2, 2, 2 + 2 * r, 2 + 2 * r, r))
    assert np.array_equal(outline, mine(n, n, lambda fb: sl.draw.circle(fb, 2 + r, 2 + r, r)))
    area = mine(n, n, lambda fb: sl.draw.rounded_rectangle(fb, 2, 2, 2 + 2 * r, 2 + 2 * r, r,
                                                           fill=True))
    assert np.array_equal(area, mine(n, n, lambda fb: sl.draw.fill_circle(fb, 2 + r, 2 + r, r)))


def test_rounded_rectangle_is_pillows_where_the_sides_are_longer_than_the_corners():
    rng = np.random.default_rng(4)
    w, h = 80, 70
    for _ in range(120):
        r = int(rng.integers(0, 31))
        x0, y0 = (int(c) for c in rng.integers(-3, 6, 2))
        x1 = x0 + 2 * r + 2 + int(rng.integers(0, 20))
        y1 = y0 + 2 * r + 2 + int(rng.integers(0, 12))
        for fill in (True, False):
            got = mine(w, h, lambda fb: sl.draw.rounded_rectangle(fb, x0, y0, x1, y1, r,
                                                                  fill=fill))
            kw = dict(fill=1) if fill else dict(outline=1)
            expected = pillow(w, h, lambda d, f: d.rounded_rectangle(
                (x0, f(y1), x1, f(y0)), r, **kw))
            assert np.array_equal(got, expected), (x0, y0, x1, y1, r, fill)


def test_rounded_rectangle_radius_zero_and_clamped():
    for x0, y0, x1, y1 in [(1, 1, 9, 6), (2, 0, 2, 5), (0, 3, 7, 3)]:
        for fill in (True, False):
            a = mine(12, 9, lambda fb: sl.draw.rounded_rectangle(fb, x0, y0, x1, y1, 0, fill=fill))
            b = mine(12, 9, lambda fb: sl.draw.rectangle(fb, x0, y0, x1, y1, fill=fill))
            assert np.array_equal(a, b)
    big = mine(14, 9, lambda fb: sl.draw.rounded_rectangle(fb, 0, 0, 12, 6, 1000))
    assert np.array_equal(big, mine(14, 9, lambda fb: sl.draw.rounded_rectangle(fb, 0, 0, 12, 6, 3)))


def test_rounded_rectangle_area_holds_its_outline_and_fills_between():
    for r in (1, 3, 6):
        fb = sl.FrameBuffer(30, 20, mode="1")
        sl.draw.rounded_rectangle(fb, 2, 1, 27, 17, r)
        outline = fb.to_array()
        area = mine(30, 20, lambda f: sl.draw.rounded_rectangle(f, 2, 1, 27, 17, r, fill=True))
        assert not (outline & ~area).any()
        for row_out, row_area in zip(outline, area):
            xs = np.flatnonzero(row_out)
            expected = np.zeros_like(row_area)
            if len(xs):
                expected[xs.min():xs.max() + 1] = True
            assert np.array_equal(row_area, expected)


def test_rounded_rectangle_thick_dashed_and_antialiased():
    fb = sl.FrameBuffer(30, 20, mode="L")
    sl.draw.rounded_rectangle(fb, 3, 3, 26, 16, 5, color=255, width=3)
    a = fb.to_array()
    assert a[20 - 1 - 10, 2:5].tolist() == [255, 255, 255] and a[20 - 1 - 10, 1] == 0
    assert a[20 - 1 - 10, 5] == 0                        # the inside stays empty
    dashed = sl.FrameBuffer(30, 20, mode="L")
    sl.draw.rounded_rectangle(dashed, 3, 3, 26, 16, 5, color=255, dash=(4, 4))
    solid = sl.FrameBuffer(30, 20, mode="L")
    sl.draw.rounded_rectangle(solid, 3, 3, 26, 16, 5, color=255)
    on, all_ = int((dashed.to_array() > 0).sum()), int((solid.to_array() > 0).sum())
    assert not (dashed.to_array() & ~solid.to_array()).any() and 0.4 < on / all_ < 0.6
    smooth = sl.FrameBuffer(30, 20, mode="L")
    sl.draw.rounded_rectangle(smooth, 3, 3, 26, 16, 5, color=255, fill=True, antialias=True)
    s = smooth.to_array().astype(float) / 255
    # the rectangle of pixel squares with corners of radius r + 1/2, by chords within
    # 0.1 pixel of the arcs: coverage adds up to the polygon's area
    from scanline.draw.shapes import _arcs
    x, y = _arcs(2.5, 2.5, 26.5, 16.5, 5.5, 5.5).T
    drawn = 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
    assert abs(s.sum() - drawn) < 0.5
    assert abs(drawn - (24 * 14 - (4 - math.pi) * 5.5 ** 2)) < 3
    assert s[20 - 1 - 10, 3] == 1.0 and s[20 - 1 - 10, 2] == 0.0      # straight sides crisp


# -- regular polygons ----------------------------------------------------------------------

@pytest.mark.parametrize("sides", range(3, 9))
@pytest.mark.parametrize("degrees", [0, 10, 45, 90, 200])
def test_regular_polygon_vertices_are_pillows_with_y_flipped(sides, degrees):
    xc, yc, r = 30.0, 20.0, 12.5
    got = sl.draw.regular_polygon_vertices(xc, yc, r, sides, f"{degrees}deg")
    theirs = np.array(ImageDraw._compute_regular_polygon_vertices((xc, -yc, r), sides, degrees))
    theirs[:, 1] = -theirs[:, 1]
    for p in got:   # the same set of vertices (Pillow's run the other way round)
        assert np.abs(theirs - p).max(axis=1).min() < 0.006    # (Pillow rounds to 0.01)
    # counterclockwise, first the right end of the (unrotated) bottom side
    (ax, ay), (bx, by) = got[1] - got[0], got[2] - got[1]
    assert ax * by - ay * bx > 0
    if degrees == 0:
        assert got[0, 1] == pytest.approx(got[-1, 1]) and got[0, 1] < yc and got[0, 0] > xc


def test_regular_polygon_is_the_polygon_and_the_closed_polyline_of_its_vertices():
    for sides, rotation in [(3, 0.0), (5, 0.3), (6, "15deg"), (12, 1)]:
        verts = sl.draw.regular_polygon_vertices(15, 12, 9.3, sides, rotation)
        for fill, kw in [(False, {}), (False, dict(width=2, join="round")), (True, {})]:
            a = sl.FrameBuffer(30, 25, mode="1")
            sl.draw.regular_polygon(a, 15, 12, 9.3, sides, rotation, fill=fill, **kw)
            b = sl.FrameBuffer(30, 25, mode="1")
            if fill:
                sl.draw.polygon(b, verts)
            else:
                sl.draw.polyline(b, verts, closed=True, **kw)
            assert np.array_equal(a.to_array(), b.to_array())


def test_regular_polygon_tiny_and_symmetric():
    fb = sl.FrameBuffer(11, 9, mode="1")
    sl.draw.regular_polygon(fb, 5, 4, 4, 6)
    assert lit(fb) == "\n".join(["-----------", "---#####---", "--#-----#--", "--#-----#--",
                                 "-#-------#-", "--#-----#--", "--#-----#--", "---#####---",
                                 "-----------"])
    square = sl.FrameBuffer(12, 12, mode="1")     # unrotated: an axis-aligned square
    sl.draw.regular_polygon(square, 5.5, 5.5, 5 * math.sqrt(2), 4, fill=True)
    assert square.to_array()[1:11, 1:11].all() and square.to_array().sum() == 100


def test_regular_polygon_with_fill_and_outline_and_rotation_warning():
    fb = sl.FrameBuffer(20, 20, mode="L")
    sl.draw.regular_polygon(fb, 10, 10, 8, 5, color=255, fill=90)
    assert fb.get_pixel(10, 10) == 90 and fb.get_pixel(10, 18) == 255
    with pytest.warns(sl.AngleWarning, match="rotation=30"):
        sl.draw.regular_polygon(fb, 10, 10, 8, 5, 30)


# -- modes, extremes and errors --------------------------------------------------------------

@pytest.mark.parametrize("mode", MODES)
def test_every_mode(mode):
    fb = sl.FrameBuffer(24, 16, mode=mode)
    sl.draw.rectangle(fb, 1, 1, 10, 6, color="red", fill="blue")
    sl.draw.rounded_rectangle(fb, 12, 1, 22, 14, 3, color="white", fill=True, antialias=True)
    sl.draw.regular_polygon(fb, 6, 11, 4, 5, color="yellow", width=2)
    sl.draw.point(fb, 0, 15, "white")
    assert fb.get_pixel(0, 15) == sl.FrameBuffer(1, 1, mode=mode, background="white").get_pixel(0, 0) \
        or mode == "P"
    assert fb.to_array().any()


def test_huge_shapes_are_clipped():
    fb = sl.FrameBuffer(32, 24, mode="1")
    sl.draw.rectangle(fb, -2**30, -2**30, 2**30, 2**30, fill=True)
    assert fb.to_array().all()
    fb.clear()
    sl.draw.rectangle(fb, -2**30, -2**30, 2**30, 2**30, width=7)
    sl.draw.rounded_rectangle(fb, -2**30, -2**30, 2**30, 2**30, 2**29, width=3)
    sl.draw.rounded_rectangle(fb, -2**30, -2**30, 2**30, 2**30, 2**29, dash=(3, 3))
    assert not fb.to_array().any()                      # all of them far outside
    sl.draw.rounded_rectangle(fb, -2**30, -2**30, 2**30, 15, 10**6, fill=True)
    assert fb.to_array()[24 - 1 - 15:].all() and not fb.to_array()[:24 - 1 - 15].any()
    fb.clear()
    sl.draw.rounded_rectangle(fb, -2**30, -2**30, 2**30, 15, 10**6)     # the straight top side
    assert fb.to_array()[24 - 1 - 15].all() and fb.to_array().sum() == 32
    fb.clear()
    sl.draw.rounded_rectangle(fb, -2**30, -2**30, 20, 15, 10**6, fill=True)
    assert not fb.to_array().any()          # the frame lies in the cut-off corner
    sl.draw.regular_polygon(fb, 10, 10, 2**29, 100, fill=True, antialias=True)


@pytest.mark.parametrize("call, error, words", [
    (lambda fb: sl.draw.rectangle(fb, float("nan"), 0, 1, 1), ValueError, ["x0"]),
    (lambda fb: sl.draw.rectangle(fb, 0, 0, 2**31, 1), ValueError, ["x1"]),
    (lambda fb: sl.draw.rectangle(fb, 0, 0, 1, 1, fill=None), TypeError, ["fill=None"]),
    (lambda fb: sl.draw.rectangle(fb, 0, 0, 1, 1, fill="nope"), ValueError, ["fill="]),
    (lambda fb: sl.draw.rectangle(fb, 0, 0, 1, 1, width=0), ValueError, ["width"]),
    (lambda fb: sl.draw.rounded_rectangle(fb, 0, 0, 5, 5, -1), ValueError, ["radius"]),
    (lambda fb: sl.draw.rounded_rectangle(fb, 0, 0, 5, 5, "2"), TypeError, ["radius"]),
    (lambda fb: sl.draw.regular_polygon(fb, 0, 0, 5, 2), ValueError, ["sides", ">= 3"]),
    (lambda fb: sl.draw.regular_polygon(fb, 0, 0, 5, 4.0), TypeError, ["sides"]),
    (lambda fb: sl.draw.regular_polygon(fb, 0, 0, 5, 2**21), ValueError, ["sides", "circle"]),
    (lambda fb: sl.draw.regular_polygon(fb, 0, 0, -1, 5), ValueError, ["r must be >= 0"]),
    (lambda fb: sl.draw.regular_polygon(fb, 0, 0, 2**31, 5), ValueError, ["2**30"]),
    (lambda fb: sl.draw.regular_polygon(fb, 0, 0, 5, 5, "sideways"), ValueError, ["rotation"]),
    (lambda fb: sl.draw.point(fb, "1", 0), TypeError, ["x"]),
    (lambda fb: sl.draw.points(fb, [1, 2, 3]), ValueError, ["points"]),
    (lambda fb: sl.draw.rectangles(fb, [(0, 0, 1)]), ValueError, ["rectangles", "(N, 4)"]),
    (lambda fb: sl.draw.rectangle(None, 0, 0, 1, 1), TypeError, ["fb"]),
])
def test_bad_input_names_the_argument(call, error, words):
    fb = sl.FrameBuffer(8, 8)
    with pytest.raises(error) as e:
        call(fb)
    assert isinstance(e.value, sl.ScanlineError)
    assert all(w in str(e.value) for w in words), str(e.value)
    assert not fb.to_array().any()


# -- fuzz: never a crash, never a write outside ----------------------------------------------
COORD = st.one_of(st.integers(-2**31, 2**31), st.floats(allow_nan=True, allow_infinity=True),
                  st.integers(-40, 40))


@pytest.mark.filterwarnings("ignore::scanline.errors.AngleWarning")
@HYPOTHESIS
@given(c=st.lists(COORD, min_size=4, max_size=4), r=COORD, sides=st.integers(-2, 40),
       width=st.one_of(st.none(), st.floats(0.5, 12)), fill=st.sampled_from([False, True, "red"]),
       antialias=st.booleans(), mode=st.sampled_from(MODES))
def test_fuzz_shapes_stay_inside(c, r, sides, width, fill, antialias, mode):
    fb = sl.FrameBuffer(9, 7, mode=mode)
    buf = fb._buf
    big = np.full((buf.shape[0] + 4,) + buf.shape[1:], 77, np.uint8)
    big[2:-2] = buf
    fb._buf = big[2:-2]
    calls = [lambda: sl.draw.rectangle(fb, *c, fill=fill, width=width, antialias=antialias),
             lambda: sl.draw.rounded_rectangle(fb, *c, r, fill=fill, width=width,
                                               antialias=antialias),
             lambda: sl.draw.regular_polygon(fb, c[0], c[1], r, sides, c[2], fill=fill,
                                             width=width, antialias=antialias),
             lambda: sl.draw.point(fb, c[0], c[1]),
             lambda: sl.draw.rectangles(fb, [c], fill=fill, width=width)]
    for call in calls:
        try:
            call()
        except (ValueError, TypeError) as error:
            assert isinstance(error, sl.ScanlineError), error
    assert (big[:2] == 77).all() and (big[-2:] == 77).all()
