"""The second half's rendering entry points on generated hostile arguments: sl.render
with every method, shading and option, the preparation, the visible-surface methods
on hand-built screen polygons (hostile offsets, planes, sizes), the BSP tree and
visible lines, the lighting and shading functions, 3-D and homogeneous clipping,
raster operations, 3-D scene files (schema version 2) and the commands that read them.
Each call runs in :func:`tests.fuzz.harness.bounded` (time and memory limits; only
ScanlineError may escape) on a frame buffer with guard memory.  Marked
``boundscheck``: .ci/run runs this module again with NUMBA_BOUNDSCHECK=1."""

import contextlib
import io
import os

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from scanline.cli import main
from tests.fuzz.harness import arrays, bounded, guard_intact, guarded, index_arrays, values

pytestmark = pytest.mark.boundscheck

MODES = st.sampled_from(["1", "L", "RGB", "RGBA", "P"])
METHODS = st.sampled_from(sorted(sl.visible.METHODS))
SHADINGS = st.sampled_from(["none", "flat", "gouraud", "phong", "fast-phong", "smooth"])
size = st.integers(1, 20)


def camera(kind, eye):
    projection = {"perspective": lambda: sl.projection.perspective(fov=0.9, near=0.5),
                  "orthographic": lambda: sl.projection.orthographic(window=(-2, -2, 2, 2)),
                  "oblique": lambda: sl.projection.oblique("cavalier")}[kind]()
    return sl.Camera(eye=eye, target=(0, 0, 0), projection=projection)


EYES = st.sampled_from([(3, 2, 4), (0, 0, 5), (0.1, 0.1, 0.2), (1e6, 1e6, 1e6), (0, 5, 0)])
CAMERAS = st.sampled_from(["perspective", "orthographic", "oblique"])
OPTION = st.sampled_from([
    {}, {"gamma": 1}, {"gamma": 0}, {"gamma": np.nan}, {"depth_cue": True},
    {"depth_cue": (2, -1)}, {"cull_back_faces": True}, {"cull_back_faces": 1},
    {"specular": "blinn"}, {"specular": "cook"}, {"shadows": True}, {"lights": []},
    {"lights": ["sun"]}, {"lights": [sl.lighting.PointLight((1e300, 0, 0))]},
    {"lights": [sl.lighting.SpotLight((0, 0, 3), (0, 0, -1), angle=0.3)]},
    {"materials": sl.lighting.Material(transparency=0.5)}, {"materials": [1, 2]},
    {"colors": "red"}, {"colors": [(1, 2, 3)] * 5}, {"colors": "nope"}, {"samples": 0},
    {"samples": 2}, {"samples": 10**9}, {"layers": -1}, {"key": "mean"}, {"key": 3},
    {"split_cycles": False}, {"split_cycles": "yes"}, {"max_pieces": 1}, {"max_work": 1},
    {"max_work": -5}, {"fallback": "z-buffer"}, {"fallback": "nope"}, {"material": 1},
    {"antialias": 2}, {"antialias": 0}, {"antialias": 3.5}, {"crease_angle": None}, {"crease_angle": 0}, {"crease_angle": 3.2}, {"crease_angle": np.nan},
])


@given(verts=arrays(3, max_rows=15), faces=index_arrays(max_len=9), mode=MODES, w=size,
       h=size, method=METHODS, shading=SHADINGS, kind=CAMERAS, eye=EYES, option=OPTION)
