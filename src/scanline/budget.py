"""The memory budget: every call whose memory grows with its arguments (a frame
buffer's size times the samples of a method, frames times their size, steps times
points, a scene's primitives together) estimates the bytes it will allocate and is
refused up front, before it allocates anything, when the estimate passes the limit.

The limit is, in order: the ``limit=`` given to :func:`check`'s caller where it takes
one, the environment variable ``SCANLINE_MEMORY_LIMIT`` (bytes, or a number with the
suffix K, M, G or T, powers of 1024), else half of this machine's physical memory.
The error, :class:`~scanline.errors.MemoryBudgetError`, names the argument and the
estimate and says how to raise the limit.

Work that a user would expect to finish whatever its size is not refused but done in
bounded memory instead (the A-buffer in tiles, animations streamed frame by frame).

>>> import scanline as sl
>>> sl.budget.check(10**6, "fb", "a 1000 x 1000 frame buffer")      # within the budget
>>> sl.budget.check(10**30, "steps", "10**30 points")
Traceback (most recent call last):
  ...
scanline.errors.MemoryBudgetError: steps: 10**30 points would take about 1e+30 bytes, more than the memory budget of ... bytes; ...
"""

import os
import re

from .errors import ArgumentValueError, MemoryBudgetError

#: The environment variable that sets the limit.
VARIABLE = "SCANLINE_MEMORY_LIMIT"
_UNITS = {"": 1, "K": 1 << 10, "M": 1 << 20, "G": 1 << 30, "T": 1 << 40}


def physical_memory():
    """This machine's physical memory in bytes (2**40 where it cannot be read)."""
    try:
        return os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    except (ValueError, OSError, AttributeError):  # pragma: no cover - non-POSIX
        return 1 << 40


def parse(text, name=VARIABLE):
    """Bytes of a size written as a number with an optional suffix K, M, G or T."""
    match = re.fullmatch(r"\s*(\d+(?:\.\d+)?)\s*([KMGT]?)i?B?\s*", str(text), re.IGNORECASE)
    if not match:
        raise ArgumentValueError(f"{name}={text!r} is not a size: write bytes, or a number "
                                 "with K, M, G or T (e.g. 8G)")
    return int(float(match.group(1)) * _UNITS[match.group(2).upper()])


def limit():
    """The limit in bytes: ``SCANLINE_MEMORY_LIMIT`` if set, else half the physical
    memory."""
    text = os.environ.get(VARIABLE)
    return parse(text) if text else physical_memory() // 2


def check(nbytes, argument, what, hint=None, limit_bytes=None):
    """Refuse a call whose estimate ``nbytes`` passes the budget: a
    :class:`~scanline.errors.MemoryBudgetError` naming ``argument`` (the argument
    that sets the size), ``what`` it asks for, the estimate and the limit; ``hint``
    says what would work instead."""
    bound = limit() if limit_bytes is None else int(limit_bytes)
    if nbytes <= bound:
        return
    try:
        size = f"{float(nbytes):.3g}"
    except OverflowError:               # an integer beyond the floats: its magnitude
        size = f"1e+{len(str(int(nbytes))) - 1}"
    raise MemoryBudgetError(
        f"{argument}: {what} would take about {size} bytes, more than the memory "
        f"budget of {bound:,} bytes; " + (f"{hint}, or " if hint else "")
        + f"raise the limit with the environment variable {VARIABLE} (e.g. {VARIABLE}=64G)")


__all__ = ["VARIABLE", "check", "limit", "parse", "physical_memory"]
