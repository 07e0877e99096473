"""Output primitives drawn into a :class:`~scanline.FrameBuffer` (notes, chapter 2).

Every function takes the frame buffer first, device coordinates (x right, y up,
pixel centers at integers) and a ``color``.  Anything outside the frame buffer is
clipped.  The default ``color=None`` is the frame buffer's
:attr:`~scanline.FrameBuffer.foreground`: white on a dark background (the default
black), black on a light one, so that a drawing made without a color is never
invisible.  Batch functions (``lines``, ``circles``, ``ellipses``, ``polygons``,
``fill_circles``, ``fill_ellipses``, ``points``, ``rectangles``) take N primitives as one array and draw them in one
compiled call.  Area functions take a ``style`` (:class:`scanline.FillStyle`).
Pillow's shapes (``point``, ``rectangle``, ``rounded_rectangle``,
``regular_polygon``) are built on these primitives (:mod:`scanline.draw.shapes`):
``fill=False`` draws the outline, ``fill=True`` or a fill color the area.
"""

from .lines import line, lines
from .conics import circle, circles, ellipse, ellipses
from .curved import arc, chord, fill_circle, fill_circles, fill_ellipse, fill_ellipses, pie
from .polygon import polygon, polygons
from .seedfill import boundary_fill, flood_fill
from .softfill import soft_fill
from . import antialias
from .strokes import polyline, polylines
from .curve import curve, curves
from .text import text
from .triangles import triangles
from .shapes import (point, points, rectangle, rectangles, regular_polygon,
                     regular_polygon_vertices, rounded_rectangle)

__all__ = ["line", "lines", "circle", "circles", "ellipse", "ellipses", "polygon", "polygons",
           "fill_circle", "fill_circles", "fill_ellipse", "fill_ellipses", "arc", "chord", "pie",
           "flood_fill", "boundary_fill", "soft_fill", "polyline", "polylines", "curve", "curves", "text",
           "triangles", "point", "points", "rectangle", "rectangles", "rounded_rectangle",
           "regular_polygon", "regular_polygon_vertices"]
