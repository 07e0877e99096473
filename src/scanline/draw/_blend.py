"""Translucent colors: compositing a primitive "over" the frame buffer (Porter &
Duff 1984) in every frame-buffer mode.

A color whose alpha is below 255 (``"#ff000080"``, ``(255, 0, 0, 128)``) does not
replace the pixels it covers: it is blended over them.  The arithmetic per mode is
in :mod:`scanline._kernels.blend` (RGBA: straight, i.e. non-premultiplied, storage
with destination alpha; RGB and L: per channel; P: blend the table colors, then the
nearest table entry; "1": the pixel is set where coverage x alpha >= 1/2).

For primitive authors
---------------------
Any primitive that can draw its pixels with an opaque value can be made
translucent with :func:`paint` (one primitive) or :func:`paint_each` (a batch with
one color per primitive)::

    from . import _blend

    def draw(buf, packed, width, height, ox, oy, value):
        # paint the primitive's pixels with ``value`` (uint8 channel values) into
        # the raster ``buf`` of ``width`` x ``height`` whose pixel (0, 0) is device
        # pixel (ox, oy) -- e.g. call a kernel with coordinates shifted by (-ox, -oy).
        my_kernel(buf, layout(packed), width, height, x0 - ox, y0 - oy, x1 - ox, y1 - oy,
                  value)

    _blend.paint(fb, color, (xmin, ymin, xmax, ymax), draw)

``paint`` draws an opaque color straight into the frame buffer (``ox = oy = 0``).
For a translucent one it clips the bounding box to the frame buffer, has ``draw``
paint a coverage mask (one uint8 channel, never packed) over that box, and
composites the color through the mask once: each pixel is blended once per
primitive however often the primitive's algorithm visits it.  This is the
``draw`` callable of :func:`scanline.draw._area.fill_area`, so area primitives
hand over the one they already have.
"""

from __future__ import annotations

import numbers
from typing import TYPE_CHECKING, Callable, Optional, Sequence, Tuple, Union, cast

import numpy as np
from numpy.typing import NDArray

from .._kernels import blend as k
from .._kernels._jit import call
from .._kernels.variants import MODE
from ..color.spec import Channels, in_context, rgba
from ._area import Draw, Outline, fill_area
from ._common import colors, target

if TYPE_CHECKING:
    from .._typing import Color, Colors
    from ..attributes import FillStyle
    from ..framebuffer import FrameBuffer

#: ``draw(i, buf, packed, width, height, ox, oy, value)``: :func:`paint_each`'s
#: ``draw``, painting primitive ``i`` as a :data:`~scanline.draw._area.Draw` does.
DrawEach = Callable[[int, NDArray[np.uint8], bool, int, int, int, int, NDArray[np.uint8]], None]
#: One source row ``(c0, c1, c2, alpha)`` of the blend kernels.
Source = Tuple[float, float, float, float]

_NO_TABLE = np.zeros((1, 3), np.uint8)
_FULL = np.full(1, 255, np.uint8)


def mode_code(fb: FrameBuffer) -> Tuple[int, ...]:
    """The blend kernels' mode token of ``fb`` (:mod:`scanline._kernels.variants`)."""
    return cast("Tuple[int, ...]", MODE[fb.mode])


def table(fb: FrameBuffer) -> NDArray[np.uint8]:
    """The color table the blend kernels need (a dummy outside mode "P")."""
    return fb._table if fb.mode == "P" else _NO_TABLE


def _alpha(spec: object) -> int:
    """The alpha (0..255) of one color spec without converting it fully."""
    if isinstance(spec, str):
        return rgba(spec)[3] if len(spec) in (5, 9) or not spec.startswith("#") else 255
    if isinstance(spec, (tuple, list, np.ndarray)) and len(spec) == 4 and np.ndim(spec) == 1 \
            and isinstance(spec[3], numbers.Integral):
        return int(spec[3])
    return 255


def translucent(color: Optional[Colors], one: bool = False) -> bool:
    """Does ``color`` have an alpha below 255 anywhere?  Integers (gray levels,
    bits, table indices) are opaque.

    ``color`` is one spec, or (for batches) a list of specs or an (N, 4) array;
    ``one=True`` says it is one spec, so that a list ``[r, g, b, a]`` is a color.

    >>> translucent("red"), translucent("#ff000080"), translucent([(0, 0, 0), (9, 9, 9, 9)])
    (False, True, True)
    >>> translucent([255, 0, 0, 128]), translucent([255, 0, 0, 128], one=True)
    (False, True)
    """
    if one:
        return _alpha(color) < 255
    if isinstance(color, np.ndarray):
        return color.ndim == 2 and color.shape[1] == 4 and bool((color[:, 3] < 255).any())
    if isinstance(color, list):
        return any(_alpha(c) < 255 for c in color)
    return _alpha(color) < 255


