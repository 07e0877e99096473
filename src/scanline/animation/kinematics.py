"""Kinematics of articulated chains (Hearn & Baker §16-6, "Kinematics and dynamics";
the notes' syllabus, "Kinematics and Dynamics").

*Forward kinematics* gives the joints' positions from the joint angles; *inverse
kinematics* finds angles that put the end of the chain (the end effector) at a goal
— goal-directed motion as far as kinematics gives it: specify where the hand must be,
and the angles follow.

A :class:`Chain` is a sequence of rigid links joined by revolute joints, fixed at a
base.  In the plane, joint i turns link i by θᵢ relative to link i - 1 (θ₀ from +x).
In space, joint i turns about an axis given in the frame of the link before it, and
each link lies along its own frame's x axis.

>>> import scanline as sl
>>> arm = sl.animation.Chain([2.0, 1.0])
>>> arm.forward([0.0, 1.5707963267948966]).round(12).tolist()
[[0.0, 0.0], [2.0, 0.0], [2.0, 1.0]]
>>> reach = arm.inverse((1.0, 2.0))
>>> reach.reached, arm.end(reach).round(9).tolist()
(True, [1.0, 2.0])
>>> arm.inverse((5.0, 0.0)).reached            # beyond the reach of 3: reported
False
"""

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, DTypeLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ._checks import flag, floats

#: Inverse-kinematics methods.
METHODS = ("analytic", "ccd", "dls")

#: The most iterations :meth:`Chain.inverse` may be asked for (each is a sweep of the
#: joints or a linear solve: more would only make a call that never returns).
MAX_ITERATIONS = 1_000_000


class UnreachableTarget(ArgumentValueError):
    """``Chain.inverse(..., strict=True)`` could not reach the target."""


@dataclass(frozen=True)
class Reach:
    """The result of :meth:`Chain.inverse`.

    ``numpy.asarray(reach)`` is the angles, so a Reach can be passed wherever angles go.

    Parameters
    ----------
    angles : numpy.ndarray
        The joint angles found (radians, within the joint limits).
    position : numpy.ndarray
        Where they put the end effector.
    reached : bool
        Whether it is within ``tolerance`` of the target.
    error : float
        The distance from the end effector to the target.
    iterations : int
        Iterations used (0 for the analytic solution).
    method : str
        The method that produced the angles.
    reason : str
        Why the target was not reached ("" when it was).

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> r = sl.animation.Chain([1.0, 1.0]).inverse((1, 1))
    >>> r.reached, r.method, np.asarray(r).shape
    (True, 'analytic', (2,))
    """

    angles: np.ndarray
    position: np.ndarray
    reached: bool
    error: float
    iterations: int
    method: str
    reason: str = ""

    def __array__(self, dtype: DTypeLike | None = None,
                  copy: bool | None = None) -> NDArray[Any]:
        return np.asarray(self.angles, dtype=dtype)


def _rotation(axis: NDArray[np.float64], angle: ArrayLike) -> NDArray[np.float64]:
    """Rotation matrices about unit ``axis`` by ``angle`` (arrays: angle (...,) ->
    (..., 3, 3)), Rodrigues' formula."""
    x, y, z = axis
    c, s = np.cos(angle), np.sin(angle)
    t = 1 - c
    out: NDArray[np.float64] = np.stack([
        np.stack([t * x * x + c, t * x * y - s * z, t * x * z + s * y], -1),
        np.stack([t * x * y + s * z, t * y * y + c, t * y * z - s * x], -1),
        np.stack([t * x * z - s * y, t * y * z + s * x, t * z * z + c], -1)], -2)
    return out


