"""``scanline warmup`` and the notice that kernels are being compiled."""

import io
import os
import re
import subprocess
import sys

import pytest

from scanline import warmup
from scanline.cli.progress import NOTICE, announce_compilation


def test_warmup_makes_every_call_in_two_processes(run):
    result = run("warmup", "--jobs", "2", "--modes", "1,RGB")
    assert result.code == 0, result.err
    total = sum(1 for _ in warmup.cases(None, ("1", "RGB")))
    lines = result.err.splitlines()
    done = [re.fullmatch(r"scanline warmup: (\d+)/(\d+) (.+) \((\d+\.\d) s\)", line)
            for line in lines if line.startswith("scanline warmup: ")]
    assert all(done) and [int(m[1]) for m in done] == list(range(1, total + 1))
    # every call reported, whichever process made it
    assert sorted(m[3] for m in done) == sorted(name for name, _, _ in
                                                 warmup.cases(None, ("1", "RGB")))
    assert re.fullmatch(rf"scanline warmup: {total} calls compiled or loaded in \d+\.\d s "
                        r"with 2 processes\n", result.out)


def test_groups_cover_every_call_once_largest_first():
    groups = warmup.by_group()
    names = [name for group in groups for name in group]
    assert sorted(names) == sorted(warmup.CALLS)
    # a group is the calls of one group of kernels
    assert all(len({warmup.CALLS[name][0] for name in group}) == 1 for group in groups)
    sizes = [sum(1 for _ in warmup.cases(group)) for group in groups]
    assert sizes == sorted(sizes, reverse=True)


@pytest.mark.parametrize("args, fragment", [
    (["--jobs", "0"], "--jobs must be a whole number"),
    (["--jobs", "many"], "--jobs must be a whole number"),
    (["--jobs", "2.0"], "--jobs must be a whole number"),
    (["--modes", "RGB,CMYK"], "--modes must name frame-buffer modes"),
    (["--modes", ","], "--modes must name frame-buffer modes"),
])
def test_bad_arguments_exit_2_with_one_line(call, one_line_error, args, fragment):
    one_line_error(call("warmup", *args), fragment)


def test_notice_when_a_compilation_lasts():
    from numba import njit

    def fresh():
        # a new function each time: compiled now, whatever the cache holds
        def squares(a):
            total = 0.0
            for i in range(a.shape[0]):
                total += a[i] * a[i]
            return total
        return njit(squares)

    import numpy as np

    slow, quick, after = io.StringIO(), io.StringIO(), io.StringIO()
    with announce_compilation(slow, after=0.0):
        fresh()(np.arange(5.0))
        fresh()(np.arange(6.0))
    assert slow.getvalue() == NOTICE + "\n"          # said once, however many compile
    with announce_compilation(quick, after=60.0):
        fresh()(np.arange(7.0))
    assert quick.getvalue() == ""
    with announce_compilation(after, after=0.0):
        pass
    fresh()(np.arange(8.0))                           # outside the context: silent
    assert after.getvalue() == ""


def test_a_cold_command_says_it_is_compiling_and_a_warm_one_does_not(tmp_path):
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"))
    argv = [sys.executable, "-m", "scanline", "draw", "--size", "64x48", "width", "5",
            "join", "round", "polyline", "3", "4", "30", "40", "60", "5",
            "-o", str(tmp_path / "out.png")]
    cold = subprocess.run(argv, capture_output=True, text=True, env=env, timeout=600)
    assert cold.returncode == 0 and cold.stderr == NOTICE + "\n"
    warm = subprocess.run(argv, capture_output=True, text=True, env=env, timeout=600)
    assert warm.returncode == 0 and warm.stderr == ""
