"""Parallel and perspective projections with their view volumes (Hearn & Baker,
section 12-3).

Every projection is a :class:`Projection`: its :attr:`~Projection.matrix` is the
textbook's 4x4 matrix, acting on viewing coordinates (x_v right, y_v up, z_v toward
the viewer, who looks along -z_v); ``numpy.asarray(projection)`` is that matrix too,
so ``scanline.transform3d.apply(projection, points)`` gives projected points.  A
projection also holds its *view volume*: the window on the view plane z_v = z_vp
and the front and back clipping planes z_v = front and z_v = back (front > back),
and :attr:`~Projection.normalization` maps that volume onto the normalized view
volume, the unit cube of normalized device coordinates (NDC) in homogeneous clip
coordinates:

* x_n, y_n from 0 to 1 across the window (x right, y up);
* z_n, the depth, from 0 on the front plane to 1 on the back plane: it grows away
  from the viewer (Hearn & Baker's normalized volume is a left-handed system; the
  notes' glossary, "Z-buffer": the closer the point, the smaller its z);
* a point is inside when 0 <= x_h, y_h, z_h <= w (clipping before the divide).

Parallel projections keep z (Hearn & Baker: "the original z-coordinate value is
kept for the depth information"); the perspective projection's matrix is Hearn &
Baker's M_pers, whose result lies on the view plane (z_p = z_vp), and its
normalization replaces z by a pseudo-depth that keeps the order of depths.

References
----------
.. [1] D. Hearn and M. P. Baker, *Computer Graphics, C Version*, 2nd ed., Prentice
   Hall, 1997, sections 12-1 and 12-3 (parallel, oblique and perspective
   projections, general parallel- and perspective-projection transformations,
   normalized view volumes).
.. [2] D. F. Rogers and J. A. Adams, *Mathematical Elements for Computer Graphics*,
   2nd ed., McGraw-Hill, 1990, section 3-9 (axonometric projections: trimetric,
   dimetric, isometric, foreshortening factors).
.. [3] J. F. Blinn and M. E. Newell, "Clipping using homogeneous coordinates",
   SIGGRAPH '78, 245-251, 1978.
"""

import math
from collections.abc import Iterable, Sequence
from typing import Any, cast

import numpy as np
from numpy.typing import ArrayLike, DTypeLike, NDArray

from .. import _validate as v
from .. import transform3d as t3
from .._typing import Angle
from ..errors import ArgumentTypeError, ArgumentValueError

KINDS = ("parallel", "perspective")

#: The standard views of :func:`orthographic`: the direction from the object to the
#: viewer and the view-up vector, in a world with y up (Hearn & Baker's figures):
#: elevations (front, rear, left and right side) and plan views (top, bottom).
VIEWS = {
    "front": ((0.0, 0.0, 1.0), (0.0, 1.0, 0.0)),
    "rear": ((0.0, 0.0, -1.0), (0.0, 1.0, 0.0)),
    "right": ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0)),
    "left": ((-1.0, 0.0, 0.0), (0.0, 1.0, 0.0)),
    "top": ((0.0, 1.0, 0.0), (0.0, 0.0, -1.0)),
    "bottom": ((0.0, -1.0, 0.0), (0.0, 0.0, 1.0)),
}
#: "side" is the right side view.
VIEW_NAMES = tuple(VIEWS) + ("side",)

#: tan(alpha) of the named oblique projections: cavalier (alpha = 45 degrees, lines
#: perpendicular to the view plane keep their length) and cabinet (tan alpha = 2,
#: they are drawn at half length).
OBLIQUE = {"cavalier": 1.0, "cabinet": 2.0}

#: The window of a projection when none is given.
DEFAULT_WINDOW = (-1.0, -1.0, 1.0, 1.0)
#: A parallel view volume without front and back planes reaches this many window
#: diagonals in front of and behind the view plane.
DEFAULT_DEPTH = 1000.0


def _window(window: object) -> tuple[float, float, float, float]:
    if isinstance(window, (str, bytes)) or not hasattr(window, "__len__") or len(window) != 4:
        raise ArgumentTypeError(
            f"window must be (xmin, ymin, xmax, ymax) on the view plane, got {v._show(window)}")
    w = cast("tuple[float, float, float, float]",
             tuple(v.number(f"window[{i}]", c)
                   for i, c in enumerate(cast("Sequence[object]", window))))
    if not (w[0] < w[2] and w[1] < w[3]) or not all(
            math.isfinite(d) and d > 0 for d in (w[2] - w[0], w[3] - w[1])):
        raise ArgumentValueError(
            f"window={w} is degenerate: it needs xmin < xmax and ymin < ymax, e.g. "
            "(-1, -1, 1, 1)")
    return w


