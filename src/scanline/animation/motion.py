"""Direct motion specification (Hearn & Baker §16-6): the motion given as explicit
functions of time or position.

>>> round(float(bouncing_ball(0.25, amplitude=10, omega=2 * 3.141592653589793)), 6)
10.0
"""

from typing import Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from ._checks import finite, floats


def bouncing_ball(x: ArrayLike, amplitude: float = 1.0, omega: float = 1.0,
                  theta0: float = 0.0,
                  damping: float = 0.0) -> Union[float, NDArray[np.float64]]:
    """The damped bounce of Hearn & Baker's direct-motion example:
    y(x) = A · |sin(ωx + θ₀)| · e^(−kx).

    Parameters
    ----------
    x : float or array_like
        Horizontal position (or time).
    amplitude : float
        A, the height of the first arch (> 0).
    omega : float
        ω, the angular frequency: a bounce every π/ω (> 0).
    theta0 : float
        θ₀, the phase at x = 0.
    damping : float
        k >= 0, the decay of the arches' heights.

    Returns
    -------
    float or numpy.ndarray
        y, >= 0, of x's shape.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If a parameter is out of range, ``x`` is not finite numbers, or y overflows.

    Notes
    -----
    Hearn & Baker, §16-6, "Direct motion specification", eq. 16-6 and Fig. 16-12.

    Examples
    --------
    The arches touch the ground at x = 0, π/ω, 2π/ω ... and peak at A half way;
    with damping k = ln 2 the second peak (x = 3π/2) is e^(-3π ln 2 / 2) of A:

    >>> import math
    >>> from scanline.animation import bouncing_ball
    >>> bouncing_ball([0, math.pi / 2, math.pi], amplitude=2).round(12).tolist()
    [0.0, 2.0, 0.0]
    >>> k = math.log(2)
    >>> math.isclose(bouncing_ball(3 * math.pi / 2, damping=k), math.exp(-3 * math.pi * k / 2))
    True
    """
    a = v.number("amplitude", amplitude)
    w = v.number("omega", omega)
    k = v.number("damping", damping)
    theta0 = v.number("theta0", theta0)
    if a <= 0 or w <= 0 or k < 0:
        raise ArgumentValueError(
            f"need amplitude > 0, omega > 0 and damping >= 0; got amplitude={a}, omega={w}, "
            f"damping={k}")
    xs = finite("x", x)
    with np.errstate(all="ignore"):
        y: NDArray[np.float64] = a * np.abs(np.sin(w * xs + theta0)) * np.exp(-k * xs)
    if not np.isfinite(y).all():
        raise ArgumentValueError(f"x: the bounce overflows at x = {v._show(x)} (e^(-kx) "
                                 f"beyond 1e308 with damping={k}); give x of a sane size")
    return float(y) if y.ndim == 0 else y


def ballistic(t: ArrayLike, position: ArrayLike, velocity: ArrayLike,
              gravity: ArrayLike = (0.0, -9.81)) -> NDArray[np.float64]:
    """Closed-form projectile motion: p(t) = p₀ + v₀ t + g t² / 2 (no drag).

    ``position``, ``velocity`` and ``gravity`` are vectors of one dimension; ``t`` a
    time or an array of times; returns shape ``np.shape(t) + (dim,)``.

    Parameters
    ----------
    t : float or array_like
        Times.
    position, velocity : array_like, shape (dim,)
        p₀ and v₀ at t = 0, finite.
    gravity : array_like, shape (dim,), default (0, -9.81)
        The constant acceleration g.

    Returns
    -------
    numpy.ndarray, shape ``np.shape(t) + (dim,)``

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If the vectors differ in shape or are not finite, or the positions overflow.

    Notes
    -----
    Direct motion specification, Hearn & Baker, §16-6.

    Examples
    --------
    p(2) = (0 + 3·2, 0 + 10·2 - 10·4/2) = (6, 0):

    >>> from scanline.animation import ballistic
    >>> ballistic(2.0, (0, 0), (3, 10), (0, -10)).tolist()
    [6.0, 0.0]
    """
    p0, v0, g = (floats(n, a, "a vector") for n, a in (("position", position),
                                                          ("velocity", velocity),
                                                          ("gravity", gravity)))
    if not (p0.shape == v0.shape == g.shape and p0.ndim == 1):
        raise ArgumentValueError(
            f"position, velocity and gravity must be vectors of one dimension, got shapes "
            f"{p0.shape}, {v0.shape}, {g.shape}")
    for name, a in (("position", p0), ("velocity", v0), ("gravity", g)):
        if not np.isfinite(a).all():
            raise ArgumentValueError(f"{name} must be finite, got {a.tolist()}")
    ts = finite("t", t)[..., None]
    with np.errstate(over="ignore", invalid="ignore"):
        out: NDArray[np.float64] = p0 + v0 * ts + 0.5 * g * ts * ts
    if not np.isfinite(out).all():
        raise ArgumentValueError("t: the position overflows at these times (beyond 1e308); "
                                 "give times, position, velocity and gravity of sane sizes")
    return out
