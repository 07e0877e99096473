"""The scene schema, version 2: cameras, 3-D transformation steps and 3-D primitives
(meshes by file or by generator, 3-D polylines).  See docs/scene-format.md.

Every error is a :class:`SceneError` whose message starts with the key path of the
offending value (``cameras[0].projection.fov must ...``).
"""

import numbers
import os
from typing import TYPE_CHECKING, Any, Callable, Collection

import numpy as np
from numpy.typing import NDArray

from .. import transform3d as t3
from ..errors import ScanlineError
from .files import SceneError
from . import schema

if TYPE_CHECKING:
    from ..display import DisplayFile
    from ..mesh import Mesh
    from ..projection import Projection
    from .shaded import Shading

#: Keys of a camera.
CAMERA = {"name", "eye", "target", "up", "view_reference_point", "view_plane_normal",
          "view_up", "projection", "viewport", "keep_aspect"}
_VOLUME = {"window", "front", "back"}
#: Projection types and their keys (besides ``type``).
PROJECTIONS = {
    "perspective": {"fov", "aspect", "near", "far", "z_prp", "z_vp"} | _VOLUME,
    "frustum": {"prp", "z_vp"} | _VOLUME,
    "orthographic": {"view", "z_vp"} | _VOLUME,
    "isometric": set(_VOLUME),
    "dimetric": {"fz"} | _VOLUME,
    "trimetric": {"phi", "theta"} | _VOLUME,
    "oblique": {"kind", "phi", "alpha", "z_vp"} | _VOLUME,
    "parallel": {"direction", "z_vp"} | _VOLUME,
}
#: Keys given as angles ({degrees = x} or {radians = x}).
ANGLES = {"fov", "phi", "theta", "alpha", "angle"}

_LINE = {"color", "width", "cap", "join", "miter_limit", "dash", "dash_phase"}
#: Mesh generators and their keys.
GENERATORS = {
    "cube": {"size", "center"},
    "box": {"lo", "hi"},
    "sphere": {"radius", "center", "resolution"},
    "ellipsoid": {"radii", "center", "resolution"},
    "torus": {"major", "minor", "center", "resolution"},
    "superellipsoid": {"s1", "s2", "radii", "center", "resolution"},
    "supertoroid": {"s1", "s2", "r", "radii", "center", "resolution"},
    "sweep": {"kind", "profile", "vector", "axis", "angle", "steps", "closed", "caps"},
    "teapot": {"n", "parts"},
    "polygons": {"vertices", "faces"},
}
#: Keys of each 3-D primitive type besides ``type``.
PRIMITIVES = {
    "mesh": {"generator", "file", "transform", "depth_cue", "material", "emission",
             "reflectance"} | _LINE
            | set().union(*GENERATORS.values()),
    "polyline3d": {"points", "closed", "transform"} | _LINE,
}
_STEPS = ("translate", "rotate", "scale", "reflect", "shear", "matrix")
#: The largest tessellations a scene may ask for (a scene file is data: it must not
#: be able to ask for gigabytes).
LIMITS = {"resolution": 1024, "n": 64, "steps": 4096}

#: Bytes a scene keeps per mesh vertex, face and face index once the mesh is made
#: (positions, normals, faces, the edge table, the projected copy a drawing makes):
#: a scene's meshes together, with its canvas, must fit the memory budget (the
#: tessellation limits above are per mesh, not per scene).
KEPT_BYTES_PER_VERTEX = 80
KEPT_BYTES_PER_FACE = 16
KEPT_BYTES_PER_INDEX = 24


def _kept_bytes(n_vertices: int, n_faces: int, n_indices: int) -> int:
    return (n_vertices * KEPT_BYTES_PER_VERTEX + n_faces * KEPT_BYTES_PER_FACE
            + n_indices * KEPT_BYTES_PER_INDEX)


