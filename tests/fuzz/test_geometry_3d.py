"""Every public entry point of sl.transform3d, sl.projection (the projections, Camera
construction and its methods) and sl.mesh (Mesh and its methods, the generators, the
sweeps, the polygon tables, load and save, hostile files from hostile_files.py) on
generated hostile arguments: NaN, ±inf, ±1e300, 5e-324, 2**63, wrong types, empty
arrays, wrong shapes, arrays of every dtype and layout.  Each call runs in
:func:`tests.fuzz.harness.bounded`: only ScanlineError may escape, within the time and
memory limits.

The memory budget is set to 128 MiB for this module, so that every size a generator
accepts stays within the harness's 512 MiB (tests/fuzz/README.md).  The tests that
reach numba kernels (Camera.project and to_clip, the wireframe and the renderer) are
marked ``boundscheck``, as test_api.py's are.
"""

import os

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from scanline import projection as pj
from scanline import transform3d as t3
from tests.fuzz import hostile_files as hf
from tests.fuzz.harness import arrays, bounded, index_arrays, values

#: Whole-number angles such as 38 are read as radians with a warning (they are
#: meant to be: the fuzz draws them on purpose).
pytestmark = pytest.mark.filterwarnings("ignore::scanline.errors.AngleWarning")


@pytest.fixture(autouse=True, scope="module")
def small_budget():
    old = os.environ.get("SCANLINE_MEMORY_LIMIT")
    os.environ["SCANLINE_MEMORY_LIMIT"] = "128M"
    yield
    if old is None:
        os.environ.pop("SCANLINE_MEMORY_LIMIT", None)
    else:
        os.environ["SCANLINE_MEMORY_LIMIT"] = old


#: Anything at all where an argument goes: numbers of every kind, strings, None,
#: containers of the wrong size, arrays of the wrong shape.
WEIRD = [None, "x", "", "z", "xy", b"x", [], (), {}, object(), 3 + 1j, True, np.zeros(0),
         np.zeros((2, 2)), np.full(3, np.nan), np.ones(4), [1e300] * 3, [5e-324] * 3,
         [-1e300, 1e300, 1e300], [2**63] * 3, [0, 0, 0], [1, 2], [[1, 2, 3]], [np.inf] * 3,
         np.float16(65504), np.int64(2**62), np.uint64(2**64 - 1)]
anything = st.one_of(values, st.sampled_from(WEIRD))
triples = st.one_of(st.tuples(values, values, values), st.sampled_from(WEIRD))
windows = st.one_of(st.tuples(values, values, values, values),
                    st.sampled_from([(-1, -1, 1, 1), (0, 0, 5e-324, 5e-324),
                                     (-1e300, -1e300, 1e300, 1e300), (1, 1, 0, 0)] + WEIRD))
maybe = st.one_of(st.none(), values)
SIZES = st.one_of(st.integers(-2, 40), st.sampled_from([0, 1, 2, 2**31, 2**62, 2**63, 2**64,
                                                        -2**63, 1.5, np.nan, None, "3"]))


def matrices():
    return st.one_of(arrays(4, max_rows=5), st.sampled_from(
        [np.eye(4), np.eye(4) * 1e300, np.full((4, 4), np.nan), np.zeros((4, 4)), np.eye(3),
         t3.scaling(1e300), t3.translation(1e300, -1e300, 1e300), "x", None, 5]))


# -- sl.transform3d ------------------------------------------------------------------------
@given(a=anything, b=anything, c=anything, p=triples, q=triples,
       axis=st.one_of(st.sampled_from(["x", "y", "z", "w", None, 3]),
                      st.tuples(triples, triples)),
       plane=st.one_of(st.sampled_from(["xy", "yz", "zx", "xx"]), triples))
def test_transform3d_constructors(a, b, c, p, q, axis, plane):
    with bounded():
        t3.translation(a, b, c)
    with bounded():
        t3.scaling(a, b, c, fixed=p)
    with bounded():
        t3.scaling(a, fixed=q)
    with bounded():
        t3.rotation(a, axis)
    with bounded():
        t3.rotation(a, "z", pivot=p)
    with bounded():
        t3.rotation(a, (p, q))
    with bounded():
        t3.rotation_steps(a, (p, q))
    with bounded():
        t3.axis_alignment((p, q))
    with bounded():
        t3.axis_alignment(axis)
    with bounded():
        t3.reflection(plane)
    with bounded():
        t3.reflection(p, q)
    with bounded():
        t3.shear(axis if isinstance(axis, str) else "z", a, b, c)
    for name in ("translation", "scaling", "rotation", "reflection", "shear"):
        with bounded():
            m = {"translation": lambda: t3.translation(a, b, c),
                 "scaling": lambda: t3.scaling(a, fixed=p),
                 "rotation": lambda: t3.rotation(a, "x", pivot=q),
                 "reflection": lambda: t3.reflection(p, q),
                 "shear": lambda: t3.shear("y", a, b, c)}[name]()
            assert np.isfinite(m).all(), (name, m)      # an answer is a finite matrix


