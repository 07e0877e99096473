"""sl.draw.fill_circle(s), fill_ellipse(s), arc, chord and pie: exact tiny images, the
filled areas against the midpoint outlines and a slow reference, clipping of huge
shapes, arcs/pies/chords that tile, peers (scikit-image, OpenCV), modes, bad input.
"""

import math

import cv2
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from skimage.draw import disk
from skimage.draw import ellipse as sk_ellipse

import scanline as sl
from tests.reference import (
    HYPOTHESIS,
    MODES,
    circle_pixels,
    circle_y,
    ellipse_pixels,
    in_frame,
    lit,
)

TAU = 2 * math.pi


# -- slow references (from the notes' midpoint outlines, chapter 2, Q.4-Q.6 and Q.8) ------
def rows_between(outline):
    """Scan-line fill of a closed outline: every pixel from the left-most to the
    right-most outline pixel of each row."""
    ext = {}
    for x, y in outline:
        lo, hi = ext.get(y, (x, x))
        ext[y] = (min(lo, x), max(hi, x))
    return {(x, y) for y, (lo, hi) in ext.items() for x in range(lo, hi + 1)}


def circle_half_width(d, r):
    """Right-most outline pixel of row offset d of the midpoint circle, for any r:
    the transposed octant point (y(d), d) when d <= y(d), else the last octant column
    x with y(x) = d, found by bisection on the closed form ``circle_y``."""
    if d > r:
        return None
    if r == 0:
        return 0
    if d < r and d <= circle_y(d, r):
        return circle_y(d, r)
    lo, hi = 0, r - 1  # largest x with circle_y(x) >= d
    while lo < hi:
        mid = (lo + hi + 1) // 2
        if circle_y(mid, r) >= d:
            lo = mid
        else:
            hi = mid - 1
    assert circle_y(lo, r) == d and lo <= d
    return lo


def disk_visible(xc, yc, r, width, height):
    out = set()
    for y in range(height):
        w = circle_half_width(abs(y - yc), r)
        if w is not None:
            out |= {(x, y) for x in range(max(0, xc - w), min(width - 1, xc + w) + 1)}
    return out


def angle_in(px, py, a, b, margin=1e-7):
    """Is the polar angle of (px, py) inside (a, b) (counterclockwise) by more than
    ``margin``, outside by more than ``margin``, or too close to tell (None)?"""
    t = math.atan2(py, px)
    rel, span = (t - a) % TAU, (b - a) % TAU
    dist = min(abs(rel), abs(rel - span), TAU - rel)
    if dist < margin:
        return None
    return rel < span


# -- drawing helpers ------------------------------------------------------------------------
def drawn(fn, *args, size, mode="L", **kw):
    fb = sl.FrameBuffer(*size, mode=mode)
    fn(fb, *args, **kw)
    return lit(fb)


def centered(fn, rx, ry, *args, margin=2):
    """Draw ``fn(fb, cx, cy, rx, ry, *args)`` whole; pixels relative to the center."""
    cx, cy = rx + margin, ry + margin
    px = drawn(fn, cx, cy, rx, ry, *args, size=(2 * cx + 1, 2 * cy + 1))
    return {(x - cx, y - cy) for x, y in px}


def filled_circle(r):
    return centered(lambda fb, x, y, rx, ry: sl.draw.fill_circle(fb, x, y, rx), r, r)


def filled_ellipse(rx, ry):
    return centered(sl.draw.fill_ellipse, rx, ry)


# == exact tiny images ========================================================================
def test_small_disks_by_hand():
    assert filled_circle(0) == {(0, 0)}
    assert filled_circle(1) == {(0, 0), (1, 0), (-1, 0), (0, 1), (0, -1)}
    # r = 2: octant (0, 2), (1, 2): rows +-2 run -1..1, rows 0 and +-1 run -2..2
    assert filled_circle(2) == {(x, y) for y in range(-2, 3) for x in range(-2, 3)
                                if abs(y) < 2 or abs(x) < 2}
    fb = sl.FrameBuffer(7, 7, mode="1")
    sl.draw.fill_circle(fb, 3, 3, 3)
    assert sl.text_image(fb).splitlines() == [
        "--###--", "-#####-", "#######", "#######", "#######", "-#####-", "--###--"]


