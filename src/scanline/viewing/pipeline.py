"""The 2-D viewing pipeline: world -> viewing coordinates (window) -> normalized
device coordinates -> device (viewport).

Matrices are 3x3 with column vectors (``p' = M @ (x, y, 1)``), built from
:mod:`scanline.transform` and composed right to left.

References
----------
D. Hearn, M. P. Baker, "Computer Graphics, C Version", 2nd ed., Prentice Hall,
1997, chapter 6 (sections 6-2 to 6-4: the viewing pipeline, viewing coordinate
reference frame, window-to-viewport coordinate transformation).
"""

import math
from collections.abc import Callable, Iterable, Sized
from typing import TypeVar, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .. import transform as tf
from ..errors import ArgumentTypeError, ArgumentValueError

ALIGNS = ("center", "lower-left")

#: (xmin, ymin, xmax, ymax)
Bounds = tuple[float, float, float, float]


def _rect(name: str, bounds: object) -> Bounds:
    """Four finite numbers with xmin < xmax and ymin < ymax."""
    if (isinstance(bounds, (str, bytes)) or not isinstance(bounds, Sized)
            or not isinstance(bounds, Iterable) or len(bounds) != 4):
        raise ArgumentTypeError(
            f"{name} must be (xmin, ymin, xmax, ymax), got {v._show(bounds)}")
    b = cast(Bounds, tuple(v.number(f"{name}[{i}]", c) for i, c in enumerate(bounds)))
    if not (b[0] < b[2] and b[1] < b[3]):
        raise ArgumentValueError(
            f"{name}={b} is degenerate: it needs xmin < xmax and ymin < ymax (zero width "
            "or height cannot be mapped), e.g. (0, 0, 1, 1)")
    return b


class Rectangle:
    """An upright rectangle ``(xmin, ymin, xmax, ymax)``; base of Window and Viewport."""

    def __init__(self, xmin: float, ymin: float, xmax: float, ymax: float) -> None:
        name = type(self).__name__.lower()
        self.xmin, self.ymin, self.xmax, self.ymax = _rect(name, (xmin, ymin, xmax, ymax))

    @property
    def bounds(self) -> Bounds:
        """``(xmin, ymin, xmax, ymax)``."""
        return (self.xmin, self.ymin, self.xmax, self.ymax)

    @property
    def width(self) -> float:
        """xmax - xmin."""
        return self.xmax - self.xmin

    @property
    def height(self) -> float:
        """ymax - ymin."""
        return self.ymax - self.ymin

    @property
    def aspect(self) -> float:
        """Width / height."""
        return self.width / self.height

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and vars(self) == vars(other)

    def __repr__(self) -> str:
        return f"{type(self).__name__}{self.bounds}"


class Window(Rectangle):
    """The clip window: an upright rectangle in *viewing* coordinates.

    Parameters
    ----------
    xmin, ymin, xmax, ymax : float
        The window in viewing coordinates (with the defaults below, these are world
        coordinates).
    origin : (float, float), default (0, 0)
        Origin P0 of the viewing frame, in world coordinates.
    view_up : (float, float), default (0, 1)
        The view-up vector V, in world coordinates: the viewing frame's y axis.  A
        tilted V gives a rotated window on the world.

    Examples
    --------
    >>> import scanline as sl
    >>> w = sl.viewing.Window(-1, -1, 1, 1, view_up=(-1, 0))   # y axis pointing left
    >>> sl.transform.apply(w.matrix, (0, 1)).round(12).tolist()     # world (0, 1) ...
    [1.0, 0.0]
    """

    def __init__(self, xmin: float, ymin: float, xmax: float, ymax: float,
                 origin: ArrayLike = (0.0, 0.0), view_up: ArrayLike = (0.0, 1.0)) -> None:
        super().__init__(xmin, ymin, xmax, ymax)
        self.matrix = viewing_matrix(origin, view_up)
        self.origin = tf.affine2d._point("origin", origin)
        self.view_up = tf.affine2d._point("view_up", view_up)

    def __eq__(self, other: object) -> bool:
        return (isinstance(other, Window) and type(other) is type(self)
                and self.bounds == other.bounds
                and self.origin == other.origin and self.view_up == other.view_up)

    def corners(self) -> NDArray[np.float64]:
        """The window's corners in world coordinates, counterclockwise from the lower
        left (a rotated rectangle when ``view_up`` is tilted).

        Returns
        -------
        ndarray of float64, shape (4, 2)

        Examples
        --------
        A window on the viewing frame whose origin is the world point (1, 1):

        >>> import scanline as sl
        >>> sl.viewing.Window(0, 0, 2, 1, origin=(1, 1)).corners().tolist()
        [[1.0, 1.0], [3.0, 1.0], [3.0, 2.0], [1.0, 2.0]]
        """
        c = [(self.xmin, self.ymin), (self.xmax, self.ymin),
             (self.xmax, self.ymax), (self.xmin, self.ymax)]
        return tf.apply(tf.inverse(self.matrix), c)

    def __repr__(self) -> str:
        return (f"Window{self.bounds}" if self.origin == (0.0, 0.0) and self.view_up == (0.0, 1.0)
                else f"Window({self.xmin}, {self.ymin}, {self.xmax}, {self.ymax}, "
                f"origin={self.origin}, view_up={self.view_up})")


