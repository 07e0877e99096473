"""The fast paths of the triangle rasterizer, the scene preparation and the
visibility-buffer shading: calls sharing the bands on several threads cover every
pixel once and give the single call's pixels; band edges keep the polygon fill's
coverage; the affine path equals the perspective one where 1/w is constant; the
kernel's clear equals a cleared buffer; the mesh arrays kept for the preparation
follow changes of the mesh; the highlight floor keeps extreme exponents within one
stored level of the numpy path."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline._kernels import _threads
from scanline._kernels import raster3d as k
from scanline._kernels import shade as ks
from scanline._kernels.variants import MODE, token
from scanline.screen import DevicePolygons, mesh_arrays, prepare
from scanline.shading import ShadingOptions, barycentrics, encode, intensities
from scanline.shading.buffer import gamma_tables, shade_buffer
from scanline.draw.triangles import bin_bands
from scanline.visible.zbuffer import nearest


def random_triangles(rng, n, width, height, size):
    c = rng.uniform(0, [width, height], size=(n, 1, 2))
    xy = c + rng.uniform(-size, size, size=(n, 3, 2))
    z = rng.uniform(0, 1, size=(n, 3, 1))
    return np.ascontiguousarray(np.concatenate([xy, z], axis=2))


def draw_in_calls(width, height, tri, att, steps):
    """The COLOR/TEST kernel run as ``steps`` calls (start 0 .. steps - 1), one after
    another: each call draws its own bands."""
    n = len(tri)
    bins, _ = bin_bands(tri, np.ones((n, 3)), att, np.zeros(n, np.int64), height)
    buf = np.zeros((height, width, att.shape[2]), np.uint8)
    zbuf = np.full((height, width), np.inf)
    for start in range(steps):
        k.raster_triangles(start, steps, token(k.COLOR), token(k.TEST), *bins, False, zbuf,
                           np.empty((1, 1)), buf, np.empty((1, 1, 1)),
                           np.empty((1, 1), np.int64),
                           np.empty((steps, k.SETUP_BATCH, att.shape[2] + 2, 3)),
                           np.empty((steps, k.SETUP_BATCH), np.bool_),
                           np.empty((steps, 2, k.BAND), np.int64), np.empty((steps, 0)))
    return buf, zbuf


@pytest.mark.parametrize("steps", [2, 3])
def test_calls_sharing_the_bands_draw_what_one_call_draws(steps):
    # 300 rows: five bands of 64, the last one short; triangles across band edges
    rng = np.random.default_rng(7)
    w, h = 90, 300
    tri = random_triangles(rng, 400, w, h, 30.0)
    att = np.ascontiguousarray(rng.uniform(0, 255, size=(400, 3, 3)))
    one, zone = draw_in_calls(w, h, tri, att, 1)
    many, zmany = draw_in_calls(w, h, tri, att, steps)
    assert np.array_equal(one, many) and np.array_equal(zone, zmany)
    assert np.isfinite(zone).mean() > 0.9


def test_threads_split_the_work_without_overlap(monkeypatch):
    # three threads, one call each with its own start, and the single call's pixels
    calls = []
    real = _threads.call

    def counted(kernel, work, *args):
        if kernel.__name__ == "raster_triangles":      # (the binning runs in chunks too)
            calls.append((kernel.__name__, args[0], args[1]))
        return real(kernel, work, *args)

    monkeypatch.setattr(_threads, "call", counted)
    rng = np.random.default_rng(8)
    w, h = 200, 700
    tri = random_triangles(rng, 3000, w, h, 12.0)
    gray = rng.uniform(0, 255, size=(3000, 3))
    images = []
    for n in (3, 1):
        monkeypatch.setattr(_threads, "threads", lambda n=n: n)
        fb = sl.FrameBuffer(w, h, mode="L")
        depth = sl.DepthBuffer.like(fb)
        sl.draw.triangles(fb, tri, colors=gray, depth=depth)
        images.append((fb.to_array(), depth.array.copy()))
    assert sorted(calls) == [("raster_triangles", 0, 1), ("raster_triangles", 0, 3),
                             ("raster_triangles", 1, 3), ("raster_triangles", 2, 3)]
    assert np.array_equal(images[0][0], images[1][0])
    assert np.array_equal(images[0][1], images[1][1])
    assert np.isfinite(images[0][1]).mean() > 0.3


def test_band_edges_keep_the_polygon_fill_coverage():
    # triangles whose rows cross the band edges at 63/64 and 127/128
    rng = np.random.default_rng(9)
    for _ in range(40):
        tri = np.concatenate([rng.uniform([0, 40], [40, 150], size=(3, 2)),
                              rng.uniform(0, 1, size=(3, 1))], axis=1)
        a = sl.FrameBuffer(40, 160, mode="L")
        b = sl.FrameBuffer(40, 160, mode="L")
        sl.draw.triangles(a, [tri], colors=255)
        sl.draw.polygon(b, tri[:, :2], color=255)
        assert np.array_equal(a.to_array(), b.to_array()), tri


def test_the_affine_path_equals_the_perspective_one_where_w_is_constant():
    # w = 1 everywhere skips the division a/w / (1/w); w = 2 everywhere takes it:
    # the same colors within one level (the division rounds)
    rng = np.random.default_rng(10)
    w, h = 60, 140
    tri = random_triangles(rng, 200, w, h, 15.0)
    colors = rng.uniform(0, 255, size=(200, 3, 3))
    a = sl.FrameBuffer(w, h)
    b = sl.FrameBuffer(w, h)
    sl.draw.triangles(a, tri, colors=colors, depth=sl.DepthBuffer.like(a))
    sl.draw.triangles(b, tri, colors=colors, depth=sl.DepthBuffer.like(b),
                      w=np.full((200, 3), 2.0))
    diff = np.abs(a._raster()[0].astype(int) - b._raster()[0].astype(int))
    assert diff.max() <= 1 and (diff > 0).mean() < 0.01
    assert (a._raster()[0] > 0).any(axis=2).mean() > 0.5


def scene():
    cam = sl.Camera(eye=(1.5, 1.0, 5.0), target=(0, 0, 0),
                    projection=sl.projection.perspective(fov=math.radians(45), near=0.5,
                                                         far=20))
    torus = sl.mesh.torus(1.0, 0.35, resolution=(24, 12))
    return torus, cam


def test_the_kernel_clear_equals_a_cleared_buffer():
    torus, cam = scene()
    sc = prepare(torus, cam, 70, 150)
    first = nearest(sc)                                      # cleared by the kernel
    ids, depth = first.ids.copy(), first.depth.copy()
    before = np.full((150, 70), np.inf)
    second = nearest(sc, zbuf=before)                        # cleared beforehand
    assert np.array_equal(ids, second.ids) and np.array_equal(depth, second.depth)
    seen = ids >= 0
    assert seen.mean() > 0.1 and (ids[~seen] == -1).all() and np.isinf(depth[~seen]).all()


def test_mesh_arrays_follow_changes_of_the_mesh():
    torus, cam = scene()
    first = mesh_arrays(torus)
    assert mesh_arrays(torus) is first                       # kept
    fb1 = sl.FrameBuffer(60, 50)
    sl.render(fb1, torus, cam, shading="phong")
    torus.vertices[:, 2] += 0.3                              # changed in place
    assert mesh_arrays(torus) is not first
    fb2 = sl.FrameBuffer(60, 50)
    sl.render(fb2, torus, cam, shading="phong")
    fresh = sl.mesh.Mesh(torus.vertices, torus.faces, normals=torus.normals)
    fb3 = sl.FrameBuffer(60, 50)
    sl.render(fb3, fresh, cam, shading="phong")
    assert np.array_equal(fb2.to_array(), fb3.to_array())
    assert not np.array_equal(fb1.to_array(), fb2.to_array())


def test_device_polygons_behave_as_a_list():
    torus, cam = scene()
    sc = prepare(torus, cam, 60, 50)
    polys = sc.polygons
    assert isinstance(polys, DevicePolygons)
    listed = list(polys)
    assert len(listed) == len(polys) == len(sc.polygon_facet)
    assert np.array_equal(polys[-1], listed[-1]) and np.array_equal(polys[0], listed[0])
    assert [p.shape for p in polys[2:5]] == [(3, 3)] * 3
    with pytest.raises(IndexError):
        polys[len(polys)]


@pytest.mark.parametrize("shininess", [0.0, 1e6, 3.0])
def test_extreme_exponents_stay_within_a_level_of_the_numpy_path(shininess):
    # the highlight floor skips s^n below 1e-12: the pixels still match the numpy path
    torus, cam = scene()
    mat = sl.lighting.Material(ka=0.2, kd=0.5, ks=0.6, shininess=shininess)
    sc = prepare(torus, cam, 64, 48, mat)
    ids = nearest(sc).ids.copy()
    ys, xs = np.nonzero(ids >= 0)
    tris = ids[ys, xs]
    lights = [sl.lighting.AmbientLight(0.1),
              sl.lighting.DirectionalLight((0.4, -0.6, -1.0), 0.8),
              sl.lighting.PointLight((2, 3, 4), 0.5)]
    options = ShadingOptions(model="phong", lights=lights, specular="phong", gamma=2.2)
    fb = sl.FrameBuffer(64, 48)
    shade_buffer(sc, fb, ids, options)
    got = fb._raster()[0][ys, xs].astype(int)
    bary = barycentrics(sc, tris, xs.astype(float), ys.astype(float))
    want = encode(intensities(sc, sc.facet[tris], bary, options), 2.2)
    assert np.abs(got - want).max() <= 1
    assert (got != want).mean() < 0.01


def test_shading_calls_sharing_the_bands_write_every_pixel_once():
    torus, cam = scene()
    sc = prepare(torus, cam, 50, 140)
    given = nearest(sc).ids.copy()
    facets = np.where(given >= 0, sc.facet[given], -1)
    table, thresholds = gamma_tables(2.2)
    from scanline.shading.buffer import homogeneous_eye, material_rows, source_rows

    sources, ambient = source_rows([sl.lighting.AmbientLight(0.2),
                                    sl.lighting.DirectionalLight((0.4, -0.6, -1.0), 0.8)])
    colors = np.ascontiguousarray(np.broadcast_to(sc.vertex_colors, sc.world.shape))
    # the triangles' ids and functions: the facet and barycentrics found per pixel
    attributes = np.empty((len(sc.facet), 5 + 27))
    ks.triangle_attributes(0, len(sc.facet), sc.triangles, sc.inv_w, sc.bary, sc.facet,
                           sc.world, sc.vertex_normals, colors, sc.front, attributes,
                           ks.SHADING["phong"])
    rest = (sc.facet_mesh, material_rows(sc.materials), ambient, sources,
            homogeneous_eye(sc.eye), table, thresholds)
    images = []
    for steps in (1, 3):
        raster = np.zeros((140, 50, 3), np.uint8)
        ids = given.copy()
        for start in range(steps):
            ks.shade_pixels(start, steps, ids, attributes, sc.facet, *rest, raster,
                            ks.SHADING["phong"], ks.SPECULAR["phong"], MODE["RGB"])
        assert np.array_equal(ids, facets)          # the facets (from the triangles' ids)
        images.append(raster)
    assert np.array_equal(images[0], images[1])
    assert (images[0].any(axis=2) == (facets >= 0)).mean() > 0.99


@pytest.mark.parametrize("threads", [1, 2, 3])
def test_binning_lists_each_band_s_triangles_in_input_order(threads, monkeypatch):
    # the two passes of the counting sort run in chunks, one per thread: whatever the
    # chunks, band b holds exactly the triangles whose rows meet it, in input order,
    # with their 1/w, attributes and ids (found here by numpy from each triangle's
    # lowest and highest y)
    rng = np.random.default_rng(7)
    n = 300_000
    tri = random_triangles(rng, n, 200, 150, 40)
    tri[::97, :, 1] = np.nan                        # covers no row
    q = rng.uniform(0.5, 2, size=(n, 3))
    att = rng.uniform(0, 255, size=(n, 3, 2))
    ids = rng.integers(0, 1 << 40, n)
    monkeypatch.setattr(_threads, "threads", lambda: threads)
    (ptri, pq, patt, pids, starts, _), area = bin_bands(tri, q, att, ids, 150)
    y = tri[:, :, 1]
    with np.errstate(invalid="ignore"):
        first = np.maximum(np.floor(y.min(axis=1)) + 1, 0)
        last = np.minimum(np.floor(y.max(axis=1)), 149)
    met = ~np.isnan(first) & (first <= last)
    assert len(starts) == 150 // k.BAND + 2 and starts[0] == 0
    for b in range(len(starts) - 1):
        lo, hi = b * k.BAND, (b + 1) * k.BAND - 1
        expected = np.flatnonzero(met & (first <= hi) & (last >= lo))
        band = slice(starts[b], starts[b + 1])
        assert np.array_equal(pids[band], ids[expected])
        assert np.array_equal(ptri[band], tri[expected])
        assert np.array_equal(pq[band], q[expected]) and np.array_equal(patt[band], att[expected])
    assert starts[-1] == len(ptri) and area > 0


def test_the_work_estimate_counts_the_boxes():
    tri = np.array([[(0.0, 0.0, 0), (10.0, 0.0, 0), (0.0, 10.0, 0)],
                    [(5.0, 5.0, 0), (5.0, 5.0, 0), (5.0, 5.0, 0)]])
    (ptri, _, _, pids, starts, _), area = bin_bands(tri, np.ones((2, 3)), np.zeros((2, 3, 0)),
                                                 np.arange(2), 20)
    # rows 1..10 (the bottom edge on row 0 is outside), 11 pixels wide; the point
    # covers no row
    assert area == 10 * 11.0 and pids.tolist() == [0] and starts.tolist() == [0, 1]


@pytest.mark.parametrize("ids_only", [False, True])
def test_a_far_vertex_reaching_the_rasterizer_does_not_crash(ids_only):
    # the float -> int conversions of the kernel are clamped first (an out-of-range
    # conversion is undefined in compiled code): a vertex at 1e300 given straight to
    # the kernel, past the API's guard, draws the triangle's part in the raster only
    from scanline.draw.triangles import rasterize

    tri = np.array([[(2.0, 2.0, 0.5), (1e300, 3.0, 0.5), (4.0, 1e300, 0.5)],
                    [(-1e300, -1e300, 0.2), (30.0, 5.0, 0.2), (5.0, 30.0, 0.2)]])
    w, h = 40, 30
    zbuf = np.full((h, w), np.inf)
    ids = np.full((h, w), -1, np.int32)
    abuf = None if ids_only else np.zeros((h, w, 2))
    rasterize(w, h, tri, np.ones((2, 3)), np.zeros((2, 3, 2)), np.arange(2, dtype=np.int64),
              zbuf=zbuf, abuf=abuf, idbuf=ids, clear=True)
    assert set(np.unique(ids)) <= {-1, 0, 1}
    assert np.isfinite(zbuf[ids >= 0]).all()



def test_kept_rows_grow_and_are_shared_by_calls_of_any_length():
    from scanline._pool import scratch_rows

    a = scratch_rows("test.rows", 5, (3,))
    assert a.shape == (5, 3) and a.base is not None and len(a.base) == 8
    a[:] = 1.0
    b = scratch_rows("test.rows", 3, (3,))            # shorter: the same memory
    assert b.shape == (3, 3) and np.shares_memory(a, b)
    c = scratch_rows("test.rows", 9, (3,))            # longer: grown to 16 rows
    assert c.shape == (9, 3) and len(c.base) == 16 and not np.shares_memory(a, c)
    d = scratch_rows("test.rows", 0, (3,), np.int64)  # another dtype: its own
    assert d.shape == (0, 3) and d.dtype == np.int64


def test_rows_beyond_the_bound_are_not_kept(monkeypatch):
    from scanline import _pool

    monkeypatch.setattr(_pool, "ROWS_KEPT", 1000)
    kept = _pool.scratch_rows("test.bound", 10, (3,))          # 16 x 3 x 8 = 384 bytes
    big = _pool.scratch_rows("test.bound", 100, (3,))          # 128 rows: 3,072 bytes
    assert big.shape == (100, 3) and big.base is None        # made for the call alone
    again = _pool.scratch_rows("test.bound", 10, (3,))
    assert np.shares_memory(kept, again)                     # the kept one stays


def test_a_second_batch_of_another_size_draws_what_it_draws_alone():
    # the binned triangles are kept between calls: a batch after a longer one (the
    # kept rows longer than it needs) and after a shorter one draws its own pixels
    rng = np.random.default_rng(12)
    w, h = 120, 90
    big = random_triangles(rng, 2000, w, h, 10.0)
    small = random_triangles(rng, 300, w, h, 10.0)
    colors = {len(t): rng.uniform(0, 255, size=(len(t), 3, 3)) for t in (big, small)}

    def draw(tri):
        fb = sl.FrameBuffer(w, h)
        depth = sl.DepthBuffer.like(fb)
        sl.draw.triangles(fb, tri, colors=colors[len(tri)], depth=depth)
        return fb.to_array(), depth.array.copy()

    alone = draw(small)
    draw(big)
    after_big = draw(small)
    big_after_small = draw(big)
    assert np.array_equal(alone[0], after_big[0]) and np.array_equal(alone[1], after_big[1])
    assert np.array_equal(draw(big)[0], big_after_small[0])
    assert np.isfinite(alone[1]).mean() > 0.2


@pytest.mark.parametrize("mode", ["L", "RGB", "RGBA"])
def test_bands_read_ahead_draw_what_sparse_bands_draw(mode):
    # one call of 600 triangles in 96 x 70: every band holds more than one triangle per
    # READ_AHEAD pixels of its width, so its depths and pixels are read ahead; drawn
    # three at a time no band holds enough: the same pixels and depths either way
    width, height = 96, 70
    rng = np.random.default_rng(11)
    tri = random_triangles(rng, 600, width, height, 9.0)
    colors = rng.uniform(0, 255, size=(600, 3, 1 if mode == "L" else 3))
    if mode == "L":
        colors = colors[:, :, 0]
    assert 600 / 3 * k.READ_AHEAD >= width > 3 * k.READ_AHEAD
    results = []
    for group in (600, 3):
        fb = sl.FrameBuffer(width, height, mode=mode, background="gray")
        depth = sl.DepthBuffer.like(fb)
        depth.array[:, :] = rng.uniform(0.2, 0.8, size=(height, width))  # some fragments lose
        saved = depth.array.copy() if group == 600 else results[0][2]
        depth.array[:, :] = saved
        for lo in range(0, 600, group):
            sl.draw.triangles(fb, tri[lo:lo + group], colors=colors[lo:lo + group],
                              depth=depth)
        results.append((fb.to_array(), depth.array.copy(), saved))
    (pixels, depths, _), (pixels3, depths3, _) = results
    assert np.array_equal(pixels, pixels3) and np.array_equal(depths, depths3)
    drawn = depths < results[0][2]
    assert 0.2 < drawn.mean() < 0.95           # fragments won and lost against the buffer


def test_a_band_is_read_ahead_only_when_it_holds_enough_triangles():
    # the kernel returns the sum of what it read ahead: the depths (0.5) of every
    # eighth pixel and the pixels (1) of every sixteenth, row after row of a band
    width, height = 64, 32                                   # one band
    rng = np.random.default_rng(5)
    for n, read in ((width // k.READ_AHEAD, 32 * (8 * 0.5 + 4 * 1)),
                    (width // k.READ_AHEAD - 1, 0.0)):
        tri = random_triangles(rng, n, width, 16, 4.0) + [0, 8, 0]    # rows 4 .. 27
        att = np.zeros((n, 3, 3))
        bins, _ = bin_bands(tri, np.ones((n, 3)), att, np.zeros(n, np.int64), height)
        assert list(bins[-2]) == [0, n]
        got = k.raster_triangles(0, 1, token(k.COLOR), token(k.TEST), *bins, False,
                                 np.full((height, width), 0.5), np.empty((1, 1)),
                                 np.ones((height, width, 3), np.uint8), np.empty((1, 1, 1)),
                                 np.empty((1, 1), np.int64),
                                 np.empty((1, k.SETUP_BATCH, 5, 3)),
                                 np.empty((1, k.SETUP_BATCH), np.bool_),
                                 np.empty((1, 2, k.BAND), np.int64), np.empty((1, 0)))
        assert got == read
