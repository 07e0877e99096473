"""What the preparation takes from each mesh, computed once per mesh and kept with it:
the faces' fan triangles (the *facets*), their normals and colors, and per face the
plane normal, centroid and color that constant shading uses.

A face of k vertices is cut into the k - 2 triangles of a fan from its first vertex;
every later stage works on these facets (the rasterizers, the visible-surface
methods' polygons, the interpolation of attributes) and reports the face each comes
from.  A face's normal is Newell's (Hearn & Baker, section 10-1), exact for planar
faces and the best plane of a bent one.  The normals at the vertices, where the mesh
gives none, are the faces' around each vertex averaged, as modelers make them: split
at a crease angle (a face's corner takes only the faces within that angle of its own,
so a cube stays flat-faced and a cylinder keeps its rims) and weighted by each face's
angle at the vertex (Thurmer & Wuthrich 1998, so that a face cut into more triangles
weighs no more); ``crease_angle=None`` gives the book's plain average over every face
sharing the vertex (Hearn & Baker, section 14-5: ``N_v = sum N_k / |sum N_k|``).
"""

import math

import weakref
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Optional

import numpy as np
from numpy.typing import NDArray

from .polygons import convex, newell_planes

if TYPE_CHECKING:
    from ..mesh import Mesh

F64 = NDArray[np.float64]


def unit_rows(a: F64) -> F64:
    """Rows of ``a`` (..., 3) divided by their length (zero rows stay zero)."""
    n = np.sqrt((a * a).sum(axis=-1, keepdims=True))
    with np.errstate(invalid="ignore", divide="ignore"):
        out: F64 = np.where(n > 0, a / n, 0.0)
    return out


def meshes_list(meshes: Any, empty: bool = False) -> list["Mesh"]:
    """``meshes`` (one mesh or several: :class:`~scanline.mesh.Mesh` or any object
    :meth:`~scanline.mesh.Mesh.from_any` takes, a trimesh mesh say) as a list of Mesh
    (``empty``: whether none is allowed)."""
    from ..mesh.convert import as_meshes

    return as_meshes(meshes, "meshes", empty=empty)


#: The default crease angle (radians): faces meeting at a sharper angle keep their own
#: normals at the shared vertex (about what modeling programs use).
CREASE_ANGLE = math.radians(30.0)


def corner_normals(mesh: "Mesh", crease_angle: Optional[float] = CREASE_ANGLE) -> F64:
    """The unit normal at each face corner, (C, 3) in the order of
    ``mesh.face_indices``: the mesh's own vertex normals where it has them, else the
    normals of the faces around the vertex within ``crease_angle`` (radians, 0..pi) of
    the corner's face, each weighted by its angle at the vertex; ``None``: the book's
    plain average of every face around the vertex (:func:`averaged_normals`)."""
    idx, off = mesh.face_indices, mesh.face_offsets
    if mesh.normals is not None:
        return unit_rows(mesh.normals[idx])
    if crease_angle is None:
        averaged: F64 = averaged_normals(mesh)[idx]
        return averaged
    from .._kernels._jit import call
    from .._kernels.normals import crease_normals

    sizes = np.diff(off)
    owner = np.repeat(np.arange(mesh.face_count), sizes)
    points = mesh.vertices[idx]
    position = np.arange(len(idx)) - off[:-1][owner]
    nxt = idx[off[:-1][owner] + (position + 1) % sizes[owner]]
    prv = idx[off[:-1][owner] + (position - 1) % sizes[owner]]
    a = mesh.vertices[nxt] - points
    b = mesh.vertices[prv] - points
    with np.errstate(all="ignore"):
        angles = np.arctan2(np.linalg.norm(np.cross(a, b), axis=1), (a * b).sum(axis=1))
    angles = np.nan_to_num(angles)
    face_normals = unit_rows(newell_planes(points, off)[:, :3])
    order = np.argsort(idx, kind="stable")
    starts = np.searchsorted(idx[order], np.arange(len(mesh.vertices) + 1))
    out = np.zeros((len(idx), 3))
    call(crease_normals, 20 * len(idx), owner.astype(np.int64), face_normals, angles,
         order.astype(np.int64), starts.astype(np.int64), math.cos(crease_angle), out)
    return out


