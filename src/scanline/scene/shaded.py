"""Shaded surfaces in a scene (schema version 2): the top-level ``lights``,
``materials``, ``method``, ``shading`` and ``radiosity`` keys, and the ``material``
key of a mesh primitive, which makes the mesh a surface drawn by
:func:`scanline.render` instead of a wireframe (with ``radiosity``, by
:func:`scanline.radiosity.solve` and Gouraud shading of its node radiosities; the
mesh's ``emission`` and ``reflectance`` keys give its radiosity values).  See
docs/scene-format.md, "Lights, materials and shading" and "Radiosity".

Surfaces are drawn first, through the camera of their segment (each camera's
surfaces share one depth test), on the whole canvas; the display file (wireframes,
lines, text) is drawn over them.
"""

from typing import TYPE_CHECKING, Any, Callable

import numpy as np

from .. import lighting
from . import schema

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer
    from ..lighting.lights import Light
    from ..mesh import Mesh
    from ..projection import Camera
    from ..texture import CubeMap, Texture

#: Top-level keys this module reads.
KEYS = {"lights", "materials", "method", "shading", "radiosity"}
#: Light types and their keys (besides ``type``).
LIGHTS = {
    "ambient": {"intensity"},
    "directional": {"direction", "intensity", "shadows"},
    "point": {"position", "intensity", "attenuation", "shadows"},
    "spot": {"position", "direction", "intensity", "angle", "exponent", "attenuation",
             "shadows"},
    "area": {"corner", "edge_u", "edge_v", "intensity", "samples", "shadows"},
}
#: Keys a light of each type must have.
REQUIRED = {"point": ("position",), "spot": ("position", "direction"),
            "area": ("corner", "edge_u", "edge_v")}
MATERIAL = {"ka", "kd", "ks", "shininess", "color", "specular_color", "transparency",
            "reflectivity", "refractive_index", "roughness", "texture", "bump", "bump_scale",
            "environment"}
#: The material keys that take a texture: an image file (relative to the scene file),
#: or a procedural texture ``{procedural = "checker" | "marble" | "wood", ...}``; the
#: environment also a cube map, ``{cube = [six files] | "cross file", filter = ...}``.
MAPS = ("texture", "bump", "environment")
#: Keys of a cube map table.
CUBE = {"cube", "filter"}
PROCEDURAL = ("checker", "marble", "wood")
SHADING = {"model", "specular", "gamma", "cull_back_faces", "depth_cue", "max_depth", "seed"}
#: Keys of the radiosity table: :func:`scanline.radiosity.solve`'s options, and the
#: ``exposure`` and ``antialias`` of the drawing (:meth:`Radiosity.render`).
RADIOSITY = {"subdivisions", "method", "form_factors", "resolution", "tolerance",
             "max_iterations", "shooting_group", "exposure", "antialias"}


def _tuples(value: Any) -> Any:
    if isinstance(value, list):
        return tuple(_tuples(x) for x in value)
    return value


def light(data: object, path: str) -> "Light":
    """A light table -> a light of :mod:`scanline.lighting`.

    Parameters
    ----------
    data : object
        A ``lights`` entry: ``type`` (one of :data:`LIGHTS`) and that light's keys.
    path : str
        Its key path, named in error messages.

    Returns
    -------
    AmbientLight, DirectionalLight, PointLight, SpotLight or AreaLight

    Raises
    ------
    SceneError
        If the type is unknown, a required key is missing or a value is invalid.

    Examples
    --------
    >>> from scanline.scene.shaded import light
    >>> light({"type": "point", "position": [0, 5, 5]}, "lights[0]").position
    array([0., 5., 5.])
    >>> light({"type": "spot", "position": [0, 5, 5]}, "lights[1]")
    Traceback (most recent call last):
    ...
    scanline.scene.files.SceneError: lights[1] needs the key 'direction'
    """
    t = schema._table(data, path, set().union(*LIGHTS.values()) | {"type"}, ("type",))
    kind = t["type"]
    if not isinstance(kind, str) or kind not in LIGHTS:
        schema._fail(f"{path}.type", f"must be one of {', '.join(LIGHTS)}; got {kind!r}")
    schema._table(data, path, LIGHTS[kind] | {"type"}, REQUIRED.get(kind, ()))
    args = {k: (schema.angle(x, f"{path}.{k}") if k == "angle" else _tuples(x))
            for k, x in t.items() if k != "type"}
    make: Callable[..., Light] = {"ambient": lighting.AmbientLight, "directional": lighting.DirectionalLight,
            "point": lighting.PointLight, "spot": lighting.SpotLight,
            "area": lighting.AreaLight}[kind]
    return schema._call(path, make, **args)


