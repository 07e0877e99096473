"""Polygon rendering methods (Hearn & Baker, section 14-5): constant (flat),
Gouraud and Phong shading, and the fast Phong approximation, plus the gamma that
turns linear intensities into stored values (section 14-2, "Displaying light
intensities").

Every visible-surface method finds, at each pixel (or sample), the face seen there
and the barycentric coordinates (lambda_0, lambda_1, lambda_2) of the point in that
face, interpolated perspective-correctly; :func:`shade` turns those into
intensities:

* ``"flat"``: one intensity per face, the illumination model at the face's centroid
  with its face normal (the notes' "constant shading": "a uniform color throughout an
  entire polygon");
* ``"gouraud"``: the model evaluated at the three vertices with the averaged vertex
  normals, the intensities interpolated, I = sum lambda_i I_i (Gouraud 1971);
* ``"phong"``: the normal interpolated, N = sum lambda_i N_i, normalized, and the
  model evaluated at each pixel's own point (Phong 1975);
* ``"fast-phong"``: a second-degree approximation of Phong's intensity across each
  triangle, in the spirit of Bishop & Weimer's fast Phong shading (1986), which
  expands the intensity to second degree in x and y so that forward differences
  evaluate it: here the quadratic through six exact Phong samples (the vertices and
  the edge midpoints), I = sum_i lambda_i (2 lambda_i - 1) I_i + sum_{i<j} 4
  lambda_i lambda_j I_ij; exact wherever Phong's intensity is quadratic, and the
  model is evaluated 6 times per face instead of once per pixel.

Faces seen from behind (not culled) are lit on the side the viewer sees: their
normals are turned toward the viewer (two-sided lighting).

Gamma.  Intensities are linear (light adds); a display's output grows as the stored
value to the power gamma.  :func:`encode` stores round(255 (I)^(1/gamma)) and
:func:`decode` turns stored colors (material and mesh colors) into linear
reflectances (c / 255)^gamma.  ``gamma=1`` keeps the linear values (what the
textbook's formulas give, and what the tests compare); the renderer's default is
2.2, close to sRGB.
"""

import numpy as np

from .. import _validate as v
from ..errors import ArgumentValueError
from ..lighting.model import ViewerAtInfinity, intensity

MODELS = ("flat", "gouraud", "phong", "fast-phong")
GAMMA = 2.2


def gamma_value(gamma):
    g = v.number("gamma", gamma)
    if not 0.1 <= g <= 10:
        raise ArgumentValueError(f"gamma must be in 0.1..10 (1: linear, 2.2: a typical "
                                 f"display), got {gamma!r}")
    return g


def encode(linear, gamma=GAMMA):
    """Stored 0..255 values of linear intensities: round(255 clamp(I, 0, 1)^(1/gamma))."""
    i = np.clip(np.asarray(linear, np.float64), 0.0, 1.0)
    return np.rint(255.0 * i ** (1.0 / gamma)).astype(np.uint8)


def decode(stored, gamma=GAMMA):
    """Linear values of stored colors given as reals 0..1 (c / 255): c^gamma."""
    return np.asarray(stored, np.float64) ** gamma


def decoded(colors, gamma=GAMMA):
    """:func:`decode` of stored colors ``colors`` (..., 3), once where they are one
    color broadcast (the scene's colors of a mesh without colors: its material's)."""
    colors = np.asarray(colors, np.float64)
    if colors.ndim > 1 and colors.size and not any(colors.strides[:-1]):
        return np.broadcast_to(decode(colors[(0,) * (colors.ndim - 1)], gamma), colors.shape)
    return decode(colors, gamma)


def _facing(scene, faces, normals, points):
    """``normals`` turned toward the viewer on faces seen from behind."""
    back = ~scene.front[faces]
    if not back.any():
        return normals
    return np.where(back[..., None], -normals, normals)


def _runs(keys):
    """``(key, where)`` for each distinct value of the integer array ``keys``: where
    it is, as a slice when the keys are sorted (a mesh's faces come together), else
    as indices from one stable sort (so every point is selected once, whatever the
    number of meshes)."""
    order = None
    if len(keys) > 1 and (keys[1:] < keys[:-1]).any():
        order = np.argsort(keys, kind="stable")
        keys = keys[order]
    starts = np.flatnonzero(np.r_[True, keys[1:] != keys[:-1]]) if len(keys) else []
    ends = list(starts[1:]) + [len(keys)]
    for a, b in zip(starts, ends):
        yield keys[a], slice(a, b) if order is None else order[a:b]


def _lit(scene, faces, points, normals, colors, lights, specular, visibility):
    """The illumination model for points of ``faces``, material by material."""
    out = np.empty(points.shape[:-1] + (3,))
    for m, sel in _runs(scene.face_mesh[faces]):
        vis = None if visibility is None else visibility(points[sel])
        out[sel] = intensity(points[sel], normals[sel], scene.eye, lights,
                             scene.materials[m], specular=specular, color=colors[sel],
                             visibility=vis)
    return out


