"""Cutaway views (Hearn & Baker, section 9-1, "Exploded and Cutaway Views"): clipping
planes through a model remove part of it to show what is inside, and the cut face is
drawn (*capped*) so that a solid looks solid.

Each plane (A, B, C, D) keeps the part of every mesh where A x + B y + C z + D >= 0
(the side its normal (A, B, C) points to, as OpenGL's user clip planes).  The
faces are clipped against one plane after another, each edge that crosses a plane
getting one new vertex shared by the two faces on it (the cut of each convex face is
Sutherland and Hodgman's polygon clipper against one plane, section 6-8, the same
as :mod:`scanline._kernels.planecut` does for depth sort and BSP trees, here on the
mesh's triangles with the mesh's connectivity kept).  The clipped surface's border
edges that lie in the plane form the plane's *intersection loops*; where a loop is
closed (a closed mesh always gives closed loops) it bounds the cap: loops
counterclockwise about the cap's normal (-A, -B, -C) are outer boundaries, clockwise
ones holes (a torus cut through its hole gives a ring), and the cap polygons are
triangulated with their holes by mapbox's earcut.  A closed mesh stays closed: the
caps use the loops' own vertices, so every edge of the clipped and capped surface
borders two faces.  Open loops (a mesh with a hole where the plane passes) are left
uncapped.  A face lying in a plane is kept where it faces the removed side (it is then
part of the cut face itself) and removed where it faces the kept side.
"""

from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Set, Tuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._typing import Color
from ..errors import ArgumentValueError
from ..mesh import Mesh
from ..mesh.mesh import check_mesh_budget
from .exploded import _parts

#: Distances from a plane, relative to the model's size, within which a vertex is
#: taken to lie in the plane.
EPS = 1e-12


@dataclass(frozen=True)
class Cutaway:
    """What :func:`cutaway` returns.

    Parameters
    ----------
    meshes, caps, loops, closed : list
        As listed under Attributes, one entry per input mesh.

    Examples
    --------
    A plane that cuts nothing away (x + 5 >= 0 on the whole cube): the mesh whole
    (its squares as triangles), no cap.

    >>> import scanline as sl
    >>> cut = sl.draw3d.cutaway(sl.mesh.cube(2.0), (1, 0, 0, 5))
    >>> cut.meshes, cut.caps
    ([<Mesh: 8 vertices, 12 faces, 18 edges>], [None])

    Attributes
    ----------
    meshes : list of Mesh or None
        The clipped surfaces, one per input mesh (open where they were cut), with
        the faces' colors, normals, uv and vertex colors (interpolated at the cuts);
        None where the planes cut all of a mesh away.
    caps : list of Mesh or None
        For each mesh, its cap polygons as triangles (normals: the planes' cap
        normals), in ``cap_color``; None where nothing was capped.
    loops : list of list of ndarray
        For each mesh, its closed intersection loops, each (k, 3), counterclockwise
        seen from the removed side.
    closed : list of Mesh or None
        For each mesh, the clipped surface and its caps as one mesh sharing the
        loops' vertices (no normals: a closed mesh stays closed, every edge shared by
        two faces).
    """

    meshes: List[Optional[Mesh]]
    caps: List[Optional[Mesh]]
    loops: List[List[NDArray[np.float64]]]
    closed: List[Optional[Mesh]]

    def drawable(self) -> List[Mesh]:
        """The clipped meshes and the caps there are: the list to render.

        Returns
        -------
        list of Mesh
            The meshes, then the caps, without the Nones.

        Examples
        --------
        Half the cube and its cap at x = 0:

        >>> import scanline as sl
        >>> sl.draw3d.cutaway(sl.mesh.cube(2.0), (1, 0, 0, 0)).drawable()
        [<Mesh: 12 vertices, 14 faces, 25 edges>, <Mesh: 18 vertices, 6 faces, 18 edges>]
        """
        return [m for m in list(self.meshes) + list(self.caps) if m is not None]


