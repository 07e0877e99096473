"""Reading and writing meshes: Wavefront OBJ, PLY (ASCII and binary) and STL.

meshio writes all three and reads PLY and STL; OBJ is read here (a small reader that
names the line of every error, and takes OBJ's relative (negative) indices).  Faces
keep their polygons (a cube's quadrilaterals stay quadrilaterals in OBJ and PLY;
trimesh would triangulate them); STL holds only triangles, so faces are split into
triangle fans when writing it.

Reading is guarded against hostile files (docs/three-d.md, "Mesh files"):

- only a regular file is read: the file is opened without blocking (``O_NONBLOCK``,
  so a FIFO cannot hang the call) and checked with ``fstat`` after opening; a FIFO, a
  device (``/dev/zero``), a socket or a folder is refused, and a symbolic link is
  followed only to a regular file;
- its size is checked after opening, against ``max_bytes`` (default
  :data:`MAX_FILE_BYTES`) and against the memory budget (:mod:`scanline.budget`: the
  reading takes about :data:`READ_BYTES_PER_BYTE` bytes of memory per byte of file),
  and at most its size and one byte are read, so a file that grows meanwhile is
  refused too;
- a PLY header must end (``end_header``) within :data:`MAX_PLY_HEADER` bytes, name
  known property types, and announce element counts that the bytes after it can hold.

Every failure is a :class:`MeshFileError` naming the file (and, in an OBJ file, the
line): unreadable, truncated or garbage files, counts that do not fit the file,
faces that refer to missing vertices, NaN coordinates.  Writing is atomic: a failure
leaves no partial file.
"""

import io
import math
import os
import re
import stat
import tempfile
import warnings
from array import array

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from .mesh import Flat, Mesh

#: File types by extension.
FORMATS = {".obj": "obj", ".ply": "ply", ".stl": "stl"}

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
    """A mesh file that cannot be read or written; ``file`` names it."""

    def __init__(self, message, file=None):
        self.file = file
        self.message = message
        super().__init__(f"{file}: {message}" if file else message)


def _format(name, path, what):
    ext = os.path.splitext(name)[1].lower()
    if ext not in FORMATS:
        raise MeshFileError(f"cannot {what} {ext or 'a file without extension'}: use one of "
                            + ", ".join(FORMATS), file=name)
    return FORMATS[ext]


def _file_name(path, what="path"):
    if not isinstance(path, (str, os.PathLike)):
        raise ArgumentTypeError(f"{what} must be a file name (str or os.PathLike), got "
                                f"{v._show(path)} of type {type(path).__name__}")
    name = os.fspath(path)
    if isinstance(name, bytes):
        name = os.fsdecode(name)
    if "\0" in name:
        raise MeshFileError("the file name has a NUL character", file=name)
    return name


def _max_bytes(value):
    if value is None:
        return MAX_FILE_BYTES
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise ArgumentTypeError(f"max_bytes must be an integer number of bytes (or None: "
                                f"{MAX_FILE_BYTES:,}), got {v._show(value)}")
    if value < 0:
        raise ArgumentValueError(f"max_bytes must be >= 0, got {value}")
    return int(value)


def read_regular_file(filename, limit, limit_name="max_bytes", budget_name="path"):
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
            chunks, left = [], size + 1
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


