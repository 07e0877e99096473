"""Step tables of depth sorting and the floating horizon: each comes from the code
that draws (the depth sort's own log; the horizon kernel's helpers run as Python
through :func:`scanline._kernels._jit.python`)."""

from typing import Any, Dict, List, Literal, Optional

import numpy as np

from .. import _validate as v
from .table import Table

#: Built-in depth-sort scenes (device-space polygons on a 40 x 30 device).
SCENES = {
    "painter": [  # a long tilted quad in front of a small one at one end only
        [[2, 10, 0.1], [38, 10, 0.9], [38, 20, 0.9], [2, 20, 0.1]],
        [[5, 5, 0.5], [12, 5, 0.5], [12, 25, 0.5], [5, 25, 0.5]]],
    "cyclic": [   # three sticks, each over the next
        [[2, 4, 0.3], [36, 4, 0.7], [36, 10, 0.7], [2, 10, 0.3]],
        [[30, 0, 0.3], [36, 4, 0.3], [14, 28, 0.7], [8, 24, 0.7]],
        [[4, 14, 0.7], [10, 8, 0.7], [30, 28, 0.3], [24, 30, 0.34]]],
    "intersecting": [  # two quads piercing each other
        [[2, 2, 0.2], [30, 2, 0.8], [30, 20, 0.8], [2, 20, 0.2]],
        [[5, 5, 0.8], [35, 5, 0.2], [35, 25, 0.2], [5, 25, 0.8]]],
}


def depth_sort(scene: Literal["painter", "cyclic", "intersecting"] = "cyclic",
               split_cycles: bool = True) -> Table:
    """The depth sort of a built-in scene (:data:`SCENES`): one row per pair
    examined, the outcome of each of the five tests tried, and the action taken
    (Hearn & Baker, section 13-6).

    Parameters
    ----------
    scene : {"painter", "cyclic", "intersecting"}
        The scene (default "cyclic": three sticks, each over the next).
    split_cycles : bool
        Split a polygon where the tests find a cycle (default True), as
        :func:`scanline.visible.depth_sort` does.

    Returns
    -------
    Table
        Columns S, S', test 1 .. test 5 ("yes" where a test settles the pair, "no",
        or empty where it was not tried) and action; the notes give the polygons,
        the tests and the drawing order.

    Raises
    ------
    ArgumentValueError
        ``scene`` is not one of :data:`SCENES`.

    References
    ----------
    M. E. Newell, R. G. Newell and T. L. Sancha, "A solution to the hidden surface
    problem", Proceedings of the ACM Annual Conference, 1972.

    Examples
    --------
    The painter scene: polygon 0, tilted from depth 0.1 to 0.9, has the greatest
    depth and comes first; polygon 1 (depth 0.5, inside its x and y extents) lies
    behind its plane at every vertex, so no test passes and 1 moves ahead; then
    test 3 finds 1 behind 0's plane, and 1 is drawn first:

    >>> t = depth_sort("painter")
    >>> for r in t.rows:
    ...     print(r["S"], r["S'"], [r[f"test {k}"] for k in range(1, 6)], r["action"])
    0 1 ['no', 'no', 'no', 'no', 'no'] move 1 to the head (flag it)
    1 0 ['no', 'no', 'yes', None, None] none
    >>> t.notes[-1]
    'drawing order (faces): 1 0'
    """
    from ..visible import TESTS, ScreenPolygons
    from ..visible import depth_sort as sort

    v.choice("scene", scene, tuple(SCENES))
    polys = [np.array(p, float) for p in SCENES[scene]]
    sp = ScreenPolygons.from_device(polys, 40, 30)
    log: List[Dict[str, Any]] = []
    out = sort(sp, split_cycles=split_cycles, log=log)
    notes = [f"polygon {i}: " + " ".join(f"({x:g}, {y:g}, {z:g})" for x, y, z in p.tolist())
             for i, p in enumerate(polys)]
    notes.append("tests: " + "; ".join(f"{k + 1} {t}" for k, t in enumerate(TESTS)))
    notes.append("drawing order (faces): " + " ".join(str(f) for f in out.face.tolist()))
    columns = ["S", "S'"] + [f"test {k + 1}" for k in range(5)] + ["action"]
    rows = [dict({"S": r["S"], "S'": r["S'"], "action": r["action"]},
                 **{f"test {k + 1}": r.get(t) for k, t in enumerate(TESTS)}) for r in log]
    return Table(f"depth sort of the {scene!r} scene", columns, rows, notes)


