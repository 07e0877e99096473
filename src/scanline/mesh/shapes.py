"""Generated meshes: the cube and box, quadric surfaces and superquadrics (Hearn &
Baker, sections 10-4 and 10-5), tessellated from their parametric equations with
the exact normals of the surfaces.

Parametric forms (φ the latitude, -π/2 <= φ <= π/2; θ the longitude, -π <= θ <= π;
z is the polar axis, as Hearn & Baker write them)::

    sphere      x = r cos φ cos θ,         y = r cos φ sin θ,         z = r sin φ
    ellipsoid   x = rx cos φ cos θ,        y = ry cos φ sin θ,        z = rz sin φ
    torus       x = (R + a cos φ) cos θ,   y = (R + a cos φ) sin θ,   z = a sin φ   (-π <= φ <= π)
    superellipsoid  x = rx cos^s1 φ cos^s2 θ,  y = ry cos^s1 φ sin^s2 θ,  z = rz sin^s1 φ
    supertoroid     x = rx (r + cos^s1 φ) cos^s2 θ,  y = ry (r + cos^s1 φ) sin^s2 θ,
                    z = rz sin^s1 φ

where c^s means sign(c) |c|^s.  The normals are those of the implicit surfaces
(Barr 1981): for the superellipsoid n ∝ (cos^(2-s1) φ cos^(2-s2) θ / rx,
cos^(2-s1) φ sin^(2-s2) θ / ry, sin^(2-s1) φ / rz), which is the sphere's
(cos φ cos θ, cos φ sin θ, sin φ) for s1 = s2 = 1.

Faces run counterclockwise seen from outside (θ, then φ increasing), so the plane
normals point outward; the poles of a sphere-like surface are single vertices
surrounded by triangles, the other faces are quadrilaterals.

References
----------
A. H. Barr, "Superquadrics and angle-preserving transformations", IEEE Computer
Graphics and Applications 1(1), 11-23, 1981.
"""

from __future__ import annotations

import numbers
from typing import TYPE_CHECKING, Any, Callable, Literal, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from .mesh import Flat, Mesh, MeshOptions, check_mesh_budget

if TYPE_CHECKING:
    from typing_extensions import Unpack

#: A tessellation: intervals (nu, nv) around and along a surface, or one integer n
#: for (n, n // 2).
Resolution = Union[int, Tuple[int, int]]
#: A parametric surface or its normal: (φ, θ) arrays of N parameters -> (N, 3).
SurfaceFunction = Callable[[NDArray[np.float64], NDArray[np.float64]], NDArray[np.float64]]

#: Largest tessellation of the generators (vertices).
MAX_VERTICES = 1 << 24


def _positive(name: str, value: object) -> float:
    x = v.number(name, value)
    if not x > 0:
        raise ArgumentValueError(f"{name} must be > 0, got {value!r}")
    return x


