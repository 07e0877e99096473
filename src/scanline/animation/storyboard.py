"""The storyboard sheet: key frames side by side with their times and captions
(notes, chapter 6, Q1: "The outline of the action is storyboard ... a set of rough
structures or ... a list of the basic ideas for the motion").

The sheet is a contact sheet: each panel is a frame reduced to the panel size
(Pillow's Lanczos filter), framed, with its label ("key 2 · t = 1.50 s · frame 36")
and caption below it.
"""

import textwrap

from PIL import Image, ImageDraw, ImageFont

from .. import _validate as v
from ..errors import ArgumentValueError
from .render import to_image

PAPER = (255, 255, 255)
INK = (40, 40, 40)
RULE = (150, 150, 150)


def _font(size):
    return ImageFont.load_default(size=size)


def contact_sheet(frames, labels, captions=None, columns=4, panel=(240, 180), title=None):
    """Frames laid out in rows of ``columns`` panels with labels and captions.

    Parameters
    ----------
    frames : sequence
        Frames (FrameBuffer, Pillow image, array, path).
    labels : sequence of str
        One line under each panel.
    captions : sequence of str, optional
        Text under the label (wrapped to the panel's width).
    columns : int
    panel : (width, height)
        Each frame is shrunk (never enlarged past 4x) to fit.
    title : str, optional
        A heading over the sheet.

    Returns
    -------
    PIL.Image.Image
        RGB.
    """
    images = [to_image(f, i).convert("RGB") for i, f in enumerate(frames)]
    if not images:
        raise ArgumentValueError("a storyboard needs at least one frame")
    labels = list(labels)
    captions = list(captions) if captions is not None else [""] * len(images)
    if len(labels) != len(images) or len(captions) != len(images):
        raise ArgumentValueError(f"give one label and caption per frame ({len(images)}), got "
                                 f"{len(labels)} labels and {len(captions)} captions")
    columns = v.positive_int("columns", columns)
    columns = min(columns, len(images))
    pw, ph = (v.positive_int("panel width", panel[0], 16), v.positive_int("panel height", panel[1], 16))
    label_font, caption_font, title_font = _font(14), _font(12), _font(18)
    chars = max(8, pw // 7)
    wrapped = [textwrap.wrap(c, chars)[:4] for c in captions]
    text_h = 22 + 15 * max((len(w) for w in wrapped), default=0)
    gap = 16
    head = 34 if title else 0
    rows = -(-len(images) // columns)
    sheet = Image.new("RGB", (gap + columns * (pw + gap), head + gap + rows * (ph + text_h + gap)),
                      PAPER)
    draw = ImageDraw.Draw(sheet)
    if title:
        draw.text((gap, gap // 2 + 2), title, fill=INK, font=title_font)
    for i, image in enumerate(images):
        x0 = gap + (i % columns) * (pw + gap)
        y0 = head + gap + (i // columns) * (ph + text_h + gap)
        scale = min(pw / image.width, ph / image.height, 4.0)
        size = (max(1, round(image.width * scale)), max(1, round(image.height * scale)))
        resample = Image.Resampling.NEAREST if scale >= 1 else Image.Resampling.LANCZOS
        thumb = image.resize(size, resample)
        sheet.paste(thumb, (x0 + (pw - size[0]) // 2, y0 + (ph - size[1]) // 2))
        draw.rectangle((x0 - 1, y0 - 1, x0 + pw, y0 + ph), outline=RULE)
        draw.text((x0, y0 + ph + 5), labels[i], fill=INK, font=label_font)
        for k, line in enumerate(wrapped[i]):
            draw.text((x0, y0 + ph + 22 + 15 * k), line, fill=INK, font=caption_font)
    return sheet
