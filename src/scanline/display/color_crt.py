"""Color CRT monitors (Hearn & Baker, section 2-1; the notes' chapter 1, Q.5): the
beam-penetration method and the shadow-mask method, simulated like the monochrome
displays of :mod:`scanline.display.crt`.

*Beam penetration* (:class:`BeamPenetration`): "two layers of phosphor, usually red
and green, are coated onto the inside of the CRT screen, and the displayed color
depends on how far the electron beam penetrates into the phosphor layers. A beam of
slow electrons excites only the outer red layer. A beam of very fast electrons
penetrates through the red layer and excites the inner green layer. At intermediate
beam speeds, combinations of red and green light are emitted to show two additional
colors, orange and yellow."  It is a random-scan display: every color the display
file asks for is drawn in the nearest of the four (:func:`penetration_color`), the
beam-acceleration voltage of :data:`PENETRATION_VOLTAGES` choosing it;
:func:`penetration_colors` quantizes a frame buffer to the same palette.

*Shadow mask* (:class:`ShadowMask`): "three phosphor color dots at each pixel
position", red, green and blue, excited by three electron guns through the holes of
a mask just behind the screen, each beam reaching only its own color's dot.  In the
*delta-delta* arrangement the dots of a pixel form a triangle; in the *in-line*
arrangement "the three electron guns, and the corresponding red-green-blue color
dots on the screen, are aligned along one scan line".  The colors come from the
three beams' intensities: white with all three equal, yellow with red and green
only, magenta with blue and red, cyan with blue and green.  The three beams are
"deflected and focused as a group"; where they are out of *convergence* each lands
offset from the others, and every edge shows color fringes (``misconvergence``).
"""

from typing import TYPE_CHECKING, Any, Literal, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..framebuffer import FrameBuffer
from .crt import RandomScan, RasterScan, glow, last_visit

if TYPE_CHECKING:
    from .file import DisplayFile

#: The four colors of a beam-penetration screen, slowest beam first, and the beam
#: accelerating voltage (kilovolts) of each: only the outer red layer, red with a
#: little and with as much green from the inner layer, only the inner green layer.
#: (The voltages are illustrative: the notes give none.)
PENETRATION_COLORS = {"red": (255, 0, 0), "orange": (255, 128, 0), "yellow": (255, 255, 0),
                      "green": (0, 255, 0)}
PENETRATION_VOLTAGES = {"red": 6.0, "orange": 8.0, "yellow": 10.0, "green": 12.0}
#: The beam off: dark screen.
OFF = (0, 0, 0)

#: Dot arrangements of a shadow-mask tube, and the (u, v) centers of the red,
#: green and blue dots inside a pixel's cell (fractions of the cell, v down).
TRIADS = {"delta": ((0.26, 0.3), (0.74, 0.3), (0.5, 0.72)),
          "in-line": ((1 / 6, 0.5), (0.5, 0.5), (5 / 6, 0.5))}
#: Dot radius as a fraction of the cell.
DOT_RADIUS = {"delta": 0.22, "in-line": 0.16}
#: Most screen pixels per frame-buffer pixel of a shadow-mask screen.
MAX_DOTS = 16


#: The beam off, then the four colors: the choices of a beam-penetration screen.
_CHOICES = np.array([OFF] + list(PENETRATION_COLORS.values()), np.float64)
_NAMES = np.array(["off"] + list(PENETRATION_COLORS), dtype=object)


def _nearest(rgb: ArrayLike) -> NDArray[np.int64]:
    """Index into _CHOICES of the choice nearest (in RGB) to each of ``rgb``."""
    a = np.asarray(rgb, np.float64)
    if a.shape[-1:] != (3,) or not np.isfinite(a).all():
        raise ArgumentValueError(f"rgb must be finite (..., 3) colors, got shape {a.shape}")
    best = np.zeros(a.shape[:-1], np.int64)
    least = np.full(a.shape[:-1], np.inf)
    for k, choice in enumerate(_CHOICES):          # one (..., ) array at a time, not (..., 5, 3)
        d = ((a - choice) ** 2).sum(axis=-1)
        best[d < least] = k
        least = np.minimum(least, d)
    return best


