"""Parse color specifications (see :mod:`scanline.color`)."""

import math
import numbers
import re

from PIL import ImageColor

from ..errors import ArgumentTypeError, ArgumentValueError

_HELP = ("a color name such as 'red' or 'tab:blue', a hex string '#rrggbb', an (r, g, b[, a]) "
         "tuple of integers 0..255 or of floats 0..1")
_TUPLE_HELP = ("a tuple needs 3 or 4 integers in 0..255, or 3 or 4 floats in 0..1 "
               "(matplotlib's convention)")


def _matplotlib_rgba(color):
    """``color`` looked up in matplotlib's color tables ("tab:blue", "C0", "xkcd:sky
    blue", the CSS4 names, single letters, gray strings such as "0.5"), or None when
    matplotlib is not installed or does not know the name."""
    try:
        from matplotlib import colors
    except ImportError:
        return None
    try:
        rgba = colors.to_rgba(color)
    except ValueError:
        return None
    return tuple(math.floor(c * 255 + 0.5) for c in rgba)


def _matplotlib_name(color):
    """Whether ``color`` is written as one of matplotlib's own color forms."""
    return (color.startswith(("tab:", "xkcd:")) or re.fullmatch(r"C\d+", color) is not None
            or color in ("b", "g", "r", "c", "m", "y", "k", "w"))


def _named(color, name):
    try:
        return ImageColor.getcolor(color, "RGBA")
    except ValueError:
        pass
    found = _matplotlib_rgba(color)
    if found is not None:
        return found
    if _matplotlib_name(color.strip()):
        try:
            import matplotlib  # noqa: F401
        except ImportError:
            raise ArgumentValueError(
                f"{name}={color!r} is one of matplotlib's color names, and matplotlib is not "
                "installed (pip install matplotlib); or use a CSS name or '#rrggbb'") from None
    raise ArgumentValueError(f"{name}={color!r} is not a known color; use {_HELP}") from None


def _from_tuple(color, values, name):
    if not all(isinstance(c, numbers.Real) and not isinstance(c, bool) for c in values):
        raise ArgumentTypeError(f"{name}={color!r} is not a color; {_TUPLE_HELP}")
    if len(values) not in (3, 4):
        raise ArgumentValueError(
            f"{name}={color!r} has {len(values)} values and is not a color; {_TUPLE_HELP}")
    if all(isinstance(c, numbers.Integral) for c in values):
        if all(0 <= c <= 255 for c in values):
            return tuple(int(c) for c in values) + ((255,) if len(values) == 3 else ())
        raise ArgumentValueError(
            f"{name}={color!r} is not a color; integers must be in 0..255 ({_TUPLE_HELP})")
    # any float: the [0, 1] convention of matplotlib, scikit-image and OpenGL
    if all(math.isfinite(c) and 0.0 <= c <= 1.0 for c in values):
        out = tuple(math.floor(float(c) * 255 + 0.5) for c in values)
        return out + ((255,) if len(values) == 3 else ())
    raise ArgumentValueError(
        f"{name}={color!r} is not a color: a tuple holding floats is read as 0..1 "
        "(matplotlib's convention); write 0..255 values as integers, e.g. (255, 128, 0)")


def rgba(color, name="color"):
    """Return ``color`` as an ``(r, g, b, a)`` tuple of ints in 0..255.

    A color is a name or a string Pillow reads (CSS names, ``"#rrggbb[aa]"``,
    ``"rgb(...)"``, ``"hsl(...)"``), else one of matplotlib's when matplotlib is
    installed (``"tab:blue"``, ``"C0"``, ``"xkcd:sky blue"``, ``"k"``); a tuple of 3
    or 4 integers in 0..255, or of floats in [0, 1] (any float element makes it the
    [0, 1] form, scaled by 255 and rounded); or an integer gray level 0..255.

    >>> rgba("red")
    (255, 0, 0, 255)
    >>> rgba((10, 20, 30))
    (10, 20, 30, 255)
    >>> rgba((1.0, 0.5, 0.0))
    (255, 128, 0, 255)
    """
    if isinstance(color, str):
        return _named(color, name)
    if isinstance(color, numbers.Integral) and not isinstance(color, bool):
        if 0 <= color <= 255:
            v = int(color)
            return (v, v, v, 255)
        raise ArgumentValueError(f"{name}={color!r}: a gray level must be in 0..255")
    if isinstance(color, (tuple, list)) or hasattr(color, "__array__"):
        try:
            values = list(color) if not hasattr(color, "tolist") else color.tolist()
        except TypeError:
            values = None
        if not isinstance(values, list):
            raise ArgumentTypeError(f"{name}={color!r} is not a color; use {_HELP}")
        return _from_tuple(color, values, name)
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
