"""Blobby objects (Hearn & Baker, section 10-7): surfaces of constant total density
around a set of centers, each center spreading a density that falls off with the
distance r from it.  Where two blobs come close their densities add and the
surfaces flow into each other, as molecules and drops do.

The surface is the level set

    F(p) = sum_k b_k D(r_k / R_k) = T,      r_k = |p - c_k|

of the density functions (one ``kind`` for all blobs):

``"blinn"``      Blinn's Gaussian bumps:  D = exp(-r² / R²)  (never zero; the box
                 is cut where the total cannot reach T)
``"metaball"``   Nishimura et al.'s piecewise quadratic:
                 D = 1 - 3 r²/R² for r <= R/3,  (3/2)(1 - r/R)² for R/3 < r <= R,
                 0 beyond R
``"soft"``       Wyvill, McPheeters and Wyvill's soft objects:
                 D = 1 - 22/9 r²/R² + 17/9 r⁴/R⁴ - 4/9 r⁶/R⁶ for r <= R, 0 beyond
                 (D(R/2) = 1/2)

F is sampled on a grid over the blobs' box and the iso-surface F = T is extracted
by marching cubes (Lorensen & Cline 1987, in scikit-image's Lewiner et al. form:
``skimage.measure.marching_cubes``), then moved from grid indices to space.  The
triangles are counterclockwise seen from outside (where F < T).

References
----------
.. [1] J. F. Blinn, "A generalization of algebraic surface drawing", *ACM
   Transactions on Graphics* 1(3), 1982, pp. 235-256.
.. [2] H. Nishimura, M. Hirai, T. Kawai, T. Kawata, I. Shirakawa and K. Omura,
   "Object modeling by distribution function and a method of image generation",
   *Transactions of the IECE Japan* J68-D(4), 1985 (metaballs).
.. [3] G. Wyvill, C. McPheeters and B. Wyvill, "Data structure for soft objects",
   *The Visual Computer* 2(4), 1986, pp. 227-234.
.. [4] W. E. Lorensen and H. E. Cline, "Marching cubes: a high resolution 3D surface
   construction algorithm", *SIGGRAPH '87*, 1987.
.. [5] D. Hearn and M. P. Baker, *Computer Graphics, C Version*, 2nd ed., 1997,
   section 10-7.
"""

from typing import Callable, Dict, List, Literal, Optional, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._typing import Points
from ..errors import ArgumentValueError
from ..transform3d.arrays import finite, points
from .mesh import Mesh, check_mesh_budget

#: A density function's name.
Kind = Literal["blinn", "metaball", "soft"]
#: The density functions' names.
KINDS: Tuple[Kind, ...] = ("blinn", "metaball", "soft")

#: Largest grid resolution (samples along the longest side).
MAX_RESOLUTION = 1024


def _gaussian(s2: NDArray[np.float64]) -> NDArray[np.float64]:
    return np.exp(-s2)


def _metaball(s2: NDArray[np.float64]) -> NDArray[np.float64]:
    s = np.sqrt(s2)
    return np.where(s <= 1 / 3, 1 - 3 * s2, np.where(s <= 1, 1.5 * (1 - s) ** 2, 0.0))


def _soft(s2: NDArray[np.float64]) -> NDArray[np.float64]:
    return np.where(s2 <= 1, 1 + s2 * (-22 / 9 + s2 * (17 / 9 - 4 / 9 * s2)), 0.0)


_DENSITY: Dict[str, Callable[[NDArray[np.float64]], NDArray[np.float64]]] = {
    "blinn": _gaussian, "metaball": _metaball, "soft": _soft}


def _blobs(centers: object, radii: object, strengths: object
           ) -> Tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    c, _ = points("centers", centers)
    if not len(c):
        raise ArgumentValueError("centers must hold at least one center (x, y, z)")
    r = finite("radii", v.real_array("radii", radii, "(N,)")).reshape(-1)
    if r.size == 1:
        r = np.full(len(c), r[0])
    if r.shape != (len(c),) or (r <= 0).any():
        raise ArgumentValueError(f"radii must be one radius > 0, or one per center "
                                 f"({len(c)}), got {v._show(radii)}")
    if strengths is None:
        b = np.ones(len(c))
    else:
        b = finite("strengths", v.real_array("strengths", strengths, "(N,)")).reshape(-1)
        if b.size == 1:
            b = np.full(len(c), b[0])
        if b.shape != (len(c),):
            raise ArgumentValueError(f"strengths must be one number or one per center "
                                     f"({len(c)}), got {v._show(strengths)}")
    return c, r, b


