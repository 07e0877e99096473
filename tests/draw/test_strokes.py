"""Thick lines: caps, joins, widths (exact tiny images, areas against shapely),
degenerate polylines, translucency, antialiasing."""

import numpy as np
import pytest
from shapely.geometry import LineString, Point

import scanline as sl
from tests.reference import lit


def image(fb):
    return sl.text_image(fb).splitlines()


def pixels(rows):
    """Device pixels of a text image given top row first ('#' = set)."""
    h = len(rows)
    return {(x, h - 1 - r) for r, row in enumerate(rows) for x, c in enumerate(row) if c == "#"}


# -- exact tiny images, derived by hand ------------------------------------------------
# A thick line is the set of pixel centers inside its outline; centers on a left or
# top edge are in, on a right or bottom edge out (docs/conventions.md).

@pytest.mark.parametrize("cap,expected", [
    # the outline x in [3, 6], y in [0.5, 3.5]: centers x = 3, 4, 5 (6 is on the
    # right edge), y = 1, 2, 3 (0.5 is not a center, 3.5 neither)
    ("butt", "---###----"),
    # the square cap extends each end by half the width: x in [1.5, 7.5]
    ("square", "--######--"),
])
def test_caps_width_3_horizontal(cap, expected):
    fb = sl.FrameBuffer(10, 5, mode="1")
    sl.draw.line(fb, 3, 2, 6, 2, color=1, width=3, cap=cap)
    assert image(fb) == ["----------"] + [expected] * 3 + ["----------"]


def test_round_cap_width_5_horizontal():
    # body x in [4, 8), y in (1.5, 6.5]; discs of radius 2.5 about (4, 4) and (8, 4)
    # take the centers at distance^2 in {1, 2, 4, 5} (< 6.25), not 8 or 9
    fb = sl.FrameBuffer(13, 9, mode="1")
    sl.draw.line(fb, 4, 4, 8, 4, color=1, width=5, cap="round")
    assert image(fb) == ["-------------",
                         "-------------",
                         "---#######---",
                         "--#########--",
                         "--#########--",
                         "--#########--",
                         "---#######---",
                         "-------------",
                         "-------------"]


@pytest.mark.parametrize("cap,expected", [
    # vertical x in [1.5, 4.5] -> columns 2, 3, 4; y from 2 to 6 (butt: rows 3..6)
    ("butt", ["-----", "--###", "--###", "--###", "--###", "-----", "-----", "-----"]),
    # square: y in [0.5, 7.5] -> rows 1..7
    ("square", ["--###", "--###", "--###", "--###", "--###", "--###", "--###", "-----"]),
])
def test_caps_width_3_vertical(cap, expected):
    fb = sl.FrameBuffer(5, 8, mode="1")
    sl.draw.line(fb, 3, 6, 3, 2, color=1, width=3, cap=cap)   # drawn downward
    assert image(fb) == expected


def test_even_width_2():
    # y in [1, 3]: the bottom edge y = 1 is out, the top edge y = 3 in
    fb = sl.FrameBuffer(8, 5, mode="1")
    sl.draw.line(fb, 2, 2, 6, 2, color=1, width=2)
    assert image(fb) == ["--------",
                         "--####--",
                         "--####--",
                         "--------",
                         "--------"]


def test_fractional_width():
    # width 2.5: y in [0.75, 3.25] -> rows 1, 2, 3
    fb = sl.FrameBuffer(8, 5, mode="1")
    sl.draw.line(fb, 2, 2, 6, 2, color=1, width=2.5)
    assert image(fb) == ["--------",
                         "--####--",
                         "--####--",
                         "--####--",
                         "--------"]


MITER_L = ["---------",
           "---------",
           "------###",
           "------###",
           "------###",
           "-########",
           "-########",
           "-########"]


def test_miter_join():
    # horizontal part x in [1, 7), rows 0..2; vertical part x in [5.5, 8.5], rows
    # 2..5 (y = 1 is its bottom edge); the miter square [7, 8.5] x [-0.5, 1] adds
    # (7..8, 0..1)
    fb = sl.FrameBuffer(9, 8, mode="1")
    sl.draw.polyline(fb, [(1, 1), (7, 1), (7, 5)], color=1, width=3, join="miter")
    assert image(fb) == MITER_L