def floating_horizon(nx: int = 6, ny: int = 4, width: int = 24, height: int = 16) -> Table:
    """The floating horizon of z = sin(2x) cos(2y) on an ``nx`` x ``ny`` grid drawn
    on a ``width`` x ``height`` device: per curve (nearest first) and column, the
    curve's y, the horizons before, the visibility and the horizons after (Rogers,
    section 4-2).

    Parameters
    ----------
    nx, ny : int
        Grid points along x and y (at least 2; default 6 x 4); the curves are the
        grid's rows.
    width, height : int
        The device in pixels (at least 4; default 24 x 16).

    Returns
    -------
    Table
        Columns curve, column, y, upper before, lower before, visible ("above",
        "below" or "hidden"), upper after, lower after: one row per column each
        curve spans, curves nearest first; an empty horizon reads None.

    Raises
    ------
    ArgumentTypeError
        A size is not an integer.
    ArgumentValueError
        ``nx`` or ``ny`` below 2, ``width`` or ``height`` below 4.

    References
    ----------
    D. F. Rogers, "Procedural Elements for Computer Graphics", section 4-2 (the
    floating horizon); Hearn & Baker, section 13-10 (curved surfaces).

    Examples
    --------
    The nearest curve is seen everywhere and becomes both horizons; the next one,
    above the upper horizon at column 3, is seen and raises it:

    >>> t = floating_horizon(2, 2, 8, 8)
    >>> [(r["curve"], r["column"], r["visible"]) for r in t.rows[:5]]
    [(0, 1, 'above'), (0, 2, 'above'), (0, 3, 'above'), (0, 4, 'above'), (1, 3, 'above')]
    >>> r = t.rows[4]
    >>> r["upper before"] < r["y"] == r["upper after"], r["lower after"] == r["lower before"]
    (True, True)
    """
    from .._kernels import horizon as k
    from .._kernels._jit import python
    from ..draw3d.horizon import _camera, _grid, horizon_runs

    nx = v.positive_int("nx", nx, 2)
    ny = v.positive_int("ny", ny, 2)
    w = v.positive_int("width", width, 4)
    h = v.positive_int("height", height, 4)
    xs, ys, zz = _grid(lambda x, y: np.sin(2 * x) * np.cos(2 * y), np.linspace(-1, 1, nx),
                       np.linspace(-1, 1, ny))
    cam = _camera((0.5, 0.5), xs, ys, zz)
    gx, gy = np.meshgrid(xs, ys)
    pts = cam.project(np.stack([gx, gy, zz], -1).reshape(-1, 3), w, h).reshape(ny, nx, 3)
    groups, runs, ylo, yhi, order = horizon_runs(pts)
    upper, lower = np.full(w, -np.inf), np.full(w, np.inf)
    segs = np.empty((4 * len(ylo) + 16, 4))
    state = np.full(w, 2, np.int8)
    t = np.empty(2)
    visibility = python(k.run_visibility)
    group = python(k.horizon_group)
    rows = []
    n = 0
    for g in range(len(groups) - 1):
        r = groups[g + 1] - 1
        c0, count, s = runs[r]
        state[:] = 2
        visibility(c0, count, ylo[s:], yhi[s:], upper, lower, state)
        before = upper.copy(), lower.copy()
        n = group(g, groups, runs, ylo, yhi, upper, lower, np.empty(w), np.empty(w), segs,
                  n, t)
        for c in range(max(c0, 0), min(c0 + count, w)):
            rows.append({"curve": int(order[g]), "column": c, "y": float(yhi[s + c - c0]),
                         "upper before": _finite(before[0][c]),
                         "lower before": _finite(before[1][c]),
                         "visible": {1: "above", -1: "below", 0: "hidden"}[int(state[c])],
                         "upper after": _finite(upper[c]), "lower after": _finite(lower[c])})
    notes = [f"z = sin(2x) cos(2y), {nx} x {ny} grid, azimuth 0.5, elevation 0.5 rad, "
             f"{w} x {h} device", f"{n} visible segments drawn; curves nearest first"]
    return Table("floating horizon", ["curve", "column", "y", "upper before", "lower before",
                                      "visible", "upper after", "lower after"], rows, notes)


def _finite(x: float) -> Optional[float]:
    return None if not np.isfinite(x) else float(x)