def frame(direction: ArrayLike, up: ArrayLike, name: str = "direction",
          up_name: str = "up") -> NDArray[np.float64]:
    """The rotation (4x4) whose rows are the unit vectors u, v, n of a viewing frame
    with n along ``direction`` and v the part of ``up`` perpendicular to n (Hearn &
    Baker, section 12-2: n = N / |N|, u = V x n / |V x n|, v = n x u)."""
    from ..transform3d.arrays import direction as unit

    n = unit(name, direction)
    upv = unit(up_name, up)
    u = np.cross(upv, n)
    length = float(np.sqrt(u @ u))
    if not length > 1e-9:
        raise ArgumentValueError(
            f"{up_name}={v._show(tuple(cast('Iterable[object]', up)))} is parallel to the view direction "
            f"{v._show(tuple(n.tolist()))}: it gives no up direction on the view plane; "
            "use a view-up vector that is not parallel to it")
    u = u / length
    m = np.eye(4)
    m[0, :3], m[1, :3], m[2, :3] = u, np.cross(n, u), n
    return m + 0.0


class Projection:
    """A projection and its view volume, in viewing coordinates.

    Build one with :func:`orthographic`, :func:`axonometric`, :func:`isometric`,
    :func:`dimetric`, :func:`trimetric`, :func:`oblique`, :func:`parallel`,
    :func:`perspective` or :func:`frustum`; see the module docstring for the
    conventions.

    Attributes
    ----------
    kind : {"parallel", "perspective"}
    name : str
        What built it (``"cabinet"``, ``"isometric"``, ...).
    matrix : ndarray (4, 4)
        The textbook's projection matrix, orientation included.
    orientation : ndarray (4, 4)
        A rotation applied to viewing coordinates before projecting (the standard
        and axonometric views turn the object to face the view plane); the identity
        for the others.
    window : (xmin, ymin, xmax, ymax)
        The window on the view plane.
    z_vp : float
        The view plane z_v = z_vp.
    front, back : float or None
        The front and back clipping planes z_v = front, z_v = back (front > back);
        ``back`` None for a perspective view volume without a back plane.
    shear : (float, float)
        Parallel projections: (a, b) of x' = x + a (z - z_vp), y' = y + b (z - z_vp),
        which makes the direction of projection parallel to z_v.
    prp : (float, float, float) or None
        Perspective projections: the projection reference point (center of
        projection).

    Parameters
    ----------
    kind : {"parallel", "perspective"}
        The kind of projection.
    name : str
        What builds it, shown in messages and ``repr``.
    window : (xmin, ymin, xmax, ymax), default (-1, -1, 1, 1)
        The window on the view plane.
    z_vp : float, default 0
        The view plane z_v = z_vp.
    front, back : float, optional
        The clipping planes (front > back).  Parallel: default a slab 1000 window
        diagonals deep on each side of the view plane; perspective: front defaults
        to the view plane and ``back`` to none.
    shear : (float, float), default (0, 0)
        Parallel projections: the shear (a, b).
    prp : (float, float, float), optional
        Perspective projections (needed): the center of projection, z_prp > z_vp.
    orientation : array_like, shape (4, 4), optional
        A rotation applied before projecting; the identity when omitted.
    given : str, optional
        How the caller's arguments read, for the message when the matrices overflow.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If an argument is not of its kind, the window is degenerate, the planes are out
        of order (back >= front, front at or behind the prp), or the matrices overflow.

    Notes
    -----
    Hearn & Baker, section 12-3 (view volumes and general projection
    transformations).

    Examples
    --------
    A parallel view volume with the window (0, 0)-(2, 2): its center maps to the
    center of the unit cube of normalized device coordinates.

    >>> import scanline as sl
    >>> p = sl.projection.Projection("parallel", "mine", window=(0, 0, 2, 2))
    >>> sl.transform3d.apply(p.normalization, (1, 1, 0)).tolist()
    [0.5, 0.5, 0.5]
    """

    prp: tuple[float, ...] | None

    def __init__(self, kind: str, name: str, window: ArrayLike = DEFAULT_WINDOW,
                 z_vp: float = 0.0, front: float | None = None, back: float | None = None,
                 shear: ArrayLike = (0.0, 0.0), prp: ArrayLike | None = None,
                 orientation: ArrayLike | None = None, *, given: str | None = None) -> None:
        v.choice("kind", kind, KINDS)
        if not isinstance(name, str):
            raise ArgumentTypeError(f"name must be a string, got {v._show(name)}")
        self.kind = kind
        self.name = name
        self.window = _window(window)
        self.z_vp = v.number("z_vp", z_vp)
        if orientation is None:
            self.orientation = np.eye(4)
        else:
            from ..transform3d.arrays import matrix4

            self.orientation = matrix4("orientation", orientation)
        pair = cast("Sequence[object]", shear)
        if isinstance(pair, (str, bytes)) or not hasattr(pair, "__len__") or len(pair) != 2:
            raise ArgumentTypeError(f"shear must be a pair (a, b), got {v._show(shear)}")
        self.shear = (v.number("shear[0]", pair[0]), v.number("shear[1]", pair[1]))
        if kind == "perspective":
            from ..transform3d.arrays import vector

            self.prp = vector("prp", prp)
            if not self.prp[2] > self.z_vp:
                raise ArgumentValueError(
                    f"the center of projection (z_prp = {self.prp[2]:g}) must be in front "
                    f"of the view plane (z_vp = {self.z_vp:g}): z_prp > z_vp, since the "
                    "viewer looks along -z_v")
        else:
            self.prp = None
        self.front, self.back = self._planes(front, back)
        self._check_finite(given)

    def _check_finite(self, given: str | None) -> None:
        """Refuse a view volume whose matrices overflow or underflow float64 (huge but
        finite arguments such as z_prp=1e300, z_vp=-1e300, or tiny ones such as
        near=5e-324): ``given`` names the arguments that built it."""
        try:
            with np.errstate(all="ignore"):
                ok = bool(np.isfinite(self.matrix).all()
                          and np.isfinite(self.normalization).all())
        except (ZeroDivisionError, OverflowError):
            ok = False
        if ok:
            return
        if given is None:
            given = (f"window={self.window}, z_vp={self.z_vp:g}, front={self.front:g}, back="
                     f"{'None' if self.back is None else format(self.back, 'g')}, "
                     + (f"prp={self.prp}" if self.prp is not None else f"shear={self.shear}"))
        raise ArgumentValueError(
            f"{given}: the {self.name} projection's matrices overflow float64 (an entry is "
            "infinite or NaN: the distances are too large, too small or too unequal); use "
            "values nearer 1, e.g. a view volume a few units across")

    def _planes(self, front: float | None,
                back: float | None) -> tuple[float, float | None]:
        if self.kind == "parallel":
            xmin, ymin, xmax, ymax = self.window
            reach = DEFAULT_DEPTH * math.hypot(xmax - xmin, ymax - ymin)
            front = self.z_vp + reach if front is None else v.number("front", front)
            back = self.z_vp - reach if back is None else v.number("back", back)
        else:
            front = self.z_vp if front is None else v.number("front", front)
            back = None if back is None else v.number("back", back)
            assert self.prp is not None          # a perspective projection has one
            if not front < self.prp[2]:
                raise ArgumentValueError(
                    f"front={front:g} must be in front of the center of projection, "
                    f"z_prp = {self.prp[2]:g} (front < z_prp): the near plane cannot be at "
                    "or behind the eye")
        if back is not None and not back < front:
            raise ArgumentValueError(
                f"the back plane must be behind the front plane (back < front, the viewer "
                f"looks along -z_v); got front={front:g}, back={back:g}; with near and far "
                "distances: near < far")
        return front, back

    # -- the textbook matrix -------------------------------------------------------------
    @property
    def matrix(self) -> NDArray[np.float64]:
        """The projection matrix (4x4), orientation included (see :func:`orthographic`,
        :func:`oblique`, :func:`perspective` for each formula)."""
        if self.kind == "parallel":
            a, b = self.shear
            m = t3.shear("z", a, b, self.z_vp)
        else:
            assert self.prp is not None
            px, py, pz = self.prp
            d = pz - self.z_vp
            m = np.array([[1.0, 0.0, -px / d, px * self.z_vp / d],
                          [0.0, 1.0, -py / d, py * self.z_vp / d],
                          [0.0, 0.0, -self.z_vp / d, self.z_vp * pz / d],
                          [0.0, 0.0, -1.0 / d, pz / d]])
        out: NDArray[np.float64] = m @ self.orientation + 0.0
        return out

    def __array__(self, dtype: DTypeLike | None = None,
                  copy: bool | None = None) -> NDArray[Any]:
        m = self.matrix
        return m if dtype is None else m.astype(dtype)

    # -- the view volume -----------------------------------------------------------------
    @property
    def normalization(self) -> NDArray[np.float64]:
        """The 4x4 matrix from viewing coordinates to homogeneous clip coordinates,
        mapping the view volume onto the unit cube 0 <= x_h, y_h, z_h <= w.

        Parallel (Hearn & Baker, "general parallel-projection transformations"): the
        shear x' = x + a (z - z_vp), y' = y + b (z - z_vp) makes the view volume a box;
        then x_n = (x' - xmin) / (xmax - xmin), y_n likewise and
        z_n = (front - z) / (front - back), w = 1.

        Perspective (Hearn & Baker, "general perspective-projection
        transformations"): with P = (px, py, pz) the projection reference point,
        d = pz - z_vp and (cx, cy) the window's center, the shear
        x' = x - (cx - px) (pz - z) / d, y' likewise (about the plane z = pz, so the
        prp stays) turns the frustum's center line parallel to z_v; then w = (pz - z) / d (Hearn & Baker's homogeneous
        factor h), x_n w = (x' - px) / (2 hx) + w / 2 with hx the window's half width
        (x_n = (x_p - xmin) / (xmax - xmin) after the divide, x_p the projection on
        the view plane), y likewise, and the pseudo-depth
        z_n = u_b (u - u_f) / (u (u_b - u_f)), u = pz - z the distance in front of
        the eye, u_f and u_b those of the front and back planes (z_n = 1 - u_f / u
        without a back plane).  Points with u <= u_f, between the eye and the front
        plane or behind the eye, get z_h < 0 and are clipped.
        """
        xmin, ymin, xmax, ymax = self.window
        if self.kind == "parallel":
            assert self.back is not None         # a parallel volume always has one
            a, b = self.shear
            n = np.array([[1.0 / (xmax - xmin), 0.0, 0.0, -xmin / (xmax - xmin)],
                          [0.0, 1.0 / (ymax - ymin), 0.0, -ymin / (ymax - ymin)],
                          [0.0, 0.0, -1.0 / (self.front - self.back),
                           self.front / (self.front - self.back)],
                          [0.0, 0.0, 0.0, 1.0]])
            box: NDArray[np.float64] = n @ t3.shear("z", a, b, self.z_vp) @ self.orientation + 0.0
            return box
        assert self.prp is not None
        px, py, pz = self.prp
        d = pz - self.z_vp
        cx, cy = (xmin + xmax) / 2, (ymin + ymax) / 2
        hx, hy = (xmax - xmin) / 2, (ymax - ymin) / 2
        shear = t3.shear("z", (cx - px) / d, (cy - py) / d, pz)
        uf = pz - self.front
        # rows in terms of (x', y', z, 1); u = pz - z, w = u / d
        w_row = np.array([0.0, 0.0, -1.0 / d, pz / d])
        x_row = np.array([1.0 / (2 * hx), 0.0, 0.0, -px / (2 * hx)]) + w_row / 2
        y_row = np.array([0.0, 1.0 / (2 * hy), 0.0, -py / (2 * hy)]) + w_row / 2
        if self.back is None:          # z_n = 1 - uf / u: z_h = (u - uf) / d
            z_row = np.array([0.0, 0.0, -1.0 / d, (pz - uf) / d])
        else:
            ub = pz - self.back
            k = ub / (d * (ub - uf))   # z_h = k (u - uf)
            z_row = np.array([0.0, 0.0, -k, k * (pz - uf)])
        n = np.stack([x_row, y_row, z_row, w_row])
        out: NDArray[np.float64] = n @ shear @ self.orientation + 0.0
        return out

    def replace(self, **changes: Any) -> "Projection":
        """A copy with some of ``window``, ``z_vp``, ``front``, ``back`` changed.

        Parameters
        ----------
        **changes
            New values of ``window``, ``z_vp``, ``front`` or ``back``.

        Returns
        -------
        Projection

        Raises
        ------
        ArgumentTypeError
            If another keyword is given.
        ArgumentValueError
            If the new view volume is invalid (see :class:`Projection`).

        Examples
        --------
        >>> import scanline as sl
        >>> p = sl.projection.orthographic().replace(front=1, back=-1)
        >>> p.front, p.back
        (1.0, -1.0)
        """
        allowed = {"window", "z_vp", "front", "back"}
        for key in changes:
            if key not in allowed:
                raise ArgumentTypeError(
                    f"replace() takes {', '.join(sorted(allowed))}; got {key!r}")
        args: dict[str, Any] = dict(window=self.window, z_vp=self.z_vp, front=self.front, back=self.back,
                    shear=self.shear, prp=self.prp, orientation=self.orientation)
        args.update(changes)
        given = ", ".join(f"{k}={x!r}" for k, x in changes.items()) or None
        return Projection(self.kind, self.name, **args, given=given)

    def volume_corners(self) -> NDArray[np.float64]:
        """The corners of the view volume in viewing coordinates, (8, 3): the front
        face (counterclockwise from the lower left), then the back face (for a
        perspective volume without a back plane, drawn at ten times the front
        plane's distance from the eye).

        Returns
        -------
        ndarray of float64, shape (8, 3)

        Examples
        --------
        >>> import scanline as sl
        >>> p = sl.projection.orthographic(window=(0, 0, 2, 1), front=1, back=-1)
        >>> corners = p.volume_corners()
        >>> corners[:4].tolist()                         # the front face, z_v = 1
        [[0.0, 0.0, 1.0], [2.0, 0.0, 1.0], [2.0, 1.0, 1.0], [0.0, 1.0, 1.0]]
        >>> corners[4:].tolist()                         # the back face, z_v = -1
        [[0.0, 0.0, -1.0], [2.0, 0.0, -1.0], [2.0, 1.0, -1.0], [0.0, 1.0, -1.0]]
        """
        from .camera import _corners

        return _corners(self.normalization, self)

    def __repr__(self) -> str:
        extra = (f", prp={self.prp}" if self.prp is not None else
                 f", shear=({self.shear[0]:g}, {self.shear[1]:g})")
        return (f"<Projection {self.name!r} ({self.kind}), window={self.window}, "
                f"z_vp={self.z_vp:g}, front={self.front:g}, back="
                f"{'none' if self.back is None else format(self.back, 'g')}{extra}>")


