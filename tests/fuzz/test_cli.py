"""The command line on hostile arguments: every command either succeeds (a line that
happens to be valid) or exits with status 2, one line on stderr
(``scanline: error: ...``) and no file left behind -- never a traceback, another
status, or a partial output file.  ``studio`` (a server), ``demo`` and ``warmup``
(minutes of work on valid input) only get arguments that cannot be valid."""

import contextlib
import io
import os

import pytest
from hypothesis import given
from hypothesis import strategies as st

from scanline.cli import main
from tests.fuzz.harness import bounded

pytestmark = pytest.mark.boundscheck

HOSTILE = ["nan", "inf", "-inf", "-1e300", "1e400", "99999999999999999999999", "0", "-1",
           "3", "", "\x00", "-", "--", "--size", "0x0", "1x1", "40000x40000", "1073741824x1",
           "abc", "/dev/zero", "/proc/x.png", "..", "out.png", "out.gif", "out.jpg", "-o",
           "--scale", "100000", "--mode", "Q", "--background", "nope", "line", "circle",
           "polygon", "text", "fill-circle", "1,2", "1e-300", "é", "--help-me", "--format",
           "json", "bresenham", "midpoint-circle", "dda", "-5", "2.5", "\n", " "]

COMMANDS = ["trace", "draw", "render", "dither", "fonts", "simulate", "explain", "animate"]
HEAVY = ["studio", "demo", "warmup"]


def run(argv):
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        status = main(argv)
    return status, err.getvalue()


@given(command=st.sampled_from(COMMANDS), args=st.lists(st.sampled_from(HOSTILE), max_size=8),
       output=st.booleans())
def test_hostile_command_lines(tmp_path_factory, command, args, output):
    where = tmp_path_factory.mktemp("cli")
    old = os.getcwd()
    os.chdir(where)
    try:
        argv = [command] + args + (["-o", str(where / "out.png")] if output else [])
        with bounded():
            status, err = run(argv)
        assert status in (0, 2), (argv, status, err)
        if status == 2:
            lines = err.strip().splitlines()
            assert len(lines) == 1 and lines[0].startswith("scanline: error: "), (argv, err)
            assert os.listdir(where) == [], (argv, os.listdir(where))
    finally:
        os.chdir(old)


@pytest.mark.parametrize("command", HEAVY)
@pytest.mark.parametrize("args", [["--nope"], ["--jobs", "-3"], ["--port", "99999999"],
                                  ["\x00"], ["--jobs", "nan"]])
def test_heavy_commands_refuse_bad_arguments_in_one_line(tmp_path, command, args):
    status, err = run([command, *args])
    assert status == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("scanline: error: "), err


#: Arguments of ``animate`` and ``storyboard``: their options with hostile values
#: (jobs far beyond the cores, malformed scheduler addresses, huge panels, frame rates
#: out of range, frame selections, output folders), next to valid ones.
ANIMATION = ["--example", "bouncing_ball", "--jobs", "1000000000", "0", "-1", "nan", "1",
             "--scheduler", "tcp://", "nope", "tls://h:1", "tcp://h:0", "tcp://:", "\x00",
             "--panel", "16384x16384", "40000x40000", "0x0", "16x16", "64x48", "99999999999x1",
             "--columns", "100000", "2", "--fps", "1e-300", "1e300", "inf", "6", "0.5",
             "--frames", "0:2", "5:1", ":", "2:", "1:1000000000", "--quality", "99", "10",
             "--format", "json", "toml", "out.gif", "out.png", "out.webp", "out.mp4", "out.txt",
             "frames/", "../escape/", "-o", "--progress", "--no-progress", "nonexistent.toml",
             "", "-", "1e400"]


@given(command=st.sampled_from(["animate", "storyboard"]),
       args=st.lists(st.sampled_from(ANIMATION), max_size=8),
       scene=st.sampled_from([["--example", "bouncing_ball"], [], ["nonexistent.toml"]]),
       output=st.sampled_from([None, "out.gif", "out.png", "frames/", "board.png", "out.mp4"]))
def test_hostile_animate_and_storyboard(tmp_path_factory, command, args, scene, output):
    """``animate`` and ``storyboard`` on hostile command lines (a small memory budget,
    so that what the budget lets through stays within the harness's): status 0, or 2
    with one error line and nothing left in the folder -- no frames of an output
    folder, no partial file, nothing written outside it."""
    root = tmp_path_factory.mktemp("animation-cli")
    where = root / "work"
    where.mkdir()
    old, budget = os.getcwd(), os.environ.get("SCANLINE_MEMORY_LIMIT")
    os.chdir(where)
    os.environ["SCANLINE_MEMORY_LIMIT"] = "256M"
    try:
        argv = [command] + scene + args + (["-o", output] if output else [])
        with bounded():
            status, err = run(argv)
        assert status in (0, 2), (argv, status, err)
        assert os.listdir(root) == ["work"], (argv, os.listdir(root))
        if status == 2:
            lines = err.strip().splitlines()
            assert len(lines) == 1 and lines[0].startswith("scanline: error: "), (argv, err)
            assert os.listdir(where) == [], (argv, os.listdir(where))
    finally:
        os.chdir(old)
        if budget is None:
            os.environ.pop("SCANLINE_MEMORY_LIMIT", None)
        else:
            os.environ["SCANLINE_MEMORY_LIMIT"] = budget
