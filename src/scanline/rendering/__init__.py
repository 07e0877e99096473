"""Rendering meshes through a camera: :func:`render` orders the passes of the one 3-D
pipeline -- shadow maps, the preparation (:mod:`scanline.screen`), a visible-surface
method (:mod:`scanline.visible`), the shading (:mod:`scanline.shading`) and the
transparent layer -- and returns a :class:`Rendering`.  See ``docs/architecture.md``.

(The package is not named ``render``: ``sl.render`` is the function, and a package of
that name would replace it as an attribute of ``scanline`` when imported.)
"""

from .api import default_lights, render, run
from .options import RenderOptions
from .result import Rendering

__all__ = ["RenderOptions", "Rendering", "default_lights", "render", "run"]
