"""The analytic primitives of solid modeling: quadric solids (Hearn & Baker 10-3:
sphere, ellipsoid, the general quadric surface in its implicit form), boxes, and capped
cylinders and cones, each placed by an optional 4 x 4 transformation.

Each primitive is a standard solid in its own coordinates u, mapped to the world by
a 4 x 4 matrix M (x = M u): the set of u with (u, 1)^T Q (u, 1) <= 0 for a symmetric
4 x 4 Q (where it has a quadric), clipped to the slabs lo <= u <= hi.  The ray
kernels (:mod:`scanline._kernels.solids`) work in these coordinates.
"""

import math
from typing import TYPE_CHECKING, Any, Optional, Sequence, Union, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from .base import Bounds, Solid, material_of, point_rows

if TYPE_CHECKING:
    from ..lighting import Material

#: A 3-vector: three numbers, or a (3,) array.
Vector = Union[Sequence[float], NDArray[np.float64]]

#: Quadric of the unit sphere x^2 + y^2 + z^2 - 1.
UNIT_SPHERE = np.diag([1.0, 1.0, 1.0, -1.0])
#: Quadric of the unit cylinder about z, x^2 + y^2 - 1.
UNIT_CYLINDER = np.diag([1.0, 1.0, 0.0, -1.0])
#: Quadric of the cone x^2 + y^2 - (1 - z)^2 (apex at z = 1, radius 1 at z = 0).
UNIT_CONE = np.array([[1.0, 0, 0, 0], [0, 1.0, 0, 0], [0, 0, -1.0, 1.0], [0, 0, 1.0, -1.0]])

_INF3 = np.full(3, math.inf)


def _positive(name: str, value: float) -> float:
    x = v.number(name, value)
    if not (x > 0 and math.isfinite(x)):
        raise ArgumentValueError(f"{name} must be a positive finite number, got {v._show(value)}")
    return x


def _vector(name: str, value: Vector) -> NDArray[np.float64]:
    from ..transform3d.arrays import vector

    return np.array(vector(name, value))


def _transform(transform: Optional[ArrayLike]) -> NDArray[np.float64]:
    """The 4 x 4 matrix ``transform`` (None: identity), affine and invertible."""
    from ..transform3d.arrays import matrix4

    if transform is None:
        return np.eye(4)
    m = matrix4("transform", transform)
    if not np.array_equal(m[3], [0.0, 0.0, 0.0, 1.0]):
        raise ArgumentValueError(f"transform must be affine (last row 0, 0, 0, 1), got last row "
                                 f"{m[3].tolist()}")
    det = np.linalg.det(m[:3, :3])
    if not (abs(det) > 1e-300 and math.isfinite(det)):
        raise ArgumentValueError(f"transform must be invertible (its 3 x 3 part has determinant "
                                 f"{det}): a solid flattened to nothing has no inside")
    return m


