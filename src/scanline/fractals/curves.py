"""Self-similar fractal curves built from an initiator and a generator (Hearn & Baker,
section 10-18, "geometric construction of deterministic self-similar fractals").

The initiator is a polyline; the generator is a polyline from (0, 0) to (1, 0).  At
each step every segment of the current curve is replaced by the generator, scaled,
rotated and moved so that its ends fall on the segment's ends.  With n generator
segments of length s each (relative to the segment they replace) the limit has the
similarity dimension D = log n / log(1 / s): log 4 / log 3 = 1.2619 for Koch's curve.

The generator may also be laid on alternate sides of the segments it replaces
(``sides``: +1 on the left, -1 mirrored onto the right, cycling along the curve),
which is how Heighway's dragon folds: left, right, left, right at every step.

The steps are numpy arrays over all segments at once (no Python loop over
segments).

References
----------
.. [1] D. Hearn and M. P. Baker, *Computer Graphics, C Version*, 2nd ed., 1997,
   section 10-18 (Koch curve, fractal dimension).
.. [2] H. von Koch, "Sur une courbe continue sans tangente ...", *Arkiv för
   Matematik* 1, 1904.
.. [3] M. Gardner, "Mathematical games" (Heighway's dragon), *Scientific American*,
   1967; B. B. Mandelbrot, *The Fractal Geometry of Nature*, 1982, chapter 6.
"""

import math
from typing import Optional, Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from . import limits

#: Koch's generator: four segments of a third, the middle two a triangle's sides.
KOCH = np.array([(0.0, 0.0), (1 / 3, 0.0), (0.5, math.sqrt(3) / 6), (2 / 3, 0.0),
                 (1.0, 0.0)])

#: Heighway's dragon: a right-angled bend, laid left and right alternately.
DRAGON = np.array([(0.0, 0.0), (0.5, 0.5), (1.0, 0.0)])
DRAGON_SIDES = (1, -1)


def _polyline(name: str, value: ArrayLike, minimum: int = 2) -> NDArray[np.float64]:
    from ..transform3d.arrays import finite

    a = v.real_array(name, value, "(N, 2)")
    if a.ndim != 2 or a.shape[1] != 2 or len(a) < minimum:
        raise ArgumentValueError(f"{name} must be a polyline of at least {minimum} points, "
                                 f"shape (N, 2), got {v._show(value)}")
    checked: NDArray[np.float64] = finite(name, np.ascontiguousarray(a, np.float64))
    return checked


def self_similar(initiator: ArrayLike, generator: ArrayLike, depth: int,
                 sides: Optional[Sequence[int]] = None) -> NDArray[np.float64]:
    """The curve after ``depth`` replacement steps.

    Parameters
    ----------
    initiator : (M, 2) array_like
        The starting polyline.
    generator : (G + 1, 2) array_like
        A polyline from (0, 0) to (1, 0): the shape that replaces each segment.
    depth : int
        Replacement steps (0 gives the initiator).
    sides : sequence of +1 / -1, optional
        The side of each replaced segment, cycling along the curve: segment j of
        the curve being replaced gets the generator on its left (+1) or mirrored
        onto its right (-1) as ``sides[j % len(sides)]`` says.  Default: all left.

    Returns
    -------
    ndarray, shape ((M - 1) G^depth + 1, 2)
        The polyline's points.

    Raises
    ------
    ArgumentValueError
        A polyline of fewer than 2 points, a generator not from (0, 0) to (1, 0),
        sides other than +1 / -1, or more points than the limits allow.

    Examples
    --------
    One step on a segment of length 3: the generator scaled by 3, the bump's apex at
    height 3 sqrt(3) / 6 = 0.866025.

    >>> import scanline as sl
    >>> sl.fractals.self_similar([(0, 0), (3, 0)], sl.fractals.KOCH, 1).round(6).tolist()
    [[0.0, 0.0], [1.0, 0.0], [1.5, 0.866025], [2.0, 0.0], [3.0, 0.0]]
    """
    start = _polyline("initiator", initiator)
    gen = _polyline("generator", generator)
    if not (np.allclose(gen[0], (0, 0)) and np.allclose(gen[-1], (1, 0))):
        raise ArgumentValueError(f"generator must run from (0, 0) to (1, 0), got "
                                 f"{gen[0].tolist()} to {gen[-1].tolist()}")
    depth = v.positive_int("depth", depth, minimum=0)
    g = len(gen) - 1
    side_of = np.ones(1) if sides is None else np.asarray(sides, np.float64)
    if side_of.ndim != 1 or not len(side_of) or not np.isin(side_of, (-1, 1)).all():
        raise ArgumentValueError(f"sides must be a sequence of +1 and -1 (left, right), got "
                                 f"{v._show(side_of.tolist())}")
    segments = len(start) - 1
    limits.points("depth", segments * limits.power(g, depth) + 1,
                  f"depth={depth} of a {g}-segment generator on {segments} segment(s)",
                  bytes_per_point=16 * 4)
    points = start
    for _ in range(depth):
        p, q = points[:-1], points[1:]
        d = q - p
        side = np.resize(side_of, len(d))
        normal = np.stack([-d[:, 1], d[:, 0]], axis=1) * side[:, None]
        pieces = (p[:, None, :] + gen[None, :-1, 0, None] * d[:, None, :]
                  + gen[None, :-1, 1, None] * normal[:, None, :])
        points = np.vstack([pieces.reshape(-1, 2), points[-1:]])
    return points


def koch(depth: int, closed: bool = False) -> NDArray[np.float64]:
    """Koch's curve on the segment (0, 0)-(1, 0) after ``depth`` steps, or, with
    ``closed``, the snowflake (the generator on the three sides of an equilateral
    triangle, outward).

    Parameters
    ----------
    depth : int
        Replacement steps (Hearn & Baker 10-18).
    closed : bool
        The snowflake instead of the curve.

    Returns
    -------
    ndarray (4^depth + 1, 2), or (3 4^depth + 1, 2) closed
        The polyline's points.

    Raises
    ------
    ArgumentValueError
        A negative depth, or one past the limits.

    Examples
    --------
    Two steps: 4^2 = 16 segments, 17 points.

    >>> import scanline as sl
    >>> len(sl.fractals.koch(2))
    17
    """
    initiator = [(0.0, 0.0), (0.5, -math.sqrt(3) / 2), (1.0, 0.0), (0.0, 0.0)] if closed \
        else [(0.0, 0.0), (1.0, 0.0)]
    if closed:            # clockwise, so that the generator's bump points outward
        initiator = initiator[::-1]
    return self_similar(initiator, KOCH, depth)


def dragon(depth: int) -> NDArray[np.float64]:
    """Heighway's dragon curve on (0, 0)-(1, 0) after ``depth`` steps: 2^depth segments
    of length 2^(-depth/2), each turning a right angle from the one before.

    Parameters
    ----------
    depth : int
        Folding steps.

    Returns
    -------
    ndarray (2^depth + 1, 2)
        The polyline's points.

    Raises
    ------
    ArgumentValueError
        A negative depth, or one past the limits.

    Examples
    --------
    One fold: the segment bent a right angle at its middle, raised to (1/2, 1/2).

    >>> import scanline as sl
    >>> sl.fractals.dragon(1).tolist()
    [[0.0, 0.0], [0.5, 0.5], [1.0, 0.0]]
    """
    return self_similar([(0.0, 0.0), (1.0, 0.0)], DRAGON, depth, sides=DRAGON_SIDES)
