"""Color: color specifications, color models, gray-scale levels, color tables,
dithering and halftoning.

A *color* argument anywhere in scanline may be

* a name or hex string that Pillow understands (``"black"``, ``"#ff8000"``,
  ``"#ff800080"``, ``"hsl(120, 100%, 50%)"``);
* a tuple of 3 (RGB) or 4 (RGBA) integers in 0..255;
* an integer: a bit (0 or 1) in mode ``"1"``, a gray level 0..255 in modes ``"L"``,
  ``"RGB"`` and ``"RGBA"``, and a color-table index in mode ``"P"``.

Color models (:mod:`.models`): ``rgb_to_hsv``, ``hsv_to_rgb``, ``rgb_to_hls``,
``hls_to_rgb``, ``rgb_to_cmy``, ``cmy_to_rgb``, ``rgb_to_cmyk``, ``cmyk_to_rgb``,
``rgb_to_yiq``, ``yiq_to_rgb``, ``luminance`` and ``convert``.  Color tables
(:mod:`.tables`): ``gray_table``, ``rgb332_table``, ``web_safe_table``,
``median_cut_table``, ``color_table``, ``nearest``.  Levels and dithering
(:mod:`.dither`): ``gray_levels``, ``indexed``, ``dither``, ``bayer_matrix``,
``halftone``.
"""

from .dither import bayer_matrix, dither, gray_levels, halftone, indexed
from .models import (cmy_to_rgb, cmyk_to_rgb, convert, hls_to_rgb, hsv_to_rgb, luminance,
                     rgb_to_cmy, rgb_to_cmyk, rgb_to_hls, rgb_to_hsv, rgb_to_yiq, yiq_to_rgb)
from .spec import pixel_value, rgba
from .tables import (color_table, gray_table, median_cut_table, nearest, rgb332_table,
                     web_safe_table)

__all__ = [
    "rgba", "pixel_value",
    "rgb_to_hsv", "hsv_to_rgb", "rgb_to_hls", "hls_to_rgb", "rgb_to_cmy", "cmy_to_rgb",
    "rgb_to_cmyk", "cmyk_to_rgb", "rgb_to_yiq", "yiq_to_rgb", "luminance", "convert",
    "gray_table", "rgb332_table", "web_safe_table", "median_cut_table", "color_table",
    "nearest", "gray_levels", "indexed", "dither", "bayer_matrix", "halftone",
]
