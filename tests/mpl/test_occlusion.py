"""scanline.mpl against the matplotlib bug reports' own examples: each scene is drawn
to an Agg canvas by matplotlib alone and through scanline.mpl (both routes), and the
pixels are compared with an independent reference (tests/mpl/reference.py: each
pixel's ray cast through the axes' own projection against the polygons given
analytically).  matplotlib alone is shown wrong, scanline right."""

import io
import re
import warnings

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

import scanline  # noqa: E402
import scanline.mpl  # noqa: E402

from . import reference as ref  # noqa: E402

ROUTES = ["vector", "raster"]
RED, BLUE, WHITE = (255, 0, 0), (0, 0, 255), (255, 255, 255)


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def figure(size=3.0):
    fig = plt.figure(figsize=(size, size), dpi=100)
    return fig, fig.add_subplot(projection="3d")


# ---------------------------------------------------------------- two planes


def planes_29060(ax, view):
    """matplotlib issue #29060: two plot_surface planes crossing (z = 0 and z = y),
    one quad each; in red and blue, unshaded."""
    X, Y = np.meshgrid([-1, 1], [-1, 1])
    ax.plot_surface(X, Y, np.zeros_like(X), color="red", shade=False)
    ax.plot_surface(X, Y, np.array([[-1.0, -1.0], [1.0, 1.0]]), color="blue", shade=False)
    ax.view_init(*view)
    quad = lambda z: np.array([(-1, -1, z(-1)), (1, -1, z(-1)), (1, 1, z(1)), (-1, 1, z(1))],  # noqa: E731
                              np.float64)
    return [(0, quad(lambda y: 0.0)), (1, quad(lambda y: y))]


VIEWS = {"default view": (30, -60), "from above": (80, -100)}


@pytest.mark.parametrize("view", list(VIEWS), ids=list(VIEWS))
def test_intersecting_planes_matplotlib_alone_is_wrong(view):
    fig, ax = figure()
    polygons = planes_29060(ax, VIEWS[view])
    image = ref.canvas(fig)
    share, n = ref.agreement(image, [RED, BLUE], ax, fig, polygons)
    assert n > 1000
    assert share < 0.85          # one plane painted over the other everywhere


@pytest.mark.parametrize("route", ROUTES)
@pytest.mark.parametrize("view", list(VIEWS), ids=list(VIEWS))
def test_intersecting_planes_are_right(view, route):
    fig, ax = figure()
    polygons = planes_29060(ax, VIEWS[view])
    occlusion = scanline.mpl.render_axes(ax, method=route)
    image = ref.canvas(fig)
    share, n = ref.agreement(image, [RED, BLUE], ax, fig, polygons)
    assert n > 1000
    assert share > 0.995
    assert occlusion.last.method == route and occlusion.last.polygons == 2
    if route == "vector":
        assert occlusion.last.pieces > occlusion.last.polygons     # split where they cross


@pytest.mark.parametrize("route", ROUTES)
def test_redrawn_right_after_the_view_changes(route):
    fig, ax = figure()
    polygons = planes_29060(ax, (30, -60))
    scanline.mpl.render_axes(ax, method=route)
    ref.canvas(fig)
    for view in [(15, 40), (-25, 120), (60, -150)]:
        ax.view_init(*view)
        share, _ = ref.agreement(ref.canvas(fig), [RED, BLUE], ax, fig, polygons)
        assert share > 0.995, view


def test_a_surface_of_many_polygons_crossing_a_plane():
    """A finely sampled tilted surface through a horizontal one (each plot_surface
    from an 8 x 8 grid, unshaded, not antialiased): every crossing quad is split."""
    fig, ax = figure(3.5)
    X, Y = np.meshgrid(np.linspace(-1, 1, 8), np.linspace(-1, 1, 8))
    ax.plot_surface(X, Y, 0.3 * X + 0.2 * Y, color="red", shade=False, antialiased=False)
    ax.plot_surface(X, Y, -0.4 * X + 0.1, color="blue", shade=False, antialiased=False)
    ax.view_init(25, -70)
    quad = lambda f: np.array([(x, y, f(x, y)) for x, y in  # noqa: E731
                               [(-1, -1), (1, -1), (1, 1), (-1, 1)]], np.float64)
    polygons = [(0, quad(lambda x, y: 0.3 * x + 0.2 * y)), (1, quad(lambda x, y: -0.4 * x + 0.1))]
    alone, _ = ref.agreement(ref.canvas(fig), [RED, BLUE], ax, fig, polygons)
    occlusion = scanline.mpl.render_axes(ax)
    share, _ = ref.agreement(ref.canvas(fig), [RED, BLUE], ax, fig, polygons)
    assert alone < 0.9 and share > 0.995
    assert occlusion.last.pieces > occlusion.last.polygons


