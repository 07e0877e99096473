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
from ..errors import ArgumentTypeError, ArgumentValueError
from .render import to_image

PAPER = (255, 255, 255)
INK = (40, 40, 40)
RULE = (150, 150, 150)


def _font(size):
    return ImageFont.load_default(size=size)


GAP = 16
HEAD = 34
#: Caption lines shown under a panel.
CAPTION_LINES = 4


def _texts(name, value, count):
    if isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
        raise ArgumentTypeError(f"{name} must be a sequence of strings, one per frame, got "
                                f"{v._show(value)}")
    texts = list(value)
    if len(texts) != count:
        raise ArgumentValueError(f"give one label and caption per frame ({count}), got "
                                 f"{len(texts)} {name}")
    for k, text in enumerate(texts):
        if not isinstance(text, str):
            raise ArgumentTypeError(f"{name}[{k}] must be a string, got {v._show(text)}")
    return texts


def panel_size(panel, name="panel"):
    """``panel`` checked: (width, height), integers of at least 16 pixels."""
    if isinstance(panel, (str, bytes)) or not hasattr(panel, "__len__") or len(panel) != 2:
        raise ArgumentTypeError(f"{name} must be (width, height) in pixels, got {v._show(panel)}")
    return (v.positive_int(f"{name} width", panel[0], 16),
            v.positive_int(f"{name} height", panel[1], 16))


def _wrapped(captions, pw):
    chars = max(8, pw // 7)
    return [textwrap.wrap(c, chars)[:CAPTION_LINES] for c in captions]


def _text_height(wrapped):
    return 22 + 15 * max((len(w) for w in wrapped), default=0)


def sheet_size(count, columns, panel, wrapped, title):
    """(width, height) of the sheet of ``count`` panels in rows of ``columns``."""
    pw, ph = panel
    rows = -(-count // columns)
    return (GAP + columns * (pw + GAP),
            (HEAD if title else 0) + GAP + rows * (ph + _text_height(wrapped) + GAP))


def check_sheet(count, columns, panel, captions=None, title=None, name="panel", copies=1):
    """Refuse a sheet that no image file may hold or that passes the memory budget
    (naming ``name``), before anything is drawn.  ``copies``: more copies of the
    sheet its caller makes (a frame buffer to save it)."""
    from ..budget import check
    from ..framebuffer import check_image_size

    wrapped = _wrapped(captions or [""] * count, panel[0])
    width, height = sheet_size(count, columns, panel, wrapped, title)
    rows = -(-count // columns)
    given = (f"{name} {panel[0]}x{panel[1]} in {rows} row{'s' if rows > 1 else ''} of "
             f"{columns}")
    check_image_size(width, height, given=f"the sheet of {given} ({width} x {height})",
                     hint=f"use a smaller {name} or fewer columns")
    # the RGB sheet (and its copies), and a panel's thumbnail of at most 4 bytes a pixel
    check(width * height * 3 * (1 + copies) + panel[0] * panel[1] * 4, name,
          f"a {width} x {height} contact sheet ({given})",
          hint=f"use a smaller {name} or fewer columns")
    return width, height


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
    if isinstance(frames, (str, bytes)) or not hasattr(frames, "__len__") \
            or not hasattr(frames, "__getitem__"):
        raise ArgumentTypeError(f"frames must be a sequence of frames, got {v._show(frames)}")
    count = len(frames)
    if not count:
        raise ArgumentValueError("a storyboard needs at least one frame")
    labels = _texts("labels", labels, count)
    captions = [""] * count if captions is None else _texts("captions", captions, count)
    if title is not None and not isinstance(title, str):
        raise ArgumentTypeError(f"title must be a string, got {v._show(title)}")
    columns = min(v.positive_int("columns", columns), count)
    pw, ph = panel_size(panel)
    check_sheet(count, columns, (pw, ph), captions, title)
    label_font, caption_font, title_font = _font(14), _font(12), _font(18)
    wrapped = _wrapped(captions, pw)
    width, height = sheet_size(count, columns, (pw, ph), wrapped, title)
    sheet = Image.new("RGB", (width, height), PAPER)
    gap, head, text_h = GAP, (HEAD if title else 0), _text_height(wrapped)
    draw = ImageDraw.Draw(sheet)
    if title:
        draw.text((gap, gap // 2 + 2), title, fill=INK, font=title_font)
    for i in range(count):
        # one frame at a time: a long storyboard never holds every frame
        image = to_image(frames[i], i).convert("RGB")
        if not image.width or not image.height:
            raise ArgumentValueError(f"frames[{i}] is {image.width} x {image.height} pixels; "
                                     "a panel needs a frame of at least one pixel")
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
