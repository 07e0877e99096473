"""Circles and ellipses beyond the kernels' exact limits: any finite center and radius.

The conic kernels are exact for centers within +-2**30, circles of radius up to
2**30 and ellipses with r_x r_y <= 2**29 (r_x, r_y <= 2**24).  A conic beyond them
that can touch the frame buffer is drawn here (one that cannot is dropped first by
:func:`scanline.geometry.guard.conics_outside`):

* width-1 outlines and filled areas: the notes' midpoint pixels and spans, computed
  exactly in Python integers for the visible columns and rows only
  (:mod:`scanline.geometry.far_conics`), so they are the pixels the kernels would
  draw given unlimited integers, written by the curved-area kernel (each pixel a
  degenerate ellipse, each span a flat one);
* thick, pen-drawn and antialiased ones: the ideal conic sampled exactly near the
  frame (:func:`scanline.geometry.far_conics.local_runs`) and stroked or filled
  by the same polygon paths as everything else.

Everything here costs O(width + height) per conic, whatever its radius.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import TYPE_CHECKING, Any, Callable, Literal, Optional, Sequence, Union, cast, overload

import numpy as np
from numpy.typing import NDArray

from .._kernels import curved as kcurved
from .._kernels import linetype as kl
from .._kernels._jit import call
from .._kernels.variants import layout, token
from ..color.spec import Channels
from ..geometry import far_conics as fc
from ..geometry.guard import conics_outside
from . import _blend
from ._common import colors, target

if TYPE_CHECKING:
    from .._typing import Color, Colors
    from ..attributes import FillStyle
    from ..framebuffer import FrameBuffer
    from ..linestyle import LineStyle
    from ._area import Outline

#: One primitive's color spec taken from a batch's colors (:func:`spec`).
Spec = Optional["Color"]
#: A region of the curved-area kernels: two half-planes (nx, ny, c, tie) and how they
#: combine (``BOTH`` or ``EITHER``); integers of any size for a far conic.
HalfPlanes = Union[NDArray[np.int64], Sequence[tuple[int, int, int, int]]]
Region = tuple[HalfPlanes, int]
#: A run of the ideal conic near the frame: (polyline, closed, start point or None).
Run = tuple[NDArray[np.float64], bool, Optional[tuple[Fraction, Fraction]]]


def _frame(fb: FrameBuffer, margin: int = 0) -> fc.Window:
    return (-margin, -margin, fb.width - 1 + margin, fb.height - 1 + margin)


def _put(buf: NDArray[np.uint8], packed: bool, width: int, height: int, rows: NDArray[np.int64],
         value: NDArray[np.uint8], ox: int = 0, oy: int = 0) -> None:
    """Write rows (x, y, half, 0): the spans x - half .. x + half of row y (a
    degenerate ellipse each), shifted by (-ox, -oy)."""
    if len(rows) == 0:
        return
    rows = rows - np.array([ox, oy, 0, 0], np.int64)
    call(kcurved.fill_regions, float(len(rows) + 2 * rows[:, 2].clip(0, width).sum()), buf,
         layout(packed), width, height, rows, token(kcurved.ELLIPSE),
         np.ascontiguousarray(value, np.uint8).reshape(1, -1))


def pixels(xc: int, yc: int, rx: int, ry: int, circle: bool, window: fc.Window
           ) -> NDArray[np.int64]:
    """The midpoint outline's pixels inside ``window`` (an (N, 2) int64 array)."""
    if circle:
        return fc.circle_pixels(xc, yc, rx, window)
    return fc.ellipse_pixels(xc, yc, rx, ry, window)


def outline(fb: FrameBuffer, xc: int, yc: int, rx: int, ry: int, value: NDArray[np.uint8],
            circle: bool) -> None:
    """Draw the width-1 midpoint outline with the pixel value ``value``."""
    buf, packed, width, height = target(fb)
    p = pixels(xc, yc, rx, ry, circle, _frame(fb))
    rows = np.zeros((len(p), 4), np.int64)
    rows[:, :2] = p
    _put(buf, packed, width, height, rows, value)


