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

from collections import namedtuple

import numpy as np

from .. import _validate as v
from ..errors import ArgumentValueError

#: The result of :func:`box_counts`: the box sizes and the boxes occupied at each.
BoxCounts = namedtuple("BoxCounts", "sizes counts")


def _points(data):
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
        sizes = 2.0 ** np.arange(0, max(int(np.log2(largest)) - 1, 1))
        return pts, sizes
    pts = finite("points_or_image", v.real_array("points_or_image", data, "(N, 2)"))
    if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) < 2:
        raise ArgumentValueError(f"points_or_image must be (N, 2) points (N >= 2) or a 2-D "
                                 f"image, got shape {pts.shape}")
    extent = float((pts.max(axis=0) - pts.min(axis=0)).max())
    if extent == 0:
        raise ArgumentValueError("points_or_image: the points are all the same point")
    # from a quarter of the extent down to where the boxes would outnumber a tenth of
    # the points (finer boxes count the sampling, not the set)
    sizes = []
    size = extent / 4
    while len(sizes) < 40:
        sizes.append(size)
        if _count(pts, size / 2) > len(pts) / 10:
            break
        size /= 2
    return pts, np.array(sizes)


def _count(points, size):
    cells = np.floor((points - points.min(axis=0)) / size).astype(np.int64)
    return len(np.unique(cells[:, 0] * (int(cells[:, 1].max()) + 1) + cells[:, 1]))


def box_counts(points_or_image, sizes=None):
    """N(ε) for each box size ε of ``sizes`` (default: halving sizes chosen from the
    data).  A point set or polyline's points (N, 2) are counted as given (sample a
    curve finely: only its points are seen); an image counts its nonzero pixels,
    sizes in pixels."""
    pts, default = _points(points_or_image)
    if sizes is None:
        sizes = default
    s = v.real_array("sizes", sizes, "(K,)")
    if s.ndim != 1 or len(s) < 2 or not np.isfinite(s).all() or (s <= 0).any():
        raise ArgumentValueError(f"sizes must be at least two finite box sizes > 0, got "
                                 f"{v._show(sizes)}")
    return BoxCounts(s, np.array([_count(pts, float(e)) for e in s]))


def dimension(points_or_image, sizes=None):
    """The box-counting dimension: the least-squares slope of log N(ε) against
    log(1/ε) over :func:`box_counts`.

    >>> import scanline as sl
    >>> round(sl.fractals.dimension(sl.fractals.koch(7)), 2)
    1.26
    """
    sizes, counts = box_counts(points_or_image, sizes)
    slope, _ = np.polyfit(np.log(1 / sizes), np.log(counts), 1)
    return float(slope)
