"""Reading and writing meshes: Wavefront OBJ, PLY (ASCII and binary) and STL,
through meshio.

meshio keeps polygon faces as they are (a cube's quadrilaterals stay
quadrilaterals in OBJ and PLY; trimesh would triangulate them); STL holds only
triangles, so faces are split into triangle fans when writing it.  Every failure is
a :class:`MeshFileError` naming the file: unreadable, truncated or garbage files,
counts that do not fit the file, faces that refer to missing vertices, NaN
coordinates.  Writing is atomic: a failure leaves no partial file.
"""

import os
import tempfile
import warnings

import numpy as np

from ..errors import ArgumentValueError
from .mesh import Mesh

#: File types by extension.
FORMATS = {".obj": "obj", ".ply": "ply", ".stl": "stl"}

#: The largest mesh file read (bytes); larger ones are refused before parsing.
MAX_FILE_BYTES = 2 << 30


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


def _ply_counts_fit(name, size):
    """Refuse a PLY header whose element counts cannot fit in the file (each vertex
    or face takes at least one byte), before meshio allocates for them."""
    with open(name, "rb") as f:
        head = f.read(4096)
    if not head.startswith(b"ply"):
        return
    for line in head.split(b"\n"):
        parts = line.split()
        if len(parts) == 3 and parts[0] == b"element":
            try:
                count = int(parts[2])
            except ValueError:
                raise MeshFileError(f"the PLY header's element count {parts[2]!r} is not a "
                                    "number", file=name) from None
            if count < 0 or count > size:
                raise MeshFileError(
                    f"the PLY header announces {count} {parts[1].decode(errors='replace')} "
                    f"elements, more than the file's {size} bytes can hold: the file is "
                    "truncated or broken", file=name)
        if line.strip() == b"end_header":
            break


def load(path, name=None):
    """Read a mesh from an OBJ, PLY or STL file.

    Faces of every polygon type in the file are kept (triangles, quadrilaterals,
    polygons); points and lines are ignored.

    Raises
    ------
    MeshFileError
        Naming the file, for a missing, unreadable, truncated, oversized or garbage
        file, or one with no faces, faces that refer to missing vertices, or
        coordinates that are not finite numbers.

    Examples
    --------
    >>> import os, tempfile, scanline as sl
    >>> path = os.path.join(tempfile.mkdtemp(), "cube.obj")
    >>> sl.mesh.cube().save(path)
    >>> sl.mesh.load(path)
    <Mesh 'cube.obj': 8 vertices, 6 faces, 12 edges>
    """
    import meshio

    filename = os.fspath(path)
    if os.path.isdir(filename):
        raise MeshFileError("it is a folder, not a mesh file", file=filename)
    fmt = _format(filename, path, "read")
    try:
        size = os.path.getsize(filename)
    except OSError as error:
        raise MeshFileError(f"cannot read the file: {error.strerror}", file=filename) from None
    if size > MAX_FILE_BYTES:
        raise MeshFileError(f"the file is {size} bytes; the limit is {MAX_FILE_BYTES}",
                            file=filename)
    if fmt == "ply":
        _ply_counts_fit(filename, size)
    try:
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore")
            # the format's own reader: meshio.read() prints and calls sys.exit on a
            # ReadError
            data = getattr(meshio, fmt).read(filename)
    except MemoryError:
        raise MeshFileError("the file announces more data than fits in memory: it is "
                            "truncated or broken", file=filename) from None
    except UnicodeDecodeError:
        raise MeshFileError(f"the file is not a readable {fmt.upper()} file (it holds bytes "
                            "that are not text where text is expected)", file=filename) from None
    except Exception as error:   # meshio raises many kinds: ReadError, ValueError, ...
        text = str(error).strip().splitlines()[0] if str(error).strip() else type(error).__name__
        raise MeshFileError(f"the file is not a readable {fmt.upper()} file ({text})",
                            file=filename) from None
    faces = []
    for block in data.cells:
        if block.dim == 2 or block.type in ("triangle", "quad", "polygon"):
            faces.extend(np.asarray(block.data, np.int64).reshape(len(block.data), -1).tolist()
                         if not isinstance(block.data, list) else block.data)
    points = np.asarray(data.points, np.float64)
    if points.size == 0:
        raise MeshFileError(f"the file holds no vertices: it is empty, truncated or not "
                            f"{fmt.upper()}", file=filename)
    if points.ndim != 2 or points.shape[1] not in (2, 3):
        raise MeshFileError(f"the file's vertices have shape {points.shape}, not (V, 3)",
                            file=filename)
    if points.shape[1] == 2:
        points = np.hstack([points, np.zeros((len(points), 1))])
    if not faces:
        raise MeshFileError(f"the file holds no faces ({len(points)} vertices)", file=filename)
    try:
        return Mesh(points, faces, name=name or os.path.basename(filename))
    except ArgumentValueError as error:
        raise MeshFileError(f"the file's mesh is broken: {error}", file=filename) from None


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
        raise ArgumentValueError(f"mesh must be a scanline.mesh.Mesh, got {type(mesh).__name__}")
    filename = os.fspath(path)
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
