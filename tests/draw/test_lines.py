"""sl.draw.line / sl.draw.lines: exact tiny images, invariants, cross-checks, clipping.

Expected pixels come from hand computation (the notes' formulas), from the slow
references in tests/reference.py, or from scikit-image / OpenCV.
"""

import math

import cv2
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from skimage.draw import line as sk_line

import scanline as sl
from tests.reference import (
    HYPOTHESIS,
    MODES,
    bresenham,
    bresenham_minor,
    bresenham_pixels,
    bresenham_visible,
    dda,
    eight_connected,
    exact_line,
    in_frame,
    lit,
    tie_steps,
)

METHODS = ("bresenham", "dda")
W = H = 64


def drawn(x0, y0, x1, y1, method="bresenham", width=W, height=H, mode="L"):
    fb = sl.FrameBuffer(width, height, mode=mode)
    sl.draw.line(fb, x0, y0, x1, y1, color="white", method=method)
    return lit(fb)


def text(fb):
    return sl.text_image(fb, on="#", off=".").splitlines()


def random_segments(n, lo, hi, seed):
    rng = np.random.default_rng(seed)
    return rng.integers(lo, hi, (n, 4)).tolist()


# -- exact tiny images, derived by hand ----------------------------------------------------
def test_gentle_slope_by_hand():
    # dx = 5, dy = 2, p0 = 2*2 - 5 = -1: keep (1,0); p = -1+4 = 3: step (2,1);
    # p = 3-6 = -3: keep (3,1); p = -3+4 = 1: step (4,2); p = 1-6 = -5: keep (5,2)
    fb = sl.FrameBuffer(6, 3, mode="1")
    sl.draw.line(fb, 0, 0, 5, 2)
    assert text(fb) == ["....##", "..##..", "##...."]


def test_steep_negative_slope_by_hand():
    # y major, start at the lower endpoint (3, 0); du = 4, dw = 2, x moves by -1.
    # p0 = 4-4 = 0 (>= 0: step) -> (2,1); p = 0+4-8 = -4 -> (2,2); p = 0 -> (1,3);
    # p = -4 -> (1,4)
    fb = sl.FrameBuffer(5, 5, mode="1")
    sl.draw.line(fb, 1, 4, 3, 0)
    assert text(fb) == [".#...", ".#...", "..#..", "..#..", "...#."]


@pytest.mark.parametrize("method", METHODS)
def test_horizontal_vertical_diagonal_and_point(method):
    fb = sl.FrameBuffer(5, 4, mode="1")
    sl.draw.line(fb, 4, 3, 0, 3, method=method)  # horizontal, right to left
    sl.draw.line(fb, 0, 0, 0, 2, method=method)  # vertical
    sl.draw.line(fb, 1, 0, 3, 2, method=method)  # diagonal
    sl.draw.line(fb, 4, 0, 4, 0, method=method)  # a point
    assert text(fb) == ["#####", "#..#.", "#.#..", "##..#"]


def test_bresenham_tie_rule_by_hand():
    # (0,0)-(2,1): at x = 1 the line is at y = 0.5 exactly; p1 = 2*1 - 2 = 0 is not < 0,
    # so y steps (away from the left endpoint): (1, 1).  The order of the endpoints
    # does not matter.
    for seg in [(0, 0, 2, 1), (2, 1, 0, 0)]:
        assert drawn(*seg, width=3, height=2) == {(0, 0), (1, 1), (2, 1)}
    # (0,1)-(2,0): start at the left endpoint (0,1), y moves down; the tie steps too
    for seg in [(0, 1, 2, 0), (2, 0, 0, 1)]:
        assert drawn(*seg, width=3, height=2) == {(0, 1), (1, 0), (2, 0)}
    # y major: (0,0)-(1,2) starts at the lower endpoint; tie at y = 1 steps x: (1, 1)
    for seg in [(0, 0, 1, 2), (1, 2, 0, 0)]:
        assert drawn(*seg, width=2, height=3) == {(0, 0), (1, 1), (1, 2)}
    # (1,0)-(0,2): lower endpoint (1,0), x moves left; tie steps: (0, 1)
    for seg in [(1, 0, 0, 2), (0, 2, 1, 0)]:
        assert drawn(*seg, width=2, height=3) == {(1, 0), (0, 1), (0, 2)}


