"""Surface properties of the basic illumination model (Hearn & Baker, section 14-2
and 14-6): reflection coefficients, the specular exponent, color, transparency, and
the ray tracer's reflectivity, index of refraction and roughness (14-6)."""

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Optional, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .._typing import Color
from ..errors import ArgumentValueError

if TYPE_CHECKING:
    from ..texture.cubemap import CubeMap
    from ..texture.texture import ImageSource, Texture


def _coefficient(name: str, value: float) -> float:
    x = v.number(name, value)
    if not 0.0 <= x <= 1.0:
        raise ArgumentValueError(f"{name} must be in 0..1, got {value!r}")
    return x


def linear_color(name: str, color: Union[Color, NDArray[np.float64]]) -> NDArray[np.float64]:
    """A color spec as linear RGB reals 0..1 (the sRGB-like stored values decoded with
    the display gamma is the shading's job: here the stored values / 255)."""
    if isinstance(color, np.ndarray) and color.dtype.kind == "f" and color.shape == (3,):
        if not (np.isfinite(color).all() and (color >= 0).all() and (color <= 1).all()):
            raise ArgumentValueError(f"{name} reals must be in 0..1, got {color.tolist()}")
        return color.astype(np.float64)
    from ..color import rgba

    return np.array(rgba(color, name)[:3], np.float64) / 255.0


