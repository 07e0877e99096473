"""Step tables of the midpoint circle and ellipse (notes, chapter 2, Q.4-Q.6)."""

from typing import Any, Dict, List, Optional, Set, Tuple, Union

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from .._kernels import conics as k
from .._kernels._jit import python
from ..draw.conics import _check_ellipse
from .._typing import Point
from .table import Table

MAX_RADIUS = 100_000
_REGIONS = {k.REGION_1: "1", k.REGION_2: "2", k.TIP: "tip"}


def _center(center: Optional[Point]) -> Tuple[int, int]:
    if center is None:
        return 0, 0
    try:
        xc, yc = center
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"center must be a pair (xc, yc), got {center!r}") from None
    return v.coordinate("center x", xc), v.coordinate("center y", yc)


def _add_screen_columns(columns: List[str], rows: List[Dict[str, Any]],
                        center: Optional[Point], xc: int, yc: int) -> List[str]:
    """With an explicit center, add the plotted pixel (xc + x, yc + y) to each row."""
    if center is None:
        return columns
    for row in rows:
        row["xc+x"], row["yc+y"] = xc + row["x"], yc + row["y"]
    return columns + ["xc+x", "yc+y"]


def _mirror4(xc: int, yc: int, a: int, b: int) -> Set[Tuple[int, int]]:
    return {(xc + a, yc + b), (xc - a, yc + b), (xc + a, yc - b), (xc - a, yc - b)}


def _radius(name: str, r: float) -> int:
    radius = v.radius(name, r)
    if radius > MAX_RADIUS:
        raise ArgumentValueError(f"{name}={radius}: a trace lists every step; use {name} <= {MAX_RADIUS}")
    return radius


def _quarters(value: int) -> Union[int, float]:
    """A decision parameter kept times 4, as the notes' exact value."""
    return value // 4 if value % 4 == 0 else value / 4


def midpoint_circle(r: float, center: Optional[Point] = None) -> Table:
    """The midpoint circle algorithm step by step: k, p_k, the point
    (x_k+1, y_k+1) of the octant from (0, r) to the diagonal, and 2x_k+1, 2y_k+1.

    ``center=(xc, yc)`` adds the plotted pixel (xc + x, yc + y) to each row; the
    other seven octants follow by symmetry.

    Parameters
    ----------
    r : float
        The radius in pixels, rounded to an int in [0, `MAX_RADIUS`].
    center : (float, float), optional
        The center (xc, yc) in device pixels, rounded to pixels; None (the default)
        traces about (0, 0) without the screen columns.

    Returns
    -------
    Table
        Columns k, p, x, y, 2x, 2y (and xc+x, yc+y with a center), one row per step;
        ``pixels()`` holds all eight octants.

    Raises
    ------
    TypeError
        If `r` is not a real number or `center` is not a pair of them.
    ValueError
        If `r` is negative or above `MAX_RADIUS`, or the center is out of range.

    Examples
    --------
    >>> t = midpoint_circle(10)
    >>> [(r["p"], r["x"], r["y"]) for r in t.rows]
    [(-9, 1, 10), (-6, 2, 10), (-1, 3, 10), (6, 4, 9), (-3, 5, 9), (8, 6, 8), (5, 7, 7)]
    """
    r = _radius("r", r)
    xc, yc = _center(center)
    out = np.zeros((int(r) + 1, 3), np.int64)
    n = python(k.circle_trace)(r, out)
    rows = [{"k": i, "p": p, "x": x, "y": y, "2x": 2 * x, "2y": 2 * y}
            for i, (p, x, y) in enumerate(out[:n].tolist())]
    columns = _add_screen_columns(["k", "p", "x", "y", "2x", "2y"], rows, center, xc, yc)
    pixels = set()
    for x, y in [(0, r)] + [(row["x"], row["y"]) for row in rows]:
        pixels |= _mirror4(xc, yc, x, y) | _mirror4(xc, yc, y, x)
    notes = [
        f"start at (x0, y0) = (0, {r}), p0 = 1 - r = {1 - r}, 2x0 = 0, 2y0 = {2 * r}",
        "p_k < 0: next point (x_k + 1, y_k), p_k+1 = p_k + 2x_k+1 + 1;",
        "otherwise (x_k + 1, y_k - 1), p_k+1 = p_k + 2x_k+1 + 1 - 2y_k+1; stop when x >= y",
        f"eight-way symmetry about the center ({xc}, {yc}) gives the other octants",
    ]
    return Table(f"Midpoint circle r = {r}, center ({xc}, {yc})", columns, rows, notes, pixels)


