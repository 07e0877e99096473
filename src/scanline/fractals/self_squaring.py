"""Self-squaring fractals (Hearn & Baker, section 10-18, "self-squaring fractals"):
the Mandelbrot set and Julia sets by the escape-time method, as iteration counts in
image order, and their coloring through a color table.

The transformation is z -> z² + c in the complex plane.  Hearn & Baker's test: once
|z| > 2 the iterates run off to infinity, so a point whose orbit stays within
|z| <= 2 for ``max_iterations`` steps is taken as a member.

The compiled loop is :func:`scanline._kernels.fractals.escape_times` (interleaved
rows, one call per thread; the counts do not depend on the number of threads).

References
----------
.. [1] D. Hearn and M. P. Baker, *Computer Graphics, C Version*, 2nd ed., 1997,
   section 10-18 (the Mandelbrot set, Julia sets, the escape test |z| > 2).
.. [2] B. B. Mandelbrot, *The Fractal Geometry of Nature*, Freeman, 1982, ch. 19.
.. [3] H.-O. Peitgen and P. H. Richter, *The Beauty of Fractals*, Springer, 1986.
"""

import numbers
from typing import TYPE_CHECKING, Optional, Sequence, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from . import limits

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer

#: A complex number, or (real, imaginary).
Complex = Union[complex, float, Tuple[float, float], Sequence[float]]


def _plane(width: int, height: int, center: Sequence[float], span: float
           ) -> Tuple[int, int, NDArray[np.float64], NDArray[np.float64]]:
    """The real parts of the columns' and the imaginary parts of the rows' pixel
    centers (rows top to bottom)."""
    width = v.positive_int("width", width)
    height = v.positive_int("height", height)
    if not isinstance(center, (tuple, list, np.ndarray)) or len(center) != 2:
        raise ArgumentTypeError(f"center must be (real, imaginary), got {v._show(center)}")
    cx, cy = v.number("center[0]", center[0]), v.number("center[1]", center[1])
    width_shown = v.number("span", span)
    if width_shown <= 0:
        raise ArgumentValueError(f"span must be > 0 (the width of the real axis shown), got "
                                 f"{width_shown:g}")
    from .. import budget

    budget.check(width * height * 8 + (width + height) * 24, "width x height",
                 f"iteration counts of {width} x {height} pixels")
    step = width_shown / width
    with np.errstate(over="ignore", invalid="ignore"):
        xs = np.asarray(cx + (np.arange(width) + 0.5 - width / 2) * step, np.float64)
        ys = np.asarray(cy + (height / 2 - np.arange(height) - 0.5) * step, np.float64)
    if not (np.isfinite(xs).all() and np.isfinite(ys).all()):
        raise ArgumentValueError("center and span give pixel coordinates beyond float64; "
                                 "use a smaller span or center")
    return width, height, xs, ys


def _counts(width: int, height: int, center: Sequence[float], span: float,
            max_iterations: int, c: Optional[complex]) -> NDArray[np.int64]:
    from .._kernels import fractals as k
    from .._kernels._threads import call_in_bands

    max_iterations = v.positive_int("max_iterations", max_iterations)
    limits.iterations("max_iterations", v.positive_int("width", width)
                      * v.positive_int("height", height), max_iterations)
    width, height, xs, ys = _plane(width, height, center, span)
    out = np.empty((height, width), np.int64)
    julia = c is not None
    cr, ci = (c.real, c.imag) if c is not None else (0.0, 0.0)
    call_in_bands(k.escape_times, width * height * max_iterations // 4, xs, ys,
                  float(cr), float(ci), julia, max_iterations, out)
    return out