class Viewport(Rectangle):
    """A viewport: an upright rectangle in normalized device coordinates (the unit
    square) or in device coordinates, depending on where it is used.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.viewing.Viewport(0, 0, 0.5, 1).aspect
    0.5
    """


R = TypeVar("R", bound=Rectangle)


def _as(cls: type[R], name: str, value: object) -> R:
    if isinstance(value, cls):
        return value
    if isinstance(value, Rectangle):
        return cls(*value.bounds)
    return cls(*_rect(name, value))


def viewing_matrix(origin: ArrayLike = (0.0, 0.0),
                   view_up: ArrayLike = (0.0, 1.0)) -> NDArray[np.float64]:
    """World -> viewing coordinates: M = R . T.

    T translates the viewing origin P0 to the world origin; R rotates the unit
    view-up vector v = V / |V| onto the y axis, its first row being
    u = (v_y, -v_x), the viewing x axis::

        R = | v_y  -v_x  0 |     T = | 1  0  -x0 |
            | v_x   v_y  0 |         | 0  1  -y0 |
            |  0     0   1 |         | 0  0   1  |

    Parameters
    ----------
    origin : (float, float)
        P0 = (x0, y0), world coordinates.
    view_up : (float, float)
        V, any nonzero length.

    Returns
    -------
    ndarray, shape (3, 3)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``origin`` or ``view_up`` is not two finite numbers, or ``view_up`` is (0, 0).

    Notes
    -----
    Notes, syllabus "2-D Viewing: the viewing pipeline, viewing coordinate
    reference frame"; Hearn & Baker, section 6-3.

    Examples
    --------
    >>> m = viewing_matrix((2, 1), (0, 1))      # just a translation
    >>> m.tolist()
    [[1.0, 0.0, -2.0], [0.0, 1.0, -1.0], [0.0, 0.0, 1.0]]
    """
    x0, y0 = tf.affine2d._point("origin", origin)
    vx, vy = tf.affine2d._point("view_up", view_up)
    length = math.hypot(vx, vy)
    if length == 0.0 or not math.isfinite(length):
        raise ArgumentValueError(
            f"view_up must be a nonzero vector such as (0, 1), got {v._show(view_up)}")
    vx, vy = vx / length, vy / length
    r = np.array([[vy, -vx, 0.0], [vx, vy, 0.0], [0.0, 0.0, 1.0]]) + 0.0
    return tf.compose(r, tf.translation(-x0, -y0))


def window_to_viewport(window: Window | Viewport | ArrayLike, viewport: Viewport | ArrayLike,
                       keep_aspect: bool = False,
                       align: str = "center") -> NDArray[np.float64]:
    """Viewing coordinates in ``window`` -> coordinates in ``viewport``.

    ::

        xv = xvmin + (xw - xwmin) sx,   sx = (xvmax - xvmin) / (xwmax - xwmin)
        yv = yvmin + (yw - ywmin) sy,   sy = (yvmax - yvmin) / (ywmax - ywmin)

    that is, M = T(xvmin, yvmin) . S(sx, sy) . T(-xwmin, -ywmin).

    Parameters
    ----------
    window, viewport : Window, Viewport or (xmin, ymin, xmax, ymax)
        The window (viewing coordinates) and the viewport it is mapped onto, each with
        xmin < xmax and ymin < ymax.
    keep_aspect : bool
        False (default): the window fills the viewport, stretched if their aspect
        ratios differ.  True: both scales are min(sx, sy), so shapes keep their
        proportions, and the window lands in a sub-rectangle of the viewport
        (letterbox), placed by ``align``.
    align : {"center", "lower-left"}
        Where the letterboxed window sits in the viewport.

    Returns
    -------
    ndarray, shape (3, 3)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If a rectangle is not four finite numbers with xmin < xmax and ymin < ymax,
        ``align`` is not one of :data:`ALIGNS`, or the scale factors overflow.

    Notes
    -----
    Notes, syllabus "Windows to view ports co-ordinate transformation"; Hearn &
    Baker, section 6-4.

    Examples
    --------
    >>> import scanline as sl
    >>> m = window_to_viewport((0, 0, 10, 5), (100, 100, 300, 200))
    >>> sl.transform.apply(m, [(0, 0), (10, 5), (5, 2.5)]).tolist()
    [[100.0, 100.0], [300.0, 200.0], [200.0, 150.0]]
    >>> m = window_to_viewport((0, 0, 10, 5), (0, 0, 100, 100), keep_aspect=True)
    >>> sl.transform.apply(m, [(0, 0), (10, 5)]).tolist()     # centered letterbox
    [[0.0, 25.0], [100.0, 75.0]]
    """
    (sx, sy), (ox, oy), w = _scales(window, viewport, keep_aspect, align)
    return tf.compose(tf.translation(ox, oy), tf.scaling(sx, sy),
                      tf.translation(-w.xmin, -w.ymin))


