"""Hermite curves and the splines built from them: cardinal, Catmull–Rom,
Kochanek–Bartels, and C1/C2 piecewise cubics (notes, chapter 5, Q.3 and Q.5).

All are piecewise polynomials with one section per unit of u: section k covers
[k, k + 1] and runs from its k-th to its (k+1)-th interpolated point.

>>> import scanline as sl
>>> h = sl.curves.Hermite([(0, 0), (4, 0)], tangents=[(0, 6), (0, -6)])
>>> h.evaluate(0.5).tolist()
[2.0, 1.5]
"""

from typing import Literal, Optional

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._kernels import curves as _k
from .._kernels._jit import call
from ..errors import ArgumentValueError
from .base import Curve, control_points
from .bezier import Bezier
from .matrices import bezier_matrix, hermite_matrix


def hermite_blending(u: ArrayLike) -> NDArray[np.float64]:
    """H₀ … H₃ at u (notes, ch. 5, Q.3): 2u³ − 3u² + 1, −2u³ + 3u², u³ − 2u² + u, u³ − u².

    Returns shape ``np.shape(u) + (4,)``.

    Parameters
    ----------
    u : float or array_like of float
        Parameter values.

    Returns
    -------
    ndarray of float64, shape ``np.shape(u) + (4,)``
        H₀(u) … H₃(u) (Hearn & Baker, section 10-8, eq. 10-27).

    Examples
    --------
    At u = 1/2: 1/4 − 3/4 + 1, −1/4 + 3/4, 1/8 − 1/2 + 1/2, 1/8 − 1/4:

    >>> import scanline as sl
    >>> sl.curves.hermite_blending(0.5).tolist()
    [0.5, 0.5, 0.125, -0.125]
    """
    u = np.asarray(u, dtype=np.float64)[..., None]
    return np.concatenate([2 * u**3 - 3 * u**2 + 1, -2 * u**3 + 3 * u**2,
                           u**3 - 2 * u**2 + u, u**3 - u**2], axis=-1)


class PiecewisePolynomial(Curve):
    """Polynomial sections in the notes' power form, section k on [k, k + 1].

    Parameters
    ----------
    coefficients : array_like, shape (S, m + 1, dim)
        Per section the coefficient rows of [uᵐ … u 1] (u local, 0 … 1): for a cubic,
        the notes' [a b c d] of P(u) = au³ + bu² + cu + d.

    Raises
    ------
    ArgumentValueError
        ``coefficients`` is not of shape (S, m + 1, dim).

    Examples
    --------
    One section P(u) = (u², u):

    >>> import scanline as sl
    >>> p = sl.curves.PiecewisePolynomial([[(1, 0), (0, 1), (0, 0)]])
    >>> p.domain, p(0.5).tolist()
    ((0.0, 1.0), [0.25, 0.5])
    """

    def __init__(self, coefficients: ArrayLike) -> None:
        c = np.array(coefficients, dtype=np.float64)
        if c.ndim != 3 or c.shape[0] < 1 or c.shape[1] < 1:
            raise ArgumentValueError(
                f"coefficients must have shape (sections, degree + 1, dim), got {c.shape}"
            )
        self.coefficients = c
        c.flags.writeable = False
        self.dimension = c.shape[2]
        self.domain = (0.0, float(c.shape[0]))

    def _evaluate(self, u: NDArray[np.float64]) -> NDArray[np.float64]:
        c = self.coefficients
        out = np.empty((len(u), self.dimension))
        call(_k.piecewise_horner, len(u) * c.shape[1], np.arange(len(c) + 1.0), v.kernel_array(c),
             v.kernel_array(u), out)
        return out

    def _derivative(self) -> Curve:
        c = self.coefficients
        m = c.shape[1] - 1
        if m == 0:
            return PiecewisePolynomial(np.zeros_like(c))
        return PiecewisePolynomial(c[:, :-1] * np.arange(m, 0, -1)[None, :, None])

    @property
    def sections(self) -> list[Bezier]:
        """Each section as a :class:`~scanline.curves.Bezier` curve on [0, 1]."""
        m = self.coefficients.shape[1] - 1
        if m == 0:
            return [Bezier(c) for c in self.coefficients]
        to_bezier = np.linalg.inv(bezier_matrix(m))
        return [Bezier(to_bezier @ c) for c in self.coefficients]


