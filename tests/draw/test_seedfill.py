"""sl.draw.flood_fill / sl.draw.boundary_fill and sl.trace.flood_fill.

Expected regions come from hand-made grids, from a pure-Python breadth-first search
written here, and from cv2.floodFill.
"""

import math
from collections import deque

import cv2
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from tests.reference import HYPOTHESIS

N4 = ((1, 0), (-1, 0), (0, 1), (0, -1))
N8 = N4 + ((1, 1), (1, -1), (-1, 1), (-1, -1))


# -- helpers --------------------------------------------------------------------------
def grid_fb(rows, mode="L", colors=None):
    """A frame buffer from text rows (top first): '.' -> 0, '#' -> 255, other
    characters -> ``colors[char]``."""
    colors = {".": 0, "#": 255, **(colors or {})}
    image = np.array([[colors[c] for c in row] for row in rows], np.uint8)
    if mode == "L":
        return sl.FrameBuffer.from_array(image, mode="L")
    fb = sl.FrameBuffer(image.shape[1], image.shape[0], mode=mode)
    for r, row in enumerate(rows):
        for x, c in enumerate(row):
            fb.set_pixel(x, len(rows) - 1 - r, colors[c] if mode != "1" else int(colors[c] > 0))
    return fb


def text(fb, values):
    """The image as text rows: each pixel value mapped through ``values``."""
    a = fb.to_array()
    if a.ndim == 3:
        return ["".join(values[tuple(p)] for p in row) for row in a.tolist()]
    return ["".join(values[int(p)] for p in row) for row in a.tolist()]


def bfs(image, seed, inside, neighbors):
    """Pixels (row, col) connected to ``seed`` through pixels where ``inside``."""
    h, w = image.shape[:2]
    todo, seen = deque([seed]), {seed}
    while todo:
        r, c = todo.popleft()
        for dr, dc in neighbors:
            q = (r + dr, c + dc)
            if 0 <= q[0] < h and 0 <= q[1] < w and q not in seen and inside(image[q]):
                seen.add(q)
                todo.append(q)
    return seen


def region_mask(shape, cells):
    m = np.zeros(shape, bool)
    for r, c in cells:
        m[r, c] = True
    return m


# -- exact tiny images ------------------------------------------------------------------
ROOM = [
    "#######",
    "#...#.#",
    "#.#.#.#",
    "#..#..#",
    "#######",
]


def test_flood_fill_by_hand():
    fb = grid_fb(ROOM)
    n = sl.draw.flood_fill(fb, 1, 1, color=128)
    assert n == 7
    assert text(fb, {0: ".", 255: "#", 128: "o"}) == [
        "#######",
        "#ooo#.#",
        "#o#o#.#",
        "#oo#..#",
        "#######",
    ]


def test_diagonal_wall_separates_4_but_not_8():
    rows = ["..#", ".#.", "#.."]
    fb4, fb8 = grid_fb(rows), grid_fb(rows)
    assert sl.draw.flood_fill(fb4, 0, 2, 100, connectivity=4) == 3
    assert sl.draw.flood_fill(fb8, 0, 2, 100, connectivity=8) == 6
    values = {0: ".", 255: "#", 100: "o"}
    assert text(fb4, values) == ["oo#", "o#.", "#.."]
    assert text(fb8, values) == ["oo#", "o#o", "#oo"]


def test_boundary_fill_by_hand_with_several_boundary_colors():
    rows = ["#####", "#..b#", "#.b.#", "#####"]
    fb = grid_fb(rows, colors={"b": 50})
    n = sl.draw.boundary_fill(fb, 1, 1, color=200, boundary=[255, 50])
    assert n == 3
    assert text(fb, {0: ".", 255: "#", 50: "b", 200: "o"}) == ["#####", "#oob#", "#ob.#", "#####"]


def test_boundary_fill_goes_through_pixels_already_in_the_fill_color():
    # The notes' warning: a recursive boundary fill that also stops at the fill color
    # leaves the right part of this room empty, behind the fill-colored stroke.
    rows = ["#######", "#..f..#", "#..f..#", "#..f..#", "#######"]
    fb = grid_fb(rows, colors={"f": 100})
    n = sl.draw.boundary_fill(fb, 1, 1, color=100, boundary=255)
    assert n == 15
    assert text(fb, {255: "#", 100: "o"}) == [
        "#######", "#ooooo#", "#ooooo#", "#ooooo#", "#######"]


