"""Sweep representations (Hearn & Baker, section 10-13): a 2-D shape moved through
space -- along a straight path (a translational sweep) or about an axis (a
rotational sweep) -- and the surface it traces, as a mesh; and tensor-product
surfaces (the Utah teapot) as meshes.

A profile is a polyline ((N, 2) points in the xy plane, or (N, 3)) or a curve of
:mod:`scanline.curves` (sampled at ``samples`` parameters).
"""

import numpy as np

from .. import _validate as v
from .. import transform3d as t3
from ..errors import ArgumentTypeError, ArgumentValueError
from ..transform3d.arrays import points as point_array
from .mesh import Mesh


def profile_points(profile, samples=32):
    """The profile as (N, 3) points: a polyline (z = 0 added to 2-D points) or a
    curve sampled at ``samples`` equally spaced parameters."""
    if hasattr(profile, "evaluate") and hasattr(profile, "domain"):
        n = v.positive_int("samples", samples, 2)
        pts = np.asarray(profile.evaluate(np.linspace(*profile.domain, n)), np.float64)
    else:
        pts = profile
    p, _ = point_array("profile", pts, (2, 3))
    if p.shape[1] == 2:
        p = np.hstack([p, np.zeros((len(p), 1))])
    if len(p) < 2:
        raise ArgumentValueError(f"profile needs at least 2 points, got {len(p)}")
    return p


def _closed(p, closed):
    if closed is None:
        closed = bool(np.allclose(p[0], p[-1]))
    if closed and np.allclose(p[0], p[-1]):
        p = p[:-1]
    return p, closed


def translational_sweep(profile, vector, closed=None, caps=True, samples=32, **kw):
    """The surface traced by moving ``profile`` along ``vector`` (dx, dy, dz): one
    quadrilateral per profile segment, and, for a closed profile with ``caps``, the
    two end faces (the profile itself and its moved copy), oriented outward when the
    profile runs counterclockwise seen against ``vector``.

    Parameters
    ----------
    profile : (N, 2|3) polyline or a curve
    vector : (dx, dy, dz)
    closed : bool, optional
        Whether the profile is a closed loop (default: when its ends coincide).
    caps : bool
        Close the ends of a closed profile.

    Examples
    --------
    >>> import scanline as sl
    >>> prism = sl.mesh.translational_sweep([(0, 0), (2, 0), (1, 1)], (0, 0, 3), closed=True)
    >>> prism, prism.polygon_tables().consistent
    (<Mesh: 6 vertices, 5 faces, 9 edges>, True)
    """
    from ..transform3d.arrays import vector as vec

    p, closed = _closed(profile_points(profile, samples), closed)
    d = np.array(vec("vector", vector))
    if not np.abs(d).max() > 0:
        raise ArgumentValueError("vector must not be (0, 0, 0): the sweep would be flat")
    n = len(p)
    verts = np.vstack([p, p + d])
    count = n if closed else n - 1
    i = np.arange(count)
    j = (i + 1) % n
    faces = [list(f) for f in np.stack([i, j, j + n, i + n], axis=1).tolist()]
    if closed and caps:
        if n < 3:
            raise ArgumentValueError("a closed profile needs at least 3 points")
        faces.append(list(range(n))[::-1])
        faces.append(list(range(n, 2 * n)))
    mesh = Mesh(verts, faces, **kw)
    if _newell_sign(mesh) < 0:
        mesh = Mesh(verts, [f[::-1] for f in faces], **kw)
    return mesh


def _newell_sign(mesh):
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


