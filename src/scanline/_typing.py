"""Types of scanline's public arguments, for annotations, editors and type checkers.

``import scanline._typing as t`` (or ``from scanline._typing import Color``); at run
time these are plain aliases, never checked by themselves (the API layer validates
values, DESIGN.md convention 7).
"""

from typing import Any, List, Literal, Sequence, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["ArrayLike", "NDArray", "Color", "Angle", "Mode", "LineMethod", "Rule", "Cap",
           "Join", "Pen", "PenLike", "Dash", "Colors", "Connectivity", "ClipMethod", "Point",
           "Points", "Resample"]

#: A color as the drawing functions take it: a name (Pillow's, or matplotlib's such as
#: "tab:blue" and "C0"), "#rrggbb[aa]", an (r, g, b[, a]) tuple of ints 0..255 or of
#: floats in [0, 1], or an int (a gray level, a bit in mode "1", a table index in "P").
Color = Union[str, int, Tuple[int, int, int], Tuple[int, int, int, int],
              Tuple[float, float, float], Tuple[float, float, float, float]]
#: An angle: radians as a number, or a string with its unit ("30deg", "30°", "0.5rad",
#: "0.25turn"); see docs/conventions.md.
Angle = Union[float, str]
#: The colors of a batch of N primitives: one color for all, a list of N colors, or an
#: integer array, (N,) bits / gray levels / table indices or (N, 3|4) RGB(A) values.
Colors = Union[Color, List[Color], NDArray[np.integer[Any]]]
#: Frame-buffer modes.
Mode = Literal["1", "L", "RGB", "RGBA", "P"]
#: Line scan-conversion algorithms.
LineMethod = Literal["bresenham", "dda"]
#: Inside-outside rules of area fills.
Rule = Literal["even-odd", "nonzero"]
#: Line caps and joins of thick lines.
Cap = Literal["butt", "round", "square"]
Join = Literal["miter", "round", "bevel"]
#: Pen footprints by name ("round" is another name of "circle").
Pen = Literal["square", "circle", "round"]
#: A pen as the line functions take it: a name, or a 2-D bool footprint array.
PenLike = Union[Pen, NDArray[np.bool_]]
#: A line type: a name ("solid", "dashed", "dotted", "dash-dot"), a 16-bit pixel mask,
#: or dash and gap lengths in pixels.
Dash = Union[str, int, Sequence[float]]
#: Neighbourhoods of seed fills.
Connectivity = Literal[4, 8]
#: Line-clipping algorithms.
ClipMethod = Literal["cohen-sutherland", "liang-barsky", "cyrus-beck"]
#: Pillow's resampling filters by name (FrameBuffer.resize).
Resample = Literal["nearest", "box", "bilinear", "hamming", "bicubic", "lanczos"]
#: A device or world point, and a sequence of them ((N, 2) arrays too).
Point = Tuple[float, float]
Points = Union[Sequence[Point], ArrayLike]
