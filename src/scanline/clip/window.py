"""Clip windows: an upright rectangle ``(xmin, ymin, xmax, ymax)`` or a polygon.

Every clipper takes its window through one of these parsers, so the checks and the
messages are the same everywhere: a window must have a positive width and height
(or area), finite coordinates within +-2**30, and, where the algorithm needs it, be
convex.  Any object with a ``bounds`` attribute (such as
:class:`scanline.viewing.Window`) is taken as the rectangle ``bounds``.
"""

import math
from typing import Optional, Protocol, Sequence, Union, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..geometry.contours import contours


class HasBounds(Protocol):
    """An object with a ``bounds`` attribute (xmin, ymin, xmax, ymax), such as
    :class:`scanline.viewing.Window`."""

    @property
    def bounds(self) -> Sequence[float]: ...


#: A clip window: an upright rectangle (xmin, ymin, xmax, ymax), an object with
#: ``bounds``, or a polygon ((M, 2) vertices, or a list of contours).
WindowLike = Union[ArrayLike, HasBounds]


def _is_rectangle_spec(window: object) -> bool:
    if hasattr(window, "bounds"):
        return True
    if isinstance(window, np.ndarray):
        return bool(window.ndim == 1)
    if isinstance(window, (list, tuple)) and len(window) == 4:
        return all(not isinstance(c, (list, tuple, np.ndarray)) for c in window)
    return False


def rectangle(window: object, name: str = "window") -> tuple[float, float, float, float]:
    """``(xmin, ymin, xmax, ymax)`` as floats, checked.

    Raises ArgumentValueError for a window of zero (or negative) width or height.
    """
    spec = window.bounds if hasattr(window, "bounds") else window
    if isinstance(spec, (str, bytes)) or not hasattr(spec, "__len__"):
        raise ArgumentTypeError(
            f"{name} must be (xmin, ymin, xmax, ymax), got {v._show(window)}")
    spec = cast("Sequence[object]", spec)
    if len(spec) != 4:
        raise ArgumentValueError(
            f"{name} must be a rectangle (xmin, ymin, xmax, ymax) with 4 numbers, got "
            f"{v._show(window)}")
    xmin, ymin, xmax, ymax = (v.number(f"{name}[{i}]", c) for i, c in enumerate(spec))
    for i, c in enumerate((xmin, ymin, xmax, ymax)):
        if abs(c) > v.COORD_LIMIT:
            raise ArgumentValueError(
                f"{name}[{i}]={c!r} is outside the supported coordinate range "
                f"[-{v.COORD_LIMIT}, {v.COORD_LIMIT}]")
    if not (xmin < xmax and ymin < ymax):
        raise ArgumentValueError(
            f"{name}={v._show(window)} is degenerate: it needs xmin < xmax and "
            f"ymin < ymax (a window of zero width or height shows nothing), e.g. "
            f"(0, 0, 10, 10)")
    return xmin, ymin, xmax, ymax


def rectangle_polygon(xmin: float, ymin: float, xmax: float, ymax: float) -> NDArray[np.float64]:
    """The rectangle's corners, counterclockwise from the lower left."""
    return np.array([(xmin, ymin), (xmax, ymin), (xmax, ymax), (xmin, ymax)], np.float64)


def _ring(points: NDArray[np.float64]) -> NDArray[np.float64]:
    """Drop repeated consecutive vertices (and a repeated first vertex at the end)."""
    if len(points) == 0:
        return points
    keep = np.any(points != np.concatenate((points[-1:], points[:-1])), axis=1)  # np.roll, faster
    if not keep.any():
        return points[:1]
    return points[keep]


def signed_area(points: NDArray[np.float64]) -> float:
    """Shoelace area: positive for a counterclockwise ring (taken about the first
    vertex: with coordinates near 2**29 and a side of 1e-6 the products about the
    origin cancel and could give the wrong sign)."""
    x, y = points[:, 0] - points[0, 0], points[:, 1] - points[0, 1]
    ahead = slice(1, None), slice(None, 1)              # np.roll(a, -1), without its overhead
    return 0.5 * float(np.dot(x, np.concatenate((y[ahead[0]], y[ahead[1]])))
                       - np.dot(np.concatenate((x[ahead[0]], x[ahead[1]])), y))