def _scales(window: object, viewport: object, keep_aspect: bool,
            align: str) -> tuple[tuple[float, float], tuple[float, float], Rectangle]:
    """``(sx, sy)``, where the window's lower-left corner lands, and the window."""
    w = _as(Rectangle, "window", window)
    vp = _as(Rectangle, "viewport", viewport)
    v.choice("align", align, ALIGNS)
    sx = vp.width / w.width
    sy = vp.height / w.height
    if not (0 < sx < math.inf and 0 < sy < math.inf):
        raise ArgumentValueError(
            f"window={w.bounds} cannot be mapped to viewport={vp.bounds}: the scale "
            f"factors ({sx:g}, {sy:g}) overflow or vanish in floating point; use window "
            "and viewport sizes within a factor of about 1e300 of each other")
    ox = oy = 0.0
    if keep_aspect:
        sx = sy = min(sx, sy)
        if align == "center":
            ox = (vp.width - sx * w.width) / 2
            oy = (vp.height - sy * w.height) / 2
    return (sx, sy), (vp.xmin + ox, vp.ymin + oy), w


def ndc_to_device(width: int, height: int) -> NDArray[np.float64]:
    """Normalized device coordinates (the unit square) -> device coordinates of a
    ``width`` x ``height`` frame buffer.

    NDC (0, 0) goes to the center of the bottom-left pixel (0, 0) and (1, 1) to the
    center of the top-right pixel (width - 1, height - 1), so a window's boundary
    lands on the outermost pixels rather than half a pixel outside them.

    Parameters
    ----------
    width, height : int
        The frame buffer's size in pixels, each at least 2.

    Returns
    -------
    ndarray of float64, shape (3, 3)
        The scaling S(width - 1, height - 1).

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``width`` or ``height`` is not an integer >= 2.

    Notes
    -----
    The last stage of the viewing pipeline (Hearn & Baker, section 6-2).

    Examples
    --------
    >>> import scanline as sl
    >>> sl.transform.apply(ndc_to_device(101, 51), (0.5, 1)).tolist()
    [50.0, 50.0]
    """
    w = v.positive_int("width", width, 2)
    h = v.positive_int("height", height, 2)
    return tf.scaling(w - 1, h - 1)


def tile(rows: int, columns: int, bounds: ArrayLike = (0.0, 0.0, 1.0, 1.0),
         gap: float = 0.0) -> list[Viewport]:
    """Viewports that tile ``bounds`` in a grid, row by row from the top left.

    Use it to put several views on one frame buffer (``gap`` is the space between
    neighbors, in the units of ``bounds``).

    Parameters
    ----------
    rows, columns : int
        The grid's size, each at least 1.
    bounds : (xmin, ymin, xmax, ymax), default (0, 0, 1, 1)
        The rectangle to tile (the unit square of normalized device coordinates).
    gap : float, default 0
        The space between neighboring viewports, >= 0.

    Returns
    -------
    list of Viewport
        ``rows * columns`` viewports, row by row from the top left.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``rows`` or ``columns`` is not a positive integer, ``bounds`` is not a
        rectangle, or ``gap`` is negative or leaves no room for the viewports.

    Examples
    --------
    >>> [vp.bounds for vp in tile(1, 2, gap=0.1)]
    [(0.0, 0.0, 0.45, 1.0), (0.55, 0.0, 1.0, 1.0)]
    """
    r = v.positive_int("rows", rows)
    c = v.positive_int("columns", columns)
    xmin, ymin, xmax, ymax = _rect("bounds", bounds)
    g = v.number("gap", gap)
    cw = (xmax - xmin - (c - 1) * g) / c
    ch = (ymax - ymin - (r - 1) * g) / r
    if g < 0 or cw <= 0 or ch <= 0:
        raise ArgumentValueError(
            f"gap={gap!r} must be >= 0 and leave room for {r} x {c} viewports in "
            f"{v._show(bounds)}")
    out: list[Viewport] = []
    for i in range(r):
        top = ymax - i * (ch + g)
        for j in range(c):
            left = xmin + j * (cw + g)
            out.append(Viewport(left, top - ch, left + cw, top))
    return out