def texture(value: object, path: str, base: str | None = None) -> "Texture":
    """A material's texture key -> a :class:`scanline.Texture`: an image file's name
    (relative to the scene file's folder ``base``), or a table naming a procedural
    texture of :mod:`scanline.texture` and its keywords (``size``, ``seed``,
    ``filter``, ``wrap`` ...).

    Parameters
    ----------
    value : object
        The material's ``texture`` (or ``bump``) value.
    path : str
        Its key path, named in error messages.
    base : str, optional
        The scene file's folder.

    Returns
    -------
    Texture

    Raises
    ------
    SceneError
        If the value is neither, the file cannot be read, or a keyword is invalid.

    Examples
    --------
    >>> from scanline.scene.shaded import texture
    >>> texture({"procedural": "checker", "size": 8, "squares": 2}, "texture").image.shape
    (8, 8, 3)
    """
    import inspect
    import os

    from .. import texture as tx

    if isinstance(value, str) and value:
        full = value if os.path.isabs(value) or base is None else os.path.join(base, value)
        return schema._call(path, tx.Texture, full)
    if not isinstance(value, dict) or value.get("procedural") not in PROCEDURAL:
        schema._fail(path, "must be an image file's name or a table {procedural = "
                      f"{' | '.join(repr(p) for p in PROCEDURAL)}, ...}}, got {value!r}")
    make: Callable[..., Texture] = getattr(tx, value["procedural"])
    known = (set(inspect.signature(make).parameters) - {"texture"}) | {"filter", "wrap"}
    schema._table(value, path, known | {"procedural"})
    return schema._call(path, make, **{k: _tuples(x) for k, x in value.items()
                                  if k != "procedural"})


def environment(value: object, path: str,
                base: str | None = None) -> "CubeMap | Texture":
    """A material's ``environment`` key -> a :class:`scanline.texture.CubeMap` for a
    table ``{cube = [+x, -x, +y, -y, +z, -z files] | "cross file", filter = ...}``
    (files relative to the scene file's folder ``base``), else a latitude-longitude
    texture (:func:`texture`).

    Parameters
    ----------
    value : object
        The material's ``environment`` value.
    path : str
        Its key path, named in error messages.
    base : str, optional
        The scene file's folder.

    Returns
    -------
    CubeMap or Texture

    Raises
    ------
    SceneError
        If the cube is not six files or one cross image, or a file cannot be read.

    Examples
    --------
    >>> from scanline.scene.shaded import environment
    >>> type(environment({"procedural": "marble", "size": 8}, "environment")).__name__
    'Texture'
    >>> environment({"cube": ["sky.png"]}, "materials.glass.environment")
    Traceback (most recent call last):
    ...
    scanline.scene.files.SceneError: materials.glass.environment.cube must be six image files (+x, -x, +y, -y, +z, -z) or one cross image, got 1
    """
    import os

    from ..texture import CubeMap

    if not (isinstance(value, dict) and "cube" in value):
        return texture(value, path, base)
    t = schema._table(value, path, CUBE, ("cube",))
    faces = t["cube"]

    def place(name: object, where: str) -> str:
        if not isinstance(name, str) or not name:
            schema._fail(where, f"must be an image file's name, got {name!r}")
        return name if os.path.isabs(name) or base is None else os.path.join(base, name)

    if isinstance(faces, list):
        if len(faces) != 6:
            schema._fail(f"{path}.cube", f"must be six image files (+x, -x, +y, -y, +z, -z) or "
                                    f"one cross image, got {len(faces)}")
        faces = [place(f, f"{path}.cube[{i}]") for i, f in enumerate(faces)]
    else:
        faces = place(faces, f"{path}.cube")
    return schema._call(path, CubeMap, faces, **{k: x for k, x in t.items() if k != "cube"})


