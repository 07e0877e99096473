"""sl.draw.polygon(s): exact tiny images, the two fill rules, the coverage (top-left)
rule on random tilings, an exact rational reference, peers (OpenCV, scikit-image),
clipping, batches, modes, styles, bad input and fuzzing.
"""

from fractions import Fraction

import cv2
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy.spatial import Delaunay
from skimage.draw import polygon as sk_polygon

import scanline as sl
from scanline._kernels import polygon as kp
from scanline._kernels.variants import layout
from tests.reference import HYPOTHESIS, MODES


# -- helpers ------------------------------------------------------------------------
def mask(fb):
    """Lit pixels as a bool array indexed [y, x] (device rows, bottom-up)."""
    a = fb.to_array()
    if a.ndim == 3:
        a = a[:, :, :3].any(axis=2)
    return (a != 0)[::-1]


def filled(points, width, height, rule="even-odd", **kw):
    fb = sl.FrameBuffer(width, height, mode="L")
    sl.draw.polygon(fb, points, color=255, rule=rule, **kw)
    return mask(fb)


def rings(points):
    """One contour or several, as a list of lists of (x, y)."""
    a = points if isinstance(points, list) and points and not np.isscalar(points[0][0]) else [points]
    return [[(float(x), float(y)) for x, y in ring] for ring in a]


def reference(points, width, height, rule="even-odd"):
    """Exact rational reference, written from the definition (not from the kernel):
    pixel (x, y) is in iff the point (x + e, y - e**2), e infinitesimal, is inside:
    edges with ylo < y <= yhi whose crossing is <= x count, +1 up and -1 down."""
    out = np.zeros((height, width), bool)
    edges = []
    for ring in rings(points):
        for i in range(len(ring)):
            (xa, ya), (xb, yb) = ring[i], ring[(i + 1) % len(ring)]
            if ya != yb:
                edges.append(tuple(Fraction(c) for c in (xa, ya, xb, yb)))
    for y in range(height):
        cross = []
        for xa, ya, xb, yb in edges:
            lo, hi = min(ya, yb), max(ya, yb)
            if lo < y <= hi:
                cross.append((xa + (y - ya) * (xb - xa) / (yb - ya), 1 if yb > ya else -1))
        for x in range(width):
            s = sum(d for xc, d in cross if xc <= x)
            out[y, x] = (s % 2 == 1) if rule == "even-odd" else s != 0
    return out


def star_polygon(rng, cx, cy, n, rmax, integer=True):
    """A random star-shaped (generally concave) simple polygon."""
    ang = np.sort(rng.uniform(0, 2 * np.pi, n))
    r = rng.uniform(0.2 * rmax, rmax, n)
    p = np.stack([cx + r * np.cos(ang), cy + r * np.sin(ang)], axis=1)
    return np.rint(p) if integer else p


def random_polygon(rng, size, n, integer=True):
    """Random vertices: self-intersecting in general."""
    p = rng.uniform(-3, size + 3, (n, 2))
    return np.rint(p) if integer else p


# -- exact tiny images ------------------------------------------------------------------
def test_triangle_hand_derived():
    # edges (0,0)-(3,4) and (6,0)-(3,4) cross y = 1, 2, 3 at 0.75|5.25, 1.5|4.5, 2.25|3.75;
    # y = 4 is the apex (on both edges: empty span), y = 0 the bottom edge (outside)
    got = filled([(0, 0), (6, 0), (3, 4)], 7, 5)
    want = np.zeros((5, 7), bool)
    want[1, 1:6] = want[2, 2:5] = want[3, 3] = True
    np.testing.assert_array_equal(got, want)


def test_rectangle_is_half_open():
    # x in [1, 4), y in (1, 3]: left and top edges in, right and bottom edges out
    got = filled([(1, 1), (4, 1), (4, 3), (1, 3)], 6, 5)
    want = np.zeros((5, 6), bool)
    want[2:4, 1:4] = True
    np.testing.assert_array_equal(got, want)


def test_orientation_and_start_vertex_do_not_matter():
    p = [(1, 1), (9, 2), (7, 8), (4, 5), (2, 7)]
    ref = filled(p, 10, 10)
    for q in (p[::-1], p[2:] + p[:2]):
        for rule in ("even-odd", "nonzero"):
            np.testing.assert_array_equal(filled(q, 10, 10, rule), ref)


