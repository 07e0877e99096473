"""Render docs/images/texture-perspective.png: the same checker-textured quad in
perspective, its texture coordinates interpolated affinely in screen space (left) and
perspective-correctly (right; Hearn & Baker 14-9) -- the demo's figure
(``scanline.gallery.surface_rendering``) at the documentation's size.

The quad is two triangles.  Affine interpolation is linear in screen x and y within
each triangle, so the squares do not shrink with the distance and the checker bends
where the two triangles meet, along the diagonal; perspective-correct interpolation
(u/w, v/w and 1/w linear, then divided) gives straight rows that shrink toward the
horizon.
"""

import sys
from pathlib import Path

from scanline.gallery._plot import side_by_side
from scanline.gallery.surface_rendering import texture_perspective_panels


def main(out):
    side_by_side(texture_perspective_panels(360, 240),
                 ["affine", "perspective-correct"]).save(out)


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("docs/images/texture-perspective.png"))
