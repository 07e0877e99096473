"""The frame buffer: the raster memory that a raster-scan display refreshes from.

Chapter 1 of the notes ("Raster scan display"): each screen point's intensity is kept
in the refresh buffer or *frame buffer*; with one bit per pixel it is a *bitmap*, with
several bits a *pixmap*.  :class:`FrameBuffer` offers both, in five modes:

====== ============================================ ==============
mode   pixel                                        bits per pixel
====== ============================================ ==============
"1"    one bit, packed 8 pixels to a byte           1
"L"    8-bit gray level                             8
"RGB"  red, green, blue                             24
"RGBA" red, green, blue, alpha                      32
"P"    index into a color table of <= 256 entries   8
====== ============================================ ==============

Device coordinates (DESIGN.md, convention 1): ``x`` to the right, ``y`` up, the
origin at the center of the bottom-left pixel.  Internally rows are stored bottom-up,
so that row ``y`` of the storage is scan line ``y``; only this class knows that.
:meth:`FrameBuffer.to_array` returns image order (top row first), ready for Pillow and
matplotlib.
"""

import contextlib
import io
import numbers
import os
import signal
import tempfile
import threading
from types import FrameType
from typing import Any, BinaryIO, Callable, Iterator, Optional, Sequence, Tuple, Union, cast

import numpy as np
from PIL import Image

from ._typing import ArrayLike, Color, Mode, NDArray, Resample

from . import _validate as v
from . import imagefile
from .color.spec import Channels, in_context, pixel_value, rgba
from .budget import physical_memory
from .errors import (ArgumentTypeError, ArgumentValueError, OutputError, PixelIndexError,
                     ScanlineError)

MODES = ("1", "L", "RGB", "RGBA", "P")

#: A color table as mode ``"P"`` takes it: colors, or an (n, 3) array of RGB rows.
ColorTable = Union[Sequence[Union[Color, Tuple[int, ...]]], NDArray[Any]]
_CHANNELS = {"1": 1, "L": 1, "RGB": 3, "RGBA": 4, "P": 1}

#: The key of the color cache's last entry used, ``(color, name, value)``: a loop that
#: draws in one color finds it by the color object's identity, with no type checks.
_LAST = object()
_BITS = {"1": 1, "L": 8, "RGB": 24, "RGBA": 32, "P": 8}

#: Largest scale factor ``_repr_png_`` uses, and the size (pixels on the longer side)
#: it enlarges a small frame buffer to, so that a 16 x 16 image is visible in a notebook.
_REPR_SIZE = 256
_REPR_SCALE = 16


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def output_path(path: object, name: str = "path") -> str:
    """``path`` (a str or os.PathLike) as a str, checked as the name of a file to
    write: no NUL character, not a folder, in a folder that exists.

    Parameters
    ----------
    path : str or os.PathLike
        The name of the file to write.
    name : str
        The argument's name, for error messages.

    Returns
    -------
    str
        ``path`` as a str.

    Raises
    ------
    ArgumentTypeError
        When ``path`` is not a str or os.PathLike.
    ArgumentValueError
        When it is empty, holds a NUL character, names a folder or lies in a folder
        that does not exist.

    Examples
    --------
    >>> import pathlib
    >>> from scanline.framebuffer import output_path
    >>> output_path(pathlib.Path("picture.png"))
    'picture.png'
    >>> output_path("no-such-folder/picture.png")
    Traceback (most recent call last):
      ...
    scanline.errors.ArgumentValueError: path='no-such-folder/picture.png': the folder ... does not exist
    """
    if not isinstance(path, (str, os.PathLike)):
        raise ArgumentTypeError(f"{name} must be a file name (str or os.PathLike), got "
                                f"{v._show(path)}")
    try:
        path = os.fsdecode(os.fspath(cast("str | os.PathLike[str]", path)))
    except (TypeError, UnicodeDecodeError):
        raise ArgumentTypeError(f"{name} must be a file name, got {v._show(path)}") from None
    if "\0" in path:
        raise ArgumentValueError(f"{name}={path!r} holds a NUL character, which no file name "
                                 "may hold")
    if not path:
        raise ArgumentValueError(f"{name} is empty; give the name of a file to write")
    directory = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(directory):
        raise ArgumentValueError(f"{name}={path!r}: the folder {directory!r} does not exist")
    if os.path.isdir(path):
        raise ArgumentValueError(f"{name}={path!r} is a folder; give the name of a file to write")
    return path


class _Terminated(BaseException):
    """SIGTERM arrived while a file was being written (see :func:`write_atomically`)."""


@contextlib.contextmanager
def _terminate_cleanly() -> Iterator[None]:
    """While the block runs, SIGTERM raises :class:`_Terminated` instead of killing the
    process at once, so that the temporary file is removed; the caller then
    terminates as SIGTERM would.  Only in the main thread, and only where SIGTERM
    has its default action (a server that handles it is left alone)."""
    if (threading.current_thread() is not threading.main_thread()
            or signal.getsignal(signal.SIGTERM) is not signal.SIG_DFL):
        yield
        return

    def terminated(signum: int, frame: Optional[FrameType]) -> None:
        raise _Terminated()

    signal.signal(signal.SIGTERM, terminated)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, signal.SIG_DFL)


def write_atomically(path: Union[str, "os.PathLike[str]"], write: Callable[[BinaryIO], Any]) -> None:
    """Call ``write(file)`` on a temporary file beside ``path``, then rename it.

    A failure (an exception from ``write``, a full disk, Ctrl-C, SIGTERM) leaves
    no file at ``path`` and no temporary file beside it; after SIGTERM the process
    then terminates as the signal asks.  Errors name ``path`` (not the temporary
    file).

    Parameters
    ----------
    path : str or os.PathLike
        The file to write (checked by :func:`output_path`).
    write : callable
        Called once with the temporary file, opened for binary writing.

    Raises
    ------
    ArgumentValueError
        When ``path`` is not a file that can be written (see :func:`output_path`),
        or no file can be made in its folder.
    OutputError
        When writing fails (a full disk, no permission).

    Examples
    --------
    >>> import os, tempfile
    >>> from scanline.framebuffer import write_atomically
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = os.path.join(folder, "out.bin")
    ...     write_atomically(path, lambda f: f.write(b"abc"))
    ...     with open(path, "rb") as f:
    ...         f.read(), os.listdir(folder)
    (b'abc', ['out.bin'])
    """
    path = output_path(path)
    directory = os.path.dirname(os.path.abspath(path))
    try:
        fd, tmp = tempfile.mkstemp(prefix=".scanline-", suffix=".tmp", dir=directory)
    except OSError as error:
        raise ArgumentValueError(f"path={path!r}: cannot create a file in {directory!r} "
                                 f"({error.strerror or error})") from None
    try:
        with _terminate_cleanly():
            with os.fdopen(fd, "wb") as f:
                write(f)
            os.chmod(tmp, 0o666 & ~_umask())  # mkstemp makes 0600; give the usual mode
            os.replace(tmp, path)
    except BaseException as exc:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        if isinstance(exc, _Terminated):
            os.kill(os.getpid(), signal.SIGTERM)   # the default action again: terminate
        if isinstance(exc, OSError) and not isinstance(exc, ScanlineError):
            raise OutputError(f"path={path!r}: cannot write the file "
                              f"({exc.strerror or exc})") from None
        raise


