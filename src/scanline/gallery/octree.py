"""
Octrees and quadtrees
=====================

Demo figures for octrees and quadtrees (Hearn & Baker, sections 10-17 and 13-10):
the quadtree of a filled polygon drawn with its cell boundaries, and the octree of a
CSG solid rendered by the octree visible-surface method."""

import math

import scanline as sl

from scanline.gallery._plot import side_by_side
from scanline.gallery.primitives import Figure

BACKGROUND = "#e4e4e4"

#: The polygon of the quadtree panel (pixels of a 64 x 64 square).
STAR = [(32 + r * math.cos(a), 32 + r * math.sin(a))
        for k in range(10) for a, r in [(math.pi / 2 + k * math.pi / 5, (29.5, 12.5)[k % 2])]]


def quadtree_panel(scale=4):
    """The quadtree (depth 6) of a star filled by the scan-line fill, each pixel
    ``scale`` x ``scale``, its leaves outlined: a Pillow image."""
    tree = sl.octree.Quadtree.from_polygon(STAR, 6)
    n = (1 << tree.depth) * scale
    fb = sl.FrameBuffer(n, n, background="white")
    tree.draw(fb, color="#2b4c8c", boundary="#b0b0b0", scale=scale)
    return fb.to_pil()


def csg_octree():
    """The octree (depth 5) of a sphere less a box at one corner and a cylinder along
    z: a CSG tree of :mod:`scanline.solids`."""
    solid = sl.csg.difference(sl.solids.Sphere(radius=1.0),
                              sl.solids.Box((0.0, 0.0, 0.0), (1.1, 1.1, 1.1)),
                              sl.solids.Cylinder(radius=0.35, height=2.2))
    return sl.octree.Octree.from_solid(solid, 5)


def octree_panel(width=256, height=256):
    """``csg_octree`` rendered by ``method="octree"``: a Pillow image."""
    cam = sl.Camera(eye=(3.2, 2.4, 2.6), target=(0, 0, 0), up=(0, 0, 1),
                    projection=sl.projection.perspective(fov=math.radians(40), near=0.5))
    fb = sl.FrameBuffer(width, height, background=BACKGROUND)
    sl.render(fb, csg_octree(), cam, method="octree", shading="flat",
              colors="#d08040")
    return fb.to_pil()


def figure_octrees():
    """A quadtree and an octree."""
    tree = csg_octree()
    return Figure(
        "octree-quadtree-and-octree", "Quadtrees and octrees",
        "Left: the quadtree of a star filled by the scan-line polygon fill (64 x 64 pixels, "
        "depth 6), its leaves outlined -- large cells where the region is uniform, single "
        "pixels along the edges. Right: the octree (depth 5) of a CSG solid, a sphere less "
        f"a box and a cylinder, {tree.node_count} nodes, volume {tree.volume():.3f} (exact "
        f"{_exact_volume():.3f}), rendered by the octree visible-surface method: the scene's "
        "octree traversed front to back, each pixel written once, equal to the z-buffer's "
        "image pixel for pixel.",
        "Hearn & Baker, sections 10-17 and 13-10",
        side_by_side([quadtree_panel(), octree_panel()], ["quadtree", "octree, method='octree'"]),
        None)


def _exact_volume():
    """The solid's volume: the sphere less its first octant (the box) and less the
    cylinder's part of the sphere, 4/3 pi (1 - (1 - c^2)^(3/2)) for radius c, of which
    one eighth lies in the first octant, gone already (each octant holds an eighth by
    symmetry)."""
    c = 0.35
    inside = 4 / 3 * math.pi * (1 - (1 - c * c) ** 1.5)
    return 4 / 3 * math.pi * 7 / 8 - inside * 7 / 8


FIGURES = (figure_octrees,)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
