"""Step tables of the line clippers (notes, chapter 4, Q.3-Q.4).

The steps are logged by the same compiled helpers that :func:`scanline.clip.lines`
runs (:mod:`scanline._kernels.clip`), so the table and the clipped segment cannot
disagree.
"""

from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from .._kernels import clip as k
from .._kernels._jit import python
from .._kernels.variants import token
from ..clip import window as w
from .._typing import Points
from .table import Table, _cell

DEFAULT_WINDOW = (0.0, 0.0, 10.0, 10.0)
#: A clip window: a rectangle (xmin, ymin, xmax, ymax) or a polygon's vertices.
_Window = Union[Tuple[float, float, float, float], Points]

_BITS = {k.LEFT: "left", k.RIGHT: "right", k.BELOW: "below", k.ABOVE: "above"}
_KINDS = {k.KIND_PARALLEL_INSIDE: "parallel, inside", k.KIND_PARALLEL_OUTSIDE:
          "parallel, outside: reject", k.KIND_ENTERING: "PE (entering)",
          k.KIND_LEAVING: "PL (leaving)"}


class LineClipTable(Table):
    """The table of a line clipper's trace, with the clipped segment."""

    #: The visible part (x0, y0, x1, y1), or None when nothing is visible.
    result: Optional[Tuple[float, float, float, float]]


class PolygonClipTable(Table):
    """The table of :func:`sutherland_hodgman`, with the polygon after each stage."""

    #: The polygon after each stage, a list of (x, y).
    stages: List[List[Tuple[float, ...]]]
    #: The clipped polygon, a list of (x, y), empty when nothing is left.
    result: List[Tuple[float, ...]]


def code_string(code: float) -> str:
    """A region code as the notes write it: bits 4 3 2 1 = above below right left."""
    return format(int(code), "04b")


def _vector(x: float, y: float) -> str:
    return f"({_cell(float(x))}, {_cell(float(y))})"


def _run(method: int, x0: float, y0: float, x1: float, y1: float, ring: NDArray[np.float64],
         rows: int, columns: int
         ) -> Tuple[NDArray[np.float64], bool, NDArray[np.float64], NDArray[np.float64]]:
    """Run clipper ``method`` on one segment against the window ``ring`` (corners,
    counterclockwise) with a log of ``rows`` x ``columns``."""
    seg = np.array([v.number(n, c) for n, c in
                    (("x0", x0), ("y0", y0), ("x1", x1), ("y1", y1))])
    bad = ~(np.abs(seg) <= v.COORD_LIMIT)
    if bad.any():
        raise ArgumentValueError(
            f"{('x0', 'y0', 'x1', 'y1')[int(np.argmax(bad))]} must be within "
            f"+-{v.COORD_LIMIT}")
    out = np.empty((1, 4))
    log = np.full((rows, columns), np.nan)
    rect = np.concatenate([ring.min(axis=0), ring.max(axis=0)])
    ok = python(k.trace_line)(token(method), seg, rect, ring, w.outward_normals(ring), out,
                              log)
    used = int(np.sum(~np.isnan(log[:, 0])))
    return seg, bool(ok), out[0], log[:used]


def _window(window: _Window, window_polygon: Optional[Sequence[float]]) -> _Window:
    """``window``, or the polygon of the flat list x0, y0, x1, y1, ...
    ``window_polygon`` (the command line's ``--window-polygon``) when it is given."""
    if window_polygon is None:
        return window
    flat = list(window_polygon)
    if len(flat) % 2:
        raise ArgumentValueError(
            f"window_polygon must list x, y pairs (an even count of numbers), got "
            f"{len(flat)} numbers")
    return [flat[i:i + 2] for i in range(0, len(flat), 2)]


def _result(ok: bool, out: NDArray[np.float64]
            ) -> Tuple[Optional[Tuple[float, float, float, float]], str]:
    if not ok:
        return None, "result: rejected, nothing is visible"
    r = (float(out[0]), float(out[1]), float(out[2]), float(out[3]))
    return r, f"result: visible from ({_cell(r[0])}, {_cell(r[1])}) to ({_cell(r[2])}, {_cell(r[3])})"


