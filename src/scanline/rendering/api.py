"""The renderer's entry point, :func:`render`: it orders the passes of the one 3-D
pipeline and does nothing else (``docs/architecture.md``):

1. the shadow maps of the lights that cast shadows (:mod:`scanline.rendering.shadows`);
2. the preparation, :func:`scanline.screen.prepare`: the screen-space scene;
3. the visible-surface method of :data:`scanline.visible.METHODS` on the scene's
   opaque facets (the A-buffer, which resolves transparency itself, on all);
4. the shading, :func:`scanline.shading.shade` (or :func:`~scanline.shading.composite`
   for layers of fragments);
5. the transparent layer: the nearest transparent surface in front of what the method
   found, blended over it (Hearn & Baker 14-5).
"""

import math
from dataclasses import replace
from typing import TYPE_CHECKING, Any, Iterable, Optional, Sequence, Tuple, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..depthbuffer import DepthBuffer
from ..draw._common import target
from ..errors import ArgumentValueError
from ..framebuffer import FrameBuffer
from ..mesh import Mesh
from ..projection import Camera
from .options import RenderOptions
from .result import Rendering

if TYPE_CHECKING:
    from ..lighting import AmbientLight, DirectionalLight
    from ..screen.scene import ScreenScene
    from ..visible import Fragments, MethodOptions
    from ..visible.visibility import Layer

#: The modes :func:`render` draws lit surfaces into ("none" shading: every mode).
MODES = ("L", "RGB", "RGBA")


def default_lights(camera: Camera) -> Tuple["AmbientLight", "DirectionalLight"]:
    """Ambient light and one white directional light coming from above the viewer's
    left shoulder (the direction fixed in viewing coordinates).

    Parameters
    ----------
    camera : Camera
        The viewer.

    Returns
    -------
    (AmbientLight, DirectionalLight)
        I_a = 0.2, and I_l = 0.9 traveling along (0.45, -0.55, -1) in viewing
        coordinates (Hearn & Baker 14-1, 14-2).

    Examples
    --------
    A camera on +z looking at the origin views along the world's axes, so the light
    travels along (0.45, -0.55, -1) / |(0.45, -0.55, -1)| = / 1.22678:

    >>> import scanline as sl
    >>> ambient, sun = sl.rendering.default_lights(sl.Camera(eye=(0, 0, 5), target=(0, 0, 0)))
    >>> ambient.intensity.tolist(), sun.direction.round(4).tolist()
    ([0.2, 0.2, 0.2], [0.3668, -0.4483, -0.8151])
    """
    from ..lighting import AmbientLight, DirectionalLight

    m = camera.projection.orientation @ camera.view_matrix
    travel = np.linalg.inv(m)[:3, :3] @ np.array([0.45, -0.55, -1.0])
    return (AmbientLight(0.2), DirectionalLight(direction=travel, intensity=0.9))


