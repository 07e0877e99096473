"""The renderer's entry point, :func:`render`."""

import numpy as np

from .. import _validate as v
from ..draw._common import target
from ..draw3d.wireframe import depth_cue_intensities
from ..errors import ArgumentValueError
from ..lighting import AmbientLight, DirectionalLight
from ..lighting.lights import light_list
from ..lighting.model import SPECULAR
from ..shading import MODELS, gamma_value
from .methods import METHODS
from .prepare import prepare

#: The modes :func:`render` draws into.
MODES = ("L", "RGB", "RGBA")


def default_lights(camera):
    """Ambient light and one white directional light coming from above the viewer's
    left shoulder (the direction fixed in viewing coordinates)."""
    m = camera.projection.orientation @ camera.view_matrix
    travel = np.linalg.inv(m)[:3, :3] @ np.array([0.45, -0.55, -1.0])
    return [AmbientLight(0.2), DirectionalLight(direction=travel, intensity=0.9)]


def render(fb, meshes, camera, method="z-buffer", shading="gouraud", lights=None,
           cull_back_faces=False, depth_cue=None, *, materials=None, specular="phong",
           gamma=2.2, shadows=False, **method_options):
    """Render meshes seen by ``camera`` into ``fb`` by a visible-surface method.

    Parameters
    ----------
    fb : FrameBuffer
        Mode "L", "RGB" or "RGBA"; pixels where no surface is seen keep their value.
    meshes : Mesh or list of Mesh
    camera : Camera
    method : str
        A name in :data:`scanline.render.methods.METHODS`: "z-buffer" (Hearn &
        Baker 13-3), "a-buffer" (13-4: fragments per pixel, transparency and
        antialiased edges), "ray-casting" (13-10: one ray per pixel), "scan-line"
        (13-5), "area-subdivision" (Warnock, 13-8), "depth-sort" (Newell, Newell and
        Sancha, 13-6), "bsp" (13-7), "painter" (one depth key per face: the
        counter-example). See :mod:`scanline.render.hidden` and
        :mod:`scanline.visible`; ``scanline.render.methods.PRECISION`` says which
        decide at image and which at object precision.
    shading : {"flat", "gouraud", "phong", "fast-phong"}
        Hearn & Baker, section 14-5 (see :mod:`scanline.shading`).
    lights : list of lights, optional
        From :mod:`scanline.lighting`; default: ambient 0.2 and a white directional
        light from above the viewer's left shoulder.
    cull_back_faces : bool
        Drop the faces whose outward normal points away from the viewer (the V . N
        test, Hearn & Baker 13-2) before any other method runs.
    depth_cue : bool or (near, far), optional
        Blend toward the background with the distance (section 9-1): factor
        ``near`` (1.0) at the nearest visible point, ``far`` (0.25) at the farthest.
    materials : Material or list of Material (one per mesh), optional
        Default ``Material()``; a mesh's own colors replace the material's color.
    specular : {"phong", "blinn"}
        The specular term: (V . R)^n or Blinn's (N . H)^n.
    gamma : float
        The display gamma the linear intensities are encoded with (1: none).
    shadows : bool
        Shadow maps for the lights made with ``shadows=True`` (Williams 1978).
    **method_options
        Options of the method (``samples`` for the A-buffer).

    Returns
    -------
    Rendering
        The depth buffer, the visible-face buffer and the prepared scene.

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
    """
    target(fb)
    if fb.mode not in MODES:
        raise ArgumentValueError(f"sl.render draws into modes {', '.join(MODES)}; the frame "
                                 f"buffer is mode {fb.mode!r}")
    if method not in METHODS:
        raise ArgumentValueError(f"method must be one of {', '.join(sorted(METHODS))}, got "
                                 f"{v._show(method)}")
    v.choice("shading", shading, MODELS)
    v.choice("specular", specular, SPECULAR)
    if not isinstance(cull_back_faces, bool):
        raise ArgumentValueError(f"cull_back_faces must be True or False, got "
                                 f"{v._show(cull_back_faces)}")
    from ..projection import Camera

    if not isinstance(camera, Camera):
        from ..errors import ArgumentTypeError

        raise ArgumentTypeError(f"camera must be a scanline.Camera, got {v._show(camera)}")
    lights = default_lights(camera) if lights is None else light_list(lights)
    options = dict(lights=lights, shading=shading, specular=specular,
                   gamma=gamma_value(gamma), depth_cue=depth_cue_intensities(depth_cue))
    scene = prepare(meshes, camera, fb.width, fb.height, materials, cull_back_faces)
    if shadows:
        from ..lighting.shadow import ShadowMaps

        options["shadows"] = ShadowMaps(meshes, scene, lights)
    options.update(method_options)
    return METHODS[method](scene, fb, options)
