"""Far and huge circles and ellipses are drawn, not refused (issue 11, item 2):
beyond the kernels' exact limits (centers within +-2**30, r <= 2**30, ellipses with
rx * ry <= 2**29) the visible part is computed exactly in Python integers
(scanline.geometry.far_conics, scanline.draw._far_conics).

Oracles: the kernels themselves, for conics within their limits drawn through the
far path (forced); independent Python references for the rest -- the notes' midpoint
ellipse loop stepped in full with Python integers, the nearest pixel to the true
curve evaluated with 700-digit decimals, exact integer point-in-band tests -- and
shapely for the areas of thick and antialiased strokes."""

import math
from decimal import Decimal, getcontext
from fractions import Fraction

import numpy as np
import pytest

import scanline as sl
from scanline.draw import _far_conics as far
from tests.fuzz.harness import bounded
from tests.reference import peer

W, H = 40, 30
FRAME = (0, 0, W - 1, H - 1)


def fb(mode="L"):
    return sl.FrameBuffer(W, H, mode=mode)


def lit(f):
    """The set of lit pixels (x, y), y up."""
    a = f.to_array()[::-1]
    if a.ndim == 3:
        a = a.any(axis=2)
    ys, xs = np.nonzero(a)
    return set(zip(xs.tolist(), ys.tolist()))


def image(draw, mode="L"):
    f = fb(mode)
    draw(f)
    return f.to_array()


# -- the far path forced on conics the kernels take: exactly their pixels -------------

def _near_outline(rng, rx, ry):
    """A center that puts the frame over a random point of the outline."""
    t = rng.uniform(0, 2 * math.pi)
    return (int(round(W / 2 - rx * math.cos(t) + rng.integers(-8, 9))),
            int(round(H / 2 - ry * math.sin(t) + rng.integers(-8, 9))))


SHAPES = [(0, 0), (0, 7), (9, 0), (1, 1), (3, 2), (2, 3), (17, 17), (40, 13), (13, 40),
          (300, 7), (7, 300), (1, 2000), (2000, 1), (5000, 5001), (20000, 26000),
          (2**24, 31), (31, 2**24), (2**14, 2**14 + 1), (4097, 2**17)]


@pytest.mark.parametrize("rx, ry", SHAPES)
def test_forced_far_ellipse_is_the_kernels_ellipse(rx, ry):
    rng = np.random.default_rng(rx * 7919 + ry)
    for _ in range(12 if rx + ry < 10**6 else 2):     # the kernel steps a whole quadrant
        xc, yc = _near_outline(rng, rx, ry)
        want, got, fill_want, fill_got = fb("1"), fb("1"), fb("1"), fb("1")
        sl.draw.ellipse(want, xc, yc, rx, ry)
        far.outline(got, xc, yc, rx, ry, got.pixel(1), False)
        assert lit(got) == lit(want), (xc, yc, rx, ry)
        sl.draw.fill_ellipse(fill_want, xc, yc, rx, ry)
        far.fill(fill_got, xc, yc, rx, ry, 1, None, False, None)
        assert lit(fill_got) == lit(fill_want), (xc, yc, rx, ry)


@pytest.mark.parametrize("r", [0, 1, 2, 3, 10, 57, 1000, 2**14, 2**20 + 3, 2**30])
def test_forced_far_circle_is_the_kernels_circle(r):
    rng = np.random.default_rng(r)
    for _ in range(12):
        xc, yc = _near_outline(rng, r, r)
        want, got, fill_want, fill_got = fb("1"), fb("1"), fb("1"), fb("1")
        sl.draw.circle(want, xc, yc, r)
        far.outline(got, xc, yc, r, r, got.pixel(1), True)
        assert lit(got) == lit(want), (xc, yc, r)
        sl.draw.fill_circle(fill_want, xc, yc, r)
        far.fill(fill_got, xc, yc, r, r, 1, None, True, None)
        assert lit(fill_got) == lit(fill_want), (xc, yc, r)


@pytest.mark.parametrize("rx, ry", [(0, 0), (1, 1), (7, 7), (30, 30), (3, 11), (40, 13),
                                    (2000, 2000), (2000, 7)])
def test_forced_far_arcs_and_pies_are_the_kernels(rx, ry):
    from scanline.draw import curved
    rng = np.random.default_rng(rx * 31 + ry)
    for _ in range(16):
        xc, yc = _near_outline(rng, rx, ry)
        a0, a1 = rng.uniform(-7, 7, 2)
        for closed, name in ((True, "arc"), (False, "pie")):
            region = curved._sector(a0, a1, closed=closed)
            want, got = fb("1"), fb("1")
            getattr(sl.draw, name)(want, xc, yc, rx, ry, a0, a1)
            if region is not None and closed:
                far.arc(got, xc, yc, rx, ry, region, 1, rx == ry)
            elif region is not None:
                far.fill(got, xc, yc, rx, ry, 1, None, rx == ry, None, region)
            assert lit(got) == lit(want), (name, xc, yc, rx, ry, a0, a1)


def test_far_arcs_and_pies():
    top = (20, 15 - 2**40, 2**40, 2**40)
    # the visible top of the circle is at polar angle pi/2 +- 2e-11
    assert lit(_draw(lambda f: sl.draw.arc(f, *top, math.pi / 2, math.pi))) == {
        (x, 15) for x in range(21)}
    # slices that share a ray tile the disk exactly once, far away too
    a, b = image(lambda f: sl.draw.pie(f, *top, 0.0, math.pi / 2)), image(
        lambda f: sl.draw.pie(f, *top, math.pi / 2, 2 * math.pi))
    whole = image(lambda f: sl.draw.fill_circle(f, *top[:3]))
    assert a.any() and b.any() and not (a & b).any()
    np.testing.assert_array_equal(a | b, whole)
    # a hollow far pie is its arc and radii
    assert image(lambda f: sl.draw.pie(f, *top, 1.0, 2.0, style=sl.FillStyle.hollow())).any()


# -- chords --------------------------------------------------------------------------

CHORD_STYLES = [None, sl.FillStyle.hollow(), sl.FillStyle.hatch(angle=0.5, spacing=3)]


@pytest.mark.parametrize("rx, ry", [(0, 0), (0, 6), (1, 1), (7, 7), (30, 30), (3, 11),
                                    (40, 13), (2000, 2000), (2000, 7)])