def cohen_sutherland(x0: float, y0: float, x1: float, y1: float,
                     window: _Window = DEFAULT_WINDOW) -> LineClipTable:
    """Cohen-Sutherland step by step: the region codes of both endpoints, their
    AND, and at each step the trivial accept, the trivial reject or the boundary
    an outside endpoint is moved to.

    Region codes are written bit 4 to bit 1: above, below, right, left (notes,
    chapter 4, Q.3).  ``table.result`` is the clipped (x0, y0, x1, y1) or None.

    Parameters
    ----------
    x0, y0 : float
        The segment's first endpoint (world coordinates).
    x1, y1 : float
        Its second endpoint.
    window : (xmin, ymin, xmax, ymax), optional
        The clip rectangle (default `DEFAULT_WINDOW`, 0..10 on both axes).

    Returns
    -------
    Table
        One row per step of the algorithm; ``table.result`` is the clipped segment (x0, y0, x1, y1) as floats, or
        None when nothing is visible.

    Raises
    ------
    TypeError
        If a coordinate is not a real number or the window is not numeric.
    ValueError
        If a coordinate is beyond the supported range or the window is degenerate.

    Examples
    --------

    >>> t = cohen_sutherland(-5, 2, 15, 22, window=(0, 0, 10, 10))
    >>> for r in t.rows:
    ...     print(r["code0"], r["code1"], r["decision"], r["x"], r["y"])
    0001 1010 clip P0 at left (x = 0) 0.0 7.0
    0000 1010 clip P1 at right (x = 10) 10.0 17.0
    0000 1000 clip P1 at above (y = 10) 3.0 10.0
    0000 0000 accept: both codes 0000 None None
    >>> t.result
    (0.0, 7.0, 3.0, 10.0)
    """
    xmin, ymin, xmax, ymax = w.rectangle(window)
    seg, ok, out, log = _run(k.COHEN_SUTHERLAND, x0, y0, x1, y1,
                             w.rectangle_polygon(xmin, ymin, xmax, ymax), k.CS_MAX_STEPS + 1,
                             k.CS_COLUMNS)
    edge = {k.LEFT: ("x", xmin), k.RIGHT: ("x", xmax), k.BELOW: ("y", ymin),
            k.ABOVE: ("y", ymax)}
    rows = []
    for i, (end, c0, c1, both, action, bit, x, y) in enumerate(log.tolist()):
        if action == k.CS_CLIP:
            axis, value = edge[int(bit)]
            decision = f"clip P{int(end)} at {_BITS[int(bit)]} ({axis} = {_cell(value)})"
        elif action == k.CS_ACCEPT:
            decision = "accept: both codes 0000"
            x = y = None
        else:
            decision = "reject: code0 AND code1 != 0000"
            x = y = None
        rows.append({"step": i, "code0": code_string(c0), "code1": code_string(c1),
                     "and": code_string(both), "decision": decision, "x": x, "y": y})
    result, line = _result(ok, out)
    notes = [f"window xmin = {_cell(xmin)}, ymin = {_cell(ymin)}, xmax = {_cell(xmax)}, "
             f"ymax = {_cell(ymax)}",
             "region code bits 4 3 2 1 = above below right left; x, y: the new endpoint",
             line]
    t = LineClipTable(f"Cohen-Sutherland clip ({_cell(seg[0])}, {_cell(seg[1])}) -> "
              f"({_cell(seg[2])}, {_cell(seg[3])})",
              ["step", "code0", "code1", "and", "decision", "x", "y"], rows, notes)
    t.result = result
    return t


def _parametric_rows(log: NDArray[np.float64], names: Sequence[str]) -> List[Dict[str, Any]]:
    rows = []
    for kk, p, q, r, kind, u1, u2 in log.tolist():
        i = int(kk) - 1
        rows.append({"k": int(kk), "edge": names[i], "p": p, "q": q,
                     "t": None if np.isnan(r) else r, "kind": _KINDS[int(kind)],
                     "u1": u1, "u2": u2})
    return rows


