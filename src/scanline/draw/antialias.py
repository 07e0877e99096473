"""Antialiased primitives: thin lines and conic outlines after Wu (1991), areas by
their coverage of each pixel (notes, syllabus "Antialiasing"; glossary:
"Anti-aliasing is sub pixel interpolation ... usually done by filtering").

Every function takes *real* coordinates (not rounded to pixel centers; pixel
centers are at integers, y up), a ``color`` that is one color spec or one per
primitive, and composites each pixel "over" the frame buffer with alpha =
coverage x the color's alpha (:mod:`scanline.draw._blend`), in every mode:
``"RGB"``, ``"RGBA"``, ``"L"``, ``"P"`` (blend, then the nearest table entry; the
drawing color itself is added to the table) and ``"1"`` (a pixel is set where
coverage x alpha >= 1/2).  Primitives are composited in order, each pixel once per
primitive.  Anything outside the frame buffer is clipped.

=============================== ==========================================
``lines(fb, segments, color)``  (N, 4) rows (x0, y0, x1, y1), width 1
``circles(fb, circles, color)`` (N, 3) rows (xc, yc, r), outlines
``ellipses(fb, ellipses, c)``   (N, 4) rows (xc, yc, rx, ry), outlines
``filled_ellipses(fb, e, c)``   (N, 4) rows (xc, yc, rx, ry), areas
``fill(fb, contours, c, rule)`` ONE shape from several contours
``fills(fb, shapes, c, rule)``  a batch of shapes in one compiled call
``fills_flat(fb, v, co, so, c)`` the same batch given as flat arrays
=============================== ==========================================
"""

from typing import TYPE_CHECKING, Iterable, Optional, Sequence, Tuple, Union, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._typing import Color, Colors, Rule
from ..errors import ArgumentTypeError, ArgumentValueError
from .._kernels import antialias as wu
from .._kernels import coverage as cov
from .._kernels._jit import call
from ..geometry import contours as parse
from ..geometry import guard
from ..geometry.guard import segments as guard_segments
from . import _blend
from . import _far_conics as far
from ._common import area_work, target
from .conics import conic_work
from .curved import region_work
from .lines import line_work
from .polygon import _rule

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer


def _reals(name: str, value: ArrayLike, columns: int, radius_columns: Iterable[int] = (),
           guard: bool = False, far: bool = False) -> NDArray[np.float64]:
    """An (N, columns) float64 array, validated as
    :func:`scanline._validate.coordinate_array` validates (finite, within +-2**30,
    radii >= 0; ``far``: any finite value) but not rounded.  A well-formed numeric
    array passes one test of its largest magnitude (NaN fails it); anything else
    goes through ``coordinate_array``, which raises the message naming the fault."""
    try:
        raw = np.asarray(value)
    except (TypeError, ValueError):
        raw = None
    if raw is not None and raw.dtype.kind in "fiu" and raw.ndim == 2 and raw.shape[1] == columns:
        a = np.ascontiguousarray(raw, np.float64)
        if a.size == 0 or (np.abs(a).max() <= v.COORD_LIMIT
                           and all(a[:, c].min() >= 0 for c in radius_columns)):
            return a
    if far:
        return v.coordinate_array(name, value, columns, radius_columns, far=True)
    v.coordinate_array(name, value, columns, radius_columns, guard)
    a = np.ascontiguousarray(np.asarray(value, np.float64).reshape(-1, columns))
    return guard_segments(a) if guard else a


def _setup(fb: "FrameBuffer", color: Optional[Colors], n: int) -> Tuple[
        NDArray[np.uint8], Tuple[int, ...], int, int, NDArray[np.uint8], NDArray[np.float64]]:
    """The blend kernels' arguments: ``(buf, mode, width, height, table, sources)``."""
    buf, _, width, height = target(fb)
    srcs = _blend.sources(fb, color, n)     # first: in mode "P" it may extend the table
    return buf, _blend.mode_code(fb), width, height, _blend.table(fb), srcs


