"""
Blobby objects
==============

Demo figure for blobby objects (Hearn & Baker, section 10-7): two soft objects
(Wyvill et al. 1986) drawn together until they merge, each frame the iso-surface of
the summed densities extracted by marching cubes; and the same as a short GIF
(:data:`ANIMATIONS`)."""

import math

import numpy as np

import scanline as sl

from scanline.gallery._plot import side_by_side
from scanline.gallery.primitives import PAPER, Figure

#: Half the distance between the two centers at each frame of the strip.
STRIP = (1.3, 1.05, 0.9, 0.8, 0.7, 0.55, 0.35)


def blobs(half, kind="soft", resolution=40):
    """The two blobs (radius 1.6, threshold 0.5) with centers at x = +-``half``."""
    return sl.mesh.blobby([(-half, 0, 0), (half, 0, 0)], [1.6, 1.6], threshold=0.5,
                          resolution=resolution, kind=kind)


def frame(half, width=150, height=110):
    """One blobby frame, Phong-shaded (a FrameBuffer)."""
    cam = sl.Camera(eye=(0.0, -5.2, 2.2), target=(0, 0, 0), up=(0, 0, 1),
                    projection=sl.projection.perspective(fov=math.radians(42), near=0.5))
    fb = sl.FrameBuffer(width, height, background=PAPER)
    material = sl.lighting.Material(color="#c0392b", ks=0.5, shininess=40)
    sl.render(fb, blobs(half), cam, shading="phong", materials=material,
              lights=[sl.lighting.AmbientLight(0.3),
                      sl.lighting.DirectionalLight((-0.4, 0.8, -0.6), 0.8)])
    return fb


def figure_blobby_merge():
    """Two soft objects merging."""
    frames = [frame(h).to_pil() for h in STRIP]
    titles = [f"d = {2 * h:.1f}" for h in STRIP]
    return Figure(
        "blobby-merge", "Blobby objects: two soft objects merging",
        "Two soft objects of radius R = 1.6 (Wyvill's density 1 - 22/9 s² + 17/9 s⁴ - 4/9 s⁶, "
        "s = r / R) with centers a distance d apart; the surface is where the summed density "
        "is 0.5, extracted by marching cubes on a 40-sample grid. Far apart each is the "
        "sphere of radius R / 2; as they approach, a neck grows between them and they "
        "flow into one surface.", "Hearn & Baker, section 10-7; Wyvill, McPheeters & "
        "Wyvill 1986", side_by_side(frames, titles, gap=6), None)


FIGURES = (figure_blobby_merge,)


def animation_blobby_merge():
    """A GIF: two blobs approaching, merging and parting."""
    count = 24
    halves = 0.35 + 1.0 * (0.5 + 0.5 * np.cos(np.linspace(0, 2 * np.pi, count, endpoint=False)))
    return "blobby-merge", sl.animation.Animation(lambda i: frame(float(halves[i])),
                                                  frames=count, fps=12)


#: Short GIFs the demo writes beside the figures: functions returning (name, Animation).
ANIMATIONS = (animation_blobby_merge,)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES, ANIMATIONS)