def liang_barsky(x0: float, y0: float, x1: float, y1: float,
                 window: _Window = DEFAULT_WINDOW) -> LineClipTable:
    """Liang-Barsky step by step: for k = 1..4 (left, right, bottom, top) the
    p_k and q_k, t = q_k / p_k, whether the line enters (p_k < 0) or leaves
    (p_k > 0), and u1 = max(0, entering t), u2 = min(1, leaving t) so far.

    p1 = -dx, q1 = x0 - xmin; p2 = dx, q2 = xmax - x0; p3 = -dy, q3 = y0 - ymin;
    p4 = dy, q4 = ymax - y0.  The segment is visible from u1 to u2 if u1 <= u2.

    Parameters
    ----------
    x0, y0 : float
        The segment's first endpoint (world coordinates).
    x1, y1 : float
        Its second endpoint.
    window : (xmin, ymin, xmax, ymax), optional
        The clip rectangle (default `DEFAULT_WINDOW`, 0..10 on both axes).

    Returns
    -------
    Table
        Columns k, edge, p, q, t, kind, u1, u2, one row per boundary; ``table.result`` is the clipped segment (x0, y0, x1, y1) as floats, or
        None when nothing is visible.

    Raises
    ------
    TypeError
        If a coordinate is not a real number or the window is not numeric.
    ValueError
        If a coordinate is beyond the supported range or the window is degenerate.

    Examples
    --------

    >>> t = liang_barsky(-5, 2, 15, 12, window=(0, 0, 10, 10))
    >>> [(r["k"], r["p"], r["q"], r["t"], r["u1"], r["u2"]) for r in t.rows]
    [(1, -20.0, -5.0, 0.25, 0.25, 1.0), (2, 20.0, 15.0, 0.75, 0.25, 0.75), (3, -10.0, 2.0, -0.2, 0.25, 0.75), (4, 10.0, 8.0, 0.8, 0.25, 0.75)]
    >>> t.result
    (0.0, 4.5, 10.0, 9.5)
    """
    xmin, ymin, xmax, ymax = w.rectangle(window)
    seg, ok, out, log = _run(k.LIANG_BARSKY, x0, y0, x1, y1,
                             w.rectangle_polygon(xmin, ymin, xmax, ymax), 4, k.PARAM_COLUMNS)
    rows = _parametric_rows(log, ["left", "right", "bottom", "top"])
    result, line = _result(ok, out)
    dx, dy = seg[2] - seg[0], seg[3] - seg[1]
    notes = [f"window xmin = {_cell(xmin)}, ymin = {_cell(ymin)}, xmax = {_cell(xmax)}, "
             f"ymax = {_cell(ymax)}; dx = {_cell(dx)}, dy = {_cell(dy)}",
             "p_k < 0: entering, u1 = max(u1, q/p); p_k > 0: leaving, u2 = min(u2, q/p); "
             "p_k = 0 and q_k < 0: parallel and outside",
             line]
    t = LineClipTable(f"Liang-Barsky clip ({_cell(seg[0])}, {_cell(seg[1])}) -> "
              f"({_cell(seg[2])}, {_cell(seg[3])})",
              ["k", "edge", "p", "q", "t", "kind", "u1", "u2"], rows, notes)
    t.result = result
    return t


