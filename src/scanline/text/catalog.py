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
from typing import Any, Callable, Optional, Union

import numpy as np
from numpy.typing import NDArray

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

    Parameters
    ----------
    name : str
        The font's name.
    source : str
        Where it comes from (a file, or "built-in").
    license : str
        Its license.

    Examples
    --------
    Every font offers the same metrics (font units, y up):

    >>> import scanline as sl
    >>> f = sl.text.font("bitmap")
    >>> isinstance(f, sl.text.Font), f.kind, f.has_glyph("A")
    (True, 'bitmap', True)
    """

    kind = ""
    #: Cap height in device pixels when the caller gives no ``height``.
    native_height = 10.0
    # metrics, set by subclasses (font units)
    units_per_em: float
    ascent: float
    descent: float
    line_gap: float
    cap_height: float
    x_height: float
    advances: NDArray[np.float64]
    _table: NDArray[np.int64]

    def __init__(self, name: str, source: str, license: str) -> None:
        self.name = name
        self.source = source
        self.license = license
        self._extra: dict[int, int] = {}
        self._bounds: dict[int, Optional[tuple[float, float, float, float]]] = {}
        self._ink_reach = 0.0

    def _ink(self, gid: int, tolerance: float) -> list[NDArray[np.float64]]:  # pragma: no cover - abstract
        raise NotImplementedError

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.name!r}: {self.glyph_count} glyphs>"

    @property
    def glyph_count(self) -> int:
        """Number of glyphs, the replacement box not counted."""
        return len(self.advances) - 1

    @property
    def replacement(self) -> int:
        """Glyph id of the replacement box."""
        return len(self.advances) - 1

    @property
    def reach(self) -> float:
        """How far (font units) any glyph's ink or advance can lie from its origin, in
        x or y: glyphs whose origin is farther than that (scaled) from the frame
        buffer cannot touch it."""
        return max(abs(self.ascent), abs(self.descent), float(self.advances.max()),
                   self.units_per_em, self._ink_reach)

    @property
    def line_height(self) -> float:
        """Baseline-to-baseline distance of consecutive lines, font units."""
        return self.ascent - self.descent + self.line_gap

    def glyph_ids(self, codes: NDArray[np.integer[Any]], small: bool = False) -> NDArray[np.int64]:
        """Glyph ids of an integer array of code points (missing -> ``replacement``);
        ``small=True`` promises every code is below 0x10000 (ASCII text).

        Parameters
        ----------
        codes : ndarray of int
            Code points.
        small : bool
            Every code is below 0x10000 (skips the astral lookup).

        Returns
        -------
        ndarray of int64
            One glyph id per code point; ``replacement`` where the font lacks it.

        Examples
        --------
        >>> import numpy as np, scanline as sl
        >>> f = sl.text.font("bitmap")
        >>> ids = f.glyph_ids(np.array([ord("A"), 0x1F600]))
        >>> int(ids[1]) == f.replacement, int(ids[0]) != f.replacement
        (True, True)
        """
        if small or len(codes) == 0 or codes.max() < len(self._table):
            found: NDArray[np.int64] = self._table[codes]
            return found
        ids: NDArray[np.int64] = self._table[np.minimum(codes, len(self._table) - 1)]
        big = codes >= len(self._table)
        if big.any():
            ids[big] = [self._extra.get(int(c), self.replacement) for c in codes[big]]
        return ids

    def has_glyph(self, char: str) -> bool:
        """Whether ``char`` (a one-character string) has its own glyph.

        Parameters
        ----------
        char : str
            One character.

        Returns
        -------
        bool
            False where the font would draw its replacement box.

        Examples
        --------
        >>> import scanline as sl
        >>> f = sl.text.font("bitmap")
        >>> f.has_glyph("A"), f.has_glyph("\u4e2d")
        (True, False)
        """
        return int(self.glyph_ids(np.array([ord(char)]))[0]) != self.replacement

    def bounds(self, gid: int) -> Optional[tuple[float, float, float, float]]:
        """Ink bounds ``(xmin, ymin, xmax, ymax)`` of glyph ``gid`` in font units, or
        None for a blank glyph (a space).

        Parameters
        ----------
        gid : int
            A glyph id (:meth:`glyph_ids`).

        Returns
        -------
        (float, float, float, float) or None
            The bounding box of the glyph's ink, None for a blank glyph.

        Examples
        --------
        >>> import numpy as np, scanline as sl
        >>> f = sl.text.font("bitmap")
        >>> space, bar = f.glyph_ids(np.array([ord(" "), ord("|")])).tolist()
        >>> f.bounds(space) is None, f.bounds(bar) is not None
        (True, True)
        """
        if gid not in self._bounds:
            pts = [p for p in self._ink(gid, self.units_per_em / 1024) if len(p)]
            if pts:
                x0, y0, x1, y1 = np.concatenate([np.vstack(pts).min(0),
                                                 np.vstack(pts).max(0)]).tolist()
                self._bounds[gid] = (x0, y0, x1, y1)
            else:
                self._bounds[gid] = None
        return self._bounds[gid]

    def _replacement_box(self, x0: float, width: float, thickness: float) -> list[NDArray[np.float64]]:
        """The replacement glyph as two contours (nonzero rule): the outer rectangle
        counterclockwise, the inner one clockwise."""
        h = self.cap_height
        t = thickness
        outer = np.array([(x0, 0), (x0 + width, 0), (x0 + width, h), (x0, h)], float)
        inner = np.array([(x0 + t, t), (x0 + t, h - t), (x0 + width - t, h - t),
                          (x0 + width - t, t)], float)
        return [outer, inner]


def _builtin() -> dict[str, Callable[[], Font]]:
    from .bitmap import BitmapFont
    from .outline import OutlineFont
    from .stroke import StrokeFont
    return {
        "sans": lambda: OutlineFont(str(DATA / "DejaVuSans.ttf"), name="sans",
                                    license="Bitstream Vera license (DejaVu changes: "
                                            "public domain); see DejaVuSans-LICENSE.txt"),
        "bitmap": lambda: BitmapFont.read(str(DATA / "dotmatrix-5x7.txt")),
        "stroke": lambda: StrokeFont.read(str(DATA / "stroke.txt")),
    }


_LOADED: dict[str, Font] = {}


def fonts() -> dict[str, Font]:
    """The built-in fonts as ``{name: Font}``.

    Returns
    -------
    dict of str to Font
        "bitmap", "sans" and "stroke", loaded (once).

    Examples
    --------
    >>> import scanline as sl
    >>> sorted(sl.text.fonts())
    ['bitmap', 'sans', 'stroke']
    >>> sl.text.fonts()["bitmap"].kind
    'bitmap'
    """
    return {name: font(name) for name in _builtin()}


def load_font(path: Union[str, "os.PathLike[str]"]) -> Font:
    """Read a TrueType or OpenType font file (outlines ``glyf`` or ``CFF``).

    Parameters
    ----------
    path : str or os.PathLike
        The font file.

    Returns
    -------
    OutlineFont
        The font (loaded once per absolute path).

    Raises
    ------
    ArgumentValueError
        If the file does not exist or is not a readable font (truncated, garbage,
        no outlines, no Unicode character map).

    Examples
    --------
    The built-in "sans" is DejaVu Sans, shipped as a file:

    >>> import scanline as sl
    >>> from scanline.text.catalog import DATA
    >>> f = sl.text.load_font(str(DATA / "DejaVuSans.ttf"))
    >>> f.kind, f.units_per_em
    ('outline', 2048.0)
    """
    if not isinstance(path, (str, os.PathLike)):
        raise ArgumentTypeError(f"path must be a file name, got {v._show(path)}")
    key = os.path.abspath(os.fspath(path))
    if key not in _LOADED:
        from .outline import OutlineFont
        _LOADED[key] = OutlineFont(key)
    return _LOADED[key]


def font(spec: Union[str, "os.PathLike[str]", Font], name: str = "font") -> Font:
    """Resolve a font argument: a built-in name, a path to a .ttf/.otf file, a font
    family's name (``"DejaVu Sans"`` is the built-in ``"sans"``; others are looked
    up among the installed fonts, :mod:`scanline.text.system`), or a :class:`Font`.

    Parameters
    ----------
    spec : str, os.PathLike or Font
        The font.
    name : str
        The argument's name, for error messages.

    Returns
    -------
    Font
        The loaded font (built-in and file fonts are loaded once).

    Raises
    ------
    ArgumentTypeError
        ``spec`` is none of these.
    ArgumentValueError
        An unknown name, or a path that is not a font file.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.text.font("stroke").kind, sl.text.font("bitmap") is sl.text.font("bitmap")
    ('stroke', True)
    """
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
