"""Step tables of the line algorithms (notes, chapter 2, Q.1-Q.3)."""

from typing import Any, Dict, List, Tuple

import numpy as np

from .. import _validate as v
from ..errors import ArgumentValueError
from .._kernels import lines as k
from .._kernels._jit import python
from .table import Table

#: A trace lists every step; longer lines would print pages nobody reads.
MAX_STEPS = 100_000


def _endpoints(x0: float, y0: float, x1: float, y1: float) -> Tuple[List[int], int]:
    pts = [v.coordinate(n, c) for n, c in (("x0", x0), ("y0", y0), ("x1", x1), ("y1", y1))]
    steps = max(abs(pts[2] - pts[0]), abs(pts[3] - pts[1]))
    if steps > MAX_STEPS:
        raise ArgumentValueError(
            f"the line from ({pts[0]}, {pts[1]}) to ({pts[2]}, {pts[3]}) has {steps} steps; "
            f"a trace lists at most {MAX_STEPS}"
        )
    return pts, steps


def bresenham(x0: float, y0: float, x1: float, y1: float) -> Table:
    """Bresenham's line algorithm step by step: the notes' table of k, p_k and the
    pixel (x_k+1, y_k+1), plus the increment added to p_k.

    The start pixel is plotted before step k = 0.  Lines with |slope| > 1 step along
    y from the lower endpoint (x and y swap roles); the table still shows device x, y.

    Parameters
    ----------
    x0, y0 : float
        The first endpoint in device pixels, rounded to the nearest pixel (halves up).
    x1, y1 : float
        The second endpoint, rounded likewise.

    Returns
    -------
    Table
        Columns k, p, x, y, increment, one row per step; ``pixels()`` includes
        the start pixel.

    Raises
    ------
    TypeError
        If a coordinate is not a real number.
    ValueError
        If a coordinate is outside the supported range, or the line has more than
        `MAX_STEPS` steps.

    Examples
    --------

    >>> t = bresenham(20, 10, 30, 18)
    >>> [(r["k"], r["p"], r["x"], r["y"]) for r in t.rows[:3]]
    [(0, 6, 21, 11), (1, 2, 22, 12), (2, -2, 23, 12)]
    """
    (x0, y0, x1, y1), steps = _endpoints(x0, y0, x1, y1)
    out = np.zeros((steps, 4), np.int64)
    swap, u0, w0, du, dw, sw = python(k.bresenham_trace)(x0, y0, x1, y1, out)
    start = (w0, u0) if swap else (u0, w0)
    a, b = ("y", "x") if swap else ("x", "y")
    rows = [
        {"k": i, "p": int(p), "x": int(x), "y": int(y), "increment": int(inc)}
        for i, (p, x, y, inc) in enumerate(out.tolist())
    ]
    notes = [
        f"major axis {a} (|d{b}| {'<' if swap else '<='} |d{a}|), stepping from "
        f"({start[0]}, {start[1]}); {b} moves by {sw:+d} when it moves",
        f"d{a} = {du}, d{b} = {dw}, 2d{b} = {2 * dw}, 2d{b} - 2d{a} = {2 * dw - 2 * du}, "
        f"p0 = 2d{b} - d{a} = {2 * dw - du}",
        f"plot the start pixel ({start[0]}, {start[1]}); then at each k: p_k < 0 keeps {b} "
        f"and adds 2d{b}, otherwise {b} moves and p adds 2d{b} - 2d{a}",
    ]
    pixels = [start] + [(r["x"], r["y"]) for r in rows]
    return Table(f"Bresenham line ({x0}, {y0}) -> ({x1}, {y1})",
                 ["k", "p", "x", "y", "increment"], rows, notes, pixels)


def dda(x0: float, y0: float, x1: float, y1: float) -> Table:
    """The DDA step by step: at each k the real x and y (x_k+1 = x_k + dx/steps,
    y_k+1 = y_k + dy/steps, accumulated in floating point) and the pixel they round
    to.  Row k = 0 is the first endpoint.

    Parameters
    ----------
    x0, y0 : float
        The first endpoint in device pixels, rounded to the nearest pixel (halves up).
    x1, y1 : float
        The second endpoint, rounded likewise.

    Returns
    -------
    Table
        Columns k, x_real, y_real, x, y, one row per step and k = 0.

    Raises
    ------
    TypeError
        If a coordinate is not a real number.
    ValueError
        If a coordinate is outside the supported range, or the line has more than
        `MAX_STEPS` steps.

    Examples
    --------

    >>> t = dda(0, 0, 4, 2)
    >>> [(r["x_real"], r["y_real"], r["x"], r["y"]) for r in t.rows]
    [(0.0, 0.0, 0, 0), (1.0, 0.5, 1, 1), (2.0, 1.0, 2, 1), (3.0, 1.5, 3, 2), (4.0, 2.0, 4, 2)]
    """
    (x0, y0, x1, y1), steps = _endpoints(x0, y0, x1, y1)
    out = np.zeros((steps + 1, 4), np.float64)
    steps, xinc, yinc = python(k.dda_trace)(x0, y0, x1, y1, out)
    rows: List[Dict[str, Any]] = [
        {"k": i, "x_real": xr, "y_real": yr, "x": int(px), "y": int(py)}
        for i, (xr, yr, px, py) in enumerate(out.tolist())
    ]
    notes = [
        f"dx = {x1 - x0}, dy = {y1 - y0}, steps = max(|dx|, |dy|) = {steps}, "
        f"x increment = {xinc:g}, y increment = {yinc:g}",
        "each pixel is (round(x), round(y)) with round(v) = floor(v + 0.5)",
    ]
    pixels = [(r["x"], r["y"]) for r in rows]
    return Table(f"DDA line ({x0}, {y0}) -> ({x1}, {y1})",
                 ["k", "x_real", "y_real", "x", "y"], rows, notes, pixels)
