"""The limits of the fractal generators: recursion depths and iteration counts are
refused up front, before anything is allocated or computed, when the points they
would make pass :data:`MAX_POINTS` (time) or the memory budget
(:mod:`scanline.budget`), or when the escape-time work passes :data:`MAX_ITERATIONS`
(pixel iterations).  The errors name the argument and the limit."""

from typing import Optional

from .. import budget
from ..errors import ArgumentValueError

#: Most points (or string symbols) a curve, an L-system or an IFS may make: about a
#: second of work, 16 bytes a point.
MAX_POINTS = 1 << 26

#: Most pixel iterations (width x height x max_iterations) of one escape-time image:
#: about ten seconds on one core (a 1920 x 1080 image of points in the set to 4,800
#: iterations).
MAX_ITERATIONS = 10_000_000_000


def power(base: int, exponent: int) -> int:
    """base ** exponent for counting points, capped at 2 ** 80 (far past every limit)
    without computing a huge integer."""
    import math

    if base <= 1 or exponent * math.log2(base) <= 80:
        return int(base ** exponent)
    return 1 << 80


def points(argument: str, count: int, what: str, bytes_per_point: int = 16,
           hint: Optional[str] = None) -> None:
    """Refuse ``count`` points (a Python int, exact at any size) past
    :data:`MAX_POINTS` or the memory budget, naming ``argument``."""
    count = int(count)
    if count > MAX_POINTS:
        raise ArgumentValueError(
            f"{argument}: {what} would make {count:,} points, more than the limit of "
            f"{MAX_POINTS:,} (scanline.fractals.limits.MAX_POINTS); "
            + (hint or f"give a smaller {argument}"))
    budget.check(count * bytes_per_point, argument, f"{what} ({count:,} points)", hint=hint)


def iterations(argument: str, pixels: int, max_iterations: int) -> None:
    """Refuse escape-time work of ``pixels`` x ``max_iterations`` past
    :data:`MAX_ITERATIONS`, naming ``argument``."""
    work = int(pixels) * int(max_iterations)
    if work > MAX_ITERATIONS:
        raise ArgumentValueError(
            f"{argument}: {int(pixels):,} pixels x {int(max_iterations):,} iterations = "
            f"{work:,} iterations at most, more than the limit of {MAX_ITERATIONS:,} "
            "(scanline.fractals.limits.MAX_ITERATIONS); give fewer pixels or a smaller "
            "max_iterations")
