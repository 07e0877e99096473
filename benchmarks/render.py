"""Triangle rasterization and rendering: scanline against Mesa's llvmpipe (OpenGL
through moderngl, EGL, headless, multithreaded on every core) on the same workloads
in one run.

Workloads (fixed seed), at 1920 x 1080 RGB with a depth test:

* ``1M small``: 1,000,000 random triangles of 1.7 pixels' mean area (``size`` 10 of
  :func:`random_triangles`), Gouraud colors per vertex.  scanline: ``sl.draw.triangles(fb, tris, colors=..., depth=depth)``
  (depth buffer cleared inside the clock); Mesa: the same triangles as a vertex
  buffer (uploaded outside the clock) drawn with ``GL_TRIANGLES`` and a depth test,
  timed from the clear to the pixels read back (``fbo.read``).
* ``100k medium``: 100,000 triangles of 8.5 pixels' mean area (``size`` 50).
* ``100k large``: 100,000 triangles of 51 pixels' mean area (``size`` 300): the
  pixels' share of the work, where the two above are mostly triangles and rows.
* ``teapot phong``: the Utah teapot (``sl.mesh.teapot(24)``), Phong-shaded (one
  directional light, ambient), filling most of the frame.  scanline: ``sl.render(fb,
  teapot, camera, shading="phong")`` -- preparation, clipping, z-buffer and per-pixel
  lighting all timed; Mesa: per-pixel Phong in a fragment shader, vertex buffers
  uploaded outside the clock.
* ``teapot phong 4 samples``: the same with ``antialias=2`` (2 x 2 supersampling)
  against llvmpipe's 4x MSAA (resolved, then read back).
* ``methods``: every registered visible-surface method on one 100k-triangle scene.

Ratios are peer time / scanline time (above 1: scanline is faster).

Run: ``python benchmarks/render.py [--quick] [--only gouraud teapot methods]``
(``--quick``: 10x fewer triangles; ``--only``: these groups of workloads).
"""

import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402

W, H = 1920, 1080

GL_GOURAUD = ("""
#version 330
uniform vec2 size;
in vec3 position; in vec3 color; out vec3 v_color;
void main() {
    gl_Position = vec4(2.0 * (position.xy + 0.5) / size - 1.0, 2.0 * position.z - 1.0, 1.0);
    v_color = color;
}""", """
#version 330
in vec3 v_color; out vec4 color;
void main() { color = vec4(v_color / 255.0, 1.0); }""")

GL_PHONG = ("""
#version 330
uniform mat4 clip; uniform vec2 size;
in vec3 position; in vec3 normal; out vec3 v_n; out vec3 v_p;
void main() {
    vec4 h = clip * vec4(position, 1.0);
    vec2 dev = h.xy * (size - 1.0) + 0.5 * h.w;
    gl_Position = vec4(2.0 * dev / size - h.w, 2.0 * h.z - h.w, h.w);
    v_n = normal; v_p = position;
}""", """
#version 330
uniform vec3 eye; uniform vec3 light;
in vec3 v_n; in vec3 v_p; out vec4 color;
void main() {
    vec3 n = normalize(v_n); vec3 l = -light; vec3 v = normalize(eye - v_p);
    float nl = dot(n, l);
    if (nl < 0.0) { n = -n; nl = -nl; }
    vec3 r = 2.0 * nl * n - l;
    float s = nl > 0.0 ? pow(max(dot(v, r), 0.0), 20.0) : 0.0;
    float i = 0.2 * 0.2 + 0.9 * (0.7 * nl + 0.3 * s);
    color = vec4(vec3(pow(clamp(i, 0.0, 1.0), 1.0 / 2.2)), 1.0);
}""")


