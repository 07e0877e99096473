"""Ctrl-C during a long kernel call is answered at once, and an interrupt after a
command has written its file prints nothing (issue 11, item 5)."""

import signal
import subprocess
import time

from tests import terminal

LONG = r"""
import sys, time, numpy as np, scanline as sl
fb = sl.FrameBuffer(4000, 4000, mode="L")
rng = np.random.default_rng(0)
n = 1_000_000            # about 4e9 pixel steps: several seconds of one kernel call
segs = np.c_[rng.integers(0, 10, n), rng.integers(0, 4000, n), rng.integers(3990, 4000, n),
             rng.integers(0, 4000, n)].astype(float)
sl.draw.lines(fb, segs[:10])
t = time.time()
sl.draw.lines(fb, segs[:n // 8])          # an eighth of the call, timed on this machine now
print("ready", round(time.time() - t, 3), flush=True)
t = time.time()
try:
    sl.draw.lines(fb, segs)
    print("finished", round(time.time() - t, 2), flush=True)
except KeyboardInterrupt:
    print("interrupted", round(time.time() - t, 2), flush=True)
"""


def _start(code):
    return terminal.python("-c", code, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           text=True)


def test_ctrl_c_interrupts_a_long_kernel_call():
    p = _start(LONG)
    word, eighth = p.stdout.readline().split()
    assert word == "ready"
    time.sleep(0.5)
    p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=300)
    # the whole call takes about 8 eighths; the interrupt came 0.5 s into it.  Were the
    # kernel not interruptible, the KeyboardInterrupt would come when it returns, at
    # about 8 eighths: answered within half the call, it was answered during it (a
    # measure relative to this machine's speed at this moment, so that a loaded
    # machine does not fail the test)
    assert out.split()[0] == "interrupted", (out, err[-2000:])
    assert float(out.split()[1]) < 0.5 + 4 * float(eighth)


QUIET = r"""
import os, signal, sys, time
sys.argv = ["scanline", "draw", "-o", sys.argv[1], "--size", "8x8", "line", "0", "0", "7", "7"]
from scanline.cli import main
status = main()
os.kill(os.getpid(), signal.SIGINT)     # Ctrl-C after the file is written
time.sleep(0.2)
sys.exit(status)
"""


def test_an_interrupt_after_the_file_is_written_prints_nothing(tmp_path):
    out = tmp_path / "x.png"
    p = _start(QUIET.replace("sys.argv[1]", repr(str(out))))
    _, err = p.communicate(timeout=120)
    assert out.exists()
    assert p.returncode == 0, err
    assert "KeyboardInterrupt" not in err and "Exception ignored" not in err