def test_forced_far_chords_are_the_kernels(rx, ry):
    # the far drawing (spans of the far fill, outline, fill styles) given the
    # kernels' half-plane: exactly the kernel's chord
    from scanline.draw import curved
    rng = np.random.default_rng(rx * 37 + ry)
    for i in range(18):
        xc, yc = _near_outline(rng, rx, ry)
        a0, a1 = rng.uniform(-7, 7, 2)
        style = CHORD_STYLES[i % 3]
        want, got = fb("L"), fb("L")
        sl.draw.chord(want, xc, yc, rx, ry, a0, a1, 200, style=style)
        found = curved._chord_region(rx, ry, a0, a1)
        if found is not None:
            curved._far_cut(got, xc, yc, rx, ry, a0, a1, 200, style, found)
        np.testing.assert_array_equal(got.to_array(), want.to_array(), str((xc, yc, a0, a1)))


@pytest.mark.parametrize("rx, ry", [(1, 1), (7, 7), (30, 30), (3, 11), (40, 13), (2000, 2000),
                                    (2000, 7), (2**29, 2**29)])
def test_the_exact_chord_line_agrees_with_the_kernels_but_at_its_resolution(rx, ry):
    # the far line (exact, through the ray ends) and the kernels' (float ends, a
    # normal resolved to 2**-30) may differ only for centers within
    # 1.4e-9 (r + d) of the exact line, d the distance from the chord's ends
    from scanline.draw import curved
    rng = np.random.default_rng(rx * 5 + ry)
    for _ in range(12):
        xc, yc = _near_outline(rng, rx, ry)
        a0, a1 = rng.uniform(-7, 7, 2)
        want, got = fb("1"), fb("1")
        sl.draw.chord(want, xc, yc, rx, ry, a0, a1)
        found = curved._chord_region(rx, ry, a0, a1, far=True)
        if found is not None:
            curved._far_cut(got, xc, yc, rx, ry, a0, a1, 1, None, found)
        differ = lit(got) ^ lit(want)
        if differ:
            pa, pb = ((xc + u, yc + w) for u, w in (ray_end(rx, ry, a0), ray_end(rx, ry, a1)))
            length = ((pb[0] - pa[0]) ** 2 + (pb[1] - pa[1]) ** 2).sqrt()
            for x, y in differ:
                d = float(min(((Decimal(x) - p[0]) ** 2 + (Decimal(y) - p[1]) ** 2).sqrt()
                              for p in (pa, pb)))
                assert abs(float(_cross(pa, pb, x, y) / length)) <= 1.4e-9 * (max(rx, ry) + d)


def _cross(p, q, x, y):
    """(q - p) x ((x, y) - p) in 700-digit decimals: < 0 right of p -> q."""
    return (q[0] - p[0]) * (Decimal(y) - p[1]) - (q[1] - p[1]) * (Decimal(x) - p[0])


def ray_end(rx, ry, t):
    """The ideal ellipse's point on the ray of direction (round(cos t 2**30),
    round(sin t 2**30)) (the sectors' resolution of an angle), in 700-digit
    decimals, relative to the center."""
    ux, uy = round(math.cos(t) * 2**30), round(math.sin(t) * 2**30)
    s = (Decimal(ry) * ux) ** 2 + (Decimal(rx) * uy) ** 2
    k = Decimal(rx) * ry / s.sqrt()
    return k * ux, k * uy


def chord_reference(xc, yc, rx, ry, a, b, disk):
    """The pixels of ``disk`` (the filled conic) strictly right of the line P_a -> P_b
    (no pixel center within 1e-6 pixel of it: no tie to decide)."""
    pa, pb = ((xc + u, yc + w) for u, w in (ray_end(rx, ry, a), ray_end(rx, ry, b)))
    length = ((pb[0] - pa[0]) ** 2 + (pb[1] - pa[1]) ** 2).sqrt()
    out = set()
    for x, y in disk:
        c = _cross(pa, pb, x, y) / length
        assert abs(c) > Decimal("1e-6"), (x, y)
        if c < 0:
            out.add((x, y))
    return out


