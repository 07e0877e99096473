"""Attributes of output primitives (notes, syllabus: "Attributes of output primitives";
Hearn & Baker, "Computer Graphics", chapter 4).

:class:`FillStyle` is the area-fill attribute: every area primitive (polygons, filled
circles and ellipses, chords, pies) takes ``style=`` and paints through
:func:`scanline.draw._area.fill_area`, which hands the style the shape as a callable
that scan-converts it, so one style works for every shape.

Styles (Hearn & Baker, section 4-4, "Area-fill attributes"):

``FillStyle.solid()``
    every pixel of the area gets the fill color (the default, ``style=None``);
``FillStyle.hollow()``
    only the boundary is drawn, in the fill color;
``FillStyle.pattern(tile)``
    a rectangular tile is repeated over the area ("tiling"), anchored at the
    frame-buffer origin or at a reference point of the shape;
``FillStyle.hatch(angle, spacing)``
    parallel lines at any angle, or two perpendicular families (cross-hatch).

How a pattern or hatch is painted: the shape is scan-converted into a mask the size
of its bounding box clipped to the frame buffer (so the cost follows the shape, not the
frame buffer); a compiled loop (``_kernels/styles.py``) then gives each masked pixel
the style's value at its device position.  Creating a style does not load numba.
"""

import math
import numbers
from types import MappingProxyType
from typing import TYPE_CHECKING, Any, Callable, Optional, Sequence, Tuple, Union, cast

import numpy as np
from numpy.typing import NDArray

from . import _validate as v
from .color.spec import Channels, rgba
from .errors import ArgumentTypeError, ArgumentValueError

if TYPE_CHECKING:
    from ._typing import Angle, Color, Point
    from .framebuffer import FrameBuffer

#: A normalized tile cell or hatch background: the fill color marker, an int or RGBA.
Spec = Union[str, int, Tuple[int, int, int, int]]
#: What a style builder returns: parameters, tile cells, palette and where each entry is.
Built = Tuple[dict[str, Any], Optional[NDArray[np.int32]], Tuple[Any, ...], Tuple[Any, ...]]

KINDS = ("solid", "hollow", "pattern", "hatch")
ANCHORS = ("origin", "shape")

#: A tile cell that takes the fill color (``True`` in a tile).
_FILL = "fill color"


def _tile(*rows: str) -> NDArray[np.bool_]:
    """A read-only boolean tile from text rows in image order ('#' = True)."""
    a = np.array([[c == "#" for c in row] for row in rows], bool)
    a.flags.writeable = False
    return a


#: Named boolean tiles for :meth:`FillStyle.pattern` (image order: row 0 on top;
#: True takes the fill color, False leaves the pixel unchanged).
TILES = MappingProxyType({
    "checker": _tile("#-", "-#"),
    "dots": _tile("#---", "----", "--#-", "----"),
    "diagonal": _tile("---#", "--#-", "-#--", "#---"),
    "grid": _tile("########", "#-------", "#-------", "#-------",
                  "#-------", "#-------", "#-------", "#-------"),
    "bricks": _tile("########", "#-------", "#-------", "#-------",
                    "########", "----#---", "----#---", "----#---"),
})


# -- validation of the kind-specific arguments ----------------------------------------

def _color_spec(name: str, value: object) -> Spec:
    """A color spec normalized at construction: an int (gray level, bit or color-table
    index, decided by the frame buffer's mode) or an (r, g, b, a) tuple."""
    if isinstance(value, numbers.Integral) and not isinstance(value, bool):
        if 0 <= int(value) <= 255:
            return int(value)
        raise ArgumentValueError(f"{name}={value!r}: an integer color must be in 0..255")
    return rgba(value, name)


def _cell(name: str, value: object) -> Optional[Spec]:
    """One tile cell: True -> the fill color, False/None -> transparent, else a color."""
    if value is None or value is False or value is np.False_:
        return None
    if value is True or value is np.True_:
        return _FILL
    if isinstance(value, np.integer):
        value = int(value)
    return _color_spec(name, value)


