"""Rotating a block of pixels (notes, chapter 6, Q3; Hearn & Baker §16-3, Fig. 16-4).

>>> import scanline as sl
>>> src = sl.FrameBuffer(2, 1, mode="L", background=200)
>>> dst = sl.FrameBuffer(3, 3, mode="L")
>>> rotate_block(dst, src, (0, 0, 2, 1), 1.5707963267948966, center=(1, 1))
>>> dst.to_array().tolist()            # a quarter turn: the 2x1 bar stands up
[[0, 100, 0], [0, 200, 0], [0, 100, 0]]
"""

import math
from typing import TYPE_CHECKING, Any, Optional, Sequence, Tuple

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from .bitblt import _rect

if TYPE_CHECKING:
    from .._typing import Angle
    from ..framebuffer import FrameBuffer

METHODS = ("area", "nearest")


def rotate_block(dst: "FrameBuffer", src: "FrameBuffer", rect: Sequence[int], angle: "Angle",
                 center: Optional[Tuple[float, float]] = None,
                 method: Optional[str] = None) -> None:
    """Rotate the block ``rect`` of ``src`` by ``angle`` and draw it into ``dst``.

    Parameters
    ----------
    dst, src : FrameBuffer
        Of one mode.
    rect : (x, y, width, height)
        The block in ``src`` (bottom-left pixel, size).
    angle : float
        Radians, counterclockwise, about the block's center.
    center : (x, y), optional
        Where the block's center goes in ``dst`` (default: where it is in ``src``).
        May be fractional.
    method : {"area", "nearest"}, optional
        ``"area"`` (default in modes "L", "RGB", "RGBA"): each destination pixel
        takes the source pixels in proportion to the area of it that their rotated
        squares cover, and keeps its own value for the uncovered rest — the notes'
        "percentage of area covered".  ``"nearest"`` (the only choice in modes "1"
        and "P", whose values cannot be mixed): a pixel whose center lies in the
        rotated block takes the source pixel it falls in.

    Notes
    -----
    Compiled kernel :func:`scanline._kernels.rotate.rotate_area`: each rotated source
    square is clipped against the destination pixels its bounding box meets
    (Sutherland–Hodgman) and the clipped area measured (shoelace formula).  Results
    are rounded half up.

    Raises
    ------
    ArgumentTypeError
        When ``dst`` or ``src`` is not a FrameBuffer, or ``center`` not a point.
    ArgumentValueError
        For frame buffers of two modes, an unknown method, ``"area"`` in mode "1" or
        "P", a bad angle or a center outside the coordinate range.

    Examples
    --------
    >>> import math
    >>> import scanline as sl
    >>> src = sl.FrameBuffer(3, 1, mode="1", background=1)
    >>> dst = sl.FrameBuffer(3, 3, mode="1")
    >>> sl.raster.rotate_block(dst, src, (0, 0, 3, 1), math.pi / 2, center=(1, 1))
    >>> print(sl.text_image(dst))
    -#-
    -#-
    -#-
    """
    from ..framebuffer import FrameBuffer

    for name, fb in (("dst", dst), ("src", src)):
        if not isinstance(fb, FrameBuffer):
            raise ArgumentTypeError(f"{name} must be a scanline.FrameBuffer, got {type(fb).__name__}")
    if dst.mode != src.mode:
        raise ArgumentValueError(f"src is mode {src.mode!r} and dst mode {dst.mode!r}; use one mode")
    mixable = dst.mode in ("L", "RGB", "RGBA")
    if method is None:
        method = "area" if mixable else "nearest"
    v.choice("method", method, METHODS)
    if method == "area" and not mixable:
        raise ArgumentValueError(f"method='area' mixes levels, which mode {dst.mode!r} cannot "
                                 "hold; use method='nearest'")
    angle = v.angle("angle", angle)
    x, y, w, h = _rect("rect", rect)
    x0, y0 = max(x, 0), max(y, 0)
    x1, y1 = min(x + w, src.width), min(y + h, src.height)
    if x1 <= x0 or y1 <= y0:
        return
    cx, cy = x + (w - 1) / 2, y + (h - 1) / 2          # the block's center, as given
    if center is None:
        px, py = cx, cy
    else:
        px, py = (v.number(f"center[{i}]", c) for i, c in enumerate(_pair(center)))
        for c in (px, py):
            if abs(c) > v.COORD_LIMIT:
                raise ArgumentValueError(f"center={center!r} is outside the coordinate range")
    cos_a, sin_a = math.cos(angle), math.sin(angle)
    if method == "area":
        _area(dst, src, (x0, y0, x1 - x0, y1 - y0), (cx, cy), (px, py), cos_a, sin_a)
    else:
        _nearest(dst, src, (x0, y0, x1 - x0, y1 - y0), (cx, cy), (px, py), cos_a, sin_a)


