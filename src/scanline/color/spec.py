"""Parse color specifications (see :mod:`scanline.color`)."""

import math
import numbers
import re
import warnings
from typing import Any, Sequence, Tuple, TypeVar, cast

from PIL import ImageColor

from ..errors import ArgumentTypeError, ArgumentValueError, ColorScaleWarning

#: Red, green, blue and alpha, each 0..255.
RGBA = Tuple[int, int, int, int]
_Spec = TypeVar("_Spec")

_HELP = ("a color name such as 'red' or 'tab:blue', a hex string '#rrggbb', an (r, g, b[, a]) "
         "tuple of integers 0..255 or of floats 0..1")
_TUPLE_HELP = ("a tuple needs 3 or 4 integers in 0..255, or 3 or 4 floats in 0..1 "
               "(matplotlib's convention)")


def _matplotlib_rgba(color: str) -> RGBA | None:
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
    r, g, b, a = (math.floor(c * 255 + 0.5) for c in rgba)
    return (r, g, b, a)


def _matplotlib_name(color: str) -> bool:
    """Whether ``color`` is written as one of matplotlib's own color forms."""
    return (color.startswith(("tab:", "xkcd:")) or re.fullmatch(r"C\d+", color) is not None
            or color in ("b", "g", "r", "c", "m", "y", "k", "w"))


def _named(color: str, name: str) -> RGBA:
    try:
        return cast(RGBA, ImageColor.getcolor(color, "RGBA"))
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


class Channels(Tuple[int, ...]):
    """Channel values 0..255 that scanline made itself (read from pixels, a color
    table or an integer array), passed on as a color spec.  A plain tuple to every
    reader; only :func:`rgba`'s scale check knows the difference: these values
    were never typed by a user, so ``Channels((1, 0, 0))`` is not questioned.

    Examples
    --------
    >>> from scanline.color.spec import Channels, rgba
    >>> rgba(Channels((1, 0, 0)))         # no ColorScaleWarning: read as 0..255
    (1, 0, 0, 255)
    >>> Channels((1, 2, 3)) == (1, 2, 3)
    True
    """

    __slots__ = ()


def _above_one(spec: object) -> bool:
    """Whether ``spec`` is a tuple or list holding an integer above 1 (so written in
    0..255)."""
    return type(spec) in (tuple, list) and any(
        isinstance(c, numbers.Integral) and not isinstance(c, bool) and int(c) > 1
        for c in cast("Sequence[object]", spec))


def in_context(specs: Sequence[_Spec]) -> Sequence[_Spec | Channels]:
    """The color specs of one list (a batch's colors, a color table) as a whole: when
    any of them is written with integers above 1, the list is in 0..255, and its 0/1
    integer tuples (``(0, 0, 0, 1)`` beside ``(10, 200, 30, 100)``, entry 1 of
    ``[(i, 0, 0) for i in range(256)]``) are meant so and are not questioned.

    Parameters
    ----------
    specs : sequence of colors
        The color specs of one list.

    Returns
    -------
    sequence of colors
        ``specs`` itself when none is written with integers above 1, else a list with
        each tuple or list made a :class:`Channels`.

    Examples
    --------
    >>> from scanline.color.spec import in_context
    >>> in_context([(0, 0, 0, 1), (10, 200, 30, 100)])
    [(0, 0, 0, 1), (10, 200, 30, 100)]
    >>> type(in_context([(0, 0, 1), (10, 200, 30)])[0]).__name__
    'Channels'
    >>> specs = ["red", (0, 0, 1)]
    >>> in_context(specs) is specs          # no integer above 1: left to rgba's check
    True
    """
    if not any(_above_one(s) for s in specs):
        return specs
    return [Channels(cast("Sequence[int]", s)) if type(s) in (tuple, list) else s
            for s in specs]


#: The 0/1 integer colors warned about so far (each distinct color once per process).
_SCALE_WARNED: set[tuple[int, ...]] = set()


def _check_scale(color: object, values: list[Any], name: str) -> None:
    """Warn (:class:`~scanline.ColorScaleWarning`, once per distinct color) when a
    tuple or list typed as integers holds only 0s and 1s and not only 0s:
    ``(1, 0, 0)`` is rgb(1, 0, 0), nearly black, where ``(1.0, 0.0, 0.0)`` (red)
    was most likely meant.  Arrays and :class:`Channels` are data, not literals,
    and are never questioned."""
    if type(color) not in (tuple, list) or not all(c == 0 or c == 1 for c in values) \
            or not any(values):
        return
    key = tuple(int(c) for c in values)
    if key in _SCALE_WARNED:
        return
    _SCALE_WARNED.add(key)
    from .._validate import _caller_level

    floats = "(" + ", ".join(f"{c}.0" for c in key) + ")"
    read = " and ".join(what for what, yes in (
        ("nearly black", any(key[:3])), ("nearly transparent", key[3:] == (1,))) if yes)
    warnings.warn(
        f"{name}={color!r} is read as 0..255 integers: {'rgba' if len(key) == 4 else 'rgb'}"
        f"{key}, {read}; if you "
        f"meant matplotlib's 0..1 form write floats, {name}={floats} (a color written with "
        f"0..255 integers such as (255, 0, 0) does not warn)",
        ColorScaleWarning, stacklevel=_caller_level())


