"""Scan-line spans of a fill area, as strokes for a vector device.

A random-scan display cannot paint pixels; it fills an area by stroking it (notes,
chapter 1, Q.3-Q.4).  :func:`spans` gives the horizontal strokes that cover exactly
the pixels the raster scan-line fill sets (the same sampling: scan line y crosses an
edge when ylo < y <= yhi, at ``xlo + (y - ylo) (xhi - xlo) / (yhi - ylo)``, and a span
covers the pixel centers ceil(xleft) <= x < ceil(xright)); :func:`hatch` strokes
parallel lines at any angle and spacing through the area.
"""

import math

import numpy as np


def _edges(contours):
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


def _runs(keys, dirs, rule):
    """Pairs (start, end) of the inside runs between sorted crossing keys."""
    order = np.argsort(keys, kind="stable")
    keys, dirs = keys[order], dirs[order]
    if rule == "even-odd":
        inside = (np.arange(1, len(keys) + 1) % 2) == 1
    else:
        inside = np.cumsum(dirs) != 0
    out = []
    for i in np.flatnonzero(inside[:-1]):
        if keys[i] < keys[i + 1]:
            out.append((keys[i], keys[i + 1]))
    return out


def spans(contours, rule, ymin=None, ymax=None):
    """Horizontal strokes (N, 4) rows (x0, y, x1, y), x0 <= x1, covering the pixel
    centers the scan-line fill covers; scan lines limited to [ymin, ymax] if given."""
    e = _edges(contours)
    if len(e) == 0:
        return np.zeros((0, 4))
    y0 = math.floor(e[:, 1].min()) + 1
    y1 = math.floor(e[:, 3].max())
    if ymin is not None:
        y0, y1 = max(y0, math.ceil(ymin)), min(y1, math.floor(ymax))
    out = []
    for y in range(y0, y1 + 1):
        act = e[(e[:, 1] < y) & (y <= e[:, 3])]
        if len(act) < 2:
            continue
        xc = act[:, 0] + ((y - act[:, 1]) * (act[:, 2] - act[:, 0])) / (act[:, 3] - act[:, 1])
        for a, b in _runs(np.ceil(xc), act[:, 4], rule):
            out.append((a, y, b - 1, y))
    return np.array(out, np.float64).reshape(-1, 4)


def hatch(contours, rule, angle, spacing):
    """Strokes (N, 4) at ``angle`` radians, ``spacing`` apart (lines through the
    origin's family), clipped to the inside of the area: exact chords, not pixels."""
    c, s = math.cos(angle), math.sin(angle)
    to_local = np.array([[c, s], [-s, c]])  # rotate by -angle: hatch lines horizontal
    local = [p @ to_local.T for p in contours]
    e = _edges(local)
    if len(e) == 0:
        return np.zeros((0, 4))
    k0 = math.floor(e[:, 1].min() / spacing) + 1
    k1 = math.floor(e[:, 3].max() / spacing)
    out = []
    for k in range(k0, k1 + 1):
        y = k * spacing
        act = e[(e[:, 1] < y) & (y <= e[:, 3])]
        xc = act[:, 0] + ((y - act[:, 1]) * (act[:, 2] - act[:, 0])) / (act[:, 3] - act[:, 1])
        out.extend((a, y, b, y) for a, b in _runs(xc, act[:, 4], rule))
    if not out:
        return np.zeros((0, 4))
    seg = np.array(out, np.float64)
    back = to_local.T
    p0, p1 = seg[:, :2] @ back.T, seg[:, 2:] @ back.T
    return np.hstack([p0, p1])
