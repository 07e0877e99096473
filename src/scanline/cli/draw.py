"""``scanline draw [options] -o OUT.png ITEMS...``: draw primitives into an image.

ITEMS is a little language: a word followed by its arguments, item after item, for
instance ``line 2 3 60 40 color red circle 32 24 15``.  :func:`parse_items` turns it
into :class:`Item` tuples without importing the drawing code; :func:`render` draws them
with :mod:`scanline.draw`.
"""

import argparse
import re
import textwrap
from collections import namedtuple

from ..errors import ArgumentValueError

#: Words that draw, with their numeric arguments and what they draw.
SHAPES = {
    "line": ("X0 Y0 X1 Y1", "the segment from (X0, Y0) to (X1, Y1), both endpoints included"),
    "circle": ("XC YC R", "the circle of radius R about (XC, YC), by the midpoint algorithm"),
    "ellipse": ("XC YC RX RY", "the axis-aligned ellipse with semi-axes RX, RY about (XC, YC)"),
    "point": ("X Y", "the single pixel (X, Y)"),
    "rectangle": ("X0 Y0 X1 Y1", "the outline of the rectangle with corner pixels (X0, Y0) "
                  "and (X1, Y1), with the current line attributes"),
    "fill-rectangle": ("X0 Y0 X1 Y1", "the filled rectangle: every pixel from (X0, Y0) to "
                       "(X1, Y1), both included, in the current style"),
    "rounded-rectangle": ("X0 Y0 X1 Y1 R", "the outline of that rectangle with its corners "
                          "rounded by quarter circles of radius R"),
    "fill-rounded-rectangle": ("X0 Y0 X1 Y1 R", "the filled rounded rectangle"),
    "regular-polygon": ("XC YC R SIDES", "the outline of the regular polygon of SIDES sides "
                        "inscribed in the circle of radius R about (XC, YC), turned by the "
                        "current rotation (0: the bottom side horizontal)"),
    "fill-regular-polygon": ("XC YC R SIDES", "the filled regular polygon"),
    "polygon": ("X1 Y1 X2 Y2 X3 Y3 ...", "the polygon through the vertices, filled by the "
                "scan-line algorithm with the current rule and style (as many vertices as "
                "numbers follow)"),
    "fill-circle": ("XC YC R", "the filled circle: the midpoint outline and every pixel "
                    "between it on each scan line"),
    "fill-ellipse": ("XC YC RX RY", "the filled axis-aligned ellipse"),
    "arc": ("XC YC RX RY START END", "the part of the ellipse outline from angle START to "
            "END, counterclockwise, in degrees"),
    "chord": ("XC YC RX RY START END", "the area between that arc and the segment joining "
              "its ends"),
    "pie": ("XC YC RX RY START END", "the area between that arc and the two radii"),
    "flood": ("X Y", "flood fill: recolor the connected region of (X, Y)'s color"),
    "boundary": ("X Y", "boundary fill from (X, Y), stopping at the boundary color"),
    "soft": ("X Y FOREGROUND BACKGROUND", "soft (tint) fill from (X, Y): pixels that blend "
             "FOREGROUND over BACKGROUND are re-blended with the current color"),
    "polyline": ("X1 Y1 X2 Y2 ...", "the open polyline through the vertices, with the current "
                 "line attributes (as many vertices as numbers follow)"),
    "closed-polyline": ("X1 Y1 X2 Y2 ...", "the closed polyline (a polygon outline) through "
                        "the vertices, with the current line attributes"),
    "text": ("X Y STRING", "the characters of STRING (one word: quote it) placed on (X, Y) "
             "by the current align, in the current font, height and angle"),
}

#: Shapes drawn with the line attributes (width, cap, join, miter-limit, dash, pen,
#: antialias).
OUTLINES = ("line", "circle", "ellipse", "polyline", "closed-polyline", "rectangle",
            "rounded-rectangle", "regular-polygon")

#: Shape parameters that are colors, not numbers.
COLOR_PARAMS = ("FOREGROUND", "BACKGROUND")

#: Shape parameters taken as they are written (any word, even an item's name).
STRING_PARAMS = ("STRING",)

#: Shapes that fill an area, and so take the current style.
AREAS = ("polygon", "fill-circle", "fill-ellipse", "chord", "pie", "fill-rectangle",
         "fill-rounded-rectangle", "fill-regular-polygon")

