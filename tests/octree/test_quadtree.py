"""Quadtrees (H&B 10-17) against numpy and matplotlib's point-in-polygon test."""

import numpy as np
import pytest
from matplotlib.path import Path

import scanline as sl
from scanline.errors import ArgumentValueError
from scanline.octree import Quadtree


@pytest.mark.parametrize("shape", [(1, 1), (4, 4), (37, 50), (64, 13)])
def test_a_quadtree_of_an_image_reproduces_it(shape):
    rng = np.random.default_rng(sum(shape))
    image = rng.random(shape) < 0.5
    image[: shape[0] // 2, : shape[1] // 2] = True           # a block that merges
    tree = Quadtree.from_image(image)
    assert tree.to_image().shape == shape and (tree.to_image() == image).all()
    assert tree.area() == image.sum()


def test_cells_are_in_device_coordinates():
    image = np.zeros((8, 8), bool)
    image[4:, :4] = True                      # the bottom-left quadrant (image order)
    tree = Quadtree.from_image(image)
    x, y, size, full = tree.cells().T
    assert [(x0, y0, s) for x0, y0, s, f in zip(x, y, size, full) if f] == [(0, 0, 4)]
    assert tree.node_count == 5


@pytest.mark.parametrize("seed", range(3))
def test_set_operations_match_numpy(seed):
    rng = np.random.default_rng(seed)
    a = np.kron(rng.random((8, 8)) < 0.5, np.ones((4, 4), bool)) ^ (rng.random((32, 32)) < 0.1)
    b = np.kron(rng.random((4, 4)) < 0.5, np.ones((8, 8), bool))
    ta, tb = Quadtree.from_image(a), Quadtree.from_image(b)
    for tree, expected in ((ta | tb, a | b), (ta & tb, a & b), (ta - tb, a & ~b)):
        assert (tree.to_image() == expected).all()
        assert tree == Quadtree.from_image(expected)


def test_a_polygon_quadtree_holds_the_pixels_whose_centers_are_inside():
    points = [(3.3, 2.7), (58.6, 11.2), (40.1, 60.4), (20.2, 30.9), (6.5, 44.3)]
    tree = Quadtree.from_polygon(points, 6)
    y, x = np.mgrid[0:64, 0:64]
    inside = Path(points).contains_points(np.column_stack([x.ravel(), y.ravel()]))
    expected = inside.reshape(64, 64)[::-1]                   # image order
    assert (tree.to_image() == expected).all()


def test_drawn_with_its_cell_boundaries():
    image = np.zeros((4, 4), bool)
    image[2:, :2] = True                                       # full cell (0, 0) size 2
    fb = sl.FrameBuffer(16, 16, mode="L", background=255)
    Quadtree.from_image(image).draw(fb, color=0, boundary=128, scale=4)
    a = fb.to_array()[::-1]                                    # rows bottom-up
    assert a[2, 2] == 0 and a[5, 5] == 0                       # inside the full cell
    assert a[0, 0] == 128 and a[7, 3] == 128                   # its boundary
    assert a[10, 10] == 255 and a[8, 8] == 128                 # an empty cell, its corner


def test_bad_images_are_refused():
    with pytest.raises(ArgumentValueError, match="image"):
        Quadtree.from_image(np.zeros((2, 2, 2)))
    with pytest.raises(ArgumentValueError, match="image"):
        Quadtree.from_image(np.zeros((0, 3)))
    with pytest.raises(ArgumentValueError, match="depth"):
        Quadtree.from_polygon([(0, 0), (1, 0), (0, 1)], 0)
