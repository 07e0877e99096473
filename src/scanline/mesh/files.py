"""Reading and writing meshes: Wavefront OBJ (with its ``.mtl`` materials), PLY (ASCII
and binary), STL and glTF 2.0 (``.gltf``, ``.glb``).

=========  ==========================================  ====================================
format     read                                        written by :func:`save`
=========  ==========================================  ====================================
``.obj``   ``v vt vn``, faces ``v``, ``v/vt``,          positions, uv, normals, polygons
           ``v//vn``, ``v/vt/vn`` (negative: relative),
           ``mtllib``/``usemtl`` (:mod:`.obj`)
``.ply``   positions, faces, vertex normals (``nx``),  positions, polygons, normals, uv,
           colors (``red``...), uv (``s t``/``u v``)   vertex colors (binary)
``.stl``   triangles                                   triangles (binary)
``.gltf``  the default scene's triangle primitives     one mesh, triangles, normals, uv,
``.glb``   with node transforms and materials          vertex colors, its material
           (:mod:`.gltf`)
=========  ==========================================  ====================================

:func:`load` gives one :class:`Mesh`; :func:`load_all` gives the file's parts: one mesh
per material of an OBJ file, one per triangle primitive of a glTF file (each with its
``material``).  meshio reads PLY and STL; OBJ is tokenized by compiled kernels
(:mod:`scanline._kernels.objtext`), glTF parsed by pygltflib and its accessors read
with numpy.  Faces keep their polygons (a cube's quadrilaterals stay quadrilaterals in
OBJ and PLY; trimesh would triangulate them); STL and glTF hold only triangles, so
faces are split into triangle fans when writing them.

Reading is guarded against hostile files (docs/three-d.md, "Mesh files"):

- only a regular file is read: the file is opened without blocking (``O_NONBLOCK``,
  so a FIFO cannot hang the call) and checked with ``fstat`` after opening; a FIFO, a
  device (``/dev/zero``), a socket or a folder is refused, and a symbolic link is
  followed only to a regular file (the same for ``.mtl`` files and glTF buffers);
- its size is checked after opening, against ``max_bytes`` (default
  :data:`MAX_FILE_BYTES`) and against the memory budget (:mod:`scanline.budget`: the
  reading takes about :data:`READ_BYTES_PER_BYTE` bytes of memory per byte of file),
  and at most its size and one byte are read, so a file that grows meanwhile is
  refused too;
- a PLY header must end (``end_header``) within :data:`MAX_PLY_HEADER` bytes, name
  known property types, and announce element counts that the bytes after it can hold;
- a glTF accessor's offset, stride and count must fit its buffer view, and the view
  its buffer.

Every failure is a :class:`MeshFileError` naming the file (and, in an OBJ file, the
line; in a glTF file, the accessor): unreadable, truncated or garbage files, counts
that do not fit the file, faces that refer to missing vertices, NaN coordinates.
What is skipped (OBJ ``l`` lines, a missing ``.mtl`` file, glTF points and lines) is
one :class:`MeshFileWarning`.  Writing is atomic: a failure leaves no partial file.
"""

import io
import os
import re
import stat
import tempfile
import warnings
from dataclasses import dataclass
from typing import (TYPE_CHECKING, Any, BinaryIO, Dict, List, Literal, Mapping, NoReturn,
                    Optional, Sequence, Tuple, TypedDict, Union)

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError, ScanlineWarning
from .materials import MaterialRecord
from .mesh import Flat, Mesh, merge

if TYPE_CHECKING:
    from meshio import Mesh as MeshioMesh

#: A file name as the functions take it.
Path = Union[str, "os.PathLike[str]"]

#: File types by extension.
FORMATS = {".obj": "obj", ".ply": "ply", ".stl": "stl", ".gltf": "gltf", ".glb": "glb"}

#: The largest mesh file read by default (bytes); ``load(..., max_bytes=...)`` reads
#: larger ones.  The memory budget applies as well.
MAX_FILE_BYTES = 2 << 30

#: Bytes of memory that reading a mesh file takes per byte of the file, at most
#: (the parsed numbers, the mesh's arrays and their checks; measured on OBJ, ASCII
#: and binary PLY and STL files, rounded up): the estimate checked against the
#: memory budget before the file is read.
READ_BYTES_PER_BYTE = 16

