"""The algorithm explorer's data: a step table from :mod:`scanline.trace`, turned
into what the page shows at each step.

Arguments are those of ``scanline trace ALGORITHM ARGS...`` and are parsed by the
very same parser (:func:`scanline.cli.trace.add_algorithms`), so a bad argument gives
the page the message the command line prints.  The rows come from ``sl.trace``;
this module only says, for each row, which pixels it plots, which piece of a
segment or polygon it leaves, and which handles (endpoints, control points, seeds)
the page may drag, as indices into the argument list.  The page never runs an
algorithm.
"""

from __future__ import annotations

import argparse
import math
import operator
import re
import shlex
from typing import TYPE_CHECKING, Any, Callable, Sequence, Union

from .. import budget
from ..cli import Parser, UsageError
from ..cli import trace as cli_trace
from ..errors import MemoryBudgetError
from ..trace.animation import TIME_CELLS
from ..trace.backface import HEIGHT as BF_HEIGHT
from ..trace.backface import WIDTH as BF_WIDTH
from ..trace.bsp import HEIGHT as BSP_HEIGHT
from ..trace.bsp import WIDTH as BSP_WIDTH
from ..trace.conics import MAX_RADIUS, _mirror4
from ..trace.shading import HEIGHT as SH_HEIGHT
from ..trace.shading import WIDTH as SH_WIDTH
from ..trace.raytracing import HEIGHT as RT_HEIGHT
from ..trace.raytracing import WIDTH as RT_WIDTH
from ..trace.seedfill import EXAMPLE_GRID, _rows
from ..trace.table import Table
from ..trace.visible import SCENES as DEPTH_SORT_SCENES
from ..trace.subdivision import HEIGHT as WA_HEIGHT
from ..trace.subdivision import WIDTH as WA_WIDTH
from ..trace.zbuffer import HEIGHT as ZB_HEIGHT
from ..trace.zbuffer import SCENE as ZB_SCENE
from ..trace.zbuffer import WIDTH as ZB_WIDTH

if TYPE_CHECKING:
    from ..trace.animation import MorphTable
    from ..trace.backface import BackFaceTable
    from ..trace.bsp import BSPTable
    from ..trace.clip import LineClipTable, PolygonClipTable
    from ..trace.polygon import FillTable
    from ..trace.raycasting import RayCastingTable
    from ..trace.scanline_method import ScanLineTable
    from ..trace.shading import ShadingTable
    from ..trace.subdivision import WarnockTable

#: Where each coordinate of the arguments sits: ``(dest, i)`` -> token index.
Where = dict[tuple[str, int], int]
#: A view, JSON-ready (see :func:`explore`).
View = dict[str, Any]

#: The first case the explorer shows for each algorithm (command-line arguments).
DEFAULTS = {
    "bresenham": ["20", "10", "30", "18"],
    "dda": ["2", "3", "14", "9"],
    "midpoint-circle": ["10", "--center", "12", "12"],
    "midpoint-ellipse": ["8", "6", "--center", "10", "8"],
    "flood-fill": ["1", "2", "--connectivity", "8"],
    "boundary-fill": ["1", "2", "--boundary", "#"],
    "scan-line-fill": ["2,1", "15,4", "10,13", "6,6", "1,9"],
    "cohen-sutherland": ["-5", "2", "15", "22"],
    "liang-barsky": ["-5", "2", "15", "12"],
    "cyrus-beck": ["-5", "2", "15", "12", "--window-polygon", "0,0,10,0,12,8,4,12"],
    "sutherland-hodgman": ["--", "-2,2", "6,-1", "13,6", "6,13"],
    "de-casteljau": ["0,0", "2,8", "10,8", "12,0", "--u", "0.5"],
    "cox-de-boor": ["--knots", "0,0,0,0,1,2,2,2,2", "--order", "4", "--u", "1.5"],
    # a segment entering through the left plane, leaving through the back one
    "cohen-sutherland-3d": ["-4", "2", "3", "14", "8", "13"],
    "liang-barsky-3d": ["-4", "2", "3", "14", "8", "13"],
    "z-buffer": ["--row", "4"],
    "depth-sort": ["--scene", "cyclic"],
    "floating-horizon": ["--nx", "6", "--ny", "4", "--width", "24", "--height", "16"],
    "ray-tracing": ["20", "11"],
    "back-face": ["--eye", "3", "2", "4"],
    "gouraud": ["--row", "12"],
    "phong": ["--row", "12"],
    "bsp-tree": ["--eye", "6", "22"],
    "warnock": ["--scene", "overlap"],
    "scan-line-visible": ["--scene", "overlap"],
    "ray-casting": ["--row", "4"],
    "inbetween-spacing": ["--n", "7", "--spacing", "accelerate"],
    "morph-equalize": ["--t", "0.5"],
}

#: Tables longer than this are refused: the page lists every row.
MAX_ROWS = 20_000


class BadArguments(ValueError):
    """Arguments the command line would refuse; the message is the command line's."""


def _parsers() -> tuple[dict[str, argparse.ArgumentParser], Parser]:
    root = Parser(prog="scanline trace")
    return cli_trace.add_algorithms(root, None), root


_SUBS, _ROOT = _parsers()


def catalog() -> list[dict[str, Any]]:
    """The explorer's algorithms: every one of ``scanline trace``.

    Returns
    -------
    list of dict
        Per algorithm: ``name``, ``description``, ``usage`` (the command line's
        usage line) and ``defaults`` (the first case shown, :data:`DEFAULTS`).

    Examples
    --------
    >>> [a["defaults"] for a in catalog() if a["name"] == "bresenham"]
    [['20', '10', '30', '18']]
    """
    return [{"name": name, "description": desc, "usage": _SUBS[name].format_usage().strip()
             .replace("usage: ", ""), "defaults": DEFAULTS.get(name, [])}
            for name, (desc, _, _) in cli_trace.ALGORITHMS.items()]


def parse(algorithm: str, args: list[str]) -> argparse.Namespace:
    """The parsed arguments of ``scanline trace ALGORITHM ARGS...``.

    Parameters
    ----------
    algorithm : str
        An algorithm of :func:`catalog`.
    args : list of str
        Its arguments, as on the command line (at most 10000).

    Returns
    -------
    argparse.Namespace
        What ``scanline trace`` parses.

    Raises
    ------
    BadArguments
        (a ValueError) with the command line's message: an unknown algorithm, bad
        arguments, ``--help``.

    Examples
    --------
    >>> parse("dda", ["0", "0", "4", "2"]).x1
    4
    """
    if algorithm not in _SUBS:
        raise BadArguments(f"unknown algorithm {algorithm!r}; choose one of "
                           + ", ".join(_SUBS))
    if not isinstance(args, list) or not all(isinstance(a, str) for a in args) or len(args) > 10_000:
        raise BadArguments("args must be a list of at most 10000 strings, as on the command line")
    try:
        return _ROOT.parse_args([algorithm, *args])
    except UsageError as error:
        raise BadArguments(str(error)) from None
    except SystemExit:  # --help
        raise BadArguments(f"use the usage line: {_SUBS[algorithm].format_usage().strip()}") from None


