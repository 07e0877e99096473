"""Scene preparation: meshes and a camera turned into the screen-space scene every
visible-surface method works on (:class:`ScreenScene`).

Steps (Hearn & Baker, chapters 12-14): every face is split into triangles (a fan from
its first vertex); the **back-face test** V . N > 0 is made in viewing coordinates
(section 13-2: V from the center of projection to the face, or the direction of
projection of a parallel view; N the face's outward normal), and with
``cull_back_faces`` the back faces are dropped; the triangles go to homogeneous clip
coordinates and those that leave the view volume's depth range are **clipped before
the divide** (Sutherland-Hodgman against z >= 0, z <= w and a guard band far outside
the window, so nothing behind the eye is mirrored and no coordinate grows without
bound: the rasterizer clips to the frame buffer itself); then the divide and the
device mapping give device x, y and depth.  Each vertex carries its 1/w and its
barycentric coordinates in its source face, which the rasterizer interpolates
perspective-correctly: any attribute of the face (normal, world position, color) is
then known at every pixel.
"""

import weakref
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from ..clip.volumes import Volume
from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..lighting.material import Material
from ..mesh import Mesh

#: Guard band: the clip volume reaches this many window widths beyond the window on
#: each side (device coordinates stay within about 2**20 for any real frame buffer).
GUARD = 256.0

#: The volume triangles are clipped against, as homogeneous planes (a x + b y + c z +
#: d w >= 0): the depth range 0 <= z <= w and the guard band around the window.
CLIP_VOLUME = Volume(
    [(0, 0, 1, 0), (0, 0, -1, 1), (1, 0, 0, GUARD), (-1, 0, 0, 1 + GUARD),
     (0, 1, 0, GUARD), (0, -1, 0, 1 + GUARD)],
    ("front", "back", "left guard", "right guard", "below guard", "above guard"),
    "render clip volume")


@dataclass
class ScreenScene:
    """A scene ready for the visible-surface methods: device-space triangles and the
    faces they come from.

    Faces are the triangles of the meshes' fan triangulations (F of them, numbered
    mesh after mesh); clipping may cut one face into several device triangles (T of
    them).  Device coordinates: x, y in pixels (centers at integers, y up), depth
    the NDC depth in the camera's viewport range (0 front, 1 back by default).

    Attributes
    ----------
    width, height : int
        The frame buffer's size.
    triangles : ndarray (T, 3, 3)
        Device x, y, depth of each vertex of each visible triangle.
    inv_w : ndarray (T, 3)
        1 / w of each vertex (w the homogeneous clip coordinate), for perspective-
        correct interpolation.
    bary : ndarray (T, 3, 2)
        Each vertex's barycentric coordinates (lambda_1, lambda_2) in its source face
        (lambda_0 = 1 - lambda_1 - lambda_2), linear in the eye's space.
    face : ndarray of int64 (T,)
        The source face of each triangle.
    polygons : sequence of ndarray (k, 3)
        The clipped device polygon (x, y, depth) of each face that is left, one per
        entry of ``polygon_face`` (convex: a clipped triangle); a
        :class:`DevicePolygons`, made on demand.
    polygon_face : ndarray of int64 (P,)
    face_mesh : ndarray of int64 (F,)
        The mesh (index into ``meshes``/``materials``) of each face.
    front : ndarray of bool (F,)
        The back-face test: True for a face whose outward normal points toward the
        viewer (V . N < 0).
    culled : ndarray of bool (F,)
        Faces dropped by back-face culling.
    world : ndarray (F, 3, 3)
        World coordinates of each face's vertices.
    normals : ndarray (F, 3)
        Unit outward face normals (world).
    vertex_normals : ndarray (F, 3, 3)
        Unit normals at each face's vertices: the mesh's own, else the average of the
        unit normals of the faces that share the vertex (Gouraud).
    vertex_colors : ndarray (F, 3, 3)
        Surface color S_d at each face vertex, the stored color values / 255.
    planes : ndarray (F, 4)
        A, B, C, D of each face's plane in device space (A x + B y + C z + D = 0,
        C > 0 for a front face), NaN for a face nothing is left of.
    materials : tuple of Material
        One per mesh.

    ``world``, ``normals`` and ``vertex_normals`` are shared with the meshes' kept
    arrays (:func:`mesh_arrays`), and ``bary`` of a scene nothing was clipped from
    with every scene's: read them, do not write them.  ``vertex_colors``
    of a mesh without colors is its material's color broadcast (not a copy).
    eye : 3-vector or ViewerAtInfinity
        The viewer for the illumination model.
    camera : Camera
    """
    width: int
    height: int
    triangles: np.ndarray
    inv_w: np.ndarray
    bary: np.ndarray
    face: np.ndarray
    polygons: list
    polygon_face: np.ndarray
    face_mesh: np.ndarray
    front: np.ndarray
    culled: np.ndarray
    world: np.ndarray
    normals: np.ndarray
    vertex_normals: np.ndarray
    vertex_colors: np.ndarray
    planes: np.ndarray
    materials: tuple
    eye: object
    camera: object
    options: dict = field(default_factory=dict)

    @property
    def face_count(self):
        return len(self.face_mesh)


