"""Step table of the scan-line seed fill (notes, chapter 2, Q.8)."""

from typing import TYPE_CHECKING, Any, Callable, Dict, List, Sequence, Tuple, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .._typing import Connectivity
from ..errors import ArgumentTypeError, ArgumentValueError
from .table import Table

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer

#: A grid: rows of characters, top row first (a string with rows separated by
#: newlines or '/', or a sequence of strings).
_Grid = Union[str, Sequence[str]]
#: ``ref_of(buf, packed, x, y, chars)``: the seed fill's reference colors.
_RefOf = Callable[[NDArray[np.uint8], bool, int, int, List[str]], NDArray[Any]]

#: The grid traced when none is given, rows top first: '#' walls, a room with a
#: pillar (left), a second room (right) and a gap that joins them only diagonally,
#: so that connectivity 4 and 8 differ.
EXAMPLE_GRID = (
    "###########",
    "#.....#...#",
    "#.###.#...#",
    "#.....#...#",
    "######.####",
    "###########",
)

#: A trace prints every step; bigger grids would print pages nobody reads.
MAX_CELLS = 10_000


def _rows(grid: object) -> List[str]:
    """The grid's rows, top first: a string (rows separated by newlines or '/') or
    a sequence of strings, all of one length."""
    if isinstance(grid, str):
        rows = grid.replace("/", "\n").split("\n")
    elif isinstance(grid, (list, tuple)) and all(isinstance(r, str) for r in grid):
        rows = list(grid)
    else:
        raise ArgumentTypeError(
            f"grid must be a string of rows (separated by newlines or '/') or a list of "
            f"strings, got {v._show(grid)}"
        )
    rows = [r for r in rows if r.strip()]
    if not rows or len({len(r) for r in rows}) != 1:
        raise ArgumentValueError(
            f"grid must have at least one row and rows of equal length, got row lengths "
            f"{[len(r) for r in rows]}"
        )
    if len(rows) * len(rows[0]) > MAX_CELLS:
        raise ArgumentValueError(
            f"grid has {len(rows)} x {len(rows[0])} cells; a trace takes at most {MAX_CELLS}"
        )
    return rows


def grid_frame(grid: _Grid) -> Tuple["FrameBuffer", List[str]]:
    """A mode "L" frame buffer holding ``grid``: each distinct character becomes one
    gray level (in order of first appearance), row 0 of the text is the top scan line.
    Returns the frame buffer and the list of characters, indexed by level."""
    from ..framebuffer import FrameBuffer

    rows = _rows(grid)
    chars = list(dict.fromkeys("".join(rows)))
    if len(chars) > 255:
        raise ArgumentValueError("grid uses more than 255 distinct characters")
    levels = {c: i for i, c in enumerate(chars)}
    image = np.array([[levels[c] for c in row] for row in rows], np.uint8)
    return FrameBuffer.from_array(image, mode="L"), chars


def _seed_table(kind: int, x: int, y: int, grid: _Grid, connectivity: Connectivity,
                ref_of: _RefOf
                ) -> Tuple[List[Dict[str, Any]], List[Tuple[int, int]], Tuple[int, int],
                           "FrameBuffer"]:
    """Run the seed fill ``kind`` (a kernel constant) from (x, y) on ``grid`` with the
    kernel's own step loop as Python (no compilation); ``ref_of(buf, packed, x, y,
    chars)`` gives the kernel's reference colors.  Returns the rows, the pixels filled,
    the seed and the frame buffer."""
    from ..draw.seedfill import eight_connected, seed
    from .._kernels import seedfill as k
    from .._kernels._jit import python
    from .._kernels.variants import layout, token

    fb, chars = grid_frame(grid)
    x, y = seed(fb, x, y)
    eight = eight_connected(connectivity)
    buf, packed = fb._raster()
    ref = np.ascontiguousarray(ref_of(buf, packed, x, y, chars), np.int64)
    # the drawing kernel's own loop, run as Python with its step log on
    _, steps, pushed = python(k.seed_loop)(buf, layout(packed), token(kind), fb.width,
                                           fb.height, x, y, eight, ref,
                                           np.array([255], np.uint8), token(k.TRACING))
    rows: List[Dict[str, Any]] = []
    pixels: List[Tuple[int, int]] = []
    stack, j = [(x, y)], 0
    for i, (sx, sy, xl, xr, n) in enumerate(np.asarray(steps).tolist()):
        stack.pop()
        new = [tuple(p) for p in np.asarray(pushed[j:j + n]).tolist()]
        j += n
        stack += new
        if xl >= 0:
            pixels += [(px, sy) for px in range(xl, xr + 1)]
        rows.append({
            "k": i, "x": sx, "y": sy,
            "span": f"{xl}..{xr}" if xl >= 0 else "already filled",
            "pushed": " ".join(f"({a}, {b})" for a, b in new),
            "stack": " ".join(f"({a}, {b})" for a, b in stack),
        })
    return rows, pixels, (x, y), fb


_COLUMNS = ["k", "x", "y", "span", "pushed", "stack"]


def _push_note(connectivity: Connectivity) -> str:
    return ("pop a seed, fill its span x_left..x_right, push the rightmost pixel of each "
            "unfilled run above and below" + (" (one pixel wider each way)"
                                              if connectivity == 8 else ""))


