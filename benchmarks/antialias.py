"""Antialiased lines and polygons: scanline vs Cairo (and skia-python) vs Pillow.

Workloads (2048 x 2048 RGB, white on black, the same random primitives for every
library, real coordinates):

* ``aa-lines``: 100 000 lines of random direction and length up to 64 px, width 1,
  one color; ``aa-lines-colors``: the same with one random color per line.
  scanline: ``sl.draw.antialias.lines`` (Wu).  Cairo: a Python loop of
  ``move_to / line_to / stroke`` with the default antialias.  skia-python: a loop
  of ``canvas.drawLine`` with an antialiased paint.  Pillow has no antialiased
  lines: its loop of (aliased) ``ImageDraw.line`` is timed for reference.
* ``aa-polygons``: 10 000 random 6-vertex polygons (star-shaped, up to 40 px wide),
  nonzero rule.  scanline: ``sl.draw.antialias.fills``; Cairo: a loop of
  path + ``fill``; Pillow: a loop of (aliased) ``ImageDraw.polygon``.

The peers are given image coordinates (y down, pixel centers at +0.5), converted
outside the clock.  Targets: Cairo time / scanline time >= 0.5 (within 2x of Cairo)
on every workload, and faster than Pillow's (aliased) lines.  Pillow's aliased
polygons are timed for reference only: an aliased fill writes each pixel once with
no coverage to compute.

Run: ``python benchmarks/antialias.py [--quick]``.
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report, image_coords  # noqa: E402

import scanline as sl  # noqa: E402

SIZE = 2048


def line_workload(n, seed=7, max_len=64.0):
    rng = np.random.default_rng(seed)
    x0 = rng.uniform(0, SIZE - 1, n)
    y0 = rng.uniform(0, SIZE - 1, n)
    angle = rng.uniform(0, 2 * np.pi, n)
    length = rng.uniform(1, max_len, n)
    segs = np.stack([x0, y0, x0 + length * np.cos(angle), y0 + length * np.sin(angle)], axis=1)
    colors = rng.integers(0, 256, (n, 3))
    return segs, colors


def polygon_workload(n, seed=11, k=6, radius=20.0):
    rng = np.random.default_rng(seed)
    centers = rng.uniform(0, SIZE - 1, (n, 1, 2))
    angles = np.sort(rng.uniform(0, 2 * np.pi, (n, k)), axis=1)
    radii = rng.uniform(0.3, 1.0, (n, k)) * radius
    return centers + np.stack([radii * np.cos(angles), radii * np.sin(angles)], axis=2)




def scanline_lines(segs, colors):
    def run():
        fb = sl.FrameBuffer(SIZE, SIZE, mode="RGB")
        sl.draw.antialias.lines(fb, segs, colors)
    return run


def cairo_lines(segs, colors):
    import cairo

    pts = image_coords(segs.reshape(-1, 2, 2), SIZE).reshape(-1, 4).tolist()
    rgb = None if colors is None else (np.asarray(colors) / 255.0).tolist()

    def run():
        surface = cairo.ImageSurface(cairo.FORMAT_RGB24, SIZE, SIZE)
        ctx = cairo.Context(surface)
        ctx.set_line_width(1.0)
        ctx.set_source_rgb(1, 1, 1)
        if rgb is None:
            for x0, y0, x1, y1 in pts:
                ctx.move_to(x0, y0)
                ctx.line_to(x1, y1)
                ctx.stroke()
        else:
            for (x0, y0, x1, y1), (r, g, b) in zip(pts, rgb):
                ctx.set_source_rgb(r, g, b)
                ctx.move_to(x0, y0)
                ctx.line_to(x1, y1)
                ctx.stroke()
        surface.flush()
    return run


def skia_lines(segs, colors):
    import skia

    pts = image_coords(segs.reshape(-1, 2, 2), SIZE).reshape(-1, 4).tolist()
    paints = None
    if colors is not None:
        paints = [skia.Paint(AntiAlias=True, StrokeWidth=1.0, Color=skia.Color(*c))
                  for c in np.asarray(colors).tolist()]

    def run():
        surface = skia.Surface(SIZE, SIZE)
        canvas = surface.getCanvas()
        canvas.clear(skia.ColorBLACK)
        if paints is None:
            paint = skia.Paint(AntiAlias=True, StrokeWidth=1.0, Color=skia.ColorWHITE)
            for x0, y0, x1, y1 in pts:
                canvas.drawLine(x0, y0, x1, y1, paint)
        else:
            for (x0, y0, x1, y1), paint in zip(pts, paints):
                canvas.drawLine(x0, y0, x1, y1, paint)
        surface.flushAndSubmit()
    return run


def pillow_lines(segs, colors):
    from PIL import Image, ImageDraw

    pts = image_coords(segs.reshape(-1, 2, 2), SIZE).reshape(-1, 4) - 0.5
    pts = [tuple(p) for p in pts.tolist()]
    fills = [(255, 255, 255)] * len(pts) if colors is None else [tuple(c) for c in np.asarray(colors).tolist()]

    def run():
        img = Image.new("RGB", (SIZE, SIZE))
        draw = ImageDraw.Draw(img)
        for p, c in zip(pts, fills):
            draw.line(p, fill=c)
    return run


def scanline_polygons(polys):
    def run():
        fb = sl.FrameBuffer(SIZE, SIZE, mode="RGB")
        sl.draw.antialias.fills(fb, polys, "white")
    return run


def cairo_polygons(polys):
    import cairo

    rings = [r.tolist() for r in image_coords(polys, SIZE)]

    def run():
        surface = cairo.ImageSurface(cairo.FORMAT_RGB24, SIZE, SIZE)
        ctx = cairo.Context(surface)
        ctx.set_source_rgb(1, 1, 1)
        ctx.set_fill_rule(cairo.FILL_RULE_WINDING)
        for ring in rings:
            ctx.move_to(*ring[0])
            for x, y in ring[1:]:
                ctx.line_to(x, y)
            ctx.close_path()
            ctx.fill()
        surface.flush()
    return run


def pillow_polygons(polys):
    from PIL import Image, ImageDraw

    rings = [[tuple(p) for p in r] for r in (image_coords(polys, SIZE) - 0.5).tolist()]

    def run():
        img = Image.new("RGB", (SIZE, SIZE))
        draw = ImageDraw.Draw(img)
        for ring in rings:
            draw.polygon(ring, fill=(255, 255, 255))
    return run


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="10x fewer primitives")
    args = parser.parse_args(argv)
    n_lines = 10_000 if args.quick else 100_000
    n_polys = 1_000 if args.quick else 10_000
    report = Report("antialias", quick=args.quick)
    segs, colors = line_workload(n_lines)
    polys = polygon_workload(n_polys)
    try:
        import cairo  # noqa: F401
        have_cairo = True
    except ImportError:
        have_cairo = False
    try:
        import skia  # noqa: F401
        have_skia = True
    except ImportError:
        have_skia = False

    for workload, cols in (("aa-lines", None), ("aa-lines-colors", colors)):
        spec = "white" if cols is None else cols
        report.add(workload, "scanline", "sl.draw.antialias.lines", scanline_lines(segs, spec),
                   n=n_lines)
        if have_cairo:
            report.add(workload, "cairo", "loop of ctx.stroke()", cairo_lines(segs, cols), n=n_lines)
        if have_skia:
            report.add(workload, "skia", "loop of canvas.drawLine", skia_lines(segs, cols),
                       n=n_lines)
        report.add(workload, "pillow", "loop of ImageDraw.line (ALIASED)",
                   pillow_lines(segs, cols), n=n_lines)
    report.add("aa-polygons", "scanline", "sl.draw.antialias.fills", scanline_polygons(polys),
               n=n_polys)
    if have_cairo:
        report.add("aa-polygons", "cairo", "loop of ctx.fill()", cairo_polygons(polys), n=n_polys)
    report.add("aa-polygons", "pillow", "loop of ImageDraw.polygon (ALIASED)",
               pillow_polygons(polys), n=n_polys)

    for workload in ("aa-lines", "aa-lines-colors", "aa-polygons"):
        if have_cairo:
            report.target(workload, "cairo", 0.5, "within 2x of Cairo")
        elif have_skia and workload != "aa-polygons":
            report.target(workload, "skia", 0.5, "within 2x of skia")
    for workload in ("aa-lines", "aa-lines-colors"):
        report.target(workload, "pillow", 1.0, "faster than Pillow's aliased lines")
    ratio = report.best("aa-polygons", "pillow") / report.best("aa-polygons", "scanline")
    print(f"  (aa-polygons: Pillow's aliased polygons / scanline's antialiased = {ratio:.2f}x, "
          "for reference only)")
    report.write()


if __name__ == "__main__":
    main()
