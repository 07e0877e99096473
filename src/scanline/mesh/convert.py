"""Meshes of other libraries as :class:`~scanline.mesh.Mesh` (:meth:`Mesh.from_any`).

Recognized by the type's module and name -- so that none of those packages is
imported unless the object given is one of theirs:

==============================  ==============================================================
object                          taken
==============================  ==============================================================
``trimesh.Trimesh``             vertices, faces, vertex normals where trimesh holds them
                                (loaded or computed), vertex or face colors, texture uv, the
                                material's diffuse color
``trimesh.Scene``               every geometry placed by the scene graph's transforms, merged
                                (parts of different materials colored by them)
``meshio.Mesh``                 points, triangle/quad/polygon cells, point data normals,
                                colors and uv named as in PLY
``open3d...TriangleMesh``       vertices, triangles, vertex normals and colors when present
anything with ``vertices`` and  the two arrays (and ``normals``, ``colors``, ``uv`` when
``faces``                       the object has them)
==============================  ==============================================================
"""

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any, Callable, List, Literal, Optional, Sequence, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError
from .materials import MaterialRecord
from .mesh import Flat, Mesh, check_mesh_budget

if TYPE_CHECKING:
    from .files import MeshKeywords

#: The kinds of mesh objects :func:`kind` tells apart.
Kind = Literal["scanline", "trimesh", "trimesh scene", "meshio", "open3d", "arrays"]

# The objects of trimesh, meshio and Open3D are typed Any below: those libraries are
# untyped (and not imported here), their attributes read by name.

#: What :func:`from_any` takes, for its error message.
TAKES = ("a scanline.mesh.Mesh, a trimesh.Trimesh or trimesh.Scene, a meshio.Mesh, an "
         "Open3D TriangleMesh, or an object with vertices (V, 3) and faces arrays")


def kind(obj: object) -> Optional[Kind]:
    """Which kind of mesh object ``obj`` is: "scanline", "trimesh", "trimesh scene",
    "meshio", "open3d", "arrays", or None."""
    if isinstance(obj, Mesh):
        return "scanline"
    cls = type(obj)
    module, name = getattr(cls, "__module__", "") or "", cls.__name__
    top = module.split(".", 1)[0]
    if top == "trimesh" and name == "Trimesh":
        return "trimesh"
    if top == "trimesh" and name == "Scene":
        return "trimesh scene"
    if top == "meshio" and name == "Mesh":
        return "meshio"
    if top == "open3d" and name == "TriangleMesh":
        return "open3d"
    if isinstance(obj, (str, bytes, dict, np.ndarray)):
        return None
    if hasattr(obj, "vertices") and hasattr(obj, "faces"):
        return "arrays"
    return None


def _sized(argument: str, vertices: NDArray[Any],
           faces: Union[NDArray[Any], Sequence[Any]]) -> None:
    check_mesh_budget(argument, len(vertices), len(faces), int(np.size(faces)),
                      "a mesh converted from another library")


def _trimesh(obj: Any, name: Optional[str]) -> Mesh:
    vertices = np.asarray(obj.vertices, np.float64)
    faces = np.asarray(obj.faces, np.int64)
    _sized("mesh", vertices, faces)
    extra: "MeshKeywords" = {}
    # normals only where trimesh holds them (read from a file or computed before):
    # asking for them would compute the plain average, which the render does better
    cache = getattr(obj, "_cache", None)
    if cache is not None and "vertex_normals" in cache:
        extra["normals"] = np.asarray(obj.vertex_normals, np.float64)
    visual: Any = getattr(obj, "visual", None)
    visual_kind = getattr(visual, "kind", None)
    material = None
    if visual_kind == "vertex":
        extra["colors"], extra["color_on"] = np.asarray(visual.vertex_colors), "vertex"
    elif visual_kind == "face":
        extra["colors"], extra["color_on"] = np.asarray(visual.face_colors), "face"
    elif visual_kind == "texture":
        uv = getattr(visual, "uv", None)
        if uv is not None and len(uv) == len(vertices):
            extra["uv"] = np.asarray(uv, np.float64)[:, :2]
        material = _trimesh_material(getattr(visual, "material", None))
    mesh = Mesh(vertices, faces, name=name or None, **extra)
    mesh.material = material
    return mesh


def _trimesh_material(material: Any) -> Optional[MaterialRecord]:
    """A MaterialRecord of a trimesh SimpleMaterial (diffuse, specular, glossiness) or
    PBRMaterial (baseColorFactor)."""
    if material is None:
        return None
    color = getattr(material, "baseColorFactor", None)
    if color is None:
        color = getattr(material, "diffuse", None)
    if color is None:
        return None
    rgba = np.asarray(color, np.float64).reshape(-1)
    if rgba.size < 3 or not np.isfinite(rgba).all():
        return None
    if rgba.max() > 1:                  # trimesh keeps uint8 colors
        rgba = rgba / 255.0
    rgba = np.clip(rgba, 0, 1)
    r, g, b = rgba[:3].tolist()
    return MaterialRecord(getattr(material, "name", None) or "material", kd=(r, g, b),
                          d=float(rgba[3]) if rgba.size > 3 else 1.0)


