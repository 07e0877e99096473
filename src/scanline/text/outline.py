"""Outline fonts read from TrueType / OpenType files with fontTools.

fontTools parses the file; scanline does the graphics: each glyph's contours of
lines and quadratic (``glyf``) or cubic (``CFF``) Bezier segments are flattened by
:mod:`scanline.geometry.flatten` within a tolerance and filled by the scan-line
polygon fill with the nonzero winding rule (TrueType and CFF outlines are defined
by it).  No FreeType, no hinting.

The flattened contours are cached per glyph and per tolerance (rounded down to a
power of two of font units), so a page of text flattens each distinct glyph once.
"""

import contextlib
import logging
import math
import os
from typing import Any, Iterator, Optional

import numpy as np
from numpy.typing import NDArray
from fontTools.pens.basePen import BasePen
from fontTools.ttLib import TTFont

from .._files import input_path
from ..errors import ArgumentValueError
from ..geometry import flatten
from .catalog import Font


#: Most segments one glyph may have (composites counted with every copy): real
#: glyphs have hundreds, CJK ones a few thousand.  A hostile font that nests
#: composites to multiply its outlines is refused when its pen passes this.
MAX_GLYPH_SEGMENTS = 100_000

#: Deepest nesting of composite glyphs (TrueType fonts use 1-3 levels; FreeType and
#: the OpenType specification's maxComponentDepth are of this order).
MAX_COMPOSITE_DEPTH = 16

#: Largest font file read.
MAX_FONT_BYTES = 256 << 20

#: A pen point, segment (kind, points...) and contour (start, segments).
Pt = tuple[float, float]
Segment = tuple[Any, ...]
Contour = tuple[Pt, list[Segment]]


class _TooComplex(Exception):
    """A glyph with more than MAX_GLYPH_SEGMENTS segments."""


class _SegmentPen(BasePen):  # type: ignore[misc]  # fontTools has no type information
    """Collect a glyph's contours as segments: ('L', p), ('Q', p1, p2) and
    ('C', p1, p2, p3), each continuing from the previous point.  fontTools'
    BasePen resolves TrueType's implied on-curve points and components.  More than
    MAX_GLYPH_SEGMENTS segments raise :class:`_TooComplex` at once, so a glyph that
    multiplies its outlines costs bounded time and memory."""

    def __init__(self, glyph_set: Any) -> None:
        super().__init__(glyph_set)
        self.contours: list[Contour] = []
        self.count = 0

    def _add(self, item: Segment) -> None:
        self.count += 1
        if self.count > MAX_GLYPH_SEGMENTS:
            raise _TooComplex()
        self.contours[-1][1].append(item)

    def _moveTo(self, p: Pt) -> None:
        self.count += 1
        self.contours.append((p, []))

    def _lineTo(self, p: Pt) -> None:
        self._add(("L", p))

    def _qCurveToOne(self, p1: Pt, p2: Pt) -> None:
        self._add(("Q", p1, p2))

    def _curveToOne(self, p1: Pt, p2: Pt, p3: Pt) -> None:
        self._add(("C", p1, p2, p3))


def flatten_contours(contours: list[Contour], tolerance: float) -> list[NDArray[np.float64]]:
    """Flatten pen contours ``[(start, segments), ...]`` into (K, 2) float arrays
    (closed implicitly), all quadratic and all cubic segments in one vectorized
    call each."""
    quads: list[tuple[Pt, ...]] = []
    cubics: list[tuple[Pt, ...]] = []
    for start, segs in contours:
        cur = start
        for s in segs:
            if s[0] == "Q":
                quads.append((cur, s[1], s[2]))
            elif s[0] == "C":
                cubics.append((cur, s[1], s[2], s[3]))
            cur = s[-1]
    flat: dict[str, tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]] = {}
    for kind, items, degree in (("Q", quads, 3), ("C", cubics, 4)):
        if items:
            pts, counts = flatten._flatten("controls", np.array(items, float), degree, tolerance)
            ends = np.cumsum(counts)
            flat[kind] = (pts, ends - counts, ends)
    out: list[NDArray[np.float64]] = []
    used = {"Q": 0, "C": 0}
    for start, segs in contours:
        pieces = [np.array([start], float)]
        for s in segs:
            if s[0] == "L":
                pieces.append(np.array([s[1]], float))
            else:
                pts, first, ends = flat[s[0]]
                i = used[s[0]]
                used[s[0]] += 1
                pieces.append(pts[first[i]:ends[i]])
        ring = np.vstack(pieces)
        if len(ring) > 1 and (ring[0] == ring[-1]).all():
            ring = ring[:-1]
        if len(ring) >= 3:
            out.append(ring)
    return out


@contextlib.contextmanager
def _quiet() -> Iterator[None]:
    """Silence fontTools' log warnings about damaged data while it reads: scanline
    either raises one clear error or draws the replacement box."""
    log = logging.getLogger("fontTools")
    level = log.level
    log.setLevel(logging.CRITICAL)
    try:
        yield
    finally:
        log.setLevel(level)


def _check_tables(path: str, font: Any) -> None:
    """Every table must lie inside the file (a truncated file fails here, not when
    a glyph is first drawn) and the tables scanline needs must be present."""
    size = os.path.getsize(path)
    for tag, entry in font.reader.tables.items():
        if entry.offset + entry.length > size:
            raise ValueError(f"table {tag!r} runs past the end of the file "
                             f"({entry.offset + entry.length} > {size} bytes): truncated")
    missing = [t for t in ("head", "hhea", "hmtx", "cmap", "maxp") if t not in font]
    if "glyf" not in font and "CFF " not in font:
        missing.append("glyf or CFF")
    if missing:
        raise ValueError(f"missing table(s) {', '.join(missing)}")


