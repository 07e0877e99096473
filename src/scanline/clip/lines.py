"""Point, line and polyline clipping (notes, chapter 4, Q.2-Q.4)."""

from typing import Optional, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._typing import ClipMethod, Points
from .._kernels import clip as k
from .._kernels._jit import call
from .._kernels.variants import token
from ..errors import ArgumentTypeError, ArgumentValueError
from . import window as w

METHODS = ("cohen-sutherland", "liang-barsky", "cyrus-beck")


def _segments(segments: ArrayLike, name: str = "segments") -> NDArray[np.float64]:
    """(N, 4) float64 array; the values are checked by the kernels (see
    :func:`_check`)."""
    try:
        raw = np.asarray(segments)
        if raw.dtype.kind in "cbSUV":     # complex, bool, text: not coordinates
            raise TypeError
        a = np.asarray(raw, dtype=np.float64)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"{name} must be a numeric array of shape (N, 4) (rows x0, y0, x1, y1), got "
            f"{v._show(segments)}") from None
    if a.ndim == 1 and a.size in (0, 4):
        a = a.reshape(-1, 4)
    if a.ndim != 2 or a.shape[1] != 4:
        raise ArgumentValueError(
            f"{name} must have shape (N, 4) (rows x0, y0, x1, y1), got shape {a.shape}")
    return np.ascontiguousarray(a)


def _check(bad: int, a: NDArray[np.float64], name: str) -> None:
    """Raise for row ``bad`` of ``a`` (a kernel found a NaN or a huge value there)."""
    if bad >= 0:
        raise ArgumentValueError(
            f"{name} row {bad} = {a[bad].tolist()} must be finite and within the "
            f"supported coordinate range [-{v.COORD_LIMIT}, {v.COORD_LIMIT}]")


def _points(pts: Points, name: str) -> NDArray[np.float64]:
    """(N, 2) float64 array of finite points within +-2**30."""
    try:
        a = np.asarray(pts, dtype=np.float64)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"{name} must be a numeric array of shape (N, 2), got {v._show(pts)}") from None
    if a.size == 0:
        return np.empty((0, 2))
    if a.ndim != 2 or a.shape[1] != 2:
        raise ArgumentValueError(f"{name} must have shape (N, 2), got shape {a.shape}")
    bad = ~(np.abs(a) <= v.COORD_LIMIT).all(axis=1)
    _check(int(np.argmax(bad)) if bad.any() else -1, a, name)
    return np.ascontiguousarray(a)


def _method(method: str) -> ClipMethod:
    return cast(ClipMethod, v.choice("method", method, METHODS))


def point(x: float, y: float, window: w.WindowLike) -> bool:
    """Whether the point (x, y) survives point clipping.

    Parameters
    ----------
    x, y : float
        The point.
    window : (xmin, ymin, xmax, ymax) or convex polygon
        A closed window: points on its boundary are kept.

    Returns
    -------
    bool
        True when the point is kept.

    Raises
    ------
    TypeError, ValueError
        A coordinate that is not a finite number within +-2**30, or a window that is
        degenerate or not convex.

    Notes
    -----
    Notes, chapter 4, Q.2: keep (x, y) iff xw_min <= x <= xw_max and
    yw_min <= y <= yw_max.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.clip.point(5, 0, (0, 0, 10, 10)), sl.clip.point(11, 5, (0, 0, 10, 10))
    (True, False)
    """
    return bool(points([(x, y)], window)[0])