def test_float_vertices_sample_at_centers():
    # a square from 0.5 to 2.5 covers the centers 1 and 2 in x, and in y
    # (its edges pass between centers)
    got = filled([(0.5, 0.5), (2.5, 0.5), (2.5, 2.5), (0.5, 2.5)], 4, 4)
    want = np.zeros((4, 4), bool)
    want[1:3, 1:3] = True
    np.testing.assert_array_equal(got, want)
    # a thin sliver between two centers covers nothing
    assert not filled([(0.1, 0.2), (3.9, 0.2), (3.9, 0.8), (0.1, 0.8)], 4, 4).any()


def test_pentagram_center_depends_on_rule():
    star = [(1, 7), (9, 7), (2, 1), (5, 11), (8, 1)]   # center near (5, 5)
    eo = filled(star, 11, 12, "even-odd")
    nz = filled(star, 11, 12, "nonzero")
    assert not eo[5, 5] and nz[5, 5]
    # scan line y = 7 by hand: keys ceil(xc) = 1 (up), 4 (up), 7 (down), 9 (down);
    # even-odd fills [1, 4) and [7, 9), nonzero (windings 1, 2, 1, 0) fills [1, 9)
    picture = {"even-odd": """
        -----------
        -----#-----
        -----#-----
        -----#-----
        -###---##--
        ---#---#---
        -----------
        ---##-##---
        ---##-##---
        ---#---#---
        -----------
        -----------""", "nonzero": """
        -----------
        -----#-----
        -----#-----
        -----#-----
        -########--
        ---#####---
        ----###----
        ---#####---
        ---##-##---
        ---#---#---
        -----------
        -----------"""}
    for rule, got in (("even-odd", eo), ("nonzero", nz)):
        rows = picture[rule].split()
        want = np.array([[c == "#" for c in row] for row in rows])[::-1]
        np.testing.assert_array_equal(got, want)
        np.testing.assert_array_equal(got, reference(star, 11, 12, rule))


def test_bow_tie_same_under_both_rules():
    bow = [(0, 0), (8, 8), (8, 0), (0, 8)]
    eo = filled(bow, 9, 9, "even-odd")
    nz = filled(bow, 9, 9, "nonzero")
    np.testing.assert_array_equal(eo, nz)
    np.testing.assert_array_equal(eo, reference(bow, 9, 9))
    # two lobes meeting at (4, 4).  y = 2 crosses x = 0, 2, 6, 8: x = 0, 1 and 6, 7;
    # y = 4 crosses x = 0, 4, 4, 8: x = 0 .. 7 (the center is on the right lobe's
    # left edges); on y = 8 each lobe ends in a vertex where its left and right edge
    # meet (keys 0, 0 and 8, 8): nothing
    np.testing.assert_array_equal(np.nonzero(eo[2])[0], [0, 1, 6, 7])
    np.testing.assert_array_equal(np.nonzero(eo[4])[0], np.arange(8))
    np.testing.assert_array_equal(np.nonzero(eo[7])[0], [0, 7])
    assert not eo[8].any()
    assert not eo[0].any()


def test_holes_and_orientation_under_nonzero():
    outer = [(0, 0), (10, 0), (10, 10), (0, 10)]
    hole_cw = [(3, 3), (3, 7), (7, 7), (7, 3)]      # opposite orientation
    hole_ccw = hole_cw[::-1]                         # same orientation: winding 2
    eo = filled([outer, hole_ccw], 12, 12, "even-odd")
    assert not eo[5, 5] and eo[1, 1]
    assert not filled([outer, hole_cw], 12, 12, "nonzero")[5, 5]
    assert filled([outer, hole_ccw], 12, 12, "nonzero")[5, 5]
    # a (C, N, 2) array works too
    np.testing.assert_array_equal(filled(np.array([outer, hole_ccw]), 12, 12), eo)