def _pair(value: Any) -> Tuple[Any, Any]:
    try:
        a, b = value
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"center must be a point (x, y), got {v._show(value)}") from None
    return a, b


def _area(dst: "FrameBuffer", src: "FrameBuffer", block: Tuple[int, int, int, int],
          c: Tuple[float, float], p: Tuple[float, float], cos_a: float, sin_a: float) -> None:
    from .._kernels._jit import call
    from .._kernels.rotate import rotate_area

    x0, y0, w, h = block
    sbuf, dbuf = src._raster()[0], dst._raster()[0]
    acc = np.zeros(dbuf.shape, np.float64)
    cover = np.zeros(dbuf.shape[:2], np.float64)
    scratch = [np.empty(16) for _ in range(6)]
    call(rotate_area, 40 * w * h, sbuf, x0, y0, w, h, float(c[0]), float(c[1]), float(p[0]),
         float(p[1]), cos_a, sin_a, acc, cover, *scratch)
    touched = cover > 0
    if not touched.any():
        return
    cover = np.minimum(cover, 1.0)[..., None]
    mixed = acc + (1.0 - cover) * dbuf
    dbuf[touched] = np.floor(mixed[touched] + 0.5).clip(0, 255).astype(np.uint8)


def _nearest(dst: "FrameBuffer", src: "FrameBuffer", block: Tuple[int, int, int, int],
             c: Tuple[float, float], p: Tuple[float, float], cos_a: float,
             sin_a: float) -> None:
    x0, y0, w, h = block
    half = math.hypot(w, h) / 2 + 1
    gx = np.arange(max(0, math.floor(p[0] - half)), min(dst.width, math.ceil(p[0] + half) + 1))
    gy = np.arange(max(0, math.floor(p[1] - half)), min(dst.height, math.ceil(p[1] + half) + 1))
    if not len(gx) or not len(gy):
        return
    X, Y = np.meshgrid(gx, gy)
    # inverse rotation of each destination center into the source block
    ux, uy = X - p[0], Y - p[1]
    sx = c[0] + cos_a * ux + sin_a * uy
    sy = c[1] - sin_a * ux + cos_a * uy
    i = np.floor(sx + 0.5).astype(np.int64)
    j = np.floor(sy + 0.5).astype(np.int64)
    inside = (i >= x0) & (i < x0 + w) & (j >= y0) & (j < y0 + h)
    if not inside.any():
        return
    if dst.mode == "1":
        s = np.unpackbits(src._raster()[0][:, :, 0], axis=1, count=src.width)
        d = np.unpackbits(dst._raster()[0][:, :, 0], axis=1, count=dst.width)
        d[Y[inside], X[inside]] = s[j[inside], i[inside]]
        dst._raster()[0][:, :, 0] = np.packbits(d, axis=1)
        return
    if dst.mode == "P":
        used = int(src._raster()[0][j[inside], i[inside]].max())
        if used >= len(dst._table):
            raise ArgumentValueError(f"src uses color-table index {used}, which dst's table "
                                     f"({len(dst._table)} entries) lacks")
    dbuf = dst._raster()[0]
    dbuf[Y[inside], X[inside]] = src._raster()[0][j[inside], i[inside]]
