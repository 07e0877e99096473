"""Refresh CRT simulations: the raster-scan and the random-scan display of the notes'
chapter 1, as frame sequences.

Both follow the beam through one refresh cycle after another and let the phosphor
fade between its visits.  *Persistence* is, as Hearn & Baker define it (section 2-1),
the time the emitted light takes to decay to one tenth of its intensity, so a spot
last excited ``dt`` seconds ago glows with ``10 ** (-dt / persistence)`` of its full
intensity.

:class:`RasterScan` (notes, chapter 1, Q.2): the beam sweeps the frame buffer one
scan line at a time from the top, left to right, returns to the left during the
*horizontal retrace* and to the top left after the last line during the *vertical
retrace*; an *interlaced* display refreshes the even scan lines in one field and the
odd ones in the next, each field taking half the refresh period.

:class:`RandomScan` (chapter 1, Q.3): the beam follows the display file's MOVE /
LINE commands in order (the :class:`~scanline.display.VectorDevice` listing), drawing
at its writing speed and jumping blanked between lines; the refresh cycle therefore
grows with the number and length of the lines, and a short cycle is delayed so that
the refresh rate never exceeds ``max_rate`` (60 per second in the notes: "faster
refreshing of the set of lines could burn out the phosphor").

The color CRTs (beam penetration and shadow mask, :mod:`scanline.display.color_crt`),
the direct-view storage tube (:mod:`scanline.display.storage_tube`) and the flat
panels (plasma and LCD, :mod:`scanline.display.flat_panel`) are simulated the same
way and can be imported from here too.

Each simulation gives the screen at any time (:meth:`screen`), the beam's position
(:meth:`beam`), a list of frames (:meth:`frames`) and a GIF (:meth:`save`, written
with Pillow).  Times are in seconds of simulated time; the frames show it slowed
down, ``frames_per_refresh`` frames per refresh cycle.
"""

import math
import os
from typing import IO, TYPE_CHECKING, Any, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..framebuffer import FrameBuffer, write_atomically

if TYPE_CHECKING:
    from .file import DisplayFile

#: Where the beam is: ``(x, y, state)`` in device units.
Beam = tuple[float, float, str]

#: Largest screen simulated, in pixels (before ``scale``).
MAX_PIXELS = 1024 * 1024
#: Most frames one call makes.
MAX_FRAMES = 2000
#: Largest scale factor of the frames.
MAX_SCALE = 16
#: Color of the beam spot and of its retrace path in the frames.
BEAM = (255, 255, 255)
RETRACE = (255, 64, 64)


def _fraction(name: str, value: object, low: float = 0.0, high: float = 1.0) -> float:
    x = v.number(name, value)
    if not low < x < high:
        raise ArgumentValueError(f"{name}={x} must be between {low} and {high} (exclusive)")
    return x


def _positive(name: str, value: object) -> float:
    x = v.number(name, value)
    if not 0 < x < 1e12:
        raise ArgumentValueError(f"{name}={x} must be a positive number of seconds or hertz")
    return x


def _count(name: str, value: object, high: int) -> int:
    n = v.positive_int(name, value)
    if n > high:
        raise ArgumentValueError(f"{name}={n} is too many; at most {high}")
    return n


def glow(elapsed: ArrayLike, persistence: float) -> NDArray[np.float64]:
    """The fraction of its full intensity a phosphor spot shows ``elapsed`` seconds
    after the beam excited it (``inf``: never, 0)."""
    with np.errstate(over="ignore", invalid="ignore"):
        g = np.power(10.0, -np.asarray(elapsed, np.float64) / persistence)
    return np.where(np.isfinite(elapsed), g, 0.0)


def last_visit(hit: NDArray[np.floating[Any]], period: float, t: float) -> NDArray[np.float64]:
    """The last time <= t at which the beam, passing at ``hit`` (seconds into every
    cycle of length ``period``), excited a spot; ``-inf`` before its first visit."""
    n = np.floor((t - hit) / period)
    return np.where(n >= 0, hit + n * period, -np.inf)


