"""Drawing runs of similar primitives in one go.

A display file often holds many primitives with the same attributes in a row: thin
solid polylines of one color, solid polygons of one color and rule.  The
interpreter hands such a run here: the geometry is mapped by one matrix product,
clipped by one batch call of :mod:`scanline.clip` (Liang-Barsky or Cyrus-Beck on all
segments, Sutherland-Hodgman on all polygons) and drawn by one device call
(``segments`` / ``areas`` when the device has them; ``stroke`` / ``fill`` otherwise).
The pixels are those of drawing the primitives one by one.
"""

from typing import Any, Literal, Optional, Sequence, cast

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .. import clip
from . import pipeline
from .pipeline import Window
from .primitives import Primitive

#: What a run of primitives shares: ("lines", color, clip) or ("areas", color, rule,
#: clip); None for a primitive drawn on its own.
Key = Optional[tuple[Any, ...]]
#: What a batch drew (the point arrays, for the highlight frame), and the index of a
#: primitive beyond the coordinate limit (then nothing was drawn) or None.
Drawn = tuple[list[NDArray[np.float64]], Optional[int]]


def key(prim: Primitive) -> Key:
    """What a run shares, or None for a primitive drawn on its own."""
    a = prim.attributes
    if prim.kind == "polyline" and a["style"].width <= 1 and a["style"].solid:
        return ("lines", a["color"], prim.clip)
    if (prim.kind == "polygon" and a["style"] is None and a["edge"] is None
            and len(prim.geometry["contours"]) == 1):
        return ("areas", a["color"], a["rule"], prim.clip)
    return None


def runs(primitives: Sequence[Primitive]) -> list[tuple[int, Sequence[Primitive], Key]]:
    """(first index, primitives, key) for each run of consecutive equal keys."""
    out: list[tuple[int, Sequence[Primitive], Key]] = []
    start = 0
    keys = [key(p) for p in primitives]
    for i in range(1, len(primitives) + 1):
        if i == len(primitives) or keys[i] is None or keys[i] != keys[start]:
            out.append((start, primitives[start:i], keys[start]))
            start = i
    return out


def _mapped(points: NDArray[np.float64], m: NDArray[np.float64]) -> NDArray[np.float64]:
    with np.errstate(all="ignore"):  # overflow -> inf, refused below
        out: NDArray[np.float64] = points @ m[:2, :2].T + m[:2, 2]
    return out


def _first_out_of_range(points: NDArray[np.float64], owner: NDArray[np.int64]
                        ) -> Optional[int]:
    """The index (in ``owner``) of the first point beyond the coordinate limit."""
    bad = ~(np.abs(points) <= v.COORD_LIMIT).all(axis=1)
    return int(owner[np.argmax(bad)]) if bad.any() else None


def lines(prims: Sequence[Primitive], m: NDArray[np.float64], rect: Window,
          device: Any) -> Drawn:
    """Thin solid polylines of one color; returns (drawn points, index of a primitive
    out of range or None)."""
    pieces: list[NDArray[np.float64]] = []
    owner: list[NDArray[np.int64]] = []
    for i, p in enumerate(prims):
        pts = p.geometry["points"]
        ring = np.vstack([pts, pts[:1]]) if p.attributes["closed"] and len(pts) > 2 else pts
        if len(ring) == 1:
            ring = np.vstack([ring, ring])
        pieces.append(np.hstack([ring[:-1], ring[1:]]))
        owner.append(np.full(len(ring) - 1, i, np.int64))
    segs = np.vstack(pieces)
    ends = _mapped(segs.reshape(-1, 2), m)
    bad = _first_out_of_range(ends, np.repeat(np.concatenate(owner), 2))
    if bad is not None:
        return [], bad
    segs = ends.reshape(-1, 4)
    if not pipeline.inside(ends, rect).all():
        method: Literal["liang-barsky", "cyrus-beck"] = (
            "liang-barsky" if isinstance(rect, tuple) else "cyrus-beck")
        segs, ok = clip.lines(segs, rect, method=method)
        segs = segs[ok]
    if len(segs):
        attributes = {**prims[0].attributes, "closed": False}
        if hasattr(device, "segments"):
            device.segments(segs, attributes)
        else:
            device.stroke([s.reshape(2, 2) for s in segs], False, attributes)
    return [segs.reshape(-1, 2)], None


def _areas_of(polys: NDArray[np.float64], offsets: NDArray[np.int64]) -> NDArray[np.float64]:
    """Shoelace areas of polygons stored one after another (offsets: starts, end)."""
    x, y = polys[:, 0], polys[:, 1]
    idx = np.arange(len(polys))
    start = np.repeat(offsets[:-1], np.diff(offsets))
    end = np.repeat(offsets[1:], np.diff(offsets))
    nxt = np.where(idx + 1 == end, start, idx + 1)
    return 0.5 * np.add.reduceat(x * y[nxt] - x[nxt] * y, offsets[:-1])


def areas(prims: Sequence[Primitive], m: NDArray[np.float64], rect: Window,
          device: Any) -> Drawn:
    """Solid one-contour polygons of one color and rule; returns (drawn contours,
    index of a primitive out of range or None)."""
    contours = [p.geometry["contours"][0] for p in prims]
    sizes = np.array([len(c) for c in contours])
    offsets = np.concatenate([[0], np.cumsum(sizes)])
    verts = _mapped(np.vstack(contours), m)
    bad = _first_out_of_range(verts, np.repeat(np.arange(len(prims)), sizes))
    if bad is not None:
        return [], bad
    keep = _areas_of(verts, offsets) != 0.0  # a zero-area polygon fills nothing
    inside = np.logical_and.reduceat(pipeline.inside(verts, rect), offsets[:-1])
    pieces = np.split(verts, offsets[1:-1])
    cut = [i for i in range(len(pieces)) if keep[i] and not inside[i]]
    # without counts, clip.polygons returns the list of clipped polygons
    polygons = cast("list[NDArray[np.float64]]", clip.polygons([pieces[i] for i in cut], rect)
                    if cut else [])
    clipped = dict(zip(cut, polygons))
    out: list[NDArray[np.float64]] = [clipped.get(i, pieces[i]) for i in range(len(pieces))
                                      if keep[i]]
    out = [c for c in out if len(c) >= 3]
    if out:
        if hasattr(device, "areas"):
            device.areas(out, prims[0].attributes)
        else:
            for c in out:
                device.fill([c], prims[0].attributes)
    return out, None
