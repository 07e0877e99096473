"""Hearn & Baker's polygon tables (section 10-1): the geometric data of a polygon
mesh in three tables, with the consistency checks the book lists.

- the **vertex table**: V1: x1, y1, z1; V2: ...
- the **edge table**: E1: V1, V2 -- each edge's two vertices, with (the expanded
  table) forward pointers to the polygons it belongs to;
- the **polygon-surface table** (surface facets): S1: E1, E2, E3 -- each polygon's
  edges in order around it.

Hearn & Baker's checks: (1) every vertex is an endpoint of at least two edges,
(2) every edge is part of at least one polygon, (3) every polygon is closed,
(4) each polygon has at least one shared edge, (5) every edge referenced by a
polygon has a reciprocal pointer back to the polygon in the edge table.  Tables are
numbered from 1 when printed, as in the book, and from 0 in the arrays.
"""

from typing import TYPE_CHECKING, List, Optional, Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..transform3d.arrays import finite, real_array

if TYPE_CHECKING:
    from .mesh import Mesh

_LOWEST = -v.INT64_MAX - 1


def _index_table(name: str, value: object, columns: Optional[int] = None) -> NDArray[np.int64]:
    try:
        a = np.asarray(value)
    except (TypeError, ValueError, OverflowError):
        a = np.asarray(None)
    if a.dtype.kind not in "iu" or a.ndim != 2 or (columns and a.shape[1] != columns):
        raise ArgumentValueError(
            f"{name} must be an integer array of shape (N, {columns or 'k'}), got "
            f"{a.dtype} of shape {a.shape}")
    # any int64 value: check() reports the ones out of range (uint64 beyond int64 too)
    return v.index_array(name, a, shape=(None, a.shape[1]), low=_LOWEST)


def _index_lists(name: str, value: object) -> List[NDArray[np.int64]]:
    """A list of 1-D int64 arrays (each table entry's indices, in range or not:
    :meth:`PolygonTables.check` reports those out of range)."""
    if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__iter__") or (
            isinstance(value, np.ndarray) and value.ndim == 0):
        raise ArgumentTypeError(f"{name} must be a list of index lists, got {v._show(value)}")
    out = []
    for i, entry in enumerate(value):
        if isinstance(entry, (str, bytes, dict)) or not hasattr(entry, "__iter__") or (
                isinstance(entry, np.ndarray) and entry.ndim != 1):
            raise ArgumentTypeError(f"{name}[{i}] must be a list of integer indices, got "
                                    f"{v._show(entry)}")
        out.append(v.index_array(f"{name}[{i}]", list(entry), low=_LOWEST,
                                 what="a list of integer indices"))
    return out