def _unit_rows(a):
    n = np.sqrt((a * a).sum(axis=-1, keepdims=True))
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(n > 0, a / n, 0.0)


def averaged_normals(mesh):
    """Vertex normals (V, 3) averaged from the unit normals of the faces sharing each
    vertex (Hearn & Baker, section 14-5, Gouraud shading: N_v = sum N_k / |sum N_k|)."""
    from ..visible.polygons import newell_planes

    idx, off = mesh.face_indices, mesh.face_offsets
    owner = np.repeat(np.arange(mesh.face_count), np.diff(off))
    fn = _unit_rows(newell_planes(mesh.vertices[idx], off)[:, :3])   # Newell's normals
    out = np.zeros_like(mesh.vertices)
    np.add.at(out, idx, fn[owner])
    return _unit_rows(out)


def _materials(materials, n):
    if materials is None:
        return (Material(),) * n
    if isinstance(materials, Material):
        return (materials,) * n
    items = tuple(materials)
    if len(items) != n or not all(isinstance(m, Material) for m in items):
        raise ArgumentValueError(
            f"materials must be one sl.lighting.Material or a list of {n} (one per mesh), "
            f"got {len(items)} item(s)")
    return items


def _meshes(meshes):
    return v.one_or_many("meshes", meshes, Mesh, "a scanline.mesh.Mesh")


def _viewer(camera):
    from ..lighting.model import at_infinity

    eye = camera.eye
    if eye is not None:
        return np.array(eye)
    toward = _view_direction(camera)
    inv = np.linalg.inv(camera.projection.orientation @ camera.view_matrix)[:3, :3]
    return at_infinity(-(inv @ toward))


def _view_direction(camera):
    """The viewing direction of a parallel projection in viewing coordinates: along
    -z_v, sheared by the projection's (a, b)."""
    a, b = camera.projection.shear
    return np.array([a, b, -1.0])


def back_faces(camera, world):
    """Hearn & Baker's back-face test for triangles (F, 3, 3) of world points: True
    where V . N > 0 in viewing coordinates."""
    m = camera.projection.orientation @ camera.view_matrix
    p = world @ m[:3, :3].T + m[:3, 3]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    if camera.projection.kind == "perspective":
        view = p[:, 0] - np.array(camera.projection.prp)
    else:
        view = np.broadcast_to(_view_direction(camera), n.shape)
    return (view * n).sum(axis=1) > 0


class DevicePolygons(Sequence):
    """The clipped device polygons (k, 3) of a scene's faces, made on demand: the
    faces left whole are rows of one (W, 3, 3) array (no list of W arrays is built
    unless asked for), followed by the polygons of the faces the volume cut."""

    def __init__(self, whole, cut):
        self._whole = whole
        self._cut = cut

    def __len__(self):
        return len(self._whole) + len(self._cut)

    def __getitem__(self, i):
        if isinstance(i, slice):
            return [self[j] for j in range(*i.indices(len(self)))]
        n = len(self)
        if not -n <= i < n:
            raise IndexError(f"polygon index {i} out of range for {n} polygons")
        i %= n
        return self._whole[i] if i < len(self._whole) else self._cut[i - len(self._whole)]

    def flat(self):
        """All the polygons at once: ``(vertices (V, 3), counts (P,))``, in order."""
        whole = np.asarray(self._whole, np.float64).reshape(-1, 3)
        cut = [np.asarray(p, np.float64) for p in self._cut]
        counts = np.concatenate([np.full(len(self._whole), 3, np.int64),
                                 np.array([len(p) for p in cut], np.int64)])
        return np.concatenate([whole] + cut) if cut else whole, counts


@dataclass
class MeshArrays:
    """What the scene preparation takes from one mesh, per triangle of its fan
    triangulation: world vertices (F, 3, 3), unit vertex normals (F, 3, 3), unit face
    normals (F, 3), the stored colors / 255 at the vertices (F, 3, 3; None: the
    material's color), and the degenerate triangles (F,).  It depends on the mesh
    only, so :func:`mesh_arrays` keeps it with the mesh."""
    world: np.ndarray
    vertex_normals: np.ndarray
    normals: np.ndarray
    colors: object
    degenerate: np.ndarray


