"""Two-dimensional geometric transformations as 3x3 homogeneous matrices (notes,
chapter 3; Hearn & Baker, chapter 5).

A point (x, y) is the column vector (x, y, 1); a matrix ``M`` maps it to
``M @ (x, y, 1)``.  Products read right to left: ``compose(A, B)`` is ``A @ B`` and
applies ``B`` first.  Angles are in radians, counterclockwise positive (y is up).

>>> import scanline as sl
>>> m = sl.transform.compose(sl.transform.translation(2, 0), sl.transform.scaling(3))
>>> sl.transform.apply(m, [(1, 1), (0, 0)]).tolist()
[[5.0, 3.0], [2.0, 0.0]]
"""

from .affine2d import (
    AXES,
    apply,
    compose,
    inverse,
    reflection,
    reflection_about_line,
    rotation,
    scaling,
    shear,
    translation,
)

__all__ = [
    "AXES",
    "apply",
    "compose",
    "inverse",
    "reflection",
    "reflection_about_line",
    "rotation",
    "scaling",
    "shear",
    "translation",
]
