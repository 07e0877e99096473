"""
Illumination and shading
========================

Demo figures for illumination and shading (Hearn & Baker, chapters 13 and 14): the
teapot flat, Gouraud and Phong shaded, Mach bands on Gouraud-shaded facets, depth
cueing, back-face culling with the culled faces shown, and the kinds of light.  Every
surface pixel is drawn by :func:`scanline.render`; labels are Pillow text."""

import math

import numpy as np

import scanline as sl

from scanline.gallery._plot import side_by_side, stacked
from scanline.gallery.primitives import PAPER, Figure

#: The teapot standing up (its model has z up), seen from the front and above.
TEAPOT_CAMERA = dict(eye=(0, 3.2, 8.0), target=(0, 0.75, 0))


def _teapot(n=8):
    return sl.mesh.teapot(n).transformed(sl.transform3d.rotation(-math.pi / 2, "x"))


def _camera(fov=34, **kw):
    return sl.Camera(**{**TEAPOT_CAMERA, **kw},
                     projection=sl.projection.perspective(fov=math.radians(fov), near=1, far=30))


def figure_teapot_shading():
    """The same teapot by constant, Gouraud and Phong shading."""
    pot = _teapot(8)
    mat = sl.lighting.Material(ka=0.25, kd=0.65, ks=0.45, shininess=30, color=(190, 90, 60))
    panels = []
    for shading in ("flat", "gouraud", "phong"):
        fb = sl.FrameBuffer(260, 190, background=PAPER)
        sl.render(fb, pot, _camera(), shading=shading, materials=mat)
        panels.append(fb.to_pil())
    return Figure(
        "shading-teapot", "Flat, Gouraud and Phong shading",
        f"The Utah teapot ({pot.triangulated().face_count} triangles), one material (ka 0.25, "
        "kd 0.65, ks 0.45, n_s 30), ambient light and one directional light, z-buffer. Flat: "
        "one intensity per facet, the illumination model at its centroid. Gouraud: the model "
        "at the vertices with normals averaged from the faces, intensities interpolated "
        "along the edges and scan lines; the highlight is smeared over whole facets. Phong: "
        "the normal interpolated and the model evaluated at every pixel; the highlight is "
        "round and sharp.", "Hearn & Baker, section 14-5",
        side_by_side(panels, ["flat", "Gouraud", "Phong"]), None)


def figure_mach_bands():
    """Gouraud shading of a coarse cylinder: bright and dark stripes at the edges."""
    prism = sl.mesh.rotational_sweep([(0, 1.0), (1.2, 1.0), (1.2, -1.0), (0, -1.0)], axis="y",
                                     steps=12)
    cam = sl.Camera(eye=(0, 0.4, 5), target=(0, 0, 0),
                    projection=sl.projection.perspective(fov=math.radians(34), near=1))
    lights = [sl.lighting.AmbientLight(0.15),
              sl.lighting.DirectionalLight((0.6, -0.3, -0.75), 0.9)]
    mat = sl.lighting.Material(ka=0.3, kd=0.8, ks=0.0)
    panels, rows = [], []
    for shading in ("flat", "gouraud"):
        fb = sl.FrameBuffer(260, 200, mode="L", background=PAPER)
        sl.render(fb, prism, cam, shading=shading, lights=lights, materials=mat)
        panels.append(fb.to_pil().convert("RGB"))
        rows.append(fb.to_array()[100].astype(int))
    # the intensity along the middle scan line of the Gouraud picture
    row = rows[1]
    plot = sl.FrameBuffer(260, 200, background=PAPER)
    xs = np.arange(len(row))
    on = row < 250
    lo, hi = row[on].min(), row[on].max()
    pts = np.stack([xs[on], 20 + (row[on] - lo) / max(hi - lo, 1) * 160.0], axis=1)
    sl.draw.polyline(plot, pts, color="#2b4c8c", width=2)
    slope = np.diff(row[on].astype(float))
    kinks = int((np.abs(np.diff(slope)) > 1.5).sum())
    return Figure(
        "shading-mach-bands", "Mach bands on Gouraud-shaded facets",
        "A twelve-sided prism, flat and Gouraud shaded. Gouraud's interpolated intensity is "
        "continuous across an edge but its slope is not; the eye exaggerates the change of "
        "slope, and light or dark stripes (Mach bands) appear along the edges. Right: the "
        "stored intensity along the middle scan line of the Gouraud picture, straight "
        "pieces meeting at the edges (scaled to the plot's height).", "Hearn & Baker, section 14-5",
        side_by_side(panels + [plot.to_pil()], ["flat", "Gouraud", "scan line 100"]),
        f"slope changes along scan line 100 of the Gouraud picture: {kinks} pixels")


