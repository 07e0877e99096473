"""Pictures for ``scanline demo``: enlarged frame buffers on graph paper.

The pixels always come from a :class:`~scanline.FrameBuffer` drawn by
:mod:`scanline.draw`; this module only enlarges them (each pixel a scale x scale
block, as ``FrameBuffer.save(scale=...)`` does) and annotates the enlarged image with
Pillow: a light pixel grid, axis labels, the ideal line or curve, labels in pixels.
"""

import math
from importlib import resources

from PIL import Image, ImageDraw, ImageFont

GRID = (200, 200, 200)
IDEAL = (214, 39, 40, 255)
PAPER = (255, 255, 255)
INK = (40, 40, 40)

#: The ideal curves are drawn this many times larger, then reduced: antialiasing.
_SUPERSAMPLE = 4


#: The annotations' font: the bundled DejaVu Sans, hinted by FreeType through Pillow
#: (Pillow's built-in Aileron has no en dash, "Cox–de Boor", and reads poorly small).
_FONT = str(resources.files("scanline") / "data" / "fonts" / "DejaVuSans.ttf")


def font(size):
    """DejaVu Sans at ``size`` pixels."""
    return ImageFont.truetype(_FONT, size)


def enlarge(image, scale):
    """A Pillow image enlarged ``scale`` times, each pixel a scale x scale block (what
    ``FrameBuffer.save(path, scale=scale)`` writes)."""
    return image.resize((image.width * scale, image.height * scale), Image.Resampling.NEAREST)


