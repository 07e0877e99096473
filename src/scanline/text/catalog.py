"""Fonts: the common interface of the three kinds, and the catalog of built-in fonts.

Character generation (notes, syllabus: "Character generation"; Hearn & Baker,
section 3-14) knows two ways to store the shapes of characters: as a *bitmap*
(dot-matrix) grid per character, and as an *outline* (strokes or curved contours)
that is scan-converted at any size.  scanline ships one font of each kind and reads
more outline fonts from TrueType/OpenType files, given by path or by family name
(``"DejaVu Serif"``: :mod:`scanline.text.system` asks fontconfig or matplotlib):

==========  ========  ===================================================
name        kind      source
==========  ========  ===================================================
"bitmap"    bitmap    a 5 x 7 dot-matrix font designed for scanline
"stroke"    stroke    a vector (Hershey-style) font of polylines, ditto
"sans"      outline   DejaVu Sans (TrueType; Bitstream Vera license)
==========  ========  ===================================================

Every font speaks *font units* (y up, the origin on the baseline at the left of the
character cell) and offers the same metrics: ``units_per_em``, ``ascent`` (top
line), ``descent`` (bottom line, negative), ``cap_height``, ``x_height``,
``line_height`` and per glyph an ``advance``.  Glyph ``replacement`` (the last id)
is the visible box drawn for characters the font lacks.
"""

import os
from importlib import resources

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError

#: Where the built-in fonts live (package data).
DATA = resources.files("scanline") / "data" / "fonts"

#: Characters handled by the layout rather than drawn.
NEWLINE = 10


class Font:
    """Base class: metrics and character-to-glyph mapping shared by all kinds.

    Subclasses set the metrics, ``advances`` (float64, one per glyph id, the
    replacement box last) and ``_table`` (int64 glyph id per code point below
    0x10000; astral code points go through ``_extra``), and implement
    ``_ink`` (contours or strokes of a glyph in font units).
    """

    kind = ""
    #: Cap height in device pixels when the caller gives no ``height``.
    native_height = 10.0

    def __init__(self, name, source, license):
        self.name = name
        self.source = source
        self.license = license
        self._extra = {}
        self._bounds = {}
        self._ink_reach = 0.0

    def __repr__(self):
        return f"<{type(self).__name__} {self.name!r}: {self.glyph_count} glyphs>"

    @property
    def glyph_count(self):
        """Number of glyphs, the replacement box not counted."""
        return len(self.advances) - 1

    @property
    def replacement(self):
        """Glyph id of the replacement box."""
        return len(self.advances) - 1

    @property
    def reach(self):
        """How far (font units) any glyph's ink or advance can lie from its origin, in
        x or y: glyphs whose origin is farther than that (scaled) from the frame
        buffer cannot touch it."""
        return max(abs(self.ascent), abs(self.descent), float(self.advances.max()),
                   self.units_per_em, self._ink_reach)

    @property
    def line_height(self):
        """Baseline-to-baseline distance of consecutive lines, font units."""
        return self.ascent - self.descent + self.line_gap

    def glyph_ids(self, codes, small=False):
        """Glyph ids of an integer array of code points (missing -> ``replacement``);
        ``small=True`` promises every code is below 0x10000 (ASCII text)."""
        if small or len(codes) == 0 or codes.max() < len(self._table):
            return self._table[codes]
        ids = self._table[np.minimum(codes, len(self._table) - 1)]
        big = codes >= len(self._table)
        if big.any():
            ids[big] = [self._extra.get(int(c), self.replacement) for c in codes[big]]
        return ids

    def has_glyph(self, char):
        """Whether ``char`` (a one-character string) has its own glyph."""
        return int(self.glyph_ids(np.array([ord(char)]))[0]) != self.replacement

    def bounds(self, gid):
        """Ink bounds ``(xmin, ymin, xmax, ymax)`` of glyph ``gid`` in font units, or
        None for a blank glyph (a space)."""
        if gid not in self._bounds:
            pts = [p for p in self._ink(gid, self.units_per_em / 1024) if len(p)]
            self._bounds[gid] = None if not pts else tuple(
                np.concatenate([np.vstack(pts).min(0), np.vstack(pts).max(0)]).tolist())
        return self._bounds[gid]

    def _replacement_box(self, x0, width, thickness):
        """The replacement glyph as two contours (nonzero rule): the outer rectangle
        counterclockwise, the inner one clockwise."""
        h = self.cap_height
        t = thickness
        outer = np.array([(x0, 0), (x0 + width, 0), (x0 + width, h), (x0, h)], float)
        inner = np.array([(x0 + t, t), (x0 + t, h - t), (x0 + width - t, h - t),
                          (x0 + width - t, t)], float)
        return [outer, inner]


