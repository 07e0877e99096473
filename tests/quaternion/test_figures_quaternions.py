"""The quaternion figure of the demo: Euler-angle and slerp in-betweens differ between
the keys and agree at them; slerp's in-betweens are evenly spaced in angle."""

import math

import numpy as np

from scanline.cli import demo
from scanline.gallery import quaternions as F


def test_the_gallery_shows_it():
    assert "quaternions" in demo.FIGURE_MODULES


def test_figure_draws_a_picture():
    fig = F.figure_euler_and_slerp()
    assert fig.name == "quaternion-inbetweens" and "11-2" in fig.source
    a = np.asarray(fig.image.convert("RGB"))
    assert a.shape[0] >= 200 and a.shape[1] >= 800
    assert len(np.unique(a.reshape(-1, 3), axis=0)) > 50


def test_inbetweens_agree_at_the_keys_and_differ_between():
    euler, slerp = F.orientations()
    for k in (0, -1):
        np.testing.assert_allclose(euler[k].matrix(), slerp[k].matrix(), atol=1e-12)
    gaps = [math.degrees((euler[k].conjugate() * slerp[k]).angle) for k in range(1, 9)]
    assert max(gaps) > 10
    steps = [(slerp[k].conjugate() * slerp[k + 1]).angle for k in range(len(slerp) - 1)]
    np.testing.assert_allclose(steps, steps[0], rtol=1e-9)        # a constant rate
    euler_steps = [(euler[k].conjugate() * euler[k + 1]).angle for k in range(len(euler) - 1)]
    assert max(euler_steps) > 1.2 * min(euler_steps)
