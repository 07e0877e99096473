"""The two mappings of the display file: world -> NDC (normalization) and NDC ->
device (workstation transformation)."""

import math

import numpy as np

from .. import _validate as v
from .. import transform as tf
from ..errors import ArgumentTypeError, ArgumentValueError


def rectangle(name, value):
    """(xmin, ymin, xmax, ymax) as floats, with xmin < xmax and ymin < ymax."""
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or len(value) != 4:
        raise ArgumentTypeError(
            f"{name} must be a rectangle (xmin, ymin, xmax, ymax), got {v._show(value)}"
        )
    r = tuple(v.number(f"{name}[{i}]", x) for i, x in enumerate(value))
    if not (r[0] < r[2] and r[1] < r[3]):
        raise ArgumentValueError(
            f"{name}={v._show(value)} is degenerate: it needs xmin < xmax and ymin < ymax"
        )
    return r


def ndc_rectangle(name, value):
    """A rectangle inside the NDC unit square."""
    r = rectangle(name, value)
    if min(r) < 0.0 or max(r) > 1.0:
        raise ArgumentValueError(
            f"{name}={v._show(value)} must lie inside the unit square of normalized "
            "device coordinates, (0, 0, 1, 1)"
        )
    return r


def window_to_viewport(window, viewport):
    """The matrix T(viewport corner) · S(sx, sy) · T(-window corner)."""
    wx0, wy0, wx1, wy1 = window
    vx0, vy0, vx1, vy1 = viewport
    return tf.compose(tf.translation(vx0, vy0),
                      tf.scaling((vx1 - vx0) / (wx1 - wx0), (vy1 - vy0) / (wy1 - wy0)),
                      tf.translation(-wx0, -wy0))


def normalization(window, viewport, view_up=(0.0, 1.0), keep_aspect=False):
    """The world -> NDC matrix of a window, an NDC viewport and a view-up vector.

    The viewing frame has its origin at the window's center and its y axis along
    ``view_up``; the window is measured in that frame (so a tilted ``view_up`` turns
    the window about its center).  With ``keep_aspect`` the viewport shrinks to the
    window's aspect ratio, centered.
    """
    w = rectangle("window", window)
    vp = ndc_rectangle("viewport", viewport)
    ux, uy = (v.number(f"view_up[{i}]", c) for i, c in enumerate(_pair("view_up", view_up)))
    if ux == 0.0 and uy == 0.0:
        raise ArgumentValueError("view_up must not be (0, 0): it gives the up direction")
    if not isinstance(keep_aspect, bool):
        raise ArgumentTypeError(f"keep_aspect must be True or False, got {v._show(keep_aspect)}")
    cx, cy = (w[0] + w[2]) / 2, (w[1] + w[3]) / 2
    # world -> viewing frame: move the window center to the origin, then turn view_up
    # onto +y (a rotation by -(angle of view_up - 90 degrees)).
    turn = tf.rotation(math.pi / 2 - math.atan2(uy, ux))
    viewing = tf.compose(tf.translation(cx, cy), turn, tf.translation(-cx, -cy))
    if keep_aspect:
        vp = _fitted(w, vp)
    return tf.compose(window_to_viewport(w, vp), viewing)


def _pair(name, value):
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or len(value) != 2:
        raise ArgumentTypeError(f"{name} must be a vector (x, y), got {v._show(value)}")
    return value


def _fitted(window, viewport):
    """The largest rectangle of the window's aspect ratio centered in ``viewport``."""
    ww, wh = window[2] - window[0], window[3] - window[1]
    vw, vh = viewport[2] - viewport[0], viewport[3] - viewport[1]
    scale = min(vw / ww, vh / wh)
    cx, cy = (viewport[0] + viewport[2]) / 2, (viewport[1] + viewport[3]) / 2
    return (cx - ww * scale / 2, cy - wh * scale / 2, cx + ww * scale / 2, cy + wh * scale / 2)


def workstation(width, height):
    """NDC -> device: the unit square onto the frame's pixel area, from the outer edge
    of pixel (0, 0) at (-0.5, -0.5) to (width - 0.5, height - 0.5)."""
    return window_to_viewport((0.0, 0.0, 1.0, 1.0),
                              (-0.5, -0.5, width - 0.5, height - 0.5))


def device_rectangle(m, rect):
    """The NDC rectangle ``rect`` mapped by the (axis-aligned) workstation matrix."""
    corners = tf.apply(m, np.array([[rect[0], rect[1]], [rect[2], rect[3]]]))
    return (corners[0, 0], corners[0, 1], corners[1, 0], corners[1, 1])
