"""Line types (bit masks on the pixel sequence, dash lengths across vertices), pens,
bad input and fuzzing of the stroked primitives."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from shapely.geometry import LineString
from shapely.ops import substring, unary_union

import scanline as sl
from tests.reference import HYPOTHESIS, bresenham, circle_pixels, in_frame, lit


def path_pixels(points, closed=False):
    """The reference pixel sequence of a polyline: each segment's Bresenham pixels
    in path order, a shared vertex once."""
    pts = [tuple(int(c) for c in p) for p in points]
    if closed and len(pts) > 2:
        pts = pts + [pts[0]]
    seq = [pts[0]]
    for a, b in zip(pts, pts[1:]):
        seg = bresenham(*a, *b)[0]
        if seg[0] != a:
            seg = seg[::-1]
        seq += seg[1:]
    if closed and len(pts) > 3:
        seq = seq[:-1]
    return seq


def mask_on(mask, k):
    return (mask >> (15 - k % 16)) & 1 == 1


# -- bit masks along the pixel sequence ----------------------------------------------------

@pytest.mark.parametrize("end", [(25, 7), (7, 25), (-7, 25), (-25, 7), (-25, -7), (-7, -25),
                                 (7, -25), (25, -7), (20, 20), (0, 18), (-18, 0)])
def test_mask_on_every_octant(end):
    mask = 0b1110011000111101
    x0, y0 = 30, 30
    fb = sl.FrameBuffer(60, 60, mode="1")
    sl.draw.line(fb, x0, y0, x0 + end[0], y0 + end[1], color=1, dash=mask)
    seq = path_pixels([(x0, y0), (x0 + end[0], y0 + end[1])])
    assert lit(fb) == {p for k, p in enumerate(seq) if mask_on(mask, k)}


def test_mask_continues_across_vertices_and_phase():
    pts = [(2, 3), (40, 9), (33, 38), (5, 20), (5, 30)]
    mask = 0b1111000011001010
    seq = path_pixels(pts)
    for phase in (0, 5, 13):
        fb = sl.FrameBuffer(45, 45, mode="1")
        sl.draw.polyline(fb, pts, color=1, dash=mask, dash_phase=phase)
        assert lit(fb) == {p for k, p in enumerate(seq) if mask_on(mask, k + phase)}


def test_mask_around_closed_polyline():
    pts = [(3, 3), (30, 5), (20, 28)]
    mask = 0b1100110011001100
    fb = sl.FrameBuffer(35, 35, mode="1")
    sl.draw.polyline(fb, pts, color=1, closed=True, dash=mask)
    seq = path_pixels(pts, closed=True)
    assert len(seq) == len(set(seq))     # each pixel of the ring once
    assert lit(fb) == {p for k, p in enumerate(seq) if mask_on(mask, k)}


def test_named_types_are_masks():
    fb = sl.FrameBuffer(20, 3, mode="1")
    sl.draw.line(fb, 0, 1, 19, 1, color=1, dash="dotted")
    assert sl.text_image(fb).splitlines()[1] == "#-#-#-#-#-#-#-#-#-#-"
    fb.clear()
    sl.draw.line(fb, 0, 1, 19, 1, color=1, dash="dashed")
    assert sl.text_image(fb).splitlines()[1] == "########--------####"
    fb.clear()
    sl.draw.line(fb, 0, 1, 19, 1, color=1, dash="dash-dot")
    assert sl.text_image(fb).splitlines()[1] == "########---##---####"


def test_mask_on_midpoint_circle_sequence():
    # the circle's pixels numbered counterclockwise from (xc + r, yc)
    mask = 0b1111111100000000
    xc, yc, r = 20, 20, 15
    fb = sl.FrameBuffer(41, 41, mode="1")
    sl.draw.circle(fb, xc, yc, r, color=1, dash=mask)
    ring = circle_pixels(xc, yc, r)
    order = sorted(ring, key=lambda p: math.atan2(p[1] - yc, p[0] - xc) % (2 * math.pi))
    assert order[0] == (xc + r, yc)
    assert lit(fb) == {p for k, p in enumerate(order) if mask_on(mask, k)}
    # the solid circle is untouched by the plumbing
    fb.clear()
    sl.draw.circle(fb, xc, yc, r, color=1, dash="solid")
    assert lit(fb) == ring


# -- dash lengths --------------------------------------------------------------------------

def test_lengths_width_one_across_a_corner():
    # pixel k of a segment sits at arc length k (axis-aligned): on when
    # (s mod 6) < 4; the corner pixel (10, 0) is s = 10, then s = 11, 12 ... upward
    fb = sl.FrameBuffer(12, 12, mode="1")
    sl.draw.polyline(fb, [(0, 0), (10, 0), (10, 10)], color=1, dash=(4, 2))
    want = {(x, 0) for x in range(11) if x % 6 < 4} | {(10, y) for y in range(1, 11)
                                                       if (10 + y) % 6 < 4}
    assert lit(fb) == want


def shapely_dashes(pts, lengths, phase, width, closed=False):
    """The dashed stroke by shapely: substrings of the path, buffered flat."""
    ring = list(map(tuple, pts)) + ([tuple(pts[0])] if closed else [])
    path = LineString(ring)
    period = sum(lengths)
    pieces = []
    s = -(phase % period)
    while s < path.length:
        for i, d in enumerate(lengths):
            if i % 2 == 0 and d > 0:
                a, b = max(s, 0), min(s + d, path.length)
                if b > a:
                    pieces.append(substring(path, a, b))
            s += d
    return unary_union([p.buffer(width / 2, cap_style="flat", join_style="mitre",
                                 mitre_limit=10, quad_segs=32) for p in pieces])


@pytest.mark.parametrize("closed", [False, True])
def test_thick_dashes_continue_across_vertices(closed):
    pts = np.array([(40.3, 50.2), (300.7, 70.1), (280.2, 300.4), (60.5, 250.9)])
    lengths, phase, width = (47.0, 23.0), 11.0, 9.0
    fb = sl.FrameBuffer(360, 360, mode="L")
    sl.draw.polyline(fb, pts, color=255, closed=closed, width=width, dash=lengths,
                     dash_phase=phase)
    count = int((fb.to_array() > 0).sum())
    ref = shapely_dashes(pts, lengths, phase, width, closed)
    assert count == pytest.approx(ref.area, rel=0.01)
    # and the dashes are where shapely puts them: few pixels differ
    ys, xs = np.nonzero(fb.to_array()[::-1])
    from shapely import contains_xy
    inside = contains_xy(ref, xs.astype(float), ys.astype(float))
    assert inside.mean() > 0.99


def test_closed_dash_wraps_into_first():
    # the pattern is on at the start and at the end of the ring: one dash runs
    # through the start vertex, mitered, with no caps there
    sq = [(10, 10), (50, 10), (50, 50), (10, 50)]
    fb = sl.FrameBuffer(60, 60, mode="1")
    sl.draw.polyline(fb, sq, color=1, closed=True, width=4, dash=(30, 10), dash_phase=20)
    # corner (10, 10) lies 20 into a 30-long dash that began on the last side; the
    # corner square [8, 10] x [8, 10] exists only if that dash is joined there
    # (cut into two dashes with butt ends it would stay empty)
    got = lit(fb)
    assert {(8, 9), (9, 9), (8, 10), (9, 10), (10, 15), (15, 10)} <= got
    # and the pattern: 10 more on along y = 10, then off from x = 20 to x = 30
    assert (19, 10) in got and (21, 10) not in got and (29, 10) not in got and (31, 10) in got


def test_dash_phase_shifts_the_pattern():
    a = sl.FrameBuffer(100, 10, mode="1")
    b = sl.FrameBuffer(100, 10, mode="1")
    # (dash ends at x = k + 0.3, never on a pixel center, so rounding cannot matter)
    sl.draw.polyline(a, [(0.3, 5), (99.3, 5)], color=1, width=3, dash=(10, 5), dash_phase=4)
    sl.draw.polyline(b, [(-3.7, 5), (99.3, 5)], color=1, width=3, dash=(10, 5))
    # a phase of 4 is the pattern of a line that began 4 pixels earlier (a starts at
    # x = 0.3, so column 0 is b's only)
    assert lit(a) == {(x, y) for x, y in lit(b) if x >= 1}
    assert (6, 5) in lit(a) and (7, 5) not in lit(a) and (11, 5) not in lit(a) and (12, 5) in lit(a)


def test_zero_length_dashes_with_round_caps_are_dots():
    fb = sl.FrameBuffer(100, 20, mode="L")
    sl.draw.line(fb, 10, 10, 89, 10, color=255, width=6, cap="round", dash=(0, 20))
    from scipy import ndimage
    labels, n = ndimage.label(fb.to_array() > 0)
    assert n == 4                                  # at 0, 20, 40 and 60 along the line
    sizes = np.bincount(labels.ravel())[1:]
    assert sizes == pytest.approx([math.pi * 9] * 4, rel=0.1)   # discs of radius 3
    assert lit(fb) >= {(10, 10), (30, 10), (50, 10), (70, 10)}


def test_mask_on_thick_line_is_width_units():
    a = sl.FrameBuffer(80, 10, mode="1")
    b = sl.FrameBuffer(80, 10, mode="1")
    sl.draw.line(a, 0, 5, 79, 5, color=1, width=3, dash=0b1111000011110000)
    sl.draw.line(b, 0, 5, 79, 5, color=1, width=3, dash=(12, 12))
    assert lit(a) == lit(b)


# -- pens ----------------------------------------------------------------------------------

def dilate(points, offsets):
    return {(x + dx, y + dy) for x, y in points for dx, dy in offsets}


def test_square_pen_is_pixel_replication():
    fb = sl.FrameBuffer(40, 30, mode="1")
    sl.draw.line(fb, 3, 4, 35, 22, color=1, pen="square", width=3)
    seq = path_pixels([(3, 4), (35, 22)])
    square = [(dx, dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1)]
    assert lit(fb) == dilate(seq, square)


def test_circle_pen_and_custom_footprint_with_dashes():
    pts = [(5, 5), (40, 12), (30, 35)]
    seq = path_pixels(pts)
    fb = sl.FrameBuffer(48, 42, mode="1")
    sl.draw.polyline(fb, pts, color=1, pen="circle", width=5)
    disc = [(dx, dy) for dx in range(-2, 3) for dy in range(-2, 3) if dx * dx + dy * dy <= 6.25]
    assert lit(fb) == in_frame(dilate(seq, disc), 48, 42)
    # a footprint in image order: the top row is +1 in y
    foot = np.array([[True, False, False],
                     [False, True, False],
                     [False, False, True]])
    fb.clear()
    sl.draw.polyline(fb, pts, color=1, pen=foot, dash=0b1111000011110000)
    on = [p for k, p in enumerate(seq) if mask_on(0b1111000011110000, k)]
    assert lit(fb) == dilate(on, [(-1, 1), (0, 0), (1, -1)])


def test_pen_on_circle_is_clipped():
    fb = sl.FrameBuffer(20, 20, mode="1")
    sl.draw.circle(fb, 3, 3, 10, color=1, pen="square", width=3)
    ring = circle_pixels(3, 3, 10)
    square = [(dx, dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1)]
    assert lit(fb) == in_frame(dilate(ring, square), 20, 20)


# -- bad input -----------------------------------------------------------------------------

BAD = [
    (dict(cap="rounded"), "cap"),
    (dict(join="mitre"), "join"),
    (dict(dash="dash"), "dash"),
    (dict(width=0), "width"),
    (dict(width=-2), "width"),
    (dict(width=float("nan")), "width"),
    (dict(width=0.5), "width"),
    (dict(width="3"), "width"),
    (dict(miter_limit=0.5), "miter_limit"),
    (dict(miter_limit=float("inf")), "miter_limit"),
    (dict(dash=[]), "dash"),
    (dict(dash=[0, 0]), "dash"),
    (dict(dash=[3, -1]), "dash"),
    (dict(dash=[3, float("nan")]), "dash"),
    (dict(dash=0), "dash"),
    (dict(dash=1 << 16), "dash"),
    (dict(dash=-5), "dash"),
    (dict(dash=True), "dash"),
    (dict(dash_phase=float("inf")), "dash_phase"),
    (dict(pen="star"), "pen"),
    (dict(pen=np.zeros((3, 3), bool)), "pen"),
    (dict(pen=np.ones((100, 100), bool)), "pen"),
    (dict(pen=np.ones(3, bool)), "pen"),
    (dict(style="thick"), "style"),
]


@pytest.mark.parametrize("kwargs,name", BAD)
def test_bad_attributes_name_the_argument(kwargs, name):
    fb = sl.FrameBuffer(10, 10)
    with pytest.raises((sl.ArgumentValueError, sl.ArgumentTypeError), match=name):
        sl.draw.polyline(fb, [(1, 1), (5, 5)], **kwargs)
    if name != "style":
        with pytest.raises((sl.ArgumentValueError, sl.ArgumentTypeError), match=name):
            sl.LineStyle(**kwargs)


@pytest.mark.parametrize("points,name", [
    ([(1, 1), (float("nan"), 2)], "points"),
    ([(1, 2, 3)], "points"),
    ("abc", "points"),
])
def test_bad_points(points, name):
    fb = sl.FrameBuffer(10, 10)
    with pytest.raises((sl.ArgumentValueError, sl.ArgumentTypeError), match=name):
        sl.draw.polyline(fb, points, width=3)


def test_bad_batches():
    fb = sl.FrameBuffer(10, 10)
    with pytest.raises(sl.ArgumentValueError, match="closed"):
        sl.draw.polylines(fb, [[(1, 1), (3, 3)]], closed=[True, False])
    with pytest.raises(sl.ArgumentValueError, match="counts"):
        sl.draw.polylines(fb, np.zeros((4, 2)), counts=[3, 3], width=2)
    with pytest.raises(sl.ArgumentValueError, match="color"):
        sl.draw.polylines(fb, [[(1, 1), (3, 3)]], color=["red", "blue"], width=2)
    with pytest.raises(sl.ArgumentValueError, match="method"):
        sl.draw.line(fb, 1, 1, 5, 5, method="dda", width=3)
    with pytest.raises(sl.ArgumentValueError, match="pen"):
        sl.draw.line(fb, 1, 1, 5, 5, pen="square", antialias=True)
    # beyond SEQUENCE_LIMIT a patterned circle numbers only its visible pixels (issue
    # 11; tests/hardening/test_far_conics.py checks the numbering): this one's top row
    # is every other pixel of the solid circle's
    dotted, solid = sl.FrameBuffer(10, 10, mode="1"), sl.FrameBuffer(10, 10, mode="1")
    sl.draw.circle(dotted, 1, 4 - 2**20, 2**20, dash="dotted")
    sl.draw.circle(solid, 1, 4 - 2**20, 2**20)
    d, s = dotted.to_array() > 0, solid.to_array() > 0
    assert (d <= s).all() and s.sum() == 10 and d.sum() == 5


# -- fuzzing: nothing is written outside the frame buffer -----------------------------------

def guarded(width, height, mode):
    """A frame buffer whose storage has guard rows above and below (a C-contiguous
    view), so that a write past the first or last scan line lands in the guard."""
    fb = sl.FrameBuffer(width, height, mode=mode)
    buf = fb._buf
    big = np.full((height + 8,) + buf.shape[1:], 77, np.uint8)
    big[4:-4] = buf
    fb._buf = big[4:-4]
    return fb, big


coordinate = st.one_of(st.floats(-80, 120, allow_nan=False).map(lambda v: round(v * 8) / 8),
                       st.sampled_from([-2**30, 2**30, -1e9, 1e9, 0.5, -0.5]))
polyline_st = st.lists(st.tuples(coordinate, coordinate), min_size=0, max_size=7)


@HYPOTHESIS
@given(pts=polyline_st, width=st.sampled_from([1, 1.5, 2, 3.7, 8, 40]),
       cap=st.sampled_from(["butt", "round", "square"]),
       join=st.sampled_from(["miter", "round", "bevel"]),
       dash=st.sampled_from([None, "dotted", 0b1011000011100001, (5, 2.5), (0, 3), (7,)]),
       pen=st.sampled_from([None, None, "square", "circle"]),
       closed=st.booleans(), mode=st.sampled_from(["1", "RGB"]))
def test_fuzz_nothing_outside(pts, width, cap, join, dash, pen, closed, mode):
    W, H = 37, 29
    fb, big = guarded(W, H, mode)
    pts = np.array(pts, float).reshape(-1, 2)
    sl.draw.polyline(fb, pts, color="white", closed=closed, width=width, cap=cap, join=join,
                     dash=dash, pen=pen)
    assert (big[:4] == 77).all() and (big[-4:] == 77).all()
    # a frame buffer as large as everything drawn agrees on the visible part: no
    # write wrapped around a row end
    if len(pts) and np.abs(pts).max() < 1000:
        ref = sl.FrameBuffer(W + 200, H + 200, mode=mode)
        sl.draw.polyline(ref, pts, color="white", closed=closed, width=width, cap=cap,
                         join=join, dash=dash, pen=pen)
        assert lit(fb) == in_frame(lit(ref), W, H)


@HYPOTHESIS
@given(xc=coordinate, yc=coordinate, r=st.integers(0, 60), width=st.sampled_from([1, 2.5, 9]),
       dash=st.sampled_from([None, "dashed", (3, 3)]), pen=st.sampled_from([None, "circle"]))
def test_fuzz_conics_nothing_outside(xc, yc, r, width, dash, pen):
    fb, big = guarded(37, 29, "RGB")
    sl.draw.circle(fb, xc, yc, r, color="white", width=width, dash=dash, pen=pen)
    sl.draw.ellipse(fb, xc, yc, r, r // 2 + 1, color="white", width=width, dash=dash, pen=pen)
    assert (big[:4] == 77).all() and (big[-4:] == 77).all()


@HYPOTHESIS
@given(pts=polyline_st, width=st.sampled_from([1, 2.5, 9]),
       cap=st.sampled_from(["butt", "round", "square"]),
       join=st.sampled_from(["miter", "round", "bevel"]),
       dash=st.sampled_from([None, "dashed", (5, 2.5)]),
       color=st.sampled_from(["white", "#ff000080"]), closed=st.booleans(),
       antialias=st.booleans())
def test_fuzz_antialiased_and_translucent_nothing_outside(pts, width, cap, join, dash, color,
                                                          closed, antialias):
    fb, big = guarded(37, 29, "RGBA")
    pts = np.array(pts, float).reshape(-1, 2)
    sl.draw.polyline(fb, pts, color=color, closed=closed, width=width, cap=cap, join=join,
                     dash=dash, antialias=antialias)
    assert (big[:4] == 77).all() and (big[-4:] == 77).all()