def test_bevel_join_and_miter_limit():
    # the bevel cuts the corner along y = x - 7.5: (8, 0) is out, (7, 0) and (8, 1) in
    bevel = MITER_L[:-1] + ["-#######-"]
    fb = sl.FrameBuffer(9, 8, mode="1")
    sl.draw.polyline(fb, [(1, 1), (7, 1), (7, 5)], color=1, width=3, join="bevel")
    assert image(fb) == bevel
    # a right angle's miter is sqrt(2) times the width: a limit below bevels it
    fb = sl.FrameBuffer(9, 8, mode="1")
    sl.draw.polyline(fb, [(1, 1), (7, 1), (7, 5)], color=1, width=3, miter_limit=1.4)
    assert image(fb) == bevel
    fb = sl.FrameBuffer(9, 8, mode="1")
    sl.draw.polyline(fb, [(1, 1), (7, 1), (7, 5)], color=1, width=3, miter_limit=1.42)
    assert image(fb) == MITER_L


def test_closed_square_outline():
    # closed: miter joins at all four corners, no caps.  The ring is the square
    # [0.5, 8.5]^2 minus the hole (3.5, 5.5)^2: x in when 0.5 <= x < 8.5, y when
    # 0.5 < y <= 8.5, the hole takes 4 and 5
    fb = sl.FrameBuffer(10, 10, mode="1")
    sl.draw.polyline(fb, [(2, 2), (7, 2), (7, 7), (2, 7)], color=1, closed=True, width=3)
    assert image(fb) == ["----------",
                         "-########-",
                         "-########-",
                         "-########-",
                         "-###--###-",
                         "-###--###-",
                         "-########-",
                         "-########-",
                         "-########-",
                         "----------"]


# -- areas: pixel counts against shapely's buffer ---------------------------------------

SHAPELY_CAP = {"butt": "flat", "round": "round", "square": "square"}
SHAPELY_JOIN = {"miter": "mitre", "round": "round", "bevel": "bevel"}


def random_polyline(rng, k, step=(40, 120), max_turn=2.4):
    """A random walk whose turns stay below ``max_turn`` radians (so no miter
    reaches the limit 10, where shapely truncates miters instead of beveling)."""
    angle = rng.uniform(0, 2 * np.pi)
    pts = [np.array([300.0, 300.0])]
    for _ in range(k - 1):
        angle += rng.uniform(-max_turn, max_turn)
        pts.append(pts[-1] + rng.uniform(*step) * np.array([np.cos(angle), np.sin(angle)]))
    return np.array(pts) + rng.uniform(0, 1, 2)


@pytest.mark.parametrize("cap", ["butt", "round", "square"])
@pytest.mark.parametrize("join", ["miter", "round", "bevel"])
def test_area_and_pixels_against_shapely(cap, join):
    from shapely import contains_xy

    rng = np.random.default_rng(["butt", "round", "square"].index(cap) * 3
                                + ["miter", "round", "bevel"].index(join))
    for trial in range(3):
        pts = random_polyline(rng, 6)
        width = rng.uniform(12, 24)
        pts -= pts.min(axis=0) - 2 * width
        size = int(pts.max() + 2 * width + 4)
        fb = sl.FrameBuffer(size, size, mode="L")
        sl.draw.polyline(fb, pts, color=255, width=width, cap=cap, join=join)
        got = fb.to_array()[::-1] > 0                 # [y, x]
        geo = LineString(pts).buffer(width / 2, quad_segs=64, cap_style=SHAPELY_CAP[cap],
                                     join_style=SHAPELY_JOIN[join], mitre_limit=10.0)
        # the pixel count is the area within 1% (digitization error only) ...
        assert got.sum() == pytest.approx(geo.area, rel=0.01), (trial, width)
        # ... and the pixels are those whose centers shapely finds inside, but for
        # centers within our arc tolerance (0.1 px) of the boundary
        ys, xs = np.mgrid[0:size, 0:size]
        inside = contains_xy(geo, xs.ravel() + 0.0, ys.ravel() + 0.0).reshape(size, size)
        assert (got != inside).sum() <= 0.002 * got.sum(), (trial, width)


