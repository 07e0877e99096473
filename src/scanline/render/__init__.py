"""Rendering meshes through a camera by a visible-surface method, with illumination
and shading: :func:`render`.

The methods (Hearn & Baker, chapter 13) are looked up by name in
:data:`scanline.render.methods.METHODS`; each works on the screen-space scene that
:func:`scanline.render.prepare.prepare` builds (:class:`ScreenScene`).
"""

from .methods import METHODS, PRECISION, register
from .output import Rendering
from .pieces import draw_pieces
from .prepare import ScreenScene, prepare
from .api import render

__all__ = ["render", "prepare", "ScreenScene", "Rendering", "METHODS", "PRECISION",
           "register", "draw_pieces"]
