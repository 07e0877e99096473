"""
Three-dimensional viewing
=========================

Demo figures for three-dimensional viewing (Hearn & Baker, chapters 9 to 12): the
six standard views, parallel projections side by side, one-, two- and three-point
perspective with their vanishing points, view-volume clipping, wireframes, a
stereoscopic pair and an exploded view.  Every line is drawn by
:func:`scanline.draw3d.wireframe` (or its 3-D lines) through a
:class:`scanline.Camera`; labels are Pillow text."""

import math

import numpy as np
from PIL import ImageDraw

import scanline as sl

from scanline.gallery._plot import font, side_by_side, stacked
from scanline.gallery.primitives import HIGHLIGHT, PAPER, PIXEL, SECOND, Figure

FAINT = "#c8c8c8"
#: The house of the standard views: a pentagonal prism (x -1.5..1.5, y 0..3,
#: z -1..1) with a chimney, world y up.
PROFILE = [(-1.5, 0), (1.5, 0), (1.5, 2), (0, 3), (-1.5, 2)]


def house():
    """The house: walls and roof swept from the gable, and the chimney."""
    body = sl.mesh.translational_sweep(PROFILE, (0, 0, -2), closed=True).translated((0, 0, 1))
    chimney = sl.mesh.box((0.6, 2.2, -0.3), (1.0, 3.2, 0.1))
    return body, chimney


def _panel(meshes, camera, size, colors=(PIXEL, HIGHLIGHT), width=2, antialias=False):
    fb = sl.FrameBuffer(*size, background=PAPER)
    sl.draw3d.wireframe(fb, list(meshes), camera, color=list(colors)[:len(meshes)],
                        width=width, antialias=antialias)
    return fb


def figure_standard_views():
    """The six standard views of the house, laid out as on an engineering drawing."""
    body, chimney = house()
    window = (-2.4, -2.4, 2.4, 2.4)
    panels, titles = [], []
    for view in ("top", "front", "right", "rear", "left", "bottom"):
        cam = sl.Camera(target=(0, 1.2, 0),
                        projection=sl.projection.orthographic(view, window=window))
        panels.append(_panel([body, chimney], cam, (150, 150)).to_pil())
        titles.append({"top": "top (plan)", "right": "right side"}.get(view, view))
    image = stacked([side_by_side(panels[:3], titles[:3]), side_by_side(panels[3:], titles[3:])])
    return Figure(
        "three-d-standard-views", "The six standard views of a house",
        "Orthographic projections x_p = x, y_p = y of the object turned to face the view "
        "plane: the plan (top) view, the front, side and rear elevations and the bottom "
        "view (sl.projection.orthographic(view)). The chimney (orange) stands on the right "
        "half of the roof.", "Hearn & Baker, section 12-3", image, None)


def figure_parallel_projections():
    """Isometric, cavalier and cabinet projections of one cube."""
    cube = sl.mesh.cube(1.0)
    axes = np.array([[0, 0, 0, 1.0, 0, 0], [0, 0, 0, 0, 1.0, 0], [0, 0, 0, 0, 0, 1.0]]) - \
        np.tile([0.5, 0.5, 0.5], 2)
    window = (-1.3, -1.3, 1.3, 1.3)
    projections = [("isometric", sl.projection.isometric(window=window)),
                   ("cavalier, phi = 30", sl.projection.oblique("cavalier", phi=math.radians(30),
                                                               window=window)),
                   ("cabinet, phi = 30", sl.projection.oblique("cabinet", phi=math.radians(30),
                                                              window=window))]
    panels = []
    rows = []
    for title, proj in projections:
        cam = sl.Camera(target=(0, 0, 0), projection=proj)
        fb = _panel([cube], cam, (200, 200))
        sl.draw3d.lines(fb, axes, cam, color=["#e15759", "#59a14f", "#4e79a7"], width=2)
        panels.append(fb.to_pil())
        f = sl.projection.foreshortening(proj)
        rows.append(f"{title:20s} f_x = {f[0]:.3f}  f_y = {f[1]:.3f}  f_z = {f[2]:.3f}")
    return Figure(
        "three-d-parallel", "Isometric, cavalier and cabinet projections",
        "One unit cube, its edges from the corner (-0.5, -0.5, -0.5) along x (red), y "
        "(green) and z (blue). Isometric: all three axes foreshortened by sqrt(2/3). "
        "Oblique: x_p = x + z L1 cos phi, y_p = y + z L1 sin phi with L1 = 1/tan alpha; "
        "cavalier (tan alpha = 1) keeps the receding edges' length, cabinet "
        "(tan alpha = 2) halves it. The table lists the lengths the unit axes are drawn "
        "with.", "Hearn & Baker, section 12-3",
        side_by_side(panels, [t for t, _ in projections]), "\n".join(rows))


