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
    NaN for faces without one."""
    f = np.full((scene.face_count, 3, 3), np.nan)
    first = {}
    for t, face in enumerate(scene.face):
        first.setdefault(int(face), t)
    for face, t in first.items():
        x, y = scene.triangles[t, :, 0], scene.triangles[t, :, 1]
        q = scene.inv_w[t]
        vals = np.stack([q, scene.bary[t, :, 0] * q, scene.bary[t, :, 1] * q])  # (3 fn, 3 vtx)
        m = np.stack([np.ones(3), x, y], axis=1)                                  # (3, 3)
        f[face] = np.linalg.solve(m, vals.T).T                                    # c, a, b
    return f


def draw_pieces(scene, fb, pieces, faces, options):
    """Draw ``pieces`` (a list of (k, 2+) device polygons, x and y first) of source
    ``faces`` (one index each) into ``fb`` in list order, later pieces over earlier
    ones, shaded with ``options`` (as :func:`scanline.render` builds them).  Returns
    the visible-face buffer (H, W) int64 (-1: nothing)."""
    faces = np.asarray(faces, np.int64).reshape(-1)
    if len(faces) != len(pieces):
        raise ArgumentValueError(f"faces must hold one face index per piece ({len(pieces)}), "
                                 f"got {len(faces)}")
    if len(faces) and (faces.min() < 0 or faces.max() >= scene.face_count):
        raise ArgumentValueError(f"faces must index the scene's {scene.face_count} faces")
    fn = face_functions(scene)
    tris, qs, atts, ids = [], [], [], []
    for piece, face in zip(pieces, faces):
        p = v.real_array("pieces", piece, "(k, 2+)")
        if p.ndim != 2 or p.shape[1] < 2 or len(p) < 3:
            continue
        g = fn[face]
        if not np.isfinite(g).all():
            continue
        xy = p[:, :2]
        vals = g[:, 0] + xy @ g[:, 1:].T                    # (k, 3): q, l1 q, l2 q
        a, b, c, d = scene.planes[face]
        depth = -(a * xy[:, 0] + b * xy[:, 1] + d) / c
        k = len(p)
        idx = np.stack([np.zeros(k - 2, int), np.arange(1, k - 1), np.arange(2, k)], 1)
        tris.append(np.concatenate([xy, depth[:, None]], axis=1)[idx])
        qs.append(vals[idx, 0])
        atts.append(vals[idx, 1:] / vals[idx, :1])
        ids.append(np.full(k - 2, face, np.int64))
    h, w = scene.height, scene.width
    vis = np.full((h, w), -1, np.int64)
    bary = np.zeros((h, w, 2))
    depth = np.full((h, w), np.inf)
    if tris:
        rasterize(w, h, v.kernel_array(np.concatenate(tris)), v.kernel_array(np.concatenate(qs)),
                  v.kernel_array(np.concatenate(atts)),
                  np.ascontiguousarray(np.concatenate(ids)), abuf=bary, idbuf=vis)
        ys, xs = np.nonzero(vis >= 0)
        planes = scene.planes[vis[ys, xs]]
        depth[ys, xs] = -(planes[:, 0] * xs + planes[:, 1] * ys + planes[:, 3]) / planes[:, 2]
    write_visible(scene, fb, vis, bary, depth, options)
    return vis
