"""The basic illumination model (Hearn & Baker, section 14-2):

    I = ka Ia + sum over sources of f_l I_l [kd (N . L) + ks (V . R)^n_s]

per color component (section 14-6: kd and ka scaled by the surface color S_d, ks by
the highlight color S_s), with N the unit surface normal, L the unit vector toward
the source, V toward the viewer, R = 2 (N . L) N - L the mirror direction of L
(Phong 1975), or with Blinn's halfway vector H = (L + V) / |L + V| and (N . H)^n_s
(Blinn 1977).  A source behind the surface (N . L <= 0) adds nothing, and no
highlight is seen from behind the mirror direction (V . R <= 0).  f_l is the
attenuation f(d) = min(1, 1 / (a0 + a1 d + a2 d^2)) of a point source (eq. 14-8) times,
for a spotlight, Warn's cos^e of the angle off its axis (zero outside the cone).

The values are linear intensities (1.0: a white surface fully lit); the shading
clamps them to 0..1 and encodes them with the display's gamma
(:func:`scanline.shading.encode`).
"""

from dataclasses import dataclass
from typing import Optional, Sequence, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..transform3d.arrays import direction as unit_vector
from ..transform3d.arrays import vector
from .lights import (AmbientLight, DirectionalLight, Lights, PointLight, SpotLight, Vector3,
                     light_list)
from .material import Material

SPECULAR = ("phong", "blinn")


@dataclass(frozen=True)
class ViewerAtInfinity:
    """A viewer infinitely far away (a parallel projection): V is the same unit
    vector ``toward`` (from the surface to the viewer) at every point.

    Parameters
    ----------
    toward : ndarray (3,)
        The unit vector from the surfaces to the viewer (:func:`at_infinity` makes
        one from any non-zero vector).

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> sl.lighting.ViewerAtInfinity(np.array([0.0, 0.0, 1.0])).toward.tolist()
    [0.0, 0.0, 1.0]
    """
    toward: NDArray[np.float64]


def at_infinity(toward: Vector3) -> ViewerAtInfinity:
    """A :class:`ViewerAtInfinity` looking back along ``toward``.

    Parameters
    ----------
    toward : 3-vector
        Non-zero: the direction from the surfaces to the viewer (normalized here).

    Returns
    -------
    ViewerAtInfinity
        The viewer of a parallel projection (Hearn & Baker 14-2: V constant).

    Examples
    --------
    >>> import scanline as sl
    >>> sl.lighting.at_infinity((0, 0, 2)).toward.tolist()
    [0.0, 0.0, 1.0]
    """
    return ViewerAtInfinity(unit_vector("toward", toward))


def attenuation(distance: ArrayLike, coefficients: Sequence[float]) -> NDArray[np.float64]:
    """Hearn & Baker's radial intensity attenuation f(d) = min(1, 1 / (a0 + a1 d +
    a2 d^2)) (eq. 14-8), elementwise.

    Parameters
    ----------
    distance : array_like
        Distances d from the source.
    coefficients : (a0, a1, a2)
        The attenuation coefficients.

    Returns
    -------
    ndarray
        f(d) at each distance.

    Examples
    --------
    >>> from scanline.lighting import attenuation
    >>> attenuation([0, 1, 2], (1, 0, 1)).tolist()     # 1 / (1 + d^2), at most 1
    [1.0, 0.5, 0.2]
    """
    a0, a1, a2 = coefficients
    d = np.asarray(distance, np.float64)
    with np.errstate(divide="ignore"):
        f: NDArray[np.float64] = np.minimum(1.0, 1.0 / (a0 + a1 * d + a2 * d * d))
    return f


def _unit(a: NDArray[np.float64]) -> NDArray[np.float64]:
    n = np.sqrt((a * a).sum(axis=-1, keepdims=True))
    with np.errstate(invalid="ignore", divide="ignore"):
        out = a / n
    return np.where(n > 0, out, 0.0)


def _dot(a: NDArray[np.float64], b: NDArray[np.float64]) -> NDArray[np.float64]:
    dot: NDArray[np.float64] = (a * b).sum(axis=-1)
    return dot