def cyrus_beck(x0: float, y0: float, x1: float, y1: float,
               window: _Window = DEFAULT_WINDOW,
               window_polygon: Optional[Sequence[float]] = None) -> LineClipTable:
    """Cyrus-Beck step by step, as the notes' Table 1: for each clip edge i its
    outward normal N_i, the point PE_i (the edge's first vertex), P0 - PE_i,
    N_i.D, t = N_i.(P0 - PE_i) / -N_i.D, and whether the crossing is potentially
    entering (N_i.D < 0) or leaving (N_i.D > 0); t_E and t_L so far.

    ``window`` is a rectangle or a convex polygon (either orientation; it is
    walked counterclockwise); ``window_polygon``, if given, is the polygon as a
    flat list x0, y0, x1, y1, ... (the command line's ``--window-polygon``).

    Parameters
    ----------
    x0, y0 : float
        The segment's first endpoint (world coordinates).
    x1, y1 : float
        Its second endpoint.
    window : (xmin, ymin, xmax, ymax) or convex polygon (M, 2), optional
        The clip window (default `DEFAULT_WINDOW`).
    window_polygon : sequence of float, optional
        The convex window as a flat list x0, y0, x1, y1, ...; it replaces `window`.

    Returns
    -------
    Table
        One row per clip edge; ``table.result`` is the clipped segment (x0, y0, x1, y1) as floats, or
        None when nothing is visible.

    Raises
    ------
    TypeError
        If a coordinate is not a real number or the window is not numeric.
    ValueError
        If a coordinate is beyond the supported range or the window is degenerate, not convex, or `window_polygon` lists an odd count of numbers.

    Examples
    --------

    >>> t = cyrus_beck(-5, 2, 15, 12, window=(0, 0, 10, 10))
    >>> [(r["edge"], r["N"], r["t"], r["kind"]) for r in t.rows]
    [(1, '(0, -1)', -0.2, 'PE (entering)'), (2, '(1, 0)', 0.75, 'PL (leaving)'), (3, '(0, 1)', 0.8, 'PL (leaving)'), (4, '(-1, 0)', 0.25, 'PE (entering)')]
    >>> t.result
    (0.0, 4.5, 10.0, 9.5)
    """
    window = _window(window, window_polygon)
    ring = w.polygon(window, convex=True, algorithm="Cyrus-Beck")
    normals = w.outward_normals(ring)
    seg, ok, out, log = _run(k.CYRUS_BECK, x0, y0, x1, y1, ring, len(ring), k.PARAM_COLUMNS)
    dx, dy = seg[2] - seg[0], seg[3] - seg[1]
    rows = []
    for kk, p, q, r, kind, u1, u2 in log.tolist():
        i = int(kk) - 1
        a = ring[i]
        nx, ny = normals[i]
        rows.append({"edge": int(kk), "N": _vector(nx, ny), "PE": _vector(*a),
                     "P0 - PE": _vector(seg[0] - a[0], seg[1] - a[1]), "N.D": p,
                     "t": None if np.isnan(r) else r, "kind": _KINDS[int(kind)],
                     "t_E": u1, "t_L": u2})
    result, line = _result(ok, out)
    notes = ["window (counterclockwise): "
             + ", ".join(_vector(*pt) for pt in ring),
             f"D = P1 - P0 = {_vector(dx, dy)}; N_i = outward normal of the edge from "
             "PE_i to the next vertex",
             "N.D < 0: PE, t_E = max(t_E, t); N.D > 0: PL, t_L = min(t_L, t); "
             "visible from t_E to t_L if t_E <= t_L",
             line]
    t = LineClipTable(f"Cyrus-Beck clip ({_cell(seg[0])}, {_cell(seg[1])}) -> "
              f"({_cell(seg[2])}, {_cell(seg[3])})",
              ["edge", "N", "PE", "P0 - PE", "N.D", "t", "kind", "t_E", "t_L"], rows, notes)
    t.result = result
    return t


#: The most vertices a Sutherland-Hodgman trace takes (each stage lists every edge).
SH_MAX_VERTICES = 10_000

_SH_CASES = {(False, True): "out -> in: output I and P", (True, True): "in -> in: output P",
             (True, False): "in -> out: output I", (False, False): "out -> out: no output"}


