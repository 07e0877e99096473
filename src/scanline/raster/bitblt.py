"""Block transfers with raster operations (notes, chapter 6, Q3; Hearn & Baker §16-3,
"Raster animations"; the bitBlt of Newman & Sproull and Ingalls' BitBlt).

"A simple method to carry out translation in the xy plane is to transfer a
rectangular block of pixel values from one location to another."  :func:`bitblt`
copies a block from a source frame buffer into a destination one, combining each
source value s with the destination value d by one of the 16 boolean functions of two
bits, applied bitwise to the stored values (bits in mode "1", gray levels, RGB(A)
channels, or color-table indices in mode "P").

The operations are numbered as in X11 (``GXclear`` = 0 ... ``GXset`` = 15): bit
``3 - (2 s + d)`` of the code is the result for source bit s and destination bit d.

====  ==================  =================  ====  ==================  ================
code  name                result             code  name                result
====  ==================  =================  ====  ==================  ================
0     ``clear``           0                  8     ``nor``             ~(s | d)
1     ``and``             s & d              9     ``equiv``           ~(s ^ d)
2     ``and-reverse``     s & ~d             10    ``invert``          ~d
3     ``copy``            s                  11    ``or-reverse``      s | ~d
4     ``and-inverted``    ~s & d             12    ``copy-inverted``   ~s (``not``)
5     ``noop``            d                  13    ``or-inverted``     ~s | d
6     ``xor``             s ^ d              14    ``nand``            ~(s & d)
7     ``or``              s | d              15    ``set``             1 (all bits)
====  ==================  =================  ====  ==================  ================

>>> import scanline as sl
>>> fb = sl.FrameBuffer(6, 2, mode="1")
>>> sprite = sl.FrameBuffer(2, 2, mode="1", background=1)
>>> sl.raster.bitblt(fb, sprite, (0, 0, 2, 2), (1, 0), op="xor")
>>> print(sl.text_image(fb))
-##---
-##---
>>> sl.raster.bitblt(fb, sprite, (0, 0, 2, 2), (1, 0), op="xor")   # again: restored
>>> print(sl.text_image(fb))
------
------
"""

import numbers
from typing import TYPE_CHECKING, Any, Callable, Optional, Sequence, Tuple, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer

#: A raster operation: a name of OPS, an alias or the X11 code 0..15.
Op = Union[str, int]

#: The 16 raster operations by name, in X11 code order.
OPS = ("clear", "and", "and-reverse", "copy", "and-inverted", "noop", "xor", "or", "nor",
       "equiv", "invert", "or-reverse", "copy-inverted", "or-inverted", "nand", "set")
#: Other names: ``not`` is NOT source (Windows' NOTSRCCOPY), ``xnor`` is equiv.
ALIASES = {"not": "copy-inverted", "xnor": "equiv", "src": "copy", "dst": "noop",
           "zero": "clear", "one": "set"}

_FUNCTIONS: Tuple[Callable[[NDArray[np.uint8], NDArray[np.uint8]], NDArray[np.uint8]], ...] = (
    lambda s, d: np.zeros_like(d),
    lambda s, d: s & d,
    lambda s, d: s & ~d,
    lambda s, d: s.copy(),
    lambda s, d: ~s & d,
    lambda s, d: d.copy(),
    lambda s, d: s ^ d,
    lambda s, d: s | d,
    lambda s, d: ~(s | d),
    lambda s, d: ~(s ^ d),
    lambda s, d: ~d,
    lambda s, d: s | ~d,
    lambda s, d: ~s,
    lambda s, d: ~s | d,
    lambda s, d: ~(s & d),
    lambda s, d: np.full_like(d, 0xFF),
)


def op_code(op: object) -> int:
    """The X11 code 0..15 of ``op`` (a name of :data:`OPS`, an alias, or the code).

    Parameters
    ----------
    op : str or int
        A name of :data:`OPS`, an alias of :data:`ALIASES`, or a code 0..15.

    Returns
    -------
    int
        The X11 code.

    Raises
    ------
    ArgumentValueError
        For anything else.

    Examples
    --------
    >>> from scanline.raster import op_code
    >>> op_code("xor"), op_code("not"), op_code(7)
    (6, 12, 7)
    """
    if isinstance(op, numbers.Integral) and not isinstance(op, bool) and 0 <= int(op) <= 15:
        return int(op)
    if isinstance(op, str):
        name = ALIASES.get(op, op)
        if name in OPS:
            return OPS.index(name)
    raise ArgumentValueError(f"op must be one of {', '.join(OPS)} (or 'not', 'xnor', or a "
                             f"code 0..15); got {v._show(op)}")


