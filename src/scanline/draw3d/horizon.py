"""The floating-horizon method for surfaces z = f(x, y) (Wright 1973; Rogers,
*Procedural Elements for Computer Graphics*, section 4-2; Hearn & Baker, section
13-10, "surfaces given as functions").

*Image precision*: the horizons are kept per screen column.
"""

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Callable, Literal, Optional, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._typing import Color
from ..draw._common import target
from ..errors import ArgumentTypeError, ArgumentValueError

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer
    from ..projection import Camera

#: Heights on a grid, or a function f(x, y).
Surface = Union[ArrayLike, Callable[..., Any]]
#: A camera, or (azimuth, elevation) in radians.
View = Union["Camera", Tuple[float, float]]
#: The grid's lines drawn as curves.
Curves = Literal["rows", "columns"]

#: Default view of ``camera_or_angles``: azimuth and elevation, radians.
ANGLES = (math.radians(30.0), math.radians(30.0))
#: Samples per axis when ``z`` is a function and ``x``/``y`` are not given.
SAMPLES = 41


@dataclass
class Horizon:
    """What :func:`floating_horizon` computed.

    Parameters
    ----------
    segments, upper, lower, states, curves, points : ndarray
        As listed under Attributes.

    Examples
    --------
    A flat plane seen from above: each farther row lies higher on the screen, so
    every curve is visible (1) wherever it has samples (2: none), nearest row first.

    >>> import numpy as np, scanline as sl
    >>> h = sl.draw3d.horizon(np.zeros((3, 3)), camera_or_angles=(0.0, 0.5), width=20, height=20)
    >>> np.unique(h.states).tolist(), h.curves.tolist()
    ([1, 2], [0, 1, 2])

    Attributes
    ----------
    segments : ndarray, shape (K, 4)
        The visible pieces drawn (device x0, y0, x1, y1).
    upper, lower : ndarray, shape (width,)
        The final horizons (-inf / +inf where no curve reached the column).
    states : ndarray of int8, shape (curves, width)
        Per curve (in the order processed, nearest first) and column: 1 visible
        above the upper horizon, -1 below the lower one, 0 hidden, 2 no sample.
    curves : ndarray of int64
        The grid row (or column) of each processed curve.
    points : ndarray, shape (ny, nx, 3)
        The device x, y and depth of every grid point.
    """

    segments: NDArray[np.float64]
    upper: NDArray[np.float64]
    lower: NDArray[np.float64]
    states: NDArray[np.int8]
    curves: NDArray[np.int64]
    points: NDArray[np.float64]


def _grid(z: Surface, x: Optional[ArrayLike], y: Optional[ArrayLike]
          ) -> Tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    if callable(z):
        xs = np.linspace(-1.0, 1.0, SAMPLES) if x is None else _axis("x", x)
        ys = np.linspace(-1.0, 1.0, SAMPLES) if y is None else _axis("y", y)
        gx, gy = np.meshgrid(xs, ys)
        with np.errstate(all="ignore"):
            try:
                zz = np.broadcast_to(np.asarray(z(gx, gy), np.float64), gx.shape).copy()
            except (TypeError, ValueError):
                zz = np.array([[float(z(a, b)) for a in xs] for b in ys])
    else:
        zz = v.real_array("z", z, "(ny, nx)")
        if zz.ndim != 2 or zz.shape[0] < 2 or zz.shape[1] < 2:
            raise ArgumentValueError(f"z must be an (ny, nx) grid, ny, nx >= 2, or a function "
                                     f"f(x, y); got shape {zz.shape}")
        xs = np.linspace(-1.0, 1.0, zz.shape[1]) if x is None else _axis("x", x)
        ys = np.linspace(-1.0, 1.0, zz.shape[0]) if y is None else _axis("y", y)
        if (len(ys), len(xs)) != zz.shape:
            raise ArgumentValueError(f"x and y must have {zz.shape[1]} and {zz.shape[0]} "
                                     f"values for z of shape {zz.shape}; got {len(xs)}, {len(ys)}")
    bad = ~np.isfinite(zz)
    if bad.any():
        i, j = np.argwhere(bad)[0]
        raise ArgumentValueError(
            f"z is not finite at x={xs[j]:g}, y={ys[i]:g} (grid row {i}, column {j}): "
            f"{zz[i, j]}; the surface must be defined everywhere on the grid (mask "
            "the holes with a finite value)")
    return xs, ys, zz


