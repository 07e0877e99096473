"""Hardening the second half: ``sl.mesh.load`` on hostile files.

Before the fix a FIFO named ``.obj``/``.ply``/``.stl`` blocked forever, a PLY header
without ``end_header`` never returned, a ``.obj`` link to /dev/zero was read towards
gigabytes, and an OBJ face index of 2**63 wrapped or overflowed.  Every call here runs
under a deadline (SIGALRM): a hang fails the test instead of blocking the suite.  The
files come from tests/fuzz/hostile_files.py.
"""

import contextlib
import os
import signal
import socket

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentTypeError, MemoryBudgetError
from scanline.mesh import MeshFileError
from tests.fuzz import hostile_files as hf


class Hang(BaseException):
    """A call past its deadline: a BaseException, so that no ``except Exception``
    in the code under test can turn the hang into an ordinary error."""


@contextlib.contextmanager
def deadline(seconds=20):
    """Fail (TimeoutError) instead of hanging."""
    def alarm(signum, frame):
        raise Hang(f"the call took more than {seconds} s: it hangs")

    old = signal.signal(signal.SIGALRM, alarm)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


def load(path, **kw):
    with deadline():
        return sl.mesh.load(path, **kw)


@pytest.mark.parametrize("ext", ["obj", "ply", "stl"])
def test_a_fifo_is_refused_without_blocking(tmp_path, ext):
    path = hf.mesh_fifo(str(tmp_path / f"pipe.{ext}"))
    with pytest.raises(MeshFileError, match="FIFO") as info:
        load(path)
    assert path in str(info.value) and "regular file" in str(info.value)


@pytest.mark.parametrize("ext", ["obj", "stl", "ply"])
def test_a_link_to_dev_zero_is_refused_before_reading(tmp_path, ext):
    path = hf.mesh_link_to_dev_zero(str(tmp_path / f"zero.{ext}"))
    with pytest.raises(MeshFileError, match="device"):
        load(path)


def test_a_link_to_a_regular_file_is_followed(tmp_path):
    sl.mesh.cube().save(tmp_path / "real.obj")
    os.symlink(tmp_path / "real.obj", tmp_path / "link.obj")
    mesh = load(tmp_path / "link.obj")
    assert (len(mesh.vertices), len(mesh)) == (8, 6)


def test_folders_and_sockets_are_refused(tmp_path):
    os.mkdir(tmp_path / "folder.obj")
    with pytest.raises(MeshFileError, match="folder"):
        load(tmp_path / "folder.obj")
    server = socket.socket(socket.AF_UNIX)
    try:
        server.bind(str(tmp_path / "s.ply"))
        with pytest.raises(MeshFileError, match="cannot read|socket"):
            load(tmp_path / "s.ply")
    finally:
        server.close()


@pytest.mark.parametrize("comments", [0, 20000])
def test_a_ply_header_without_end_header_stops(tmp_path, comments):
    path = hf.ply_without_end_header(str(tmp_path / "open.ply"), comments)
    with pytest.raises(MeshFileError, match="end_header"):
        load(path)


@pytest.mark.parametrize("binary", [False, True])
@pytest.mark.parametrize("vertices, faces", [(10**11, 1), (3, 2**64),
                                             (99999999999999999999999999, 1)])
def test_ply_counts_beyond_the_file_are_refused(tmp_path, binary, vertices, faces):
    path = hf.ply_with_huge_counts(str(tmp_path / "huge.ply"), vertices, faces, binary)
    with pytest.raises(MeshFileError, match="announces .* more than the file's"):
        load(path)


@pytest.mark.parametrize("header, match", [
    ("ply\nformat ascii 1.0\nelement vertex x\nend_header\n", "count"),
    ("ply\nformat ascii 1.0\nelement vertex 3\nproperty quad x\nend_header\n", "type"),
    ("ply\nformat hex 1.0\nend_header\n", "format"),
    ("ply\nelement vertex 1\nproperty float x\nend_header\n0\n", "format line"),
    ("ply\nformat ascii 1.0\nelement vertex 100\nend_header\n", "no properties"),
])
def test_malformed_ply_headers_are_clear_errors(tmp_path, header, match):
    (tmp_path / "bad.ply").write_text(header)
    with pytest.raises(MeshFileError, match=match):
        load(tmp_path / "bad.ply")


