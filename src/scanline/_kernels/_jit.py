"""The one place numba is configured (DESIGN.md, "Layers"; the compile-time rule is in
:mod:`scanline._kernels`).

Kernels are compiled with numpy's error model: a division by zero gives inf or nan
(integers: 0) instead of raising, as kernels raise nothing, and numba generates no
exception paths for divisions (measured: 10-12% less compile time for a polygon fill
and a thick stroke).  They are cached on disk (numba's ``cache=True``); where no
cache folder can be written (a read-only installation with no writable
``NUMBA_CACHE_DIR`` or home folder), numba refuses ``cache=True`` when the function
is defined, and the kernels are then compiled uncached in every process, which is
slower to start but works.
"""

import functools
import hashlib
import os
import signal
import threading
import time
import types
import warnings

import numpy as np


def check_thread_setting(environ=os.environ):
    """Refuse a ``NUMBA_NUM_THREADS`` that is not a positive integer, before numba
    is imported: numba itself raises a bare "Number of threads specified must be > 0"
    for 0 or a negative count and ignores other text with a warning.  (A count above
    the machine's cores is clamped by :func:`scanline._kernels._threads.threads`.)"""
    value = environ.get("NUMBA_NUM_THREADS")
    if value is not None and not (value.strip().isdigit() and int(value) > 0):
        raise ValueError(
            f"NUMBA_NUM_THREADS must be a positive integer (the threads a batch drawing "
            f"call uses, at most {len(os.sched_getaffinity(0))} on this machine), got "
            f"{value!r}; unset it to use every core")


check_thread_setting()

from numba import njit  # noqa: E402  (after the check: numba reads the setting)
from numba.core import caching  # noqa: E402
from numba.core.dispatcher import Dispatcher  # noqa: E402
from numba.core.errors import NumbaWarning  # noqa: E402

#: The folder of the kernel modules.
_HERE = os.path.dirname(os.path.abspath(__file__))


@functools.lru_cache(maxsize=1)
def sources_stamp(folder=_HERE):
    """A digest of every kernel module's source (``*.py`` in ``folder``, by name):
    the key under which numba's on-disk cache keeps each kernel.

    numba keys a cached kernel by its own file alone, so a kernel loaded from the
    cache would still run the old code of a helper edited in another module (an
    ``@inline`` one is copied into its callers; a ``@helper`` is linked in) -- in a
    checkout after an edit or a ``git pull``, stale machine code, even code for a
    helper's old arguments.  With the digest of all of them, any change to a kernel
    module recompiles every kernel on its next use (an installed package changes all
    its files at once anyway).  Computed once per process."""
    digest = hashlib.sha256()
    for name in sorted(os.listdir(folder)):
        if name.endswith(".py"):
            digest.update(name.encode() + b"\0")
            with open(os.path.join(folder, name), "rb") as f:
                digest.update(f.read())
    return digest.digest()


def _whole_package(locator):
    """numba's cache locator class ``locator``, for the functions of this folder
    only, with the sources' digest (:func:`sources_stamp`) as their key."""
    class Locator(locator):
        @classmethod
        def from_function(cls, py_func, py_file):
            if os.path.dirname(os.path.abspath(py_file)) != _HERE:
                return None
            return super().from_function(py_func, py_file)

        def get_source_stamp(self):
            return sources_stamp()

    Locator.__name__ = Locator.__qualname__ = "Kernels" + locator.__name__
    return Locator


def _numba(name):
    """numba's caching class ``name`` (public since numba 0.58, ``_name`` before)."""
    return getattr(caching, name, None) or getattr(caching, "_" + name, None)


# the same places as numba's own locators (its cache folder, the module's
# __pycache__, the user's cache), tried first, in numba's order (if numba's internals
# moved: its own keys, as before; tests/test_kernel_cache.py would say so)
_LOCATORS = [_numba(name) for name in ("UserProvidedCacheLocator", "InTreeCacheLocator",
                                       "UserWideCacheLocator")]
if _numba("CacheImpl") is not None and all(_LOCATORS):
    _numba("CacheImpl")._locator_classes[:0] = [_whole_package(c) for c in _LOCATORS]


def _compiled(**options):
    """A decorator compiling with ``options``, cached on disk where that is possible."""
    def decorate(fn):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", NumbaWarning)
                return njit(cache=True, nogil=True, error_model="numpy", **options)(fn)
        except RuntimeError:          # "cannot cache function ...: no locator available"
            return njit(nogil=True, error_model="numpy", **options)(fn)
    return decorate


#: Decorator for compiled kernels, the entry points the API layer calls: cached on
#: disk, releasing the GIL.
kernel = _compiled()

#: Decorator for the few kernels that run bands of their work on every core
#: (numba's ``prange``; the Python twin runs the bands one after another).
parallel_kernel = _compiled(parallel=True)

#: Decorator for compiled helpers that kernels call; LLVM decides what to inline.
helper = _compiled()

