"""Filled polygons by the scan-line algorithm: ``polygon`` and ``polygons`` (notes,
chapter 2, Q.8; Hearn & Baker, section 3-11)."""

from typing import TYPE_CHECKING, Any, Dict, Optional, Sequence, Tuple, Union

import numpy as np

from .. import _validate as v
from .._kernels import polygon as k
from .._kernels._jit import call, call_typed
from .._kernels._threads import call_in_chunks
from .._kernels.variants import layout
from ..errors import ArgumentValueError
from ..geometry import contours as parse
from ..geometry import guard
from . import _blend
from ._common import area_work, colors, target
from .._typing import ArrayLike, Color, Colors, NDArray, Rule

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer
    from ..attributes import FillStyle

RULES: Dict[str, int] = {"even-odd": k.EVEN_ODD, "nonzero": k.NONZERO}


def _rule(rule: Rule) -> int:
    code = RULES.get(rule) if isinstance(rule, str) else None
    return code if code is not None else RULES[v.choice("rule", rule, tuple(RULES))]


def _max_edges(offsets: NDArray[np.int64], polys: NDArray[np.int64]) -> int:
    if len(polys) < 2:
        return 0
    return int((offsets[polys[1:]] - offsets[polys[:-1]]).max())


def _bbox(verts: NDArray[np.float64]) -> Tuple[int, int, int, int]:
    """Device pixels (inclusive) whose centers can be inside: x in
    [ceil(xmin), ceil(xmax) - 1], y in [floor(ymin) + 1, floor(ymax)]."""
    if len(verts) == 0:
        return (0, 0, -1, -1)
    lo = verts.min(axis=0)
    hi = verts.max(axis=0)
    return (int(np.ceil(lo[0])), int(np.floor(lo[1])) + 1,
            int(np.ceil(hi[0])) - 1, int(np.floor(hi[1])))


def _outline(fb: "FrameBuffer", verts: NDArray[np.float64], offsets: NDArray[np.int64],
             color: Optional[Color]) -> None:
    """Draw the closed contours with :func:`scanline.draw.lines`."""
    from .lines import lines
    segs = []
    for c in range(len(offsets) - 1):
        ring = verts[offsets[c]:offsets[c + 1]]
        if len(ring):
            segs.append(np.hstack([ring, np.roll(ring, -1, axis=0)]))
    if segs:
        lines(fb, np.concatenate(segs), color=color)


def _solid_only(style: Optional["FillStyle"]) -> None:
    """antialias=True fills solid areas only."""
    if style is not None and getattr(style, "kind", None) != "solid":
        raise ArgumentValueError(
            f"antialias=True fills solid areas only, got style={style!r}; use style=None, "
            "or antialias=False for hollow, pattern and hatch styles"
        )


