"""Stereoscopic views (Hearn & Baker, section 9-1, "Stereoscopic Views"): two views of
a scene from eye positions a little apart (:meth:`scanline.Camera.stereo`), shown so
that each eye sees its own, "the left view to the left eye and the right view to
the right eye".

:func:`side_by_side` lays the pair out for a stereoscope (parallel viewing) or, with
``crossed=True``, for cross-eyed free viewing; :func:`anaglyph` merges it into one
red-cyan image for glasses with a red filter over the left eye and a cyan one over
the right: the red channel carries the left eye's luminance, green and blue the
right eye's (the luminance of ITU-R BT.601, :func:`scanline.color.luminance`).

>>> import scanline as sl
>>> cam = sl.Camera(eye=(0, 0, 6), target=(0, 0, 0))
>>> views = []
>>> for eye in cam.stereo(0.4):
...     fb = sl.FrameBuffer(40, 30, background="white")
...     _ = sl.draw3d.wireframe(fb, sl.mesh.cube(1.0), eye, color="black")
...     views.append(fb)
>>> sl.draw3d.anaglyph(*views).mode, sl.draw3d.side_by_side(*views, gap=4).width
('RGB', 84)
"""

from typing import List

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .._typing import Color
from ..errors import ArgumentTypeError, ArgumentValueError
from ..framebuffer import FrameBuffer


def _pair(left: FrameBuffer, right: FrameBuffer) -> List[NDArray[np.uint8]]:
    for name, fb in (("left", left), ("right", right)):
        if not isinstance(fb, FrameBuffer):
            raise ArgumentTypeError(f"{name} must be a scanline.FrameBuffer, got {v._show(fb)}")
    if (left.width, left.height) != (right.width, right.height):
        raise ArgumentValueError(
            f"left is {left.width} x {left.height} and right is {right.width} x "
            f"{right.height}; the two views must be the same size")
    return [np.asarray(fb.to_pil().convert("RGB"), np.uint8) for fb in (left, right)]


def anaglyph(left: FrameBuffer, right: FrameBuffer) -> FrameBuffer:
    """A red-cyan anaglyph of a stereo pair: an RGB frame buffer whose red channel is
    the left view's luminance and whose green and blue channels are the right
    view's.

    Parameters
    ----------
    left, right : FrameBuffer
        The views of the left and right eye, the same size, any mode.

    Returns
    -------
    FrameBuffer
        Mode RGB.

    Raises
    ------
    ArgumentTypeError
        A view that is not a FrameBuffer.
    ArgumentValueError
        Views of different sizes.

    Examples
    --------
    A white left view and a black right one: red alone.

    >>> import scanline as sl
    >>> left = sl.FrameBuffer(1, 1, background="white")
    >>> right = sl.FrameBuffer(1, 1, background="black")
    >>> sl.draw3d.anaglyph(left, right).to_array().tolist()
    [[[255, 0, 0]]]
    """
    from ..color import luminance

    a, b = _pair(left, right)
    out = np.empty(a.shape, np.uint8)
    out[..., 0] = luminance(a)
    out[..., 1] = out[..., 2] = luminance(b)
    return FrameBuffer.from_array(out)


def side_by_side(left: FrameBuffer, right: FrameBuffer, gap: int = 0, crossed: bool = False,
                 background: Color = "white") -> FrameBuffer:
    """A stereo pair side by side, ``gap`` pixels of ``background`` between them: the
    left view on the left (parallel viewing, a stereoscope), or with ``crossed`` the
    right view on the left (cross-eyed viewing).  An RGB frame buffer.

    Parameters
    ----------
    left, right : FrameBuffer
        The two views, the same size.
    gap : int
        Pixels between them, 0..4096.
    crossed : bool
        The right view on the left.
    background : color
        The gap's color.

    Returns
    -------
    FrameBuffer
        Mode RGB, 2 width + gap wide.

    Raises
    ------
    ArgumentTypeError
        A view that is not a FrameBuffer, or ``crossed`` not a bool.
    ArgumentValueError
        Views of different sizes, or a gap past 4096.

    Examples
    --------
    >>> import scanline as sl
    >>> left = sl.FrameBuffer(1, 1, background="red")
    >>> right = sl.FrameBuffer(1, 1, background="blue")
    >>> sl.draw3d.side_by_side(left, right, gap=1, background="black").to_array().tolist()
    [[[255, 0, 0], [0, 0, 0], [0, 0, 255]]]
    >>> sl.draw3d.side_by_side(left, right, crossed=True).to_array().tolist()
    [[[0, 0, 255], [255, 0, 0]]]
    """
    a, b = _pair(left, right)
    gap = v.positive_int("gap", gap, minimum=0)
    if gap > 4096:
        raise ArgumentValueError(f"gap={gap} pixels is too wide; at most 4096")
    if not isinstance(crossed, bool):
        raise ArgumentTypeError(f"crossed must be True or False, got {v._show(crossed)}")
    fb = FrameBuffer(2 * left.width + gap, left.height, mode="RGB", background=background)
    out = fb.to_array()
    first, second = (b, a) if crossed else (a, b)
    out[:, :left.width] = first
    out[:, left.width + gap:] = second
    return FrameBuffer.from_array(out)
