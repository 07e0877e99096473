"""3-D geometric transformations in homogeneous coordinates: 4x4 float64 matrices.

Conventions (DESIGN.md, convention 3, as :mod:`scanline.transform` in 2-D): a point
(x, y, z) is the column vector (x, y, z, 1) and ``M`` maps it to ``M @ (x, y, z, 1)``;
composition reads right to left.  The coordinate system is right-handed; a positive
rotation angle turns counterclockwise when one looks from the positive end of the
axis toward the origin (the right-hand rule).  Angles are in radians.

Everything here is plain numpy.  The batch projections that must be fast run in
:mod:`scanline._kernels.three_d` (``Camera.project``).

References
----------
.. [1] D. Hearn and M. P. Baker, *Computer Graphics, C Version*, 2nd ed., Prentice
   Hall, 1997, chapter 11 (three-dimensional geometric and modeling
   transformations), sections 11-1 to 11-5.
.. [2] J. D. Foley, A. van Dam, S. K. Feiner and J. F. Hughes, *Computer Graphics:
   Principles and Practice*, 2nd ed., Addison-Wesley, 1990, section 5.7.
"""

import math
from collections.abc import Sequence
from typing import Any, NamedTuple, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._typing import Angle
from ..errors import ArgumentTypeError, ArgumentValueError
from .arrays import direction, matrix4, points, vector

#: The coordinate axes of :func:`rotation` and :func:`shear`.
AXES = ("x", "y", "z")
#: The coordinate planes of :func:`reflection`.
PLANES = ("xy", "yz", "zx")

#: A matrix counts as singular when |det A| <= SINGULAR * ||A||_F**3 for its
#: (scaled) linear part A.
SINGULAR = 64 * np.finfo(np.float64).eps

class Step(NamedTuple):
    """One step of a composite transformation: its name, its 4x4 matrix and what it
    does (the steps of :func:`rotation_steps`).

    Parameters
    ----------
    name : str
        A short name such as ``"Rx(alpha)"``.
    matrix : ndarray of float64, shape (4, 4)
        The step's transformation.
    description : str
        What the step does, in words.

    Examples
    --------
    >>> from scanline.transform3d import Step, translation
    >>> step = Step("T", translation(1, 0, 0), "move right")
    >>> step.name, step.matrix[:3, 3].tolist()
    ('T', [1.0, 0.0, 0.0])
    """

    name: str
    matrix: NDArray[np.float64]
    description: str


def _tidy(m: ArrayLike) -> NDArray[np.float64]:
    """``m`` with negative zeros made positive (tidy printing, same values)."""
    return np.asarray(m, dtype=np.float64) + 0.0


def _finite_matrix(m: NDArray[np.float64], arguments: str) -> NDArray[np.float64]:
    """``m``, or an error naming ``arguments`` when an entry overflowed float64 (huge
    but finite arguments: 1e300 times 1e300)."""
    if not np.isfinite(m).all():
        raise ArgumentValueError(
            f"{arguments} give a matrix whose entries overflow float64 (beyond about "
            "1.8e308); use smaller values")
    return m


def translation(tx: float, ty: float, tz: float) -> NDArray[np.float64]:
    """Translation by the vector (tx, ty, tz).

    ::

        T(tx, ty, tz) = | 1  0  0  tx |      x' = x + tx
                        | 0  1  0  ty |      y' = y + ty
                        | 0  0  1  tz |      z' = z + tz
                        | 0  0  0   1 |

    Parameters
    ----------
    tx, ty, tz : float
        The translation distances, finite.

    Returns
    -------
    ndarray of float64, shape (4, 4)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If a distance is not a finite real number.

    Notes
    -----
    Hearn & Baker, section 11-1.  The inverse is T(-tx, -ty, -tz).

    Examples
    --------
    >>> from scanline.transform3d import translation, apply
    >>> apply(translation(1, 2, 3), (1, 1, 1)).tolist()
    [2.0, 3.0, 4.0]
    """
    m = np.eye(4)
    m[:3, 3] = [v.number("tx", tx), v.number("ty", ty), v.number("tz", tz)]
    return _tidy(m)


def _about(m3: NDArray[np.float64], fixed: tuple[float, ...] | None) -> NDArray[np.float64]:
    """The 4x4 matrix of the linear map ``m3`` (3x3) about the point ``fixed``
    (None: the origin): T(fixed) · M · T(-fixed)."""
    m = np.eye(4)
    m[:3, :3] = m3
    if fixed is not None:
        f = np.array(fixed)
        with np.errstate(over="ignore", invalid="ignore"):
            m[:3, 3] = f - m3 @ f
    return _tidy(m)


