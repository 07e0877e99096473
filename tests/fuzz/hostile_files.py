"""Hostile input files, generated (nothing is downloaded): fonts, scene files and
images built to break a careless reader.

Run as a script to write them all into a folder (``python -m tests.fuzz.hostile_files
DIR``); the tests call the functions.
"""

import json
import os
import struct
import sys
import zlib

from fontTools.fontBuilder import FontBuilder
from fontTools.pens.ttGlyphPen import TTGlyphPen
from fontTools.ttLib.tables._g_l_y_f import Glyph, GlyphComponent


def _font(path, units_per_em, glyphs, cmap, recalc=True):
    """A TrueType font with ``glyphs`` ({name: Glyph}), ``.notdef`` first
    (``recalc=False``: keep fontTools from summing up maxp's composite counts, which
    overflow for the nested font)."""
    order = list(glyphs)
    fb = FontBuilder(units_per_em, isTTF=True)
    fb.setupGlyphOrder(order)
    fb.setupCharacterMap(cmap)
    fb.setupGlyf(glyphs)
    fb.setupHorizontalMetrics({name: (units_per_em, 0) for name in order})
    fb.setupHorizontalHeader(ascent=units_per_em, descent=-units_per_em // 4)
    fb.setupNameTable({"familyName": "Hostile", "styleName": "Regular"})
    fb.setupOS2(sCapHeight=units_per_em * 7 // 10, sxHeight=units_per_em // 2)
    fb.setupPost()
    if not recalc:
        maxp = fb.font["maxp"]
        maxp.recalc = lambda font: None
        for name, glyph in glyphs.items():
            if glyph.isComposite():
                glyph.xMin = glyph.yMin = 0
                glyph.xMax, glyph.yMax = 500, 700
    fb.save(path)
    return path


def _box(x0, y0, x1, y1):
    """A rectangle, with midpoints so that no step between points exceeds the int16
    deltas of the glyf table."""
    xm, ym = (x0 + x1) // 2, (y0 + y1) // 2
    pen = TTGlyphPen(None)
    pen.moveTo((x0, y0))
    for p in ((xm, y0), (x1, y0), (x1, ym), (x1, y1), (xm, y1), (x0, y1), (x0, ym)):
        pen.lineTo(p)
    pen.closePath()
    return pen.glyph()


def font_with_far_points(path):
    """unitsPerEm 16 and a glyph 'A' whose outline reaches 32767 units (2048 em) right, up and down:
    a careless glyph cache allocates a bitmap of its bounding box."""
    return _font(path, 16, {".notdef": _box(0, 0, 8, 10), "A": _box(0, -32767, 32767, 32767)},
                 {ord("A"): "A"})


def font_with_nested_composites(path, depth=24, copies=2):
    """Glyph 'A' is a composite of ``copies`` copies of g1, each of g2, ... down to
    a box at level ``depth``: copies**depth boxes once resolved."""
    glyphs = {".notdef": _box(0, 0, 500, 700)}
    names = [f"g{i}" for i in range(1, depth + 1)]
    for i, name in enumerate(["A"] + names[:-1]):
        g = Glyph()
        g.numberOfContours = -1
        g.components = []
        for k in range(copies):
            c = GlyphComponent()
            c.glyphName = names[i]
            c.x, c.y, c.flags = k, 0, 0
            g.components.append(c)
        glyphs[name] = g
    glyphs[names[-1]] = _box(0, 0, 500, 700)
    return _font(path, 1000, glyphs, {ord("A"): "A"}, recalc=False)


def font_truncated(path):
    """A real font cut in half."""
    full = font_with_far_points(path + ".full")
    data = open(full, "rb").read()
    os.unlink(full)
    with open(path, "wb") as f:
        f.write(data[: len(data) // 2])
    return path


def scene_with_a_big_string(path, megabytes=8):
    """A valid TOML scene whose one error (a bad color) sits beside a huge string:
    locating the error must stay linear in memory."""
    text = ("version = 1\n[[segments]]\nname = \"s\"\n[[segments.primitives]]\n"
            "type = \"text\"\nposition = [1, 1]\nstring = \"" + "x" * (megabytes << 20) + "\"\n"
            "color = \"no-such-color\"\n")
    with open(path, "w") as f:
        f.write(text)
    return path


def scene_with_a_long_integer(path, digits=5000):
    with open(path, "w") as f:
        f.write("version = 1\n[canvas]\nwidth = " + "9" * digits + "\n")
    return path


def scene_with_a_bom(path):
    with open(path, "wb") as f:
        f.write(b"\xef\xbb\xbfversion = 1\n[canvas]\nwidth = 20\nheight = 10\n")
    return path


def scene_with_boolean_points(path):
    data = {"version": 1, "segments": [{"name": "s", "primitives": [
        {"type": "polyline", "points": [[True, False], [3, 4]]}]}]}
    with open(path, "w") as f:
        json.dump(data, f)
    return path


def scene_nested_deeply(path, depth=100_000):
    with open(path, "w") as f:
        f.write('{"version": 1, "x": ' + "[" * depth + "]" * depth + "}")
    return path


def scene_huge_canvas(path, size=16384):
    with open(path, "w") as f:
        f.write(f"version = 1\n[canvas]\nwidth = {size}\nheight = {size}\n")
    return path


def png_bomb(path, side=65535):
    """A PNG that claims side x side pixels (a decompression bomb: a few kB on disk)."""
    def chunk(tag, data):
        return (struct.pack(">I", len(data)) + tag + data
                + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))
    raw = zlib.compress(b"\0" * (side + 1) * 16, 9)   # the first rows only
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", side, side, 8, 0, 0, 0, 0))
                + chunk(b"IDAT", raw) + chunk(b"IEND", b""))
    return path


def garbage(path, size=4096, seed=0):
    import random
    with open(path, "wb") as f:
        f.write(random.Random(seed).randbytes(size))
    return path


ALL = {
    "far-points.ttf": font_with_far_points,
    "nested-composites.ttf": font_with_nested_composites,
    "truncated.ttf": font_truncated,
    "garbage.ttf": garbage,
    "big-string.toml": scene_with_a_big_string,
    "long-integer.toml": scene_with_a_long_integer,
    "bom.toml": scene_with_a_bom,
    "boolean-points.json": scene_with_boolean_points,
    "deep.json": scene_nested_deeply,
    "huge-canvas.toml": scene_huge_canvas,
    "bomb.png": png_bomb,
    "garbage.png": garbage,
}


if __name__ == "__main__":
    folder = sys.argv[1] if len(sys.argv) > 1 else "hostile"
    os.makedirs(folder, exist_ok=True)
    for name, make in ALL.items():
        print(make(os.path.join(folder, name)))
