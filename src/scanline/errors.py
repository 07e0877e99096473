"""Exceptions raised by scanline.

Every error the package raises on purpose derives from :class:`ScanlineError`, so
``except scanline.ScanlineError`` catches them all.  Bad arguments raise
:class:`ArgumentValueError` or :class:`ArgumentTypeError`, which are also plain
``ValueError`` / ``TypeError``: code that expects the built-in types keeps working.
"""


class ScanlineError(Exception):
    """Base class of every error raised by scanline."""


class ArgumentValueError(ScanlineError, ValueError):
    """An argument has the right type but a value scanline cannot use."""


class ArgumentTypeError(ScanlineError, TypeError):
    """An argument has a type scanline cannot use."""


class PixelIndexError(ScanlineError, IndexError):
    """``fb[x, y]`` names a pixel outside the frame buffer: also a plain
    ``IndexError``; the message names the coordinate and the valid range."""


class OutputError(ScanlineError, OSError):
    """A file could not be written (a full disk, an encoder's failure): also a plain
    ``OSError``; the message names the file asked for, and no file is left."""


class ImageFileError(ArgumentValueError):
    """An image file cannot be read: missing, not an image, truncated or damaged, or
    larger than Pillow's decompression-bomb limit."""


class ScanlineWarning(UserWarning):
    """Base class of every warning scanline gives."""


class AngleWarning(ScanlineWarning):
    """An angle given in radians looks as if it was meant in degrees (a whole number
    beyond one turn, such as ``30`` or ``90``): write ``"30deg"`` or
    ``math.radians(30)``, or pass a float to mean radians."""


class ColorScaleWarning(ScanlineWarning):
    """A color written as integers that are all 0 or 1, such as ``(1, 0, 0)``:
    integers are read as 0..255, so this is nearly black; matplotlib's 0..1 form
    is written with floats, ``(1.0, 0.0, 0.0)``.  Given once per distinct color;
    ``(0, 0, 0)`` (black either way) never warns."""


class DepthSortLoopError(ArgumentValueError):
    """Depth sorting cannot order the polygons: a cyclic overlap or an intersection
    with splitting turned off, or one that splitting cannot resolve (the loop flag
    of the Newell-Newell-Sancha method)."""


class BSPTooLargeError(ArgumentValueError):
    """A BSP tree would need more polygon pieces than its limit allows."""


class MemoryBudgetError(ArgumentValueError):
    """A call would allocate more memory than the budget allows
    (:mod:`scanline.budget`): the message names the argument that sets the size and
    the estimate, and says how to raise the limit."""