def test_dda_by_hand():
    # (0,0)-(4,2): y += 0.5: 0, 0.5, 1, 1.5, 2 -> rounded half up 0, 1, 1, 2, 2
    assert drawn(0, 0, 4, 2, "dda") == {(0, 0), (1, 1), (2, 1), (3, 2), (4, 2)}
    # (0,1)-(2,0): y = 1, 0.5, 0 -> 1, 1, 0: the DDA rounds the tie up where
    # Bresenham (starting at (0, 1) and stepping down on the tie) takes (1, 0)
    assert drawn(0, 1, 2, 0, "dda") == {(0, 1), (1, 1), (2, 0)}
    assert drawn(0, 1, 2, 0, "bresenham") == {(0, 1), (1, 0), (2, 0)}
    # (0,0)-(3,1) by the DDA: y = 0, 1/3, 2/3, 1 -> 0, 0, 1, 1
    assert drawn(0, 0, 3, 1, "dda") == {(0, 0), (1, 0), (2, 1), (3, 1)}


def test_endpoints_are_rounded_half_up():
    # (0.4, 0.5) -> (0, 1); (4.6, 2.49) -> (5, 2); then (0,1)-(5,2): dx = 5, dy = 1,
    # p0 = 2-5 = -3 (0,1)->(1,1); p=-1 ->(2,1); p=1 -> (3,2); p=-7 -> (4,2); p=-5 -> (5,2)
    assert drawn(0.4, 0.5, 4.6, 2.49) == {(0, 1), (1, 1), (2, 1), (3, 2), (4, 2), (5, 2)}
    assert drawn(-0.5, 0, 2.5, 0) == {(0, 0), (1, 0), (2, 0), (3, 0)}
    assert drawn(np.int32(1), np.float32(1.0), np.int64(3), 1) == {(1, 1), (2, 1), (3, 1)}


def test_notes_example_20_10_to_30_18():
    # notes, chapter 2, Q.3 (checked by hand: p = 6, 2, -2, 14, 10, 6, 2, -2, 14, 10)
    expected = {(20, 10), (21, 11), (22, 12), (23, 12), (24, 13), (25, 14),
                (26, 15), (27, 16), (28, 16), (29, 17), (30, 18)}
    fb = sl.FrameBuffer(40, 30, mode="1")
    sl.draw.line(fb, 20, 10, 30, 18)
    assert lit(fb) == expected
    fb = sl.FrameBuffer(40, 30, mode="1")
    sl.draw.line(fb, 30, 18, 20, 10)
    assert lit(fb) == expected
    # and the reference reproduces the notes' decision parameters
    assert bresenham(20, 10, 30, 18)[1] == [6, 2, -2, 14, 10, 6, 2, -2, 14, 10]


# -- invariants on random lines in all octants --------------------------------------------------
@pytest.mark.parametrize("method", METHODS)
def test_invariants_on_random_lines(method):
    for x0, y0, x1, y1 in random_segments(1500, 0, W, seed=1 if method == "dda" else 2):
        px = drawn(x0, y0, x1, y1, method)
        assert (x0, y0) in px and (x1, y1) in px
        steps = max(abs(x1 - x0), abs(y1 - y0))
        assert len(px) == steps + 1
        # exactly one pixel per step along the major axis
        major = 0 if abs(x1 - x0) >= abs(y1 - y0) else 1
        assert sorted(p[major] for p in px) == list(
            range(min((x0, y0)[major], (x1, y1)[major]), max((x0, y0)[major], (x1, y1)[major]) + 1))
        assert eight_connected(px)
        # within half a pixel of the ideal line, measured along the minor axis
        for x, y in px:
            if steps:
                if major == 0:
                    ideal = y0 + (y1 - y0) * (x - x0) / (x1 - x0)
                    assert abs(y - ideal) <= 0.5 + 1e-9
                else:
                    ideal = x0 + (x1 - x0) * (y - y0) / (y1 - y0)
                    assert abs(x - ideal) <= 0.5 + 1e-9


