"""2-D affine transformations in homogeneous coordinates: 3x3 float64 matrices.

Conventions (DESIGN.md, convention 3): a point (x, y) is the column vector
(x, y, 1) and ``M`` maps it to ``M @ (x, y, 1)``; every matrix built here has the
bottom row (0, 0, 1).  Composition reads right to left.  Angles are in radians and
positive angles turn counterclockwise (y is up).

The notes (chapter 3) derive translation (Q.1) and rotation about the origin and
about a pivot (Q.2); the rest of the chapter's syllabus -- scaling, homogeneous
coordinates, composite and inverse transformations -- and the reflections and shears
follow Hearn & Baker, chapter 5.  See docs/errata.md, "Chapter 3".

Everything here is plain numpy: no numba kernel is involved.

References
----------
.. [1] D. Hearn and M. P. Baker, *Computer Graphics, C Version*, 2nd ed., Prentice
   Hall, 1997, chapter 5.
.. [2] J. D. Foley, A. van Dam, S. K. Feiner and J. F. Hughes, *Computer Graphics:
   Principles and Practice*, 2nd ed., Addison-Wesley, 1990, chapter 5.
"""

import math
from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._validate import real_array as _real_array
from .._typing import Angle
from ..errors import ArgumentTypeError, ArgumentValueError

#: The axes accepted by :func:`reflection`.
AXES = ("x", "y", "origin", "y=x", "y=-x")

#: How far the bottom row of a matrix may be from (0, 0, 1) for it to count as affine.
AFFINE_TOLERANCE = 1e-12

#: A matrix counts as singular when |det A| <= SINGULAR * ||A||_F**2 for its 2x2 part
#: A: 64 times the rounding error of the determinant itself (1/cond(A) below ~1e-14).
SINGULAR = 64 * np.finfo(np.float64).eps


# -- argument checking ------------------------------------------------------------------
def _point(name: str, value: object) -> tuple[float, float]:
    """A point or vector given as two finite real numbers -> (float, float)."""
    if isinstance(value, (str, bytes)) or not isinstance(value, (Sequence, np.ndarray)):
        raise ArgumentTypeError(
            f"{name} must be a point (x, y) of two real numbers, got {v._show(value)}"
            f" of type {type(value).__name__}"
        )
    if (isinstance(value, np.ndarray) and value.ndim != 1) or len(value) != 2:
        raise ArgumentValueError(
            f"{name} must be a point (x, y) of two real numbers, got {v._show(value)}"
        )
    return v.number(f"{name}[0]", value[0]), v.number(f"{name}[1]", value[1])


def _matrix(name: str, value: object) -> NDArray[np.float64]:
    """A finite 3x3 matrix as a new float64 array."""
    a = _real_array(name, value, "(3, 3)")
    if a.shape != (3, 3):
        hint = ""
        if a.ndim == 3 and a.shape[1:] == (3, 3):
            hint = "; to multiply a stack of matrices pass them one by one: compose(*stack)"
        raise ArgumentValueError(
            f"{name} must be a 3x3 matrix, got {v._show(value)} of shape {a.shape}{hint}"
        )
    if not np.isfinite(a).all():
        i, j = (int(k) for k in np.argwhere(~np.isfinite(a))[0])
        raise ArgumentValueError(f"{name} must be finite; {name}[{i}, {j}] is {a[i, j]}")
    return a


def _affine(name: str, value: object) -> NDArray[np.float64]:
    """A finite 3x3 matrix whose bottom row is (0, 0, 1)."""
    a = _matrix(name, value)
    bottom = a[2]
    if (abs(bottom[0]) > AFFINE_TOLERANCE or abs(bottom[1]) > AFFINE_TOLERANCE
            or abs(bottom[2] - 1.0) > AFFINE_TOLERANCE):
        hint = ""
        if bottom[0] == 0 and bottom[1] == 0 and bottom[2] != 0:
            hint = f" (divide the matrix by its corner element {bottom[2]:g} first)"
        raise ArgumentValueError(
            f"{name} must be an affine 2-D transformation, whose bottom row is (0, 0, 1); "
            f"got bottom row {bottom.tolist()}{hint}"
        )
    return a


