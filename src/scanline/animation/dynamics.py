"""Dynamics: particle systems moved by forces (Hearn & Baker §16-6, "Kinematics and
dynamics": "motion parameters ... obtained from the forces", Newton's second law
F = m a; the notes' syllabus, "Kinematics and Dynamics").

:class:`Particles` holds positions, velocities and masses in 2-D or 3-D; forces
(:class:`Gravity`, :class:`Spring`, :class:`Drag`, :class:`Force` for any function)
give the accelerations a = F / m; :meth:`Particles.step` integrates one time step
with explicit Euler, semi-implicit (symplectic) Euler, velocity Verlet or classical
Runge–Kutta 4, then resolves collisions with :class:`Plane` obstacles (restitution
and friction).  :meth:`Particles.energy` reports kinetic, potential and total energy
so that conservation can be checked.

>>> import scanline as sl
>>> ball = sl.animation.Particles([(0.0, 10.0)], velocities=[(2.0, 0.0)],
...                               forces=[sl.animation.Gravity((0, -10))])
>>> path = ball.run(1.0, dt=0.01, method="verlet")     # 100 steps
>>> ball.positions.round(9).tolist()             # exact for constant forces
[[2.0, 5.0]]
"""

from __future__ import annotations

import math
from typing import Callable, Iterable, Literal, Optional, Protocol, Sequence, TypedDict, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError, ScanlineError
from ..budget import check as budget
from ._checks import finite, floats

#: Integration methods.
METHODS = ("euler", "semi-implicit-euler", "verlet", "rk4")
#: An integration method's name.
Method = Literal["euler", "semi-implicit-euler", "verlet", "rk4"]
#: Vectors, one per particle: a float array (N, dim).
Vectors = NDArray[np.float64]

_T = TypeVar("_T")


class ForceField(Protocol):
    """What :class:`Particles` takes as a force: :class:`Gravity`, :class:`Spring`,
    :class:`Drag`, :class:`Force`, or any object with these two methods (and
    optionally ``bind(system)``, called when the system is made)."""

    def force(self, system: Particles, x: Vectors, vel: Vectors, t: float) -> Vectors:
        """The forces on the particles at positions ``x``, velocities ``vel``, time ``t``."""

    def potential(self, system: Particles, x: Vectors) -> float:
        """The potential energy at positions ``x`` (0 for a force without one)."""


class Energy(TypedDict):
    """:meth:`Particles.energy`: kinetic, potential and their sum."""
    kinetic: float
    potential: float
    total: float

#: The most steps :meth:`Particles.run` takes in one call.
MAX_STEPS = 2**40


def _indices(name: str, value: object) -> NDArray[np.int64]:
    """Particle numbers: an integer array (numbers that are not whole are refused)."""
    a = floats(name, value, "particle numbers (integers)")
    if not (np.isfinite(a).all() and (a == np.floor(a)).all() and (np.abs(a) < 2**53).all()):
        raise ArgumentValueError(f"{name} must hold particle numbers (whole numbers), got "
                                 f"{v._show(value)}")
    return a.astype(np.int64)


def _per(name: str, value: object, count: int) -> NDArray[np.float64]:
    """A number, or one per item (``count``), as a float array of ``count``."""
    a = floats(name, value, f"a number or {count} numbers")
    try:
        out: NDArray[np.float64] = np.broadcast_to(a, (count,)).copy()
        return out
    except ValueError:
        raise ArgumentValueError(f"{name} must be one number or {count}, one per item, got "
                                 f"shape {a.shape}") from None


def _objects(name: str, value: Iterable[_T]) -> list[_T]:
    if isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
        raise ArgumentTypeError(f"{name} must be a sequence, got {v._show(value)}")
    return list(value)


class DynamicsError(ScanlineError):
    """The simulation blew up: positions or velocities became NaN or infinite.

    Parameters
    ----------
    message : str
        What happened and what to do (a smaller ``dt``, another method ...).
    step : int
        The step (counted from the system's creation) at which it happened.
    time : float
        The simulated time at the start of that step.

    Attributes
    ----------
    step : int
        The step (counted from the system's creation) at which it happened.
    time : float
        The simulated time at the start of that step.

    Examples
    --------
    :meth:`Particles.step` raises it; a program can read where the simulation broke:

    >>> import scanline as sl
    >>> error = sl.animation.DynamicsError("blew up", step=12, time=1.1)
    >>> error.step, error.time
    (12, 1.1)
    """

    def __init__(self, message: str, step: int, time: float) -> None:
        super().__init__(message)
        self.step, self.time = step, time


