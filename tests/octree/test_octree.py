"""Octrees (H&B 10-17) against independent references: closed-form volumes, trimesh's
inside test and mesh measures, numpy's boolean operations on the voxel arrays."""

import math

import numpy as np
import pytest
import trimesh

import scanline as sl
from scanline.errors import ArgumentTypeError, ArgumentValueError, MemoryBudgetError
from scanline.octree import Octree


def shell(r, width):
    """The volume of the shell of points within ``width`` of a sphere of radius r."""
    return 4 / 3 * math.pi * ((r + width) ** 3 - max(r - width, 0.0) ** 3)


@pytest.mark.parametrize("depth", [3, 4, 5, 6, 7])
def test_sphere_volume_converges_within_the_boundary_cells(depth):
    # Only cells the surface passes through can be decided wrongly: a cell whose nine
    # samples are all inside a sphere lies inside it (the sphere is convex), and one
    # whose samples are all outside misses it here, so the error is at most the
    # volume of the finest cells that meet the surface.  Such a cell (side h, diagonal
    # sqrt(3) h) lies within sqrt(3) h of the surface: inside the shell of that width.
    r = 1.0
    tree = Octree.from_solid(sl.solids.Sphere(radius=r), depth)
    h = 2 * r / 2 ** depth
    exact = 4 / 3 * math.pi * r ** 3
    assert tree.cell_size == pytest.approx(h)
    assert abs(tree.volume() - exact) <= shell(r, math.sqrt(3) * h)


def test_sphere_volume_error_shrinks_with_depth():
    exact = 4 / 3 * math.pi
    errors = [abs(Octree.from_solid(sl.solids.Sphere(radius=1.0), d).volume() - exact)
              for d in (2, 4, 6, 8)]
    assert errors == sorted(errors, reverse=True) and errors[-1] < 1e-3 * exact


def test_full_voxels_of_a_sphere_have_their_centers_inside():
    # a voxel is full because its center was sampled inside at the finest level, or
    # because a coarser cell's nine samples were all inside: then, the sphere being
    # convex, the whole cell and every center in it is inside
    tree = Octree.from_solid(sl.solids.Sphere(radius=1.0), 5)
    vox = tree.to_voxels()
    index = np.argwhere(vox)
    assert len(index) and (np.linalg.norm(centers(tree, index), axis=1) < 1.0).all()


def test_a_csg_tree_and_a_stand_in_solid_become_octrees():
    box = sl.solids.Box((-1, -1, -1), (1, 1, 1))
    hole = sl.csg.difference(box, sl.solids.Sphere(radius=0.8))
    tree = Octree.from_solid(hole, 6)
    exact = 8 - 4 / 3 * math.pi * 0.8 ** 3
    assert abs(tree.volume() - exact) <= shell(0.8, math.sqrt(3) * tree.cell_size)

    class Slab:                                    # any object with contains and bounds
        def contains(self, points):
            return np.abs(points[:, 2]) <= 0.25

        def bounds(self):
            return (-1, -1, -1), (1, 1, 1)

    slab = Octree.from_solid(Slab(), 3)
    assert slab.volume() == pytest.approx(2 * 2 * 0.5)
    fine = slab.to_voxels().repeat(8, 0).repeat(8, 1).repeat(8, 2)   # depth 3 -> 6
    both = slab & tree
    assert both.depth == 6 and (both.to_voxels() == (tree.to_voxels() & fine)).all()


def centers(tree, index):
    return tree.origin + (index + 0.5) * tree.cell_size


@pytest.mark.parametrize("make", [lambda: trimesh.creation.icosphere(3),
                                  lambda: trimesh.creation.torus(1.0, 0.35),
                                  lambda: trimesh.creation.annulus(0.4, 1.0, 0.8)])
def test_voxelization_agrees_with_trimesh_contains(make):
    tm = make()
    tree = Octree.from_mesh(sl.mesh.Mesh(tm.vertices, tm.faces), 6)
    vox = tree.to_voxels()
    rng = np.random.default_rng(5)
    index = rng.integers(0, 64, size=(4000, 3))
    inside = tm.contains(centers(tree, index))
    assert inside.any() and (~inside).any()
    assert (vox[tuple(index.T)] == inside).all()


