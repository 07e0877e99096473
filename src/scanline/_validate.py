"""Argument checking shared by the functional API.

Each helper takes the argument's *name* so that the message names it, shows the value
that was given and says what would work (DESIGN.md, convention 7).
"""

import difflib
import functools
import inspect
import math
import numbers
import os
import re
import sys
import warnings
from typing import Any, Callable, Iterable, Optional, Sequence, Tuple, TypeVar, cast

import numpy as np
from numpy.typing import DTypeLike, NDArray

from .errors import AngleWarning, ArgumentTypeError, ArgumentValueError

#: Largest magnitude accepted for a device coordinate.  Within +-2**30 every
#: scan-conversion kernel does exact int64 arithmetic (products such as
#: ``dy * (x - x0)`` stay below 2**62); anything drawn outside the frame buffer is
#: clipped.
COORD_LIMIT = 2**30

T = TypeVar("T")
F = TypeVar("F", bound=Callable[..., Any])


def _show(value: object) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def number(name: str, value: object) -> float:
    """Return ``value`` as a finite float, or raise naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ArgumentTypeError(
            f"{name} must be a real number, got {_show(value)} of type {type(value).__name__}"
        )
    try:
        v = float(value)
    except OverflowError:
        v = math.inf
    if not math.isfinite(v):
        raise ArgumentValueError(f"{name} must be a finite number, got {_show(value)}")
    return v


#: The units an angle may be written in as a string, in radians per unit.
ANGLE_UNITS = {"deg": math.pi / 180, "°": math.pi / 180, "rad": 1.0, "turn": 2 * math.pi}
_ANGLE = re.compile(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(deg|°|rad|turn)\s*")
#: The largest whole number an angle warning suspects of being degrees (two turns).
DEGREE_LIKE = 720
_PACKAGE = os.path.dirname(os.path.abspath(__file__))


def _caller_level() -> int:
    """The ``stacklevel`` of the first frame outside scanline: a warning then names
    the user's line, however deep the call that gives it."""
    frame: Optional[Any] = sys._getframe(1)
    level = 1
    while frame is not None and os.path.abspath(frame.f_code.co_filename).startswith(_PACKAGE):
        frame, level = frame.f_back, level + 1
    return level


def angle(name: str, value: object) -> float:
    """Return the angle ``value`` in radians, or raise naming ``name``.

    A number is radians (DESIGN.md, convention 3).  A string carries its unit:
    ``"30deg"`` or ``"30°"`` (degrees), ``"0.5rad"``, ``"0.25turn"``.  A whole number
    beyond one turn and at most 720 (``30``, ``90``, ``360``: 2 pi < ``|value|`` <= 720)
    reads as radians but was most likely meant in degrees, so it gives an
    :class:`~scanline.AngleWarning` (pass a float such as ``30.0``, or a unit, to say
    what is meant).

    >>> angle("angle", "90deg") == math.pi / 2, angle("angle", "0.5turn") == math.pi
    (True, True)
    """
    if isinstance(value, str):
        match = _ANGLE.fullmatch(value)
        if match is None:
            raise ArgumentValueError(
                f"{name}={_show(value)} is not an angle: give radians as a number "
                f"(math.pi / 6) or a number with a unit: '30deg', '30°', '0.5rad', '0.25turn'")
        return number(name, float(match[1]) * ANGLE_UNITS[match[2]])
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ArgumentTypeError(
            f"{name} must be an angle, radians as a number or a string with a unit "
            f"such as '30deg', got {_show(value)} of type {type(value).__name__}")
    a = number(name, value)
    if isinstance(value, numbers.Integral) and 2 * math.pi < abs(a) <= DEGREE_LIKE:
        warnings.warn(
            f"{name}={value} is read as radians ({a / (2 * math.pi):.3g} turns); if you "
            f"meant degrees write {name}='{value}deg' or math.radians({value}) (a float "
            f"such as {value}.0 says radians and silences this warning)",
            AngleWarning, stacklevel=_caller_level())
    return a


