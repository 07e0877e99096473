"""OBJ files as exporters write them: ``v/vt/vn`` corners, materials, polygons, lines,
and their errors.  Compared with trimesh's reading of the same files and with values
written out in the tests; ``triangle_set`` is the shared comparison (faces equal up to
vertex order)."""

import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanline as sl
from scanline.mesh import MeshFileError, MeshFileWarning, load, load_all

trimesh = pytest.importorskip("trimesh")


def triangle_set(vertices, triangles, decimals=5, extra=None):
    """The triangles as a set of corner tuples (rounded coordinates, plus ``extra``
    per-vertex values), each rotated to start at its smallest corner: equal sets
    mean the same faces with the same orientation, whatever the vertex order."""
    vertices = np.round(np.asarray(vertices, np.float64), decimals) + 0.0
    if extra is not None:
        vertices = np.hstack([vertices, np.round(np.asarray(extra, np.float64), decimals) + 0.0])
    out = set()
    for tri in np.asarray(triangles):
        corners = [tuple(vertices[i].tolist()) for i in tri]
        k = corners.index(min(corners))
        out.add(tuple(corners[k:] + corners[:k]))
    return out


def scanline_set(mesh, **kw):
    tri = mesh.triangulated()
    return triangle_set(tri.vertices, tri.faces, **kw)


def textured_sphere():
    mesh = trimesh.creation.icosphere(subdivisions=2)
    uv = np.random.default_rng(1).random((len(mesh.vertices), 2))
    mesh.visual = trimesh.visual.TextureVisuals(uv=uv)
    return mesh


def test_an_obj_written_by_trimesh_with_uv_and_normals_reads_as_trimesh_reads_it(tmp_path):
    path = tmp_path / "sphere.obj"
    path.write_text(trimesh.exchange.obj.export_obj(textured_sphere(), include_normals=True,
                                                    include_texture=True))
    assert "vt " in path.read_text() and "vn " in path.read_text()
    mine = load(path)
    theirs = trimesh.load(path, process=False, maintain_order=True)
    assert scanline_set(mine) == triangle_set(theirs.vertices, theirs.faces)
    # the uv and normals of every corner, as trimesh reads them
    assert scanline_set(mine, extra=mine.uv) == triangle_set(
        theirs.vertices, theirs.faces, extra=theirs.visual.uv)
    assert scanline_set(mine, extra=mine.normals, decimals=4) == triangle_set(
        theirs.vertices, theirs.faces, extra=theirs.vertex_normals, decimals=4)


BLENDER_CUBE = """# Blender 4.0
mtllib cube.mtl
o Cube
v 1 1 -1
v 1 -1 -1
v 1 1 1
v 1 -1 1
v -1 1 -1
v -1 -1 -1
v -1 1 1
v -1 -1 1
vn -0 1 -0
vn -0 -0 1
vn -1 -0 -0
vn -0 -1 -0
vn 1 -0 -0
vn -0 -0 -1
vt 0.625 0.5
vt 0.875 0.5
vt 0.875 0.75
vt 0.625 0.75
vt 0.375 0.75
vt 0.625 1
vt 0.375 1
vt 0.375 0
vt 0.625 0
vt 0.625 0.25
vt 0.375 0.25
vt 0.125 0.5
vt 0.375 0.5
vt 0.125 0.75
s 0
usemtl Material
f 1/1/1 5/2/1 7/3/1 3/4/1
f 4/5/2 3/4/2 7/6/2 8/7/2
f 8/8/3 7/9/3 5/10/3 6/11/3
f 6/12/4 2/13/4 4/5/4 8/14/4
f 2/13/5 1/1/5 3/4/5 4/5/5
f 6/11/6 5/10/6 1/1/6 2/13/6
"""

BLENDER_MTL = """# Blender MTL
newmtl Material
Ns 250.000000
Ka 1.000000 1.000000 1.000000
Kd 0.800000 0.100000 0.100000
Ks 0.500000 0.500000 0.500000
Ke 0.000000 0.000000 0.000000
Ni 1.450000
d 0.750000
illum 2
map_Kd -s 1 1 1 textures/wood.png
"""