def midpoint_ellipse(rx: float, ry: float, center: Optional[Point] = None) -> Table:
    """The midpoint ellipse algorithm step by step, both regions: region, k, p1_k or
    p2_k, the point (x_k+1, y_k+1), 2 r_y^2 x_k+1 and 2 r_x^2 y_k+1.

    ``k`` restarts at 0 in region 2, as in the notes.  Rows of region ``"tip"``
    complete a very flat ellipse along y = 0 (see :func:`scanline.draw.ellipse`).

    Parameters
    ----------
    rx, ry : float
        The semi-axes along x and y in pixels, each rounded to an int in
        [0, `MAX_RADIUS`].
    center : (float, float), optional
        The center (xc, yc) in device pixels, rounded to pixels; None (the default)
        traces about (0, 0) without the screen columns.

    Returns
    -------
    Table
        Columns region, k, p, x, y, 2ry2x, 2rx2y (and xc+x, yc+y with a center);
        ``pixels()`` holds all four quadrants.

    Raises
    ------
    TypeError
        If a radius is not a real number or `center` is not a pair of them.
    ValueError
        If a radius is negative or too large for exact 64-bit decision parameters,
        or the center is out of range.

    Examples
    --------
    >>> t = midpoint_ellipse(8, 6)
    >>> [(r["region"], r["p"], r["x"], r["y"]) for r in t.rows]  # doctest: +NORMALIZE_WHITESPACE
    [('1', -332, 1, 6), ('1', -224, 2, 6), ('1', -44, 3, 6), ('1', 208, 4, 5),
     ('1', -108, 5, 5), ('1', 288, 6, 4), ('1', 244, 7, 3),
     ('2', -23, 8, 2), ('2', 361, 8, 1), ('2', 297, 8, 0)]
    """
    rx = _radius("rx", rx)
    ry = _radius("ry", ry)
    _check_ellipse(rx, ry)
    xc, yc = _center(center)
    out = np.zeros((int(rx + ry) + 1, 6), np.int64)
    n = python(k.ellipse_trace)(rx, ry, out)
    columns = ["region", "k", "p", "x", "y", "2ry2x", "2rx2y"]
    rows = []
    counter: Dict[str, int] = {}
    for region, p4, x, y, px, py in out[:n].tolist():
        name = _REGIONS[region]
        i = counter.get(name, 0)
        counter[name] = i + 1
        rows.append({"region": name, "k": i, "p": None if name == "tip" else _quarters(p4),
                     "x": x, "y": y, "2ry2x": px, "2rx2y": py})
    columns = _add_screen_columns(columns, rows, center, xc, yc)
    pixels = set()
    for x, y in [(0, ry)] + [(row["x"], row["y"]) for row in rows]:
        pixels |= _mirror4(xc, yc, x, y)
    p10 = _quarters(4 * ry * ry - 4 * rx * rx * ry + rx * rx)
    notes = [
        f"r_x^2 = {rx * rx}, r_y^2 = {ry * ry}, 2r_x^2 = {2 * rx * rx}, 2r_y^2 = {2 * ry * ry}",
        f"region 1 starts at (0, {ry}): p1_0 = r_y^2 - r_x^2 r_y + r_x^2/4 = {p10}; "
        "p1_k < 0 keeps y, otherwise y - 1; it ends when 2r_y^2 x >= 2r_x^2 y",
        "region 2 starts at region 1's last point: p2_0 = r_y^2 (x + 1/2)^2 + r_x^2 (y - 1)^2 "
        "- r_x^2 r_y^2; p2_k > 0 keeps x, otherwise x + 1; it ends at y = 0",
        f"four-way symmetry about the center ({xc}, {yc}) gives the other quadrants",
    ]
    return Table(f"Midpoint ellipse r_x = {rx}, r_y = {ry}, center ({xc}, {yc})",
                 columns, rows, notes, pixels)
