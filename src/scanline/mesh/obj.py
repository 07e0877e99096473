"""Wavefront OBJ as exporters write it (Wavefront Technologies, "Object Files (.obj)",
Advanced Visualizer manual, appendix B1).

Statements read: ``v x y z [w ...]`` positions (``v x y z r g b``: a vertex color, as
MeshLab and trimesh write it, kept when every vertex has one), ``vt u [v]`` texture
coordinates, ``vn x y z`` normals, ``f`` faces of corners ``v``, ``v/vt``, ``v//vn`` or
``v/vt/vn`` (1-based; a negative index counts back from the last element read), ``mtllib`` and
``usemtl`` (materials, :mod:`scanline.mesh.materials`).  ``o``, ``g``, ``s`` and the
free-form statements are skipped; ``l`` lines are skipped with one
:class:`~scanline.mesh.files.MeshFileWarning`.  Faces keep their polygons.

OBJ indexes positions, texture coordinates and normals separately, while a mesh
vertex carries one of each: every distinct (v, vt, vn) triple of the faces becomes
its own mesh vertex (a cube with per-face normals has 24), in the order first met --
as trimesh does.  A file without ``vt`` and ``vn`` in its faces keeps its vertex list
as it is.

The bytes are tokenized by compiled kernels (:mod:`scanline._kernels.objtext`); every
error names the file and the line.  Numbers are read correctly rounded: the kernel's
fast path (Clinger 1990) where it is exact, numpy's conversion of the few others
(17-digit numbers, as ``repr`` and :func:`scanline.mesh.save` write them).
"""

import os
import re
import warnings
from typing import Dict, List, NoReturn, Optional, Tuple

import numpy as np
from numpy.typing import NDArray

from ..errors import ArgumentValueError
from .materials import MaterialRecord
from .mesh import Flat, Mesh, check_mesh_budget

_WHAT = ("vertex", "texture coordinate", "normal")
_ELEMENTS = ("vertices", "texture coordinates", "normals")

#: The largest ``.mtl`` file read (bytes).
MAX_MTL_BYTES = 64 << 20


class ObjContent:
    """What an OBJ file holds, as arrays: the mesh vertices (split by (v, vt, vn)),
    their uv and normals (None unless every corner has one) and colors (None unless
    every ``v`` line has one), the faces (flat), the
    line of each face, each face's material number (-1: none) and the materials
    (:class:`~scanline.mesh.materials.MaterialRecord` or None where ``usemtl`` names
    an unknown material), in the order first used."""

    __slots__ = ("vertices", "uv", "normals", "colors", "indices", "sizes", "face_line",
                 "face_material", "materials")

    vertices: NDArray[np.float64]
    uv: Optional[NDArray[np.float64]]
    normals: Optional[NDArray[np.float64]]
    colors: Optional[NDArray[np.uint8]]
    indices: NDArray[np.int64]
    sizes: NDArray[np.int64]
    face_line: NDArray[np.int64]
    face_material: NDArray[np.int64]
    materials: List[Optional[MaterialRecord]]


def _message(code: int, err: NDArray[np.int64], data: bytes, totals: NDArray[np.int64]) -> str:
    from .._kernels import objtext as k

    token = data[err[2]:err[3]].decode("utf-8", errors="replace")
    kind = int(err[4])
    if code == k.ERR_FEW_COORDS:
        form = ("v x y z", "vt u [v]", "vn x y z")[kind]
        need = "at least u" if kind == 1 else "three coordinates"
        return f"a {_WHAT[kind]} needs {need} ({form}), got {token!r}"
    if code == k.ERR_NOT_NUMBER:
        return f"the {_WHAT[kind]} coordinates have {token!r}, which is not a number"
    if code == k.ERR_NOT_FINITE:
        return f"the {_WHAT[kind]} coordinates are not all finite numbers ({token!r})"
    if code == k.ERR_FEW_CORNERS:
        return f"a face needs at least three vertices, got {kind}"
    if code == k.ERR_NOT_INDEX:
        return (f"the face's vertex index {token!r} is not an integer (a corner is v, v/vt, "
                "v//vn or v/vt/vn)")
    if code == k.ERR_INDEX_ZERO:
        return f"{_WHAT[kind]} index 0: OBJ counts {_ELEMENTS[kind]} from 1"
    if code == k.ERR_BEFORE_FIRST:
        return (f"the relative {_WHAT[kind]} index {token} reaches back before the first "
                f"{_WHAT[kind]}")
    return (f"the face refers to {_WHAT[kind]} {token.lstrip('+')}, out of range: the file "
            f"has {int(totals[kind])} {_ELEMENTS[kind]}")