def test_bresenham_is_independent_of_endpoint_order():
    for x0, y0, x1, y1 in random_segments(1500, 0, W, seed=3):
        assert drawn(x0, y0, x1, y1) == drawn(x1, y1, x0, y0)


def _mirror_segment(seg, f):
    x0, y0, x1, y1 = seg
    a, b = f(x0, y0), f(x1, y1)
    return (*a, *b)


def test_bresenham_symmetries_that_the_tie_rule_keeps():
    """Ties step the minor coordinate away from the left (x major) or lower (y major)
    endpoint.  So transposing (x <-> y) and mirroring the minor axis map the drawn
    pixels onto each other for every line; mirroring the major axis (and the
    180-degree rotation) do so exactly for lines without ties, and at each tie pick
    the other candidate pixel."""
    n = W - 1
    transpose = lambda x, y: (y, x)  # noqa: E731
    flip_x = lambda x, y: (n - x, y)  # noqa: E731
    flip_y = lambda x, y: (x, n - y)  # noqa: E731
    rotate = lambda x, y: (n - x, n - y)  # noqa: E731
    ties_seen = 0
    for seg in random_segments(1200, 0, W, seed=4):
        x0, y0, x1, y1 = seg
        px = drawn(*seg)
        x_major = abs(y1 - y0) <= abs(x1 - x0)
        minor_flip, major_flip = (flip_y, flip_x) if x_major else (flip_x, flip_y)
        if abs(y1 - y0) != abs(x1 - x0):  # transpose swaps the roles of the axes
            assert drawn(*_mirror_segment(seg, transpose)) == {transpose(*p) for p in px}
        assert drawn(*_mirror_segment(seg, minor_flip)) == {minor_flip(*p) for p in px}
        ties = tie_steps(*seg)
        for f in (major_flip, rotate):
            mirrored = drawn(*_mirror_segment(seg, f))
            expected = {f(*p) for p in px}
            if not ties:
                assert mirrored == expected
            else:
                ties_seen += 1
                k = 0 if x_major else 1
                differ = mirrored ^ expected
                # they differ exactly at the (mirrored) tie positions, where each takes
                # the other of the two candidate pixels
                assert {p[k] for p in differ} == {n - t for t in ties}
                assert len(differ) == 2 * len(ties)
                for t in ties:
                    a, b = sorted(p[1 - k] for p in differ if p[k] == n - t)
                    assert b - a == 1
    assert ties_seen > 100


def test_reference_closed_form_equals_the_iteration():
    """The closed form used for the huge-line reference (round half up of i*dw/du)
    is what the notes' iteration computes, for every du, dw up to 60."""
    for du in range(0, 61):
        for dw in range(0, du + 1):
            pts, _ = bresenham(0, 0, du, dw)
            assert pts == [(i, bresenham_minor(i, du, dw)) for i in range(du + 1)]


def test_bresenham_equals_reference_on_thousands_of_lines():
    for seg in random_segments(4000, 0, W, seed=5):
        assert drawn(*seg) == bresenham_pixels(*seg), seg


@given(st.lists(st.integers(0, 199), min_size=4, max_size=4))
@HYPOTHESIS
def test_bresenham_equals_reference_hypothesis(seg):
    assert drawn(*seg, width=200, height=200) == bresenham_pixels(*seg)


