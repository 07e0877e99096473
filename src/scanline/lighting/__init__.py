"""Illumination models (Hearn & Baker, chapter 14): light sources, surface
properties and the intensity at a point.

>>> import scanline as sl
>>> m = sl.lighting.Material(ka=0.2, kd=0.8, ks=0.0)
>>> sun = sl.lighting.DirectionalLight(direction=(0, 0, -1))      # travels down -z
>>> sl.lighting.intensity((0, 0, 0), (0, 0, 1), (0, 0, 5), [sun], m).tolist()
[0.8, 0.8, 0.8]
"""

from .lights import AmbientLight, AreaLight, DirectionalLight, PointLight, SpotLight
from .material import Material
from .model import ViewerAtInfinity, at_infinity, attenuation, depth_cue, intensity, transparency

__all__ = ["AmbientLight", "AreaLight", "DirectionalLight", "PointLight", "SpotLight",
           "Material", "intensity", "attenuation", "depth_cue", "transparency", "at_infinity",
           "ViewerAtInfinity"]
