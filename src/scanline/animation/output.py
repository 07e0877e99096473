"""Animation output: GIF, APNG and WebP through Pillow, MP4 (H.264) through PyAV;
numbered frame files for long films; a Jupyter display.

>>> import scanline as sl
>>> def frame(i):
...     fb = sl.FrameBuffer(16, 8, mode="L")
...     sl.draw.line(fb, i, 0, i, 7, color=255)
...     return fb
>>> anim = sl.animation.Animation(frame, frames=16, fps=8)
>>> len(anim), anim.duration
(16, 2.0)
"""

from __future__ import annotations

import base64
import hashlib
import io
import math
import numbers
import os
import re
import string
from collections.abc import Sized
from fractions import Fraction
from typing import IO, TYPE_CHECKING, Any, Callable, Iterable, Iterator, Literal, Sequence, Union

import numpy as np
from PIL import Image

from .. import _validate as v
from ..budget import check
from ._checks import progress_flag
from ..errors import ArgumentTypeError, ArgumentValueError, OutputError
from ..framebuffer import write_atomically
from . import render as _render
from .render import Frame, RenderFunction, Stream

if TYPE_CHECKING:
    from distributed import Client
    from tqdm import tqdm

#: A file or folder argument.
PathArgument = Union[str, "os.PathLike[str]"]
#: Frames to save: (start, stop) or a slice of the frame numbers; None: all.
FrameSelection = Union[tuple[int, int], slice, None]
#: Output formats' names (the values of :data:`FORMATS`).
Kind = Literal["GIF", "APNG", "WebP", "MP4"]

#: Output formats by extension.
FORMATS: dict[str, Kind] = {".gif": "GIF", ".png": "APNG", ".apng": "APNG", ".webp": "WebP", ".mp4": "MP4"}

#: GIF stores delays in hundredths of a second and players show delays under 2/100 s
#: as 1/10 s, so a GIF cannot play faster than this.
GIF_MAX_FPS = 50.0


def frame_durations(count: int, fps: float, unit: int) -> list[int]:
    """Per-frame display times in multiples of ``unit`` milliseconds whose running
    sums stay within half a unit of the exact times i / fps, so that a GIF (10 ms
    units) or WebP (1 ms) keeps frame-exact timing over its whole length.

    >>> frame_durations(6, 24, 10)       # 24 fps in hundredths: 40, 40, 50, ...
    [40, 40, 50, 40, 40, 40]
    >>> sum(frame_durations(24, 24, 10))
    1000
    """
    edges = [math.floor(1000 * i / fps / unit + 0.5) * unit for i in range(count + 1)]
    return [b - a for a, b in zip(edges, edges[1:])]


#: GIF delays are 16-bit hundredths of a second (655.35 s at most): a GIF cannot play
#: slower than this (one frame every 600 s, so that the rounding of frame-exact
#: delays stays within the field).
GIF_MIN_FPS = 1 / 600

#: WebP times frames in 32-bit milliseconds.
WEBP_MAX_MS = 2**31 - 1

#: The most plays a GIF, APNG or WebP stores (16 bits); 0 plays forever.
MAX_LOOP = 65535

#: Frame file types of :meth:`Animation.write_frames`, by extension.
FRAME_FILES = {".png": "PNG", ".gif": "GIF", ".bmp": "BMP", ".webp": "WEBP", ".tif": "TIFF",
               ".tiff": "TIFF"}


def _path(name: str, value: PathArgument) -> str:
    """A file or folder argument as a string (refused: NUL bytes, non-paths)."""
    try:
        text = os.fspath(value)
    except TypeError:
        raise ArgumentTypeError(f"{name} must be a file path (str or os.PathLike), got "
                                f"{v._show(value)}") from None
    if isinstance(text, bytes):
        text = os.fsdecode(text)
    if not text or "\0" in text:
        raise ArgumentValueError(f"{name}={text!r} is not a file path")
    return text