def _angle(name: str, value: object, low: float, high: float) -> float:
    a = v.angle(name, value)
    if not low < a < high:
        raise ArgumentValueError(
            f"{name} must be between {low:g} and {high:g} radians (exclusive), got "
            f"{value!r}; write degrees with their unit, e.g. {name}='30deg'")
    return a


# -- parallel projections ----------------------------------------------------------------
def orthographic(view: str | None = None, window: ArrayLike = DEFAULT_WINDOW,
                 front: float | None = None, back: float | None = None,
                 z_vp: float = 0.0) -> Projection:
    """Orthographic parallel projection: onto the view plane along -z_v.

    ::

        x_p = x,  y_p = y,  z kept as the depth      M = I (4x4)

    With ``view`` one of the standard views the object is first turned to face the
    viewer (the matrix is that rotation): the elevations ``"front"`` (seen from +z),
    ``"rear"``, ``"right"`` (= ``"side"``, seen from +x), ``"left"``, and the plan
    views ``"top"`` (seen from +y, with -z up on the drawing, so the front edge is at
    the bottom) and ``"bottom"``, for a world with y up.

    Parameters
    ----------
    view : str, optional
        One of :data:`VIEW_NAMES`, or None (viewing coordinates as they are).
    window, front, back, z_vp
        The view volume: the window on the view plane z_v = z_vp and the front and
        back clipping planes (default: a slab 1000 window diagonals deep on each
        side of the view plane).

    Returns
    -------
    Projection

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``view`` is not one of :data:`VIEW_NAMES` or the view volume is invalid.

    Notes
    -----
    Hearn & Baker, section 12-3, "orthographic projections": front, side and rear
    elevations and the top (plan) view; the orthographic equations x_p = x,
    y_p = y.

    Examples
    --------
    >>> import scanline as sl
    >>> p = sl.projection.orthographic("side")
    >>> sl.transform3d.apply(p, (1, 2, 3)).round(12).tolist()    # seen from +x
    [-3.0, 2.0, 1.0]
    """
    orientation = None
    name = "orthographic"
    if view is not None:
        v.choice("view", view, VIEW_NAMES)
        name = "right" if view == "side" else view
        orientation = frame(*VIEWS[name])
    return Projection("parallel", name, window, z_vp, front, back, (0.0, 0.0),
                      orientation=orientation,
                      given=f"window={window!r}, front={front!r}, back={back!r}, z_vp={z_vp!r}")


