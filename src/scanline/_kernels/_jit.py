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

import types
import warnings

from numba import njit
from numba.core.dispatcher import Dispatcher
from numba.core.errors import NumbaWarning


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

#: Decorator for compiled helpers that kernels call; LLVM decides what to inline.
helper = _compiled()

#: Decorator for the few small helpers that must be inlined into the caller's numba
#: IR (rule 3 of :mod:`scanline._kernels`: each call site costs compile time, and a
#: token branch in an inlined body is not folded, so only token-free helpers where a
#: benchmark showed it pays).
inline = _compiled(inline="always")

_PYTHON = {}


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
