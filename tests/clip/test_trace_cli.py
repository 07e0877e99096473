"""``scanline trace cohen-sutherland | liang-barsky | cyrus-beck``: the command line
prints the same tables as sl.trace, and bad windows give one-line errors."""

import json

import pytest

import scanline as sl
from scanline.cli import main


def run(capsys, *args):
    code = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("args, table", [
    (["cohen-sutherland", "-5", "2", "15", "22", "--window", "0", "0", "10", "10"],
     lambda: sl.trace.cohen_sutherland(-5, 2, 15, 22, window=(0, 0, 10, 10))),
    (["liang-barsky", "-5", "2", "15", "22"], lambda: sl.trace.liang_barsky(-5, 2, 15, 22)),
    (["cyrus-beck", "-5", "2", "15", "12", "--window-polygon", "0,0,10,0,5,8"],
     lambda: sl.trace.cyrus_beck(-5, 2, 15, 12, window=[(0, 0), (10, 0), (5, 8)])),
    (["cyrus-beck", "0.5", "-1.25", "3", "9", "--window", "-1", "-1", "2", "2"],
     lambda: sl.trace.cyrus_beck(0.5, -1.25, 3, 9, window=(-1, -1, 2, 2))),
])
def test_cli_prints_the_api_table(capsys, args, table):
    code, out, err = run(capsys, "trace", *args)
    assert code == 0 and err == ""
    assert out == str(table()) + "\n"
    code, out, err = run(capsys, "trace", *args, "--format", "json")
    assert json.loads(out) == json.loads(table().to_json())


def test_cli_region_codes_in_csv(capsys):
    code, out, _ = run(capsys, "trace", "cohen-sutherland", "-3", "12", "14", "15", "--format", "csv")
    assert code == 0
    assert out.splitlines()[1].startswith("0,1001,1010,1000,reject")


@pytest.mark.parametrize("args, fragment", [
    (["cohen-sutherland", "0", "0", "1", "1", "--window", "0", "0", "0", "5"], "degenerate"),
    (["cyrus-beck", "0", "0", "1", "1", "--window-polygon", "0,0,10,0,10,10,5,3,0,10"], "convex"),
    (["cyrus-beck", "0", "0", "1", "1", "--window-polygon", "0,0,10,0,10"], "even"),
])
def test_cli_bad_windows(capsys, args, fragment):
    code, out, err = run(capsys, "trace", *args)
    assert code == 2 and out == ""
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("scanline: error: ") and fragment in lines[0]
