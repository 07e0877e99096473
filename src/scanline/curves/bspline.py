"""B-spline curves and NURBS (notes, chapter 5, Q.2).

>>> import scanline as sl
>>> c = sl.curves.BSpline([(0, 0), (1, 2), (3, 2), (4, 0)], order=4, knots="periodic")
>>> c.domain
(0.0, 4.0)
>>> (6 * c.evaluate(0.0)).round(12).tolist()     # P0 + 4 P1 + P2, 6 times the notes' P(0)
[7.0, 10.0]
"""

import numbers
from math import factorial
from typing import Optional, TypeVar, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._kernels import curves as _k
from .._kernels._jit import call
from ..errors import ArgumentTypeError, ArgumentValueError
from .._validate import _show
from .base import Curve, control_points, parameters, weights_array
from .rational import RationalDerivative, Weighted, project

KNOT_KINDS = ("open", "uniform", "periodic")
METHODS = ("de-boor", "cox-de-boor", "matrix")

#: Highest order evaluated by default in the per-span matrix (power) form; above it
#: de Boor's algorithm, which is better conditioned.
MATRIX_ORDER = 6

#: Most control points of a knot vector made by :func:`open_uniform_knots` (32 MiB).
MAX_CONTROL_POINTS = 1 << 22

_Spline = TypeVar("_Spline", bound="BSpline")


def open_uniform_knots(count: int, order: int) -> NDArray[np.float64]:
    """The open uniform knot vector for ``count`` = n + 1 control points of order d.

    uⱼ = 0 for j < d, j − d + 1 for d ≤ j ≤ n, n − d + 2 for j > n (Hearn & Baker,
    §10-9): the notes' [0 0 1 2 3 3] (d = 2, n = 3) and [0 0 0 0 1 2 2 2 2] (d = 4, n = 4).

    ``count`` is at most :data:`MAX_CONTROL_POINTS`.

    Parameters
    ----------
    count : int
        n + 1, the number of control points (1 … ``MAX_CONTROL_POINTS``).
    order : int
        d, 1 ≤ d ≤ n + 1.

    Returns
    -------
    ndarray of float64, shape (n + d + 1,)
        The knots u₀ … u_{n+d}.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        ``count`` or ``order`` is not an integer in its range.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.curves.open_uniform_knots(4, 2).tolist()
    [0.0, 0.0, 1.0, 2.0, 3.0, 3.0]
    """
    count = v.positive_int("count", count, minimum=1)
    if count > MAX_CONTROL_POINTS:
        raise ArgumentValueError(
            f"count={count:,}: a knot vector is made for at most {MAX_CONTROL_POINTS:,} "
            "control points")
    order = _order(order, count)
    n, d = count - 1, order
    j = np.arange(n + d + 1)
    return np.clip(j - d + 1, 0, n - d + 2).astype(np.float64)


def _order(order: object, count: int) -> int:
    if isinstance(order, bool) or not isinstance(order, numbers.Integral):
        raise ArgumentTypeError(f"order must be an integer, got {_show(order)}")
    if not 1 <= int(order) <= count:
        raise ArgumentValueError(
            f"order must satisfy 1 <= order <= number of control points ({count}) "
            f"(the notes: 2 <= d <= n + 1), got order={order}; use more control points "
            "or a lower order"
        )
    return int(order)


def check_knots(knots: ArrayLike, count: int, order: int) -> NDArray[np.float64]:
    """Validate an explicit knot vector: n + d + 1 finite non-decreasing values with
    u_{d−1} < u_{n+1}.  Returns it as float64."""
    try:
        u = np.array(knots, dtype=np.float64)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"knots must be 'open', 'uniform', 'periodic' or an array of numbers, got "
            f"{_show(knots)}"
        ) from None
    need = count + order
    if u.shape != (need,):
        raise ArgumentValueError(
            f"knots must hold n + d + 1 = {need} values for {count} control points of "
            f"order {order}, got shape {u.shape}"
        )
    if not np.isfinite(u).all():
        raise ArgumentValueError(f"knots must be finite, got {_show(u.tolist())}")
    if (np.diff(u) < 0).any():
        i = int(np.argmax(np.diff(u) < 0))
        raise ArgumentValueError(
            f"knots must be non-decreasing; knots[{i}] = {u[i]:g} > knots[{i + 1}] = "
            f"{u[i + 1]:g}"
        )
    if not u[order - 1] < u[count]:
        raise ArgumentValueError(
            f"knots give an empty parameter range: u_(d-1) = knots[{order - 1}] = "
            f"{u[order - 1]:g} must be < u_(n+1) = knots[{count}] = {u[count]:g}"
        )
    return u


