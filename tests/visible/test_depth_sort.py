"""Depth sort: each of the five tests decides a constructed pair; cycles; bad input."""

import importlib

import numpy as np
import pytest

import scanline as sl
from scanline.errors import BSPTooLargeError, DepthSortLoopError
from scanline.visible import TESTS, ScreenPolygons, depth_sort

from .test_methods import H, W, compare


def quad(x0, y0, x1, y1, z00, z10=None, z11=None, z01=None):
    z10 = z00 if z10 is None else z10
    z11 = z00 if z11 is None else z11
    z01 = z00 if z01 is None else z01
    return np.array([[x0, y0, z00], [x1, y0, z10], [x1, y1, z11], [x0, y1, z01]], float)


def decided_by(polys):
    """The test that decided the first pair compared, and the log."""
    log = []
    depth_sort(ScreenPolygons.from_device(polys, W, H), log=log)
    row = log[0]
    passed = [name for name in TESTS if row.get(name) == "yes"]
    return passed, log


# S is the first in the sorted list (greatest depth); S' the one compared with it.
CASES = {
    # 1: x extents apart, depths overlapping
    TESTS[0]: [quad(0, 0, 10, 10, 0.5, 0.7, 0.7, 0.5), quad(20, 0, 30, 10, 0.6)],
    # 2: x extents overlap, y extents apart
    TESTS[1]: [quad(0, 0, 10, 10, 0.5, 0.7, 0.7, 0.5), quad(5, 20, 15, 28, 0.6)],
    # 3: S (tilted, far) wholly behind the plane of S' (flat, in front of it)
    TESTS[2]: [quad(0, 0, 20, 20, 0.75, 0.95, 0.95, 0.75), quad(5, 5, 25, 25, 0.5, 0.5, 0.8,
                                                              0.8)],
    # 4: S' wholly in front of the plane of S, S not behind S's plane
    TESTS[3]: [quad(0, 0, 20, 20, 0.5, 0.9, 0.9, 0.5), quad(10, 5, 30, 15, 0.6)],
    # 5: bounding boxes overlap, planes straddle, projections apart
    TESTS[4]: [np.array([[0, 0, 0.5], [20, 0, 0.9], [0, 20, 0.5]], float),
               np.array([[25, 10, 0.5], [25, 25, 0.5], [11, 25, 0.9]], float)],
}


@pytest.mark.parametrize("test", TESTS)
def test_each_test_decides_its_case(test):
    polys = CASES[test]
    passed, log = decided_by(polys)
    assert passed == [test], log[0]
    # the tests before it were tried and failed, in order
    k = TESTS.index(test)
    assert [log[0][name] for name in TESTS[:k]] == ["no"] * k
    assert compare(depth_sort(ScreenPolygons.from_device(polys, W, H)), polys) == []


def cyclic():
    """Three sticks overlapping cyclically: each lies over the next."""
    a = quad(2, 4, 36, 10, 0.2, 0.2, 0.2, 0.2)
    a[:, 2] = [0.3, 0.7, 0.7, 0.3]        # near at the left, far at the right
    b = np.array([[30, 0, 0.3], [36, 4, 0.3], [14, 28, 0.7], [8, 24, 0.7]], float)
    c = np.array([[4, 14, 0.7], [10, 8, 0.7], [30, 28, 0.3], [24, 30, 0.34]], float)
    return [a, b, c]


def test_cyclic_overlap_split():
    polys = cyclic()
    sp = ScreenPolygons.from_device(polys, W, H)
    log = []
    out = depth_sort(sp, log=log)
    assert len(out) > 3                      # something was split
    assert any("split" in row["action"] for row in log)
    assert compare(out, polys) == []
    assert sl.visible.painter(sp) is not None
    assert compare(sl.visible.painter(sp), polys) != []


def test_cycle_without_splitting_is_an_error():
    sp = ScreenPolygons.from_device(cyclic(), W, H)
    with pytest.raises(DepthSortLoopError, match="split_cycles=True"):
        depth_sort(sp, split_cycles=False)


def test_intersecting_pair_split():
    a = quad(2, 2, 30, 20, 0.2, 0.8, 0.8, 0.2)
    b = quad(5, 5, 35, 25, 0.8, 0.2, 0.2, 0.8)
    out = depth_sort(ScreenPolygons.from_device([a, b], W, H))
    assert len(out) >= 3 and sorted(set(out.face.tolist())) == [0, 1]
    assert compare(out, [a, b]) == []