def _number(x: object) -> str:
    if isinstance(x, float) and x.is_integer() and abs(x) < 1e15:
        return str(int(x))
    return repr(x) if isinstance(x, float) else str(x)


def canonical(ns: argparse.Namespace) -> tuple[list[str], Where]:
    """The arguments of ``ns`` spelled out (options first, then the positionals,
    after ``--`` when one starts with '-' and is not a number) and where each coordinate sits: ``(tokens, where)`` with
    ``where[(dest, i)]`` the token index of element i of argument ``dest`` (for a
    list of points, ``(dest, i)`` is the token 'x,y' of point i)."""
    sub = _SUBS[ns.algorithm]
    options: list[str] = []
    positionals: list[str] = []
    at: dict[tuple[str, int], Union[int, tuple[str, int]]] = {}
    for action in sub._actions:
        if action.dest in ("help",) or isinstance(action, argparse._HelpAction):
            continue
        value = getattr(ns, action.dest, None)
        if value is None:
            continue
        if action.option_strings and action.nargs == 0:
            if value != action.default:      # a flag (--no-split): its name, no value
                options.append(action.option_strings[0])
            continue
        if action.option_strings:
            options.append(action.option_strings[0])
            items = value if isinstance(value, list) else [value]
            if action.type is cli_trace.numbers and action.nargs is None:
                items = [",".join(_number(c) for c in value)]   # one token: 'x,y,x,y,...'
            for i, item in enumerate(items):
                at[(action.dest, i)] = len(options)
                options.append(_number(item))
        else:
            items = value if isinstance(value, list) else [value]
            for i, item in enumerate(items):
                at[(action.dest, i)] = ("p", len(positionals))
                positionals.append(",".join(_number(c) for c in item) if isinstance(item, list)
                                   else _number(item))
    dash = any(t.startswith("-") and not _ROOT._negative_number_matcher.match(t)
               for t in positionals)
    tokens = options + (["--"] if dash else []) + positionals
    base = len(options) + (1 if dash else 0)
    where = {k: (base + i[1] if isinstance(i, tuple) else i) for k, i in at.items()}
    return tokens, where


def _handle(where: Where, label: str, x: float, y: float, xkey: tuple[str, int],
            ykey: tuple[str, int] | None = None, kind: str = "point") -> dict[str, Any]:
    """A draggable handle at (x, y) bound to tokens: two tokens (x, y) or one token
    'x,y' (``ykey`` None); ``kind`` "radius-x" / "radius-y" binds one token to the
    distance from the center."""
    h: dict[str, Any] = {"label": label, "x": x, "y": y, "kind": kind}
    if ykey is None:
        h["token"] = where[xkey]
    else:
        h["tokens"] = [where[xkey], where[ykey]] if kind == "point" else [where[xkey]]
    return h


def _pixels(points: Any) -> list[list[int]]:
    return [[int(x), int(y)] for x, y in points]


def _bounds(points: Sequence[Sequence[float]], margin: int = 2) -> list[int]:
    xs = [p[0] for p in points] or [0]
    ys = [p[1] for p in points] or [0]
    return [math.floor(min(xs)) - margin, math.floor(min(ys)) - margin,
            math.ceil(max(xs)) + margin, math.ceil(max(ys)) + margin]


#: Rules of the line algorithms, filled in by the page from each row's columns
#: (``{p}`` is the row's p): the server picks the rule of each row.
_BRESENHAM_RULES = [
    "p_{k} = {p} < 0: keep the minor coordinate; p_k+1 = p_k + 2dy (add {increment})",
    "p_{k} = {p} >= 0: step the minor coordinate; p_k+1 = p_k + 2dy - 2dx (add {increment})",
]
_DDA_RULES = ["x = {x_real} -> {x}, y = {y_real} -> {y} (round: floor(v + 0.5))"]


def _lines(table: Table, ns: argparse.Namespace, where: Where) -> View:
    rows = table.rows
    if ns.algorithm == "bresenham":
        # the start pixel, plotted before step 0, is the endpoint the last row is not
        end = (rows[-1]["x"], rows[-1]["y"]) if rows else None
        start = (ns.x1, ns.y1) if end == (ns.x0, ns.y0) else (ns.x0, ns.y0)
        rules = {"templates": _BRESENHAM_RULES, "pick": [int(r["p"] >= 0) for r in rows]}
        before = _pixels([start])
    else:
        rules = {"templates": _DDA_RULES, "pick": [0] * len(rows)}
        before = []
    ends = [(ns.x0, ns.y0), (ns.x1, ns.y1)]
    # each row plots the pixel in its columns x, y: no per-step lists for long lines
    return {"before": before, "steps": None, "pixel_columns": ["x", "y"], "rules": rules,
            "bounds": _bounds(ends),
            "shapes": [{"kind": "line", "points": [list(ends[0]), list(ends[1])]}],
            "handles": [_handle(where, "P0", ns.x0, ns.y0, ("x0", 0), ("y0", 0)),
                        _handle(where, "P1", ns.x1, ns.y1, ("x1", 0), ("y1", 0))]}


def _conics(table: Table, ns: argparse.Namespace, where: Where) -> View:
    xc, yc = ns.center
    circle = ns.algorithm == "midpoint-circle"
    rx, ry = (ns.r, ns.r) if circle else (ns.rx, ns.ry)
    steps: list[dict[str, Any]] = []
    for i, r in enumerate(table.rows):
        pts = _mirror4(xc, yc, r["x"], r["y"])
        if circle:
            pts |= _mirror4(xc, yc, r["y"], r["x"])
        p = r.get("p")
        if p is None:
            rule = "tip: complete the flat ellipse along y = 0"
        elif circle:
            rule = (f"p_{r['k']} = {p} < 0: (x + 1, y)" if p < 0 else
                    f"p_{r['k']} = {p} >= 0: (x + 1, y - 1)")
        elif r["region"] == "1":
            rule = (f"region 1, p1_{r['k']} = {p} < 0: (x + 1, y)" if p < 0 else
                    f"region 1, p1_{r['k']} = {p} >= 0: (x + 1, y - 1)")
        else:
            rule = (f"region 2, p2_{r['k']} = {p} > 0: (x, y - 1)" if p > 0 else
                    f"region 2, p2_{r['k']} = {p} <= 0: (x + 1, y - 1)")
        steps.append({"pixels": _pixels(sorted(pts)), "rule": rule})
    start = _mirror4(xc, yc, 0, ry) | (_mirror4(xc, yc, ry, 0) if circle else set())
    handles = [_handle(where, "center", xc, yc, ("center", 0), ("center", 1))]
    if circle:
        handles.append(_handle(where, "r", xc + rx, yc, ("r", 0), ("r", 0), "radius-x"))
    else:
        handles += [_handle(where, "rx", xc + rx, yc, ("rx", 0), ("rx", 0), "radius-x"),
                    _handle(where, "ry", xc, yc + ry, ("ry", 0), ("ry", 0), "radius-y")]
    return {"before": _pixels(sorted(start)), "steps": steps,
            "bounds": [xc - rx - 2, yc - ry - 2, xc + rx + 2, yc + ry + 2],
            "shapes": [], "handles": handles, "center": [xc, yc]}


