"""Dithering: scanline vs Pillow (Floyd-Steinberg) and vs numpy (ordered dithering).

Workloads (fixed seed; a 4096 x 4096 photo-like gray image: smooth waves plus noise):

* ``fs-bitmap``: Floyd-Steinberg to 1 bit per pixel.  scanline:
  ``sl.color.dither(gray)`` (a mode "1" FrameBuffer, packed 8 pixels per byte);
  Pillow: ``Image.convert("1")`` (also Floyd-Steinberg, in integers, packed).
* ``ordered-bitmap``: Bayer 8x8 ordered dithering to 1 bit.  scanline:
  ``sl.color.dither(gray, "bayer8")``; numpy: the vectorized threshold test
  ``gray > tiled_thresholds`` followed by ``np.packbits`` (the same packed bits).
* ``ordered-4-levels``: Bayer 8x8 to 4 gray levels (mode "L"); numpy: floor +
  threshold test + table lookup, vectorized.
* ``fs-web-palette``: Floyd-Steinberg of a 1024 x 1024 RGB image to the 216 web-safe
  colors (mode "P").  Pillow: ``Image.quantize(palette=..., dither=FLOYDSTEINBERG)``.

Inputs are made outside the clock (the Pillow image, the tiled thresholds).  Ratios
are peer time / scanline time (above 1: scanline is faster).

Run: ``python benchmarks/dither.py [--quick]``.
"""

import argparse
import os
import sys

import numpy as np
from PIL import Image

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402


def photo_like(size, seed=1976, channels=None):
    rng = np.random.default_rng(seed)
    y, x = np.mgrid[0:size, 0:size] / size
    shape = (size, size) if channels is None else (size, size, channels)
    base = 0.5 + 0.35 * np.sin(9 * x + 3 * y) * np.cos(7 * y - 2 * x)
    if channels is not None:
        base = np.stack([base, 1 - base * x, y * base], axis=2)
    noisy = base + rng.normal(0, 0.05, shape)
    return np.clip(noisy * 255 + 0.5, 0, 255).astype(np.uint8)


def numpy_ordered(gray, tiled, levels):
    """Ordered dithering, vectorized: ``tiled`` holds the thresholds over the image."""
    scaled = gray.astype(np.float32) * np.float32((levels - 1) / 255)
    base = np.floor(scaled)
    q = np.minimum(base + (scaled - base > tiled), levels - 1).astype(np.uint8)
    if levels == 2:
        return np.packbits(q, axis=1)
    return sl.color.gray_table(levels)[:, 0][q]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="1024 x 1024 instead of 4096 x 4096")
    args = parser.parse_args()
    size = 1024 if args.quick else 4096
    report = Report("dither", quick=args.quick)

    gray = photo_like(size)
    pil_gray = Image.fromarray(gray)
    name = "fs-bitmap"
    report.add(name, "scanline", "sl.color.dither(gray)", lambda: sl.color.dither(gray))
    report.add(name, "Pillow", 'Image.convert("1")', lambda: pil_gray.convert("1"))
    report.target(name, "Pillow", 1.0, "our aim, faster than Pillow; no issue target")

    thresholds = ((sl.color.bayer_matrix(8) + 0.5) / 64).astype(np.float32)
    tiled = np.tile(thresholds, (size // 8, size // 8))
    for name, levels in (("ordered-bitmap", 2), ("ordered-4-levels", 4)):
        mode = "1" if levels == 2 else "L"
        report.add(name, "scanline", f'sl.color.dither(gray, "bayer8", levels={levels})',
                   lambda: sl.color.dither(gray, "bayer8", levels=levels, mode=mode))
        report.add(name, "numpy", "vectorized threshold map",
                   lambda: numpy_ordered(gray, tiled, levels))
        report.target(name, "numpy", 1.0, "our aim, faster than numpy; no issue target")

    small = size // 4
    rgb = photo_like(small, channels=3)
    table = sl.color.web_safe_table()
    pil_rgb = Image.fromarray(rgb)
    pal_image = Image.new("P", (1, 1))
    pal_image.putpalette(table.tobytes())
    name = "fs-web-palette"
    report.add(name, "scanline", "sl.color.dither(rgb, palette=web_safe_table())",
               lambda: sl.color.dither(rgb, palette=table))
    report.add(name, "Pillow", "Image.quantize(palette=..., dither=FLOYDSTEINBERG)",
               lambda: pil_rgb.quantize(palette=pal_image, dither=Image.Dither.FLOYDSTEINBERG))
    # Pillow maps colors to a palette through a cache of coarse color cells: about 9%
    # of random colors get a table color that is not the nearest; scanline's search
    # is exact (docs/color.md)
    report.target(name, "Pillow", 1.0, "our aim; Pillow's mapping is approximate")
    report.write()


if __name__ == "__main__":
    main()