def test_dda_equals_reference_on_thousands_of_lines():
    for seg in random_segments(4000, 0, W, seed=6):
        assert drawn(*seg, method="dda") == set(dda(*seg)), seg


def test_dda_equals_exact_rounding_except_at_ties():
    """The DDA's floating-point accumulation only matters where the ideal point is
    exactly half-way between two pixels; everywhere else it picks the nearest pixel."""
    for seg in random_segments(2000, 0, W, seed=7):
        px = drawn(*seg, method="dda")
        exact = set(exact_line(*seg))
        ties = tie_steps(*seg)
        k = 0 if abs(seg[2] - seg[0]) >= abs(seg[3] - seg[1]) else 1
        assert {p for p in px if p[k] not in ties} == {p for p in exact if p[k] not in ties}
        for p in px:
            if p[k] in ties:  # either candidate: the exact half-up one or the one below
                q = next(e for e in exact if e[k] == p[k])
                assert p == q or abs(p[1 - k] - q[1 - k]) == 1


def test_dda_and_bresenham_agree_off_ties():
    for seg in random_segments(2000, 0, W, seed=8):
        ties = tie_steps(*seg)
        k = 0 if abs(seg[2] - seg[0]) >= abs(seg[3] - seg[1]) else 1
        a = {p for p in drawn(*seg) if p[k] not in ties}
        b = {p for p in drawn(*seg, method="dda") if p[k] not in ties}
        assert a == b


# -- peers -------------------------------------------------------------------------------------
def _skimage(x0, y0, x1, y1):
    rr, cc = sk_line(y0, x0, y1, x1)  # rows are y, columns x
    return set(zip(cc.tolist(), rr.tolist()))


def test_skimage_line_agrees_when_started_from_the_left_or_lower_endpoint():
    """skimage.draw.line runs Bresenham from the *first* endpoint given, with the same
    tie rule (a tie steps the minor coordinate away from the start).  Given the left
    endpoint first (x major) or the lower one (y major), as scanline chooses, the two
    agree exactly."""
    for x0, y0, x1, y1 in random_segments(3000, 0, W, seed=9):
        if abs(y1 - y0) <= abs(x1 - x0):
            if x0 > x1:
                x0, y0, x1, y1 = x1, y1, x0, y0
        elif y0 > y1:
            x0, y0, x1, y1 = x1, y1, x0, y0
        assert drawn(x0, y0, x1, y1) == _skimage(x0, y0, x1, y1)


def test_skimage_line_in_given_order_differs_only_at_ties():
    """In the order given, skimage's result depends on the endpoint order; it then
    differs from scanline only at tie positions (one pixel each side)."""
    differing = 0
    for seg in random_segments(3000, 0, W, seed=10):
        ours, theirs = drawn(*seg), _skimage(*seg)
        ties = tie_steps(*seg)
        k = 0 if abs(seg[2] - seg[0]) >= abs(seg[3] - seg[1]) else 1
        assert {p for p in ours if p[k] not in ties} == {p for p in theirs if p[k] not in ties}
        assert len(ours) == len(theirs)
        differing += ours != theirs
    assert differing > 0  # e.g. (2,1)->(0,0): skimage (1,0), scanline (1,1)
    assert _skimage(2, 1, 0, 0) == {(0, 0), (1, 0), (2, 1)}


def test_opencv_line_differs_only_at_ties():
    """cv2.line (LINE_8) agrees with scanline's Bresenham except at tie positions, where
    it picks the other candidate in most cases (e.g. (0,0)-(2,1): OpenCV (1,0),
    scanline (1,1)) - OpenCV's ties do not follow the notes' p_k >= 0 rule."""
    differing = 0
    for seg in random_segments(2000, 0, W, seed=11):
        x0, y0, x1, y1 = seg
        img = np.zeros((H, W), np.uint8)
        cv2.line(img, (x0, y0), (x1, y1), 255, 1, cv2.LINE_8)
        r, c = np.nonzero(img)
        theirs = set(zip(c.tolist(), r.tolist()))
        ours = drawn(*seg)
        ties = tie_steps(*seg)
        k = 0 if abs(x1 - x0) >= abs(y1 - y0) else 1
        assert {p for p in ours if p[k] not in ties} == {p for p in theirs if p[k] not in ties}
        assert len(ours) == len(theirs)
        differing += ours != theirs
    assert differing > 0