# -- OBJ ---------------------------------------------------------------------------------
def _read_obj(data, filename):
    """(vertices (V, 3), Flat faces, the line of each face) of Wavefront OBJ text:
    ``v x y z [w]`` vertices (extra values, a w or a color, are ignored) and
    ``f i j k ...`` faces of 1-based vertex indices (``i/t/n`` forms take i; a
    negative index counts back from the last vertex read); other statements
    (texture coordinates, normals, groups, materials, lines) are ignored."""
    def fail(number, message):
        raise MeshFileError(f"line {number}: {message}", file=filename)

    coords = array("d")
    indices = array("q")
    sizes = array("q")
    lines = array("q")
    # no file can hold more vertices than it has bytes: an index beyond that is
    # refused on its line, before it is stored
    most = max(len(data), 1)
    for number, raw in enumerate(io.BytesIO(data), 1):
        words = raw.split(b"#", 1)[0].split()
        if not words:
            continue
        key = words[0]
        if key == b"v":
            if len(words) < 4:
                fail(number, f"a vertex needs three coordinates (v x y z), got "
                     f"{b' '.join(words).decode(errors='replace')!r}")
            try:
                xyz = [float(w) for w in words[1:4]]
            except ValueError:
                fail(number, "the vertex coordinates "
                     f"{b' '.join(words[1:4]).decode(errors='replace')!r} are not numbers")
            if not all(math.isfinite(c) for c in xyz):
                fail(number, f"the vertex coordinates {xyz} are not all finite numbers")
            coords.extend(xyz)
        elif key == b"f":
            count = len(coords) // 3
            if len(words) < 4:
                fail(number, f"a face needs at least three vertices, got {len(words) - 1}")
            for word in words[1:]:
                text = word.split(b"/", 1)[0]
                try:
                    i = int(text)
                except ValueError:
                    fail(number, f"the face's vertex index {word.decode(errors='replace')!r} "
                         "is not an integer")
                if i < 0:
                    i += count            # relative: -1 is the last vertex read so far
                    if i < 0:
                        fail(number, f"the relative vertex index {text.decode()} reaches back "
                             f"before the first vertex ({count} read so far)")
                elif i == 0:
                    fail(number, "vertex index 0: OBJ counts vertices from 1")
                else:
                    if i > most:
                        fail(number, f"the face refers to vertex {i}, out of range: the file "
                             f"cannot hold that many vertices ({len(data):,} bytes)")
                    i -= 1
                indices.append(i)
            sizes.append(len(words) - 1)
            lines.append(number)
    vertices = np.frombuffer(coords, np.float64).reshape(-1, 3) if len(coords) \
        else np.zeros((0, 3))
    idx = np.frombuffer(indices, np.int64) if len(indices) else np.zeros(0, np.int64)
    nv = len(vertices)
    if len(idx) and nv and int(idx.max()) >= nv:
        k = int(np.argmax(idx >= nv))
        face = int(np.searchsorted(np.cumsum(np.frombuffer(sizes, np.int64)), k, side="right"))
        fail(lines[face], f"the face refers to vertex {int(idx[k]) + 1}, out of range: the file "
             f"has {nv} vertices")
    return (vertices, Flat(idx, np.frombuffer(sizes, np.int64) if len(sizes)
                           else np.zeros(0, np.int64)), lines)


# -- PLY ---------------------------------------------------------------------------------
#: Bytes of each PLY property type.
PLY_TYPES = {"char": 1, "uchar": 1, "int8": 1, "uint8": 1, "short": 2, "ushort": 2,
             "int16": 2, "uint16": 2, "int": 4, "uint": 4, "int32": 4, "uint32": 4,
             "float": 4, "float32": 4, "double": 8, "float64": 8, "int64": 8, "uint64": 8}


def _ply_header(data, filename):
    """Check a PLY header before meshio reads it: the magic line, ``end_header``
    within :data:`MAX_PLY_HEADER` bytes, the format, known property types, and
    element counts that the bytes after the header can hold (each element takes at
    least its fixed properties' bytes, or two characters per value in ASCII; a face
    at least three indices)."""
    def fail(message):
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
    elements = []
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
            elements.append([words[1], int(words[2]), 0, 0])   # name, count, bytes, values
        elif words[0] == "property":
            if not elements:
                fail("the PLY header has a property before any element")
            element = elements[-1]
            if len(words) == 5 and words[1] == "list":
                types = words[2:4]
                least = 3 if element[0] == "face" else 0
            elif len(words) == 3:
                types, least = words[1:2], None
            else:
                fail(f"the PLY header's property line {' '.join(words)!r} is malformed")
            for t in types:
                if t not in PLY_TYPES:
                    fail(f"the PLY property type {t!r} is not one of "
                         + ", ".join(sorted(PLY_TYPES)))
            if least is None:
                element[2] += PLY_TYPES[types[0]]
                element[3] += 1
            else:
                element[2] += PLY_TYPES[types[0]] + least * PLY_TYPES[types[1]]
                element[3] += 1 + least
        elif words[0] != "ply":
            fail(f"the PLY header has an unknown line {' '.join(words)[:60]!r}")
    if ascii_ is None:
        fail("the PLY header has no format line")
    need = 0
    for name, count, nbytes, values in elements:
        if values == 0 and count:
            fail(f"the PLY element {name!r} has no properties but a count of {count}")
        need += count * (2 * values if ascii_ else nbytes)
        # (ASCII: a value and its separator, but the last line may lack its newline)
        if need - bool(ascii_) > body:
            fail(f"the PLY header announces {count:,} {name} elements, more than the file's "
                 f"{body:,} bytes after the header can hold: the file is truncated or broken")


