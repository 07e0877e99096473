"""sl.draw.circle(s) and sl.draw.ellipse(s): the notes' examples, references,
invariants, peers (scikit-image, OpenCV), clipping of huge circles, batches, modes.
"""

import math

import cv2
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from skimage.draw import circle_perimeter, ellipse_perimeter

import scanline as sl
from tests.reference import (
    HYPOTHESIS,
    MODES,
    circle_octant,
    circle_pixels,
    circle_visible,
    circle_y,
    eight_connected,
    ellipse_pixels,
    ellipse_quadrant,
    in_frame,
    lit,
    mirror4,
    mirror8,
)


def drawn_circle(xc, yc, r, width, height, mode="L"):
    fb = sl.FrameBuffer(width, height, mode=mode)
    sl.draw.circle(fb, xc, yc, r, color="white")
    return lit(fb)


def drawn_ellipse(xc, yc, rx, ry, width, height, mode="L"):
    fb = sl.FrameBuffer(width, height, mode=mode)
    sl.draw.ellipse(fb, xc, yc, rx, ry, color="white")
    return lit(fb)


def whole_circle(r, margin=2):
    """Draw a circle whole on a frame buffer big enough; pixels relative to the center."""
    c = r + margin
    return {(x - c, y - c) for x, y in drawn_circle(c, c, r, 2 * c + 1, 2 * c + 1)}


def whole_ellipse(rx, ry, margin=2):
    cx, cy = rx + margin, ry + margin
    return {(x - cx, y - cy) for x, y in drawn_ellipse(cx, cy, rx, ry, 2 * cx + 1, 2 * cy + 1)}


def text(fb):
    return sl.text_image(fb, on="#", off=".").splitlines()


def hausdorff(a, b):
    """Chebyshev Hausdorff distance between two non-empty pixel sets."""
    A, B = np.array(sorted(a)), np.array(sorted(b))
    d = np.abs(A[:, None, :] - B[None, :, :]).max(axis=2)
    return int(max(d.min(axis=1).max(), d.min(axis=0).max()))


# == midpoint circle ===========================================================================
NOTES_R10 = [(0, 10), (1, 10), (2, 10), (3, 10), (4, 9), (5, 9), (6, 8), (7, 7)]


def test_notes_circle_r10():
    # notes, chapter 2, Q.5 (checked by hand: p = -9, -6, -1, 6, -3, 8, 5)
    assert circle_octant(10) == (NOTES_R10, [-9, -6, -1, 6, -3, 8, 5, 6])
    fb = sl.FrameBuffer(25, 25, mode="1")
    sl.draw.circle(fb, 12, 12, 10)
    assert lit(fb) == mirror8(NOTES_R10, 12, 12)
    assert len(lit(fb)) == 8 * 8 - 8  # (0,10) and (7,7) have 4 images each, the rest 8


def test_small_circles_by_hand():
    assert drawn_circle(2, 2, 0, 5, 5) == {(2, 2)}
    # r = 1: p0 = 0 -> y steps at x = 1, past the diagonal: octant (0, 1) only
    assert drawn_circle(2, 2, 1, 5, 5) == {(2, 3), (2, 1), (1, 2), (3, 2)}
    # r = 2: p0 = -1 keeps y: (1, 2); then p = 2 steps past the diagonal
    assert whole_circle(2) == mirror8([(0, 2), (1, 2)])
    # r = 3: p0 = -2: (1, 3), p = 1: (2, 2)
    fb = sl.FrameBuffer(7, 7, mode="1")
    sl.draw.circle(fb, 3, 3, 3)
    assert text(fb) == ["..###..", ".#...#.", "#.....#", "#.....#", "#.....#", ".#...#.", "..###.."]


def test_circle_center_and_radius_are_rounded():
    assert drawn_circle(2.4, 2.5, 1.49, 6, 6) == {(2, 4), (2, 2), (1, 3), (3, 3)}
    assert drawn_circle(2, 2, 0.5, 5, 5) == {(2, 3), (2, 1), (1, 2), (3, 2)}  # 0.5 -> 1
    assert drawn_circle(2, 2, 0.49, 5, 5) == {(2, 2)}


def test_circle_equals_reference_for_r_0_to_300():
    rng = np.random.default_rng(20)
    for r in range(0, 301):
        size = 2 * r + 7
        xc, yc = rng.integers(r, size - r, 2).tolist()  # whole circle visible
        assert drawn_circle(xc, yc, r, size, size) == circle_pixels(xc, yc, r), r