def penetration_color(rgb: ArrayLike) -> NDArray[np.object_]:
    """The beam-penetration color nearest (in RGB) to each of ``rgb`` (..., 3), the
    beam off (black) where that is nearer: an array of names, ``"off"`` included.

    >>> penetration_color([(250, 20, 10), (255, 200, 40), (0, 0, 30), (90, 255, 0)]).tolist()
    ['red', 'yellow', 'off', 'green']
    """
    return _NAMES[_nearest(rgb)]


def penetration_colors(fb: FrameBuffer) -> FrameBuffer:
    """``fb`` as a beam-penetration screen shows it: every pixel in the nearest of
    red, orange, yellow and green, or dark.  An RGB frame buffer."""
    if not isinstance(fb, FrameBuffer):
        raise ArgumentTypeError(f"fb must be a scanline.FrameBuffer, got {v._show(fb)}")
    rgb = np.asarray(fb.to_pil().convert("RGB"))
    return FrameBuffer.from_array(_CHOICES[_nearest(rgb)].astype(np.uint8))


class BeamPenetration(RandomScan):
    """A random-scan display with a beam-penetration color screen: the display
    file's lines in red, orange, yellow or green, the beam's voltage choosing each
    (every other color goes to the nearest of the four).  Takes the arguments of
    :class:`~scanline.display.crt.RandomScan`.

    Attributes
    ----------
    voltages : list of (kilovolts, color name)
        The beam voltage set for each COLOR command, in order.

    Examples
    --------
    >>> import scanline as sl
    >>> df = sl.DisplayFile()
    >>> df.set_viewing(window=(0, 0, 100, 100))
    >>> df.create_segment("a")
    >>> df.polyline([(10, 10), (90, 10)], color="gold")
    >>> df.polyline([(10, 50), (90, 50)], color="blue")
    >>> df.close_segment()
    >>> BeamPenetration(df, 101, 101).voltages
    [(10.0, 'yellow'), (0.0, 'off')]
    """

    def __init__(self, display_file: "DisplayFile", width: int, height: int,
                 **kw: float) -> None:
        self.voltages: list[tuple[float, str]] = []
        super().__init__(display_file, width, height, **kw)

    def _beam_color(self, rgb: tuple[int, int, int]) -> tuple[int, int, int]:
        name = str(penetration_color(rgb[:3]))
        self.voltages.append((PENETRATION_VOLTAGES.get(name, 0.0), name))
        return PENETRATION_COLORS.get(name, OFF)


def _offsets(misconvergence: Union[float, ArrayLike]) -> NDArray[np.float64]:
    """(3, 2) beam offsets in pixels from a number m (red (-m, 0), blue (+m, 0)) or
    three (dx, dy) pairs."""
    if isinstance(misconvergence, (int, float)) and not isinstance(misconvergence, bool):
        m = v.number("misconvergence", misconvergence)
        off = np.array([(-m, 0.0), (0.0, 0.0), (m, 0.0)])
    else:
        off = v.real_array("misconvergence", misconvergence, "a number or (3, 2) offsets")
        if off.shape != (3, 2):
            raise ArgumentValueError(
                f"misconvergence must be a number of pixels or three (dx, dy) offsets of the "
                f"red, green and blue beams, got shape {off.shape}")
    if not (np.abs(off) <= 64).all():
        raise ArgumentValueError(
            f"misconvergence offsets {off.tolist()} must be finite and within 64 pixels")
    return off.astype(np.float64)


