"""``scanline trace flood-fill``: the seed fill's stack on a text grid."""

import json

import scanline as sl


def test_flood_fill_trace_json(cli):
    result = cli("trace", "flood-fill", "1", "1", "--grid", "#####/#..##/#...#/#####",
                 "--format", "json")
    assert result.code == 0 and result.err == ""
    rows = json.loads(result.out)
    assert [(r["k"], r["x"], r["y"], r["span"], r["stack"]) for r in rows] == [
        (0, 1, 1, "1..3", "(2, 2)"), (1, 2, 2, "1..2", "")]


def test_flood_fill_trace_default_grid_and_connectivity(call):
    out4 = call("trace", "flood-fill", "1", "2").out
    out8 = call("trace", "flood-fill", "1", "2", "--connectivity", "8").out
    assert out4 == f"{sl.trace.flood_fill(1, 2)}\n"
    assert out8 == f"{sl.trace.flood_fill(1, 2, connectivity=8)}\n"
    assert "8-connected" in out8 and out4 != out8


def test_flood_fill_trace_bad_input(call, one_line_error):
    one_line_error(call("trace", "flood-fill", "50", "1"), "x=50")
    one_line_error(call("trace", "flood-fill", "1", "1", "--connectivity", "6"), "connectivity")
    one_line_error(call("trace", "flood-fill", "0", "0", "--grid", "../..."), "grid")