#: Decorator for the few small helpers that must be inlined into the caller's numba
#: IR (rule 3 of :mod:`scanline._kernels`: each call site costs compile time, and a
#: token branch in an inlined body is not folded, so only token-free helpers where a
#: benchmark showed it pays).
inline = _compiled(inline="always")

#: How :func:`call` runs kernels: ``"auto"`` (the default: small first calls as
#: Python, the rest compiled), ``"always"`` (compile on the first call: the tests,
#: ``scanline warmup``) or ``"never"`` (always the Python twins: to debug a kernel
#: with print or a debugger, slowly).  Set by ``SCANLINE_COMPILE``.
COMPILE = os.environ.get("SCANLINE_COMPILE", "auto")
if COMPILE not in ("auto", "always", "never"):
    raise ValueError(f"SCANLINE_COMPILE must be auto, always or never, got {COMPILE!r}")

#: Most work units for which a kernel that is neither compiled nor cached runs as
#: Python.  A unit is about one microsecond of the twin's time (the estimates of the
#: API layer are scaled so, measured per kernel): at most ~0.1 s, against seconds of
#: compilation.
TWIN_WORK = 100_000

#: Seconds a process may spend in one kernel's Python twin before the kernel is
#: compiled after all (many small calls: compiling then pays).
TWIN_TIME = 0.25

_PYTHON = {}
_CACHED = {}
_SPENT = {}
_LIMITS = {}


def slow_to_compile(kernel, seconds):
    """Declare that ``kernel`` takes about ``seconds`` to compile (its own compilation,
    measured by ``benchmarks/compile.py --compile``), well above most kernels' second:
    its twin may then run calls of up to a quarter of that (work units of a
    microsecond) and spend as much in a process before compiling pays.  Returns the
    kernel."""
    _LIMITS[kernel] = (max(TWIN_WORK, seconds / 4 * 1e6), max(TWIN_TIME, seconds / 4))
    return kernel


def call(kernel, work, *args):
    """Call ``kernel(*args)``, or on a first use its Python twin.

    A new environment has no compiled kernels: compiling one takes seconds, while the
    same code run by the interpreter (:func:`python`) finishes a small drawing in
    milliseconds with the same result.  So a kernel that is neither compiled in this
    process nor found in numba's on-disk cache runs as Python when ``work`` (an
    estimate of its work units; a callable is evaluated only here) is at most
    :data:`TWIN_WORK`, until the twin has used :data:`TWIN_TIME` seconds; a larger or
    later call compiles it, as does every call once it is compiled or cached.  A
    tiered JIT, in short: interpret first, compile where it pays.  The twins compute
    exactly what the kernels compute (``tests/test_first_use.py`` compares them).
    A kernel declared :func:`slow_to_compile` has larger limits.
    :data:`COMPILE` overrides the choice.  Anything else than a compiled function
    (a test's stand-in, say) is just called.
    """
    args = _writable(args)
    compiled = getattr(kernel, "overloads", None)
    if compiled is None:
        return kernel(*args)
    if compiled and COMPILE != "never" or COMPILE == "always":
        return _interruptible(kernel, work, args)
    if COMPILE == "never":
        return _interpreted(kernel, args)
    cached = _CACHED.get(kernel)
    if cached is None:
        try:
            cached = _CACHED[kernel] = os.path.exists(kernel._cache._cache_file._index_path)
        except AttributeError:           # uncached (NullCache), or numba's internals moved
            cached = _CACHED[kernel] = False
    spent = _SPENT.get(kernel, 0.0)
    most_work, most_time = _LIMITS.get(kernel, (TWIN_WORK, TWIN_TIME))
    if cached or spent > most_time or (work() if callable(work) else work) > most_work:
        return _interruptible(kernel, work, args)
    t0 = time.perf_counter()
    try:
        return _interpreted(kernel, args)
    finally:
        _SPENT[kernel] = spent + time.perf_counter() - t0