def _expected_size(gen: str, args: dict[str, Any]) -> tuple[int, int, int] | None:
    """(vertices, faces, face indices) the generator ``gen`` will make from
    ``args`` (the scene's keys as arguments), or None where it cannot say before
    making it; a bad resolution raises the generator's own error."""
    import inspect

    from ..mesh import shapes

    functions: dict[str, Callable[..., Mesh]] = {
        "sphere": shapes.sphere, "ellipsoid": shapes.ellipsoid,
        "superellipsoid": shapes.superellipsoid, "torus": shapes.torus,
        "supertoroid": shapes.supertoroid}
    function = functions.get(gen)
    if gen in ("cube", "box"):
        return 8, 6, 24
    if function is not None:
        res = args.get("resolution",
                       inspect.signature(function).parameters["resolution"].default)
        if gen in ("torus", "supertoroid"):
            return shapes.periodic_size(*shapes._resolution(res, 3))
        return shapes.closed_size(*shapes._resolution(res))
    if gen == "polygons":
        faces = args.get("faces")
        if isinstance(args.get("vertices"), (list, tuple)) and isinstance(faces, (list, tuple)):
            return (len(args["vertices"]), len(faces),
                    sum(len(f) if isinstance(f, (list, tuple)) else 1 for f in faces))
        return None
    if gen == "teapot":
        n = args.get("n", 6)
        k = int(n) if isinstance(n, numbers.Integral) and not isinstance(n, bool) else 0
        if k > 0:
            return 32 * (k + 1) ** 2, 64 * k * k, 192 * k * k
        return None
    profile = args.get("profile")
    n = len(profile) if isinstance(profile, (list, tuple)) else None
    if n is None:
        return None
    if args.get("kind", "rotational") == "translational":
        return 2 * n, n + 2, 6 * n
    steps = args.get("steps", 32)
    k = int(steps) if isinstance(steps, numbers.Integral) and not isinstance(steps, bool) else 0
    if k > 0:
        return (k + 1) * n, k * n, 4 * k * n
    return None


def _count(totals: dict[str, int] | None, path: str, size: tuple[int, int, int] | None,
           kept: bool = False) -> None:
    """Add a mesh of ``size`` = (vertices, faces, face indices) to the scene's
    ``totals`` after checking that the scene's memory -- what it keeps so far, and
    this mesh's making (its peak, or with ``kept`` only what it keeps) -- fits the
    memory budget: a SceneError naming the primitive's key path otherwise."""
    from .. import budget
    from ..errors import MemoryBudgetError
    from ..mesh.mesh import mesh_bytes

    if totals is None or size is None:
        return
    nv, nf, nk = (int(x) for x in size)
    making = _kept_bytes(nv, nf, nk) if kept else max(mesh_bytes(nv, nf, nk),
                                                      _kept_bytes(nv, nf, nk))
    meshes = totals["meshes"] + 1
    try:
        budget.check(
            totals["bytes"] + making, path,
            f"the scene's canvas and its {meshes} mesh primitive{'s' * (meshes > 1)} together "
            f"({totals['vertices'] + nv:,} vertices, {totals['faces'] + nf:,} faces)",
            hint="the tessellation limits are per mesh, the budget is for the whole scene: "
                 "use lower resolutions, fewer meshes or a smaller canvas")
    except MemoryBudgetError as error:
        raise SceneError(str(error), path=path) from None
    totals["bytes"] += _kept_bytes(nv, nf, nk)
    totals["meshes"] = meshes
    totals["vertices"] += nv
    totals["faces"] += nf


def _real(value: object, path: str) -> float:
    return schema._real(value, path)


def _vector(value: object, path: str, size: int = 3) -> list[float]:
    if not isinstance(value, list) or len(value) != size:
        schema._fail(path, f"must be [{', '.join('xyzw'[:size])}], {size} numbers, got "
                        f"{value!r}")
    return [_real(c, f"{path}[{i}]") for i, c in enumerate(value)]


def _arguments(data: dict[str, Any], path: str,
               angles: Collection[str] = ANGLES) -> dict[str, Any]:
    """``data`` with angles turned into radians and lists into tuples."""
    out: dict[str, Any] = {}
    for key, value in data.items():
        here = f"{path}.{key}"
        if key in angles:
            out[key] = schema.angle(value, here)
        elif isinstance(value, list) and value and all(isinstance(x, list) for x in value):
            out[key] = [tuple(x) for x in value]
        elif isinstance(value, list):
            out[key] = tuple(value)
        else:
            out[key] = value
    return out


