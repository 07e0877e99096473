"""Placing characters: text path, spacing, expansion, orientation and alignment
(notes, syllabus: "Text attributes"; Hearn & Baker, section 4-5).

The layout works in *text space*: u along the baseline, v along the up vector, in
device units, with the reference point at the origin.  A glyph point ``g`` (font
units) of the character whose origin is ``(u, v)`` lands at the device point

    p = (x, y) + R(angle) @ ((u, v) + diag(sx, sy) @ g),

with ``sy = height / cap_height`` (font units to pixels), ``sx = expansion * sy``
and R the rotation by the baseline angle.  Each character origin is then rounded to
the nearest pixel center, as raster text engines do, so a character looks the same
wherever it is drawn (and its rasterized image can be cached).

Text path (GKS): ``"right"`` places characters left to right along the baseline,
``"left"`` right to left, ``"up"`` and ``"down"`` stack them along the up vector,
each centered on the path.  A newline starts a new line below (paths right and left)
or a new column to the right (paths up and down).

Alignment (GKS): the *text extent rectangle* of each line runs along the path over
the characters' advances, across it from the bottom line to the top line.
Horizontal ``left/center/right`` and vertical ``top/cap/half/base/bottom`` pick the
point of that rectangle placed on the reference point: for paths right and left the
horizontal choice applies to each line, the vertical one to the block of lines
(``top``, ``cap`` and ``base`` of the first line, ``bottom`` of the last, ``half``
halfway between the first cap line and the last baseline, which centers the
block); for paths up and down the vertical choice applies to each column, the
horizontal one to the block.
"""

import math
from typing import Any, Iterable, Optional

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .._typing import Angle
from ..errors import ArgumentTypeError, ArgumentValueError
from .catalog import font as resolve_font
from .catalog import NEWLINE
from .catalog import Font
from .style import Align, FontSpec, TextStyle, resolve

#: A bounding box (xmin, ymin, xmax, ymax).
Box = tuple[float, float, float, float]
#: Text-space origins of a placement: per glyph, or one number for all (one line).
Coordinate = Any

#: Flattening tolerance of outline glyphs, device pixels.
TOLERANCE = 0.2


class Placement:
    """The placed characters of a string, as arrays (internal: the drawing path uses
    it directly; :func:`layout` wraps it in :class:`PlacedGlyph` objects).

    Attributes: ``font``, ``style``, ``sx``, ``sy`` (font units -> pixels),
    ``rotation`` (2 x 2), ``matrix`` (``rotation @ diag(sx, sy)``), ``gids``,
    ``index`` (position of each glyph's character in the string), ``ox``, ``oy``
    (int64 pixel origins), ``reference`` (x, y), ``extent`` (u0, v0, u1, v1: the
    block's text extent in text space) and ``end`` (the concatenation point, text
    space).
    """

    __slots__ = ("font", "style", "sx", "sy", "matrix", "gids", "index", "ox", "oy",
                 "reference", "extent", "end", "tolerance")
    font: Font
    style: TextStyle
    sx: float
    sy: float
    matrix: NDArray[np.float64]
    gids: NDArray[np.int64]
    index: NDArray[np.int64]
    ox: NDArray[np.int64]
    oy: NDArray[np.int64]
    reference: tuple[float, float]
    extent: Box
    end: tuple[float, float]
    tolerance: float

    @property
    def rotation(self) -> NDArray[np.float64]:
        c, s = math.cos(self.style.angle), math.sin(self.style.angle)
        return np.array([[c, -s], [s, c]])

    def corners(self) -> NDArray[np.float64]:
        """The block's text extent rectangle, (4, 2) device corners."""
        u0, v0, u1, v1 = self.extent
        local = np.array([(u0, v0), (u1, v0), (u1, v1), (u0, v1)])
        corners: NDArray[np.float64] = local @ self.rotation.T + self.reference
        return corners

    def concatenation_point(self) -> tuple[float, float]:
        """Where the next text along the path would start, device coordinates."""
        x, y = (self.rotation @ np.array(self.end) + self.reference).tolist()
        return (x, y)


