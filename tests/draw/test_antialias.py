"""Antialiased lines, conics and areas (scanline.draw.antialias).

Intensities are read from mode-"L" frame buffers (white on black: intensity =
level / 255).  References: the ideal lengths, perimeters and areas; shapely's
polygon area; a supersampled pure-numpy winding-number rasterizer written here.
"""

import math

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

import scanline as sl
from scanline._kernels.antialias import BAND_SHIFT
from scanline.draw import antialias as aa

#: Scan lines per band of the line kernel: tests of band edges straddle this row.
BAND = 1 << BAND_SHIFT


def intensity(fb):
    return fb.to_array().astype(np.float64) / 255.0


# -- reference: supersampled coverage ------------------------------------------------------
def reference_coverage(contours, width, height, rule, n=32):
    """Coverage of each pixel by an n x n grid of samples, inside by the winding
    number of all contours (nonzero) or its parity (even-odd).  Image order."""
    offs = (np.arange(n) + 0.5) / n - 0.5
    xs = (np.arange(width)[:, None] + offs[None, :]).ravel()
    ys = (np.arange(height)[:, None] + offs[None, :]).ravel()
    px, py = np.meshgrid(xs, ys)
    wind = np.zeros(px.shape, np.int64)
    for ring in contours:
        ring = np.asarray(ring, np.float64)
        for (x0, y0), (x1, y1) in zip(ring, np.roll(ring, -1, axis=0)):
            if y0 == y1:
                continue
            up = y1 > y0
            lo, hi = (y0, y1) if up else (y1, y0)
            crosses = (py >= lo) & (py < hi)
            xc = x0 + (py - y0) * (x1 - x0) / (y1 - y0)
            hit = crosses & (px < xc)
            wind += np.where(hit, 1 if up else -1, 0)
    inside = (wind != 0) if rule == "nonzero" else (wind % 2 == 1)
    cov = inside.reshape(height, n, width, n).mean(axis=(1, 3))
    return cov[::-1]


# -- lines -------------------------------------------------------------------------------
@pytest.mark.parametrize("k", range(16))
def test_line_intensity_is_its_length_in_every_octant(k):
    angle = k * math.pi / 8 + 0.21
    x0, y0, length = 60.37, 59.81, 52.6
    x1, y1 = x0 + length * math.cos(angle), y0 + length * math.sin(angle)
    fb = sl.FrameBuffer(121, 121, mode="L")
    aa.lines(fb, [(x0, y0, x1, y1)], "white")
    assert intensity(fb).sum() == pytest.approx(length, rel=0.02)


def test_long_lines_add_up_to_their_lengths():
    rng = np.random.default_rng(5)
    segs = rng.uniform(5, 395, (40, 4))
    for s in segs:
        fb = sl.FrameBuffer(400, 400, mode="L")
        aa.lines(fb, [s], "white")
        length = math.hypot(s[2] - s[0], s[3] - s[1])
        assert intensity(fb).sum() == pytest.approx(length, rel=0.02, abs=0.05)


def test_horizontal_line_is_wus_two_pixel_split_by_hand():
    # y = 0.75: rows 0 and 1 get 0.25 and 0.75; the end columns [0.25, 0.5] and
    # [3.5, 3.75] a quarter of that
    fb = sl.FrameBuffer(6, 3, mode="L")
    aa.lines(fb, [(0.25, 0.75, 3.75, 0.75)], "white")
    assert fb.to_array().tolist() == [
        [0, 0, 0, 0, 0, 0],
        [48, 191, 191, 191, 48, 0],     # 0.1875 * 255 = 47.8; 0.75 * 255 = 191.25
        [16, 64, 64, 64, 16, 0],        # 0.0625 * 255 = 15.9; 0.25 * 255 = 63.75
    ]


