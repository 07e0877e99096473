"""Curve flattening and stroking: scanline vs Cairo, and surface tessellation.

Workloads (fixed seed):

* ``flatten-cubics-10k``: 10 000 random cubic Bezier curves in a 1000 x 1000 box
  flattened within 0.25 device units.  scanline:
  ``sl.curves.flatten.flatten_all(curves, 0.25)`` (adaptive de Casteljau subdivision,
  one compiled call, guaranteed bound), also with ``method="wang"`` (equal steps by
  Wang's bound); Cairo: one path of 10 000 ``curve_to`` with ``set_tolerance(0.25)``
  and ``copy_path_flat()`` (Cairo's own adaptive subdivision).  Cairo's path is
  built inside its clock (``curve_to`` calls are how Cairo takes curves), scanline's
  ``Bezier`` objects outside (they are how scanline takes them).
* ``stroke-cubics-10k``: the same curves stroked width 1 into a 1000 x 1000 frame.
  scanline: ``sl.draw.curves(fb, curves)`` (flattening + Bresenham polylines);
  Cairo: ``stroke()`` with ``ANTIALIAS_NONE``, line width 1, tolerance 0.25 on an
  A8 surface.  The pixels differ (Cairo's coverage rule vs Bresenham) -- the
  timing compares the same job, not the same output.
* ``teapot-64x64``: the teapot tessellated 64 x 64 per patch (270 000 vertices and
  normals), scanline only (no peer in the environment tessellates Bezier patches).

Ratios are peer time / scanline time (above 1: scanline is faster).

Run: ``python benchmarks/flatten.py [--quick]``.
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402
from scanline.curves.flatten import flatten_all  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="1 000 curves instead of 10 000")
    args = parser.parse_args()
    n = 1_000 if args.quick else 10_000
    label = f"{n // 1000}k"
    rng = np.random.default_rng(1959)
    report = Report("flatten", quick=args.quick)
    controls = rng.uniform(0, 1000, (n, 4, 2))
    curves = [sl.curves.Bezier(c) for c in controls]

    w = f"flatten-cubics-{label}"
    report.add(w, "scanline", "flatten_all(curves, 0.25)", lambda: flatten_all(curves, 0.25), n=n)
    report.add(w, "scanline-wang", "flatten_all(curves, 0.25, 'wang')",
               lambda: flatten_all(curves, 0.25, "wang"), n=n)
    try:
        import cairo
    except ImportError:  # pragma: no cover - optional peer
        cairo = None
    if cairo is not None:
        def cairo_flatten():
            surface = cairo.ImageSurface(cairo.FORMAT_A8, 8, 8)
            ctx = cairo.Context(surface)
            ctx.set_tolerance(0.25)
            for c in controls:
                ctx.move_to(*c[0])
                ctx.curve_to(*c[1], *c[2], *c[3])
            return ctx.copy_path_flat()

        report.add(w, "cairo", "curve_to + copy_path_flat()", cairo_flatten, n=n)
        report.target(w, "cairo", 1.0, "at least as fast as Cairo's flattening")

    w = f"stroke-cubics-{label}"

    def ours():
        fb = sl.FrameBuffer(1000, 1000, mode="L")
        sl.draw.curves(fb, curves, color=255)

    report.add(w, "scanline", "sl.draw.curves(fb, curves)", ours, n=n)
    if cairo is not None:
        def theirs():
            surface = cairo.ImageSurface(cairo.FORMAT_A8, 1000, 1000)
            ctx = cairo.Context(surface)
            ctx.set_antialias(cairo.ANTIALIAS_NONE)
            ctx.set_tolerance(0.25)
            ctx.set_line_width(1.0)
            for c in controls:
                ctx.move_to(*c[0])
                ctx.curve_to(*c[1], *c[2], *c[3])
            ctx.stroke()

        report.add(w, "cairo", "curve_to + stroke() (no antialiasing)", theirs, n=n)
        report.target(w, "cairo", 1.0, "at least as fast as Cairo")

    report.add("teapot-64x64", "scanline", "teapot_mesh(64)",
               lambda: sl.curves.teapot_mesh(64), repeats=2)
    report.write()


if __name__ == "__main__":
    main()
