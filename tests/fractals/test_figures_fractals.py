"""The fractal figures of the demo: each draws a picture with what its caption
states."""

import numpy as np
import pytest

from scanline.cli import demo
from scanline.gallery import fractals as F


def test_the_gallery_shows_them():
    assert "fractals" in demo.FIGURE_MODULES


@pytest.mark.parametrize("make", F.FIGURES, ids=lambda f: f.__name__)
def test_figure_draws_a_picture(make):
    fig = make()
    assert fig.name.startswith("fractal-") and fig.caption and "10-18" in fig.source
    a = np.asarray(fig.image.convert("RGB"))
    assert a.shape[0] >= 200 and a.shape[1] >= 400
    assert len(np.unique(a.reshape(-1, 3), axis=0)) > 8


def test_the_escape_time_panels_show_the_set_in_black_at_its_known_points():
    mandelbrot, _ = F.escape_time_panels(120, 80)
    a = np.asarray(mandelbrot.convert("RGB"))
    # center -0.6, span 3.2: c = 0 at column (0 + 0.6) / 3.2 * 120 + 60 - 0.5, row 40
    assert (a[40, int(0.6 / 3.2 * 120 + 60)] == 0).all()
    assert (a[40, 2] != 0).any()                     # c = -2.2: escapes at once
