"""Gray-scale levels, dithering and halftoning: showing an image with fewer intensity
levels (or colors) than it has.

Notes
-----
Notes, chapter "Attributes of output primitives", *Color and gray scale levels* and
*Gray scale*: a frame buffer of b bits per pixel holds 2**b intensity levels (1 bit: a
bitmap, black and white; 2 bits: 4 levels).  The glossary's *Dithering*: "uses two
colors to create the appearance of a third", so that a frame buffer of few bits
gives a smooth appearance to an otherwise abrupt transition.

References
----------
.. [1] B. E. Bayer, "An optimum method for two-level rendition of continuous-tone
   pictures", IEEE International Conference on Communications, 1973.
.. [2] R. W. Floyd and L. Steinberg, "An adaptive algorithm for spatial grey scale",
   Proceedings of the Society for Information Display 17(2), 75-77, 1976.
"""

from typing import TYPE_CHECKING, Any, Optional, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from .images import UNIT_LUT, gray_image, rgb_image
from .tables import color_table, gray_table, levels_argument, search_cells

#: Dithering methods of :func:`dither`: error diffusion, ordered dithering with a
#: Bayer matrix of side 2, 4 or 8, and "none" (round to the nearest level or color).
METHODS = ("floyd-steinberg", "bayer2", "bayer4", "bayer8", "none", "ordered")

#: Other names of methods: ``"ordered"``, the textbook's name of Bayer's ordered
#: dithering (Hearn & Baker, "Halftone Patterns and Dithering Techniques": the
#: ordered-dither methods, here with the 4 x 4 matrix D4).
ALIASES = {"ordered": "bayer4"}
OUTPUT_MODES = ("1", "L", "RGB", "P")

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer


def bayer_matrix(n: int) -> NDArray[np.int64]:
    """Bayer's ``n`` x ``n`` index matrix (n a power of two): a permutation of
    0 .. n*n - 1, built recursively from ``M(1) = [[0]]``::

        M(2k) = [[4 M(k),     4 M(k) + 2],
                 [4 M(k) + 3, 4 M(k) + 1]]

    Pixel (row, col) of an image is set when its intensity reaches the threshold
    ``(M[row mod n, col mod n] + 1/2) / n**2``.

    Parameters
    ----------
    n : int
        The side, a power of two from 1 to 256.

    Returns
    -------
    numpy.ndarray
        int64 (n, n).

    Raises
    ------
    ArgumentValueError
        When ``n`` is not a power of two from 1 to 256.

    Examples
    --------
    >>> bayer_matrix(2).tolist()
    [[0, 2], [3, 1]]
    >>> bayer_matrix(4)
    array([[ 0,  8,  2, 10],
           [12,  4, 14,  6],
           [ 3, 11,  1,  9],
           [15,  7, 13,  5]])
    """
    n = v.positive_int("n", n)
    if n & (n - 1) or n > 256:
        raise ArgumentValueError(f"n={n}: a Bayer matrix has a side that is a power of two, 1 to 256")
    m = np.zeros((1, 1), np.int64)
    while m.shape[0] < n:
        m = np.block([[4 * m, 4 * m + 2], [4 * m + 3, 4 * m + 1]])
    return m


def _thresholds(method: str) -> NDArray[np.float32]:
    side = {"bayer2": 2, "bayer4": 4, "bayer8": 8, "none": 1}[method]
    return ((bayer_matrix(side) + 0.5) / (side * side)).astype(np.float32)


def _output_mode(mode: Optional[str], levels: int, palette: object) -> str:
    if mode is not None:
        v.choice("mode", mode, OUTPUT_MODES)
    if palette is not None:
        if mode not in (None, "P"):
            raise ArgumentValueError(f"mode={mode!r}: dithering to a palette makes mode 'P'")
        return "P"
    if mode is None:
        return "1" if levels == 2 else "L"
    if mode == "1" and levels != 2:
        raise ArgumentValueError(f"mode='1' holds 2 levels (1 bit per pixel), not levels={levels}")
    return mode


def _spread(table: NDArray[np.float32]) -> NDArray[np.float32]:
    """How far ordered dithering pushes each channel toward the neighboring table
    colors (floats in [0, 1]): per channel, the median gap between the distinct
    values the table uses (a gray table of n levels: 1 / (n - 1); the 3-3-2 table:
    1/7, 1/7, 1/3)."""
    spread = np.zeros(table.shape[1], np.float32)
    for k in range(table.shape[1]):
        gaps = np.diff(np.unique(table[:, k]))
        if gaps.size:
            spread[k] = np.median(gaps)
    return spread