def lines(fb: "FrameBuffer", segments: ArrayLike, color: Optional[Colors] = None) -> None:
    """Draw N antialiased lines of width 1 with Wu's algorithm.

    Parameters
    ----------
    fb : FrameBuffer
    segments : array_like, shape (N, 4)
        Rows (x0, y0, x1, y1), real device coordinates within +-2**30.
    color : color or list/array of N colors
        Alpha multiplies the coverage.

    Notes
    -----
    Syllabus "Antialiasing" (chapter 3, attributes).  Each column along the major
    axis splits the cross-section of the 1-pixel-wide line, ``sqrt(1 + m**2)`` long
    at slope m, between the pixels it straddles (Wu's two intensities for
    axis-aligned lines); real endpoints weight their end columns by the part of
    the column the segment spans.  The total intensity is the segment's length at
    every slope.  See :mod:`scanline._kernels.antialias`.

    References
    ----------
    X. Wu, "An efficient antialiasing technique", Computer Graphics 25(4)
    (SIGGRAPH '91), 143-152, 1991.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(6, 3, mode="L")
    >>> sl.draw.antialias.lines(fb, [(0, 0.75, 5, 0.75)], "white")
    >>> fb.to_array()
    array([[  0,   0,   0,   0,   0,   0],
           [ 96, 191, 191, 191, 191,  96],
           [ 32,  64,  64,  64,  64,  32]], dtype=uint8)
    """
    segs = _reals("segments", segments, 4, guard=True)
    buf, mode, width, height, table, srcs = _setup(fb, color, len(segs))
    call(wu.draw_lines, lambda: 20 * line_work(segs, width, height), buf, mode, width, height,
         table, segs, srcs)


def ellipses(fb: "FrameBuffer", ellipses: ArrayLike, color: Optional[Colors] = None) -> None:
    """Draw N antialiased ellipse outlines (Wu-style conics).

    Parameters
    ----------
    fb : FrameBuffer
    ellipses : array_like, shape (N, 4)
        Rows (xc, yc, rx, ry), real; semi-axes >= 0 (one of them 0: the segment
        along the other, traced twice).  Any finite values: a row beyond +-2**30
        is drawn as the coverage of the band within half a pixel of the ideal
        ellipse near the frame (:mod:`scanline.draw._far_conics`).
    color : color or list/array of N colors

    Notes
    -----
    The arcs where |slope| <= 1 are stepped by columns, the others by rows; each
    column (row) splits the curve's cross-section between the pixels straddling
    the ideal ellipse, as :func:`lines` does.  The total intensity is the
    perimeter (also for far rows, whose band has the outline's length as area).

    References
    ----------
    X. Wu, "An efficient antialiasing technique", 1991 (the circle generator).
    """
    arr = _reals("ellipses", ellipses, 4, radius_columns=(2, 3), far=True)

    def near(rows: NDArray[np.float64], c: Optional[Colors]) -> None:
        buf, mode, width, height, table, srcs = _setup(fb, c, len(rows))
        call(wu.draw_ellipses, lambda: 12 * conic_work(rows[:, 2], rows[:, 3], width, height),
             buf, mode, width, height, table, rows, srcs)

    far.batch(fb, arr, color, _in_range(arr), near,
              lambda *row: far.antialiased_outline(fb, *row), rounded=False)


def circles(fb: "FrameBuffer", circles: ArrayLike, color: Optional[Colors] = None) -> None:
    """Draw N antialiased circles, rows (xc, yc, r) of ``circles`` (real); see
    :func:`ellipses`.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(7, 7, mode="L")
    >>> sl.draw.antialias.circles(fb, [(3, 3, 2.5)])
    >>> print(sl.text_image(fb))
    -#####-
    #######
    ##---##
    ##---##
    ##---##
    #######
    -#####-
    """
    arr = _reals("circles", circles, 3, radius_columns=(2,), far=True)
    ellipses(fb, arr[:, [0, 1, 2, 2]], color)


def filled_ellipses(fb: "FrameBuffer", ellipses: ArrayLike,
                    color: Optional[Colors] = None) -> None:
    """Fill N ellipses (rows (xc, yc, rx, ry), real; rx = ry: disks) with
    antialiased edges: each pixel's coverage, measured on 16 sub-scan-lines (see
    :mod:`scanline._kernels.coverage`).  Any finite values: a row beyond +-2**30
    is filled as the polygon of its part near the frame
    (:func:`scanline.draw._far_conics.antialiased_fill`)."""
    arr = _reals("ellipses", ellipses, 4, radius_columns=(2, 3), far=True)

    def near(rows: NDArray[np.float64], c: Optional[Colors]) -> None:
        buf, mode, width, height, table, srcs = _setup(fb, c, len(rows))
        call(cov.fill_ellipses, lambda: 20 * region_work(rows[:, 2], rows[:, 3], width, height)
             + cov.SUB * float(np.minimum(2 * rows[:, 3] + 2, height).sum()), buf, mode, width,
             height, table, rows, srcs)

    far.batch(fb, arr, color, _in_range(arr), near,
              lambda *row: far.antialiased_fill(fb, *row), fill=True, rounded=False)