def test_diagonal_line_cross_section_by_hand():
    # slope 1 through pixel centers: each column spans sqrt(2) rows centered on
    # the line: the center pixel 1, its two neighbors (sqrt(2) - 1) / 2 each
    fb = sl.FrameBuffer(7, 7, mode="L")
    aa.lines(fb, [(0.5, 0.5, 5.5, 5.5)], "white")
    side = round((math.sqrt(2) - 1) / 2 * 255)
    a = fb.to_array()[::-1]
    for x in range(1, 6):
        assert a[x, x] == 255
        assert a[x + 1, x] == side and a[x - 1, x] == side


def test_line_is_independent_of_endpoint_order_and_mirrors():
    fwd = sl.FrameBuffer(40, 30, mode="L")
    back = sl.FrameBuffer(40, 30, mode="L")
    mirror = sl.FrameBuffer(40, 30, mode="L")
    aa.lines(fwd, [(3.3, 4.1, 35.2, 22.7)], "white")
    aa.lines(back, [(35.2, 22.7, 3.3, 4.1)], "white")
    aa.lines(mirror, [(39 - 3.3, 4.1, 39 - 35.2, 22.7)], "white")
    assert np.array_equal(fwd.to_array(), back.to_array())
    assert np.abs(fwd.to_array()[:, ::-1].astype(int) - mirror.to_array()).max() <= 1


def test_line_transposed_is_the_transpose():
    a = sl.FrameBuffer(30, 30, mode="L")
    b = sl.FrameBuffer(30, 30, mode="L")
    aa.lines(a, [(2.2, 3.7, 27.1, 13.4)], "white")
    aa.lines(b, [(3.7, 2.2, 13.4, 27.1)], "white")
    ta = a.to_array()[::-1]
    tb = b.to_array()[::-1]
    assert np.array_equal(ta.T, tb)


def test_zero_length_line_draws_nothing():
    fb = sl.FrameBuffer(5, 5, mode="L")
    aa.lines(fb, [(2.3, 2.3, 2.3, 2.3)], "white")
    assert fb.to_array().max() == 0


def test_line_batch_with_colors_equals_single_calls():
    segs = [(1.2, 1.5, 18.3, 9.9), (3.1, 12.2, 15.5, 0.4), (9.0, 0.0, 9.5, 13.0)]
    colors = [(255, 0, 0, 200), "#00ff0080", (0, 0, 255)]
    batch = sl.FrameBuffer(20, 14, mode="RGB", background="white")
    aa.lines(batch, segs, colors)
    single = sl.FrameBuffer(20, 14, mode="RGB", background="white")
    for s, c in zip(segs, colors):
        aa.lines(single, [s], c)
    assert np.array_equal(batch.to_array(), single.to_array())


def test_alpha_multiplies_coverage():
    full = sl.FrameBuffer(20, 8, mode="L")
    half = sl.FrameBuffer(20, 8, mode="L")
    aa.lines(full, [(1, 3.3, 18, 4.1)], (255, 255, 255))
    aa.lines(half, [(1, 3.3, 18, 4.1)], (255, 255, 255, 128))
    assert np.abs(full.to_array() * (128 / 255) - half.to_array()).max() <= 1


# -- conics ------------------------------------------------------------------------------
@pytest.mark.parametrize("xc,yc,r", [(60, 60, 40), (60.3, 59.6, 25.7), (61.5, 60.5, 55)])
def test_circle_intensity_is_its_circumference(xc, yc, r):
    fb = sl.FrameBuffer(121, 121, mode="L")
    aa.circles(fb, [(xc, yc, r)], "white")
    assert intensity(fb).sum() == pytest.approx(2 * math.pi * r, rel=0.02)


def test_ellipse_intensity_is_its_perimeter():
    rx, ry = 50.3, 21.8
    fb = sl.FrameBuffer(121, 61, mode="L")
    aa.ellipses(fb, [(60.2, 30.4, rx, ry)], "white")
    h = ((rx - ry) / (rx + ry)) ** 2     # Ramanujan's second approximation
    perimeter = math.pi * (rx + ry) * (1 + 3 * h / (10 + math.sqrt(4 - 3 * h)))
    assert intensity(fb).sum() == pytest.approx(perimeter, rel=0.02)


