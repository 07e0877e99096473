"""Fractal dimension by box counting (Hearn & Baker, section 10-18, "fractal
dimension"; Mandelbrot 1982).

Cover the set with a grid of boxes of side ε and count N(ε), the boxes that hold a
part of it; for a fractal N(ε) ~ ε^(-D), so D is the slope of log N(ε) against
log(1/ε), fitted by least squares over a range of box sizes.

References
----------
.. [1] D. Hearn and M. P. Baker, *Computer Graphics, C Version*, 2nd ed., 1997,
   section 10-18.
.. [2] B. B. Mandelbrot, *The Fractal Geometry of Nature*, Freeman, 1982.
.. [3] K. Falconer, *Fractal Geometry*, Wiley, 1990, section 3.1 (box-counting
   dimension).
"""

from typing import List, NamedTuple, Optional, Tuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentValueError


class BoxCounts(NamedTuple):
    """The result of :func:`box_counts`: the box sizes and the boxes occupied at each.

    Parameters
    ----------
    sizes : ndarray (K,) float64
        The box sizes ε.
    counts : ndarray (K,) int64
        N(ε), the boxes that hold a part of the set.

    Examples
    --------
    >>> import scanline as sl
    >>> sizes, counts = sl.fractals.box_counts([(0, 0), (3, 0)], sizes=[1, 4])
    >>> counts.tolist()
    [2, 1]
    """
    sizes: NDArray[np.float64]
    counts: NDArray[np.int64]


def _points(data: ArrayLike) -> Tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(N, 2) points of a point set or a polyline, or the occupied pixels' centers of
    a 2-D image (nonzero pixels), and the sizes to try by default."""
    from ..transform3d.arrays import finite

    a = np.asarray(data)
    if a.ndim == 2 and a.shape[1] != 2 or a.dtype == bool:
        if a.ndim != 2 or a.size == 0:
            raise ArgumentValueError(f"points_or_image: an image must be 2-D, got shape "
                                     f"{a.shape}")
        rows, cols = np.nonzero(a)
        if not len(rows):
            raise ArgumentValueError("points_or_image: the image has no nonzero pixel")
        pts = np.stack([cols, rows], axis=1).astype(np.float64)
        largest = max(a.shape)
        pixel_sizes = np.asarray(2.0 ** np.arange(0, max(int(np.log2(largest)) - 1, 1)),
                                 np.float64)
        return pts, pixel_sizes
    pts = finite("points_or_image", v.real_array("points_or_image", data, "(N, 2)"))
    if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) < 2:
        raise ArgumentValueError(f"points_or_image must be (N, 2) points (N >= 2) or a 2-D "
                                 f"image, got shape {pts.shape}")
    extent = float((pts.max(axis=0) - pts.min(axis=0)).max())
    if extent == 0:
        raise ArgumentValueError("points_or_image: the points are all the same point")
    # from a quarter of the extent down to where the boxes would outnumber a tenth of
    # the points (finer boxes count the sampling, not the set)
    sizes: List[float] = []
    size = extent / 4
    while len(sizes) < 40:
        sizes.append(size)
        if _count(pts, size / 2) > len(pts) / 10:
            break
        size /= 2
    return pts, np.array(sizes)


def _count(points: NDArray[np.float64], size: float) -> int:
    cells = np.floor((points - points.min(axis=0)) / size).astype(np.int64)
    return len(np.unique(cells[:, 0] * (int(cells[:, 1].max()) + 1) + cells[:, 1]))


def box_counts(points_or_image: ArrayLike, sizes: Optional[ArrayLike] = None) -> BoxCounts:
    """N(ε) for each box size ε of ``sizes`` (default: halving sizes chosen from the
    data).  A point set or polyline's points (N, 2) are counted as given (sample a
    curve finely: only its points are seen); an image counts its nonzero pixels,
    sizes in pixels.

    Parameters
    ----------
    points_or_image : array_like
        (N, 2) points (N >= 2, not all one point), or a 2-D image (bool, or an (H, W)
        array whose nonzero pixels are the set).
    sizes : array_like (K,), optional
        At least two box sizes > 0.

    Returns
    -------
    BoxCounts
        The sizes and N(ε) at each, boxes counted from the set's lowest corner.

    Raises
    ------
    ArgumentValueError
        Too few or non-finite points, an empty image, or bad sizes.

    Examples
    --------
    Two points 3 apart: two boxes of side 1, one of side 4.

    >>> import scanline as sl
    >>> sl.fractals.box_counts([(0, 0), (3, 0)], sizes=[1, 4]).counts.tolist()
    [2, 1]
    """
    pts, default = _points(points_or_image)
    if sizes is None:
        sizes = default
    s = v.real_array("sizes", sizes, "(K,)")
    if s.ndim != 1 or len(s) < 2 or not np.isfinite(s).all() or (s <= 0).any():
        raise ArgumentValueError(f"sizes must be at least two finite box sizes > 0, got "
                                 f"{v._show(sizes)}")
    return BoxCounts(s, np.array([_count(pts, float(e)) for e in s]))


def dimension(points_or_image: ArrayLike, sizes: Optional[ArrayLike] = None) -> float:
    """The box-counting dimension: the least-squares slope of log N(ε) against
    log(1/ε) over :func:`box_counts`.

    Parameters
    ----------
    points_or_image : array_like
        As :func:`box_counts` takes it.
    sizes : array_like (K,), optional
        As :func:`box_counts` takes them.

    Returns
    -------
    float
        The fitted dimension D (Hearn & Baker 10-18: N ~ ε^(-D)).

    Raises
    ------
    ArgumentValueError
        As :func:`box_counts`.

    Examples
    --------
    Koch's curve: log 4 / log 3 = 1.2619 in the limit.

    >>> import scanline as sl
    >>> round(sl.fractals.dimension(sl.fractals.koch(7)), 2)
    1.26
    """
    sizes, counts = box_counts(points_or_image, sizes)
    slope, _ = np.polyfit(np.log(1 / sizes), np.log(counts), 1)
    return float(slope)