def test_render(verts, faces, mode, w, h, method, shading, kind, eye, option):
    fb, big = guarded(w, h, mode)
    with bounded():
        f = np.asarray(faces)
        mesh = sl.mesh.Mesh(verts, f[:len(f) // 3 * 3].reshape(-1, 3) if f.ndim == 1 else f)
        sl.render(fb, mesh, camera(kind, eye), method=method, shading=shading, **option)
    assert guard_intact(big)


@given(n=st.integers(1, 60), seed=st.integers(0, 2**32 - 1), spread=values, mode=MODES,
       method=METHODS, kind=CAMERAS)
def test_render_random_triangles(n, seed, spread, mode, method, kind):
    # valid scenes of finite triangles at hostile scales: drawn, or refused by name
    fb, big = guarded(17, 13, mode)
    rng = np.random.default_rng(seed)
    with bounded():
        s = float(spread)
        tri = rng.uniform(-1, 1, (3 * n, 3)) * s
        mesh = sl.mesh.Mesh(tri, np.arange(3 * n).reshape(n, 3))
        sl.render(fb, mesh, camera(kind, (3, 2, 4)), method=method, shading="none",
                  fallback="z-buffer")
    assert guard_intact(big)


@given(verts=arrays(3, max_rows=20), offsets=index_arrays(), face=index_arrays(),
       planes=arrays(4, max_rows=6), w=st.sampled_from([1, 5, 40, 0, -3, 2**40, 1.5]),
       h=st.sampled_from([1, 7, 30, 0, 2**40]),
       method=st.sampled_from(["depth_sort", "scan_line", "area_subdivision", "painter",
                               "painted_depth_sort", "hidden_lines"]))
def test_hand_built_screen_polygons(verts, offsets, face, planes, w, h, method):
    with bounded():
        sp = sl.visible.ScreenPolygons(verts, offsets, face, planes, w, h)
        if method == "hidden_lines":
            sl.visible.hidden_lines([[0, 0, 10, 10]], [[0.5, 0.5]], sp)
        else:
            getattr(sl.visible, method)(sp)


@given(verts=arrays(3, max_rows=9, flavour=False), mode=MODES, eye=EYES, kind=CAMERAS,
       hidden=st.sampled_from(["remove", "dash", "none"]))
def test_bsp_and_visible_lines(verts, mode, eye, kind, hidden):
    fb, big = guarded(16, 12, mode)
    n = len(verts) // 3
    with bounded():
        mesh = sl.mesh.Mesh(verts[:3 * n], np.arange(3 * n).reshape(n, 3))
        tree = sl.visible.BSPTree(mesh, max_pieces=500)
        tree.order(eye)
        sl.visible.bsp(tree, camera(kind, eye), 16, 12, cull_back_faces=True)
        sl.visible.visible_lines(fb, mesh, camera(kind, eye), hidden=hidden)
    assert guard_intact(big)


@given(point=arrays(3, max_rows=4), normal=arrays(3, max_rows=4), eye=arrays(3, max_rows=1),
       a=values, b=values, c=values, kind=st.sampled_from(["ambient", "directional", "point",
                                                            "spot", "material"]))
def test_lighting(point, normal, eye, a, b, c, kind):
    with bounded():
        light = {"ambient": lambda: sl.lighting.AmbientLight(a),
                 "directional": lambda: sl.lighting.DirectionalLight((a, b, c), intensity=b),
                 "point": lambda: sl.lighting.PointLight((a, b, c), attenuation=(a, b, c)),
                 "spot": lambda: sl.lighting.SpotLight((a, b, c), (c, b, a), angle=a,
                                                       exponent=b),
                 "material": lambda: sl.lighting.AmbientLight(0.5)}[kind]()
        material = sl.lighting.Material(ka=a, kd=b, ks=c, shininess=a) \
            if kind == "material" else sl.lighting.Material()
        sl.lighting.intensity(point, normal, eye.reshape(-1)[:3] if eye.size else eye,
                              [light], material)
    with bounded():
        sl.lighting.attenuation(a, (a, b, c))
        sl.lighting.depth_cue(point, a, b, c, cue=(a, b))
        sl.lighting.transparency(point, normal, a)
    with bounded():
        sl.shading.encode(point, gamma=a)
        sl.shading.decode(point, gamma=b)


@given(ids=arrays(1, max_rows=12), values_=arrays(3, max_rows=5), mode=MODES,
       w=st.integers(1, 4), h=st.integers(1, 3))
def test_shading_paint(ids, values_, mode, w, h):
    fb, big = guarded(w, h, mode)
    with bounded():
        flat = np.asarray(ids).reshape(-1)
        sl.shading.paint(fb, flat[:w * h].reshape(h, w) if flat.size >= w * h else flat,
                         values_)
    assert guard_intact(big)


@given(segs=arrays(6, max_rows=8), hom=arrays(8, max_rows=6), polys=arrays(3, max_rows=9),
       counts=index_arrays(), lo=values, hi=values,
       method=st.sampled_from(["cohen-sutherland", "liang-barsky", "cyrus-beck", "nope"]))
def test_clipping_3d(segs, hom, polys, counts, lo, hi, method):
    with bounded():
        box = sl.clip.box((lo, lo, lo), (hi, hi, hi))
        sl.clip.lines3d(segs, box, method=method)
    with bounded():
        sl.clip.homogeneous(hom, method=method)
    with bounded():
        sl.clip.polygons3d(polys, sl.clip.box((-1, -1, -1), (1, 1, 1)), counts=counts)
    with bounded():
        sl.clip.polygons3d(np.c_[polys, np.ones(len(polys))] if polys.ndim == 2 and
                           polys.shape[1] == 3 else polys, sl.clip.UNIT_CUBE, counts=counts,
                           homogeneous=True)


@given(mode=MODES, src_mode=MODES, rect=arrays(4, max_rows=1), at=arrays(2, max_rows=1),
       op=st.sampled_from(["copy", "xor", "and", "or", "nope", 3]), w=size, h=size)
def test_raster_ops(mode, src_mode, rect, at, op, w, h):
    dst, big = guarded(w, h, mode)
    src = sl.FrameBuffer(h, w, mode=src_mode)
    with bounded():
        sl.raster.bitblt(dst, src, rect.reshape(-1), at.reshape(-1), op=op)
    assert guard_intact(big)


SCENE = """version = 2
method = "{method}"
shading = {{model = "{model}", cull_back_faces = {cull}}}
[canvas]
width = {w}
height = {h}
[[cameras]]
name = "eye"
eye = [{a}, {b}, 4]
target = [0, 0, 0]
projection = {{type = "perspective", fov = {{degrees = {fov}}}, near = {near}}}
[[lights]]
type = "point"
position = [{c}, 1, 2]
intensity = {i}
[materials.m]
ka = {ka}
shininess = {n}
transparency = {t}
[[segments]]
primitives = [{{type = "mesh", generator = "{gen}", resolution = {res}, material = "m"}}]
"""

TOKENS = st.sampled_from(["0", "1", "-1", "1e300", "-1e300", "nan", "inf", "2.5", "100000",
                          "3", "1e-300", '"x"', "[1, 2]", "true"])


@given(method=st.sampled_from(["z-buffer", "a-buffer", "bsp", "depth-sort", "x"]),
       model=st.sampled_from(["phong", "none", "gouraud", "x"]), cull=st.booleans(),
       w=TOKENS, h=TOKENS, a=TOKENS, b=TOKENS, c=TOKENS, fov=TOKENS, near=TOKENS, i=TOKENS,
       ka=TOKENS, n=TOKENS, t=TOKENS, gen=st.sampled_from(["sphere", "cube", "torus", "x"]),
       res=TOKENS)
def test_scene_files_version_2(tmp_path_factory, method, model, cull, w, h, a, b, c, fov,
                               near, i, ka, n, t, gen, res):
    where = tmp_path_factory.mktemp("scene")
    text = SCENE.format(method=method, model=model, cull=str(cull).lower(), w=w, h=h, a=a,
                        b=b, c=c, fov=fov, near=near, i=i, ka=ka, n=n, t=t, gen=gen, res=res)
    path = where / "s.toml"
    path.write_text(text)
    with bounded():
        sl.scene.load(str(path)).raster()
    for command in (["check", str(path)], ["render", str(path), "-o", str(where / "o.png")]):
        err = io.StringIO()
        with bounded(), contextlib.redirect_stderr(err), \
                contextlib.redirect_stdout(io.StringIO()):
            status = main(command)
        assert status in (0, 2), (command, status, err.getvalue())
        if status == 2:
            lines = err.getvalue().strip().splitlines()
            assert len(lines) == 1 and lines[0].startswith("scanline: error: "), err.getvalue()
            assert not os.path.exists(where / "o.png")