def _grid(tile: Any) -> list[list[Any]]:
    """The cells of a tile given as a sequence of rows; returns a list of row lists."""
    if isinstance(tile, (str, bytes)) or not hasattr(tile, "__len__"):
        raise ArgumentTypeError(
            f"tile must be a 2-D array-like (rows of cells) or a name in FillStyle.TILES, "
            f"got {v._show(tile)}"
        )
    rows = [list(row) if hasattr(row, "__len__") and not isinstance(row, (str, bytes))
            else None for row in tile]
    if not rows or any(r is None for r in rows) or not rows[0]:
        raise ArgumentValueError(
            f"tile must be a non-empty 2-D array-like (a list of rows), got {v._show(tile)}"
        )
    if any(len(r or ()) != len(rows[0]) for r in rows):
        raise ArgumentValueError(
            f"tile rows must all have the same length, got lengths {[len(r or ()) for r in rows]}"
        )
    return cast("list[list[Any]]", rows)


def _palette(tile: Any) -> tuple[NDArray[np.int32], tuple[Spec, ...], tuple[tuple[int, int], ...]]:
    """Normalize a tile to ``(cells, palette)``: ``cells`` a read-only int32 (th, tw)
    array in image order indexing ``palette`` (-1: transparent), ``palette`` a tuple
    of color specs (``_FILL`` for the fill color) and ``where`` the first cell of each
    entry (for error messages)."""
    if isinstance(tile, str):
        if tile not in TILES:
            v.choice("tile", tile, tuple(TILES))
        tile = TILES[tile]
    a = tile if isinstance(tile, np.ndarray) else None
    if a is not None and a.dtype != object:
        if a.size == 0 or a.ndim not in (2, 3) or (a.ndim == 3 and a.shape[2] not in (3, 4)):
            raise ArgumentValueError(
                f"tile array must be non-empty with shape (th, tw) or (th, tw, 3|4), got {a.shape}"
            )
        if a.dtype == bool:
            cells = np.where(a, 0, -1).astype(np.int32)
            return cells, (_FILL,), ((0, 0),)
        if not np.issubdtype(a.dtype, np.integer):
            raise ArgumentTypeError(
                f"tile array must hold booleans or integer colors, got dtype {a.dtype}"
            )
        if a.min() < 0 or a.max() > 255:
            raise ArgumentValueError("tile array values must be in 0..255")
        flat = a.reshape(a.shape[0] * a.shape[1], -1)
        colors, first, inverse = np.unique(flat, axis=0, return_index=True, return_inverse=True)
        palette: tuple[Spec, ...]
        if a.ndim == 2:
            palette = tuple(int(c[0]) for c in colors)
        else:
            palette = tuple(rgba(Channels(int(x) for x in c)) for c in colors)
        where = tuple(divmod(int(i), a.shape[1]) for i in first)
        return inverse.reshape(a.shape[:2]).astype(np.int32), palette, where
    rows = _grid(tile)
    index: dict[Spec, int] = {}
    found: list[tuple[int, int]] = []
    cells = np.empty((len(rows), len(rows[0])), np.int32)
    for r, row in enumerate(rows):
        for c, value in enumerate(row):
            spec = _cell(f"tile[{r}][{c}]", value)
            if spec is None:
                cells[r, c] = -1
                continue
            if spec not in index:
                index[spec] = len(found)
                found.append((r, c))
            cells[r, c] = index[spec]
    return cells, tuple(index), tuple(found)


def _anchor(anchor: str, reference: Any) -> tuple[str, Optional[tuple[int, int]]]:
    v.choice("anchor", anchor, ANCHORS)
    if reference is None:
        return anchor, None
    if anchor != "shape":
        raise ArgumentValueError(
            f"reference={v._show(reference)} needs anchor='shape'; with anchor='origin' the "
            "pattern is fixed to device (0, 0)"
        )
    if isinstance(reference, (str, bytes)) or not hasattr(reference, "__len__") or len(reference) != 2:
        raise ArgumentValueError(
            f"reference must be an (x, y) device point, got {v._show(reference)}"
        )
    return anchor, (v.coordinate("reference x", reference[0]), v.coordinate("reference y", reference[1]))


def _positive(name: str, value: object) -> float:
    number = v.number(name, value)
    if number <= 0:
        raise ArgumentValueError(f"{name} must be > 0 (pixels), got {number:g}")
    return number