#: The PLY header must end (``end_header``) within this many bytes.
MAX_PLY_HEADER = 64 << 10


class MeshFileError(ArgumentValueError):
    """A mesh file that cannot be read or written; ``file`` names it.

    Parameters
    ----------
    message : str
        What is wrong.
    file : str, optional
        The file's name; the error's text is ``"FILE: MESSAGE"`` when given.

    Examples
    --------
    >>> from scanline.mesh import MeshFileError
    >>> error = MeshFileError("the file holds no faces", file="empty.obj")
    >>> str(error), error.file
    ('empty.obj: the file holds no faces', 'empty.obj')
    """

    file: Optional[str]
    message: str

    def __init__(self, message: str, file: Optional[str] = None) -> None:
        self.file = file
        self.message = message
        super().__init__(f"{file}: {message}" if file else message)


class MeshFileWarning(ScanlineWarning):
    """Something in a mesh file was skipped (OBJ lines, a missing material file,
    glTF primitives that are not triangles)."""


def _format(name: str, path: object, what: str) -> str:
    ext = os.path.splitext(name)[1].lower()
    if ext not in FORMATS:
        raise MeshFileError(f"cannot {what} {ext or 'a file without extension'}: use one of "
                            + ", ".join(FORMATS), file=name)
    return FORMATS[ext]


def _file_name(path: object, what: str = "path") -> str:
    if not isinstance(path, (str, os.PathLike)):
        raise ArgumentTypeError(f"{what} must be a file name (str or os.PathLike), got "
                                f"{v._show(path)} of type {type(path).__name__}")
    name = os.fspath(path)
    if isinstance(name, bytes):
        name = os.fsdecode(name)
    if "\0" in name:
        raise MeshFileError("the file name has a NUL character", file=name)
    return name


def _max_bytes(value: object) -> int:
    if value is None:
        return MAX_FILE_BYTES
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise ArgumentTypeError(f"max_bytes must be an integer number of bytes (or None: "
                                f"{MAX_FILE_BYTES:,}), got {v._show(value)}")
    if value < 0:
        raise ArgumentValueError(f"max_bytes must be >= 0, got {value}")
    return int(value)


def read_regular_file(filename: str, limit: int, limit_name: str = "max_bytes",
                      budget_name: str = "path") -> bytes:
    """The bytes of the regular file ``filename``, read safely: opened without
    blocking, checked after opening (a regular file: no FIFO, device, socket or
    folder, whatever a symbolic link points to; at most ``limit`` bytes; within the
    memory budget), then at most its size + 1 bytes read (a file that grows
    meanwhile is refused)."""
    from .. import budget

    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0) \
        | getattr(os, "O_NOCTTY", 0) | getattr(os, "O_BINARY", 0)
    try:
        fd = os.open(filename, flags)
    except FileNotFoundError:
        raise MeshFileError("cannot read the file: it does not exist (No such file or "
                            "directory)", file=filename) from None
    except OSError as error:
        raise MeshFileError(f"cannot read the file: {error.strerror or error}",
                            file=filename) from None
    try:
        info = os.fstat(fd)
        if stat.S_ISDIR(info.st_mode):
            raise MeshFileError("it is a folder, not a mesh file", file=filename)
        if not stat.S_ISREG(info.st_mode):
            kind = ("a FIFO (named pipe)" if stat.S_ISFIFO(info.st_mode) else
                    "a device" if stat.S_ISCHR(info.st_mode) or stat.S_ISBLK(info.st_mode)
                    else "a socket" if stat.S_ISSOCK(info.st_mode) else "not a regular file")
            raise MeshFileError(f"it is {kind}, not a regular file; give a mesh file on disk",
                                file=filename)
        f = os.fdopen(fd, "rb", buffering=0)
    except BaseException:
        os.close(fd)
        raise
    with f:
        size = info.st_size
        if size > limit:
            raise MeshFileError(f"the file is {size:,} bytes, more than {limit_name}="
                                f"{limit:,}; pass a larger {limit_name} to read it",
                                file=filename)
        budget.check(size * READ_BYTES_PER_BYTE, budget_name,
                     f"reading the {size:,}-byte mesh file {filename!r}",
                     hint="use a smaller mesh file")
        try:
            # one byte more than the size: a file that grew shows; in pieces, since
            # one read() returns at most about 2 GiB
            chunks: List[bytes] = []
            left = size + 1
            while left > 0:
                chunk = f.read(min(left, 1 << 30))
                if not chunk:
                    break
                chunks.append(chunk)
                left -= len(chunk)
            data = chunks[0] if len(chunks) == 1 else b"".join(chunks)
        except OSError as error:
            raise MeshFileError(f"cannot read the file: {error.strerror or error}",
                                file=filename) from None
    if len(data) > size:
        raise MeshFileError(f"the file changed while it was read (it has more than the "
                            f"{size:,} bytes it had when opened)", file=filename)
    return data


