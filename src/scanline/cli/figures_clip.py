"""Figures of ``scanline demo`` for clipping (notes, chapter 4): lines P1 ... P4
against a clip window with their region codes, and Sutherland-Hodgman versus
Weiler-Atherton on a concave polygon."""

import numpy as np

import scanline as sl

from ._plot import INK, GraphPaper, side_by_side
from .figures import HIGHLIGHT, PAPER, PIXEL, SECOND, Figure

FAINT = "#c8c8c8"
WINDOW = (8, 6, 40, 26)
#: Lines named as in the notes' figure: P1P2 inside, P3P4 outside above the window,
#: P5P6 and P7P8 crossing one or more boundaries.
LINES = {
    ("P1", "P2"): (14, 10, 32, 21),
    ("P3", "P4"): (4, 29, 44, 30),
    ("P5", "P6"): (2, 2, 24, 29),
    ("P7", "P8"): (20, 3, 46, 16),
}


def _outline(fb, ring, color):
    ring = np.asarray(ring, float)
    sl.draw.lines(fb, np.hstack([ring, np.roll(ring, -1, axis=0)]), color=color)


def figure_cohen_sutherland():
    """Lines against a clip window, each endpoint labeled with its region code."""
    fb = sl.FrameBuffer(49, 33, mode="RGB", background=PAPER)
    xmin, ymin, xmax, ymax = WINDOW
    _outline(fb, [(xmin, ymin), (xmax, ymin), (xmax, ymax), (xmin, ymax)], INK)
    seg = np.array(list(LINES.values()), float)
    sl.draw.lines(fb, seg, color=FAINT)
    clipped, ok = sl.clip.lines(seg, WINDOW, method="cohen-sutherland")
    sl.draw.lines(fb, clipped[ok], color=PIXEL)
    paper = GraphPaper(fb, scale=18)
    for (a, b), (x0, y0, x1, y1) in LINES.items():
        for name, x, y in ((a, x0, y0), (b, x1, y1)):
            code = sl.trace.cohen_sutherland(x, y, x, y, window=WINDOW).rows[0]["code0"]
            paper.label(x, y + 1.2 if y < 28 else y - 1.3, f"{name} {code}", color=HIGHLIGHT)
    table = sl.trace.cohen_sutherland(*LINES[("P5", "P6")], window=WINDOW)
    return Figure(
        "clip-cohen-sutherland", "Cohen-Sutherland line clipping",
        "The window (black) from (8, 6) to (40, 26); each endpoint is labeled with its "
        "region code (bits 4 3 2 1 = above, below, right, left). P1P2 is accepted "
        "trivially (both 0000), P3P4 rejected trivially (the AND is 1000), P5P6 and P7P8 "
        "are clipped: the faint parts are discarded, the blue parts drawn. The table "
        "traces P5P6.",
        "Notes, chapter 4, Q.3", paper.image, str(table))


def figure_polygon_clipping():
    """Sutherland-Hodgman against Weiler-Atherton on a concave subject."""
    subject = np.array([(3, 3), (37, 3), (37, 25), (28, 25), (28, 9), (12, 9), (12, 25),
                        (3, 25)], float)
    window = (1, 14, 39, 22)
    pictures = []
    tables = []
    for method in ("sutherland-hodgman", "weiler-atherton"):
        fb = sl.FrameBuffer(41, 29, mode="RGB", background=PAPER)
        _outline(fb, subject, FAINT)
        xmin, ymin, xmax, ymax = window
        _outline(fb, [(xmin, ymin), (xmax, ymin), (xmax, ymax), (xmin, ymax)], HIGHLIGHT)
        pieces = sl.clip.polygon(subject, window, method=method)
        sl.draw.polygon(fb, pieces, color="#a9c1e8")
        for k, c in enumerate(pieces):
            _outline(fb, c, PIXEL if k == 0 else SECOND)
        pictures.append(GraphPaper(fb, scale=10).image)
        tables.append(f"{method}: {len(pieces)} contour(s): "
                      + "; ".join(" ".join(f"({x:g}, {y:g})" for x, y in c) for c in pieces))
    image = side_by_side(pictures, ["Sutherland-Hodgman: one contour",
                                    "Weiler-Atherton: two pieces"])
    return Figure(
        "clip-polygons", "Sutherland-Hodgman versus Weiler-Atherton",
        "A concave U (gray) clipped by the window (orange). Sutherland-Hodgman clips the "
        "vertex list edge by edge and returns one contour: the two legs stay joined by "
        "edges along the window's bottom, which its outline draws (blue, from x = 12 to "
        "28); they enclose no area, so the fill is right. Weiler-Atherton follows the subject inside the window and "
        "the window inside the subject, switching at each crossing: two separate pieces.",
        "Notes, syllabus: polygon clipping", image, "\n".join(tables))


FIGURES = (figure_cohen_sutherland, figure_polygon_clipping)
