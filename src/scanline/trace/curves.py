"""Step tables of de Casteljau's algorithm and the Cox–de Boor recursion (notes, ch. 5).

>>> print(de_casteljau([(0, 0), (0, 4), (4, 4), (4, 0)], u=0.5))
de Casteljau's algorithm, degree 3, u = 0.5
P_i^r = (1 - u) P_i^(r-1) + u P_(i+1)^(r-1); P(u) = P_0^3 = (2, 3)
<BLANKLINE>
r  i  x  y
-  -  -  -
0  0  0  0
0  1  0  4
0  2  4  4
0  3  4  0
1  0  0  2
1  1  2  4
1  2  4  2
2  0  1  3
2  1  3  3
3  0  2  3
"""

import numpy as np
from numpy.typing import ArrayLike

from .. import _validate as v
from ..curves.bezier import Bezier
from ..curves.bspline import basis, knot_span
from ..errors import ArgumentTypeError, ArgumentValueError
from .lines import MAX_STEPS
from .table import Table

_AXES = ("x", "y", "z")


def _largest_triangle() -> int:
    """Most control points whose de Casteljau triangle fits in MAX_STEPS rows."""
    n = 1
    while (n + 1) * (n + 2) // 2 <= MAX_STEPS:
        n += 1
    return n


def de_casteljau(points: ArrayLike, u: float = 0.5) -> Table:
    """de Casteljau's triangle at u: every intermediate point Pᵢʳ, level by level.

    Row ``r``, ``i``, ``x``, ``y`` (``z`` for 3-D points): Pᵢʳ = (1 − u)Pᵢʳ⁻¹ + uPᵢ₊₁ʳ⁻¹,
    Pᵢ⁰ = Pᵢ.  The last row, P₀ⁿ, is the curve point P(u) that
    :meth:`scanline.curves.Bezier.evaluate` returns.  The first points of each level
    are the control points of the left half of the subdivided curve, the last points
    those of the right half.

    Parameters
    ----------
    points : array_like
        The n + 1 control points of a degree-n Bézier curve, an (n + 1, 2) or
        (n + 1, 3) array of numbers.
    u : float, optional
        The parameter in [0, 1] (default 0.5, the midpoint subdivision).

    Returns
    -------
    Table
        Columns r, i, x, y (and z for 3-D points), one row per point Pᵢʳ.

    Raises
    ------
    TypeError
        If `points` or `u` is not numeric.
    ValueError
        If the points are not 2-D or 3-D, their triangle would have more than
        `MAX_STEPS` rows, or `u` is outside [0, 1].

    Examples
    --------
    >>> t = de_casteljau([(0, 0), (2, 2)])
    >>> [(r["r"], r["i"], r["x"], r["y"]) for r in t.rows]
    [(0, 0, 0.0, 0.0), (0, 1, 2.0, 2.0), (1, 0, 1.0, 1.0)]
    """
    curve = Bezier(points)
    if curve.dimension > 3:
        raise ArgumentValueError(f"points must be 2-D or 3-D, got {curve.dimension}-D points")
    count = (curve.degree + 1) * (curve.degree + 2) // 2
    if count > MAX_STEPS:
        raise ArgumentValueError(
            f"points: de Casteljau's triangle of {curve.degree + 1} control points has "
            f"{count:,} rows; a trace lists at most {MAX_STEPS:,} (at most "
            f"{_largest_triangle()} control points)")
    triangle = curve.de_casteljau(u)
    u = v.number("u", u)
    axes = _AXES[: curve.dimension]
    rows = [dict({"r": r, "i": i}, **{a: float(c) for a, c in zip(axes, p)})
            for r, level in enumerate(triangle) for i, p in enumerate(level)]
    end = ", ".join(f"{c:g}" for c in triangle[-1][0])
    notes = [f"P_i^r = (1 - u) P_i^(r-1) + u P_(i+1)^(r-1); P(u) = P_0^{curve.degree} = ({end})"]
    return Table(f"de Casteljau's algorithm, degree {curve.degree}, u = {u:g}",
                 ["r", "i", *axes], rows, notes=notes)


