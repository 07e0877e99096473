"""Easing functions: how a key-frame segment's time fraction maps to its progress.

An easing function takes the fraction ``t`` of a segment's time that has passed
(0 at the first key frame, 1 at the second) and returns the fraction of the change
that has happened.  Hearn & Baker (section 16-5, "Simulating accelerations") simulate
acceleration by the *spacing* of the in-between frames; spacing the in-betweens by a
function of ``j/(n + 1)`` is the same as easing, and their four laws are here under
their names:

===========================  ========================  ==========================
Hearn & Baker                 formula                   also known as
===========================  ========================  ==========================
``"constant"``                t                         ``"linear"``
``"accelerate"``              1 - cos(t pi / 2)          ``"ease-in-sine"``
``"decelerate"``              sin(t pi / 2)              ``"ease-out-sine"``
``"accelerate-decelerate"``   (1 - cos(t pi)) / 2        ``"ease-in-out-sine"``
===========================  ========================  ==========================

The rest of the catalog is Robert Penner's set, the one CSS, jQuery UI, GSAP and
most animation tools ship: ``ease-in-``, ``ease-out-`` and ``ease-in-out-`` of
``quad``, ``cubic``, ``quart``, ``quint``, ``sine``, ``expo``, ``circ``, ``back``,
``elastic`` and ``bounce``; and :func:`cubic_bezier`, the CSS timing function.

Every easing maps 0 to 0 and 1 to 1 exactly (``back`` and ``elastic`` overshoot in
between, ``bounce`` touches 1 several times).

>>> ease("ease-in-quad", [0.0, 0.5, 1.0]).tolist()
[0.0, 0.25, 1.0]
>>> round(ease("accelerate-decelerate", 0.5), 12)
0.5

References
----------
R. Penner, *Robert Penner's Programming Macromedia Flash MX*, chapter 7, "Motion,
Tweening, and Easing", McGraw-Hill, 2002.  D. Hearn and M. P. Baker, *Computer
Graphics, C Version*, 2nd ed., section 16-5.
"""

import math
from collections.abc import Callable
from typing import Any, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validate import _show
from ..errors import ArgumentTypeError, ArgumentValueError

#: An easing function: time fractions (an array) in, fractions of the change out.
Easing = Callable[[NDArray[np.float64]], Any]

_HALF_PI = math.pi / 2
_C1 = 1.70158                 # Penner's "back" overshoot (10 % overshoot)
_C2 = _C1 * 1.525
_C3 = _C1 + 1
_C4 = 2 * math.pi / 3          # elastic period, ease-in / ease-out
_C5 = 2 * math.pi / 4.5        # elastic period, ease-in-out


