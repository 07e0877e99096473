"""Constructive solid geometry (Hearn & Baker 10-16; Requicha 1980): solids combined
by the set operations union, intersection and difference into a CSG tree, rendered by
ray casting (Roth 1982: each ray's inside intervals of the primitives combined up the
tree; :mod:`scanline._kernels.csg`) through ``sl.render(..., method="ray-casting")``
or ``"ray-tracing"``, and measured by ray casting: the volume and mass properties
from rays through a grid over the solid's bounds (10-16, "volume determination").

>>> import scanline as sl
>>> a = sl.solids.Box((0, 0, 0), (2, 2, 2))
>>> b = sl.solids.Box((1, 1, 1), (3, 3, 3))
>>> tree = a - b
>>> tree
<CSG difference of Box and Box>
>>> round(sl.csg.volume(tree, resolution=64), 6)
7.0
"""

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Tuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import _validate as v
from .errors import ArgumentTypeError, ArgumentValueError
from .solids.base import Bounds, Solid, finite_bounds, is_solid

if TYPE_CHECKING:
    from .lighting import Material

#: The set operations.
OPERATIONS = ("union", "intersection", "difference")


class CSG(Solid):
    """A node of a CSG tree: ``op`` ("union", "intersection" or "difference") of the
    solids ``left`` and ``right`` (primitives or nodes) (Hearn & Baker 10-16).

    Parameters
    ----------
    op : {"union", "intersection", "difference"}
        The set operation.
    left, right : Solid
        The operands (the difference is ``left`` minus ``right``).

    Raises
    ------
    ArgumentValueError
        An unknown ``op``.
    ArgumentTypeError
        An operand that is not a solid.

    Examples
    --------
    >>> import scanline as sl
    >>> a, b = sl.solids.Box((0, 0, 0), (2, 2, 2)), sl.solids.Box((1, 1, 1), (3, 3, 3))
    >>> both = sl.csg.CSG("intersection", a, b)
    >>> [c.tolist() for c in both.bounds()]
    [[1.0, 1.0, 1.0], [2.0, 2.0, 2.0]]
    """

    def __init__(self, op: str, left: Solid, right: Solid) -> None:
        if op not in OPERATIONS:
            raise ArgumentValueError(f"op must be one of {', '.join(OPERATIONS)}, got "
                                     f"{v._show(op)}")
        for name, s in (("left", left), ("right", right)):
            if not is_solid(s):
                raise ArgumentTypeError(f"{name} must be a solid (scanline.solids: Sphere, Box, "
                                        f"... or a CSG tree), got {v._show(s)}")
        self.op, self.left, self.right = op, left, right

    # a tree's material is read-only, its left operand's; primitives hold their own
    @property
    def material(self) -> "Material":  # type: ignore[override]
        """The left operand's material (each surface drawn keeps its primitive's)."""
        return self.left.material

    def contains(self, points: ArrayLike) -> NDArray[np.bool_]:
        """Whether each point is inside: the operands' answers combined by the set
        operation (or, and, and-not).

        Parameters
        ----------
        points : array_like (N, 3) or (3,)
            Finite points.

        Returns
        -------
        ndarray (N,) bool
            True inside.

        Examples
        --------
        >>> import scanline as sl
        >>> cut = sl.solids.Box((0, 0, 0), (2, 2, 2)) - sl.solids.Box((1, 1, 1), (3, 3, 3))
        >>> cut.contains([(0.5, 0.5, 0.5), (1.5, 1.5, 1.5)]).tolist()
        [True, False]
        """
        a = self.left.contains(points)
        b = self.right.contains(points)
        return a | b if self.op == "union" else a & b if self.op == "intersection" else a & ~b

    def bounds(self) -> Bounds:
        """The union's box of boxes, the intersection's overlap, the difference's
        left box.

        Returns
        -------
        lo, hi : ndarray (3,)
            The box's corners.

        Examples
        --------
        >>> import scanline as sl
        >>> a, b = sl.solids.Box((0, 0, 0), (2, 2, 2)), sl.solids.Box((1, 1, 1), (3, 3, 3))
        >>> [c.tolist() for c in (a | b).bounds()], [c.tolist() for c in (a - b).bounds()]
        ([[0.0, 0.0, 0.0], [3.0, 3.0, 3.0]], [[0.0, 0.0, 0.0], [2.0, 2.0, 2.0]])
        """
        (a0, a1), (b0, b1) = self.left.bounds(), self.right.bounds()
        if self.op == "union":
            return np.minimum(a0, b0), np.maximum(a1, b1)
        if self.op == "intersection":
            return np.maximum(a0, b0), np.minimum(a1, b1)
        return a0, a1

    def volume(self, resolution: int = 256) -> float:
        """The volume by ray casting (:func:`volume`).

        Parameters
        ----------
        resolution : int
            Rays per side of the grid over the bounds.

        Returns
        -------
        float
            The volume.

        Examples
        --------
        >>> import scanline as sl
        >>> a, b = sl.solids.Box((0, 0, 0), (2, 2, 2)), sl.solids.Box((1, 1, 1), (3, 3, 3))
        >>> (a & b).volume(resolution=4)          # the unit cube [1, 2]^3
        1.0
        """
        return volume(self, resolution=resolution)

    def __repr__(self) -> str:
        return f"<CSG {self.op} of {type(self.left).__name__} and {type(self.right).__name__}>"


