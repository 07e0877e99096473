"""The analytic primitives of solid modeling: quadric solids (Hearn & Baker 10-3:
sphere, ellipsoid, the general quadric surface in its implicit form), boxes, and capped
cylinders and cones, each placed by an optional 4 x 4 transformation.

Each primitive is a standard solid in its own coordinates u, mapped to the world by
a 4 x 4 matrix M (x = M u): the set of u with (u, 1)^T Q (u, 1) <= 0 for a symmetric
4 x 4 Q (where it has a quadric), clipped to the slabs lo <= u <= hi.  The ray
kernels (:mod:`scanline._kernels.solids`) work in these coordinates.
"""

import math

import numpy as np

from .. import _validate as v
from ..errors import ArgumentValueError
from .base import Solid, material_of, point_rows

#: Quadric of the unit sphere x^2 + y^2 + z^2 - 1.
UNIT_SPHERE = np.diag([1.0, 1.0, 1.0, -1.0])
#: Quadric of the unit cylinder about z, x^2 + y^2 - 1.
UNIT_CYLINDER = np.diag([1.0, 1.0, 0.0, -1.0])
#: Quadric of the cone x^2 + y^2 - (1 - z)^2 (apex at z = 1, radius 1 at z = 0).
UNIT_CONE = np.array([[1.0, 0, 0, 0], [0, 1.0, 0, 0], [0, 0, -1.0, 1.0], [0, 0, 1.0, -1.0]])

_INF3 = np.full(3, math.inf)


def _positive(name, value):
    x = v.number(name, value)
    if not (x > 0 and math.isfinite(x)):
        raise ArgumentValueError(f"{name} must be a positive finite number, got {v._show(value)}")
    return x


def _vector(name, value):
    from ..transform3d.arrays import vector

    return np.array(vector(name, value))


def _transform(transform):
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


