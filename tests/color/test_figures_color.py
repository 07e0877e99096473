"""The color figures of ``scanline demo`` render, and say what they show."""

import pytest

from scanline.cli import demo
from scanline.gallery import color as figures_color


def test_registered_in_the_gallery():
    assert "color" in demo.FIGURE_MODULES
    assert all(make in demo.all_figures() for make in figures_color.FIGURES)


@pytest.mark.parametrize("make", figures_color.FIGURES)
def test_each_figure_renders(make):
    fig = make()
    assert fig.name and fig.title and fig.caption and fig.source.startswith("Notes")
    assert fig.image.width > 200 and fig.image.height > 100
    # a figure of dithered pixels has black, white and grays or colors in it
    assert len(fig.image.getcolors(1 << 20)) > 2
