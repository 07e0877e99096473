"""Any finite coordinate drawn: geometry reaching beyond the exact integer range is
clipped in floating point against a *guard rectangle* before the kernels see it.

The drawing kernels are exact for coordinates within +-2**30
(:data:`scanline._validate.COORD_LIMIT`).  A primitive with a vertex beyond that
(a projection near the eye plane, a plot's far-away point) is first clipped to the
guard square [-GUARD, GUARD]**2: Sutherland-Hodgman (1974) for areas, whose result
has the same winding number as the original at every point inside the guard (so
both fill rules keep their meaning there), Liang-Barsky (1984) for strokes and lines,
which are cut where they leave the guard.  The guard lies at least 2**28 pixels
beyond any frame buffer scanline writes (the largest image is far smaller), so the
cuts, caps and joins it introduces are never visible.  Geometry within the exact
range is passed on unchanged, so everything drawn before is drawn exactly as before.

Crossings are computed in float64 when the edge's coordinates are within
:data:`EXACT_FROM` (an error below 2**-14 pixel) and as exact rationals beyond (the
float formula would lose the line's position: with vertices at 1e300 its rounding
error is 1e284), then rounded once to the nearest float.

References
----------
I. E. Sutherland, G. W. Hodgman, "Reentrant polygon clipping", CACM 17(1), 32-42, 1974.
Y.-D. Liang, B. A. Barsky, "A new concept and method for line clipping", ACM TOG 3(1),
1-22, 1984.  Hearn & Baker, sections 6-7 (line clipping) and 6-8 (polygon clipping).
"""

import numbers
from fractions import Fraction
from typing import TYPE_CHECKING, Union, cast

import numpy as np
from numpy.typing import NDArray

from .._validate import COORD_LIMIT

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer

#: An exact number of any size.
Exact = Union[int, Fraction]

#: Half side of the guard square (device pixels).
GUARD = float(2**29)

#: Edges with a coordinate beyond this magnitude get exact crossings.
EXACT_FROM = float(2**36)

#: The four sides of the guard: (axis, sign) keeps sign * p[axis] <= GUARD.
_SIDES = ((0, 1.0), (0, -1.0), (1, 1.0), (1, -1.0))


def far(verts: NDArray[np.float64]) -> bool:
    """Whether any vertex of the (N, 2) array lies beyond the exact range."""
    return bool(verts.size > 0 and not np.abs(verts).max() <= COORD_LIMIT)


def _cross(a: NDArray[np.float64], b: NDArray[np.float64], axis: int, bound: float) -> NDArray[np.float64]:
    """The points where the segments a[i]-b[i] (rows (x, y, ...)) meet the line
    p[axis] = bound (each segment crosses it); columns after the first two (values
    linear along the segment, such as depths) are interpolated at the same point."""
    o = 1 - axis
    out = np.empty_like(a)
    with np.errstate(all="ignore"):
        t = (bound - a[:, axis]) / (b[:, axis] - a[:, axis])
    big = np.flatnonzero(np.maximum(np.abs(a[:, :2]).max(axis=1),
                                    np.abs(b[:, :2]).max(axis=1)) > EXACT_FROM)
    exact: dict[int, float] = {}
    for i in big.tolist():
        ai, bi = a[i, :2].tolist(), b[i, :2].tolist()
        r = (Fraction(bound) - Fraction(ai[axis])) / (Fraction(bi[axis]) - Fraction(ai[axis]))
        t[i] = float(r)
        exact[i] = float(Fraction(ai[o]) + r * (Fraction(bi[o]) - Fraction(ai[o])))
    with np.errstate(all="ignore"):
        out[:] = a + t[:, None] * (b - a)
    out[:, axis] = bound
    for i, value in exact.items():
        out[i, o] = value
    return out