@given(m1=matrices(), m2=matrices(), pts=st.one_of(arrays(3), arrays(4), triples),
       tolerance=anything)
def test_transform3d_operations(m1, m2, pts, tolerance):
    with bounded():
        assert np.isfinite(t3.compose(m1, m2)).all()
    with bounded():
        assert np.isfinite(t3.inverse(m1)).all()
    with bounded():
        t3.is_affine(m1, tolerance)
    with bounded():
        assert np.isfinite(t3.apply(m1, pts)).all()
    with bounded():
        assert np.isfinite(t3.apply(t3.compose(m2), pts)).all()


# -- sl.projection -------------------------------------------------------------------------
@given(a=anything, b=anything, c=anything, d=maybe, e=maybe, window=windows, p=triples,
       view=st.sampled_from(list(pj.VIEW_NAMES) + ["up", None, 3]),
       kind=st.sampled_from(["cavalier", "cabinet", "other", None, 2]))
def test_projections(a, b, c, d, e, window, p, view, kind):
    made = []
    calls = [
        lambda: pj.orthographic(view, window, d, e, a),
        lambda: pj.axonometric(a, b, window, d, e),
        lambda: pj.trimetric(a, b, window, d, e),
        lambda: pj.isometric(window, d, e),
        lambda: pj.dimetric(a, window, d, e),
        lambda: pj.oblique(kind, a, None, window, d, e, c),
        lambda: pj.oblique(None, a, b, window, d, e, c),
        lambda: pj.parallel(p, window, d, e, c),
        lambda: pj.perspective(a, b, window, d, e),
        lambda: pj.perspective(fov=a, aspect=b, near=c, far=d),
        lambda: pj.frustum(p, window, a, d, e),
    ]
    for call in calls:
        with bounded():
            made.append(call())
    for proj in made:
        # whatever is made has finite matrices, and its derived objects are answers too
        assert np.isfinite(proj.matrix).all() and np.isfinite(proj.normalization).all()
        with bounded():
            pj.foreshortening(proj)
        with bounded():
            proj.volume_corners()
        with bounded():
            proj.replace(window=window, front=d, back=e)
    with bounded():
        pj.foreshortening(a)
    with bounded():
        pj.viewing_matrix(p, (a, b, c), (0, 1, 0))
    with bounded():
        pj.look_at(p, (a, b, c), (c, b, a))


PROJECTIONS = [pj.perspective(fov=1.0, near=0.5, far=20), pj.perspective(z_prp=10, z_vp=0),
               pj.orthographic(), pj.isometric(), pj.oblique("cabinet"),
               pj.frustum((1, 0, 4), window=(0, -1, 2, 1))]


@pytest.mark.boundscheck
@given(eye=triples, target=triples, up=st.one_of(st.none(), triples),
       which=st.integers(0, len(PROJECTIONS) - 1), form=st.sampled_from(["usual", "textbook",
                                                                          "target", "none"]),
       viewport=st.one_of(st.just((0, 0, 0, 1, 1, 1)), st.tuples(*[values] * 6),
                          st.sampled_from(WEIRD)),
       keep=st.sampled_from([True, False, None, 1, np.zeros(0)]))
def test_camera_construction(eye, target, up, which, form, viewport, keep):
    projection = PROJECTIONS[which]
    with bounded():
        if form == "usual":
            cam = sl.Camera(eye, target, up, projection, viewport=viewport, keep_aspect=keep)
        elif form == "textbook":
            cam = sl.Camera(projection=projection, view_reference_point=eye,
                            view_plane_normal=target, view_up=up, viewport=viewport,
                            keep_aspect=keep)
        elif form == "target":
            cam = sl.Camera(target=target, projection=projection)
        else:
            cam = sl.Camera(projection=projection, viewport=viewport)
        assert np.isfinite(cam.matrix()).all()
        cam.project([(0.0, 0.0, 0.0)], 8, 6)
    with bounded():
        sl.Camera.standard(form if form != "none" else "front", target=target,
                           distance=eye[0] if isinstance(eye, tuple) and eye else eye)


CAMERAS = [sl.Camera(eye=(3, 2, 4), target=(0, 0, 0), projection=p) for p in PROJECTIONS[:3]
           + PROJECTIONS[5:]] + [sl.Camera(target=(0, 0, 0), projection=pj.isometric()),
                                 sl.Camera(projection=pj.perspective(z_prp=10, z_vp=0),
                                           view_reference_point=(0, 0, 5))]