def projection(data: object, path: str) -> "Projection":
    """A projection table -> a Projection.

    Parameters
    ----------
    data : object
        A camera's ``projection`` table: ``type`` (one of :data:`PROJECTIONS`) and
        that projection's keys, angles as ``{degrees = x}`` or ``{radians = x}``.
    path : str
        Its key path, named in error messages.

    Returns
    -------
    Projection

    Raises
    ------
    SceneError
        If the type is unknown or a key invalid.

    Examples
    --------
    >>> from scanline.scene.schema3d import projection
    >>> p = projection({"type": "isometric"}, "cameras[0].projection")
    >>> p.name, p.kind
    ('isometric', 'parallel')
    """
    from .. import projection as pj

    t = schema._table(data, path, set().union(*PROJECTIONS.values()) | {"type"}, ("type",))
    kind = t["type"]
    if not isinstance(kind, str) or kind not in PROJECTIONS:
        schema._fail(f"{path}.type", f"must be one of {', '.join(PROJECTIONS)}; got {kind!r}")
    schema._table(data, path, PROJECTIONS[kind] | {"type"})
    args = _arguments({k: x for k, x in t.items() if k != "type"}, path)
    functions: dict[str, Callable[..., Projection]] = {
        "perspective": pj.perspective, "frustum": pj.frustum,
        "orthographic": pj.orthographic, "isometric": pj.isometric,
        "dimetric": pj.dimetric, "trimetric": pj.trimetric, "oblique": pj.oblique,
        "parallel": pj.parallel}
    return schema._call(path, functions[kind], **args)


def cameras(data: object, df: "DisplayFile") -> list[str]:
    """Build the scene's cameras into the display file; returns their names.

    Parameters
    ----------
    data : object
        The scene's ``cameras``: a list of camera tables (:data:`CAMERA` keys).
    df : DisplayFile
        Gets each camera (:meth:`~scanline.DisplayFile.set_camera`).

    Returns
    -------
    list of str
        The cameras' names (``camera0``, ``camera1`` ... where a name is not given).

    Raises
    ------
    SceneError
        If a camera is invalid, a name repeats, or there is no camera.

    Examples
    --------
    >>> import scanline as sl
    >>> from scanline.scene.schema3d import cameras
    >>> df = sl.DisplayFile()
    >>> cameras([{"name": "front", "eye": [0, 0, 5], "target": [0, 0, 0]}, {}], df)
    ['front', 'camera1']
    >>> type(df.camera("front")).__name__
    'Camera'
    """
    from ..projection import Camera

    names: list[str] = []
    for i, c in enumerate(schema._list(data, "cameras")):
        path = f"cameras[{i}]"
        t = schema._table(c, path, CAMERA)
        name = t.get("name", f"camera{i}")
        if not isinstance(name, str) or not name:
            schema._fail(f"{path}.name", f"must be a non-empty string, got {name!r}")
        if name in names:
            schema._fail(f"{path}.name", f"repeats the camera name {name!r}")
        args = {k: (tuple(_vector(x, f"{path}.{k}", 6 if k == "viewport" else 3))
                    if k not in ("name", "projection", "keep_aspect") else x)
                for k, x in t.items() if k not in ("name",)}
        if "projection" in args:
            args["projection"] = projection(args["projection"], f"{path}.projection")
        if "keep_aspect" in args:
            args["keep_aspect"] = schema._flag(args["keep_aspect"], f"{path}.keep_aspect")
        camera = schema._call(path, Camera, **args)
        df.set_camera(camera, name)
        names.append(name)
    if not names:
        schema._fail("cameras", "must hold at least one camera")
    return names