def coordinate(name: str, value: object) -> int:
    """Round a device coordinate to the nearest pixel center (halves round up).

    Returns a Python int within +-COORD_LIMIT.
    """
    if type(value) is int:  # fast path: most calls pass plain ints
        v = value
    else:
        v = math.floor(number(name, value) + 0.5)
    if -COORD_LIMIT <= v <= COORD_LIMIT:
        return v
    raise ArgumentValueError(
        f"{name}={_show(value)} is outside the supported coordinate range "
        f"[-{COORD_LIMIT}, {COORD_LIMIT}] of a pixel position (a seed, a pixel read or "
        "written, a block of pixels, a pattern's reference point, a step table's "
        "points); give one within it"
    )


def any_coordinate(name: str, value: object) -> int:
    """Round any finite device coordinate to the nearest pixel center (halves round
    up), as a Python int of any size (for the primitives that draw beyond
    +-COORD_LIMIT exactly, such as the conics of :mod:`scanline.geometry.far_conics`)."""
    if type(value) is int and -FLOAT_MAX <= value <= FLOAT_MAX:
        return value          # exact (an int beyond the float range is not finite)
    return math.floor(number(name, value) + 0.5)


#: The largest finite float: an int beyond it is refused as not finite, as
#: :func:`number` refuses it.
FLOAT_MAX = sys.float_info.max


def any_radius(name: str, value: object) -> int:
    """Round any finite radius >= 0 to a Python int of any size, or raise naming
    ``name``."""
    v = any_coordinate(name, value)
    if v < 0:
        raise ArgumentValueError(f"{name} must be >= 0, got {_show(value)}")
    return v


def radius(name: str, value: object, limit: int = COORD_LIMIT) -> int:
    """Round a radius to an int in [0, limit], or raise naming ``name``."""
    v = value if type(value) is int else math.floor(number(name, value) + 0.5)
    if v < 0:
        raise ArgumentValueError(f"{name} must be >= 0, got {_show(value)}")
    if v > limit:
        raise ArgumentValueError(f"{name}={_show(value)} is too large; the limit is {limit}")
    return v


def choice(name: str, value: T, options: Sequence[Any]) -> T:
    """Check that ``value`` is one of ``options`` (a tuple of strings)."""
    if isinstance(value, str) and value in options:
        return value
    listed = ", ".join(repr(o) for o in options)
    raise ArgumentValueError(f"{name} must be one of {listed}; got {_show(value)}")


def one_or_many(name: str, value: object, kinds: Any, what: str,
                empty: bool = True) -> tuple[Any, ...]:
    """``value`` as a tuple: one object of ``kinds`` (a type or a tuple of types), or
    any iterable of them; ``what`` names the kind in the error (e.g. "a
    scanline.mesh.Mesh").  ``empty=False`` refuses an empty collection."""
    if isinstance(value, kinds):
        return (value,)
    items: Optional[tuple[Any, ...]] = None
    if isinstance(value, Iterable) and not isinstance(value, (str, bytes)):
        items = tuple(value)
    if items is None or (not empty and not items):
        raise ArgumentTypeError(f"{name} must be {what} or a{'' if empty else ' non-empty'} "
                                f"list of them, got {_show(value)}")
    for i, item in enumerate(items):
        if not isinstance(item, kinds):
            raise ArgumentTypeError(f"{name}[{i}] must be {what}, got {_show(item)}")
    return items