def axonometric(phi: Angle, theta: Angle, window: ArrayLike = DEFAULT_WINDOW,
                front: float | None = None, back: float | None = None,
                name: str = "trimetric") -> Projection:
    """Axonometric projection: rotate about y by φ, then about x by θ, then project
    orthographically onto the xy plane (Rogers & Adams's trimetric projection).

    ::

        M = Rx(θ) · Ry(φ)          (z kept as the depth)

    The unit vectors along x, y, z are drawn with the lengths (foreshortening
    factors, :func:`foreshortening`) f_x² = cos²φ + sin²φ sin²θ, f_y² = cos²θ,
    f_z² = sin²φ + cos²φ sin²θ.

    Parameters
    ----------
    phi : float or str
        The rotation about y (radians, or a string with its unit).
    theta : float or str
        The rotation about x that follows.
    window : (xmin, ymin, xmax, ymax), default (-1, -1, 1, 1)
        The window on the view plane.
    front, back : float, optional
        The front and back clipping planes z_v = front > z_v = back (default: a slab
        1000 window diagonals deep on each side of the view plane).
    name : str, default "trimetric"
        The projection's name.

    Returns
    -------
    Projection

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If an angle is not finite or the view volume is invalid.

    Notes
    -----
    Hearn & Baker, section 12-3: an axonometric projection is an orthographic one
    that shows more than one face of the object; Rogers & Adams, section 3-9, give
    it by the two rotation angles.

    Examples
    --------
    >>> import math, scanline as sl
    >>> p = sl.projection.axonometric(math.radians(-30), math.radians(20))
    >>> [round(f, 4) for f in sl.projection.foreshortening(p)]
    [0.8827, 0.9397, 0.5811]
    """
    phi = v.angle("phi", phi)
    theta = v.angle("theta", theta)
    rot = t3.compose(t3.rotation(theta, "x"), t3.rotation(phi, "y"))
    return Projection("parallel", name, window, 0.0, front, back, (0.0, 0.0), orientation=rot,
                      given=f"window={window!r}, front={front!r}, back={back!r}")