def _read_stl(meshio, data):
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
            return meshio.Mesh(points, cells)
    f = io.BytesIO(data)
    if len(data) >= 80:
        f.readline()                 # the 'solid NAME' line
    return _stl._read_ascii(f)


def load(path, name=None, max_bytes=None):
    """Read a mesh from an OBJ, PLY or STL file.

    Faces of every polygon type in the file are kept (triangles, quadrilaterals,
    polygons); points and lines are ignored.

    Parameters
    ----------
    path : str or os.PathLike
        A regular file (or a symbolic link to one) named ``.obj``, ``.ply`` or ``.stl``.
    name : str, optional
        The mesh's name (default: the file's).
    max_bytes : int, optional
        The largest file read (default :data:`MAX_FILE_BYTES`, 2 GiB); the memory
        budget (:mod:`scanline.budget`) applies as well.

    Raises
    ------
    MeshFileError
        Naming the file, for a missing, unreadable, truncated, oversized or garbage
        file, or one that is not a regular file (a FIFO, a device, a folder), a PLY
        header without ``end_header`` or with counts the file cannot hold, or a mesh
        with no faces, faces that refer to missing vertices, or coordinates that are
        not finite numbers (in an OBJ file the message names the line).
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
    filename = _file_name(path)
    if name is not None and not isinstance(name, str):
        raise ArgumentTypeError(f"name must be a string or None, got {v._show(name)}")
    limit = _max_bytes(max_bytes)
    fmt = _format(filename, path, "read")
    data = read_regular_file(filename, limit)
    mesh_name = name or os.path.basename(filename)
    if fmt == "obj":
        points, faces, lines = _read_obj(data, filename)
        if len(points) == 0:
            raise MeshFileError("the file holds no vertices: it is empty, truncated or not "
                                "OBJ", file=filename)
        if len(faces.sizes) == 0:
            raise MeshFileError(f"the file holds no faces ({len(points)} vertices)",
                                file=filename)
        try:
            return Mesh(points, faces, name=mesh_name)
        except ArgumentValueError as error:
            text = str(error)
            which = re.match(r"face (\d+)", text)
            where = f"line {lines[int(which.group(1))]}: " if which else ""
            raise MeshFileError(f"{where}the file's mesh is broken: {text}",
                                file=filename) from None
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


def _from_meshio(data, fmt, filename, mesh_name):
    """A Mesh from what meshio read."""
    indices, sizes = [], []
    try:
        with np.errstate(all="ignore"):
            for block in data.cells:
                if not (block.dim == 2 or block.type in ("triangle", "quad", "polygon")):
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
    if not indices or not sum(len(s) for s in sizes):
        raise MeshFileError(f"the file holds no faces ({len(points)} vertices)", file=filename)
    try:
        idx = v.index_array("faces", np.concatenate(indices), what="vertex indices",
                            high=len(points) - 1,
                            bound_text=f" (the file has {len(points)} vertices)")
        return Mesh(points, Flat(idx, np.concatenate(sizes)), name=mesh_name)
    except ArgumentValueError as error:
        raise MeshFileError(f"the file's mesh is broken: {error}", file=filename) from None
    except ArgumentTypeError as error:
        raise MeshFileError(f"the file is not a readable {fmt.upper()} file ({error})",
                            file=filename) from None


def _cells(mesh, fmt):
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


def save(mesh, path):
    """Write ``mesh`` to an OBJ, PLY or STL file (by extension), atomically.

    OBJ and PLY keep every face as it is; STL gets the faces split into triangle
    fans.  Colors and normals are not written."""
    import meshio

    from ..framebuffer import write_atomically

    if not isinstance(mesh, Mesh):
        raise ArgumentTypeError(f"mesh must be a scanline.mesh.Mesh, got {type(mesh).__name__}")
    filename = _file_name(path)
    if os.path.isdir(filename):
        raise MeshFileError("it is a folder; give a file name", file=filename)
    fmt = _format(filename, path, "write")
    out = meshio.Mesh(mesh.vertices, _cells(mesh, fmt))

    def write(f):
        # meshio writes to a path: a private scratch folder, then the bytes into the
        # atomic writer's file
        with tempfile.TemporaryDirectory(prefix="scanline-mesh-") as folder:
            tmp = os.path.join(folder, "mesh." + fmt)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                getattr(meshio, fmt).write(tmp, out, **({"binary": True} if fmt in ("stl", "ply")
                                                         else {}))
            with open(tmp, "rb") as src:
                f.write(src.read())
    try:
        write_atomically(filename, write)
    except OSError as error:
        raise MeshFileError(f"cannot write the file: {error.strerror}", file=filename) from None
