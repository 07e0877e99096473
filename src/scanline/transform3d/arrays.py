"""Argument checking for 3-D geometry: points, vectors and 4x4 matrices.

Shared by :mod:`scanline.transform3d`, :mod:`scanline.projection`,
:mod:`scanline.mesh`, the 3-D clippers and :mod:`scanline.draw3d`, so that every
message names the argument, shows the value and says what would work (DESIGN.md,
convention 7).
"""

from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .._validate import real_array
from ..errors import ArgumentTypeError, ArgumentValueError

__all__ = ["direction", "finite", "matrix4", "points", "real_array", "vector"]


def finite(name: str, a: NDArray[np.float64]) -> NDArray[np.float64]:
    """Raise unless every entry of ``a`` is finite, naming the first bad row."""
    if not np.isfinite(a).all():
        if a.ndim == 0:
            raise ArgumentValueError(f"{name} must be finite, got {a}")
        where = np.argwhere(~np.isfinite(a))[0]
        if a.ndim == 1:
            raise ArgumentValueError(f"{name} must be finite; {name}[{int(where[0])}] is "
                                     f"{a[int(where[0])]}")
        row = int(where[0])
        raise ArgumentValueError(f"{name} must be finite; row {row} is {a[row].tolist()}")
    return a


def vector(name: str, value: object, size: int = 3) -> tuple[float, ...]:
    """A point or vector of ``size`` finite real numbers -> tuple of floats."""
    if isinstance(value, (str, bytes)) or not isinstance(value, (Sequence, np.ndarray)):
        raise ArgumentTypeError(
            f"{name} must be a {size}-vector ({', '.join('xyzw'[:size])}) of real numbers, "
            f"got {v._show(value)} of type {type(value).__name__}")
    if (isinstance(value, np.ndarray) and value.ndim != 1) or len(value) != size:
        raise ArgumentValueError(
            f"{name} must be a {size}-vector ({', '.join('xyzw'[:size])}) of real numbers, "
            f"got {v._show(value)}")
    return tuple(v.number(f"{name}[{i}]", c) for i, c in enumerate(value))


def direction(name: str, value: object) -> NDArray[np.float64]:
    """A nonzero 3-vector as a unit float64 array."""
    d = np.array(vector(name, value))
    big = np.abs(d).max()
    if big == 0.0:
        raise ArgumentValueError(f"{name} must not be the zero vector (0, 0, 0): it gives no "
                                 "direction")
    d = d / big            # no overflow or underflow in the norm
    unit: NDArray[np.float64] = d / np.sqrt(d @ d)
    return unit


def matrix4(name: str, value: object) -> NDArray[np.float64]:
    """A finite 4x4 matrix as a float64 array."""
    a = real_array(name, value, "(4, 4)")
    if a.shape != (4, 4):
        hint = ""
        if a.shape == (3, 3):
            hint = "; a 3x3 matrix is a 2-D transformation (scanline.transform)"
        raise ArgumentValueError(
            f"{name} must be a 4x4 matrix, got {v._show(value)} of shape {a.shape}{hint}")
    if not np.isfinite(a).all():
        i, j = (int(k) for k in np.argwhere(~np.isfinite(a))[0])
        raise ArgumentValueError(f"{name} must be finite; {name}[{i}, {j}] is {a[i, j]}")
    return a


def points(name: str, value: object,
           columns: tuple[int, ...] = (3,)) -> tuple[NDArray[np.float64], bool]:
    """(N, c) float64 finite points with c in ``columns``, and whether one point (c,)
    was given.  ``[]`` is an empty batch of ``columns[0]`` columns."""
    shapes = " or ".join(f"(N, {c})" for c in columns)
    a = real_array(name, value, shapes)
    if a.ndim == 1 and a.size == 0:
        a = a.reshape(0, columns[0])
    single = a.ndim == 1 and a.shape[0] in columns
    if single:
        a = a.reshape(1, -1)
    if a.ndim != 2 or a.shape[1] not in columns:
        raise ArgumentValueError(
            f"{name} must be one point or an array of shape {shapes}, got "
            f"{v._show(value)} of shape {a.shape}")
    return finite(name, np.ascontiguousarray(a)), single