def test_voxelized_volume_approaches_the_mesh_volume():
    tm = trimesh.creation.torus(1.0, 0.35)
    tree = Octree.from_mesh(tm, 7)                  # a trimesh mesh is taken as it is
    assert tree.volume() == pytest.approx(tm.volume, rel=0.02)


def random_blobs(rng, n, count):
    """A voxel array with blocks of several sizes (so that the trees have leaves at
    several levels)."""
    v = np.zeros((n, n, n), bool)
    for _ in range(count):
        s = int(rng.choice([1, 2, 4, 8]))
        x, y, z = rng.integers(0, n - s + 1, size=3) // s * s
        v[x:x + s, y:y + s, z:z + s] = rng.random() < 0.7
    return v


@pytest.mark.parametrize("seed", range(4))
def test_set_operations_match_numpy_on_the_voxels(seed):
    rng = np.random.default_rng(seed)
    a, b = random_blobs(rng, 16, 60), random_blobs(rng, 16, 60)
    ta, tb = Octree.from_voxels(a), Octree.from_voxels(b)
    for tree, expected in ((ta | tb, a | b), (ta & tb, a & b), (ta - tb, a & ~b),
                           (ta.union(tb), a | b)):
        assert (tree.to_voxels() == expected).all()
        assert tree == Octree.from_voxels(expected)            # canonical: merged
        assert tree.volume() == expected.sum()


def test_voxels_round_trip_and_merge():
    rng = np.random.default_rng(3)
    a = rng.random((5, 9, 3)) < 0.4                            # padded to 16 a side
    tree = Octree.from_voxels(a, origin=(1, 2, 3), voxel_size=0.5)
    assert tree.depth == 4 and tree.side == 8.0
    assert (tree.to_voxels()[:5, :9, :3] == a).all() and tree.to_voxels().sum() == a.sum()
    full = Octree.from_voxels(np.ones((8, 8, 8)))
    assert full.node_count == 1 and full.volume() == 512
    assert (Octree.from_voxels(np.ones((8, 8, 8))) - full).node_count == 1


def test_boundary_mesh_is_closed_and_bounds_the_volume():
    rng = np.random.default_rng(7)
    tree = Octree.from_voxels(random_blobs(rng, 16, 40), voxel_size=0.25)
    mesh = tree.to_mesh()
    tm = trimesh.Trimesh(mesh.vertices, mesh.triangulated().face_indices.reshape(-1, 3),
                         process=False)
    tm.merge_vertices()
    # T-junctions (a large face beside small ones) leave the mesh closed as a surface
    # but not edge-manifold, so its volume is measured, not its edges
    assert tm.volume == pytest.approx(tree.volume())
    vox = tree.to_voxels()
    faces = sum(np.count_nonzero(np.diff(np.pad(vox, 1).astype(int), axis=a)) for a in range(3))
    assert tm.area == pytest.approx(faces * tree.cell_size ** 2)


def test_front_to_back_order_follows_the_distances_along_the_view():
    rng = np.random.default_rng(11)
    tree = Octree.from_voxels(rng.random((8, 8, 8)) < 0.5)
    for direction in ([1.0, 0.3, -0.5], [-0.2, -1.0, 0.7], [0.0, 0.0, 1.0]):
        d = np.array(direction)
        lo, side, _ = tree.cells(direction=d)
        # every pair of face-adjacent leaves: the one nearer the viewer (its center
        # lower along the direction) comes first
        center = lo + side[:, None] / 2
        position = {tuple(np.round(c, 6)): i for i, c in enumerate(center)}
        checked = 0
        for i, (c, s) in enumerate(zip(center, side)):
            for axis in range(3):
                step = np.zeros(3)
                step[axis] = s
                j = position.get(tuple(np.round(c + step, 6)))
                if j is not None and side[j] == s and d[axis] != 0:
                    nearer = i if c @ d < (c + step) @ d else j
                    assert nearer == min(i, j)
                    checked += 1
        assert checked > 50


