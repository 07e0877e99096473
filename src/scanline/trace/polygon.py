"""Step table of the scan-line polygon fill: the sorted edge table and, scan line by
scan line, the active edge list and the spans filled (notes, chapter 2, Q.8;
Hearn & Baker, section 3-11).

The table runs the fill kernel's own helpers as Python
(:func:`scanline._kernels._jit.python`): ``build_edges`` and ``sort_by_row`` make the
edge table, ``step_active`` moves the active edge list up one scan line and
``fill_row`` paints the row's spans, exactly as :func:`scanline.draw.polygon` does.
"""

from typing import Any, Dict, List, Sequence, Tuple, Union

import numpy as np
from numpy.typing import NDArray

from ..draw.polygon import _rule
from ..errors import ArgumentValueError
from ..geometry.contours import contours
from .._typing import Points, Rule
from .table import Table, _cell

#: Largest bounding box traced, in pixels (the table lists every scan line and the
#: spans are read back from a raster of the box).
MAX_PIXELS = 1 << 22

_SIGN = {1: "up", -1: "down"}


class FillTable(Table):
    """The table of :func:`scan_line_fill`, with the sorted edge table."""

    #: One dict per non-horizontal edge, in the order edges enter the active list:
    #: ``edge``, ``lower``, ``upper``, ``scan lines``, ``direction``, ``dx/dy``.
    edges: List[Dict[str, Any]]


def _box(verts: NDArray[np.float64]) -> Tuple[int, int, int, int]:
    lo = np.floor(verts.min(axis=0)).astype(np.int64)
    hi = np.ceil(verts.max(axis=0)).astype(np.int64)
    width, height = int(hi[0] - lo[0] + 1), int(hi[1] - lo[1] + 1)
    if width * height > MAX_PIXELS:
        raise ArgumentValueError(
            f"the polygon's bounding box is {width} x {height} pixels; a trace takes at "
            f"most {MAX_PIXELS} pixels (scale the polygon down)")
    return int(lo[0]), int(lo[1]), width, height


def _point(x: float, y: float) -> str:
    return f"({_cell(float(x))}, {_cell(float(y))})"