def _vectors(name: str, value: object, count: int | None, dim: int | None) -> Vectors:
    a = floats(name, value, "an array of vectors")
    if a.ndim == 1 and count is not None and dim is not None and a.shape == (dim,):
        a = np.tile(a, (count, 1))
    if a.ndim != 2 or (count is not None and len(a) != count) or (dim is not None and a.shape[1] != dim):
        want = f"({count if count is not None else 'N'}, {dim if dim is not None else '2 or 3'})"
        raise ArgumentValueError(f"{name} must have shape {want}, got {a.shape}")
    if not np.isfinite(a).all():
        raise ArgumentValueError(f"{name} must be finite, got {v._show(a.tolist())}")
    return a


class Gravity:
    """A uniform field: F = m g.  Potential energy -m g · x.

    Parameters
    ----------
    g : array_like (dim,)
        The acceleration of gravity, a finite vector of the particles' dimension
        (default (0, -9.81): metres per second squared, y up).

    Raises
    ------
    ArgumentTypeError
        For a ``g`` that is not numbers.
    ArgumentValueError
        For a ``g`` that is not a finite vector (and, in :class:`Particles`, one of
        another dimension than the particles).

    Examples
    --------
    >>> import scanline as sl
    >>> sl.animation.Gravity((0, -10)).g.tolist()
    [0.0, -10.0]
    """

    def __init__(self, g: ArrayLike = (0.0, -9.81)) -> None:
        self.g = floats("g", g, "a vector")
        if self.g.ndim != 1 or not np.isfinite(self.g).all():
            raise ArgumentValueError(f"g must be a finite vector, got {v._show(g)}")

    def force(self, system: Particles, x: Vectors, vel: Vectors, t: float) -> Vectors:
        """F = m g on each particle.

        Parameters
        ----------
        system : Particles
            The system (its masses).
        x, vel : numpy.ndarray (N, dim)
            Positions and velocities (unused: the field is uniform).
        t : float
            Time (unused).

        Returns
        -------
        numpy.ndarray (N, dim)
            The forces.

        Examples
        --------
        >>> import scanline as sl
        >>> g = sl.animation.Gravity((0, -10))
        >>> system = sl.animation.Particles([(0, 5), (1, 0)], masses=[2, 1], forces=[g])
        >>> g.force(system, system.positions, system.velocities, 0.0).tolist()
        [[0.0, -20.0], [0.0, -10.0]]
        """
        return system.masses[:, None] * self.g

    def potential(self, system: Particles, x: Vectors) -> float:
        """The potential energy -Σ m g · x (zero at the origin).

        Parameters
        ----------
        system : Particles
            The system (its masses).
        x : numpy.ndarray (N, dim)
            Positions.

        Returns
        -------
        float

        Examples
        --------
        Two kilograms 5 m up, one at height 0, g = 10: 2 · 10 · 5 = 100 J.

        >>> import scanline as sl
        >>> g = sl.animation.Gravity((0, -10))
        >>> system = sl.animation.Particles([(0, 5), (1, 0)], masses=[2, 1], forces=[g])
        >>> g.potential(system, system.positions)
        100.0
        """
        return float(-(system.masses * (x @ self.g)).sum())