def positive_int(name: str, value: object, minimum: int = 1) -> int:
    """Check an integer size argument (``width``, ``height`` ...)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise ArgumentTypeError(
            f"{name} must be an integer, got {_show(value)} of type {type(value).__name__}"
        )
    if value < minimum:
        raise ArgumentValueError(f"{name} must be >= {minimum}, got {value}")
    return int(value)


def coordinate_array(name: str, value: object, columns: int,
                     radius_columns: Iterable[int] = (), guard: bool = False,
                     far: bool = False) -> NDArray[Any]:
    """Convert an (N, columns) array of primitives to int64, rounding to pixels
    (an integer array in range is only checked: :func:`integers_in_range`).

    ``radius_columns`` lists the columns that hold radii, which must be >= 0.
    With ``guard`` (segments: ``columns`` = 4), any finite coordinate is taken: rows
    beyond the exact range are clipped to the guard square first
    (:func:`scanline.geometry.guard.segments`).  With ``far`` any finite value is
    taken and the rows come back as float64, not rounded (conic batches, which
    draw far rows themselves).
    """
    exact = None if far else exact_coordinates(name, value, columns, radius_columns)
    if exact is not None:
        return exact
    try:
        a = np.asarray(value)
        if a.dtype.kind in "iu" or a.dtype == object:
            a = a.astype(np.float64)
    except OverflowError:
        raise ArgumentValueError(
            f"{name} holds a number beyond the supported coordinate range "
            f"[-{COORD_LIMIT}, {COORD_LIMIT}]"
        ) from None
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"{name} must be a numeric array of shape (N, {columns}), got {_show(value)}"
        ) from None
    if a.dtype.kind != "f":
        raise ArgumentTypeError(
            f"{name} must hold real numbers, got an array of dtype {a.dtype}"
        )
    if a.ndim == 1 and a.size == 0:  # [] is an empty batch
        a = a.reshape(0, columns)
    if a.ndim == 1 and a.size == columns:
        a = a.reshape(1, columns)
    if a.ndim != 2 or a.shape[1] != columns:
        raise ArgumentValueError(
            f"{name} must have shape (N, {columns}), got shape {a.shape}"
        )
    # in range (the common case) in two passes without temporaries; NaN fails both
    # (compared as Python floats: against a float16 array the limit itself would be
    # cast to float16, where it is inf)
    if a.size and not (-COORD_LIMIT <= float(a.min()) and float(a.max()) <= COORD_LIMIT):
        if not np.isfinite(a).all():
            row = int(np.argwhere(~np.isfinite(a))[0][0])
            raise ArgumentValueError(
                f"{name} must be finite; row {row} is {a[row].tolist()}"
            )
        if guard:
            from .geometry.guard import segments
            a = segments(np.ascontiguousarray(a, np.float64))
        if not far and np.abs(a).max() > COORD_LIMIT:
            row = int(np.argwhere(np.abs(a) > COORD_LIMIT)[0][0])
            raise ArgumentValueError(
                f"{name} row {row} = {a[row].tolist()} is outside the supported coordinate "
                f"range [-{COORD_LIMIT}, {COORD_LIMIT}]"
            )
    for c in radius_columns:
        _radii(name, a, c)
    if far:
        return np.ascontiguousarray(a, np.float64)
    half: NDArray[np.float64] = np.add(a, 0.5)
    np.floor(half, out=half)
    return half.astype(np.int64, order="C")


def integers_in_range(value: object, columns: int) -> Optional[NDArray[np.int64]]:
    """``value`` as an (N, columns) int64 array when it is an integer array of that
    shape whose values lie within +-COORD_LIMIT (the common case of a large batch:
    checked in two passes, not converted to floats and back), else None.  An int64
    C-contiguous array comes back itself, not copied: its callers only read it."""
    if not isinstance(value, np.ndarray):
        return None
    if value.dtype.kind not in "iu" or value.ndim != 2 or value.shape[1] != columns:
        return None
    if value.size:
        lo, hi = extremes(value)        # (on every core for a large batch)
        if not (-COORD_LIMIT <= lo and hi <= COORD_LIMIT):
            return None
    return np.ascontiguousarray(value, np.int64)


def exact_coordinates(name: str, value: object, columns: int,
                      radius_columns: Iterable[int] = ()) -> Optional[NDArray[np.int64]]:
    """``value`` as :func:`integers_in_range` gives it, its ``radius_columns``
    checked (a negative radius is an error naming ``name``), or None when it is not
    an integer array in range (:func:`coordinate_array` then converts it)."""
    exact = integers_in_range(value, columns)
    if exact is not None:
        for c in radius_columns:
            _radii(name, exact, c)
    return exact


def _radii(name: str, a: NDArray[Any], c: int) -> None:
    """Refuse a negative value in column ``c`` (radii) of the (N, k) array ``a``."""
    if a.size and (a[:, c] < 0).any():
        row = int(np.argwhere(a[:, c] < 0)[0][0])
        raise ArgumentValueError(
            f"{name} column {c} holds radii, which must be >= 0; row {row} is {a[row].tolist()}"
        )


#: Largest value an int64 holds.
INT64_MAX = 2**63 - 1


def _integers(name: str, value: object, what: str) -> Optional[NDArray[Any]]:
    """``value`` as an integer numpy array (int or uint dtype, or int64 converted
    from Python ints of any size), refusing everything else; None for an empty
    array of any dtype."""
    try:
        a = np.asarray(value)
    except (TypeError, ValueError, OverflowError):
        raise ArgumentTypeError(f"{name} must be {what}, got {_show(value)}") from None
    if a.size == 0 and a.dtype.kind in "iufbO":
        return None
    if a.dtype == object:
        items = a.ravel().tolist()
        if not all(isinstance(i, numbers.Integral) and not isinstance(i, (bool, np.bool_))
                   for i in items):
            raise ArgumentTypeError(f"{name} must be {what}, got {_show(value)}")
        lo, hi = min(items), max(items)
        if lo < -INT64_MAX - 1 or hi > INT64_MAX:
            bad = lo if lo < -INT64_MAX - 1 else hi
            raise ArgumentValueError(f"{name} holds {bad}, beyond the 64-bit integer range; "
                                     f"{name} indexes arrays, so its values are small")
        return np.array(items, np.int64).reshape(a.shape)
    if a.dtype.kind not in "iu":
        raise ArgumentTypeError(f"{name} must be {what} (an integer dtype), got "
                                f"{'an array of dtype ' + str(a.dtype) if a.ndim else _show(value)}")
    return a


def index_array(name: str, value: object, *, shape: Sequence[Optional[int]] = (None,),
                low: int = 0, high: int = INT64_MAX, rising: bool = False,
                first: Optional[int] = None, last: Optional[int] = None,
                what: Optional[str] = None, bound_text: str = "") -> NDArray[np.int64]:
    """An integer array that indexes -- counts, offsets, indices, the faces of a
    mesh -- checked and converted to int64 before any arithmetic is done with it.

    This is the one validation path for such arrays (a kernel trusts them: numba
    does not check bounds).  In order:

    1. an integer dtype is required (int or uint; Python ints of any size; not
       bool, not float, not even integral floats);
    2. the shape must match ``shape`` (None: any length in that axis); an empty
       list is an empty array of that shape;
    3. every value must lie in ``[low, high]``, compared in the array's own dtype
       (a uint64 above 2**63 - 1 is refused, not wrapped to a negative int64);
    4. only then is it converted to C-contiguous, writable int64;
    5. ``rising=True``: the values must not decrease; ``first`` / ``last``: the
       first / last value must equal them.

    Returns the int64 array.

    >>> index_array("counts", [3, 4])
    array([3, 4])
    >>> index_array("offsets", np.array([0, 2**64 - 5, 3], np.uint64), high=3)
    Traceback (most recent call last):
    ...
    scanline.errors.ArgumentValueError: offsets must be <= 3; offsets[1] is 18446744073709551611
    """
    what = what or f"an integer array of shape {_shape_text(shape)}"
    a = _integers(name, value, what)
    if a is None:
        out = np.zeros(tuple(0 if s is None else s for s in shape), np.int64)
        if len(shape) > 1 and shape[0] is None and all(s is not None for s in shape[1:]):
            return out
        if len(shape) == 1 and (shape[0] is None or shape[0] == 0):
            if first is not None or last is not None:
                raise ArgumentValueError(f"{name} must not be empty, got {_show(value)}")
            return out
        raise ArgumentValueError(f"{name} must have shape {_shape_text(shape)}, got an empty array")
    if a.ndim != len(shape):   # not even the right kind of array
        raise ArgumentTypeError(f"{name} must be {what}, got shape {a.shape}")
    if any(s is not None and s != n for s, n in zip(shape, a.shape)):
        raise ArgumentValueError(f"{name} must have shape {_shape_text(shape)}, got shape {a.shape}")
    rule = (f"{name} must rise from {first} to {last} without decreasing"
            if rising and first is not None and last is not None else None)
    lo, hi = int(a.min()), int(a.max())
    if lo < low or hi > high:
        flat = a.ravel()
        i = int(np.argmax(flat < low)) if lo < low else int(np.argmax(flat > high))
        index = ", ".join(str(int(k)) for k in np.unravel_index(i, a.shape))
        bound = f">= {low}" if lo < low else f"<= {high}{bound_text}"
        raise ArgumentValueError(f"{rule or name + ' must be ' + bound}; {name}[{index}] is "
                                 f"{int(flat[i])}")
    out = np.ascontiguousarray(a, np.int64)
    if not out.flags.writeable:
        out = out.copy()
    if rising and out.size > 1:
        down = out[1:] < out[:-1]
        if down.any():
            i = int(np.argmax(down))
            raise ArgumentValueError(f"{rule or name + ' must not decrease'}; {name}[{i + 1}] = "
                                     f"{int(out[i + 1])} comes after {int(out[i])}")
    for which, want, got in (("first", first, 0), ("last", last, -1)):
        if want is not None and int(out.flat[got]) != want:
            raise ArgumentValueError(f"{rule or name + ' must ' + which[:-1] + ' with ' + str(want)}"
                                     f"; its {which} value is {int(out.flat[got])}")
    return out


def _shape_text(shape: Sequence[Optional[int]]) -> str:
    return "(" + ", ".join("N" if s is None else str(s) for s in shape) + ("," if len(shape) == 1 else "") + ")"


def exact_sum(a: NDArray[np.int64]) -> int:
    """The sum of an int64 array as a Python int, exact: numpy's sum wraps around
    on overflow, so large values are added as Python ints."""
    if a.size == 0:
        return 0
    big = max(abs(int(a.min())), abs(int(a.max())))
    if big * a.size <= INT64_MAX:
        return int(a.sum())
    return sum(a.tolist())


def counts(name: str, value: object, total: int,
           total_name: str) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Per-part counts (``value``, e.g. vertices per polygon) that must add up to
    ``total`` (the length of ``total_name``), as int64 counts and offsets
    ``(counts, offsets)``: part ``i`` is ``offsets[i]:offsets[i + 1]``.

    Each count is checked against ``total`` and the sum computed exactly before the
    offsets are (a sum that wraps around would pass a check done in int64).

    >>> counts("counts", [2, 3], 5, "points")
    (array([2, 3]), array([0, 2, 5]))
    >>> counts("counts", np.array([2**63, 2**63, 3], np.uint64), 3, "points")
    Traceback (most recent call last):
    ...
    scanline.errors.ArgumentValueError: counts must be <= 3 (the length of points); counts[0] is 9223372036854775808
    """
    c = index_array(name, value, high=total, bound_text=f" (the length of {total_name})",
                    what="a 1-D array of integers (how many belong to each part)")
    s = exact_sum(c)
    if s != total:
        raise ArgumentValueError(f"{name} add up to {s}, but {total_name} holds {total}; give "
                                 "one count per part, adding up to that")
    offsets = np.zeros(len(c) + 1, np.int64)
    np.cumsum(c, out=offsets[1:])
    return c, offsets


