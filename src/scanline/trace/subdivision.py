"""The step table of Warnock's area subdivision (Hearn & Baker, section 13-8): every
area that :func:`scanline.visible.area_subdivision` examines, in its order, with the
class of each polygon relative to the area and the decision.

The rows come from the kernel itself: its loop runs as Python
(:func:`scanline._kernels._jit.python`) with its test of an area,
``decide_area``, wrapped so that each call is recorded -- the relevant polygons and
their classes that the loop found, and the case the test returned."""

import types
from typing import Any, Callable, Dict, List, Literal, Tuple

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .table import Table


class WarnockTable(Table):
    """The table of :func:`warnock`, with the scene and what each area painted."""

    #: The scene's polygons, [x, y] per vertex.
    polygons: List[List[List[float]]]
    #: Per row, the pixels (x, y) its area painted.
    written: List[List[Tuple[int, int]]]
    #: The polygon each pixel shows, ``face[y, x]`` (-1: the background).
    face: NDArray[np.int32]


#: A recorded test of an area: x0, y0, x1, y1, level, the relevant polygons, their
#: classes, the case, the pixels painted and the polygons painted.
_Area = Tuple[int, int, int, int, int, List[int], List[int], int, List[Tuple[int, int]],
              List[int]]

#: The device of the built-in scenes.
WIDTH, HEIGHT = 16, 12

#: Built-in scenes: device-space polygons (x, y, depth per vertex).
SCENES = {
    "overlap": [   # a far rectangle, a near triangle over it, a tilted quad piercing it
        [[1, 1, 0.8], [14, 1, 0.8], [14, 10, 0.8], [1, 10, 0.8]],
        [[3, 3, 0.3], [11, 4, 0.3], [6, 9, 0.3]],
        [[9, 6, 0.9], [15, 6, 0.2], [15, 11, 0.2], [9, 11, 0.9]]],
    "surrounding": [  # a near rectangle covering most of the screen, a far one behind
        [[0, 0, 0.2], [15, 0, 0.2], [15, 11, 0.2], [0, 11, 0.2]],
        [[4, 3, 0.7], [12, 3, 0.7], [12, 9, 0.7], [4, 9, 0.7]]],
}

#: Class names of the kernel's polygon classes, by number.
CLASSES = {0: "outside", 1: "surrounding", 2: "inside", 3: "overlapping"}


def _recorded(record: List[_Area]) -> Callable[..., Any]:
    """The kernel's loop as Python, its area test appending to ``record``."""
    from .._kernels import visible as k
    from .._kernels._jit import python

    loop = python(k.area_subdivision)
    scope = dict(loop.__globals__)
    decide = scope["decide_area"]

    def decide_area(verts: NDArray[np.float64], offsets: NDArray[np.int64],
                    planes: NDArray[np.float64], ext: NDArray[np.float64],
                    cand: NDArray[np.int64], level: int, n: int, x0: int, y0: int, x1: int,
                    y1: int, face: NDArray[np.int32], depth: NDArray[np.float64]) -> Any:
        before = face.copy()
        case = decide(verts, offsets, planes, ext, cand, level, n, x0, y0, x1, y1, face, depth)
        ys, xs = np.nonzero(face != before)
        record.append((int(x0), int(y0), int(x1), int(y1), int(level) // 2,
                       cand[level, :n].tolist(), cand[level + 1, :n].tolist(), int(case),
                       list(zip(xs.tolist(), ys.tolist())), sorted(set(face[ys, xs].tolist()))))
        return case

    scope["decide_area"] = decide_area
    return types.FunctionType(loop.__code__, scope, loop.__name__)