def _points(name: str, value: object) -> tuple[NDArray[np.float64], bool]:
    """(N, 2) float64 points and whether a single (2,) point was given."""
    a = _real_array(name, value, "(N, 2)")
    if a.ndim == 1 and a.size == 0:  # [] is an empty batch
        a = a.reshape(0, 2)
    single = a.shape == (2,)
    if single:
        a = a.reshape(1, 2)
    if a.ndim != 2 or a.shape[1] != 2:
        raise ArgumentValueError(
            f"{name} must be one point of shape (2,) or an array of shape (N, 2), "
            f"got {v._show(value)} of shape {a.shape}"
        )
    if not np.isfinite(a).all():
        row = int(np.argwhere(~np.isfinite(a))[0][0])
        raise ArgumentValueError(f"{name} must be finite; row {row} is {a[row].tolist()}")
    return a, single


def _homogeneous(a: float, b: float, c: float, d: float, e: float,
                 f: float) -> NDArray[np.float64]:
    """The matrix [[a, b, c], [d, e, f], [0, 0, 1]] (negative zeros made positive)."""
    m = np.array([[a, b, c], [d, e, f], [0.0, 0.0, 1.0]], dtype=np.float64)
    m += 0.0  # -0.0 + 0.0 == +0.0: tidy printing, no change in value
    return m


# -- the basic transformations ------------------------------------------------------------
def translation(tx: float, ty: float) -> NDArray[np.float64]:
    """Translation by the vector (tx, ty).

    ::

        T(tx, ty) = | 1  0  tx |        x' = x + tx
                    | 0  1  ty |        y' = y + ty
                    | 0  0   1 |

    Parameters
    ----------
    tx, ty : float
        The translation distances (the shift vector), finite.

    Returns
    -------
    ndarray of float64, shape (3, 3)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``tx`` or ``ty`` is not a finite real number.

    Notes
    -----
    The notes, chapter 3, Q.1 ("translation"), write this as P' = P + T with 2-vectors;
    homogeneous coordinates turn the addition into the product P' = T(tx, ty) · P, so that
    translations compose with the other transformations (Hearn & Baker, section 5-2).
    The inverse is T(-tx, -ty).

    References
    ----------
    Hearn & Baker, chapter 5, sections 5-1 and 5-2;
    Foley et al., chapter 5 (cited in full in the module docstring).

    Examples
    --------
    >>> from scanline.transform import translation, apply
    >>> translation(2, 3).tolist()
    [[1.0, 0.0, 2.0], [0.0, 1.0, 3.0], [0.0, 0.0, 1.0]]
    >>> apply(translation(2, 3), (1, 1)).tolist()
    [3.0, 4.0]
    """
    tx = v.number("tx", tx)
    ty = v.number("ty", ty)
    return _homogeneous(1.0, 0.0, tx, 0.0, 1.0, ty)


