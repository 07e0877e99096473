"""``sl.render(..., method="ray-tracing")``: the recursive ray tracer as the renderer's
coloring pass (Whitted 1980; Hearn & Baker 14-6).

The primary rays are the ray-casting method's (:mod:`scanline.visible.raycast`, one
ray through each pixel center, or each sample's with ``antialias=n``): it finds the
surface each one meets first.  From that surface on, the tracer
(:mod:`scanline._kernels.raytrace`) follows shadow, reflected and transmitted rays
through a bounding volume hierarchy of the scene's world facets
(:class:`~scanline.raytrace.BVH`), and the intensity it sums is stored with the
shading's gamma.  The primary hits are lit by the shading stage itself (any
``shading=`` model, textures, depth cueing), its shadow test made by shadow rays;
the further hits by the basic illumination model at the point with the interpolated
normal, as Phong shading lights a pixel.  So a scene with no reflective or
transparent surface and no shadow falling on a seen point comes out as ray casting
draws it, pixel for pixel.
"""

from dataclasses import dataclass
from typing import (TYPE_CHECKING, Any, Callable, Iterable, List, Optional, Sequence, Tuple, Union,
                    overload)

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..solids.program import TracerSolids

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer
    from ..lighting.lights import Light
    from ..lighting.material import Material
    from ..screen.scene import ScreenScene
    from ..shading.options import ShadingOptions
    from ..solids.program import Program
    from ..solids.render import Hits
    from ..visible.methods import MethodOptions
    from ..visible.visibility import Layer
    from .bvh import BVH

F64 = NDArray[np.float64]
I64 = NDArray[np.int64]

#: The default depth of the ray tree (levels, the primary ray's included).
MAX_DEPTH = 5

#: Most shadow rays from one point (the lights' count, an area light's samples**2).
SHADOW_RAYS = 1024

#: Offset of secondary rays' origins from their surface, in units of the scene's size
#: (its box's longest side): no ray meets the surface it leaves.
OFFSET = 1e-7


@dataclass(frozen=True, eq=False)
class Traced:
    """A screen scene ready for the tracer kernel: the tree over its world facets and
    the per-facet, per-material and per-light tables (the kernel's arguments after
    the samples' own), and those the shadow test reads."""
    tree: "BVH"
    arguments: Tuple[Any, ...]      # the kernel's arguments: arrays, numbers, tokens
    lights: F64
    seed: int
    eps: float
    clear: F64
    solids: Union[TracerSolids, Tuple[()]] = ()
    with_solids: Tuple[Any, ...] = (0,)
    max_depth: int = MAX_DEPTH


def material_table(materials: Sequence["Material"], gamma: float) -> F64:
    """The shading's material rows (:func:`scanline.shading.buffer.material_rows`)
    with each material's k_r, k_t, refractive index, roughness and bump scale, (M,
    16)."""
    from ..shading.buffer import material_rows

    extra = np.array([[m.reflectivity, m.transparency, m.refractive_index, m.roughness,
                       m.bump_scale] for m in materials], np.float64).reshape(-1, 5)
    return np.ascontiguousarray(np.hstack([material_rows(materials, gamma), extra]))


