"""The ray tree of one pixel's primary ray (Whitted 1980; Hearn & Baker 14-6): every
surface the primary ray crosses, then each ray the tracer follows -- reflected,
refracted and shadow rays with their depth -- and the intensities summed.  The rows
are the log of the tracer kernel itself (:mod:`scanline._kernels.raytrace`), run as
Python on the one sample."""

import math
from typing import TYPE_CHECKING, Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from .._typing import Color
from .table import Table

if TYPE_CHECKING:
    from ..lighting.lights import Light
    from ..lighting.material import Material
    from ..mesh.mesh import Mesh
    from ..projection.camera import Camera
    from ..raytrace.render import Traced
    from ..screen import ScreenScene

#: The built-in scene's device size.
WIDTH, HEIGHT = 32, 24

KINDS = ("primary", "reflected", "refracted", "shadow")


def scene() -> Tuple[List["Mesh"], List["Material"], List["Light"], "Camera"]:
    """The built-in scene: a gray floor, a mirror sphere and a glass sphere (index
    1.5) under a point light, seen from above the floor: ``(meshes, materials,
    lights, camera)``."""
    import scanline as sl

    lit = sl.lighting
    floor = sl.mesh.Mesh([(-4, -1, -4), (4, -1, -4), (4, -1, 4), (-4, -1, 4)], [(3, 2, 1, 0)])
    meshes: List["Mesh"] = [floor, sl.mesh.sphere(1.0, center=(-1.2, 0, 0), resolution=12),
              sl.mesh.sphere(0.8, center=(1.2, -0.2, 0.8), resolution=12)]
    materials = [lit.Material(color=(200, 200, 200)),
                 lit.Material(color=(255, 80, 80), kd=0.2, reflectivity=0.8),
                 lit.Material(kd=0.1, ks=0.5, shininess=60, transparency=0.9,
                              refractive_index=1.5)]
    lights: List["Light"] = [lit.AmbientLight(0.15), lit.PointLight((3, 5, 4), intensity=0.9)]
    camera = sl.Camera(eye=(0, 1.5, 6), target=(0, 0, 0))
    return meshes, materials, lights, camera


