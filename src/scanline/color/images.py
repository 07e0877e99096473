"""Reading a frame buffer or an image array as float intensities in [0, 1], the form
the gray-scale, color-table and dithering functions work on.

An image *source* is a :class:`~scanline.FrameBuffer` (any mode; mode ``"P"`` is read
through its color table, the alpha of ``"RGBA"`` is ignored) or an array in image
order (top row first): ``(h, w)`` gray or ``(h, w, 3)`` RGB (``(h, w, 4)`` RGBA, alpha
ignored), of bool, uint8 (0..255) or floats in [0, 1].
"""

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import ArgumentTypeError, ArgumentValueError
from .models import LUMA_WEIGHTS


def unit_floats(name: str, value: ArrayLike) -> NDArray[np.float32]:
    """``value`` as a float32 array in [0, 1]: uint8 / 255, bool as 0 or 1, floats
    checked to be finite and in [0, 1]."""
    a = np.asarray(value)
    if a.dtype == bool:
        return a.astype(np.float32)
    if a.dtype == np.uint8:   # one pass, the same values as astype then divide
        scaled: NDArray[np.float32] = np.divide(a, np.float32(255), dtype=np.float32)
        return scaled
    if a.dtype.kind != "f":
        raise ArgumentTypeError(
            f"{name} must hold uint8 (0..255), bool or floats in [0, 1], got dtype {a.dtype}")
    if not np.isfinite(a).all():
        raise ArgumentValueError(f"{name} must hold finite numbers (it has NaN or infinity)")
    if a.size and (a.min() < 0 or a.max() > 1):
        raise ArgumentValueError(
            f"{name} must hold floats in [0, 1]; got values from {a.min():g} to {a.max():g}")
    return a.astype(np.float32)


#: ``UNIT_LUT[v]`` is the uint8 value ``v`` as a float32 in [0, 1], exactly as
#: :func:`unit_floats` converts it; kernels read uint8 images through it.
UNIT_LUT = unit_floats("UNIT_LUT", np.arange(256, dtype=np.uint8))


def source_pixels(source: object, name: str = "source",
                  keep_uint8: bool = False) -> tuple[NDArray[Any], bool]:
    """``(pixels, is_gray)``: float32 ``(h, w, 1)`` gray or ``(h, w, 3)`` RGB in [0, 1]
    (with ``keep_uint8``, uint8 pixels stay uint8: read them through
    :data:`UNIT_LUT`)."""
    from ..framebuffer import FrameBuffer

    if isinstance(source, FrameBuffer):
        a = source.to_array()
        if source.mode == "P":
            a = source.color_table[a]
    elif isinstance(source, (np.ndarray, list, tuple)):
        a = np.asarray(source)
    else:
        raise ArgumentTypeError(
            f"{name} must be a scanline.FrameBuffer or an image array, got {type(source).__name__}")
    if a.ndim == 3 and a.shape[2] == 4:
        a = a[:, :, :3]
    if not (a.ndim == 2 or (a.ndim == 3 and a.shape[2] == 3)) or a.shape[0] < 1 or a.shape[1] < 1:
        raise ArgumentValueError(
            f"{name} must be a non-empty (h, w) gray or (h, w, 3|4) color image, got shape {a.shape}")
    pixels = a if keep_uint8 and a.dtype == np.uint8 else unit_floats(name, a)
    if pixels.ndim == 2:
        return pixels[:, :, None], True
    return pixels, False


def gray_image(source: object, name: str = "source", keep_uint8: bool = False) -> NDArray[Any]:
    """The source's luminance (BT.601), float32 ``(h, w, 1)`` in [0, 1] (with
    ``keep_uint8``, a uint8 gray source stays uint8)."""
    pixels, is_gray = source_pixels(source, name, keep_uint8)
    if is_gray:
        return pixels
    gray: NDArray[np.float32] = unit_floats(name, pixels) @ LUMA_WEIGHTS.astype(np.float32)
    return np.clip(gray, 0, 1)[:, :, None]


def rgb_image(source: object, name: str = "source", keep_uint8: bool = False) -> NDArray[Any]:
    """The source as float32 RGB ``(h, w, 3)`` in [0, 1] (a gray source repeated;
    with ``keep_uint8``, uint8 stays uint8)."""
    pixels, is_gray = source_pixels(source, name, keep_uint8)
    return np.repeat(pixels, 3, axis=2) if is_gray else pixels