def map_tables(scene: "ScreenScene", gamma: float
               ) -> Tuple[F64, F64, I64, NDArray[np.float32], I64]:
    """The materials' texture, bump and environment maps as the tracer kernel takes
    them: ``(uvs (G, 3, 2), tangents (G, 6), maps (M, 3, 5), texels, levels)``
    (:data:`scanline._kernels.raytrace.TEXTURE` ...: each map's first row of
    ``levels``, -1 for none, its levels a face, filter, wrap and kind); the texture
    decoded with ``gamma``, the bump map's heights as stored.  Empty facet tables
    when no material has a texture or bump map."""
    from ..shading.surface import facet_tangents
    from ..texture.cubemap import environment_arrays
    from ..texture.mipmap import joined
    from ..texture.texture import FILTER_CODES, WRAP_CODES

    maps = np.full((len(scene.materials), 3, 5), -1, np.int64)
    parts: List[Tuple[NDArray[np.float32], I64]] = []
    where: List[Tuple[int, int]] = []
    for i, m in enumerate(scene.materials):
        for j, (texture, g) in enumerate(((m.texture, gamma), (m.bump, 1.0))):
            if texture is not None:
                texels, table = texture.kernel_arrays(g)
                parts.append((texels, table))
                where.append((i, j))
                maps[i, j, 1:] = (len(table), FILTER_CODES[texture.filter],
                                  WRAP_CODES[texture.wrap], 0)
        if m.environment is not None:
            texels, table, count, filt, wrap, kind = environment_arrays(m.environment, gamma)
            parts.append((texels, table))
            where.append((i, 2))
            maps[i, 2, 1:] = count, filt, wrap, kind
    texels, levels, firsts = joined(parts)
    for (i, j), first in zip(where, firsts):
        maps[i, j, 0] = first
    if scene.uv is None or (maps[:, :2, 0] < 0).all():
        uvs, tangents = np.zeros((0, 3, 2)), np.zeros((0, 6))
    else:
        facets = np.arange(len(scene.world))
        with np.errstate(invalid="ignore"):      # NaN uv: meshes without maps
            tangents = np.hstack(facet_tangents(scene, facets))
        uvs = scene.uv
    return (v.kernel_array(uvs), v.kernel_array(tangents), maps,
            v.kernel_array(texels, np.float32), v.kernel_array(levels, np.int64))


def light_table(lights: Iterable["Light"]) -> Tuple[F64, F64]:
    """The shading's source rows (:func:`scanline.shading.buffer.source_rows`) with an
    area light's corner, edges and samples per side (zeros for the others), (S, 26),
    and the ambient intensity."""
    from ..lighting.lights import AmbientLight, AreaLight
    from ..shading.buffer import source_rows

    from ..errors import ArgumentValueError

    rays = sum(light.samples ** 2 if isinstance(light, AreaLight) else 1
               for light in lights if not isinstance(light, AmbientLight))
    if rays > SHADOW_RAYS:
        raise ArgumentValueError(f"lights: the ray tracer would send {rays:,} shadow rays from "
                                 f"every point (one per light, samples**2 per area light); at "
                                 f"most {SHADOW_RAYS:,}: use fewer lights or fewer samples")
    rows, ambient = source_rows(lights)
    area = np.zeros((len(rows), 10))
    for i, light in enumerate(x for x in lights if not isinstance(x, AmbientLight)):
        if isinstance(light, AreaLight):
            area[i] = [*light.corner, *light.edge_u, *light.edge_v, light.samples]
    return np.ascontiguousarray(np.hstack([rows, area])), ambient