def test_closed_form_equals_the_notes_iteration_up_to_r_2000():
    """The closed form used for huge circles, y(x) = floor((isqrt(4(r^2-x^2)-1)+1)/2),
    gives exactly the y of the notes' iteration at every x of the octant."""
    for r in range(0, 2001):
        pts, _ = circle_octant(r)
        assert pts == [(x, circle_y(x, r)) for x in range(len(pts))]
        n = len(pts)
        assert circle_y(n, r) < n  # the octant ends where the closed form says


def test_circle_invariants():
    for r in range(0, 160):
        px = whole_circle(r)
        # 8-fold symmetry
        for f in (lambda x, y: (-x, y), lambda x, y: (x, -y), lambda x, y: (y, x)):
            assert {f(*p) for p in px} == px
        assert eight_connected(px)
        # each pixel is less than half a pixel from the circle:
        # (r - 1/2)^2 < x^2 + y^2 < (r + 1/2)^2, in integers
        for x, y in px:
            d2 = 4 * (x * x + y * y)
            assert (2 * r - 1) ** 2 < d2 < (2 * r + 1) ** 2 or r == 0
        # one pixel per column in the octant x <= y (the octant is a function of x)
        octant = sorted(p for p in px if 0 <= p[0] <= p[1])
        assert [p[0] for p in octant] == list(range(len(octant)))
        # extreme points
        assert {(r, 0), (-r, 0), (0, r), (0, -r)} <= px
        assert max(abs(x) for x, _ in px) == r
    assert whole_circle(0) == {(0, 0)}


def test_skimage_circle_perimeter_bresenham_agrees_exactly():
    """skimage.draw.circle_perimeter(method='bresenham') draws the same pixels as the
    notes' midpoint circle for every r in 0..300 (its decision parameter differs by a
    constant that never changes a decision)."""
    for r in range(0, 301):
        c = r + 1
        rr, cc = circle_perimeter(c, c, r, method="bresenham")
        theirs = set(zip((np.atleast_1d(cc) - c).tolist(), (np.atleast_1d(rr) - c).tolist()))
        assert whole_circle(r) == theirs, r


def test_opencv_circle_differs_but_stays_within_one_pixel():
    """cv2.circle (thickness 1, LINE_8) uses its own algorithm: for r in 1..100 it
    matches the midpoint circle only for r = 1 (and 0); about as many pixels differ as
    the circles have; every pixel of either is within one pixel (Chebyshev) of the
    other, and OpenCV's pixels lie up to ~1.0 from the true circle where scanline's
    lie within 0.5."""
    same = 0
    worst_cv = 0.0
    for r in range(0, 101):
        img = np.zeros((2 * r + 3, 2 * r + 3), np.uint8)
        cv2.circle(img, (r + 1, r + 1), r, 255, 1, cv2.LINE_8)
        rr, cc = np.nonzero(img)
        theirs = {(c - r - 1, q - r - 1) for q, c in zip(rr.tolist(), cc.tolist())}
        ours = whole_circle(r)
        same += theirs == ours
        assert hausdorff(ours, theirs) <= 1
        worst_cv = max(worst_cv, max(abs(math.hypot(x, y) - r) for x, y in theirs))
    assert same <= 5
    assert worst_cv > 0.5


# -- huge and partly visible circles ---------------------------------------------------------------
def test_circle_clipping_against_the_big_frame_buffer():
    rng = np.random.default_rng(21)
    W, H = 40, 30
    for _ in range(400):
        r = int(rng.integers(0, 80))
        xc, yc = rng.integers(-100, 140, 2).tolist()
        big = 400
        whole = drawn_circle(xc + 150, yc + 150, r, big, big)
        expected = in_frame({(x - 150, y - 150) for x, y in whole}, W, H)
        assert drawn_circle(xc, yc, r, W, H) == expected
        assert expected == circle_visible(xc, yc, r, W, H)


def _crossing_circles(rng, n, W, H):
    """Circles whose boundary passes near the frame: pick a point near the frame and
    a direction, put the center r away from it."""
    out = []
    limit = 2**30
    for _ in range(n):
        r = int(math.exp(rng.uniform(0, math.log(limit))))
        r = min(r, limit)
        px, py = rng.uniform(-3, W + 3), rng.uniform(-3, H + 3)
        t = rng.uniform(0, 2 * math.pi)
        xc = int(round(px - r * math.cos(t)))
        yc = int(round(py - r * math.sin(t)))
        out.append((max(-limit, min(limit, xc)), max(-limit, min(limit, yc)), r))
    return out


