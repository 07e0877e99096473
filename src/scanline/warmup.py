"""Compiling the kernels ahead of time: one representative call of every public entry
point that reaches a numba kernel, in every frame-buffer mode where the mode matters.

numba compiles a kernel on its first call and caches it on disk; a process that finds
it in the cache loads it in milliseconds.  :data:`CALLS` is the list of calls that
reaches every kernel: :func:`run` makes them (``scanline warmup`` does it in parallel
processes, for images built for containers or CI caches), ``benchmarks/compile.py``
times each one in a fresh process with an empty cache (the compile-time budget of
:mod:`scanline._kernels`), and ``tests/test_compile_budget.py`` counts the
specializations they produce.

>>> group, code, modes = CALLS["line"]
>>> group, code, modes == MODES
('lines', "sl.draw.line(fb, 3, 4, 90, 50, color='black')", True)
"""

import time
from typing import TYPE_CHECKING, Callable, Iterable, Iterator, Sequence, cast

if TYPE_CHECKING:
    from ._typing import Mode
    from .framebuffer import FrameBuffer

#: The frame-buffer modes.
MODES = ("1", "L", "RGB", "RGBA", "P")

RGB = ("RGB",)
STAR = "[(48, 60), (20, 4), (92, 40), (4, 40), (76, 4)]"
TRIANGLE = "[(3, 4), (80, 20), (30, 60)]"
PATH = "[(3, 4), (50, 60), (90, 5)]"
DISK = "sl.draw.circle(fb, 48, 32, 20, color='black'); "

