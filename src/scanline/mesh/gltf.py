"""glTF 2.0 meshes (Khronos Group, "glTF 2.0 Specification", 2021): ``.gltf`` (JSON with
external or data-URI buffers) and ``.glb`` (binary), read and written with pygltflib.

Reading walks the default scene's node hierarchy (section 3.5): each node's local
transformation is its ``matrix`` (column-major) or T R S (translation, rotation
quaternion, scale), composed with its parents' (world = parent world x local), and
every triangle primitive (``mode`` 4, section 3.7.2.1) of each node's mesh becomes a
:class:`~scanline.mesh.Mesh` moved into world space: ``POSITION``, ``NORMAL``,
``TEXCOORD_0`` (v flipped: glTF's v = 0 is the image's top, the mesh's its bottom)
and ``COLOR_0`` (vertex colors), ``indices`` (or none: the vertices in order), and its
material's ``pbrMetallicRoughness.baseColorFactor`` as the diffuse color (alpha as
opacity) with ``baseColorTexture`` kept as a reference
(:class:`~scanline.mesh.materials.MaterialRecord`).  Points, lines, strips and fans
(modes 0-3, 5, 6) are skipped with a warning.

Accessors are read with numpy from their buffer views (section 3.6), every offset,
stride and count checked against the view's and the buffer's length first: a
truncated buffer or a lying accessor is a
:class:`~scanline.mesh.files.MeshFileError` naming the accessor.
"""

import base64
import math
import os
import warnings
from typing import TYPE_CHECKING, Any, Dict, List, NoReturn, Optional, Sequence, Set, Tuple

import numpy as np
from numpy.typing import NDArray

from ..errors import ArgumentValueError
from ..transform3d.quaternion import Quaternion
from .materials import MaterialRecord
from .mesh import Mesh, check_mesh_budget

if TYPE_CHECKING:
    from pygltflib import GLTF2, Node, Primitive

    from .files import MeshKeywords

#: numpy dtypes of glTF's component types (section 3.6.2.2).
COMPONENTS: Dict[int, type[np.number[Any]]] = {5120: np.int8, 5121: np.uint8, 5122: np.int16, 5123: np.uint16,
              5125: np.uint32, 5126: np.float32}

#: Components of each accessor type.
TYPES = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}

#: Extensions a file may require that change nothing read here (material and
#: texture extensions: the base color stays).
SUPPORTED_EXTENSIONS = ("KHR_materials_unlit", "KHR_materials_emissive_strength",
                        "KHR_mesh_quantization")

#: Deepest node hierarchy followed.
MAX_DEPTH = 256


def _parse(data: bytes, filename: str) -> Tuple["GLTF2", Optional[bytes]]:
    """The pygltflib document of ``data`` and its binary chunk (None for .gltf)."""
    import pygltflib

    from .files import MeshFileError

    def fail(message: str) -> NoReturn:
        raise MeshFileError(message, file=filename)

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            if data[:4] == b"glTF":
                if len(data) < 20:
                    fail("the GLB file is truncated: it has no JSON chunk")
                length = int.from_bytes(data[8:12], "little")
                if length > len(data):
                    fail(f"the GLB header announces {length:,} bytes, but the file has "
                         f"{len(data):,}: it is truncated")
                doc = pygltflib.GLTF2.load_from_bytes(data)
                blob = doc.binary_blob()
            else:
                doc = pygltflib.GLTF2.from_json(data.decode("utf-8"))
                blob = None
    except MeshFileError:
        raise
    except UnicodeDecodeError:
        fail("the file is not a readable glTF file (its JSON is not UTF-8 text)")
    except Exception as error:      # noqa: BLE001 - json, struct, dataclasses_json errors
        text = str(error).strip().splitlines()[0] if str(error).strip() else type(error).__name__
        fail(f"the file is not a readable glTF file ({text[:200]})")
    if doc is None or not isinstance(doc.accessors, list):
        fail("the file is not a readable glTF file (no glTF document)")
    required = [e for e in (doc.extensionsRequired or []) if e not in SUPPORTED_EXTENSIONS]
    if required:
        fail(f"the file requires the extension(s) {', '.join(map(str, required))}, which "
             "scanline does not decode (compressed geometry: export it uncompressed)")
    return doc, blob


