"""Geometric predicates on polygons: inside-outside tests (notes, chapter 2, Q.8;
Hearn & Baker, section 3-11).

``inside(points, polygon, rule)`` and ``winding_number(points, polygon)`` follow the
same boundary convention (the top-left rule) as ``sl.draw.polygon``.
"""

from .inside import inside, winding_number

__all__ = ["inside", "winding_number"]