def _direction(angle: float) -> tuple[float, float]:
    """(cos, sin) of ``angle``, exact (0 and +-1) at multiples of pi/2."""
    c, s = math.cos(angle), math.sin(angle)
    if abs(c) < 1e-12:
        c, s = 0.0, math.copysign(1.0, s)
    elif abs(s) < 1e-12:
        c, s = math.copysign(1.0, c), 0.0
    return c, s


# -- painting --------------------------------------------------------------------------

def _clip(fb: "FrameBuffer", bbox: Sequence[float]) -> tuple[int, int, int, int, int, int]:
    """``bbox`` (inclusive device pixels; fractions widen it outward) as ints, and
    its part inside ``fb``: ``(xmin, ymin, x0, y0, x1, y1)``; x0 > x1 or y0 > y1 when
    nothing is visible."""
    b = [float(e) for e in bbox]
    if len(b) != 4 or not all(map(math.isfinite, b)):
        raise ArgumentValueError(f"bbox must be 4 finite numbers (xmin, ymin, xmax, ymax), got {bbox!r}")
    xmin, ymin, xmax, ymax = math.floor(b[0]), math.floor(b[1]), math.ceil(b[2]), math.ceil(b[3])
    return (xmin, ymin, max(xmin, 0), max(ymin, 0),
            min(xmax, fb.width - 1), min(ymax, fb.height - 1))


