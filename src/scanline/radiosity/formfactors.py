"""Form factors between patches (Hearn & Baker, section 14-7, "radiosity lighting
model"): F_ij, the fraction of the energy leaving patch i that arrives at patch j,

    F_ij = 1 / A_i  integral over A_i, A_j of  cos(theta_i) cos(theta_j) V / (pi r**2) dA_j dA_i

(V = 1 where the two points see each other), approximated from the centre of patch i.

* **hemicube** (Cohen and Greenberg 1985): a half cube of ``resolution`` x
  ``resolution`` cells on the top face (and half that on the four sides) is set on
  the patch; every other patch is projected onto its faces and scan-converted with a
  z-buffer into an item buffer; each cell of the cube carries a *delta form factor*,
  dA / (pi (x**2 + y**2 + 1)**2) on the top and z dA / (pi (y**2 + z**2 + 1)**2) on a
  side, and F_ij is the sum of the delta form factors of the cells where j is seen.
* **ray-casting** (area to differential area; Wallace, Elmquist and Haines 1989):
  ``resolution`` x ``resolution`` points on patch j, each seen or not from the centre
  of i by a shadow ray through a bounding volume hierarchy
  (:class:`scanline.raytrace.BVH`), F_ij = sum of cos cos dA / (pi r**2 + dA).

Progressive refinement (:mod:`scanline.radiosity.solve`) needs, when a
patch shoots, what every other patch receives of it: the hemicube set on the shooter
gives its row, read backward by reciprocity; ray casting gives the column itself,
from each receiver's centre to the shooter's area (Wallace et al.'s way).

References
----------
C. M. Goral, K. E. Torrance, D. P. Greenberg and B. Battaile, "Modeling the
interaction of light between diffuse surfaces", SIGGRAPH '84, 213-222.
M. F. Cohen and D. P. Greenberg, "The hemi-cube: a radiosity solution for complex
environments", SIGGRAPH '85, 31-40.
J. R. Wallace, K. A. Elmquist and E. A. Haines, "A ray tracing algorithm for
progressive radiosity", SIGGRAPH '89, 315-324.
"""

from typing import Any, Optional, Tuple

import numpy as np

from .. import _validate as v
from ..errors import ArgumentValueError
from .patches import Patches, patches

#: The methods of :func:`form_factors`.
METHODS = ("hemicube", "ray-casting")

#: Default resolution: hemicube cells per side of the top face; ray-casting sample
#: points per side of a patch.
RESOLUTION = {"hemicube": 100, "ray-casting": 4}

#: Largest resolution of each method.
MAX_RESOLUTION = {"hemicube": 2048, "ray-casting": 64}


def as_patches(meshes: Any, subdivisions: int = 8) -> Patches:
    """``meshes`` subdivided (:func:`~scanline.radiosity.patches.patches`), or the
    :class:`Patches` given."""
    if not isinstance(meshes, Patches):
        return patches(meshes, subdivisions)
    meshes.check()
    return meshes


