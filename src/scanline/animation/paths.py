"""Motion paths with arc-length parameterization (notes, chapter 6, Q4: "motion paths
can be defined with a kinematic description in terms of a set of spline curves";
Hearn & Baker §16-5 and §16-6).

A curve's parameter u does not run at constant speed along it: equal steps of u
bunch up where the control points do.  :class:`MotionPath` measures the curve's arc
length s(u) = ∫ |P'(u)| du and inverts it, so that equal steps of its parameter
cover equal distances; an easing then controls the speed along the path exactly as
it controls any other in-between, and an object can face along the tangent.

>>> import scanline as sl
>>> path = sl.animation.MotionPath([(0, 0), (30, 0), (30, 40)])   # a polyline
>>> path.length
70.0
>>> path.point(0.5).tolist()
[30.0, 5.0]
"""

import math
from typing import Any, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from ..budget import check as budget
from ._checks import flag, floats
from .easing import Easing, apply, fractions, resolve

#: Intervals of the arc-length table integrated at a time (bounding the memory of the
#: quadrature's temporaries, whatever ``intervals`` is).
CHUNK = 1 << 16

#: Gauss–Legendre nodes and weights on [0, 1] (8 points: exact for degree 15).
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(8)
_NODES = (_NODES + 1) / 2
_WEIGHTS = _WEIGHTS / 2


class _Polyline:
    """A polyline as a curve with parameter u in [0, segments]: one unit per segment."""

    def __init__(self, points: NDArray[np.float64]) -> None:
        self.points = points
        self.domain = (0.0, float(len(points) - 1))
        self.dimension = points.shape[1]

    def evaluate(self, u: ArrayLike) -> NDArray[np.float64]:
        u = np.asarray(u, dtype=np.float64)
        k = np.clip(np.floor(u).astype(np.int64), 0, len(self.points) - 2)
        f = (u - k)[..., None]
        out: NDArray[np.float64] = self.points[k] + f * (self.points[k + 1] - self.points[k])
        return out

    def velocity(self, u: ArrayLike) -> NDArray[np.float64]:
        u = np.asarray(u, dtype=np.float64)
        k = np.clip(np.floor(u).astype(np.int64), 0, len(self.points) - 2)
        out: NDArray[np.float64] = self.points[k + 1] - self.points[k]
        return out


class _Smooth:
    """A :class:`scanline.curves.Curve` and its derivative."""

    def __init__(self, curve: Any) -> None:
        self.curve = curve
        self.derivative = curve.derivative()
        lo, hi = (float(x) for x in curve.domain)
        self.domain = (lo, hi)
        self.dimension = curve.dimension

    def evaluate(self, u: ArrayLike) -> NDArray[np.float64]:
        lo, hi = self.domain
        out: NDArray[np.float64] = self.curve.evaluate(np.clip(u, lo, hi))
        return out

    def velocity(self, u: ArrayLike) -> NDArray[np.float64]:
        lo, hi = self.domain
        out: NDArray[np.float64] = self.derivative.evaluate(np.clip(u, lo, hi))
        return out


def _geometry(curve: Any) -> Union[_Polyline, _Smooth]:
    from ..curves import Curve

    if isinstance(curve, Curve):
        return _Smooth(curve)
    if isinstance(curve, MotionPath):
        return curve._geometry
    points = floats("curve", curve, "a scanline.curves curve or an array of polyline points")
    if points.ndim != 2 or len(points) < 2 or points.shape[1] < 1:
        raise ArgumentValueError(f"curve as points must have shape (N >= 2, dim), got "
                                 f"shape {points.shape}")
    if not np.isfinite(points).all():
        raise ArgumentValueError(f"curve must have finite points, got {v._show(points.tolist())}")
    return _Polyline(points)


