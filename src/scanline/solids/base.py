"""What every solid has: a material, ``contains``, ``bounds``, ``volume``, and the
operators ``|``, ``&`` and ``-`` that build constructive-solid-geometry trees
(:mod:`scanline.csg`)."""

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError


def material_of(material):
    """``material`` (a :class:`~scanline.lighting.Material` or None: the default)."""
    from ..lighting import Material

    if material is None:
        return Material()
    if not isinstance(material, Material):
        raise ArgumentTypeError(f"material must be a scanline.lighting.Material or None, got "
                                f"{v._show(material)}")
    return material


class Solid:
    """A closed region of space (Hearn & Baker 10-16: the primitives of solid
    modeling and the trees made from them).

    Subclasses give :meth:`contains`, :meth:`bounds`, :meth:`volume` and their
    primitives; ``a | b``, ``a & b`` and ``a - b`` are :func:`scanline.csg.union`,
    :func:`~scanline.csg.intersection` and :func:`~scanline.csg.difference`.
    """

    def contains(self, points):
        """Whether each point (N, 3) lies inside the solid: a bool array (N,)."""
        raise NotImplementedError

    def bounds(self):
        """``(lo, hi)``: two (3,) arrays, corners of a box that holds the solid
        (+-inf where it is unbounded)."""
        raise NotImplementedError

    def volume(self):
        """The solid's volume."""
        raise NotImplementedError

    def __or__(self, other):
        from ..csg import union

        return union(self, other)

    def __and__(self, other):
        from ..csg import intersection

        return intersection(self, other)

    def __sub__(self, other):
        from ..csg import difference

        return difference(self, other)


def is_solid(value):
    """Whether ``value`` is a solid (a primitive or a CSG tree)."""
    return isinstance(value, Solid)


def point_rows(points):
    """Finite points (N, 3) float64 from ``points`` (one point or many)."""
    from ..transform3d.arrays import points as point_array

    return point_array("points", points)[0]


def finite_bounds(solid, argument="solid"):
    """``solid.bounds()`` as two (3,) arrays, refused when unbounded."""
    from ..errors import ArgumentValueError

    lo, hi = solid.bounds()
    if not (np.isfinite(lo).all() and np.isfinite(hi).all()):
        raise ArgumentValueError(f"{argument} is unbounded (bounds {lo.tolist()} .. "
                                 f"{hi.tolist()}): intersect it with a Box to bound it")
    return lo, hi
