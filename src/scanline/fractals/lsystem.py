"""Shape grammars and L-systems (Hearn & Baker, section 10-19): a set of rewriting
rules applied in parallel to every symbol of a string, and a turtle that reads the
string as drawing commands.

Symbols the turtle knows (Prusinkiewicz and Lindenmayer's):

==========  =====================================================
``F``, ``G``  move forward one step, drawing
``f``       move forward without drawing
``+``       turn left (counterclockwise) by the angle
``-``       turn right by the angle
``|``       turn around (180 degrees)
``[``       push the turtle's position and heading (a branch starts)
``]``       pop them (the branch ends)
==========  =====================================================

Any other symbol (``X``, ``A``, ``B`` ...) only takes part in the rewriting.  The
string's length after each step follows from the rules alone (a count of each
symbol, multiplied by the rules' matrix), so a derivation too long for the limits is
refused before it is made (:mod:`scanline.fractals.limits`).

References
----------
.. [1] D. Hearn and M. P. Baker, *Computer Graphics, C Version*, 2nd ed., 1997,
   section 10-19 (shape grammars and other procedural methods).
.. [2] A. Lindenmayer, "Mathematical models for cellular interaction in
   development", *Journal of Theoretical Biology* 18, 1968.
.. [3] P. Prusinkiewicz and A. Lindenmayer, *The Algorithmic Beauty of Plants*,
   Springer, 1990, chapter 1 (turtle interpretation, bracketed L-systems).
"""

import math
from typing import Dict, List, Sequence, Tuple, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from . import limits

#: Most rewriting steps (a string that stops growing could otherwise be rewritten
#: for ever).
MAX_STEPS = 10_000

#: The turtle's command code of each symbol (:func:`scanline._kernels.fractals.turtle`).
COMMANDS = {"F": 1, "G": 1, "f": 2, "+": 3, "-": 4, "[": 5, "]": 6, "|": 7}


def _steps(n: int) -> int:
    n = v.positive_int("n", n, minimum=0)
    if n > MAX_STEPS:
        raise ArgumentValueError(f"n={n:,} rewriting steps is more than the limit of "
                                 f"{MAX_STEPS:,} (scanline.fractals.lsystem.MAX_STEPS)")
    return n


class LSystem:
    """A deterministic, context-free L-system.

    Parameters
    ----------
    axiom : str
        The starting string.
    rules : dict
        symbol -> replacement string (single-character symbols); symbols without a
        rule stay as they are.
    angle : float
        The turtle's turn, radians (or a string with its unit, ``"25deg"``).

    Examples
    --------
    >>> from scanline.fractals import LSystem
    >>> algae = LSystem("A", {"A": "AB", "B": "A"})
    >>> [algae.string(n) for n in range(5)]
    ['A', 'AB', 'ABA', 'ABAAB', 'ABAABABA']
    >>> algae.length(30)          # Fibonacci numbers, counted without the string
    2178309
    """

    def __init__(self, axiom: str, rules: Dict[str, str],
                 angle: Union[float, str] = math.pi / 2) -> None:
        if not isinstance(axiom, str) or not axiom:
            raise ArgumentTypeError(f"axiom must be a non-empty string, got {v._show(axiom)}")
        if not isinstance(rules, dict):
            raise ArgumentTypeError(f"rules must be a dict symbol -> replacement, got "
                                    f"{v._show(rules)}")
        for key, value in rules.items():
            if not isinstance(key, str) or len(key) != 1:
                raise ArgumentValueError(f"rules: each symbol must be one character, got "
                                         f"{key!r}")
            if not isinstance(value, str):
                raise ArgumentTypeError(f"rules[{key!r}] must be a string, got {v._show(value)}")
        self.axiom, self.rules = axiom, dict(rules)
        self.angle = v.angle("angle", angle)
        self.symbols = sorted(set(axiom).union(*rules.values(), rules))
        index = {s: i for i, s in enumerate(self.symbols)}
        n = len(self.symbols)
        self._matrix: List[List[int]] = [[0] * n for _ in range(n)]      # Python ints: exact at any size
        for s in self.symbols:
            for r in rules.get(s, s):
                self._matrix[index[r]][index[s]] += 1
        self._start = [axiom.count(s) for s in self.symbols]
        self._table = str.maketrans(self.rules)

    def counts(self, n: int) -> List[int]:
        """How many of each symbol (in :attr:`symbols` order) the string has after
        ``n`` steps: the rules' matrix applied n times to the axiom's counts.

        Parameters
        ----------
        n : int
            Rewriting steps, 0..:data:`MAX_STEPS`.

        Returns
        -------
        list of int
            Exact counts (counting stops once far past every limit).

        Raises
        ------
        ArgumentValueError
            ``n`` negative or past :data:`MAX_STEPS`.

        Examples
        --------
        F -> F+F: each F makes two F and one +, so after two steps 4 F and 1 + 2 = 3 +.

        >>> from scanline.fractals import LSystem
        >>> grow = LSystem("F", {"F": "F+F"})
        >>> grow.symbols, grow.counts(2)
        (['+', 'F'], [3, 4])
        """
        n = _steps(n)
        c = self._start
        for _ in range(n):
            c = [sum(row[j] * c[j] for j in range(len(c))) for row in self._matrix]
            if sum(c) > limits.MAX_POINTS * 64:      # far past any limit: stop counting
                return c
        return c

    def length(self, n: int) -> int:
        """The string's length after ``n`` steps (from :meth:`counts`).

        Parameters
        ----------
        n : int
            Rewriting steps.

        Returns
        -------
        int
            The length, without making the string.

        Examples
        --------
        >>> from scanline.fractals import LSystem
        >>> LSystem("F", {"F": "F+F"}).length(3)      # 8 F and 7 +
        15
        """
        return sum(self.counts(n))

    def string(self, n: int) -> str:
        """The string after ``n`` parallel rewriting steps.

        Parameters
        ----------
        n : int
            Rewriting steps.

        Returns
        -------
        str
            The derived string.

        Raises
        ------
        ArgumentValueError
            A string longer than the limits allow.

        Examples
        --------
        >>> from scanline.fractals import LSystem
        >>> LSystem("F", {"F": "F+F"}).string(2)
        'F+F+F+F'
        """
        n = _steps(n)
        limits.points("n", self.length(n), f"{n} steps of the L-system (symbols)",
                      bytes_per_point=2)
        s = self.axiom
        for _ in range(n):
            s = s.translate(self._table)
        return s

    def draw(self, n: int, step: float = 1.0, start: Sequence[float] = (0.0, 0.0),
             heading: Union[float, str] = math.pi / 2) -> List[NDArray[np.float64]]:
        """The turtle's polylines after ``n`` steps: see :func:`turtle`.

        Parameters
        ----------
        n : int
            Rewriting steps.
        step : float
            The length of one move.
        start : (float, float)
            The turtle's first position.
        heading : float
            Its first heading, radians from +x.

        Returns
        -------
        list of ndarray (k, 2)
            The polylines.

        Examples
        --------
        Up one step, a left turn of 90 degrees, one step west:

        >>> from scanline.fractals import LSystem
        >>> [line.tolist() for line in LSystem("F", {"F": "F+F"}, "90deg").draw(1)]
        [[[0.0, 0.0], [0.0, 1.0], [-1.0, 1.0]]]
        """
        return turtle(self.string(n), self.angle, step, start, heading)

    def __repr__(self) -> str:
        rules = ", ".join(f"{k} -> {r}" for k, r in self.rules.items())
        return f"LSystem({self.axiom!r}; {rules}; angle {math.degrees(self.angle):g} deg)"


