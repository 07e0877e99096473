"""Color tables (palettes) for indexed frame buffers (mode ``"P"``).

A color table here is a uint8 array of shape (n, 3), 1 <= n <= 256: row ``i`` is the
RGB color that index ``i`` displays.  ``FrameBuffer(..., mode="P",
color_table=table)`` takes one; editing a frame buffer's table recolors its image
(see :class:`scanline.FrameBuffer`).

Notes
-----
Notes, chapter "Attributes of output primitives", *Color-tables* and *Gray scale*:
with a color table (a video lookup table) each pixel stores a short index instead of
the full color, so a frame buffer of 8 bits per pixel shows 256 colors chosen from
2**24, and the notes' color-table animation recolors without redrawing.  A table of
equally spaced grays gives the gray-scale levels: with 2 bits per pixel, 4 levels.
"""

import numbers
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import ArgumentTypeError, ArgumentValueError
from .spec import in_context, rgba


def gray_table(n: int) -> NDArray[np.uint8]:
    """``n`` evenly spaced gray levels from black to white, ``round(255 i / (n - 1))``.

    Parameters
    ----------
    n : int
        The number of levels, 2 .. 256.

    Returns
    -------
    numpy.ndarray
        uint8 (n, 3): gray ``i`` in row ``i``.

    Raises
    ------
    ArgumentTypeError
        When ``n`` is not an integer.
    ArgumentValueError
        When ``n`` is outside 2 .. 256.

    Examples
    --------
    >>> gray_table(4)[:, 0].tolist()       # 2 bits per pixel: 4 levels
    [0, 85, 170, 255]
    """
    n = levels_argument("n", n)
    values = np.floor(np.arange(n) * (255.0 / (n - 1)) + 0.5).astype(np.uint8)
    return np.repeat(values[:, None], 3, axis=1)


def rgb332_table() -> NDArray[np.uint8]:
    """The 256-color "3-3-2" table: index ``r << 5 | g << 2 | b`` with 8 levels of red,
    8 of green and 4 of blue (an 8-bit frame buffer read directly as RGB).

    Returns
    -------
    numpy.ndarray
        uint8 (256, 3): level ``k`` of red is ``round(255 k / 7)``, of blue
        ``round(255 k / 3)``.

    Examples
    --------
    >>> rgb332_table()[0b111_000_11].tolist()
    [255, 0, 255]
    """
    i = np.arange(256)
    r, g, b = i >> 5, (i >> 2) & 7, i & 3
    return np.floor(np.stack([r * 255 / 7, g * 255 / 7, b * 255 / 3], axis=1) + 0.5).astype(np.uint8)


