"""
Rotations with quaternions
==========================

Demo figure for rotations with quaternions (Hearn & Baker, section 11-2; Shoemake
1985): the in-betweens of two key orientations by linear interpolation of Euler
angles and by quaternion slerp, and the path each gives the teapot's spout."""

import math

import numpy as np

import scanline as sl

from scanline.gallery._plot import side_by_side, stacked
from scanline.gallery.primitives import HIGHLIGHT, PAPER, PIXEL, Figure

#: The key orientations, as Euler angles (scipy's extrinsic "xyz", degrees).
START, END = (0.0, 0.0, 0.0), (160.0, 70.0, 110.0)
#: In-betweens shown between the keys.
INBETWEENS = 8

def orientations(steps=INBETWEENS + 2):
    """(Euler-angle orientations, slerp orientations) at ``steps`` evenly spaced times
    from the first key to the second: lists of Quaternions."""
    Q = sl.transform3d.Quaternion
    angles = sl.animation.KeyFrames([0, 1], [START, END])
    keys = sl.animation.RotationKeyFrames([0, 1], [Q.from_euler("xyz", [math.radians(a)
                                                                      for a in START]),
                                                   Q.from_euler("xyz", [math.radians(a)
                                                                      for a in END])])
    times = np.linspace(0, 1, steps)
    euler = [Q.from_euler("xyz", np.radians(angles(t)).tolist()) for t in times]
    return euler, [keys(t) for t in times]


def _body():
    """The Utah teapot, centered: its spout and handle show which way it faces."""
    pot = sl.mesh.teapot(4)
    return pot.transformed(sl.transform3d.translation(0, 0, -1.2))


def _camera():
    return sl.Camera(eye=(6.5, -8.5, 5.0), target=(0, 0, 0), up=(0, 0, 1),
                     projection=sl.projection.perspective(fov=math.radians(36), near=1.0))


def strip(rotations, size=96):
    """The teapot at each orientation, side by side (one Pillow image)."""
    body, cam = _body(), _camera()
    lights = [sl.lighting.AmbientLight(0.3), sl.lighting.DirectionalLight((-0.3, 0.6, -1), 0.8)]
    material = sl.lighting.Material(color="#2b4c8c", ks=0.3, shininess=20)
    frames = []
    for q in rotations:
        fb = sl.FrameBuffer(size, size, background=PAPER)
        sl.render(fb, body.transformed(q.matrix()), cam, lights=lights, materials=material)
        frames.append(fb.to_pil())
    return side_by_side(frames, [""] * len(frames), gap=2)


#: The tip of the spout (the teapot's +x end) before the rotation, centered as _body.
SPOUT = (3.0, 0.0, 1.2)


def paths_panel(size=280, samples=160):
    """The path of the spout's tip: Euler angles (orange) and slerp (blue), with dots at
    the in-betweens of the strips."""
    cam = _camera()
    fb = sl.FrameBuffer(size, size, background=PAPER)
    radius = float(np.linalg.norm(SPOUT))
    sl.draw3d.wireframe(fb, sl.mesh.sphere(radius, resolution=(24, 12)), cam, color="#d0d4dc")
    fine = orientations(samples)
    dots = orientations()
    for k, color in ((0, HIGHLIGHT), (1, PIXEL)):
        tips = np.array([q.rotate(SPOUT) for q in fine[k]])
        sl.draw3d.polylines(fb, [tips], cam, color=color, width=3)
        marks = cam.project(np.array([q.rotate(SPOUT) for q in dots[k]]), size, size)
        for x, y in marks[:, :2]:
            sl.draw.fill_circle(fb, x, y, 4, color=color)
    return fb.to_pil()


def figure_euler_and_slerp():
    """Euler-angle in-betweens against quaternion slerp."""
    euler, slerp = orientations()
    rows = stacked([side_by_side([strip(euler)], ["Euler angles (x, y, z) interpolated"]),
                    side_by_side([strip(slerp)], ["quaternion slerp"])], gap=8)
    return Figure(
        "quaternion-inbetweens", "In-betweens of orientation: Euler angles and quaternions",
        f"Two key orientations (Euler angles {START} and {END} degrees, extrinsic x, y, z) and "
        f"{INBETWEENS} in-betweens each way. Interpolating the three angles one by one swings "
        "the teapot on a detour at a changing rate; slerp of the unit quaternions turns it "
        "about one fixed axis at a constant rate, by the smallest angle. Right: the path of "
        "the spout's tip (orange: Euler angles, blue: slerp, a circle about the rotation "
        "axis), dots at the in-betweens: evenly spaced for slerp only.",
        "Hearn & Baker, section 11-2; Shoemake 1985",
        side_by_side([rows, paths_panel()], ["", "path of the spout"], gap=16), None)


FIGURES = (figure_euler_and_slerp,)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
