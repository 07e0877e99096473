"""Render docs/images/coordinates.png: scanline's device coordinates.

A 12 x 8 frame buffer with pixel (0, 0) and pixel (11, 7) set and a Bresenham line
between them, enlarged with a grid and labels, to show that x runs right, y runs up
and pixel centers sit at integer coordinates.
"""

import sys
from pathlib import Path

from PIL import ImageDraw

import scanline as sl

SCALE = 40


def main(out):
    fb = sl.FrameBuffer(12, 8, mode="RGB", background="white")
    sl.draw.line(fb, 0, 0, 11, 7, color="steelblue")
    fb.set_pixel(0, 0, "crimson")
    fb.set_pixel(11, 7, "seagreen")
    img = fb.to_pil().resize((12 * SCALE, 8 * SCALE), 0)
    pen = ImageDraw.Draw(img)
    for i in range(13):
        pen.line([(i * SCALE, 0), (i * SCALE, 8 * SCALE)], fill="lightgray")
    for j in range(9):
        pen.line([(0, j * SCALE), (12 * SCALE, j * SCALE)], fill="lightgray")
    # the ideal line through the pixel centers
    def center(x, y):
        return (x * SCALE + SCALE // 2, (7 - y) * SCALE + SCALE // 2)
    pen.line([center(0, 0), center(11, 7)], fill="black", width=2)
    pen.text((center(0, 0)[0] - 16, center(0, 0)[1] - 6), "(0,0)", fill="white")
    pen.text((center(11, 7)[0] - 18, center(11, 7)[1] - 6), "(11,7)", fill="white")
    pen.text((6, 4), "y up", fill="black")
    pen.text((12 * SCALE - 44, 8 * SCALE - 14), "x right", fill="black")
    img.save(out)


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("docs/images/coordinates.png"))