#: Longest string drawn, placed or measured: 2**20 characters (a few hundred pages;
#: the placement arrays take about 100 bytes per character).
MAX_CHARACTERS = 1 << 20

#: Longest string :func:`layout` places: it makes one Python object per character.
MAX_LAYOUT = 100_000


def check_length(text: object, limit: int = MAX_CHARACTERS, what: str = "drawn or measured") -> str:
    """Refuse a string longer than ``limit`` characters before anything is allocated."""
    if not isinstance(text, str):
        raise ArgumentTypeError(f"text must be a str, got {v._show(text)}")
    if len(text) > limit:
        raise ArgumentValueError(
            f"text has {len(text):,} characters; a string {what} has at most {limit:,}"
            + ("; draw it with sl.draw.text or measure it with sl.text.extents"
               if limit == MAX_LAYOUT else "; split it"))
    return text


def codes_of(text: str) -> NDArray[np.uint32]:
    """Code points of a string as a uint32 array (writable, as kernels take arrays:
    a read-only one would compile a second specialization)."""
    check_length(text)
    return np.frombuffer(bytearray(text.encode("utf-32-le", "surrogatepass")), np.uint32)


def _segments(line: NDArray[np.int64]) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Start and end (exclusive) of each run of equal ``line`` ids."""
    if len(line) == 0:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    cut = np.flatnonzero(np.diff(line)) + 1
    return np.concatenate([[0], cut]), np.concatenate([cut, [len(line)]])


def _per_line_sum(values: NDArray[np.float64], starts: NDArray[np.int64], ends: NDArray[np.int64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Inclusive running sum restarting at each line, and each line's total."""
    run = np.cumsum(values)
    before = np.where(starts > 0, run[starts - 1], 0.0) if len(run) else np.zeros(0)
    total = run[ends - 1] - before if len(run) else np.zeros(0)
    return run - np.repeat(before, ends - starts), total


def _align_span(lo: Coordinate, hi: Coordinate, key: str) -> Coordinate:
    """Offset that puts the ``key`` end (left/center/right) of [lo, hi] at 0."""
    return -lo if key == "left" else -hi if key == "right" else -(lo + hi) / 2


def _levels(font: Font, style: TextStyle, sy: float, nlines: int
            ) -> tuple[float, float, float, float, float]:
    """Vertical alignment for paths right and left, text space: the first
    baseline's v (``dv``), the last baseline's v, the bottom and top lines of the
    block and the baseline-to-baseline step."""
    step = font.line_height * sy
    base_last = -(nlines - 1) * step
    cap = font.cap_height * sy
    levels = {"top": font.ascent * sy, "cap": cap, "half": (cap + base_last) / 2,
              "base": 0.0, "bottom": base_last + font.descent * sy}
    dv = -levels[style.align[1]]
    return dv, base_last + dv, base_last + font.descent * sy + dv, font.ascent * sy + dv, step