def rotational_sweep(profile, axis="y", angle=2 * np.pi, steps=32, closed=False,
                     samples=32, **kw):
    """The surface of revolution of ``profile`` turned by ``angle`` about ``axis``
    in ``steps`` equal rotations (Hearn & Baker's rotational sweep).

    A full turn (``angle`` = 2π) joins the last copy to the first.  Profile points
    on the axis become single vertices (the faces there are triangles).  A 2-D
    profile lies in the xy plane, so the default axis y turns it into a vase or a
    bowl standing on the xz plane.

    Parameters
    ----------
    profile : (N, 2|3) polyline or a curve
    axis : {"x", "y", "z"} or (p1, p2)
        As :func:`scanline.transform3d.rotation`.
    angle : float
        The sweep angle in radians, 0 < angle <= 2π.
    steps : int
        Rotations (faces around), >= 3 for a full turn.
    closed : bool
        The profile is a closed loop (a torus-like surface).

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
    rots = [t3.rotation(a * k / steps, axis) for k in range(copies)]
    if isinstance(axis, str):
        origin, direction = np.zeros(3), np.eye(3)["xyz".index(axis)]
    else:
        p1, p2 = (np.asarray(q, np.float64) for q in axis)
        origin, direction = p1, (p2 - p1) / np.linalg.norm(p2 - p1)
    rel = p - origin
    off = rel - np.outer(rel @ direction, direction)
    scale = max(float(np.abs(p).max()), 1.0)
    on_axis = np.sqrt((off * off).sum(axis=1)) <= 1e-12 * scale
    # vertex ids: points on the axis once, the others once per copy
    ids = np.empty((copies, len(p)), np.int64)
    verts = []
    for k, m in enumerate(rots):
        moved = t3.apply(m, p)
        for i in range(len(p)):
            if on_axis[i] and k > 0:
                ids[k, i] = ids[0, i]
            else:
                ids[k, i] = len(verts)
                verts.append(moved[i])
    faces = []
    segs = len(p) if closed else len(p) - 1
    for k in range(steps):
        k2 = (k + 1) % copies
        for i in range(segs):
            i2 = (i + 1) % len(p)
            quad = [ids[k, i], ids[k, i2], ids[k2, i2], ids[k2, i]]
            ring = [q for n, q in enumerate(quad) if q not in quad[:n]]
            if len(ring) >= 3:
                faces.append(ring)
    if not faces:
        raise ArgumentValueError("the profile lies on the axis: the sweep has no area")
    mesh = Mesh(np.array(verts), faces, **kw)
    if _newell_sign(mesh) < 0:
        mesh = Mesh(mesh.vertices, [f[::-1] for f in faces], **kw)
    return mesh


def sweep(profile, kind="rotational", **kw):
    """A sweep by name: ``"rotational"`` (:func:`rotational_sweep`, keywords
    ``axis``, ``angle``, ``steps``) or ``"translational"``
    (:func:`translational_sweep`, keyword ``vector``)."""
    v.choice("kind", kind, ("rotational", "translational"))
    own = ({"axis", "angle", "steps", "closed", "samples"} if kind == "rotational"
           else {"vector", "closed", "caps", "samples"}) | {"colors", "color_on", "name"}
    for key in kw:
        if key not in own:
            raise ArgumentTypeError(f"a {kind} sweep takes {', '.join(sorted(own))}; got "
                                    f"{key!r}")
    return (rotational_sweep if kind == "rotational" else translational_sweep)(profile, **kw)


def from_surface(surface, nu=16, nv=16, **kw):
    """A tensor-product surface (:class:`scanline.curves.BezierSurface`,
    :class:`~scanline.curves.BSplineSurface`) tessellated into a triangle mesh with
    its exact normals (:meth:`~scanline.curves.surfaces.Surface.tessellate`)."""
    from ..curves.surfaces import Surface, weld

    if not isinstance(surface, Surface):
        raise ArgumentTypeError(f"surface must be a scanline.curves surface, got "
                                f"{v._show(surface)}")
    verts, tris, normals = weld(*surface.tessellate(nu, nv))
    return Mesh(verts, tris, normals=normals, **kw)


def teapot(n=6, parts=None, **kw):
    """The Utah teapot (:func:`scanline.curves.teapot_mesh`) as a :class:`Mesh`: its
    patches tessellated n x n, welded, with exact normals; z up, spout toward +x.

    Examples
    --------
    >>> import scanline as sl
    >>> pot = sl.mesh.teapot(4)
    >>> pot.vertices.shape[1], int(pot.face_sizes.max())
    (3, 3)
    """
    from ..curves.teapot import teapot_mesh

    verts, tris, normals = teapot_mesh(n, parts)
    return Mesh(verts, tris, normals=normals, **kw)