def polygon(fb: "FrameBuffer", points: ArrayLike, color: Optional[Color] = None,
            rule: Rule = "even-odd", style: Optional["FillStyle"] = None,
            antialias: bool = False) -> None:
    """Fill a polygon by the scan-line algorithm.

    Parameters
    ----------
    fb : FrameBuffer
    points : array_like
        The vertices, an (N, 2) array-like of (x, y) in device coordinates (floats
        allowed, not rounded), closed implicitly; or several contours (an outer
        boundary and its holes, or any rings): a list of (N_i, 2) arrays or a
        (C, N, 2) array.  Finite and within +-2**30; what falls outside ``fb`` is
        clipped.
    color : color
        See :mod:`scanline.color`.
    rule : {"even-odd", "nonzero"}
        The inside-outside test (:func:`scanline.geometry.inside`): odd parity, or
        nonzero winding number.  They differ where contours overlap or a contour
        crosses itself (the center of a pentagram is outside under even-odd).
    style : FillStyle, optional
        None (solid) or a :class:`scanline.FillStyle` (hollow, pattern, hatch ...).
    antialias : bool
        False: a pixel is filled iff its center is inside (below).  True: every
        pixel is composited with alpha = the fraction of it inside the polygon
        (:func:`scanline.draw.antialias.fill`; solid fills only).

    Notes
    -----
    A translucent ``color`` (alpha < 255) is composited over the frame buffer,
    each pixel once (:mod:`scanline.draw._blend`).

    Notes, chapter 2, Q.8, approach (1), "determine the overlap intervals for scan
    lines that cross the area", done as in Hearn & Baker, section 3-11: a *sorted
    edge table* (the edges bucket-sorted by their first scan line) feeds an *active
    edge list* whose crossings are advanced from one scan line to the next by the
    inverse slope dx/dy; on each scan line the sorted crossings bound the spans that
    are filled.

    *Coverage.*  A pixel is filled iff its center is inside.  Centers exactly on the
    boundary follow the top-left rule: on a left edge, or on a horizontal edge with
    the area below it (y is up), they are filled; on a right edge or a bottom edge,
    not.  Concretely an edge is active on the scan lines ``ylo < y <= yhi`` and a
    span covers ``xleft <= x < xright``.  The half-open interval in y is the
    textbook's vertex rule: a vertex between two edges going the same way is
    counted once, a local maximum or minimum twice (or not at all), and horizontal
    edges are skipped.  Polygons that share edges (a triangulated square, a tiling)
    therefore cover every pixel exactly once.  See :mod:`scanline._kernels.polygon`.

    *Degenerate polygons.*  A polygon of zero area -- fewer than three distinct
    vertices, all vertices on one line, or an empty list -- fills no pixel (no pixel
    center is strictly inside it).  Draw its outline with
    :func:`scanline.draw.lines` (or ``style`` hollow) to see it.

    *Arithmetic.*  Integer vertices are handled exactly (integer increments); edges
    with fractional coordinates evaluate the edge equation in float64 on every scan
    line, so no error accumulates.

    References
    ----------
    D. Hearn, M. P. Baker, "Computer Graphics", 2nd ed., Prentice Hall, 1994,
    section 3-11.
    J. D. Foley, A. van Dam, S. K. Feiner, J. F. Hughes, "Computer Graphics:
    Principles and Practice", 2nd ed., 1990, section 3.6.
    W. M. Newman, R. F. Sproull, "Principles of Interactive Computer Graphics", 2nd
    ed., 1979, chapter 16.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(7, 5, mode="1")
    >>> sl.draw.polygon(fb, [(0, 0), (6, 0), (3, 4)])
    >>> print(sl.text_image(fb))
    -------
    ---#---
    --###--
    -#####-
    -------

    Two contours, a square with a square hole:

    >>> fb = sl.FrameBuffer(6, 6, mode="1")
    >>> sl.draw.polygon(fb, [[(0, 0), (6, 0), (6, 6), (0, 6)],
    ...                      [(2, 2), (4, 2), (4, 4), (2, 4)]])
    >>> print(sl.text_image(fb))
    ######
    ##--##
    ##--##
    ######
    ######
    ------
    """
    ring = _one_ring(points) if style is None and antialias is False else None
    if ring is not None and not _blend.translucent(color, one=True):
        # one contour in an opaque solid color: a single compiled call
        buf, packed, width, height = target(fb)
        verts = np.ascontiguousarray(ring, np.float64)
        code = _rule(rule)
        if call_typed(k.fill_ring, (packed, code), width * height + len(verts), _ring_work,
                      buf, layout(packed), width, height, verts, fb.pixel(color), code):
            return
    target(fb)
    if antialias:
        from .antialias import fill
        _solid_only(style)
        fill(fb, points, color, rule)
        return
    verts, offsets = parse.contours("points", points, far=True)
    code = _rule(rule)
    verts, offsets, polys = guard.areas(verts, offsets, np.array([0, len(offsets) - 1],
                                                                 np.int64))
    max_edges = _max_edges(offsets, polys)

    def draw(buf: NDArray[np.uint8], packed: bool, width: int, height: int, ox: int, oy: int,
             pixel: NDArray[np.uint8]) -> None:
        call(k.fill_polygons, lambda: area_work(width, height, verts - (ox, oy)) / 4, buf,
             layout(packed), width, height, ox, oy, verts, offsets, polys,
             np.asarray(pixel, np.uint8).reshape(1, -1), code, max_edges)

    def outline() -> None:
        _outline(fb, verts, offsets, color)

    _blend.fill(fb, color, style, _bbox(verts), draw, outline)


def _one_ring(points: object) -> Optional[NDArray[Any]]:
    """``points`` as an (N, 2) array of numbers when it is one contour (an array, or
    a list or tuple of vertices), else None (several contours, or something for the
    general path to refuse by name)."""
    a = points
    if type(a) is list or type(a) is tuple:
        try:
            a = np.asarray(a)
        except (TypeError, ValueError):             # ragged: several contours
            return None
    if type(a) is np.ndarray and a.ndim == 2 and a.shape[1] == 2 and a.dtype.kind in "fiu":
        return a
    return None


