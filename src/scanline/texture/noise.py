"""Perlin's noise: a smooth pseudo-random function of space for procedural textures
(Perlin 1985, "An image synthesizer", SIGGRAPH '85; in its improved form, Perlin
2002, "Improving noise", SIGGRAPH '02; Hearn & Baker 14-9, "Procedural texturing
methods").

At each point of the integer lattice a gradient is chosen by hashing the lattice
coordinates through a permutation of 0..255 (here drawn from ``seed``, so that a
texture is the same on every run); the noise at a point is the interpolation of the
eight corner gradients' dot products with the offsets from the corners, weighted
by the quintic fade 6t^5 - 15t^4 + 10t^3 (2002: continuous second derivatives),
with the twelve cube-edge directions as gradients (2002).  It is 0 at every lattice
point and within about -1..1.  :func:`turbulence` sums octaves, |noise(2^k p)| /
2^k (1985).

**Tileable noise**: with ``period`` (P_x, P_y, P_z) the lattice coordinates are
taken modulo the period before they are hashed, so the gradients -- and with them the
noise -- repeat: noise(p + P_x e_x) = noise(p) (the tiling used by Perlin's own
reference code when its hash is given a repeat, and by texture tools since: a
texture made from one period tiles without seams).  Turbulence doubles the period
with each octave, so the sum has the period of the first.
"""

import numpy as np

from .. import _validate as v
from ..errors import ArgumentValueError

#: The gradients of improved noise: the twelve directions to the cube's edge middles
#: (and four of them again, so that a 4-bit hash picks one).
GRADIENTS = np.array([[1, 1, 0], [-1, 1, 0], [1, -1, 0], [-1, -1, 0], [1, 0, 1], [-1, 0, 1],
                      [1, 0, -1], [-1, 0, -1], [0, 1, 1], [0, -1, 1], [0, 1, -1], [0, -1, -1],
                      [1, 1, 0], [0, -1, 1], [-1, 1, 0], [0, -1, -1]], np.float64)


def permutation(seed):
    """The hash table: a permutation of 0..255 drawn from ``seed``, repeated twice
    (512 entries, as Perlin's reference code holds it)."""
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise ArgumentValueError(f"seed must be an integer >= 0, got {v._show(seed)}")
    p = np.random.default_rng(int(seed)).permutation(256)
    return np.concatenate([p, p]).astype(np.int64)


def _fade(t):
    return t * t * t * (t * (t * 6 - 15) + 10)


def periods(period):
    """``period`` (None, a positive integer, or three, each one or None) as three
    lattice periods (0: none), or an error naming it."""
    if period is None:
        return (0, 0, 0)
    values = period if isinstance(period, (tuple, list, np.ndarray)) else (period,) * 3
    if len(values) != 3 or not all(
            p is None or isinstance(p, (int, np.integer)) and not isinstance(p, bool)
            and 0 < p <= 2 ** 31 for p in values):
        raise ArgumentValueError(f"period must be a positive whole number of lattice cells "
                                 f"(up to 2**31), or three of them (x, y, z; None: not "
                                 f"periodic along that axis), got {v._show(period)}")
    return tuple(0 if p is None else int(p) for p in values)


def _wrapped(c, d, p):
    """Lattice coordinate ``c + d`` taken modulo the period ``p`` (0: none), then to
    the hash table's 0..255."""
    return ((c + d) % p if p else c + d) & 255


def noise(points, seed=0, period=None):
    """Improved Perlin noise at ``points`` (..., 3) (Perlin 2002): (...) reals in
    about -1..1, 0 at integer points; with ``period`` (a positive integer, or one per
    axis) it repeats: noise(p + period) = noise(p)."""
    p = np.asarray(points, np.float64)
    if p.shape[-1:] != (3,) or not np.isfinite(p).all():
        raise ArgumentValueError(f"points must be finite (..., 3) coordinates, got shape "
                                 f"{p.shape}")
    px, py, pz = periods(period)
    perm = permutation(seed)
    cell = np.floor(p)
    f = p - cell
    c = cell.astype(np.int64)
    u = _fade(f)
    x, y, z = c[..., 0], c[..., 1], c[..., 2]
    out = 0.0
    for dx in (0, 1):
        for dy in (0, 1):
            for dz in (0, 1):
                h = perm[perm[perm[_wrapped(x, dx, px)] + _wrapped(y, dy, py)]
                         + _wrapped(z, dz, pz)] & 15
                g = GRADIENTS[h]
                d = ((f[..., 0] - dx) * g[..., 0] + (f[..., 1] - dy) * g[..., 1]
                     + (f[..., 2] - dz) * g[..., 2])
                w = ((u[..., 0] if dx else 1 - u[..., 0]) * (u[..., 1] if dy else 1 - u[..., 1])
                     * (u[..., 2] if dz else 1 - u[..., 2]))
                out = out + w * d
    return out


def turbulence(points, octaves=5, seed=0, period=None):
    """Perlin's turbulence (1985): sum over k < ``octaves`` of |noise(2^k p)| / 2^k;
    with ``period``, octave k's noise has the period 2^k ``period``, so the sum
    repeats with ``period``."""
    octaves = v.positive_int("octaves", octaves)
    if octaves > 16:
        raise ArgumentValueError(f"octaves must be 1..16, got {octaves}")
    base = periods(period)
    p = np.asarray(points, np.float64)
    return sum(np.abs(noise(p * 2.0 ** k, seed, None if period is None else
                            tuple(q * 2 ** k or None for q in base))) / 2.0 ** k
               for k in range(octaves))
