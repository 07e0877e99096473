"""The camera: the viewing transformation, a projection and the 3-D viewport
(Hearn & Baker, sections 12-2 to 12-4).

The pipeline of a :class:`Camera`::

    world --V--> viewing coordinates --N--> homogeneous clip coordinates
          --clip 0 <= x, y, z <= w--> divide by w --> NDC (the unit cube)
          --3-D viewport--> device x, y and depth

V is the composite world -> viewing matrix R · T (section 12-2), N the projection's
:attr:`~scanline.projection.Projection.normalization` (with the window widened to
the device's aspect ratio when ``keep_aspect``).  Device coordinates follow
:func:`scanline.viewing.ndc_to_device`: NDC (0, 0) is the center of the bottom-left
pixel and (1, 1) of the top-right one.  The depth is the NDC z mapped into the
viewport's z range (default 0 at the front plane, 1 at the back plane).
"""

import math
from collections.abc import Sequence
from typing import Any, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .. import transform3d as t3
from ..errors import ArgumentTypeError, ArgumentValueError
from ..transform3d.arrays import points as point_array
from ..transform3d.arrays import vector
from .projections import VIEWS, Projection, frame, perspective

#: The 3-D viewport of a camera when none is given: the whole normalized cube.
FULL_VIEWPORT = (0.0, 0.0, 0.0, 1.0, 1.0, 1.0)


def viewing_matrix(view_reference_point: ArrayLike, view_plane_normal: ArrayLike,
                   view_up: ArrayLike) -> NDArray[np.float64]:
    """The world -> viewing-coordinates matrix M_wc,vc = R · T (Hearn & Baker,
    section 12-2).

    T = T(-P0) moves the view reference point P0 to the origin; R has the rows
    u, v, n of the viewing frame::

        n = N / |N|,   u = (V x N) / |V x N|,   v = n x u

        R = | u_x  u_y  u_z  0 |
            | v_x  v_y  v_z  0 |
            | n_x  n_y  n_z  0 |
            |  0    0    0   1 |

    so that the view-plane normal N becomes z_v and the projection of the view-up
    vector V onto the view plane becomes y_v (right-handed; the viewer looks along
    -z_v).

    Parameters
    ----------
    view_reference_point : (float, float, float)
        P0, the origin of viewing coordinates, in world coordinates.
    view_plane_normal : (float, float, float)
        N, nonzero (any length): the z_v axis, pointing toward the viewer.
    view_up : (float, float, float)
        V, nonzero and not parallel to N.

    Returns
    -------
    ndarray of float64, shape (4, 4)

    Raises
    ------
    ArgumentValueError
        If N or V is the zero vector or V is parallel to N.

    Examples
    --------
    >>> from scanline.projection import viewing_matrix
    >>> m = viewing_matrix((0, 0, 5), (0, 0, 1), (0, 1, 0))
    >>> m[:3, 3].tolist()
    [0.0, 0.0, -5.0]
    """
    p0 = np.array(vector("view_reference_point", view_reference_point))
    r = frame(view_plane_normal, view_up, "view_plane_normal", "view_up")
    return t3.compose(r, t3.translation(*(-p0)))


def look_at(eye: ArrayLike, target: ArrayLike, up: ArrayLike = (0.0, 1.0, 0.0)) -> NDArray[np.float64]:
    """The viewing matrix of an eye at ``eye`` looking at ``target``: the view
    reference point is the eye and N = eye - target (Hearn & Baker's N points from
    the scene toward the viewer).

    Parameters
    ----------
    eye : (float, float, float)
        The eye, in world coordinates.
    target : (float, float, float)
        The point looked at.
    up : (float, float, float), default (0, 1, 0)
        The view-up vector, not parallel to the view direction.

    Returns
    -------
    ndarray of float64, shape (4, 4)

    Raises
    ------
    ArgumentValueError
        If eye = target (no view direction) or ``up`` is parallel to the view
        direction.

    Notes
    -----
    :func:`viewing_matrix` with P0 = eye, N = eye - target, V = up (Hearn & Baker,
    section 12-2).

    Examples
    --------
    The target lands on the -z_v axis, 5 units in front of the eye:

    >>> from scanline.projection import look_at
    >>> from scanline.transform3d import apply
    >>> apply(look_at((0, 0, 5), (0, 0, 0)), (0, 0, 0)).tolist()
    [0.0, 0.0, -5.0]
    """
    e = np.array(vector("eye", eye))
    t = np.array(vector("target", target))
    if (e == t).all():
        raise ArgumentValueError(
            f"eye and target are the same point {tuple(e.tolist())}: the camera needs a "
            "direction to look in; move the eye or the target")
    with np.errstate(over="ignore"):
        n = e - t
    r = frame(n, up, "eye - target", "up")
    return t3.compose(r, t3.translation(*(-e)))


