"""
Line attributes
===============

Figures of ``scanline demo`` for the line attributes: line types, widths, caps and
joins, pens (notes, syllabus: "Line attributes - Line type. Line width. Pen and
Brush options")."""

import numpy as np

import scanline as sl

from scanline.gallery._plot import enlarge, side_by_side, stacked
from scanline.gallery.primitives import HIGHLIGHT, PAPER, PIXEL, SECOND, Figure


def _stroked(size, path, color, scale, **attributes):
    """A frame buffer of ``size`` with the stroke of ``path`` and, over it, the path
    itself at width 1 in the highlight color, enlarged ``scale`` times."""
    fb = sl.FrameBuffer(*size, background=PAPER)
    sl.draw.polyline(fb, path, color=color, **attributes)
    sl.draw.polyline(fb, path, color=HIGHLIGHT)
    return enlarge(fb.to_pil(), scale)


def figure_line_types():
    """Line types: named masks, a user bit mask and dash lengths, width 1 and thick."""
    zigzag = [(3, 4), (30, 26), (57, 4), (84, 26), (111, 4)]
    rows = [("solid", None), ("dashed", "dashed"), ("dotted", "dotted"),
            ("dash-dot", "dash-dot"), ("mask 0b1110010011100100", 0b1110010011100100),
            ("lengths (9, 3, 2, 3)", (9, 3, 2, 3))]
    panels, titles = [], []
    for title, dash in rows:
        fb = sl.FrameBuffer(115, 31, background=PAPER)
        sl.draw.polyline(fb, zigzag, color=PIXEL, dash=dash)
        panels.append(enlarge(fb.to_pil(), 3))
        titles.append(title)
    # thick: each mask bit is `width` units of arc length; round caps make the dots
    # round (a dot of the mask 0b1010... would be a 4 x 4 square turned along the path),
    # with lengths that leave a gap after the caps
    thick_rows = [("dashed", "dashed"), ("dots (0.5, 9.5)", (0.5, 9.5)),
                  ("dash-dot (16, 6, 0.5, 6)", (16, 6, 0.5, 6))]
    thick = []
    for title, dash in thick_rows:
        fb = sl.FrameBuffer(115, 31, background=PAPER)
        sl.draw.polyline(fb, zigzag, color=SECOND, dash=dash, width=4, join="round",
                         cap="round")
        thick.append(enlarge(fb.to_pil(), 3))
    return Figure(
        "line-types", "Line types: pixel masks along the Bresenham path, dash lengths",
        "Width 1 (blue): the Bresenham pixels of each segment are numbered along the "
        "path, a shared vertex once, and a 16-bit mask decides each pixel (bit 15 "
        "first); the named types are masks (dashed 0b1111111100000000, dotted "
        "0b1010101010101010, dash-dot 0b1111111100011000), so the pattern runs on "
        "round the corners. Dash lengths are measured along the path in pixels, so "
        "steep and shallow segments get dashes of the same length. Width 4 (green): "
        "each mask bit stands for one line width of length, and every dash is a thick "
        "polyline with caps and joins of its own; with round caps a short dash (0.5) is a "
        "round dot, and each gap must exceed the line width to show.",
        "Notes, syllabus: Line attributes - Line type (Hearn & Baker, section 4-1)",
        stacked([side_by_side(panels[:3], titles[:3]), side_by_side(panels[3:], titles[3:]),
                 side_by_side(thick, [f"width 4, round caps, {t}" for t, _ in thick_rows])]),
        None)


def figure_caps_and_joins():
    """Caps (butt, round, square) and joins (miter, round, bevel) at width 12."""
    vee = [(12, 14), (44, 60), (76, 14)]
    panels, titles = [], []
    for cap, join in (("butt", "miter"), ("round", "round"), ("square", "bevel")):
        panels.append(_stroked((89, 75), vee, PIXEL, 3, width=12, cap=cap, join=join))
        titles.append(f"cap {cap}, join {join}")
    sharp = [(6, 10), (80, 30), (6, 50)]
    limits = [_stroked((130, 61), sharp, SECOND, 2, width=9, miter_limit=limit)
              for limit in (10, 2)]
    return Figure(
        "caps-joins", "Line width: caps and joins",
        "A thick polyline is filled by the package's own scan-line polygon fill: one "
        "outline per polyline (segment sides, the outer join at each turn, the caps), "
        "nonzero rule, so each pixel is painted once. Caps: butt ends at the endpoint, "
        "round adds a half disc, square extends the line by half its width. Joins: "
        "miter extends the outer sides to meet, round adds a circular wedge, bevel "
        "cuts the corner. Below, a 30-degree turn of width 9: its miter is 3.8 widths "
        "long, drawn with miter_limit=10 and beveled with miter_limit=2.",
        "Notes, syllabus: Line attributes - Line width (Hearn & Baker, section 4-1)",
        stacked([side_by_side(panels, titles),
                 side_by_side(limits, ["miter_limit=10", "miter_limit=2"])]),
        None)


def figure_pens():
    """Pen footprints stamped along the pixel path (pixel replication)."""
    path = [(6, 6), (60, 20), (30, 50), (70, 54)]
    brush = np.array([[False, False, True],
                      [False, True, False],
                      [True, False, False]])
    pens = [("square pen, width 4", dict(pen="square", width=4)),
            ("round pen, width 5", dict(pen="circle", width=5)),
            ("calligraphic brush 3x3", dict(pen=brush)),
            ("outline, width 5", dict(width=5, cap="round", join="round"))]
    panels = [_stroked((77, 61), path, PIXEL, 3, **kw) for _, kw in pens]
    return Figure(
        "pens", "Pen and brush shapes",
        "A pen is a footprint (a square, a disc or any small bitmap) stamped at every "
        "pixel of the Bresenham path: pixel replication, the notes' thick primitives. "
        "A pen line is thicker than the width along diagonals (the square's diagonal) "
        "and a slanted brush gives calligraphic strokes whose width follows the "
        "direction; the last panel is the exact outline of width 5 with round caps "
        "and joins, for comparison.",
        "Notes, syllabus: Line attributes - Pen and Brush options; objective "
        "questions 19-20",
        stacked([side_by_side(panels[:2], [t for t, _ in pens[:2]]),
                 side_by_side(panels[2:], [t for t, _ in pens[2:]])]),
        None)


FIGURES = (figure_line_types, figure_caps_and_joins, figure_pens)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
