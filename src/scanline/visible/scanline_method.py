"""The scan-line method of visible-surface detection (Hearn & Baker, section 13-5).

*Image precision*: visibility is decided at the pixel centers of each scan line.
"""

import numpy as np

from ..screen.polygons import ScreenPolygons, as_screen
from .visibility import VisibleFaces


def scan_line(polygons: ScreenPolygons) -> VisibleFaces:
    """Visible faces by the scan-line method.

    Parameters
    ----------
    polygons : ScreenPolygons
        The polygons (:func:`scanline.screen.screen_polygons`).

    Returns
    -------
    VisibleFaces
        ``face[y, x]`` the source face visible at each pixel (-1: background) and its
        depth; ``compared`` (an attribute) counts the pixels where depths had to be
        compared.

    Notes
    -----
    Hearn & Baker, section 13-5: an *edge table* of every polygon's edges sorted by
    first scan line, a *polygon table* with each polygon's plane coefficients and an
    in/out flag, and one *active edge list* for all polygons, kept sorted by x from
    scan line to scan line (coherence: the order changes little, so insertion keeps
    it sorted cheaply).  Along a scan line the crossings are visited left to right;
    each turns its polygon's flag on or off.  Where one flag is on, the span takes that
    polygon without any depth computation; only where flags overlap are the depths of
    the polygons that are on compared, at each pixel (so polygons that intersect are
    resolved too: the book compares once per span, which assumes they do not).  The
    crossing x is evaluated from the edge exactly as the 2-D fill evaluates it, so the
    spans are exactly :func:`scanline.draw.polygons`' pixels.  Image precision.

    The method was introduced by Wylie, Romney, Evans and Erdahl (1967), Bouknight
    (1970) and Watkins (1970).

    References
    ----------
    C. Wylie, G. Romney, D. Evans and A. Erdahl, "Half-tone perspective drawings by
    computer", FJCC 1967.  W. J. Bouknight, "A procedure for generation of
    three-dimensional half-toned computer graphics presentations", CACM 13(9), 1970.
    G. S. Watkins, "A real-time visible surface algorithm", University of Utah,
    UTEC-CSc-70-101, 1970.

    Examples
    --------
    >>> import scanline as sl
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> sp = sl.screen.screen_polygons(sl.mesh.cube(2), cam, 4, 4)
    >>> sp.face.tolist()                  # the back and front faces; the sides are edge-on
    [4, 5]
    >>> sl.visible.scan_line(sp).face.tolist()       # rows bottom-up
    [[-1, -1, -1, -1], [-1, 5, 5, -1], [-1, 5, 5, -1], [-1, -1, -1, -1]]
    """
    from .._kernels import visible as k
    from .._kernels._jit import call

    sp = as_screen(polygons)
    w, h = sp.width, sp.height
    face = np.full((h, w), -1, np.int32)
    depth = np.full((h, w), np.inf)
    ne = len(sp.vertices)
    npoly = len(sp)
    compared = call(k.scan_line_method, 3 * w * h + 20 * ne + 1,
                    sp.vertices, sp.offsets, sp.planes, w, h, face, depth,
                    np.empty((ne, 4)), np.empty((ne, 3), np.int64), np.empty(ne, np.int64),
                    np.empty(h + 1, np.int64), np.empty(ne, np.int64), np.empty(ne),
                    np.zeros(npoly, np.bool_), np.empty(npoly, np.int64),
                    np.empty(npoly, np.int64))
    result = VisibleFaces(face, depth, sp.face)
    result.compared = int(compared)
    return result
