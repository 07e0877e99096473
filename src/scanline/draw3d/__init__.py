"""Three-dimensional objects drawn on a :class:`~scanline.FrameBuffer` through a
:class:`~scanline.Camera`: wireframes of meshes, 3-D lines and polylines, view
volumes and axes, each clipped in homogeneous coordinates and drawn by the 2-D line
kernels with every line attribute (Hearn & Baker, section 9-1).

>>> import scanline as sl
>>> fb = sl.FrameBuffer(64, 64)
>>> cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0),
...                 projection=sl.projection.perspective(fov=0.8, near=1))
>>> segments = sl.draw3d.wireframe(fb, sl.mesh.cube(), cam, color="white", depth_cue=True)
>>> len(segments)
12
"""

from .horizon import Horizon, floating_horizon, horizon
from .wireframe import (axes, lines, polyline_pieces, polylines, project_edges, view_volume,
                        wireframe)

__all__ = ["Horizon", "axes", "floating_horizon", "horizon", "lines", "polyline_pieces", "polylines", "project_edges", "view_volume",
           "wireframe"]