#: Words that set an attribute of the items after them, with their argument.
SETTINGS = {
    "color": ("NAME", "the color of the following items (default: white on a dark "
              "background, black on a light one): a name such as "
              "red, #rrggbb, or an integer (a gray level in mode L, a bit in mode 1, "
              "a color-table index in mode P)"),
    "method": ("dda|bresenham", "the line algorithm of the following lines (default bresenham)"),
    "rule": ("even-odd|nonzero", "the inside-outside rule of the following polygons "
             "(default: --rule)"),
    "style": ("STYLE", "the fill style of the following areas: solid, hollow, "
              "pattern:NAME[:shape] (NAME checker, dots, diagonal, grid or bricks), "
              "hatch:DEG[:SPACING[:WIDTH]] or crosshatch:DEG[:SPACING[:WIDTH]]"),
    "connectivity": ("4|8", "the connectivity of the following flood and boundary fills "
                     "(default 4)"),
    "boundary-color": ("COLOR", "the boundary color of the following boundary fills "
                       "(default: the default color)"),
    "tolerance": ("N", "the largest channel difference from the seed's color that the "
                  "following flood fills still recolor (default 0)"),
    "width": ("W", "the line width of the following lines, circles, ellipses and polylines "
              "in pixels, >= 1, fractions allowed (default 1)"),
    "cap": ("butt|round|square", "the ends of the following thick lines (default butt)"),
    "join": ("miter|round|bevel", "the corners of the following thick polylines (default "
             "miter)"),
    "miter-limit": ("N", "miters longer than N times the width become bevels (default 10)"),
    "dash": ("TYPE", "the line type: solid, dashed, dotted, dash-dot, a 16-bit pixel mask "
             "such as 0b1111000011110000, or dash,gap lengths in pixels such as 6,3"),
    "dash-phase": ("N", "where the line type starts: pixels into a mask, pixels of length "
                   "into dash lengths (default 0)"),
    "pen": ("none|square|circle", "a pen footprint, a width x width square or a disc "
            "(circle, also called round) of diameter width, stamped at every pixel of the "
            "following lines (default none)"),
    "antialias": ("on|off", "antialiased lines, circles, ellipses, polylines and text "
                  "(default off)"),
    "font": ("NAME", "the font of the following text: sans (default), bitmap, stroke, a "
             ".ttf/.otf file or an installed font's family name such as 'DejaVu Serif' "
             "(quoted: one word)"),
    "rotation": ("DEG", "the rotation of the following regular polygons, degrees "
                 "counterclockwise (default 0)"),
    "height": ("H", "the character (cap) height of the following text in pixels (default: "
               "the font's own, 10 for sans)"),
    "angle": ("DEG", "the baseline direction of the following text, degrees counterclockwise "
              "(default 0)"),
    "align": ("H,V", "which point of the following text lies on (X, Y): H left, center or "
              "right, V top, cap, half, base or bottom (default left,base)"),
}

#: Settings that are text attributes: SETTINGS word -> TextStyle field.
TEXT_SETTINGS = {"font": "font", "height": "height", "angle": "angle", "align": "align"}

#: Settings that are line attributes: SETTINGS word -> LineStyle field.
LINE_SETTINGS = {"width": "width", "cap": "cap", "join": "join", "miter-limit": "miter_limit",
                 "dash": "dash", "dash-phase": "dash_phase", "pen": "pen"}

#: scanline.framebuffer.MODES, spelled out so that --help does not import numpy.
MODES = ("1", "L", "RGB", "RGBA", "P")

#: One parsed item: ``word``, its ``args`` (numbers, or one string for a setting),
#: ``position``, the 1-based index of the word in ITEMS, and ``text``, the item as
#: written (for messages).
Item = namedtuple("Item", "word args position text")


