"""Curve clipping (notes, chapter 4, Q.1 "curve clipping"): circles and ellipses
against a window, as the visible arcs; any curve through its flattened polyline."""

import math
from typing import Protocol, Sequence, Union, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._typing import ClipMethod, Points
from ..curves.flatten import MAX_POINTS
from ..errors import ArgumentTypeError, ArgumentValueError
from . import window as w
from .lines import _points, polyline

TWO_PI = 2 * math.pi

#: An angle interval (start, end) of an arc, radians.
Interval = tuple[float, float]


class Flattenable(Protocol):
    """A curve that flattens itself into a polyline (the curves of
    :mod:`scanline.curves`)."""

    def flatten(self, tolerance: float = ...) -> NDArray[np.float64]: ...


def _intersect(intervals: list[Interval], start: float, length: float) -> list[Interval]:
    """The parts of ``intervals`` (sorted, within [0, 2 pi)) inside the circular
    interval [start, start + length)."""
    out: list[Interval] = []
    for s0 in (start - TWO_PI, start, start + TWO_PI):
        for a, b in intervals:
            lo, hi = max(a, s0), min(b, s0 + length)
            if lo < hi:
                out.append((lo, hi))
    return sorted(out)


def ellipse(xc: float, yc: float, rx: float, ry: float, window: w.WindowLike
            ) -> list[Interval]:
    """The visible arcs of the ellipse (x - xc)**2 / rx**2 + (y - yc)**2 / ry**2 = 1.

    Parameters
    ----------
    xc, yc : float
        Center.
    rx, ry : float
        Semi-axes along x and y, > 0.
    window : (xmin, ymin, xmax, ymax) or convex polygon
        Closed; arcs that only touch the boundary at a point are dropped.

    Returns
    -------
    list of (float, float)
        Intervals ``(start, end)`` of the parameter angle t, counterclockwise from
        +x (the point is (xc + rx cos t, yc + ry sin t)); ``0 <= start < 2 pi``
        and ``start < end <= start + 2 pi``: an arc through t = 0 ends beyond
        2 pi.  The whole ellipse is ``[(0.0, 2 pi)]``.

    Raises
    ------
    TypeError, ValueError
        A center or semi-axis that is not a finite number, ``rx`` or ``ry`` <= 0, or
        a window that is degenerate or not convex.

    Notes
    -----
    Each window edge, with outward unit normal n through the point a, keeps the
    points with n.(p - a) <= 0.  Mapped to the unit circle by
    (x, y) -> ((x - xc) / rx, (y - yc) / ry) (which keeps t and convexity), the
    edge keeps cos(t - phi) <= -d / |m| (m the mapped normal, phi its angle, d the
    mapped center's signed distance), one arc; the visible arcs are the
    intersection of these arcs over the edges.

    Examples
    --------
    >>> import math, scanline as sl
    >>> [(round(a / math.pi, 6), round(b / math.pi, 6))
    ...  for a, b in sl.clip.ellipse(0, 0, 2, 1, (-3, 0, 3, 3))]   # upper half
    [(0.0, 1.0)]
    """
    cx, cy = v.number("xc", xc), v.number("yc", yc)
    ax, ay = v.number("rx", rx), v.number("ry", ry)
    if ax <= 0 or ay <= 0:
        raise ArgumentValueError(f"rx and ry must be > 0, got rx={rx!r}, ry={ry!r}")
    ring = w.polygon(window, convex=True, algorithm="curve clipping")
    unit = (ring - (cx, cy)) / (ax, ay)
    normals = w.outward_normals(unit)
    intervals: list[Interval] = [(0.0, TWO_PI)]
    for a, n in zip(unit, normals):
        d = float(np.dot(n, -a))                 # n.(center - a), center = (0, 0)
        c = -d                                   # inside where cos(t - phi) <= c
        if c >= 1.0:
            continue
        if c <= -1.0:
            return []
        alpha = math.acos(c)
        phi = math.atan2(n[1], n[0])
        intervals = _intersect(intervals, (phi + alpha) % TWO_PI, TWO_PI - 2 * alpha)
        if not intervals:
            return []
    # join the arc that runs through t = 0
    if len(intervals) > 1 and intervals[0][0] == 0.0 and intervals[-1][1] == TWO_PI:
        first = intervals.pop(0)
        last = intervals.pop()
        intervals.append((last[0], TWO_PI + first[1]))
        intervals.sort()
    return intervals


def circle(xc: float, yc: float, r: float, window: w.WindowLike) -> list[Interval]:
    """The visible arcs of the circle of center (xc, yc) and radius r > 0, as angle
    intervals; see :func:`ellipse`.

    Parameters
    ----------
    xc, yc : float
        Center.
    r : float
        Radius, > 0.
    window : (xmin, ymin, xmax, ymax) or convex polygon
        Closed; arcs that only touch the boundary at a point are dropped.

    Returns
    -------
    list of (float, float)
        The visible arcs' angle intervals ``(start, end)``, as :func:`ellipse`.

    Raises
    ------
    TypeError, ValueError
        As :func:`ellipse`.

    Notes
    -----
    Curve clipping, notes chapter 4, Q.1 (Hearn & Baker, section 6-9).

    Examples
    --------
    >>> import math, scanline as sl
    >>> arcs = sl.clip.circle(0, 0, 10, (-8, -8, 8, 8))   # four arcs at the corners
    >>> len(arcs), round(sum(b - a for a, b in arcs) / math.pi, 6)
    (4, 0.361338)
    """
    return ellipse(xc, yc, r, r, window)