# -- PLY ---------------------------------------------------------------------------------
#: Bytes of each PLY property type.
PLY_TYPES = {"char": 1, "uchar": 1, "int8": 1, "uint8": 1, "short": 2, "ushort": 2,
             "int16": 2, "uint16": 2, "int": 4, "uint": 4, "int32": 4, "uint32": 4,
             "float": 4, "float32": 4, "double": 8, "float64": 8, "int64": 8, "uint64": 8}


@dataclass
class _PlyElement:
    """An element line of a PLY header, and what its properties take at least."""
    name: str
    count: int
    nbytes: int = 0        # bytes of one element in a binary file
    values: int = 0        # values of one element


def _ply_header(data: bytes, filename: str) -> None:
    """Check a PLY header before meshio reads it: the magic line, ``end_header``
    within :data:`MAX_PLY_HEADER` bytes, the format, known property types, and
    element counts that the bytes after the header can hold (each element takes at
    least its fixed properties' bytes, or two characters per value in ASCII; a face
    at least three indices)."""
    def fail(message: str) -> NoReturn:
        raise MeshFileError(message, file=filename)

    if not re.match(rb"ply\r?\n", data[:5]):
        fail("the file is not a readable PLY file (it does not start with the line 'ply')")
    head = data[:MAX_PLY_HEADER]
    match = re.search(rb"^[ \t]*end_header[ \t]*\r?(\n|$)", head, re.MULTILINE)
    if match is None:
        fail(f"the PLY header has no end_header line within its first {MAX_PLY_HEADER:,} "
             "bytes: the file is truncated or not PLY")
    body = len(data) - match.end()
    ascii_ = None
    elements: List[_PlyElement] = []
    for raw in head[:match.start()].split(b"\n")[1:]:
        words = raw.decode("ascii", errors="replace").split()
        if not words or words[0] in ("comment", "obj_info"):
            continue
        if words[0] == "format":
            if len(words) < 2 or words[1] not in ("ascii", "binary_little_endian",
                                                  "binary_big_endian"):
                fail(f"the PLY format {' '.join(words[1:])!r} is not ascii, "
                     "binary_little_endian or binary_big_endian")
            ascii_ = words[1] == "ascii"
        elif words[0] == "element":
            if len(words) != 3 or not (words[2].isascii() and words[2].isdigit()):
                fail(f"the PLY header's element line {' '.join(words)!r} does not give a "
                     "count (element NAME COUNT, COUNT a whole number)")
            elements.append(_PlyElement(words[1], int(words[2])))
        elif words[0] == "property":
            if not elements:
                fail("the PLY header has a property before any element")
            element = elements[-1]
            least: Optional[int]
            if len(words) == 5 and words[1] == "list":
                types = words[2:4]
                least = 3 if element.name == "face" else 0
            elif len(words) == 3:
                types, least = words[1:2], None
            else:
                fail(f"the PLY header's property line {' '.join(words)!r} is malformed")
            for t in types:
                if t not in PLY_TYPES:
                    fail(f"the PLY property type {t!r} is not one of "
                         + ", ".join(sorted(PLY_TYPES)))
            if least is None:
                element.nbytes += PLY_TYPES[types[0]]
                element.values += 1
            else:
                element.nbytes += PLY_TYPES[types[0]] + least * PLY_TYPES[types[1]]
                element.values += 1 + least
        elif words[0] != "ply":
            fail(f"the PLY header has an unknown line {' '.join(words)[:60]!r}")
    if ascii_ is None:
        fail("the PLY header has no format line")
    need = 0
    for e in elements:
        if e.values == 0 and e.count:
            fail(f"the PLY element {e.name!r} has no properties but a count of {e.count}")
        need += e.count * (2 * e.values if ascii_ else e.nbytes)
        # (ASCII: a value and its separator, but the last line may lack its newline)
        if need - bool(ascii_) > body:
            fail(f"the PLY header announces {e.count:,} {e.name} elements, more than the file's "
                 f"{body:,} bytes after the header can hold: the file is truncated or broken")