def scaling(sx: float, sy: float | None = None, sz: float | None = None,
            fixed: ArrayLike | None = None) -> NDArray[np.float64]:
    """Scaling by sx, sy, sz along the axes, about the origin or a fixed point.

    ::

        S(sx, sy, sz) = | sx  0   0  0 |       about (xf, yf, zf):
                        | 0   sy  0  0 |       x' = xf + (x - xf) sx
                        | 0   0  sz  0 |       y' = yf + (y - yf) sy
                        | 0   0   0  1 |       z' = zf + (z - zf) sz

    Parameters
    ----------
    sx : float
        The factor along x (and along y and z when ``sy`` and ``sz`` are omitted).
    sy, sz : float, optional
        The factors along y and z; give both or neither.
    fixed : (float, float, float), optional
        The fixed point; the origin when omitted.

    Returns
    -------
    ndarray of float64, shape (4, 4)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If a factor or the fixed point is not finite, only one of ``sy`` and ``sz`` is
        given, or the matrix overflows.

    Notes
    -----
    Hearn & Baker, section 11-3: scaling about a fixed point is
    T(xf, yf, zf) · S(sx, sy, sz) · T(-xf, -yf, -zf).  A zero factor is allowed (it
    flattens space; such a matrix has no :func:`inverse`).

    Examples
    --------
    >>> from scanline.transform3d import scaling, apply
    >>> apply(scaling(2, 3, 4), (1, 1, 1)).tolist()
    [2.0, 3.0, 4.0]
    >>> apply(scaling(2, fixed=(1, 1, 1)), (2, 2, 2)).tolist()
    [3.0, 3.0, 3.0]
    """
    sx = v.number("sx", sx)
    if (sy is None) != (sz is None):
        raise ArgumentValueError(
            f"give both sy and sz, or neither (uniform scaling by sx); got sy={sy!r}, "
            f"sz={sz!r}")
    sy = sx if sy is None else v.number("sy", sy)
    sz = sx if sz is None else v.number("sz", sz)
    return _finite_matrix(
        _about(np.diag([sx, sy, sz]), None if fixed is None else vector("fixed", fixed)),
        "the factors (sx, sy, sz) and the fixed point")


def _axis_rotation(axis: str, c: float, s: float) -> NDArray[np.float64]:
    """The 3x3 rotation about a coordinate axis with cos c and sin s."""
    if axis == "x":
        return np.array([[1, 0, 0], [0, c, -s], [0, s, c]], np.float64)
    if axis == "y":
        return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]], np.float64)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]], np.float64)


def rotation(angle: Angle, axis: str | ArrayLike = "z",
             pivot: ArrayLike | None = None) -> NDArray[np.float64]:
    """Rotation by ``angle`` radians about a coordinate axis or any axis.

    About the coordinate axes (counterclockwise looking from the positive axis toward
    the origin)::

        Rz(θ): x' = x cos θ - y sin θ,  y' = x sin θ + y cos θ,  z' = z
        Rx(θ): y' = y cos θ - z sin θ,  z' = y sin θ + z cos θ,  x' = x
        Ry(θ): z' = z cos θ - x sin θ,  x' = z sin θ + x cos θ,  y' = y

        Rx(θ) = | 1    0       0     0 |   Ry(θ) = |  cos θ  0  sin θ  0 |
                | 0  cos θ  -sin θ   0 |           |    0    1    0    0 |
                | 0  sin θ   cos θ   0 |           | -sin θ  0  cos θ  0 |
                | 0    0       0     1 |           |    0    0    0    1 |

    About the axis through two points P1, P2 (``axis=(p1, p2)``), counterclockwise
    looking from P2 toward P1, it is the notes' composite (Hearn & Baker,
    section 11-2, "general three-dimensional rotations")::

        R(θ) = T⁻¹ · Rx⁻¹(α) · Ry⁻¹(β) · Rz(θ) · Ry(β) · Rx(α) · T

    with T = T(-P1), u = (P2 - P1) / |P2 - P1| = (a, b, c), d = sqrt(b² + c²),
    cos α = c / d, sin α = b / d (Rx(α) turns u into the xz plane; skipped when
    d = 0) and cos β = d, sin β = -a (Ry(β) turns it onto +z).
    :func:`rotation_steps` returns the seven steps.

    Parameters
    ----------
    angle : float
        θ in radians.
    axis : {"x", "y", "z"} or (p1, p2)
        A coordinate axis, or two distinct points of the axis.
    pivot : (float, float, float), optional
        For a coordinate axis: rotate about the parallel axis through ``pivot``.

    Returns
    -------
    ndarray of float64, shape (4, 4)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If the angle is not finite, ``axis`` is neither a coordinate axis nor two
        distinct points, ``pivot`` is given with two axis points, or the matrix
        overflows.

    Examples
    --------
    >>> import math
    >>> from scanline.transform3d import rotation, apply
    >>> (apply(rotation(math.pi / 2, "z"), (1, 0, 0)).round(12) + 0).tolist()
    [0.0, 1.0, 0.0]
    >>> (apply(rotation(math.pi / 2, ((0, 0, 0), (1, 1, 1))), (1, 0, 0)).round(12) + 0).tolist()
    [0.333333333333, 0.910683602523, -0.244016935856]
    """
    theta = v.angle("angle", angle)
    if isinstance(axis, str):
        v.choice("axis", axis, AXES)
        m3 = _axis_rotation(axis, math.cos(theta), math.sin(theta))
        return _finite_matrix(_about(m3, None if pivot is None else vector("pivot", pivot)),
                              "the angle and the pivot")
    if pivot is not None:
        raise ArgumentValueError("pivot is for rotations about a coordinate axis; an axis "
                                 "given by two points (p1, p2) already passes through p1")
    steps = rotation_steps(theta, axis)
    return _composite(steps, "the angle and the axis points (p1, p2)")