class _Buffers:
    """The document's buffers, read on first use: the GLB binary chunk, a data URI,
    or a file beside the document (read with the mesh-file guards)."""

    def __init__(self, doc: "GLTF2", blob: Optional[bytes], filename: str,
                 max_bytes: int) -> None:
        self.doc, self.blob, self.filename, self.max_bytes = doc, blob, filename, max_bytes
        self.cache: Dict[int, bytes] = {}

    def __call__(self, index: object, where: str) -> bytes:
        from .files import MeshFileError, read_regular_file

        if isinstance(index, int) and index in self.cache:
            return self.cache[index]
        buffers = self.doc.buffers or []
        if not isinstance(index, int) or not 0 <= index < len(buffers):
            raise MeshFileError(f"{where} refers to buffer {index!r}; the file has "
                                f"{len(buffers)}", file=self.filename)
        uri = buffers[index].uri
        if uri is None:
            if self.blob is None or index != 0:
                raise MeshFileError(f"buffer {index} has no data (no uri and no GLB binary "
                                    "chunk)", file=self.filename)
            data: bytes = self.blob
        elif uri.startswith("data:"):
            try:
                data = base64.b64decode(uri.split(",", 1)[1], validate=False)
            except (IndexError, ValueError):
                raise MeshFileError(f"buffer {index}'s data URI is not base64 data",
                                    file=self.filename) from None
        else:
            from urllib.parse import unquote

            path = os.path.join(os.path.dirname(os.path.abspath(self.filename)), unquote(uri))
            data = read_regular_file(path, self.max_bytes)
        declared = buffers[index].byteLength
        if isinstance(declared, int) and len(data) < declared:
            raise MeshFileError(f"buffer {index} holds {len(data):,} bytes, less than its "
                                f"byteLength {declared:,}: it is truncated", file=self.filename)
        self.cache[index] = data
        return data


def _accessor(doc: "GLTF2", buffers: _Buffers, index: object, filename: str,
              kinds: Optional[Sequence[str]] = None) -> NDArray[np.float64]:
    """Accessor ``index`` as a (count, components) array (normalized integers scaled
    to 0..1), every offset checked against its view and buffer."""
    from .files import MeshFileError

    where = f"accessor {index}"

    def fail(message: str) -> NoReturn:
        raise MeshFileError(f"{where}: {message}", file=filename)

    accessors = doc.accessors or []
    if not isinstance(index, int) or not 0 <= index < len(accessors):
        raise MeshFileError(f"a primitive refers to accessor {index!r}; the file has "
                            f"{len(accessors)}", file=filename)
    acc = accessors[index]
    dtype = COMPONENTS.get(acc.componentType)
    width = TYPES.get(acc.type)
    if dtype is None or width is None:
        fail(f"component type {acc.componentType!r} / type {acc.type!r} is not a glTF "
             "accessor type")
    if kinds is not None and acc.type not in kinds:
        fail(f"has type {acc.type}, expected {' or '.join(kinds)}")
    count = acc.count
    if not isinstance(count, int) or count < 0:
        fail(f"count {count!r} is not a whole number")
    if acc.sparse is not None:
        fail("sparse accessors are not supported")
    itemsize = np.dtype(dtype).itemsize
    element = itemsize * width
    if acc.bufferView is None:
        fail("has no buffer view (an accessor of zeros): not supported")
    views = doc.bufferViews or []
    if not isinstance(acc.bufferView, int) or not 0 <= acc.bufferView < len(views):
        fail(f"refers to buffer view {acc.bufferView!r}; the file has {len(views)}")
    view = views[acc.bufferView]
    data = buffers(view.buffer, f"buffer view {acc.bufferView}")
    v_off, v_len = view.byteOffset or 0, view.byteLength
    a_off = acc.byteOffset or 0
    stride = view.byteStride or element
    if not all(isinstance(x, int) and x >= 0 for x in (v_off, v_len, a_off, stride)):
        fail("its buffer view's offsets, length or stride are not whole numbers")
    if v_off + v_len > len(data):
        fail(f"its buffer view {acc.bufferView} reaches byte {v_off + v_len:,} of buffer "
             f"{view.buffer}, which has {len(data):,}: the buffer is truncated")
    if stride < element:
        fail(f"its byte stride {stride} is less than an element's {element} bytes")
    need = a_off + (stride * (count - 1) + element if count else 0)
    if need > v_len:
        fail(f"{count:,} elements from byte {a_off:,} need {need:,} bytes of buffer view "
             f"{acc.bufferView}, which has {v_len:,}: the accessor is truncated or lies")
    check_mesh_budget("path", count, 0, count * width // 2,
                      f"{where} of the mesh file {filename!r}", hint="use a smaller mesh file")
    raw = np.ndarray((count, width), np.dtype(dtype).newbyteorder("<"), buffer=data,
                     offset=v_off + a_off, strides=(stride, itemsize))
    out: NDArray[np.float64] = raw.astype(np.float64) \
        if dtype is np.float32 or not acc.normalized else \
        np.maximum(raw / float(np.iinfo(raw.dtype).max), -1.0)
    if dtype is np.float32 and not np.isfinite(out).all():
        fail("holds values that are not finite numbers (NaN or infinity)")
    return out


