"""Bezier curves of any degree, plain and rational (notes, chapter 5, Q.1).

>>> import scanline as sl
>>> c = sl.curves.Bezier([(0, 0), (1, 2), (3, 2), (4, 0)])
>>> c.evaluate(0.5)
array([2. , 1.5])
>>> c.evaluate([0, 0.5, 1], method="bernstein").tolist()
[[0.0, 0.0], [2.0, 1.5], [4.0, 0.0]]
"""

from math import comb
from typing import Optional, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from .._kernels import curves as _k
from .._kernels._jit import call
from .base import Curve, control_points, parameters, weights_array
from .matrices import MAX_DEGREE, bezier_matrix
from .rational import RationalDerivative, Weighted, project

METHODS = ("de-casteljau", "bernstein", "recursive", "matrix")

#: Highest degree evaluated by default in the matrix (power) form: up to it Horner's
#: rule on M_bez·P is both the fastest and accurate to ~1e-15 of the coordinates'
#: scale; above it de Casteljau's algorithm is better conditioned.
MATRIX_DEGREE = 6

#: Highest degree whose binomial coefficients C(n, k) all fit in a float64
#: (C(1030, 515) overflows): above it ``method="bernstein"`` is refused.
BERNSTEIN_DEGREE = 1029

#: Highest degree :meth:`Bezier.elevate` builds (each step costs O(n); the loop
#: would otherwise run for as long as a huge ``times`` asks).
ELEVATE_DEGREE = 10_000


def bernstein(degree: int, u: ArrayLike) -> NDArray[np.float64]:
    """The Bezier blending functions BEZ_{k,n}(u) = C(n, k) uᵏ (1 − u)ⁿ⁻ᵏ, k = 0 … n.

    Notes, ch. 5, Q.1, eqs. 2–3.  Returns shape ``np.shape(u) + (n + 1,)``.

    Parameters
    ----------
    degree : int
        n >= 0, at most ``BERNSTEIN_DEGREE`` (1029).
    u : float or array_like of float
        Parameter values.

    Returns
    -------
    ndarray of float64, shape ``np.shape(u) + (n + 1,)``
        BEZ_{0,n}(u) … BEZ_{n,n}(u).

    Raises
    ------
    ArgumentValueError
        ``degree`` is not an integer >= 0, or above ``BERNSTEIN_DEGREE``.

    Examples
    --------
    Cubic blending at u = 1/2: C(3, k) / 8:

    >>> import scanline as sl
    >>> sl.curves.bernstein(3, 0.5).tolist()
    [0.125, 0.375, 0.375, 0.125]
    """
    n = v.positive_int("degree", degree, minimum=0)
    if n > BERNSTEIN_DEGREE:
        raise ArgumentValueError(
            f"degree={n}: the binomial coefficients of eq. 3 overflow float64 above degree "
            f"{BERNSTEIN_DEGREE}; use method='de-casteljau' or 'recursive'")
    t = np.asarray(u, dtype=np.float64)[..., None]
    k = np.arange(n + 1)
    binomial = np.array([comb(n, i) for i in k], dtype=np.float64)
    blend: NDArray[np.float64] = binomial * t**k * (1.0 - t) ** (n - k)
    return blend


def bernstein_recursive(degree: int, u: ArrayLike) -> NDArray[np.float64]:
    """BEZ_{k,n}(u) by the notes' recursion (ch. 5, Q.1, eq. 4).

    BEZ_{k,n} = (1 − u) BEZ_{k,n−1} + u BEZ_{k−1,n−1}, starting from BEZ_{0,0} = 1 and
    taking BEZ_{k,m} = 0 for k < 0 or k > m (the base cases the notes leave out,
    erratum E42).  Returns shape ``np.shape(u) + (n + 1,)``.

    Parameters
    ----------
    degree : int
        n >= 0.
    u : float or array_like of float
        Parameter values.

    Returns
    -------
    ndarray of float64, shape ``np.shape(u) + (n + 1,)``
        BEZ_{0,n}(u) … BEZ_{n,n}(u), as :func:`bernstein` gives them.

    Raises
    ------
    ArgumentValueError
        ``degree`` is not an integer >= 0.

    Examples
    --------
    Quadratic blending at u = 1/4: (3/4)², 2 (1/4)(3/4), (1/4)²:

    >>> import scanline as sl
    >>> sl.curves.bernstein_recursive(2, 0.25).tolist()
    [0.5625, 0.375, 0.0625]
    """
    n = v.positive_int("degree", degree, minimum=0)
    u = np.asarray(u, dtype=np.float64)[..., None]
    row: NDArray[np.float64] = np.ones(u.shape[:-1] + (1,))
    for _ in range(n):
        padded = np.concatenate([row, np.zeros_like(row[..., :1])], axis=-1)
        shifted = np.concatenate([np.zeros_like(row[..., :1]), row], axis=-1)
        row = (1.0 - u) * padded + u * shifted
    return row


