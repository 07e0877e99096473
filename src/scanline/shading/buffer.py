"""Shading a whole visibility buffer at once: the compiled form of
:func:`scanline.shading.intensities` followed by the gamma encoding and the store
(the kernel is :mod:`scanline._kernels.shade`).

Flat and Gouraud shading (and "none") compute their intensities once per face or per
vertex (numpy, :func:`scanline.shading.vertex_intensities`), and the kernel
interpolates those intensities at each pixel; Phong shading evaluates the model at
every pixel in the kernel.  The numpy path (:func:`scanline.shading.intensities`)
stays the reference (the tests compare the two) and still serves what the kernel
does not do: fast Phong, shadow maps, depth cueing, layers of fragments.
"""

import functools
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING, Any, Callable, Dict, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v

from ..lighting import AmbientLight, DirectionalLight, SpotLight
from ..lighting.lights import Light
from ..lighting.model import ViewerAtInfinity

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer
    from ..lighting.material import Material
    from ..screen.scene import ScreenScene
    from .options import ShadingOptions

#: What :func:`texture_rows` gives: the materials' texture rows, texels and levels.
TextureRows = Tuple[NDArray[np.int64], NDArray[np.float32], NDArray[np.int64]]

#: Shading models the kernel draws (the rest go through the numpy path).
MODELS = ("none", "flat", "gouraud", "phong")


