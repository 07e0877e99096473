"""The visible-surface methods of :mod:`scanline.visible` as methods of
:func:`scanline.render`, with illumination and shading.

:mod:`scanline.visible` decides visibility on screen-space polygons; here the
prepared scene's clipped device polygons (one per face of the fan triangulation,
:class:`~scanline.render.prepare.ScreenScene`) are handed to it and its answer is
shaded like the depth buffer's:

* the **object-order** methods ("painter", "depth-sort", "bsp"; object precision,
  Hearn & Baker 13-6 and 13-7) give pieces of faces back to front, drawn in that
  order without a depth test by :func:`~scanline.render.pieces.draw_pieces`, each
  pixel shaded from its source face;
* the **image-space** methods ("scan-line", "area-subdivision"; image precision,
  13-5 and 13-8) give the visible face at each pixel, whose barycentric
  coordinates in that face are found from the face's screen-space interpolation
  functions, then shaded.

The BSP tree is built in world coordinates from the scene's faces and traversed
from the camera's eye (Fuchs, Kedem and Naylor 1980), so the same faces numbered
the same way reach the shading.
"""

import numpy as np

from ..depthbuffer import DepthBuffer
from ..mesh import Mesh
from ..visible import (BSPTree, ScreenPolygons, area_subdivision, depth_sort, painter,
                       scan_line)
from ..visible.bsp import camera_eye
from ..visible.polygons import flat_polygons, project
from .output import Rendering, write_visible
from .pieces import draw_pieces, face_functions


def screen_polygons(scene):
    """The scene's clipped device polygons as :class:`~scanline.visible.ScreenPolygons`
    (faces numbered as the scene's; culled faces are already gone)."""
    verts, counts = scene.polygons.flat()
    return flat_polygons(verts, counts, scene.polygon_face, scene.width, scene.height)


def _bsp_pieces(scene, options):
    """The scene's faces back to front by a BSP tree built in world coordinates."""
    keep = np.unique(np.asarray(scene.polygon_face, np.int64))
    tri = scene.world[keep]
    area = np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
    keep = keep[area > 0]
    if not len(keep):
        return ScreenPolygons.from_device([], scene.width, scene.height)
    mesh = Mesh(scene.world[keep].reshape(-1, 3), np.arange(3 * len(keep)).reshape(-1, 3))
    tree = BSPTree(mesh, max_pieces=options.get("max_pieces"))
    verts, counts, faces = tree.world_pieces(camera_eye(scene.camera, scene.width,
                                                        scene.height))
    return project(verts, counts, keep[faces], scene.camera, scene.width, scene.height)


def _object_order(name, order):
    def render(scene, fb, options):
        pieces = order(scene, options)
        faces = draw_pieces(scene, fb, pieces, pieces.face, options)
        return Rendering(name, _depth_of(scene, faces), faces, scene)
    render.__doc__ = f"Draw ``scene`` into ``fb`` by the {name} method (object order)."
    return render


def _image_space(name, method):
    def render(scene, fb, options):
        seen = method(screen_polygons(scene)).face
        ys, xs = np.nonzero(seen >= 0)
        g = face_functions(scene)[seen[ys, xs]]                # (n, 3 functions, c a b)
        vals = g[:, :, 0] + xs[:, None] * g[:, :, 1] + ys[:, None] * g[:, :, 2]
        bary = np.zeros((scene.height, scene.width, 2))
        bary[ys, xs] = vals[:, 1:] / vals[:, :1]
        depth = _depth_of(scene, seen)
        write_visible(scene, fb, seen, bary, depth.array, options)
        return Rendering(name, depth, seen, scene)
    render.__doc__ = f"Draw ``scene`` into ``fb`` by the {name} method (image space)."
    return render


def _depth_of(scene, faces):
    """The depth buffer of the visible faces ``faces`` (H, W): each face's device
    plane at the pixel centers."""
    out = DepthBuffer(scene.width, scene.height)
    ys, xs = np.nonzero(faces >= 0)
    a, b, c, d = scene.planes[faces[ys, xs]].T
    out.array[ys, xs] = -(a * xs + b * ys + d) / c
    return out


#: name -> (callable, precision), registered in :data:`scanline.render.methods.METHODS`.
METHODS = {
    "painter": (_object_order("painter", lambda s, o: painter(
        screen_polygons(s), o.get("key", "farthest"))), "object"),
    "depth-sort": (_object_order("depth-sort", lambda s, o: depth_sort(
        screen_polygons(s), o.get("split_cycles", True),
        max_pieces=o.get("max_pieces"))), "object"),
    "bsp": (_object_order("bsp", _bsp_pieces), "object"),
    "scan-line": (_image_space("scan-line", scan_line), "image"),
    "area-subdivision": (_image_space("area-subdivision", area_subdivision), "image"),
}