class Spring:
    """Hooke's springs with optional damping.

    Parameters
    ----------
    pairs : array_like (m, 2) of int
        The particles each spring joins.  ``anchors`` instead fixes one end in space.
    stiffness : float or sequence
        k > 0 (force per unit stretch).
    rest_length : float or sequence, optional
        Default: the distances at creation.
    damping : float
        c >= 0: a force -c (relative velocity along the spring).
    anchors : array_like (m, dim), optional
        With ``pairs`` of shape (m,): particle ``pairs[i]`` is tied to the fixed point
        ``anchors[i]``.

    Attributes
    ----------
    rest_length : numpy.ndarray (m,)
        The rest lengths, from :meth:`bind` on (when the spring joins a system).

    Raises
    ------
    ArgumentTypeError
        For arguments that are not numbers.
    ArgumentValueError
        For ``pairs`` of another shape, particle numbers that are not whole, a
        stiffness that is not > 0, a negative damping, or (on :meth:`bind`) particle
        numbers out of range, anchors of another dimension or negative rest lengths.

    Examples
    --------
    Two particles 5 apart on a spring of rest length 4 and stiffness 2: stretched by
    1, it pulls each toward the other with a force of 2 along the (0.6, 0.8) line.

    >>> import scanline as sl
    >>> spring = sl.animation.Spring([(0, 1)], stiffness=2.0, rest_length=4.0)
    >>> system = sl.animation.Particles([(0, 0), (3, 4)], forces=[spring])
    >>> spring.force(system, system.positions, system.velocities, 0.0).tolist()
    [[1.2, 1.6], [-1.2, -1.6]]
    """

    def __init__(self, pairs: ArrayLike, stiffness: ArrayLike,
                 rest_length: ArrayLike | None = None, damping: float = 0.0,
                 anchors: ArrayLike | None = None) -> None:
        self.pairs = _indices("pairs", pairs)
        self.anchors = None if anchors is None else finite("anchors", anchors, "(m, dim) points")
        if self.anchors is None and (self.pairs.ndim != 2 or self.pairs.shape[1] != 2):
            raise ArgumentValueError(f"pairs must have shape (m, 2), got {self.pairs.shape}")
        if self.anchors is not None and (self.pairs.ndim != 1 or self.anchors.ndim != 2
                                         or len(self.anchors) != len(self.pairs)):
            raise ArgumentValueError("with anchors, pairs must list one particle per anchor")
        m = len(self.pairs)
        self.stiffness = _per("stiffness", stiffness, m)
        if not (np.isfinite(self.stiffness).all() and (self.stiffness > 0).all()):
            raise ArgumentValueError(f"stiffness must be finite and > 0, got {v._show(stiffness)}")
        self.damping = v.number("damping", damping)
        if self.damping < 0:
            raise ArgumentValueError(f"damping must be >= 0, got {self.damping}")
        # the argument, then (bound) the array of rest lengths
        self._rest: ArrayLike | None = rest_length
        self.rest_length: NDArray[np.float64]

    def _ends(self, x: Vectors) -> tuple[Vectors, Vectors]:
        if self.anchors is None:
            return x[self.pairs[:, 0]], x[self.pairs[:, 1]]
        return x[self.pairs], self.anchors

    def bind(self, system: Particles) -> None:
        """Join ``system`` (:class:`Particles` calls it): check the particle numbers and
        anchors, and fix the rest lengths (when not given: the distances now).

        Parameters
        ----------
        system : Particles

        Raises
        ------
        ArgumentValueError
            For particle numbers out of range, anchors of another dimension than the
            particles, or rest lengths that are not finite and >= 0.

        Examples
        --------
        >>> import scanline as sl
        >>> spring = sl.animation.Spring([(0, 1)], stiffness=2.0)
        >>> system = sl.animation.Particles([(0, 0), (3, 4)])
        >>> spring.bind(system)
        >>> spring.rest_length.tolist()
        [5.0]
        """
        n = len(system.positions)
        idx = self.pairs.ravel()
        if idx.size and (idx.min() < 0 or idx.max() >= n):
            raise ArgumentValueError(f"spring pairs name particles 0..{n - 1}, got {idx.tolist()}")
        if self.anchors is not None and self.anchors.shape != (len(self.pairs), system.dimension):
            raise ArgumentValueError(f"anchors must have shape ({len(self.pairs)}, "
                                     f"{system.dimension}), got {self.anchors.shape}")
        if self._rest is None:
            a, b = self._ends(system.positions)
            self.rest_length = np.linalg.norm(b - a, axis=1)
        else:
            self.rest_length = _per("rest_length", self._rest, len(self.pairs))
            if not (np.isfinite(self.rest_length).all() and (self.rest_length >= 0).all()):
                raise ArgumentValueError("rest_length must be finite and >= 0")
        self._rest = self.rest_length

    def force(self, system: Particles, x: Vectors, vel: Vectors, t: float) -> Vectors:
        """Hooke's law, -k (length - rest length) along each spring, plus the damping
        -c (relative velocity along the spring).

        Parameters
        ----------
        system : Particles
            The system the spring is bound to.
        x, vel : numpy.ndarray (N, dim)
            Positions and velocities.
        t : float
            Time (unused).

        Returns
        -------
        numpy.ndarray (N, dim)
            The forces (zero on particles without a spring).

        Examples
        --------
        A particle 3 from its anchor on a spring of rest length 1 and stiffness 0.5:
        pulled back by 0.5 · 2 = 1.

        >>> import scanline as sl
        >>> spring = sl.animation.Spring([0], 0.5, rest_length=1.0, anchors=[(0, 0)])
        >>> system = sl.animation.Particles([(3, 0)], forces=[spring])
        >>> spring.force(system, system.positions, system.velocities, 0.0).tolist()
        [[-1.0, 0.0]]
        """
        a, b = self._ends(x)
        d = b - a
        length = np.linalg.norm(d, axis=1)
        unit = np.divide(d, length[:, None], out=np.zeros_like(d), where=length[:, None] > 0)
        magnitude = self.stiffness * (length - self.rest_length)
        if self.damping:
            va = vel[self.pairs[:, 0]] if self.anchors is None else vel[self.pairs]
            vb = vel[self.pairs[:, 1]] if self.anchors is None else 0.0
            magnitude = magnitude + self.damping * ((vb - va) * unit).sum(axis=1)
        f = magnitude[:, None] * unit           # pulls a toward b when stretched
        out = np.zeros_like(x)
        if self.anchors is None:
            np.add.at(out, self.pairs[:, 0], f)
            np.add.at(out, self.pairs[:, 1], -f)
        else:
            np.add.at(out, self.pairs, f)
        return out

    def potential(self, system: Particles, x: Vectors) -> float:
        """The energy stored in the springs, Σ k (length - rest length)² / 2.

        Parameters
        ----------
        system : Particles
            The system the spring is bound to.
        x : numpy.ndarray (N, dim)
            Positions.

        Returns
        -------
        float

        Examples
        --------
        >>> import scanline as sl
        >>> spring = sl.animation.Spring([(0, 1)], stiffness=2.0, rest_length=4.0)
        >>> system = sl.animation.Particles([(0, 0), (3, 4)], forces=[spring])
        >>> spring.potential(system, system.positions)      # 2 * 1**2 / 2
        1.0
        """
        a, b = self._ends(x)
        stretch = np.linalg.norm(b - a, axis=1) - self.rest_length
        return float((0.5 * self.stiffness * stretch * stretch).sum())


