"""glTF 2.0 files: GLB written by trimesh with node transforms, hand-written .gltf files
with external and data-URI buffers, node hierarchies (matrix and T R S), materials,
round trips and malformed files (truncated buffers, lying accessors)."""

import base64
import json
import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanline as sl
from scanline.mesh import MeshFileError, MeshFileWarning, load, load_all

from .test_mesh_files_obj import scanline_set, triangle_set

trimesh = pytest.importorskip("trimesh")


def test_a_glb_with_node_transforms_reads_as_trimesh_reads_it(tmp_path):
    scene = trimesh.Scene()
    rotate = trimesh.transformations.rotation_matrix(0.7, [0, 1, 1])
    scene.add_geometry(trimesh.creation.box(extents=(1, 2, 3)), node_name="box",
                       transform=trimesh.transformations.translation_matrix([3, 0, 0]) @ rotate)
    scene.add_geometry(trimesh.creation.icosphere(1), node_name="ball",
                       transform=trimesh.transformations.scale_matrix(0.5))
    path = tmp_path / "scene.glb"
    path.write_bytes(scene.export(file_type="glb"))
    parts = load_all(path)
    assert len(parts) == 2
    theirs = trimesh.load(path, force="mesh")
    assert scanline_set(load(path), decimals=4) == triangle_set(theirs.vertices, theirs.faces,
                                                                decimals=4)


def square_document(buffer_uri, data):
    """A glTF document of one square (two triangles) with normals, uv and a
    material, under a node hierarchy: a parent translated by (10, 0, 0) and a child
    rotated a quarter turn about z (quaternion) and scaled by 2."""
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"translation": [10, 0, 0], "children": [1]},
                  {"mesh": 0, "rotation": [0, 0, math.sin(math.pi / 4), math.cos(math.pi / 4)],
                   "scale": [2, 2, 2]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1,
                                                   "TEXCOORD_0": 2},
                                    "indices": 3, "material": 0}]}],
        "materials": [{"name": "paint", "pbrMetallicRoughness": {
            "baseColorFactor": [0.2, 0.4, 0.6, 0.5], "baseColorTexture": {"index": 0}}}],
        "textures": [{"source": 0}], "images": [{"uri": "paint.png"}],
        "buffers": [{"uri": buffer_uri, "byteLength": len(data)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 96, "byteLength": 32},
                        {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                      {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                      {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}],
    }
    return doc


SQUARE = np.array([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], np.float32)
UV = np.array([(0, 1), (1, 1), (1, 0), (0, 0)], np.float32)       # glTF: v = 0 at the top


def square_bytes():
    return (SQUARE.tobytes() + np.tile(np.float32([0, 0, 1]), 4).tobytes() + UV.tobytes()
            + np.array([0, 1, 2, 0, 2, 3], np.uint16).tobytes())


def expected_square():
    """The square moved by the node hierarchy, by hand: (x, y) -> 2 (-y, x) + (10, 0)."""
    return np.array([(10 - 2 * y, 2 * x, 2 * z) for x, y, z in SQUARE.tolist()])


def test_a_gltf_with_an_external_buffer_and_a_trs_hierarchy(tmp_path):
    data = square_bytes()
    (tmp_path / "square.bin").write_bytes(data)
    (tmp_path / "square.gltf").write_text(json.dumps(square_document("square.bin", data)))
    mesh = load(tmp_path / "square.gltf")
    np.testing.assert_allclose(mesh.vertices, expected_square(), atol=1e-12)
    np.testing.assert_allclose(mesh.normals, np.tile([0, 0, 1.0], (4, 1)), atol=1e-12)
    np.testing.assert_array_equal(mesh.uv, [(0, 0), (1, 0), (1, 1), (0, 1)])
    assert mesh.faces.tolist() == [[0, 1, 2], [0, 2, 3]]
    record = mesh.material
    assert record.name == "paint" and record.d == 0.5
    np.testing.assert_allclose(record.kd, (0.2, 0.4, 0.6))
    assert record.map_kd == str(tmp_path / "paint.png")
    theirs = trimesh.load(tmp_path / "square.gltf", force="mesh")
    assert scanline_set(mesh) == triangle_set(theirs.vertices, theirs.faces)


def test_a_gltf_with_a_data_uri_buffer_and_a_matrix(tmp_path):
    data = square_bytes()
    doc = square_document("data:application/octet-stream;base64,"
                          + base64.b64encode(data).decode(), data)
    # the same transformation as one column-major matrix on the child, parent without
    m = np.zeros((4, 4))
    m[:3, :3] = 2 * np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1]])
    m[:, 3] = (10, 0, 0, 1)
    doc["nodes"] = [{"children": [1]}, {"mesh": 0, "matrix": m.T.reshape(-1).tolist()}]
    (tmp_path / "inline.gltf").write_text(json.dumps(doc))
    np.testing.assert_allclose(load(tmp_path / "inline.gltf").vertices, expected_square(),
                               atol=1e-12)


