"""Polygon clipping: Sutherland-Hodgman and Weiler-Atherton."""

from typing import Literal, Optional, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._kernels import clip as k
from .._kernels._jit import call
from ..errors import ArgumentValueError
from ..geometry.contours import batch, contours
from . import weiler_atherton as wa
from . import window as w

METHODS = ("sutherland-hodgman", "weiler-atherton")


def _sutherland_hodgman(verts: NDArray[np.float64], counts: ArrayLike, ring: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Run the batch kernel, growing its buffers until the results fit."""
    n = np.ascontiguousarray(counts, np.int64)
    longest = int(n.max()) if len(n) else 0
    size = 2 * (len(verts) + len(n) * len(ring)) + 8
    width = 2 * (longest + len(ring)) + 8
    while True:
        out = np.empty((size, 2))
        out_counts = np.zeros(len(n), np.int64)
        scratch = np.empty((2, width, 2))
        used: int = call(k.sutherland_hodgman, 3 * len(verts) * len(ring), verts, n, ring, out,
                    out_counts, scratch)
        if used >= 0:
            return out[:used], out_counts
        size *= 2
        width *= 2


def polygon(points: ArrayLike, window: w.WindowLike,
            method: Literal["sutherland-hodgman", "weiler-atherton"] = "sutherland-hodgman"
            ) -> list[NDArray[np.float64]]:
    """Clip a polygon by a window; returns the list of resulting contours.

    Parameters
    ----------
    points : array_like, shape (N, 2), or a list of contours
        The subject polygon: one contour, or several (an outer boundary and its
        holes, combined by the even-odd rule).  Vertices in either orientation.
    window : (xmin, ymin, xmax, ymax) or polygon, shape (M, 2)
        ``"sutherland-hodgman"`` needs a convex window; ``"weiler-atherton"``
        takes any simple polygon, concave included, or a list of contours (a
        window with holes, even-odd).
    method : {"sutherland-hodgman", "weiler-atherton"}
        The algorithm.

    Returns
    -------
    list of ndarray, each (K, 2) float64
        Sutherland-Hodgman: one contour per subject contour that is not clipped
        away entirely, in the subject's orientation.  When the window cuts a
        concave subject into several parts, they stay joined in one contour by
        *degenerate edges* running along the window boundary (they enclose no area,
        so the filled area and the shoelace area are right, but an outline shows
        them).  Weiler-Atherton: every separate part is its own contour, outer
        boundaries counterclockwise and holes clockwise.

    Raises
    ------
    TypeError, ValueError
        Vertices that are not finite numbers within +-2**30, an unknown ``method``,
        a degenerate window, or a concave one for Sutherland-Hodgman.

    Notes
    -----
    Sutherland-Hodgman (notes, syllabus "Polygon clipping. Sutherland Hodgeman
    clipping") clips the whole vertex list against one window edge at a time; for
    each subject edge s -> p it outputs the intersection when the edge crosses the
    boundary and then p when p is inside (on the boundary counts as inside).
    Weiler-Atherton follows the subject boundary while it is inside the window and
    the window boundary while it is inside the subject, switching at each crossing;
    see :mod:`scanline.clip.weiler_atherton` for how it handles vertices on edges,
    overlapping edges and holes.

    References
    ----------
    I. E. Sutherland, G. W. Hodgman, "Reentrant polygon clipping",
    Communications of the ACM 17(1), 32-42, 1974.
    K. Weiler, P. Atherton, "Hidden surface removal using polygon area sorting",
    SIGGRAPH '77, Computer Graphics 11(2), 214-222, 1977.

    Examples
    --------
    >>> import scanline as sl
    >>> u = [(0, 0), (6, 0), (6, 6), (4, 6), (4, 2), (2, 2), (2, 6), (0, 6)]
    >>> sh = sl.clip.polygon(u, (-1, 3, 7, 5))
    >>> len(sh), len(sh[0])          # one contour, joined along y = 3
    (1, 8)
    >>> wa = sl.clip.polygon(u, (-1, 3, 7, 5), method="weiler-atherton")
    >>> sorted(c.tolist() for c in wa)
    [[[0.0, 3.0], [2.0, 3.0], [2.0, 5.0], [0.0, 5.0]], [[4.0, 3.0], [6.0, 3.0], [6.0, 5.0], [4.0, 5.0]]]
    """
    chosen = v.choice("method", method, METHODS)
    verts, offsets = contours("points", points)
    rings = [w._ring(verts[offsets[c]:offsets[c + 1]]) for c in range(len(offsets) - 1)]
    rings = [r for r in rings if len(r) >= 3 and w.signed_area(r) != 0.0]
    if chosen == "sutherland-hodgman":
        ring = w.polygon(window, convex=True, algorithm="Sutherland-Hodgman")
        if not rings:
            return []
        out, counts = _sutherland_hodgman(np.concatenate(rings), [len(r) for r in rings], ring)
        return [c for c in np.split(out, np.cumsum(counts)[:-1]) if len(c)]
    window_rings = w.polygon_rings(window)
    if not rings:
        return []
    return wa.clip(rings, window_rings)


def polygons(polys: ArrayLike, window: w.WindowLike, counts: Optional[ArrayLike] = None
             ) -> Union[list[NDArray[np.float64]], tuple[NDArray[np.float64], NDArray[np.int64]]]:
    """Sutherland-Hodgman on many polygons in one compiled call.

    Parameters
    ----------
    polys : list of (N_i, 2) arrays, an (M, K, 2) array, or flat (V, 2) vertices
        One contour per polygon.  With ``counts``, ``polys`` is the flat array of
        all vertices and ``counts[i]`` says how many belong to polygon i.
    window : (xmin, ymin, xmax, ymax) or convex polygon
        The closed window.
    counts : array_like of int, optional
        The vertex count of each polygon, when ``polys`` is flat.

    Returns
    -------
    list of ndarray
        Without ``counts``: the clipped contour of each polygon ((0, 2) when
        nothing is left).
    (vertices, counts)
        With ``counts``: the flat clipped vertices and the count of each polygon.

    Raises
    ------
    TypeError, ValueError
        Malformed polygons or counts, a polygon with holes, or a degenerate or
        concave window.

    Notes
    -----
    Sutherland-Hodgman (Hearn & Baker, section 6-8), as :func:`polygon`.

    Examples
    --------
    >>> import scanline as sl
    >>> out = sl.clip.polygons([[(0, 0), (4, 0), (0, 4)], [(5, 5), (6, 5), (6, 6)]], (1, 1, 9, 9))
    >>> [len(c) for c in out]
    [3, 3]
    """
    ring = w.polygon(window, convex=True, algorithm="Sutherland-Hodgman")
    if counts is None:
        verts, offsets, parts = batch("polys", polys)
        if len(parts) - 1 != len(offsets) - 1:
            raise ArgumentValueError(
                "polys must give one contour per polygon for the batch clipper; clip "
                "polygons with holes one at a time with sl.clip.polygon")
        n = np.diff(offsets)
        out, out_counts = _sutherland_hodgman(verts, n, ring)
        return np.split(out, np.cumsum(out_counts)[:-1]) if len(n) else []
    verts, _ = contours("polys", polys)
    n, _ = v.counts("counts", counts, len(verts), "polys")
    return _sutherland_hodgman(verts, n, ring)