def test_a_blender_cube_splits_its_corners_into_24_vertices_with_flat_normals(tmp_path):
    (tmp_path / "cube.obj").write_text(BLENDER_CUBE)
    (tmp_path / "cube.mtl").write_text(BLENDER_MTL)
    mesh = load(tmp_path / "cube.obj")
    # 6 quads whose 4 corners each are a distinct (v, vt, vn) triple
    assert len(mesh.vertices) == 24 and mesh.face_count == 6
    assert (mesh.face_sizes == 4).all()
    theirs = trimesh.load(tmp_path / "cube.obj", process=False)
    assert scanline_set(mesh) == triangle_set(theirs.vertices, theirs.faces)
    # each face's corners carry the face's own normal: the cross product of two edges
    for f in range(6):
        p = mesh.vertices[mesh.face(f)]
        n = np.cross(p[1] - p[0], p[2] - p[0])
        n /= np.linalg.norm(n)
        np.testing.assert_allclose(mesh.normals[mesh.face(f)], np.tile(n, (4, 1)), atol=1e-12)
    # the uv of the first face's corners, as written (vt 1, 2, 3, 4)
    np.testing.assert_array_equal(mesh.uv[mesh.face(0)],
                                  [[0.625, 0.5], [0.875, 0.5], [0.875, 0.75], [0.625, 0.75]])
    record = mesh.material
    assert record.name == "Material" and record.kd == (0.8, 0.1, 0.1)
    assert record.ks == (0.5, 0.5, 0.5) and record.ns == 250 and record.d == 0.75
    assert record.map_kd == str(tmp_path / "textures" / "wood.png")


