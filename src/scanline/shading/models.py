"""Polygon rendering methods (Hearn & Baker, section 14-5): constant (flat),
Gouraud and Phong shading, and the fast Phong approximation, plus the gamma that
turns linear intensities into stored values (section 14-2, "Displaying light
intensities").

Every visible-surface method finds, at each pixel (or sample), the facet seen there
(a triangle of a face's fan), and the shading the barycentric coordinates
(lambda_0, lambda_1, lambda_2) of the point in that facet, perspective-correct;
:func:`intensities` turns those into linear intensities (the numpy form; the
compiled one is :mod:`scanline.shading.buffer`):

* ``"none"``: no illumination: each surface shows its color S_d;
* ``"flat"``: one intensity per polygon, the illumination model at the face's
  centroid with its plane (Newell) normal (Hearn & Baker 14-5, "constant-intensity
  shading"; the notes' "a uniform color throughout an entire polygon");
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
normals are turned toward the viewer (two-sided lighting).  Where the options give
shadow maps, each point's visibility of each light multiplies that light's term.

Gamma.  Intensities are linear (light adds); a display's output grows as the stored
value to the power gamma.  :func:`encode` stores round(255 (I)^(1/gamma)) and
:func:`decode` turns stored colors (material and mesh colors) into linear
reflectances (c / 255)^gamma.  ``gamma=1`` keeps the linear values (what the
textbook's formulas give, and what the tests compare); the renderer's default is
2.2, close to sRGB.
"""

import numpy as np

from ..lighting.model import ViewerAtInfinity, intensity
from .options import GAMMA, gamma_value


def encode(linear, gamma=GAMMA):
    """Stored 0..255 values of linear intensities: round(255 clamp(I, 0, 1)^(1/gamma))
    (NaN stores 0)."""
    gamma = gamma_value(gamma)
    with np.errstate(invalid="ignore"):
        i = np.nan_to_num(np.clip(np.asarray(linear, np.float64), 0.0, 1.0), nan=0.0)
    return np.rint(255.0 * i ** (1.0 / gamma)).astype(np.uint8)


def decode(stored, gamma=GAMMA):
    """Linear values of stored colors given as reals 0..1 (c / 255): c^gamma."""
    return np.asarray(stored, np.float64) ** gamma_value(gamma)


def decoded(colors, gamma=GAMMA):
    """:func:`decode` of stored colors ``colors`` (..., 3), once where they are one
    color broadcast (the scene's colors of a mesh without colors: its material's)."""
    colors = np.asarray(colors, np.float64)
    if colors.ndim > 1 and colors.size and not any(colors.strides[:-1]):
        return np.broadcast_to(decode(colors[(0,) * (colors.ndim - 1)], gamma), colors.shape)
    return decode(colors, gamma)


def _facing(scene, facets, normals):
    """``normals`` turned toward the viewer on facets seen from behind."""
    back = ~scene.front[facets]
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


def _lit(scene, meshes, points, normals, colors, options):
    """The illumination model at ``points`` of ``meshes`` (the mesh of each point),
    material by material."""
    out = np.empty(points.shape[:-1] + (3,))
    shadows = options.shadows
    for m, sel in _runs(meshes):
        vis = None if shadows is None else shadows(points[sel])
        out[sel] = intensity(points[sel], normals[sel], scene.eye, list(options.lights),
                             scene.materials[m], specular=options.specular, color=colors[sel],
                             visibility=vis)
    return out


def face_intensities(scene, faces, options, colors=None):
    """The one intensity (U, 3) of each of ``faces`` (constant shading, Hearn & Baker
    14-5): the model at the face's centroid with its plane normal, turned toward the
    viewer when the face is seen from behind; "none": the face's color.  ``colors``
    (U, 3): linear surface colors instead of the faces' own."""
    if colors is None:
        colors = decode(scene.face_colors[faces], options.gamma)
    if options.model == "none":
        return colors
    centroid = scene.face_centroids[faces]
    n = scene.face_normals[faces]
    eye = scene.eye
    toward = (np.broadcast_to(eye.toward, n.shape) if isinstance(eye, ViewerAtInfinity)
              else np.asarray(eye, np.float64) - centroid)
    n = np.where(((n * toward).sum(axis=1) < 0)[:, None], -n, n)
    return _lit(scene, scene.face_mesh[faces], centroid, n, colors, options)


def _gouraud(scene, u, colors, options):
    """The intensities (U, 3, 3) at the vertices of each facet of ``u``, with the
    averaged vertex normals (``colors``: (G, 3, 3) per facet vertex)."""
    return _gouraud_colored(scene, u, colors[u], options)


def _gouraud_colored(scene, u, colors, options):
    """:func:`_gouraud` with the colors (U, 3, 3) of ``u``'s own vertices."""
    pts = scene.world[u]                                            # (U, 3, 3)
    n = _facing(scene, np.repeat(u, 3), scene.vertex_normals[u].reshape(-1, 3))
    return _lit(scene, np.repeat(scene.facet_mesh[u], 3), pts.reshape(-1, 3), n,
                colors.reshape(-1, 3), options).reshape(-1, 3, 3)


