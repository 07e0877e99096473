"""
Constructive solid geometry
===========================

Demo figure of constructive solid geometry (Hearn & Baker 10-16; Roth 1982): the
classic CSG tree -- a box intersected with a sphere, minus three cylinders along the
axes -- ray cast exactly (``sl.render(..., method="ray-casting")``), with its tree drawn
beside it, each node ray cast on its own."""

import math

from PIL import Image, ImageDraw

import scanline as sl

from scanline.gallery._plot import INK, PAPER, font, side_by_side
from scanline.gallery.primitives import Figure

BACKGROUND = "#e4e4e4"


def classic_tree():
    """``(tree, nodes)``: the classic CSG object and its tree as nested tuples
    ``(label, solid, children)``."""
    m = sl.lighting.Material
    box = sl.solids.Box((-1, -1, -1), (1, 1, 1), material=m(color="#c0392b", ks=0.3))
    ball = sl.solids.Sphere((0, 0, 0), 1.35, material=m(color="#2e6fbd", ks=0.4,
                                                          shininess=40))
    cylinders = [sl.solids.Cylinder((0, 0, 0), 0.55, 3.2, axis=a,
                                    material=m(color="#e0b020", ks=0.3))
                 for a in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
    body = box & ball
    holes = sl.csg.union(*cylinders)
    tree = body - holes
    nodes = ("\u2212", tree, (("\u2229", body, (("box", box, ()), ("sphere", ball, ()))),
                              ("\u222a", holes, tuple((f"cylinder {a}", c, ())
                                                      for a, c in zip("xyz", cylinders)))))
    return tree, nodes


def _camera():
    return sl.Camera(eye=(3.2, 2.6, 4.2), target=(0, 0, 0),
                     projection=sl.projection.perspective(fov=math.radians(34), near=0.5))


def _cast(solid, width, height):
    fb = sl.FrameBuffer(width, height, background=BACKGROUND)
    lights = [sl.lighting.AmbientLight(0.3),
              sl.lighting.DirectionalLight((-0.4, -0.7, -0.6), 0.85)]
    sl.render(fb, solid, _camera(), method="ray-casting", shading="phong", lights=lights)
    return fb.to_pil()


def tree_image(nodes, thumb=84):
    """The tree drawn top-down, each node its own ray-cast picture under its label."""
    label_font = font(14)
    levels, todo = [], [(nodes, 0, None)]
    while todo:                                   # breadth first: (node, level, parent)
        node, level, parent = todo.pop(0)
        if len(levels) <= level:
            levels.append([])
        levels[level].append((node, parent))
        todo += [(child, level + 1, node) for child in node[2]]
    gap, head = 12, 20
    width = max(len(row) for row in levels) * (thumb + gap) + gap
    height = len(levels) * (thumb + head + 28) + gap
    out = Image.new("RGB", (width, height), PAPER)
    draw = ImageDraw.Draw(out)
    where = {}
    for level, row in enumerate(levels):
        y = gap + level * (thumb + head + 28)
        span = len(row) * (thumb + gap) - gap
        for i, (node, parent) in enumerate(row):
            x = (width - span) // 2 + i * (thumb + gap)
            where[id(node)] = (x + thumb // 2, y, y + head + thumb)
            if parent is not None:
                px, _, pbottom = where[id(parent)]
                draw.line([(px, pbottom + 2), (x + thumb // 2, y)], fill=INK, width=2)
            draw.text((x + thumb // 2, y + 2), node[0], fill=INK, font=label_font, anchor="mt")
            out.paste(_cast(node[1], thumb, thumb), (x, y + head))
    return out


def figure_csg():
    """The classic CSG tree, rendered by ray casting, beside its tree."""
    tree, nodes = classic_tree()
    image = side_by_side([_cast(tree, 300, 280), tree_image(nodes)],
                         ["(box \u2229 sphere) \u2212 (three cylinders)", "its CSG tree"])
    return Figure(
        "csg-tree", "Constructive solid geometry: the classic CSG tree",
        "A box intersected with a sphere, minus the union of three cylinders along the "
        "axes. Each pixel's ray meets every primitive exactly (the quadrics' roots, the "
        "box's slabs); the intervals where it is inside each one are combined up the tree "
        "by Roth's rules (union, intersection, difference), and the first surface left is "
        "lit with its primitive's normal and material: the red faces are the box's, the "
        "blue corners the sphere's, the yellow bores the cylinders' surfaces turned "
        "inside out. Beside it, the tree, each node ray cast on its own.",
        "Hearn & Baker, section 10-16; Roth 1982, \"Ray casting for modeling solids\"",
        image, None)


FIGURES = (figure_csg,)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