class Hermite(PiecewisePolynomial):
    """Cubic Hermite curve through ``points`` with given tangents DPₖ.

    Section k: P(u) = [u³ u² u 1] · M_H · [Pₖ, Pₖ₊₁, DPₖ, DPₖ₊₁]ᵀ, 0 ≤ u ≤ 1, M_H
    the inverse of the notes' boundary-constraint matrix.

    Parameters
    ----------
    points : array_like, shape (m, dim)
        The m ≥ 2 interpolated points.
    tangents : array_like, shape (m, dim)
        Parametric derivatives DPₖ (leaving point k).
    incoming : array_like, shape (m, dim), optional
        Derivatives arriving at each point, if they differ from ``tangents`` (a corner,
        as Kochanek–Bartels splines make); the default is ``tangents``.

    Raises
    ------
    ArgumentValueError
        Fewer than 2 points, non-finite values, or tangents of another shape.

    Notes
    -----
    Notes, chapter 5, Q.3 (boundary conditions, M_H, H₀ … H₃).

    Examples
    --------
    >>> import scanline as sl
    >>> h = sl.curves.Hermite([(0, 0), (4, 0)], tangents=[(0, 6), (0, -6)])
    >>> h(0.5).tolist()        # H0 (0, 0) + H1 (4, 0) + H2 (0, 6) + H3 (0, -6)
    [2.0, 1.5]
    """

    def __init__(self, points: ArrayLike, tangents: ArrayLike,
                 incoming: Optional[ArrayLike] = None) -> None:
        p = control_points("points", points, minimum=2)
        t = control_points("tangents", tangents, minimum=len(p))
        t_in = t if incoming is None else control_points("incoming", incoming, minimum=len(p))
        for name, a in (("tangents", t), ("incoming", t_in)):
            if a.shape != p.shape:
                raise ArgumentValueError(
                    f"{name} must have the shape of points {p.shape}, got {a.shape}"
                )
        self.points, self.tangents, self.incoming = p, t, t_in
        geometry = np.stack([p[:-1], p[1:], t[:-1], t_in[1:]], axis=1)
        super().__init__(np.einsum("ij,sjd->sid", hermite_matrix(), geometry))


def _neighbours(points: NDArray[np.float64], closed: bool) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """(previous, current, next) point arrays for the tangent formulas."""
    if closed:
        return np.roll(points, 1, axis=0), points, np.roll(points, -1, axis=0)
    return points[:-2], points[1:-1], points[2:]


def _spline_points(points: ArrayLike, closed: bool) -> NDArray[np.float64]:
    return control_points("points", points, minimum=3 if closed else 4)


def _parameter(name: str, value: ArrayLike, count: int) -> NDArray[np.float64]:
    """A scalar or one value per point, as a float array broadcastable to (count, 1)."""
    a = np.array(value, dtype=np.float64)
    if a.ndim == 0:
        a = np.full(count, v.number(name, float(a)))
    if a.shape != (count,) or not np.isfinite(a).all():
        raise ArgumentValueError(
            f"{name} must be a finite number or one per point ({count}), got {value!r}"
        )
    return a[:, None]


