"""Kernels run on every core by threads of the API layer: a kernel written to take
every ``step``-th band of rows from band ``start`` is called ``step`` times at once,
once per thread (kernels release the GIL, so the calls run in parallel).

Why not numba's ``prange``: a ``parallel=True`` kernel took 1.5-2.5 s longer to
compile (measured on the shading and triangle kernels), and its threads share the
kernel's arrays, so every call of a helper that takes arrays updates the same
reference counts from both cores (the triangle kernel ran slower on two threads than
on one); separate calls own their arrays' counts."""

import contextlib
import os
import queue
import threading
import warnings

from ._jit import TWIN_WORK, WAIT, call

_local = threading.local()


class _Worker:
    """A daemon thread kept for the calls of :func:`_together`: starting a thread
    per call cost 0.05-1.5 ms (the new thread waits for the interpreter lock while
    the last one ends), several times per frame.  It runs one task at a time, from
    its queue."""

    def __init__(self):
        self.tasks = queue.SimpleQueue()
        self.busy = False
        self.thread = threading.Thread(target=self._run, daemon=True, name="scanline worker")
        self.thread.start()

    def _run(self):
        while True:
            fn, outcome, done = self.tasks.get()
            try:
                outcome.append((True, fn()))
            except BaseException as error:      # handed to the waiter
                outcome.append((False, error))
            finally:
                self.busy = False
                done.set()


_workers = []
_workers_lock = threading.Lock()
_workers_pid = [os.getpid()]


def _submit(fn):
    """Run ``fn()`` on an idle kept worker (a new one when none is idle: another
    caller's, or one still finishing a call whose waiter was interrupted); returns a
    function that waits for it in steps of :data:`~scanline._kernels._jit.WAIT`
    seconds (so KeyboardInterrupt reaches the waiting thread at once; ``fn`` then
    finishes in the background) and returns its result or raises its error."""
    with _workers_lock:
        if _workers_pid[0] != os.getpid():          # a forked child: no threads there
            _workers.clear()
            _workers_pid[0] = os.getpid()
        worker = next((w for w in _workers if not w.busy), None)
        if worker is None:
            worker = _Worker()
            _workers.append(worker)
        worker.busy = True
    outcome, done = [], threading.Event()
    worker.tasks.put((fn, outcome, done))

    def wait():
        while not done.wait(WAIT):
            pass
        ok, value = outcome[0]
        if not ok:
            raise value
        return value
    return wait


def cores():
    """The CPU cores this process may run on."""
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1


#: Whether :func:`threads` has warned of a thread count above the cores (once).
_warned = []


def threads():
    """How many threads :func:`call_in_bands` uses: numba's thread count (1 on one
    core, ``NUMBA_NUM_THREADS`` or ``numba.set_num_threads`` to change it), or 1
    inside :func:`one_thread`.  A count above the machine's cores is clamped to
    them, with a RuntimeWarning the first time: more threads than cores only take
    turns (``NUMBA_NUM_THREADS`` of 0, a negative count or text is refused when the
    kernels are loaded, :func:`scanline._kernels._jit.check_thread_setting`)."""
    import numba

    if getattr(_local, "one", False):
        return 1
    count = numba.get_num_threads()
    most = cores()
    if count > most:
        if not _warned:
            _warned.append(True)
            warnings.warn(f"numba's thread count {count} (NUMBA_NUM_THREADS or "
                          f"numba.set_num_threads) is above this machine's {most} cores; "
                          f"batch drawing calls use {most} threads", RuntimeWarning,
                          stacklevel=3)
        return most
    return count


@contextlib.contextmanager
def one_thread():
    """Kernels called by this thread inside the block run on this thread alone: for
    workers that already run one task per core (the frames of an animation rendered
    in processes or on a Dask cluster), where more threads per call would only
    compete for the same cores.  The pixels do not depend on the thread count."""
    before = getattr(_local, "one", False)
    _local.one = True
    try:
        yield
    finally:
        _local.one = before


def _together(calls):
    """The ``(kernel, work, *args)`` calls at once, through
    :func:`scanline._kernels._jit.call`: the first in this thread, the others on
    kept daemon threads (:func:`_submit`: Ctrl-C reaches the caller at once, the
    other calls finish in the background, as a long kernel does).  Returns their
    results in order."""
    waits = [_submit(lambda c=c: call(*c)) for c in calls[1:]]
    first = call(*calls[0])
    return [first] + [wait() for wait in waits]


def call_in_bands(kernel, work, *args):
    """``kernel(start, step, *args)`` for start = 0 .. step - 1, one call per thread,
    through :func:`scanline._kernels._jit.call`; one call (start 0, step 1) when the
    ``work`` is small (at most :data:`~scanline._kernels._jit.TWIN_WORK` units: a
    first use may then run the kernel's Python twin, which gains nothing from
    threads)."""
    step = threads() if work > TWIN_WORK else 1
    if step <= 1:
        return call(kernel, work, 0, 1, *args)
    _together([(kernel, work / step, i, step) + args for i in range(step)])
    return None


def call_in_chunks(kernel, work, n, args_of, parts=None):
    """``kernel(*args_of(lo, hi))`` for consecutive chunks [lo, hi) of range(n), one
    call per thread (one chunk when the ``work`` is at most
    :data:`~scanline._kernels._jit.TWIN_WORK` units, as in :func:`call_in_bands`),
    or ``parts`` chunks when given (a second pass over the chunks of a first).
    Returns ``[(lo, result), ...]`` in the order of the chunks: a kernel that writes
    its chunk's results to the front of its output slices leaves them for the caller
    to join."""
    step = parts or min(threads() if work > TWIN_WORK else 1, max(n, 1))
    bounds = [n * i // step for i in range(step + 1)]
    results = _together([(kernel, work / step) + tuple(args_of(bounds[i], bounds[i + 1]))
                         for i in range(step)])
    return list(zip(bounds, results))
