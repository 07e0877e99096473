"""Rotations as unit quaternions (Hearn & Baker, section 11-2, "rotations with
quaternions"; Shoemake 1985).

A quaternion q = s + a i + b j + c k is written here ``Quaternion(w, x, y, z)``
(scalar part first, as Hearn & Baker's q = (s, v); scipy and glTF store it last:
:meth:`Quaternion.xyzw` and :meth:`Quaternion.from_xyzw` convert).  The rotation by
θ about the unit axis u is

    q = (cos θ/2, u sin θ/2),        p' = q p q⁻¹        (p = (0, point))

and its 3x3 matrix, for a unit q = (s, a, b, c), is Hearn & Baker's eq. 11-41::

    | 1 - 2b² - 2c²    2ab - 2sc       2ac + 2sb   |
    |   2ab + 2sc    1 - 2a² - 2c²     2bc - 2sa   |
    |   2ac - 2sb      2bc + 2sa     1 - 2a² - 2b² |

q and -q are the same rotation.  Products compose rotations like matrices: ``(q1 *
q2).matrix() == q1.matrix() @ q2.matrix()`` (q2 acts first).  In-betweens of two
orientations follow the great arc between them (:func:`slerp`, the short way round)
and a sequence of key orientations a smooth curve (:func:`squad`).

The zero quaternion is no rotation and has no inverse: it is refused wherever it
could arise (a constructor's arguments, a matrix that is not a rotation).

References
----------
.. [1] D. Hearn and M. P. Baker, *Computer Graphics, C Version*, 2nd ed., 1997,
   section 11-2 (rotations with quaternions) and appendix A-4.
.. [2] K. Shoemake, "Animating rotation with quaternion curves", *SIGGRAPH '85*,
   Computer Graphics 19(3), 1985, pp. 245-254 (slerp, squad).
.. [3] S. W. Shepperd, "Quaternion from rotation matrix", *Journal of Guidance and
   Control* 1(3), 1978, pp. 223-224.
"""

import math
import numbers
from collections.abc import Iterable, Sequence
from typing import cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._typing import Angle
from ..errors import ArgumentTypeError, ArgumentValueError
from .arrays import direction, points, real_array

#: How far a matrix given to :meth:`Quaternion.from_matrix` may be from a rotation
#: (max |MᵀM - I| and |det M - 1|).
ORTHONORMAL_TOLERANCE = 1e-6

#: The axes that Euler-angle sequences name.
_AXIS = {"x": (1.0, 0.0, 0.0), "y": (0.0, 1.0, 0.0), "z": (0.0, 0.0, 1.0)}

#: Below this angle between two orientations slerp interpolates linearly (sin θ
#: would lose its digits); the result is normalized.
_TINY_ANGLE = 1e-8


def _component(name: str, value: object) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ArgumentTypeError(f"{name} must be a real number, got {v._show(value)} of type "
                                f"{type(value).__name__}")
    return v.number(name, value)