def dither(source: Any, method: str = "floyd-steinberg", levels: Optional[int] = None,
           palette: Any = None, *, mode: Optional[str] = None,
           serpentine: bool = False) -> "FrameBuffer":
    """Dither an image to fewer intensity levels or to the colors of a color table.

    Parameters
    ----------
    source : FrameBuffer or array
        The image: a frame buffer of any mode, or an image-order array (top row
        first), ``(h, w)`` gray or ``(h, w, 3|4)`` RGB(A), of uint8, bool or floats in
        [0, 1].  Alpha is ignored.
    method : str
        ``"floyd-steinberg"`` (error diffusion), ``"bayer2"``, ``"bayer4"``,
        ``"bayer8"`` (ordered dithering; ``"ordered"``, the notes' name, is
        ``"bayer4"``) or ``"none"`` (each pixel rounded to the nearest level, halves
        up, or color, to compare).
    levels : int, optional
        Evenly spaced intensity levels, 2 to 256 (default 2: a bitmap).  With mode
        ``"RGB"`` each of red, green and blue gets ``levels`` levels.
    palette : colors, optional
        A color table (see :func:`scanline.color.color_table`): dither to its colors
        and return mode ``"P"`` with that table.  Not together with ``levels``.
    mode : str, optional
        The result's mode: ``"1"`` (bitmap, 2 levels), ``"L"`` (gray levels),
        ``"RGB"`` (levels per channel) or ``"P"`` (indexed: ``palette``, or a gray
        table of ``levels`` entries).  Default: ``"P"`` with a palette, ``"1"`` for 2
        levels, else ``"L"``.  Modes ``"1"`` and ``"L"`` use the source's luminance.
    serpentine : bool
        Floyd-Steinberg only: scan odd rows right to left (fewer directional
        artifacts).

    Returns
    -------
    FrameBuffer
        The dithered image, the source's size, in the mode chosen above.

    Raises
    ------
    ArgumentValueError
        For an unknown method or mode, ``levels`` together with ``palette``, levels
        outside 2 .. 256, a mode that cannot hold the levels, or a bad source.
    ArgumentTypeError
        For a source that is not an image.

    Notes
    -----
    Floyd-Steinberg scans the rows top to bottom (image order), left to right, rounds
    each pixel plus the error it has received to the nearest level, and passes its
    error on: 7/16 to the next pixel, 3/16, 5/16 and 1/16 to the three below it.
    Error pushed past the image's border is dropped, so the mean intensity is kept
    within a fraction of a percent on images of more than a few rows.

    Ordered dithering compares each pixel's position between two levels with the
    threshold ``(M + 1/2) / n**2`` of the Bayer matrix ``M`` tiled over the image
    (``M[row mod n, col mod n]``, image rows from the top).  An n x n matrix renders
    n**2 + 1 patterns between two levels: a constant intensity is shown exactly when
    it is one of them, and otherwise within half a pattern step, 1 / (2 n**2) of the
    level spacing.  Ordered dithering to a palette offsets each channel by
    ``(1/2 - threshold)`` times the palette's typical step in that channel (the
    median gap between the distinct values the table uses), then takes the nearest
    color.

    See the module docstring for the notes' sections and the references.

    Examples
    --------
    >>> import scanline as sl
    >>> ramp = np.tile(np.linspace(0, 1, 8), (2, 1))
    >>> print(sl.text_image(dither(ramp, "bayer2")))
    --#-####
    ---#-#-#
    >>> dither(ramp, "floyd-steinberg", levels=4).to_array()[0].tolist()
    [0, 0, 85, 85, 170, 170, 255, 255]
    """
    from .._kernels import dither as kernels
    from ..framebuffer import FrameBuffer

    method = ALIASES.get(v.choice("method", method, METHODS), method)
    if palette is not None and levels is not None:
        raise ArgumentValueError("give levels or palette, not both: a palette sets the colors itself")
    if not isinstance(serpentine, (bool, np.bool_)):
        raise ArgumentValueError(f"serpentine={serpentine!r} must be True or False")
    levels = 2 if levels is None else levels_argument("levels", levels)
    out_mode = _output_mode(mode, levels, palette)
    if out_mode == "P" and palette is None:
        palette = gray_table(levels)
    table = None if palette is None else color_table(palette)

    if table is not None:
        pixels = rgb_image(source)
        floats = table.astype(np.float32) / np.float32(255)
        out = np.empty(pixels.shape[:2], np.uint8)
        search = search_cells(floats, out.size)
        if method == "floyd-steinberg":
            kernels.diffuse_palette(pixels, floats, *search, bool(serpentine), out)
        else:
            spread = _spread(floats) * (method != "none")
            kernels.ordered_palette(pixels, _thresholds(method), spread, floats, *search, out)
        return FrameBuffer.from_array(out, mode="P", color_table=table)

    image = rgb_image if out_mode == "RGB" else gray_image
    pixels = image(source, keep_uint8=True)
    lut = UNIT_LUT if pixels.dtype == np.uint8 else None
    # what the kernels store for each level: a bit, or a gray (channel) value
    values = np.arange(2, dtype=np.uint8) if out_mode == "1" else \
        np.ascontiguousarray(gray_table(levels)[:, 0])
    out = np.empty((pixels.shape[2],) + pixels.shape[:2], np.uint8)
    for k in range(pixels.shape[2]):   # channels are independent
        channel = np.ascontiguousarray(pixels[:, :, k])
        if method == "floyd-steinberg":
            kernels.diffuse_levels(channel, lut, values, bool(serpentine), out[k])
        else:
            kernels.ordered_levels(channel, lut, _thresholds(method), values, out[k])
    if out_mode == "1":
        return FrameBuffer.from_array(out[0].view(bool))
    return FrameBuffer.from_array(out[0] if out_mode == "L" else out.transpose(1, 2, 0))


