"""Flat-panel displays (Hearn & Baker, section 2-1): the plasma panel and the
active-matrix liquid-crystal display, each an *addressed matrix* of cells rather
than a beam, simulated like the CRTs of :mod:`scanline.display.crt`.

*Plasma panel* (:class:`PlasmaPanel`): the gas between two glass plates; "a series
of vertical conducting ribbons is placed on one glass panel, and a set of horizontal
ribbons is built into the other.  Firing voltages applied to a pair of horizontal
and vertical conductors cause the gas at the intersection of the two conductors to
break down into a glowing plasma of electrons and ions.  Picture definition is
stored in a refresh buffer, and the firing voltages are applied to refresh the
pixel positions (at the intersections of the conductors) 60 times per second."  A
cell glows or not (neon orange); the simulation fires the intersections one after
another, row (horizontal conductor) by row from the top, column (vertical
conductor) by column from the left, and a fired cell's glow fades with the
panel's persistence until the next refresh.

*Liquid-crystal display* (:class:`LCD`), active matrix: the picture is "stored in a
refresh buffer, and the screen is refreshed at the rate of 60 frames per second";
one row is selected at a time (its horizontal select line on), and every column
conductor drives that row's values at once; a transistor at each cell then holds
the voltage until the row's next refresh, so the cell does not fade between
refreshes.  The liquid crystal itself turns slowly: a cell moves toward its new
value with the time constant ``response_time``.  Given a ``previous`` picture, the
panel shows the change sweeping down one row at a time.
"""

from typing import Optional

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..framebuffer import FrameBuffer
from .crt import MAX_PIXELS, Beam, _positive, _Simulation, glow, last_visit

#: The orange glow of a neon plasma cell.
NEON = (255, 110, 30)
#: Most screen pixels per cell.
MAX_DOTS = 16


def _rgb(name: str, fb: object) -> NDArray[np.float64]:
    if not isinstance(fb, FrameBuffer):
        raise ArgumentTypeError(f"{name} must be a scanline.FrameBuffer, got {v._show(fb)}")
    return np.asarray(fb.to_pil().convert("RGB"), np.float64)


class _Matrix(_Simulation):
    """An addressed matrix of cells, each ``dots`` x ``dots`` screen pixels with a
    dark line between cells (the conductors' gaps)."""

    def __init__(self, fb: FrameBuffer, refresh_rate: float, dots: int) -> None:
        self.pixels = _rgb("fb", fb)
        self.height, self.width = self.pixels.shape[:2]
        if self.width * self.height > MAX_PIXELS:
            raise ArgumentValueError(f"the frame buffer has {self.width} x {self.height} "
                                     f"pixels; a simulation takes at most {MAX_PIXELS}")
        self.refresh_rate = _positive("refresh_rate", refresh_rate)
        self.period = 1.0 / self.refresh_rate
        self.dots = v.positive_int("dots", dots)
        if self.dots > MAX_DOTS or self.width * self.height * self.dots ** 2 > 4 * 1024 * 1024:
            raise ArgumentValueError(
                f"dots={self.dots}: at most {MAX_DOTS} and 4 million screen pixels in all")

    def _cells(self, values: NDArray[np.float64]) -> NDArray[np.uint8]:
        """(H, W, 3) cell values as the screen shows them: blocks with gaps."""
        img = np.repeat(np.repeat(values, self.dots, axis=0), self.dots, axis=1)
        if self.dots >= 3:
            img[self.dots - 1::self.dots] = 0
            img[:, self.dots - 1::self.dots] = 0
        return np.clip(np.rint(img), 0, 255).astype(np.uint8)