def _from_tuple(color: object, values: list[Any], name: str) -> RGBA:
    if not all(isinstance(c, numbers.Real) and not isinstance(c, bool) for c in values):
        raise ArgumentTypeError(f"{name}={color!r} is not a color; {_TUPLE_HELP}")
    if len(values) not in (3, 4):
        raise ArgumentValueError(
            f"{name}={color!r} has {len(values)} values and is not a color; {_TUPLE_HELP}")
    if all(isinstance(c, numbers.Integral) for c in values):
        if all(0 <= c <= 255 for c in values):
            _check_scale(color, values, name)
            r, g, b, *alpha = (int(c) for c in values)
            return (r, g, b, alpha[0] if alpha else 255)
        raise ArgumentValueError(
            f"{name}={color!r} is not a color; integers must be in 0..255 ({_TUPLE_HELP})")
    # any float: the [0, 1] convention of matplotlib, scikit-image and OpenGL
    if all(math.isfinite(c) and 0.0 <= c <= 1.0 for c in values):
        r, g, b, *alpha = (math.floor(float(c) * 255 + 0.5) for c in values)
        return (r, g, b, alpha[0] if alpha else 255)
    raise ArgumentValueError(
        f"{name}={color!r} is not a color: a tuple holding floats is read as 0..1 "
        "(matplotlib's convention); write 0..255 values as integers, e.g. (255, 128, 0)")


def rgba(color: object, name: str = "color") -> RGBA:
    """Return ``color`` as an ``(r, g, b, a)`` tuple of ints in 0..255.

    A color is a name or a string Pillow reads (CSS names, ``"#rrggbb[aa]"``,
    ``"rgb(...)"``, ``"hsl(...)"``), else one of matplotlib's when matplotlib is
    installed (``"tab:blue"``, ``"C0"``, ``"xkcd:sky blue"``, ``"k"``); a tuple of 3
    or 4 integers in 0..255, or of floats in [0, 1] (any float element makes it the
    [0, 1] form, scaled by 255 and rounded); or an integer gray level 0..255.

    A tuple or list of integers that are all 0 or 1 (``(1, 0, 0)``, not
    ``(0, 0, 0)``) is read as 0..255 -- nearly black -- and gives a
    :class:`~scanline.ColorScaleWarning` once per distinct color, naming the float
    form ``(1.0, 0.0, 0.0)`` that was probably meant.

    Parameters
    ----------
    color : Color
        The color spec (see above; also a NumPy array of 3 or 4 values).
    name : str
        The argument's name, for error messages.

    Returns
    -------
    tuple of int
        ``(r, g, b, a)``, each 0..255; alpha 255 when not given.

    Raises
    ------
    ArgumentValueError
        For an unknown name, a value out of range or a tuple of the wrong length.
    ArgumentTypeError
        For anything that is not a color spec.

    Examples
    --------
    >>> from scanline.color.spec import rgba
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
        if 0 <= int(color) <= 255:
            v = int(color)
            return (v, v, v, 255)
        raise ArgumentValueError(f"{name}={color!r}: a gray level must be in 0..255")
    if isinstance(color, (tuple, list)) or hasattr(color, "__array__"):
        try:
            values = (list(cast("Sequence[Any]", color)) if not hasattr(color, "tolist")
                      else cast(Any, color).tolist())
        except TypeError:
            values = None
        if not isinstance(values, list):
            raise ArgumentTypeError(f"{name}={color!r} is not a color; use {_HELP}")
        return _from_tuple(color, values, name)
    raise ArgumentTypeError(f"{name}={color!r} of type {type(color).__name__} is not a color; use {_HELP}")


def _luma(r: int, g: int, b: int) -> int:
    """ITU-R BT.601 luma, as Pillow's RGB -> L conversion computes it."""
    return (r * 299 + g * 587 + b * 114) // 1000


def pixel_value(color: object, mode: str, name: str = "color") -> tuple[int, ...]:
    """Return the channel values that ``color`` stores in a frame buffer of ``mode``.

    Mode ``"P"`` is handled by the frame buffer itself (it owns the color table);
    here an integer in ``"P"`` is returned unchanged.

    Parameters
    ----------
    color : Color
        The color spec (see :func:`rgba`; in mode ``"1"`` also a bit, 0 or 1).
    mode : {"1", "L", "RGB", "RGBA"}
        The frame buffer's mode.
    name : str
        The argument's name, for error messages.

    Returns
    -------
    tuple of int
        One value per channel: the bit (luma >= 128) in ``"1"``, the ITU-R BT.601
        luma in ``"L"``, ``(r, g, b)`` or ``(r, g, b, a)``.

    Raises
    ------
    ArgumentValueError
        For a color that is not one, or mode ``"P"``.

    Examples
    --------
    >>> from scanline.color.spec import pixel_value
    >>> pixel_value("white", "1"), pixel_value("red", "L"), pixel_value("red", "RGB")
    ((1,), (76,), (255, 0, 0))
    """
    if mode == "1" and isinstance(color, numbers.Integral) and not isinstance(color, bool):
        if int(color) in (0, 1):
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