def density(points_: Points, centers: Points, radii: ArrayLike, kind: Kind = "blinn",
            strengths: Optional[ArrayLike] = None) -> Union[np.float64, NDArray[np.float64]]:
    """The total density F(p) = sum_k b_k D(|p - c_k| / R_k) at each point of
    ``points_`` ((N, 3) or one (3,)); see the module's table for D."""
    kind = v.choice("kind", kind, KINDS)
    c, r, b = _blobs(centers, radii, strengths)
    p, single = points("points", points_)
    total = np.zeros(len(p))
    for ck, rk, bk in zip(c, r, b):
        total += bk * _DENSITY[kind](((p - ck) ** 2).sum(axis=1) / (rk * rk))
    if single:
        first: np.float64 = total[0]
        return first
    return total


def _reach(kind: str, r: NDArray[np.float64], b: NDArray[np.float64],
           threshold: float) -> NDArray[np.float64]:
    """How far from its center each blob can matter: its support (R for the finite
    kernels); for Blinn's Gaussian the distance beyond which even all the blobs'
    strengths together, N max |b|, fall below a hundredth of T."""
    if kind != "blinn":
        return r
    log_ratio = np.log(100.0) + np.log(np.abs(b).max()) + np.log(len(b)) - np.log(threshold)
    reach: NDArray[np.float64] = r * np.sqrt(max(log_ratio, 1.0))
    return reach


def _accumulate(field: NDArray[np.float64], axes: List[NDArray[np.float64]], kind: str,
                c: NDArray[np.float64], r: NDArray[np.float64], b: NDArray[np.float64],
                reach: NDArray[np.float64]) -> None:
    """Add each blob's density to the grid ``field`` (sample coordinates ``axes``),
    over the samples within the blob's reach only."""
    for ck, rk, bk, reach_k in zip(c, r, b, reach):
        box: List[slice] = []
        for i in range(3):
            first = int(np.searchsorted(axes[i], ck[i] - reach_k))
            last = int(np.searchsorted(axes[i], ck[i] + reach_k, side="right"))
            box.append(slice(first, last))
        x, y, z = ((axes[i][box[i]] - ck[i]) / rk for i in range(3))
        s2 = x[:, None, None] ** 2 + y[None, :, None] ** 2 + z[None, None, :] ** 2
        field[tuple(box)] += bk * _DENSITY[kind](s2)


