"""The A-buffer method (Hearn & Baker, section 13-4; Carpenter 1984): an image-space
method that keeps, for each pixel, a list of the surface fragments that reach it --
their depth, intensity, opacity and the part of the pixel each covers -- and
resolves the list front to back, so transparent surfaces show what is behind them
and edges are antialiased by their coverage.

Here each pixel is sampled at ``samples`` x ``samples`` points (the coverage mask of
Carpenter's fragments), and the fragment lists are gathered layer by layer by
depth peeling (Everitt 2001): the first layer is the z-buffer of the scene, each
next one the nearest fragment strictly behind the previous layer.  Peeling stops
after an opaque fragment at every sample, or after ``layers`` layers.  Then each
sample composites its fragments front to back, I = sum_k T_k (1 - k_t,k) I_k with
T_k the product of the transparencies k_t in front of it (Hearn & Baker, section
14-5: I = (1 - k_t) I_refl + k_t I_trans, applied repeatedly), over the background,
and each pixel averages its samples.
"""

import numpy as np

from .. import _validate as v
from ..depthbuffer import DepthBuffer
from ..draw.triangles import rasterize
from ..errors import ArgumentValueError
from ..shading import encode
from .output import Rendering, background_linear, cue, point_colors

SAMPLES = 3
LAYERS = 8


def render(scene, fb, options):
    """Draw ``scene`` into ``fb`` by the A-buffer method (``options``: ``samples``
    per pixel side, default 3; ``layers``, at most 8 by default)."""
    s = options.get("samples", SAMPLES)
    if not isinstance(s, int) or isinstance(s, bool) or not 1 <= s <= 8:
        raise ArgumentValueError(f"samples must be an integer in 1..8 (per pixel side), got "
                                 f"{v._show(s)}")
    layers = options.get("layers", LAYERS)
    if not isinstance(layers, int) or isinstance(layers, bool) or not 1 <= layers <= 64:
        raise ArgumentValueError(f"layers must be an integer in 1..64, got {v._show(layers)}")
    h, w = scene.height, scene.width
    hs, ws = h * s, w * s
    # sample (i, j) of pixel (x, y) is at (x - 1/2 + (i + 1/2)/s, ...): device * s + (s-1)/2
    tri = scene.triangles.copy()
    tri[..., :2] = tri[..., :2] * s + (s - 1) / 2.0
    tri = np.ascontiguousarray(tri)
    q = np.ascontiguousarray(scene.inv_w)
    att = np.ascontiguousarray(scene.bary)
    ids = np.ascontiguousarray(scene.face)
    kt = np.array([m.transparency for m in scene.materials])
    gamma = options["gamma"]
    background = background_linear(fb, gamma)
    color = np.zeros((hs, ws, 3))
    through = np.ones((hs, ws))                 # the product of k_t in front so far
    floor = np.full((hs, ws), -np.inf)
    first = None
    first_depth = None
    for _ in range(layers):
        faces = np.full((hs, ws), -1, np.int64)
        bary = np.zeros((hs, ws, 2))
        depth = np.full((hs, ws), np.inf)
        if len(tri):
            rasterize(ws, hs, tri, q, att, ids, zbuf=depth, abuf=bary, idbuf=faces,
                      floor=floor)
        live = (faces >= 0) & (through > 0)
        if first is None:
            first, first_depth = faces.copy(), depth.copy()
        if not live.any():
            break
        ys, xs = np.nonzero(live)
        f = faces[ys, xs]
        lin = cue(scene, point_colors(scene, f, bary[ys, xs], options), depth[ys, xs],
                  options, background)
        t = kt[scene.face_mesh[f]]
        color[ys, xs] += (through[ys, xs] * (1 - t))[:, None] * lin
        through[ys, xs] *= t
        floor = np.where(live, depth, np.inf)       # peel behind this layer
    color += through[..., None] * background
    pixel = color.reshape(h, s, w, s, 3).mean(axis=(1, 3))
    covered = (first >= 0).reshape(h, s, w, s).any(axis=(1, 3))
    ys, xs = np.nonzero(covered)
    buf = fb._raster()[0]
    lin = pixel[ys, xs]
    if fb.mode == "L":
        buf[ys, xs, 0] = encode((lin * np.array([0.299, 0.587, 0.114])).sum(axis=1), gamma)
    else:
        buf[ys, xs, :3] = encode(lin, gamma)
        if fb.mode == "RGBA":
            buf[ys, xs, 3] = 255
    # the depth and face of each pixel's central sample
    c = s // 2
    out = DepthBuffer(w, h)
    out.array[...] = first_depth[c::s, c::s]
    return Rendering("a-buffer", out, first[c::s, c::s].copy(), scene)