def test_degenerate_polygons_fill_nothing():
    for pts in ([], [(3, 3)], [(1, 1), (6, 4)], [(1, 1), (3, 3), (5, 5)],
                [(1, 1), (1, 1), (1, 1)], [(0, 2), (7, 2), (3, 2)], [(2, 0), (2, 7)],
                [(1, 1), (5, 5), (1, 1), (5, 5)]):
        for rule in ("even-odd", "nonzero"):
            assert not filled(pts, 8, 8, rule).any(), pts


# -- the coverage rule: tilings cover each pixel exactly once -------------------------
def coverage(polys, width, height):
    count = np.zeros((height, width), np.int64)
    for p in polys:
        count += filled(p, width, height)
    return count


@pytest.mark.parametrize("integer", [True, False])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_random_triangulation_covers_each_pixel_once(seed, integer):
    rng = np.random.default_rng(seed)
    w, h = 40, 32
    x0, y0, x1, y1 = (-3, -2, 44, 35) if integer else (-2.7, -1.3, 43.2, 34.6)
    corners = np.array([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], float)
    if integer:  # integer vertices: many edges pass exactly through pixel centers
        pts = np.unique(rng.integers(-3, 45, (60, 2)), axis=0).astype(float)
        pts = pts[(pts[:, 1] >= y0) & (pts[:, 1] <= y1)]
    else:
        pts = np.stack([rng.uniform(x0, x1, 60), rng.uniform(y0, y1, 60)], axis=1)
    pts = np.vstack([corners, pts])
    tri = Delaunay(pts)
    polys = [pts[s] for s in tri.simplices]
    count = coverage(polys, w, h)
    whole = filled(corners, w, h)
    assert count.max() == 1
    np.testing.assert_array_equal(count == 1, whole)


def test_float_fan_with_vertex_on_a_pixel_center():
    # many triangles meeting at a pixel center, float outer vertices
    c = (10.0, 10.0)
    ang = np.linspace(0, 2 * np.pi, 13)[:-1] + 0.1
    ring = np.stack([c[0] + 9.3 * np.cos(ang), c[1] + 9.3 * np.sin(ang)], axis=1)
    polys = [[c, tuple(ring[i]), tuple(ring[(i + 1) % 12])] for i in range(12)]
    count = coverage(polys, 21, 21)
    assert count.max() == 1 and count[10, 10] == 1
    np.testing.assert_array_equal(count == 1, filled(ring, 21, 21))


def test_adjacent_squares_no_overlap_no_gap():
    polys = [[(x, y), (x + 3, y), (x + 3, y + 3), (x, y + 3)]
             for x in range(-1, 20, 3) for y in range(-2, 20, 3)]
    count = coverage(polys, 16, 16)
    np.testing.assert_array_equal(count, np.ones((16, 16), int))
    # the batch call draws the same union
    fb = sl.FrameBuffer(16, 16, mode="L")
    sl.draw.polygons(fb, [np.array(p, float) for p in polys], color=255)
    assert mask(fb).all()


# -- cross-checks ---------------------------------------------------------------------
@pytest.mark.parametrize("integer", [True, False])
@pytest.mark.parametrize("rule", ["even-odd", "nonzero"])
def test_matches_exact_reference_on_random_polygons(rule, integer):
    rng = np.random.default_rng(7 if integer else 8)
    for _ in range(12):
        n = int(rng.integers(3, 12))
        p = random_polygon(rng, 20, n, integer)
        np.testing.assert_array_equal(filled(p, 20, 18, rule), reference(p, 20, 18, rule))


def test_matches_geometry_inside_on_pixel_centers():
    rng = np.random.default_rng(11)
    yy, xx = np.mgrid[0:30, 0:33]
    centers = np.stack([xx.ravel(), yy.ravel()], axis=1)
    for i in range(20):
        p = random_polygon(rng, 30, int(rng.integers(3, 16)), integer=i % 2 == 0)
        for rule in ("even-odd", "nonzero"):
            got = filled(p, 33, 30, rule)
            want = sl.geometry.inside(centers, p, rule).reshape(30, 33)
            np.testing.assert_array_equal(got, want)


