"""Turning visible points into pixels: shading, simple transparency, depth cueing and
the gamma encoding, shared by every visible-surface method."""

from dataclasses import dataclass

import numpy as np

from ..lighting.model import depth_cue as cue_blend
from ..shading import decode, encode, shade
from ..shading.buffer import drawable, shade_buffer


@dataclass
class Rendering:
    """What :func:`scanline.render` drew.

    Attributes
    ----------
    method : str
    depth : DepthBuffer
        The depth of the visible surface at each pixel (inf where none).
    faces : ndarray of int64 (H, W)
        The visible face at each pixel (-1: background), rows bottom-up like the
        depth buffer's array (``faces[y, x]``).
    scene : ScreenScene
    """
    method: str
    depth: object
    faces: np.ndarray
    scene: object

    def face_image(self):
        """``faces`` in image order (top row first)."""
        return self.faces[::-1].copy()


def background_linear(fb, gamma):
    """The frame buffer's background as linear RGB."""
    value = np.asarray(fb._background, np.float64)
    c = np.repeat(value[:1], 3) if len(value) == 1 else value[:3]
    return decode(c / 255.0, gamma)


def point_colors(scene, faces, bary, options):
    """Linear RGB of points of ``faces`` at barycentrics ``bary`` (M, 2)."""
    return shade(scene, faces, bary, options["lights"], options["shading"],
                 options["specular"], options["gamma"], options.get("shadows"))


def cue(scene, linear, depth, options, background):
    """Depth cueing of linear colors at device depths ``depth`` (M,)."""
    intensities = options.get("depth_cue")
    if intensities is None or not len(depth):
        return linear
    d = scene.camera.linear_depth(depth)
    return cue_blend(linear, d, float(d.min()), float(d.max()), intensities, background)


def store(fb, ys, xs, linear, gamma):
    """Write linear RGB (M, 3) at pixels (xs, ys), encoded with ``gamma``."""
    buf = fb._raster()[0]
    rgb = encode(linear, gamma)
    if fb.mode == "L":
        lum = encode((linear * np.array([0.299, 0.587, 0.114])).sum(axis=1), gamma)
        buf[ys, xs, 0] = lum
    else:
        buf[ys, xs, :3] = rgb
        if fb.mode == "RGBA":
            buf[ys, xs, 3] = 255


def write_visible(scene, fb, faces, bary, depth, options):
    """Shade the pixels whose visible face ``faces[y, x]`` (-1 none) is known, with
    barycentrics ``bary[y, x]`` and depth ``depth[y, x]``, into ``fb``: compiled
    (:mod:`scanline.shading.buffer`) where it can be, else with numpy."""
    if drawable(fb, options):
        shade_buffer(scene, fb, faces, bary, options)
        return
    ys, xs = np.nonzero(faces >= 0)
    f = faces[ys, xs]
    linear = point_colors(scene, f, bary[ys, xs], options)
    background = background_linear(fb, options["gamma"])
    linear = cue(scene, linear, depth[ys, xs], options, background)
    store(fb, ys, xs, linear, options["gamma"])