def traced(scene: "ScreenScene", shading: "ShadingOptions", background: F64, max_depth: int,
           seed: int,
           program: Optional["Program"] = None) -> Traced:
    """The :class:`Traced` form of ``scene`` with the shading options ``shading``
    (lights, gamma, the specular term) and the linear ``background`` (3,); ``program``:
    the solids (:class:`scanline.solids.program.Program`) traced with the facets."""
    from ..budget import check
    from ..shading import decoded
    from .._kernels import raytrace as k
    from .._kernels.variants import token
    from ..solids.program import tracer_solids
    from .bvh import BVH

    world = v.kernel_array(scene.world)
    check(200 * len(world), "meshes", f"the ray tracer's tables of {len(world):,} facets",
          "trace fewer triangles")
    tree = BVH(world)
    facet_row = np.empty(len(world), np.int64)
    facet_row[tree.order] = np.arange(len(world))
    solid_materials = () if program is None else tuple(program.materials)
    mats = material_table(tuple(scene.materials) + solid_materials, shading.gamma)
    solids = tracer_solids(program, len(scene.materials))
    with_solids = token(k.WITH if program is not None and len(program.primitives) else k.WITHOUT)
    tables = map_tables(scene, shading.gamma)
    maps_used = bool((tables[2][:, :, 0] >= 0).any())
    kt = mats[:, 12][scene.facet_mesh] if len(world) else np.zeros(0)
    lights, ambient = light_table(shading.lights)
    with np.errstate(over="ignore"):
        size = float(np.max(tree.bounds[0, 3:] - tree.bounds[0, :3])) if len(world) else 1.0
    if not np.isfinite(size):                     # coordinates near the float range's end
        size = float(np.max(np.abs(tree.bounds[0])))
    eps = OFFSET * max(size, 1e-300)
    clear = v.kernel_array(kt[tree.order])
    return Traced(tree, (
        int(seed), int(max_depth), eps, shading.specular == "blinn", tree.bounds, tree.links,
        tree.table, v.kernel_array(tree.order, np.int64), facet_row, clear,
        v.kernel_array(scene.normals),
        v.kernel_array(scene.vertex_normals), v.kernel_array(decoded(scene.vertex_colors,
                                                                     shading.gamma)),
        v.kernel_array(scene.facet_mesh, np.int64), v.kernel_array(scene.front, np.bool_),
        mats, lights, v.kernel_array(ambient), v.kernel_array(background),
        *tables, token(k.WITH if maps_used else k.WITHOUT), solids, with_solids), lights,
        int(seed), eps, clear, solids, with_solids, int(max_depth))


def primary_rays(scene: "ScreenScene", xs: ArrayLike, ys: ArrayLike) -> Tuple[F64, F64]:
    """The world rays through device points (``xs``, ``ys``) of ``scene``, (P, 3)
    origins and unit directions into the view volume.

    A point (X, 1) projects to NDC x = (r_x . (X, 1)) / (r_w . (X, 1)), r_x, r_y and
    r_w rows of the clip matrix, so the points seen at (x, y) are where the planes
    (r_x - x r_w) . (X, 1) = 0 and (r_y - y r_w) . (X, 1) = 0 meet: a line, with the
    direction n_1 x n_2 of their normals, turned toward growing w (perspective) or
    depth (parallel), and as origin its point on the front plane of the view volume
    (NDC depth 0; where that cannot be found, its point nearest the world's origin).
    No matrix is inverted: a camera whose depth range is lost to rounding still has
    its rays."""
    clip, scale, offset = scene.mapping
    x = (np.asarray(xs, np.float64) - offset[0]) / scale[0]
    y = (np.asarray(ys, np.float64) - offset[1]) / scale[1]
    planes: List[F64] = []
    for row, at in ((clip[0], x), (clip[1], y)):
        p = row[None, :] - at[:, None] * clip[3][None, :]
        p /= np.linalg.norm(p[:, :3] / np.abs(p[:, :3]).max(axis=1, keepdims=True), axis=1,
                            keepdims=True) * np.abs(p[:, :3]).max(axis=1, keepdims=True)
        planes.append(p)
    (n1, h1), (n2, h2) = ((p[:, :3], -p[:, 3]) for p in planes)
    d = np.cross(n1, n2)
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    ahead = clip[3, :3] if scene.camera.projection.kind == "perspective" else clip[2, :3]
    d *= np.where(d @ ahead < 0, -1.0, 1.0)[:, None]
    c = (n1 * n2).sum(axis=1)
    det = 1.0 - c * c
    origin = (((h1 - h2 * c) / det)[:, None] * n1 + ((h2 - h1 * c) / det)[:, None] * n2)
    # moved along the line onto the front plane (NDC depth 0: r_z . (X, 1) = 0)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        t = -(origin @ clip[2, :3] + clip[2, 3]) / (d @ clip[2, :3])
        front = origin + t[:, None] * d
    origin = np.where(np.isfinite(front).all(axis=1)[:, None], front, origin)
    return np.ascontiguousarray(origin), np.ascontiguousarray(d)


