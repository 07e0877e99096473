"""Image files: reading any image Pillow reads, writing any format Pillow writes.

Pillow decodes and encodes (DESIGN.md, convention 8: never an encoder by hand); this
module only chooses the format, guards the reading, and turns Pillow's refusals into
:class:`scanline.ImageFileError` messages that name the argument.

Reading keeps Pillow's limits: an image of more than ``PIL.Image.MAX_IMAGE_PIXELS``
pixels (a *decompression bomb*: a small file that would decode to gigabytes) is
refused before its pixels are decoded, and so is a truncated file
(``PIL.ImageFile.LOAD_TRUNCATED_IMAGES`` is left off).  Writing encodes the whole
image in memory first, so that a format that cannot hold the frame buffer's mode,
or bad format options, leave no file, and a path is then written atomically.
"""

from __future__ import annotations

import io
import os
import struct
import warnings
import zlib
from typing import IO, Any, TypeGuard, Union

from PIL import Image, UnidentifiedImageError

from .errors import ArgumentTypeError, ArgumentValueError, ImageFileError

#: What ``FrameBuffer.open`` and ``FrameBuffer.save`` accept as a file: a path, or a
#: binary file object.
File = Union[str, "os.PathLike[str]", IO[bytes]]

# Pillow's plugins report damaged data with several exception types
_DAMAGED = (OSError, SyntaxError, ValueError, EOFError, IndexError, KeyError, TypeError,
            struct.error, zlib.error)

#: Lossless widenings tried, in order, when a format cannot hold a mode as it is
#: (JPEG has no palette images: "P" is written as RGB; QOI has no gray: RGB ...).
_WIDER = {"1": ("L", "RGB"), "L": ("RGB",), "P": ("RGB",), "RGB": (), "RGBA": ()}


def _describe(file: object) -> str:
    if isinstance(file, (str, os.PathLike)):
        return f"file={os.fspath(file)!r}"
    return f"file={file!r}"


def _is_path(file: object) -> TypeGuard[str | os.PathLike[str]]:
    return isinstance(file, (str, os.PathLike))


def _check_binary(file: object, action: str) -> None:
    """A file object must be binary and offer ``read`` or ``write``."""
    if isinstance(file, io.TextIOBase):
        raise ArgumentTypeError(
            f"file={file!r} is a text file; open it in binary mode ({action[0]!r}b) "
            "or give a path")
    if not callable(getattr(file, action, None)):
        raise ArgumentTypeError(
            f"file must be a path or a binary file object with a {action}() method, got "
            f"{type(file).__name__}")


def read(file: File) -> Image.Image:
    """Open and decode the first frame of an image file, within Pillow's limits.

    Raises :class:`~scanline.ImageFileError` for a missing file, a file that is not
    an image (or not one Pillow reads), a truncated or damaged one, and an image
    larger than ``PIL.Image.MAX_IMAGE_PIXELS`` pixels.
    """
    if _is_path(file):
        path = os.fspath(file)
        if not os.path.exists(path):
            raise ImageFileError(f"{_describe(file)}: no such file")
        if not os.path.isfile(path):
            raise ImageFileError(f"{_describe(file)} is not a regular file; give an image file")
    else:
        _check_binary(file, "read")
    what = _describe(file)
    try:
        with warnings.catch_warnings():
            # past MAX_IMAGE_PIXELS Pillow only warns (it raises past twice that):
            # refuse both, before any pixel is decoded
            warnings.simplefilter("error", Image.DecompressionBombWarning)
            image = Image.open(file)
            try:
                image.load()
            except BaseException:
                image.close()
                raise
    except (Image.DecompressionBombWarning, Image.DecompressionBombError) as e:
        raise ImageFileError(
            f"{what} is refused as a possible decompression bomb: {e} Pillow's limit "
            f"(PIL.Image.MAX_IMAGE_PIXELS = {Image.MAX_IMAGE_PIXELS:,} pixels) protects "
            "memory; raise it only for files you trust") from None
    except UnidentifiedImageError:
        raise ImageFileError(
            f"{what} is not an image file Pillow can read (PNG, JPEG, GIF, BMP, TIFF, "
            "WebP, ...)") from None
    except _DAMAGED as e:
        raise ImageFileError(f"{what} is truncated or damaged: {e}") from None
    return image


def format_of(file: File, format: str | None) -> str:
    """The Pillow format name to write ``file`` in: ``format`` if given (a name such
    as ``"jpeg"`` or an extension such as ``".jpg"``), else from the file's name."""
    writable = sorted(Image.SAVE)
    extensions = {ext: fmt for ext, fmt in Image.registered_extensions().items()
                  if fmt in Image.SAVE}
    if format is not None:
        if not isinstance(format, str):
            raise ArgumentTypeError(f"format must be a string such as 'png', got {format!r}")
        name = format.upper().lstrip(".")
        if name in Image.SAVE:
            return name
        by_ext = extensions.get("." + format.lower().lstrip("."))
        if by_ext is not None:
            return by_ext
        raise ArgumentValueError(
            f"format={format!r} is not a format Pillow writes; use one of "
            f"{', '.join(writable)}")
    file_name = os.fspath(file) if _is_path(file) else getattr(file, "name", None)
    if not isinstance(file_name, str):
        raise ArgumentValueError(
            f"{_describe(file)} has no name to take the format from; give format= "
            "(for example format='png')")
    ext = os.path.splitext(file_name)[1].lower()
    if ext not in extensions:
        common = ".png, .jpg, .webp, .tif, .gif, .bmp"
        raise ArgumentValueError(
            f"{_describe(file)}: unknown image type {ext or '(no extension)'!r}; use {common} "
            "or another extension Pillow writes, or give format=")
    return extensions[ext]


def encode(image: Image.Image, format: str, options: dict[str, Any]) -> bytes:
    """``image`` encoded in ``format`` with Pillow's ``options``.

    A mode the format cannot hold is widened without loss where that helps ("1" and
    "L" to RGB, "P" to RGB); a format that cannot hold it at all (RGBA as JPEG, the
    alpha would be lost) and options Pillow refuses raise
    :class:`~scanline.ArgumentValueError`.
    """
    first: Exception | None = None
    for candidate in (image.mode, *_WIDER.get(image.mode, ())):
        im = image if candidate == image.mode else image.convert(candidate)
        out = io.BytesIO()
        try:
            im.save(out, format=format, **options)
            return out.getvalue()
        except OSError as e:
            if not str(e).startswith(("cannot write mode", "broken data stream")):
                raise                   # not a refusal of the mode
            first = first or e
        except (ValueError, TypeError, KeyError) as e:
            first = first or e
    shown = ", ".join(f"{k}={val!r}" for k, val in options.items())
    if shown and _writes(image, format):
        raise ArgumentValueError(
            f"format {format!r} refuses the options {shown} (Pillow: {first}); see Pillow's "
            "documentation of the format's options") from None
    raise ArgumentValueError(
        f"format {format!r} cannot hold this {image.mode!r} image (Pillow: {first}); use "
        "PNG, TIFF or WebP, which hold every mode") from None


def _writes(image: Image.Image, format: str) -> bool:
    """Whether ``format`` holds ``image``'s mode (widened as :func:`encode` does)
    with Pillow's default options: tried on one pixel."""
    for candidate in (image.mode, *_WIDER.get(image.mode, ())):
        try:
            Image.new(candidate, (1, 1)).save(io.BytesIO(), format=format)
            return True
        except (OSError, ValueError, TypeError, KeyError):
            continue
    return False