def weave(n=6):
    """n horizontal and n vertical sticks woven like a basket: each stick passes over
    and under the crossing ones in turn, so every crossing pair is tilted through the
    other -- intersections and cycles everywhere."""
    polys = []
    for i in range(n):
        y = 2 + i * (H - 4) / n
        tilt = 0.3 if i % 2 else -0.3
        polys.append(quad(1, y, W - 1, y + 2.5, 0.5 - tilt, 0.5 + tilt, 0.5 + tilt, 0.5 - tilt))
        x = 2 + i * (W - 4) / n
        polys.append(quad(x, 1, x + 3, H - 1, 0.5 + tilt, 0.5 + tilt, 0.5 - tilt, 0.5 - tilt))
    return polys


@pytest.mark.parametrize("compile_mode", ["never", "always"])
def test_a_woven_scene_needs_many_splits_and_still_matches_ray_casting(compile_mode,
                                                                      monkeypatch):
    # each split ends one piece and makes two: more pieces than the sort's first arrays
    # hold (twice the polygons plus 16), so the kernel stops for room, the arrays grow,
    # and the sort resumes; the Python twin and the compiled kernel agree
    from scanline._kernels import _jit

    monkeypatch.setattr(_jit, "COMPILE", compile_mode)
    polys = weave()
    out = depth_sort(ScreenPolygons.from_device(polys, W, H))
    splits = len(out) - len(polys)
    assert len(polys) + 2 * splits > 2 * len(polys) + 16
    assert compare(out, polys) == []
    log = []
    again = depth_sort(ScreenPolygons.from_device(polys, W, H), log=log)
    assert compare(again, polys) == []
    assert sum("split" in row["action"] for row in log) == len(again) - len(polys)


#: The canvas of :func:`small_triangles`.
SMALL_W, SMALL_H = 256, 192


def small_triangles(n, seed):
    """n random small triangles at random depths on SMALL_W x SMALL_H, overlapping
    about six deep, some intersecting (the benchmark's scene, at the same density)."""
    rng = np.random.default_rng(seed)
    c = rng.uniform([0, 0], [SMALL_W, SMALL_H], (n, 2))
    r = rng.uniform(3, 25, (n, 1, 1))
    ang = rng.uniform(0, 2 * np.pi, (n, 1)) + np.array([0, 2.1, 4.2])
    xy = c[:, None, :] + r * np.stack([np.cos(ang), np.sin(ang)], axis=-1)
    z = rng.uniform(0.05, 0.95, (n, 1)) + rng.uniform(-0.02, 0.02, (n, 3))
    return ScreenPolygons.from_device(list(np.concatenate([xy, z[:, :, None]], axis=-1)),
                                      SMALL_W, SMALL_H)


def same_pieces(a, b):
    return (np.array_equal(a.vertices, b.vertices) and np.array_equal(a.offsets, b.offsets)
            and np.array_equal(a.face, b.face))


@pytest.mark.parametrize("seed", [1, 2])
def test_the_grid_search_finds_what_comparing_every_surface_finds(seed):
    # the sort looks for the surfaces to compare with S in the grid cells it shares
    # with them, read in depth order up to the first surface wholly in front of S; a
    # step table (log=) compares S with every surface alive instead: the same pairs
    # reach the tests, so the same pieces come out in the same order
    sp = small_triangles(1000, seed)
    log = []
    fast, every = depth_sort(sp), depth_sort(sp, log=log)
    assert any("split" in row["action"] for row in log)
    assert any("move" in row["action"] for row in log)
    assert same_pieces(fast, every)


def test_the_buckets_grow_when_the_grid_needs_more_entries(monkeypatch):
    # the kernel counts the grid entries itself; given too few rows it stops for
    # room, and the sort resumes with enough
    module = importlib.import_module("scanline.visible.depth_sort")   # not the function
    sp = small_triangles(300, 3)
    expected = depth_sort(sp)
    asked = []
    monkeypatch.setattr(module, "_bucket_room", lambda entries: asked.append(entries) or 1)
    assert same_pieces(depth_sort(sp), expected)
    assert asked and asked[0] > len(sp)              # one row a piece would be too few


def test_too_many_pieces_is_an_error():
    with pytest.raises(DepthSortLoopError, match="max_pieces"):
        depth_sort(ScreenPolygons.from_device(cyclic(), W, H), max_pieces=1)


