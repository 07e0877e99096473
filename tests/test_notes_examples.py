"""The notes' worked examples (chapter 2, Q.3, Q.5, Q.6), value by value.

Expected values were computed by hand from the notes' formulas (docs/errata.md shows
the arithmetic).  Where the notes print a wrong number, the test pins the correct one
and names the erratum.
"""

from fractions import Fraction

import pytest

import scanline as sl


def _fb_pixels(fb):
    """Set of lit (x, y) device pixels of a mode-"1" frame buffer."""
    a = fb.to_array()
    h = a.shape[0]
    return {(int(c), h - 1 - int(r)) for r, c in zip(*a.nonzero())}


# -- Q.3: Bresenham, (20, 10) -> (30, 18) -------------------------------------------

NOTES_BRESENHAM = [  # k, p_k, (x_k+1, y_k+1) -- all correct in the notes
    (0, 6, 21, 11), (1, 2, 22, 12), (2, -2, 23, 12), (3, 14, 24, 13), (4, 10, 25, 14),
    (5, 6, 26, 15), (6, 2, 27, 16), (7, -2, 28, 16), (8, 14, 29, 17), (9, 10, 30, 18),
]


def test_bresenham_table_matches_the_notes():
    t = sl.trace.bresenham(20, 10, 30, 18)
    assert [(r["k"], r["p"], r["x"], r["y"]) for r in t.rows] == NOTES_BRESENHAM
    # increments: 2dy - 2dx = -4 after p >= 0, 2dy = 16 after p < 0
    assert [r["increment"] for r in t.rows] == [16 if p < 0 else -4 for _, p, _, _ in NOTES_BRESENHAM]


def test_bresenham_example_draws_the_tabulated_pixels():
    fb = sl.FrameBuffer(40, 30, mode="1")
    sl.draw.line(fb, 20, 10, 30, 18)
    assert _fb_pixels(fb) == {(20, 10)} | {(x, y) for _, _, x, y in NOTES_BRESENHAM}


def test_bresenham_example_reversed_gives_the_same_pixels():
    fb = sl.FrameBuffer(40, 30, mode="1")
    sl.draw.line(fb, 30, 18, 20, 10)
    assert _fb_pixels(fb) == {(20, 10)} | {(x, y) for _, _, x, y in NOTES_BRESENHAM}


# -- Q.5: midpoint circle, r = 10 -----------------------------------------------------

NOTES_CIRCLE = [  # k, p_k, (x_k+1, y_k+1), 2x_k+1, 2y_k+1 -- all correct in the notes
    (0, -9, 1, 10, 2, 20), (1, -6, 2, 10, 4, 20), (2, -1, 3, 10, 6, 20),
    (3, 6, 4, 9, 8, 18), (4, -3, 5, 9, 10, 18), (5, 8, 6, 8, 12, 16), (6, 5, 7, 7, 14, 14),
]


def test_midpoint_circle_table_matches_the_notes():
    t = sl.trace.midpoint_circle(10)
    got = [(r["k"], r["p"], r["x"], r["y"], r["2x"], r["2y"]) for r in t.rows]
    assert got == NOTES_CIRCLE


def test_midpoint_circle_example_draws_eight_octants():
    fb = sl.FrameBuffer(41, 41, mode="1")
    sl.draw.circle(fb, 20, 20, 10)
    octant = [(0, 10)] + [(x, y) for _, _, x, y, _, _ in NOTES_CIRCLE]
    expected = set()
    for x, y in octant:
        for a, b in ((x, y), (y, x)):
            expected |= {(20 + sx * a, 20 + sy * b) for sx in (1, -1) for sy in (1, -1)}
    assert _fb_pixels(fb) == expected
    assert len(expected) == 4 * 2 * 8 - 8  # 8 octant points, axis and diagonal shared


def test_circle_equation_erratum_E4():
    # E4: y = yc +- sqrt(r^2 - (xc - x)^2); the notes' radicand (xc - x)^2 - r^2 is
    # negative on the circle.  Every octant point of r = 10 lies within half a pixel.
    for _, _, x, y, _, _ in NOTES_CIRCLE:
        assert abs(y - (100 - x * x) ** 0.5) < 0.5
        assert (x * x) - 100 < 0  # the notes' radicand


# -- Q.6: midpoint ellipse, rx = 8, ry = 6 ----------------------------------------------

