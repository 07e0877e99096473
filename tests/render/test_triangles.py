"""sl.draw.triangles: coverage equal to the polygon fill's, depths and attributes
against a plain-Python per-pixel reference, shared edges covered once, perspective-
correct interpolation, bad input."""

import math

import numpy as np
import pytest

import scanline as sl


def reference(width, height, tris, values, q=None):
    """Plain Python, per pixel: the crossing test at each pixel center (edges active
    for ylo < Y <= yhi, inside for ceil(xl) <= x < ceil(xr)), the depth from the plane
    through the three vertices, the smallest depth wins (the first among equals), the
    attribute perspective-correct (a/w and 1/w linear)."""
    zbuf = np.full((height, width), np.inf)
    out = np.zeros((height, width))
    q = np.ones((len(tris), 3)) if q is None else q
    for t, tri in enumerate(tris):
        (x0, y0, z0), (x1, y1, z1), (x2, y2, z2) = tri
        area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
        if area == 0:
            continue
        for y in range(height):
            xs = []
            for a, b in ((0, 1), (1, 2), (2, 0)):
                lo, hi = (a, b) if tri[a][1] < tri[b][1] else (b, a)
                if tri[lo][1] < y <= tri[hi][1]:
                    xl, yl = tri[lo][0], tri[lo][1]
                    xs.append(xl + ((y - yl) * (tri[hi][0] - xl)) / (tri[hi][1] - yl))
            if len(xs) != 2:
                continue
            for x in range(max(math.ceil(min(xs)), 0), min(math.ceil(max(xs)), width)):
                # barycentric coordinates of the center
                l1 = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / area
                l2 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / area
                l0 = 1 - l1 - l2
                z = l0 * z0 + l1 * z1 + l2 * z2
                if z < zbuf[y, x]:
                    zbuf[y, x] = z
                    qq = l0 * q[t, 0] + l1 * q[t, 1] + l2 * q[t, 2]
                    out[y, x] = (l0 * values[t, 0] * q[t, 0] + l1 * values[t, 1] * q[t, 1]
                                 + l2 * values[t, 2] * q[t, 2]) / qq
    return zbuf, out


def random_triangles(rng, n, width, height, integer=False):
    xy = rng.uniform(-4, [width + 4, height + 4], size=(n, 3, 2))
    if integer:
        xy = np.round(xy)
    z = rng.uniform(0, 1, size=(n, 3, 1))
    return np.concatenate([xy, z], axis=2)


@pytest.mark.parametrize("integer", [False, True])
def test_depth_and_gouraud_match_the_per_pixel_reference(integer):
    rng = np.random.default_rng(5 + integer)
    w, h = 37, 29
    tris = random_triangles(rng, 40, w, h, integer)
    gray = rng.uniform(0, 255, size=(40, 3))
    fb = sl.FrameBuffer(w, h, mode="L")
    depth = sl.DepthBuffer.like(fb)
    sl.draw.triangles(fb, tris, colors=gray, depth=depth)
    zref, vref = reference(w, h, tris, gray)
    # the same pixels are covered ...
    assert np.array_equal(np.isfinite(depth.array), np.isfinite(zref))
    covered = np.isfinite(zref)
    # ... at the same depths (incremental along the scan line: rounding only)
    assert np.abs(depth.array[covered] - zref[covered]).max() < 1e-9
    # ... with the same winner and value, except where two depths nearly tie
    ours = fb._raster()[0][..., 0].astype(int)
    expect = np.rint(vref).astype(int)
    assert (np.abs(ours[covered] - expect[covered]) <= 1).mean() > 0.99


def test_coverage_is_exactly_the_polygon_fill():
    rng = np.random.default_rng(11)
    for integer in (False, True):
        for tri in random_triangles(rng, 60, 30, 20, integer):
            a = sl.FrameBuffer(30, 20, mode="L")
            b = sl.FrameBuffer(30, 20, mode="L")
            sl.draw.triangles(a, [tri], colors=255)
            sl.draw.polygon(b, tri[:, :2], color=255)
            assert np.array_equal(a.to_array(), b.to_array()), tri


def test_a_mesh_covers_each_pixel_once():
    # a fan of triangles around a center, and a grid of split squares
    rng = np.random.default_rng(2)
    pts = rng.uniform(0, 40, size=(12, 2))
    center = np.array([20.3, 19.7])
    ang = np.sort(rng.uniform(0, 2 * np.pi, 12))
    rim = center + np.c_[np.cos(ang), np.sin(ang)] * rng.uniform(8, 19, (12, 1))
    fan = [[(*center, 0), (*rim[i], 0), (*rim[(i + 1) % 12], 0)] for i in range(12)]
    grid = []
    for i in range(5):
        for j in range(5):
            p = [(i * 7.5, j * 7.5), ((i + 1) * 7.5, j * 7.5), ((i + 1) * 7.5, (j + 1) * 7.5),
                 (i * 7.5, (j + 1) * 7.5)]
            grid += [[(*p[0], 0), (*p[1], 0), (*p[2], 0)], [(*p[0], 0), (*p[2], 0), (*p[3], 0)]]
    del pts
    for mesh in (fan, grid):
        counts = np.zeros((40, 40), int)
        for tri in mesh:
            fb = sl.FrameBuffer(40, 40, mode="L")
            sl.draw.triangles(fb, [tri], colors=1)
            counts += fb._raster()[0][..., 0]
        union = sl.FrameBuffer(40, 40, mode="L")
        sl.draw.triangles(union, mesh, colors=1)
        assert counts.max() == 1
        assert np.array_equal(counts, union._raster()[0][..., 0])