def _read_stl(meshio: Any, data: bytes) -> "MeshioMesh":
    """meshio's STL reading, on bytes: binary when the triangle count in the header
    matches the size (84 + 50 bytes per triangle), else ASCII."""
    from meshio.stl import _stl

    if len(data) >= 84:
        count = int.from_bytes(data[80:84], "little")
        if 84 + count * 50 == len(data):
            facets = np.frombuffer(data, np.dtype([("normal", "<f4", (3,)),
                                                   ("facet", "<f4", (3, 3)),
                                                   ("attr count", "<i2")]),
                                   count=count, offset=84)["facet"]
            points, cells = _stl.data_from_facets(facets)
            mesh: MeshioMesh = meshio.Mesh(points, cells)
            return mesh
    f = io.BytesIO(data)
    if len(data) >= 80:
        f.readline()                 # the 'solid NAME' line
    read: MeshioMesh = _stl._read_ascii(f)
    return read


def _arguments(path: object, name: object, max_bytes: object) -> Tuple[str, int, str]:
    filename = _file_name(path)
    if name is not None and not isinstance(name, str):
        raise ArgumentTypeError(f"name must be a string or None, got {v._show(name)}")
    return filename, _max_bytes(max_bytes), _format(filename, path, "read")


def load_all(path: Path, name: Optional[str] = None,
             max_bytes: Optional[int] = None) -> List[Mesh]:
    """Read the parts of a mesh file: a list of meshes.

    An OBJ file gives one mesh per material (in the order its ``usemtl`` statements
    first use them; faces before any ``usemtl`` first), each with its ``material``
    (a :class:`~scanline.mesh.materials.MaterialRecord` from the ``.mtl`` file) and
    only the vertices its faces use; a glTF file one mesh per triangle primitive of
    the default scene, moved by its node's transformation, with its material; PLY
    and STL one mesh.  ``sl.render(fb, sl.mesh.load_all(path), camera)`` draws each
    part in its material.  Parameters and errors as :func:`load`.

    Parameters
    ----------
    path : str or os.PathLike
        A regular file (or a symbolic link to one) named ``.obj``, ``.ply``, ``.stl``,
        ``.gltf`` or ``.glb``.
    name : str, optional
        The meshes' name (default: the file's).
    max_bytes : int, optional
        The largest file read (default :data:`MAX_FILE_BYTES`, 2 GiB); the memory
        budget (:mod:`scanline.budget`) applies as well.

    Returns
    -------
    list of Mesh
        The file's parts, at least one.

    Raises
    ------
    MeshFileError
        As :func:`load`: naming the file, for a file that cannot be read as a mesh.
    MemoryBudgetError
        When reading the file would take more memory than the budget allows.

    Examples
    --------
    An OBJ file of two materials gives two parts, each with its material and the
    vertices its faces use, renumbered in their order (the blue face 2 4 3 uses
    vertices 2, 3, 4: it becomes 0 2 1).

    >>> import os, tempfile, scanline as sl
    >>> folder = tempfile.mkdtemp()
    >>> with open(os.path.join(folder, "two.mtl"), "w") as f:
    ...     _ = f.write("newmtl red\\nKd 1 0 0\\nnewmtl blue\\nKd 0 0 1\\n")
    >>> with open(os.path.join(folder, "two.obj"), "w") as f:
    ...     _ = f.write("mtllib two.mtl\\nv 0 0 0\\nv 1 0 0\\nv 0 1 0\\nv 1 1 0\\n"
    ...                 "usemtl red\\nf 1 2 3\\nusemtl blue\\nf 2 4 3\\n")
    >>> parts = sl.mesh.load_all(os.path.join(folder, "two.obj"))
    >>> [(part.material.name, part.material.kd) for part in parts]
    [('red', (1.0, 0.0, 0.0)), ('blue', (0.0, 0.0, 1.0))]
    >>> [part.faces.tolist() for part in parts]      # each part keeps its own vertices
    [[[0, 1, 2]], [[0, 2, 1]]]
    """
    filename, limit, fmt = _arguments(path, name, max_bytes)
    data = read_regular_file(filename, limit)
    mesh_name = name or os.path.basename(filename)
    if fmt == "obj":
        from .obj import obj_meshes

        return obj_meshes(data, filename, mesh_name)
    if fmt in ("gltf", "glb"):
        from .gltf import gltf_meshes

        return gltf_meshes(data, filename, mesh_name, limit)
    return [_read_meshio(data, fmt, filename, mesh_name)]