def step(step_: object, path: str) -> NDArray[np.float64]:
    """One 3-D transformation step -> its 4x4 matrix.

    Parameters
    ----------
    step_ : object
        A one-key table: ``translate``, ``rotate`` (an angle with ``axis`` and
        ``pivot``, or a ``quaternion``), ``scale``, ``reflect``, ``shear`` or
        ``matrix``.
    path : str
        Its key path, named in error messages.

    Returns
    -------
    numpy.ndarray
        The 4x4 matrix (column vectors, ``p' = M p``).

    Raises
    ------
    SceneError
        If the step is unknown or its arguments invalid.

    Examples
    --------
    >>> from scanline.scene.schema3d import step
    >>> step({"translate": [1, 2, 3]}, "transform[0]") @ [0, 0, 0, 1]
    array([1., 2., 3., 1.])
    """
    if not isinstance(step_, dict) or len(step_) != 1:
        schema._fail(path, "must be a table with one key: " + ", ".join(_STEPS)
                + " (e.g. {translate = [1, 0, 2]})")
    (name, arg), = step_.items()
    here = f"{path}.{name}"
    if name == "translate":
        return t3.translation(*_vector(arg, here))
    if name == "rotate":
        a = schema._table(arg, here, {"degrees", "radians", "axis", "pivot", "quaternion"})
        if "quaternion" in a:
            return _quaternion_step(a, here)
        unit = {k: a[k] for k in a if k in ("degrees", "radians")}
        axis = a.get("axis", "z")
        if isinstance(axis, list):
            if len(axis) != 2:
                schema._fail(f"{here}.axis", f"must be 'x', 'y', 'z' or two points [[x, y, z], "
                        f"[x, y, z]], got {axis!r}")
            axis = (_vector(axis[0], f"{here}.axis[0]"), _vector(axis[1], f"{here}.axis[1]"))
        pivot = a.get("pivot")
        return schema._call(here, t3.rotation, schema.angle(unit, here), axis,
                       None if pivot is None else _vector(pivot, f"{here}.pivot"))
    if name == "scale":
        if isinstance(arg, dict):
            a = schema._table(arg, here, {"factors", "fixed"}, ("factors",))
            factors, fixed = a["factors"], a.get("fixed")
        else:
            factors, fixed = arg, None
        f = [factors] if isinstance(factors, numbers.Real) else factors
        if not isinstance(f, list) or len(f) not in (1, 3):
            schema._fail(here, f"must be a factor or [sx, sy, sz], got {factors!r}")
        return schema._call(here, t3.scaling, *f, fixed=None if fixed is None
                       else _vector(fixed, f"{here}.fixed"))
    if name == "reflect":
        if isinstance(arg, dict):
            a = schema._table(arg, here, {"point", "normal"}, ("point", "normal"))
            return schema._call(here, t3.reflection, _vector(a["point"], f"{here}.point"),
                           _vector(a["normal"], f"{here}.normal"))
        return schema._call(here, t3.reflection, arg)
    if name == "shear":
        a = schema._table(arg, here, {"axis", "a", "b", "reference"})
        return schema._call(here, t3.shear, a.get("axis", "z"), a.get("a", 0.0), a.get("b", 0.0),
                       a.get("reference", 0.0))
    if name == "matrix":
        return schema._call(here, t3.compose, arg)
    schema._fail(path, f"has an unknown transformation {name!r}; use one of {', '.join(_STEPS)}")


def _quaternion_step(a: dict[str, Any], here: str) -> NDArray[np.float64]:
    """``{rotate = {quaternion = [w, x, y, z], pivot = [x, y, z]}}``: the rotation of a
    unit quaternion (Hearn & Baker 11-2; any nonzero multiple is the same rotation),
    about the origin or the pivot."""
    from ..transform3d.quaternion import Quaternion

    extra = sorted(set(a) - {"quaternion", "pivot"})
    if extra:
        schema._fail(f"{here}.{extra[0]}", "cannot go with a quaternion (it holds the axis and "
                "the angle); give one or the other")
    q = a["quaternion"]
    if not isinstance(q, list) or len(q) != 4:
        schema._fail(f"{here}.quaternion", f"must be four numbers [w, x, y, z], got {q!r}")
    q = schema._call(here, Quaternion.from_array,
                [_real(c, f"{here}.quaternion[{i}]") for i, c in enumerate(q)], "quaternion")
    m = q.matrix()
    pivot = a.get("pivot")
    if pivot is None:
        return m
    p = _vector(pivot, f"{here}.pivot")
    return t3.compose(t3.translation(*p), m, t3.translation(*(-c for c in p)))


def transformation(steps: object, path: str) -> NDArray[np.float64]:
    """A list of 3-D steps, applied in the order listed (the first acts first).

    Parameters
    ----------
    steps : object
        A primitive's ``transform``: a list of :func:`step` tables.
    path : str
        Its key path, named in error messages.

    Returns
    -------
    numpy.ndarray
        The 4x4 matrix ``M = S_n ... S_2 S_1``.

    Raises
    ------
    SceneError
        If a step is invalid (naming its path).

    Examples
    --------
    Scaling by 2 first, then moving 1 along x, takes (1, 1, 1) to (3, 2, 2):

    >>> from scanline.scene.schema3d import transformation
    >>> transformation([{"scale": 2}, {"translate": [1, 0, 0]}], "transform") @ [1, 1, 1, 1]
    array([3., 2., 2., 1.])
    """
    m = t3.compose()
    for i, st in enumerate(schema._list(steps, path)):
        m = t3.compose(step(st, f"{path}[{i}]"), m)
    return m


