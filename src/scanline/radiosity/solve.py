"""The radiosity equations and their two solutions (Hearn & Baker, section 14-7):

    B_i = E_i + rho_i  sum_j  F_ij B_j          (Goral et al. 1984)

per RGB channel, B the radiosity (light leaving a patch per unit area), E the
emission, rho the reflectance, F the form factors
(:mod:`scanline.radiosity.formfactors`).

* ``method="gauss-seidel"``: the full matrix of form factors, then Gauss-Seidel
  sweeps of the system (I - rho F) B = E until no B_i changes by more than
  ``tolerance`` x the largest reflected radiosity B - E (Cohen and Greenberg 1985,
  section 2; the matrix is diagonally dominant since rho < 1 and each row of F adds
  up to at most 1, so the sweeps converge).
* ``method="progressive"``: progressive refinement by shooting (Cohen, Chen, Wallace
  and Greenberg 1988): the patch with the most unshot energy dB_i A_i shoots it,
  every patch j receiving rho_j dB_i F_ji, computed when i shoots: by the shooter's
  own hemicube and reciprocity, F_ji = F_ij A_i / A_j, or by rays from each
  receiver to the shooter (area to differential area, Wallace, Elmquist and Haines
  1989); with a matrix given, its column i.  Until the unshot energy is below
  ``tolerance`` x the emitted energy.  Each estimate is displayed with the *ambient
  term* rho_j x ambient, ambient = R sum_j dB_j A_j / sum_j A_j, R = 1 / (1 -
  rho_avg), the area-weighted mean reflectance (section 3.4 of the paper), so the
  first images are already about as bright as the last.

The nodes (patch corners) take the mean radiosity of the patches around them, and
Gouraud shading interpolates those across the patches (Cohen and Greenberg 1985,
section 5): :meth:`Radiosity.render`.

References
----------
M. F. Cohen, S. E. Chen, J. R. Wallace and D. P. Greenberg, "A progressive
refinement approach to fast radiosity image generation", SIGGRAPH '88, 75-84.
"""

from dataclasses import dataclass
from typing import Any, Optional, Union

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from .formfactors import METHODS as FORM_FACTOR_METHODS
from .formfactors import RowSource, as_patches, check_matrix_budget, check_resolution
from .patches import Patches

#: The methods of :func:`solve`.
METHODS = ("gauss-seidel", "progressive")

#: Default most iterations: Gauss-Seidel sweeps; shots per patch of the progressive
#: solution.
MAX_SWEEPS = 1000
SHOTS_PER_PATCH = 20