# ---------------------------------------------------------------- lines


def line_scene(ax):
    """matplotlib issue #12620 made a line *through* the plane: a white-faced plane
    with black edges (a Poly3DCollection) and a red segment from below it to above
    it, and red markers above and below."""
    corners = np.array([[0, 0, 0], [0, 5, 0], [5, 5, 0], [5, 0, 0]], np.float64)
    plane = Poly3DCollection([corners], alpha=1)
    plane.set_color("blue")
    plane.set_edgecolor("k")
    ax.add_collection3d(plane)
    ax.plot([2, 2], [2, 2], [-2, 4], c="red", lw=5, solid_capstyle="butt")
    ax.set_xlim(0, 5)
    ax.set_ylim(0, 5)
    ax.set_zlim(-2.5, 2.5)
    ax.view_init(30, -60)
    return [(0, corners)]


def line_samples(ax, fig, polygons, a, b, n=200):
    """Points along the world segment a-b, whether each is hidden (reference), and its
    pixel; points within 5 pixels of a change of state or of the line's ends left
    out."""
    t = np.linspace(0, 1, n)
    xyz = np.asarray(a) + t[:, None] * (np.asarray(b) - np.asarray(a))
    hidden, rows, cols = ref.point_hidden(ax, fig, polygons, xyz)
    pos = np.stack([rows, cols], axis=1)
    change = np.flatnonzero(hidden[1:] != hidden[:-1])
    far = np.ones(n, bool)
    for i in list(change) + [0, n - 1]:
        far &= np.hypot(*(pos - pos[i]).T) > 5
    return hidden[far], np.rint(rows[far]).astype(int), np.rint(cols[far]).astype(int)


def test_line_through_a_surface_matplotlib_alone_is_wrong():
    fig, ax = figure(3.5)
    polygons = line_scene(ax)
    image = ref.canvas(fig)
    hidden, r, c = line_samples(ax, fig, polygons, (2, 2, -2), (2, 2, 4))
    assert hidden.any() and (~hidden).any()
    shown = ref.labels(image, [RED, BLUE])[r, c] == 0
    assert (shown == ~hidden).mean() < 0.9     # drawn wholly behind the plane or in front


@pytest.mark.parametrize("route", ROUTES)
def test_line_through_a_surface_is_cut_where_hidden(route):
    fig, ax = figure(3.5)
    polygons = line_scene(ax)
    occlusion = scanline.mpl.render_axes(ax, method=route)
    image = ref.canvas(fig)
    hidden, r, c = line_samples(ax, fig, polygons, (2, 2, -2), (2, 2, 4))
    got = ref.labels(image, [RED, BLUE])[r, c]
    assert ((got == 0) == ~hidden).all()
    assert (got[hidden] == 1).all()            # the plane is seen where the line is hidden
    if route == "vector":
        assert occlusion.last.hidden_parts == 1


def test_wireframe_lines_through_a_surface():
    """Line3DCollection (plot_wireframe of a vertical sheet through the plane): the
    parts under the plane are left out."""
    fig, ax = figure(3.5)
    polygons = line_scene(ax)
    ax.lines[0].remove()
    Xw, Zw = np.meshgrid([1.0, 2.5, 4.0], np.linspace(-2, 2, 5))
    ax.plot_wireframe(Xw, np.full_like(Xw, 2.5), Zw, color="red", linewidth=4)
    occlusion = scanline.mpl.render_axes(ax)
    image = ref.canvas(fig)
    for x in (1.0, 2.5, 4.0):
        hidden, r, c = line_samples(ax, fig, polygons, (x, 2.5, -2), (x, 2.5, 2))
        got = ref.labels(image, [RED, BLUE])[r, c]
        assert hidden.any()
        assert ((got == 0) == ~hidden).all(), x
    assert occlusion.last.hidden_parts > 0