def test_bad_input():
    with pytest.raises(sl.ArgumentValueError, match="non-finite"):
        ScreenPolygons.from_device([quad(0, 0, 5, 5, np.nan)], W, H)
    with pytest.raises(sl.ArgumentValueError, match="not convex"):
        ScreenPolygons.from_device([np.array([[0, 0, 0], [10, 0, 0], [2, 2, 0], [0, 10, 0]],
                                             float)], W, H)
    with pytest.raises(sl.ArgumentValueError, match="not planar"):
        ScreenPolygons.from_device([quad(0, 0, 5, 5, 0.1, 0.2, 0.1, 0.2)], W, H)
    with pytest.raises(sl.ArgumentTypeError, match="ScreenPolygons"):
        depth_sort([quad(0, 0, 5, 5, 0.5)])
    with pytest.raises(sl.ArgumentValueError, match="method"):
        sl.render(sl.FrameBuffer(8, 8), sl.mesh.cube(), sl.Camera(), method="nope")


def test_bsp_million_coplanar_polygons_bounded():
    n = 1_000_000
    rng = np.random.default_rng(0)
    base = rng.uniform(-1, 1, (n, 2))
    tri = np.zeros((n, 3, 3))
    tri[:, 0, :2] = base
    tri[:, 1, :2] = base + [0.01, 0]
    tri[:, 2, :2] = base + [0, 0.01]
    mesh = sl.mesh.Mesh(tri.reshape(-1, 3), np.arange(3 * n).reshape(n, 3))
    tree = sl.visible.BSPTree(mesh)
    assert len(tree) == 1 and len(tree.pieces[0]) == n and tree.splits == 0
    assert len(tree.order((0, 0, 5))) == n


def crossed_sticks(count=6):
    """Boxes crossing each other at 30-degree steps: many splits."""
    sticks = []
    for k in range(count):
        a = np.radians(30 * k)
        c, s = np.cos(a), np.sin(a)
        sticks.append(sl.mesh.box((-2, -0.1, -0.1), (2, 0.1, 0.1)).transformed(
            np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0.05 * k], [0, 0, 0, 1]])))
    return sticks


@pytest.mark.parametrize("compile_mode", ["never", "always"])
def test_bsp_tree_of_crossed_sticks_grows_its_arrays_and_orders_every_piece(compile_mode,
                                                                           monkeypatch):
    # more pieces than the build's first arrays hold: the kernel stops for room and
    # resumes; every piece is listed once from any eye, the far side of the root first
    from scanline._kernels import _jit

    monkeypatch.setattr(_jit, "COMPILE", compile_mode)
    tree = sl.visible.BSPTree(crossed_sticks())
    faces = 6 * 6
    assert tree.splits > 0 and len(tree._pieces) > 2 * faces + 64
    for eye in [(0, 0, 9), (5, -3, 1), (0, 0, 1, 0)]:
        order = tree.order(eye)
        live = sum(len(p) for p in tree.pieces)
        assert sorted(order.tolist()) == sorted(np.concatenate(tree.pieces).tolist())
        assert len(order) == live
        root = tree.pieces[0]
        e = np.append(eye, 1.0) if len(eye) == 3 else np.array(eye, float)
        far = tree.back[0] if tree.planes[0] @ e >= 0 else tree.front[0]
        if far >= 0:                           # the far subtree is drawn before the root
            assert order.tolist().index(int(root[0])) > order.tolist().index(
                int(tree.pieces[far][0]))


def test_bsp_piece_limit():
    with pytest.raises(BSPTooLargeError, match="max_pieces"):
        sl.visible.BSPTree(crossed_sticks(), max_pieces=40)


@pytest.mark.parametrize("compile_mode", ["never", "always"])
def test_runs_handed_over_are_every_piece_once_in_drawing_order(compile_mode, monkeypatch):
    # the sort pauses after each run of RUN pieces (here 37: a run ends between any
    # two pieces, splits included) and hands the run to drawn=; the runs put end to
    # end are the pieces returned, and pausing changes no piece
    from scanline._kernels import _jit

    monkeypatch.setattr(_jit, "COMPILE", compile_mode)
    module = importlib.import_module("scanline.visible.depth_sort")
    monkeypatch.setattr(module, "RUN", 37)
    sp = small_triangles(400, 4)
    runs = []
    out = depth_sort(sp, drawn=lambda v, o, f: runs.append((v.copy(), o.copy(), f.copy())))
    assert len(out) > len(sp) and same_pieces(out, depth_sort(sp))
    assert [len(f) for _, _, f in runs[:-1]] == [37] * (len(runs) - 1)
    assert 0 < len(runs[-1][2]) <= 37
    assert np.array_equal(np.concatenate([f for _, _, f in runs]), out.face)
    assert np.array_equal(np.concatenate([v for v, _, _ in runs]), out.vertices)
    for (v, o, f), lo in zip(runs, range(0, len(out), 37)):
        assert o[0] == 0 and o[-1] == len(v) and len(o) == len(f) + 1
        assert np.array_equal(o + out.offsets[lo], out.offsets[lo:lo + len(f) + 1])