def _ring_work(buf: NDArray[np.uint8], layout: Tuple[int, ...], width: int, height: int,
               verts: NDArray[np.float64], color: NDArray[np.uint8], rule: int) -> float:
    """Work units of :func:`scanline._kernels.polygon.fill_ring`."""
    return area_work(width, height, verts) / 4


def polygons(fb: "FrameBuffer", polygons: Union[Sequence[ArrayLike], ArrayLike],
             color: Optional[Colors] = None, rule: Rule = "even-odd",
             counts: Optional[ArrayLike] = None, antialias: bool = False) -> None:
    """Fill M polygons in one compiled call.

    Parameters
    ----------
    fb : FrameBuffer
    polygons : list or array_like, shape (M, K, 2)
        A list of M polygons, each an (N_i, 2) array of vertices (or several
        contours, as :func:`polygon` takes), or an (M, K, 2) array of M polygons of
        K vertices each.
    color : color or list/array of M colors
        One color for all, or one per polygon (see
        :func:`scanline.draw._common.colors`); later polygons paint over earlier
        ones.
    rule : {"even-odd", "nonzero"}
        Applied to each polygon on its own.
    counts : array_like of int, optional
        The flat form for numpy data: ``polygons`` is then one (V, 2) array holding
        the vertices of every polygon in turn, and ``counts[p]`` is the vertex count
        of polygon ``p`` (one contour each).  Nothing is converted per polygon.
    antialias : bool
        True composites each pixel with the fraction of it inside each polygon
        (:func:`scanline.draw.antialias.fills`).

    Notes
    -----
    Translucent colors are composited, polygon after polygon.

    Each polygon is filled exactly as :func:`polygon` fills it; the vertices of all
    polygons are passed to the kernel as one array with offsets, so the cost per
    polygon is a few dozen nanoseconds plus its spans.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(8, 3, mode="1")
    >>> sl.draw.polygons(fb, [[(0, 0), (3, 0), (3, 3), (0, 3)],
    ...                       [(5, 0), (8, 0), (8, 2)]])
    >>> print(sl.text_image(fb))
    ###-----
    ###----#
    --------

    The bottom row (y = 0) stays empty: pixel centers on a bottom edge are outside,
    those on a top edge inside (the top-left rule); the right column of the
    triangle's row y = 1 is its only pixel.
    """
    buf, packed, width, height = target(fb)
    if counts is None:
        verts, offsets, polys = parse.batch("polygons", polygons, far=True)
    else:
        verts, offsets, polys = parse.flat("polygons", polygons, counts, far=True)
    if antialias:
        from .antialias import _fill_parsed
        _fill_parsed(fb, verts, offsets, polys, color, rule)
        return
    verts, offsets, polys = guard.areas(verts, offsets, polys)
    code = _rule(rule)
    n = len(polys) - 1
    most = _max_edges(offsets, polys)
    if _blend.translucent(color):
        def draw(i: int, buf: NDArray[np.uint8], packed: bool, width: int, height: int, ox: int,
                 oy: int, value: NDArray[np.uint8]) -> None:
            one = verts[offsets[polys[i]]:offsets[polys[i + 1]]]
            call(k.fill_polygons, lambda: area_work(width, height, one - (ox, oy)) / 4, buf,
                 layout(packed), width, height, ox, oy, verts, offsets, polys[i:i + 2],
                 value.reshape(1, -1), code, most)

        boxes = [_bbox(verts[offsets[polys[i]]:offsets[polys[i + 1]]]) for i in range(n)]
        _blend.paint_each(fb, color, n, boxes, draw)
        return
    values = colors(fb, color, n)
    work = area_work(width, height, verts, n) / 4
    if len(values) == 1 and n > 1:   # one color: the order cannot change the image
        verts, offsets, polys = call(k.band_reordered, len(verts), verts, offsets, polys, 0,
                                     height)
    # one call per thread, each filling a strip of rows (a view of them whose row 0 is
    # device row lo): the crossings come from the edges' device coordinates, so each
    # strip gets the whole raster's spans, every pixel from one thread, in order
    call_in_chunks(k.fill_polygons, work, height, lambda lo, hi: (
        buf[lo:hi], layout(packed), width, hi - lo, 0, lo, verts, offsets, polys, values, code,
        most))