def _horizontal(font: Font, gids: NDArray[np.int64], line: NDArray[np.int64], nlines: int, style: TextStyle, sx: float,
                sy: float, gap: float) -> tuple[NDArray[np.float64], Coordinate, Box, tuple[float, float]]:
    """Text-space origins for paths right and left; the block's extent.  (One line
    of upright text is drawn by the compiled ``stamp_line``, which repeats this
    arithmetic operation for operation, see :func:`line_setup`.)"""
    adv = font.advances[gids] * sx
    if gap:
        adv += gap
    width: Coordinate   # one line: a number; several: one per line
    if nlines == 1:  # the common case: scalars instead of per-line arrays
        run = np.add.accumulate(adv)  # (np.cumsum: the same, with 1-2 us more overhead)
        width = float(run[-1]) - gap if len(run) else 0.0
    else:
        starts, ends = _segments(line)
        run, total = _per_line_sum(adv, starts, ends)
        width = np.zeros(nlines)
        width[line[starts]] = total - gap
    right = style.path == "right"
    lo: Coordinate
    hi: Coordinate
    lo, hi = (0.0 * width, width) if right else (-width, 0.0 * width)
    shift = _align_span(lo, hi, style.align[0])
    u = run - adv if right else gap - run
    u += shift if nlines == 1 else shift[line]
    dv, base_last, bottom, top, step = _levels(font, style, sy, nlines)
    v_ = dv - step * line if nlines > 1 else dv  # one line: a scalar
    lo, hi = lo + shift, hi + shift
    if nlines > 1:
        lo, hi, last_lo, last_hi = float(lo.min()), float(hi.max()), lo[-1], hi[-1]
    else:
        last_lo, last_hi = lo, hi
    extent = (lo, bottom, hi, top)
    end_u = float(last_hi) + gap if right else float(last_lo) - gap
    return u, v_, extent, (end_u, base_last)


def _vertical(font: Font, gids: NDArray[np.int64], line: NDArray[np.int64], nlines: int, style: TextStyle, sx: float,
              sy: float, gap: float) -> tuple[NDArray[np.float64], Coordinate, Box, tuple[float, float]]:
    """Text-space origins for paths up and down; the block's extent."""
    adv = font.advances[gids] * sx
    step = font.line_height * sy + gap
    starts, ends = _segments(line)
    k = np.arange(len(gids)) - np.repeat(starts, ends - starts)
    count = np.zeros(nlines)
    count[line[starts]] = ends - starts
    sign = 1.0 if style.path == "up" else -1.0
    v_ = sign * k * step
    top_char = np.where(sign > 0, (count - 1) * step, 0.0)
    bottom_char = np.where(sign > 0, 0.0, -(count - 1) * step)
    cap = font.cap_height * sy
    levels = {"top": top_char + font.ascent * sy, "cap": top_char + cap,
              "half": (top_char + cap + bottom_char) / 2, "base": bottom_char,
              "bottom": bottom_char + font.descent * sy}
    shift_v = -levels[style.align[1]]
    v_ = v_ + shift_v[line]
    column = font.line_height * sx
    half = float(adv.max()) / 2 if len(adv) else 0.0
    lo, hi = -half, (nlines - 1) * column + half
    du = _align_span(lo, hi, style.align[0])
    u = line * column - adv / 2 + du
    vmin = float((bottom_char + shift_v).min()) + font.descent * sy
    vmax = float((top_char + shift_v).max()) + font.ascent * sy
    last = nlines - 1
    end_v = (top_char + shift_v)[last] + step if sign > 0 else (bottom_char + shift_v)[last] - step
    return u, v_, (lo + du, vmin, hi + du, vmax), (last * column + du, end_v)


