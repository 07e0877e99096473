"""
Character generation and text attributes
========================================

Figures of ``scanline demo`` for character generation and text attributes
(:mod:`scanline.text`, :func:`scanline.draw.text`)."""

import math

import scanline as sl

from scanline.gallery._plot import GraphPaper, enlarge, side_by_side, stacked
from scanline.gallery.primitives import Figure

INK = "#2b4c8c"
MARK = "#e15759"
PAPER = "white"


def _mark(fb, x, y):
    """A small red cross on the reference point."""
    sl.draw.lines(fb, [(x - 3, y, x + 3, y), (x, y - 3, x, y + 3)], color=MARK)


def figure_fonts():
    """The three kinds of font: dot matrix, strokes, outlines."""
    text = "Raster & vector: Ag5?"
    panels, titles = [], []
    fb = sl.FrameBuffer(130, 12, background=PAPER)
    sl.draw.text(fb, 1, 2, text, font="bitmap", color=INK)
    panels.append(enlarge(fb.to_pil(), 4))
    titles.append("bitmap: 5 x 7 dots (enlarged 4x)")
    rows = [side_by_side(panels, titles)]
    panels, titles = [], []
    for font, aa, title in (("stroke", False, "stroke: polylines drawn as lines"),
                            ("sans", False, "outline: DejaVu Sans, scan-line fill"),
                            ("sans", True, "outline, antialiased")):
        box = sl.text.extents(text, font=font, height=10).box       # the string's own width
        fb = sl.FrameBuffer(math.ceil(box[2]) + 6, 24, background=PAPER)
        sl.draw.text(fb, 2, 6, text, font=font, height=10, color=INK, antialias=aa)
        panels.append(enlarge(fb.to_pil(), 3))
        titles.append(title)
    rows += [side_by_side(panels[:1], titles[:1]), side_by_side(panels[1:], titles[1:])]
    glyph = sl.text.layout("g", 0, 0, font="sans", height=60)[0]
    points = sum(len(c) for c in glyph.contours)
    return Figure(
        "fonts", "Character generation: bitmap, stroke and outline fonts",
        "One string in the three kinds of font scanline ships. The dot-matrix font "
        "stores each character as a 5 x 7 grid of dots (descenders hang two rows below "
        "the baseline); the stroke font as polylines on a small grid, drawn with line "
        "segments as a vector display or plotter would; the outline font (DejaVu Sans, "
        "read with fontTools) as quadratic Bezier contours, flattened within 0.2 px and "
        f"filled by the scan-line fill with the nonzero rule (a 60 px 'g' becomes "
        f"{len(glyph.contours)} contours of {points} points). Antialiased, each pixel "
        "gets the covered fraction of the color.",
        "Notes, syllabus: Character generation; Hearn & Baker, section 3-14",
        stacked(rows), None)


def figure_text_attributes():
    """Height, expansion, spacing, orientation, text path and alignment."""
    panels, titles = [], []
    fb = sl.FrameBuffer(220, 70, background=PAPER)
    for k, h in enumerate((8, 14, 22)):
        sl.draw.text(fb, 6, 50 - 22 * k, f"height {h}", height=h, color=INK, antialias=h < 10)
    panels.append(fb.to_pil())
    titles.append("height (cap height, px)")
    fb = sl.FrameBuffer(220, 70, background=PAPER)
    for k, (e, s) in enumerate(((0.6, 0), (1.6, 0), (1, 0.4))):
        sl.draw.text(fb, 6, 50 - 22 * k, f"x{e} +{s}", height=12, expansion=e, spacing=s,
                     color=INK)
    panels.append(fb.to_pil())
    titles.append("expansion, spacing")
    fb = sl.FrameBuffer(170, 140, background=PAPER)
    for k in range(8):
        sl.draw.text(fb, 85, 70, "   angle", height=9, angle=k * math.pi / 4,
                     align=("left", "half"), color=INK, antialias=True)
    _mark(fb, 85, 70)
    panels.append(fb.to_pil())
    titles.append("orientation (8 angles)")
    row1 = side_by_side(panels, titles)
    panels, titles = [], []
    fb = sl.FrameBuffer(240, 170, background=PAPER)
    for path, align in (("right", ("left", "half")), ("left", ("left", "half")),
                        ("up", ("center", "bottom")), ("down", ("center", "top"))):
        start = {"right": (128, 85), "left": (112, 85), "up": (120, 93), "down": (120, 77)}[path]
        sl.draw.text(fb, *start, path.upper(), font="stroke", height=12, path=path,
                     align=align if path != "left" else ("right", "half"), color=INK)
    _mark(fb, 120, 85)
    panels.append(fb.to_pil())
    titles.append("text path right / left / up / down")
    fb = sl.FrameBuffer(380, 170, background=PAPER)
    for i, v in enumerate(("top", "cap", "half", "base", "bottom")):
        for j, h in enumerate(("left", "center", "right")):
            x, y = 60 + 130 * j, 150 - 32 * i
            sl.draw.text(fb, x, y, f"{h}/{v}", height=10, align=(h, v), color=INK,
                         antialias=True)          # small unhinted outlines read only antialiased
            _mark(fb, x, y)
    panels.append(fb.to_pil())
    titles.append("alignment (red: the reference point)")
    row2 = side_by_side(panels, titles)
    e = sl.text.extents("Extent", font="sans", height=20)
    return Figure(
        "text-attributes", "Text attributes",
        "Character height (the cap height, baseline to capital line), width expansion "
        "factor and character spacing (a fraction of the height); orientation by the "
        "baseline angle (or the character up vector); the text path, the direction in "
        "which characters follow each other with each character upright; and the "
        "alignment of the text extent rectangle on the reference point (horizontal "
        "left/center/right, vertical top/cap/half/base/bottom). The extent query "
        f"answers before drawing: 'Extent' at height 20 is {e.width:.1f} x "
        f"{e.height:.1f} px.",
        "Notes, syllabus: Character attributes, Text attributes; Hearn & Baker, "
        "section 4-5; GKS (ISO 7942) text attributes",
        stacked([enlarge(row1, 2), enlarge(row2, 2)]), None)


def figure_glyph_outline():
    """An outline glyph flattened and filled: contours over the pixels."""
    fb = sl.FrameBuffer(22, 30, background=PAPER)
    sl.draw.text(fb, 2, 8, "g", font="sans", height=24, color="#a0c4e8")
    glyph = sl.text.layout("g", 2, 8, font="sans", height=24)[0]
    paper = GraphPaper(fb, scale=18)
    for contour in glyph.contours:
        for a, b in zip(contour, list(contour[1:]) + [contour[0]]):
            paper.line(*a, *b)
    points = sum(len(c) for c in glyph.contours)
    return Figure(
        "glyph-outline", "An outline glyph: flattened contours, scan-line fill",
        "The letter g of DejaVu Sans at a cap height of 24 px. fontTools reads its two "
        "contours of quadratic Bezier segments; scanline flattens each segment into "
        "equal parameter steps, as many as Wang's bound asks for a distance of at most "
        f"0.2 px from the curve ({points} points in all, red), and fills the polygons "
        "with the nonzero winding rule: a pixel (blue) is inside when its center is.",
        "Notes, chapter 2: scan-line fill of curved boundary areas; syllabus: character "
        "generation", paper.image, None)


FIGURES = (figure_fonts, figure_text_attributes, figure_glyph_outline)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
