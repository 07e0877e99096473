"""Radiosity (Goral, Torrance, Greenberg and Battaile 1984; Hearn & Baker, section
14-7): light exchanged between diffuse surfaces.

* :func:`patches`: meshes subdivided into patches with area, centre, normal,
  emission and reflectance (:mod:`scanline.radiosity.patches`);
* :func:`form_factors`: the (P, P) form factors by the hemicube (Cohen and
  Greenberg 1985) or by ray casting (:mod:`scanline.radiosity.formfactors`);
* :func:`solve`: the full solution by Gauss-Seidel sweeps, or progressive
  refinement by shooting with the ambient term (Cohen, Chen, Wallace and Greenberg
  1988), convergence reported per iteration; the result's node radiosities rendered
  by Gouraud shading through :func:`scanline.render` (:mod:`scanline.radiosity.solve`);
* :func:`cornell_box`: the Cornell box's published geometry and colors.
"""

from .cornell import cornell_box
from .formfactors import delta_form_factors, form_factors
from .patches import Patches, patches
from .solve import Radiosity, solve, vertex_radiosity

__all__ = ["Patches", "Radiosity", "cornell_box", "delta_form_factors", "form_factors",
           "patches", "solve", "vertex_radiosity"]
