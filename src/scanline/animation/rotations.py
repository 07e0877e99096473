"""Key frames of orientation: in-betweens of rotations by quaternion interpolation
(Hearn & Baker, §16-5 and §11-2; Shoemake 1985).

Interpolating Euler angles one by one turns an object along a path that depends on
the order of the axes and wobbles between keys (and locks where two axes line up);
interpolating the rotations' unit quaternions along great arcs (slerp) turns it
about one axis at a constant rate between two keys, the shortest way, and squad
joins a sequence of keys with a continuous angular velocity.

A :class:`RotationKeyFrames` track is a :class:`~scanline.animation.KeyFrames` whose
values are orientations: a :class:`~scanline.animation.Timeline` plays it like any
track, and it returns a :class:`~scanline.transform3d.Quaternion` at each time
(:meth:`RotationKeyFrames.matrices` gives 4x4 matrices).

>>> import math, scanline as sl
>>> Q = sl.transform3d.Quaternion
>>> spin = sl.animation.RotationKeyFrames([0, 2], [Q(), Q.from_axis_angle("z", math.pi / 2)])
>>> round(math.degrees(spin(1.0).angle), 9)
45.0
"""

import numbers
from collections.abc import Sequence
from typing import Any, Union, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..transform3d.quaternion import Quaternion, slerp, squad, squad_controls
from .easing import Easing, resolve
from .keyframes import KeyFrames, _per_segment, _times
from ._checks import floats

#: Interpolation methods between key orientations.
ROTATION_INTERPOLATIONS = ("slerp", "squad")


def rotation(name: str, value: object) -> Quaternion:
    """A key orientation: a Quaternion, a 3x3 or 4x4 rotation matrix, or four
    numbers (w, x, y, z)."""
    if isinstance(value, Quaternion):
        return value
    if isinstance(value, (str, bytes, numbers.Number)) or value is None:
        raise ArgumentTypeError(f"{name} must be a Quaternion, a rotation matrix or (w, x, y, "
                                f"z), got {v._show(value)}")
    a = v.real_array(name, value, "(4,), (3, 3) or (4, 4)")
    if a.shape == (4,):
        return Quaternion.from_array(a, name)
    if a.shape in ((3, 3), (4, 4)):
        try:
            return Quaternion.from_matrix(a)
        except ArgumentValueError as error:
            raise ArgumentValueError(f"{name}: {error}") from None
    raise ArgumentValueError(f"{name} must be a Quaternion, a 3x3 or 4x4 rotation matrix or "
                             f"(w, x, y, z), got shape {a.shape}")