class Quaternion:
    """An immutable quaternion w + x i + y j + z k; a nonzero one is a rotation.

    Parameters
    ----------
    w, x, y, z : float
        The scalar part w and the vector part (x, y, z); finite, not all zero.
        Any nonzero multiple of a unit quaternion stands for the same rotation
        (:meth:`matrix` normalizes); :meth:`normalize` gives the unit one.

    Examples
    --------
    >>> import math
    >>> from scanline.transform3d import Quaternion
    >>> q = Quaternion.from_axis_angle((0, 0, 1), math.pi / 2)
    >>> q.rotate((1, 0, 0)).round(12).tolist()
    [0.0, 1.0, 0.0]
    >>> (q * q).matrix3().round(12).tolist()[0]
    [-1.0, -0.0, 0.0]
    >>> Quaternion(0, 0, 0, 0)
    Traceback (most recent call last):
      ...
    scanline.errors.ArgumentValueError: the quaternion (w, x, y, z) = (0, 0, 0, 0) is the zero quaternion: it is no rotation and has no inverse; give at least one nonzero component (the identity is Quaternion(1, 0, 0, 0))
    """

    __slots__ = ("_q",)
    _q: NDArray[np.float64]

    def __init__(self, w: float = 1.0, x: float = 0.0, y: float = 0.0,
                 z: float = 0.0) -> None:
        q = np.array([_component("w", w), _component("x", x), _component("y", y),
                      _component("z", z)])
        if not q.any():
            raise ArgumentValueError(
                "the quaternion (w, x, y, z) = (0, 0, 0, 0) is the zero quaternion: it is no "
                "rotation and has no inverse; give at least one nonzero component (the "
                "identity is Quaternion(1, 0, 0, 0))")
        q.flags.writeable = False
        object.__setattr__(self, "_q", q)

    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError("a Quaternion is immutable; its operations return new ones")

    @classmethod
    def _of(cls, q: NDArray[np.float64], what: str = "the result") -> "Quaternion":
        """A quaternion from the array ``q`` (the result of an operation)."""
        if not np.isfinite(q).all():
            raise ArgumentValueError(f"{what} overflows float64 (components beyond about "
                                     "1.8e308); normalize the quaternions first")
        if not q.any():
            raise ArgumentValueError(f"{what} is the zero quaternion (its components "
                                     "underflowed); normalize the quaternions first")
        return cls(*(float(c) for c in q))

    # -- construction ---------------------------------------------------------------------
    @classmethod
    def from_array(cls, wxyz: ArrayLike, name: str = "q") -> "Quaternion":
        """The quaternion of the four numbers ``wxyz`` (scalar first).

        Parameters
        ----------
        wxyz : array_like, shape (4,)
            (w, x, y, z), finite and not all zero.
        name : str, default "q"
            The argument's name in error messages.

        Returns
        -------
        Quaternion

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``wxyz`` is not four finite real numbers or is all zero.

        Examples
        --------
        >>> from scanline.transform3d import Quaternion
        >>> Quaternion.from_array([1, 0, 0, 0])
        Quaternion(w=1, x=0, y=0, z=0)
        """
        a = real_array(name, wxyz, "(4,): w, x, y, z")
        if a.shape != (4,):
            raise ArgumentValueError(f"{name} must be four numbers (w, x, y, z), got "
                                     f"{v._show(wxyz)} of shape {a.shape}")
        if not np.isfinite(a).all():
            raise ArgumentValueError(f"{name} must be finite, got {a.tolist()}")
        if not a.any():
            raise ArgumentValueError(f"{name} is the zero quaternion (0, 0, 0, 0): it is no "
                                     "rotation; give at least one nonzero component")
        return cls(*(float(c) for c in a))

    @classmethod
    def from_xyzw(cls, xyzw: ArrayLike, name: str = "q") -> "Quaternion":
        """The quaternion stored scalar last (scipy's ``as_quat()``, glTF's
        ``rotation``): (x, y, z, w).

        Parameters
        ----------
        xyzw : array_like, shape (4,)
            (x, y, z, w), finite and not all zero.
        name : str, default "q"
            The argument's name in error messages.

        Returns
        -------
        Quaternion

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``xyzw`` is not four finite real numbers or is all zero.

        Examples
        --------
        >>> from scanline.transform3d import Quaternion
        >>> Quaternion.from_xyzw((0, 1, 0, 0))
        Quaternion(w=0, x=0, y=1, z=0)
        """
        a = real_array(name, xyzw, "(4,): x, y, z, w")
        if a.shape != (4,):
            raise ArgumentValueError(f"{name} must be four numbers (x, y, z, w), got "
                                     f"{v._show(xyzw)} of shape {a.shape}")
        return cls.from_array(a[[3, 0, 1, 2]], name)

    @classmethod
    def from_axis_angle(cls, axis: str | ArrayLike, angle: Angle) -> "Quaternion":
        """The rotation by ``angle`` about ``axis`` (through the origin,
        counterclockwise looking from the axis' tip toward the origin):
        q = (cos θ/2, u sin θ/2), u = axis / |axis| (Hearn & Baker, eq. 11-37).

        Parameters
        ----------
        axis : {"x", "y", "z"} or (float, float, float)
            A coordinate axis or a nonzero 3-vector (any length).
        angle : float or str
            θ in radians (or a string with its unit, ``"30deg"``).

        Returns
        -------
        Quaternion
            A unit quaternion.

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``axis`` is neither a coordinate axis nor a finite nonzero 3-vector, or
            ``angle`` is not a finite angle.

        Examples
        --------
        >>> import math
        >>> from scanline.transform3d import Quaternion
        >>> Quaternion.from_axis_angle("x", math.pi / 2)
        Quaternion(w=0.707106781, x=0.707106781, y=0, z=0)
        """
        if isinstance(axis, str):
            v.choice("axis", axis, tuple(_AXIS))
            axis = _AXIS[axis]
        u = direction("axis", axis)
        half = v.angle("angle", angle) / 2
        s = math.sin(half)
        return cls(math.cos(half), *(float(c) * s for c in u))

    @classmethod
    def from_matrix(cls, m: ArrayLike) -> "Quaternion":
        """The unit quaternion of a rotation matrix (3x3, or 4x4 with no translation
        and last row 0 0 0 1), by Shepperd's method: of 4w², 4x², 4y², 4z² (from the
        trace and the diagonal) the largest is found first, and the other components
        from the off-diagonal sums and differences divided by it, so that nothing is
        divided by a small number.  The result has w >= 0.

        A matrix that is not a rotation (a scaling, a reflection, a shear, a
        translation) is refused: see :data:`ORTHONORMAL_TOLERANCE`.

        Parameters
        ----------
        m : array_like, shape (3, 3) or (4, 4)
            A finite rotation matrix.

        Returns
        -------
        Quaternion
            The unit quaternion with w >= 0.

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``m`` is not a finite 3x3 or 4x4 matrix, or not a rotation about the
            origin.

        References
        ----------
        Shepperd 1978 (cited in full in the module docstring).

        Examples
        --------
        The rotation by 90° about z:

        >>> from scanline.transform3d import Quaternion
        >>> Quaternion.from_matrix([[0, -1, 0], [1, 0, 0], [0, 0, 1]])
        Quaternion(w=0.707106781, x=0, y=0, z=0.707106781)
        """
        a = real_array("m", m, "(3, 3) or (4, 4)")
        if a.shape not in ((3, 3), (4, 4)):
            raise ArgumentValueError(f"m must be a 3x3 or 4x4 rotation matrix, got shape "
                                     f"{a.shape}")
        if not np.isfinite(a).all():
            raise ArgumentValueError("m must be finite; it holds "
                                     f"{a[~np.isfinite(a)][0]}")
        if a.shape == (4, 4):
            if np.abs(a[3] - (0, 0, 0, 1)).max() > ORTHONORMAL_TOLERANCE:
                raise ArgumentValueError(f"m's last row must be 0 0 0 1 for a rotation, got "
                                         f"{a[3].tolist()} (a projection is no rotation)")
            if np.abs(a[:3, 3]).max() > ORTHONORMAL_TOLERANCE:
                raise ArgumentValueError(
                    f"m has a translation {a[:3, 3].tolist()}: a quaternion holds a "
                    "rotation about the origin only; pass m[:3, :3] for its rotation part")
            a = a[:3, :3]
        with np.errstate(over="ignore", invalid="ignore"):   # huge entries: inf, refused
            error = float(np.abs(a.T @ a - np.eye(3)).max())
            det = float(np.linalg.det(a))
        if error > ORTHONORMAL_TOLERANCE or abs(det - 1) > ORTHONORMAL_TOLERANCE:
            what = "a reflection (det < 0)" if det < 0 else "not orthonormal (a scaling or a shear?)"
            raise ArgumentValueError(
                f"m is not a rotation matrix: it is {what}; max |MᵀM - I| = {error:.3g}, "
                f"det = {det:.6g}; a rotation has MᵀM = I and det = 1 (within "
                f"{ORTHONORMAL_TOLERANCE:g})")
        trace = a[0, 0] + a[1, 1] + a[2, 2]
        k = int(np.argmax([trace, a[0, 0], a[1, 1], a[2, 2]]))
        if k == 0:
            r = math.sqrt(1 + trace)                  # r = 2|w|
            parts: tuple[float, ...] = (
                r / 2, (a[2, 1] - a[1, 2]) / (2 * r), (a[0, 2] - a[2, 0]) / (2 * r),
                (a[1, 0] - a[0, 1]) / (2 * r))
        else:
            i = k - 1
            j, l = (i + 1) % 3, (i + 2) % 3
            r = math.sqrt(max(1 + a[i, i] - a[j, j] - a[l, l], 0.0))   # 2|q_i|
            out = [0.0, 0.0, 0.0, 0.0]
            out[0] = (a[l, j] - a[j, l]) / (2 * r)
            out[1 + i] = r / 2
            out[1 + j] = (a[j, i] + a[i, j]) / (2 * r)
            out[1 + l] = (a[l, i] + a[i, l]) / (2 * r)
            parts = tuple(out)
        q = np.array(parts, dtype=np.float64)
        if q[0] < 0:
            q = -q
        return cls._of(q / np.linalg.norm(q))

    @classmethod
    def from_euler(cls, seq: str, angles: Angle | Sequence[Angle]) -> "Quaternion":
        """The rotation of Euler angles, with scipy's names for the conventions.

        Parameters
        ----------
        seq : str
            One to three axis letters.  Lower case (``"xyz"``): *extrinsic*
            rotations about the fixed axes, the first letter acting first (R =
            Rz Ry Rx for ``"xyz"``).  Upper case (``"XYZ"``): *intrinsic* rotations
            about the axes of the turning body, the first acting first (R = Rx Ry
            Rz for ``"XYZ"``).  As ``scipy.spatial.transform.Rotation.from_euler``.
        angles : sequence of float
            One angle per letter, in radians (or strings with units, ``"30deg"``); a
            single angle for a single letter.

        Returns
        -------
        Quaternion
            A unit quaternion.

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``seq`` is not one to three axis letters of one case without a repeat in
            a row, or ``angles`` is not one finite angle per letter.

        Notes
        -----
        The product of the rotations about single axes (Hearn & Baker, section 11-2),
        composed as quaternions.

        Examples
        --------
        Extrinsic "xz" turns about x first, then about the fixed z; intrinsic "XZ"
        turns about the body's z after the x turn (the fixed -y), so the x axis goes
        elsewhere:

        >>> import math
        >>> from scanline.transform3d import Quaternion
        >>> q = Quaternion.from_euler("xz", [math.pi / 2, math.pi / 2])
        >>> (q.rotate((1, 0, 0)).round(12) + 0.0).tolist()
        [0.0, 1.0, 0.0]
        >>> q = Quaternion.from_euler("XZ", [math.pi / 2, math.pi / 2])
        >>> (q.rotate((1, 0, 0)).round(12) + 0.0).tolist()
        [0.0, 0.0, 1.0]
        """
        if not isinstance(seq, str) or not 1 <= len(seq) <= 3 or not (
                set(seq) <= set("xyz") or set(seq) <= set("XYZ")):
            raise ArgumentValueError(
                f"seq must be one to three axis letters, all lower case (extrinsic: 'xyz') "
                f"or all upper case (intrinsic: 'XYZ'), got {v._show(seq)}")
        if any(a == b for a, b in zip(seq, seq[1:])):
            raise ArgumentValueError(f"seq={seq!r} names the same axis twice in a row; "
                                     "successive axes must differ (e.g. 'zxz' or 'xyz')")
        given: object = [angles] if isinstance(angles, (numbers.Real, str)) else angles
        try:
            values = list(cast("Iterable[object]", given))
        except TypeError:
            raise ArgumentTypeError(f"angles must be {len(seq)} angle(s), got "
                                    f"{v._show(angles)}") from None
        if len(values) != len(seq):
            raise ArgumentValueError(f"angles must hold one angle per axis of seq={seq!r} "
                                     f"({len(seq)}), got {len(values)}")
        steps = [cls.from_axis_angle(axis.lower(), v.angle(f"angles[{i}]", a))
                 for i, (axis, a) in enumerate(zip(seq, values))]
        q = steps[0]
        for step in steps[1:]:
            q = step * q if seq.islower() else q * step
        return q

    # -- components -----------------------------------------------------------------------
    @property
    def w(self) -> float:
        """The scalar part."""
        return float(self._q[0])

    @property
    def x(self) -> float:
        """The i component."""
        return float(self._q[1])

    @property
    def y(self) -> float:
        """The j component."""
        return float(self._q[2])

    @property
    def z(self) -> float:
        """The k component."""
        return float(self._q[3])

    @property
    def wxyz(self) -> NDArray[np.float64]:
        """(w, x, y, z) as a read-only float64 array."""
        return self._q

    @property
    def xyzw(self) -> NDArray[np.float64]:
        """(x, y, z, w): scalar last, as scipy and glTF store it."""
        return self._q[[1, 2, 3, 0]]

    @property
    def norm(self) -> float:
        """|q| = sqrt(w² + x² + y² + z²)."""
        big = np.abs(self._q).max()
        return float(big * np.linalg.norm(self._q / big))

    @property
    def angle(self) -> float:
        """The rotation angle in [0, π] (radians)."""
        q = self.normalize()._q
        return float(2 * math.atan2(np.linalg.norm(q[1:]), abs(q[0])))

    @property
    def axis(self) -> NDArray[np.float64]:
        """The unit rotation axis (for the angle in [0, π]); (1, 0, 0) for the
        identity, whose axis is any."""
        q = self.normalize()._q
        u = q[1:] if q[0] >= 0 else -q[1:]
        n = np.linalg.norm(u)
        return np.array([1.0, 0.0, 0.0]) if n == 0 else u / n

    # -- algebra --------------------------------------------------------------------------
    def __mul__(self, other: object) -> "Quaternion":
        """The Hamilton product (Hearn & Baker, eq. A-51):
        (s1, v1)(s2, v2) = (s1 s2 - v1·v2, s1 v2 + s2 v1 + v1 × v2).  As rotations,
        ``q1 * q2`` turns by q2 first, then by q1."""
        if not isinstance(other, Quaternion):
            return NotImplemented
        s1, v1 = self._q[0], self._q[1:]
        s2, v2 = other._q[0], other._q[1:]
        with np.errstate(over="ignore", invalid="ignore", under="ignore"):
            out = np.concatenate([[s1 * s2 - v1 @ v2], s1 * v2 + s2 * v1 + np.cross(v1, v2)])
        return Quaternion._of(out, "the product")

    def __neg__(self) -> "Quaternion":
        """-q: the same rotation, the other sign."""
        return Quaternion(*(-self._q))

    def dot(self, other: "Quaternion") -> float:
        """The four-dimensional dot product w1 w2 + x1 x2 + y1 y2 + z1 z2.

        Parameters
        ----------
        other : Quaternion

        Returns
        -------
        float
            For unit quaternions, the cosine of half the angle between the rotations
            (up to sign).

        Raises
        ------
        ArgumentTypeError
            If ``other`` is not a Quaternion.

        Examples
        --------
        >>> from scanline.transform3d import Quaternion
        >>> Quaternion(1, 2, 3, 4).dot(Quaternion(1, 0, 0, 1))
        5.0
        """
        if not isinstance(other, Quaternion):
            raise ArgumentTypeError(f"other must be a Quaternion, got {v._show(other)}")
        return float(self._q @ other._q)

    def conjugate(self) -> "Quaternion":
        """q* = (w, -x, -y, -z).

        Returns
        -------
        Quaternion

        Examples
        --------
        >>> from scanline.transform3d import Quaternion
        >>> Quaternion(1, 2, 3, 4).conjugate()
        Quaternion(w=1, x=-2, y=-3, z=-4)
        """
        return Quaternion(self._q[0], *(-self._q[1:]))

    def inverse(self) -> "Quaternion":
        """q⁻¹ = q* / |q|² (the inverse rotation; q* itself for a unit q).

        Returns
        -------
        Quaternion

        Raises
        ------
        ArgumentValueError
            If the inverse overflows or underflows float64.

        Examples
        --------
        >>> from scanline.transform3d import Quaternion
        >>> Quaternion(1, 1, 1, 1).inverse()          # |q| = 2
        Quaternion(w=0.25, x=-0.25, y=-0.25, z=-0.25)
        """
        n = self.norm
        return Quaternion._of(self.conjugate()._q / n / n, "the inverse")

    def normalize(self) -> "Quaternion":
        """q / |q|: the unit quaternion of the same rotation.

        Returns
        -------
        Quaternion

        Examples
        --------
        >>> from scanline.transform3d import Quaternion
        >>> Quaternion(0, 3, 0, 4).normalize()
        Quaternion(w=0, x=0.6, y=0, z=0.8)
        """
        big = np.abs(self._q).max()
        q = self._q / big
        return Quaternion(*(q / np.linalg.norm(q)))

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Quaternion):
            return NotImplemented
        return bool((self._q == other._q).all())

    def __hash__(self) -> int:
        return hash(tuple(self._q.tolist()))

    def __repr__(self) -> str:
        return "Quaternion(w={:.9g}, x={:.9g}, y={:.9g}, z={:.9g})".format(*self._q)

    def __reduce__(self) -> tuple[type["Quaternion"], tuple[float, ...]]:
        return (Quaternion, tuple(self._q.tolist()))

    # -- as a rotation --------------------------------------------------------------------
    def matrix3(self) -> NDArray[np.float64]:
        """The 3x3 rotation matrix (Hearn & Baker, eq. 11-41) of q / |q|.

        Returns
        -------
        ndarray of float64, shape (3, 3)

        Examples
        --------
        The half turn about z:

        >>> from scanline.transform3d import Quaternion
        >>> Quaternion(0, 0, 0, 1).matrix3().tolist()
        [[-1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]]
        """
        s, a, b, c = self.normalize()._q
        return np.array([
            [1 - 2 * (b * b + c * c), 2 * (a * b - s * c), 2 * (a * c + s * b)],
            [2 * (a * b + s * c), 1 - 2 * (a * a + c * c), 2 * (b * c - s * a)],
            [2 * (a * c - s * b), 2 * (b * c + s * a), 1 - 2 * (a * a + b * b)]])

    def matrix(self) -> NDArray[np.float64]:
        """The 4x4 homogeneous rotation matrix (the 3x3 of :meth:`matrix3` in the
        upper left), ready for :func:`scanline.transform3d.compose`.

        Returns
        -------
        ndarray of float64, shape (4, 4)

        Examples
        --------
        >>> from scanline.transform3d import Quaternion
        >>> Quaternion(0, 0, 0, 1).matrix().tolist()
        [[-1.0, 0.0, 0.0, 0.0], [0.0, -1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]]
        """
        m = np.eye(4)
        m[:3, :3] = self.matrix3()
        return m

    def rotate(self, vectors: ArrayLike) -> NDArray[np.float64]:
        """``vectors`` (one (3,) or (N, 3)) rotated: q p q⁻¹ for each p, computed
        as the matrix product (the same rotation, fewer operations).

        Parameters
        ----------
        vectors : array_like, shape (N, 3) or (3,)
            Finite points or vectors.

        Returns
        -------
        ndarray of float64, in the shape of ``vectors``

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``vectors`` is not finite points of shape (N, 3) or (3,).

        Notes
        -----
        Hearn & Baker, section 11-2, eq. 11-40 (p' = q p q⁻¹) and eq. 11-41.

        Examples
        --------
        The half turn about z maps (x, y, z) to (-x, -y, z):

        >>> from scanline.transform3d import Quaternion
        >>> Quaternion(0, 0, 0, 1).rotate([(1, 2, 3), (0, 1, 0)]).tolist()
        [[-1.0, -2.0, 3.0], [0.0, -1.0, 0.0]]
        """
        p, single = points("vectors", vectors)
        out: NDArray[np.float64] = p @ self.matrix3().T
        return out.reshape(3) if single else out

    # -- Shoemake's curves ----------------------------------------------------------------
    def log(self) -> NDArray[np.float64]:
        """The logarithm of the unit quaternion q / |q| = (cos θ, u sin θ):
        (0, u θ), θ in [0, π].

        Returns
        -------
        ndarray of float64, shape (4,)
            The pure quaternion (0, u θ), scalar first.

        References
        ----------
        Shoemake 1985 (cited in full in the module docstring).

        Examples
        --------
        The quarter turn about z is (cos π/4, sin π/4 (0, 0, 1)); its log is
        (0, 0, 0, π/4):

        >>> import math
        >>> from scanline.transform3d import Quaternion
        >>> Quaternion.from_axis_angle("z", math.pi / 2).log().round(9).tolist()
        [0.0, 0.0, 0.0, 0.785398163]
        """
        q = self.normalize()._q
        n = np.linalg.norm(q[1:])
        if n == 0:
            return np.zeros(4)
        theta = math.atan2(n, q[0])
        return np.concatenate([[0.0], q[1:] * (theta / n)])

    @staticmethod
    def exp(pure: ArrayLike) -> "Quaternion":
        """exp((0, u θ)) = (cos θ, u sin θ) for a pure quaternion ``pure`` (four
        numbers, w = 0, or three: the vector part), the inverse of :meth:`log`.

        Parameters
        ----------
        pure : array_like, shape (4,) or (3,)
            (0, x, y, z) or (x, y, z), finite.

        Returns
        -------
        Quaternion
            A unit quaternion.

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``pure`` is not three or four finite numbers, or has w != 0.

        Examples
        --------
        >>> import math
        >>> from scanline.transform3d import Quaternion
        >>> Quaternion.exp((0, 0, math.pi / 4))
        Quaternion(w=0.707106781, x=0, y=0, z=0.707106781)
        """
        a = real_array("pure", pure, "(3,) or (4,)")
        if a.shape == (4,):
            if a[0] != 0:
                raise ArgumentValueError(f"pure must have w = 0, got w = {a[0]}")
            a = a[1:]
        if a.shape != (3,) or not np.isfinite(a).all():
            raise ArgumentValueError(f"pure must be a finite vector part (x, y, z), got "
                                     f"{v._show(pure)}")
        theta = float(np.linalg.norm(a))
        if theta == 0:
            return Quaternion(1.0, 0.0, 0.0, 0.0)
        return Quaternion(math.cos(theta), *(a * (math.sin(theta) / theta)))

    def slerp(self, other: "Quaternion", t: float) -> "Quaternion":
        """The in-between at ``t`` (0 gives this rotation, 1 ``other``) on the
        shorter great arc; see :func:`slerp`.

        Parameters
        ----------
        other : Quaternion
            The orientation at t = 1.
        t : float
            The parameter, finite (outside [0, 1] extrapolates).

        Returns
        -------
        Quaternion
            A unit quaternion.

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            As :func:`slerp`.

        Examples
        --------
        >>> import math
        >>> from scanline.transform3d import Quaternion
        >>> b = Quaternion.from_axis_angle("z", math.pi / 2)
        >>> round(math.degrees(Quaternion().slerp(b, 0.25).angle), 9)
        22.5
        """
        return slerp(self, other, t)