def test_notes_r10_octant_gives_the_row_extents():
    # notes, Q.5: octant (0,10) (1,10) (2,10) (3,10) (4,9) (5,9) (6,8) (7,7): rows 0..7
    # end at y_k of column k, rows 8, 9, 10 at the last x with that y
    half = [10, 10, 10, 10, 9, 9, 8, 7, 6, 5, 3]
    expected = {(x, s * d) for d, w in enumerate(half) for s in (1, -1) for x in range(-w, w + 1)}
    assert filled_circle(10) == expected
    assert len(expected) == 2 * sum(2 * w + 1 for w in half) - 21


def test_small_ellipses_by_hand():
    fb = sl.FrameBuffer(9, 5, mode="1")
    sl.draw.fill_ellipse(fb, 4, 2, 4, 2)
    assert sl.text_image(fb).splitlines() == ["--#####--", "-#######-", "#########", "-#######-", "--#####--"]
    assert filled_ellipse(3, 0) == {(x, 0) for x in range(-3, 4)}  # ry = 0: the segment
    assert filled_ellipse(0, 2) == {(0, y) for y in range(-2, 3)}
    assert filled_ellipse(0, 0) == {(0, 0)}


# == against the outlines and the reference ===================================================
def test_disk_is_the_outline_and_what_lies_between_r_0_to_120():
    rng = np.random.default_rng(40)
    for r in range(0, 121):
        size = 2 * r + 5
        xc, yc = rng.integers(r, size - r, 2).tolist()
        filled = drawn(sl.draw.fill_circle, xc, yc, r, size=(size, size))
        outline = drawn(sl.draw.circle, xc, yc, r, size=(size, size))
        assert outline <= filled
        assert filled == rows_between(outline) == rows_between(circle_pixels(xc, yc, r)), r


def test_ellipse_area_is_the_outline_and_what_lies_between():
    rng = np.random.default_rng(41)
    cases = [(rx, ry) for rx in range(0, 9) for ry in range(0, 9)]
    cases += [tuple(rng.integers(0, 70, 2).tolist()) for _ in range(80)]
    cases += [(1, 60), (60, 1), (100, 3), (2, 90), (45, 45)]
    for rx, ry in cases:
        w, h = 2 * rx + 5, 2 * ry + 5
        xc, yc = rx + 2, ry + 2
        filled = drawn(sl.draw.fill_ellipse, xc, yc, rx, ry, size=(w, h))
        outline = drawn(sl.draw.ellipse, xc, yc, rx, ry, size=(w, h))
        assert outline <= filled
        assert filled == rows_between(outline) == rows_between(ellipse_pixels(xc, yc, rx, ry)), (rx, ry)


def test_filled_invariants():
    for rx, ry in [(r, r) for r in range(0, 40)] + [(7, 3), (3, 7), (30, 11), (11, 30)]:
        px = filled_circle(rx) if rx == ry else filled_ellipse(rx, ry)
        assert {(-x, y) for x, y in px} == px and {(x, -y) for x, y in px} == px
        if rx == ry:
            assert {(y, x) for x, y in px} == px
        rows = {}
        for x, y in px:
            rows.setdefault(y, []).append(x)
        assert sorted(rows) == list(range(-ry, ry + 1))  # every row, no gaps between rows
        for xs in rows.values():
            assert sorted(xs) == list(range(min(xs), max(xs) + 1))  # one span per row


# == clipping: partly visible and huge shapes =================================================
def test_partly_visible_circles_equal_the_reference():
    rng = np.random.default_rng(42)
    W, H = 40, 30
    for _ in range(300):
        r = int(rng.integers(0, 90))
        xc, yc = rng.integers(-100, 140, 2).tolist()
        assert drawn(sl.draw.fill_circle, xc, yc, r, size=(W, H)) == disk_visible(xc, yc, r, W, H)


