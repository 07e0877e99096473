"""Hermite curves and the splines built from them: cardinal, Catmull–Rom,
Kochanek–Bartels, and C1/C2 piecewise cubics (notes, chapter 5, Q.3 and Q.5).

All are piecewise polynomials with one section per unit of u: section k covers
[k, k + 1] and runs from its k-th to its (k+1)-th interpolated point.

>>> import scanline as sl
>>> h = sl.curves.Hermite([(0, 0), (4, 0)], tangents=[(0, 6), (0, -6)])
>>> h.evaluate(0.5).tolist()
[2.0, 1.5]
"""

import numpy as np

from .. import _validate as v
from .._kernels import curves as _k
from .._kernels._jit import call
from ..errors import ArgumentValueError
from .base import Curve, control_points
from .bezier import Bezier
from .matrices import bezier_matrix, hermite_matrix


def hermite_blending(u):
    """H₀ … H₃ at u (notes, ch. 5, Q.3): 2u³ − 3u² + 1, −2u³ + 3u², u³ − 2u² + u, u³ − u².

    Returns shape ``np.shape(u) + (4,)``.
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
    """

    def __init__(self, coefficients):
        c = np.array(coefficients, dtype=np.float64)
        if c.ndim != 3 or c.shape[0] < 1 or c.shape[1] < 1:
            raise ArgumentValueError(
                f"coefficients must have shape (sections, degree + 1, dim), got {c.shape}"
            )
        self.coefficients = c
        c.flags.writeable = False
        self.dimension = c.shape[2]
        self.domain = (0.0, float(c.shape[0]))

    def _evaluate(self, u):
        c = self.coefficients
        out = np.empty((len(u), self.dimension))
        call(_k.piecewise_horner, len(u) * c.shape[1], np.arange(len(c) + 1.0), v.kernel_array(c),
             v.kernel_array(u), out)
        return out

    def _derivative(self):
        c = self.coefficients
        m = c.shape[1] - 1
        if m == 0:
            return PiecewisePolynomial(np.zeros_like(c))
        return PiecewisePolynomial(c[:, :-1] * np.arange(m, 0, -1)[None, :, None])

    @property
    def sections(self):
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

    Notes
    -----
    Notes, chapter 5, Q.3 (boundary conditions, M_H, H₀ … H₃).
    """

    def __init__(self, points, tangents, incoming=None):
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


def _neighbours(points, closed):
    """(previous, current, next) point arrays for the tangent formulas."""
    if closed:
        return np.roll(points, 1, axis=0), points, np.roll(points, -1, axis=0)
    return points[:-2], points[1:-1], points[2:]


def _spline_points(points, closed):
    return control_points("points", points, minimum=3 if closed else 4)


def _parameter(name, value, count):
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

    References
    ----------
    D. Kochanek and R. Bartels, "Interpolating splines with local tension, continuity
    and bias control", *SIGGRAPH '84*, 1984.
    """

    def __init__(self, points, tension=0.0, continuity=0.0, bias=0.0, closed=False):
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
    """

    def __init__(self, points, tension=0.0, closed=False):
        super().__init__(points, tension=tension, closed=closed)


class CatmullRom(CardinalSpline):
    """Catmull–Rom spline: the cardinal spline of tension 0, DPₖ = (Pₖ₊₁ − Pₖ₋₁)/2.

    References
    ----------
    E. Catmull and R. Rom, "A class of local interpolating splines", in *Computer
    Aided Geometric Design*, Academic Press, 1974.
    """

    def __init__(self, points, closed=False):
        super().__init__(points, tension=0.0, closed=closed)


def piecewise_bezier(points, continuity="C1"):
    """A piecewise cubic (Bezier sections) through every one of ``points``.

    ``continuity="C1"``: tangents (Pₖ₊₁ − Pₖ₋₁)/2 inside, one-sided differences at the
    ends; neighbouring Bezier sections then have their inner control points on one line
    through the joint, at equal distances (the notes, Q.1: "a constant ratio of
    collinear line segments").  ``continuity="C2"``: the natural cubic spline
    (second derivative 0 at both ends), whose tangents solve the tridiagonal system
    DPₖ₋₁ + 4DPₖ + DPₖ₊₁ = 3(Pₖ₊₁ − Pₖ₋₁).  Returns a :class:`Hermite`; its
    ``sections`` are the Bezier curves.
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
