"""Object representations (scanline.mesh): polygon tables and their consistency checks
on every generated mesh and on broken tables; plane equations against Hearn &
Baker's formula; exact normals of the quadrics and superquadrics; sweeps; OBJ, PLY
and STL round trips and broken files."""

import functools
import os

import numpy as np
import pytest

import scanline as sl
from scanline.mesh import Mesh, MeshFileError, PolygonTables


@functools.lru_cache(maxsize=1)
def generated():
    return {
        "cube": sl.mesh.cube(),
        "box": sl.mesh.box((0, 0, 0), (1, 2, 3)),
        "sphere": sl.mesh.sphere(2, resolution=(16, 8)),
        "ellipsoid": sl.mesh.ellipsoid(1, 2, 0.5, resolution=(12, 7)),
        "torus": sl.mesh.torus(2, 0.5, resolution=(16, 8)),
        "superellipsoid": sl.mesh.superellipsoid(0.5, 1.5, resolution=(20, 10)),
        "supertoroid": sl.mesh.supertoroid(0.7, 1.3, r=3, resolution=(16, 8)),
        "vase": sl.mesh.rotational_sweep([(0, 0), (1, 0), (1.5, 2), (0.8, 3), (0, 3)], steps=12),
        "prism": sl.mesh.translational_sweep([(0, 0), (2, 0), (2, 1), (1, 2), (0, 1)],
                                             (0.2, 0.1, 3), closed=True),
        "teapot": sl.mesh.teapot(4),
        "patch": sl.mesh.from_surface(sl.curves.BezierSurface(
            np.stack(list(np.meshgrid(np.arange(4.0), np.arange(4.0), indexing="ij"))
                     + [np.ones((4, 4))], axis=-1)), 3, 3),
    }


CLOSED = ("cube", "box", "sphere", "ellipsoid", "torus", "superellipsoid", "supertoroid",
          "vase", "prism")


NAMES = ("box", "cube", "ellipsoid", "patch", "prism", "sphere", "superellipsoid",
         "supertoroid", "teapot", "torus", "vase")


@pytest.mark.parametrize("name", NAMES)
def test_generated_meshes_have_consistent_polygon_tables(name):
    mesh = generated()[name]
    tables = mesh.polygon_tables()
    # (an open surface, the patch, passes too: its boundary vertices have two edges,
    # every edge borders a face and every facet shares an edge)
    assert tables.check() == []
    assert tables.consistent
    if name in CLOSED:       # closed: every edge borders exactly two faces, V - E + F
        _, count = mesh.edge_faces()
        assert (count == 2).all()
        genus = 1 if "tor" in name else 0
        assert len(mesh.vertices) - len(mesh.edges) + len(mesh) == 2 - 2 * genus


def test_cube_tables_by_hand():
    t = sl.mesh.cube().polygon_tables()
    assert len(t.vertices) == 8 and len(t.edges) == 12 and len(t.surfaces) == 6
    assert all(len(p) == 2 for p in t.edge_surfaces)            # each edge in two faces
    assert "S1: E" in str(t) and str(t).startswith("vertex table\n  V1: -1, -1, -1")


def test_broken_tables_are_reported():
    verts = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (5, 5, 5)]
    t = PolygonTables(verts, [(0, 1), (1, 2), (2, 0), (0, 2), (0, 7)], [[0, 1, 3], [0, 9]])
    problems = "\n".join(t.check())
    assert "edge E5 refers to vertex V8" in problems
    assert "vertex V4 is an endpoint of 0 edge(s)" in problems
    assert "edge E3 is not part of any polygon" in problems
    assert "surface S2 refers to edge E10" in problems
    # E1 E2 E4 do close (E4 joins V1 and V3 like E3), so S1 is closed; an open one:
    t = PolygonTables(verts[:3], [(0, 1), (1, 2), (2, 0), (0, 2)], [[0, 1], [0, 1, 2]])
    problems = "\n".join(t.check())
    assert "S1 has 2 edges" in problems
    t = PolygonTables([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)],
                      [(0, 1), (1, 3), (2, 3), (0, 2)], [[0, 2, 1, 3]])
    assert any("not closed" in p for p in t.check())
    # a missing back pointer in the expanded edge table
    t = PolygonTables(verts[:3], [(0, 1), (1, 2), (2, 0)], [[0, 1, 2]],
                      edge_surfaces=[[0], [0], []])
    assert any("no pointer from E3 back to S1" in p for p in t.check())
    with pytest.raises(sl.ScanlineError, match="not consistent"):
        t.validate()