def _in_range(arr: NDArray[np.float64]) -> NDArray[np.bool_]:
    """The rows the antialiasing kernels take: every value within +-2**30."""
    return cast("NDArray[np.bool_]", np.abs(arr).max(axis=1, initial=0) <= v.COORD_LIMIT)


#: The largest vertex magnitude :func:`fills_flat` takes: the coverage arithmetic is
#: exact far beyond the drawing range +-2**30, and generated outlines (a wide stroke's
#: round caps and miters around an in-range vertex) may reach past it.
OUTLINE_LIMIT = 2.0**40


def _vertices(value: ArrayLike) -> NDArray[np.float64]:
    """``value`` as a contiguous float64 (V, 2) array of finite vertices (no copy if
    it already is one; what lies beyond +-OUTLINE_LIMIT is clipped to the guard
    square, :mod:`scanline.geometry.guard`)."""
    try:
        a = np.asarray(value)
    except (TypeError, ValueError):
        a = None
    if a is None or a.dtype.kind not in "fiu" or a.ndim != 2 or a.shape[1] != 2:
        raise ArgumentTypeError(f"vertices must be a (V, 2) array of real numbers, got "
                                f"{v._show(value)}")
    a = np.ascontiguousarray(a, np.float64)
    if a.size and not np.abs(a).max() <= OUTLINE_LIMIT and not np.isfinite(a).all():
        i = int(np.argmax(~np.isfinite(a).all(axis=1)))
        raise ArgumentValueError(f"vertices must be finite; vertex {i} is {a[i].tolist()}")
    return a


def _offsets(name: str, value: ArrayLike, end: int) -> NDArray[np.int64]:
    """``value`` as a contiguous int64 array that rises from 0 to ``end``."""
    return v.index_array(name, value, high=end, rising=True, first=0, last=end,
                         what="a non-empty 1-D array of integers (where each part starts, "
                              "then the end)")


def _fill_parsed(fb: "FrameBuffer", verts: NDArray[np.float64], offsets: NDArray[np.int64],
                 shapes: NDArray[np.int64], color: Optional[Colors], rule: Rule) -> None:
    """:func:`fills_flat` for arrays already validated (by
    :mod:`scanline.geometry.contours`)."""
    code = _rule(rule)
    buf, mode, width, height, table, srcs = _setup(fb, color, len(shapes) - 1)
    verts, offsets, shapes = guard.areas(verts, offsets, shapes)
    counts = offsets[shapes[1:]] - offsets[shapes[:-1]]
    most = int(counts.max()) if len(counts) else 0
    call(cov.fill_shapes, lambda: 4 * area_work(width, height, verts, len(shapes) - 1),
         buf, mode, width, height, table, verts,
         offsets, shapes, srcs, code, most)


