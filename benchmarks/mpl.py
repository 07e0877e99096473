"""scanline.mpl: a matplotlib 3-D axes drawn by matplotlib alone and with
``scanline.mpl.render_axes`` (both routes), in one run.

Target (issue: correct occlusion for matplotlib 3-D axes): drawing with scanline.mpl
is not slower than matplotlib's own drawing by more than 2x on a 100 x 100
``plot_surface`` (matplotlib time / scanline time >= 0.5).

Workloads (one figure 6.4 x 4.8 in at 100 dpi, the Agg canvas, ``fig.canvas.draw()``
timed; every call first turns the view by 0.25 degree, on both sides, so that each
draw projects and orders anew, as an interactive rotation does):

* ``surface 100x100 strides 1``: ``plot_surface`` of a 100 x 100 grid with
  ``rstride=cstride=1`` -- 9,801 quadrilaterals, colormapped.
* ``surface 100x100 default``: the same grid with plot_surface's default counts
  (50 x 50: 2,500 polygons of eight points each).
* ``surface + line + scatter``: the strided surface with a line through it (100
  points) and 500 markers above and below it: the hidden-line and marker tests too.

For each: matplotlib alone; ``render_axes(ax, "vector")`` (depth sort with
splitting, one path collection); ``render_axes(ax, "raster")`` (a z-buffer image, 2 x 2
samples a pixel).  ``first`` is the first draw (numba's compiled kernels loaded from
the cache, or compiled).

* ``ordering``: the vector route's choice of method, on the 100 x 100 surface's
  screen polygons: ``sl.visible.depth_sort`` (device space, once per view) against
  a ``sl.visible.BSPTree`` of the surface's triangles in world space (built once,
  ``order(eye)`` per view, but it splits the surface into many more pieces, each of
  which must then be projected and drawn).

Ratios are matplotlib time / scanline time (above 1: scanline is faster).

Run: ``python benchmarks/mpl.py [--quick]`` (``--quick``: a 50 x 50 grid, fewer
repeats).
"""

import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import scanline as sl  # noqa: E402
import scanline.mpl  # noqa: E402


def surface_axes(n, strides, extras=False):
    """A figure with a colormapped plot_surface of an n x n grid."""
    fig = plt.figure(figsize=(6.4, 4.8), dpi=100)
    ax = fig.add_subplot(projection="3d")
    x = np.linspace(-2, 2, n)
    X, Y = np.meshgrid(x, x)
    Z = np.sin(2 * X) * np.cos(2 * Y)
    kw = {"rstride": 1, "cstride": 1} if strides == 1 else {}
    ax.plot_surface(X, Y, Z, cmap="viridis", **kw)
    if extras:
        t = np.linspace(-2, 2, 100)
        ax.plot(t, 0.5 * t, 1.5 * np.sin(t), color="red", lw=2)
        rng = np.random.default_rng(7)
        p = rng.uniform([-2, -2, -1.5], [2, 2, 1.5], (500, 3))
        ax.scatter(*p.T, s=8, color="k")
    return fig, ax


def drawer(fig, ax):
    """A function drawing the figure, the view turned by 0.25 degree each call."""
    state = {"azim": -60.0}

    def draw():
        state["azim"] += 0.25
        ax.view_init(30, state["azim"])
        fig.canvas.draw()
        return fig.canvas.buffer_rgba()
    return draw


def figure_workload(report, name, n, strides, extras, repeats):
    """matplotlib alone against both routes on one figure, each route its own row
    pair (the matplotlib time is taken again beside each, so that a change of load
    during the run affects both sides alike)."""
    for route in ("vector", "raster"):
        work = f"{name} {route}"
        fig, ax = surface_axes(n, strides, extras)
        report.add(work, "matplotlib", "fig.canvas.draw() (mplot3d alone)", drawer(fig, ax),
                   repeats=repeats)
        plt.close(fig)
        fig, ax = surface_axes(n, strides, extras)
        occlusion = scanline.mpl.render_axes(ax, method=route)
        report.add(work, "scanline", f"render_axes(ax, {route!r}); fig.canvas.draw()",
                   drawer(fig, ax), repeats=repeats)
        last = occlusion.last
        print(f"    {last.polygons} polygons, {last.units} convex planar polygons"
              + (f", {last.pieces} pieces drawn" if last.pieces is not None else
                 f", image {last.image[0]} x {last.image[1]}")
              + (f", {last.segments} segments, {last.points} markers "
                 f"({last.points_hidden} hidden)" if last.segments or last.points else ""))
        report.target(work, "matplotlib", 0.5,
                      "not slower than matplotlib's own drawing by more than 2x")
        plt.close(fig)


def ordering_workload(report, n):
    """Depth sort against a BSP tree for the surface's polygons."""
    from scanline.mpl import _scene, _sources

    fig, ax = surface_axes(n, 1)
    occlusion = scanline.mpl.render_axes(ax)
    fig.canvas.draw()
    width, height = fig.canvas.get_width_height()
    scene = _scene.collect(ax, occlusion.sources, ax.M, width, height, occlusion.flatness)
    work = f"ordering {n}x{n} surface"
    report.add(work, "depth sort", "sl.visible.depth_sort(screen polygons)",
               lambda: sl.visible.depth_sort(scene.sp), repeats=5, n=len(scene.sp))
    pieces = sl.visible.depth_sort(scene.sp)
    coll = ax.collections[0]
    p = _sources.polygons(coll)
    quads = np.arange(len(p.xyz) * 4).reshape(-1, 4)
    tri = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    mesh = sl.mesh.Mesh(p.xyz.reshape(-1, 3), tri)
    t0 = time.perf_counter()
    tree = sl.visible.BSPTree(mesh)
    build = time.perf_counter() - t0
    eye = np.linalg.svd(ax.M[[0, 1, 3], :])[2][-1]       # where M sends nothing on screen
    report.add(work, "bsp order", "BSPTree(mesh).world_pieces(eye) (tree built once)",
               lambda: tree.world_pieces(eye), repeats=5, n=len(tri))
    print(f"    depth sort: {len(scene.sp)} polygons -> {len(pieces)} pieces; BSP tree of "
          f"{len(tri)} triangles: built in {build * 1e3:.0f} ms, "
          f"{len(tree.world_pieces(eye)[1])} pieces")
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="a 50 x 50 grid, fewer repeats")
    args = parser.parse_args()
    report = Report("mpl", quick=args.quick)
    n = 50 if args.quick else 100
    repeats = 3 if args.quick else 5
    figure_workload(report, f"surface {n}x{n} strides 1", n, 1, False, repeats)
    figure_workload(report, f"surface {n}x{n} default", n, None, False, repeats)
    figure_workload(report, "surface + line + scatter", n, None, True, repeats)
    ordering_workload(report, n)
    report.write()


if __name__ == "__main__":
    main()
