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

import numpy as np

from .. import _validate as v
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


def _component(name, value):
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

    def __init__(self, w=1.0, x=0.0, y=0.0, z=0.0):
        q = np.array([_component("w", w), _component("x", x), _component("y", y),
                      _component("z", z)])
        if not q.any():
            raise ArgumentValueError(
                "the quaternion (w, x, y, z) = (0, 0, 0, 0) is the zero quaternion: it is no "
                "rotation and has no inverse; give at least one nonzero component (the "
                "identity is Quaternion(1, 0, 0, 0))")
        q.flags.writeable = False
        object.__setattr__(self, "_q", q)

    def __setattr__(self, name, value):
        raise AttributeError("a Quaternion is immutable; its operations return new ones")

    @classmethod
    def _of(cls, q, what="the result"):
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
    def from_array(cls, wxyz, name="q"):
        """The quaternion of the four numbers ``wxyz`` (scalar first)."""
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
    def from_xyzw(cls, xyzw, name="q"):
        """The quaternion stored scalar last (scipy's ``as_quat()``, glTF's
        ``rotation``): (x, y, z, w)."""
        a = real_array(name, xyzw, "(4,): x, y, z, w")
        if a.shape != (4,):
            raise ArgumentValueError(f"{name} must be four numbers (x, y, z, w), got "
                                     f"{v._show(xyzw)} of shape {a.shape}")
        return cls.from_array(a[[3, 0, 1, 2]], name)

    @classmethod
    def from_axis_angle(cls, axis, angle):
        """The rotation by ``angle`` about ``axis`` (through the origin,
        counterclockwise looking from the axis' tip toward the origin):
        q = (cos θ/2, u sin θ/2), u = axis / |axis| (Hearn & Baker, eq. 11-37).

        ``axis`` is a nonzero 3-vector or ``"x"``, ``"y"``, ``"z"``; ``angle`` in
        radians (or a string with its unit, ``"30deg"``).
        """
        if isinstance(axis, str):
            v.choice("axis", axis, tuple(_AXIS))
            axis = _AXIS[axis]
        u = direction("axis", axis)
        half = v.angle("angle", angle) / 2
        s = math.sin(half)
        return cls(math.cos(half), *(float(c) * s for c in u))

    @classmethod
    def from_matrix(cls, m):
        """The unit quaternion of a rotation matrix (3x3, or 4x4 with no translation
        and last row 0 0 0 1), by Shepperd's method: of 4w², 4x², 4y², 4z² (from the
        trace and the diagonal) the largest is found first, and the other components
        from the off-diagonal sums and differences divided by it, so that nothing is
        divided by a small number.  The result has w >= 0.

        A matrix that is not a rotation (a scaling, a reflection, a shear, a
        translation) is refused: see :data:`ORTHONORMAL_TOLERANCE`.
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
            q = (r / 2, (a[2, 1] - a[1, 2]) / (2 * r), (a[0, 2] - a[2, 0]) / (2 * r),
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
            q = tuple(out)
        q = np.array(q, dtype=np.float64)
        if q[0] < 0:
            q = -q
        return cls._of(q / np.linalg.norm(q))

    @classmethod
    def from_euler(cls, seq, angles):
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
            One angle per letter, in radians (or strings with units, ``"30deg"``).
        """
        if not isinstance(seq, str) or not 1 <= len(seq) <= 3 or not (
                set(seq) <= set("xyz") or set(seq) <= set("XYZ")):
            raise ArgumentValueError(
                f"seq must be one to three axis letters, all lower case (extrinsic: 'xyz') "
                f"or all upper case (intrinsic: 'XYZ'), got {v._show(seq)}")
        if any(a == b for a, b in zip(seq, seq[1:])):
            raise ArgumentValueError(f"seq={seq!r} names the same axis twice in a row; "
                                     "successive axes must differ (e.g. 'zxz' or 'xyz')")
        if isinstance(angles, numbers.Real) or isinstance(angles, str):
            angles = [angles]
        try:
            angles = list(angles)
        except TypeError:
            raise ArgumentTypeError(f"angles must be {len(seq)} angle(s), got "
                                    f"{v._show(angles)}") from None
        if len(angles) != len(seq):
            raise ArgumentValueError(f"angles must hold one angle per axis of seq={seq!r} "
                                     f"({len(seq)}), got {len(angles)}")
        steps = [cls.from_axis_angle(axis.lower(), v.angle(f"angles[{i}]", a))
                 for i, (axis, a) in enumerate(zip(seq, angles))]
        q = steps[0]
        for step in steps[1:]:
            q = step * q if seq.islower() else q * step
        return q

    # -- components -----------------------------------------------------------------------
    @property
    def w(self):
        """The scalar part."""
        return float(self._q[0])

    @property
    def x(self):
        """The i component."""
        return float(self._q[1])

    @property
    def y(self):
        """The j component."""
        return float(self._q[2])

    @property
    def z(self):
        """The k component."""
        return float(self._q[3])

    @property
    def wxyz(self):
        """(w, x, y, z) as a read-only float64 array."""
        return self._q

    @property
    def xyzw(self):
        """(x, y, z, w): scalar last, as scipy and glTF store it."""
        return self._q[[1, 2, 3, 0]]

    @property
    def norm(self):
        """|q| = sqrt(w² + x² + y² + z²)."""
        big = np.abs(self._q).max()
        return float(big * np.linalg.norm(self._q / big))

    @property
    def angle(self):
        """The rotation angle in [0, π] (radians)."""
        q = self.normalize()._q
        return float(2 * math.atan2(np.linalg.norm(q[1:]), abs(q[0])))

    @property
    def axis(self):
        """The unit rotation axis (for the angle in [0, π]); (1, 0, 0) for the
        identity, whose axis is any."""
        q = self.normalize()._q
        u = q[1:] if q[0] >= 0 else -q[1:]
        n = np.linalg.norm(u)
        return np.array([1.0, 0.0, 0.0]) if n == 0 else u / n

    # -- algebra --------------------------------------------------------------------------
    def __mul__(self, other):
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

    def __neg__(self):
        """-q: the same rotation, the other sign."""
        return Quaternion(*(-self._q))

    def dot(self, other):
        """The four-dimensional dot product w1 w2 + x1 x2 + y1 y2 + z1 z2."""
        if not isinstance(other, Quaternion):
            raise ArgumentTypeError(f"other must be a Quaternion, got {v._show(other)}")
        return float(self._q @ other._q)

    def conjugate(self):
        """q* = (w, -x, -y, -z)."""
        return Quaternion(self._q[0], *(-self._q[1:]))

    def inverse(self):
        """q⁻¹ = q* / |q|² (the inverse rotation; q* itself for a unit q)."""
        n = self.norm
        return Quaternion._of(self.conjugate()._q / n / n, "the inverse")

    def normalize(self):
        """q / |q|: the unit quaternion of the same rotation."""
        big = np.abs(self._q).max()
        q = self._q / big
        return Quaternion(*(q / np.linalg.norm(q)))

    def __eq__(self, other):
        if not isinstance(other, Quaternion):
            return NotImplemented
        return bool((self._q == other._q).all())

    def __hash__(self):
        return hash(tuple(self._q.tolist()))

    def __repr__(self):
        return "Quaternion(w={:.9g}, x={:.9g}, y={:.9g}, z={:.9g})".format(*self._q)

    def __reduce__(self):
        return (Quaternion, tuple(self._q.tolist()))

    # -- as a rotation --------------------------------------------------------------------
    def matrix3(self):
        """The 3x3 rotation matrix (Hearn & Baker, eq. 11-41) of q / |q|."""
        s, a, b, c = self.normalize()._q
        return np.array([
            [1 - 2 * (b * b + c * c), 2 * (a * b - s * c), 2 * (a * c + s * b)],
            [2 * (a * b + s * c), 1 - 2 * (a * a + c * c), 2 * (b * c - s * a)],
            [2 * (a * c - s * b), 2 * (b * c + s * a), 1 - 2 * (a * a + b * b)]])

    def matrix(self):
        """The 4x4 homogeneous rotation matrix (the 3x3 of :meth:`matrix3` in the
        upper left), ready for :func:`scanline.transform3d.compose`."""
        m = np.eye(4)
        m[:3, :3] = self.matrix3()
        return m

    def rotate(self, vectors):
        """``vectors`` (one (3,) or (N, 3)) rotated: q p q⁻¹ for each p, computed
        as the matrix product (the same rotation, fewer operations)."""
        p, single = points("vectors", vectors)
        out = p @ self.matrix3().T
        return out[0] if single else out

    # -- Shoemake's curves ----------------------------------------------------------------
    def log(self):
        """The logarithm of the unit quaternion q / |q| = (cos θ, u sin θ):
        (0, u θ), θ in [0, π]."""
        q = self.normalize()._q
        n = np.linalg.norm(q[1:])
        if n == 0:
            return np.zeros(4)
        theta = math.atan2(n, q[0])
        return np.concatenate([[0.0], q[1:] * (theta / n)])

    @staticmethod
    def exp(pure):
        """exp((0, u θ)) = (cos θ, u sin θ) for a pure quaternion ``pure`` (four
        numbers, w = 0, or three: the vector part), the inverse of :meth:`log`."""
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

    def slerp(self, other, t):
        """The in-between at ``t`` (0 gives this rotation, 1 ``other``) on the
        shorter great arc; see :func:`slerp`."""
        return slerp(self, other, t)