@pytest.mark.parametrize("route", ROUTES)
def test_markers_behind_a_surface_are_left_out(route):
    fig, ax = figure(3.5)
    polygons = line_scene(ax)
    ax.lines[0].remove()
    rng = np.random.default_rng(3)
    pts = np.c_[rng.uniform(0.5, 4.5, (40, 2)), rng.choice([-1.5, 1.5], 40)]
    ax.scatter(*pts.T, color="red", s=30, depthshade=False)
    occlusion = scanline.mpl.render_axes(ax, method=route)
    image = ref.canvas(fig)
    hidden, rows, cols = ref.point_hidden(ax, fig, polygons, pts)
    got = ref.labels(image, [RED, BLUE])[np.rint(rows).astype(int), np.rint(cols).astype(int)]
    assert 5 < hidden.sum() < 35
    assert (got[hidden] == 1).all() and (got[~hidden] == 0).all()
    assert occlusion.last.points == 40 and occlusion.last.points_hidden == hidden.sum()


def test_markers_of_report_12620_are_drawn_over_the_plane():
    """Issue #12620 as reported: the markers above the plane and the segment standing
    on it are seen (matplotlib paints the plane over them)."""
    fig, ax = figure(3.5)
    corners = [[0, 0, 0], [0, 5, 0], [5, 5, 0], [5, 0, 0]]
    tri = Poly3DCollection([corners], alpha=1)
    tri.set_color("w")
    tri.set_edgecolor("k")
    ax.add_collection3d(tri)
    ax.plot([2, 2], [2, 2], [0, 4], c="r")
    ax.scatter([1, 3], [1, 3], [1, 3], c="r")
    ax.set_xlim([0, 5.0])
    ax.set_ylim([0, 5.0])
    ax.set_zlim([0, 2.5])
    occlusion = scanline.mpl.render_axes(ax)
    ref.canvas(fig)
    assert occlusion.last.points == 2 and occlusion.last.points_hidden == 0
    assert occlusion.last.hidden_parts == 0


# ---------------------------------------------------------------- bars


