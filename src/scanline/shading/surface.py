"""Surface detail in the shading (Hearn & Baker 14-8 and 14-9): the texture, bump and
environment maps of :class:`~scanline.lighting.Material` applied at the points a
visible-surface method found.

* **Texture coordinates**, perspective-correct: u/w, v/w and 1/w are linear in
  screen space (w the homogeneous coordinate, the depth before the divide), so at a
  pixel u = (u/w) / (1/w) -- the same interpolation as every attribute's
  (:func:`scanline.shading.barycentrics`: the perspective-correct barycentric
  coordinates, u = sum lambda_i u_i).  ``texture_mapping="affine"`` interpolates u
  linearly in screen space instead, the error the perspective-correct form removes
  (textures swim and bend along the diagonal of a quad seen at an angle).
* **Texture mapping** (14-9): the surface color is S_d = color x texel, so the
  ambient and diffuse terms are ka S_d I_a and kd S_d (N . L) I_l; the specular
  term keeps S_s.  Flat and Gouraud shading compute the intensity at the face or
  the vertices in two parts, I = S_d-scaled part A + specular part S, and each
  pixel takes T A + S with its own texel T.
* **Bump mapping** (Blinn 1978, "Simulation of wrinkled surfaces"; 14-9): the
  surface P(u, v) displaced along its unit normal by the height B(u, v) has the
  normal N' = P'_u x P'_v = N + B_u (n x P_v) - B_v (n x P_u) to first order (N = P_u
  x P_v, n = N / |N|): P_u, P_v are a facet's tangents along u and v (constant on a
  planar triangle, solved from its vertices and texture coordinates), B_u, B_v the
  height map's central differences one texel apart.
* **Environment mapping** (14-8): the view direction V reflected about the normal, R
  = 2 (N . V) N - V, looks up a cube map or a latitude-longitude map of the
  surroundings (:mod:`scanline._kernels.environment`); the surface adds k_r S_s
  times its color (the reflected term tinted by the specular color, as the ray
  tracer's).

Bump and environment maps need a normal at each pixel: Phong shading.
"""

from typing import TYPE_CHECKING, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import ArgumentValueError

if TYPE_CHECKING:
    from ..lighting.model import ViewerAtInfinity
    from ..screen.scene import ScreenScene
    from ..texture.texture import Texture
    from .options import ShadingOptions

#: How texture coordinates are interpolated across the screen.
TEXTURE_MAPPINGS = ("perspective", "affine")


def any_maps(scene: "ScreenScene") -> bool:
    """True when some material of ``scene`` has a texture, bump or environment map."""
    return any(m.texture is not None or m.bump is not None or m.environment is not None
               for m in scene.materials)


def _has_uv(scene: "ScreenScene", mesh: int) -> bool:
    """Whether mesh ``mesh`` of ``scene`` has texture coordinates: the scene's are NaN
    for every facet of a mesh without them and finite for the others (``Mesh``
    refuses coordinates that are not), so its first facet tells (a mesh with no
    facet needs none)."""
    if scene.uv is None:
        return False
    mine = scene.facet_mesh == mesh
    first = int(mine.argmax())
    return not (mine[first] and np.isnan(scene.uv[first]).any()) if len(mine) else True


def check_maps(scene: "ScreenScene", options: "ShadingOptions") -> None:
    """Refuse maps the shading cannot apply: a textured mesh without texture
    coordinates, bump or environment maps without per-pixel normals."""
    for i, m in enumerate(scene.materials):
        if m.texture is None and m.bump is None and m.environment is None:
            continue
        if (m.texture is not None or m.bump is not None) and not _has_uv(scene, i):
            raise ArgumentValueError(
                f"materials[{i}] has a texture or bump map, but meshes[{i}] has no texture "
                f"coordinates: give the mesh uv= (one (u, v) per vertex)")
        if (m.bump is not None or m.environment is not None) and options.model != "phong":
            raise ArgumentValueError(
                f"materials[{i}] has a bump or environment map, which needs a normal at each "
                f"pixel: use shading='phong', not {options.model!r}")