def _fills(table: Table, ns: argparse.Namespace, where: Where) -> View:
    rows = _rows(ns.grid if ns.grid is not None else EXAMPLE_GRID)
    h = len(rows)
    cells = [[x, h - 1 - j, c] for j, line in enumerate(rows) for x, c in enumerate(line)]
    steps: list[dict[str, Any]] = []
    for r in table.rows:
        if r["span"] == "already filled":
            steps.append({"pixels": [], "mark": [[r["x"], r["y"]]],
                          "rule": f"pop ({r['x']}, {r['y']}): already filled"})
            continue
        a, b = (int(t) for t in r["span"].split(".."))
        steps.append({"pixels": [[x, r["y"]] for x in range(a, b + 1)], "mark": [[r["x"], r["y"]]],
                      "rule": f"pop ({r['x']}, {r['y']}), fill {a}..{b} on y = {r['y']}"
                              + (f", push {r['pushed']}" if r["pushed"] else "")})
    return {"before": [], "steps": steps, "bounds": [0, 0, len(rows[0]) - 1, h - 1],
            "cells": cells, "shapes": [],
            "handles": [_handle(where, "seed", ns.x, ns.y, ("x", 0), ("y", 0))]}


def _point_handles(where: Where, dest: str, points: Sequence[Sequence[float]]
                   ) -> list[dict[str, Any]]:
    return [_handle(where, f"P{i}", p[0], p[1], (dest, i)) for i, p in enumerate(points)]


def _scan_fill(table: FillTable, ns: argparse.Namespace, where: Where) -> View:
    steps: list[dict[str, Any]] = []
    for r in table.rows:
        spans = [tuple(int(t) for t in s.split("..")) for s in r["spans"].split()]
        keys = [[int(e.split(":")[1]), r["y"]] for e in r["active"].split()]
        steps.append({"pixels": [[x, r["y"]] for a, b in spans for x in range(a, b + 1)],
                      "mark": keys,
                      "rule": f"y = {r['y']}: active {r['active'] or 'none'}; spans "
                              f"{r['spans'] or 'none'}"})
    pts = ns.points
    return {"before": [], "steps": steps, "bounds": _bounds(pts),
            "shapes": [{"kind": "polygon", "points": pts}],
            "handles": _point_handles(where, "points", pts), "edges": table.edges}


def _clip_window(ns: argparse.Namespace) -> list[list[float]]:
    if getattr(ns, "window_polygon", None):
        f = ns.window_polygon
        return [[f[i], f[i + 1]] for i in range(0, len(f) - 1, 2)]
    x0, y0, x1, y1 = ns.window or (0, 0, 10, 10)
    return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]


def _line_clip(table: LineClipTable, ns: argparse.Namespace, where: Where) -> View:
    p0, p1 = [ns.x0, ns.y0], [ns.x1, ns.y1]
    steps: list[dict[str, Any]] = []
    if ns.algorithm == "cohen-sutherland":
        cur = [list(p0), list(p1)]
        for r in table.rows:
            if r["x"] is not None:
                end = 0 if r["decision"].startswith("clip P0") else 1
                cur[end] = [r["x"], r["y"]]
            steps.append({"segment": [cur[0][:], cur[1][:]],
                          "rule": f"codes {r['code0']} {r['code1']}, AND {r['and']}: {r['decision']}"})
    else:
        lo, hi = ("u1", "u2") if ns.algorithm == "liang-barsky" else ("t_E", "t_L")
        d = [p1[0] - p0[0], p1[1] - p0[1]]
        for r in table.rows:
            a, b = r[lo], r[hi]
            seg = ([[p0[0] + a * d[0], p0[1] + a * d[1]], [p0[0] + b * d[0], p0[1] + b * d[1]]]
                   if a <= b else None)
            steps.append({"segment": seg, "rule": f"{r['kind']}: t = {r['t']}, {lo} = {a:.6g}, "
                                                  f"{hi} = {b:.6g}"})
    win = _clip_window(ns)
    return {"before": [], "steps": steps, "bounds": _bounds(win + [p0, p1]),
            "shapes": [{"kind": "polygon", "points": win, "role": "window"},
                       {"kind": "line", "points": [p0, p1], "role": "subject"}],
            "handles": [_handle(where, "P0", p0[0], p0[1], ("x0", 0), ("y0", 0)),
                        _handle(where, "P1", p1[0], p1[1], ("x1", 0), ("y1", 0))],
            "result": getattr(table, "result", None)}


def _vertex(text: str) -> list[float]:
    return [float(c) for c in text.strip("()").split(", ")]


def _polygon_clip(table: PolygonClipTable, ns: argparse.Namespace, where: Where) -> View:
    steps: list[dict[str, Any]] = []
    stage = None
    out: list[list[float]] = []
    inputs = [ns.points] + table.stages
    for r in table.rows:
        if r["stage"] != stage:
            stage, out = r["stage"], []
        out = out + [_vertex("(" + v) for v in r["output"].strip("(").split(" (") if r["output"]]
        a, b = r["boundary"].split(" -> ")
        steps.append({"polygon": inputs[r["stage"] - 1], "output": out,
                      "boundary": [_vertex(a), _vertex(b)], "edge": [_vertex(r["S"]), _vertex(r["P"])],
                      "rule": f"stage {stage}, edge S {r['S']} -> P {r['P']}: {r['case']}"})
    win = _clip_window(ns)
    return {"before": [], "steps": steps, "bounds": _bounds(win + ns.points),
            "shapes": [{"kind": "polygon", "points": win, "role": "window"},
                       {"kind": "polygon", "points": ns.points, "role": "subject"}],
            "handles": _point_handles(where, "points", ns.points), "result": table.result}