def _fold(op: str, solids: Tuple[Any, ...]) -> Solid:
    if not solids:
        raise ArgumentValueError(f"{op} needs at least one solid, got none")
    first = solids[0]
    if not isinstance(first, Solid):
        raise ArgumentTypeError(f"{op}'s operands must be solids, got {v._show(first)}")
    tree: Solid = first
    for s in solids[1:]:
        tree = CSG(op, tree, s)
    return tree


def union(*solids: Any) -> Solid:
    """The union of the solids (a single solid is itself): a CSG tree folded left.

    Parameters
    ----------
    *solids : Solid
        One or more primitives or CSG trees.

    Returns
    -------
    Solid
        ``((s0 | s1) | s2) ...``.

    Raises
    ------
    ArgumentValueError
        No solids.
    ArgumentTypeError
        An operand that is not a solid.

    Examples
    --------
    >>> import scanline as sl
    >>> a, b = sl.solids.Box((0, 0, 0), (2, 2, 2)), sl.solids.Box((1, 1, 1), (3, 3, 3))
    >>> sl.csg.union(a, b)
    <CSG union of Box and Box>
    >>> sl.csg.union(a, b).contains([(2.5, 2.5, 2.5), (-1, 0, 0)]).tolist()
    [True, False]
    """
    return _fold("union", solids)


def intersection(*solids: Any) -> Solid:
    """The intersection of the solids: a CSG tree folded left.

    Parameters
    ----------
    *solids : Solid
        One or more primitives or CSG trees.

    Returns
    -------
    Solid
        ``((s0 & s1) & s2) ...``.

    Raises
    ------
    ArgumentValueError
        No solids.
    ArgumentTypeError
        An operand that is not a solid.

    Examples
    --------
    >>> import scanline as sl
    >>> a, b = sl.solids.Box((0, 0, 0), (2, 2, 2)), sl.solids.Box((1, 1, 1), (3, 3, 3))
    >>> sl.csg.intersection(a, b).contains([(1.5, 1.5, 1.5), (0.5, 0.5, 0.5)]).tolist()
    [True, False]
    """
    return _fold("intersection", solids)


def difference(solid: Any, *others: Any) -> Solid:
    """``solid`` minus each of ``others`` in turn: a CSG tree folded left.

    Parameters
    ----------
    solid : Solid
        What is cut.
    *others : Solid
        What is cut away, in turn.

    Returns
    -------
    Solid
        ``((solid - o0) - o1) ...``.

    Raises
    ------
    ArgumentTypeError
        An operand that is not a solid.

    Examples
    --------
    >>> import scanline as sl
    >>> a = sl.solids.Box((0, 0, 0), (2, 2, 2))
    >>> sl.csg.difference(a, sl.solids.Sphere((2, 2, 2), 1.0), sl.solids.Sphere())
    <CSG difference of CSG and Sphere>
    """
    return _fold("difference", (solid,) + others)


@dataclass(frozen=True)
class MassProperties:
    """Mass properties of a solid of uniform ``density`` (:func:`mass_properties`).

    Parameters
    ----------
    volume, mass : float
        The volume, and the volume times the density.
    center : ndarray (3,)
        The center of mass.
    inertia : ndarray (3, 3)
        The inertia tensor about the center of mass, I_ij = integral of rho (|r|^2
        delta_ij - r_i r_j) dV.

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> p = sl.csg.MassProperties(1.0, 2.0, np.zeros(3), np.eye(3))
    >>> p.mass, p.center.tolist()
    (2.0, [0.0, 0.0, 0.0])
    """
    volume: float
    mass: float
    center: NDArray[np.float64]
    inertia: NDArray[np.float64]


def _grid(solid: Solid, resolution: int) -> Tuple[NDArray[np.float64], float]:
    """Rays up +z through the centers of a ``resolution`` x ``resolution`` grid over
    the solid's bounds: their origins (R, 3) and the cell area."""
    from .budget import check

    n = v.positive_int("resolution", resolution)
    if n > 8192:
        raise ArgumentValueError(f"resolution must be at most 8192 (rays per side), got {n}")
    check(64 * n * n, "resolution", f"{n} x {n} rays", "use a smaller resolution")
    lo, hi = finite_bounds(solid)
    if not (np.abs(np.concatenate([lo, hi])) < 1e150).all():
        raise ArgumentValueError(f"solid: bounds {lo.tolist()} .. {hi.tolist()} reach past "
                                 f"1e150: its volume would overflow; scale it down")
    if not (hi > lo).all():
        return np.zeros((0, 3)), 0.0
    size = (hi - lo)[:2] / n
    xs = lo[0] + (np.arange(n) + 0.5) * size[0]
    ys = lo[1] + (np.arange(n) + 0.5) * size[1]
    gx, gy = np.meshgrid(xs, ys, indexing="ij")
    z0 = lo[2] - 1.0 - abs(lo[2])
    origins = np.stack([gx.ravel(), gy.ravel(), np.full(n * n, z0)], axis=1)
    return origins, float(size[0] * size[1])