def joined(parts: List[Mesh], name: Optional[str]) -> Mesh:
    """One mesh of ``parts`` (:func:`load_all`'s): the parts merged, keeping their
    material when they share one; parts of different materials get their faces
    colored by each material's diffuse color (a part without a material: the
    default gray) so that the merged mesh looks as the parts do."""
    if len(parts) == 1:
        parts[0].name = name
        return parts[0]
    records = [p.material for p in parts]
    if len({id(r) for r in records}) > 1 and all(p.colors is None for p in parts) \
            and all(r is None or isinstance(r, MaterialRecord) for r in records):
        default = MaterialRecord("")
        parts = [p.colored([(r if isinstance(r, MaterialRecord) else default).diffuse_rgb255]
                           * p.face_count, color_on="face") for p, r in zip(parts, records)]
    return merge(parts, name=name)


def load(path: Path, name: Optional[str] = None, max_bytes: Optional[int] = None) -> Mesh:
    """Read a mesh from an OBJ, PLY, STL or glTF (``.gltf``, ``.glb``) file: one mesh.

    Faces of every polygon type in the file are kept (triangles, quadrilaterals,
    polygons); points and lines are skipped.  Texture coordinates and normals come
    along (OBJ ``vt``/``vn``, PLY ``s t``/``nx ny nz``, glTF ``TEXCOORD_0``/``NORMAL``),
    as do vertex colors (PLY, glTF ``COLOR_0``).  A file of several parts
    (:func:`load_all`: an OBJ file's materials, a glTF file's primitives) gives them
    merged: with their shared material, or, when they differ, with each part's
    faces colored by its material's diffuse color; :func:`load_all` keeps the parts
    and their materials apart.

    Parameters
    ----------
    path : str or os.PathLike
        A regular file (or a symbolic link to one) named ``.obj``, ``.ply``, ``.stl``,
        ``.gltf`` or ``.glb``.
    name : str, optional
        The mesh's name (default: the file's).
    max_bytes : int, optional
        The largest file read (default :data:`MAX_FILE_BYTES`, 2 GiB); the memory
        budget (:mod:`scanline.budget`) applies as well.

    Returns
    -------
    Mesh
        The file's mesh (its parts merged).

    Raises
    ------
    MeshFileError
        Naming the file, for a missing, unreadable, truncated, oversized or garbage
        file, or one that is not a regular file (a FIFO, a device, a folder), a PLY
        header without ``end_header`` or with counts the file cannot hold, a glTF
        accessor or buffer view reaching past its buffer, or a mesh with no faces,
        faces that refer to missing vertices, or coordinates that are not finite
        numbers (in an OBJ file the message names the line, in a glTF file the
        accessor).
    MemoryBudgetError
        When reading the file would take more memory than the budget allows.

    Examples
    --------
    >>> import os, tempfile, scanline as sl
    >>> path = os.path.join(tempfile.mkdtemp(), "cube.obj")
    >>> sl.mesh.cube().save(path)
    >>> sl.mesh.load(path)
    <Mesh 'cube.obj': 8 vertices, 6 faces, 12 edges>
    """
    parts = load_all(path, name, max_bytes)
    return joined(parts, name or os.path.basename(_file_name(path)))


