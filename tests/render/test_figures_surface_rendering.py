"""The surface-rendering figures of the demo: each draws a picture with what its
caption states."""

import numpy as np
import pytest

from scanline.cli import demo
from scanline.gallery import surface_rendering as F


def test_the_gallery_shows_them():
    assert "surface_rendering" in demo.FIGURE_MODULES


@pytest.mark.parametrize("make", F.FIGURES, ids=lambda f: f.__name__)
def test_figure_draws_a_picture(make):
    fig = make()
    assert fig.name.startswith("surface-") and fig.caption and "14-" in fig.source
    a = np.asarray(fig.image.convert("RGB"))
    assert a.shape[0] >= 200 and a.shape[1] >= 240
    assert len(np.unique(a.reshape(-1, 3), axis=0)) > 50      # shaded, not flat paint


def test_affine_and_perspective_panels_differ_only_inside_the_quad():
    affine, correct = (np.asarray(p.convert("RGB")).astype(int)
                       for p in F.texture_perspective_panels(180, 120))
    background = np.all(affine == (0xe4, 0xe4, 0xe4), axis=2)
    assert (background == np.all(correct == (0xe4, 0xe4, 0xe4), axis=2)).mean() > 0.99
    differ = np.abs(affine - correct).sum(axis=2) > 60
    assert differ.any() and not (differ & background).any()


def test_the_cornell_box_shows_its_red_and_green_walls():
    image, solution = F.cornell_box_image(120, 3)
    a = np.asarray(image.convert("RGB")).astype(int)
    left, right = a[60, 8], a[60, 111]                       # red wall, green wall
    assert left[0] > left[1] + 30 and left[0] > left[2] + 30
    assert right[1] > right[0] + 15 and right[1] > right[2] + 15
    assert solution.converged
