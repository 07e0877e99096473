"""Inside-outside tests: the odd-parity (even-odd) rule and the nonzero winding-number
rule (Hearn & Baker, "Computer Graphics", section 3-11, "Inside-outside tests").

Both count the polygon edges crossed by a ray from the point towards -x (to the
left).  The boundary convention is the fill's top-left rule, so that
``sl.draw.polygon`` fills exactly the pixels whose centers ``inside`` accepts: an
edge from ``(xlo, ylo)`` up to ``(xhi, yhi)`` is crossed by the ray from ``(px, py)``
when ``ylo < py <= yhi`` and its crossing ``xc = xlo + (py - ylo) * dx / dy`` has
``xc <= px``.  A point exactly on a left edge, or on a horizontal edge with the area
below it, is inside; on a right edge, or on a horizontal edge with the area above
it, outside.  (This is the test of the point ``(px + e, py - e**2)`` for an
infinitesimal ``e``, which lies on no edge: a point is inside exactly one polygon of
a tiling.)

For integer points and integer edges the test is exact (int64: coordinates within
+-2**30); otherwise it evaluates the edge equation in float64 with the lower
endpoint first, exactly as the fill kernel does.  The work is vectorized with numpy
over points x edges, in chunks that bound the memory.
"""

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._typing import Points, Rule
from ..errors import ArgumentTypeError, ArgumentValueError
from .contours import check_vertices, contours

RULES = ("even-odd", "nonzero")

#: Points x edges per chunk of the vectorized test (about 16 MB of temporaries).
CHUNK = 1 << 18


def _points(points: Points) -> tuple[NDArray[np.float64], tuple[int, ...]]:
    try:
        a = np.asarray(points)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"points must be an (M, 2) array of points, got {v._show(points)}") from None
    if a.dtype == bool or a.dtype.kind not in "iuf":
        raise ArgumentTypeError(f"points must hold real numbers, got an array of dtype {a.dtype}")
    if a.size == 0:
        return np.empty((0, 2), np.float64), a.shape[:-1] if a.ndim > 1 else (0,)
    if a.ndim == 0 or a.shape[-1] != 2:
        raise ArgumentValueError(f"points must have shape (M, 2) (or (..., 2)), got shape {a.shape}")
    shape = a.shape[:-1]
    a = a.reshape(-1, 2).astype(np.float64)
    check_vertices("points", a)
    return a, shape


def _edges(polygon: ArrayLike) -> NDArray[np.float64]:
    """The non-horizontal edges, lower endpoint first: xlo, ylo, xhi, yhi, direction."""
    verts, offsets = contours("polygon", polygon)
    rings: list[NDArray[np.float64]] = []
    nexts: list[NDArray[np.float64]] = []
    for c in range(len(offsets) - 1):
        ring = verts[offsets[c]:offsets[c + 1]]
        rings.append(ring)
        nexts.append(np.roll(ring, -1, axis=0))
    if not rings:
        return np.empty((5, 0))
    a = np.concatenate(rings)
    b = np.concatenate(nexts)
    keep = a[:, 1] != b[:, 1]
    a, b = a[keep], b[keep]
    up = a[:, 1] < b[:, 1]
    lo = np.where(up[:, None], a, b)
    hi = np.where(up[:, None], b, a)
    return np.stack([lo[:, 0], lo[:, 1], hi[:, 0], hi[:, 1], np.where(up, 1.0, -1.0)])


