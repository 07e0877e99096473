"""Clip volumes in three dimensions: convex regions bounded by planes.

A :class:`Volume` is K planes, rows (a, b, c, d) of a (K, 4) array; a point is inside
plane k when a x + b y + c z + d w >= 0 (w = 1 for ordinary points), so the boundary
is inside.  The region codes of Cohen-Sutherland number the planes from bit 1.

- :func:`box` -- an upright box from (xmin, ymin, zmin) to (xmax, ymax, zmax): the
  normalized parallel view volume of Hearn & Baker, section 12-5, whose planes and
  region-code bits are 1 left (x < xmin), 2 right (x > xmax), 3 below, 4 above,
  5 front (z < zmin), 6 back (z > zmax) -- z is the depth, growing away from the
  viewer as in normalized device coordinates;
- :func:`frustum` -- the canonical perspective view volume of Foley et al.
  (section 6.5.3): z <= x <= -z, z <= y <= -z, -1 <= z <= z_min (the eye at the
  origin looking along -z);
- :data:`UNIT_CUBE` -- the unit cube 0 <= x, y, z <= 1, which is also, for points
  (x, y, z, w) in homogeneous clip coordinates, 0 <= x, y, z <= w
  (:func:`scanline.clip.homogeneous`);
- :func:`polyhedron` -- any convex polyhedron, from plane equations or a convex
  :class:`~scanline.mesh.Mesh` (Cyrus-Beck: the notes, chapter 4, Q.4, "a 3-D line
  against an arbitrary convex polyhedron").
"""

from typing import TYPE_CHECKING, Iterable, Sequence, Union, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError

if TYPE_CHECKING:
    from ..mesh import Mesh

BOX_PLANES = ("left", "right", "below", "above", "front", "back")


class Volume:
    """A convex clip volume: ``planes`` (K, 4) with inside a x + b y + c z + d w >= 0,
    and a name per plane (for the step tables).

    Parameters
    ----------
    planes : array_like, shape (K, 4)
        Rows (a, b, c, d): inside where a x + b y + c z + d w >= 0.
    names : iterable of str
        A name per plane.
    kind : str
        What the volume is ("box", "frustum", "polyhedron" ...).

    Attributes
    ----------
    bounds : ((float, float, float), (float, float, float))
        ``(lo, hi)``, set on a :func:`box`.
    z_min : float
        The front plane, set on a :func:`frustum`.

    Notes
    -----
    Hearn & Baker, section 12-5: the view volume's planes, with inside on the
    positive side of each row (the region codes of Cohen-Sutherland number the
    planes from bit 1).

    Examples
    --------
    >>> import scanline as sl
    >>> half = sl.clip.volumes.Volume([(1, 0, 0, 0)], ["x >= 0"], "half-space")
    >>> half
    <Volume half-space: 1 planes>
    >>> half.contains([(1, 5, 5), (-1, 0, 0)]).tolist()
    [True, False]
    """

    bounds: tuple[tuple[float, ...], tuple[float, ...]]
    z_min: float

    def __init__(self, planes: ArrayLike, names: Iterable[str], kind: str) -> None:
        self.planes = np.ascontiguousarray(planes, dtype=np.float64)
        self.names = tuple(names)
        self.kind = kind

    @overload
    def contains(self, points: Sequence[float]) -> bool: ...
    @overload
    def contains(self, points: ArrayLike) -> Union[bool, NDArray[np.bool_]]: ...

    def contains(self, points: ArrayLike) -> Union[bool, NDArray[np.bool_]]:
        """Whether each point (N, 3) or homogeneous point (N, 4) is inside.

        Parameters
        ----------
        points : array_like, shape (N, 3) or (N, 4), or one point (3,) or (4,)
            Points (x, y, z), or homogeneous points (x, y, z, w).

        Returns
        -------
        bool or ndarray of bool, shape (N,)
            For one point a bool, else one per point; the boundary is inside.

        Raises
        ------
        TypeError, ValueError
            Points that are not finite real numbers of 3 or 4 columns.

        Examples
        --------
        >>> import scanline as sl
        >>> sl.clip.UNIT_CUBE.contains((0.5, 0.5, 1.0))
        True
        >>> sl.clip.UNIT_CUBE.contains([(2, 2, 2, 2), (2, 2, 2, 1)]).tolist()
        [True, False]
        """
        from ..transform3d.arrays import points as point_array

        p, single = point_array("points", points, (3, 4))
        if p.shape[1] == 3:
            p = np.hstack([p, np.ones((len(p), 1))])
        inside: NDArray[np.bool_] = (p @ self.planes.T >= 0).all(axis=1)
        return bool(inside[0]) if single else inside

    def __repr__(self) -> str:
        return f"<Volume {self.kind}: {len(self.planes)} planes>"