def ring(points: NDArray[np.float64]) -> NDArray[np.float64]:
    """The (N, 2) closed contour ``points`` clipped to the guard square
    (Sutherland-Hodgman, one side after another); may come back empty.  Columns
    after the first two are carried along, interpolated where an edge is cut."""
    p = points
    for axis, sign in _SIDES:
        if len(p) == 0:
            break
        inside = sign * p[:, axis] <= GUARD
        if inside.all():
            continue
        prev = np.roll(p, 1, axis=0)
        prev_in = np.roll(inside, 1)
        crossing = inside != prev_in
        cut = np.zeros_like(p)
        cut[crossing] = _cross(prev[crossing], p[crossing], axis, sign * GUARD)
        # each vertex emits [the crossing of the edge reaching it] + [itself if inside]
        pair = np.stack([cut, p], axis=1).reshape(-1, p.shape[1])
        keep = np.stack([crossing, inside], axis=1).reshape(-1)
        p = pair[keep]
    return np.ascontiguousarray(p, np.float64)


def triangles(rows: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Far triangles clipped to the guard square and cut again into triangles:
    ``rows`` (N, 3, K) per vertex x, y and K - 2 values linear on the screen (depth,
    1/w, attributes times 1/w).  Returns ``(rows, owner)``: the pieces (M, 3, K), a
    fan of each clipped triangle (their shared edges inside it, so each pixel is
    still covered once), and the triangle each comes from."""
    out: list[NDArray[np.float64]] = []
    owner: list[int] = []
    for i in range(len(rows)):
        r = ring(rows[i])
        for j in range(1, len(r) - 1):
            out.append(np.stack([r[0], r[j], r[j + 1]]))
            owner.append(i)
    shape = (0,) + rows.shape[1:]
    return (np.array(out, np.float64).reshape(-1, *rows.shape[1:]) if out else np.empty(shape),
            np.array(owner, np.int64))


def areas(verts: NDArray[np.float64], offsets: NDArray[np.int64], polys: NDArray[np.int64]) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]:
    """Clip every contour of a batch of areas (:func:`scanline.geometry.contours.batch`
    form) that reaches beyond the exact range; contours left empty are dropped.
    Returns new ``(verts, offsets, polys)`` (the same arrays when nothing is far)."""
    if not far(verts):
        return verts, offsets, polys
    rings: list[NDArray[np.float64]] = []
    counts = np.zeros(len(polys) - 1, np.int64)
    for p in range(len(polys) - 1):
        for c in range(polys[p], polys[p + 1]):
            r = verts[offsets[c]:offsets[c + 1]]
            if far(r):
                r = ring(r)
            if len(r):
                rings.append(r)
                counts[p] += 1
    new_offsets = np.zeros(len(rings) + 1, np.int64)
    new_offsets[1:] = np.cumsum([len(r) for r in rings])
    new_polys = np.zeros(len(polys), np.int64)
    new_polys[1:] = np.cumsum(counts)
    new_verts = np.concatenate(rings) if rings else np.empty((0, 2), np.float64)
    return np.ascontiguousarray(new_verts), new_offsets, new_polys


def segments(segs: NDArray[np.float64]) -> NDArray[np.float64]:
    """Liang-Barsky: the (N, 4) segments (x0, y0, x1, y1) clipped to the guard
    square; a segment outside it becomes the point (-GUARD, -GUARD), outside every
    frame buffer (so rows keep their colors); rows within the exact range are
    unchanged (the same array when no row is far)."""
    if not far(segs.reshape(-1, 2)):
        return segs
    out: NDArray[np.float64] = segs.copy()
    for i in np.flatnonzero(np.abs(segs).max(axis=1) > COORD_LIMIT).tolist():
        piece = _clip_segment(segs[i])
        out[i] = (-GUARD, -GUARD, -GUARD, -GUARD) if piece is None else piece
    return out


def _clip_segment(s: NDArray[np.float64]) -> NDArray[np.float64] | None:
    """One float segment clipped to the guard (:func:`clip_segment`), or None."""
    return clip_segment(*(Fraction(c) for c in s.tolist()))


def clip_parameters(x0: Exact, y0: Exact, x1: Exact, y1: Exact,
                    box: tuple[Exact, Exact, Exact, Exact]) -> tuple[Fraction, Fraction] | None:
    """Liang-Barsky in exact arithmetic: the parameters ``(t0, t1)`` (Fractions) of
    the part of the segment (x0, y0) + t (x1 - x0, y1 - y0), 0 <= t <= 1, inside
    ``box`` = (xmin, ymin, xmax, ymax), all exact numbers of any size (ints,
    Fractions), or None when it misses the box."""
    dx, dy = x1 - x0, y1 - y0
    xmin, ymin, xmax, ymax = box
    t0, t1 = Fraction(0), Fraction(1)
    for p, q in ((-dx, x0 - xmin), (dx, xmax - x0), (-dy, y0 - ymin), (dy, ymax - y0)):
        if p == 0:
            if q < 0:
                return None
            continue
        r = Fraction(q) / p
        if p < 0:
            t0 = max(t0, r)
        else:
            t1 = min(t1, r)
        if t0 > t1:
            return None
    return t0, t1


def clip_segment(x0: Exact, y0: Exact, x1: Exact, y1: Exact) -> NDArray[np.float64] | None:
    """The segment (x0, y0)-(x1, y1), exact numbers of any size (ints, Fractions),
    clipped to the guard with exact parameters (:func:`clip_parameters`) and rounded
    once to floats: an array (x0, y0, x1, y1), or None when it misses the guard."""
    g = Fraction(GUARD)
    t = clip_parameters(x0, y0, x1, y1, (-g, -g, g, g))
    if t is None:
        return None
    (t0, t1), dx, dy = t, x1 - x0, y1 - y0
    return np.array([float(x0 + t0 * dx), float(y0 + t0 * dy), float(x0 + t1 * dx),
                     float(y0 + t1 * dy)])


def _clipped(segs: NDArray[np.float64]) -> NDArray[np.float64]:
    """The segments (rows x0, y0, x1, y1) clipped to the guard, in order, those that
    miss it left out: a segment within the guard is kept as it is and one wholly
    beyond a side of it dropped (both as :func:`_clip_segment` gives them, without
    its exact arithmetic: a circle of radius 2**30 has 230,000 of them); only the
    segments that cross the guard's boundary are clipped exactly."""
    inside = (np.abs(segs) <= GUARD).all(axis=1)
    beyond = np.zeros(len(segs), bool)
    for c in (0, 1):
        beyond |= (segs[:, c] > GUARD) & (segs[:, c + 2] > GUARD)
        beyond |= (segs[:, c] < -GUARD) & (segs[:, c + 2] < -GUARD)
    pieces: NDArray[np.float64] = segs.copy()
    keep = inside.copy()
    for j in np.flatnonzero(~inside & ~beyond).tolist():
        piece = _clip_segment(segs[j])
        if piece is not None:
            pieces[j], keep[j] = piece, True
    kept: NDArray[np.float64] = pieces[keep]
    return kept


def _runs(segs: NDArray[np.float64]) -> list[NDArray[np.float64]]:
    """Consecutive segments joined into polylines (a new one wherever a segment does
    not start where the previous one ended)."""
    if not len(segs):
        return []
    starts = np.flatnonzero((segs[1:, :2] != segs[:-1, 2:]).any(axis=1)) + 1
    bounds = [0] + starts.tolist() + [len(segs)]
    return [np.vstack([segs[a:b, :2], segs[b - 1:b, 2:]]) for a, b in zip(bounds, bounds[1:])]


def paths(verts: NDArray[np.float64], offsets: NDArray[np.int64], closed: NDArray[np.bool_]
          ) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.bool_], NDArray[np.int64]]:
    """Polylines (``closed[i]``: joined back to their start) cut where they leave the
    guard square: each far polyline becomes the open runs of its segments' clipped
    parts.  Returns ``(verts, offsets, closed, owner)``, ``owner[j]`` the polyline
    piece j comes from (the same arrays and ``arange`` when nothing is far)."""
    n = len(offsets) - 1
    if not far(verts):
        return verts, offsets, closed, np.arange(n)
    out: list[NDArray[np.float64]] = []
    flags: list[bool] = []
    owner: list[int] = []
    for i in range(n):
        p = verts[offsets[i]:offsets[i + 1]]
        if not far(p):
            out.append(p)
            flags.append(bool(closed[i]))
            owner.append(i)
            continue
        if closed[i] and len(p) > 2:
            p = np.vstack([p, p[:1]])
        if len(p) == 1:
            continue          # a single far point: outside the guard, nothing to draw
        for run in _runs(_clipped(np.hstack([p[:-1], p[1:]]))):
            out.append(run)
            flags.append(False)
            owner.append(i)
    new_offsets = np.zeros(len(out) + 1, np.int64)
    new_offsets[1:] = np.cumsum([len(r) for r in out])
    new_verts = np.concatenate(out) if out else np.empty((0, 2), np.float64)
    return (np.ascontiguousarray(new_verts, np.float64), new_offsets,
            np.array(flags, bool), np.array(owner, np.int64))


