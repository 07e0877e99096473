"""The BSP tree's step table (Fuchs, Kedem and Naylor 1980; Hearn & Baker, section
13-7): the tree that :class:`scanline.visible.BSPTree` builds for a few upright walls
seen in plan -- each node's splitting plane, the polygons in it, in front of it and
behind it, the polygons it splits -- then the order its traversal paints the pieces
from an eye, back to front."""

from typing import Dict, List, Sequence, Tuple

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .._typing import Point
from ..errors import ArgumentValueError
from .table import Table

#: The plan (x, y) of the device the walls are drawn on.
WIDTH, HEIGHT = 32, 24

#: The walls' footprints in plan, (x0, y0, x1, y1): each wall stands from z = 0 to
#: z = 1.  Wall 0 (the root's plane, y = 12) cuts walls 1 and 4 in two.
WALLS = [(4, 12, 28, 12), (10, 4, 10, 20), (16, 16, 26, 20), (14, 6, 24, 3),
         (22, 16, 28, 7)]

#: The eye's height above the floor (half way up the walls).
EYE_Z = 0.5


class BSPTable(Table):
    """The table of :func:`bsp_tree`, with the plan geometry of its tree."""

    #: Each piece's plan segment [[x0, y0], [x1, y1]] by its name ("1a", "2" ...).
    pieces: Dict[str, List[List[float]]]
    #: Each node's splitting plane [A, B, C, D].
    planes: List[List[float]]
    #: Each node's pieces by name.
    node_pieces: List[List[str]]


def walls() -> Tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]:
    """The walls as world quadrilaterals: ``(vertices (4 W, 3), counts, faces)``."""
    quads = [[(x0, y0, 0.0), (x1, y1, 0.0), (x1, y1, 1.0), (x0, y0, 1.0)]
             for x0, y0, x1, y1 in WALLS]
    return (np.array(quads, float).reshape(-1, 3), np.full(len(WALLS), 4, np.int64),
            np.arange(len(WALLS), dtype=np.int64))


def _plane(p: NDArray[np.float64]) -> str:
    a, b, c, d = (float(np.round(x, 6)) + 0.0 for x in p)
    terms = [f"{k:g} {n}" for k, n in ((a, "x"), (b, "y"), (c, "z")) if k]
    return " + ".join(terms).replace("+ -", "- ") + (f" {'-' if d < 0 else '+'} {abs(d):g}"
                                                      if d else "") + " = 0"


def _names(pieces: Sequence[int], label: Dict[int, str]) -> str:
    return " ".join(label[p] for p in pieces) or "-"