class KochanekBartels(Hermite):
    """Kochanek–Bartels spline: tension t, continuity c and bias b at each point.

    The tangent leaving Pₖ is
    (1−t)(1+b)(1+c)/2 (Pₖ − Pₖ₋₁) + (1−t)(1−b)(1−c)/2 (Pₖ₊₁ − Pₖ) and the tangent
    arriving at Pₖ is (1−t)(1+b)(1−c)/2 (Pₖ − Pₖ₋₁) + (1−t)(1−b)(1+c)/2 (Pₖ₊₁ − Pₖ).
    t = c = b = 0 is Catmull–Rom; c ≠ 0 makes corners (G0 only).

    Parameters
    ----------
    points : array_like, shape (m, dim)
        Open curves (m ≥ 4) run from P₁ to P_{m−2}: the first and last points only
        steer the end tangents, as in the notes' source (Hearn & Baker, §10-8).
        ``closed=True`` (m ≥ 3) runs through every point and back to P₀.
    tension, continuity, bias : float or array_like of m floats
        t, c and b, one for all points or one per point.
    closed : bool
        Whether the curve closes back to P₀.

    Raises
    ------
    ArgumentValueError
        Too few points, or parameters that are not finite (one or one per point).

    References
    ----------
    D. Kochanek and R. Bartels, "Interpolating splines with local tension, continuity
    and bias control", *SIGGRAPH '84*, 1984.

    Examples
    --------
    Through P₁ = (1, 1) and P₂ = (2, 0); the tangent at P₁ is (P₂ − P₀)/2 with
    t = c = b = 0, and zero with tension 1:

    >>> import scanline as sl
    >>> pts = [(0, 0), (1, 1), (2, 0), (3, 1)]
    >>> kb = sl.curves.KochanekBartels(pts)
    >>> kb(1.0).tolist(), kb.derivative()(0.0).tolist()
    ([2.0, 0.0], [1.0, 0.0])
    >>> sl.curves.KochanekBartels(pts, tension=1.0).derivative()(0.0).tolist()
    [0.0, 0.0]
    """

    def __init__(self, points: ArrayLike, tension: ArrayLike = 0.0, continuity: ArrayLike = 0.0,
                 bias: ArrayLike = 0.0, closed: bool = False) -> None:
        p = _spline_points(points, closed)
        prev, cur, nxt = _neighbours(p, closed)
        rows = slice(None) if closed else slice(1, -1)
        t, c, b = (_parameter(name, value, len(p))[rows] for name, value in
                   (("tension", tension), ("continuity", continuity), ("bias", bias)))
        back, ahead = cur - prev, nxt - cur
        out = (1 - t) * ((1 + b) * (1 + c) * back + (1 - b) * (1 - c) * ahead) / 2
        arrive = (1 - t) * ((1 + b) * (1 - c) * back + (1 - b) * (1 + c) * ahead) / 2
        if closed:
            cur, out, arrive = (np.vstack([a, a[:1]]) for a in (cur, out, arrive))
        super().__init__(cur, out, incoming=arrive)
        self.points = p


class CardinalSpline(KochanekBartels):
    """Cardinal spline: DPₖ = (1 − t)/2 (Pₖ₊₁ − Pₖ₋₁), t the ``tension``.

    Section k equals [u³ u² u 1] · M_C · [Pₖ₋₁ Pₖ Pₖ₊₁ Pₖ₊₂]ᵀ
    (:func:`~scanline.curves.matrices.cardinal_matrix`).  Endpoints as for
    :class:`KochanekBartels`.

    Parameters
    ----------
    points : array_like, shape (m, dim)
        The points (m ≥ 4 open, m ≥ 3 closed).
    tension : float or array_like of m floats
        t; 0 is Catmull–Rom.
    closed : bool
        Whether the curve closes back to P₀.

    Raises
    ------
    ArgumentValueError
        As :class:`KochanekBartels`.

    Notes
    -----
    Hearn & Baker, section 10-8 (cardinal splines).

    Examples
    --------
    DP₁ = (1 − ½)/2 (P₂ − P₀) = ¼ (2, 0):

    >>> import scanline as sl
    >>> c = sl.curves.CardinalSpline([(0, 0), (1, 1), (2, 0), (3, 1)], tension=0.5)
    >>> c.derivative()(0.0).tolist()
    [0.5, 0.0]
    """

    def __init__(self, points: ArrayLike, tension: ArrayLike = 0.0, closed: bool = False) -> None:
        super().__init__(points, tension=tension, closed=closed)