def _axis(name: str, value: ArrayLike) -> NDArray[np.float64]:
    a = v.real_array(name, value, "(n,)")
    if a.ndim != 1 or len(a) < 2 or not np.isfinite(a).all() or not (np.diff(a) > 0).all():
        raise ArgumentValueError(f"{name} must be at least two finite, increasing values, "
                                 f"got {v._show(np.asarray(value).tolist())}")
    return a


def _camera(camera_or_angles: View, xs: NDArray[np.float64], ys: NDArray[np.float64],
            zz: NDArray[np.float64]) -> "Camera":
    from ..projection import Camera, orthographic

    if isinstance(camera_or_angles, Camera):
        return camera_or_angles
    if not (isinstance(camera_or_angles, (tuple, list)) and len(camera_or_angles) == 2):
        raise ArgumentTypeError(
            "camera_or_angles must be a scanline.Camera or (azimuth, elevation) in "
            f"radians, got {v._show(camera_or_angles)}")
    az = v.number("azimuth", camera_or_angles[0])
    el = v.number("elevation", camera_or_angles[1])
    if not -math.pi / 2 < el < math.pi / 2:
        raise ArgumentValueError(f"elevation must lie strictly between -pi/2 and pi/2, got {el}")
    lo = np.array([xs[0], ys[0], zz.min()])
    hi = np.array([xs[-1], ys[-1], zz.max()])
    center = (lo + hi) / 2
    # the viewer at azimuth az (from -y toward +x, about z) and elevation el
    d = np.array([math.sin(az) * math.cos(el), -math.cos(az) * math.cos(el), math.sin(el)])
    size = float(np.linalg.norm(hi - lo)) or 1.0
    cam = Camera(eye=center + 4 * size * d, target=center, up=(0, 0, 1),
                 projection=orthographic(window=(-1, -1, 1, 1)))
    corners = np.array([[a, b, c] for a in (lo[0], hi[0]) for b in (lo[1], hi[1])
                        for c in (lo[2], hi[2])])
    view = cam.to_viewing(corners)
    (x0, y0), (x1, y1) = view[:, :2].min(axis=0), view[:, :2].max(axis=0)
    m = 0.04 * max(x1 - x0, y1 - y0, 1e-12)
    zmin, zmax = view[:, 2].min(), view[:, 2].max()
    return Camera(eye=center + 4 * size * d, target=center, up=(0, 0, 1),
                  projection=orthographic(window=(x0 - m, y0 - m, x1 + m, y1 + m),
                                          front=zmax + size, back=zmin - size))


def _run(xs: NDArray[np.float64], ys: NDArray[np.float64], single: bool = False) -> Tuple[int,
         int, NDArray[np.float64], NDArray[np.float64]]:
    """One run: (c0, count, ylo, yhi) of the polyline (xs increasing) sampled at
    integer columns, or a vertical stroke when it spans no column or ``single``."""
    c0 = math.ceil(xs[0])
    c1 = math.floor(xs[-1])
    if c1 - c0 >= 1 and not single:
        cols = np.arange(c0, c1 + 1, dtype=np.float64)
        y = np.interp(cols, xs, ys)
        return c0, len(cols), y, y
    c = int(round(float(np.mean(xs))))
    return c, 1, np.array([float(np.min(ys))]), np.array([float(np.max(ys))])


