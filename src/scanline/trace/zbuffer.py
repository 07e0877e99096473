"""The depth-buffer method's step table (Hearn & Baker, section 13-3): along one scan
line of a small scene, each triangle's depth at each pixel it covers, the depth
stored there before, and whether the triangle wins."""

from typing import Any, Dict, List, Optional

import numpy as np
from numpy.typing import ArrayLike

from .. import _validate as v
from ..errors import ArgumentValueError
from .table import Table

#: The built-in scene: three overlapping triangles (device x, y, depth) on 16 x 10,
#: the third passing through the others (depth varying across it).
SCENE = np.array([
    [(1.0, 1.0, 0.6), (13.0, 2.0, 0.6), (5.0, 9.0, 0.6)],
    [(4.0, 0.5, 0.3), (15.0, 5.0, 0.3), (8.0, 9.5, 0.3)],
    [(0.5, 3.0, 0.1), (14.0, 4.0, 0.9), (2.0, 8.0, 0.1)],
])
WIDTH, HEIGHT = 16, 10


def z_buffer(row: int = 4, triangles: Optional[ArrayLike] = None, width: int = WIDTH,
             height: int = HEIGHT) -> Table:
    """The z-buffer steps on scan line ``row``: per triangle in drawing order, per
    pixel it covers on that row, ``z`` (from the drawing kernel, incrementally z' = z
    - A/C), the stored ``depth`` before, and ``result`` ("write": z < depth, the
    pixel and depth take the triangle's; "keep": hidden).

    Parameters
    ----------
    row : int
        The scan line traced, 0 .. ``height - 1`` (default 4).
    triangles : array_like, shape (N, 3, 3), optional
        Device-space triangles, (x, y, depth) per vertex, drawn in this order;
        default :data:`SCENE`, three overlapping triangles, the third passing
        through the others.
    width, height : int
        The device (default :data:`WIDTH` x :data:`HEIGHT`, 16 x 10).

    Returns
    -------
    Table
        Columns triangle, x, z, depth, result: one row per pixel of the row that a
        triangle covers, triangles in drawing order.  The notes give the visible
        triangle per pixel after the row.

    Raises
    ------
    ArgumentTypeError
        ``triangles`` is not numeric.
    ArgumentValueError
        ``triangles`` not finite or not of shape (N, 3, 3); ``row`` not a scan line
        of the device.

    Notes
    -----
    Hearn & Baker, section 13-3; E. Catmull, "A subdivision algorithm for computer
    display of curved surfaces", PhD thesis, University of Utah, 1974.

    Examples
    --------
    Triangle 2's depth plane through (0.5, 3, 0.1), (14, 4, 0.9) and (2, 8, 0.1) is
    z = 0.1 + (x - 0.5) 0.8/13.2 - (y - 3) 0.24/13.2, so z rises by 0.060606 per
    pixel; it is nearer than triangle 0 (0.6) at x = 5 and farther than triangle 1
    (0.3, drawn before it) from x = 6:

    >>> t = z_buffer(4)
    >>> for r in t.rows:
    ...     if r["triangle"] == 2 and 4 <= r["x"] <= 6:
    ...         print(r["x"], r["z"], r["depth"], r["result"])
    4 0.293939 0.6 write
    5 0.354545 0.6 write
    6 0.415152 0.3 keep
    """
    from .._kernels import raster3d as k
    from .._kernels._jit import python
    from .._kernels.variants import token

    tris = SCENE if triangles is None else v.real_array("triangles", triangles, "(N, 3, 3)")
    if tris.ndim != 3 or tris.shape[1:] != (3, 3) or not np.isfinite(tris).all():
        raise ArgumentValueError("triangles must be finite, of shape (N, 3, 3)")
    row = v.positive_int("row", row + 1) - 1 if isinstance(row, int) else row
    if not isinstance(row, int) or not 0 <= row < height:
        raise ArgumentValueError(f"row must be a scan line 0..{height - 1}, got {row!r}")
    tri = v.kernel_array(tris)
    n = len(tri)
    q = np.ones((n, 3))
    att = np.zeros((n, 3, 0))
    ids = np.arange(n, dtype=np.int64)
    zbuf = np.full((height, width), np.inf)
    idbuf = np.full((height, width), -1, np.int64)
    draw = python(k.raster_triangle)
    out, test = token(k.ATTRIBUTES), token(k.TEST)
    dummy_b, dummy_a, dummy_f = np.empty((1, 1, 1), np.uint8), np.empty((height, width, 0)), \
        np.empty((1, 1))
    rows: List[Dict[str, Any]] = []
    for t in range(n):
        # the triangle's own depths on the row (none where its rows miss the row): the
        # same kernel, on a fresh (inf) buffer
        own = np.full((height, width), np.inf)
        mine = np.full((height, width), -1, np.int64)
        draw(out, test, tri, q, att, ids, t, row, row, own, dummy_f, dummy_b, dummy_a, mine)
        before = zbuf[row].copy()
        draw(out, test, tri, q, att, ids, t, row, row, zbuf, dummy_f, dummy_b, dummy_a,
             idbuf)
        for x in np.flatnonzero(mine[row] >= 0):
            z = own[row, x]
            zf = float(z)
            rows.append({"triangle": t, "x": int(x), "z": round(zf, 6),
                         "depth": round(float(before[x]), 6) if np.isfinite(before[x]) else "inf",
                         "result": "write" if idbuf[row, x] == t and zbuf[row, x] == z else "keep"})
    # the buffer after the row: which triangle each pixel shows
    final = " ".join("." if f < 0 else str(f) for f in idbuf[row])
    return Table(f"z-buffer, scan line y = {row}", ["triangle", "x", "z", "depth", "result"],
                 rows, notes=[f"{n} triangles on {width} x {height}, depth buffer cleared to inf",
                              "write when z < depth(x, y) (the nearer point has the smaller z)",
                              f"visible triangle per pixel after the row: {final}"])