def test_v_slash_slash_vn_and_v_slash_vt_and_relative_indices(tmp_path):
    (tmp_path / "forms.obj").write_text(
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
        "f 1//1 2//1 3//1\n"
        "f -4/-4 -2/-2 -1/-1\n")
    mesh = load(tmp_path / "forms.obj")
    assert mesh.face_count == 2
    # the first face has no uv, the second no normals: neither is every corner's
    assert mesh.uv is None and mesh.normals is None
    assert scanline_set(mesh) == {((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0)),
                                  ((0.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0))}
    (tmp_path / "vt.obj").write_text(
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\n")
    np.testing.assert_array_equal(load(tmp_path / "vt.obj").uv, [[0, 0], [1, 0], [1, 1]])


def test_polygons_stay_polygons_and_a_file_without_attributes_keeps_its_vertex_list(tmp_path):
    angles = np.arange(5) * 2 * math.pi / 5
    text = "".join(f"v {math.cos(a)!r} {math.sin(a)!r} 0\n" for a in angles)
    (tmp_path / "penta.obj").write_text("v 9 9 9\n" + text + "f 2 3 4 5 6\n")
    mesh = load(tmp_path / "penta.obj")
    assert mesh.faces.tolist() == [[1, 2, 3, 4, 5]]
    np.testing.assert_array_equal(mesh.vertices[0], [9, 9, 9])       # unused, kept
    np.testing.assert_array_equal(mesh.vertices[1:, 0], np.cos(angles))


def test_numbers_are_read_as_python_reads_them():
    rng = np.random.default_rng(7)
    values = np.concatenate([rng.normal(0, 1, 300), rng.normal(0, 1e6, 100),
                             rng.normal(0, 1e-6, 100), [0.0, -0.0, 1.0, 1e-300, 1e300]])
    short = [f"{x:.6f}" for x in values] + [f"{x:.9e}" for x in values] + ["5.", ".5", "-.25e1",
                                                                           "+3", "1E2"]
    import tempfile, os
    folder = tempfile.mkdtemp()
    path = os.path.join(folder, "n.obj")
    rows = [short[i:i + 3] for i in range(0, len(short) - len(short) % 3, 3)]
    with open(path, "w") as f:
        for r in rows:
            f.write("v " + " ".join(r) + "\n")
        f.write("f 1 2 3\n")
    mesh = load(path)
    expected = np.array([[float(w) for w in r] for r in rows])
    np.testing.assert_array_equal(mesh.vertices, expected)
    # 17 significant digits: within one unit in the last place of Python's float()
    long = [repr(float(x)) for x in values[:300]]
    rows = [long[i:i + 3] for i in range(0, 300, 3)]
    with open(path, "w") as f:
        for r in rows:
            f.write("v " + " ".join(r) + "\n")
        f.write("f 1 2 3\n")
    got = load(path).vertices
    want = np.array([[float(w) for w in r] for r in rows])
    assert (np.abs(got - want) <= np.spacing(np.abs(want))).all()


MTL_TWO = """newmtl red
Kd 1 0 0
newmtl blue
Kd 0 0 1
Ks 0.2 0.2 0.2
Tr 0.25
"""


def two_material_file(tmp_path):
    (tmp_path / "two.mtl").write_text(MTL_TWO)
    (tmp_path / "two.obj").write_text(
        "mtllib two.mtl\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
        "usemtl red\nf 1 2 3 4\nusemtl blue\nf 2 5 6 3\n")
    return tmp_path / "two.obj"


def test_several_materials_load_all_gives_one_mesh_per_material(tmp_path):
    parts = load_all(two_material_file(tmp_path))
    assert [p.material.name for p in parts] == ["red", "blue"]
    assert [p.face_count for p in parts] == [1, 1]
    assert [len(p.vertices) for p in parts] == [4, 4]      # only the vertices each uses
    np.testing.assert_array_equal(parts[1].vertices[:, 0].max(), 2)
    assert parts[0].material.kd == (1.0, 0.0, 0.0)
    assert parts[1].material.d == 0.75 and parts[1].material.ks == (0.2, 0.2, 0.2)


def test_several_materials_load_gives_one_mesh_colored_by_them(tmp_path):
    mesh = load(two_material_file(tmp_path))
    assert mesh.material is None and mesh.color_on == "face"
    assert mesh.colors[:, :3].tolist() == [[255, 0, 0], [0, 0, 255]]


def test_a_material_record_renders_in_its_color(tmp_path):
    (tmp_path / "red.mtl").write_text("newmtl red\nKd 1 0 0\nKs 0 0 0\n")
    (tmp_path / "sq.obj").write_text("mtllib red.mtl\nusemtl red\nv -1 -1 0\nv 1 -1 0\n"
                                     "v 1 1 0\nv -1 1 0\nf 1 2 3 4\n")
    mesh = load(tmp_path / "sq.obj")
    fb = sl.FrameBuffer(16, 16, mode="RGB")
    cam = sl.Camera(eye=(0, 0, 3), target=(0, 0, 0))
    sl.render(fb, [mesh], cam, shading="flat")
    r, g, b = fb.to_array()[8, 8][:3]
    assert r > 100 and g == 0 and b == 0


def test_skipped_lines_and_missing_materials_warn_once(tmp_path):
    (tmp_path / "l.obj").write_text("mtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                    "l 1 2\nl 2 3\nusemtl x\nf 1 2 3\n")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        mesh = load(tmp_path / "l.obj")
    messages = [str(w.message) for w in caught if issubclass(w.category, MeshFileWarning)]
    assert len([m for m in messages if "2 line statement(s)" in m]) == 1
    assert any("nowhere.mtl" in m and "missing" in m for m in messages)
    assert mesh.face_count == 1 and mesh.material is None


@pytest.mark.parametrize("text, match", [
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/2 2/1 3/1\n",
     "line 5: the face refers to texture coordinate 2, out of range: the file has 1"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//-1 2//1 3//1\nvn 0 0 1\n",
     "line 4: the relative normal index -1 reaches back before the first normal"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x/1 2 3\n", "line 4: the face's vertex index '1/x/1'"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1/1 2 3\n",
     "line 6: the face's vertex index '1/1/1/1'"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 nan 1\nf 1 2 3\n", "line 4: the normal coordinates are "
                                                          "not all finite"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt\nf 1 2 3\n", "line 4: a texture coordinate needs at least u"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 0/1\n", "line 4: vertex index 0"),
])
def test_corner_errors_name_the_line(tmp_path, text, match):
    (tmp_path / "bad.obj").write_text(text)
    with pytest.raises(MeshFileError, match=match) as info:
        load(tmp_path / "bad.obj")
    assert str(tmp_path / "bad.obj") in str(info.value)


def test_non_utf8_bytes_name_their_line(tmp_path):
    (tmp_path / "latin.obj").write_bytes(b"# caf\xe9\nv 0 0 0\nv 1 \xff\xfe 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(MeshFileError, match="line 3: the vertex coordinates"):
        load(tmp_path / "latin.obj")
    # in a comment or a name they are harmless
    (tmp_path / "ok.obj").write_bytes(b"# caf\xe9\no \xff\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    assert load(tmp_path / "ok.obj").face_count == 1


def test_a_hostile_material_file_is_refused_naming_the_obj_line(tmp_path):
    import os

    os.symlink("/dev/zero", tmp_path / "zero.mtl")
    (tmp_path / "z.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nmtllib zero.mtl\nf 1 2 3\n")
    with pytest.raises(MeshFileError, match="line 4: mtllib 'zero.mtl'.*device"):
        load(tmp_path / "z.obj")
    (tmp_path / "nan.mtl").write_text("newmtl a\nKd nan 0 0\n")
    (tmp_path / "n.obj").write_text("mtllib nan.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(MeshFileError, match="nan.mtl: line 2: Kd needs finite numbers"):
        load(tmp_path / "n.obj")


def test_obj_round_trip_keeps_uv_normals_and_polygons(tmp_path):
    mesh = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 2, 0)],
                        [[0, 1, 2, 3], [3, 2, 4]], normals=np.tile([0.0, 0, 1], (5, 1)),
                        uv=[(0, 0), (1, 0), (1, 1), (0, 1), (0.5, 1 / 3)])
    mesh.save(tmp_path / "m.obj")
    back = load(tmp_path / "m.obj")
    np.testing.assert_array_equal(back.vertices, mesh.vertices)
    np.testing.assert_array_equal(back.uv, mesh.uv)          # 17 digits: exact
    np.testing.assert_array_equal(back.normals, mesh.normals)
    assert back.faces == [] or [f.tolist() for f in back.faces] == [[0, 1, 2, 3], [3, 2, 4]]
    theirs = trimesh.load(tmp_path / "m.obj", process=False)
    assert scanline_set(back) == triangle_set(theirs.vertices, theirs.faces)


def test_a_material_record_becomes_the_lighting_material_hearn_and_baker_use():
    from scanline.mesh import MaterialRecord
    from scanline.screen.prepare import _from_record

    record = MaterialRecord("m", kd=(0.8, 0.4, 0.2), ks=(0.5, 0.5, 0.25), ns=64, d=0.25)
    square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0)], [[0, 1, 2]], material=record)
    assert square.material is record
    m = _from_record(record)
    # Kd = k_d S_d with S_d scaled to a largest component of 1; likewise Ks
    assert m.kd == 0.8 and m.ks == 0.5 and m.shininess == 64 and m.transparency == 0.75
    np.testing.assert_allclose(m.color, (1.0, 0.5, 0.25))
    np.testing.assert_allclose(m.specular_color, (1.0, 1.0, 0.5))
    black = _from_record(MaterialRecord("b", kd=(0, 0, 0)))
    assert black.kd == 0 and black.ks == sl.lighting.Material().ks


