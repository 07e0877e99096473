"""The storyboard sheet: key frames side by side with their times and captions
(notes, chapter 6, Q1: "The outline of the action is storyboard ... a set of rough
structures or ... a list of the basic ideas for the motion").

The sheet is a contact sheet: each panel is a frame reduced to the panel size
(Pillow's Lanczos filter), framed, with its label ("key 2 · t = 1.50 s · frame 36")
and caption below it.
"""

import textwrap
from collections.abc import Sequence
from typing import cast

from PIL import Image, ImageDraw, ImageFont

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from .render import to_image

PAPER = (255, 255, 255)
INK = (40, 40, 40)
RULE = (150, 150, 150)


def _font(size: int) -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    return ImageFont.load_default(size=size)


GAP = 16
HEAD = 34
#: Caption lines shown under a panel.
CAPTION_LINES = 4


def _texts(name: str, value: object, count: int) -> list[str]:
    if isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
        raise ArgumentTypeError(f"{name} must be a sequence of strings, one per frame, got "
                                f"{v._show(value)}")
    texts = list(cast("Sequence[object]", value))
    if len(texts) != count:
        raise ArgumentValueError(f"give one label and caption per frame ({count}), got "
                                 f"{len(texts)} {name}")
    for k, text in enumerate(texts):
        if not isinstance(text, str):
            raise ArgumentTypeError(f"{name}[{k}] must be a string, got {v._show(text)}")
    return cast("list[str]", texts)


def panel_size(panel: object, name: str = "panel") -> tuple[int, int]:
    """``panel`` checked: (width, height), integers of at least 16 pixels."""
    size = cast("Sequence[object]", panel)
    if isinstance(size, (str, bytes)) or not hasattr(size, "__len__") or len(size) != 2:
        raise ArgumentTypeError(f"{name} must be (width, height) in pixels, got {v._show(panel)}")
    return (v.positive_int(f"{name} width", size[0], 16),
            v.positive_int(f"{name} height", size[1], 16))


def _wrapped(captions: Sequence[str], pw: int) -> list[list[str]]:
    chars = max(8, pw // 7)
    return [textwrap.wrap(c, chars)[:CAPTION_LINES] for c in captions]


def _text_height(wrapped: list[list[str]]) -> int:
    return 22 + 15 * max((len(w) for w in wrapped), default=0)


def sheet_size(count: int, columns: int, panel: tuple[int, int], wrapped: list[list[str]],
               title: str | None) -> tuple[int, int]:
    """(width, height) of the sheet of ``count`` panels in rows of ``columns``."""
    pw, ph = panel
    rows = -(-count // columns)
    return (GAP + columns * (pw + GAP),
            (HEAD if title else 0) + GAP + rows * (ph + _text_height(wrapped) + GAP))


def check_sheet(count: int, columns: int, panel: tuple[int, int],
                captions: Sequence[str] | None = None, title: str | None = None,
                name: str = "panel", copies: int = 1) -> tuple[int, int]:
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


def contact_sheet(frames: Sequence[object], labels: Sequence[str],
                  captions: Sequence[str] | None = None, columns: int = 4,
                  panel: tuple[int, int] = (240, 180), title: str | None = None) -> Image.Image:
    """Frames laid out in rows of ``columns`` panels with labels and captions.

    Parameters
    ----------
    frames : sequence
        Frames (FrameBuffer, Pillow image, array, path).
    labels : sequence of str
        One line under each panel.
    captions : sequence of str, optional
        Text under the label (wrapped to the panel's width).
    columns : int, default 4
        Panels per row (at most the number of frames).
    panel : (width, height), default (240, 180)
        Each frame is shrunk (never enlarged past 4x) to fit; at least 16 pixels.
    title : str, optional
        A heading over the sheet.

    Returns
    -------
    PIL.Image.Image
        RGB.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If there are no frames, the labels or captions are not one string per frame,
        the sizes are out of range, a frame cannot be read, or the sheet would pass
        the image-size or memory limits.

    Notes
    -----
    The storyboard of the notes, chapter 6, Q1 (Hearn & Baker, section 16-1).

    Examples
    --------
    Two panels of 40 x 20 in one row: 16 + 2 (40 + 16) = 128 pixels wide; a panel,
    its label line (22) and the gaps make 16 + 20 + 22 + 16 = 74 high:

    >>> import scanline as sl
    >>> frames = [sl.FrameBuffer(20, 10), sl.FrameBuffer(20, 10)]
    >>> sl.animation.contact_sheet(frames, ["a", "b"], panel=(40, 20)).size
    (128, 74)
    """
    if isinstance(frames, (str, bytes)) or not hasattr(frames, "__len__") \
            or not hasattr(frames, "__getitem__"):
        raise ArgumentTypeError(f"frames must be a sequence of frames, got {v._show(frames)}")
    count = len(frames)
    if not count:
        raise ArgumentValueError("a storyboard needs at least one frame")
    label_texts = _texts("labels", labels, count)
    caption_texts = [""] * count if captions is None else _texts("captions", captions, count)
    if title is not None and not isinstance(title, str):
        raise ArgumentTypeError(f"title must be a string, got {v._show(title)}")
    columns = min(v.positive_int("columns", columns), count)
    pw, ph = panel_size(panel)
    check_sheet(count, columns, (pw, ph), caption_texts, title)
    label_font, caption_font, title_font = _font(14), _font(12), _font(18)
    wrapped = _wrapped(caption_texts, pw)
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
        draw.text((x0, y0 + ph + 5), label_texts[i], fill=INK, font=label_font)
        for k, line in enumerate(wrapped[i]):
            draw.text((x0, y0 + ph + 22 + 15 * k), line, fill=INK, font=caption_font)
    return sheet