#: mesh -> (copies of the arrays it was made from, MeshArrays)
_MESH_ARRAYS = weakref.WeakKeyDictionary()


def _mesh_key(mesh):
    return (mesh.vertices, mesh.face_indices, mesh.face_offsets, mesh.normals, mesh.colors,
            mesh.color_on)


def _same(a, b):
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return (isinstance(a, np.ndarray) and isinstance(b, np.ndarray) and a.shape == b.shape
                and a.dtype == b.dtype and np.array_equal(a, b))
    return a == b


def mesh_arrays(mesh):
    """The :class:`MeshArrays` of ``mesh``, computed once and kept while the mesh's
    vertices, faces, normals and colors are equal to what they were (they are public
    arrays: a change in place is noticed by comparing them with copies).  Its arrays
    are read-only (several scenes share them)."""
    key = _mesh_key(mesh)
    kept = _MESH_ARRAYS.get(mesh)
    if kept is not None and all(_same(a, b) for a, b in zip(kept[0], key)):
        return kept[1]
    tri = mesh.triangulated()
    f = tri.face_indices.reshape(-1, 3)
    world = mesh.vertices[f]
    vertex = mesh.normals if mesh.normals is not None else averaged_normals(mesh)
    normals = _unit_rows(np.cross(world[:, 1] - world[:, 0], world[:, 2] - world[:, 0]))
    if mesh.colors is None:
        colors = None
    elif mesh.color_on == "vertex":
        colors = mesh.colors[f][..., :3] / 255.0
    else:
        colors = np.repeat(tri.colors[:, None, :3] / 255.0, 3, axis=1)
    arrays = MeshArrays(world, _unit_rows(vertex[f]), normals, colors,
                        ~(np.abs(normals).sum(axis=1) > 0))
    _MESH_ARRAYS[mesh] = (tuple(a.copy() if isinstance(a, np.ndarray) else a for a in key),
                          arrays)
    return arrays


#: The barycentrics of a triangle's own vertices, (n, 3, 2) rows for up to n triangles
#: (grown when a scene has more): kept, as every whole triangle's are the same.
_VERTEX_BARY = [np.zeros((0, 3, 2))]


def _vertex_bary(n):
    """(n, 3, 2) rows of (0, 0), (1, 0), (0, 1), C-contiguous (a view of a kept array:
    read it, do not write it)."""
    kept = _VERTEX_BARY[0]
    if len(kept) < n:
        kept = np.empty((max(n, 2 * len(kept)), 3, 2))
        kept[:] = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]
        _VERTEX_BARY[0] = kept
    return kept[:n]


def _joined(parts, shape):
    """One array of ``parts`` (the part itself when there is one: no copy)."""
    if len(parts) == 1:
        return parts[0]
    return np.concatenate(parts) if parts else np.zeros(shape)