def test_circle_has_the_eight_symmetries():
    fb = sl.FrameBuffer(31, 31, mode="L")
    aa.circles(fb, [(15, 15, 11.3)], "white")
    a = fb.to_array()
    for image in (a[::-1], a[:, ::-1], a.T):
        assert np.abs(image.astype(int) - a).max() <= 1


def test_circle_straddles_the_ideal_curve():
    # on the row through the center the curve crosses x = xc + r = 10.25: pixels 10
    # and 11 share the intensity 3:1 (distance 0.25 and 0.75)
    fb = sl.FrameBuffer(13, 13, mode="L")
    aa.circles(fb, [(4, 6, 6.25)], "white")
    row = fb.to_array()[::-1][6]
    assert row[10] == round(0.75 * 255) and row[11] == 0 or row[11] < row[10]
    assert abs(row[10] / 255 - 0.75) < 0.03 and abs(row[9] / 255) < 0.03


def test_flat_ellipse_is_its_axis_twice():
    fb = sl.FrameBuffer(30, 5, mode="L")
    aa.ellipses(fb, [(15, 2, 10, 0)], (255, 255, 255, 128))
    once = 128 / 255
    twice = 1 - (1 - once) ** 2
    assert fb.to_array()[2][8:23].tolist() == [round(twice * 255)] * 15


# -- areas -------------------------------------------------------------------------------
def random_polygon(rng, k, center, radius):
    angles = np.sort(rng.uniform(0, 2 * np.pi, k))
    radii = rng.uniform(0.3, 1.0, k) * radius
    return np.c_[center[0] + radii * np.cos(angles), center[1] + radii * np.sin(angles)]


@pytest.mark.parametrize("seed", range(6))
def test_polygon_coverage_sums_to_its_area(seed):
    rng = np.random.default_rng(seed)
    poly = random_polygon(rng, 9, rng.uniform(30, 50, 2), 28)
    fb = sl.FrameBuffer(80, 80, mode="L")
    aa.fill(fb, [poly], "white")
    area = shapely.Polygon(poly).area
    assert intensity(fb).sum() == pytest.approx(area, rel=0.003, abs=0.5)


@pytest.mark.parametrize("rule", ["nonzero", "even-odd"])
def test_pentagram_both_rules_against_supersampling(rule):
    star = [(20 + 17 * math.cos(math.pi / 2 + 4 * math.pi * i / 5),
             20 + 17 * math.sin(math.pi / 2 + 4 * math.pi * i / 5)) for i in range(5)]
    fb = sl.FrameBuffer(40, 40, mode="L")
    aa.fill(fb, [star], "white", rule=rule)
    ref = reference_coverage([star], 40, 40, rule)
    got = intensity(fb)
    assert np.abs(got - ref).max() < 0.08
    assert got.sum() == pytest.approx(ref.sum(), rel=0.003)
    center = got[::-1][20, 20]
    assert center == (1.0 if rule == "nonzero" else 0.0)


@pytest.mark.parametrize("rule", ["nonzero", "even-odd"])
def test_overlapping_contours_and_holes(rule):
    outer = [(2.3, 2.1), (37.6, 2.4), (36.9, 31.2), (3.1, 30.8)]
    inner = [(10.2, 9.7), (25.5, 10.3), (24.8, 22.6), (11.1, 21.9)]    # same orientation
    overlap = [(30.4, 20.2), (45.7, 25.1), (33.3, 38.6)]
    fb = sl.FrameBuffer(48, 40, mode="L")
    aa.fill(fb, [outer, inner, overlap], "white", rule=rule)
    ref = reference_coverage([outer, inner, overlap], 48, 40, rule)
    got = intensity(fb)
    assert np.abs(got - ref).max() < 0.08
    assert got.sum() == pytest.approx(ref.sum(), rel=0.003)
    a, b, c = (shapely.Polygon(p) for p in (outer, inner, overlap))
    expected = (a.union(c).area if rule == "nonzero"
                else a.symmetric_difference(c).area - b.area)
    assert got.sum() == pytest.approx(expected, rel=0.003)


