"""Step tables of the animation chapter (notes, chapter 6; Hearn & Baker, section
16-5): the in-betweens of one pair of key frames spaced by a law of motion
(:func:`scanline.animation.inbetween_times`), and the equalization of two key-frame
shapes before a morph (:func:`scanline.animation.equalize`)."""

from typing import List, Optional

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from .table import Table

#: The explorer's time line: the key frames' interval drawn this many cells wide.
TIME_CELLS = 40

#: The default key-frame shapes of the morph: a triangle and a pentagon.
TRIANGLE = [2.0, 2.0, 18.0, 2.0, 10.0, 16.0]
PENTAGON = [26.5, 2.5, 35.5, 2.5, 38.0, 11.0, 31.0, 16.0, 24.0, 11.0]

#: The most vertices a morph's key frame may have (one row each after equalizing).
MAX_VERTICES = 1000

#: The most in-betweens a table lists (one row each).
MAX_INBETWEENS = 200


def inbetweens(n: int = 7, spacing: str = "accelerate", t1: float = 0.0,
               t2: float = 1.0) -> Table:
    """The ``n`` in-betweens between key frames at times ``t1`` and ``t2`` spaced by
    ``spacing`` (Hearn & Baker's ``constant``, ``accelerate``, ``decelerate``,
    ``accelerate-decelerate``, or any easing name): one row per in-between ``j``:
    ``j/(n+1)`` (its place in the frame sequence), ``eased`` (the fraction of the
    interval its time lies at: the law, or the easing, at j/(n+1)), its time ``t``
    (what :func:`~scanline.animation.inbetween_times` returns) and ``dt``, the gap
    from the frame before (the key frame at t1 for j = 1).

    Parameters
    ----------
    n : int
        The in-betweens, 1 .. :data:`MAX_INBETWEENS` (default 7).
    spacing : str
        The law of motion: "constant", "accelerate" (the default), "decelerate",
        "accelerate-decelerate", or an easing name of
        :mod:`scanline.animation.easing`.
    t1, t2 : float
        The key frames' times (default 0 and 1).

    Returns
    -------
    Table
        Columns j, j/(n+1), eased, t, dt, one row per in-between; the notes give the
        last gap, to the key frame at t2.

    Raises
    ------
    ArgumentTypeError
        ``t1`` or ``t2`` is not a number.
    ArgumentValueError
        ``n`` is not a count 1 .. :data:`MAX_INBETWEENS`, ``t2 - t1`` is not finite,
        or ``spacing`` names no law or easing.

    Examples
    --------
    Accelerating (1 - cos(u pi/2)): 1 - cos(22.5 deg) = 0.07612, 1 - cos(45 deg) =
    0.292893, 1 - cos(67.5 deg) = 0.617317, the gaps growing; constant spacing
    splits the interval evenly:

    >>> for r in inbetweens(3, "accelerate").rows:
    ...     print(r["j"], r["j/(n+1)"], r["t"], r["dt"])
    1 0.25 0.07612 0.07612
    2 0.5 0.292893 0.216773
    3 0.75 0.617317 0.324423
    >>> [r["t"] for r in inbetweens(3, "constant").rows]
    [0.25, 0.5, 0.75]
    """
    from ..animation import inbetween_times
    from ..animation.easing import ease

    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) \
            or not 1 <= n <= MAX_INBETWEENS:
        raise ArgumentValueError(f"n must be a count of in-betweens 1..{MAX_INBETWEENS}, got "
                                 f"{v._show(n)}")
    t1, t2 = v.number("t1", t1), v.number("t2", t2)
    if not np.isfinite(t2 - t1):
        raise ArgumentValueError(f"t2 - t1 must be finite, got t1={t1:g}, t2={t2:g}: bring the "
                                 "key frames' times closer together")
    times = inbetween_times(t1, t2, int(n), spacing)
    u = np.arange(1, n + 1) / (n + 1)
    eased = np.atleast_1d(ease(spacing, u))
    rows, before = [], float(t1)
    for j in range(n):
        t = float(times[j])
        rows.append({"j": j + 1, "j/(n+1)": round(float(u[j]), 6),
                     "eased": round(float(eased[j]), 6), "t": round(t, 6),
                     "dt": round(t - before, 6)})
        before = t
    notes = [f"key frames at t1 = {t1:g} and t2 = {t2:g}, {n} in-betweens, spacing "
             f"{spacing!r}", "t_j = t1 + (t2 - t1) * spacing(j / (n + 1)) (Hearn & Baker "
             "16-5: constant t; accelerate 1 - cos(t pi/2); decelerate sin(t pi/2); "
             "accelerate-decelerate (1 - cos(t pi)) / 2)",
             f"last gap, to the key frame at t2: {float(t2) - before:.6g}"]
    return Table(f"in-betweens spaced {spacing!r}", ["j", "j/(n+1)", "eased", "t", "dt"],
                 rows, notes)


class MorphTable(Table):
    """The table of :func:`morph_equalize`, with the two key-frame shapes."""

    #: The key frames A and B as given, [x, y] per vertex (before equalizing).
    shapes: List[List[List[float]]]