@pytest.mark.parametrize("pts", [[(17, 10), (17, 30), (17, 10)], [(17, 30), (17, 10), (17, 30)],
                                 [(10, 15), (30, 15), (10, 15)], [(30, 15), (10, 15), (30, 15)],
                                 [(10, 10), (30, 25), (10, 10)], [(5, 5), (20, 5), (5, 5), (5, 20)]])
def test_a_reversal_gets_its_round_join(pts):
    # a polyline turning back on itself (180 degrees exactly): the round join is the
    # half disc beyond the turning vertex, whichever the direction and the sign of
    # the zero cross product (shapely: the buffer of the same path)
    from shapely import contains_xy

    fb = sl.FrameBuffer(40, 40, mode="1")
    sl.draw.polyline(fb, pts, color=1, width=7, join="round")
    got = fb.to_array()[::-1]
    geo = LineString(pts).buffer(3.5, quad_segs=64, cap_style="flat", join_style="round")
    ys, xs = np.mgrid[0:40, 0:40]
    inside = contains_xy(geo, xs.ravel() + 0.0, ys.ravel() + 0.0).reshape(40, 40)
    near = np.abs(geo.boundary.distance(  # centers on the boundary: the tie rules decide
        [Point(x, y) for x, y in zip(xs.ravel(), ys.ravel())])).reshape(40, 40) < 0.1
    assert not ((got != inside) & ~near).any()
    tip = np.array(pts[1]) + 3 * (np.array(pts[1]) - pts[0]) / np.hypot(*np.subtract(pts[1], pts[0]))
    assert got[int(round(tip[1])), int(round(tip[0]))]      # the join's far side is drawn


def test_area_of_self_overlapping_stroke_counts_once():
    # a star traced with a wide pen crosses itself: the union, once
    t = np.arange(5) * 4 * np.pi / 5
    pts = np.stack([200 + 150 * np.cos(t), 200 + 150 * np.sin(t)], axis=1)
    fb = sl.FrameBuffer(400, 400, mode="L")
    sl.draw.polyline(fb, pts, color=255, closed=True, width=14, join="round")
    count = int((fb.to_array() > 0).sum())
    ring = list(map(tuple, pts)) + [tuple(pts[0])]
    area = LineString(ring).buffer(7, quad_segs=64, join_style="round").area
    assert count == pytest.approx(area, rel=0.01)


@pytest.mark.parametrize("r,width", [(40, 6), (60, 11.5)])
def test_thick_circle_area(r, width):
    fb = sl.FrameBuffer(160, 160, mode="L")
    sl.draw.circle(fb, 80, 80, r, color=255, width=width)
    count = int((fb.to_array() > 0).sum())
    area = np.pi * ((r + width / 2) ** 2 - (r - width / 2) ** 2)
    assert count == pytest.approx(area, rel=0.01)


def test_thick_ellipse_area():
    fb = sl.FrameBuffer(200, 140, mode="L")
    sl.draw.ellipse(fb, 100, 70, 80, 50, color=255, width=8)
    count = int((fb.to_array() > 0).sum())
    e = Point(100, 70).buffer(1, quad_segs=256)
    from shapely import affinity
    outer = affinity.scale(e, 84, 54, origin=(100, 70))
    inner = affinity.scale(e, 76, 46, origin=(100, 70))
    # the stroke of an ellipse is not an ellipse ring exactly; within 1.5% of it
    assert count == pytest.approx(outer.area - inner.area, rel=0.015)


# -- degenerate polylines ---------------------------------------------------------------