def _source(fb: FrameBuffer, spec: Optional[Union[Color, Channels]], name: str) -> Source:
    """One source row (c0, c1, c2, alpha 0..1) for the blend kernels."""
    value = fb.pixel(spec, name)      # validates; in "P" adds the color to the table
    integer = spec is None or isinstance(spec, numbers.Integral)   # None: the opaque foreground
    alpha = 1.0 if integer else rgba(spec, name)[3] / 255.0
    if fb.mode == "P":
        c = fb._table[value[0]]
    elif fb.mode in ("RGB", "RGBA"):
        c = value[:3]
    else:
        c = (value[0], 0, 0)
    return (float(c[0]), float(c[1]), float(c[2]), alpha)


def sources(fb: FrameBuffer, color: Optional[Colors], n: int,
            name: str = "color") -> NDArray[np.float64]:
    """Source rows for N primitives: a float64 array of shape (1, 4) (one color) or
    (n, 4) holding ``(c0, c1, c2, alpha)`` as :mod:`scanline._kernels.blend` takes
    them.

    ``color`` is what :func:`scanline.draw._common.colors` accepts: one spec, a list
    of N specs, an (N,) integer array (bits, gray levels or table indices) or an
    (N, 3|4) integer array of RGB(A) values (alpha is honored in every mode).
    """
    if not isinstance(color, (list, np.ndarray)):
        return np.array([_source(fb, color, name)], np.float64)
    if isinstance(color, np.ndarray) and color.ndim == 2 and color.shape[1] == 4 \
            and np.issubdtype(color.dtype, np.integer) and fb.mode not in ("RGB", "RGBA"):
        # (N, 4) specs in a mode without color channels: convert each distinct RGB
        uniq, inverse = np.unique(color[:, :3], axis=0, return_inverse=True)
        rows = np.array([_source(fb, Channels(int(c) for c in u), f"{name}") for u in uniq])
        out = rows[inverse.reshape(-1)]
        out[:, 3] = color[:, 3] / 255.0
        return out
    if isinstance(color, list):
        if len(color) == n:
            return np.array([_source(fb, c, f"{name}[{i}]")
                             for i, c in enumerate(in_context(color))],
                            np.float64).reshape(n, 4)
    values = colors(fb, color, n, name)   # validates the length and the values
    out = np.zeros((len(values), 4), np.float64)
    out[:, 3] = 1.0
    if fb.mode == "P":
        out[:, :3] = fb._table[values[:, 0]]
    elif fb.mode in ("RGB", "RGBA"):
        out[:, :3] = values[:, :3]
        if isinstance(color, np.ndarray) and color.shape[-1] == 4 and color.ndim == 2:
            out[:, 3] = color[:, 3] / 255.0
    else:
        out[:, 0] = values[:, 0]
    return out


def _clip(fb: FrameBuffer, bbox: Sequence[float]) -> Tuple[int, int, int, int]:
    x0, y0, x1, y1 = (int(v) for v in bbox)
    return max(x0, 0), max(y0, 0), min(x1, fb.width - 1), min(y1, fb.height - 1)


def composite(fb: FrameBuffer, mask: NDArray[np.uint8], ox: int, oy: int,
              source: NDArray[np.float64]) -> None:
    """Composite ``source`` (one row of :func:`sources`) through ``mask`` (uint8
    (h, w, 1), 255 = fully covered) whose pixel (0, 0) is device pixel (ox, oy).
    Mask pixels outside ``fb`` are ignored."""
    buf, _, width, height = target(fb)
    call(k.composite, 3 * mask.shape[0] * mask.shape[1], buf, mode_code(fb), width, height, table(fb),
         mask, int(ox), int(oy), np.ascontiguousarray(source, np.float64))


def _masked(fb: FrameBuffer, source: NDArray[np.float64], bbox: Sequence[float],
            draw: Draw) -> None:
    x0, y0, x1, y1 = _clip(fb, bbox)
    if x0 > x1 or y0 > y1 or source[3] <= 0.0:
        return
    mask = np.zeros((y1 - y0 + 1, x1 - x0 + 1, 1), np.uint8)
    draw(mask, False, x1 - x0 + 1, y1 - y0 + 1, x0, y0, _FULL)
    composite(fb, mask, x0, y0, source)


