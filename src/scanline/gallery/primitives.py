"""
Output primitives and area filling
==================================

The figures of ``scanline demo``: the notes' worked examples and more, drawn by
:mod:`scanline.draw` and annotated by :mod:`scanline.gallery._plot`.

Each ``figure_*`` function returns a :class:`Figure`; :data:`FIGURES` lists them in
gallery order.
"""

import math
import time
from collections import namedtuple

import numpy as np
from PIL import Image, ImageColor

import scanline as sl

from scanline.gallery._plot import INK, GraphPaper, enlarge, side_by_side, stacked

#: ``name`` (file stem), ``title``, ``caption`` (plain text), ``source`` (the notes'
#: section), ``image`` (a Pillow image) and ``table`` (step-table text or None).
Figure = namedtuple("Figure", "name title caption source image table")

PAPER = "white"
PIXEL = "#2b4c8c"       # scan-converted pixels
HIGHLIGHT = "#f28e2b"   # the pixels the algorithm computes (the rest are mirrored)
SECOND = "#59a14f"      # a second group: region 2, pixels where DDA and Bresenham differ
#: Eight distinguishable colors (Tableau 10), one per octant.
OCTANT_COLORS = ["#4e79a7", "#f28e2b", "#e15759", "#76b7b2",
                 "#59a14f", "#edc948", "#b07aa1", "#ff9da7"]


def _hues(t):
    """(N, 3) uint8 RGB: bright, saturated colors of the hues ``t`` (0 to 1 is red
    around the color wheel back to red)."""
    t = np.asarray(t, np.float64)
    hsv = np.stack([t % 1.0 * 255, np.full(t.shape, 217), np.full(t.shape, 255)], axis=1)
    return np.array(Image.fromarray(hsv.astype(np.uint8)[None], "HSV").convert("RGB"))[0]


def _mirror4(xc, yc, x, y):
    return {(xc + x, yc + y), (xc - x, yc + y), (xc + x, yc - y), (xc - x, yc - y)}


def _lit(fb):
    """The (x, y) pixels of an RGB frame buffer on white paper that are not white."""
    rows, xs = np.nonzero((fb.to_array() != 255).any(axis=2))
    return {(int(x), fb.height - 1 - int(row)) for row, x in zip(rows, xs)}


def _recolor(fb, pixels, color):
    """Give already-drawn pixels another color (to show which step made them)."""
    for x, y in pixels:
        fb.set_pixel(x, y, color)


def figure_bresenham():
    """(a) The notes' Q.3: Bresenham from (20, 10) to (30, 18), step by step."""
    table = sl.trace.bresenham(20, 10, 30, 18)
    fb = sl.FrameBuffer(33, 21, background=PAPER)
    sl.draw.line(fb, 20, 10, 30, 18, color=PIXEL)
    _recolor(fb, [(20, 10)], HIGHLIGHT)
    paper = GraphPaper(fb, window=(18, 8, 32, 20), scale=36)
    paper.line(20, 10, 30, 18)
    for row in table.rows:
        paper.label(row["x"], row["y"], str(row["k"]))
    return Figure(
        "bresenham", "Bresenham's line (20, 10) to (30, 18)",
        "The notes' worked example. The start pixel (orange) is plotted first; each "
        "blue pixel is labeled with the step k that chose it, as in the table: "
        "p_k < 0 keeps y, otherwise y moves up. The red line is the ideal segment.",
        "Notes, chapter 2, Q.2-Q.3", paper.image, str(table))


def figure_dda_vs_bresenham():
    """(b) DDA and Bresenham on the same line, differences marked."""
    ends = (0, 7, 14, 0)
    fbs = {}
    for method in ("dda", "bresenham"):
        fbs[method] = sl.FrameBuffer(15, 8, background=PAPER)
        sl.draw.line(fbs[method], *ends, color=PIXEL, method=method)
    lit = {method: _lit(fb) for method, fb in fbs.items()}
    panels = []
    for method, other in (("dda", "bresenham"), ("bresenham", "dda")):
        _recolor(fbs[method], lit[method] - lit[other], SECOND)
        paper = GraphPaper(fbs[method], scale=28)
        paper.line(*ends)
        panels.append(paper.image)
    tables = [sl.trace.dda(*ends), sl.trace.bresenham(*ends)]
    return Figure(
        "dda-vs-bresenham", "DDA and Bresenham, (0, 7) to (14, 0)",
        "The same segment by both line algorithms; green pixels are where they differ. "
        "The slope is -1/2, so at every other column the ideal line (red) passes exactly "
        "halfway between two pixels: the DDA rounds the half up (y = 6.5 becomes 7), "
        "while Bresenham's p_k = 0 moves y, here down. Elsewhere they agree; the DDA "
        "pays for floating-point increments and a rounding at every step.",
        "Notes, chapter 2, Q.1, Q.2 and Q.7",
        side_by_side(panels, ["DDA", "Bresenham"]),
        "\n\n".join(map(str, tables)))