def test_repeated_points_change_nothing():
    a = sl.FrameBuffer(40, 30, mode="1")
    b = sl.FrameBuffer(40, 30, mode="1")
    pts = [(3, 4), (30, 8), (12, 25)]
    sl.draw.polyline(a, pts, color=1, width=4, join="round", cap="round")
    sl.draw.polyline(b, [pts[0], pts[0], pts[1], pts[1], pts[1], pts[2], pts[2]], color=1,
                     width=4, join="round", cap="round")
    assert lit(a) == lit(b)


def test_collinear_points_are_one_segment():
    for join in ("miter", "round", "bevel"):
        a = sl.FrameBuffer(40, 20, mode="1")
        b = sl.FrameBuffer(40, 20, mode="1")
        sl.draw.polyline(a, [(3, 4), (20, 12), (37, 20)], color=1, width=5, join=join)
        sl.draw.line(b, 3, 4, 37, 20, color=1, width=5)
        assert lit(a) == lit(b)


def test_one_point_polylines():
    fb = sl.FrameBuffer(9, 9, mode="1")
    sl.draw.polyline(fb, [(4, 4)], color=1, width=5)          # butt: nothing
    assert lit(fb) == set()
    sl.draw.polyline(fb, [(4, 4)], color=1, width=5, cap="round")
    assert lit(fb) == {(4 + dx, 4 + dy) for dx in range(-2, 3) for dy in range(-2, 3)
                       if dx * dx + dy * dy < 6.25}
    fb.clear()
    sl.draw.polyline(fb, [(4, 4)], color=1, width=3, cap="square")
    # the square [2.5, 5.5]^2: centers 3, 4, 5
    assert lit(fb) == {(x, y) for x in (3, 4, 5) for y in (3, 4, 5)}
    fb.clear()
    sl.draw.polyline(fb, [(4, 4)], color=1)                   # width 1: the pixel
    assert lit(fb) == {(4, 4)}
    for kw in (dict(width=3), dict(), dict(antialias=True), dict(width=3, antialias=True)):
        fb.clear()
        sl.draw.polyline(fb, [], color=1, **kw)               # nothing at all
        assert lit(fb) == set()


def test_half_turn():
    # going back along the same line: a miter would be infinitely long -> bevel,
    # which adds nothing; a round join adds the half disc beyond the turn
    a = sl.FrameBuffer(30, 11, mode="1")
    b = sl.FrameBuffer(30, 11, mode="1")
    sl.draw.polyline(a, [(3, 5), (20, 5), (10, 5)], color=1, width=5)
    sl.draw.line(b, 3, 5, 20, 5, color=1, width=5)
    assert lit(a) == lit(b)
    a.clear()
    sl.draw.polyline(a, [(3, 5), (20, 5), (10, 5)], color=1, width=5, join="round")
    disc = {(20 + dx, 5 + dy) for dx in range(0, 3) for dy in range(-2, 3)
            if dx * dx + dy * dy < 6.25}
    assert lit(a) == lit(b) | disc


def test_closed_two_points_and_width_one_closed():
    fb = sl.FrameBuffer(12, 5, mode="1")
    sl.draw.polyline(fb, [(1, 2), (10, 2)], color=1, width=3, closed=True)
    # there and back, miter joins beveled at both half turns: the butt line
    ref = sl.FrameBuffer(12, 5, mode="1")
    sl.draw.line(ref, 1, 2, 10, 2, color=1, width=3)
    assert lit(fb) == lit(ref)


# -- width 1 is the classic line --------------------------------------------------------

def test_width_one_polyline_is_bresenham_lines():
    rng = np.random.default_rng(3)
    pts = rng.integers(-5, 45, (12, 2))
    a = sl.FrameBuffer(40, 40, mode="RGB")
    b = sl.FrameBuffer(40, 40, mode="RGB")
    sl.draw.polyline(a, pts, color="red", closed=True)
    ring = np.vstack([pts, pts[:1]])
    sl.draw.lines(b, np.hstack([ring[:-1], ring[1:]]), color="red")
    assert (a.to_array() == b.to_array()).all()


# -- colors: translucency blends once, per-polyline colors --------------------------------

