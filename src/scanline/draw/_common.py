"""Argument handling shared by the drawing functions."""

from typing import Any, Optional, Sequence, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._typing import Color, Colors
from ..color.spec import Channels, in_context
from ..errors import ArgumentTypeError, ArgumentValueError
from ..framebuffer import FrameBuffer


def target(fb: FrameBuffer) -> Tuple[NDArray[np.uint8], bool, int, int]:
    """Check that ``fb`` is a FrameBuffer; return ``(buf, packed, width, height)``."""
    if type(fb) is not FrameBuffer and not isinstance(fb, FrameBuffer):
        raise ArgumentTypeError(f"fb must be a scanline.FrameBuffer, got {type(fb).__name__}")
    return fb._buf, fb._mode == "1", fb._width, fb._height     # (FrameBuffer._raster)


def _direct(fb: FrameBuffer, a: NDArray[Any], name: str) -> Optional[NDArray[np.uint8]]:
    """Per-primitive values given as an integer array: (N,) bits / gray levels /
    indices, or (N, 3|4) RGB(A) for an RGB or RGBA frame buffer.  None if the array
    needs per-color conversion."""
    if not np.issubdtype(a.dtype, np.integer):
        raise ArgumentTypeError(f"{name} array must hold integers, got dtype {a.dtype}")
    mode = fb.mode
    if a.ndim == 1 and mode in ("L", "P", "1"):
        top = {"L": 255, "1": 1, "P": len(fb.color_table) - 1 if mode == "P" else 0}[mode]
        if a.size and (a.min() < 0 or a.max() > top):
            raise ArgumentValueError(f"{name} values must be in 0..{top} for mode {mode!r}")
        return a.astype(np.uint8)[:, None]
    if a.ndim == 2 and mode in ("RGB", "RGBA") and a.shape[1] in (3, 4):
        if a.size and (a.min() < 0 or a.max() > 255):
            raise ArgumentValueError(f"{name} values must be in 0..255")
        if mode == "RGB":
            return a[:, :3].astype(np.uint8)
        if a.shape[1] == 4:
            return a.astype(np.uint8)
        return np.hstack([a.astype(np.uint8), np.full((len(a), 1), 255, np.uint8)])
    return None


def colors(fb: FrameBuffer, color: Union[Colors, NDArray[Any], None], n: int,
           name: str = "color") -> NDArray[np.uint8]:
    """Pixel values for N primitives, shape (1, channels) or (n, channels).

    A string, tuple or integer is one color for all.  A list holds one color spec per
    primitive; an integer array holds N bits / gray levels / color-table indices, or
    an (N, 3|4) array of RGB(A) values.
    """
    if not isinstance(color, (list, np.ndarray)):
        return fb.pixel(color, name)[None, :]
    if len(color) != n:
        raise ArgumentValueError(
            f"{name} holds {len(color)} colors but there are {n} primitives; give one "
            "color per primitive, or a single color (a string, tuple or integer)"
        )
    if isinstance(color, np.ndarray):
        if color.ndim not in (1, 2):
            raise ArgumentValueError(f"{name} array must have shape (N,) or (N, 3|4), got {color.shape}")
        direct = _direct(fb, color, name)
        if direct is not None:
            return direct
        specs: Sequence[Union[Color, Channels]] = [
            Channels(row.tolist()) if color.ndim == 2 else int(row) for row in color]
    else:
        specs = color
    channels = fb._raster()[0].shape[2]
    out = np.empty((n, channels), np.uint8)
    for i, spec in enumerate(in_context(specs)):
        out[i] = fb.pixel(spec, f"{name}[{i}]")
    return out


def area_work(width: int, height: int, points: ArrayLike, count: int = 1,
              margin: float = 0) -> float:
    """Work units of drawing ``count`` primitives within the box of ``points`` (an
    (N, 2+) array of device coordinates, any columns past x and y ignored), grown by
    ``margin``, clipped to a ``width`` x ``height`` raster: an upper bound of the
    pixels written, for :func:`scanline._kernels._jit.call`."""
    points = np.asarray(points, np.float64)
    if points.size == 0:
        return 0
    points = points.reshape(len(points), -1)
    # column by column: numpy reduces an (N, 2) array along axis 0 row by row, ten
    # times slower than each column on its own (4.5 ms for 115k vertices)
    xs, ys = points[:, 0], points[:, 1]
    lo = np.maximum(np.floor([xs.min(), ys.min()]) - margin, 0)
    hi = np.minimum(np.ceil([xs.max(), ys.max()]) + margin, (width - 1, height - 1))
    area = float(np.prod(np.maximum(hi - lo + 1, 0)))
    return count * area + len(points)


def band_order(rows: NDArray[np.int64], values: NDArray[np.uint8],
               height: int) -> NDArray[np.int64]:
    """The (N, k) int64 primitive ``rows`` (y in column 1) in order of bands of
    scan lines (the counting sort of :func:`scanline._kernels.raster.band_sorted`,
    its two passes on every core: each thread counts its chunk's rows per band,
    then copies them to their slots) when ``values`` holds one color for all, which
    makes any drawing order give the same image; else ``rows`` as they are.  Drawn
    band by band, the rows being written stay in the cache; sorted once here, not
    by each thread's kernel."""
    n = len(rows)
    if len(values) != 1 or n < 2:
        return rows
    from .._kernels._threads import call_in_chunks
    from .._kernels.raster import band_counts, band_scatter

    parts = call_in_chunks(band_counts, n, n, lambda lo, hi: (rows, height, lo, hi))
    counts = np.stack([c for _, c in parts])          # (chunks, bands)
    # a row's slot: the rows of the bands before its band, then those of its band
    # in the chunks before its chunk, then those before it in its chunk
    before = np.cumsum(counts.sum(axis=0)) - counts.sum(axis=0)
    slots = {lo: before + np.cumsum(counts, axis=0)[t] - counts[t]
             for t, (lo, _) in enumerate(parts)}
    out = np.empty_like(rows)
    call_in_chunks(band_scatter, n, n, lambda lo, hi: (rows, height, lo, hi, slots[lo], out),
                   parts=len(parts))
    return out
