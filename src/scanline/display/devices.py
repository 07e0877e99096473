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
from xml.sax.saxutils import escape, quoteattr

import numpy as np

from .. import draw
from ..color.spec import rgba
from ..errors import ArgumentTypeError
from ..framebuffer import FrameBuffer, write_atomically
from ..linestyle import LineStyle
from . import spans
from .primitives import THIN

def _simple(style):
    """True when a stroke is a plain one-pixel line (Bresenham segments suffice)."""
    return style.width <= 1 and style.solid


def _segments(pieces, closed):
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
    """

    def __init__(self, fb, antialias=False):
        if not isinstance(fb, FrameBuffer):
            raise ArgumentTypeError(f"fb must be a scanline.FrameBuffer, got {type(fb).__name__}")
        if not isinstance(antialias, bool):
            raise ArgumentTypeError(f"antialias must be True or False, got {antialias!r}")
        self.fb = fb
        self.antialias = antialias
        self.width, self.height = fb.width, fb.height

    def stroke(self, pieces, closed, attributes):
        color, style = attributes["color"], attributes["style"]
        if _simple(style) and not self.antialias:
            draw.lines(self.fb, _segments(pieces, closed), color=color)
        else:
            draw.polylines(self.fb, list(pieces), color=color, closed=closed, style=style,
                           antialias=self.antialias)

    def fill(self, contours, attributes):
        style = attributes["style"]
        draw.polygon(self.fb, list(contours), color=attributes["color"],
                     rule=attributes["rule"], style=style,
                     antialias=self.antialias and style is None)

    def segments(self, segments, attributes):
        """Thin solid line segments (N, 4), one color, in one call."""
        draw.lines(self.fb, segments, color=attributes["color"], antialias=self.antialias)

    def areas(self, polygons, attributes):
        """Solid one-contour areas, one color and rule, in one call."""
        draw.polygons(self.fb, list(polygons), color=attributes["color"],
                      rule=attributes["rule"], antialias=self.antialias)


def _fill_strokes(contours, attributes):
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
    """

    def __init__(self, width, height):
        self.width, self.height = width, height
        self._chunks = []  # (rgba, (N, 4) segments) in drawing order

    def _draw(self, segments, color):
        if len(segments):   # no color given: the white beam of a dark vector screen
            self._chunks.append((rgba("white" if color is None else color),
                                 np.asarray(segments, np.float64)))

    def stroke(self, pieces, closed, attributes):
        self._draw(_segments(pieces, closed), attributes["color"])

    def fill(self, contours, attributes):
        self._draw(_fill_strokes(contours, attributes), attributes["color"])
        self._draw(_segments(contours, True), attributes["color"])

    def segments(self, segments, attributes):
        self._draw(segments, attributes["color"])

    def areas(self, polygons, attributes):
        for p in polygons:
            self.fill([p], attributes)

    @property
    def commands(self):
        """The beam commands: ``("COLOR", r, g, b, a)``, ``("MOVE", x, y)``,
        ``("LINE", x, y)``; a MOVE only where a line does not start at the beam."""
        out, color, beam = [], None, None
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

    def lines(self):
        """The LINE commands as (N, 4) segments (x0, y0, x1, y1) in device units."""
        return np.vstack([np.zeros((0, 4))] + [seg for _, seg in self._chunks])

    def listing(self):
        """The commands as text, one per line (``MOVE x y``, ``LINE x y``,
        ``COLOR r g b a``), coordinates rounded to 1/1000 of a device unit."""
        rows = [f"; random-scan display file, {self.width} x {self.height} device units"]
        for cmd in self.commands:
            if cmd[0] == "COLOR":
                rows.append("COLOR " + " ".join(str(c) for c in cmd[1:]))
            else:
                rows.append(f"{cmd[0]} {_num(cmd[1])} {_num(cmd[2])}")
        return "\n".join(rows) + "\n"

    def save(self, path):
        """Write :meth:`listing` to ``path`` atomically."""
        write_atomically(path, lambda f: f.write(self.listing().encode("utf-8")))


def _num(x):
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
    background : color or None
        None: transparent.  Primitives without a color are drawn black, or in the
        color that contrasts with ``background`` (as ``FrameBuffer.foreground``).
    """

    def __init__(self, width, height, background=None):
        self.width, self.height = width, height
        self.elements = []
        self.foreground = "black" if background is None else FrameBuffer(
            1, 1, background=background).foreground
        if background is not None:
            self.elements.append(
                f'<rect width="{width}" height="{height}"{_paint("fill", background)}/>')

    def _path(self, pieces, closed):
        parts = []
        for p in pieces:
            xs = [_num(x + 0.5) for x in p[:, 0]]
            ys = [_num(self.height - 0.5 - y) for y in p[:, 1]]
            coords = [f"{x} {y}" for x, y in zip(xs, ys)]
            if len(coords) == 1:
                coords.append(coords[0])
            parts.append("M" + " L".join(coords) + (" Z" if closed else ""))
        return quoteattr(" ".join(parts))

    def stroke(self, pieces, closed, attributes):
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

    def fill(self, contours, attributes):
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

    def begin_segment(self, name):
        """Start a group for the segment ``name`` (its name as the group's title)."""
        self.elements.append(f"<g data-segment={quoteattr(name)}><title>{escape(name)}</title>")

    def end_segment(self):
        self.elements.append("</g>")

    def svg(self):
        """The SVG document as a string."""
        body = "\n".join(self.elements)
        return (f'<svg xmlns="http://www.w3.org/2000/svg" version="1.1" '
                f'width="{self.width}" height="{self.height}" '
                f'viewBox="0 0 {self.width} {self.height}">\n{body}\n</svg>\n')

    def save(self, path):
        """Write :meth:`svg` to ``path`` atomically."""
        write_atomically(path, lambda f: f.write(self.svg().encode("utf-8")))


def _paint(attribute, color):
    """`` fill="rgb(...)"`` (with an opacity when translucent) for a color spec."""
    r, g, b, a = rgba(color)
    text = f' {attribute}="rgb({r},{g},{b})"'
    if a < 255:
        text += f' {attribute}-opacity="{_num(a / 255)}"'
    return text