def warnock(scene: Literal["overlap", "surrounding"] = "overlap") -> WarnockTable:
    """Warnock's area subdivision of a built-in scene (:data:`SCENES`, on a
    :data:`WIDTH` x :data:`HEIGHT` device): one row per area examined, in the order
    the method takes them (depth first, from the whole screen): the area ``x0, y0,
    x1, y1`` (pixel centers, inclusive), its ``level`` of subdivision, each
    polygon's class (``P0``, ``P1`` ...: surrounding, overlapping, inside or
    outside) and the ``decision`` (background, one polygon painted, a surrounding
    polygon in front painted, one pixel resolved by depth, or subdivide).
    ``table.polygons`` holds the scene's polygons in (x, y).

    Parameters
    ----------
    scene : {"overlap", "surrounding"}
        The scene (default "overlap": a far rectangle, a near triangle over it and a
        tilted quadrilateral piercing it).

    Returns
    -------
    WarnockTable
        Columns x0, y0, x1, y1, level, P0, P1 ... (each polygon's class), decision
        and painted, one row per area examined; ``polygons``, ``written`` (the
        pixels each area painted) and ``face`` (the polygon per pixel) as well.

    Raises
    ------
    ArgumentValueError
        ``scene`` is not one of :data:`SCENES`.

    References
    ----------
    J. E. Warnock, "A hidden-surface algorithm for computer generated half-tone
    pictures", University of Utah, 1969.

    Examples
    --------
    The "surrounding" scene: a near rectangle P0 (depth 0.2) over the whole
    screen, a far one P1 (depth 0.7, x 4..12, y 3..9) behind it.  The screen holds
    both (inside), so it is divided, its top-right quadrant first, and again;
    the top-right corner area (14..15, 11) meets P0 only (P1 ends at y = 9), and
    the quadrant (8..11, 6..8), surrounded by both, is decided by P0's greatest
    depth (0.2) below P1's least (0.7):

    >>> t = warnock("surrounding")
    >>> for r in t.rows[:4] + t.rows[13:14]:
    ...     print(r["x0"], r["y0"], r["x1"], r["y1"], r["level"], r["P0"], r["P1"],
    ...           "|", r["decision"], r["painted"])
    0 0 15 11 0 inside inside | subdivide None
    8 6 15 11 1 overlapping overlapping | subdivide None
    12 9 15 11 2 overlapping overlapping | subdivide None
    14 11 15 11 3 overlapping outside | one polygon P0
    8 6 11 8 2 surrounding surrounding | surrounding in front P0
    """
    from ..visible import ScreenPolygons
    from ..visible.warnock import CASES

    v.choice("scene", scene, tuple(SCENES))
    polys = [np.array(p, float) for p in SCENES[scene]]
    sp = ScreenPolygons.from_device(polys, WIDTH, HEIGHT)
    levels = int(np.ceil(np.log2(max(WIDTH, HEIGHT)))) + 2
    npoly = len(sp)
    face = np.full((HEIGHT, WIDTH), -1, np.int32)
    record: List[_Area] = []
    _recorded(record)(sp.vertices, sp.offsets, sp.planes, np.ascontiguousarray(sp.extents()),
                      WIDTH, HEIGHT, face, np.full((HEIGHT, WIDTH), np.inf),
                      np.empty((2 * levels, max(npoly, 1)), np.int64),
                      np.zeros(levels, np.int64), np.empty((3 * levels + 4, 5), np.int64),
                      np.zeros((0, 5), np.int64))
    names = [f"P{i}" for i in range(npoly)]
    rows: List[Dict[str, Any]] = []
    written: List[List[Tuple[int, int]]] = []
    for x0, y0, x1, y1, level, cand, classes, case, pixels, painted in record:
        row: Dict[str, Any] = {"x0": x0, "y0": y0, "x1": x1, "y1": y1, "level": level}
        of = dict(zip(cand, classes))
        row.update({n: CLASSES[of.get(p, 0)] for p, n in enumerate(names)})
        row["decision"] = CASES[case] if case >= 0 else "subdivide"
        row["painted"] = " ".join(names[p] for p in painted) or None
        rows.append(row)
        written.append(pixels)
    notes = [f"polygon P{i}: " + " ".join(f"({x:g}, {y:g}, {z:g})" for x, y, z in p.tolist())
             for i, p in enumerate(polys)]
    notes += [f"{WIDTH} x {HEIGHT} device, areas of pixel centers; depth: smaller is nearer",
              "decided: background (no polygon), one polygon (painted), surrounding in "
              "front (its greatest depth below every other's least), pixel (nearest at the "
              "center); otherwise subdivide into four quadrants",
              f"{sum(r['decision'] != 'subdivide' for r in rows)} areas decided, "
              f"{sum(r['decision'] == 'subdivide' for r in rows)} subdivided"]
    t = WarnockTable(f"Warnock area subdivision of the {scene!r} scene",
              ["x0", "y0", "x1", "y1", "level"] + names + ["decision", "painted"], rows, notes)
    t.polygons = [p[:, :2].tolist() for p in polys]
    t.written = written
    t.face = face
    return t
