"""
Antialiasing and alpha blending
===============================

Figures of ``scanline demo`` for antialiasing and alpha blending
(:mod:`scanline.draw.antialias`, :mod:`scanline.draw._blend`)."""

import math

import numpy as np
from PIL import Image

import scanline as sl

from scanline.gallery._plot import enlarge, side_by_side
from scanline.gallery.primitives import PAPER, PIXEL, Figure

SIZE = (44, 30)


def _scene(fb, antialias):
    """A line, a circle and a triangle, aliased or antialiased."""
    if antialias:
        sl.draw.antialias.lines(fb, [(1.2, 2.4, 42.6, 11.8)], PIXEL)
        sl.draw.antialias.circles(fb, [(12.3, 18.6, 8.4)], PIXEL)
        sl.draw.polygon(fb, [(24.5, 15.2), (42.3, 19.6), (30.4, 28.7)], PIXEL, antialias=True)
    else:
        sl.draw.line(fb, 1.2, 2.4, 42.6, 11.8, PIXEL)
        sl.draw.circle(fb, 12.3, 18.6, 8.4, PIXEL)
        sl.draw.polygon(fb, [(24.5, 15.2), (42.3, 19.6), (30.4, 28.7)], PIXEL)


def figure_antialiasing():
    """Aliased and antialiased primitives side by side, enlarged."""
    panels = []
    for antialias in (False, True):
        fb = sl.FrameBuffer(*SIZE, background=PAPER)
        _scene(fb, antialias)
        panels.append(enlarge(fb.to_pil(), 8))
    gray = sl.FrameBuffer(*SIZE, mode="L")
    sl.draw.antialias.lines(gray, [(1.2, 2.4, 42.6, 11.8)], "white")
    total = gray.to_array().sum() / 255
    length = math.hypot(42.6 - 1.2, 11.8 - 2.4)
    return Figure(
        "antialiasing", "Antialiasing: Wu lines and conics, area coverage",
        "Left: the line (Bresenham), circle (midpoint) and triangle (scan-line fill) "
        "with pixels either on or off: the staircase 'jaggies'. Right: the same ideal "
        "shapes antialiased. Lines and circles use Wu's algorithm: each column splits "
        "the curve's intensity between the pixels straddling it (here scaled so that a "
        "1-pixel-wide line of any slope is as bright as a horizontal one); the "
        "triangle's pixels are blended with the fraction of them it covers, measured "
        f"on 16 sub-scan-lines. The line's total intensity is {total:.2f} for a length "
        f"of {length:.2f}.",
        "Notes, syllabus (Antialiasing) and glossary (Anti-aliasing, Filtering)",
        side_by_side(panels, ["aliased", "antialiased"]), None)


def _disks(fb, antialias):
    """Three translucent disks (alpha 128) overlapping."""
    disks = [(15, 19, 10), (25, 19, 10), (20, 10.5, 10)]
    colors = [(255, 0, 0, 128), (0, 200, 0, 128), (0, 0, 255, 128)]
    if antialias:
        sl.draw.fill_circles(fb, disks, colors, antialias=True)
    else:
        sl.draw.fill_circles(fb, disks, colors)


def figure_blending():
    """Translucent colors composited "over" the frame buffer in several modes."""
    panels, titles = [], []
    fb = sl.FrameBuffer(40, 30, background=PAPER)
    sl.draw.polygon(fb, [(0, 0), (40, 0), (40, 8), (0, 8)], "black")
    _disks(fb, False)
    panels.append(fb.to_pil())
    titles.append("RGB")
    fb = sl.FrameBuffer(40, 30, background=PAPER)
    sl.draw.polygon(fb, [(0, 0), (40, 0), (40, 8), (0, 8)], "black")
    _disks(fb, True)
    panels.append(fb.to_pil())
    titles.append("RGB, antialiased")
    table = [(255, 255, 255), (0, 0, 0)] + [tuple(int(c) for c in rgb) for rgb in
                                            np.array(np.meshgrid([0, 128, 255], [0, 128, 255],
                                                                 [0, 128, 255])).reshape(3, -1).T]
    fb = sl.FrameBuffer(40, 30, mode="P", color_table=table[:29], background=PAPER)
    sl.draw.polygon(fb, [(0, 0), (40, 0), (40, 8), (0, 8)], "black")
    _disks(fb, True)
    panels.append(fb.to_pil())
    titles.append("P, 27-color table")
    fb = sl.FrameBuffer(40, 30, mode="L", background=PAPER)
    sl.draw.polygon(fb, [(0, 0), (40, 0), (40, 8), (0, 8)], "black")
    _disks(fb, True)
    panels.append(fb.to_pil())
    titles.append("L")
    fb = sl.FrameBuffer(40, 30, mode="RGBA", background=(0, 0, 0, 0))
    _disks(fb, True)
    over = fb.get_pixel(20, 19)
    checker = np.where(np.indices((30, 40)).sum(axis=0) % 2 == 0, 200, 255).astype(np.uint8)
    back = Image.fromarray(np.repeat(checker[..., None], 3, axis=2)).convert("RGBA")
    panels.append(Image.alpha_composite(back, fb.to_pil()))
    titles.append("RGBA on transparent")
    return Figure(
        "blending", "Alpha blending: translucent colors composited 'over'",
        "Red, green and blue disks with alpha 128 (50 %), drawn in that order over white "
        "paper and a black band: each color is blended with what is already there, "
        "c = c_dst + (c_src - c_dst) a (Porter-Duff 'over'). With antialias=True the "
        "edge pixels' coverage multiplies the alpha. In mode P the blended color is "
        "replaced by the nearest table entry; in RGBA the destination alpha is "
        f"composited too (where all three overlap on a transparent frame buffer the "
        f"pixel is {over}).",
        "Notes, glossary (Blending); Porter & Duff 1984",
        side_by_side([enlarge(p, 6) for p in panels], titles, gap=16), None)


FIGURES = (figure_antialiasing, figure_blending)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