def _casteljau(table: Table, ns: argparse.Namespace, where: Where) -> View:
    steps = [{"points": [[r["x"], r["y"]]], "level": r["r"],
              "rule": f"P_{r['i']}^{r['r']} = (1 - u) P_{r['i']}^{r['r'] - 1} + u P_{r['i'] + 1}^{r['r'] - 1}"
              if r["r"] else f"P_{r['i']}^0 = control point {r['i']}"} for r in table.rows]
    pts = [p[:2] for p in ns.points]
    return {"before": [], "steps": steps, "bounds": _bounds(pts),
            "shapes": [{"kind": "polyline", "points": pts, "role": "control"}],
            "handles": _point_handles(where, "points", pts)}


def _cox_de_boor(table: Table, ns: argparse.Namespace, where: Where) -> View:
    steps = [{"bar": [r["k"], r["r"], r["B"]],
              "rule": f"B_{r['k']},{r['r']}({ns.u:g}) = {r['B']:.6g} on {r['interval']}"}
             for r in table.rows]
    return {"before": [], "steps": steps, "bounds": [0, 0, len(ns.knots), ns.order + 1],
            "shapes": [], "handles": []}


#: The oblique (cabinet) projection of the 3-D views: depth z recedes up and to the
#: right at 30 degrees, at half scale (Hearn & Baker, section 12-1, oblique projections).
_OBLIQUE = (0.5 * math.cos(math.pi / 6), 0.5 * math.sin(math.pi / 6))


def _volume_corners(ns: argparse.Namespace) -> list[list[float]]:
    """The clip volume's 8 corners (front face first) in the coordinates the segment
    is drawn in: the box, the canonical frustum, or the unit cube of ``--w``."""
    if ns.w is not None:
        lo, hi = [0.0] * 3, [1.0] * 3
    elif ns.frustum is not None:     # z <= x, y <= -z between z = ZMIN and z = -1
        los = [[z, z, z] for z in (ns.frustum, -1.0)]
        his = [[-z, -z, z] for z in (ns.frustum, -1.0)]
        return [c for a, b in zip(los, his) for c in ([a[0], a[1], a[2]], [b[0], a[1], a[2]],
                                                  [b[0], b[1], a[2]], [a[0], b[1], a[2]])]
    else:
        b = ns.volume or [0, 0, 0, 10, 10, 10]
        lo, hi = b[:3], b[3:]
    return [[lo[0], lo[1], lo[2]], [hi[0], lo[1], lo[2]], [hi[0], hi[1], lo[2]],
            [lo[0], hi[1], lo[2]], [lo[0], lo[1], hi[2]], [hi[0], lo[1], hi[2]],
            [hi[0], hi[1], hi[2]], [lo[0], hi[1], hi[2]]]


def _clip3d(table: Table, ns: argparse.Namespace, where: Where) -> View:
    """The 3-D clippers on the grid: the volume and the segment in an oblique
    projection scaled to about 20 cells, the piece kept so far drawn at each step."""
    corners = _volume_corners(ns)
    start: list[float] = [ns.x0, ns.y0, ns.z0]
    end: list[float] = [ns.x1, ns.y1, ns.z1]
    p0: list[float] | None = start
    p1: list[float] | None = end
    if ns.w is not None:             # drawn after the divide, where w > 0
        p0 = [c / ns.w[0] for c in start] if ns.w[0] > 0 else None
        p1 = [c / ns.w[1] for c in end] if ns.w[1] > 0 else None
    span = max(max(c[i] for c in corners) - min(c[i] for c in corners) for i in range(3))
    scale = 20.0 / span if span > 0 and math.isfinite(span) else 1.0

    def at(p: Sequence[float]) -> list[float]:
        x, y, z = p
        return [round(scale * (x + _OBLIQUE[0] * z), 6), round(scale * (y + _OBLIQUE[1] * z), 6)]

    def along(a: Sequence[float], b: Sequence[float], u: float) -> list[float]:
        return at([a[i] + u * (b[i] - a[i]) for i in range(3)])

    steps: list[dict[str, Any]] = []
    if ns.algorithm == "cohen-sutherland-3d":
        cur: list[list[float] | None] = [p0, p1]
        for r in table.rows:
            if r["point"] is not None and ns.w is None:
                cur[int(r["decision"][6])] = _vertex(r["point"])
            c0, c1 = cur
            seg = [at(c0), at(c1)] if c0 is not None and c1 is not None else None
            steps.append({"segment": seg, "mark": [seg[int(r["decision"][6])]] if seg and
                          r["point"] else [],
                          "rule": f"codes {r['code0']} {r['code1']}, AND {r['and']}: "
                                  f"{r['decision']}"})
    else:
        for r in table.rows:
            u1, u2 = r["u1"], r["u2"]
            seg = ([along(p0, p1, u1), along(p0, p1, u2)] if p0 is not None and p1 is not None
                   and u1 <= u2 and ns.w is None else None)
            t = "parallel" if r["t"] is None else f"t = q/p = {r['t']:.6g}"
            steps.append({"segment": seg, "rule": f"{r['plane']}: p = {r['p']:g}, q = {r['q']:g}, "
                          f"{t}, {r['kind']}: u1 = {u1:.6g}, u2 = {u2:.6g}"})
    box = [at(c) for c in corners]
    shapes = [{"kind": "polygon", "points": box[:4], "role": "window"},
              {"kind": "polygon", "points": box[4:], "role": "window"}]
    shapes += [{"kind": "line", "points": [box[i], box[i + 4]], "role": "window"} for i in range(4)]
    ends = [at(p) for p in (p0, p1) if p is not None]
    if len(ends) == 2:
        shapes.append({"kind": "line", "points": ends, "role": "subject"})
    return {"before": [], "steps": steps, "bounds": _bounds(box + ends), "shapes": shapes,
            "handles": []}


def _z_buffer(table: Table, ns: argparse.Namespace, where: Where) -> View:
    """The scene's triangles on its device, the scan line, and at each step the pixel
    written (a write) or marked (a keep)."""
    steps: list[dict[str, Any]] = []
    for r in table.rows:
        write = r["result"] == "write"
        steps.append({"pixels": [[r["x"], ns.row]] if write else [], "mark": [[r["x"], ns.row]],
                      "rule": f"triangle {r['triangle']} at x = {r['x']}: z = {r['z']:.6g} "
                              f"{'<' if write else '>='} depth {r['depth']}: {r['result']}"})
    shapes = [{"kind": "polygon", "points": [[float(x), float(y)] for x, y, _ in tri.tolist()]}
              for tri in ZB_SCENE]
    shapes.append({"kind": "line", "points": [[0, ns.row], [ZB_WIDTH - 1, ns.row]]})
    return {"before": [], "steps": steps, "bounds": [0, 0, ZB_WIDTH - 1, ZB_HEIGHT - 1],
            "shapes": shapes, "handles": []}