def averaged_normals(mesh: "Mesh") -> F64:
    """Vertex normals (V, 3) averaged from the unit normals of the faces sharing each
    vertex (Hearn & Baker, section 14-5, Gouraud shading: ``N_v = sum N_k / |sum N_k|``).

    Parameters
    ----------
    mesh : Mesh
        The mesh.

    Returns
    -------
    numpy.ndarray
        float64 (V, 3) unit vertex normals.

    Examples
    --------
    >>> import scanline as sl
    >>> n = sl.screen.averaged_normals(sl.mesh.cube())   # a corner meets 3 faces
    >>> bool(abs(abs(n).round(6) - round(3 ** -0.5, 6)).max() == 0)
    True
    """
    idx, off = mesh.face_indices, mesh.face_offsets
    owner = np.repeat(np.arange(mesh.face_count), np.diff(off))
    fn = unit_rows(newell_planes(mesh.vertices[idx], off)[:, :3])
    out = np.zeros_like(mesh.vertices)
    np.add.at(out, idx, fn[owner])
    return unit_rows(out)


@dataclass
class MeshArrays:
    """One mesh's arrays for the preparation.

    Per facet (G, the fan triangles, face after face): world vertices (G, 3, 3), unit
    vertex normals (G, 3, 3), unit facet normals (G, 3), the stored colors / 255 at
    the vertices (G, 3, 3; None: the material's color), degenerate facets (G,), and
    the face of each facet (G,).  Per face (F): unit Newell normals (F, 3), centroids
    (the mean of the vertices, F, 3), colors (stored / 255, the mean of the
    vertices' for a mesh colored by vertex; F, 3; None: the material's), and whether
    the face is planar (its vertices within 1e-9 of its size of its Newell plane) and
    convex (F,): a polygon method may then take it whole, since a planar convex
    polygon in front of the eye projects to a convex polygon.  The texture
    coordinates at each facet's vertices (G, 3, 2; None: the mesh has none).  The
    mesh's vertices (V, 3) and each facet's corners among them (G, 3): ``world`` is
    ``points[corners]``, and a vertex is projected once however many facets share
    it."""
    world: F64
    vertex_normals: F64
    normals: F64
    colors: Optional[F64]
    degenerate: NDArray[np.bool_]
    facet_face: NDArray[np.int64]
    face_normals: F64
    face_centroids: F64
    face_colors: Optional[F64]
    face_planar: NDArray[np.bool_]
    uv: Optional[F64]
    points: F64
    corners: NDArray[np.int64]


#: mesh -> (copies of the arrays it was made from, MeshArrays)
_KEPT: "weakref.WeakKeyDictionary[Mesh, tuple[tuple[Any, ...], MeshArrays]]" = (
    weakref.WeakKeyDictionary())


def _key(mesh: "Mesh") -> tuple[Any, ...]:
    return (mesh.vertices, mesh.face_indices, mesh.face_offsets, mesh.normals, mesh.colors,
            mesh.color_on, mesh.uv)


def _same(a: object, b: object) -> bool:
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return (isinstance(a, np.ndarray) and isinstance(b, np.ndarray) and a.shape == b.shape
                and a.dtype == b.dtype and np.array_equal(a, b))
    return bool(a == b)


