"""The back-face test's step table (Hearn & Baker, section 13-2): for each face of a
cube seen from an eye, its outward normal N, the vector V from the eye to one of its
vertices, V . N, and the verdict that the drawing pipeline itself reached
(:func:`scanline.screen.prepare`, whose kernel tests each facet in viewing
coordinates: a back face where V . N > 0)."""

from typing import TYPE_CHECKING, Any, Dict, List, Sequence, Tuple, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from .table import Table, _cell

if TYPE_CHECKING:
    from ..screen import ScreenScene


class BackFaceTable(Table):
    """The table of :func:`back_face`, with the device outline of each face."""

    #: Per face, its device triangles, [x, y] per vertex.
    outlines: List[List[List[List[float]]]]

#: The device the cube is drawn on.
WIDTH, HEIGHT = 40, 30


def scene(eye: Union[Sequence[float], NDArray[np.float64]]) -> "ScreenScene":
    """The cube of edge 2 about the origin seen from ``eye`` looking at the origin,
    prepared for a :data:`WIDTH` x :data:`HEIGHT` device."""
    import scanline as sl

    # view-up +y, or -z for an eye straight above or below the cube (+y would be the
    # direction of view)
    up = (0.0, 0.0, -1.0) if eye[0] == 0 and eye[2] == 0 else (0.0, 1.0, 0.0)
    camera = sl.Camera(eye=tuple(eye), target=(0.0, 0.0, 0.0), up=up)
    return sl.screen.prepare(sl.mesh.cube(), camera, WIDTH, HEIGHT)


def _vector(p: Union[Sequence[float], NDArray[np.float64]]) -> str:
    return "(" + ", ".join(_cell(float(c)) for c in p) + ")"


def back_face(eye: Tuple[float, float, float] = (3.0, 2.0, 4.0)) -> BackFaceTable:
    """The back-face test of each face of the cube (edge 2, about the origin) seen
    from ``eye`` (looking at the origin): ``N`` the unit outward normal, ``P`` the
    face's first vertex, ``V = P - eye``, ``V.N`` and ``result`` ("front": V . N < 0,
    the face turns toward the eye; "back": the face is hidden by the solid itself).
    ``result`` is the pipeline's own verdict for the face's facets;
    ``table.outlines`` holds each face's device triangles, (x, y) per vertex.

    Parameters
    ----------
    eye : (float, float, float)
        The eye, outside the cube (|x|, |y| or |z| > 1); default (3, 2, 4).

    Returns
    -------
    BackFaceTable
        Columns face, N, P, V, V.N, result: one row per face of the cube; its
        ``outlines`` attribute holds each face's device triangles.

    Raises
    ------
    ArgumentTypeError
        A coordinate of ``eye`` is not a number.
    ArgumentValueError
        ``eye`` is not three numbers, not finite, or inside the cube.

    Examples
    --------
    Seen from (3, 2, 4), the faces x = +1, y = +1 and z = +1 turn toward the eye:
    for x = -1, N = (-1, 0, 0), P = (-1, -1, -1), V = P - eye = (-4, -3, -5) and
    V . N = 4 > 0, a back face; for x = +1, V = (1, -1, -1) - eye = (-2, -3, -5) and
    V . N = -2 < 0, a front face.

    >>> t = back_face((3, 2, 4))
    >>> for r in t.rows:
    ...     print(r["face"], r["N"], r["V"], r["V.N"], r["result"])
    0 (-1, 0, 0) (-4, -3, -5) 4.0 back
    1 (1, 0, 0) (-2, -3, -5) -2.0 front
    2 (0, -1, 0) (-4, -3, -5) 3.0 back
    3 (0, 1, 0) (-4, -1, -5) -1.0 front
    4 (0, 0, -1) (-4, -3, -5) 5.0 back
    5 (0, 0, 1) (-4, -3, -3) -3.0 front
    """
    if not (isinstance(eye, (list, tuple, np.ndarray)) and len(eye) == 3):
        raise ArgumentValueError(f"eye must be 3 numbers x, y, z, got {eye!r}")
    e = np.array([v.number(n, c) for n, c in zip(("eye x", "eye y", "eye z"), eye)])
    if np.all(np.abs(e) <= 1.0):
        raise ArgumentValueError(f"eye {_vector(e)} is inside the cube (|x|, |y|, |z| <= 1): "
                                 "put it outside, e.g. 3 2 4")
    s = scene(e)
    rows: List[Dict[str, Any]] = []
    for face in range(s.face_count):
        facets = np.flatnonzero(s.facet_face == face)
        n = s.face_normals[face]
        p = s.world[facets[0], 0]
        view = p - e
        dot = float(view @ n)
        front = bool(s.front[facets].all())
        rows.append({"face": face, "N": _vector(n), "P": _vector(p), "V": _vector(view),
                     "V.N": round(dot, 6), "result": "front" if front else "back"})
    notes = [f"cube of edge 2 about the origin, eye {_vector(e)} looking at the origin, "
             f"{WIDTH} x {HEIGHT} device",
             "V = P - eye (P: a vertex of the face), N: the outward normal; "
             "V.N < 0: front face (drawn), V.N > 0: back face (culled)",
             f"{sum(r['result'] == 'back' for r in rows)} of {len(rows)} faces are back faces"]
    t = BackFaceTable(f"back-face test, eye {_vector(e)}", ["face", "N", "P", "V", "V.N", "result"],
              rows, notes)
    faces = s.facet_face[s.facet]
    t.outlines = [[s.triangles[k, :, :2].tolist() for k in np.flatnonzero(faces == f)]
                  for f in range(s.face_count)]
    return t