def test_fills_batch_equals_fill_in_order():
    rng = np.random.default_rng(3)
    shapes = [random_polygon(rng, 6, rng.uniform(8, 22, 2), 9) for _ in range(5)]
    colors = [(255, 0, 0, 128), "green", (0, 0, 255, 60), (9, 9, 9), (200, 100, 0, 250)]
    batch = sl.FrameBuffer(30, 30, mode="RGBA")
    aa.fills(batch, shapes, colors)
    single = sl.FrameBuffer(30, 30, mode="RGBA")
    for s, c in zip(shapes, colors):
        aa.fill(single, [s], c)
    assert np.array_equal(batch.to_array(), single.to_array())


def test_disk_and_ellipse_areas():
    fb = sl.FrameBuffer(100, 60, mode="L")
    aa.filled_ellipses(fb, [(30.3, 29.8, 20.6, 20.6), (75.2, 30.1, 18.4, 9.3)], "white")
    assert intensity(fb).sum() == pytest.approx(math.pi * (20.6 ** 2 + 18.4 * 9.3), rel=0.002)


def test_disk_matches_supersampled_reference():
    ring = [(10.4 + 7.3 * math.cos(t), 9.6 + 7.3 * math.sin(t))
            for t in np.linspace(0, 2 * math.pi, 2000, endpoint=False)]
    fb = sl.FrameBuffer(21, 20, mode="L")
    sl.draw.fill_circle(fb, 10.4, 9.6, 7.3, "white", antialias=True)
    assert np.abs(intensity(fb) - reference_coverage([ring], 21, 20, "nonzero")).max() < 0.08


def test_polygon_keyword_antialias():
    tri = [(1.5, 1.2), (18.7, 3.3), (7.1, 16.9)]
    a = sl.FrameBuffer(20, 20, mode="RGB")
    b = sl.FrameBuffer(20, 20, mode="RGB")
    sl.draw.polygon(a, tri, "orange", antialias=True)
    aa.fill(b, [tri], "orange", rule="even-odd")
    assert np.array_equal(a.to_array(), b.to_array())
    sl.draw.polygons(a, [tri, tri], ["red", (0, 0, 255, 50)], antialias=True)
    aa.fills(b, [tri, tri], ["red", (0, 0, 255, 50)], rule="even-odd")
    assert np.array_equal(a.to_array(), b.to_array())
    with pytest.raises(sl.ArgumentValueError, match="solid"):
        sl.draw.polygon(a, tri, "red", antialias=True, style=sl.FillStyle.hollow())


def test_fill_circles_keyword_antialias():
    a = sl.FrameBuffer(30, 20, mode="L")
    sl.draw.fill_circles(a, [(8.5, 9.5, 6.2), (20, 10, 4)], "white", antialias=True)
    sl.draw.fill_ellipses(a, [(8.5, 9.5, 6.2, 3.0)], "black", antialias=True)
    b = sl.FrameBuffer(30, 20, mode="L")
    aa.filled_ellipses(b, [(8.5, 9.5, 6.2, 6.2), (20, 10, 4, 4)], "white")
    aa.filled_ellipses(b, [(8.5, 9.5, 6.2, 3.0)], "black")
    assert np.array_equal(a.to_array(), b.to_array())