def test_huge_circles_cost_only_their_visible_rows_and_equal_the_reference():
    rng = np.random.default_rng(43)
    W, H = 48, 32
    cases = [(24, 16, 10**9), (24, 10**9 + 5, 10**9), (-10**9 + 20, 16, 10**9),
             (10**9, 10**9, 2**30), (-2**30, -2**30, 2**30), (24, -2**30 + 40, 2**30)]
    for _ in range(60):  # boundaries crossing the frame
        r = int(math.exp(rng.uniform(0, math.log(2**30))))
        t = rng.uniform(0, TAU)
        px, py = rng.uniform(-3, W + 3), rng.uniform(-3, H + 3)
        cases.append((int(px - r * math.cos(t)), int(py - r * math.sin(t)), r))
    for xc, yc, r in cases:
        assert drawn(sl.draw.fill_circle, xc, yc, r, size=(W, H)) == disk_visible(xc, yc, r, W, H), (xc, yc, r)


def test_partly_visible_ellipses_equal_the_whole_ellipse_clipped():
    rng = np.random.default_rng(44)
    W, H = 40, 30
    for _ in range(150):
        rx, ry = rng.integers(0, 70, 2).tolist()
        xc, yc = rng.integers(-80, 120, 2).tolist()
        whole = rows_between(ellipse_pixels(xc, yc, rx, ry))
        assert drawn(sl.draw.fill_ellipse, xc, yc, rx, ry, size=(W, H)) == in_frame(whole, W, H)


def test_extreme_ellipses_are_clipped():
    fb = sl.FrameBuffer(32, 16, mode="L")
    sl.draw.fill_ellipse(fb, 16, 8, 2**24, 20)  # rows +-8 of a very flat ellipse: all lit
    assert len(lit(fb)) == 32 * 16
    fb = sl.FrameBuffer(32, 16, mode="L")
    sl.draw.fill_ellipse(fb, -10**9, 10**9, 2**24, 20)
    assert lit(fb) == set()


# == peers ====================================================================================
def test_skimage_disk_and_opencv_bracket_the_midpoint_disk():
    """Neither peer rasterizes the midpoint circle, but for r = 1..100 they bracket
    it: cv2.circle(thickness=-1) <= midpoint disk <= skimage.draw.disk of radius
    r + 1/2 (pixel centers strictly inside), and every difference lies next to the
    midpoint outline.  Measured: skimage adds at most 72 pixels (0 for 8 radii, 2200
    over all radii); OpenCV lacks up to 336 (it agrees for r = 1 only, 15672 in all)."""
    sk_same = cv_same = 0
    sk_worst = cv_worst = 0
    for r in range(1, 101):
        ours = filled_circle(r)
        outline = circle_pixels(0, 0, r)
        near = {(x + dx, y + dy) for x, y in outline for dx in (-1, 0, 1) for dy in (-1, 0, 1)}
        rr, cc = disk((0, 0), r + 0.5, shape=None)
        sk = set(zip(cc.tolist(), rr.tolist()))
        img = np.zeros((2 * r + 5, 2 * r + 5), np.uint8)
        cv2.circle(img, (r + 2, r + 2), r, 255, -1, cv2.LINE_8)
        rows, cols = np.nonzero(img)
        cv = {(c - r - 2, q - r - 2) for q, c in zip(rows.tolist(), cols.tolist())}
        assert cv <= ours <= sk
        assert sk - cv <= near
        sk_same += sk == ours
        cv_same += cv == ours
        sk_worst = max(sk_worst, len(sk - ours))
        cv_worst = max(cv_worst, len(ours - cv))
    assert (sk_same, sk_worst) == (8, 72)
    assert (cv_same, cv_worst) == (1, 336)


