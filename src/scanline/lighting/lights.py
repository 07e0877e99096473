"""Light sources (Hearn & Baker, section 14-1 and 14-2): ambient light, distant
(directional) sources, point sources with intensity attenuation and spotlights
(Warn's directed sources).

Every intensity is a gray level or an (r, g, b) triple of non-negative reals, 1.0
being the full intensity of the source (Hearn & Baker's I_l, per color component in
section 14-6).
"""

import math
from dataclasses import dataclass
from typing import Sequence, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..transform3d.arrays import direction as unit_vector
from ..transform3d.arrays import vector

#: A 3-vector: three numbers, or a (3,) array.
Vector3 = Union[Sequence[float], NDArray[np.float64]]


def rgb_intensity(name: str, value: ArrayLike) -> NDArray[np.float64]:
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


def attenuation_coefficients(value: Sequence[float]) -> Tuple[float, float, float]:
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
    return a[0], a[1], a[2]


@dataclass(frozen=True, init=False)
class AmbientLight:
    """Background light, the same from every direction: I_a (Hearn & Baker, 14-2,
    "ambient light").

    Parameters
    ----------
    intensity : float or (r, g, b)
        I_a: a gray level or a triple, each finite and >= 0 (1: full).

    Raises
    ------
    ArgumentValueError
        A negative or non-finite intensity, or not 1 or 3 numbers.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.lighting.AmbientLight(0.5).intensity.tolist()
    [0.5, 0.5, 0.5]
    """
    intensity: NDArray[np.float64]

    def __init__(self, intensity: ArrayLike = 0.2) -> None:
        object.__setattr__(self, "intensity", rgb_intensity("intensity", intensity))


@dataclass(frozen=True, init=False)
class DirectionalLight:
    """A source at infinity: parallel rays traveling along ``direction`` (so the
    unit vector toward the light is L = -direction), no attenuation (Hearn & Baker
    14-2).

    Parameters
    ----------
    direction : 3-vector
        The direction the light travels (normalized here).
    intensity : float or (r, g, b)
        I_l, finite and >= 0.
    shadows : bool
        Whether the light casts shadows (a shadow map or shadow rays).

    Examples
    --------
    >>> import scanline as sl
    >>> sl.lighting.DirectionalLight(direction=(0, 0, -2)).direction.tolist()
    [0.0, 0.0, -1.0]
    """
    direction: NDArray[np.float64]
    intensity: NDArray[np.float64]
    shadows: bool

    def __init__(self, direction: Vector3 = (0.0, 0.0, -1.0),
                 intensity: ArrayLike = 1.0, shadows: bool = False) -> None:
        object.__setattr__(self, "direction", unit_vector("direction", direction))
        object.__setattr__(self, "intensity", rgb_intensity("intensity", intensity))
        object.__setattr__(self, "shadows", bool(shadows))


@dataclass(frozen=True, init=False)
class PointLight:
    """A point source at ``position``, radiating equally in all directions, its
    intensity attenuated with the distance d by f(d) = min(1, 1 / (a0 + a1 d + a2
    d^2)) (Hearn & Baker, eq. 14-8; ``attenuation=(1, 0, 0)``: none).

    Parameters
    ----------
    position : 3-vector
        The source's world position.
    intensity : float or (r, g, b)
        I_l, finite and >= 0.
    attenuation : (a0, a1, a2)
        The coefficients of f(d), finite, >= 0, not all zero.
    shadows : bool
        Whether the light casts shadows.

    Raises
    ------
    ArgumentValueError
        Bad attenuation coefficients or intensity.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.lighting.PointLight((1, 2, 3), attenuation=(1, 0, 1)).attenuation
    (1.0, 0.0, 1.0)
    """
    position: NDArray[np.float64]
    intensity: NDArray[np.float64]
    attenuation: Tuple[float, float, float]
    shadows: bool

    def __init__(self, position: Vector3, intensity: ArrayLike = 1.0,
                 attenuation: Sequence[float] = (1.0, 0.0, 0.0), shadows: bool = False) -> None:
        object.__setattr__(self, "position", np.array(vector("position", position)))
        object.__setattr__(self, "intensity", rgb_intensity("intensity", intensity))
        object.__setattr__(self, "attenuation", attenuation_coefficients(attenuation))
        object.__setattr__(self, "shadows", bool(shadows))