# -- every mode ----------------------------------------------------------------------------
def test_bitmap_mode_thresholds_coverage_at_one_half():
    fb = sl.FrameBuffer(8, 4, mode="1")
    aa.lines(fb, [(0, 1.25, 7, 1.25)], "white")   # rows 1 and 2 get 0.75 and 0.25,
    # the end columns half of that (the line ends at their centers): 0.375 < 1/2
    assert sl.text_image(fb).splitlines() == ["--------", "--------", "-######-", "--------"]
    fb = sl.FrameBuffer(6, 3, mode="1")
    aa.fill(fb, [[(0.9, -1), (4.1, -1), (4.1, 5), (0.9, 5)]], "white")  # columns 0.4 and 0.6
    assert sl.text_image(fb).splitlines() == ["-####-"] * 3


@pytest.mark.parametrize("draw", [lambda fb: aa.lines(fb, [(1.3, 2.2, 18.4, 15.1)], (255, 255, 255)),
                                  lambda fb: aa.fill(fb, [[(2, 2), (15, 4), (5, 17)]],
                                                     (255, 255, 255, 100))])
def test_indexed_mode_picks_the_nearest_table_entries(draw):
    table = [(0, 0, 0)] + [(g, g, g) for g in range(15, 250, 16)]   # no white
    fb = sl.FrameBuffer(20, 20, mode="P", color_table=table)
    draw(fb)
    idx = fb.to_array()
    assert len(fb.color_table) == len(table) + 1     # white itself was added
    levels = fb.color_table[idx][..., 0].astype(int)
    ref = sl.FrameBuffer(20, 20, mode="L")
    draw(ref)
    gray = ref.to_array().astype(int)
    # the nearest of the table's levels (at most 8 away) to the gray result, up to
    # the gray result's rounding
    nearest = np.abs(levels - gray) <= np.abs(fb.color_table[:, 0][None, None, :] - gray[..., None]).min(axis=2) + 1
    assert nearest.all()
    assert (levels > 0).sum() == (gray > 7).sum()


def test_rgba_mode_composites_with_destination_alpha():
    fb = sl.FrameBuffer(10, 3, mode="RGBA", background=(0, 0, 0, 0))
    aa.lines(fb, [(0, 1, 9, 1)], (255, 0, 0, 255))
    assert fb.to_array()[1, 3].tolist() == [255, 0, 0, 255]
    fb = sl.FrameBuffer(10, 3, mode="RGBA", background=(0, 0, 0, 0))
    aa.lines(fb, [(0, 1.5, 9, 1.5)], (255, 0, 0, 255))  # rows 1 and 2 half covered
    assert fb.to_array()[0, 4].tolist() == [255, 0, 0, 128]


# -- bounds and bad input ------------------------------------------------------------------
def guarded(width, height, mode):
    """A frame buffer whose storage sits between guard rows."""
    fb = sl.FrameBuffer(width, height, mode=mode)
    buf = fb._buf
    big = np.full((buf.shape[0] + 4,) + buf.shape[1:], 77, np.uint8)
    big[2:-2] = buf
    fb._buf = big[2:-2]
    return fb, big


coord = st.one_of(st.floats(-2.0**30, 2.0**30), st.floats(-30, 30), st.sampled_from([0.0, -0.5, 7.5]))


@settings(max_examples=60, deadline=None)
@given(rows=st.lists(st.tuples(coord, coord, coord, coord), min_size=1, max_size=4),
       mode=st.sampled_from(["1", "L", "RGB", "RGBA", "P"]))