def source_terms(light: Union[DirectionalLight, PointLight, SpotLight],
                 points: NDArray[np.float64]
                 ) -> Tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(L, factor): unit vectors toward ``light`` (..., 3) and its attenuated
    intensity factor f_l (...,) at ``points``."""
    if isinstance(light, DirectionalLight):
        return np.broadcast_to(-light.direction, points.shape), np.ones(points.shape[:-1])
    to = light.position - points
    d = np.sqrt(_dot(to, to))
    f = attenuation(d, light.attenuation)
    big_l = _unit(to)
    if isinstance(light, SpotLight):
        cos = _dot(-big_l, light.direction)
        inside = cos >= np.cos(light.angle)
        f = f * np.where(inside, np.clip(cos, 0.0, 1.0) ** light.exponent, 0.0)
    return big_l, f


def intensity(point: ArrayLike, normal: ArrayLike, eye: Union[Vector3, ViewerAtInfinity],
              lights: Lights, material: Material, *, specular: str = "phong",
              color: Optional[ArrayLike] = None,
              visibility: Optional[Sequence[ArrayLike]] = None) -> NDArray[np.float64]:
    """The illumination model at points: RGB intensities (..., 3).

    Parameters
    ----------
    point : array_like (..., 3)
        Surface points (world coordinates).
    normal : array_like (..., 3)
        Surface normals there (normalized here).
    eye : 3-vector or ViewerAtInfinity
        The viewer's position (the center of projection), or
        :func:`at_infinity` for a parallel projection.
    lights : light or list of lights
    material : Material
    specular : {"phong", "blinn"}
        (V . R)^n_s (Phong) or (N . H)^n_s (Blinn's halfway vector).
    color : array_like (..., 3), optional
        The surface color S_d per point (linear 0..1), instead of the material's.
    visibility : list of array_like (...,), optional
        Per light, 1 where the point sees the light and 0 in its shadow (a shadow
        map's answer); ambient light ignores it.

    Returns
    -------
    ndarray (..., 3) float64
        The linear intensities, unclamped.

    Raises
    ------
    ArgumentTypeError
        ``material`` not a Material, or a light not a light.
    ArgumentValueError
        Shapes that do not end in 3 or do not broadcast; ``visibility`` not one
        array per non-ambient light; an unknown ``specular``.

    Examples
    --------
    A white surface facing a light straight on, viewed from the light's side:
    ka Ia + kd Il + ks Il = 0.1 * 0.5 + 0.6 * 1 + 0.3 * 1.

    >>> import scanline as sl
    >>> m = sl.lighting.Material(ka=0.1, kd=0.6, ks=0.3, shininess=10)
    >>> lights = [sl.lighting.AmbientLight(0.5), sl.lighting.PointLight((0, 0, 5))]
    >>> sl.lighting.intensity((0, 0, 0), (0, 0, 1), (0, 0, 9), lights, m).round(6).tolist()
    [0.95, 0.95, 0.95]
    """
    if not isinstance(material, Material):
        raise ArgumentTypeError(f"material must be a scanline.lighting.Material, got "
                                f"{v._show(material)}")
    v.choice("specular", specular, SPECULAR)
    all_lights = light_list(lights)
    p = v.real_array("point", point, "(..., 3)")
    n = v.real_array("normal", normal, "(..., 3)")
    if p.shape[-1:] != (3,) or n.shape[-1:] != (3,):
        raise ArgumentValueError(f"point and normal must end in 3 coordinates, got shapes "
                                 f"{p.shape} and {n.shape}")
    try:
        p, n = np.broadcast_arrays(p, n)
    except ValueError:
        raise ArgumentValueError(f"point and normal must have shapes that broadcast (one "
                                 f"normal for all points, or one per point), got {p.shape} "
                                 f"and {n.shape}") from None
    big_n = _unit(n)
    if isinstance(eye, ViewerAtInfinity):
        big_v = np.broadcast_to(eye.toward, p.shape)
    else:
        big_v = _unit(np.array(vector("eye", eye)) - p)
    sd = material.color if color is None else np.asarray(color, np.float64)
    out = np.zeros(p.shape[:-1] + (3,))
    ambient = np.zeros(3)
    for light in all_lights:
        if isinstance(light, AmbientLight):
            ambient = ambient + light.intensity
    out += material.ka * sd * ambient
    sources = [light for light in all_lights if not isinstance(light, AmbientLight)]
    if visibility is not None and len(visibility) != len(sources):
        raise ArgumentValueError(f"visibility must hold one array per non-ambient light "
                                 f"({len(sources)}), got {len(visibility)}")
    for i, light in enumerate(sources):
        big_l, f = source_terms(light, p)
        if visibility is not None:
            f = f * np.asarray(visibility[i], np.float64)
        nl = _dot(big_n, big_l)
        lit = nl > 0
        diffuse = material.kd * np.where(lit, nl, 0.0)
        if specular == "phong":
            r = 2.0 * nl[..., None] * big_n - big_l
            s = _dot(big_v, r)
        else:
            s = _dot(big_n, _unit(big_l + big_v))
        with np.errstate(under="ignore"):
            shine = np.where(lit & (s > 0), np.clip(s, 0.0, 1.0) ** material.shininess, 0.0)
        out += (f[..., None] * light.intensity) * (diffuse[..., None] * sd
                                                    + (material.ks * shine)[..., None]
                                                    * material.specular_color)
    return out


def depth_cue(intensities: ArrayLike, distance: ArrayLike, near_distance: float,
              far_distance: float, cue: Tuple[float, float] = (1.0, 0.25),
              background: ArrayLike = (0.0, 0.0, 0.0)) -> NDArray[np.float64]:
    """Depth cueing (Hearn & Baker, section 9-1 and 14-2): the intensities (..., 3)
    blended toward ``background`` with the factor f = f_far + (f_near - f_far)
    (d_max - d) / (d_max - d_min) of the distance d between ``near_distance`` (f =
    ``cue[0]``) and ``far_distance`` (f = ``cue[1]``): I' = f I + (1 - f) I_bg.

    Parameters
    ----------
    intensities : array_like (..., 3)
        The intensities before cueing.
    distance : array_like (...)
        Each point's distance d.
    near_distance, far_distance : float
        d_min and d_max: f is ``cue[0]`` at and before d_min, ``cue[1]`` at and past
        d_max.
    cue : (near, far)
        The factors, each in 0..1.
    background : array_like (3,)
        I_bg, the intensity blended toward.

    Returns
    -------
    ndarray (..., 3) float64
        The cued intensities.

    Raises
    ------
    ArgumentValueError
        Factors outside 0..1, or intensities and distances that do not match.

    Examples
    --------
    Halfway between d_min = 0 and d_max = 10, f = 0.25 + (1 - 0.25) / 2 = 0.625:

    >>> from scanline.lighting import depth_cue
    >>> depth_cue([[1.0, 1.0, 1.0]], [5.0], 0, 10).tolist()
    [[0.625, 0.625, 0.625]]
    """
    near, far = (v.number("cue", c) for c in cue)
    if not (0 <= near <= 1 and 0 <= far <= 1):
        raise ArgumentValueError(f"cue must be (near, far) factors in 0..1, got {cue!r}")
    near_distance = v.number("near_distance", near_distance)
    far_distance = v.number("far_distance", far_distance)
    d = v.real_array("distance", distance, "(...)")
    i = v.real_array("intensities", intensities, "(..., 3)")
    bg = v.real_array("background", background, "(3,)")
    span = far_distance - near_distance
    with np.errstate(all="ignore"):
        t = np.clip((far_distance - d) / span, 0.0, 1.0) if span > 0 else np.ones_like(d)
        f = (far + (near - far) * t)[..., None]
        try:
            cued: NDArray[np.float64] = f * i + (1.0 - f) * bg
            return cued
        except ValueError:
            raise ArgumentValueError(
                f"intensities (..., 3) and distance (...) must match point for point, got "
                f"shapes {i.shape} and {d.shape}") from None


def transparency(reflected: ArrayLike, transmitted: ArrayLike,
                 kt: ArrayLike) -> NDArray[np.float64]:
    """Hearn & Baker's simple transparency (section 14-5): I = (1 - k_t) I_refl +
    k_t I_trans.

    Parameters
    ----------
    reflected : array_like (..., 3)
        I_refl, the intensity of the transparent surface itself.
    transmitted : array_like (..., 3)
        I_trans, the intensity of what lies behind it.
    kt : array_like (...)
        The transmission coefficients, each in 0..1.

    Returns
    -------
    ndarray (..., 3) float64
        The blended intensities.

    Raises
    ------
    ArgumentValueError
        ``kt`` outside 0..1, or shapes that do not match.

    Examples
    --------
    >>> from scanline.lighting import transparency
    >>> transparency((1.0, 0.0, 0.0), (0.0, 0.0, 1.0), 0.25).tolist()
    [0.75, 0.0, 0.25]
    """
    kt = v.real_array("kt", kt, "(...)")
    if kt.size and (not np.isfinite(kt).all() or kt.min() < 0 or kt.max() > 1):
        raise ArgumentValueError("kt must be in 0..1")
    kt = kt[..., None] if kt.ndim else kt
    reflected = v.real_array("reflected", reflected, "(..., 3)")
    transmitted = v.real_array("transmitted", transmitted, "(..., 3)")
    try:
        blended: NDArray[np.float64] = (1.0 - kt) * reflected + kt * transmitted
        return blended
    except ValueError:
        raise ArgumentValueError(f"reflected, transmitted and kt must match point for point, got "
                                 f"shapes {reflected.shape}, {transmitted.shape} and "
                                 f"{kt.shape}") from None