def _on_chord(rx, ry, a, b, at=0.5):
    """A center putting the point at fraction ``at`` of the chord at the frame's
    middle."""
    pa, pb = ray_end(rx, ry, a), ray_end(rx, ry, b)
    m = [pa[i] + (pb[i] - pa[i]) * Decimal(at) for i in (0, 1)]
    return int(W // 2 - m[0]), int(H // 2 - m[1])


def _disk(xc, yc, rx, ry):
    return lit(_draw(lambda f: (sl.draw.fill_circle(f, xc, yc, rx) if rx == ry
                                else sl.draw.fill_ellipse(f, xc, yc, rx, ry))))


FAR_CHORDS = [   # (rx, ry, a, b, where): the frame over the chord at fraction ``where``
    (2**40, 2**40, 1.0, 2.5, 0.5), (2**40, 2**40, 2.5, 1.0, 0.3),
    (2**40 + 1, 2**40 + 1, math.pi / 2 - 4e-6, math.pi / 2 + 3e-6, 0.5),   # near the top
    (10**12, 3 * 10**11, -0.3, 2.9, 0.8), (10**300, 10**300, 0.0, 1.0, 0.5),
    (10**300, 10**300, 3.0, 1.0, 0.61), (3 * 10**299, 10**300, 4.0, 5.5, 0.5),
    (2**62, 2**24, 0.2, 3.3, 0.1), (10**300, 7 * 10**10, 1.0, -1.2, 0.5),   # a needle
]


@pytest.mark.parametrize("rx, ry, a, b, where", FAR_CHORDS)
def test_far_chords_crossing_the_frame_match_an_exact_reference(rx, ry, a, b, where):
    xc, yc = _on_chord(rx, ry, a, b, where)
    disk = _disk(xc, yc, rx, ry)
    got = lit(_draw(lambda f: sl.draw.chord(f, xc, yc, rx, ry, a, b)))
    other = lit(_draw(lambda f: sl.draw.chord(f, xc, yc, rx, ry, b, a)))
    want = chord_reference(xc, yc, rx, ry, a, b, disk)
    assert got == want and 0 < len(got) < len(disk)      # the line crosses the frame
    assert other == disk - got                           # (b, a): the rest, exactly


def test_far_chords_beside_the_frame_degenerate_and_whole():
    r = 10**300
    xc, yc = 20, 15                       # the frame about the center: deep inside
    every = {(x, y) for x in range(W) for y in range(H)}
    for a, b, want in [(0.0, 1.0, set()), (1.0, 0.0, every),       # beyond the chord, or not
                       (0.0, math.pi, {p for p in every if p[1] > 15}),   # the diameter
                       (math.pi, 2 * math.pi, {p for p in every if p[1] <= 15}),
                       (1.0, 1.0, set()), (1.0, 1.0 + 2 * math.pi, every),  # nothing, all
                       (2.0, 2.0 + 1e-12, set()), (2.0, 2.0 - 1e-12, every)]:  # below 1e-9
        for rx, ry in [(r, r), (r, r // 3)]:
            assert lit(_draw(lambda f: sl.draw.chord(f, xc, yc, rx, ry, a, b))) == want, (a, b)
    # a chord whose arc is off the frame, its line far beyond: all or nothing
    top = (20, 15 - 2**40, 2**40, 2**40)
    assert not lit(_draw(lambda f: sl.draw.chord(f, *top, -2.0, -1.0)))
    assert lit(_draw(lambda f: sl.draw.chord(f, *top, -1.0, -2.0))) == _disk(*top)
    # a sweep just above the resolution: the sliver below the top, 1.4e-5 deep,
    # holds the top row only (pixel centers at y = 15, the ideal top)
    t = math.pi / 2
    sliver = lit(_draw(lambda f: sl.draw.chord(f, *top, t - 5e-9, t + 5e-9)))
    assert sliver == chord_reference(*top, t - 5e-9, t + 5e-9, _disk(*top)) == {
        (x, 15) for x in range(W)}


def test_a_hollow_far_chord_is_its_arc_and_its_exact_line():
    rx = ry = 10**300
    a, b = 0.0, 1.0
    xc, yc = _on_chord(rx, ry, a, b)
    got = lit(_draw(lambda f: sl.draw.chord(f, xc, yc, rx, ry, a, b,
                                             style=sl.FillStyle.hollow())))
    pa, pb = ((xc + u, yc + w) for u, w in (ray_end(rx, ry, a), ray_end(rx, ry, b)))
    length = ((pb[0] - pa[0]) ** 2 + (pb[1] - pa[1]) ** 2).sqrt()
    # the arc is far off the frame: only the line, its pixels within a pixel of it,
    # one per row (the line is y-major: slope -cot(1/2))
    assert got and all(abs(_cross(pa, pb, x, y) / length) < 0.75 for x, y in got)
    assert sorted(y for _, y in got) == list(range(H))


def test_far_chords_are_bounded():
    f = fb()
    with bounded(refusals=False):    # 20 s, 512 MiB; any error fails
        sl.draw.chord(f, 1e308, -1e308, 1.7e308, 1.7e308, 0.5, 2.0)
        sl.draw.chord(f, -1e300, 15, 1e300 + 30, 1e300, -0.1, 0.1, style=sl.FillStyle.hollow())
        sl.draw.chord(f, 20, 15, 1e308, 1e-3, 1.0, 5.0)
    assert f.to_array().any()


# -- beyond the limits: independent references ---------------------------------------

def midpoint_ellipse_quadrant(rx, ry):
    """The notes' midpoint ellipse (chapter 2, Q.6) stepped in full with Python
    integers (decision parameters times 4), as an independent reference: region 1
    while 2 ry^2 x < 2 rx^2 y, region 2 while y > 0, then the run to (rx, 0)."""
    rx2, ry2 = rx * rx, ry * ry
    x, y = 0, ry
    pts = [(x, y)]
    p = 4 * ry2 - 4 * rx2 * ry + rx2
    while 2 * ry2 * x < 2 * rx2 * y:
        x += 1
        if p < 0:
            p += 4 * (2 * ry2 * x + ry2)
        else:
            y -= 1
            p += 4 * (2 * ry2 * x - 2 * rx2 * y + ry2)
        pts.append((x, y))
    p = ry2 * (2 * x + 1) ** 2 + 4 * rx2 * (y - 1) ** 2 - 4 * rx2 * ry2
    while y > 0:
        y -= 1
        if p > 0:
            p += 4 * (rx2 - 2 * rx2 * y)
        else:
            x += 1
            p += 4 * (2 * ry2 * x - 2 * rx2 * y + rx2)
        pts.append((x, y))
    while x < rx:
        x += 1
        pts.append((x, 0))
    return pts


def mirrored_in_frame(pts, xc, yc):
    return {(xc + sx * a, yc + sy * b) for a, b in pts for sx in (1, -1) for sy in (1, -1)
            if 0 <= xc + sx * a < W and 0 <= yc + sy * b < H}


@pytest.mark.parametrize("rx, ry", [(2_000, 300_000), (30_000, 29_999), (500_001, 1_100),
                                    (123_457, 98_765)])
def test_ellipses_beyond_the_limits_match_the_full_midpoint_loop(rx, ry):
    assert rx * ry > sl.draw.conics.ELLIPSE_PRODUCT_LIMIT or max(rx, ry) > 2**24
    quadrant = midpoint_ellipse_quadrant(rx, ry)
    rng = np.random.default_rng(rx + ry)
    # frames over the axes, over the slope -1 point, and random outline points
    d = math.hypot(rx * rx, ry * ry)
    spots = [(rx, 0), (0, ry), (rx * rx / d, ry * ry / d), (rx - 3, 1), (2, ry - 1)]
    spots += [(rx * abs(math.cos(t)), ry * abs(math.sin(t))) for t in rng.uniform(0, 7, 4)]
    for a, b in spots:
        xc, yc = int(W // 2 - a), int(H // 2 - b)
        f = fb("1")
        sl.draw.ellipse(f, xc, yc, rx, ry)
        assert lit(f) == mirrored_in_frame(quadrant, xc, yc), (xc, yc)
        # the fill: from the left-most to the right-most outline pixel of each row
        g = fb("1")
        sl.draw.fill_ellipse(g, xc, yc, rx, ry)
        ends = {}
        for x, y in quadrant:
            ends[y] = max(ends.get(y, -1), x)
        want = {(x, y) for y in range(H) if abs(y - yc) in ends
                for x in range(W) if abs(x - xc) <= ends[abs(y - yc)]}
        assert lit(g) == want


getcontext().prec = 700


def nearest_row(r, x):
    """round(sqrt(r**2 - x**2)) in 700-digit decimals: the midpoint circle's octant
    point (the midpoints are never on the circle, so there is no tie)."""
    return int((Decimal(r * r - x * x).sqrt()).to_integral_value(rounding="ROUND_HALF_EVEN"))


def circle_reference(xc, yc, r):
    out = set()
    for col in range(W):
        x = abs(col - xc)
        if x < r and x <= nearest_row(r, x):
            out |= {(col, yc + s * nearest_row(r, x)) for s in (1, -1)}
    for row in range(H):
        x = abs(row - yc)
        if x < r and x <= nearest_row(r, x):
            out |= {(xc + s * nearest_row(r, x), row) for s in (1, -1)}
    return {(x, y) for x, y in out if 0 <= x < W and 0 <= y < H}


@pytest.mark.parametrize("xc, yc, r", [
    (20, 15 - 2**40, 2**40),                          # the top crosses the frame
    (-10**12, 15, 10**12 + 20),                       # a far center, r reaching in
    (20 - 2**62, 15 - 3 * 2**61, 2**62),              # over a random-ish angle
    (int(-1e300), 17, int(1e300) + 25),
    (int(7e299), int(7e299), int(1e300 * 2**0.5) - 7),   # near the 45-degree point
    (20, 15 - 2**40 - 1, 2**40),                      # tangent to the bottom edge from below
])
def test_huge_circles_match_the_nearest_pixel_reference(xc, yc, r):
    f = fb("1")
    sl.draw.circle(f, xc, yc, r)
    want = circle_reference(xc, yc, r)
    assert lit(f) == want
    if yc == 15 - 2**40:
        assert len(want) == W                         # the whole row y = 15


def test_far_arguments_as_floats_round_as_the_kernels_do():
    # 1e12 + 0.5 rounds up (halves up), as every coordinate does
    a = image(lambda f: sl.draw.circle(f, 20.0, 15 - 1e12 - 0.5, 1e12))
    b = image(lambda f: sl.draw.circle(f, 20, 15 - 10**12, 10**12))
    np.testing.assert_array_equal(a, b)


def nearest_on(a, b, t):
    """round(b sqrt(1 - t**2 / a**2)) in 700-digit decimals: the nearest pixel to the
    ellipse along the other axis at offset t."""
    t = Decimal(t)
    return int((Decimal(b) * (1 - t * t / Decimal(a) ** 2).sqrt()).to_integral_value(
        rounding="ROUND_HALF_EVEN"))


def test_huge_ellipses_match_the_nearest_pixel_where_it_is_unambiguous():
    # far from the slope -1 point the midpoint ellipse is the pixel nearest the
    # curve in each column (region 1) or row (region 2)
    rx, ry = 10**300, 3 * 10**299
    xc, yc = 20, 15 - ry                              # the top, x = 0 .. 20 in region 1
    top = {(col, yc + nearest_on(rx, ry, col - xc)) for col in range(W)}
    assert lit(_draw(lambda f: sl.draw.ellipse(f, xc, yc, rx, ry))) == top
    xc, yc = 20 - rx, 15                              # the right tip, region 2
    tip = {(xc + nearest_on(ry, rx, row - yc), row) for row in range(H)}
    assert lit(_draw(lambda f: sl.draw.ellipse(f, xc, yc, rx, ry))) == tip
    assert {y for _, y in top} == {15} and {x for x, _ in tip} == {20}


# -- degenerate and special cases ----------------------------------------------------

def test_degenerate_far_conics():
    # r = 0 far away: nothing; rx = 0 or ry = 0: segments
    assert not image(lambda f: sl.draw.circle(f, 1e12, 3, 0)).any()
    a = image(lambda f: sl.draw.ellipse(f, 20, -10**12, 0, 10**12 + 10))
    b = image(lambda f: sl.draw.line(f, 20, 0, 20, 10))
    np.testing.assert_array_equal(a, b)
    a = image(lambda f: sl.draw.ellipse(f, -10**15, 4, 10**15 + 30, 0))
    b = image(lambda f: sl.draw.line(f, 0, 4, 30, 4))
    np.testing.assert_array_equal(a, b)
    a = image(lambda f: sl.draw.fill_ellipse(f, -10**15, 4, 10**15 + 30, 0))
    np.testing.assert_array_equal(a, b)


def test_huge_conic_about_the_frame():
    # the outline is far outside: nothing; the fill covers everything
    for r in (2**31, 10**12, 1e300):
        assert not image(lambda f: sl.draw.circle(f, 20, 15, r)).any()
        assert not image(lambda f: sl.draw.ellipse(f, 20, 15, r, r / 3)).any()
        assert image(lambda f: sl.draw.fill_circle(f, 20, 15, r)).all()
        assert image(lambda f: sl.draw.fill_ellipse(f, 20, 15, r, r / 3)).all()
        assert image(lambda f: sl.draw.fill_circle(f, 20, 15, r, antialias=True)).all()
        assert not image(lambda f: sl.draw.circle(f, 20, 15, r, width=5)).any()


def test_tangent_to_the_frame_edge():
    # the lowest row of a circle above the frame: y = H exactly, just outside
    assert not image(lambda f: sl.draw.circle(f, 20, H + 2**40, 2**40)).any()
    a = image(lambda f: sl.draw.circle(f, 20, H - 1 + 2**40, 2**40))
    assert (a[0] == 255).all() and not a[1:].any()


def test_nan_and_inf_still_refused_by_name():
    for bad in (np.nan, np.inf, -np.inf):
        for call, name in [(lambda: sl.draw.circle(fb(), bad, 3, 2**40), "xc"),
                           (lambda: sl.draw.ellipse(fb(), 3, 3, 2**40, bad), "ry"),
                           (lambda: sl.draw.fill_circle(fb(), 3, bad, 1e12), "yc"),
                           (lambda: sl.draw.circle(fb(), 3, 3, bad, width=3), "r")]:
            with pytest.raises(sl.ArgumentValueError, match=f"{name} must be a finite"):
                call()
        with pytest.raises(sl.ArgumentValueError, match="finite"):
            sl.draw.circles(fb(), [[1e12, 0, 1e12], [bad, 1, 1]])
    with pytest.raises(sl.ArgumentValueError, match="r must be >= 0"):
        sl.draw.circle(fb(), 1e12, 3, -1e12)


# -- wide and antialiased dashed degenerate ellipses: segments there and back ---------

def _legs(xc, yc, rx, ry):
    """The degenerate ellipse's path (t = 0 .. 2 pi of (xc + rx cos t, yc + ry sin t))
    as legs (a0, a1, s0) along its line: coordinate a (x for ry = 0, y for rx = 0)
    from a0 to a1, path length s0 at a0."""
    if ry == 0:
        return [(xc + rx, xc - rx, 0), (xc - rx, xc + rx, 2 * rx)]
    return [(yc, yc + ry, 0), (yc + ry, yc - ry, ry), (yc - ry, yc, 3 * ry)]


def _on_set(legs, lengths, phase, lo, hi):
    """The dashes' intervals of coordinate a within [lo, hi] (exact Fractions): the
    pattern of ``lengths`` (its period the float sum, as the kernels take it) from
    ``phase`` at path length 0."""
    total = 0.0
    for c in lengths:
        total += c
    period = Fraction(total)
    out = []
    for a0, a1, s0 in legs:
        d = 1 if a1 > a0 else -1
        u, v = (max(lo, min(a0, a1)), min(hi, max(a0, a1)))
        if u > v:
            continue
        s_lo = min(s0 + d * (u - a0), s0 + d * (v - a0))          # path lengths seen
        s_hi = max(s0 + d * (u - a0), s0 + d * (v - a0))
        q = (Fraction(phase) + s_lo) // period - 1
        while q * period - Fraction(phase) <= s_hi:
            at = q * period - Fraction(phase)
            for k in range(0, len(lengths), 2):
                b0 = at + sum(Fraction(c) for c in lengths[:k])
                b1 = min(b0 + Fraction(lengths[k]), at + period)
                e0, e1 = max(b0, s_lo), min(b1, s_hi)
                if e0 < e1:
                    x0, x1 = a0 + d * (e0 - s0), a0 + d * (e1 - s0)
                    out.append((min(x0, x1), max(x0, x1)))
            q += 1
    return out


def degenerate_reference(xc, yc, rx, ry, width, lengths, phase, cap, tol):
    """Pixel centers of the stroke of the dashes along the degenerate ellipse (butt
    caps and miter joins: the dashes' rectangles; round caps and joins: the points
    within width / 2 of them), computed exactly, and those within ``tol`` of a
    membership boundary along the line (``near``)."""
    legs = _legs(xc, yc, rx, ry)
    centre = yc if ry == 0 else xc
    span = W if ry == 0 else H
    on = _on_set(legs, lengths, phase, -5, span + 5)
    ends = [e for iv in on for e in iv]
    lit, near = set(), set()
    for x in range(W):
        for y in range(H):
            a, lat = (x, y - centre) if ry == 0 else (y, x - centre)
            if 4 * lat * lat >= width * width:
                continue
            reach = 0.0 if cap == "butt" else math.sqrt(width * width / 4 - lat * lat)
            dist = min((0 if lo <= a <= hi else min(abs(a - lo), abs(a - hi))
                        for lo, hi in on), default=math.inf)
            if dist <= reach:
                lit.add((x, y))
            if any(abs(abs(a - e) - reach) < tol for e in ends):
                near.add((x, y))
    return lit, near


DEGENERATE_STYLES = [dict(width=3, dash=(4.4, 1.3, 0.9, 2.1), dash_phase=0.25, cap="butt"),
                     dict(width=2.5, dash=(3.7, 1.3), dash_phase=0.3, cap="round",
                          join="round")]


@pytest.mark.parametrize("rx, ry", [(0, 5), (9, 0), (0, 13), (30, 0), (0, 200), (2000, 0),
                                    (0, 60_000), (2**20, 0)])
def test_forced_far_dashed_degenerate_ellipses_are_the_kernels_but_for_their_polygon(rx, ry):
    # the kernels stroke the polygon conic_polyline, whose vertices lie at
    # sqrt(t / sin t) times the radii (the ellipse's area): its ends are up to 0.07
    # pixel beyond (xc +- rx, yc), its length at most 0.27 pixel more than 4 r, so
    # pixel centers within 0.3 pixel of a dash end (in the exact reference) may differ
    from scanline.linestyle import LineStyle
    rng = np.random.default_rng(rx + 7 * ry)
    for kw in DEGENERATE_STYLES:
        for _ in range(6):
            xc, yc = _near_outline(rng, rx, ry)
            want, got = fb("1"), fb("1")
            sl.draw.ellipse(want, xc, yc, rx, ry, 1, **kw)
            far.stroke(got, xc, yc, rx, ry, 1, LineStyle(**kw), False, False)
            ref, near = degenerate_reference(xc, yc, rx, ry, kw["width"], kw["dash"],
                                             kw["dash_phase"], kw["cap"], 0.3)
            assert lit(got) ^ lit(want) <= near, (xc, yc, kw)
            assert lit(got) ^ ref <= near, (xc, yc, kw)
            # antialiased: the same coverage but where a dash end moved
            want, got = image(lambda f: sl.draw.ellipse(f, xc, yc, rx, ry, antialias=True,
                                                        **kw)), fb()
            far.stroke(got, xc, yc, rx, ry, 255, LineStyle(**kw), True, False)
            diff = np.abs(got.to_array().astype(int) - want.astype(int))[::-1]
            ends = [e for iv in _on_set(_legs(xc, yc, rx, ry), kw["dash"], kw["dash_phase"],
                                        -5, max(W, H) + 5) for e in iv]
            for x, y in zip(*np.nonzero(diff.T)):    # pixels a dash end's cap may touch
                a, lat = (x, y - yc) if ry == 0 else (y, x - xc)
                assert abs(lat) <= kw["width"] / 2 + 1, (xc, yc, kw, x, y)
                assert min(abs(a - e) for e in ends) <= kw["width"] / 2 + 1.5, (xc, yc, kw, x, y)
            assert diff.max() <= 80, (xc, yc, kw)


FAR_DEGENERATE = [
    (-10**12, 12, 10**12 + 25, 0),             # its right end in the frame, at x = 25
    (10**12, 7, 10**12 + 3, 0),                # from x = -3: across the frame, both legs
    (17, -10**300, 0, 10**300 + 20),           # its top end at y = 20
    (5, 10**300, 0, 10**300 - 10),             # from y = 10 up
    (20, 15, 10**300, 0),                      # center in the frame, ends at +-1e300
    (20, 15, 0, 10**300 + 1),
    (20, 15, 1e300, 0),                        # a float radius, rounded
    (-10**12 + 7, 3, 10**12, 0),               # the left end at x = -10**12 + 7 - 10**12
]


@pytest.mark.parametrize("xc, yc, rx, ry", FAR_DEGENERATE)
@pytest.mark.parametrize("kw", DEGENERATE_STYLES)
def test_far_dashed_degenerate_ellipses_match_the_exact_reference(xc, yc, rx, ry, kw):
    # exact: only pixel centers on a membership boundary (ties, 1e-9) may differ
    got = lit(_draw(lambda f: sl.draw.ellipse(f, xc, yc, rx, ry, **kw)))
    rx, ry = (int(c) for c in (rx, ry))
    want, near = degenerate_reference(xc, yc, rx, ry, kw["width"], kw["dash"],
                                      kw["dash_phase"], kw["cap"], 1e-9)
    assert got ^ want <= near and len(want) > 20
    if kw["cap"] == "butt" and ry == 0:
        # antialiased: the coverage adds up to the dashes' area in the frame
        cover = image(lambda f: sl.draw.ellipse(f, xc, yc, rx, ry, antialias=True, **kw))
        on = _on_set(_legs(xc, yc, rx, ry), kw["dash"], kw["dash_phase"], Fraction(-1, 2),
                     W - Fraction(1, 2))
        merged, area = sorted(on), Fraction(0)
        end = None
        for lo, hi in merged:                  # the union's length, times the width
            lo = lo if end is None else max(lo, end)
            if end is None or hi > end:
                area += hi - lo
                end = hi
        assert abs(cover.sum() / 255 - 3 * float(area)) <= 0.01 * 3 * float(area) + 1


def test_far_dashed_degenerate_ellipses_outside_draw_nothing_in_bounded_time():
    with bounded(refusals=False):    # 20 s, 512 MiB; any error fails
        for args in [(20, -10**12, 10**12, 0), (10**12, 15, 10**12 - 100, 0),
                     (-10**300, 15, 0, 10**300), (1e12, 3, 0, 0),
                     (-1e300, -1e300, 1e300, 0)]:
            for kw in DEGENERATE_STYLES + [dict(dash=(2, 1))]:
                assert not image(lambda f: sl.draw.ellipse(f, *args, antialias=True, **kw)).any()
                assert not image(lambda f: sl.draw.ellipse(f, *args, **kw)).any()


def decimal_pi():
    """pi to the context's precision (the decimal module's documented recipe)."""
    getcontext().prec += 2
    lasts, t, s, n, na, d, da = 0, Decimal(3), 3, 1, 0, 0, 24
    while s != lasts:
        lasts = s
        n, na = n + na, na + 8
        d, da = d + da, da + 32
        t = (t * n) / d
        s += t
    getcontext().prec -= 2
    return +s


def quarter_perimeter(a, b):
    """A quarter of the ellipse's perimeter by the arithmetic-geometric mean,
    C = 2 pi / M(a, b) (a**2 - sum_n 2**(n-1) c_n**2), c_0**2 = a**2 - b**2,
    c_(n+1) = (a_n - b_n) / 2, in 700-digit decimals."""
    a, b = Decimal(max(a, b)), Decimal(min(a, b))
    a0 = a
    total, c2, n = Decimal(0), a * a - b * b, 0
    while c2 > Decimal(10) ** -650 * a0 * a0:
        total += Decimal(2) ** (n - 1) * c2
        a, b, c2, n = (a + b) / 2, (a * b).sqrt(), ((a - b) / 2) ** 2, n + 1
    return decimal_pi() / (2 * a) * (a0 * a0 - total)


def test_the_references_arc_lengths():
    special = pytest.importorskip("scipy.special")
    for a, b in [(5, 5), (3, 1), (1000, 7), (10, 9)]:
        for p, q in ((a, b), (b, a)):
            assert math.isclose(float(quarter_perimeter(p, q)),
                                a * special.ellipe(1 - b * b / (a * a)), rel_tol=1e-13)


def _dashes_on(s, lengths, phase):
    """Whether arc length s (decimal) is on a dash of ``lengths`` (floats, exactly)
    from ``phase``, and its distance to the nearest dash end."""
    period = 0.0                  # the period is the float sum of the lengths (kernels)
    for c in lengths:
        period += c
    t = (s + Decimal(phase)) % Decimal(period)
    edges, at = [Decimal(0)], Decimal(0)
    state = None
    for i, c in enumerate(lengths):
        at += Decimal(c)
        edges.append(at)
        if state is None and t < at:
            state = i % 2 == 0
    return state, float(min(abs(t - e) for e in edges))


@pytest.mark.parametrize("rx, ry", [(2**40 + 12345, 2**40 + 12345), (10**300, 3 * 10**299),
                                    (3 * 10**299, 10**300), (10**18 + 7, 10**15)])
@pytest.mark.parametrize("dash, phase", [((3, 2), 0.5), ((4.4, 1.3, 0.9, 2.1), 0.25)])
def test_wide_dashed_huge_conics_count_their_dashes_from_xc_plus_rx(rx, ry, dash, phase):
    # the frame over the top (0, ry): the visible conic is the row y = 15 (it drops
    # by x**2 rx**-2 ry / 2 < 1e-12 there); arc length at column x is the quarter
    # perimeter minus (x - xc) (the curvature term x**3 / ry**2 is below 1e-20)
    xc, yc = 20, 15 - ry
    q = quarter_perimeter(rx, ry) if rx != ry else decimal_pi() * rx / 2
    got = lit(_draw(lambda f: sl.draw.ellipse(f, xc, yc, rx, ry, width=3, dash=dash,
                                              dash_phase=phase)))
    want, near, cols = set(), set(), []
    for x in range(W):
        on, margin = _dashes_on(q - (x - xc), dash, phase)
        column = {(x, 14), (x, 15), (x, 16)}
        if margin < 0.05:                    # a dash end within the tolerance of a center
            near |= column
        if on:
            cols.append(x)
            want |= column
    assert got ^ want <= near and len(near) <= 9 and 5 < len(cols) < W
    # antialiased: the coverage adds up to the dashes' area in the frame
    cover = image(lambda f: sl.draw.ellipse(f, xc, yc, rx, ry, width=3, dash=dash,
                                            dash_phase=phase, antialias=True))
    area = 0.0
    for k in range(-2000, 2000):                       # the dashes along the row, exactly
        x = (-0.5 + k / 50)
        area += 0.02 * 3 * (-0.5 <= x < W - 0.5 and _dashes_on(q - (Decimal(x) + Decimal("0.01") - xc),
                                                                dash, phase)[0])
    assert abs(cover.sum() / 255 - area) <= 0.02 * area + 1


def test_wide_dashed_far_circle_at_any_angle_matches_the_radial_reference():
    # exact reference: a pixel center p is lit when | |p - c| - r | < w / 2 and its
    # arc length r theta(p) (counterclockwise from (xc + r, yc)) is on a dash; only
    # centers within 0.1 pixel of the band's edges or of a dash end may differ (the
    # stroke follows a polygon within 0.025 pixel, dashes its length)
    r = 2**31 + 99
    for t in (0.7, 2.4, 4.0, 5.9):
        xc, yc = 20 - round(r * math.cos(t)), 15 - round(r * math.sin(t))
        dash, phase = (3.5, 1.5), 0.2
        got = lit(_draw(lambda f: sl.draw.circle(f, xc, yc, r, width=2.6, dash=dash,
                                                 dash_phase=phase)))
        want, near = set(), set()
        for x in range(W):
            for y in range(H):
                d = math.hypot(x - xc, y - yc) - r        # exact enough: ints to floats
                s = Decimal(r) * Decimal(math.atan2(y - yc, x - xc) % (2 * math.pi))
                on, margin = _dashes_on(s, dash, phase)
                if abs(abs(d) - 1.3) < 0.1 or margin < 0.1:
                    near.add((x, y))
                if abs(d) < 1.3 and on:
                    want.add((x, y))
        assert len(want) > 40 and got ^ want <= near, t


@pytest.mark.parametrize("rx, ry", [(0, 5), (1, 1), (9, 9), (40, 40), (7, 30), (30, 7),
                                    (300, 2000), (60_000, 60_000)])   # within SEQUENCE_LIMIT
def test_forced_far_dashed_conics_are_the_kernels(rx, ry):
    from scanline.linestyle import LineStyle
    rng = np.random.default_rng(rx + 3 * ry)
    kinds = [{"dash": (2, 1)}, {"dash": (3.7, 1.3), "dash_phase": 0.6}, {"dash": "dotted"},
             {"dash": 0b1111000011001100, "dash_phase": 3}, {"dash": (1, 1, 4, 2)},
             {"dash": "dashed", "pen": "circle", "width": 3}]
    for kw in kinds:
        xc, yc = _near_outline(rng, rx, ry)
        want, got = fb("1"), fb("1")
        (sl.draw.circle(want, xc, yc, rx, 1, **kw) if rx == ry
         else sl.draw.ellipse(want, xc, yc, rx, ry, 1, **kw))
        far.stroke(got, xc, yc, rx, ry, 1, LineStyle(**kw), False, rx == ry)
        assert lit(got) == lit(want), (xc, yc, kw)


def test_a_huge_dashed_circle_counts_its_dashes_from_xc_plus_r():
    # independent reference: the sequence runs from (r, 0) through the octant's
    # mirror image and the octant to the top (0, r); Xd is the octant's last column
    # (x <= round(sqrt(r^2 - x^2))), its diagonal steps are the drops of y, and the
    # top pixels near (0, r) are unit steps apart
    r = 2**40 + 12345
    xc, yc = 20, 15 - r
    x0 = int(Decimal(r) / Decimal(2).sqrt())
    xd = max(x for x in range(x0 - 3, x0 + 4) if x <= nearest_row(r, x))
    yd = nearest_row(r, xd)
    dup = int(yd == xd)
    steps = 2 * xd + 1 - dup                          # from (r, 0) to (0, r)
    diagonal = 2 * (r - yd) + 1 - dup
    top_k = steps
    top_s = Decimal(steps - diagonal) + Decimal(diagonal) * Decimal(2).sqrt()
    dotted = lit(_draw(lambda f: sl.draw.circle(f, xc, yc, r, dash="dotted")))
    dashed = lit(_draw(lambda f: sl.draw.circle(f, xc, yc, r, dash=(3, 2), dash_phase=0.5)))
    want_dotted, want_dashed = set(), set()
    for col in range(W):
        u = col - xc                                  # k and s grow to the left of the top
        if (top_k - u) % 2 == 0:                      # "dotted": bits 1010..., bit 0 on
            want_dotted.add((col, 15))
        if (top_s - u + Decimal("0.5")) % 5 < 3:
            want_dashed.add((col, 15))
    assert dotted == want_dotted and dashed == want_dashed and 10 < len(dashed) < 30


# -- strokes, pens, antialiasing, areas ------------------------------------------------

def test_thick_and_pen_strokes_of_a_far_circle_are_its_straight_top():
    # at r = 2**40 the circle's top deviates from y = 15 by 1e-9 over the frame
    top = (20, 15 - 2**40, 2**40)
    for kw in ({"width": 3}, {"width": 4.5, "cap": "round"}, {"pen": "square"},
               {"pen": np.ones((3, 2), bool)}):
        a = image(lambda f: sl.draw.circle(f, *top, **kw))
        b = image(lambda f: sl.draw.polyline(f, [(-60, 15), (100, 15)], **kw))
        assert a.any()
        np.testing.assert_array_equal(a, b)
    a = image(lambda f: sl.draw.circle(f, *top, antialias=True))
    b = image(lambda f: sl.draw.antialias.lines(f, [(-60, 15, 100, 15)]))
    np.testing.assert_array_equal(a, b)


def _tip_geometry():
    """An ellipse far beyond the limits whose tip, in the frame, has a radius of
    curvature of 12 pixels: rx = 2e12, ry = sqrt(12 rx); and the ideal tip near
    the frame as a local polyline (cos t - 1 = -2 sin^2(t/2), no cancellation)."""
    rx = 2 * 10**12
    ry = math.isqrt(12 * rx)
    xc, yc = 30 - rx, 15
    t = np.linspace(-1e-5, 1e-5, 20001)
    local = np.stack([30 - 2 * rx * np.sin(t / 2) ** 2, 15 + ry * np.sin(t)], axis=1)
    return (xc, yc, rx, ry), local


def test_far_thick_and_antialiased_strokes_cover_the_ideal_areas():
    shapely = peer("shapely")
    from shapely.geometry import LineString, Polygon, box
    row, local = _tip_geometry()
    frame = box(-0.5, -0.5, W - 0.5, H - 0.5)
    curve = LineString(local)
    for width in (3, 6):
        band = curve.buffer(width / 2, cap_style="flat").intersection(frame)
        n = (image(lambda f: sl.draw.ellipse(f, *row, width=width)) > 0).sum()
        # pixel counts of a band follow its area within about its boundary length / 4
        assert abs(n - band.area) <= 0.25 * band.boundary.length, (width, n, band.area)
        cover = image(lambda f: sl.draw.ellipse(f, *row, width=width, antialias=True))
        assert abs(cover.sum() / 255 - band.area) <= 0.01 * band.area + 1, width
    # width-1 antialiased: the intensity is the length of the outline in the frame
    inside = curve.intersection(frame).length
    cover = image(lambda f: sl.draw.ellipse(f, *row, antialias=True))
    assert abs(cover.sum() / 255 - inside) <= 0.01 * inside + 1
    # filled, and filled by coverage
    area = Polygon(local).intersection(frame).area
    n = (image(lambda f: sl.draw.fill_ellipse(f, *row)) > 0).sum()
    assert abs(n - area) <= 0.25 * Polygon(local).intersection(frame).boundary.length
    cover = image(lambda f: sl.draw.fill_ellipse(f, *row, antialias=True))
    assert abs(cover.sum() / 255 - area) <= 0.005 * area + 1


def test_pixels_of_a_far_thick_stroke_are_those_within_half_its_width():
    # exact integer reference: a pixel center p is in the width-w stroke of the
    # circle when (r - w/2)**2 <= |p - c|**2 <= (r + w/2)**2 (w = 3.2: no ties)
    r = 2**45
    xc, yc = 20 - (r * 3) // 5, 15 - (r * 4) // 5          # the frame over the 3-4-5 point
    got = lit(_draw(lambda f: sl.draw.circle(f, xc, yc, r, width=3.2)))
    want = set()
    for x in range(W):
        for y in range(H):
            d2 = (x - xc) ** 2 + (y - yc) ** 2
            if (r - 1.6) ** 2 <= d2 <= (r + 1.6) ** 2:
                want.add((x, y))
    # the stroke is the polygon within 0.1 pixel of the circle, so only pixel
    # centers within 0.1 of the band's edges may differ
    near_edge = {(x, y) for x in range(W) for y in range(H)
                 if abs(math.sqrt((x - xc) ** 2 + (y - yc) ** 2) - r) - 1.6 > -0.1
                 and abs(math.sqrt((x - xc) ** 2 + (y - yc) ** 2) - r) - 1.6 < 0.1}
    assert want and got ^ want <= near_edge


def _draw(draw):
    f = fb()
    draw(f)
    return f


# -- batches -------------------------------------------------------------------------

def test_batches_draw_far_rows_in_order_with_their_colors():
    rows = [(20, 15, 6), (20, 15 - 2**40, 2**40), (-1e300, 0, 1e300), (20, 14 - 10**12, 10**12),
            (25, 18, 4)]
    colors = ["red", "lime", "blue", (255, 255, 0), "white"]
    for batch, one, extra in [(sl.draw.circles, sl.draw.circle, {}),
                              (sl.draw.circles, sl.draw.circle, {"width": 3}),
                              (sl.draw.fill_circles, sl.draw.fill_circle, {}),
                              (sl.draw.fill_circles, sl.draw.fill_circle, {"antialias": True})]:
        a = image(lambda f: batch(f, rows, colors, **extra), "RGB")
        b = image(lambda f: [one(f, *row, c, **extra) for row, c in zip(rows, colors)], "RGB")
        np.testing.assert_array_equal(a, b)
    erows = [(r[0], r[1], r[2], r[2] // 2 if r[2] > 100 else r[2]) for r in rows]
    for batch, one, extra in [(sl.draw.ellipses, sl.draw.ellipse, {}),
                              (sl.draw.fill_ellipses, sl.draw.fill_ellipse, {}),
                              (sl.draw.ellipses, sl.draw.ellipse, {"antialias": True})]:
        a = image(lambda f: batch(f, erows, colors, **extra), "RGB")
        b = image(lambda f: [one(f, *row, c, **extra) for row, c in zip(erows, colors)], "RGB")
        np.testing.assert_array_equal(a, b)
    # color arrays stay aligned with their rows
    rgb = np.array([[255, 0, 0], [0, 255, 0], [0, 0, 255], [9, 9, 9], [1, 2, 3]], np.uint8)
    a = image(lambda f: sl.draw.circles(f, rows, rgb), "RGB")
    b = image(lambda f: [sl.draw.circle(f, *row, tuple(c)) for row, c in zip(rows, rgb.tolist())],
              "RGB")
    np.testing.assert_array_equal(a, b)


def test_batches_within_the_limits_are_unchanged():
    rng = np.random.default_rng(3)
    rows = np.column_stack([rng.uniform(-20, 60, 50), rng.uniform(-20, 50, 50),
                            rng.uniform(0, 30, 50)])
    erows = np.column_stack([rows, rng.uniform(0, 30, 50)])
    for batch, one, r in [(sl.draw.circles, sl.draw.circle, rows),
                          (sl.draw.fill_circles, sl.draw.fill_circle, rows),
                          (sl.draw.ellipses, sl.draw.ellipse, erows),
                          (sl.draw.fill_ellipses, sl.draw.fill_ellipse, erows)]:
        a = image(lambda f: batch(f, r))
        b = image(lambda f: [one(f, *row) for row in r.tolist()])
        np.testing.assert_array_equal(a, b)


def test_a_million_far_rows_and_huge_radii_are_bounded():
    rng = np.random.default_rng(9)
    rows = np.column_stack([rng.uniform(-1e300, 1e300, 10**6), rng.uniform(-1e12, 1e12, 10**6),
                            rng.uniform(0, 1e308, 10**6)])
    rows[0] = (20, 15 - 2.0**40, 2.0**40)
    f = fb()
    with bounded(refusals=False):    # 20 s, 512 MiB; any error fails
        sl.draw.circles(f, rows)
        sl.draw.fill_circles(f, rows[:1000])
        sl.draw.ellipse(f, 1e308, -1e308, 1.7e308, 1.7e308)
        sl.draw.fill_ellipse(f, -1e308, 1e308, 1.7e308, 1.7e308, antialias=True)
        sl.draw.circle(f, 20, 15 - 1e307, 1e307, width=7)
    assert f.to_array().any()