def _quaternion(name: str, q: object) -> Quaternion:
    if not isinstance(q, Quaternion):
        raise ArgumentTypeError(f"{name} must be a scanline.transform3d.Quaternion, got "
                                f"{v._show(q)}")
    return q


def slerp(q1: Quaternion, q2: Quaternion, t: float) -> Quaternion:
    """Spherical linear interpolation (Shoemake 1985, section 3.3):

        slerp(q1, q2; t) = sin((1 - t) θ) / sin θ · q1 + sin(t θ) / sin θ · q2,
        cos θ = q1 · q2

    for the unit quaternions of q1 and q2, with q2 negated first when q1 · q2 < 0, so
    that the in-betweens take the short way round (q2 and -q2 are the same
    orientation; the long way would turn by more than π).  The angular velocity is
    constant in t.  ``t`` outside [0, 1] extrapolates along the same great circle.

    Parameters
    ----------
    q1, q2 : Quaternion
        The orientations at t = 0 and t = 1 (any nonzero lengths).
    t : float
        The parameter, finite.

    Returns
    -------
    Quaternion
        A unit quaternion.

    Raises
    ------
    ArgumentTypeError
        If ``q1`` or ``q2`` is not a Quaternion.
    ArgumentValueError
        If ``t`` is not finite, or so far outside [0, 1] that the result overflows.

    References
    ----------
    Shoemake 1985 (cited in full in the module docstring).

    Examples
    --------
    >>> import math
    >>> from scanline.transform3d import Quaternion, slerp
    >>> a = Quaternion(1, 0, 0, 0)
    >>> b = Quaternion.from_axis_angle("z", math.pi / 2)
    >>> round(math.degrees(slerp(a, b, 0.5).angle), 9)
    45.0
    """
    p = _quaternion("q1", q1).normalize()._q
    q = _quaternion("q2", q2).normalize()._q
    t = v.number("t", t)
    d = float(p @ q)
    if d < 0:
        q, d = -q, -d
    d = min(d, 1.0)
    theta = math.acos(d)
    if theta < _TINY_ANGLE:
        with np.errstate(over="ignore", invalid="ignore"):
            out = p + t * (q - p)
    else:
        s = math.sin(theta)
        out = math.sin((1 - t) * theta) / s * p + math.sin(t * theta) / s * q
    return _unit(out, "slerp")


