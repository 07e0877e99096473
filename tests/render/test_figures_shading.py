"""The shading figures of the demo: each draws something, with the facts its caption
states."""

import numpy as np
import pytest

from scanline.gallery import shading as F


@pytest.mark.parametrize("make", F.FIGURES, ids=lambda f: f.__name__)
def test_figure_draws_a_picture(make):
    fig = make()
    assert fig.name.startswith("shading-") and fig.caption and fig.source
    a = np.asarray(fig.image.convert("RGB"))
    assert a.shape[0] > 150 and a.shape[1] > 400
    assert len(np.unique(a.reshape(-1, 3), axis=0)) > 50      # shaded, not flat paint


def test_back_face_figure_counts_add_up():
    table = F.figure_back_faces().table
    numbers = dict(part.split(": ") for part in table.split(", "))
    total, culled, kept = (int(numbers[k]) for k in ("triangles", "culled", "kept"))
    assert total == culled + kept and 0.3 * total < culled < 0.7 * total
