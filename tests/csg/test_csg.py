"""CSG trees: Roth's interval rules along rays against intervals worked out here,
volumes by ray casting against exact values (a lens, a sphere minus a box's corner,
two overlapping boxes) within the grid's stated tolerance, and against trimesh's
boolean operations (manifold3d) on the same solids tessellated; mass properties
against closed forms and trimesh; bad input named."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentTypeError, ArgumentValueError
from scanline.solids.program import Program

S = sl.solids
csg = sl.csg
trimesh = pytest.importorskip("trimesh")
pytest.importorskip("manifold3d")


def lens_volume(r, d):
    """Two balls of radius r whose centers are d apart: pi (4 r + d) (2 r - d)^2 / 12."""
    return math.pi * (4 * r + d) * (2 * r - d) ** 2 / 12


def test_interval_rules_along_one_ray():
    # boxes [0,2] and [1,3] along x, one ray along x: union [0,3], intersection [1,2],
    # difference [0,1] whose far end is b's near face, turned inside out
    a, b = S.Box((0, -1, -1), (2, 1, 1)), S.Box((1, -1, -1), (3, 1, 1))
    o, d = np.array([[-5.0, 0, 0]]), np.array([[1.0, 0, 0]])
    for tree, near, far, far_normal in [(a | b, 5.0, 8.0, 1), (a & b, 6.0, 7.0, 1),
                                        (a - b, 5.0, 6.0, 1), (b - a, 7.0, 8.0, 1)]:
        p = Program(tree)
        t, _, n = p.cast(o, d)
        assert t[0] == near and n[0, 0] == -1.0
        t, _, n = p.cast(o, d, tmin=near + 0.1)            # from inside: the exit
        assert t[0] == far and n[0, 0] == far_normal


def test_difference_sees_the_subtracted_surface_turned_outward():
    # a box with a spherical bite: the ray down the axis enters the bite's surface
    tree = S.Box((-1, -1, -1), (1, 1, 1)) - S.Sphere((0, 0, 1), 0.5)
    t, _, n = Program(tree).cast(np.array([[0.0, 0, 5]]), np.array([[0.0, 0, -1]]))
    assert t[0] == pytest.approx(4.5) and n[0] == pytest.approx([0, 0, 1])
    t, _, n = Program(tree).cast(np.array([[0.3, 0, 5]]), np.array([[0.0, 0, -1]]))
    z = 1 - math.sqrt(0.25 - 0.09)
    assert t[0] == pytest.approx(5 - z)
    np.testing.assert_allclose(n[0], -np.array([0.3, 0, z - 1]) / 0.5, atol=1e-12)


def test_touching_intervals_join():
    tree = S.Box((0, 0, 0), (1, 1, 1)) | S.Box((1, 0, 0), (2, 1, 1))
    t, _, n = Program(tree).cast(np.array([[0.5, 0.5, 0.5]]), np.array([[1.0, 0, 0]]))
    assert t[0] == 1.5 and n[0, 0] == 1.0            # no face inside the solid at x = 1


#: (tree, exact volume, relative tolerance at resolution 256)
CASES = {
    "lens": (lambda: S.Sphere((0, 0, 0), 1.0) & S.Sphere((1, 0, 0), 1.0), lens_volume(1, 1),
             2e-3),
    "sphere minus corner": (lambda: S.Sphere((0, 0, 0), 1.0) - S.Box((0, 0, 0), (2, 2, 2)),
                            7 / 8 * 4 / 3 * math.pi, 2e-3),
    "box union box": (lambda: S.Box((0, 0, 0), (2, 2, 2)) | S.Box((1, 1, 1), (3, 3, 3)), 15.0,
                      1e-2),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_volume_by_ray_casting_against_exact(name):
    make, exact, tol = CASES[name]
    assert csg.volume(make(), resolution=256) == pytest.approx(exact, rel=tol)


def test_volume_converges_with_the_grid():
    tree = CASES["box union box"][0]()
    # a grid of 3 k cells per side holds the boxes' faces on cell edges: exact
    assert csg.volume(tree, resolution=96) == pytest.approx(15.0, rel=1e-12)
    errors = [abs(csg.volume(CASES["lens"][0](), resolution=n) - lens_volume(1, 1))
              for n in (32, 256)]
    assert errors[1] < errors[0] / 4


def tessellated(solid):
    """The same solid as a trimesh mesh: icospheres and boxes."""
    if isinstance(solid, S.Sphere):
        m = trimesh.creation.icosphere(subdivisions=6, radius=1.0)
        m.apply_transform(solid.matrix)
        return m
    if isinstance(solid, S.Box):
        return trimesh.creation.box(bounds=[solid.lo, solid.hi])
    op = {"union": trimesh.boolean.union, "intersection": trimesh.boolean.intersection,
          "difference": trimesh.boolean.difference}[solid.op]
    return op([tessellated(solid.left), tessellated(solid.right)], engine="manifold")


@pytest.mark.parametrize("name", sorted(CASES))
def test_volume_against_trimesh_boolean(name):
    make, exact, _ = CASES[name]
    peer = tessellated(make()).volume
    assert peer == pytest.approx(exact, rel=2e-3)          # the peer's own tessellation error
    assert csg.volume(make(), resolution=256) == pytest.approx(peer, rel=4e-3)


def test_mesh_solids_combine_like_trimesh():
    a = trimesh.creation.box(extents=(2, 2, 2))
    b = trimesh.creation.cylinder(radius=0.6, height=3, sections=48)
    peer = trimesh.boolean.difference([a, b], engine="manifold")
    ours = S.MeshSolid(sl.mesh.Mesh(a.vertices, a.faces)) - \
        S.MeshSolid(sl.mesh.Mesh(b.vertices, b.faces))
    assert csg.volume(ours, resolution=200) == pytest.approx(peer.volume, rel=3e-3)
    p = np.random.default_rng(1).uniform(-1.2, 1.2, (2000, 3))
    agree = ours.contains(p) == peer.contains(p)
    assert agree.mean() > 0.999


def test_mass_properties_of_a_box_and_of_a_sphere_minus_a_corner():
    box = S.Box((1, 2, 3), (2, 4, 6))         # 1 x 2 x 3
    mp = csg.mass_properties(box, resolution=128, density=2.0)
    m = 2.0 * 6
    assert mp.volume == pytest.approx(6.0) and mp.mass == pytest.approx(m)
    np.testing.assert_allclose(mp.center, [1.5, 3.0, 4.5])
    np.testing.assert_allclose(np.diag(mp.inertia), [m * (4 + 9) / 12, m * (1 + 9) / 12,
                                                     m * (1 + 4) / 12], rtol=1e-3)
    tree = CASES["sphere minus corner"][0]()
    mp = csg.mass_properties(tree, resolution=256)
    peer = tessellated(tree)
    # the missing octant moves the center by -(3/8 per octant's centroid) / 7 per axis
    np.testing.assert_allclose(mp.center, [-3 / 8 / 7] * 3, atol=2e-3)
    np.testing.assert_allclose(mp.center, peer.center_mass, atol=2e-3)
    np.testing.assert_allclose(mp.inertia, peer.moment_inertia, atol=5e-3)


def test_contains_follows_the_set_operations():
    a, b = S.Sphere((0, 0, 0), 1.0), S.Box((0, 0, 0), (2, 2, 2))
    p = np.random.default_rng(3).uniform(-1.5, 1.5, (4000, 3))
    ia = (p ** 2).sum(axis=1) <= 1
    ib = ((p >= 0) & (p <= 2)).all(axis=1)
    assert np.array_equal((a | b).contains(p), ia | ib)
    assert np.array_equal((a & b).contains(p), ia & ib)
    assert np.array_equal((a - b).contains(p), ia & ~ib)
    lo, hi = (a - b).bounds()
    assert lo.tolist() == [-1, -1, -1] and hi.tolist() == [1, 1, 1]


def test_bad_input():
    a = S.Sphere()
    with pytest.raises(ArgumentValueError, match="at least one solid"):
        csg.union()
    with pytest.raises(ArgumentValueError, match="op must be one of"):
        csg.CSG("xor", a, a)
    with pytest.raises(ArgumentTypeError, match="solid"):
        csg.difference(a, sl.mesh.cube())
    with pytest.raises(ArgumentTypeError, match="solid"):
        csg.volume(sl.mesh.cube())
    with pytest.raises(ArgumentValueError, match="unbounded"):
        csg.volume(S.Quadric.from_coefficients(a=1, b=1, j=-1))
    with pytest.raises(ArgumentValueError, match="resolution"):
        csg.volume(a, resolution=0)
    with pytest.raises(ArgumentValueError, match="density"):
        csg.mass_properties(a, density=float("nan"))
    # past the bounded interval lists: a clear error naming max_intervals
    slabs = csg.union(*[S.Box((2 * i, -1, -1), (2 * i + 1, 1, 1)) for i in range(40)])
    with pytest.raises(ArgumentValueError, match="max_intervals"):
        Program(slabs).cast(np.array([[-1.0, 0, 0]]), np.array([[1.0, 0, 0]]))
    # cells one unit wide along x: every cell center lies in a box or in a gap
    assert csg.volume(slabs, resolution=79, max_intervals=64) == pytest.approx(160.0)


def test_a_deep_tree_flattens_without_recursion():
    tree = S.Sphere((0, 0, 0), 1.0)
    for i in range(3000):
        tree = tree | S.Sphere((0, 0, 0), 0.5)
    assert Program(tree).program.shape == (6001, 2)


def random_tree(rng, depth):
    """A random CSG tree of spheres, boxes, cylinders and cones, ``depth`` levels."""
    if depth == 0:
        c = rng.uniform(-0.6, 0.6, 3)
        kind = rng.integers(4)
        if kind == 0:
            return S.Sphere(c, rng.uniform(0.3, 0.9))
        if kind == 1:
            return S.Box(c - rng.uniform(0.2, 0.8, 3), c + rng.uniform(0.2, 0.8, 3))
        axis = rng.normal(size=3)
        if kind == 2:
            return S.Cylinder(c, rng.uniform(0.2, 0.6), rng.uniform(0.5, 1.5), axis=axis)
        return S.Cone(c, rng.uniform(0.3, 0.8), rng.uniform(0.5, 1.5), axis=axis)
    op = ("union", "intersection", "difference")[rng.integers(3)]
    return csg.CSG(op, random_tree(rng, depth - 1), random_tree(rng, depth - 1))


@pytest.mark.parametrize("seed", range(6))
def test_first_surfaces_of_random_trees_agree_with_contains(seed):
    # contains() combines the primitives' own point tests with numpy's set operations,
    # independently of the kernels' interval rules: just before the first surface a ray
    # from outside is outside, just after it inside; a ray that meets nothing stays out
    rng = np.random.default_rng(seed)
    tree = random_tree(rng, 3) | random_tree(rng, 1)          # not empty
    o = rng.normal(size=(3000, 3))
    o = 4 * o / np.linalg.norm(o, axis=1, keepdims=True)            # outside every primitive
    d = rng.uniform(-0.8, 0.8, (3000, 3)) - o
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    t, code, _ = Program(tree).cast(o, d)
    hit = code >= 0
    assert hit.sum() > 50
    eps = 1e-7
    before = tree.contains(o[hit] + (t[hit] - eps)[:, None] * d[hit])
    after = tree.contains(o[hit] + (t[hit] + eps)[:, None] * d[hit])
    assert (~before).mean() > 0.995 and after.mean() > 0.995
    steps = np.linspace(0, 8, 161)
    missed = o[~hit][:, None, :] + steps[None, :, None] * d[~hit][:, None, :]
    assert not tree.contains(missed.reshape(-1, 3)).any()