@v.keywords
def render(fb: FrameBuffer, meshes: Union[Mesh, Iterable[Mesh]], camera: Camera, *,
           method: str = "z-buffer", shading: str = "gouraud",
           lights: Optional[Sequence[Any]] = None, materials: Any = None, colors: Any = None,
           specular: str = "phong", gamma: float = 2.2, cull_back_faces: bool = False,
           crease_angle: Optional[float] = math.radians(30),
           depth_cue: Union[None, bool, Tuple[float, float]] = None, shadows: bool = False,
           samples: Optional[int] = None, layers: Optional[int] = None,
           key: Optional[str] = None, split_cycles: Optional[bool] = None,
           max_pieces: Optional[int] = None, max_work: Optional[int] = None,
           fallback: Optional[str] = None, antialias: int = 1,
           texture_mapping: str = "perspective", max_depth: Optional[int] = None,
           seed: Optional[int] = None) -> Rendering:
    """Render meshes seen by ``camera`` into ``fb`` by a visible-surface method.

    Parameters
    ----------
    fb : FrameBuffer
        Mode "L", "RGB" or "RGBA" (any mode with ``shading="none"``); pixels where no
        surface is seen keep their value.
    meshes : Mesh or list of Mesh
        Solids (:mod:`scanline.solids`, CSG trees of :mod:`scanline.csg`) may be given
        among them: ``method="ray-casting"`` and ``"ray-tracing"`` draw their exact
        surfaces (``docs/solids.md``); the other methods refuse them.
    camera : Camera
    method : str
        A name in :data:`scanline.visible.METHODS`: "z-buffer" (Hearn & Baker 13-3),
        "a-buffer" (13-4: fragments per pixel, transparency and antialiased edges),
        "ray-casting" (13-10: one ray per pixel), "ray-tracing" (14-6: the ray
        caster's rays followed by shadow, reflected and refracted rays,
        :mod:`scanline.raytrace`), "scan-line" (13-5),
        "area-subdivision" (Warnock, 13-8), "depth-sort" (Newell, Newell and Sancha,
        13-6), "bsp" (13-7), "octree" (13-10: an octree of the viewing volume
        traversed front to back, covered regions skipped; :mod:`scanline.octree`),
        "painter" (one depth key per face: the counter-example).  ``scanline.visible.PRECISION`` says which decide at image
        and which at object precision.
    shading : {"gouraud", "flat", "phong", "fast-phong", "none"}
        Hearn & Baker, section 14-5 (see :mod:`scanline.shading`); "none": each
        surface shows its color, unlit.
    lights : list of lights, optional
        From :mod:`scanline.lighting`; default: ambient 0.2 and a white directional
        light from above the viewer's left shoulder.
    materials : Material or list of Material (one per mesh), optional
        Default ``Material()``; a mesh's own colors replace the material's color.
    colors : color, or list of colors (one per mesh or one per face), optional
        The surfaces' color S_d, instead of the meshes' and the materials' colors.
    specular : {"phong", "blinn"}
        The specular term: (V . R)^n or Blinn's (N . H)^n.
    gamma : float
        The display gamma the linear intensities are encoded with (1: none).
    cull_back_faces : bool
        Drop the faces whose outward normal points away from the viewer (the V . N
        test, Hearn & Baker 13-2) before any method runs.
    depth_cue : bool or (near, far), optional
        Blend toward the background with the distance (section 9-1): factor
        ``near`` (1.0) at the nearest visible point, ``far`` (0.25) at the farthest.
    shadows : bool
        Shadow maps for the lights made with ``shadows=True`` (Williams 1978).
    samples, layers : int, optional
        A-buffer: samples per pixel side (default 3) and most layers (default 8).
    key : {"farthest", "mean"}, optional
        Painter: each polygon's sort key.
    split_cycles : bool, optional
        Depth sort: split cyclic or intersecting polygons (default True).
    max_pieces : int, optional
        Depth sort and BSP: most pieces the splitting may make.
    max_work : int, optional
        Depth sort: the bound of its time, in surfaces compared (default 2,000,000 +
        100 per polygon, seconds at most).
    antialias : int
        Supersampling: each pixel the mean of ``antialias`` x ``antialias`` samples,
        averaged as light (1: none, one sample at the pixel's center; at most 8).
        Any method; ``faces`` and ``depth`` are then the central samples'.
    fallback : str, optional
        A method to draw with when ``method`` gives up on the scene (a depth sort
        past ``max_pieces`` or ``max_work``, a BSP tree past ``max_pieces``), e.g.
        "z-buffer"; a :class:`~scanline.errors.ScanlineWarning` says so, and the
        result's ``method`` names the one that drew.  Default: the error is raised.
    max_depth : int, optional
        Ray tracing: the most levels of the ray tree (1..64, default 5; the primary
        ray is level 1).  Octree: the most levels of the viewing volume's octree
        (1..64, default :data:`scanline.visible.octree.DEPTH`).
    seed : int, optional
        Ray tracing: the seed of the random numbers of area lights' soft shadows and
        glossy reflection (default 0): the same seed, the same image.
    texture_mapping : {"perspective", "affine"}
        How the materials' texture coordinates are interpolated: perspective-correct
        (the default), or affine in screen space (to show the error it makes; Hearn
        & Baker 14-9; see :mod:`scanline.shading.surface`).

    Returns
    -------
    Rendering
        The faces seen, the depth buffer and the prepared scene.

    Raises
    ------
    ArgumentTypeError
        ``fb`` not a FrameBuffer, ``camera`` not a Camera, or a keyword it does not take.
    ArgumentValueError
        Lit shading or antialiasing into a mode other than L, RGB, RGBA, an unknown
        method, shading or specular term, or an option outside its range
        (:class:`~scanline.visible.MethodOptions`, :class:`~scanline.shading.ShadingOptions`).
    DepthSortLoopError, BSPTooLargeError
        The depth sort or the BSP tree gave up on the scene, unless ``fallback`` names a
        method to draw it instead.
    MemoryBudgetError
        A scene or an image too large for the memory budget.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(9, 9, mode="L")
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-1.5, -1.5, 1.5, 1.5)))
    >>> r = sl.render(fb, sl.mesh.cube(2), cam, shading="flat", gamma=1,
    ...               lights=[sl.lighting.AmbientLight(1.0)],
    ...               materials=sl.lighting.Material(ka=1.0, kd=0, ks=0))
    >>> print(sl.text_image(fb))
    ---------
    ---------
    --#####--
    --#####--
    --#####--
    --#####--
    --#####--
    ---------
    ---------
    >>> r
    <Rendering method='z-buffer' 9x9: 1 mesh(es), 6 faces, 25 of 81 pixels covered>
    """
    from ..draw3d.wireframe import depth_cue_intensities
    from ..shading import ShadingOptions
    from ..visible import MethodOptions

    target(fb)
    if not isinstance(camera, Camera):
        from ..errors import ArgumentTypeError

        raise ArgumentTypeError(f"camera must be a scanline.Camera, got {v._show(camera)}")
    options = RenderOptions(
        method=method,
        visible=MethodOptions(samples=samples, layers=layers, key=key,
                              split_cycles=split_cycles, max_pieces=max_pieces,
                              max_work=max_work, max_depth=max_depth, seed=seed),
        shading=ShadingOptions(model=shading,
                               lights=default_lights(camera) if lights is None else lights,
                               specular=specular, gamma=gamma,
                               depth_cue=depth_cue_intensities(depth_cue),
                               texture_mapping=texture_mapping),
        cull_back_faces=cull_back_faces, shadows=shadows, fallback=fallback,
        antialias=antialias)
    if options.shading.model != "none" and fb.mode not in MODES:
        raise ArgumentValueError(f"sl.render draws lit surfaces into modes {', '.join(MODES)}; "
                                 f"the frame buffer is mode {fb.mode!r} (shading='none' draws "
                                 f"the surfaces' colors into any mode)")
    if options.antialias > 1 and fb.mode not in MODES:
        raise ArgumentValueError(f"antialias={antialias} averages samples: modes "
                                 f"{', '.join(MODES)}, not mode {fb.mode!r}")
    return run(fb, meshes, camera, options, materials=materials, colors=colors,
               crease_angle=crease_angle)