def _resolution(resolution: object, low_v: int = 2) -> Tuple[int, int]:
    """(nu, nv): intervals around (θ) and along (φ)."""
    first: object
    second: object
    if isinstance(resolution, numbers.Integral) and not isinstance(resolution, (bool, np.bool_)):
        first, second = int(resolution), max(low_v, int(resolution) // 2)
    elif not isinstance(resolution, (str, bytes)) and hasattr(resolution, "__len__") \
            and hasattr(resolution, "__iter__") and len(resolution) == 2:
        first, second = resolution
    else:
        raise ArgumentValueError(
            f"resolution must be an integer or a pair (nu, nv), got {v._show(resolution)}")
    nu = v.positive_int("resolution[0]", first, 3)
    nv = v.positive_int("resolution[1]", second, low_v)
    if nu * (nv + 1) > MAX_VERTICES:
        raise ArgumentValueError(f"resolution ({nu}, {nv}) asks for more than {MAX_VERTICES} "
                                 "vertices")
    return nu, nv


def spow(c: NDArray[np.float64], s: float) -> NDArray[np.float64]:
    """sign(c) |c|^s, the signed power of the superquadrics."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        power: NDArray[np.float64] = np.sign(c) * np.abs(c) ** s
        return power


def _unit(n: NDArray[np.float64]) -> NDArray[np.float64]:
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        # (an overflowed length gives NaN here, which _fallback replaces)
        length = np.sqrt((n * n).sum(axis=-1, keepdims=True))
        unit: NDArray[np.float64] = n / length
        return unit


def closed_size(nu: int, nv: int) -> Tuple[int, int, int]:
    """(vertices, faces, face indices) of :func:`_closed_surface`'s tessellation."""
    return nu * (nv - 1) + 2, nu * nv, 6 * nu + 4 * nu * (nv - 2)


def periodic_size(nu: int, nv: int) -> Tuple[int, int, int]:
    """(vertices, faces, face indices) of :func:`_periodic_surface`'s tessellation."""
    return nu * nv, nu * nv, 4 * nu * nv


def _closed_surface(point: SurfaceFunction, normal: SurfaceFunction, nu: int, nv: int,
                    **kw: Unpack[MeshOptions]) -> Mesh:
    """A sphere-like mesh: rings at φ_j = -π/2 + j π / nv (j = 1 .. nv - 1) of nu
    vertices at θ_i = -π + 2π i / nu, and one vertex at each pole."""
    check_mesh_budget("resolution", *closed_size(nu, nv),
                      f"a tessellation of resolution ({nu}, {nv})")
    theta = -np.pi + 2 * np.pi * np.arange(nu) / nu
    phi = -np.pi / 2 + np.pi * np.arange(1, nv) / nv
    t, p = np.meshgrid(theta, phi)                 # rows: rings
    south_pole, north_pole = np.array([-np.pi / 2]), np.array([np.pi / 2])
    verts = np.vstack([point(south_pole, np.zeros(1)), point(p.ravel(), t.ravel()),
                       point(north_pole, np.zeros(1))])
    normals = np.vstack([normal(south_pole, np.zeros(1)), normal(p.ravel(), t.ravel()),
                         normal(north_pole, np.zeros(1))])
    # faces in order: the south cap's triangles, the bands' quadrilaterals ring by
    # ring, the north cap's triangles (vertex 1 + j nu + i is ring j's i-th vertex)
    i = np.arange(nu, dtype=np.int64)
    i1 = (i + 1) % nu
    south = np.stack([np.zeros(nu, np.int64), 1 + i1, 1 + i], axis=1)
    j = np.arange(nv - 2, dtype=np.int64)[:, None]
    bands = np.stack([1 + j * nu + i, 1 + j * nu + i1, 1 + (j + 1) * nu + i1,
                      1 + (j + 1) * nu + i], axis=-1)
    top = len(verts) - 1
    north = np.stack([1 + (nv - 2) * nu + i, 1 + (nv - 2) * nu + i1,
                      np.full(nu, top, np.int64)], axis=1)
    flat = Flat(np.concatenate([south.ravel(), bands.ravel(), north.ravel()]),
                np.concatenate([np.full(nu, 3), np.full(nu * (nv - 2), 4), np.full(nu, 3)]))
    normals = _fallback(normals, verts)
    return Mesh(verts, flat, normals=normals, **kw)


def _fallback(normals: NDArray[np.float64], verts: NDArray[np.float64]) -> NDArray[np.float64]:
    """Normals the formula leaves undefined (0/0 at a cusp) taken from the position
    direction instead."""
    bad = ~np.isfinite(normals).all(axis=1) | (np.abs(normals).sum(axis=1) == 0)
    if bad.any():
        normals = normals.copy()
        normals[bad] = _unit(np.where(np.abs(verts[bad]) > 0, verts[bad], [0, 0, 1.0]))
    return normals


def _periodic_surface(point: SurfaceFunction, normal: SurfaceFunction, nu: int, nv: int,
                      **kw: Unpack[MeshOptions]) -> Mesh:
    """A torus-like mesh: an nv x nu grid of quadrilaterals, periodic both ways."""
    check_mesh_budget("resolution", *periodic_size(nu, nv),
                      f"a tessellation of resolution ({nu}, {nv})")
    theta = -np.pi + 2 * np.pi * np.arange(nu) / nu
    phi = -np.pi + 2 * np.pi * np.arange(nv) / nv
    t, p = np.meshgrid(theta, phi)
    verts = point(p.ravel(), t.ravel())
    normals = _fallback(normal(p.ravel(), t.ravel()), verts)
    j, i = np.meshgrid(np.arange(nv), np.arange(nu), indexing="ij")
    a = j * nu + i
    b = j * nu + (i + 1) % nu
    c = ((j + 1) % nv) * nu + (i + 1) % nu
    d = ((j + 1) % nv) * nu + i
    faces = np.stack([a, b, c, d], axis=-1).reshape(-1, 4)
    return Mesh(verts, faces, normals=normals, **kw)


def superellipsoid(s1: float = 1.0, s2: float = 1.0, radii: ArrayLike = (1.0, 1.0, 1.0),
                   center: ArrayLike = (0.0, 0.0, 0.0), resolution: Resolution = 24,
                   **kw: Unpack[MeshOptions]) -> Mesh:
    """The superellipsoid of exponents ``s1`` (latitude) and ``s2`` (longitude), with
    semi-axes ``radii`` = (rx, ry, rz) about ``center`` (see the module docstring).
    s1 = s2 = 1 is the ellipsoid; exponents toward 0 make it box-like, 2 an
    octahedron-like shape, larger ones pinched.

    ``resolution``: intervals (nu, nv) around and pole to pole, or one integer n for
    (n, n // 2).  Other keywords (``colors``, ``name``) go to :class:`Mesh`.

    Parameters
    ----------
    s1, s2 : float, optional
        The exponents of the latitude φ and the longitude θ (> 0).
    radii : array_like, shape (3,), optional
        The semi-axes (rx, ry, rz), each > 0.
    center : array_like, shape (3,), optional
        The center (x, y, z).
    resolution : int or (int, int), optional
        Intervals (nu, nv) around (nu >= 3) and pole to pole (nv >= 2), or one
        integer n for (n, n // 2).
    **kw
        ``colors``, ``color_on``, ``name``, ``uv``, ``material``: as :class:`Mesh`
        takes them.

    Returns
    -------
    Mesh
        nu (nv - 1) + 2 vertices with the surface's normals; nu triangles around
        each pole and nu (nv - 2) quadrilaterals between.

    Raises
    ------
    ArgumentValueError
        If an exponent or a semi-axis is not > 0, or ``resolution`` is not an
        integer or a pair of them large enough (or asks for more than
        :data:`MAX_VERTICES` vertices).
    ArgumentTypeError
        If a number is not a real number.
    MemoryBudgetError
        If the mesh would take more memory than the budget allows.

    Notes
    -----
    Hearn & Baker, section 10-5, eq. 10-14.

    Examples
    --------
    Exponents 1/2 make a rounded box: it still touches the unit sphere's poles and
    its points on the axes, but its vertex at φ = θ = π/4 lies out at
    (cos π/4, cos π/4, sin^(1/2) π/4), not the sphere's (1/2, 1/2, cos π/4).

    >>> import scanline as sl
    >>> s = sl.mesh.superellipsoid(0.5, 0.5, resolution=(8, 4))
    >>> len(s.vertices), len(s)                      # 8 * 3 + 2 vertices, 8 * 4 faces
    (26, 32)
    >>> [corner.tolist() for corner in s.bounds]
    [[-1.0, -1.0, -1.0], [1.0, 1.0, 1.0]]
    >>> s.vertices[1 + 2 * 8 + 5].round(4).tolist()   # ring φ = π/4, θ = π/4
    [0.7071, 0.7071, 0.8409]
    """
    s1, s2 = _positive("s1", s1), _positive("s2", s2)
    rx, ry, rz = (_positive(f"radii[{i}]", r) for i, r in enumerate(_triple("radii", radii)))
    c = np.array(_triple("center", center), np.float64)
    nu, nv = _resolution(resolution)

    def point(p: NDArray[np.float64], t: NDArray[np.float64]) -> NDArray[np.float64]:
        cp = spow(np.cos(p), s1)
        return np.stack([rx * cp * spow(np.cos(t), s2), ry * cp * spow(np.sin(t), s2),
                         rz * spow(np.sin(p), s1)], axis=1) + c

    return _closed_surface(point, _super_normal(s1, s2, rx, ry, rz), nu, nv, **kw)


def _super_normal(s1: float, s2: float, rx: float, ry: float, rz: float) -> SurfaceFunction:
    """The unit normal n(φ, θ) of a superellipsoid or supertoroid (Barr 1981): the
    gradient of the implicit surface, (cos^(2-s1) φ cos^(2-s2) θ / rx,
    cos^(2-s1) φ sin^(2-s2) θ / ry, sin^(2-s1) φ / rz) normalized."""
    def normal(p: NDArray[np.float64], t: NDArray[np.float64]) -> NDArray[np.float64]:
        cp = spow(np.cos(p), 2 - s1)
        return _unit(np.stack([cp * spow(np.cos(t), 2 - s2) / rx,
                               cp * spow(np.sin(t), 2 - s2) / ry,
                               spow(np.sin(p), 2 - s1) / rz], axis=1))
    return normal


def _triple(name: str, value: object) -> Tuple[float, ...]:
    from ..transform3d.arrays import vector

    return vector(name, value)


def ellipsoid(rx: float = 1.0, ry: float = 1.0, rz: float = 1.0,
              center: ArrayLike = (0.0, 0.0, 0.0), resolution: Resolution = 24,
              **kw: Unpack[MeshOptions]) -> Mesh:
    """The ellipsoid x²/rx² + y²/ry² + z²/rz² = 1 (Hearn & Baker, section 10-4,
    eq. 10-9), normals ∝ (x/rx², y/ry², z/rz²).

    Parameters
    ----------
    rx, ry, rz : float, optional
        The semi-axes along x, y and z (> 0).
    center : array_like, shape (3,), optional
        The center (x, y, z).
    resolution : int or (int, int), optional
        As :func:`superellipsoid` takes it.
    **kw
        ``colors``, ``color_on``, ``name``, ``uv``, ``material``: as :class:`Mesh`
        takes them.

    Returns
    -------
    Mesh
        The tessellation of :func:`superellipsoid` with s1 = s2 = 1.

    Raises
    ------
    ArgumentValueError
        If a semi-axis is not > 0 or ``resolution`` is not valid (see
        :func:`superellipsoid`).

    Examples
    --------
    >>> import scanline as sl
    >>> e = sl.mesh.ellipsoid(2, 1, 0.5, resolution=(8, 4))
    >>> [corner.tolist() for corner in e.bounds]
    [[-2.0, -1.0, -0.5], [2.0, 1.0, 0.5]]
    >>> e.normals[0].round(12).tolist(), e.normals[-1].round(12).tolist()   # the poles
    ([0.0, 0.0, -1.0], [0.0, 0.0, 1.0])
    """
    return superellipsoid(1.0, 1.0, (rx, ry, rz), center, resolution, **kw)


def sphere(radius: float = 1.0, center: ArrayLike = (0.0, 0.0, 0.0),
           resolution: Resolution = 24, **kw: Unpack[MeshOptions]) -> Mesh:
    """The sphere of ``radius`` about ``center`` (Hearn & Baker, section 10-4,
    eq. 10-7): unit normals (x, y, z) / r.

    Parameters
    ----------
    radius : float, optional
        The radius (> 0).
    center : array_like, shape (3,), optional
        The center (x, y, z).
    resolution : int or (int, int), optional
        As :func:`superellipsoid` takes it.
    **kw
        ``colors``, ``color_on``, ``name``, ``uv``, ``material``: as :class:`Mesh`
        takes them.

    Returns
    -------
    Mesh
        nu (nv - 1) + 2 vertices: nu triangles around each pole and nu (nv - 2)
        quadrilaterals between.

    Raises
    ------
    ArgumentValueError
        If ``radius`` is not > 0 or ``resolution`` is not valid (see
        :func:`superellipsoid`).

    Examples
    --------
    >>> import scanline as sl
    >>> s = sl.mesh.sphere(2.0, resolution=(8, 4))
    >>> len(s.vertices), len(s), s.polygon_tables().consistent
    (26, 32, True)
    """
    r = _positive("radius", radius)
    return superellipsoid(1.0, 1.0, (r, r, r), center, resolution, **kw)


def supertoroid(s1: float = 1.0, s2: float = 1.0, r: float = 3.0,
                radii: ArrayLike = (1.0, 1.0, 1.0), center: ArrayLike = (0.0, 0.0, 0.0),
                resolution: Resolution = (32, 16), **kw: Unpack[MeshOptions]) -> Mesh:
    """The supertoroid of Hearn & Baker, section 10-5: ``r`` is the distance from the
    center to the middle of the tube in units of the tube radius (r > 1), ``radii``
    scale x, y, z.  s1 = s2 = 1 is the torus of tube radius rx and ring radius
    r·rx.

    Parameters
    ----------
    s1, s2 : float, optional
        The exponents of φ (around the tube) and θ (around the axis), > 0.
    r : float, optional
        The ring's radius in tube radii (> 1).
    radii : array_like, shape (3,), optional
        The scales (rx, ry, rz) of x, y and z, each > 0.
    center : array_like, shape (3,), optional
        The center (x, y, z).
    resolution : int or (int, int), optional
        Intervals (nu, nv) around the axis (nu >= 3) and around the tube (nv >= 3),
        or one integer n for (n, max(3, n // 2)).
    **kw
        ``colors``, ``color_on``, ``name``, ``uv``, ``material``: as :class:`Mesh`
        takes them.

    Returns
    -------
    Mesh
        nu nv vertices and nu nv quadrilaterals, periodic both ways.

    Raises
    ------
    ArgumentValueError
        If an exponent or a scale is not > 0, ``r`` not > 1, or ``resolution`` not
        valid.
    ArgumentTypeError
        If a number is not a real number.
    MemoryBudgetError
        If the mesh would take more memory than the budget allows.

    Notes
    -----
    Hearn & Baker, section 10-5, eq. 10-16.

    Examples
    --------
    The torus of ring radius 3 and tube radius 1 reaches out to 3 + 1 = 4 and up to
    1; a closed grid of quadrilaterals has two edges per vertex.

    >>> import scanline as sl
    >>> t = sl.mesh.supertoroid(resolution=(8, 4))
    >>> t
    <Mesh: 32 vertices, 32 faces, 64 edges>
    >>> [corner.tolist() for corner in t.bounds]
    [[-4.0, -4.0, -1.0], [4.0, 4.0, 1.0]]
    """
    s1, s2 = _positive("s1", s1), _positive("s2", s2)
    r = v.number("r", r)
    if not r > 1:
        raise ArgumentValueError(f"r must be > 1 (the ring wider than the tube), got {r!r}")
    rx, ry, rz = (_positive(f"radii[{i}]", q) for i, q in enumerate(_triple("radii", radii)))
    c = np.array(_triple("center", center), np.float64)
    nu, nv = _resolution(resolution, 3)

    def point(p: NDArray[np.float64], t: NDArray[np.float64]) -> NDArray[np.float64]:
        ring = r + spow(np.cos(p), s1)
        return np.stack([rx * ring * spow(np.cos(t), s2), ry * ring * spow(np.sin(t), s2),
                         rz * spow(np.sin(p), s1)], axis=1) + c

    return _periodic_surface(point, _super_normal(s1, s2, rx, ry, rz), nu, nv, **kw)


def torus(major: float = 1.0, minor: float = 0.25, center: ArrayLike = (0.0, 0.0, 0.0),
          resolution: Resolution = (32, 16), **kw: Unpack[MeshOptions]) -> Mesh:
    """The torus about the z axis with ring radius ``major`` (center to the middle
    of the tube) and tube radius ``minor`` < ``major`` (Hearn & Baker, section 10-4,
    eq. 10-11); normals (cos φ cos θ, cos φ sin θ, sin φ).

    Parameters
    ----------
    major : float, optional
        The ring radius (> 0).
    minor : float, optional
        The tube radius (0 < minor < major).
    center : array_like, shape (3,), optional
        The center (x, y, z).
    resolution : int or (int, int), optional
        As :func:`supertoroid` takes it.
    **kw
        ``colors``, ``color_on``, ``name``, ``uv``, ``material``: as :class:`Mesh`
        takes them.

    Returns
    -------
    Mesh
        nu nv vertices and nu nv quadrilaterals.

    Raises
    ------
    ArgumentValueError
        If a radius is not > 0, ``minor`` is not below ``major``, or ``resolution``
        is not valid.

    Examples
    --------
    >>> import scanline as sl
    >>> t = sl.mesh.torus(2.0, 0.5, resolution=(12, 6))
    >>> len(t.vertices), len(t), len(t.edges)
    (72, 72, 144)
    """
    big, small = _positive("major", major), _positive("minor", minor)
    if not small < big:
        raise ArgumentValueError(f"minor ({small:g}) must be smaller than major ({big:g}): "
                                 "the tube would cross the axis")
    return supertoroid(1.0, 1.0, big / small, (small, small, small), center, resolution, **kw)


def superquadric(kind: Literal["ellipsoid", "toroid"] = "ellipsoid", s1: float = 1.0,
                 s2: float = 1.0, **kw: Any) -> Mesh:
    """A superquadric by name: ``"ellipsoid"`` (:func:`superellipsoid`) or
    ``"toroid"`` (:func:`supertoroid`).

    Parameters
    ----------
    kind : {"ellipsoid", "toroid"}, optional
        Which superquadric.
    s1, s2 : float, optional
        Its exponents (> 0).
    **kw
        The other arguments of :func:`superellipsoid` (``radii``, ``center``,
        ``resolution``) or :func:`supertoroid` (``r`` too), and :class:`Mesh`'s
        keywords.

    Returns
    -------
    Mesh

    Raises
    ------
    ArgumentValueError
        If ``kind`` is neither, or as the function it names.

    Notes
    -----
    Hearn & Baker, section 10-5.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.mesh.superquadric("toroid", 1.0, 1.0, resolution=(8, 4))
    <Mesh: 32 vertices, 32 faces, 64 edges>
    """
    v.choice("kind", kind, ("ellipsoid", "toroid"))
    return (superellipsoid if kind == "ellipsoid" else supertoroid)(s1, s2, **kw)


#: The cube's faces, counterclockwise seen from outside: -x, +x, -y, +y, -z, +z.
_CUBE_FACES = [[0, 4, 6, 2], [1, 3, 7, 5], [0, 1, 5, 4], [2, 6, 7, 3], [0, 2, 3, 1],
               [4, 5, 7, 6]]


def box(lo: ArrayLike = (-1.0, -1.0, -1.0), hi: ArrayLike = (1.0, 1.0, 1.0),
        **kw: Unpack[MeshOptions]) -> Mesh:
    """The box from ``lo`` to ``hi``: 8 vertices (vertex k has x = hi if k & 1, y if
    k & 2, z if k & 4), 6 quadrilateral faces (-x, +x, -y, +y, -z, +z), 12 edges.

    Parameters
    ----------
    lo, hi : array_like, shape (3,), optional
        The corners of least and greatest x, y and z.
    **kw
        ``colors``, ``color_on``, ``name``, ``uv``, ``material``: as :class:`Mesh`
        takes them.

    Returns
    -------
    Mesh

    Raises
    ------
    ArgumentValueError
        If ``lo`` is not below ``hi`` on every axis.

    Notes
    -----
    Hearn & Baker, section 10-1 (a polygon mesh and its tables).

    Examples
    --------
    >>> import scanline as sl
    >>> b = sl.mesh.box((0, 0, 0), (2, 1, 1))
    >>> b.vertices[[0, 1, 7]].tolist()
    [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 1.0, 1.0]]
    >>> b.face_normals()[1].tolist()                  # face 1 is the +x side
    [1.0, 0.0, 0.0]
    """
    low, high = _triple("lo", lo), _triple("hi", hi)
    if not all(a < b for a, b in zip(low, high)):
        raise ArgumentValueError(f"the box needs lo < hi on every axis, got {low}, {high}")
    verts = [[high[0] if k & 1 else low[0], high[1] if k & 2 else low[1],
              high[2] if k & 4 else low[2]] for k in range(8)]
    return Mesh(verts, _CUBE_FACES, **kw)


def cube(size: float = 2.0, center: ArrayLike = (0.0, 0.0, 0.0),
         **kw: Unpack[MeshOptions]) -> Mesh:
    """The cube of edge ``size`` about ``center`` (see :func:`box`).

    Parameters
    ----------
    size : float, optional
        The edge length (> 0).
    center : array_like, shape (3,), optional
        The center (x, y, z).
    **kw
        ``colors``, ``color_on``, ``name``, ``uv``, ``material``: as :class:`Mesh`
        takes them.

    Returns
    -------
    Mesh
        8 vertices, 6 quadrilateral faces, 12 edges.

    Raises
    ------
    ArgumentValueError
        If ``size`` is not > 0.

    Examples
    --------
    >>> import scanline as sl
    >>> c = sl.mesh.cube()
    >>> c, c.polygon_tables().consistent
    (<Mesh: 8 vertices, 6 faces, 12 edges>, True)
    """
    s = _positive("size", size) / 2
    c = _triple("center", center)
    return box([x - s for x in c], [x + s for x in c], **kw)