def test_lines_are_skipped_with_a_warning_and_only_lines_is_an_error(tmp_path):
    data = square_bytes()
    doc = square_document("data:application/octet-stream;base64,"
                          + base64.b64encode(data).decode(), data)
    doc["meshes"][0]["primitives"].append({"attributes": {"POSITION": 0}, "mode": 1})
    (tmp_path / "lines.gltf").write_text(json.dumps(doc))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert load(tmp_path / "lines.gltf").face_count == 2
    assert any(issubclass(w.category, MeshFileWarning) and "mode(s) [1]" in str(w.message)
               for w in caught)
    doc["meshes"][0]["primitives"] = doc["meshes"][0]["primitives"][1:]
    (tmp_path / "only.gltf").write_text(json.dumps(doc))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(MeshFileError, match="no triangle primitives"):
            load(tmp_path / "only.gltf")


def broken(tmp_path, change, data=None):
    data = square_bytes() if data is None else data
    doc = square_document("square.bin", data)
    change(doc)
    (tmp_path / "square.bin").write_bytes(data)
    path = tmp_path / "broken.gltf"
    path.write_text(json.dumps(doc))
    return path


@pytest.mark.parametrize("change, match", [
    (lambda d: d["accessors"][0].update(count=40), "accessor 0: 40 elements .* truncated or lies"),
    (lambda d: d["accessors"][3].update(count=2**40), "accessor 3: .* truncated or lies"),
    (lambda d: d["accessors"][1].update(byteOffset=40), "accessor 1: .*need 88 bytes"),
    (lambda d: d["bufferViews"][3].update(byteLength=1000), "accessor 3: its buffer view 3 "
                                                             "reaches byte 1,128"),
    (lambda d: d["accessors"][2].update(type="VEC3"), "accessor 2: has type VEC3, expected VEC2"),
    (lambda d: d["accessors"][0].update(componentType=1), "accessor 0: component type 1"),
    (lambda d: d["meshes"][0]["primitives"][0].update(indices=9), "accessor 9"),
    (lambda d: d["nodes"][1].update(children=[0]), "node 0 is reached twice"),
    (lambda d: d["nodes"][1].update(scale=[1, 2]), "node 1: its matrix or"),
    (lambda d: d["buffers"][0].update(byteLength=10**6), "buffer 0 holds 140 bytes, less than"),
])
def test_malformed_gltf_name_the_accessor_or_node(tmp_path, change, match):
    with pytest.raises(MeshFileError, match=match) as info:
        load(broken(tmp_path, change))
    assert "broken.gltf" in str(info.value)


def test_out_of_range_indices_and_nan_positions_name_the_accessor(tmp_path):
    data = bytearray(square_bytes())
    data[128:130] = np.uint16(7).tobytes()
    with pytest.raises(MeshFileError, match="accessor 3: index 7 is out of range: POSITION "
                                            r"\(accessor 0\) has 4 vertices"):
        load(broken(tmp_path, lambda d: None, bytes(data)))
    data = bytearray(square_bytes())
    data[0:4] = np.float32(np.nan).tobytes()
    with pytest.raises(MeshFileError, match="accessor 0: holds values that are not finite"):
        load(broken(tmp_path, lambda d: None, bytes(data)))


@pytest.mark.parametrize("cut", [10, 100, 400, -4])
def test_truncated_glb_files_are_clear_errors(tmp_path, cut):
    sl.mesh.sphere(resolution=(8, 4)).save(tmp_path / "s.glb")
    data = (tmp_path / "s.glb").read_bytes()
    (tmp_path / "cut.glb").write_bytes(data[:cut])
    with pytest.raises(MeshFileError) as info:
        load(tmp_path / "cut.glb")
    assert "cut.glb" in str(info.value)