class MotionPath:
    """A path for an object to move along, parameterized by arc length.

    Parameters
    ----------
    curve : scanline.curves.Curve or array_like (N, dim)
        Any curve of :mod:`scanline.curves` (Bezier, B-spline, NURBS, Catmull–Rom ...)
        in 2-D or 3-D, or the points of a polyline.
    arc_length : bool
        True (default): the path parameter s in [0, 1] is the fraction of the length
        travelled.  False: s runs linearly over the curve's own parameter (the speed
        then varies as the curve's does).
    intervals : int, optional
        Intervals of the arc-length table (default 64 per curve section, at least
        256); each is integrated by 8-point Gauss–Legendre quadrature.

    Notes
    -----
    For s in [0, 1] the parameter u(s) solves s·L = ∫_{u0}^{u} |P'(w)| dw: the table
    brackets u in one interval, and Newton's method on the interval's quadrature
    (derivative |P'(u)|) refines it to about 1e-12 of the length.  A polyline's arc
    length is exact.

    References
    ----------
    B. Guenter and R. Parent, "Computing the arc length of parametric curves", *IEEE
    Computer Graphics and Applications* 10(3), 1990.  Hearn & Baker, §16-6.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``curve`` is not a curve or at least two finite points, its length is not
        positive and finite, or ``intervals`` is not a positive integer.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.animation.MotionPath([(0, 0), (30, 0), (30, 40)])
    MotionPath(2-D, length 70, by arc length)
    """

    _geometry: Union[_Polyline, _Smooth]

    def __init__(self, curve: Any, arc_length: bool = True,
                 intervals: int | None = None) -> None:
        self._geometry = g = _geometry(curve)
        self.arc_length = flag("arc_length", arc_length)
        lo, hi = g.domain
        if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
            raise ArgumentValueError(f"curve has the parameter domain [{lo:g}, {hi:g}]; a motion "
                                     "path needs a finite one")
        if isinstance(g, _Polyline):
            self._u = np.arange(len(g.points), dtype=np.float64)
            pieces = np.linalg.norm(np.diff(g.points, axis=0), axis=1)
        else:
            if intervals is None:
                intervals = max(256, 64 * math.ceil(hi - lo))
            intervals = v.positive_int("intervals", intervals)
            # the table (parameters, lengths, running sums) and, per piece of at most
            # CHUNK intervals, the quadrature's points and speeds
            budget(intervals * 8 * 4 + CHUNK * 8 * 8 * (2 * g.dimension + 8), "intervals",
                   f"an arc-length table of {intervals} intervals",
                   hint="give fewer intervals (the default is 64 per curve section)")
            self._u = np.linspace(lo, hi, intervals + 1)
            starts, ends = self._u[:-1], self._u[1:]
            pieces = np.concatenate([self._integral(starts[k:k + CHUNK], ends[k:k + CHUNK])
                                     for k in range(0, intervals, CHUNK)])
        self._cumulative = np.concatenate([[0.0], np.cumsum(pieces)])
        self.length = float(self._cumulative[-1])
        if not (self.length > 0 and math.isfinite(self.length)):
            raise ArgumentValueError(
                f"curve has length {self.length}: a motion path must have a positive, "
                "finite length (its points must not all coincide)")
        self.dimension = g.dimension

    # -- arc length ------------------------------------------------------------------
    def _speed(self, u: NDArray[np.float64]) -> NDArray[np.float64]:
        out: NDArray[np.float64] = np.linalg.norm(self._geometry.velocity(u), axis=-1)
        return out

    def _integral(self, a: ArrayLike, b: ArrayLike) -> NDArray[np.float64]:
        """∫_a^b |P'(u)| du by Gauss–Legendre, for arrays a, b."""
        a, b = np.asarray(a, np.float64), np.asarray(b, np.float64)
        u = a[..., None] + (b - a)[..., None] * _NODES
        out: NDArray[np.float64] = (b - a) * (self._speed(u.ravel()).reshape(u.shape) @ _WEIGHTS)
        return out

    def parameter(self, s: ArrayLike) -> NDArray[np.float64]:
        """The curve parameter u at path parameter(s) ``s`` in [0, 1].

        Parameters
        ----------
        s : float or array_like
            Path parameters in [0, 1].

        Returns
        -------
        numpy.ndarray, of ``s``'s shape

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``s`` is not in [0, 1].

        Examples
        --------
        Half of 70 is 5 units into the second segment (length 40), whose parameter
        runs from 1 to 2:

        >>> import scanline as sl
        >>> path = sl.animation.MotionPath([(0, 0), (30, 0), (30, 40)])     # length 70
        >>> path.parameter([0, 0.5]).tolist()
        [0.0, 1.125]
        """
        s = fractions(s, "s")
        flat = s.ravel()
        lo, hi = self._geometry.domain
        if not self.arc_length:
            return (lo + flat * (hi - lo)).reshape(s.shape)
        target = flat * self.length
        cum, table = self._cumulative, self._u
        k = np.clip(np.searchsorted(cum, target, side="right") - 1, 0, len(table) - 2)
        if isinstance(self._geometry, _Polyline):
            piece = cum[k + 1] - cum[k]
            f = np.divide(target - cum[k], piece, out=np.zeros_like(target), where=piece > 0)
            return np.asarray((table[k] + f).reshape(s.shape), np.float64)
        a, b = table[k], table[k + 1]
        want = target - cum[k]
        piece = cum[k + 1] - cum[k]
        u = a + np.divide(want, piece, out=np.zeros_like(want), where=piece > 0) * (b - a)
        for _ in range(6):
            speed = self._speed(u)
            step = np.divide(self._integral(a, u) - want, speed, out=np.zeros_like(u),
                             where=speed > 1e-300)
            u = np.clip(u - step, a, b)
        return np.asarray(u.reshape(s.shape), np.float64)

    def distance(self, s: ArrayLike) -> NDArray[np.float64]:
        """The arc length from the start to path parameter(s) ``s``.

        Parameters
        ----------
        s : float or array_like
            Path parameters in [0, 1].

        Returns
        -------
        numpy.ndarray, of ``s``'s shape

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``s`` is not in [0, 1].

        Examples
        --------
        >>> import scanline as sl
        >>> path = sl.animation.MotionPath([(0, 0), (30, 0), (30, 40)])     # length 70
        >>> path.distance([0.5, 1.0]).tolist()
        [35.0, 70.0]
        """
        if self.arc_length:
            return fractions(s, "s") * self.length
        u = np.ravel(self.parameter(s))
        k = np.clip(np.searchsorted(self._u, u, side="right") - 1, 0, len(self._u) - 2)
        if isinstance(self._geometry, _Polyline):
            piece = self._cumulative[k + 1] - self._cumulative[k]
            out = self._cumulative[k] + (u - self._u[k]) * piece
        else:
            out = self._cumulative[k] + self._integral(self._u[k], u)
        return np.asarray(out.reshape(np.shape(s)), np.float64)

    # -- positions and directions ------------------------------------------------------
    def point(self, s: ArrayLike) -> NDArray[np.float64]:
        """The point(s) at path parameter(s) ``s`` in [0, 1]: shape ``np.shape(s) + (dim,)``.

        Parameters
        ----------
        s : float or array_like
            Path parameters in [0, 1].

        Returns
        -------
        numpy.ndarray, shape ``np.shape(s) + (dim,)``

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``s`` is not in [0, 1].

        Examples
        --------
        >>> import scanline as sl
        >>> path = sl.animation.MotionPath([(0, 0), (30, 0), (30, 40)])     # length 70
        >>> path.point([0, 0.5, 1]).tolist()
        [[0.0, 0.0], [30.0, 5.0], [30.0, 40.0]]
        """
        u = self.parameter(s)
        out: NDArray[np.float64] = self._geometry.evaluate(u.ravel()).reshape(
            np.shape(u) + (self.dimension,))
        return out

    __call__ = point

    def tangent(self, s: ArrayLike) -> NDArray[np.float64]:
        """The unit tangent(s) at ``s``, in the direction of travel (where the curve's
        derivative vanishes, the direction of its next nonzero derivative is taken
        from a nearby point).

        Parameters
        ----------
        s : float or array_like
            Path parameters in [0, 1].

        Returns
        -------
        numpy.ndarray, shape ``np.shape(s) + (dim,)``

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``s`` is not in [0, 1].

        Examples
        --------
        >>> import scanline as sl
        >>> path = sl.animation.MotionPath([(0, 0), (30, 0), (30, 40)])     # length 70
        >>> path.tangent([0.25, 0.75]).tolist()
        [[1.0, 0.0], [0.0, 1.0]]
        """
        u = np.ravel(self.parameter(s))
        d = self._geometry.velocity(u)
        n = np.linalg.norm(d, axis=1)
        stalled = n <= 1e-12 * self.length
        if stalled.any():
            lo, hi = self._geometry.domain
            nudge = 1e-6 * (hi - lo)
            near = np.where(u[stalled] + nudge <= hi, u[stalled] + nudge, u[stalled] - nudge)
            sign = np.where(u[stalled] + nudge <= hi, 1.0, -1.0)[:, None]
            d[stalled] = sign * (self._geometry.evaluate(near) - self._geometry.evaluate(u[stalled]))
            n = np.linalg.norm(d, axis=1)
        out: NDArray[np.float64] = (d / n[:, None]).reshape(np.shape(s) + (self.dimension,))
        return out

    def heading(self, s: ArrayLike) -> Union[float, NDArray[np.float64]]:
        """2-D paths: the direction of travel at ``s`` as an angle in radians,
        counterclockwise from +x (to make an object face along the path).

        Parameters
        ----------
        s : float or array_like
            Path parameters in [0, 1].

        Returns
        -------
        float or numpy.ndarray, of ``s``'s shape

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``s`` is not in [0, 1] or the path is not 2-D.

        Examples
        --------
        >>> import scanline as sl
        >>> path = sl.animation.MotionPath([(0, 0), (30, 0), (30, 40)])     # length 70
        >>> round(path.heading(0.75), 9)                  # up the second segment: pi/2
        1.570796327
        """
        self._require_2d("heading")
        t = self.tangent(s)
        out: NDArray[np.float64] = np.arctan2(t[..., 1], t[..., 0])
        return float(out) if out.ndim == 0 else out

    def transform(self, s: float, orient: bool = True) -> NDArray[np.float64]:
        """2-D paths: the 3x3 matrix that moves an object drawn around the origin (and
        facing +x) to the point at ``s``, turned along the tangent when ``orient``.

        Parameters
        ----------
        s : float
            One path parameter in [0, 1].
        orient : bool, default True
            Turn the object along the tangent.

        Returns
        -------
        ndarray of float64, shape (3, 3)
            T(point) · R(heading), or T(point) alone.

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``s`` is not one number in [0, 1] or the path is not 2-D.

        Examples
        --------
        3/4 of 70 is 22.5 units up the second segment:

        >>> import scanline as sl
        >>> path = sl.animation.MotionPath([(0, 0), (30, 0), (30, 40)])     # length 70
        >>> path.transform(0.75, orient=False).tolist()
        [[1.0, 0.0, 30.0], [0.0, 1.0, 22.5], [0.0, 0.0, 1.0]]
        """
        from .. import transform as tf

        self._require_2d("transform")
        given = fractions(s, "s")
        if given.ndim != 0:
            raise ArgumentValueError(f"s must be one path parameter in [0, 1], got an array of "
                                     f"shape {given.shape}")
        one = float(given)
        x, y = (float(c) for c in self.point(one))
        m = tf.translation(x, y)
        if not flag("orient", orient):
            return m
        return tf.compose(m, tf.rotation(float(self.heading(one))))

    def at(self, t: ArrayLike, start: float = 0.0, end: float = 1.0,
           ease: Union[str, Easing] = "linear") -> NDArray[np.float64]:
        """The point at time(s) ``t`` of a trip from ``start`` to ``end`` seconds, the
        time fraction eased by ``ease`` (held at the ends outside [start, end]).

        Parameters
        ----------
        t : float or array_like
            Times in seconds, finite.
        start, end : float, default 0 and 1
            The trip's start and end, start < end.
        ease : str or callable, default "linear"
            The easing of the time fraction (:func:`~scanline.animation.ease`).

        Returns
        -------
        numpy.ndarray, shape ``np.shape(t) + (dim,)``

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If the times are not finite, start >= end, or ``ease`` is unknown.

        Notes
        -----
        Motion along a path with simulated acceleration (Hearn & Baker, §16-5).

        Examples
        --------
        >>> import scanline as sl
        >>> path = sl.animation.MotionPath([(0, 0), (30, 0), (30, 40)])     # length 70
        >>> path.at(1.0, start=0, end=2).tolist()          # half way in time
        [30.0, 5.0]
        """
        return self.point(self.progress(t, start, end, ease))

    def progress(self, t: ArrayLike, start: float = 0.0, end: float = 1.0,
                 ease: Union[str, Easing] = "linear") -> Union[float, NDArray[np.float64]]:
        """The path parameter s at time(s) ``t`` (see :meth:`at`).

        Parameters
        ----------
        t : float or array_like
            Times in seconds, finite.
        start, end : float, default 0 and 1
            The trip's start and end, start < end.
        ease : str or callable, default "linear"
            The easing of the time fraction.

        Returns
        -------
        float or numpy.ndarray, of ``t``'s shape
            In [0, 1].

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If the times are not finite, start >= end, or ``ease`` is unknown.

        Examples
        --------
        >>> import scanline as sl
        >>> path = sl.animation.MotionPath([(0, 0), (30, 0), (30, 40)])     # length 70
        >>> path.progress([0, 1, 3], start=0, end=2).tolist()
        [0.0, 0.5, 1.0]
        """
        start, end = v.number("start", start), v.number("end", end)
        if not start < end:
            raise ArgumentValueError(f"start must come before end, got start={start}, end={end}")
        if not math.isfinite(end - start):
            raise ArgumentValueError(f"end - start overflows (start={start:g}, end={end:g})")
        times = floats("t", t, "a time or an array of times")
        if not np.isfinite(times).all():
            raise ArgumentValueError(f"t must be finite, got {v._show(times.tolist())}")
        f = np.clip((times - start) / (end - start), 0.0, 1.0)
        out = apply(resolve(ease), f)
        return float(out) if out.ndim == 0 else out

    def _require_2d(self, what: str) -> None:
        if self.dimension != 2:
            raise ArgumentValueError(f"{what} is for 2-D paths; this path is {self.dimension}-D "
                                     "(use tangent)")

    def __repr__(self) -> str:
        kind = "arc length" if self.arc_length else "curve parameter"
        return f"MotionPath({self.dimension}-D, length {self.length:g}, by {kind})"