def _builtin():
    from .bitmap import BitmapFont
    from .outline import OutlineFont
    from .stroke import StrokeFont
    return {
        "sans": lambda: OutlineFont(str(DATA / "DejaVuSans.ttf"), name="sans",
                                    license="Bitstream Vera license (DejaVu changes: "
                                            "public domain); see DejaVuSans-LICENSE.txt"),
        "bitmap": lambda: BitmapFont.read(DATA / "dotmatrix-5x7.txt"),
        "stroke": lambda: StrokeFont.read(DATA / "stroke.txt"),
    }


_LOADED = {}


def fonts():
    """The built-in fonts as ``{name: Font}``.

    Examples
    --------
    >>> import scanline as sl
    >>> sorted(sl.text.fonts())
    ['bitmap', 'sans', 'stroke']
    >>> sl.text.fonts()["bitmap"].kind
    'bitmap'
    """
    return {name: font(name) for name in _builtin()}


def load_font(path):
    """Read a TrueType or OpenType font file (outlines ``glyf`` or ``CFF``).

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    OutlineFont

    Raises
    ------
    ArgumentValueError
        If the file does not exist or is not a readable font (truncated, garbage,
        no outlines, no Unicode character map).
    """
    if not isinstance(path, (str, os.PathLike)):
        raise ArgumentTypeError(f"path must be a file name, got {v._show(path)}")
    key = os.path.abspath(os.fspath(path))
    if key not in _LOADED:
        from .outline import OutlineFont
        _LOADED[key] = OutlineFont(key)
    return _LOADED[key]


def font(spec, name="font"):
    """Resolve a font argument: a built-in name, a path to a .ttf/.otf file, a font
    family's name (``"DejaVu Sans"`` is the built-in ``"sans"``; others are looked
    up among the installed fonts, :mod:`scanline.text.system`), or a :class:`Font`."""
    if isinstance(spec, Font):
        return spec
    if isinstance(spec, str) and spec in _LOADED:
        return _LOADED[spec]
    builtin = _builtin()
    if isinstance(spec, str) and spec in builtin:
        _LOADED[spec] = builtin[spec]()
        return _LOADED[spec]
    if isinstance(spec, (str, os.PathLike)) and (
            os.fspath(spec).lower().endswith((".ttf", ".otf", ".ttc", ".otc"))
            or os.path.exists(spec)):
        return load_font(spec)
    if isinstance(spec, str):
        from . import system

        found = system._find(spec)
        if found is None:
            raise ArgumentValueError(system.not_found(name, spec, tuple(builtin)))
        _LOADED[spec] = font(found) if found in builtin else load_font(found)
        return _LOADED[spec]
    if isinstance(spec, os.PathLike):
        raise ArgumentValueError(
            f"{name}={v._show(spec)} is neither a built-in font ({', '.join(map(repr, builtin))}) "
            "nor an existing .ttf/.otf file")
    raise ArgumentTypeError(
        f"{name} must be a font name, a path to a .ttf/.otf file or a scanline.text.Font; "
        f"got {v._show(spec)}")
