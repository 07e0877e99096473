"""Affine fractals by iterated function systems (Hearn & Baker, section 10-18,
"affine fractal-construction methods"; Barnsley 1988): a set of contracting affine
maps, one chosen at random (with its probability) at each step of the chaos game;
the points visited fill the attractor.

References
----------
.. [1] M. F. Barnsley, *Fractals Everywhere*, Academic Press, 1988, chapter III
   (the fern, table 3.8.3) and the random iteration algorithm.
.. [2] D. Hearn and M. P. Baker, *Computer Graphics, C Version*, 2nd ed., 1997,
   section 10-18.
"""

import numpy as np

from .. import _validate as v
from ..errors import ArgumentValueError
from . import limits

#: Barnsley's fern: four maps (a, b, c, d, e, f): x' = a x + b y + e,
#: y' = c x + d y + f, and their probabilities (Fractals Everywhere, table 3.8.3).
FERN = (np.array([[0.0, 0.0, 0.0, 0.16, 0.0, 0.0],
                  [0.85, 0.04, -0.04, 0.85, 0.0, 1.6],
                  [0.2, -0.26, 0.23, 0.22, 0.0, 1.6],
                  [-0.15, 0.28, 0.26, 0.24, 0.0, 0.44]]),
        np.array([0.01, 0.85, 0.07, 0.07]))

#: The iterations thrown away before points are kept (the orbit reaching the
#: attractor from its start).
SKIP = 20


def ifs(maps, probabilities, n, seed=None, start=(0.0, 0.0)):
    """``n`` points of the attractor of an iterated function system, by the chaos
    game.

    Parameters
    ----------
    maps : (K, 6) array_like
        Each row a, b, c, d, e, f of the map x' = a x + b y + e, y' = c x + d y + f.
    probabilities : (K,) array_like
        The chance of each map at each step (>= 0, summing to 1).
    n : int
        Points kept (after :data:`SKIP` first iterations).
    seed : int or numpy Generator, optional
        The random choices (a seed gives the same points every time).

    Returns
    -------
    ndarray, shape (n, 2)
    """
    from .._kernels import fractals as k
    from .._kernels._jit import call
    from ..transform3d.arrays import finite

    m = finite("maps", v.real_array("maps", maps, "(K, 6)"))
    if m.ndim != 2 or m.shape[1] != 6 or len(m) < 1:
        raise ArgumentValueError(f"maps must be (K, 6): rows a, b, c, d, e, f, got shape "
                                 f"{m.shape}")
    p = finite("probabilities", v.real_array("probabilities", probabilities, "(K,)"))
    if p.shape != (len(m),) or (p < 0).any() or abs(p.sum() - 1) > 1e-9:
        raise ArgumentValueError(f"probabilities must be {len(m)} numbers >= 0 summing to 1, "
                                 f"got {v._show(p.tolist())}")
    n = v.positive_int("n", n)
    limits.points("n", n + SKIP, f"the chaos game of {n:,} points", bytes_per_point=24)
    x0, y0 = v.number("start[0]", start[0]), v.number("start[1]", start[1])
    rng = np.random.default_rng(seed)
    choices = rng.choice(len(m), size=n + SKIP, p=p / p.sum()).astype(np.int64)
    affine = np.ascontiguousarray(m[:, [0, 1, 4, 2, 3, 5]].reshape(-1, 2, 3))
    out = np.empty((n, 2))
    call(k.chaos_game, n + SKIP, affine, choices, x0, y0, SKIP, out)
    return out


def fern(n=50_000, seed=None):
    """Barnsley's fern: ``n`` points of the :data:`FERN` system's attractor."""
    return ifs(*FERN, n, seed=seed)