def flood_fill(x: int, y: int, grid: Union[str, Sequence[str]] = EXAMPLE_GRID,
               connectivity: Connectivity = 4) -> Table:
    """The scan-line seed fill step by step, flood-filling the region of ``grid``
    that holds the seed's character.

    Each row of the table is one step k: the seed popped from the stack, the span
    filled from it (x_left..x_right on scan line y; "already filled" when an earlier
    span covered the seed), the seeds pushed (the rightmost pixel of each run still
    to be filled in the rows above and below) and the stack after pushing, top last.
    ``table.pixels()`` is the set of pixels filled: exactly those that
    :func:`scanline.draw.flood_fill` paints, since both run the same kernel.

    Parameters
    ----------
    x, y : int
        The seed, in device coordinates: x to the right, y up, (0, 0) the
        bottom-left character of the grid.
    grid : str or list of str
        Rows of characters, top row first; a string separates rows with newlines or
        '/'.  Each character is a color.  Default: :data:`EXAMPLE_GRID`.
    connectivity : {4, 8}
        4 (the default) fills through edges only, 8 through corners too.

    Returns
    -------
    Table
        Columns k, x, y, span, pushed, stack, one row per seed popped; ``pixels()``
        is the set of pixels filled.

    Raises
    ------
    TypeError
        If the seed is not numeric, `grid` is not text.
    ValueError
        If the seed lies outside the grid, the grid's rows differ in length or it has
        more than `MAX_CELLS` cells, or `connectivity` is not 4 or 8.

    Examples
    --------
    >>> t = flood_fill(1, 1, ["####", "#..#", "#..#", "####"])
    >>> [(r["k"], r["x"], r["y"], r["span"], r["stack"]) for r in t.rows]
    [(0, 1, 1, '1..2', '(2, 2)'), (1, 2, 2, '1..2', '')]
    """
    from ..draw.seedfill import seed_value
    from .._kernels import seedfill as k

    def ref_of(buf: NDArray[np.uint8], packed: bool, x: int, y: int,
               chars: List[str]) -> NDArray[Any]:
        value = seed_value(buf, packed, x, y)
        return np.stack([value, value])

    rows, pixels, (x, y), fb = _seed_table(k.FLOOD, x, y, grid, connectivity, ref_of)
    value = _rows(grid)[fb.height - 1 - y][x]
    notes = [
        f"flood fill of the {value!r} region from seed ({x}, {y}), "
        f"{connectivity}-connected, on a {fb.width} x {fb.height} grid (y up, "
        "(0, 0) bottom left)",
        _push_note(connectivity),
        f"stack at the start: ({x}, {y}); top of the stack last",
    ]
    return Table(f"Scan-line seed fill from ({x}, {y})", _COLUMNS, rows, notes, pixels)


def boundary_fill(x: int, y: int, grid: Union[str, Sequence[str]] = EXAMPLE_GRID,
                  boundary: str = "#", connectivity: Connectivity = 4) -> Table:
    """The scan-line boundary fill step by step: the region around the seed bounded
    by the characters of ``boundary`` (each character of the grid is a color).

    The rows are those of :func:`flood_fill` (seed popped, span filled, seeds pushed,
    the stack); the region is every pixel reachable from the seed that is not a
    boundary character, whatever its own character.  ``table.pixels()`` is exactly
    what :func:`scanline.draw.boundary_fill` paints: the table runs the same kernel
    loop, as Python.

    Parameters
    ----------
    x, y : int
        The seed, in device coordinates (y up, (0, 0) the bottom-left character).
    grid : str or list of str
        Rows of characters, top row first (see :func:`flood_fill`).
    boundary : str
        The boundary color(s): one or more characters of the grid.
    connectivity : {4, 8}
        4 (the default) fills through edges only, 8 through corners too.

    Returns
    -------
    Table
        Columns k, x, y, span, pushed, stack, one row per seed popped; ``pixels()``
        is the set of pixels filled.

    Raises
    ------
    TypeError
        If the seed is not numeric, `grid` is not text, or `boundary` is not a non-empty string.
    ValueError
        If the seed lies outside the grid, the grid's rows differ in length or it has
        more than `MAX_CELLS` cells, or `connectivity` is not 4 or 8, or no character of `boundary` occurs in the grid.

    Notes
    -----
    Notes, chapter 2, Q.8, "Boundary Fill Algorithm"; Hearn & Baker, section 3-11
    (boundary-fill algorithm, the scan-line stack of spans).

    Examples
    --------
    >>> t = boundary_fill(1, 1, ["#####", "#.o.#", "#####"], boundary="#")
    >>> [(r["k"], r["span"]) for r in t.rows], sorted(t.pixels())
    ([(0, '1..3')], [(1, 1), (2, 1), (3, 1)])
    """
    from .._kernels import seedfill as k

    if not isinstance(boundary, str) or not boundary:
        raise ArgumentTypeError(
            f"boundary must be a string of one or more grid characters, got {v._show(boundary)}")
    fb, chars = grid_frame(grid)
    missing = [c for c in boundary if c not in chars]
    if len(missing) == len(set(boundary)):
        raise ArgumentValueError(
            f"boundary={boundary!r}: none of its characters occurs in the grid, which uses "
            f"{''.join(chars)!r}")

    def ref_of(buf: NDArray[np.uint8], packed: bool, x: int, y: int,
               chars: List[str]) -> NDArray[Any]:
        return np.array([[chars.index(c)] for c in dict.fromkeys(boundary) if c in chars])

    rows, pixels, (x, y), fb = _seed_table(k.BOUNDARY, x, y, grid, connectivity,
                                                  ref_of)
    notes = [
        f"boundary fill bounded by {boundary!r} from seed ({x}, {y}), "
        f"{connectivity}-connected, on a {fb.width} x {fb.height} grid (y up, "
        "(0, 0) bottom left)",
        _push_note(connectivity),
        f"stack at the start: ({x}, {y}); top of the stack last",
    ]
    return Table(f"Scan-line boundary fill from ({x}, {y})", _COLUMNS, rows, notes, pixels)
