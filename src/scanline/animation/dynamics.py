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

import math

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError, ScanlineError
from ..budget import check as budget
from ._checks import finite, floats

#: Integration methods.
METHODS = ("euler", "semi-implicit-euler", "verlet", "rk4")

#: The most steps :meth:`Particles.run` takes in one call.
MAX_STEPS = 2**40


def _indices(name, value):
    """Particle numbers: an integer array (numbers that are not whole are refused)."""
    a = floats(name, value, "particle numbers (integers)")
    if not (np.isfinite(a).all() and (a == np.floor(a)).all() and (np.abs(a) < 2**53).all()):
        raise ArgumentValueError(f"{name} must hold particle numbers (whole numbers), got "
                                 f"{v._show(value)}")
    return a.astype(np.int64)


def _per(name, value, count):
    """A number, or one per item (``count``), as a float array of ``count``."""
    a = floats(name, value, f"a number or {count} numbers")
    try:
        return np.broadcast_to(a, (count,)).copy()
    except ValueError:
        raise ArgumentValueError(f"{name} must be one number or {count}, one per item, got "
                                 f"shape {a.shape}") from None


def _objects(name, value):
    if isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
        raise ArgumentTypeError(f"{name} must be a sequence, got {v._show(value)}")
    return list(value)


class DynamicsError(ScanlineError):
    """The simulation blew up: positions or velocities became NaN or infinite.

    Attributes
    ----------
    step : int
        The step (counted from the system's creation) at which it happened.
    time : float
        The simulated time at the start of that step.
    """

    def __init__(self, message, step, time):
        super().__init__(message)
        self.step, self.time = step, time


def _vectors(name, value, count, dim):
    a = floats(name, value, "an array of vectors")
    if a.ndim == 1 and dim is not None and a.shape == (dim,):
        a = np.tile(a, (count, 1))
    if a.ndim != 2 or (count is not None and len(a) != count) or (dim is not None and a.shape[1] != dim):
        want = f"({count if count is not None else 'N'}, {dim if dim is not None else '2 or 3'})"
        raise ArgumentValueError(f"{name} must have shape {want}, got {a.shape}")
    if not np.isfinite(a).all():
        raise ArgumentValueError(f"{name} must be finite, got {v._show(a.tolist())}")
    return a