class Drag:
    """Air resistance: F = -c v (linear) plus -c₂ |v| v (quadratic).  No potential:
    it takes energy out.

    Parameters
    ----------
    linear : float
        c >= 0.
    quadratic : float
        c₂ >= 0.

    Raises
    ------
    ArgumentTypeError
        For a coefficient that is not a number.
    ArgumentValueError
        For a negative or infinite coefficient.

    Examples
    --------
    >>> import scanline as sl
    >>> drag = sl.animation.Drag(linear=0.5, quadratic=0.1)
    >>> drag.linear, drag.quadratic
    (0.5, 0.1)
    """

    def __init__(self, linear: float = 0.1, quadratic: float = 0.0) -> None:
        self.linear = v.number("linear", linear)
        self.quadratic = v.number("quadratic", quadratic)
        if self.linear < 0 or self.quadratic < 0:
            raise ArgumentValueError("drag coefficients must be >= 0")

    def force(self, system: Particles, x: Vectors, vel: Vectors, t: float) -> Vectors:
        """-(c + c₂ |v|) v on each particle.

        Parameters
        ----------
        system : Particles
            The system (unused).
        x, vel : numpy.ndarray (N, dim)
            Positions (unused) and velocities.
        t : float
            Time (unused).

        Returns
        -------
        numpy.ndarray (N, dim)
            The forces.

        Examples
        --------
        At speed 5, c = 0.5 and c₂ = 0.1 make -(0.5 + 0.5) v:

        >>> import scanline as sl
        >>> drag = sl.animation.Drag(linear=0.5, quadratic=0.1)
        >>> system = sl.animation.Particles([(0, 0)], velocities=[(3, 4)], forces=[drag])
        >>> drag.force(system, system.positions, system.velocities, 0.0).tolist()
        [[-3.0, -4.0]]
        """
        speed = np.linalg.norm(vel, axis=1)[:, None]
        out: Vectors = -(self.linear + self.quadratic * speed) * vel
        return out

    def potential(self, system: Particles, x: Vectors) -> float:
        """0: drag has no potential energy.

        Parameters
        ----------
        system : Particles
            The system (unused).
        x : numpy.ndarray (N, dim)
            Positions (unused).

        Returns
        -------
        float
            0.0.

        Examples
        --------
        >>> import scanline as sl
        >>> system = sl.animation.Particles([(0, 0)])
        >>> sl.animation.Drag().potential(system, system.positions)
        0.0
        """
        return 0.0


