"""What every solid has: a material, ``contains``, ``bounds``, ``volume``, and the
operators ``|``, ``&`` and ``-`` that build constructive-solid-geometry trees
(:mod:`scanline.csg`)."""

from typing import TYPE_CHECKING, Optional, Tuple, TypeGuard

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError

if TYPE_CHECKING:
    from ..lighting import Material

#: A box's corners: (lo (3,), hi (3,)).
Bounds = Tuple[NDArray[np.float64], NDArray[np.float64]]


def material_of(material: Optional["Material"]) -> "Material":
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

    Examples
    --------
    >>> import scanline as sl
    >>> tree = sl.solids.Sphere((0, 0, 0), 1.0) | sl.solids.Box((0, 0, 0), (2, 1, 1))
    >>> isinstance(tree, sl.solids.Solid), tree.contains([(1.5, 0.5, 0.5)]).tolist()
    (True, [True])
    """

    #: The surface's material (a primitive's own; a CSG tree's left operand's).
    material: "Material"

    def contains(self, points: ArrayLike) -> NDArray[np.bool_]:
        """Whether each point (N, 3) lies inside the solid: a bool array (N,).

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
        >>> sl.solids.Sphere((0, 0, 0), 1.0).contains([(0, 0, 0.5), (0, 1, 1)]).tolist()
        [True, False]
        """
        raise NotImplementedError

    def bounds(self) -> Bounds:
        """``(lo, hi)``: two (3,) arrays, corners of a box that holds the solid
        (+-inf where it is unbounded).

        Returns
        -------
        lo, hi : ndarray (3,)
            The box's corners.

        Examples
        --------
        >>> import scanline as sl
        >>> [c.tolist() for c in sl.solids.Box((0, 0, 0), (1, 2, 3)).bounds()]
        [[0.0, 0.0, 0.0], [1.0, 2.0, 3.0]]
        """
        raise NotImplementedError

    def volume(self) -> float:
        """The solid's volume.

        Returns
        -------
        float
            The volume (exact for the primitives; by ray casting for CSG trees).

        Examples
        --------
        >>> import scanline as sl
        >>> sl.solids.Box((0, 0, 0), (1, 2, 3)).volume()
        6.0
        """
        raise NotImplementedError

    def __or__(self, other: "Solid") -> "Solid":
        from ..csg import union

        return union(self, other)

    def __and__(self, other: "Solid") -> "Solid":
        from ..csg import intersection

        return intersection(self, other)

    def __sub__(self, other: "Solid") -> "Solid":
        from ..csg import difference

        return difference(self, other)


def is_solid(value: object) -> TypeGuard["Solid"]:
    """Whether ``value`` is a solid (a primitive or a CSG tree).

    Parameters
    ----------
    value : object
        Anything.

    Returns
    -------
    bool
        Whether it is a :class:`Solid`.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.csg.is_solid(sl.solids.Sphere()), sl.csg.is_solid("a sphere")
    (True, False)
    """
    return isinstance(value, Solid)


def point_rows(points: ArrayLike) -> NDArray[np.float64]:
    """Finite points (N, 3) float64 from ``points`` (one point or many)."""
    from ..transform3d.arrays import points as point_array

    return point_array("points", points)[0]


def finite_bounds(solid: Solid, argument: str = "solid") -> Bounds:
    """``solid.bounds()`` as two (3,) arrays, refused when unbounded.

    Parameters
    ----------
    solid : Solid
        A primitive or a CSG tree.
    argument : str
        The argument's name in the error.

    Returns
    -------
    lo, hi : ndarray (3,)
        Finite corners of a box that holds the solid.

    Raises
    ------
    ArgumentValueError
        The solid is unbounded (a quadric such as a cylinder without caps).

    Examples
    --------
    >>> import scanline as sl
    >>> [c.tolist() for c in sl.csg.finite_bounds(sl.solids.Sphere((1, 0, 0), 2.0))]
    [[-1.0, -2.0, -2.0], [3.0, 2.0, 2.0]]
    """
    from ..errors import ArgumentValueError

    lo, hi = solid.bounds()
    if not (np.isfinite(lo).all() and np.isfinite(hi).all()):
        raise ArgumentValueError(f"{argument} is unbounded (bounds {lo.tolist()} .. "
                                 f"{hi.tolist()}): intersect it with a Box to bound it")
    return lo, hi
