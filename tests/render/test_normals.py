"""Vertex normals as modelers make them: split at a crease angle and weighted by the
faces' angles at the vertex -- against a plain-Python reference written here, on a
cube (flat faces), a sphere without normals (nearly radial), and the book's plain
average with crease_angle=None."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.screen.meshes import averaged_normals, corner_normals


def reference(mesh, crease):
    """The normal at each face corner, written out: for each face f and each of its
    vertices v, the sum over the faces g around v with n_g . n_f >= cos(crease) of
    angle_g(v) n_g, normalized (Thurmer & Wuthrich 1998)."""
    faces = [list(mesh.face(i)) for i in range(mesh.face_count)]
    p = mesh.vertices

    def normal(face):
        n = np.zeros(3)
        for a, b in zip(face, face[1:] + face[:1]):     # Newell
            n += [(p[a][1] - p[b][1]) * (p[a][2] + p[b][2]),
                  (p[a][2] - p[b][2]) * (p[a][0] + p[b][0]),
                  (p[a][0] - p[b][0]) * (p[a][1] + p[b][1])]
        return n / np.linalg.norm(n)

    def angle(face, v):
        k = face.index(v)
        a, b = p[face[(k + 1) % len(face)]] - p[v], p[face[k - 1]] - p[v]
        return math.atan2(np.linalg.norm(np.cross(a, b)), a @ b)

    out = []
    for f in faces:
        nf = normal(f)
        for v in f:
            s = sum((angle(g, v) * normal(g) for g in faces if v in g
                     and normal(g) @ nf >= math.cos(crease) - 1e-12), np.zeros(3))
            out.append(s / np.linalg.norm(s))
    return np.array(out)


def bare(mesh):
    """The mesh without its own normals."""
    return sl.mesh.Mesh(mesh.vertices, [list(mesh.face(i)) for i in range(mesh.face_count)])


@pytest.mark.parametrize("crease", [math.radians(30), math.radians(60), math.pi])
def test_the_kernel_gives_the_reference_normals(crease):
    rng = np.random.default_rng(4)
    mesh = bare(sl.mesh.sphere(1.0, resolution=(8, 5)))
    mesh.vertices[:] += rng.uniform(-0.08, 0.08, mesh.vertices.shape)   # uneven angles
    np.testing.assert_allclose(corner_normals(mesh, crease), reference(mesh, crease),
                               atol=1e-12)


def test_a_cube_keeps_its_faces_flat():
    cube = sl.mesh.cube(2)
    n = corner_normals(cube)
    for i in range(cube.face_count):
        at = slice(cube.face_offsets[i], cube.face_offsets[i + 1])
        assert np.allclose(n[at], n[at][0]) and np.isclose(np.abs(n[at][0]).max(), 1.0)
    # rendered: one level per face under a directional light, Gouraud and Phong alike
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0))
    for shading in ("gouraud", "phong"):
        fb = sl.FrameBuffer(48, 36, mode="L")
        r = sl.render(fb, cube, cam, shading=shading, specular="blinn",
                      lights=[sl.lighting.DirectionalLight((-1, -2, -3))],
                      materials=sl.lighting.Material(ka=0, kd=1, ks=0))
        for f in np.unique(r.faces[r.faces >= 0]):
            assert np.ptp(fb._raster()[0][..., 0][r.faces == f]) <= 1, (shading, f)
    # the book's plain average: the corners are shared and the faces shade unevenly
    fb = sl.FrameBuffer(48, 36, mode="L")
    r = sl.render(fb, cube, cam, shading="gouraud", crease_angle=None)
    assert max(np.ptp(fb._raster()[0][..., 0][r.faces == f])
               for f in np.unique(r.faces[r.faces >= 0])) > 20


def test_a_sphere_without_normals_gets_nearly_radial_ones():
    sphere = bare(sl.mesh.sphere(1.0, resolution=(32, 16)))
    n = corner_normals(sphere)
    radial = sphere.vertices[sphere.face_indices]
    radial /= np.linalg.norm(radial, axis=1, keepdims=True)
    assert (n * radial).sum(axis=1).min() > 0.999


def test_none_is_the_books_plain_average():
    mesh = bare(sl.mesh.torus(1, 0.4, resolution=(10, 6)))
    np.testing.assert_allclose(corner_normals(mesh, None),
                               averaged_normals(mesh)[mesh.face_indices])


def test_a_meshs_own_normals_win():
    sphere = sl.mesh.sphere(1.0, resolution=(8, 5))
    np.testing.assert_allclose(corner_normals(sphere, 0.1),
                               sphere.normals[sphere.face_indices] /
                               np.linalg.norm(sphere.normals[sphere.face_indices], axis=1,
                                              keepdims=True))


@pytest.mark.parametrize("bad", [-0.1, 4.0, float("nan"), "30deg?", [1]])
def test_bad_crease_angles(bad):
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0))
    with pytest.raises(sl.ScanlineError, match="crease_angle"):
        sl.render(sl.FrameBuffer(8, 8), sl.mesh.cube(), cam, crease_angle=bad)
