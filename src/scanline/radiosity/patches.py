"""Meshes subdivided into patches, the radiosity method's unknowns (Hearn & Baker,
section 14-7; Goral, Torrance, Greenberg and Battaile 1984).

Each face of each mesh is cut into ``subdivisions`` x ``subdivisions`` patches: a
quadrilateral by its bilinear grid (n x n quadrilaterals), a triangle by its
barycentric grid (n x n triangles), a larger polygon by a fan of triangles first.
A patch is stored as four corners -- a triangle repeats its third -- with its area,
its centre (the area centroid), its unit normal (Newell's), and the surface's
emission E and reflectance rho per RGB channel.

The patches of one face share their corner vertices (the *nodes* whose radiosities
Gouraud shading interpolates, Cohen and Greenberg 1985, section 5); faces do not
share nodes, so a corner of the room keeps both walls' colors apart.
"""

import numbers
from dataclasses import dataclass
from typing import Any, List, Optional, Sequence, Tuple

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError

#: Most patches a scene may have: the form factors are an n x n matrix and a
#: hemicube renders every patch once for every patch (n**2 work).
MAX_PATCHES = 60_000

#: The widest scene (units across) the radiosity method takes: beyond it a patch's
#: area or the fourth power of a distance in a form factor could overflow.
MAX_EXTENT = 1e60

#: Largest subdivision of a face (patches per side).
MAX_SUBDIVISIONS = 256

#: Largest emission: radiosities stay far from float64's overflow.
MAX_EMISSION = 1e100

#: A patch whose area is below this fraction of the scene's squared size is
#: degenerate (its normal and form factors are undefined).
DEGENERATE = 1e-12


