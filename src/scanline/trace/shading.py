"""Gouraud and Phong shading along one scan line (Hearn & Baker, section 14-5;
Gouraud 1971, Phong 1975): at each pixel of the row that a lit sphere covers, the
facet the depth buffer found there, the pixel's barycentric coordinates in it
(perspective-correct), and what is interpolated -- the three vertex intensities
(Gouraud) or the vertex normals (Phong) -- with the intensity the renderer stores.
The rows come from the renderer's own stages: :func:`scanline.screen.prepare`, the
depth buffer (:func:`scanline.visible.zbuffer.nearest`) and the shading
(:mod:`scanline.shading.models`, gamma 1: linear intensities, as the book's
formulas give them)."""

from typing import TYPE_CHECKING, Any, Dict, List, Literal, Tuple

import numpy as np
from numpy.typing import NDArray

from ..errors import ArgumentValueError
from .table import Table, _cell

if TYPE_CHECKING:
    from ..lighting.lights import Light
    from ..screen import ScreenScene


class ShadingTable(Table):
    """The table of :func:`gouraud` and :func:`phong`, with the triangles drawn."""

    #: Per row, the index of the device triangle its pixel lies in.
    triangle_of: List[int]
    #: The device triangles the scan line crosses, [x, y] per vertex, by index.
    triangles: Dict[int, List[List[float]]]

#: The device the sphere is drawn on.
WIDTH, HEIGHT = 32, 24


def scene() -> Tuple["ScreenScene", Tuple["Light", ...]]:
    """The built-in case: a gray sphere (resolution 8, so its facets show) lit by an
    ambient light and a point light up and to the left, on a :data:`WIDTH` x
    :data:`HEIGHT` device: ``(screen scene, lights)``."""
    import scanline as sl

    lit = sl.lighting
    lights = (lit.AmbientLight(0.1), lit.PointLight((-4, 5, 6), intensity=0.9))
    material = lit.Material(color=(255, 255, 255), ka=1.0, kd=0.7, ks=0.4, shininess=20)
    camera = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
    prepared = sl.screen.prepare(sl.mesh.sphere(1.5, resolution=8), camera, WIDTH, HEIGHT,
                                 materials=material)
    return prepared, lights


def _vector(p: NDArray[np.float64]) -> str:
    return "(" + ", ".join(_cell(round(float(c), 6)) for c in p) + ")"


def _shading(model: Literal["gouraud", "phong"], row: int) -> ShadingTable:
    from ..shading.compose import surface_coordinates
    from ..shading.models import intensities, vertex_intensities
    from ..shading.options import ShadingOptions
    from ..visible.zbuffer import nearest

    if isinstance(row, bool) or not isinstance(row, (int, np.integer)) or not 0 <= row < HEIGHT:
        raise ArgumentValueError(f"row must be a scan line 0..{HEIGHT - 1}, got {row!r}")
    s, lights = scene()
    options = ShadingOptions(model=model, lights=lights, gamma=1.0)
    ids = nearest(s).ids[row]
    xs = np.flatnonzero(ids >= 0)
    t = ids[xs].astype(np.int64)
    facets = s.facet[t]
    lam = surface_coordinates(s, t, xs.astype(np.float64), np.full(len(xs), float(row)))[0]
    shade = intensities(s, facets, lam[:, 1:], options)[:, 0]
    rows: List[Dict[str, Any]] = []
    if model == "gouraud":
        corner = vertex_intensities(s, facets, options)[:, :, 0]              # (M, 3)
        for x, f, l, c, i in zip(xs.tolist(), facets.tolist(), lam, corner, shade):
            rows.append({"x": x, "facet": f, "l0": round(float(l[0]), 6),
                         "l1": round(float(l[1]), 6), "l2": round(float(l[2]), 6),
                         "I0": round(float(c[0]), 6), "I1": round(float(c[1]), 6),
                         "I2": round(float(c[2]), 6), "I": round(float(i), 6)})
        columns = ["x", "facet", "l0", "l1", "l2", "I0", "I1", "I2", "I"]
        rule = "I = l0 I0 + l1 I1 + l2 I2 (the illumination model at the vertices only)"
    else:
        normals = np.einsum("mk,mkc->mc", lam, s.vertex_normals[facets])
        normals /= np.linalg.norm(normals, axis=1, keepdims=True)
        for x, f, l, n, i in zip(xs.tolist(), facets.tolist(), lam, normals, shade):
            rows.append({"x": x, "facet": f, "l0": round(float(l[0]), 6),
                         "l1": round(float(l[1]), 6), "l2": round(float(l[2]), 6),
                         "N": _vector(n), "I": round(float(i), 6)})
        columns = ["x", "facet", "l0", "l1", "l2", "N", "I"]
        rule = ("N = (l0 N0 + l1 N1 + l2 N2) / |...|, then the illumination model at the "
                "pixel's own point with N")
    notes = [f"a sphere of radius 1.5 (8 x 8 facets) on {WIDTH} x {HEIGHT}, eye (0, 0, 5); "
             "ambient 0.1, point light 0.9 at (-4, 5, 6); ka 1, kd 0.7, ks 0.4, n_s 20; "
             "gamma 1 (linear intensities)",
             "l0, l1, l2: the pixel's barycentric coordinates in its facet (perspective-"
             "correct: l/w and 1/w are linear along the scan line)", rule]
    table = ShadingTable(f"{model.capitalize()} shading, scan line y = {row}", columns, rows, notes)
    # for the explorer: each pixel's device triangle, and the triangles the row crosses
    table.triangle_of = t.tolist()
    crossing = (s.triangles[:, :, 1].min(axis=1) <= row) & (s.triangles[:, :, 1].max(axis=1) >= row)
    table.triangles = {int(k): s.triangles[k, :, :2].tolist() for k in np.flatnonzero(crossing)}
    return table