def mesh_arrays(mesh: "Mesh", crease_angle: Optional[float] = CREASE_ANGLE) -> MeshArrays:
    """The :class:`MeshArrays` of ``mesh`` (its vertex normals split at
    ``crease_angle``, :func:`corner_normals`), computed once and kept while the mesh's
    vertices, faces, normals and colors are equal to what they were (they are public
    arrays: a change in place is noticed by comparing them with copies) and the crease
    angle is the same.  Its arrays are read-only in effect: several scenes share
    them.

    Parameters
    ----------
    mesh : Mesh
        The mesh.
    crease_angle : float or None
        Radians, 0..pi; None averages every face around a vertex.

    Returns
    -------
    MeshArrays
        Its arrays (shared: do not write to them).

    Examples
    --------
    >>> import scanline as sl
    >>> arrays = sl.screen.mesh_arrays(sl.mesh.cube())
    >>> arrays.world.shape, arrays.face_normals.shape, bool(arrays.face_planar.all())
    ((12, 3, 3), (6, 3), True)
    """
    key = _key(mesh) + (crease_angle,)
    kept = _KEPT.get(mesh)
    if kept is not None and all(_same(a, b) for a, b in zip(kept[0], key)):
        return kept[1]
    idx, off = mesh.face_indices, mesh.face_offsets
    sizes = np.diff(off)
    tri = mesh.triangulated()
    f = tri.face_indices.reshape(-1, 3)
    facet_face = np.repeat(np.arange(mesh.face_count, dtype=np.int64), sizes - 2)
    world = mesh.vertices[f]
    # the corners of each facet among the face's corners: (0, j + 1, j + 2) of its fan
    j = np.arange(len(facet_face)) - np.repeat(np.cumsum(sizes - 2) - (sizes - 2), sizes - 2)
    first = off[:-1][facet_face]
    corners = np.stack([first, first + j + 1, first + j + 2], axis=1)
    # vertices far out (finite, past about 1e150) overflow the products: their normals
    # come out NaN, and such facets are degenerate (below)
    with np.errstate(over="ignore", invalid="ignore"):
        normals = unit_rows(np.cross(world[:, 1] - world[:, 0], world[:, 2] - world[:, 0]))
    points = mesh.vertices[idx]
    plane = newell_planes(points, off)
    centroids = np.add.reduceat(points, off[:-1], axis=0) / sizes[:, None]
    norm = np.linalg.norm(plane[:, :3], axis=1)
    owner = np.repeat(np.arange(mesh.face_count), sizes)
    with np.errstate(over="ignore", invalid="ignore"):
        dist = np.abs(np.einsum("ij,ij->i", points, plane[owner, :3]) + plane[owner, 3])
        off_plane = np.maximum.reduceat(dist, off[:-1]) / np.where(norm > 0, norm, 1.0)
        size = (np.maximum.reduceat(points, off[:-1], axis=0)
                - np.minimum.reduceat(points, off[:-1], axis=0)).max(axis=1)
    planar = (norm > 0) & (off_plane <= 1e-9 * np.where(size > 0, size, 1.0))
    # convex: in the plane's own coordinates (the two axes the normal is least along)
    drop = np.abs(plane[:, :3]).argmax(axis=1)[owner]
    keep = np.array([[1, 2], [0, 2], [0, 1]])[drop]
    flat = np.take_along_axis(points, keep, axis=1)
    with np.errstate(over="ignore", invalid="ignore"):
        planar &= convex(flat, off)
    if mesh.colors is None:
        colors = face_colors = None
    elif mesh.color_on == "vertex":
        colors = mesh.colors[f][..., :3] / 255.0
        face_colors = np.add.reduceat(mesh.colors[idx][:, :3] / 255.0, off[:-1],
                                      axis=0) / sizes[:, None]
    else:
        face_colors = mesh.colors[:, :3] / 255.0
        colors = np.repeat(face_colors[facet_face][:, None], 3, axis=1)
    arrays = MeshArrays(world, corner_normals(mesh, crease_angle)[corners], normals, colors,
                        ~(np.abs(normals).sum(axis=1) > 0), facet_face,
                        unit_rows(plane[:, :3]), centroids, face_colors, planar,
                        None if mesh.uv is None else mesh.uv[f],
                        np.ascontiguousarray(mesh.vertices, np.float64),
                        np.ascontiguousarray(f, np.int64))
    _KEPT[mesh] = (tuple(a.copy() if isinstance(a, np.ndarray) else a for a in key), arrays)
    return arrays