def _read_meshio(data: bytes, fmt: str, filename: str, mesh_name: str) -> Mesh:
    """A PLY or STL file's mesh, read by meshio."""
    import meshio
    from meshio.ply import _ply

    if fmt == "ply":
        _ply_header(data, filename)
    try:
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore")
            # the format's own reader, on the bytes read (meshio.read() prints and
            # calls sys.exit on a ReadError)
            data_mesh = (_ply.read_buffer(io.BytesIO(data)) if fmt == "ply"
                         else _read_stl(meshio, data))
    except MemoryError:
        raise MeshFileError("the file announces more data than fits in memory: it is "
                            "truncated or broken", file=filename) from None
    except UnicodeDecodeError:
        raise MeshFileError(f"the file is not a readable {fmt.upper()} file (it holds bytes "
                            "that are not text where text is expected)", file=filename) from None
    except Exception as error:   # noqa: BLE001 - meshio raises many kinds: ReadError, ...
        text = str(error).strip().splitlines()[0] if str(error).strip() else type(error).__name__
        raise MeshFileError(f"the file is not a readable {fmt.upper()} file ({text})",
                            file=filename) from None
    return _from_meshio(data_mesh, fmt, filename, mesh_name)


#: PLY vertex properties carried into the mesh: normals, colors, texture coordinates
#: (the names exporters use, first match wins).
PLY_NORMALS: Tuple[str, ...] = ("nx", "ny", "nz")
PLY_COLORS: Tuple[Tuple[str, ...], ...] = (("red", "green", "blue", "alpha"), ("diffuse_red", "diffuse_green",
                                                  "diffuse_blue", "diffuse_alpha"),
              ("r", "g", "b", "a"))
PLY_UV: Tuple[Tuple[str, ...], ...] = (("s", "t"), ("u", "v"), ("texture_u", "texture_v"), ("texture_s", "texture_t"))


class MeshKeywords(TypedDict, total=False):
    """The keywords of :class:`Mesh` that a file's attributes give."""
    normals: NDArray[np.float64]
    colors: NDArray[np.uint8]
    color_on: Literal["face", "vertex"]
    uv: NDArray[np.float64]


def ply_attributes(data: Mapping[str, Any], count: int, face_data: Mapping[str, Any],
                   face_count: int) -> MeshKeywords:
    """The mesh keywords (normals, colors, color_on, uv) of meshio's PLY point data
    (and cell data: face colors)."""
    out: MeshKeywords = {}

    def columns(table: Mapping[str, Any], names: Sequence[str], n: int
                ) -> Optional[NDArray[Any]]:
        if not all(k in table for k in names[:3 if len(names) > 2 else 2]):
            return None
        cols = [np.asarray(table[k]).reshape(-1) for k in names if k in table]
        return np.stack(cols, axis=1) if all(len(c) == n for c in cols) else None

    normals = columns(data, PLY_NORMALS, count)
    if normals is not None and np.isfinite(normals).all():
        out["normals"] = normals.astype(np.float64)
    places: Tuple[Tuple[Mapping[str, Any], int, Literal["face", "vertex"]], ...] = (
        (data, count, "vertex"), (face_data, face_count, "face"))
    for table, n, on in places:
        for names in PLY_COLORS:
            c = columns(table, names, n)
            if c is not None:
                if c.dtype.kind == "i" and c.dtype.itemsize == 1:
                    c = c.view(np.uint8)       # meshio reads a binary uchar as int8
                c = c.astype(np.float64)
                if np.asarray(table[names[0]]).dtype.kind == "f" and c.max(initial=0) <= 1:
                    c = c * 255
                out["colors"] = np.clip(np.round(np.nan_to_num(c)), 0, 255).astype(np.uint8)
                out["color_on"] = on
                break
        if "colors" in out:
            break
    for names in PLY_UV:
        uv = columns(data, names, count)
        if uv is not None and np.isfinite(uv).all():
            out["uv"] = uv.astype(np.float64)
            break
    return out


def meshio_faces(data: "MeshioMesh") -> Tuple[NDArray[np.int64], NDArray[np.int64], bool]:
    """(indices, sizes, whether every cell block was taken) of a meshio mesh's
    surface cells (triangle, quad, polygon and other 2-D cells); points, lines and
    volume cells are skipped."""
    indices: List[NDArray[Any]] = []
    sizes: List[ArrayLike] = []
    kept_all = True
    for block in data.cells:
        if not (block.dim == 2 or block.type in ("triangle", "quad", "polygon")):
            kept_all = False
            continue
        cells = block.data
        if isinstance(cells, list):       # polygons of several sizes
            for face in cells:
                f = np.asarray(face)
                indices.append(f.reshape(-1))
                sizes.append([f.size])
        else:
            a = np.asarray(cells)
            a = a.reshape(len(a), -1)
            indices.append(a.reshape(-1))
            sizes.append(np.full(len(a), a.shape[1]))
    if not indices:
        return np.zeros(0, np.int64), np.zeros(0, np.int64), kept_all
    return np.concatenate(indices), np.concatenate(sizes).astype(np.int64), kept_all


