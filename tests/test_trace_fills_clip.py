"""The step tables of the boundary fill, the scan-line polygon fill and
Sutherland-Hodgman: worked by hand, and equal to what sl.draw draws / sl.clip clips
(DESIGN.md, convention 5)."""

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentTypeError, ArgumentValueError
from scanline.trace.seedfill import grid_frame


def lit(fb):
    a = fb.to_array()
    a = a if a.ndim == 2 else a[..., 0]
    ys, xs = np.nonzero(a[::-1])
    return set(zip(xs.tolist(), ys.tolist()))


# -- boundary fill ---------------------------------------------------------------------------
def test_boundary_fill_by_hand_fills_through_other_colors():
    grid = ["#######",
            "#..o..#",
            "#.###.#",
            "#######"]
    t = sl.trace.boundary_fill(1, 1, grid, boundary="#")
    # the seed's span on y = 1 is 1..1 (walls at x = 0 and 2); the 'o' pixel is filled
    assert [(r["k"], r["x"], r["y"], r["span"]) for r in t.rows][:2] == [
        (0, 1, 1, "1..1"), (1, 1, 2, "1..5")]
    assert t.pixels() == {(1, 1), (5, 1)} | {(x, 2) for x in range(1, 6)}
    assert t.rows[-1]["stack"] == ""


def test_boundary_fill_table_equals_draw_boundary_fill():
    rng = np.random.default_rng(15)
    for trial in range(60):
        h, w = rng.integers(3, 14, 2)
        cells = rng.choice(list("#.o"), size=(h, w), p=[0.35, 0.5, 0.15])
        grid = ["".join(r) for r in cells]
        chars = list(dict.fromkeys("".join(grid)))
        if "#" not in chars:
            continue
        x, y = int(rng.integers(0, w)), int(rng.integers(0, h))
        conn = int(rng.choice([4, 8]))
        t = sl.trace.boundary_fill(x, y, grid, boundary="#", connectivity=conn)
        fb, _ = grid_frame(grid)
        before = fb.to_array().copy()
        sl.draw.boundary_fill(fb, x, y, color=255, boundary=chars.index("#"), connectivity=conn)
        changed = fb.to_array() != before
        painted = {(int(c), h - 1 - int(r)) for r, c in zip(*np.nonzero(changed))}
        assert painted <= t.pixels()
        # pixels that already held the fill value (255) never occur: levels are < 3
        assert t.pixels() == painted, (grid, x, y, conn)


def test_boundary_fill_bad_boundary_is_named():
    with pytest.raises(ArgumentValueError, match="boundary='x'"):
        sl.trace.boundary_fill(1, 1, ["###", "#.#", "###"], boundary="x")
    with pytest.raises(ArgumentTypeError, match="boundary must be"):
        sl.trace.boundary_fill(1, 1, ["###", "#.#", "###"], boundary=3)


def test_flood_fill_table_still_matches_the_notes_example():
    t = sl.trace.flood_fill(1, 1, ["####", "#..#", "#..#", "####"])
    assert [(r["k"], r["x"], r["y"], r["span"], r["stack"]) for r in t.rows] == [
        (0, 1, 1, "1..2", "(2, 2)"), (1, 2, 2, "1..2", "")]


# -- scan-line polygon fill -----------------------------------------------------------------
def test_scan_line_fill_triangle_by_hand():
    # edges (8,1)-(5,6) and (2,1)-(5,6): x = 2 + 3(y-1)/5 and 8 - 3(y-1)/5
    t = sl.trace.scan_line_fill([(2, 1), (8, 1), (5, 6)])
    assert [(e["edge"], e["lower"], e["upper"], e["scan lines"], e["direction"])
            for e in t.edges] == [(1, "(8, 1)", "(5, 6)", "2..6", "up"),
                                  (2, "(2, 1)", "(5, 6)", "2..6", "down")]
    assert [e["dx/dy"] for e in t.edges] == [-0.6, 0.6]
    # y = 2: crossings 2.6 and 7.4 -> keys 3 and 8 -> pixels 3..7; y = 6: both at 5
    assert [(r["y"], r["active"], r["spans"]) for r in t.rows] == [
        (2, "e2:3 e1:8", "3..7"), (3, "e2:4 e1:7", "4..6"), (4, "e2:4 e1:7", "4..6"),
        (5, "e2:5 e1:6", "5..5"), (6, "e2:5 e1:5", "")]
    assert t.pixels() == {(x, 2) for x in range(3, 8)} | {(x, y) for y in (3, 4)
                                                          for x in range(4, 7)} | {(5, 5)}


def test_scan_line_fill_star_winding_differs_by_rule():
    star = [(32, 60), (13, 4), (62, 40), (2, 40), (51, 4)]
    even = sl.trace.scan_line_fill(star, "even-odd")
    nonzero = sl.trace.scan_line_fill(star, "nonzero")
    row = next(r for r in nonzero.rows if r["y"] == 30)
    assert row["winding"].split() == ["1", "2", "1"] or row["winding"].split() == ["-1", "-2", "-1"]
    assert len(nonzero.pixels()) > len(even.pixels())
    center = (32, 30)
    assert center in nonzero.pixels() and center not in even.pixels()