def _point_visibility(shadows):
    return None if shadows is None else shadows.visibility


def _flat(scene, u, colors, lights, specular, vis):
    """The intensity (U, 3) of each face of ``u``: the model at its centroid with its
    face normal."""
    centroid = scene.world[u].mean(axis=1)
    n = _facing(scene, u, scene.normals[u], centroid)
    return _lit(scene, u, centroid, n, colors[u].mean(axis=1), lights, specular, vis)


def _gouraud(scene, u, colors, lights, specular, vis):
    """The intensities (U, 3, 3) at the vertices of each face of ``u``, with the
    averaged vertex normals."""
    pts = scene.world[u]                                            # (U, 3, 3)
    n = _facing(scene, np.repeat(u, 3), scene.vertex_normals[u].reshape(-1, 3),
                pts.reshape(-1, 3))
    return _lit(scene, np.repeat(u, 3), pts.reshape(-1, 3), n, colors[u].reshape(-1, 3),
                lights, specular, vis).reshape(-1, 3, 3)


def vertex_intensities(scene, faces, lights, shading="gouraud", specular="phong", gamma=GAMMA):
    """Linear RGB intensities (U, 3, 3) at the three vertices of each of ``faces``
    (U,): Gouraud's vertex intensities, or for ``"flat"`` the face's one intensity
    three times (what :mod:`scanline.shading.buffer` interpolates per pixel)."""
    faces = np.asarray(faces, np.int64)
    colors = decoded(scene.vertex_colors, gamma)
    if shading == "flat":
        per = _flat(scene, faces, colors, lights, specular, None)
        return np.repeat(per[:, None, :], 3, axis=1)
    return _gouraud(scene, faces, colors, lights, specular, None)


def shade(scene, faces, bary, lights, shading="gouraud", specular="phong", gamma=GAMMA,
          shadows=None):
    """Linear RGB intensities (M, 3) of M points given by their ``faces`` (M,) and
    barycentric coordinates ``bary`` (M, 2) = (lambda_1, lambda_2)."""
    v.choice("shading", shading, MODELS)
    faces = np.asarray(faces, np.int64)
    lam = np.empty((len(faces), 3))
    lam[:, 1:] = bary
    lam[:, 0] = 1.0 - bary[:, 0] - bary[:, 1]
    colors = decoded(scene.vertex_colors, gamma)                   # (F, 3, 3)
    vis = _point_visibility(shadows)
    if shading == "flat":
        u, inverse = np.unique(faces, return_inverse=True)
        return _flat(scene, u, colors, lights, specular, vis)[inverse.reshape(-1)]
    if shading == "gouraud":
        u, inverse = np.unique(faces, return_inverse=True)
        per = _gouraud(scene, u, colors, lights, specular, vis)
        return np.einsum("mi,mic->mc", lam, per[inverse.reshape(-1)])
    if shading == "phong":
        p = np.einsum("mi,mic->mc", lam, scene.world[faces])
        n = np.einsum("mi,mic->mc", lam, scene.vertex_normals[faces])
        c = np.einsum("mi,mic->mc", lam, colors[faces])
        return _lit(scene, faces, p, _facing(scene, faces, n, p), c, lights, specular, vis)
    # fast Phong: six exact samples per face, quadratic interpolation
    u, inverse = np.unique(faces, return_inverse=True)
    w6 = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [.5, .5, 0], [0, .5, .5], [.5, 0, .5]])
    p = np.einsum("si,uic->usc", w6, scene.world[u]).reshape(-1, 3)
    n = np.einsum("si,uic->usc", w6, scene.vertex_normals[u]).reshape(-1, 3)
    c = np.einsum("si,uic->usc", w6, colors[u]).reshape(-1, 3)
    f6 = np.repeat(u, 6)
    samples = _lit(scene, f6, p, _facing(scene, f6, n, p), c, lights, specular,
                   vis).reshape(-1, 6, 3)[inverse.reshape(-1)]
    l0, l1, l2 = lam[:, 0:1], lam[:, 1:2], lam[:, 2:3]
    return (l0 * (2 * l0 - 1) * samples[:, 0] + l1 * (2 * l1 - 1) * samples[:, 1]
            + l2 * (2 * l2 - 1) * samples[:, 2] + 4 * l0 * l1 * samples[:, 3]
            + 4 * l1 * l2 * samples[:, 4] + 4 * l2 * l0 * samples[:, 5])


__all__ = ["MODELS", "GAMMA", "shade", "vertex_intensities", "encode", "decode", "decoded",
           "ViewerAtInfinity"]
