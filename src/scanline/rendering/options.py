"""The renderer's options, one typed, frozen object: the method and its options, the
shading options, back-face culling and shadows."""

from dataclasses import dataclass, field

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..shading.options import ShadingOptions
from ..visible.methods import METHODS, MethodOptions


@dataclass(frozen=True)
class RenderOptions:
    """Everything :func:`scanline.render` decides with besides the scene.

    Attributes
    ----------
    method : str
        A name in :data:`scanline.visible.METHODS`.
    visible : MethodOptions
        The method's options (only those the method reads may be set).
    shading : ShadingOptions
    cull_back_faces : bool
        Drop the facets turned away from the viewer before any method runs.
    shadows : bool
        Shadow maps for the lights made with ``shadows=True`` (Williams 1978).
    """
    method: str = "z-buffer"
    visible: MethodOptions = field(default_factory=MethodOptions)
    shading: ShadingOptions = field(default_factory=ShadingOptions)
    cull_back_faces: bool = False
    shadows: bool = False

    def __post_init__(self):
        if self.method not in METHODS:
            raise ArgumentValueError(f"method must be one of {', '.join(sorted(METHODS))}, got "
                                     f"{v._show(self.method)}")
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