def device_viewport(viewport: Viewport | ArrayLike, width: int, height: int) -> Viewport:
    """A viewport given in normalized device coordinates, in device coordinates of a
    ``width`` x ``height`` frame buffer (see :func:`ndc_to_device`).

    Parameters
    ----------
    viewport : Viewport or (xmin, ymin, xmax, ymax)
        The viewport in normalized device coordinates.
    width, height : int
        The frame buffer's size in pixels, each at least 2.

    Returns
    -------
    Viewport
        The same viewport in device coordinates.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``viewport`` is not a rectangle or the size is not two integers >= 2.

    Examples
    --------
    >>> device_viewport((0, 0, 0.5, 1), 101, 51)
    Viewport(0.0, 0.0, 50.0, 50.0)
    """
    vp = _as(Viewport, "viewport", viewport)
    (x0, y0), (x1, y1) = tf.apply(ndc_to_device(width, height),
                                  [(vp.xmin, vp.ymin), (vp.xmax, vp.ymax)]).tolist()
    return Viewport(x0, y0, x1, y1)


class View:
    """One window shown in one viewport: the whole pipeline as one object.

    ``matrix`` maps world coordinates to viewport coordinates:
    M = M_window-to-viewport . M_viewing (= R . T, see :func:`viewing_matrix`).
    Clipping happens in viewing coordinates, against the upright window, before
    the mapping, as in the notes' pipeline.

    Parameters
    ----------
    window : Window or (xmin, ymin, xmax, ymax)
    viewport : Viewport or (xmin, ymin, xmax, ymax)
        In the coordinates the view should produce (device coordinates to draw into
        a frame buffer; see :func:`device_viewport` for NDC viewports).
    keep_aspect : bool, default False
        Keep the window's proportions (letterbox); see :func:`window_to_viewport`.
    align : {"center", "lower-left"}, default "center"
        Where a letterboxed window sits; see :func:`window_to_viewport`.

    Examples
    --------
    >>> import scanline as sl
    >>> view = sl.viewing.View((0, 0, 10, 10), (0, 0, 20, 20))
    >>> seg, ok = view.clip_lines([(-5, 5, 5, 5)])
    >>> seg.tolist(), ok.tolist()
    ([[0.0, 10.0, 10.0, 10.0]], [True])
    """

    def __init__(self, window: Window | ArrayLike, viewport: Viewport | ArrayLike,
                 keep_aspect: bool = False, align: str = "center") -> None:
        self.window = _as(Window, "window", window)
        self.viewport = _as(Viewport, "viewport", viewport)
        self.window_to_viewport = window_to_viewport(self.window, self.viewport,
                                                     keep_aspect, align)
        self.matrix = tf.compose(self.window_to_viewport, self.window.matrix)
        # The inverse, factor by factor (exact for any scales): T(P0) R^T for the
        # viewing frame, T(xwmin, ywmin) S(1/sx, 1/sy) T(-xv, -yv) for the mapping.
        (sx, sy), (ox, oy), w = _scales(self.window, self.viewport, keep_aspect, align)
        r = self.window.matrix[:2, :2]
        frame = np.eye(3)
        frame[:2, :2] = r.T
        frame[:2, 2] = self.window.origin
        self.inverse = tf.compose(frame, tf.translation(w.xmin, w.ymin),
                                  tf.scaling(1 / sx, 1 / sy), tf.translation(-ox, -oy))

    def to_viewport(self, points: ArrayLike) -> NDArray[np.float64]:
        """World points -> viewport coordinates.

        Parameters
        ----------
        points : array_like, shape (N, 2) or (2,)
            Finite world points.

        Returns
        -------
        ndarray of float64, shape (N, 2) or (2,)
            ``matrix`` applied to the points.

        Examples
        --------
        >>> import scanline as sl
        >>> sl.viewing.View((0, 0, 10, 10), (0, 0, 20, 20)).to_viewport((5, 5)).tolist()
        [10.0, 10.0]
        """
        return tf.apply(self.matrix, points)

    def to_world(self, points: ArrayLike) -> NDArray[np.float64]:
        """Viewport coordinates -> world points (the round trip of
        :meth:`to_viewport`).

        Parameters
        ----------
        points : array_like, shape (N, 2) or (2,)
            Finite points in viewport coordinates.

        Returns
        -------
        ndarray of float64, shape (N, 2) or (2,)
            ``inverse`` applied to the points.

        Examples
        --------
        >>> import scanline as sl
        >>> sl.viewing.View((0, 0, 10, 10), (0, 0, 20, 20)).to_world((10, 20)).tolist()
        [5.0, 10.0]
        """
        return tf.apply(self.inverse, points)

    def clip_lines(self, segments: ArrayLike, method: str = "liang-barsky"
                   ) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
        """World segments (N, 4) clipped by the window and mapped to the viewport:
        ``(segments, accepted)`` as :func:`scanline.clip.lines` returns them.

        Parameters
        ----------
        segments : array_like, shape (N, 4)
            Segments (x0, y0, x1, y1) in world coordinates.
        method : {"liang-barsky", "cohen-sutherland", "cyrus-beck"}, default "liang-barsky"
            The line-clipping algorithm (:func:`scanline.clip.lines`).

        Returns
        -------
        segments : ndarray of float64, shape (N, 4)
            The clipped segments in viewport coordinates.
        accepted : ndarray of bool, shape (N,)
            Whether each segment has a part inside the window.

        Raises
        ------
        ArgumentValueError
            If ``method`` is not a line-clipping algorithm or the segments are not finite.

        Notes
        -----
        Clipping in viewing coordinates against the upright window, then the
        window-to-viewport mapping (Hearn & Baker, sections 6-2 and 6-7).

        Examples
        --------
        >>> import scanline as sl
        >>> view = sl.viewing.View((0, 0, 10, 10), (0, 0, 20, 20))
        >>> seg, ok = view.clip_lines([(5, 5, 15, 5), (11, 0, 11, 9)])
        >>> seg[ok].tolist(), ok.tolist()
        ([[10.0, 10.0, 20.0, 10.0]], [True, False])
        """
        from .. import clip

        clip_lines = cast(
            Callable[[NDArray[np.float64], Bounds, str],
                     tuple[NDArray[np.float64], NDArray[np.bool_]]], clip.lines)
        seg = np.asarray(segments, np.float64).reshape(-1, 4)
        ends = tf.apply(self.window.matrix, seg.reshape(-1, 2)).reshape(-1, 4)
        out, ok = clip_lines(ends, self.window.bounds, method)
        return tf.apply(self.window_to_viewport, out.reshape(-1, 2)).reshape(-1, 4), ok

    def clip_polygon(self, points: ArrayLike, method: str = "sutherland-hodgman"
                     ) -> list[NDArray[np.float64]]:
        """A world polygon clipped by the window, as contours in the viewport.

        Parameters
        ----------
        points : array_like, shape (N, 2), or a list of such contours
            The polygon in world coordinates.
        method : str, default "sutherland-hodgman"
            The polygon-clipping algorithm (:func:`scanline.clip.polygon`).

        Returns
        -------
        list of ndarray of float64, shape (M, 2)
            The clipped contours in viewport coordinates (none when the polygon misses
            the window).

        Raises
        ------
        ArgumentValueError
            If ``method`` is not a polygon-clipping algorithm or the points are not a
            polygon.

        Notes
        -----
        Hearn & Baker, section 6-8 (polygon clipping).

        Examples
        --------
        The square (5, 5)-(15, 15) keeps its corner (5, 5)-(10, 10), which the viewport
        doubles (counterclockwise, from the world point (5, 10) where the window's top
        edge cuts the square):

        >>> import scanline as sl
        >>> view = sl.viewing.View((0, 0, 10, 10), (0, 0, 20, 20))
        >>> [c.tolist() for c in view.clip_polygon([(5, 5), (15, 5), (15, 15), (5, 15)])]
        [[[10.0, 20.0], [10.0, 10.0], [20.0, 10.0], [20.0, 20.0]]]
        """
        from .. import clip
        from ..geometry.contours import contours

        clip_polygon = cast(Callable[[list[NDArray[np.float64]], Bounds, str],
                                     list[NDArray[np.float64]]], clip.polygon)

        verts, offsets = contours("points", points)
        local = tf.apply(self.window.matrix, verts) if len(verts) else verts
        rings = [local[offsets[c]:offsets[c + 1]] for c in range(len(offsets) - 1)]
        return [tf.apply(self.window_to_viewport, c)
                for c in clip_polygon(rings, self.window.bounds, method)]