def check_frames_memory(count: int, width: int, height: int, mode: str, kind: str,
                        argument: str = "frames", hint: str | None = None) -> None:
    """Refuse (MemoryBudgetError naming ``argument``) an animation of ``count``
    frames of ``width`` x ``height`` pixels in Pillow ``mode`` that a writer holding
    every frame (``kind``: GIF, APNG, WebP) could not hold: each frame's pixels, the
    copy Pillow converts or compares, and its own buffers."""
    bands = {"1": 1, "L": 1, "P": 1, "LA": 2, "RGB": 3, "RGBA": 4}.get(mode, 4)
    per_frame = width * height * (bands + 2) + 1024
    check(count * per_frame, argument,
          f"{count} frames of {width} x {height} {mode} held in memory for {kind} (its writer "
          "keeps every frame)",
          hint=hint or "save as .mp4 (encoded as the frames come, any length) or write "
                       "numbered files with write_frames, or save fewer frames "
                       "(frames=(start, stop))")


def check_pattern(pattern: object) -> str:
    """A frame-file ``pattern`` of :meth:`Animation.write_frames`: one field, the
    frame number (``{}``, ``{:05d}``, ``{0:6}``: digits, optionally zero-padded to a
    width), in a plain file name with an image extension.  Refused: a pattern
    without the field (every frame would overwrite one file), a fill character,
    sign or other spec that could make two numbers one name, and any folder part
    (``../x-{:05d}.png`` would write outside the folder)."""
    shown = v._show(pattern)
    if not isinstance(pattern, str):
        raise ArgumentTypeError(f"pattern must be a string such as 'frame-{{:05d}}.png', got "
                                f"{shown}")
    try:
        parts = list(string.Formatter().parse(pattern))
    except ValueError as error:
        raise ArgumentValueError(f"pattern={shown} must format a frame number, like "
                                 f"'frame-{{:05d}}.png' ({error})") from None
    fields = [(name, spec, conversion) for _, name, spec, conversion in parts
              if name is not None]
    if len(fields) != 1:
        raise ArgumentValueError(
            f"pattern={shown} must format a frame number: it has {len(fields)} fields, and "
            "needs exactly one, so that each frame has its own file, like 'frame-{:05d}.png'")
    name, spec, conversion = fields[0]
    if name not in ("", "0") or conversion or not re.fullmatch(r"(0?[1-9][0-9]?)?d?", spec or ""):
        raise ArgumentValueError(
            f"pattern={shown}: the field must be the frame number as digits, '{{}}' or "
            "'{:05d}' (a width up to 99, optionally zero-padded), so that every frame "
            "gets a different name")
    literal = "".join(text for text, *_ in parts)
    for bad in (os.sep, os.altsep, "\0"):
        if bad and bad in literal:
            raise ArgumentValueError(
                f"pattern={shown} names a folder; the pattern is a file name only (the "
                "frames go into folder): give folder='...' and pattern='frame-{:05d}.png'")
    first = pattern.format(0)
    ext = os.path.splitext(first)[1].lower()
    if ext not in FRAME_FILES:
        raise ArgumentValueError(f"pattern={shown}: frame files must be .png, .gif, "
                                 ".bmp, .webp or .tif")
    return pattern


