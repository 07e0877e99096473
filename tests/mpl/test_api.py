"""scanline.mpl's arguments, errors, and the geometry it makes of matplotlib's
polygons, each checked against a plain reference."""

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.path import Path  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

import scanline  # noqa: E402
import scanline.mpl  # noqa: E402
from scanline.mpl import _geometry as g  # noqa: E402

from . import reference as ref  # noqa: E402


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def axes3d(size=3.0):
    fig = plt.figure(figsize=(size, size), dpi=100)
    return fig, fig.add_subplot(projection="3d")


# ---------------------------------------------------------------- errors


@pytest.mark.parametrize("ax", ["2d", None, "figure"])
def test_an_axes_that_is_not_3d_is_refused(ax):
    fig = plt.figure()
    value = {"2d": fig.add_subplot(), None: None, "figure": fig}[ax]
    with pytest.raises(scanline.ArgumentTypeError, match=r"^ax must be a matplotlib 3-D axes"):
        scanline.mpl.render_axes(value)


@pytest.mark.parametrize("kw, name", [
    ({"method": "bogus"}, "method"), ({"method": None}, "method"),
    ({"flatness": -0.1}, "flatness"), ({"flatness": "x"}, "flatness"),
    ({"flatness": float("nan")}, "flatness"),
    ({"samples": 0}, "samples"), ({"samples": 9}, "samples"), ({"samples": 1.5}, "samples"),
    ({"max_pieces": 0}, "max_pieces")])
def test_bad_arguments_name_themselves(kw, name):
    fig, ax = axes3d()
    with pytest.raises(scanline.ScanlineError, match=rf"^{name}\b"):
        scanline.mpl.render_axes(ax, **kw)
    assert not any(isinstance(a, scanline.mpl.Occlusion) for a in ax.get_children())


def test_unknown_method_lists_the_methods():
    fig, ax = axes3d()
    with pytest.raises(ValueError, match="'vector', 'raster'"):
        scanline.mpl.render_axes(ax, method="z-buffer")


def test_a_bad_method_set_later_fails_at_the_draw_by_name():
    fig, ax = axes3d()
    occlusion = scanline.mpl.render_axes(ax)
    occlusion.method = "painter"
    with pytest.raises(scanline.ArgumentValueError, match="^method"):
        fig.canvas.draw()


def test_empty_axes_draw():
    fig, ax = axes3d()
    occlusion = scanline.mpl.render_axes(ax)
    fig.canvas.draw()
    assert occlusion.last.polygons == 0 and occlusion.last.pieces == 0


def test_nan_data_is_left_out():
    fig, ax = axes3d()
    X, Y = np.meshgrid(np.linspace(-1, 1, 6), np.linspace(-1, 1, 6))
    Z = X * Y
    Z[2, 3] = np.nan
    ax.plot_surface(X, Y, Z)
    ax.plot([0, np.nan, 1], [0, 0, 1], [0, 0, 1])
    ax.scatter([0, np.nan], [0, 0], [0, 0])
    for route in ("vector", "raster"):
        occlusion = scanline.mpl.render_axes(ax, method=route)
        fig.canvas.draw()
        assert occlusion.last.segments == 0


# ---------------------------------------------------------------- surfaces


def test_a_strided_surface_covers_what_matplotlib_covers():
    """plot_surface's default strides make polygons of eight points, the middle
    points nearly on the chords: dropped alike by neighbours, so no gap opens."""
    def covered(use):
        fig, ax = axes3d(4)
        x = np.linspace(-2, 2, 100)
        X, Y = np.meshgrid(x, x)
        ax.plot_surface(X, Y, np.exp(-X ** 2 - Y ** 2), color="red", shade=False,
                        antialiased=False)
        ax.set_axis_off()
        ax.view_init(50, -60)                # no part of the surface hides another
        occ = scanline.mpl.render_axes(ax) if use else None
        img = ref.canvas(fig)
        return (np.abs(img.astype(int) - (255, 0, 0)).max(axis=2) < 10), occ
    alone, _ = covered(False)
    ours, occ = covered(True)
    assert occ.last.polygons == 33 * 33 or occ.last.polygons == 2500
    assert occ.last.units < 1.5 * occ.last.polygons        # kept whole, not cut in six
    assert (alone != ours).sum() <= 0.002 * alone.sum()