#: Values from which :func:`extremes` splits an array between the cores.
SPLIT_VALUES = 1 << 18


#: Values from which :func:`_min_max` reduces an array block by block (32 MB of
#: float64, a processor's last-level cache), and the block (1 MB): the maximum then
#: reads what the minimum just brought into the cache instead of memory again (the
#: 9M vertex values of a million triangles on two threads: 1.19-1.34x as fast in four
#: runs in turn in one process, 2026-12-07; below the threshold a part stays cached).
MIN_MAX_BLOCKED = 1 << 22
MIN_MAX_BLOCK = 1 << 17


def _min_max(a: NDArray[Any]) -> Tuple[float, float]:
    """The least and the largest value of the flat array ``a`` (NaN where it holds
    one): a large array in one pass over memory, not two (:data:`MIN_MAX_BLOCKED`)."""
    if a.size < MIN_MAX_BLOCKED:
        return float(a.min()), float(a.max())
    found = np.array([(b.min(), b.max()) for b in
                      (a[i:i + MIN_MAX_BLOCK] for i in range(0, a.size, MIN_MAX_BLOCK))])
    return float(found[:, 0].min()), float(found[:, 1].max())        # (NaN carries)


def extremes(a: NDArray[Any]) -> Tuple[float, float]:
    """The smallest and the largest value of the non-empty array ``a`` (both NaN
    where it holds a NaN), for checking a large batch's values in range: from
    :data:`SPLIT_VALUES` values on, its parts are reduced at once on every core
    (numpy's reductions release the interpreter lock), the threads of the batch
    kernels (:func:`scanline._kernels._threads.threads`).  One million triangles'
    vertices and colors, 2 x 72 MB: 20 ms in one thread, 10 ms on two (measured
    2026-12-06)."""
    from ._kernels._threads import _together, threads

    flat = a.ravel(order="K")
    n = flat.size
    parts = min(threads(), n // SPLIT_VALUES + 1)
    if parts <= 1:
        return _min_max(flat)
    found = np.array(_together([(_min_max, 0, flat[n * i // parts:n * (i + 1) // parts])
                                for i in range(parts)]))
    return float(found[:, 0].min()), float(found[:, 1].max())       # (NaN carries)


def kernel_array(a: Any, dtype: DTypeLike = np.float64) -> NDArray[Any]:
    """``a`` as the kernels take arrays: C-contiguous, writable, of ``dtype`` (a copy
    only where one of those is missing).  numba compiles a separate specialization
    for a read-only or non-contiguous array, so every array reaches a kernel this way
    (the compile-time rule of :mod:`scanline._kernels`, rule 2)."""
    out: NDArray[Any] = np.ascontiguousarray(a, dtype)
    return out if out.flags.writeable else out.copy()


def real_array(name: str, value: object, expected: str) -> NDArray[np.float64]:
    """``value`` as a float64 array (not copied when it is one), or an error naming
    ``name``; ``expected`` describes the shape that would work, for the message."""
    try:
        a = np.asarray(value)
        if a.dtype == object:
            a = a.astype(np.float64)
    except OverflowError:
        raise ArgumentValueError(
            f"{name} holds a number too large for float64: {_show(value)}") from None
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"{name} must be a numeric array of shape {expected}, got {_show(value)}"
        ) from None
    if a.dtype == bool or a.dtype.kind not in "iuf":
        raise ArgumentTypeError(
            f"{name} must hold real numbers ({expected}), got an array of dtype {a.dtype}")
    return np.asarray(a, dtype=np.float64)


def keywords(function: F) -> F:
    """``function`` with its keyword arguments checked before the call: an unknown
    keyword is an :class:`ArgumentTypeError` that names it and suggests the nearest
    valid one ("material= is not an option of render; did you mean materials=?").
    Type checkers see ``function``'s own signature."""
    names = [p.name for p in inspect.signature(function).parameters.values()
             if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)]

    @functools.wraps(function)
    def checked(*args: Any, **kwargs: Any) -> Any:
        for key in kwargs:
            if key not in names:
                close = difflib.get_close_matches(key, names, n=1, cutoff=0.6)
                hint = f"; did you mean {close[0]}=?" if close else \
                    f"; its options are {', '.join(n + '=' for n in names)}"
                raise ArgumentTypeError(f"{key}= is not an option of "
                                        f"{function.__name__}{hint}")
        return function(*args, **kwargs)

    return cast(F, checked)
