"""The depth-buffer (z-buffer) method (Hearn & Baker, section 13-3; Catmull 1974):
an image-space method ("image precision": visibility is decided at each pixel).

Two buffers: the depth buffer, cleared to infinity, and the refresh buffer, cleared
to the background.  Each surface is scan-converted; at each pixel (x, y) it covers,
its depth z is computed (incrementally along the scan line, z' = z - A/C) and, if z
< depth(x, y), depth(x, y) = z and the pixel takes the surface's intensity.  Here the
"intensity" written is the face index and the barycentric coordinates of the point
(a visibility buffer), shaded once per pixel afterwards, so a covered-over fragment
costs no lighting.  Where the compiled shading draws the whole (opaque) scene, the
intensity written is the triangle's index alone (:func:`visible_triangles`), and the
shading finds the barycentrics from the triangle itself.

Simple transparency (Hearn & Baker, section 14-5): opaque faces first; then the
nearest transparent face in front of them at each pixel, blended I = (1 - k_t)
I_refl + k_t I_behind (one transparent layer; method="a-buffer" composites any
number).
"""

import threading

import numpy as np

from ..depthbuffer import DepthBuffer
from ..draw.triangles import rasterize
from ..shading.buffer import drawable, shade_buffer
from .output import Rendering, background_linear, cue, point_colors, store, write_visible


_SCRATCH = threading.local()


def scratch_bary(height, width):
    """A barycentric buffer (H, W, 2) kept for the calling thread and reused by its
    next render of the same size: a new 33 MB buffer (1920 x 1080) costs several
    milliseconds of page zeroing on every call."""
    kept = getattr(_SCRATCH, "bary", None)
    if kept is None or kept.shape != (height, width, 2):
        kept = _SCRATCH.bary = np.empty((height, width, 2))
    return kept


def visibility(scene, select=None, zbuf=None, bary=None):
    """The z-buffer pass over the scene's triangles (those where ``select``, a
    boolean mask over them, holds): ``(faces, bary, depth)`` arrays (H, W); ``bary``
    (a new array unless given) is set where ``faces`` >= 0 only.  ``zbuf``: the depth
    buffer to test against (default a new one, cleared to +inf)."""
    h, w = scene.height, scene.width
    clear = zbuf is None
    faces = np.empty((h, w), np.int64) if clear else np.full((h, w), -1, np.int64)
    bary = np.empty((h, w, 2)) if bary is None else bary
    depth = np.empty((h, w)) if clear else zbuf
    tri, q, att, ids = scene.triangles, scene.inv_w, scene.bary, scene.face
    if select is not None:
        tri, q, att, ids = tri[select], q[select], att[select], ids[select]
    if len(tri):
        rasterize(w, h, np.ascontiguousarray(tri), np.ascontiguousarray(q),
                  np.ascontiguousarray(att), np.ascontiguousarray(ids), zbuf=depth,
                  abuf=bary, idbuf=faces, clear=clear)
    elif clear:
        faces.fill(-1)
        depth.fill(np.inf)
    return faces, bary, depth


def visible_triangles(scene):
    """The z-buffer pass over all the scene's triangles writing each visible one's
    index alone: ``(ids, depth)``, ``ids`` (H, W) int64 the triangle seen at each
    pixel (-1: none).  The barycentrics of a pixel are found where it is shaded
    (:func:`scanline.shading.buffer.shade_buffer` with ``triangles=True``), once,
    instead of at every fragment drawn."""
    from .pool import recycled

    h, w = scene.height, scene.width
    ids = recycled("faces", (h, w), np.int64)
    depth = recycled("depth", (h, w))
    n = len(scene.triangles)
    if n:
        rasterize(w, h, np.ascontiguousarray(scene.triangles),
                  np.ascontiguousarray(scene.inv_w), np.empty((n, 3, 0)),
                  np.arange(n, dtype=np.int64), zbuf=depth, idbuf=ids, clear=True)
    else:
        ids.fill(-1)
        depth.fill(np.inf)
    return ids, depth


def transparent_triangles(scene):
    """Per triangle: True when its material lets light through."""
    kt = np.array([m.transparency for m in scene.materials])
    return kt[scene.face_mesh[scene.face]] > 0 if len(scene.face) else np.zeros(0, bool)


def render(scene, fb, options):
    """Draw ``scene`` into ``fb`` by the depth-buffer method."""
    clear = transparent_triangles(scene)
    if not clear.any() and drawable(fb, options):
        faces, depth = visible_triangles(scene)
        shade_buffer(scene, fb, faces, None, options, triangles=True)
    elif not clear.any():
        faces, bary, depth = visibility(scene, bary=scratch_bary(scene.height, scene.width))
        write_visible(scene, fb, faces, bary, depth, options)
    else:
        faces, bary, depth = visibility(scene, ~clear)
        write_visible(scene, fb, faces, bary, depth, options)
        front = depth.copy()
        tf, tb, td = visibility(scene, clear, front)
        ys, xs = np.nonzero(tf >= 0)
        f = tf[ys, xs]
        gamma = options["gamma"]
        background = background_linear(fb, gamma)
        from ..shading import decode

        stored = fb._raster()[0][ys, xs].astype(np.float64) / 255.0
        if stored.shape[1] == 1:
            stored = np.repeat(stored, 3, axis=1)
        behind = decode(stored[:, :3], gamma)
        refl = cue(scene, point_colors(scene, f, tb[ys, xs], options), td[ys, xs], options,
                   background)
        kt = np.array([m.transparency for m in scene.materials])[scene.face_mesh[f]]
        store(fb, ys, xs, (1 - kt)[:, None] * refl + kt[:, None] * behind, gamma)
        faces = np.where(tf >= 0, tf, faces)
        np.minimum(depth, td, out=depth)
    return Rendering("z-buffer", DepthBuffer.holding(depth), faces, scene)