TOKENS = [b"/", b"//", b"-", b"-1", b"0", b"99999999999999999999", b"1e999", b"nan", b"\n",
          b"f ", b"v ", b"vt ", b"vn ", b"usemtl ", b"mtllib ", b" ", b"#", b"\xff", b".", b"e"]


@pytest.mark.boundscheck
@settings(max_examples=60, deadline=None)
@given(ops=st.lists(st.tuples(st.floats(0, 1), st.one_of(st.binary(max_size=8),
                                                         st.sampled_from(TOKENS))),
                    min_size=1, max_size=8))
def test_mutated_obj_files_are_read_or_refused_by_the_compiled_kernels(ops):
    """The kernels compiled (a small file would run their Python twins): whatever the
    bytes, a mesh with finite vertices and faces in range, or a MeshFileError."""
    import tempfile

    from scanline._kernels import _jit

    data = bytearray(BLENDER_CUBE.encode())
    for where, what in ops:
        at = int(where * len(data))
        data[at:at + len(what)] = what
    with tempfile.TemporaryDirectory() as folder:
        path = f"{folder}/m.obj"
        with open(path, "wb") as f:
            f.write(bytes(data))
        before, _jit.COMPILE = _jit.COMPILE, "always"
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                mesh = load(path)
        except MeshFileError:
            return
        finally:
            _jit.COMPILE = before
    assert np.isfinite(mesh.vertices).all()
    assert 0 <= mesh.face_indices.min() and mesh.face_indices.max() < len(mesh.vertices)


def test_vertex_colors_as_trimesh_writes_them(tmp_path):
    tm = trimesh.creation.icosphere(subdivisions=1)
    tm.visual.vertex_colors = np.random.default_rng(4).integers(0, 256, (len(tm.vertices), 4))
    (tmp_path / "c.obj").write_text(trimesh.exchange.obj.export_obj(tm, include_color=True))
    mine = load(tmp_path / "c.obj")
    theirs = trimesh.load(tmp_path / "c.obj", process=False)
    assert mine.color_on == "vertex"
    assert scanline_set(mine, extra=mine.colors[:, :3]) == triangle_set(
        theirs.vertices, theirs.faces, extra=theirs.visual.vertex_colors[:, :3])
    # a w, or extra words that are not numbers: no colors
    (tmp_path / "w.obj").write_text("v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 1 2 3\n")
    (tmp_path / "x.obj").write_text("v 0 0 0 1 x y\nv 1 0 0 1 1 1\nv 0 1 0 0 0 0\nf 1 2 3\n")
    assert load(tmp_path / "w.obj").colors is None and load(tmp_path / "x.obj").colors is None