def test_skimage_and_opencv_ellipses_differ_only_next_to_the_outline():
    """skimage.draw.ellipse with semi-axes + 1/2 and cv2.ellipse(thickness=-1) are
    neither inside nor around the midpoint ellipse area in general (skimage contains
    it for 93 of these 130 shapes), but every pixel they disagree on is next to the
    midpoint outline; at most 36 pixels differ (measured)."""
    contained = 0
    for rx in range(1, 40, 3):
        for ry in range(1, 40, 4):
            ours = filled_ellipse(rx, ry)
            outline = ellipse_pixels(0, 0, rx, ry)
            near = {(x + dx, y + dy) for x, y in outline for dx in (-1, 0, 1) for dy in (-1, 0, 1)}
            rr, cc = sk_ellipse(0, 0, ry + 0.5, rx + 0.5, shape=None)
            sk = set(zip(cc.tolist(), rr.tolist()))
            img = np.zeros((2 * ry + 5, 2 * rx + 5), np.uint8)
            cv2.ellipse(img, (rx + 2, ry + 2), (rx, ry), 0, 0, 360, 255, -1, cv2.LINE_8)
            rows, cols = np.nonzero(img)
            cv = {(c - rx - 2, q - ry - 2) for q, c in zip(rows.tolist(), cols.tolist())}
            for theirs in (sk, cv):
                assert ours ^ theirs <= near and len(ours ^ theirs) <= 36
            contained += ours <= sk
    assert contained == 93


# == arcs =====================================================================================
def test_arcs_are_outline_pixels_in_the_angular_range():
    rng = np.random.default_rng(45)
    for _ in range(120):
        rx, ry = rng.integers(0, 40, 2).tolist()
        if rng.random() < 0.4:
            ry = rx
        a, b = rng.uniform(-2 * TAU, 2 * TAU, 2).tolist()
        px = centered(sl.draw.arc, rx, ry, a, b)
        outline = circle_pixels(0, 0, rx) if rx == ry else ellipse_pixels(0, 0, rx, ry)
        assert px <= outline
        for x, y in outline - {(0, 0)}:
            inside = angle_in(x, y, a, b) if b - a < TAU else True
            if inside is not None:
                assert ((x, y) in px) == inside, (rx, ry, a, b, x, y)


def test_arcs_join_and_make_the_whole_outline():
    rng = np.random.default_rng(46)
    quarter = [0, math.pi / 2, math.pi, 3 * math.pi / 2, TAU]
    for r in (1, 2, 5, 17, 40):
        outline = circle_pixels(0, 0, r)
        assert centered(sl.draw.arc, r, r, 0, TAU) == outline
        parts = [centered(sl.draw.arc, r, r, quarter[i], quarter[i + 1]) for i in range(4)]
        assert set().union(*parts) == outline
        assert (r, 0) in parts[0] and (r, 0) in parts[3] and (0, r) in parts[0] and (0, r) in parts[1]
        for _ in range(10):
            a, b, c = np.sort(rng.uniform(-TAU, TAU, 3)).tolist()
            for rx, ry in ((r, r), (r + 3, r)):
                assert (centered(sl.draw.arc, rx, ry, a, b) | centered(sl.draw.arc, rx, ry, b, c)
                        == centered(sl.draw.arc, rx, ry, a, c))


# == pies and chords ==========================================================================
def coverage(pieces, shape):
    count = {}
    for piece in pieces:
        for p in piece:
            count[p] = count.get(p, 0) + 1
    assert set(count) == shape
    return max(count.values())


def test_pie_quarters_and_eighths_tile_the_disk_exactly_once():
    for rx, ry in [(r, r) for r in (0, 1, 2, 3, 8, 25)] + [(9, 4), (4, 9), (30, 17)]:
        shape = filled_circle(rx) if rx == ry else filled_ellipse(rx, ry)
        for n in (2, 4, 8):
            cuts = [TAU * i / n for i in range(n + 1)]
            pieces = [centered(sl.draw.pie, rx, ry, cuts[i], cuts[i + 1]) for i in range(n)]
            assert coverage(pieces, shape) == 1, (rx, ry, n)