class Animation:
    """A sequence of frames at a frame rate, to save or show.

    Parameters
    ----------
    source : sequence or callable
        The frames (FrameBuffers, Pillow images, uint8 arrays in image order, image
        file paths), or a *render function*, frame index -> frame, called for each
        frame as it is saved (here, in worker processes, or on a Dask cluster).
    fps : float
        Frames per second, > 0.
    frames : int, optional
        The number of frames a render function makes (default ``len(source)``).
    loop : int
        GIF, APNG and WebP: how many times to play; 0 (default) = forever.

    Raises
    ------
    ArgumentTypeError
        For a ``source`` that is neither a sequence nor a function, or a ``fps``,
        ``frames`` or ``loop`` that is not a number.
    ArgumentValueError
        For an empty ``source``, ``frames`` that disagrees with ``len(source)``, a render
        function without ``frames`` (and without ``len``), ``fps`` <= 0 or out of
        range, more than 2**31 - 1 frames, or ``loop`` over 65535.

    Examples
    --------
    ``Animation(render, frames=200, fps=25).save("out.gif", jobs=2)``;
    ``Animation([fb0, fb1, fb2], fps=2).save("out.png")``.  Two seconds of a render
    function at 12 frames a second:

    >>> import scanline as sl
    >>> def render(i):
    ...     fb = sl.FrameBuffer(8, 8, mode="L")
    ...     sl.draw.line(fb, 0, 0, 7, i % 8, color=255)
    ...     return fb
    >>> anim = sl.animation.Animation(render, frames=24, fps=12)
    >>> anim
    Animation(24 frames at 12 fps, 2 s)
    """

    def __init__(self, source: Sequence[Frame] | Callable[[int], Frame], fps: float = 24,
                 frames: int | None = None, loop: int = 0) -> None:
        from .timing import MAX_FRAMES, _fps

        self.fps = _fps(fps)
        self.loop = v.positive_int("loop", loop, minimum=0)
        if self.loop > MAX_LOOP:
            raise ArgumentValueError(f"loop={self.loop}: the formats store at most {MAX_LOOP} "
                                     "plays; give 0 to play forever")
        if frames is not None:
            frames = v.positive_int("frames", frames)
            if frames > MAX_FRAMES:
                raise ArgumentValueError(f"frames={frames:,} is more than the {MAX_FRAMES:,} "
                                         "frames a sequence may have")
        self.render: RenderFunction
        #: The number of frames.
        self.count: int
        if isinstance(source, (list, tuple)) or not callable(source):
            if isinstance(source, (str, bytes)) or not hasattr(source, "__len__"):
                raise ArgumentTypeError(f"source must be a sequence of frames or a render "
                                        f"function, got {v._show(source)}")
            items = list(source)
            if not items:
                raise ArgumentValueError("source is empty; an animation needs at least one frame")
            if frames is not None and frames != len(items):
                raise ArgumentValueError(f"source holds {len(items)} frames but frames={frames}")
            self.render = _Sequence(items)
            self.count = len(items)
        else:
            self.render = source
            if frames is None:
                if not isinstance(source, Sized):
                    raise ArgumentValueError(
                        "a render function needs the number of frames: "
                        "Animation(render, frames=N, fps=...)")
                frames = v.positive_int("len(source)", len(source))
                if frames > MAX_FRAMES:
                    raise ArgumentValueError(f"len(source) = {frames:,} is more than the "
                                             f"{MAX_FRAMES:,} frames a sequence may have")
            self.count = frames

    def __len__(self) -> int:
        return self.count

    @property
    def duration(self) -> float:
        """Seconds: frames / fps."""
        return self.count / self.fps

    def frame(self, index: int) -> Image.Image:
        """Frame ``index`` as a Pillow image.

        Parameters
        ----------
        index : int
            The frame number, 0 to ``len(self) - 1``.

        Returns
        -------
        PIL.Image.Image
            Of mode "L", "RGB", "RGBA" or "P" (a frame buffer of mode "1" gives "L",
            0 and 255).

        Raises
        ------
        ArgumentTypeError
            For an ``index`` that is not an integer.
        ArgumentValueError
            For an ``index`` out of range, or a frame that is not an image (see
            :class:`Animation`).

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> frames = [np.full((2, 3), 60 * i, np.uint8) for i in range(3)]
        >>> image = sl.animation.Animation(frames, fps=10).frame(2)
        >>> image.mode, image.size, image.getpixel((0, 0))
        ('L', (3, 2), 120)
        """
        index = v.positive_int("index", index, minimum=0)
        if index >= self.count:
            raise ArgumentValueError(f"index={index}: the animation has {self.count} frames")
        return _render.to_image(self.render(index), index)

    def _range(self, frames: FrameSelection) -> range:
        if frames is None:
            return range(self.count)
        if isinstance(frames, slice):
            for part in ("start", "stop", "step"):
                value = getattr(frames, part)
                if value is not None and (isinstance(value, bool)
                                          or not isinstance(value, numbers.Integral)):
                    raise ArgumentTypeError(f"frames={frames!r}: a slice of frame numbers "
                                            f"needs integers, got {part}={v._show(value)}")
            if frames.step == 0:
                raise ArgumentValueError(f"frames={frames!r}: a slice step cannot be zero")
            return range(self.count)[frames]
        if isinstance(frames, (str, bytes)) or not hasattr(frames, "__len__") \
                or len(frames) != 2:
            raise ArgumentTypeError(f"frames must be (start, stop) or a slice, got "
                                    f"{v._show(frames)}")
        start, stop = frames
        start = v.positive_int("frames start", start, minimum=0)
        stop = v.positive_int("frames stop", stop, minimum=0)
        if not start < stop <= self.count:
            raise ArgumentValueError(f"frames=({start}, {stop}) must satisfy 0 <= start < "
                                     f"stop <= {self.count} (the frame count)")
        return range(start, stop)

    def images(self, frames: FrameSelection = None, jobs: int = 1,
               client: Client | str | None = None, progress: bool | None = None
               ) -> Stream[Image.Image]:
        """Yield the frames as Pillow images in order (rendered here, in ``jobs``
        processes, or on the Dask ``client``).

        Parameters
        ----------
        frames : (start, stop) or slice, optional
            Only these frames (default all).
        jobs : int
            Render in this many processes.
        client : distributed.Client or str, optional
            Render on a Dask cluster (a client or a scheduler address).
        progress : bool, optional
            Show a progress bar (tqdm) on stderr; default: when stderr is a terminal
            and the render takes more than a moment.

        Yields
        ------
        PIL.Image.Image
            Each frame, in order.  The stream's ``close()`` stops the workers (also
            when it is closed before its first frame).

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            For bad ``frames``, ``jobs``, ``client`` or ``progress``, or a frame that is
            not an image.
        SchedulerUnreachable
            For a scheduler address that does not answer.

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> frames = [np.full((2, 3), 60 * i, np.uint8) for i in range(4)]
        >>> anim = sl.animation.Animation(frames, fps=10)
        >>> [image.getpixel((0, 0)) for image in anim.images(frames=(1, 3))]
        [60, 120]
        """
        return _stream(self.render, self._range(frames), jobs, client, progress)

    def save(self, path: PathArgument, jobs: int = 1, client: Client | str | None = None,
             progress: bool | None = None, frames: FrameSelection = None,
             quality: int | None = None) -> None:
        """Write the animation to ``path``, the format chosen by the extension.

        Parameters
        ----------
        path : str or os.PathLike
            ``.gif`` (Pillow; 256 colors per frame), ``.png`` or ``.apng`` (animated
            PNG, lossless), ``.webp`` (lossless unless ``quality`` is given), ``.mp4``
            (H.264 through PyAV; odd sizes are padded to even by repeating the last
            column or row, as yuv420p requires).
        jobs : int
            Render in this many processes.
        client : distributed.Client or str, optional
            Render on a Dask cluster (a client or a scheduler address).
        progress : bool, optional
            Show a progress bar (tqdm) on stderr; default: when stderr is a terminal
            and the render takes more than a moment.
        frames : (start, stop) or slice, optional
            Save only these frames.
        quality : int, optional
            WebP: 0-100 lossy quality (default lossless).  MP4: the x264 CRF, 0-51
            (default 18, visually lossless; 0 is lossless).

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            For a path without a known extension, an ``fps`` the format cannot play
            (GIF: 1/600 to 50), a ``quality`` out of range, bad ``frames``, ``jobs`` or
            ``client``, frames of different sizes, a frame that is not an image, or
            MP4 without PyAV.
        MemoryBudgetError
            For a GIF, APNG or WebP whose frames would not fit in memory (the writers
            hold every frame).
        OutputError
            When the file cannot be written.
        SchedulerUnreachable, WorkerLost
            For a Dask scheduler that does not answer, or frames whose workers died.

        Notes
        -----
        The write is atomic: an error or an interruption (Ctrl-C) leaves no file at
        ``path`` and stops the workers.  Timing is frame-exact: MP4 frames have
        timestamps i / fps exactly (a rational time base); GIF (10 ms units) and WebP
        (1 ms) durations are chosen so that frame i starts within half a unit of
        i / fps; APNG stores each delay as the exact fraction 1 / fps.  GIF, APNG and
        WebP store identical consecutive frames once, with their durations added.

        Examples
        --------
        Three frames at 10 fps: a GIF of three frames of 100 ms (ten hundredths) each.

        >>> import os, tempfile
        >>> import numpy as np
        >>> from PIL import Image
        >>> import scanline as sl
        >>> frames = [np.full((2, 3), 60 * i, np.uint8) for i in range(3)]
        >>> anim = sl.animation.Animation(frames, fps=10)
        >>> with tempfile.TemporaryDirectory() as folder:
        ...     path = os.path.join(folder, "fade.gif")
        ...     anim.save(path)
        ...     with Image.open(path) as gif:
        ...         print(gif.n_frames, gif.info["duration"])
        3 100
        """
        name = _path("path", path)
        ext = os.path.splitext(name)[1].lower()
        if ext not in FORMATS:
            raise ArgumentValueError(f"path={name!r}: no writer for {ext or 'a file without an extension'!r}; "
                                     f"use {', '.join(FORMATS)}")
        kind = FORMATS[ext]
        if kind == "GIF" and self.fps > GIF_MAX_FPS:
            raise ArgumentValueError(
                f"fps={self.fps:g} is too fast for GIF: its delays are in 1/100 s and players "
                f"show delays under 2/100 s as 1/10 s; use fps <= {GIF_MAX_FPS:g}, or .png, "
                ".webp or .mp4")
        if kind == "GIF" and self.fps < GIF_MIN_FPS:
            raise ArgumentValueError(
                f"fps={self.fps:g} is too slow for GIF: a frame's delay is at most 655.35 s; "
                f"use fps >= {GIF_MIN_FPS:.3g} (one frame every 600 s), or .png, .webp or .mp4")
        if kind == "MP4":
            _mp4_available()
            if quality is not None and not 0 <= v.positive_int("quality", quality, 0) <= 51:
                raise ArgumentValueError(f"quality for MP4 is the x264 CRF, 0..51; got {quality}")
        elif quality is not None and not 0 <= v.positive_int("quality", quality, 0) <= 100:
            raise ArgumentValueError(f"quality must be 0..100, got {quality}")
        indices = self._range(frames)
        if kind == "WebP" and len(indices) * 1000 / self.fps > WEBP_MAX_MS:
            raise ArgumentValueError(
                f"frames: {len(indices)} frames at fps={self.fps:g} last "
                f"{len(indices) / self.fps:g} s; a WebP animation holds at most "
                f"{WEBP_MAX_MS / 1000:g} s (its times are 32-bit milliseconds); save as .mp4")
        images = self.images(frames, jobs=jobs, client=client, progress=progress)
        writer = {"GIF": self._pillow, "APNG": self._pillow, "WebP": self._pillow,
                  "MP4": self._mp4}[kind]
        try:
            write_atomically(name, lambda f: writer(f, images, len(indices), kind, quality))
        finally:
            images.close()

    def _pillow(self, f: IO[bytes], images: Iterator[Image.Image], count: int, kind: Kind,
                quality: int | None) -> None:
        first = next(images)
        # Pillow's GIF, APNG and WebP writers hold every frame (GIF and APNG compare
        # each with the one before, WebP's encoder keeps them), and read them twice
        # (modes and sizes first), so they take a list: refused up front where it would
        # pass the memory budget (MP4 and numbered files stream any length)
        check_frames_memory(count, first.width, first.height, first.mode, kind)
        rest = list(_Checked(images, first.size))
        options: dict[str, Any] = {"save_all": True, "append_images": rest, "loop": self.loop}
        if kind == "GIF":
            options["duration"] = frame_durations(count, self.fps, 10)
            options["disposal"] = 1
            fmt = "GIF"
        elif kind == "APNG":
            options["duration"] = 1000.0 / self.fps
            fmt = "PNG"
        else:
            options["duration"] = frame_durations(count, self.fps, 1)
            options.update(lossless=quality is None, quality=100 if quality is None else quality,
                           method=4)
            fmt = "WEBP"
        if kind == "WebP" and first.mode not in ("RGB", "RGBA"):
            first = first.convert("RGBA" if first.mode == "P" and "transparency" in first.info
                                  else "RGB")
        first.save(f, format=fmt, **options)

    def _mp4(self, f: IO[bytes], images: Iterator[Image.Image], count: int, kind: Kind,
             quality: int | None) -> None:
        import av

        rate = Fraction(self.fps).limit_denominator(1_000_000)
        first = next(images)
        width, height = first.size
        with av.open(f, mode="w", format="mp4") as container:
            stream = container.add_stream("libx264", rate=rate)
            stream.width, stream.height = width + width % 2, height + height % 2
            stream.pix_fmt = "yuv420p"
            # frames count in 1 / fps; the muxer picks the file's own time base when it
            # writes the header (PyAV rescales the packets)
            tick = 1 / rate
            stream.time_base = tick
            stream.codec_context.time_base = tick
            # x264's macroblock-tree rate control gave different bytes from run to run
            # for the same frames (clips of a few dozen small frames, even on one
            # thread); without it the output is reproducible, for a few % of bitrate
            stream.options = {"crf": str(18 if quality is None else quality), "preset": "medium",
                              "x264-params": "mbtree=0"}
            for i, image in enumerate(_prepend(first, _Checked(images, first.size))):
                rgb = np.asarray(image.convert("RGB"))
                if width % 2 or height % 2:
                    rgb = np.pad(rgb, ((0, height % 2), (0, width % 2), (0, 0)), mode="edge")
                frame = av.VideoFrame.from_ndarray(rgb, format="rgb24")
                frame.pts = i
                frame.time_base = tick
                for packet in stream.encode(frame):
                    container.mux(packet)
            for packet in stream.encode():
                container.mux(packet)

    def write_frames(self, folder: PathArgument, pattern: str = "frame-{:05d}.png",
                     jobs: int = 1, client: Client | str | None = None,
                     progress: bool | None = None, frames: FrameSelection = None) -> list[str]:
        """Write each frame to its own image file in ``folder`` (created if needed),
        rendered and encoded by the workers themselves.

        This is how a long film is rendered on many machines: give a ``client`` whose
        workers see ``folder`` (shared storage); each worker writes its frames there
        (atomically) and sends back only the file's name and checksum; then
        ``Animation(sorted(paths), fps=...).save("film.mp4")`` encodes them.

        Parameters
        ----------
        folder : str or os.PathLike
            Where the files go (made if it does not exist).
        pattern : str
            The file name of frame i, ``pattern.format(i)``: one field, the frame
            number (``{}``, ``{:05d}``), and an image extension (.png, .gif, .bmp,
            .webp (lossless), .tif); no folder part.
        jobs : int
            Render and write in this many processes.
        client : distributed.Client or str, optional
            Render and write on a Dask cluster whose workers see ``folder``.
        progress : bool, optional
            Show a progress bar (tqdm) on stderr; default: when stderr is a terminal
            and the render takes more than a moment.
        frames : (start, stop) or slice, optional
            Write only these frames.

        Returns
        -------
        list of str
            The paths written, in frame order.

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            For a ``pattern`` without exactly one frame-number field, with a folder part
            or without an image extension, bad ``frames``, ``jobs`` or ``client``, or a
            frame that is not an image.
        MemoryBudgetError
            When the list of names alone would pass the memory budget.
        OutputError
            When the folder or a file cannot be written.
        SchedulerUnreachable, WorkerLost
            For a Dask scheduler that does not answer, or frames whose workers died.

        Examples
        --------
        >>> import os, tempfile
        >>> import numpy as np
        >>> import scanline as sl
        >>> frames = [np.full((2, 3), 60 * i, np.uint8) for i in range(3)]
        >>> anim = sl.animation.Animation(frames, fps=10)
        >>> with tempfile.TemporaryDirectory() as folder:
        ...     paths = anim.write_frames(folder, pattern="f{:02d}.png")
        ...     [os.path.basename(path) for path in paths]
        ['f00.png', 'f01.png', 'f02.png']
        """
        folder = _path("folder", folder)
        check_pattern(pattern)
        indices = self._range(frames)
        # the list of paths returned: a name and its string, about 100 bytes a frame
        check(len(indices) * (len(folder) + len(pattern) + 100), "frames",
              f"the names of {len(indices)} frame files",
              hint="write the film in parts (frames=(start, stop))")
        receipts = _stream(_FrameWriter(self.render, folder, pattern), indices, jobs, client,
                           progress)
        try:
            try:
                os.makedirs(folder, exist_ok=True)
            except OSError as error:
                raise OutputError(f"folder={folder!r}: cannot make the folder "
                                  f"({error.strerror or error})") from None
            return [os.path.join(folder, receipt.info["scanline_file"]) for receipt in receipts]
        finally:
            receipts.close()

    def _repr_html_(self) -> str:
        """Jupyter: the animation as an animated PNG in an <img> tag (the first 250
        frames when longer)."""
        buffer = io.BytesIO()
        count = min(self.count, 250)
        images = self.images((0, count), progress=False)
        try:
            self._pillow(buffer, images, count, "APNG", None)
        finally:
            images.close()
        data = base64.b64encode(buffer.getvalue()).decode("ascii")
        note = "" if count == self.count else f"<br><small>first {count} of {self.count} frames</small>"
        return f'<img src="data:image/png;base64,{data}" alt="animation">{note}'

    def __repr__(self) -> str:
        return f"Animation({self.count} frames at {self.fps:g} fps, {self.duration:g} s)"


