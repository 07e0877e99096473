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

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..transform3d.arrays import direction as unit_vector
from ..transform3d.arrays import vector
from .lights import AmbientLight, DirectionalLight, PointLight, SpotLight, light_list
from .material import Material

SPECULAR = ("phong", "blinn")


@dataclass(frozen=True)
class ViewerAtInfinity:
    """A viewer infinitely far away (a parallel projection): V is the same unit
    vector ``toward`` (from the surface to the viewer) at every point."""
    toward: np.ndarray


def at_infinity(toward):
    """A :class:`ViewerAtInfinity` looking back along ``toward``."""
    return ViewerAtInfinity(unit_vector("toward", toward))


def attenuation(distance, coefficients):
    """Hearn & Baker's radial intensity attenuation f(d) = min(1, 1 / (a0 + a1 d +
    a2 d^2)) (eq. 14-8), elementwise."""
    a0, a1, a2 = coefficients
    d = np.asarray(distance, np.float64)
    with np.errstate(divide="ignore"):
        return np.minimum(1.0, 1.0 / (a0 + a1 * d + a2 * d * d))


def _unit(a):
    n = np.sqrt((a * a).sum(axis=-1, keepdims=True))
    with np.errstate(invalid="ignore", divide="ignore"):
        out = a / n
    return np.where(n > 0, out, 0.0)


def _dot(a, b):
    return (a * b).sum(axis=-1)


def source_terms(light, points):
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


def intensity(point, normal, eye, lights, material, *, specular="phong", color=None,
              visibility=None):
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
    lights = light_list(lights)
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
    out += material.ka * sd * sum((light.intensity for light in lights
                                   if isinstance(light, AmbientLight)), np.zeros(3))
    sources = [light for light in lights if not isinstance(light, AmbientLight)]
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


def depth_cue(intensities, distance, near_distance, far_distance, cue=(1.0, 0.25),
              background=(0.0, 0.0, 0.0)):
    """Depth cueing (Hearn & Baker, section 9-1 and 14-2): the intensities (..., 3)
    blended toward ``background`` with the factor f = f_far + (f_near - f_far)
    (d_max - d) / (d_max - d_min) of the distance d between ``near_distance`` (f =
    ``cue[0]``) and ``far_distance`` (f = ``cue[1]``): I' = f I + (1 - f) I_bg."""
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
            return f * i + (1.0 - f) * bg
        except ValueError:
            raise ArgumentValueError(
                f"intensities (..., 3) and distance (...) must match point for point, got "
                f"shapes {i.shape} and {d.shape}") from None


def transparency(reflected, transmitted, kt):
    """Hearn & Baker's simple transparency (section 14-5): I = (1 - k_t) I_refl +
    k_t I_trans."""
    kt = v.real_array("kt", kt, "(...)")
    if kt.size and (not np.isfinite(kt).all() or kt.min() < 0 or kt.max() > 1):
        raise ArgumentValueError("kt must be in 0..1")
    kt = kt[..., None] if kt.ndim else kt
    reflected = v.real_array("reflected", reflected, "(..., 3)")
    transmitted = v.real_array("transmitted", transmitted, "(..., 3)")
    try:
        return (1.0 - kt) * reflected + kt * transmitted
    except ValueError:
        raise ArgumentValueError(f"reflected, transmitted and kt must match point for point, got "
                                 f"shapes {reflected.shape}, {transmitted.shape} and "
                                 f"{kt.shape}") from None