def run(fb: FrameBuffer, meshes: Any, camera: Camera, options: RenderOptions,
        materials: Any = None, colors: Any = None,
        crease_angle: Optional[float] = math.radians(30)) -> Rendering:
    """The passes of :func:`render` with its options already made
    (:class:`RenderOptions`).

    Parameters
    ----------
    fb : FrameBuffer
        Drawn into.
    meshes : Mesh, solid, or a list of them
        As :func:`scanline.render` takes them.
    camera : Camera
        The viewer.
    options : RenderOptions
        The method, its options, the shading, culling, shadows and antialiasing.
    materials, colors : optional
        As :func:`scanline.render` takes them.
    crease_angle : float or None
        As :func:`scanline.render` takes it.

    Returns
    -------
    Rendering
        What was drawn.

    Raises
    ------
    ArgumentValueError
        A method that cannot draw the scene (solids need a ray-casting method), or a
        supersampled render past the memory budget.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(4, 4, mode="L")
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> options = sl.rendering.RenderOptions(method="painter")
    >>> sl.rendering.run(fb, sl.mesh.cube(2), cam, options)
    <Rendering method='painter' 4x4: 1 mesh(es), 6 faces, 4 of 16 pixels covered>
    """
    from ..screen import prepare
    from ..shading import composite, shade
    from ..visible import METHODS, Fragments
    from ..visible.zbuffer import nearest

    from ..solids.render import check_method, split

    meshes, solids = split(meshes)
    check_method(options.method, solids)
    n = options.antialias
    scene = prepare(meshes, camera, fb.width, fb.height, materials, colors,
                    options.cull_back_faces, crease_angle)
    if n > 1:
        from ..budget import check
        from ..screen.prepare import PIXEL_BYTES

        check(PIXEL_BYTES * n * n * fb.width * fb.height, "antialias",
              f"{n} x {n} samples a pixel of a {fb.width} x {fb.height} render",
              "use fewer samples or a smaller image")
        target_fb = fb
        scene = scene.supersampled(n)
        fb = _finer(fb, n, layers=bool(scene.transparent.any())
                    or METHODS[options.method].transparency)
    shading = options.shading
    if options.shadows:
        from .shadows import ShadowMaps

        shading = replace(shading, shadows=ShadowMaps(meshes, scene, shading.lights))
    clear = scene.transparent
    name, layered, opaque, seen = _visible(scene, clear, options.method, options.visible,
                                           options.fallback)
    pieces = None
    if isinstance(seen, Fragments):
        facets, depth = composite(fb, scene, seen.bands, seen.samples, shading)
    elif METHODS[name].traced:
        from ..raytrace.render import shade as trace
        from ..solids.render import cast, mark

        hits = cast(opaque, solids, seen.depth) if solids else None
        facets = trace(fb, opaque, seen, shading, options.visible, hits)
        depth = seen.depth
    else:
        facets = shade(fb, opaque, seen, shading)
        depth, pieces = seen.depth, seen.pieces
    solid_map = None
    if solids and METHODS[name].traced:
        assert hits is not None                  # cast above: solids, a traced method
        facets, depth, solid_map = mark(hits, facets, depth)
    elif solids:
        from ..solids.render import draw

        facets, depth, solid_map = draw(fb, scene, solids, shading, facets, depth)
    if layered:
        glass = scene.with_triangles(clear)
        front = nearest(glass, zbuf=depth.copy())
        over, over_depth = composite(fb, glass, [(0, scene.height, [front])], 1, shading)
        facets = np.where(over >= 0, over, facets)
        depth = np.minimum(depth, over_depth)
    if n > 1:
        covered = facets >= 0 if solid_map is None else (facets >= 0) | (solid_map >= 0)
        _resolve(target_fb, fb, covered, n, shading.gamma)
        c = n // 2
        facets = np.ascontiguousarray(facets[c::n, c::n])
        depth = np.ascontiguousarray(depth[c::n, c::n])
        solid_map = None if solid_map is None else np.ascontiguousarray(solid_map[c::n, c::n])
        fb = target_fb
    return Rendering(name, fb, DepthBuffer.holding(depth), facets, scene, pieces, solid_map)


