"""Render docs/images/surface-detail.png: surface detail (Hearn & Baker 14-8, 14-9) --
procedural marble and wood from Perlin's noise on tilted tiles, a bump-mapped tile
(Blinn 1978: a turbulence height map perturbing the normals of a flat square) and a
mirror sphere with a latitude-longitude environment map (sky over a checkered ground);
the demo's figure (``scanline.gallery.surface_rendering``) at the documentation's
size.
"""

import sys
from pathlib import Path

from scanline.gallery._plot import side_by_side
from scanline.gallery.surface_rendering import surface_detail_panels


def main(out):
    panels = surface_detail_panels(220)
    side_by_side([image for _, image in panels], [name for name, _ in panels]).save(out)


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("docs/images/surface-detail.png"))