class OutlineFont(Font):
    """A TrueType (``glyf``) or OpenType (``CFF``) font.

    Parameters
    ----------
    path : str
        The font file.
    name : str, optional
        The font's name in scanline (default: the file name).
    license : str, optional
        Its license.

    Raises
    ------
    ArgumentValueError
        If the file is missing or is not a readable font.
    """

    kind = "outline"

    def __init__(self, path: str, name: Optional[str] = None,
                 license: str = "see the font file") -> None:
        super().__init__(name or os.path.basename(path), path, license)
        input_path(path, "font file", MAX_FONT_BYTES)
        self._flat: dict[tuple[int, int], list[NDArray[np.float64]]] = {}
        self._depth: dict[str, int] = {}
        try:
            with _quiet():
                font = TTFont(path, fontNumber=0, lazy=False)
                _check_tables(path, font)
                self._read(font)
        except (ArgumentValueError, MemoryError):
            raise
        except Exception as exc:  # fontTools raises many types on corrupt data
            raise ArgumentValueError(
                f"font file {path!r} is not a readable TrueType/OpenType font "
                f"({type(exc).__name__}: {exc})") from None

    def _read(self, font: Any) -> None:
        self._font = font
        self._glyphs = font.getGlyphSet()
        order = font.getGlyphOrder()
        self._names = order
        head, hhea = font["head"], font["hhea"]
        self.units_per_em = float(head.unitsPerEm)
        if not 16 <= self.units_per_em <= 16384:
            raise ValueError(f"unitsPerEm {head.unitsPerEm} is outside 16..16384")
        self.ascent = float(hhea.ascent)
        self.descent = float(min(hhea.descent, 0))
        self.line_gap = float(max(hhea.lineGap, 0))
        hmtx = font["hmtx"]
        self.advances = np.array([hmtx[n][0] for n in order] + [0.0], float)
        cmap = font.getBestCmap()
        if not cmap:
            raise ValueError("no Unicode character map")
        gid = {n: i for i, n in enumerate(order)}
        self._table = np.full(0x10000, len(order), np.int64)
        for code, glyph in cmap.items():
            if code < 0x10000:
                self._table[code] = gid[glyph]
            else:
                self._extra[code] = gid[glyph]
        os2 = font["OS/2"] if "OS/2" in font else None
        self.cap_height = self._metric(os2, "sCapHeight", "H", 0.7)
        self.x_height = self._metric(os2, "sxHeight", "x", 0.5)
        t = self.cap_height * 0.08
        self._box = self._replacement_box(0.1 * self.cap_height, 0.6 * self.cap_height, t)
        self.advances[-1] = 0.8 * self.cap_height
        self._ink_reach = float(max(abs(head.xMin), abs(head.yMin), abs(head.xMax),
                                    abs(head.yMax)))

    def _metric(self, os2: Any, field: str, char: str, fraction: float) -> float:
        value = getattr(os2, field, 0) if os2 is not None else 0
        if value > 0:
            return float(value)
        code = ord(char)
        if self._table[code] < len(self._names):
            b = self.bounds(int(self._table[code]))
            if b is not None and b[3] > 0:
                return float(b[3])
        return fraction * self.units_per_em

    def _composite_depth(self, name: str, active: tuple[str, ...] = ()) -> int:
        """How deeply the ``glyf`` glyph ``name`` nests composites (0: a simple
        glyph), or raise once it passes MAX_COMPOSITE_DEPTH or contains itself."""
        if name in self._depth:
            return self._depth[name]
        if name in active:
            raise ValueError(f"composite glyph {name!r} contains itself")   # corrupt data
        if len(active) > MAX_COMPOSITE_DEPTH:
            raise _TooComplex()
        glyph = self._font["glyf"][name]
        depth = 0
        if glyph.isComposite():
            depth = 1 + max(self._composite_depth(c.glyphName, active + (name,))
                            for c in glyph.components)
        self._depth[name] = depth
        return depth

    def _contours(self, gid: int) -> Optional[list[Contour]]:
        """The pen contours of glyph ``gid``; a glyph fontTools cannot decode is
        drawn as the replacement box rather than raising mid-string.  A glyph that
        nests composites more than MAX_COMPOSITE_DEPTH deep or has more than
        MAX_GLYPH_SEGMENTS segments is refused: an ArgumentValueError naming the
        font and the glyph."""
        pen = _SegmentPen(self._glyphs)
        name = self._names[gid]
        try:
            with _quiet():
                if "glyf" in self._font:
                    self._composite_depth(name)
                self._glyphs[name].draw(pen)
        except _TooComplex:
            raise ArgumentValueError(
                f"font file {self.source!r}: glyph {name!r} is too complex to draw (composites "
                f"nested more than {MAX_COMPOSITE_DEPTH} deep, or more than "
                f"{MAX_GLYPH_SEGMENTS:,} outline segments); use another font") from None
        except Exception:  # fontTools raises many types on corrupt glyph data (and a
            return None    # RecursionError on a composite glyph that contains itself)
        return pen.contours

    def _ink(self, gid: int, tolerance: float) -> list[NDArray[np.float64]]:
        """Flattened contours of glyph ``gid`` in font units, within ``tolerance``
        font units (cached per power-of-two tolerance)."""
        if gid == self.replacement:
            return self._box
        level = math.floor(math.log2(max(tolerance, 1e-6)))
        key = (gid, level)
        if key not in self._flat:
            contours = self._contours(gid)
            self._flat[key] = (self._box if contours is None
                               else flatten_contours(contours, 2.0 ** level))
        return self._flat[key]