@dataclass(frozen=True)
class Radiosity:
    """The solution of the radiosity equations (Hearn & Baker 14-7): made by
    :func:`solve`.

    Parameters
    ----------
    patches, radiosity, vertex_radiosity, ambient, method, history, power, converged, form_factors
        The values listed under Attributes.

    Attributes
    ----------
    patches : Patches
    radiosity : ndarray (P, 3)
        B per patch and RGB channel (progressive: with the ambient term).
    vertex_radiosity : ndarray (V, 3)
        The mean of the patches around each node (``patches.vertices``).
    ambient : ndarray (3,)
        The progressive solution's ambient term (zero for Gauss-Seidel).
    method : str
    history : ndarray
        The convergence measure after each iteration: Gauss-Seidel, the largest change
        of a B_i in the sweep over the largest B - E; progressive, the unshot energy over
        the emitted energy.
    power : ndarray
        sum_i A_i B_i (the three channels added, without the ambient term) after each
        iteration: the energy leaving the surfaces found so far.
    converged : bool
        Whether ``history`` reached the tolerance within the iterations allowed.
    form_factors : ndarray (P, P) or None
        The matrix (Gauss-Seidel), None for the progressive solution (whose rows are
        made as patches shoot and not kept).

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> cube = sl.mesh.cube(2.0)
    >>> room = sl.mesh.Mesh(cube.vertices, cube.faces[:, ::-1])     # faces turned inward
    >>> e = np.zeros((6, 3)); e[5] = 1.0                            # the ceiling glows
    >>> s = sl.radiosity.solve(room, emission=e, reflectance=0.5, subdivisions=1)
    >>> s
    <Radiosity gauss-seidel: 6 patches, 9 iterations, converged>
    """
    patches: Patches
    radiosity: np.ndarray
    vertex_radiosity: np.ndarray
    ambient: np.ndarray
    method: str
    history: np.ndarray
    power: np.ndarray
    converged: bool
    form_factors: Optional[np.ndarray]

    @property
    def iterations(self) -> int:
        """The iterations made: Gauss-Seidel sweeps or progressive shots."""
        return len(self.history)

    def mesh(self, exposure: Optional[float] = None, gamma: float = 2.2) -> Any:
        """The patches as one :class:`~scanline.mesh.Mesh` with the node radiosities as
        vertex colors: B x ``exposure`` clipped to 0..1 and encoded with ``gamma``
        (the render decodes them back to linear light).  Default exposure: the
        brightest patch that emits nothing shows white.

        Parameters
        ----------
        exposure : float, optional
            The factor of B, positive and finite.
        gamma : float
            The display gamma the colors are encoded with.

        Returns
        -------
        Mesh
            One face per patch, colored at its nodes.

        Raises
        ------
        ArgumentValueError
            An exposure that is not positive and finite.

        Examples
        --------
        >>> import numpy as np, scanline as sl
        >>> cube = sl.mesh.cube(2.0)
        >>> room = sl.mesh.Mesh(cube.vertices, cube.faces[:, ::-1])     # faces turned inward
        >>> e = np.zeros((6, 3)); e[5] = 1.0                            # the ceiling glows
        >>> s = sl.radiosity.solve(room, emission=e, reflectance=0.5, subdivisions=1)
        >>> s.mesh()
        <Mesh 'radiosity': 24 vertices, 6 faces, 24 edges>
        """
        from ..mesh import Mesh
        from ..mesh.mesh import Flat
        from ..shading import encode

        pts = self.patches
        if exposure is None:
            lit = pts.emission.max(axis=1) <= 0
            top = float(self.radiosity[lit].max()) if lit.any() else 0.0
            exposure = 1.0 / top if top > 0 else 1.0
        x = v.number("exposure", exposure)
        if not 0 < x < np.inf:
            raise ArgumentValueError(f"exposure must be a positive finite number, got "
                                     f"{exposure!r}")
        tri = pts.corners[:, 3] == pts.corners[:, 2]
        sizes = np.where(tri, 3, 4)
        keep = np.ones(pts.corners.shape, bool)
        keep[:, 3] = ~tri
        colors = encode(self.vertex_radiosity * x, gamma)
        return Mesh(pts.vertices, Flat(pts.corners[keep], sizes), colors=colors,
                    color_on="vertex", name="radiosity")

    def render(self, fb: Any, camera: Any, exposure: Optional[float] = None,
               gamma: float = 2.2, **options: Any) -> Any:
        """Draw the solution into ``fb`` through :func:`scanline.render` with Gouraud
        shading of the node radiosities (lit by an ambient light of 1 and a material
        that reflects only it: each surface shows its radiosity); ``options`` go to
        :func:`scanline.render` (``method=``, ``antialias=`` ...).

        Parameters
        ----------
        fb : FrameBuffer
            Drawn into.
        camera : Camera
            The viewer.
        exposure : float, optional
            As :meth:`mesh` takes it.
        gamma : float
            The display gamma.
        **options
            Further keywords of :func:`scanline.render`.

        Returns
        -------
        Rendering
            What :func:`scanline.render` drew.

        Raises
        ------
        ArgumentTypeError
            ``shading``, ``lights``, ``materials`` or ``colors`` among ``options``.

        Examples
        --------
        From inside the room every pixel sees a wall:

        >>> import numpy as np, scanline as sl
        >>> cube = sl.mesh.cube(2.0)
        >>> room = sl.mesh.Mesh(cube.vertices, cube.faces[:, ::-1])     # faces turned inward
        >>> e = np.zeros((6, 3)); e[5] = 1.0                            # the ceiling glows
        >>> s = sl.radiosity.solve(room, emission=e, reflectance=0.5, subdivisions=1)
        >>> fb = sl.FrameBuffer(4, 4)
        >>> s.render(fb, sl.Camera(eye=(0, 0, 0.5), target=(0, 0, -1)))
        <Rendering method='z-buffer' 4x4: 1 mesh(es), 6 faces, 16 of 16 pixels covered>
        """
        from ..lighting import AmbientLight, Material
        from ..rendering import render

        for name in ("shading", "lights", "materials", "colors"):
            if name in options:
                raise ArgumentTypeError(f"{name}= is set by the radiosity solution (Gouraud "
                                        "shading of its node radiosities); give it to "
                                        "scanline.render with solution.mesh() instead")
        return render(fb, self.mesh(exposure, gamma), camera, shading="gouraud",
                      lights=[AmbientLight(1.0)], materials=Material(ka=1.0, kd=0.0, ks=0.0),
                      gamma=gamma, **options)

    def __repr__(self) -> str:
        state = "converged" if self.converged else "not converged"
        return (f"<Radiosity {self.method}: {len(self.patches)} patches, "
                f"{self.iterations} iterations, {state}>")


