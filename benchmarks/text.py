"""A page of text: scanline vs Cairo (and skia-python) vs Pillow.

Workload (1024 x 1400 RGB, black text on white): 60 lines
of 80 random printable ASCII characters (about one in eight a space), DejaVu Sans at
14 px per em (scanline: ``height = 14 * 1493 / 2048``, the cap height), lines
16.3 px apart (DejaVu's ascent - descent at that size, scanline's newline step).

* ``text``: scanline without antialiasing, the page as one string with newlines
  (one ``sl.draw.text`` call), vs Cairo (toy text API, ``show_text`` per line,
  ``ANTIALIAS_NONE``), skia-python (aliased ``drawString`` per line) and Pillow
  (``ImageDraw.text`` per line, ``fontmode = "1"``);
* ``text-lines``: the same page drawn by scanline with one call per line (the
  per-call cost of the Python layer and numba dispatch, ~4 us, shows here);
* ``text-aa``: antialiased: scanline ``antialias=True`` (one call) vs Cairo's
  default antialiasing, skia-python's antialiased font and Pillow's default.

Cairo's toy API finds "DejaVu Sans" through fontconfig (the same DejaVuSans.ttf
scanline ships); skia-python and Pillow load the shipped file.  Every engine caches
rendered glyphs: the timings are warm (the best of several runs after a first one).
Each library's canvas is made once, outside the clock: the timings are the text
alone (making a white 1024 x 1400 canvas costs Cairo 0.1 ms, scanline's
FrameBuffer about 5 ms, which would hide the text).
Targets: Cairo time / scanline time >= 0.5 (within 2x of Cairo), faster than Pillow.

Run: ``python benchmarks/text.py [--quick]``.
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402
from scanline.text import catalog  # noqa: E402

WIDTH, HEIGHT = 1024, 1400
EM = 14.0
TTF = str(catalog.DATA / "DejaVuSans.ttf")
CAP = EM * 1493 / 2048
STEP = EM * (1901 + 483) / 2048
TOP = HEIGHT - 30          # first baseline, device y


def workload(lines, seed=7):
    rng = np.random.default_rng(seed)
    chars = np.array([chr(c) for c in range(33, 127)] + [" "] * 13)
    return ["".join(rng.choice(chars, 80)) for _ in range(lines)]


def scanline_page(lines, antialias):
    page = "\n".join(lines)

    fb = sl.FrameBuffer(WIDTH, HEIGHT, mode="RGB", background="white")

    def run():
        sl.draw.text(fb, 10, TOP, page, color="black", font="sans", height=CAP,
                     antialias=antialias)
    return run


def scanline_lines(lines):
    fb = sl.FrameBuffer(WIDTH, HEIGHT, mode="RGB", background="white")

    def run():
        for i, line in enumerate(lines):
            sl.draw.text(fb, 10, TOP - i * STEP, line, color="black", font="sans",
                         height=CAP)
    return run


def cairo_run(lines, antialias):
    import cairo

    surface = cairo.ImageSurface(cairo.FORMAT_RGB24, WIDTH, HEIGHT)
    ctx = cairo.Context(surface)
    ctx.set_source_rgb(1, 1, 1)
    ctx.paint()

    def run():
        ctx = cairo.Context(surface)
        ctx.set_source_rgb(0, 0, 0)
        ctx.select_font_face("DejaVu Sans")
        ctx.set_font_size(EM)
        options = cairo.FontOptions()
        options.set_antialias(cairo.ANTIALIAS_GRAY if antialias else cairo.ANTIALIAS_NONE)
        ctx.set_font_options(options)
        for i, line in enumerate(lines):
            ctx.move_to(10, HEIGHT - 1 - TOP + i * STEP)
            ctx.show_text(line)
        surface.flush()
    return run


def skia_run(lines, antialias):
    import skia

    font = skia.Font(skia.Typeface.MakeFromFile(TTF), EM)
    font.setEdging(skia.Font.Edging.kAntiAlias if antialias else skia.Font.Edging.kAlias)
    paint = skia.Paint(Color=skia.ColorBLACK, AntiAlias=antialias)

    surface = skia.Surface(WIDTH, HEIGHT)
    canvas = surface.getCanvas()
    canvas.clear(skia.ColorWHITE)

    def run():
        for i, line in enumerate(lines):
            canvas.drawString(line, 10, HEIGHT - 1 - TOP + i * STEP, font, paint)
        surface.flushAndSubmit()
    return run


def pillow_run(lines, antialias):
    from PIL import Image, ImageDraw, ImageFont

    font = ImageFont.truetype(TTF, int(EM))

    img = Image.new("RGB", (WIDTH, HEIGHT), "white")
    draw = ImageDraw.Draw(img)
    draw.fontmode = "L" if antialias else "1"

    def run():
        for i, line in enumerate(lines):
            draw.text((10, HEIGHT - 1 - TOP + i * STEP), line, fill="black", font=font,
                      anchor="ls")
    return run


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats")
    args = parser.parse_args(argv)
    lines = workload(60)
    n = sum(len(line) for line in lines)
    repeats = 3 if args.quick else 10
    report = Report("text", quick=args.quick)
    peers = []
    for module in ("cairo", "skia"):
        try:
            __import__(module)
            peers.append(module)
        except ImportError:
            pass
    runs = {"cairo": cairo_run, "skia": skia_run}
    for name, aa in (("text", False), ("text-aa", True)):
        report.add(name, "scanline", f"sl.draw.text(page with newlines, antialias={aa})",
                   scanline_page(lines, aa), repeats=repeats, n=n)
        for peer in peers:
            report.add(name, peer, "loop over lines" + ("" if aa else ", aliased"),
                       runs[peer](lines, aa), repeats=repeats, n=n)
        report.add(name, "pillow", f"loop: ImageDraw.text, fontmode={'L' if aa else '1'}",
                   pillow_run(lines, aa), repeats=repeats, n=n)
        if peers:
            report.target(name, peers[0], 0.5, f"within 2x of {peers[0]}")
        report.target(name, "pillow", 1.0, "faster than Pillow")
    report.add("text-lines", "scanline", "loop: sl.draw.text per line", scanline_lines(lines),
               repeats=repeats, n=n)
    for peer in peers[:1]:
        report.add("text-lines", peer, "loop over lines, aliased", runs[peer](lines, False),
                   repeats=repeats, n=n)
        report.target("text-lines", peer, 0.5, f"within 2x of {peer}")
    report.write()


if __name__ == "__main__":
    main()
