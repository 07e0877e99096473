"""Blobby objects (Blinn 1982, Nishimura et al. 1985, Wyvill et al. 1986): a single
blob is the sphere whose radius solves b D(r / R) = T (solved here in closed form or
by bisection of the formula written here), two far blobs are two such spheres, two
near ones one merged surface; the surface is closed, counterclockwise from outside,
its normals outward; bad input is named."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentTypeError, ArgumentValueError
from scanline.mesh.blobby import density

trimesh = pytest.importorskip("trimesh")


def formula(kind, s):
    """The density functions as the papers write them, of s = r / R."""
    if kind == "blinn":
        return math.exp(-s * s)
    if kind == "metaball":
        if s <= 1 / 3:
            return 1 - 3 * s * s
        return 1.5 * (1 - s) ** 2 if s <= 1 else 0.0
    return 1 - 22 / 9 * s ** 2 + 17 / 9 * s ** 4 - 4 / 9 * s ** 6 if s <= 1 else 0.0


def radius_for(kind, R, T, b=1.0):
    """The r where b D(r / R) = T, by bisection on [0, R * 4] (D decreases)."""
    lo, hi = 0.0, 4.0
    for _ in range(200):
        mid = (lo + hi) / 2
        if b * formula(kind, mid) > T:
            lo = mid
        else:
            hi = mid
    return R * lo


def as_trimesh(mesh):
    tri = mesh.triangulated()
    return trimesh.Trimesh(tri.vertices, np.asarray(tri.faces), process=False)


@pytest.mark.parametrize("kind, T, closed_form", [
    ("blinn", 0.5, math.sqrt(math.log(2))),            # exp(-s²) = T
    ("blinn", 0.2, math.sqrt(math.log(5))),
    ("metaball", 0.5, 1 - math.sqrt(1 / 3)),           # (3/2)(1 - s)² = T, s > 1/3
    ("metaball", 0.7, math.sqrt(0.1)),                 # 1 - 3 s² = T, s <= 1/3
    ("soft", 0.5, 0.5),                                # Wyvill's D(1/2) = 1/2
    ("soft", 0.25, None),
])
def test_a_single_blob_is_the_sphere_of_the_formulas_radius(kind, T, closed_form):
    R, center = 1.5, np.array([0.3, -1.0, 2.0])
    r = radius_for(kind, R, T)
    if closed_form is not None:
        assert r == pytest.approx(R * closed_form, rel=1e-9)
    mesh = sl.mesh.blobby([center], R, threshold=T, resolution=64, kind=kind)
    distances = np.linalg.norm(mesh.vertices - center, axis=1)
    step = 2 * R / 63            # at most the grid spacing (the box is at least 2R wide)
    assert np.abs(distances - r).max() < 0.02 * step + 0.01 * r
    t = as_trimesh(mesh)
    assert t.is_watertight and t.is_winding_consistent
    assert t.volume == pytest.approx(4 / 3 * math.pi * r ** 3, rel=0.02)   # > 0: outward
    outward = np.einsum("ij,ij->i", mesh.normals, mesh.vertices - center)
    assert (outward > 0).all()


@pytest.mark.parametrize("kind", ["metaball", "soft", "blinn"])
def test_two_far_blobs_are_two_spheres_and_two_near_ones_merge(kind):
    R, T = 1.0, 0.3
    r = radius_for(kind, R, T)
    far = sl.mesh.blobby([(-5, 0, 0), (5, 0, 0)], R, threshold=T, resolution=160, kind=kind)
    parts = as_trimesh(far).split(only_watertight=True)
    assert len(parts) == 2
    for part in parts:
        c = np.array([5.0 if part.centroid[0] > 0 else -5.0, 0, 0])
        d = np.linalg.norm(part.vertices - c, axis=1)
        assert np.abs(d - r).max() < 0.05 * r
    near = sl.mesh.blobby([(-0.5, 0, 0), (0.5, 0, 0)], R, threshold=T, resolution=48,
                          kind=kind)
    assert len(as_trimesh(near).split(only_watertight=True)) == 1
    # every vertex lies where the two densities, as the papers write them, add to T
    total = [sum(formula(kind, math.dist(p, c) / R) for c in ((-0.5, 0, 0), (0.5, 0, 0)))
             for p in near.vertices.tolist()]
    np.testing.assert_allclose(total, T, rtol=0.05)


def test_density_adds_the_blobs_and_strengths():
    p = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])
    got = density(p, [(0, 0, 0), (2, 0, 0)], [1.0, 2.0], kind="soft", strengths=[1.0, 3.0])
    expected = [1 + 3 * formula("soft", 1.0), formula("soft", 1.0) + 3 * formula("soft", 0.5)]
    np.testing.assert_allclose(got, expected)


def test_a_negative_strength_carves():
    whole = sl.mesh.blobby([(0, 0, 0)], 1.0, kind="soft", resolution=32)
    carved = sl.mesh.blobby([(0, 0, 0), (0.5, 0, 0)], [1.0, 0.6], kind="soft",
                            strengths=[1.0, -1.0], resolution=32)
    assert as_trimesh(carved).volume < 0.9 * as_trimesh(whole).volume


@pytest.mark.parametrize("call, error, match", [
    (lambda: sl.mesh.blobby([(np.nan, 0, 0)], 1.0), ArgumentValueError, "centers must be finite"),
    (lambda: sl.mesh.blobby([(0, 0, 0)], np.nan), ArgumentValueError, "radii must be finite"),
    (lambda: sl.mesh.blobby([(0, 0, 0)], 1.0, strengths=[np.nan]), ArgumentValueError,
     "strengths must be finite"),
    (lambda: sl.mesh.blobby([(0, 0, 0)], 1.0, threshold=np.nan), ArgumentValueError,
     "threshold must be a finite"),
    (lambda: sl.mesh.blobby([(0, 0, 0)], 1.0, threshold=0), ArgumentValueError,
     "threshold must be > 0"),
    (lambda: sl.mesh.blobby([(0, 0, 0)], 1.0, threshold=2.0), ArgumentValueError,
     "the object is empty"),
    (lambda: sl.mesh.blobby([(0, 0, 0)], [1.0, 2.0]), ArgumentValueError, "one per center"),
    (lambda: sl.mesh.blobby([(0, 0, 0)], -1.0), ArgumentValueError, "radius > 0"),
    (lambda: sl.mesh.blobby([], 1.0), ArgumentValueError, "at least one center"),
    (lambda: sl.mesh.blobby([(0, 0, 0)], 1.0, kind="gauss"), ArgumentValueError,
     "kind must be one of"),
    (lambda: sl.mesh.blobby([(0, 0, 0)], 1.0, resolution=4), ArgumentValueError,
     "resolution must be >= 8"),
    (lambda: sl.mesh.blobby([(0, 0, 0)], 1.0, resolution=5000), ArgumentValueError,
     "limit of 1024"),
    (lambda: sl.mesh.blobby([(0, 0, 0)], 1.0, resolution=64.0), ArgumentTypeError,
     "resolution must be an integer"),
    (lambda: sl.mesh.blobby([(1e308, 0, 0), (-1e308, 0, 0)], 1e308), ArgumentValueError,
     "beyond float64"),
    (lambda: sl.mesh.blobby([(0, 0, 0)] * 2, 1.0, strengths=1e308, threshold=1e300),
     ArgumentValueError, "strengths: the total density overflows"),
])
def test_bad_input_is_named(call, error, match):
    with np.errstate(all="raise"):
        with pytest.raises(error, match=match):
            call()


def test_the_grid_is_refused_before_it_is_allocated(monkeypatch):
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "1M")
    with pytest.raises(ArgumentValueError, match="resolution: a density grid"):
        sl.mesh.blobby([(0, 0, 0)], 1.0, resolution=200)
