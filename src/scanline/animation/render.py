"""Rendering frames: in this process, in worker processes (``jobs=N``), or on a Dask
distributed cluster (``client=``), gathered in frame order.

A *render function* takes a frame index and returns the frame: a
:class:`~scanline.FrameBuffer`, a Pillow image, a uint8 numpy array in image order
(top row first) or the path of an image file.  Frames are rendered in chunks of
consecutive indices; each worker renders a chunk and sends back Pillow images, which
this process yields in order, whoever rendered them and in whatever order they
finished.  The pixels do not depend on where a frame was rendered, so an animation
saved from a serial, a multi-process or a cluster render is the same file, byte for
byte.

Interrupting (Ctrl-C) or any error stops the workers: the process pool is
terminated, the cluster's pending tasks are cancelled.
"""

from __future__ import annotations

import collections
import mmap
import multiprocessing.context
import multiprocessing.pool
import os
import pickle
import re
import signal
import threading
import time
import typing
from types import MappingProxyType, ModuleType
from typing import Any, Callable, Generator, Generic, Iterable, Iterator, NoReturn, Sequence, TypeVar

import numpy as np
from numpy.typing import NDArray
from PIL import Image

from .. import _validate as v
from .._kernels._threads import one_thread
from ..errors import ArgumentTypeError, ArgumentValueError, ScanlineError

if typing.TYPE_CHECKING:
    from distributed import Client, Future

    from ..framebuffer import FrameBuffer

#: A frame: a frame buffer, a Pillow image, a uint8 (h, w), (h, w, 3) or (h, w, 4) or a
#: bool (h, w) array in image order, or the path of an image file.
Frame = typing.Union["FrameBuffer", Image.Image, NDArray[np.uint8], NDArray[np.bool_], str,
                     "os.PathLike[str]"]
#: A render function: frame index -> frame (anything :func:`to_image` takes).
RenderFunction = Callable[[int], object]

#: Seconds to wait for a Dask scheduler given by address.
CONNECT_TIMEOUT = 10.0

#: Dask settings under which a worker's own threads keep out of the frames' way: set
#: them where the workers start (``with dask.config.set(QUIET_WORKERS):`` around a
#: ``LocalCluster``, or :func:`worker_environment` for ``dask worker`` processes).
#: While another thread of a worker waits for the interpreter lock -- the event loop
#: at each ``tick`` (every 20 ms by default), the statistical profiler at each sample
#: (every 10 ms) -- every brief release of the lock by the frame's thread (numpy's
#: fancy indexing, ``arange``, a compiled kernel) wakes it, and it finds the lock
#: taken again; a frame of the scaling benchmark took 1.2x its time in a plain process
#: with Dask's defaults and 1.0x with these (``docs/animation.md``).  The tick only
#: measures how long the event loop was blocked, the monitors feed the dashboard and
#: the memory limits (checked every 5 s instead of 0.1 s), and the profile only the
#: dashboard's profile page.
QUIET_WORKERS: typing.Mapping[str, object] = MappingProxyType({
    "distributed.admin.tick.interval": "1s",
    "distributed.worker.profile.enabled": False,
    "distributed.admin.system-monitor.interval": "5s",
    "distributed.worker.memory.monitor-interval": "5s",
})


def worker_environment() -> dict[str, str]:
    """:data:`QUIET_WORKERS` as environment variables, for workers started by
    ``dask worker`` (or a job script) rather than from this process.

    Returns
    -------
    dict
        Variable name to value, as Dask reads them (``DASK_`` and the setting's
        path, ``__`` between its parts).

    Examples
    --------
    >>> from scanline.animation import worker_environment
    >>> worker_environment()["DASK_DISTRIBUTED__WORKER__PROFILE__ENABLED"]
    'False'
    """
    return {"DASK_" + key.upper().replace(".", "__").replace("-", "_"): str(value)
            for key, value in QUIET_WORKERS.items()}


class SchedulerUnreachable(ScanlineError):
    """A Dask scheduler address that does not answer."""


