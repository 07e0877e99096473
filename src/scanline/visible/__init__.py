"""Stage two of the 3-D pipeline: visible-surface detection (Hearn & Baker, chapter
13) -- the z-buffer, the A-buffer, ray casting, the scan-line method, area
subdivision, depth sorting, BSP trees and the painter's one-key sort (the
counter-example) -- and visible-line detection for wireframes.

Each method of :data:`METHODS` takes the prepared scene
(:class:`~scanline.screen.ScreenScene`) and returns what is visible, never a color:
:func:`scanline.render` orders the stages.  The polygon methods can also be called
on their own, on :class:`ScreenPolygons` (device x, y and depth per vertex, a face
and a device-space plane per polygon): :func:`painter`, :func:`depth_sort` and
:func:`bsp` give the pieces in drawing order, :func:`scan_line` and
:func:`area_subdivision` the visible face at every pixel.

>>> import scanline as sl
>>> cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0),
...                 projection=sl.projection.perspective(fov=0.8, near=1))
>>> polygons = sl.visible.screen_polygons(sl.mesh.cube(), cam, 48, 32)
>>> sorted(set(sl.visible.depth_sort(polygons).face.tolist()))
[0, 1, 2, 3, 4, 5]
"""

from ..screen.polygons import ScreenPolygons
from ..screen.prepare import screen_polygons
from .bsp import BSPTree, bsp, camera_eye
from .depth_sort import TESTS, depth_sort, painted_depth_sort
from .hidden_lines import hidden_lines, visible_lines
from .methods import METHODS, PRECISION, Method, MethodOptions, register
from .painter import painter
from .scanline_method import scan_line
from .visibility import Fragments, Layer, VisibleFaces
from .warnock import area_subdivision

__all__ = ["BSPTree", "Fragments", "Layer", "METHODS", "Method", "MethodOptions", "PRECISION",
           "ScreenPolygons", "TESTS", "VisibleFaces", "area_subdivision", "bsp", "camera_eye",
           "depth_sort", "hidden_lines", "painted_depth_sort", "painter", "register",
           "scan_line", "screen_polygons", "visible_lines"]
