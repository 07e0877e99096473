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
from typing import TYPE_CHECKING, Any, List

__version__ = "0.2.0"

if TYPE_CHECKING:   # what the lazy attributes are, for type checkers and editors
    # ("X as X" marks each as exported; a test keeps this list equal to _LAZY)
    from . import animation as animation, attributes as attributes, clip as clip
    from . import color as color, curves as curves, display as display, draw as draw
    from . import draw3d as draw3d, geometry as geometry, mesh as mesh
    from . import projection as projection, raster as raster, scene as scene, text as text
    from . import trace as trace, transform as transform, transform3d as transform3d
    from . import viewing as viewing, visible as visible, lighting as lighting
    from . import shading as shading, rendering as rendering, screen as screen
    from . import budget as budget, mpl as mpl, texture as texture
    from . import raytrace as raytrace, radiosity as radiosity
    from . import solids as solids, csg as csg, octree as octree
    from . import fractals as fractals, studio as studio
    from .texture import Texture as Texture
    from .rendering import render as render
    from .depthbuffer import DepthBuffer as DepthBuffer
    from .attributes import FillStyle as FillStyle
    from .context import Context as Context
    from .display import DisplayFile as DisplayFile
    from .errors import AngleWarning as AngleWarning, ArgumentTypeError as ArgumentTypeError
    from .errors import ColorScaleWarning as ColorScaleWarning
    from .errors import ArgumentValueError as ArgumentValueError
    from .errors import ImageFileError as ImageFileError, ScanlineError as ScanlineError
    from .errors import OutputError as OutputError, ScanlineWarning as ScanlineWarning
    from .framebuffer import FrameBuffer as FrameBuffer, text_image as text_image
    from .linestyle import LineStyle as LineStyle
    from .projection import Camera as Camera
    from .text.style import TextStyle as TextStyle

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
    "ColorScaleWarning": ("scanline.errors", "ColorScaleWarning"),
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
    "render": ("scanline.rendering", "render"),
    "rendering": ("scanline.rendering", None),
    "raytrace": ("scanline.raytrace", None),
    "radiosity": ("scanline.radiosity", None),
    "solids": ("scanline.solids", None),
    "csg": ("scanline.csg", None),
    "octree": ("scanline.octree", None),
    "fractals": ("scanline.fractals", None),
    "studio": ("scanline.studio", None),
    "screen": ("scanline.screen", None),
    "budget": ("scanline.budget", None),
    "mpl": ("scanline.mpl", None),
    "visible": ("scanline.visible", None),
    "texture": ("scanline.texture", None),
    "Texture": ("scanline.texture", "Texture"),
}

__all__ = sorted(_LAZY) + ["__version__"]


def __getattr__(name: str) -> Any:
    try:
        module, attr = _LAZY[name]
    except KeyError:
        raise AttributeError(f"module 'scanline' has no attribute {name!r}") from None
    value = importlib.import_module(module)
    if attr is not None:
        value = getattr(value, attr)
    globals()[name] = value
    return value


def __dir__() -> List[str]:
    return __all__