def _sample(texture: "Texture", uv: NDArray[np.float64], derivatives: NDArray[np.float64],
            gamma: float) -> NDArray[np.float64]:
    """``texture``'s linear colors at ``uv`` (M, 2) (the kernel: no argument checks)."""
    from .._kernels import texture as k
    from .._kernels._jit import call
    from ..texture.texture import FILTER_CODES, WRAP_CODES

    texels, table = texture.kernel_arrays(gamma)
    out = np.empty((len(uv), 3))
    call(k.sample_points, 4 * len(uv), texels, table, 0, len(table),
         FILTER_CODES[texture.filter], WRAP_CODES[texture.wrap],
         np.ascontiguousarray(uv, np.float64), np.ascontiguousarray(derivatives, np.float64),
         out)
    return out


def texture_coordinates(scene: "ScreenScene", facets: NDArray[np.int64], lam: NDArray[np.float64],
                        dlam: NDArray[np.float64]
                        ) -> Tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(u, v) at points of ``facets`` (M,) with barycentric coordinates ``lam`` (M, 3)
    and their screen derivatives ``dlam`` (M, 3, 2) (d/dx, d/dy): ``(uv (M, 2),
    derivatives (M, 4): du/dx, dv/dx, du/dy, dv/dy)``."""
    assert scene.uv is not None
    t = scene.uv[facets]                                               # (M, 3, 2)
    uv = np.einsum("mi,mic->mc", lam, t)
    d = np.einsum("mik,mic->mkc", dlam, t).reshape(-1, 4)
    return uv, d


def texel_factors(scene: "ScreenScene", facets: NDArray[np.int64], uv: NDArray[np.float64],
                  derivatives: NDArray[np.float64],
                  gamma: float) -> NDArray[np.float64]:
    """The texel T (M, 3, linear) scaling S_d at each point: its material's texture
    there, 1 on untextured surfaces."""
    out = np.ones((len(facets), 3))
    mesh = scene.facet_mesh[facets]
    for i, m in enumerate(scene.materials):
        if m.texture is None:
            continue
        sel = np.flatnonzero(mesh == i)
        if len(sel):
            out[sel] = _sample(m.texture, uv[sel], derivatives[sel], gamma)
    return out


def facet_tangents(scene: "ScreenScene", facets: NDArray[np.int64]) -> Tuple[NDArray[np.float64],
                   NDArray[np.float64]]:
    """P_u and P_v (M, 3) each, of ``facets``: the world tangents along u and v, from
    P_1 - P_0 = P_u du_1 + P_v dv_1 and P_2 - P_0 = P_u du_2 + P_v dv_2 (zero for a
    facet whose texture coordinates are degenerate)."""
    assert scene.uv is not None
    p = scene.world[facets]
    t = scene.uv[facets]
    e1, e2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    a1, a2 = t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]
    det = a1[:, 0] * a2[:, 1] - a2[:, 0] * a1[:, 1]
    ok = np.abs(det) > 1e-300
    r = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)[:, None]
    pu = (e1 * a2[:, 1:2] - e2 * a1[:, 1:2]) * r
    pv = (e2 * a1[:, 0:1] - e1 * a2[:, 0:1]) * r
    return pu, pv


def bumped_normals(normals: NDArray[np.float64], pu: NDArray[np.float64], pv: NDArray[np.float64],
                   bu: NDArray[np.float64],
                   bv: NDArray[np.float64]) -> NDArray[np.float64]:
    """Blinn's perturbed unit normals (M, 3): N' = (N . n) n + B_u (n x P_v) - B_v (n x
    P_u) with n the unit shading normal and N = P_u x P_v, turned to n's side."""
    n = normals / np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-300)
    big = np.cross(pu, pv)
    s = (big * n).sum(axis=1, keepdims=True)
    out = s * n + bu[:, None] * np.cross(n, pv) - bv[:, None] * np.cross(n, pu)
    out = np.where(s < 0, -out, out)
    length = np.linalg.norm(out, axis=1, keepdims=True)
    unit: NDArray[np.float64] = np.where(length > 0, out / np.where(length > 0, length, 1.0), n)
    return unit