def bsp_tree(eye: Point = (6.0, 22.0)) -> BSPTable:
    """The BSP tree of the walls :data:`WALLS` (upright quadrilaterals, seen in plan)
    and its traversal from the eye at plan point ``eye`` (height :data:`EYE_Z`).

    Rows of phase ``build``, one per node in the order the build creates them: its
    ``plane`` (A x + B y + C z + D = 0, the positive side in front), the walls lying
    ``on`` it, those ``in front`` and ``behind`` (every piece in the front and the
    back subtree, by wall number), the walls it ``splits`` (pieces on both sides).
    Rows of phase ``draw``, one per piece in the order the traversal paints them:
    the ``node`` holding it, the eye's ``side`` of that node's plane, the ``piece``
    (its wall, lettered a, b, ... when split) and its ``wall``.  ``table.pieces``
    holds each piece's plan segment by name, ``table.node_pieces`` each node's pieces;
    ``table.planes`` each node's plane (A, B, C, D).

    Parameters
    ----------
    eye : (float, float)
        The eye's plan point (x, y) (default (6, 22)).

    Returns
    -------
    BSPTable
        Columns phase, node, plane, on, in front, behind, splits, side, piece, wall;
        ``pieces``, ``planes`` and ``node_pieces`` hold the tree's geometry.

    Raises
    ------
    ArgumentTypeError
        A coordinate of ``eye`` is not a number.
    ArgumentValueError
        ``eye`` is not two numbers, or not finite.

    References
    ----------
    H. Fuchs, Z. M. Kedem and B. F. Naylor, "On visible surface generation by a
    priori tree structures", SIGGRAPH 1980.

    Examples
    --------
    The root's plane is wall 0's, y = 12 (-y + 12 = 0: in front where y < 12); it
    cuts wall 1 (x = 10, y 4..20) and wall 4 ((22, 16) to (28, 7)) in two.  Node 1
    is wall 2's plane, from (16, 16) along (10, 4): its normal (4, -10) / sqrt(116)
    = (0.371391, -0.928477) and D = -(0.371391 x 16 - 0.928477 x 16) = 8.91338.
    The eye (6, 22) is behind the root, so the front subtree is painted first:

    >>> t = bsp_tree((6, 22))
    >>> for r in t.rows[:2]:
    ...     print(r["node"], r["plane"], "|", r["on"], "|", r["in front"], "|", r["behind"],
    ...           "|", r["splits"])
    0 -1 y + 12 = 0 | 0 | 3 4a 1c 1d | 2 4b 1a 1b | 1 4
    1 0.371391 x - 0.928477 y + 8.91338 = 0 | 2 | 4b 1a | 1b | 1
    >>> " ".join(r["piece"] for r in t.rows if r["phase"] == "draw")
    '1c 3 4a 1d 0 4b 1a 2 1b'
    """
    from ..visible import BSPTree

    if not (isinstance(eye, (list, tuple, np.ndarray)) and len(eye) == 2):
        raise ArgumentValueError(f"eye must be 2 numbers x, y (a plan point), got {eye!r}")
    ex, ey = (v.number(n, c) for n, c in zip(("eye x", "eye y"), eye))
    tree = BSPTree.of_polygons(*walls())
    e = np.array([ex, ey, EYE_Z])
    order = tree.order(e)
    verts, counts, faces = tree.world_pieces(e)
    starts = np.cumsum(counts) - counts
    face = dict(zip(order.tolist(), faces.tolist()))
    pieces: Dict[int, List[List[float]]] = {}
    for p, s, c in zip(order.tolist(), starts.tolist(), counts.tolist()):
        plan = verts[s:s + c, :2]
        far = np.linalg.norm(plan[:, None] - plan[None], axis=2)
        i, j = np.unravel_index(int(far.argmax()), far.shape)
        pieces[p] = [plan[i].tolist(), plan[j].tolist()]

    label: Dict[int, str] = {}                  # piece -> its wall, lettered when the wall was split
    for w in set(face.values()):
        mine = sorted(p for p in face if face[p] == w)
        label.update({p: str(w) if len(mine) == 1 else f"{w}{chr(97 + i)}"
                      for i, p in enumerate(mine)})

    def below(node: int) -> List[int]:
        """The pieces of the subtree under ``node``, -1: none."""
        out: List[int] = []
        todo = [node]
        while todo:
            n = todo.pop()
            if n >= 0:
                out += tree.pieces[n].tolist()
                todo += [int(tree.front[n]), int(tree.back[n])]
        return sorted(out)

    rows = []
    for n in range(len(tree)):
        front, back = below(int(tree.front[n])), below(int(tree.back[n]))
        split = sorted({face[p] for p in front} & {face[p] for p in back})
        rows.append({"phase": "build", "node": n, "plane": _plane(tree.planes[n]),
                     "on": _names(tree.pieces[n].tolist(), label),
                     "in front": _names(front, label), "behind": _names(back, label),
                     "splits": " ".join(map(str, split)) or "-"})
    node_of = {int(p): n for n in range(len(tree)) for p in tree.pieces[n]}
    for p in order.tolist():
        n = node_of[p]
        s = float(tree.planes[n] @ np.append(e, 1.0))
        rows.append({"phase": "draw", "node": n, "side": "front" if s >= 0 else "back",
                     "piece": label[p], "wall": face[p]})
    notes = [f"wall {i}: ({x0:g}, {y0:g}) to ({x1:g}, {y1:g}) in plan, z from 0 to 1"
             for i, (x0, y0, x1, y1) in enumerate(WALLS)]
    notes += [f"eye ({ex:g}, {ey:g}, {EYE_Z:g}); the first polygon of each set gives the "
              "splitting plane; front: A x + B y + C z + D > 0",
              f"{len(tree)} nodes, {len(order)} pieces, {tree.splits} splits; draw: at each "
              "node the subtree away from the eye, the node, the subtree on the eye's side"]
    columns = ["phase", "node", "plane", "on", "in front", "behind", "splits", "side",
               "piece", "wall"]
    t = BSPTable(f"BSP tree of {len(WALLS)} walls, eye ({ex:g}, {ey:g})", columns,
              [{c: r.get(c) for c in columns} for r in rows], notes)
    t.pieces = {label[p]: seg for p, seg in pieces.items()}
    t.planes = tree.planes.tolist()
    t.node_pieces = [[label[p] for p in tree.pieces[n].tolist()] for n in range(len(tree))]
    return t
