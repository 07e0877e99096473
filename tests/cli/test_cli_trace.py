"""``scanline trace``: the step tables of the notes' worked examples."""

import csv
import io
import json

import pytest

import scanline as sl

# Hand-verified from the notes, chapter 2, Q.3: k, p_k, (x_k+1, y_k+1).
BRESENHAM_20_10_30_18 = [
    (0, 6, 21, 11), (1, 2, 22, 12), (2, -2, 23, 12), (3, 14, 24, 13), (4, 10, 25, 14),
    (5, 6, 26, 15), (6, 2, 27, 16), (7, -2, 28, 16), (8, 14, 29, 17), (9, 10, 30, 18),
]
# Q.5: the midpoint circle r = 10: p_k, (x_k+1, y_k+1).
CIRCLE_10 = [(-9, 1, 10), (-6, 2, 10), (-1, 3, 10), (6, 4, 9), (-3, 5, 9), (8, 6, 8), (5, 7, 7)]

#: One call of each algorithm, with its API equivalent.
CASES = [
    (["bresenham", "20", "10", "30", "18"], lambda: sl.trace.bresenham(20, 10, 30, 18)),
    (["bresenham", "-5", "3", "10", "-2"], lambda: sl.trace.bresenham(-5, 3, 10, -2)),
    (["dda", "-5", "3", "10", "-2"], lambda: sl.trace.dda(-5, 3, 10, -2)),
    (["midpoint-circle", "10"], lambda: sl.trace.midpoint_circle(10)),
    (["midpoint-circle", "7", "--center", "-3", "4"],
     lambda: sl.trace.midpoint_circle(7, center=(-3, 4))),
    (["midpoint-ellipse", "8", "6"], lambda: sl.trace.midpoint_ellipse(8, 6)),
    (["midpoint-ellipse", "3", "9", "--center", "10", "-10"],
     lambda: sl.trace.midpoint_ellipse(3, 9, center=(10, -10))),
]


def test_bresenham_json_is_the_notes_table(cli):
    result = cli("trace", "bresenham", "20", "10", "30", "18", "--format", "json")
    assert result.code == 0 and result.err == ""
    rows = json.loads(result.out)
    assert len(rows) == 10
    assert {"k": 2, "p": -2, "x": 23, "y": 12}.items() <= rows[2].items()
    assert [(r["k"], r["p"], r["x"], r["y"]) for r in rows] == BRESENHAM_20_10_30_18


def test_bresenham_table_and_csv(call):
    table = call("trace", "bresenham", "20", "10", "30", "18").out
    assert table.startswith("Bresenham line (20, 10) -> (30, 18)\n")
    assert "p0 = 2dy - dx = 6" in table
    rows = list(csv.DictReader(io.StringIO(call("trace", "bresenham", "20", "10", "30", "18",
                                                "--format", "csv").out)))
    assert [(int(r["k"]), int(r["p"]), int(r["x"]), int(r["y"])) for r in rows] == \
        BRESENHAM_20_10_30_18


def test_midpoint_circle_json_is_the_notes_table(call):
    rows = json.loads(call("trace", "midpoint-circle", "10", "--format", "json").out)
    assert [(r["p"], r["x"], r["y"]) for r in rows] == CIRCLE_10
    assert [(r["2x"], r["2y"]) for r in rows] == [(2 * x, 2 * y) for _, x, y in CIRCLE_10]


def test_center_adds_the_plotted_pixels(cli):
    result = cli("trace", "midpoint-circle", "10", "--center", "-5", "3", "--format", "json")
    rows = json.loads(result.out)
    assert [(r["xc+x"], r["yc+y"]) for r in rows] == [(x - 5, y + 3) for _, x, y in CIRCLE_10]


def test_midpoint_ellipse_regions(call):
    rows = json.loads(call("trace", "midpoint-ellipse", "8", "6", "--center", "1", "2",
                           "--format", "json").out)
    assert [r["region"] for r in rows] == ["1"] * 7 + ["2"] * 3
    assert (rows[0]["p"], rows[0]["xc+x"], rows[0]["yc+y"]) == (-332, 2, 8)
    assert (rows[7]["k"], rows[7]["p"], rows[7]["x"], rows[7]["y"]) == (0, -23, 8, 2)


@pytest.mark.parametrize("args, table", CASES, ids=[" ".join(a) for a, _ in CASES])
def test_every_format_prints_the_api_table(call, args, table):
    expected = table()
    assert call("trace", *args).out == f"{expected}\n"
    assert call("trace", *args, "--format", "csv").out == expected.to_csv()
    assert json.loads(call("trace", *args, "--format", "json").out) == \
        json.loads(expected.to_json())