def blobby(centers: Points, radii: ArrayLike, threshold: float = 0.5, resolution: int = 64,
           kind: Kind = "blinn", strengths: Optional[ArrayLike] = None,
           name: Optional[str] = "blobby") -> Mesh:
    """A blobby object as a triangle :class:`~scanline.mesh.Mesh`.

    Parameters
    ----------
    centers : (N, 3) array_like
        The blobs' centers.
    radii : float or (N,) array_like
        Each blob's radius R (> 0): the distance scale of its density.
    threshold : float
        T > 0: the surface is F = T.  An isolated blob is the sphere of the radius
        where b D(r / R) = T: R sqrt(ln(b / T)) for Blinn's, R (1 - sqrt(2T / 3b))
        for a metaball when T <= b / 6, R / 2 for a soft object at T = b / 2.
    resolution : int
        Grid samples along the box's longest side (>= 8); finer grids follow the
        surface closer.
    kind : {"blinn", "metaball", "soft"}
        The density function.
    strengths : float or (N,) array_like, optional
        The blobs' b_k (default 1); a negative one carves.
    name : str, optional
        The mesh's name.

    Returns
    -------
    Mesh
        Triangles counterclockwise seen from outside, with the normals of marching
        cubes (the density's gradient).

    Raises
    ------
    ArgumentValueError
        If there is no center, a radius is not > 0, ``threshold`` is not > 0 or
        above every density on the grid (an empty object), ``resolution`` is
        outside 8 .. :data:`MAX_RESOLUTION`, ``kind`` is unknown, or the sizes
        overflow float64.
    MemoryBudgetError
        If the grid or the mesh would take more memory than the budget allows.

    Notes
    -----
    Hearn & Baker, section 10-7, "blobby objects".

    Examples
    --------
    >>> import scanline as sl
    >>> two = sl.mesh.blobby([(-0.6, 0, 0), (0.6, 0, 0)], 1.0, resolution=24)
    >>> bool(len(two.vertices) > 100), two.polygon_tables().consistent
    (True, True)

    One Blinn blob of R = 1 and b = 1 is the sphere exp(-r²) = T: for T = 1/2 its
    radius is sqrt(ln 2) = 0.8326 (on the grid, to about a hundredth).

    >>> import numpy as np
    >>> one = sl.mesh.blobby([(0, 0, 0)], 1.0, threshold=0.5, resolution=32)
    >>> r = np.linalg.norm(one.vertices, axis=1)
    >>> bool(abs(r.mean() - np.sqrt(np.log(2))) < 0.01), bool(np.ptp(r) < 0.05)
    (True, True)
    """
    from skimage.measure import marching_cubes

    kind = v.choice("kind", kind, KINDS)
    c, r, b = _blobs(centers, radii, strengths)
    threshold = v.number("threshold", threshold)
    if threshold <= 0:
        raise ArgumentValueError(f"threshold must be > 0 (the density of the surface), got "
                                 f"{threshold:g}")
    resolution = v.positive_int("resolution", resolution, minimum=8)
    if resolution > MAX_RESOLUTION:
        raise ArgumentValueError(f"resolution={resolution} is more than the limit of "
                                 f"{MAX_RESOLUTION} samples a side")
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        reach = _reach(kind, r, b, threshold)
        lo = (c - reach[:, None]).min(axis=0)
        hi = (c + reach[:, None]).max(axis=0)
        span = float((hi - lo).max())
    if not (np.isfinite(lo).all() and np.isfinite(hi).all() and np.isfinite(span)):
        raise ArgumentValueError("centers and radii reach beyond float64; use smaller ones")
    step = span / (resolution - 1)
    if not step > 0 or not np.all(np.abs(lo) + step > np.abs(lo)):
        raise ArgumentValueError(
            "radii are too small beside the centers' coordinates: the grid's spacing rounds "
            f"to nothing (radii {v._show(r.tolist())}); use larger radii or centers nearer "
            "the origin")
    shape = np.maximum(np.ceil((hi - lo) / step).astype(np.int64) + 1, 2) + 2   # + a rim
    cells = int(np.prod(shape))
    from .. import budget

    budget.check(cells * 8 * (4 + len(c) // 64), "resolution",
                 f"a density grid of {' x '.join(map(str, shape))} samples",
                 hint="give a smaller resolution")
    origin = lo - step                        # the rim: one sample outside every blob
    axes = [origin[i] + step * np.arange(shape[i]) for i in range(3)]
    field = np.zeros(tuple(shape))
    with np.errstate(over="ignore", invalid="ignore", under="ignore"):
        _accumulate(field, axes, kind, c, r, b, reach)
    if not np.isfinite(field).all():
        raise ArgumentValueError("strengths: the total density overflows float64; use "
                                 "smaller strengths")
    if field.max() < threshold:
        raise ArgumentValueError(
            f"threshold={threshold:g} is above the largest density on the grid "
            f"({field.max():.3g}): the object is empty; give a smaller threshold or larger "
            "strengths")
    field[[0, -1]] = field[:, [0, -1]] = field[:, :, [0, -1]] = min(field.min(), 0.0)
    verts, faces, normals, _ = marching_cubes(field, threshold, spacing=(step,) * 3,
                                              method="lewiner")
    check_mesh_budget("resolution", len(verts), len(faces), 3 * len(faces),
                      "the iso-surface")
    norms = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = np.where(norms > 0, normals / np.where(norms > 0, norms, 1), 0.0)
    return Mesh(verts + origin, faces[:, ::-1].astype(np.int64), normals=normals, name=name)