def test_translucent_stroke_blends_each_pixel_once():
    fb = sl.FrameBuffer(60, 60, mode="RGB", background="white")
    t = np.arange(5) * 4 * np.pi / 5
    star = np.stack([30 + 25 * np.cos(t), 30 + 25 * np.sin(t)], axis=1)
    sl.draw.polyline(fb, star, color=(0, 0, 255, 128), closed=True, width=5, join="round")
    a = fb.to_array().reshape(-1, 3)
    values = {tuple(v) for v in a.tolist()}
    assert values == {(255, 255, 255), (127, 127, 255)}


def test_translucent_width_one_polyline_blends_vertex_once():
    fb = sl.FrameBuffer(10, 10, mode="L", background=0)
    sl.draw.polyline(fb, [(1, 1), (8, 1), (8, 8), (1, 1)], color=(255, 255, 255, 128))
    assert set(np.unique(fb.to_array()).tolist()) == {0, 128}


def test_one_color_per_polyline():
    fb = sl.FrameBuffer(20, 10, mode="RGB")
    sl.draw.polylines(fb, [[(2, 2), (17, 2)], [(2, 7), (17, 7)]], color=["red", "blue"],
                      width=3)
    assert fb.get_pixel(5, 2) == (255, 0, 0)
    assert fb.get_pixel(5, 7) == (0, 0, 255)
    flat = np.array([(2, 2), (17, 2), (2, 7), (17, 7)], float)
    fb2 = sl.FrameBuffer(20, 10, mode="RGB")
    sl.draw.polylines(fb2, flat, color=["red", "blue"], counts=[2, 2], width=3)
    assert (fb.to_array() == fb2.to_array()).all()


def test_batch_equals_one_by_one():
    rng = np.random.default_rng(8)
    polys = [rng.uniform(-10, 70, (int(rng.integers(1, 7)), 2)) for _ in range(25)]
    closed = rng.random(25) < 0.3
    for kw in (dict(width=4.5, join="round", cap="round"), dict(width=3, cap="square"),
               dict(width=6, join="bevel", dash=(7, 3))):
        a = sl.FrameBuffer(64, 64, mode="1")
        b = sl.FrameBuffer(64, 64, mode="1")
        sl.draw.polylines(a, polys, color=1, closed=closed, **kw)
        for p, c in zip(polys, closed):
            sl.draw.polyline(b, p, color=1, closed=bool(c), **kw)
        assert lit(a) == lit(b)


def test_lines_batch_with_attributes_equals_line():
    segs = np.array([[2, 3, 30, 20], [5, 25, 28, 4], [10, 10, 10, 10]], float)
    a = sl.FrameBuffer(32, 32, mode="1")
    b = sl.FrameBuffer(32, 32, mode="1")
    sl.draw.lines(a, segs, color=1, width=4, cap="round")
    for s in segs:
        sl.draw.line(b, *s, color=1, width=4, cap="round")
    assert lit(a) == lit(b)


def test_style_object_and_keyword_override():
    style = sl.LineStyle(width=5, cap="round", join="bevel")
    a = sl.FrameBuffer(40, 30, mode="1")
    b = sl.FrameBuffer(40, 30, mode="1")
    sl.draw.polyline(a, [(5, 5), (30, 10), (10, 25)], color=1, style=style, cap="butt")
    sl.draw.polyline(b, [(5, 5), (30, 10), (10, 25)], color=1, width=5, join="bevel")
    assert lit(a) == lit(b)


def test_styles_pickle_and_copy_as_themselves():
    import copy
    import pickle

    pen = np.array([[0, 1, 0], [1, 1, 1], [0, 1, 0]], bool)
    for style in (sl.LineStyle(), sl.LineStyle(width=5, cap="round", join="bevel",
                                               miter_limit=3, dash=(6, 3), dash_phase=2.5),
                  sl.LineStyle(dash="dash-dot"), sl.LineStyle(pen=pen)):
        back = pickle.loads(pickle.dumps(style))
        assert back == style and repr(back) == repr(style)
        assert copy.deepcopy(style) == style
        a = sl.FrameBuffer(40, 30, mode="1")
        b = sl.FrameBuffer(40, 30, mode="1")
        sl.draw.polyline(a, [(5, 5), (30, 10), (10, 25)], color=1, style=style)
        sl.draw.polyline(b, [(5, 5), (30, 10), (10, 25)], color=1, style=back)
        assert lit(a) == lit(b)
    with pytest.raises(AttributeError, match="immutable"):
        back.width = 3


