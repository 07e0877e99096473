"""Solids: analytic primitives and closed meshes with exact ray intersections (Hearn &
Baker 10-3, quadric surfaces; 10-16, solid modeling; 14-6, ray-surface intersections).

Every solid has a material and ``contains(points)``, ``bounds()`` and ``volume()``;
``a | b``, ``a & b`` and ``a - b`` build CSG trees (:mod:`scanline.csg`).  Solids are
drawn by ``sl.render(fb, [solid, mesh, ...], camera, method="ray-casting")`` or
``method="ray-tracing"`` (exactly, ray by ray; docs/solids.md).

>>> import scanline as sl
>>> s = sl.solids.Sphere((0, 0, 0), 1.0)
>>> s.contains([(0, 0, 0.5), (0, 0, 1.5)]).tolist()
[True, False]
"""

from .base import Solid
from .meshsolid import MeshSolid
from .primitives import Box, Cone, Cylinder, Ellipsoid, Primitive, Quadric, Sphere

__all__ = ["Box", "Cone", "Cylinder", "Ellipsoid", "MeshSolid", "Primitive", "Quadric",
           "Solid", "Sphere"]
