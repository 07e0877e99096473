"""Scan-line spans of a fill area, as strokes for a vector device.

A random-scan display cannot paint pixels; it fills an area by stroking it (notes,
chapter 1, Q.3-Q.4).  :func:`spans` gives the horizontal strokes that cover exactly
the pixels the raster scan-line fill sets (the same sampling: scan line y crosses an
edge when ylo < y <= yhi, at ``xlo + (y - ylo) (xhi - xlo) / (yhi - ylo)``, and a span
covers the pixel centers ceil(xleft) <= x < ceil(xright)); :func:`hatch` strokes
parallel lines at any angle and spacing through the area.
"""

import math
from typing import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]


def _edges(contours: Sequence[F64]) -> F64:
    """(E, 5) rows xlo, ylo, xhi, yhi, direction (+1 up, -1 down), non-horizontal only."""
    rows = []
    for c in contours:
        a, b = c, np.roll(c, -1, axis=0)
        up = b[:, 1] > a[:, 1]
        lo = np.where(up[:, None], a, b)
        hi = np.where(up[:, None], b, a)
        keep = a[:, 1] != b[:, 1]
        rows.append(np.column_stack([lo, hi, np.where(up, 1.0, -1.0)])[keep])
    return np.vstack(rows) if rows else np.zeros((0, 5))


def _chords(edges: F64, spacing: float, rule: str, keys: Callable[[F64], F64]) -> F64:
    """The inside runs of the lines y = k * spacing: rows (x0, y, x1, y).

    Every edge crosses the lines with ylo < y <= yhi at
    ``xlo + (y - ylo) (xhi - xlo) / (yhi - ylo)``; ``keys`` maps those crossings to
    run ends (``np.ceil`` for pixel spans).  The crossings of each line, sorted, bound
    the runs that are inside by the fill rule: odd parity, or a nonzero sum of the
    edges' directions.  All lines at once, in numpy.
    """
    k0 = np.floor(edges[:, 1] / spacing) + 1
    k1 = np.floor(edges[:, 3] / spacing)
    count = np.maximum(k1 - k0 + 1, 0).astype(np.int64)
    if count.sum() == 0:
        return np.zeros((0, 4))
    e = np.repeat(np.arange(len(edges)), count)
    first = np.repeat(np.cumsum(count) - count, count)
    y = (np.repeat(k0, count) + (np.arange(len(e)) - first)) * spacing
    xlo, ylo, xhi, yhi, d = edges[e].T
    x = keys(xlo + ((y - ylo) * (xhi - xlo)) / (yhi - ylo))
    order = np.lexsort((x, y))
    x, y, d = x[order], y[order], d[order]
    same = y[1:] == y[:-1]  # crossing i and i + 1 lie on one line
    start = np.flatnonzero(np.concatenate([[True], ~same]))
    group = np.cumsum(np.concatenate([[True], ~same])) - 1
    if rule == "even-odd":
        inside = (np.arange(len(x)) - start[group]) % 2 == 0
    else:
        total = np.cumsum(d)
        inside = total - np.concatenate([[0.0], total])[start[group]] != 0
    run = same & inside[:-1] & (x[:-1] < x[1:])
    out: F64 = np.column_stack([x[:-1][run], y[:-1][run], x[1:][run], y[1:][run]])
    return out


def spans(contours: Sequence[F64], rule: str) -> F64:
    """Horizontal strokes (N, 4) rows (x0, y, x1, y), x0 <= x1, covering the pixel
    centers the scan-line fill covers."""
    e = _edges(contours)
    out = _chords(e, 1.0, rule, np.ceil)
    out[:, 2] -= 1.0  # a span ends before the next crossing's key
    return out


def hatch(contours: Sequence[F64], rule: str, angle: float, spacing: float) -> F64:
    """Strokes (N, 4) at ``angle`` radians, ``spacing`` apart (the family of lines
    through the origin), clipped to the inside of the area: exact chords, not pixels."""
    c, s = math.cos(angle), math.sin(angle)
    to_local = np.array([[c, s], [-s, c]])  # rotate by -angle: hatch lines horizontal
    seg = _chords(_edges([p @ to_local.T for p in contours]), float(spacing), rule,
                  lambda x: x)
    out: F64 = np.hstack([seg[:, :2] @ to_local, seg[:, 2:] @ to_local])
    return out