def trimetric(phi: Angle, theta: Angle, window: ArrayLike = DEFAULT_WINDOW,
              front: float | None = None, back: float | None = None) -> Projection:
    """A trimetric projection: :func:`axonometric` with any angles (three different
    foreshortening factors in general).

    Parameters
    ----------
    phi, theta : float or str
        The rotations about y and then about x, as :func:`axonometric`.
    window : (xmin, ymin, xmax, ymax), default (-1, -1, 1, 1)
        The window on the view plane.
    front, back : float, optional
        The front and back clipping planes z_v = front > z_v = back (default: a slab
        1000 window diagonals deep on each side of the view plane).

    Returns
    -------
    Projection

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If an angle is not finite or the view volume is invalid.

    Notes
    -----
    Rogers & Adams, section 3-9.

    Examples
    --------
    >>> import math, scanline as sl
    >>> p = sl.projection.trimetric(math.radians(-30), math.radians(20))
    >>> [round(f, 4) for f in sl.projection.foreshortening(p)]
    [0.8827, 0.9397, 0.5811]
    """
    return axonometric(phi, theta, window, front, back, "trimetric")


def isometric(window: ArrayLike = DEFAULT_WINDOW, front: float | None = None,
              back: float | None = None) -> Projection:
    """The isometric projection: the view-plane normal along (1, 1, 1), so the three
    axes are foreshortened equally (by sqrt(2/3) = 0.8165) and drawn 120 degrees
    apart.

    ::

        M = Rx(θ) · Ry(φ),  φ = -45°,  θ = asin(1 / sqrt(3)) = 35.26°

    Parameters
    ----------
    window : (xmin, ymin, xmax, ymax), default (-1, -1, 1, 1)
        The window on the view plane.
    front, back : float, optional
        The front and back clipping planes z_v = front > z_v = back (default: a slab
        1000 window diagonals deep on each side of the view plane).

    Returns
    -------
    Projection

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If the view volume is invalid.

    Notes
    -----
    Hearn & Baker, section 12-3 ("isometric projection ... the projection plane
    intersects each coordinate axis at the same distance from the origin"); Rogers
    & Adams, section 3-9.

    Examples
    --------
    >>> import scanline as sl
    >>> [round(f, 6) for f in sl.projection.foreshortening(sl.projection.isometric())]
    [0.816497, 0.816497, 0.816497]
    """
    return axonometric(-math.pi / 4, math.asin(1 / math.sqrt(3)), window, front, back,
                       "isometric")


