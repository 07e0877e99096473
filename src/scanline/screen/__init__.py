"""Stage one of the 3-D pipeline: the screen-space scene.

:func:`prepare` takes meshes and a camera through viewing and clip coordinates, the
back-face test, homogeneous clipping, the divide and the device mapping, and gives
one :class:`ScreenScene`: what every visible-surface method (:mod:`scanline.visible`)
and the shading (:mod:`scanline.shading`) take.  :class:`ScreenPolygons` is the
form of it the polygon methods work on, also made by hand
(:meth:`ScreenPolygons.from_device`).  See ``docs/architecture.md``.

>>> import scanline as sl
>>> cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0))
>>> sl.screen.prepare(sl.mesh.cube(), cam, 40, 30)
<ScreenScene 40x30: 1 mesh(es), 6 faces, 12 facets, 12 device triangles>
"""

from .meshes import averaged_normals, mesh_arrays
from .polygons import ScreenPolygons, newell_plane, newell_planes
from .prepare import CLIP_VOLUME, GUARD, device_polygons, prepare, screen_polygons
from .scene import DevicePolygons, ScreenScene

__all__ = ["CLIP_VOLUME", "GUARD", "DevicePolygons", "ScreenPolygons", "ScreenScene",
           "averaged_normals", "device_polygons", "mesh_arrays", "newell_plane",
           "newell_planes", "prepare", "screen_polygons"]