# region, k, p, (x_k+1, y_k+1), 2ry^2 x_k+1, 2rx^2 y_k+1
NOTES_ELLIPSE_REGION1 = [
    ("1", 0, -332, 1, 6, 72, 768), ("1", 1, -224, 2, 6, 144, 768), ("1", 2, -44, 3, 6, 216, 768),
    ("1", 3, 208, 4, 5, 288, 640), ("1", 4, -108, 5, 5, 360, 640), ("1", 5, 288, 6, 4, 432, 512),
    ("1", 6, 244, 7, 3, 504, 384),
]
# Errata E10 and E11: the notes print p = -215 and -279 and "-" for the last terms.
CORRECT_ELLIPSE_REGION2 = [
    ("2", 0, -23, 8, 2, 576, 256), ("2", 1, 361, 8, 1, 576, 128), ("2", 2, 297, 8, 0, 576, 0),
]


def test_midpoint_ellipse_table_with_errata_corrected():
    t = sl.trace.midpoint_ellipse(8, 6)
    got = [(r["region"], r["k"], r["p"], r["x"], r["y"], r["2ry2x"], r["2rx2y"]) for r in t.rows]
    assert got == NOTES_ELLIPSE_REGION1 + CORRECT_ELLIPSE_REGION2


def test_ellipse_region2_values_by_the_definition():
    # Independent of the incremental updates: p2_k = f(x_k + 1/2, y_k - 1) at each
    # region-2 point (x_k, y_k), with f(x, y) = ry^2 x^2 + rx^2 y^2 - rx^2 ry^2.
    def f(x, y):
        return 36 * x * x + 64 * y * y - 64 * 36

    half = Fraction(1, 2)
    assert f(7 + half, 3 - 1) == -23
    assert f(8 + half, 2 - 1) == 361      # E10: the notes print -215
    assert f(8 + half, 1 - 1) == 297      # E10: the notes print -279
    # E8: the notes' P1_7 = 1168; the correct value is f(7 + 1, 3 - 1/2) = 400
    assert f(8, 3 - half) == 400


def test_region2_positive_p2_keeps_x_erratum_e17():
    # E17: the notes' derivation says P2_k > 0 selects x_k+1; their step (5) and the
    # geometry say x_k.  The midpoint f(x_k + 1/2, y_k - 1) is evaluated here exactly,
    # not taken from the tracer's increments.
    seen = {True: 0, False: 0}
    for rx, ry in [(8, 6), (6, 8), (10, 3), (3, 10), (12, 12), (20, 7), (5, 1), (1, 9)]:
        def f(x, y):
            return ry * ry * x * x + rx * rx * y * y - rx * rx * ry * ry

        rows = sl.trace.midpoint_ellipse(rx, ry).rows
        for prev, row in zip(rows, rows[1:]):
            if row["region"] != "2":
                continue
            outside = f(Fraction(2 * prev["x"] + 1, 2), prev["y"] - 1) > 0
            assert (row["p"] > 0) == outside, (rx, ry, row)
            assert (row["x"], row["y"]) == (prev["x"] + (0 if outside else 1), prev["y"] - 1)
            seen[outside] += 1
    assert seen[True] > 5 and seen[False] > 5        # both cases exercised


def test_midpoint_ellipse_example_draws_four_quadrants():
    fb = sl.FrameBuffer(21, 15, mode="1")
    sl.draw.ellipse(fb, 10, 7, 8, 6)
    quadrant = [(0, 6)] + [(x, y) for _, _, _, x, y, _, _ in NOTES_ELLIPSE_REGION1 + CORRECT_ELLIPSE_REGION2]
    expected = {(10 + sx * x, 7 + sy * y) for x, y in quadrant for sx in (1, -1) for sy in (1, -1)}
    assert _fb_pixels(fb) == expected


@pytest.mark.parametrize("fmt", ["json", "csv", "table"])
def test_tables_export(fmt):
    import csv
    import io
    import json

    t = sl.trace.bresenham(20, 10, 30, 18)
    if fmt == "json":
        rows = json.loads(t.to_json())
        assert rows[2] == {"k": 2, "p": -2, "x": 23, "y": 12, "increment": 16}
    elif fmt == "csv":
        rows = list(csv.DictReader(io.StringIO(t.to_csv())))
        assert rows[3] == {"k": "3", "p": "14", "x": "24", "y": "13", "increment": "-4"}
    else:
        text = str(t)
        assert "p0 = 2dy - dx = 6" in text
        assert text.splitlines()[-1].split() == ["9", "10", "30", "18", "-4"]