def _unit(q: NDArray[np.float64], what: str) -> Quaternion:
    """``q`` / |q| without overflow; an error naming ``what`` where q is not finite or
    zero (t far outside [0, 1] on nearly equal keys)."""
    with np.errstate(over="ignore", invalid="ignore"):
        big = np.abs(q).max()
        if not np.isfinite(big) or big == 0:
            return Quaternion._of(q, what)
        q = q / big
    return Quaternion._of(q / np.linalg.norm(q), what)


def squad(q1: Quaternion, q2: Quaternion, a1: Quaternion, a2: Quaternion,
          t: float) -> Quaternion:
    """Spherical cubic interpolation between key orientations q1 and q2 with inner
    control points a1 and a2 (Shoemake 1985, section 6; his "squad"):

        squad(q1, q2, a1, a2; t) = slerp(slerp(q1, q2; t), slerp(a1, a2; t); 2t(1 - t))

    The control points of a key sequence come from :func:`squad_controls`; with them
    the curve through the keys has a continuous tangent at each key.  Here the inner
    slerps take the arc as given (no short-arc flip: the keys are put on one
    hemisphere beforehand, as :func:`squad_controls` does).

    Parameters
    ----------
    q1, q2 : Quaternion
        The key orientations at t = 0 and t = 1.
    a1, a2 : Quaternion
        Their inner control points (:func:`squad_controls`).
    t : float
        The parameter, finite.

    Returns
    -------
    Quaternion
        A unit quaternion.

    Raises
    ------
    ArgumentTypeError
        If an orientation is not a Quaternion.
    ArgumentValueError
        If ``t`` is not finite or the result overflows.

    References
    ----------
    Shoemake 1985 (cited in full in the module docstring).

    Examples
    --------
    With the keys as their own controls the middle is slerp's: half of a quarter turn.

    >>> import math
    >>> from scanline.transform3d import Quaternion, squad
    >>> a, b = Quaternion(), Quaternion.from_axis_angle("z", math.pi / 2)
    >>> round(math.degrees(squad(a, b, a, b, 0.5).angle), 9)
    45.0
    """
    qs = [_quaternion(n, q).normalize()._q for n, q in
          (("q1", q1), ("q2", q2), ("a1", a1), ("a2", a2))]
    t = v.number("t", t)
    outer = _arc(qs[0], qs[1], t)
    inner = _arc(qs[2], qs[3], t)
    out = _arc(outer, inner, 2 * t * (1 - t))
    return Quaternion._of(out, "squad")