def horizon_runs(points: NDArray[np.float64], curves: Curves = "rows",
                 side_edges: bool = True
                 ) -> Tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.float64],
                         NDArray[np.float64], NDArray[np.int64]]:
    """The groups and runs the kernel processes, from device ``points`` (ny, nx, 3):
    ``(groups, runs, ylo, yhi, order)`` (see :mod:`scanline._kernels.horizon`).
    Curves go nearest first (by mean depth); each group holds the side edges
    joining the curve's ends to the previous curve's, then the curve."""
    v.choice("curves", curves, ("rows", "columns"))
    p = points if curves == "rows" else points.transpose(1, 0, 2)
    order = np.argsort(p[:, :, 2].mean(axis=1), kind="stable")
    groups = [0]
    runs: list[Tuple[int, int, int]] = []
    lo: list[NDArray[np.float64]] = []
    hi: list[NDArray[np.float64]] = []
    start = 0
    prev: Optional[Tuple[Tuple[float, float], Tuple[float, float]]] = None
    for i in order.tolist():
        cx, cy = p[i, :, 0], p[i, :, 1]
        if not (np.isfinite(cx).all() and np.isfinite(cy).all()):
            raise ArgumentValueError(
                "the surface reaches behind the camera's eye; move the camera back")
        dx = np.diff(cx)
        if (dx < 0).all():
            cx, cy = cx[::-1], cy[::-1]
        elif not (dx > 0).all():
            raise ArgumentValueError(
                f"curve {i} of the surface does not project to increasing screen x (it "
                "folds back on itself in this view); the floating horizon needs curves "
                f"that do: use curves={'columns' if curves == 'rows' else 'rows'!r} or "
                "another azimuth")
        pieces: list[Tuple[int, int, NDArray[np.float64], NDArray[np.float64]]] = []
        if side_edges and prev is not None:
            for a, b in ((prev[0], (cx[0], cy[0])), (prev[1], (cx[-1], cy[-1]))):
                (xa, ya), (xb, yb) = sorted([a, b])
                pieces.append(_run(np.array([xa, xb]), np.array([ya, yb]),
                                   single=math.floor(max(xa, xb)) - math.ceil(min(xa, xb)) < 1))
        pieces.append(_run(cx, cy))
        for c0, n, ylo, yhi in pieces:
            runs.append((c0, n, start))
            lo.append(ylo)
            hi.append(yhi)
            start += n
        groups.append(len(runs))
        prev = ((cx[0], cy[0]), (cx[-1], cy[-1]))
    return (np.array(groups, np.int64), np.array(runs, np.int64).reshape(-1, 3),
            np.ascontiguousarray(np.concatenate(lo)), np.ascontiguousarray(np.concatenate(hi)),
            order)


def floating_horizon(fb: "FrameBuffer", z: Surface, x: Optional[ArrayLike] = None,
                     y: Optional[ArrayLike] = None, camera_or_angles: View = ANGLES,
                     color: Color = "white", curves: Curves = "rows", side_edges: bool = True,
                     **line: Any) -> Horizon:
    """Plot the surface z = f(x, y) as curves with hidden parts removed by the
    floating-horizon method.

    Parameters
    ----------
    fb : FrameBuffer
        Drawn into.
    z : (ny, nx) array_like or callable
        The heights on the grid (row i at y[i], column j at x[j]), or f(x, y)
        (vectorized over numpy arrays, or called point by point).
    x, y : array_like, optional
        Increasing grid coordinates (default: -1..1; 41 samples for a function).
    camera_or_angles : Camera or (azimuth, elevation)
        A camera, or an orthographic view from azimuth (about z, from -y toward
        +x) and elevation (radians), fitted to the frame buffer.
    color : color
        The curves' color.
    curves : {"rows", "columns"}
        Plot the curves of constant y (rows) or of constant x.
    side_edges : bool
        Join the ends of each curve to the previous curve's (Rogers' fix of the edge
        effect: without it a curve that reaches beyond the previous ones at the sides
        is compared with an undefined horizon there and drawn where the surface's
        edge hides it).
    **line
        Attributes of :func:`scanline.draw.lines` (width, antialias, ...).

    Returns
    -------
    Horizon
        The segments drawn, the horizons and each curve's states.

    Raises
    ------
    ArgumentTypeError
        ``fb`` not a FrameBuffer, or ``camera_or_angles`` neither a Camera nor a pair.
    ArgumentValueError
        A grid that is not (ny, nx) with ny, nx >= 2, axes that are not increasing, a
        surface not finite on the grid, an elevation outside (-pi/2, pi/2), an unknown
        ``curves``, or curves that fold back on themselves in this view.

    Notes
    -----
    Wright (1973); Rogers, section 4-2.  The curves of constant y (or x) are
    projected and processed from the nearest to the farthest.  Two arrays hold, for
    every screen column, the highest (upper horizon) and lowest (lower horizon)
    screen y reached so far.  Each curve is evaluated at every screen column it
    spans (linear interpolation between its projected points: the horizon lives at
    the screen's resolution); between columns c and c + 1 the curve and both
    horizons are interpolated linearly, and the parts of the curve above the upper
    or below the lower horizon are drawn, cut exactly where they cross it (so a curve
    entering or leaving the horizon between two columns does not jump a column: the
    aliasing Rogers describes).  Then the horizons are raised to the curve.  The
    edge effect is handled by the side edges (``side_edges``).  The horizon arrays
    give image precision.

    References
    ----------
    T. J. Wright, "A two-space solution to the hidden line problem for plotting
    functions of two variables", IEEE Transactions on Computers C-22(1), 28-33,
    1973.  D. F. Rogers, *Procedural Elements for Computer Graphics*, 2nd ed.,
    McGraw-Hill, 1998, section 4-2 (the floating horizon algorithm).

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> fb = sl.FrameBuffer(120, 90, background="white")
    >>> h = sl.draw3d.floating_horizon(fb, lambda x, y: np.exp(-4 * (x * x + y * y)),
    ...                                color="black")
    >>> h.states.shape
    (41, 120)
    """
    from ..draw import lines as draw_lines

    target(fb)
    h = horizon(z, x, y, camera_or_angles, fb.width, fb.height, curves, side_edges)
    if len(h.segments):
        draw_lines(fb, h.segments, color=color, **line)
    return h