class _Sequence:
    """A list of frames as a render function (picklable for workers)."""

    def __init__(self, items: list[Frame]) -> None:
        self.items = items

    def __call__(self, index: int) -> Frame:
        return self.items[index]

    def __len__(self) -> int:
        return len(self.items)


class _FrameWriter:
    """Render a frame, write it to ``folder`` atomically, return a 1x1 receipt image
    carrying the file name (so the worker sends back a few bytes, not the frame)."""

    def __init__(self, render: RenderFunction, folder: str, pattern: str) -> None:
        self.render, self.folder, self.pattern = render, folder, pattern

    def __call__(self, index: int) -> Image.Image:
        image = _render.to_image(self.render(index), index)
        name = self.pattern.format(index)
        if os.path.basename(name) != name or name in (".", ".."):    # (check_pattern)
            raise ArgumentValueError(f"pattern={self.pattern!r} makes {name!r} for frame "
                                     f"{index}, not a file name")
        out = io.BytesIO()
        fmt = FRAME_FILES[os.path.splitext(name)[1].lower()]
        image.save(out, format=fmt, **({"lossless": True} if fmt == "WEBP" else {}))
        data = out.getvalue()
        write_atomically(os.path.join(self.folder, name), lambda f: f.write(data))
        receipt = Image.new("L", (1, 1))
        receipt.info["scanline_file"] = name
        receipt.info["sha256"] = hashlib.sha256(data).hexdigest()
        return receipt