def _composite(steps: list[Step], arguments: str) -> NDArray[np.float64]:
    """The product of the steps' matrices, in the order they act; an error naming
    ``arguments`` when it overflows."""
    result = np.eye(4)
    with np.errstate(over="ignore", invalid="ignore"):
        for s in reversed(steps):
            result = result @ s.matrix
    return _finite_matrix(result, arguments)


def _axis_points(axis: object) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    if isinstance(axis, (str, bytes)) or not hasattr(axis, "__len__") or len(axis) != 2:
        raise ArgumentTypeError(
            f"axis must be 'x', 'y', 'z' or two points (p1, p2) of the rotation axis, got "
            f"{v._show(axis)}")
    ends = cast("Sequence[object]", axis)
    p1 = np.array(vector("axis[0]", ends[0]))
    p2 = np.array(vector("axis[1]", ends[1]))
    if (p1 == p2).all():
        raise ArgumentValueError(
            f"the axis points p1 and p2 must differ (both are {p1.tolist()}): two distinct "
            "points give the axis direction")
    return p1, p2


def axis_alignment(axis: ArrayLike) -> NDArray[np.float64]:
    """The matrix Ry(β) · Rx(α) · T(-P1) that moves the axis through ``axis`` =
    (p1, p2) onto the positive z axis (P1 to the origin, P2 onto +z), the first
    three steps of :func:`rotation` about that axis.

    Parameters
    ----------
    axis : (p1, p2)
        Two distinct points of the axis, each three finite numbers.

    Returns
    -------
    ndarray of float64, shape (4, 4)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``axis`` is not two distinct finite 3-D points.

    Notes
    -----
    Hearn & Baker, section 11-2 (general three-dimensional rotations).

    Examples
    --------
    >>> from scanline.transform3d import axis_alignment, apply
    >>> (apply(axis_alignment(((1, 1, 1), (1, 1, 3))), (1, 1, 3)).round(12) + 0).tolist()
    [0.0, 0.0, 2.0]
    """
    steps = rotation_steps(0.0, axis)
    return _composite(steps[:3], "the axis points (p1, p2)")


