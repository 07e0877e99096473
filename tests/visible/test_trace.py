"""The step tables of depth sorting and the floating horizon come from the drawing
code."""

import subprocess
import sys

import numpy as np

import scanline as sl
from scanline.draw3d.horizon import _grid


def test_depth_sort_table_painter_scene():
    table = sl.trace.depth_sort("painter")
    assert table.rows[0]["action"] == "move 1 to the head (flag it)"
    assert [table.rows[0][f"test {k}"] for k in range(1, 6)] == ["no"] * 5
    assert table.rows[1]["test 3"] == "yes"
    assert "drawing order (faces): 1 0" in table.notes


def test_depth_sort_table_cyclic_splits():
    table = sl.trace.depth_sort("cyclic")
    assert any("split" in r["action"] for r in table.rows)


def test_floating_horizon_table_matches_the_kernel():
    table = sl.trace.floating_horizon(nx=6, ny=4, width=24, height=16)
    xs, ys, zz = _grid(lambda x, y: np.sin(2 * x) * np.cos(2 * y), np.linspace(-1, 1, 6),
                       np.linspace(-1, 1, 4))
    h = sl.draw3d.horizon(zz, x=xs, y=ys, camera_or_angles=(0.5, 0.5), width=24, height=16)
    names = {1: "above", -1: "below", 0: "hidden"}
    order = h.curves.tolist()
    for row in table.rows:
        g = order.index(row["curve"])
        assert names[int(h.states[g, row["column"]])] == row["visible"]


def test_cli_tables():
    for args in (["depth-sort", "--scene", "intersecting"], ["floating-horizon", "--nx", "5"]):
        out = subprocess.run([sys.executable, "-m", "scanline", "trace", *args],
                             capture_output=True, text=True, check=True).stdout
        assert "test 1" in out or "upper before" in out
    bad = subprocess.run([sys.executable, "-m", "scanline", "trace", "depth-sort", "--no-split"],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and "split_cycles=True" in bad.stderr
