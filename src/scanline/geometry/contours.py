"""Polygons as flat arrays: every vertex in one (V, 2) float64 array, and offsets
saying where each contour (and, for a batch, each polygon) starts.

A *polygon* is one contour, an (N, 2) array-like of vertices (closed implicitly: the
last vertex joins the first), or several contours: a list of such arrays or an
(C, N, 2) array (an outer boundary and its holes, or any overlapping rings; the fill
rule decides what is inside).
"""

from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._validate import COORD_LIMIT, _show
from .._validate import counts as index_counts
from ..errors import ArgumentTypeError, ArgumentValueError


def _numeric(name: str, a: NDArray[Any]) -> NDArray[np.float64]:
    if a.dtype == bool or a.dtype.kind not in "iuf":
        raise ArgumentTypeError(
            f"{name} must hold real numbers (vertex coordinates), got an array of dtype "
            f"{a.dtype}"
        )
    return a.astype(np.float64, copy=False)


def _ring(name: str, value: object) -> NDArray[np.float64]:
    """One contour as a float64 (N, 2) array."""
    try:
        a = np.asarray(value)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"{name} must be an (N, 2) array of vertices, got {_show(value)}"
        ) from None
    if a.size == 0:
        return np.empty((0, 2), np.float64)
    if a.ndim != 2 or a.shape[1] != 2:
        raise ArgumentValueError(
            f"{name} must be an (N, 2) array of vertices (x, y), got shape {a.shape}"
        )
    return _numeric(name, a)


def check_vertices(name: str, verts: NDArray[np.float64],
                   offsets: NDArray[np.int64] | None = None, far: bool = False) -> None:
    """Raise naming ``name`` unless every vertex is finite and within +-2**30 (any
    finite value with ``far``: the drawing functions clip such geometry to a guard
    rectangle, :mod:`scanline.geometry.guard`).

    With ``offsets`` (where each part starts), the message names the part:
    ``name[p]``."""
    if verts.size == 0:
        return
    lo, hi = verts.min(), verts.max()   # NaN propagates: one fast test for the usual case
    limit = np.inf if far else COORD_LIMIT
    if -limit <= lo and hi <= limit and not (far and (np.isinf(lo) or np.isinf(hi))):
        return
    for bad, what in ((~np.isfinite(verts).all(axis=1), "must be finite"),
                      ((np.abs(verts) > limit).any(axis=1),
                       f"must be within the supported coordinate range [-{COORD_LIMIT}, "
                       f"{COORD_LIMIT}] (what lies beyond the frame buffer is clipped "
                       "anyway)")):
        if bad.any():
            i = int(np.argmax(bad))
            where, j = name, i
            if offsets is not None:
                p = int(np.searchsorted(offsets, i, side="right")) - 1
                where, j = f"{name}[{p}]", i - int(offsets[p])
            raise ArgumentValueError(f"{where} {what}; vertex {j} is {verts[i].tolist()}")