class _Simulation:
    """What every simulation shares: frames, scaled, with the beam, and a GIF.

    A subclass gives ``period`` (seconds per refresh cycle, or of the whole
    sequence shown), ``screen(t)`` (an image-order RGB array) and ``beam(t)``
    (``(x, y, state)`` in device units; state ``"off"``: no beam to draw); ``dots``
    is the number of screen pixels per device unit of its screen (a shadow mask or a
    flat panel draws each pixel as several)."""

    dots = 1
    width: int
    height: int
    period: float

    def screen(self, t: float) -> NDArray[np.uint8]:
        """The screen at time ``t``: an image-order uint8 RGB array (each subclass's)."""
        raise NotImplementedError

    def beam(self, t: float) -> Beam:
        """Where the beam is at time ``t`` (each subclass's)."""
        raise NotImplementedError

    def frames(self, frames_per_refresh: int = 24, refreshes: int = 1, scale: int = 1,
               beam: bool = True) -> list[NDArray[np.uint8]]:
        """The screen at ``frames_per_refresh`` evenly spaced times per refresh cycle,
        for ``refreshes`` cycles: a list of (height * scale, width * scale, 3) uint8
        arrays in image order, the beam's spot (and, on a retrace, its path) drawn
        on top when ``beam``."""
        per = _count("frames_per_refresh", frames_per_refresh, MAX_FRAMES)
        cycles = _count("refreshes", refreshes, MAX_FRAMES)
        if per * cycles > MAX_FRAMES:
            raise ArgumentValueError(
                f"frames_per_refresh * refreshes = {per * cycles} frames; at most {MAX_FRAMES}")
        scale = _count("scale", scale, MAX_SCALE)
        if not isinstance(beam, bool):
            raise ArgumentTypeError(f"beam must be True or False, got {v._show(beam)}")
        return [self.image(k * self.period / per, scale, beam) for k in range(per * cycles)]

    def image(self, t: float, scale: int = 1, beam: bool = True) -> NDArray[np.uint8]:
        """The screen at time ``t`` as an image-order RGB array, enlarged ``scale``
        times, with the beam drawn when ``beam``."""
        img = self.screen(t)
        if scale > 1:
            img = np.repeat(np.repeat(img, scale, axis=0), scale, axis=1)
        x, y, state = self.beam(t) if beam else (0.0, 0.0, "off")
        if state != "off":
            h = img.shape[0]
            k = scale * self.dots
            cx, cy = int(round((x + 0.5) * k - 0.5)), int(round(h - 1 - (y + 0.5) * k + 0.5))
            r = max(1, k)
            color = BEAM if state in ("drawing", "firing", "row select") else RETRACE
            img[max(cy - r, 0):max(cy + r + 1, 0), max(cx - r, 0):max(cx + r + 1, 0)] = color
        return img

    def save(self, path: Union[str, "os.PathLike[str]"], frames_per_refresh: int = 24,
             refreshes: int = 1, scale: int = 1, fps: float = 12) -> None:
        """Write the frames as an animated GIF (Pillow), atomically; ``fps`` frames
        per second of playback."""
        from PIL import Image

        fps = v.number("fps", fps)
        if not 0 < fps <= 100:
            raise ArgumentValueError(f"fps={fps} must be > 0 and at most 100")
        images = [Image.fromarray(f) for f in self.frames(frames_per_refresh, refreshes, scale)]

        def write(f: IO[bytes]) -> None:
            images[0].save(f, format="GIF", save_all=True, append_images=images[1:],
                           duration=int(round(1000 / fps)), loop=0)

        write_atomically(path, write)


