"""The stroke (vector) font: characters as polylines, for vector devices (notes,
section "random-scan displays" -- "stroke-writing or calligraphic displays";
Hearn & Baker, section 3-14, "outline font ... line segments").

A stroke character is drawn with line segments, so it can be scaled, slanted and
rotated freely and costs a few lines per character: the way random-scan displays
and pen plotters wrote text.  The glyphs live in ``data/fonts/stroke.txt`` (its
header documents the format), on a grid with cap height 6.

References
----------
A. V. Hershey, "Calligraphy for computer display", NWL Report 2101, U.S. Naval
Weapons Laboratory, 1967.
"""

import os
import re
from typing import Any, Callable, Optional, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from .catalog import Font

_GLYPH = re.compile(r'^U\+([0-9A-Fa-f]{4,6}) "(.)"\s*(.*)$')
_KEYS: dict[str, Callable[[str], Any]] = {"name": str, "cap-height": float, "x-height": float, "ascent": float,
         "descent": float, "advance": float, "line-gap": float}


def _parse(text: str) -> tuple[dict[str, Any], dict[int, list[NDArray[np.float64]]]]:
    props: dict[str, Any] = {}
    glyphs: dict[int, list[NDArray[np.float64]]] = {}
    for n, line in enumerate(text.splitlines(), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        m = _GLYPH.match(line)
        if m:
            code = int(m.group(1), 16)
            if chr(code) != m.group(2):
                raise ValueError(f"line {n}: U+{m.group(1)} is not {m.group(2)!r}")
            strokes: list[NDArray[np.float64]] = []
            for part in m.group(3).split("|"):
                if part.strip():
                    pts = [tuple(float(c) for c in p.split(",")) for p in part.split()]
                    if any(len(p) != 2 for p in pts) or len(pts) < 2:
                        raise ValueError(f"line {n}: a stroke needs two or more x,y points")
                    strokes.append(np.array(pts, float))
            glyphs[code] = strokes
            continue
        key, _, rest = line.partition(" ")
        if key not in _KEYS:
            raise ValueError(f"line {n}: unknown property or malformed glyph {line[:30]!r}")
        props[key] = _KEYS[key](rest.strip())
    missing = [k for k in _KEYS if k not in props]
    if missing or not glyphs:
        raise ValueError(f"missing {', '.join(missing) or 'glyphs'}")
    return props, glyphs


class StrokeFont(Font):
    """A vector font: each glyph a list of polylines ((K, 2) arrays, font units)."""

    kind = "stroke"
    native_height = 12.0

    def __init__(self, props: dict[str, Any], glyphs: dict[int, list[NDArray[np.float64]]], source: str) -> None:
        super().__init__(props["name"], source, "MIT (designed for scanline)")
        self.cap_height = props["cap-height"]
        self.x_height = props["x-height"]
        self.ascent = props["ascent"]
        self.descent = props["descent"]
        self.line_gap = props["line-gap"]
        self.units_per_em = self.ascent - self.descent
        codes = sorted(glyphs)
        self._strokes = [glyphs[c] for c in codes]
        w = props["advance"] - 2
        h = self.cap_height
        self._strokes.append([np.array([(0, 0), (w, 0), (w, h), (0, h), (0, 0)], float),
                              np.array([(0, 0), (w, h)], float),
                              np.array([(0, h), (w, 0)], float)])
        self.advances = np.full(len(self._strokes), props["advance"], float)
        self._table = np.full(0x10000, len(codes), np.int64)
        for gid, code in enumerate(codes):
            if code < 0x10000:
                self._table[code] = gid
            else:
                self._extra[code] = gid
        # all strokes as segments (x0, y0, x1, y1), glyph g's in seg[first[g]:first[g+1]]
        self.segments = np.vstack([np.hstack([p[:-1], p[1:]])
                                   for g in self._strokes for p in g])
        counts = [sum(len(p) - 1 for p in g) for g in self._strokes]
        self.first = np.concatenate([[0], np.cumsum(counts)]).astype(np.int64)
        self._ink_reach = float(np.abs(self.segments).max())

    @classmethod
    def read(cls, path: Union[str, "os.PathLike[str]"]) -> "StrokeFont":
        """Read a stroke font file (see ``data/fonts/stroke.txt``)."""
        try:
            with open(path, encoding="utf-8") as f:
                props, glyphs = _parse(f.read())
        except (OSError, UnicodeDecodeError, ValueError) as exc:
            raise ArgumentValueError(f"stroke font file {v._show(str(path))}: {exc}") from None
        return cls(props, glyphs, str(path))

    def _ink(self, gid: int, tolerance: Optional[float] = None) -> list[NDArray[np.float64]]:
        """The polylines of glyph ``gid``, font units."""
        return self._strokes[gid]