@dataclass(frozen=True, init=False)
class SpotLight:
    """A point source that shines in a cone: along ``direction``, within
    ``angle`` (radians, half the cone's opening) of it, with the intensity falling
    as cos^exponent of the angle off the axis (Warn's model, 1983), and attenuated
    with distance as a :class:`PointLight` (Hearn & Baker 14-2).

    Parameters
    ----------
    position : 3-vector
        The source's world position.
    direction : 3-vector
        The cone's axis (normalized here).
    intensity : float or (r, g, b)
        I_l, finite and >= 0.
    angle : float
        Half the cone's opening, in (0, pi/2] radians.
    exponent : float
        Warn's exponent e >= 0 of cos^e.
    attenuation : (a0, a1, a2)
        As :class:`PointLight`'s.
    shadows : bool
        Whether the light casts shadows.

    Raises
    ------
    ArgumentValueError
        An angle outside (0, pi/2], a negative exponent, bad attenuation.

    References
    ----------
    Warn, D. R. (1983). Lighting controls for synthetic images. SIGGRAPH '83.

    Examples
    --------
    >>> import math, scanline as sl
    >>> spot = sl.lighting.SpotLight((0, 0, 5), (0, 0, -3), angle=math.pi / 4, exponent=2)
    >>> spot.direction.tolist(), round(spot.angle, 6), spot.exponent
    ([0.0, 0.0, -1.0], 0.785398, 2.0)
    """
    position: NDArray[np.float64]
    direction: NDArray[np.float64]
    intensity: NDArray[np.float64]
    angle: float
    exponent: float
    attenuation: Tuple[float, float, float]
    shadows: bool

    def __init__(self, position: Vector3, direction: Vector3,
                 intensity: ArrayLike = 1.0, angle: float = math.radians(30),
                 exponent: float = 1.0, attenuation: Sequence[float] = (1.0, 0.0, 0.0),
                 shadows: bool = False) -> None:
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

    Parameters
    ----------
    corner : 3-vector
        A corner of the parallelogram.
    edge_u, edge_v : 3-vectors
        Its edges from ``corner`` (not parallel, not zero).
    intensity : float or (r, g, b)
        I_l, finite and >= 0.
    samples : int
        Shadow rays per side of the sampling grid, 1..32.
    shadows : bool
        Whether the light casts shadows.

    Raises
    ------
    ArgumentValueError
        Parallel or zero edges, or samples outside 1..32.

    References
    ----------
    Cook, R. L., Porter, T., Carpenter, L. (1984). Distributed ray tracing. SIGGRAPH '84.

    Examples
    --------
    >>> import scanline as sl
    >>> panel = sl.lighting.AreaLight((0, 0, 4), (2, 0, 0), (0, 2, 0))
    >>> panel.position.tolist(), panel.samples          # lights as a point at its center
    ([1.0, 1.0, 4.0], 4)
    """
    corner: NDArray[np.float64]
    edge_u: NDArray[np.float64]
    edge_v: NDArray[np.float64]
    samples: int

    def __init__(self, corner: Vector3, edge_u: Vector3,
                 edge_v: Vector3, intensity: ArrayLike = 1.0, samples: int = 4,
                 shadows: bool = False) -> None:
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

#: A light source (an AreaLight is a PointLight).
Light = Union[AmbientLight, DirectionalLight, PointLight, SpotLight]
#: Light sources as the renderers take them: one, several, or None.
Lights = Union[Light, Sequence[Light], None]


def light_list(lights: object) -> Tuple[Light, ...]:
    """``lights`` as a tuple of light objects, or an error naming the bad one."""
    if lights is None:
        return ()
    return v.one_or_many("lights", lights, LIGHTS,
                         "an AmbientLight, DirectionalLight, PointLight, SpotLight or "
                         "AreaLight from sl.lighting")
