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


class _RenderModule(type(__import__("sys"))):
    """``scanline.render`` is both this package and the function :func:`render`:
    importing a sub-module (``scanline.render.prepare``) binds the package as the
    attribute ``scanline.render``, so the package itself is callable."""

    def __call__(self, *args, **kwargs):
        return render(*args, **kwargs)


__import__("sys").modules[__name__].__class__ = _RenderModule
