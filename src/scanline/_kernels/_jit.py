"""The one place numba is configured (DESIGN.md, "Layers")."""

from numba import njit

#: Decorator for compiled kernels, the entry points the API layer calls: cached on
#: disk, releasing the GIL.
kernel = njit(cache=True, nogil=True)

#: Decorator for compiled helpers that kernels call; LLVM decides what to inline.
helper = njit(cache=True, nogil=True)

#: Decorator for the few tiny helpers that must be inlined into the caller's numba
#: IR (the pixel store).  Measured: inlining larger helpers this way made the circle
#: loop six times slower than letting LLVM inline them.
inline = njit(cache=True, nogil=True, inline="always")