def sutherland_hodgman(points: Points, window: _Window = DEFAULT_WINDOW,
                       window_polygon: Optional[Sequence[float]] = None) -> PolygonClipTable:
    """Sutherland-Hodgman polygon clipping step by step: the polygon is clipped by
    one window boundary after another, and for each boundary every edge S -> P of
    the polygon so far falls in one of the four cases of Hearn & Baker (section 6-8):
    out -> in outputs the intersection I and P, in -> in outputs P, in -> out
    outputs I, out -> out outputs nothing.

    Each row is one edge of one stage: the boundary (``stage``, numbered from 1, and
    the directed window edge), S, P, the case and what was output.  A vertex on the
    boundary counts as inside, and a vertex equal to the one output before it is
    output once (so some rows output less than their case says).  ``table.stages``
    lists the polygon after each stage; ``table.result`` is the clipped polygon, a
    list of (x, y), empty when nothing is left.  The rows come from the clipper's own
    stage (:func:`scanline._kernels.clip.clip_stage`, run as Python), so they are
    the steps of :func:`scanline.clip.polygon`.

    Parameters
    ----------
    points : array_like, shape (N, 2)
        The subject polygon (one contour, either orientation).
    window : (xmin, ymin, xmax, ymax) or convex polygon (M, 2), optional
        The clip window (default `DEFAULT_WINDOW`).
    window_polygon : list of numbers, optional
        The convex window as a flat list x0, y0, x1, y1, ... (as :func:`cyrus_beck`).

    Returns
    -------
    Table
        One row per polygon edge per stage; ``table.stages`` lists the polygon after
        each stage and ``table.result`` the clipped polygon as a list of (x, y).

    Raises
    ------
    TypeError
        If `points` or the window is not numeric.
    ValueError
        If the window is degenerate or not convex, or `window_polygon` lists an odd
        count of numbers.

    Examples
    --------
    >>> t = sutherland_hodgman([(-2, 2), (6, 2), (6, 12)], window=(0, 0, 10, 10))
    >>> [(r["stage"], r["S"], r["P"], r["case"]) for r in t.rows[6:9]]  # the top, y = 10
    [(3, '(6, 12)', '(-2, 2)', 'out -> in: output I and P'), (3, '(-2, 2)', '(6, 2)', 'in -> in: output P'), (3, '(6, 2)', '(6, 12)', 'in -> out: output I')]
    >>> t.result
    [(4.4, 10.0), (0.0, 4.5), (0.0, 2.0), (6.0, 2.0), (6.0, 10.0)]
    """
    from .._kernels._jit import python
    from ..geometry.contours import contours

    verts, offsets = contours("points", points)
    if len(offsets) != 2:
        raise ArgumentValueError(
            f"points must be one contour for a trace, got {len(offsets) - 1} contours")
    if len(verts) > SH_MAX_VERTICES:
        raise ArgumentValueError(
            f"points has {len(verts)} vertices; a trace takes at most {SH_MAX_VERTICES}")
    ring = w.polygon(_window(window, window_polygon), convex=True,
                     algorithm="Sutherland-Hodgman")
    stage = python(k.clip_stage)
    current = w._ring(verts)
    rows, stages = [], []
    for e in range(len(ring)):
        a, b = ring[e], ring[(e + 1) % len(ring)]
        n = len(current)
        dst = np.empty((2 * n + 2, 2))
        log = np.full((n, k.SH_COLUMNS), np.nan)
        m = stage(current, n, dst, a[0], a[1], b[0], b[1], log)
        for i, s_in, p_in, got_i, ix, iy, got_p in log[:n].tolist():
            i = int(i)
            s, p = current[i - 1], current[i]
            out = ([_vector(ix, iy)] if got_i else []) + ([_vector(*p)] if got_p else [])
            rows.append({"stage": e + 1, "boundary": f"{_vector(*a)} -> {_vector(*b)}",
                         "S": _vector(*s), "P": _vector(*p),
                         "case": _SH_CASES[(bool(s_in), bool(p_in))],
                         "output": " ".join(out)})
        current = dst[:m].copy()
        stages.append([tuple(q) for q in current.tolist()])
        if m == 0:
            break
    result = stages[-1] if stages and len(stages[-1]) >= 3 else []
    notes = ["window (counterclockwise): " + ", ".join(_vector(*q) for q in ring),
             "each stage keeps the half-plane left of (or on) its directed window edge",
             *(f"after stage {i + 1}: " + (" ".join(_vector(*q) for q in s) or "nothing")
               for i, s in enumerate(stages)),
             "result: " + (" ".join(_vector(*q) for q in result) or "nothing is visible")]
    t = PolygonClipTable(f"Sutherland-Hodgman clip of a {len(verts)}-vertex polygon",
              ["stage", "boundary", "S", "P", "case", "output"], rows, notes)
    t.stages = stages
    t.result = result
    return t
