"""Outline fonts: metrics against fontTools' tables, filled glyphs against the exact
outline area (fontTools' AreaPen) and against FreeType (Pillow), CFF outlines."""

import numpy as np
import pytest
from fontTools.fontBuilder import FontBuilder
from fontTools.pens.areaPen import AreaPen
from fontTools.pens.t2CharStringPen import T2CharStringPen
from fontTools.ttLib import TTFont
from PIL import Image, ImageDraw, ImageFont

import scanline as sl
from scanline.text import catalog

TTF = str(catalog.DATA / "DejaVuSans.ttf")


@pytest.fixture(scope="module")
def ft():
    return TTFont(TTF)


def cap_height(ft):
    return ft["glyf"]["H"].yMax          # DejaVu's OS/2 table (version 1) has none


def test_sans_is_the_shipped_dejavu_with_its_license():
    text = (catalog.DATA / "DejaVuSans-LICENSE.txt").read_text()
    assert "Bitstream" in text and "Permission is hereby granted, free of charge" in text
    f = sl.text.fonts()["sans"]
    assert f.kind == "outline" and f.glyph_count == len(TTFont(TTF).getGlyphOrder())


def test_advances_are_hmtx_scaled(ft):
    text = "AVWAY To, fi 0.5%"
    height = 37.0
    scale = height / cap_height(ft)
    cmap = ft.getBestCmap()
    adv = [ft["hmtx"][cmap[ord(c)]][0] * scale for c in text]
    e = sl.text.extents(text, font="sans", height=height)
    assert e.width == pytest.approx(sum(adv), rel=1e-12)
    glyphs = sl.text.layout(text, 100.25, 50, font="sans", height=height)
    expected_x = np.floor(100.25 + np.concatenate([[0], np.cumsum(adv)[:-1]]) + 0.5)
    assert [g.origin[0] for g in glyphs] == expected_x.astype(int).tolist()
    assert e.advance == pytest.approx((100.0 * 0 + sum(adv), 0.0))


def test_vertical_metrics_are_hhea_scaled(ft):
    height = 20.0
    scale = height / cap_height(ft)
    e = sl.text.extents("x", font="sans", height=height)
    assert e.box[1] == pytest.approx(ft["hhea"].descent * scale)
    assert e.box[3] == pytest.approx(ft["hhea"].ascent * scale)
    two = sl.text.layout("a\nb", 0, 0, font="sans", height=height)
    step = (ft["hhea"].ascent - ft["hhea"].descent + ft["hhea"].lineGap) * scale
    assert two[1].origin[1] == np.floor(-step + 0.5)


@pytest.mark.parametrize("char", ["O", "g", "&", "8", "@", "B"])
def test_filled_pixels_match_the_exact_outline_area(ft, char):
    gs = ft.getGlyphSet()
    pen = AreaPen(gs)
    gs[ft.getBestCmap()[ord(char)]].draw(pen)
    height = 150.0
    scale = height / cap_height(ft)
    area = abs(pen.value) * scale ** 2
    fb = sl.FrameBuffer(260, 260, mode="1")
    sl.draw.text(fb, 20.0, 60.0, char, font="sans", height=height)
    count = int(fb.to_array().sum())
    assert count == pytest.approx(area, rel=0.01)


def test_antialiased_coverage_sums_to_the_area(ft):
    gs = ft.getGlyphSet()
    pen = AreaPen(gs)
    gs["R"].draw(pen)
    height = 60.0
    area = abs(pen.value) * (height / cap_height(ft)) ** 2
    fb = sl.FrameBuffer(100, 100, mode="L")
    sl.draw.text(fb, 10.3, 20.6, "R", font="sans", height=height, antialias=True,
                 color=255)
    values = fb.to_array().astype(float)
    assert ((values > 0) & (values < 255)).any()
    assert values.sum() / 255 == pytest.approx(area, rel=0.02)