def fills_flat(fb: "FrameBuffer", vertices: ArrayLike, contour_offsets: ArrayLike,
               shape_offsets: ArrayLike, color: Optional[Colors] = None,
               rule: Rule = "nonzero") -> None:
    """Fill a batch of shapes made of several contours each, given as flat arrays,
    with antialiased edges in one compiled call (as :func:`fills`).

    Parameters
    ----------
    fb : FrameBuffer
    vertices : array_like, shape (V, 2)
        All the contours' vertices, real device coordinates: finite, within
        +-2**40 (outlines generated from geometry in the drawing range +-2**30,
        such as wide strokes, may reach beyond it).
    contour_offsets : array_like of int, shape (C + 1,)
        Contour c is ``vertices[contour_offsets[c]:contour_offsets[c + 1]]``
        (closed implicitly); rises from 0 to V.
    shape_offsets : array_like of int, shape (M + 1,)
        Shape p is made of contours ``shape_offsets[p]`` .. ``shape_offsets[p + 1]
        - 1``; rises from 0 to C.
    color : color or list/array of M colors
    rule : {"nonzero", "even-odd"}
        Applied to each shape on its own.

    Notes
    -----
    This is the form :func:`fill` and :func:`fills` reduce their arguments to, and
    the form stroke outlines come in (:func:`scanline.draw.polyline` with a width),
    so that generated geometry needs no per-contour Python objects.  Float64
    C-contiguous vertices are used without a copy.

    Examples
    --------
    Two shapes: a square with a square hole (contours 0 and 1) and a triangle
    (contour 2) whose hypotenuse halves two pixels.

    >>> import scanline as sl
    >>> square = [(-0.5, -0.5), (4.5, -0.5), (4.5, 4.5), (-0.5, 4.5)]
    >>> hole = [(0.5, 0.5), (0.5, 3.5), (3.5, 3.5), (3.5, 0.5)]
    >>> triangle = [(5.5, -0.5), (7.5, -0.5), (5.5, 1.5)]
    >>> fb = sl.FrameBuffer(8, 5, mode="L")
    >>> sl.draw.antialias.fills_flat(fb, square + hole + triangle, [0, 4, 8, 11], [0, 2, 3])
    >>> fb.to_array()
    array([[255, 255, 255, 255, 255,   0,   0,   0],
           [255,   0,   0,   0, 255,   0,   0,   0],
           [255,   0,   0,   0, 255,   0,   0,   0],
           [255,   0,   0,   0, 255,   0, 128,   0],
           [255, 255, 255, 255, 255,   0, 255, 128]], dtype=uint8)
    """
    verts = _vertices(vertices)
    offsets = _offsets("contour_offsets", contour_offsets, len(verts))
    shapes = _offsets("shape_offsets", shape_offsets, len(offsets) - 1)
    _fill_parsed(fb, verts, offsets, shapes, color, rule)


def fill(fb: "FrameBuffer", contours: ArrayLike, color: Optional[Color] = None,
         rule: Rule = "nonzero") -> None:
    """Fill ONE shape made of several contours with antialiased edges.

    Parameters
    ----------
    fb : FrameBuffer
    contours : list of (K, 2) arrays, or one (K, 2) array
        The shape's contours (outer boundaries, holes, overlapping pieces), real
        device coordinates, each closed implicitly.
    color : color
    rule : {"nonzero", "even-odd"}
        How the contours combine: nonzero winding number or odd parity, counted
        over all contours together.

    Notes
    -----
    Each pixel is composited once with alpha = the fraction of it inside the
    shape, measured exactly along 16 sub-scan-lines per row (the fill rule is
    applied on each), so a hole, an overlap and a self-intersection are
    antialiased as exactly as a simple polygon.  See
    :mod:`scanline._kernels.coverage`.

    References
    ----------
    J. D. Foley, A. van Dam, S. K. Feiner, J. F. Hughes, "Computer Graphics:
    Principles and Practice", 2nd ed., 1990, section 3.17.

    Examples
    --------
    A rectangle from x = 1 to 3 (pixel edges are at half-integers): the pixels
    whose centers are on its sides are half covered.

    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(5, 3, mode="L")
    >>> sl.draw.antialias.fill(fb, [[(1, -0.5), (3, -0.5), (3, 2.5), (1, 2.5)]])
    >>> fb.to_array()
    array([[  0, 128, 255, 128,   0],
           [  0, 128, 255, 128,   0],
           [  0, 128, 255, 128,   0]], dtype=uint8)
    """
    verts, offsets = parse.contours("contours", contours, far=True)
    _fill_parsed(fb, verts, offsets, np.array([0, len(offsets) - 1], np.int64),
                 [color] if color is not None else None, rule)


def fills(fb: "FrameBuffer", shapes: Union[Sequence[ArrayLike], ArrayLike],
          color: Optional[Colors] = None, rule: Rule = "nonzero",
          counts: Optional[ArrayLike] = None) -> None:
    """Fill a batch of shapes with antialiased edges in one compiled call.

    Parameters
    ----------
    fb : FrameBuffer
    shapes : list
        Shapes as :func:`fill` takes them (each a (K, 2) array or a list of
        contours), or an (M, K, 2) array of one-contour shapes; with ``counts``,
        one flat (V, 2) array of vertices (as :func:`scanline.draw.polygons`).
    color : color or list/array of M colors
    rule : {"nonzero", "even-odd"}
        Applied to each shape on its own.
    counts : array_like of int, optional
        Vertices per shape for the flat form.

    Later shapes are composited over earlier ones.
    """
    if counts is None:
        verts, offsets, polys = parse.batch("shapes", shapes, far=True)
    else:
        verts, offsets, polys = parse.flat("shapes", shapes, counts, far=True)
    _fill_parsed(fb, verts, offsets, polys, color, rule)