def source_rows(lights: Iterable[Light]) -> Tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The non-ambient lights as rows (S, 16) of the kernel's source table:
    homogeneous position, attenuation a0 a1 a2, spot cos(angle), exponent, spot flag,
    spot axis, RGB intensity; and the summed ambient intensity (3,)."""
    ambient = np.zeros(3)
    rows: list[NDArray[np.float64]] = []
    for light in lights:
        if isinstance(light, AmbientLight):
            ambient = ambient + light.intensity
            continue
        row = np.zeros(16)
        if isinstance(light, DirectionalLight):
            row[:3] = -light.direction
            row[4] = 1.0
        else:
            row[:3] = light.position
            row[3] = 1.0
            row[4:7] = light.attenuation
        if isinstance(light, SpotLight):
            row[7] = np.cos(light.angle)
            row[8] = light.exponent
            row[9] = 1.0
            row[10:13] = light.direction
        row[13:16] = light.intensity
        rows.append(row)
    return np.array(rows).reshape(-1, 16), np.ascontiguousarray(ambient, np.float64)


def material_rows(materials: Sequence["Material"], gamma: float = 2.2) -> NDArray[np.float64]:
    """ka, kd, ks, n_s, S_s of each material, the least s = V . R (or N . H) whose
    s^n_s reaches :data:`scanline._kernels.shade.SHINE_FLOOR` (0 for n_s = 0), and
    its color S_d decoded with ``gamma`` (linear), (M, 11)."""
    from .._kernels.shade import SHINE_FLOOR
    from . import decode

    rows = []
    for m in materials:
        n = float(m.shininess)
        cut = SHINE_FLOOR ** (1.0 / n) if n > 0 else 0.0
        rows.append([m.ka, m.kd, m.ks, n, *m.specular_color, cut,
                     *decode(np.asarray(m.color, np.float64), gamma)])
    return np.array(rows, np.float64).reshape(-1, 11)


def homogeneous_eye(eye: Union[ArrayLike, ViewerAtInfinity]) -> NDArray[np.float64]:
    """The viewer as (x, y, z, w): w = 1 at a point, 0 at infinity."""
    if isinstance(eye, ViewerAtInfinity):
        return np.append(np.asarray(eye.toward, np.float64), 0.0)
    return np.append(np.asarray(eye, np.float64), 1.0)


@functools.lru_cache(maxsize=8)
def gamma_tables(gamma: float) -> Tuple[NDArray[np.int64], NDArray[np.float64]]:
    """The gamma encoding as the kernel's tables: the stored value v of each of
    ``GAMMA_STEPS`` evenly spaced intensities (-2 - v where the next one is more than
    one value higher: :func:`scanline._kernels.shade.encode` climbs there), and the
    intensity ((v - 1/2) / 255)^gamma from which value v is stored (index 0: -inf,
    256: inf), followed by each step's copy of the threshold of its value plus one
    (index 257 + step: :func:`scanline._kernels.shade.store_chunk` reads it without
    first reading the step's value).  Kept per gamma, read-only."""
    from .._kernels.shade import GAMMA_STEPS
    from . import encode

    table = encode(np.linspace(0.0, 1.0, GAMMA_STEPS), gamma).astype(np.int64)
    table[:-1] = np.where(np.diff(table) > 1, -2 - table[:-1], table[:-1])
    thresholds = np.empty(257 + GAMMA_STEPS)
    thresholds[0], thresholds[256] = -np.inf, np.inf
    thresholds[1:256] = ((np.arange(1, 256) - 0.5) / 255.0) ** gamma
    thresholds[257:] = thresholds[np.minimum(np.maximum(table, 0) + 1, 256)]
    table.flags.writeable = thresholds.flags.writeable = False
    return table, thresholds


def drawable(fb: "FrameBuffer", options: "ShadingOptions") -> bool:
    """True when the kernel can shade for these ``options`` (a
    :class:`~scanline.shading.options.ShadingOptions`) into ``fb``."""
    return (options.model in MODELS and options.shadows is None
            and options.depth_cue is None and fb.mode in ("L", "RGB", "RGBA"))


def _material_colored(scene: "ScreenScene") -> bool:
    """True when every facet takes its material's color (the scene's vertex colors are
    the one material's color broadcast): the kernel then reads it from the material
    rows instead of an (G, 3, 3) array."""
    c = scene.vertex_colors
    return (len(scene.materials) == 1 and c.ndim == 3 and c.size > 0 and not any(c.strides[:-1])
            and np.array_equal(c[0, 0], scene.materials[0].color))


def shade_buffer(scene: "ScreenScene", fb: "FrameBuffer", ids: NDArray[np.int32],
                 options: "ShadingOptions") -> None:
    """Shade the pixels of ``ids`` (H, W; the scene's device triangle seen at each
    pixel, -1 none; int32, C order) into ``fb`` (:func:`drawable` must hold).  Each
    triangle's attributes are found from the triangle itself
    (:func:`scanline._kernels.shade.triangle_attributes`), once per triangle; ``ids``
    is changed in place to hold the facet at each pixel."""
    from .._kernels import shade as k
    from .._kernels._threads import call_in_bands, call_in_chunks
    from .._kernels.variants import MODE
    from .._pool import scratch
    from . import decoded, vertex_intensities

    gamma = options.gamma
    model = options.model
    sources, ambient = source_rows(options.lights)
    empty = np.zeros((0, 3, 3))
    if model == "phong":
        world = v.kernel_array(scene.world)
        normals = v.kernel_array(scene.vertex_normals)
        colors = (empty if _material_colored(scene) else
                  v.kernel_array(decoded(scene.vertex_colors, gamma)))
    else:
        world = normals = empty
        colors = np.zeros((scene.facet_count, 3, 3))
        mark = np.zeros(scene.facet_count, bool)       # the facets drawn (np.unique:
        mark[scene.facet] = True                         # a hash of every triangle)
        seen = np.flatnonzero(mark)
        if len(seen):
            colors[seen] = vertex_intensities(scene, seen, options)
    token = k.SHADING["phong" if model == "phong" else "vertex"]
    tface = v.kernel_array(scene.facet, np.int64)
    n = len(tface)
    kk = 3 if model != "phong" else 9 if len(colors) else 6
    table = scratch("triangle attributes", (n, 5 + 3 * kk))
    tri, q = v.kernel_array(scene.triangles), v.kernel_array(scene.inv_w)
    front = np.ascontiguousarray(scene.front, np.bool_)
    tb = v.kernel_array(scene.bary)
    call_in_chunks(k.triangle_attributes, 10 * kk * n, n,
                   lambda lo, hi: (lo, hi, tri, q, tb, tface, world, normals, colors, front,
                                   table, token))
    h, w = ids.shape
    work = h * w * (2 + (8 * len(sources) if model == "phong" else 0))
    call_in_bands(k.shade_pixels, work, ids, table, tface,
                  np.ascontiguousarray(scene.facet_mesh, np.int64),
                  material_rows(scene.materials, gamma), ambient,
                  np.ascontiguousarray(sources), homogeneous_eye(scene.eye),
                  *gamma_tables(gamma), fb._raster()[0], token,
                  k.SPECULAR[options.specular if model == "phong" else "phong"], MODE[fb.mode])


#: The last few results of :func:`texture_rows`, by their textures, filters, wraps
#: and gamma: the joined texels are a copy (writable, as the kernels take arrays)
#: that a frame after frame of the same textures need not make again.
_TEXTURE_ROWS: Dict[Tuple[object, ...], TextureRows] = {}


def texture_rows(materials: Sequence["Material"], gamma: float) -> TextureRows:
    """Every material's texture for :mod:`scanline._kernels.surface`: ``(mat_tex (M,
    4) int64: first level, level count, filter, wrap (first -1: none), texels (3 N,)
    float32, levels (L, 3) int64)``, the textures' levels one after the other,
    decoded with ``gamma``.  Kept for the same textures (:data:`_TEXTURE_ROWS`);
    the arrays are the kernels' to read, not to write."""
    key = (float(gamma),) + tuple((m.texture, m.texture.filter, m.texture.wrap)
                                  if m.texture is not None else None for m in materials)
    kept = _TEXTURE_ROWS.get(key)
    if kept is None:
        if len(_TEXTURE_ROWS) >= 4:
            _TEXTURE_ROWS.clear()
        kept = _TEXTURE_ROWS[key] = _joined_textures(materials, gamma)
    return kept


def _joined_textures(materials: Sequence["Material"], gamma: float) -> TextureRows:
    """:func:`texture_rows` computed."""
    from ..texture.texture import FILTER_CODES, WRAP_CODES

    rows = np.full((len(materials), 4), -1, np.int64)
    texels: list[NDArray[np.float32]] = []
    levels: list[NDArray[np.int64]] = []
    at_texel = at_level = 0
    for i, m in enumerate(materials):
        if m.texture is None:
            continue
        tx, lv = m.texture.kernel_arrays(gamma)
        shifted = lv.copy()
        shifted[:, 0] += at_texel
        rows[i] = at_level, len(lv), FILTER_CODES[m.texture.filter], WRAP_CODES[m.texture.wrap]
        texels.append(tx)
        levels.append(shifted)
        at_texel += len(tx) // 3
        at_level += len(lv)
    if not texels:
        return rows, np.zeros(3, np.float32), np.array([[0, 1, 1]], np.int64)
    return (rows, v.kernel_array(np.concatenate(texels), np.float32),
            v.kernel_array(np.concatenate(levels), np.int64))


def texturable(fb: "FrameBuffer", scene: "ScreenScene", options: "ShadingOptions") -> bool:
    """True when :func:`shade_textured` can shade ``scene`` (textures only: no bump or
    environment map; perspective-correct) into ``fb``."""
    return (drawable(fb, options) and options.texture_mapping == "perspective"
            and scene.uv is not None
            and all(m.bump is None and m.environment is None for m in scene.materials))


def _shines(scene: "ScreenScene", sources: NDArray[np.float64]) -> bool:
    """Whether any surface of ``scene`` has a highlight: a material with ks > 0 and a
    light source that is not ambient (``sources``: :func:`source_rows`)."""
    return any(m.ks > 0 for m in scene.materials) and len(sources) > 0


def vertex_light(scene: "ScreenScene", facets: NDArray[np.int64],
                 options: "ShadingOptions") -> NDArray[np.float64]:
    """Gouraud's vertex intensities of ``facets`` in the two parts of
    :func:`scanline.shading.models.vertex_parts`, (U, 3, 6): A then S (U, 3, 3: A
    alone where nothing shines, S = 0), compiled
    (:func:`scanline._kernels.surface.vertex_light`; the facets' colors as one row
    where they are one color broadcast)."""
    from .._kernels import surface as k
    from .._kernels._threads import call_in_chunks
    from .._kernels.shade import SPECULAR
    from . import decoded

    sources, ambient = source_rows(options.lights)
    every = len(facets) == scene.facet_count
    pick: Callable[[NDArray[Any]], NDArray[Any]] = ((lambda a: a) if every
                                                    else (lambda a: a[facets]))
    normals = pick(scene.vertex_normals)
    back = ~pick(scene.front)
    if back.any():
        normals = np.where(back[:, None, None], -normals, normals)
    points = v.kernel_array(pick(scene.world).reshape(-1, 3))
    normals = v.kernel_array(normals.reshape(-1, 3))
    colors = decoded(scene.vertex_colors, options.gamma)
    colors = (colors[(0,) * (colors.ndim - 1)].reshape(1, 3)
              if colors.size and not any(colors.strides[:-1]) else pick(colors).reshape(-1, 3))
    colors = v.kernel_array(colors)
    material = v.kernel_array(np.repeat(pick(scene.facet_mesh), 3), np.int64)
    highlight = _shines(scene, sources)
    out = np.empty((len(points), 6 if highlight else 3))
    mats = material_rows(scene.materials, options.gamma)
    eye = homogeneous_eye(scene.eye)
    spec = SPECULAR[options.specular]
    call_in_chunks(k.vertex_light, 20 * (1 + len(sources)) * len(points), len(points),
                   lambda lo, hi: (lo, hi, points, normals, colors, material, mats, ambient,
                                   np.ascontiguousarray(sources), eye, spec, highlight, out))
    return out.reshape(len(facets), 3, -1)


def shade_textured(scene: "ScreenScene", fb: "FrameBuffer", ids: NDArray[np.int32],
                   options: "ShadingOptions") -> None:
    """:func:`shade_buffer` for scenes with textured materials (:func:`texturable`):
    the kernel :func:`scanline._kernels.surface.textured_pixels`."""
    from .._kernels import surface as k
    from .._kernels._threads import call_in_bands, call_in_chunks
    from .._kernels.shade import SHADING, SPECULAR
    from .._kernels.variants import MODE
    from .._pool import scratch
    from . import decoded
    from .models import vertex_parts

    gamma = options.gamma
    model = options.model
    sources, ambient = source_rows(options.lights)
    g = scene.facet_count
    uv = v.kernel_array(scene.uv)   # NaN only on meshes without a texture (check_maps)
    if model == "phong":
        normals = np.where(scene.front[:, None, None], scene.vertex_normals,
                           -scene.vertex_normals) if not scene.front.all() \
            else scene.vertex_normals
        attributes = np.concatenate([scene.world, normals,
                                     np.broadcast_to(decoded(scene.vertex_colors, gamma),
                                                     (g, 3, 3))], axis=2)
        kk = 9
    else:
        mark = np.zeros(g, bool)
        mark[scene.facet] = True
        seen = np.flatnonzero(mark)
        if len(seen) and model == "gouraud":
            attributes = vertex_light(scene, seen, options)
        else:
            attributes = np.concatenate(vertex_parts(scene, seen, options), axis=2)
        if len(seen) < g:
            every = np.zeros((g, 3, attributes.shape[2]))
            every[seen] = attributes
            attributes = every
        # no highlight anywhere (S = 0): the table holds A and (u, v) only
        kk = 6 if _shines(scene, sources) else 3
    attributes = v.kernel_array(attributes)
    tface = v.kernel_array(scene.facet, np.int64)
    n = len(tface)
    table = scratch("textured triangle attributes", (n, 5 + 3 * (kk + 2)))
    tri, q = v.kernel_array(scene.triangles), v.kernel_array(scene.inv_w)
    tb = v.kernel_array(scene.bary)
    call_in_chunks(k.attribute_table, 10 * (kk + 2) * n, n,
                   lambda lo, hi: (lo, hi, tri, q, tb, tface, attributes, kk, uv, table))
    mat_tex, texels, levels = texture_rows(scene.materials, gamma)
    slopes = any(m.texture is not None and m.texture.filter == "trilinear"
                 for m in scene.materials)
    h, w = ids.shape
    work = h * w * (4 + (8 * len(sources) if model == "phong" else 0))
    call_in_bands(k.textured_pixels, work, ids, table, tface,
                  np.ascontiguousarray(scene.facet_mesh, np.int64),
                  material_rows(scene.materials, gamma), mat_tex, texels, levels, slopes,
                  ambient,
                  np.ascontiguousarray(sources), homogeneous_eye(scene.eye),
                  *gamma_tables(gamma), fb._raster()[0],
                  SHADING["phong" if model == "phong" else "vertex"],
                  SPECULAR[options.specular if model == "phong" else "phong"], MODE[fb.mode])