class PolygonTables:
    """The vertex, edge and polygon-surface tables of a mesh.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
        The vertex table: each vertex's (x, y, z).
    edges : array_like of int, shape (E, 2)
        Vertex indices (0-based) of each edge.
    surfaces : list of sequences of int
        Each polygon's edge indices, in order around it.
    edge_surfaces : list of sequences of int, optional
        The expanded edge table: for each edge, the polygons it belongs to (the
        forward pointers).  Built from ``surfaces`` when omitted.

    Build them from a mesh with :meth:`scanline.mesh.Mesh.polygon_tables`, or give
    the tables directly (also broken ones: :meth:`check` says what is wrong).

    Raises
    ------
    ArgumentValueError
        If ``vertices`` is not a finite (V, 3) array or ``edges`` not an (E, 2)
        integer array.
    ArgumentTypeError
        If ``surfaces`` or ``edge_surfaces`` is not a list of index lists.

    Notes
    -----
    Hearn & Baker, section 10-1, "polygon tables".

    Examples
    --------
    One triangle: three vertices, three edges, one surface S1: E1, E2, E3.

    >>> from scanline.mesh import PolygonTables
    >>> tables = PolygonTables([(0, 0, 0), (1, 0, 0), (0, 1, 0)],
    ...                        [(0, 1), (1, 2), (2, 0)], [[0, 1, 2]])
    >>> print(tables)
    vertex table
      V1: 0, 0, 0
      V2: 1, 0, 0
      V3: 0, 1, 0
    edge table
      E1: V1, V2   (S1)
      E2: V2, V3   (S1)
      E3: V3, V1   (S1)
    polygon-surface table
      S1: E1, E2, E3
    """

    vertices: NDArray[np.float64]
    edges: NDArray[np.int64]
    surfaces: List[NDArray[np.int64]]
    edge_surfaces: List[List[int]]

    def __init__(self, vertices: ArrayLike, edges: ArrayLike,
                 surfaces: Sequence[Sequence[int]],
                 edge_surfaces: Optional[Sequence[Sequence[int]]] = None) -> None:
        verts = finite("vertices", real_array("vertices", vertices, "(V, 3)"))
        if verts.ndim == 1 and verts.size == 0:
            verts = verts.reshape(0, 3)
        if verts.ndim != 2 or verts.shape[1] != 3:
            raise ArgumentValueError(f"vertices must have shape (V, 3), got shape {verts.shape}")
        self.vertices = verts
        self.edges = _index_table("edges", edges, 2)
        self.surfaces = _index_lists("surfaces", surfaces)
        if edge_surfaces is None:
            pointers: List[List[int]] = [[] for _ in range(len(self.edges))]
            for s, ring in enumerate(self.surfaces):
                for e in ring.tolist():
                    if 0 <= e < len(pointers) and s not in pointers[e]:
                        pointers[e].append(s)
            edge_surfaces = pointers
        self.edge_surfaces = [p.tolist() for p in _index_lists("edge_surfaces", edge_surfaces)]

    @classmethod
    def from_mesh(cls, mesh: "Mesh") -> "PolygonTables":
        """The tables of a :class:`~scanline.mesh.Mesh`: its distinct edges and, for
        each face, its edges in order (face i's edge k joins its vertices k and k + 1).

        Parameters
        ----------
        mesh : Mesh
            The polygon mesh.

        Returns
        -------
        PolygonTables
            Its tables (:meth:`scanline.mesh.Mesh.polygon_tables` gives the same).

        Examples
        --------
        A square's four edges, numbered in the sorted order of their vertex pairs:
        (0, 1), (0, 3), (1, 2), (2, 3); the face walks them as E1, E3, E4, E2.

        >>> import scanline as sl
        >>> square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
        >>> tables = sl.mesh.PolygonTables.from_mesh(square)
        >>> [ring.tolist() for ring in tables.surfaces]
        [[0, 2, 3, 1]]
        """
        from .mesh import _rows_in

        half, owner = mesh._half_edges()
        which = _rows_in(mesh.edges, np.sort(half, axis=1))
        surfaces = [which[mesh.face_offsets[i]:mesh.face_offsets[i + 1]]
                    for i in range(mesh.face_count)]
        tables = cls.__new__(cls)
        tables.vertices = mesh.vertices
        tables.edges = mesh.edges
        tables.surfaces = surfaces
        pointers: List[List[int]] = [[] for _ in range(len(mesh.edges))]
        for e, s in zip(which.tolist(), owner.tolist()):
            pointers[e].append(s)
        tables.edge_surfaces = pointers
        return tables

    def check(self) -> List[str]:
        """Hearn & Baker's consistency checks: a list of problems, empty when the
        tables are consistent.  Each problem is a sentence naming the table entry
        (numbered from 1, as printed).

        Returns
        -------
        list of str
            The problems found, in the order of the checks; empty when none.

        Examples
        --------
        Two edges of a triangle without the third: the surface is not closed,
        and V1 and V3 end one edge each.

        >>> from scanline.mesh import PolygonTables
        >>> tables = PolygonTables([(0, 0, 0), (1, 0, 0), (0, 1, 0)],
        ...                        [(0, 1), (1, 2)], [[0, 1]])
        >>> for problem in tables.check():
        ...     print(problem)
        vertex V1 is an endpoint of 1 edge(s); every vertex must be an endpoint of at least two
        vertex V3 is an endpoint of 1 edge(s); every vertex must be an endpoint of at least two
        surface S1 has 2 edges; a polygon needs at least three
        """
        problems: List[str] = []
        nv, ne = len(self.vertices), len(self.edges)
        for e, (a, b) in enumerate(self.edges.tolist()):
            for end in (a, b):
                if not 0 <= end < nv:
                    problems.append(f"edge E{e + 1} refers to vertex V{end + 1}, which is not "
                                    f"in the vertex table (V1 to V{nv})")
            if a == b:
                problems.append(f"edge E{e + 1} joins vertex V{a + 1} to itself")
        ends = self.edges[(self.edges >= 0).all(axis=1) & (self.edges < nv).all(axis=1)]
        degree = np.bincount(ends.reshape(-1), minlength=nv) if nv else np.zeros(0, int)
        for vtx in np.flatnonzero(degree < 2).tolist():
            problems.append(f"vertex V{vtx + 1} is an endpoint of {int(degree[vtx])} edge(s); "
                            "every vertex must be an endpoint of at least two")
        used = np.zeros(ne, np.int64)
        for s, ring in enumerate(self.surfaces):
            bad = [int(e) for e in ring if not 0 <= e < ne]
            if bad:
                problems.append(f"surface S{s + 1} refers to edge E{bad[0] + 1}, which is not "
                                f"in the edge table (E1 to E{ne})")
                continue
            used[ring] += 1
            if len(ring) < 3:
                problems.append(f"surface S{s + 1} has {len(ring)} edges; a polygon needs at "
                                "least three")
            elif not _closed(self.edges, ring):
                problems.append(f"surface S{s + 1} is not closed: its edges "
                                f"{', '.join('E' + str(int(e) + 1) for e in ring)} do not "
                                "form one loop")
        for e in np.flatnonzero(used == 0).tolist():
            problems.append(f"edge E{e + 1} is not part of any polygon")
        for s, ring in enumerate(self.surfaces):
            inside = [int(e) for e in ring if 0 <= e < ne]
            if inside and len(self.surfaces) > 1 and not any(used[e] >= 2 for e in inside):
                problems.append(f"surface S{s + 1} shares no edge with another polygon")
            for e in inside:
                if e < len(self.edge_surfaces) and s not in self.edge_surfaces[e]:
                    problems.append(f"surface S{s + 1} lists edge E{e + 1}, but the edge "
                                    f"table has no pointer from E{e + 1} back to S{s + 1}")
        for e, pointers in enumerate(self.edge_surfaces):
            for s in pointers:
                if not 0 <= s < len(self.surfaces) or e not in self.surfaces[s].tolist():
                    problems.append(f"edge E{e + 1} points to surface S{s + 1}, which does not "
                                    f"list E{e + 1}")
        return problems

    @property
    def consistent(self) -> bool:
        """Whether :meth:`check` finds nothing.

        Returns
        -------
        bool

        Examples
        --------
        >>> import scanline as sl
        >>> sl.mesh.cube().polygon_tables().consistent
        True
        """
        return not self.check()

    def validate(self) -> None:
        """Raise ArgumentValueError with the first problems if the tables are not
        consistent.

        Returns
        -------
        None

        Raises
        ------
        ArgumentValueError
            If :meth:`check` finds a problem; the message gives the first three.

        Examples
        --------
        >>> from scanline.mesh import PolygonTables
        >>> PolygonTables([(0, 0, 0), (1, 0, 0), (0, 1, 0)],
        ...               [(0, 1), (1, 2), (2, 0)], [[0, 1, 2]]).validate()
        >>> PolygonTables([(0, 0, 0), (1, 0, 0), (0, 1, 0)],
        ...               [(0, 1), (1, 2), (2, 0)], [[0, 1]]).validate()
        Traceback (most recent call last):
        ...
        scanline.errors.ArgumentValueError: the polygon tables are not consistent: surface S1 has 2 edges; a polygon needs at least three; edge E3 is not part of any polygon
        """
        problems = self.check()
        if problems:
            more = f" (and {len(problems) - 3} more)" if len(problems) > 3 else ""
            raise ArgumentValueError("the polygon tables are not consistent: "
                                     + "; ".join(problems[:3]) + more)

    def __str__(self) -> str:
        lines = ["vertex table"]
        lines += [f"  V{i + 1}: {x:g}, {y:g}, {z:g}" for i, (x, y, z) in
                  enumerate(self.vertices.tolist())]
        lines.append("edge table")
        for e, (a, b) in enumerate(self.edges.tolist()):
            back = ", ".join(f"S{s + 1}" for s in self.edge_surfaces[e]) \
                if e < len(self.edge_surfaces) else ""
            lines.append(f"  E{e + 1}: V{a + 1}, V{b + 1}" + (f"   ({back})" if back else ""))
        lines.append("polygon-surface table")
        lines += [f"  S{s + 1}: " + ", ".join(f"E{int(e) + 1}" for e in ring)
                  for s, ring in enumerate(self.surfaces)]
        return "\n".join(lines)

    def __repr__(self) -> str:
        return (f"<PolygonTables: {len(self.vertices)} vertices, {len(self.edges)} edges, "
                f"{len(self.surfaces)} surfaces>")


def _closed(edges: NDArray[np.int64], ring: NDArray[np.int64]) -> bool:
    """Whether the edges ``ring`` (in order) form one closed loop."""
    pairs = [tuple(edges[e]) for e in ring]
    shared = set(pairs[0]) & set(pairs[-1])
    if not shared:
        return False
    for start in shared:           # walk from a vertex the last and first edges share
        at = start
        ok = True
        for a, b in pairs:
            if at == a:
                at = b
            elif at == b:
                at = a
            else:
                ok = False
                break
        if ok and at == start:
            return True
    return False
