"""Seed fills: ``flood_fill`` and ``boundary_fill`` (notes, chapter 2, Q.8).

Both start from an interior pixel (the seed) and paint outward, span by span, with
the scan-line seed fill of :mod:`scanline._kernels.seedfill`.
"""

from __future__ import annotations

import numbers
from typing import TYPE_CHECKING, Any, Callable, Literal, Optional, Union, cast

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .._kernels._jit import call
from .._kernels.variants import layout, token
from ..errors import ArgumentTypeError, ArgumentValueError
from ._common import colors, target

if TYPE_CHECKING:
    from .._typing import Color, Colors, Connectivity
    from ..framebuffer import FrameBuffer

#: The seed fills of the kernel.
Kind = Literal["flood", "boundary", "soft"]
#: The kernel's reference colors, or a function of (buf, packed, x, y) giving them.
Reference = Union[NDArray[np.integer[Any]],
                  Callable[[NDArray[np.uint8], bool, int, int], NDArray[np.int64]]]
#: Allowed values of ``connectivity``.
CONNECTIVITIES = (4, 8)


def seed(fb: FrameBuffer, x: object, y: object) -> tuple[int, int]:
    """The seed (x, y) rounded to a pixel, which must lie in ``fb``."""
    x = v.coordinate("x", x)
    y = v.coordinate("y", y)
    for name, value, size in (("x", x, fb.width), ("y", y, fb.height)):
        if not 0 <= value < size:
            raise ArgumentValueError(
                f"the seed must be a pixel of the frame buffer: {name}={value} is outside "
                f"0..{size - 1} (the frame buffer is {fb.width} x {fb.height})"
            )
    return x, y


def eight_connected(connectivity: object) -> int:
    """1 for ``connectivity=8``, 0 for 4; anything else is an error."""
    if isinstance(connectivity, numbers.Integral) and not isinstance(connectivity, bool) \
            and connectivity in CONNECTIVITIES:
        return int(connectivity == 8)
    raise ArgumentValueError(
        f"connectivity must be 4 (edge neighbors) or 8 (edge and corner neighbors), "
        f"got {v._show(connectivity)}"
    )


def fill(fb: FrameBuffer, x: object, y: object, kind: Kind, connectivity: object,
         ref: Reference, color: NDArray[np.uint8], buf: Optional[NDArray[np.uint8]] = None
         ) -> int:
    """Run the seed fill ``kind`` ("flood", "boundary" or "soft") from (x, y); return
    the number of pixels filled.  ``ref`` is the kernel's reference colors (see
    :mod:`scanline._kernels.seedfill`) or a function of (buf, packed, x, y) giving them.
    ``buf``: fill this copy of the frame buffer's storage instead."""
    from .._kernels import seedfill as k

    own, packed, width, height = target(fb)
    buf = own if buf is None else buf
    sx, sy = seed(fb, x, y)
    eight = eight_connected(connectivity)
    table = np.ascontiguousarray(ref(buf, packed, sx, sy) if callable(ref) else ref, np.int64)
    code = {"flood": k.FLOOD, "boundary": k.BOUNDARY, "soft": k.SOFT}[kind]
    # the region is unknown before the fill: the raster bounds it (each pixel is
    # classified once and painted at most once)
    return int(call(k.seed_fill, 3 * width * height, buf, layout(packed), token(code), width,
                    height, sx, sy, eight, table, color))


def _region(buf: NDArray[np.uint8], packed: bool, width: int) -> NDArray[np.uint8]:
    """The storage as one comparable value per pixel: bits, or channel rows."""
    return np.unpackbits(buf[:, :, 0], axis=1, count=width)[..., None] if packed else buf


def over_region(fb: FrameBuffer, x: object, y: object, kind: Kind, connectivity: object,
                ref: Reference, color: Color) -> int:
    """A seed fill in a translucent ``color``: the region is found on two copies of
    the storage, filled with two different values (a pixel of the region changes in
    at least one of them, any other pixel in neither), then ``color`` is composited
    over it once (:mod:`scanline.draw._blend`).  Returns the region's size."""
    from . import _blend

    source = _blend.sources(fb, [color], 1)[0]
    buf, packed, width, height = target(fb)
    region = np.zeros((height, width), bool)
    for marker in (0, 255):
        copy = buf.copy()
        value = np.full(buf.shape[2], marker & 1 if packed else marker, np.uint8)
        count = fill(fb, x, y, kind, connectivity, ref, value, buf=copy)
        region |= (_region(copy, packed, width) != _region(buf, packed, width)).any(axis=2)
    _blend.composite(fb, (region * np.uint8(255))[..., None], 0, 0, source)
    return count


