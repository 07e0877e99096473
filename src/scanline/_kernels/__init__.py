"""numba-compiled kernels: arrays and scalars in, arrays out.

Kernels never import from the layers above, raise nothing, hold no globals and write
only inside the arrays they are given: every pixel write goes through
:func:`scanline._kernels.raster.put` (or a loop whose bounds were clipped to the
raster first).  This package is imported lazily (``import scanline`` does not import
numba).

The compile-time rule
---------------------
A user's first call of an entry point compiles the kernels it reaches, and must
answer in about 3 s on a 2-core machine with an empty numba cache
(``benchmarks/compile.py`` measures every entry point; ``docs/conventions.md``,
"Compile time").  Kernels keep to this by construction:

1. **Only the variant used is compiled.**  A choice of code (frame-buffer mode,
   packed or byte storage, algorithm, fill rule) reaches a kernel as a *token*
   (:mod:`scanline._kernels.variants`), never as a plain int: a token's length is
   part of its type, so each variant is its own specialization, and ``if
   len(token) == CODE`` folds away the other variants' code before typing.  An
   RGB user compiles RGB code only.
2. **One specialization per variant.**  The API layer passes arrays normalized
   (C-contiguous, writable, one dtype per role: int64 integers, float64 reals,
   uint8 pixels, bool flags) and scalars as Python int/float/bool, so a kernel has at
   most one specialization per token combination actually used; a test
   (``tests/test_compile_budget.py``) counts them.
3. **Inline on evidence.**  ``@inline`` (numba's ``inline="always"``) re-translates
   the function at *every call site* (about 0.05-0.1 s each) and its body is not
   pruned by tokens, so it is kept for small, token-free helpers where a benchmark
   showed that it pays; the default is ``@helper`` (LLVM inlines small callees
   itself).
4. **Small kernels.**  No kernel specialization takes more than about 1 s to
   compile (``benchmarks/compile.py`` lists the slowest); split a larger one into
   helpers, and merge a layer that only forwards its arguments (each compiled
   function costs about 0.1-0.3 s whatever its size).
5. **Tables run as Python.**  Step tables (:mod:`scanline.trace`) run the very same
   step helpers uncompiled (:func:`scanline._kernels._jit.python`), so a 20-row
   table never waits for LLVM and still comes from the algorithm that draws.
6. **No accidental literals.**  numba types an integer or boolean constant passed
   to a helper as a literal and compiles the helper for it, and a loop-carried
   variable that starts at a constant is typed first as that literal: the helper is
   then compiled twice.  Start such values typed (``np.int64(0)``,
   ``np.bool_(False)``) and pass variables; a literal argument is kept only where
   the two specializations are the point (``swap``, ``reverse``, ``weighted``:
   the loop of each is its own), and the test checks that no kernel has a literal
   and a non-literal specialization of the same argument.
7. **Costly constructs.**  An array-to-array slice or row assignment (``a[:n] =
   b[:n]``, ``out[i] = rows[j]``) compiles numba's shape-mismatch error message,
   2.5-4 s on the first call of a process: copy element by element.  numba's sorts
   (``np.sort``, ``np.argsort``) cost about 1.5 s: use them only where an
   O(n log n) order is needed.
8. **Every call goes through** :func:`scanline._kernels._jit.call` with a work
   estimate, so that a first call too small to pay for its compilation runs the
   kernel's Python twin (``tests/test_first_use.py`` proves the twins equal the
   compiled kernels); a new entry point also gets a row in
   :data:`scanline.warmup.CALLS`.

Measuring an edit
-----------------
numba keys its on-disk cache of a function by the function's own source file; the
kernels' cache is keyed instead by the digest of every kernel module
(:func:`scanline._kernels._jit.sources_stamp`), since a kernel inlines or links
helpers of other modules: after any edit of a kernel module (or a ``git pull``),
every kernel is compiled again on its next use instead of running stale code.
"""