def test_pies_at_random_angles_tile_the_disk_exactly_once():
    rng = np.random.default_rng(47)
    for _ in range(25):
        rx = int(rng.integers(0, 30))
        ry = rx if rng.random() < 0.5 else int(rng.integers(0, 30))
        n = int(rng.integers(1, 7))
        cuts = np.sort(rng.uniform(0, TAU, n)).tolist()
        cuts = cuts + [cuts[0] + TAU]
        if n == 1:
            cuts = [cuts[0], cuts[0] + 1.5, cuts[0] + TAU]  # one reflex slice and its rest
        shape = filled_circle(rx) if rx == ry else filled_ellipse(rx, ry)
        pieces = [centered(sl.draw.pie, rx, ry, cuts[i], cuts[i + 1]) for i in range(len(cuts) - 1)]
        assert coverage(pieces, shape) == 1


def test_pie_pixels_are_disk_pixels_in_the_angular_range():
    rng = np.random.default_rng(48)
    for _ in range(60):
        rx, ry = rng.integers(0, 35, 2).tolist()
        a, b = rng.uniform(-TAU, TAU, 2).tolist()
        px = centered(sl.draw.pie, rx, ry, a, b)
        shape = filled_ellipse(rx, ry) if rx != ry else filled_circle(rx)
        assert px <= shape
        for x, y in shape - {(0, 0)}:
            inside = angle_in(x, y, a, b) if b - a < TAU else True
            if inside is not None:
                assert ((x, y) in px) == inside


def test_pie_edges_follow_the_top_left_rule():
    px = centered(sl.draw.pie, 5, 5, 0, math.pi / 2)
    assert (0, 3) in px and (3, 0) not in px and (0, 0) not in px  # +y ray: a left edge
    px = centered(sl.draw.pie, 5, 5, 3 * math.pi / 2, TAU)
    assert (3, 0) in px and (0, -3) in px and (0, 0) in px  # a top and a left edge
    px = centered(sl.draw.pie, 5, 5, math.pi / 2, math.pi)
    assert (0, 3) not in px and (-3, 0) not in px  # a right and a bottom edge
    assert centered(sl.draw.pie, 5, 5, 1.0, 1.0) == set()
    assert centered(sl.draw.pie, 5, 5, 1.0, 1.0 + TAU) == filled_circle(5)


def test_chords_are_inside_the_disk_and_complementary_chords_tile_it():
    rng = np.random.default_rng(49)
    for _ in range(60):
        rx = int(rng.integers(0, 35))
        ry = rx if rng.random() < 0.5 else int(rng.integers(0, 35))
        a = rng.uniform(-TAU, TAU)
        b = a + rng.uniform(-TAU, TAU)  # |b - a| < 2 pi: (a, b) and (b, a) are complements
        shape = filled_circle(rx) if rx == ry else filled_ellipse(rx, ry)
        one, other = centered(sl.draw.chord, rx, ry, a, b), centered(sl.draw.chord, rx, ry, b, a)
        assert one <= shape
        assert coverage([one, other], shape) == 1
        # the chord's side: right of the directed line P_a -> P_b (float check, margin)
        pa = [(rx * ry / math.hypot(ry * math.cos(t), rx * math.sin(t)) if rx and ry else 0) * f(t)
              for t in (a, b) for f in (math.cos, math.sin)]
        dx, dy = pa[2] - pa[0], pa[3] - pa[1]
        length = math.hypot(dx, dy)
        if length > 1e-3:
            for x, y in shape:
                side = (dx * (y - pa[1]) - dy * (x - pa[0])) / length
                if abs(side) > 1e-6:
                    assert ((x, y) in one) == (side < 0)


def test_chord_by_hand():
    fb = sl.FrameBuffer(7, 7, mode="1")
    sl.draw.chord(fb, 3, 3, 3, 3, 0, math.pi)  # the center row is a bottom edge: left out
    assert sl.text_image(fb).splitlines()[:4] == ["--###--", "-#####-", "#######", "-------"]
    assert len(lit(fb)) == 3 + 5 + 7
    sl.draw.chord(fb, 3, 3, 3, 3, math.pi, TAU)  # ... and the top edge of the other half
    assert len(lit(fb)) == 37


