"""Documentation that runs as pasted (issue 16, item 5): every Python block of
README.md and docs/*.md runs on its own in a fresh interpreter, in an empty folder.

A block that needs the one before it says so on the line above its fence,
``<!-- continues the block above -->``; the test then runs the two (or more) together.
Shell blocks are checked in tests/cli/test_examples.py.
"""

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
CONTINUES = "<!-- continues the block above -->"
FENCE = re.compile(r"^```python\n(.*?)^```", re.S | re.M)


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


def test_there_are_blocks():
    assert len(CASES) >= 25


@pytest.mark.parametrize("page, source", CASES)
def test_block_runs_as_pasted(page, source, tmp_path):
    env = {**os.environ, "MPLBACKEND": "Agg"}
    proc = subprocess.run([sys.executable, "-"], input=source, cwd=tmp_path, env=env,
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert "Warning" not in proc.stderr, proc.stderr[-3000:]