def distance_to_edges(p, width, height):
    """Distance of every pixel center to the polygon's boundary, shape (height, width)."""
    yy, xx = np.mgrid[0:height, 0:width].astype(float)
    d = np.full((height, width), np.inf)
    for a, b in zip(p, np.roll(p, -1, axis=0)):
        ab = b - a
        t = ((xx - a[0]) * ab[0] + (yy - a[1]) * ab[1]) / max(ab @ ab, 1e-300)
        t = np.clip(t, 0, 1)
        d = np.minimum(d, np.hypot(xx - a[0] - t * ab[0], yy - a[1] - t * ab[1]))
    return d


def test_peers_agree_away_from_edges():
    """Different boundary conventions, quantified.  OpenCV's fillPoly paints the
    pixels its outline touches too: on these polygons (radius <= 30) it sets ~8%
    more pixels than scanline and misses almost none of ours.  scikit-image's
    polygon tests the centers with its own boundary rule (centers on an edge count
    as inside): ~2% more.  Centers more than 1 px from every edge agree exactly."""
    rng = np.random.default_rng(5)
    w = h = 64
    diff_cv = diff_sk = missed_cv = total = 0
    for _ in range(30):
        p = star_polygon(rng, rng.uniform(20, 44), rng.uniform(20, 44), int(rng.integers(3, 20)), 30)
        ours = filled(p, w, h)
        img = np.zeros((h, w), np.uint8)
        cv2.fillPoly(img, [np.c_[p[:, 0], h - 1 - p[:, 1]].astype(np.int32)], 255)
        cvm = (img[::-1] > 0)
        sk = np.zeros((h, w), bool)
        rr, cc = sk_polygon(p[:, 1], p[:, 0], shape=(h, w))   # rows = y here
        sk[rr, cc] = True
        far = distance_to_edges(p, w, h) > 1.0
        np.testing.assert_array_equal(ours[far], cvm[far])
        np.testing.assert_array_equal(ours[far], sk[far])
        missed_cv += int((ours & ~cvm).sum())
        diff_cv += int((ours != cvm).sum())
        diff_sk += int((ours != sk).sum())
        total += int(ours.sum())
    assert 0.03 * total < diff_cv < 0.15 * total and missed_cv < 0.005 * total
    assert 0.005 * total < diff_sk < 0.05 * total


# -- clipping, batches, modes, styles -------------------------------------------------------
def test_huge_coordinates_are_clipped():
    big = 10**9
    assert filled([(-big, -big), (big, -big), (0, big)], 50, 40).all()
    p = [(-big, -big + 3), (big, -big), (big, big), (-big, big - 7)]
    np.testing.assert_array_equal(filled(p, 30, 20), reference(p, 30, 20))
    # a thin wedge from far away: exact integer arithmetic decides each pixel
    p = [(-big, 5), (40, 0), (40, 12)]
    np.testing.assert_array_equal(filled(p, 45, 15), reference(p, 45, 15))
    # off the raster entirely
    assert not filled([(-big, -big), (-big + 5, -big), (-big, -big + 9)], 10, 10).any()


def test_batch_matches_loop_with_colors():
    rng = np.random.default_rng(3)
    polys = [star_polygon(rng, *rng.uniform(0, 60, 2), int(rng.integers(3, 9)), 15,
                          integer=bool(i % 2)) for i in range(40)]
    cols = [tuple(int(c) for c in rng.integers(0, 256, 3)) for _ in polys]
    a = sl.FrameBuffer(60, 50, mode="RGB")
    b = sl.FrameBuffer(60, 50, mode="RGB")
    sl.draw.polygons(a, polys, color=cols, rule="nonzero")
    for p, c in zip(polys, cols):
        sl.draw.polygon(b, p, color=c, rule="nonzero")
    np.testing.assert_array_equal(a.to_array(), b.to_array())
    # an (M, K, 2) array and an integer color array
    arr = np.stack([star_polygon(rng, 30, 25, 6, 20) for _ in range(5)])
    a.clear(), b.clear()
    sl.draw.polygons(a, arr, color=np.array([[255, 0, 0]] * 5))
    for p in arr:
        sl.draw.polygon(b, p, color=(255, 0, 0))
    np.testing.assert_array_equal(a.to_array(), b.to_array())
    sl.draw.polygons(a, [])   # an empty batch draws nothing, no error
    # polygons with holes in a batch
    outer = [(0, 0), (20, 0), (20, 20), (0, 20)]
    hole = [(5, 5), (15, 5), (15, 15), (5, 15)]
    a.clear(), b.clear()
    sl.draw.polygons(a, [[outer, hole], [(30, 0), (50, 0), (40, 20)]], color="red")
    sl.draw.polygon(b, [outer, hole], color="red")
    sl.draw.polygon(b, [(30, 0), (50, 0), (40, 20)], color="red")
    np.testing.assert_array_equal(a.to_array(), b.to_array())


