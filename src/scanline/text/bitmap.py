"""The dot-matrix (bitmap) font: each character a grid of dots (notes, syllabus:
"Character generation"; Hearn & Baker, section 3-14, "bitmap font").

Glyphs are read from a plain-text file (``data/fonts/dotmatrix-5x7.txt``; its header
documents the format).  In font units one dot is one unit: the dot in column ``c``
and row ``r`` above the baseline (``r = 0`` just above it, negative below) is the
unit square ``[c, c + 1] x [r, r + 1]``.

Scaling.  The font's cap height is 7 units.  At ``height = 7 k`` for an integer
``k`` each dot becomes a k x k block of pixels: pixel replication.  Any other height
(or a rotation, or an expansion factor) stamps each dot as a square (a run of dots
as one rectangle) of the scaled size, filled by the scan-line polygon fill, so a
dot-matrix character can take any size and direction.
"""

import os
from typing import Any, Optional, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from .catalog import Font

_KEYS = ("name", "width", "rows", "above", "advance", "x-height")


def _parse(text: str, source: str) -> tuple[dict[str, Any], dict[str, NDArray[np.bool_]]]:
    """``(properties, {char: bool array rows x width, top row first})``."""
    props: dict[str, Any] = {}
    glyphs: dict[str, NDArray[np.bool_]] = {}
    lines = [ln.rstrip("\n") for ln in text.splitlines()]
    i = 0
    while i < len(lines):
        line = lines[i].strip()
        i += 1
        if not line or line.startswith("#"):
            continue
        key, _, rest = line.partition(" ")
        if key == "chars":
            if not all(k in props for k in _KEYS):
                raise ValueError(f"line {i}: 'chars' before the properties {', '.join(_KEYS)}")
            chars = [" " if t == "SP" else t for t in rest.split()]
            rows = int(props["rows"])
            block = [ln.split() for ln in lines[i:i + rows]]
            i += rows
            for r, cells in enumerate(block):
                if len(cells) != len(chars) or any(len(c) != int(props["width"]) for c in cells):
                    raise ValueError(f"glyph strip {chars}: row {r + 1} does not hold "
                                     f"{len(chars)} groups of {props['width']} symbols")
            for n, ch in enumerate(chars):
                glyphs[ch] = np.array([[s == "@" for s in row[n]] for row in block], bool)
        elif key in _KEYS:
            props[key] = rest.strip() if key == "name" else int(rest)
        else:
            raise ValueError(f"line {i}: unknown property {key!r}")
    if not glyphs:
        raise ValueError("no glyphs")
    return props, glyphs


def _runs(dots: NDArray[np.bool_], above: int) -> list[NDArray[np.float64]]:
    """Each horizontal run of dots as a rectangle [c0, c1] x [r, r + 1] in font units
    (counterclockwise contours; runs that touch share edges, which the nonzero
    rule fills once)."""
    out: list[NDArray[np.float64]] = []
    for row, line in enumerate(dots):
        r = above - 1 - row
        c = 0
        while c < len(line):
            if line[c]:
                c0 = c
                while c < len(line) and line[c]:
                    c += 1
                out.append(np.array([(c0, r), (c, r), (c, r + 1), (c0, r + 1)], float))
            else:
                c += 1
    return out


class BitmapFont(Font):
    """A dot-matrix font.

    Attributes
    ----------
    glyphs : dict
        ``{char: bool array}``: each character's dots, top row first.
    """

    kind = "bitmap"

    def __init__(self, props: dict[str, Any], glyphs: dict[str, NDArray[np.bool_]],
                 source: str) -> None:
        super().__init__(props["name"], source, "MIT (designed for scanline)")
        self.glyphs = glyphs
        self.above = props["above"]
        self.units_per_em = float(props["rows"])
        self.cap_height = float(self.above)
        self.native_height = self.cap_height
        self.x_height = float(props["x-height"])
        self.ascent = float(self.above)
        self.descent = float(self.above - props["rows"])
        self.line_gap = 2.0
        chars = sorted(glyphs)
        self._chars = chars
        self.advances = np.array([props["advance"]] * (len(chars) + 1), float)
        self._table = np.full(0x10000, len(chars), np.int64)
        for gid, ch in enumerate(chars):
            self._table[ord(ch)] = gid
        self._shapes = [_runs(glyphs[ch], self.above) for ch in chars]
        self._shapes.append(self._replacement_box(0.0, float(props["width"]), 1.0))

    @classmethod
    def read(cls, path: Union[str, "os.PathLike[str]"]) -> "BitmapFont":
        """Read a dot-matrix font file (see ``data/fonts/dotmatrix-5x7.txt``)."""
        try:
            with open(path, encoding="utf-8") as f:
                props, glyphs = _parse(f.read(), str(path))
        except (OSError, UnicodeDecodeError, ValueError) as exc:
            raise ArgumentValueError(f"bitmap font file {v._show(str(path))}: {exc}") from None
        return cls(props, glyphs, str(path))

    def _ink(self, gid: int, tolerance: Optional[float] = None) -> list[NDArray[np.float64]]:
        """The dots of glyph ``gid`` as rectangles (runs of dots), font units."""
        return self._shapes[gid]
