"""Fixtures that run the ``scanline`` command, in a subprocess or in-process."""

import subprocess
import sys
from collections import namedtuple

import pytest

from scanline.cli import main
from scanline.cli.progress import NOTICE

#: What a run of the command gives: exit status, stdout, stderr.
Result = namedtuple("Result", "code out err")


def _without_notice(err):
    """``err`` without the compile notice: it is printed when a first compilation
    lasts over two seconds, which depends on the machine and what else runs on it
    (``test_cli_warmup.py`` tests when it is said); every other line is kept."""
    return err.replace(NOTICE + "\n", "", 1)


def _subprocess(*args, cwd=None):
    proc = subprocess.run([sys.executable, "-m", "scanline", *map(str, args)],
                          capture_output=True, text=True, cwd=cwd, timeout=300)
    return Result(proc.returncode, proc.stdout, _without_notice(proc.stderr))


@pytest.fixture(scope="session")
def run():
    """Run ``python -m scanline ARGS...`` in a subprocess; return a :class:`Result`
    (session-scoped: it holds nothing, so module-scoped fixtures may use it too)."""
    return _subprocess


@pytest.fixture
def call(capsys):
    """Call ``scanline.cli.main(ARGS)`` in this process; return a :class:`Result`."""

    def call(*args):
        code = main([str(a) for a in args])
        out, err = capsys.readouterr()
        return Result(code, out, _without_notice(err))

    return call


@pytest.fixture(params=["subprocess", "in-process"])
def cli(request, run, call):
    """Both ways of running the command, for the tests that must hold for both."""
    return run if request.param == "subprocess" else call


def _assert_one_line_error(result, *fragments):
    assert result.code == 2, result
    assert result.out == ""
    lines = result.err.splitlines()
    assert len(lines) == 1, result.err
    assert lines[0].startswith("scanline: error: "), lines[0]
    assert "Traceback" not in result.err
    for fragment in fragments:
        assert fragment in lines[0], (fragment, lines[0])


@pytest.fixture
def one_line_error():
    """``one_line_error(result, *fragments)`` asserts exit status 2, nothing on stdout,
    one ``scanline: error:`` line on stderr containing each fragment, no traceback."""
    return _assert_one_line_error