def _left_crossings(pts: NDArray[np.float64], edges: NDArray[np.float64]) -> NDArray[np.int64]:
    """Signed sum of the edges crossed left of each point (+1 up, -1 down)."""
    out = np.zeros(len(pts), np.int64)
    if edges.shape[1] == 0 or len(pts) == 0:
        return out
    xlo, ylo, xhi, yhi, d = edges
    exact_edge = ((xlo == np.floor(xlo)) & (xhi == np.floor(xhi))
                  & (ylo == np.floor(ylo)) & (yhi == np.floor(yhi)))
    ilo, iylo = xlo.astype(np.int64), ylo.astype(np.int64)
    idx, idy = xhi.astype(np.int64) - ilo, yhi.astype(np.int64) - iylo
    dx, dy = xhi - xlo, yhi - ylo
    d = d.astype(np.int64)
    step = max(1, CHUNK // edges.shape[1])
    for s in range(0, len(pts), step):
        px = pts[s:s + step, 0:1]
        py = pts[s:s + step, 1:2]
        active = (ylo < py) & (py <= yhi)
        with np.errstate(invalid="ignore", over="ignore"):
            xc = xlo + ((py - ylo) * dx) / dy
        left = xc <= px
        exact_pt = (px == np.floor(px)) & (py == np.floor(py))
        both = exact_edge & exact_pt
        if both.any():
            ipx, ipy = px.astype(np.int64), py.astype(np.int64)
            left_exact = (ipx - ilo) * idy >= (ipy - iylo) * idx
            left = np.where(both, left_exact, left)
        out[s:s + step] = ((active & left) * d).sum(axis=1)
    return out


def winding_number(points: Points, polygon: ArrayLike) -> NDArray[np.int64]:
    """Winding number of ``polygon`` about each point.

    Parameters
    ----------
    points : array_like, shape (M, 2) or (..., 2)
        The points (x, y).
    polygon : array_like
        One contour, an (N, 2) array of vertices, or several: a list of such arrays
        or a (C, N, 2) array.  The winding numbers of the contours add up.

    Returns
    -------
    ndarray of int64, shape (M,) (or the leading shape of ``points``)
        How many times the boundary winds counterclockwise about each point
        (clockwise counts negative).  Points on the boundary follow the top-left
        rule of the module docstring.

    Raises
    ------
    TypeError
        ``points`` or ``polygon`` is not an array of real numbers.
    ValueError
        ``points`` is not of shape (..., 2), ``polygon`` not of shape (N, 2) (or a
        list of such arrays, or (C, N, 2)), or a coordinate is not finite or beyond
        +-2**30.

    Notes
    -----
    The winding number is the signed count of edges crossing a ray from the point:
    here the ray towards +x, whose crossings are minus those of the ray towards -x
    (the signed crossings of a whole scan line add up to zero).

    Examples
    --------
    >>> import scanline as sl
    >>> square = [(0, 0), (4, 0), (4, 4), (0, 4)]
    >>> sl.geometry.winding_number([(2, 2), (5, 2)], square).tolist()
    [1, 0]
    >>> sl.geometry.winding_number([(2, 2)], square[::-1]).tolist()
    [-1]
    """
    pts, shape = _points(points)
    return (-_left_crossings(pts, _edges(polygon))).reshape(shape)


def inside(points: Points, polygon: ArrayLike, rule: Rule = "even-odd") -> NDArray[np.bool_]:
    """Which points are inside ``polygon`` under an inside-outside rule.

    Parameters
    ----------
    points : array_like, shape (M, 2) or (..., 2)
        The points (x, y).
    polygon : array_like
        One contour or several (see :func:`winding_number`).
    rule : {"even-odd", "nonzero"}
        ``"even-odd"`` (odd parity): inside when a ray from the point crosses the
        boundary an odd number of times.  ``"nonzero"``: inside when the winding
        number is not zero.

    Returns
    -------
    ndarray of bool, shape (M,) (or the leading shape of ``points``)
        True where the point is inside.

    Raises
    ------
    TypeError
        ``points`` or ``polygon`` is not an array of real numbers.
    ValueError
        ``rule`` is not one of the two rules, or the points or the polygon are
        malformed (see :func:`winding_number`).

    Notes
    -----
    Hearn & Baker, section 3-11, "Inside-outside tests"; the notes, chapter 2, Q.8,
    fill "the overlap intervals for scan lines that cross the area", which are the
    points these tests accept.  Points on the boundary follow the fill's top-left
    rule (module docstring): ``sl.draw.polygon`` lights exactly the pixels whose
    centers are inside.

    References
    ----------
    D. Hearn, M. P. Baker, "Computer Graphics", 2nd ed., 1994, section 3-11.
    E. Haines, "Point in polygon strategies", Graphics Gems IV, 24-46, 1994.

    Examples
    --------
    >>> import scanline as sl
    >>> star = [(0, 3), (8, 3), (1, -3), (4, 7), (7, -3)]   # a pentagram
    >>> sl.geometry.inside([(4, 1)], star).tolist()
    [False]
    >>> sl.geometry.inside([(4, 1)], star, rule="nonzero").tolist()
    [True]
    """
    v.choice("rule", rule, RULES)
    pts, shape = _points(points)
    s = _left_crossings(pts, _edges(polygon))
    out: NDArray[np.bool_] = ((s & 1) != 0 if rule == "even-odd" else s != 0).reshape(shape)
    return out
