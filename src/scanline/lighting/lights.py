"""Light sources (Hearn & Baker, section 14-1 and 14-2): ambient light, distant
(directional) sources, point sources with intensity attenuation and spotlights
(Warn's directed sources).

Every intensity is a gray level or an (r, g, b) triple of non-negative reals, 1.0
being the full intensity of the source (Hearn & Baker's I_l, per color component in
section 14-6).
"""

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..transform3d.arrays import direction as unit_vector
from ..transform3d.arrays import vector


def rgb_intensity(name, value):
    """An intensity as an (3,) float64 array: a number (gray) or 3 numbers, each
    finite and >= 0."""
    if isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool):
        a = np.full(3, float(value))
    else:
        try:
            a = np.asarray(value, np.float64).reshape(-1)
        except (TypeError, ValueError):
            raise ArgumentTypeError(
                f"{name} must be a number or an (r, g, b) triple, got {v._show(value)}"
            ) from None
        if a.shape != (3,):
            raise ArgumentValueError(
                f"{name} must be a number or an (r, g, b) triple, got {v._show(value)}")
    if not (np.isfinite(a).all() and (a >= 0).all()):
        raise ArgumentValueError(
            f"{name} must be finite and >= 0 (0 is darkness, 1 the full intensity), got "
            f"{v._show(value)}")
    return a


def attenuation_coefficients(value):
    """(a0, a1, a2) of f(d) = 1 / (a0 + a1 d + a2 d^2): finite, >= 0, not all 0."""
    try:
        a = tuple(float(x) for x in value)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"attenuation must be (a0, a1, a2), got {v._show(value)}") from None
    if len(a) != 3 or not all(math.isfinite(x) and x >= 0 for x in a) or sum(a) == 0:
        raise ArgumentValueError(
            f"attenuation must be three finite numbers a0, a1, a2 >= 0, not all zero (f(d) "
            f"= 1 / (a0 + a1 d + a2 d^2)), got {v._show(value)}")
    return a


@dataclass(frozen=True, init=False)
class AmbientLight:
    """Background light, the same from every direction: I_a (Hearn & Baker, 14-2,
    "ambient light")."""
    intensity: np.ndarray

    def __init__(self, intensity=0.2):
        object.__setattr__(self, "intensity", rgb_intensity("intensity", intensity))


@dataclass(frozen=True, init=False)
class DirectionalLight:
    """A source at infinity: parallel rays traveling along ``direction`` (so the
    unit vector toward the light is L = -direction), no attenuation."""
    direction: np.ndarray
    intensity: np.ndarray
    shadows: bool

    def __init__(self, direction=(0.0, 0.0, -1.0), intensity=1.0, shadows=False):
        object.__setattr__(self, "direction", unit_vector("direction", direction))
        object.__setattr__(self, "intensity", rgb_intensity("intensity", intensity))
        object.__setattr__(self, "shadows", bool(shadows))


@dataclass(frozen=True, init=False)
class PointLight:
    """A point source at ``position``, radiating equally in all directions, its
    intensity attenuated with the distance d by f(d) = min(1, 1 / (a0 + a1 d + a2
    d^2)) (Hearn & Baker, eq. 14-8; ``attenuation=(1, 0, 0)``: none)."""
    position: np.ndarray
    intensity: np.ndarray
    attenuation: tuple
    shadows: bool

    def __init__(self, position, intensity=1.0, attenuation=(1.0, 0.0, 0.0), shadows=False):
        object.__setattr__(self, "position", np.array(vector("position", position)))
        object.__setattr__(self, "intensity", rgb_intensity("intensity", intensity))
        object.__setattr__(self, "attenuation", attenuation_coefficients(attenuation))
        object.__setattr__(self, "shadows", bool(shadows))


@dataclass(frozen=True, init=False)
class SpotLight:
    """A point source that shines in a cone: along ``direction``, within
    ``angle`` (radians, half the cone's opening) of it, with the intensity falling
    as cos^exponent of the angle off the axis (Warn's model, 1983), and attenuated
    with distance as a :class:`PointLight`."""
    position: np.ndarray
    direction: np.ndarray
    intensity: np.ndarray
    angle: float
    exponent: float
    attenuation: tuple
    shadows: bool

    def __init__(self, position, direction, intensity=1.0, angle=math.radians(30),
                 exponent=1.0, attenuation=(1.0, 0.0, 0.0), shadows=False):
        object.__setattr__(self, "position", np.array(vector("position", position)))
        object.__setattr__(self, "direction", unit_vector("direction", direction))
        object.__setattr__(self, "intensity", rgb_intensity("intensity", intensity))
        a = v.number("angle", angle)
        if not 0 < a <= math.pi / 2:
            raise ArgumentValueError(f"angle must be in (0, pi/2] radians (half the cone), "
                                     f"got {angle!r}")
        e = v.number("exponent", exponent)
        if e < 0:
            raise ArgumentValueError(f"exponent must be >= 0, got {exponent!r}")
        object.__setattr__(self, "angle", a)
        object.__setattr__(self, "exponent", e)
        object.__setattr__(self, "attenuation", attenuation_coefficients(attenuation))
        object.__setattr__(self, "shadows", bool(shadows))


@dataclass(frozen=True, init=False)
class AreaLight(PointLight):
    """A light-emitting parallelogram: the corner ``corner`` and the edges ``edge_u``
    and ``edge_v`` (world vectors), its ``intensity`` shared by its area.

    It lights as a :class:`PointLight` at its center (its ``position``), without
    attenuation; the ray tracer samples it for soft shadows, distributed ray tracing
    (Cook, Porter and Carpenter 1984; Hearn & Baker 14-6): from each point it shades,
    ``samples`` x ``samples`` shadow rays go to jittered points of as many equal cells
    of the parallelogram, and the fraction that reach it scales the light's term (the
    penumbra).
    """
    corner: np.ndarray
    edge_u: np.ndarray
    edge_v: np.ndarray
    samples: int

    def __init__(self, corner, edge_u, edge_v, intensity=1.0, samples=4, shadows=False):
        c = np.array(vector("corner", corner))
        u = np.array(vector("edge_u", edge_u))
        w = np.array(vector("edge_v", edge_v))
        if not np.linalg.norm(np.cross(u, w)) > 0:
            raise ArgumentValueError(f"edge_u and edge_v must span a parallelogram (not "
                                     f"parallel, not zero), got {v._show(edge_u)} and "
                                     f"{v._show(edge_v)}")
        if (not isinstance(samples, (int, np.integer)) or isinstance(samples, bool)
                or not 1 <= samples <= 32):
            raise ArgumentValueError(f"samples must be an integer in 1..32 (shadow rays per "
                                     f"side of the light's grid), got {v._show(samples)}")
        super().__init__(c + (u + w) / 2, intensity=intensity, shadows=shadows)
        object.__setattr__(self, "corner", c)
        object.__setattr__(self, "edge_u", u)
        object.__setattr__(self, "edge_v", w)
        object.__setattr__(self, "samples", int(samples))


LIGHTS = (AmbientLight, DirectionalLight, PointLight, SpotLight)


def light_list(lights):
    """``lights`` as a tuple of light objects, or an error naming the bad one."""
    if lights is None:
        return ()
    return v.one_or_many("lights", lights, LIGHTS,
                         "an AmbientLight, DirectionalLight, PointLight, SpotLight or "
                         "AreaLight from sl.lighting")
