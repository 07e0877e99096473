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

from typing import Optional, Sequence, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentValueError

#: A lattice period: one for all three axes, or one per axis (None: not periodic).
Period = Union[int, Sequence[Optional[int]], None]

#: The gradients of improved noise: the twelve directions to the cube's edge middles
#: (and four of them again, so that a 4-bit hash picks one).
GRADIENTS = np.array([[1, 1, 0], [-1, 1, 0], [1, -1, 0], [-1, -1, 0], [1, 0, 1], [-1, 0, 1],
                      [1, 0, -1], [-1, 0, -1], [0, 1, 1], [0, -1, 1], [0, 1, -1], [0, -1, -1],
                      [1, 1, 0], [0, -1, 1], [-1, 1, 0], [0, -1, -1]], np.float64)


def permutation(seed: int) -> NDArray[np.int64]:
    """The hash table: a permutation of 0..255 drawn from ``seed``, repeated twice
    (512 entries, as Perlin's reference code holds it)."""
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise ArgumentValueError(f"seed must be an integer >= 0, got {v._show(seed)}")
    p = np.random.default_rng(int(seed)).permutation(256)
    return np.concatenate([p, p]).astype(np.int64)


def _fade(t: NDArray[np.float64]) -> NDArray[np.float64]:
    return t * t * t * (t * (t * 6 - 15) + 10)


def periods(period: Period) -> Tuple[int, int, int]:
    """``period`` (None, a positive integer, or three, each one or None) as three
    lattice periods (0: none), or an error naming it."""
    if period is None:
        return (0, 0, 0)
    values: Sequence[Optional[int]] = period if isinstance(period, (tuple, list, np.ndarray)) \
        else (period,) * 3
    if len(values) != 3 or not all(
            p is None or isinstance(p, (int, np.integer)) and not isinstance(p, bool)
            and 0 < p <= 2 ** 31 for p in values):
        raise ArgumentValueError(f"period must be a positive whole number of lattice cells "
                                 f"(up to 2**31), or three of them (x, y, z; None: not "
                                 f"periodic along that axis), got {v._show(period)}")
    x, y, z = (0 if p is None else int(p) for p in values)
    return x, y, z


def _wrapped(c: NDArray[np.int64], d: int, p: int) -> NDArray[np.int64]:
    """Lattice coordinate ``c + d`` taken modulo the period ``p`` (0: none), then to
    the hash table's 0..255."""
    return ((c + d) % p if p else c + d) & 255


def noise(points: ArrayLike, seed: int = 0, period: Period = None) -> NDArray[np.float64]:
    """Improved Perlin noise at ``points`` (..., 3) (Perlin 2002): (...) reals in
    about -1..1, 0 at integer points; with ``period`` (a positive integer, or one per
    axis) it repeats: noise(p + period) = noise(p).

    Parameters
    ----------
    points : array_like (..., 3)
        Finite points of space.
    seed : int
        Draws the permutation (the hash table) of the lattice's gradients.
    period : int, three of int or None, or None
        The lattice periods (x, y, z); None: not periodic.

    Returns
    -------
    ndarray (...) float64
        The noise at each point.

    Raises
    ------
    ArgumentValueError
        Points not finite or not (..., 3); a negative seed; a period not a positive
        whole number.

    Notes
    -----
    Hearn & Baker 14-9, "Procedural texturing methods"; the gradients, hash and fade
    of Perlin's improved noise.

    References
    ----------
    Perlin, K. (1985). An image synthesizer. SIGGRAPH '85.
    Perlin, K. (2002). Improving noise. SIGGRAPH '02.

    Examples
    --------
    >>> import numpy as np
    >>> from scanline.texture import noise
    >>> noise([(0, 0, 0), (3, -2, 5)]).tolist()           # 0 at lattice points
    [0.0, 0.0]
    >>> p = np.array([0.3, 1.7, 0.2])
    >>> bool(np.isclose(noise(p, period=4), noise(p + (4, 0, 0), period=4)))
    True
    """
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
    out = np.zeros(p.shape[:-1])
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


def turbulence(points: ArrayLike, octaves: int = 5, seed: int = 0,
               period: Period = None) -> NDArray[np.float64]:
    """Perlin's turbulence (1985): sum over k < ``octaves`` of |noise(2^k p)| / 2^k;
    with ``period``, octave k's noise has the period 2^k ``period``, so the sum
    repeats with ``period``.

    Parameters
    ----------
    points : array_like (..., 3)
        Finite points of space.
    octaves : int
        The number of octaves, 1..16.
    seed : int
        As :func:`noise`'s.
    period : int, three of int or None, or None
        The first octave's lattice periods, as :func:`noise`'s.

    Returns
    -------
    ndarray (...) float64
        The turbulence, >= 0, at each point.

    Raises
    ------
    ArgumentValueError
        ``octaves`` outside 1..16, or as :func:`noise`.

    Examples
    --------
    >>> from scanline.texture import noise, turbulence
    >>> p = [(0.5, 0.25, 0.75)]
    >>> bool(turbulence(p, octaves=1) == abs(noise(p)))    # one octave: |noise(p)|
    True
    >>> turbulence([(2, 3, 4)]).tolist()                  # lattice points: every octave's 0
    [0.0]
    """
    octaves = v.positive_int("octaves", octaves)
    if octaves > 16:
        raise ArgumentValueError(f"octaves must be 1..16, got {octaves}")
    base = periods(period)
    p = np.asarray(points, np.float64)
    total = np.zeros(p.shape[:-1])
    for k in range(octaves):
        total = total + np.abs(noise(p * 2.0 ** k, seed, None if period is None else
                                     tuple(q * 2 ** k or None for q in base))) / 2.0 ** k
    return total
