"""The :class:`Curve` base class and the argument checks every curve shares.

A curve is a map u -> point from a parameter interval ``domain = (u_min, u_max)``
to ``dimension``-D space.  Subclasses implement ``_evaluate`` (a 1-D float array of
parameters already checked to lie in the domain -> an (N, dimension) array) and
``_derivative`` (the first derivative as another :class:`Curve`); the base class does
the rest: argument checking, shapes, higher derivatives and flattening.
"""

import numbers
from typing import Callable, Optional

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import ArgumentTypeError, ArgumentValueError
from .._validate import _show, choice


class Curve:
    """A parametric curve P(u), u in ``domain``, with values in ``dimension``-D space.

    ``curve(u)`` is ``curve.evaluate(u)``.

    Attributes
    ----------
    domain : tuple of float
        ``(u_min, u_max)``, the parameter interval on which the curve is defined.
    dimension : int
        Number of coordinates of each point (2 for plane curves, 3 for space curves).

    Notes
    -----
    Notes, chapter 5 (Hearn & Baker, chapter 10): the parametric representation
    P(u) of curves, used by every subclass.

    Examples
    --------
    >>> import scanline as sl
    >>> c = sl.curves.Bezier([(0, 0), (2, 2), (4, 0)])
    >>> isinstance(c, sl.curves.Curve), c.domain, c.dimension
    (True, (0.0, 1.0), 2)
    >>> c(0.5).tolist()
    [2.0, 1.0]
    """

    #: set by subclasses
    domain: tuple[float, float] = (0.0, 1.0)
    dimension: int = 2
    #: names of the evaluation algorithms a subclass offers (``method=``)
    METHODS: tuple[str, ...] = ()

    def evaluate(self, u: ArrayLike, method: Optional[str] = None) -> NDArray[np.float64]:
        """Points on the curve.

        Parameters
        ----------
        u : float or array_like of float
            Parameter values inside ``domain`` (the ends included).
        method : str, optional
            One of the class's ``METHODS``; None picks the default.

        Returns
        -------
        numpy.ndarray
            Shape ``np.shape(u) + (dimension,)``: one point per parameter value.

        Raises
        ------
        ArgumentValueError
            If a parameter is NaN or outside ``domain``, or ``method`` is not one of
            ``METHODS``.

        Examples
        --------
        A quadratic Bezier curve at u = 1/2: (P0 + 2 P1 + P2) / 4:

        >>> import scanline as sl
        >>> sl.curves.Bezier([(0, 0), (2, 2), (4, 0)]).evaluate([0.0, 0.5]).tolist()
        [[0.0, 0.0], [2.0, 1.0]]
        """
        if method is not None:
            choice("method", method, self.METHODS)
        params = parameters("u", u, self.domain)
        flat = params.ravel()
        with_method: Callable[..., NDArray[np.float64]] = self._evaluate
        out = self._evaluate(flat) if method is None else with_method(flat, method)
        return out.reshape(params.shape + (self.dimension,))

    __call__ = evaluate

    def derivative(self, k: int = 1) -> "Curve":
        """The k-th derivative dᵏP/duᵏ as a curve with the same ``domain``.

        ``k = 0`` returns the curve itself.

        Parameters
        ----------
        k : int
            The order of the derivative, >= 0.

        Returns
        -------
        Curve
            The derivative, a curve on the same domain.

        Raises
        ------
        ArgumentValueError
            ``k`` is not an integer >= 0.

        Examples
        --------
        P(u) = (4u, 4u(1 - u)) (control points (0, 0), (2, 2), (4, 0)) has
        P'(u) = (4, 4 - 8u) and P'' = (0, -8):

        >>> import scanline as sl
        >>> c = sl.curves.Bezier([(0, 0), (2, 2), (4, 0)])
        >>> c.derivative().evaluate(0.0).tolist(), c.derivative(2).evaluate(0.5).tolist()
        ([4.0, 4.0], [0.0, -8.0])
        """
        if isinstance(k, bool) or not isinstance(k, numbers.Integral) or k < 0:
            raise ArgumentValueError(
                f"k must be an integer >= 0 (the order of the derivative), got {_show(k)}"
            )
        curve: Curve = self
        for _ in range(int(k)):
            curve = curve._derivative()
        return curve

    def flatten(self, tolerance: float = 0.25) -> NDArray[np.float64]:
        """A polyline within ``tolerance`` of the curve: a (K, dimension) array.

        See :func:`scanline.curves.flatten.flatten`.

        Parameters
        ----------
        tolerance : float
            Largest distance between the curve and the polyline (> 0).

        Returns
        -------
        ndarray of float64, shape (K, dimension)
            The polyline, from ``domain[0]`` to ``domain[1]``.

        Raises
        ------
        ArgumentValueError
            ``tolerance`` is not a number > 0.

        Examples
        --------
        A straight Bezier curve flattens to its two ends:

        >>> import scanline as sl
        >>> sl.curves.Bezier([(0, 0), (1, 1), (2, 2)]).flatten(0.1).tolist()
        [[0.0, 0.0], [2.0, 2.0]]
        """
        from .flatten import flatten

        return flatten(self, tolerance)

    def _evaluate(self, u: NDArray[np.float64]) -> NDArray[np.float64]:  # pragma: no cover - abstract
        raise NotImplementedError

    def _derivative(self) -> "Curve":  # pragma: no cover - abstract
        raise NotImplementedError

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.dimension}-D on [{self.domain[0]:g}, {self.domain[1]:g}]>"