def read_obj(data: bytes, filename: str) -> ObjContent:
    """The :class:`ObjContent` of the OBJ bytes ``data`` (read from ``filename``,
    which names errors and locates ``mtllib`` files)."""
    from .._kernels._jit import call
    from .._kernels import objtext as k
    from .files import MeshFileError, MeshFileWarning

    def fail(line: int, message: str) -> NoReturn:
        raise MeshFileError(f"line {line}: {message}", file=filename)

    buf = np.frombuffer(bytearray(data), np.uint8)
    counts = np.zeros(8, np.int64)
    call(k.obj_count, len(buf), buf, counts)
    nv, nt, nn, nf, nk, ne, nl, _ = (int(c) for c in counts)
    check_mesh_budget("path", nv + nk, nf, nk, f"reading the mesh file {filename!r}",
                      hint="use a smaller mesh file")
    pos, uvs, nrm = np.zeros((nv, 6)), np.zeros((nt, 2)), np.zeros((nn, 3))
    corners = np.zeros((nk, 3), np.int64)
    sizes, face_line = np.zeros(nf, np.int64), np.zeros(nf, np.int64)
    events = np.zeros((ne, 5), np.int64)
    err = np.zeros(7, np.int64)
    totals = np.array([nv, nt, nn], np.int64)
    slow = np.zeros((nv + nt + nn, 4), np.int64)
    call(k.obj_parse, 4 * len(buf), buf, totals, pos, uvs, nrm, corners, sizes, face_line,
         events, slow, err)
    if err[0]:
        fail(int(err[1]), _message(int(err[0]), err, data, totals))
    _exactly(buf, data, slow[:int(err[5])], (pos, uvs, nrm))
    if nv == 0:
        raise MeshFileError("the file holds no vertices: it is empty, truncated or not OBJ",
                            file=filename)
    if nf == 0:
        raise MeshFileError(f"the file holds no faces ({nv} vertices)", file=filename)
    if nl:
        warnings.warn(f"{filename}: {nl} line statement(s) (l) skipped: a mesh holds faces",
                      MeshFileWarning, stacklevel=4)
    out = ObjContent()
    out.sizes, out.face_line = sizes, face_line
    colors = pos[:, 3:] if err[6] == nv else None
    source = _split(out, uvs, nrm, corners, nv)
    out.vertices = pos[:, :3] if source is None else pos[source, :3]
    out.colors = None
    if colors is not None:         # v x y z r g b: reals 0..1 (or 0..255 where above 1)
        colors = colors if source is None else colors[source]
        scale = 255.0 if colors.max(initial=0) <= 1 else 1.0
        out.colors = np.clip(np.round(colors * scale), 0, 255).astype(np.uint8)
    _materials(out, events, data, filename)
    return out


#: Bytes of the longest number converted in one numpy pass (longer ones: one by one).
TOKEN_BYTES = 32


def _exactly(buf: NDArray[np.uint8], data: bytes, rows: NDArray[np.int64],
             arrays: Tuple[NDArray[np.float64], ...]) -> None:
    """Convert again, correctly rounded, the numbers of the v/vt/vn ``rows`` that the
    kernel's fast path could not round exactly (more than 15 digits, or powers of
    ten beyond 22): their bytes gathered by a kernel, converted by numpy's
    string-to-float in one pass (as Python's float does)."""
    from .._kernels._jit import call
    from .._kernels.objtext import obj_tokens

    if not len(rows):
        return
    widths = np.array([a.shape[1] for a in arrays], np.int64)
    most = len(rows) * int(widths.max())
    tokens = np.zeros((most, TOKEN_BYTES), np.uint8)
    where = np.zeros((most, 3), np.int64)
    long_rows = np.zeros(len(rows), bool)
    m: int = call(obj_tokens, 8 * most, buf, rows, widths, tokens, where, long_rows)
    values = tokens[:m].view(f"S{TOKEN_BYTES}").reshape(-1).astype(np.float64)
    for kind, target in enumerate(arrays):
        pick = where[:m, 0] == kind
        target[where[:m][pick, 1], where[:m][pick, 2]] = values[pick]
    for kind, row, a, b in rows[long_rows].tolist():
        target = arrays[kind]
        for column, word in enumerate(data[a:b].split(b"#")[0].split()[:target.shape[1]]):
            try:
                target[row, column] = float(word)
            except ValueError:          # an extra value that is no number (no color then)
                break