class GraphPaper:
    """A window of a frame buffer, enlarged, with a pixel grid and axis labels.

    Parameters
    ----------
    fb : FrameBuffer
    window : (xmin, ymin, xmax, ymax), optional
        The pixels shown, inclusive, in device coordinates; default all.
    scale : int
        Size of one pixel in the picture.
    origin : (x, y)
        Device pixel labeled (0, 0) on the axes, e.g. a circle's center.
    """

    def __init__(self, fb, window=None, scale=24, origin=(0, 0)):
        self.xmin, self.ymin, self.xmax, self.ymax = window or (0, 0, fb.width - 1, fb.height - 1)
        self.scale = scale
        box = (self.xmin, fb.height - 1 - self.ymax, self.xmax + 1, fb.height - self.ymin)
        pixels = enlarge(fb.to_pil().convert("RGB").crop(box), scale)
        self.font = font(max(9, min(15, scale // 2)))
        self.left, self.bottom = 3 * self.font.size, 2 * self.font.size
        self.top = self.right = self.font.size // 2
        size = (self.left + pixels.width + self.right, self.top + pixels.height + self.bottom)
        self._image = Image.new("RGB", size, PAPER)
        self._image.paste(pixels, (self.left, self.top))
        self._draw = ImageDraw.Draw(self._image)
        self._overlay = Image.new("RGBA", (size[0] * _SUPERSAMPLE, size[1] * _SUPERSAMPLE))
        self._grid_and_axes(origin)

    def _grid_and_axes(self, origin):
        s, draw = self.scale, self._draw
        width, height = self.xmax - self.xmin + 1, self.ymax - self.ymin + 1
        x_end, y_end = self.left + width * s, self.top + height * s
        for i in range(width + 1):
            draw.line([(self.left + i * s, self.top), (self.left + i * s, y_end)], fill=GRID)
        for j in range(height + 1):
            draw.line([(self.left, self.top + j * s), (x_end, self.top + j * s)], fill=GRID)
        step = next(n for n in (1, 2, 5, 10, 20, 50) if n * s >= 2.5 * self.font.size)
        text = {"fill": INK, "font": self.font}
        for x in range(self.xmin, self.xmax + 1):
            if (x - origin[0]) % step == 0:
                at = (self.xy(x, self.ymin)[0], y_end + 3)
                draw.text(at, str(x - origin[0]), anchor="mt", **text)
        for y in range(self.ymin, self.ymax + 1):
            if (y - origin[1]) % step == 0:
                at = (self.left - 4, self.xy(self.xmin, y)[1])
                draw.text(at, str(y - origin[1]), anchor="rm", **text)

    def xy(self, x, y):
        """Picture coordinates of the device point (x, y); pixel centers are at integers."""
        return (self.left + (x - self.xmin + 0.5) * self.scale,
                self.top + (self.ymax - y + 0.5) * self.scale)

    def _ideal(self, points):
        return [(px * _SUPERSAMPLE, py * _SUPERSAMPLE) for px, py in points]

    def line(self, x0, y0, x1, y1, color=IDEAL):
        """Draw the ideal line segment from (x0, y0) to (x1, y1), thin and antialiased."""
        ImageDraw.Draw(self._overlay).line(self._ideal([self.xy(x0, y0), self.xy(x1, y1)]),
                                           fill=color, width=2 * _SUPERSAMPLE)

    def ellipse(self, xc, yc, rx, ry, color=IDEAL):
        """Draw the ideal ellipse with semi-axes rx, ry about (xc, yc) (a circle if rx = ry)."""
        width = 2 * _SUPERSAMPLE  # Pillow strokes inside the box: widen it by half of that
        (left, top), (right, bottom) = self._ideal([self.xy(xc - rx, yc + ry),
                                                    self.xy(xc + rx, yc - ry)])
        box = (left - width / 2, top - width / 2, right + width / 2, bottom + width / 2)
        ImageDraw.Draw(self._overlay).ellipse(box, outline=color, width=width)

    def label(self, x, y, text, color=PAPER):
        """Write ``text`` in the middle of pixel (x, y)."""
        self._draw.text(self.xy(x, y), text, fill=color, font=self.font, anchor="mm")

    @property
    def image(self):
        """The finished picture (RGB), ideal curves on top."""
        overlay = self._overlay.resize(self._image.size, Image.Resampling.LANCZOS)
        return Image.alpha_composite(self._image.convert("RGBA"), overlay).convert("RGB")


def side_by_side(images, titles, gap=24):
    """Put pictures in a row, each with its title above, on white paper."""
    title_font = font(16)
    head = title_font.size + 10
    # each column as wide as its picture or its title, whichever is wider
    widths = [max(im.width, math.ceil(title_font.getlength(t)) + 4) for im, t in zip(images, titles)]
    width = sum(widths) + gap * (len(images) - 1)
    out = Image.new("RGB", (width, head + max(im.height for im in images)), PAPER)
    draw = ImageDraw.Draw(out)
    x = 0
    for im, title, w in zip(images, titles, widths):
        draw.text((x + w / 2, 2), title, fill=INK, font=title_font, anchor="mt")
        out.paste(im.convert("RGB"), (x + (w - im.width) // 2, head))
        x += w + gap
    return out


def stacked(images, gap=24):
    """Put pictures one above another, each centered, on white paper (e.g. rows made
    by :func:`side_by_side`)."""
    width = max(im.width for im in images)
    out = Image.new("RGB", (width, sum(im.height for im in images) + gap * (len(images) - 1)),
                    PAPER)
    y = 0
    for im in images:
        out.paste(im.convert("RGB"), ((width - im.width) // 2, y))
        y += im.height + gap
    return out


def _wrap(text, font_, width):
    """``text`` broken into lines no wider than ``width`` pixels (at word breaks)."""
    lines = [""]
    for word in text.split():
        candidate = f"{lines[-1]} {word}".strip()
        if lines[-1] and font_.getlength(candidate) > width:
            lines.append(word)
        else:
            lines[-1] = candidate
    return lines


def grid_of(images, titles, columns=3, cell=(400, 300), gap=16):
    """A contact sheet: each picture shrunk to fit ``cell`` with its title below,
    wrapped to the cell's width (large enough to read when the sheet is shown 1000
    pixels wide, as in the README); a last row that is not full is centered."""
    title_font = font(20)
    cw, ch = cell
    wrapped = [_wrap(t, title_font, cw - 8) for t in titles]
    line_height = title_font.size + 4
    foot = max(map(len, wrapped)) * line_height + 10
    rows = -(-len(images) // columns)
    out = Image.new("RGB", (columns * (cw + gap) + gap, rows * (ch + foot + gap) + gap), PAPER)
    draw = ImageDraw.Draw(out)
    last_row = (rows - 1) * columns
    for i, (im, lines) in enumerate(zip(images, wrapped)):
        x0 = gap + (i % columns) * (cw + gap)
        if i >= last_row:
            x0 += (rows * columns - len(images)) * (cw + gap) // 2
        y0 = gap + (i // columns) * (ch + foot + gap)
        thumb = im.convert("RGB")
        thumb.thumbnail(cell, Image.Resampling.LANCZOS)
        out.paste(thumb, (x0 + (cw - thumb.width) // 2, y0 + (ch - thumb.height) // 2))
        for k, line in enumerate(lines):
            draw.text((x0 + cw / 2, y0 + ch + 6 + k * line_height), line, fill=INK,
                      font=title_font, anchor="mt")
    return out