def test_huge_circles_partly_visible_equal_the_reference():
    rng = np.random.default_rng(22)
    W, H = 64, 48
    cases = _crossing_circles(rng, 1500, W, H)
    # circles along an edge, tangent, through corners, center inside with huge r
    for r in (10**6, 10**9, 2**30 - W - 1):
        cases += [(-r, 20, r), (W - 1 + r, 20, r), (30, -r, r), (30, H - 1 + r, r),
                  (-r + 1, 20, r), (W + r, 20, r), (30, 30, r), (0, 0, r), (W - 1, H - 1, r)]
    cases += [(-2**30, 20, 2**30), (20, -2**30, 2**30), (2**30, 2**30, 2**30), (-2**30, -2**30, 2**30)]
    drew = 0
    for xc, yc, r in cases:
        got = drawn_circle(xc, yc, r, W, H)
        assert got == circle_visible(xc, yc, r, W, H), (xc, yc, r)
        drew += bool(got)
    assert drew > 1000  # most of them cross the frame


@given(st.integers(-2**30, 2**30), st.integers(-2**30, 2**30), st.integers(0, 2**30))
@HYPOTHESIS
def test_any_circle_equals_the_reference_hypothesis(xc, yc, r):
    assert drawn_circle(xc, yc, r, 32, 24) == circle_visible(xc, yc, r, 32, 24)


@given(st.integers(-40, 80), st.integers(-40, 80), st.integers(0, 2**30),
       st.sampled_from(["x", "y", "xy"]))
@HYPOTHESIS
def test_huge_circles_grazing_the_frame_hypothesis(px, py, r, axis):
    # centers exactly r away from a pixel near the frame, along an axis or a diagonal
    if axis == "x":
        xc, yc = px - r, py
    elif axis == "y":
        xc, yc = px, py - r
    else:
        d = int(r / math.sqrt(2))
        xc, yc = px - d, py - d
    xc = max(-2**30, min(2**30, xc))
    yc = max(-2**30, min(2**30, yc))
    assert drawn_circle(xc, yc, r, 40, 40) == circle_visible(xc, yc, r, 40, 40)


# == midpoint ellipse ===========================================================================
NOTES_8_6 = [(0, 6), (1, 6), (2, 6), (3, 6), (4, 5), (5, 5), (6, 4), (7, 3), (8, 2), (8, 1), (8, 0)]


def test_notes_ellipse_8_6():
    # notes, chapter 2, Q.6 (by hand: region 1 p = -332, -224, -44, 208, -108, 288, 244;
    # region 2 starts at (7, 3) with p2_0 = -23, then 361, 297 - the notes print -215 and
    # -279 there, but the points (8,2), (8,1), (8,0) are right)
    rows = ellipse_quadrant(8, 6)
    assert [r[1] for r in rows] == [-332, -224, -44, 208, -108, 288, 244, -23, 361, 297]
    assert [(0, 6)] + [(r[2], r[3]) for r in rows] == NOTES_8_6
    fb = sl.FrameBuffer(21, 17, mode="1")
    sl.draw.ellipse(fb, 10, 8, 8, 6)
    assert lit(fb) == mirror4(NOTES_8_6, 10, 8)


def test_small_ellipses_by_hand():
    # rx = 4, ry = 2: p1 = -24 -> (1,2); -12 -> (2,2); 8 -> (3,1); 4 -> (4,0)
    fb = sl.FrameBuffer(9, 5, mode="1")
    sl.draw.ellipse(fb, 4, 2, 4, 2)
    assert text(fb) == ["..#####..", ".#.....#.", "#.......#", ".#.....#.", "..#####.."]
    # degenerate ellipses: segments, and the center pixel
    assert drawn_ellipse(3, 2, 3, 0, 7, 5) == {(x, 2) for x in range(7)}
    assert drawn_ellipse(3, 2, 0, 2, 7, 5) == {(3, y) for y in range(5)}
    assert drawn_ellipse(3, 2, 0, 0, 7, 5) == {(3, 2)}


