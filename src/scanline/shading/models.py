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

from typing import TYPE_CHECKING, Callable, Iterator, Optional, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..lighting.model import ViewerAtInfinity, intensity
from .options import GAMMA, ShadingOptions, gamma_value

if TYPE_CHECKING:
    from ..screen.scene import ScreenScene

Floats = NDArray[np.float64]


def encode(linear: ArrayLike, gamma: float = GAMMA) -> NDArray[np.uint8]:
    """Stored 0..255 values of linear intensities: round(255 clamp(I, 0, 1)^(1/gamma))
    (NaN stores 0).

    Parameters
    ----------
    linear : array_like
        Linear intensities (clamped to 0..1).
    gamma : float
        The display gamma (Hearn & Baker 14-2, "Displaying light intensities").

    Returns
    -------
    ndarray of uint8
        The stored values, same shape.

    Raises
    ------
    ArgumentValueError
        A gamma outside 0.1..10.

    Examples
    --------
    With gamma 2 a quarter of the light stores round(255 sqrt(1/4)) = round(127.5) = 128:

    >>> from scanline.shading import encode
    >>> encode([0.0, 0.25, 1.0, 2.0], gamma=2).tolist()
    [0, 128, 255, 255]
    """
    gamma = gamma_value(gamma)
    with np.errstate(invalid="ignore"):
        i = np.nan_to_num(np.clip(np.asarray(linear, np.float64), 0.0, 1.0), nan=0.0)
    return np.rint(255.0 * i ** (1.0 / gamma)).astype(np.uint8)


def decode(stored: ArrayLike, gamma: float = GAMMA) -> Floats:
    """Linear values of stored colors given as reals 0..1 (c / 255): c^gamma.

    Parameters
    ----------
    stored : array_like
        Stored values as reals 0..1.
    gamma : float
        The display gamma.

    Returns
    -------
    ndarray float64
        The linear values, same shape.

    Raises
    ------
    ArgumentValueError
        A gamma outside 0.1..10.

    Examples
    --------
    >>> from scanline.shading import decode
    >>> decode([0.5, 1.0], gamma=2).tolist()
    [0.25, 1.0]
    """
    linear: Floats = np.asarray(stored, np.float64) ** gamma_value(gamma)
    return linear


def decoded(colors: ArrayLike, gamma: float = GAMMA) -> Floats:
    """:func:`decode` of stored colors ``colors`` (..., 3), once where they are one
    color broadcast (the scene's colors of a mesh without colors: its material's).

    Parameters
    ----------
    colors : array_like (..., 3)
        Stored colors as reals 0..1.
    gamma : float
        The display gamma.

    Returns
    -------
    ndarray (..., 3) float64
        The linear colors (a broadcast view where the input was one).

    Examples
    --------
    >>> import numpy as np
    >>> from scanline.shading import decoded
    >>> one = np.broadcast_to([0.5, 0.5, 0.5], (2, 3))      # one color, two places
    >>> decoded(one, gamma=2).tolist()
    [[0.25, 0.25, 0.25], [0.25, 0.25, 0.25]]
    """
    stored = np.asarray(colors, np.float64)
    if stored.ndim > 1 and stored.size and not any(stored.strides[:-1]):
        return np.broadcast_to(decode(stored[(0,) * (stored.ndim - 1)], gamma), stored.shape)
    return decode(stored, gamma)


def _facing(scene: "ScreenScene", facets: NDArray[np.int64], normals: Floats) -> Floats:
    """``normals`` turned toward the viewer on facets seen from behind."""
    back = ~scene.front[facets]
    if not back.any():
        return normals
    return np.where(back[..., None], -normals, normals)


def _runs(keys: NDArray[np.int64]) -> Iterator[Tuple[int, Union[slice, NDArray[np.int64]]]]:
    """``(key, where)`` for each distinct value of the integer array ``keys``: where
    it is, as a slice when the keys are sorted (a mesh's faces come together), else
    as indices from one stable sort (so every point is selected once, whatever the
    number of meshes)."""
    order: Optional[NDArray[np.int64]] = None
    if len(keys) > 1 and (keys[1:] < keys[:-1]).any():
        order = np.argsort(keys, kind="stable")
        keys = keys[order]
    starts = list(np.flatnonzero(np.r_[True, keys[1:] != keys[:-1]])) if len(keys) else []
    ends = starts[1:] + [len(keys)]
    for a, b in zip(starts, ends):
        yield int(keys[a]), slice(a, b) if order is None else order[a:b]


