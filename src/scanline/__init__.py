"""scanline: the classic computer-graphics pipeline, as taught and as fast as C.

The public surface is loaded lazily, so ``import scanline`` is quick and does not
import numba; the compiled kernels load on first use.

>>> import scanline as sl
>>> fb = sl.FrameBuffer(8, 4, mode="1")
>>> sl.draw.line(fb, 0, 0, 7, 3)
>>> print(sl.text_image(fb))
------##
----##--
--##----
##------
"""

import importlib

__version__ = "0.1.0"

_LAZY = {
    "FrameBuffer": ("scanline.framebuffer", "FrameBuffer"),
    "text_image": ("scanline.framebuffer", "text_image"),
    "ScanlineError": ("scanline.errors", "ScanlineError"),
    "ArgumentValueError": ("scanline.errors", "ArgumentValueError"),
    "ArgumentTypeError": ("scanline.errors", "ArgumentTypeError"),
    "OutputError": ("scanline.errors", "OutputError"),
    "ImageFileError": ("scanline.errors", "ImageFileError"),
    "ScanlineWarning": ("scanline.errors", "ScanlineWarning"),
    "AngleWarning": ("scanline.errors", "AngleWarning"),
    "draw": ("scanline.draw", None),
    "trace": ("scanline.trace", None),
    "color": ("scanline.color", None),
    "geometry": ("scanline.geometry", None),
    "curves": ("scanline.curves", None),
    "transform": ("scanline.transform", None),
    "clip": ("scanline.clip", None),
    "viewing": ("scanline.viewing", None),
    "display": ("scanline.display", None),
    "DisplayFile": ("scanline.display", "DisplayFile"),
    "Context": ("scanline.context", "Context"),
    "scene": ("scanline.scene", None),
    "attributes": ("scanline.attributes", None),
    "FillStyle": ("scanline.attributes", "FillStyle"),
    "LineStyle": ("scanline.attributes", "LineStyle"),
    "text": ("scanline.text", None),
    "TextStyle": ("scanline.text.style", "TextStyle"),
    "animation": ("scanline.animation", None),
    "raster": ("scanline.raster", None),
    "transform3d": ("scanline.transform3d", None),
    "projection": ("scanline.projection", None),
    "Camera": ("scanline.projection", "Camera"),
    "mesh": ("scanline.mesh", None),
    "draw3d": ("scanline.draw3d", None),
    "DepthBuffer": ("scanline.depthbuffer", "DepthBuffer"),
    "lighting": ("scanline.lighting", None),
    "shading": ("scanline.shading", None),
    "render": ("scanline.render", None),
    "visible": ("scanline.visible", None),
}

__all__ = sorted(_LAZY) + ["__version__"]


def __getattr__(name):
    try:
        module, attr = _LAZY[name]
    except KeyError:
        raise AttributeError(f"module 'scanline' has no attribute {name!r}") from None
    value = importlib.import_module(module)
    if attr is not None:
        value = getattr(value, attr)
    globals()[name] = value
    return value


def __dir__():
    return __all__