def points(pts: Points, window: w.WindowLike) -> NDArray[np.bool_]:
    """Point clipping for many points: a bool mask, True where a point is kept.

    Parameters
    ----------
    pts : array_like, shape (N, 2)
        The points (x, y), finite and within +-2**30.
    window : (xmin, ymin, xmax, ymax) or convex polygon (counterclockwise or not)
        A closed window: points on its boundary are kept.

    Returns
    -------
    ndarray of bool, shape (N,)
        True where a point is kept.

    Raises
    ------
    TypeError, ValueError
        ``pts`` not an (N, 2) array of finite numbers within +-2**30, or a window
        that is degenerate or not convex.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.clip.points([(0, 0), (10, 10.5), (-1e-9, 3)], (0, 0, 10, 10)).tolist()
    [True, False, False]
    """
    p = _points(pts, "pts")
    if w._is_rectangle_spec(window):
        xmin, ymin, xmax, ymax = w.rectangle(window)
        return (xmin <= p[:, 0]) & (p[:, 0] <= xmax) & (ymin <= p[:, 1]) & (p[:, 1] <= ymax)
    return w.contains(w.polygon(window, convex=True, algorithm="point clipping"), p)


def lines(segments: ArrayLike, window: w.WindowLike, method: ClipMethod = "liang-barsky"
          ) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """Clip N line segments in one compiled call.

    Parameters
    ----------
    segments : array_like, shape (N, 4)
        Rows (x0, y0, x1, y1); any finite coordinates within +-2**30.
    window : (xmin, ymin, xmax, ymax), or a convex polygon for ``"cyrus-beck"``
        Closed: a segment that only touches the boundary is kept (as the touching
        part, possibly a single point).
    method : {"liang-barsky", "cohen-sutherland", "cyrus-beck"}
        The algorithm.

    Returns
    -------
    clipped : ndarray of float64, shape (N, 4)
        The visible part of each segment, in the same direction as given.  Rows
        that are not accepted hold the segment as given.
    accepted : ndarray of bool, shape (N,)
        True where some of the segment is visible.

    Raises
    ------
    TypeError
        ``segments`` is not a numeric array.
    ValueError
        ``segments`` not of shape (N, 4) or with a coordinate not finite or beyond
        +-2**30; an unknown ``method``; a window that is degenerate, or not a
        rectangle for Cohen-Sutherland and Liang-Barsky, or not convex for
        Cyrus-Beck.

    Notes
    -----
    Notes, chapter 4, Q.3 (Cohen-Sutherland: region codes, trivial accept and
    reject, intersections with y = y1 + m (x - x1)) and Q.4 (Cyrus-Beck:
    t = N_i.(P0 - PE_i) / -N_i.D, potentially entering when N_i.D < 0, leaving when
    N_i.D > 0, visible from t_E = max(0, PE) to t_L = min(1, PL) if t_E <= t_L).
    Liang-Barsky is Cyrus-Beck for an upright rectangle, written with
    p_k and q_k.  All three give the same segments (to round-off).

    References
    ----------
    I. E. Sutherland, W. M. Newman, "Principles of Interactive Computer Graphics",
    McGraw-Hill, 1973 (the Cohen-Sutherland algorithm).
    M. Cyrus, J. Beck, "Generalized two- and three-dimensional clipping",
    Computers & Graphics 3(1), 23-28, 1978.
    Y.-D. Liang, B. A. Barsky, "A new concept and method for line clipping",
    ACM Transactions on Graphics 3(1), 1-22, 1984.

    Examples
    --------
    >>> import scanline as sl
    >>> seg, ok = sl.clip.lines([(-5, 5, 15, 5), (20, 0, 30, 5)], (0, 0, 10, 10))
    >>> seg[0].tolist(), ok.tolist()
    ([0.0, 5.0, 10.0, 5.0], [True, False])
    """
    method = _method(method)
    seg = _segments(segments)
    out = np.empty(seg.shape)
    accepted = np.empty(len(seg), np.bool_)
    if method == "cyrus-beck":
        ring = w.polygon(window, convex=True, algorithm="Cyrus-Beck")
        rect, code = np.zeros(4), k.CYRUS_BECK
    elif not w._is_rectangle_spec(window):
        raise ArgumentValueError(
            f"window must be a rectangle (xmin, ymin, xmax, ymax) for {method}; "
            f"use method='cyrus-beck' for a convex polygon window, got {v._show(window)}")
    else:
        rect = np.array(w.rectangle(window))
        ring = w.rectangle_polygon(*rect)
        code = k.COHEN_SUTHERLAND if method == "cohen-sutherland" else k.LIANG_BARSKY
    bad: int = call(k.clip_lines, 2 * len(seg) * len(ring), token(code), seg.reshape(-1), rect, ring,
               w.outward_normals(ring), float(v.COORD_LIMIT), out.reshape(-1), accepted)
    _check(bad, seg, "segments")
    return out, accepted