def test_seed_on_the_boundary_fills_nothing():
    fb = grid_fb(ROOM)
    before = fb.to_array()
    assert sl.draw.boundary_fill(fb, 0, 0, color=9, boundary=255) == 0
    assert np.array_equal(fb.to_array(), before)


def test_fill_with_the_same_color_reports_the_region_and_changes_nothing():
    fb = grid_fb(ROOM)
    before = fb.to_array()
    assert sl.draw.flood_fill(fb, 1, 1, color=0) == 7
    assert np.array_equal(fb.to_array(), before)


def test_tolerance_that_covers_the_fill_color_terminates():
    fb = sl.FrameBuffer.from_array(np.array([[10, 12, 14, 40]], np.uint8), mode="L")
    assert sl.draw.flood_fill(fb, 0, 0, color=13, tolerance=5) == 3
    assert fb.to_array().tolist() == [[13, 13, 13, 40]]


@pytest.mark.parametrize("mode", ["1", "L", "RGB", "RGBA", "P"])
def test_every_mode(mode):
    fb = grid_fb(ROOM, mode=mode) if mode != "P" else None
    if mode == "P":
        fb = sl.FrameBuffer(7, 5, mode="P", color_table=["black", "white", "red"])
        for r, row in enumerate(ROOM):
            for x, c in enumerate(row):
                fb.set_pixel(x, 4 - r, 1 if c == "#" else 0)
    fill = {"1": 1, "P": 2}.get(mode, "red")
    assert sl.draw.flood_fill(fb, 5, 2, color=fill) == 4
    wall = {"1": 1, "P": 1}.get(mode, "white")
    assert sl.draw.boundary_fill(fb, 1, 3, color=fill, boundary=wall) == 7
    region = {(x, y) for y in range(5) for x in range(7) if ROOM[4 - y][x] == "."}
    for x in range(7):
        for y in range(5):
            expected = fb.pixel(fill) if (x, y) in region else fb.pixel(wall)
            got = fb.get_pixel(x, y)
            assert np.array_equal(np.atleast_1d(got), expected), (x, y)


def test_mode_1_packed_bits_across_byte_boundaries():
    fb = sl.FrameBuffer(21, 3, mode="1")
    sl.draw.line(fb, 13, 0, 13, 2, color=1)
    assert sl.draw.flood_fill(fb, 20, 1, color=1) == 21
    assert sl.text_image(fb) == "\n".join(["-------------########"] * 3)
    assert sl.draw.boundary_fill(fb, 0, 0, color=1, boundary=1, connectivity=8) == 39


# -- cross-checks -----------------------------------------------------------------------
@pytest.mark.parametrize("connectivity", [4, 8])
@pytest.mark.parametrize("tolerance", [0, 1, 40])
def test_flood_fill_matches_cv2_on_random_images(connectivity, tolerance):
    rng = np.random.default_rng(connectivity * 100 + tolerance)
    for trial in range(40):
        h, w = rng.integers(1, 40, 2)
        levels = np.array([0, 1, 60, 100, 200], np.uint8)[: rng.integers(2, 6)]
        image = levels[rng.integers(0, len(levels), (h, w))]
        if trial % 2:
            image = np.dstack([image, image[::-1, ::-1], levels[rng.integers(0, len(levels), (h, w))]])
        image = np.ascontiguousarray(image)
        r, c = int(rng.integers(0, h)), int(rng.integers(0, w))
        mask = np.zeros((h + 2, w + 2), np.uint8)
        flags = connectivity | cv2.FLOODFILL_FIXED_RANGE | cv2.FLOODFILL_MASK_ONLY | (1 << 8)
        diff = (tolerance,) * 3
        area, *_ = cv2.floodFill(image.copy(), mask, (c, r), 0, diff, diff, flags)
        expected = mask[1:-1, 1:-1] == 1
        fill = (7, 8, 9) if image.ndim == 3 else 7
        fb = sl.FrameBuffer.from_array(image, mode="RGB" if image.ndim == 3 else "L")
        n = sl.draw.flood_fill(fb, c, h - 1 - r, fill, connectivity, tolerance)
        out = fb.to_array()
        changed = (out != image).any(axis=2) if image.ndim == 3 else out != image
        painted = (out == fill).all(axis=2) if image.ndim == 3 else out == fill
        assert n == area == expected.sum()
        assert not (changed & ~expected).any()
        assert painted[expected].all()