_SPLIT = re.compile(r"split (\d+) by the plane of \d+ into (\d+) and (\d+)")


def _depth_sort(table: Table, ns: argparse.Namespace, where: Where) -> View:
    """The scene's polygons; at each step the pair compared: S (this step's color)
    and S' (plotted), split pieces drawn as the polygon they came from."""
    polys = [[[float(x), float(y)] for x, y, _ in p] for p in DEPTH_SORT_SCENES[ns.scene]]
    face = list(range(len(polys)))                 # piece number -> its polygon
    steps: list[dict[str, Any]] = []
    for r in table.rows:
        s, t = r["S"], r["S'"]
        tried = [f"{k + 1} {r[f'test {k + 1}']}" for k in range(5) if r[f"test {k + 1}"]]
        steps.append({"areas": [[polys[face[s]], "current"], [polys[face[t]], "plotted"]],
                      "rule": f"S = {s}, S' = {t}: tests {', '.join(tried)}; {r['action']}"})
        split = _SPLIT.search(r["action"])
        if split:
            a, b, c = (int(g) for g in split.groups())
            face += [face[a]] * (max(b, c) + 1 - len(face))
            face[b] = face[c] = face[a]
    return {"before": [], "steps": steps, "bounds": [0, 0, 39, 29],
            "shapes": [{"kind": "polygon", "points": p} for p in polys], "handles": []}


def _floating_horizon(table: Table, ns: argparse.Namespace, where: Where) -> View:
    """Each curve's point at each column: plotted where visible (above the upper or
    below the lower horizon), marked where hidden; the page draws both horizons as
    they stand after the step (``horizon``: the columns that hold them)."""
    steps: list[dict[str, Any]] = []
    for r in table.rows:
        at = [r["column"], round(r["y"])]
        seen = r["visible"] != "hidden"
        steps.append({"pixels": [at] if seen else [], "mark": [at],
                      "rule": f"curve {r['curve']}, column {r['column']}: y = {r['y']:.6g}; "
                              f"lower {_finite_text(r['lower before'])}, upper "
                              f"{_finite_text(r['upper before'])}: {_SEEN[r['visible']]}"})
    ys = [round(r["y"]) for r in table.rows]
    return {"before": [], "steps": steps,
            "bounds": [0, min([0] + ys), ns.width - 1, max([ns.height - 1] + ys)],
            "horizon": {"column": "column", "upper": "upper after", "lower": "lower after"},
            "shapes": [], "handles": []}


_SEEN = {"above": "above the upper horizon, visible; it raises the upper",
         "below": "below the lower horizon, visible; it lowers the lower",
         "hidden": "between the horizons, hidden"}


def _finite_text(x: float | None) -> str:
    return "none" if x is None else f"{x:.6g}"


def _ray_tracing(table: Table, ns: argparse.Namespace, where: Where) -> View:
    """The pixel whose ray tree the table lists, draggable; each ray's row as a rule."""
    steps: list[dict[str, Any]] = []
    for r in table.rows:
        if r["kind"] == "shadow":
            rule = (f"shadow ray of ray {r['parent']} to light {r['light']}: lets through "
                    f"{r['through']:g}")
        else:
            hit = (f"hits face {r['face']} at t = {r['t']:.6g}" if r["face"] is not None
                   and r["face"] >= 0 else "leaves the scene")
            total = ", ".join(f"{r[c]:.4g}" for c in ("sum_r", "sum_g", "sum_b"))
            rule = (f"ray {r['ray']} ({r['kind']}, depth {r['depth']}): {hit}; weight "
                    f"{r['weight']:.6g}, sum ({total})")
        steps.append({"pixels": [[ns.x, ns.y]], "rule": rule})
    return {"before": [], "steps": steps, "bounds": [0, 0, RT_WIDTH - 1, RT_HEIGHT - 1],
            "shapes": [], "handles": [_handle(where, "pixel", ns.x, ns.y, ("x", 0), ("y", 0))]}


def _back_face(table: BackFaceTable, ns: argparse.Namespace, where: Where) -> View:
    """The cube's faces on the device: at each step the face tested (this step's
    color), the front faces found before it plotted."""
    steps: list[dict[str, Any]] = []
    for r in table.rows:
        front = r["result"] == "front"
        done = [[t, "plotted"] for q in table.rows[:r["face"]] if q["result"] == "front"
                for t in table.outlines[q["face"]]]
        steps.append({"areas": done + [[t, "current"] for t in table.outlines[r["face"]]],
                      "rule": f"face {r['face']}: V.N = {r['V.N']:g} "
                              f"{'< 0: front face, drawn' if front else '> 0: back face, culled'}"
                              if r["V.N"] else f"face {r['face']}: V.N = 0, seen edge-on"})
    shapes = [{"kind": "polygon", "points": t} for face in table.outlines for t in face]
    return {"before": [], "steps": steps, "bounds": [0, 0, BF_WIDTH - 1, BF_HEIGHT - 1],
            "shapes": shapes, "handles": []}


def _shading(table: ShadingTable, ns: argparse.Namespace, where: Where) -> View:
    """The sphere's triangles that the scan line crosses; at each step the pixel
    shaded, its triangle filled, and the pixels before it in their gray (the
    ``shade_column``, a linear intensity)."""
    steps: list[dict[str, Any]] = []
    for r, k in zip(table.rows, table.triangle_of):
        what = (f"I = {r['l0']:.4g} x {r['I0']:.4g} + {r['l1']:.4g} x {r['I1']:.4g} + "
                f"{r['l2']:.4g} x {r['I2']:.4g}" if "I0" in r else f"N = {r['N']}, I")
        steps.append({"pixels": [[r["x"], ns.row]], "areas": [[table.triangles[k], "plotted"]],
                      "rule": f"x = {r['x']}, facet {r['facet']}: {what} = {r['I']:.6g}"})
    shapes = [{"kind": "polygon", "points": t} for t in table.triangles.values()]
    shapes.append({"kind": "line", "points": [[0, ns.row], [SH_WIDTH - 1, ns.row]]})
    return {"before": [], "steps": steps, "bounds": [0, 0, SH_WIDTH - 1, SH_HEIGHT - 1],
            "shapes": shapes, "handles": [], "shade_column": "I"}