def knot_span(knots: ArrayLike, u: ArrayLike, last: Optional[int] = None) -> NDArray[np.intp]:
    """Index ℓ ≤ ``last`` of the knot span [u_ℓ, u_ℓ₊₁) holding each u.

    ``last`` (default: the last span of the knot vector; a curve passes n, so that
    its domain ends at u_{n+1}) is stepped down to a non-empty span, which is closed on
    the right: a u at its end belongs to it.
    """
    k = np.asarray(knots, dtype=np.float64)
    t = np.asarray(u, dtype=np.float64)
    end = len(k) - 2 if last is None else last
    while k[end] >= k[end + 1]:
        end -= 1
    span: NDArray[np.intp] = np.minimum(np.searchsorted(k, t, side="right") - 1, end)
    return span


def _basis_arguments(knots: ArrayLike, order: object, u: ArrayLike, last: Optional[int]
                     ) -> tuple[NDArray[np.float64], int, NDArray[np.float64], Optional[int]]:
    """Check :func:`basis`'s arguments (it is public): a finite non-decreasing knot
    vector of at least d + 1 values spanning a non-empty range, an integer order
    d >= 1, parameters inside [u_0, u_{n+d}], and ``last`` a span ending after u_0."""
    if isinstance(order, bool) or not isinstance(order, numbers.Integral):
        raise ArgumentTypeError(f"order must be an integer >= 1, got {_show(order)}")
    d = int(order)
    if d < 1:
        raise ArgumentValueError(f"order must be an integer >= 1, got {order}")
    try:
        k = np.asarray(knots, dtype=np.float64)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"knots must be an array of numbers, got {_show(knots)}") from None
    if (k.ndim != 1 or len(k) < d + 1 or not np.isfinite(k).all()
            or (np.diff(k) < 0).any() or not k[0] < k[-1]):
        raise ArgumentValueError(
            f"knots must be at least order + 1 = {d + 1} finite non-decreasing numbers, "
            f"not all equal, got {_show(k.tolist())}")
    t = parameters("u", u, (float(k[0]), float(k[-1])))
    if last is not None and not (isinstance(last, numbers.Integral) and 0 <= last <= len(k) - 2
                                 and k[last + 1] > k[0]):
        raise ArgumentValueError(
            f"last must be the index of a knot span, 0 to {len(k) - 2}, ending after "
            f"knots[0]; got {_show(last)}")
    return k, d, t, last


