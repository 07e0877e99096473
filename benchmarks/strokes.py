"""Thick polylines: scanline vs Cairo (and skia-python) vs Pillow.

Workload (2048 x 2048 RGB, white strokes on black, the same random polylines for
every library): 10 000 open polylines of 8-16 vertices (random walks with steps of
8-40 px), widths 3-8 px (one sixth of the polylines each), round joins and round
caps.  scanline draws each width as one batch (``sl.draw.polylines(..., counts=)``:
a style holds for a whole batch); Cairo and skia-python loop over the polylines
(path + ``stroke``), Pillow over ``ImageDraw.line(..., width=w, joint="curve")``
(Pillow has no round caps).

* ``strokes``: scanline without antialiasing vs Cairo with ``ANTIALIAS_NONE`` and
  skia-python with an aliased paint, and Pillow;
* ``strokes-aa``: scanline ``antialias=True`` vs Cairo's default antialiasing and
  skia-python's antialiased paint.

The peers are given image coordinates (y down, pixel centers at +0.5), converted
outside the clock.  Targets: Cairo time / scanline time >= 0.5 (within 2x of
Cairo) and faster than Pillow.

Run: ``python benchmarks/strokes.py [--quick]``.
"""

import argparse
import importlib.util
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report, image_coords  # noqa: E402

import scanline as sl  # noqa: E402

SIZE = 2048
WIDTHS = (3, 4, 5, 6, 7, 8)


def workload(n, seed=5):
    """``{width: (vertices (V, 2), counts)}``: n random-walk polylines."""
    rng = np.random.default_rng(seed)
    counts = rng.integers(8, 17, n)
    widths = np.array(WIDTHS)[np.arange(n) % len(WIDTHS)]
    out = {}
    for w in WIDTHS:
        polys = []
        for k in counts[widths == w]:
            steps = rng.uniform(8, 40, k - 1)
            angles = rng.uniform(0, 2 * np.pi, k - 1)
            start = rng.uniform(40, SIZE - 40, 2)
            moves = np.stack([steps * np.cos(angles), steps * np.sin(angles)], axis=1)
            polys.append(np.vstack([start, start + np.cumsum(moves, axis=0)]))
        out[w] = (np.ascontiguousarray(np.concatenate(polys)), counts[widths == w])
    return out




def split(verts, counts):
    return np.split(verts, np.cumsum(counts)[:-1])


def scanline_run(data, antialias):
    def run():
        fb = sl.FrameBuffer(SIZE, SIZE, mode="RGB")
        for w, (verts, counts) in data.items():
            sl.draw.polylines(fb, verts, "white", counts=counts, width=w, cap="round",
                              join="round", antialias=antialias)
    return run


def cairo_run(data, antialias):
    import cairo

    jobs = [(w, [p.tolist() for p in split(image_coords(v, SIZE), c)]) for w, (v, c) in data.items()]

    def run():
        surface = cairo.ImageSurface(cairo.FORMAT_RGB24, SIZE, SIZE)
        ctx = cairo.Context(surface)
        if not antialias:
            ctx.set_antialias(cairo.ANTIALIAS_NONE)
        ctx.set_source_rgb(1, 1, 1)
        ctx.set_line_cap(cairo.LINE_CAP_ROUND)
        ctx.set_line_join(cairo.LINE_JOIN_ROUND)
        for w, polys in jobs:
            ctx.set_line_width(w)
            for pts in polys:
                ctx.move_to(*pts[0])
                for x, y in pts[1:]:
                    ctx.line_to(x, y)
                ctx.stroke()
        surface.flush()
    return run


def skia_run(data, antialias):
    import skia

    jobs = []
    for w, (v, c) in data.items():
        paint = skia.Paint(AntiAlias=antialias, StrokeWidth=float(w), Color=skia.ColorWHITE,
                           Style=skia.Paint.kStroke_Style, StrokeCap=skia.Paint.kRound_Cap,
                           StrokeJoin=skia.Paint.kRound_Join)
        paths = []
        for pts in split(image_coords(v, SIZE), c):
            path = skia.Path()
            path.addPoly([skia.Point(x, y) for x, y in pts.tolist()], False)
            paths.append(path)
        jobs.append((paint, paths))

    def run():
        surface = skia.Surface(SIZE, SIZE)
        canvas = surface.getCanvas()
        canvas.clear(skia.ColorBLACK)
        for paint, paths in jobs:
            for path in paths:
                canvas.drawPath(path, paint)
        surface.flushAndSubmit()
    return run


def pillow_run(data):
    from PIL import Image, ImageDraw

    jobs = [(w, [[tuple(q) for q in p.tolist()] for p in split(image_coords(v, SIZE) - 0.5, c)])
            for w, (v, c) in data.items()]

    def run():
        img = Image.new("RGB", (SIZE, SIZE))
        draw = ImageDraw.Draw(img)
        for w, polys in jobs:
            for pts in polys:
                draw.line(pts, fill=(255, 255, 255), width=w, joint="curve")
    return run


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="10x fewer polylines")
    args = parser.parse_args(argv)
    n = 1_000 if args.quick else 10_000
    data = workload(n)
    report = Report("strokes", quick=args.quick)
    have_cairo, have_skia = (importlib.util.find_spec(m) is not None for m in ("cairo", "skia"))
    peer = "cairo" if have_cairo else "skia" if have_skia else None
    for name, aa in (("strokes", False), ("strokes-aa", True)):
        report.add(name, "scanline", f"sl.draw.polylines(width=w, cap/join round, antialias={aa})",
                   scanline_run(data, aa), n=n)
        if have_cairo:
            report.add(name, "cairo", "loop: path + stroke" + ("" if aa else ", ANTIALIAS_NONE"),
                       cairo_run(data, aa), n=n)
        if have_skia:
            report.add(name, "skia", "loop: canvas.drawPath", skia_run(data, aa), n=n)
        if not aa:
            report.add(name, "pillow", "loop: ImageDraw.line(width=w, joint='curve')",
                       pillow_run(data), n=n)
        if peer:
            report.target(name, peer, 0.5, f"within 2x of {peer}")
        if not aa:
            report.target(name, "pillow", 1.0, "faster than Pillow")
    report.write()


if __name__ == "__main__":
    main()