def to_image(frame: object, index: int | None = None) -> Image.Image:
    """A frame as a Pillow image of mode "L", "RGB", "RGBA" or "P".

    Accepts a :class:`~scanline.FrameBuffer` (mode "1" becomes "L" 0/255), a Pillow
    image, a numpy array in image order (bool, or uint8 (h, w), (h, w, 3), (h, w, 4))
    or the path of an image file.  An empty frame (no rows or no columns) is an
    ArgumentValueError naming the frame.
    """
    from ..framebuffer import FrameBuffer

    what = "frame" if index is None else f"frame {index}"
    if isinstance(frame, FrameBuffer):
        image = frame.to_pil()
    elif isinstance(frame, Image.Image):
        image = frame
    elif isinstance(frame, (str, os.PathLike)):
        try:
            with Image.open(frame) as opened:
                image = opened.copy()
        except (OSError, ValueError) as error:
            raise ArgumentValueError(f"{what}: {os.fspath(frame)!r} cannot be read as an "
                                     f"image file: {error}") from None
    elif isinstance(frame, np.ndarray):
        a = frame
        if a.dtype == bool:
            a = a.astype(np.uint8) * 255
        if a.dtype != np.uint8 or a.ndim not in (2, 3) or (a.ndim == 3 and a.shape[2] not in (3, 4)):
            raise ArgumentValueError(f"{what} must be a uint8 array (h, w), (h, w, 3) or "
                                     f"(h, w, 4) in image order, got dtype {a.dtype}, shape {a.shape}")
        image = Image.fromarray(np.ascontiguousarray(a))
    else:
        raise ArgumentTypeError(f"{what} must be a FrameBuffer, a PIL image, a numpy array "
                                f"or an image file path, got {type(frame).__name__}")
    if image.width == 0 or image.height == 0:
        raise ArgumentValueError(f"{what} is empty ({image.width} x {image.height} pixels); "
                                 "a frame needs at least one pixel")
    if image.mode == "1":
        image = image.convert("L")
    elif image.mode not in ("L", "RGB", "RGBA", "P"):
        has_alpha = "A" in image.getbands() or "transparency" in image.info
        image = image.convert("RGBA" if has_alpha else "RGB")
    image.load()
    return image


def render_chunk(render: RenderFunction, indices: Iterable[int], compress: bool = False,
                 slots: _Slots | str | None = None, slot: int | None = None) -> list[Packed]:
    """Render the frames ``indices`` with ``render`` (what one worker does with one
    chunk): a list of packed frames, see :func:`pack`.  Each frame's pixels are taken
    away before the next frame is rendered (a render function may draw every frame
    into one frame buffer): copied into ``slot`` of the shared memory ``slots`` (see
    :class:`_Slots`; given by its file's path, a Dask worker opens it, if it can),
    else, with ``compress`` (a Dask worker sending to a client that can read LZ4),
    LZ4-compressed, else copied.  A frame buffer's pixels are read where they are,
    never copied first: a Dask worker's process gives freed memory back to the
    system at once (Dask's nanny sets ``MALLOC_TRIM_THRESHOLD_``), so every megabyte
    copied is a megabyte of fresh pages, about 2 ms of a 640 x 480 frame's 20 in
    page faults for the copy and the frame buffer together."""
    lz4 = _lz4() if compress else None
    opened = None
    if isinstance(slots, str):
        opened = slots = _Slots.attach(slots)
    out: list[Packed] = []
    # (a slot comes with slots)
    offset = None if slots is None or slot is None else slot * SLOT_BYTES
    try:
        with one_thread():
            for i in indices:
                array, mode, palette, info = pack(render(int(i)), int(i))
                placed = None
                if slots is not None and offset is not None and slot is not None \
                        and slots.fits(array, offset, slot):
                    placed = slots.put(array, offset)
                pixels: FramePixels
                if placed is not None and offset is not None:
                    pixels, offset = placed, offset + array.nbytes
                elif lz4 is not None:
                    pixels = Compressed.of(lz4, array)
                else:
                    pixels = np.array(array)
                out.append((pixels, mode, palette, info))
    finally:
        if opened is not None:
            opened.close()
    return out


def _lz4() -> ModuleType | None:
    """The ``lz4.block`` module, or None when lz4 is not installed (it comes with
    ``scanline-graphics[dask]``)."""
    try:
        import lz4.block
    except ImportError:
        return None
    module: ModuleType = lz4.block
    return module


class InMemory(typing.NamedTuple):
    """Where a worker put a frame's pixels in the shared memory of :class:`_Slots`."""
    offset: int
    shape: tuple[int, ...]
    dtype: str


