"""Characteristic matrices of cubic curves, derived exactly (notes, chapter 5).

Each cubic section is written P(u) = [u³ u² u 1] · M · G, G the geometry (control
points, or end points and tangents).  The matrices are *derived* here in exact rational
arithmetic rather than copied: the notes print the Bezier matrix and the periodic
B-spline matrix wrongly (docs/errata.md, E40 and E41).

>>> bezier_matrix()
array([[-1.,  3., -3.,  1.],
       [ 3., -6.,  3.,  0.],
       [-3.,  3.,  0.,  0.],
       [ 1.,  0.,  0.,  0.]])
>>> 6 * bspline_matrix()
array([[-1.,  3., -3.,  1.],
       [ 3., -6.,  3.,  0.],
       [-3.,  0.,  3.,  0.],
       [ 1.,  4.,  1.,  0.]])
>>> hermite_matrix()
array([[ 2., -2.,  1.,  1.],
       [-3.,  3., -2., -1.],
       [ 0.,  0.,  1.,  0.],
       [ 1.,  0.,  0.,  0.]])
"""

from fractions import Fraction
from functools import lru_cache
from typing import Iterable, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentValueError

#: The notes' Hermite boundary-constraint matrix (ch. 5, Q.3, eq. 5): rows give
#: P(0), P(1), P'(0), P'(1) from the coefficients [a b c d] of au³ + bu² + cu + d.
HERMITE_CONSTRAINTS = ((0, 0, 0, 1), (1, 1, 1, 1), (0, 0, 1, 0), (3, 2, 1, 0))

#: Highest degree of the derived matrices: the exact derivation costs O(n⁴) Fraction
#: operations (about a second at 40), and beyond it the power form has lost every
#: digit to cancellation anyway (its entries reach C(n, n/2)²).
MAX_DEGREE = 40

#: A polynomial c0 + c1 t + ... as its exact coefficients; a matrix as rows of floats.
Polynomial = list[Fraction]
Matrix = tuple[tuple[float, ...], ...]


def span_polynomials(knots: Iterable[Union[int, float, Fraction]], order: int, span: int
                     ) -> list[Polynomial]:
    """Exact Cox–de Boor blending functions on one knot span, as polynomials.

    Returns a list ``B`` with ``B[k][p]`` the coefficient of tᵖ in B_{k,order}(u_span + t)
    for k = span - order + 1 ... span (the blending functions not identically zero
    on [u_span, u_span+1]); Fractions throughout.
    """
    u = [Fraction(x) for x in knots]
    origin = u[span]

    def lin(c0: Fraction, c1: Fraction) -> Polynomial:  # the polynomial c0 + c1 t
        return [Fraction(c0), Fraction(c1)]

    def mul(p: Polynomial, q: Polynomial) -> Polynomial:
        r = [Fraction(0)] * (len(p) + len(q) - 1)
        for i, a in enumerate(p):
            for j, b in enumerate(q):
                r[i + j] += a * b
        return r

    def add(p: Polynomial, q: Polynomial) -> Polynomial:
        n = max(len(p), len(q))
        zero = Fraction(0)
        return [(p[i] if i < len(p) else zero) + (q[i] if i < len(q) else zero) for i in range(n)]

    # level 1: B_{k,1} = 1 on [u_k, u_k+1): only k == span is non-zero here
    basis = {k: [Fraction(int(k == span))] for k in range(len(u) - 1)}
    for d in range(2, order + 1):
        nxt: dict[int, Polynomial] = {}
        for k in range(len(u) - d):
            term = [Fraction(0)]
            den = u[k + d - 1] - u[k]
            if den:  # 0/0 is taken as 0
                term = add(term, mul(lin((origin - u[k]) / den, 1 / den), basis[k]))
            den = u[k + d] - u[k + 1]
            if den:
                term = add(term, mul(lin((u[k + d] - origin) / den, -1 / den), basis[k + 1]))
            nxt[k] = term
        basis = nxt
    return [basis[k] + [Fraction(0)] * (order - len(basis[k]))
            for k in range(span - order + 1, span + 1)]


def _matrix(polys: list[Polynomial]) -> Matrix:
    """[u^(n) ... u 1] · M = blending functions: row i holds the u^(n-i) coefficients."""
    n = len(polys)
    return tuple(tuple(float(polys[k][n - 1 - i]) for k in range(n)) for i in range(n))


@lru_cache(maxsize=64)
def _bezier(n: int) -> Matrix:
    return _matrix(span_polynomials([0] * (n + 1) + [1] * (n + 1), n + 1, n))


@lru_cache(maxsize=64)
def _bspline(d: int) -> Matrix:
    return _matrix(span_polynomials(range(2 * d), d, d - 1))