@pytest.mark.parametrize("rule", ["even-odd", "nonzero"])
def test_scan_line_fill_table_equals_draw_polygon(rule):
    rng = np.random.default_rng(7 if rule == "even-odd" else 8)
    for trial in range(80):
        n = int(rng.integers(3, 9))
        pts = rng.uniform(-5, 45, (n, 2))
        if trial % 2:
            pts = np.round(pts)
        shapes = [pts] if trial % 3 else [pts, rng.uniform(0, 40, (4, 2))]
        t = sl.trace.scan_line_fill(shapes, rule)
        fb = sl.FrameBuffer(60, 60, mode="L")
        # draw shifted into the frame: the table is in device coordinates
        sl.draw.polygon(fb, [s + 10 for s in shapes], color=255, rule=rule)
        assert {(x - 10, y - 10) for x, y in lit(fb)} == t.pixels(), (shapes, rule)


def test_scan_line_fill_refuses_huge_boxes_and_bad_points():
    with pytest.raises(ArgumentValueError, match="bounding box"):
        sl.trace.scan_line_fill([(0, 0), (1e6, 0), (0, 1e6)])
    with pytest.raises(ArgumentValueError):
        sl.trace.scan_line_fill([(0, 0), (float("nan"), 0), (0, 1)])
    with pytest.raises(ArgumentValueError, match="rule"):
        sl.trace.scan_line_fill([(0, 0), (4, 0), (0, 4)], rule="odd")


def test_scan_line_fill_of_no_vertices_has_an_empty_edge_table():
    # every table of scan_line_fill carries .edges (the explorer reads it), the
    # empty polygon's too (it had none before issue 32 item 3 typed the table)
    t = sl.trace.scan_line_fill(np.zeros((0, 2)))
    assert len(t) == 0 and t.edges == [] and t.pixels() == set()


# -- Sutherland-Hodgman ---------------------------------------------------------------------
def test_sutherland_hodgman_by_hand():
    t = sl.trace.sutherland_hodgman([(-2, 2), (6, 2), (6, 12)], window=(0, 0, 10, 10))
    top = [r for r in t.rows if r["stage"] == 3]
    # y = 10: (6,12)->(-2,2) enters at x = 6 - 8 * 2/10 = 4.4; (6,2)->(6,12) leaves at (6, 10)
    assert [(r["case"], r["output"]) for r in top] == [
        ("out -> in: output I and P", "(4.4, 10) (-2, 2)"),
        ("in -> in: output P", "(6, 2)"),
        ("in -> out: output I", "(6, 10)")]
    left = [r for r in t.rows if r["stage"] == 4]
    # x = 0: (4.4,10)->(-2,2) leaves at y = 10 - 8 * 4.4/6.4 = 4.5; (-2,2)->(6,2) enters at (0, 2)
    assert [r["output"] for r in left] == ["(4.4, 10)", "(0, 4.5)", "(0, 2) (6, 2)", "(6, 10)"]
    assert t.result == [(4.4, 10.0), (0.0, 4.5), (0.0, 2.0), (6.0, 2.0), (6.0, 10.0)]


def _side(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= 0


def test_sutherland_hodgman_table_equals_sl_clip_polygon():
    from scanline.clip import window as w

    rng = np.random.default_rng(21)
    for trial in range(80):
        pts = rng.uniform(-10, 20, (int(rng.integers(3, 9)), 2))
        if trial % 2:
            x0, y0 = rng.uniform(-2, 6, 2)
            window = (x0, y0, x0 + rng.uniform(1, 10), y0 + rng.uniform(1, 10))
        else:
            window = [(0, 0), (10, 0), (12, 8), (4, 12)]
        t = sl.trace.sutherland_hodgman(pts, window=window)
        clipped = sl.clip.polygon(pts, window)
        if clipped:
            assert np.allclose(np.array(t.result), clipped[0]), (pts, window)
        else:
            assert t.result == []
        # each row's case is the side of S and P, computed here independently
        ring = w.polygon(window, convex=True)
        inputs = [w._ring(pts).tolist()] + t.stages
        for stage in range(1, len(t.stages) + 1):
            a, b = ring[stage - 1], ring[stage % len(ring)]
            rows = [r for r in t.rows if r["stage"] == stage]
            src = inputs[stage - 1]
            assert len(rows) == len(src)
            for i, r in enumerate(rows):
                want = {(False, True): "out -> in", (True, True): "in -> in",
                        (True, False): "in -> out", (False, False): "out -> out"}[
                    (_side(a, b, src[i - 1]), _side(a, b, src[i]))]
                assert r["case"].startswith(want)


def test_sutherland_hodgman_bad_input():
    with pytest.raises(ArgumentValueError, match="one contour"):
        sl.trace.sutherland_hodgman([[(0, 0), (4, 0), (0, 4)], [(1, 1), (2, 1), (1, 2)]])
    with pytest.raises(ArgumentValueError, match="convex"):
        sl.trace.sutherland_hodgman([(0, 0), (4, 0), (0, 4)],
                                    window=[(0, 0), (10, 0), (5, 2), (10, 10), (0, 10)])
