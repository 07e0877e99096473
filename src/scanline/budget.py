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


def physical_memory() -> int:
    """This machine's physical memory in bytes (2**40 where it cannot be read).

    Returns
    -------
    int
        The bytes of physical memory (``SC_PHYS_PAGES`` times ``SC_PAGE_SIZE``).

    Examples
    --------
    >>> import scanline as sl
    >>> sl.budget.physical_memory() > 0
    True
    """
    try:
        return os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    except (ValueError, OSError, AttributeError):  # pragma: no cover - non-POSIX
        return 1 << 40


def parse(text: object, name: str = VARIABLE) -> int:
    """Bytes of a size written as a number with an optional suffix K, M, G or T.

    Parameters
    ----------
    text : object
        The size: bytes, or a number with the suffix K, M, G or T (powers of 1024,
        case ignored; ``KB``, ``KiB`` ... too).
    name : str
        The name of what gave it, for the error message.

    Returns
    -------
    int
        The size in bytes.

    Raises
    ------
    ArgumentValueError
        When ``text`` is not a size.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.budget.parse("8G") == 8 * 1024**3
    True
    >>> sl.budget.parse("1.5k")
    1536
    """
    match = re.fullmatch(r"\s*(\d+(?:\.\d+)?)\s*([KMGT]?)i?B?\s*", str(text), re.IGNORECASE)
    if not match:
        raise ArgumentValueError(f"{name}={text!r} is not a size: write bytes, or a number "
                                 "with K, M, G or T (e.g. 8G)")
    return int(float(match.group(1)) * _UNITS[match.group(2).upper()])


def limit() -> int:
    """The limit in bytes: ``SCANLINE_MEMORY_LIMIT`` if set, else half the physical
    memory.

    Returns
    -------
    int
        The memory budget in bytes.

    Raises
    ------
    ArgumentValueError
        When ``SCANLINE_MEMORY_LIMIT`` is set to something that is not a size.

    Examples
    --------
    >>> import os
    >>> import scanline as sl
    >>> os.environ["SCANLINE_MEMORY_LIMIT"] = "2M"
    >>> sl.budget.limit()
    2097152
    >>> del os.environ["SCANLINE_MEMORY_LIMIT"]
    >>> sl.budget.limit() == sl.budget.physical_memory() // 2
    True
    """
    text = os.environ.get(VARIABLE)
    return parse(text) if text else physical_memory() // 2


def check(nbytes: float, argument: str, what: str, hint: str | None = None,
          limit_bytes: float | None = None) -> None:
    """Refuse a call whose estimate ``nbytes`` passes the budget: a
    :class:`~scanline.errors.MemoryBudgetError` naming ``argument`` (the argument
    that sets the size), ``what`` it asks for, the estimate and the limit; ``hint``
    says what would work instead.

    Parameters
    ----------
    nbytes : float
        The estimated bytes the call would allocate.
    argument : str
        The argument that sets the size, named first in the message.
    what : str
        What the call asks for, in words.
    hint : str, optional
        What would work instead, put before the advice to raise the limit.
    limit_bytes : float, optional
        The limit in bytes (default: :func:`limit`).

    Raises
    ------
    MemoryBudgetError
        When ``nbytes`` is more than the limit.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.budget.check(1000, "n", "1000 bytes", limit_bytes=1000)
    >>> sl.budget.check(1001, "n", "1001 bytes", hint="use fewer", limit_bytes=1000)
    Traceback (most recent call last):
      ...
    scanline.errors.MemoryBudgetError: n: 1001 bytes would take about 1e+03 bytes, more than the memory budget of 1,000 bytes; use fewer, or raise the limit with the environment variable SCANLINE_MEMORY_LIMIT (e.g. SCANLINE_MEMORY_LIMIT=64G)
    """
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