def _integrals(solid: object, resolution: int, max_intervals: int
               ) -> Tuple[NDArray[np.float64], NDArray[np.float64], float]:
    from .solids.program import Program

    if not isinstance(solid, Solid):
        raise ArgumentTypeError(f"solid must be a solid (scanline.solids or a CSG tree), got "
                                f"{v._show(solid)}")
    origins, area = _grid(solid, resolution)
    if not len(origins):
        return origins, np.zeros((0, 3)), area
    return origins, Program(solid, max_intervals).moments(origins), area


def volume(solid: Any, resolution: int = 256, max_intervals: int = 32) -> float:
    """The volume of ``solid`` by ray casting (Hearn & Baker 10-16): rays parallel to
    the z axis through the centers of a ``resolution`` x ``resolution`` grid over its
    bounding box, each ray's length inside (exact, from its intervals) times the cell's
    area.  The error comes from the grid only: the silhouette's cells are sampled at
    their centers (of the order of the silhouette's length times the cell size,
    mostly cancelling).

    Parameters
    ----------
    solid : Solid
        A bounded primitive or CSG tree.
    resolution : int
        Rays per side of the grid, 1..8192.
    max_intervals : int
        The most inside intervals a ray's list may hold at any node of the tree.

    Returns
    -------
    float
        The volume.

    Raises
    ------
    ArgumentTypeError
        ``solid`` is not a solid.
    ArgumentValueError
        An unbounded solid, a resolution outside 1..8192, or rays that cross the
        solid more than ``max_intervals`` times.

    Notes
    -----
    Hearn & Baker 10-16, "volume determination" by ray casting; Roth (1982), "Ray
    casting for modeling solids".

    Examples
    --------
    >>> import math, scanline as sl
    >>> v = sl.csg.volume(sl.solids.Sphere((0, 0, 0), 1.0), resolution=512)
    >>> abs(v / (4 / 3 * math.pi) - 1) < 1e-4
    True
    """
    _, m, area = _integrals(solid, resolution, max_intervals)
    return float(m[:, 0].sum() * area)


def mass_properties(solid: Any, resolution: int = 256, density: float = 1.0,
                    max_intervals: int = 32) -> MassProperties:
    """Volume, mass, center of mass and inertia tensor of ``solid`` of uniform
    ``density`` by ray casting (Hearn & Baker 10-16): per ray (as :func:`volume`) the
    exact integrals of 1, z and z^2 along its inside, times x, y, x^2, y^2 and x y of
    the ray and the cell's area.

    Parameters
    ----------
    solid : Solid
        A bounded primitive or CSG tree.
    resolution : int
        Rays per side of the grid, 1..8192.
    density : float
        rho > 0.
    max_intervals : int
        As :func:`volume`'s.

    Returns
    -------
    MassProperties
        Volume, mass, center of mass and inertia tensor (zeros for an empty solid).

    Raises
    ------
    ArgumentTypeError
        ``solid`` is not a solid.
    ArgumentValueError
        A density not positive, or as :func:`volume`.

    Examples
    --------
    A 2 x 2 x 2 cube of density 2: mass 16, and about its center I = m (2^2 + 2^2) / 12
    = 32/3 on the diagonal (exact in z, the grid's midpoint rule in x and y):

    >>> import numpy as np, scanline as sl
    >>> p = sl.csg.mass_properties(sl.solids.Box((0, 0, 0), (2, 2, 2)), 128, density=2.0)
    >>> p.volume, p.mass, p.center.tolist()
    (8.0, 16.0, [1.0, 1.0, 1.0])
    >>> bool(np.allclose(p.inertia, np.diag([32 / 3] * 3), rtol=1e-3, atol=1e-9))
    True
    """
    rho = v.number("density", density)
    if not rho > 0:
        raise ArgumentValueError(f"density must be positive, got {v._show(density)}")
    o, m, area = _integrals(solid, resolution, max_intervals)
    x, y = o[:, 0], o[:, 1]
    s0, s1, s2 = m[:, 0] * area, m[:, 1] * area, m[:, 2] * area
    vol = float(s0.sum())
    if not vol > 0:
        return MassProperties(0.0, 0.0, np.zeros(3), np.zeros((3, 3)))
    center = np.array([(x * s0).sum(), (y * s0).sum(), s1.sum()]) / vol
    # second moments about the center of mass
    xx = (x * x * s0).sum() - vol * center[0] ** 2
    yy = (y * y * s0).sum() - vol * center[1] ** 2
    zz = s2.sum() - vol * center[2] ** 2
    xy = (x * y * s0).sum() - vol * center[0] * center[1]
    xz = (x * s1).sum() - vol * center[0] * center[2]
    yz = (y * s1).sum() - vol * center[1] * center[2]
    inertia = rho * np.array([[yy + zz, -xy, -xz], [-xy, xx + zz, -yz], [-xz, -yz, xx + yy]])
    return MassProperties(vol, rho * vol, center, inertia)