def _mark(draw, xy, height, color, label):
    x, y = xy
    y = height - 1 - y
    draw.ellipse((x - 4, y - 4, x + 4, y + 4), outline=color, width=2)
    draw.text((x + 6, y - 6), label, fill=color, font=font(12), anchor="lb")


def figure_vanishing_points():
    """One-, two- and three-point perspective of one box, vanishing points marked."""
    box = sl.mesh.box((-1, 0, -1), (1, 1, 1))

    def perspective(degrees):
        return sl.projection.perspective(fov=math.radians(degrees), near=0.5)
    # wide fields of view put the vanishing points inside the picture
    p, d = math.radians(38), 3.6
    cams = [("one-point", sl.Camera(eye=(0.5, 1.2, 3.6), target=(0.5, 1.2, 0),
                                    projection=perspective(70))),
            ("two-point", sl.Camera(eye=(2.5, 0.5, 2.5), target=(0, 0.5, 0),
                                    projection=perspective(100))),
            ("three-point", sl.Camera(eye=(d * math.cos(p) * math.sin(math.pi / 4),
                                           d * math.sin(p) + 0.5,
                                           d * math.cos(p) * math.cos(math.pi / 4)),
                                      target=(0, 0.5, 0), projection=perspective(110)))]
    size = (300, 300)
    panels, rows = [], []
    for title, cam in cams:
        fb = sl.FrameBuffer(*size, background=PAPER)
        corners = box.vertices
        vps = {}
        for name, d in zip("xyz", np.eye(3)):
            vp = cam.vanishing_point(d, *size)
            vps[name] = vp
            if vp is None:
                continue
            # dashed lines from the box's corners toward the vanishing point
            for c in cam.project(corners, *size):
                if np.isfinite(c).all():
                    sl.draw.line(fb, c[0], c[1], vp[0], vp[1], color=FAINT, dash=(3, 3))
        sl.draw3d.wireframe(fb, box, cam, color=PIXEL, width=2)
        image = fb.to_pil()
        draw = ImageDraw.Draw(image)
        for name, vp in vps.items():
            if vp is not None:
                _mark(draw, vp, size[1], HIGHLIGHT, f"V{name}")
        panels.append(image)
        rows.append(f"{title}: " + ", ".join(
            f"V{n} = ({vp[0]:.1f}, {vp[1]:.1f})" if vp is not None else f"V{n}: none (parallel "
            "to the view plane)" for n, vp in vps.items()))
    return Figure(
        "three-d-vanishing-points", "One-, two- and three-point perspective",
        "The same box through a perspective camera turned so that the view plane cuts one, "
        "two or three of the principal axes. Lines parallel to an axis that the view plane "
        "cuts converge at that axis's vanishing point (orange, computed by "
        "camera.vanishing_point as the image of the point at infinity (d, 0)); gray "
        "dashes run from the box's corners to it. Wide fields of view (70, 100 and 110 "
        "degrees) keep them on the picture.", "Hearn & Baker, section 12-3", side_by_side(
            panels, [t for t, _ in cams]), "\n".join(rows))


def _scene_objects():
    """The objects of the view-volume figure: a row of cubes and a torus."""
    cubes = [sl.mesh.cube(0.8, center=(x, 0.4, -z)) for x, z in
             ((-2.5, 1), (-1, 2), (0.5, 4), (2, 6), (3.5, 9), (0, 13))]
    ring = sl.mesh.torus(1.0, 0.25, center=(0, 0, 0), resolution=(20, 8)).transformed(
        sl.transform3d.compose(sl.transform3d.translation(-1.2, 1.2, -7),
                               sl.transform3d.rotation(math.pi / 2, "x")))
    return cubes + [ring]


