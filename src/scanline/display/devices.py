"""Devices the display-file interpreter drives: raster and random-scan (vector).

Every device has ``width`` and ``height`` (device units, pixel centers at integers,
y up) and two drawing operations, called with geometry already clipped to the device:

``stroke(pieces, closed, attributes)``
    Polylines, each a (K, 2) array; ``closed`` when one unclipped ring is given;
    ``attributes`` the line attributes: ``color`` and ``style``, a
    :class:`scanline.LineStyle`.
``fill(contours, attributes)``
    One area: contours combined by ``attributes["rule"]``, painted in
    ``attributes["style"]`` (None: solid) and ``attributes["color"]``.

and optionally two batch operations (the interpreter uses ``stroke`` and ``fill``
when a device lacks them): ``segments(segments, attributes)``, thin solid line
segments as an (N, 4) array, and ``areas(polygons, attributes)``, solid one-contour
areas that each take the rule on their own.

:class:`RasterDevice` scan-converts into a :class:`~scanline.FrameBuffer`;
:class:`VectorDevice` records the MOVE/LINE commands a random-scan display would
refresh; :class:`SVGDevice` writes an SVG document.
"""

import math
import os
from typing import TYPE_CHECKING, Any, Optional, Sequence, Union
from xml.sax.saxutils import escape, quoteattr

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import draw
from ..color.spec import rgba
from ..errors import ArgumentTypeError
from ..framebuffer import FrameBuffer, write_atomically
from ..linestyle import LineStyle
from . import spans
from .primitives import THIN

if TYPE_CHECKING:
    from .._typing import Color

F64 = NDArray[np.float64]
#: Polylines or contours, each a (K, 2) array of device points.
Pieces = Sequence[F64]
#: A primitive's attributes as the interpreter passes them.
Attributes = dict[str, Any]

def _simple(style: LineStyle) -> bool:
    """True when a stroke is a plain one-pixel line (Bresenham segments suffice)."""
    return bool(style.width <= 1 and style.solid)


def _segments(pieces: Pieces, closed: bool) -> F64:
    """The polylines as (N, 4) line segments."""
    rows = []
    for p in pieces:
        q = np.vstack([p, p[:1]]) if closed and len(p) > 2 else p
        if len(q) == 1:
            q = np.vstack([q, q])
        rows.append(np.hstack([q[:-1], q[1:]]))
    return np.vstack(rows) if rows else np.zeros((0, 4))


