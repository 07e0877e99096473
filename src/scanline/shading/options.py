"""The options of the shading stage, one typed, frozen object."""

from dataclasses import dataclass
from typing import Callable, Optional

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError

#: The polygon rendering methods (Hearn & Baker 14-5), and "none": no illumination.
MODELS = ("none", "flat", "gouraud", "phong", "fast-phong")
SPECULAR = ("phong", "blinn")
GAMMA = 2.2


def gamma_value(gamma):
    g = v.number("gamma", gamma)
    if not 0.1 <= g <= 10:
        raise ArgumentValueError(f"gamma must be in 0.1..10 (1: linear, 2.2: a typical "
                                 f"display), got {gamma!r}")
    return g


@dataclass(frozen=True)
class ShadingOptions:
    """How the shading colors what a visible-surface method found.

    Attributes
    ----------
    model : {"none", "flat", "gouraud", "phong", "fast-phong"}
        "none": each surface shows its color S_d, unlit; the others as
        :mod:`scanline.shading` describes them (Hearn & Baker 14-5).
    lights : tuple of lights
        Light sources of :mod:`scanline.lighting`.
    specular : {"phong", "blinn"}
        The specular term: (V . R)^n or Blinn's (N . H)^n.
    gamma : float
        The display gamma the linear intensities are encoded with (1: none).
    depth_cue : (near, far) or None
        Blend toward the background with the distance (Hearn & Baker 9-1).
    shadows : callable or None
        ``shadows(points (M, 3))`` -> per non-ambient light, 1 where the points see
        it and 0 in its shadow (a shadow map's answer).
    texture_mapping : {"perspective", "affine"}
        How texture coordinates are interpolated across the screen: perspective-
        correct (u/w, v/w and 1/w linear, then divided), or affine (u and v linear
        in screen space: wrong under perspective, shown for comparison).
    """
    model: str = "gouraud"
    lights: tuple = ()
    specular: str = "phong"
    gamma: float = GAMMA
    depth_cue: Optional[tuple] = None
    shadows: Optional[Callable] = None
    texture_mapping: str = "perspective"

    def __post_init__(self):
        from ..lighting.lights import light_list

        v.choice("shading", self.model, MODELS)
        v.choice("specular", self.specular, SPECULAR)
        v.choice("texture_mapping", self.texture_mapping, ("perspective", "affine"))
        object.__setattr__(self, "gamma", gamma_value(self.gamma))
        object.__setattr__(self, "lights", tuple(light_list(self.lights)))
        if self.shadows is not None and not callable(self.shadows):
            raise ArgumentTypeError(f"shadows must be a function of points or None, got "
                                    f"{v._show(self.shadows)}")
