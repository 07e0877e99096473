"""The two mappings of the display file, from :mod:`scanline.viewing`: world -> NDC
(the normalization transformation) and NDC -> device (the workstation
transformation, :func:`scanline.viewing.ndc_to_device`)."""

from typing import Any, Sequence

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .. import transform as tf
from .. import viewing
from ..clip.window import rectangle
from ..errors import ArgumentTypeError, ArgumentValueError


def ndc_rectangle(name: str, value: Any) -> tuple[float, float, float, float]:
    """A rectangle (xmin, ymin, xmax, ymax) inside the NDC unit square."""
    r = rectangle(value, name)
    if min(r) < 0.0 or max(r) > 1.0:
        raise ArgumentValueError(
            f"{name}={v._show(value)} must lie inside the unit square of normalized "
            "device coordinates, (0, 0, 1, 1)"
        )
    return r


def normalization(window: Any, viewport: Any, view_up: Sequence[float] = (0.0, 1.0),
                  keep_aspect: bool = False, aspect: float = 1.0) -> NDArray[np.float64]:
    """The world -> NDC matrix of a window, an NDC viewport and a view-up vector.

    The viewing frame has its origin at the window's center and its y axis along
    ``view_up`` (:func:`scanline.viewing.viewing_matrix`), so a tilted ``view_up``
    turns the window about its center.  With ``keep_aspect`` the window keeps its
    proportions on a device whose NDC unit square is ``aspect`` times as high as it
    is wide (the picture is centered in the viewport).
    """
    w = rectangle(window, "window")
    vp = ndc_rectangle("viewport", viewport)
    if not isinstance(keep_aspect, bool):
        raise ArgumentTypeError(f"keep_aspect must be True or False, got {v._show(keep_aspect)}")
    cx, cy = (w[0] + w[2]) / 2, (w[1] + w[3]) / 2
    hw, hh = (w[2] - w[0]) / 2, (w[3] - w[1]) / 2
    to_viewing = viewing.viewing_matrix((cx, cy), view_up)
    # Fit in device proportions: stretch NDC y by ``aspect``, fit, stretch back.
    stretched = (vp[0], vp[1] * aspect, vp[2], vp[3] * aspect)
    fit = viewing.window_to_viewport((-hw, -hh, hw, hh), stretched, keep_aspect=keep_aspect)
    return tf.compose(tf.scaling(1.0, 1.0 / aspect), fit, to_viewing)


def workstation(width: int, height: int) -> NDArray[np.float64]:
    """NDC -> device: (0, 0) to the center of pixel (0, 0), (1, 1) to the center of
    pixel (width - 1, height - 1)."""
    return viewing.ndc_to_device(width, height)


def aspect(width: int, height: int) -> float:
    """How much higher than wide the NDC unit square is on a width x height device."""
    return (v.positive_int("height", height, 2) - 1) / (v.positive_int("width", width, 2) - 1)


def device_rectangle(m: NDArray[np.float64], rect: Sequence[float]
                     ) -> tuple[float, float, float, float]:
    """The NDC rectangle ``rect`` mapped by the (axis-aligned) workstation matrix."""
    corners = tf.apply(m, np.array([[rect[0], rect[1]], [rect[2], rect[3]]]))
    return (float(corners[0, 0]), float(corners[0, 1]), float(corners[1, 0]),
            float(corners[1, 1]))
