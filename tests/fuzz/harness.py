"""The guard every fuzzed call runs in: a frame buffer whose storage sits between
guard rows (any write outside it shows), a time limit (SIGALRM) and a memory limit
(tracemalloc's peak: numpy reports its allocations there).  Only ScanlineError may
escape."""

import os
import signal
import tracemalloc
from contextlib import contextmanager

import numpy as np
from hypothesis import strategies as st

import scanline as sl

#: Seconds one fuzzed call may take (SCANLINE_FUZZ_TIME: more where the call may
#: compile, as under NUMBA_BOUNDSCHECK=1 with an empty cache).
TIME_LIMIT = int(os.environ.get("SCANLINE_FUZZ_TIME", "20"))
#: Bytes one fuzzed call may allocate at its peak.
MEMORY_LIMIT = 512 * 2**20
GUARD_VALUE = 77


class Overtime(Exception):
    pass


def guarded(width, height, mode):
    """(fb, storage): ``fb`` draws into the middle of ``storage``, two guard rows of
    GUARD_VALUE on each side."""
    fb = sl.FrameBuffer(width, height, mode=mode)
    buf = fb._buf
    big = np.full((buf.shape[0] + 4,) + buf.shape[1:], GUARD_VALUE, np.uint8)
    big[2:-2] = buf
    fb._buf = big[2:-2]
    return fb, big


def guard_intact(big):
    return (big[:2] == GUARD_VALUE).all() and (big[-2:] == GUARD_VALUE).all()


@contextmanager
def bounded(refusals=True):
    """Run the body within TIME_LIMIT seconds and MEMORY_LIMIT bytes; a ScanlineError
    is an answer (swallowed), any other exception a failure.  ``refusals=False``:
    the arguments are valid, so a ScanlineError is a failure too."""
    def alarm(signum, frame):
        raise Overtime(f"the call took more than {TIME_LIMIT} s")

    old = signal.signal(signal.SIGALRM, alarm)
    signal.alarm(TIME_LIMIT)
    tracemalloc.start()
    try:
        yield
    except sl.ScanlineError:
        if not refusals:
            raise
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
    assert peak <= MEMORY_LIMIT, f"peak allocation {peak / 2**20:.0f} MiB"


#: Extreme and special values of every kind.
SPECIAL = [0, 1, -1, 0.5, -0.5, 2.5, 1e-300, 5e-324, 1e300, -1e300, np.nan, np.inf, -np.inf,
           2**30, -2**30, 2**31, 2**53 + 1, 2**62, 2**63 - 1, -2**63, 1e12, -1e12, 3.0, 7.0]

values = st.one_of(st.sampled_from(SPECIAL), st.floats(-50, 80), st.integers(-50, 80),
                   st.floats(allow_nan=True, allow_infinity=True))

DTYPES = [np.float64, np.float32, np.int64, np.int32, np.uint64, np.uint8, np.int8, bool,
          object, np.complex128, np.float16]


def _cast(a, dtype):
    with np.errstate(all="ignore"):
        try:
            return a.astype(dtype)
        except (OverflowError, ValueError, TypeError):
            return a


@st.composite
def arrays(draw, columns, max_rows=12, flavour=True):
    """Arrays of (n, columns) values of any dtype, with any memory layout: read-only,
    strided, reversed, Fortran-ordered, or a wrong shape now and then."""
    n = draw(st.integers(0, max_rows))
    a = np.array(draw(st.lists(values, min_size=n * columns, max_size=n * columns)),
                 dtype=np.float64 if True else None).reshape(n, columns)
    a = _cast(a, draw(st.sampled_from(DTYPES)))
    if flavour:
        kind = draw(st.sampled_from(["plain", "read-only", "strided", "reversed", "fortran",
                                     "flat", "3-d", "transposed"]))
        if kind == "read-only":
            a = a.copy()
            a.flags.writeable = False
        elif kind == "strided":
            a = np.repeat(a, 2, axis=0)[::2]
        elif kind == "reversed":
            a = a[::-1]
        elif kind == "fortran":
            a = np.asfortranarray(a)
        elif kind == "flat":
            a = a.reshape(-1)
        elif kind == "3-d":
            a = a.reshape(1, n, columns)
        elif kind == "transposed":
            a = a.T
    return a


#: Index arrays: counts and offsets of any dtype, wrapped, negative, huge.
INDEX_SPECIAL = [0, 1, 2, 3, 4, -1, 2**31, 2**32, 2**62, 2**63 - 1, 2**63, 2**64 - 5, -2**63]


@st.composite
def index_arrays(draw, max_len=6):
    vals = draw(st.lists(st.one_of(st.sampled_from(INDEX_SPECIAL), st.integers(0, 12)),
                         min_size=0, max_size=max_len))
    dtype = draw(st.sampled_from([np.int64, np.uint64, np.int32, np.uint8, np.float64, bool,
                                  object]))
    with np.errstate(all="ignore"):
        try:
            return np.array(vals, dtype=object).astype(dtype)
        except (OverflowError, ValueError, TypeError):
            return np.array(vals, dtype=object)