def image_limit() -> int:
    """Most pixels an image file written by scanline may hold: twice Pillow's
    decompression-bomb threshold (``PIL.Image.MAX_IMAGE_PIXELS``, 89,478,485 by
    default), past which Pillow refuses to open the file again.

    Returns
    -------
    int
        The limit in pixels (2**40 when Pillow's threshold is switched off).

    Examples
    --------
    >>> from PIL import Image
    >>> from scanline.framebuffer import image_limit
    >>> image_limit() == 2 * Image.MAX_IMAGE_PIXELS
    True
    """
    bound = Image.MAX_IMAGE_PIXELS
    return 2 * int(bound) if bound else 1 << 40


def check_image_size(width: int, height: int, scale: int = 1, given: Optional[str] = None,
                     hint: Optional[str] = None) -> None:
    """The size rule of every image scanline writes, checked before anything is
    allocated: ``width x height`` pixels enlarged ``scale`` times must fit
    :func:`image_limit`.  ``given`` says how the caller gave the size (for
    instance ``"--size 40000x40000"``, ``"canvas.width x canvas.height"``), so
    that the message names it; ``hint`` says what to change.

    Parameters
    ----------
    width, height : int
        The size in pixels before enlarging.
    scale : int
        The whole factor each pixel is enlarged by.
    given : str, optional
        How the caller gave the size, named in the message.
    hint : str, optional
        What to change, ending the message (default: use a smaller size).

    Raises
    ------
    ArgumentValueError
        When ``width * height * scale**2`` is more than :func:`image_limit`.

    Examples
    --------
    >>> from scanline.framebuffer import check_image_size
    >>> check_image_size(640, 480, scale=4)
    >>> check_image_size(100000, 100000, given="--size 100000x100000")
    Traceback (most recent call last):
      ...
    scanline.errors.ArgumentValueError: --size 100000x100000 is 10,000,000,000 pixels, more than the ... an image file may hold; use a smaller size
    """
    pixels = width * height * scale * scale
    limit = image_limit()
    if pixels <= limit:
        return
    given = given or f"width x height = {width} x {height}"
    made = f" enlarged {scale} times, {width * scale} x {height * scale}," if scale > 1 else ""
    raise ArgumentValueError(
        f"{given}{made} is {pixels:,} pixels, more than the {limit:,} an image file may hold; "
        + (hint or "use a smaller size" + (" or scale" if scale > 1 else "")))


def _row_bytes(width: int, height: int, mode: str, given: Optional[str] = None) -> int:
    """Bytes per storage row of a ``width`` x ``height`` frame buffer of ``mode``,
    after checking that the size is within the coordinate limit and fits the
    machine's memory (``given`` says how the caller gave the size, for messages)."""
    for name, size in (("width", width), ("height", height)):
        if size > v.COORD_LIMIT:
            raise ArgumentValueError(f"{given + ': ' if given else ''}{name}={size} is larger "
                                     f"than the limit {v.COORD_LIMIT}")
    row_bytes = (width + 7) // 8 if mode == "1" else width
    nbytes = height * row_bytes * _CHANNELS[mode]
    available = physical_memory()
    if nbytes > available:
        raise ArgumentValueError(
            f"{given or 'width x height'} = {width} x {height} in mode {mode!r} needs "
            f"{nbytes:,} bytes, more than this machine's {available:,} bytes of memory; "
            "use a smaller size")
    return row_bytes


#: ``resample=`` names of :meth:`FrameBuffer.resize` and Pillow's filters.
RESAMPLE = {"nearest": Image.Resampling.NEAREST, "box": Image.Resampling.BOX,
            "bilinear": Image.Resampling.BILINEAR, "hamming": Image.Resampling.HAMMING,
            "bicubic": Image.Resampling.BICUBIC, "lanczos": Image.Resampling.LANCZOS}