def rotation(angle: Angle, pivot: ArrayLike | None = None) -> NDArray[np.float64]:
    """Rotation by ``angle`` radians, counterclockwise, about the origin or a pivot.

    ::

        R(θ) = | cos θ  -sin θ  0 |        x' = x cos θ - y sin θ
               | sin θ   cos θ  0 |        y' = x sin θ + y cos θ
               |   0       0    1 |

    About a pivot (xr, yr) the matrix is T(xr, yr) · R(θ) · T(-xr, -yr)::

        | cos θ  -sin θ  xr (1 - cos θ) + yr sin θ |
        | sin θ   cos θ  yr (1 - cos θ) - xr sin θ |
        |   0       0                1             |

        x' = xr + (x - xr) cos θ - (y - yr) sin θ
        y' = yr + (x - xr) sin θ + (y - yr) cos θ

    Parameters
    ----------
    angle : float
        The rotation angle θ in radians, finite; positive turns counterclockwise.
    pivot : (float, float), optional
        The fixed point (xr, yr) of the rotation; the origin when omitted.

    Returns
    -------
    ndarray of float64, shape (3, 3)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``angle`` is not a finite angle or ``pivot`` not a point of two finite numbers.

    Notes
    -----
    The notes, chapter 3, Q.2 ("rotation"), derive both sets of equations: about the
    origin from x = r cos φ, y = r sin φ and the angle-sum formulas, and about a pivot
    by adding the pivot's terms (see docs/errata.md for the misprints in that
    derivation).  A rotation is rigid: it keeps distances and angles, its determinant
    is 1 and its inverse is R(-θ) about the same pivot.  Multiples of π/2 are not
    exact in floating point: ``cos(math.pi / 2)`` is about 6e-17, not 0.

    References
    ----------
    Hearn & Baker, chapter 5, sections 5-1 to 5-3;
    Foley et al., chapter 5 (cited in full in the module docstring).

    Examples
    --------
    >>> import math
    >>> from scanline.transform import rotation, apply
    >>> (apply(rotation(math.pi / 2), (1, 0)).round(12) + 0.0).tolist()
    [0.0, 1.0]
    >>> (apply(rotation(math.pi, pivot=(1, 1)), (3, 1)).round(12) + 0.0).tolist()
    [-1.0, 1.0]
    """
    theta = v.angle("angle", angle)
    c, s = math.cos(theta), math.sin(theta)
    if pivot is None:
        return _homogeneous(c, -s, 0.0, s, c, 0.0)
    xr, yr = _point("pivot", pivot)
    return _homogeneous(c, -s, xr * (1.0 - c) + yr * s, s, c, yr * (1.0 - c) - xr * s)


def scaling(sx: float, sy: float | None = None,
            fixed: ArrayLike | None = None) -> NDArray[np.float64]:
    """Scaling by sx along x and sy along y, about the origin or a fixed point.

    ::

        S(sx, sy) = | sx   0  0 |        x' = x · sx
                    |  0  sy  0 |        y' = y · sy
                    |  0   0  1 |

    About a fixed point (xf, yf) the matrix is T(xf, yf) · S(sx, sy) · T(-xf, -yf)::

        | sx   0  xf (1 - sx) |        x' = xf + (x - xf) sx
        |  0  sy  yf (1 - sy) |        y' = yf + (y - yf) sy
        |  0   0       1      |

    Parameters
    ----------
    sx : float
        The scale factor along x, finite.  Negative factors also reflect; a zero factor
        collapses the plane onto a line (allowed, but such a matrix has no
        :func:`inverse`).
    sy : float, optional
        The scale factor along y; ``sx`` (uniform scaling) when omitted.
    fixed : (float, float), optional
        The point (xf, yf) that stays in place; the origin when omitted.

    Returns
    -------
    ndarray of float64, shape (3, 3)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If a factor is not a finite real number or ``fixed`` not a point of two finite
        numbers.

    Notes
    -----
    The notes' syllabus for chapter 3 lists "scaling transformations" and "inverse
    transformations", but the notes derive neither; this follows Hearn & Baker,
    section 5-1 (scaling about a fixed point: section 5-3).  Scaling about the origin
    also moves every point other than the origin, which is why a fixed point is
    offered.  The inverse is S(1/sx, 1/sy) about the same point.

    References
    ----------
    Hearn & Baker, chapter 5, sections 5-1 and 5-3;
    Foley et al., chapter 5 (cited in full in the module docstring).

    Examples
    --------
    >>> from scanline.transform import scaling, apply
    >>> scaling(2, 3).tolist()
    [[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 1.0]]
    >>> apply(scaling(2, fixed=(1, 1)), [(1, 1), (2, 3)]).tolist()
    [[1.0, 1.0], [3.0, 5.0]]
    """
    sx = v.number("sx", sx)
    sy = sx if sy is None else v.number("sy", sy)
    if fixed is None:
        return _homogeneous(sx, 0.0, 0.0, 0.0, sy, 0.0)
    xf, yf = _point("fixed", fixed)
    return _homogeneous(sx, 0.0, xf * (1.0 - sx), 0.0, sy, yf * (1.0 - sy))