def figure_view_volume():
    """A scene, the camera's view volume seen from outside, and what the camera sees."""
    objects = _scene_objects()
    viewer = sl.Camera(eye=(0, 1, 2), target=(0, 0.6, -5),
                       projection=sl.projection.perspective(fov=math.radians(40), near=1.5,
                                                            far=10))
    size = (320, 240)
    outside = sl.Camera(eye=(14, 9, 4), target=(0, 0, -5),
                        projection=sl.projection.perspective(fov=math.radians(45), near=1))
    fb = sl.FrameBuffer(*size, background=PAPER)
    sl.draw3d.wireframe(fb, objects, outside, color=FAINT)
    sl.draw3d.view_volume(fb, viewer, outside, HIGHLIGHT, size=size, width=2)
    # the parts inside the view volume, clipped in 3-D, drawn over in blue
    inside = sl.FrameBuffer(*size, background=PAPER)
    for mesh in objects:
        a = mesh.vertices[mesh.edges[:, 0]]
        b = mesh.vertices[mesh.edges[:, 1]]
        h = np.stack([viewer.to_clip(a, *size), viewer.to_clip(b, *size)], axis=1)
        seg, ok = sl.clip.homogeneous(h)
        world = _unproject(viewer, seg[ok], size)
        sl.draw3d.lines(fb, world, outside, color=PIXEL)
    sl.draw3d.wireframe(inside, objects, viewer, color=PIXEL)
    corners = viewer.volume_corners(*size)
    table = "view volume corners (world):\n" + "\n".join(
        f"  {'front' if i < 4 else 'back '} {i % 4}: ({c[0]:7.3f}, {c[1]:7.3f}, {c[2]:7.3f})"
        for i, c in enumerate(corners))
    return Figure(
        "three-d-view-volume", "View-volume clipping",
        "Left: the scene seen from outside, with the viewing camera's frustum (orange: "
        "front plane 1.5 and back plane 10 units from the eye, 40 degree field of view). "
        "Blue: what survives clipping against the view volume, computed in homogeneous "
        "coordinates before the perspective divide (sl.clip.homogeneous); gray: what is "
        "clipped away. Right: the camera's own picture of the same clipped edges.",
        "Hearn & Baker, sections 12-3 and 12-5",
        side_by_side([fb.to_pil(), inside.to_pil()], ["from outside", "through the camera"]),
        table)


def _unproject(camera, clip_segments, size):
    """World coordinates (N, 6) of homogeneous clip-coordinate segments (N, 2, 4)."""
    inv = sl.transform3d.inverse(camera.matrix(*size))
    h = clip_segments.reshape(-1, 4) @ inv.T
    return (h[:, :3] / h[:, 3:]).reshape(-1, 6)


def figure_wireframes():
    """The Utah teapot and a torus in wireframe, depth-cued."""
    cam = sl.Camera(eye=(6.5, -5.5, 4.5), target=(0.2, 0, 1.2), up=(0, 0, 1),
                    projection=sl.projection.perspective(fov=math.radians(38), near=1))
    pot = sl.mesh.teapot(5)
    fb1 = sl.FrameBuffer(300, 220, background=PAPER)
    sl.draw3d.wireframe(fb1, pot, cam, color=PIXEL, depth_cue=(1.0, 0.15))
    ring = sl.mesh.torus(1.6, 0.55, resolution=(36, 14))
    cam2 = sl.Camera(eye=(0, -4.8, 3.2), target=(0, 0, 0), up=(0, 0, 1),
                     projection=sl.projection.perspective(fov=math.radians(45), near=1))
    fb2 = sl.FrameBuffer(300, 220, background=PAPER)
    sl.draw3d.wireframe(fb2, ring, cam2, color=SECOND, depth_cue=(1.0, 0.15))
    tables = pot.polygon_tables()
    return Figure(
        "three-d-wireframes", "Wireframes with depth cueing",
        f"Left: the Utah teapot as a mesh of {len(pot.vertices)} vertices, "
        f"{len(pot.edges)} edges and {len(pot)} triangles (sl.mesh.teapot(5)); right: a "
        "torus tessellated 36 x 14 from its parametric equations. Each edge is clipped in "
        "homogeneous coordinates, projected and drawn, its intensity falling "
        "linearly with its distance (depth cueing: the nearest edges in full color, the "
        "farthest at 15%).", "Hearn & Baker, sections 9-1, 10-1 and 10-4",
        side_by_side([fb1.to_pil(), fb2.to_pil()], ["teapot", "torus"]),
        f"polygon tables of the teapot: {len(tables.vertices)} vertices, "
        f"{len(tables.edges)} edges, {len(tables.surfaces)} surfaces; consistency "
        f"checks: {'all passed' if tables.consistent else tables.check()[:3]}")