def horizon(z: Surface, x: Optional[ArrayLike] = None, y: Optional[ArrayLike] = None,
            camera_or_angles: View = ANGLES, width: int = 640, height: int = 480,
            curves: Curves = "rows", side_edges: bool = True) -> Horizon:
    """The floating horizon of :func:`floating_horizon` on a ``width`` x ``height``
    device without drawing: a :class:`Horizon`.

    Parameters
    ----------
    z : (ny, nx) array_like or callable
        The heights, or f(x, y).
    x, y : array_like, optional
        Increasing grid coordinates.
    camera_or_angles : Camera or (azimuth, elevation)
        The view.
    width, height : int
        The device's size, at least 2.
    curves : {"rows", "columns"}
        Which curves.
    side_edges : bool
        Join the curves' ends (Rogers' edge fix).

    Returns
    -------
    Horizon
        What the method found (Hearn & Baker 13-10; Wright 1973).

    Raises
    ------
    ArgumentValueError
        A bad grid, size or curve choice.

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> h = sl.draw3d.horizon(np.zeros((3, 3)), camera_or_angles=(0.0, 0.5), width=20, height=20)
    >>> h.states.shape, h.upper.shape
    ((3, 20), (20,))
    """
    from .._kernels import horizon as k
    from .._kernels._jit import call

    w = v.positive_int("width", width, 2)
    hgt = v.positive_int("height", height, 2)
    xs, ys, zz = _grid(z, x, y)
    cam = _camera(camera_or_angles, xs, ys, zz)
    gx, gy = np.meshgrid(xs, ys)
    pts = cam.project(np.stack([gx, gy, zz], axis=-1).reshape(-1, 3), w, hgt)
    pts = pts.reshape(len(ys), len(xs), 3)
    groups, runs, ylo, yhi, order = horizon_runs(pts, curves, side_edges)
    upper = np.full(w, -np.inf)
    lower = np.full(w, np.inf)
    states = np.empty((len(groups) - 1, w), np.int8)
    segs = np.empty((2 * len(ylo) + 16, 4))
    while True:
        a, b = upper.copy(), lower.copy()
        n = call(k.floating_horizon, 3 * len(ylo) + 2 * w * len(groups), groups, runs, ylo,
                 yhi, a, b, np.empty(w), np.empty(w), segs, states)
        if n <= len(segs):
            break
        segs = np.empty((n, 4))
    return Horizon(segs[:n].copy(), a, b, states, order.astype(np.int64), pts)
