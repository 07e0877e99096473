"""Stage three of the 3-D pipeline: shading, the one way the renderer colors pixels.

The polygon rendering methods of Hearn & Baker, section 14-5 -- constant (flat),
Gouraud and Phong shading, and the fast Phong approximation -- and "none" (each
surface its own color), with the illumination models of :mod:`scanline.lighting`,
depth cueing, the gamma encoding (section 14-2, "Displaying light intensities") and
the compositing of transparent layers.  See :mod:`scanline.shading.models` (the
formulas), :mod:`scanline.shading.buffer` (the compiled path) and
:mod:`scanline.shading.compose` (:func:`shade`, :func:`composite`).
"""

from ..lighting.model import ViewerAtInfinity
from .compose import barycentrics, composite, paint, shade
from .models import decode, decoded, encode, face_intensities, intensities, vertex_intensities
from .options import GAMMA, MODELS, SPECULAR, ShadingOptions, gamma_value

__all__ = ["GAMMA", "MODELS", "SPECULAR", "ShadingOptions", "ViewerAtInfinity", "barycentrics",
           "composite", "decode", "decoded", "encode", "face_intensities", "gamma_value",
           "intensities", "paint", "shade", "vertex_intensities"]