def test_huge_pies_chords_and_arcs_are_clipped_consistently():
    W, H = 40, 30
    for xc, yc, r in [(20, 15, 10**9), (20, -10**9 + 10, 10**9), (-2**30 + 30, 10, 2**30)]:
        shape = disk_visible(xc, yc, r, W, H)
        quarters = [drawn(sl.draw.pie, xc, yc, r, r, i * math.pi / 2, (i + 1) * math.pi / 2, size=(W, H))
                    for i in range(4)]
        assert sum(len(q) for q in quarters) == len(shape) and set().union(*quarters) == shape
        chords = [drawn(sl.draw.chord, xc, yc, r, r, a, b, size=(W, H)) for a, b in ((0.3, 2.0), (2.0, 0.3))]
        assert not chords[0] & chords[1] and chords[0] | chords[1] == shape
        outline = drawn(sl.draw.circle, xc, yc, r, size=(W, H))
        assert drawn(sl.draw.arc, xc, yc, r, r, 0, TAU, size=(W, H)) == outline
        assert drawn(sl.draw.arc, xc, yc, r, r, 0.5, 4.0, size=(W, H)) <= outline


# == batches, modes, styles ===================================================================
def test_batches_equal_single_calls():
    rng = np.random.default_rng(50)
    circles = np.column_stack([rng.integers(-20, 100, (50, 2)), rng.integers(0, 30, 50)])
    ellipses = np.column_stack([rng.integers(-20, 100, (50, 2)), rng.integers(0, 30, (50, 2))])
    palette = rng.integers(0, 256, 50)
    for batch, single, shapes in ((sl.draw.fill_circles, sl.draw.fill_circle, circles),
                                  (sl.draw.fill_ellipses, sl.draw.fill_ellipse, ellipses)):
        for color in (200, palette):
            a = sl.FrameBuffer(80, 70, mode="L")
            batch(a, shapes, color=color)
            b = sl.FrameBuffer(80, 70, mode="L")
            for i, row in enumerate(shapes.tolist()):
                single(b, *row, color=int(palette[i]) if color is palette else 200)
            assert np.array_equal(a.to_array(), b.to_array())
    fb = sl.FrameBuffer(8, 8, mode="L")
    sl.draw.fill_circles(fb, [])
    assert lit(fb) == set()


@pytest.mark.parametrize("mode", MODES)
def test_every_mode(mode):
    def paint(fb):
        sl.draw.fill_circle(fb, 13, 9, 7, color="white")
        sl.draw.fill_ellipse(fb, 30, 20, 9, 4, color="white")
        sl.draw.pie(fb, 5, 25, 6, 4, 0.5, 4.0, color="white")
        sl.draw.chord(fb, 25, 5, 5, 5, 1.0, 3.0, color="white")
        sl.draw.arc(fb, 33, 8, 6, 3, 2.0, 6.0, color="white")
        sl.draw.fill_circles(fb, [(3, 3, 2), (37, 27, 3)], color="white")

    ref = sl.FrameBuffer(41, 31, mode="L")
    paint(ref)
    fb = sl.FrameBuffer(41, 31, mode=mode)
    paint(fb)
    assert lit(fb) == lit(ref) and len(lit(ref)) > 300


