"""The registry of visible-surface methods: name -> callable ``(scene, fb, options)``
taking the prepared :class:`~scanline.render.prepare.ScreenScene`, the frame buffer
and the shading options (``lights``, ``shading``, ``specular``, ``gamma``,
``depth_cue``, ``shadows``, and the method's own), drawing, and returning a
:class:`~scanline.render.output.Rendering`.  :func:`scanline.render` looks methods
up here; another module adds one with :func:`register`."""

from . import abuffer, hidden, raycast, zbuffer

#: name -> (callable, "image" or "object" precision)
METHODS = {
    "z-buffer": zbuffer.render,
    "a-buffer": abuffer.render,
    "ray-casting": raycast.render,
    **{name: method for name, (method, _) in hidden.METHODS.items()},
}

#: Each method's precision (Hearn & Baker, section 13-1): "image" methods decide
#: visibility per pixel, "object" methods compare surfaces with one another.
PRECISION = {"z-buffer": "image", "a-buffer": "image", "ray-casting": "image",
             **{name: precision for name, (_, precision) in hidden.METHODS.items()}}


def register(name, method, precision):
    """Add a method (``precision``: "image" or "object")."""
    METHODS[name] = method
    PRECISION[name] = precision