def _corners(clip: NDArray[np.float64], projection: Projection) -> NDArray[np.float64]:
    """The view volume's corners (8, 3) in the space that ``clip`` maps to clip
    coordinates."""
    back = 0.9 if projection.kind == "perspective" and projection.back is None else 1.0
    cube = np.array([[x, y, z, 1.0] for z in (0.0, back)
                     for x, y in ((0, 0), (1, 0), (1, 1), (0, 1))])
    h = cube @ t3.inverse(clip).T
    corners: NDArray[np.float64] = h[:, :3] / h[:, 3:]
    return corners


def _viewport(value: object) -> tuple[float, float, float, float, float, float]:
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or len(value) != 6:
        raise ArgumentTypeError(
            "viewport must be (xmin, ymin, zmin, xmax, ymax, zmax) within the unit cube, "
            f"got {v._show(value)}")
    b = cast("tuple[float, float, float, float, float, float]",
             tuple(v.number(f"viewport[{i}]", c)
                   for i, c in enumerate(cast("Sequence[object]", value))))
    if not (0.0 <= b[0] < b[3] <= 1.0 and 0.0 <= b[1] < b[4] <= 1.0
            and 0.0 <= b[2] < b[5] <= 1.0):
        raise ArgumentValueError(
            f"viewport={b} must lie within the unit cube with xmin < xmax, ymin < ymax and "
            "zmin < zmax, e.g. (0, 0, 0, 1, 1, 1)")
    return b