class FrameBuffer:
    """A width x height raster of pixels in one of the modes ``"1"``, ``"L"``,
    ``"RGB"``, ``"RGBA"`` and ``"P"``.

    Parameters
    ----------
    width, height : int
        Size in pixels, each >= 1.
    mode : str
        Pixel format (see the module docstring).
    background : color
        Initial color of every pixel, also used by :meth:`clear`.
    color_table : sequence of colors, optional
        Mode ``"P"`` only: the initial color table (at most 256 entries).  Without it
        the table starts with just the background color; drawing with a color that is
        not in the table appends it.

    Notes
    -----
    Notes, chapter 1, "Raster scan display" (frame buffer, bitmap, pixmap) and
    "Color-tables" in the syllabus: in mode ``"P"`` the frame buffer stores indices
    and the color table maps them to RGB, so editing the table recolors the image
    without touching a pixel.

    Examples
    --------
    >>> fb = FrameBuffer(4, 3, mode="L")
    >>> fb.set_pixel(0, 0, 255)          # bottom-left pixel
    >>> fb.to_array()                    # image order: top row first
    array([[  0,   0,   0,   0],
           [  0,   0,   0,   0],
           [255,   0,   0,   0]], dtype=uint8)
    """

    def __init__(self, width: int, height: int, mode: Mode = "RGB", background: Color = "black",
                 color_table: Optional[ColorTable] = None) -> None:
        width = v.positive_int("width", width)
        height = v.positive_int("height", height)
        v.choice("mode", mode, MODES)
        row_bytes = _row_bytes(width, height, mode)
        self._width = width
        self._height = height
        self._mode = mode
        self._table = np.zeros((0, 3), np.uint8)
        self._cache: dict[object, Any] = {}
        if mode == "P" and color_table is not None:
            self.color_table = color_table
        elif color_table is not None:
            raise ArgumentValueError(f"color_table is only for mode 'P', not mode {mode!r}")
        if background is None:
            raise ArgumentTypeError("background=None is not a color; use a color such as 'black'")
        self._background = self.pixel(background, "background")
        self._buf = np.empty((height, row_bytes, _CHANNELS[mode]), np.uint8)
        self.clear()

    # -- properties -------------------------------------------------------------------
    @property
    def width(self) -> int:
        """Width in pixels."""
        return self._width

    @property
    def height(self) -> int:
        """Height in pixels."""
        return self._height

    @property
    def size(self) -> Tuple[int, int]:
        """``(width, height)``."""
        return (self._width, self._height)

    @property
    def mode(self) -> Mode:
        """Pixel format: ``"1"``, ``"L"``, ``"RGB"``, ``"RGBA"`` or ``"P"``."""
        return self._mode

    @property
    def bits_per_pixel(self) -> int:
        """Bits of frame-buffer memory per pixel: 1, 8, 24, 32 or 8 (``"P"``)."""
        return _BITS[self._mode]

    @property
    def nbytes(self) -> int:
        """Memory size of the pixel storage in bytes (mode ``"1"`` rows are padded to
        whole bytes; the color table of mode ``"P"`` is not counted).

        >>> FrameBuffer(640, 480, mode="1").nbytes, FrameBuffer(640, 480).nbytes
        (38400, 921600)
        """
        return self._buf.nbytes

    def __repr__(self) -> str:
        return f"FrameBuffer({self._width}, {self._height}, mode={self._mode!r})"

    @property
    def foreground(self) -> Color:
        """The color drawn where no color is given (``color=None``, the default of
        every drawing function): white on a dark background, black on a light one
        (luma below 128 is dark, in mode ``"1"`` the bit 0), so that a default drawing
        is never invisible.

        >>> FrameBuffer(4, 4).foreground, FrameBuffer(4, 4, background="white").foreground
        ('white', 'black')
        """
        if self._mode == "1":
            dark = not self._background[0]
        else:
            rgb = self._table[self._background[0]] if self._mode == "P" else self._background
            r, g, b = (int(c) for c in (rgb[:3] if len(rgb) >= 3 else (rgb[0],) * 3))
            dark = (r * 299 + g * 587 + b * 114) // 1000 < 128
        return "white" if dark else "black"

    # -- colors -----------------------------------------------------------------------
    def pixel(self, color: Optional[Union[Color, Channels]],
              name: str = "color") -> NDArray[np.uint8]:
        """Return the stored channel values of ``color`` as a uint8 array.

        In mode ``"P"`` an integer is a color-table index; any other color is looked
        up in the table and appended to it when absent.  ``None`` is
        :attr:`foreground`.

        Parameters
        ----------
        color : Color, Channels or None
            The color (see :func:`scanline.color.spec.rgba`; the package passes
            channel values it read as :class:`~scanline.color.spec.Channels`); None
            for :attr:`foreground`.
        name : str
            The argument's name, for error messages.

        Returns
        -------
        numpy.ndarray
            uint8, one value per stored channel (a bit, a gray level, a table index,
            RGB or RGBA); do not write to it (it is cached).

        Raises
        ------
        ArgumentValueError
            For a color that is not one, or a new color in a full color table.

        Examples
        --------
        >>> FrameBuffer(2, 2, mode="L").pixel("red")      # luma (299 * 255) // 1000
        array([76], dtype=uint8)
        >>> fb = FrameBuffer(2, 2, mode="P")             # table: black
        >>> fb.pixel("red"), fb.color_table.tolist()
        (array([1], dtype=uint8), [[0, 0, 0], [255, 0, 0]])
        """
        last = self._cache.get(_LAST)
        if last is not None and color is last[0] and name == last[1]:
            return cast("NDArray[np.uint8]", last[2])      # the very object of the last cached call (immutable)
        if color is None:
            color = self.foreground
        # cache exact types only: True == 1 and (1.0, 2) == (1, 2) must not share
        # an entry, and a tuple holding a list must not be hashed
        cacheable = type(color) in (str, int) or (
            type(color) is tuple and all(type(c) is int for c in color))
        key = (color, name)
        if cacheable:
            hit = self._cache.get(key)
            if hit is not None:
                self._cache[_LAST] = (color, name, hit)
                return cast("NDArray[np.uint8]", hit)
        value: Tuple[int, ...]
        if self._mode == "P":
            value = (self._table_index(color, name),)
        else:
            value = pixel_value(color, self._mode, name)
        out: NDArray[np.uint8] = np.array(value, np.uint8)
        if cacheable:
            self._cache[key] = out
            self._cache[_LAST] = (color, name, out)
        return out

    def _table_index(self, color: Union[Color, Channels], name: str) -> int:
        if isinstance(color, int) and not isinstance(color, bool):
            if 0 <= color < len(self._table):
                return color
            raise ArgumentValueError(
                f"{name}={color}: mode 'P' reads an integer as a color-table index, "
                f"and the table has {len(self._table)} entries (0..{len(self._table) - 1})"
            )
        rgb = rgba(color, name)[:3]
        hits = np.flatnonzero((self._table == rgb).all(axis=1))
        if hits.size:
            return int(hits[0])
        if len(self._table) >= 256:
            raise ArgumentValueError(
                f"{name}={color!r} is not in the color table, which is full (256 entries); "
                "draw with an existing index or change an entry with set_table_entry()"
            )
        self._table = np.vstack([self._table, np.array([rgb], np.uint8)])
        return len(self._table) - 1

    @property
    def color_table(self) -> NDArray[np.uint8]:
        """Mode ``"P"``: a copy of the color table, shape (n, 3), uint8 RGB.

        Assigning a sequence of colors replaces the table; the stored indices stay,
        so the image is recolored.
        """
        self._require_p("color_table")
        return np.array(self._table)

    @color_table.setter
    def color_table(self, colors: ColorTable) -> None:
        self._require_p("color_table")
        entries = in_context(list(colors))
        if not 1 <= len(entries) <= 256:
            raise ArgumentValueError(f"color_table must have 1..256 entries, got {len(entries)}")
        table = np.array([rgba(c, f"color_table[{i}]")[:3] for i, c in enumerate(entries)],
                         np.uint8)
        if hasattr(self, "_buf") and self._buf.size and int(self._buf.max()) >= len(table):
            raise ArgumentValueError(
                f"color_table has {len(table)} entries but the image uses index "
                f"{int(self._buf.max())}; give at least {int(self._buf.max()) + 1} entries"
            )
        self._table = table
        self._cache.clear()

    def set_table_entry(self, index: int, color: Color) -> None:
        """Mode ``"P"``: set color-table entry ``index`` to ``color`` (recolors every
        pixel that stores that index).  ``index`` may be the next free entry.

        Parameters
        ----------
        index : int
            The entry, 0 .. the table's length (the next free entry), at most 255.
        color : Color
            Its new color (alpha is dropped).

        Raises
        ------
        ArgumentValueError
            When the frame buffer is not in mode ``"P"`` or ``index`` is out of range.

        Examples
        --------
        >>> fb = FrameBuffer(2, 1, mode="P", color_table=["black", "white"])
        >>> fb[1, 0] = 1
        >>> fb.set_table_entry(1, "red")
        >>> fb.to_pil().convert("RGB").getpixel((1, 0))
        (255, 0, 0)
        """
        self._require_p("set_table_entry")
        index = v.positive_int("index", index, minimum=0)
        if index > len(self._table) or index > 255:
            raise ArgumentValueError(
                f"index={index}: the color table has {len(self._table)} entries; "
                f"use 0..{min(len(self._table), 255)}"
            )
        rgb = np.array([rgba(color)[:3]], np.uint8)
        self._table = np.vstack([self._table, rgb]) if index == len(self._table) else self._table
        self._table[index] = rgb[0]
        self._cache.clear()

    def _require_p(self, what: str) -> None:
        if self._mode != "P":
            raise ArgumentValueError(f"{what} exists only in mode 'P', this frame buffer is {self._mode!r}")

    # -- pixels -----------------------------------------------------------------------
    def _raster(self) -> Tuple[NDArray[np.uint8], bool]:
        """Storage for the kernels: ``(buf, packed)``; ``buf[y, x]`` is pixel (x, y),
        or in mode ``"1"`` the byte holding it (most significant bit first)."""
        return self._buf, self._mode == "1"

    def clear(self, color: Optional[Color] = None) -> None:
        """Set every pixel to ``color`` (default: the background).

        Parameters
        ----------
        color : Color, optional
            The color; None (the default) is the background given when the frame
            buffer was made.

        Examples
        --------
        >>> fb = FrameBuffer(3, 1, mode="L", background=9)
        >>> fb.clear(200)
        >>> fb.to_array().tolist()
        [[200, 200, 200]]
        >>> fb.clear()
        >>> fb.to_array().tolist()
        [[9, 9, 9]]
        """
        value = self._background if color is None else self.pixel(color)
        if self._mode == "1":
            self._buf.fill(0xFF if value[0] else 0)
        elif (value == value[0]).all():
            self._buf.fill(value[0])
        else:
            # one row of pixels, then every row from it: broadcasting the pixel value
            # over the whole (H, W, C) array directly is about 20 times slower
            self._buf[...] = np.tile(value, (self._buf.shape[1], 1))

    def _check_xy(self, x: float, y: float) -> Tuple[int, int, bool]:
        x = v.coordinate("x", x)
        y = v.coordinate("y", y)
        return x, y, 0 <= x < self._width and 0 <= y < self._height

    def set_pixel(self, x: float, y: float, color: Color) -> None:
        """Set pixel ``(x, y)`` to ``color``.

        One rule for both pixel methods, the rule of every drawing operation: a
        pixel outside the frame buffer is clipped.  ``set_pixel`` writes nothing
        there and :meth:`get_pixel` returns its ``default`` (None).  The color is
        checked either way.

        Parameters
        ----------
        x, y : float
            The pixel in device coordinates (x right, y up); floats round to the
            nearest pixel.
        color : Color
            Its color.

        Raises
        ------
        ArgumentTypeError
            When ``color`` is None, or a coordinate is not a number.
        ArgumentValueError
            When ``color`` is not a color.

        Examples
        --------
        >>> fb = FrameBuffer(3, 2, mode="L")
        >>> fb.set_pixel(2, 1, 255)
        >>> fb.set_pixel(7, 7, 255)          # outside: clipped, no error
        >>> fb.to_array().tolist()
        [[0, 0, 255], [0, 0, 0]]
        """
        xi, yi, inside = self._check_xy(x, y)
        if color is None:
            raise ArgumentTypeError("color=None: set_pixel needs a color, e.g. fb.foreground")
        value = self.pixel(color)
        if not inside:
            return
        if self._mode == "1":
            bit = 0x80 >> (xi & 7)
            byte = int(self._buf[yi, xi >> 3, 0])
            self._buf[yi, xi >> 3, 0] = (byte | bit) if value[0] else (byte & ~bit & 0xFF)
        else:
            self._buf[yi, xi] = value

    def get_pixel(self, x: float, y: float, default: Any = None) -> Any:
        """Return pixel ``(x, y)``: an int in modes ``"1"``, ``"L"`` and ``"P"`` (bit,
        gray level, color-table index), a tuple in ``"RGB"`` and ``"RGBA"``.

        A pixel outside the frame buffer is clipped, as :meth:`set_pixel` clips it:
        the result is ``default`` (None unless given, like ``dict.get``).

        Parameters
        ----------
        x, y : float
            The pixel in device coordinates (x right, y up); floats round to the
            nearest pixel.
        default : object
            What a pixel outside the frame buffer gives.

        Returns
        -------
        int, tuple of int or ``default``
            The stored value: an int in modes ``"1"``, ``"L"`` and ``"P"``, an
            ``(r, g, b[, a])`` tuple in ``"RGB"`` and ``"RGBA"``.

        Examples
        --------
        >>> fb = FrameBuffer(2, 2, mode="L")
        >>> fb.get_pixel(1, 1), fb.get_pixel(5, 0), fb.get_pixel(-1, 0, default=0)
        (0, None, 0)
        >>> FrameBuffer(1, 1, background=(10, 20, 30)).get_pixel(0, 0)
        (10, 20, 30)
        """
        xi, yi, inside = self._check_xy(x, y)
        if not inside:
            return default
        if self._mode == "1":
            return int(self._buf[yi, xi >> 3, 0] >> (7 - (xi & 7))) & 1
        values = self._buf[yi, xi]
        return int(values[0]) if values.size == 1 else tuple(int(c) for c in values)

    # -- indexing: fb[x, y] -----------------------------------------------------------------
    def _index(self, key: object) -> Tuple[int, int]:
        """``(x, y)`` of ``fb[x, y]``: two integers inside the frame buffer, else the
        error Python's indexing gives (TypeError, IndexError) naming the coordinate."""
        if isinstance(key, slice) or (isinstance(key, tuple) and any(
                isinstance(k, slice) for k in key)):
            raise ArgumentTypeError(
                f"fb[{_show_key(key)}]: a frame buffer is indexed by one pixel, fb[x, y]; for a "
                "block use fb.crop(x0, y0, x1, y1) (corners included) or fb.to_array()")
        if not (isinstance(key, tuple) and len(key) == 2):
            raise ArgumentTypeError(
                f"fb[{_show_key(key)}]: index a frame buffer by a pixel's device coordinates, "
                "fb[x, y] (x to the right, y up, (0, 0) the bottom-left pixel)")
        out = []
        for name, given, size in (("x", key[0], self._width), ("y", key[1], self._height)):
            if isinstance(given, bool) or not isinstance(given, numbers.Integral):
                raise ArgumentTypeError(
                    f"fb[x, y]: {name} must be an integer, got {v._show(given)} of type "
                    f"{type(given).__name__} (get_pixel and set_pixel round a float to the "
                    "nearest pixel)")
            value = int(given)
            if not 0 <= value < size:
                raise PixelIndexError(
                    f"fb[x, y]: {name}={value} is outside the frame buffer, whose "
                    f"{'columns' if name == 'x' else 'rows'} are {name} = 0..{size - 1} "
                    f"({'width' if name == 'x' else 'height'} {size}); device coordinates "
                    f"count from the {'left' if name == 'x' else 'bottom'} and are never "
                    "negative inside it (get_pixel and set_pixel clip instead of raising)")
            out.append(value)
        return out[0], out[1]

    def __getitem__(self, key: Tuple[int, int]) -> Any:
        """``fb[x, y]``: pixel ``(x, y)`` in device coordinates (x right, y up), as
        :meth:`get_pixel` returns it (an int in modes ``"1"``, ``"L"``, ``"P"``, a
        tuple in ``"RGB"`` and ``"RGBA"``).

        Unlike :meth:`get_pixel`, which clips, a pixel outside the frame buffer is an
        ``IndexError`` (:class:`scanline.errors.PixelIndexError`) naming the
        coordinate, and the coordinates must be integers.  A negative coordinate
        is left of (below) the frame buffer, not counted from the end as in a list.
        Slices are not taken: use :meth:`crop` or :meth:`to_array`.

        >>> fb = FrameBuffer(3, 2, mode="L")
        >>> fb[2, 0] = 200
        >>> fb[2, 0], fb[0, 1]
        (200, 0)
        """
        x, y = self._index(key)
        return self.get_pixel(x, y)

    def __setitem__(self, key: Tuple[int, int], color: Color) -> None:
        """``fb[x, y] = color``: set pixel ``(x, y)`` as :meth:`set_pixel` does,
        with the coordinate checks of :meth:`__getitem__`."""
        x, y = self._index(key)
        self.set_pixel(x, y, color)

    #: A frame buffer is not a sequence: ``fb[x, y]`` takes two coordinates.
    __iter__ = None

    # -- copies, crops and sizes ---------------------------------------------------------
    def _like(self, width: int, height: int, given: Optional[str] = None) -> "FrameBuffer":
        """A new cleared ``width`` x ``height`` frame buffer with this one's mode,
        background and color table."""
        row_bytes = _row_bytes(width, height, self._mode, given)
        out = object.__new__(type(self))
        out.__dict__.update(self.__dict__)
        out._width, out._height = width, height
        out._table = self._table.copy()
        out._background = self._background.copy()
        out._cache = {}
        out._buf = np.empty((height, row_bytes, _CHANNELS[self._mode]), np.uint8)
        out.clear()
        return out

    def copy(self) -> "FrameBuffer":
        """An independent copy: the same size, mode, background, color table and
        pixels; drawing into one leaves the other alone (``copy.copy(fb)`` and
        ``copy.deepcopy(fb)`` give the same).

        Returns
        -------
        FrameBuffer
            The copy.

        Examples
        --------
        >>> fb = FrameBuffer(2, 1, mode="L")
        >>> twin = fb.copy()
        >>> twin[0, 0] = 9
        >>> fb[0, 0], twin[0, 0]
        (0, 9)
        """
        out = object.__new__(type(self))
        out.__dict__.update(self.__dict__)
        out._buf = self._buf.copy()
        out._table = self._table.copy()
        out._background = self._background.copy()
        out._cache = {}
        return out

    def __copy__(self) -> "FrameBuffer":
        return self.copy()

    def __deepcopy__(self, memo: Any) -> "FrameBuffer":
        return self.copy()

    def crop(self, x0: int, y0: int, x1: int, y1: int) -> "FrameBuffer":
        """The block of pixels from corner ``(x0, y0)`` to corner ``(x1, y1)``, both
        included, as a new frame buffer of the same mode, background and color table.

        Device coordinates (x right, y up): the block holds columns x0..x1 and rows
        y0..y1, ``x1 - x0 + 1`` by ``y1 - y0 + 1`` pixels, and its pixel (0, 0) is
        pixel (x0, y0) here.  Corners are pixels, as in
        :func:`scanline.draw.rectangle` (which fills exactly these pixels) and
        :func:`scanline.draw.line`; either corner may come first.  Floats round to
        the nearest pixel center.  What lies outside this frame buffer is the
        background color (Pillow's ``crop`` pads the same way, with zeros), so the
        size is always the one asked for.

        Pillow's ``Image.crop((left, upper, right, lower))`` counts rows from the
        top and excludes ``right`` and ``lower``: ``fb.crop(x0, y0, x1, y1)`` is
        ``fb.to_pil().crop((x0, height - 1 - y1, x1 + 1, height - y0))``.

        Parameters
        ----------
        x0, y0 : int
            One corner pixel, included.
        x1, y1 : int
            The opposite corner pixel, included.

        Returns
        -------
        FrameBuffer
            ``|x1 - x0| + 1`` by ``|y1 - y0| + 1`` pixels.

        Raises
        ------
        ArgumentValueError
            When the block is larger than the coordinate limit or this machine's
            memory.

        Examples
        --------
        >>> fb = FrameBuffer(4, 3, mode="L")
        >>> fb[1, 0] = 7
        >>> fb.crop(1, 0, 2, 1).to_array()
        array([[0, 0],
               [7, 0]], dtype=uint8)
        """
        x0, y0 = v.coordinate("x0", x0), v.coordinate("y0", y0)
        x1, y1 = v.coordinate("x1", x1), v.coordinate("y1", y1)
        x0, x1 = min(x0, x1), max(x0, x1)
        y0, y1 = min(y0, y1), max(y0, y1)
        width, height = x1 - x0 + 1, y1 - y0 + 1
        out = self._like(width, height, f"crop({x0}, {y0}, {x1}, {y1}): width x height")
        ax0, ay0 = max(x0, 0), max(y0, 0)
        ax1, ay1 = min(x1, self._width - 1), min(y1, self._height - 1)
        if ax0 > ax1 or ay0 > ay1:
            return out
        rows, cols = slice(ay0 - y0, ay1 - y0 + 1), slice(ax0 - x0, ax1 - x0 + 1)
        if self._mode == "1":
            src = np.unpackbits(self._buf[ay0:ay1 + 1, :, 0], axis=1,
                                count=self._width)[:, ax0:ax1 + 1]
            dst = np.unpackbits(out._buf[:, :, 0], axis=1, count=width)
            dst[rows, cols] = src
            out._buf[:, :, 0] = np.packbits(dst, axis=1)
        else:
            out._buf[rows, cols] = self._buf[ay0:ay1 + 1, ax0:ax1 + 1]
        return out

    def resize(self, width: int, height: int, resample: Resample = "nearest") -> "FrameBuffer":
        """A new ``width`` x ``height`` frame buffer holding this image scaled by
        Pillow's ``Image.resize``, in the same mode (background and color table kept).

        Parameters
        ----------
        width, height : int
            The new size, each >= 1.
        resample : {"nearest", "box", "bilinear", "hamming", "bicubic", "lanczos"}
            Pillow's filter.  ``"nearest"`` (the default) copies pixels: an
            enlargement by a whole factor turns each pixel into a block, as
            scan-converted pixels are best looked at.

        Notes
        -----
        Modes ``"L"``, ``"RGB"`` and ``"RGBA"`` are filtered as Pillow filters them
        (RGBA with premultiplied alpha).  The stored values of the other two modes
        cannot be averaged, and Pillow would fall back to ``"nearest"`` for them; here
        a mode ``"1"`` image is filtered as gray levels and each pixel set where the
        result is >= 128 (the mode's rule for colors), and a mode ``"P"`` image is
        filtered in RGB and each pixel set to the nearest color-table entry
        (smallest squared RGB distance, the lower index on a tie).  With
        ``"nearest"`` both keep their stored values.

        Returns
        -------
        FrameBuffer
            The scaled image, ``width`` x ``height``.

        Examples
        --------
        >>> fb = FrameBuffer(2, 1, mode="L")
        >>> fb[0, 0] = 255
        >>> fb.resize(4, 2).to_array()
        array([[255, 255,   0,   0],
               [255, 255,   0,   0]], dtype=uint8)
        """
        width = v.positive_int("width", width)
        height = v.positive_int("height", height)
        method = v.choice("resample", resample, tuple(RESAMPLE))
        out = self._like(width, height, "resize(width, height)")
        size, flt = (width, height), RESAMPLE[method]
        if self._mode == "1":
            if method == "nearest":
                bits = np.asarray(self.to_pil().resize(size, flt), dtype=bool)
            else:
                gray = Image.fromarray(self.to_array().astype(np.uint8) * 255)
                bits = np.asarray(gray.resize(size, flt)) >= 128
            out._buf[:, :, 0] = np.packbits(bits[::-1], axis=1)
        elif self._mode == "P":
            if method == "nearest":
                index = np.asarray(Image.fromarray(self.to_array()).resize(size, flt))
            else:
                rgb = np.asarray(self.to_pil().convert("RGB").resize(size, flt))
                index = _nearest_entries(rgb, self._table)
            out._buf[:, :, 0] = index[::-1]
        else:
            image = np.asarray(self.to_pil().resize(size, flt))
            out._buf[...] = image[::-1].reshape(out._buf.shape)
        return out

    def show(self, title: Optional[str] = None, scale: Optional[int] = None) -> None:
        """Open the image in the system's image viewer, through Pillow's
        ``Image.show`` (a temporary PNG handed to the platform's viewer; nothing
        happens where there is none, as on a headless server).

        ``scale`` enlarges each pixel to a ``scale`` x ``scale`` block; by default a
        small frame buffer is enlarged as in a notebook (a whole factor, at most 16,
        to about 256 pixels on the longer side).  In Jupyter there is no need to call
        this: a frame buffer that ends a cell is shown as an image
        (``_repr_png_``), enlarged the same way.

        Parameters
        ----------
        title : str, optional
            The viewer window's title, where the viewer takes one.
        scale : int, optional
            Enlarge each pixel to a ``scale`` x ``scale`` block (default: as in a
            notebook).

        Raises
        ------
        ArgumentValueError
            When the enlarged image would pass :func:`image_limit`.

        Examples
        --------
        >>> FrameBuffer(16, 16).show(scale=8)      # doctest: +SKIP
        """
        if scale is None:
            scale = self._repr_scale()
        self._scaled_image(scale).show(title=title)

    # -- arrays and images --------------------------------------------------------------
    def __array__(self, dtype: Any = None, copy: Optional[bool] = None) -> NDArray[Any]:
        """The numpy array protocol: ``np.asarray(fb)`` is the image in image order,
        as :meth:`to_array` gives it.

        Without a copy where the storage allows one (modes ``"L"``, ``"P"``, ``"RGB"``
        and ``"RGBA"``): a read-only view of the pixels, which follows later drawing;
        ``np.array(fb)`` (or ``copy=True``) gives a writable copy.  Mode ``"1"``
        stores packed bits, so its bool array is always a new array
        (``copy=False`` raises ``ValueError``, as numpy asks).

        >>> import numpy as np
        >>> fb = FrameBuffer(3, 2, mode="L")
        >>> fb.set_pixel(0, 0, 7)
        >>> np.asarray(fb)
        array([[0, 0, 0],
               [7, 0, 0]], dtype=uint8)
        """
        if self._mode == "1":
            if copy is False:
                raise ValueError("a mode '1' frame buffer stores packed bits: its bool "
                                 "array is always a copy")
            a = self.to_array()
        else:
            a = self._buf[::-1]
            a = a[:, :, 0] if self._mode in ("L", "P") else a
            if copy:
                a = a.copy()
            else:
                a = a.view()
                a.flags.writeable = False
        if dtype is not None and np.dtype(dtype) != a.dtype:
            if copy is False:
                raise ValueError(f"the pixels are {a.dtype}; a {np.dtype(dtype)} array is a copy")
            a = a.astype(dtype)
        return a

    def to_array(self) -> NDArray[Any]:
        """A copy of the pixels in image order (top row first).

        Shape (height, width) for modes ``"1"`` (bool), ``"L"`` and ``"P"`` (uint8
        indices), (height, width, 3 or 4) for ``"RGB"`` and ``"RGBA"``.

        Returns
        -------
        numpy.ndarray
            bool in mode ``"1"``, else uint8; a new array.

        Examples
        --------
        >>> fb = FrameBuffer(2, 2, mode="1")
        >>> fb.set_pixel(0, 0, 1)
        >>> fb.to_array()
        array([[False, False],
               [ True, False]])
        >>> FrameBuffer(1, 1, background="red").to_array().shape
        (1, 1, 3)
        """
        rows = self._buf[::-1]
        if self._mode == "1":
            return np.unpackbits(rows[:, :, 0], axis=1, count=self._width).astype(bool)
        if self._mode in ("L", "P"):
            return np.array(rows[:, :, 0])
        return np.array(rows)

    @classmethod
    def from_array(cls, array: ArrayLike, mode: Optional[Mode] = None,
                   color_table: Optional[ColorTable] = None) -> "FrameBuffer":
        """Make a frame buffer from an image-order array (the inverse of :meth:`to_array`).

        The mode follows from the array's shape: 2-D -> ``"L"`` (bool: ``"1"``; or
        ``"P"`` when ``mode="P"`` and a ``color_table`` is given), (h, w, 1) -> the
        same as 2-D, (h, w, 3) -> ``"RGB"``, (h, w, 4) -> ``"RGBA"``.

        Values: integers 0..255 (uint8 or any integer dtype), bools (mode ``"1"``),
        or floats in [0, 1] as matplotlib and scikit-image store images, scaled to
        0..255 and rounded (``floor(255 v + 0.5)``).  Anything else (a float above
        1 or NaN, an integer above 255) is refused, not clipped.

        Parameters
        ----------
        array : array_like
            The image, top row first: (h, w), (h, w, 1), (h, w, 3) or (h, w, 4).
        mode : {"1", "L", "RGB", "RGBA", "P"}, optional
            The mode; by default it follows from the shape and dtype.
        color_table : sequence of colors, optional
            Mode ``"P"``: the colors of the indices the array holds.

        Returns
        -------
        FrameBuffer
            A new frame buffer holding the pixels.

        Raises
        ------
        ArgumentValueError
            For a shape that is not an image, values out of range, a mode the array
            cannot hold, or mode ``"P"`` without a long enough color table.

        Examples
        --------
        >>> FrameBuffer.from_array([[0.0, 0.5], [1.0, 0.25]]).to_array()
        array([[  0, 128],
               [255,  64]], dtype=uint8)
        """
        a = np.asarray(array)
        if a.ndim == 3 and a.shape[2] == 1:
            a = a[:, :, 0]
        if a.ndim not in (2, 3) or a.shape[0] < 1 or a.shape[1] < 1:
            raise ArgumentValueError(
                f"array must be (h, w), (h, w, 1), (h, w, 3) or (h, w, 4) and non-empty, "
                f"got shape {a.shape}")
        inferred = (
            "1" if a.dtype == bool and a.ndim == 2
            else "L" if a.ndim == 2
            else {3: "RGB", 4: "RGBA"}.get(a.shape[2])
        )
        if inferred is None:
            raise ArgumentValueError(
                f"array of shape {a.shape} is not an image; use (h, w), (h, w, 1), (h, w, 3) "
                "or (h, w, 4)")
        mode = cast(Mode, inferred if mode is None else v.choice("mode", mode, MODES))
        if (mode != inferred and not (mode == "P" and inferred == "L")):
            raise ArgumentValueError(
                f"array of shape {a.shape} and dtype {a.dtype} does not hold mode {mode!r} pixels; "
                "use bool (h, w) for '1', (h, w) for 'L' or 'P', (h, w, 3|4) for 'RGB'/'RGBA'"
            )
        if a.dtype.kind == "f":
            if mode == "P":
                raise ArgumentValueError(
                    f"array of dtype {a.dtype}: mode 'P' needs integer color-table indices")
            a = _unit_floats(a)
        elif a.dtype != bool and a.dtype != np.uint8:
            if a.dtype.kind not in "iu":
                raise ArgumentValueError(
                    f"array of dtype {a.dtype} holds no pixels; use uint8 (or any integer "
                    "dtype) values 0..255, bools, or floats in [0, 1]")
            low, high = int(a.min()), int(a.max())
            if low < 0 or high > 255:
                raise ArgumentValueError(
                    f"array of dtype {a.dtype} holds values {low}..{high}; integers must be "
                    "in 0..255 (16-bit images: divide by 257 first)")
        if mode == "P" and color_table is None:
            raise ArgumentValueError("mode 'P' needs a color_table for the indices in array")
        if mode == "P":
            assert color_table is not None        # refused just above
            color_table = list(color_table)
            top = int(a.max())
            if top >= len(color_table):
                raise ArgumentValueError(
                    f"array holds color-table index {top} but color_table has "
                    f"{len(color_table)} entries (0..{len(color_table) - 1}); give at least "
                    f"{top + 1} entries")
        fb = cls(a.shape[1], a.shape[0], mode=mode, color_table=color_table)
        if mode == "1":
            fb._buf[:, :, 0] = np.packbits(a[::-1], axis=1)
        else:
            fb._buf[...] = a[::-1].reshape(fb._buf.shape)
        return fb

    def to_pil(self) -> Image.Image:
        """The image as a Pillow ``Image`` (modes map one to one).

        Returns
        -------
        PIL.Image.Image
            A new image of the same mode and size (mode ``"P"`` with the color table
            as its palette).

        Examples
        --------
        >>> fb = FrameBuffer(3, 2, mode="L")
        >>> fb.set_pixel(0, 0, 200)               # bottom left: Pillow's row 1
        >>> image = fb.to_pil()
        >>> image.mode, image.size, image.getpixel((0, 1))
        ('L', (3, 2), 200)
        """
        h, w = self._height, self._width
        if self._mode == "1":
            return Image.frombytes("1", (w, h), np.ascontiguousarray(self._buf[::-1]).tobytes())
        if self._mode == "P":
            img = Image.frombytes("P", (w, h), self.to_array().tobytes())
            img.putpalette(self._table.tobytes())
            return img
        return Image.fromarray(self.to_array())

    @classmethod
    def from_pil(cls, image: Image.Image) -> "FrameBuffer":
        """Make a frame buffer from a Pillow ``Image``.  Modes ``1``, ``L``, ``P``,
        ``RGB`` and ``RGBA`` map directly (a ``P`` image with a transparent color
        becomes ``RGBA``); 16-bit gray (``I;16``, and ``I`` holding 0..65535) keeps
        its high byte as ``L``; other modes are converted by Pillow to ``L`` (``F``),
        ``RGB``, or ``RGBA`` when they carry transparency.

        Parameters
        ----------
        image : PIL.Image.Image
            The image.

        Returns
        -------
        FrameBuffer
            A new frame buffer holding its pixels.

        Raises
        ------
        ArgumentTypeError
            When ``image`` is not a Pillow image.
        ArgumentValueError
            For a 32-bit integer image holding values outside 0..65535.

        Examples
        --------
        >>> from PIL import Image
        >>> fb = FrameBuffer.from_pil(Image.new("I;16", (2, 1), 0x1234))
        >>> fb.mode, fb.to_array().tolist()       # the high byte, 0x12
        ('L', [[18, 18]])
        """
        if not isinstance(image, Image.Image):
            raise ArgumentTypeError(f"image must be a PIL.Image.Image, got {type(image).__name__}")
        if image.mode.startswith("I;16") or image.mode == "I":
            a = np.asarray(image).astype(np.int64)
            low, high = (int(a.min()), int(a.max())) if a.size else (0, 0)
            if low < 0 or high > 65535:
                raise ArgumentValueError(
                    f"image of mode {image.mode!r} holds values {low}..{high}; 32-bit "
                    "integer images need scaling to 0..255 first (Image.point)")
            wide = image.mode.startswith("I;16") or high > 255
            return cls.from_array((a >> 8 if wide else a).astype(np.uint8))
        if image.mode == "F":
            image = image.convert("L")
        if image.mode == "P" and "transparency" in image.info:
            image = image.convert("RGBA")
        if image.mode == "1":
            return cls.from_array(np.array(image, dtype=bool))
        if image.mode == "P":
            palette = image.getpalette("RGB") or []
            table = [Channels(palette[i:i + 3]) for i in range(0, len(palette), 3)][:256]
            indices = np.array(image, np.uint8)
            used = max(int(indices.max()) + 1, 1) if indices.size else 1
            # a palette shorter than the indices used: the missing entries are black, as
            # Pillow shows them
            entries = (table + [(0, 0, 0)] * used)[:used]
            return cls.from_array(indices, mode="P", color_table=entries)
        if image.mode not in ("L", "RGB", "RGBA"):
            has_alpha = "A" in image.getbands() or "transparency" in image.info
            image = image.convert("RGBA" if has_alpha else "RGB")
        return cls.from_array(np.array(image))

    @classmethod
    def open(cls, file: Union[str, "os.PathLike[str]", BinaryIO]) -> "FrameBuffer":
        """Read an image file: any format Pillow reads (PNG, JPEG, GIF, BMP, TIFF, WebP,
        ...), from a path or a binary file object; an animated file gives its first
        frame.  The mode follows the image, as in :meth:`from_pil`.

        Pillow's safety limits are kept: a file that is not an image, a truncated
        one, or an image over ``PIL.Image.MAX_IMAGE_PIXELS`` pixels (a decompression
        bomb) raises :class:`scanline.ImageFileError` before its pixels are decoded.

        Parameters
        ----------
        file : str, os.PathLike or binary file object
            The image file.

        Returns
        -------
        FrameBuffer
            Its first frame.

        Raises
        ------
        ImageFileError
            For a missing, damaged or too large file, or one that is not an image.

        Examples
        --------
        >>> import io
        >>> from PIL import Image
        >>> data = io.BytesIO()
        >>> Image.new("RGB", (2, 1), (9, 8, 7)).save(data, format="PNG")
        >>> fb = FrameBuffer.open(io.BytesIO(data.getvalue()))
        >>> fb.size, fb.mode, fb.get_pixel(1, 0)
        ((2, 1), 'RGB', (9, 8, 7))
        """
        with imagefile.read(file) as image:
            return cls.from_pil(image)

    def save(self, file: Union[str, "os.PathLike[str]", BinaryIO], format: Optional[str] = None, *,
             scale: int = 1, **options: Any) -> None:
        """Write the image to ``file``, a path or a binary file object.

        ``format`` is any format Pillow writes (``"png"``, ``"jpeg"``, ``"webp"``,
        ``"tiff"``, ``"gif"``, ``"bmp"`` ...); by default the file name's extension
        chooses it.  ``options`` go to Pillow's encoder unchanged (``quality=90``,
        ``lossless=True``, ``compression="tiff_lzw"``, ``optimize=True`` ...).  A mode
        a format cannot hold as it is is widened without loss (mode ``"P"`` is written
        as RGB in JPEG); one it cannot hold at all (``"RGBA"`` as JPEG: no alpha) is
        refused.  ``scale`` enlarges each pixel to a scale x scale block (handy to
        look at scan-converted pixels).

        The image is encoded in memory first and a path is written atomically: on
        any failure no file is left at ``file`` and a file object is not written to.

        Parameters
        ----------
        file : str, os.PathLike or binary file object
            Where to write.
        format : str, optional
            A format name or extension; by default the file name's extension.
        scale : int
            Enlarge each pixel to a ``scale`` x ``scale`` block.
        **options
            Pillow's encoder options.

        Raises
        ------
        ArgumentValueError
            For an unknown format, a path that cannot be written, or an image too
            large to write.
        ImageFileError
            When the format cannot hold the mode.
        OutputError
            When writing the file fails.

        Examples
        --------
        >>> import io
        >>> from PIL import Image
        >>> out = io.BytesIO()
        >>> FrameBuffer(2, 1, mode="L", background=50).save(out, "png", scale=3)
        >>> Image.open(io.BytesIO(out.getvalue())).size
        (6, 3)
        """
        if isinstance(file, (str, os.PathLike)):
            file = output_path(file)
        fmt = imagefile.format_of(file, format)
        if not isinstance(file, (str, os.PathLike)):
            imagefile._check_binary(file, "write")
        image = self._scaled_image(scale)
        data = imagefile.encode(image, fmt, options)
        if isinstance(file, (str, os.PathLike)):
            write_atomically(file, lambda f: f.write(data))
        else:
            file.write(data)

    def _scaled_image(self, scale: int) -> Image.Image:
        scale = v.positive_int("scale", scale)
        check_image_size(self._width, self._height, scale,
                         f"the {self._width} x {self._height} frame buffer"
                         + (f" at scale={scale}" if scale > 1 else ""))
        image = self.to_pil()
        if scale > 1:
            image = image.resize((self._width * scale, self._height * scale), Image.Resampling.NEAREST)
        return image

    def _repr_png_(self) -> bytes:
        """PNG bytes, so that Jupyter shows a frame buffer as an image: a small one
        is enlarged by a whole factor (each pixel a square block, at most
        16 x 16) to about 256 pixels on its longer side, so that a 16 x 16 image is
        visible."""
        out = io.BytesIO()
        self._scaled_image(self._repr_scale()).save(out, format="PNG")
        return out.getvalue()

    def _repr_scale(self) -> int:
        """The whole factor that enlarges a small frame buffer to about
        ``_REPR_SIZE`` pixels on its longer side (at most ``_REPR_SCALE``)."""
        return max(1, min(_REPR_SCALE, _REPR_SIZE // max(self._width, self._height)))


def _show_key(key: object) -> str:
    """An index as it was written between the brackets."""
    def one(k: object) -> str:
        if isinstance(k, slice):
            return ":".join("" if p is None else repr(p) for p in (k.start, k.stop)) + (
                "" if k.step is None else f":{k.step!r}")
        return v._show(k)
    return ", ".join(one(k) for k in key) if isinstance(key, tuple) else one(key)


def _nearest_entries(rgb: NDArray[np.uint8], table: NDArray[np.uint8]) -> NDArray[np.uint8]:
    """The color-table index nearest to each pixel of the (h, w, 3) uint8 image
    ``rgb`` (squared RGB distance, the lower index on ties), as uint8 (h, w)."""
    flat = rgb.reshape(-1, 3).astype(np.int32)
    entries = table.astype(np.int32)
    out = np.empty(len(flat), np.uint8)
    step = max(1, (1 << 21) // max(len(entries), 1))     # about 8 MB of distances a chunk
    for start in range(0, len(flat), step):
        chunk = flat[start:start + step]
        d = ((chunk[:, None, :] - entries[None, :, :]) ** 2).sum(axis=2)
        out[start:start + step] = d.argmin(axis=1)
    return out.reshape(rgb.shape[:2])


def _unit_floats(a: NDArray[np.floating[Any]]) -> NDArray[np.uint8]:
    """A float image in [0, 1] as uint8 0..255, or an error naming what is wrong."""
    finite = np.isfinite(a)
    if not finite.all():
        raise ArgumentValueError(
            f"array of dtype {a.dtype} holds {a[~finite].flat[0]}; float images must be "
            "finite values in [0, 1]")
    low, high = float(a.min()), float(a.max())
    if low < 0 or high > 1:
        hint = " (it looks like 0..255: use an integer dtype, or divide by 255)" if high <= 255 else ""
        raise ArgumentValueError(
            f"array of dtype {a.dtype} holds values {low:g}..{high:g}; float images must be "
            f"in [0, 1], as matplotlib and scikit-image store them{hint}")
    out: NDArray[np.uint8] = np.floor(a * 255 + 0.5).astype(np.uint8)
    return out


def text_image(fb: "FrameBuffer", on: str = "#", off: str = "-") -> str:
    """The frame buffer as text, top row first: ``on`` where a pixel differs from
    the background, ``off`` elsewhere.  Handy in doctests and terminals.

    Parameters
    ----------
    fb : FrameBuffer
        The frame buffer.
    on : str
        The character of a pixel that differs from the background.
    off : str
        The character of a background pixel.

    Returns
    -------
    str
        One line per row, top row first.

    Raises
    ------
    ArgumentTypeError
        When ``fb`` is not a FrameBuffer.

    Examples
    --------
    >>> fb = FrameBuffer(3, 2, mode="L")
    >>> fb.set_pixel(2, 0, 200)
    >>> print(text_image(fb))
    ---
    --#
    """
    if not isinstance(fb, FrameBuffer):
        raise ArgumentTypeError(f"fb must be a scanline.FrameBuffer, got {type(fb).__name__}")
    a = fb.to_array()
    if fb.mode == "1":
        lit = a != bool(fb._background[0])
    elif a.ndim == 3:
        lit = (a != fb._background).any(axis=2)
    else:
        lit = a != fb._background[0]
    return "\n".join("".join(on if c else off for c in row) for row in lit)