def _lit(scene: "ScreenScene", meshes: NDArray[np.int64], points: Floats, normals: Floats,
         colors: Floats, options: ShadingOptions) -> Floats:
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


def face_intensities(scene: "ScreenScene", faces: NDArray[np.int64], options: ShadingOptions,
                     colors: Optional[Floats] = None) -> Floats:
    """The one intensity (U, 3) of each of ``faces`` (constant shading, Hearn & Baker
    14-5): the model at the face's centroid with its plane normal, turned toward the
    viewer when the face is seen from behind; "none": the face's color.  ``colors``
    (U, 3): linear surface colors instead of the faces' own.

    Parameters
    ----------
    scene : ScreenScene
        The prepared scene (:func:`scanline.screen.prepare`).
    faces : ndarray of int64 (U,)
        Face numbers of the scene.
    options : ShadingOptions
        The lights, model, gamma and specular term.
    colors : ndarray (U, 3), optional
        Linear surface colors S_d.

    Returns
    -------
    ndarray (U, 3)
        Linear intensities.

    Examples
    --------
    The default material (ka = 0.2, white) under ambient light 1: 0.2 ka Ia.

    >>> import numpy as np, scanline as sl
    >>> from scanline.screen import prepare
    >>> from scanline.shading import ShadingOptions
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> scene = prepare(sl.mesh.cube(2), cam, 4, 4)
    >>> ambient = ShadingOptions(model="flat", lights=sl.lighting.AmbientLight(1.0), gamma=1)
    >>> sl.shading.face_intensities(scene, np.array([5]), ambient).tolist()
    [[0.2, 0.2, 0.2]]
    """
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


def _gouraud(scene: "ScreenScene", u: NDArray[np.int64], colors: Floats,
             options: ShadingOptions) -> Floats:
    """The intensities (U, 3, 3) at the vertices of each facet of ``u``, with the
    averaged vertex normals (``colors``: (G, 3, 3) per facet vertex)."""
    return _gouraud_colored(scene, u, colors[u], options)


def _gouraud_colored(scene: "ScreenScene", u: NDArray[np.int64], colors: Floats,
                     options: ShadingOptions) -> Floats:
    """:func:`_gouraud` with the colors (U, 3, 3) of ``u``'s own vertices."""
    pts = scene.world[u]                                            # (U, 3, 3)
    n = _facing(scene, np.repeat(u, 3), scene.vertex_normals[u].reshape(-1, 3))
    return _lit(scene, np.repeat(scene.facet_mesh[u], 3), pts.reshape(-1, 3), n,
                colors.reshape(-1, 3), options).reshape(-1, 3, 3)


def vertex_intensities(scene: "ScreenScene", facets: ArrayLike,
                       options: ShadingOptions) -> Floats:
    """Linear RGB intensities (U, 3, 3) at the three vertices of each of ``facets``
    (U,): Gouraud's vertex intensities, or for "flat" and "none" the face's one
    intensity three times (what :mod:`scanline.shading.buffer` interpolates per
    pixel).

    Parameters
    ----------
    scene : ScreenScene
        The prepared scene.
    facets : array_like of int (U,)
        Facet numbers (triangles of the faces' fans).
    options : ShadingOptions
        The lights and model.

    Returns
    -------
    ndarray (U, 3, 3)
        Per facet, per vertex, linear RGB.

    Examples
    --------
    The cube's front face lit head on by a white directional light and seen head on:
    kd (N . L) + ks (V . R)^n = 0.7 + 0.3 = 1 at every vertex (Gouraud 1971).

    >>> import numpy as np, scanline as sl
    >>> from scanline.screen import prepare
    >>> from scanline.shading import ShadingOptions
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> scene = prepare(sl.mesh.cube(2), cam, 4, 4)
    >>> sun = ShadingOptions(lights=sl.lighting.DirectionalLight((0, 0, -1)), gamma=1)
    >>> front = np.flatnonzero(scene.facet_face == 5)                # its two facets
    >>> sl.shading.vertex_intensities(scene, front, sun).round(12).tolist() == [[[1.0] * 3] * 3] * 2
    True
    """
    facets = np.asarray(facets, np.int64)
    if options.model in ("flat", "none"):
        faces, inverse = np.unique(scene.facet_face[facets], return_inverse=True)
        per = face_intensities(scene, faces, options)[inverse.reshape(-1)]
        return np.repeat(per[:, None, :], 3, axis=1)
    return _gouraud(scene, facets, decoded(scene.vertex_colors, options.gamma), options)


