"""
Surface rendering
=================

Demo figures for surface rendering (Hearn & Baker, chapter 14, sections 14-6 to
14-9): texture coordinates interpolated affinely and perspective-correctly, surface
detail (procedural marble and wood, a bump map, an environment map), recursive ray
tracing of the ``glass_spheres`` example scene, and the Cornell box by radiosity.
The documentation's images (docs/images/texture-perspective.png, surface-detail.png,
cornell-box.png) are these figures at their own sizes
(``examples/ch14_surface_detail``)."""

import math

import numpy as np

import scanline as sl

from scanline.gallery._plot import side_by_side
from scanline.gallery.primitives import Figure

BACKGROUND = "#e4e4e4"


def _tile():
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


def texture_perspective_panels(width=360, height=240):
    """The checker quad, affine and perspective-correct (two Pillow images)."""
    quad = sl.mesh.Mesh([(-1, 0, 0.6), (1, 0, 0.6), (1, 0, -5), (-1, 0, -5)], [[0, 1, 2, 3]],
                        uv=[(0, 0), (1, 0), (1, 1), (0, 1)])
    cam = sl.Camera(eye=(0, 1.2, 2.6), target=(0, 0, -1.2),
                    projection=sl.projection.perspective(fov=math.radians(50), near=0.5))
    mat = sl.lighting.Material(ka=1.0, kd=0.0, ks=0.0,
                               texture=sl.texture.checker(256, 8, colors=("white", "#2b4c8c"),
                                                          filter="trilinear"))
    panels = []
    for mapping in ("affine", "perspective"):
        fb = sl.FrameBuffer(width, height, background=BACKGROUND)
        sl.render(fb, quad, cam, materials=mat, shading="flat", texture_mapping=mapping,
                  lights=[sl.lighting.AmbientLight(1.0)], antialias=2)
        panels.append(fb.to_pil())
    return panels


def figure_texture_perspective():
    """The same textured quad with affine and perspective-correct texture coordinates."""
    return Figure(
        "surface-texture-perspective", "Texture mapping: affine and perspective-correct",
        "A checker-textured quad (two triangles) in perspective. Left: u and v interpolated "
        "linearly in screen x and y within each triangle -- the squares do not shrink with "
        "the distance and the rows bend where the triangles meet. Right: u/w, v/w and 1/w "
        "interpolated and divided at every pixel, so straight rows shrink toward the "
        "horizon. Trilinear filtering over the mipmap levels.",
        "Hearn & Baker, section 14-9", side_by_side(texture_perspective_panels(),
                                                    ["affine", "perspective-correct"]), None)


def surface_detail_panels(size=220):
    """Marble, wood, a bump-mapped tile and an environment-mapped sphere:
    ``[(label, Pillow image)]``."""
    lights = [sl.lighting.AmbientLight(0.25),
              sl.lighting.DirectionalLight((0.5, -0.4, -1.0), 0.9)]
    tilted = sl.Camera(eye=(0, -2.2, 2.6), target=(0, 0, 0), up=(0, 0, 1),
                       projection=sl.projection.perspective(fov=math.radians(45), near=0.5))
    t = np.linspace(0, 4, 256)
    height = sl.texture.turbulence(np.stack([*np.meshgrid(t, t), np.full((256, 256), 0.5)], -1),
                                   4)
    bump = sl.Texture(height / height.max(), wrap="repeat")
    scenes = [
        ("marble", _tile(), tilted,
         sl.lighting.Material(ks=0.3, shininess=30, texture=sl.texture.marble(256, seed=2))),
        ("wood", _tile(), tilted,
         sl.lighting.Material(ks=0.2, shininess=10, texture=sl.texture.wood(256, seed=3))),
        ("bump map", _tile(), tilted,
         sl.lighting.Material(color=(200, 170, 140), ks=0.3, shininess=20, bump=bump,
                              bump_scale=0.25)),
        ("environment map", sl.mesh.sphere(1.0, resolution=48),
         sl.Camera(eye=(0, 0.6, 3.2), target=(0, 0, 0),
                   projection=sl.projection.perspective(fov=math.radians(45), near=0.5)),
         sl.lighting.Material(ka=0.05, kd=0.15, ks=0.4, shininess=60, color="gray",
                              environment=sl.Texture(sky_and_ground()), reflectivity=0.85)),
    ]
    panels = []
    for name, mesh, cam, mat in scenes:
        fb = sl.FrameBuffer(size, size, background=BACKGROUND)
        sl.render(fb, mesh, cam, materials=mat, shading="phong", lights=lights, antialias=2)
        panels.append((name, fb.to_pil()))
    return panels