class Gravity:
    """A uniform field: F = m g.  Potential energy -m g · x."""

    def __init__(self, g=(0.0, -9.81)):
        self.g = floats("g", g, "a vector")
        if self.g.ndim != 1 or not np.isfinite(self.g).all():
            raise ArgumentValueError(f"g must be a finite vector, got {v._show(g)}")

    def force(self, system, x, vel, t):
        return system.masses[:, None] * self.g

    def potential(self, system, x):
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
    """

    def __init__(self, pairs, stiffness, rest_length=None, damping=0.0, anchors=None):
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
        self.rest_length = rest_length

    def _ends(self, x):
        if self.anchors is None:
            return x[self.pairs[:, 0]], x[self.pairs[:, 1]]
        return x[self.pairs], self.anchors

    def bind(self, system):
        n = len(system.positions)
        idx = self.pairs.ravel()
        if idx.size and (idx.min() < 0 or idx.max() >= n):
            raise ArgumentValueError(f"spring pairs name particles 0..{n - 1}, got {idx.tolist()}")
        if self.anchors is not None and self.anchors.shape != (len(self.pairs), system.dimension):
            raise ArgumentValueError(f"anchors must have shape ({len(self.pairs)}, "
                                     f"{system.dimension}), got {self.anchors.shape}")
        if self.rest_length is None:
            a, b = self._ends(system.positions)
            self.rest_length = np.linalg.norm(b - a, axis=1)
        else:
            self.rest_length = _per("rest_length", self.rest_length, len(self.pairs))
            if not (np.isfinite(self.rest_length).all() and (self.rest_length >= 0).all()):
                raise ArgumentValueError("rest_length must be finite and >= 0")

    def force(self, system, x, vel, t):
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

    def potential(self, system, x):
        a, b = self._ends(x)
        stretch = np.linalg.norm(b - a, axis=1) - self.rest_length
        return float((0.5 * self.stiffness * stretch * stretch).sum())


class Drag:
    """Air resistance: F = -c v (linear) plus -c₂ |v| v (quadratic).  No potential:
    it takes energy out."""

    def __init__(self, linear=0.1, quadratic=0.0):
        self.linear = v.number("linear", linear)
        self.quadratic = v.number("quadratic", quadratic)
        if self.linear < 0 or self.quadratic < 0:
            raise ArgumentValueError("drag coefficients must be >= 0")

    def force(self, system, x, vel, t):
        speed = np.linalg.norm(vel, axis=1)[:, None]
        return -(self.linear + self.quadratic * speed) * vel

    def potential(self, system, x):
        return 0.0


class Force:
    """Any force: ``function(t, positions, velocities) -> forces`` (arrays (N, dim)).

    ``potential(positions) -> float``, if given, enters :meth:`Particles.energy`.
    """

    def __init__(self, function, potential=None):
        if not callable(function):
            raise ArgumentTypeError(f"function must be callable, got {v._show(function)}")
        self.function = function
        self._potential = potential

    def force(self, system, x, vel, t):
        f = floats("the force function's result", self.function(t, x, vel),
                   f"forces, one per particle, shape {x.shape}")
        if f.shape != x.shape:
            raise ArgumentValueError(f"the force function returned shape {f.shape}; it must "
                                     f"return one force per particle, shape {x.shape}")
        return f

    def potential(self, system, x):
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
    """

    def __init__(self, point, normal, restitution=1.0, friction=0.0):
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

    def collide(self, x, vel):
        """Push particles behind the plane back and reflect their normal velocity;
        returns the number of contacts."""
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
    """

    def __init__(self, positions, velocities=None, masses=1.0, forces=(), obstacles=()):
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

    def accelerations(self, x=None, vel=None, t=None):
        """a = F / m for every particle (F = m a, Newton's second law)."""
        n, dim = self.positions.shape
        x = self.positions if x is None else _vectors("x", x, n, dim)
        vel = self.velocities if vel is None else _vectors("vel", vel, n, dim)
        t = self.time if t is None else v.number("t", t)
        total = np.zeros_like(x)
        for f in self.forces:
            total += f.force(self, x, vel, t)
        return total / self.masses[:, None]

    def step(self, dt, method="verlet"):
        """Advance by ``dt`` seconds with ``method``; returns self.

        ``"euler"``: x += v dt, v += a(x) dt (both from the old state; energy grows).
        ``"semi-implicit-euler"``: v += a(x) dt, then x += v dt (symplectic).
        ``"verlet"``: velocity Verlet, x += v dt + a dt²/2, v += (a + a_new) dt / 2
        (symplectic, second order).  ``"rk4"``: classical fourth-order Runge–Kutta.
        Then each :class:`Plane` resolves its collisions.

        Raises
        ------
        DynamicsError
            If the state becomes NaN or infinite (too large a step for the stiffness):
            the message names the step and ``dt``.
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

    def run(self, duration, dt, method="verlet"):
        """Step for ``duration`` seconds; returns the positions after each step,
        (steps + 1, N, dim), the initial state first."""
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

    def energy(self):
        """``{"kinetic": ..., "potential": ..., "total": ...}``: ½ Σ m |v|² and the
        forces' potentials (gravity and springs; drag and user forces without a
        potential add none)."""
        kinetic = float(0.5 * (self.masses * (self.velocities ** 2).sum(axis=1)).sum())
        potential = sum(f.potential(self, self.positions) for f in self.forces
                        if hasattr(f, "potential"))
        return {"kinetic": kinetic, "potential": float(potential),
                "total": kinetic + float(potential)}

    def __len__(self):
        return len(self.positions)

    def __repr__(self):
        return (f"Particles({len(self)} in {self.dimension}-D, t = {self.time:g} s, "
                f"{len(self.forces)} forces, {len(self.obstacles)} obstacles)")