def figure_octants():
    """(c) A fan of lines through all eight octants, one color per octant."""
    n, length, c = 64, 76, 80
    angles = (np.arange(n) + 0.5) * (2 * math.pi / n)
    segments = np.column_stack([np.full(n, c), np.full(n, c),
                                c + length * np.cos(angles), c + length * np.sin(angles)])
    octant = (angles // (math.pi / 4)).astype(int)
    fb = sl.FrameBuffer(2 * c + 1, 2 * c + 1)
    sl.draw.lines(fb, segments, color=[OCTANT_COLORS[i] for i in octant])
    return Figure(
        "octants", "A fan of lines through the eight octants",
        f"{n} lines from the center, drawn by one sl.draw.lines call, colored by octant. "
        "The notes derive Bresenham's algorithm for slopes 0 < m < 1 (the first octant); "
        "the others follow by swapping the roles of x and y and stepping by -1, and the "
        "lines stay straight and gap-free in every direction.",
        "Notes, chapter 2, Q.2", enlarge(fb.to_pil(), 4), None)


def figure_circle():
    """(d) The notes' Q.5: midpoint circle r = 10, computed octant highlighted."""
    r, c = 10, 12
    table = sl.trace.midpoint_circle(r, center=(c, c))
    fb = sl.FrameBuffer(2 * c + 1, 2 * c + 1, background=PAPER)
    sl.draw.circle(fb, c, c, r, color=PIXEL)
    octant = [(c, c + r)] + [(row["xc+x"], row["yc+y"]) for row in table.rows]
    _recolor(fb, octant, HIGHLIGHT)
    paper = GraphPaper(fb, scale=26, origin=(c, c))
    paper.ellipse(c, c, r, r)
    for row in table.rows:
        paper.label(row["xc+x"], row["yc+y"], str(row["k"]), color=INK)
    return Figure(
        "midpoint-circle", "Midpoint circle, r = 10",
        "The notes' worked example. The algorithm computes only the orange octant, from "
        "(0, 10) to the diagonal x = y, labeled with the step k of the table; the blue "
        "pixels are its mirror images in the other seven octants. The red circle is the "
        "ideal one.",
        "Notes, chapter 2, Q.4-Q.5", paper.image, str(table))


def figure_ellipse():
    """(e) The notes' Q.6: midpoint ellipse rx = 8, ry = 6, regions 1 and 2."""
    rx, ry = 8, 6
    xc, yc = rx + 2, ry + 2
    table = sl.trace.midpoint_ellipse(rx, ry, center=(xc, yc))
    fb = sl.FrameBuffer(2 * xc + 1, 2 * yc + 1, background=PAPER)
    sl.draw.ellipse(fb, xc, yc, rx, ry, color=PIXEL)
    regions = {"1": {(0, ry)}, "2": set()}
    for row in table.rows:
        regions.setdefault(row["region"], set()).add((row["x"], row["y"]))
    for name, color in (("1", HIGHLIGHT), ("2", SECOND)):
        _recolor(fb, set().union(*(_mirror4(xc, yc, x, y) for x, y in regions[name])), color)
    paper = GraphPaper(fb, scale=28, origin=(xc, yc))
    paper.ellipse(xc, yc, rx, ry)
    for row in table.rows:
        paper.label(row["xc+x"], row["yc+y"], str(row["k"]), color=INK)
    return Figure(
        "midpoint-ellipse", "Midpoint ellipse, rx = 8, ry = 6",
        "The notes' worked example. Region 1 (orange, |slope| < 1) steps x from (0, 6) "
        "until 2 ry^2 x >= 2 rx^2 y; region 2 (green) steps y down to 0. The first "
        "quadrant is labeled with the step k (k restarts in region 2); the other three "
        "are mirror images. Erratum: the notes print p2_1 = -215 and p2_2 = -279; the "
        "formulas give 361 and 297 (the pixels (8, 1), (8, 0) are the same).",
        "Notes, chapter 2, Q.6", paper.image, str(table))


def figure_concentric():
    """(f) Concentric circles and ellipses: rx > ry, rx < ry, equal, and radius 0."""
    radii = np.arange(0, 51, 5)
    n, c = len(radii), 55
    fb = sl.FrameBuffer(330, 2 * c + 1)
    colors = _hues(np.linspace(0, 0.8, n))
    sl.draw.circles(fb, np.column_stack([np.full(n, c), np.full(n, c), radii]), color=colors)
    full = np.full(n, 50)
    for xc, rx, ry in ((165, full, radii), (275, radii, full)):
        sl.draw.ellipses(fb, np.column_stack([np.full(n, xc), np.full(n, c), rx, ry]),
                         color=colors)
    return Figure(
        "concentric", "Concentric circles and ellipses",
        "Left: circles of radius 0, 5, ..., 50 (radius 0 is the center pixel). Middle: "
        "ellipses with rx = 50 and ry = 0, 5, ..., 50 (rx > ry; ry = 0 is a segment, "
        "ry = 50 a circle). Right: the same with rx and ry swapped (rx < ry). Each group "
        "is one sl.draw.circles or sl.draw.ellipses call with one color per shape.",
        "Notes, chapter 2, Q.4-Q.6", enlarge(fb.to_pil(), 3), None)


def figure_color_table():
    """(g) Mode "P": drawn once, shown with two color tables."""
    bands, radius, c = 12, 60, 64
    rainbow = ["black"] + [tuple(rgb) for rgb in _hues(np.arange(bands) / bands).tolist()]
    fb = sl.FrameBuffer(2 * c, 2 * c, mode="P", color_table=rainbow)
    segments, indices = [], []
    for band in range(bands):  # filled discs, largest first, leave rings of 1..bands
        r = radius * (bands - band) / bands
        for y in range(-math.floor(r), math.floor(r) + 1):
            half = math.sqrt(r * r - y * y)
            segments.append((c - half, c + y, c + half, c + y))
            indices.append(band + 1)
    sl.draw.lines(fb, segments, color=np.array(indices))
    first = fb.to_pil()
    grays = np.linspace(255, 40, bands).astype(int).tolist()
    fb.color_table = ["black"] + [(v, v, v) for v in grays]
    second = fb.to_pil()
    return Figure(
        "color-table", "One image, two color tables",
        "A mode 'P' frame buffer stores color-table indices, 8 bits per pixel. The rings "
        f"were drawn once, as {len(segments)} horizontal spans with indices 1..{bands} "
        "(one sl.draw.lines call); assigning a new color table recolors every pixel "
        "without redrawing. Changing the entries step by step animates an image this way.",
        "Notes, chapter 2 (syllabus: Color-tables); chapter 6, Q.3",
        side_by_side([enlarge(first, 3), enlarge(second, 3)],
                     ["color table 1", "color table 2"]), None)


def figure_bitmap():
    """(h) Mode "1": a bitmap, one bit per pixel."""
    w, h, step = 200, 120, 3
    fb = sl.FrameBuffer(w, h, mode="1")
    cx, cy = w // 2, h // 2
    border = ([(x, y) for x in range(0, w, step) for y in (0, h - 1)]
              + [(x, y) for y in range(0, h, step) for x in (0, w - 1)])
    sl.draw.lines(fb, [(cx, cy, x, y) for x, y in border], color=1)
    return Figure(
        "bitmap", "A bitmap (mode '1')",
        f"One bit per pixel: {w} x {h} pixels in {fb.nbytes:,} bytes, eight pixels to a "
        f"byte. {len(border)} lines from the center to every third pixel of the border: "
        "their staircases beat against each other and make a moire pattern, an "
        "artifact of sampling (aliasing).",
        "Notes, chapter 1, Q.2 (bitmap and pixmap)", enlarge(fb.to_pil(), 3), None)


def _timed(draw, fb, primitives, colors):
    """Draw once (in one call) and return the time it took in milliseconds."""
    start = time.perf_counter()
    draw(fb, primitives, color=colors)
    return (time.perf_counter() - start) * 1000


def figure_batch():
    """(i) Batch drawing: 20,000 lines and 5,000 circles, one call each."""
    rng = np.random.default_rng(1965)
    n_lines, n_circles, size = 20_000, 5_000, 320
    starts = rng.uniform(0, size, (n_lines, 2))
    angles = rng.uniform(0, 2 * math.pi, n_lines)
    lengths = rng.uniform(4, 24, (n_lines, 1))
    ends = starts + lengths * np.column_stack([np.cos(angles), np.sin(angles)])
    radii = rng.uniform(2, 30, n_circles)
    circles = np.column_stack([rng.uniform(0, size, (n_circles, 2)), radii])
    sl.draw.lines(sl.FrameBuffer(1, 1), [(0, 0, 1, 1)])  # load the compiled kernels first
    sl.draw.circles(sl.FrameBuffer(1, 1), [(0, 0, 1)])
    lines_fb, circles_fb = sl.FrameBuffer(size, size), sl.FrameBuffer(size, size)
    ms_lines = _timed(sl.draw.lines, lines_fb, np.hstack([starts, ends]),
                      _hues(angles / (2 * math.pi)))
    ms_circles = _timed(sl.draw.circles, circles_fb, circles, _hues(radii / 36))
    return Figure(
        "batch", "20,000 lines and 5,000 circles",
        f"Left: {n_lines:,} random lines, colored by direction, drawn by one "
        f"sl.draw.lines call in {ms_lines:.1f} ms. Right: {n_circles:,} random circles, "
        f"colored by radius, one sl.draw.circles call, {ms_circles:.1f} ms. Each call "
        "takes an (N, 4) or (N, 3) array and one color per primitive; the loop runs in "
        "compiled code.",
        "Notes, chapter 2, Q.2 and Q.4",
        side_by_side([lines_fb.to_pil(), circles_fb.to_pil()],
                     [f"{n_lines:,} lines", f"{n_circles:,} circles"]), None)


def _star(xc, yc, r, turns=2, n=5):
    """The vertices of the star polygon {n/turns} about (xc, yc), first vertex up."""
    angles = math.pi / 2 + np.arange(n) * (2 * math.pi * turns / n)
    return np.column_stack([xc + r * np.cos(angles), yc + r * np.sin(angles)])


def _contours_on_paper(fb, contours, scale):
    """Graph paper of ``fb`` with the ideal edges of ``contours`` in red."""
    paper = GraphPaper(fb, scale=scale)
    for contour in contours:
        for (x0, y0), (x1, y1) in zip(contour, np.roll(contour, -1, axis=0)):
            paper.line(x0, y0, x1, y1)
    return paper.image


def figure_fill_rules():
    """(j) Inside-outside tests: a pentagram and a polygon with a hole under both rules."""
    size, c = 33, 16
    star = _star(c, c, 15.5)
    square = np.array([(2, 3), (30, 3), (30, 29), (2, 29)], float)
    hexagon = _star(c, c - 1, 10, turns=1, n=6)  # counterclockwise, like the square
    rows = []
    for contours, color in (([star], PIXEL), ([square, hexagon], SECOND)):
        probe = [(c, c)]
        panels, titles = [], []
        for rule in ("even-odd", "nonzero"):
            fb = sl.FrameBuffer(size, size, background=PAPER)
            sl.draw.polygon(fb, contours, color=color, rule=rule)
            inside = bool(sl.geometry.inside(probe, contours, rule=rule)[0])
            panels.append(_contours_on_paper(fb, contours, 9))
            titles.append(f"{rule}: center {'inside' if inside else 'outside'}")
        winding = int(sl.geometry.winding_number(probe, contours)[0])
        rows.append(side_by_side(panels, [f"{t} (w = {winding})" for t in titles]))
    return Figure(
        "fill-rules", "Inside-outside tests: even-odd and nonzero",
        "The scan-line polygon fill fills a pixel iff its center is inside, and 'inside' "
        "is a rule. Even-odd (odd parity): a ray from the point crosses the boundary an "
        "odd number of times. Nonzero: the boundary winds around the point (winding "
        "number w) a nonzero number of times. Top: the pentagram's center has w = 2, so "
        "it is outside under even-odd and inside under nonzero. Bottom: one polygon of "
        "two contours, a square and a hexagon, both counterclockwise: the hexagon is a "
        "hole under even-odd, but filled under nonzero (w = 2); wound clockwise it would "
        "be a hole under both rules. Titles from sl.geometry.inside and winding_number "
        "at the center, which agree with the pixels; the red lines are the ideal edges.",
        "Notes, chapter 2, Q.8 (syllabus: Scan-line polygon fill algorithm. "
        "Inside-Outside tests)",
        stacked(rows), None)


def figure_curved_areas():
    """(k) Filled circle and ellipse, a pie chart of pie slices, a chord and an arc."""
    shares = np.array([0.34, 0.24, 0.18, 0.14, 0.10])
    bounds = 2 * math.pi * np.concatenate([[0], np.cumsum(shares)])
    c, r = 32, 30

    disks = sl.FrameBuffer(48, 65, background=PAPER)
    sl.draw.fill_circle(disks, 24, 46, 17, color=PIXEL)
    sl.draw.fill_ellipse(disks, 24, 13, 22, 11, color=HIGHLIGHT)

    chart = sl.FrameBuffer(2 * c + 1, 2 * c + 1, background=PAPER)
    count = np.zeros((2 * c + 1, 2 * c + 1), int)  # how often each pixel is in a slice
    for i, (start, end) in enumerate(zip(bounds[:-1], bounds[1:])):
        sl.draw.pie(chart, c, c, r, r, start, end, color=OCTANT_COLORS[i])
        one = sl.FrameBuffer(2 * c + 1, 2 * c + 1, mode="1")
        sl.draw.pie(one, c, c, r, r, start, end, color=1)
        count += one.to_array()
    disk = sl.FrameBuffer(2 * c + 1, 2 * c + 1, mode="1")
    sl.draw.fill_circle(disk, c, c, r, color=1)
    exact = bool(np.array_equal(count, disk.to_array().astype(int)))

    cut = sl.FrameBuffer(2 * c + 1, 2 * c + 1, background=PAPER)
    a, b = math.radians(200), math.radians(340)
    sl.draw.chord(cut, c, c, r, r, a, b, color=SECOND)
    sl.draw.arc(cut, c, c, r, r, b, a, color=PIXEL)
    sl.draw.pie(cut, c, c + 4, 22, 14, math.radians(30), math.radians(150), color=HIGHLIGHT)

    panels = [enlarge(fb.to_pil(), 4) for fb in (disks, chart, cut)]
    return Figure(
        "curved-areas", "Scan-line fill of curved boundary areas",
        "Left: sl.draw.fill_circle and fill_ellipse fill each scan line between the "
        "outermost pixels of the midpoint circle and ellipse, so the area holds its "
        "outline exactly. Middle: a pie chart of five sl.draw.pie slices "
        f"({', '.join(f'{s:.0%}' for s in shares)}); pixel centers on a shared ray "
        "follow the top-left rule, so the slices "
        + ("tile the disk exactly: every pixel of fill_circle is in one slice, none in "
           "two" if exact else "do NOT tile the disk exactly (a bug)")
        + f" ({int(count.sum()):,} pixels). Right: the chord from 200 to 340 degrees "
        "(green), the arc from 340 back to 200 degrees (blue), and a pie slice of an "
        "ellipse (orange, 30 to 150 degrees; its edges leave the center at the polar "
        "angles given).",
        "Notes, chapter 2, Q.8 (syllabus: Scan-Line fill of curved Boundary Areas)",
        side_by_side(panels, ["fill_circle, fill_ellipse", "pie (5 slices)",
                              "chord, arc, elliptic pie"]), None)


def figure_fill_styles():
    """(l) One shape in six fill styles: hollow, solid, patterns, hatch, cross-hatch."""
    house = [(5, 4), (45, 4), (45, 28), (25, 46), (5, 28)]
    o, g = ImageColor.getrgb(HIGHLIGHT), ImageColor.getrgb(SECOND)
    tile = [[o, o, None, None], [o, o, None, None], [None, None, g, g], [None, None, g, g]]
    styles = [(word, sl.FillStyle.parse(word)) for word in
              ("hollow", "solid", "pattern:bricks:shape", "hatch:45:5", "crosshatch:30:6")]
    styles.append(("pattern: colored tile", sl.FillStyle.pattern(tile, anchor="shape")))
    panels = []
    for _, style in styles:
        fb = sl.FrameBuffer(51, 51, background=PAPER)
        sl.draw.polygon(fb, house, color=PIXEL, style=style)
        panels.append(enlarge(fb.to_pil(), 4))
    titles = [word for word, _ in styles]
    return Figure(
        "fill-styles", "Fill styles: hollow, solid, pattern, hatch",
        "One polygon, six values of the area-fill attribute sl.FillStyle (titles as "
        "FillStyle.parse spells them): hollow draws only the boundary; solid fills "
        "every pixel; a pattern repeats a rectangular tile (FillStyle.TILES has "
        f"{', '.join(sl.FillStyle.TILES)}) anchored here at the shape's lower-left "
        "corner, so it moves with the shape; hatching draws parallel lines at an angle "
        "and spacing, cross-hatching two perpendicular families. A tile may hold its "
        "own colors and transparent cells (last panel). The same styles work for "
        "circles, ellipses, chords and pies.",
        "Notes, chapter 2, Q.8 (syllabus: Area-Fill Attributes - Fill styles. "
        "Pattern fill)",
        stacked([side_by_side(panels[:3], titles[:3]), side_by_side(panels[3:], titles[3:])]),
        None)


#: Walls '#' and floor '.': a room with a pillar, a second room, and a gap (x = 6,
#: y = 1) that joins them only diagonally (rows top first).
ROOMS = ("###########",
         "#.....#...#",
         "#.###.#...#",
         "#.....#...#",
         "######.####",
         "###########")
WALL = (90, 90, 90)


def _soft_disk(r, foreground, background):
    """An RGB frame buffer with an antialiased-looking disk: each pixel is
    t F + (1 - t) B, t the share of the pixel (roughly) covered by the disk."""
    c = math.ceil(r) + 1
    yy, xx = np.mgrid[-c:c + 1, -c:c + 1]
    t = np.clip(r + 0.5 - np.hypot(xx, yy), 0, 1)[..., None]
    blend = t * np.array(foreground) + (1 - t) * np.array(background)
    return sl.FrameBuffer.from_array(np.round(blend).astype(np.uint8)), c


def figure_seed_fills():
    """(m) Flood fill 4- and 8-connected through a diagonal gap; soft fill."""
    seed = (1, 2)
    floor = np.array([[ch == "." for ch in row] for row in ROOMS])
    tables, papers = [], []
    for connectivity, color in ((4, HIGHLIGHT), (8, SECOND)):
        table = sl.trace.flood_fill(*seed, grid=ROOMS, connectivity=connectivity)
        fb = sl.FrameBuffer.from_array(
            np.where(floor[..., None], ImageColor.getrgb(PAPER), WALL).astype(np.uint8))
        sl.draw.flood_fill(fb, *seed, color=color, connectivity=connectivity)
        paper = GraphPaper(fb, scale=26)
        for row in table.rows:
            if row["span"] != "already filled":
                left, right = map(int, row["span"].split(".."))
                for x in range(left, right + 1):
                    paper.label(x, row["y"], str(row["k"]))
        papers.append(paper.image)
        tables.append(table)

    blue, orange, white = map(ImageColor.getrgb, (PIXEL, HIGHLIGHT, PAPER))
    fb, c = _soft_disk(10.5, blue, white)
    before = fb.to_pil()
    flooded = sl.FrameBuffer.from_array(fb.to_array())
    sl.draw.flood_fill(flooded, c, c, color=orange)
    soft = sl.draw.soft_fill(fb, c, c, color=orange, foreground=blue, background=white)
    fills = [enlarge(im, 7) for im in (before, flooded.to_pil(), fb.to_pil())]
    counts = [len(t.pixels()) for t in tables]
    return Figure(
        "seed-fills", "Seed fills: 4- and 8-connected flood fill, soft fill",
        f"Top: sl.draw.flood_fill from the seed {seed} recolors the connected floor "
        f"pixels. 4-connected (orange) it stays in the left room ({counts[0]} pixels); "
        "8-connected (green) it also steps through the diagonal gap at (6, 1) into the "
        f"right room ({counts[1]} pixels in all). Each pixel is labeled with the step k "
        "of the table that filled its span: the scan-line seed fill pops a seed, fills "
        "its whole span, and pushes one seed per unfilled run above and below. Bottom: "
        "a disk with soft (antialiased) edges, made with numpy, each pixel "
        "t F + (1 - t) B; a flood fill recolors only the pixels of exactly F and leaves "
        "a blue fringe; sl.draw.soft_fill recovers t per pixel and repaints "
        f"t F' + (1 - t) B ({soft} pixels), so the edge stays soft.",
        "Notes, chapter 2, Q.8 (Flood Fill Algorithm; 4- and 8-connected areas; "
        "syllabus: Soft fill)",
        stacked([side_by_side(papers, ["flood fill, 4-connected", "flood fill, 8-connected"]),
                 side_by_side(fills, ["antialiased disk", "flood fill", "soft fill"])]),
        "\n\n".join(map(str, tables)))


#: Every figure of the demo, in gallery order (a) to (m).
FIGURES = (figure_bresenham, figure_dda_vs_bresenham, figure_octants, figure_circle,
           figure_ellipse, figure_concentric, figure_color_table, figure_bitmap, figure_batch,
           figure_fill_rules, figure_curved_areas, figure_fill_styles, figure_seed_fills)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
