"""Clipping (notes, chapter 4): points, lines, polylines, polygons, curves and text.

A *window* is an upright rectangle ``(xmin, ymin, xmax, ymax)`` or, where the
algorithm allows it, a polygon ((M, 2) vertices, either orientation).  Windows are
closed: what lies on the boundary is kept.  Each algorithm of the notes is chosen by
name with ``method=``:

- lines: ``"cohen-sutherland"`` (region codes), ``"liang-barsky"`` (the default) and
  ``"cyrus-beck"`` (any convex polygon window);
- polygons: ``"sutherland-hodgman"`` (convex windows; one contour per subject
  contour) and ``"weiler-atherton"`` (concave windows and subjects; separate pieces);
- curves: ``circle`` and ``ellipse`` give the visible arcs as angle intervals,
  ``arcs`` flattens them, ``curve`` clips any curve through its polyline;
- text (placed by :func:`scanline.text.layout`): ``mode="string"``, ``"character"``
  (all or none), ``"stroke"`` or ``"pixel"``.

Three dimensions (:mod:`scanline.clip.three_d`): ``line3d`` / ``lines3d``
(Cohen-Sutherland with six-bit codes, Liang-Barsky, Cyrus-Beck) and ``polygon3d`` /
``polygons3d`` (Sutherland-Hodgman) against a box, Foley's canonical frustum or any
convex polyhedron (:mod:`scanline.clip.volumes`), and ``homogeneous``: clipping in
homogeneous coordinates before the perspective divide.

The step tables of the line clippers are in :mod:`scanline.trace`
(``scanline trace cohen-sutherland ...``, ``scanline trace cohen-sutherland-3d ...``).
"""

from .curves import arcs, circle, curve, ellipse
from .lines import line, lines, point, points, polyline
from .polygons import polygon, polygons
from .text import text
from .three_d import homogeneous, line3d, lines3d, polygon3d, polygons3d
from .volumes import UNIT_CUBE, Volume, box, frustum, polyhedron

__all__ = ["point", "points", "line", "lines", "polyline", "polygon", "polygons",
           "circle", "ellipse", "arcs", "curve", "text",
           "line3d", "lines3d", "polygon3d", "polygons3d", "homogeneous",
           "Volume", "box", "frustum", "polyhedron", "UNIT_CUBE"]
