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

from typing import Sequence, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

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

#: A seed of numpy's random generator, or the generator.
Seed = Union[int, np.random.Generator, None]

#: The iterations thrown away before points are kept (the orbit reaching the
#: attractor from its start).
SKIP = 20


def ifs(maps: ArrayLike, probabilities: ArrayLike, n: int,
        seed: Seed = None,
        start: Sequence[float] = (0.0, 0.0)) -> NDArray[np.float64]:
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
    start : (float, float)
        The orbit's first point.

    Returns
    -------
    ndarray, shape (n, 2)
        The points visited, in order.

    Raises
    ------
    ArgumentValueError
        Maps not (K, 6), probabilities that are negative or do not sum to 1, or more
        points than the limits allow.

    Examples
    --------
    One map, x' = 1, y' = 2: every point is (1, 2).

    >>> import scanline as sl
    >>> sl.fractals.ifs([(0, 0, 0, 0, 1, 2)], [1.0], 2).tolist()
    [[1.0, 2.0], [1.0, 2.0]]
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


def fern(n: int = 50_000, seed: Seed = None) -> NDArray[np.float64]:
    """Barnsley's fern: ``n`` points of the :data:`FERN` system's attractor.

    Parameters
    ----------
    n : int
        Points kept.
    seed : int or numpy Generator, optional
        The random choices.

    Returns
    -------
    ndarray (n, 2)
        The points (Hearn & Baker 10-18, affine fractal-construction methods).

    Examples
    --------
    The attractor is about 10 units tall, from y = 0 to just below y = 10:

    >>> import scanline as sl
    >>> pts = sl.fractals.fern(1000, seed=0)
    >>> pts.shape, bool((pts[:, 1] >= 0).all() and (pts[:, 1] <= 10).all())
    ((1000, 2), True)
    """
    return ifs(*FERN, n, seed=seed)