@pytest.mark.parametrize("connectivity", [4, 8])
def test_boundary_fill_matches_a_python_bfs(connectivity):
    rng = np.random.default_rng(connectivity)
    neighbors = N4 if connectivity == 4 else N8
    for _ in range(60):
        h, w = rng.integers(1, 30, 2)
        image = rng.choice(np.array([0, 50, 99, 255], np.uint8), (h, w), p=[0.45, 0.15, 0.15, 0.25])
        r, c = int(rng.integers(0, h)), int(rng.integers(0, w))
        inside = lambda v: v not in (255, 50)  # noqa: E731
        cells = bfs(image, (r, c), inside, neighbors) if inside(image[r, c]) else set()
        expected = region_mask(image.shape, cells)
        fb = sl.FrameBuffer.from_array(image, mode="L")
        n = sl.draw.boundary_fill(fb, c, h - 1 - r, 99, [255, 50], connectivity)
        out = fb.to_array()
        assert n == len(cells)
        assert (out[expected] == 99).all()
        assert np.array_equal(out[~expected], image[~expected])


@pytest.mark.parametrize("connectivity", [4, 8])
def test_trace_fills_exactly_the_drawn_pixels(connectivity):
    rng = np.random.default_rng(10 + connectivity)
    for _ in range(150):
        h, w = rng.integers(1, 12, 2)
        rows = ["".join(rng.choice(list(".#o"), w, p=[0.55, 0.3, 0.15])) for _ in range(h)]
        x, y = int(rng.integers(0, w)), int(rng.integers(0, h))
        table = sl.trace.flood_fill(x, y, rows, connectivity)
        fb = grid_fb(rows, colors={"o": 128})
        before = fb.to_array()
        n = sl.draw.flood_fill(fb, x, y, color=77, connectivity=connectivity)
        a = fb.to_array()
        drawn = {(int(c), int(h - 1 - r)) for r, c in zip(*np.nonzero(a == 77))}
        seed_value = before[h - 1 - y, x]
        cells = bfs(before, (h - 1 - y, x), lambda v: v == seed_value,
                    N4 if connectivity == 4 else N8)
        assert table.pixels() == drawn == {(c, h - 1 - r) for r, c in cells}
        assert n == len(drawn) == sum(
            int(s.split("..")[1]) - int(s.split("..")[0]) + 1
            for s in (r["span"] for r in table.rows) if ".." in s)


def test_trace_table_by_hand():
    t = sl.trace.flood_fill(1, 1, ["#####", "#..##", "#...#", "#####"])
    assert [(r["k"], r["x"], r["y"], r["span"], r["pushed"], r["stack"]) for r in t.rows] == [
        (0, 1, 1, "1..3", "(2, 2)", "(2, 2)"),
        (1, 2, 2, "1..2", "", ""),
    ]
    assert t.pixels() == {(1, 1), (2, 1), (3, 1), (1, 2), (2, 2)}


def test_trace_shows_a_seed_that_was_filled_already():
    # the U-shaped room is reached from both arms; the second seed finds its span done
    t = sl.trace.flood_fill(1, 2)
    assert t.rows[-1]["span"] == "already filled"
    assert t.rows[-1]["stack"] == ""
    assert len(sl.trace.flood_fill(1, 2, connectivity=8).pixels()) > len(t.pixels())


