"""Render docs/images/surface-detail.png: surface detail (Hearn & Baker 14-8, 14-9) --
procedural marble and wood from Perlin's noise on tilted tiles, a bump-mapped tile
(Blinn 1978: a turbulence height map perturbing the normals of a flat square) and a
mirror sphere with a latitude-longitude environment map (sky over a checkered ground).
"""

import math
import sys
from pathlib import Path

import numpy as np

import scanline as sl
from scanline.cli._plot import side_by_side

SIZE = 220


def tile():
    return sl.mesh.Mesh([(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)], [[0, 1, 2, 3]],
                        uv=[(0, 0), (1, 0), (1, 1), (0, 1)])


def sky_and_ground(width=512, height=256):
    """A latitude-longitude image: a blue sky brightening to the horizon over a
    checkered ground, rows top (straight up) to bottom (straight down)."""
    v = (np.arange(height)[::-1] + 0.5) / height
    u = (np.arange(width) + 0.5) / width
    up = np.clip((v - 0.5) * 2, 0, 1)[:, None, None]
    sky = (1 - up) * np.array([0.85, 0.9, 1.0]) + up * np.array([0.2, 0.4, 0.85])
    squares = ((np.floor(u * 16)[None, :] + np.floor(v * 16)[:, None]) % 2)[..., None]
    ground = 0.25 + 0.5 * squares * np.array([0.9, 0.75, 0.5])
    return np.where((v < 0.5)[:, None, None], ground, np.broadcast_to(sky, (height, width, 3)))


def main(out):
    lights = [sl.lighting.AmbientLight(0.25),
              sl.lighting.DirectionalLight((0.5, -0.4, -1.0), 0.9)]
    tilted = sl.Camera(eye=(0, -2.2, 2.6), target=(0, 0, 0), up=(0, 0, 1),
                       projection=sl.projection.perspective(fov=math.radians(45), near=0.5))
    t = np.linspace(0, 4, 256)
    height = sl.texture.turbulence(np.stack([*np.meshgrid(t, t), np.full((256, 256), 0.5)], -1), 4)
    bump = sl.Texture(height / height.max(), wrap="repeat")
    scenes = [
        ("marble", tile(), tilted,
         sl.lighting.Material(ks=0.3, shininess=30, texture=sl.texture.marble(256, seed=2))),
        ("wood", tile(), tilted,
         sl.lighting.Material(ks=0.2, shininess=10, texture=sl.texture.wood(256, seed=3))),
        ("bump map", tile(), tilted,
         sl.lighting.Material(color=(200, 170, 140), ks=0.3, shininess=20, bump=bump,
                              bump_scale=0.25)),
        ("environment map", sl.mesh.sphere(1.0, resolution=48),
         sl.Camera(eye=(0, 0.6, 3.2), target=(0, 0, 0),
                   projection=sl.projection.perspective(fov=math.radians(45), near=0.5)),
         sl.lighting.Material(ka=0.05, kd=0.15, ks=0.4, shininess=60, color="gray",
                              environment=sl.Texture(sky_and_ground()), reflectivity=0.85)),
    ]
    panels = []
    for _, mesh, cam, mat in scenes:
        fb = sl.FrameBuffer(SIZE, SIZE, background="#e4e4e4")
        sl.render(fb, mesh, cam, materials=mat, shading="phong", lights=lights, antialias=2)
        panels.append(fb.to_pil())
    side_by_side(panels, [name for name, *_ in scenes]).save(out)


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("docs/images/surface-detail.png"))