def test_every_mode():
    for mode in ("1", "L", "RGB", "RGBA", "P"):
        fb = sl.FrameBuffer(20, 12, mode=mode)
        sl.draw.polyline(fb, [(2, 2), (17, 9)], color="white", width=3, cap="round")
        assert len(lit(fb)) > 40


# -- antialiasing ---------------------------------------------------------------------------

def test_antialiased_thick_line_intensity_is_its_area():
    fb = sl.FrameBuffer(200, 120, mode="L")
    sl.draw.line(fb, 10.3, 20.7, 185.2, 97.9, color=255, width=6, antialias=True)
    total = fb.to_array().astype(float).sum() / 255
    length = np.hypot(185.2 - 10.3, 97.9 - 20.7)
    assert total == pytest.approx(length * 6, rel=0.02)
    values = np.unique(fb.to_array())
    assert len(values) > 10          # graded edges, not a hard mask


def test_antialiased_width_one_line_intensity_is_its_length():
    fb = sl.FrameBuffer(200, 120, mode="L")
    sl.draw.polyline(fb, [(10.5, 20.25), (185.5, 97.75), (20, 110)], color=255,
                     antialias=True)
    total = fb.to_array().astype(float).sum() / 255
    # antialias.lines spreads intensity so that a segment sums to its length
    length = np.hypot(175, 77.5) + np.hypot(165.5, 12.25)
    assert total == pytest.approx(length, rel=0.02)


def test_antialiased_dashed_circle_is_lighter_than_solid():
    a = sl.FrameBuffer(80, 80, mode="L")
    b = sl.FrameBuffer(80, 80, mode="L")
    sl.draw.circle(a, 40, 40, 30, color=255, width=3, antialias=True)
    sl.draw.circle(b, 40, 40, 30, color=255, width=3, antialias=True, dash=(10, 10))
    sa = a.to_array().astype(float).sum() / 255
    sb = b.to_array().astype(float).sum() / 255
    assert sa == pytest.approx(2 * np.pi * 30 * 3, rel=0.02)
    assert sb == pytest.approx(sa / 2, rel=0.05)


def test_translucent_colors_per_circle():
    # one translucent and one opaque color, as specs and as an RGBA array
    for color in (["#ff000080", "blue"], np.array([[255, 0, 0, 128], [0, 0, 255, 255]])):
        fb = sl.FrameBuffer(40, 40, mode="RGB", background="white")
        sl.draw.circles(fb, [[20, 20, 10], [20, 20, 15]], color=color, dash="dashed")
        values = {tuple(v) for v in fb.to_array().reshape(-1, 3).tolist()}
        assert values == {(255, 255, 255), (255, 127, 127), (0, 0, 255)}
        assert fb.get_pixel(30, 20) == (255, 127, 127)     # (xc + r, yc): pixel 0, on
        assert fb.get_pixel(35, 20) == (0, 0, 255)


def test_translucent_batch_composites_each_polyline():
    # two crossing strokes of one translucent color: where they cross, the second
    # is composited over the first, as when they are drawn one by one
    polys = [[(5, 20), (55, 20)], [(30, 2), (30, 38)]]
    for kw in (dict(width=5), dict(), dict(width=4, dash=(6, 2))):
        a = sl.FrameBuffer(60, 40, mode="RGB", background="white")
        b = sl.FrameBuffer(60, 40, mode="RGB", background="white")
        sl.draw.polylines(a, polys, color="#0000ff80", **kw)
        for p in polys:
            sl.draw.polyline(b, p, color="#0000ff80", **kw)
        assert (a.to_array() == b.to_array()).all()
        assert a.get_pixel(30, 20) == (63, 63, 255)
