"""Solids in ``sl.render``: exact surfaces seen by the ray-casting method (Hearn &
Baker 13-10 and 14-6: the ray through each pixel center against each object's exact
surface; Roth 1982 for CSG trees).

The rays are the ray caster's own (:func:`scanline.raytrace.render.primary_rays`: one
through each pixel center, or each sample's with ``antialias=n``), cast against every
solid given (their union, one program: :class:`~scanline.solids.program.Program`);
a solid's first surface is projected by the camera's clip matrix to a device depth,
and where it lies in the view volume and in front of the meshes' depth it is what the
pixel sees.  It is lit by the illumination model (:func:`scanline.lighting.intensity`)
with the surface's exact normal (the gradient of its quadric, its face's or triangle's
normal), the primitive's material and the shading's lights, specular term and shadow
test -- whatever ``shading=`` says, as Phong shading of an exact normal.
"""

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, List, Sequence, Tuple

import numpy as np
from numpy.typing import NDArray

from ..errors import ArgumentValueError
from .base import Solid, is_solid

F64 = NDArray[np.float64]
I64 = NDArray[np.int64]

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer
    from ..lighting.material import Material
    from ..screen.scene import ScreenScene
    from ..shading.options import ShadingOptions
    from .program import Program

#: The methods that draw solids (they cast rays).
METHODS = ("ray-casting", "ray-tracing")


def split(items: Any) -> Tuple[Any, List[Solid]]:
    """``items`` (a mesh, a solid, or a list of both) -> (the meshes' list or the
    original object when it holds no solid, the solids' list)."""
    if is_solid(items):
        return [], [items]
    if isinstance(items, (list, tuple)):
        solids = [x for x in items if is_solid(x)]
        if solids:
            return [x for x in items if not is_solid(x)], solids
    return items, []


def check_method(method: str, solids: Sequence[Solid]) -> None:
    """Refuse solids for a method that does not cast rays."""
    if solids and method not in METHODS:
        raise ArgumentValueError(
            f"method={method!r} draws polygon meshes; solids ({type(solids[0]).__name__}, CSG "
            f"trees) are drawn exactly by method='ray-casting' or 'ray-tracing' (or convert a "
            f"primitive to a mesh first, e.g. sl.mesh.sphere for a Sphere)")


@dataclass(frozen=True, eq=False)
class Hits:
    """The solids' first surfaces at pixels (``ys``, ``xs``) seen in front of the
    meshes: world ``points`` and unit ``normals`` (facing the viewer), ``rays`` (their
    unit directions), ``depth`` (device), ``solid`` (the index in the list given),
    ``primitive`` (the program's) and ``materials`` (the primitives'), ``program``
    (:class:`~scanline.solids.program.Program` of the solids' union)."""
    ys: NDArray[np.int64]
    xs: NDArray[np.int64]
    points: NDArray[np.float64]
    normals: NDArray[np.float64]
    rays: NDArray[np.float64]
    depth: NDArray[np.float64]
    solid: NDArray[np.int64]
    materials: List["Material"]
    primitive: NDArray[np.int64]
    program: "Program"


def pixels(solids: Sequence[Solid], clip: F64, scale: F64, offset: F64,
           shape: Tuple[int, ...]) -> Tuple[I64, I64]:
    """The pixels (ys, xs) whose rays may meet the solids: those in the device
    rectangle of their bounding boxes' corners when every corner lies in front of the
    eye (the bounding-rectangle test of Hearn & Baker 13-10), else every pixel."""
    h, w = shape
    lo = np.full(2, np.inf)
    hi = np.full(2, -np.inf)
    for s in solids:
        a, b = s.bounds()
        corners = np.array([[x, y, z] for x in (a[0], b[0]) for y in (a[1], b[1])
                            for z in (a[2], b[2])])
        with np.errstate(all="ignore"):
            hom = corners @ clip[:, :3].T + clip[:, 3]
            dev = hom[:, :2] / hom[:, 3:] * scale[:2] + offset[:2]
        if not (np.isfinite(corners).all() and (hom[:, 3] > 0).all()
                and np.isfinite(dev).all()):
            lo[:], hi[:] = -np.inf, np.inf
            break
        lo, hi = np.minimum(lo, dev.min(axis=0)), np.maximum(hi, dev.max(axis=0))
    x0, y0 = (max(int(np.floor(c)), 0) if np.isfinite(c) else 0 for c in lo)
    x1, y1 = (min(int(np.ceil(c)), n - 1) if np.isfinite(c) else n - 1 for c, n in
              zip(hi, (w, h)))
    if x0 > x1 or y0 > y1:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    ys, xs = np.divmod(np.arange((y1 - y0 + 1) * (x1 - x0 + 1)), x1 - x0 + 1)
    return ys + y0, xs + x0


