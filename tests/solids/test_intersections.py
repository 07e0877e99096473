"""Ray-solid intersections against exact ones written here: spheres, ellipsoids and
general quadrics (random rays, tangent rays, rays from inside), boxes, capped
cylinders and cones, closed meshes; contains, bounds and volumes against closed
forms; bad input named."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentTypeError, ArgumentValueError
from scanline.solids.program import Program

S = sl.solids
RNG = np.random.default_rng(7)


def first_hits(solid, origins, directions, tmin=0.0):
    return Program(solid).cast(np.asarray(origins, float), np.asarray(directions, float), tmin)


def sphere_roots(c, r, o, d):
    """|o + t d - c| = r: t = -b +- sqrt(b^2 - (|o - c|^2 - r^2)), b = d.(o - c), |d| = 1."""
    oc = o - c
    b = (d * oc).sum(axis=1)
    disc = b * b - ((oc * oc).sum(axis=1) - r * r)
    s = np.sqrt(np.where(disc > 0, disc, np.nan))
    return -b - s, -b + s


def random_rays(n, spread=4.0):
    o = RNG.uniform(-spread, spread, (n, 3))
    d = RNG.normal(size=(n, 3))
    return o, d / np.linalg.norm(d, axis=1, keepdims=True)


def test_sphere_random_rays_meet_the_exact_roots_with_gradient_normals():
    c, r = np.array([0.3, -0.2, 0.5]), 1.7
    o, _ = random_rays(4000)
    d = c + RNG.uniform(-2.5, 2.5, (4000, 3)) - o          # aimed near the sphere
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    near, far = sphere_roots(c, r, o, d)
    expect = np.where(near > 0, near, np.where(far > 0, far, np.inf))
    expect = np.where(np.isnan(expect), np.inf, expect)
    t, code, n = first_hits(S.Sphere(c, r), o, d)
    assert np.isfinite(t).sum() > 1000 and (~np.isfinite(t)).sum() > 500
    assert np.array_equal(np.isfinite(t), np.isfinite(expect))
    hit = np.isfinite(t)
    np.testing.assert_allclose(t[hit], expect[hit], rtol=1e-10, atol=1e-10)
    p = o[hit] + t[hit, None] * d[hit]
    np.testing.assert_allclose(n[hit], (p - c) / r, atol=1e-9)


def test_rays_from_inside_meet_the_far_root_from_outside():
    c = np.zeros(3)
    o, d = random_rays(500, spread=0.5)
    t, _, n = first_hits(S.Sphere(c, 1.0), o, d)
    _, far = sphere_roots(c, 1.0, o, d)
    np.testing.assert_allclose(t, far, rtol=1e-12)
    assert ((n * d).sum(axis=1) > 0).all()          # outward normal: the ray leaves


def test_tangent_rays_graze_and_rays_just_inside_enter():
    d = np.array([[1.0, 0.0, 0.0]] * 3)
    o = np.array([[-5.0, 0.0, 2.0], [-5.0, 0.0, 2.0 - 1e-6], [-5.0, 0.0, 2.0 + 1e-9]])
    t, code, _ = first_hits(S.Sphere((0, 0, 0), 2.0), o, d)
    assert not np.isfinite(t[0]) and code[0] == -1          # tangent: touches, enters nothing
    assert t[1] == pytest.approx(5.0 - math.sqrt(4 - (2 - 1e-6) ** 2), abs=1e-9)
    assert not np.isfinite(t[2])


def test_far_ray_keeps_the_accuracy_of_its_near_root():
    # the careful root formula: a sphere of radius 1 seen from 1e7 away along a chord
    o = np.array([[-1e7, 0.5, 0.0]])
    t, _, _ = first_hits(S.Sphere((0, 0, 0), 1.0), o, [[1.0, 0.0, 0.0]])
    assert t[0] == pytest.approx(1e7 - math.sqrt(0.75), abs=1e-8)


def test_ellipsoid_and_transformed_sphere_hits_are_exact():
    # ellipsoid x^2/9 + y^2/4 + z^2 = 1 along rays parallel to x through (y, z)
    e = S.Ellipsoid((0, 0, 0), (3, 2, 1))
    ys, zs = RNG.uniform(-1.5, 1.5, 200), RNG.uniform(-0.9, 0.9, 200)
    o = np.stack([np.full(200, -10.0), ys, zs], axis=1)
    t, _, n = first_hits(e, o, np.tile([1.0, 0, 0], (200, 1)))
    s = 1 - ys ** 2 / 4 - zs ** 2
    expect = np.where(s > 0, 10 - 3 * np.sqrt(np.clip(s, 0, None)), np.inf)
    np.testing.assert_allclose(t, expect, rtol=1e-12)
    p = o + np.where(np.isfinite(t), t, 0)[:, None] * [1, 0, 0]
    g = p / [9, 4, 1]
    g /= np.linalg.norm(g, axis=1, keepdims=True)
    np.testing.assert_allclose(n[np.isfinite(t)], g[np.isfinite(t)], atol=1e-9)


def test_general_quadric_hyperboloid_of_one_sheet():
    # x^2 + y^2 - z^2 - 1 <= 0 (the inside of a hyperboloid of one sheet), ray along x at z
    q = S.Quadric.from_coefficients(a=1, b=1, c=-1, j=-1)
    zs = np.array([0.0, 0.5, 2.0])
    o = np.stack([np.full(3, -10.0), np.zeros(3), zs], axis=1)
    t, _, n = first_hits(q, o, np.tile([1.0, 0, 0], (3, 1)))
    np.testing.assert_allclose(t, 10 - np.sqrt(1 + zs ** 2), rtol=1e-12)
    # along the axis the ray stays inside forever: no surface ahead of an inside origin
    t, code, _ = first_hits(q, [[0.0, 0.0, -5.0]], [[0.0, 0.0, 1.0]])
    assert not np.isfinite(t[0]) and code[0] == -1


def test_box_cylinder_and_cone_hits():
    box = S.Box((0, 0, 0), (1, 2, 3))
    t, _, n = first_hits(box, [[0.5, 1.0, -1.0], [-1, 1, 1], [0.5, 5.0, 1.0]],
                         [[0, 0, 1.0], [1, 0, 0], [0, -1, 0]])
    np.testing.assert_allclose(t, [1.0, 1.0, 3.0])
    np.testing.assert_allclose(n, [[0, 0, -1], [-1, 0, 0], [0, 1, 0]])
    cyl = S.Cylinder((0, 0, 0), radius=2.0, height=4.0, axis=(1, 0, 0))   # |x| <= 2, y^2+z^2 <= 4
    t, _, n = first_hits(cyl, [[0.0, 0.0, 9.0], [-9.0, 1.0, 1.0], [0.0, 3.0, 9.0]],
                         [[0, 0, -1.0], [1, 0, 0], [0, 0, -1.0]])
    np.testing.assert_allclose(t[:2], [7.0, 7.0])
    np.testing.assert_allclose(n[:2], [[0, 0, 1], [-1, 0, 0]], atol=1e-12)
    assert not np.isfinite(t[2])
    cone = S.Cone((0, 0, 0), radius=1.0, height=2.0)               # r(z) = 1 - z / 2
    z = 0.5
    t, _, n = first_hits(cone, [[-5.0, 0.0, z], [0.2, 0.0, -3.0]], [[1.0, 0, 0], [0, 0, 1.0]])
    np.testing.assert_allclose(t, [5.0 - (1 - z / 2), 3.0])
    np.testing.assert_allclose(n[0], np.array([-1.0, 0.0, 0.5]) / math.sqrt(1.25), atol=1e-12)


def test_mesh_solid_hits_match_the_polyhedron_planes():
    cube = S.MeshSolid(sl.mesh.cube(2.0))
    o, d = random_rays(300, spread=5.0)
    t, _, n = first_hits(cube, o, d)
    # the slab method on the same box, written here
    with np.errstate(divide="ignore", invalid="ignore"):
        a, b = (-1 - o) / d, (1 - o) / d
    near = np.minimum(a, b).max(axis=1)
    far = np.maximum(a, b).min(axis=1)
    expect = np.where(far > np.maximum(near, 0), np.where(near > 0, near, far), np.inf)
    np.testing.assert_allclose(t, expect, rtol=1e-9)


def test_contains_bounds_and_exact_volumes():
    p = RNG.uniform(-3, 3, (5000, 3))
    s = S.Sphere((0.5, 0, 0), 2.0)
    assert np.array_equal(s.contains(p), ((p - [0.5, 0, 0]) ** 2).sum(axis=1) <= 4)
    cyl = S.Cylinder((0, 0, 0), 1.0, 2.0)
    assert np.array_equal(cyl.contains(p), (p[:, 0] ** 2 + p[:, 1] ** 2 <= 1)
                          & (np.abs(p[:, 2]) <= 1))
    cone = S.Cone((0, 0, 0), 1.0, 2.0)
    assert np.array_equal(cone.contains(p), (np.hypot(p[:, 0], p[:, 1]) <= 1 - p[:, 2] / 2)
                          & (p[:, 2] >= 0) & (p[:, 2] <= 2))
    mesh = S.MeshSolid(sl.mesh.cube(2.0))
    q = RNG.uniform(-1.5, 1.5, (3000, 3))
    assert np.array_equal(mesh.contains(q), (np.abs(q) < 1).all(axis=1))
    assert s.volume() == pytest.approx(4 / 3 * math.pi * 8)
    assert cyl.volume() == pytest.approx(2 * math.pi)
    assert cone.volume() == pytest.approx(math.pi * 2 / 3)
    assert S.Box((0, 0, 0), (1, 2, 3)).volume() == pytest.approx(6)
    assert mesh.volume() == pytest.approx(8)
    rot = sl.transform3d.rotation(0.7, "z")
    e = S.Ellipsoid((1, 2, 3), (3, 2, 1), transform=rot)
    assert e.volume() == pytest.approx(4 / 3 * math.pi * 6)
    lo, hi = e.bounds()
    # exact extents of the rotated ellipsoid: sqrt(sum_j (R_ij r_j)^2)
    m = rot[:3, :3] * [3, 2, 1]
    c = rot[:3, :3] @ [1, 2, 3]
    np.testing.assert_allclose(hi, c + np.sqrt((m ** 2).sum(axis=1)))
    np.testing.assert_allclose(lo, c - np.sqrt((m ** 2).sum(axis=1)))
    q = S.Quadric.from_coefficients(a=1 / 4, b=1, c=1, g=-1 / 4, j=-3)
    # x^2/4 - x/2 + y^2 + z^2 - 3 = (x - 1)^2 / 4 + y^2 + z^2 - 13/4: half-axes 2k, k, k
    k = math.sqrt(13 / 4)
    assert q.volume() == pytest.approx(4 / 3 * math.pi * 2 * k ** 3)
    np.testing.assert_allclose(q.bounds()[1], [1 + 2 * k, k, k])


@pytest.mark.parametrize("make, message", [
    (lambda: S.Sphere((0, 0, 0), float("nan")), "radius"),
    (lambda: S.Sphere((0, 0, 0), -1.0), "radius"),
    (lambda: S.Sphere((0, float("inf"), 0), 1.0), "center"),
    (lambda: S.Box((0, 0, 0), (1, -1, 1)), "lo must be below hi"),
    (lambda: S.Cylinder(axis=(0, 0, 0)), "axis"),
    (lambda: S.Sphere(transform=np.zeros((4, 4))), "transform"),
    (lambda: S.Quadric(np.arange(16.0).reshape(4, 4)), "symmetric"),
    (lambda: S.Quadric.from_coefficients(a=1, c=-1).volume(), "infinite"),
    (lambda: S.MeshSolid(sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)])),
     "not closed"),
    (lambda: S.Sphere(material="red"), "material"),
])
def test_bad_input_is_named(make, message):
    with pytest.raises((ArgumentValueError, ArgumentTypeError), match=message):
        make()


def test_open_box_is_refused_and_inverted_face_named():
    box = sl.mesh.cube(2.0)
    faces = [list(f) for f in box.faces]
    with pytest.raises(ArgumentValueError, match="not closed"):
        S.MeshSolid(sl.mesh.Mesh(box.vertices, faces[:-1]))
    faces[0] = faces[0][::-1]
    with pytest.raises(ArgumentValueError, match="same way"):
        S.MeshSolid(sl.mesh.Mesh(box.vertices, faces))


def test_hostile_rays_give_misses_or_hits_never_garbage():
    # NaN, infinite, huge and zero components against every kind of primitive and a mesh
    tree = (S.Box() & S.Sphere(radius=1.3)) - S.Cylinder(radius=0.5, height=3) | \
        S.Cone() | S.MeshSolid(sl.mesh.cube(0.5, center=(2, 0, 0))) | \
        S.Quadric.from_coefficients(a=1, b=1, c=-1, j=-1)
    values = np.array([0.0, 1.0, -1.0, 1e300, -1e300, 1e-300, np.inf, -np.inf, np.nan])
    o = RNG.choice(values, (3000, 3))
    d = RNG.choice(values, (3000, 3))
    t, code, n = Program(tree).cast(o, d)
    hit = code >= 0
    assert np.array_equal(hit, np.isfinite(t)) and (code >= -1).all()
    assert hit.any() and (t[hit] > 0).all()
    finite = n[hit][np.isfinite(n[hit]).all(axis=1)]
    assert np.allclose(np.linalg.norm(finite[(finite != 0).any(axis=1)], axis=1), 1)


def test_huge_solids_are_refused_by_volume():
    with pytest.raises(ArgumentValueError, match="1e150"):
        sl.csg.volume(S.Box((0, 0, 0), (1e200, 1, 1)))
    with pytest.raises(ArgumentValueError, match="unbounded"):      # its bounds overflow
        sl.csg.volume(S.Sphere((0, 0, 0), 1e200))