def vertex_intensities(scene, facets, options):
    """Linear RGB intensities (U, 3, 3) at the three vertices of each of ``facets``
    (U,): Gouraud's vertex intensities, or for "flat" and "none" the face's one
    intensity three times (what :mod:`scanline.shading.buffer` interpolates per
    pixel)."""
    facets = np.asarray(facets, np.int64)
    if options.model in ("flat", "none"):
        faces, inverse = np.unique(scene.facet_face[facets], return_inverse=True)
        per = face_intensities(scene, faces, options)[inverse.reshape(-1)]
        return np.repeat(per[:, None, :], 3, axis=1)
    return _gouraud(scene, facets, decoded(scene.vertex_colors, options.gamma), options)


def _parts(colors, fn):
    """The intensities ``fn(colors)`` split in two: the part A the surface colors scale
    (ambient and diffuse) and the part S = fn(0) they do not (the highlight)."""
    spec = fn(np.zeros_like(colors))
    return fn(colors) - spec, spec


def _textured(per, colors, texels, fn):
    """Intensities ``fn(colors)`` (U, ..., 3) with the surface colors scaled by each
    point's texel T: T A + S (:func:`_parts`; :mod:`scanline.shading.surface`);
    ``per`` maps points to rows."""
    if texels is None:
        return fn(colors)[per]
    a, spec = _parts(colors, fn)
    return texels[(slice(None),) + (None,) * (a.ndim - 2)] * a[per] + spec[per]


def vertex_parts(scene, facets, options):
    """:func:`vertex_intensities` in two parts, A and S (U, 3, 3) each, the part a
    texel scales and the part it does not (:func:`_parts`)."""
    facets = np.asarray(facets, np.int64)
    if options.model in ("flat", "none"):
        faces, inverse = np.unique(scene.facet_face[facets], return_inverse=True)
        a, spec = _parts(decode(scene.face_colors[faces], options.gamma),
                         lambda c: face_intensities(scene, faces, options, c))
        per = inverse.reshape(-1)
        return (np.repeat(a[per][:, None], 3, axis=1), np.repeat(spec[per][:, None], 3, axis=1))
    return _parts(decoded(scene.vertex_colors, options.gamma)[facets],
                  lambda c: _gouraud_colored(scene, facets, c, options))


def intensities(scene, facets, bary, options, texture=None):
    """Linear RGB intensities (M, 3) of M points given by their ``facets`` (M,) and
    barycentric coordinates ``bary`` (M, 2) = (lambda_1, lambda_2) there.  ``texture``:
    the points' texture coordinates and their screen derivatives, ``(uv (M, 2), (M,
    4))``, for the materials' texture and bump maps (:mod:`scanline.shading.surface`)."""
    from . import surface

    facets = np.asarray(facets, np.int64)
    model = options.model
    texels = None
    if texture is not None:
        texels = surface.texel_factors(scene, facets, texture[0], texture[1], options.gamma)
    if model in ("flat", "none"):
        faces, inverse = np.unique(scene.facet_face[facets], return_inverse=True)
        return _textured(inverse.reshape(-1), decode(scene.face_colors[faces], options.gamma),
                         texels, lambda c: face_intensities(scene, faces, options, c))
    lam = np.empty((len(facets), 3))
    lam[:, 1:] = bary
    lam[:, 0] = 1.0 - bary[:, 0] - bary[:, 1]
    colors = decoded(scene.vertex_colors, options.gamma)                   # (G, 3, 3)
    if model == "gouraud":
        u, inverse = np.unique(facets, return_inverse=True)
        per = _textured(inverse.reshape(-1), colors[u], texels,
                        lambda c: _gouraud_colored(scene, u, c, options))
        return np.einsum("mi,mic->mc", lam, per)
    if model == "phong":
        p = np.einsum("mi,mic->mc", lam, scene.world[facets])
        n = _facing(scene, facets, np.einsum("mi,mic->mc", lam, scene.vertex_normals[facets]))
        c = np.einsum("mi,mic->mc", lam, colors[facets])
        if texels is not None:
            c = c * texels
            n = surface.bumped(scene, facets, n, texture[0])
        out = _lit(scene, scene.facet_mesh[facets], p, n, c, options)
        if any(m.environment is not None for m in scene.materials):
            out = out + surface.environment_light(scene, facets, p, n, options.gamma)
        return out
    # fast Phong: six exact samples per facet, quadratic interpolation
    u, inverse = np.unique(facets, return_inverse=True)
    w6 = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [.5, .5, 0], [0, .5, .5], [.5, 0, .5]])
    p = np.einsum("si,uic->usc", w6, scene.world[u]).reshape(-1, 3)
    n = np.einsum("si,uic->usc", w6, scene.vertex_normals[u]).reshape(-1, 3)
    c = np.einsum("si,uic->usc", w6, colors[u]).reshape(-1, 3)
    f6 = np.repeat(u, 6)
    samples = _textured(inverse.reshape(-1), c.reshape(-1, 6, 3), texels, lambda cc: _lit(
        scene, scene.facet_mesh[f6], p, _facing(scene, f6, n), cc.reshape(-1, 3),
        options).reshape(-1, 6, 3))
    l0, l1, l2 = lam[:, 0:1], lam[:, 1:2], lam[:, 2:3]
    return (l0 * (2 * l0 - 1) * samples[:, 0] + l1 * (2 * l1 - 1) * samples[:, 1]
            + l2 * (2 * l2 - 1) * samples[:, 2] + 4 * l0 * l1 * samples[:, 3]
            + 4 * l1 * l2 * samples[:, 4] + 4 * l2 * l0 * samples[:, 5])