def prepare(meshes, camera, width, height, materials=None, cull_back_faces=False):
    """The :class:`ScreenScene` of ``meshes`` seen by ``camera`` on a ``width`` x
    ``height`` device."""
    from .._kernels._threads import call_in_bands
    from .._kernels.screen import project_faces
    from ..clip import polygons3d
    from ..projection import Camera

    if not isinstance(camera, Camera):
        raise ArgumentTypeError(f"camera must be a scanline.Camera, got {type(camera).__name__}")
    meshes = _meshes(meshes)
    mats = _materials(materials, len(meshes))
    parts = [mesh_arrays(mesh) for mesh in meshes]
    world = _joined([p.world for p in parts], (0, 3, 3))
    nf = len(world)
    normals = _joined([p.normals for p in parts], (0, 3))
    vertex_normals = _joined([p.vertex_normals for p in parts], (0, 3, 3))
    vertex_colors = _joined([p.colors if p.colors is not None else
                             np.broadcast_to(np.asarray(mats[i].color, np.float64), p.world.shape)
                             for i, p in enumerate(parts)], (0, 3, 3))
    degenerate = _joined([p.degenerate for p in parts], (0,))
    owners = _joined([np.full(len(p.world), i, np.int64) for i, p in enumerate(parts)], (0,))

    clip, scale, offset = camera.mapping((0.0, 0.0, float(width - 1), float(height - 1)))
    view = camera.projection.orientation @ camera.view_matrix
    if camera.projection.kind == "perspective":
        toward = np.append(np.asarray(camera.projection.prp, np.float64), 1.0)
    else:
        toward = np.append(-_view_direction(camera), 0.0)
    back = np.empty(nf, np.bool_)
    inside = np.empty(nf, np.bool_)
    good = np.empty(nf, np.bool_)
    dev = np.empty((nf, 3, 3))
    inv_w = np.empty((nf, 3))
    planes = np.empty((nf, 4))
    call_in_bands(project_faces, 40 * nf, np.ascontiguousarray(world),
                  np.ascontiguousarray(view), toward, np.ascontiguousarray(clip),
                  np.ascontiguousarray(CLIP_VOLUME.planes),
                  np.ascontiguousarray(scale, np.float64),
                  np.ascontiguousarray(offset, np.float64), back, inside, good, dev, inv_w, planes)
    front = ~back
    culled = back if cull_back_faces else np.zeros(nf, bool)
    kept = ~culled & ~degenerate
    whole = kept & inside
    drawn = whole & good
    everything = bool(drawn.all())
    whole_faces = np.flatnonzero(whole)
    tface = [np.arange(nf, dtype=np.int64) if everything else np.flatnonzero(drawn)]
    tris = [dev if everything else dev[tface[0]]]
    tq = [inv_w if everything else inv_w[tface[0]]]
    eye_bary = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    bary = [_vertex_bary(len(tface[0]))]
    polygons, polygon_face = [], []
    cut = np.flatnonzero(kept & ~inside)
    if len(cut):
        w3 = world[cut]
        h = w3 @ clip[:3, :3].T + clip[:3, 3]                        # (K, 3, 3) ... + w
        hw = (w3 @ clip[3, :3] + clip[3, 3])[..., None]
        hom = np.concatenate([h, hw], axis=2)                       # (K, 3, 4)
        rows = np.concatenate([hom, np.broadcast_to(eye_bary, (len(cut), 3, 2))], axis=2)
        verts, counts = polygons3d(rows.reshape(-1, 6), CLIP_VOLUME,
                                   counts=np.full(len(cut), 3), homogeneous=True)
        starts = np.concatenate([[0], np.cumsum(counts)])
        for j in np.flatnonzero(counts >= 3):
            poly = verts[starts[j]:starts[j + 1]]
            k = len(poly)
            idx = np.stack([np.zeros(k - 2, int), np.arange(1, k - 1), np.arange(2, k)], 1)
            t_hom = poly[idx, :4]
            with np.errstate(divide="ignore", invalid="ignore"):
                q = 1.0 / t_hom[..., 3]
                t_dev = t_hom[..., :3] * q[..., None] * scale + offset
            ok = np.isfinite(t_dev).all(axis=(1, 2)) & (t_hom[..., 3] > 0).all(axis=1)
            tris.append(t_dev[ok])
            tq.append(q[ok])
            bary.append(poly[idx, 4:][ok])
            tface.append(np.full(int(ok.sum()), cut[j], np.int64))
            with np.errstate(divide="ignore", invalid="ignore"):
                polygons.append(poly[:, :3] / poly[:, 3:4] * scale + offset)
            polygon_face.append(cut[j])
    plane = np.full((nf, 4), np.nan)
    if len(whole_faces) == nf:
        plane = planes
    else:
        plane[whole_faces] = planes[whole_faces]
    if polygons:
        plane[polygon_face] = [_device_plane(p) for p in polygons]
    triangles = _joined(tris, (0, 3, 3))
    return ScreenScene(
        width=int(width), height=int(height),
        triangles=np.ascontiguousarray(triangles), inv_w=np.ascontiguousarray(_joined(tq, (0, 3))),
        bary=np.ascontiguousarray(_joined(bary, (0, 3, 2))),
        face=np.ascontiguousarray(_joined(tface, (0,)), np.int64),
        polygons=DevicePolygons(dev[whole_faces] if len(whole_faces) < nf else dev, polygons),
        polygon_face=np.concatenate([whole_faces, np.array(polygon_face, np.int64)]),
        face_mesh=owners, front=front, culled=culled, world=world, normals=normals,
        vertex_normals=vertex_normals, vertex_colors=vertex_colors,
        planes=plane, materials=mats, eye=_viewer(camera), camera=camera)


def _device_plane(poly):
    """A, B, C, D of the plane of device polygons (..., k, 3) by Newell's method, the
    normal toward +depth for a counterclockwise (front) polygon, i.e. C > 0 when the
    polygon runs counterclockwise in device x, y."""
    a = poly
    b = np.roll(poly, -1, axis=-2)
    n = np.stack([((a[..., 1] - b[..., 1]) * (a[..., 2] + b[..., 2])).sum(axis=-1),
                  ((a[..., 2] - b[..., 2]) * (a[..., 0] + b[..., 0])).sum(axis=-1),
                  ((a[..., 0] - b[..., 0]) * (a[..., 1] + b[..., 1])).sum(axis=-1)], axis=-1)
    d = -(n * poly.mean(axis=-2)).sum(axis=-1)
    return np.concatenate([n, d[..., None]], axis=-1)