def gouraud(row: int = 12) -> ShadingTable:
    """Gouraud shading along scan line ``row`` of the built-in sphere (:func:`scene`):
    per pixel, its facet, barycentric coordinates l0..l2, the intensities I0..I2
    the model gives at the facet's vertices (with the averaged vertex normals) and
    the interpolated I = sum l_k I_k that is stored (red channel; the sphere is
    gray).

    Parameters
    ----------
    row : int
        The scan line, 0 .. :data:`HEIGHT` - 1 (default 12, through the middle).

    Returns
    -------
    ShadingTable
        Columns x, facet, l0, l1, l2, I0, I1, I2, I: one row per pixel of the row the
        sphere covers; ``triangle_of`` and ``triangles`` give the device triangles.

    Raises
    ------
    ArgumentValueError
        ``row`` is not a scan line of the device.

    References
    ----------
    H. Gouraud, "Continuous shading of curved surfaces", IEEE Transactions on
    Computers C-20(6), 1971.

    Examples
    --------
    At pixel x = 9, I = 0.093388 x 0.726628 + 0.792426 x 0.56071 + 0.114186 x
    0.462249 = 0.067858 + 0.444322 + 0.052782 = 0.564962:

    >>> t = gouraud(12)
    >>> r = t.rows[1]
    >>> r["x"], r["facet"], (r["l0"], r["l1"], r["l2"]), (r["I0"], r["I1"], r["I2"]), r["I"]
    (9, 47, (0.093388, 0.792426, 0.114186), (0.726628, 0.56071, 0.462249), 0.564962)
    >>> all(abs(r["I"] - (r["l0"] * r["I0"] + r["l1"] * r["I1"] + r["l2"] * r["I2"])) < 1e-5
    ...     for r in t.rows)
    True
    """
    return _shading("gouraud", row)


def phong(row: int = 12) -> ShadingTable:
    """Phong shading along scan line ``row`` of the built-in sphere (:func:`scene`):
    per pixel, its facet, barycentric coordinates l0..l2, the interpolated and
    normalized normal N and the intensity I the model gives with it at the pixel's
    point (red channel; the sphere is gray).

    Parameters
    ----------
    row : int
        The scan line, 0 .. :data:`HEIGHT` - 1 (default 12, through the middle).

    Returns
    -------
    ShadingTable
        Columns x, facet, l0, l1, l2, N, I: one row per pixel of the row the sphere
        covers; ``triangle_of`` and ``triangles`` give the device triangles.

    Raises
    ------
    ArgumentValueError
        ``row`` is not a scan line of the device.

    References
    ----------
    B. T. Phong, "Illumination for computer generated pictures", Communications
    of the ACM 18(6), 1975.

    Examples
    --------
    The pixels and barycentric coordinates are Gouraud's; the normal interpolated
    at x = 9 is a unit vector ((-0.633185)^2 + 0.048707^2 + 0.772466^2 = 0.999999,
    1 but for the rounding to six decimals), and the model evaluated with it gives
    0.595163 there, more than Gouraud's interpolated 0.564962:

    >>> t = phong(12)
    >>> r = t.rows[1]
    >>> r["x"], r["facet"], r["N"], r["I"]
    (9, 47, '(-0.633185, 0.048707, 0.772466)', 0.595163)
    >>> [(g["x"], g["l0"]) for g in gouraud(12).rows[:2]] == [(p["x"], p["l0"]) for p in t.rows[:2]]
    True
    """
    return _shading("phong", row)