def _fill_color(fb: FrameBuffer, x: object, y: object, kind: Kind, connectivity: object,
                ref: Reference, color: Optional[Color]) -> int:
    """Fill opaque, or composite a translucent color over the region."""
    from ._blend import translucent

    if color is not None and translucent(color, one=True):
        return over_region(fb, x, y, kind, connectivity, ref, color)
    return fill(fb, x, y, kind, connectivity, ref, fb.pixel(color))


def seed_value(buf: NDArray[np.uint8], packed: bool, x: int, y: int) -> NDArray[np.int64]:
    """The stored value of pixel (x, y): its bit in packed storage, else its channels."""
    if packed:
        return np.array([(int(buf[y, x >> 3, 0]) >> (7 - (x & 7))) & 1], np.int64)
    return np.asarray(buf[y, x], np.int64)


def _tolerance(fb: FrameBuffer, tolerance: object) -> int:
    if isinstance(tolerance, bool) or not isinstance(tolerance, numbers.Real):
        raise ArgumentTypeError(
            f"tolerance must be a number of levels >= 0, got {v._show(tolerance)}")
    # a numbers.Real (an int of any size, a Fraction, a numpy scalar ...): typeshed's
    # numbers.Real has no >= and does not suit min(), hence the float view
    level = cast(float, tolerance)
    if not level >= 0:  # also NaN
        raise ArgumentValueError(f"tolerance must be a number of levels >= 0, got {tolerance!r}")
    if level and fb.mode == "P":
        raise ArgumentValueError(
            f"tolerance={tolerance!r}: mode 'P' stores color-table indices, which have no "
            "distance; use tolerance=0"
        )
    return int(min(level, 255))


def flood_fill(fb: FrameBuffer, x: float, y: float, color: Optional[Color] = None,
               connectivity: Connectivity = 4, tolerance: float = 0) -> int:
    """Recolor the connected region of pixels that have the seed's value.

    Parameters
    ----------
    fb : FrameBuffer
    x, y : number
        The seed, a pixel of ``fb`` (rounded to the nearest pixel center); a seed
        outside the frame buffer is an error.
    color : color
        The fill color; a translucent one is composited over the region, each
        pixel once.
    connectivity : {4, 8}
        4: a pixel's neighbors share an edge with it; 8: or a corner.
    tolerance : number, >= 0
        A pixel belongs to the region when each of its channels differs from the
        **seed's original value** by at most ``tolerance`` levels (cv2.floodFill's
        ``FLOODFILL_FIXED_RANGE`` mode, not a neighbor-to-neighbor range).  In mode
        ``"P"`` only 0 (indices have no distance); in mode ``"1"`` any tolerance >= 1
        takes both bit values.

    Returns
    -------
    int
        The number of pixels in the region, all now ``color`` (also when ``color``
        is the old value and nothing visibly changes).

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer, or ``tolerance`` is not a number.
    ArgumentValueError
        For a seed outside the frame buffer, a connectivity other than 4 or 8, a
        negative or NaN ``tolerance`` (or a nonzero one in mode ``"P"``), or a bad
        color.

    Notes
    -----
    Notes, chapter 2, Q.8, "Flood Fill Algorithm": replace a specified interior color
    instead of searching for a boundary color.  The scan-line seed fill (Smith 1979;
    Rogers 1985; Heckbert 1990) fills a whole span per stack entry, not one pixel:
    pop a seed, extend it left and right to the ends of its span, fill the span, then
    push the rightmost pixel of each run of region pixels in the rows above and below
    (over x_left..x_right, one pixel further each way for 8-connectivity).  The stack
    is an array that grows as needed: no recursion, no size limit.  Filled pixels are
    marked in a separate visited mask, so a fill color that still matches the region
    (a generous ``tolerance``) cannot loop.  ``scanline trace flood-fill`` shows the
    stack step by step.

    References
    ----------
    A. R. Smith, "Tint fill", SIGGRAPH '79 (Computer Graphics 13(2)), 276-283, 1979.
    D. F. Rogers, "Procedural Elements for Computer Graphics", McGraw-Hill, 1985,
    section 2-26, "A scan line seed fill algorithm".
    P. S. Heckbert, "A seed fill algorithm", in A. S. Glassner (ed.), Graphics Gems,
    Academic Press, 275-277, 1990.
    D. Hearn and M. P. Baker, "Computer Graphics", 2nd ed., Prentice Hall, 1994,
    section 3-11.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(7, 3, mode="L")
    >>> sl.draw.line(fb, 3, 0, 3, 2, color=128)         # a wall
    >>> sl.draw.flood_fill(fb, 0, 0, color=255)          # the pixels left of it
    9
    >>> print(sl.text_image(fb))
    ####---
    ####---
    ####---
    """
    target(fb)  # type check
    tol = _tolerance(fb, tolerance)

    def ref(buf: NDArray[np.uint8], packed: bool, sx: int, sy: int) -> NDArray[np.int64]:
        value = seed_value(buf, packed, sx, sy)
        return np.stack([value - tol, value + tol])

    return _fill_color(fb, x, y, "flood", connectivity, ref, color)