class Compressed(typing.NamedTuple):
    """A frame's pixels LZ4-compressed for the network.  The frames of a drawn scene
    are mostly flat color: a 640 x 480 RGB frame of a few hundred primitives is about
    12 times smaller, compressed in about 0.3 ms and decompressed in less, while
    sending its 0.9 MB between processes costs each side more (Collet, LZ4, 2011).
    ``bottom_up``: the rows are stored bottom row first, as a frame buffer keeps
    them (compressed from its storage without a copy; Pillow's raw decoder turns
    them over as it reads them)."""
    data: bytes
    shape: tuple[int, ...]
    dtype: str
    bottom_up: bool = False

    @classmethod
    def of(cls, lz4: ModuleType, pixels: NDArray[np.uint8]) -> Compressed:
        """``pixels`` (an image-order array) compressed with the ``lz4.block``
        module, from the bottom-up storage they view where they are one."""
        flipped = pixels[::-1]
        bottom_up = pixels.strides[0] < 0 and flipped.flags.c_contiguous
        stored = flipped if bottom_up else np.ascontiguousarray(pixels)
        return cls(lz4.compress(stored, store_size=True), pixels.shape, pixels.dtype.str,
                   bool(bottom_up))


#: Frame buffer modes whose pixels (``FrameBuffer.to_array``) are their Pillow image's.
_DIRECT = ("L", "RGB", "RGBA")

#: A frame's pixels on their way from a worker: an array, where they are in shared
#: memory, or compressed.
FramePixels = typing.Union[NDArray[np.uint8], InMemory, Compressed]
#: Pillow's ``Image.info``.
ImageInfo = dict[typing.Union[str, tuple[int, int]], Any]
#: A packed frame: (pixels, mode, palette, info), see :func:`pack`.
Packed = tuple[FramePixels, str, typing.Optional[list[int]], ImageInfo]


def pack(frame: object, index: int | None = None
         ) -> tuple[NDArray[np.uint8], str, list[int] | None, ImageInfo]:
    """A frame (anything :func:`to_image` takes) as (pixels, mode, palette, info): a
    numpy array travels between processes without the copies a pickled image takes
    (and Dask sends it as one buffer).  A frame buffer of mode "L", "RGB" or "RGBA"
    is sent as its pixels, without making its Pillow image first: ``pixels`` is then
    a read-only view of the frame buffer (``np.asarray``), valid until it is drawn
    on again."""
    from ..framebuffer import FrameBuffer

    if isinstance(frame, FrameBuffer) and frame.mode in _DIRECT:
        return np.asarray(frame), frame.mode, None, {}
    image = to_image(frame, index)
    palette = image.getpalette() if image.mode == "P" else None
    return np.asarray(image), image.mode, palette, dict(image.info)


def unpack(packed: Packed, memory: mmap.mmap | None = None) -> Image.Image:
    """The Pillow image of a :func:`pack` (whose pixels may have been put in the
    shared ``memory`` of :class:`_Slots`: they are copied out)."""
    pixels, mode, palette, info = packed
    h, w = pixels.shape[:2]
    data: bytes | memoryview
    if isinstance(pixels, Compressed):
        lz4 = _lz4()
        assert lz4 is not None      # (frames are compressed for a client that has lz4)
        data, orientation = lz4.decompress(pixels.data), -1 if pixels.bottom_up else 1
    else:
        if isinstance(pixels, InMemory):
            pixels = np.ndarray(pixels.shape, pixels.dtype, buffer=memory, offset=pixels.offset)
        data, orientation = np.ascontiguousarray(pixels).data, 1
    image = Image.frombytes(mode, (w, h), data, "raw", mode, 0, orientation)
    if palette is not None:
        image.putpalette(palette)
    image.info.update(info)
    return image


def chunks(indices: Iterable[int], parts: int) -> list[Sequence[int]]:
    """``indices`` cut into consecutive chunks for ``parts`` workers, largest first
    (guided self-scheduling, Polychronopoulos & Kuck 1987): each chunk takes about a
    quarter of the frames left per worker, at most 16, so that the overhead per task stays small while most frames
    are left, and the last chunks are single frames, so that the workers finish
    within about one frame of each other and the output streams.  A list; the
    renderers take them one at a time from :func:`iter_chunks`."""
    return list(iter_chunks(indices, parts))


