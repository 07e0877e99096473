"""The step table of the scan-line method of visible-surface detection (Hearn & Baker,
section 13-5): per scan line the active edge list, and per crossing the polygon
whose in/out flag it turns, the span to the next crossing, the polygons on there,
their depths where more than one is on, and what the span shows.

The rows come from :func:`scanline.visible.scan_line`'s kernel run as Python
(:func:`scanline._kernels._jit.python`) with its edge table and its walk along each
scan line wrapped so that their inputs and results are recorded."""

import math
import types
from typing import Any, Callable, Dict, List, Literal, Tuple

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .subdivision import HEIGHT, SCENES, WIDTH
from .table import Table

#: A recorded edge: its floats (x, y, dx, dy) and ints (first, last scan line, polygon).
_Edge = Tuple[List[float], List[int]]
#: A recorded scan line: y, its active edges, their crossings x, the polygon shown
#: per pixel of the row, the pixels where depths were compared.
_Line = Tuple[int, List[int], List[float], List[int], int]


class ScanLineTable(Table):
    """The table of :func:`scan_line_method`, with the scene and the visible faces."""

    #: The scene's polygons, [x, y] per vertex.
    polygons: List[List[List[float]]]
    #: The polygon each pixel shows, ``face[y, x]`` (-1: the background).
    face: NDArray[np.int32]


def _recorded(edges: List[_Edge], lines: List[_Line]
              ) -> Tuple[Callable[..., Any], Callable[..., Any]]:
    """The kernel as Python; its edge table is appended to ``edges``, each scan
    line's active edges, crossings and polygon flags to ``lines``."""
    from .._kernels import visible as k
    from .._kernels._jit import python

    loop = python(k.scan_line_method)
    scope = dict(loop.__globals__)
    table, walk = scope["scan_edges"], scope["scan_spans"]

    def scan_edges(verts: NDArray[np.float64], offsets: NDArray[np.int64], height: int,
                   ef: NDArray[np.float64], ei: NDArray[np.int64]) -> Any:
        n = table(verts, offsets, height, ef, ei)
        edges.extend(zip(ef[:n].tolist(), ei[:n].tolist()))
        return n

    def scan_spans(y: int, width: int, planes: NDArray[np.float64], ei: NDArray[np.int64],
                   nact: int, active: NDArray[np.int64], xs: NDArray[np.float64],
                   inside: NDArray[np.bool_], on: NDArray[np.int64], onpos: NDArray[np.int64],
                   face: NDArray[np.int32], depth: NDArray[np.float64]) -> Any:
        compared = walk(y, width, planes, ei, nact, active, xs, inside, on, onpos, face, depth)
        lines.append((y, active[:nact].tolist(), xs[:nact].tolist(), face[y].tolist(),
                      int(compared)))
        return compared

    scope.update(scan_edges=scan_edges, scan_spans=scan_spans)
    return types.FunctionType(loop.__code__, scope, loop.__name__), python(k.plane_depth)