class Bezier(Weighted, Curve):
    """A Bezier curve P(u) = Σ Pₖ BEZ_{k,n}(u), 0 ≤ u ≤ 1, of degree n = len(points) − 1.

    Parameters
    ----------
    points : array_like, shape (n + 1, dim)
        Control points P₀ … Pₙ, 2-D or 3-D (any dim ≥ 1 works), finite.
    weights : array_like, shape (n + 1,), optional
        Positive weights wₖ: the rational curve Σ wₖPₖBEZ_{k,n} / Σ wₖBEZ_{k,n}.
        Equal weights give the plain curve.

    Notes
    -----
    Notes, chapter 5, Q.1.  ``evaluate(u, method=...)`` offers the notes' three
    formulations and de Casteljau's: ``"de-casteljau"`` (compiled, the numerically
    most stable), ``"bernstein"`` (binomial coefficients, eqs. 2–3), ``"recursive"``
    (eq. 4) and ``"matrix"`` ([uⁿ … u 1] · M_bez · P, see
    :func:`~scanline.curves.matrices.bezier_matrix`, with M_bez · P computed once and
    evaluated by Horner's rule, compiled).  The default, ``method=None``, is
    ``"matrix"`` up to degree 6 (:data:`MATRIX_DEGREE`), the fastest, and
    ``"de-casteljau"`` above.  Rational curves are evaluated in homogeneous
    coordinates [wP, w] and projected.

    References
    ----------
    P. Bézier, *Numerical Control: Mathematics and Applications*, Wiley, 1972.
    P. de Casteljau, *Outillages méthodes calcul*, Citroën, 1959.

    Examples
    --------
    A quadratic curve and the rational one with the middle weight 2:

    >>> import scanline as sl
    >>> c = sl.curves.Bezier([(0, 0), (1, 1), (2, 0)])
    >>> c.degree, c(0.5).tolist()
    (2, [1.0, 0.5])
    >>> sl.curves.Bezier([(0, 0), (1, 1), (2, 0)], weights=[1, 2, 1])(0.5).tolist()
    [1.0, 0.6666666666666666]
    """

    METHODS = METHODS

    def __init__(self, points: ArrayLike, weights: Optional[ArrayLike] = None) -> None:
        self.points = control_points("points", points)
        self.degree = len(self.points) - 1
        self.dimension = self.points.shape[1]
        self.domain = (0.0, 1.0)
        self.weights = None if weights is None else weights_array(
            "weights", weights, len(self.points))
        self.points.flags.writeable = False
        self._coefficients: Optional[Union[NDArray[np.float64], tuple[()]]] = None

    def _evaluate(self, u: NDArray[np.float64], method: Optional[str] = None) -> NDArray[np.float64]:
        if method is None:
            fits = self.degree <= MATRIX_DEGREE and self._power_form() is not None
            method = "matrix" if fits else "de-casteljau"
        pts = self.homogeneous() if self.rational else self.points
        if method == "de-casteljau":
            out = np.empty((len(u), pts.shape[1]))
            call(_k.de_casteljau, len(u) * len(pts) ** 2, v.kernel_array(pts), v.kernel_array(u),
                 out)
        elif method == "bernstein":
            out = bernstein(self.degree, u) @ pts
        elif method == "recursive":
            out = bernstein_recursive(self.degree, u) @ pts
        else:
            if self._power_form() is None:
                raise ArgumentValueError(
                    "method='matrix' cannot represent this curve: M_bez·P overflows for "
                    f"control points this large or degrees above {MAX_DEGREE}; use "
                    "method='de-casteljau'"
                )
            out = np.empty((len(u), pts.shape[1]))
            call(_k.piecewise_horner, len(u) * len(pts), np.array([0.0, 1.0]), self._power_form(),
                 v.kernel_array(u), out)
        return project(out) if self.rational else out

    def _power_form(self) -> Optional[NDArray[np.float64]]:
        """M_bez · P as a one-section coefficient array, or None if it overflows (or
        the degree is above the derived matrices' :data:`~.matrices.MAX_DEGREE`)."""
        if self.degree > MAX_DEGREE:
            return None
        if self._coefficients is None:
            pts = self.homogeneous() if self.rational else self.points
            m = bezier_matrix(self.degree) if self.degree else np.ones((1, 1))
            with np.errstate(all="ignore"):
                c = (m @ pts)[None]
            self._coefficients = c if np.isfinite(c).all() else ()
        coefficients = self._coefficients
        return coefficients if isinstance(coefficients, np.ndarray) else None

    def _derivative(self) -> Curve:
        if self.rational:
            return RationalDerivative(Bezier(self.homogeneous()), 1)
        if self.degree == 0:
            return Bezier(np.zeros_like(self.points))
        return Bezier(self.degree * np.diff(self.points, axis=0))

    def de_casteljau(self, u: float) -> list[NDArray[np.float64]]:
        """de Casteljau's triangle at one parameter u: a list of n + 1 arrays.

        Level r holds the n + 1 − r points Pᵢʳ = (1 − u)Pᵢʳ⁻¹ + u Pᵢ₊₁ʳ⁻¹; level n is the
        curve point (in homogeneous coordinates [wP, w] for a rational curve).

        Parameters
        ----------
        u : float
            The parameter, in the domain [0, 1].

        Returns
        -------
        list of ndarray of float64
            Level r, shape (n + 1 − r, dim) (dim + 1 for a rational curve).

        Raises
        ------
        ArgumentValueError
            ``u`` is not a number in [0, 1].

        Examples
        --------
        >>> import scanline as sl
        >>> levels = sl.curves.Bezier([(0, 0), (2, 2), (4, 0)]).de_casteljau(0.5)
        >>> [level.tolist() for level in levels]
        [[[0.0, 0.0], [2.0, 2.0], [4.0, 0.0]], [[1.0, 1.0], [3.0, 1.0]], [[2.0, 1.0]]]
        """
        t = float(parameters("u", v.number("u", u), self.domain))
        level = self.homogeneous() if self.rational else self.points.copy()
        triangle = [level]
        for _ in range(self.degree):
            level = (1.0 - t) * level[:-1] + t * level[1:]
            triangle.append(level)
        return triangle

    def subdivide(self, u: float = 0.5) -> tuple["Bezier", "Bezier"]:
        """Split the curve at u into two Bezier curves of the same degree.

        The left curve's control points are the first points of de Casteljau's
        triangle, the right curve's the last ones (reversed order of levels).

        Parameters
        ----------
        u : float
            Where to split, in [0, 1].

        Returns
        -------
        (Bezier, Bezier)
            The parts on [0, u] and [u, 1], each reparameterized to [0, 1].

        Raises
        ------
        ArgumentValueError
            ``u`` is not a number in [0, 1].

        Examples
        --------
        >>> import scanline as sl
        >>> left, right = sl.curves.Bezier([(0, 0), (2, 2), (4, 0)]).subdivide()
        >>> left.points.tolist(), right.points.tolist()
        ([[0.0, 0.0], [1.0, 1.0], [2.0, 1.0]], [[2.0, 1.0], [3.0, 1.0], [4.0, 0.0]])
        """
        triangle = self.de_casteljau(u)
        left = np.array([level[0] for level in triangle])
        right = np.array([level[-1] for level in triangle[::-1]])
        return self._from_homogeneous(left), self._from_homogeneous(right)

    def elevate(self, times: int = 1) -> "Bezier":
        """The same curve as a Bezier curve of degree n + ``times``.

        Qᵢ = i/(n+1) Pᵢ₋₁ + (1 − i/(n+1)) Pᵢ, i = 0 … n + 1, applied ``times`` times
        (to [wP, w] for a rational curve).

        Parameters
        ----------
        times : int
            How many degrees to add, >= 0.

        Returns
        -------
        Bezier
            The same curve, of degree n + ``times``.

        Raises
        ------
        ArgumentValueError
            ``times`` is not an integer >= 0, or the degree would pass
            ``ELEVATE_DEGREE``.

        Examples
        --------
        The quadratic with P1 = (3, 3) as a cubic: Q1 = P0/3 + 2 P1/3, Q2 = 2 P1/3 + P2/3:

        >>> import scanline as sl
        >>> sl.curves.Bezier([(0, 0), (3, 3), (6, 0)]).elevate().points.tolist()
        [[0.0, 0.0], [2.0, 2.0], [4.0, 2.0], [6.0, 0.0]]
        """
        times = v.positive_int("times", times, minimum=0)
        if self.degree + times > ELEVATE_DEGREE:
            raise ArgumentValueError(
                f"times={times} would raise degree {self.degree} above {ELEVATE_DEGREE}; "
                "elevate by fewer degrees")
        pts = self.homogeneous() if self.rational else self.points
        for _ in range(times):
            n = len(pts) - 1
            a = (np.arange(n + 2) / (n + 1))[:, None]
            padded = np.vstack([pts, np.zeros_like(pts[:1])])
            shifted = np.vstack([np.zeros_like(pts[:1]), pts])
            pts = a * shifted + (1.0 - a) * padded
        return self._from_homogeneous(pts)

    def _from_homogeneous(self, pts: NDArray[np.float64]) -> "Bezier":
        if not self.rational:
            return Bezier(pts)
        return Bezier(project(pts), weights=pts[:, -1])