def dimetric(fz: float, window: ArrayLike = DEFAULT_WINDOW, front: float | None = None,
             back: float | None = None) -> Projection:
    """A dimetric projection: x and y foreshortened equally, z by the factor ``fz``
    (0 < fz < 1).

    ::

        θ = asin(fz / sqrt(2)),  φ = -asin(fz / sqrt(2 - fz²)),  f_x = f_y = sqrt(1 - fz²/2)

    Parameters
    ----------
    fz : float
        The foreshortening factor of z, 0 < fz < 1.
    window : (xmin, ymin, xmax, ymax), default (-1, -1, 1, 1)
        The window on the view plane.
    front, back : float, optional
        The front and back clipping planes z_v = front > z_v = back (default: a slab
        1000 window diagonals deep on each side of the view plane).

    Returns
    -------
    Projection

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``fz`` is not between 0 and 1 or the view volume is invalid.

    Notes
    -----
    Rogers & Adams, section 3-9, eqs. 3-33 and 3-34 (φ negative here, so that the
    viewer is on the +x side, as in :func:`isometric`).  ``fz = sqrt(2/3)`` is the
    isometric projection.

    Examples
    --------
    >>> import scanline as sl
    >>> [round(f, 4) for f in sl.projection.foreshortening(sl.projection.dimetric(0.5))]
    [0.9354, 0.9354, 0.5]
    """
    fz = v.number("fz", fz)
    if not 0.0 < fz < 1.0:
        raise ArgumentValueError(f"fz must be between 0 and 1 (exclusive), got {fz!r}")
    theta = math.asin(fz / math.sqrt(2.0))
    phi = -math.asin(fz / math.sqrt(2.0 - fz * fz))
    return axonometric(phi, theta, window, front, back, "dimetric")


def foreshortening(projection: Projection | ArrayLike) -> tuple[float, float, float]:
    """The lengths (f_x, f_y, f_z) on the view plane of the unit vectors along the
    world axes under a parallel ``projection`` (a Projection or a 4x4 matrix).

    Parameters
    ----------
    projection : Projection or array_like, shape (4, 4)
        A parallel projection or its matrix.

    Returns
    -------
    (float, float, float)
        The foreshortening factors f_x, f_y, f_z.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``projection`` is neither a Projection nor a finite 4x4 matrix.

    Notes
    -----
    Rogers & Adams, section 3-9 (foreshortening factors of axonometric projections).

    Examples
    --------
    The plain orthographic projection keeps x and y and flattens z:

    >>> import scanline as sl
    >>> sl.projection.foreshortening(sl.projection.orthographic())
    (1.0, 1.0, 0.0)
    """
    from ..transform3d.arrays import matrix4

    m = projection.matrix if isinstance(projection, Projection) else matrix4(
        "projection", projection)
    fx, fy, fz = (float(math.hypot(m[0, k], m[1, k])) for k in range(3))
    return fx, fy, fz


def oblique(kind: str | None = None, phi: Angle = math.pi / 4, alpha: Angle | None = None,
            window: ArrayLike = DEFAULT_WINDOW, front: float | None = None,
            back: float | None = None, z_vp: float = 0.0) -> Projection:
    """Oblique parallel projection: projectors at the angle α to the view plane.

    A point (x, y, z) projects to (Hearn & Baker, section 12-3)::

        x_p = x + z L1 cos φ,   y_p = y + z L1 sin φ,   L1 = 1 / tan α

        M = | 1  0  L1 cos φ  0 |      (about the view plane z_vp: z - z_vp
            | 0  1  L1 sin φ  0 |       in place of z)
            | 0  0     1      0 |
            | 0  0     0      1 |

    Parameters
    ----------
    kind : {"cavalier", "cabinet"}, optional
        Cavalier: tan α = 1 (α = 45°, lines perpendicular to the view plane keep
        their length); cabinet: tan α = 2 (α ≈ 63.4°, they are drawn at half length).
    phi : float
        The angle φ (radians) the receding lines make with the horizontal; typical
        values are 30° and 45° (the default).
    alpha : float, optional
        α in radians, 0 < α < π/2, instead of ``kind`` (α = π/2 is the orthographic
        projection: use :func:`orthographic`).
    window, front, back, z_vp
        The view volume, as :func:`orthographic`.

    Returns
    -------
    Projection

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If both or neither of ``kind`` and ``alpha`` are given, ``kind`` is unknown,
        ``alpha`` is not in (0, pi/2), or the view volume is invalid.

    Notes
    -----
    Hearn & Baker, section 12-3, "oblique projections".

    Examples
    --------
    >>> import math, scanline as sl
    >>> p = sl.projection.oblique("cabinet", phi=math.radians(30))
    >>> sl.transform3d.apply(p, (0, 0, 1)).round(6).tolist()
    [0.433013, 0.25, 1.0]
    """
    phi = v.angle("phi", phi)
    if (kind is None) == (alpha is None):
        raise ArgumentValueError(
            "give either kind ('cavalier' or 'cabinet') or alpha (radians), not both and "
            f"not neither; got kind={kind!r}, alpha={alpha!r}")
    if kind is not None:
        tan_alpha = OBLIQUE[v.choice("kind", kind, tuple(OBLIQUE))]
        name = kind
    else:
        tan_alpha = math.tan(_angle("alpha", alpha, 0.0, math.pi / 2))
        name = "oblique"
    l1 = 1.0 / tan_alpha
    return Projection("parallel", name, window, z_vp, front, back,
                      (l1 * math.cos(phi), l1 * math.sin(phi)),
                      given=f"kind={kind!r}, alpha={alpha!r}, phi={phi!r}, window={window!r}, "
                            f"front={front!r}, back={back!r}, z_vp={z_vp!r}")


