"""The options of the shading stage, one typed, frozen object."""

from dataclasses import dataclass
from typing import Any, Callable, Optional, Tuple

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError

#: The polygon rendering methods (Hearn & Baker 14-5), and "none": no illumination.
MODELS = ("none", "flat", "gouraud", "phong", "fast-phong")
SPECULAR = ("phong", "blinn")
GAMMA = 2.2


def gamma_value(gamma: float) -> float:
    """``gamma`` checked: a display gamma in 0.1..10.

    Parameters
    ----------
    gamma : float
        The exponent (1: linear; 2.2: a typical display, Hearn & Baker 14-2).

    Returns
    -------
    float
        The gamma.

    Raises
    ------
    ArgumentValueError
        A gamma outside 0.1..10.

    Examples
    --------
    >>> from scanline.shading import gamma_value
    >>> gamma_value(2)
    2.0
    """
    g = v.number("gamma", gamma)
    if not 0.1 <= g <= 10:
        raise ArgumentValueError(f"gamma must be in 0.1..10 (1: linear, 2.2: a typical "
                                 f"display), got {gamma!r}")
    return g


@dataclass(frozen=True)
class ShadingOptions:
    """How the shading colors what a visible-surface method found.

    Parameters
    ----------
    model, lights, specular, gamma, depth_cue, shadows, texture_mapping
        As listed under Attributes (``lights``: one light or several).

    Raises
    ------
    ArgumentValueError
        An unknown model, specular term or texture mapping, or a gamma outside
        0.1..10.
    ArgumentTypeError
        A light that is not one, or ``shadows`` not callable.

    Examples
    --------
    >>> import scanline as sl
    >>> options = sl.shading.ShadingOptions(model="phong", lights=sl.lighting.AmbientLight())
    >>> options.model, len(options.lights), options.gamma
    ('phong', 1, 2.2)

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
    lights: Any = ()
    specular: str = "phong"
    gamma: float = GAMMA
    depth_cue: Optional[Tuple[float, float]] = None
    shadows: Optional[Callable[..., Any]] = None
    texture_mapping: str = "perspective"

    def __post_init__(self) -> None:
        from ..lighting.lights import light_list

        v.choice("shading", self.model, MODELS)
        v.choice("specular", self.specular, SPECULAR)
        v.choice("texture_mapping", self.texture_mapping, ("perspective", "affine"))
        object.__setattr__(self, "gamma", gamma_value(self.gamma))
        object.__setattr__(self, "lights", tuple(light_list(self.lights)))
        if self.shadows is not None and not callable(self.shadows):
            raise ArgumentTypeError(f"shadows must be a function of points or None, got "
                                    f"{v._show(self.shadows)}")