def _arc(p: NDArray[np.float64], q: NDArray[np.float64], t: float) -> NDArray[np.float64]:
    """slerp on the great arc from unit p to unit q as given (the long way round when
    p · q < 0)."""
    d = min(max(float(p @ q), -1.0), 1.0)
    theta = math.acos(d)
    if math.sin(theta) < _TINY_ANGLE:
        out = p + t * (q - p) if d > 0 else p      # antipodes: no arc is defined; stay
    else:
        s = math.sin(theta)
        out = math.sin((1 - t) * theta) / s * p + math.sin(t * theta) / s * q
    unit: NDArray[np.float64] = out / np.linalg.norm(out)
    return unit


def hemisphere(quaternions: Iterable[Quaternion],
               name: str = "quaternions") -> list[Quaternion]:
    """The unit quaternions of a sequence, each negated where needed so that it lies
    on the same hemisphere as the one before (q_i · q_(i+1) >= 0): the same
    orientations, and in-betweens that take the short way round."""
    keys = [_quaternion(f"{name}[{i}]", q).normalize() for i, q in enumerate(quaternions)]
    for i in range(1, len(keys)):
        if keys[i].dot(keys[i - 1]) < 0:
            keys[i] = -keys[i]
    return keys


def squad_controls(quaternions: Iterable[Quaternion]
                   ) -> tuple[list[Quaternion], list[Quaternion]]:
    """The inner control points a_i of :func:`squad` for a key sequence q_0 ... q_n
    (put on one hemisphere first by :func:`hemisphere`; Shoemake 1985, section 6):

        a_i = q_i exp(-(log(q_i⁻¹ q_(i+1)) + log(q_i⁻¹ q_(i-1))) / 4)

    with q_(-1) = q_0 and q_(n+1) = q_n at the ends.  Returns (keys, controls): the
    hemisphere-aligned keys and one control per key.

    Parameters
    ----------
    quaternions : iterable of Quaternion
        The key orientations, at least one.

    Returns
    -------
    keys : list of Quaternion
        The unit keys, each on the hemisphere of the one before.
    controls : list of Quaternion
        One inner control point per key.

    Raises
    ------
    ArgumentTypeError
        If a key is not a Quaternion.
    ArgumentValueError
        If there is no key.

    References
    ----------
    Shoemake 1985 (cited in full in the module docstring).

    Examples
    --------
    For the two keys 0 and a quarter turn about z, the controls turn by -π/8 and
    π/2 + π/8 about z (the tangent -(log q1 + log q0) / 4 = (0, 0, 0, -π/16)):

    >>> import math
    >>> from scanline.transform3d import Quaternion, squad_controls
    >>> keys, controls = squad_controls([Quaternion(),
    ...                                  Quaternion.from_axis_angle("z", math.pi / 2)])
    >>> [round(math.degrees(c.angle), 9) for c in controls]
    [22.5, 112.5]
    """
    keys = hemisphere(quaternions)
    if not keys:
        raise ArgumentValueError("quaternions must hold at least one key orientation")
    controls: list[Quaternion] = []
    for i, q in enumerate(keys):
        before, after = keys[max(i - 1, 0)], keys[min(i + 1, len(keys) - 1)]
        inv = q.conjugate()
        tangent = -((inv * after).log() + (inv * before).log()) / 4
        controls.append(q * Quaternion.exp(tangent))
    return keys, controls


__all__ = ["ORTHONORMAL_TOLERANCE", "Quaternion", "hemisphere", "slerp", "squad",
           "squad_controls"]