@pytest.mark.parametrize("depth", [0, -1, 21, 2.5, True, "3"])
def test_bad_depths_are_refused(depth):
    with pytest.raises(ArgumentValueError, match="depth"):
        Octree.from_solid(sl.solids.Sphere(), depth)


def test_depth_beyond_the_memory_budget_is_refused_up_front(monkeypatch):
    # a full tree of depth d has (8**(d + 1) - 1) / 7 nodes at 64 bytes each: depth 6
    # takes 19 MB, depth 7 153 MB
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "64M")
    with pytest.raises(MemoryBudgetError, match=r"depth: .*use a depth of 6 or less"):
        Octree.from_solid(sl.solids.Sphere(), 9)
    assert Octree.from_solid(sl.solids.Sphere(), 6).depth == 6


def test_bad_solids_meshes_and_regions_are_refused():
    class Unbounded:
        def contains(self, points):
            return np.ones(len(points), bool)

        def bounds(self):
            return (np.nan, 0, 0), (1, 1, 1)

    with pytest.raises(ArgumentValueError, match="finite"):
        Octree.from_solid(Unbounded(), 3)
    with pytest.raises(ArgumentTypeError, match="contains"):
        Octree.from_solid(np.zeros(3), 3)
    with pytest.raises(ArgumentValueError, match="bounds"):
        Octree.from_solid(sl.solids.Sphere(), 3, bounds=((0, 0, 0), (np.inf, 1, 1)))
    open_box = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)],
                            [(0, 2, 1), (0, 1, 3), (0, 3, 2)])
    with pytest.raises(ArgumentValueError, match="not closed"):
        Octree.from_mesh(open_box, 3)
    with pytest.raises(ArgumentValueError, match="3-D array"):
        Octree.from_voxels(np.zeros((4, 4)))
    with pytest.raises(ArgumentValueError, match="NaN"):
        Octree.from_voxels(np.full((2, 2, 2), np.nan))
    a = Octree.from_voxels(np.ones((4, 4, 4)))
    with pytest.raises(ArgumentValueError, match="region"):
        a | Octree.from_voxels(np.ones((4, 4, 4)), voxel_size=2.0)
    with pytest.raises(ArgumentTypeError, match="Octree"):
        a & sl.octree.Quadtree.from_image(np.ones((4, 4)))


@pytest.mark.parametrize("seed", range(20))
def test_malformed_trees_never_index_outside_their_arrays(seed, monkeypatch):
    # the kernels' Python twins raise IndexError where a compiled kernel would read or
    # write outside an array: run them on trees made by hand with children pointing
    # anywhere (backwards, past the end, to -5), kinds beyond the three
    from scanline._kernels import _jit

    monkeypatch.setattr(_jit, "COMPILE", "never")
    rng = np.random.default_rng(seed)
    n = int(rng.integers(1, 40))
    kind = rng.integers(0, 4, size=n).astype(np.int8)
    child = rng.integers(-5, n + 5, size=n)
    tree = Octree(kind, child, int(rng.integers(1, 4)), np.zeros(3), 1.0)
    good = Octree.from_voxels(rng.random((8, 8, 8)) < 0.5)
    good = Octree(good.kind, good.child, tree.depth, np.zeros(3), 1.0)
    for result in (tree | good, tree & good, tree - good, good - tree):
        assert result.kind[0] in (0, 1, 2)
    tree.volume()
    tree.to_voxels()
    try:
        tree.to_mesh()
    except ArgumentValueError as error:
        assert "no faces" in str(error)
    tree.cells(direction=(1, 2, 3))


def test_an_empty_octree_has_no_boundary_mesh():
    with pytest.raises(ArgumentValueError, match="no faces"):
        Octree.from_voxels(np.zeros((4, 4, 4))).to_mesh()


def test_kind_and_child_must_match():
    with pytest.raises(ArgumentValueError, match="one length"):
        Octree(np.zeros(3, np.int8), np.zeros(2), 2, np.zeros(3), 1.0)
