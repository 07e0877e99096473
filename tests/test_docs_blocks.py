"""Documentation that runs as pasted (issue 16, item 5): every Python block of
README.md and docs/*.md runs on its own in a fresh interpreter, in an empty folder.

A block that needs the one before it says so on the line above its fence,
``<!-- continues the block above -->``; the test then runs the two (or more) together.
Shell blocks are checked in tests/cli/test_examples.py.

The interpreters are forks of one that has imported numpy, numba, matplotlib and
Pillow and has compiled a function (what most blocks do first: numba's first compilation
or cache load loads its registries, scipy's among them; about 2 s of a 2-core machine's
time per start): each
block runs in a child of it, in a ``__main__`` of its own and the block's empty folder,
with its output in files, and ends as a script ends (``sys.exit``, the interpreter's
shutdown).  What those imports print goes to a file that every test reads too.
"""

import json
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
CONTINUES = "<!-- continues the block above -->"
FENCE = re.compile(r"^```python\n(.*?)^```", re.S | re.M)
#: Seconds a block may run.
TIME_LIMIT = 600

#: The forking interpreter: it reads a job (JSON) per line and answers the child's exit
#: status (a negative number: the signal that ended it, SIGALRM past its time limit).
FORK_SERVER = r"""
import json, os, signal, sys, traceback, types
import numpy, numba, matplotlib.pyplot, PIL.Image
numba.njit(lambda: 0)()     # numba's registries, loaded at its first compilation or cache load
for line in sys.stdin:
    job = json.loads(line)
    pid = os.fork()
    if pid:
        print(os.waitstatus_to_exitcode(os.waitpid(pid, 0)[1]), flush=True)
        continue
    signal.alarm(job["seconds"])
    os.chdir(job["cwd"])
    for fd, name, flags in ((0, os.devnull, os.O_RDONLY), (1, job["out"], os.O_WRONLY | os.O_CREAT),
                            (2, job["err"], os.O_WRONLY | os.O_CREAT)):
        os.dup2(os.open(name, flags), fd)
    sys.stdin = open(0, closefd=False)
    main = types.ModuleType("__main__")
    sys.modules["__main__"], sys.argv = main, ["-"]
    try:
        exec(compile(job["source"], "<stdin>", "exec"), main.__dict__)
    except SystemExit:
        raise
    except BaseException:
        traceback.print_exc()
        sys.exit(1)
    sys.exit(0)
"""


def python_blocks(page):
    """[(line, source)] of the page's Python blocks, continuations joined to what they
    continue."""
    text = page.read_text()
    blocks = []
    for match in FENCE.finditer(text):
        line = text.count("\n", 0, match.start()) + 1
        before = text[:match.start()].rstrip("\n").rsplit("\n", 1)[-1]
        if before.strip() == CONTINUES:
            assert blocks, f"{page.name}:{line} continues nothing"
            blocks[-1] = (blocks[-1][0], blocks[-1][1] + match[1], line)
        else:
            blocks.append((line, match[1], line))
    return [(first, source) for first, source, _ in blocks]


CASES = [pytest.param(page, source, id=f"{page.name}:{line}")
         for page in PAGES for line, source in python_blocks(page)]


@pytest.fixture(scope="module")
def interpreter(tmp_path_factory):
    """(the forking interpreter, the file of what its imports printed)."""
    printed = tmp_path_factory.mktemp("fork-server") / "stderr"
    with open(printed, "w") as err:
        server = subprocess.Popen([sys.executable, "-c", FORK_SERVER], text=True,
                                  stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=err,
                                  env={**os.environ, "MPLBACKEND": "Agg"})
    yield server, printed
    server.stdin.close()
    server.wait(timeout=60)


def run_block(interpreter, source, folder, seconds=TIME_LIMIT):
    """(exit status, stderr) of ``source`` run as a script in the empty ``folder/run``
    (the output files lie beside it)."""
    server, printed = interpreter
    (folder / "run").mkdir()
    job = {"source": source, "cwd": str(folder / "run"), "out": str(folder / "stdout"),
           "err": str(folder / "stderr"), "seconds": seconds}
    server.stdin.write(json.dumps(job) + "\n")
    server.stdin.flush()
    status = server.stdout.readline()
    assert status, "the forking interpreter has gone"
    assert int(status) != -signal.SIGALRM, f"the block ran past {seconds} s"
    return int(status), printed.read_text() + (folder / "stderr").read_text()


def test_there_are_blocks():
    assert len(CASES) >= 25


@pytest.mark.parametrize("page, source", CASES)
def test_block_runs_as_pasted(interpreter, page, source, tmp_path):
    status, stderr = run_block(interpreter, source, tmp_path)
    assert status == 0, stderr[-3000:]
    assert "Warning" not in stderr, stderr[-3000:]


@pytest.mark.parametrize("source, status, says", [
    ("print('out')\n", 0, ""),
    ("x = 1\n", 0, ""),
    ("import sys\nsys.exit(3)\n", 3, ""),
    ("1 / 0\n", 1, "ZeroDivisionError"),
    ("import warnings\nwarnings.warn('careful')\n", 0, "UserWarning: careful"),
    ("import os\nopen('made', 'w').close()\nassert os.listdir() == ['made']\n", 0, ""),
    ("print(x)\n", 1, "NameError: name 'x'"),
])
def test_a_block_runs_as_a_script_would(interpreter, tmp_path, source, status, says):
    """The forked interpreter answers as ``python -`` would: the exit status, the
    traceback and warnings on stderr, the empty folder as the working directory, and a
    namespace of its own (``x`` of the block before is undefined)."""
    assert run_block(interpreter, source, tmp_path)[0] == status
    assert says in (tmp_path / "stderr").read_text()


def test_a_block_past_its_time_limit_fails(interpreter, tmp_path):
    with pytest.raises(AssertionError, match="ran past 1 s"):
        run_block(interpreter, "import time\ntime.sleep(30)\n", tmp_path, seconds=1)