class RasterDevice:
    """Scan-converts the display file into a frame buffer (``sl.draw``).

    Parameters
    ----------
    fb : FrameBuffer
        Drawn into as it is (not cleared).
    antialias : bool
        Draw strokes and solid areas antialiased (``antialias=True`` of
        ``sl.draw.polylines`` and ``sl.draw.polygon``); pattern and hatch fills stay
        aliased.

    Raises
    ------
    ArgumentTypeError
        When ``fb`` is not a FrameBuffer or ``antialias`` not a bool.

    Examples
    --------
    >>> import numpy as np
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(4, 1, mode="1")
    >>> device = sl.display.RasterDevice(fb)
    >>> device.segments(np.array([[0, 0, 2, 0]]), {"color": 1})
    >>> print(sl.text_image(fb))
    ###-
    """

    def __init__(self, fb: FrameBuffer, antialias: bool = False) -> None:
        if not isinstance(fb, FrameBuffer):
            raise ArgumentTypeError(f"fb must be a scanline.FrameBuffer, got {type(fb).__name__}")
        if not isinstance(antialias, bool):
            raise ArgumentTypeError(f"antialias must be True or False, got {antialias!r}")
        self.fb = fb
        self.antialias = antialias
        self.width, self.height = fb.width, fb.height

    def stroke(self, pieces: Pieces, closed: bool, attributes: Attributes) -> None:
        """Draw polylines with the line attributes.

        Parameters
        ----------
        pieces : sequence of (K, 2) arrays
            The polylines, in device coordinates.
        closed : bool
            Join each one's last point to its first.
        attributes : dict
            ``color`` and ``style`` (a :class:`~scanline.LineStyle`).

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(4, 1, mode="1")
        >>> sl.display.RasterDevice(fb).stroke(
        ...     [np.array([[0.0, 0.0], [3.0, 0.0]])], False, {"color": 1, "style": sl.LineStyle()})
        >>> print(sl.text_image(fb))
        ####
        """
        color, style = attributes["color"], attributes["style"]
        if _simple(style) and not self.antialias:
            draw.lines(self.fb, _segments(pieces, closed), color=color)
        else:
            draw.polylines(self.fb, list(pieces), color=color, closed=closed, style=style,
                           antialias=self.antialias)

    def fill(self, contours: Pieces, attributes: Attributes) -> None:
        """Fill one area.

        Parameters
        ----------
        contours : sequence of (K, 2) arrays
            Its contours, in device coordinates.
        attributes : dict
            ``color``, ``rule`` and ``style`` (a FillStyle, or None: solid).

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(4, 1, mode="1")
        >>> square = np.array([(-0.5, -0.5), (1.5, -0.5), (1.5, 0.5), (-0.5, 0.5)])
        >>> sl.display.RasterDevice(fb).fill([square], {"color": 1, "rule": "even-odd", "style": None})
        >>> print(sl.text_image(fb))
        ##--
        """
        style = attributes["style"]
        draw.polygon(self.fb, list(contours), color=attributes["color"],
                     rule=attributes["rule"], style=style,
                     antialias=self.antialias and style is None)

    def segments(self, segments: ArrayLike, attributes: Attributes) -> None:
        """Thin solid line segments (N, 4), one color, in one call.

        Parameters
        ----------
        segments : (N, 4) array_like
            Rows x0, y0, x1, y1 in device coordinates.
        attributes : dict
            ``color``.

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(3, 2, mode="1")
        >>> sl.display.RasterDevice(fb).segments(np.array([[0, 0, 2, 0], [0, 1, 0, 1]]), {"color": 1})
        >>> print(sl.text_image(fb))
        #--
        ###
        """
        draw.lines(self.fb, segments, color=attributes["color"], antialias=self.antialias)

    def areas(self, polygons: Pieces, attributes: Attributes) -> None:
        """Solid one-contour areas, one color and rule, in one call.

        Parameters
        ----------
        polygons : sequence of (K, 2) arrays
            One contour each, in device coordinates.
        attributes : dict
            ``color`` and ``rule``.

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(4, 1, mode="1")
        >>> cell = np.array([(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)])
        >>> sl.display.RasterDevice(fb).areas([cell, cell + (2, 0)], {"color": 1, "rule": "nonzero"})
        >>> print(sl.text_image(fb))
        #-#-
        """
        draw.polygons(self.fb, list(polygons), color=attributes["color"],
                      rule=attributes["rule"], antialias=self.antialias)


def _fill_strokes(contours: Pieces, attributes: Attributes) -> F64:
    """The strokes a vector device draws for an area: hatch lines for a hatch style,
    the scan-line spans for any other painted style; none for a hollow one."""
    style = attributes["style"]
    if style is not None and style.kind == "hollow":
        return np.zeros((0, 4))
    if style is not None and style.kind == "hatch":
        angles = [style.angle] + ([style.angle + math.pi / 2] if style.cross else [])
        return np.vstack([spans.hatch(contours, attributes["rule"], a, style.spacing)
                          for a in angles])
    return spans.spans(contours, attributes["rule"])


