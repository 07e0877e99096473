"""Stage one of the 3-D pipeline, the preparation: meshes and a camera turned into the
screen-space scene every visible-surface method works on (:class:`ScreenScene`).

Steps (Hearn & Baker, chapters 12-14): every face is split into the triangles of a fan
from its first vertex (the *facets*, :mod:`scanline.screen.meshes`); the **back-face
test** V . N > 0 is made in viewing coordinates (section 13-2: V from the center of
projection to the facet, or the direction of projection of a parallel view; N the
outward normal), and with ``cull_back_faces`` the back facets are dropped; the facets
go to homogeneous clip coordinates and those that leave the view volume's depth range
are **clipped before the divide** (Sutherland-Hodgman against z >= 0, z <= w and a
guard band far outside the window, so nothing behind the eye is mirrored and no
coordinate grows without bound: the rasterizers clip to the frame buffer themselves,
and a face covering the whole view still reaches past every pixel center); then the
divide and the device mapping give device x, y and depth.  Each vertex carries its
1/w and its barycentric coordinates in its facet, which the rasterizers interpolate
perspective-correctly: any attribute of the face (normal, world position, color) is
then known at every pixel.

The same clipping serves polygons that a method makes in world coordinates (the
pieces of a BSP tree): :func:`device_polygons`.
"""

import math
from typing import TYPE_CHECKING, Any, Optional, Sequence, cast

import numpy as np
from numpy.typing import ArrayLike, DTypeLike, NDArray

from .. import _validate as v
from ..clip.volumes import Volume
from ..errors import ArgumentTypeError, ArgumentValueError
from .meshes import CREASE_ANGLE, mesh_arrays, meshes_list
from .polygons import flat_polygons
from .polygons import ScreenPolygons
from .scene import DevicePolygons, ScreenScene

if TYPE_CHECKING:
    from .._typing import Color
    from ..lighting.material import Material
    from ..mesh import Mesh
    from ..projection import Camera

F64 = NDArray[np.float64]
#: ``(clip (4, 4), scale (3,), offset (3,))``: world to clip, NDC to device.
Mapping = tuple[F64, F64, F64]

#: Bytes the pipeline holds per facet (its world, normal, color, device and clipping
#: arrays in the scene) and per pixel (the buffers of triangles, depths, facets and
#: labels the methods and the shading pass along): the memory budget's estimate.
FACET_BYTES = 640
PIXEL_BYTES = 48

#: Guard band: the clip volume reaches this many window widths beyond the window on
#: each side (device coordinates stay within about 2**20 for any real frame buffer).
GUARD = 256.0

#: The volume facets are clipped against, as homogeneous planes (a x + b y + c z + d w
#: >= 0): the depth range 0 <= z <= w and the guard band around the window.
CLIP_VOLUME = Volume(
    [(0, 0, 1, 0), (0, 0, -1, 1), (1, 0, 0, GUARD), (-1, 0, 0, 1 + GUARD),
     (0, 1, 0, GUARD), (0, -1, 0, 1 + GUARD)],
    ("front", "back", "left guard", "right guard", "below guard", "above guard"),
    "render clip volume")


def _materials(materials: Any, meshes: Sequence["Mesh"]) -> tuple["Material", ...]:
    """One Material per mesh: ``materials`` (one, or one per mesh), else each mesh's
    own ``material``, else the default Material."""
    from ..lighting.material import Material
    from ..mesh.materials import MaterialRecord

    n = len(meshes)
    if materials is None:
        default = Material()
        own = tuple(m.material if m.material is not None else default for m in meshes)
        mats = tuple(_from_record(m) if isinstance(m, MaterialRecord) else m for m in own)
        checked = []
        for i, m in enumerate(mats):
            if not isinstance(m, Material):
                raise ArgumentTypeError(f"meshes[{i}].material must be a sl.lighting.Material, "
                                        f"got {v._show(m)}")
            checked.append(m)
        return tuple(checked)
    if isinstance(materials, Material):
        return (materials,) * n
    if isinstance(materials, (str, bytes)) or not hasattr(materials, "__iter__"):
        raise ArgumentTypeError(f"materials must be one sl.lighting.Material or a list of {n} "
                                f"(one per mesh), got {v._show(materials)}")
    items = tuple(materials)
    if len(items) != n or not all(isinstance(m, Material) for m in items):
        raise ArgumentValueError(
            f"materials must be one sl.lighting.Material or a list of {n} (one per mesh), "
            f"got {len(items)} item(s)")
    return items