def _epilog():
    """The --help text of the ITEMS language, made from SHAPES and SETTINGS."""
    rows = [(f"{word} {params}", text) for word, (params, text) in {**SHAPES, **SETTINGS}.items()]
    width = max(len(head) for head, _ in rows) + 4
    lines = [textwrap.fill(text, 79, initial_indent=f"  {head}".ljust(width),
                           subsequent_indent=" " * width) for head, text in rows]
    return "\n".join([
        "ITEMS, drawn in order (x to the right, y up, (0, 0) the bottom-left pixel;",
        "numbers may be negative or fractional and round to the nearest pixel; what",
        "falls outside the image is clipped):",
        *lines,
        "",
        "Examples:",
        "  scanline draw --size 64x48 line 2 3 60 40 circle 32 24 15 -o out.png",
        "  scanline draw --size 64x64 --rule nonzero color gold \\",
        "      polygon 32 60 13 4 62 40 2 40 51 4 -o star.png",
        "  scanline draw --size 64x64 style crosshatch:45:6 color red fill-circle 32 32 25 \\",
        "      style solid color blue pie 32 32 20 20 0 90 -o pie.png",
        "  scanline draw circle 64 64 30 color green flood 64 64 -o disk.png",
        "  scanline draw --size 64x48 width 5 cap round join round dash 12,6 \\",
        "      polyline 5 5 30 40 58 10 -o strokes.png",
        "  scanline draw --size 64x48 color navy fill-rounded-rectangle 4 4 59 43 8 \\",
        "      color gold width 2 regular-polygon 32 24 14 5 -o badge.png",
        "  scanline draw --size 160x40 font stroke height 12 align center,half \\",
        "      text 80 20 'Hello, world' -o text.png",
        "  scanline draw --scale 4 color red method dda line -5 3 40 20 \\",
        "      color '#00a0ff' ellipse 20 12 15 8 -o out.gif",
    ])


def size(text):
    """argparse type: ``WIDTHxHEIGHT`` such as ``64x48``."""
    match = re.fullmatch(r"\s*(\d+)\s*[xX]\s*(\d+)\s*", text)
    if not match:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT such as 64x48, got {text!r}")
    return int(match[1]), int(match[2])


def positive_int(text):
    """argparse type: an integer >= 1."""
    try:
        value = int(text)
    except ValueError:
        value = None
    if value is None or value < 1:
        raise argparse.ArgumentTypeError(f"expected an integer >= 1, got {text!r}")
    return value