def test_drawn_must_be_a_function():
    with pytest.raises(sl.ArgumentTypeError, match="drawn must be a function"):
        depth_sort(small_triangles(5, 1), drawn=3)


@pytest.mark.parametrize("mode", ["1", "L", "RGB", "RGBA"])
def test_painting_beside_the_sort_gives_the_pixels_of_sort_then_paint(mode, monkeypatch):
    # painted_depth_sort paints each run on a second thread while the sort goes on;
    # the pixels are those of painting the sorted pieces afterwards (short runs, so
    # that many runs overlap the sort)
    from scanline.shading import paint
    from scanline.visible.visibility import piece_numbers

    module = importlib.import_module("scanline.visible.depth_sort")
    monkeypatch.setattr(module, "RUN", 50)
    sp = small_triangles(800, 5)
    ours = sl.FrameBuffer(SMALL_W, SMALL_H, mode=mode, background="white")
    theirs = sl.FrameBuffer(SMALL_W, SMALL_H, mode=mode, background="white")
    rng = np.random.default_rng(5)
    values = np.array([ours.pixel(tuple(int(c) for c in rng.integers(0, 256, 3)))
                       for _ in range(len(sp))], np.uint8).reshape(len(sp), -1)
    pieces, numbers = sl.visible.painted_depth_sort(sp)
    paint(ours, numbers, values[pieces.face])
    after = depth_sort(sp)
    paint(theirs, piece_numbers(after), values[after.face])
    assert same_pieces(pieces, after)
    assert np.array_equal(ours.to_array(), theirs.to_array())
    shades = len(np.unique(ours.to_array().reshape(SMALL_H * SMALL_W, -1), axis=0))
    assert shades == 2 if mode == "1" else shades > 100


def cyclic_bars():
    """Three flat bars in world space, each lying over the next (120 degrees apart,
    each one's far end raised over the next one's near end)."""
    bars = []
    for k in range(3):
        a = 2 * np.pi * k / 3
        c, s = np.cos(a), np.sin(a)
        turn = np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
        shift = np.array([[1, 0, 0, 0], [0, 1, 0, 0.55], [0, 0, 1, 0], [0, 0, 0, 1]])
        bar = sl.mesh.Mesh([(-1.6, -0.22, -0.35), (1.6, -0.22, 0.35), (1.6, 0.22, 0.35),
                            (-1.6, 0.22, -0.35)], [[0, 1, 2, 3]])
        bars.append(bar.transformed(turn @ shift))
    return bars


def test_a_render_whose_sort_fails_leaves_the_frame_buffer_as_it_was():
    cam = sl.Camera(eye=(0, 0, 6), target=(0, 0, 0),
                    projection=sl.projection.orthographic(window=(-2.5, -2.5, 2.5, 2.5)))
    fb = sl.FrameBuffer(W, H, background="white")
    before = fb.to_array()
    with pytest.raises(DepthSortLoopError):
        sl.render(fb, cyclic_bars(), cam, method="depth-sort", split_cycles=False)
    assert np.array_equal(fb.to_array(), before)
    sl.render(fb, cyclic_bars(), cam, method="depth-sort")         # split: drawn
    assert not np.array_equal(fb.to_array(), before)


def test_painting_checks_the_values_and_the_numbers():
    from scanline.shading import paint
    from scanline.visible.visibility import piece_numbers

    sp = small_triangles(20, 6)
    numbers = piece_numbers(sp)
    fb = sl.FrameBuffer(SMALL_W, SMALL_H, mode="L")
    for values, message in [(np.zeros((20, 3), np.uint8), r"shape \(n, 1\) for a mode 'L'"),
                            (np.zeros(20, np.uint8), "one pixel value per number"),
                            (np.full((20, 1), 300), "integers 0-255"),
                            (np.zeros((20, 1), float), "integers 0-255"),
                            (np.zeros((5, 1), np.uint8), "values holds 5 rows.*number 19")]:
        with pytest.raises(sl.ArgumentValueError, match=message):
            paint(fb, numbers, values)
    for ids, message in [(numbers[:-1], "ids must have the frame buffer's shape"),
                         (numbers.astype(float), "ids must be integers")]:
        with pytest.raises(sl.ArgumentValueError, match=message):
            paint(fb, ids, np.zeros((20, 1), np.uint8))
    assert not fb.to_array().any()
    paint(fb, numbers, np.full((20, 1), 200))      # integers are taken
    assert (fb.to_array() == 200).any()