def rotation_steps(angle: Angle, axis: ArrayLike) -> list[Step]:
    """The seven steps of the rotation by ``angle`` about the axis through
    ``axis`` = (p1, p2), in the order they act (Hearn & Baker, section 11-2).

    Parameters
    ----------
    angle : float or str
        θ in radians (or a string with its unit, ``"30deg"``).
    axis : (p1, p2)
        Two distinct points of the axis; the rotation is counterclockwise looking from
        p2 toward p1.

    Returns
    -------
    list of Step
        ``(name, matrix, description)``: translate P1 to the origin, rotate about x
        by α into the xz plane, rotate about y by β onto z, rotate by θ about z, and
        undo the three alignment steps.  ``compose(*reversed([s.matrix for s in
        steps]))`` is :func:`rotation` about the axis.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If the angle is not finite or ``axis`` is not two distinct finite 3-D points.

    Examples
    --------
    >>> from scanline.transform3d import rotation_steps
    >>> [s.name for s in rotation_steps(0.5, ((0, 0, 0), (0, 0, 1)))]
    ['T', 'Rx(alpha)', 'Ry(beta)', 'Rz(theta)', 'Ry(beta)^-1', 'Rx(alpha)^-1', 'T^-1']
    """
    theta = v.angle("angle", angle)
    p1, p2 = _axis_points(axis)
    with np.errstate(over="ignore"):
        a, b, c = direction("axis[1] - axis[0]", p2 - p1)
    d = math.hypot(b, c)
    t = translation(*(-p1))
    rx = _about(np.eye(3) if d == 0.0 else _axis_rotation("x", c / d, b / d), None)
    ry = _about(_axis_rotation("y", d, -a), None)
    rz = _about(_axis_rotation("z", math.cos(theta), math.sin(theta)), None)
    return [
        Step("T", t, f"translate P1 = {tuple(p1.tolist())} to the origin"),
        Step("Rx(alpha)", rx, "rotate about x by alpha (cos = c/d, sin = b/d): the axis "
             "into the xz plane" + (" (skipped: d = 0, the axis is along x)" if d == 0 else "")),
        Step("Ry(beta)", ry, "rotate about y by beta (cos = d, sin = -a): the axis onto +z"),
        Step("Rz(theta)", rz, f"rotate by theta = {theta:g} about z"),
        Step("Ry(beta)^-1", _tidy(ry.T), "undo the rotation about y"),
        Step("Rx(alpha)^-1", _tidy(rx.T), "undo the rotation about x"),
        Step("T^-1", translation(*p1), "translate the origin back to P1"),
    ]


def reflection(plane: str | ArrayLike, normal: ArrayLike | None = None) -> NDArray[np.float64]:
    """Reflection in a coordinate plane or in any plane.

    ::

        "xy": z' = -z      "yz": x' = -x      "zx": y' = -y

    ``reflection(point, normal)`` reflects in the plane through ``point`` with the
    normal ``normal`` (unit n after normalizing): p' = p - 2 ((p - q) · n) n, the
    matrix T(q) · (I - 2 n nᵀ) · T(-q).

    Parameters
    ----------
    plane : {"xy", "yz", "zx"} or (float, float, float)
        A coordinate plane, or (with ``normal``) a point q of the plane.
    normal : (float, float, float), optional
        The plane's normal, nonzero (any length); only with a point as ``plane``.

    Returns
    -------
    ndarray of float64, shape (4, 4)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``plane`` is not one of :data:`PLANES` (without ``normal``), the point or
        normal is not finite, the normal is zero, or the matrix overflows.

    Notes
    -----
    Hearn & Baker, section 11-4 ("reflections": a 180° rotation through
    four-dimensional space; the xy-plane reflection converts between right- and
    left-handed systems).  Every reflection is its own inverse, determinant -1.

    Examples
    --------
    >>> from scanline.transform3d import reflection, apply
    >>> apply(reflection("xy"), (1, 2, 3)).tolist()
    [1.0, 2.0, -3.0]
    >>> apply(reflection((0, 0, 1), (0, 0, 1)), (1, 2, 3)).tolist()
    [1.0, 2.0, -1.0]
    """
    if normal is None:
        k = {"xy": 2, "yz": 0, "zx": 1}[v.choice("plane", cast(str, plane), PLANES)]
        d = np.ones(3)
        d[k] = -1.0
        return _about(np.diag(d), None)
    q = vector("point", plane)
    n = direction("normal", normal)
    return _finite_matrix(_about(np.eye(3) - 2.0 * np.outer(n, n), q), "the point and the normal")