def test_flatness_trades_triangles_for_whole_polygons():
    units = {}
    for flatness in (0.0, 0.05, 1.0):
        fig, ax = axes3d()
        X, Y = np.meshgrid(np.linspace(-1, 1, 12), np.linspace(-1, 1, 12))
        ax.plot_surface(X, Y, np.sin(3 * X) * np.cos(3 * Y), rstride=1, cstride=1)
        occlusion = scanline.mpl.render_axes(ax, flatness=flatness)
        fig.canvas.draw()
        units[flatness] = occlusion.last.units
        n = occlusion.last.polygons
    assert units[0.0] >= 1.8 * n               # (nearly) every bent quad cut in two
    assert units[0.0] > units[0.05] >= units[1.0]
    assert units[1.0] <= 1.2 * n               # only those not convex on the screen cut


def test_a_non_convex_planar_polygon_is_drawn_as_matplotlib_fills_it():
    """An L-shaped planar face (which matplotlib draws right): the ear-clipped
    triangles cover exactly its pixels."""
    L = np.array([(0, 0, 0), (2, 0, 0), (2, 1, 0), (1, 1, 0), (1, 2, 0), (0, 2, 0)], float)

    def draw(use):
        fig, ax = axes3d()
        ax.add_collection3d(Poly3DCollection([L + (0, 0, 0.5)], facecolor="red",
                                             antialiased=False))
        ax.set_xlim(0, 2)
        ax.set_ylim(0, 2)
        ax.set_zlim(0, 1)
        ax.view_init(60, -70)
        if use:
            scanline.mpl.render_axes(ax)
        return (ref.labels(ref.canvas(fig), [(255, 0, 0)]) == 0)
    alone, ours = draw(False), draw(True)
    assert alone.sum() > 2000
    assert (alone != ours).sum() <= 0.01 * alone.sum()


# ---------------------------------------------------------------- geometry


def test_units_cut_non_convex_polygons_into_covering_triangles():
    rng = np.random.default_rng(5)
    for _ in range(50):
        k = int(rng.integers(4, 9))
        ang = np.sort(rng.uniform(0, 2 * np.pi, k))
        if np.diff(np.r_[ang, ang[0] + 2 * np.pi]).max() >= np.pi:
            continue                                 # the center outside: not simple
        r = rng.uniform(0.3, 1.0, k)                 # a star-shaped (often non-convex) outline
        xy = np.stack([np.cos(ang) * r, np.sin(ang) * r], axis=1) * 50 + 100
        z = 0.2 * xy[:, 0] / 100 + 0.3
        dev = np.c_[xy, z][None]
        verts, counts, owner, bent = g.units(dev, dev.copy(), np.array([k]), 0.05)
        pieces = np.split(verts, np.cumsum(counts)[:-1])
        areas = np.array([g._areas(p[None, :, :2])[0] for p in pieces])
        whole = abs(g._areas(xy[None])[0])
        assert np.isclose(np.abs(areas).sum(), whole, rtol=1e-9)
        assert (np.sign(areas) == np.sign(g._areas(xy[None])[0])).all()
        assert len(pieces) == 1 or (counts == 3).all()
        assert len(pieces) == 1 or not g._convex(xy[None])[0]
        assert (owner == 0).all() and (bent == 0).all()


def test_units_keep_convex_planar_polygons_whole_and_lay_bent_ones_flat():
    quad = np.array([[(0, 0, 0.1), (10, 0, 0.2), (10, 10, 0.3), (0, 10, 0.2)],
                     [(0, 0, 0.0), (10, 0, 0.2), (10, 10, 0.0), (0, 10, 0.2)],
                     [(0, 0, 0.0), (10, 0, 3.0), (10, 10, 0.0), (0, 10, 3.0)]])
    verts, counts, owner, bent = g.units(quad, quad.copy(), np.array([4, 4, 4]), 0.05)
    assert counts.tolist() == [4, 4, 3, 3] and owner.tolist() == [0, 1, 2, 2]
    assert bent[0] == 0 and 0 < bent[1] < bent[2]
    sp = g.screen_polygons(verts, counts, owner, 20, 20)
    # each unit lies in its plane
    for p in range(len(sp)):
        v = sp.polygon(p)
        assert np.allclose(v @ sp.planes[p, :3] + sp.planes[p, 3], 0, atol=1e-9)


def test_simplify_drops_middle_points_alike_on_both_sides():
    # two polygons sharing the side (0,0)-(0,10) with a middle point 0.1 off the chord
    a = np.array([(0, 0, 0), (0, 5, 0), (0, 10, 0), (-10, 10, 0), (-10, 0, 0)], float)
    b = np.array([(0, 0, 0), (10, 0, 0), (10, 10, 0), (0, 10, 0), (0, 5, 0)], float)
    a[1, 0] = b[4, 0] = 0.1
    dev = np.stack([a, b])
    d2, p2, count = g.simplify(dev, dev.copy(), np.array([5, 5]), 0.25)
    assert count.tolist() == [4, 4]
    assert not any((p[:c, :2] == (0.1, 5)).all(axis=1).any() for p, c in zip(d2, count))
    d3, _, count3 = g.simplify(dev, dev.copy(), np.array([5, 5]), 0.05)
    assert count3.tolist() == [5, 5]


