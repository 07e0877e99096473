"""Hardening the second half: scene files that reach hostile mesh files through
their ``file =`` key, and scenes whose totals pass the memory budget.

Before the fix a scene naming a FIFO blocked ``scanline render`` forever, one naming a
link to /dev/zero read towards gigabytes, a PLY without ``end_header`` never returned;
200 spheres at resolution 1024 (each within the per-mesh limit) and a 13000 x 13000
canvas with 3-D surfaces (a 400-byte file) were built and drawn, allocating
gigabytes.  Now each is one error naming the key path: ``scanline render`` prints one
line on stderr, exits 2 and leaves no output file.
"""

import contextlib
import io
import os
import signal

import pytest

from scanline.cli import main
from scanline.scene import SceneError, load
from tests.fuzz import hostile_files as hf


class Hang(BaseException):
    """A call past its deadline: a BaseException, so that no ``except Exception``
    in the code under test can turn the hang into an ordinary error."""


@contextlib.contextmanager
def deadline(seconds=60):
    def alarm(signum, frame):
        raise Hang(f"the call took more than {seconds} s: it hangs")

    old = signal.signal(signal.SIGALRM, alarm)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


def run(argv):
    err = io.StringIO()
    with deadline(), contextlib.redirect_stderr(err), \
            contextlib.redirect_stdout(io.StringIO()):
        status = main(argv)
    return status, err.getvalue()


def render(scene, out):
    return run(["render", str(scene), "-o", str(out)])


def one_error_line(status, err, out):
    assert status == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("scanline: error: "), err
    assert "Traceback" not in err
    assert not os.path.exists(out)
    return lines[0]


@pytest.mark.parametrize("name", sorted(hf.MESH_FILES))
def test_a_scene_naming_a_hostile_mesh_file_is_one_error(tmp_path, name):
    hf.MESH_FILES[name](str(tmp_path / name))
    scene = hf.scene_with_a_mesh_file(str(tmp_path / "scene.toml"), name)
    with deadline(), pytest.raises(SceneError) as info:
        load(scene)
    message = str(info.value)
    assert "segments[0].primitives[0].file" in message and name in message
    assert info.value.line == 10          # the line of the primitive
    out = tmp_path / "out.png"
    line = one_error_line(*render(scene, out), out)
    assert "segments[0].primitives[0].file" in line
    line = one_error_line(*run(["check", str(scene)]), out)       # scanline check too
    assert "segments[0].primitives[0].file" in line


@pytest.mark.parametrize("name, match", [("fifo.obj", "FIFO"), ("zero.obj", "device"),
                                         ("no-end-header.ply", "end_header"),
                                         ("index-2-63.obj", "line 4"),
                                         ("huge-counts.ply", "announces")])
def test_the_error_says_what_is_wrong_with_the_file(tmp_path, name, match):
    hf.MESH_FILES[name](str(tmp_path / name))
    scene = hf.scene_with_a_mesh_file(str(tmp_path / "scene.toml"), name)
    with deadline(), pytest.raises(SceneError, match=match):
        load(scene)


def test_a_scene_naming_a_good_mesh_file_still_renders(tmp_path):
    import scanline as sl

    sl.mesh.cube().save(tmp_path / "cube.obj")
    os.symlink(tmp_path / "cube.obj", tmp_path / "link.obj")
    scene = hf.scene_with_a_mesh_file(str(tmp_path / "scene.toml"), "link.obj")
    status, err = render(scene, tmp_path / "out.png")
    assert status == 0, err
    assert os.path.getsize(tmp_path / "out.png") > 0


def test_many_meshes_are_checked_together_not_one_by_one(tmp_path, monkeypatch):
    # one sphere at resolution 1024 fits this budget; 200 of them do not
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "800M")
    import scanline as sl

    assert len(sl.mesh.sphere(resolution=1024)) == 1024 * 512
    scene = hf.scene_with_many_spheres(str(tmp_path / "spheres.toml"))
    with deadline(), pytest.raises(SceneError) as info:
        load(scene)
    message = str(info.value)
    assert "mesh primitives together" in message and "per mesh" in message
    k = int(info.value.path.split("primitives[")[1].rstrip("]"))
    assert 1 <= k < 200 and info.value.path == f"segments[0].primitives[{k}]"
    assert info.value.line == 11 + k        # "primitives = [" is line 10
    out = tmp_path / "out.png"
    assert "primitives" in one_error_line(*render(scene, out), out)


def test_a_few_meshes_within_the_budget_still_build(tmp_path, monkeypatch):
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "800M")
    scene = load(hf.scene_with_many_spheres(str(tmp_path / "s.toml"), count=20,
                                            resolution=32))
    assert len(scene.display_file.segments[0].primitives) == 20


def test_a_huge_canvas_with_surfaces_is_refused_naming_its_size(tmp_path, monkeypatch):
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "2G")
    scene = hf.scene_huge_3d_canvas(str(tmp_path / "canvas.toml"))
    assert os.path.getsize(scene) < 400
    with deadline(), pytest.raises(SceneError) as info:
        load(scene)
    message = str(info.value)
    assert "canvas.width x canvas.height" in message and "13000 x 13000" in message
    assert "z-buffer" in message and info.value.line == 3
    out = tmp_path / "out.png"
    assert "canvas.width x canvas.height" in one_error_line(*render(scene, out), out)
    # the same canvas without 3-D (the frame buffer alone, 507 MB) passes the check
    (tmp_path / "flat.toml").write_text("version = 1\n[canvas]\nwidth = 13000\n"
                                        "height = 13000\n")
    assert load(tmp_path / "flat.toml").canvas.width == 13000