def shear(axis: str = "z", a: float = 0.0, b: float = 0.0,
          reference: float = 0.0) -> NDArray[np.float64]:
    """Shear of the two other coordinates in proportion to one coordinate.

    ::

        axis="z":  x' = x + a (z - zref),  y' = y + b (z - zref)
        axis="x":  y' = y + a (x - xref),  z' = z + b (x - xref)
        axis="y":  x' = x + a (y - yref),  z' = z + b (y - yref)

    The z-axis shear is Hearn & Baker's (section 11-4)::

        | 1  0  a  -a zref |
        | 0  1  b  -b zref |
        | 0  0  1     0    |
        | 0  0  0     1    |

    It is also the shear of the general parallel projection (Hearn & Baker, section
    12-3): with a = -px/pz, b = -py/pz it turns the projection vector (px, py, pz)
    parallel to z.  The plane ``axis = reference`` stays fixed; the determinant is 1.

    Parameters
    ----------
    axis : {"x", "y", "z"}, default "z"
        The coordinate in proportion to which the two others move.
    a, b : float, default 0
        The shear factors of the two other coordinates, in the order x, y, z.
    reference : float, default 0
        The fixed plane ``axis = reference``.

    Returns
    -------
    ndarray of float64, shape (4, 4)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``axis`` is not one of :data:`AXES`, a number is not finite, or the matrix
        overflows.

    Notes
    -----
    Hearn & Baker, section 11-4 (shears).

    Examples
    --------
    >>> from scanline.transform3d import shear, apply
    >>> apply(shear("z", 0.5, -1), (0, 0, 2)).tolist()
    [1.0, -2.0, 2.0]
    """
    v.choice("axis", axis, AXES)
    a, b, ref = v.number("a", a), v.number("b", b), v.number("reference", reference)
    k = AXES.index(axis)
    others = {"x": (1, 2), "y": (0, 2), "z": (0, 1)}[axis]
    m = np.eye(4)
    for row, f in zip(others, (a, b)):
        m[row, k] = f
        m[row, 3] = -f * ref          # Python floats: may overflow to inf, checked below
    return _finite_matrix(_tidy(m), "a, b and reference")


def compose(*matrices: ArrayLike) -> NDArray[np.float64]:
    """The product of 4x4 matrices, applied right to left: ``compose(A, B, C)`` is
    ``A @ B @ C`` (C acts first).  ``compose()`` is the identity.

    Parameters
    ----------
    *matrices : array_like, shape (4, 4)
        Finite 4x4 matrices (affine or projective).

    Returns
    -------
    ndarray of float64, shape (4, 4)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If a matrix is not a finite 4x4 array or the product overflows.

    Notes
    -----
    Hearn & Baker, section 11-5 (composite transformations).

    Examples
    --------
    >>> from scanline.transform3d import compose, translation, scaling, apply
    >>> apply(compose(translation(1, 0, 0), scaling(2)), (1, 1, 1)).tolist()
    [3.0, 2.0, 2.0]
    """
    result = np.eye(4)
    for i, m in enumerate(matrices):
        with np.errstate(over="ignore", invalid="ignore"):
            result = result @ matrix4(f"matrices[{i}]", m)
        if not np.isfinite(result).all():
            raise ArgumentValueError(
                f"the product of matrices[0] to matrices[{i}] overflows float64 (entries beyond "
                "about 1.8e308); compose matrices with smaller entries")
    return result


def is_affine(m: ArrayLike, tolerance: float = 1e-12) -> bool:
    """Whether a 4x4 matrix's bottom row is (0, 0, 0, 1) within ``tolerance``.

    Parameters
    ----------
    m : array_like, shape (4, 4)
        A finite matrix.
    tolerance : float, default 1e-12
        The largest difference allowed in each entry of the bottom row, >= 0.

    Returns
    -------
    bool
        True for affine transformations (translations, rotations, scalings, ...),
        False for projective ones (a perspective matrix).

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``m`` is not a finite 4x4 matrix or ``tolerance`` is negative.

    Examples
    --------
    >>> from scanline.transform3d import is_affine, translation
    >>> is_affine(translation(1, 2, 3))
    True
    >>> is_affine([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 0]])
    False
    """
    a = matrix4("m", m)
    t = v.number("tolerance", tolerance)
    if t < 0:
        raise ArgumentValueError(f"tolerance must be >= 0, got {tolerance!r}")
    with np.errstate(over="ignore"):
        return bool(np.abs(a[3] - (0.0, 0.0, 0.0, 1.0)).max() <= t)