def cast(scene: "ScreenScene", solids: Sequence[Solid], depth: F64) -> Hits:
    """Cast every pixel's ray of ``scene`` (its device and camera mapping) against
    ``solids``; :class:`Hits` where a solid is nearer than ``depth`` (H, W)."""
    from ..csg import union
    from ..raytrace.render import primary_rays
    from .program import Program, flatten

    program = Program(union(*solids))
    clip, scale, offset = scene.mapping
    ys, xs = pixels(solids, clip, scale, offset, depth.shape)
    origins, directions = primary_rays(scene, xs, ys)
    t, code, normal = program.cast(origins, directions)
    points = origins + np.where(code >= 0, t, 0.0)[:, None] * directions
    with np.errstate(all="ignore"):
        hom = points @ clip[:, :3].T + clip[:, 3]
        z = hom[:, 2] / hom[:, 3] * scale[2] + offset[2]
        seen = (code >= 0) & (hom[:, 3] > 0) & (hom[:, 2] >= 0) & (hom[:, 2] <= hom[:, 3]) \
            & (z < depth[ys, xs])
    prim = program.primitive(code[seen])
    # each primitive's solid: the solids' primitives are numbered one solid after another
    sizes = [len(flatten(s)[1]) for s in solids]
    owner = np.repeat(np.arange(len(solids)), sizes)
    n = normal[seen]
    d = directions[seen]
    n *= np.where((n * d).sum(axis=1) > 0, -1.0, 1.0)[:, None]
    return Hits(ys[seen], xs[seen], points[seen], n, d, z[seen], owner[prim],
                program.materials, prim, program)


def local_light(scene: "ScreenScene", hits: Hits, shading: "ShadingOptions") -> F64:
    """The illumination model at the hits (linear RGB, (M, 3)), primitive by
    primitive's material (its color decoded with the shading's gamma, as a mesh's);
    unlit colors for ``shading="none"``."""
    from ..lighting import intensity
    from ..shading import decode

    out = np.empty((len(hits.ys), 3))
    for k in np.unique(hits.primitive):
        sel = hits.primitive == k
        m = hits.materials[k]
        color = decode(np.asarray(m.color, np.float64), shading.gamma)
        if shading.model == "none":
            out[sel] = color
            continue
        vis = None if shading.shadows is None else shading.shadows(hits.points[sel])
        out[sel] = intensity(hits.points[sel], hits.normals[sel], scene.eye, list(shading.lights),
                             m, specular=shading.specular, color=np.broadcast_to(color, (int(sel.sum()), 3)),
                             visibility=vis)
    return out


def mark(hits: Hits, facets: NDArray[np.int32], depth: F64
         ) -> Tuple[NDArray[np.int32], F64, I64]:
    """``facets`` (-1 where a solid is seen) and ``depth`` (H, W) with the hits in
    front, and the solid seen at each pixel (-1: none)."""
    seen = np.full(depth.shape, -1, np.int64)
    if len(hits.ys):
        facets = facets.copy()
        depth = depth.copy()
        facets[hits.ys, hits.xs] = -1
        depth[hits.ys, hits.xs] = hits.depth
        seen[hits.ys, hits.xs] = hits.solid
    return facets, depth, seen


def draw(fb: "FrameBuffer", scene: "ScreenScene", solids: Sequence[Solid],
         shading: "ShadingOptions",
         facets: NDArray[np.int32], depth: F64) -> Tuple[NDArray[np.int32], F64, I64]:
    """Draw ``solids`` over what the method drew of the meshes (``facets``, ``depth``:
    (H, W)) where they are nearer: returns :func:`mark`'s arrays."""
    from ..shading.compose import store

    hits = cast(scene, solids, depth)
    if len(hits.ys):
        store(fb, hits.ys, hits.xs, local_light(scene, hits, shading), shading.gamma)
    return mark(hits, facets, depth)
