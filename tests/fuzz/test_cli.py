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
