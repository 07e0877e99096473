"""Random fractals for terrain (Hearn & Baker, section 10-18, "random midpoint-
displacement methods"; Fournier, Fussell and Carpenter 1982): fractional Brownian
motion with the roughness parameter H (0 < H < 1; the surface's dimension is
3 - H, a profile's 2 - H), by random midpoint displacement and by spectral
synthesis, and the height field as a :class:`~scanline.mesh.Mesh`.

Fractional Brownian motion has increments X(t + d) - X(t) with mean 0 and variance
proportional to d^(2H): small H gives rough, jagged terrain, H near 1 smooth hills.

Midpoint displacement builds it coarse to fine: each new midpoint is the mean of
its neighbors plus a Gaussian displacement whose standard deviation halves as
2^(-H) per halving of the spacing (Voss's form: σ_k = σ 2^(-kH) sqrt(1 - 2^(2H-2))
along a line, so that the midpoints' increments have the variance of fBm; on a
grid, the diamond-square steps each shrink the spacing by sqrt 2 and σ by 2^(-H/2)).
Spectral synthesis filters white noise: amplitudes f^-(H + 1) in two dimensions
(the spectral density of fBm, f^-(2H + 2)), then an inverse FFT.

Every generator takes a ``seed``: the same seed gives the same terrain.

References
----------
.. [1] A. Fournier, D. Fussell and L. Carpenter, "Computer rendering of stochastic
   models", *Communications of the ACM* 25(6), 1982, pp. 371-384.
.. [2] R. F. Voss, "Fractals in nature: from characterization to simulation", in
   H.-O. Peitgen and D. Saupe (eds.), *The Science of Fractal Images*, Springer,
   1988, chapter 1 (MidPointFM1D, MidPointFM2D, SpectralSynthesisFM2D).
.. [3] D. Hearn and M. P. Baker, *Computer Graphics, C Version*, 2nd ed., 1997,
   section 10-18.
"""

from typing import TYPE_CHECKING, Tuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from . import limits
from .ifs import Seed

if TYPE_CHECKING:
    from ..mesh.mesh import Mesh

#: The most levels of a grid (2^levels + 1 samples a side).
MAX_LEVELS = 24


def _roughness(H: float) -> float:
    h = v.number("H", H)
    if not 0 < h < 1:
        raise ArgumentValueError(f"H must lie strictly between 0 and 1 (the roughness: "
                                 f"0.2 jagged, 0.8 smooth), got {h:g}")
    return h


def _levels(levels: int, dimensions: int) -> Tuple[int, int]:
    count = v.positive_int("levels", levels)
    if count > MAX_LEVELS:
        raise ArgumentValueError(f"levels={count} is more than the limit of {MAX_LEVELS}")
    side = (1 << count) + 1
    limits.points("levels", side ** dimensions, f"levels={count} ({side} samples a side)",
                  bytes_per_point=8 * 4)
    return count, side


def midpoint_profile(levels: int, H: float = 0.5, seed: Seed = None,
                     sigma: float = 1.0) -> NDArray[np.float64]:
    """A 1-D fBm profile of 2^levels + 1 samples over t in [0, 1] by random midpoint
    displacement (Voss's MidPointFM1D): X(0) = 0, X(1) ~ N(0, σ²), and at level k
    each new midpoint is the mean of its two ends plus N(0, σ_k²) with
    σ_k² = σ² 2^(-2kH) (1 - 2^(2H - 2)), so that Var(X(t + d) - X(t)) = σ² d^(2H)
    for the spacings d = 2^-k.

    Parameters
    ----------
    levels : int
        Halvings of [0, 1], 1..:data:`MAX_LEVELS`.
    H : float
        The roughness, 0 < H < 1 (the profile's dimension is 2 - H).
    seed : int or numpy Generator, optional
        The random displacements.
    sigma : float
        The standard deviation σ of X(1).

    Returns
    -------
    ndarray (2^levels + 1,)
        X at t = 0, 2^-levels, ..., 1.

    Raises
    ------
    ArgumentValueError
        H outside (0, 1), or levels outside 1..MAX_LEVELS or past the limits.

    Examples
    --------
    >>> import scanline as sl
    >>> x = sl.fractals.midpoint_profile(3, seed=0)
    >>> len(x), float(x[0])                      # 2^3 + 1 samples, X(0) = 0
    (9, 0.0)
    >>> bool((sl.fractals.midpoint_profile(2, sigma=0.0) == 0).all())   # no displacement
    True
    """
    H = _roughness(H)
    sigma = v.number("sigma", sigma)
    levels, n = _levels(levels, 1)
    rng = np.random.default_rng(seed)
    x = np.zeros(n)
    x[-1] = sigma * rng.standard_normal()
    factor = np.sqrt(1 - 2.0 ** (2 * H - 2))
    step = n - 1
    for k in range(1, levels + 1):
        half = step // 2
        mids = slice(half, n - 1, step)
        x[mids] = 0.5 * (x[0:n - 1:step] + x[step::step]) + \
            sigma * 2.0 ** (-k * H) * factor * rng.standard_normal(len(x[mids]))
        step = half
    return x