def shadow_test(prepared: Traced, twin: bool = False) -> Callable[[ArrayLike], List[F64]]:
    """The shading's shadow test (:attr:`scanline.shading.ShadingOptions.shadows`) by
    shadow rays through the tree: ``test(points (M, 3))`` -> per non-ambient light,
    the fraction of it that reaches each point
    (:func:`scanline._kernels.raytrace.shadow_all`; ``twin``: run as Python, for the
    step table)."""
    from .._kernels._jit import python
    from .._kernels._threads import call_in_bands
    from .._kernels import raytrace as k

    tree = prepared.tree
    lights = prepared.lights

    def test(points: ArrayLike) -> List[F64]:
        pts = v.kernel_array(np.reshape(points, (-1, 3)))
        out = np.empty((len(lights), len(pts)))
        args = (pts, prepared.seed, prepared.eps, lights, tree.bounds, tree.links, tree.table,
                prepared.clear, prepared.solids, prepared.with_solids, out)
        if twin:
            with np.errstate(all="ignore"):
                python(k.shadow_all)(0, 1, *args)
        else:
            call_in_bands(k.shadow_all, 50 * len(pts) * max(len(lights), 1), *args)
        return list(out.reshape((len(lights),) + np.shape(points)[:-1]))
    return test


def _without_environment(material: "Material") -> "Material":
    """``material`` without its environment map (a copy, as ``Material.with_color``
    makes one)."""
    new = object.__new__(type(material))
    new.__dict__.update(material.__dict__)
    object.__setattr__(new, "environment", None)
    return new


def primary_light(scene: "ScreenScene", layer: "Layer", ys: I64, xs: I64,
                  shading: "ShadingOptions",
                  prepared: Traced, background: F64, twin: bool = False) -> F64:
    """The local intensities (P, 3) of the primary rays' hits at pixels (``xs``, ``ys``)
    of ``layer`` (the ray caster's): the shading stage's own
    (:func:`scanline.shading.compose`: any shading model, textures, depth cueing),
    with :func:`shadow_test` as its shadow test; environment maps are left out (the
    reflected rays see the scene, and the map where they leave it)."""
    from dataclasses import replace

    from ..shading.compose import _points

    if any(getattr(m, "environment", None) is not None for m in scene.materials):
        # the reflected rays see the scene, and the map where they leave it
        scene = replace(scene, materials=tuple(_without_environment(m)
                                               for m in scene.materials))
    options = replace(shading, shadows=shadow_test(prepared, twin))
    _, linear = _points(scene, layer.ids, layer.depth, ys, xs, xs.astype(np.float64),
                        ys.astype(np.float64), options, background)
    return linear


@overload
def trace(prepared: Traced, origins: F64, directions: F64, firsts: ArrayLike, givens: F64,
          samples: ArrayLike, log: None = None) -> F64: ...


@overload
def trace(prepared: Traced, origins: F64, directions: F64, firsts: ArrayLike, givens: F64,
          samples: ArrayLike, log: F64) -> Tuple[F64, int]: ...