def figure_depth_cue():
    """A row of spheres receding, without and with depth cueing."""
    balls = [sl.mesh.sphere(0.6, center=(-1.0 + 1.2 * i, 0, -2.5 * i), resolution=(20, 10))
             for i in range(6)]
    cam = sl.Camera(eye=(2.6, 1.2, 5.5), target=(0.4, 0, -5),
                    projection=sl.projection.perspective(fov=math.radians(45), near=1, far=40))
    mat = sl.lighting.Material(color=(70, 120, 200), ks=0.4, shininess=25)
    panels = []
    for cue in (None, (1.0, 0.2)):
        fb = sl.FrameBuffer(300, 200, background="black")
        sl.render(fb, balls, cam, shading="phong", materials=mat, depth_cue=cue)
        panels.append(fb.to_pil())
    return Figure(
        "shading-depth-cue", "Depth cueing",
        "Six spheres, each farther away. Right: each pixel's intensity blended toward the "
        "background (black) with its distance, factor 1.0 at the nearest visible point and "
        "0.2 at the farthest (sl.render(..., depth_cue=(1.0, 0.2))).",
        "Hearn & Baker, sections 9-1 and 14-2", side_by_side(panels, ["no cue", "depth cued"]),
        None)


def figure_back_faces():
    """The back-face test: which faces are culled, and the picture without them."""
    from scanline.screen import prepare

    pot = _teapot(6)
    cam = _camera()
    size = (260, 200)
    scene = prepare(pot, cam, *size, cull_back_faces=True)
    back = scene.world[scene.culled]
    back_mesh = sl.mesh.Mesh(back.reshape(-1, 3), np.arange(3 * len(back)).reshape(-1, 3))
    fb1 = sl.FrameBuffer(*size, background=PAPER)
    sl.render(fb1, pot, cam, shading="gouraud", cull_back_faces=True)
    fb2 = sl.FrameBuffer(*size, background=PAPER)
    sl.draw3d.wireframe(fb2, back_mesh, cam, color="#e15759")
    fb3 = sl.FrameBuffer(*size, background=PAPER)
    sl.render(fb3, pot, cam, shading="gouraud", cull_back_faces=True)
    sl.draw3d.wireframe(fb3, back_mesh, cam, color="#e15759")
    total = scene.facet_count
    return Figure(
        "shading-back-faces", "Back-face culling with the culled faces shown",
        f"The back-face test V . N > 0 in viewing coordinates marks {int(scene.culled.sum())} "
        f"of the teapot's {total} triangles as facing away from the viewer; culling drops them "
        "before the z-buffer runs. Left: the picture with them culled (nothing changes for a "
        "closed surface); middle: the culled faces alone, in red; right: both, the culled "
        "faces drawn over the picture.", "Hearn & Baker, section 13-2",
        side_by_side([fb1.to_pil(), fb2.to_pil(), fb3.to_pil()],
                     ["culled", "the culled faces", "both"]),
        f"triangles: {total}, culled: {int(scene.culled.sum())}, kept: "
        f"{total - int(scene.culled.sum())}")


def figure_light_types():
    """Ambient, directional, point and spot light on one scene."""
    floor = sl.mesh.Mesh([(-3, -1, -3), (3, -1, -3), (3, -1, 3), (-3, -1, 3)], [(3, 2, 1, 0)])
    ball = sl.mesh.sphere(0.9, center=(0, 0, 0), resolution=(28, 14))
    cam = sl.Camera(eye=(0, 2.2, 6), target=(0, -0.3, 0),
                    projection=sl.projection.perspective(fov=math.radians(40), near=1))
    mats = [sl.lighting.Material(ka=0.3, kd=0.7, ks=0.0, color=(200, 200, 190)),
            sl.lighting.Material(ka=0.3, kd=0.6, ks=0.5, shininess=40, color=(200, 70, 60))]
    amb = sl.lighting.AmbientLight(0.15)
    setups = [
        ("ambient only", [sl.lighting.AmbientLight(0.8)]),
        ("directional", [amb, sl.lighting.DirectionalLight((0.5, -1, -0.4), 0.9)]),
        ("point, attenuated", [amb, sl.lighting.PointLight((1.5, 0.6, 1.2), 1.0,
                                                           attenuation=(0.3, 0.2, 0.3))]),
        ("spot, 25 degrees", [amb, sl.lighting.SpotLight((0, 3.5, 1.5), (0, -1, -0.45), 1.0,
                                                         angle=math.radians(25), exponent=4)]),
    ]
    panels = []
    for _, lights in setups:
        fb = sl.FrameBuffer(220, 170, background=PAPER)
        sl.render(fb, [floor, ball], cam, shading="phong", lights=lights, materials=mats)
        panels.append(fb.to_pil())
    return Figure(
        "shading-lights", "Kinds of light",
        "A ball on a floor, Phong-shaded, under each kind of source: ambient light only (no "
        "shape is seen); a directional light (parallel rays, no attenuation); a point light "
        "with f(d) = 1 / (0.3 + 0.2 d + 0.3 d^2); a spotlight whose cone of 25 degrees "
        "falls off as cos^4 of the angle off its axis (Warn).",
        "Hearn & Baker, sections 14-1 and 14-2",
        stacked([side_by_side(panels[:2], [s[0] for s in setups[:2]]),
                 side_by_side(panels[2:], [s[0] for s in setups[2:]])]), None)


FIGURES = (figure_teapot_shading, figure_mach_bands, figure_depth_cue, figure_back_faces,
           figure_light_types)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
