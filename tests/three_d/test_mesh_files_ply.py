"""PLY files with vertex normals and colors (written by trimesh, and by hand with face
colors), and the round trips of PLY and STL."""

import numpy as np
import pytest

import scanline as sl
from scanline.mesh import load

from .test_mesh_files_obj import scanline_set, triangle_set

trimesh = pytest.importorskip("trimesh")


@pytest.mark.parametrize("encoding", ["binary", "ascii"])
def test_vertex_colors_and_normals_from_trimesh(tmp_path, encoding):
    mesh = trimesh.creation.icosphere(subdivisions=1)
    colors = np.random.default_rng(3).integers(0, 256, (len(mesh.vertices), 4), dtype=np.uint8)
    mesh.visual.vertex_colors = colors
    path = tmp_path / "c.ply"
    path.write_bytes(trimesh.exchange.ply.export_ply(mesh, encoding=encoding,
                                                     vertex_normal=True))
    mine = load(path)
    theirs = trimesh.load(path, process=False)
    assert scanline_set(mine) == triangle_set(theirs.vertices, theirs.faces)
    assert mine.color_on == "vertex"
    np.testing.assert_array_equal(mine.colors, theirs.visual.vertex_colors)
    np.testing.assert_allclose(mine.normals, theirs.vertex_normals, atol=1e-6)


def test_face_colors_of_an_ascii_ply(tmp_path):
    (tmp_path / "f.ply").write_text(
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
        "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n"
        "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2 255 0 0\n3 0 2 3 0 0 255\n")
    mesh = load(tmp_path / "f.ply")
    assert mesh.color_on == "face"
    assert mesh.colors[:, :3].tolist() == [[255, 0, 0], [0, 0, 255]]


def test_ply_round_trip_keeps_polygons_normals_uv_and_vertex_colors(tmp_path):
    base = sl.mesh.cube()
    mesh = sl.mesh.Mesh(base.vertices, base.faces, normals=base.vertices / np.sqrt(3),
                        uv=base.vertices[:, :2] * 0.5 + 0.5,
                        colors=np.arange(24).reshape(8, 3) * 10, color_on="vertex")
    mesh.save(tmp_path / "cube.ply")
    back = load(tmp_path / "cube.ply")
    np.testing.assert_array_equal(back.vertices, mesh.vertices)
    np.testing.assert_array_equal(back.faces, mesh.faces)          # quadrilaterals kept
    np.testing.assert_allclose(back.normals, mesh.normals, atol=1e-7)
    np.testing.assert_allclose(back.uv, mesh.uv, atol=1e-7)
    np.testing.assert_array_equal(back.colors, mesh.colors)
    theirs = trimesh.load(tmp_path / "cube.ply", process=False)
    assert scanline_set(back) == triangle_set(theirs.vertices, theirs.faces)


def test_stl_round_trip_gives_the_triangles(tmp_path):
    mesh = sl.mesh.torus(1, 0.3, resolution=(12, 6))
    mesh.save(tmp_path / "t.stl")
    back = load(tmp_path / "t.stl")
    assert scanline_set(back, decimals=5) == scanline_set(mesh, decimals=5)
    theirs = trimesh.load(tmp_path / "t.stl")
    assert scanline_set(back, decimals=5) == triangle_set(theirs.vertices, theirs.faces,
                                                          decimals=5)