class Force:
    """Any force: ``function(t, positions, velocities) -> forces`` (arrays (N, dim)).

    ``potential(positions) -> float``, if given, enters :meth:`Particles.energy`.

    Parameters
    ----------
    function : callable
        ``function(t, positions, velocities)``: the forces, an array (N, dim).
    potential : callable, optional
        ``potential(positions)``: the potential energy, a number.

    Raises
    ------
    ArgumentTypeError
        For a ``function`` that is not callable (and, when the system calls it, a
        result that is not numbers).
    ArgumentValueError
        When the system calls them: a force of another shape than the positions, or
        a potential that is not one number.

    Examples
    --------
    A harmonic pull toward the origin, F = -x, with its potential |x|² / 2:

    >>> import scanline as sl
    >>> pull = sl.animation.Force(lambda t, x, v: -x, potential=lambda x: 0.5 * (x ** 2).sum())
    >>> system = sl.animation.Particles([(3, 4)], forces=[pull])
    >>> system.energy()["potential"]
    12.5
    """

    def __init__(self, function: Callable[[float, Vectors, Vectors], ArrayLike],
                 potential: Optional[Callable[[Vectors], ArrayLike]] = None) -> None:
        if not callable(function):
            raise ArgumentTypeError(f"function must be callable, got {v._show(function)}")
        self.function = function
        self._potential = potential

    def force(self, system: Particles, x: Vectors, vel: Vectors, t: float) -> Vectors:
        """``function(t, x, vel)``, checked.

        Parameters
        ----------
        system : Particles
            The system (unused).
        x, vel : numpy.ndarray (N, dim)
            Positions and velocities.
        t : float
            Time.

        Returns
        -------
        numpy.ndarray (N, dim)
            The forces, as floats.

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            For a result that is not numbers, or not of the positions' shape.

        Examples
        --------
        >>> import scanline as sl
        >>> pull = sl.animation.Force(lambda t, x, v: -x)
        >>> system = sl.animation.Particles([(3, 4)], forces=[pull])
        >>> pull.force(system, system.positions, system.velocities, 0.0).tolist()
        [[-3.0, -4.0]]
        """
        f = floats("the force function's result", self.function(t, x, vel),
                   f"forces, one per particle, shape {x.shape}")
        if f.shape != x.shape:
            raise ArgumentValueError(f"the force function returned shape {f.shape}; it must "
                                     f"return one force per particle, shape {x.shape}")
        return f

    def potential(self, system: Particles, x: Vectors) -> float:
        """``potential(x)``, or 0 without one.

        Parameters
        ----------
        system : Particles
            The system (unused).
        x : numpy.ndarray (N, dim)
            Positions.

        Returns
        -------
        float

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            For a result that is not one number.

        Examples
        --------
        >>> import scanline as sl
        >>> pull = sl.animation.Force(lambda t, x, v: -x, potential=lambda x: 0.5 * (x ** 2).sum())
        >>> system = sl.animation.Particles([(3, 4)], forces=[pull])
        >>> pull.potential(system, system.positions)
        12.5
        """
        if self._potential is None:
            return 0.0
        value = floats("the potential function's result", self._potential(x), "a number")
        if value.ndim != 0:
            raise ArgumentValueError(f"the potential function returned shape {value.shape}; "
                                     "it must return one number")
        return float(value)