def _mesh(data: dict[str, Any], path: str, base: str | None,
          totals: dict[str, int] | None = None) -> "Mesh":
    from .. import mesh as ms

    if ("file" in data) == ("generator" in data):
        schema._fail(path, "needs either file (a mesh file) or generator (cube, sphere, ...)")
    if "file" in data:
        name = data["file"]
        if not isinstance(name, str) or not name:
            schema._fail(f"{path}.file", f"must be a file name, got {name!r}")
        full = name if os.path.isabs(name) or base is None else os.path.join(base, name)
        try:
            # ms.load reads only a regular file (no FIFO, device or folder, whatever a
            # link points to), of a bounded size, within the memory budget
            mesh = ms.load(full)
        except ScanlineError as error:
            raise SceneError(f"{path}.file: {error}", path=f"{path}.file") from None
        _count(totals, f"{path}.file", (len(mesh.vertices), mesh.face_count,
                                        len(mesh.face_indices)), kept=True)
        return mesh
    gen = data["generator"]
    if not isinstance(gen, str) or gen not in GENERATORS:
        schema._fail(f"{path}.generator", f"must be one of {', '.join(GENERATORS)}; got {gen!r}")
    allowed = GENERATORS[gen]
    given = {k: x for k, x in data.items() if k in set().union(*GENERATORS.values())}
    for k in given:
        if k not in allowed:
            schema._fail(f"{path}.{k}", f"is not a key of the {gen} generator; its keys: "
                    + ", ".join(sorted(allowed)))
    for key, top in LIMITS.items():
        value = given.get(key)
        for i, x in enumerate(value if isinstance(value, list) else [value]):
            if isinstance(x, numbers.Real) and not isinstance(x, bool) and float(x) > top:
                where = f"{path}.{key}" + (f"[{i}]" if isinstance(value, list) else "")
                schema._fail(where, f"is {x!r}; a scene's meshes allow at most {top}")
    for key in ("profile", "vertices", "faces"):
        if isinstance(given.get(key), list) and len(given[key]) > 100_000:
            schema._fail(f"{path}.{key}", "holds more than 100000 items")
    args = _arguments(given, path)
    _count(totals, path, schema._call(path, _expected_size, gen, args))
    if gen == "polygons":
        for key in ("vertices", "faces"):
            if key not in args:
                schema._fail(path, f"needs the key '{key}' (vertices: a list of [x, y, z]; faces: "
                        "a list of vertex-number lists, from 0)")
        return schema._call(path, ms.Mesh, args["vertices"], args["faces"])
    if gen == "sweep":
        if "profile" not in args:
            schema._fail(path, "needs the key 'profile' (a list of points [x, y])")
        return schema._call(path, ms.sweep, args.pop("profile"), **args)
    if "resolution" in args and isinstance(args["resolution"], tuple):
        args["resolution"] = tuple(args["resolution"])
    if gen == "teapot" and "parts" in args:
        parts = args["parts"]
        if isinstance(parts, str):
            parts = [parts]
        if not isinstance(parts, tuple | list) or not all(isinstance(p, str) for p in parts):
            schema._fail(f"{path}.parts", f"must be a part name or a list of them (rim, body, "
                    f"handle, spout, lid, bottom), got {data['parts']!r}")
        args["parts"] = list(parts)
    functions: dict[str, Callable[..., Mesh]] = {
        "cube": ms.cube, "box": ms.box, "sphere": ms.sphere, "ellipsoid": ms.ellipsoid,
        "torus": ms.torus, "superellipsoid": ms.superellipsoid,
        "supertoroid": ms.supertoroid, "teapot": ms.teapot}
    function = functions[gen]
    if gen == "ellipsoid" and "radii" in args:
        radii = args.pop("radii")
        if not isinstance(radii, tuple) or len(radii) != 3:
            schema._fail(f"{path}.radii", f"must be [rx, ry, rz], got {radii!r}")
        args.update(rx=radii[0], ry=radii[1], rz=radii[2])
    return schema._call(path, function, **args)