def _from_record(record: Any) -> "Material":
    """The Material of a mesh file's material record: the diffuse reflectance Kd as
    k_d = max(Kd) times the color Kd / max(Kd), the specular Ks likewise (k_s and the
    highlight color), Ns as the exponent, 1 - d as the transparency (Hearn & Baker,
    sections 14-2, 14-5); what the file leaves out, the Material's defaults."""
    from ..lighting.material import Material

    def split(rgb: ArrayLike) -> tuple[float, F64]:
        rgb = np.clip(np.asarray(rgb, np.float64), 0.0, 1.0)
        top = float(rgb.max())
        return top, (rgb / top if top > 0 else np.ones(3))

    kd, color = split(record.kd)
    extra: dict[str, Any] = {}
    if record.ks is not None:
        extra["ks"], extra["specular_color"] = split(record.ks)
    if record.ns is not None:
        extra["shininess"] = record.ns
    # Material takes linear reals (3,) as color (linear_color), though its annotation
    # says Color only: the array goes through as it is
    return Material(kd=kd, color=cast("Color", color),
                    transparency=min(max(1.0 - record.d, 0.0), 1.0), **extra)


def _given_colors(colors: Any, sizes: Sequence[int]) -> F64:
    """``colors`` (one color, one per mesh, or one per face of all the meshes) as
    stored values / 255 per face (F, 3)."""
    from ..color.spec import rgba

    total = int(sum(sizes))
    if isinstance(colors, (str, tuple)) or (isinstance(colors, np.ndarray) and colors.ndim == 1):
        colors = [colors]
    items = list(colors)
    if len(items) == 1 and len(sizes) != 1:
        items = items * len(sizes)
    per_mesh = len(items) == len(sizes) and len(sizes) != total
    if len(items) != total and not per_mesh:
        raise ArgumentValueError(
            f"colors holds {len(items)} colors; give one color, one per mesh ({len(sizes)}) "
            f"or one per face ({total})")
    unique: dict[tuple[Any, ...], F64] = {}
    rows = np.empty((len(items), 3))
    for i, c in enumerate(items):
        key = (type(c), c) if isinstance(c, (str, int)) else \
            (type(c), tuple(np.asarray(c).ravel().tolist()))
        if key not in unique:
            unique[key] = np.asarray(rgba(c, f"colors[{i}]")[:3], np.float64) / 255.0
        rows[i] = unique[key]
    return np.repeat(rows, sizes, axis=0) if per_mesh else rows


def _viewer(camera: "Camera") -> Any:
    from ..lighting.model import at_infinity

    eye = camera.eye
    if eye is not None:
        return np.array(eye)
    toward = _view_direction(camera)
    inv = np.linalg.inv(camera.projection.orientation @ camera.view_matrix)[:3, :3]
    return at_infinity(-(inv @ toward))


def _view_direction(camera: "Camera") -> F64:
    """The viewing direction of a parallel projection in viewing coordinates: along
    -z_v, sheared by the projection's (a, b)."""
    a, b = camera.projection.shear
    return np.array([a, b, -1.0])


#: The barycentrics of a triangle's own vertices, (n, 3, 2) rows for up to n triangles
#: (grown when a scene has more): kept, as every whole triangle's are the same.
_VERTEX_BARY = [np.zeros((0, 3, 2))]


def _vertex_bary(n: int) -> F64:
    """(n, 3, 2) rows of (0, 0), (1, 0), (0, 1), C-contiguous (a view of a kept array:
    read it, do not write it)."""
    kept = _VERTEX_BARY[0]
    if len(kept) < n:
        kept = np.empty((max(n, 2 * len(kept)), 3, 2))
        kept[:] = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]
        _VERTEX_BARY[0] = kept
    return kept[:n]


def _joined(parts: Sequence[NDArray[Any]], shape: tuple[int, ...],
            dtype: DTypeLike = np.float64) -> NDArray[Any]:
    """One array of ``parts`` (the part itself when there is one: no copy; an empty
    one of ``shape`` and ``dtype`` when there is none)."""
    if len(parts) == 1:
        return parts[0]
    return np.concatenate(parts) if parts else np.zeros(shape, dtype)


def camera_mapping(camera: "Camera", width: int, height: int) -> Mapping:
    """``(clip, scale, offset)``: the world -> homogeneous clip matrix and the NDC ->
    device mapping of ``camera`` on a ``width`` x ``height`` device."""
    from ..projection import Camera

    if not isinstance(camera, Camera):
        raise ArgumentTypeError(f"camera must be a scanline.Camera, got {v._show(camera)}")
    return camera.mapping(camera._device_box(width, height))


