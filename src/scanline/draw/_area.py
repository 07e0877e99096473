"""Painting a filled area with a fill style (notes, syllabus: "Area-Fill Attributes -
Fill styles. Pattern fill. Soft fill").

Every area primitive (polygons, filled circles and ellipses, chords, pies) hands this
module two callables, so that a style can be applied without knowing the shape:

``draw(buf, packed, width, height, ox, oy, color)``
    fills the area's spans into the storage ``buf`` (see ``FrameBuffer._raster``) of
    a ``width`` x ``height`` raster whose pixel (0, 0) is device pixel (ox, oy),
    with the uint8 channel values ``color``.
``outline()``
    draws the area's boundary into the frame buffer (the hollow style).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable, Optional, Sequence

import numpy as np
from numpy.typing import NDArray

from ._common import target

if TYPE_CHECKING:
    from .._typing import Color
    from ..attributes import FillStyle
    from ..framebuffer import FrameBuffer

#: ``draw(buf, packed, width, height, ox, oy, color)`` (see the module notes).
Draw = Callable[[NDArray[np.uint8], bool, int, int, int, int, NDArray[np.uint8]], None]
#: ``outline()`` (see the module notes).
Outline = Callable[[], None]


def fill_area(fb: FrameBuffer, color: Optional[Color], style: Optional[FillStyle],
              bbox: Sequence[float], draw: Draw, outline: Outline) -> None:
    """Fill an area of ``fb`` with ``color`` in ``style``.

    ``style`` None (or a solid style) fills directly; any other style object must
    provide ``paint(fb, color, bbox, draw, outline)`` (anything else, such as the
    name ``"hatch"``, is an ArgumentTypeError naming ``style``).  ``bbox`` is
    ``(xmin, ymin, xmax, ymax)``, the device pixels (inclusive) that can be covered.
    """
    if style is None or getattr(style, "kind", None) == "solid":
        buf, packed, width, height = target(fb)
        draw(buf, packed, width, height, 0, 0, fb.pixel(color))
    elif not callable(getattr(style, "paint", None)):
        from .._validate import _show
        from ..errors import ArgumentTypeError
        hint = (f"; for that kind write style=sl.FillStyle({style!r})"
                if isinstance(style, str) and style in ("solid", "hollow", "pattern", "hatch")
                else "")
        raise ArgumentTypeError(f"style must be a FillStyle (sl.FillStyle.hatch(), "
                                f"sl.FillStyle.pattern(tile) ...) or None for solid, got "
                                f"{_show(style)}{hint}")
    else:
        style.paint(fb, color, bbox, draw, outline)