# -- large regions ----------------------------------------------------------------------
def test_large_open_region_and_a_deep_stack():
    fb = sl.FrameBuffer(4096, 4096, mode="L")
    assert sl.draw.flood_fill(fb, 2000, 2000, color=255) == 4096 * 4096
    assert fb.to_array().min() == 255
    # a comb: 1024 teeth push 1024 seeds from one span, and the stack grows past its start
    comb = np.zeros((64, 2048), np.uint8)
    comb[1:, 1::2] = 255
    fb = sl.FrameBuffer.from_array(comb, mode="L")
    assert sl.draw.flood_fill(fb, 0, 0, color=9) == int((comb == 0).sum())
    assert (fb.to_array() != 255).sum() == int((comb == 0).sum())


def test_serpentine_maze_with_a_stack_of_many_seeds():
    h = w = 512
    maze = np.zeros((h, w), np.uint8)
    maze[1::4, :-1] = 255
    maze[3::4, 1:] = 255
    fb = sl.FrameBuffer.from_array(maze, mode="L")
    assert sl.draw.flood_fill(fb, 0, 0, color=100) == int((maze == 0).sum())


# -- bad input --------------------------------------------------------------------------
def test_seed_outside_is_an_error_naming_the_argument():
    fb = sl.FrameBuffer(5, 4, mode="L")
    with pytest.raises(sl.ArgumentValueError, match=r"x=5 is outside 0\.\.4"):
        sl.draw.flood_fill(fb, 5, 0, 1)
    with pytest.raises(sl.ArgumentValueError, match=r"y=-1 is outside 0\.\.3"):
        sl.draw.boundary_fill(fb, 0, -1, 1, 2)


@HYPOTHESIS
@given(x=st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-10**20, 10**20)),
       y=st.integers(0, 3))
def test_fuzz_seed(x, y):
    fb = sl.FrameBuffer(5, 4, mode="RGB")
    finite = isinstance(x, int) or math.isfinite(x)
    if finite and -0.5 <= x < 4.5:
        assert sl.draw.flood_fill(fb, x, y, "red") == 20
        return
    with pytest.raises(sl.ArgumentValueError, match=r"\bx\b"):
        sl.draw.flood_fill(fb, x, y, "red")


@HYPOTHESIS
@given(connectivity=st.one_of(st.integers(), st.floats(), st.text(max_size=3), st.none(),
                              st.booleans()))
def test_fuzz_connectivity(connectivity):
    fb = sl.FrameBuffer(3, 3, mode="L")
    if type(connectivity) is int and connectivity in (4, 8):
        assert sl.draw.flood_fill(fb, 1, 1, 5, connectivity=connectivity) == 9
        return
    with pytest.raises(sl.ArgumentValueError, match="connectivity"):
        sl.draw.flood_fill(fb, 1, 1, 5, connectivity=connectivity)
    with pytest.raises(sl.ArgumentValueError, match="connectivity"):
        sl.draw.boundary_fill(fb, 1, 1, 5, 255, connectivity=connectivity)


@HYPOTHESIS
@given(tolerance=st.one_of(st.floats(allow_nan=True), st.integers(-1000, 1000), st.text(max_size=2)))
def test_fuzz_tolerance(tolerance):
    fb = sl.FrameBuffer(3, 3, mode="L")
    if isinstance(tolerance, (int, float)) and tolerance >= 0:
        assert sl.draw.flood_fill(fb, 1, 1, 5, tolerance=tolerance) == 9
        return
    with pytest.raises((sl.ArgumentValueError, sl.ArgumentTypeError), match="tolerance"):
        sl.draw.flood_fill(fb, 1, 1, 5, tolerance=tolerance)


def test_other_bad_arguments():
    fb = sl.FrameBuffer(3, 3, mode="P")
    with pytest.raises(sl.ArgumentValueError, match="tolerance"):
        sl.draw.flood_fill(fb, 1, 1, "red", tolerance=2)
    with pytest.raises(sl.ArgumentValueError, match="boundary"):
        sl.draw.boundary_fill(fb, 1, 1, "red", boundary=[])
    with pytest.raises(sl.ArgumentTypeError, match="fb"):
        sl.draw.flood_fill(np.zeros((3, 3)), 1, 1, "red")
    with pytest.raises(sl.ArgumentValueError, match="grid"):
        sl.trace.flood_fill(0, 0, ["..", "..."])
    with pytest.raises(sl.ArgumentValueError, match="x=9"):
        sl.trace.flood_fill(9, 0, [".."])