class RotationKeyFrames(KeyFrames):
    """Key orientations at key times, and the in-betweens on the unit quaternions.

    Parameters
    ----------
    times : sequence of float
        Key times in seconds, strictly increasing.
    rotations : sequence
        One orientation per key time: :class:`~scanline.transform3d.Quaternion`,
        rotation matrices (3x3 or 4x4) or (w, x, y, z).  Each key is put on the
        hemisphere of the one before (q and -q are one orientation), so that each
        segment turns the short way.
    interpolation : {"slerp", "squad"}
        ``"slerp"``: along the great arc between each pair of keys, at a constant
        angular velocity (Shoemake's section 3.3); ``"squad"``: Shoemake's
        spherical cubic through the keys (section 6), whose angular velocity is
        continuous at the keys.
    ease : str, callable or list
        The easing of each segment, as for :class:`KeyFrames`.

    Notes
    -----
    Outside [times[0], times[-1]] a track holds its first or last orientation; at a
    key time it is the key exactly.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If the times do not increase strictly, ``rotations`` is not one orientation
        per key time, or an option is unknown.

    Examples
    --------
    Half way between no turn and a quarter turn about z is an eighth of a turn:

    >>> import math, scanline as sl
    >>> Q = sl.transform3d.Quaternion
    >>> spin = sl.animation.RotationKeyFrames([0, 2], [Q(), Q.from_axis_angle("z", math.pi / 2)])
    >>> spin(1.0)
    Quaternion(w=0.923879533, x=0, y=0, z=0.382683432)
    """

    def __init__(self, times: ArrayLike, rotations: Sequence[object],
                 interpolation: str = "slerp",
                 ease: Union[str, Easing, list[Union[str, Easing]]] = "linear") -> None:
        self.times = _times(times)
        k = len(self.times)
        if isinstance(rotations, (str, bytes)) or not hasattr(rotations, "__len__"):
            raise ArgumentTypeError(f"rotations must be a sequence of orientations, one per "
                                    f"key frame, got {v._show(rotations)}")
        if len(rotations) != k:
            raise ArgumentValueError(f"rotations must hold one orientation per key frame "
                                     f"({k}), got {len(rotations)}")
        keys = [rotation(f"rotations[{i}]", r) for i, r in enumerate(rotations)]
        self.keys, self.controls = squad_controls(keys)
        self.values = np.array([q.wxyz for q in self.keys])
        self.times.flags.writeable = False
        self.values.flags.writeable = False
        self.interpolation = v.choice("interpolation", interpolation, ROTATION_INTERPOLATIONS)
        self.ease = _per_segment("ease", ease, max(k - 1, 1), resolve)
        self._flat = self.values
        self._keys = self.times.tolist()
        self._curve = None

    @property
    def shape(self) -> tuple[int, ...]:
        """The shape of one value's components (w, x, y, z)."""
        return (4,)

    def at(self, t: ArrayLike) -> Any:
        """The orientation at time ``t``: a Quaternion; for an array of times, an
        array of their (w, x, y, z) components, shape ``np.shape(t) + (4,)``.

        Parameters
        ----------
        t : float or array_like
            Times in seconds, finite.

        Returns
        -------
        Quaternion or numpy.ndarray

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``t`` is not finite numbers.

        Examples
        --------
        >>> import math, scanline as sl
        >>> Q = sl.transform3d.Quaternion
        >>> spin = sl.animation.RotationKeyFrames([0, 2], [Q(), Q.from_axis_angle("z", math.pi / 2)])
        >>> spin.at([0.0, 2.0]).round(9).tolist()
        [[1.0, 0.0, 0.0, 0.0], [0.707106781, 0.0, 0.0, 0.707106781]]
        """
        ts = floats("t", t, "a time or an array of times")
        if not np.isfinite(ts).all():
            raise ArgumentValueError(f"t must be finite, got {v._show(t)}")
        if ts.ndim == 0:
            return self._orientation(float(ts))
        flat = [self._orientation(x).wxyz for x in ts.ravel().tolist()]
        return np.array(flat).reshape(ts.shape + (4,))

    def _orientation(self, t: float) -> Quaternion:
        keys = self.keys
        if len(keys) == 1 or t <= self._keys[0]:
            return keys[0]
        if t >= self._keys[-1]:
            return keys[-1]
        ks, ss = self.segment(np.array([t]))
        k, s = int(ks[0]), float(ss[0])
        if self._keys[k] == t:
            return keys[k]
        if self.interpolation == "slerp":
            return slerp(keys[k], keys[k + 1], s)
        return squad(keys[k], keys[k + 1], self.controls[k], self.controls[k + 1], s)

    def _at_one(self, t: float) -> NDArray[np.float64]:
        wxyz: NDArray[np.float64] = self._orientation(t).wxyz.copy()
        return wxyz

    def _evaluate(self, t: NDArray[np.float64]) -> NDArray[np.float64]:
        return np.array([self._orientation(x).wxyz for x in np.asarray(t).tolist()])

    def matrices(self, t: ArrayLike) -> NDArray[np.float64]:
        """The 4x4 rotation matrices at the times ``t`` (one time: (4, 4); an array:
        ``np.shape(t) + (4, 4)``).

        Parameters
        ----------
        t : float or array_like
            Times in seconds, finite.

        Returns
        -------
        ndarray of float64, shape ``np.shape(t) + (4, 4)``

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``t`` is not finite numbers.

        Examples
        --------
        At the last key, the quarter turn about z:

        >>> import math, scanline as sl
        >>> Q = sl.transform3d.Quaternion
        >>> spin = sl.animation.RotationKeyFrames([0, 2], [Q(), Q.from_axis_angle("z", math.pi / 2)])
        >>> (spin.matrices(2.0).round(12) + 0.0).tolist()
        [[0.0, -1.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]]
        """
        ts = floats("t", t, "a time or an array of times")
        if ts.ndim == 0:
            return cast(Quaternion, self.at(t)).matrix()
        q = self.at(ts).reshape(-1, 4)
        out = np.array([Quaternion(*row).matrix() for row in q.tolist()])
        stacked: NDArray[np.float64] = out.reshape(ts.shape + (4, 4))
        return stacked

    def __repr__(self) -> str:
        return (f"RotationKeyFrames({len(self)} keys, {self.start:g} s to {self.end:g} s, "
                f"{self.interpolation})")