def conic_outside(fb: "FrameBuffer", xc: object, yc: object, rx: object, ry: object,
                  reach: float = 1.0, fill: bool = False) -> bool:
    """Whether the axis-aligned ellipse (or circle, rx = ry) about (xc, yc), its
    outline widened by ``reach`` pixels (or its interior with ``fill``), certainly
    misses the frame buffer ``fb``, for a conic beyond the kernels' exact limits
    (an off-screen ellipse at x = 1e9 with ry = 1e8 is then simply not drawn).

    Exact for the ellipse itself, conservative for the widened outline: the
    d-offsets of the ellipse lie between the ellipses of semi-axes (rx - d, ry - d)
    and (rx + d, ry + d).  Scaling x by 1/a and y by 1/b makes an ellipse the unit
    circle and the frame's rectangle another rectangle: the ellipse misses it when
    its nearest point is beyond 1 (outside) or, for an outline, its farthest corner
    within the inner ellipse (the frame inside the ring's hole).  Anything that is
    not four finite reals gives False (the usual validation then answers)."""
    vals = (xc, yc, rx, ry)
    if not all(isinstance(c, numbers.Real) and not isinstance(c, (bool, np.bool_))
               for c in vals):
        return False
    try:
        x, y, a, b = (float(cast(numbers.Real, c)) for c in vals)
    except OverflowError:
        return False
    if not all(np.isfinite((x, y, a, b))) or a < -0.5 or b < -0.5:
        return False
    rows = [np.array([c], np.float64) for c in (x, y, a, b)]
    return bool(conics_outside(fb, rows[0], rows[1], rows[2], rows[3], reach, fill)[0])    # -0.5 < r < 0 rounds to 0


