"""The A-buffer method (Hearn & Baker, section 13-4; Carpenter 1984): an image-space
method that keeps, for each pixel, a list of the surface fragments that reach it --
their depth, opacity and the part of the pixel each covers -- so that the shading can
resolve the list front to back: transparent surfaces show what is behind them and
edges are antialiased by their coverage.

Here each pixel is sampled at ``samples`` x ``samples`` points (the coverage mask of
Carpenter's fragments), and the fragment lists are gathered layer by layer by depth
peeling (Everitt 2001): the first layer is the z-buffer of the scene, each next one
the nearest fragment strictly behind the previous layer.  A sample stops peeling once
it has met an opaque fragment, and the peeling stops when no sample has a fragment
left or after ``layers`` layers.  The layers are made one at a time, as the shading
consumes them (:func:`scanline.shading.composite`), band of rows after band of rows,
so memory stays that of a few supersampled buffers of one band whatever the frame's
size and its depth complexity.
"""

from collections.abc import Iterator
from typing import TYPE_CHECKING

import numpy as np

from .visibility import Fragments, Layer
from .zbuffer import nearest

if TYPE_CHECKING:
    from ..screen.scene import ScreenScene
    from .methods import MethodOptions

#: Default samples per pixel side, and most layers peeled.
SAMPLES = 3
LAYERS = 8
#: The supersampled buffers of a band of rows take at most about this many bytes
#: (:data:`SAMPLE_BYTES` a sample): the frame is resolved band after band, so that
#: any size is drawn in bounded memory.
BAND_BYTES = 64 << 20
#: Bytes a sample takes while a band is resolved: the layer's triangle and depth,
#: the peeling floor, the color and the transparency so far, and their temporaries.
SAMPLE_BYTES = 96


def band_rows(width: int, samples: int) -> int:
    """Rows of pixels a band holds: as many as :data:`BAND_BYTES` allows, at least
    one."""
    return max(1, BAND_BYTES // (SAMPLE_BYTES * width * samples * samples))


def _layers(scene: "ScreenScene", samples: int, limit: int, y0: int,
            rows: int) -> Iterator[Layer]:
    """The layers of fragments of the band of pixel rows ``y0 .. y0 + rows - 1``."""
    s = samples
    hs, ws = rows * s, scene.width * s
    # sample (i, j) of pixel (x, y) is at (x - 1/2 + (i + 1/2)/s, ...): device * s + (s-1)/2
    tri = scene.triangles.copy()
    tri[..., 0] = tri[..., 0] * s + (s - 1) / 2.0
    tri[..., 1] = (tri[..., 1] - y0) * s + (s - 1) / 2.0
    ys = tri[..., 1]
    select = np.flatnonzero((ys.max(axis=1) >= -1.0) & (ys.min(axis=1) <= hs))
    opaque = ~scene.transparent
    floor = np.full((hs, ws), -np.inf)
    blocked = np.zeros((hs, ws), bool)
    for _ in range(limit):
        depth = np.full((hs, ws), np.inf)
        layer = nearest(scene, zbuf=depth, floor=floor, triangles=tri, size=(ws, hs),
                        select=select)
        live = (layer.ids >= 0) & ~blocked
        if not live.any():
            return
        ids = np.where(live, layer.ids, -1)
        yield Layer(ids, np.where(live, depth, np.inf))
        blocked |= live & opaque[scene.facet[np.maximum(ids, 0)]]
        floor = np.where(live, depth, np.inf)       # peel behind this layer


def abuffer(scene: "ScreenScene", options: "MethodOptions") -> Fragments:
    """The fragments at every sample, front to back (``options.samples`` per pixel
    side, at most ``options.layers`` layers), band after band of rows
    (:func:`band_rows`)."""
    samples = SAMPLES if options.samples is None else options.samples
    layers = LAYERS if options.layers is None else options.layers
    rows = band_rows(scene.width, samples)
    bands = ((y0, min(rows, scene.height - y0),
              _layers(scene, samples, layers, y0, min(rows, scene.height - y0)))
             for y0 in range(0, scene.height, rows))
    return Fragments(samples, bands)