def test_perspective_correct_attributes_match_the_reference():
    rng = np.random.default_rng(3)
    w, h = 31, 23
    tris = random_triangles(rng, 25, w, h)
    wv = rng.uniform(0.5, 4.0, size=(25, 3))
    gray = rng.uniform(0, 255, size=(25, 3))
    fb = sl.FrameBuffer(w, h, mode="L")
    depth = sl.DepthBuffer.like(fb)
    sl.draw.triangles(fb, tris, colors=gray, depth=depth, w=wv)
    zref, vref = reference(w, h, tris, gray, 1.0 / wv)
    covered = np.isfinite(zref)
    ours = fb._raster()[0][..., 0].astype(int)
    assert (np.abs(ours[covered] - np.rint(vref[covered])) <= 1).mean() > 0.99
    # and it differs from affine interpolation
    affine = sl.FrameBuffer(w, h, mode="L")
    sl.draw.triangles(affine, tris, colors=gray, depth=sl.DepthBuffer.like(fb))
    assert (affine._raster()[0] != fb._raster()[0]).sum() > 50


def test_depth_test_keeps_the_nearer_and_no_test_keeps_the_later():
    near = [(0, 0, 0.2), (20, 0, 0.2), (0, 20, 0.2)]
    far = [(0, 0, 0.8), (20, 0, 0.8), (0, 20, 0.8)]
    fb = sl.FrameBuffer(10, 10, mode="RGB")
    d = sl.DepthBuffer.like(fb)
    sl.draw.triangles(fb, [near, far], colors=["red", "blue"], depth=d)
    assert fb.get_pixel(3, 3) == (255, 0, 0)
    assert d.array[3, 3] == pytest.approx(0.2)
    sl.draw.triangles(fb, [near, far], colors=["red", "blue"])
    assert fb.get_pixel(3, 3) == (0, 0, 255)


def test_depth_buffer_object():
    d = sl.DepthBuffer(4, 3)
    assert np.isinf(d.to_array()).all() and d.to_array().shape == (3, 4)
    fb = sl.FrameBuffer(4, 3, mode="L")
    sl.draw.triangles(fb, [[(-1, -1, 0.25), (9, -1, 0.5), (-1, 9, 0.75)]], colors=200, depth=d)
    img = d.image()
    assert img.mode == "L" and img.width == 4
    a = img.to_array()
    assert a[-1, 0] == 255 and a.min() < 255          # the nearest white, farther darker
    d.clear(0.5)
    assert (d.array == 0.5).all()


@pytest.mark.parametrize("bad, match", [
    (np.full((1, 3, 3), np.nan), "not finite"),
    (np.full((1, 3, 3), np.inf), "not finite"),
    (np.zeros((2, 4, 3)), "shape"),
    ([[1, 2]], "shape"),
    ("triangles", "real numbers"),
])
def test_bad_vertices(bad, match):
    fb = sl.FrameBuffer(8, 8)
    with pytest.raises(sl.ScanlineError, match=match):
        sl.draw.triangles(fb, bad)


def test_far_vertices_are_drawn_not_refused():
    # any finite coordinate is drawn (issue 11; refused before): a triangle at 1e300
    # collapsed to a point covers nothing, one reaching 1e300 covers the frame's part
    # of it (tests/hardening/test_far_coordinates.py checks depths and colors)
    fb = sl.FrameBuffer(8, 8)
    sl.draw.triangles(fb, np.full((1, 3, 3), 1e300))
    assert not fb.to_array().any()
    sl.draw.triangles(fb, [[(0, 0, 0), (1e300, 0, 0), (0, 1e300, 0)]])
    assert fb.to_array().any(axis=2).sum() == 8 * 8 - 8      # the bottom row is an edge


def test_bad_depth_buffers_and_modes():
    fb = sl.FrameBuffer(8, 8)
    tri = [[(0, 0, 0), (5, 0, 0), (0, 5, 0)]]
    with pytest.raises(sl.ScanlineError, match="8 x 8"):
        sl.draw.triangles(fb, tri, depth=sl.DepthBuffer(9, 8))
    with pytest.raises(sl.ScanlineError, match="DepthBuffer"):
        sl.draw.triangles(fb, tri, depth=np.zeros((8, 8)))
    d = sl.DepthBuffer(8, 8)
    d.array = d.array.astype(np.float32)
    with pytest.raises(sl.ScanlineError, match="float64"):
        sl.draw.triangles(fb, tri, depth=d)
    with pytest.raises(sl.ScanlineError, match="mode"):
        sl.draw.triangles(sl.FrameBuffer(8, 8, mode="1"), tri)
    with pytest.raises(sl.ScanlineError, match="w must"):
        sl.draw.triangles(fb, tri, w=[[1, 0, 1]])
    with pytest.raises(sl.ScanlineError, match="clear"):
        sl.DepthBuffer(4, 4, clear=float("nan"))


def test_degenerate_and_huge_triangles_write_inside_only():
    fb = sl.FrameBuffer(16, 16, mode="L")
    d = sl.DepthBuffer.like(fb)
    tris = [[(0, 0, 0), (5, 5, 0), (10, 10, 0)],               # zero area
            [(3, 3, 0), (3, 3, 0), (3, 3, 0)],                 # a point
            [(-1e9, -1e9, 0.5), (1e9, -1e9, 0.5), (0, 1e9, 0.5)]]   # far beyond
    sl.draw.triangles(fb, tris, colors=[10, 20, 30], depth=d)
    assert (fb.to_array() == 30).all()