class FillStyle:
    """How an area is filled: ``"solid"``, ``"hollow"``, ``"pattern"`` or ``"hatch"``.

    Make styles with the constructors :meth:`solid`, :meth:`hollow`, :meth:`pattern`
    and :meth:`hatch` (or ``FillStyle(kind, **arguments)``, which calls them) and pass
    them to any area primitive as ``style=``.  Styles are immutable, hashable and
    compare by value; the fill color is the primitive's ``color``.

    Parameters
    ----------
    kind : {"solid", "hollow", "pattern", "hatch"}
        The fill style.
    **arguments
        The arguments of the constructor of that kind (:meth:`pattern`,
        :meth:`hatch`; none for the other two).

    Raises
    ------
    ArgumentValueError
        For an unknown kind or a bad argument of it.
    ArgumentTypeError
        For an argument the kind does not take, or one of the wrong type.

    Attributes
    ----------
    kind : str
        ``"solid"``, ``"hollow"``, ``"pattern"`` or ``"hatch"``.
    tile, anchor, reference
        Pattern styles: the tile (bool array when it only says fill/leave, else an
        object array of cells), ``"origin"`` or ``"shape"``, the reference point or None.
    angle, spacing, cross, line_width, background, anchor, reference
        Hatch styles.

    Notes
    -----
    Notes, syllabus: "Area-Fill Attributes - Fill styles. Pattern fill"; the objective
    question "Rectangular patterns are sometimes referred as tiling patterns".  As in
    Hearn & Baker (section 4-4), a pattern is a rectangular mask replicated across the
    area like floor tiles, its position fixed by a *reference point*: the frame-buffer
    origin (neighboring shapes continue each other's pattern) or a point of the shape
    (the pattern moves with the shape).  Hatch fill is the same idea with a pattern of
    parallel lines computed per pixel instead of stored.

    References
    ----------
    D. Hearn and M. P. Baker, "Computer Graphics", 2nd ed., Prentice Hall, 1994,
    section 4-4, "Area-fill attributes" (fill styles, pattern fill, hatch fill).
    J. D. Foley, A. van Dam, S. K. Feiner and J. F. Hughes, "Computer Graphics:
    Principles and Practice", 2nd ed., Addison-Wesley, 1990, chapter 3, "Pattern
    filling" (patterns anchored to the screen origin or to the primitive).

    Examples
    --------
    >>> import scanline as sl
    >>> sl.FillStyle.hatch(angle=0.0, spacing=4)
    FillStyle.hatch(angle=0.0, spacing=4, cross=False, line_width=1, background=None, anchor='origin')
    >>> sl.FillStyle.pattern("checker").kind
    'pattern'
    """

    __slots__ = ("_kind", "_params", "_cells", "_palette", "_where")

    #: Named boolean tiles (image order, True = fill color): ``checker``, ``dots``,
    #: ``diagonal``, ``grid``, ``bricks``.  ``FillStyle.pattern("bricks")`` uses one.
    TILES = TILES

    def __init__(self, kind: str = "solid", **arguments: Any) -> None:
        v.choice("kind", kind, KINDS)
        _fields(self, kind, *_BUILDERS[kind](**arguments))

    # -- constructors --------------------------------------------------------------------
    @classmethod
    def solid(cls) -> "FillStyle":
        """Every pixel of the area takes the fill color (same as ``style=None``).

        Returns
        -------
        FillStyle
            A ``"solid"`` style.

        Examples
        --------
        >>> import scanline as sl
        >>> sl.FillStyle.solid() == sl.FillStyle()
        True
        """
        return cls("solid")

    @classmethod
    def hollow(cls) -> "FillStyle":
        """Only the boundary of the area is drawn, in the fill color.

        Returns
        -------
        FillStyle
            A ``"hollow"`` style.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(5, 4, mode="1")
        >>> box = [(0, 0), (4, 0), (4, 3), (0, 3)]
        >>> sl.draw.polygon(fb, box, color=1, style=sl.FillStyle.hollow())
        >>> print(sl.text_image(fb))
        #####
        #---#
        #---#
        #####
        """
        return cls("hollow")

    @classmethod
    def pattern(cls, tile: Any, anchor: str = "origin",
                reference: Optional["Point"] = None) -> "FillStyle":
        """Fill with a rectangular tile repeated over the area.

        Parameters
        ----------
        tile : 2-D array-like, (th, tw, 3|4) integer array or str
            Rows of cells in image order: row 0 is the *top* row of the tile as you
            look at it.  A cell is ``True`` (the fill color), ``False`` or ``None``
            (transparent: the pixel keeps its value), or any color: a name, hex
            string, (r, g, b[, a]) tuple or integer (gray level, bit or color-table
            index, as the frame buffer's mode reads it).  A boolean array is a
            transparent mask; an integer (th, tw, 3|4) array gives RGB(A) colors.  A
            string names one of :attr:`TILES`.
        anchor : {"origin", "shape"}
            Where the tile's bottom-left cell sits: on device pixel (0, 0) and every
            multiple of the tile size from it (``"origin"``: the pattern stays put when
            the shape moves), or on ``reference`` (``"shape"``).
        reference : (x, y), optional
            With ``anchor="shape"``: the device point (rounded to a pixel) of the tile's
            bottom-left cell.  Default: the lower-left corner of the shape's bounding
            box, so the pattern moves with the shape.

        Notes
        -----
        Device pixel (x, y) takes tile cell ``tile[th - 1 - (y - ay) mod th][(x - ax)
        mod tw]`` where (ax, ay) is the anchor point.  In mode ``"P"`` the tile's colors
        are looked up in (or appended to) the color table when the area is painted.

        Returns
        -------
        FillStyle
            A ``"pattern"`` style.

        Raises
        ------
        ArgumentValueError
            For a tile that is empty, ragged, paints nothing or holds bad colors, an
            unknown tile name or anchor, or a reference without ``anchor="shape"``.
        ArgumentTypeError
            For a tile that is not rows of cells.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(6, 4, mode="1")
        >>> style = sl.FillStyle.pattern([[True, False, False], [False, True, False]])
        >>> box = [(-0.5, -0.5), (5.5, -0.5), (5.5, 3.5), (-0.5, 3.5)]  # pixels 0..5 x 0..3
        >>> sl.draw.polygon(fb, box, color=1, style=style)
        >>> print(sl.text_image(fb))
        #--#--
        -#--#-
        #--#--
        -#--#-
        """
        return cls("pattern", tile=tile, anchor=anchor, reference=reference)

    @classmethod
    def hatch(cls, angle: "Angle" = 0.0, spacing: float = 8, cross: bool = False,
              line_width: float = 1, background: Optional["Color"] = None,
              anchor: str = "origin", reference: Optional["Point"] = None) -> "FillStyle":
        """Fill with parallel lines (hatching), or two perpendicular families.

        Parameters
        ----------
        angle : float
            Direction of the lines in radians, counterclockwise from +x.
        spacing : float
            Distance between neighboring lines, measured perpendicular to them, in
            pixels (> 0).
        cross : bool
            Add the family of lines perpendicular to the first (cross-hatch).
        line_width : float
            Thickness of each line in pixels (> 0), measured like the width of raster
            lines: vertically for lines nearer horizontal, horizontally for steeper
            ones.  ``line_width >= spacing`` fills the area solid.
        background : color, optional
            None leaves the area's other pixels unchanged; a color paints them.
        anchor : {"origin", "shape"}
            The lines pass through device pixel (0, 0), or through ``reference``.
        reference : (x, y), optional
            With ``anchor="shape"``: a point the lines pass through.  Default: the
            lower-left corner of the shape's bounding box.

        Notes
        -----
        The exact rule.  Let (c, s) = (cos angle, sin angle) and d = c y - s x the
        signed distance of pixel center (x, y) (relative to the anchor) from the line
        through the anchor.  With the *minor-axis width* ``w' = line_width * max(|c|, |s|)``,
        the pixel is a hatch pixel iff ``(d + w'/2) mod spacing < w'``.  So a line of
        width 1 has exactly one pixel per column when it is nearer horizontal (one per
        row when steeper), like a Bresenham line; at 0 and pi/2 it is exactly every
        ``spacing``-th row or column, and at pi/4 a single diagonal.  The share of hatch
        pixels in a large area is ``line_width * max(|c|, |s|) / spacing`` per family.
        Angles that are multiples of pi/2 are exact (cos and sin snapped to 0 and +-1).

        Returns
        -------
        FillStyle
            A ``"hatch"`` style.

        Raises
        ------
        ArgumentValueError
            For a spacing or line width <= 0, a bad angle, background or anchor.
        ArgumentTypeError
            When ``cross`` is not a bool.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(8, 5, mode="1")
        >>> style = sl.FillStyle.hatch(angle=0.0, spacing=2)
        >>> box = [(-0.5, -0.5), (7.5, -0.5), (7.5, 4.5), (-0.5, 4.5)]  # pixels 0..7 x 0..4
        >>> sl.draw.polygon(fb, box, color=1, style=style)
        >>> print(sl.text_image(fb))
        ########
        --------
        ########
        --------
        ########
        """
        return cls("hatch", angle=angle, spacing=spacing, cross=cross, line_width=line_width,
                   background=background, anchor=anchor, reference=reference)

    @classmethod
    def parse(cls, text: str) -> "FillStyle":
        """A style from one word, as the command line and scene files spell it.

        ``solid``, ``hollow``, ``pattern:NAME[:shape]`` (NAME one of :attr:`TILES`;
        ``:shape`` anchors it to the shape), ``hatch:DEGREES[:SPACING[:WIDTH]]`` and
        ``crosshatch:DEGREES[:SPACING[:WIDTH]]`` (the angle in degrees here).

        Parameters
        ----------
        text : str
            The style's spelling.

        Returns
        -------
        FillStyle
            The style.

        Raises
        ------
        ArgumentTypeError
            When ``text`` is not a str.
        ArgumentValueError
            When it spells no style, or bad arguments of one.

        Examples
        --------
        >>> FillStyle.parse("crosshatch:45:6")
        FillStyle.hatch(angle=0.7853981633974483, spacing=6, cross=True, line_width=1, background=None, anchor='origin')
        >>> FillStyle.parse("pattern:bricks:shape") == FillStyle.pattern("bricks", anchor="shape")
        True
        """
        if not isinstance(text, str):
            raise ArgumentTypeError(f"style must be a string such as 'hatch:45:8', got {v._show(text)}")
        word, *args = text.strip().split(":")
        try:
            if word in ("solid", "hollow") and not args:
                return cls(word)
            if word == "pattern" and 1 <= len(args) <= 2 and args[1:] in ([], ["shape"]):
                return cls.pattern(args[0], anchor="shape" if args[1:] else "origin")
            if word in ("hatch", "crosshatch") and 1 <= len(args) <= 3:
                values = [float(a) for a in args]
                kw: dict[str, Any] = dict(zip(("spacing", "line_width"), values[1:]))
                return cls.hatch(math.radians(values[0]), cross=word == "crosshatch", **kw)
        except (ValueError, TypeError) as error:
            raise ArgumentValueError(f"style={text!r}: {error}") from None
        raise ArgumentValueError(
            f"style={text!r} is not a fill style; use solid, hollow, pattern:NAME[:shape] "
            f"(NAME: {', '.join(TILES)}), hatch:DEGREES[:SPACING[:WIDTH]] or "
            "crosshatch:DEGREES[:SPACING[:WIDTH]]"
        )

    # -- value semantics -------------------------------------------------------------------
    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError(f"FillStyle is immutable; make a new one with FillStyle.{self._kind}(...)")

    def __getattr__(self, name: str) -> Any:
        params = object.__getattribute__(self, "_params")
        if name in params:
            return params[name]
        raise AttributeError(f"a {self._kind!r} FillStyle has no attribute {name!r}")

    @property
    def kind(self) -> str:
        """``"solid"``, ``"hollow"``, ``"pattern"`` or ``"hatch"``."""
        return cast(str, self._kind)

    @property
    def tile(self) -> NDArray[Any]:
        """Pattern styles: the tile in image order (a read-only bool array when its cells
        only say fill / leave, else an object array of normalized cells)."""
        if self._kind != "pattern":
            raise AttributeError(f"a {self._kind!r} FillStyle has no attribute 'tile'")
        out: NDArray[Any]
        if self._palette == (_FILL,):
            out = self._cells >= 0
        else:
            lookup = np.empty(len(self._palette) + 1, object)
            lookup[:-1] = [True if p == _FILL else p for p in self._palette]
            lookup[-1] = None
            out = lookup[self._cells]
        out.flags.writeable = False
        return out

    def _key(self) -> tuple[Any, ...]:
        cells = None if self._cells is None else (self._cells.shape, self._cells.tobytes())
        return (self._kind, tuple(sorted(self._params.items())), cells, self._palette)

    def __reduce__(self) -> tuple[Callable[..., "FillStyle"], tuple[Any, ...]]:
        return (_restore, (self._kind, dict(self._params), self._cells, self._palette, self._where))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, FillStyle) and self._key() == other._key()

    def __hash__(self) -> int:
        return hash(self._key())

    def __repr__(self) -> str:
        args = []
        if self._kind == "pattern":
            th, tw = self._cells.shape
            colors = "fill color" if self._palette == (_FILL,) else f"{len(self._palette)} colors"
            args.append(f"<{th}x{tw} tile, {colors}>")
        args += [f"{k}={val!r}" for k, val in self._params.items()
                 if not (k == "reference" and val is None)]
        return f"FillStyle.{self._kind}({', '.join(args)})"

    # -- painting ----------------------------------------------------------------------------
    def paint(self, fb: "FrameBuffer", color: Optional["Color"], bbox: Sequence[float],
              draw: Callable[..., object], outline: Callable[[], object]) -> None:
        """Paint an area of ``fb`` in this style (called by ``draw._area.fill_area``).

        Parameters
        ----------
        fb : FrameBuffer
            The frame buffer painted.
        color : color
            The fill color.
        bbox : (xmin, ymin, xmax, ymax)
            Device pixels (inclusive) the area can cover; only its part inside ``fb``
            is scan-converted.
        draw : callable
            ``draw(buf, packed, width, height, ox, oy, value)`` fills the area into a
            raster whose pixel (0, 0) is device pixel (ox, oy).
        outline : callable
            ``outline()`` draws the boundary (the hollow style).

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(3, 1, mode="L")
        >>> def draw(buf, packed, width, height, ox, oy, value):
        ...     buf[0, 1] = value                    # the area: pixel (1, 0)
        >>> sl.FillStyle.solid().paint(fb, 200, (1, 0, 1, 0), draw, outline=lambda: None)
        >>> fb.to_array().tolist()
        [[0, 200, 0]]
        """
        if self._kind == "hollow":
            outline()
            return
        if self._kind == "solid":
            buf, packed = fb._raster()
            draw(buf, packed, fb.width, fb.height, 0, 0, fb.pixel(color))
            return
        xmin, ymin, x0, y0, x1, y1 = _clip(fb, bbox)
        if x0 > x1 or y0 > y1:
            return
        from ._kernels.styles import paint_styled
        from ._kernels._jit import call
        from ._kernels.variants import layout

        w, h = x1 - x0 + 1, y1 - y0 + 1
        mask = np.zeros((h, w, 1), np.uint8)
        draw(mask, False, w, h, x0, y0, np.array([1], np.uint8))
        p = self._params
        ax, ay = (0, 0) if p["anchor"] == "origin" else p["reference"] or (xmin, ymin)
        hatch = self._kind == "hatch"
        if hatch:
            cells = np.zeros((1, 1), np.int32)
            families = _families(p["angle"], p["line_width"], p["cross"])
            spacing, other = float(p["spacing"]), -1 if p["background"] is None else 1
            entries = [(color, "color"), (p["background"], "background")][:1 + (other > 0)]
        else:
            cells = np.ascontiguousarray(self._cells[::-1])  # tile rows bottom-up, like y
            families, spacing, other = np.zeros((0, 3)), 1.0, -1
            entries = [(color, "color") if spec == _FILL else (spec, f"tile[{r}][{c}]")
                       for spec, (r, c) in zip(self._palette, self._where)]
        lut = np.array([fb.pixel(spec, name) for spec, name in entries])
        buf, packed = fb._raster()
        call(paint_styled, mask.shape[0] * mask.shape[1] / 2, buf, layout(packed), hatch,
             fb.width, fb.height, mask, x0, y0, ax, ay, cells, families, spacing, other, lut)


