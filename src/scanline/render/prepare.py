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

from dataclasses import dataclass, field

import numpy as np

from ..clip.volumes import Volume
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
    polygons : list of ndarray (k, 3)
        The clipped device polygon (x, y, depth) of each face that is left, one per
        entry of ``polygon_face`` (convex: a clipped triangle).
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
    idx, off = mesh.face_indices, mesh.face_offsets
    owner = np.repeat(np.arange(mesh.face_count), np.diff(off))
    v = mesh.vertices
    # Newell's normal of each face
    nxt = np.arange(len(idx)) + 1
    nxt[off[1:] - 1] = off[:-1]
    a, b = v[idx], v[idx[nxt]]
    terms = np.stack([(a[:, 1] - b[:, 1]) * (a[:, 2] + b[:, 2]),
                      (a[:, 2] - b[:, 2]) * (a[:, 0] + b[:, 0]),
                      (a[:, 0] - b[:, 0]) * (a[:, 1] + b[:, 1])], axis=1)
    fn = np.zeros((mesh.face_count, 3))
    np.add.at(fn, owner, terms)
    fn = _unit_rows(fn)
    out = np.zeros_like(v)
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
    if isinstance(meshes, Mesh):
        return (meshes,)
    try:
        items = tuple(meshes)
    except TypeError:
        raise ArgumentTypeError(f"meshes must be a Mesh or a list of Mesh, got "
                                f"{type(meshes).__name__}") from None
    for i, m in enumerate(items):
        if not isinstance(m, Mesh):
            raise ArgumentTypeError(f"meshes[{i}] must be a scanline.mesh.Mesh, got "
                                    f"{type(m).__name__}")
    return items


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


def prepare(meshes, camera, width, height, materials=None, cull_back_faces=False):
    """The :class:`ScreenScene` of ``meshes`` seen by ``camera`` on a ``width`` x
    ``height`` device."""
    from ..clip import polygons3d
    from ..projection import Camera

    if not isinstance(camera, Camera):
        raise ArgumentTypeError(f"camera must be a scanline.Camera, got {type(camera).__name__}")
    meshes = _meshes(meshes)
    mats = _materials(materials, len(meshes))
    worlds, vnormals, vcolors, owners = [], [], [], []
    for i, mesh in enumerate(meshes):
        tri = mesh.triangulated()
        f = tri.face_indices.reshape(-1, 3)
        normals = mesh.normals if mesh.normals is not None else averaged_normals(mesh)
        worlds.append(mesh.vertices[f])
        vnormals.append(_unit_rows(normals[f]))
        if mesh.colors is None:
            vcolors.append(np.broadcast_to(mats[i].color, f.shape + (3,)))
        elif mesh.color_on == "vertex":
            vcolors.append(mesh.colors[f][..., :3] / 255.0)
        else:
            vcolors.append(np.repeat(tri.colors[:, None, :3] / 255.0, 3, axis=1))
        owners.append(np.full(len(f), i, np.int64))
    world = np.concatenate(worlds) if worlds else np.zeros((0, 3, 3))
    nf = len(world)
    normals = _unit_rows(np.cross(world[:, 1] - world[:, 0], world[:, 2] - world[:, 0]))
    back = back_faces(camera, world) if nf else np.zeros(0, bool)
    front = ~back
    culled = back if cull_back_faces else np.zeros(nf, bool)
    degenerate = ~(np.abs(normals).sum(axis=1) > 0)
    keep = np.flatnonzero(~culled & ~degenerate)

    clip, scale, offset = camera.mapping((0.0, 0.0, float(width - 1), float(height - 1)))
    h = world[keep] @ clip[:3, :3].T + clip[:3, 3]                  # (K, 3, 3) ... + w
    hw = (world[keep] @ clip[3, :3] + clip[3, 3])[..., None]
    hom = np.concatenate([h, hw], axis=2)                           # (K, 3, 4)
    inside = ((hom @ CLIP_VOLUME.planes.T) >= 0).all(axis=2)         # (K, 3)
    whole = inside.all(axis=1)
    eye_bary = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    tris = [hom[whole]]
    bary = [np.broadcast_to(eye_bary, (int(whole.sum()), 3, 2))]
    tface = [keep[whole]]
    polygons, polygon_face = [], []
    cut = np.flatnonzero(~whole)
    if len(cut):
        rows = np.concatenate([hom[cut], np.broadcast_to(eye_bary, (len(cut), 3, 2))], axis=2)
        verts, counts = polygons3d(rows.reshape(-1, 6), CLIP_VOLUME,
                                   counts=np.full(len(cut), 3), homogeneous=True)
        starts = np.concatenate([[0], np.cumsum(counts)])
        fan_t, fan_b, fan_f = [], [], []
        for j in np.flatnonzero(counts >= 3):
            poly = verts[starts[j]:starts[j + 1]]
            k = len(poly)
            idx = np.stack([np.zeros(k - 2, int), np.arange(1, k - 1), np.arange(2, k)], 1)
            fan_t.append(poly[idx, :4])
            fan_b.append(poly[idx, 4:])
            fan_f.append(np.full(k - 2, keep[cut[j]], np.int64))
            polygons.append(poly[:, :4])
            polygon_face.append(keep[cut[j]])
        if fan_t:
            tris.append(np.concatenate(fan_t))
            bary.append(np.concatenate(fan_b))
            tface.append(np.concatenate(fan_f))
    hom_t = np.concatenate(tris) if tris else np.zeros((0, 3, 4))
    w = hom_t[..., 3]
    with np.errstate(divide="ignore", invalid="ignore"):
        inv_w = 1.0 / w
        dev = hom_t[..., :3] * inv_w[..., None] * scale + offset
    good = np.isfinite(dev).all(axis=(1, 2)) & (w > 0).all(axis=1)
    face = np.concatenate(tface)[good] if tface else np.zeros(0, np.int64)
    # the clipped polygon of every face: the whole triangle's, or the clipped one's
    whole_faces = keep[whole]
    with np.errstate(divide="ignore", invalid="ignore"):
        whole_dev = hom[whole][..., :3] / hom[whole][..., 3:] * scale + offset
        cut_dev = [p[:, :3] / p[:, 3:] * scale + offset for p in polygons]
    all_polys = list(whole_dev) + cut_dev
    all_faces = np.concatenate([whole_faces, np.array(polygon_face, np.int64)])
    planes = np.full((nf, 4), np.nan)
    planes[whole_faces] = _device_plane(whole_dev)
    if cut_dev:
        planes[polygon_face] = [_device_plane(p) for p in cut_dev]
    from ..lighting.model import ViewerAtInfinity  # noqa: F401  (the eye's type)

    return ScreenScene(
        width=int(width), height=int(height),
        triangles=np.ascontiguousarray(dev[good]), inv_w=np.ascontiguousarray(inv_w[good]),
        bary=np.ascontiguousarray(np.concatenate(bary)[good] if bary else np.zeros((0, 3, 2))),
        face=np.ascontiguousarray(face, np.int64),
        polygons=all_polys, polygon_face=all_faces,
        face_mesh=np.concatenate(owners) if owners else np.zeros(0, np.int64),
        front=front, culled=culled, world=world, normals=normals,
        vertex_normals=np.concatenate(vnormals) if vnormals else np.zeros((0, 3, 3)),
        vertex_colors=np.ascontiguousarray(np.concatenate(vcolors)) if vcolors
        else np.zeros((0, 3, 3)),
        planes=planes, materials=mats, eye=_viewer(camera), camera=camera)


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