def gray_levels(source: Any, n: Optional[int] = None, *,
                bits: Optional[int] = None) -> Union["FrameBuffer", NDArray[np.uint8]]:
    """Quantize an image to ``n`` evenly spaced gray levels (or ``2**bits``), each
    pixel's luminance rounded to the nearest level, without dithering.

    Returns a mode ``"L"`` FrameBuffer for a FrameBuffer source, a uint8 gray array
    for an array source.

    Parameters
    ----------
    source : FrameBuffer or array_like
        The image (see :func:`dither`).
    n : int, optional
        The number of levels, 2 .. 256.
    bits : int, optional
        Bits per pixel, 1 .. 8 (``n = 2**bits``); give ``n`` or ``bits``, not both.

    Returns
    -------
    FrameBuffer or numpy.ndarray
        Mode ``"L"`` for a frame buffer source, else a uint8 (h, w) array.

    Raises
    ------
    ArgumentValueError
        When neither or both of ``n`` and ``bits`` are given, or they are out of range.

    Examples
    --------
    >>> gray_levels(np.array([[0, 40, 100, 128, 200, 255]], np.uint8), bits=2).tolist()
    [[0, 0, 85, 170, 170, 255]]
    """
    from ..framebuffer import FrameBuffer

    if (n is None) == (bits is None):
        raise ArgumentValueError(f"give the number of levels n or bits, exactly one (got n={n!r}, bits={bits!r})")
    if bits is not None:
        bits = v.positive_int("bits", bits)
        if bits > 8:
            raise ArgumentValueError(f"bits={bits} must be 1 to 8 (2 to 256 levels)")
        n = 2 ** bits
    n = levels_argument("n", n)
    fb = dither(source, "none", levels=n, mode="L")
    return fb if isinstance(source, FrameBuffer) else fb.to_array()


def indexed(source: Any, table: Any) -> "FrameBuffer":
    """An indexed (mode ``"P"``) frame buffer of ``source`` with color table
    ``table``: each pixel stores the index of the nearest table color (no
    dithering; ``dither(source, palette=table)`` dithers).

    Parameters
    ----------
    source : FrameBuffer or array_like
        The image (see :func:`dither`).
    table : array_like or sequence of colors
        The color table (see :func:`scanline.color.color_table`).

    Returns
    -------
    FrameBuffer
        Mode ``"P"`` with color table ``table``.

    Examples
    --------
    >>> fb = indexed(np.array([[[250, 0, 0], [0, 0, 10]]], np.uint8), ["black", "red"])
    >>> fb.mode, fb.to_array().tolist()
    ('P', [[1, 0]])
    """
    return dither(source, "none", palette=table)


def halftone(source: Any, size: int = 4) -> "FrameBuffer":
    """A halftone bitmap: each pixel becomes a ``size`` x ``size`` cell of dots
    (``size`` 2, 4 or 8) in which ``intensity * size**2`` dots, rounded to the nearest
    whole number (halves up), are set in the order of the Bayer matrix, so a cell
    shows ``size**2 + 1`` intensity levels.  The result is ``size`` times wider and
    taller: resolution traded for gray levels.

    Parameters
    ----------
    source : FrameBuffer or array_like
        The image (see :func:`dither`); its luminance is used.
    size : {2, 4, 8}
        The cell's side in pixels.

    Returns
    -------
    FrameBuffer
        Mode ``"1"``, ``size`` times the source's width and height.

    Raises
    ------
    ArgumentValueError
        When ``size`` is not 2, 4 or 8, or for a bad source.

    Notes
    -----
    Halftoning (the printer's technique) is not in the notes; this is the classic
    n x n dot-pattern approximation of the standard texts.  It equals ordered
    dithering (:func:`dither` with ``"bayer<size>"``) of the image enlarged ``size``
    times.

    Examples
    --------
    >>> import scanline as sl
    >>> print(sl.text_image(halftone(np.array([[0.0, 0.25, 0.5, 1.0]]), 2)))
    --#-#-##
    -----###
    """
    if size not in (2, 4, 8) or isinstance(size, bool):
        raise ArgumentValueError(f"size={size!r} must be 2, 4 or 8 (the cell's side in pixels)")
    pixels = gray_image(source)[:, :, 0]
    cells = np.repeat(np.repeat(pixels, size, axis=0), size, axis=1)
    return dither(cells, f"bayer{size}")
