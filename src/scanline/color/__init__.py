"""Color specifications and their conversion to frame-buffer pixel values.

A *color* argument anywhere in scanline may be

* a name or hex string that Pillow understands (``"black"``, ``"#ff8000"``,
  ``"#ff800080"``, ``"hsl(120, 100%, 50%)"``);
* a tuple of 3 (RGB) or 4 (RGBA) integers in 0..255;
* an integer: a bit (0 or 1) in mode ``"1"``, a gray level 0..255 in modes ``"L"``,
  ``"RGB"`` and ``"RGBA"``, and a color-table index in mode ``"P"``.
"""

from .spec import rgba, pixel_value

__all__ = ["rgba", "pixel_value"]