def apply_op(op: Op, s: NDArray[np.uint8], d: NDArray[np.uint8]) -> NDArray[np.uint8]:
    """The raster operation ``op`` on uint8 arrays of source and destination values.

    Parameters
    ----------
    op : str or int
        The operation (see :func:`op_code`).
    s, d : numpy.ndarray
        uint8 source and destination values, of one shape.

    Returns
    -------
    numpy.ndarray
        uint8, the result bitwise.

    Raises
    ------
    ArgumentValueError
        For an unknown op.

    Examples
    --------
    >>> import numpy as np
    >>> from scanline.raster import apply_op
    >>> s, d = np.array([0b1010], np.uint8), np.array([0b1100], np.uint8)
    >>> [int(apply_op(op, s, d)[0]) for op in ("and", "or", "xor", "nand")]
    [8, 14, 6, 247]
    """
    return _FUNCTIONS[op_code(op)](s, d)


def _rect(name: str, value: Any) -> Tuple[int, int, int, int]:
    try:
        x, y, w, h = (v.coordinate(f"{name}[{i}]", c) for i, c in enumerate(value))
    except (TypeError, ValueError) as error:
        if isinstance(error, ArgumentValueError):
            raise
        raise ArgumentTypeError(f"{name} must be (x, y, width, height), got {v._show(value)}") from None
    if w < 0 or h < 0:
        raise ArgumentValueError(f"{name} must have width and height >= 0, got {value!r}")
    return x, y, w, h


def _point(name: str, value: Any) -> Tuple[int, int]:
    try:
        x, y = (v.coordinate(f"{name}[{i}]", c) for i, c in enumerate(value))
    except (TypeError, ValueError) as error:
        if isinstance(error, ArgumentValueError):
            raise
        raise ArgumentTypeError(f"{name} must be a point (x, y), got {v._show(value)}") from None
    return x, y


def clip_transfer(src_size: Tuple[int, int], dst_size: Tuple[int, int],
                  rect: Tuple[int, int, int, int],
                  at: Tuple[int, int]) -> Tuple[int, int, int, int, int, int]:
    """The part of a transfer inside both rasters: (sx, sy, dx, dy, w, h), w or h 0
    when nothing is left."""
    sw, sh = src_size
    dw, dh = dst_size
    x, y, w, h = rect
    dx, dy = at
    if x < 0:                      # clip to the source, moving the destination along
        dx, w, x = dx - x, w + x, 0
    if y < 0:
        dy, h, y = dy - y, h + y, 0
    w, h = min(w, sw - x), min(h, sh - y)
    if dx < 0:                     # then to the destination
        x, w, dx = x - dx, w + dx, 0
    if dy < 0:
        y, h, dy = y - dy, h + dy, 0
    w, h = min(w, dw - dx), min(h, dh - dy)
    return x, y, dx, dy, max(w, 0), max(h, 0)


def bitblt(dst: "FrameBuffer", src: "FrameBuffer", rect: Sequence[int], at: Sequence[int],
           op: Op = "copy") -> None:
    """Transfer the block ``rect`` of ``src`` to ``at`` in ``dst``, combining by ``op``.

    Parameters
    ----------
    dst, src : FrameBuffer
        Of one mode (``src`` may be ``dst``: overlapping moves work, the source is
        read before anything is written).
    rect : (x, y, width, height)
        The block in ``src``, (x, y) its bottom-left pixel (device coordinates).
    at : (x, y)
        Where the block's bottom-left pixel goes in ``dst``.
    op : str or int
        One of :data:`OPS` (or an alias / code), see the module docstring.

    Notes
    -----
    Parts of the block outside either frame buffer are clipped.  In mode "1" the
    operation works on bits; in mode "P" on color-table indices (an index the table
    does not hold raises, the frame buffer is then left unchanged).

    Hearn & Baker, section 16-3, "Raster animations" (block transfers, Fig. 16-3).

    Raises
    ------
    ArgumentTypeError
        When ``dst`` or ``src`` is not a FrameBuffer, or ``rect`` / ``at`` not a
        rectangle / point.
    ArgumentValueError
        For frame buffers of two modes, an unknown op, a negative size, or (mode "P")
        a result index the color table lacks.

    Examples
    --------
    >>> import scanline as sl
    >>> dst = sl.FrameBuffer(4, 1, mode="L", background=0b1100)
    >>> src = sl.FrameBuffer(2, 1, mode="L", background=0b1010)
    >>> sl.raster.bitblt(dst, src, (0, 0, 2, 1), (1, 0), op="and")   # 1100 & 1010 = 1000
    >>> dst.to_array().tolist()
    [[12, 8, 8, 12]]
    """
    from ..framebuffer import FrameBuffer

    for name, fb in (("dst", dst), ("src", src)):
        if not isinstance(fb, FrameBuffer):
            raise ArgumentTypeError(f"{name} must be a scanline.FrameBuffer, got {type(fb).__name__}")
    if dst.mode != src.mode:
        raise ArgumentValueError(f"src is mode {src.mode!r} and dst mode {dst.mode!r}; a block "
                                 "transfer combines stored values, so the modes must match "
                                 "(convert with FrameBuffer.from_pil(fb.to_pil().convert(...)))")
    code = op_code(op)
    x, y, dx, dy, w, h = clip_transfer(src.size, dst.size, _rect("rect", rect), _point("at", at))
    if w == 0 or h == 0:
        return
    sbuf, dbuf = src._raster()[0], dst._raster()[0]
    if dst.mode == "1":
        s = np.unpackbits(sbuf[y:y + h, :, 0], axis=1, count=src.width)[:, x:x + w]
        rows = dbuf[dy:dy + h, :, 0]
        d_all = np.unpackbits(rows, axis=1, count=dst.width)
        d = d_all[:, dx:dx + w]
        d_all[:, dx:dx + w] = _FUNCTIONS[code](s, d) & 1
        dbuf[dy:dy + h, :, 0] = np.packbits(d_all, axis=1)
        return
    s = sbuf[y:y + h, x:x + w].copy()
    d = dbuf[dy:dy + h, dx:dx + w]
    out = _FUNCTIONS[code](s, d)
    if dst.mode == "P" and code != 5 and out.size and int(out.max()) >= len(dst._table):
        raise ArgumentValueError(
            f"op={OPS[code]!r} on color-table indices gives index {int(out.max())}, but the table "
            f"has {len(dst._table)} entries; fill the table (up to 256) first")
    d[...] = out


