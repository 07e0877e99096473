"""Bundled example scenes from any folder (issue 16, item 5): ``scanline examples``,
``--example NAME``, ``sl.scene.example``, and every shell line of the docs that uses
them, run as pasted in an empty folder."""

import re
import shlex
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

import scanline as sl

ROOT = Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
SHELL = re.compile(r"^```(?:bash|sh|console|shell)\n(.*?)^```", re.S | re.M)


def example_lines():
    """Shell lines of the docs that name a bundled example, without their comments."""
    out = []
    for page in PAGES:
        for block in SHELL.findall(page.read_text()):
            for line in block.splitlines():
                line = line.removeprefix("$ ").split("  #")[0].strip()
                if "--example" in line or line.startswith("scanline examples"):
                    out.append(pytest.param(line, id=f"{page.name}: {line[:50]}"))
    return out


def test_the_docs_use_the_examples_option():
    lines = [p.values[0] for p in example_lines()]
    assert len(lines) >= 8
    for page in PAGES:
        for block in SHELL.findall(page.read_text()):
            assert "examples/scenes/" not in block, page   # a path that works in a checkout only


@pytest.mark.parametrize("line", example_lines())
def test_shell_line_runs_in_an_empty_folder(run, tmp_path, line):
    for command in line.split("&&"):
        words = shlex.split(command)
        if "[" in command:                       # a synopsis with optional parts: take them out
            words = shlex.split(re.sub(r"\[[^]]*\]", "", command))
        assert words[0] == "scanline"
        words = [str(p) for w in words[1:]
                 for p in (sorted(tmp_path.glob(w)) if "*" in w else [w])]
        result = run(*words, cwd=tmp_path)
        assert result.code == 0, result.err


def test_examples_lists_every_bundled_scene(call):
    out = call("examples").out.splitlines()
    names = sl.scene.examples()
    assert [line.split()[0] for line in out] == list(names) and "rotation" in names
    assert all(len(line.split(maxsplit=1)) == 2 for line in out)       # each has a summary


def test_render_an_example_equals_rendering_its_file(call, tmp_path):
    assert call("render", "--example", "rotation", "-o", tmp_path / "a.png").code == 0
    assert call("render", sl.scene.example("rotation"), "-o", tmp_path / "b.png").code == 0
    a, b = (np.array(Image.open(tmp_path / n)) for n in ("a.png", "b.png"))
    assert np.array_equal(a, b) and a.std() > 0


@pytest.mark.parametrize("args, message", [
    (["render", "--example", "nosuch", "-o", "{tmp}/x.png"], "example='nosuch' is not a bundled scene; the examples are axonometric"),
    (["render", "-o", "{tmp}/x.png"], "one of the arguments SCENE --example is required"),
    (["render", "a.toml", "--example", "rotation", "-o", "{tmp}/x.png"], "not allowed with"),
])
def test_bad_example_arguments(call, tmp_path, args, message):
    result = call(*[a.format(tmp=tmp_path) for a in args])
    assert result.code == 2 and message in result.err
    assert not (tmp_path / "x.png").exists()


def test_copy_refuses_to_overwrite(call, tmp_path):
    assert call("examples", "--copy", tmp_path / "s").code == 0
    copied = sorted(p.stem for p in (tmp_path / "s").iterdir())
    assert copied == list(sl.scene.examples())
    (tmp_path / "t").mkdir()
    (tmp_path / "t" / "rotation.toml").write_text("mine")
    result = call("examples", "--copy", tmp_path / "t")
    assert result.code == 2 and "already has rotation.toml" in result.err
    assert [p.name for p in (tmp_path / "t").iterdir()] == ["rotation.toml"]
    assert (tmp_path / "t" / "rotation.toml").read_text() == "mine"
    with pytest.raises(sl.ArgumentValueError, match="example"):
        sl.scene.example(3)