# -- clipping ------------------------------------------------------------------------------------
@pytest.mark.parametrize("method", METHODS)
def test_partly_visible_lines_equal_the_big_frame_buffer(method):
    """A line with endpoints outside a small frame buffer draws exactly the pixels
    that the same line, drawn whole on a frame buffer big enough, has inside it.

    For Bresenham this holds for any translation too (integer arithmetic)."""
    big = 3 * W
    for x0, y0, x1, y1 in random_segments(1500, -W, 2 * W, seed=12):
        whole = drawn(x0 + W, y0 + W, x1 + W, y1 + W, method, width=big, height=big)
        part = {(x - W, y - W) for x, y in whole}
        got = drawn(x0, y0, x1, y1, method)
        if method == "bresenham":
            assert got == in_frame(part, W, H)
        else:
            # the DDA is float arithmetic in absolute coordinates, so a translation can
            # move an exact tie; off-tie pixels must agree
            ties = tie_steps(x0, y0, x1, y1)
            k = 0 if abs(x1 - x0) >= abs(y1 - y0) else 1
            assert {p for p in got if p[k] not in ties} == {p for p in in_frame(part, W, H) if p[k] not in ties}


def test_clipped_dda_equals_the_in_frame_part_of_the_unclipped_dda():
    """BUG (fails): the DDA kernel starts a clipped line at x0 + lo*xinc instead of
    accumulating lo increments, so at an exact tie the visible pixel can differ from
    the one the unclipped algorithm (and ``sl.trace.dda``) plots.  Minimal case:
    (-3, 2)-(3, 1) on an 8x8 frame buffer: y at x = 0 is 2 - 3/6 = 1.5; accumulated
    2 - 1/6 - 1/6 - 1/6 = 1.4999999999999998 -> 1, but drawn: (0, 2)."""
    assert in_frame(dda(-3, 2, 3, 1), 8, 8) == {(0, 1), (1, 1), (2, 1), (3, 1)}
    assert set(sl.trace.dda(-3, 2, 3, 1).pixels()) >= {(0, 1)}
    assert drawn(-3, 2, 3, 1, "dda", width=8, height=8) == {(0, 1), (1, 1), (2, 1), (3, 1)}
    mismatches = [seg for seg in random_segments(3000, -W, 2 * W, seed=13)
                  if drawn(*seg, method="dda") != in_frame(dda(*seg), W, H)]
    assert mismatches == []


EXTREME = [-10**9, -2**30, -10**6, -1000, -1, 0, 5, 31, 63, 64, 1000, 10**6, 10**9, 2**30]


