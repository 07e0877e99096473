"""Hardening the second half: the mesh generators and the depth buffer check their
memory against the budget (scanline.budget) before allocating, naming the argument
that sets the size; sizes within the budget keep working and give the same meshes.

Before the fix ``rotational_sweep(steps=10**9)`` and the quadrics at huge resolutions
allocated without limit (minutes, gigabytes) and ``DepthBuffer(100000, 100000)``
raised a raw MemoryError.  Each refused call runs under a deadline so that a
regression fails instead of hanging.
"""

import contextlib
import math
import signal

import numpy as np
import pytest

import scanline as sl
from scanline.errors import MemoryBudgetError


class Hang(BaseException):
    """A call past its deadline: a BaseException, so that no ``except Exception``
    in the code under test can turn the hang into an ordinary error."""


@contextlib.contextmanager
def deadline(seconds=20):
    def alarm(signum, frame):
        raise Hang(f"the call took more than {seconds} s")

    old = signal.signal(signal.SIGALRM, alarm)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


@pytest.fixture
def budget(monkeypatch):
    """A 64 MiB budget: big enough for every ordinary mesh, far too small for these."""
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "64M")


BEZIER = sl.curves.Bezier([(1, 0), (2, 1), (1, 2)])
PATCH = sl.curves.BezierSurface(np.stack(list(np.meshgrid(np.arange(4.0), np.arange(4.0),
                                                          indexing="ij"))
                                         + [np.ones((4, 4))], axis=-1))

HUGE = {
    "rotational_sweep steps": (lambda: sl.mesh.rotational_sweep([(1, 0), (1, 1)], steps=10**9),
                               "steps"),
    "rotational_sweep axis": (lambda: sl.mesh.rotational_sweep(
        [(1, 0), (1, 1)], axis=((0, 0, 0), (0, 1, 1)), steps=10**7), "steps"),
    "sweep": (lambda: sl.mesh.sweep([(1, 0), (1, 1)], steps=10**8), "steps"),
    "sweep of a curve": (lambda: sl.mesh.rotational_sweep(BEZIER, samples=10**9), "samples"),
    "translational_sweep samples": (lambda: sl.mesh.translational_sweep(
        BEZIER, (0, 0, 1), samples=10**9), "samples"),
    "translational_sweep profile": (lambda: sl.mesh.translational_sweep(
        np.random.default_rng(0).random((400_000, 2)), (0, 0, 1)), "profile"),
    "sphere": (lambda: sl.mesh.sphere(resolution=(4096, 4000)), "resolution"),
    "ellipsoid": (lambda: sl.mesh.ellipsoid(1, 2, 3, resolution=4000), "resolution"),
    "superellipsoid": (lambda: sl.mesh.superellipsoid(0.5, 2, resolution=(2000, 2000)),
                       "resolution"),
    "superquadric": (lambda: sl.mesh.superquadric("toroid", 0.5, 2,
                                                  resolution=(4000, 4000)), "resolution"),
    "torus": (lambda: sl.mesh.torus(2, 0.5, resolution=(4000, 4000)), "resolution"),
    "supertoroid": (lambda: sl.mesh.supertoroid(resolution=(1000, 1000)), "resolution"),
    "from_surface": (lambda: sl.mesh.from_surface(PATCH, 10**5, 10**5), "nu x nv"),
    "teapot": (lambda: sl.mesh.teapot(10**4), "n"),
    "depth buffer": (lambda: sl.DepthBuffer(100_000, 100_000), "width x height"),
}


@pytest.mark.parametrize("name", sorted(HUGE))
def test_huge_sizes_are_refused_by_the_budget_naming_the_argument(budget, name):
    make, argument = HUGE[name]
    with deadline(), pytest.raises(MemoryBudgetError) as info:
        make()
    message = str(info.value)
    assert message.startswith(f"{argument}: "), message
    assert "SCANLINE_MEMORY_LIMIT" in message


def test_the_depth_buffer_is_refused_under_the_default_budget_too(monkeypatch):
    # 100000 x 100000 x 8 bytes = 80 GB: more than half of any test machine
    monkeypatch.delenv("SCANLINE_MEMORY_LIMIT", raising=False)
    if 8 * 10**10 <= sl.budget.limit():      # pragma: no cover - a machine of 160+ GB
        pytest.skip("this machine's default budget holds 80 GB")
    with pytest.raises(MemoryBudgetError, match="width x height"):
        sl.DepthBuffer(100_000, 100_000)


def test_sizes_within_the_budget_still_work(budget):
    assert len(sl.mesh.sphere(resolution=64)) == 64 * 32
    assert len(sl.mesh.torus(resolution=(32, 16))) == 32 * 16
    assert len(sl.mesh.rotational_sweep([(1, 0), (1, 1)], steps=1000)) == 1000
    assert sl.DepthBuffer(1000, 1000).array.shape == (1000, 1000)
    assert len(sl.mesh.teapot(4)) > 0


@pytest.mark.parametrize("make", [lambda: sl.mesh.sphere(resolution=(48, 24)),
                                  lambda: sl.mesh.torus(resolution=(40, 20)),
                                  lambda: sl.mesh.rotational_sweep([(0, 0), (1, 0), (1, 1),
                                                                    (0, 2)], steps=300),
                                  lambda: sl.mesh.translational_sweep(
                                      np.random.default_rng(1).random((500, 2)), (0, 0, 1),
                                      closed=True)])
def test_the_estimate_bounds_what_a_generator_allocates(make):
    import tracemalloc

    from scanline.mesh.mesh import mesh_bytes

    tracemalloc.start()
    try:
        mesh = make()
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak <= mesh_bytes(len(mesh.vertices), len(mesh), len(mesh.face_indices))


def _sweep_by_hand(profile, axis, angle, steps):
    """The rotational sweep's vertices copy by copy, with transform3d, as the sweep was
    first written (on-axis points once, in the first copy)."""
    p = np.hstack([np.asarray(profile, float), np.zeros((len(profile), 1))])
    full = math.isclose(angle, 2 * math.pi)
    copies = steps if full else steps + 1
    on_axis = None
    verts = []
    for k in range(copies):
        moved = sl.transform3d.apply(sl.transform3d.rotation(angle * k / steps, axis), p)
        if on_axis is None:
            on_axis = np.array([np.allclose(moved[i], sl.transform3d.apply(
                sl.transform3d.rotation(1.0, axis), moved[i])) for i in range(len(p))])
        verts.extend(moved[i] for i in range(len(p)) if k == 0 or not on_axis[i])
    return np.array(verts)


@pytest.mark.parametrize("axis", ["x", "y", "z", ((0, 0, 0), (0, 1, 1)),
                                  ((1, -1, 0.5), (0.3, 2, 1))])
@pytest.mark.parametrize("angle", [2 * math.pi, 1.25])
def test_the_vectorized_rotational_sweep_gives_the_same_vertices(axis, angle):
    profile = [(0.0, 0.0), (1.0, 0.25), (1.5, 2.0), (0.0, 3.0)]
    mesh = sl.mesh.rotational_sweep(profile, axis=axis, angle=angle, steps=7)
    expected = _sweep_by_hand(profile, axis, angle, 7)
    np.testing.assert_array_equal(mesh.vertices, expected)