def _split(out: ObjContent, uvs: NDArray[np.float64], nrm: NDArray[np.float64],
           corners: NDArray[np.int64], nv: int) -> Optional[NDArray[np.int64]]:
    """Mesh vertices from the corners' (v, vt, vn) triples (module docstring): sets
    the faces' indices, uv and normals, and returns the position row of each mesh
    vertex (None: the positions as they are)."""
    from .._kernels._jit import call
    from .._kernels.objtext import obj_split

    has_t = len(uvs) > 0 and (corners[:, 1] >= 0).any()
    has_n = len(nrm) > 0 and (corners[:, 2] >= 0).any()
    v = corners[:, 0]
    if not has_t and not has_n:
        out.uv, out.normals, out.indices = None, None, v
        return None
    same_t = not has_t or (len(uvs) == nv and np.array_equal(corners[:, 1], v))
    same_n = not has_n or (len(nrm) == nv and np.array_equal(corners[:, 2], v))
    if same_t and same_n:
        # one index for all three (trimesh writes so): no split
        out.indices = v
        out.uv = uvs if has_t else None
        out.normals = nrm if has_n else None
        return None
    size = 1 << max(int(2 * len(corners)).bit_length(), 4)
    table = np.full(size, -1, np.int64)
    vertex = np.zeros(len(corners), np.int64)
    unique = np.zeros((len(corners), 3), np.int64)
    count: int = call(obj_split, 3 * len(corners), corners, table, vertex, unique)
    unique = unique[:count]
    out.indices = vertex
    out.uv = uvs[unique[:, 1]] if has_t and (unique[:, 1] >= 0).all() else None
    out.normals = nrm[unique[:, 2]] if has_n and (unique[:, 2] >= 0).all() else None
    return unique[:, 0]


def _materials(out: ObjContent, events: NDArray[np.int64], data: bytes, filename: str) -> None:
    """Each face's material from the ``usemtl`` statements, the records from the
    ``mtllib`` files (a missing file or material: a warning, and no material)."""
    from .._kernels.objtext import EVENT_MTLLIB
    from .files import MeshFileError, MeshFileWarning, read_regular_file
    from .materials import read_mtl

    nf = len(out.sizes)
    library: Dict[str, MaterialRecord] = {}
    names: List[str] = []
    starts: List[int] = []
    folder = os.path.dirname(os.path.abspath(filename))
    for kind, a, b, face, line in events.tolist():
        text = data[a:b].decode("utf-8", errors="replace")
        if kind == EVENT_MTLLIB:
            candidates = [text] if os.path.isfile(os.path.join(folder, text)) else text.split()
            for part in candidates:
                path = os.path.join(folder, part)
                if not os.path.lexists(path):
                    warnings.warn(f"{filename}: line {line}: the material file {part!r} is "
                                  "missing; its materials are left out", MeshFileWarning,
                                  stacklevel=5)
                    continue
                try:
                    library.update(read_mtl(read_regular_file(path, MAX_MTL_BYTES), path))
                except MeshFileError as error:
                    raise MeshFileError(f"line {line}: mtllib {part!r}: {error}",
                                        file=filename) from None
        else:
            names.append(text)
            starts.append(face)
    order: List[str] = []
    numbers: Dict[str, int] = {}
    face_material = np.full(nf, -1, np.int64)
    bounds = starts + [nf]
    for i, name in enumerate(names):
        if name not in numbers:
            numbers[name] = len(order)
            order.append(name)
        face_material[bounds[i]:bounds[i + 1]] = numbers[name]
    missing = [n for n in order if n not in library]
    if missing:
        warnings.warn(f"{filename}: usemtl names material(s) no mtllib file defines: "
                      + ", ".join(repr(n) for n in missing[:5]), MeshFileWarning, stacklevel=5)
    out.face_material = face_material
    out.materials = [library.get(n) for n in order]


def _mesh(content: ObjContent, filename: str, name: str,
          faces: Optional[NDArray[np.bool_]] = None) -> Mesh:
    """The Mesh of ``content`` (of its faces ``faces``, a boolean mask, with only the
    vertices they use), errors naming the file and the face's line."""
    from .files import MeshFileError

    indices, sizes, lines = content.indices, content.sizes, content.face_line
    vertices, uv, normals = content.vertices, content.uv, content.normals
    colors = content.colors
    if faces is not None:
        indices = indices[np.repeat(faces, sizes)]
        sizes, lines = sizes[faces], lines[faces]
        used, indices = np.unique(indices, return_inverse=True)
        vertices = vertices[used]
        uv = uv[used] if uv is not None else None
        normals = normals[used] if normals is not None else None
        colors = colors[used] if colors is not None else None
    try:
        return Mesh(vertices, Flat(indices, sizes), normals=normals, uv=uv, name=name,
                    colors=colors, color_on="vertex" if colors is not None else None)
    except ArgumentValueError as error:
        text = str(error)
        which = re.match(r"face (\d+)", text)
        where = f"line {lines[int(which.group(1))]}: " if which else ""
        raise MeshFileError(f"{where}the file's mesh is broken: {text}", file=filename) from None


def obj_meshes(data: bytes, filename: str, name: str) -> List[Mesh]:
    """One Mesh per material (in the order first used; faces before any ``usemtl``
    first), each with its material and only the vertices its faces use (one
    material: the file's vertex list as it is)."""
    content = read_obj(data, filename)
    groups = np.unique(content.face_material)
    out: List[Mesh] = []
    for m in groups:
        mesh = _mesh(content, filename, name,
                     content.face_material == m if len(groups) > 1 else None)
        if m >= 0:
            mesh.material = content.materials[int(m)]
            mesh.name = f"{name}:{mesh.material.name}" if mesh.material else name
        out.append(mesh)
    return out