def parallel(direction: ArrayLike, window: ArrayLike = DEFAULT_WINDOW,
             front: float | None = None, back: float | None = None,
             z_vp: float = 0.0) -> Projection:
    """The general parallel projection along the projection vector
    V_p = (px, py, pz) (pz != 0), by the shear (Hearn & Baker, section 12-3)::

        x' = x + a (z - z_vp),  y' = y + b (z - z_vp),  a = -px / pz,  b = -py / pz

    which makes V_p parallel to z_v; then an orthographic projection.  V_p = (0, 0, 1)
    is the orthographic projection; :func:`oblique` is the case
    V_p = (-L1 cos φ, -L1 sin φ, 1).

    Parameters
    ----------
    direction : (float, float, float)
        The projection vector V_p, finite, with pz != 0.
    window : (xmin, ymin, xmax, ymax), default (-1, -1, 1, 1)
        The window on the view plane.
    front, back : float, optional
        The front and back clipping planes z_v = front > z_v = back (default: a slab
        1000 window diagonals deep on each side of the view plane).
    z_vp : float, default 0
        The view plane z_v = z_vp.

    Returns
    -------
    Projection

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``direction`` is not three finite numbers or is parallel to the view plane,
        or the view volume is invalid.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.transform3d.apply(sl.projection.parallel((1, 0, -1)), (0, 0, 2)).tolist()
    [2.0, 0.0, 2.0]
    """
    from ..transform3d.arrays import vector

    px, py, pz = vector("direction", direction)
    shown = v._show(tuple(cast("Iterable[object]", direction)))
    if pz == 0.0 or not math.isfinite(px / pz) or not math.isfinite(py / pz):
        raise ArgumentValueError(
            f"direction={shown} is parallel (or nearly) to the view "
            "plane (pz = 0): its projectors never reach the plane; use a vector with "
            "pz != 0")
    return Projection("parallel", "parallel", window, z_vp, front, back, (-px / pz, -py / pz),
                      given=f"direction={shown}, window={window!r}, "
                            f"front={front!r}, back={back!r}, z_vp={z_vp!r}")


