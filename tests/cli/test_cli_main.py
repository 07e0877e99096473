"""The ``scanline`` command as a whole: help, version, start-up cost, error reporting."""

import subprocess
import sys

import pytest

import scanline
from scanline.cli import trace


def test_import_and_parser_do_not_load_numba_or_numpy():
    code = ("import sys, scanline.cli; scanline.cli.build_parser(); "
            "print(sorted({'numba', 'numpy', 'PIL'} & set(sys.modules)))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_help_lists_the_commands(run):
    result = run("--help")
    assert result.code == 0 and result.err == ""
    for command in ("trace", "draw", "demo"):
        assert f"    {command} " in result.out
    assert "--debug" in result.out and "--version" in result.out


@pytest.mark.parametrize("command", [
    ["trace"], ["trace", "bresenham"], ["trace", "dda"], ["trace", "midpoint-circle"],
    ["trace", "midpoint-ellipse"], ["draw"], ["demo"],
])
def test_help_of_each_command(call, command):
    result = call(*command, "--help")
    assert result.code == 0 and result.err == ""
    assert result.out.startswith(f"usage: scanline {' '.join(command)} ")


def test_draw_help_documents_the_items_language(call):
    out = call("draw", "--help").out
    for usage in ("line X0 Y0 X1 Y1", "circle XC YC R", "ellipse XC YC RX RY", "point X Y",
                  "color NAME", "method dda|bresenham"):
        assert usage in out
    assert "scanline draw --size 64x48 line 2 3 60 40 circle 32 24 15 -o out.png" in out


def test_version(cli):
    result = cli("--version")
    assert result.code == 0
    assert result.out.strip() == f"scanline {scanline.__version__}"


def test_trace_algorithms_are_those_of_the_package():
    assert set(trace.ALGORITHMS) == set(scanline.trace.ALGORITHMS)


@pytest.mark.parametrize("args, fragments", [
    ([], ["required: COMMAND"]),
    (["paint"], ["invalid choice: 'paint'"]),
    (["trace"], ["ALGORITHM"]),
    (["trace", "spline", "1"], ["invalid choice: 'spline'"]),
    (["trace", "bresenham", "1", "2", "3"], ["Y1", "scanline trace bresenham --help"]),
    (["trace", "bresenham", "1", "2", "3", "four"], ["argument Y1", "'four' is not an integer"]),
    (["trace", "dda", "1", "2", "3", "4.5"], ["argument Y1", "'4.5'"]),
    (["trace", "dda", "1", "2", "3", "4", "--format", "xml"], ["--format", "'xml'"]),
    (["trace", "midpoint-circle", "5", "--center", "1"], ["--center"]),
    (["draw", "line", "1", "2", "3", "4"], ["-o/--output"]),
    (["draw", "--size", "64", "point", "1", "1", "-o", "x.png"], ["--size", "64x48"]),
    (["draw", "--scale", "0", "point", "1", "1", "-o", "x.png"], ["--scale", "'0'"]),
    (["draw", "--mode", "CMYK", "point", "1", "1", "-o", "x.png"], ["--mode", "'CMYK'"]),
    (["demo", "--bogus"], ["unrecognized arguments: --bogus"]),
])
def test_usage_errors_print_one_line_and_exit_2(call, one_line_error, args, fragments):
    one_line_error(call(*args), *fragments)


@pytest.mark.parametrize("args, fragments", [
    (["trace", "bresenham", "0", "0", "1000000", "0"], ["1000000 steps"]),
    (["trace", "midpoint-circle", "-3"], ["r must be >= 0"]),
    (["trace", "midpoint-ellipse", "8", "-6"], ["ry must be >= 0"]),
    (["trace", "dda", str(10**40), "0", "0", "0"], ["x0=", "outside"]),
])
def test_errors_of_the_algorithms_name_the_argument(cli, one_line_error, args, fragments):
    one_line_error(cli(*args), *fragments)


def test_debug_adds_the_traceback(call, tmp_path):
    args = ["draw", "circle", "1", "2", "-3", "-o", tmp_path / "x.png"]
    result = call("--debug", *args)
    assert result.code == 2
    assert result.err.startswith("Traceback")
    assert result.err.splitlines()[-1].startswith("scanline: error: ITEMS word 1")
    assert "Traceback" not in call(*args).err