def vertex_radiosity(patches: Patches, radiosity: np.ndarray) -> np.ndarray:
    """The radiosity of each node: the mean of the patches it is a corner of.

    Parameters
    ----------
    patches : Patches
        The patches and their nodes.
    radiosity : ndarray (P, 3)
        B per patch.

    Returns
    -------
    ndarray (V, 3)
        B per node (Cohen and Greenberg 1985, section 5: what Gouraud shading
        interpolates).

    Examples
    --------
    Four patches with B = 1, 2, 3, 4 (row by row from the bottom): the middle node
    gets their mean 2.5, an edge's middle node the mean of its two.

    >>> import numpy as np, scanline as sl
    >>> square = sl.mesh.Mesh([(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0)], [[0, 1, 2, 3]])
    >>> p = sl.radiosity.patches(square, subdivisions=2)
    >>> b = np.array([1.0, 2.0, 3.0, 4.0])[:, None] * np.ones(3)
    >>> sl.radiosity.vertex_radiosity(p, b)[:, 0].tolist()
    [1.0, 1.5, 2.0, 2.0, 2.5, 3.0, 3.0, 3.5, 4.0]
    """
    corners = patches.corners
    distinct = np.ones(corners.shape, bool)
    distinct[:, 3] = corners[:, 3] != corners[:, 2]
    owner = np.repeat(np.arange(len(corners)), 4).reshape(corners.shape)[distinct]
    node = corners[distinct]
    total = np.zeros((len(patches.vertices), 3))
    np.add.at(total, node, radiosity[owner])
    count = np.bincount(node, minlength=len(patches.vertices))
    return total / np.maximum(count, 1)[:, None]


def _matrix(value: Any, n: int) -> np.ndarray:
    """A form-factor matrix given by the caller, checked."""
    f = v.real_array("form_factors", value, f"({n}, {n})")
    if f.shape != (n, n):
        raise ArgumentValueError(f"form_factors must be a ({n}, {n}) matrix (one row and "
                                 f"column per patch), got shape {f.shape}")
    if not np.isfinite(f).all() or (f < 0).any():
        raise ArgumentValueError("form_factors must be finite and >= 0")
    worst = float(f.sum(axis=1).max())
    if worst > 1.05:
        raise ArgumentValueError(f"form_factors rows must add up to at most 1 (the energy "
                                 f"leaving a patch), a row adds up to {worst:.4g}")
    return v.kernel_array(f)


@v.keywords
def solve(meshes: Any, emission: Any = None, reflectance: Any = None, *,
          subdivisions: int = 8, method: str = "gauss-seidel",
          form_factors: Union[str, Any] = "hemicube", resolution: Optional[int] = None,
          tolerance: float = 1e-4, max_iterations: Optional[int] = None,
          shooting_group: int = 1) -> Radiosity:
    """Solve the radiosity equations of ``meshes``.

    Parameters
    ----------
    meshes : Mesh, list of Mesh, or Patches
        Subdivided into ``subdivisions`` x ``subdivisions`` patches per face
        (:func:`scanline.radiosity.patches`); :class:`Patches` keep their own emission
        and reflectance unless these are given.
    emission : optional
        E per mesh: a number or (r, g, b) for each mesh (a list as long as
        ``meshes``), or per patch ((P,) or (P, 3)); one number or triple for all.
        Linear radiosity units.  At least one patch must emit.
    reflectance : optional
        rho in [0, 1) per channel, given as ``emission``.  Default: kd x S_d of each
        mesh's material and colors, what :func:`scanline.render` shades it with.
    method : {"gauss-seidel", "progressive"}
    form_factors : {"hemicube", "ray-casting"} or ndarray (P, P)
        How the form factors are computed (:func:`scanline.radiosity.form_factors`),
        or the matrix itself.
    resolution : int, optional
        Of the form-factor method (hemicube cells per side, default 100; ray-casting
        points per patch side, default 4).
    tolerance : float
        Gauss-Seidel: the largest change of a sweep over the largest B - E; progressive:
        the unshot energy over the emitted energy (0 < tolerance < 1).
    max_iterations : int, optional
        Most sweeps (default 1000) or shots (default 20 per patch).
    shooting_group : int
        Progressive: the patches of a quadrilateral face shoot together in blocks of
        ``shooting_group`` x ``shooting_group`` (Cohen, Greenberg, Immel and Brock
        1986: coarse *patches* shoot, fine *elements* receive; here the patches are
        the elements), one hemicube at the block's centroid per shot.  1: each
        patch shoots alone.

    Returns
    -------
    Radiosity

    Raises
    ------
    ArgumentTypeError
        A keyword it does not take, or an argument of the wrong type.
    ArgumentValueError
        An unknown ``method`` or ``form_factors`` name, a ``tolerance`` outside 0..1, no
        patch that emits light, a form-factor matrix of the wrong shape, negative or with
        rows adding up to more than 1, or a non-positive ``max_iterations`` or
        ``shooting_group``.

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> cube = sl.mesh.cube(2.0)
    >>> room = sl.mesh.Mesh(cube.vertices, cube.faces[:, ::-1])     # faces turned inward
    >>> e = np.zeros((6, 3)); e[5] = 1.0                            # the ceiling glows
    >>> s = sl.radiosity.solve(room, emission=e, reflectance=0.5, subdivisions=1,
    ...                        resolution=64)
    >>> s.converged, np.round(s.radiosity[:, 0], 2).tolist()      # walls, floor, ceiling
    (True, [0.18, 0.18, 0.18, 0.18, 0.2, 1.09])
    """
    method = v.choice("method", method, METHODS)
    tol = v.number("tolerance", tolerance)
    if not 0 < tol < 1:
        raise ArgumentValueError(f"tolerance must be between 0 and 1, got {tolerance!r}")
    pts = as_patches(meshes, subdivisions)
    if emission is not None or reflectance is not None:
        pts = pts.with_values(emission, reflectance)
    p = len(pts)
    if not (pts.emission > 0).any():
        raise ArgumentValueError("emission: no patch emits light, so every radiosity is 0; "
                                 "give emission=, e.g. one (r, g, b) per mesh")
    given = not isinstance(form_factors, str)
    if not given:
        v.choice("form_factors", form_factors, FORM_FACTOR_METHODS)
        check_resolution(form_factors, resolution)
    limit = (MAX_SWEEPS if method == "gauss-seidel" else SHOTS_PER_PATCH * p) \
        if max_iterations is None else v.positive_int("max_iterations", max_iterations)
    if method == "gauss-seidel":
        check_matrix_budget(p)
        f = _matrix(form_factors, p) if given else \
            RowSource(pts, form_factors, resolution).rows(np.arange(p))
        return _gauss_seidel(pts, f, tol, limit)
    group = pts.groups(v.positive_int("shooting_group", shooting_group))
    if given:
        matrix = _matrix(form_factors, p)
        return _progressive(pts, group, lambda g: matrix[:, group == g].sum(axis=1), tol, limit)
    source = RowSource(pts, form_factors, resolution, group)
    return _progressive(pts, group, source.received, tol, limit)