def _indices(doc: "GLTF2", buffers: _Buffers, index: int, filename: str) -> NDArray[np.int64]:
    from .files import MeshFileError

    acc = _accessor(doc, buffers, index, filename, ("SCALAR",))
    if doc.accessors[index].componentType not in (5121, 5123, 5125):
        raise MeshFileError(f"accessor {index}: indices must be unsigned integers",
                            file=filename)
    return acc[:, 0].astype(np.int64)


def _local(node: "Node", i: int, filename: str) -> NDArray[np.float64]:
    """A node's local 4 x 4 transformation: its matrix (column-major) or T R S."""
    from .files import MeshFileError

    try:
        if node.matrix is not None:
            m = np.asarray(node.matrix, np.float64)
            if m.shape != (16,):
                raise ValueError
            m = m.reshape(4, 4).T
        else:
            t = np.asarray(node.translation if node.translation is not None else (0, 0, 0),
                           np.float64).reshape(3)
            xyzw = np.asarray(node.rotation if node.rotation is not None
                              else (0, 0, 0, 1), np.float64).reshape(4)
            s = np.asarray(node.scale if node.scale is not None else (1, 1, 1),
                           np.float64).reshape(3)
            try:
                r = Quaternion.from_xyzw(xyzw, "rotation").matrix3()
            except ArgumentValueError as error:     # zero or not finite
                raise MeshFileError(f"node {i}: {error}", file=filename) from None
            m = np.eye(4)
            m[:3, :3] = r * s
            m[:3, 3] = t
    except MeshFileError:
        raise
    except (TypeError, ValueError):
        raise MeshFileError(f"node {i}: its matrix or translation/rotation/scale are not "
                            "16, 3, 4 and 3 numbers", file=filename) from None
    if not np.isfinite(m).all():
        raise MeshFileError(f"node {i}: its transformation is not finite", file=filename)
    return m


def _instances(doc: "GLTF2", filename: str
               ) -> List[Tuple[object, NDArray[np.float64], Optional[int]]]:
    """(mesh index, world matrix, node) of every node with a mesh in the default scene
    (or, without scenes, under every root node), parents before children."""
    from .files import MeshFileError

    nodes = doc.nodes or []
    if doc.scenes:
        scene = doc.scene if isinstance(doc.scene, int) and 0 <= doc.scene < len(doc.scenes) \
            else 0
        roots = list(doc.scenes[scene].nodes or [])
    else:
        children = {c for n in nodes for c in (n.children or [])}
        roots = [i for i in range(len(nodes)) if i not in children]
    out: List[Tuple[object, NDArray[np.float64], Optional[int]]] = []
    seen: Set[int] = set()
    stack: List[Tuple[object, NDArray[np.float64], int]] = \
        [(r, np.eye(4), 0) for r in reversed(roots)]
    while stack:
        i, parent, depth = stack.pop()
        if not isinstance(i, int) or not 0 <= i < len(nodes):
            raise MeshFileError(f"the scene refers to node {i!r}; the file has {len(nodes)}",
                                file=filename)
        if i in seen or depth > MAX_DEPTH:
            raise MeshFileError(f"node {i} is reached twice: the node hierarchy has a cycle or "
                                "is too deep", file=filename)
        seen.add(i)
        world = parent @ _local(nodes[i], i, filename)
        if nodes[i].mesh is not None:
            out.append((nodes[i].mesh, world, i))
        stack.extend((c, world, depth + 1) for c in reversed(nodes[i].children or []))
    if not out and not doc.scenes and doc.meshes:     # meshes without nodes
        out = [(m, np.eye(4), None) for m in range(len(doc.meshes))]
    return out