def _families(angle: float, line_width: float, cross: bool) -> NDArray[np.float64]:
    """Rows (c, s, w') of the hatch line families: direction (c, s) = (cos, sin) of
    the angle (and of angle + pi/2 for cross-hatch), minor-axis width w'."""
    c, s = _direction(angle)
    directions = [(c, s), (-s, c)] if cross else [(c, s)]
    return np.array([(c, s, line_width * max(abs(c), abs(s))) for c, s in directions])


def _fields(style: "FillStyle", kind: str, params: dict[str, Any],
            cells: Optional[NDArray[np.int32]], palette: tuple[Any, ...],
            where: tuple[Any, ...]) -> None:
    for name, value in (("_kind", kind), ("_params", MappingProxyType(params)),
                        ("_cells", cells), ("_palette", palette), ("_where", where)):
        object.__setattr__(style, name, value)


def _restore(kind: str, params: dict[str, Any], cells: Optional[NDArray[np.int32]],
             palette: tuple[Any, ...], where: tuple[Any, ...]) -> "FillStyle":
    """Unpickle a FillStyle (its fields are already validated)."""
    style = object.__new__(FillStyle)
    _fields(style, kind, params, cells, palette, where)
    return style


# -- builders: validate the arguments of each kind -------------------------------------

def _no_arguments(**arguments: Any) -> Built:
    if arguments:
        raise ArgumentTypeError(f"this fill style takes no arguments, got {sorted(arguments)}")
    return {}, None, (), ()