def web_safe_table() -> NDArray[np.uint8]:
    """The 216 "web-safe" colors: 6 levels (0, 51, ..., 255) of each primary, index
    ``36 r + 6 g + b``.

    Returns
    -------
    numpy.ndarray
        uint8 (216, 3).

    Examples
    --------
    >>> web_safe_table()[[0, 5, 215]].tolist()
    [[0, 0, 0], [0, 0, 255], [255, 255, 255]]
    """
    i = np.arange(216)
    return (np.stack([i // 36, (i // 6) % 6, i % 6], axis=1) * 51).astype(np.uint8)


def median_cut_table(source: Any, colors: int = 16) -> NDArray[np.uint8]:
    """A table of at most ``colors`` colors fitted to an image by Heckbert's median cut.

    ``source`` is a FrameBuffer or an image array (see :func:`scanline.color.dither`).
    The table may be shorter than ``colors`` when the image has fewer colors.

    Notes
    -----
    All the image's colors start in one box of RGB space.  While there are fewer
    boxes than ``colors``, the box holding the most pixels (among those with two or
    more distinct colors) is cut across its longest side at the median pixel, so
    that each half holds about half of its pixels; each table entry is the mean
    color of one box's pixels, rounded.  Every entry thus stands for about the same
    number of pixels (Heckbert's aim).

    References
    ----------
    .. [1] P. Heckbert, "Color image quantization for frame buffer display",
       Computer Graphics (SIGGRAPH '82) 16(3), 297-307, 1982.

    Examples
    --------

    Parameters
    ----------
    source : FrameBuffer or array_like
        The image: a frame buffer, or an image-order array (h, w) gray or (h, w, 3|4)
        color, of bool, uint8 or floats in [0, 1].
    colors : int
        The most entries the table may have, 1 .. 256.

    Returns
    -------
    numpy.ndarray
        uint8 (n, 3), n <= ``colors``.

    Raises
    ------
    ArgumentTypeError
        When ``source`` is not an image or ``colors`` not an integer.
    ArgumentValueError
        For an empty image, bad pixel values or ``colors`` outside 1 .. 256.

    Examples
    --------
    >>> image = np.array([[[0, 0, 0], [10, 0, 0], [200, 0, 0], [250, 0, 0]]], np.uint8)
    >>> median_cut_table(image, 2).tolist()
    [[5, 0, 0], [225, 0, 0]]
    """
    from .images import rgb_image

    colors = levels_argument("colors", colors, minimum=1)
    rgb = np.floor(rgb_image(source) * 255 + 0.5).astype(np.int64).reshape(-1, 3)
    keys, counts = np.unique((rgb[:, 0] << 16) | (rgb[:, 1] << 8) | rgb[:, 2],
                             return_counts=True)
    points = np.stack([keys >> 16, (keys >> 8) & 255, keys & 255], axis=1)
    boxes = [np.arange(len(keys))]
    while len(boxes) < colors:
        sizes = [counts[b].sum() if len(b) > 1 else -1 for b in boxes]
        i = int(np.argmax(sizes))
        if sizes[i] < 0:
            break                              # every box is a single color
        box = boxes[i]
        side = points[box]
        axis = int(np.argmax(side.max(axis=0) - side.min(axis=0)))
        box = box[np.argsort(side[:, axis], kind="stable")]
        running = np.cumsum(counts[box])
        cut = int(np.searchsorted(running, running[-1] / 2)) + 1
        cut = min(max(cut, 1), len(box) - 1)   # both halves keep a color
        boxes[i:i + 1] = [box[:cut], box[cut:]]
    table = [np.floor(counts[b] @ points[b] / counts[b].sum() + 0.5) for b in boxes]
    return np.array(table, np.uint8)


def levels_argument(name: str, value: object, minimum: int = 2) -> int:
    """Check a count of levels or colors: an int in ``minimum`` .. 256."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise ArgumentTypeError(
            f"{name}={value!r} must be an integer from {minimum} to 256, "
            f"not {type(value).__name__}")
    if not minimum <= int(value) <= 256:
        raise ArgumentValueError(
            f"{name}={value!r} must be from {minimum} to 256 "
            f"(2 levels = 1 bit per pixel, 4 = 2 bits, 256 = 8 bits)")
    return int(value)


def color_table(colors: Any, name: str = "palette") -> NDArray[np.uint8]:
    """Return ``colors`` as a color table, a uint8 (n, 3) array with 1 <= n <= 256.

    ``colors`` is an (n, 3) array of uint8 (or of floats in [0, 1]), or a sequence of
    color specifications (``"red"``, ``"#ff8000"``, ``(r, g, b)``).

    Parameters
    ----------
    colors : array_like or sequence of colors
        An (n, 3) array of uint8 or of floats in [0, 1], or a sequence of color specs.
    name : str
        The argument's name, for error messages.

    Returns
    -------
    numpy.ndarray
        uint8 (n, 3), C-contiguous.

    Raises
    ------
    ArgumentTypeError
        For one string, or anything that is not a sequence of colors.
    ArgumentValueError
        For values out of range, or fewer than 1 or more than 256 colors.

    Examples
    --------
    >>> color_table(["black", (255, 128, 0)]).tolist()
    [[0, 0, 0], [255, 128, 0]]
    """
    if isinstance(colors, str):
        raise ArgumentTypeError(
            f"{name}={colors!r} must be a sequence of colors, not one string; "
            "e.g. ['black', 'white'] or an (n, 3) uint8 array")
    a = np.asarray(colors) if isinstance(colors, np.ndarray) else None
    if a is not None and a.dtype.kind in "uif" and a.ndim == 2 and a.shape[1] == 3:
        if a.dtype.kind == "f":
            if not (np.isfinite(a).all() and (a >= 0).all() and (a <= 1).all()):
                raise ArgumentValueError(f"{name}: a float color table must hold values in [0, 1]")
            a = np.floor(a * 255 + 0.5)
        elif a.size and (a.min() < 0 or a.max() > 255):
            raise ArgumentValueError(f"{name}: an integer color table must hold values in 0..255")
        table = a.astype(np.uint8)
    else:
        try:
            entries = list(colors)
        except TypeError:
            raise ArgumentTypeError(
                f"{name} must be a sequence of colors or an (n, 3) array, "
                f"got {type(colors).__name__}") from None
        table = np.array([rgba(c, f"{name}[{i}]")[:3]
                          for i, c in enumerate(in_context(entries))],
                         np.uint8).reshape(-1, 3)
    if not 1 <= len(table) <= 256:
        raise ArgumentValueError(
            f"{name} must have 1 to 256 colors, got {len(table)}; "
            "e.g. scanline.color.web_safe_table() or gray_table(4)")
    return np.ascontiguousarray(table)


def nearest(colors: ArrayLike, table: Any) -> NDArray[np.uint8]:
    """Index of the nearest table color (Euclidean distance in RGB; the lowest index
    among equally near ones) for each color of ``colors``.

    ``colors`` has any leading shape and 3 components, uint8 or floats in [0, 1]; the
    result has shape ``colors.shape[:-1]``, dtype uint8.

    Parameters
    ----------
    colors : array_like
        Colors, 3 components on the last axis: uint8, bool or floats in [0, 1].
    table : array_like or sequence of colors
        The color table (see :func:`color_table`).

    Returns
    -------
    numpy.ndarray
        uint8 indices, shape ``colors.shape[:-1]``.

    Raises
    ------
    ArgumentTypeError
        For colors of another dtype, or a table that is not one.
    ArgumentValueError
        For colors without 3 components or out of range, or a bad table.

    Examples
    --------
    >>> nearest(np.array([[250, 10, 10], [20, 20, 20]], np.uint8), ["black", "red"]).tolist()
    [1, 0]
    """
    from .._kernels import dither as kernels
    from .images import unit_floats

    a = unit_floats("colors", colors)
    if a.ndim == 0 or a.shape[-1] != 3:
        raise ArgumentValueError(f"colors must have 3 components (RGB) on its last axis, got shape {a.shape}")
    palette = color_table(table, "table").astype(np.float32) / np.float32(255)
    flat = np.ascontiguousarray(a.reshape(1, -1, 3))
    out = np.empty(flat.shape[:2], np.uint8)
    if flat.size:
        kernels.ordered_palette(flat, np.full((1, 1), 0.5, np.float32), np.zeros(3, np.float32),
                                palette, *search_cells(palette, flat.shape[1]), out)
    return out.reshape(a.shape[:-1])


def search_cells(palette: NDArray[np.float32], pixels: int
                 ) -> tuple[NDArray[np.int16], NDArray[np.int32], int, float, float]:
    """``(cells, counts, grid, low, span)`` for the palette kernels' nearest-color
    search: the candidate lists of :func:`scanline._kernels.dither.palette_cells` on
    a 16 x 16 x 16 grid over [-1/2, 3/2] (error diffusion pushes colors past [0, 1])
    when there are enough pixels to repay building it (a few milliseconds), else one
    cell that lists every entry (plain exhaustive search)."""
    from .._kernels import dither as kernels

    grid = 16 if pixels * len(palette) >= 1 << 20 else 1
    low, span = -0.5, 2.0
    n_cells = grid ** palette.shape[1] + 1
    cells = np.empty((n_cells, len(palette)), np.int16)
    counts = np.empty(n_cells, np.int32)
    kernels.palette_cells(palette.astype(np.float64), grid, low, span, cells, counts)
    return cells, counts, grid, low, span