def _material(doc: "GLTF2", index: object, filename: str) -> Optional[MaterialRecord]:
    materials = doc.materials or []
    if index is None or not isinstance(index, int) or not 0 <= index < len(materials):
        return None
    mat = materials[index]
    pbr = mat.pbrMetallicRoughness
    factor = (pbr.baseColorFactor if pbr is not None and pbr.baseColorFactor else
              [1.0, 1.0, 1.0, 1.0])
    try:
        rgba = [min(max(float(c), 0.0), 1.0) for c in factor][:4] + [1.0] * (4 - len(factor))
    except (TypeError, ValueError):
        rgba = [1.0, 1.0, 1.0, 1.0]
    if not all(math.isfinite(c) for c in rgba):
        rgba = [1.0, 1.0, 1.0, 1.0]
    texture = None
    if pbr is not None and pbr.baseColorTexture is not None:
        t = pbr.baseColorTexture.index
        textures, images = doc.textures or [], doc.images or []
        source = textures[t].source if isinstance(t, int) and 0 <= t < len(textures) else None
        if isinstance(source, int) and 0 <= source < len(images):
            uri = images[source].uri
            texture = (os.path.join(os.path.dirname(os.path.abspath(filename)), uri)
                       if uri and not uri.startswith("data:") else f"image {source}")
    return MaterialRecord(mat.name or f"material {index}", kd=(rgba[0], rgba[1], rgba[2]),
                          d=rgba[3], map_kd=texture)


def gltf_meshes(data: bytes, filename: str, name: str, max_bytes: int) -> List[Mesh]:
    """One Mesh per triangle primitive of every mesh node of the default scene, in
    world coordinates, with its material (module docstring)."""
    from .files import MeshFileError, MeshFileWarning

    doc, blob = _parse(data, filename)
    buffers = _Buffers(doc, blob, filename, max_bytes)
    meshes = doc.meshes or []
    out: List[Mesh] = []
    skipped: Set[int] = set()
    for m, world, node in _instances(doc, filename):
        if not isinstance(m, int) or not 0 <= m < len(meshes):
            raise MeshFileError(f"node {node} refers to mesh {m!r}; the file has "
                                f"{len(meshes)}", file=filename)
        for p, prim in enumerate(meshes[m].primitives or []):
            mode = 4 if prim.mode is None else prim.mode
            if mode != 4:
                skipped.add(mode)
                continue
            mesh = _primitive(doc, buffers, prim, filename, f"{name}:{meshes[m].name or m}:{p}")
            out.append(mesh if np.array_equal(world, np.eye(4)) else mesh.transformed(world))
    if skipped:
        warnings.warn(f"{filename}: primitives of mode(s) {sorted(skipped)} skipped: only "
                      "triangles (mode 4) make faces", MeshFileWarning, stacklevel=4)
    if not out:
        raise MeshFileError("the file holds no triangle primitives in its scene",
                            file=filename)
    return out


def _primitive(doc: "GLTF2", buffers: _Buffers, prim: "Primitive", filename: str,
               name: str) -> Mesh:
    from ..errors import ArgumentValueError
    from .files import MeshFileError

    attributes = prim.attributes
    position = getattr(attributes, "POSITION", None)
    if position is None:
        raise MeshFileError(f"primitive {name!r} has no POSITION accessor", file=filename)
    where = f"accessor {position}"
    vertices = _accessor(doc, buffers, position, filename, ("VEC3",))
    nv = len(vertices)
    if prim.indices is not None:
        faces = _indices(doc, buffers, prim.indices, filename)
        where = f"accessor {prim.indices}"
        if len(faces) % 3:
            raise MeshFileError(f"accessor {prim.indices}: {len(faces)} triangle indices is "
                                "not a multiple of 3", file=filename)
        if len(faces) and faces.max() >= nv:
            raise MeshFileError(f"accessor {prim.indices}: index {int(faces.max())} is out of "
                                f"range: POSITION (accessor {position}) has {nv} vertices",
                                file=filename)
    else:
        faces = np.arange(nv - nv % 3, dtype=np.int64)
    triangles = faces.reshape(-1, 3)
    flat = ((triangles[:, 0] == triangles[:, 1]) | (triangles[:, 1] == triangles[:, 2])
            | (triangles[:, 0] == triangles[:, 2]))
    if flat.any():
        # exporters leave degenerate triangles (a vertex twice) in index lists: they
        # cover nothing, and a mesh face visits each vertex once
        from .files import MeshFileWarning

        warnings.warn(f"{filename}: {where}: {int(flat.sum())} degenerate triangle(s) (a "
                      "vertex repeated) skipped", MeshFileWarning, stacklevel=5)
        triangles = triangles[~flat]
    extra: "MeshKeywords" = {}
    normal = getattr(attributes, "NORMAL", None)
    if normal is not None:
        extra["normals"] = _sized(_accessor(doc, buffers, normal, filename, ("VEC3",)), nv,
                                  normal, filename)
    uv = getattr(attributes, "TEXCOORD_0", None)
    if uv is not None:
        tex = _sized(_accessor(doc, buffers, uv, filename, ("VEC2",)), nv, uv, filename)
        extra["uv"] = np.stack([tex[:, 0], 1.0 - tex[:, 1]], axis=1)
    color = getattr(attributes, "COLOR_0", None)
    if color is not None:
        c = _sized(_accessor(doc, buffers, color, filename, ("VEC3", "VEC4")), nv, color,
                   filename)
        extra["colors"] = np.round(np.clip(c, 0, 1) * 255).astype(np.uint8)
        extra["color_on"] = "vertex"
    try:
        mesh = Mesh(vertices, triangles, name=name, **extra)
    except ArgumentValueError as error:
        raise MeshFileError(f"{where}: the primitive's mesh is broken: {error}",
                            file=filename) from None
    mesh.material = _material(doc, prim.material, filename)
    return mesh