def primitive(kind: str, data: dict[str, Any], path: str, df: "DisplayFile", background: Any,
              base: str | None, shading: "Shading | None" = None,
              segment: NDArray[np.float64] | None = None, *,
              totals: dict[str, int] | None = None) -> None:
    """Build one 3-D primitive into the open segment of ``df``; a mesh with a
    ``material`` becomes a surface of ``shading`` (:mod:`scanline.scene.shaded`),
    transformed by its own 3-D transformation (``segment``, the segment's 2-D one,
    must be the identity).  ``totals`` (the scene's memory so far, see
    :func:`scanline.scene.schema.build`) gets each mesh added, checked against the
    memory budget.

    Parameters
    ----------
    kind : {"mesh", "polyline3d"}
        The primitive's type.
    data : dict
        The primitive's table.
    path : str
        Its key path, named in error messages.
    df : DisplayFile
        The display file, a segment open and a camera set.
    background : color
        The canvas background (depth cueing fades to it).
    base : str or None
        The scene file's folder, where mesh files are found.
    shading : Shading, optional
        The scene's shading (needed by a mesh with a ``material``).
    segment : numpy.ndarray, optional
        The segment's 2-D transformation.
    totals : dict, optional
        The scene's memory so far.

    Raises
    ------
    SceneError
        If the primitive is invalid, its mesh cannot be made or read, or the scene's
        meshes pass the memory budget.

    Examples
    --------
    >>> import scanline as sl
    >>> from scanline.scene.schema3d import primitive
    >>> df = sl.DisplayFile()
    >>> df.set_camera(sl.Camera(eye=(0, 0, 5), target=(0, 0, 0)))
    >>> df.create_segment("cube")
    >>> primitive("mesh", {"type": "mesh", "generator": "cube"}, "segments[0].primitives[0]",
    ...           df, "black", None)
    >>> df.close_segment()
    >>> [p.kind for p in df.segment("cube").primitives]
    ['mesh']
    """
    schema._table(data, path, PRIMITIVES[kind] | {"type"},
             ("points",) if kind == "polyline3d" else ())
    line = {k: x for k, x in data.items() if k in _LINE and k != "color"}
    if isinstance(line.get("dash"), list):
        line["dash"] = tuple(line["dash"])
    m = transformation(data.get("transform", []), f"{path}.transform")
    if kind == "polyline3d":
        pts = [_vector(p, f"{path}.points[{i}]") for i, p in
               enumerate(schema._list(data["points"], f"{path}.points"))]
        if not pts:
            schema._fail(f"{path}.points", "needs at least one point")
        closed = schema._flag(data.get("closed", False), f"{path}.closed")
        schema._call(path, df.polyline3d, t3.apply(m, pts), data.get("color", "white"), closed, **line)
        return
    mesh = _mesh(data, path, base, totals)
    for key in ("emission", "reflectance"):
        if key in data and (shading is None or shading.radiosity is None):
            schema._fail(f"{path}.{key}", "is a radiosity value: it needs the scene's radiosity "
                    "table (radiosity = {subdivisions = 8})")
        if key in data and "material" not in data:
            schema._fail(f"{path}.{key}", "needs the mesh's material (a radiosity surface is a "
                    "shaded surface)")
    if "material" in data:
        if shading is None:
            schema._fail(f"{path}.material", "needs the scene's lights, materials or shading keys "
                    "(add [materials.NAME])")
        if segment is not None and not (segment == np.eye(3)).all():
            schema._fail(f"{path}.material", "makes a shaded surface, which the segment's 2-D "
                    "transform cannot move: give the mesh its own (3-D) transform")
    if not (m == t3.compose()).all():
        mesh = schema._call(f"{path}.transform", mesh.transformed, m)
    if "material" in data:
        # checked above: a material needs the shading keys; a 3-D primitive, a camera
        camera = df._current_camera
        assert shading is not None and camera is not None
        shading.surface(mesh, data["material"], path, df.camera(camera),
                        data.get("emission"), data.get("reflectance"))
        return
    cue = data.get("depth_cue")
    if isinstance(cue, list):
        cue = tuple(cue)
    schema._call(path, df.mesh, mesh, data.get("color"), cue, background, **line)