def _from_meshio(data: "MeshioMesh", fmt: str, filename: str, mesh_name: str) -> Mesh:
    """A Mesh from what meshio read."""
    try:
        with np.errstate(all="ignore"):
            indices, sizes, kept_all = meshio_faces(data)
            points = np.asarray(data.points, np.float64)
    except (TypeError, ValueError, OverflowError) as error:
        raise MeshFileError(f"the file is not a readable {fmt.upper()} file ({error})",
                            file=filename) from None
    if points.size == 0:
        raise MeshFileError(f"the file holds no vertices: it is empty, truncated or not "
                            f"{fmt.upper()}", file=filename)
    if points.ndim != 2 or points.shape[1] not in (2, 3):
        raise MeshFileError(f"the file's vertices have shape {points.shape}, not (V, 3)",
                            file=filename)
    if points.shape[1] == 2:
        points = np.hstack([points, np.zeros((len(points), 1))])
    if not len(sizes):
        raise MeshFileError(f"the file holds no faces ({len(points)} vertices)", file=filename)
    extra: MeshKeywords
    try:
        face_data = {k: np.concatenate([np.asarray(c).reshape(-1) for c in blocks])
                     for k, blocks in data.cell_data.items()} if kept_all else {}
        extra = ply_attributes(data.point_data, len(points), face_data, len(sizes))
    except (TypeError, ValueError):       # attributes meshio read oddly: the geometry only
        extra = {}
    try:
        idx = v.index_array("faces", indices, what="vertex indices",
                            high=len(points) - 1,
                            bound_text=f" (the file has {len(points)} vertices)")
        return Mesh(points, Flat(idx, sizes), name=mesh_name, **extra)
    except ArgumentValueError as error:
        raise MeshFileError(f"the file's mesh is broken: {error}", file=filename) from None
    except ArgumentTypeError as error:
        raise MeshFileError(f"the file is not a readable {fmt.upper()} file ({error})",
                            file=filename) from None


def _cells(mesh: Mesh, fmt: str) -> List[Tuple[str, NDArray[np.int32]]]:
    """meshio cell blocks: triangles for STL, else one block per run of faces of one
    size (so the faces keep their order)."""
    if fmt == "stl":
        mesh = mesh.triangulated()
    sizes = mesh.face_sizes
    cuts = np.concatenate([[0], np.flatnonzero(np.diff(sizes)) + 1, [len(sizes)]])
    blocks = []
    for a, b in zip(cuts[:-1], cuts[1:]):
        n = int(sizes[a])
        which = np.arange(a, b)
        data = np.stack([mesh.face_indices[mesh.face_offsets[which] + k] for k in range(n)],
                        axis=1).astype(np.int32)
        blocks.append(({3: "triangle", 4: "quad"}.get(n, "polygon"), data))
    return blocks


#: Rows formatted at once when writing text (bounds the temporary Python objects).
TEXT_ROWS = 1 << 16


def _text_rows(out: io.StringIO, fmt: str, rows: NDArray[Any]) -> None:
    """Write ``rows`` (N, k) as lines of ``fmt`` (k fields), many rows per call of
    Python's formatting (numpy's savetxt formats one row a call: about twice as slow)."""
    for start in range(0, len(rows), TEXT_ROWS):
        part = rows[start:start + TEXT_ROWS]
        out.write((fmt * len(part)) % tuple(part.ravel().tolist()))


