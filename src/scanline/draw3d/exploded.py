"""Exploded views (Hearn & Baker, section 9-1, "Exploded and Cutaway Views"): the
parts of an assembly moved apart, so that each part and how it joins the others can
be seen.

Each part moves along the line from the assembly's center through its own centroid,
its centroid going from ``c`` to ``center + factor * (c - center)``: every part's
distance from the center is multiplied by ``factor`` (1: assembled; 2: twice as
far).  The centroid of a part is the area-weighted centroid of its surface (each
face's triangles weighted by their area), which does not depend on how finely a part
is tessellated; the default center is the same centroid of all the parts together.
"""

from typing import Any, List, Optional, Sequence, Tuple

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..mesh import Mesh


def _parts(meshes: Any) -> List[Mesh]:
    if isinstance(meshes, Mesh):
        return [meshes]
    if isinstance(meshes, (str, bytes)) or not hasattr(meshes, "__iter__"):
        raise ArgumentTypeError(f"meshes must be a scanline.mesh.Mesh or a list of them, got "
                                f"{v._show(meshes)}")
    parts = list(meshes)
    if not parts or not all(isinstance(m, Mesh) for m in parts):
        raise ArgumentTypeError("meshes must be a non-empty list of scanline.mesh.Mesh")
    return parts


def surface_moments(mesh: Mesh) -> Tuple[float, NDArray[np.float64]]:
    """The surface area of ``mesh`` and its first moment (area times the area-weighted
    centroid), from the triangles of its faces' fans."""
    tri = mesh.triangulated()
    p = mesh.vertices[tri.faces]                               # (T, 3, 3)
    area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    return float(area.sum()), (area[:, None] * p.mean(axis=1)).sum(axis=0)


def centroid(mesh: Mesh) -> NDArray[np.float64]:
    """The area-weighted centroid of the surface of ``mesh`` (the vertex mean where
    its faces have no area).

    Parameters
    ----------
    mesh : Mesh
        Any mesh.

    Returns
    -------
    ndarray (3,)
        The centroid.

    Raises
    ------
    ArgumentTypeError
        ``mesh`` not a Mesh.

    Examples
    --------
    A box's surface is symmetric about its center:

    >>> import scanline as sl
    >>> centroid(sl.mesh.box((0, 0, 0), (2, 4, 6))).tolist()
    [1.0, 2.0, 3.0]
    """
    if not isinstance(mesh, Mesh):
        raise ArgumentTypeError(f"mesh must be a scanline.mesh.Mesh, got {v._show(mesh)}")
    area, moment = surface_moments(mesh)
    return moment / area if area > 0 else mesh.vertices.mean(axis=0)


def exploded(meshes: Any, factor: float,
             center: Optional[Sequence[float]] = None) -> List[Mesh]:
    """The parts of an assembly moved apart along the lines from its center through
    their centroids (Hearn & Baker, section 9-1).

    Parameters
    ----------
    meshes : Mesh or list of Mesh
        The parts, in place (assembled).
    factor : float
        How far each part's centroid goes, as a multiple of its distance from the
        center: 1 leaves the assembly as it is, 2 doubles every distance; at least 0
        (0 stacks every centroid on the center).
    center : 3-vector, optional
        The point the parts move away from; default the area-weighted centroid of all
        the parts' surfaces.

    Returns
    -------
    list of Mesh
        The parts translated, in the order given.

    Raises
    ------
    ArgumentTypeError
        ``meshes`` not meshes.
    ArgumentValueError
        A factor outside 0..1e6, or moves past float64.

    Examples
    --------
    >>> import scanline as sl
    >>> parts = [sl.mesh.cube(1.0, center=(-1, 0, 0)), sl.mesh.cube(1.0, center=(1, 0, 0))]
    >>> [centroid(m).tolist() for m in exploded(parts, 3)]
    [[-3.0, 0.0, 0.0], [3.0, 0.0, 0.0]]
    """
    parts = _parts(meshes)
    f = v.number("factor", factor)
    if not 0 <= f <= 1e6:
        raise ArgumentValueError(
            f"factor={f} must be between 0 and 1e6 (1: assembled, 2: each part twice as far "
            "from the center)")
    moments = [surface_moments(m) for m in parts]
    cents = np.array([c / a if a > 0 else m.vertices.mean(axis=0)
                      for m, (a, c) in zip(parts, moments)])
    if center is None:
        total = sum(a for a, _ in moments)
        c0 = (sum(c for _, c in moments) / total if total > 0
              else np.concatenate([m.vertices for m in parts]).mean(axis=0))
    else:
        from ..transform3d.arrays import vector

        c0 = np.array(vector("center", center))
    moves = (f - 1.0) * (cents - c0)
    if not np.isfinite(moves).all():
        raise ArgumentValueError(f"factor={f} moves the parts beyond float64; use a smaller one")
    return [m.translated(tuple(d)) for m, d in zip(parts, moves)]