def control_points(name: str, value: ArrayLike, minimum: int = 1) -> NDArray[np.float64]:
    """Return ``value`` as a float64 (n + 1, dim) array of finite points, dim >= 1.

    Raises an error naming ``name`` if it is not a 2-D array of at least ``minimum``
    rows, or holds NaN or infinite coordinates.
    """
    try:
        if np.asarray(value).dtype.kind in "cbSUV":    # complex, bool, text
            raise TypeError
        a = np.array(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"{name} must be an array of points of shape (n + 1, 2) or (n + 1, 3), got "
            f"{_show(value)}"
        ) from None
    if a.size == 0 and a.shape[0] < minimum:
        raise ArgumentValueError(f"{name} must hold at least {minimum} points, got none")
    if a.ndim != 2 or a.shape[1] < 1:
        raise ArgumentValueError(
            f"{name} must be an array of points of shape (n + 1, 2) or (n + 1, 3), got "
            f"shape {a.shape}"
        )
    if a.shape[0] < minimum:
        raise ArgumentValueError(
            f"{name} must hold at least {minimum} points, got {a.shape[0]}"
        )
    bad = ~np.isfinite(a)
    if bad.any():
        row = int(np.argwhere(bad)[0][0])
        raise ArgumentValueError(
            f"{name} must be finite; point {row} is {a[row].tolist()}"
        )
    return a


def weights_array(name: str, value: ArrayLike, count: int) -> NDArray[np.float64]:
    """Return ``value`` as ``count`` finite positive float64 weights."""
    try:
        w = np.array(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"{name} must be an array of numbers, got {_show(value)}") from None
    if w.shape != (count,):
        raise ArgumentValueError(
            f"{name} must hold one weight per control point ({count}), got shape {w.shape}"
        )
    if not (np.isfinite(w).all() and (w > 0).all()):
        raise ArgumentValueError(
            f"{name} must be finite and > 0, got {_show(w.tolist())}"
        )
    return w


def parameters(name: str, value: ArrayLike, domain: tuple[float, float]) -> NDArray[np.float64]:
    """Return ``value`` as a float64 array of parameters inside ``domain``.

    Out-of-range parameters are an error: a curve is not defined there (the B-spline's
    valid range, notes ch. 5 Q.2 property 5).
    """
    try:
        u = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"{name} must be a number or an array of numbers, got {_show(value)}"
        ) from None
    lo, hi = domain
    if u.size and not (u.min() >= lo and u.max() <= hi):  # also catches NaN
        bad = float(u[~((u >= lo) & (u <= hi))].ravel()[0])
        raise ArgumentValueError(
            f"{name} must lie in the curve's domain [{lo:g}, {hi:g}]; got {bad!r}"
        )
    return u