def test_two_separate_triangles_share_no_edge():
    mesh = Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0), (5, 0, 0), (6, 0, 0), (5, 1, 0)],
                [[0, 1, 2], [3, 4, 5]])
    assert sum("shares no edge" in p for p in mesh.polygon_tables().check()) == 2


def hearn_baker_plane(p1, p2, p3):
    (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = p1, p2, p3
    a = y1 * (z2 - z3) + y2 * (z3 - z1) + y3 * (z1 - z2)
    b = z1 * (x2 - x3) + z2 * (x3 - x1) + z3 * (x1 - x2)
    c = x1 * (y2 - y3) + x2 * (y3 - y1) + x3 * (y1 - y2)
    d = -x1 * (y2 * z3 - y3 * z2) - x2 * (y3 * z1 - y1 * z3) - x3 * (y1 * z2 - y2 * z1)
    return a, b, c, d


def test_plane_equations_of_triangles_are_hearn_and_bakers():
    rng = np.random.default_rng(1)
    verts = rng.uniform(-5, 5, (300, 3))
    faces = np.arange(300).reshape(100, 3)
    planes = Mesh(verts, faces).plane_equations()
    expect = np.array([hearn_baker_plane(*verts[f]) for f in faces])
    np.testing.assert_allclose(planes, expect, rtol=1e-10, atol=1e-9)


@pytest.mark.parametrize("name", CLOSED[:7])
def test_outward_normals_and_the_inside_test(name):
    mesh = generated()[name]
    planes = mesh.plane_equations()
    lo, hi = mesh.bounds
    center = (lo + hi) / 2
    # a point far outside is in front of some plane; the normals point away from the
    # center on average (outward)
    assert not mesh.inside(center + 10 * (hi - lo))
    owner = np.repeat(np.arange(len(mesh)), mesh.face_sizes)
    centers = np.zeros((len(mesh), 3))
    np.add.at(centers, owner, mesh.vertices[mesh.face_indices])
    centers /= mesh.face_sizes[:, None]
    assert ((centers - center) * planes[:, :3]).sum(axis=1).mean() > 0
    if "tor" not in name:    # convex: the center is behind every plane
        assert mesh.inside(center)


def test_exact_normals_of_quadrics():
    s = sl.mesh.sphere(3, center=(1, 2, 3), resolution=(12, 6))
    np.testing.assert_allclose(s.normals, (s.vertices - (1, 2, 3)) / 3, atol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(s.vertices - (1, 2, 3), axis=1), 3)
    e = sl.mesh.ellipsoid(1, 2, 3, resolution=(10, 5))
    x, y, z = e.vertices.T
    np.testing.assert_allclose(x ** 2 + y ** 2 / 4 + z ** 2 / 9, 1)
    grad = e.vertices / [1, 4, 9]
    np.testing.assert_allclose(e.normals, grad / np.linalg.norm(grad, axis=1)[:, None], atol=1e-12)
    t = sl.mesh.torus(2, 0.5, resolution=(12, 6))
    ring = t.vertices * [1, 1, 0]
    ring = 2 * ring / np.linalg.norm(ring, axis=1)[:, None]
    np.testing.assert_allclose(np.linalg.norm(t.vertices - ring, axis=1), 0.5)
    np.testing.assert_allclose(t.normals, (t.vertices - ring) / 0.5, atol=1e-12)


def test_superellipsoid_lies_on_its_implicit_surface_with_its_gradient_as_normal():
    s1, s2, r = 0.6, 1.4, np.array([1.0, 2.0, 1.5])
    m = sl.mesh.superellipsoid(s1, s2, r, resolution=(16, 8))
    u = np.abs(m.vertices / r)
    f = (u[:, 0] ** (2 / s2) + u[:, 1] ** (2 / s2)) ** (s2 / s1) + u[:, 2] ** (2 / s1)
    np.testing.assert_allclose(f, 1, atol=1e-9)
    # the normal is the gradient of f (away from the poles and the axes' planes)
    p = m.vertices / r
    g_xy = (np.abs(p[:, 0]) ** (2 / s2) + np.abs(p[:, 1]) ** (2 / s2)) ** (s2 / s1 - 1)
    grad = np.stack([g_xy * np.sign(p[:, 0]) * np.abs(p[:, 0]) ** (2 / s2 - 1) / r[0],
                     g_xy * np.sign(p[:, 1]) * np.abs(p[:, 1]) ** (2 / s2 - 1) / r[1],
                     np.sign(p[:, 2]) * np.abs(p[:, 2]) ** (2 / s1 - 1) / r[2]], axis=1)
    ok = (np.abs(p) > 1e-6).all(axis=1)
    grad = grad[ok] / np.linalg.norm(grad[ok], axis=1)[:, None]
    np.testing.assert_allclose(m.normals[ok], grad, atol=1e-9)


def test_sweeps():
    # a unit square profile revolved a quarter turn about y: an open, quarter ring
    quarter = sl.mesh.rotational_sweep([(1, 0), (2, 0), (2, 1), (1, 1)], angle=np.pi / 2,
                                       steps=4, closed=True)
    assert len(quarter.vertices) == 4 * 5 and len(quarter) == 16
    r = np.hypot(quarter.vertices[:, 0], quarter.vertices[:, 2])
    assert set(np.round(r, 12)) == {1.0, 2.0}
    # a curve profile: a Bezier arc swept along z
    arc = sl.curves.Bezier([(0, 0), (1, 2), (2, 0)])
    wall = sl.mesh.translational_sweep(arc, (0, 0, 1), samples=9)
    assert len(wall) == 8 and len(wall.vertices) == 18
    np.testing.assert_allclose(wall.vertices[9:, 2], 1)
    with pytest.raises(sl.ScanlineError, match="on the axis"):
        sl.mesh.rotational_sweep([(0, 0), (0, 1)])
    with pytest.raises(sl.ScanlineError, match="vector"):
        sl.mesh.translational_sweep([(0, 0), (1, 0)], (0, 0, 0))


@pytest.mark.parametrize("ext", ["obj", "ply", "stl"])
def test_file_round_trips(ext, tmp_path):
    mesh = sl.mesh.merge([sl.mesh.cube(), sl.mesh.sphere(resolution=(8, 4)).translated((3, 0, 0))])
    path = tmp_path / f"m.{ext}"
    mesh.save(path)
    back = sl.mesh.load(path)
    if ext == "stl":       # triangles only, vertices shared by position: compare the triangles
        def tris(m):
            t = m.triangulated()
            return sorted(tuple(sorted(map(tuple, np.round(m.vertices[f], 5)))) for f in t.faces)
        assert tris(back) == tris(mesh)
    else:
        np.testing.assert_allclose(back.vertices, mesh.vertices, atol=1e-6)
        assert back.face_indices.tolist() == mesh.face_indices.tolist()
        assert back.face_sizes.tolist() == mesh.face_sizes.tolist()


BROKEN = {
    "truncated.ply": lambda ok: ok["ply"][:-10],
    "truncated.stl": lambda ok: ok["stl"][:200],
    "truncated.obj": lambda ok: ok["obj"][:40],
    "huge-count.ply": lambda ok: (b"ply\nformat ascii 1.0\nelement vertex 100000000000\n"
                                  b"property float x\nproperty float y\nproperty float z\n"
                                  b"end_header\n0 0 0\n"),
    "huge-count-binary.ply": lambda ok: (b"ply\nformat binary_little_endian 1.0\nelement vertex "
                                         b"4000000000\nproperty float x\nproperty float y\n"
                                         b"property float z\nend_header\n" + b"\0" * 24),
    "huge-count.stl": lambda ok: b"\0" * 80 + (4000000000).to_bytes(4, "little") + b"\0" * 100,
    "garbage.obj": lambda ok: bytes(np.random.default_rng(0).integers(0, 256, 600, np.uint8)),
    "garbage.ply": lambda ok: bytes(np.random.default_rng(1).integers(0, 256, 600, np.uint8)),
    "garbage.stl": lambda ok: bytes(np.random.default_rng(2).integers(0, 256, 600, np.uint8)),
    "empty.obj": lambda ok: b"",
    "no-faces.obj": lambda ok: b"v 0 0 0\nv 1 0 0\n",
    "bad-index.obj": lambda ok: b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
    "nan.obj": lambda ok: b"v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
}


@pytest.mark.parametrize("name", sorted(BROKEN))
def test_broken_files_are_clear_errors_naming_the_file(name, tmp_path):
    ok = {}
    for ext in ("obj", "ply", "stl"):
        sl.mesh.cube().save(tmp_path / f"ok.{ext}")
        ok[ext] = (tmp_path / f"ok.{ext}").read_bytes()
    path = tmp_path / name
    path.write_bytes(BROKEN[name](ok))
    with pytest.raises(MeshFileError) as info:
        sl.mesh.load(path)
    assert str(path) in str(info.value)


def test_file_errors(tmp_path):
    with pytest.raises(MeshFileError, match="use one of"):
        sl.mesh.load(tmp_path / "x.3ds")
    with pytest.raises(MeshFileError, match="cannot read"):
        sl.mesh.load(tmp_path / "missing.obj")
    with pytest.raises(sl.ScanlineError, match="folder"):
        sl.mesh.cube().save(tmp_path)
    target = tmp_path / "out.stl"
    with pytest.raises(sl.ScanlineError):
        sl.mesh.save("not a mesh", target)
    assert not os.path.exists(target)


@pytest.mark.parametrize("make, match", [
    (lambda: Mesh([(0, 0, 0), (1, 0, 0)], [[0, 1, 2]]), "out of range"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [[0, 1]]), "at least 3"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [[0, 1, 1]]), "repeats a vertex"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], []), "at least one face"),
    (lambda: Mesh(np.zeros((0, 3)), np.zeros((0, 3), int)), "at least one face"),
    (lambda: Mesh([(0, 0, np.nan), (1, 0, 0), (0, 1, 0)], [[0, 1, 2]]), "finite"),
    (lambda: Mesh([(0, 0), (1, 0), (0, 1)], [[0, 1, 2]]), r"\(V, 3\)"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [[0, 1, 2.5]]), "integer"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (2, 0, 0)], [[0, 1, 2]]).plane_equations(), "degenerate"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0.5), (0, 1, 0)], [[0, 1, 2, 3]]).plane_equations(),
     "not planar"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [[0, 1, 2]], colors=["red", "blue"]), "colors"),
    (lambda: sl.mesh.sphere(-1), "radius"),
    (lambda: sl.mesh.torus(1, 2), "minor"),
    (lambda: sl.mesh.sphere(resolution=(2, 2)), "resolution"),
])
def test_bad_meshes_are_clear_errors(make, match):
    with pytest.raises(sl.ScanlineError, match=match):
        make()


def test_transforms_keep_orientation_and_normals():
    s = sl.mesh.sphere(resolution=(8, 4))
    m = sl.transform3d.compose(sl.transform3d.reflection("xy"), sl.transform3d.scaling(2, 1, 1))
    t = s.transformed(m)
    assert t.polygon_tables().consistent
    center = t.vertices.mean(axis=0)
    assert t.inside(center)                      # the faces still point outward
    grad = t.vertices / [4, 1, 1]
    np.testing.assert_allclose(t.normals, grad / np.linalg.norm(grad, axis=1)[:, None], atol=1e-12)
    tri = sl.mesh.cube(colors=["red"] * 6).triangulated()
    assert len(tri) == 12 and tri.colors.shape == (12, 4)
