"""Drawing screen-space pieces of faces in a given order, without a depth test: how
the object-order methods (painter's sort, depth sort, BSP trees) put their result
on the screen, with any shading.

A piece is a convex polygon lying in the plane of its source face (a face, or a part
of it that a method split off).  Its pixels take the attributes of the face at that
point: the barycentric coordinates of each piece vertex in its face are found from
the face's screen-space interpolation functions (of one of the face's device
triangles, which all share them), so a piece shades exactly as the whole face would.
"""

import numpy as np

from .. import _validate as v
from ..errors import ArgumentValueError
from ..draw.triangles import rasterize
from .output import write_visible


def face_functions(scene):
    """Per face: the screen-space linear functions (value at the origin, d/dx, d/dy)
    of 1/w, lambda_1/w and lambda_2/w, from the first device triangle of the face;
    NaN for faces without one (or whose first triangle has no area on screen)."""
    f = np.full((scene.face_count, 3, 3), np.nan)
    faces, first = np.unique(np.asarray(scene.face, np.int64), return_index=True)
    if not len(faces):
        return f
    x, y = scene.triangles[first, :, 0], scene.triangles[first, :, 1]
    q = scene.inv_w[first]
    vals = np.stack([q, scene.bary[first, :, 0] * q, scene.bary[first, :, 1] * q], 1)
    m = np.stack([np.ones_like(x), x, y], axis=2)                 # (F, 3 vertices, 3)
    solvable = np.abs(np.linalg.det(m)) > 1e-12 * (np.abs(m).max(axis=(1, 2)) ** 2 + 1.0)
    c = np.linalg.solve(m[solvable], vals[solvable].transpose(0, 2, 1))  # (F, c a b, fn)
    f[faces[solvable]] = c.transpose(0, 2, 1)
    return f


def _flat(pieces, faces):
    """``pieces`` (a :class:`~scanline.visible.ScreenPolygons`, or a list of (k, 2+)
    device polygons) as flat x, y (V, 2) and offsets, with their ``faces``; list
    entries that are not polygons are dropped with their faces."""
    from ..visible import ScreenPolygons

    if isinstance(pieces, ScreenPolygons):
        return pieces.vertices[:, :2], pieces.offsets, faces
    keep, parts = [], []
    for i, piece in enumerate(pieces):
        p = v.real_array("pieces", piece, "(k, 2+)")
        if p.ndim == 2 and p.shape[1] >= 2 and len(p) >= 3:
            keep.append(i)
            parts.append(p[:, :2])
    offsets = np.zeros(len(parts) + 1, np.int64)
    np.cumsum([len(p) for p in parts], out=offsets[1:])
    xy = np.concatenate(parts) if parts else np.empty((0, 2))
    return xy, offsets, faces[np.array(keep, np.int64)]


def draw_pieces(scene, fb, pieces, faces, options):
    """Draw ``pieces`` (:class:`~scanline.visible.ScreenPolygons`, or a list of (k, 2+)
    device polygons, x and y first) of source ``faces`` (one index each) into ``fb``
    in order, later pieces over earlier ones, shaded with ``options`` (as
    :func:`scanline.render` builds them).  Returns the visible-face buffer (H, W)
    int64 (-1: nothing).  Each piece is cut into a fan of triangles whose vertices
    take the face's 1/w and barycentric functions and the face's plane depth; all are
    rasterized in one call."""
    faces = np.asarray(faces, np.int64).reshape(-1)
    if len(faces) != len(pieces):
        raise ArgumentValueError(f"faces must hold one face index per piece ({len(pieces)}), "
                                 f"got {len(faces)}")
    if len(faces) and (faces.min() < 0 or faces.max() >= scene.face_count):
        raise ArgumentValueError(f"faces must index the scene's {scene.face_count} faces")
    xy, offsets, faces = _flat(pieces, faces)
    g = face_functions(scene)[faces]                        # (P, 3 functions, c a b)
    counts = np.diff(offsets)
    fans = np.where(np.isfinite(g).all(axis=(1, 2)), counts - 2, 0)
    owner = np.repeat(np.arange(len(faces)), counts)
    gv = g[owner]
    vals = gv[:, :, 0] + xy[:, :1] * gv[:, :, 1] + xy[:, 1:2] * gv[:, :, 2]  # q, l1 q, l2 q
    a, b, c, d = scene.planes[faces][owner].T
    depth = -(a * xy[:, 0] + b * xy[:, 1] + d) / c
    piece = np.repeat(np.arange(len(faces)), fans)          # the fan (0, j + 1, j + 2)
    j = np.arange(int(fans.sum())) - np.repeat(np.cumsum(fans) - fans, fans)
    first = offsets[piece]
    idx = np.stack([first, first + j + 1, first + j + 2], axis=1)
    h, w = scene.height, scene.width
    vis = np.full((h, w), -1, np.int64)
    bary = np.zeros((h, w, 2))
    out = np.full((h, w), np.inf)
    if len(idx):
        tris = np.concatenate([xy, depth[:, None]], axis=1)[idx]
        rasterize(w, h, v.kernel_array(tris), v.kernel_array(vals[idx, 0]),
                  v.kernel_array(vals[idx, 1:] / vals[idx, :1]),
                  np.ascontiguousarray(faces[piece]), abuf=bary, idbuf=vis)
        ys, xs = np.nonzero(vis >= 0)
        planes = scene.planes[vis[ys, xs]]
        out[ys, xs] = -(planes[:, 0] * xs + planes[:, 1] * ys + planes[:, 3]) / planes[:, 2]
    write_visible(scene, fb, vis, bary, out, options)
    return vis