#: name -> (group, code, modes).  The code runs with ``sl`` (scanline), ``np`` (numpy)
#: and ``fb``, a 96 x 64 frame buffer with a white background in each mode listed;
#: modes ``None``: the call does not draw into ``fb``.  ``group`` names the kernels
#: the call mostly reaches (a parallel warm-up gives each group to one process).
CALLS = {
    "line": ("lines", "sl.draw.line(fb, 3, 4, 90, 50, color='black')", MODES),
    "line dda": ("lines", "sl.draw.line(fb, 3, 4, 90, 50, color='black', method='dda')", RGB),
    "lines": ("lines", "sl.draw.lines(fb, np.array([[3, 4, 90, 50], [0, 60, 95, 0]]), "
                       "color='black')", MODES),
    "line translucent": ("lines", "sl.draw.line(fb, 3, 4, 90, 50, color=(255, 0, 0, 128))",
                         ("RGB", "RGBA")),
    "circle": ("conics", "sl.draw.circle(fb, 48, 32, 20, color='black')", MODES),
    "circles": ("conics", "sl.draw.circles(fb, [[48, 32, 20], [20, 20, 9]], color='black')",
                MODES),
    "ellipse": ("conics", "sl.draw.ellipse(fb, 48, 32, 30, 12, color='black')", MODES),
    "ellipses": ("conics", "sl.draw.ellipses(fb, [[48, 32, 30, 12], [20, 20, 9, 4]], "
                           "color='black')", RGB),
    "line aa": ("antialias", "sl.draw.line(fb, 3.5, 4, 90, 50.2, color='black', "
                             "antialias=True)", MODES),
    "lines aa": ("antialias", "sl.draw.lines(fb, [[3, 4, 90, 50], [0, 60, 95, 0]], "
                              "color='black', antialias=True)", MODES),
    "circle aa": ("antialias", "sl.draw.circle(fb, 48, 32, 20.5, color='black', "
                               "antialias=True)", MODES),
    "ellipse aa": ("antialias", "sl.draw.ellipse(fb, 48, 32, 30, 12.5, color='black', "
                                "antialias=True)", RGB),
    "polygon aa": ("antialias", f"sl.draw.polygon(fb, {STAR}, color='black', antialias=True)",
                   MODES),
    "polygons aa": ("antialias", f"sl.draw.polygons(fb, [{STAR}, {TRIANGLE}], color='black', "
                                 "antialias=True)", RGB),
    "fill_circle aa": ("antialias", "sl.draw.fill_circle(fb, 48, 32, 20.5, color='black', "
                                    "antialias=True)", MODES),
    "fill_ellipses aa": ("antialias", "sl.draw.fill_ellipses(fb, [[48, 32, 30, 12]], "
                                      "color='black', antialias=True)", RGB),
    "polyline thick aa": ("antialias", f"sl.draw.polyline(fb, {PATH}, color='black', width=5, "
                                       "join='round', antialias=True)", MODES),
    "curve filled aa": ("antialias", "sl.draw.curve(fb, sl.curves.nurbs_circle((48, 32), 20), "
                                     "color='black', fill=True, antialias=True)", RGB),
    "text outline aa": ("antialias", "sl.draw.text(fb, 4, 20, 'Hello', color='black', "
                                     "height=14, antialias=True)", RGB),
    "polygon": ("polygon", f"sl.draw.polygon(fb, {STAR}, color='black')", MODES),
    "polygon nonzero": ("polygon", f"sl.draw.polygon(fb, {STAR}, color='black', "
                                   "rule='nonzero')", RGB),
    "polygons": ("polygon", f"sl.draw.polygons(fb, [{STAR}, {TRIANGLE}], color='black')", RGB),
    "polygon hatch": ("polygon", f"sl.draw.polygon(fb, {STAR}, color='black', "
                                 "style=sl.FillStyle.hatch(angle=0.8, spacing=6, cross=True))",
                      RGB),
    "polygon translucent": ("polygon", f"sl.draw.polygon(fb, {STAR}, color=(255, 0, 0, 128))",
                            ("RGB", "RGBA")),
    "inside": ("polygon", f"sl.geometry.inside([(32, 30), (5, 5)], {STAR}, rule='nonzero')",
               None),
    "fill_circle": ("curved", "sl.draw.fill_circle(fb, 48, 32, 20, color='black')", MODES),
    "fill_circles": ("curved", "sl.draw.fill_circles(fb, [[48, 32, 20], [20, 20, 9]], "
                               "color='black')", RGB),
    "fill_ellipse": ("curved", "sl.draw.fill_ellipse(fb, 48, 32, 30, 12, color='black')", RGB),
    "arc": ("curved", "sl.draw.arc(fb, 48, 32, 30, 20, 0.2, 2.5, color='black')", RGB),
    "pie": ("curved", "sl.draw.pie(fb, 48, 32, 30, 20, 0.2, 2.5, color='black')", RGB),
    "chord": ("curved", "sl.draw.chord(fb, 48, 32, 30, 20, 0.2, 2.5, color='black')", RGB),
    "polyline": ("strokes", f"sl.draw.polyline(fb, {PATH}, color='black')", RGB),
    "polyline thick round": ("strokes", f"sl.draw.polyline(fb, {PATH}, color='black', width=5, "
                                        "cap='round', join='round')", MODES),
    "polyline thick miter": ("strokes", f"sl.draw.polyline(fb, {PATH}, color='black', width=5, "
                                        "join='miter')", RGB),
    "polyline dashed": ("strokes", f"sl.draw.polyline(fb, {PATH}, color='black', dash=(6, 3))",
                        RGB),
    "polyline dashed thick": ("strokes", f"sl.draw.polyline(fb, {PATH}, color='black', "
                                         "dash=(6, 3), width=3)", RGB),
    "polyline mask": ("strokes", f"sl.draw.polyline(fb, {PATH}, color='black', "
                                 "dash=0b1111000011110000)", RGB),
    "polyline pen": ("strokes", f"sl.draw.polyline(fb, {PATH}, color='black', pen='circle', "
                                "width=3)", RGB),
    "polylines": ("strokes", "sl.draw.polylines(fb, [[(3, 4), (50, 60)], [(90, 5), (10, 50), "
                             "(60, 10)]], color='black', width=3)", RGB),
    "circle thick": ("strokes", "sl.draw.circle(fb, 48, 32, 20, color='black', width=4)", RGB),
    "circle dashed": ("strokes", "sl.draw.circle(fb, 48, 32, 20, color='black', dash=(4, 2))",
                      RGB),
    "curve bspline thick": ("strokes", "sl.draw.curve(fb, sl.curves.BSpline([(5, 5), (20, 60), "
                                       "(50, 30), (70, 60), (90, 5)], order=4), color='black', "
                                       "width=3)", RGB),
    "flood_fill": ("seedfill", DISK + "sl.draw.flood_fill(fb, 48, 32, 'red')", MODES),
    "flood_fill 8": ("seedfill", DISK + "sl.draw.flood_fill(fb, 48, 32, 'red', connectivity=8)",
                     RGB),
    "boundary_fill": ("seedfill", DISK + "sl.draw.boundary_fill(fb, 48, 32, 'red', "
                                         "boundary='black')", MODES),
    "soft_fill": ("seedfill", "sl.draw.fill_circle(fb, 48, 32, 20, color='black', "
                              "antialias=True); sl.draw.soft_fill(fb, 48, 32, 'red', 'black', "
                              "'white')", RGB),
    "text outline": ("text", "sl.draw.text(fb, 4, 20, 'Hello', color='black', height=14)", MODES),
    "text outline rotated": ("text", "sl.draw.text(fb, 4, 20, 'Hello', color='black', height=14, "
                                     "angle=0.3)", RGB),
    "text bitmap": ("text", "sl.draw.text(fb, 4, 20, 'Hello', color='black', font='bitmap')",
                    RGB),
    "text stroke": ("text", "sl.draw.text(fb, 4, 20, 'Hello', color='black', font='stroke', "
                            "height=12)", RGB),
    "clip text": ("text", "sl.clip.text(sl.text.layout('Hello', 0, 0, height=10), "
                          "(0, 0, 20, 20))", None),
    "curve bezier": ("curves", "sl.draw.curve(fb, sl.curves.Bezier([(5, 5), (30, 60), (60, 60), "
                               "(90, 5)]), color='black')", RGB),
    "bezier evaluate": ("curves", "sl.curves.Bezier([(0, 0), (1, 3), (4, 3), (5, 0)])"
                                  ".evaluate(np.linspace(0, 1, 1000))", None),
    "bspline evaluate": ("curves", "sl.curves.BSpline([(0, 0), (1, 2), (3, 3), (4, 0), (6, 1)], "
                                   "order=4, knots='open').evaluate(np.linspace(0, 1, 1000))",
                         None),
    "curve flatten": ("curves", "sl.curves.BSpline([(0, 0), (1, 2), (3, 3), (4, 0), (6, 1)], "
                                "order=4, knots='open').flatten(0.01)", None),
    "surface tessellate": ("curves", "sl.curves.teapot_mesh(4)", None),
    "dither floyd-steinberg": ("dither", "sl.color.dither(np.linspace(0, 1, 96 * 64)"
                                         ".reshape(64, 96))", None),
    "dither bayer": ("dither", "sl.color.dither(np.linspace(0, 1, 96 * 64).reshape(64, 96), "
                               "'bayer4', levels=4)", None),
    "dither palette": ("dither", "sl.color.dither(np.random.default_rng(0).integers(0, 256, "
                                 "(64, 96, 3), np.uint8), palette=sl.color.web_safe_table())",
                       None),
    "median_cut_table": ("dither", "sl.color.median_cut_table(np.random.default_rng(0)"
                                   ".integers(0, 256, (64, 96, 3), np.uint8), 16)", None),
    "clip lines cohen-sutherland": ("clip", "sl.clip.lines(np.random.default_rng(1).uniform("
                                            "-50, 150, (100, 4)), (0, 0, 100, 100), "
                                            "method='cohen-sutherland')", None),
    "clip lines liang-barsky": ("clip", "sl.clip.lines(np.random.default_rng(1).uniform(-50, "
                                        "150, (100, 4)), (0, 0, 100, 100), "
                                        "method='liang-barsky')", None),
    "clip line cyrus-beck": ("clip", "sl.clip.line(-5, 2, 15, 22, [(0, 0), (10, 0), (12, 8), "
                                     "(4, 12)], method='cyrus-beck')", None),
    "clip polygon sutherland-hodgman": ("clip", "sl.clip.polygon([(0, 0), (10, 0), (10, 10), "
                                                "(5, 2), (0, 10)], (1, 1, 9, 6))", None),
    "clip polygon weiler-atherton": ("clip", "sl.clip.polygon([(0, 0), (10, 0), (10, 10), "
                                             "(5, 2), (0, 10)], (1, 1, 9, 6), "
                                             "method='weiler-atherton')", None),
    "clip polygons": ("clip", "sl.clip.polygons([[(0, 0), (10, 0), (10, 10)], [(2, 2), "
                              "(12, 3), (5, 9)]], (1, 1, 9, 6))", None),
    "clip ellipse": ("clip", "sl.clip.ellipse(5, 5, 8, 3, (0, 0, 10, 10))", None),
    "display file": ("display", "df = sl.DisplayFile(); df.set_viewing(window=(0, 0, 100, 100), "
                                "viewport=(0, 0, 1, 1)); df.create_segment('house'); "
                                "df.polygon([(20, 10), (80, 10), (80, 60), (20, 60)], "
                                "color='tan', edge='brown', width=2); df.text((25, 30), 'HOME', "
                                "height=8, color='black', font='stroke'); df.close_segment(); "
                                "df.draw(fb)", RGB),
    "context": ("display", "ctx = sl.Context(fb); ctx.rotate(0.3, pivot=(48, 32)); "
                           "ctx.set_line(color='red', width=3); ctx.rectangle(30, 20, 30, 20)",
                RGB),
    "display pick": ("display", "df = sl.DisplayFile(); df.set_viewing(window=(0, 0, 100, 100)); "
                                "df.create_segment('roof'); df.polyline([(10, 50), (50, 90), "
                                "(90, 50)]); df.polygon([(20, 10), (80, 10), (80, 50)]); "
                                "df.close_segment(); df.pick(50, 89, 2, (101, 101)); "
                                "df.pick(60, 30, 2, (101, 101))", None),
    "raster-scan simulation": ("display", "from scanline.display.crt import RasterScan; "
                                          "sl.draw.circle(fb, 48, 32, 20, color='black'); "
                                          "RasterScan(fb, interlaced=True).frames(8, 1, scale=2)",
                               RGB),
    "beier_neely": ("animation", "sl.animation.beier_neely(np.zeros((32, 48, 3), np.uint8), "
                                 "np.full((32, 48, 3), 200, np.uint8), [[5, 5, 40, 20]], "
                                 "[[8, 4, 42, 25]], 0.5)", None),
    "rotate_block": ("animation", "sl.raster.rotate_block(fb, fb.__class__(20, 10, mode=fb.mode), "
                                  "(0, 0, 20, 10), 0.6, center=(48, 32))", RGB),
    "keyframes catmull-rom": ("animation", "sl.animation.KeyFrames([0, 1, 3], [(0, 0), (5, 4), "
                                           "(9, 1)], interpolation='catmull-rom')"
                                           "(np.linspace(0, 3, 50))", None),
    "motion path": ("animation", "sl.animation.MotionPath(sl.curves.Bezier([(0, 0), (0, 9), "
                                 "(9, 9), (9, 0)])).point(np.linspace(0, 1, 20))", None),
    "camera project": ("three_d", "sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)).project("
                                  "np.random.default_rng(0).uniform(-1, 1, (100, 3)), 96, 64)",
                       None),
    "clip lines3d liang-barsky": ("three_d", "sl.clip.lines3d(np.random.default_rng(1).uniform("
                                             "-5, 15, (100, 6)), ((0, 0, 0), (10, 10, 10)))",
                                  None),
    "clip lines3d cohen-sutherland": ("three_d", "sl.clip.lines3d(np.random.default_rng(1)"
                                                 ".uniform(-5, 15, (100, 6)), ((0, 0, 0), "
                                                 "(10, 10, 10)), method='cohen-sutherland')",
                                      None),
    "clip homogeneous": ("three_d", "sl.clip.homogeneous([[(1, 1, 1, 2), (1, 1, -3, -2)]])",
                         None),
    "clip polygon3d": ("three_d", "sl.clip.polygon3d([(-1, 0.5, 0.5), (2, 0.5, 0.5), "
                                  "(0.5, 2, 0.5)], ((0, 0, 0), (1, 1, 1)))", None),
    "wireframe": ("three_d", "sl.draw3d.wireframe(fb, sl.mesh.torus(1, 0.3), "
                             "sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)), color='black')", RGB),
    "wireframe depth cue": ("three_d", "sl.draw3d.wireframe(fb, sl.mesh.sphere(), "
                                       "sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)), "
                                       "color='black', depth_cue=True)", RGB),
    "mesh obj": ("three_d", "(lambda c: (c.vertices, c.indices, c.uv, c.normals))(__import__("
                            "'scanline.mesh.obj', fromlist=['read_obj']).read_obj(b'v 0 0 0\\n"
                            "v 1 0 0\\nv 0 1 0.12345678901234567\\nvt 0 0\\nvt .5 1\\n"
                            "vn 0 0 1\\nf 1/1/1 2/2/1 -1/1/-1\\nf 1/2 2/1 3/1\\n', "
                            "'warmup.obj'))", None),
    "draw3d polylines thick": ("three_d", "sl.draw3d.polylines(fb, [[(0, 0, 0), (1, 1, 0), "
                                          "(1, 0, 1)]], sl.Camera(eye=(3, 2, 4), "
                                          "target=(0, 0, 0)), color='black', width=3)", RGB),
    "triangles": ("render", "sl.draw.triangles(fb, [[(3, 4, 0.5), (90, 20, 0.2), (30, 60, 0.9)]], "
                            "colors=np.array([[[255, 0, 0], [0, 255, 0], [0, 0, 255]]]), "
                            "depth=sl.DepthBuffer.like(fb))", ("L", "RGB", "RGBA")),
    "triangles no depth": ("render", "sl.draw.triangles(fb, [[(3, 4, 0), (90, 20, 0), "
                                     "(30, 60, 0)]], colors='red')", RGB),
    "render z-buffer": ("render", "sl.render(fb, sl.mesh.sphere(1, resolution=(8, 4)), "
                                  "sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)), "
                                  "shading='phong')", RGB),
    "render phong blinn": ("render", "sl.render(fb, sl.mesh.torus(1, 0.4, resolution=(8, 4)), "
                                     "sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)), "
                                     "shading='phong', specular='blinn')", ("L", "RGB", "RGBA")),
    "render gouraud": ("render", "sl.render(fb, sl.mesh.torus(1, 0.4, resolution=(8, 4)), "
                                 "sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)))", RGB),
    "render ray-casting": ("render", "sl.render(fb, sl.mesh.cube(), sl.Camera(eye=(3, 2, 4), "
                                     "target=(0, 0, 0)), method='ray-casting')", RGB),
    "render ray-tracing": ("raytrace", "sl.render(fb, [sl.mesh.cube(), sl.mesh.sphere(0.5, "
                                       "center=(0, 1.2, 0), resolution=(8, 4))], "
                                       "sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)), "
                                       "method='ray-tracing', materials=[sl.lighting.Material("
                                       "reflectivity=0.5, roughness=0.1), sl.lighting.Material("
                                       "transparency=0.5, refractive_index=1.5)], lights=["
                                       "sl.lighting.AmbientLight(0.2), sl.lighting.AreaLight("
                                       "(1, 4, 1), (1, 0, 0), (0, 0, 1), samples=2)])", RGB),
    "render ray-tracing maps": ("raytrace", "sl.render(fb, [sl.mesh.Mesh([(-2, -1, -2), "
                                            "(2, -1, -2), (2, -1, 2), (-2, -1, 2)], [[3, 2, 1, 0]], "
                                            "uv=[(0, 0), (1, 0), (1, 1), (0, 1)]), "
                                            "sl.mesh.sphere(0.8, resolution=(8, 4))], "
                                            "sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)), "
                                            "method='ray-tracing', shading='phong', materials=["
                                            "sl.lighting.Material(texture=sl.texture.checker(8, 2), "
                                            "bump=sl.texture.checker(8, 2), reflectivity=0.3), "
                                            "sl.lighting.Material(reflectivity=0.8, environment="
                                            "sl.texture.CubeMap([np.full((2, 2, 3), 40 * k, "
                                            "np.uint8) for k in range(6)]))])", RGB),
    "cube map": ("render", "sl.texture.CubeMap([np.full((2, 2, 3), 40 * k, np.uint8) for k in "
                            "range(6)]).sample([(1, 0, 0), (0, -1, 0.5)]).tolist()", None),
    "raytrace bvh": ("raytrace", "sl.raytrace.BVH(sl.mesh.torus(1, 0.4, resolution=(8, 4))"
                                 ".triangulated().vertices[sl.mesh.torus(1, 0.4, resolution="
                                 "(8, 4)).triangulated().faces]).intersect([(0, 0, 3), "
                                 "(1, 0, 3)], [(0, 0, -1), (0, 0, -1)]).t.tolist()", None),
    "radiosity hemicube": ("radiosity", "sl.radiosity.solve(sl.radiosity.cornell_box()['meshes'], "
                                        "sl.radiosity.cornell_box()['emission'], 0.5, "
                                        "subdivisions=1, resolution=16).radiosity.tolist()", None),
    "radiosity ray-casting": ("radiosity", "sl.radiosity.solve(sl.radiosity.cornell_box()["
                                           "'meshes'], sl.radiosity.cornell_box()['emission'], "
                                           "0.5, subdivisions=1, method='progressive', "
                                           "form_factors='ray-casting', resolution=2"
                                           ").radiosity.tolist()", None),
    "render a-buffer": ("render", "sl.render(fb, sl.mesh.cube(), sl.Camera(eye=(3, 2, 4), "
                                  "target=(0, 0, 0)), method='a-buffer', samples=2)", RGB),
    "render antialias": ("render", "sl.render(fb, sl.mesh.cube(), sl.Camera(eye=(3, 2, 4), "
                                   "target=(0, 0, 0)), antialias=2)", ("L", "RGB", "RGBA")),
    "render texture": ("render", "sl.render(fb, sl.mesh.Mesh([(-1, 0, 0), (1, 0, 0), (1, 0, -4), "
                                 "(-1, 0, -4)], [[0, 1, 2, 3]], uv=[(0, 0), (1, 0), (1, 2), "
                                 "(0, 2)]), sl.Camera(eye=(0, 1, 1.5), target=(0, 0, -2)), "
                                 "materials=sl.lighting.Material(texture=sl.texture.checker("
                                 "16, 4, filter='trilinear')))", ("L", "RGB", "RGBA")),
    "render texture phong": ("render", "sl.render(fb, sl.mesh.Mesh([(-1, 0, 0), (1, 0, 0), "
                                       "(1, 0, -4), (-1, 0, -4)], [[0, 1, 2, 3]], uv=[(0, 0), "
                                       "(1, 0), (1, 2), (0, 2)]), sl.Camera(eye=(0, 1, 1.5), "
                                       "target=(0, 0, -2)), shading='phong', "
                                       "materials=sl.lighting.Material(texture="
                                       "sl.texture.checker(16, 4)))", RGB),
    "visible scan-line": ("visible", "sl.render(fb, [sl.mesh.cube(), sl.mesh.sphere(0.6, "
                                     "(0.8, 0.5, 0.8))], sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)), "
                                     "method='scan-line', shading='none')", RGB),
    "visible depth sort": ("visible", "sl.render(fb, [sl.mesh.cube(), sl.mesh.sphere(0.6, "
                                      "(0.8, 0.5, 0.8))], sl.Camera(eye=(3, 2, 4), "
                                      "target=(0, 0, 0)), method='depth-sort', shading='none')", RGB),
    "visible bsp": ("visible", "sl.render(fb, [sl.mesh.cube(), sl.mesh.sphere(0.6, "
                               "(0.8, 0.5, 0.8))], sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)), "
                               "method='bsp', shading='none')", RGB),
    "visible area subdivision": ("visible", "sl.render(fb, [sl.mesh.cube(), "
                                            "sl.mesh.sphere(0.6, (0.8, 0.5, 0.8))], "
                                            "sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)), "
                                            "method='area-subdivision', shading='none')", RGB),
    "visible octree": ("visible", "sl.render(fb, [sl.mesh.cube(), sl.mesh.sphere(0.6, "
                                  "(0.8, 0.5, 0.8))], sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)), "
                                  "method='octree', shading='none')", RGB),
    "csg ray-casting": ("csg", "sl.render(fb, [(sl.solids.Box() & sl.solids.Sphere(radius=1.3)) "
                               "- sl.solids.Cylinder(radius=0.5, height=3), sl.solids.MeshSolid("
                               "sl.mesh.cube(0.5, center=(2, 0, 0)))], sl.Camera(eye=(3, 2, 4), "
                               "target=(0, 0, 0)), method='ray-casting')", RGB),
    "csg volume": ("csg", "sl.csg.mass_properties(sl.solids.Sphere() - sl.solids.MeshSolid("
                          "sl.mesh.cube(1.0)), resolution=16).volume", None),
    "octree": ("octree", "(sl.octree.Octree.from_mesh(sl.mesh.cube(), 3) - sl.octree.Octree"
                         ".from_solid(sl.solids.Sphere(), 3)).to_mesh().face_count", None),
    "quadtree": ("octree", "(sl.octree.Quadtree.from_polygon([(1, 1), (7, 2), (3, 6)], 3) | "
                           "sl.octree.Quadtree.from_image(np.eye(8))).to_image().sum()", None),
    "visible lines": ("visible", "sl.visible.visible_lines(fb, sl.mesh.torus(1, 0.3), "
                                 "sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)), color='black', "
                                 "hidden='dash')", RGB),
    "floating horizon": ("visible", "sl.draw3d.floating_horizon(fb, lambda x, y: np.sin(3 * x) "
                                    "* np.cos(2 * y), color='black')", RGB),
    "fractals mandelbrot": ("fractals", "sl.fractals.mandelbrot(24, 16, max_iterations=64)"
                                        ".tolist()", None),
    "fractals fern": ("fractals", "sl.fractals.fern(200, seed=1).tolist()", None),
    "fractals turtle": ("fractals", "[p.tolist() for p in sl.fractals.plant(2)]", None),
    "four calls": ("mixed", "sl.draw.line(fb, 3, 4, 90, 50, color='black'); "
                            f"sl.draw.polygon(fb, {STAR}, color='navy', rule='nonzero'); "
                            "sl.draw.text(fb, 4, 20, 'Hello', color='black', height=14); "
                            "sl.draw.circle(fb, 48, 32, 20.5, color='red', antialias=True)", RGB),
}


