"""Flattening Bezier curves into polylines within a tolerance (notes, chapter 2,
"Scan-line fill of curved boundary areas", and the Bezier curves of chapter 5).

A curved boundary is filled by the scan-line algorithm once it is replaced by a
polygon close enough to it.  Each quadratic or cubic Bezier segment is split into
``m`` equal steps of its parameter, with ``m`` chosen *per segment* from the
flatness of its control polygon, so a nearly straight segment becomes one chord and
a tight turn many (adaptive in the number of steps, uniform within a segment, which
keeps the whole computation vectorized in numpy).

The bound (Wang 1984, as given by Filip, Magedson & Markot 1986): for a Bezier
curve of degree ``n`` with control points P_0 .. P_n, the polyline through the
points at ``u = i / m`` stays within distance

    d <= n (n - 1) / 8 * L / m**2,     L = max_i |P_i - 2 P_(i+1) + P_(i+2)|,

of the curve.  So ``m = ceil(sqrt(n (n - 1) L / (8 tolerance)))`` steps keep the
error below ``tolerance``: ``sqrt(L / (4 tol))`` for a quadratic, ``sqrt(3 L / (4 tol))``
for a cubic.  (The bound is the second derivative's maximum, ``n (n - 1) L``, times
the chord-interpolation error ``h**2 / 8`` of a step ``h = 1 / m``.)

References
----------
D. Filip, R. Magedson, R. Markot, "Surface algorithms using bounds on derivatives",
Computer Aided Geometric Design 3 (1986), 295-311 (Wang's formula, lemma 3).
G. Wang, "The subdivision method for finding the intersection between two Bezier
curves or surfaces", Zhejiang University Journal, 1984.
D. Hearn, M. P. Baker, "Computer Graphics", 2nd ed., 1994, section 10-6 (Bezier
curves, the Bernstein blending functions).
"""

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentValueError

#: Upper bound on the steps of one segment, so a wild control point with a tiny
#: tolerance cannot ask for billions of points.
MAX_STEPS = 1 << 16


def _controls(name: str, value: ArrayLike, count: int) -> NDArray[np.float64]:
    a = np.asarray(value, dtype=np.float64)
    if a.ndim == 2 and a.shape == (count, 2):
        a = a[None]
    if a.ndim != 3 or a.shape[1:] != (count, 2):
        raise ArgumentValueError(
            f"{name} must have shape (N, {count}, 2): N segments of {count} control "
            f"points (x, y); got shape {a.shape}")
    if not np.isfinite(a).all():
        raise ArgumentValueError(f"{name} must hold finite coordinates")
    return a


def steps(controls: NDArray[np.float64], tolerance: float) -> NDArray[np.int64]:
    """The number of equal parameter steps that flattens each segment within
    ``tolerance`` (Wang's bound, see the module docstring).

    Parameters
    ----------
    controls : ndarray, shape (N, n + 1, 2)
        N Bezier segments of degree n.
    tolerance : float
        Largest distance allowed between curve and polyline (> 0).

    Returns
    -------
    ndarray of int64, shape (N,), each in 1 .. MAX_STEPS.

    Examples
    --------
    A straight quadratic needs one step; a right-angle turn of 100 units twelve at a
    tolerance of 0.25 (L = |(0,0) - 2 (100,0) + (100,100)| = 141.4 and
    sqrt(141.4 / (4 * 0.25)) = 11.9 -> 12):

    >>> import numpy as np
    >>> steps(np.array([[[0, 0], [1, 1], [2, 2]], [[0, 0], [100, 0], [100, 100]]],
    ...       float), 0.25).tolist()
    [1, 12]
    """
    n = controls.shape[1] - 1
    second = controls[:, :-2] - 2 * controls[:, 1:-1] + controls[:, 2:]
    worst = np.sqrt((second ** 2).sum(axis=2)).max(axis=1)
    m = np.ceil(np.sqrt(n * (n - 1) * worst / (8.0 * tolerance)))
    counts: NDArray[np.int64] = np.clip(m, 1, MAX_STEPS).astype(np.int64)
    return counts


def _bernstein(controls: NDArray[np.float64], m: NDArray[np.int64]) -> NDArray[np.float64]:
    """Points of each segment at u = 1/m .. m/m (the start point is left out, so
    consecutive segments of a contour join without repeating points)."""
    n = controls.shape[1] - 1
    seg = np.repeat(np.arange(len(controls)), m)
    first = np.cumsum(m) - m
    i = np.arange(int(m.sum())) - np.repeat(first, m) + 1
    u = (i / m[seg])[:, None]
    w = 1.0 - u
    c = controls[seg]
    if n == 2:
        return w * w * c[:, 0] + 2 * w * u * c[:, 1] + u * u * c[:, 2]
    return (w * w * w * c[:, 0] + 3 * w * w * u * c[:, 1] + 3 * w * u * u * c[:, 2]
            + u * u * u * c[:, 3])


def _flatten(name: str, controls: ArrayLike, count: int, tolerance: float
             ) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    tolerance = v.number("tolerance", tolerance)
    if tolerance <= 0:
        raise ArgumentValueError(f"tolerance must be > 0 (device units), got {tolerance}")
    c = _controls(name, controls, count)
    m = steps(c, tolerance)
    return _bernstein(c, m), m


def quadratic(controls: ArrayLike, tolerance: float = 0.25) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Flatten quadratic Bezier segments.

    Parameters
    ----------
    controls : array_like, shape (N, 3, 2) or (3, 2)
        Control points P0, P1, P2 of each segment.
    tolerance : float
        Largest distance between the curve and the polyline, in the units of the
        control points (device pixels when they are device coordinates).

    Returns
    -------
    points : ndarray, shape (K, 2)
        The polyline's points after each segment's start: segment ``s`` contributes
        ``counts[s]`` points ending with its P2.  Prepend P0 of the first segment to
        get the whole polyline.
    counts : ndarray of int64, shape (N,)

    Examples
    --------
    >>> pts, counts = quadratic([[0, 0], [1, 2], [2, 0]], tolerance=0.1)
    >>> counts.tolist(), pts[-1].tolist()
    ([4], [2.0, 0.0])
    """
    return _flatten("controls", controls, 3, tolerance)


def cubic(controls: ArrayLike, tolerance: float = 0.25) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Flatten cubic Bezier segments; as :func:`quadratic` with P0 .. P3.

    Examples
    --------
    >>> pts, counts = cubic([[0, 0], [0, 10], [10, 10], [10, 0]], tolerance=0.25)
    >>> int(counts[0]), pts[-1].tolist()
    (7, [10.0, 0.0])
    """
    return _flatten("controls", controls, 4, tolerance)