def _parts(colors: Floats, fn: Callable[[Floats], Floats]) -> Tuple[Floats, Floats]:
    """The intensities ``fn(colors)`` split in two: the part A the surface colors scale
    (ambient and diffuse) and the part S = fn(0) they do not (the highlight)."""
    spec = fn(np.zeros_like(colors))
    return fn(colors) - spec, spec


def _textured(per: NDArray[np.int64], colors: Floats, texels: Optional[Floats],
              fn: Callable[[Floats], Floats]) -> Floats:
    """Intensities ``fn(colors)`` (U, ..., 3) with the surface colors scaled by each
    point's texel T: T A + S (:func:`_parts`; :mod:`scanline.shading.surface`);
    ``per`` maps points to rows."""
    if texels is None:
        return fn(colors)[per]
    a, spec = _parts(colors, fn)
    out: Floats = texels[(slice(None),) + (None,) * (a.ndim - 2)] * a[per] + spec[per]
    return out


def vertex_parts(scene: "ScreenScene", facets: ArrayLike,
                 options: ShadingOptions) -> Tuple[Floats, Floats]:
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


def intensities(scene: "ScreenScene", facets: ArrayLike, bary: Floats,
                options: ShadingOptions,
                texture: Optional[Tuple[Floats, Floats]] = None) -> Floats:
    """Linear RGB intensities (M, 3) of M points given by their ``facets`` (M,) and
    barycentric coordinates ``bary`` (M, 2) = (lambda_1, lambda_2) there.  ``texture``:
    the points' texture coordinates and their screen derivatives, ``(uv (M, 2), (M,
    4))``, for the materials' texture and bump maps (:mod:`scanline.shading.surface`).

    Parameters
    ----------
    scene : ScreenScene
        The prepared scene.
    facets : array_like of int (M,)
        The facet of each point.
    bary : ndarray (M, 2)
        (lambda_1, lambda_2) of each point in its facet.
    options : ShadingOptions
        The model (Hearn & Baker 14-5: flat, Gouraud, Phong, fast Phong, none),
        lights and gamma.
    texture : (ndarray (M, 2), ndarray (M, 4)), optional
        Texture coordinates and their screen derivatives.

    Returns
    -------
    ndarray (M, 3)
        Linear RGB.

    Examples
    --------
    Phong shading of two points of the cube's front face under a head-on light:
    0.7 + 0.3 = 1 wherever the interpolated normal is the face's.

    >>> import numpy as np, scanline as sl
    >>> from scanline.screen import prepare
    >>> from scanline.shading import ShadingOptions
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> scene = prepare(sl.mesh.cube(2), cam, 4, 4)
    >>> phong = ShadingOptions(model="phong", lights=sl.lighting.DirectionalLight((0, 0, -1)),
    ...                        gamma=1)
    >>> front = np.flatnonzero(scene.facet_face == 5)
    >>> sl.shading.intensities(scene, front, np.array([[0.5, 0.25], [0.2, 0.2]]), phong).round(12).tolist()
    [[1.0, 1.0, 1.0], [1.0, 1.0, 1.0]]
    """
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
        gouraud: NDArray[np.float64] = np.einsum("mi,mic->mc", lam, per)
        return gouraud
    if model == "phong":
        p = np.einsum("mi,mic->mc", lam, scene.world[facets])
        n = _facing(scene, facets, np.einsum("mi,mic->mc", lam, scene.vertex_normals[facets]))
        c = np.einsum("mi,mic->mc", lam, colors[facets])
        if texture is not None:                  # texels too
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