def polygon(window: object, name: str = "window", convex: bool = False,
            algorithm: Optional[str] = None) -> NDArray[np.float64]:
    """A polygon window as a counterclockwise (M, 2) float64 array.

    A rectangle spec is turned into its four corners.  With ``convex=True`` a
    non-convex polygon raises ArgumentValueError naming ``algorithm``.
    """
    rings = polygon_rings(window, name)
    if len(rings) != 1:
        raise ArgumentValueError(
            f"{name} must be one polygon contour (an (M, 2) array of vertices) for "
            f"{algorithm or 'this algorithm'}, got {len(rings)} contours")
    ring = rings[0]
    if signed_area(ring) < 0:
        ring = ring[::-1].copy()
    if convex:
        check_convex(ring, name, algorithm)
    return np.ascontiguousarray(ring)


def polygon_rings(window: object, name: str = "window") -> list[NDArray[np.float64]]:
    """A window as a list of (M, 2) rings (a rectangle's corners counterclockwise;
    a polygon's contours as given, repeated vertices dropped), each checked to have
    at least 3 distinct vertices and a nonzero area."""
    if _is_rectangle_spec(window):
        return [rectangle_polygon(*rectangle(window, name))]
    verts, offsets = contours(name, window)
    rings: list[NDArray[np.float64]] = []
    for c in range(len(offsets) - 1):
        ring = _ring(verts[offsets[c]:offsets[c + 1]])
        if len(ring) < 3 or signed_area(ring) == 0.0:
            raise ArgumentValueError(
                f"{name} is degenerate: a polygon window needs at least 3 distinct "
                f"vertices and a nonzero area in each contour, got {v._show(window)}")
        rings.append(np.ascontiguousarray(ring))
    if not rings:
        raise ArgumentValueError(f"{name} must have at least one contour, got {v._show(window)}")
    return rings


def check_convex(ring: NDArray[np.float64], name: str, algorithm: Optional[str]) -> None:
    """Raise unless the counterclockwise ``ring`` is convex (collinear vertices are
    allowed): every turn is a left turn and the turns add up to one revolution."""
    d = np.roll(ring, -1, axis=0) - ring
    e = np.roll(d, -1, axis=0)
    cross = d[:, 0] * e[:, 1] - d[:, 1] * e[:, 0]
    turning = float(np.sum(np.arctan2(cross, np.einsum("ij,ij->i", d, e))))
    if (cross < 0).any() or abs(turning - 2 * math.pi) > 1e-6:
        bad = int(np.argmax(cross < 0)) if (cross < 0).any() else 0
        vertex = np.asarray(ring)[(bad + 1) % len(ring)].tolist()
        raise ArgumentValueError(
            f"{name} must be a convex polygon for {algorithm}, but it turns the other "
            f"way at vertex {vertex} (or winds more than once); use "
            f"method='weiler-atherton' for concave windows, or split the window into "
            f"convex parts")


def is_convex(ring: ArrayLike) -> bool:
    """Whether the polygon ``ring`` (vertices (N, 2), N >= 3, either orientation,
    collinear vertices allowed) is convex.

    >>> is_convex([(0, 0), (4, 0), (1, 1), (0, 4)]), is_convex([(0, 0), (0, 4), (4, 0)])
    (False, True)
    """
    try:
        a = np.array(ring, dtype=np.float64)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"ring must be (N, 2) vertices, got {v._show(ring)}") from None
    if a.ndim != 2 or a.shape[1] != 2 or len(a) < 3 or not np.isfinite(a).all():
        raise ArgumentValueError(
            f"ring must be at least 3 finite (x, y) vertices, got {v._show(ring)}")
    for candidate in (a, a[::-1].copy()):
        try:
            check_convex(candidate, "window", "")
        except ArgumentValueError:
            continue
        return True
    return False


def outward_normals(ring: NDArray[np.float64]) -> NDArray[np.float64]:
    """Unit outward normals (M, 2) of the edges of the counterclockwise ``ring``
    (edge i from ring[i] to ring[i + 1]): N = (dy, -dx) / |d|."""
    d = np.roll(ring, -1, axis=0) - ring
    n = np.stack([d[:, 1], -d[:, 0]], axis=1) / np.hypot(d[:, 0], d[:, 1])[:, None]
    return np.ascontiguousarray(n + 0.0)


def contains(ring: NDArray[np.float64], pts: NDArray[np.float64]) -> NDArray[np.bool_]:
    """Which of the (N, 2) points lie in the closed convex counterclockwise ``ring``
    (left of or on every edge)."""
    d = np.roll(ring, -1, axis=0) - ring
    cross = (d[None, :, 0] * (pts[:, None, 1] - ring[None, :, 1])
             - d[None, :, 1] * (pts[:, None, 0] - ring[None, :, 0]))
    return cast("NDArray[np.bool_]", (cross >= 0).all(axis=1))