def _trimesh_scene(obj: Any, name: Optional[str]) -> Mesh:
    from .files import joined

    parts: List[Mesh] = []
    for node in obj.graph.nodes_geometry:
        transform, geometry = obj.graph[node]
        part = obj.geometry.get(geometry)
        if kind(part) != "trimesh":
            continue                     # paths and point clouds have no faces
        mesh = _trimesh(part, f"{name}:{node}" if name else str(node))
        matrix = np.asarray(transform, np.float64)
        parts.append(mesh if np.array_equal(matrix, np.eye(4)) else mesh.transformed(matrix))
    if not parts:
        raise ArgumentTypeError("the trimesh.Scene holds no triangle meshes")
    return joined(parts, name)


def _meshio(obj: Any, name: Optional[str]) -> Mesh:
    from .files import ply_attributes, meshio_faces

    points = np.asarray(obj.points, np.float64)
    if points.ndim == 2 and points.shape[1] == 2:
        points = np.hstack([points, np.zeros((len(points), 1))])
    indices, sizes, _ = meshio_faces(obj)
    if not len(sizes):
        raise ArgumentTypeError("the meshio.Mesh has no triangle, quad or polygon cells")
    check_mesh_budget("mesh", len(points), len(sizes), len(indices),
                      "a mesh converted from meshio")
    extra = ply_attributes(obj.point_data, len(points), {}, len(sizes))
    return Mesh(points, Flat(indices, sizes), name=name, **extra)


def _open3d(obj: Any, name: Optional[str]) -> Mesh:
    vertices = np.asarray(obj.vertices, np.float64)
    faces = np.asarray(obj.triangles, np.int64)
    _sized("mesh", vertices, faces)
    extra: "MeshKeywords" = {}
    if getattr(obj, "has_vertex_normals", lambda: False)():
        extra["normals"] = np.asarray(obj.vertex_normals, np.float64)
    if getattr(obj, "has_vertex_colors", lambda: False)():
        colors = np.clip(np.asarray(obj.vertex_colors, np.float64), 0, 1)
        extra["colors"] = np.round(colors * 255).astype(np.uint8)
        extra["color_on"] = "vertex"
    return Mesh(vertices, faces, name=name, **extra)


def _arrays(obj: Any, name: Optional[str]) -> Mesh:
    vertices = np.asarray(obj.vertices)
    faces = obj.faces
    if isinstance(faces, np.ndarray) or not isinstance(faces, (list, tuple)):
        faces = np.asarray(faces)
    _sized("mesh", vertices.reshape(-1, 3) if vertices.size % 3 == 0 else vertices, faces)
    extra = {k: getattr(obj, k) for k in ("normals", "colors", "uv")
             if getattr(obj, k, None) is not None}
    return Mesh(vertices, faces, name=name, **extra)


def from_any(obj: object, name: Optional[str] = None) -> Mesh:
    """A :class:`~scanline.mesh.Mesh` of ``obj`` (the module docstring lists what is
    taken); a Mesh is returned as it is.

    Parameters
    ----------
    obj : object
        The mesh-like object.
    name : str, optional
        The new mesh's name.

    Returns
    -------
    Mesh

    Raises
    ------
    ArgumentTypeError
        For anything else, naming what works.

    Examples
    --------
    >>> import types
    >>> from scanline.mesh.convert import from_any
    >>> from_any(types.SimpleNamespace(vertices=[(0, 0, 0), (1, 0, 0), (0, 1, 0)],
    ...                                faces=[(0, 1, 2)]), name="triangle")
    <Mesh 'triangle': 3 vertices, 1 faces, 3 edges>
    """
    if isinstance(obj, Mesh):
        return obj
    what = kind(obj)
    if what is None:
        raise ArgumentTypeError(f"cannot make a mesh of {v._show(obj)} (type "
                                f"{type(obj).__module__}.{type(obj).__name__}): give {TAKES}")
    if name is not None and not isinstance(name, str):
        raise ArgumentTypeError(f"name must be a string or None, got {v._show(name)}")
    make: Callable[[Any, Optional[str]], Mesh] = {"trimesh": _trimesh, "trimesh scene": _trimesh_scene, "meshio": _meshio,
            "open3d": _open3d, "arrays": _arrays}[what]
    return make(obj, name)


def as_meshes(value: object, argument: str = "meshes", empty: bool = False) -> List[Mesh]:
    """``value`` -- one mesh object of any kind :func:`from_any` takes, or a list of
    them -- as a list of :class:`~scanline.mesh.Mesh` (``empty``: whether none is
    allowed).  Errors name ``argument``."""
    items = [value] if kind(value) is not None else None
    if items is None and isinstance(value, Iterable) \
            and not isinstance(value, (str, bytes, dict, np.ndarray)):
        items = list(value)
    if items is None or (not items and not empty):
        raise ArgumentTypeError(f"{argument} must be a mesh or a{'' if empty else ' non-empty'} "
                                f"list of meshes ({TAKES}), got {v._show(value)}")
    out: List[Mesh] = []
    for i, item in enumerate(items):
        if kind(item) is None:
            raise ArgumentTypeError(f"{argument}[{i}] is {v._show(item)}, not a mesh: give "
                                    f"{TAKES}")
        out.append(from_any(item))
    return out