def _sized(values: NDArray[np.float64], count: int, index: int, filename: str
           ) -> NDArray[np.float64]:
    from .files import MeshFileError

    if len(values) != count:
        raise MeshFileError(f"accessor {index}: {len(values)} values for {count} vertices "
                            "(POSITION's count)", file=filename)
    return values


def gltf_bytes(mesh: Mesh, binary: bool) -> bytes:
    """The glTF document of ``mesh`` (triangulated): a GLB's bytes, or a .gltf's JSON
    with the buffer as a data URI (one self-contained file)."""
    import pygltflib as g

    tri = mesh.triangulated()
    arrays: List[Tuple[Optional[str], NDArray[Any], str]] = [
        ("POSITION", tri.vertices.astype(np.float32), "VEC3")]
    if tri.normals is not None:
        arrays.append(("NORMAL", tri.normals.astype(np.float32), "VEC3"))
    if tri.uv is not None:
        arrays.append(("TEXCOORD_0", np.stack([tri.uv[:, 0], 1.0 - tri.uv[:, 1]], axis=1)
                       .astype(np.float32), "VEC2"))
    if tri.colors is not None and tri.color_on == "vertex":
        arrays.append(("COLOR_0", tri.colors.astype(np.float32) / 255.0, "VEC4"))
    indices = tri.face_indices.astype(np.uint32)
    blob = b""
    views: List["g.BufferView"] = []
    accessors: List["g.Accessor"] = []
    attributes: Dict[str, int] = {}
    for key, a, kind in arrays + [(None, indices, "SCALAR")]:
        data = np.ascontiguousarray(a).tobytes()
        views.append(g.BufferView(buffer=0, byteOffset=len(blob), byteLength=len(data),
                                  target=g.ELEMENT_ARRAY_BUFFER if key is None else g.ARRAY_BUFFER))
        blob += data + b"\0" * (-len(data) % 4)
        accessors.append(g.Accessor(
            bufferView=len(views) - 1, componentType=g.UNSIGNED_INT if key is None else g.FLOAT,
            count=len(a), type=kind,
            max=a.max(axis=0).tolist() if key == "POSITION" else None,
            min=a.min(axis=0).tolist() if key == "POSITION" else None))
        if key is not None:
            attributes[key] = len(accessors) - 1
    materials: List["g.Material"] = []
    material: Optional[int] = None
    record = mesh.material
    if record is not None:
        kd = getattr(record, "kd", None)
        rgb = list(kd) if isinstance(kd, tuple) else \
            [float(c) for c in np.asarray(getattr(record, "color", (1, 1, 1)))]
        alpha = getattr(record, "d", 1.0 - getattr(record, "transparency", 0.0))
        materials = [g.Material(name=getattr(record, "name", None) or "material",
                                pbrMetallicRoughness=g.PbrMetallicRoughness(
                                    baseColorFactor=rgb + [alpha], metallicFactor=0.0))]
        material = 0
    doc = g.GLTF2(
        scene=0, scenes=[g.Scene(nodes=[0])], nodes=[g.Node(mesh=0, name=mesh.name)],
        meshes=[g.Mesh(primitives=[g.Primitive(attributes=g.Attributes(**attributes),
                                               indices=len(accessors) - 1, mode=g.TRIANGLES,
                                               material=material)])],
        materials=materials, accessors=accessors, bufferViews=views,
        buffers=[g.Buffer(byteLength=len(blob))])
    if binary:
        doc.set_binary_blob(blob)
        return b"".join(doc.save_to_bytes())
    doc.buffers[0].uri = ("data:application/octet-stream;base64,"
                          + base64.b64encode(blob).decode("ascii"))
    text: str = doc.to_json(indent=1)
    return text.encode("utf-8")