def _linear(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return t


def _sine_in(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return 1 - np.cos(t * _HALF_PI)


def _sine_out(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return np.sin(t * _HALF_PI)


def _sine_in_out(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return (1 - np.cos(math.pi * t)) / 2


def _power(k: int) -> tuple[Easing, Easing, Easing]:
    """ease-in, ease-out and ease-in-out of t**k (quad k = 2 ... quint k = 5)."""
    def ease_in(t: NDArray[np.float64]) -> NDArray[np.float64]:
        return t ** k

    def ease_out(t: NDArray[np.float64]) -> NDArray[np.float64]:
        return 1 - (1 - t) ** k

    def ease_in_out(t: NDArray[np.float64]) -> NDArray[np.float64]:
        return np.where(t < 0.5, 2 ** (k - 1) * t ** k, 1 - (2 - 2 * t) ** k / 2)
    return ease_in, ease_out, ease_in_out


def _expo_in(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return np.where(t == 0, 0.0, 2.0 ** (10 * t - 10))


def _expo_out(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return np.where(t == 1, 1.0, 1 - 2.0 ** (-10 * t))


def _expo_in_out(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return np.where(t < 0.5, 2.0 ** (20 * t - 10) / 2, (2 - 2.0 ** (10 - 20 * t)) / 2)


def _circ_in(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return 1 - np.sqrt(1 - t * t)


def _circ_out(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return np.sqrt(1 - (t - 1) ** 2)


def _circ_in_out(t: NDArray[np.float64]) -> NDArray[np.float64]:
    lo = (1 - np.sqrt(np.clip(1 - (2 * t) ** 2, 0, 1))) / 2
    hi = (np.sqrt(np.clip(1 - (2 - 2 * t) ** 2, 0, 1)) + 1) / 2
    return np.where(t < 0.5, lo, hi)


def _back_in(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return _C3 * t ** 3 - _C1 * t ** 2


def _back_out(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return 1 + _C3 * (t - 1) ** 3 + _C1 * (t - 1) ** 2


def _back_in_out(t: NDArray[np.float64]) -> NDArray[np.float64]:
    u = 2 * t
    lo = u ** 2 * ((_C2 + 1) * u - _C2) / 2
    hi = ((u - 2) ** 2 * ((_C2 + 1) * (u - 2) + _C2) + 2) / 2
    return np.where(t < 0.5, lo, hi)


def _elastic_in(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return -(2.0 ** (10 * t - 10)) * np.sin((10 * t - 10.75) * _C4)


def _elastic_out(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return 2.0 ** (-10 * t) * np.sin((10 * t - 0.75) * _C4) + 1


def _elastic_in_out(t: NDArray[np.float64]) -> NDArray[np.float64]:
    s = np.sin((20 * t - 11.125) * _C5)
    return np.where(t < 0.5, -(2.0 ** (20 * t - 10)) * s / 2, 2.0 ** (10 - 20 * t) * s / 2 + 1)


def _bounce_out(t: NDArray[np.float64]) -> NDArray[np.float64]:
    n1, d1 = 7.5625, 2.75
    return np.select(
        [t < 1 / d1, t < 2 / d1, t < 2.5 / d1],
        [n1 * t * t, n1 * (t - 1.5 / d1) ** 2 + 0.75, n1 * (t - 2.25 / d1) ** 2 + 0.9375],
        n1 * (t - 2.625 / d1) ** 2 + 0.984375)


def _bounce_in(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return 1 - _bounce_out(1 - t)


def _bounce_in_out(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return np.where(t < 0.5, (1 - _bounce_out(1 - 2 * t)) / 2, (1 + _bounce_out(2 * t - 1)) / 2)


def _catalog() -> dict[str, Easing]:
    table: dict[str, Easing] = {"linear": _linear}
    families: dict[str, tuple[Easing, Easing, Easing]] = {
        "sine": (_sine_in, _sine_out, _sine_in_out),
        "quad": _power(2), "cubic": _power(3), "quart": _power(4), "quint": _power(5),
        "expo": (_expo_in, _expo_out, _expo_in_out),
        "circ": (_circ_in, _circ_out, _circ_in_out),
        "back": (_back_in, _back_out, _back_in_out),
        "elastic": (_elastic_in, _elastic_out, _elastic_in_out),
        "bounce": (_bounce_in, _bounce_out, _bounce_in_out),
    }
    for family, functions in families.items():
        for kind, fn in zip(("in", "out", "in-out"), functions):
            table[f"ease-{kind}-{family}"] = fn
    # Hearn & Baker's spacing laws (section 16-5) are the sine easings
    table["constant"] = _linear
    table["accelerate"] = _sine_in
    table["decelerate"] = _sine_out
    table["accelerate-decelerate"] = _sine_in_out
    return table


#: Every easing by name.
EASINGS = _catalog()

#: Hearn & Baker's in-between spacing laws (section 16-5), a subset of :data:`EASINGS`.
SPACINGS = ("constant", "accelerate", "decelerate", "accelerate-decelerate")


def resolve(name: Union[str, Easing], argument: str = "ease") -> Easing:
    """The easing function of ``name`` (a catalog name or a callable), checked.

    A callable must map an array of fractions in [0, 1] to an array of the same
    shape; it is called once here on [0, 1] to check that it maps 0 to 0 and 1 to 1.
    """
    if callable(name):
        try:
            ends = np.asarray(name(np.array([0.0, 1.0])), dtype=np.float64)
        except Exception as error:  # a user function: report whatever it raised
            raise ArgumentValueError(
                f"{argument}={_show(name)} failed on [0, 1]: {error!r}") from None
        if ends.shape != (2,) or not np.allclose(ends, [0.0, 1.0], atol=1e-9):
            raise ArgumentValueError(
                f"{argument}={_show(name)} must map 0 to 0 and 1 to 1 (an array in, an array "
                f"of the same shape out); it gave {_show(ends.tolist())}")
        return name
    if isinstance(name, str) and name in EASINGS:
        return EASINGS[name]
    if not isinstance(name, str):
        raise ArgumentTypeError(
            f"{argument} must be an easing name or a function, got {_show(name)}")
    close = [n for n in EASINGS if name.replace("_", "-").lower() in n][:6]
    hint = f"; did you mean {', '.join(repr(n) for n in close)}?" if close else ""
    raise ArgumentValueError(
        f"{argument}={name!r} is not an easing; use 'linear', a Hearn & Baker spacing "
        f"({', '.join(SPACINGS)}) or 'ease-in-', 'ease-out-', 'ease-in-out-' followed by "
        f"quad, cubic, quart, quint, sine, expo, circ, back, elastic or bounce{hint}")


def fractions(t: ArrayLike, name: str = "t") -> NDArray[np.float64]:
    """``t`` as a float64 array of fractions in [0, 1], or an error naming ``name``."""
    from ._checks import floats

    a = floats(name, t)
    if a.size and not ((a >= 0) & (a <= 1)).all():   # also catches NaN
        bad = float(a[~((a >= 0) & (a <= 1))].ravel()[0])
        raise ArgumentValueError(f"{name} must lie in [0, 1] (the fraction of the segment's "
                                 f"time), got {bad!r}")
    return a


def apply(function: Easing, t: NDArray[np.float64]) -> NDArray[np.float64]:
    """``function`` applied to checked fractions ``t``, with 0 -> 0 and 1 -> 1 exact."""
    with np.errstate(all="ignore"):
        out = np.asarray(function(t), dtype=np.float64)
    exact: NDArray[np.float64] = np.where(t == 0, 0.0, np.where(t == 1, 1.0, out))
    return exact


def ease(name: Union[str, Easing], t: ArrayLike) -> Union[float, NDArray[np.float64]]:
    """The easing ``name`` at the time fractions ``t``.

    Parameters
    ----------
    name : str or callable
        A name from :data:`EASINGS` (``"linear"``, ``"ease-in-quad"``,
        ``"ease-out-bounce"``, ``"accelerate"`` ...) or a function of an array.
    t : float or array_like
        Fractions of the segment's time, each in [0, 1].

    Returns
    -------
    float or numpy.ndarray
        The fractions of the change: a float for a scalar ``t``, else an array of
        ``t``'s shape.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``name`` is neither an easing name nor a function mapping 0 to 0 and 1 to
        1, or a fraction lies outside [0, 1].

    Notes
    -----
    Hearn & Baker, section 16-5 (spacing the in-betweens to simulate acceleration);
    Penner 2002 (the catalog).

    Examples
    --------
    >>> round(float(ease("ease-out-bounce", 0.5)), 6)
    0.765625
    >>> ease("ease-in-out-cubic", [0.25, 0.75]).tolist()
    [0.0625, 0.9375]
    """
    function = resolve(name, "name")
    a = fractions(t)
    out = apply(function, a)
    return float(out) if out.ndim == 0 else out


def cubic_bezier(x1: float, y1: float, x2: float, y2: float) -> Easing:
    """The CSS timing function ``cubic-bezier(x1, y1, x2, y2)`` as an easing.

    The curve runs from (0, 0) to (1, 1) with control points (x1, y1) and (x2, y2);
    for a time fraction t it returns y where x(s) = t.  x1 and x2 must lie in [0, 1]
    (so that x is monotone); y1 and y2 may overshoot.  ``cubic_bezier(0.25, 0.1,
    0.25, 1)`` is CSS's ``ease``.

    Parameters
    ----------
    x1, y1 : float
        The first control point; 0 <= x1 <= 1.
    x2, y2 : float
        The second control point; 0 <= x2 <= 1.

    Returns
    -------
    callable
        The easing: an array of time fractions in, progress out.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If a coordinate is not a finite number or x1, x2 lie outside [0, 1].

    References
    ----------
    W3C, *CSS Easing Functions Level 1*, section 2.2, "Cubic Bézier easing functions".

    Examples
    --------
    ``cubic_bezier(0, 0, 1, 1)`` is the straight line, linear easing:

    >>> round(float(ease(cubic_bezier(0, 0, 1, 1), 0.3)), 9)
    0.3
    >>> css_ease = cubic_bezier(0.25, 0.1, 0.25, 1.0)
    >>> round(float(ease(css_ease, 0.5)), 4)
    0.8024
    """
    from .. import _validate as v

    x1, y1, x2, y2 = (v.number(n, c) for n, c in (("x1", x1), ("y1", y1), ("x2", x2),
                                                    ("y2", y2)))
    for n, c in (("x1", x1), ("x2", x2)):
        if not 0 <= c <= 1:
            raise ArgumentValueError(f"{n} must lie in [0, 1] so that time runs forward, got {c}")

    def coordinate(s: NDArray[np.float64], p1: float, p2: float) -> NDArray[np.float64]:
        return 3 * (1 - s) ** 2 * s * p1 + 3 * (1 - s) * s * s * p2 + s ** 3

    def timing(t: NDArray[np.float64]) -> NDArray[np.float64]:
        t = np.asarray(t, dtype=np.float64)
        lo, hi = np.zeros_like(t), np.ones_like(t)
        for _ in range(60):            # bisection: x(s) is monotone, 2**-60 is exact
            mid = (lo + hi) / 2
            below = coordinate(mid, x1, x2) < t
            lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
        return coordinate((lo + hi) / 2, y1, y2)

    timing.__name__ = f"cubic_bezier({x1:g}, {y1:g}, {x2:g}, {y2:g})"
    return timing
