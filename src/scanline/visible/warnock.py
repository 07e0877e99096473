"""Area subdivision (Warnock's method) of visible-surface detection (Hearn & Baker,
section 13-8).

*Image precision*: areas are subdivided down to single pixels, whose centers decide.
"""

import numpy as np

from ..screen.polygons import ScreenPolygons, as_screen
from .visibility import VisibleFaces

#: The cases an area is decided by, as :attr:`VisibleFaces.regions` records them.
CASES = ("background", "one polygon", "surrounding in front", "pixel")


def area_subdivision(polygons: ScreenPolygons, record: int = 0) -> VisibleFaces:
    """Visible faces by Warnock's area subdivision.

    Parameters
    ----------
    polygons : ScreenPolygons
        The polygons (:func:`scanline.screen.screen_polygons`).
    record : int
        Keep up to this many decided areas in ``result.regions`` (rows x0, y0, x1,
        y1, case; ``CASES[case]`` names it), e.g. to draw the subdivision.

    Returns
    -------
    VisibleFaces
        With ``areas``: the number of areas decided.

    Notes
    -----
    Hearn & Baker, section 13-8: each polygon relates to an area in one of four ways
    -- *surrounding* (it contains the area), *overlapping* (partly inside),
    *inside* (it lies within the area), *outside* -- and an area is left alone when
    (1) all polygons are outside it (the background), (2) only one is inside,
    overlapping or surrounding it (that polygon is painted over the area), or (3) a
    surrounding polygon is in front of all the others: its greatest depth over the
    area is less than the least depth of every other relevant polygon (depths taken
    from the planes at the area's corners, bounded below by the polygon's own least
    depth).  Otherwise the area is divided into four quadrants, each inheriting only
    its parent's relevant polygons, down to single pixels, where the nearest polygon
    covering the pixel center wins.  Areas are sets of pixel centers, and a center is
    in a polygon by the 2-D fill's rule (:mod:`scanline._kernels.visible`), so the
    pixels agree with the other methods.  Image precision.

    References
    ----------
    J. E. Warnock, "A hidden-surface algorithm for computer generated half-tone
    pictures", University of Utah, TR 4-15, 1969.

    Examples
    --------
    >>> import scanline as sl
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> sp = sl.screen.screen_polygons(sl.mesh.cube(2), cam, 4, 4)
    >>> sp.face.tolist()                  # the back and front faces; the sides are edge-on
    [4, 5]
    >>> sl.visible.area_subdivision(sp).face.tolist()
    [[-1, -1, -1, -1], [-1, 5, 5, -1], [-1, 5, 5, -1], [-1, -1, -1, -1]]
    """
    from .._kernels import visible as k
    from .._kernels._jit import call

    sp = as_screen(polygons)
    w, h = sp.width, sp.height
    npoly = len(sp)
    levels = int(np.ceil(np.log2(max(w, h)))) + 2
    face = np.full((h, w), -1, np.int32)
    depth = np.full((h, w), np.inf)
    regions = np.zeros((max(int(record), 0), 5), np.int64)
    ext = np.ascontiguousarray(sp.extents())
    # work units: ~2.5 us of the twin per pixel and per polygon and level (measured)
    decided = call(k.area_subdivision, 10 * w * h + 75 * npoly * levels + 1,
                   sp.vertices, sp.offsets, sp.planes, ext, w, h, face, depth,
                   np.empty((2 * levels, max(npoly, 1)), np.int64),
                   np.zeros(levels, np.int64), np.empty((3 * levels + 4, 5), np.int64),
                   regions)
    result = VisibleFaces(face, depth, sp.face)
    result.areas = int(decided)
    result.regions = regions[:min(decided, len(regions))]
    return result