# -- perspective projections -------------------------------------------------------------
def perspective(z_prp: float | None = None, z_vp: float | None = None,
                window: ArrayLike = DEFAULT_WINDOW, front: float | None = None,
                back: float | None = None, *, fov: Angle | None = None, aspect: float = 1.0,
                near: float | None = None, far: float | None = None) -> Projection:
    """Perspective projection, in Hearn & Baker's form or by field of view.

    *Hearn & Baker's form* (section 12-3): the center of projection on the z_v axis at
    z_prp, the view plane at z_vp < z_prp; with d_p = z_prp - z_vp::

        x_p = x (z_prp - z_vp) / (z_prp - z),   y_p = y (z_prp - z_vp) / (z_prp - z)

        M_pers = | 1  0       0             0        |    h = (z_prp - z) / d_p
                 | 0  1       0             0        |    x_p = x_h / h, ...
                 | 0  0   -z_vp / d_p   z_vp z_prp / d_p |    z_p = z_vp
                 | 0  0   -1 / d_p      z_prp / d_p  |

    ``front`` (default: the view plane) and ``back`` (default: none, an infinitely
    deep volume) are the clipping planes z_v = front, z_v = back.

    *Field-of-view form*: ``perspective(fov=..., aspect=..., near=..., far=...)``, the
    eye at the origin of viewing coordinates (z_prp = 0) looking along -z_v: the
    view plane and front plane at z_v = -near, the back plane at z_v = -far (None:
    none), and the window ±near tan(fov / 2) high and ``aspect`` times as wide.

    Parameters
    ----------
    z_prp, z_vp : float
        Hearn & Baker's form (both needed).
    window, front, back
        Its view volume.
    fov : float
        The vertical field of view in radians, 0 < fov < π.
    aspect : float
        Window width / height (a :class:`~scanline.Camera` with ``keep_aspect``
        widens the window to the device anyway).
    near, far : float
        Distances of the front and back planes from the eye, 0 < near < far.

    Returns
    -------
    Projection

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If the two forms are mixed or incomplete, a number is out of range (fov not
        in (0, pi), aspect or near not > 0, far not > near, z_prp not > z_vp) or the
        matrices overflow.

    See Also
    --------
    frustum : the general (oblique) frustum, with the center of projection anywhere.

    Examples
    --------
    >>> import scanline as sl
    >>> p = sl.projection.perspective(z_prp=10, z_vp=0)
    >>> sl.transform3d.apply(p, (2, 1, -10)).tolist()      # twice as far as the plane: half size
    [1.0, 0.5, 0.0]
    >>> q = sl.projection.perspective(fov=1.0, near=0.5, far=50)
    >>> q.front, q.back, q.prp
    (-0.5, -50.0, (0.0, 0.0, 0.0))
    """
    if fov is not None:
        if z_prp is not None or z_vp is not None:
            raise ArgumentValueError(
                "give either z_prp and z_vp (Hearn & Baker's form) or fov, near and far, "
                "not both")
        fov_radians = _angle("fov", fov, 0.0, math.pi)
        aspect = v.number("aspect", aspect)
        if not aspect > 0:
            raise ArgumentValueError(f"aspect must be > 0 (width / height), got {aspect!r}")
        if near is None:
            raise ArgumentValueError("the field-of-view form needs near, the distance of the "
                                     "front plane from the eye (> 0), e.g. near=0.1")
        near = v.number("near", near)
        if not near > 0:
            raise ArgumentValueError(
                f"near must be > 0 (the front plane in front of the eye), got {near!r}")
        if far is not None:
            far = v.number("far", far)
            if not far > near:
                raise ArgumentValueError(
                    f"far must be greater than near (got near={near:g}, far={far:g}): the "
                    "back plane lies beyond the front plane")
        half = near * math.tan(fov_radians / 2)
        given = f"fov={fov_radians!r}, aspect={aspect!r}, near={near!r}, far={far!r}"
        if not half > 0:
            raise ArgumentValueError(f"fov={fov_radians!r} with near={near!r} gives an empty "
                                     "window")
        if not (math.isfinite(half * aspect) and half * aspect > 0):
            raise ArgumentValueError(
                f"{given}: the window (±near tan(fov / 2), aspect times as wide) overflows or "
                "underflows float64; use values nearer 1")
        return Projection("perspective", "perspective", (-half * aspect, -half, half * aspect,
                                                         half), -near, -near,
                          None if far is None else -far, prp=(0.0, 0.0, 0.0), given=given)
    if near is not None or far is not None:
        raise ArgumentValueError("near and far belong to the field-of-view form "
                                 "(fov=...); with z_prp and z_vp give front and back")
    if z_prp is None or z_vp is None:
        raise ArgumentValueError(
            "perspective needs z_prp and z_vp (Hearn & Baker's form), or fov and near; "
            f"got z_prp={z_prp!r}, z_vp={z_vp!r}")
    z_prp = v.number("z_prp", z_prp)
    z_vp = v.number("z_vp", z_vp)
    return Projection("perspective", "perspective", window, z_vp, front, back,
                      prp=(0.0, 0.0, z_prp),
                      given=f"z_prp={z_prp!r}, z_vp={z_vp!r}, window={window!r}, "
                            f"front={front!r}, back={back!r}")


def frustum(prp: ArrayLike, window: ArrayLike = DEFAULT_WINDOW, z_vp: float = 0.0,
            front: float | None = None, back: float | None = None) -> Projection:
    """The general perspective projection: the center of projection at any point
    ``prp`` = (x_prp, y_prp, z_prp) in front of the view plane (z_prp > z_vp), so the
    frustum through the window may be oblique.  Points project along lines through
    the prp onto the view plane::

        x_p = x_prp + (x - x_prp) d / (z_prp - z),  d = z_prp - z_vp, y likewise

    and the normalization shears the frustum's center line parallel to z_v before
    the perspective scaling (Hearn & Baker, section 12-3, "general perspective-
    projection transformations").

    Parameters
    ----------
    prp : (float, float, float)
        The center of projection (x_prp, y_prp, z_prp), z_prp > z_vp.
    window : (xmin, ymin, xmax, ymax), default (-1, -1, 1, 1)
        The window on the view plane.
    z_vp : float, default 0
        The view plane z_v = z_vp.
    front, back : float, optional
        The clipping planes (front > back); the view plane and none by default.

    Returns
    -------
    Projection

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``prp`` is not three finite numbers, is not in front of the view plane, or
        the view volume is invalid.

    Examples
    --------
    >>> import scanline as sl
    >>> p = sl.projection.frustum((1, 0, 4), window=(0, -1, 2, 1))
    >>> sl.transform3d.apply(p, (3, 0, -4)).tolist()     # halfway from the prp: the offset halves
    [2.0, 0.0, 0.0]
    """
    from ..transform3d.arrays import vector

    p = vector("prp", prp)
    return Projection("perspective", "frustum", window, v.number("z_vp", z_vp), front, back,
                      prp=p, given=f"prp={p!r}, window={window!r}, z_vp={z_vp!r}, "
                                   f"front={front!r}, back={back!r}")