class Plane:
    """A wall: particles stay on the side its normal points to.

    Parameters
    ----------
    point, normal : vectors
        A point on the plane (a line in 2-D) and its normal (toward the free side).
    restitution : float
        e in [0, 1]: the normal velocity after a bounce is -e times the one before.
    friction : float
        μ >= 0: a bounce removes up to μ times the normal velocity change from the
        tangential velocity (Coulomb friction in impulse form).

    Raises
    ------
    ArgumentTypeError
        For arguments that are not numbers.
    ArgumentValueError
        For a point and normal that are not finite vectors of one dimension, a zero
        normal, a restitution outside [0, 1] or a negative friction.

    Examples
    --------
    A floor, y = 0; the normal is made a unit vector:

    >>> import scanline as sl
    >>> floor = sl.animation.Plane((0, 0), (0, 2), restitution=0.5)
    >>> floor.normal.tolist()
    [0.0, 1.0]
    """

    def __init__(self, point: ArrayLike, normal: ArrayLike, restitution: float = 1.0,
                 friction: float = 0.0) -> None:
        self.point = floats("point", point, "a vector")
        n = floats("normal", normal, "a vector")
        if self.point.shape != n.shape or n.ndim != 1 or not (np.isfinite(n).all()
                                                              and np.isfinite(self.point).all()):
            raise ArgumentValueError("point and normal must be finite vectors of one dimension")
        length = float(np.linalg.norm(n))
        if length == 0:
            raise ArgumentValueError("normal must not be the zero vector")
        self.normal = n / length
        self.restitution = v.number("restitution", restitution)
        if not 0 <= self.restitution <= 1:
            raise ArgumentValueError(f"restitution must lie in [0, 1], got {self.restitution}")
        self.friction = v.number("friction", friction)
        if self.friction < 0:
            raise ArgumentValueError(f"friction must be >= 0, got {self.friction}")

    def collide(self, x: Vectors, vel: Vectors) -> int:
        """Push particles behind the plane back and reflect their normal velocity;
        returns the number of contacts.

        Parameters
        ----------
        x, vel : numpy.ndarray (N, dim)
            Positions and velocities, changed in place.

        Returns
        -------
        int
            The number of particles behind the plane.

        Examples
        --------
        A particle 0.5 below the floor, falling at 2 with e = 0.5: mirrored to
        0.5 · 0.5 = 0.25 above it, rising at 0.5 · 2 = 1.

        >>> import numpy as np
        >>> import scanline as sl
        >>> floor = sl.animation.Plane((0, 0), (0, 1), restitution=0.5)
        >>> x, vel = np.array([[0.0, -0.5]]), np.array([[1.0, -2.0]])
        >>> floor.collide(x, vel), x.tolist(), vel.tolist()
        (1, [[0.0, 0.25]], [[1.0, 1.0]])
        """
        depth = (x - self.point) @ self.normal
        hit = depth < 0
        if not hit.any():
            return 0
        n = self.normal
        vn = vel[hit] @ n
        approaching = vn < 0
        # mirror the penetration, scaled by e: the bounce happened during the step
        x[hit] -= ((1 + self.restitution) * depth[hit])[:, None] * n
        dv = np.where(approaching, -(1 + self.restitution) * vn, 0.0)
        tangential = vel[hit] - vn[:, None] * n
        speed_t = np.linalg.norm(tangential, axis=1)
        cut = np.minimum(self.friction * dv, speed_t)
        tangent_unit = np.divide(tangential, speed_t[:, None], out=np.zeros_like(tangential),
                                 where=speed_t[:, None] > 0)
        vel[hit] += dv[:, None] * n - cut[:, None] * tangent_unit
        return int(hit.sum())