def test_styles_get_the_area_and_its_offset_origin():
    """A fill style receives the bounding box, a span drawer that accepts an origin
    offset, and the outline (the hollow style)."""
    class Probe:
        kind = "probe"

        def paint(self, fb, color, bbox, draw, outline):
            self.bbox = bbox
            x0, y0, x1, y1 = bbox
            sub = sl.FrameBuffer(x1 - x0 + 1, y1 - y0 + 1, mode="L")
            buf, packed = sub._raster()
            draw(buf, packed, sub.width, sub.height, x0, y0, sub.pixel(255))
            self.pixels = {(x + x0, y + y0) for x, y in lit(sub)}
            outline()

    probe = Probe()
    fb = sl.FrameBuffer(30, 30, mode="L")
    sl.draw.fill_circle(fb, 12, 14, 6, style=probe)
    assert probe.bbox == (6, 8, 18, 20)
    assert probe.pixels == rows_between(circle_pixels(12, 14, 6))
    assert lit(fb) == circle_pixels(12, 14, 6)  # outline() drew the circle
    probe = Probe()
    fb = sl.FrameBuffer(30, 30, mode="L")
    sl.draw.pie(fb, 12, 14, 8, 5, 0.2, 2.5, style=probe)
    expected = drawn(sl.draw.pie, 12, 14, 8, 5, 0.2, 2.5, size=(30, 30))
    assert probe.pixels == expected
    assert lit(fb) >= drawn(sl.draw.arc, 12, 14, 8, 5, 0.2, 2.5, size=(30, 30)) | {(12, 14)}


# == bad input ================================================================================
@pytest.mark.parametrize("call, name", [
    (lambda fb: sl.draw.fill_circle(fb, math.nan, 3, 2), "xc"),
    (lambda fb: sl.draw.fill_circle(fb, 3, 3, math.inf), "r"),
    (lambda fb: sl.draw.fill_circle(fb, 3, 3, -1), "r"),
    (lambda fb: sl.draw.chord(fb, 3, 3, math.nan, 1, 0, 1), "rx"),    # any finite rx is drawn
    (lambda fb: sl.draw.fill_ellipse(fb, 3, 3, 2, math.nan), "ry"),
    (lambda fb: sl.draw.arc(fb, 3, 3, 2, 2, math.nan, 1), "start"),
    (lambda fb: sl.draw.pie(fb, 3, 3, 2, 2, 0, math.inf), "end"),
    (lambda fb: sl.draw.chord(fb, 3, -math.inf, 2, 2, 0, 1), "yc"),
    (lambda fb: sl.draw.chord(fb, 3, 2**31, -2**40, 2, 0, 1), "rx"),
    (lambda fb: sl.draw.fill_circles(fb, [(1, 2, math.nan)]), "circles"),
    (lambda fb: sl.draw.fill_ellipses(fb, [(1, 2, 3, 4), (1, 2, -5, 2)]), "radii"),
    (lambda fb: sl.draw.fill_circles(fb, [(1, 2, 3)], color=[1, 2]), "color"),
])
def test_bad_input_names_the_argument(call, name):
    with pytest.raises((ValueError, TypeError), match=name):
        call(sl.FrameBuffer(8, 8, mode="L"))


finite = st.floats(min_value=-2.0**31, max_value=2.0**31, allow_nan=False)
anything = st.one_of(finite, st.just(math.nan), st.just(math.inf), st.integers(-2**40, 2**40))


@HYPOTHESIS
@given(st.sampled_from(["fill_circle", "fill_ellipse", "arc", "chord", "pie"]),
       st.lists(anything, min_size=6, max_size=6), st.sampled_from(["1", "L", "RGB"]))
def test_fuzz_never_crashes_nor_writes_outside(fn, args, mode):
    fb = sl.FrameBuffer(13, 9, mode=mode)
    xc, yc, rx, ry, a, b = args
    call = {"fill_circle": lambda: sl.draw.fill_circle(fb, xc, yc, abs(rx)),
            "fill_ellipse": lambda: sl.draw.fill_ellipse(fb, xc, yc, abs(rx) % 2**12, abs(ry) % 2**12),
            "arc": lambda: sl.draw.arc(fb, xc, yc, abs(rx), abs(rx), a, b),
            "chord": lambda: sl.draw.chord(fb, xc, yc, abs(rx) % 2**12, abs(ry) % 2**12, a, b),
            "pie": lambda: sl.draw.pie(fb, xc, yc, abs(rx), abs(rx), a, b)}[fn]
    try:
        call()
    except (ValueError, TypeError) as e:
        assert isinstance(e, sl.ScanlineError)
    assert fb.to_array().shape[:2] == (9, 13)