@pytest.mark.parametrize("content", [b"\xff\xfe not json", b"{\"asset\": ", b"[1, 2]",
                                     b"glTF\x02\x00\x00\x00\xff\xff\xff\xff"])
def test_garbage_gltf_is_a_clear_error(tmp_path, content):
    (tmp_path / "g.gltf").write_bytes(content)
    with pytest.raises(MeshFileError, match="g.gltf"):
        load(tmp_path / "g.gltf")


def test_an_external_buffer_that_is_a_device_is_refused(tmp_path):
    import os

    os.symlink("/dev/zero", tmp_path / "zero.bin")
    doc = square_document("zero.bin", square_bytes())
    (tmp_path / "z.gltf").write_text(json.dumps(doc))
    with pytest.raises(MeshFileError, match="zero.bin: it is a device"):
        load(tmp_path / "z.gltf")


@pytest.mark.parametrize("ext", ["glb", "gltf"])
def test_round_trip_keeps_geometry_uv_normals_colors_and_material(tmp_path, ext):
    from scanline.mesh import MaterialRecord

    base = sl.mesh.sphere(resolution=(12, 6))
    mesh = sl.mesh.Mesh(base.vertices, base.faces, normals=base.normals,
                        uv=np.random.default_rng(0).random((len(base.vertices), 2)),
                        colors=np.random.default_rng(1).integers(0, 256, (len(base.vertices), 3)),
                        color_on="vertex")
    mesh.material = MaterialRecord("glaze", kd=(0.5, 0.25, 1.0), d=0.8)
    mesh.save(tmp_path / f"m.{ext}")
    back = load(tmp_path / f"m.{ext}")
    tri = mesh.triangulated()
    np.testing.assert_allclose(back.vertices, tri.vertices, rtol=1e-6, atol=1e-7)
    np.testing.assert_array_equal(back.faces, tri.faces)
    np.testing.assert_allclose(back.normals, tri.normals, atol=1e-6)
    np.testing.assert_allclose(back.uv, tri.uv, atol=1e-6)
    np.testing.assert_array_equal(back.colors, tri.colors)
    assert back.material.name == "glaze" and back.material.d == pytest.approx(0.8)
    np.testing.assert_allclose(back.material.kd, (0.5, 0.25, 1.0))
    theirs = trimesh.load(tmp_path / f"m.{ext}", force="mesh")
    assert scanline_set(back, decimals=4) == triangle_set(theirs.vertices, theirs.faces,
                                                          decimals=4)


def test_compressed_geometry_is_refused_by_name(tmp_path):
    doc = square_document("square.bin", square_bytes())
    doc["extensionsRequired"] = ["KHR_draco_mesh_compression"]
    (tmp_path / "square.bin").write_bytes(square_bytes())
    (tmp_path / "draco.gltf").write_text(json.dumps(doc))
    with pytest.raises(MeshFileError, match="requires the extension.*KHR_draco_mesh_compression"):
        load(tmp_path / "draco.gltf")


@pytest.mark.boundscheck
@settings(max_examples=60, deadline=None)
@given(ops=st.lists(st.tuples(st.floats(0, 1), st.binary(min_size=1, max_size=8)),
                    min_size=1, max_size=6))
def test_mutated_glb_files_are_read_or_refused(ops):
    import tempfile

    with tempfile.TemporaryDirectory() as folder:
        sl.mesh.sphere(resolution=(6, 4)).save(f"{folder}/s.glb")
        with open(f"{folder}/s.glb", "rb") as f:
            data = bytearray(f.read())
        for where, what in ops:
            at = int(where * len(data))
            data[at:at + len(what)] = what
        with open(f"{folder}/m.glb", "wb") as f:
            f.write(bytes(data))
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                mesh = load(f"{folder}/m.glb")
        except MeshFileError:
            return
    assert np.isfinite(mesh.vertices).all()


def test_degenerate_triangles_are_skipped_with_a_warning(tmp_path):
    data = bytearray(square_bytes())
    data[128:140] = np.array([0, 1, 2, 0, 0, 3], np.uint16).tobytes()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        mesh = load(broken(tmp_path, lambda d: None, bytes(data)))
    assert mesh.faces.tolist() == [[0, 1, 2]]
    assert any("accessor 3: 1 degenerate triangle(s)" in str(w.message) for w in caught)
