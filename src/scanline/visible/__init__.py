"""Visible-surface detection on screen-space polygons (Hearn & Baker, chapter 13):
the painter's one-key sort (the counter-example), depth sorting, BSP trees, the
scan-line method, area subdivision, and visible-line detection for wireframes.

Every method works on :class:`ScreenPolygons` (device x, y and depth per vertex, a
face index and a device-space plane per polygon) and gives either the pieces in
drawing order (object-order methods) or the visible face at every pixel (image
space); :func:`render` draws either flat shaded.

>>> import scanline as sl
>>> cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0),
...                 projection=sl.projection.perspective(fov=0.8, near=1))
>>> fb = sl.FrameBuffer(48, 32)
>>> pieces = sl.visible.render(fb, sl.mesh.cube(), cam, method="depth-sort")
>>> sorted(set(pieces.face.tolist()))
[0, 1, 2, 3, 4, 5]
"""

from .bsp import BSPTree, bsp, camera_eye
from .depth_sort import TESTS, depth_sort
from .hidden_lines import hidden_lines, visible_lines
from .painter import painter
from .polygons import ScreenPolygons, VisibleFaces, screen_polygons
from .render import METHODS, paint_depth_sorted, render, visible
from .scanline_method import scan_line
from .warnock import area_subdivision

__all__ = ["BSPTree", "METHODS", "ScreenPolygons", "TESTS", "VisibleFaces",
           "area_subdivision", "bsp", "camera_eye", "depth_sort", "hidden_lines",
           "paint_depth_sorted", "painter", "render", "scan_line", "screen_polygons", "visible",
           "visible_lines"]