def place(text: str, x: float, y: float, style: TextStyle) -> Placement:
    """Place ``text`` at reference point ``(x, y)`` with a resolved ``style``."""
    x = v.number("x", x)          # any finite reference point (origins far away are
    y = v.number("y", y)          # kept at the range's edge below: nothing is drawn)
    fx: Coordinate
    fy: Coordinate
    font = resolve_font(style.font)
    codes = codes_of(text)
    if "\n" in text:
        newline = codes == NEWLINE
        keep = ~newline
        index = np.flatnonzero(keep)
        line = (np.cumsum(newline) - newline)[keep]
        nlines = int(newline.sum()) + 1
        codes = codes[keep]
    else:
        index = np.arange(len(codes))
        line = np.zeros(len(codes), np.int64)
        nlines = 1
    gids = font.glyph_ids(codes, small=text.isascii())
    sx, sy, gap = _scale(font, style)
    if style.path in ("right", "left"):
        u, v_, extent, end = _horizontal(font, gids, line, nlines, style, sx, sy, gap)
    else:
        u, v_, extent, end = _vertical(font, gids, line, nlines, style, sx, sy, gap)
    c, s = math.cos(style.angle), math.sin(style.angle)
    p = Placement()
    p.font, p.style, p.sx, p.sy = font, style, sx, sy
    p.matrix = _matrix(c, s, sx, sy)
    p.gids, p.index = gids, index
    # origins, rounded to pixel centers (floor(f + 0.5), computed in place)
    if s == 0.0 and c == 1.0:
        fx, fy = u, v_ + y + 0.5
        fx += x + 0.5
    else:
        fx, fy = x + 0.5 + c * u - s * v_, y + 0.5 + s * u + c * v_
    reach = max(abs(x), abs(y)) + max(abs(e) for e in extent)
    if reach > v.COORD_LIMIT:  # far away: keep the origins in the exact range
        lim = float(v.COORD_LIMIT)
        fx, fy = np.clip(fx, -lim, lim), np.clip(fy, -lim, lim)
    p.ox = np.floor(fx, out=fx).astype(np.int64)
    if np.ndim(fy) == 0:  # one unrotated line: one baseline row
        p.oy = np.full(len(gids), math.floor(fy), np.int64)
    else:
        p.oy = np.floor(fy).astype(np.int64)
    p.reference, p.extent, p.end = (x, y), extent, end
    p.tolerance = TOLERANCE / max(sx, sy)
    return p


def _scale(font: Font, style: TextStyle) -> tuple[float, float, float]:
    """``(sx, sy, gap)``: font units -> pixels along and across the baseline, and
    the extra space between characters (pixels)."""
    height = font.native_height if style.height is None else style.height
    sy = height / font.cap_height
    return sy * style.expansion, sy, style.spacing * height


def _matrix(c: float, s: float, sx: float, sy: float) -> NDArray[np.float64]:
    """Font units -> device units: the rotation (cosine ``c``, sine ``s``) @
    diag(sx, sy)."""
    return np.array([[c * sx, -s * sy], [s * sx, c * sy]])


class LineSetup:
    """What drawing one line of upright text with a style needs besides the string
    and the reference point (internal, made by :func:`line_setup`): ``font``,
    ``matrix``, ``tolerance`` and ``params``, the float64 array that the compiled
    ``stamp_line`` reads: ``sx``, ``gap``, horizontal alignment (0 left, 1 center,
    2 right), 1 for path right (0 left), ``dv`` (the baseline's v), how far the
    bottom and top lines lie from the baseline's reference (``max(|bottom|,
    |top|)``, for the coordinate-range check) and the coordinate limit."""

    __slots__ = ("font", "matrix", "tolerance", "params")
    font: Font
    matrix: NDArray[np.float64]
    tolerance: float
    params: NDArray[np.float64]


def line_setup(style: TextStyle) -> Optional[LineSetup]:
    """The :class:`LineSetup` of a resolved ``style``, or None when its text is not
    upright along path right or left (those strings are placed by :func:`place`)."""
    c, s = math.cos(style.angle), math.sin(style.angle)
    if not (s == 0.0 and c == 1.0) or style.path not in ("right", "left"):
        return None
    font = resolve_font(style.font)
    sx, sy, gap = _scale(font, style)
    dv, _, bottom, top, _ = _levels(font, style, sy, 1)
    setup = LineSetup()
    setup.font, setup.matrix = font, _matrix(c, s, sx, sy)
    setup.tolerance = TOLERANCE / max(sx, sy)
    setup.params = np.array([sx, gap, ("left", "center", "right").index(style.align[0]),
                             style.path == "right", dv, max(abs(bottom), abs(top)),
                             v.COORD_LIMIT], float)
    return setup


def _box(points: NDArray[np.float64]) -> Box:
    x0, y0, x1, y1 = np.concatenate([points.min(0), points.max(0)]).tolist()
    return (x0, y0, x1, y1)