def test_flat_ellipse_tip_by_hand():
    # rx = 6, ry = 1: region 1 from (0,1), p1 = 1 - 36 + 9 = -26; -26+2+1 = -23 (1,1);
    # -23+4+1 = -18 (2,1); -18+6+1 = -11 (3,1); -11+8+1 = -2 (4,1); p = -2 < 0 -> (5,1),
    # p = -2+10+1 = 9; 2ry^2x = 10 < 2rx^2y = 72 -> p >= 0: (6,0).  No tip needed.
    assert [(r[0], r[2], r[3]) for r in ellipse_quadrant(6, 1)] == [
        ("1", 1, 1), ("1", 2, 1), ("1", 3, 1), ("1", 4, 1), ("1", 5, 1), ("1", 6, 0)]
    # rx = 10, ry = 1: p1 = 1 - 100 + 25 = -74; after x = 1..8 p = -74 + 3+5+...+17 = 6;
    # so (8,1) is followed by (9,0) with y = 0 - region 1 ends at x = 9 < rx: the tip
    # adds (10, 0)
    rows = ellipse_quadrant(10, 1)
    assert [(r[0], r[2], r[3]) for r in rows][-3:] == [("1", 8, 1), ("1", 9, 0), ("tip", 10, 0)]
    assert whole_ellipse(10, 1) == mirror4([(0, 1)] + [(r[2], r[3]) for r in rows])
    assert {(10, 0), (-10, 0)} <= whole_ellipse(10, 1)


def test_ellipse_equals_the_exact_reference():
    cases = [(rx, ry) for rx in range(0, 41) for ry in range(0, 41)]
    rng = np.random.default_rng(23)
    cases += [tuple(rng.integers(0, 300, 2).tolist()) for _ in range(120)]
    cases += [(200, 1), (1, 200), (300, 2), (2, 300), (150, 149), (149, 150), (250, 5), (7, 260)]
    for rx, ry in cases:
        assert whole_ellipse(rx, ry) == ellipse_pixels(0, 0, rx, ry), (rx, ry)


def test_when_the_tip_completes_a_flat_ellipse():
    """Observed: the notes' regions stop short of (rx, 0) - and scanline adds the tip -
    exactly when ry = 0 < rx or rx >= 8 ry^2 (checked for ry <= 6, rx <= 400), in the
    reference and in scanline's step table alike."""
    for ry in range(0, 7):
        for rx in range(0, 401):
            expected = (ry == 0 < rx) or (ry > 0 and rx >= 8 * ry * ry)
            assert any(r[0] == "tip" for r in ellipse_quadrant(rx, ry)) == expected, (rx, ry)
            rows = sl.trace.midpoint_ellipse(rx, ry).rows
            assert any(r["region"] == "tip" for r in rows) == expected, (rx, ry)
    assert not any(r[0] == "tip" for rx in range(41) for ry in range(7, 41) for r in ellipse_quadrant(rx, ry))


def test_ellipse_with_equal_radii_is_the_midpoint_circle():
    """For rx = ry = r the notes' ellipse reduces to the circle (all its decision
    parameters are r^2 times the circle's) - identical pixels for r in 0..200."""
    for r in range(0, 201):
        assert whole_ellipse(r, r) == whole_circle(r), r


def test_ellipse_invariants():
    rng = np.random.default_rng(24)
    cases = [(rx, ry) for rx in range(0, 25) for ry in range(0, 25)]
    cases += [tuple(rng.integers(0, 200, 2).tolist()) for _ in range(60)]
    for rx, ry in cases:
        px = whole_ellipse(rx, ry)
        # 4-fold symmetry
        assert {(-x, y) for x, y in px} == px
        assert {(x, -y) for x, y in px} == px
        # bounding box exactly [-rx, rx] x [-ry, ry], touched at the axes' ends
        assert min(x for x, _ in px) == -rx and max(x for x, _ in px) == rx
        assert min(y for _, y in px) == -ry and max(y for _, y in px) == ry
        assert {(rx, 0), (-rx, 0), (0, ry), (0, -ry)} <= px
        assert eight_connected(px)
        # transposing the radii transposes the picture only up to ties; but the ellipse
        # stays within one pixel of its transpose
        if rx and ry and rx != ry:
            t = {(y, x) for x, y in whole_ellipse(ry, rx)}
            assert hausdorff(px, t) <= 1