class ShadowMask(RasterScan):
    """A raster-scan color monitor with a shadow mask: each pixel of the frame buffer
    is a triad of red, green and blue phosphor dots, ``dots`` x ``dots`` screen pixels.

    Parameters
    ----------
    fb : FrameBuffer
        The refresh buffer (its RGB values are the three beams' intensities).
    arrangement : {"delta", "in-line"}
        The dots of a triad in a triangle (delta-delta) or side by side along the
        scan line (in-line).
    dots : int
        Screen pixels per frame-buffer pixel, each way (3 to 16).
    misconvergence : float or (3, 2) array
        How far each beam lands from where it should, in pixels (x right, y up): a
        number m moves red by (-m, 0) and blue by (+m, 0); green stays.
    **raster
        The timing of :class:`~scanline.display.crt.RasterScan` (refresh_rate,
        interlaced, persistence, horizontal_retrace, vertical_retrace).

    Attributes
    ----------
    mask : ndarray (dots, dots)
        Which dot each screen pixel of a cell belongs to: 0 red, 1 green, 2 blue,
        -1 the dark mask between dots.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(2, 1, background="yellow")
    >>> tube = ShadowMask(fb, arrangement="in-line", dots=6)
    >>> tube.mask[3].tolist()
    [0, 0, 1, 1, 2, 2]
    >>> tube.screen(tube.hits[0, 0])[3, :6].tolist()[::2]   # yellow: red and green dots
    [[255, 0, 0], [0, 255, 0], [0, 0, 0]]
    """

    def __init__(self, fb: FrameBuffer, arrangement: Literal["delta", "in-line"] = "delta",
                 dots: int = 6, misconvergence: Union[float, ArrayLike] = 0.0,
                 **raster: Any) -> None:
        super().__init__(fb, **raster)
        self.arrangement = v.choice("arrangement", arrangement, tuple(TRIADS))
        self.dots = v.positive_int("dots", dots, minimum=3)
        if self.dots > MAX_DOTS:
            raise ArgumentValueError(f"dots={self.dots} is too many; at most {MAX_DOTS}")
        if self.width * self.height * self.dots ** 2 > 4 * 1024 * 1024:
            raise ArgumentValueError(
                f"{self.width} x {self.height} pixels of {self.dots} x {self.dots} dots is "
                "more than 4 million screen pixels; use a smaller frame buffer or fewer dots")
        self.offsets = _offsets(misconvergence)
        d = self.dots
        c = (np.arange(d) + 0.5) / d
        u, w = np.meshgrid(c, c)                                 # w: down the cell
        self.mask = np.full((d, d), -1, np.int64)
        for k, (cu, cw) in enumerate(TRIADS[self.arrangement]):
            inside = (u - cu) ** 2 + (w - cw) ** 2 <= DOT_RADIUS[self.arrangement] ** 2
            self.mask[inside] = k
        # for each screen pixel, the frame-buffer pixel its dot's beam shows (the beam
        # offset by its misconvergence), or -1 off the frame buffer
        rows, cols = self.height * d, self.width * d
        x = (np.arange(cols) + 0.5) / d - 0.5                    # pixel units, centers at ints
        y_down = (np.arange(rows) + 0.5) / d - 0.5
        channel = np.tile(self.mask, (self.height, self.width))
        src_x = np.rint(x[None, :] - self.offsets[np.maximum(channel, 0), 0]).astype(np.int64)
        src_row = np.rint(y_down[:, None] + self.offsets[np.maximum(channel, 0), 1]).astype(np.int64)
        ok = (channel >= 0) & (src_x >= 0) & (src_x < self.width) & (src_row >= 0) & \
            (src_row < self.height)
        self._channel = channel
        value = np.zeros((rows, cols))
        value[ok] = self.pixels[src_row[ok], src_x[ok], channel[ok]]
        self._dot_value = value

    def screen(self, t: float) -> NDArray[np.uint8]:
        """The screen at time ``t``: (height * dots, width * dots, 3) uint8, each dot
        glowing in its own color with its beam's intensity."""
        t = v.number("t", t)
        g = glow(t - last_visit(self.hits, self.period, t), self.persistence)
        g = np.repeat(np.repeat(g, self.dots, axis=0), self.dots, axis=1)
        out = np.zeros(self._channel.shape + (3,))
        lit = self._channel >= 0
        rr, cc = np.nonzero(lit)
        out[rr, cc, self._channel[lit]] = self._dot_value[lit] * g[lit]
        return np.clip(np.rint(out), 0, 255).astype(np.uint8)

    def triad_centers(self) -> NDArray[np.float64]:
        """The centers of a cell's red, green and blue dots, (3, 2), in screen pixels
        (x right, y down) from the cell's top left corner, measured from the mask."""
        out = []
        for k in range(3):
            w, u = np.nonzero(self.mask == k)
            out.append((u.mean() + 0.5, w.mean() + 0.5))
        return np.array(out)