def bars_13728(ax):
    """matplotlib issue #13728: an 8 x 8 grid of touching bars of height x + y, one
    color per face (unshaded), so that each pixel says which face of which bar it
    shows."""
    _x = np.arange(8)
    xx, yy = np.meshgrid(_x, _x)
    x, y = xx.ravel(), yy.ravel()
    top = x + y
    i = np.arange(6 * 64)
    palette = np.stack([16 + 32 * (i % 8), 16 + 32 * (i // 8 % 8), 16 + 40 * (i // 64)], axis=1)
    ax.bar3d(x, y, np.zeros_like(top), 1, 1, top, color=palette / 255, shade=False)
    polygons = [(6 * b + k, f) for b in range(64) if top[b] > 0
                for k, f in enumerate(ref.box(x[b], y[b], 0, 1, 1, top[b]))]
    return polygons, palette


def test_interleaved_bars_matplotlib_alone_is_wrong():
    fig, ax = figure(4)
    polygons, palette = bars_13728(ax)
    share, n = ref.agreement(ref.canvas(fig), palette, ax, fig, polygons, step=1)
    assert n > 10000
    assert share < 0.995        # side faces painted over the tops of the steps


@pytest.mark.parametrize("route", ROUTES)
def test_interleaved_bars_are_right(route):
    fig, ax = figure(4)
    polygons, palette = bars_13728(ax)
    scanline.mpl.render_axes(ax, method=route)
    share, n = ref.agreement(ref.canvas(fig), palette, ax, fig, polygons, step=1)
    assert n > 10000
    assert share > 0.999


# ---------------------------------------------------------------- output


def svg_of(fig):
    buf = io.StringIO()
    fig.savefig(buf, format="svg")
    return buf.getvalue()


def test_vector_route_writes_only_paths_to_svg():
    fig, ax = figure()
    planes_29060(ax, (30, -60))
    for i, c in enumerate(ax.collections):
        c.set_gid(f"source-{i}")
    occlusion = scanline.mpl.render_axes(ax)
    occlusion.set_gid("occlusion")
    svg = svg_of(fig)
    assert "<image" not in svg
    assert 'id="source-0"' not in svg and 'id="source-1"' not in svg   # nothing 3-D drawn
    group = re.search(r'<g id="occlusion-pieces">(.*?)\n  </g>', svg, re.S)
    assert group is not None
    drawn = len(re.findall(r"<(?:path|use)\b", group.group(1)))
    assert drawn == occlusion.last.pieces > occlusion.last.polygons == 2
    # matplotlib alone writes its two collections (the ids are there)
    plt.close(fig)
    fig, ax = figure()
    planes_29060(ax, (30, -60))
    ax.collections[0].set_gid("source-0")
    assert 'id="source-0"' in svg_of(fig)


def test_raster_route_places_one_image_in_the_axes():
    fig, ax = figure()
    planes_29060(ax, (30, -60))
    occlusion = scanline.mpl.render_axes(ax, method="raster")
    svg = svg_of(fig)
    assert svg.count("<image") == 1
    fig.canvas.draw()
    w, h = occlusion.last.image
    assert abs(w - ax.bbox.width) <= 2 and abs(h - ax.bbox.height) <= 2


@pytest.mark.parametrize("route", ROUTES)
def test_axes_panes_ticks_and_labels_are_untouched(route):
    """A single plane (which matplotlib draws right): the figure with scanline is
    matplotlib's, pixel for pixel but for the antialiased outline of the plane."""
    def draw(use):
        fig, ax = figure()
        X, Y = np.meshgrid(np.linspace(-1, 1, 5), np.linspace(-1, 1, 5))
        ax.plot_surface(X, Y, 0.3 * X, cmap="viridis", antialiased=False)
        ax.set_xlabel("x label")
        ax.set_title("title")
        if use:
            scanline.mpl.render_axes(ax, method=route)
        return ref.canvas(fig)
    alone, ours = draw(False), draw(True)
    differ = (np.abs(alone.astype(int) - ours.astype(int)).max(axis=2) > 8)
    assert differ.mean() < 0.01
    # the colors of the colormap are matplotlib's: the surface's pixels agree
    surface = (np.abs(alone.astype(int) - 255).max(axis=2) > 60) & ~differ
    assert surface.sum() > 1000


def test_remove_gives_the_artists_back_to_matplotlib():
    fig, ax = figure()
    planes_29060(ax, (30, -60))
    alone = ref.canvas(fig)
    occlusion = scanline.mpl.render_axes(ax)
    assert not np.array_equal(ref.canvas(fig), alone)
    occlusion.remove()
    assert np.array_equal(ref.canvas(fig), alone)
    assert all(c.get_visible() for c in ax.collections)


def test_render_again_adopts_new_artists_once():
    fig, ax = figure()
    planes_29060(ax, (30, -60))
    scanline.mpl.render_axes(ax)
    ax.plot([0, 0], [0, 0], [-1, 1], color="k")
    occlusion = scanline.mpl.render_axes(ax, method="raster")
    ref.canvas(fig)
    assert sum(isinstance(a, scanline.mpl.Occlusion) for a in ax.get_children()) == 1
    assert occlusion.last.segments == 1 and occlusion.last.method == "raster"


def test_legend_still_shows_adopted_artists():
    fig, ax = figure()
    X, Y = np.meshgrid([-1, 1], [-1, 1])
    ax.plot_surface(X, Y, 0 * X, color="blue", label="plane")
    ax.plot([0, 0], [0, 0], [-1, 1], color="red", label="line")
    scanline.mpl.render_axes(ax)
    legend = ax.legend()
    ref.canvas(fig)
    assert [t.get_text() for t in legend.get_texts()] == ["plane", "line"]
    assert all(h.get_visible() for h in legend.legend_handles)


def test_translucent_surface_veils_the_line_behind_it():
    """A half-transparent plane over the lower half of the line: the line is drawn
    beneath the plane there (its color mixed with the plane's), above it elsewhere."""
    fig, ax = figure(3.5)
    corners = np.array([[0, 0, 0], [0, 5, 0], [5, 5, 0], [5, 0, 0]], np.float64)
    ax.add_collection3d(Poly3DCollection([corners], facecolor=(0, 0, 1, 0.5)))
    ax.plot([2, 2], [2, 2], [-2, 4], c="red", lw=5)
    ax.set_xlim(0, 5)
    ax.set_ylim(0, 5)
    ax.set_zlim(-2.5, 2.5)
    scanline.mpl.render_axes(ax)
    image = ref.canvas(fig)
    hidden, r, c = line_samples(ax, fig, [(0, corners)], (2, 2, -2), (2, 2, 4))
    veiled = (128, 0, 127)                      # red under half-transparent blue
    got = ref.labels(image, [RED, veiled])[r, c]
    assert hidden.any()
    assert (got[hidden] == 1).all() and (got[~hidden] == 0).all()


def test_fallback_to_raster_when_the_depth_sort_gives_up():
    fig, ax = figure()
    polygons = planes_29060(ax, (30, -60))
    occlusion = scanline.mpl.render_axes(ax, max_pieces=1)
    with pytest.warns(scanline.ScanlineWarning, match="raster"):
        image = ref.canvas(fig)
    assert occlusion.last.fell_back and occlusion.last.method == "raster"
    assert ref.agreement(image, [RED, BLUE], ax, fig, polygons)[0] > 0.995


def test_no_warnings_in_an_ordinary_draw():
    fig, ax = figure()
    planes_29060(ax, (30, -60))
    ax.scatter([0], [0], [0])
    ax.plot([0, 1], [0, 1], [0, 1])
    for route in ROUTES:
        scanline.mpl.render_axes(ax, method=route)
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            ref.canvas(fig)


# ---------------------------------------------------------------- random scenes


def random_triangles(ax, seed, n=25):
    """``n`` random triangles, intersecting and overlapping cyclically, one color each,
    not antialiased, seen from a random view in which none is a sliver thinner than 4
    pixels (Agg fills slivers where no pixel center lies; the reference samples
    pixel centers)."""
    rng = np.random.default_rng(seed)
    tris = rng.uniform(-1, 1, (n, 1, 3)) + rng.uniform(-0.7, 0.7, (n, 3, 3))
    i = np.arange(n)
    palette = np.stack([16 + 48 * (i % 5), 16 + 48 * (i // 5 % 5), np.full(n, 128)], axis=1)
    ax.add_collection3d(Poly3DCollection(tris, facecolors=palette / 255, antialiased=False))
    for lim in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
        lim(-2, 2)
    ax.get_figure().canvas.draw()             # (the axes' 2-D transform is set)
    for _ in range(100):
        ax.view_init(rng.uniform(-60, 60), rng.uniform(-180, 180))
        p = ref._project(ax.get_proj(), tris.reshape(-1, 3))[:, :2]
        xy = ax.transData.transform(p).reshape(n, 3, 2)
        e = np.roll(xy, -1, axis=1) - xy
        area = np.abs(e[:, 0, 0] * e[:, 1, 1] - e[:, 0, 1] * e[:, 1, 0])
        if (area / np.hypot(e[..., 0], e[..., 1]).max(axis=1)).min() >= 4:
            break
    return [(k, tris[k]) for k in range(n)], palette


def test_random_intersecting_triangles():
    """Both routes against the reference on random scenes.  (The few pixels the
    vector route differs by are thin slivers of split pieces, which Agg fills where no
    pixel center lies.)"""
    wrong = {None: 0, "vector": 0, "raster": 0}
    for seed in range(4):
        for route in wrong:
            fig, ax = figure(3.5)
            polygons, palette = random_triangles(ax, seed)
            if route:
                scanline.mpl.render_axes(ax, method=route)
            share, n = ref.agreement(ref.canvas(fig), palette, ax, fig, polygons, step=1)
            wrong[route] += (1 - share) * n
            if route:
                assert share > 0.995, (seed, route)
            plt.close(fig)
    assert wrong[None] > 8 * max(wrong["vector"], wrong["raster"], 1)
