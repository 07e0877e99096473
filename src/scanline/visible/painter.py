"""The painter's algorithm with one sort key per polygon: the counter-example.

*Object precision* ordering (a sort of whole polygons), painted at image precision.
"""

import numpy as np

from .. import _validate as v
from ..screen.polygons import ScreenPolygons, as_screen

KEYS = ("farthest", "mean")


def painter(polygons: ScreenPolygons, key: str = "farthest") -> ScreenPolygons:
    """Order the polygons back to front by one depth key each, as matplotlib's
    ``Poly3DCollection`` and manim do, and nothing else.

    Parameters
    ----------
    polygons : ScreenPolygons
        The polygons (:func:`scanline.screen.screen_polygons`).
    key : {"farthest", "mean"}
        Each polygon's greatest vertex depth, or the mean of its vertex depths.

    Returns
    -------
    ScreenPolygons
        The polygons in drawing order (farthest key first; ties keep the input
        order).

    Raises
    ------
    ArgumentValueError
        An unknown ``key``.

    Notes
    -----
    This is step 1 of the depth-sorting method (Hearn & Baker, section 13-6) alone:
    "surfaces are sorted in order of decreasing depth" and scan converted in turn.
    It is right whenever no two polygons overlap in depth where they overlap on the
    screen, and wrong otherwise: a long polygon whose far end lies behind a small one
    but whose near end covers it is painted first and then hidden, polygons that
    overlap cyclically have no correct order at all, and intersecting polygons
    cannot be drawn by whole-polygon ordering.  :func:`scanline.visible.depth_sort`
    adds the tests, reordering and splitting that fix those cases.  The ordering is
    computed at object precision (whole polygons); their pixels are painted at image
    precision.

    Examples
    --------
    >>> import scanline as sl
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> sp = sl.screen.screen_polygons(sl.mesh.cube(2), cam, 4, 4)
    >>> sp.face.tolist()                  # the back and front faces; the sides are edge-on
    [4, 5]
    >>> sl.visible.painter(sp).face.tolist()          # the back face first
    [4, 5]
    """
    sp = as_screen(polygons)
    v.choice("key", key, KEYS)
    starts = sp.offsets[:-1]
    z = sp.vertices[:, 2]
    if not len(sp):
        return sp
    if key == "farthest":
        k = np.maximum.reduceat(z, starts)
    else:
        k = np.add.reduceat(z, starts) / sp.counts
    return sp.subset(np.argsort(-k, kind="stable"))