def trace(prepared: Traced, origins: F64, directions: F64, firsts: ArrayLike, givens: F64,
          samples: ArrayLike, log: Optional[F64] = None) -> Union[F64, Tuple[F64, int]]:
    """Linear intensities (P, 3) of the samples whose primary rays (``origins``,
    ``directions``) meet the facets ``firsts`` first (-1: none, NaN out), where the
    local intensities are ``givens`` (P, 3), the samples numbered ``samples`` for the
    random numbers; ``log``: a (L, LOG_COLUMNS) array that receives the rays of a
    single sample (Python, the kernel's twin), returned with the number of rows
    written."""
    from .._kernels._jit import first_use_parts, python
    from .._kernels._threads import call_in_bands
    from .._kernels import raytrace as k
    from .._kernels.variants import token

    out = np.empty((len(origins), 3))
    count = np.zeros(1, np.int64)
    rows = (v.kernel_array(origins), v.kernel_array(directions),
            v.kernel_array(firsts, np.int64), v.kernel_array(givens),
            v.kernel_array(samples, np.int64))
    if log is None:
        # work units a sample: its rays, shadow rays and their levels.  The estimate
        # cannot see a ray tree's size (a camera in a box of mirrors and glass took 15
        # microseconds a unit as Python, the first-use case 2): a first use goes in parts
        each = 20 * (8 + 6 * len(prepared.lights)) * max(1.0, prepared.max_depth / MAX_DEPTH)
        for lo, hi in first_use_parts(k.trace_all, each, len(out)):
            call_in_bands(k.trace_all, each * (hi - lo), *(a[lo:hi] for a in rows),
                          *prepared.arguments, out[lo:hi], token(k.WITHOUT),
                          np.zeros((0, k.LOG_COLUMNS)), count)
        return out
    args = rows + prepared.arguments + (out,)
    with np.errstate(all="ignore"):
        python(k.trace_all)(0, 1, *args, token(k.WITH), log, count)
    return out, int(count[0])


def shade(fb: "FrameBuffer", scene: "ScreenScene", layer: "Layer", shading: "ShadingOptions",
          options: "MethodOptions", hits: Optional["Hits"] = None) -> NDArray[np.int32]:
    """Color the pixels of ``layer`` (the ray-casting method's
    :class:`~scanline.visible.visibility.Layer` of ``scene``) into ``fb`` by tracing
    their rays; ``options``: the :class:`~scanline.visible.MethodOptions`
    (``max_depth``, ``seed``); ``hits``: the solids seen in front of the layer
    (:class:`scanline.solids.render.Hits`: their pixels' rays start at a solid, and
    every further ray meets the solids too).  Returns the facet seen at each pixel
    (H, W int32, -1: none)."""
    from .._kernels._jit import call
    from ..errors import ArgumentValueError
    from ..shading.buffer import gamma_tables
    from ..shading.compose import background_linear
    from .._kernels import raytrace as k

    if fb.mode not in ("L", "RGB", "RGBA"):
        raise ArgumentValueError(f"method='ray-tracing' draws into modes L, RGB and RGBA; the "
                                 f"frame buffer is mode {fb.mode!r}")
    ids = layer.ids
    facets = np.full(ids.shape, -1, np.int32)
    meshes = ids >= 0
    if hits is not None:
        meshes[hits.ys, hits.xs] = False
    ys, xs = np.nonzero(meshes)
    if not len(ys) and (hits is None or not len(hits.ys)):
        return facets
    first = scene.facet[ids[ys, xs]]
    facets[ys, xs] = first
    depth = MAX_DEPTH if options.max_depth is None else options.max_depth
    background = background_linear(fb, shading.gamma)
    prepared = traced(scene, shading, background, depth, options.seed or 0,
                      None if hits is None else hits.program)
    given = primary_light(scene, layer, ys, xs, shading, prepared, background) if len(ys) \
        else np.zeros((0, 3))
    if hits is not None and len(hits.ys):
        from dataclasses import replace

        from ..solids.render import local_light

        lit = local_light(scene, hits, replace(shading, shadows=shadow_test(prepared)))
        ys, xs = np.concatenate([ys, hits.ys]), np.concatenate([xs, hits.xs])
        first = np.concatenate([first, np.full(len(hits.ys), k.SOLID)])
        given = np.vstack([given, lit])
    origins, directions = primary_rays(scene, xs, ys)
    linear = trace(prepared, origins, directions, first, given,
                   ys.astype(np.int64) * fb.width + xs)
    call(k.store, 4 * len(ys), v.kernel_array(ys, np.int64), v.kernel_array(xs, np.int64),
         linear, *gamma_tables(shading.gamma), fb._raster()[0], fb.mode == "L",
         fb.mode == "RGBA")
    return facets