def test_hidden_points_against_brute_force():
    rng = np.random.default_rng(11)
    tris = []
    for _ in range(60):
        c = rng.uniform(0, 200, 2)
        pts = c + rng.uniform(-30, 30, (3, 2))
        z = rng.uniform(0, 1, 3)
        tris.append(np.c_[pts, z])
    tris = np.array(tris)
    sp = g.screen_polygons(tris.reshape(-1, 3), np.full(60, 3), np.arange(60), 200, 200)
    n = 3000
    x, y, z = rng.uniform(0, 200, n), rng.uniform(0, 200, n), rng.uniform(0, 1, n)
    got = g.hidden_points(x, y, z, sp, 1e-9)
    want = np.zeros(n, bool)
    for p in range(len(sp)):
        v = sp.polygon(p)
        path = Path(v[:, :2])
        inside = path.contains_points(np.c_[x, y])
        depth = sp.depth_at(p, x, y)
        want |= inside & (depth < z - 1e-9)
    # points within rounding of an edge may go either way
    assert (got != want).sum() <= 3
    assert want.sum() > 300


def test_polylines_join_parts_that_continue_one_another():
    parts = np.array([[0, 0, 1, 0], [1, 0, 2, 0], [3, 0, 4, 0], [4, 0, 5, 0], [5, 0, 6, 1]],
                     float)
    of = np.array([0, 1, 2, 3, 4])
    line_of = np.array([0, 0, 0, 1, 1])      # segments 3, 4 belong to another polyline
    verts, offsets, lines = g.polylines(parts, of, line_of, 10)
    pieces = np.split(verts, offsets[1:-1])
    assert [p.tolist() for p in pieces] == [[[0, 0], [1, 0], [2, 0]], [[3, 0], [4, 0]],
                                            [[4, 0], [5, 0], [6, 1]]]
    assert lines.tolist() == [0, 0, 1]


def test_original_edges_of_split_pieces():
    src = np.array([[(0, 0), (10, 0), (10, 10), (0, 10)]], float)
    # a piece cut off by the line x = 4: its edge along x = 4 is a cut
    piece = np.array([(0, 0), (4, 0), (4, 10), (0, 10)], float)
    on = g.original_edges(piece, np.array([0, 4]), np.array([0]), src, np.array([4]))
    assert on.tolist() == [True, False, True, True]


def test_the_doctest_example_splits():
    fig, ax = axes3d()
    X, Y = np.meshgrid([-1, 1], [-1, 1])
    ax.plot_surface(X, Y, 0.5 * X, color="tab:blue")
    ax.plot_surface(X, Y, -0.5 * X, color="tab:orange")
    occlusion = scanline.mpl.render_axes(ax)
    fig.canvas.draw()
    assert occlusion.last.pieces > occlusion.last.polygons == 2


# ---------------------------------------------------------------- artists


def test_patches_markers_and_removed_artists():
    """ax.bar's patches are polygons too; markevery picks the markers; an artist
    removed from the axes is not drawn."""
    fig, ax = axes3d()
    ax.bar(np.arange(4), [1, 2, 3, 4], zs=1, zdir="y", color="g")
    line, = ax.plot(np.arange(7), np.zeros(7), np.zeros(7), "o-", markevery=3)
    gone, = ax.plot([0, 1], [0, 1], [0, 1])
    occlusion = scanline.mpl.render_axes(ax)
    gone.remove()
    fig.canvas.draw()
    assert occlusion.last.polygons == 4
    assert occlusion.last.points == 3                  # points 0, 3 and 6
    assert occlusion.last.segments == 6


def test_orthographic_axes():
    fig, ax = axes3d()
    ax.set_proj_type("ortho")
    X, Y = np.meshgrid([-1, 1], [-1, 1])
    ax.plot_surface(X, Y, 0 * X, color="red", shade=False)
    ax.plot_surface(X, Y, np.array([[-1.0, -1.0], [1.0, 1.0]]), color="blue", shade=False)
    quad = lambda z: np.array([(-1, -1, z(-1)), (1, -1, z(-1)), (1, 1, z(1)), (-1, 1, z(1))],  # noqa: E731
                              float)
    polygons = [(0, quad(lambda y: 0.0)), (1, quad(lambda y: y))]
    for route in ("vector", "raster"):
        scanline.mpl.render_axes(ax, method=route)
        share, n = ref.agreement(ref.canvas(fig), [(255, 0, 0), (0, 0, 255)], ax, fig, polygons)
        assert n > 1000 and share > 0.995, route