@pytest.mark.boundscheck
@given(pts=st.one_of(arrays(3), triples), which=st.integers(0, len(CAMERAS) - 1),
       width=SIZES, height=SIZES, box=windows, aspect=st.one_of(st.none(), anything),
       depth=st.one_of(arrays(1), anything), direction=triples, separation=anything)
def test_camera_methods(pts, which, width, height, box, aspect, depth, direction, separation):
    cam = CAMERAS[which]
    with bounded():
        cam.project(pts, width, height)
    with bounded():
        cam.to_clip(pts, width, height)
    with bounded():
        cam.to_clip(pts)
    with bounded():
        cam.to_viewing(pts)
    with bounded():
        cam.visible(pts, width, height)
    with bounded():
        clip, scale, _ = cam.mapping(box, aspect)
        assert np.isfinite(clip).all() and np.isfinite(scale).all()
    with bounded():
        assert np.isfinite(cam.matrix(width, height)).all()
    with bounded():
        cam.device(width, height)
    with bounded():
        cam.linear_depth(depth)
    with bounded():
        cam.vanishing_point(direction, width, height)
    with bounded():
        cam.volume_corners(width, height)
    with bounded():
        cam.stereo(separation)
    with bounded():
        cam.replace(viewport=box, keep_aspect=aspect)
    with bounded():
        cam.replace(projection=depth)


@pytest.mark.boundscheck
@given(width=st.integers(1, 3), height=st.integers(1, 12), which=st.integers(0, 3))
def test_small_devices_are_drawn(width, height, which):
    # valid: frames one pixel wide or high are devices too (refusals fail)
    fb = sl.FrameBuffer(width, height, mode="L")
    with bounded(refusals=False):
        sl.render(fb, sl.mesh.sphere(resolution=8), CAMERAS[which])
        sl.draw3d.wireframe(fb, sl.mesh.cube(), CAMERAS[which])
        CAMERAS[which].project([(0, 0, 0), (1, 1, 1)], width, height)


# -- sl.mesh -------------------------------------------------------------------------------
@pytest.mark.boundscheck
@given(verts=arrays(3, max_rows=10), faces=st.one_of(arrays(3, max_rows=6), index_arrays(),
                                                     st.sampled_from(WEIRD)),
       colors=st.one_of(st.none(), st.sampled_from(["red", (1, 2, 3), 7, np.nan, [], "nope",
                                                    np.zeros((2, 2))])),
       normals=st.one_of(st.none(), arrays(3, max_rows=10), st.sampled_from(WEIRD)),
       color_on=st.sampled_from([None, "face", "vertex", "edge", 3]), m=matrices(),
       tolerance=anything, i=st.one_of(SIZES, anything), offset=triples, pts=arrays(3))
def test_meshes(verts, faces, colors, normals, color_on, m, tolerance, i, offset, pts):
    mesh = None
    with bounded():
        mesh = sl.mesh.Mesh(verts, faces, colors, normals, color_on)
    if mesh is None:
        mesh = sl.mesh.cube()
    for call in (lambda: mesh.plane_equations(tolerance), mesh.planarity, mesh.face_normals,
                 lambda: mesh.inside(pts), lambda: mesh.edges, mesh.edge_faces,
                 mesh.triangulated, lambda: mesh.transformed(m), lambda: mesh.translated(offset),
                 lambda: mesh.colored(colors, color_on), lambda: mesh.face(i),
                 lambda: mesh.polygon_tables().check(), lambda: mesh.bounds, lambda: repr(mesh),
                 lambda: mesh.faces, lambda: sl.mesh.merge([mesh, sl.mesh.cube()]),
                 lambda: sl.mesh.merge(faces)):
        with bounded():
            out = call()
            if isinstance(out, sl.mesh.Mesh):
                assert np.isfinite(out.vertices).all()


@given(a=anything, b=anything, c=anything, center=triples, radii=triples,
       resolution=st.one_of(SIZES, st.tuples(SIZES, SIZES), st.sampled_from(WEIRD)),
       kind=st.sampled_from(["ellipsoid", "toroid", "cube", 5]))
def test_generators(a, b, c, center, radii, resolution, kind):
    calls = [lambda: sl.mesh.cube(a, center), lambda: sl.mesh.box(center, radii),
             lambda: sl.mesh.sphere(a, center, resolution),
             lambda: sl.mesh.ellipsoid(a, b, c, center, resolution),
             lambda: sl.mesh.torus(a, b, center, resolution),
             lambda: sl.mesh.superellipsoid(a, b, radii, center, resolution),
             lambda: sl.mesh.supertoroid(a, b, c, radii, center, resolution),
             lambda: sl.mesh.superquadric(kind, a, b, resolution=resolution)]
    for call in calls:
        with bounded():
            mesh = call()
            assert np.isfinite(mesh.vertices).all()