def _pattern_arguments(tile: Any, anchor: str = "origin", reference: Any = None) -> Built:
    anchor, reference = _anchor(anchor, reference)
    cells, palette, where = _palette(tile)
    if not (cells >= 0).any():
        raise ArgumentValueError("tile has no visible cell (all False / None); it would paint nothing")
    cells.flags.writeable = False
    return {"anchor": anchor, "reference": reference}, cells, palette, where


def _hatch_arguments(angle: Any = 0.0, spacing: Any = 8, cross: Any = False,
                     line_width: Any = 1, background: Any = None, anchor: str = "origin",
                     reference: Any = None) -> Built:
    angle = v.angle("angle", angle)
    spacing = _positive("spacing", spacing)
    line_width = _positive("line_width", line_width)
    if not isinstance(cross, (bool, np.bool_)):
        raise ArgumentTypeError(f"cross must be True or False, got {v._show(cross)}")
    if background is not None:
        spec = _color_spec("background", background)
        background = background if isinstance(background, str) else spec
    anchor, reference = _anchor(anchor, reference)
    params = {"angle": angle, "spacing": _plain(spacing), "cross": bool(cross),
              "line_width": _plain(line_width), "background": background,
              "anchor": anchor, "reference": reference}
    return params, None, (), ()


def _plain(value: float) -> float:
    """An integral float as an int (for a readable repr)."""
    return int(value) if value == int(value) else value


_BUILDERS: dict[str, Callable[..., Built]] = {"solid": _no_arguments, "hollow": _no_arguments,
             "pattern": _pattern_arguments, "hatch": _hatch_arguments}


from .linestyle import LineStyle  # noqa: E402  (the line attributes, beside FillStyle)
from .text.style import TextStyle  # noqa: E402  (the text attributes; see scanline.text)