def test_fuzz_never_writes_outside(rows, mode):
    fb, big = guarded(9, 7, mode)
    arr = np.array(rows)
    aa.lines(fb, arr, (200, 100, 50, 180))
    aa.ellipses(fb, np.c_[arr[:, :2], np.abs(arr[:, 2:])], "white")
    aa.filled_ellipses(fb, np.c_[arr[:, :2], np.abs(arr[:, 2:])], (0, 0, 255, 99))
    aa.fill(fb, [arr.reshape(-1, 2)], "red", rule="even-odd")
    assert (big[:2] == 77).all() and (big[-2:] == 77).all()


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), 2.0**31])
def test_bad_coordinates_are_rejected(bad):
    fb = sl.FrameBuffer(5, 5, mode="L")
    if bad == 2.0**31:
        # finite: lines and fills are clipped to the guard square, conics drawn
        # where they reach the frame (issue 11, item 2)
        aa.lines(fb, [(0, 0, bad, 1)])
        aa.fill(fb, [[(0, 0), (bad, 1), (2, 2)]])
        assert fb.to_array()[4, 0] > 0
        ring = sl.FrameBuffer(5, 5, mode="L")
        aa.circles(ring, [(bad, 2, bad - 2)])         # its left-most point is (2, 2)
        assert ring.to_array()[2, 2] > 0 and not ring.to_array()[:, :2].any()
        return
    with pytest.raises(sl.ArgumentValueError, match="circles"):
        aa.circles(fb, [(bad, 0, 1)])
    with pytest.raises(sl.ArgumentValueError, match="segments"):
        aa.lines(fb, [(0, 0, bad, 1)])
    with pytest.raises(sl.ArgumentValueError, match="contours"):
        aa.fill(fb, [[(0, 0), (bad, 1), (2, 2)]])


def test_bad_arguments_are_named():
    fb = sl.FrameBuffer(5, 5)
    with pytest.raises(sl.ArgumentValueError, match="rule"):
        aa.fill(fb, [[(0, 0), (3, 0), (0, 3)]], rule="winding")
    with pytest.raises(sl.ArgumentValueError, match=r"segments must have shape \(N, 4\)"):
        aa.lines(fb, [(0, 0, 1)])
    with pytest.raises(sl.ArgumentValueError, match="radii"):
        aa.ellipses(fb, [(0, 0, -1, 2)])
    with pytest.raises(sl.ArgumentValueError, match="2 colors but there are 1"):
        aa.lines(fb, [(0, 0, 1, 1)], ["red", "blue"])
    with pytest.raises(sl.ArgumentTypeError, match="segments"):
        aa.lines(fb, "0 0 1 1")


@pytest.mark.parametrize("mode", ["RGB", "P"])
def test_banded_batch_equals_single_calls(mode):
    # batches are drawn band by band of scan lines, each pixel still composited by
    # the segments in their order
    rng = np.random.default_rng(9)
    segs = np.c_[rng.uniform(0, 60, (300, 2)), rng.uniform(0, 60, (300, 2))]
    segs[:, [1, 3]] += BAND - 30                     # around the first band edge
    segs[::2, 1] += 40
    segs[::7] *= 3                                   # some long ones, some outside
    colors = [(200, 30, 90, 150), "navy", (0, 255, 0, 40)] * 100
    batch = sl.FrameBuffer(64, BAND + 80, mode=mode, background="white")
    aa.lines(batch, segs, colors)
    aa.lines(batch, segs, (200, 30, 90, 150))
    single = sl.FrameBuffer(64, BAND + 80, mode=mode, background="white")
    for s, c in zip(segs, colors):
        aa.lines(single, [s], c)
    for s in segs:
        aa.lines(single, [s], (200, 30, 90, 150))
    assert np.array_equal(batch.to_array(), single.to_array())


def wu_reference(x0, y0, x1, y1, width, height):
    """Intensities of the slope-corrected Wu line, written out plainly: for each
    column of the major axis, the part of the segment in it times the overlap of
    the cross-section [w - k/2, w + k/2] with each pixel.  Image order."""
    out = np.zeros((height, width))
    swap = abs(y1 - y0) > abs(x1 - x0)
    u0, w0, u1, w1 = (y0, x0, y1, x1) if swap else (x0, y0, x1, y1)
    if u0 > u1:
        u0, w0, u1, w1 = u1, w1, u0, w0
    m = (w1 - w0) / (u1 - u0)
    k = math.sqrt(1 + m * m)
    for i in range(math.floor(u0 + 0.5), math.floor(u1 + 0.5) + 1):
        lo, hi = max(u0, i - 0.5), min(u1, i + 0.5)
        if hi <= lo:
            continue
        w = w0 + ((lo + hi) / 2 - u0) * m
        for j in range(math.floor(w - k / 2) - 1, math.floor(w + k / 2) + 2):
            cover = max(0.0, min(w + k / 2, j + 0.5) - max(w - k / 2, j - 0.5)) * (hi - lo)
            x, y = (j, i) if swap else (i, j)
            if 0 <= x < width and 0 <= y < height:
                out[height - 1 - y, x] += cover
    return out