def _clipped(rows: F64, counts: NDArray[np.int64], scale: F64,
             offset: F64) -> tuple[F64, F64, NDArray[np.int64]]:
    """Homogeneous polygons (V, 4 + attributes) clipped against :data:`CLIP_VOLUME`,
    divided and mapped to the device: ``(device (V', 3 + attributes), inverse w (V',),
    counts (P,))``, polygons with nothing left given count 0."""
    from ..clip import polygons3d

    verts, counts = polygons3d(rows, CLIP_VOLUME, counts=counts, homogeneous=True)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        q = 1.0 / verts[:, 3]
        dev = np.concatenate([verts[:, :3] * q[:, None] * scale + offset, verts[:, 4:]], axis=1)
    return dev, q, counts


def device_polygons(vertices: ArrayLike, counts: ArrayLike, labels: ArrayLike, camera: "Camera",
                    width: int, height: int,
                    mapping: Optional[Mapping] = None) -> ScreenPolygons:
    """World polygons (flat form: ``vertices`` (V, 3), ``counts`` (P,)) through
    ``camera`` onto a ``width`` x ``height`` device, clipped as the scene's facets are
    (:data:`CLIP_VOLUME`, before the divide), as :class:`ScreenPolygons` whose face is
    each polygon's entry of ``labels`` (P,), in the given order; those nothing is left
    of, or seen edge-on, are dropped.  ``mapping``: a scene's own ``(clip, scale,
    offset)`` (:attr:`ScreenScene.mapping`) instead of the camera's on this device.

    Parameters
    ----------
    vertices : array_like
        (V, 3) world vertices, polygon after polygon.
    counts : array_like of int
        (P,) vertices per polygon.
    labels : array_like of int
        (P,) the ``face`` each polygon gets.
    camera : Camera
        The camera.
    width, height : int
        The device's size in pixels.
    mapping : tuple, optional
        A scene's ``(clip, scale, offset)``.

    Returns
    -------
    ScreenPolygons
        The clipped device polygons left.

    Examples
    --------
    >>> import scanline as sl
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
    >>> square = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
    >>> sp = sl.screen.device_polygons(square, [4], [7], cam, 16, 16)
    >>> len(sp), sp.face.tolist(), sp.counts.tolist()
    (1, [7], [4])
    """
    clip, scale, offset = camera_mapping(camera, width, height) if mapping is None else mapping
    points = np.asarray(vertices, np.float64)
    hom = np.hstack([points, np.ones((len(points), 1))]) @ clip.T
    dev, _, out = _clipped(np.ascontiguousarray(hom), np.asarray(counts, np.int64), scale,
                           offset)
    whole = out >= 3
    return flat_polygons(dev[np.repeat(whole, out)], out[whole],
                         np.asarray(labels, np.int64)[whole], width, height)