class PlacedGlyph:
    """One character placed by :func:`layout`.

    Attributes
    ----------
    char : str
        The character (the replacement box is drawn for characters the font lacks:
        ``glyph == font.replacement``).
    index : int
        Its position in the string.
    glyph : int
        Glyph id in ``font``.
    font : Font
    origin : (int, int)
        Device pixel of the character's origin (left end of its baseline in its
        cell), rounded to a pixel center.
    matrix : ndarray, shape (2, 2)
        Font units -> device units (rotation @ diag(sx, sy)).
    box : (float, float, float, float) or None
        ``(xmin, ymin, xmax, ymax)``, device coordinates: the bounding box of the
        glyph's geometry below (None for a blank glyph such as the space).  Pixel
        centers inside it are the only ones the glyph can set (within half a pixel
        more for the stroke font, whose lines round their ends to pixels).
    cell : (float, float, float, float)
        Device bounding box of the character body: advance x (bottom line .. top
        line), rotated.  Use it for all-or-none character clipping.
    contours : list of (K, 2) float arrays, or None
        Outline and bitmap fonts: closed contours in device coordinates, to be
        filled with the nonzero rule (a bitmap glyph's dots are squares).
    strokes : list of (K, 2) float arrays, or None
        Stroke font: the polylines, device coordinates.
    bitmap : bool ndarray (lazy)
        The pixels :func:`scanline.draw.text` sets for this glyph (without
        antialiasing; for the stroke font, the pixels of its lines), image order
        (top row first); ``bitmap_origin`` is the device (x, y) of its bottom-left
        pixel.

    Examples
    --------
    The bitmap font's "I" at (0, 0): its cell is the advance, 6 dots, wide and runs
    from the bottom line (2 dots below the baseline) to the top line (7 above):

    >>> import scanline as sl
    >>> g = sl.text.layout("I", font="bitmap")[0]
    >>> g.char, g.origin, g.cell
    ('I', (0, 0), (0.0, -2.0, 6.0, 7.0))
    """

    __slots__ = ("char", "index", "glyph", "font", "origin", "matrix", "box", "cell",
                 "contours", "strokes", "_tolerance", "_bitmap")
    char: str
    index: int
    glyph: int
    font: Font
    origin: tuple[int, int]
    matrix: NDArray[np.float64]
    box: Optional[Box]
    cell: Box
    contours: Optional[list[NDArray[np.float64]]]
    strokes: Optional[list[NDArray[np.float64]]]
    _tolerance: float
    _bitmap: Optional[tuple[NDArray[np.bool_], tuple[int, int]]]

    def __repr__(self) -> str:
        return f"PlacedGlyph({self.char!r}, origin={self.origin}, box={self.box})"

    def _raster(self) -> tuple[NDArray[np.bool_], tuple[int, int]]:
        if self._bitmap is None:
            from .glyphcache import GlyphImages, images, stroke_bitmap
            if self.strokes is not None:
                self._bitmap = stroke_bitmap(self.strokes)
            else:
                cache = images(self.font, self.matrix, False, self._tolerance) or GlyphImages(
                    self.font, self.matrix, False, self._tolerance)
                x0, y0, mask = cache.bitmap(self.glyph)
                self._bitmap = (mask, (self.origin[0] + x0, self.origin[1] + y0))
        return self._bitmap

    @property
    def bitmap(self) -> NDArray[np.bool_]:
        """The pixels this glyph sets, image order (top row first), computed once."""
        return self._raster()[0]

    @property
    def bitmap_origin(self) -> tuple[int, int]:
        """The device (x, y) of the bitmap's bottom-left pixel."""
        return self._raster()[1]