@pytest.mark.parametrize("mode", MODES)
def test_modes_same_pixels(mode):
    p = [(0.5, 1), (29, 3.5), (20, 17), (12, 6), (3, 15)]
    fb = sl.FrameBuffer(31, 19, mode=mode)
    sl.draw.polygon(fb, p, color="white")
    np.testing.assert_array_equal(mask(fb), reference(p, 31, 19))


class RecordingStyle:
    """A stand-in fill style: paints through the ``draw`` callable with an origin."""
    kind = "test"

    def paint(self, fb, color, bbox, draw, outline):
        self.bbox = bbox
        x0, y0, x1, y1 = bbox
        buf = np.zeros((y1 - y0 + 1, x1 - x0 + 1, 1), np.uint8)
        draw(buf, False, buf.shape[1], buf.shape[0], x0, y0, np.array([7], np.uint8))
        self.buf = buf[:, :, 0]
        self.outline = outline


def test_style_gets_bbox_draw_with_origin_and_outline():
    p = [(2.5, 1.2), (17, 4), (13.7, 14.9), (6, 9)]
    st_ = RecordingStyle()
    fb = sl.FrameBuffer(20, 16, mode="L")
    sl.draw.polygon(fb, p, color="white", style=st_)
    assert not mask(fb).any()                      # the style paints, not polygon()
    x0, y0, x1, y1 = st_.bbox
    ref = reference(p, 20, 16)
    ys, xs = np.nonzero(ref)
    assert (x0, y0, x1, y1) == (xs.min(), ys.min(), xs.max(), ys.max())
    np.testing.assert_array_equal(st_.buf == 7, ref[y0:y1 + 1, x0:x1 + 1])
    st_.outline()                                  # the closed outline, via sl.draw.lines
    want = sl.FrameBuffer(20, 16, mode="L")
    q = np.array(p)
    sl.draw.lines(want, np.hstack([q, np.roll(q, -1, axis=0)]), color="white")
    np.testing.assert_array_equal(fb.to_array(), want.to_array())


def test_solid_style_object_fills():
    class Solid:
        kind = "solid"
    a = filled([(1, 1), (9, 2), (5, 8)], 10, 10, style=Solid())
    np.testing.assert_array_equal(a, filled([(1, 1), (9, 2), (5, 8)], 10, 10))


# -- bad input ------------------------------------------------------------------------
def test_bad_input_names_the_argument():
    fb = sl.FrameBuffer(8, 8)
    with pytest.raises(sl.ArgumentValueError, match="points"):
        sl.draw.polygon(fb, [(0, 0), (np.nan, 1), (3, 3)])
    with pytest.raises(sl.ArgumentValueError, match="points"):
        sl.draw.polygon(fb, [(0, 0), (np.inf, 1), (3, 3)])
    sl.draw.polygon(fb, [(0, 0), (2**31, 1), (3, 3)])   # finite: clipped to the guard square
    with pytest.raises(sl.ArgumentValueError, match="points"):
        sl.draw.polygon(fb, [(0, 0, 1), (1, 1, 1)])
    with pytest.raises(sl.ArgumentTypeError, match="points"):
        sl.draw.polygon(fb, [("a", "b"), (1, 1)])
    with pytest.raises(sl.ArgumentTypeError, match="points"):
        sl.draw.polygon(fb, 5)
    with pytest.raises(sl.ArgumentValueError, match="points\\[1\\]"):
        sl.draw.polygon(fb, [[(0, 0), (4, 0), (4, 4)], [(1, 1), (np.nan, 2), (2, 2), (3, 3)]])
    with pytest.raises(sl.ArgumentValueError, match="rule"):
        sl.draw.polygon(fb, [(0, 0), (4, 0), (4, 4)], rule="odd")
    with pytest.raises(sl.ArgumentValueError, match="polygons"):
        sl.draw.polygons(fb, [np.array([[0, 0], [4, 0], [np.nan, 4.0]])])
    with pytest.raises(sl.ArgumentValueError, match="color"):
        sl.draw.polygons(fb, [np.zeros((3, 2))] * 2, color=["red"] * 3)
    with pytest.raises(sl.ArgumentTypeError, match="fb"):
        sl.draw.polygon(np.zeros((8, 8)), [(0, 0), (4, 0), (4, 4)])