def box(lo: Sequence[float], hi: Sequence[float]) -> Volume:
    """The box from ``lo`` = (xmin, ymin, zmin) to ``hi`` = (xmax, ymax, zmax).

    Parameters
    ----------
    lo, hi : (float, float, float)
        The opposite corners, ``lo < hi`` on every axis.

    Returns
    -------
    Volume
        Six planes, region-code bits 1 left (x < xmin), 2 right, 3 below, 4 above,
        5 front (z < zmin), 6 back (z > zmax); ``bounds`` is ``(lo, hi)``.

    Raises
    ------
    TypeError, ValueError
        Corners that are not three finite numbers, or not lo < hi on every axis.

    Notes
    -----
    The normalized parallel view volume of Hearn & Baker, section 12-5.

    Examples
    --------
    >>> import scanline as sl
    >>> b = sl.clip.box((0, 0, 0), (2, 1, 1))
    >>> b.planes[:2].tolist(), b.bounds
    ([[1.0, 0.0, 0.0, -0.0], [-1.0, 0.0, 0.0, 2.0]], ((0.0, 0.0, 0.0), (2.0, 1.0, 1.0)))
    """
    from ..transform3d.arrays import vector

    low = vector("lo", lo)
    high = vector("hi", hi)
    if not all(a < b for a, b in zip(low, high)):
        raise ArgumentValueError(
            f"the box needs lo < hi on every axis, got lo={low}, hi={high}")
    (x0, y0, z0), (x1, y1, z1) = low, high
    planes = [(1, 0, 0, -x0), (-1, 0, 0, x1), (0, 1, 0, -y0), (0, -1, 0, y1),
              (0, 0, 1, -z0), (0, 0, -1, z1)]
    vol = Volume(planes, BOX_PLANES, "box")
    vol.bounds = (low, high)
    return vol


#: The unit cube of normalized device coordinates; as homogeneous planes,
#: 0 <= x, y, z <= w.
UNIT_CUBE = box((0, 0, 0), (1, 1, 1))


def frustum(z_min: float) -> Volume:
    """Foley et al.'s canonical perspective view volume with the front plane at
    z = ``z_min`` (-1 < z_min < 0): z <= x <= -z, z <= y <= -z, -1 <= z <= z_min.

    Planes (bits): 1 left x >= z, 2 right x <= -z, 3 below y >= z, 4 above y <= -z,
    5 front z <= z_min, 6 back z >= -1.

    Parameters
    ----------
    z_min : float
        The front plane, -1 < z_min < 0 (the eye at the origin looking along -z).

    Returns
    -------
    Volume
        Six planes; ``z_min`` is kept as an attribute.

    Raises
    ------
    TypeError, ValueError
        ``z_min`` not a number between -1 and 0.

    References
    ----------
    J. D. Foley, A. van Dam, S. K. Feiner, J. F. Hughes, "Computer Graphics:
    Principles and Practice", 2nd ed., 1990, section 6.5.3.

    Examples
    --------
    >>> import scanline as sl
    >>> f = sl.clip.frustum(-0.1)
    >>> f.contains([(0, 0, -0.5), (0.6, 0, -0.5)]).tolist()
    [True, False]
    """
    z = v.number("z_min", z_min)
    if not -1.0 < z < 0.0:
        raise ArgumentValueError(
            f"z_min must be between -1 and 0 (the front plane between the eye and the "
            f"back plane z = -1), got {z_min!r}")
    planes = [(1, 0, -1, 0), (-1, 0, -1, 0), (0, 1, -1, 0), (0, -1, -1, 0),
              (0, 0, -1, z), (0, 0, 1, 1)]
    vol = Volume(planes, BOX_PLANES, "frustum")
    vol.z_min = z
    return vol


def polyhedron(planes: Union[ArrayLike, "Mesh"]) -> Volume:
    """A convex polyhedron from plane equations (A, B, C, D) with outward normals
    (inside A x + B y + C z + D <= 0, Hearn & Baker's convention, section 10-1), or
    from a closed convex :class:`~scanline.mesh.Mesh`.

    Parameters
    ----------
    planes : array_like, shape (K, 4), or Mesh
        Plane equations with outward normals, or a closed convex mesh (its faces'
        planes).

    Returns
    -------
    Volume
        The K planes negated (inside where a x + b y + c z + d >= 0).

    Raises
    ------
    TypeError, ValueError
        Planes that are not a finite (K, 4) array, K >= 1, or a plane with a zero
        normal.

    Notes
    -----
    Cyrus-Beck clips against any convex polyhedron (notes, chapter 4, Q.4).

    Examples
    --------
    >>> import scanline as sl
    >>> half = sl.clip.polyhedron([(0, 0, 1, -2)])     # z - 2 <= 0
    >>> half.contains([(0, 0, 1), (0, 0, 3)]).tolist()
    [True, False]
    """
    from ..mesh import Mesh

    if isinstance(planes, Mesh):
        rows = planes.plane_equations()
    else:
        from ..transform3d.arrays import finite, real_array

        rows = finite("planes", real_array("planes", planes, "(K, 4)"))
        if rows.ndim != 2 or rows.shape[1] != 4 or len(rows) < 1:
            raise ArgumentValueError(f"planes must have shape (K, 4) with K >= 1, got "
                                     f"shape {rows.shape}")
    if (np.abs(rows[:, :3]).max(axis=1) == 0).any():
        raise ArgumentValueError("every plane needs a nonzero normal (A, B, C)")
    return Volume(-rows, [f"plane {k + 1}" for k in range(len(rows))], "polyhedron")


def volume(value: object, name: str = "volume") -> Volume:
    """A :class:`Volume`, or a box given as a pair (lo, hi)."""
    if isinstance(value, Volume):
        return value
    if isinstance(value, (tuple, list)) and len(value) == 2:
        return box(value[0], value[1])
    raise ArgumentTypeError(
        f"{name} must be a box (lo, hi) = ((xmin, ymin, zmin), (xmax, ymax, zmax)) or a "
        f"scanline.clip volume (box, frustum, UNIT_CUBE, polyhedron), got {v._show(value)}")
