"""The directions and weights of the ray tracer's secondary rays, one ray at a time
(Hearn & Baker 14-6): the mirror direction, Snell's law with total internal
reflection, and the Fresnel reflectance.  These run the tracer's own compiled
helpers (:mod:`scanline._kernels.raytrace`) as Python."""

from typing import Optional, Tuple, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentValueError


def _unit(name: str, value: ArrayLike) -> NDArray[np.float64]:
    a = v.real_array(name, value, "(3,)")
    if a.shape != (3,) or not np.isfinite(a).all() or not np.linalg.norm(a) > 0:
        raise ArgumentValueError(f"{name} must be a finite, non-zero 3-vector, got "
                                 f"{v._show(value)}")
    unit: NDArray[np.float64] = a / np.linalg.norm(a)
    return unit


def _index(name: str, value: float) -> float:
    x = v.number(name, value)
    if not x > 0:
        raise ArgumentValueError(f"{name} must be an index of refraction > 0 (1: air, 1.5: "
                                 f"glass), got {value!r}")
    return x


def _facing(d: NDArray[np.float64], n: NDArray[np.float64]) -> Tuple[NDArray[np.float64], float]:
    """The normal turned to face the incoming direction, and cos i = N . -d."""
    cos_i = -float(d @ n)
    return (n, cos_i) if cos_i >= 0 else (-n, -cos_i)


def reflect(direction: ArrayLike, normal: ArrayLike) -> NDArray[np.float64]:
    """The unit mirror direction of a ray traveling along ``direction`` that meets a
    surface of normal ``normal`` (either side): R = d + 2 (N . -d) N.

    Parameters
    ----------
    direction : array_like (3,)
        The ray's direction (any length, not zero).
    normal : array_like (3,)
        The surface normal (any length, either side).

    Returns
    -------
    ndarray (3,)
        The unit reflected direction.

    Raises
    ------
    ArgumentValueError
        A vector that is not finite, not 3-D, or zero.

    Notes
    -----
    Hearn & Baker 14-6, the specular reflection direction of ray tracing.

    Examples
    --------
    A ray down at 45 degrees onto the floor leaves up at 45 degrees:

    >>> reflect((1, -1, 0), (0, 1, 0)).round(6).tolist()
    [0.707107, 0.707107, 0.0]
    """
    from .._kernels._jit import python
    from .._kernels.raytrace import mirror

    d = _unit("direction", direction)
    n, cos_i = _facing(d, _unit("normal", normal))
    out = np.empty(3)
    python(mirror)(d, n, cos_i, out)
    return out


def fresnel(cos_i: float, n1: float, n2: float) -> float:
    """The fraction of unpolarized light reflected where a ray meets the interface
    from index ``n1`` to ``n2`` at incidence cos i = ``cos_i`` (0..1): the Fresnel
    equations' (r_s^2 + r_p^2) / 2; 1 past the critical angle.

    Parameters
    ----------
    cos_i : float
        The cosine of the incidence angle, 0..1.
    n1, n2 : float
        The indices of refraction before and behind the interface, > 0.

    Returns
    -------
    float
        The reflectance, 0..1 (the transmitted fraction is 1 minus it).

    Raises
    ------
    ArgumentValueError
        ``cos_i`` outside 0..1, or an index not > 0.

    Examples
    --------
    >>> round(fresnel(1.0, 1.0, 1.5), 6)     # ((n1 - n2) / (n1 + n2))^2 head on
    0.04
    """
    from .._kernels._jit import python
    from .._kernels.raytrace import fresnel as kernel

    c = v.number("cos_i", cos_i)
    if not 0 <= c <= 1:
        raise ArgumentValueError(f"cos_i must be the cosine of an incidence angle, 0..1, got "
                                 f"{cos_i!r}")
    reflectance, _ = python(kernel)(c, _index("n1", n1), _index("n2", n2))
    return float(reflectance)


def refract(direction: ArrayLike, normal: ArrayLike, n1: float,
            n2: float) -> Optional[NDArray[np.float64]]:
    """The unit direction of a ray traveling along ``direction`` through the interface
    of normal ``normal`` from index ``n1`` into index ``n2``, by Snell's law (n1 sin
    i = n2 sin t, Hearn & Baker eq. 14-33), or None when it is totally reflected (sin
    t would pass 1: beyond the critical angle asin(n2 / n1)).

    Parameters
    ----------
    direction : array_like (3,)
        The ray's direction (any length, not zero).
    normal : array_like (3,)
        The surface normal (either side).
    n1, n2 : float
        The indices of refraction before and behind the interface, > 0.

    Returns
    -------
    ndarray (3,) or None
        The unit transmitted direction; None under total internal reflection.

    Raises
    ------
    ArgumentValueError
        A bad vector or index.

    Examples
    --------
    Head on the ray goes straight through; from glass into air at a grazing angle
    (sin i = 0.995 > 1 / 1.5) it is totally reflected:

    >>> refract((0, -1, 0), (0, 1, 0), 1.0, 1.5).tolist()
    [0.0, -1.0, 0.0]
    >>> refract((1, -0.1, 0), (0, 1, 0), 1.5, 1.0) is None
    True
    """
    from .._kernels._jit import python
    from .._kernels.raytrace import bend
    from .._kernels.raytrace import fresnel as kernel

    d = _unit("direction", direction)
    n, cos_i = _facing(d, _unit("normal", normal))
    a, b = _index("n1", n1), _index("n2", n2)
    _, cos_t = cast("Tuple[float, float]", python(kernel)(cos_i, a, b))
    if cos_t < 0:
        return None
    out = np.empty(3)
    python(bend)(d, n, a / b, cos_i, cos_t, out)
    return out