class XorSprite:
    """A sprite moved over a background with the xor trick: drawing it with ``xor``
    shows it, drawing it again at the same place restores what was under it, so no
    copy of the background is needed (Hearn & Baker §16-3).

    Parameters
    ----------
    sprite : FrameBuffer
        The sprite's pixels, xor-ed onto the frame buffer (of its mode).

    Raises
    ------
    ArgumentTypeError
        When ``sprite`` is not a FrameBuffer.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(5, 1, mode="L", background=10)
    >>> ball = XorSprite(sl.FrameBuffer(1, 1, mode="L", background=255))
    >>> ball.show(fb, (1, 0)); ball.move(fb, (3, 0))
    >>> fb.to_array().tolist()
    [[10, 10, 10, 245, 10]]
    >>> ball.hide(fb); fb.to_array().tolist()
    [[10, 10, 10, 10, 10]]
    """

    def __init__(self, sprite: "FrameBuffer") -> None:
        from ..framebuffer import FrameBuffer

        if not isinstance(sprite, FrameBuffer):
            raise ArgumentTypeError(f"sprite must be a FrameBuffer, got {type(sprite).__name__}")
        self.sprite = sprite
        self.at: Optional[Tuple[int, int]] = None

    def _blit(self, fb: "FrameBuffer", at: Tuple[int, int]) -> None:
        bitblt(fb, self.sprite, (0, 0, self.sprite.width, self.sprite.height), at, op="xor")

    def show(self, fb: "FrameBuffer", at: Sequence[int]) -> None:
        """Draw the sprite at ``at`` (its bottom-left pixel).

        Parameters
        ----------
        fb : FrameBuffer
            The frame buffer drawn on.
        at : (x, y)
            Where the sprite's bottom-left pixel goes.

        Raises
        ------
        ArgumentValueError
            When the sprite is already shown.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(3, 1, mode="1")
        >>> sl.raster.XorSprite(sl.FrameBuffer(1, 1, mode="1", background=1)).show(fb, (2, 0))
        >>> print(sl.text_image(fb))
        --#
        """
        if self.at is not None:
            raise ArgumentValueError("the sprite is already shown; use move() or hide() first")
        self.at = _point("at", at)
        self._blit(fb, self.at)

    def hide(self, fb: "FrameBuffer") -> None:
        """Remove the sprite: the pixels under it come back.

        Parameters
        ----------
        fb : FrameBuffer
            The frame buffer it is shown on.

        Raises
        ------
        ArgumentValueError
            When the sprite is not shown.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(2, 1, mode="L", background=7)
        >>> dot = sl.raster.XorSprite(sl.FrameBuffer(1, 1, mode="L", background=1))
        >>> dot.show(fb, (0, 0)); fb.to_array().tolist()      # 7 ^ 1 = 6
        [[6, 7]]
        >>> dot.hide(fb); fb.to_array().tolist()
        [[7, 7]]
        """
        if self.at is None:
            raise ArgumentValueError("the sprite is not shown")
        self._blit(fb, self.at)
        self.at = None

    def move(self, fb: "FrameBuffer", at: Sequence[int]) -> None:
        """Hide the sprite where it is and show it at ``at``.

        Parameters
        ----------
        fb : FrameBuffer
            The frame buffer it is shown on.
        at : (x, y)
            The new place of its bottom-left pixel.

        Raises
        ------
        ArgumentValueError
            When the sprite is not shown.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(3, 1, mode="1")
        >>> dot = sl.raster.XorSprite(sl.FrameBuffer(1, 1, mode="1", background=1))
        >>> dot.show(fb, (0, 0)); dot.move(fb, (2, 0))
        >>> print(sl.text_image(fb))
        --#
        """
        self.hide(fb)
        self.show(fb, at)