def figure_surface_detail():
    """Procedural textures, a bump map and an environment map."""
    panels = surface_detail_panels(180)
    return Figure(
        "surface-detail", "Surface detail: procedural textures, bump and environment maps",
        "Marble and wood: colors from Perlin's noise and turbulence (Perlin 1985; his "
        "improved noise of 2002), a sine of the position disturbed by turbulence and rings "
        "of the distance from an axis. Bump map: a flat square whose shading normal is "
        "tilted by the derivatives of a turbulence height map along the surface (Blinn "
        "1978). Environment map: a mirror-like sphere that adds k_r times a latitude-"
        "longitude picture of its surroundings in the direction of the reflected view ray.",
        "Hearn & Baker, sections 14-8 and 14-9",
        side_by_side([p for _, p in panels], [n for n, _ in panels]), None)


def figure_ray_tracing():
    """The glass_spheres example scene, ray traced."""
    from PIL import Image

    image = sl.scene.load(sl.scene.example("glass_spheres")).raster().to_pil()
    image = image.resize((image.width * 3 // 4, image.height * 3 // 4), Image.LANCZOS)
    return Figure(
        "surface-ray-tracing", "Recursive ray tracing",
        "A mirror, a glass and a glossy sphere on a checkered floor under a square area "
        "light (scanline render --example glass_spheres). From each primary ray's hit, "
        "shadow rays go to every light (16 to the area light: a soft penumbra), a reflected "
        "ray and a ray bent by Snell's law follow, weighted by Fresnel's equations, up to "
        "six levels; the glossy sphere spreads its reflected rays over a cone (distributed "
        "ray tracing). scanline trace ray-tracing X Y prints one pixel's ray tree.",
        "Hearn & Baker, section 14-6; Whitted 1980; Cook, Porter & Carpenter 1984",
        image, None)


def cornell_box_image(size=480, subdivisions=10):
    """The Cornell box solved by radiosity (hemicube form factors, Gauss-Seidel) and
    drawn by Gouraud shading of the node radiosities: (Pillow image, solution)."""
    box = sl.radiosity.cornell_box()
    solution = sl.radiosity.solve(box["meshes"], box["emission"], box["reflectance"],
                                  subdivisions=subdivisions)
    fb = sl.FrameBuffer(size, size, mode="RGB", background="black")
    solution.render(fb, box["camera"], antialias=2)
    return fb.to_pil(), solution


def figure_radiosity():
    """The Cornell box by radiosity."""
    image, solution = cornell_box_image(240, 6)
    return Figure(
        "surface-radiosity", "Radiosity: the Cornell box",
        f"The Cornell box (its published geometry and colors), {len(solution.radiosity):,} "
        f"patches, form factors by the hemicube, the radiosity equations solved by "
        f"Gauss-Seidel in {solution.iterations} sweeps; node radiosities drawn by Gouraud "
        "shading. Light reflected from the red and green walls colors the blocks and the "
        "floor, and the shadows are soft: the light arrives from every surface.",
        "Hearn & Baker, section 14-7; Goral et al. 1984; Cohen & Greenberg 1985",
        image, None)


FIGURES = (figure_texture_perspective, figure_surface_detail, figure_ray_tracing,
           figure_radiosity)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