def _diamond_sums(s: NDArray[np.float64]
                  ) -> Tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Each cell's sum and count of its four edge neighbors in the grid ``s`` (those
    inside it)."""
    total = np.zeros_like(s)
    count = np.zeros_like(s)
    total[1:] += s[:-1]
    count[1:] += 1
    total[:-1] += s[1:]
    count[:-1] += 1
    total[:, 1:] += s[:, :-1]
    count[:, 1:] += 1
    total[:, :-1] += s[:, 1:]
    count[:, :-1] += 1
    return total, count


def midpoint_displacement(levels: int, H: float = 0.5, seed: Seed = None,
                          sigma: float = 1.0) -> NDArray[np.float64]:
    """A fBm height field of (2^levels + 1)² samples by random midpoint displacement
    on a square grid (Fournier, Fussell & Carpenter's method in the diamond-square
    form): the four corners ~ N(0, σ²); then per level, each square's center is the
    mean of its corners plus a displacement (the square step), and each edge's
    midpoint the mean of its (three or four) neighbors plus a displacement (the
    diamond step); σ shrinks by 2^(-H/2) at every step.

    Parameters
    ----------
    levels : int
        Halvings of the square's side, 1..:data:`MAX_LEVELS`.
    H : float
        The roughness, 0 < H < 1 (the surface's dimension is 3 - H).
    seed : int or numpy Generator, optional
        The random displacements.
    sigma : float
        The corners' standard deviation σ.

    Returns
    -------
    ndarray, shape (2^levels + 1, 2^levels + 1)
        z[row, column]; row and column run along y and x.

    Raises
    ------
    ArgumentValueError
        H outside (0, 1), or levels outside 1..MAX_LEVELS or past the limits.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.fractals.midpoint_displacement(2, seed=0).shape
    (5, 5)
    >>> bool((sl.fractals.midpoint_displacement(2, sigma=0.0) == 0).all())   # flat
    True
    """
    H = _roughness(H)
    sigma = v.number("sigma", sigma)
    levels, n = _levels(levels, 2)
    rng = np.random.default_rng(seed)
    z = np.zeros((n, n))
    z[::n - 1, ::n - 1] = sigma * rng.standard_normal((2, 2))
    shrink = 2.0 ** (-H / 2)
    delta = sigma
    step = n - 1
    while step > 1:
        half = step // 2
        delta *= shrink
        corners = (z[0:-1:step, 0:-1:step] + z[step::step, 0:-1:step]
                   + z[0:-1:step, step::step] + z[step::step, step::step])
        z[half::step, half::step] = corners / 4 + delta * rng.standard_normal(corners.shape)
        delta *= shrink
        grid = z[::half, ::half]
        total, count = _diamond_sums(grid)
        i, j = np.indices(grid.shape)
        odd = (i + j) % 2 == 1
        grid[odd] = total[odd] / count[odd] + delta * rng.standard_normal(int(odd.sum()))
        step = half
    return z


def fbm_surface(levels: int, H: float = 0.5, seed: Seed = None,
                sigma: float = 1.0) -> NDArray[np.float64]:
    """A fBm height field of (2^levels)² samples by spectral synthesis (Voss's
    SpectralSynthesisFM2D): Gaussian Fourier coefficients with amplitude
    f^-(H + 1), random phases, the zero frequency removed, an inverse FFT; scaled to
    standard deviation ``sigma``.  The surface is periodic (its edges meet).

    Parameters
    ----------
    levels : int
        log2 of the samples a side, 1..:data:`MAX_LEVELS`.
    H : float
        The roughness, 0 < H < 1.
    seed : int or numpy Generator, optional
        The random coefficients.
    sigma : float
        The surface's standard deviation.

    Returns
    -------
    ndarray, shape (2^levels, 2^levels)
        z[row, column].

    Raises
    ------
    ArgumentValueError
        H outside (0, 1), or levels outside 1..MAX_LEVELS or past the limits.

    Examples
    --------
    The zero frequency removed, the mean is 0; the standard deviation is sigma:

    >>> import scanline as sl
    >>> z = sl.fractals.fbm_surface(3, seed=0, sigma=2.0)
    >>> z.shape, round(float(z.std()), 9), abs(float(z.mean())) < 1e-12
    ((8, 8), 2.0, True)
    """
    H = _roughness(H)
    sigma = v.number("sigma", sigma)
    count = v.positive_int("levels", levels)
    if count > MAX_LEVELS:
        raise ArgumentValueError(f"levels={count} is more than the limit of {MAX_LEVELS}")
    n = 1 << count
    limits.points("levels", n * n, f"levels={count} ({n} samples a side)",
                  bytes_per_point=16 * 5)
    rng = np.random.default_rng(seed)
    fx = np.fft.fftfreq(n)[:, None]
    fy = np.fft.rfftfreq(n)[None, :]
    f = np.hypot(fx, fy)
    f[0, 0] = 1.0
    amplitude = f ** -(H + 1)
    amplitude[0, 0] = 0.0
    coefficients = amplitude * (rng.standard_normal(f.shape) + 1j * rng.standard_normal(f.shape))
    z: NDArray[np.float64] = np.fft.irfft2(coefficients, s=(n, n))
    spread = z.std()
    return z * (sigma / spread) if spread > 0 else z


def height_field(z: ArrayLike, size: float = 1.0, height: float = 1.0,
                 name: str = "terrain") -> "Mesh":
    """The height field ``z`` (rows along y, columns along x) as a triangle
    :class:`~scanline.mesh.Mesh`: vertex (x, y, height z) over the square
    [0, size]², two triangles per grid cell, counterclockwise seen from above.

    Parameters
    ----------
    z : array_like (rows, columns)
        Finite heights, at least 2 x 2.
    size : float
        The side of the square the longer side of the grid spans.
    height : float
        The factor of the heights.
    name : str
        The mesh's name.

    Returns
    -------
    Mesh
        rows x columns vertices, 2 (rows - 1) (columns - 1) triangles.

    Raises
    ------
    ArgumentValueError
        A grid smaller than 2 x 2, or non-finite heights.

    Examples
    --------
    >>> import scanline as sl
    >>> mesh = sl.fractals.height_field([[0, 1], [2, 3]], size=2.0)
    >>> mesh.vertices.tolist()
    [[0.0, 0.0, 0.0], [2.0, 0.0, 1.0], [0.0, 2.0, 2.0], [2.0, 2.0, 3.0]]
    >>> mesh.face_count
    2
    """
    from ..curves.surfaces import grid_triangles
    from ..mesh.mesh import Mesh, check_mesh_budget
    from ..transform3d.arrays import finite

    a = finite("z", v.real_array("z", z, "(rows, columns)"))
    if a.ndim != 2 or min(a.shape) < 2:
        raise ArgumentValueError(f"z must be a 2-D grid of at least 2 x 2 heights, got shape "
                                 f"{a.shape}")
    side, factor = v.number("size", size), v.number("height", height)
    rows, cols = a.shape
    check_mesh_budget("z", rows * cols, 2 * (rows - 1) * (cols - 1),
                      6 * (rows - 1) * (cols - 1), f"a {rows} x {cols} height field")
    scale = side / (max(rows, cols) - 1)
    x, y = np.meshgrid(np.arange(cols) * scale, np.arange(rows) * scale, indexing="xy")
    vertices = np.stack([x.ravel(), y.ravel(), factor * a.ravel()], axis=1)
    # grid_triangles indexes (nu + 1) x (nv + 1) vertices u-major: u = row, v = column
    faces = grid_triangles(rows - 1, cols - 1)
    return Mesh(vertices, faces[:, ::-1], name=name)


def terrain(levels: int = 6, H: float = 0.7, seed: Seed = None, method: str = "midpoint",
            size: float = 1.0, height: float = 0.3) -> "Mesh":
    """A fractal terrain Mesh: :func:`midpoint_displacement` (``method="midpoint"``)
    or :func:`fbm_surface` (``"spectral"``) as a :func:`height_field`, heights scaled
    to ``height`` times their standard deviation over the square [0, size]².

    Parameters
    ----------
    levels : int
        As the generator takes them.
    H : float
        The roughness, 0 < H < 1.
    seed : int or numpy Generator, optional
        The random numbers.
    method : {"midpoint", "spectral"}
        The generator.
    size : float
        The square's side.
    height : float
        The heights' standard deviation.

    Returns
    -------
    Mesh
        The terrain.

    Raises
    ------
    ArgumentValueError
        An unknown method, or as the generator.

    Examples
    --------
    Three levels: 9 x 9 vertices, 2 x 8 x 8 triangles.

    >>> import scanline as sl
    >>> sl.fractals.terrain(3, seed=1)
    <Mesh 'terrain': 81 vertices, 128 faces, 208 edges>
    """
    method = v.choice("method", method, ("midpoint", "spectral"))
    z = (midpoint_displacement if method == "midpoint" else fbm_surface)(levels, H, seed)
    return height_field(z / (z.std() or 1.0), size=size, height=height)