_REFLECTIONS = {
    "x": (1.0, 0.0, 0.0, -1.0),
    "y": (-1.0, 0.0, 0.0, 1.0),
    "origin": (-1.0, 0.0, 0.0, -1.0),
    "y=x": (0.0, 1.0, 1.0, 0.0),
    "y=-x": (0.0, -1.0, -1.0, 0.0),
}


def reflection(axis: str) -> NDArray[np.float64]:
    """Reflection about a coordinate axis, the origin or a diagonal.

    ::

        axis="x"         axis="y"         axis="origin"     axis="y=x"       axis="y=-x"
        | 1  0  0 |      | -1  0  0 |     | -1   0  0 |     | 0  1  0 |      |  0  -1  0 |
        | 0 -1  0 |      |  0  1  0 |     |  0  -1  0 |     | 1  0  0 |      | -1   0  0 |
        | 0  0  1 |      |  0  0  1 |     |  0   0  1 |     | 0  0  1 |      |  0   0  1 |
        (x, -y)          (-x, y)          (-x, -y)          (y, x)           (-y, -x)

    Parameters
    ----------
    axis : {"x", "y", "origin", "y=x", "y=-x"}
        ``"x"`` reflects about the x axis (the line y = 0), ``"y"`` about the y axis,
        ``"origin"`` through the origin (a point reflection), ``"y=x"`` and ``"y=-x"``
        about those diagonals.

    Returns
    -------
    ndarray of float64, shape (3, 3)

    Raises
    ------
    ArgumentValueError
        If ``axis`` is not one of :data:`AXES`.

    See Also
    --------
    reflection_about_line : reflection about any line.

    Notes
    -----
    Not in the notes; Hearn & Baker, section 5-4.  Every reflection is its own
    inverse.  The line reflections have determinant -1 (they reverse orientation); the
    reflection through the origin is the rotation by π and has determinant +1.

    References
    ----------
    Hearn & Baker, chapter 5, section 5-4;
    Foley et al., chapter 5 (cited in full in the module docstring).

    Examples
    --------
    >>> from scanline.transform import reflection, apply
    >>> apply(reflection("y=x"), (1, 2)).tolist()
    [2.0, 1.0]
    >>> apply(reflection("x"), [(1, 2), (3, -4)]).tolist()
    [[1.0, -2.0], [3.0, 4.0]]
    """
    a, b, d, e = _REFLECTIONS[v.choice("axis", axis, AXES)]
    return _homogeneous(a, b, 0.0, d, e, 0.0)