def _plane_line(plane: Sequence[float], width: int, height: int) -> list[list[float]]:
    """The plan line A x + B y + D = 0 of a wall's plane cut to the grid [0, width - 1]
    x [0, height - 1]: its two ends."""
    a, b, _, d = plane
    w, h = width - 1, height - 1
    ends = [[x, -(a * x + d) / b] for x in (0, w) if b] + [[-(b * y + d) / a, y] for y in (0, h)
                                                          if a]
    ends = [p for p in ends if -1e-9 <= p[0] <= w + 1e-9 and -1e-9 <= p[1] <= h + 1e-9]
    return [min(ends), max(ends)] if ends else []


def _bsp_tree(table: BSPTable, ns: argparse.Namespace, where: Where) -> View:
    """The walls in plan.  Building: the node's splitting plane (a line across the
    grid), its pieces (this step's color), the pieces in front (result color) and
    behind (plotted).  Drawing: the pieces painted so far and this one; the eye is a
    handle."""
    steps: list[dict[str, Any]] = []
    drawn: list[str] = []
    for r in table.rows:
        if r["phase"] == "build":
            n = r["node"]
            sets = [(r["in front"], "result"), (r["behind"], "plotted"), (r["on"], "current")]
            areas = [[table.pieces[p], role] for names, role in sets if names != "-"
                     for p in names.split()]
            steps.append({"areas": areas,
                          "plane": _plane_line(table.planes[n], BSP_WIDTH, BSP_HEIGHT),
                          "rule": f"node {n}: plane {r['plane']} of wall {r['on']}; in front: "
                                  f"{r['in front']}; behind: {r['behind']}; split: {r['splits']}"})
        else:
            near = "front" if r["side"] == "back" else "back"
            steps.append({"areas": [[table.pieces[p], "plotted"] for p in drawn]
                          + [[table.pieces[r["piece"]], "current"]],
                          "rule": f"node {r['node']}: the eye is on its {r['side']} side, so its "
                                  f"{near} subtree was painted first; piece {r['piece']} "
                                  f"(wall {r['wall']}) painted"})
            drawn.append(r["piece"])
    shapes = [{"kind": "line", "points": seg} for seg in table.pieces.values()]
    return {"before": [], "steps": steps, "bounds": [0, 0, BSP_WIDTH - 1, BSP_HEIGHT - 1],
            "shapes": shapes,
            "handles": [_handle(where, "eye", ns.eye[0], ns.eye[1], ("eye", 0), ("eye", 1))]}


#: The colors of polygons P0, P1, P2, ... (cycled) where the image-space visible-surface
#: views paint their pixels.
POLYGON_COLORS = ("#1c7ed6", "#2b8a3e", "#ae3ec9", "#f59f00")


def _polygon_colors(table: WarnockTable | ScanLineTable, pixels: Sequence[Sequence[int]]
                    ) -> list[str]:
    """The color of the polygon that ``table.face`` shows at each pixel (x, y)."""
    return [POLYGON_COLORS[int(table.face[y, x]) % len(POLYGON_COLORS)] for x, y in pixels]


def _warnock(table: WarnockTable, ns: argparse.Namespace, where: Where) -> View:
    """The scene's polygons; at each step the area examined (this step's color), the
    pixels its decision paints, and those painted before (each in its polygon's
    color, :data:`POLYGON_COLORS`)."""
    steps: list[dict[str, Any]] = []
    for r, pixels in zip(table.rows, table.written):
        x0, y0, x1, y1 = r["x0"] - 0.5, r["y0"] - 0.5, r["x1"] + 0.5, r["y1"] + 0.5
        classes = ", ".join(f"{p} {r[p]}" for p in table.columns[5:-2])
        what = r["decision"] + (f": {r['painted']} painted" if r["painted"] else "")
        steps.append({"pixels": [list(p) for p in pixels],
                      "colors": _polygon_colors(table, pixels),
                      "areas": [[[[x0, y0], [x1, y0], [x1, y1], [x0, y1]], "current"]],
                      "rule": f"area ({r['x0']}, {r['y0']})-({r['x1']}, {r['y1']}), level "
                              f"{r['level']}: {classes}; {what}"})
    return {"before": [], "steps": steps, "bounds": [0, 0, WA_WIDTH - 1, WA_HEIGHT - 1],
            "shapes": [{"kind": "polygon", "points": p} for p in table.polygons],
            "handles": []}


def _scan_line_visible(table: ScanLineTable, ns: argparse.Namespace, where: Where) -> View:
    """The scene's polygons and the scan line; at each step the crossing (marked)
    and the span to the next crossing (this step's color), the spans before it in
    their polygons' colors."""
    steps: list[dict[str, Any]] = []
    for r in table.rows:
        y = r["y"]
        p = r["edge"].split("(")[1].rstrip(")")
        turned = "on" if p in r["on"].split() else "off"
        text = f"y = {y}: edge {r['edge']} crossed at x = {r['x']:.4g} turns {p} {turned}; "
        if r["span"] is None:
            text += "no pixel to the next crossing" if r["on"] != "-" else "no polygon on"
        elif r["depths"] is None:
            text += f"span {r['span']}: only {r['on']} on, shown without depths"
        else:
            text += f"span {r['span']}: {r['on']} on, depths {r['depths']}: {r['visible']} shown"
        pixels = []
        if r["span"]:
            a, b = (int(c) for c in r["span"].split(".."))
            pixels = [[x, y] for x in range(a, b + 1)]
        steps.append({"pixels": pixels, "colors": _polygon_colors(table, pixels),
                      "mark": [[r["x"], y]], "rule": text,
                      "plane": [[0, y], [WA_WIDTH - 1, y]]})
    return {"before": [], "steps": steps, "bounds": [0, 0, WA_WIDTH - 1, WA_HEIGHT - 1],
            "shapes": [{"kind": "polygon", "points": p} for p in table.polygons],
            "handles": []}


def _ray_casting(table: RayCastingTable, ns: argparse.Namespace, where: Where) -> View:
    """The z-buffer's triangles and the scan line; at each step the pixel whose ray
    is cast (this step's color, the nearest triangle filled), the pixels before it
    plotted where a triangle was met."""
    steps: list[dict[str, Any]] = []
    for r in table.rows:
        hit = r["nearest"] != "none"
        rule = (f"x = {r['x']}: the ray meets {r['hits']}; nearest {r['nearest']} at depth "
                f"{r['depth']:.6g}" if hit else f"x = {r['x']}: the ray meets nothing: "
                "background")
        steps.append({"pixels": [[r["x"], ns.row]] if hit else [], "mark": [[r["x"], ns.row]],
                      "areas": [[table.triangles[int(r["nearest"][1:])], "current"]] if hit
                      else [], "rule": rule})
    shapes = [{"kind": "polygon", "points": t} for t in table.triangles]
    shapes.append({"kind": "line", "points": [[0, ns.row], [ZB_WIDTH - 1, ns.row]]})
    return {"before": [], "steps": steps, "bounds": [0, 0, ZB_WIDTH - 1, ZB_HEIGHT - 1],
            "shapes": shapes, "handles": []}