def mandelbrot(width: int, height: int, center: Sequence[float] = (-0.5, 0.0),
               span: float = 3.0, max_iterations: int = 256) -> NDArray[np.int64]:
    """Escape-time iteration counts of the Mandelbrot set.

    Parameters
    ----------
    width, height : int
        Pixels.
    center : (float, float)
        The complex number (real, imaginary) at the image's center.
    span : float
        The width of the real axis shown; pixels are square (span / width).
    max_iterations : int
        The most iterations per pixel.

    Returns
    -------
    ndarray of int64, shape (height, width)
        Image order (row 0 at the top, the largest imaginary part).  Pixel (r, k)
        stands for c at its center, x = center[0] + (k + 0.5 - width / 2) span /
        width, y = center[1] + (height / 2 - r - 0.5) span / width; its count is the
        number of iterations of z -> z² + c from z = 0 made while |z| <= 2:
        ``max_iterations`` for a point that did not escape (a member).

    Raises
    ------
    ArgumentValueError
        Sizes or iterations not positive, a span not > 0, or more work than
        :data:`~scanline.fractals.limits.MAX_ITERATIONS`.
    ArgumentTypeError
        A center that is not (real, imaginary).

    Examples
    --------
    >>> import scanline as sl
    >>> counts = sl.fractals.mandelbrot(5, 3, center=(-0.5, 0), span=3.0, max_iterations=50)
    >>> counts.tolist()
    [[3, 4, 50, 50, 3], [50, 50, 50, 50, 3], [3, 4, 50, 50, 3]]
    """
    return _counts(width, height, center, span, max_iterations, None)


def julia(width: int, height: int, c: Complex = complex(-0.8, 0.156),
          center: Sequence[float] = (0.0, 0.0), span: float = 3.0,
          max_iterations: int = 256) -> NDArray[np.int64]:
    """Escape-time iteration counts of the filled Julia set of z -> z² + ``c``: as
    :func:`mandelbrot`, with z starting at each pixel's number and ``c`` fixed (a
    complex number, or (real, imaginary)).

    Parameters
    ----------
    width, height : int
        Pixels.
    c : complex or (float, float)
        The constant of the map.
    center : (float, float)
        The complex number at the image's center.
    span : float
        The width of the real axis shown.
    max_iterations : int
        The most iterations per pixel.

    Returns
    -------
    ndarray of int64, shape (height, width)
        Per pixel, the iterations made while |z| <= 2 (``max_iterations``: a member),
        image order.

    Raises
    ------
    ArgumentTypeError
        ``c`` neither a complex number nor (real, imaginary).
    ArgumentValueError
        A non-finite ``c``, or as :func:`mandelbrot`.

    Examples
    --------
    c = 0: z -> z², whose filled Julia set is the unit disk; pixels at -2, 0 and 2:
    |2| <= 2 allows one iteration (to 4, escaped), 0 never leaves.

    >>> import scanline as sl
    >>> sl.fractals.julia(3, 1, c=0, span=6.0, max_iterations=20).tolist()
    [[1, 20, 1]]
    """
    if isinstance(c, (tuple, list)) and len(c) == 2:
        fixed = complex(v.number("c[0]", c[0]), v.number("c[1]", c[1]))
    elif isinstance(c, numbers.Complex) and not isinstance(c, bool):
        fixed = complex(c)
        if not (np.isfinite(fixed.real) and np.isfinite(fixed.imag)):
            raise ArgumentValueError(f"c must be finite, got {fixed}")
    else:
        raise ArgumentTypeError(f"c must be a complex number or (real, imaginary), got "
                                f"{v._show(c)}")
    return _counts(width, height, center, span, max_iterations, fixed)