def reflection_about_line(point: ArrayLike, direction: ArrayLike) -> NDArray[np.float64]:
    """Reflection about the line through ``point`` along ``direction``.

    With (dx, dy) the direction, n = dx² + dy², c = (dx² - dy²) / n = cos 2α and
    s = 2 dx dy / n = sin 2α (α the line's angle with the x axis), and (x0, y0) the
    point, the matrix is T(x0, y0) · Ref · T(-x0, -y0)::

        | c   s  x0 - c x0 - s y0 |
        | s  -c  y0 - s x0 + c y0 |
        | 0   0         1         |

    Parameters
    ----------
    point : (float, float)
        Any point (x0, y0) of the line, finite.
    direction : (float, float)
        A direction (dx, dy) of the line, finite and not (0, 0); its length does not
        matter.

    Returns
    -------
    ndarray of float64, shape (3, 3)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``point`` or ``direction`` is not a point of two finite numbers, or
        ``direction`` is (0, 0).

    Notes
    -----
    Not in the notes.  Hearn & Baker (section 5-4) build the same matrix as a
    composite: translate the line to the origin, rotate it onto the x axis, reflect
    about the x axis, and undo the rotation and the translation.  Integer directions
    give exact matrices for the axes and diagonals; the reflection is its own inverse
    and has determinant -1.

    References
    ----------
    Hearn & Baker, chapter 5, sections 5-3 and 5-4;
    Foley et al., chapter 5 (cited in full in the module docstring).

    Examples
    --------
    The line y = x + 1:

    >>> from scanline.transform import reflection_about_line, apply
    >>> m = reflection_about_line((0, 1), (1, 1))
    >>> m.tolist()
    [[0.0, 1.0, -1.0], [1.0, 0.0, 1.0], [0.0, 0.0, 1.0]]
    >>> apply(m, [(0, 0), (2, 3)]).tolist()
    [[-1.0, 1.0], [2.0, 3.0]]
    """
    x0, y0 = _point("point", point)
    dx, dy = _point("direction", direction)
    n = dx * dx + dy * dy
    if not 1e-290 < n < math.inf:  # rescale to avoid underflow or overflow
        big = max(abs(dx), abs(dy))
        if big == 0.0:
            raise ArgumentValueError(
                f"direction must not be (0, 0): a line needs a nonzero direction (dx, dy), "
                f"got {v._show(direction)}"
            )
        dx, dy = dx / big, dy / big
        n = dx * dx + dy * dy
    c = (dx * dx - dy * dy) / n
    s = 2.0 * dx * dy / n
    return _homogeneous(c, s, x0 - c * x0 - s * y0, s, -c, y0 - s * x0 + c * y0)


def shear(shx: float = 0.0, shy: float = 0.0,
          reference: ArrayLike | None = None) -> NDArray[np.float64]:
    """Shear along x (by ``shx``) and along y (by ``shy``), relative to a reference.

    ::

        | 1    shx  -shx · yref |        x' = x + shx (y - yref)
        | shy   1   -shy · xref |        y' = y + shy (x - xref)
        | 0     0        1      |

    ``shear(shx=a)`` alone is the x-shear: it slides each point along x by ``a`` times
    its height above the reference line y = yref, which stays fixed.  ``shear(shy=b)``
    alone is the y-shear relative to the line x = xref.  Given both, the two act at
    once (the matrix above), which differs from one shear after the other: use
    ``compose(shear(shy=b), shear(shx=a))`` for "x-shear, then y-shear".

    Parameters
    ----------
    shx : float, optional
        The x-shear parameter, finite (a slope: ``math.tan(angle)`` shears lines
        x = const by ``angle`` from the vertical towards +x).
    shy : float, optional
        The y-shear parameter, finite.
    reference : (float, float), optional
        (xref, yref): the x-shear keeps the line y = yref fixed and the y-shear the line
        x = xref; the point (xref, yref) is fixed by every shear.  The origin when
        omitted.

    Returns
    -------
    ndarray of float64, shape (3, 3)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If a parameter is not a finite real number or ``reference`` not a point of two
        finite numbers.

    Notes
    -----
    Not in the notes; Hearn & Baker, section 5-4 (x-shear relative to y = yref and
    y-shear relative to x = xref).  The determinant is 1 - shx · shy: a one-way shear
    keeps areas; with shx · shy = 1 the matrix is singular.  shapely's
    ``affinity.skew(geom, xs, ys, origin=(xref, yref), use_radians=True)`` is
    ``shear(math.tan(xs), math.tan(ys), (xref, yref))``.

    References
    ----------
    Hearn & Baker, chapter 5, section 5-4;
    Foley et al., chapter 5 (cited in full in the module docstring).

    Examples
    --------
    The unit square sheared along x by 2, about y = 0 and about y = -1:

    >>> from scanline.transform import shear, apply
    >>> square = [(0, 0), (1, 0), (1, 1), (0, 1)]
    >>> apply(shear(shx=2), square).tolist()
    [[0.0, 0.0], [1.0, 0.0], [3.0, 1.0], [2.0, 1.0]]
    >>> apply(shear(shx=2, reference=(0, -1)), square).tolist()
    [[2.0, 0.0], [3.0, 0.0], [5.0, 1.0], [4.0, 1.0]]
    """
    shx = v.number("shx", shx)
    shy = v.number("shy", shy)
    xref, yref = (0.0, 0.0) if reference is None else _point("reference", reference)
    return _homogeneous(1.0, shx, -shx * yref, shy, 1.0, -shy * xref)