def tangled(n, seed=3, size=120.0):
    """n large triangles at random depths in device space: each cuts hundreds of
    others (the sort's worst case)."""
    rng = np.random.default_rng(seed)
    c = rng.uniform([0, 0], [800, 600], (n, 2))
    r = rng.uniform(10, size, (n, 1, 1))
    ang = rng.uniform(0, 2 * np.pi, (n, 1)) + np.sort(rng.uniform(0, 2 * np.pi, (n, 3)), 1)
    xy = c[:, None, :] + r * np.stack([np.cos(ang), np.sin(ang)], axis=-1)
    return np.concatenate([xy, rng.uniform(0.05, 0.95, (n, 3, 1))], axis=-1)


def test_a_tangled_scene_stops_at_the_work_bound():
    # 16,000 large triangles at random depths: without a bound the sort went on for
    # minutes (pieces by the hundred thousand); it stops at the bound on the surfaces
    # compared, 2,000,000 + 100 per polygon, with an error that says what to do
    from scanline.visible.depth_sort import default_work

    sp = ScreenPolygons.from_device(list(tangled(16_000)), 800, 600)
    with pytest.raises(DepthSortLoopError, match=r"gave up after comparing 3,600,000 "
                                                 r"surfaces.*method='z-buffer'.*max_work"):
        depth_sort(sp)
    assert default_work(16_000) == 3_600_000
    with pytest.raises(DepthSortLoopError, match="gave up after comparing 50,000 surfaces"):
        depth_sort(sp, max_work=50_000)


def test_whole_objects_stay_within_the_bound_per_polygon():
    # the benchmark's kind of scene (small triangles, many deep) and whole meshes sort
    # within the bound's share per polygon alone (100 each), without its constant
    sp = small_triangles(3000, 9)
    assert len(depth_sort(sp, max_work=100 * 3000)) >= 3000
    cam = sl.Camera(eye=(4, 3, 5), target=(0, 0, 0))
    meshes = [sl.mesh.sphere(1.0, (0.6, 0.4, 0.3), resolution=24),
              sl.mesh.torus(1.3, 0.35, resolution=(32, 12)), sl.mesh.cube(1.6)]
    polys = sl.visible.screen_polygons(meshes, cam, 320, 240)
    assert len(depth_sort(polys, max_work=100 * len(polys))) >= len(polys)


def test_a_render_falls_back_when_the_sort_gives_up():
    n = 2000
    tri = tangled(n, 4)
    # the same triangles as a mesh seen straight on by an orthographic camera
    world = np.concatenate([tri[..., :2] / 100.0, -10 * tri[..., 2:]], axis=-1)
    mesh = sl.mesh.Mesh(world.reshape(-1, 3), np.arange(3 * n).reshape(n, 3))
    cam = sl.Camera(eye=(4, 3, 5), target=(4, 3, 0),
                    projection=sl.projection.orthographic(window=(-4, -3, 4, 3)))
    with pytest.raises(DepthSortLoopError):
        sl.render(sl.FrameBuffer(80, 60), mesh, cam, method="depth-sort", max_work=10_000)
    fb, ref = sl.FrameBuffer(80, 60), sl.FrameBuffer(80, 60)
    with pytest.warns(sl.ScanlineWarning, match="method='depth-sort' gave up.*z-buffer"):
        r = sl.render(fb, mesh, cam, method="depth-sort", max_work=10_000, fallback="z-buffer")
    assert r.method == "z-buffer"
    sl.render(ref, mesh, cam, method="z-buffer")
    assert np.array_equal(fb.to_array(), ref.to_array())


def test_a_step_table_log_is_bounded(monkeypatch):
    module = importlib.import_module("scanline.visible.depth_sort")
    monkeypatch.setattr(module, "LOG_ROWS", 500)
    with pytest.raises(sl.ScanlineError, match="log: the step table of 400 polygons passes "
                                               "500 rows"):
        depth_sort(small_triangles(400, 2), log=[])
    log = []
    depth_sort(ScreenPolygons.from_device(cyclic(), W, H), log=log)   # a small one: in full
    assert log and len(log) < 500