def basis(knots: ArrayLike, order: int, u: ArrayLike, last: Optional[int] = None) -> NDArray[np.float64]:
    """All blending functions B_{k,d}(u), k = 0 … n, by the Cox–de Boor recursion.

    Parameters
    ----------
    knots : array_like
        Non-decreasing knot vector u₀ … u_{n+d}.
    order : int
        d ≥ 1 (degree d − 1).
    u : float or array_like
        Parameters in [u₀, u_{n+d}].
    last : int, optional
        The last knot span to use (see :func:`knot_span`); curves pass n.

    Returns
    -------
    numpy.ndarray
        Shape ``np.shape(u) + (n + 1,)``.

    Notes
    -----
    Notes, ch. 5, Q.2: B_{k,1}(u) = 1 if u_k ≤ u < u_{k+1} else 0 (half-open: the
    notes' closed interval counts a knot twice, erratum E43), and
    B_{k,d} = (u − u_k)/(u_{k+d−1} − u_k) B_{k,d−1} + (u_{k+d} − u)/(u_{k+d} − u_{k+1}) B_{k+1,d−1},
    a term with a zero denominator being 0.  The last non-empty span is closed on the
    right, so the curve reaches u = u_{n+1}.

    References
    ----------
    M. G. Cox, "The numerical evaluation of B-splines", *J. Inst. Maths Applics* 10, 1972.
    C. de Boor, "On calculating with B-splines", *J. Approx. Theory* 6, 1972.

    Examples
    --------
    The linear (d = 2) functions on the knots [0 0 1 1] at u = 1/4: 1 − u and u:

    >>> import scanline as sl
    >>> sl.curves.basis([0, 0, 1, 1], 2, 0.25).tolist()
    [0.75, 0.25]
    """
    k_, d, t, last = _basis_arguments(knots, order, u, last)
    knots_ = k_
    flat = t.ravel()
    count = len(knots_) - 1  # number of order-1 functions
    b = np.zeros((flat.size, count))
    b[np.arange(flat.size), knot_span(knots_, flat, last)] = 1.0
    with np.errstate(all="ignore"):
        for r in range(2, d + 1):
            k = np.arange(count - r + 1)
            left = knots_[k + r - 1] - knots_[k]
            right = knots_[k + r] - knots_[k + 1]
            # where B_k,r-1 (resp. B_k+1,r-1) is non-zero these ratios lie in [0, 1];
            # clipping them changes no product and keeps inf * 0 out (tiny knot gaps)
            a = np.clip(np.where(left > 0, (flat[:, None] - knots_[k]) / left, 0.0), 0, 1)
            c = np.clip(np.where(right > 0, (knots_[k + r] - flat[:, None]) / right, 0.0), 0, 1)
            b = a * b[:, :-1] + c * b[:, 1:]
    return b.reshape(t.shape + (b.shape[1],))