def first_use_parts(kernel, each, n):
    """The ranges ``(lo, hi)`` of ``n`` items of ``each`` work units in which to call
    ``kernel`` (through :func:`call`): one range once it is compiled, and until then
    parts of :data:`TWIN_WORK` units.  For a kernel whose work estimate can miss by
    far (the ray tracer's cannot see how deep its ray trees go): a first use runs as
    the Python twin part by part, and the twin's time budget, checked before each
    part, compiles the kernel for the rest instead of letting one call run on."""
    lo = 0
    while lo < n:
        if getattr(kernel, "overloads", None):
            hi = n
        else:
            hi = min(n, lo + max(1, int(TWIN_WORK // max(each, 1e-300))))
        yield lo, hi
        lo = hi


#: Compiled entry points by ``(kernel, types)``: see :func:`call_typed`.
_ENTRIES = {}


def call_typed(kernel, types, bound, work, *args):
    """:func:`call`, for a single call that is too small to pay numba's dispatch.

    A dispatcher call resolves the numba type of every argument (``typeof``) to
    choose its compiled specialization, about as long as drawing a short line.  The
    caller knows better: ``types`` is a hashable key that determines the numba types
    of ``args`` (for a line: the frame buffer's storage layout and the method's
    token, the other arguments being arrays and ints of fixed types), so the
    specialization found for the first call of each key is called directly after it
    -- its compiled entry point, which unboxes the arguments with no type
    resolution.  A key must never stand for two sets of types: the entry point does
    not check them.  ``bound`` is an upper bound of ``work`` known at no cost (for a
    line, twice the frame buffer's width plus height): a call that may run long
    (``bound`` >= :data:`LONG_WORK`), a first one or one run as the Python twin goes
    through :func:`call`, with the work that ``work(*args)`` estimates.
    """
    entry = _ENTRIES.get((kernel, types))
    if entry is not None and bound < LONG_WORK and COMPILE != "never":
        return entry(*args)
    result = call(kernel, lambda: work(*args), *args)
    if getattr(kernel, "overloads", None):
        from numba.core.typing.typeof import Purpose, typeof

        found = kernel.overloads.get(tuple(typeof(a, Purpose.argument) for a in args))
        if found is not None:
            _ENTRIES[kernel, types] = found.entry_point
    return result


#: Work units from which a compiled kernel runs in a worker thread while the main
#: thread waits for it in steps of :data:`WAIT` seconds, so that Ctrl-C is answered
#: at once (a kernel releases the GIL but cannot see signals: the interrupt would
#: wait for its return).  About a second of a compiled kernel's work.
LONG_WORK = 20_000_000

#: The main thread's wait step for a long kernel (seconds).
WAIT = 0.05


def _interruptible(kernel, work, args):
    """``kernel(*args)``; a long one (``work`` >= :data:`LONG_WORK`, in the main
    thread with Python's own SIGINT handler) in a daemon thread, waited for in short
    steps: KeyboardInterrupt then reaches the caller within :data:`WAIT` seconds
    (the kernel finishes its call in the background; the command exits)."""
    if ((work() if callable(work) else work) < LONG_WORK
            or threading.current_thread() is not threading.main_thread()
            or signal.getsignal(signal.SIGINT) is not signal.default_int_handler):
        return kernel(*args)
    return in_background(kernel, lambda: kernel(*args))()


def in_background(kernel, fn):
    """Start ``fn()`` (a call of ``kernel``, which names the thread) in a daemon
    thread; returns a function that waits for it in steps of :data:`WAIT` seconds
    (so KeyboardInterrupt reaches the waiting thread at once; ``fn`` then finishes in
    the background) and returns its result or raises its error."""
    outcome = []

    def run():
        try:
            outcome.append((True, fn()))
        except BaseException as error:      # handed to the waiter below
            outcome.append((False, error))

    worker = threading.Thread(target=run, daemon=True,
                              name=f"scanline {getattr(kernel, '__name__', 'kernel')}")
    worker.start()

    def wait():
        while worker.is_alive():
            worker.join(WAIT)
        ok, value = outcome[0]
        if not ok:
            raise value
        return value
    return wait


def _writable(args):
    """``args`` with each read-only array replaced by a writable copy: numba would
    compile a second specialization of the kernel for it (a read-only array is an
    input, never written, so the copy changes nothing else).  The API layer gives
    the other flags (C order, dtype by role); a read-only array is the one a caller
    can slip through unchanged (``np.ascontiguousarray`` keeps it)."""
    if all(a.flags.writeable for a in args if isinstance(a, np.ndarray)):
        return args
    return tuple(a.copy() if isinstance(a, np.ndarray) and not a.flags.writeable else a
                 for a in args)


def _interpreted(kernel, args):
    """The Python twin of ``kernel`` on ``args``, with numpy's floating-point warnings
    off: the compiled kernels' error model gives inf and nan silently too."""
    with np.errstate(all="ignore"):
        return python(kernel)(*args)


def python(fn):
    """The plain-Python twin of the compiled function ``fn``: its Python source run
    by the interpreter, with every compiled function it calls replaced by that
    function's own twin, so that nothing is compiled.

    Step tables run the drawing kernels' own step helpers this way: a table of a few
    hundred rows costs microseconds instead of a compilation, and it still comes
    from the same code as the pixels (DESIGN.md, convention 5).

    >>> from scanline._kernels.lines import bresenham_decide
    >>> python(bresenham_decide)(-4, 16, -4)
    (12, 0)
    """
    if not isinstance(fn, Dispatcher):
        return fn
    twin = _PYTHON.get(fn)
    if twin is None:
        py = fn.py_func
        scope = dict(py.__globals__)
        twin = types.FunctionType(py.__code__, scope, py.__name__, py.__defaults__,
                                  py.__closure__)
        twin.__doc__ = py.__doc__
        _PYTHON[fn] = twin
        for name in py.__code__.co_names:
            if isinstance(scope.get(name), Dispatcher):
                scope[name] = python(scope[name])
    return twin
