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
import os
import signal
import tempfile
import threading

import numpy as np
from PIL import Image

from . import _validate as v
from .color.spec import pixel_value, rgba
from .errors import ArgumentTypeError, ArgumentValueError, OutputError, ScanlineError

MODES = ("1", "L", "RGB", "RGBA", "P")
_CHANNELS = {"1": 1, "L": 1, "RGB": 3, "RGBA": 4, "P": 1}
_BITS = {"1": 1, "L": 8, "RGB": 24, "RGBA": 32, "P": 8}
_FORMATS = {".png": "PNG", ".gif": "GIF", ".bmp": "BMP"}


def _physical_memory():
    try:
        return os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    except (ValueError, OSError, AttributeError):  # pragma: no cover - non-POSIX
        return 1 << 40


def _umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask


def output_path(path, name="path"):
    """``path`` (a str or os.PathLike) as a str, checked as the name of a file to
    write: no NUL character, not a folder, in a folder that exists."""
    if not isinstance(path, (str, os.PathLike)):
        raise ArgumentTypeError(f"{name} must be a file name (str or os.PathLike), got "
                                f"{v._show(path)}")
    try:
        path = os.fsdecode(os.fspath(path))
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
def _terminate_cleanly():
    """While the block runs, SIGTERM raises :class:`_Terminated` instead of killing the
    process at once, so that the temporary file is removed; the caller then
    terminates as SIGTERM would.  Only in the main thread, and only where SIGTERM
    has its default action (a server that handles it is left alone)."""
    if (threading.current_thread() is not threading.main_thread()
            or signal.getsignal(signal.SIGTERM) is not signal.SIG_DFL):
        yield
        return

    def terminated(signum, frame):
        raise _Terminated()

    signal.signal(signal.SIGTERM, terminated)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, signal.SIG_DFL)


