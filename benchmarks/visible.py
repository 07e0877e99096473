"""Visible-surface methods: depth sort against matplotlib's one-key sort, and every
method of ``sl.visible`` on one common scene, in one run.

Workloads (fixed seed):

* ``depth sort``: 10,000 random small triangles (a few pixels to tens of pixels, at
  random depths, some overlapping) on an 800 x 600 RGB canvas.  scanline:
  ``sl.visible.painted_depth_sort``: ``sl.visible.depth_sort`` on the screen-space
  polygons with the pieces' numbers painted in order as the sort hands them over (on
  the second core, while it orders the next ones), then each pixel colored by
  ``sl.shading.paint`` (all timed); matplotlib: a ``Poly3DCollection`` of the same
  triangles in a 3-D axes drawn to an Agg canvas (``fig.canvas.draw()``), which sorts
  by one key per polygon -- it is doing less (no tests, no splitting).
* ``methods``: a sphere, a torus and a cube (about 2,700 faces) through a perspective
  camera at 640 x 480, by every polygon method of ``sl.visible.METHODS`` through
  ``sl.render(..., shading="none")``, each face one color (projection and clipping
  included), so that users see each method's cost.

Ratios are peer time / scanline time (above 1: scanline is faster).

Run: ``python benchmarks/visible.py [--quick] [--only depth|methods]`` (``--quick``: 10x
fewer triangles; ``--only``: one workload).
"""

import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402

W, H = 800, 600
#: One color per mesh (the palette the visible-surface figures use).
PALETTE = ["#4e79a7", "#f28e2b", "#e15759"]


def triangles(rng, n):
    """n random triangles in device space: (n, 3, 3)."""
    c = rng.uniform([0, 0], [W, H], (n, 2))
    r = rng.uniform(3, 25, (n, 1, 1))
    ang = rng.uniform(0, 2 * np.pi, (n, 1)) + np.array([0, 2.1, 4.2])
    xy = c[:, None, :] + r * np.stack([np.cos(ang), np.sin(ang)], axis=-1)
    z = rng.uniform(0.05, 0.95, (n, 1)) + rng.uniform(-0.02, 0.02, (n, 3))
    return np.concatenate([xy, z[:, :, None]], axis=-1)


def matplotlib_draw(tris):
    """Draw the triangles with a Poly3DCollection onto an Agg canvas."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    fig = plt.figure(figsize=(W / 100, H / 100), dpi=100)
    ax = fig.add_subplot(projection="3d")
    ax.set_xlim(0, W)
    ax.set_ylim(0, 1)
    ax.set_zlim(0, H)
    # x right, depth into the screen (y axis), device y up (z axis)
    coll = Poly3DCollection(tris[:, :, [0, 2, 1]], facecolors="tab:blue", edgecolors="none")
    ax.add_collection3d(coll)

    def draw():
        fig.canvas.draw()
        return fig.canvas.buffer_rgba()
    return draw


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="10x fewer triangles")
    parser.add_argument("--only", choices=("depth", "methods"),
                        help="run one workload only (default: both)")
    args = parser.parse_args()
    report = Report("visible" + (f"-{args.only}" if args.only else ""), quick=args.quick)
    rng = np.random.default_rng(2026)

    if args.only != "methods":
        depth_sort_workload(report, rng, args.quick)
    if args.only != "depth":
        methods_workload(report)
    report.write()


def depth_sort_workload(report, rng, quick):
    """Depth sort and painting of random triangles against ``Poly3DCollection``."""
    n = 10_000 // (10 if quick else 1)
    tris = triangles(rng, n)
    sp = sl.visible.ScreenPolygons.from_device(list(tris), W, H)
    values = np.tile(np.array([[78, 121, 167]], np.uint8), (n, 1))
    work = f"depth sort {n // 1000}k triangles" if n >= 1000 else f"depth sort {n}"

    def scanline_sort():
        fb = sl.FrameBuffer(W, H, background="white")
        pieces, numbers = sl.visible.painted_depth_sort(sp)
        sl.shading.paint(fb, numbers, values[pieces.face])
        return fb

    report.add(work, "matplotlib", "Poly3DCollection + fig.canvas.draw() (Agg)",
               matplotlib_draw(tris), repeats=2, n=n)
    report.add(work, "scanline", "painted_depth_sort(sp) + shading.paint(fb, ...)",
               scanline_sort, repeats=2, n=n)
    report.target(work, "matplotlib", 5.0, ">= 5x faster than matplotlib's one-key sort")


def methods_workload(report):
    """The polygon methods of ``sl.visible.METHODS`` on one scene, one color a face."""
    meshes = [sl.mesh.sphere(1.0, (0.6, 0.4, 0.3), resolution=48),
              sl.mesh.torus(1.3, 0.35, resolution=(64, 24)), sl.mesh.cube(1.6)]
    faces = sum(m.face_count for m in meshes)
    cam = sl.Camera(eye=(4, 3, 5), target=(0, 0, 0),
                    projection=sl.projection.perspective(fov=math.radians(45), near=1))
    for method in ("painter", "depth-sort", "bsp", "scan-line", "area-subdivision"):
        def run(method=method):
            fb = sl.FrameBuffer(640, 480)
            return sl.render(fb, meshes, cam, method=method, shading="none", colors=PALETTE)
        report.add(f"scene of {faces} faces", method,
                   f"sl.render(method={method!r}, shading='none')", run, repeats=1, n=faces)


if __name__ == "__main__":
    main()
