"""Hostile input files, generated (nothing is downloaded): fonts, scene files,
images and mesh files (FIFOs, links to /dev/zero, PLY headers that never end or
announce absurd counts, OBJ indices beyond int64) built to break a careless reader.

Run as a script to write them all into a folder (``python -m tests.fuzz.hostile_files
DIR``); the tests call the functions.
"""

import functools
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


# -- mesh files and the scenes that name them (sl.mesh.load, a scene's `file =` key) --------
def mesh_fifo(path):
    """A FIFO named like a mesh file (``x.obj``): opening it for reading blocks until
    a writer comes, unless the reader opens it without blocking."""
    os.mkfifo(path)
    return path


def mesh_link_to_dev_zero(path):
    """A symbolic link named like a mesh file to /dev/zero: endless zero bytes (a
    careless reader follows it to gigabytes)."""
    os.symlink("/dev/zero", path)
    return path


def ply_without_end_header(path, comments=0):
    """A PLY header that never ends (``comments`` comment lines after it: more than
    the header may take)."""
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                "property float y\nproperty float z\n" + "comment x\n" * comments)
    return path


def ply_with_huge_counts(path, vertices=10**11, faces=2**64, binary=False):
    """A short PLY file whose header announces far more elements than it holds."""
    fmt = "binary_little_endian" if binary else "ascii"
    with open(path, "wb") as f:
        f.write((f"ply\nformat {fmt} 1.0\nelement vertex {vertices}\nproperty float x\n"
                 f"property float y\nproperty float z\nelement face {faces}\n"
                 "property list uchar int vertex_indices\nend_header\n").encode()
                + (b"\0" * 36 if binary else b"0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"))
    return path


def obj_with_a_huge_index(path, index=2**63):
    """A triangle whose third index is ``index`` (2**63: beyond int64)."""
    with open(path, "w") as f:
        f.write(f"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 {index}\n")
    return path


def stl_with_a_huge_count(path):
    """A binary STL header announcing 2**32 - 1 triangles, with one."""
    with open(path, "wb") as f:
        f.write(b"\0" * 80 + (2**32 - 1).to_bytes(4, "little") + b"\0" * 50)
    return path


def scene_with_a_mesh_file(path, mesh_file="fifo.obj", size=40):
    """A version-2 scene whose one mesh primitive is ``file = mesh_file`` (relative
    to the scene's folder)."""
    with open(path, "w") as f:
        f.write(f"version = 2\n[canvas]\nwidth = {size}\nheight = {size}\n"
                "[[cameras]]\neye = [3, 2, 4]\ntarget = [0, 0, 0]\n"
                "[[segments]]\nname = \"m\"\nprimitives = [{type = \"mesh\", file = "
                + json.dumps(mesh_file) + "}]\n")
    return path


def scene_with_many_spheres(path, count=200, resolution=1024):
    """``count`` spheres at ``resolution`` (each within the per-mesh limit): the
    scene's total must be checked, not only each mesh."""
    sphere = f'{{type = "mesh", generator = "sphere", resolution = {resolution}}}'
    with open(path, "w") as f:
        f.write("version = 2\n[canvas]\nwidth = 40\nheight = 40\n"
                "[[cameras]]\neye = [3, 2, 4]\ntarget = [0, 0, 0]\n"
                "[[segments]]\nname = \"m\"\nprimitives = [\n"
                + ",\n".join([sphere] * count) + "\n]\n")
    return path


def scene_huge_3d_canvas(path, size=13000):
    """About 400 bytes asking for a size x size canvas with 3-D surfaces (a z-buffer
    of 12 bytes a pixel besides the frame buffer)."""
    with open(path, "w") as f:
        f.write(f"version = 2\n[canvas]\nwidth = {size}\nheight = {size}\n"
                "[[cameras]]\neye = [3, 2, 4]\ntarget = [0, 0, 0]\n"
                "[materials.m]\ncolor = \"red\"\n"
                "[[segments]]\nname = \"m\"\nprimitives = [{type = \"mesh\", "
                "generator = \"cube\", material = \"m\"}]\n")
    return path


def _scene_naming(mesh_file, path):
    return scene_with_a_mesh_file(path, mesh_file)


#: The hostile mesh files, by name (the scene files below name them).
MESH_FILES = {
    "fifo.obj": mesh_fifo,
    "fifo.ply": mesh_fifo,
    "fifo.stl": mesh_fifo,
    "zero.obj": mesh_link_to_dev_zero,
    "zero.stl": mesh_link_to_dev_zero,
    "no-end-header.ply": ply_without_end_header,
    "long-header.ply": lambda path: ply_without_end_header(path, comments=20000),
    "huge-counts.ply": ply_with_huge_counts,
    "huge-counts-binary.ply": lambda path: ply_with_huge_counts(path, binary=True),
    "index-2-63.obj": obj_with_a_huge_index,
    "index-2-64.obj": lambda path: obj_with_a_huge_index(path, 2**64),
    "index-minus-2-63.obj": lambda path: obj_with_a_huge_index(path, -2**63),
    "huge-count.stl": stl_with_a_huge_count,
}


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
    **MESH_FILES,
    **{f"scene-{name}.toml": functools.partial(_scene_naming, name) for name in MESH_FILES},
    "many-spheres.toml": scene_with_many_spheres,
    "huge-3d-canvas.toml": scene_huge_3d_canvas,
}


if __name__ == "__main__":
    folder = sys.argv[1] if len(sys.argv) > 1 else "hostile"
    os.makedirs(folder, exist_ok=True)
    for name, make in ALL.items():
        print(make(os.path.join(folder, name)))