def register(subparsers):
    """Add the ``draw`` command."""
    parser = subparsers.add_parser(
        "draw", help="draw lines, polylines, circles, ellipses, polygons, rectangles, "
        "fills, points and text, with their attributes, into a PNG, GIF or BMP",
        description="Draw ITEMS into a frame buffer and save it; the extension of OUT\n"
        "(.png, .jpg, .webp, .tif, .gif, .bmp ...) picks the format.  Options may come before or after ITEMS.",
        epilog=_epilog(), formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("items", metavar="ITEMS", nargs="+", help="what to draw (see below)")
    parser.add_argument("-o", "--output", metavar="OUT", required=True,
                        help="the image file to write: any format Pillow writes (.png, .jpg, "
                        ".webp, .tif, .gif, .bmp ...)")
    parser.add_argument("--size", metavar="WxH", type=size, default=(128, 128),
                        help="width x height in pixels (default 128x128)")
    parser.add_argument("--mode", choices=MODES, default="RGB",
                        help="pixel format: 1 (bitmap), L (gray), RGB (default), RGBA, "
                        "P (color table)")
    parser.add_argument("--background", metavar="COLOR", default="black",
                        help="background color (default black)")
    parser.add_argument("--scale", metavar="N", type=positive_int, default=1,
                        help="enlarge each pixel to an N x N block in the saved image")
    parser.add_argument("--rule", choices=("even-odd", "nonzero"), default="even-odd",
                        help="inside-outside rule of polygons (default even-odd)")
    parser.set_defaults(run=run)


def _number(text):
    """``text`` as an int or float, or None if it is not a number."""
    for convert in (int, float):
        try:
            return convert(text)
        except ValueError:
            pass
    return None


def _color(text):
    """A color argument: an integer literal is an int (gray level, bit or index)."""
    try:
        return int(text)
    except ValueError:
        return text


def parse_items(words):
    """Parse the ITEMS words into a list of :class:`Item`.

    Raises :class:`~scanline.errors.ArgumentValueError` naming the word's position
    when a word is unknown, or an argument is missing or is not a number.

    >>> [item[:3] for item in parse_items(["color", "red", "circle", "1", "2", "-3.5"])]
    [('color', ('red',), 1), ('circle', (1, 2, -3.5), 3)]
    """
    keywords = {**SHAPES, **SETTINGS}
    items = []
    i = 0
    while i < len(words):
        word, position = words[i], i + 1
        if word not in keywords:
            if items and _number(word) is not None:
                hint = f"{items[-1].text!r} takes only {keywords[items[-1].word][0]}"
            else:
                hint = f"use one of {', '.join(keywords)}"
            raise ArgumentValueError(f"ITEMS word {position}: unexpected {word!r}; {hint}")
        params = keywords[word][0].split()
        if params[-1] == "...":  # as many numbers as follow
            params = params[:-1]
            count = next((k for k, text in enumerate(words[i + 1:]) if _number(text) is None),
                         len(words) - i - 1)
            params = (params * (count // len(params) + 1))[:max(count, len(params))]
        given = []
        for text in words[i + 1:i + 1 + len(params)]:
            if text in keywords and params[len(given)] not in STRING_PARAMS \
                    and "|" not in params[len(given)]:   # a word of a|b|c may be a shape's name
                break
            given.append(text)
        if len(given) < len(params):
            raise ArgumentValueError(f"ITEMS word {position}: {word} needs {keywords[word][0]}, "
                                     f"got only {' '.join([word, *given])!r}")
        if word in SETTINGS:
            args = (_color(given[0]),) if word in ("color", "boundary-color") else (given[0],)
        else:
            args = tuple(_color(text) if param in COLOR_PARAMS else
                         text if param in STRING_PARAMS else _number(text)
                         for param, text in zip(params, given))
            for j, (param, value) in enumerate(zip(params, args)):
                if value is None:
                    raise ArgumentValueError(f"ITEMS word {position + 1 + j}: {param} of {word} "
                                             f"must be a number, got {given[j]!r}")
        items.append(Item(word, args, position, " ".join([word, *given])))
        i += 1 + len(params)
    return items


def _degrees(args):
    """The CLI's arc items give angles in degrees; the API takes radians."""
    import math

    return (*args[:4], math.radians(args[4]), math.radians(args[5]))


def render(items, width, height, mode="RGB", background="black", rule="even-odd"):
    """Draw ``items`` into a new frame buffer and return it.

    Colors start white, lines with Bresenham's method, areas solid, fills
    4-connected.  An error from the drawing functions is raised again naming the item.
    """
    from .. import _validate, draw
    from ..attributes import FillStyle, LineStyle
    from ..draw.lines import METHODS
    from ..framebuffer import FrameBuffer
    from ..text import TextStyle

    fb = FrameBuffer(width, height, mode=mode, background=background)
    state = {"color": None, "method": "bresenham", "rule": rule, "style": None,
             "connectivity": 4, "boundary-color": None, "tolerance": 0,
             "line": LineStyle(), "antialias": False, "text": TextStyle(), "rotation": 0.0}
    for item in items:
        try:
            if item.word in SETTINGS:
                value = item.args[0]
                if item.word in ("color", "boundary-color"):
                    fb.pixel(value)  # check it here, where it is given
                elif item.word == "method":
                    _validate.choice("method", value, tuple(METHODS))
                elif item.word == "rule":
                    _validate.choice("rule", value, ("even-odd", "nonzero"))
                elif item.word == "style":
                    value = FillStyle.parse(value)
                elif item.word in LINE_SETTINGS:
                    state["line"] = _line_style(state["line"], item.word, value)
                    continue
                elif item.word in TEXT_SETTINGS:
                    state["text"] = _text_style(state["text"], item.word, value)
                    continue
                elif item.word == "antialias":
                    value = _validate.choice("antialias", value, ("on", "off")) == "on"
                elif item.word == "tolerance":
                    value = _validate.positive_int("tolerance", _number(value), minimum=0)
                elif item.word == "rotation":
                    value = _degree_setting("rotation", value)
                else:  # connectivity
                    value = int(_validate.choice("connectivity", value, ("4", "8")))
                state[item.word] = value
            else:
                _draw(fb, item, state, draw)
        except (ValueError, TypeError) as exc:
            raise ArgumentValueError(
                f"ITEMS word {item.position} ({item.text}): {exc}") from exc
    return fb


def _degree_setting(word, text):
    """A setting in degrees (``rotation DEG``) as radians."""
    import math

    value = _number(text)
    if value is None:
        raise ArgumentValueError(f"{word} must be a number of degrees, got {text!r}")
    return math.radians(value)


def _line_style(style, word, text):
    """``style`` with the line attribute of setting ``word`` changed to ``text``."""
    from ..attributes import LineStyle

    field = LINE_SETTINGS[word]
    if field in ("width", "miter_limit", "dash_phase"):
        value = _number(text)
        if value is None:
            raise ArgumentValueError(f"{word} must be a number, got {text!r}")
    elif field == "dash":
        value = LineStyle.parse_dash(text)
    elif field == "pen":
        value = None if text == "none" else text      # LineStyle knows the pen names
    else:
        value = text
    return LineStyle(**{**_fields(style), field: value})


def _text_style(style, word, text):
    """``style`` with the text attribute of setting ``word`` changed to ``text``."""
    import math

    if word in ("height", "angle"):
        value = _number(text)
        if value is None:
            raise ArgumentValueError(f"{word} must be a number, got {text!r}")
        return style.replace(**{word: math.radians(value) if word == "angle" else value})
    if word == "font":
        from ..text import font

        font(text)  # an unknown font is reported here, where it is named
    return style.replace(**{TEXT_SETTINGS[word]: text})


def _fields(style):
    return {name: getattr(style, name) for name in
            ("width", "cap", "join", "miter_limit", "dash", "dash_phase", "pen")}


def _draw(fb, item, state, draw):
    """Draw one shape item with the current settings."""
    word, args, color = item.word, item.args, state["color"]
    lines = {"style": state["line"], "antialias": state["antialias"]}
    if word == "line":
        draw.line(fb, *args, color=color, method=state["method"], **lines)
    elif word == "point":
        draw.point(fb, *args, color=color)
    elif word in ("rectangle", "rounded-rectangle"):
        getattr(draw, word.replace("-", "_"))(fb, *args, color=color, **lines)
    elif word in ("fill-rectangle", "fill-rounded-rectangle"):
        getattr(draw, word[5:].replace("-", "_"))(fb, *args, color=color, fill=True,
                                                  fill_style=state["style"])
    elif word in ("regular-polygon", "fill-regular-polygon"):
        xc, yc, r, sides = args
        if sides != int(sides):
            raise ArgumentValueError(f"SIDES must be a whole number, got {sides}")
        shape = dict(fill=True, fill_style=state["style"]) if word.startswith("fill") else lines
        draw.regular_polygon(fb, xc, yc, r, int(sides), state["rotation"], color=color, **shape)
    elif word in ("circle", "ellipse"):
        getattr(draw, word)(fb, *args, color=color, **lines)
    elif word in ("polyline", "closed-polyline"):
        if len(args) % 2:
            raise ArgumentValueError(f"{word} needs x y pairs, got {len(args)} numbers")
        points = [args[k:k + 2] for k in range(0, len(args), 2)]
        draw.polyline(fb, points, color=color, closed=word == "closed-polyline", **lines)
    elif word == "polygon":
        if len(args) % 2:
            raise ArgumentValueError(f"polygon needs x y pairs, got {len(args)} numbers")
        points = [args[k:k + 2] for k in range(0, len(args), 2)]
        draw.polygon(fb, points, color=color, rule=state["rule"], style=state["style"])
    elif word in ("fill-circle", "fill-ellipse"):
        getattr(draw, word.replace("-", "_"))(fb, *args, color=color, style=state["style"])
    elif word == "arc":
        draw.arc(fb, *_degrees(args), color=color)
    elif word in ("chord", "pie"):
        getattr(draw, word)(fb, *_degrees(args), color=color, style=state["style"])
    elif word == "flood":
        draw.flood_fill(fb, *args, color, connectivity=state["connectivity"],
                        tolerance=state["tolerance"])
    elif word == "soft":
        draw.soft_fill(fb, *args[:2], color, *args[2:], connectivity=state["connectivity"])
    elif word == "text":
        draw.text(fb, *args, color=color, style=state["text"], antialias=state["antialias"])
    else:  # boundary
        draw.boundary_fill(fb, *args, color, boundary=state["boundary-color"],
                           connectivity=state["connectivity"])


def run(args):
    """Parse the items, draw them and save the image atomically."""
    from ..framebuffer import check_image_size

    items = parse_items(args.items)
    w, h = args.size
    check_image_size(w, h, args.scale, f"--size {w}x{h}"
                     + (f" with --scale {args.scale}" if args.scale > 1 else ""))
    fb = render(items, *args.size, mode=args.mode, background=args.background, rule=args.rule)
    try:
        fb.save(args.output, scale=args.scale)
    except ValueError as exc:
        raise ArgumentValueError(f"-o/--output: {exc}") from exc