def _planes(planes: ArrayLike) -> NDArray[np.float64]:
    p = v.real_array("planes", planes, "(A, B, C, D) or (N, 4)")
    if p.ndim == 1:
        p = p[None, :]
    if p.ndim != 2 or p.shape[1] != 4 or len(p) == 0:
        raise ArgumentValueError(
            f"planes must be one plane (A, B, C, D) or an (N, 4) array of them, got shape "
            f"{p.shape}")
    if len(p) > 64:
        raise ArgumentValueError(f"{len(p)} planes: a cutaway takes at most 64")
    if not np.isfinite(p).all():
        raise ArgumentValueError("planes must be finite numbers")
    n = np.linalg.norm(p[:, :3], axis=1)
    if not (n > 0).all() or not np.isfinite(n).all():
        raise ArgumentValueError(
            "each plane's normal (A, B, C) must be a nonzero vector, e.g. (1, 0, 0, -0.5) for "
            "the plane x = 0.5 keeping x >= 0.5")
    unit: NDArray[np.float64] = p / n[:, None]
    return unit


def _attributes(mesh: Mesh) -> Tuple[NDArray[np.float64], Dict[str, slice]]:
    """Per-vertex arrays interpolated at the cuts: (V, k) and their column slices."""
    cols: List[NDArray[np.float64]] = []
    parts: Dict[str, slice] = {}
    k = 0
    for name in ("normals", "uv"):
        a = getattr(mesh, name)
        if a is not None:
            cols.append(a)
            parts[name] = slice(k, k + a.shape[1])
            k += a.shape[1]
    if mesh.colors is not None and mesh.color_on == "vertex":
        cols.append(mesh.colors.astype(np.float64))
        parts["colors"] = slice(k, k + mesh.colors.shape[1])
        k += mesh.colors.shape[1]
    attrs = np.hstack(cols) if cols else np.zeros((len(mesh.vertices), 0))
    return attrs, parts