def test_lines_match_a_plain_reference_across_bands():
    rng = np.random.default_rng(21)
    segs = rng.uniform(-10, 110, (60, 4))
    segs[:, [1, 3]] += BAND - 50                                 # around a band edge
    segs[:10, 3] = segs[:10, 1] + rng.uniform(-0.9, 0.9, 10)     # flat ones on it
    segs[:10, 1] = BAND - 0.7 + np.arange(10) * 0.31
    segs[:10, 3] = segs[:10, 1] + rng.uniform(-0.9, 0.9, 10)
    for s in segs:
        fb = sl.FrameBuffer(100, BAND + 60, mode="L")
        aa.lines(fb, [s], "white")
        ref = wu_reference(*s, 100, BAND + 60)
        assert np.abs(fb.to_array() - np.round(ref * 255)).max() <= 1


def wu_exact(out, x0, y0, x1, y1, src, alpha):
    """The column-span line composited over ``out`` (image order, uint8, channels
    last) one pixel at a time in plain Python, with the fixed-point "over" of modes
    RGB and L (weight f = round(alpha x coverage x 65536), d + ((s - d) f + 2**15)
    >> 16), every floating-point operation in the order the notes' algorithm
    states it: the kernel's vectorized two-pass form must give these bytes."""
    height, width = out.shape[:2]
    swap = abs(y1 - y0) > abs(x1 - x0)
    u0, w0, u1, w1 = (y0, x0, y1, x1) if swap else (x0, y0, x1, y1)
    if u0 > u1:
        u0, w0, u1, w1 = u1, w1, u0, w0
    if not u1 > u0:
        return
    m = (w1 - w0) / (u1 - u0)
    half = 0.5 * math.sqrt(1.0 + m * m)
    for i in range(math.floor(u0 + 0.5), math.ceil(u1 + 0.5)):
        lo, hi = max(u0, i - 0.5), min(u1, i + 0.5)
        if not hi > lo:
            continue
        wc = w0 + (0.5 * (lo + hi) - u0) * m
        a, b = wc - half, wc + half
        for j in range(math.floor(a + 0.5), math.ceil(b + 0.5)):
            cover = (min(b, j + 0.5) - max(a, j - 0.5)) * ((hi - lo) * alpha)
            x, y = (j, i) if swap else (i, j)
            if cover > 0.0 and 0 <= x < width and 0 <= y < height:
                f = int(min(cover, 1.0) * 65536.0 + 0.5)
                px = out[height - 1 - y, x]
                for c in range(out.shape[2]):
                    d = int(px[c])
                    px[c] = d + (((src[c] - d) * f + 32768) >> 16)


@pytest.mark.parametrize("mode", ["RGB", "L"])
def test_lines_equal_a_pixel_by_pixel_reference_exactly(mode):
    rng = np.random.default_rng(5)
    segs = rng.uniform(-8, 48, (40, 4))
    segs[:, [1, 3]] += BAND - 20                    # across a band edge, some outside
    segs[:6, 2] = segs[:6, 0] + rng.uniform(-0.5, 0.5, 6)          # steep
    segs[6:12, 3] = segs[6:12, 1]                                   # horizontal
    segs[12:16] = np.round(segs[12:16] * 2) / 2                     # on half-integers
    colors = rng.integers(0, 256, (40, 4))
    fb = sl.FrameBuffer(40, BAND + 20, mode=mode, background=90 if mode == "L" else (90, 40, 7))
    grays = [(int(c[0]),) * 3 + (int(c[3]),) for c in colors]
    aa.lines(fb, segs, colors if mode == "RGB" else grays)
    out = np.full((BAND + 20, 40, 3 if mode == "RGB" else 1), 0, np.int64)
    out[...] = (90, 40, 7) if mode == "RGB" else 90
    for s, c in zip(segs, colors):
        src = [int(v) for v in c[:3]] if mode == "RGB" else [int(c[0])]
        wu_exact(out, *s, src, c[3] / 255.0)
    got = fb.to_array().reshape(out.shape)
    assert np.array_equal(got, out)


