"""Three-dimensional objects drawn on a :class:`~scanline.FrameBuffer` through a
:class:`~scanline.Camera`: wireframes of meshes, 3-D lines and polylines, view
volumes and axes, each clipped in homogeneous coordinates and drawn by the 2-D line
kernels with every line attribute (Hearn & Baker, section 9-1); and the display
methods of section 9-1: exploded views (:func:`exploded`), cutaway views with their
cut faces capped (:func:`cutaway`), and stereo pairs shown as anaglyphs or side by
side (:func:`anaglyph`, :func:`side_by_side`, with :meth:`scanline.Camera.stereo`).

>>> import scanline as sl
>>> fb = sl.FrameBuffer(64, 64)
>>> cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0),
...                 projection=sl.projection.perspective(fov=0.8, near=1))
>>> segments = sl.draw3d.wireframe(fb, sl.mesh.cube(), cam, color="white", depth_cue=True)
>>> len(segments)
12
"""

from .cutaway import Cutaway, cutaway
from .exploded import centroid, exploded
from .horizon import Horizon, floating_horizon, horizon
from .wireframe import (axes, lines, polyline_pieces, polylines, project_edges, view_volume,
                        wireframe)
from .stereo import anaglyph, side_by_side

__all__ = ["Cutaway", "Horizon", "anaglyph", "axes", "centroid", "cutaway", "exploded",
           "floating_horizon", "horizon", "lines", "polyline_pieces", "polylines",
           "project_edges", "side_by_side", "view_volume", "wireframe"]
