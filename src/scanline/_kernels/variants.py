"""Variant tokens: how a choice of code (the frame-buffer mode, packed or byte
storage, an algorithm) reaches a kernel so that only the chosen code is compiled.

numba compiles a function once per combination of argument *types*, and a plain
integer argument has one type whatever its value: a kernel that branches on an
``int`` mode types, lowers and optimizes every branch, for every mode, on the first
call (the antialiased line kernel took a minute that way).  A *token* is a tuple of
zeros whose length is the variant's code.  Its length is part of its type, so numba
compiles a separate specialization per variant actually used, and in a function
that receives the token as an argument, ``if len(token) == CODE:`` is folded to a
constant before typing (numba's ``RewriteSemanticConstants`` and
``DeadBranchPrune`` passes): the branches of the other variants are never typed or
compiled.

The fold happens only in the function that receives the token as a parameter and
is compiled on its own (``@kernel`` or ``@helper``), not in code inlined into it
with ``inline="always"``: a function that branches on a token is never
``@inline``.  Pass a token down the call chain as an argument, and test it with
``len(token) == CODE`` written out (a helper that returns the code would not fold).

>>> MODE["RGB"], len(MODE["RGB"]) == RGB
((0, 0, 0), True)
>>> len(LAYOUT["1"]) == PACKED, len(LAYOUT["RGBA"]) == BYTES
(True, True)
"""

#: Frame-buffer modes, for kernels whose arithmetic depends on the mode (blending,
#: antialiasing): the length of ``MODE[name]``.
BIT = 1
GRAY = 2
RGB = 3
RGBA = 4
INDEXED = 5

#: Storage layouts, for kernels that only store pixel values: packed bits (mode
#: "1") or one byte per channel (every other mode; the channel count is the color's).
PACKED = 1
BYTES = 2


def token(code):
    """The token of variant ``code``: a tuple of ``code`` zeros."""
    return (0,) * code


MODE = {"1": token(BIT), "L": token(GRAY), "RGB": token(RGB), "RGBA": token(RGBA),
        "P": token(INDEXED)}
LAYOUT = {"1": token(PACKED), "L": token(BYTES), "RGB": token(BYTES), "RGBA": token(BYTES),
          "P": token(BYTES)}

LAYOUT_PACKED = token(PACKED)
LAYOUT_BYTES = token(BYTES)


def layout(packed):
    """The layout token of packed (mode "1") or byte storage: the API layer keeps a
    ``packed`` flag (``FrameBuffer._raster()``) and turns it into the token where it
    calls a kernel."""
    return LAYOUT_PACKED if packed else LAYOUT_BYTES
