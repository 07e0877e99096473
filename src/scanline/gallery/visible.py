"""
Visible-surface detection
=========================

Demo figures for visible-surface and visible-line detection (Hearn & Baker,
chapter 13): the painter's one-key sort failing where depth sorting succeeds, the
scene by every method, a floating-horizon plot and a hidden-line wireframe.  Every
picture is drawn by :mod:`scanline.visible` and :func:`scanline.draw3d.floating_horizon`;
labels are Pillow text."""

import math
import time

import numpy as np

import scanline as sl

from scanline.gallery._plot import side_by_side, stacked
from scanline.gallery.primitives import PAPER, PIXEL, Figure

SHADES = ["#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f", "#edc948"]


def _sticks():
    """Three flat bars lying across each other cyclically (each over the next), a
    long bar pierced by a plate."""
    bars = []
    for k in range(3):
        a = 2 * math.pi * k / 3
        c, s = math.cos(a), math.sin(a)
        tilt = 0.35
        m = np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
        # a thin bar along x, its far end raised: it passes over the next bar's near end
        bar = sl.mesh.Mesh([(-1.6, -0.22, -tilt), (1.6, -0.22, tilt), (1.6, 0.22, tilt),
                            (-1.6, 0.22, -tilt)], [[0, 1, 2, 3]])
        bars.append(bar.transformed(m @ np.array([[1, 0, 0, 0], [0, 1, 0, 0.55],
                                                  [0, 0, 1, 0], [0, 0, 0, 1]])))
    return bars


def figure_painter_failure():
    """One key per polygon (painter) against depth sorting on cyclic bars."""
    bars = _sticks()
    cam = sl.Camera(eye=(0, 0, 6), target=(0, 0, 0),
                    projection=sl.projection.orthographic(window=(-2.2, -2.2, 2.2, 2.2)))
    panels, notes = [], []
    for method in ("painter", "depth-sort"):
        fb = sl.FrameBuffer(260, 260, background=PAPER)
        out = sl.render(fb, bars, cam, method=method, shading="none", colors=SHADES[:3])
        sl.draw3d.wireframe(fb, bars, cam, color="black")
        panels.append(fb.to_pil())
        notes.append(f"{method}: {len(out.pieces)} pieces drawn")
    image = side_by_side(panels, ["painter (one key each)", "depth sort (tests, split)"])
    return Figure(
        "visible-painter-failure", "The painter's one-key sort against depth sorting",
        "Three bars overlap cyclically: each lies over the next. Sorting whole polygons by "
        "their greatest depth (what matplotlib and manim do) must paint one bar entirely "
        "last, so it covers both others. Depth sorting runs the five overlap tests, finds "
        "the cycle by the flag of the moved polygon and splits a bar by another's plane; "
        "the pieces then have an order.", "Hearn & Baker, section 13-6", image,
        "\n".join(notes))


def _lit(meshes, bases, light=(0.4, 0.8, 0.6)):
    """One color per face: the mesh's base color scaled by 0.35 + 0.65 max(N.L, 0)
    (Lambert, so that the facets can be told apart)."""
    rgb = [tuple(int(bases[i][k:k + 2], 16) for k in (1, 3, 5)) for i in range(len(meshes))]
    out = []
    el = np.array(light) / np.linalg.norm(light)
    for m, base in zip(meshes, rgb):
        n = m.face_normals()
        f = 0.35 + 0.65 * np.clip(n @ el / np.linalg.norm(n, axis=1), 0, 1)
        out += [tuple(int(round(c * k)) for c in base) for k in f]
    return out


def figure_methods():
    """The same scene by every method, with timings."""
    meshes = [sl.mesh.cube(1.4), sl.mesh.sphere(0.75, (0.7, 0.55, 0.6), resolution=12),
              sl.mesh.torus(0.9, 0.2, (-0.2, -0.1, 0.2), resolution=(18, 8))]
    cam = sl.Camera(eye=(3.5, 2.5, 4.5), target=(0, 0, 0),
                    projection=sl.projection.perspective(fov=0.42, near=1))
    panels, titles, rows = [], [], []
    colors = _lit(meshes, SHADES[:3])
    for method in sl.visible.METHODS:
        fb = sl.FrameBuffer(170, 140, background=PAPER)
        t = time.perf_counter()
        sl.render(fb, meshes, cam, method=method, shading="none", colors=colors)
        rows.append(f"{method:17s} {1000 * (time.perf_counter() - t):8.1f} ms")
        panels.append(fb.to_pil())
        titles.append(method)
    half = (len(panels) + 1) // 2
    image = stacked([side_by_side(panels[:half], titles[:half]),
                     side_by_side(panels[half:], titles[half:])])
    return Figure(
        "visible-methods", "One scene by every visible-surface method",
        "A cube pierced by a sphere and a torus, each face one color, by every method of "
        "sl.render: painter (one key per polygon) gets the intersections wrong; depth sort "
        "and BSP split polygons and agree pixel for pixel with the z-buffer, ray casting, "
        "the scan-line method and area subdivision; the A-buffer smooths the edges. Times "
        "include the first call's interpretation or compilation.",
        "Hearn & Baker, sections 13-3 to 13-10",
        image, "\n".join(rows))


def figure_floating_horizon():
    """The sombrero function by the floating horizon."""
    fb = sl.FrameBuffer(520, 360, background=PAPER)

    def sombrero(x, y):
        r = np.hypot(x, y) * 9
        return np.where(r == 0, 1.0, np.sin(r) / np.where(r == 0, 1, r))

    h = sl.draw3d.floating_horizon(fb, sombrero, x=np.linspace(-1, 1, 121),
                                   y=np.linspace(-1, 1, 61), camera_or_angles=(0.45, 0.5),
                                   color=PIXEL)
    return Figure(
        "visible-floating-horizon", "The sombrero z = sin r / r by the floating horizon",
        "61 curves of constant y drawn nearest first; a curve is visible where it rises "
        "above the upper horizon or falls below the lower one (both kept per screen "
        "column), cut where it crosses them, and the side edges join each curve to the "
        "previous one.", "Rogers, Procedural Elements, section 4-2; Wright 1973",
        fb.to_pil(), f"{len(h.segments)} visible segments")


def figure_hidden_lines():
    """A torus and a cube: wireframe, hidden lines dashed, hidden lines removed."""
    meshes = [sl.mesh.torus(1.0, 0.35, resolution=(20, 10)), sl.mesh.cube(0.9)]
    cam = sl.Camera(eye=(2.5, 3.5, 3.0), target=(0, 0, 0),
                    projection=sl.projection.perspective(fov=0.8, near=1))
    panels = []
    fb = sl.FrameBuffer(220, 200, background=PAPER)
    sl.draw3d.wireframe(fb, meshes, cam, color=PIXEL)
    panels.append(fb.to_pil())
    for hidden in ("dash", "remove"):
        fb = sl.FrameBuffer(220, 200, background=PAPER)
        seen, unseen = sl.visible.visible_lines(fb, meshes, cam, color=PIXEL, hidden=hidden,
                                                hidden_color="#b0b0b0")
        panels.append(fb.to_pil())
    image = side_by_side(panels, ["wireframe", "hidden lines dashed", "hidden lines removed"])
    return Figure(
        "visible-hidden-lines", "Visible-line detection",
        "Each edge is compared with each face: the part inside the face's projection and "
        "behind its plane is hidden.", "Hearn & Baker, section 13-10", image,
        f"{len(seen)} visible parts, {len(unseen)} hidden parts")


FIGURES = (figure_painter_failure, figure_methods, figure_floating_horizon, figure_hidden_lines)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