class RasterScan(_Simulation):
    """A raster-scan refresh display showing a frame buffer.

    Parameters
    ----------
    fb : FrameBuffer
        The refresh buffer; its pixels are the intensities the beam writes (mode
        ``"P"`` through its color table).
    refresh_rate : float
        Frames per second (60 to 80 in the notes).
    interlaced : bool
        Refresh the even scan lines (from the top: 0, 2, 4 ...) in one field and the
        odd ones in the next, each in half the period.
    persistence : float
        Seconds for the phosphor to decay to a tenth of its intensity.
    horizontal_retrace : float
        The fraction of each scan line's time spent returning to the left.
    vertical_retrace : float
        The vertical retrace's time as a fraction of a field (or frame) time.

    Attributes
    ----------
    period : float
        Seconds per refresh cycle (1 / refresh_rate).
    line_time : float
        Seconds per scan line, retrace included.
    hits : ndarray (height, width)
        When, in seconds into each cycle, the beam passes each pixel (image order).

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(4, 2, mode="L", background=255)
    >>> scan = RasterScan(fb, refresh_rate=50, horizontal_retrace=0.2, vertical_retrace=0.2)
    >>> round(scan.line_time * 1e3, 3), scan.beam(0.0)
    (8.0, (-0.5, 1.0, 'drawing'))
    >>> scan.beam(0.0072)[2], scan.beam(0.0175)[2]
    ('horizontal retrace', 'vertical retrace')
    """

    def __init__(self, fb: FrameBuffer, refresh_rate: float = 60.0, interlaced: bool = False,
                 persistence: float = 0.02, horizontal_retrace: float = 0.2,
                 vertical_retrace: float = 0.05) -> None:
        if not isinstance(fb, FrameBuffer):
            raise ArgumentTypeError(f"fb must be a scanline.FrameBuffer, got {v._show(fb)}")
        if fb.width * fb.height > MAX_PIXELS:
            raise ArgumentValueError(
                f"the frame buffer has {fb.width} x {fb.height} pixels; a simulation takes at "
                f"most {MAX_PIXELS}")
        if not isinstance(interlaced, bool):
            raise ArgumentTypeError(f"interlaced must be True or False, got {v._show(interlaced)}")
        self.refresh_rate = _positive("refresh_rate", refresh_rate)
        self.persistence = _positive("persistence", persistence)
        self.horizontal_retrace = _fraction("horizontal_retrace", horizontal_retrace)
        self.vertical_retrace = _fraction("vertical_retrace", vertical_retrace)
        self.interlaced = interlaced
        self.width, self.height = fb.width, fb.height
        self.period = 1.0 / self.refresh_rate
        self.pixels = np.asarray(fb.to_pil().convert("RGB"), np.float64)
        fields = 2 if interlaced else 1
        self.field_time = self.period / fields
        self.lines_per_field = -(-self.height // fields)
        self.line_time = self.field_time * (1 - self.vertical_retrace) / self.lines_per_field
        rows = np.arange(self.height)
        field, line = (rows % 2, rows // 2) if interlaced else (0 * rows, rows)
        start = field * self.field_time + line * self.line_time
        active = self.line_time * (1 - self.horizontal_retrace)
        self.hits = start[:, None] + (np.arange(self.width)[None, :] + 0.5) / self.width * active

    def screen(self, t: float) -> NDArray[np.uint8]:
        """The glow of every pixel at time ``t``: an image-order uint8 RGB array."""
        t = v.number("t", t)
        g = glow(t - last_visit(self.hits, self.period, t), self.persistence)
        return np.clip(np.rint(self.pixels * g[..., None]), 0, 255).astype(np.uint8)

    def beam(self, t: float) -> Beam:
        """Where the beam is at time ``t``: ``(x, y, state)`` in device coordinates (y up;
        y may lie between scan lines on a retrace), ``state`` one of ``"drawing"``,
        ``"horizontal retrace"``, ``"vertical retrace"``."""
        t = v.number("t", t) % self.period
        fields = 2 if self.interlaced else 1
        field = min(int(t // self.field_time), fields - 1)
        s = t - field * self.field_time
        line = int(s // self.line_time)
        u = (s - line * self.line_time) / self.line_time
        step = fields
        if line >= self.lines_per_field or field * 1 + line * step >= self.height:
            # from the end of the last line back to the top left of the next field
            w = (s - self.lines_per_field * self.line_time) / (self.period / fields
                                                               - self.lines_per_field * self.line_time)
            w = min(max(w, 0.0), 1.0)
            last = self.height - 1 if not self.interlaced else (
                field + step * ((self.height - 1 - field) // step))
            top = (field + 1) % fields
            row = last + (top - last) * w
            x = (self.width - 1) * (1 - w)
            return float(x), float(self.height - 1 - row), "vertical retrace"
        row = field + line * step
        a = 1 - self.horizontal_retrace
        if u < a:
            return float(u / a * self.width - 0.5), float(self.height - 1 - row), "drawing"
        w = (u - a) / self.horizontal_retrace
        return (float((self.width - 1) * (1 - w)), float(self.height - 1 - row - step * w),
                "horizontal retrace")


def bit_planes(fb: FrameBuffer) -> NDArray[np.bool_]:
    """The stored values of ``fb`` (mode ``"1"``, ``"L"`` or ``"P"``) split into bit
    planes: a (bits, height, width) bool array, plane k = bit k (image order).

    >>> import scanline as sl
    >>> bit_planes(sl.FrameBuffer.from_array(np.array([[0, 5, 255]], np.uint8)))[:3, 0].tolist()
    [[False, True, True], [False, False, True], [False, True, True]]
    """
    if not isinstance(fb, FrameBuffer):
        raise ArgumentTypeError(f"fb must be a scanline.FrameBuffer, got {v._show(fb)}")
    if fb.mode not in ("1", "L", "P"):
        raise ArgumentValueError(
            f"bit planes are those of a frame buffer of one value per pixel (mode '1', 'L' or "
            f"'P'), got mode {fb.mode!r}")
    a = fb.to_array().astype(np.uint8)
    bits = 1 if fb.mode == "1" else 8
    return np.stack([(a >> k) & 1 for k in range(bits)]).astype(bool)


class RandomScan(_Simulation):
    """A random-scan (vector) refresh display following a display file.

    Parameters
    ----------
    display_file : DisplayFile
        Interpreted onto a :class:`~scanline.display.VectorDevice`; the beam follows
        its MOVE / LINE commands in order.
    width, height : int
        The addressable area, in device units.
    writing_speed : float
        Device units per second the beam draws at.
    jump_speed : float
        Device units per second of a blanked move (MOVE).
    settle_time : float
        Seconds each command takes besides its travel (the deflection settling).
    max_rate : float
        The highest refresh rate: a shorter cycle waits to take 1 / max_rate.
    persistence : float
        Seconds for the phosphor to decay to a tenth.

    Attributes
    ----------
    commands : list
        The beam commands of the display file.
    drawing_time : float
        Seconds one pass over the commands takes.
    period : float
        The refresh cycle: ``max(drawing_time, 1 / max_rate)``.
    refresh_rate : float
        1 / period.

    Examples
    --------
    >>> import scanline as sl
    >>> df = sl.DisplayFile()
    >>> df.set_viewing(window=(0, 0, 100, 100))
    >>> df.create_segment("a")
    >>> df.polyline([(0, 0), (100, 0), (100, 100)])
    >>> df.close_segment()
    >>> scan = RandomScan(df, 101, 101, writing_speed=1e4, settle_time=0.0)
    >>> round(scan.drawing_time, 6)   # 200 units drawn at 10^4 /s, a 100-unit jump at 2 10^6 /s
    0.02005
    >>> fast = RandomScan(df, 101, 101, writing_speed=1e5, settle_time=0.0)
    >>> round(fast.drawing_time, 6), fast.refresh_rate   # done in 2 ms: held at 60 per second
    (0.00205, 60.0)
    """

    def __init__(self, display_file: "DisplayFile", width: int, height: int,
                 writing_speed: float = 2e5, jump_speed: float = 2e6, settle_time: float = 2e-6,
                 max_rate: float = 60.0, persistence: float = 0.02) -> None:
        from .devices import VectorDevice
        from .interpreter import interpret
        from .pick import device_size

        width, height = device_size((width, height))
        if width * height > MAX_PIXELS:
            raise ArgumentValueError(
                f"the screen is {width} x {height}; a simulation takes at most {MAX_PIXELS} "
                "pixels")
        self.width, self.height = width, height
        self.writing_speed = _positive("writing_speed", writing_speed)
        self.jump_speed = _positive("jump_speed", jump_speed)
        settle = v.number("settle_time", settle_time)
        if not 0 <= settle < 1:
            raise ArgumentValueError(f"settle_time={settle} must be >= 0 and < 1 second")
        self.settle_time = settle
        self.max_rate = _positive("max_rate", max_rate)
        self.persistence = _positive("persistence", persistence)
        device = VectorDevice(width, height)
        interpret(display_file, device)
        self.commands = device.commands
        self._trace()

    def _trace(self) -> None:
        """The beam's path: for each command its start time, end time, start and end
        point and color; and sample points along every line with their hit times."""
        t, beam, color = 0.0, (0.0, float(self.height - 1)), (255, 255, 255)
        path, pts, times, colors = [], [], [], []
        for cmd in self.commands:
            if cmd[0] == "COLOR":
                color = self._beam_color(cmd[1:4])
                continue
            end = (float(cmd[1]), float(cmd[2]))
            length = math.hypot(end[0] - beam[0], end[1] - beam[1])
            drawing = cmd[0] == "LINE"
            travel = length / (self.writing_speed if drawing else self.jump_speed)
            path.append((t, t + self.settle_time + travel, beam, end, drawing))
            if drawing:
                n = max(int(math.ceil(length * 2)), 1) + 1
                s = np.linspace(0.0, 1.0, n)
                pts.append(np.stack([beam[0] + s * (end[0] - beam[0]),
                                     beam[1] + s * (end[1] - beam[1])], axis=1))
                times.append(t + self.settle_time + s * travel)
                colors.append(np.tile(np.array(color, np.float64), (n, 1)))
            t += self.settle_time + travel
            beam = end
        self.drawing_time = t
        self.period = max(t, 1.0 / self.max_rate)
        self.refresh_rate = 1.0 / self.period
        self._path = path
        if pts:
            p = np.rint(np.vstack(pts)).astype(np.int64)
            keep = (p[:, 0] >= 0) & (p[:, 0] < self.width) & (p[:, 1] >= 0) & (p[:, 1] < self.height)
            self._spots = p[keep]
            self._times = np.concatenate(times)[keep]
            self._colors = np.vstack(colors)[keep]
        else:
            self._spots = np.zeros((0, 2), np.int64)
            self._times = np.zeros(0)
            self._colors = np.zeros((0, 3))

    def _beam_color(self, rgb: tuple[int, int, int]) -> tuple[int, int, int]:
        """The color the phosphor shows for a COLOR command's (r, g, b)."""
        return rgb

    def screen(self, t: float) -> NDArray[np.uint8]:
        """The glow of the screen at time ``t``: an image-order uint8 RGB array (each
        spot the brightest of the line samples on it)."""
        t = v.number("t", t)
        g = glow(t - last_visit(self._times, self.period, t), self.persistence)
        value = self._colors * g[:, None]
        img = np.zeros((self.height, self.width, 3))
        rows = self.height - 1 - self._spots[:, 1]
        for c in range(3):
            np.maximum.at(img[:, :, c], (rows, self._spots[:, 0]), value[:, c])
        return np.clip(np.rint(img), 0, 255).astype(np.uint8)

    def beam(self, t: float) -> Beam:
        """``(x, y, state)``: the beam at time ``t``, ``state`` ``"drawing"`` (a LINE),
        ``"moving"`` (a blanked MOVE) or ``"waiting"`` (the delay that holds the
        refresh rate at ``max_rate``, or settling)."""
        t = v.number("t", t) % self.period
        for start, end, a, b, drawing in self._path:
            if start <= t < end:
                travel = end - start - self.settle_time
                w = 0.0 if travel <= 0 else min(max((t - start - self.settle_time) / travel, 0.0), 1.0)
                state = ("drawing" if drawing else "moving") if t >= start + self.settle_time \
                    else "waiting"
                return (a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]), state)
        last = self._path[-1][3] if self._path else (0.0, float(self.height - 1))
        return (float(last[0]), float(last[1]), "waiting")


_MORE = {"BeamPenetration": "color_crt", "ShadowMask": "color_crt", "StorageTube": "storage_tube",
         "PlasmaPanel": "flat_panel", "LCD": "flat_panel"}


def __getattr__(name: str) -> Any:
    """The other devices' simulations, from their modules (which import this one)."""
    if name in _MORE:
        import importlib

        return getattr(importlib.import_module(f".{_MORE[name]}", __package__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
