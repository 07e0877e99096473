"""Color-table animation (notes, chapter 6, Q3; Hearn & Baker §16-3, Fig. 16-5).

"Using color-table transformations we can animate objects along two dimensional
motion paths.  The object at successive positions is predefined along with the motion
path.  And the color table entries are updated with the successive blocks of pixel
values.  We set the pixels at the first position of the object to 'on' values, and we
set the pixels at the other object positions to the background color.  The animation
is attained by varying the color table values so that the object is 'on' at
successively along the animation path."

:class:`ColorTableAnimation` draws the object once at each position into a mode "P"
frame buffer, each position in its own color-table entries; frame k is the same pixels
with a table in which only position k's entries hold the object's color.  No pixel is
redrawn to animate: only the (at most 256) table entries change.

Two ways of giving positions entries:

- ``"entries"`` (the notes' description): position k is index k + 1.  A pixel has one
  index, so where positions overlap the later one owns the pixel; exact when the
  positions do not overlap (up to 255 positions).
- ``"bit-planes"``: position k is bit k of the index (up to 8 positions); a pixel
  covered by several positions holds the OR of their bits, and frame k's table lights
  every index with bit k set, so overlapping positions animate exactly.

>>> import numpy as np
>>> cta = ColorTableAnimation(6, 1, steps=3, color="white", background="black")
>>> for k in range(3):
...     cta.draw(k, lambda fb, color, k=k: fb.set_pixel(2 * k, 0, color))
>>> for k in range(3):                         # the same indices, three tables
...     print(np.asarray(cta.frame(k).to_pil().convert("L"))[0].tolist())
[255, 0, 0, 0, 0, 0]
[0, 0, 255, 0, 0, 0]
[0, 0, 0, 0, 255, 0]
"""

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError

METHODS = ("entries", "bit-planes")


class ColorTableAnimation:
    """An object pre-drawn at successive positions, animated by its color table.

    Parameters
    ----------
    width, height : int
        The frame buffer's size.
    steps : int
        Positions along the path (``"entries"``: up to 255; ``"bit-planes"``: up to 8).
    color : color
        The object's color when it is "on".
    background : color
        The background color (also the color of the positions that are "off").
    method : {"entries", "bit-planes"}

    Attributes
    ----------
    fb : FrameBuffer
        Mode "P": the indices, drawn once.
    """

    def __init__(self, width, height, steps, color="white", background="black",
                 method="entries"):
        from ..color.spec import rgba
        from ..framebuffer import FrameBuffer

        v.choice("method", method, METHODS)
        limit = 255 if method == "entries" else 8
        self.steps = v.positive_int("steps", steps)
        if self.steps > limit:
            raise ArgumentValueError(
                f"steps={steps} is more than method={method!r} can hold ({limit}: "
                f"{'one table entry per position, 256 entries' if method == 'entries' else 'one bit of the 8-bit index per position'})")
        self.method = method
        self.color = tuple(rgba(color, "color")[:3])
        self.background = tuple(rgba(background, "background")[:3])
        size = 1 + self.steps if method == "entries" else 1 << self.steps
        self.fb = FrameBuffer(width, height, mode="P", background=0,
                              color_table=[self.background] * size)
        self._mask = FrameBuffer(width, height, mode="L")

    def draw(self, step, draw):
        """Pre-draw the object at position ``step``: ``draw(fb, color)`` draws it on a
        scratch frame buffer (any ``sl.draw`` calls), and every pixel it sets joins
        position ``step``."""
        step = v.positive_int("step", step, minimum=0)
        if step >= self.steps:
            raise ArgumentValueError(f"step={step}: positions are 0..{self.steps - 1}")
        if not callable(draw):
            raise ArgumentTypeError(f"draw must be a function (fb, color) -> None, got "
                                    f"{v._show(draw)}")
        self._mask.clear(0)
        draw(self._mask, 255)
        on = self._mask._raster()[0][:, :, 0] != 0
        indices = self.fb._raster()[0][:, :, 0]
        if self.method == "entries":
            indices[on] = step + 1
        else:
            indices[on] |= np.uint8(1 << step)

    def table(self, step):
        """The color table of frame ``step`` (cycled: ``step`` modulo ``steps``):
        position ``step``'s entries hold the color, all others the background."""
        step = v.positive_int("step", step, minimum=0) % self.steps
        size = len(self.fb._table)
        lit = np.zeros(size, bool)
        if self.method == "entries":
            lit[step + 1] = True
        else:
            lit = (np.arange(size) >> step) & 1 == 1
        table = np.tile(np.array(self.background, np.uint8), (size, 1))
        table[lit] = self.color
        return table

    def frame(self, step):
        """Frame ``step``: a copy of the frame buffer with the table of that step."""
        from ..color.spec import Channels
        from ..framebuffer import FrameBuffer

        out = FrameBuffer(self.fb.width, self.fb.height, mode="P", background=0,
                          color_table=[Channels(int(c) for c in row) for row in self.table(step)])
        out._raster()[0][...] = self.fb._raster()[0]
        return out

    def frames(self):
        """Every frame, one per position."""
        return [self.frame(k) for k in range(self.steps)]

    def animation(self, fps=12, loop=0):
        """The frames as an :class:`~scanline.animation.Animation` (saved as GIF, the
        color tables go into the file as they are)."""
        from ..animation import Animation

        return Animation(self.frames(), fps=fps, loop=loop)