def conics_outside(fb: "FrameBuffer", xc: NDArray[np.float64], yc: NDArray[np.float64], rx: NDArray[np.float64], ry: NDArray[np.float64],
                   reach: float = 1.0, fill: bool = False) -> NDArray[np.bool_]:
    """:func:`conic_outside` for arrays of finite centers and radii >= -0.5 (a batch
    of conics): a bool array, True where the conic certainly misses ``fb``."""
    rx, ry = np.maximum(rx, 0.0), np.maximum(ry, 0.0)
    reach = max(float(reach), 1.0)
    # drawn pixel centers lie within 1 (the center and radii rounded) plus the
    # outline's half width of the ellipse: ``reach`` (>= 1) on the ellipse's side
    # and ``reach`` on the frame's cover both
    with np.errstate(all="ignore"):       # squares of huge ratios are inf: fine
        lo_x, hi_x = -reach - xc, fb.width - 1 + reach - xc
        lo_y, hi_y = -reach - yc, fb.height - 1 + reach - yc
        near_x = np.where((lo_x <= 0) & (0 <= hi_x), 0.0, np.minimum(abs(lo_x), abs(hi_x)))
        near_y = np.where((lo_y <= 0) & (0 <= hi_y), 0.0, np.minimum(abs(lo_y), abs(hi_y)))
        a, b = rx + reach, ry + reach
        out = (near_x / a) ** 2 + (near_y / b) ** 2 > 1.0 + 1e-9   # the frame outside
        if fill:
            return out
        a, b = rx - reach, ry - reach
        far_x = np.maximum(abs(lo_x), abs(hi_x))
        far_y = np.maximum(abs(lo_y), abs(hi_y))
        hole = (a > 0) & (b > 0) & ((far_x / a) ** 2 + (far_y / b) ** 2 < 1.0 - 1e-9)
    return out | hole