def cox_de_boor(knots: ArrayLike, order: int, u: float) -> Table:
    """The Cox–de Boor recursion at u: B_{k,r}(u) for r = 1 … d on u's knot span.

    Rows ``r``, ``k``, ``interval`` (the support [u_k, u_{k+r})) and ``B`` = B_{k,r}(u),
    for the r blending functions of each order r that can be non-zero on the span
    [u_ℓ, u_ℓ₊₁) holding u — the recursion's triangle.  All other B_{k,r}(u) are 0.
    The last r = d rows are the weights that :class:`scanline.curves.BSpline` gives the
    control points P_{ℓ−d+1} … P_ℓ.

    Parameters
    ----------
    knots : array_like
        Non-decreasing knot vector (at least ``order`` + 1 values).
    order : int
        d ≥ 1.
    u : float
        A parameter in [u₀, u_last].

    Returns
    -------
    Table
        Columns r, k, interval, B, one row per blending function of the triangle.

    Raises
    ------
    TypeError
        If `knots`, `order` or `u` is not numeric.
    ValueError
        If `order` < 1, the knots are too few, not finite, decreasing or all equal,
        or `u` is outside [u₀, u_last].

    Examples
    --------
    Order d = 2 (linear pieces) on uniform knots; u = 1.5 lies in span 1, where both
    blending functions weigh 1/2:

    >>> t = cox_de_boor([0, 1, 2, 3], 2, 1.5)
    >>> [(r["r"], r["k"], r["interval"], r["B"]) for r in t.rows]
    [(1, 1, '[1, 2)', 1.0), (2, 0, '[0, 2)', 0.5), (2, 1, '[1, 3)', 0.5)]
    """
    order = v.positive_int("order", order, minimum=1)
    try:
        t = np.array(knots, dtype=np.float64)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"knots must be an array of numbers, got {knots!r}") from None
    if t.ndim != 1 or len(t) < order + 1 or not np.isfinite(t).all():
        raise ArgumentValueError(
            f"knots must be at least order + 1 = {order + 1} finite numbers, got {knots!r}"
        )
    if (np.diff(t) < 0).any() or t[0] == t[-1]:
        raise ArgumentValueError(f"knots must be non-decreasing and not all equal, got {knots!r}")
    u = v.number("u", u)
    if not t[0] <= u <= t[-1]:
        raise ArgumentValueError(f"u must lie in [{t[0]:g}, {t[-1]:g}], got {u!r}")
    span = int(knot_span(t, u))

    def interval(lo: float, hi: float) -> str:
        # the last span is closed, [u_m-1, u_m]: u at the end belongs to it
        return f"[{lo:g}, {hi:g}" + ("]" if hi == t[-1] == u else ")")

    rows = []
    for r in range(1, order + 1):
        values = basis(t, r, u)
        for k in range(max(span - r + 1, 0), min(span, len(values) - 1) + 1):
            rows.append({"r": r, "k": k, "interval": interval(t[k], t[k + r]),
                         "B": float(values[k])})
    notes = [f"knots = [{', '.join(f'{x:g}' for x in t)}], d = {order}, "
             f"u = {u:g} in span {span}: {interval(t[span], t[span + 1])}"
             + (" (the last span is closed at its end)" if u == t[-1] else ""),
             "B_k,1 = 1 on [u_k, u_k+1); B_k,r = (u - u_k)/(u_k+r-1 - u_k) B_k,r-1 "
             "+ (u_k+r - u)/(u_k+r - u_k+1) B_k+1,r-1 (0/0 = 0)"]
    return Table(f"Cox-de Boor recursion, order {order}, u = {u:g}",
                 ["r", "k", "interval", "B"], rows, notes=notes)