@dataclass(frozen=True)
class Patches:
    """The patches of a scene (Hearn & Baker 14-7): made by :func:`patches`.

    Parameters
    ----------
    vertices, corners, area, centre, normal, emission, reflectance, mesh, face, cell
        The arrays listed under Attributes.
    subdivisions : int
        Patches per side of each face.

    Attributes
    ----------
    vertices : ndarray (V, 3)
        The nodes: corners of patches, shared by the patches of one face.
    corners : ndarray of int64 (P, 4)
        Each patch's corners, counterclockwise seen from its front (a triangle
        repeats its third corner).
    area, centre, normal : ndarray (P,), (P, 3), (P, 3)
    emission, reflectance : ndarray (P, 3)
        E and rho per RGB channel (linear).
    mesh, face : ndarray of int64 (P,)
        The mesh (its place in the list given) and the face each patch comes from.
    cell : ndarray of int64 (P,)
        The patch's place in its face's grid: row x subdivisions + column for a
        quadrilateral face, -1 for the triangles of other faces.
    subdivisions : int
        Patches per side of each face.

    Examples
    --------
    A 2 x 2 square cut 2 x 2: four unit patches sharing 9 nodes.

    >>> import scanline as sl
    >>> square = sl.mesh.Mesh([(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0)], [[0, 1, 2, 3]])
    >>> p = sl.radiosity.patches(square, subdivisions=2)
    >>> p, p.area.tolist()
    (<Patches: 4 patches, 9 nodes>, [1.0, 1.0, 1.0, 1.0])
    """
    vertices: np.ndarray
    corners: np.ndarray
    area: np.ndarray
    centre: np.ndarray
    normal: np.ndarray
    emission: np.ndarray
    reflectance: np.ndarray
    mesh: np.ndarray
    face: np.ndarray
    cell: np.ndarray
    subdivisions: int

    def __len__(self) -> int:
        return len(self.corners)

    @property
    def quads(self) -> np.ndarray:
        """The patches' corner positions, (P, 4, 3)."""
        positions: np.ndarray = self.vertices[self.corners]
        return positions

    def triangles(self) -> np.ndarray:
        """Two triangles per patch, (2P, 3, 3) (a triangle patch's second one is
        degenerate, which a ray never hits).

        Returns
        -------
        ndarray (2P, 3, 3)
            Corners 0 1 2 of every patch, then corners 0 2 3.

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0)], [[0, 1, 2, 3]])
        >>> p = sl.radiosity.patches(square, subdivisions=2)
        >>> p.triangles().shape
        (8, 3, 3)
        """
        q = self.quads
        return np.concatenate([q[:, [0, 1, 2]], q[:, [0, 2, 3]]])

    def with_values(self, emission: Any = None, reflectance: Any = None) -> "Patches":
        """The same patches with other emission or reflectance (see :func:`patches`).

        Parameters
        ----------
        emission, reflectance : optional
            As :func:`patches` takes them (None: kept).

        Returns
        -------
        Patches
            A new set of the same patches.

        Raises
        ------
        ArgumentValueError
            Values of the wrong shape, negative, or a reflectance of 1 or more.

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0)], [[0, 1, 2, 3]])
        >>> p = sl.radiosity.patches(square, subdivisions=2)
        >>> p.with_values(emission=(1, 0, 0)).emission[0].tolist()
        [1.0, 0.0, 0.0]
        """
        n_meshes = int(self.mesh.max()) + 1
        e = self.emission if emission is None else _per_patch(
            "emission", emission, self.mesh, n_meshes, upper=None)
        r = self.reflectance if reflectance is None else _per_patch(
            "reflectance", reflectance, self.mesh, n_meshes, upper=1.0)
        return Patches(self.vertices, self.corners, self.area, self.centre, self.normal, e, r,
                       self.mesh, self.face, self.cell, self.subdivisions)

    def groups(self, size: int) -> np.ndarray:
        """A group number per patch: the patches of a quadrilateral face in blocks of
        ``size`` x ``size`` of its grid (the *patches* that shoot, of Cohen, Greenberg,
        Immel and Brock 1986, these patches being their *elements*); each triangle on
        its own.

        Parameters
        ----------
        size : int
            Patches per side of a block.

        Returns
        -------
        ndarray of int64 (P,)
            The group of each patch, numbered from 0.

        Examples
        --------
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0)], [[0, 1, 2, 3]])
        >>> p = sl.radiosity.patches(square, subdivisions=2)
        >>> p.groups(2).tolist(), p.groups(1).tolist()
        ([0, 0, 0, 0], [0, 1, 2, 3])
        """
        size = v.positive_int("size", size)
        n = self.subdivisions
        quad = self.cell >= 0
        row, col = self.cell // n, self.cell % n
        blocks = -(-n // size)
        key = np.where(quad, (self.mesh * (int(self.face.max()) + 1) + self.face) * blocks ** 2
                       + (row // size) * blocks + col // size, -1 - np.arange(len(self)))
        return np.unique(key, return_inverse=True)[1].reshape(-1).astype(np.int64)

    def check(self) -> None:
        """Refuse patches made by hand whose arrays disagree (the kernels index them
        by one another): shapes, corner indices in range, finite values.

        Raises
        ------
        ArgumentValueError
            Arrays of disagreeing shapes, values not finite, corners out of range, or
            areas not > 0.

        Examples
        --------
        >>> from dataclasses import replace
        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0)], [[0, 1, 2, 3]])
        >>> p = sl.radiosity.patches(square, subdivisions=2)
        >>> p.check()
        >>> replace(p, area=-p.area).check()
        Traceback (most recent call last):
        ...
        scanline.errors.ArgumentValueError: meshes: the Patches' corners must be vertex numbers, their meshes numbered from 0 and their areas > 0
        """
        p = len(self.corners)
        shapes = {"vertices": (len(self.vertices), 3), "corners": (p, 4), "area": (p,),
                  "centre": (p, 3), "normal": (p, 3), "emission": (p, 3),
                  "reflectance": (p, 3), "mesh": (p,), "face": (p,), "cell": (p,)}
        for name, shape in shapes.items():
            value = np.asarray(getattr(self, name))
            if value.shape != shape or value.dtype.kind not in "iuf":
                raise ArgumentValueError(f"meshes: the Patches' {name} must have shape {shape}, "
                                         f"got {value.shape} of {value.dtype}; make patches "
                                         "with scanline.radiosity.patches")
            if value.dtype.kind == "f" and not np.isfinite(value).all():
                raise ArgumentValueError(f"meshes: the Patches' {name} must be finite")
        if p == 0 or self.corners.min() < 0 or self.corners.max() >= len(self.vertices) \
                or self.mesh.min() < 0 or not (self.area > 0).all():
            raise ArgumentValueError("meshes: the Patches' corners must be vertex numbers, "
                                     "their meshes numbered from 0 and their areas > 0")

    def __repr__(self) -> str:
        return f"<Patches: {len(self)} patches, {len(self.vertices)} nodes>"


def mesh_list(meshes: Any) -> List[Any]:
    """``meshes`` as a list of :class:`~scanline.mesh.Mesh` (one mesh, or a list)."""
    from ..mesh import Mesh

    items = [meshes] if isinstance(meshes, Mesh) else meshes
    if isinstance(items, (str, bytes)) or not hasattr(items, "__iter__"):
        raise ArgumentTypeError(f"meshes must be a scanline.mesh.Mesh or a list of them, got "
                                f"{v._show(meshes)}")
    items = list(items)
    for k, m in enumerate(items):
        if not isinstance(m, Mesh):
            raise ArgumentTypeError(f"meshes[{k}] must be a scanline.mesh.Mesh, got "
                                    f"{v._show(m)}")
    if not items:
        raise ArgumentValueError("meshes is empty: give at least one mesh")
    return items


def patches(meshes: Any, subdivisions: int = 8, emission: Any = None,
            reflectance: Any = None) -> Patches:
    """Subdivide ``meshes`` into patches.

    Parameters
    ----------
    meshes : Mesh or list of Mesh
        Faces counterclockwise seen from the side that receives and emits light.
    subdivisions : int
        Patches per side of each face (1 to 256).
    emission : optional
        E, the light each patch emits (radiosity units, linear): one value or (r, g,
        b) per mesh (a list as long as ``meshes``), or one per patch ((P,) or (P, 3));
        a single number or triple for every mesh.  Default: nothing emits.
    reflectance : optional
        rho in [0, 1) per channel, given as ``emission``.  Default: the diffuse
        reflection that :func:`scanline.render` shades each surface with, kd x S_d:
        the mesh's material (default ``Material()``, kd = 0.7) and its face colors
        (else the material's color), decoded to linear light.

    Returns
    -------
    Patches
        The patches, each face's sharing its nodes.

    Raises
    ------
    ArgumentTypeError
        ``meshes`` not meshes.
    ArgumentValueError
        Too many patches, a subdivision outside 1..256, or bad values.

    Examples
    --------
    >>> import scanline as sl
    >>> square = sl.mesh.Mesh([(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0)], [[0, 1, 2, 3]])
    >>> p = sl.radiosity.patches(square, subdivisions=2)
    >>> p.centre.tolist()                 # patches row by row from the bottom
    [[0.5, 0.5, 0.0], [1.5, 0.5, 0.0], [0.5, 1.5, 0.0], [1.5, 1.5, 0.0]]
    """
    items = mesh_list(meshes)
    n = v.positive_int("subdivisions", subdivisions)
    if n > MAX_SUBDIVISIONS:
        raise ArgumentValueError(f"subdivisions must be at most {MAX_SUBDIVISIONS}, got {n}")
    count = sum(int(np.where(m.face_sizes == 4, 1, m.face_sizes - 2).sum()) for m in items) * n * n
    if count > MAX_PATCHES:
        raise ArgumentValueError(
            f"meshes with subdivisions={n} make {count:,} patches, more than the "
            f"{MAX_PATCHES:,} the radiosity method handles (its form factors are a "
            f"patches x patches matrix): give fewer faces or a smaller subdivisions")
    parts = [_subdivide(m, n) for m in items]
    nodes = np.cumsum([0] + [len(p[0]) for p in parts])
    verts = np.concatenate([p[0] for p in parts])
    corners = np.concatenate([p[1] + base for p, base in zip(parts, nodes)])
    owner = np.concatenate([np.full(len(p[1]), k, np.int64) for k, p in enumerate(parts)])
    face = np.concatenate([p[2] for p in parts])
    cell = np.concatenate([p[3] for p in parts])
    with np.errstate(over="ignore", invalid="ignore"):
        extent = float(np.ptp(verts, axis=0).max())
    if not extent <= MAX_EXTENT:
        raise ArgumentValueError(
            f"meshes span {extent:.3g} units: the radiosity method takes scenes up to "
            f"{MAX_EXTENT:.0e} across (patch areas and the distances of the form factors "
            "must stay finite); scale the meshes down")
    area, centre, normal = _geometry(verts[corners])
    scale = extent ** 2
    flat = np.flatnonzero(~(area > DEGENERATE * scale))
    if len(flat):
        p = int(flat[0])
        raise ArgumentValueError(
            f"meshes[{int(owner[p])}] face {int(face[p])} is degenerate (area "
            f"{float(area[p]):.3g}): a patch needs an area and a normal; remove faces whose "
            f"vertices are collinear or coincide")
    e = np.zeros((len(corners), 3)) if emission is None else _per_patch(
        "emission", emission, owner, len(items), upper=None)
    r = _default_reflectance(items, owner, face) if reflectance is None else _per_patch(
        "reflectance", reflectance, owner, len(items), upper=1.0)
    return Patches(verts, corners, area, centre, normal, e, r, owner, face, cell, n)


def _subdivide(mesh: Any, n: int) -> Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(nodes (V, 3), corners (P, 4), face of each patch (P,), its cell (P,)) of one
    mesh."""
    idx, off, sizes = mesh.face_indices, mesh.face_offsets, mesh.face_sizes
    pos = mesh.vertices
    out_v, out_c, out_f, out_k = [], [], [], []
    base = 0
    quads = np.flatnonzero(sizes == 4)
    if len(quads):
        c = pos[idx[off[quads][:, None] + np.arange(4)]]                 # (Q, 4, 3)
        s = np.linspace(0.0, 1.0, n + 1)
        a, b = s[:, None, None], s[None, :, None]                          # rows t, columns s
        grid = ((1 - a) * (1 - b) * c[:, None, None, 0] + (1 - a) * b * c[:, None, None, 1]
                + a * b * c[:, None, None, 2] + a * (1 - b) * c[:, None, None, 3])
        out_v.append(grid.reshape(-1, 3))
        k = np.arange(n)
        cell = (k[:, None] * (n + 1) + k[None, :]).reshape(-1)              # (row, column)
        local = np.stack([cell, cell + 1, cell + n + 2, cell + n + 1], axis=1)
        starts = base + np.arange(len(quads)) * (n + 1) ** 2
        out_c.append((starts[:, None, None] + local[None]).reshape(-1, 4))
        out_f.append(np.repeat(quads, n * n))
        out_k.append(np.tile(np.arange(n * n), len(quads)))
        base += len(quads) * (n + 1) ** 2
    others = np.flatnonzero(sizes != 4)
    if len(others):
        # fans of triangles (first vertex, k + 1, k + 2) of the other faces
        per = sizes[others] - 2
        owner = np.repeat(others, per)
        k = np.arange(len(owner)) - np.repeat(np.cumsum(per) - per, per)
        first = off[owner]
        c = pos[np.stack([idx[first], idx[first + k + 1], idx[first + k + 2]], axis=1)]
        i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="ij")
        keep = i + j <= n
        i, j = i[keep], j[keep]                                 # node (i, j): weights i/n, j/n
        number = -np.ones((n + 1, n + 1), np.int64)
        number[i, j] = np.arange(len(i))
        w1, w2 = (i / n)[None, :, None], (j / n)[None, :, None]
        out_v.append(((1 - w1 - w2) * c[:, None, 0] + w1 * c[:, None, 1]
                      + w2 * c[:, None, 2]).reshape(-1, 3))
        up_i, up_j = np.nonzero((np.add.outer(np.arange(n), np.arange(n))) < n)
        up = np.stack([number[up_i, up_j], number[up_i + 1, up_j], number[up_i, up_j + 1],
                       number[up_i, up_j + 1]], axis=1)
        dn_i, dn_j = np.nonzero((np.add.outer(np.arange(n), np.arange(n))) < n - 1)
        dn = np.stack([number[dn_i + 1, dn_j], number[dn_i + 1, dn_j + 1],
                       number[dn_i, dn_j + 1], number[dn_i, dn_j + 1]], axis=1)
        local = np.concatenate([up, dn])                                    # n * n triangles
        starts = base + np.arange(len(owner)) * len(i)
        out_c.append((starts[:, None, None] + local[None]).reshape(-1, 4))
        out_f.append(np.repeat(owner, n * n))
        out_k.append(np.full(len(owner) * n * n, -1))
    order = np.argsort(np.concatenate(out_f), kind="stable")       # patches in face order
    return (np.concatenate(out_v), np.concatenate(out_c)[order].astype(np.int64),
            np.concatenate(out_f)[order].astype(np.int64),
            np.concatenate(out_k)[order].astype(np.int64))


def _geometry(q: np.ndarray) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Area, area centroid and unit normal of quadrilaterals ``q`` (P, 4, 3) (as the
    triangles (0, 1, 2) and (0, 2, 3))."""
    c1 = np.cross(q[:, 1] - q[:, 0], q[:, 2] - q[:, 0])
    c2 = np.cross(q[:, 2] - q[:, 0], q[:, 3] - q[:, 0])
    a1 = 0.5 * np.sqrt((c1 * c1).sum(axis=1))
    a2 = 0.5 * np.sqrt((c2 * c2).sum(axis=1))
    area = a1 + a2
    with np.errstate(invalid="ignore", divide="ignore"):
        centre = (a1[:, None] * (q[:, 0] + q[:, 1] + q[:, 2])
                  + a2[:, None] * (q[:, 0] + q[:, 2] + q[:, 3])) / (3 * area[:, None])
        newell = np.cross(q[:, 2] - q[:, 0], q[:, 3] - q[:, 1])    # twice the vector area
        normal = newell / np.sqrt((newell * newell).sum(axis=1))[:, None]
    return area, centre, normal


def _per_patch(name: str, value: Any, owner: np.ndarray, n_meshes: int,
               upper: Optional[float]) -> np.ndarray:
    """(P, 3) values of ``name`` given per mesh or per patch, checked: finite, >= 0 and
    below ``upper`` where there is one."""
    p = len(owner)
    if isinstance(value, (list, tuple)) and len(value) == n_meshes \
            and not all(isinstance(x, numbers.Real) for x in value):
        # one item per mesh, each a number or (r, g, b)
        rows = [v.real_array(f"{name}[{k}]", x, "a number or (r, g, b)") for k, x in
                enumerate(value)]
        for k, row in enumerate(rows):
            if row.shape not in ((), (1,), (3,)):
                raise ArgumentValueError(f"{name}[{k}] must be a number or (r, g, b), got "
                                         f"shape {row.shape}")
        value = np.array([np.broadcast_to(row.reshape(-1), (3,)) for row in rows])
    arr = v.real_array(name, value, "a number, (r, g, b), one per mesh or one per patch")
    if arr.ndim == 0 or arr.shape == (3,):
        out = np.broadcast_to(arr, (p, 3))
    elif arr.shape in ((n_meshes,), (n_meshes, 3)) and n_meshes != p:
        out = np.broadcast_to(arr.reshape(n_meshes, -1), (n_meshes, 3))[owner]
    elif arr.shape in ((p,), (p, 3)):
        out = np.broadcast_to(arr.reshape(p, -1), (p, 3))
    else:
        raise ArgumentValueError(
            f"{name} has shape {arr.shape}: give one value or (r, g, b) for all, one per mesh "
            f"({n_meshes}) or one per patch ({p})")
    if not np.isfinite(out).all():
        raise ArgumentValueError(f"{name} must be finite (got NaN or infinity)")
    if (out < 0).any():
        raise ArgumentValueError(f"{name} must be >= 0, got {float(out.min())!r}")
    if upper is None and (out > MAX_EMISSION).any():
        raise ArgumentValueError(f"{name} must be at most {MAX_EMISSION:g}, got "
                                 f"{float(out.max())!r}")
    if upper is not None and (out >= upper).any():
        raise ArgumentValueError(
            f"{name} must be below {upper:g} on every channel (a surface that reflects all "
            f"the light it receives makes the radiosity equations singular), got "
            f"{float(out.max())!r}")
    return np.array(out, np.float64)


def _default_reflectance(items: Sequence[Any], owner: np.ndarray,
                         face: np.ndarray) -> np.ndarray:
    """kd x S_d per patch: each mesh's material (default ``Material()``) and its
    colors (per face, or the mean of a face's vertex colors), linear."""
    from ..lighting import Material
    from ..shading import decode

    out = np.empty((len(owner), 3))
    for k, mesh in enumerate(items):
        sel = owner == k
        mat = mesh.material if isinstance(mesh.material, Material) else Material()
        if mesh.colors is None:
            color = np.broadcast_to(decode(np.asarray(mat.color, np.float64)[:3]), (sel.sum(), 3))
        elif mesh.color_on == "face":
            color = decode(mesh.colors[face[sel], :3] / 255.0)
        else:
            per_face = np.add.reduceat(decode(mesh.colors[mesh.face_indices, :3] / 255.0),
                                       mesh.face_offsets[:-1]) / mesh.face_sizes[:, None]
            color = per_face[face[sel]]
        out[sel] = mat.kd * color
    return np.minimum(out, np.nextafter(1.0, 0.0))