def cells(p: Placement) -> NDArray[np.float64]:
    """The device bounding boxes of the character bodies of a placement, (n, 4):
    xmin, ymin, xmax, ymax of the cell (advance x bottom line .. top line), turned
    by the placement's matrix and moved to each origin."""
    font = p.font
    a = font.advances[p.gids]
    m = p.matrix
    xs: list[NDArray[np.float64]] = []
    ys: list[NDArray[np.float64]] = []
    for u, w in ((0.0, font.descent), (1.0, font.descent), (1.0, font.ascent),
                 (0.0, font.ascent)):
        xs.append(m[0, 0] * a * u + m[0, 1] * w + p.ox)
        ys.append(m[1, 0] * a * u + m[1, 1] * w + p.oy)
    x, y = np.stack(xs, axis=1), np.stack(ys, axis=1)
    boxes: NDArray[np.float64] = np.stack([x.min(1), y.min(1), x.max(1), y.max(1)], axis=1)
    return boxes


def glyphs(text: str, p: Placement, select: Optional[Iterable[int]] = None) -> list[PlacedGlyph]:
    """PlacedGlyph objects for the characters ``select`` (indices into the placement
    ``p``; default all) of ``text``."""
    out: list[PlacedGlyph] = []
    outline = p.font.kind != "stroke"
    boxes = cells(p)
    for j in (range(len(p.gids)) if select is None else select):
        k = int(j)
        g = PlacedGlyph()
        gid = int(p.gids[k])
        g.char = text[p.index[k]]
        g.index = int(p.index[k])
        g.glyph, g.font, g.matrix = gid, p.font, p.matrix
        g.origin = (int(p.ox[k]), int(p.oy[k]))
        ink = [c @ p.matrix.T + g.origin for c in p.font._ink(gid, p.tolerance)]
        g.contours = ink if outline else None
        g.strokes = None if outline else ink
        g.box = _box(np.vstack(ink)) if ink else None
        x0, y0, x1, y1 = boxes[k].tolist()
        g.cell = (x0, y0, x1, y1)
        g._tolerance = p.tolerance
        g._bitmap = None
        out.append(g)
    return out


def layout(text: str, x: float = 0.0, y: float = 0.0, *, font: Optional[FontSpec] = None,
           height: Optional[float] = None, expansion: Optional[float] = None,
           spacing: Optional[float] = None, angle: Optional[Angle] = None,
           up: Optional[tuple[float, float]] = None, path: Optional[str] = None,
           align: Optional[Align] = None, style: Optional[TextStyle] = None) -> list[PlacedGlyph]:
    """Place the characters of ``text`` as :func:`scanline.draw.text` would draw
    them, without drawing.

    Parameters
    ----------
    text : str
        Newlines start new lines (paths right/left) or columns (paths up/down); at
        most :data:`MAX_LAYOUT` characters (one object each).
    x, y : float
        Reference point, device coordinates.
    font, height, expansion, spacing, angle, up, path, align
        Text attributes, see :class:`scanline.TextStyle`; they override ``style``.
    style : TextStyle, optional
        The base style (default: the default style).

    Returns
    -------
    list of PlacedGlyph
        One per character (newlines left out), in string order, each with its
        ``char``, device ``box`` and geometry (``contours``, ``strokes`` or the
        lazily rasterized ``bitmap`` + ``bitmap_origin``): what text clipping needs.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        ``text`` not a str or longer than :data:`MAX_LAYOUT`, a reference point that
        is not finite, or an attribute :class:`scanline.TextStyle` refuses.

    Notes
    -----
    Hearn & Baker, section 4-5 (text attributes: height, expansion, spacing, up
    vector, path, alignment); the origins are rounded to pixel centers.

    Examples
    --------
    >>> import scanline as sl
    >>> glyphs = sl.text.layout("Hi", 10, 20, font="bitmap")
    >>> [(g.char, g.origin, g.box) for g in glyphs]
    [('H', (10, 20), (10.0, 20.0, 15.0, 27.0)), ('i', (16, 20), (17.0, 20.0, 20.0, 27.0))]
    """
    check_length(text, MAX_LAYOUT, "laid out")
    p = place(text, x, y, resolve(style, font=font, height=height, expansion=expansion,
                                  spacing=spacing, angle=angle, up=up, path=path,
                                  align=align))
    return glyphs(text, p)