def inverse(m: ArrayLike) -> NDArray[np.float64]:
    """The inverse of a 4x4 transformation matrix (affine or projective).

    For an affine M = [[A, t], [0, 1]] the inverse is [[A⁻¹, -A⁻¹ t], [0, 1]]; a
    projective matrix (a perspective transformation) is inverted as a whole.

    Parameters
    ----------
    m : array_like, shape (4, 4)
        A finite, invertible matrix.

    Returns
    -------
    ndarray of float64, shape (4, 4)

    Raises
    ------
    ArgumentValueError
        If ``m`` is singular or so nearly singular that its inverse means nothing
        (a zero scale factor, a projection onto a plane): say which.

    Notes
    -----
    Hearn & Baker, section 11-5 (the inverse of a composite is the composite of the
    inverses in the reverse order); computed here in one step.

    Examples
    --------
    >>> from scanline.transform3d import inverse, translation
    >>> inverse(translation(1, 2, 3))[:3, 3].tolist()
    [-1.0, -2.0, -3.0]
    """
    a = matrix4("m", m)
    affine = is_affine(a)
    part = a[:3, :3] if affine else a
    big = float(np.abs(part).max())
    if big == 0.0:
        raise ArgumentValueError("m is singular (its linear part is zero): it maps all of "
                                 "space to one point and has no inverse")
    n = part / big
    det = float(np.linalg.det(n))
    size = float(np.sqrt((n * n).sum())) ** n.shape[0]
    if not abs(det) > SINGULAR * size:
        with np.errstate(over="ignore", under="ignore"):
            shown = det * np.float64(big) ** n.shape[0]    # (a Python float ** overflows)
        raise ArgumentValueError(
            f"m is singular (determinant {shown:.3g}), so it has no "
            "inverse: it flattens space onto a plane, a line or a point (a zero scale "
            "factor, a projection onto the view plane, ...); use an invertible matrix")
    with np.errstate(over="ignore", invalid="ignore"):
        inv = np.linalg.inv(n) / big
        if affine:
            out: NDArray[np.floating[Any]] = np.eye(4)
            out[:3, :3] = inv
            out[:3, 3] = -inv @ a[:3, 3]
        else:
            out = inv
    if not np.isfinite(out).all():
        raise ArgumentValueError(f"the inverse of m overflows float64 (m = {a.tolist()})")
    return _tidy(out)


def apply(m: ArrayLike, points_: ArrayLike) -> NDArray[np.float64]:
    """Transform points by a 4x4 matrix.

    ``points`` of shape (N, 3) (or one (3,) point) are taken as (x, y, z, 1); the
    result (x_h, y_h, z_h, h) = M · (x, y, z, 1) is divided by h (the homogeneous
    factor of a perspective matrix; 1 for affine matrices), giving (N, 3).  Points of
    shape (N, 4) (or (4,)) are homogeneous: the result is M · P, (N, 4), undivided.

    Parameters
    ----------
    m : array_like, shape (4, 4)
        A finite matrix.
    points_ : array_like, shape (N, 3), (3,), (N, 4) or (4,)
        Finite points: Cartesian (x, y, z) or homogeneous (x, y, z, h).

    Returns
    -------
    ndarray of float64, in the shape of ``points_``
        The transformed points.

    Raises
    ------
    ArgumentValueError
        For (N, 3) points that a projective matrix sends to infinity (h = 0: the point
        lies in the plane through the center of projection parallel to the view
        plane).

    Examples
    --------
    >>> from scanline.transform3d import apply, translation
    >>> apply(translation(1, 0, 0), [(0, 0, 0), (1, 2, 3)]).tolist()
    [[1.0, 0.0, 0.0], [2.0, 2.0, 3.0]]
    >>> apply(translation(1, 0, 0), (0, 0, 0, 2)).tolist()
    [2.0, 0.0, 0.0, 2.0]
    """
    a = matrix4("m", m)
    p, single = points("points", points_, (3, 4))
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        if p.shape[1] == 4:
            out: NDArray[np.float64] = p @ a.T
        else:
            h = p @ a[3, :3] + a[3, 3]
            if (h == 0.0).any():
                row = int(np.argmax(h == 0.0))
                raise ArgumentValueError(
                    f"points row {row} = {p[row].tolist()} maps to infinity (homogeneous "
                    "factor h = 0: it lies in the plane of the center of projection)")
            out = (p @ a[:3, :3].T + a[:3, 3]) / h[:, None]
    bad = ~np.isfinite(out).all(axis=1)
    if bad.any():
        row = int(np.argmax(bad))
        raise ArgumentValueError(
            f"points row {row} = {p[row].tolist()} maps beyond the range of float64 under m "
            "(an overflow, or a homogeneous factor h that underflows); use smaller "
            "coordinates or a smaller transformation")
    out = out + 0.0
    return out.reshape(-1) if single else out