# -- composition, inversion, application ----------------------------------------------------
def compose(*matrices: ArrayLike) -> NDArray[np.float64]:
    """The product of 3x3 matrices, applied right to left.

    ``compose(A, B, C)`` is ``A @ B @ C``: applied to a point it performs C first, then
    B, then A, as in M · P = A · (B · (C · P)).  ``compose()`` is the identity.

    Parameters
    ----------
    *matrices : array_like, shape (3, 3)
        Finite 3x3 matrices (any bottom row: this is the plain matrix product).

    Returns
    -------
    ndarray of float64, shape (3, 3)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If a matrix is not a finite real 3x3 array.

    Notes
    -----
    Composite transformations: Hearn & Baker, section 5-3 ("composite
    transformations").  Matrix products do not commute, so the order matters:
    ``compose(translation(1, 0), reflection("y=x"))`` reflects first and then moves
    right, ``compose(reflection("y=x"), translation(1, 0))`` moves right first and then
    reflects.

    References
    ----------
    Hearn & Baker, chapter 5, section 5-3;
    Foley et al., chapter 5 (cited in full in the module docstring).

    Examples
    --------
    >>> from scanline.transform import compose, translation, reflection, apply
    >>> apply(compose(translation(1, 0), reflection("y=x")), (2, 0)).tolist()
    [1.0, 2.0]
    >>> apply(compose(reflection("y=x"), translation(1, 0)), (2, 0)).tolist()
    [0.0, 3.0]
    """
    result = np.eye(3)
    for i, m in enumerate(matrices):
        result = result @ _matrix(f"matrices[{i}]", m)
    return result


