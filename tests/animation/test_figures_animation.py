"""The animation figures of the demo gallery draw what their captions say."""

import numpy as np

import scanline as sl
from scanline.gallery import animation as fa


def test_every_figure_and_animation_renders():
    for make in fa.FIGURES:
        fig = make()
        assert fig.image.width > 100 and fig.image.height > 100
        assert fig.caption and fig.source
    for make in fa.ANIMATIONS:
        name, anim = make()
        assert len(anim) > 1 and anim.frame(0).size == anim.frame(len(anim) - 1).size


def test_spacing_table_lists_the_four_laws():
    table = fa.figure_spacing_laws().table
    assert [line.split(":")[0].strip() for line in table.splitlines()] == list(sl.animation.SPACINGS)
    constant = [float(x) for x in table.splitlines()[0].split(":")[1].split()]
    np.testing.assert_allclose(constant, np.arange(1, 10) / 10)


def test_arm_figure_reports_the_unreachable_target():
    table = fa.figure_two_link_arm().table
    assert table.count("NOT reached") == 1 and table.count(": reached") == 3
