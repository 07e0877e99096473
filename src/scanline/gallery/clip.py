"""
Clipping
========

Figures of ``scanline demo`` for clipping (notes, chapter 4): lines P1 ... P4
against a clip window with their region codes, and Sutherland-Hodgman versus
Weiler-Atherton on a concave polygon."""

import numpy as np

import scanline as sl

from scanline.gallery._plot import INK, GraphPaper, enlarge, side_by_side
from scanline.gallery.primitives import HIGHLIGHT, PAPER, PIXEL, SECOND, Figure

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


#: A small world: a house (walls, roof, door) and a path of segments.
HOUSE = [(10, 10), (50, 10), (50, 40), (30, 58), (10, 40)]
DOOR = [(25, 10), (35, 10), (35, 28), (25, 28)]
PATH = [(0, 4, 20, 8), (20, 8, 40, 4), (40, 4, 60, 8), (55, 20, 70, 55)]


def _draw_world(fb, view):
    """The world as ``view`` shows it: polygons clipped in viewing coordinates (a
    concave window is not needed here: Sutherland-Hodgman), lines by Liang-Barsky."""
    sl.draw.polygon(fb, view.clip_polygon(HOUSE), color="#a9c1e8")
    sl.draw.polygon(fb, view.clip_polygon(DOOR), color="#8c6d31")
    seg, ok = view.clip_lines(PATH + [(a[0], a[1], b[0], b[1]) for a, b in
                                      zip(HOUSE, HOUSE[1:] + HOUSE[:1])])
    sl.draw.lines(fb, seg[ok], color=PIXEL)


def figure_viewing():
    """Two viewports on one frame buffer: the world, and a turned window on it."""
    fb = sl.FrameBuffer(200, 100, mode="RGB", background=PAPER)
    left, right = sl.viewing.tile(1, 2, gap=0.04)
    world = sl.viewing.Window(-5, -5, 75, 65)
    window = sl.viewing.Window(-14, -10, 14, 10, origin=(30, 30), view_up=(-0.5, 1))
    views = [sl.viewing.View(world, sl.viewing.device_viewport(left, 200, 100),
                             keep_aspect=True),
             sl.viewing.View(window, sl.viewing.device_viewport(right, 200, 100),
                             keep_aspect=True)]
    for view in views:
        _draw_world(fb, view)
    corners = views[0].to_viewport(window.corners())
    sl.draw.lines(fb, np.hstack([corners, np.roll(corners, -1, axis=0)]), color=HIGHLIGHT)
    vp = sl.viewing.device_viewport(right, 200, 100)
    box = views[1].to_viewport(window.corners())
    sl.draw.lines(fb, np.hstack([box, np.roll(box, -1, axis=0)]), color=HIGHLIGHT)
    image = enlarge(fb.to_pil().convert("RGB"), 4)
    lines = [f"world -> device, left:  {np.round(views[0].matrix, 4).tolist()}",
             f"world -> device, right: {np.round(views[1].matrix, 4).tolist()}",
             f"right viewport (device): {vp.bounds}"]
    return Figure(
        "viewing", "Window, view-up vector and two viewports",
        "One frame buffer, two viewports. Left: the whole world; the orange rectangle is "
        "a window centered on (30, 30) whose viewing frame has the view-up vector "
        "(-0.5, 1). Right: that window mapped to its viewport (M = window-to-viewport "
        "times R.T), the world clipped against it in viewing coordinates; aspect ratio "
        "kept (letterbox).",
        "Notes, syllabus: 2-D viewing, window to viewport", image, "\n".join(lines))


FIGURES = (figure_cohen_sutherland, figure_polygon_clipping, figure_viewing)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