class BSpline(Weighted, Curve):
    """A B-spline curve P(u) = Σₖ Pₖ B_{k,d}(u) of order d (degree d − 1).

    Parameters
    ----------
    points : array_like, shape (n + 1, dim)
        Control points P₀ … Pₙ, finite.
    order : int
        d, with 1 ≤ d ≤ n + 1 (the notes: 2 ≤ d ≤ n + 1; d = 1 is the piecewise
        constant base case, which derivatives of linear splines reach).
    knots : {"open", "uniform", "periodic"} or array_like, default "open"
        ``"open"``: open uniform, the end knots repeated d times, so the curve starts
        at P₀ and ends at Pₙ.  ``"uniform"``: the integers 0 … n + d.  ``"periodic"``:
        a closed curve: the first d − 1 points are appended again and the knots are
        uniform, with the domain [0, n + 1], one unit per section.  An array: n + d + 1
        non-decreasing values (non-uniform B-splines; repeated knots allowed).
    weights : array_like, shape (n + 1,), optional
        Positive weights: a rational B-spline (NURBS).

    Notes
    -----
    Notes, chapter 5, Q.2.  The curve is defined on [u_{d−1}, u_{n+1}] (property 5):
    :attr:`domain`; a parameter outside it raises ``ArgumentValueError`` (no
    clamping).  ``evaluate(u, method=...)``: ``"de-boor"`` runs de Boor's algorithm,
    compiled; ``"cox-de-boor"`` sums the control points times the blending functions
    of :func:`basis`; ``"matrix"`` writes each knot span once in the notes' matrix
    form [t^(d−1) … t 1]·C, t local in [0, 1] (the periodic cubic's C is M_B·P), the
    coefficients C being Taylor's D^j P(u_ℓ) h^j / j! from the derivative splines,
    and evaluates it by Horner's rule, compiled.  The default, ``method=None``, is
    ``"matrix"`` up to order 6 (:data:`MATRIX_ORDER`), the fastest, and
    ``"de-boor"`` above.

    References
    ----------
    C. de Boor, "On calculating with B-splines", *J. Approx. Theory* 6, 1972.
    W. Boehm, "Inserting new knots into B-spline curves", *CAD* 12(4), 1980.
    L. Piegl and W. Tiller, *The NURBS Book*, 2nd ed., Springer, 1997.

    Examples
    --------
    The quadratic open B-spline of (0, 0), (2, 2), (4, 0) is their Bezier curve:

    >>> import scanline as sl
    >>> c = sl.curves.BSpline([(0, 0), (2, 2), (4, 0)], order=3)
    >>> c.knots.tolist(), c(0.5).tolist()
    ([0.0, 0.0, 0.0, 1.0, 1.0, 1.0], [2.0, 1.0])
    """

    METHODS = METHODS
    closed: bool
    order: int
    degree: int
    knots: NDArray[np.float64]

    def __init__(self, points: ArrayLike, order: int = 4,
                 knots: Union[str, ArrayLike, None] = "open",
                 weights: Optional[ArrayLike] = None) -> None:
        pts = control_points("points", points)
        d = _order(order, len(pts))
        w = None if weights is None else weights_array("weights", weights, len(pts))
        self.closed = isinstance(knots, str) and knots == "periodic"
        if knots is None:
            knots = "open"
        if isinstance(knots, str):
            v.choice("knots", knots, KNOT_KINDS)
            u: NDArray[np.float64]
            if self.closed:
                pts = np.vstack([pts, pts[: d - 1]])
                w = None if w is None else np.concatenate([w, w[: d - 1]])
                u = np.arange(len(pts) + d, dtype=np.float64) - (d - 1)
            elif knots == "uniform":
                u = np.arange(len(pts) + d, dtype=np.float64)
            else:
                u = open_uniform_knots(len(pts), d)
        else:
            u = check_knots(knots, len(pts), d)
        self._set(pts, d, u, w)

    def _set(self, points: NDArray[np.float64], order: int, knots: NDArray[np.float64], weights: Optional[NDArray[np.float64]]) -> None:
        self.points = points
        self.order = order
        self.degree = order - 1
        self.knots = knots
        self.weights = weights
        self.dimension = points.shape[1]
        self.domain = (float(knots[order - 1]), float(knots[len(points)]))
        for a in (points, knots, weights):
            if a is not None:
                a.flags.writeable = False
        self._power: Optional[Union[tuple[NDArray[np.float64], NDArray[np.float64]], tuple[()]]] = None

    @classmethod
    def _raw(cls: type[_Spline], points: NDArray[np.float64], order: int, knots: NDArray[np.float64],
             weights: Optional[NDArray[np.float64]] = None) -> _Spline:
        curve = cls.__new__(cls)
        curve.closed = False
        curve._set(points, order, knots, weights)
        return curve

    def _evaluate(self, u: NDArray[np.float64], method: Optional[str] = None) -> NDArray[np.float64]:
        if method is None:
            fits = self.order <= MATRIX_ORDER and self._power_form() is not None
            method = "matrix" if fits else "de-boor"
        elif method == "matrix" and self._power_form() is None:
            raise ArgumentValueError(
                "method='matrix' cannot represent this curve: a knot span is too narrow "
                "for the power form (its coefficients overflow); use method='de-boor'"
            )
        pts = self.homogeneous() if self.rational else self.points
        if method == "cox-de-boor":
            out = self._basis(u) @ pts
        else:
            out = np.empty((len(u), pts.shape[1]))
            t = v.kernel_array(u)
            if method == "de-boor":
                call(_k.de_boor, len(t) * self.order ** 2, v.kernel_array(pts),
                     v.kernel_array(self.knots), self.order, t, out)
            else:
                power = self._power_form()
                assert power is not None            # "matrix" only where it exists (above)
                call(_k.piecewise_horner, len(t) * self.order, *power, t, out)
        return project(out) if self.rational else out

    def _power_form(self) -> Optional[tuple[NDArray[np.float64], NDArray[np.float64]]]:
        """(breaks, coefficients) of the non-empty knot spans in the power form, or
        None if a coefficient or a span's 1/h is not finite (spans too narrow:
        D^j P ~ 1/h^j)."""
        if self._power is None:
            lo, hi = self.domain
            breaks = np.unique(self.knots[(self.knots >= lo) & (self.knots <= hi)])
            start, h = breaks[:-1], np.diff(breaks)
            spline = BSpline._raw(self.homogeneous() if self.rational else self.points,
                                  self.order, self.knots)
            rows: list[NDArray[np.float64]] = []
            with np.errstate(all="ignore"):
                for j in range(self.order - 1, -1, -1):  # highest power first
                    d = spline.derivative(j)
                    assert isinstance(d, BSpline)   # a plain spline's derivatives are splines
                    value = np.empty((len(start), d.dimension))
                    call(_k.de_boor, len(start) * d.order ** 2, v.kernel_array(d.points),
                         v.kernel_array(d.knots), d.order, v.kernel_array(start), value)
                    rows.append(value * (h**j / factorial(j))[:, None])
                coefficients = np.ascontiguousarray(np.stack(rows, axis=1))
                finite = np.isfinite(coefficients).all() and np.isfinite(1 / h).all()
            self._power = (breaks, coefficients) if finite else ()
        return self._power if len(self._power) == 2 else None

    def basis(self, u: ArrayLike) -> NDArray[np.float64]:
        """The blending functions B_{k,d}(u) of this curve, shape np.shape(u) + (n + 1,).

        Parameters
        ----------
        u : float or array_like of float
            Parameters in the curve's ``domain``.

        Returns
        -------
        ndarray of float64, shape ``np.shape(u) + (n + 1,)``
            B_{0,d}(u) … B_{n,d}(u) (:func:`basis`).

        Raises
        ------
        ArgumentValueError
            A parameter outside the domain.

        Examples
        --------
        The quadratic open B-spline on 3 points is a Bezier curve: its blending
        functions at u = 1/2 are (1/4, 1/2, 1/4):

        >>> import scanline as sl
        >>> sl.curves.BSpline([(0, 0), (2, 2), (4, 0)], order=3).basis(0.5).tolist()
        [0.25, 0.5, 0.25]
        """
        return self._basis(parameters("u", u, self.domain))

    def _basis(self, u: NDArray[np.float64]) -> NDArray[np.float64]:
        return basis(self.knots, self.order, u, last=len(self.points) - 1)

    def _derivative(self) -> Curve:
        if self.rational:
            return RationalDerivative(BSpline._raw(self.homogeneous(), self.order, self.knots), 1)
        if self.order == 1:
            return BSpline._raw(np.zeros_like(self.points), 1, self.knots)
        d, u = self.order, self.knots
        n = len(self.points) - 1
        gap = (u[d: n + d] - u[1: n + 1])[:, None]
        diff = np.diff(self.points, axis=0)
        q = np.divide((d - 1) * diff, gap, out=np.zeros_like(diff), where=gap > 0)
        return BSpline._raw(q, d - 1, u[1:-1])

    def insert_knot(self, u: float, times: int = 1) -> "BSpline":
        """The same curve with the knot u inserted ``times`` times (Boehm 1980).

        The control points P_{ℓ−d+2} … P_ℓ of u's span ℓ are replaced by
        Qᵢ = (1 − aᵢ) Pᵢ₋₁ + aᵢ Pᵢ, aᵢ = (u − uᵢ)/(u_{i+d−1} − uᵢ); the others are kept.
        u must lie in [u_{d−1}, u_{n+1}) and no knot may end up repeated more than d
        times.

        Parameters
        ----------
        u : float
            The new knot, in [u_{d−1}, u_{n+1}).
        times : int
            How many times to insert it, >= 0.

        Returns
        -------
        BSpline
            The same curve (same class) with ``times`` more knots and control points.

        Raises
        ------
        ArgumentValueError
            ``u`` outside the domain, or a knot repeated more than d times.

        Examples
        --------
        Inserting u = 1/2 into the quadratic on (0, 0), (2, 2), (4, 0):
        Q₁ = ½ P₀ + ½ P₁ and Q₂ = ½ P₁ + ½ P₂:

        >>> import scanline as sl
        >>> c = sl.curves.BSpline([(0, 0), (2, 2), (4, 0)], order=3).insert_knot(0.5)
        >>> c.points.tolist(), c(0.5).tolist()
        ([[0.0, 0.0], [1.0, 1.0], [3.0, 1.0], [4.0, 0.0]], [2.0, 1.0])
        """
        lo, hi = self.domain
        u = v.number("u", u)
        if not lo <= u < hi:
            raise ArgumentValueError(
                f"u must lie in [{lo:g}, {hi:g}) to insert a knot, got {u!r}"
            )
        times = v.positive_int("times", times, minimum=0)
        d = self.order
        mult = int(np.count_nonzero(self.knots == u))
        if mult + times > d:
            raise ArgumentValueError(
                f"inserting u={u:g} {times} times would repeat it {mult + times} times; "
                f"at most order={d} allowed"
            )
        pts = self.homogeneous() if self.rational else self.points
        knots = self.knots
        for _ in range(times):
            span = int(knot_span(knots, u))
            i = np.arange(span - d + 2, span + 1)
            a = ((u - knots[i]) / (knots[i + d - 1] - knots[i]))[:, None]
            new = (1.0 - a) * pts[i - 1] + a * pts[i]
            pts = np.vstack([pts[: span - d + 2], new, pts[span:]])
            knots = np.insert(knots, span + 1, u)
        if self.rational:
            return type(self)._raw(project(pts), d, knots, pts[:, -1].copy())
        return type(self)._raw(pts, d, knots)