class Shading:
    """What a scene's top-level shading keys say: ``lights`` (None: the renderer's
    default), ``materials`` (name -> Material), ``options`` for
    :func:`scanline.render`, and the ``surfaces`` the mesh primitives add.  ``base``:
    the scene file's folder, where texture files are found.

    Parameters
    ----------
    data : dict
        The scene's data (its keys :data:`KEYS` are read).
    base : str, optional
        The scene file's folder.

    Raises
    ------
    SceneError
        If a light, material, the method or the shading table is invalid.

    Examples
    --------
    >>> from scanline.scene.shaded import Shading
    >>> sh = Shading({"materials": {"red": {"color": "red"}}, "shading": "flat"})
    >>> sorted(sh.materials), sh.options, sh.lights
    (['red'], {'method': 'z-buffer', 'shading': 'flat'}, None)
    """

    def __init__(self, data: dict[str, Any], base: str | None = None) -> None:
        self.lights: list[Light] | None = None
        if "lights" in data:
            self.lights = [light(x, f"lights[{i}]")
                           for i, x in enumerate(schema._list(data["lights"], "lights"))]
        self.materials: dict[str, lighting.Material] = {}
        mats = data.get("materials", {})
        if not isinstance(mats, dict):
            schema._fail("materials", "must be a table of named materials ([materials.NAME])")
        for name, m in mats.items():
            t = schema._table(m, f"materials.{name}", MATERIAL)
            args = {k: (environment if k == "environment" else texture)(
                        x, f"materials.{name}.{k}", base) if k in MAPS else _tuples(x)
                    for k, x in t.items()}
            self.materials[name] = schema._call(f"materials.{name}", lighting.Material, **args)
        from ..visible import METHODS
        from ..shading import MODELS

        method = data.get("method", "z-buffer")
        if not isinstance(method, str) or method not in METHODS:
            schema._fail("method", f"must be one of {', '.join(sorted(METHODS))}; got {method!r}")
        shading = data.get("shading", {})
        if isinstance(shading, str):
            shading = {"model": shading}
        t = schema._table(shading, "shading", SHADING)
        model = t.get("model", "gouraud")
        if not isinstance(model, str) or model not in MODELS:
            schema._fail("shading.model" if isinstance(data.get("shading"), dict) else "shading",
                    f"must be one of {', '.join(MODELS)}; got {model!r}")
        self.options: dict[str, Any] = {"method": method, "shading": model}
        if "specular" in t:
            if t["specular"] not in ("phong", "blinn"):
                schema._fail("shading.specular", f"must be 'phong' or 'blinn'; got {t['specular']!r}")
            self.options["specular"] = t["specular"]
        if "gamma" in t:
            from ..shading import gamma_value

            self.options["gamma"] = schema._call("shading.gamma", gamma_value,
                                            schema._real(t["gamma"], "shading.gamma"))
        if "cull_back_faces" in t:
            self.options["cull_back_faces"] = schema._flag(t["cull_back_faces"],
                                                      "shading.cull_back_faces")
        for key in ("max_depth", "seed"):          # ray tracing's, checked by render
            if key in t:
                self.options[key] = t[key]
        if "depth_cue" in t:
            from ..draw3d.wireframe import depth_cue_intensities

            cue = _tuples(t["depth_cue"])
            schema._call("shading.depth_cue", depth_cue_intensities, cue)
            self.options["depth_cue"] = cue
        self.radiosity: dict[str, Any] | None = None
        if "radiosity" in data:
            self.radiosity = _tuples(schema._table(data["radiosity"], "radiosity", RADIOSITY))
        self.surfaces: list[tuple[Mesh, lighting.Material, Camera]] = []
        self.values: list[tuple[str, Any, Any]] = []

    def surface(self, mesh: "Mesh", material: object, path: str, camera: "Camera",
                emission: object = None, reflectance: object = None) -> None:
        """Add ``mesh`` as a surface of the named ``material`` seen by ``camera``
        (``emission``, ``reflectance``: its radiosity values, None: no light, the
        material's kd x color).

        Parameters
        ----------
        mesh : Mesh
        material : object
            The primitive's ``material``: a name in :attr:`materials`.
        path : str
            The primitive's key path, named in error messages.
        camera : Camera
        emission, reflectance : object, optional
            The primitive's radiosity values: a number or [r, g, b].

        Raises
        ------
        SceneError
            If ``material`` names no material.

        Examples
        --------
        >>> import scanline as sl
        >>> from scanline.scene.shaded import Shading
        >>> sh = Shading({"materials": {"red": {"color": "red"}}})
        >>> camera = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
        >>> sh.surface(sl.mesh.cube(), "red", "segments[0].primitives[0]", camera)
        >>> len(sh.surfaces)
        1
        >>> sh.surface(sl.mesh.cube(), "blue", "segments[1].primitives[0]", camera)
        Traceback (most recent call last):
        ...
        scanline.scene.files.SceneError: segments[1].primitives[0].material names no material: 'blue'; materials: 'red'
        """
        if not isinstance(material, str) or material not in self.materials:
            schema._fail(f"{path}.material", f"names no material: {material!r}; materials: "
                            + (", ".join(repr(k) for k in self.materials) or
                               "none (add [materials.NAME])"))
        self.surfaces.append((mesh, self.materials[material], camera))
        self.values.append((path, _tuples(emission), _tuples(reflectance)))

    def draw(self, fb: "FrameBuffer") -> None:
        """Render the surfaces into ``fb``, camera by camera.

        Parameters
        ----------
        fb : FrameBuffer

        Examples
        --------
        Without surfaces nothing is drawn:

        >>> import scanline as sl
        >>> from scanline.scene.shaded import Shading
        >>> fb = sl.FrameBuffer(3, 2, background="black")
        >>> Shading({"shading": "flat"}).draw(fb)
        >>> print(sl.text_image(fb))
        ---
        ---
        """
        from ..rendering import render

        by_camera: dict[int, tuple[Camera, list[Mesh], list[lighting.Material]]] = {}
        for mesh, material, camera in self.surfaces:
            by_camera.setdefault(id(camera), (camera, [], []))
            by_camera[id(camera)][1].append(mesh)
            by_camera[id(camera)][2].append(material)
        for camera, meshes, mats in by_camera.values():
            if self.radiosity is None:
                render(fb, meshes, camera, lights=self.lights, materials=mats, **self.options)
        if self.radiosity is not None:
            self._radiosity(fb, self.radiosity)

    def _radiosity(self, fb: "FrameBuffer", table: dict[str, Any]) -> None:
        """Solve the radiosity of every surface together (the light goes from surface
        to surface whatever camera sees them) and draw the solution through each
        camera (``table``: the scene's radiosity table)."""
        import copy

        from .. import radiosity

        options = dict(table)
        draw = {k: options.pop(k) for k in ("exposure", "antialias") if k in options}
        meshes = []
        for mesh, material, _ in self.surfaces:
            mesh = copy.copy(mesh)
            mesh.material = material           # the default reflectance: kd x color
            meshes.append(mesh)
        pts = schema._call("radiosity", radiosity.patches, meshes, options.pop("subdivisions", 8))
        emission = np.zeros((len(pts), 3))
        reflectance = pts.reflectance.copy()
        for k, (path, e, r) in enumerate(self.values):
            on = pts.mesh == k
            if e is not None:
                emission[on] = schema._call(f"{path}.emission", _triple, "emission", e)
            if r is not None:
                reflectance[on] = schema._call(f"{path}.reflectance", _triple, "reflectance", r)
        pts = schema._call("radiosity", pts.with_values, emission, reflectance)
        solution = schema._call("radiosity", radiosity.solve, pts, **options)
        cameras = {id(camera): camera for _, _, camera in self.surfaces}
        for camera in cameras.values():
            schema._call("radiosity", solution.render, fb, camera, **draw)


def _triple(name: str, value: object) -> tuple[float, float, float]:
    """A radiosity value: one number or (r, g, b), as three floats."""
    from .. import _validate as v

    if isinstance(value, tuple) and len(value) == 3:
        r, g, b = value
        return v.number(f"{name}[0]", r), v.number(f"{name}[1]", g), v.number(f"{name}[2]", b)
    return (v.number(name, value),) * 3


def shading(data: dict[str, Any], base: str | None = None) -> Shading | None:
    """The :class:`Shading` of scene data (a dict), or None when it has no shading
    key and so no surfaces can be asked for (``base``: the scene file's folder).

    Parameters
    ----------
    data : dict
        The scene's data.
    base : str, optional
        The scene file's folder.

    Returns
    -------
    Shading or None

    Raises
    ------
    SceneError
        As :class:`Shading`.

    Examples
    --------
    >>> from scanline.scene.shaded import shading
    >>> shading({"version": 2}) is None
    True
    >>> shading({"version": 2, "method": "painter"}).options
    {'method': 'painter', 'shading': 'gouraud'}
    """
    if not any(k in data for k in KEYS):
        return None
    return Shading(data, base)