def ray_tracing(x: int = 20, y: int = 11,
                meshes: Union["Mesh", Sequence["Mesh"], None] = None,
                materials: Union["Material", Sequence["Material"], None] = None,
                lights: Optional[Sequence["Light"]] = None, camera: Optional["Camera"] = None,
                width: int = WIDTH, height: int = HEIGHT, max_depth: int = 5, seed: int = 0,
                gamma: float = 2.2, background: Color = (40, 60, 90)) -> Table:
    """The ray tree of the primary ray through pixel (``x``, ``y``), as
    ``sl.render(fb, meshes, camera, method="ray-tracing", shading="phong", ...)``
    follows it on a ``width`` x ``height`` frame buffer of color ``background``
    (default: the built-in scene of :func:`scene`).

    Rows, in the order the tracer takes the rays (depth first): ``ray`` (its number;
    shadow rays have none), ``parent``, ``kind`` (primary, reflected, refracted,
    shadow), ``depth`` (the primary ray is 1), ``t`` (the distance to its nearest
    hit; a shadow ray's to its light), ``face`` (hit; -1: none, the ray brings the
    background), ``light`` and ``through`` (a shadow ray's light and the fraction
    that reaches the point), ``weight`` (the product of the k_r S_s + k_t F and k_t (1 -
    F) factors down the tree; a list of three, red, green and blue, where a
    specular color tints it), ``I_r``, ``I_g``, ``I_b`` (the ray's own intensity:
    (1 - k_t) I_local, or the background or environment map) and ``sum_r``, ``sum_g``, ``sum_b``
    (the weighted intensities summed so far).  The notes list every intersection
    of the primary ray and the pixel's stored value.

    Parameters
    ----------
    x, y : int
        The pixel whose primary ray is traced (default (20, 11): through the glass
        sphere of the built-in scene).
    meshes : Mesh or sequence of Mesh, optional
        The scene (default: :func:`scene`'s floor, mirror sphere and glass sphere,
        with its materials, lights and camera where those are not given).
    materials : Material or sequence of Material, optional
        One material, or one per mesh (as :func:`scanline.render` takes them).
    lights : sequence of lights, optional
        The lights (default: the built-in scene's, or where ``meshes`` is given
        :func:`scanline.rendering.api.default_lights`: ambient light and a white
        light from above the viewer's left shoulder).
    camera : Camera, optional
        The camera; required when ``meshes`` is given.
    width, height : int
        The frame buffer (default :data:`WIDTH` x :data:`HEIGHT`, 32 x 24).
    max_depth : int
        The deepest ray followed (the primary ray is depth 1; default 5).
    seed : int
        The seed of the distributed rays' random numbers (default 0; the same seed
        gives the same table).
    gamma : float
        The display gamma the stored value is encoded with (default 2.2).
    background : color
        The frame buffer's background, which rays that meet nothing bring.

    Returns
    -------
    Table
        The columns above, one row per ray (shadow rays included), in the order the
        tracer follows them; empty when the primary ray meets nothing.

    Raises
    ------
    ArgumentTypeError
        ``width`` or ``height`` is not an integer, or an argument of the scene is
        of the wrong kind.
    ArgumentValueError
        (x, y) is not a pixel of the device; ``meshes`` given without ``camera``;
        an option out of range.

    References
    ----------
    T. Whitted, "An improved illumination model for shaded display",
    Communications of the ACM 23(6), 1980.

    Examples
    --------
    The primary ray through pixel (20, 11) meets the glass sphere; its shadow ray
    reaches the light unblocked (``through`` 1), and each ray adds its weight x I to
    the sums (0.007893 + 0.038366 x 0.016988 = 0.008545 for the reflected ray):

    >>> t = ray_tracing(20, 11)
    >>> for r in t.rows[:3]:
    ...     print(r["ray"], r["parent"], r["kind"], r["depth"], r["face"], r["through"],
    ...           round(r["sum_r"], 6))
    0 None primary 1 131 None 0.007893
    None 0 shadow 2 -1 1.0 0.007893
    1 0 reflected 2 -1 None 0.008545
    >>> len(ray_tracing(0, 23).rows)        # the top-left corner sees the sky only
    0
    """
    import scanline as sl

    from .._kernels import raytrace as k
    from ..rendering.api import default_lights
    from ..raytrace.render import primary_light, primary_rays, shadow_test, trace, traced
    from ..screen import prepare
    from ..shading import ShadingOptions
    from ..shading.compose import background_linear
    from ..visible import MethodOptions
    from ..visible.raycast import raycast

    width = v.positive_int("width", width)
    height = v.positive_int("height", height)
    for name, value, top in (("x", x, width), ("y", y, height)):
        if (not isinstance(value, (int, np.integer)) or isinstance(value, bool)
                or not 0 <= value < top):
            raise ArgumentValueError(f"{name} must be a pixel 0..{top - 1} of the {width} x "
                                     f"{height} device, got {v._show(value)}")
    given = meshes is not None
    if not given:
        meshes, own_materials, own_lights, own_camera = scene()
        materials = own_materials if materials is None else materials
        lights = own_lights if lights is None else lights
        camera = own_camera if camera is None else camera
    if camera is None:
        raise ArgumentValueError("camera must be given with meshes")
    options = MethodOptions(max_depth=max_depth, seed=seed)
    fb = sl.FrameBuffer(width, height, background=background)
    shading = ShadingOptions(model="phong", lights=lights if lights is not None else
                             default_lights(camera), gamma=gamma)
    screen = prepare(meshes, camera, width, height, materials)
    layer = raycast(screen)
    seen = int(layer.ids[y, x])
    first = int(screen.facet[seen]) if seen >= 0 else -1
    light = background_linear(fb, gamma)
    prepared = traced(screen, shading, light, max_depth, seed)     # options validated them
    origins, directions = primary_rays(screen, np.array([x]), np.array([y]))
    px, py = np.array([x]), np.array([y])
    local = primary_light(screen, layer, py, px, shading, prepared, light, twin=True) \
        if first >= 0 else np.zeros((1, 3))
    notes = [f"{len(screen.materials)} mesh(es), {screen.face_count} faces on {width} x "
             f"{height}; max_depth {options.max_depth}, seed {options.seed}, gamma {gamma}",
             f"primary ray through pixel ({x}, {y}): origin "
             f"{np.round(origins[0], 6).tolist()}, direction "
             f"{np.round(directions[0], 6).tolist()}"]
    notes.append("intersections of the primary ray (t, face): " + (
        ", ".join(f"({t:.6f}, {f})" for t, f in _crossings(prepared, screen, origins[0],
                                                            directions[0])) or "none"))
    shadow_rays = sum(max(int(g), 1) ** 2 for g in prepared.lights[:, k.GRID])
    log = np.zeros((k.MAX_RAYS * (1 + shadow_rays), k.LOG_COLUMNS))
    out, count = trace(prepared, origins, directions, np.array([first]), local,
                       np.array([y * width + x]), log=log)
    if count:
        # the primary hit's shadow rays: the shading stage's shadow test at the point
        point = origins[0] + log[0, 10] * directions[0]
        through = shadow_test(prepared, twin=True)(point[None])
        extra = np.zeros((len(through), k.LOG_COLUMNS))
        for s, fraction in enumerate(through):
            extra[s, [0, 1, 2, 3, 10, 11, 19, 20]] = [-1, 0, k.SHADOW, 2, math.nan, -1, s,
                                                      fraction[0]]
        log = np.concatenate([extra, log[:count]])     # (put after the primary below)
        count += len(extra)
    rows: List[Dict[str, Any]] = []
    total = np.zeros(3)
    # the kernel logs a point's shadow rays before the ray that found the point
    ordered: List[NDArray[np.float64]] = []
    waiting: List[NDArray[np.float64]] = []
    for r in log[:count]:
        if int(r[2]) == k.SHADOW:
            waiting.append(r)
        else:
            ordered += [r] + waiting
            waiting = []
    for r in ordered + waiting:
        kind = KINDS[int(r[2])]
        shadow = kind == "shadow"
        facet = int(r[11])
        weight = r[[12, 21, 22]]
        if not shadow:
            total += r[16:19]
        rows.append({
            "ray": None if shadow else int(r[0]), "parent": None if r[1] < 0 else int(r[1]),
            "kind": kind, "depth": int(r[3]),
            "t": float(r[10]) if math.isfinite(r[10]) else None if math.isnan(r[10]) else "inf",
            "face": int(screen.facet_face[facet]) if facet >= 0 else -1,
            "light": int(r[19]) if shadow else None,
            "through": float(r[20]) if shadow else None,
            "weight": None if shadow else float(weight[0]) if (weight == weight[0]).all()
            else weight.tolist(),
            "I_r": None if shadow else float(r[13]), "I_g": None if shadow else float(r[14]),
            "I_b": None if shadow else float(r[15]),
            "sum_r": float(total[0]), "sum_g": float(total[1]), "sum_b": float(total[2])})
    if first < 0:
        notes.append("the primary ray meets nothing: the pixel keeps the background")
    else:
        from ..shading import encode

        notes.append(f"pixel intensity I = sum of weight x I = {np.round(out[0], 6).tolist()}, "
                     f"stored {encode(out[0], gamma).tolist()} (gamma {gamma})")
    return Table(f"ray tracing, the ray tree of pixel ({x}, {y})",
                 ["ray", "parent", "kind", "depth", "t", "face", "light", "through", "weight",
                  "I_r", "I_g", "I_b", "sum_r", "sum_g", "sum_b"], rows, notes=notes)


def _crossings(prepared: "Traced", screen: "ScreenScene", origin: NDArray[np.float64],
               direction: NDArray[np.float64]) -> List[Tuple[float, int]]:
    """Every facet the ray crosses, (t, face) nearest first, by the tracer's own
    Moller-Trumbore test run on each triangle of its table."""
    from .._kernels._jit import python
    from .._kernels.bvh import inside, moller_trumbore

    test, hit = python(moller_trumbore), python(inside)
    tree = prepared.tree
    table = tree.table
    out: List[Tuple[float, int]] = []
    with np.errstate(all="ignore"):
        for row in range(len(table)):
            t, a, b = test(*origin, *direction, table, row)
            if hit(t, a, b, 0.0, math.inf):
                out.append((float(t), int(screen.facet_face[tree.order[row]])))
    return sorted(out)
