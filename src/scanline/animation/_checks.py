"""Argument checks shared by :mod:`scanline.animation`: arrays of real numbers, flags,
and the memory budget with estimates of any size.

Every conversion of a user's value to an array goes through :func:`floats`, so that
a string, a complex number, a ragged list or an integer beyond the float range is a
:class:`~scanline.errors.ScanlineError` naming the argument, never numpy's own
``ValueError``, ``TypeError`` or ``OverflowError``.
"""

import numbers
import warnings

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError


def floats(name: str, value: object,
           what: str = "a number or an array of numbers") -> NDArray[np.float64]:
    """``value`` as a float64 array (a copy), or ArgumentTypeError naming ``name``.

    Refused: strings and bytes (numpy would read ``"5"`` as 5.0), complex numbers,
    ragged nesting, objects that are not numbers, integers beyond the float range."""
    if isinstance(value, (str, bytes, complex)) or (
            isinstance(value, np.ndarray) and value.dtype.kind in "USVcmM"):
        raise ArgumentTypeError(f"{name} must be {what}, got {v._show(value)}")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")      # (a ComplexWarning inside an object array)
            out: NDArray[np.float64] = np.array(value, dtype=np.float64)
    except (TypeError, ValueError, OverflowError):
        raise ArgumentTypeError(f"{name} must be {what}, got {v._show(value)}") from None
    return out


def finite(name: str, value: object,
           what: str = "a number or an array of numbers") -> NDArray[np.float64]:
    """:func:`floats`, and every element finite."""
    out = floats(name, value, what)
    if not np.isfinite(out).all():
        raise ArgumentValueError(f"{name} must be finite, got {v._show(value)}")
    return out


def flag(name: str, value: object) -> bool:
    """``value`` as a bool: True, False (or numpy's), or the integers 1 and 0."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, numbers.Integral) and value in (0, 1):
        return bool(value)
    raise ArgumentTypeError(f"{name} must be True or False, got {v._show(value)}")


def progress_flag(value: object) -> bool | None:
    """``progress``: None (automatic), True or False."""
    return None if value is None else flag("progress", value)