def _quaternion(name, q):
    if not isinstance(q, Quaternion):
        raise ArgumentTypeError(f"{name} must be a scanline.transform3d.Quaternion, got "
                                f"{v._show(q)}")
    return q


def slerp(q1, q2, t):
    """Spherical linear interpolation (Shoemake 1985, section 3.3):

        slerp(q1, q2; t) = sin((1 - t) θ) / sin θ · q1 + sin(t θ) / sin θ · q2,
        cos θ = q1 · q2

    for the unit quaternions of q1 and q2, with q2 negated first when q1 · q2 < 0, so
    that the in-betweens take the short way round (q2 and -q2 are the same
    orientation; the long way would turn by more than π).  The angular velocity is
    constant in t.  ``t`` outside [0, 1] extrapolates along the same great circle.

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


def _unit(q, what):
    """``q`` / |q| without overflow; an error naming ``what`` where q is not finite or
    zero (t far outside [0, 1] on nearly equal keys)."""
    with np.errstate(over="ignore", invalid="ignore"):
        big = np.abs(q).max()
        if not np.isfinite(big) or big == 0:
            return Quaternion._of(q, what)
        q = q / big
    return Quaternion._of(q / np.linalg.norm(q), what)


def squad(q1, q2, a1, a2, t):
    """Spherical cubic interpolation between key orientations q1 and q2 with inner
    control points a1 and a2 (Shoemake 1985, section 6; his "squad"):

        squad(q1, q2, a1, a2; t) = slerp(slerp(q1, q2; t), slerp(a1, a2; t); 2t(1 - t))

    The control points of a key sequence come from :func:`squad_controls`; with them
    the curve through the keys has a continuous tangent at each key.  Here the inner
    slerps take the arc as given (no short-arc flip: the keys are put on one
    hemisphere beforehand, as :func:`squad_controls` does).
    """
    qs = [_quaternion(n, q).normalize()._q for n, q in
          (("q1", q1), ("q2", q2), ("a1", a1), ("a2", a2))]
    t = v.number("t", t)
    outer = _arc(qs[0], qs[1], t)
    inner = _arc(qs[2], qs[3], t)
    out = _arc(outer, inner, 2 * t * (1 - t))
    return Quaternion._of(out, "squad")


def _arc(p, q, t):
    """slerp on the great arc from unit p to unit q as given (the long way round when
    p · q < 0)."""
    d = min(max(float(p @ q), -1.0), 1.0)
    theta = math.acos(d)
    if math.sin(theta) < _TINY_ANGLE:
        out = p + t * (q - p) if d > 0 else p      # antipodes: no arc is defined; stay
    else:
        s = math.sin(theta)
        out = math.sin((1 - t) * theta) / s * p + math.sin(t * theta) / s * q
    return out / np.linalg.norm(out)


def hemisphere(quaternions, name="quaternions"):
    """The unit quaternions of a sequence, each negated where needed so that it lies
    on the same hemisphere as the one before (q_i · q_(i+1) >= 0): the same
    orientations, and in-betweens that take the short way round."""
    keys = [_quaternion(f"{name}[{i}]", q).normalize() for i, q in enumerate(quaternions)]
    for i in range(1, len(keys)):
        if keys[i].dot(keys[i - 1]) < 0:
            keys[i] = -keys[i]
    return keys


def squad_controls(quaternions):
    """The inner control points a_i of :func:`squad` for a key sequence q_0 ... q_n
    (put on one hemisphere first by :func:`hemisphere`; Shoemake 1985, section 6):

        a_i = q_i exp(-(log(q_i⁻¹ q_(i+1)) + log(q_i⁻¹ q_(i-1))) / 4)

    with q_(-1) = q_0 and q_(n+1) = q_n at the ends.  Returns (keys, controls): the
    hemisphere-aligned keys and one control per key.
    """
    keys = hemisphere(quaternions)
    if not keys:
        raise ArgumentValueError("quaternions must hold at least one key orientation")
    controls = []
    for i, q in enumerate(keys):
        before, after = keys[max(i - 1, 0)], keys[min(i + 1, len(keys) - 1)]
        inv = q.conjugate()
        tangent = -((inv * after).log() + (inv * before).log()) / 4
        controls.append(q * Quaternion.exp(tangent))
    return keys, controls


__all__ = ["ORTHONORMAL_TOLERANCE", "Quaternion", "hemisphere", "slerp", "squad",
           "squad_controls"]
