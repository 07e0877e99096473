"""
Color: dithering, halftoning and color models
=============================================

Figures of ``scanline demo`` for color: dithering and halftoning, color models and
color tables (:mod:`scanline.color`)."""

import numpy as np
from PIL import ImageOps

import scanline as sl

from scanline.gallery._plot import enlarge, side_by_side, stacked
from scanline.gallery.primitives import Figure


def _photo_like(width=96, height=72):
    """A smooth gray image, values in [0, 1]: a horizontal ramp below, a lit sphere
    above (made with numpy: it is the input, not a scanline drawing)."""
    y, x = np.mgrid[0:height, 0:width]
    ramp = x / (width - 1)
    dx, dy = (x - 0.62 * width) / (0.3 * height), (y - 0.4 * height) / (0.3 * height)
    inside = dx * dx + dy * dy < 1
    nz = np.sqrt(np.clip(1 - dx * dx - dy * dy, 0, 1))
    shade = np.clip(0.15 + 0.85 * (0.5 * nz - 0.45 * dx - 0.55 * dy), 0, 1)
    image = np.where(inside, shade, 0.25 + 0.5 * ramp * (y / (height - 1)))
    image[-12:] = ramp[-12:]
    return image


def figure_dithering():
    """A gray image shown with 1 bit per pixel by each method, and with 2 bits."""
    image = _photo_like()
    panels, titles = [], []
    for method, title in (("none", "rounded"), ("bayer2", "Bayer 2x2"),
                          ("bayer4", "Bayer 4x4"), ("bayer8", "Bayer 8x8"),
                          ("floyd-steinberg", "Floyd-Steinberg")):
        panels.append(enlarge(sl.color.dither(image, method).to_pil(), 2))
        titles.append(title)
    two_bits = sl.color.dither(image, "floyd-steinberg", levels=4)
    original = sl.FrameBuffer.from_array(np.floor(image * 255 + 0.5).astype(np.uint8))
    rows = [side_by_side([enlarge(original.to_pil(), 2), panels[0], enlarge(two_bits.to_pil(), 2)],
                         ["original, 8 bits", titles[0], "F-S, 2 bits (4 levels)"]),
            side_by_side(panels[1:], titles[1:])]
    means = {m: sl.color.dither(image, m).to_array().mean()
             for m in ("bayer4", "floyd-steinberg")}
    return Figure(
        "dithering", "Dithering: 256 gray levels on a bitmap",
        "The same 96 x 72 gray image in a 1-bit frame buffer: each pixel rounded (the "
        "smooth shading becomes abrupt steps); ordered dithering with Bayer's 2x2, 4x4 "
        "and 8x8 threshold matrices (5, 17 and 65 patterns between black and white); "
        "Floyd-Steinberg error diffusion, which passes each pixel's rounding error on "
        "to its neighbors; and Floyd-Steinberg with 2 bits per pixel. Dithering keeps "
        f"the mean intensity: {image.mean():.3f} in the original, "
        f"{means['bayer4']:.3f} (Bayer 4x4) and {means['floyd-steinberg']:.3f} "
        "(Floyd-Steinberg) in the bitmaps.",
        "Notes, glossary (Dithering); chapter 2 syllabus (Color and gray scale levels)",
        stacked(rows), None)


def figure_color_models():
    """The HSV hexcone seen from above, its luminance, and the same colors in an
    8-bit indexed frame buffer."""
    size = 129
    c = size // 2
    y, x = np.mgrid[0:size, 0:size]
    dx, dy = (x - c) / c, (c - y) / c
    radius = np.hypot(dx, dy)
    hue = (np.arctan2(dy, dx) / (2 * np.pi)) % 1.0
    hsv = np.stack([hue, np.clip(radius, 0, 1), np.ones_like(hue)], axis=2)
    rgb = np.where((radius <= 1)[:, :, None], sl.color.hsv_to_rgb(hsv), 1.0)
    rgb8 = np.floor(rgb * 255 + 0.5).astype(np.uint8)
    wheel = sl.FrameBuffer.from_array(rgb8)
    gray = sl.FrameBuffer.from_array(sl.color.luminance(rgb8))
    web = sl.color.dither(wheel, palette=sl.color.web_safe_table())
    rounded = sl.color.indexed(wheel, sl.color.web_safe_table())
    panels = [wheel.to_pil(), gray.to_pil(), rounded.to_pil(), web.to_pil()]
    return Figure(
        "color-models", "The HSV color wheel, its luminance and 216 colors",
        "Hue around the circle (red at 0, green at 1/3 of a turn, blue at 2/3), "
        "saturation from the center out, value 1: sl.color.hsv_to_rgb on every pixel. "
        "Its luminance Y (the Y of YIQ, what a black-and-white television shows), and "
        "the wheel in an 8-bit indexed frame buffer with the 216 web-safe colors: "
        "each pixel the nearest table color, then Floyd-Steinberg dithered to the "
        "same table.",
        "Notes, chapter 1, Q.5 (color CRT); chapter 2 syllabus (Color-tables)",
        side_by_side([enlarge(p, 2) for p in panels],
                     ["HSV, V = 1", "luminance Y", "nearest of 216", "dithered, 216"]),
        None)


def figure_halftone():
    """The dot patterns of halftoning: every pattern of a 2x2 and a 4x4 cell."""
    rows = []
    for size, scale in ((2, 20), (4, 10)):
        n = size * size + 1
        patterns = sl.color.halftone(np.linspace(0.0, 1.0, n)[None], size).to_pil()
        cells = [ImageOps.expand(enlarge(patterns.crop((i * size, 0, (i + 1) * size, size)),
                                         scale).convert("RGB"), border=2, fill=(150, 150, 150))
                 for i in range(n)]
        rows.append(side_by_side(cells, [str(i) for i in range(n)], gap=10))
    photo = sl.color.halftone(_photo_like(48, 36), 4)
    rows.append(side_by_side([enlarge(photo.to_pil(), 2)], ["the gray image, 4x4 cells"]))
    return Figure(
        "halftone", "Halftone patterns",
        "A cell of n x n pixels shows n*n + 1 intensity levels by how many of its dots "
        "are set (white): the 5 patterns of a 2x2 cell and the 17 of a 4x4 cell, "
        "labeled with their number of dots. The dots are added in the "
        "order of Bayer's matrix, so each pattern contains the one before it and the "
        "dots stay spread out. sl.color.halftone trades resolution for levels: the "
        "48 x 36 image becomes 192 x 144 pixels.",
        "Notes, chapter 2 syllabus (Color and gray scale levels); glossary (Dithering)",
        stacked(rows), None)


FIGURES = (figure_dithering, figure_halftone, figure_color_models)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