def test_extreme_bresenham_lines_draw_exactly_the_visible_part():
    rng = np.random.default_rng(14)
    cases = [(a, b, c, d) for a in EXTREME[::3] for b in EXTREME[1::3] for c in EXTREME[2::3] for d in EXTREME[::2]]
    for _ in range(1500):
        kind = rng.integers(0, 3)
        if kind == 0:
            seg = rng.choice(EXTREME, 4).tolist()
        elif kind == 1:  # one endpoint inside, the other far away
            seg = [int(rng.integers(0, W)), int(rng.integers(0, H)),
                   int(rng.integers(-2**30, 2**30)), int(rng.integers(-2**30, 2**30))]
        else:  # a long line passing near the frame: endpoints mirrored through a pixel
            cx, cy = rng.integers(-4, W + 4, 2).tolist()
            dx, dy = rng.integers(-10**9, 10**9, 2).tolist()
            seg = [cx - dx // 2, cy - dy // 2, cx + dx // 2 + int(rng.integers(0, 2)), cy + dy // 2]
            seg = [max(-2**30, min(2**30, v)) for v in seg]
        cases.append(tuple(seg))
    for seg in cases:
        assert drawn(*seg) == bresenham_visible(*seg, W, H), seg


@given(
    st.integers(-2**30, 2**30), st.integers(-2**30, 2**30),
    st.integers(-2**30, 2**30), st.integers(-2**30, 2**30),
)
@HYPOTHESIS
def test_extreme_bresenham_lines_hypothesis(x0, y0, x1, y1):
    assert drawn(x0, y0, x1, y1, width=40, height=30) == bresenham_visible(x0, y0, x1, y1, 40, 30)


@given(
    st.integers(0, 63), st.integers(0, 47),
    st.integers(-2**30, 2**30), st.integers(-2**30, 2**30),
)
@HYPOTHESIS
def test_lines_from_inside_to_far_away_hypothesis(x0, y0, x1, y1):
    got = drawn(x0, y0, x1, y1, width=64, height=48)
    assert (x0, y0) in got
    assert got == bresenham_visible(x0, y0, x1, y1, 64, 48)
    assert eight_connected(got)


def test_extreme_dda_lines_stay_within_half_a_pixel_plus_float_error():
    """For huge coordinates the DDA's float increments carry a tiny error, so only
    closeness can be checked: one pixel per visible major-axis position, each within
    0.5 (+1e-6) of the ideal line."""
    rng = np.random.default_rng(15)
    for _ in range(800):
        seg = [int(rng.integers(0, W)), int(rng.integers(0, H)),
               int(rng.integers(-2**30, 2**30)), int(rng.integers(-2**30, 2**30))]
        if rng.integers(0, 2):
            seg = seg[2:] + seg[:2]
        x0, y0, x1, y1 = seg
        got = drawn(*seg, method="dda")
        k = 0 if abs(x1 - x0) >= abs(y1 - y0) else 1
        majors = [p[k] for p in got]
        assert len(majors) == len(set(majors))
        a0, b0, a1, b1 = (x0, y0, x1, y1) if k == 0 else (y0, x0, y1, x1)
        for p in got:
            ideal = b0 + (b1 - b0) * (p[k] - a0) / (a1 - a0)
            assert abs(p[1 - k] - ideal) <= 0.5 + 1e-6
        # the endpoint inside is drawn
        inside = (x0, y0) if 0 <= x0 < W and 0 <= y0 < H else (x1, y1)
        assert inside in got
        # every visible major position whose ideal point is clearly inside is drawn
        for u in range(W if k == 0 else H):
            if min(a0, a1) <= u <= max(a0, a1):
                ideal = b0 + (b1 - b0) * (u - a0) / (a1 - a0)
                lim = H if k == 0 else W
                if 0.5 < ideal < lim - 1.5 and abs(ideal - math.floor(ideal) - 0.5) > 1e-3:
                    assert u in majors


def test_line_entirely_outside_draws_nothing():
    for seg in [(-10, -10, -1, -1), (64, 0, 10**9, 10**9), (-5, 70, 70, 70), (-2**30, -1, 2**30, -1),
                (-2**30, 64, 2**30, 64), (70, -2**30, 70, 2**30), (-1, -2**30, -1, 2**30)]:
        for method in METHODS:
            assert drawn(*seg, method) == set()


def test_line_along_the_edges_of_the_frame():
    for method in METHODS:
        assert drawn(-2**30, 0, 2**30, 0, method) == {(x, 0) for x in range(W)}
        assert drawn(W - 1, 2**30, W - 1, -2**30, method) == {(W - 1, y) for y in range(H)}
        # the long diagonal through the frame: exactly the frame's diagonal
        assert drawn(-10**9, -10**9, 10**9, 10**9, method) == {(i, i) for i in range(W)}


# -- modes, batches, colors ------------------------------------------------------------------------
@pytest.mark.parametrize("method", METHODS)
def test_every_mode_draws_the_same_pixels(method):
    white = {"1": True, "L": 255, "RGB": [255, 255, 255], "RGBA": [255, 255, 255, 255], "P": 1}
    for seg in random_segments(60, -20, 84, seed=16):
        sets = []
        for mode in MODES:
            fb = sl.FrameBuffer(W, 50, mode=mode, **({"color_table": ["black", "white"]} if mode == "P" else {}))
            sl.draw.line(fb, *seg, color="white", method=method)
            px = lit(fb)
            a = fb.to_array()
            for x, y in px:
                assert np.array_equal(a[49 - y, x], white[mode])
            sets.append(px)
        assert all(s == sets[0] for s in sets), seg
        if method == "bresenham":
            assert sets[0] == bresenham_visible(*seg, W, 50)


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("method", METHODS)
def test_batch_lines_equal_a_loop_of_line(mode, method):
    rng = np.random.default_rng(17)
    segs = rng.integers(-40, 100, (300, 4))
    segs[::7] *= 10**6  # some far outside
    kw = {"color_table": ["black", "white", "red"]} if mode == "P" else {}
    a = sl.FrameBuffer(W, H, mode=mode, **kw)
    b = sl.FrameBuffer(W, H, mode=mode, **kw)
    sl.draw.lines(a, segs, color="white", method=method)
    for s in segs.tolist():
        sl.draw.line(b, *s, color="white", method=method)
    assert np.array_equal(a.to_array(), b.to_array())
    # float rows are rounded like line()'s arguments
    c = sl.FrameBuffer(W, H, mode=mode, **kw)
    sl.draw.lines(c, segs + 0.3, color="white", method=method)
    assert np.array_equal(c.to_array(), a.to_array())


@pytest.mark.parametrize("mode", ["1", "L", "RGB"])
def test_batch_on_threads_equals_the_lines_drawn_in_order(mode, monkeypatch):
    # a batch large enough to be shared by threads (three here): each thread draws
    # the bands of 32 rows it owns, a line crossing bands in each of them; per-line
    # colors, later lines over earlier ones, and packed bits where neighbouring bands
    # are written by different threads.  The reference: every line's own Bresenham
    # pixels (tests/reference.py), painted in the batch's order.
    from scanline._kernels import _threads
    monkeypatch.setattr(_threads, "threads", lambda: 3)
    calls = []
    real = _threads.call
    monkeypatch.setattr(_threads, "call", lambda *a: calls.append(a[2:4]) or real(*a))
    rng = np.random.default_rng(5)
    w, h = 203, 171
    n = 30_000
    start = rng.integers(-30, [w + 30, h + 30], (n, 2))
    length = np.where(rng.random((n, 1)) < 0.9, 3, 120)   # mostly short, some long
    segs = np.concatenate([start, start + rng.integers(-length, length + 1, (n, 2))], axis=1)
    levels = {"1": 2, "L": 256, "RGB": 256}[mode]
    values = rng.integers(0, levels, n)
    color = values if mode != "RGB" else np.stack([values, 255 - values, values // 2], axis=1)
    fb = sl.FrameBuffer(w, h, mode=mode)
    sl.draw.lines(fb, segs, color=color)
    assert sorted(calls) == [(0, 3), (1, 3), (2, 3)]
    expected = np.zeros(fb.to_array().shape, np.uint8)
    for row, value in zip(segs.tolist(), color.tolist()):
        for x, y in bresenham_visible(*row, w, h):
            expected[h - 1 - y, x] = value
    assert np.array_equal(fb.to_array(), expected if mode != "1" else expected.astype(bool))


def test_per_primitive_colors():
    segs = [(0, 0, 9, 0), (0, 2, 9, 2), (5, 0, 5, 4)]
    # names, one per segment; later segments overwrite earlier ones
    fb = sl.FrameBuffer(10, 5, mode="RGB")
    sl.draw.lines(fb, segs, color=["red", (0, 255, 0), "#0000ff"])
    assert fb.get_pixel(0, 0) == (255, 0, 0)
    assert fb.get_pixel(9, 2) == (0, 255, 0)
    assert fb.get_pixel(5, 0) == (0, 0, 255) and fb.get_pixel(5, 2) == (0, 0, 255)
    assert fb.get_pixel(5, 4) == (0, 0, 255) and fb.get_pixel(0, 4) == (0, 0, 0)
    # an (N, 3) integer array
    fb2 = sl.FrameBuffer(10, 5, mode="RGB")
    sl.draw.lines(fb2, np.array(segs), color=np.array([[255, 0, 0], [0, 255, 0], [0, 0, 255]]))
    assert np.array_equal(fb.to_array(), fb2.to_array())
    # (N, 4) into RGBA, (N,) gray levels, bits, table indices
    fb = sl.FrameBuffer(10, 5, mode="RGBA")
    sl.draw.lines(fb, segs, color=np.array([[1, 2, 3, 4], [5, 6, 7, 8], [9, 10, 11, 12]]))
    assert fb.get_pixel(0, 0) == (1, 2, 3, 4) and fb.get_pixel(5, 4) == (9, 10, 11, 12)
    fb = sl.FrameBuffer(10, 5, mode="L")
    sl.draw.lines(fb, segs, color=np.array([10, 20, 30]))
    assert (fb.get_pixel(0, 0), fb.get_pixel(0, 2), fb.get_pixel(5, 3)) == (10, 20, 30)
    fb = sl.FrameBuffer(10, 5, mode="1")
    sl.draw.lines(fb, segs, color=[1, 0, 1])
    assert (fb.get_pixel(0, 0), fb.get_pixel(0, 2), fb.get_pixel(5, 2)) == (1, 0, 1)
    fb = sl.FrameBuffer(10, 5, mode="P", color_table=["black", "red", "green", "blue"])
    sl.draw.lines(fb, segs, color=np.array([3, 2, 1]))
    assert (fb.get_pixel(0, 0), fb.get_pixel(0, 2), fb.get_pixel(5, 3)) == (3, 2, 1)
    rgb = np.array(fb.to_pil().convert("RGB"))
    assert tuple(rgb[4, 0]) == (0, 0, 255)  # (0, 0) -> entry 3, blue


def test_single_color_forms():
    for color, mode, expected in [(200, "L", 200), ("white", "1", 1), ((1, 2, 3), "RGB", (1, 2, 3)),
                                  ("#010203", "RGBA", (1, 2, 3, 255)), (7, "RGB", (7, 7, 7))]:
        fb = sl.FrameBuffer(4, 1, mode=mode)
        sl.draw.line(fb, 0, 0, 3, 0, color=color)
        assert [fb.get_pixel(x, 0) for x in range(4)] == [expected] * 4


def test_wrong_number_of_colors_raises():
    fb = sl.FrameBuffer(4, 4)
    with pytest.raises(ValueError) as e:
        sl.draw.lines(fb, [(0, 0, 1, 1), (1, 1, 2, 2)], color=["red"])
    assert isinstance(e.value, sl.ScanlineError) and "color" in str(e.value)


def test_unknown_method_raises():
    fb = sl.FrameBuffer(4, 4)
    for bad in ("Bresenham", "wu", None, 0):
        with pytest.raises(ValueError) as e:
            sl.draw.line(fb, 0, 0, 1, 1, method=bad)
        assert isinstance(e.value, sl.ScanlineError) and "method" in str(e.value)
        with pytest.raises(ValueError):
            sl.draw.lines(fb, [(0, 0, 1, 1)], method=bad)
