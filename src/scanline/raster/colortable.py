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

from typing import TYPE_CHECKING, Callable, cast

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError

METHODS = ("entries", "bit-planes")

if TYPE_CHECKING:
    from .._typing import Color
    from ..animation import Animation
    from ..framebuffer import FrameBuffer


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
        How positions get color-table entries (see the module docstring).

    Raises
    ------
    ArgumentValueError
        For an unknown method, or more steps than it can hold.

    Attributes
    ----------
    fb : FrameBuffer
        Mode "P": the indices, drawn once.

    Notes
    -----
    Hearn & Baker, section 16-3, "Raster animations" (color-table animation,
    Fig. 16-5); the notes, chapter 6, Q3.

    Examples
    --------
    >>> import scanline as sl
    >>> cta = sl.raster.ColorTableAnimation(4, 1, steps=2, method="bit-planes")
    >>> cta.draw(0, lambda fb, color: fb.set_pixel(1, 0, color))
    >>> cta.draw(1, lambda fb, color: fb.set_pixel(1, 0, color))   # the same pixel
    >>> cta.fb.to_array().tolist()                  # bits 0 and 1: index 3
    [[0, 3, 0, 0]]
    """

    def __init__(self, width: int, height: int, steps: int, color: "Color" = "white",
                 background: "Color" = "black", method: str = "entries") -> None:
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

    def draw(self, step: int, draw: Callable[["FrameBuffer", int], object]) -> None:
        """Pre-draw the object at position ``step``: ``draw(fb, color)`` draws it on a
        scratch frame buffer (any ``sl.draw`` calls), and every pixel it sets joins
        position ``step``.

        Parameters
        ----------
        step : int
            The position, 0 .. ``steps - 1``.
        draw : callable
            ``draw(fb, color)``: draws the object at that position on ``fb`` with the
            pixel value ``color``.

        Raises
        ------
        ArgumentValueError
            For a step out of range.
        ArgumentTypeError
            When ``draw`` is not callable.

        Examples
        --------
        >>> import scanline as sl
        >>> cta = sl.raster.ColorTableAnimation(3, 1, steps=2)
        >>> cta.draw(1, lambda fb, color: sl.draw.line(fb, 0, 0, 1, 0, color=color))
        >>> cta.fb.to_array().tolist()                      # position 1: index 2
        [[2, 2, 0]]
        """
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

    def table(self, step: int) -> NDArray[np.uint8]:
        """The color table of frame ``step`` (cycled: ``step`` modulo ``steps``):
        position ``step``'s entries hold the color, all others the background.

        Parameters
        ----------
        step : int
            The frame, >= 0 (taken modulo ``steps``).

        Returns
        -------
        numpy.ndarray
            uint8 (n, 3), the RGB color table.

        Examples
        --------
        >>> import scanline as sl
        >>> cta = sl.raster.ColorTableAnimation(2, 1, steps=2, color="red")
        >>> cta.table(1).tolist()        # entry 0 the background, 1 position 0, 2 position 1
        [[0, 0, 0], [0, 0, 0], [255, 0, 0]]
        """
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

    def frame(self, step: int) -> "FrameBuffer":
        """Frame ``step``: a copy of the frame buffer with the table of that step.

        Parameters
        ----------
        step : int
            The frame, >= 0 (taken modulo ``steps``).

        Returns
        -------
        FrameBuffer
            Mode "P": the same indices, the table of that step.

        Examples
        --------
        >>> import scanline as sl
        >>> cta = sl.raster.ColorTableAnimation(2, 1, steps=2, color="white")
        >>> cta.draw(0, lambda fb, color: fb.set_pixel(0, 0, color))
        >>> cta.frame(0).to_pil().convert("L").getpixel((0, 0)), cta.frame(1).to_pil().convert("L").getpixel((0, 0))
        (255, 0)
        """
        from ..color.spec import Channels
        from ..framebuffer import FrameBuffer

        out = FrameBuffer(self.fb.width, self.fb.height, mode="P", background=0,
                          color_table=[Channels(int(c) for c in row) for row in self.table(step)])
        out._raster()[0][...] = self.fb._raster()[0]
        return out

    def frames(self) -> list["FrameBuffer"]:
        """Every frame, one per position.

        Returns
        -------
        list of FrameBuffer
            ``frame(0)`` .. ``frame(steps - 1)``.

        Examples
        --------
        >>> import scanline as sl
        >>> len(sl.raster.ColorTableAnimation(2, 1, steps=3).frames())
        3
        """
        return [self.frame(k) for k in range(self.steps)]

    def animation(self, fps: float = 12, loop: int = 0) -> "Animation":
        """The frames as an :class:`~scanline.animation.Animation` (saved as GIF, the
        color tables go into the file as they are).

        Parameters
        ----------
        fps : float
            Frames per second.
        loop : int
            How many times a GIF repeats (0: forever).

        Returns
        -------
        Animation
            The frames, one per position.

        Examples
        --------
        >>> import scanline as sl
        >>> movie = sl.raster.ColorTableAnimation(2, 1, steps=3).animation(fps=6)
        >>> movie.count, movie.fps
        (3, 6.0)
        """
        from .. import animation

        # sl.animation is not yet annotated (issue 32): its class called as a typed maker
        make = cast(Callable[..., "Animation"], animation.Animation)
        return make(self.frames(), fps=fps, loop=loop)