def frame(axis: Vector) -> NDArray[np.float64]:
    """A rotation (4 x 4) taking the z axis to the unit vector along ``axis``."""
    from ..transform3d.arrays import direction

    w = direction("axis", axis)
    u = np.cross(w, [1.0, 0.0, 0.0] if abs(w[0]) < 0.9 else [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2] = u, np.cross(w, u), w
    return m


def _placed(center: NDArray[np.float64], scale: Sequence[float],
            rotation: Optional[NDArray[np.float64]] = None) -> NDArray[np.float64]:
    m = np.diag([*scale, 1.0])
    if rotation is not None:
        m = rotation @ m
    m[:3, 3] = center
    return m


class Primitive(Solid):
    """An analytic primitive: the standard solid (quadric ``q`` or None, slabs ``lo``
    .. ``hi``) placed by the matrix ``matrix`` (x = M u).

    Parameters
    ----------
    matrix : ndarray (4, 4)
        M, affine and invertible: world = M (own coordinates).
    quadric : ndarray (4, 4) or None
        The symmetric Q of (u, 1)^T Q (u, 1) <= 0 (None: slabs only).
    lo, hi : array_like (3,)
        The slabs lo <= u <= hi (+-inf: none).
    material : Material or None
        The surface's material (None: the default).

    Examples
    --------
    The unit cube as slabs alone:

    >>> import numpy as np, scanline as sl
    >>> cube = sl.solids.Primitive(np.eye(4), None, (0, 0, 0), (1, 1, 1), None)
    >>> cube.contains([(0.5, 0.5, 0.5), (2, 0, 0)]).tolist()
    [True, False]
    """

    #: The standard solid's volume (None: not closed-form).
    unit_volume: Optional[float] = None

    def __init__(self, matrix: NDArray[np.float64], quadric: Optional[NDArray[np.float64]],
                 lo: ArrayLike, hi: ArrayLike, material: Optional["Material"]) -> None:
        self.matrix = matrix
        self.inverse = np.linalg.inv(matrix)
        self.quadric = quadric
        self.lo = np.asarray(lo, np.float64)
        self.hi = np.asarray(hi, np.float64)
        self.material = material_of(material)

    def row(self) -> NDArray[np.float64]:
        """The kernel's row (:data:`scanline._kernels.solids.COLUMNS` reals).

        Returns
        -------
        ndarray (35,)
            The kind, M^-1's first three rows (12), Q (16), lo (3) and hi (3).

        Examples
        --------
        >>> import scanline as sl
        >>> len(sl.solids.Box().row())
        35
        """
        from .._kernels.solids import QUADRIC, SLABS

        kind = SLABS if self.quadric is None else QUADRIC
        q = np.zeros((4, 4)) if self.quadric is None else self.quadric
        return np.concatenate([[kind], self.inverse[:3].ravel(), q.ravel(), self.lo, self.hi])

    def local(self, points: ArrayLike) -> NDArray[np.float64]:
        """World points (N, 3) in the primitive's own coordinates.

        Parameters
        ----------
        points : array_like (N, 3) or (3,)
            World points.

        Returns
        -------
        ndarray (N, 3)
            u = M^-1 x.

        Examples
        --------
        A sphere of radius 2 about (1, 2, 3) is the unit sphere scaled by 2 and moved:

        >>> import scanline as sl
        >>> sl.solids.Sphere((1, 2, 3), 2.0).local([(3, 2, 3)]).tolist()
        [[1.0, 0.0, 0.0]]
        """
        p = point_rows(points)
        u: NDArray[np.float64] = p @ self.inverse[:3, :3].T + self.inverse[:3, 3]
        return u

    def contains(self, points: ArrayLike) -> NDArray[np.bool_]:
        """Whether each point is inside: within the slabs and, where there is a
        quadric, (u, 1)^T Q (u, 1) <= 0 (Hearn & Baker 10-3).

        Parameters
        ----------
        points : array_like (N, 3) or (3,)
            World points.

        Returns
        -------
        ndarray (N,) bool
            True inside (the surface included).

        Examples
        --------
        >>> import scanline as sl
        >>> sl.solids.Cylinder().contains([(0.9, 0, 0.9), (0, 0, 1.1)]).tolist()
        [True, False]
        """
        u = self.local(points)
        # numpy's stub: all(axis=) may be a scalar; here always (n,)
        inside = cast("NDArray[np.bool_]", ((u >= self.lo) & (u <= self.hi)).all(axis=1))
        if self.quadric is not None:
            h = np.hstack([u, np.ones((len(u), 1))])
            inside &= np.einsum("ni,ij,nj->n", h, self.quadric, h) <= 0
        return inside

    def bounds(self) -> Bounds:
        """The box of the standard solid's slab box mapped by M (corners; tight for
        boxes, spheres and ellipsoids, which say so themselves).

        Returns
        -------
        lo, hi : ndarray (3,)
            The box's corners (+-inf where unbounded).

        Examples
        --------
        >>> import scanline as sl
        >>> [c.tolist() for c in sl.solids.Cylinder().bounds()]
        [[-1.0, -1.0, -1.0], [1.0, 1.0, 1.0]]
        """
        corners = np.array([[x, y, z] for x in (self.lo[0], self.hi[0])
                            for y in (self.lo[1], self.hi[1]) for z in (self.lo[2], self.hi[2])])
        if not np.isfinite(corners).all():
            return -_INF3.copy(), _INF3.copy()
        w = corners @ self.matrix[:3, :3].T + self.matrix[:3, 3]
        return w.min(axis=0), w.max(axis=0)

    def volume(self) -> float:
        """The exact volume: the standard solid's times |det M|.

        Returns
        -------
        float
            The volume.

        Examples
        --------
        The default cylinder, radius 1 and height 2: pi r^2 h = 2 pi.

        >>> import scanline as sl
        >>> round(sl.solids.Cylinder().volume(), 6)
        6.283185
        """
        if self.unit_volume is None:
            raise TypeError(f"{type(self).__name__} has no closed-form volume: measure it "
                            f"with scanline.csg.volume")
        return float(self.unit_volume * abs(np.linalg.det(self.matrix[:3, :3])))

    def __repr__(self) -> str:
        return f"<{type(self).__name__}: M {np.round(self.matrix[:3], 6).tolist()}>"


class Ellipsoid(Primitive):
    """The ellipsoid (x - c_x)^2 / r_x^2 + (y - c_y)^2 / r_y^2 + (z - c_z)^2 / r_z^2 <= 1
    (Hearn & Baker 10-3, eq. 10-10), then ``transform``; volume 4/3 pi r_x r_y r_z.

    Parameters
    ----------
    center : 3-vector
        c.
    radii : 3-vector
        r_x, r_y, r_z, positive.
    material : Material, optional
        The surface's material (default ``Material()``).
    transform : array_like (4, 4), optional
        An affine, invertible matrix applied after the placement.

    Raises
    ------
    ArgumentValueError
        A radius not positive and finite, or a transform not affine and invertible.

    Examples
    --------
    >>> import scanline as sl
    >>> e = sl.solids.Ellipsoid((0, 0, 0), (3, 2, 1))
    >>> round(e.volume(), 6), e.contains([(2.9, 0, 0), (0, 2.1, 0)]).tolist()
    (25.132741, [True, False])
    """
    unit_volume = 4.0 / 3.0 * math.pi

    def __init__(self, center: Vector = (0.0, 0.0, 0.0), radii: Vector = (1.0, 1.0, 1.0), *,
                 material: Optional["Material"] = None,
                 transform: Optional[ArrayLike] = None) -> None:
        r = [_positive(f"radii[{i}]", x) for i, x in enumerate(_vector("radii", radii))]
        m = _transform(transform) @ _placed(_vector("center", center), r)
        super().__init__(m, UNIT_SPHERE, -_INF3, _INF3, material)

    def bounds(self) -> Bounds:
        """Exact: the center +- the norms of the rows of M's linear part.

        Returns
        -------
        lo, hi : ndarray (3,)
            The tight box.

        Examples
        --------
        >>> import scanline as sl
        >>> [c.tolist() for c in sl.solids.Ellipsoid((1, 0, 0), (3, 2, 1)).bounds()]
        [[-2.0, -2.0, -1.0], [4.0, 2.0, 1.0]]
        """
        c = self.matrix[:3, 3]
        with np.errstate(over="ignore"):            # past the float range: unbounded
            half = np.sqrt((self.matrix[:3, :3] ** 2).sum(axis=1))
        return c - half, c + half


class Sphere(Ellipsoid):
    """The ball |x - center| <= radius (Hearn & Baker 10-3, eq. 10-7), then ``transform``.

    Parameters
    ----------
    center : 3-vector
        The center.
    radius : float
        Positive.
    material : Material, optional
        The surface's material (default ``Material()``).
    transform : array_like (4, 4), optional
        An affine, invertible matrix applied after the placement.

    Examples
    --------
    >>> import scanline as sl
    >>> s = sl.solids.Sphere((0, 0, 0), 2.0)
    >>> round(s.volume(), 6), [b.tolist() for b in s.bounds()]
    (33.510322, [[-2.0, -2.0, -2.0], [2.0, 2.0, 2.0]])
    """

    def __init__(self, center: Vector = (0.0, 0.0, 0.0), radius: float = 1.0, *,
                 material: Optional["Material"] = None,
                 transform: Optional[ArrayLike] = None) -> None:
        r = _positive("radius", radius)
        super().__init__(center, (r, r, r), material=material, transform=transform)


class Box(Primitive):
    """The box lo <= x <= hi (axis-aligned), then ``transform``.

    Parameters
    ----------
    lo, hi : 3-vectors
        Opposite corners, lo below hi on every axis.
    material : Material, optional
        The surface's material (default ``Material()``).
    transform : array_like (4, 4), optional
        An affine, invertible matrix applied after the placement.

    Raises
    ------
    ArgumentValueError
        lo not below hi, or a bad transform.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.solids.Box((0, 0, 0), (1, 2, 3)).volume()
    6.0
    """

    def __init__(self, lo: Vector = (-1.0, -1.0, -1.0), hi: Vector = (1.0, 1.0, 1.0), *,
                 material: Optional["Material"] = None,
                 transform: Optional[ArrayLike] = None) -> None:
        a, b = _vector("lo", lo), _vector("hi", hi)
        if not (a < b).all():
            raise ArgumentValueError(f"lo must be below hi on every axis, got lo={a.tolist()} "
                                     f"and hi={b.tolist()}")
        super().__init__(_transform(transform), None, a, b, material)

    def volume(self) -> float:
        """The box's volume times |det M| of its transform.

        Returns
        -------
        float
            The volume.

        Examples
        --------
        The unit cube scaled by 2: 2^3.

        >>> import numpy as np, scanline as sl
        >>> round(sl.solids.Box((0, 0, 0), (1, 1, 1), transform=np.diag([2, 2, 2, 1])).volume(), 9)
        8.0
        """
        return float(np.prod(self.hi - self.lo) * abs(np.linalg.det(self.matrix[:3, :3])))


class Cylinder(Primitive):
    """The capped circular cylinder of ``radius`` and ``height`` about ``axis`` through
    ``center`` (the middle of its axis), then ``transform``: the quadric x^2 + y^2 = 1
    (Hearn & Baker 10-3) cut by two planes; volume pi r^2 h.

    Parameters
    ----------
    center : 3-vector
        The middle of its axis.
    radius, height : float
        Positive.
    axis : 3-vector
        The axis's direction.
    material : Material, optional
        The surface's material (default ``Material()``).
    transform : array_like (4, 4), optional
        An affine, invertible matrix applied after the placement.

    Examples
    --------
    >>> import scanline as sl
    >>> c = sl.solids.Cylinder(radius=1.0, height=2.0)
    >>> round(c.volume(), 6), c.contains([(0, 0.9, -0.9), (1.1, 0, 0)]).tolist()
    (6.283185, [True, False])
    """
    unit_volume = 2.0 * math.pi

    def __init__(self, center: Vector = (0.0, 0.0, 0.0), radius: float = 1.0,
                 height: float = 2.0, axis: Vector = (0.0, 0.0, 1.0), *,
                 material: Optional["Material"] = None,
                 transform: Optional[ArrayLike] = None) -> None:
        r, h = _positive("radius", radius), _positive("height", height)
        m = _transform(transform) @ _placed(_vector("center", center), (r, r, h / 2),
                                            frame(axis))
        super().__init__(m, UNIT_CYLINDER, [-1.0, -1.0, -1.0], [1.0, 1.0, 1.0], material)


class Cone(Primitive):
    """The capped right circular cone with its base of ``radius`` centered at ``base``
    and its apex ``height`` along ``axis``, then ``transform``: the quadric x^2 + y^2 =
    (1 - z)^2 cut by the base plane; volume pi r^2 h / 3.

    Parameters
    ----------
    base : 3-vector
        The base's center.
    radius, height : float
        Positive.
    axis : 3-vector
        From the base toward the apex.
    material : Material, optional
        The surface's material (default ``Material()``).
    transform : array_like (4, 4), optional
        An affine, invertible matrix applied after the placement.

    Examples
    --------
    Height 3 and radius 1: pi r^2 h / 3 = pi; the apex is at z = 3.

    >>> import scanline as sl
    >>> cone = sl.solids.Cone(height=3.0)
    >>> round(cone.volume(), 6), cone.contains([(0, 0, 0.5), (0, 0, 3.5)]).tolist()
    (3.141593, [True, False])
    """
    unit_volume = math.pi / 3.0

    def __init__(self, base: Vector = (0.0, 0.0, 0.0), radius: float = 1.0, height: float = 1.0,
                 axis: Vector = (0.0, 0.0, 1.0), *, material: Optional["Material"] = None,
                 transform: Optional[ArrayLike] = None) -> None:
        r, h = _positive("radius", radius), _positive("height", height)
        m = _transform(transform) @ _placed(_vector("base", base), (r, r, h), frame(axis))
        super().__init__(m, UNIT_CONE, [-1.0, -1.0, 0.0], [1.0, 1.0, 1.0], material)


class Quadric(Primitive):
    """The general quadric solid (Hearn & Baker 10-3): the points (x, y, z) where
    (x, y, z, 1) Q (x, y, z, 1)^T <= 0 for a symmetric 4 x 4 ``matrix`` Q, then
    ``transform``.  It may be unbounded (a cylinder, a paraboloid, a half space):
    intersect it with a :class:`Box` to render or measure it.

    Parameters
    ----------
    matrix : array_like (4, 4)
        Q, symmetric, not all zero.
    material : Material, optional
        The surface's material (default ``Material()``).
    transform : array_like (4, 4), optional
        An affine, invertible matrix applied after the placement.

    Raises
    ------
    ArgumentValueError
        Q not symmetric or all zeros, or a bad transform.

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> q = sl.solids.Quadric.from_coefficients(a=1, b=1, c=1, j=-4)   # x^2+y^2+z^2 = 4
    >>> round(q.volume(), 6)
    33.510322
    """

    def __init__(self, matrix: ArrayLike, *, material: Optional["Material"] = None,
                 transform: Optional[ArrayLike] = None) -> None:
        from ..transform3d.arrays import matrix4

        q = matrix4("matrix", matrix)
        if not np.allclose(q, q.T, rtol=0, atol=1e-12 * np.abs(q).max()):
            raise ArgumentValueError("matrix must be symmetric (Q = Q^T): write each cross term "
                                     "half above and half below the diagonal")
        if not np.abs(q).max() > 0:
            raise ArgumentValueError("matrix must not be all zeros (it would be no surface)")
        super().__init__(_transform(transform), (q + q.T) / 2, -_INF3, _INF3, material)

    @classmethod
    def from_coefficients(cls, a: float = 0.0, b: float = 0.0, c: float = 0.0, d: float = 0.0,
                          e: float = 0.0, f: float = 0.0, g: float = 0.0, h: float = 0.0,
                          i: float = 0.0, j: float = 0.0, **kw: Any) -> "Quadric":
        """The solid a x^2 + b y^2 + c z^2 + 2 d xy + 2 e yz + 2 f xz + 2 g x + 2 h y +
        2 i z + j <= 0 (the quadric's implicit equation, Hearn & Baker eq. 10-3 with
        its cross terms halved into the symmetric matrix).

        Parameters
        ----------
        a, b, c : float
            The squares' coefficients.
        d, e, f : float
            Half the xy, yz and xz coefficients.
        g, h, i : float
            Half the x, y and z coefficients.
        j : float
            The constant.
        **kw
            ``material`` and ``transform``.

        Returns
        -------
        Quadric
            The solid.

        Examples
        --------
        The unit ball about (1, 0, 0): (x - 1)^2 + y^2 + z^2 <= 1 is x^2 + y^2 + z^2 -
        2 x <= 0, so a = b = c = 1 and g = -1 (half of -2).

        >>> import scanline as sl
        >>> q = sl.solids.Quadric.from_coefficients(a=1, b=1, c=1, g=-1)
        >>> q.contains([(1.9, 0, 0), (-0.1, 0, 0)]).tolist()
        [True, False]
        """
        return cls([[a, d, f, g], [d, b, e, h], [f, e, c, i], [g, h, i, j]], **kw)

    def _ellipsoid(self) -> Optional[tuple[NDArray[np.float64], float, NDArray[np.float64]]]:
        """(center, half-axes matrix) when the solid is a bounded ellipsoid, else None."""
        q = self.quadric
        assert q is not None                      # a Quadric's is always set
        a, b, c = q[:3, :3], q[:3, 3], q[3, 3]
        if not (np.linalg.eigvalsh(a) > 0).all():
            return None
        center = -np.asarray(np.linalg.solve(a, b), np.float64)    # floating[Any] to the stubs
        k: float = b @ -center - c
        return (center, k, a) if k > 0 else None

    def bounds(self) -> Bounds:
        """Exact for an ellipsoid (the center +- sqrt(k (A^-1)_ii) per axis, mapped by
        the transform's rows), else unbounded.

        Returns
        -------
        lo, hi : ndarray (3,)
            The box (+-inf: unbounded).

        Examples
        --------
        >>> import scanline as sl
        >>> q = sl.solids.Quadric.from_coefficients(a=1, b=1, c=1, j=-4)   # radius 2
        >>> [c.tolist() for c in q.bounds()]
        [[-2.0, -2.0, -2.0], [2.0, 2.0, 2.0]]
        """
        e = self._ellipsoid()
        if e is None:
            return -_INF3.copy(), _INF3.copy()
        center, k, a = e
        # x = M u with u on the ellipsoid u^T A u' = k: half-extents sqrt(k m_i A^-1 m_i)
        lin = self.matrix[:3, :3]
        half = np.sqrt(k * np.einsum("ij,jk,ik->i", lin, np.linalg.inv(a), lin))
        c = lin @ center + self.matrix[:3, 3]
        return c - half, c + half

    def volume(self) -> float:
        """Exact for an ellipsoid, 4/3 pi k^(3/2) / sqrt(det A) |det M|; an empty
        quadric has volume 0; others are refused.

        Returns
        -------
        float
            The volume.

        Raises
        ------
        ArgumentValueError
            An unbounded quadric.

        Examples
        --------
        Radius 2: 4/3 pi 8 = 33.510322.

        >>> import scanline as sl
        >>> round(sl.solids.Quadric.from_coefficients(a=1, b=1, c=1, j=-4).volume(), 6)
        33.510322
        """
        e = self._ellipsoid()
        if e is None:
            assert self.quadric is not None
            a = self.quadric[:3, :3]
            if (np.linalg.eigvalsh(a) > 0).all():
                return 0.0
            raise ArgumentValueError("this quadric is not a bounded ellipsoid: its volume is "
                                     "infinite (intersect it with a Box and use "
                                     "scanline.csg.volume)")
        _, k, a = e
        return float(4.0 / 3.0 * math.pi * k ** 1.5 / math.sqrt(np.linalg.det(a))
                     * abs(np.linalg.det(self.matrix[:3, :3])))