class Camera:
    """A synthetic camera: where it is, where it looks, how it projects.

    Parameters
    ----------
    eye, target, up : 3-vectors, optional
        The usual form: the eye (the view reference point) looking at the target,
        ``up`` (default +y) giving the view-up vector.  ``target`` alone: viewing
        coordinates are world coordinates with the origin moved to the target (for
        the projections that carry their own view direction: the standard and
        axonometric views).  With neither this nor the Hearn & Baker form, viewing
        coordinates are world coordinates.
    projection : Projection, optional
        Default: ``perspective(fov=45 degrees, near=0.1)`` (no back plane).
    view_reference_point, view_plane_normal, view_up : 3-vectors, optional
        Hearn & Baker's form (section 12-2) instead of eye/target/up: the origin P0
        of viewing coordinates, the view-plane normal N (z_v) and the view-up
        vector V.  The projection's center of projection and view plane are then
        given relative to P0 along N (e.g. ``perspective(z_prp=10, z_vp=0)``).
    viewport : (xmin, ymin, zmin, xmax, ymax, zmax)
        The 3-D viewport within the normalized unit cube (Hearn & Baker, section
        12-3): where the view volume lands on the device, and the depth range.
    keep_aspect : bool
        Widen the window about its center to the device viewport's aspect ratio, so
        shapes keep their proportions (default True).  False stretches the window
        over the viewport.

    Examples
    --------
    >>> import math, scanline as sl
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.perspective(fov=math.pi / 2, near=1, far=9))
    >>> cam.project([(0, 0, 0), (1, 1, 0)], 101, 101).round(6).tolist()
    [[50.0, 50.0, 0.9], [60.0, 60.0, 0.9]]
    """

    view_matrix: NDArray[np.float64]
    _eye: tuple[float, ...] | None
    target: tuple[float, ...] | None
    up: tuple[float, ...] | None

    def __init__(self, eye: ArrayLike | None = None, target: ArrayLike | None = None,
                 up: ArrayLike | None = None, projection: Projection | None = None, *,
                 view_reference_point: ArrayLike | None = None,
                 view_plane_normal: ArrayLike | None = None, view_up: ArrayLike | None = None,
                 viewport: ArrayLike = FULL_VIEWPORT, keep_aspect: bool = True) -> None:
        usual = eye is not None or target is not None or up is not None
        textbook = (view_reference_point is not None or view_plane_normal is not None
                    or view_up is not None)
        if usual and textbook:
            raise ArgumentValueError(
                "give the camera either eye/target/up or view_reference_point/"
                "view_plane_normal/view_up (Hearn & Baker's form), not both")
        if projection is None:
            projection = perspective(fov=math.radians(45), near=0.1)
        if not isinstance(projection, Projection):
            raise ArgumentTypeError(
                "projection must be a scanline.projection.Projection (from "
                "sl.projection.perspective, orthographic, oblique, isometric, ...), got "
                f"{v._show(projection)}")
        oriented = not np.array_equal(projection.orientation, np.eye(4))
        if usual and eye is None and target is not None and up is None:
            # target alone: viewing coordinates are world coordinates moved to the
            # target, for the views that carry their own direction (isometric, top ...)
            self.view_matrix = t3.translation(*(-np.array(vector("target", target))))
            usual = False
            self._eye = self.up = None
            self.target = vector("target", target)
        elif usual:
            if eye is None or target is None:
                raise ArgumentValueError(
                    f"the eye/target form needs both eye and target; got eye={eye!r}, "
                    f"target={target!r} (a view with its own direction, such as "
                    "isometric() or orthographic('top'), takes target alone)")
            if oriented:
                raise ArgumentValueError(
                    f"the {projection.name} projection carries its own view direction; give "
                    "it target alone (Camera(target=..., projection=...)), or use "
                    "orthographic() with the eye where you want it")
            up = (0.0, 1.0, 0.0) if up is None else up
            self.view_matrix = look_at(eye, target, up)
            self._eye, self.target, self.up = (vector(n, x) for n, x in
                                               (("eye", eye), ("target", target), ("up", up)))
        elif textbook:
            self.view_matrix = viewing_matrix(
                (0.0, 0.0, 0.0) if view_reference_point is None else view_reference_point,
                (0.0, 0.0, 1.0) if view_plane_normal is None else view_plane_normal,
                (0.0, 1.0, 0.0) if view_up is None else view_up)
        elif target is None:
            self.view_matrix = np.eye(4)
        if not usual and target is None:
            self._eye = self.target = self.up = None
        self.projection = projection
        self.viewport = _viewport(viewport)
        if not isinstance(keep_aspect, bool):
            raise ArgumentTypeError(f"keep_aspect must be True or False, got {keep_aspect!r}")
        self.keep_aspect = keep_aspect
        with np.errstate(all="ignore"):
            clip = projection.normalization @ self.view_matrix
        if not np.isfinite(clip).all():
            given = ("eye, target and up" if usual else
                     "view_reference_point, view_plane_normal and view_up" if textbook
                     else "target")
            raise ArgumentValueError(
                f"{given} with this projection give a world -> clip matrix that overflows "
                "float64 (the camera is too far from the origin for the view volume's size); "
                "move the camera and the scene nearer the origin, or use a larger view volume")

    @classmethod
    def standard(cls, view: str, target: ArrayLike = (0.0, 0.0, 0.0), distance: float = 10.0,
                 projection: Projection | None = None, **kw: Any) -> "Camera":
        """A camera ``distance`` from ``target`` in one of the standard views of
        :data:`scanline.projection.VIEWS` (front, rear, right, left, top, bottom;
        "side" is "right"), looking at the target with that view's up vector.
        Default projection: orthographic with the window (-1, -1, 1, 1).

        Parameters
        ----------
        view : str
            One of :data:`scanline.projection.VIEW_NAMES`.
        target : (float, float, float), default (0, 0, 0)
            The point looked at.
        distance : float, default 10
            The eye's distance from the target, > 0.
        projection : Projection, optional
            Default: :func:`~scanline.projection.orthographic`.
        **kw
            ``viewport`` and ``keep_aspect``, as :class:`Camera`.

        Returns
        -------
        Camera

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``view`` is unknown, ``distance`` is not > 0 or another argument is
            invalid.

        Notes
        -----
        The standard views: Hearn & Baker, section 12-3 (orthographic projections).

        Examples
        --------
        Seen from the top (+y) with -z up on the drawing, the world point (0, 0, -1)
        is one unit up and 5 units in front of the eye:

        >>> import scanline as sl
        >>> cam = sl.Camera.standard("top", distance=5)
        >>> cam.to_viewing((0, 0, -1)).tolist()
        [0.0, 1.0, -5.0]
        """
        from .projections import VIEW_NAMES, orthographic

        v.choice("view", view, VIEW_NAMES)
        direction, up = VIEWS["right" if view == "side" else view]
        d = v.number("distance", distance)
        if not d > 0:
            raise ArgumentValueError(f"distance must be > 0, got {distance!r}")
        t = np.array(vector("target", target))
        return cls(eye=t + d * np.array(direction), target=t, up=up,
                   projection=orthographic() if projection is None else projection, **kw)

    def replace(self, **changes: Any) -> "Camera":
        """A copy with ``projection``, ``viewport`` or ``keep_aspect`` changed.

        Parameters
        ----------
        **changes
            New values of ``projection``, ``viewport`` or ``keep_aspect``.

        Returns
        -------
        Camera

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If another keyword is given or a value is invalid.

        Examples
        --------
        >>> import scanline as sl
        >>> sl.Camera().replace(keep_aspect=False).keep_aspect
        False
        """
        new = object.__new__(Camera)
        new.__dict__.update(self.__dict__)
        for key, value in changes.items():
            if key == "projection":
                if not isinstance(value, Projection):
                    raise ArgumentTypeError("projection must be a scanline.projection.Projection")
                new.projection = value
            elif key == "viewport":
                new.viewport = _viewport(value)
            elif key == "keep_aspect":
                if not isinstance(value, bool):
                    raise ArgumentTypeError(f"keep_aspect must be True or False, got "
                                            f"{v._show(value)}")
                new.keep_aspect = value
            else:
                raise ArgumentTypeError(
                    f"replace() takes projection, viewport or keep_aspect; got {key!r}")
        return new

    # -- matrices -------------------------------------------------------------------------
    @property
    def eye(self) -> tuple[float, ...] | None:
        """The world position of the center of projection (perspective), or None."""
        if self.projection.prp is None:
            return None
        p = t3.apply(t3.inverse(self.view_matrix), self.projection.prp)
        return tuple(float(c) for c in p)

    def _fit(self, aspect: float | None) -> NDArray[np.float64]:
        """The aspect correction (4x4, on clip coordinates) for a device viewport
        whose width / height is ``aspect`` (None: none)."""
        if not self.keep_aspect or aspect is None:
            return np.eye(4)
        xmin, ymin, xmax, ymax = self.projection.window
        window = (xmax - xmin) / (ymax - ymin)
        sx, sy = (window / aspect, 1.0) if aspect > window else (1.0, aspect / window)
        return np.array([[sx, 0, 0, 0.5 * (1 - sx)], [0, sy, 0, 0.5 * (1 - sy)],
                         [0, 0, 1, 0], [0, 0, 0, 1]], np.float64)

    def mapping(self, box: ArrayLike,
                aspect: float | None = None) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
        """How the camera projects into the rectangle ``box`` = (x0, y0, x1, y1) of
        some 2-D coordinates (a frame buffer's pixels, a display file's NDC):
        ``(matrix, scale, offset)``, the world -> clip matrix (the window widened to
        the displayed aspect ratio ``aspect`` = width / height of ``box`` as seen,
        default the box's own), and the per-axis map from NDC to ``box``
        (x, y) and to the depth range (z): ``ndc * scale + offset``.  The camera's
        3-D viewport is a part of ``box``.

        ``box`` needs x0 < x1 and y0 < y1 (finite); a device one pixel wide or high
        gets the box (-0.5, 0.5) on that axis (see :meth:`device`).

        Parameters
        ----------
        box : (x0, y0, x1, y1)
            The target rectangle, x0 < x1 and y0 < y1, finite.
        aspect : float, optional
            Width / height of ``box`` as displayed, > 0; the box's own by default.

        Returns
        -------
        matrix : ndarray of float64, shape (4, 4)
            World -> homogeneous clip coordinates.
        scale, offset : ndarray of float64, shape (3,)
            NDC -> box coordinates and depth: ``ndc * scale + offset``.

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``box`` is not a rectangle, ``aspect`` is not > 0, or the mapping
            overflows.

        Notes
        -----
        The 3-D viewport transformation: Hearn & Baker, section 12-3 (normalized view
        volumes and the workstation transformation).

        Examples
        --------
        >>> import scanline as sl
        >>> cam = sl.Camera(projection=sl.projection.orthographic(
        ...     window=(0, 0, 1, 1), front=1, back=-1), keep_aspect=False)
        >>> clip, scale, offset = cam.mapping((0, 0, 100, 50))
        >>> scale.tolist(), offset.tolist()
        ([100.0, 50.0, 1.0], [0.0, 0.0, 0.0])
        """
        corners = cast("Sequence[object]", box)
        if isinstance(corners, (str, bytes)) or not hasattr(corners, "__len__") or len(corners) != 4:
            raise ArgumentTypeError(f"box must be (x0, y0, x1, y1), four numbers, got "
                                    f"{v._show(box)}")
        x0, y0, x1, y1 = (v.number(f"box[{i}]", c) for i, c in enumerate(corners))
        with np.errstate(over="ignore"):
            wide, high = np.float64(x1) - x0, np.float64(y1) - y0
        if not (x0 < x1 and y0 < y1 and math.isfinite(wide) and math.isfinite(high)):
            raise ArgumentValueError(
                f"box={(x0, y0, x1, y1)} must have x0 < x1 and y0 < y1 (a rectangle with an "
                "area, its sides within float64), e.g. (0, 0, 639, 479)")
        dx, dy = float(wide), float(high)
        vx0, vy0, vz0, vx1, vy1, vz1 = self.viewport
        scale = np.array([(vx1 - vx0) * dx, (vy1 - vy0) * dy, vz1 - vz0])
        offset = np.array([x0 + vx0 * dx, y0 + vy0 * dy, vz0])
        if aspect is None:
            aspect = dx / dy
        else:
            aspect = v.number("aspect", aspect)
            if not aspect > 0:
                raise ArgumentValueError(f"aspect must be > 0 (width / height as seen), got "
                                         f"{aspect!r}")
        with np.errstate(all="ignore"):
            seen = aspect * (vx1 - vx0) / (vy1 - vy0)
            clip = self._fit(seen) @ self.projection.normalization @ self.view_matrix
        if not (np.isfinite(clip).all() and np.isfinite(scale).all()
                and np.isfinite(offset).all() and seen > 0):
            raise ArgumentValueError(
                f"box={(x0, y0, x1, y1)} with aspect={aspect!r} gives a mapping that overflows "
                "float64 (a box or an aspect ratio too extreme); use a box of ordinary "
                "proportions")
        return clip, scale, offset

    def _device_box(self, width: object,
                    height: object) -> tuple[float, float, float, float]:
        """The box of pixel centers of a ``width`` x ``height`` device: (0, 0) to
        (width - 1, height - 1); an axis one pixel long gets (-0.5, 0.5), the pixel's
        own extent about its center, so that NDC 0.5 -- the middle of the window --
        falls on the pixel's center (docs/three-d.md)."""
        w = v.positive_int("width", width)
        h = v.positive_int("height", height)
        x0, x1 = (0.0, float(w - 1)) if w > 1 else (-0.5, 0.5)
        y0, y1 = (0.0, float(h - 1)) if h > 1 else (-0.5, 0.5)
        return (x0, y0, x1, y1)

    def matrix(self, width: int | None = None, height: int | None = None) -> NDArray[np.float64]:
        """The world -> homogeneous clip matrix: N · V, with the window widened to a
        ``width`` x ``height`` device when given (and ``keep_aspect``).

        Parameters
        ----------
        width, height : int, optional
            The device's size in pixels; none: the window as it is.

        Returns
        -------
        ndarray of float64, shape (4, 4)

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If the size is not two positive integers.

        Notes
        -----
        Hearn & Baker, sections 12-2 and 12-3: the viewing transformation followed by
        the normalization of the view volume.

        Examples
        --------
        The window (0, 0)-(1, 1) is NDC already; z from front 1 to back -1 becomes
        the depth (1 - z) / 2:

        >>> import scanline as sl
        >>> cam = sl.Camera(projection=sl.projection.orthographic(
        ...     window=(0, 0, 1, 1), front=1, back=-1), keep_aspect=False)
        >>> cam.matrix().tolist()
        [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, -0.5, 0.5], [0.0, 0.0, 0.0, 1.0]]
        """
        if width is None:
            m: NDArray[np.float64] = self.projection.normalization @ self.view_matrix
            return m
        return self.mapping(self._device_box(width, height))[0]

    def device(self, width: int, height: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """``(scale, offset)``: device = NDC * scale + offset per axis (x, y, depth)
        for a ``width`` x ``height`` frame buffer and this camera's 3-D viewport.

        NDC 0 and 1 fall on the centers of the first and last pixels; on an axis one
        pixel long, on -0.5 and 0.5, the pixel's edges (its center is NDC 0.5).

        Parameters
        ----------
        width, height : int
            The frame buffer's size in pixels.

        Returns
        -------
        scale, offset : ndarray of float64, shape (3,)

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If the size is not two positive integers.

        Examples
        --------
        >>> import scanline as sl
        >>> cam = sl.Camera(projection=sl.projection.orthographic(
        ...     window=(0, 0, 1, 1), front=1, back=-1), keep_aspect=False)
        >>> [a.tolist() for a in cam.device(101, 51)]
        [[100.0, 50.0, 1.0], [0.0, 0.0, 0.0]]
        """
        return self.mapping(self._device_box(width, height))[1:]

    # -- points ---------------------------------------------------------------------------
    def to_viewing(self, points: ArrayLike) -> NDArray[np.float64]:
        """Points (N, 3) in viewing coordinates.

        Parameters
        ----------
        points : array_like, shape (N, 3) or (3,)
            World points.

        Returns
        -------
        ndarray of float64, in the shape of ``points``

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``points`` is not finite points.

        Examples
        --------
        >>> import scanline as sl
        >>> sl.Camera(eye=(0, 0, 5), target=(0, 0, 0)).to_viewing((0, 0, 0)).tolist()
        [0.0, 0.0, -5.0]
        """
        return t3.apply(self.view_matrix, points)

    def to_clip(self, points: ArrayLike, width: int | None = None,
                height: int | None = None) -> NDArray[np.float64]:
        """Points (N, 3) as homogeneous clip coordinates (N, 4).

        Parameters
        ----------
        points : array_like, shape (N, 3) or (3,)
            World points.
        width, height : int, optional
            The device, as :meth:`matrix`.

        Returns
        -------
        ndarray of float64, shape (N, 4) or (4,)

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``points`` is not finite points or the size is invalid.

        Examples
        --------
        >>> import scanline as sl
        >>> cam = sl.Camera(projection=sl.projection.orthographic(
        ...     window=(0, 0, 1, 1), front=1, back=-1), keep_aspect=False)
        >>> cam.to_clip((0.5, 0.5, 0)).tolist()
        [0.5, 0.5, 0.5, 1.0]
        """
        from .._kernels import project3d as k
        from .._kernels._jit import call

        p, single = point_array("points", points)
        out = np.empty((len(p), 4))
        call(k.to_clip, 4 * len(p), np.ascontiguousarray(self.matrix(width, height)), p, out)
        return out.reshape(4) if single else out

    def project(self, points: ArrayLike, width: int, height: int) -> NDArray[np.float64]:
        """Device x, y and depth of world points, (N, 3) (or (3,) for one point).

        x and y are device coordinates of a ``width`` x ``height`` frame buffer, the
        depth the NDC depth in the viewport's z range (0 on the front plane, 1 on
        the back plane by default).  Points outside the view volume still get their
        projection; points at or behind the eye of a perspective view (w <= 0) get
        NaN rather than a mirrored position.  Use :meth:`visible` to know which
        points are inside, and the clippers (:func:`scanline.clip.homogeneous`,
        :func:`scanline.draw3d.wireframe`) for lines and polygons.

        Parameters
        ----------
        points : array_like, shape (N, 3) or (3,)
            World points.
        width, height : int
            The frame buffer's size in pixels.

        Returns
        -------
        ndarray of float64, shape (N, 3) or (3,)
            Device x, y and depth.

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``points`` is not finite points or the size is invalid.

        Notes
        -----
        Hearn & Baker, sections 12-2 to 12-4: viewing, projection, normalization and
        the 3-D viewport.

        Examples
        --------
        >>> import scanline as sl
        >>> cam = sl.Camera(projection=sl.projection.orthographic(
        ...     window=(0, 0, 1, 1), front=1, back=-1), keep_aspect=False)
        >>> cam.project([(1, 1, 1), (0, 0, -1)], 101, 51).tolist()
        [[100.0, 50.0, 0.0], [0.0, 0.0, 1.0]]
        """
        from .._kernels import project3d as k
        from .._kernels._jit import call

        p, single = point_array("points", points)
        scale, offset = self.device(width, height)
        out = np.empty((len(p), 3))
        call(k.project_points, 6 * len(p), np.ascontiguousarray(self.matrix(width, height)),
             scale, offset, p, out)
        return out.reshape(3) if single else out

    def linear_depth(self, depth: ArrayLike) -> NDArray[np.float64]:
        """Device depths (as :meth:`project` gives them) turned into distances beyond
        the front plane along the viewing direction, linear in viewing coordinates
        (the NDC depth of a perspective view is a pseudo-depth, 1 - u_f / u scaled:
        the same order, not the same spacing).

        Parameters
        ----------
        depth : float or array_like
            Depths in the viewport's z range.

        Returns
        -------
        ndarray of float64, in the shape of ``depth``

        Raises
        ------
        ArgumentTypeError
            If ``depth`` is not real numbers.

        Examples
        --------
        The parallel volume from front 1 to back -1 is 2 deep:

        >>> import scanline as sl
        >>> cam = sl.Camera(projection=sl.projection.orthographic(
        ...     window=(0, 0, 1, 1), front=1, back=-1), keep_aspect=False)
        >>> cam.linear_depth([0.0, 0.5, 1.0]).tolist()
        [0.0, 1.0, 2.0]
        """
        from .._validate import real_array

        d = real_array("depth", depth, "a number or an array of depths")
        z0, z1 = self.viewport[2], self.viewport[5]
        p = self.projection
        with np.errstate(all="ignore"):       # NaN depths (points behind the eye) stay NaN
            zn = (d - z0) / (z1 - z0)
            if p.kind == "parallel":
                assert p.back is not None        # a parallel volume always has one
                out: NDArray[np.float64] = zn * (p.front - p.back)
                return out
            assert p.prp is not None             # a perspective projection has one
            uf = p.prp[2] - p.front
            if p.back is None:
                out = uf / (1.0 - zn) - uf
                return out
            ub = p.prp[2] - p.back
            out = uf * ub / (ub - zn * (ub - uf)) - uf
            return out

    def visible(self, points: ArrayLike, width: int | None = None,
                height: int | None = None) -> NDArray[np.bool_]:
        """Whether each point lies inside the view volume (boundary included).

        Parameters
        ----------
        points : array_like, shape (N, 3) or (3,)
            World points.
        width, height : int, optional
            The device, as :meth:`matrix`.

        Returns
        -------
        ndarray of bool, shape (N,)

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``points`` is not finite points or the size is invalid.

        Notes
        -----
        The test of homogeneous clipping, 0 <= x_h, y_h, z_h <= w (Blinn & Newell
        1978; Hearn & Baker, section 12-5).

        Examples
        --------
        >>> import scanline as sl
        >>> cam = sl.Camera(projection=sl.projection.orthographic(
        ...     window=(0, 0, 1, 1), front=1, back=-1), keep_aspect=False)
        >>> cam.visible([(0.5, 0.5, 0), (2, 0, 0)]).tolist()
        [True, False]
        """
        h = np.atleast_2d(self.to_clip(points, width, height))
        w = h[:, 3:]
        inside: NDArray[np.bool_] = (((h[:, :3] >= 0) & (h[:, :3] <= w)).all(axis=1)
                                     & (w[:, 0] > 0))
        return inside

    def vanishing_point(self, direction: ArrayLike, width: int,
                        height: int) -> tuple[float, float] | None:
        """The device position (x, y) where lines along ``direction`` (world
        coordinates) converge, or None when they stay parallel (the direction is
        parallel to the view plane, or the projection is parallel).

        The vanishing point is the image of the point at infinity (d, 0): the clip
        coordinates M · (dx, dy, dz, 0), divided by their w (Hearn & Baker, section
        12-3: "principal vanishing points" for lines parallel to the axes).

        Parameters
        ----------
        direction : (float, float, float)
            A nonzero world direction.
        width, height : int
            The frame buffer's size in pixels.

        Returns
        -------
        (float, float) or None

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``direction`` is not a finite nonzero 3-vector or the size is invalid.

        Examples
        --------
        Lines along the view direction meet in the middle; lines across it stay
        parallel:

        >>> import math, scanline as sl
        >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
        ...                 projection=sl.projection.perspective(fov=math.pi / 2, near=1))
        >>> cam.vanishing_point((0, 0, -1), 101, 101)
        (50.0, 50.0)
        >>> cam.vanishing_point((1, 0, 0), 101, 101) is None
        True
        """
        from ..transform3d.arrays import direction as unit

        d = unit("direction", direction)
        h = self.matrix(width, height) @ np.append(d, 0.0)
        if abs(h[3]) <= 1e-12 * np.abs(h).max():
            return None
        scale, offset = self.device(width, height)
        ndc = h[:3] / h[3]
        return (float(ndc[0] * scale[0] + offset[0]), float(ndc[1] * scale[1] + offset[1]))

    def volume_corners(self, width: int | None = None, height: int | None = None) -> NDArray[np.float64]:
        """The corners of the view volume in world coordinates, (8, 3): the front face
        counterclockwise from the lower left, then the back face (for a volume
        without a back plane, drawn at ten times the front plane's distance).  With
        ``width`` and ``height``, the window widened to that device.

        Parameters
        ----------
        width, height : int, optional
            The device, as :meth:`matrix`.

        Returns
        -------
        ndarray of float64, shape (8, 3)

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If the size is invalid.

        Examples
        --------
        >>> import scanline as sl
        >>> cam = sl.Camera(projection=sl.projection.orthographic(
        ...     window=(0, 0, 1, 1), front=1, back=-1), keep_aspect=False)
        >>> cam.volume_corners()[:4].tolist()          # the front face, z = 1
        [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [1.0, 1.0, 1.0], [0.0, 1.0, 1.0]]
        """
        return _corners(self.matrix(width, height), self.projection)

    def stereo(self, eye_separation: float) -> tuple["Camera", "Camera"]:
        """Left-eye and right-eye cameras for a stereoscopic view (Hearn & Baker,
        section 9-1): the eye moved by -``eye_separation`` / 2 and +``eye_separation``
        / 2 along the camera's x_v (u) axis, both looking at the target (the two views
        are computed "from viewing directions along the lines from each eye position
        to the center of the scene"); up vector, projection and viewport are the mono
        camera's.  Needs a camera made with eye and target.  Show the pair with
        :func:`scanline.draw3d.anaglyph` or :func:`scanline.draw3d.side_by_side`.

        Parameters
        ----------
        eye_separation : float
            The distance between the eyes in world units, >= 0.

        Returns
        -------
        left, right : Camera

        Raises
        ------
        ArgumentValueError
            If ``eye_separation`` is negative or huge, or the camera was not made with
            eye and target.

        Examples
        --------
        >>> import scanline as sl
        >>> left, right = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0)).stereo(0.5)
        >>> [round(c, 6) for c in left.eye], [round(c, 6) for c in right.eye]
        ([-0.25, 0.0, 5.0], [0.25, 0.0, 5.0])
        """
        s = v.number("eye_separation", eye_separation)
        if not 0 <= s < 1e150:
            raise ArgumentValueError(
                f"eye_separation={s} must be >= 0 (the distance between the eyes, in world "
                "units; about a thirtieth of the distance to the target looks natural)")
        if self.target is None or self._eye is None:
            raise ArgumentValueError(
                "stereo needs a camera made with eye= and target= (the eyes turn toward "
                "the target)")
        eye = np.array(self._eye)
        u = t3.inverse(self.view_matrix)[:3, 0]
        left, right = (Camera(eye=eye + sign * s / 2 * u, target=self.target, up=self.up,
                              projection=self.projection, viewport=self.viewport,
                              keep_aspect=self.keep_aspect) for sign in (-1.0, 1.0))
        return left, right

    def __repr__(self) -> str:
        return (f"<Camera {self.projection.name} ({self.projection.kind}), viewport="
                f"{self.viewport}, keep_aspect={self.keep_aspect}>")