def paint(fb: FrameBuffer, color: Optional[Color], bbox: Sequence[float], draw: Draw) -> None:
    """Draw one primitive in ``color``, composited over ``fb`` when translucent.

    Parameters
    ----------
    fb : FrameBuffer
    color : color
        One color spec.  Opaque: ``draw`` paints straight into ``fb``.  Alpha below
        255: ``draw`` paints a coverage mask over ``bbox`` and the color is
        composited through it once.
    bbox : (xmin, ymin, xmax, ymax)
        Device pixels (inclusive) the primitive can touch; it may extend beyond
        ``fb`` (it is clipped here).  Pixels that ``draw`` paints outside it are
        lost, so make it generous rather than tight.
    draw : callable
        ``draw(buf, packed, width, height, ox, oy, value)`` paints the primitive's
        pixels with the uint8 channel values ``value`` into the storage ``buf`` of a
        ``width`` x ``height`` raster whose pixel (0, 0) is device pixel (ox, oy)
        (``packed`` says whether ``buf`` is a packed mode-"1" bitmap; kernels take it
        as :func:`scanline._kernels.variants.layout` of it).

    Examples
    --------
    >>> import scanline as sl
    >>> from scanline._kernels.lines import BRESENHAM, draw_line
    >>> from scanline._kernels.variants import layout, token
    >>> fb = sl.FrameBuffer(4, 1, mode="RGB", background="white")
    >>> def draw(buf, packed, width, height, ox, oy, value):
    ...     draw_line(buf, layout(packed), width, height, 0 - ox, 0 - oy, 3 - ox, 0 - oy,
    ...               value, token(BRESENHAM))
    >>> paint(fb, (0, 0, 255, 128), (0, 0, 3, 0), draw)
    >>> fb.get_pixel(0, 0)
    (127, 127, 255)
    """
    if not translucent(color, one=True):
        buf, packed, width, height = target(fb)
        draw(buf, packed, width, height, 0, 0, fb.pixel(color))
        return
    assert color is not None        # None is the foreground, opaque
    _masked(fb, sources(fb, [color], 1)[0], bbox, draw)


def paint_each(fb: FrameBuffer, color: Optional[Colors], n: int,
               bboxes: Sequence[Sequence[float]], draw: DrawEach) -> None:
    """Draw a batch of ``n`` primitives in turn, each composited with its own color.

    For batches whose colors include a translucent one (check with
    :func:`translucent`; an all-opaque batch is faster drawn by its own batch
    kernel).  ``color`` is one color or one per primitive (:func:`sources`);
    ``bboxes`` is an (n, 4) array of inclusive device boxes; ``draw(i, buf, packed,
    width, height, ox, oy, value)`` paints primitive ``i`` as :func:`paint`'s
    ``draw`` does.  Later primitives are composited over earlier ones.
    """
    src = sources(fb, color, n)
    buf, packed, width, height = target(fb)
    for i in range(n):
        s = src[i if len(src) > 1 else 0]
        if s[3] >= 1.0:
            value = fb.pixel(_opaque_spec(fb, s))
            draw(i, buf, packed, width, height, 0, 0, value)
        else:
            _masked(fb, s, bboxes[i], lambda *a, i=i: draw(i, *a))


def _opaque_spec(fb: FrameBuffer, s: NDArray[np.float64]) -> Union[Channels, int]:
    """The color spec of an opaque source row (the inverse of :func:`_source`)."""
    if fb.mode in ("RGB", "RGBA", "P"):
        return Channels((int(s[0]), int(s[1]), int(s[2])))
    return int(s[0])  # the gray level ("L") or the bit ("1")


def fill(fb: FrameBuffer, color: Optional[Color], style: Optional[FillStyle],
         bbox: Sequence[float], draw: Draw, outline: Outline) -> None:
    """:func:`scanline.draw._area.fill_area` with translucent solid fills
    composited (:func:`paint`).  Styled fills (hollow, patterns, hatches) are
    painted by the style, which stores ``color`` opaque."""
    if (style is None or getattr(style, "kind", None) == "solid") and translucent(color, one=True):
        paint(fb, color, bbox, draw)
    else:
        fill_area(fb, color, style, bbox, draw, outline)
