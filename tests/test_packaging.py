"""Packaging (issue 16, item 6): a LICENSE and an SPDX license expression, an sdist
with the tests, docs and examples whose tests pass from the unpacked archive, and a
lean wheel."""

import os
import subprocess
import sys
import tarfile
import zipfile
from pathlib import Path

import pytest
from tests.reference import peer

ROOT = Path(__file__).resolve().parent.parent

try:
    import tomllib
except ModuleNotFoundError:          # Python 3.10
    import tomli as tomllib


def test_license_is_an_spdx_expression_with_its_files():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert project["license"] == "MIT AND Bitstream-Vera"        # a string, not a table
    for name in project["license-files"]:
        assert (ROOT / name).is_file(), name
    assert (ROOT / "LICENSE").read_text().startswith("MIT License")


def test_the_distribution_name_and_one_version():
    """``scanline`` on the package index is an unrelated project: the distribution is
    ``scanline-graphics``, its version read from ``scanline.__version__`` alone, and the
    changelog's latest release is that version."""
    import re

    import scanline

    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert project["name"] == "scanline-graphics"
    assert "version" not in project and project["dynamic"] == ["version"]
    assert scanline.__version__ == "0.2.0"
    changelog = (ROOT / "CHANGELOG.md").read_text()
    releases = re.findall(r"^## \[(\d+\.\d+\.\d+)\] - ", changelog, re.M)
    assert releases[:2] == ["0.2.0", "0.1.0"]


def test_install_hints_name_the_distribution():
    """Every ``pip install`` hint in messages and documentation names
    ``scanline-graphics`` (``pip install 'scanline[video]'`` would fetch the wrong
    project)."""
    import re

    wrong = re.compile(r"""(install|\(|`)\s*['"]?scanline\[""")
    pages = list((ROOT / "docs").glob("*.md"))
    files = [ROOT / "README.md", *pages, *(ROOT / "src" / "scanline").rglob("*.py")]
    bad = [f"{f.relative_to(ROOT)}:{n}" for f in files
           for n, line in enumerate(f.read_text(encoding="utf-8").splitlines(), 1)
           if wrong.search(line)]
    assert not bad, bad


@pytest.fixture(scope="module")
def dist(tmp_path_factory):
    """The sdist and the wheel, built from this checkout as a user would."""
    if not (ROOT / "pyproject.toml").is_file() or not (ROOT / "MANIFEST.in").is_file():
        pytest.skip("not a source checkout")
    peer("build")
    import fcntl
    out = tmp_path_factory.mktemp("dist")
    # pytest-xdist's workers each build (a module fixture per worker); the builds share the
    # checkout's build/ and egg-info folders, so they take turns (a lock beside the
    # workers' temporary folders)
    with open(tmp_path_factory.getbasetemp().parent / "build.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        proc = subprocess.run([sys.executable, "-m", "build", "--sdist", "--wheel", "-o",
                               str(out), str(ROOT)], capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stderr[-3000:]
    return next(out.glob("*.tar.gz")), next(out.glob("*.whl"))


def _tracked(folder):
    """The files git tracks under ``folder`` (without git: every file there)."""
    proc = subprocess.run(["git", "-C", str(ROOT), "ls-files", folder], capture_output=True,
                          text=True)
    if proc.returncode == 0 and proc.stdout:
        return set(proc.stdout.split())
    return {str(p.relative_to(ROOT)) for p in (ROOT / folder).rglob("*") if p.is_file()}


def test_the_sdist_holds_tests_docs_and_examples(dist):
    sdist, _ = dist
    with tarfile.open(sdist) as tar:
        names = {n.split("/", 1)[1] for n in tar.getnames() if "/" in n}
    for folder in ("tests", "docs", "examples"):
        missing = {f for f in _tracked(folder) if "__pycache__" not in f} - names
        assert not missing, missing
    assert {"tests/reference.py", "conftest.py", "LICENSE", "README.md", "pyproject.toml",
            "src/scanline/data/fonts/DejaVuSans.ttf"} <= names
    assert not [n for n in names if n.endswith((".nbi", ".nbc", ".pyc"))]


def test_the_wheel_is_lean(dist):
    _, wheel = dist
    names = zipfile.ZipFile(wheel).namelist()
    tops = {n.split("/")[0] for n in names}
    assert tops == {"scanline", wheel.name.split("-py3")[0] + ".dist-info"}, tops
    assert not [n for n in names if n.endswith((".nbi", ".nbc", ".pyc"))]
    assert "scanline/data/scenes/rotation.toml" in names and "scanline/py.typed" in names
    meta = zipfile.ZipFile(wheel).read(next(n for n in names if n.endswith("METADATA"))).decode()
    assert "License-Expression: MIT AND Bitstream-Vera" in meta
    assert "\nName: scanline-graphics\n" in meta and "\nVersion: 0.2.0\n" in meta
    # what is in it is the package's sources (3.1 MB on 2026-12-05, grown with chapters
    # 10-14) and one 0.76 MB font: the bound catches a data file or a cache swept in
    assert sum(zipfile.ZipFile(wheel).getinfo(n).file_size for n in names) < 5_000_000


def test_tests_pass_from_the_unpacked_sdist(dist, tmp_path):
    """A sample of the suite (the notes' worked examples and a doctest module; small,
    since the unpacked sources compile their kernels afresh) run from the unpacked
    archive against its own sources.  The whole suite passes there too (issue 16's
    report: PYTHONPATH=src pytest in the unpacked sdist)."""
    sdist, _ = dist
    with tarfile.open(sdist) as tar:
        tar.extractall(tmp_path, filter="data") if hasattr(tarfile, "data_filter") \
            else tar.extractall(tmp_path)
    top = next(tmp_path.iterdir())
    env = {**os.environ, "PYTHONPATH": str(top / "src")}
    proc = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
         "tests/test_notes_examples.py", "src/scanline/trace/table.py"],
        cwd=top, env=env, capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-2000:]
    assert "[100%]" in proc.stdout and str(top / "src") in subprocess.run(
        [sys.executable, "-c", "import scanline; print(scanline.__file__)"], cwd=top, env=env,
        capture_output=True, text=True).stdout
