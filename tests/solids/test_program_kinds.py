"""A Solid subclass of the user's own (contains, bounds, volume) is not something the
ray kernels can cast rays at: rendering it by ray casting is a named error, not a bare
AttributeError from deep inside the program's construction (found by mypy --strict,
issue 32 item 3: Program called ``row()``, which only the primitives have)."""

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentTypeError
from scanline.solids.program import Program


class Ball(sl.solids.Solid):
    material = sl.lighting.Material()

    def contains(self, points):
        return (np.asarray(points, np.float64) ** 2).sum(axis=-1) <= 1.0

    def bounds(self):
        return np.full(3, -1.0), np.full(3, 1.0)

    def volume(self):
        return 4.0 / 3.0 * np.pi


def test_a_solid_of_ones_own_is_refused_by_name():
    with pytest.raises(ArgumentTypeError, match="Ball"):
        Program(Ball())


@pytest.mark.parametrize("solids", [Ball(), Ball() | sl.solids.Sphere()])
def test_rendering_it_by_ray_casting_names_it(solids):
    fb = sl.FrameBuffer(8, 8)
    cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
    with pytest.raises(ArgumentTypeError, match="MeshSolid"):
        sl.render(fb, solids, cam, method="ray-casting")


def test_the_primitives_and_mesh_solids_still_make_a_program():
    p = Program(sl.solids.Sphere() | sl.solids.MeshSolid(sl.mesh.cube(1.0)))
    assert len(p.primitives) == 2