def _inbetweens(table: Table, ns: argparse.Namespace, where: Where) -> View:
    """Time across (the key frames' interval :data:`TIME_CELLS` cells wide), frame
    number up: the key frames at the corners, each in-between's point, its tick on
    the time line (ticks before it plotted) and the drop from point to tick."""
    scale = TIME_CELLS / (ns.t2 - ns.t1)
    steps: list[dict[str, Any]] = []
    for r in table.rows:
        x, j = (r["t"] - ns.t1) * scale, r["j"]
        steps.append({"pixels": [[round(x), 0]], "mark": [[x, j], [x, 0]],
                      "areas": [[[[x, 0], [x, j]], "current"]],
                      "rule": f"in-between {j}: {ns.spacing}({r['j/(n+1)']:.4g}) = "
                              f"{r['eased']:.4g}, t = {r['t']:.6g}, {r['dt']:.4g} after the "
                              "frame before"})
    curve = [[0, 0]] + [[(r["t"] - ns.t1) * scale, r["j"]] for r in table.rows]
    curve.append([TIME_CELLS, len(table.rows) + 1])
    return {"before": [], "steps": steps, "bounds": [0, 0, TIME_CELLS, len(table.rows) + 1],
            "shapes": [{"kind": "line", "points": curve},
                       {"kind": "line", "points": [[0, 0], [TIME_CELLS, 0]]}], "handles": []}


def _morph_equalize(table: MorphTable, ns: argparse.Namespace, where: Where) -> View:
    """Both key frames; at each step the vertex pair joined (this step's color) and
    the in-between vertex's pixel, those before plotted; at the last, the
    in-between polygon."""
    steps: list[dict[str, Any]] = []
    for r in table.rows:
        a, b = [r["ax"], r["ay"]], [r["bx"], r["by"]]
        new = {"A": " (added to A)", "B": " (added to B)", "-": ""}[r["added"]]
        steps.append({"pixels": [[round(r["x"]), round(r["y"])]], "mark": [a, b],
                      "areas": [[[a, b], "current"]],
                      "rule": f"vertex {r['k']}{new}: A ({r['ax']:.4g}, {r['ay']:.4g}), B "
                              f"({r['bx']:.4g}, {r['by']:.4g}); at t = {ns.t:g}: "
                              f"({r['x']:.4g}, {r['y']:.4g})"})
    steps[-1]["areas"].append([[[r["x"], r["y"]] for r in table.rows], "result"])
    points = [p for shape in table.shapes for p in shape]
    return {"before": [], "steps": steps,
            "bounds": [math.floor(min(p[0] for p in points)), math.floor(min(p[1] for p in points)),
                       math.ceil(max(p[0] for p in points)), math.ceil(max(p[1] for p in points))],
            "shapes": [{"kind": "polygon", "points": s} for s in table.shapes], "handles": []}


def _table_only(table: Table, ns: argparse.Namespace, where: Where) -> View:
    """An algorithm with no grid view yet: its table, stepped row by row."""
    return {"before": [], "steps": [{"rule": ""} for _ in table.rows], "bounds": [0, 0, 10, 10],
            "shapes": [], "handles": []}


#: The view of each algorithm; its table is the Table subclass that algorithm's tracer
#: returns (chosen by the same name), hence Any for the first argument.
_VIEWS: dict[str, Callable[[Any, argparse.Namespace, Where], View]] = {
          "bresenham": _lines, "dda": _lines, "midpoint-circle": _conics,
          "midpoint-ellipse": _conics, "flood-fill": _fills, "boundary-fill": _fills,
          "scan-line-fill": _scan_fill, "cohen-sutherland": _line_clip,
          "liang-barsky": _line_clip, "cyrus-beck": _line_clip,
          "sutherland-hodgman": _polygon_clip, "de-casteljau": _casteljau,
          "cox-de-boor": _cox_de_boor, "cohen-sutherland-3d": _clip3d,
          "liang-barsky-3d": _clip3d, "z-buffer": _z_buffer, "depth-sort": _depth_sort,
          "floating-horizon": _floating_horizon, "ray-tracing": _ray_tracing,
          "back-face": _back_face, "gouraud": _shading, "phong": _shading,
          "bsp-tree": _bsp_tree, "warnock": _warnock,
          "scan-line-visible": _scan_line_visible, "ray-casting": _ray_casting,
          "inbetween-spacing": _inbetweens, "morph-equalize": _morph_equalize}


#: Estimated bytes that building, encoding and sending a view takes (measured with
#: tracemalloc on CPython 3.11, rounded up): per table row of the Cox-de Boor and
#: Cyrus-Beck views, per row of the conics (each lists its 4 or 8 pixels), per pixel of
#: the scan-line fill's bounding box (each step lists its pixels), per vertex that a
#: Sutherland-Hodgman step carries (the stage's polygon and the output so far), and per
#: column and grid point of the floating horizon.
ROW_BYTES, CONIC_ROW_BYTES, PIXEL_BYTES, VERTEX_BYTES = 1024, 4096, 256, 24
COLUMN_BYTES, GRID_POINT_BYTES = 64, 96


def _check(nbytes: float, argument: str, what: str, limit_bytes: float | None) -> None:
    """:func:`scanline.budget.check` against ``limit_bytes`` (the studio's limit per
    request), saying so in the message; ``None``: the package's own budget."""
    hint = "ask for a smaller case"
    if limit_bytes is None:
        return budget.check(nbytes, argument, what, hint=hint)
    try:
        budget.check(nbytes, argument, what, hint=hint, limit_bytes=limit_bytes)
    except MemoryBudgetError as error:
        first = str(error).split("; ", 1)[0]
        raise MemoryBudgetError(f"{first}; the studio takes at most {int(limit_bytes):,} bytes "
                                "per request: ask for a smaller case, or run scanline trace "
                                "on the command line") from None