def arcs(xc: float, yc: float, rx: float, ry: float,
         intervals: Union[Sequence[Sequence[float]], ArrayLike],
         tolerance: float = 0.25) -> list[NDArray[np.float64]]:
    """Flatten elliptical arcs into polylines within ``tolerance`` of the curve.

    Parameters
    ----------
    xc, yc : float
        Center.
    rx, ry : float
        Semi-axes along x and y.
    intervals : list of (float, float)
        Angle intervals ``(start, end)``, start <= end, as :func:`ellipse` returns
        them.
    tolerance : float
        Largest distance between the arc and its polyline (> 0).

    Returns
    -------
    list of ndarray of float64, shape (K, 2)
        One polyline per interval, from start to end.

    Raises
    ------
    TypeError, ValueError
        Intervals that are not (start, end) pairs or run backwards, a tolerance
        <= 0, or one that would need more than ``MAX_POINTS`` points.

    Examples
    --------
    >>> import scanline as sl
    >>> [p.round(6).tolist() for p in sl.clip.arcs(0, 0, 1, 1, [(0, 1.5707963267948966)], 0.5)]
    [[[1.0, 0.0], [0.0, 1.0]]]
    """
    cx, cy = v.number("xc", xc), v.number("yc", yc)
    ax, ay = v.number("rx", rx), v.number("ry", ry)
    tol = v.number("tolerance", tolerance)
    if tol <= 0:
        raise ArgumentValueError(f"tolerance must be > 0, got {tolerance!r}")
    r = max(abs(ax), abs(ay))
    step = 2 * math.acos(max(-1.0, 1 - tol / r)) if r > 0 else math.pi
    spans: list[Interval] = []
    for i, interval in enumerate(_intervals(intervals)):
        start = v.number(f"intervals[{i}] start", interval[0])
        end = v.number(f"intervals[{i}] end", interval[1])
        if end < start:
            raise ArgumentValueError(f"intervals[{i}] = ({start}, {end}) runs backwards; give "
                                     "(start, end) with start <= end, as ellipse() returns them")
        spans.append((start, end))
    total = sum(max(1.0, math.ceil((end - start) / step)) + 1 for start, end in spans)
    if total > MAX_POINTS:
        raise ArgumentValueError(
            f"tolerance={tolerance!r} would flatten these arcs into about {total:.3g} points, "
            f"more than {MAX_POINTS}; use a larger tolerance")
    out: list[NDArray[np.float64]] = []
    for start, end in spans:
        n = max(1, math.ceil((end - start) / step))
        t = np.linspace(start, end, n + 1)
        out.append(np.stack([cx + ax * np.cos(t), cy + ay * np.sin(t)], axis=1))
    return out


def _intervals(value: object) -> list[Sequence[float]]:
    """The (start, end) pairs of ``intervals``, or raise naming it."""
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if not isinstance(value, (list, tuple)) or not all(
            isinstance(i, (list, tuple, np.ndarray)) and len(i) == 2 for i in value):
        raise ArgumentTypeError(f"intervals must be a list of (start, end) angle pairs, as "
                                f"ellipse() returns, got {v._show(value)}")
    return cast("list[Sequence[float]]", list(value))


def curve(c: Union[Flattenable, Points], window: w.WindowLike, tolerance: float = 0.25,
          method: ClipMethod = "liang-barsky") -> list[NDArray[np.float64]]:
    """Clip any curve by its flattened polyline: the visible pieces, (K, 2) arrays.

    ``c`` is an object with ``flatten(tolerance)`` (the curves of
    :mod:`scanline.curves`) or an (N, 2) array of points along a curve; the pieces
    come from :func:`scanline.clip.polyline`.

    Parameters
    ----------
    c : curve or array_like, shape (N, 2)
        A curve with ``flatten(tolerance)``, or points along a curve.
    window : (xmin, ymin, xmax, ymax), or a convex polygon for ``"cyrus-beck"``
        The closed window.
    tolerance : float
        The flattening tolerance passed to ``c.flatten``.
    method : {"liang-barsky", "cohen-sutherland", "cyrus-beck"}
        The line-clipping algorithm.

    Returns
    -------
    list of ndarray of float64, shape (K, 2)
        The visible pieces, in order.

    Raises
    ------
    TypeError, ValueError
        As :func:`scanline.clip.polyline`.

    Notes
    -----
    Curve clipping, notes chapter 4, Q.1: the curve is approximated by a polyline
    and its segments are line-clipped (Hearn & Baker, section 6-9).

    Examples
    --------
    >>> import scanline as sl
    >>> [p.tolist() for p in sl.clip.curve([(0, 0), (4, 4), (8, 0)], (0, 0, 6, 6))]
    [[[0.0, 0.0], [4.0, 4.0], [6.0, 2.0]]]
    >>> import numpy as np
    >>> [p.tolist() for p in sl.clip.curve(np.array([(-2.0, 1.0), (2.0, 1.0)]), (0, 0, 6, 6))]
    [[[0.0, 1.0], [2.0, 1.0]]]
    """
    # an ndarray has a flatten method too (numpy's, not a curve's): it is points
    pts = (cast(Flattenable, c).flatten(tolerance)
           if hasattr(c, "flatten") and not isinstance(c, np.ndarray) else c)
    return polyline(_points(pts, "curve"), window, method)
