"""The renderer's options, one typed, frozen object: the method and its options, the
shading options, back-face culling and shadows."""

from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..shading.options import ShadingOptions
from ..visible.methods import METHODS, MethodOptions


@dataclass(frozen=True)
class RenderOptions:
    """Everything :func:`scanline.render` decides with besides the scene.

    Parameters
    ----------
    method : str
        A name in :data:`scanline.visible.METHODS`.
    visible : MethodOptions
        The method's options (only those the method reads may be set).
    shading : ShadingOptions
        The shading stage's options.
    cull_back_faces : bool
        Drop the facets turned away from the viewer before any method runs.
    shadows : bool
        Shadow maps for the lights made with ``shadows=True`` (Williams 1978).
    fallback : str or None
        The method to draw with when ``method`` gives up on a scene.
    antialias : int
        Samples per pixel side of supersampling (1: none).

    Raises
    ------
    ArgumentValueError
        An unknown method or fallback, antialias outside 1..8, or a method option
        the method does not read.
    ArgumentTypeError
        ``cull_back_faces`` or ``shadows`` not a bool.

    Examples
    --------
    >>> import scanline as sl
    >>> options = sl.rendering.RenderOptions(method="painter", antialias=2)
    >>> options.method, options.antialias, options.shading.model
    ('painter', 2, 'gouraud')
    """
    method: str = "z-buffer"
    visible: MethodOptions = field(default_factory=MethodOptions)
    shading: ShadingOptions = field(default_factory=ShadingOptions)
    cull_back_faces: bool = False
    shadows: bool = False
    fallback: Optional[str] = None
    antialias: int = 1

    def __post_init__(self) -> None:
        a = self.antialias
        if not isinstance(a, (int, np.integer)) or isinstance(a, bool) or not 1 <= a <= 8:
            raise ArgumentValueError(f"antialias must be an integer in 1..8 (samples per pixel "
                                     f"side; 1: none), got {v._show(a)}")
        object.__setattr__(self, "antialias", int(a))
        for name in ("method", "fallback"):
            value = getattr(self, name)
            if (value is not None or name == "method") and value not in METHODS:
                raise ArgumentValueError(f"{name} must be one of {', '.join(sorted(METHODS))}, "
                                         f"got {v._show(value)}")
        for name in ("cull_back_faces", "shadows"):
            if not isinstance(getattr(self, name), bool):
                raise ArgumentTypeError(f"{name} must be True or False, got "
                                        f"{v._show(getattr(self, name))}")
        reads = METHODS[self.method].options
        other = [name for name in self.visible.given() if name not in reads]
        if other:
            users = sorted(m.name for m in METHODS.values() if other[0] in m.options)
            raise ArgumentValueError(
                f"{other[0]}= is an option of method={' or '.join(map(repr, users))}, not of "
                f"method={self.method!r}" + (f" (which reads {', '.join(reads)})" if reads
                                             else ""))