def scan_line_fill(points: Union[Points, Sequence[Points]], rule: Rule = "even-odd") -> FillTable:
    """The scan-line polygon fill step by step.

    ``table.edges`` is the sorted edge table: one row per non-horizontal edge, in
    the order edges enter the active list, with its lower and upper endpoints, the
    scan lines it is active on (``ylo < y <= yhi``), its direction and its inverse
    slope dx/dy.  ``table.rows`` has one row per scan line y: the active edge list
    after the step (edge numbers with their crossing keys, the first pixel center at
    or right of each crossing, sorted), the winding numbers between crossings, and
    the spans filled.  ``table.pixels()`` is what :func:`scanline.draw.polygon`
    paints.

    Parameters
    ----------
    points : array_like, shape (N, 2), or a list of contours
        The polygon, device coordinates (as :func:`scanline.draw.polygon`).
    rule : {"even-odd", "nonzero"}
        The inside-outside rule (default "even-odd").

    Returns
    -------
    Table
        One row per scan line (columns y, active, winding, spans), with the sorted
        edge table in ``table.edges``.

    Raises
    ------
    TypeError
        If `points` is not an array of numbers.
    ValueError
        If `rule` is not one of the two rules, or the polygon's bounding box has
        more than `MAX_PIXELS` pixels.

    Notes
    -----
    Notes, chapter 2, Q.8 ("determine the overlap intervals for scan lines that
    cross the area"); Hearn & Baker, section 3-11: the sorted edge table, the active
    edge list, and the vertex rule (here the half-open rule of
    :mod:`scanline._kernels.polygon`: an edge is active on ``ylo < y <= yhi``, so a
    monotone vertex counts once and an extremum twice or not at all).

    Examples
    --------
    >>> t = scan_line_fill([(2, 1), (8, 1), (5, 6)])
    >>> [(e["edge"], e["scan lines"], e["dx/dy"]) for e in t.edges]
    [(1, '2..6', -0.6), (2, '2..6', 0.6)]
    >>> [(r["y"], r["active"], r["spans"]) for r in t.rows[:2]]
    [(2, 'e2:3 e1:8', '3..7'), (3, 'e2:4 e1:7', '4..6')]
    """
    from .._kernels import polygon as k
    from .._kernels._jit import python
    from .._kernels.variants import layout

    verts, offsets = contours("points", points)
    code = _rule(rule)
    if len(verts) == 0:
        empty = FillTable("Scan-line polygon fill (no vertices)", ["y"], [], ["nothing to fill"])
        empty.edges = []
        return empty
    ox, oy, width, height = _box(verts)
    n_edges = len(verts)
    et = np.zeros((n_edges, 9), np.int64)
    ef = np.zeros((n_edges, 4), np.float64)
    n = python(k.build_edges)(verts, offsets, 0, len(offsets) - 1, ox, oy, height, et, ef)
    edges: List[Dict[str, Any]] = []
    rows: List[Dict[str, Any]] = []
    pixels: List[Tuple[int, int]] = []
    if n:
        counts = np.zeros(height + 2, np.int64)
        order = np.zeros(n, np.int64)
        rmin, rmax = python(k.sort_by_row)(et, n, counts, order)
        # the edge table, as built (before the steps move the keys)
        names: Dict[int, int] = {}
        for e in order.tolist():
            names[e] = len(names) + 1
            xlo, ylo, dx, dy = ef[e].tolist()
            edges.append({
                "edge": names[e], "lower": _point(xlo, ylo), "upper": _point(xlo + dx, ylo + dy),
                "scan lines": f"{int(et[e, 0]) + oy}..{int(et[e, 1]) + oy}",
                "direction": _SIGN[int(et[e, 2])], "dx/dy": dx / dy,
            })
        active = np.zeros(n, np.int64)
        keys = np.zeros(n, np.int64)
        dirs = np.zeros(n, np.int64)
        buf = np.zeros((height, width, 1), np.uint8)
        mask = python(k.rule_mask)(code)
        step, fill = python(k.step_active), python(k.fill_row)
        nact = nxt = 0
        for r in range(rmin, rmax + 1):
            nact, nxt, ordered = step(et, ef, r, oy, ox, counts[r - rmin], nxt, nact, order,
                                      active, keys, dirs)
            if not ordered:
                python(k.sort_active)(et, active, keys, dirs, nact, np.zeros(n), np.zeros(n),
                                      np.zeros(n, np.int64))
            fill(buf, layout(False), width, height, r, keys, dirs, nact, mask,
                 np.array([1], np.uint8))
            xs = np.flatnonzero(buf[r, :, 0])
            runs = np.split(xs, np.flatnonzero(np.diff(xs) > 1) + 1) if len(xs) else []
            spans = [(int(a[0]) + ox, int(a[-1]) + ox) for a in runs]
            pixels += [(x, r + oy) for a, b in spans for x in range(a, b + 1)]
            winding = np.cumsum(dirs[:nact]).tolist()
            rows.append({
                "y": r + oy,
                "active": " ".join(f"e{names[int(e)]}:{int(x) + ox}"
                                   for e, x in zip(active[:nact], keys[:nact])),
                "winding": " ".join(str(w) for w in winding[:-1]),
                "spans": " ".join(f"{a}..{b}" for a, b in spans),
            })
    title = f"Scan-line polygon fill, {len(verts)} vertices, {rule} rule"
    notes = [
        f"edge table ({len(edges)} non-horizontal edges, sorted by their first scan line):",
        *(f"  e{e['edge']}: {e['lower']} -> {e['upper']}, scan lines {e['scan lines']}, "
          f"{e['direction']}, dx/dy = {_cell(e['dx/dy'])}" for e in edges),
        "an edge is active on the scan lines ylo < y <= yhi; each crossing key is "
        "ceil(x), the first pixel center at or right of the crossing",
        "a span runs from one key (inclusive) to the next (exclusive) where the winding "
        "number between them is " + ("odd" if code == k.EVEN_ODD else "not zero"),
    ]
    t = FillTable(title, ["y", "active", "winding", "spans"], rows, notes, pixels)
    t.edges = edges
    return t

