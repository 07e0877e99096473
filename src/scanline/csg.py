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
from typing import Any

import numpy as np

from . import _validate as v
from .errors import ArgumentTypeError, ArgumentValueError
from .solids.base import Solid, finite_bounds, is_solid

#: The set operations.
OPERATIONS = ("union", "intersection", "difference")


class CSG(Solid):
    """A node of a CSG tree: ``op`` ("union", "intersection" or "difference") of the
    solids ``left`` and ``right`` (primitives or nodes)."""

    def __init__(self, op, left, right):
        if op not in OPERATIONS:
            raise ArgumentValueError(f"op must be one of {', '.join(OPERATIONS)}, got "
                                     f"{v._show(op)}")
        for name, s in (("left", left), ("right", right)):
            if not is_solid(s):
                raise ArgumentTypeError(f"{name} must be a solid (scanline.solids: Sphere, Box, "
                                        f"... or a CSG tree), got {v._show(s)}")
        self.op, self.left, self.right = op, left, right

    @property
    def material(self):
        """The left operand's material (each surface drawn keeps its primitive's)."""
        return self.left.material

    def contains(self, points):
        a = self.left.contains(points)
        b = self.right.contains(points)
        return a | b if self.op == "union" else a & b if self.op == "intersection" else a & ~b

    def bounds(self):
        """The union's box of boxes, the intersection's overlap, the difference's
        left box."""
        (a0, a1), (b0, b1) = self.left.bounds(), self.right.bounds()
        if self.op == "union":
            return np.minimum(a0, b0), np.maximum(a1, b1)
        if self.op == "intersection":
            return np.maximum(a0, b0), np.minimum(a1, b1)
        return a0, a1

    def volume(self, resolution=256):
        """The volume by ray casting (:func:`volume`)."""
        return volume(self, resolution=resolution)

    def __repr__(self):
        return f"<CSG {self.op} of {type(self.left).__name__} and {type(self.right).__name__}>"


def _fold(op, solids):
    if not solids:
        raise ArgumentValueError(f"{op} needs at least one solid, got none")
    tree = solids[0]
    if not is_solid(tree):
        raise ArgumentTypeError(f"{op}'s operands must be solids, got {v._show(tree)}")
    for s in solids[1:]:
        tree = CSG(op, tree, s)
    return tree


def union(*solids: Any) -> Solid:
    """The union of the solids (a single solid is itself): a CSG tree folded left."""
    return _fold("union", solids)


def intersection(*solids: Any) -> Solid:
    """The intersection of the solids: a CSG tree folded left."""
    return _fold("intersection", solids)


def difference(solid: Any, *others: Any) -> Solid:
    """``solid`` minus each of ``others`` in turn: a CSG tree folded left."""
    return _fold("difference", (solid,) + others)


@dataclass(frozen=True)
class MassProperties:
    """Mass properties of a solid of uniform ``density``.

    Attributes
    ----------
    volume, mass : float
    center : ndarray (3,)
        The center of mass.
    inertia : ndarray (3, 3)
        The inertia tensor about the center of mass, I_ij = integral of rho (|r|^2
        delta_ij - r_i r_j) dV.
    """
    volume: float
    mass: float
    center: np.ndarray
    inertia: np.ndarray


def _grid(solid, resolution):
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


def _integrals(solid, resolution, max_intervals):
    from .solids.program import Program

    if not is_solid(solid):
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
    the ray and the cell's area."""
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
