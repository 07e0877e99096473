"""Sweep representations (Hearn & Baker, section 10-13): a 2-D shape moved through
space -- along a straight path (a translational sweep) or about an axis (a
rotational sweep) -- and the surface it traces, as a mesh; and tensor-product
surfaces (the Utah teapot) as meshes.

A profile is a polyline ((N, 2) points in the xy plane, or (N, 3)) or a curve of
:mod:`scanline.curves` (sampled at ``samples`` parameters).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, List, Literal, Optional, Sequence, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .. import transform3d as t3
from .._typing import Angle, Points
from ..errors import ArgumentTypeError, ArgumentValueError
from ..transform3d.arrays import points as point_array
from .mesh import Flat, Mesh, MeshOptions, _reversed_faces, check_mesh_budget

if TYPE_CHECKING:
    from typing_extensions import Unpack

    from ..curves.base import Curve
    from ..curves.surfaces import Surface

#: A profile: a polyline ((N, 2) or (N, 3) points) or a curve of :mod:`scanline.curves`.
Profile = Union[Points, "Curve"]

#: Bytes a curve profile takes per sample while it is evaluated (the parameters,
#: the points and the evaluation's temporaries), for the memory budget.
BYTES_PER_SAMPLE = 256


def profile_points(profile: Profile, samples: int = 32) -> NDArray[np.float64]:
    """The profile as (N, 3) points: a polyline (z = 0 added to 2-D points) or a
    curve sampled at ``samples`` equally spaced parameters."""
    if hasattr(profile, "evaluate") and hasattr(profile, "domain"):
        from .. import budget

        n = v.positive_int("samples", samples, 2)
        budget.check(n * BYTES_PER_SAMPLE, "samples", f"{n:,} samples of the profile curve",
                     hint="give fewer samples")
        start, stop = profile.domain
        pts: object = np.asarray(profile.evaluate(np.linspace(start, stop, n)), np.float64)
    else:
        pts = profile
    p, _ = point_array("profile", pts, (2, 3))
    if p.shape[1] == 2:
        p = np.hstack([p, np.zeros((len(p), 1))])
    if len(p) < 2:
        raise ArgumentValueError(f"profile needs at least 2 points, got {len(p)}")
    return p


def _closed(p: NDArray[np.float64], closed: object) -> Tuple[NDArray[np.float64], bool]:
    if closed is not None and not isinstance(closed, (bool, np.bool_)):
        raise ArgumentTypeError(f"closed must be True, False or None (None: when the "
                                f"profile's ends coincide), got {v._show(closed)}")
    if closed is None:
        closed = bool(np.allclose(p[0], p[-1]))
    if closed and np.allclose(p[0], p[-1]):
        p = p[:-1]
    return p, bool(closed)


def translational_sweep(profile: Profile, vector: ArrayLike, closed: Optional[bool] = None,
                        caps: bool = True, samples: int = 32,
                        **kw: Unpack[MeshOptions]) -> Mesh:
    """The surface traced by moving ``profile`` along ``vector`` (dx, dy, dz): one
    quadrilateral per profile segment, and, for a closed profile with ``caps``, the
    two end faces (the profile itself and its moved copy), oriented outward when the
    profile runs counterclockwise seen against ``vector``.

    Parameters
    ----------
    profile : (N, 2|3) polyline or a curve
        The profile: points (2-D points get z = 0) or a curve of
        :mod:`scanline.curves`.
    vector : (dx, dy, dz)
        The sweep's path, not (0, 0, 0).
    closed : bool, optional
        Whether the profile is a closed loop (default: when its ends coincide).
    caps : bool
        Close the ends of a closed profile.
    samples : int, optional
        Parameters a curve profile is sampled at (>= 2).
    **kw
        ``colors``, ``color_on``, ``name``, ``uv``, ``material``: as :class:`Mesh`
        takes them.

    Returns
    -------
    Mesh
        2 N vertices; a quadrilateral per profile segment, and the two caps.

    Raises
    ------
    ArgumentValueError
        If the profile has fewer than 2 points (3 when closed and capped),
        ``vector`` is (0, 0, 0) or moves it beyond float64's range.
    ArgumentTypeError
        If ``closed`` or ``caps`` is not a bool.
    MemoryBudgetError
        If the mesh would take more memory than the budget allows.

    Notes
    -----
    Hearn & Baker, section 10-13, "sweep representations".

    Examples
    --------
    >>> import scanline as sl
    >>> prism = sl.mesh.translational_sweep([(0, 0), (2, 0), (1, 1)], (0, 0, 3), closed=True)
    >>> prism, prism.polygon_tables().consistent
    (<Mesh: 6 vertices, 5 faces, 9 edges>, True)
    """
    from ..transform3d.arrays import vector as vec

    p, closed = _closed(profile_points(profile, samples), closed)
    if not isinstance(caps, (bool, np.bool_)):
        raise ArgumentTypeError(f"caps must be True or False, got {v._show(caps)}")
    given = vec("vector", vector)
    d = np.array(given)
    if not np.abs(d).max() > 0:
        raise ArgumentValueError("vector must not be (0, 0, 0): the sweep would be flat")
    with np.errstate(over="ignore"):
        moved = p + d
    if not np.isfinite(moved).all():
        raise ArgumentValueError(f"vector={v._show(given)} moves the profile beyond "
                                 "the range of float64; use a shorter vector")
    n = len(p)
    count = n if closed else n - 1
    capped = closed and caps
    if capped and n < 3:
        raise ArgumentValueError("a closed profile needs at least 3 points")
    check_mesh_budget("profile", 2 * n, count + 2 * capped, 4 * count + 2 * n * capped,
                      f"the translational sweep of {n:,} profile points",
                      hint="give fewer profile points (or samples)")
    verts = np.vstack([p, moved])
    i = np.arange(count)
    j = (i + 1) % n
    parts = [np.stack([i, j, j + n, i + n], axis=1).ravel()]
    sizes: List[ArrayLike] = [np.full(count, 4)]
    if capped:
        parts += [np.arange(n)[::-1], np.arange(n, 2 * n)]
        sizes += [[n, n]]
    flat = Flat(np.concatenate(parts), np.concatenate(sizes))
    mesh = Mesh(verts, flat, **kw)
    if _newell_sign(mesh) < 0:
        mesh = Mesh(verts, Flat(_reversed_faces(mesh.face_indices, mesh.face_offsets),
                                mesh.face_sizes), **kw)
    return mesh


def _newell_sign(mesh: Mesh) -> int:
    """+1 when the faces point outward (positive enclosed volume) or the mesh is
    open, -1 when they point inward."""
    from .mesh import _newell

    planes = _newell(mesh.vertices, mesh.face_indices, mesh.face_offsets)
    centroid = mesh.vertices.mean(axis=0)
    owner = np.repeat(np.arange(mesh.face_count), mesh.face_sizes)
    centers = np.zeros((mesh.face_count, 3))
    np.add.at(centers, owner, mesh.vertices[mesh.face_indices])
    centers /= mesh.face_sizes[:, None]
    volume = ((centers - centroid) * planes[:, :3]).sum()
    return 1 if volume >= 0 else -1


def rotational_sweep(profile: Profile, axis: Union[str, ArrayLike] = "y",
                     angle: Angle = 2 * np.pi, steps: int = 32, closed: Optional[bool] = False,
                     samples: int = 32, **kw: Unpack[MeshOptions]) -> Mesh:
    """The surface of revolution of ``profile`` turned by ``angle`` about ``axis``
    in ``steps`` equal rotations (Hearn & Baker's rotational sweep).

    A full turn (``angle`` = 2π) joins the last copy to the first.  Profile points
    on the axis become single vertices (the faces there are triangles).  A 2-D
    profile lies in the xy plane, so the default axis y turns it into a vase or a
    bowl standing on the xz plane.

    Parameters
    ----------
    profile : (N, 2|3) polyline or a curve
        The profile: points (2-D points get z = 0) or a curve of
        :mod:`scanline.curves`.
    axis : {"x", "y", "z"} or (p1, p2)
        As :func:`scanline.transform3d.rotation`.
    angle : float
        The sweep angle in radians, 0 < angle <= 2π.
    steps : int
        Rotations (faces around), >= 3 for a full turn.
    closed : bool
        The profile is a closed loop (a torus-like surface); None: when its ends
        coincide.
    samples : int, optional
        Parameters a curve profile is sampled at (>= 2).
    **kw
        ``colors``, ``color_on``, ``name``, ``uv``, ``material``: as :class:`Mesh`
        takes them.

    Returns
    -------
    Mesh
        Faces counterclockwise seen from outside: quadrilaterals, and triangles
        where a profile point lies on the axis.

    Raises
    ------
    ArgumentValueError
        If ``angle`` is not in (0, 2π], ``steps`` is too small, the profile lies on
        the axis, or the swept points overflow float64.
    ArgumentTypeError
        If ``axis`` is neither a coordinate axis nor two points.
    MemoryBudgetError
        If the mesh would take more memory than the budget allows.

    Notes
    -----
    Hearn & Baker, section 10-13, "sweep representations".

    Examples
    --------
    >>> import scanline as sl
    >>> cone = sl.mesh.rotational_sweep([(0, 2), (1, 0), (0, 0)], steps=8)
    >>> len(cone.vertices), len(cone), cone.polygon_tables().consistent
    (10, 16, True)
    """
    p, closed = _closed(profile_points(profile, samples), closed)
    a = v.angle("angle", angle)
    if not 0 < a <= 2 * np.pi + 1e-12:
        raise ArgumentValueError(f"angle must be in (0, 2π], got {angle!r}")
    full = abs(a - 2 * np.pi) <= 1e-12
    steps = v.positive_int("steps", steps, 3 if full else 1)
    copies = steps if full else steps + 1
    n = len(p)
    segs = n if closed else n - 1
    check_mesh_budget("steps", copies * n, steps * segs, 4 * steps * segs,
                      f"the rotational sweep of {n:,} profile points in {steps:,} steps",
                      hint="give fewer steps (or profile points)")
    moved = _rotated_copies(p, axis, [a * k / steps for k in range(copies)])
    if isinstance(axis, str):
        origin, direction = np.zeros(3), np.eye(3)["xyz".index(axis)]
    else:
        from ..transform3d.affine3d import _axis_points
        from ..transform3d.arrays import direction as unit

        p1, p2 = _axis_points(axis)      # (checked already by _rotated_copies)
        origin = p1
        with np.errstate(over="ignore"):
            direction = unit("axis[1] - axis[0]", p2 - p1)
    with np.errstate(over="ignore", invalid="ignore"):
        rel = p - origin
        off = rel - np.outer(rel @ direction, direction)
        scale = max(float(np.abs(p).max()), 1.0)
        on_axis = np.sqrt((off * off).sum(axis=1)) <= 1e-12 * scale
    # vertex ids: points on the axis once (in the first copy), the others once per
    # copy, numbered copy by copy
    free = np.flatnonzero(~on_axis)
    ids = np.empty((copies, n), np.int64)
    ids[0] = np.arange(n)
    ids[1:, free] = n + (np.arange(copies - 1)[:, None] * len(free) + np.arange(len(free)))
    ids[1:, on_axis] = ids[0, on_axis]
    verts = np.concatenate([moved[0], moved[1:, free].reshape(-1, 3)])
    # the quadrilateral (a, b, c, d) between copies k, k + 1 and points i, i + 1 loses
    # c where point i + 1 is on the axis and d where point i is (a triangle), and
    # vanishes where both are
    i = np.arange(segs)
    i2 = (i + 1) % n
    k = np.arange(steps)
    k2 = (k + 1) % copies
    quads = np.stack([ids[k][:, i], ids[k][:, i2], ids[k2][:, i2], ids[k2][:, i]], axis=-1)
    keep = np.stack([np.ones(segs, bool), np.ones(segs, bool), ~on_axis[i2], ~on_axis[i]],
                    axis=-1)
    keep = np.broadcast_to(keep, quads.shape)
    sizes = keep.sum(axis=-1).ravel()
    whole = np.repeat(sizes >= 3, 4)
    indices = quads.reshape(-1)[keep.reshape(-1) & whole]
    sizes = sizes[sizes >= 3]
    if not len(sizes):
        raise ArgumentValueError("the profile lies on the axis: the sweep has no area")
    mesh = Mesh(verts, Flat(indices, sizes), **kw)
    if _newell_sign(mesh) < 0:
        mesh = Mesh(mesh.vertices, Flat(_reversed_faces(mesh.face_indices, mesh.face_offsets),
                                        sizes), **kw)
    return mesh


def _rotated_copies(p: NDArray[np.float64], axis: Union[str, ArrayLike],
                    angles: List[float]) -> NDArray[np.float64]:
    """``p`` (n, 3) turned by each of ``angles`` about ``axis``, (len(angles), n, 3):
    the points :func:`scanline.transform3d.rotation` and
    :func:`~scanline.transform3d.apply` give, computed for all the angles at once
    (the same products in the same order, so the same numbers).  The matrices are
    affine: their bottom row is exactly (0, 0, 0, 1), so no division is needed."""
    import math

    t3.rotation(angles[0], axis)                  # checks the axis
    cos = np.array([math.cos(t) for t in angles])
    sin = np.array([math.sin(t) for t in angles])
    m = np.zeros((len(angles), 4, 4))
    m[:, 3, 3] = 1.0
    if isinstance(axis, str):
        k = "xyz".index(axis)
        a, b = [j for j in range(3) if j != k]    # the plane turned: (y, z), (x, z), (x, y)
        m[:, k, k] = 1.0
        m[:, a, a] = m[:, b, b] = cos
        # Rx and Rz: -sin above the diagonal; Ry (a, b = x, z): +sin above it
        sign = -1.0 if axis != "y" else 1.0
        m[:, a, b], m[:, b, a] = sign * sin, -sign * sin
    else:
        steps = t3.rotation_steps(0.0, axis)
        left = np.eye(4)
        for step in reversed(steps[4:]):          # T^-1, Rx^-1, Ry^-1: the same for all
            left = left @ step.matrix
        m[:, 0, 0], m[:, 0, 1], m[:, 1, 0], m[:, 1, 1] = cos, -sin, sin, cos
        m[:, 2, 2] = 1.0
        m = left @ (m + 0.0)
        for step in reversed(steps[:3]):          # Ry, Rx, T
            m = m @ step.matrix
    m = m + 0.0
    with np.errstate(over="ignore", invalid="ignore"):
        out = p @ m[:, :3, :3].transpose(0, 2, 1) + m[:, None, :3, 3]
    if not np.isfinite(out).all():
        raise ArgumentValueError("the swept points overflow float64 (the profile or the axis "
                                 "lies too far from the origin); move them closer")
    copies: NDArray[np.float64] = out + 0.0
    return copies


def sweep(profile: Profile, kind: Literal["rotational", "translational"] = "rotational",
          **kw: Any) -> Mesh:
    """A sweep by name: ``"rotational"`` (:func:`rotational_sweep`, keywords
    ``axis``, ``angle``, ``steps``) or ``"translational"``
    (:func:`translational_sweep`, keyword ``vector``).

    Parameters
    ----------
    profile : (N, 2|3) polyline or a curve
        The profile.
    kind : {"rotational", "translational"}, optional
        Which sweep.
    **kw
        The keywords of that sweep (``axis``, ``angle``, ``steps``, ``closed``,
        ``samples``; or ``vector``, ``closed``, ``caps``, ``samples``), and
        ``colors``, ``color_on``, ``name``.

    Returns
    -------
    Mesh

    Raises
    ------
    ArgumentValueError
        If ``kind`` is neither, or as the sweep it names.
    ArgumentTypeError
        If a keyword is not one of that sweep's.

    Notes
    -----
    Hearn & Baker, section 10-13, "sweep representations".

    Examples
    --------
    A triangle swept 3 along z: a prism of three sides and two caps.

    >>> import scanline as sl
    >>> sl.mesh.sweep([(0, 0), (2, 0), (1, 1)], "translational", vector=(0, 0, 3), closed=True)
    <Mesh: 6 vertices, 5 faces, 9 edges>
    """
    v.choice("kind", kind, ("rotational", "translational"))
    own = ({"axis", "angle", "steps", "closed", "samples"} if kind == "rotational"
           else {"vector", "closed", "caps", "samples"}) | {"colors", "color_on", "name"}
    for key in kw:
        if key not in own:
            raise ArgumentTypeError(f"a {kind} sweep takes {', '.join(sorted(own))}; got "
                                    f"{key!r}")
    return (rotational_sweep if kind == "rotational" else translational_sweep)(profile, **kw)


def from_surface(surface: Surface, nu: int = 16, nv: int = 16,
                 **kw: Unpack[MeshOptions]) -> Mesh:
    """A tensor-product surface (:class:`scanline.curves.BezierSurface`,
    :class:`~scanline.curves.BSplineSurface`) tessellated into a triangle mesh with
    its exact normals (:meth:`~scanline.curves.surfaces.Surface.tessellate`).

    Parameters
    ----------
    surface : scanline.curves.BezierSurface or scanline.curves.BSplineSurface
        The surface.
    nu, nv : int, optional
        Intervals of the parameter grid in u and v (>= 1).
    **kw
        ``colors``, ``color_on``, ``name``, ``uv``, ``material``: as :class:`Mesh`
        takes them.

    Returns
    -------
    Mesh
        (nu + 1)(nv + 1) vertices (fewer where the surface meets itself: welded)
        and 2 nu nv triangles (fewer where they collapse).

    Raises
    ------
    ArgumentTypeError
        If ``surface`` is not a surface of :mod:`scanline.curves`.
    ArgumentValueError
        If ``nu`` or ``nv`` is not >= 1.
    MemoryBudgetError
        If the mesh would take more memory than the budget allows.

    Examples
    --------
    The bilinear patch P(u, v) = (u, v, 0): a 3 x 3 grid of vertices, 8 triangles,
    normals ∂P/∂u × ∂P/∂v = +z.

    >>> import scanline as sl
    >>> patch = sl.curves.BezierSurface([[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 0)]])
    >>> square = sl.mesh.from_surface(patch, 2, 2)
    >>> square
    <Mesh: 9 vertices, 8 faces, 16 edges>
    >>> square.normals[0].tolist()
    [0.0, 0.0, 1.0]
    """
    from ..curves.surfaces import Surface, weld

    if not isinstance(surface, Surface):
        raise ArgumentTypeError(f"surface must be a scanline.curves surface, got "
                                f"{v._show(surface)}")
    nu = v.positive_int("nu", nu)
    nv = v.positive_int("nv", nv)
    check_mesh_budget("nu x nv", (nu + 1) * (nv + 1), 2 * nu * nv, 6 * nu * nv,
                      f"a tessellation of {nu} x {nv} intervals",
                      hint="give fewer intervals nu x nv")
    verts, tris, normals = weld(*surface.tessellate(nu, nv))
    return Mesh(verts, tris, normals=normals, **kw)


def teapot(n: int = 6, parts: Union[str, Sequence[str], None] = None,
           **kw: Unpack[MeshOptions]) -> Mesh:
    """The Utah teapot (:func:`scanline.curves.teapot_mesh`) as a :class:`Mesh`: its
    patches tessellated n x n, welded, with exact normals; z up, spout toward +x.

    Parameters
    ----------
    n : int, optional
        Intervals per patch side (>= 1).
    parts : str or list of str, optional
        The parts to include (``"rim"``, ``"body"``, ``"handle"`` ...; see
        :data:`scanline.curves.teapot.PARTS`); all by default.
    **kw
        ``colors``, ``color_on``, ``name``, ``uv``, ``material``: as :class:`Mesh`
        takes them.

    Returns
    -------
    Mesh
        A triangle mesh.

    Raises
    ------
    ArgumentValueError
        If ``n`` is not >= 1 or a part name is unknown.
    ArgumentTypeError
        If ``parts`` is not a name or a non-empty list of names.
    MemoryBudgetError
        If the mesh would take more memory than the budget allows.

    Notes
    -----
    Newell's teapot (1975) of 32 bicubic Bezier patches; Hearn & Baker, section
    10-8 (Bezier surfaces).

    Examples
    --------
    >>> import scanline as sl
    >>> pot = sl.mesh.teapot(4)
    >>> pot.vertices.shape[1], int(pot.face_sizes.max())
    (3, 3)
    """
    from ..curves.teapot import PARTS, teapot_mesh

    n = v.positive_int("n", n)
    if parts is not None:
        names = [parts] if isinstance(parts, str) else parts
        if isinstance(names, (bytes, dict)) or not hasattr(names, "__iter__") \
                or not hasattr(names, "__len__") or not len(names) \
                or not all(isinstance(name, str) for name in names):
            raise ArgumentTypeError(
                f"parts must be a part name or a non-empty list of them ({', '.join(PARTS)}), "
                f"got {v._show(parts)}")
        for name in names:
            v.choice("parts", name, tuple(PARTS))
    # 32 patches (fewer with parts), each (n + 1)**2 points and 2 n**2 triangles
    check_mesh_budget("n", 32 * (n + 1) ** 2, 64 * n * n, 192 * n * n,
                      f"the teapot tessellated {n} x {n} per patch")
    verts, tris, normals = teapot_mesh(n, parts)
    return Mesh(verts, tris, normals=normals, **kw)
