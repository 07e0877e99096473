"""The Utah teapot: Martin Newell's 32 bicubic Bezier patches (1975), built in.

The data (306 control points, 32 patches of 16) is Newell's table as published by
Crow (1987), shipped in ``scanline/data/teapot.txt`` (its header names the source).
z is up, the teapot stands on z = 0 and its spout points to +x; it spans
x in [-3, 3.43], y in [-2, 2], z in [0, 3.15].

>>> import scanline as sl
>>> patches = sl.curves.teapot()
>>> len(patches), patches[0]
(32, <BezierSurface of degree (3, 3), 3-D>)
>>> vertices, triangles, normals = sl.curves.teapot_mesh(4)
>>> vertices.shape[1], triangles.shape[1]
(3, 3)
"""

from importlib import resources
from typing import Sequence, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .surfaces import BezierSurface, MeshArrays, merge, weld

#: The teapot's parts and their patches (0-based, in the data's order).
PARTS = {
    "rim": range(0, 4),
    "body": range(4, 12),
    "handle": range(12, 16),
    "spout": range(16, 20),
    "lid": range(20, 28),
    "bottom": range(28, 32),
}


def teapot_data() -> tuple[NDArray[np.int64], NDArray[np.float64]]:
    """The raw table: (patches (32, 16) int 0-based vertex indices, vertices (306, 3))."""
    text = resources.files("scanline").joinpath("data/teapot.txt").read_text("ascii")
    rows = [line for line in text.splitlines() if line.strip() and not line.startswith("#")]
    count = int(rows[0])
    patches = np.array([[int(x) for x in r.split(",")] for r in rows[1:1 + count]]) - 1
    nverts = int(rows[1 + count])
    vertices = np.array([[float(x) for x in r.split(",")] for r in rows[2 + count:2 + count + nverts]])
    return patches, vertices


def teapot(parts: Union[str, Sequence[str], None] = None) -> list[BezierSurface]:
    """The Utah teapot as a list of bicubic :class:`BezierSurface` patches.

    Parameters
    ----------
    parts : str or sequence of str, optional
        Which parts, of "rim", "body", "handle", "spout", "lid", "bottom" (default
        all 32 patches, in the data's order).

    Returns
    -------
    list of BezierSurface
        The patches, each of degree (3, 3).

    Raises
    ------
    ArgumentValueError
        An unknown part.

    Notes
    -----
    Each patch's 16 indices are the data's four rows of four; the data's rows run
    down the body and around it clockwise seen from above, so S_u x S_v would point
    inward.  Each net is therefore transposed (``net[i, j]`` is the data's row j,
    column i): S_u x S_v, the normals and the tessellated triangles' winding then
    face outward on every part.

    References
    ----------
    M. E. Newell, *The utilization of procedure models in digital image synthesis*,
    PhD thesis, University of Utah, 1975.
    F. C. Crow, "The origins of the teapot", IEEE Computer Graphics and Applications
    7(1), 8-19, 1987.

    Examples
    --------
    The lid's 8 patches; the knob's top, the pole at the lid's center, is the
    data's point (0, 0, 3.15):

    >>> import scanline as sl
    >>> lid = sl.curves.teapot("lid")
    >>> len(lid), [round(c, 6) for c in lid[0].evaluate(0.0, 0.0).tolist()]
    (8, [0.0, 0.0, 3.15])
    """
    patches, vertices = teapot_data()
    return [BezierSurface(vertices[patches[p]].reshape(4, 4, 3).transpose(1, 0, 2))
            for p in _indices(parts)]


def _indices(parts: Union[str, Sequence[str], None]) -> Sequence[int]:
    if parts is None:
        return range(32)
    names = (parts,) if isinstance(parts, str) else parts
    out: list[int] = []
    for name in names:
        v.choice("parts", name, tuple(PARTS))
        out.extend(PARTS[name])
    return out


def teapot_mesh(n: int = 8, parts: Union[str, Sequence[str], None] = None,
                weld_tolerance: float = 1e-9) -> MeshArrays:
    """The teapot tessellated into one welded triangle mesh.

    Parameters
    ----------
    n : int
        Intervals per patch side (each patch gives 2 n² triangles before welding).
    parts : str or sequence of str, optional
        As :func:`teapot`.
    weld_tolerance : float
        Vertices this close are merged (the shared patch boundaries, the poles);
        triangles that collapse are dropped.

    Returns
    -------
    vertices (K, 3), triangles (T, 3) int64, normals (K, 3)
        Triangles counterclockwise seen from outside; normals point outward.

    Raises
    ------
    ArgumentValueError
        An unknown part, ``n`` < 1, or ``weld_tolerance`` <= 0.

    Notes
    -----
    Hearn & Baker, section 10-11 (Bezier surfaces); the tessellation is
    :meth:`~scanline.curves.surfaces.Surface.tessellate`, the welding
    :func:`~scanline.curves.surfaces.weld`.

    Examples
    --------
    One body patch at n = 1: a 2 x 2 vertex grid, two triangles, unit normals:

    >>> import numpy as np, scanline as sl
    >>> vertices, triangles, normals = sl.curves.teapot_mesh(1, parts=["body"])
    >>> triangles.shape[1], bool(np.allclose(np.linalg.norm(normals, axis=1), 1))
    (3, True)
    """
    meshes = [patch.tessellate(n, n) for patch in teapot(parts)]
    vertices, triangles, normals = weld(*merge(meshes), tolerance=weld_tolerance)
    assert normals is not None           # tessellated patches carry normals
    return vertices, triangles, normals