def test_fills_flat_equals_fill_in_order():
    rng = np.random.default_rng(4)
    square = [(2.3, 2.1), (25.6, 2.9), (26.2, 24.4), (1.7, 25.2)]
    hole = [(8.2, 8.4), (8.9, 18.3), (19.1, 18.6), (18.4, 7.7)]
    tri = random_polygon(rng, 6, (15, 15), 9)
    shapes = [[np.array(square), np.array(hole)], [tri], [np.array(hole)]]
    colors = [(255, 0, 0, 200), "navy", (0, 255, 0, 90)]
    verts = np.concatenate([c for shape in shapes for c in shape])
    contour_offsets = np.cumsum([0, 4, 4, len(tri), 4])
    flat = sl.FrameBuffer(30, 30, mode="RGB")
    aa.fills_flat(flat, verts, contour_offsets, [0, 2, 3, 4], colors, "even-odd")
    single = sl.FrameBuffer(30, 30, mode="RGB")
    for shape, c in zip(shapes, colors):
        aa.fill(single, shape, c, "even-odd")
    assert np.array_equal(flat.to_array(), single.to_array())
    assert flat.to_array().any()


def test_fills_flat_rejects_inconsistent_offsets():
    fb = sl.FrameBuffer(5, 5)
    tri = [(0, 0), (3, 0), (0, 3)]
    with pytest.raises(sl.ArgumentValueError, match="contour_offsets must rise from 0 to 3"):
        aa.fills_flat(fb, tri, [0, 4], [0, 1])
    with pytest.raises(sl.ArgumentValueError, match="contour_offsets"):
        aa.fills_flat(fb, tri + tri, [0, 4, 3, 6], [0, 3])
    with pytest.raises(sl.ArgumentValueError, match="shape_offsets must rise from 0 to 1"):
        aa.fills_flat(fb, tri, [0, 3], [1, 1])
    with pytest.raises(sl.ArgumentTypeError, match="shape_offsets"):
        aa.fills_flat(fb, tri, [0, 3], [0.0, 1.0])
    with pytest.raises(sl.ArgumentTypeError, match="contour_offsets"):
        aa.fills_flat(fb, tri, [[0, 3]], [0, 1])
    with pytest.raises(sl.ArgumentValueError, match=r"vertex 1 is \[nan, 0.0\]"):
        aa.fills_flat(fb, [(0, 0), (float("nan"), 0), (0, 3)], [0, 3], [0, 1])
    # beyond +-2**40: any finite vertex is clipped to the guard square (issue 11)
    aa.fills_flat(fb, [(0, 0), (2.0**40, 0), (0, -2.0**41)], [0, 3], [0, 1])
    with pytest.raises(sl.ArgumentTypeError, match="vertices"):
        aa.fills_flat(fb, [(0, 0, 1)], [0, 1], [0, 1])


def test_fills_flat_takes_outlines_beyond_the_drawing_range():
    # a square reaching 2**35 beyond the frame: its inside covers the frame exactly
    fb = sl.FrameBuffer(6, 4, mode="L")
    big = 2.0**35
    aa.fills_flat(fb, [(-big, -big), (big, -big), (big, 1.5), (-big, 1.5)], [0, 4], [0, 1])
    assert fb.to_array().tolist() == [[0] * 6, [0] * 6, [255] * 6, [255] * 6]