def test_skimage_ellipse_perimeter_differences():
    """skimage.draw.ellipse_perimeter uses a different algorithm.  Over rx, ry in
    0..40 it agrees exactly for about 70 % of the ellipses; the differing pixels
    (symmetric difference) are about 3.4 % of scanline's pixels, mostly on thin
    ellipses, and every pixel of either is within one
    pixel (Chebyshev) of the other.  E.g. rx=10, ry=1: scikit-image (+-8, 0), scanline
    and the notes (+-8, +-1) - the true ellipse is at y = 0.6 there."""
    same = total = diff = 0
    for rx in range(0, 41):
        for ry in range(0, 41):
            rr, cc = ellipse_perimeter(100, 100, ry, rx)
            theirs = set(zip((np.atleast_1d(cc) - 100).tolist(), (np.atleast_1d(rr) - 100).tolist()))
            ours = whole_ellipse(rx, ry)
            assert hausdorff(ours, theirs) <= 1, (rx, ry)
            same += ours == theirs
            total += len(ours)
            diff += len(ours ^ theirs)
    assert same > 0.6 * 41 * 41
    assert diff < 0.05 * total
    rr, cc = ellipse_perimeter(100, 100, 1, 10)
    theirs = set(zip((cc - 100).tolist(), (rr - 100).tolist()))
    assert (8, 0) in theirs and (8, 1) not in theirs
    assert (8, 1) in whole_ellipse(10, 1) and (8, 0) not in whole_ellipse(10, 1)


def test_ellipse_clipping_equals_the_reference_restricted_to_the_frame():
    rng = np.random.default_rng(25)
    W, H = 40, 30
    for _ in range(300):
        rx, ry = rng.integers(0, 120, 2).tolist()
        xc, yc = rng.integers(-130, 170, 2).tolist()
        assert drawn_ellipse(xc, yc, rx, ry, W, H) == in_frame(ellipse_pixels(xc, yc, rx, ry), W, H)
    # large flat ellipses far off-center
    for xc, yc, rx, ry in [(-20000, 15, 20010, 3), (20050, 5, 20000, 7), (20, -4000, 9, 4010),
                           (10, 10, 30000, 2), (-29990, 40, 30000, 40)]:
        assert drawn_ellipse(xc, yc, rx, ry, W, H) == in_frame(ellipse_pixels(xc, yc, rx, ry), W, H)


def test_ellipse_far_outside_draws_nothing():
    for xc, yc, rx, ry in [(-100, 10, 99, 5), (10, 10**9, 5, 10**6), (2**30, 2**30, 2**20, 2**9),
                           (-2**30, 0, 2**24, 1)]:
        assert drawn_ellipse(xc, yc, rx, ry, 32, 32) == set()


def _near_the_ellipse(px, xc, yc, rx, ry):
    """Every pixel within one pixel of the true ellipse in y (y-major parts: in x)."""
    for x, y in px:
        X, Y = x - xc, y - yc
        true_y = ry * math.sqrt(max(0.0, 1 - (X / rx) ** 2))
        true_x = rx * math.sqrt(max(0.0, 1 - (Y / ry) ** 2))
        assert abs(abs(Y) - true_y) <= 1.0 or abs(abs(X) - true_x) <= 1.0


def test_largest_allowed_ellipses_draw_the_right_visible_part():
    # rx * ry = 2**29: the decision parameters must stay exact.  The visible part near
    # (xc + rx, yc) of a very flat ellipse: compare with the closed-form band
    # |x^2/rx^2 + y^2/ry^2 - 1| test computed exactly for the pixels drawn.
    rx, ry = 2**24, 32
    fb = sl.FrameBuffer(64, 64, mode="L")
    sl.draw.ellipse(fb, 32 - rx, 32, rx, ry, color="white")
    px = lit(fb)
    assert (32, 32) in px  # the right end (xc + rx, yc)
    assert {(x, y) for x, y in px if x == 32} == {(32, 32)}
    assert {(x, 2 * 32 - y) for x, y in px} == px  # symmetric about y = yc
    _near_the_ellipse(px, 32 - rx, 32, rx, ry)
    # beyond the limits the same rule is computed in Python integers (issue 11;
    # tests/hardening/test_far_conics.py compares it with the full midpoint loop)
    for xc, yc, a, b in [(0, 0, 2**24 + 1, 1), (0, 5 - (2**14 + 1), 2**15, 2**14 + 1)]:
        beyond = sl.FrameBuffer(64, 64, mode="L")
        sl.draw.ellipse(beyond, xc, yc, a, b)
        assert lit(beyond)
        _near_the_ellipse(lit(beyond), xc, yc, a, b)
    # the frame inside the ring's hole: nothing to draw
    before = lit(fb)
    sl.draw.ellipse(fb, 0, 0, 2**15, 2**14 + 1)
    assert lit(fb) == before


