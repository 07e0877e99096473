"""The CSG figure of the demo: the classic tree drawn with what its caption states."""

import numpy as np

from scanline.cli import demo
from scanline.gallery import csg as F


def test_the_gallery_shows_it():
    assert "csg" in demo.FIGURE_MODULES


def test_figure_draws_the_tree_and_its_nodes():
    fig = F.figure_csg()
    assert fig.name == "csg-tree" and "10-16" in fig.source and "Roth" in fig.source
    a = np.asarray(fig.image.convert("RGB")).astype(int)
    assert a.shape[0] >= 300 and a.shape[1] >= 600
    assert len(np.unique(a.reshape(-1, 3), axis=0)) > 200        # shaded, not flat paint


def test_the_tree_has_the_classic_shape():
    tree, nodes = F.classic_tree()
    assert [n[0] for n in nodes[2]] == ["\u2229", "\u222a"]
    assert len(nodes[2][1][2]) == 3
    # the center is bored through, the box's corners are cut by the sphere
    assert tree.contains([(0, 0, 0), (0.9, 0.9, 0.9), (0.9, 0.9, 0.0)]).tolist() == \
        [False, False, True]