class PlasmaPanel(_Matrix):
    """A plasma panel refreshing a frame buffer, one intersection of conductors
    at a time.

    Parameters
    ----------
    fb : FrameBuffer
        The refresh buffer: a cell fires where the pixel's luminance is at least
        ``threshold``.
    refresh_rate : float
        Refreshes per second (60 in Hearn & Baker).
    persistence : float
        Seconds a fired cell's glow takes to fall to a tenth.
    threshold : int
        Luminance (0-255) from which a cell is on.
    dots : int
        Screen pixels per cell, each way.

    Attributes
    ----------
    cell_time : float
        Seconds per cell: the period over the number of cells.
    on : ndarray (height, width) of bool
        The cells that fire (image order).
    hits : ndarray (height, width)
        When in each cycle each cell's conductors are energized.

    Examples
    --------
    >>> import scanline as sl
    >>> panel = PlasmaPanel(sl.FrameBuffer(4, 3, background="white"), refresh_rate=50)
    >>> panel.cell_time * 600                  # 12 cells in 1/50 s
    1.0
    >>> [panel.conductors(k * panel.cell_time + 1e-5) for k in (0, 3, 4)]   # (row, column)
    [(0, 0), (0, 3), (1, 0)]
    """

    def __init__(self, fb: FrameBuffer, refresh_rate: float = 60.0, persistence: float = 0.02,
                 threshold: float = 128, dots: int = 4) -> None:
        super().__init__(fb, refresh_rate, dots)
        self.persistence = _positive("persistence", persistence)
        threshold = v.number("threshold", threshold)
        if not 0 < threshold <= 255:
            raise ArgumentValueError(f"threshold={threshold} must be in 1..255")
        from ..color import luminance

        self.on = luminance(self.pixels.astype(np.uint8)) >= threshold
        self.cell_time = self.period / (self.width * self.height)
        order = np.arange(self.width * self.height).reshape(self.height, self.width)
        self.hits = order * self.cell_time

    def conductors(self, t: float) -> tuple[int, int]:
        """The horizontal conductor (row, from the top) and vertical conductor
        (column, from the left) energized at time ``t``."""
        k = int((v.number("t", t) % self.period) // self.cell_time)
        k = min(k, self.width * self.height - 1)
        return divmod(k, self.width)

    def screen(self, t: float) -> NDArray[np.uint8]:
        """The panel at time ``t``: each fired cell glowing in neon orange, fading
        since its last firing."""
        t = v.number("t", t)
        g = glow(t - last_visit(self.hits, self.period, t), self.persistence) * self.on
        return self._cells(g[..., None] * np.array(NEON, np.float64))

    def beam(self, t: float) -> Beam:
        """The cell being fired: ``(x, y, "firing")`` in device coordinates (y up)."""
        row, col = self.conductors(t)
        return float(col), float(self.height - 1 - row), "firing"


class LCD(_Matrix):
    """An active-matrix liquid-crystal display refreshing a frame buffer one row at
    a time.

    Parameters
    ----------
    fb : FrameBuffer
        The picture in the refresh buffer.
    previous : FrameBuffer, optional
        What the panel showed before time 0 (default: black); with ``alternate``
        the two pictures take turns, one per refresh cycle.
    refresh_rate : float
        Refreshes per second (60 in Hearn & Baker).
    response_time : float
        The liquid crystal's time constant: seconds for a cell to move all but 1/e
        of the way to its new value.
    alternate : bool
        Refresh ``fb`` and ``previous`` in turn (to watch every refresh sweep down).
    dots : int
        Screen pixels per cell, each way.

    Attributes
    ----------
    line_time : float
        Seconds each row is selected: the period over the number of rows.

    Examples
    --------
    >>> import scanline as sl
    >>> lcd = LCD(sl.FrameBuffer(3, 4, background="white"), refresh_rate=50,
    ...           response_time=1e-9, dots=1)
    >>> lcd.selected_row(0.0), lcd.selected_row(0.011)
    (0, 2)
    >>> lcd.screen(0.011)[:, 0, 0].tolist()       # rows 0 to 2 turned white, row 3 not yet
    [255, 255, 255, 0]
    """

    def __init__(self, fb: FrameBuffer, previous: Optional[FrameBuffer] = None,
                 refresh_rate: float = 60.0, response_time: float = 0.004,
                 alternate: bool = False, dots: int = 4) -> None:
        super().__init__(fb, refresh_rate, dots)
        before = np.zeros_like(self.pixels) if previous is None else _rgb("previous", previous)
        if before.shape != self.pixels.shape:
            raise ArgumentValueError(
                f"previous is {before.shape[1]} x {before.shape[0]}; it must be the size of "
                f"fb, {self.width} x {self.height}")
        self.previous = before
        self.response_time = _positive("response_time", response_time)
        if not isinstance(alternate, bool):
            raise ArgumentTypeError(f"alternate must be True or False, got {v._show(alternate)}")
        self.alternate = alternate
        self.line_time = self.period / self.height
        self.row_starts = np.arange(self.height) * self.line_time

    def selected_row(self, t: float) -> int:
        """The row (from the top) whose select line is on at time ``t``."""
        return min(int((v.number("t", t) % self.period) // self.line_time), self.height - 1)

    def _picture(self, n: int) -> NDArray[np.float64]:
        """The picture written in refresh cycle ``n`` (-1: before the first)."""
        if n < 0 or (self.alternate and n % 2 == 1):
            return self.previous
        return self.pixels

    def screen(self, t: float) -> NDArray[np.uint8]:
        """The panel at time ``t``: each row turning from the value it held toward
        the value written at its last selection."""
        t = v.number("t", t)
        out = np.empty_like(self.pixels)
        for r, start in enumerate(self.row_starts):
            n = int(np.floor((t - start) / self.period))
            target = self._picture(n)[r]
            if n < 0:
                out[r] = target
                continue
            held = self._picture(n - 1)[r]
            elapsed = t - (start + n * self.period)
            out[r] = target + (held - target) * np.exp(-elapsed / self.response_time)
        return self._cells(out)

    def beam(self, t: float) -> Beam:
        """The selected row: ``(-0.5, y, "row select")``, at the row drivers on the
        left edge."""
        return -0.5, float(self.height - 1 - self.selected_row(t)), "row select"