def frame(axis):
    """A rotation (4 x 4) taking the z axis to the unit vector along ``axis``."""
    from ..transform3d.arrays import direction

    w = direction("axis", axis)
    u = np.cross(w, [1.0, 0.0, 0.0] if abs(w[0]) < 0.9 else [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2] = u, np.cross(w, u), w
    return m


def _placed(center, scale, rotation=None):
    m = np.diag([*scale, 1.0])
    if rotation is not None:
        m = rotation @ m
    m[:3, 3] = center
    return m


class Primitive(Solid):
    """An analytic primitive: the standard solid (quadric ``q`` or None, slabs ``lo``
    .. ``hi``) placed by the matrix ``matrix`` (x = M u)."""

    #: The standard solid's volume (None: not closed-form).
    unit_volume = None

    def __init__(self, matrix, quadric, lo, hi, material):
        self.matrix = matrix
        self.inverse = np.linalg.inv(matrix)
        self.quadric = quadric
        self.lo = np.asarray(lo, np.float64)
        self.hi = np.asarray(hi, np.float64)
        self.material = material_of(material)

    def row(self):
        """The kernel's row (:data:`scanline._kernels.solids.COLUMNS` reals)."""
        from .._kernels.solids import QUADRIC, SLABS

        kind = SLABS if self.quadric is None else QUADRIC
        q = np.zeros((4, 4)) if self.quadric is None else self.quadric
        return np.concatenate([[kind], self.inverse[:3].ravel(), q.ravel(), self.lo, self.hi])

    def local(self, points):
        """World points (N, 3) in the primitive's own coordinates."""
        p = point_rows(points)
        return p @ self.inverse[:3, :3].T + self.inverse[:3, 3]

    def contains(self, points):
        u = self.local(points)
        inside = ((u >= self.lo) & (u <= self.hi)).all(axis=1)
        if self.quadric is not None:
            h = np.hstack([u, np.ones((len(u), 1))])
            inside &= np.einsum("ni,ij,nj->n", h, self.quadric, h) <= 0
        return inside

    def bounds(self):
        """The box of the standard solid's slab box mapped by M (corners; tight for
        boxes, spheres and ellipsoids, which say so themselves)."""
        corners = np.array([[x, y, z] for x in (self.lo[0], self.hi[0])
                            for y in (self.lo[1], self.hi[1]) for z in (self.lo[2], self.hi[2])])
        if not np.isfinite(corners).all():
            return -_INF3.copy(), _INF3.copy()
        w = corners @ self.matrix[:3, :3].T + self.matrix[:3, 3]
        return w.min(axis=0), w.max(axis=0)

    def volume(self):
        """The exact volume: the standard solid's times |det M|."""
        return float(self.unit_volume * abs(np.linalg.det(self.matrix[:3, :3])))

    def __repr__(self):
        return f"<{type(self).__name__}: M {np.round(self.matrix[:3], 6).tolist()}>"


class Ellipsoid(Primitive):
    """The ellipsoid (x - c_x)^2 / r_x^2 + (y - c_y)^2 / r_y^2 + (z - c_z)^2 / r_z^2 <= 1
    (Hearn & Baker 10-3, eq. 10-10), then ``transform``; volume 4/3 pi r_x r_y r_z.

    >>> import scanline as sl
    >>> e = sl.solids.Ellipsoid((0, 0, 0), (3, 2, 1))
    >>> round(e.volume(), 6), e.contains([(2.9, 0, 0), (0, 2.1, 0)]).tolist()
    (25.132741, [True, False])
    """
    unit_volume = 4.0 / 3.0 * math.pi

    def __init__(self, center=(0.0, 0.0, 0.0), radii=(1.0, 1.0, 1.0), *, material=None,
                 transform=None):
        r = [_positive(f"radii[{i}]", x) for i, x in enumerate(_vector("radii", radii))]
        m = _transform(transform) @ _placed(_vector("center", center), r)
        super().__init__(m, UNIT_SPHERE, -_INF3, _INF3, material)

    def bounds(self):
        """Exact: the center +- the norms of the rows of M's linear part."""
        c = self.matrix[:3, 3]
        with np.errstate(over="ignore"):            # past the float range: unbounded
            half = np.sqrt((self.matrix[:3, :3] ** 2).sum(axis=1))
        return c - half, c + half


class Sphere(Ellipsoid):
    """The ball |x - center| <= radius (Hearn & Baker 10-3, eq. 10-7), then ``transform``.

    >>> import scanline as sl
    >>> s = sl.solids.Sphere((0, 0, 0), 2.0)
    >>> round(s.volume(), 6), [b.tolist() for b in s.bounds()]
    (33.510322, [[-2.0, -2.0, -2.0], [2.0, 2.0, 2.0]])
    """

    def __init__(self, center=(0.0, 0.0, 0.0), radius=1.0, *, material=None, transform=None):
        r = _positive("radius", radius)
        super().__init__(center, (r, r, r), material=material, transform=transform)


class Box(Primitive):
    """The box lo <= x <= hi (axis-aligned), then ``transform``.

    >>> import scanline as sl
    >>> sl.solids.Box((0, 0, 0), (1, 2, 3)).volume()
    6.0
    """

    def __init__(self, lo=(-1.0, -1.0, -1.0), hi=(1.0, 1.0, 1.0), *, material=None,
                 transform=None):
        a, b = _vector("lo", lo), _vector("hi", hi)
        if not (a < b).all():
            raise ArgumentValueError(f"lo must be below hi on every axis, got lo={a.tolist()} "
                                     f"and hi={b.tolist()}")
        super().__init__(_transform(transform), None, a, b, material)

    def volume(self):
        return float(np.prod(self.hi - self.lo) * abs(np.linalg.det(self.matrix[:3, :3])))


class Cylinder(Primitive):
    """The capped circular cylinder of ``radius`` and ``height`` about ``axis`` through
    ``center`` (the middle of its axis), then ``transform``: the quadric x^2 + y^2 = 1
    (Hearn & Baker 10-3) cut by two planes; volume pi r^2 h."""
    unit_volume = 2.0 * math.pi

    def __init__(self, center=(0.0, 0.0, 0.0), radius=1.0, height=2.0, axis=(0.0, 0.0, 1.0), *,
                 material=None, transform=None):
        r, h = _positive("radius", radius), _positive("height", height)
        m = _transform(transform) @ _placed(_vector("center", center), (r, r, h / 2),
                                            frame(axis))
        super().__init__(m, UNIT_CYLINDER, [-1.0, -1.0, -1.0], [1.0, 1.0, 1.0], material)


class Cone(Primitive):
    """The capped right circular cone with its base of ``radius`` centered at ``base``
    and its apex ``height`` along ``axis``, then ``transform``: the quadric x^2 + y^2 =
    (1 - z)^2 cut by the base plane; volume pi r^2 h / 3."""
    unit_volume = math.pi / 3.0

    def __init__(self, base=(0.0, 0.0, 0.0), radius=1.0, height=1.0, axis=(0.0, 0.0, 1.0), *,
                 material=None, transform=None):
        r, h = _positive("radius", radius), _positive("height", height)
        m = _transform(transform) @ _placed(_vector("base", base), (r, r, h), frame(axis))
        super().__init__(m, UNIT_CONE, [-1.0, -1.0, 0.0], [1.0, 1.0, 1.0], material)


class Quadric(Primitive):
    """The general quadric solid (Hearn & Baker 10-3): the points (x, y, z) where
    (x, y, z, 1) Q (x, y, z, 1)^T <= 0 for a symmetric 4 x 4 ``matrix`` Q, then
    ``transform``.  It may be unbounded (a cylinder, a paraboloid, a half space):
    intersect it with a :class:`Box` to render or measure it.

    >>> import numpy as np, scanline as sl
    >>> q = sl.solids.Quadric.from_coefficients(a=1, b=1, c=1, j=-4)   # x^2+y^2+z^2 = 4
    >>> round(q.volume(), 6)
    33.510322
    """

    def __init__(self, matrix, *, material=None, transform=None):
        from ..transform3d.arrays import matrix4

        q = matrix4("matrix", matrix)
        if not np.allclose(q, q.T, rtol=0, atol=1e-12 * np.abs(q).max()):
            raise ArgumentValueError("matrix must be symmetric (Q = Q^T): write each cross term "
                                     "half above and half below the diagonal")
        if not np.abs(q).max() > 0:
            raise ArgumentValueError("matrix must not be all zeros (it would be no surface)")
        super().__init__(_transform(transform), (q + q.T) / 2, -_INF3, _INF3, material)

    @classmethod
    def from_coefficients(cls, a=0.0, b=0.0, c=0.0, d=0.0, e=0.0, f=0.0, g=0.0, h=0.0, i=0.0,
                          j=0.0, **kw):
        """The solid a x^2 + b y^2 + c z^2 + 2 d xy + 2 e yz + 2 f xz + 2 g x + 2 h y +
        2 i z + j <= 0 (the quadric's implicit equation, Hearn & Baker eq. 10-3 with
        its cross terms halved into the symmetric matrix)."""
        return cls([[a, d, f, g], [d, b, e, h], [f, e, c, i], [g, h, i, j]], **kw)

    def _ellipsoid(self):
        """(center, half-axes matrix) when the solid is a bounded ellipsoid, else None."""
        q = self.quadric
        a, b, c = q[:3, :3], q[:3, 3], q[3, 3]
        if not (np.linalg.eigvalsh(a) > 0).all():
            return None
        center = -np.linalg.solve(a, b)
        k = b @ -center - c
        return (center, k, a) if k > 0 else None

    def bounds(self):
        """Exact for an ellipsoid (the center +- sqrt(k (A^-1)_ii) per axis, mapped by
        the transform's rows), else unbounded."""
        e = self._ellipsoid()
        if e is None:
            return -_INF3.copy(), _INF3.copy()
        center, k, a = e
        # x = M u with u on the ellipsoid u^T A u' = k: half-extents sqrt(k m_i A^-1 m_i)
        lin = self.matrix[:3, :3]
        half = np.sqrt(k * np.einsum("ij,jk,ik->i", lin, np.linalg.inv(a), lin))
        c = lin @ center + self.matrix[:3, 3]
        return c - half, c + half

    def volume(self):
        """Exact for an ellipsoid, 4/3 pi k^(3/2) / sqrt(det A) |det M|; an empty
        quadric has volume 0; others are refused."""
        e = self._ellipsoid()
        if e is None:
            a = self.quadric[:3, :3]
            if (np.linalg.eigvalsh(a) > 0).all():
                return 0.0
            raise ArgumentValueError("this quadric is not a bounded ellipsoid: its volume is "
                                     "infinite (intersect it with a Box and use "
                                     "scanline.csg.volume)")
        _, k, a = e
        return float(4.0 / 3.0 * math.pi * k ** 1.5 / math.sqrt(np.linalg.det(a))
                     * abs(np.linalg.det(self.matrix[:3, :3])))