class _Checked:
    """Iterate images, checking that each has the first frame's size."""

    def __init__(self, images: Iterable[Image.Image], size: tuple[int, int]) -> None:
        self.images, self.size, self.index = images, size, 0

    def __iter__(self) -> Iterator[Image.Image]:
        for image in self.images:
            self.index += 1
            if image.size != self.size:
                raise ArgumentValueError(f"frame {self.index} is {image.size[0]}x{image.size[1]}, "
                                         f"frame 0 is {self.size[0]}x{self.size[1]}; every frame "
                                         "of an animation must have one size")
            yield image


def _stream(render: RenderFunction, indices: range, jobs: int, client: Client | str | None,
            progress: bool | None) -> Stream[Image.Image]:
    """The rendered frames ``indices`` in order, with a progress bar; closing the
    stream (started or not), or an error, stops the workers."""
    if not indices:
        raise ArgumentValueError("frames selects no frame")
    stream = _render.frames(render, indices, jobs=jobs, client=client)
    try:
        bar = _progress(progress, len(indices))
    except BaseException:
        stream.close()
        raise

    def run() -> Iterator[Image.Image]:
        try:
            for image in stream:
                yield image
                if bar is not None:
                    bar.update(1)
        finally:
            release()

    def release() -> None:
        close = getattr(stream, "close", None)
        if close is not None:
            close()
        if bar is not None:
            bar.close()
    return Stream(run(), release)


def _prepend(first: Image.Image, rest: Iterable[Image.Image]) -> Iterator[Image.Image]:
    yield first
    yield from rest


def _mp4_available() -> None:
    try:
        import av  # noqa: F401
    except ImportError:
        raise ArgumentValueError("writing .mp4 needs PyAV (which brings FFmpeg): pip install "
                                 "'scanline-graphics[video]', or save as .gif, .png or .webp") from None


def _progress(progress: object, total: int) -> tqdm[Any] | None:
    """A tqdm bar (shown after half a second, on a terminal unless forced), or None."""
    progress = progress_flag(progress)
    if progress is False:
        return None
    try:
        from tqdm.auto import tqdm
    except ImportError:
        if progress:
            raise ArgumentValueError("progress=True needs tqdm: pip install tqdm") from None
        return None

    # tqdm ships no type information (and no stubs are installed): its class is Any here
    class Bar(tqdm):  # type: ignore[misc]
        monitor_interval = 0       # no monitor thread: worker processes can still fork

    return Bar(total=total, unit="frame", desc="scanline", delay=0.5 if progress is None else 0,
               leave=False,
               disable=None if progress is None else not progress)