class VectorDevice:
    """A random-scan (vector, calligraphic) display: a list of beam commands.

    The refresh display file of the notes (chapter 1, Q.3) is "a set of
    line-drawing commands"; this device records them as ``("COLOR", r, g, b, a)``,
    ``("MOVE", x, y)`` and ``("LINE", x, y)`` tuples in device coordinates.  A beam
    has one width, so line width and dash patterns are not represented; areas are
    drawn as their outline plus strokes: hatch lines for a hatch style, one stroke
    per scan line (exactly the pixels of the raster fill) for the other styles,
    only the outline for a hollow one.

    Parameters
    ----------
    width, height : int
        The addressable area (the same frame as a raster device's).

    Examples
    --------
    >>> import numpy as np
    >>> import scanline as sl
    >>> beam = sl.display.VectorDevice(10, 10)
    >>> beam.segments(np.array([[0, 0, 5, 0], [5, 0, 5, 5]]), {"color": "red"})
    >>> beam.commands
    [('COLOR', 255, 0, 0, 255), ('MOVE', 0.0, 0.0), ('LINE', 5.0, 0.0), ('LINE', 5.0, 5.0)]
    """

    def __init__(self, width: int, height: int) -> None:
        self.width, self.height = width, height
        # (rgba, (N, 4) segments) in drawing order
        self._chunks: list[tuple[tuple[int, int, int, int], F64]] = []

    def _draw(self, segments: ArrayLike, color: Optional["Color"]) -> None:
        rows = np.asarray(segments, np.float64)
        if len(rows):   # no color given: the white beam of a dark vector screen
            self._chunks.append((rgba("white" if color is None else color), rows))

    def stroke(self, pieces: Pieces, closed: bool, attributes: Attributes) -> None:
        """Record polylines as beam strokes (width and dashes are not represented).

        Parameters
        ----------
        pieces : sequence of (K, 2) arrays
            The polylines, in device coordinates.
        closed : bool
            Join each one's last point to its first.
        attributes : dict
            ``color``.

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> beam = sl.display.VectorDevice(10, 10)
        >>> beam.stroke([np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 4.0]])], True, {"color": None})
        >>> beam.lines().tolist()                    # closed: back to the start
        [[0.0, 0.0, 4.0, 0.0], [4.0, 0.0, 4.0, 4.0], [4.0, 4.0, 0.0, 0.0]]
        """
        self._draw(_segments(pieces, closed), attributes["color"])

    def fill(self, contours: Pieces, attributes: Attributes) -> None:
        """Record an area as strokes: its fill strokes (one per scan line, or hatch
        lines) and then its outline.

        Parameters
        ----------
        contours : sequence of (K, 2) arrays
            Its contours, in device coordinates.
        attributes : dict
            ``color``, ``rule`` and ``style``.

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> beam = sl.display.VectorDevice(10, 10)
        >>> square = np.array([(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)])
        >>> beam.fill([square], {"color": "white", "rule": "even-odd", "style": sl.FillStyle.hollow()})
        >>> len(beam.lines())                        # hollow: the 4 sides only
        4
        """
        self._draw(_fill_strokes(contours, attributes), attributes["color"])
        self._draw(_segments(contours, True), attributes["color"])

    def segments(self, segments: ArrayLike, attributes: Attributes) -> None:
        """Record line segments (N, 4), one color.

        Parameters
        ----------
        segments : (N, 4) array_like
            Rows x0, y0, x1, y1 in device coordinates.
        attributes : dict
            ``color``.

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> beam = sl.display.VectorDevice(10, 10)
        >>> beam.segments(np.array([[1, 2, 3, 4]]), {"color": None})
        >>> beam.lines().tolist()
        [[1.0, 2.0, 3.0, 4.0]]
        """
        self._draw(segments, attributes["color"])

    def areas(self, polygons: Pieces, attributes: Attributes) -> None:
        """Record one-contour areas, each as :meth:`fill` does.

        Parameters
        ----------
        polygons : sequence of (K, 2) arrays
            One contour each, in device coordinates.
        attributes : dict
            ``color``, ``rule`` and ``style``.

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> beam = sl.display.VectorDevice(10, 10)
        >>> tri = np.array([(0.0, 0.0), (3.0, 0.0), (0.0, 3.0)])
        >>> beam.areas([tri, tri + 5], {"color": 1, "rule": "nonzero", "style": sl.FillStyle.hollow()})
        >>> len(beam.lines())
        6
        """
        for p in polygons:
            self.fill([p], attributes)

    @property
    def commands(self) -> list[tuple[Any, ...]]:
        """The beam commands: ``("COLOR", r, g, b, a)``, ``("MOVE", x, y)``,
        ``("LINE", x, y)``; a MOVE only where a line does not start at the beam."""
        out: list[tuple[Any, ...]] = []
        color: Optional[tuple[int, int, int, int]] = None
        beam: Optional[tuple[float, float]] = None
        for c, segments in self._chunks:
            if c != color:
                out.append(("COLOR",) + c)
                color = c
            for x0, y0, x1, y1 in segments.tolist():
                if beam != (x0, y0):
                    out.append(("MOVE", x0, y0))
                out.append(("LINE", x1, y1))
                beam = (x1, y1)
        return out

    def lines(self) -> F64:
        """The LINE commands as (N, 4) segments (x0, y0, x1, y1) in device units.

        Returns
        -------
        numpy.ndarray
            float64 (N, 4), in drawing order.

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> sl.display.VectorDevice(4, 4).lines().shape
        (0, 4)
        """
        return np.vstack([np.zeros((0, 4))] + [seg for _, seg in self._chunks])

    def listing(self) -> str:
        """The commands as text, one per line (``MOVE x y``, ``LINE x y``,
        ``COLOR r g b a``), coordinates rounded to 1/1000 of a device unit.

        Returns
        -------
        str
            A comment line, then one command a line.

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> beam = sl.display.VectorDevice(8, 8)
        >>> beam.segments(np.array([[0, 0, 2.5, 1 / 3]]), {"color": "black"})
        >>> print(beam.listing(), end="")
        ; random-scan display file, 8 x 8 device units
        COLOR 0 0 0 255
        MOVE 0 0
        LINE 2.5 0.333
        """
        rows = [f"; random-scan display file, {self.width} x {self.height} device units"]
        for cmd in self.commands:
            if cmd[0] == "COLOR":
                rows.append("COLOR " + " ".join(str(c) for c in cmd[1:]))
            else:
                rows.append(f"{cmd[0]} {_num(cmd[1])} {_num(cmd[2])}")
        return "\n".join(rows) + "\n"

    def save(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Write :meth:`listing` to ``path`` atomically.

        Parameters
        ----------
        path : str or os.PathLike
            The file to write.

        Raises
        ------
        ArgumentValueError
            For a path that cannot be written.
        OutputError
            When writing fails.

        Examples
        --------
        >>> import os, tempfile
        >>> import scanline as sl
        >>> with tempfile.TemporaryDirectory() as folder:
        ...     sl.display.VectorDevice(3, 2).save(os.path.join(folder, "beam.txt"))
        ...     print(open(os.path.join(folder, "beam.txt")).read(), end="")
        ; random-scan display file, 3 x 2 device units
        """
        write_atomically(path, lambda f: f.write(self.listing().encode("utf-8")))


def _num(x: float) -> str:
    """A coordinate for text output: at most 3 decimals, no trailing zeros."""
    text = f"{x:.3f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


class SVGDevice:
    """An SVG document, the display file as resolution-independent vector output.

    Each segment is a group ``<g data-segment="NAME">`` titled with its name.

    Device coordinates map to SVG user units by ``(x + 0.5, height - 0.5 - y)``: the
    SVG canvas is the frame of a ``width`` x ``height`` raster, y flipped.  Strokes keep
    their width, caps, joins and dashes; areas are paths filled by their rule; a
    hatch style is drawn as its hatch strokes, a pattern as its fill color.

    Parameters
    ----------
    width, height : int
        The canvas, in device units.
    background : color or None
        None: transparent.  Primitives without a color are drawn black, or in the
        color that contrasts with ``background`` (as ``FrameBuffer.foreground``).

    Examples
    --------
    >>> import numpy as np
    >>> import scanline as sl
    >>> svg = sl.display.SVGDevice(4, 3)
    >>> svg.stroke([np.array([[0.0, 0.0], [3.0, 2.0]])], False, {"color": "red", "style": sl.LineStyle()})
    >>> svg.elements[0]          # y flipped: (0, 0) -> (0.5, 2.5)
    '<path d="M0.5 2.5 L3.5 0.5" fill="none" stroke="rgb(255,0,0)" stroke-width="1" stroke-linecap="butt" stroke-linejoin="miter" stroke-miterlimit="10"/>'
    """

    def __init__(self, width: int, height: int, background: Optional["Color"] = None) -> None:
        self.width, self.height = width, height
        self.elements: list[str] = []
        self.foreground = "black" if background is None else FrameBuffer(
            1, 1, background=background).foreground
        if background is not None:
            self.elements.append(
                f'<rect width="{width}" height="{height}"{_paint("fill", background)}/>')

    def _path(self, pieces: Pieces, closed: bool) -> str:
        parts = []
        for p in pieces:
            xs = [_num(x + 0.5) for x in p[:, 0]]
            ys = [_num(self.height - 0.5 - y) for y in p[:, 1]]
            coords = [f"{x} {y}" for x, y in zip(xs, ys)]
            if len(coords) == 1:
                coords.append(coords[0])
            parts.append("M" + " L".join(coords) + (" Z" if closed else ""))
        return quoteattr(" ".join(parts))

    def stroke(self, pieces: Pieces, closed: bool, attributes: Attributes) -> None:
        """Add a ``<path>`` stroked with the line attributes.

        Parameters
        ----------
        pieces : sequence of (K, 2) arrays
            The polylines, in device coordinates.
        closed : bool
            Close each one.
        attributes : dict
            ``color`` and ``style`` (a :class:`~scanline.LineStyle`).

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> svg = sl.display.SVGDevice(4, 4)
        >>> svg.stroke([np.zeros((2, 2))], False, {"color": None, "style": sl.LineStyle(dash=(2, 1))})
        >>> 'stroke-dasharray="2 1"' in svg.elements[0]
        True
        """
        if not pieces:
            return
        style = attributes["style"]
        extra = ""
        lengths, phase = style.lengths()
        if lengths:
            extra = (f' stroke-dasharray="{" ".join(_num(d) for d in lengths)}"'
                     f' stroke-dashoffset="{_num(phase)}"')
        self.elements.append(
            f'<path d={self._path(pieces, closed)} fill="none"'
            f'{_paint("stroke", attributes["color"] or self.foreground)} stroke-width="{_num(style.width)}"'
            f' stroke-linecap="{style.cap}" stroke-linejoin="{style.join}"'
            f' stroke-miterlimit="{_num(style.miter_limit)}"{extra}/>')

    def fill(self, contours: Pieces, attributes: Attributes) -> None:
        """Add an area: a ``<path>`` filled by its rule, or strokes for a hollow or
        hatch style.

        Parameters
        ----------
        contours : sequence of (K, 2) arrays
            Its contours, in device coordinates.
        attributes : dict
            ``color``, ``rule`` and ``style``.

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> svg = sl.display.SVGDevice(4, 4)
        >>> square = np.array([(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)])
        >>> svg.fill([square], {"color": "blue", "rule": "nonzero", "style": None})
        >>> svg.elements[0]
        '<path d="M0.5 3.5 L2.5 3.5 L2.5 1.5 L0.5 1.5 Z" fill-rule="nonzero" fill="rgb(0,0,255)"/>'
        """
        style = attributes["style"]
        line = {"color": attributes["color"], "style": THIN}
        if style is not None and style.kind in ("hollow", "hatch"):
            if style.kind == "hatch":
                hatch = _fill_strokes(contours, attributes)
                self.stroke([h.reshape(2, 2) for h in hatch], False,
                            {**line, "style": LineStyle(width=style.line_width)})
            self.stroke(contours, True, line)
            return
        rule = "evenodd" if attributes["rule"] == "even-odd" else "nonzero"
        self.elements.append(
            f'<path d={self._path(contours, True)} fill-rule="{rule}"'
            f'{_paint("fill", attributes["color"] or self.foreground)}/>')

    def begin_segment(self, name: str) -> None:
        """Start a group for the segment ``name`` (its name as the group's title).

        Parameters
        ----------
        name : str
            The segment's name.

        Examples
        --------
        >>> import scanline as sl
        >>> svg = sl.display.SVGDevice(4, 4)
        >>> svg.begin_segment("a & b"); svg.end_segment()
        >>> svg.elements
        ['<g data-segment="a &amp; b"><title>a &amp; b</title>', '</g>']
        """
        self.elements.append(f"<g data-segment={quoteattr(name)}><title>{escape(name)}</title>")

    def end_segment(self) -> None:
        """End the group :meth:`begin_segment` started.

        Examples
        --------
        >>> import scanline as sl
        >>> svg = sl.display.SVGDevice(4, 4)
        >>> svg.end_segment(); svg.elements
        ['</g>']
        """
        self.elements.append("</g>")

    def svg(self) -> str:
        """The SVG document as a string.

        Returns
        -------
        str
            The ``<svg>`` element holding :attr:`elements`.

        Examples
        --------
        >>> import scanline as sl
        >>> print(sl.display.SVGDevice(2, 1, background="white").svg(), end="")
        <svg xmlns="http://www.w3.org/2000/svg" version="1.1" width="2" height="1" viewBox="0 0 2 1">
        <rect width="2" height="1" fill="rgb(255,255,255)"/>
        </svg>
        """
        body = "\n".join(self.elements)
        return (f'<svg xmlns="http://www.w3.org/2000/svg" version="1.1" '
                f'width="{self.width}" height="{self.height}" '
                f'viewBox="0 0 {self.width} {self.height}">\n{body}\n</svg>\n')

    def save(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Write :meth:`svg` to ``path`` atomically.

        Parameters
        ----------
        path : str or os.PathLike
            The file to write.

        Raises
        ------
        ArgumentValueError
            For a path that cannot be written.
        OutputError
            When writing fails.

        Examples
        --------
        >>> import os, tempfile
        >>> import scanline as sl
        >>> with tempfile.TemporaryDirectory() as folder:
        ...     sl.display.SVGDevice(2, 2).save(os.path.join(folder, "picture.svg"))
        ...     open(os.path.join(folder, "picture.svg")).read().startswith("<svg")
        True
        """
        write_atomically(path, lambda f: f.write(self.svg().encode("utf-8")))


def _paint(attribute: str, color: "Color") -> str:
    """`` fill="rgb(...)"`` (with an opacity when translucent) for a color spec."""
    r, g, b, a = rgba(color)
    text = f' {attribute}="rgb({r},{g},{b})"'
    if a < 255:
        text += f' {attribute}-opacity="{_num(a / 255)}"'
    return text
