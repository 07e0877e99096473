"""The one place numba is configured (DESIGN.md, "Layers")."""

from numba import njit

#: Decorator for compiled kernels: cached on disk, releasing the GIL.
kernel = njit(cache=True, nogil=True)

#: Decorator for small helpers inlined into the kernels that call them.
inline = njit(cache=True, nogil=True, inline="always")