def iou_best_shift(a, b):
    best = 0.0
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            s = np.roll(np.roll(b, dy, 0), dx, 1)
            best = max(best, (a & s).sum() / (a | s).sum())
    return best


@pytest.mark.parametrize("char", list("Rag&8@Qy%"))
def test_glyphs_agree_with_freetype(char):
    """FreeType (through Pillow, hinted, one glyph at a time: their layouts round
    advances differently) and scanline's fill of the flattened outline.  At 200 px
    per em hinting moves edges by a fraction of a pixel: IoU 0.94 - 0.98 (at 96 px,
    0.85 - 0.95, thin features suffering most)."""
    em = 200
    W, H = 280, 280
    img = Image.new("1", (W, H), 0)
    draw = ImageDraw.Draw(img)
    draw.fontmode = "1"
    draw.text((20, 220), char, fill=1, font=ImageFont.truetype(TTF, em), anchor="ls")
    theirs = np.array(img, bool)
    fb = sl.FrameBuffer(W, H, mode="1")
    sl.draw.text(fb, 20, H - 1 - 220, char, font="sans", height=em * 1493 / 2048)
    ours = fb.to_array()
    assert iou_best_shift(theirs, ours) > 0.93
    assert ours.sum() == pytest.approx(theirs.sum(), rel=0.03)


def build_cff(path):
    """A CFF (cubic) OpenType font: "O" a ring of cubic arcs, "I" a bar."""
    fb = FontBuilder(1000, isTTF=False)
    fb.setupGlyphOrder([".notdef", "O", "I"])
    fb.setupCharacterMap({ord("O"): "O", ord("I"): "I"})
    k = 0.5522847498
    strings = {}
    for name in (".notdef", "O", "I"):
        pen = T2CharStringPen(600, None)
        if name == "O":
            for r, turn in ((300, 1), (200, -1)):   # outer ccw, inner cw
                cx, cy = 300, 350
                pts = [(cx + r, cy), (cx, cy + turn * r), (cx - r, cy), (cx, cy - turn * r)]
                pen.moveTo(pts[0])
                for i in range(4):
                    p0, p1 = pts[i], pts[(i + 1) % 4]
                    c0 = (p0[0] + k * (p1[0] - cx) * 1, p0[1] + k * (p1[1] - cy))
                    c1 = (p1[0] + k * (p0[0] - cx), p1[1] + k * (p0[1] - cy))
                    pen.curveTo(c0, c1, p1)
                pen.closePath()
        elif name == "I":
            pen.moveTo((100, 0))
            pen.lineTo((200, 0))
            pen.lineTo((200, 700))
            pen.lineTo((100, 700))
            pen.closePath()
        strings[name] = pen.getCharString()
    fb.setupCFF("Test", {"FullName": "Test"}, strings, {})
    fb.setupHorizontalMetrics({n: (600, 0) for n in (".notdef", "O", "I")})
    fb.setupHorizontalHeader(ascent=800, descent=-200)
    fb.setupNameTable({"familyName": "Test", "styleName": "Regular"})
    fb.setupOS2(sTypoAscender=800, usWinAscent=800, usWinDescent=200, sCapHeight=700,
                sxHeight=500, version=2)
    fb.setupPost()
    fb.save(str(path))


def test_cff_cubic_outlines(tmp_path):
    path = tmp_path / "test.otf"
    build_cff(path)
    font = sl.text.load_font(path)
    assert font.cap_height == 700 and font.glyph_count == 3
    scale = 140 / 700
    fb = sl.FrameBuffer(200, 200, mode="1")
    sl.draw.text(fb, 10, 10, "O", font=font, height=140)
    ring = np.pi * (300 ** 2 - 200 ** 2) * scale ** 2
    assert fb.to_array().sum() == pytest.approx(ring, rel=0.01)
    fb.clear()
    sl.draw.text(fb, 10, 10, "I", font=str(path), height=140)
    assert fb.to_array().sum() == 20 * 140      # a 20 x 140 pixel bar, exactly