def bezier_matrix(degree: int = 3) -> NDArray[np.float64]:
    """M_bez, with P(u) = [uⁿ … u 1] · M_bez · [P₀ … Pₙ]ᵀ for a degree-n Bezier curve.

    Derived from the Bernstein polynomials, which are the Cox–de Boor functions of the
    knot vector [0ⁿ⁺¹ 1ⁿ⁺¹].  For n = 3 the first row is [-1 3 -3 1]; the notes print
    [1 0 -3 1] (erratum E40).

    Parameters
    ----------
    degree : int
        n, 1 … ``MAX_DEGREE`` (40).

    Returns
    -------
    ndarray of float64, shape (n + 1, n + 1)
        Row i holds the coefficients of u^(n - i) of the blending functions.

    Raises
    ------
    ArgumentValueError
        ``degree`` is not an integer in 1 … 40.

    Examples
    --------
    The quadratic: (1 - u)² = u² - 2u + 1, 2u(1 - u) = -2u² + 2u, u²:

    >>> import scanline as sl
    >>> sl.curves.bezier_matrix(2).tolist()
    [[1.0, -2.0, 1.0], [-2.0, 2.0, 0.0], [1.0, 0.0, 0.0]]
    """
    degree = v.positive_int("degree", degree, minimum=1)
    if degree > MAX_DEGREE:
        raise ArgumentValueError(
            f"degree={degree} is above {MAX_DEGREE}: the power form of a curve this high is "
            "useless in floating point; evaluate it by de Casteljau's algorithm")
    return np.array(_bezier(degree))


def bspline_matrix(order: int = 4) -> NDArray[np.float64]:
    """M_B of the uniform periodic B-spline: P(u) = [u^(d-1) … u 1] · M_B · [P₀ … P_{d-1}]ᵀ.

    Derived by the Cox–de Boor recursion on the integer knots 0, 1, …, 2d−1 over the
    span [d−1, d].  For d = 4 it is ⅙[[-1 3 -3 1] [3 -6 3 0] [-3 0 3 0] [1 4 1 0]];
    the notes print ⅙ times the Bezier matrix, itself misprinted (erratum E41).

    Parameters
    ----------
    order : int
        d (degree d − 1), 2 … ``MAX_DEGREE`` + 1.

    Returns
    -------
    ndarray of float64, shape (d, d)
        Row i holds the coefficients of u^(d - 1 - i) of the blending functions.

    Raises
    ------
    ArgumentValueError
        ``order`` is not an integer in 2 … 41.

    Examples
    --------
    The quadratic uniform B-spline (d = 3): ½[(1 - u)², -2u² + 2u + 1, u²]:

    >>> import scanline as sl
    >>> (2 * sl.curves.bspline_matrix(3)).tolist()
    [[1.0, -2.0, 1.0], [-2.0, 2.0, 0.0], [1.0, 1.0, 0.0]]
    """
    order = v.positive_int("order", order, minimum=2)
    if order > MAX_DEGREE + 1:
        raise ArgumentValueError(
            f"order={order} is above {MAX_DEGREE + 1}: the power form of a curve this high "
            "is useless in floating point; evaluate it by de Boor's algorithm")
    return np.array(_bspline(order))


@lru_cache(maxsize=8)
def _inverse(rows: tuple[tuple[int, ...], ...]) -> list[list[Fraction]]:
    """Exact inverse of a small invertible matrix (Gauss–Jordan on Fractions)."""
    n = len(rows)
    a = [[Fraction(x) for x in row] + [Fraction(int(i == j)) for j in range(n)]
         for i, row in enumerate(rows)]
    for col in range(n):
        pivot = next(r for r in range(col, n) if a[r][col] != 0)
        a[col], a[pivot] = a[pivot], a[col]
        p = a[col][col]
        a[col] = [x / p for x in a[col]]
        for r in range(n):
            if r != col and a[r][col] != 0:
                f = a[r][col]
                a[r] = [x - f * y for x, y in zip(a[r], a[col])]
    return [row[n:] for row in a]


def hermite_matrix() -> NDArray[np.float64]:
    """M_H, the inverse of the notes' boundary-constraint matrix (ch. 5, Q.3, eq. 6).

    P(u) = [u³ u² u 1] · M_H · [P_k, P_k+1, DP_k, DP_k+1]ᵀ.

    Returns
    -------
    ndarray of float64, shape (4, 4)
        M_H (Hearn & Baker, section 10-8, eq. 10-26).

    Examples
    --------
    >>> import scanline as sl
    >>> sl.curves.hermite_matrix()[0].tolist()
    [2.0, -2.0, 1.0, 1.0]
    """
    return np.array([[float(x) for x in row] for row in _inverse(HERMITE_CONSTRAINTS)])


def cardinal_matrix(tension: float = 0.0) -> NDArray[np.float64]:
    """M_C of the cardinal spline, P(u) = [u³ u² u 1] · M_C · [P_k-1 P_k P_k+1 P_k+2]ᵀ.

    With s = (1 − t)/2: M_C = M_H · G, where G maps the four points to
    [P_k, P_k+1, s(P_k+1 − P_k-1), s(P_k+2 − P_k)] (Hearn & Baker, §10-8).
    ``tension`` t = 0 gives the Catmull–Rom spline.

    Parameters
    ----------
    tension : float
        t; 0 is Catmull–Rom.

    Returns
    -------
    ndarray of float64, shape (4, 4)
        M_C.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        ``tension`` is not a finite number.

    Examples
    --------
    Catmull–Rom (s = ½), Hearn & Baker eq. 10-30's first row [-s, 2 - s, s - 2, s]:

    >>> import scanline as sl
    >>> sl.curves.cardinal_matrix(0.0)[0].tolist()
    [-0.5, 1.5, -1.5, 0.5]
    """
    s = (1.0 - v.number("tension", tension)) / 2
    geometry = np.array([[0, 1, 0, 0], [0, 0, 1, 0], [-s, 0, s, 0], [0, -s, 0, s]])
    m_c: NDArray[np.float64] = hermite_matrix() @ geometry
    return m_c