def test_a_ply_without_a_final_newline_still_reads(tmp_path):
    (tmp_path / "t.ply").write_text(
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
        "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2")
    mesh = load(tmp_path / "t.ply")
    assert mesh.faces.tolist() == [[0, 1, 2]]


@pytest.mark.parametrize("index, match", [
    (2**63, "line 4: .*vertex 9223372036854775808, out of range"),
    (2**64, "line 4: .*out of range"),
    (-2**63, "line 4: .*reaches back before the first vertex"),
    (0, "line 4: vertex index 0: OBJ counts vertices from 1"),
    (4, "line 4: the face refers to vertex 4, out of range: the file has 3 vertices"),
])
def test_obj_face_indices_out_of_range_name_the_line(tmp_path, index, match):
    path = hf.obj_with_a_huge_index(str(tmp_path / "big.obj"), index)
    with pytest.raises(MeshFileError, match=match):
        load(path)


@pytest.mark.parametrize("text, match", [
    ("v 0 0 0\nv 1 x 0\nv 0 1 0\nf 1 2 3\n", "line 2: the vertex coordinates"),
    ("v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", "line 2: a vertex needs three coordinates"),
    ("v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n", "line 3: .*finite"),
    ("v 0 0 0\nv 1 0 0\nv 0 1e999 0\nf 1 2 3\n", "line 3: .*finite"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\n# note\nf 1 2\n", "line 5: a face needs at least three"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 3\nf 1 2 2\n", "line 6: .*repeats a vertex"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 three\n", "line 4: the face's vertex index"),
])
def test_obj_errors_name_their_line(tmp_path, text, match):
    (tmp_path / "bad.obj").write_text(text)
    with pytest.raises(MeshFileError, match=match):
        load(tmp_path / "bad.obj")


def test_obj_relative_indices_and_vertex_attributes(tmp_path):
    (tmp_path / "rel.obj").write_text(
        "# a square\nv 0 0 0\nv 1 0 0 1.0\nv 1 1 0 0.5 0.5 0.5\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
        "g square\nusemtl red\nf -4/1/1 -3/1/1 -2/1/1 -1/1/1\nl 1 2\n")
    mesh = load(tmp_path / "rel.obj")
    assert mesh.faces.tolist() == [[0, 1, 2, 3]]
    np.testing.assert_array_equal(mesh.vertices[2], [1, 1, 0])


def test_the_size_limit_is_an_argument(tmp_path):
    sl.mesh.cube().save(tmp_path / "cube.obj")
    size = os.path.getsize(tmp_path / "cube.obj")
    with pytest.raises(MeshFileError, match="max_bytes"):
        load(tmp_path / "cube.obj", max_bytes=size - 1)
    assert len(load(tmp_path / "cube.obj", max_bytes=size)) == 6
    with pytest.raises(ArgumentTypeError, match="max_bytes"):
        load(tmp_path / "cube.obj", max_bytes=1.5)
    with pytest.raises(ArgumentTypeError, match="path"):
        load(3.5)


def test_reading_is_checked_against_the_memory_budget(tmp_path, monkeypatch):
    sl.mesh.sphere(resolution=(16, 8)).save(tmp_path / "s.ply")
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "4K")
    with pytest.raises(MemoryBudgetError, match="path: reading the"):
        load(tmp_path / "s.ply")
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "10M")
    assert len(load(tmp_path / "s.ply")) == 16 * 8


@pytest.mark.parametrize("name", sorted(hf.MESH_FILES))
def test_every_hostile_mesh_file_is_a_clear_error(tmp_path, name):
    path = hf.MESH_FILES[name](str(tmp_path / name))
    with pytest.raises(MeshFileError) as info:
        load(path)
    assert str(path) in str(info.value)