def write_atomically(path, write):
    """Call ``write(file)`` on a temporary file beside ``path``, then rename it.

    A failure (an exception from ``write``, a full disk, Ctrl-C, SIGTERM) leaves
    no file at ``path`` and no temporary file beside it; after SIGTERM the process
    then terminates as the signal asks.  Errors name ``path`` (not the temporary
    file).
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


def image_limit():
    """Most pixels an image file written by scanline may hold: twice Pillow's
    decompression-bomb threshold (``PIL.Image.MAX_IMAGE_PIXELS``, 89,478,485 by
    default), past which Pillow refuses to open the file again."""
    bound = Image.MAX_IMAGE_PIXELS
    return 2 * int(bound) if bound else 1 << 40


def check_image_size(width, height, scale=1, given=None, hint=None):
    """The size rule of every image scanline writes, checked before anything is
    allocated: ``width x height`` pixels enlarged ``scale`` times must fit
    :func:`image_limit`.  ``given`` says how the caller gave the size (for
    instance ``"--size 40000x40000"``, ``"canvas.width x canvas.height"``), so
    that the message names it; ``hint`` says what to change."""
    pixels = width * height * scale * scale
    limit = image_limit()
    if pixels <= limit:
        return
    given = given or f"width x height = {width} x {height}"
    made = f" enlarged {scale} times, {width * scale} x {height * scale}," if scale > 1 else ""
    raise ArgumentValueError(
        f"{given}{made} is {pixels:,} pixels, more than the {limit:,} an image file may hold; "
        + (hint or "use a smaller size" + (" or scale" if scale > 1 else "")))


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

    def __init__(self, width, height, mode="RGB", background="black", color_table=None):
        width = v.positive_int("width", width)
        height = v.positive_int("height", height)
        v.choice("mode", mode, MODES)
        for name, size in (("width", width), ("height", height)):
            if size > v.COORD_LIMIT:
                raise ArgumentValueError(f"{name}={size} is larger than the limit {v.COORD_LIMIT}")
        row_bytes = (width + 7) // 8 if mode == "1" else width
        nbytes = height * row_bytes * _CHANNELS[mode]
        available = _physical_memory()
        if nbytes > available:
            raise ArgumentValueError(
                f"width x height = {width} x {height} in mode {mode!r} needs {nbytes:,} bytes, "
                f"more than this machine's {available:,} bytes of memory; use a smaller size"
            )
        self._width = width
        self._height = height
        self._mode = mode
        self._table = np.zeros((0, 3), np.uint8)
        self._cache = {}
        if mode == "P" and color_table is not None:
            self.color_table = color_table
        elif color_table is not None:
            raise ArgumentValueError(f"color_table is only for mode 'P', not mode {mode!r}")
        self._background = self.pixel(background, "background")
        self._buf = np.empty((height, row_bytes, _CHANNELS[mode]), np.uint8)
        self.clear()

    # -- properties -------------------------------------------------------------------
    @property
    def width(self):
        """Width in pixels."""
        return self._width

    @property
    def height(self):
        """Height in pixels."""
        return self._height

    @property
    def size(self):
        """``(width, height)``."""
        return (self._width, self._height)

    @property
    def mode(self):
        """Pixel format: ``"1"``, ``"L"``, ``"RGB"``, ``"RGBA"`` or ``"P"``."""
        return self._mode

    @property
    def bits_per_pixel(self):
        """Bits of frame-buffer memory per pixel: 1, 8, 24, 32 or 8 (``"P"``)."""
        return _BITS[self._mode]

    @property
    def nbytes(self):
        """Memory size of the pixel storage in bytes (mode ``"1"`` rows are padded to
        whole bytes; the color table of mode ``"P"`` is not counted).

        >>> FrameBuffer(640, 480, mode="1").nbytes, FrameBuffer(640, 480).nbytes
        (38400, 921600)
        """
        return self._buf.nbytes

    def __repr__(self):
        return f"FrameBuffer({self._width}, {self._height}, mode={self._mode!r})"

    # -- colors -----------------------------------------------------------------------
    def pixel(self, color, name="color"):
        """Return the stored channel values of ``color`` as a uint8 array.

        In mode ``"P"`` an integer is a color-table index; any other color is looked
        up in the table and appended to it when absent.
        """
        # cache exact types only: True == 1 and (1.0, 2) == (1, 2) must not share
        # an entry, and a tuple holding a list must not be hashed
        cacheable = type(color) in (str, int) or (
            type(color) is tuple and all(type(c) is int for c in color))
        key = (color, name)
        if cacheable:
            hit = self._cache.get(key)
            if hit is not None:
                return hit
        if self._mode == "P":
            value = (self._table_index(color, name),)
        else:
            value = pixel_value(color, self._mode, name)
        out = np.array(value, np.uint8)
        if cacheable:
            self._cache[key] = out
        return out

    def _table_index(self, color, name):
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
    def color_table(self):
        """Mode ``"P"``: a copy of the color table, shape (n, 3), uint8 RGB.

        Assigning a sequence of colors replaces the table; the stored indices stay,
        so the image is recolored.
        """
        self._require_p("color_table")
        return self._table.copy()

    @color_table.setter
    def color_table(self, colors):
        self._require_p("color_table")
        colors = list(colors)
        if not 1 <= len(colors) <= 256:
            raise ArgumentValueError(f"color_table must have 1..256 entries, got {len(colors)}")
        table = np.array([rgba(c, f"color_table[{i}]")[:3] for i, c in enumerate(colors)], np.uint8)
        if hasattr(self, "_buf") and self._buf.size and int(self._buf.max()) >= len(table):
            raise ArgumentValueError(
                f"color_table has {len(table)} entries but the image uses index "
                f"{int(self._buf.max())}; give at least {int(self._buf.max()) + 1} entries"
            )
        self._table = table
        self._cache.clear()

    def set_table_entry(self, index, color):
        """Mode ``"P"``: set color-table entry ``index`` to ``color`` (recolors every
        pixel that stores that index).  ``index`` may be the next free entry."""
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

    def _require_p(self, what):
        if self._mode != "P":
            raise ArgumentValueError(f"{what} exists only in mode 'P', this frame buffer is {self._mode!r}")

    # -- pixels -----------------------------------------------------------------------
    def _raster(self):
        """Storage for the kernels: ``(buf, packed)``; ``buf[y, x]`` is pixel (x, y),
        or in mode ``"1"`` the byte holding it (most significant bit first)."""
        return self._buf, self._mode == "1"

    def clear(self, color=None):
        """Set every pixel to ``color`` (default: the background)."""
        value = self._background if color is None else self.pixel(color)
        if self._mode == "1":
            self._buf.fill(0xFF if value[0] else 0)
        elif (value == value[0]).all():
            self._buf.fill(value[0])
        else:
            # one row of pixels, then every row from it: broadcasting the pixel value
            # over the whole (H, W, C) array directly is about 20 times slower
            self._buf[...] = np.tile(value, (self._buf.shape[1], 1))

    def _check_xy(self, x, y):
        x = v.coordinate("x", x)
        y = v.coordinate("y", y)
        return x, y, 0 <= x < self._width and 0 <= y < self._height

    def set_pixel(self, x, y, color):
        """Set pixel ``(x, y)`` to ``color``; a pixel outside the buffer is ignored
        (clipped), like every drawing operation."""
        x, y, inside = self._check_xy(x, y)
        value = self.pixel(color)
        if not inside:
            return
        if self._mode == "1":
            bit = 0x80 >> (x & 7)
            byte = int(self._buf[y, x >> 3, 0])
            self._buf[y, x >> 3, 0] = (byte | bit) if value[0] else (byte & ~bit & 0xFF)
        else:
            self._buf[y, x] = value

    def get_pixel(self, x, y):
        """Return pixel ``(x, y)``: an int in modes ``"1"``, ``"L"`` and ``"P"`` (bit,
        gray level, color-table index), a tuple in ``"RGB"`` and ``"RGBA"``."""
        x, y, inside = self._check_xy(x, y)
        if not inside:
            raise ArgumentValueError(
                f"(x, y) = ({x}, {y}) is outside the frame buffer; "
                f"use 0 <= x < {self._width} and 0 <= y < {self._height}"
            )
        if self._mode == "1":
            return int(self._buf[y, x >> 3, 0] >> (7 - (x & 7))) & 1
        values = self._buf[y, x]
        return int(values[0]) if values.size == 1 else tuple(int(c) for c in values)

    # -- arrays and images --------------------------------------------------------------
    def to_array(self):
        """A copy of the pixels in image order (top row first).

        Shape (height, width) for modes ``"1"`` (bool), ``"L"`` and ``"P"`` (uint8
        indices), (height, width, 3 or 4) for ``"RGB"`` and ``"RGBA"``.
        """
        rows = self._buf[::-1]
        if self._mode == "1":
            return np.unpackbits(rows[:, :, 0], axis=1, count=self._width).astype(bool)
        if self._mode in ("L", "P"):
            return rows[:, :, 0].copy()
        return rows.copy()

    @classmethod
    def from_array(cls, array, mode=None, color_table=None):
        """Make a frame buffer from an image-order array (the inverse of :meth:`to_array`).

        The mode follows from the array: bool 2-D -> ``"1"``, uint8 2-D -> ``"L"``
        (or ``"P"`` when ``mode="P"`` and a ``color_table`` is given), uint8
        (h, w, 3) -> ``"RGB"``, (h, w, 4) -> ``"RGBA"``.
        """
        a = np.asarray(array)
        if a.ndim not in (2, 3) or a.shape[0] < 1 or a.shape[1] < 1:
            raise ArgumentValueError(f"array must be 2-D or 3-D and non-empty, got shape {a.shape}")
        inferred = (
            "1" if a.dtype == bool and a.ndim == 2
            else "L" if a.ndim == 2
            else {3: "RGB", 4: "RGBA"}.get(a.shape[2])
        )
        mode = inferred if mode is None else v.choice("mode", mode, MODES)
        if inferred is None or (mode != inferred and not (mode == "P" and inferred == "L")):
            raise ArgumentValueError(
                f"array of shape {a.shape} and dtype {a.dtype} does not hold mode {mode!r} pixels; "
                "use bool (h, w) for '1', uint8 (h, w) for 'L' or 'P', uint8 (h, w, 3|4) for 'RGB'/'RGBA'"
            )
        if a.dtype != bool and a.dtype != np.uint8:
            if not np.issubdtype(a.dtype, np.integer) or a.min() < 0 or a.max() > 255:
                raise ArgumentValueError(f"array must hold uint8 values 0..255, got dtype {a.dtype}")
        if mode == "P" and color_table is None:
            raise ArgumentValueError("mode 'P' needs a color_table for the indices in array")
        if mode == "P":
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

    def to_pil(self):
        """The image as a Pillow ``Image`` (modes map one to one)."""
        h, w = self._height, self._width
        if self._mode == "1":
            return Image.frombytes("1", (w, h), np.ascontiguousarray(self._buf[::-1]).tobytes())
        if self._mode == "P":
            img = Image.frombytes("P", (w, h), self.to_array().tobytes())
            img.putpalette(self._table.tobytes())
            return img
        return Image.fromarray(self.to_array())

    @classmethod
    def from_pil(cls, image):
        """Make a frame buffer from a Pillow ``Image``.  Modes ``1``, ``L``, ``P``,
        ``RGB`` and ``RGBA`` map directly; other modes are converted to ``RGB`` (or
        ``RGBA`` when they carry transparency)."""
        if not isinstance(image, Image.Image):
            raise ArgumentTypeError(f"image must be a PIL.Image.Image, got {type(image).__name__}")
        if image.mode == "1":
            return cls.from_array(np.array(image, dtype=bool))
        if image.mode == "P":
            palette = image.getpalette("RGB") or []
            table = [tuple(palette[i:i + 3]) for i in range(0, len(palette), 3)][:256]
            indices = np.array(image, np.uint8)
            used = max(int(indices.max()) + 1, 1) if indices.size else 1
            # a palette shorter than the indices used: the missing entries are black, as
            # Pillow shows them
            table = (table + [(0, 0, 0)] * used)[:used]
            return cls.from_array(indices, mode="P", color_table=table)
        if image.mode not in ("L", "RGB", "RGBA"):
            has_alpha = "A" in image.getbands() or "transparency" in image.info
            image = image.convert("RGBA" if has_alpha else "RGB")
        return cls.from_array(np.array(image))

    def save(self, path, scale=1):
        """Write the image to ``path``; the extension picks PNG, GIF or BMP and Pillow
        encodes it.  ``scale`` enlarges each pixel to a scale x scale block (handy to
        look at scan-converted pixels).  The write is atomic: on any failure no file
        is left at ``path``."""
        path = output_path(path)
        ext = os.path.splitext(path)[1].lower()
        if ext not in _FORMATS:
            raise ArgumentValueError(
                f"path={path!r}: unknown image type {ext!r}; use .png, .gif or .bmp"
            )
        image = self._scaled_image(scale)
        write_atomically(path, lambda f: image.save(f, format=_FORMATS[ext]))

    def _scaled_image(self, scale):
        scale = v.positive_int("scale", scale)
        check_image_size(self._width, self._height, scale,
                         f"the {self._width} x {self._height} frame buffer"
                         + (f" at scale={scale}" if scale > 1 else ""))
        image = self.to_pil()
        if scale > 1:
            image = image.resize((self._width * scale, self._height * scale), Image.Resampling.NEAREST)
        return image

    def _repr_png_(self):
        """PNG bytes, so that Jupyter shows a frame buffer as an image."""
        out = io.BytesIO()
        self.to_pil().save(out, format="PNG")
        return out.getvalue()


def text_image(fb, on="#", off="-"):
    """The frame buffer as text, top row first: ``on`` where a pixel differs from
    the background, ``off`` elsewhere.  Handy in doctests and terminals.

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