def _gauss_seidel(pts: Patches, f: np.ndarray, tol: float, limit: int) -> Radiosity:
    from .._kernels._jit import call
    from .._kernels.radiosity import gauss_seidel_sweep

    rho, e = v.kernel_array(pts.reflectance), v.kernel_array(pts.emission)
    b = e.copy()
    history, power = [], []
    converged = False
    for _ in range(limit):
        change = call(gauss_seidel_sweep, 4 * f.size, f, rho, e, b)
        history.append(change / max(float((b - e).max()), 1e-300))
        power.append(float((pts.area[:, None] * b).sum()))
        if history[-1] <= tol:
            converged = True
            break
    return Radiosity(pts, b, vertex_radiosity(pts, b), np.zeros(3), "gauss-seidel",
                     np.array(history), np.array(power), converged, f)


def _progressive(pts: Patches, group: np.ndarray, received: Any, tol: float,
                 limit: int) -> Radiosity:
    """Shooting: each patch's group (``group``) shoots the area-weighted mean of its
    patches' unshot radiosity; ``received(g)`` gives F_jg for every j, the fraction of
    group g's radiosity that arrives at j per unit of j's area."""
    area = pts.area
    rho = pts.reflectance
    b = pts.emission.copy()
    unshot = pts.emission.copy()
    count = int(group.max()) + 1
    group_area = np.bincount(group, area, count)
    emitted = float((area[:, None] * pts.emission).sum())
    mean_rho = (area[:, None] * rho).sum(axis=0) / area.sum()
    interreflection = 1.0 / (1.0 - mean_rho)
    history, power = [], []
    converged = False
    for _ in range(limit):
        energy = np.bincount(group, area * unshot.sum(axis=1), count)
        g = int(np.argmax(energy))
        members = group == g
        shot = (area[members, None] * unshot[members]).sum(axis=0) / group_area[g]
        f = received(g)
        unshot[members] = 0.0
        gain = rho * shot[None, :] * f[:, None]
        b += gain
        unshot += gain
        history.append(float((area[:, None] * unshot).sum()) / emitted)
        power.append(float((area[:, None] * b).sum()))
        if history[-1] <= tol:
            converged = True
            break
    ambient = interreflection * (area[:, None] * unshot).sum(axis=0) / area.sum()
    shown = b + rho * ambient[None, :]
    return Radiosity(pts, shown, vertex_radiosity(pts, shown), ambient, "progressive",
                     np.array(history), np.array(power), converged, None)