class Extents:
    """The result of :func:`extents`.

    Attributes
    ----------
    box : (xmin, ymin, xmax, ymax)
        Device bounding box of the text extent rectangle (see ``corners``).
    corners : ndarray, shape (4, 2)
        The text extent rectangle (all lines or columns: along the path over the
        characters' advances, across it from bottom line to top line), rotated,
        counterclockwise from its lower-left corner in text space.
    width, height : float
        The rectangle's sides along the baseline and the up vector.
    ink : (xmin, ymin, xmax, ymax) or None
        Bounding box of the glyphs' geometry (None when every character is blank).
    advance : (float, float)
        The concatenation point: where text drawn next along the path would start.

    Examples
    --------
    >>> import scanline as sl
    >>> e = sl.text.extents("A", font="bitmap")
    >>> isinstance(e, sl.text.Extents), e.advance
    (True, (6.0, 0.0))
    """

    __slots__ = ("box", "corners", "width", "height", "ink", "advance")
    box: Box
    corners: NDArray[np.float64]
    width: float
    height: float
    ink: Optional[Box]
    advance: tuple[float, float]

    def __repr__(self) -> str:
        return (f"Extents(box={self.box}, width={self.width:g}, height={self.height:g}, "
                f"advance={self.advance})")


def extents(text: str, x: float = 0.0, y: float = 0.0, *, font: Optional[FontSpec] = None,
            height: Optional[float] = None, expansion: Optional[float] = None,
            spacing: Optional[float] = None, angle: Optional[Angle] = None,
            up: Optional[tuple[float, float]] = None, path: Optional[str] = None,
            align: Optional[Align] = None, style: Optional[TextStyle] = None) -> Extents:
    """The text-extent query: where :func:`scanline.draw.text` would put ``text``.

    Parameters
    ----------
    text : str
        The string; newlines start new lines or columns.
    x, y : float
        Reference point, device coordinates.
    font, height, expansion, spacing, angle, up, path, align
        Text attributes, see :class:`scanline.TextStyle`; they override ``style``.
    style : TextStyle, optional
        The base style.

    Returns
    -------
    Extents
        The text extent rectangle, its bounding box, the ink box and the
        concatenation point.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        As :func:`layout` (up to ``MAX_CHARACTERS`` characters).

    Examples
    --------
    The bitmap font advances 6 dots a character (5 dots and a gap); "Hi" at height
    14 (scale 2), from the bottom line (2 dots below the baseline) to the top line:

    >>> import scanline as sl
    >>> e = sl.text.extents("Hi", font="bitmap", height=14)
    >>> e.width, e.height, e.box, e.advance
    (24.0, 18.0, (0.0, -4.0, 24.0, 14.0), (24.0, 0.0))
    """
    p = place(text, x, y, resolve(style, font=font, height=height, expansion=expansion,
                                  spacing=spacing, angle=angle, up=up, path=path,
                                  align=align))
    e = Extents()
    e.corners = p.corners()
    e.box = _box(e.corners)
    e.width = p.extent[2] - p.extent[0]
    e.height = p.extent[3] - p.extent[1]
    e.advance = p.concatenation_point()
    boxes: list[Box] = []
    for gid in np.unique(p.gids):
        b = p.font.bounds(int(gid))
        if b is None:
            continue
        sel = p.gids == gid
        corners = np.array([(b[0], b[1]), (b[2], b[1]), (b[2], b[3]), (b[0], b[3])]) @ p.matrix.T
        origins = np.column_stack([p.ox[sel], p.oy[sel]]).astype(float)
        boxes.append(_box((corners[None] + origins[:, None]).reshape(-1, 2)))
    ink = np.array(boxes)
    e.ink = (float(ink[:, 0].min()), float(ink[:, 1].min()), float(ink[:, 2].max()),
             float(ink[:, 3].max())) if boxes else None
    return e