def _clip(verts: NDArray[np.float64], attrs: NDArray[np.float64], tris: NDArray[np.int64],
          labels: NDArray[np.int64], plane: NDArray[np.float64],
           eps: float) -> Tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.int64],
                                NDArray[np.int64], NDArray[np.bool_]]:
    """Clip the triangles by one plane, keeping distance >= 0: new vertices (with
    their attributes) on the crossing edges, the kept pieces as triangles."""
    d = verts @ plane[:3] + plane[3]
    pos, neg = d > eps, d < -eps
    a, b = tris, np.roll(tris, -1, axis=1)                 # edge i: corner i -> i + 1
    cross = (pos[a] & neg[b]) | (neg[a] & pos[b])
    lo, hi = np.minimum(a, b)[cross], np.maximum(a, b)[cross]
    nv = len(verts)
    keys, inverse = np.unique(lo * nv + hi, return_inverse=True)
    e0, e1 = keys // nv, keys % nv
    # the crossing computed once per edge, from its lower vertex: both faces share it
    u = (d[e0] / (d[e0] - d[e1]))[:, None]
    verts = np.vstack([verts, verts[e0] + u * (verts[e1] - verts[e0])])
    attrs = np.vstack([attrs, attrs[e0] + u * (attrs[e1] - attrs[e0])])
    on = np.concatenate([~pos & ~neg, np.ones(len(keys), bool)])
    xid = np.full(tris.shape, -1, np.int64)
    xid[cross] = nv + inverse.reshape(-1)
    slots = np.empty((len(tris), 6), np.int64)
    valid = np.empty((len(tris), 6), bool)
    slots[:, 0::2], valid[:, 0::2] = tris, ~neg[tris]
    slots[:, 1::2], valid[:, 1::2] = xid, cross
    order = np.argsort(~valid, axis=1, kind="stable")
    comp = np.take_along_axis(slots, order, axis=1)
    count = valid.sum(axis=1)
    # a face lying in the plane bounds the kept part only if it faces away from it
    flat = (~pos[tris] & ~neg[tris]).all(axis=1)
    p = verts[tris[flat]]
    away = np.einsum("ij,j->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), plane[:3]) < 0
    count[np.flatnonzero(flat)[~away]] = 0
    three, four = count == 3, count == 4
    tris = np.vstack([comp[three, :3], comp[four][:, [0, 1, 2]], comp[four][:, [0, 2, 3]]])
    labels = np.concatenate([labels[three], labels[four], labels[four]])
    return verts, attrs, tris, labels, on


def _loops(tris: NDArray[np.int64], on: NDArray[np.bool_]) -> List[NDArray[np.int64]]:
    """The closed loops of the clipped surface's border edges lying in the plane,
    each reversed (the cap's orientation); the open chains are dropped."""
    half = np.stack([tris, np.roll(tris, -1, axis=1)], axis=2).reshape(-1, 2)
    n = int(tris.max()) + 1 if len(tris) else 1
    fwd = half[:, 0] * n + half[:, 1]
    twin = half[:, 1] * n + half[:, 0]
    border = half[~np.isin(twin, fwd) & on[half[:, 0]] & on[half[:, 1]]]
    nxt: Dict[int, List[int]] = {}
    for a, b in border[:, ::-1].tolist():                 # reversed: the cap's edges
        nxt.setdefault(a, []).append(b)
    loops: List[NDArray[np.int64]] = []
    while nxt:
        start = next(iter(nxt))
        loop, p = [start], start
        while True:
            q = nxt[p].pop()
            if not nxt[p]:
                del nxt[p]
            if q == start:
                loops.append(np.array(loop, np.int64))
                break
            if q not in nxt:                               # an open chain: no cap
                break
            loop.append(q)
            p = q
    return loops


def _inside(point: NDArray[np.float64], poly: NDArray[np.float64]) -> bool:
    """Even-odd point-in-polygon test in 2-D."""
    x, y = point
    a, b = poly, np.roll(poly, -1, axis=0)
    crosses = (a[:, 1] > y) != (b[:, 1] > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        xs = a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    return bool(np.count_nonzero(crosses & (x < xs)) % 2)


def _area(poly: NDArray[np.float64]) -> float:
    x, y = poly[:, 0], poly[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def _cap(verts: NDArray[np.float64], loops: List[NDArray[np.int64]],
         normal: NDArray[np.float64]) -> NDArray[np.int64]:
    """Triangles (indices into ``verts``) filling the loops: outer loops with the holes
    they contain, by earcut; counterclockwise about ``normal``."""
    import mapbox_earcut

    e1 = np.cross(normal, (1.0, 0.0, 0.0) if abs(normal[0]) < 0.9 else (0.0, 1.0, 0.0))
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(normal, e1)
    flat = [np.stack([verts[lp] @ e1, verts[lp] @ e2], axis=1) for lp in loops]
    areas = [_area(f) for f in flat]
    outer = [i for i, s in enumerate(areas) if s > 0]
    holes: Dict[int, List[int]] = {i: [] for i in outer}
    for j, s in enumerate(areas):
        if s < 0:
            owners = [i for i in outer if _inside(flat[j][0], flat[i])]
            if owners:
                holes[min(owners, key=lambda i: areas[i])].append(j)
    out: List[NDArray[np.int64]] = []
    for i in outer:
        rings = [i] + holes[i]
        ids = np.concatenate([loops[r] for r in rings])
        xy = np.vstack([flat[r] for r in rings])
        ends = np.cumsum([len(loops[r]) for r in rings]).astype(np.uint32)
        t = ids[np.asarray(mapbox_earcut.triangulate_float64(xy, ends), np.int64).reshape(-1, 3)]
        out.append(_with_every_vertex(t, ids, verts, e1, e2))
    if not out:
        return np.zeros((0, 3), np.int64)
    tris = np.vstack(out)
    p = verts[tris]
    flip = np.einsum("ij,j->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), normal) < 0
    tris[flip] = tris[flip][:, ::-1]
    return tris


def _with_every_vertex(tris: NDArray[np.int64], ids: NDArray[np.int64],
                       verts: NDArray[np.float64], e1: NDArray[np.float64],
                       e2: NDArray[np.float64]) -> NDArray[np.int64]:
    """Earcut may skip a loop vertex on a straight stretch of its loop, or fill a
    straight stretch with a triangle of no area; either leaves a T-junction (an edge
    of the cap passing through a vertex of the clipped surface).  Remove the slivers
    and split the triangle whose edge passes through such a vertex, so that the cap
    meets the clipped surface edge for edge and the capped mesh stays closed."""
    flat = np.stack([verts @ e1, verts @ e2], axis=1)
    rows: List[List[int]] = [list(t) for t in tris.tolist()]
    pending = set(ids.tolist()) - {i for t in rows for i in t}
    for _ in range(4 * len(ids) + 4):
        pending |= _slivers(rows, flat)
        if not pending:
            break
        b = pending.pop()
        for t in rows:
            for k in range(3):
                p, q = flat[t[k]], flat[t[(k + 1) % 3]]
                if _between(flat[b], p, q):
                    r = t[(k + 2) % 3]
                    rows.append([b, t[(k + 1) % 3], r])
                    t[:] = [t[k], b, r]
                    break
            else:
                continue
            break
    return np.array(rows, np.int64).reshape(-1, 3)


def _between(b: NDArray[np.float64], p: NDArray[np.float64], q: NDArray[np.float64]) -> bool:
    """Whether 2-D point ``b`` lies strictly inside the segment pq."""
    d = q - p
    length2 = float(d @ d)
    s = float((b - p) @ d) / max(length2, 1e-300)
    off = (b - p)[0] * d[1] - (b - p)[1] * d[0]
    return 0 < s < 1 and bool(off * off <= 1e-20 * length2 * length2)


def _slivers(tris: List[List[int]], flat: NDArray[np.float64]) -> Set[int]:
    """Remove the triangles of no area; their middle vertices."""
    middle: Set[int] = set()
    for t in list(tris):
        for k in range(3):
            if _between(flat[t[k]], flat[t[(k + 1) % 3]], flat[t[(k + 2) % 3]]):
                tris.remove(t)
                middle.add(t[k])
                break
    return middle


def _cut(mesh: Mesh, planes: NDArray[np.float64], cap_color: Optional[Tuple[int, ...]]
         ) -> Tuple[Optional[Mesh], Optional[Mesh], List[NDArray[np.float64]], Optional[Mesh]]:
    tri = mesh.triangulated()
    verts = mesh.vertices.copy()
    attrs, parts = _attributes(mesh)
    tris = np.asarray(tri.faces).reshape(-1, 3).astype(np.int64)
    face_colors = tri.colors if tri.color_on == "face" else None
    labels = np.arange(len(tris))                          # >= 0: a face; -1 - k: plane k's cap
    size = float(np.abs(verts).max(initial=0.0)) + float(np.ptp(verts, axis=0).max(initial=0.0))
    eps = EPS * max(size, 1e-300)
    loops_all: List[NDArray[np.int64]] = []
    for k, plane in enumerate(planes):
        if not len(tris):
            break
        check_mesh_budget("meshes", len(verts) + 3 * len(tris), 2 * len(tris), 6 * len(tris),
                          "the cutaway of the mesh")
        verts, attrs, tris, labels, on = _clip(verts, attrs, tris, labels, plane, eps)
        loops: List[NDArray[np.int64]] = _loops(tris, on) if len(tris) else []
        # the loops run across the earlier planes' caps where this plane cuts them
        cap = _cap(verts, loops, -plane[:3]) if loops else np.zeros((0, 3), np.int64)
        tris = np.vstack([tris, cap])
        labels = np.concatenate([labels, np.full(len(cap), -1 - k)])
        loops_all += loops
    body, caps = labels >= 0, labels < 0
    closed = _compact(verts, tris, None, None)
    used = np.zeros(len(verts), bool)
    used[tris.reshape(-1)] = True
    # a later plane may have cut an earlier plane's loop away
    outlines = [verts[lp] for lp in loops_all if used[lp].all()]
    clipped = _compact(verts, tris[body], attrs, parts,
                       None if face_colors is None else face_colors[labels[body]])
    if clipped is not None:
        clipped.name, clipped.material = mesh.name, mesh.material
    cap_mesh = None
    if caps.any():
        t = tris[caps]
        p = verts[t].reshape(-1, 3)
        normals = np.repeat(-planes[-1 - labels[caps], :3], 3, axis=0)
        cap_mesh = Mesh(p, np.arange(len(p)).reshape(-1, 3), normals=normals,
                        colors=None if cap_color is None else [cap_color] * len(t),
                        name=None if mesh.name is None else f"{mesh.name} cap")
        cap_mesh.material = mesh.material
    return clipped, cap_mesh, outlines, closed


def _compact(verts: NDArray[np.float64], tris: NDArray[np.int64],
             attrs: Optional[NDArray[np.float64]], parts: Optional[Dict[str, slice]],
             colors: Optional[NDArray[Any]] = None) -> Optional[Mesh]:
    """A Mesh of the triangles, keeping only the vertices they use."""
    used = np.unique(tris.reshape(-1))
    remap = np.full(len(verts), -1, np.int64)
    remap[used] = np.arange(len(used))
    kw: Dict[str, Any] = {}     # Mesh's keyword arguments
    if attrs is not None and parts is not None:
        a = attrs[used]
        if "normals" in parts:
            n = a[:, parts["normals"]]
            kw["normals"] = n / np.maximum(np.linalg.norm(n, axis=1), 1e-300)[:, None]
        if "uv" in parts:
            kw["uv"] = a[:, parts["uv"]]
        if "colors" in parts:
            kw["colors"], kw["color_on"] = np.clip(np.rint(a[:, parts["colors"]]), 0, 255) \
                .astype(np.int64), "vertex"
    if colors is not None:
        kw["colors"], kw["color_on"] = colors, "face"
    if not len(used):
        return None
    return Mesh(verts[used], remap[tris], **kw)


def cutaway(meshes: Any, planes: ArrayLike, cap_color: Optional[Color] = None) -> Cutaway:
    """Meshes cut by clipping planes, with the cut faces capped (Hearn & Baker, section
    9-1).

    Parameters
    ----------
    meshes : Mesh or list of Mesh
        The surfaces to cut (closed ones get caps).
    planes : (A, B, C, D) or (N, 4) array_like
        Each keeps where A x + B y + C z + D >= 0; several cut one after another
        (what is kept lies on the positive side of every plane).
    cap_color : color, optional
        The caps' face color (default: none, so that a render's material colors them).

    Returns
    -------
    Cutaway
        ``.meshes`` the clipped meshes, ``.caps`` their cap meshes, ``.loops`` the
        intersection loops, ``.closed`` each clipped mesh and its caps as one closed
        mesh; ``.drawable()`` the meshes and caps to render.

    Examples
    --------
    >>> import scanline as sl
    >>> cut = sl.draw3d.cutaway(sl.mesh.cube(2.0), (1, 0, 0, 0))     # keep x >= 0
    >>> body, cap = cut.meshes[0], cut.caps[0]
    >>> float(body.vertices[:, 0].min()), float(body.vertices[:, 0].max()), len(cut.loops[0])
    (0.0, 1.0, 1)
    >>> sorted(set(cap.vertices[:, 0].tolist())), cap.normals[0].tolist()
    ([0.0], [-1.0, -0.0, -0.0])
    """
    parts = _parts(meshes)
    p = _planes(planes)
    if cap_color is not None:
        from ..color.spec import rgba

        cap_rgba: Optional[Tuple[int, ...]] = tuple(int(c) for c in rgba(cap_color, "cap_color"))
    else:
        cap_rgba = None
    results = [_cut(m, p, cap_rgba) for m in parts]
    return Cutaway([r[0] for r in results], [r[1] for r in results],
                   [r[2] for r in results], [r[3] for r in results])