def fill(fb: FrameBuffer, xc: int, yc: int, rx: int, ry: int, color: Optional[Color],
         style: Optional[FillStyle], circle: bool, hollow: Outline,
         region: Optional[Region] = None) -> None:
    """Fill the area bounded by the midpoint outline (spans from its left-most to
    its right-most pixel on each visible row) in ``style``, within the half-planes
    ``region`` (a pie or a chord: ``(hp, combine)`` as the curved-area kernels take
    them, their integers of any size);
    ``hollow`` draws the outline (the hollow style)."""
    s: list[tuple[int, int, int]] = []
    for row, y, w in fc.half_widths(yc, rx, ry, fb.height, circle):
        for lo, hi in _cut([(-w, w)], region, y):
            s += fc.clipped(row, xc + int(lo), xc + int(hi), fb.width)   # finite: ints
    if not s:
        return
    spans = np.array(s, np.int64)
    rows = np.stack([(spans[:, 1] + spans[:, 2]) // 2, spans[:, 0],
                     (spans[:, 2] - spans[:, 1]) // 2, np.zeros(len(spans), np.int64)], axis=1)
    bbox = (int(spans[:, 1].min()), int(spans[:, 0].min()), int(spans[:, 2].max()),
            int(spans[:, 0].max()))

    def draw(buf: NDArray[np.uint8], packed: bool, width: int, height: int, ox: int, oy: int,
             value: NDArray[np.uint8]) -> None:
        _put(buf, packed, width, height, rows, value, ox, oy)

    _blend.fill(fb, color, style, bbox, draw, hollow)


def arc(fb: FrameBuffer, xc: int, yc: int, rx: int, ry: int, region: Region,
        color: Optional[Color], circle: bool) -> None:
    """The midpoint outline's pixels whose polar angle is in the sector ``region``
    (``(hp, combine)``: the half-planes of the curved-area kernels)."""
    p = [(x, y) for x, y in pixels(xc, yc, rx, ry, circle, _frame(fb)).tolist()
         if _cut([(x - xc, x - xc)], region, y - yc)]
    if not p:
        return
    rows = np.zeros((len(p), 4), np.int64)
    rows[:, :2] = p
    lo, hi = rows[:, :2].min(axis=0), rows[:, :2].max(axis=0)

    def draw(buf: NDArray[np.uint8], packed: bool, width: int, height: int, ox: int, oy: int,
             value: NDArray[np.uint8]) -> None:
        _put(buf, packed, width, height, rows, value, ox, oy)

    _blend.paint(fb, color, (int(lo[0]), int(lo[1]), int(hi[0]), int(hi[1])), draw)


def _half_plane(nx: int, ny: int, c: int, tie: bool, y: int) -> tuple[float, float]:
    """The x-interval of row y where nx x + ny y + c > 0 (>= 0 with ``tie``), in
    integers of any size with unbounded ends (the kernels' ``half_plane`` rule,
    whose open end 2**62 would be too near for a far conic)."""
    k = ny * y + c
    if nx > 0:
        return (-(k // nx) if tie else (-k) // nx + 1), math.inf
    if nx < 0:
        return -math.inf, (k // -nx if tie else -((-k) // -nx) - 1)
    if k > 0 or (k == 0 and tie):
        return -math.inf, math.inf
    return math.inf, -math.inf


def _cut(runs: Sequence[tuple[int, int]], region: Optional[Region], y: int
         ) -> Sequence[tuple[float, float]]:
    """The parts of the runs (x-intervals of row y, relative to the center) inside
    ``region`` (None: everything), combined as ``region_spans`` combines them."""
    if region is None:
        return runs
    hp, combine = region
    (s0, e0), (s1, e1) = (_half_plane(int(h[0]), int(h[1]), int(h[2]), h[3] != 0, y) for h in hp)
    if combine == kcurved.BOTH:
        parts = [(max(s0, s1), min(e0, e1))]
    elif s0 > e0:
        parts = [(s1, e1)]
    elif s1 <= e1 and s1 <= e0 + 1 and s0 <= e1 + 1:      # touching: one interval
        parts = [(min(s0, s1), max(e0, e1))]
    else:
        parts = [(s0, e0), (s1, e1)]
    return [(max(a, s), min(b, e)) for a, b in runs for s, e in parts if max(a, s) <= min(b, e)]


def _runs(fb: FrameBuffer, xc: int, yc: int, rx: int, ry: int, margin: int) -> Sequence[Run]:
    """The ideal conic within ``margin`` pixels of the frame: a list of
    (polyline, closed, start) (:func:`scanline.geometry.far_conics.local_runs`;
    a degenerate conic is its segment, clipped by the guard, start None)."""
    if rx == 0 or ry == 0:
        return [(np.array([[xc - rx, yc - ry], [xc + rx, yc + ry]], np.float64), True, None)]
    return fc.local_runs(xc, yc, rx, ry, _frame(fb, margin))


def _packed(runs: Sequence[Union[Run, tuple[NDArray[np.float64], bool]]]
            ) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.bool_]]:
    """Polylines ``(verts, offsets, closed)`` for :func:`scanline.draw.strokes.stroke`."""
    offsets = np.zeros(len(runs) + 1, np.int64)
    offsets[1:] = np.cumsum([len(r[0]) for r in runs])
    verts = np.concatenate([r[0] for r in runs]) if runs else np.empty((0, 2))
    return (np.ascontiguousarray(verts, np.float64), offsets,
            np.array([r[1] for r in runs], bool))


def _split_at_start(runs: Sequence[Run], x: int, y: int) -> list[Run]:
    """Open runs passing through the conic's start point (x, y) (where the dash
    pattern starts again, as on the kernels' closed polygon) cut in two there, the
    second starting at arc length 0 (start None)."""
    out: list[Run] = []
    for xy, closed, start in runs:
        hit = np.flatnonzero((xy[1:] == (float(x), float(y))).all(axis=1)) + 1
        if closed or len(hit) == 0:
            out.append((xy, closed, start))
            continue
        i = int(hit[0])
        out += [(xy[:i + 1], False, start), (xy[i:], False, None)]
    return [r for r in out if len(r[0]) > 1]


def _dashed_runs(fb: FrameBuffer, xc: int, yc: int, rx: int, ry: int, color: Spec,
                 style: LineStyle, antialias: bool, runs: Sequence[Run]) -> None:
    """Stroke each run with the dash pattern's phase at its first vertex: the
    given phase plus the ideal conic's arc length from (xc + rx, yc), where the
    pattern starts (a run through that point is cut there: a dash across it is two
    dashes with their ends meeting, where the kernels' closed polygon joins them)
    (:func:`scanline.geometry.far_conics.arc_length`, exact to about 10**-30
    pixel beyond the sample's 2**-40), reduced modulo the pattern's period (the
    kernels' float sum of the lengths, :func:`_period`) in Fractions and rounded
    once to a float.  Along a run the dashes follow the polyline's length,
    shorter than the arc by at most a third of its turning angle times the
    sampling tolerance (0.025 pixel): under 0.03 pixel."""
    from . import strokes

    lengths, phase = style.lengths()
    assert lengths is not None                   # a dashed style (the caller's test)
    period = _period(lengths)
    for xy, closed, start in _split_at_start(runs, xc + rx, yc):
        s = fc.arc_length(rx, ry, *start) if start is not None else Fraction(0)
        at = float((Fraction(phase) + s) % period)
        verts, offsets, flags = _packed([(xy, closed)])
        strokes.stroke(fb, verts, offsets, flags, color,
                       style.replace(dash=tuple(lengths), dash_phase=at), antialias)


def _dashed_segment(fb: FrameBuffer, xc: int, yc: int, rx: int, ry: int, color: Spec,
                    style: LineStyle, antialias: bool, margin: int) -> None:
    """A wide or antialiased dashed degenerate ellipse: the dashes of the path the
    kernels stroke it along (:func:`scanline.geometry.far_conics.degenerate_path`,
    there and back), cut exactly within ``margin`` pixels of the frame
    (:func:`scanline.geometry.far_conics.path_dashes`, the period the kernels'
    float sum, :func:`_period`), and stroked solid as one shape with the style's
    caps and joins (a dash through a turn joined there, as on the kernels' closed
    polygon)."""
    from .._kernels import strokes as ks
    from . import strokes

    lengths, phase = style.lengths()
    assert lengths is not None                   # a dashed style (the caller's test)
    dashes = fc.path_dashes(fc.degenerate_path(xc, yc, rx, ry), lengths, _period(lengths),
                            phase, _frame(fb, margin), ks.EPSILON_DASH)
    if dashes:
        verts, offsets, closed = _packed(dashes)
        strokes.stroke(fb, verts, offsets, closed, color, style.replace(dash="solid"),
                       antialias, one=True)


def stroke(fb: FrameBuffer, xc: int, yc: int, rx: int, ry: int, color: Spec,
           style: LineStyle, antialias: bool, circle: bool) -> None:
    """A far conic with line attributes: thick or antialiased ones stroked along the
    ideal conic near the frame; width-1 and pen lines are the midpoint pixels within
    the pen's reach of the frame, in the order of the conic's pixel sequence, each
    visible run with the line type's phase at its first pixel (exact: its index, or
    its arc length axial + diagonal sqrt 2 along the sequence).  Dashed thick or
    antialiased conics have their dashes measured along the ideal conic from
    (xc + rx, yc), the arc length to each visible run computed in decimals
    (:func:`_dashed_runs`)."""
    from . import strokes

    pixel_line = not antialias and (style.width == 1 or style.pen is not None)
    dashed = style.lengths()[0] is not None
    margin = int(math.ceil(strokes._margin(style))) + 2
    if antialias and style.width == 1 and style.pen is None and not dashed:
        antialiased_outline(fb, xc, yc, rx, ry, color)
        return
    if dashed and not pixel_line and (rx == 0 or ry == 0):
        _dashed_segment(fb, xc, yc, rx, ry, color, style, antialias, margin)
        return
    if not pixel_line:
        runs = _runs(fb, xc, yc, rx, ry, margin)
        if dashed:
            _dashed_runs(fb, xc, yc, rx, ry, color, style, antialias, runs)
            return
        verts, offsets, closed = _packed(runs)
        if len(closed):
            strokes.stroke(fb, verts, offsets, closed, color, style, antialias)
        return
    pen = style.footprint()
    kind, mask, dashes, phase = strokes._line_type(style)
    window = _frame(fb, margin)
    if kind == kl.SOLID:
        found = [(pixels(xc, yc, rx, ry, circle, window), 0, 0, 0)]
    else:
        found = fc.sequence_runs(xc, yc, rx, ry, circle, window)
    sequences = [(p, _phase(kind, dashes, phase, k, a, d)) for p, k, a, d in found if len(p)]
    if not sequences:
        return

    def draw(buf: NDArray[np.uint8], packed: bool, width: int, height: int, ox: int, oy: int,
             value: NDArray[np.uint8]) -> None:
        for p, start in sequences:
            call(kl.draw_sequence, len(p) * len(pen), buf, layout(packed), width, height,
                 p - np.array([ox, oy], np.int64), kind, mask, dashes, start, pen, value)

    if _blend.translucent(color, one=True):
        every = np.concatenate([p for p, _ in sequences])
        lo, hi = every.min(axis=0) - margin, every.max(axis=0) + margin
        _blend.paint(fb, color, (int(lo[0]), int(lo[1]), int(hi[0]), int(hi[1])), draw)
    else:
        buf, packed, width, height = target(fb)
        draw(buf, packed, width, height, 0, 0, fb.pixel(color))


#: Fixed-point bits of a far run's dash phase.
_PHASE_BITS = 96


def _phase(kind: int, dashes: NDArray[np.float64], phase: float, k: int, axial: int,
           diagonal: int) -> float:
    """The line type's phase at pixel k of the sequence, reached by ``axial`` unit
    and ``diagonal`` diagonal steps: for a mask, the bit index (k more than the
    first pixel's), for dash lengths the arc length axial + diagonal sqrt 2 past
    ``phase`` modulo the pattern (the kernel's float sum of the lengths), exact to
    2**-96 however long the way."""
    if kind == kl.MASK:
        return float((int(phase) + k) % 16)
    if kind != kl.LENGTHS:
        return phase
    one = 1 << _PHASE_BITS
    s = round((Fraction(phase) + axial) * one) + math.isqrt(2 * diagonal * diagonal * one * one)
    return (s % round(_period(dashes.tolist()) * one)) / one


def _period(lengths: Sequence[float]) -> Fraction:
    """The dash pattern's period as the kernels take it: the float sum of its
    lengths (exactly, as a Fraction)."""
    period = 0.0
    for length in lengths:
        period += length
    return Fraction(period)


def _band(xy: NDArray[np.float64], closed: bool, half: float = 0.5
          ) -> list[NDArray[np.float64]]:
    """The band within ``half`` pixel of the polyline ``xy`` (dense along a smooth
    curve): its contours for a nonzero fill, offset along the vertex normals."""
    if closed:
        d = np.roll(xy, -1, axis=0) - np.roll(xy, 1, axis=0)
    else:
        d = np.empty_like(xy)
        d[1:-1] = xy[2:] - xy[:-2]
        d[0], d[-1] = xy[1] - xy[0], xy[-1] - xy[-2]
    length = np.hypot(d[:, 0], d[:, 1])
    n = np.stack([d[:, 1], -d[:, 0]], axis=1) / np.where(length > 0, length, 1.0)[:, None]
    outer, inner = xy + half * n, (xy - half * n)[::-1]
    return [outer, inner] if closed else [np.vstack([outer, inner])]


def antialiased_outline(fb: FrameBuffer, xc: float, yc: float, rx: float, ry: float,
                        color: Spec) -> None:
    """The width-1 antialiased outline of a far conic (reals): the coverage of the
    band within half a pixel of the ideal conic near the frame, so that, as for
    Wu's conics, a column's intensities add up to the outline's length in it."""
    from . import antialias as aa

    if rx == 0 or ry == 0:                          # a segment, clipped by the guard
        aa.lines(fb, [[xc - rx, yc - ry, xc + rx, yc + ry]], one(color))
        return
    contours: list[NDArray[np.float64]] = []
    for xy, closed, _ in fc.local_runs(xc, yc, rx, ry, _frame(fb, 3)):
        contours += _band(xy, closed)
    if contours:
        aa.fill(fb, contours, color)


def antialiased_fill(fb: FrameBuffer, xc: float, yc: float, rx: float, ry: float,
                     color: Spec) -> None:
    """The ideal ellipse's area near the frame, filled by coverage: the conic's
    pieces inside the window two pixels beyond the frame joined by the window's
    corners inside the ellipse (the intersection of two convex sets, in angular
    order about an inner point)."""
    from . import antialias as aa

    x0, y0, x1, y1 = window = _frame(fb, 2)
    if rx == 0 or ry == 0:
        return
    runs = fc.local_runs(xc, yc, rx, ry, window)
    pts = [r[0] for r in runs]
    fx, fy, frx, fry = (Fraction(c) for c in (xc, yc, rx, ry))
    corners = [(x, y) for x in (x0, x1) for y in (y0, y1)
               if ((x - fx) * fry) ** 2 + ((y - fy) * frx) ** 2 <= (frx * fry) ** 2]
    if corners:
        pts.append(np.array(corners, np.float64))
    if not pts:
        return
    poly = np.concatenate(pts)
    if len(poly) < 3:
        return
    mid = poly.mean(axis=0)
    poly = poly[np.argsort(np.arctan2(poly[:, 1] - mid[1], poly[:, 0] - mid[0]))]
    aa.fill(fb, [poly], color)


def spec(color: Optional[Colors], i: int) -> Spec:
    """The color spec of primitive i of a batch (one spec, a list, or an array)."""
    if isinstance(color, np.ndarray):
        # a row of an (N, 3|4) array: an RGB(A) tuple, of a length mypy cannot see
        return cast("Color", Channels(int(c) for c in color[i])) if color.ndim == 2 \
            else int(color[i])
    if isinstance(color, list):
        return color[i]
    return color


def one(color: Spec) -> Optional[Colors]:
    """One primitive's color spec as the colors of a batch of one: a list of it (a
    4-list ``[r, g, b, a]`` stays one color), or None (the default color)."""
    return None if color is None else [color]


def _subset(color: Optional[Colors], idx: NDArray[np.intp]) -> Optional[Colors]:
    if isinstance(color, np.ndarray):
        return color[idx]
    if isinstance(color, list):
        return [color[i] for i in idx.tolist()]
    return color


@overload
def batch(fb: FrameBuffer, rows: NDArray[np.float64], color: Optional[Colors],
          exact: NDArray[np.bool_], near: Callable[[NDArray[np.int64], Optional[Colors]], None],
          far: Callable[[int, int, int, int, Spec], None], reach: float = ...,
          fill: bool = ..., rounded: Literal[True] = ...) -> None: ...


@overload
def batch(fb: FrameBuffer, rows: NDArray[np.float64], color: Optional[Colors],
          exact: NDArray[np.bool_],
          near: Callable[[NDArray[np.float64], Optional[Colors]], None],
          far: Callable[[float, float, float, float, Spec], None], reach: float = ...,
          fill: bool = ..., *, rounded: Literal[False]) -> None: ...


def batch(fb: FrameBuffer, rows: NDArray[np.float64], color: Optional[Colors],
          exact: NDArray[np.bool_], near: Callable[[NDArray[Any], Optional[Colors]], None],
          far: Callable[..., None], reach: float = 1.0, fill: bool = False,
          rounded: bool = True) -> None:
    """Draw a batch of conics ``rows`` (N, 4) float64 (xc, yc, rx, ry), finite, in
    order: the rows ``exact`` (a bool array) by ``near(int64 rows, colors)`` (the
    compiled batch, as before), the others one by one by ``far(xc, yc, rx, ry,
    color)`` with Python integers (rounded as the kernels round), after dropping
    those that cannot touch the frame (:func:`scanline.geometry.guard.conics_outside`,
    vectorized, so a million far rows cost a few numpy passes).  Consecutive exact
    rows go to one compiled call; with one color for all, all of them do.
    ``rounded=False`` (antialiasing): the rows are passed on as they are, floats."""
    n = len(rows)
    colors(fb, color, n)                          # checks the count and the specs

    def pixels(a: NDArray[np.float64]) -> NDArray[Any]:
        return np.ascontiguousarray(np.floor(a + 0.5).astype(np.int64)) if rounded else a

    if exact.all():
        near(pixels(rows), color)
        return
    missing = ~exact & conics_outside(fb, rows[:, 0], rows[:, 1], rows[:, 2], rows[:, 3],
                                      reach, fill)
    keep = np.flatnonzero(~missing)
    one = not isinstance(color, (list, np.ndarray))
    kinds = exact[keep]
    if one:                                       # order does not matter
        groups = [keep[kinds], keep[~kinds]]
    else:
        groups = np.split(keep, np.flatnonzero(np.diff(kinds.astype(np.int8))) + 1)
    for idx in groups:
        if len(idx) == 0:
            continue
        if exact[idx[0]]:
            near(pixels(rows[idx]), _subset(color, idx))
            continue
        for i in idx.tolist():
            row = rows[i].tolist()
            far(*((math.floor(c + 0.5) for c in row) if rounded else row), spec(color, i))