def _finer(fb: FrameBuffer, n: int, layers: bool) -> FrameBuffer:
    """A frame buffer ``n`` times finer than ``fb``; with ``layers`` (fragments blend
    over what lies behind them) holding its pixels, each an n x n block."""
    fine = FrameBuffer(fb.width * n, fb.height * n, mode=fb.mode)
    fine._background = fb._background.copy()     # what the ray tracer's escaping rays bring
    if layers:
        fine._raster()[0][...] = np.repeat(np.repeat(fb._raster()[0], n, axis=0), n, axis=1)
    return fine


def _resolve(fb: FrameBuffer, fine: FrameBuffer, covered: NDArray[np.bool_], n: int,
             gamma: float) -> None:
    """Each pixel of ``fb`` with a ``covered`` sample the mean of its n x n samples in
    ``fine`` (an uncovered one counting as the pixel's present value), averaged as
    light: supersampling (Hearn & Baker 4-8; 14, area sampling), in one compiled pass
    (:func:`scanline._kernels.supersample.resolve_samples`)."""
    from .._kernels._threads import call_in_bands
    from .._kernels.supersample import resolve_samples
    from ..shading import decode
    from ..shading.buffer import gamma_tables

    linear = decode(np.arange(256) / 255.0, gamma)
    call_in_bands(resolve_samples, 2 * n * n * fb.width * fb.height, fine._raster()[0],
                  np.ascontiguousarray(covered), n, linear, *gamma_tables(gamma),
                  fb._raster()[0])


def _visible(scene: "ScreenScene", clear: NDArray[np.bool_], name: str,
             options: "MethodOptions", fallback: Optional[str] = None
             ) -> Tuple[str, bool, "ScreenScene", Union["Layer", "Fragments"]]:
    """Run the method ``name`` on the scene's opaque facets (all, for a method that
    resolves transparency itself; ``clear``: the transparent facets): ``(name,
    layered, the scene it ran on, what it found)``.  Where it gives up and
    ``fallback`` names a method, that one runs instead, with a warning."""
    import warnings

    from ..errors import BSPTooLargeError, DepthSortLoopError, ScanlineWarning
    from ..visible import METHODS, MethodOptions

    method = METHODS[name]
    layered = bool(clear.any()) and not method.transparency
    opaque = scene.with_triangles(~clear) if layered else scene
    try:
        return name, layered, opaque, method.find(opaque, options)
    except (DepthSortLoopError, BSPTooLargeError) as error:
        if fallback is None:
            raise
        warnings.warn(f"method={name!r} gave up on this scene ({error}); drawn by "
                      f"fallback={fallback!r}", ScanlineWarning, stacklevel=4)
        return _visible(scene, clear, fallback, MethodOptions())