BEZIER = sl.curves.Bezier([(1, 0), (2, 1), (1, 2)])
PATCH = sl.curves.BezierSurface(np.stack(list(np.meshgrid(np.arange(4.0), np.arange(4.0),
                                                          indexing="ij"))
                                         + [np.ones((4, 4))], axis=-1))


@given(profile=st.one_of(arrays(2, max_rows=8), arrays(3, max_rows=8), st.just(BEZIER),
                         st.sampled_from(WEIRD)),
       axis=st.one_of(st.sampled_from(["x", "y", "z", "q"]), st.tuples(triples, triples)),
       angle=anything, steps=SIZES, samples=SIZES, vector=triples,
       closed=st.sampled_from([None, True, False, np.zeros(0), "yes"]),
       caps=st.sampled_from([True, False, None, 2]), n=SIZES,
       parts=st.sampled_from([None, "lid", ["body", "spout"], [], "nope", np.nan, [3]]),
       kind=st.sampled_from(["rotational", "translational", "other"]))
def test_sweeps_and_surfaces(profile, axis, angle, steps, samples, vector, closed, caps, n,
                             parts, kind):
    calls = [lambda: sl.mesh.rotational_sweep(profile, axis, angle, steps, closed, samples),
             lambda: sl.mesh.translational_sweep(profile, vector, closed, caps, samples),
             lambda: sl.mesh.sweep(profile, kind, steps=steps),
             lambda: sl.mesh.from_surface(PATCH, n, steps),
             lambda: sl.mesh.from_surface(profile, 3, 3),
             lambda: sl.mesh.teapot(n if n != 0 else 1, parts)]
    for call in calls:
        with bounded():
            mesh = call()
            assert np.isfinite(mesh.vertices).all()


@given(vertices=arrays(3, max_rows=6), edges=arrays(2, max_rows=6),
       surfaces=st.one_of(st.lists(index_arrays(), max_size=4), st.sampled_from(WEIRD)),
       pointers=st.one_of(st.none(), st.lists(index_arrays(), max_size=6),
                          st.sampled_from(WEIRD)))
def test_polygon_tables(vertices, edges, surfaces, pointers):
    with bounded():
        tables = sl.mesh.PolygonTables(vertices, edges, surfaces, pointers)
        tables.check()
        str(tables)
        repr(tables)
        assert tables.consistent in (True, False)


@pytest.fixture(scope="module")
def hostile_mesh_files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("hostile-meshes")
    for name, make in hf.MESH_FILES.items():
        make(str(folder / name))
    for ext in ("obj", "ply", "stl"):
        sl.mesh.merge([sl.mesh.cube(), sl.mesh.sphere(resolution=(6, 3))]).save(
            folder / f"ok.{ext}")
    return folder


def _mutated(data, draw_ops):
    data = bytearray(data)
    for where, what in draw_ops:
        at = int(where * len(data))
        data[at:at + len(what) // 2] = what
    return bytes(data)


@given(name=st.sampled_from(sorted(hf.MESH_FILES)), ext=st.sampled_from(["obj", "ply", "stl"]),
       ops=st.lists(st.tuples(st.floats(0, 1), st.one_of(st.binary(max_size=12), st.sampled_from(
           [b"99999999999999999999", b"-9223372036854775808", b"nan", b"\n", b"end_header\n",
            b"element face 4294967295\n", b"\xff\xff\xff\xff", b"1e999", b"f 1 2 -9\n"]))),
           max_size=5),
       max_bytes=st.sampled_from([None, 0, 100, 2**63, -1, 1.5]))
def test_loading_hostile_mesh_files(hostile_mesh_files, tmp_path_factory, name, ext, ops,
                                    max_bytes):
    with bounded():
        sl.mesh.load(hostile_mesh_files / name)           # FIFOs, /dev/zero, huge counts
    data = (hostile_mesh_files / f"ok.{ext}").read_bytes()
    path = tmp_path_factory.mktemp("mutated") / f"m.{ext}"
    path.write_bytes(_mutated(data, ops))
    with bounded():
        mesh = sl.mesh.load(path, max_bytes=max_bytes)
        assert np.isfinite(mesh.vertices).all()


@given(name=st.one_of(st.sampled_from(["x.obj", "x.ply", "x.stl", "x.3ds", "", "dir",
                                       "a\0b.obj", "missing/x.obj"]), st.sampled_from(WEIRD)),
       mesh=st.sampled_from([sl.mesh.cube(), None, "mesh", 3]))
def test_saving_to_hostile_paths(tmp_path_factory, name, mesh):
    folder = tmp_path_factory.mktemp("save")
    (folder / "dir").mkdir()
    target = folder / name if isinstance(name, str) else name
    with bounded():
        sl.mesh.save(mesh, target)
    with bounded():
        sl.mesh.load(target)
    assert not [f for f in os.listdir(folder) if f.startswith(".") or f.endswith(".tmp")]
