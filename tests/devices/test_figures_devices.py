"""The display-device and display-method figures of the demo: each draws what its
caption states."""

import numpy as np
import pytest

from scanline.cli import demo
from scanline.gallery import devices as F
from scanline.display.color_crt import PENETRATION_COLORS


def test_the_gallery_shows_them():
    assert "devices" in demo.FIGURE_MODULES
    assert all(make in demo.all_figures() for make in F.FIGURES)


@pytest.mark.parametrize("make", F.FIGURES, ids=lambda f: f.__name__)
def test_figure_draws_a_picture(make):
    fig = make()
    assert fig.name.startswith("devices-") and fig.caption and "Hearn & Baker" in fig.source
    a = np.asarray(fig.image.convert("RGB"))
    assert a.shape[0] >= 150 and a.shape[1] >= 300
    assert len(np.unique(a.reshape(-1, 3), axis=0)) > 8


def test_beam_penetration_panel_holds_only_the_four_colors_and_black():
    strip = F._hues()
    out = F.penetration_colors(strip).to_array().reshape(-1, 3)
    allowed = {(0, 0, 0)} | set(PENETRATION_COLORS.values())
    assert {tuple(c) for c in out.tolist()} == allowed     # all four are reached


def test_cutaway_figure_caps_close_every_mesh():
    fig = F.figure_cutaway()
    assert fig.table.endswith("closed (every edge on two faces): True")
    assert "box    2 intersection loop(s)" in fig.table   # the square ring: outer and hole
