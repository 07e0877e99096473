"""The octree figures of the demo: each draws what its caption states."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.cli import demo
from scanline.gallery import octree as F


def test_the_gallery_shows_them():
    assert "octree" in demo.FIGURE_MODULES


def test_the_figure_draws_a_quadtree_and_a_rendered_octree():
    fig = F.figure_octrees()
    assert fig.name.startswith("octree-") and "10-17" in fig.source and "13-10" in fig.source
    a = np.asarray(fig.image.convert("RGB"))
    assert a.shape[0] >= 256 and a.shape[1] >= 500
    assert len(np.unique(a.reshape(-1, 3), axis=0)) > 5


def test_the_quadtree_panel_outlines_leaves_around_the_star():
    a = np.asarray(F.quadtree_panel(scale=4).convert("RGB")).astype(int)
    blue = np.all(a == (0x2b, 0x4c, 0x8c), axis=2)
    gray = np.all(a == (0xb0, 0xb0, 0xb0), axis=2)
    assert blue[130, 130] and gray[128, 128]         # inside the star; a leaf corner
    # the star (area about 1100 of 4096 pixels) less the outlines over it
    assert 0.12 < blue.mean() < 0.3


def test_the_captions_volume_is_the_solids_by_monte_carlo():
    rng = np.random.default_rng(0)
    p = rng.uniform(-1, 1, size=(400_000, 3))
    inside = ((np.linalg.norm(p, axis=1) <= 1) & ~(p >= 0).all(axis=1)
              & (np.hypot(p[:, 0], p[:, 1]) > 0.35))
    assert F._exact_volume() == pytest.approx(8 * inside.mean(), rel=0.01)
    assert abs(F.csg_octree().volume() - F._exact_volume()) < 0.05 * F._exact_volume()
    assert math.isfinite(sl.octree.Octree.from_solid(sl.solids.Sphere(), 2).volume())
