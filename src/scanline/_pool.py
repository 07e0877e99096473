"""Large arrays kept between renders, per thread: a new array of a frame's size costs
its page faults on first touch (a 1920 x 1080 float64 buffer, 16 MB: several
milliseconds, more than its whole depth test), and a render makes several.

:func:`scratch` is for temporaries that are not handed back (their contents are
not kept), :func:`scratch_rows` for those whose length changes from call to call.
:func:`recycled` is for the buffers a render hands back (the depth and face buffers of
a :class:`~scanline.rendering.Rendering`): the array of the previous call is used
again only when nothing else holds it any more -- its reference count says that only
the pool does (a view of it, a :class:`~scanline.depthbuffer.DepthBuffer` or a kept
``Rendering`` each hold a reference) -- so a result the caller kept is never written
over.
"""

import sys
import threading
from typing import Any

import numpy as np
from numpy.typing import DTypeLike, NDArray

_LOCAL = threading.local()


def _kept() -> dict[str, NDArray[Any]]:
    kept: dict[str, NDArray[Any]] | None = getattr(_LOCAL, "arrays", None)
    if kept is None:
        kept = _LOCAL.arrays = {}
    return kept


def scratch(name: str, shape: tuple[int, ...], dtype: DTypeLike = np.float64) -> NDArray[Any]:
    """An array of ``shape`` and ``dtype`` kept for the calling thread under ``name``
    and given again to its next call with the same shape and dtype (contents not
    kept)."""
    kept = _kept()
    a = kept.get(name)
    if a is None or a.shape != tuple(shape) or a.dtype != dtype:
        a = kept[name] = np.empty(shape, dtype)
    return a


#: The largest array :func:`scratch_rows` keeps (bytes): a longer call gets a new
#: array, not kept, so what a thread holds stays bounded whatever it once drew.
ROWS_KEPT = 1 << 28


def scratch_rows(name: str, rows: int, shape: tuple[int, ...],
                 dtype: DTypeLike = np.float64) -> NDArray[Any]:
    """The first ``rows`` rows of an array with rows of ``shape`` and ``dtype`` kept
    for the calling thread under ``name`` (contents not kept): grown to the next
    power of two rows when it is too short, never shrunk, so calls of any length
    share it.  Only the pages a call writes are ever resident: the kept array costs
    the memory of the longest call in this thread, and one beyond
    :data:`ROWS_KEPT` bytes is made for the call alone."""
    kept = _kept()
    a = kept.get(name)
    if a is None or len(a) < rows or a.shape[1:] != tuple(shape) or a.dtype != dtype:
        grown = (1 << max(rows - 1, 0).bit_length(),) + tuple(shape)
        if np.prod(grown) * np.dtype(dtype).itemsize > ROWS_KEPT:
            return np.empty((rows,) + tuple(shape), dtype)
        a = kept[name] = np.empty(grown, dtype)
    return a[:rows]


#: References to an array of the pool that nothing else holds: the pool's dict, the
#: local name in :func:`recycled` and the argument of ``sys.getrefcount``.
_UNHELD = 3


def recycled(name: str, shape: tuple[int, ...], dtype: DTypeLike = np.float64) -> NDArray[Any]:
    """A new array of ``shape`` and ``dtype`` for a result the caller gets: the one
    handed out under ``name`` last time in this thread when nothing else references
    it any more, else a new one (kept for next time)."""
    kept = _kept()
    a = kept.get(name)
    if (a is None or a.shape != tuple(shape) or a.dtype != dtype
            or sys.getrefcount(a) != _UNHELD):
        a = np.empty(shape, dtype)
        kept[name] = a
    return a
