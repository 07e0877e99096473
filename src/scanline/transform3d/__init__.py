"""Three-dimensional geometric transformations as 4x4 homogeneous matrices (Hearn &
Baker, chapter 11), with the names of :mod:`scanline.transform`.

A point (x, y, z) is the column vector (x, y, z, 1); ``compose(A, B)`` is ``A @ B``
and applies ``B`` first.  Right-handed coordinates; angles in radians,
counterclockwise looking from the positive axis toward the origin.

>>> import math, scanline as sl
>>> m = sl.transform3d.compose(sl.transform3d.translation(0, 0, 1),
...                            sl.transform3d.rotation(math.pi / 2, "x"))
>>> (sl.transform3d.apply(m, (0, 1, 0)).round(12) + 0).tolist()
[0.0, 0.0, 2.0]

Rotations can also be held as unit quaternions (:class:`Quaternion`, section 11-2),
interpolated by :func:`slerp` and :func:`squad` (Shoemake 1985).
"""

from .affine3d import (
    AXES,
    PLANES,
    Step,
    apply,
    axis_alignment,
    compose,
    inverse,
    is_affine,
    reflection,
    rotation,
    rotation_steps,
    scaling,
    shear,
    translation,
)
from .quaternion import Quaternion, slerp, squad, squad_controls

__all__ = ["AXES", "PLANES", "Step", "apply", "axis_alignment", "compose", "inverse",
           "is_affine", "Quaternion", "reflection", "rotation", "rotation_steps", "scaling",
           "shear", "slerp", "squad", "squad_controls", "translation"]
