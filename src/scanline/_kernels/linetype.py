"""Line types and pens along the pixel sequence of Bresenham lines (notes, syllabus:
"Line attributes - Line type. Pen and Brush options"; Hearn & Baker, section 4-1).

The raster method of the notes' sources: a polyline is scan-converted segment by
segment with Bresenham's algorithm (the very pixels of ``_kernels/lines.py``), the
pixels are numbered along the path -- a vertex shared by two segments counts once --
and each pixel is drawn or skipped by the line type:

* ``MASK``: bit ``15 - (k mod 16)`` of a 16-bit pixel mask decides pixel ``k``
  (Hearn & Baker's "11111000" masks: the first pixel takes the leftmost bit);
* ``LENGTHS``: dash lengths in device units; pixel ``k`` of a segment of length
  ``L`` scanned in ``du`` steps sits at arc length ``s0 + L * k / du``;
* ``SOLID``: every pixel.

A drawn pixel stamps the pen's footprint (a list of pixel offsets; one offset (0, 0)
for a plain line): pixel replication, the "moving pen" of the notes' Q.19-Q.20.
"""

import numpy as np

from ._jit import helper, kernel
from .lines import bresenham_clip, bresenham_decide, bresenham_setup, bresenham_state
from .raster import put

SOLID = 0
MASK = 1
LENGTHS = 2


@helper
def dash_on(dashes, period, s):
    """Whether arc length ``s`` falls in an "on" entry of the dash lengths."""
    t = s % period
    k = 0
    while k < dashes.shape[0] - 1:
        if t < dashes[k]:
            break
        t -= dashes[k]
        k += 1
    return k % 2 == 0


@helper
def segment_pixels(buf, layout, width, height, x0, y0, x1, y1, skip_first, skip_last,
                   kind, mask, count0, dashes, period, s0, length, pen, margin, color):
    """Draw the patterned pixels of segment (x0, y0)-(x1, y1) in path order
    (k = 0 at (x0, y0)), numbered from ``count0``; returns the count after it."""
    swap, u0, w0, du, dw, sw = bresenham_setup(x0, y0, x1, y1)
    reverse = (y0 > y1) if swap else (x0 > x1)
    if swap:
        lo, hi = bresenham_clip(u0 + margin, w0 + margin, du, dw, sw,
                                height - 1 + 2 * margin, width - 1 + 2 * margin)
    else:
        lo, hi = bresenham_clip(u0 + margin, w0 + margin, du, dw, sw,
                                width - 1 + 2 * margin, height - 1 + 2 * margin)
    if lo <= hi:
        j, p = bresenham_state(lo, du, dw)
        two_dw = 2 * dw
        two_dw_minus_two_du = 2 * dw - 2 * du
        npen = pen.shape[0]
        for i in range(lo, hi + 1):
            k = du - i if reverse else i
            draw = not ((skip_first and k == 0) or (skip_last and k == du))
            if draw and kind == MASK:
                draw = ((mask >> (15 - ((count0 + k) & 15))) & 1) == 1
            elif draw and kind == LENGTHS:
                draw = dash_on(dashes, period, s0 + (length * k / du if du > 0 else 0.0))
            if draw:
                u = u0 + i
                w = w0 + sw * j
                x = w if swap else u
                y = u if swap else w
                for q in range(npen):
                    put(buf, layout, width, height, x + pen[q, 0], y + pen[q, 1], color)
            p, advance = bresenham_decide(p, two_dw, two_dw_minus_two_du)
            j += advance
    return count0 + du


@helper
def patterned_loop(buf, layout, width, height, verts, offsets, closed, colors, kind,
                   mask, dashes, phase, pen, margin):
    period = 0.0
    for i in range(dashes.shape[0]):
        period += dashes[i]
    one = colors.shape[0] == 1
    for p in range(offsets.shape[0] - 1):
        a = offsets[p]
        b = offsets[p + 1]
        color = colors[0 if one else p]
        count = int(phase) if kind == MASK else 0
        s = phase
        if b - a == 1:
            no = np.bool_(False)    # (not a literal: the helper compiles once)
            segment_pixels(buf, layout, width, height, verts[a, 0], verts[a, 1], verts[a, 0],
                           verts[a, 1], no, no, kind, mask, count, dashes, period, s,
                           0.0, pen, margin, color)
            continue
        nseg = b - a if (closed[p] and b - a > 2) else b - a - 1
        for q in range(nseg):
            i = a + q
            j = i + 1 if i + 1 < b else a
            x0 = verts[i, 0]
            y0 = verts[i, 1]
            x1 = verts[j, 0]
            y1 = verts[j, 1]
            length = ((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5
            count = segment_pixels(buf, layout, width, height, x0, y0, x1, y1, q > 0,
                                   q == nseg - 1 and nseg == b - a, kind, mask, count,
                                   dashes, period, s, length, pen, margin, color)
            s += length


@kernel
def draw_patterned(buf, layout, width, height, verts, offsets, closed, colors, kind, mask,
                   dashes, phase, pen, margin):
    """Draw polylines of integer vertices ``verts[offsets[p]:offsets[p + 1]]``
    (closed if ``closed[p]``) as Bresenham pixel sequences in line type ``kind``
    (SOLID, MASK with the 16-bit ``mask`` starting at pixel ``phase``, or LENGTHS
    with ``dashes`` starting at arc length ``phase``), stamping the ``pen`` offsets
    ((K, 2) int64, each within ``margin`` pixels) at every drawn pixel."""
    patterned_loop(buf, layout, width, height, verts, offsets, closed, colors, kind, mask,
                   dashes, phase, pen, margin)


@helper
def sequence_loop(buf, layout, width, height, pixels, kind, mask, dashes, phase, pen, color):
    period = 0.0
    for i in range(dashes.shape[0]):
        period += dashes[i]
    s = phase
    npen = pen.shape[0]
    for k in range(pixels.shape[0]):
        if k > 0:
            s += ((pixels[k, 0] - pixels[k - 1, 0]) ** 2
                  + (pixels[k, 1] - pixels[k - 1, 1]) ** 2) ** 0.5
        draw = True
        if kind == MASK:
            draw = ((mask >> (15 - ((int(phase) + k) & 15))) & 1) == 1
        elif kind == LENGTHS:
            draw = dash_on(dashes, period, s)
        if draw:
            for q in range(npen):
                put(buf, layout, width, height, pixels[k, 0] + pen[q, 0],
                    pixels[k, 1] + pen[q, 1], color)


@kernel
def draw_sequence(buf, layout, width, height, pixels, kind, mask, dashes, phase, pen, color):
    """Draw a pixel sequence (K, 2) in path order (the ordered pixels of a midpoint
    circle or ellipse) in line type ``kind``, stamping ``pen``; pixel ``k`` sits at
    the arc length of the polyline through the pixel centers."""
    sequence_loop(buf, layout, width, height, pixels, kind, mask, dashes, phase, pen, color)