def cases(names: Iterable[str] | None = None,
          modes: Sequence[str] = MODES) -> Iterator[tuple[str, str | None, str]]:
    """``(name, mode, code)`` for the calls ``names`` (default: all) in ``modes`` (a
    call that does not draw runs once, with mode None)."""
    for name in names or CALLS:
        _, code, call_modes = CALLS[name]
        if call_modes is None:
            yield name, None, code
        else:
            for mode in call_modes:
                if mode in modes:
                    yield name, mode, code


def run_case(mode: str | None, code: str) -> "FrameBuffer":
    """Make one call: ``code`` with ``sl``, ``np`` and a fresh 96 x 64 ``fb`` (white,
    in ``mode``; RGB for calls that do not draw).  Returns the frame buffer."""
    import numpy as np

    import scanline as sl

    fb = sl.FrameBuffer(96, 64, mode=cast("Mode", mode or "RGB"), background="white")
    exec(code, {"sl": sl, "np": np, "fb": fb})
    return fb


def run(names: Iterable[str] | None = None, modes: Sequence[str] = MODES,
        progress: Callable[[int, int, str], object] | None = None
        ) -> dict[tuple[str, str | None], float]:
    """Make the calls ``names`` (default: every call) in ``modes``, compiling or
    loading every kernel they reach (small as the calls are, never through the
    kernels' Python twins: :func:`scanline._kernels._jit.call`); returns the seconds
    each took, by ``(name, mode)``.  ``progress(done, total, name)`` is called after
    each."""
    from ._kernels import _jit

    todo = list(cases(names, modes))
    seconds: dict[tuple[str, str | None], float] = {}
    before, _jit.COMPILE = _jit.COMPILE, "always"
    try:
        for i, (name, mode, code) in enumerate(todo):
            t0 = time.perf_counter()
            run_case(mode, code)
            seconds[name, mode] = time.perf_counter() - t0
            if progress is not None:
                progress(i + 1, len(todo), name)
    finally:
        _jit.COMPILE = before
    return seconds


def by_group(modes: Sequence[str] = MODES) -> list[list[str]]:
    """The names of the calls, one list per group, the groups with the most calls in
    ``modes`` first (the order in which parallel workers should take them)."""
    members: dict[str, list[str]] = {}
    for name, mode, _ in cases(None, modes):
        members.setdefault(CALLS[name][0], [])
        if name not in members[CALLS[name][0]]:
            members[CALLS[name][0]].append(name)
    sizes = {g: sum(1 for n, _, _ in cases(names, modes)) for g, names in members.items()}
    return [members[g] for g in sorted(members, key=lambda g: -sizes[g])]