def prepare(meshes: Any, camera: "Camera", width: int, height: int, materials: Any = None,
            colors: Any = None, cull_back_faces: bool = False,
            crease_angle: Optional[float] = CREASE_ANGLE) -> ScreenScene:
    """The :class:`ScreenScene` of ``meshes`` seen by ``camera`` on a ``width`` x
    ``height`` device.

    Parameters
    ----------
    meshes : Mesh or list of Mesh
        Or any mesh object :meth:`~scanline.mesh.Mesh.from_any` takes.
    camera : Camera
        The camera (viewing coordinates, projection and viewport).
    width, height : int
        The device's size in pixels.
    materials : Material or list of Material (one per mesh), optional
        Else each mesh's own material (a mesh file's material record is converted:
        :func:`_from_record`), else the default Material.
    colors : color, or list of colors (one per mesh or one per face), optional
        The surface color S_d of the faces, instead of the meshes' own colors (else
        the materials' colors).
    cull_back_faces : bool
        Drop the facets turned away from the viewer (Hearn & Baker, section 13-2).
    crease_angle : float or None
        Where a mesh gives no vertex normals, faces meeting at a sharper angle
        (radians) keep their own normals at the shared vertex (default 30 degrees);
        None: the plain average of every face around the vertex (Hearn & Baker 14-5).

    Returns
    -------
    ScreenScene
        The screen-space scene.

    Raises
    ------
    ArgumentTypeError
        For a camera that is not one, meshes or materials of the wrong type.
    ArgumentValueError
        For a bad size, colors, materials count or crease angle.
    MemoryBudgetError
        When the facets or the per-pixel buffers pass the memory budget.

    Examples
    --------
    >>> import scanline as sl
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
    >>> scene = sl.screen.prepare(sl.mesh.cube(), cam, 16, 16, cull_back_faces=True)
    >>> int(scene.culled.sum()), int(scene.whole.sum())   # 10 facets turned away or edge-on
    (10, 2)
    """
    from .._kernels._threads import call_in_bands
    from .._kernels.screen import project_faces, project_points

    from ..budget import check

    width = v.positive_int("width", width)
    height = v.positive_int("height", height)
    clip, scale, offset = camera_mapping(camera, width, height)
    meshes = meshes_list(meshes, empty=True)
    facets = sum(len(m.face_indices) - 2 * m.face_count for m in meshes)
    check(FACET_BYTES * facets, "meshes", f"{facets:,} triangles prepared for rendering",
          "render fewer or coarser meshes")
    check(PIXEL_BYTES * width * height, "width x height",
          f"the per-pixel buffers of a {width} x {height} render", "render a smaller image")
    mats = _materials(materials, meshes)
    if crease_angle is not None:
        crease_angle = v.number("crease_angle", crease_angle)
        if not 0 <= crease_angle <= math.pi:
            raise ArgumentValueError(f"crease_angle must be an angle in 0..pi radians (or None: "
                                     f"no creases), got {v._show(crease_angle)}")
    parts = [mesh_arrays(mesh, crease_angle) for mesh in meshes]
    sizes = [len(p.face_normals) for p in parts]
    face_mesh = _joined([np.full(n, i, np.int64) for i, n in enumerate(sizes)], (0,), np.int64)
    face_base = np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)
    facet_face = _joined([p.facet_face + face_base[i] if i else p.facet_face
                          for i, p in enumerate(parts)], (0,), np.int64)
    if colors is not None:
        face_colors = _given_colors(colors, sizes)
        vertex_colors = np.repeat(face_colors[facet_face][:, None], 3, axis=1)
    else:
        face_colors = _joined([p.face_colors if p.face_colors is not None else
                               np.broadcast_to(np.asarray(mats[i].color, np.float64), (n, 3))
                               for i, (p, n) in enumerate(zip(parts, sizes))], (0, 3))
        vertex_colors = _joined([p.colors if p.colors is not None else
                                 np.broadcast_to(np.asarray(mats[i].color, np.float64),
                                                 p.world.shape)
                                 for i, p in enumerate(parts)], (0, 3, 3))
    world = _joined([p.world for p in parts], (0, 3, 3))
    nf = len(world)
    degenerate = _joined([p.degenerate for p in parts], (0,), bool)

    view = camera.projection.orientation @ camera.view_matrix
    if camera.projection.kind == "perspective":
        toward = np.append(np.asarray(camera.projection.prp, np.float64), 1.0)
    else:
        toward = np.append(-_view_direction(camera), 0.0)
    # each vertex projected once (project_points), then each face from its corners
    points = _joined([p.points for p in parts], (0, 3))
    point_base = np.cumsum([0] + [len(p.points) for p in parts])
    corners = _joined([p.corners + point_base[i] if i else p.corners
                       for i, p in enumerate(parts)], (0, 3), np.int64)
    nv = len(points)
    eye = np.empty((nv, 3))
    pdev = np.empty((nv, 3))
    pinv_w = np.empty(nv)
    pinside = np.empty(nv, np.bool_)
    pgood = np.empty(nv, np.bool_)
    call_in_bands(project_points, 40 * nv, points, np.ascontiguousarray(view),
                  np.ascontiguousarray(clip), np.ascontiguousarray(CLIP_VOLUME.planes),
                  np.ascontiguousarray(scale, np.float64),
                  np.ascontiguousarray(offset, np.float64), eye, pdev, pinv_w, pinside, pgood)
    back = np.empty(nf, np.bool_)
    inside = np.empty(nf, np.bool_)
    good = np.empty(nf, np.bool_)
    dev = np.empty((nf, 3, 3))
    inv_w = np.empty((nf, 3))
    planes = np.empty((nf, 4))
    call_in_bands(project_faces, 20 * nf, corners, eye, pdev, pinv_w, pinside, pgood, toward,
                  back, inside, good, dev, inv_w, planes)
    culled = back if cull_back_faces else np.zeros(nf, bool)
    kept = ~culled & ~degenerate
    whole = kept & inside
    drawn = whole & good
    everything = bool(drawn.all())
    whole_facets = np.flatnonzero(whole)
    tfacet = [np.arange(nf, dtype=np.int64) if everything else np.flatnonzero(drawn)]
    tris = [dev if everything else dev[tfacet[0]]]
    tq = [inv_w if everything else inv_w[tfacet[0]]]
    bary = [_vertex_bary(len(tfacet[0]))]
    polygons, polygon_facet = [], []
    cut = np.flatnonzero(kept & ~inside)
    if len(cut):
        w3 = world[cut]
        h = w3 @ clip[:3, :3].T + clip[:3, 3]                        # (K, 3, 3) ... + w
        hw = (w3 @ clip[3, :3] + clip[3, 3])[..., None]
        own = np.broadcast_to(np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]), (len(cut), 3, 2))
        rows = np.concatenate([h, hw, own], axis=2).reshape(-1, 6)
        out, q, counts = _clipped(rows, np.full(len(cut), 3), scale, offset)
        starts = np.concatenate([[0], np.cumsum(counts)])
        for j in np.flatnonzero(counts >= 3):
            poly = out[starts[j]:starts[j + 1]]
            pq = q[starts[j]:starts[j + 1]]
            k = len(poly)
            idx = np.stack([np.zeros(k - 2, int), np.arange(1, k - 1), np.arange(2, k)], 1)
            ok = np.isfinite(poly[idx, :3]).all(axis=(1, 2)) & (pq[idx] > 0).all(axis=1)
            tris.append(poly[idx, :3][ok])
            tq.append(pq[idx][ok])
            bary.append(poly[idx, 3:][ok])
            tfacet.append(np.full(int(ok.sum()), cut[j], np.int64))
            polygons.append(poly[:, :3])
            polygon_facet.append(cut[j])
    plane = planes if len(whole_facets) == nf else np.full((nf, 4), np.nan)
    if len(whole_facets) < nf:
        plane[whole_facets] = planes[whole_facets]
    if polygons:
        plane[polygon_facet] = [_device_plane(p) for p in polygons]
    return ScreenScene(
        width=width, height=height, camera=camera, mapping=(clip, scale, offset),
        eye=_viewer(camera), materials=mats,
        face_mesh=face_mesh,
        face_normals=_joined([p.face_normals for p in parts], (0, 3)),
        face_centroids=_joined([p.face_centroids for p in parts], (0, 3)),
        face_colors=face_colors,
        face_planar=_joined([p.face_planar for p in parts], (0,), bool),
        facet_face=facet_face, whole=drawn, world=world,
        normals=_joined([p.normals for p in parts], (0, 3)),
        vertex_normals=_joined([p.vertex_normals for p in parts], (0, 3, 3)),
        vertex_colors=vertex_colors, front=~back, culled=culled, planes=plane,
        triangles=np.ascontiguousarray(_joined(tris, (0, 3, 3))),
        inv_w=np.ascontiguousarray(_joined(tq, (0, 3))),
        bary=np.ascontiguousarray(_joined(bary, (0, 3, 2))),
        facet=np.ascontiguousarray(_joined(tfacet, (0,)), np.int64),
        polygons=DevicePolygons(dev[whole_facets] if len(whole_facets) < nf else dev, polygons),
        polygon_facet=np.concatenate([whole_facets, np.array(polygon_facet, np.int64)]),
        uv=None if all(p.uv is None for p in parts) else _joined(
            [np.full((len(p.world), 3, 2), np.nan) if p.uv is None else p.uv for p in parts],
            (0, 3, 2)))