# == batches, modes, colors =====================================================================
@pytest.mark.parametrize("mode", MODES)
def test_every_mode_draws_the_same_conics(mode):
    rng = np.random.default_rng(26)
    kw = {"color_table": ["black", "white"]} if mode == "P" else {}
    for _ in range(25):
        xc, yc = rng.integers(-20, 60, 2).tolist()
        r, rx, ry = rng.integers(0, 40, 3).tolist()
        fb = sl.FrameBuffer(43, 37, mode=mode, **kw)
        sl.draw.circle(fb, xc, yc, r, color="white")
        assert lit(fb) == in_frame(circle_pixels(xc, yc, r), 43, 37)
        fb = sl.FrameBuffer(43, 37, mode=mode, **kw)
        sl.draw.ellipse(fb, xc, yc, rx, ry, color="white")
        assert lit(fb) == in_frame(ellipse_pixels(xc, yc, rx, ry), 43, 37)


@pytest.mark.parametrize("mode", MODES)
def test_batch_circles_and_ellipses_equal_loops(mode):
    rng = np.random.default_rng(27)
    kw = {"color_table": ["black", "white", "red", "blue"]} if mode == "P" else {}
    W, H = 50, 40
    circles = np.column_stack([rng.integers(-30, 80, 200), rng.integers(-30, 70, 200), rng.integers(0, 60, 200)])
    circles[::9, 2] *= 10**6
    ellipses = np.column_stack([rng.integers(-30, 80, 200), rng.integers(-30, 70, 200),
                                rng.integers(0, 60, 200), rng.integers(0, 60, 200)])
    colors = ["white", "red", "blue"] * 66 + ["white", "red"]
    for batch, single, data in [(sl.draw.circles, sl.draw.circle, circles),
                                (sl.draw.ellipses, sl.draw.ellipse, ellipses)]:
        for color in ("white", colors):
            a = sl.FrameBuffer(W, H, mode=mode, **kw)
            b = sl.FrameBuffer(W, H, mode=mode, **kw)
            batch(a, data, color=color)
            for i, row in enumerate(data.tolist()):
                single(b, *row, color=color if isinstance(color, str) else color[i])
            assert np.array_equal(a.to_array(), b.to_array())
        # float rows are rounded like the scalar arguments
        c = sl.FrameBuffer(W, H, mode=mode, **kw)
        batch(c, data + 0.25, color="white")
        d = sl.FrameBuffer(W, H, mode=mode, **kw)
        batch(d, data, color="white")
        assert np.array_equal(c.to_array(), d.to_array())


def test_batch_per_primitive_colors_values():
    fb = sl.FrameBuffer(30, 10, mode="RGB")
    sl.draw.circles(fb, [(4, 4, 3), (15, 4, 3)], color=np.array([[255, 0, 0], [0, 0, 255]]))
    assert fb.get_pixel(4, 7) == (255, 0, 0) and fb.get_pixel(15, 7) == (0, 0, 255)
    sl.draw.ellipses(fb, [(25, 4, 3, 2)], color=["#00ff00"])
    assert fb.get_pixel(25, 6) == (0, 255, 0) and fb.get_pixel(25, 4) == (0, 0, 0)


def test_empty_batches_draw_nothing():
    fb = sl.FrameBuffer(5, 5)
    sl.draw.circles(fb, np.zeros((0, 3)))
    sl.draw.ellipses(fb, np.zeros((0, 4)))
    assert not fb.to_array().any()


@pytest.mark.parametrize("rows", [
    np.array([(4, 4, 3), (15, 4, -2)]),                 # integers in the exact range
    np.array([(4, 4, 3), (15, 4, -2)], np.int32),
    [(4, 4, 3), (15, 4, -2)],
    np.array([(4, 4, 3), (15, 4, -2.0)]),               # floats: converted first
    np.array([(4, 4, 3), (15, 2**40, -2)]),             # beyond the exact range
    np.concatenate([np.tile([(4, 4, 3)], (300_000, 1)), [(15, 4, -2)]]),  # split between cores
])
def test_a_negative_radius_is_refused_naming_its_row(rows):
    fb = sl.FrameBuffer(30, 10)
    with pytest.raises(sl.ArgumentValueError, match=r"circles column 2 holds radii.*row (1|300000)"):
        sl.draw.circles(fb, rows)
    assert not fb.to_array().any()
