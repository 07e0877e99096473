"""The blobby figure and GIF of the demo: two separate blobs in the first frame, one
merged silhouette in the last."""

import numpy as np
from scipy import ndimage

from scanline.cli import demo
from scanline.gallery import blobby as F


def test_the_gallery_shows_it():
    assert "blobby" in demo.FIGURE_MODULES
    assert F.ANIMATIONS


def silhouettes(half):
    a = np.asarray(F.frame(half, 120, 80).to_array())
    covered = np.any(a != a[0, 0], axis=2)
    return ndimage.label(covered)[1]


def test_the_strip_goes_from_two_blobs_to_one():
    assert silhouettes(F.STRIP[0]) == 2
    assert silhouettes(F.STRIP[-1]) == 1
    fig = F.figure_blobby_merge()
    assert fig.name == "blobby-merge" and "10-7" in fig.source
    assert fig.image.width > 700


def test_the_animation_has_its_frames():
    name, animation = F.ANIMATIONS[0]()
    assert name == "blobby-merge" and len(animation) == 24