def line(x0: float, y0: float, x1: float, y1: float, window: w.WindowLike,
         method: ClipMethod = "liang-barsky") -> Optional[tuple[float, float, float, float]]:
    """Clip the segment from (x0, y0) to (x1, y1).

    Parameters
    ----------
    x0, y0, x1, y1 : float
        The segment's ends, finite and within +-2**30.
    window : (xmin, ymin, xmax, ymax), or a convex polygon for ``"cyrus-beck"``
        The closed window (see :func:`lines`).
    method : {"liang-barsky", "cohen-sutherland", "cyrus-beck"}
        The algorithm (notes, chapter 4, Q.3 and Q.4).

    Returns
    -------
    tuple of 4 floats or None
        The visible part ``(x0, y0, x1, y1)`` (same direction), or None when none
        of the segment is visible.

    Raises
    ------
    TypeError, ValueError
        As :func:`lines`.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.clip.line(-5, -5, 15, 15, (0, 0, 10, 10), method="cohen-sutherland")
    (0.0, 0.0, 10.0, 10.0)
    >>> sl.clip.line(-5, 12, 15, 12, (0, 0, 10, 10)) is None
    True
    """
    ends = [v.number(n, c) for n, c in (("x0", x0), ("y0", y0), ("x1", x1), ("y1", y1))]
    out, ok = lines([ends], window, method)
    x0_, y0_, x1_, y1_ = out[0].tolist()
    return (x0_, y0_, x1_, y1_) if ok[0] else None


def polyline(pts: Points, window: w.WindowLike, method: ClipMethod = "liang-barsky"
             ) -> list[NDArray[np.float64]]:
    """Clip a polyline: the list of its visible pieces, each a (K, 2) array.

    The polyline's segments are clipped in one batch; consecutive visible segments
    that still meet (neither was cut at the shared vertex) are joined into one piece.

    Parameters
    ----------
    pts : array_like, shape (N, 2)
        The polyline's vertices.
    window : (xmin, ymin, xmax, ymax), or a convex polygon for ``"cyrus-beck"``
        The closed window (see :func:`lines`).
    method : {"liang-barsky", "cohen-sutherland", "cyrus-beck"}
        The line-clipping algorithm.

    Returns
    -------
    list of ndarray of float64, shape (K, 2)
        The visible pieces, in order.

    Raises
    ------
    TypeError, ValueError
        As :func:`lines`.

    Examples
    --------
    >>> import scanline as sl
    >>> [p.tolist() for p in sl.clip.polyline([(-2, 1), (2, 1), (2, 12), (6, 4)], (0, 0, 10, 10))]
    [[[0.0, 1.0], [2.0, 1.0], [2.0, 10.0]], [[3.0, 10.0], [6.0, 4.0]]]
    """
    p = _points(pts, "pts")
    if len(p) == 1:
        return [p.copy()] if points(p, window)[0] else []
    seg = np.hstack([p[:-1], p[1:]])
    out, ok = lines(seg, window, method)
    pieces: list[list[tuple[float, ...]]] = []
    current: Optional[list[tuple[float, ...]]] = None
    for i in range(len(seg)):
        if not ok[i]:
            current = None
            continue
        a, b = out[i, :2], out[i, 2:]
        if current is not None and current[-1] == tuple(a):
            current.append(tuple(b))
        else:
            current = [tuple(a), tuple(b)]
            pieces.append(current)
    return [np.array(c, np.float64) for c in pieces]