def height_slopes(bump: "Texture", uv: NDArray[np.float64],
                  scale: float) -> Tuple[NDArray[np.float64], NDArray[np.float64]]:
    """B_u and B_v (M,) of the height map ``bump`` (its first channel, stored values
    0..1, times ``scale``) at ``uv``: central differences one texel apart."""
    du, dv = 1.0 / bump.width, 1.0 / bump.height
    zero = np.zeros((len(uv), 4))
    shifts = np.array([[du, 0.0], [-du, 0.0], [0.0, dv], [0.0, -dv]])
    h = _sample(bump, (uv[None] + shifts[:, None]).reshape(-1, 2),
                np.tile(zero, (4, 1)), 1.0)[:, 0].reshape(4, -1) * scale
    return (h[0] - h[1]) / (2 * du), (h[2] - h[3]) / (2 * dv)


def bumped(scene: "ScreenScene", facets: NDArray[np.int64], normals: NDArray[np.float64],
           uv: NDArray[np.float64]) -> NDArray[np.float64]:
    """``normals`` (M, 3) of points of ``facets`` at ``uv`` perturbed by their
    materials' bump maps (:func:`bumped_normals`)."""
    mesh = scene.facet_mesh[facets]
    out = normals
    for i, m in enumerate(scene.materials):
        if m.bump is None:
            continue
        sel = np.flatnonzero(mesh == i)
        if not len(sel):
            continue
        if out is normals:
            out = normals.copy()
        pu, pv = facet_tangents(scene, facets[sel])
        bu, bv = height_slopes(m.bump, uv[sel], m.bump_scale)
        out[sel] = bumped_normals(normals[sel], pu, pv, bu, bv)
    return out


def reflected_views(points: NDArray[np.float64], normals: NDArray[np.float64],
                    eye: Union[ArrayLike, "ViewerAtInfinity"]) -> NDArray[np.float64]:
    """R = 2 (N . V) N - V (M, 3) for unit normals and V the unit direction to the
    viewer (a point, or a viewer at infinity)."""
    from ..lighting.model import ViewerAtInfinity

    if isinstance(eye, ViewerAtInfinity):
        view = np.broadcast_to(np.asarray(eye.toward, np.float64), points.shape)
    else:
        view = np.asarray(eye, np.float64) - points
    view = view / np.maximum(np.linalg.norm(view, axis=1, keepdims=True), 1e-300)
    n = normals / np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-300)
    reflected: NDArray[np.float64] = 2 * (n * view).sum(axis=1, keepdims=True) * n - view
    return reflected


def environment_light(scene: "ScreenScene", facets: NDArray[np.int64],
                      points: NDArray[np.float64], normals: NDArray[np.float64],
                      gamma: float) -> NDArray[np.float64]:
    """k_r S_s env(R) (M, 3, linear) at the points: each material's environment map
    (cube or latitude-longitude) in the reflected view direction, tinted by its
    specular color, 0 where it has none."""
    from ..texture.cubemap import environment_colors

    out = np.zeros((len(facets), 3))
    mesh = scene.facet_mesh[facets]
    for i, m in enumerate(scene.materials):
        if m.environment is None or m.reflectivity == 0:
            continue
        sel = np.flatnonzero(mesh == i)
        if len(sel):
            r = reflected_views(points[sel], normals[sel], scene.eye)
            out[sel] = (m.reflectivity * np.asarray(m.specular_color)
                        * environment_colors(m.environment, r, gamma))
    return out