class Chain:
    """An articulated chain of rigid links and revolute joints.

    Parameters
    ----------
    lengths : sequence of float
        The links' lengths, each > 0.
    base : point, optional
        Where joint 0 is fixed (default the origin).
    axes : array_like (n, 3), optional
        A 3-D chain: the rotation axis of each joint in the frame of the link before
        it (joint 0: the world frame).  Without it the chain is planar.
    limits : array_like (n, 2), optional
        (lower, upper) angle of each joint in radians; use ``-inf`` / ``inf`` for a
        free joint.

    Examples
    --------
    A 3-D arm: a base that turns about z, a shoulder and an elbow about y.

    >>> arm = Chain([1.0, 1.0, 1.0], axes=[(0, 0, 1), (0, 1, 0), (0, 1, 0)])
    >>> arm.forward([0.0, -1.5707963267948966, 0.0])[-1].round(12).tolist()
    [1.0, 0.0, 2.0]
    """

    axes: NDArray[np.float64] | None

    def __init__(self, lengths: ArrayLike, base: ArrayLike | None = None,
                 axes: ArrayLike | None = None, limits: ArrayLike | None = None) -> None:
        lengths = floats("lengths", lengths, "a sequence of numbers")
        if lengths.ndim != 1 or len(lengths) < 1:
            raise ArgumentValueError(f"lengths must be a 1-D sequence of at least one length, "
                                     f"got shape {lengths.shape}")
        if not (np.isfinite(lengths).all() and (lengths > 0).all()):
            raise ArgumentValueError(f"lengths must be finite and > 0, got {lengths.tolist()}")
        self.lengths = lengths
        n = len(lengths)
        if axes is None:
            self.axes = None
            self.dimension = 2
        else:
            a = floats("axes", axes, f"({n}, 3) axes, one per joint")
            if a.shape != (n, 3) or not np.isfinite(a).all():
                raise ArgumentValueError(f"axes must have shape ({n}, 3), one finite axis per "
                                         f"joint, got {v._show(axes)}")
            norms = np.linalg.norm(a, axis=1)
            if (norms == 0).any():
                raise ArgumentValueError(f"axes[{int(np.flatnonzero(norms == 0)[0])}] is zero; "
                                         "an axis needs a direction")
            self.axes = a / norms[:, None]
            self.dimension = 3
        at = np.zeros(self.dimension) if base is None else floats("base", base, "a point")
        if at.shape != (self.dimension,) or not np.isfinite(at).all():
            raise ArgumentValueError(f"base must be a finite {self.dimension}-D point, got "
                                     f"{v._show(base)}")
        self.base = at
        if limits is None:
            self.limits = np.tile([-np.inf, np.inf], (n, 1))
        else:
            lim = floats("limits", limits, f"({n}, 2) limits, (lower, upper) per joint")
            if lim.shape != (n, 2) or np.isnan(lim).any() or (lim[:, 0] > lim[:, 1]).any():
                raise ArgumentValueError(f"limits must have shape ({n}, 2), (lower, upper) per "
                                         f"joint with lower <= upper, got {v._show(limits)}")
            self.limits = lim

    @property
    def joints(self) -> int:
        """The number of joints (= links)."""
        return len(self.lengths)

    @property
    def reach(self) -> float:
        """The largest distance from the base the end can be: the sum of the lengths."""
        return float(self.lengths.sum())

    @property
    def inner_reach(self) -> float:
        """The smallest distance from the base a free chain can reach:
        max(0, L_max - (sum of the others))."""
        longest = float(self.lengths.max())
        return max(0.0, 2 * longest - self.reach)

    def _angles(self, angles: ArrayLike, name: str = "angles") -> NDArray[np.float64]:
        a = floats(name, angles, "numbers")
        if a.ndim < 1 or a.shape[-1] != self.joints:
            raise ArgumentValueError(f"{name} must have one angle per joint ({self.joints}) in "
                                     f"the last axis, got shape {a.shape}")
        if not np.isfinite(a).all():
            raise ArgumentValueError(f"{name} must be finite, got {v._show(a.tolist())}")
        return a

    def forward(self, angles: ArrayLike) -> NDArray[np.float64]:
        """Forward kinematics: the positions of the base, each joint and the end.

        Parameters
        ----------
        angles : array_like (..., n)
            Joint angles in radians (a batch of poses in the leading axes).

        Returns
        -------
        numpy.ndarray (..., n + 1, dim)
            Row 0 is the base, row n the end effector.

        Notes
        -----
        Planar: φᵢ = θ₀ + … + θᵢ and pᵢ₊₁ = pᵢ + Lᵢ (cos φᵢ, sin φᵢ).  Spatial:
        Rᵢ = Rᵢ₋₁ · Rot(aᵢ, θᵢ) and pᵢ₊₁ = pᵢ + Rᵢ (Lᵢ, 0, 0)ᵀ.

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``angles`` is not finite numbers, one per joint in the last axis.

        Examples
        --------
        The elbow bent by a right angle:

        >>> import math, scanline as sl
        >>> arm = sl.animation.Chain([1.0, 1.0])                 # planar, two links
        >>> (arm.forward([0, math.pi / 2]).round(12) + 0.0).tolist()
        [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]
        """
        a = self._angles(angles)
        return self._positions(a)[0]

    def _positions(self, a: NDArray[np.float64]
                   ) -> tuple[NDArray[np.float64], NDArray[np.float64] | None]:
        """(positions, world axes of the joints) for angle array ``a``."""
        n = self.joints
        if self.axes is None:
            phi = np.cumsum(a, axis=-1)
            steps = self.lengths[:, None] * np.stack([np.cos(phi), np.sin(phi)], -1)
            out = np.concatenate([np.broadcast_to(self.base, a.shape[:-1] + (1, 2)),
                                  self.base + np.cumsum(steps, axis=-2)], axis=-2)
            return out, None
        frame = np.broadcast_to(np.eye(3), a.shape[:-1] + (3, 3))
        points = [np.broadcast_to(self.base, a.shape[:-1] + (3,))]
        world_axes: list[NDArray[np.float64]] = []
        for i in range(n):
            world_axes.append(frame @ self.axes[i])
            frame = frame @ _rotation(self.axes[i], a[..., i])
            points.append(points[-1] + self.lengths[i] * frame[..., :, 0])
        return np.stack(points, axis=-2), np.stack(world_axes, axis=-2)

    def end(self, angles: ArrayLike) -> NDArray[np.float64]:
        """The end effector's position for ``angles``.

        Parameters
        ----------
        angles : array_like (..., n)
            Joint angles in radians.

        Returns
        -------
        numpy.ndarray (..., dim)

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            As :meth:`forward`.

        Examples
        --------
        >>> import math, scanline as sl
        >>> arm = sl.animation.Chain([1.0, 1.0])                 # planar, two links
        >>> arm.end([0, 0]).tolist()
        [2.0, 0.0]
        """
        out: NDArray[np.float64] = self.forward(angles)[..., -1, :]
        return out

    def jacobian(self, angles: ArrayLike) -> NDArray[np.float64]:
        """∂(end position)/∂θ, shape (dim, n): column i is the joint's axis crossed
        with the vector from the joint to the end.

        Parameters
        ----------
        angles : array_like (n,)
            One pose.

        Returns
        -------
        numpy.ndarray (dim, n)

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``angles`` is not one finite pose.

        Examples
        --------
        With the elbow at (1, 0) and the end at (1, 1), the arms from the joints to
        the end are (1, 1) and (0, 1); turned by 90 degrees, (-1, 1) and (-1, 0):

        >>> import math, scanline as sl
        >>> arm = sl.animation.Chain([1.0, 1.0])                 # planar, two links
        >>> arm.jacobian([0, math.pi / 2]).tolist()
        [[-1.0, -1.0], [1.0, 0.0]]
        """
        a = self._angles(angles)
        if a.ndim != 1:
            raise ArgumentValueError("jacobian takes one pose (a 1-D array of angles)")
        points, axes = self._positions(a)
        arm = points[-1] - points[:-1]
        if axes is None:
            planar: NDArray[np.float64] = np.stack([-arm[:, 1], arm[:, 0]])
            return planar
        spatial: NDArray[np.float64] = np.cross(axes, arm).T
        return spatial

    # -- inverse kinematics ---------------------------------------------------------------
    def inverse(self, target: ArrayLike, method: str | None = None,
                initial: ArrayLike | None = None, tolerance: float | None = None,
                max_iterations: int = 500, elbow: str = "up", damping: float | None = None,
                strict: bool = False) -> Reach:
        """Inverse kinematics: joint angles that put the end effector at ``target``.

        Parameters
        ----------
        target : point
            The goal, a point of the chain's dimension.
        method : {"analytic", "ccd", "dls"}, optional
            ``"analytic"``: the closed form of a planar two-link chain (law of
            cosines).  ``"ccd"``: cyclic coordinate descent (Wang & Chen 1991), each
            joint in turn, last to first, turned to swing the end toward the target.
            ``"dls"``: damped least squares (Wampler 1986; Nakamura & Hanafusa
            1986), Δθ = Jᵀ (J Jᵀ + λ² I)⁻¹ e.  Default: analytic where it applies,
            else dls.
        initial : angles, optional
            Starting angles of the iterative methods (default: all 0, or the limits'
            middle); the previous frame's angles make a smooth motion.
        tolerance : float, optional
            A target closer than this is reached (default 1e-9 of the reach).
        max_iterations : int
            Sweeps (ccd) or steps (dls).
        elbow : {"up", "down"}
            The analytic solution's branch: "up" bends the elbow counterclockwise.
        damping : float, optional
            λ of dls (default 1 % of the reach).
        strict : bool
            Raise :class:`UnreachableTarget` instead of reporting it.

        Returns
        -------
        Reach
            The angles and whether (and how closely) the target is reached.  An
            unreachable target is *reported*: the angles then bring the end as close
            as the method gets (the arm stretched toward it).

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If an argument is out of range or ``method`` does not fit the chain.
        UnreachableTarget
            With ``strict``, when the target is not reached.

        Examples
        --------
        >>> import math, scanline as sl
        >>> arm = sl.animation.Chain([1.0, 1.0])                 # planar, two links
        >>> r = arm.inverse((1, 1))
        >>> r.reached, r.method, (r.position.round(12) + 0.0).tolist()
        (True, 'analytic', [1.0, 1.0])
        >>> arm.inverse((3, 0)).reached                   # beyond the reach of 2
        False
        """
        try:
            p = floats("target", target, f"a {self.dimension}-D point")
        except ArgumentTypeError:
            p = None
        if p is None or p.shape != (self.dimension,) or not np.isfinite(p).all():
            raise ArgumentValueError(f"target must be a finite {self.dimension}-D point, got "
                                     f"{v._show(target)}")
        if tolerance is None:
            tolerance = 1e-9 * self.reach
        tolerance = v.number("tolerance", tolerance)
        if tolerance <= 0:
            raise ArgumentValueError(f"tolerance must be > 0, got {tolerance}")
        max_iterations = v.positive_int("max_iterations", max_iterations)
        if max_iterations > MAX_ITERATIONS:
            raise ArgumentValueError(f"max_iterations={max_iterations} is more than "
                                     f"{MAX_ITERATIONS:,}; the methods converge in far fewer")
        strict = flag("strict", strict)
        v.choice("elbow", elbow, ("up", "down"))
        analytic_fits = self.axes is None and self.joints == 2
        if method is None:
            method = "analytic" if analytic_fits else "dls"
        v.choice("method", method, METHODS)
        if method == "analytic" and not analytic_fits:
            raise ArgumentValueError(
                f"method='analytic' solves planar two-link chains; this chain has "
                f"{self.joints} links in {self.dimension}-D; use method='ccd' or 'dls'")
        angles: NDArray[np.float64] | None = None
        iterations = 0
        if method == "analytic":
            angles = self._two_link(p, elbow)
            if angles is None:       # neither branch within the limits: iterate instead
                method = "dls"
        if method != "analytic":
            start = self._start(initial)
            if method == "ccd":
                angles, iterations = self._ccd(p, start, tolerance, max_iterations)
            else:
                angles, iterations = self._dls(p, start, tolerance, max_iterations, damping)
        assert angles is not None
        position = self.end(angles)
        error = float(np.linalg.norm(position - p))
        reached = error <= tolerance * (1 + 1e-6)
        reason = "" if reached else self._why(p, error)
        if strict and not reached:
            raise UnreachableTarget(f"target={p.tolist()} cannot be reached: {reason}")
        return Reach(angles, position, reached, error, iterations, method, reason)

    def _why(self, p: NDArray[np.float64], error: float) -> str:
        d = float(np.linalg.norm(p - self.base))
        if d > self.reach:
            return (f"it is {d:g} from the base, beyond the chain's reach of {self.reach:g} "
                    f"(the end stops {error:g} short)")
        if d < self.inner_reach:
            return (f"it is {d:g} from the base, inside the radius {self.inner_reach:g} the "
                    f"chain cannot fold into (the end stops {error:g} away)")
        return (f"the end stops {error:g} away: the target is outside what this chain's "
                "joints can reach, or joint limits block it, or the method did not converge "
                "within max_iterations")

    def _start(self, initial: ArrayLike | None) -> NDArray[np.float64]:
        if initial is None:
            lo, hi = self.limits[:, 0], self.limits[:, 1]
            finite = np.isfinite(lo) & np.isfinite(hi)
            mid = np.zeros(self.joints)
            mid[finite] = (lo[finite] + hi[finite]) / 2
            return np.clip(mid, lo, hi)
        a = self._angles(initial, "initial")
        if a.ndim != 1:
            raise ArgumentValueError("initial must be one pose (a 1-D array of angles)")
        return np.clip(a, self.limits[:, 0], self.limits[:, 1])

    def _within(self, a: NDArray[np.float64]) -> bool:
        return bool(((a >= self.limits[:, 0] - 1e-12) & (a <= self.limits[:, 1] + 1e-12)).all())

    def _two_link(self, p: NDArray[np.float64], elbow: str) -> NDArray[np.float64] | None:
        """The law of cosines; None when neither elbow branch fits the limits."""
        l1, l2 = self.lengths
        x, y = p - self.base
        d2 = x * x + y * y
        c2 = np.clip((d2 - l1 * l1 - l2 * l2) / (2 * l1 * l2), -1.0, 1.0)
        branches = (1.0, -1.0) if elbow == "up" else (-1.0, 1.0)
        for sign in branches:
            t2 = sign * math.acos(c2)
            if d2 == 0:             # target on the base: any θ1 works when l1 == l2
                t1 = 0.0
            else:
                t1 = math.atan2(y, x) - math.atan2(l2 * math.sin(t2), l1 + l2 * math.cos(t2))
            t1 = math.remainder(t1, 2 * math.pi)
            candidate = np.array([t1, t2])
            for turn in (0.0, 2 * math.pi, -2 * math.pi):
                shifted: NDArray[np.float64] = candidate + np.array([turn, 0.0])
                if self._within(shifted):
                    return shifted
        return None

    def _ccd(self, p: NDArray[np.float64], angles: NDArray[np.float64], tolerance: float,
             max_iterations: int) -> tuple[NDArray[np.float64], int]:
        angles = angles.copy()
        lo, hi = self.limits[:, 0], self.limits[:, 1]
        for sweep in range(1, max_iterations + 1):
            for i in range(self.joints - 1, -1, -1):
                points, axes = self._positions(angles)
                to_end, to_goal = points[-1] - points[i], p - points[i]
                if axes is None:
                    cross = to_end[0] * to_goal[1] - to_end[1] * to_goal[0]
                    delta = math.atan2(cross, float(to_end @ to_goal))
                else:
                    a = axes[i]
                    e = to_end - (to_end @ a) * a
                    g = to_goal - (to_goal @ a) * a
                    delta = math.atan2(float(a @ np.cross(e, g)), float(e @ g))
                angles[i] = min(max(angles[i] + delta, lo[i]), hi[i])
            if np.linalg.norm(self.end(angles) - p) <= tolerance:
                return angles, sweep
        return angles, max_iterations

    def _dls(self, p: NDArray[np.float64], angles: NDArray[np.float64], tolerance: float,
             max_iterations: int, damping: float | None) -> tuple[NDArray[np.float64], int]:
        """Damped least squares with Levenberg–Marquardt control of λ: a step that
        brings the end closer is taken and λ halved, one that does not is refused
        and λ quadrupled (so the method neither oscillates nor stalls)."""
        lam = 0.01 * self.reach if damping is None else v.number("damping", damping)
        if lam < 0:
            raise ArgumentValueError(f"damping must be >= 0, got {lam}")
        lam = max(lam, 1e-12 * self.reach)
        angles = angles.copy()
        lo, hi = self.limits[:, 0], self.limits[:, 1]
        eye = np.eye(self.dimension)
        e = p - self.end(angles)
        error = float(np.linalg.norm(e))
        for step in range(1, max_iterations + 1):
            if error <= tolerance:
                return angles, step - 1
            j = self.jacobian(angles)
            delta = j.T @ np.linalg.solve(j @ j.T + lam * lam * eye, e)
            scale = max(1.0, float(np.abs(delta).max()) / 0.5)   # at most 0.5 rad a step
            trial = np.clip(angles + delta / scale, lo, hi)
            e_trial = p - self.end(trial)
            trial_error = float(np.linalg.norm(e_trial))
            if trial_error < error:
                angles, e, error = trial, e_trial, trial_error
                lam = max(lam * 0.5, 1e-12 * self.reach)
            else:
                lam *= 4.0
                if lam > 1e6 * self.reach:      # no step helps: a minimum (limits, reach)
                    return angles, step
        return angles, max_iterations

    def follow(self, targets: ArrayLike, initial: ArrayLike | None = None,
               method: str | None = None,
               **options: Any) -> tuple[NDArray[np.float64], list[Reach]]:
        """Solve a target per frame, each from the previous frame's angles: the end
        effector follows the path ``targets`` (m points) smoothly.

        Returns an (m, n) array of angles and the list of :class:`Reach` results.

        Parameters
        ----------
        targets : array_like (m, dim)
            One target per frame.
        initial : angles, optional
            The first frame's starting angles.
        method : {"analytic", "ccd", "dls"}, optional
            As :meth:`inverse`.
        **options
            Further options of :meth:`inverse`.

        Returns
        -------
        angles : numpy.ndarray (m, n)
        results : list of Reach

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``targets`` is not (m, dim) points, or as :meth:`inverse`.

        Notes
        -----
        Goal-directed motion by inverse kinematics (Hearn & Baker, §16-6).

        Examples
        --------
        >>> import math, scanline as sl
        >>> arm = sl.animation.Chain([1.0, 1.0])                 # planar, two links
        >>> angles, results = arm.follow([(1, 1), (0, 1.5)])
        >>> angles.shape, [r.reached for r in results]
        ((2, 2), [True, True])
        """
        pts = floats("targets", targets, f"(m, {self.dimension}) points")
        if pts.ndim != 2 or pts.shape[1] != self.dimension:
            raise ArgumentValueError(f"targets must have shape (m, {self.dimension}), got "
                                     f"{pts.shape}")
        current = self._start(initial)
        results: list[Reach] = []
        for point in pts:
            r = self.inverse(point, method=method, initial=current, **options)
            results.append(r)
            current = r.angles
        return np.array([r.angles for r in results]).reshape(len(pts), self.joints), results

    def __repr__(self) -> str:
        kind = "planar" if self.axes is None else "spatial"
        return f"Chain({self.joints} links, {kind}, reach {self.reach:g})"