class NURBS(BSpline):
    """A non-uniform rational B-spline: :class:`BSpline` with ``weights`` (default all 1).

    Notes
    -----
    The curve is Σ wₖPₖB_{k,d}(u) / Σ wₖB_{k,d}(u): a B-spline in homogeneous
    coordinates, projected.  Conic sections are exact, e.g. :func:`nurbs_circle`.

    Parameters
    ----------
    points : array_like, shape (n + 1, dim)
        Control points P₀ … Pₙ, finite.
    order : int
        d, 1 ≤ d ≤ n + 1.
    knots : {"open", "uniform", "periodic"} or array_like, default "open"
        The knot vector (see :class:`BSpline`).
    weights : array_like, shape (n + 1,), optional
        Positive weights; all 1 by default.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        As :class:`BSpline`.

    Examples
    --------
    The quadratic with weights (1, 2, 1) at u = 1/2:
    (¼·(0, 0) + 2·½·(2, 2) + ¼·(4, 0)) / (¼ + 1 + ¼) = (2, 4/3):

    >>> import scanline as sl
    >>> c = sl.curves.NURBS([(0, 0), (2, 2), (4, 0)], order=3, weights=[1, 2, 1])
    >>> c(0.5).round(12).tolist()
    [2.0, 1.333333333333]
    """

    def __init__(self, points: ArrayLike, order: int = 4,
                 knots: Union[str, ArrayLike, None] = "open",
                 weights: Optional[ArrayLike] = None) -> None:
        if weights is None:
            weights = np.ones(len(control_points("points", points)))
        super().__init__(points, order, knots, weights)