def colorize(counts: ArrayLike, max_iterations: int, table: Optional[ArrayLike] = None,
             cycle: bool = False) -> "FrameBuffer":
    """Iteration counts as a mode-``"P"`` :class:`~scanline.FrameBuffer` whose color
    table is ``table`` (any table of :mod:`scanline.color.tables`: ``gray_table``,
    ``web_safe_table``, ``rgb332_table``, ``color_table([...])``).

    Index 0 (the table's first color) marks the members (count ==
    ``max_iterations``); an escaping pixel gets index 1 + floor(count (n - 1) /
    max_iterations) over the table's other n - 1 colors, or, with ``cycle``, 1 +
    count mod (n - 1) (bands that repeat, as the section's color plates do).
    Editing the frame buffer's table recolors the image (color-table animation).

    Parameters
    ----------
    counts : array_like (H, W) of int
        Iteration counts in 0..``max_iterations`` (:func:`mandelbrot`, :func:`julia`).
    max_iterations : int
        The count of a member.
    table : color table, optional
        At least 2 colors (default: :func:`default_table`).
    cycle : bool
        Bands that repeat instead of one ramp.

    Returns
    -------
    FrameBuffer
        Mode "P", the indices in image order.

    Raises
    ------
    ArgumentValueError
        Counts not a non-empty 2-D integer array within 0..max_iterations, or a table
        of fewer than 2 colors.

    Examples
    --------
    Three colors: counts 0 and 5 of 10 go to 1 + floor(c 2 / 10) = 1 and 2, the member
    (10) to 0.

    >>> import numpy as np, scanline as sl
    >>> gray = [(0, 0, 0), (128, 128, 128), (255, 255, 255)]
    >>> sl.fractals.colorize(np.array([[0, 5, 10]]), 10, table=gray).to_array().tolist()
    [[1, 2, 0]]
    """
    from ..color.tables import color_table
    from ..framebuffer import FrameBuffer

    a = np.asarray(counts)
    if a.ndim != 2 or a.size == 0 or a.dtype.kind not in "iu":
        raise ArgumentValueError(f"counts must be a non-empty 2-D array of iteration counts "
                                 f"(mandelbrot's or julia's), got {v._show(counts)}")
    max_iterations = v.positive_int("max_iterations", max_iterations)
    if a.min() < 0 or a.max() > max_iterations:
        raise ArgumentValueError(f"counts must lie in 0..max_iterations ({max_iterations}), "
                                 f"got {int(a.min())}..{int(a.max())}")
    colors = color_table(default_table() if table is None else table, "table")
    n = len(colors)
    if n < 2:
        raise ArgumentValueError("table must have at least 2 colors: one for the set, the "
                                 "others for the escaping points")
    inside = a == max_iterations
    if cycle:
        index = 1 + a % (n - 1)
    else:
        index = 1 + (a.astype(np.int64) * (n - 1)) // max_iterations
    index = np.where(inside, 0, np.minimum(index, n - 1)).astype(np.uint8)
    return FrameBuffer.from_array(index, mode="P", color_table=colors)


def default_table(n: int = 64) -> NDArray[np.uint8]:
    """A color table for :func:`colorize`: black for the set, then dark blue through
    white to orange (``n`` colors).

    Parameters
    ----------
    n : int
        Colors, the first black; the others a ramp through five stops.

    Returns
    -------
    ndarray (n, 3) uint8
        The table.

    Examples
    --------
    Four colors: black, then the ramp at its start, middle and end (the stops
    (0, 7, 100), (237, 255, 255) and (0, 2, 0)).

    >>> import scanline as sl
    >>> sl.fractals.default_table(4).tolist()
    [[0, 0, 0], [0, 7, 100], [237, 255, 255], [0, 2, 0]]
    """
    from ..color.tables import color_table

    stops = np.array([(0, 7, 100), (32, 107, 203), (237, 255, 255), (255, 170, 0),
                      (0, 2, 0)], np.float64)
    t = np.linspace(0, 1, n - 1) * (len(stops) - 1)
    k = np.minimum(t.astype(int), len(stops) - 2)
    f = (t - k)[:, None]
    ramp = stops[k] * (1 - f) + stops[k + 1] * f
    return color_table(np.vstack([[0, 0, 0], np.floor(ramp + 0.5)]).astype(np.uint8))