@dataclass(frozen=True, init=False)
class Material:
    """How a surface reflects light.

    Parameters
    ----------
    ka, kd, ks : float in 0..1
        Ambient, diffuse and specular reflection coefficients.
    shininess : float >= 0
        The specular exponent n_s (large: a small, sharp highlight; Hearn & Baker
        suggest 1 for dull surfaces up to 100 or more for shiny ones).
    color : color
        The surface color S_d: the diffuse and ambient reflection of each component
        are ka * S_d and kd * S_d (Hearn & Baker, section 14-6).
    specular_color : color
        The color of the highlights, S_s (default white: a dielectric such as
        plastic; a metal takes its own color).
    transparency : float in 0..1
        k_t: the fraction of the light behind the surface that passes through
        (Hearn & Baker, section 14-5, I = (1 - k_t) I_refl + k_t I_trans).
    texture : scanline.Texture or image, optional
        The surface color S_d varies over the surface: S_d = color x the texel at the
        point's texture coordinates (the mesh's ``uv``), so the diffuse and ambient
        reflections are kd S_d and ka S_d (Hearn & Baker 14-9, texture mapping).  An
        image (array, Pillow Image, path) becomes a bilinear, repeated Texture.
    bump : scanline.Texture or image, optional
        A height map (its first channel, 0..1) that perturbs the shading normal
        (Blinn 1978, bump mapping; Hearn & Baker 14-9).
    bump_scale : float
        The height of a bump-map value of 1, in the surface's units per unit of
        texture coordinate.
    environment : scanline.texture.CubeMap, scanline.Texture or image, optional
        The surroundings as a cube map, or a latitude-longitude map (a Texture or
        image), looked up in the direction of the reflected view ray (Hearn & Baker
        14-8, environment mapping); the ray tracer looks it up for every ray that
        leaves the scene from this surface.
    reflectivity : float in 0..1
        k_r: the fraction of the environment (or, when ray tracing, of the light
        along the reflected ray) the surface reflects, added to its intensity,
        tinted by the specular color: k_r S_s I_reflected (the reflected term of
        Whitted's model, Hearn & Baker 14-6, whose coefficient is the specular one).
    refractive_index : float > 0
        eta, the index of refraction of the material behind the surface (1: no
        bending; glass about 1.5): the ray tracer bends transmitted rays by Snell's law
        (Hearn & Baker 14-6).
    roughness : float in 0..pi/2
        Half the angle (radians) of the cone the ray tracer spreads reflected rays
        over: glossy reflection by distributed ray tracing (Cook, Porter and Carpenter
        1984); 0: a perfect mirror.

    Raises
    ------
    ArgumentValueError
        A coefficient outside 0..1, a negative shininess, a refractive index not in
        (0, 100], a roughness outside 0..pi/2.

    Notes
    -----
    The coefficients of the basic illumination model, Hearn & Baker 14-2 (ka, kd,
    ks, n_s), 14-5 (k_t), 14-6 (S_d, S_s, k_r, eta) and 14-8 / 14-9 (the maps).

    Examples
    --------
    >>> import scanline as sl
    >>> m = sl.lighting.Material(kd=0.5, color=(255, 0, 0))
    >>> m.kd, m.color.tolist(), m.specular_color.tolist()
    (0.5, [1.0, 0.0, 0.0], [1.0, 1.0, 1.0])
    """
    ka: float
    kd: float
    ks: float
    shininess: float
    color: NDArray[np.float64]
    specular_color: NDArray[np.float64]
    transparency: float
    texture: Optional["Texture"]
    bump: Optional["Texture"]
    bump_scale: float
    environment: Union["CubeMap", "Texture", None]
    reflectivity: float
    refractive_index: float
    roughness: float

    def __init__(self, ka: float = 0.2, kd: float = 0.7, ks: float = 0.3,
                 shininess: float = 20.0, color: Color = "white",
                 specular_color: Color = "white", transparency: float = 0.0,
                 texture: Union["Texture", "ImageSource", None] = None,
                 bump: Union["Texture", "ImageSource", None] = None,
                 bump_scale: float = 1.0,
                 environment: Union["CubeMap", "Texture", "ImageSource", None] = None,
                 reflectivity: float = 0.0, refractive_index: float = 1.0,
                 roughness: float = 0.0) -> None:
        for name, value in (("ka", ka), ("kd", kd), ("ks", ks), ("transparency", transparency),
                            ("reflectivity", reflectivity)):
            object.__setattr__(self, name, _coefficient(name, value))
        if texture is not None or bump is not None or environment is not None:
            from ..texture.cubemap import environment_of
            from ..texture.texture import texture_of

            object.__setattr__(self, "texture", texture_of("texture", texture))
            object.__setattr__(self, "bump", texture_of("bump", bump))
            object.__setattr__(self, "environment", environment_of("environment", environment))
        else:
            object.__setattr__(self, "texture", None)
            object.__setattr__(self, "bump", None)
            object.__setattr__(self, "environment", None)
        object.__setattr__(self, "bump_scale", v.number("bump_scale", bump_scale))
        eta = v.number("refractive_index", refractive_index)
        if not 0 < eta <= 100:
            raise ArgumentValueError(f"refractive_index must be > 0 and at most 100 (1: air, "
                                     f"1.5: glass, 2.42: diamond), got {refractive_index!r}")
        object.__setattr__(self, "refractive_index", eta)
        rough = v.number("roughness", roughness)
        if not 0 <= rough <= math.pi / 2:
            raise ArgumentValueError(f"roughness must be an angle in 0..pi/2 radians (0: a "
                                     f"mirror), got {roughness!r}")
        object.__setattr__(self, "roughness", rough)
        n = v.number("shininess", shininess)
        if n < 0:
            raise ArgumentValueError(f"shininess must be >= 0 (the specular exponent n_s), got "
                                     f"{shininess!r}")
        object.__setattr__(self, "shininess", n)
        object.__setattr__(self, "color", linear_color("color", color))
        object.__setattr__(self, "specular_color", linear_color("specular_color",
                                                                specular_color))

    def with_color(self, color: Color) -> "Material":
        """The same material in another color.

        Parameters
        ----------
        color : color
            The new surface color S_d.

        Returns
        -------
        Material
            A copy with that color, everything else the same.

        Examples
        --------
        >>> import scanline as sl
        >>> m = sl.lighting.Material(ks=0.5).with_color("blue")
        >>> m.color.tolist(), m.ks
        ([0.0, 0.0, 1.0], 0.5)
        """
        new = object.__new__(Material)
        new.__dict__.update(self.__dict__)
        object.__setattr__(new, "color", linear_color("color", color))
        return new