def nurbs_circle(center: tuple[float, float] = (0.0, 0.0), radius: float = 1.0) -> NURBS:
    """An exact circle: a quadratic NURBS with 9 control points (a square's corners and
    edge midpoints), corner weights √2/2 and knots [0 0 0 ¼ ¼ ½ ½ ¾ ¾ 1 1 1].

    Counterclockwise, starting and ending at (xc + r, yc).  Every point lies at distance
    ``radius`` from ``center`` (the parameterization is not by arc length).

    Parameters
    ----------
    center : (float, float)
        (xc, yc).
    radius : float
        r > 0.

    Returns
    -------
    NURBS
        The circle, on the domain [0, 1].

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        A center or radius that is not a finite number, or r <= 0.

    Notes
    -----
    Piegl & Tiller, *The NURBS Book*, section 7.5 (the nine-point circle).

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> c = sl.curves.nurbs_circle((1, 1), 2)
    >>> c(0.25).round(12).tolist(), c(0.5).round(12).tolist()
    ([1.0, 3.0], [-1.0, 1.0])
    >>> bool(np.allclose(np.hypot(*(c(np.linspace(0, 1, 9)) - (1, 1)).T), 2))
    True
    """
    xc, yc = (v.number("center[0]", center[0]), v.number("center[1]", center[1]))
    r = v.number("radius", radius)
    if r <= 0:
        raise ArgumentValueError(f"radius must be > 0, got {radius!r}")
    square = np.array([(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1),
                       (1, -1), (1, 0)], dtype=np.float64)
    w = np.where(np.arange(9) % 2 == 1, np.sqrt(0.5), 1.0)
    knots = [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1]
    return NURBS(square * r + (xc, yc), order=3, knots=knots, weights=w)
