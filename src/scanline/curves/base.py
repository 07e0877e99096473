"""The :class:`Curve` base class and the argument checks every curve shares.

A curve is a map u -> point from a parameter interval ``domain = (u_min, u_max)``
to ``dimension``-D space.  Subclasses implement ``_evaluate`` (a 1-D float array of
parameters already checked to lie in the domain -> an (N, dimension) array) and
``_derivative`` (the first derivative as another :class:`Curve`); the base class does
the rest: argument checking, shapes, higher derivatives and flattening.
"""

import numbers

import numpy as np

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
    """

    #: set by subclasses
    domain = (0.0, 1.0)
    dimension = 2
    #: names of the evaluation algorithms a subclass offers (``method=``)
    METHODS = ()

    def evaluate(self, u, method=None):
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
            If a parameter is NaN or outside ``domain``.
        """
        if method is not None:
            choice("method", method, self.METHODS)
        u = parameters("u", u, self.domain)
        flat = u.ravel()
        out = self._evaluate(flat) if method is None else self._evaluate(flat, method)
        return out.reshape(u.shape + (self.dimension,))

    __call__ = evaluate

    def derivative(self, k=1):
        """The k-th derivative dᵏP/duᵏ as a curve with the same ``domain``.

        ``k = 0`` returns the curve itself.
        """
        if isinstance(k, bool) or not isinstance(k, numbers.Integral) or k < 0:
            raise ArgumentValueError(
                f"k must be an integer >= 0 (the order of the derivative), got {_show(k)}"
            )
        curve = self
        for _ in range(int(k)):
            curve = curve._derivative()
        return curve

    def flatten(self, tolerance=0.25):
        """A polyline within ``tolerance`` of the curve: a (K, dimension) array.

        See :func:`scanline.curves.flatten.flatten`.
        """
        from .flatten import flatten

        return flatten(self, tolerance)

    def _evaluate(self, u):  # pragma: no cover - abstract
        raise NotImplementedError

    def _derivative(self):  # pragma: no cover - abstract
        raise NotImplementedError

    def __repr__(self):
        return f"<{type(self).__name__} {self.dimension}-D on [{self.domain[0]:g}, {self.domain[1]:g}]>"


def control_points(name, value, minimum=1):
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


def weights_array(name, value, count):
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


def parameters(name, value, domain):
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