def inverse(m: ArrayLike) -> NDArray[np.float64]:
    """The inverse of an affine 3x3 transformation matrix.

    For ``m`` = [[A, t], [0, 1]] with A = [[a, b], [c, d]] its 2x2 part and t its
    translation::

        m⁻¹ = | A⁻¹  -A⁻¹ t |        A⁻¹ = 1 / (a d - b c) · |  d  -b |
              |  0      1   |                                 | -c   a |

    Parameters
    ----------
    m : array_like, shape (3, 3)
        A finite affine matrix: its bottom row is (0, 0, 1) (within 1e-12), as for every
        matrix built by this module and their products.

    Returns
    -------
    ndarray of float64, shape (3, 3)
        With the bottom row exactly (0, 0, 1); ``compose(inverse(m), m)`` is the
        identity up to rounding.

    Raises
    ------
    ArgumentValueError
        If ``m`` is not 3x3, not finite or not affine, if it is singular (a zero scale
        factor, a shear with shx · shy = 1: the plane collapses onto a line or a point,
        so no inverse exists) or so nearly singular that |det A| is within
        64 · eps · ||A||² of zero, or if the inverse overflows float64.

    Notes
    -----
    The notes' syllabus for chapter 3 lists "inverse transformations" but the notes do
    not cover them.  Hearn & Baker (chapter 5) give the inverses of the basic
    transformations -- T(-tx, -ty), R(-θ), S(1/sx, 1/sy) -- and the inverse of a
    composite is the composite of the inverses in the reverse order; this function
    inverts any affine matrix in closed form instead.

    References
    ----------
    Hearn & Baker, chapter 5;
    Foley et al., chapter 5 (cited in full in the module docstring).

    Examples
    --------
    >>> from scanline.transform import inverse, translation, scaling
    >>> inverse(translation(2, 3)).tolist()
    [[1.0, 0.0, -2.0], [0.0, 1.0, -3.0], [0.0, 0.0, 1.0]]
    >>> inverse(scaling(2, 4, fixed=(1, 1))).tolist()
    [[0.5, 0.0, 0.5], [0.0, 0.25, 0.75], [0.0, 0.0, 1.0]]
    """
    a = _affine("m", m)
    A = a[:2, :2]
    t = a[:2, 2]
    big = float(np.abs(A).max())
    if big == 0.0:
        raise ArgumentValueError(
            "m is singular: its 2x2 part is zero, so it maps the whole plane to one point "
            "and has no inverse; use an invertible matrix (nonzero determinant)"
        )
    An = A / big  # entries within [-1, 1]: no overflow in the determinant
    det = An[0, 0] * An[1, 1] - An[0, 1] * An[1, 0]
    if abs(det) <= SINGULAR * float((An * An).sum()):
        raise ArgumentValueError(
            f"m is singular (determinant {det * big * big:.3g} of its 2x2 part "
            f"{A.tolist()}), so it has no inverse: it collapses the plane onto a line "
            "(a zero scale factor, a shear with shx * shy = 1, ...); use an invertible "
            "matrix"
        )
    adj = np.array([[An[1, 1], 0.0 - An[0, 1]], [0.0 - An[1, 0], An[0, 0]]])
    with np.errstate(over="ignore", invalid="ignore"):
        Ai = adj / det / big
        ti = 0.0 - Ai @ t
    if not (np.isfinite(Ai).all() and np.isfinite(ti).all()):
        raise ArgumentValueError(
            f"the inverse of m overflows float64 (m = {a.tolist()}); its entries are too "
            "small or its translation too large"
        )
    return _homogeneous(Ai[0, 0], Ai[0, 1], ti[0], Ai[1, 0], Ai[1, 1], ti[1])


def apply(m: ArrayLike, points: ArrayLike) -> NDArray[np.float64]:
    """Transform points by an affine 3x3 matrix: p' = m @ (x, y, 1).

    ::

        x' = m[0,0] x + m[0,1] y + m[0,2]
        y' = m[1,0] x + m[1,1] y + m[1,2]

    Parameters
    ----------
    m : array_like, shape (3, 3)
        A finite affine matrix (bottom row (0, 0, 1), within 1e-12).
    points : array_like, shape (N, 2) or (2,)
        Finite points (x, y); ``[]`` is an empty batch.

    Returns
    -------
    ndarray of float64, shape (N, 2) or (2,)
        The transformed points, in the shape given.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``m`` is not a finite affine 3x3 matrix or ``points`` not finite points of
        shape (N, 2) or (2,).

    Notes
    -----
    The notes, chapter 3, transform a polygon by transforming each vertex (Q.1, Q.2);
    this does so for N points in one numpy product.  Projective matrices (another
    bottom row) are refused rather than divided through by w.

    References
    ----------
    Hearn & Baker, chapter 5, section 5-2 (cited in full in the module docstring).

    Examples
    --------
    >>> from scanline.transform import apply, scaling
    >>> apply(scaling(2, 3), [(1, 1), (-1, 2)]).tolist()
    [[2.0, 3.0], [-2.0, 6.0]]
    >>> apply(scaling(2, 3), (1, 1)).tolist()
    [2.0, 3.0]
    """
    a = _affine("m", m)
    p, single = _points("points", points)
    out: NDArray[np.float64] = p @ a[:2, :2].T + a[:2, 2]
    return out.reshape(2) if single else out