def _vertices(name: str, flat: ArrayLike) -> NDArray[np.float64]:
    a = v.real_array(name, flat, "(2 V,)")
    if a.ndim != 1 or len(a) % 2 or not 6 <= len(a) <= 2 * MAX_VERTICES \
            or not np.isfinite(a).all():
        raise ArgumentValueError(f"{name} must be finite x,y pairs of 3..{MAX_VERTICES} "
                                 f"vertices, got {v._show(flat)}")
    with np.errstate(over="ignore"):
        spread = np.ptp(a)
    if not np.isfinite(spread):
        raise ArgumentValueError(f"{name}'s coordinates must differ by a finite amount (their "
                                 "differences overflow floats): bring them closer together")
    return a.reshape(-1, 2)


def morph_equalize(a: Optional[ArrayLike] = None, b: Optional[ArrayLike] = None,
                   t: float = 0.5) -> "MorphTable":
    """Hearn & Baker's equalization of two key-frame polygons (section 16-5): the
    shape with fewer edges (L_min) gets N_e = L_max mod L_min of its edges divided
    into N_s + 1 sections and the others into N_s (N_s = int(L_max / L_min)), then
    corresponding vertices are interpolated.  One row per vertex pair ``k``: the
    vertex of shape A (``ax, ay``) and of B (``bx, by``) after equalizing, which
    shape had it ``added`` (``A``, ``B`` or ``-``), and the in-between vertex at
    fraction ``t`` (``x, y``: :func:`~scanline.animation.morph`).  ``a`` and ``b``:
    flat x, y lists (default a triangle and a pentagon).

    Parameters
    ----------
    a, b : array_like, optional
        The key frames as flat lists x0, y0, x1, y1, ... of 3 .. :data:`MAX_VERTICES`
        vertices (default :data:`TRIANGLE` and :data:`PENTAGON`).
    t : float
        The fraction of the in-between shown, 0 .. 1 (default 0.5).

    Returns
    -------
    MorphTable
        Columns k, ax, ay, bx, by, added, x, y, one row per vertex pair; its
        ``shapes`` attribute holds the two key frames as given.

    Raises
    ------
    ArgumentTypeError
        ``a``, ``b`` or ``t`` is not numeric.
    ArgumentValueError
        A key frame is not finite x, y pairs of 3 .. :data:`MAX_VERTICES` vertices,
        or ``t`` is outside 0 .. 1.

    Examples
    --------
    The triangle (2, 2), (18, 2), (10, 16) and the pentagon: L_max = 5, L_min = 3,
    N_s = 1 and N_e = 2, so the triangle's two longest edges (the slanted ones, of
    length sqrt(260) against 16) get their midpoints (14, 9) and (6, 9); half way,
    the added vertex (14, 9) and the pentagon's (38, 11) meet at (26, 10):

    >>> for r in morph_equalize().rows:
    ...     print(r["k"], (r["ax"], r["ay"]), (r["bx"], r["by"]), r["added"], (r["x"], r["y"]))
    0 (2.0, 2.0) (26.5, 2.5) - (14.25, 2.25)
    1 (18.0, 2.0) (35.5, 2.5) - (26.75, 2.25)
    2 (14.0, 9.0) (38.0, 11.0) A (26.0, 10.0)
    3 (10.0, 16.0) (31.0, 16.0) - (20.5, 16.0)
    4 (6.0, 9.0) (24.0, 11.0) A (15.0, 10.0)
    """
    from ..animation import equalization, equalize, morph

    sa = _vertices("a", TRIANGLE if a is None else a)
    sb = _vertices("b", PENTAGON if b is None else b)
    t = v.number("t", t)
    if not 0 <= t <= 1:
        raise ArgumentValueError(f"t must be a fraction 0..1, got {t:g}")
    ea, eb, added_a, added_b = equalize(sa, sb, return_added=True)
    between = morph(sa, sb, t)
    rows = []
    for k in range(len(ea)):
        rows.append({"k": k, "ax": float(ea[k, 0]), "ay": float(ea[k, 1]),
                     "bx": float(eb[k, 0]), "by": float(eb[k, 1]),
                     "added": "A" if added_a[k] else "B" if added_b[k] else "-",
                     "x": round(float(between[k, 0]), 6), "y": round(float(between[k, 1]), 6)})
    c = equalization(len(sa), len(sb))
    notes = [f"A: {len(sa)} vertices, B: {len(sb)} vertices (closed polygons)",
             f"L_max = {c.edges_max}, L_min = {c.edges_min}: N_e = L_max mod L_min = {c.n_e} "
             f"edge(s) divided into N_s + 1 = {c.n_s + 1} sections, the other "
             f"{c.edges_min - c.n_e} into N_s = {c.n_s} (the longest edges take the extra)",
             f"in-between at t = {t:g}: (1 - t) A + t B per vertex pair"]
    table = MorphTable(f"morph: equalizing {len(sa)} and {len(sb)} vertices",
                  ["k", "ax", "ay", "bx", "by", "added", "x", "y"], rows, notes)
    table.shapes = [sa.tolist(), sb.tolist()]
    return table