coord = st.one_of(st.integers(-40, 40), st.floats(-40, 40),
                  st.sampled_from([0.5, -0.5, 2**30, -2**30, 10**9, -10**9, 1e-300]))


@HYPOTHESIS
@given(st.lists(st.tuples(coord, coord), min_size=0, max_size=9),
       st.sampled_from(["even-odd", "nonzero"]), st.integers(0, 3))
def test_fuzz_never_writes_outside_and_matches_inside(points, rule, dup):
    if points and dup:   # repeated vertices
        points = points + points[:dup]
    w, h = 13, 11
    # a kernel call on a raster smaller than its storage: the guard must stay zero
    # (a negative index would wrap around into it)
    verts = np.array(points, float).reshape(-1, 2)
    buf = np.zeros((h + 3, w + 3, 1), np.uint8)
    kp.fill_polygons(buf, layout(False), w, h, 0, 0, verts, np.array([0, len(verts)], np.int64),
                     np.array([0, 1], np.int64), np.array([[1]], np.uint8),
                     kp.EVEN_ODD if rule == "even-odd" else kp.NONZERO, len(verts))
    assert not buf[h:].any() and not buf[:, w:].any()
    yy, xx = np.mgrid[0:h, 0:w]
    want = sl.geometry.inside(np.stack([xx.ravel(), yy.ravel()], axis=1), points, rule)
    np.testing.assert_array_equal(buf[:h, :w, 0] == 1, want.reshape(h, w))
    np.testing.assert_array_equal(filled(points, w, h, rule), want.reshape(h, w))


@HYPOTHESIS
@given(st.lists(st.tuples(st.floats(allow_nan=True, allow_infinity=True),
                          st.floats(allow_nan=True, allow_infinity=True)),
                min_size=1, max_size=6))
def test_fuzz_non_finite_is_a_clear_error(points):
    fb = sl.FrameBuffer(8, 8)
    a = np.array(points, float)
    if np.isfinite(a).all():   # any finite vertex is drawn (issue 11: the guard square)
        sl.draw.polygon(fb, points)
    else:
        with pytest.raises(sl.ArgumentValueError, match="points"):
            sl.draw.polygon(fb, points)


def test_flat_batch_with_counts_equals_the_list_form():
    rng = np.random.default_rng(11)
    polys = [rng.uniform(-5, 45, (int(k), 2)) for k in rng.integers(3, 9, 40)]
    a = sl.FrameBuffer(40, 30)
    b = sl.FrameBuffer(40, 30)
    sl.draw.polygons(a, polys, color="red", rule="nonzero")
    sl.draw.polygons(b, np.concatenate(polys), counts=[len(p) for p in polys],
                     color="red", rule="nonzero")
    assert np.array_equal(a.to_array(), b.to_array())
    assert a.to_array().any()


@pytest.mark.parametrize("vertices, counts, fragment", [
    (np.zeros((7, 2)), [4, 4], "add up to 8"),
    (np.zeros((7, 2)), [8, -1], ">= 0"),
    (np.zeros((7, 2)), [[7]], "counts"),
    (np.zeros((7, 3)), [7], "(V, 2)"),
    ([[0, 0], [1, float("nan")], [2, 2]], [3], "finite"),
])
def test_flat_batch_bad_input(vertices, counts, fragment):
    with pytest.raises(sl.ScanlineError) as e:
        sl.draw.polygons(sl.FrameBuffer(5, 5), vertices, counts=counts)
    assert fragment in str(e.value)
