"""Continuity of the join of two curve sections (notes, chapter 5, Q.5).

>>> import scanline as sl
>>> a = sl.curves.Bezier([(0, 0), (1, 1), (2, 1), (3, 0)])
>>> b = sl.curves.Bezier([(3, 0), (4, -1), (5, -3), (6, 0)])
>>> sl.curves.continuity(a, b)
Join(C=2, G=2)
>>> c = sl.curves.Bezier([(3, 0), (5, -2), (6, -1), (7, 0)])
>>> sl.curves.continuity(a, c)
Join(C=0, G=1)
"""

from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from .base import Curve


class Join(NamedTuple):
    """Order of parametric (C) and geometric (G) continuity at a join; −1: no join.

    Parameters
    ----------
    C : int
        The order of parametric continuity (up to 2), −1 when not joined.
    G : int
        The order of geometric continuity (up to 2), −1 when not joined.

    Examples
    --------
    >>> import scanline as sl
    >>> j = sl.curves.Join(C=0, G=1)
    >>> str(j), j.G
    ('C0 G1', 1)
    >>> str(sl.curves.Join(-1, -1))
    'not joined'
    """

    C: int
    G: int

    def __str__(self) -> str:
        return f"C{self.C} G{self.G}" if self.C >= 0 else "not joined"


def _close(p: NDArray[np.float64], q: NDArray[np.float64], tol: float) -> bool:
    return bool(np.linalg.norm(p - q)
                <= tol * max(1.0, float(np.linalg.norm(p)), float(np.linalg.norm(q))))


def _curvature_vector(d1: NDArray[np.float64], d2: NDArray[np.float64]) -> NDArray[np.float64]:
    """κN = (P'' − (P''·T)T) / |P'|², T = P'/|P'|: the same for any regular
    reparameterization, so it is what G2 matches."""
    speed2 = float(d1 @ d1)
    tangent = d1 / np.sqrt(speed2)
    kn: NDArray[np.float64] = (d2 - (d2 @ tangent) * tangent) / speed2
    return kn


def continuity(a: Curve, b: Curve, tol: float = 1e-9) -> Join:
    """Classify the join of the end of curve ``a`` with the start of curve ``b``.

    Parameters
    ----------
    a, b : Curve
        Two sections; ``a`` is evaluated at ``a.domain[1]``, ``b`` at ``b.domain[0]``.
    tol : float
        Relative tolerance: two vectors p, q are equal when
        |p − q| ≤ tol · max(1, |p|, |q|).

    Returns
    -------
    Join
        ``Join(C, G)``: the highest orders (up to 2) of parametric and geometric
        continuity; −1 when the sections do not meet.

    Raises
    ------
    ArgumentTypeError
        ``a`` or ``b`` is not a Curve.
    ArgumentValueError
        The curves' dimensions differ, or ``tol`` < 0.

    Notes
    -----
    Notes, ch. 5, Q.5.  Cⁿ: the derivatives of orders 0 … n are equal.  G1: the first
    derivatives are parallel and point the same way (proportional, positive factor).
    G2: G1 and the curvature vectors κN agree (the notes: "curvature of the two
    sections will match"); the second derivatives need not be proportional.  A zero
    first derivative at the join counts as G1 only if the other side is zero too.

    References
    ----------
    B. A. Barsky and T. D. DeRose, "Geometric continuity of parametric curves: three
    equivalent characterizations", *IEEE Computer Graphics and Applications* 9(6),
    60-68, 1989.

    Examples
    --------
    Two quadratic Bezier sections meeting at (2, 0): the end tangent 2 (P2 - P1) =
    (2, -2) of the first and the start tangent (2, -2) of the second agree, the
    second derivatives 2 (P0 - 2 P1 + P2) = (0, -4) and (0, 4) do not:

    >>> import scanline as sl
    >>> a = sl.curves.Bezier([(0, 0), (1, 1), (2, 0)])
    >>> b = sl.curves.Bezier([(2, 0), (3, -1), (4, 0)])
    >>> sl.curves.continuity(a, b)
    Join(C=1, G=1)
    """
    for name, curve in (("a", a), ("b", b)):
        if not isinstance(curve, Curve):
            raise ArgumentTypeError(f"{name} must be a scanline Curve, got {type(curve).__name__}")
    if a.dimension != b.dimension:
        raise ArgumentValueError(
            f"a and b must have the same dimension, got {a.dimension} and {b.dimension}"
        )
    tol = v.number("tol", tol)
    if tol < 0:
        raise ArgumentValueError(f"tol must be >= 0, got {tol!r}")
    da = [a.derivative(k).evaluate(a.domain[1]) for k in range(3)]
    db = [b.derivative(k).evaluate(b.domain[0]) for k in range(3)]
    if not _close(da[0], db[0], tol):
        return Join(-1, -1)
    c = 0
    while c < 2 and _close(da[c + 1], db[c + 1], tol):
        c += 1
    g = 0
    na, nb = float(np.linalg.norm(da[1])), float(np.linalg.norm(db[1]))
    scale = tol * max(1.0, na, nb)
    if na <= scale or nb <= scale:
        g = 1 if (na <= scale and nb <= scale) else 0
        return Join(c, max(g, min(c, 2)))
    if _close(da[1] / na, db[1] / nb, tol):
        g = 1
        if _close(_curvature_vector(da[1], da[2]), _curvature_vector(db[1], db[2]), tol):
            g = 2
    return Join(c, max(g, c))
