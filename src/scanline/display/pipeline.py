"""From a primitive in device coordinates to the commands a device draws.

The interpreter maps each primitive to device coordinates (workstation matrix times
segment transformation) and hands it here with the device clipping rectangle.  What
comes out is the same for every device -- clipped polylines to stroke and clipped
contours to fill -- so the raster and the vector output of one display file agree.
"""

import functools
import math
from typing import Any, Literal, Optional, Sequence, Union

import numpy as np
from numpy.typing import NDArray

from .. import clip as clipping

#: A device rectangle (xmin, ymin, xmax, ymax).
Rect = tuple[float, float, float, float]
#: A clip region: a rectangle, or a convex (M, 2) polygon (see :func:`inside`).
Window = Union[Rect, NDArray[np.float64]]

#: Largest distance (device units) between a flattened ellipse and the true curve.
FLATNESS = 0.25

#: Most segments of a flattened ellipse (a radius of about 10^6 device units).
MAX_SEGMENTS = 8192

#: Marker strokes of a unit marker (size 1), as (x0, y0, x1, y1) rows.
_S = math.sqrt(0.5) / 2
_MARKER_STROKES = {
    "dot": np.array([[0.0, 0.0, 0.0, 0.0]]),
    "plus": np.array([[-0.5, 0, 0.5, 0], [0, -0.5, 0, 0.5]]),
    "cross": np.array([[-_S, -_S, _S, _S], [-_S, _S, _S, -_S]]),
    "asterisk": np.array([[-0.5, 0, 0.5, 0], [0, -0.5, 0, 0.5],
                          [-_S, -_S, _S, _S], [-_S, _S, _S, -_S]]),
}


def ellipse_points(center: NDArray[np.float64], axes: NDArray[np.float64]) -> NDArray[np.float64]:
    """The ellipse ``center + axes @ (cos t, sin t)`` as a closed polygon (first point
    not repeated) within :data:`FLATNESS` of the curve."""
    with np.errstate(all="ignore"):  # overflow -> inf, refused when drawn
        return _ellipse_points(center, axes)


def _ellipse_points(center: NDArray[np.float64], axes: NDArray[np.float64]) -> NDArray[np.float64]:
    r = float(np.sqrt((axes * axes).sum(axis=0)).max())
    # a chord of the angle 2 pi / n stays within r (1 - cos(pi / n)) of the circle
    step = math.acos(1.0 - FLATNESS / r) if r > FLATNESS else math.pi / 2
    n = MAX_SEGMENTS if step == 0.0 else int(min(MAX_SEGMENTS, max(
        4 if r <= FLATNESS else 16, math.ceil(math.pi / step))))
    points: NDArray[np.float64] = center + _unit_ring(n) @ axes.T
    return points


@functools.lru_cache(maxsize=64)
def _unit_ring(n: int) -> NDArray[np.float64]:
    """(cos t, sin t) at n angles t = 2 pi k / n (read-only; an animation flattens the
    same ellipses on every frame)."""
    t = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    ring = np.stack([np.cos(t), np.sin(t)], axis=1)
    ring.flags.writeable = False
    return ring


def marker_segments(points: NDArray[np.float64], kind: str, size: float) -> NDArray[np.float64]:
    """Device-space line segments (N, 4) drawing ``kind`` markers at ``points``."""
    if kind == "circle":
        unit = ellipse_points(np.zeros(2), np.eye(2) * 0.5)
        ring = np.hstack([unit, np.roll(unit, -1, axis=0)])
    else:
        ring = _MARKER_STROKES[kind]
    offsets = np.hstack([points, points])
    segments: NDArray[np.float64] = (offsets[:, None, :] + size * ring[None, :, :]).reshape(-1, 4)
    return segments


def inside(pts: NDArray[np.float64], window: Any) -> NDArray[np.bool_]:
    """Which points lie in the window: a rectangle (xmin, ymin, xmax, ymax) or a
    convex polygon (M, 2), counterclockwise; the boundary counts as inside."""
    if isinstance(window, tuple):
        box: NDArray[np.bool_] = ((pts[:, 0] >= window[0]) & (pts[:, 0] <= window[2])
                                  & (pts[:, 1] >= window[1]) & (pts[:, 1] <= window[3]))
        return box
    a, b = window, np.roll(window, -1, axis=0)
    cross = ((b[:, 0] - a[:, 0]) * (pts[:, 1, None] - a[:, 1])
             - (b[:, 1] - a[:, 1]) * (pts[:, 0, None] - a[:, 0]))
    within: NDArray[np.bool_] = (cross >= 0).all(axis=1)
    return within


def polylines(pts: NDArray[np.float64], closed: bool,
              window: Any) -> tuple[list[NDArray[np.float64]], bool]:
    """Clip one polyline to ``window`` (see :func:`inside`): a list of (K, 2) pieces
    and whether the result is still one closed ring."""
    ring = np.vstack([pts, pts[:1]]) if closed and len(pts) > 1 else pts
    if len(pts) and inside(ring, window).all():
        return [pts], closed
    method: Literal["liang-barsky", "cyrus-beck"] = (
        "liang-barsky" if isinstance(window, tuple) else "cyrus-beck")
    return clipping.polyline(ring, window, method=method), False


def contours(cs: Any, window: Any) -> list[NDArray[np.float64]]:
    """Clip a fill area (contours combined by a fill rule) to ``window``.

    Sutherland-Hodgman clips each contour; inside a convex window that keeps every
    point's winding number, so both fill rules still hold.  The edges it adds along
    the window boundary enclose no area.
    """
    return [c for c in clipping.polygon(list(cs), window, method="sutherland-hodgman")
            if len(c) >= 3]


def intersect(a: Sequence[float], b: Sequence[float]
              ) -> Optional[tuple[float, float, float, float]]:
    """The intersection of two rectangles, or None when it is empty."""
    r = (max(a[0], b[0]), max(a[1], b[1]), min(a[2], b[2]), min(a[3], b[3]))
    return r if r[0] <= r[2] and r[1] <= r[3] else None