def contours(name: str, value: object,
             far: bool = False) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Parse a polygon given as one contour or several.

    Returns ``(verts, offsets)``: contour ``c`` is ``verts[offsets[c]:offsets[c+1]]``.
    """
    rings: list[NDArray[np.float64]] = []
    multiple = False
    a: NDArray[Any] | None
    if isinstance(value, np.ndarray):
        a = value
    else:
        try:
            a = np.asarray(value)
        except (TypeError, ValueError):  # ragged: a list of contours
            a = None
            if not isinstance(value, (list, tuple)):
                raise ArgumentTypeError(
                    f"{name} must be an (N, 2) array of vertices or a list of such arrays, "
                    f"got {_show(value)}"
                ) from None
            rings = [_ring(f"{name}[{i}]", r) for i, r in enumerate(value)]
            multiple = True
    if a is not None:
        if a.dtype == object and isinstance(value, (list, tuple)):
            rings = [_ring(f"{name}[{i}]", r) for i, r in enumerate(value)]
            multiple = True
        elif a.ndim == 0:
            raise ArgumentTypeError(
                f"{name} must be an (N, 2) array of vertices or a list of such arrays, "
                f"got {_show(value)}"
            )
        elif a.size == 0:
            rings = []
        elif a.ndim == 2 and a.shape[1] == 2:
            rings = [_numeric(name, a)]
        elif a.ndim == 3 and a.shape[2] == 2:
            a = _numeric(name, a)
            verts = np.ascontiguousarray(a.reshape(-1, 2))
            offsets = np.arange(0, verts.shape[0] + 1, a.shape[1], dtype=np.int64)
            check_vertices(name, verts, offsets, far)
            return verts, offsets
        else:
            raise ArgumentValueError(
                f"{name} must be an (N, 2) array of vertices (x, y), a list of such "
                f"arrays or a (C, N, 2) array of contours; got shape {a.shape}"
            )
    offsets = np.zeros(len(rings) + 1, np.int64)
    offsets[1:] = np.cumsum([len(r) for r in rings])
    verts = (np.ascontiguousarray(np.concatenate(rings), dtype=np.float64) if rings
             else np.empty((0, 2), np.float64))
    check_vertices(name, verts, offsets if multiple else None, far)
    return verts, offsets


def batch(name: str, value: object, far: bool = False
          ) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]:
    """Parse a batch of polygons: a list of polygons (each one contour or several,
    as :func:`contours` takes) or an (M, K, 2) array of M one-contour polygons.

    Returns ``(verts, contour_offsets, polygon_offsets)``: polygon ``p`` is made of
    contours ``polygon_offsets[p] .. polygon_offsets[p + 1] - 1``.
    """
    if isinstance(value, np.ndarray) and value.ndim == 3 and value.shape[2] == 2:
        a = _numeric(name, value)
        m, k = a.shape[0], a.shape[1]
        verts = np.ascontiguousarray(a.reshape(-1, 2))
        offsets = np.arange(m + 1, dtype=np.int64) * k
        check_vertices(name, verts, offsets, far)
        return verts, offsets, np.arange(m + 1, dtype=np.int64)
    if isinstance(value, np.ndarray) and value.size == 0:
        value = []
    if not isinstance(value, (list, tuple)):
        raise ArgumentTypeError(
            f"{name} must be a list of polygons ((N, 2) arrays of vertices) or an "
            f"(M, K, 2) array, got {_show(value)}"
        )
    joined: NDArray[Any] | None
    try:  # the fast path: one contour per polygon, (N_i, 2) array-likes
        joined = np.concatenate(value) if len(value) else np.empty((0, 2), np.float64)
    except (TypeError, ValueError):
        joined = None
    if joined is not None and joined.ndim == 2 and joined.shape[1] == 2:
        m = len(value)
        offsets = np.zeros(m + 1, np.int64)
        offsets[1:] = np.cumsum(np.fromiter(map(len, value), np.int64, m))
        verts = np.ascontiguousarray(_numeric(name, joined))
        check_vertices(name, verts, offsets, far)
        return verts, offsets, np.arange(m + 1, dtype=np.int64)
    parts = [contours(f"{name}[{i}]", p, far) for i, p in enumerate(value)]
    polys = np.zeros(len(parts) + 1, np.int64)
    polys[1:] = np.cumsum([len(off) - 1 for _, off in parts])
    offs = [np.zeros(1, np.int64)]
    base = 0
    for verts, off in parts:
        offs.append(off[1:] + base)
        base += len(verts)
    verts = (np.ascontiguousarray(np.concatenate([v for v, _ in parts]))
             if parts else np.empty((0, 2), np.float64))
    return verts, np.concatenate(offs), polys


def flat(name: str, vertices: object, counts: object, far: bool = False
         ) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]:
    """Parse a batch given flat: all vertices in one (V, 2) array and the vertex
    count of each polygon (one contour each) in ``counts``, so that numpy data needs
    no per-polygon conversion.

    Returns ``(verts, contour_offsets, polygon_offsets)`` like :func:`batch`.
    """
    try:
        verts = np.asarray(vertices)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"{name} must be a (V, 2) array of vertices when counts "
                                f"is given, got {_show(vertices)}") from None
    verts = np.ascontiguousarray(_numeric(name, verts))
    if verts.ndim != 2 or verts.shape[1] != 2:
        raise ArgumentValueError(f"{name} must be a (V, 2) array of vertices when counts is "
                                 f"given, got shape {verts.shape}")
    c, offsets = index_counts("counts", counts, verts.shape[0], name)
    check_vertices(name, verts, offsets, far)
    return verts, offsets, np.arange(c.size + 1, dtype=np.int64)