class Particles:
    """A particle system.

    Parameters
    ----------
    positions : array_like (N, dim)
        dim 2 or 3.
    velocities : array_like (N, dim), optional
        Default 0.
    masses : float or sequence of N floats
        > 0.
    forces : sequence
        :class:`Gravity`, :class:`Spring`, :class:`Drag`, :class:`Force` ... (any
        object with ``force(system, x, v, t)`` and ``potential(system, x)``).
    obstacles : sequence of :class:`Plane`

    Attributes
    ----------
    positions, velocities : numpy.ndarray (N, dim)
    time : float
    steps : int
        Steps taken.

    Raises
    ------
    ArgumentTypeError
        For arguments that are not numbers, forces without a ``force`` method, or
        obstacles that are not :class:`Plane` objects.
    ArgumentValueError
        For positions that are not finite 2-D or 3-D points, velocities of another
        shape, masses that are not > 0, or forces and obstacles of another dimension.

    Examples
    --------
    A ball thrown sideways at 3 m/s under g = 10 m/s²:

    >>> import scanline as sl
    >>> ball = sl.animation.Particles([(0, 5)], velocities=[(3, 0)], masses=2,
    ...                               forces=[sl.animation.Gravity((0, -10))])
    >>> ball
    Particles(1 in 2-D, t = 0 s, 1 forces, 0 obstacles)
    """

    def __init__(self, positions: ArrayLike, velocities: ArrayLike | None = None,
                 masses: ArrayLike = 1.0, forces: Sequence[ForceField] = (),
                 obstacles: Sequence[Plane] = ()) -> None:
        self.positions = _vectors("positions", positions, None, None)
        n, dim = self.positions.shape
        if dim not in (2, 3):
            raise ArgumentValueError(f"positions must be 2-D or 3-D points, got dimension {dim}")
        self.dimension = dim
        self.velocities = (np.zeros_like(self.positions) if velocities is None
                           else _vectors("velocities", velocities, n, dim))
        self.masses = _per("masses", masses, n)
        if not (np.isfinite(self.masses).all() and (self.masses > 0).all()):
            raise ArgumentValueError(f"masses must be finite and > 0, got {v._show(masses)}")
        self.forces = _objects("forces", forces)
        for f in self.forces:
            if not hasattr(f, "force"):
                raise ArgumentTypeError(f"forces must be Gravity, Spring, Drag, Force ... "
                                        f"objects, got {v._show(f)}")
            if hasattr(f, "bind"):
                f.bind(self)
            g = getattr(f, "g", None)
            if g is not None and g.shape != (dim,):
                raise ArgumentValueError(f"Gravity g has {g.shape[0]} components; the "
                                         f"particles are {dim}-D")
        self.obstacles = _objects("obstacles", obstacles)
        for p in self.obstacles:
            if not isinstance(p, Plane):
                raise ArgumentTypeError(f"obstacles must be Plane objects, got {v._show(p)}")
            if p.normal.shape != (dim,):
                raise ArgumentValueError(f"a Plane of dimension {p.normal.shape[0]} cannot hold "
                                         f"{dim}-D particles")
        self.time = 0.0
        self.steps = 0
        self.contacts = 0

    def accelerations(self, x: ArrayLike | None = None, vel: ArrayLike | None = None,
                      t: float | None = None) -> Vectors:
        """a = F / m for every particle (F = m a, Newton's second law).

        Parameters
        ----------
        x, vel : array_like (N, dim), optional
            Positions and velocities (default: the system's).
        t : float, optional
            Time (default: the system's).

        Returns
        -------
        numpy.ndarray (N, dim)

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            For ``x`` or ``vel`` that are not finite arrays of the positions' shape, a
            ``t`` that is not a number, or a :class:`Force` whose function fails its
            checks.

        Examples
        --------
        A force of 2 along x on a mass of 4:

        >>> import scanline as sl
        >>> push = sl.animation.Force(lambda t, x, v: [(2, 0)])
        >>> sl.animation.Particles([(0, 0)], masses=4, forces=[push]).accelerations().tolist()
        [[0.5, 0.0]]
        """
        n, dim = self.positions.shape
        xs = self.positions if x is None else _vectors("x", x, n, dim)
        vs = self.velocities if vel is None else _vectors("vel", vel, n, dim)
        time = self.time if t is None else v.number("t", t)
        total = np.zeros_like(xs)
        for f in self.forces:
            total += f.force(self, xs, vs, time)
        return total / self.masses[:, None]

    def step(self, dt: float, method: Method = "verlet") -> Particles:
        """Advance by ``dt`` seconds with ``method``; returns self.

        ``"euler"``: x += v dt, v += a(x) dt (both from the old state; energy grows).
        ``"semi-implicit-euler"``: v += a(x) dt, then x += v dt (symplectic).
        ``"verlet"``: velocity Verlet, x += v dt + a dt²/2, v += (a + a_new) dt / 2
        (symplectic, second order).  ``"rk4"``: classical fourth-order Runge–Kutta.
        Then each :class:`Plane` resolves its collisions.

        Parameters
        ----------
        dt : float
            The time step, seconds, > 0.
        method : {"verlet", "euler", "semi-implicit-euler", "rk4"}
            The integrator.

        Returns
        -------
        Particles
            This system, advanced.

        Raises
        ------
        DynamicsError
            If the state becomes NaN or infinite (too large a step for the stiffness):
            the message names the step and ``dt``.
        ArgumentTypeError, ArgumentValueError
            For a ``dt`` that is not a number > 0, or an unknown ``method``.

        Examples
        --------
        One Verlet step of half a second under g = 10 from rest at 3 m/s sideways:
        x = v dt + g dt² / 2 = (1.5, -1.25), v = (3, -5).

        >>> import scanline as sl
        >>> ball = sl.animation.Particles([(0, 0)], velocities=[(3, 0)],
        ...                               forces=[sl.animation.Gravity((0, -10))])
        >>> ball.step(0.5).positions.tolist(), ball.velocities.tolist(), ball.time
        ([[1.5, -1.25]], [[3.0, -5.0]], 0.5)
        """
        dt = v.number("dt", dt)
        if dt <= 0:
            raise ArgumentValueError(f"dt must be > 0 seconds, got {dt}")
        v.choice("method", method, METHODS)
        x, vel, t = self.positions, self.velocities, self.time
        with np.errstate(all="ignore"):
            if method == "euler":
                a = self.accelerations(x, vel, t)
                x_new, v_new = x + vel * dt, vel + a * dt
            elif method == "semi-implicit-euler":
                v_new = vel + self.accelerations(x, vel, t) * dt
                x_new = x + v_new * dt
            elif method == "verlet":
                a = self.accelerations(x, vel, t)
                x_new = x + vel * dt + 0.5 * a * dt * dt
                # a velocity-dependent force (drag, damping) uses the predicted velocity
                a_new = self.accelerations(x_new, vel + a * dt, t + dt)
                v_new = vel + 0.5 * (a + a_new) * dt
            else:
                k1x, k1v = vel, self.accelerations(x, vel, t)
                k2x = vel + 0.5 * dt * k1v
                k2v = self.accelerations(x + 0.5 * dt * k1x, k2x, t + dt / 2)
                k3x = vel + 0.5 * dt * k2v
                k3v = self.accelerations(x + 0.5 * dt * k2x, k3x, t + dt / 2)
                k4x = vel + dt * k3v
                k4v = self.accelerations(x + dt * k3x, k4x, t + dt)
                x_new = x + dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x)
                v_new = vel + dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)
            for plane in self.obstacles:
                self.contacts += plane.collide(x_new, v_new)
        if not (np.isfinite(x_new).all() and np.isfinite(v_new).all()):
            raise DynamicsError(
                f"the simulation blew up at step {self.steps + 1} (t = {t:g} s): positions or "
                f"velocities became NaN or infinite; use a smaller dt (got {dt:g}), a stabler "
                f"method than {method!r}, or softer springs", self.steps + 1, t)
        self.positions, self.velocities = x_new, v_new
        self.time = t + dt
        self.steps += 1
        return self

    def run(self, duration: float, dt: float, method: Method = "verlet") -> Vectors:
        """Step for ``duration`` seconds; returns the positions after each step,
        (steps + 1, N, dim), the initial state first.

        Parameters
        ----------
        duration : float
            Seconds, >= 0: ``floor(duration / dt)`` steps (a step within 1e-9 of a
            whole number counts).
        dt : float
            The time step, seconds, > 0.
        method : {"verlet", "euler", "semi-implicit-euler", "rk4"}
            The integrator (see :meth:`step`).

        Returns
        -------
        numpy.ndarray (steps + 1, N, dim)
            The positions, the initial ones first.

        Raises
        ------
        DynamicsError
            As :meth:`step`.
        ArgumentTypeError, ArgumentValueError
            For a negative duration, a ``dt`` that is not > 0, more than 2**40 steps,
            or an unknown ``method``.
        MemoryBudgetError
            When the positions of every step would not fit in the memory budget.

        Examples
        --------
        A fall from rest under g = 10, two Verlet steps of 0.5 s (exact for a
        constant force: y = -5 t²):

        >>> import scanline as sl
        >>> ball = sl.animation.Particles([(0, 0)], forces=[sl.animation.Gravity((0, -10))])
        >>> ball.run(1.0, dt=0.5)[:, 0, 1].tolist()
        [0.0, -1.25, -5.0]
        """
        duration = v.number("duration", duration)
        dt = v.number("dt", dt)
        if duration < 0 or dt <= 0:
            raise ArgumentValueError(f"need duration >= 0 and dt > 0, got {duration}, {dt}")
        ratio = duration / dt + 1e-9
        if not ratio < MAX_STEPS:
            raise ArgumentValueError(f"duration / dt = {duration:g} / {dt:g} is {ratio:.3g} "
                                     f"steps, more than {MAX_STEPS:.0e}; use a larger dt")
        steps = int(math.floor(ratio))
        budget((steps + 1) * self.positions.size * 8, "duration",
               f"the positions after each of {steps} steps",
               hint="use a shorter duration or a larger dt, or call step() in a loop and "
                    "keep what you need")
        out = np.empty((steps + 1,) + self.positions.shape)
        out[0] = self.positions
        for i in range(steps):
            out[i + 1] = self.step(dt, method).positions
        return out

    def energy(self) -> Energy:
        """``{"kinetic": ..., "potential": ..., "total": ...}``: ½ Σ m |v|² and the
        forces' potentials (gravity and springs; drag and user forces without a
        potential add none).

        Returns
        -------
        dict
            ``kinetic``, ``potential`` and ``total``, floats.

        Examples
        --------
        Two kilograms 5 m up moving at (3, 4) m/s under g = 10: kinetic
        ½ · 2 · 25 = 25 J, potential 2 · 10 · 5 = 100 J.

        >>> import scanline as sl
        >>> ball = sl.animation.Particles([(0, 5)], velocities=[(3, 4)], masses=2,
        ...                               forces=[sl.animation.Gravity((0, -10))])
        >>> ball.energy()
        {'kinetic': 25.0, 'potential': 100.0, 'total': 125.0}
        """
        kinetic = float(0.5 * (self.masses * (self.velocities ** 2).sum(axis=1)).sum())
        potential = sum(f.potential(self, self.positions) for f in self.forces
                        if hasattr(f, "potential"))
        return {"kinetic": kinetic, "potential": float(potential),
                "total": kinetic + float(potential)}

    def __len__(self) -> int:
        return len(self.positions)

    def __repr__(self) -> str:
        return (f"Particles({len(self)} in {self.dimension}-D, t = {self.time:g} s, "
                f"{len(self.forces)} forces, {len(self.obstacles)} obstacles)")