def screen_polygons(meshes: Any, camera: "Camera", width: int, height: int,
                    cull_back_faces: bool = False) -> ScreenPolygons:
    """The faces of ``meshes`` seen through ``camera`` on a ``width`` x ``height``
    device as :class:`ScreenPolygons`, ready for the methods of
    :mod:`scanline.visible`: the prepared scene's clipped facets (:func:`prepare`),
    each labeled with its face (``face``: faces numbered mesh after mesh).

    Parameters
    ----------
    meshes : Mesh or list of Mesh
        The meshes (see :func:`prepare`).
    camera : Camera
        The camera.
    width, height : int
        The device's size in pixels.
    cull_back_faces : bool
        Drop the facets turned away from the viewer.

    Returns
    -------
    ScreenPolygons
        One polygon per face taken whole, else per clipped facet, labeled with its face.

    Examples
    --------
    >>> import scanline as sl
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
    >>> sp = sl.screen.screen_polygons(sl.mesh.cube(), cam, 16, 16, cull_back_faces=True)
    >>> len(sp), sp.counts.tolist()            # the front face, whole: one quadrilateral
    (1, [4])
    """
    import dataclasses

    scene = prepare(meshes, camera, width, height, cull_back_faces=cull_back_faces)
    sp = scene.screen_polygons
    return dataclasses.replace(sp, face=scene.facet_face[sp.face])


def _device_plane(poly: F64) -> F64:
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