def iter_chunks(indices: Iterable[int], parts: int) -> Iterator[Sequence[int]]:
    """The chunks of :func:`chunks`, made as they are asked for: a film of 10**9
    frames is a ``range`` and its chunks are ranges, so no list of frames or chunks
    is ever made."""
    frames = indices if isinstance(indices, range) else list(indices)
    start, total = 0, len(frames)
    while start < total:
        size = max(1, min(16, (total - start) // (4 * parts)))
        yield frames[start:start + size]
        start += size


_T = TypeVar("_T")


class Stream(Generic[_T]):
    """The frames of a render, one by one, with a ``close()`` that releases what the
    render holds (worker processes, shared memory, a cluster connection) whether or
    not the frames have started coming (closing a generator that never started runs
    none of its ``finally`` clauses)."""

    def __init__(self, frames: Iterator[_T], release: Callable[[], None] | None = None) -> None:
        self._frames, self._release = frames, release

    def __iter__(self) -> Stream[_T]:
        return self

    def __next__(self) -> _T:
        return next(self._frames)

    def close(self) -> None:
        try:
            close = getattr(self._frames, "close", None)
            if close is not None:
                close()
        finally:
            release, self._release = self._release, None
            if release is not None:
                release()


# -- worker processes --------------------------------------------------------------------------
_WORKER_RENDER: RenderFunction | None = None


def _dumps(render: RenderFunction) -> bytes:
    """``render`` serialized for worker processes: cloudpickle when it is installed
    (it ships with Dask; lambdas and closures then work), else pickle."""
    try:
        import cloudpickle
        data: bytes = cloudpickle.dumps(render)
        return data
    except ImportError:
        pass
    try:
        return pickle.dumps(render)
    except (pickle.PicklingError, AttributeError, TypeError) as error:
        raise ArgumentValueError(
            f"render={v._show(render)} cannot be sent to worker processes ({error}); with "
            "jobs > 1 use a module-level function or a picklable object, or install "
            "cloudpickle") from None


_WORKER_ERROR: str | None = None


class _Slots:
    """Shared memory for the frames of the chunks in flight, one slot of
    :data:`SLOT_BYTES` per chunk.  A worker copies the chunk's pixels into its slot
    and sends only where they are; this process makes the images from there.
    (Through the pool's pipe a 640 x 480 RGB frame costs each side about 3 ms of
    processor time, more than an eighth of drawing a frame of a few hundred
    primitives; through a Dask worker's TCP connection, LZ4-compressed, about 1 ms.)

    Two kinds: an anonymous shared mapping made before the worker processes are
    forked (``_Slots(count)``), or a file in the machine's shared memory, /dev/shm
    (:meth:`in_shared_file`), that a Dask worker opens by name (:meth:`attach`) when
    it runs on this machine.  The pages are only made when written; a file's are
    reserved first (``posix_fallocate``), so that a full /dev/shm is an error the
    worker sees (the frame then goes another way), not a crash on the write.  Pixels
    that do not fit in the slot go another way too."""

    def __init__(self, count: int, memory: mmap.mmap | None = None, fd: int | None = None,
                 path: str | None = None) -> None:
        self.count = count
        self.memory = mmap.mmap(-1, count * SLOT_BYTES) if memory is None else memory
        self.fd = fd
        self.path = path

    @classmethod
    def in_shared_file(cls, count: int) -> _Slots | None:
        """Slots in a new file of /dev/shm (readable by this user only), or None where
        there is none (not Linux) or it cannot be made."""
        import secrets

        folder = "/dev/shm"
        if not (os.path.isdir(folder) and hasattr(os, "posix_fallocate")):
            return None
        path = os.path.join(folder, f"scanline-frames-{secrets.token_hex(8)}")
        try:
            fd = os.open(path, os.O_CREAT | os.O_EXCL | os.O_RDWR, 0o600)
        except OSError:
            return None
        try:
            os.ftruncate(fd, count * SLOT_BYTES)
            return cls(count, mmap.mmap(fd, count * SLOT_BYTES), fd, path)
        except OSError:
            os.close(fd)
            os.unlink(path)
            return None

    @classmethod
    def attach(cls, path: str) -> _Slots | None:
        """The slots of the file ``path`` that :meth:`in_shared_file` made (worker
        side), or None when this process cannot open it (another machine, or another
        /dev/shm)."""
        try:
            fd = os.open(path, os.O_RDWR)
        except OSError:
            return None
        try:
            size = os.fstat(fd).st_size
            return cls(size // SLOT_BYTES, mmap.mmap(fd, size), fd)
        except (OSError, ValueError):        # (an empty file cannot be mapped)
            os.close(fd)
            return None

    def fits(self, pixels: NDArray[np.uint8], offset: int, slot: int) -> bool:
        """Whether ``pixels`` fit in ``slot`` from ``offset`` on."""
        return slot < self.count and offset + pixels.nbytes <= (slot + 1) * SLOT_BYTES

    def put(self, pixels: NDArray[np.uint8], offset: int) -> InMemory | None:
        """``pixels`` copied to ``offset`` (worker side): where they are now, or None
        when a file's pages cannot be reserved (/dev/shm full)."""
        if self.fd is not None:
            try:
                os.posix_fallocate(self.fd, offset, pixels.nbytes)
            except OSError:
                return None
        np.ndarray(pixels.shape, pixels.dtype, buffer=self.memory, offset=offset)[...] = pixels
        return InMemory(offset, pixels.shape, pixels.dtype.str)

    def close(self) -> None:
        """Unmap (and close a file; the one that made it removes it).  A view still
        held (by a traceback) keeps the mapping, which goes with it."""
        try:
            self.memory.close()
        except BufferError:
            pass
        if self.fd is not None:
            os.close(self.fd)
            self.fd = None
        if self.path is not None:
            try:
                os.unlink(self.path)
            except FileNotFoundError:
                pass
            self.path = None


#: Bytes of shared address space for the frames of one chunk in flight (64 MB: 16
#: frames of 1280 x 720 RGBA; the pages are only made when written).
SLOT_BYTES = 1 << 26

_WORKER_SLOTS: _Slots | None = None


def _worker_start(render: RenderFunction | None, payload: bytes | None,
                  slots: _Slots | None = None) -> None:
    """Each worker: ignore Ctrl-C (the parent stops the pool) and take the render
    function: ``render`` itself in a forked worker (it has a copy of the parent's
    memory, with what the render function has made ready, such as a scene's frame
    plan), else loaded from ``payload``.  A failure is kept and raised by the first
    task, so that it reaches the parent (an initializer that raises makes the pool
    restart workers forever)."""
    global _WORKER_RENDER, _WORKER_ERROR, _WORKER_SLOTS
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _WORKER_SLOTS = slots
    try:
        _WORKER_RENDER = render if payload is None else pickle.loads(payload)
    except Exception as error:  # noqa: BLE001 - reported to the parent by _worker_chunk
        _WORKER_ERROR = f"{type(error).__name__}: {error}"


def _worker_chunk(indices: Sequence[int], slot: int | None = None) -> list[Packed]:
    if _WORKER_ERROR is not None:
        raise ArgumentValueError(f"the render function could not be loaded in a worker "
                                 f"process ({_WORKER_ERROR}); render with jobs=1")
    assert _WORKER_RENDER is not None           # (set by _worker_start, or an error)
    return render_chunk(_WORKER_RENDER, indices, slots=_WORKER_SLOTS, slot=slot)


def _context() -> multiprocessing.context.BaseContext:
    """fork where it is safe (a POSIX process with one thread: the workers start at
    once and inherit the compiled kernels); forkserver or spawn elsewhere."""
    import multiprocessing as mp

    methods = mp.get_all_start_methods()
    if "fork" in methods and threading.active_count() == 1:
        return mp.get_context("fork")
    return mp.get_context("forkserver" if "forkserver" in methods else "spawn")


def _processes(render: RenderFunction, parts: Iterator[Sequence[int]],
               jobs: int) -> Stream[Image.Image]:
    """Start ``jobs`` worker processes now (before any progress bar or other thread
    exists, so that fork can be used) and return the generator of their frames."""
    context = _context()
    window = 2 * jobs                      # chunks in flight
    slots: _Slots | None
    args: tuple[RenderFunction | None, bytes | None, _Slots | None]
    if context.get_start_method() == "fork":
        # a forked worker inherits its arguments: the render function is not
        # pickled, and the frames come back through shared memory
        slots = _Slots(window)
        args = (render, None, slots)
    else:
        slots, args = None, (None, _dumps(render), None)
    pool = context.Pool(jobs, initializer=_worker_start, initargs=args)

    def gather() -> Iterator[Image.Image]:
        pending: collections.deque[
            tuple[multiprocessing.pool.AsyncResult[list[Packed]], int | None]] = collections.deque()
        free = list(range(window))
        queue = iter(parts)

        def submit() -> None:
            for part in queue:
                slot = free.pop() if slots is not None else None
                pending.append((pool.apply_async(_worker_chunk, (part, slot)), slot))
                return

        try:
            for _ in range(window):
                submit()
            while pending:
                result, slot = pending.popleft()
                images = [unpack(p, None if slots is None else slots.memory) for p in result.get()]
                if slot is not None:
                    free.append(slot)               # the pixels are copied out
                submit()
                yield from images
            pool.close()
            pool.join()
        finally:
            stop()

    def stop() -> None:
        pool.terminate()
        pool.join()
        if slots is not None:
            slots.close()
    return Stream(gather(), stop)


# -- Dask ----------------------------------------------------------------------------------------
def connect(client: Client | str) -> tuple[Client, bool]:
    """``(client, owned)``: a ``distributed.Client`` as given, or one connected to the
    scheduler address ``client`` (then ``owned``: the caller closes it).

    An address is checked first (``tcp://HOST:PORT``), then the scheduler is asked who
    it is; the connection *and* that first exchange must finish within
    :data:`CONNECT_TIMEOUT` seconds, or :class:`SchedulerUnreachable` says so (a
    server that accepts connections and never answers would otherwise hold the
    client's handshake forever)."""
    if not isinstance(client, str):
        if not hasattr(client, "submit") or not hasattr(client, "scatter"):
            raise ArgumentTypeError(f"client must be a dask.distributed Client or a scheduler "
                                    f"address, got {v._show(client)}")
        return client, False
    address = scheduler_address(client, "client")
    try:
        from distributed import Client
    except ImportError:
        raise ArgumentValueError("rendering on a Dask cluster needs dask.distributed: pip "
                                 "install 'scanline-graphics[dask]'") from None
    deadline = time.monotonic() + CONNECT_TIMEOUT
    _probe(address, CONNECT_TIMEOUT)
    made: list[Client | BaseException] = []
    gave_up = threading.Event()

    def start() -> None:
        try:
            new = Client(address, timeout=max(0.1, deadline - time.monotonic()),
                         set_as_default=False)
        except BaseException as error:  # noqa: BLE001 - handed to the waiting thread
            made.append(error)
            return
        made.append(new)
        if gave_up.is_set():             # too late: nobody will use it
            new.close()

    thread = threading.Thread(target=start, daemon=True, name="scanline dask connect")
    thread.start()
    thread.join(max(0.0, deadline - time.monotonic()) + 1.0)
    if not made:
        gave_up.set()
        if made and not isinstance(made[0], BaseException):   # it came just now
            made[0].close()
        raise SchedulerUnreachable(
            f"scheduler={client!r} answered once, then did not complete the connection "
            f"within {CONNECT_TIMEOUT:g} s; check that it is a running Dask scheduler")
    connected = made[0]
    if isinstance(connected, BaseException):
        if not isinstance(connected, Exception):
            raise connected
        raise SchedulerUnreachable(
            f"scheduler={client!r} cannot be reached within {CONNECT_TIMEOUT:g} s "
            f"({type(connected).__name__}: {connected}); check the address (tcp://HOST:PORT) "
            "and that the scheduler is running") from None
    return connected, True


_HOST = re.compile(r"[A-Za-z0-9](?:[A-Za-z0-9._-]{0,252})")
_IPV6 = re.compile(r"\[[0-9A-Fa-f:.]{2,45}\]")


def scheduler_address(text: object, name: str = "scheduler") -> str:
    """The Dask scheduler address ``text`` checked and written out in full:
    ``tcp://HOST:PORT`` (``HOST:PORT`` means tcp), HOST a name, an IPv4 address or
    an IPv6 address in brackets, PORT 1 to 65535.  Other schemes (tls, ws, ucx ...)
    need more than an address (a security context, a transport): connect a
    ``distributed.Client`` and pass it instead."""
    shown = v._show(text)
    what = (f"{name}={shown} is not a scheduler address: write tcp://HOST:PORT, such as "
            "tcp://10.0.0.5:8786")
    if not isinstance(text, str) or not text.strip():
        raise ArgumentValueError(what)
    scheme, sep, rest = text.strip().partition("://")
    if not sep:
        scheme, rest = "tcp", text.strip()
    if scheme.lower() != "tcp":
        raise ArgumentValueError(
            f"{name}={shown}: scanline connects to tcp:// addresses only; for a "
            f"{scheme!r} scheduler (security settings, another transport) make a "
            "distributed.Client yourself and pass it as client=")
    host, colon, port = rest.rpartition(":")
    if not colon or not (_HOST.fullmatch(host) or _IPV6.fullmatch(host)):
        raise ArgumentValueError(what)
    if not re.fullmatch(r"[0-9]{1,5}", port) or not 1 <= int(port) <= 65535:
        raise ArgumentValueError(f"{name}={shown}: the port must be a number from 1 to "
                                 "65535, such as tcp://10.0.0.5:8786")
    return f"tcp://{host}:{int(port)}"


def _probe(address: str, timeout: float) -> dict[str, Any]:
    """Connect to ``address`` and ask the scheduler's identity, all within ``timeout``
    seconds (in a thread of its own with its own event loop, so that it works where
    an event loop is already running, as in Jupyter); raise SchedulerUnreachable
    otherwise."""
    import asyncio

    from distributed.comm.core import connect as comm_connect
    from distributed.core import send_recv

    async def ask() -> object:
        comm = await comm_connect(address, timeout=timeout)
        try:
            return await send_recv(comm, op="identity")
        finally:
            comm.abort()

    async def bounded() -> object:
        return await asyncio.wait_for(ask(), timeout)

    outcome: list[object] = []

    def run() -> None:
        try:
            outcome.append(asyncio.run(bounded()))
        except BaseException as error:  # noqa: BLE001 - handed to the waiting thread
            outcome.append(error)

    thread = threading.Thread(target=run, daemon=True, name="scanline dask probe")
    thread.start()
    thread.join(timeout + 1.0)
    answer = outcome[0] if outcome else None
    if isinstance(answer, dict) and answer.get("type") == "Scheduler":
        return answer
    if not outcome or isinstance(answer, asyncio.TimeoutError):
        why = "no answer"
    elif isinstance(answer, BaseException):
        why = f"{type(answer).__name__}: {' '.join(str(answer).split())[:200]}"
    else:
        why = f"it answered as {v._show(answer)}, not as a Dask scheduler"
    raise SchedulerUnreachable(
        f"scheduler={address!r} did not answer as a Dask scheduler within {timeout:g} s "
        f"({why}); check the address (tcp://HOST:PORT) and that the scheduler is running")


class WorkerLost(ScanlineError):
    """Frames a Dask cluster could not render: the worker rendering them died (as often
    as the scheduler allows, ``distributed.scheduler.allowed-failures``), or their
    tasks were cancelled because every worker holding the render function left."""


def _span(part: Sequence[int]) -> str:
    """Frames ``part`` written out for a message: ``7`` or ``8-15``."""
    return f"{part[0]}" if len(part) == 1 else f"{part[0]}-{part[-1]}"


def _dask(render: RenderFunction, indices: Sequence[int], client: Client,
          owned: bool) -> Iterator[Image.Image]:
    """The frames ``indices`` rendered on the Dask ``client``'s workers, in order.

    Chunks are sized to the workers' threads (:func:`iter_chunks`) and a new one is
    sent as soon as any chunk comes back (``distributed.as_completed``), not only the
    oldest: a worker that finishes first gets more work at once, so no worker waits
    for a slow neighbour's chunk.  The frames that come back early wait here,
    unpacked, until their turn; at most four chunks per thread are in flight, and
    eight in flight or waiting, which bounds the memory.  A chunk whose worker died
    (``KilledWorker``), or whose task was cancelled because no worker holds the
    render function any more, raises :class:`WorkerLost` naming the frames lost,
    and the other chunks are cancelled; the wait is in steps of 0.1 s, so Ctrl-C
    stops it at once (and cancels them)."""
    from concurrent.futures import CancelledError

    from distributed import as_completed

    try:
        # the chunks sized to the threads that run tasks at once (a worker with four
        # threads takes four chunks), counted when the render starts
        workers = max(1, sum(client.nthreads().values()))
        parts = iter_chunks(indices, workers)
        # a fresh key each time (hash=False): a repeated render must not reuse the key of
        # a scatter the client is just releasing
        [shared] = client.scatter([render], broadcast=True, hash=False)
        window = 4 * workers
        # the frames' pixels: in a shared file that workers on this machine open, else
        # LZ4-compressed on the way
        compress = _lz4() is not None
        slots = _Slots.in_shared_file(window)
        path = None if slots is None else slots.path
        memory = None if slots is None else slots.memory
        # future -> (chunk number, slot, frames)
        pending: dict[Future[list[Packed]], tuple[int, int, Sequence[int]]] = {}
        done: dict[int, list[Image.Image]] = {}   # chunk number -> its images, waiting for their turn
        free = list(range(window))
        queue = iter(parts)
        arrived = as_completed(loop=client.loop, raise_errors=False)
        sent, turn = 0, 0

        def refill() -> None:
            nonlocal sent
            while len(pending) < window and len(pending) + len(done) < 2 * window:
                part = next(queue, None)
                if part is None:
                    return
                slot = free.pop()
                future = client.submit(render_chunk, shared, part, compress, path, slot,
                                       pure=False)
                pending[future] = (sent, slot, part)
                arrived.add(future)
                sent += 1

        try:
            refill()
            while pending:
                for future in arrived.next_batch():     # waits in steps of 0.1 s
                    number, slot, part = pending.pop(future)
                    try:
                        packed = future.result() if future.status == "finished" else None
                    except CancelledError:      # finished, then its workers all died
                        packed = None
                    if packed is None:
                        _lost(future, part, pending)
                    done[number] = [unpack(p, memory) for p in packed]
                    free.append(slot)               # the pixels are copied out
                    future.release()
                refill()
                while turn in done:
                    images = done.pop(turn)
                    turn += 1
                    yield from images
                # the frames that waited are out: room for more (all in flight may
                # have come back with the window full of waiting chunks)
                refill()
        finally:
            if pending:
                client.cancel(list(pending))
            if slots is not None:
                slots.close()
    finally:
        if owned:
            client.close()


def _spans(frames: Sequence[int]) -> str:
    """Sorted frame numbers as runs: ``3-7, 12, 20-23``."""
    runs, start = [], 0
    for k in range(1, len(frames) + 1):
        if k == len(frames) or frames[k] != frames[k - 1] + 1:
            runs.append(_span(frames[start:k]))
            start = k
    return ", ".join(runs)


def _lost(future: Future[list[Packed]], part: Sequence[int],
          pending: dict[Future[list[Packed]], tuple[int, int, Sequence[int]]]) -> NoReturn:
    """Raise the error of the chunk ``part`` (its ``future`` failed): the render
    function's own error, or :class:`WorkerLost` naming the frames lost (those of this
    chunk and of every ``pending`` chunk that failed too) when the worker rendering
    them died, or their tasks were cancelled (the workers holding the scattered render
    function all died, or the cluster closed)."""
    error = future.exception() if future.status == "error" else None
    if error is not None and type(error).__name__ != "KilledWorker":
        raise error
    failed = [future] + [f for f in pending if f.status in ("error", "cancelled")]
    frames = sorted({i for f in failed for i in (part if f is future else pending[f][2])})
    died = any(f.status == "error" for f in failed)
    raise WorkerLost(
        f"frames {_spans(frames)} were lost: "
        + ("the Dask worker rendering them died (its process ended: out of memory, a "
           "crash in the render function, or killed) as many times as the scheduler "
           "retries a task" if died else
           "their tasks were cancelled, because the Dask workers holding the render "
           "function died or the cluster closed")
        + "; the render is stopped") from error


# -- the one entry point -----------------------------------------------------------------------
#: Most worker processes per core of this machine: rendering is bound by the
#: processor, so more processes than cores only add memory and start-up time (a few
#: per core still help a render function that waits for files).
JOBS_PER_CORE = 4


def cores() -> int:
    """The cores this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):           # pragma: no cover - not Linux
        return max(1, os.cpu_count() or 1)


def max_jobs() -> int:
    """The most worker processes ``jobs`` may ask for: :data:`JOBS_PER_CORE` per core."""
    return JOBS_PER_CORE * cores()


def check_jobs(jobs: object, name: str = "jobs") -> int:
    """``jobs`` checked: an integer from 1 to :func:`max_jobs`."""
    jobs = v.positive_int(name, jobs)
    most = max_jobs()
    if jobs > most:
        raise ArgumentValueError(
            f"{name}={jobs} is more worker processes than this machine can use: at most "
            f"{most} ({JOBS_PER_CORE} per core, {cores()} cores); give {name} <= {most} "
            "(for more, render on a Dask cluster)")
    return jobs


def frames(render: RenderFunction, indices: Iterable[int], jobs: int = 1,
           client: Client | str | None = None
           ) -> Generator[Image.Image, None, None] | Stream[Image.Image]:
    """Yield the rendered frames ``indices`` as Pillow images, in order.

    Parameters
    ----------
    render : callable
        Frame index -> frame (see the module docstring).
    indices : sequence of int
    jobs : int
        Worker processes (1: render here).
    client : distributed.Client or str, optional
        Render on this Dask cluster (a client, or a scheduler address such as
        ``"tcp://10.0.0.5:8786"``) instead.
    """
    if not callable(render):
        raise ArgumentTypeError(f"render must be a function of the frame index, got "
                                f"{v._show(render)}")
    jobs = check_jobs(jobs)
    if client is not None and jobs != 1:
        raise ArgumentValueError(f"give jobs (processes here) or client (a Dask cluster), not "
                                 f"both; got jobs={jobs} and client={v._show(client)}")
    # a range stays one: a film of 10**9 frames
    selected = indices if isinstance(indices, range) else list(indices)
    if client is not None:
        connected, owned = connect(client)
        return Stream(_dask(render, selected, connected, owned),
                      connected.close if owned else None)
    if jobs == 1 or len(selected) <= 1:
        return (to_image(render(i), i) for i in selected)
    return _processes(render, iter_chunks(selected, jobs), min(jobs, len(selected)))