def _obj_text(mesh: Mesh) -> bytes:
    """Wavefront OBJ text of ``mesh``: ``v``, ``vt`` and ``vn`` lines (17 significant
    digits: the floats exactly) and faces ``f v/vt/vn`` (one index for all three, as
    the uv and normals are per vertex)."""
    out = io.StringIO()
    out.write(f"# written by scanline{': ' + mesh.name if mesh.name else ''}\n")
    _text_rows(out, "v %.17g %.17g %.17g\n", mesh.vertices)
    if mesh.uv is not None:
        _text_rows(out, "vt %.17g %.17g\n", mesh.uv)
    if mesh.normals is not None:
        _text_rows(out, "vn %.17g %.17g %.17g\n", mesh.normals)
    corner = "%d" + ("/%d" if mesh.uv is not None else "/" if mesh.normals is not None
                     else "") + ("/%d" if mesh.normals is not None else "")
    repeat = corner.count("%d")
    sizes = mesh.face_sizes
    cuts = np.concatenate([[0], np.flatnonzero(np.diff(sizes)) + 1, [len(sizes)]])
    for a, b in zip(cuts[:-1], cuts[1:]):
        n = int(sizes[a])
        block = mesh.face_indices[mesh.face_offsets[a]:mesh.face_offsets[b]].reshape(-1, n) + 1
        _text_rows(out, "f " + " ".join([corner] * n) + "\n", np.repeat(block, repeat, axis=1))
    return out.getvalue().encode("utf-8")


def _ply_point_data(mesh: Mesh) -> Dict[str, NDArray[Any]]:
    """meshio point data of the mesh's normals, uv and vertex colors (PLY properties
    nx ny nz, s t, red green blue alpha)."""
    data: Dict[str, NDArray[Any]] = {}
    if mesh.normals is not None:
        data.update(zip(PLY_NORMALS, mesh.normals.astype(np.float32).T))
    if mesh.uv is not None:
        data.update(zip(PLY_UV[0], mesh.uv.astype(np.float32).T))
    if mesh.colors is not None and mesh.color_on == "vertex":
        data.update(zip(PLY_COLORS[0], np.ascontiguousarray(mesh.colors.T)))
    return data


def save(mesh: Mesh, path: Path) -> None:
    """Write ``mesh`` to an OBJ, PLY, STL, glTF or GLB file (by extension), atomically.

    OBJ and PLY keep every face as it is, with the uv and normals (and in PLY the
    vertex colors); STL (triangles only) and glTF (triangles, with normals, uv,
    vertex colors and the material's diffuse color) get the faces split into
    triangle fans.  A ``.gltf`` file holds its buffer as a data URI (one file).

    Parameters
    ----------
    mesh : Mesh
        The mesh.
    path : str or os.PathLike
        The file, named ``.obj``, ``.ply``, ``.stl``, ``.gltf`` or ``.glb``; a file
        there is replaced.

    Raises
    ------
    ArgumentTypeError
        If ``mesh`` is not a :class:`Mesh` or ``path`` not a file name.
    MeshFileError
        Naming the file, for an unknown extension, a folder, or a file that cannot
        be written (nothing is left of it then).

    Examples
    --------
    >>> import os, tempfile, scanline as sl
    >>> path = os.path.join(tempfile.mkdtemp(), "tetrahedron.stl")
    >>> tetrahedron = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)],
    ...                            [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    >>> sl.mesh.save(tetrahedron, path)
    >>> os.path.getsize(path)             # binary STL: 84 bytes + 50 per triangle
    284
    """
    import meshio

    from ..framebuffer import write_atomically

    if not isinstance(mesh, Mesh):
        raise ArgumentTypeError(f"mesh must be a scanline.mesh.Mesh, got {type(mesh).__name__}")
    filename = _file_name(path)
    if os.path.isdir(filename):
        raise MeshFileError("it is a folder; give a file name", file=filename)
    fmt = _format(filename, path, "write")

    def write(f: BinaryIO) -> None:
        if fmt == "obj":
            f.write(_obj_text(mesh))
            return
        if fmt in ("gltf", "glb"):
            from .gltf import gltf_bytes

            f.write(gltf_bytes(mesh, fmt == "glb"))
            return
        out = meshio.Mesh(mesh.vertices, _cells(mesh, fmt),
                          point_data=_ply_point_data(mesh) if fmt == "ply" else None)
        # meshio writes to a path: a private scratch folder, then the bytes into the
        # atomic writer's file
        with tempfile.TemporaryDirectory(prefix="scanline-mesh-") as folder:
            tmp = os.path.join(folder, "mesh." + fmt)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                getattr(meshio, fmt).write(tmp, out, binary=True)
            with open(tmp, "rb") as src:
                f.write(src.read())
    try:
        write_atomically(filename, write)
    except OSError as error:
        raise MeshFileError(f"cannot write the file: {error.strerror}", file=filename) from None
