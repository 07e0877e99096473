"""Render docs/images/texture-perspective.png: the same checker-textured quad in
perspective, its texture coordinates interpolated affinely in screen space (left) and
perspective-correctly (right; Hearn & Baker 14-9).

The quad is two triangles.  Affine interpolation is linear in screen x and y within
each triangle, so the squares do not shrink with the distance and the checker bends
where the two triangles meet, along the diagonal; perspective-correct interpolation
(u/w, v/w and 1/w linear, then divided) gives straight rows that shrink toward the
horizon.
"""

import math
import sys
from pathlib import Path

import scanline as sl
from scanline.cli._plot import side_by_side


def main(out):
    quad = sl.mesh.Mesh([(-1, 0, 0.6), (1, 0, 0.6), (1, 0, -5), (-1, 0, -5)], [[0, 1, 2, 3]],
                        uv=[(0, 0), (1, 0), (1, 1), (0, 1)])
    cam = sl.Camera(eye=(0, 1.2, 2.6), target=(0, 0, -1.2),
                    projection=sl.projection.perspective(fov=math.radians(50), near=0.5))
    mat = sl.lighting.Material(ka=1.0, kd=0.0, ks=0.0,
                               texture=sl.texture.checker(256, 8, colors=("white", "#2b4c8c"),
                                                          filter="trilinear"))
    panels = []
    for mapping in ("affine", "perspective"):
        fb = sl.FrameBuffer(360, 240, background="#e4e4e4")
        sl.render(fb, quad, cam, materials=mat, shading="flat", texture_mapping=mapping,
                  lights=[sl.lighting.AmbientLight(1.0)], antialias=2)
        panels.append(fb.to_pil())
    side_by_side(panels, ["affine", "perspective-correct"]).save(out)


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("docs/images/texture-perspective.png"))
