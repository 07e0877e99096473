"""Quiz mode: for each step of a case, the question whose answer is in the step's row.

One algorithm, one truth: a question is never answered by a second implementation.
Each algorithm declares (:data:`QUESTIONS`) which columns of its step table are
asked -- the pixel a row plots (two columns, clicked on the grid), a column chosen
among offered values (the sign of a decision parameter, a region code's decision,
the depth-sort action, write or keep in the z-buffer ...), or a number typed in --
and the answer is that column of the row :func:`scanline.studio.explorer.view_of`
sends, the very row the explorer shows.  :func:`case` draws a case of each
algorithm from a seed (``random.Random(seed)``): the same seed gives the same case,
so a teacher can hand out "case 17".
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass
from typing import Any, Callable

from ..trace.bsp import HEIGHT as BSP_HEIGHT
from ..trace.bsp import WIDTH as BSP_WIDTH
from ..trace.raytracing import HEIGHT as RT_HEIGHT
from ..trace.raytracing import WIDTH as RT_WIDTH
from ..trace.shading import HEIGHT as SH_HEIGHT
from ..trace.zbuffer import HEIGHT as ZB_HEIGHT
from .explorer import BadArguments, DEFAULTS, catalog, explore

#: Largest seed :func:`case` takes (seeds are shared by hand: small integers).
MAX_SEED = 2**31 - 1


@dataclass(frozen=True)
class Question:
    """What a step asks: ``kind`` "pixel" (the pixel in columns ``columns[0]``,
    ``columns[1]``, clicked on the grid), "choice" (the value of ``columns[0]``
    among the values the table's rows hold there) or "number" (the value of
    ``columns[0]``, typed, right within ``tolerance``).  ``given``: the columns of
    the row shown with the question (what the step starts from; never a column
    that gives the answer away).  ``offered``: choices always offered besides the
    values the table holds (so that a case whose rows all say "write" still asks
    "write or keep")."""

    kind: str
    columns: tuple[str, ...]
    prompt: str
    given: tuple[str, ...] = ()
    tolerance: float = 0.0
    offered: tuple[str, ...] = ()


def _pixel(x: str, y: str, given: str = "k",
           prompt: str = "Which pixel does this step plot?") -> Question:
    return Question("pixel", (x, y), prompt, tuple(given.split()))


def _choice(column: str, given: str, prompt: str, offered: tuple[str, ...] = ()) -> Question:
    return Question("choice", (column,), prompt, tuple(given.split("|")), offered=offered)


def _number(column: str, given: str, prompt: str) -> Question:
    return Question("number", (column,), prompt, tuple(given.split("|")), 1e-3)


_CROSSING = ("PE (entering)", "PL (leaving)")
_POPPED = "Which seed is popped from the stack at this step?"

#: The question of each algorithm's steps (given columns separated by "|").
QUESTIONS: dict[str, Question] = {
    "bresenham": _pixel("x", "y"),
    "dda": _pixel("x", "y"),
    "midpoint-circle": _pixel("xc+x", "yc+y"),
    "midpoint-ellipse": _pixel("xc+x", "yc+y"),
    "flood-fill": _pixel("x", "y", "k", _POPPED),
    "boundary-fill": _pixel("x", "y", "k", _POPPED),
    "scan-line-fill": _choice("spans", "y|active", "Which spans does this scan line fill?"),
    "cohen-sutherland": _choice("decision", "step|code0|code1|and",
                                "What do the region codes decide?"),
    "cohen-sutherland-3d": _choice("decision", "step|code0|code1|and",
                                   "What do the region codes decide?"),
    "liang-barsky": _choice("kind", "k|edge", "Is this boundary crossed entering or leaving "
                            "(the sign of p)?", _CROSSING),
    "liang-barsky-3d": _choice("kind", "k|plane", "Is this plane crossed entering or leaving "
                               "(the sign of p)?", _CROSSING),
    "cyrus-beck": _choice("kind", "edge|N|PE", "Is this edge crossed entering or leaving "
                          "(the sign of N.D)?", _CROSSING),
    "sutherland-hodgman": _choice("case", "stage|boundary|S|P",
                                  "Which case is the edge S -> P, and what is output?"),
    "de-casteljau": _number("x", "r|i", "What is x of this point (to 3 decimals)?"),
    "cox-de-boor": _number("B", "r|k|interval",
                           "What is this basis function's value (to 3 decimals)?"),
    "z-buffer": _choice("result", "triangle|x|z|depth",
                        "Is this pixel written to the z-buffer or kept?", ("write", "keep")),
    "depth-sort": _choice("action", "S|S'", "Which action do the depth-sort tests decide?"),
    "floating-horizon": _choice("visible", "curve|column|y|upper before|lower before",
                                "Is this point above, below or between the horizons?",
                                ("above", "below", "hidden")),
    "ray-tracing": _choice("kind", "ray|parent", "Which kind of ray is cast next?"),
    "back-face": _choice("result", "face|N|V", "Is this face a back face or a front face "
                         "(the sign of V.N)?", ("back", "front")),
    "gouraud": _number("I", "x|facet|l0|l1|l2|I0|I1|I2",
                       "What is the interpolated intensity I (to 3 decimals)?"),
    "phong": _number("I", "x|facet|l0|l1|l2|N",
                     "What is the intensity I from the interpolated normal (to 3 decimals)?"),
    "bsp-tree": _choice("side", "phase|node", "On which side of this node's plane is the eye?",
                        ("front", "back")),
    "warnock": _choice("decision", "x0|y0|x1|y1|level|P0|P1|P2",
                       "What does Warnock's test decide for this area?"),
    "scan-line-visible": _choice("visible", "y|edge|x|on|depths",
                                 "Which polygon is visible on this span?"),
    "ray-casting": _choice("nearest", "x|hits", "Which triangle does this pixel's ray meet first?"),
    "inbetween-spacing": _number("t", "j|j/(n+1)",
                                 "At what time t is this in-between (to 3 decimals)?"),
    "morph-equalize": _choice("added", "k|ax|ay|bx|by",
                              "Was this vertex pair's vertex added to A, to B, or neither?",
                              ("-", "A", "B")),
}


def _ints(rng: random.Random, lo: int, hi: int, n: int) -> list[str]:
    return [str(rng.randint(lo, hi)) for _ in range(n)]


def _segment(rng: random.Random) -> list[str]:
    x0, y0 = rng.randint(0, 12), rng.randint(0, 12)
    # both coordinates change: a sloped line, in any of the eight octants
    dx, dy = rng.choice([-1, 1]) * rng.randint(4, 14), rng.choice([-1, 1]) * rng.randint(2, 10)
    if rng.random() < 0.5:
        dx, dy = dy, dx
    return [str(x0), str(y0), str(x0 + dx), str(y0 + dy)]


def _star(rng: random.Random, n: int, center: float, radius: tuple[int, int]) -> list[str]:
    """A simple polygon: ``n`` vertices at increasing angles around ``center``."""
    angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    points = []
    for a in angles:
        r = rng.randint(*radius)
        points.append(f"{round(center + r * math.cos(a))},{round(center + r * math.sin(a))}")
    return points


def _clip_segment(rng: random.Random) -> list[str]:
    return _ints(rng, -6, 16, 4)


def _clip3d(rng: random.Random) -> list[str]:
    return _ints(rng, -6, 16, 6)


#: Draws the arguments of one case of each algorithm from a random generator.
GENERATORS: dict[str, Callable[[random.Random], list[str]]] = {
    "bresenham": _segment,
    "dda": _segment,
    "midpoint-circle": lambda r: [str(r.randint(4, 10)), "--center", *_ints(r, 0, 6, 2)],
    "midpoint-ellipse": lambda r: [*_ints(r, 3, 10, 2), "--center", *_ints(r, 0, 6, 2)],
    "flood-fill": lambda r: [*r.choice([["1", "1"], ["3", "3"], ["5", "2"], ["7", "2"],
                                        ["8", "3"], ["2", "4"]]),
                             "--connectivity", r.choice(["4", "8"])],
    "boundary-fill": lambda r: [*r.choice([["1", "1"], ["3", "3"], ["5", "2"], ["2", "4"]]),
                                "--boundary", "#", "--connectivity", r.choice(["4", "8"])],
    "scan-line-fill": lambda r: _star(r, r.randint(4, 6), 8, (3, 8)),
    "cohen-sutherland": _clip_segment,
    "liang-barsky": _clip_segment,
    "cyrus-beck": lambda r: [*_clip_segment(r), "--window-polygon", "0,0,10,0,12,8,4,12"],
    "sutherland-hodgman": lambda r: ["--", *_star(r, r.randint(3, 6), 5, (4, 9))],
    "de-casteljau": lambda r: [*(f"{x},{y}" for x, y in zip(_ints(r, 0, 12, 4), _ints(r, 0, 10, 4))),
                               "--u", r.choice(["0.25", "0.5", "0.75"])],
    "cox-de-boor": lambda r: ["--knots", "0,0,0,0,1,2,3,3,3,3", "--order", "4", "--u",
                              r.choice(["0.5", "1.5", "2.25", "2.75"])],
    "cohen-sutherland-3d": _clip3d,
    "liang-barsky-3d": _clip3d,
    "z-buffer": lambda r: ["--row", str(r.randint(1, ZB_HEIGHT - 2))],
    "depth-sort": lambda r: ["--scene", r.choice(["painter", "cyclic", "intersecting"])],
    "floating-horizon": lambda r: ["--nx", str(r.randint(4, 7)), "--ny", str(r.randint(3, 5)),
                                   "--width", "24", "--height", "16"],
    "ray-tracing": lambda r: [str(r.randint(4, RT_WIDTH - 5)), str(r.randint(4, RT_HEIGHT - 5))],
    "back-face": lambda r: ["--eye", *(str(r.choice([-1, 1]) * r.randint(2, 6)) for _ in "xyz")],
    "gouraud": lambda r: ["--row", str(r.randint(4, SH_HEIGHT - 5))],
    "phong": lambda r: ["--row", str(r.randint(4, SH_HEIGHT - 5))],
    "bsp-tree": lambda r: ["--eye", str(r.randint(0, BSP_WIDTH - 1)),
                           str(r.randint(0, BSP_HEIGHT - 1))],
    "warnock": lambda r: ["--scene", r.choice(["overlap", "surrounding"])],
    "scan-line-visible": lambda r: ["--scene", r.choice(["overlap", "surrounding"])],
    "ray-casting": lambda r: ["--row", str(r.randint(1, ZB_HEIGHT - 2))],
    "inbetween-spacing": lambda r: ["--n", str(r.randint(3, 9)), "--spacing",
                                    r.choice(["constant", "accelerate", "decelerate",
                                              "accelerate-decelerate"])],
    "morph-equalize": lambda r: ["--t", r.choice(["0.25", "0.5", "0.75"])],
}

#: Draws tried for a case whose table asks something before the algorithm's
#: example case (:data:`scanline.studio.explorer.DEFAULTS`) is taken.
TRIES = 20


def _check_algorithm(algorithm: object) -> str:
    if not isinstance(algorithm, str) or algorithm not in QUESTIONS:
        raise BadArguments(f"unknown algorithm {algorithm!r}; choose one of "
                           + ", ".join(QUESTIONS))
    return algorithm


def _check_seed(seed: object) -> int:
    if isinstance(seed, bool) or not isinstance(seed, int):
        raise TypeError(f"seed must be an integer 0..{MAX_SEED}, not {type(seed).__name__}")
    if not 0 <= seed <= MAX_SEED:
        raise ValueError(f"seed must be 0..{MAX_SEED}, not {seed}")
    return seed


def case(algorithm: str, seed: int) -> list[str]:
    """The arguments (as for ``scanline trace ALGORITHM``) of quiz case ``seed``.

    Parameters
    ----------
    algorithm : str
        An algorithm of the explorer's catalog (``scanline trace`` names).
    seed : int
        The case number, 0 to :data:`MAX_SEED`; the same seed gives the same case.

    Returns
    -------
    list of str
        Command-line arguments of a case whose table has at least one question.

    Raises
    ------
    ValueError
        An unknown algorithm (:class:`~scanline.studio.explorer.BadArguments`), a seed
        out of range.
    TypeError
        A seed that is not an integer.

    Notes
    -----
    Each draw comes from ``random.Random(seed)``; a draw whose table asks nothing
    (an empty table) is followed by the next draw of the same generator, and after
    :data:`TRIES` draws the algorithm's example case is taken.

    Examples
    --------
    >>> case("bresenham", 17) == case("bresenham", 17)
    True
    >>> case("depth-sort", 3)[0]
    '--scene'
    """
    algorithm, seed = _check_algorithm(algorithm), _check_seed(seed)
    rng = random.Random(f"{algorithm}:{seed}")
    for _ in range(TRIES):
        args = GENERATORS[algorithm](rng)
        try:
            if questions(algorithm, explore(algorithm, args)):
                return args
        except (ValueError, TypeError):
            continue
    return list(DEFAULTS[algorithm])


def questions(algorithm: str, view: dict[str, Any]) -> list[dict[str, Any] | None]:
    """The question of each step of ``view`` (:func:`scanline.studio.explorer.view_of`),
    answered from its rows; ``None`` where the row has no value in the asked column.

    Parameters
    ----------
    algorithm : str
        The view's algorithm.
    view : dict
        The explorer's view of one case (its ``columns`` and ``rows``).

    Returns
    -------
    list of dict or None
        One entry per row: ``kind``, ``columns``, ``prompt``, ``answer`` (the row's
        cells, a list), ``given`` ([column, cell] pairs of the row shown with the
        question), ``choices`` (for "choice": the values the column takes in the
        table, sorted) and ``tolerance``; an empty list when no row is asked.

    Examples
    --------
    >>> from scanline.studio.explorer import explore
    >>> q = questions("bresenham", explore("bresenham", ["0", "0", "3", "1"]))
    >>> q[0]["kind"], q[0]["answer"]
    ('pixel', [1, 0])
    """
    question = QUESTIONS[_check_algorithm(algorithm)]
    index = [view["columns"].index(c) for c in question.columns]
    shown = [(c, view["columns"].index(c)) for c in question.given if c in view["columns"]]
    answers = [[row[i] for i in index] for row in view["rows"]]
    choices = sorted({str(a[0]) for a in answers if a[0] is not None} | set(question.offered))
    asked: list[dict[str, Any] | None] = [None if any(v is None for v in a) else
             {"kind": question.kind, "columns": list(question.columns), "prompt": question.prompt,
              "answer": a, "tolerance": question.tolerance,
              "given": [[c, row[i]] for c, i in shown],
              **({"choices": choices} if question.kind == "choice" else {})}
             for a, row in zip(answers, view["rows"])]
    return asked if any(asked) else []


def quiz(algorithm: str, args: list[str]) -> dict[str, Any]:
    """The explorer's view of one case with its questions (``view["quiz"]``).

    Parameters
    ----------
    algorithm : str
        An algorithm of the catalog.
    args : list of str
        Its arguments, as for ``scanline trace``.

    Returns
    -------
    dict
        :func:`scanline.studio.explorer.explore`'s view, with ``quiz``: the list of
        :func:`questions`.

    Examples
    --------
    >>> view = quiz("z-buffer", ["--row", "4"])
    >>> view["quiz"][0]["choices"]
    ['keep', 'write']
    """
    view = explore(_check_algorithm(algorithm), args)
    view["quiz"] = questions(algorithm, view)
    return view


def algorithms() -> list[str]:
    """The algorithms that have a quiz: the explorer's whole catalog.

    Returns
    -------
    list of str
        The names, in the catalog's order.

    Examples
    --------
    >>> "bresenham" in algorithms()
    True
    """
    return [c["name"] for c in catalog() if c["name"] in QUESTIONS]
