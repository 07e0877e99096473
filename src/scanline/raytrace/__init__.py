"""Recursive ray tracing (Whitted 1980; Hearn & Baker, section 14-6).

* :class:`BVH`: a bounding volume hierarchy over triangles, built by the
  surface-area heuristic in compiled code, and rays cast against it
  (Moller-Trumbore intersections);
* :func:`reflect`, :func:`refract`, :func:`fresnel`: the secondary rays' directions
  and weights, one ray at a time (the tracer's own helpers);
* ``sl.render(..., method="ray-tracing", max_depth=5, seed=0)``: shadows from every
  light, reflection, refraction with total internal reflection, Fresnel weighting,
  supersampling (``antialias=``) and distributed ray tracing (soft shadows from
  :class:`~scanline.lighting.AreaLight`, glossy reflection from a material's
  ``roughness``) -- :mod:`scanline.raytrace.render`;
* ``sl.trace.ray_tracing(x, y)``: the ray tree of one primary ray, step by step.
"""

from .bvh import BVH, Hits
from .optics import fresnel, reflect, refract

__all__ = ["BVH", "Hits", "fresnel", "reflect", "refract"]
