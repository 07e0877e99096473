"""Direct motion specification (Hearn & Baker §16-6): the motion given as explicit
functions of time or position.

>>> round(float(bouncing_ball(0.25, amplitude=10, omega=2 * 3.141592653589793)), 6)
10.0
"""

import numpy as np

from .. import _validate as v
from ..errors import ArgumentValueError
from ._checks import finite, floats


def bouncing_ball(x, amplitude=1.0, omega=1.0, theta0=0.0, damping=0.0):
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

    Notes
    -----
    Hearn & Baker, §16-6, "Direct motion specification", eq. 16-6 and Fig. 16-12.
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
        y = a * np.abs(np.sin(w * xs + theta0)) * np.exp(-k * xs)
    if not np.isfinite(y).all():
        raise ArgumentValueError(f"x: the bounce overflows at x = {v._show(x)} (e^(-kx) "
                                 f"beyond 1e308 with damping={k}); give x of a sane size")
    return float(y) if y.ndim == 0 else y


def ballistic(t, position, velocity, gravity=(0.0, -9.81)):
    """Closed-form projectile motion: p(t) = p₀ + v₀ t + g t² / 2 (no drag).

    ``position``, ``velocity`` and ``gravity`` are vectors of one dimension; ``t`` a
    time or an array of times; returns shape ``np.shape(t) + (dim,)``.

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
        out = p0 + v0 * ts + 0.5 * g * ts * ts
    if not np.isfinite(out).all():
        raise ArgumentValueError("t: the position overflows at these times (beyond 1e308); "
                                 "give times, position, velocity and gravity of sane sizes")
    return out
