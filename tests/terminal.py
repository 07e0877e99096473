"""Start a Python command as a terminal would, for the tests that press Ctrl-C.

A command started from a terminal has SIGINT at its default action.  A test suite run
from a background job does not: a shell without job control starts asynchronous
commands with SIGINT ignored, the ignored disposition is inherited by every process
they start, and a command that inherits it never sees Ctrl-C (the Ctrl-C tests then
timed out or exited 0 instead of 130 -- but only when the suite itself was started in
the background, as in a load test beside a CPU hog).  :func:`python` restores the
default before the command runs, by exec'ing it from a small Python wrapper (not
``preexec_fn``, which is unsafe in a process with threads, as pytest-xdist's workers
are).
"""

import subprocess
import sys

_RESET = ("import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); "
          "os.execv(sys.executable, [sys.executable, *sys.argv[1:]])")


def python(*args: str, **popen) -> subprocess.Popen:
    """``subprocess.Popen([python, *args], **popen)`` with SIGINT at its default."""
    return subprocess.Popen([sys.executable, "-c", _RESET, *args], **popen)
