"""Kernels run on every core by threads of the API layer: a kernel written to take
every ``step``-th band of rows from band ``start`` is called ``step`` times at once,
once per thread (kernels release the GIL, so the calls run in parallel).

Why not numba's ``prange``: a ``parallel=True`` kernel took 1.5-2.5 s longer to
compile (measured on the shading and triangle kernels), and its threads share the
kernel's arrays, so every call of a helper that takes arrays updates the same
reference counts from both cores (the triangle kernel ran slower on two threads than
on one); separate calls own their arrays' counts."""

from concurrent.futures import ThreadPoolExecutor

from ._jit import TWIN_WORK, call


def threads():
    """How many threads :func:`call_in_bands` uses: numba's thread count (1 on one
    core, ``NUMBA_NUM_THREADS`` or ``numba.set_num_threads`` to change it)."""
    import numba

    return numba.get_num_threads()


def call_in_bands(kernel, work, *args):
    """``kernel(start, step, *args)`` for start = 0 .. step - 1, one call per thread,
    through :func:`scanline._kernels._jit.call`; one call (start 0, step 1) when the
    ``work`` is small (at most :data:`~scanline._kernels._jit.TWIN_WORK` units: a
    first use may then run the kernel's Python twin, which gains nothing from
    threads)."""
    step = threads() if work > TWIN_WORK else 1
    if step <= 1:
        return call(kernel, work, 0, 1, *args)
    with ThreadPoolExecutor(step - 1) as pool:
        others = [pool.submit(call, kernel, work / step, i, step, *args)
                  for i in range(1, step)]
        call(kernel, work / step, 0, step, *args)
        for job in others:
            job.result()
    return None
