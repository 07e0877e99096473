"""Soft fill, or tint fill: recolor an antialiased area and keep its soft edges
(notes, syllabus: "Area-Fill Attributes - Soft fill")."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..errors import ArgumentValueError
from ._common import target
from .seedfill import fill

if TYPE_CHECKING:
    from .._typing import Color, Connectivity
    from ..framebuffer import FrameBuffer


def soft_fill(fb: FrameBuffer, x: float, y: float, color: Color, foreground: Color,
              background: Color, connectivity: Connectivity = 4) -> int:
    """Replace the foreground of a soft-edged area, blend by blend.

    From the seed, the connected region of pixels P that are blends
    P = t*F + (1 - t)*B of the old ``foreground`` F and the ``background`` B with
    t > 0 is repainted t*F' + (1 - t)*B, F' = ``color``: solid pixels (t = 1) take the
    new color, and the antialiased or shaded fringe keeps its fraction t of it.

    Parameters
    ----------
    fb : FrameBuffer
        Mode ``"L"``, ``"RGB"`` or ``"RGBA"``: soft fill needs intensity levels
        (modes ``"1"`` and ``"P"`` raise ArgumentValueError).
    x, y : number
        The seed, a pixel of ``fb``, normally one of full foreground.
    color : color
        The new foreground F'.
    foreground, background : color
        The old foreground F and the background B the area was blended with; they
        must differ.
    connectivity : {4, 8}
        4: the region spreads to the edge neighbors; 8: also to the corner
        neighbors.

    Returns
    -------
    int
        The number of pixels repainted.

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer.
    ArgumentValueError
        For mode ``"1"`` or ``"P"``, equal ``foreground`` and ``background``, a seed
        outside the frame buffer, a connectivity other than 4 or 8, or a bad color.

    Notes
    -----
    Hearn & Baker's soft fill (the notes' syllabus, "Area-Fill Attributes"; Smith's
    tint fill): each pixel's fraction t is recovered from P = t*F + (1 - t)*B.  With
    several channels the equation is overdetermined, so t is its least-squares
    solution t = (P - B).(F - B) / |F - B|**2, clipped to 1.  A pixel belongs to the
    region when t > 0 and P lies within one level per channel of t*F + (1 - t)*B
    (stored channels are rounded to whole levels); it is repainted
    round(t*F' + (1 - t)*B).  In mode ``"L"`` every gray level strictly between B and
    F (or beyond F) has an exact t, so the region is every connected pixel on F's
    side of B.  The region is found with the scan-line seed fill of
    :func:`scanline.draw.flood_fill`, whose visited mask lets F' be any color, even
    one that is itself a blend of F and B.

    References
    ----------
    A. R. Smith, "Tint fill", SIGGRAPH '79 (Computer Graphics 13(2)), 276-283, 1979.
    K. P. Fishkin and B. A. Barsky, "A family of new algorithms for soft filling",
    SIGGRAPH '84 (Computer Graphics 18(3)), 235-244, 1984.
    D. Hearn and M. P. Baker, "Computer Graphics", 2nd ed., Prentice Hall, 1994,
    section 4-5, "Soft fill".

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer.from_array(np.array([[0, 64, 255, 255, 128, 0]], np.uint8))
    >>> sl.draw.soft_fill(fb, 2, 0, color=100, foreground=255, background=0)
    4
    >>> fb.to_array().tolist()
    [[0, 25, 100, 100, 50, 0]]
    """
    target(fb)  # type check
    if fb.mode in ("1", "P"):
        raise ArgumentValueError(
            f"soft fill needs intensity levels; this frame buffer is mode {fb.mode!r} "
            "(bits or color-table indices): use mode 'L', 'RGB' or 'RGBA', or flood_fill"
        )
    new = fb.pixel(color)
    old = fb.pixel(foreground, "foreground")
    back = fb.pixel(background, "background")
    if np.array_equal(old, back):
        raise ArgumentValueError(
            f"foreground and background must differ (both are {tuple(old.tolist())}): "
            "the blend fraction t of P = t*F + (1 - t)*B is then undefined"
        )
    return fill(fb, x, y, "soft", connectivity, np.stack([old, back, new]), new)
