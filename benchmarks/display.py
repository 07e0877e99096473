"""Benchmark: the display-file interpreter on a raster, a vector and an SVG device.

Workload: one display file with thin polylines and filled polygons in world
coordinates through a viewport that clips part of them.  Timed:

* scanline: ``sl.display.interpret`` on a RasterDevice (clip + scan-convert);
* the same primitives drawn directly with ``sl.draw`` in a Python loop (mapped to
  device coordinates beforehand, no clipping): the interpreter's overhead;
* Cairo (when installed), aliased, clipped to the viewport: a peer that draws the
  same device-space geometry immediately;
* the vector device (MOVE/LINE commands, fills as scan-line strokes) and the SVG
  device.

Usage: ``python benchmarks/display.py [--quick]``.  Ratios are peer time / scanline
time; timings on a shared machine are indicative.
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402

SIZE = 512


def workload(n_lines, n_polygons, seed=1):
    rng = np.random.default_rng(seed)
    lines = [rng.uniform(-10, 110, (5, 2)) for _ in range(n_lines)]
    polygons = [rng.uniform(-10, 110, (6, 2)) for _ in range(n_polygons)]
    df = sl.DisplayFile()
    df.set_viewing(window=(0, 0, 100, 100), viewport=(0.05, 0.05, 0.95, 0.95))
    df.create_segment("lines")
    for p in lines:
        df.polyline(p, color="black")
    df.close_segment()
    df.create_segment("areas")
    for p in polygons:
        df.polygon(p, color="red")
    df.close_segment()
    m = sl.viewing.ndc_to_device(SIZE, SIZE) @ df.normalization
    clip = sl.transform.apply(sl.viewing.ndc_to_device(SIZE, SIZE), [(0.05, 0.05), (0.95, 0.95)])
    return df, [sl.transform.apply(m, p) for p in lines], \
        [sl.transform.apply(m, p) for p in polygons], clip


def cairo_draw(lines, polygons, clip):
    import cairo

    surface = cairo.ImageSurface(cairo.FORMAT_RGB24, SIZE, SIZE)
    ctx = cairo.Context(surface)
    ctx.set_antialias(cairo.ANTIALIAS_NONE)
    ctx.set_source_rgb(1, 1, 1)
    ctx.paint()
    (x0, y0), (x1, y1) = clip
    ctx.rectangle(x0, SIZE - 1 - y1, x1 - x0 + 1, y1 - y0 + 1)
    ctx.clip()
    ctx.set_line_width(1)
    ctx.set_source_rgb(0, 0, 0)
    for p in lines:
        ctx.move_to(p[0, 0] + 0.5, SIZE - 0.5 - p[0, 1])
        for x, y in p[1:]:
            ctx.line_to(x + 0.5, SIZE - 0.5 - y)
        ctx.stroke()
    ctx.set_source_rgb(1, 0, 0)
    ctx.set_fill_rule(cairo.FILL_RULE_EVEN_ODD)
    for p in polygons:
        ctx.move_to(p[0, 0] + 0.5, SIZE - 0.5 - p[0, 1])
        for x, y in p[1:]:
            ctx.line_to(x + 0.5, SIZE - 0.5 - y)
        ctx.close_path()
        ctx.fill()
    surface.flush()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a smaller workload")
    args = parser.parse_args()
    n_lines, n_polygons = (400, 100) if args.quick else (4000, 1000)
    report = Report("display", quick=args.quick)
    df, lines, polygons, clip = workload(n_lines, n_polygons)
    name = f"{n_lines} polylines + {n_polygons} polygons"
    fb = sl.FrameBuffer(SIZE, SIZE, background="white")

    def direct():
        for p in lines:
            sl.draw.lines(fb, np.hstack([p[:-1], p[1:]]), color="black")
        for p in polygons:
            sl.draw.polygon(fb, p, color="red")

    report.add(name, "scanline", "sl.display.interpret(df, RasterDevice(fb))",
               lambda: sl.display.interpret(df, sl.display.RasterDevice(fb)), n=n_lines + n_polygons)
    report.add(name, "sl.draw loop", "sl.draw.lines / sl.draw.polygon per primitive, no clipping",
               direct)
    try:
        import cairo  # noqa: F401

        report.add(name, "cairo", "pycairo move_to/line_to, stroke/fill, clip rectangle",
                   lambda: cairo_draw(lines, polygons, clip))
        report.target(name, "cairo", 0.5, "interpreting the display file takes at most 2x "
                      "Cairo's immediate drawing")
    except ImportError:
        print("  (pycairo not installed: no Cairo comparison)")
    report.add(f"{name}, vector", "scanline", "interpret(df, VectorDevice)",
               lambda: sl.display.interpret(df, sl.display.VectorDevice(SIZE, SIZE)))
    report.add(f"{name}, SVG", "scanline", "interpret(df, SVGDevice).svg()",
               lambda: _svg(df))
    overhead = report.best(name, "scanline") / report.best(name, "sl.draw loop")
    print(f"  interpreter time / direct sl.draw loop time = {overhead:.2f}x")
    report.write()


def _svg(df):
    device = sl.display.SVGDevice(SIZE, SIZE)
    sl.display.interpret(df, device)
    return device.svg()


if __name__ == "__main__":
    main()