def check_memory(ns: argparse.Namespace, limit_bytes: float | None = None) -> None:
    """Refuse (:class:`~scanline.errors.MemoryBudgetError`, naming the argument) a case
    whose view would take more than ``limit_bytes`` (default: the package's memory
    budget), estimated from its sizes before anything is computed.  Sizes the tracer
    itself refuses are left to it, so that its message is the command line's."""
    a = ns.algorithm
    if a == "floating-horizon":
        columns, grid = COLUMN_BYTES * ns.width, GRID_POINT_BYTES * ns.nx * ns.ny
        if columns >= grid:
            _check(columns + grid, "--width", f"a horizon {ns.width} columns wide", limit_bytes)
        else:
            _check(columns + grid, "--nx" if ns.nx >= ns.ny else "--ny",
                   f"a {ns.nx} x {ns.ny} grid", limit_bytes)
    elif a == "cox-de-boor":
        n, d = len(ns.knots), max(ns.order, 0)
        rows = min(d * (d + 1) // 2, n * d)
        if ROW_BYTES * rows >= COLUMN_BYTES * n:
            _check(ROW_BYTES * rows + COLUMN_BYTES * n, "--order",
                   f"order {d} (up to {rows:,} rows)", limit_bytes)
        else:
            _check(ROW_BYTES * rows + COLUMN_BYTES * n, "--knots", f"{n:,} knots", limit_bytes)
    elif a == "cyrus-beck" and ns.window_polygon:
        k = len(ns.window_polygon) // 2
        _check(ROW_BYTES * k, "--window-polygon", f"a window of {k:,} edges", limit_bytes)
    elif a == "sutherland-hodgman":
        n = len(ns.points)
        k = len(ns.window_polygon) // 2 if ns.window_polygon else 4
        nbytes = VERTEX_BYTES * k * n * 2 * n
        _check(nbytes, "--window-polygon" if k > n else "points",
               f"{n:,} vertices clipped by {k:,} boundaries", limit_bytes)
    elif a == "scan-line-fill" and ns.points:
        xs = [p[0] for p in ns.points if p]
        ys = [p[1] for p in ns.points if len(p) > 1]
        if xs and ys and all(math.isfinite(c) for c in xs + ys):
            w, h = max(xs) - min(xs) + 1, max(ys) - min(ys) + 1
            _check(PIXEL_BYTES * w * h, "points", f"a polygon of {w:g} x {h:g} pixels",
                   limit_bytes)
    elif a == "midpoint-circle" and 0 <= ns.r <= MAX_RADIUS:
        _check(CONIC_ROW_BYTES * ns.r * 0.71, "R", f"a circle of radius {ns.r}", limit_bytes)
    elif a == "midpoint-ellipse" and 0 <= ns.rx <= MAX_RADIUS and 0 <= ns.ry <= MAX_RADIUS:
        _check(CONIC_ROW_BYTES * (ns.rx + ns.ry), "RX" if ns.rx >= ns.ry else "RY",
               f"an ellipse of semi-axes {ns.rx} and {ns.ry}", limit_bytes)


def explore(algorithm: str, args: list[str], limit_bytes: float | None = None) -> dict[str, Any]:
    """The explorer's view of ``scanline trace ALGORITHM ARGS...``.

    Parameters
    ----------
    algorithm : str
        An algorithm of :func:`catalog`.
    args : list of str
        Its arguments, as on the command line.
    limit_bytes : float or None
        Refuse a case whose view would take more (:func:`check_memory`); None: the
        package's memory budget.

    Returns
    -------
    dict
        JSON-ready: the table (``title``, ``notes``, ``columns``, ``rows`` as lists in
        column order, ``count``), one step per row (``steps``; or, for the line
        algorithms, ``pixel_columns`` naming the columns that hold each row's pixel
        and ``rules``, rule templates filled from each row's columns and the template
        each row used), the static ``shapes``, the grid ``bounds``, the ``handles``
        and the ``command`` line.

    Raises
    ------
    BadArguments
        Arguments the command line refuses, a table over :data:`MAX_ROWS` rows.
    scanline.errors.MemoryBudgetError
        A case over ``limit_bytes``.

    Examples
    --------
    >>> view = explore("bresenham", ["0", "0", "3", "1"])
    >>> view["command"], view["count"]
    ('scanline trace bresenham 0 0 3 1', 3)
    """
    return view_of(parse(algorithm, args), limit_bytes)


def view_of(ns: argparse.Namespace, limit_bytes: float | None = None) -> dict[str, Any]:
    """The explorer's view of parsed arguments.

    Parameters
    ----------
    ns : argparse.Namespace
        Arguments as :func:`parse` returns them.
    limit_bytes : float or None
        As for :func:`explore`.

    Returns
    -------
    dict
        The view (see :func:`explore`).

    Raises
    ------
    BadArguments, scanline.errors.MemoryBudgetError
        As :func:`explore`.

    Examples
    --------
    >>> view_of(parse("dda", ["0", "0", "4", "2"]))["columns"]
    ['k', 'x_real', 'y_real', 'x', 'y']
    """
    check_memory(ns, limit_bytes)
    if ns.algorithm in ("midpoint-circle", "midpoint-ellipse") and ns.center is None:
        ns.center = [0, 0]
    table = table_of(ns)
    if len(table.rows) > MAX_ROWS:
        raise BadArguments(f"the table has {len(table.rows)} rows; the explorer shows at most "
                           f"{MAX_ROWS} (use scanline trace for longer ones)")
    tokens, where = canonical(ns)
    view = _VIEWS.get(ns.algorithm, _table_only)(table, ns, where)
    view.update({"algorithm": ns.algorithm, "args": tokens, "title": table.title,
                 "notes": table.notes, "columns": table.columns,
                 "rows": _cells(table),
                 "count": len(table.rows),
                 "command": shlex.join(["scanline", "trace", ns.algorithm, *tokens])})
    return view


def table_of(ns: argparse.Namespace) -> Table:
    """The step table of parsed arguments: ``scanline trace``'s own.

    Parameters
    ----------
    ns : argparse.Namespace
        Arguments as :func:`parse` returns them.

    Returns
    -------
    scanline.trace.table.Table
        The table :func:`scanline.cli.trace.table_of` builds (printed by
        ``scanline trace``).

    Examples
    --------
    >>> len(table_of(parse("dda", ["0", "0", "4", "2"])).rows)
    5
    """
    table: Table = cli_trace.table_of(ns)
    return table


def _cells(table: Table) -> list[list[Any]]:
    """The rows as lists in column order (a row lacking a column has None there)."""
    cols = table.columns
    get = operator.itemgetter(*cols)
    try:
        return [list(get(r)) for r in table.rows] if len(cols) > 1 else [[r[cols[0]]] for r in table.rows]
    except KeyError:
        return [[r.get(c) for c in cols] for r in table.rows]


def rows_of(view: View) -> list[dict[str, Any]]:
    """The table rows of a view as dicts keyed by the column names (the view sends
    them as lists, in column order)."""
    return [dict(zip(view["columns"], r)) for r in view["rows"]]