def random_triangles(rng, n, size):
    """n triangles, depths 0.05..0.95, whose vertices lie at random in a square of
    side 1.2 sqrt(2 size / 1.3) pixels around a random center.  Their mean area is
    11/144 of the square's (a random triangle in a square), 0.17 ``size``: 1.7 pixels
    for ``size`` 10 and 8.5 for 50, not ``size`` pixels as this function's earlier
    docstring and the workloads' labels said (the workloads are kept as they were, so
    that their ratios compare across sessions)."""
    c = rng.uniform(0, [W, H], size=(n, 1, 2))
    r = math.sqrt(2 * size / 1.3)
    xy = c + rng.uniform(-r / 2, r / 2, size=(n, 3, 2)) * 1.2
    z = rng.uniform(0.05, 0.95, size=(n, 3, 1))
    return np.ascontiguousarray(np.concatenate([xy, z], axis=2))


def gl_setup():
    try:
        import moderngl

        ctx = moderngl.create_standalone_context(backend="egl")
    except Exception as error:
        print(f"  (Mesa unavailable: {error})")
        return None, None
    return ctx, ctx.info.get("GL_RENDERER", "?")


def gl_draw(ctx, program, buffers, fmt, names, samples=0):
    """A function drawing ``buffers`` with ``program`` from the clear to the pixels read
    back; ``samples``: multisampling (MSAA), resolved into a plain buffer first."""
    import moderngl

    vbo = ctx.buffer(buffers.astype("f4").tobytes())
    vao = ctx.vertex_array(program, [(vbo, fmt, *names)])
    fbo = ctx.framebuffer(color_attachments=[ctx.renderbuffer((W, H), 4, samples=samples)],
                          depth_attachment=ctx.depth_renderbuffer((W, H), samples=samples))
    plain = ctx.framebuffer(color_attachments=[ctx.renderbuffer((W, H), 4)]) if samples else fbo

    def run():
        fbo.use()
        fbo.clear(0.0, 0.0, 0.0, 1.0, depth=1.0)
        ctx.enable(moderngl.DEPTH_TEST)
        vao.render(moderngl.TRIANGLES)
        if samples:
            ctx.copy_framebuffer(plain, fbo)
        return plain.read(components=4)
    return run


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--only", nargs="+", choices=("gouraud", "teapot", "methods"),
                    help="run these groups of workloads only")
    args = ap.parse_args()
    run_group = lambda group: args.only is None or group in args.only  # noqa: E731
    report = Report("render" if args.only is None else "render-" + "-".join(args.only),
                    quick=args.quick)
    rng = np.random.default_rng(1)
    ctx, renderer = gl_setup()
    scale = 10 if args.quick else 1
    rounds = 3 if args.quick else 15       # scanline and Mesa in turn (common.alternated)
    for n, size, name in ((1_000_000 // scale, 10, "small"), (100_000 // scale, 50, "medium"),
                          (100_000 // scale, 300, "large")):
        tris = random_triangles(rng, n, size)
        colors = rng.uniform(0, 255, size=(n, 3, 3))       # drawn anyway: the same scenes
        if not run_group("gouraud"):
            continue
        work = f"{n // 1000}k {name} gouraud"
        fb = sl.FrameBuffer(W, H)
        depth = sl.DepthBuffer.like(fb)

        def ours():
            fb.clear()
            depth.clear()
            sl.draw.triangles(fb, tris, colors=colors, depth=depth)
        entries = [("scanline", "sl.draw.triangles(fb, tris, colors, depth=depth)", ours, n)]
        if ctx is not None:
            prog = ctx.program(vertex_shader=GL_GOURAUD[0], fragment_shader=GL_GOURAUD[1])
            prog["size"].value = (W, H)
            run = gl_draw(ctx, prog, np.concatenate([tris, colors], axis=2), "3f 3f",
                          ("position", "color"))
            entries.append(("mesa", f"moderngl GL_TRIANGLES on {renderer}, clear to read-back",
                            run, n))
        report.alternate(work, entries, rounds)
        if ctx is not None:
            report.target(work, "mesa", 1.0, ">= 1.0: at least as fast as Mesa llvmpipe")

    # -- the teapot, Phong-shaded ---------------------------------------------------------
    if run_group("teapot"):
        teapot = sl.mesh.teapot(24 if not args.quick else 8).transformed(
            sl.transform3d.rotation(-math.pi / 2, "x"))
        cam = sl.Camera(eye=(0, 2.5, 6.5), target=(0, 0.7, 0),
                        projection=sl.projection.perspective(fov=math.radians(32), near=1, far=30))
        light = sl.lighting.DirectionalLight((0.45, -0.55, -1.0), 0.9)
        lights = [sl.lighting.AmbientLight(0.2), light]
        mat = sl.lighting.Material(ka=0.2, kd=0.7, ks=0.3, shininess=20)
        fb = sl.FrameBuffer(W, H)
        work = f"teapot phong {teapot.triangulated().face_count // 1000}k triangles"

        def teapot_ours():
            fb.clear()
            sl.render(fb, teapot, cam, shading="phong", lights=lights, materials=mat)
        entries = [("scanline", 'sl.render(fb, teapot, camera, shading="phong")', teapot_ours,
                    None)]
        if ctx is not None:
            tri = teapot.triangulated()
            f = tri.face_indices.reshape(-1, 3)
            from scanline.screen import averaged_normals

            normals = teapot.normals if teapot.normals is not None else averaged_normals(teapot)
            data = np.concatenate([teapot.vertices[f], normals[f]], axis=2)
            prog = ctx.program(vertex_shader=GL_PHONG[0], fragment_shader=GL_PHONG[1])
            prog["clip"].write(cam.matrix(W, H).T.astype("f4").tobytes())
            prog["size"].value = (W, H)
            prog["eye"].value = cam.eye
            prog["light"].value = tuple(light.direction)
            run = gl_draw(ctx, prog, data, "3f 3f", ("position", "normal"))
            entries.append(("mesa", f"moderngl per-pixel Phong on {renderer}", run, None))
        report.alternate(work, entries, rounds)
        fb.save(os.path.join(os.path.dirname(os.path.abspath(__file__)), "results",
                             "render-teapot.png"))
        if ctx is not None:
            report.target(work, "mesa", 1.0, ">= 1.0: at least as fast as Mesa llvmpipe")
        # antialiased: 2 x 2 supersampling against 4x MSAA (four samples a pixel each;
        # MSAA shades once a pixel, supersampling at every sample)
        work_aa = work.replace("phong", "phong 4 samples")

        def teapot_aa():
            fb.clear()
            sl.render(fb, teapot, cam, shading="phong", lights=lights, materials=mat,
                      antialias=2)
        entries = [("scanline", 'sl.render(..., shading="phong", antialias=2)', teapot_aa,
                    None)]
        if ctx is not None:
            run = gl_draw(ctx, prog, data, "3f 3f", ("position", "normal"), samples=4)
            entries.append(("mesa", f"moderngl MSAA 4x Phong on {renderer}", run, None))
        report.alternate(work_aa, entries, max(rounds // 3, 3))
        if ctx is not None:
            report.target(work_aa, "mesa", 0.5, ">= 0.5: report (supersampling shades every "
                          "sample, MSAA once a pixel)")

    # -- every method on one scene --------------------------------------------------------
    if run_group("methods"):
        n = 100_000 // scale
        sphere_count = 40
        res = int(math.sqrt(n / sphere_count / 2))
        meshes = [sl.mesh.sphere(0.4, center=tuple(rng.uniform(-3, 3, 3)),
                                 resolution=(2 * res, res)) for _ in range(sphere_count)]
        cam = sl.Camera(eye=(0, 0, 10), target=(0, 0, 0))
        for method in sorted(sl.visible.METHODS):
            fb = sl.FrameBuffer(W, H)
            report.add(f"methods {n // 1000}k", f"scanline {method}",
                       f'sl.render(fb, spheres, camera, method="{method}")',
                       lambda: sl.render(fb, meshes, cam, method=method), repeats=2)
    report.write()


if __name__ == "__main__":
    main()