def scan_line_method(scene: Literal["overlap", "surrounding"] = "overlap") -> ScanLineTable:
    """The scan-line method on a built-in scene (:data:`scanline.trace.subdivision.SCENES`,
    a 16 x 12 device): one row per crossing of each scan line ``y``, left to right:
    the ``edge`` crossed and its polygon, the crossing ``x``, the polygons whose
    flags are ``on`` after it, the ``span`` of pixels to the next crossing, the
    ``depths`` of the polygons on at the span's first pixel when more than one is
    on (the comparison the method makes only where spans overlap), and the polygon
    ``visible`` there (each one that wins some pixel of the span).  The first row
    of each scan line lists its ``active edges`` (sorted by x).
    ``table.polygons``: the polygons in (x, y); ``table.face``: the visible polygon
    per pixel (row y, -1: background).

    Parameters
    ----------
    scene : {"overlap", "surrounding"}
        The scene (default "overlap"; the scenes of :func:`warnock`).

    Returns
    -------
    ScanLineTable
        Columns y, active edges, edge, x, on, span, depths, visible: one row per
        crossing of each scan line; ``polygons`` and ``face`` as well.

    Raises
    ------
    ArgumentValueError
        ``scene`` is not one of :data:`SCENES`.

    References
    ----------
    W. J. Bouknight, "A procedure for generation of three-dimensional half-toned
    computer graphics presentations", Communications of the ACM 13(9), 1970.

    Examples
    --------
    Scan line 4 of the "surrounding" scene: P0's left edge turns P0 on at x = 0;
    P1's left edge (x = 4) turns P1 on too, so the span 4..11 compares the depths,
    P0 0.2 against P1 0.7, and shows the nearer P0; P1's right edge (x = 12) and
    P0's (x = 15) turn them off again:

    >>> t = scan_line_method("surrounding")
    >>> for r in t.rows:
    ...     if r["y"] == 4:
    ...         print(r["edge"], r["x"], r["on"], r["span"], r["depths"], r["visible"])
    e1 (P0) 0.0 P0 0..3 None P0
    e3 (P1) 4.0 P0 P1 4..11 P0 0.2, P1 0.7 P0
    e2 (P1) 12.0 P0 12..14 None P0
    e0 (P0) 15.0 - None None None
    """
    from ..visible import ScreenPolygons

    v.choice("scene", scene, tuple(SCENES))
    polys = [np.array(p, float) for p in SCENES[scene]]
    sp = ScreenPolygons.from_device(polys, WIDTH, HEIGHT)
    ne, npoly = len(sp.vertices), len(sp)
    face = np.full((HEIGHT, WIDTH), -1, np.int32)
    edges: List[_Edge] = []
    lines: List[_Line] = []
    run, plane_depth = _recorded(edges, lines)
    compared = run(sp.vertices, sp.offsets, sp.planes, WIDTH, HEIGHT, face,
                   np.full((HEIGHT, WIDTH), np.inf), np.empty((ne, 4)),
                   np.empty((ne, 3), np.int64), np.empty(ne, np.int64),
                   np.empty(HEIGHT + 1, np.int64), np.empty(ne, np.int64), np.empty(ne),
                   np.zeros(npoly, np.bool_), np.empty(npoly, np.int64),
                   np.empty(npoly, np.int64))
    polygon_of = [int(ei[2]) for _, ei in edges]
    rows: List[Dict[str, Any]] = []
    for y, active, xs, shown, _ in lines:
        on: List[int] = []
        for k, (e, x) in enumerate(zip(active, xs)):
            p = polygon_of[e]
            on = [q for q in on if q != p] if p in on else on + [p]
            row: Dict[str, Any] = {"y": y, "active edges": " ".join(f"e{a}" for a in active) if k == 0 else None,
                   "edge": f"e{e} (P{p})", "x": x, "on": " ".join(f"P{q}" for q in sorted(on))
                   or "-", "span": None, "depths": None, "visible": None}
            if on and k + 1 < len(xs):
                x0 = min(max(math.ceil(x), 0), WIDTH)
                x1 = min(max(math.ceil(xs[k + 1]), 0), WIDTH)
                if x0 < x1:
                    row["span"] = f"{x0}..{x1 - 1}"
                    if len(on) > 1:
                        row["depths"] = ", ".join(
                            f"P{q} {plane_depth(sp.planes, q, float(x0), float(y)):.4g}"
                            for q in sorted(on))
                    row["visible"] = " ".join(f"P{q}" for q in dict.fromkeys(shown[x0:x1]))
            rows.append(row)
    notes = [f"polygon P{i}: " + " ".join(f"({x:g}, {y:g}, {z:g})" for x, y, z in p.tolist())
             for i, p in enumerate(polys)]
    notes += [f"edge e{n} of P{ei[2]}: scan lines {ei[0]}..{ei[1]}, from ({ef[0]:g}, {ef[1]:g}),"
              f" dx/dy {ef[2] / ef[3]:.4g}" for n, (ef, ei) in enumerate(edges)]
    notes += [f"{WIDTH} x {HEIGHT} device; pixel x is in a span when ceil(x left) <= x < "
              "ceil(x right); depth: smaller is nearer",
              f"depths compared at {compared} pixels (only where spans overlap)"]
    t = ScanLineTable(f"scan-line method on the {scene!r} scene",
              ["y", "active edges", "edge", "x", "on", "span", "depths", "visible"], rows, notes)
    t.polygons = [p[:, :2].tolist() for p in polys]
    t.face = face
    return t
