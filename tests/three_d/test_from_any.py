"""Mesh.from_any: trimesh, meshio, Open3D (a stand-in class: open3d is not installed
here) and plain vertices/faces objects, taken by sl.render and sl.draw3d without
importing those packages unless given one of their objects."""

import subprocess
import sys
import types

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentTypeError
from scanline.mesh import Mesh

from .test_mesh_files_obj import scanline_set, triangle_set

trimesh = pytest.importorskip("trimesh")


def test_a_trimesh_with_vertex_colors_and_normals():
    tm = trimesh.creation.icosphere(subdivisions=1)
    tm.visual.vertex_colors = np.random.default_rng(0).integers(0, 256, (len(tm.vertices), 4))
    normals = np.asarray(tm.vertex_normals)             # computed: trimesh holds them now
    mesh = Mesh.from_any(tm)
    np.testing.assert_array_equal(mesh.vertices, tm.vertices)
    np.testing.assert_array_equal(mesh.faces, tm.faces)
    np.testing.assert_array_equal(mesh.colors, tm.visual.vertex_colors)
    assert mesh.color_on == "vertex"
    np.testing.assert_allclose(mesh.normals, normals)


def test_a_trimesh_without_computed_normals_leaves_them_to_the_render():
    assert Mesh.from_any(trimesh.creation.box()).normals is None


def test_a_trimesh_with_face_colors_and_one_with_uv_and_a_material():
    tm = trimesh.creation.box()
    tm.visual.face_colors = [0, 200, 0, 255]
    mesh = Mesh.from_any(tm)
    assert mesh.color_on == "face" and (mesh.colors[:, 1] == 200).all()
    uv = np.random.default_rng(1).random((8, 2))
    tm = trimesh.creation.box()
    tm.visual = trimesh.visual.TextureVisuals(
        uv=uv, material=trimesh.visual.material.SimpleMaterial(diffuse=[255, 0, 0, 255]))
    mesh = Mesh.from_any(tm)
    np.testing.assert_array_equal(mesh.uv, uv)
    assert mesh.material.kd == (1.0, 0.0, 0.0)


def test_a_trimesh_scene_places_its_geometry_by_the_graph():
    scene = trimesh.Scene()
    box = trimesh.creation.box()
    move = trimesh.transformations.translation_matrix([5, 0, 0])
    scene.add_geometry(box, node_name="a")
    scene.add_geometry(box, node_name="b", transform=move)
    mesh = Mesh.from_any(scene)
    moved = box.copy().apply_transform(move)
    expected = triangle_set(box.vertices, box.faces) | triangle_set(moved.vertices, moved.faces)
    assert scanline_set(mesh) == expected
    assert scanline_set(mesh) == triangle_set(scene.to_mesh().vertices, scene.to_mesh().faces)


def test_a_meshio_mesh_with_triangles_and_quads():
    import meshio

    points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (2, 0, 0)]
    m = meshio.Mesh(points, [("quad", [[0, 1, 2, 3]]), ("triangle", [[1, 4, 2]]),
                             ("line", [[0, 4]])], point_data={"nx": np.zeros(5), "ny":
                                                              np.zeros(5), "nz": np.ones(5)})
    mesh = Mesh.from_any(m)
    assert [f.tolist() for f in mesh.faces] == [[0, 1, 2, 3], [1, 4, 2]]
    np.testing.assert_array_equal(mesh.normals, np.tile([0.0, 0, 1], (5, 1)))


class Vector3dVector:
    """Open3D's vector type: np.asarray gives the (N, 3) array."""

    def __init__(self, rows):
        self.rows = np.asarray(rows, np.float64)

    def __array__(self, dtype=None, copy=None):
        return self.rows if dtype is None else self.rows.astype(dtype)


def fake_open3d_mesh(with_colors):
    tm = trimesh.creation.icosphere(subdivisions=1)
    colors = np.random.default_rng(2).random((len(tm.vertices), 3))
    TriangleMesh = type("TriangleMesh", (), {
        "__module__": "open3d.cpu.pybind.geometry",
        "has_vertex_normals": lambda self: False,
        "has_vertex_colors": lambda self: with_colors,
    })
    obj = TriangleMesh()
    obj.vertices = Vector3dVector(tm.vertices)
    obj.triangles = Vector3dVector(tm.faces)
    obj.vertex_colors = Vector3dVector(colors)
    return obj, tm, colors


def test_an_open3d_triangle_mesh_stand_in():
    obj, tm, colors = fake_open3d_mesh(True)
    mesh = Mesh.from_any(obj)
    assert scanline_set(mesh) == triangle_set(tm.vertices, tm.faces)
    np.testing.assert_array_equal(mesh.colors[:, :3], np.round(colors * 255))
    assert "open3d" not in sys.modules


def test_anything_with_vertices_and_faces():
    obj = types.SimpleNamespace(vertices=[(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)],
                                faces=[[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
                                uv=np.zeros((4, 2)))
    mesh = Mesh.from_any(obj)
    assert mesh.face_count == 4 and mesh.uv is not None
    assert Mesh.from_any(mesh) is mesh


@pytest.mark.parametrize("thing", [3, "cube.obj", np.zeros((3, 3)), {"vertices": 1},
                                   types.SimpleNamespace(vertices=[(0, 0, 0)])])
def test_a_non_mesh_is_a_type_error_naming_what_works(thing):
    with pytest.raises(ArgumentTypeError, match="trimesh.Trimesh or trimesh.Scene, a meshio.Mesh"):
        Mesh.from_any(thing)


def test_render_and_wireframe_take_a_trimesh_as_they_take_its_mesh():
    tm = trimesh.creation.icosphere(subdivisions=2)
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0))
    images = []
    for meshes in ([tm], [Mesh(tm.vertices, tm.faces)]):
        fb = sl.FrameBuffer(48, 48, mode="RGB")
        sl.render(fb, meshes, cam, shading="gouraud")
        sl.draw3d.wireframe(fb, meshes[0], cam, color="red")
        images.append(fb.to_array())
    np.testing.assert_array_equal(images[0], images[1])
    assert images[0].any()
    with pytest.raises(ArgumentTypeError, match=r"meshes\[1\] is 'x', not a mesh"):
        sl.render(sl.FrameBuffer(8, 8), [tm, "x"], cam)


def test_plain_objects_do_not_import_the_mesh_libraries():
    code = ("import sys, types, scanline as sl\n"
            "o = types.SimpleNamespace(vertices=[(0,0,0),(1,0,0),(0,1,0)], faces=[(0,1,2)])\n"
            "fb = sl.FrameBuffer(8, 8)\n"
            "sl.render(fb, [o], sl.Camera(eye=(0, 0, 3), target=(0, 0, 0)))\n"
            "print(sorted(m for m in ('trimesh', 'open3d', 'pygltflib') if m in sys.modules))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "[]"
