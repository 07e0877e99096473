"""Straight lines: ``line`` and ``lines`` (notes, chapter 2, Q.1-Q.3, Q.7)."""

from typing import TYPE_CHECKING, Any, Dict, Optional, Tuple

import numpy as np

from .. import _validate as v
from .._kernels import lines as k
from .._kernels._jit import call, call_typed
from .._kernels._threads import call_in_bands
from .._kernels.variants import layout, token
from ..errors import ArgumentValueError
from . import strokes
from ._common import band_order, colors, target
from .._typing import ArrayLike, Cap, Color, Colors, Dash, Join, LineMethod, NDArray, PenLike

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer
    from ..linestyle import LineStyle

METHODS: Dict[str, Tuple[int, ...]] = {"bresenham": token(k.BRESENHAM), "dda": token(k.DDA)}


#: Segments from which :func:`line_work` estimates from an evenly spaced sample.
WORK_SAMPLE = 1 << 12


def line_work(segments: NDArray[np.number[Any]], width: int, height: int) -> float:
    """Work units of drawing the (N, 4) ``segments``: their steps, each at most the
    raster's width + height once clipped (:func:`scanline._kernels._jit.call`) -- over
    every segment up to 2 * WORK_SAMPLE of them, else estimated from WORK_SAMPLE
    evenly spaced ones (the estimate only chooses between the twin, one thread,
    threads and a background thread; the full count cost a fifth of drawing a
    million short lines)."""
    n = len(segments)
    rows = segments[::n // WORK_SAMPLE] if n > 2 * WORK_SAMPLE else segments
    d = np.abs(rows[:, 2:4] - rows[:, 0:2]).max(axis=1, initial=0)
    return float(np.minimum(d, width + height).sum()) * n / max(len(rows), 1) + n


def _method(method: LineMethod) -> Tuple[int, ...]:
    code = METHODS.get(method) if isinstance(method, str) else None
    return code if code is not None else METHODS[v.choice("method", method, tuple(METHODS))]


def _attributes_need_bresenham(code: Tuple[int, ...]) -> None:
    if len(code) != k.BRESENHAM:
        raise ArgumentValueError(
            "method='dda' draws plain width-1 solid lines; lines with attributes (width, "
            "dash, pen, antialias) follow Bresenham's pixels or exact outlines, so leave "
            "method='bresenham'")


def line(fb: "FrameBuffer", x0: float, y0: float, x1: float, y1: float,
         color: Optional[Color] = None, method: LineMethod = "bresenham",
         *, style: Optional["LineStyle"] = None, antialias: bool = False, width: Optional[float] = None,
         cap: Optional[Cap] = None, join: Optional[Join] = None, miter_limit: Optional[float] = None,
         dash: Optional[Dash] = None, dash_phase: Optional[float] = None,
         pen: Optional[PenLike] = None) -> None:
    """Draw the line segment from (x0, y0) to (x1, y1), both endpoints included.

    Parameters
    ----------
    fb : FrameBuffer
    x0, y0, x1, y1 : number
        Endpoints in device coordinates, rounded to the nearest pixel center
        (halves round up); within +-2**30.  What falls outside ``fb`` is clipped.
    color : color
        See :mod:`scanline.color`.
    method : {"bresenham", "dda"}
        ``"bresenham"``: integer decision parameter, exact.  ``"dda"``: the digital
        differential analyzer, real increments dx/steps and dy/steps rounded to the
        nearest pixel at each step.  Line attributes other than the plain width-1
        solid line use Bresenham's pixels.
    style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen
        Line attributes, as :func:`scanline.draw.polyline` takes them (a thick,
        dashed, pen-drawn or antialiased line is the polyline of its two endpoints).

    Notes
    -----
    Notes, chapter 2, Q.1 (DDA), Q.2-Q.3 (Bresenham) and Q.7 (why DDA is slower and
    drifts).  Bresenham scans from the left endpoint when x is the major axis
    (|dy| <= |dx|) and from the lower endpoint otherwise, as the notes prescribe, so
    the pixels do not depend on the endpoint order.

    *Tie rule.*  When the line passes exactly halfway between the two candidate
    pixels (p_k = 0), the notes' test "p_k < 0 keeps y" takes the step: the minor
    coordinate advances, away from the start endpoint.  The DDA rounds halves up
    (floor(v + 0.5)) in absolute coordinates and follows the endpoints in the order
    given; its accumulated floating-point error can move a tie either way.

    References
    ----------
    J. E. Bresenham, "Algorithm for computer control of a digital plotter",
    IBM Systems Journal 4(1), 25-30, 1965.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(6, 3, mode="1")
    >>> sl.draw.line(fb, 0, 0, 5, 2)
    >>> print(sl.text_image(fb))
    ----##
    --##--
    ##----
    """
    code = _method(method)
    attrs = strokes.styled(style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen)
    if attrs is not None:
        _attributes_need_bresenham(code)
        points = [(v.number("x0", x0), v.number("y0", y0)), (v.number("x1", x1), v.number("y1", y1))]
        strokes.polyline(fb, points, color, style=attrs, antialias=antialias)
        return
    buf, packed, width, height = target(fb)
    limit = v.COORD_LIMIT
    if not (type(x0) is type(y0) is type(x1) is type(y1) is int
            and -limit <= x0 <= limit and -limit <= y0 <= limit
            and -limit <= x1 <= limit and -limit <= y1 <= limit):
        ends = [v.number(n, c) for n, c in (("x0", x0), ("y0", y0), ("x1", x1), ("y1", y1))]
        if max(map(abs, ends)) > limit:     # far: clipped to the guard first
            lines(fb, np.array([ends]), color, method)
            return
        x0, y0, x1, y1 = (v.coordinate(n, c) for n, c in (("x0", x0), ("y0", y0),
                                                          ("x1", x1), ("y1", y1)))
    # the types of the kernel's arguments follow from the storage and the method
    call_typed(k.draw_line, (packed, code), 2 * (width + height), _line_work,
               buf, layout(packed), width, height, x0, y0, x1, y1, fb.pixel(color), code)


def _line_work(buf: NDArray[np.uint8], layout: Tuple[int, ...], width: int, height: int,
               x0: int, y0: int, x1: int, y1: int, color: NDArray[np.uint8],
               code: Tuple[int, ...]) -> int:
    """Work units of one line (its pixels, at most the frame buffer's perimeter)."""
    return 2 * min(max(abs(x1 - x0), abs(y1 - y0)), width + height)


def lines(fb: "FrameBuffer", segments: ArrayLike, color: Optional[Colors] = None,
          method: LineMethod = "bresenham",
          *, style: Optional["LineStyle"] = None, antialias: bool = False, width: Optional[float] = None,
          cap: Optional[Cap] = None, join: Optional[Join] = None, miter_limit: Optional[float] = None,
          dash: Optional[Dash] = None, dash_phase: Optional[float] = None,
          pen: Optional[PenLike] = None) -> None:
    """Draw N line segments in one compiled call.

    Parameters
    ----------
    fb : FrameBuffer
    segments : array_like, shape (N, 4)
        Rows ``(x0, y0, x1, y1)``, rounded to pixel centers like :func:`line`.
    color : color or list/array of N colors
        One color for all, or one per segment (see :func:`scanline.draw._common.colors`).
    method : {"bresenham", "dda"}
    style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen
        Line attributes for every segment (see :func:`line`).

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> fb = sl.FrameBuffer(5, 5, mode="1")
    >>> sl.draw.lines(fb, np.array([[0, 0, 4, 4], [0, 4, 4, 0]]))
    >>> print(sl.text_image(fb))
    #---#
    -#-#-
    --#--
    -#-#-
    #---#
    """
    code = _method(method)
    attrs = strokes.styled(style, antialias, width, cap, join, miter_limit, dash, dash_phase, pen)
    if attrs is not None:
        _attributes_need_bresenham(code)
        ends = strokes.segment_array("segments", segments)
        strokes.polylines(fb, ends.reshape(-1, 2), color, counts=np.full(len(ends), 2),
                          style=attrs, antialias=antialias)
        return
    buf, packed, width, height = target(fb)
    segs = v.coordinate_array("segments", segments, 4, guard=True)
    values = colors(fb, color, len(segs))
    if len(code) == k.DDA:
        call(k.draw_lines, lambda: 2 * line_work(segs, width, height), 0, 1, buf,
             layout(packed), width, height, segs, values, code)
    else:
        call_in_bands(k.draw_lines, 2 * line_work(segs, width, height), buf, layout(packed),
                      width, height, band_order(segs, values, height), values, code)
