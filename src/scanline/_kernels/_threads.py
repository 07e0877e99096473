"""Kernels run on every core by threads of the API layer: a kernel written to take
every ``step``-th band of rows from band ``start`` is called ``step`` times at once,
once per thread (kernels release the GIL, so the calls run in parallel).

Why not numba's ``prange``: a ``parallel=True`` kernel took 1.5-2.5 s longer to
compile (measured on the shading and triangle kernels), and its threads share the
kernel's arrays, so every call of a helper that takes arrays updates the same
reference counts from both cores (the triangle kernel ran slower on two threads than
on one); separate calls own their arrays' counts."""

import contextlib
import threading

from ._jit import TWIN_WORK, call, in_background

_local = threading.local()


def threads():
    """How many threads :func:`call_in_bands` uses: numba's thread count (1 on one
    core, ``NUMBA_NUM_THREADS`` or ``numba.set_num_threads`` to change it), or 1
    inside :func:`one_thread`."""
    import numba

    return 1 if getattr(_local, "one", False) else numba.get_num_threads()


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
    :func:`scanline._kernels._jit.call`: the first in this thread, the others in
    daemon threads (:func:`scanline._kernels._jit.in_background`: Ctrl-C reaches
    the caller at once, the other calls finish in the background, as a long kernel
    does).  Returns their results in order."""
    waits = [in_background(c[0], lambda c=c: call(*c)) for c in calls[1:]]
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


def call_in_chunks(kernel, work, n, args_of):
    """``kernel(*args_of(lo, hi))`` for consecutive chunks [lo, hi) of range(n), one
    call per thread (one chunk when the ``work`` is at most
    :data:`~scanline._kernels._jit.TWIN_WORK` units, as in :func:`call_in_bands`).
    Returns ``[(lo, result), ...]`` in the order of the chunks: a kernel that writes
    its chunk's results to the front of its output slices leaves them for the caller
    to join."""
    step = min(threads() if work > TWIN_WORK else 1, max(n, 1))
    bounds = [n * i // step for i in range(step + 1)]
    results = _together([(kernel, work / step) + tuple(args_of(bounds[i], bounds[i + 1]))
                         for i in range(step)])
    return list(zip(bounds, results))