def _directions(angle: float, heading: float
                ) -> Tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The direction tables (cosines, sines of heading + t angle) of a turn that
    divides the full turn into an even number of directions (right angles: 4, 60
    degrees: 6 ...), with the values of the axes exact; else empty tables."""
    n = 2 * math.pi / angle if angle > 0 else 0.0
    if not n <= 3600.5:                 # (a tiny angle: n is huge or infinite)
        return np.zeros(0), np.zeros(0)
    count = int(round(n))
    if count < 2 or count % 2 or count > 3600 or abs(n - count) > 1e-9 * count:
        return np.zeros(0), np.zeros(0)
    a = heading + np.arange(count) * (2 * math.pi / count)
    cosines, sines = np.cos(a), np.sin(a)
    for t in (cosines, sines):
        near = np.abs(np.abs(t) - 1) < 1e-12
        t[near] = np.sign(t[near])
        t[np.abs(t) < 1e-12] = 0.0
    return cosines, sines


def turtle(string: str, angle: Union[float, str], step: float = 1.0,
           start: Sequence[float] = (0.0, 0.0),
           heading: Union[float, str] = math.pi / 2) -> List[NDArray[np.float64]]:
    """The polylines a turtle draws reading ``string`` (the symbols of this module's
    table; others are skipped).

    Parameters
    ----------
    string : str
        The commands.
    angle : float
        Radians per turn (or a string with its unit).
    step : float
        The length of one move.
    start : (float, float)
        The turtle's first position.
    heading : float
        Its first heading, radians from +x (default: up, as plants grow).

    Returns
    -------
    list of ndarray, each (k, 2)
        One polyline per unbroken run of moves (a branch, or the run after a ``f``).

    Raises
    ------
    ArgumentTypeError
        ``string`` not a str, or ``start`` not (x, y).
    ArgumentValueError
        Unbalanced brackets, or more points than the limits allow.

    Examples
    --------
    A branch to the left, back to its start, a jump up and a move right:

    >>> import scanline as sl
    >>> [line.tolist() for line in sl.fractals.turtle("F[+F]f-F", "90deg")]
    [[[0.0, 0.0], [0.0, 1.0], [-1.0, 1.0]], [[0.0, 2.0], [1.0, 2.0]]]
    """
    from .._kernels import fractals as k
    from .._kernels._jit import call

    if not isinstance(string, str):
        raise ArgumentTypeError(f"string must be a str, got {v._show(string)}")
    turn = v.angle("angle", angle)
    length = v.number("step", step)
    first_heading = v.angle("heading", heading)
    if not isinstance(start, (tuple, list, np.ndarray)) or len(start) != 2:
        raise ArgumentTypeError(f"start must be (x, y), got {v._show(start)}")
    x0, y0 = v.number("start[0]", start[0]), v.number("start[1]", start[1])
    lookup = np.zeros(128, np.int64)
    for symbol, code in COMMANDS.items():
        lookup[ord(symbol)] = code
    raw = np.frombuffer(string.encode("utf-32-le"), np.uint32)
    codes = np.where(raw < 128, lookup[np.minimum(raw, 127)], 0).astype(np.int64)
    moves = int(np.count_nonzero(codes == 1))
    runs = int(np.count_nonzero((codes == 2) | (codes == 6))) + 1
    limits.points("string", moves + runs, "the turtle's drawing", bytes_per_point=40)
    nesting = np.cumsum((codes == 5).astype(np.int64) - (codes == 6))
    if len(nesting) and nesting.min() < 0:
        where = int(np.argmax(nesting < 0))
        raise ArgumentValueError(f"string has a ']' at position {where} with no '[' open "
                                 "before it; branches must be balanced")
    cosines, sines = _directions(turn, first_heading)
    points = np.empty((moves + min(moves, runs), 2))
    starts = np.zeros(min(moves, runs) + 1, np.int64)
    stack = np.empty((int(nesting.max()) if len(nesting) else 0, 3))
    count, lines = call(k.turtle, len(codes), codes, length, turn, x0, y0, first_heading,
                        cosines, sines, points, starts, stack)
    return [points[starts[i]:starts[i + 1]].copy() for i in range(lines)]


#: Named L-systems: (axiom, rules, angle in degrees).  Hilbert's curve (fills the
#: square), Peano's (the square, by thirds), a bracketed plant (Prusinkiewicz &
#: Lindenmayer, figure 1.24(f)) and Koch's curve written as a grammar.
EXAMPLES = {
    "hilbert": ("A", {"A": "+BF-AFA-FB+", "B": "-AF+BFB+FA-"}, 90),
    "peano": ("X", {"X": "XFYFX+F+YFXFY-F-XFYFX", "Y": "YFXFY-F-XFYFX+F+YFXFY"}, 90),
    "plant": ("X", {"X": "F+[[X]-X]-F[-FX]+X", "F": "FF"}, 25),
    "koch": ("F", {"F": "F+F--F+F"}, 60),
}


def example(name: str) -> LSystem:
    """One of the :data:`EXAMPLES` as an :class:`LSystem`.

    Parameters
    ----------
    name : {"hilbert", "peano", "plant", "koch"}
        The example.

    Returns
    -------
    LSystem
        Its axiom, rules and angle.

    Raises
    ------
    ArgumentValueError
        An unknown name.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.fractals.example("koch")
    LSystem('F'; F -> F+F--F+F; angle 60 deg)
    """
    v.choice("name", name, tuple(EXAMPLES))
    axiom, rules, degrees = EXAMPLES[name]
    return LSystem(axiom, rules, math.radians(degrees))


def hilbert(order: int) -> NDArray[np.float64]:
    """Hilbert's curve of ``order`` (4^order cells of a 2^order square): the points
    of the cells' centers in visiting order, cell side 1, from (0.5, 0.5).

    Parameters
    ----------
    order : int
        >= 1.

    Returns
    -------
    ndarray (4^order, 2)
        The cells' centers in visiting order.

    Raises
    ------
    ArgumentValueError
        An order below 1 or past the limits.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.fractals.hilbert(1).tolist()
    [[0.5, 0.5], [0.5, 1.5], [1.5, 1.5], [1.5, 0.5]]
    """
    order = v.positive_int("order", order, minimum=1)
    limits.points("order", limits.power(4, order), f"Hilbert's curve of order {order}")
    lines = example("hilbert").draw(order, start=(0.5, 0.5), heading=0.0)
    return lines[0]


def plant(n: int = 5, angle: Union[float, str] = "25deg",
          step: float = 1.0) -> List[NDArray[np.float64]]:
    """The bracketed plant of :data:`EXAMPLES` after ``n`` steps, as polylines.

    Parameters
    ----------
    n : int
        Rewriting steps.
    angle : float or str
        The branching angle.
    step : float
        The length of one move.

    Returns
    -------
    list of ndarray (k, 2)
        The polylines (Hearn & Baker 10-19; Prusinkiewicz & Lindenmayer, figure
        1.24(f)).

    Examples
    --------
    One step, F+[[X]-X]-F[-FX]+X: the stem up to (0, 1), then from there up to (0, 2)
    and a branch 25 degrees to the right, to (sin 25°, 2 + cos 25°):

    >>> import scanline as sl
    >>> lines = sl.fractals.plant(1)
    >>> len(lines), lines[1].round(4).tolist()
    (2, [[0.0, 1.0], [0.0, 2.0], [0.4226, 2.9063]])
    """
    axiom, rules, _ = EXAMPLES["plant"]
    return LSystem(axiom, rules, angle).draw(n, step=step)