class CatmullRom(CardinalSpline):
    """Catmull–Rom spline: the cardinal spline of tension 0, DPₖ = (Pₖ₊₁ − Pₖ₋₁)/2.

    References
    ----------
    E. Catmull and R. Rom, "A class of local interpolating splines", in *Computer
    Aided Geometric Design*, Academic Press, 1974.

    Parameters
    ----------
    points : array_like, shape (m, dim)
        The points (m ≥ 4 open, m ≥ 3 closed).
    closed : bool
        Whether the curve closes back to P₀.

    Raises
    ------
    ArgumentValueError
        As :class:`KochanekBartels`.

    Examples
    --------
    Halfway from P₁ = (1, 1) to P₂ = (2, 0), with DP₁ = DP₂ = (1, 0):
    H₀ P₁ + H₁ P₂ + H₂ DP₁ + H₃ DP₂ = ½ (1, 1) + ½ (2, 0) + ⅛ (1, 0) − ⅛ (1, 0):

    >>> import scanline as sl
    >>> sl.curves.CatmullRom([(0, 0), (1, 1), (2, 0), (3, 1)])(0.5).tolist()
    [1.5, 0.5]
    """

    def __init__(self, points: ArrayLike, closed: bool = False) -> None:
        super().__init__(points, tension=0.0, closed=closed)


def piecewise_bezier(points: ArrayLike, continuity: Literal["C1", "C2"] = "C1") -> Hermite:
    """A piecewise cubic (Bezier sections) through every one of ``points``.

    ``continuity="C1"``: tangents (Pₖ₊₁ − Pₖ₋₁)/2 inside, one-sided differences at the
    ends; neighbouring Bezier sections then have their inner control points on one line
    through the joint, at equal distances (the notes, Q.1: "a constant ratio of
    collinear line segments").  ``continuity="C2"``: the natural cubic spline
    (second derivative 0 at both ends), whose tangents solve the tridiagonal system
    DPₖ₋₁ + 4DPₖ + DPₖ₊₁ = 3(Pₖ₊₁ − Pₖ₋₁).  Returns a :class:`Hermite`; its
    ``sections`` are the Bezier curves.

    Parameters
    ----------
    points : array_like, shape (m, dim)
        The m ≥ 2 points to pass through.
    continuity : {"C1", "C2"}
        Which tangents (see above).

    Returns
    -------
    Hermite
        The curve, section k on [k, k + 1].

    Raises
    ------
    ArgumentValueError
        Fewer than 2 points, non-finite points, or an unknown ``continuity``.

    Examples
    --------
    Through (0, 0), (1, 1), (2, 0); the C1 tangent at the middle point is
    ((2, 0) − (0, 0))/2:

    >>> import scanline as sl
    >>> h = sl.curves.piecewise_bezier([(0, 0), (1, 1), (2, 0)])
    >>> h([0.0, 1.0, 2.0]).tolist(), h.derivative()(1.0).tolist()
    ([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]], [1.0, 0.0])
    """
    p = control_points("points", points, minimum=2)
    v.choice("continuity", continuity, ("C1", "C2"))
    m = len(p)
    if continuity == "C1":
        d = np.empty_like(p)
        d[0], d[-1] = p[1] - p[0], p[-1] - p[-2]
        d[1:-1] = (p[2:] - p[:-2]) / 2
        return Hermite(p, d)
    a = 4.0 * np.eye(m) + np.eye(m, k=1) + np.eye(m, k=-1)
    a[0, 0] = a[-1, -1] = 2.0
    rhs = np.empty_like(p)
    rhs[0], rhs[-1] = 3 * (p[1] - p[0]), 3 * (p[-1] - p[-2])
    rhs[1:-1] = 3 * (p[2:] - p[:-2])
    return Hermite(p, np.linalg.solve(a, rhs))
