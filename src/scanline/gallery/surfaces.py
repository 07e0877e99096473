"""
Surfaces
========

Demo figures for surfaces and curve rasterization: the Utah teapot as a wireframe,
a bicubic patch over its control net, and adaptive flattening."""

import numpy as np

import scanline as sl

from scanline.curves.flatten import flatten
from scanline.gallery._plot import enlarge, side_by_side
from scanline.gallery.primitives import PAPER, PIXEL, HIGHLIGHT, Figure

LIGHT = "#c8cdd8"


def _camera(target, window):
    """An orthographic camera from above the +x, -y quadrant, z up (the teapot stands
    on z = 0)."""
    return sl.Camera(eye=np.asarray(target) + (6.0, -9.5, 7.0), target=target, up=(0, 0, 1),
                     projection=sl.projection.orthographic(window=window))


def figure_teapot():
    """The Utah teapot tessellated and drawn as a wireframe."""
    pot = sl.mesh.teapot(6)
    cam = _camera((0.2, 0.0, 1.5), (-3.6, -2.6, 3.6, 2.6))
    size = 360, 272
    fb = sl.FrameBuffer(*size, background=PAPER)
    p = cam.project(pot.vertices, *size)[:, :2]
    tris = pot.faces
    a, b, c = p[tris[:, 0]], p[tris[:, 1]], p[tris[:, 2]]
    u, w = b - a, c - a
    facing = u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0] > 0   # counterclockwise on screen: front face
    for front, color in ((False, LIGHT), (True, PIXEL)):
        sl.draw3d.wireframe(fb, sl.mesh.Mesh(pot.vertices, tris[facing == front]), cam,
                            color=color)
    return Figure(
        "teapot", "The Utah teapot, 32 bicubic Bezier patches",
        f"Newell's teapot (1975): 32 patches, 306 control points, tessellated 6 x 6 per "
        f"patch and welded into {len(pot.vertices)} vertices and {len(pot)} triangles "
        "(sl.mesh.teapot), drawn through an orthographic sl.Camera. Triangles facing the "
        "viewer (counterclockwise on screen: the mesh's normals point outward) are blue, "
        "the others light gray.",
        "Notes, chapter 5, Q.1 (Bezier surfaces); Crow 1987", fb.to_pil(), None)


def figure_bicubic_patch():
    """A bicubic Bezier patch: its isoparametric curves over its control net."""
    g = np.arange(4.0)
    x, y = np.meshgrid(g, g, indexing="ij")
    z = np.array([[0, 1, 1, 0], [1, 3, 2.5, 0.5], [0.5, 2, 3, 1], [0, 0.5, 1, 0]]) * 0.6
    net = np.stack([x, y, z], axis=-1)
    # a parallel projection is affine: the projected control points are the control
    # points of the projected curves
    cam = sl.Camera(eye=(6.5, -5.0, 9.0), target=(1.5, 1.5, 1.0), up=(0, 0, 1),
                    projection=sl.projection.orthographic(window=(-3.0, -2.4, 3.0, 2.4)))
    size = (300, 240)
    p = cam.project(net.reshape(-1, 3), *size)[:, :2].reshape(4, 4, 2)
    fb = sl.FrameBuffer(*size, background=PAPER)
    rows = [p[i] for i in range(4)] + [p[:, j] for j in range(4)]
    sl.draw.polylines(fb, rows, color=HIGHLIGHT, dash="dashed")
    iso = []
    for t in np.linspace(0, 1, 9):   # P(t, v): the Bezier curve of sum_i B_i(t) P_ij
        b = sl.curves.bernstein(3, t)
        iso.append(sl.curves.Bezier(np.einsum("i,ijc->jc", b, p)))
        iso.append(sl.curves.Bezier(np.einsum("j,ijc->ic", b, p)))
    sl.draw.curves(fb, iso, color=PIXEL)
    sl.draw.circles(fb, np.hstack([p.reshape(-1, 2), np.full((16, 1), 2)]), color=HIGHLIGHT)
    return Figure(
        "bicubic-patch", "A bicubic Bezier patch and its control net",
        "The patch P(u, v) = sum P_ij BEZ_i,3(u) BEZ_j,3(v) (blue: the curves u = const "
        "and v = const, each a cubic Bezier curve flattened within a quarter pixel by "
        "sl.draw.curves) over its 4 x 4 control net (orange, dashed). The patch "
        "interpolates the four corner points and stays in the net's convex hull.",
        "Notes, chapter 5, Q.1, eq. 10", fb.to_pil(), None)


def figure_flattening():
    """Adaptive flattening of a cubic at two tolerances."""
    curve = sl.curves.Bezier([(2, 2), (40, 46), (-6, 40), (44, 4)])
    panels, titles = [], []
    for tol in (2.0, 0.25):
        fb = sl.FrameBuffer(48, 48, background=PAPER)
        sl.draw.curve(fb, curve, color=PIXEL, tolerance=tol)
        points = flatten(curve, tol)
        for x, y in np.floor(points + 0.5).astype(int):
            fb.set_pixel(int(x), int(y), HIGHLIGHT)
        panels.append(enlarge(fb.to_pil(), 6))
        titles.append(f"tolerance {tol:g}: {len(points)} points")
    return Figure(
        "flattening", "Adaptive flattening of a Bezier curve",
        "de Casteljau subdivision at u = 1/2 until every control point is within the "
        "tolerance of its piece's chord; the convex hull property then keeps the whole "
        "curve within the tolerance of the polyline. Orange: the polyline's vertices "
        "(points of the curve); blue: its Bresenham pixels.",
        "Notes, chapter 5, Q.1 (convex hull property)", side_by_side(panels, titles), None)


FIGURES = (figure_teapot, figure_bicubic_patch, figure_flattening)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
