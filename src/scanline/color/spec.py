"""Parse color specifications (see :mod:`scanline.color`)."""

import numbers

from PIL import ImageColor

from ..errors import ArgumentTypeError, ArgumentValueError

_HELP = "a color name such as 'red', a hex string '#rrggbb', or an (r, g, b[, a]) tuple of 0..255"


def rgba(color, name="color"):
    """Return ``color`` as an ``(r, g, b, a)`` tuple of ints in 0..255.

    >>> rgba("red")
    (255, 0, 0, 255)
    >>> rgba((10, 20, 30))
    (10, 20, 30, 255)
    """
    if isinstance(color, str):
        try:
            return ImageColor.getcolor(color, "RGBA")
        except ValueError:
            raise ArgumentValueError(f"{name}={color!r} is not a known color; use {_HELP}") from None
    if isinstance(color, numbers.Integral) and not isinstance(color, bool):
        if 0 <= color <= 255:
            v = int(color)
            return (v, v, v, 255)
        raise ArgumentValueError(f"{name}={color!r}: a gray level must be in 0..255")
    if isinstance(color, (tuple, list)) or hasattr(color, "__array__"):
        values = list(color) if not hasattr(color, "tolist") else color.tolist()
        if not all(isinstance(v, numbers.Real) and not isinstance(v, bool) for v in values):
            raise ArgumentTypeError(
                f"{name}={color!r} is not a color; a tuple needs 3 or 4 integers in 0..255"
            )
        if len(values) in (3, 4) and all(
            isinstance(v, numbers.Integral) and 0 <= v <= 255 for v in values
        ):
            return tuple(int(v) for v in values) + ((255,) if len(values) == 3 else ())
        raise ArgumentValueError(
            f"{name}={color!r} is not a color; a tuple needs 3 or 4 integers in 0..255"
        )
    raise ArgumentTypeError(f"{name}={color!r} of type {type(color).__name__} is not a color; use {_HELP}")


def _luma(r, g, b):
    """ITU-R BT.601 luma, as Pillow's RGB -> L conversion computes it."""
    return (r * 299 + g * 587 + b * 114) // 1000


def pixel_value(color, mode, name="color"):
    """Return the channel values that ``color`` stores in a frame buffer of ``mode``.

    Mode ``"P"`` is handled by the frame buffer itself (it owns the color table);
    here an integer in ``"P"`` is returned unchanged.

    >>> pixel_value("white", "1"), pixel_value("red", "L"), pixel_value("red", "RGB")
    ((1,), (76,), (255, 0, 0))
    """
    if mode == "1" and isinstance(color, numbers.Integral) and not isinstance(color, bool):
        if color in (0, 1):
            return (int(color),)
        raise ArgumentValueError(f"{name}={color!r}: in mode '1' an integer color is a bit, 0 or 1")
    r, g, b, a = rgba(color, name)
    if mode == "1":
        return (1 if _luma(r, g, b) >= 128 else 0,)
    if mode == "L":
        return (_luma(r, g, b),)
    if mode == "RGB":
        return (r, g, b)
    if mode == "RGBA":
        return (r, g, b, a)
    raise ArgumentValueError(f"mode={mode!r} has no direct pixel value")