def boundary_fill(fb: FrameBuffer, x: float, y: float, color: Optional[Color] = None,
                  boundary: Optional[Colors] = None, connectivity: Connectivity = 4) -> int:
    """Paint outward from the seed until pixels of the boundary color(s).

    Parameters
    ----------
    fb : FrameBuffer
    x, y : number
        The seed, a pixel of ``fb``; a seed outside the frame buffer is an error.  A
        seed on the boundary fills nothing.
    color : color
        The fill color; a translucent one is composited over the region.
    boundary : color or list of colors, optional
        The color of the area's border; a list gives several (a tuple is one RGB(A)
        color).  Default: the frame buffer's ``foreground``, the color outlines are
        drawn in when no color is given.
    connectivity : {4, 8}
        4: spread to the edge neighbors; 8: also to the corner neighbors (the
        boundary must then be 4-connected to hold the fill).

    Returns
    -------
    int
        The number of pixels filled: the region bounded by the boundary colors.

    Raises
    ------
    ArgumentTypeError
        If ``fb`` is not a FrameBuffer.
    ArgumentValueError
        For a seed outside the frame buffer, a connectivity other than 4 or 8, an
        empty list of boundary colors, or a bad color.

    Notes
    -----
    Notes, chapter 2, Q.8, "Boundary Fill Algorithm", with the scan-line seed fill
    described in :func:`flood_fill`.

    The notes warn: "Recursive boundary fill algorithm may not fill regions correctly
    if some interior pixels are already displayed in the fill color.  This occurs
    because the algorithm checks next point both for boundary color and for fill
    color."  The recursive procedure must stop at fill-colored pixels, since that is
    how it recognizes where it has been; so a fill-colored stroke inside the area
    blocks it like a wall.  Here, where the fill has been is recorded in a separate
    visited mask, and a pixel joins the region when it is neither visited nor a
    boundary color: a pixel that already has the fill color is filled through.

    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(7, 3, mode="L")
    >>> sl.draw.line(fb, 3, 0, 3, 2, color=200)          # fill-colored, not boundary
    >>> sl.draw.boundary_fill(fb, 0, 0, color=200, boundary=255)
    21
    >>> print(sl.text_image(fb))
    #######
    #######
    #######

    References
    ----------
    See :func:`flood_fill`.

    Examples
    --------
    A wall in the boundary color holds the fill on its left (the wall's own pixels
    are not filled, but they are not background either):

    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(7, 3, mode="L")
    >>> sl.draw.line(fb, 3, 0, 3, 2, color=255)         # the boundary
    >>> sl.draw.boundary_fill(fb, 0, 0, color=128, boundary=255)
    9
    >>> fb.to_array()[0].tolist()
    [128, 128, 128, 255, 0, 0, 0]
    """
    target(fb)  # type check
    if isinstance(boundary, (list, np.ndarray)):
        if len(boundary) == 0:
            raise ArgumentValueError("boundary must hold at least one color, got an empty list")
        ref = colors(fb, boundary, len(boundary), "boundary")
    else:
        ref = fb.pixel(boundary, "boundary")[None, :]
    return _fill_color(fb, x, y, "boundary", connectivity, ref, color)