def delta_form_factors(resolution: int) -> Tuple[np.ndarray, np.ndarray]:
    """The hemicube's delta form factors (Cohen and Greenberg 1985, section 4): the top
    face (res, res), rows from y = -1 up, and a side face (res / 2, res), rows from the
    patch's plane (z = 0) up; a cell of side 2 / res at (x, y) on the top holds
    dA / (pi (x**2 + y**2 + 1)**2), at (y, z) on a side z dA / (pi (y**2 + z**2 + 1)**2).
    Together they add up to 1 (less the cells' discretization error).

    Parameters
    ----------
    resolution : int
        Cells per side of the top face (even).

    Returns
    -------
    top : ndarray (resolution, resolution)
        The top face's delta form factors.
    side : ndarray (resolution / 2, resolution)
        One side face's.

    Examples
    --------
    Two cells a side: each top cell, centred at (+-1/2, +-1/2), holds 1 / (pi 1.5^2)
    = 0.141471; a side cell at height 1/2 half that.

    >>> import scanline as sl
    >>> top, side = sl.radiosity.delta_form_factors(2)
    >>> top.round(6).tolist(), side.round(6).tolist()
    ([[0.141471, 0.141471], [0.141471, 0.141471]], [[0.070736, 0.070736]])
    """
    res = resolution
    c = (np.arange(res) + 0.5) / (res / 2) - 1.0
    da = (2.0 / res) ** 2
    top = da / (np.pi * (c[None, :] ** 2 + c[:, None] ** 2 + 1.0) ** 2)
    z = c[res // 2:]
    side = z[:, None] * da / (np.pi * (c[None, :] ** 2 + z[:, None] ** 2 + 1.0) ** 2)
    return np.ascontiguousarray(top), np.ascontiguousarray(side)


def check_resolution(method: str, resolution: Optional[int]) -> int:
    """``resolution`` checked for ``method`` (None: its default)."""
    if resolution is None:
        return RESOLUTION[method]
    res = v.positive_int("resolution", resolution, 2 if method == "hemicube" else 1)
    if res > MAX_RESOLUTION[method]:
        raise ArgumentValueError(f"resolution must be at most {MAX_RESOLUTION[method]} for "
                                 f"method={method!r}, got {res}")
    if method == "hemicube" and res % 2:
        raise ArgumentValueError(f"resolution of a hemicube must be even (its sides are half "
                                 f"cubes of resolution / 2 rows), got {res}")
    return res


class RowSource:
    """Rows of the form-factor matrix of ``patches`` on demand, by ``method`` at
    ``resolution``; and what a group of patches (``group``, a number per patch,
    :meth:`Patches.groups`; default each patch alone) sends to every patch when it
    shoots (:meth:`received`, for the progressive solution)."""

    def __init__(self, patches: Patches, method: str = "hemicube",
                 resolution: Optional[int] = None, group: Optional[np.ndarray] = None):
        self.method = v.choice("method", method, METHODS)
        self.resolution = check_resolution(self.method, resolution)
        self.patches = patches
        self.quads = v.kernel_array(patches.quads)
        self.centre = v.kernel_array(patches.centre)
        self.normal = v.kernel_array(patches.normal)
        self.edge = v.kernel_array(self.quads[:, 1] - self.quads[:, 0])
        self.alone = np.arange(len(patches), dtype=np.int64)
        self.group = self.alone if group is None else v.kernel_array(group, np.int64)
        # each group's area, centroid, mean normal and first patch's edge
        count = int(self.group.max()) + 1
        area = patches.area
        self.group_area = np.bincount(self.group, area, count)
        weighted = [np.bincount(self.group, area * x, count) for x in
                    (*self.centre.T, *self.normal.T)]
        self.group_centre = v.kernel_array(np.stack(weighted[:3], 1) / self.group_area[:, None])
        n = np.stack(weighted[3:], 1)
        self.group_normal = v.kernel_array(n / np.sqrt((n * n).sum(axis=1))[:, None])
        first = np.full(count, len(patches))
        np.minimum.at(first, self.group, self.alone)
        self.group_edge = v.kernel_array(self.edge[first])
        size = float(np.ptp(patches.vertices, axis=0).max())
        self.near = 1e-9 * size
        if self.method == "hemicube":
            self.top, self.side = delta_form_factors(self.resolution)
        else:
            from ..raytrace import BVH

            self.tree = BVH(patches.triangles())
            self.clear = np.zeros(len(self.tree))

    def rows(self, sources: Any, columns: bool = False) -> np.ndarray:
        """The rows ``sources`` (patch numbers), (len(sources), P), in parallel; with
        ``columns`` (ray casting only) the columns instead: F_ji for every j, from the
        centre of each patch j to the whole of patch i."""
        from .._kernels._threads import call_in_bands
        from .._kernels import formfactors as k

        src = np.ascontiguousarray(sources, np.int64).reshape(-1)
        p = len(self.patches)
        out = np.zeros((len(src), p))
        if self.method == "hemicube":
            res = self.resolution
            call_in_bands(k.hemicube_rows, len(src) * (60 * p + 4 * res * res), src,
                          self.centre, self.normal, self.edge, self.alone, self.quads,
                          self.centre, self.normal, self.near, res, self.top, self.side, out)
        else:
            t = self.tree
            call_in_bands(k.raycast_rows, len(src) * p * self.resolution ** 2 * 40, src,
                          self.quads, self.centre, self.normal, self.resolution, t.bounds,
                          t.links, t.table, self.clear, bool(columns), out)
        return out

    def received(self, g: int) -> np.ndarray:
        """What each patch j receives of the energy group ``g`` shoots, per unit of j's
        area and of the group's radiosity: F_jg.  Ray casting casts it directly (from
        each receiver's centre to the group's patches, Wallace et al. 1989); the
        hemicube, set at the group's centroid, gives its row, and reciprocity F_jg =
        F_gj A_g / A_j (Cohen et al. 1988).  One hemicube runs serially (a parallel
        loop's start would cost more than it saves)."""
        from .._kernels._jit import call
        from .._kernels import formfactors as k

        if self.method == "ray-casting":
            summed: np.ndarray = self.rows(np.flatnonzero(self.group == g),
                                           columns=True).sum(axis=0)
            return summed
        p = len(self.patches)
        row = np.zeros((1, p))
        res = self.resolution
        call(k.hemicube_rows, 60 * p + 4 * res * res, 0, 1, np.array([g], np.int64),
             self.group_centre, self.group_normal, self.group_edge, self.group, self.quads,
             self.centre, self.normal, self.near, res, self.top, self.side, row)
        received: np.ndarray = row[0] * self.group_area[g] / self.patches.area
        return received


def check_matrix_budget(n: int, copies: int = 1) -> None:
    """Refuse, before it is allocated, an n x n matrix (``copies`` of it) past the
    memory budget (:mod:`scanline.budget`)."""
    from ..budget import check

    check(8 * n * n * copies, "meshes", f"a {n:,} x {n:,} form-factor matrix",
          "give fewer faces or a smaller subdivisions, or use method='progressive' "
          "(one row at a time)")


def form_factors(meshes: Any, subdivisions: int = 8, method: str = "hemicube",
                 resolution: Optional[int] = None) -> np.ndarray:
    """The form factors F_ij between the patches of ``meshes``.

    Parameters
    ----------
    meshes : Mesh, list of Mesh, or Patches
        Subdivided by :func:`~scanline.radiosity.patches.patches` (each face into
        ``subdivisions`` x ``subdivisions`` patches); :class:`Patches` as they are.
    subdivisions : int
    method : {"hemicube", "ray-casting"}
    resolution : int, optional
        Hemicube: cells per side of the top face (even; default 100).  Ray casting:
        sample points per side of each receiving patch (default 4).

    Returns
    -------
    ndarray (P, P)
        Row i: the fraction of the energy leaving patch i that reaches each patch j.
        In a closed room every row adds up to 1, and A_i F_ij = A_j F_ji
        (reciprocity), both up to the method's discretization.

    Raises
    ------
    ArgumentValueError
        An unknown ``method``.

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> cube = sl.mesh.cube(2.0)
    >>> room = sl.mesh.Mesh(cube.vertices, cube.faces[:, ::-1])      # the faces turned inward
    >>> f = sl.radiosity.form_factors(room, subdivisions=1, resolution=64)
    >>> f.shape, round(float(f[0].sum()), 3)          # a closed room: every row adds up to 1
    ((6, 6), 1.0)
    >>> round(float(f[0, 1]), 2)       # from the centre of a face to the opposite face
    0.24
    """
    method = v.choice("method", method, METHODS)
    res = check_resolution(method, resolution)
    pts = as_patches(meshes, subdivisions)
    check_matrix_budget(len(pts))
    return RowSource(pts, method, res).rows(np.arange(len(pts)))