def figure_stereo_pair():
    """A red-cyan anaglyph: the left eye's view in red, the right eye's in cyan."""
    objects = [sl.mesh.sphere(0.9, center=(0, 0, 0), resolution=(18, 9)),
               sl.mesh.cube(0.7, center=(1.7, -0.3, -1.2)),
               sl.mesh.torus(0.7, 0.18, center=(-1.8, 0.2, -1.8), resolution=(20, 8))]
    cam = sl.Camera(eye=(0, 0.8, 4.4), target=(0, 0, -0.6),
                    projection=sl.projection.perspective(fov=math.radians(40), near=1))
    left, right = cam.stereo(0.35)
    size = (320, 220)
    views = []
    for eye in (left, right):
        fb = sl.FrameBuffer(*size, mode="L", background=255)
        sl.draw3d.wireframe(fb, objects, eye, color=0, depth_cue=(1.0, 0.35))
        views.append(fb)
    # red channel: the left eye's view, green and blue: the right eye's
    anaglyph = sl.draw3d.anaglyph(*views)
    return Figure(
        "three-d-stereo", "A red-cyan stereoscopic pair",
        "Two views from eye positions 0.35 units apart along the camera's x axis, both "
        "looking at the scene's center (camera.stereo), merged by sl.draw3d.anaglyph: the "
        "red channel is the left eye's view, green and blue the right eye's, so the left "
        "eye's lines print in cyan ink (dark through the red filter) and the right eye's in "
        "red ink; depth cueing (sl.draw3d.wireframe's depth_cue, the farthest lines at 35%) "
        "adds its own cue. With red-cyan glasses the sphere stands in front of the cube and "
        "the ring.",
        "Hearn & Baker, section 9-1 (stereoscopic views)", anaglyph.to_pil(), None)


def figure_exploded_view():
    """The teapot's parts moved apart: an exploded view."""
    names = ("lid", "rim", "body", "handle", "spout", "bottom")
    colors = (HIGHLIGHT, "#e15759", PIXEL, SECOND, "#b07aa1", "#76b7b2")
    assembled = [sl.mesh.teapot(4, parts=[p]) for p in names]
    factor = 1.7
    parts = sl.draw3d.exploded(assembled, factor)
    cam = sl.Camera(eye=(2.5, -9, 4.5), target=(0.1, 0, 1.2), up=(0, 0, 1),
                    projection=sl.projection.perspective(fov=math.radians(40), near=1))
    fb = sl.FrameBuffer(420, 300, background=PAPER)
    sl.draw3d.wireframe(fb, parts, cam.replace(projection=sl.projection.perspective(
        fov=math.radians(52), near=1)), color=list(colors))
    whole = sl.FrameBuffer(300, 300, background=PAPER)
    sl.draw3d.wireframe(whole, sl.mesh.teapot(4), cam, color=PIXEL)
    image = side_by_side([whole.to_pil(), fb.to_pil()], ["assembled", "exploded"])
    moves = [sl.draw3d.centroid(b) - sl.draw3d.centroid(a) for a, b in zip(assembled, parts)]
    return Figure(
        "three-d-exploded", "An exploded view of the teapot",
        "The teapot's six parts (lid, rim, body, handle, spout, bottom: Newell's patch "
        f"groups, each its own mesh) moved apart by sl.draw3d.exploded(parts, {factor}): each "
        "part along the line from the teapot's center through its own centroid, to "
        f"{factor} times its distance, so that each part and how it joins the others can "
        "be seen.", "Hearn & Baker, section 9-1 (exploded and cutaway views)", image,
        "\n".join(f"{p:7s} moved by ({d[0]:.2f}, {d[1]:.2f}, {d[2]:.2f})"
                  for p, d in zip(names, moves)))


FIGURES = (figure_standard_views, figure_parallel_projections, figure_vanishing_points,
           figure_view_volume, figure_wireframes, figure_stereo_pair, figure_exploded_view)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
