"""Texture mapping: perspective-correct, bilinear-filtered textured triangles at 1920 x
1080, scanline's ``sl.render`` against Mesa's llvmpipe (OpenGL through moderngl, EGL,
headless, multithreaded on every core) in one run.

Workload (issue 28, "Speed"): a 100,000-triangle grid (224 x 224 quads) on the plane y =
0 seen in perspective from above its near edge, filling the frame to the horizon, its
texture coordinates repeating a 512 x 512 marble texture 8 times each way, bilinear,
Gouraud-lit by an ambient and a directional light.  scanline: ``sl.render(fb, grid,
camera, materials=Material(texture=...))`` -- preparation, clipping, z-buffer, the
perspective-correct interpolation of u and v, the texture lookups and the lighting
all timed.  Mesa: the same triangles as a vertex buffer (uploaded outside the clock)
with per-vertex lighting, the texture (uploaded outside the clock, GL_LINEAR,
GL_REPEAT; GLSL interpolates perspective-correct), a depth test, timed from the clear
to the pixels read back (``fbo.read``).

Ratio: Mesa time / scanline time (above 1: scanline is faster).

Thread counts: the same on both sides, every core by default: scanline's rows and
triangles are shared out by numba's thread count (``numba.set_num_threads``), and
llvmpipe's rasterizer threads are set by ``LP_NUM_THREADS`` (read when the GL context
is made, after scanline's timing) to the same number; ``--threads N`` sets both.
Each side's time is the best of ``--repeats`` warm frames (default 10: llvmpipe's
frames vary more on a shared machine).

Run: ``python benchmarks/texture.py [--quick] [--threads N] [--repeats R]``
(``--quick``: a 10x smaller grid).
"""

import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402
from render import W, H, gl_setup  # noqa: E402

import scanline as sl  # noqa: E402

GL_TEXTURED = ("""
#version 330
uniform mat4 clip; uniform vec2 size; uniform vec3 light;
in vec3 position; in vec2 uv; out vec2 v_uv; out float v_i;
void main() {
    vec4 h = clip * vec4(position, 1.0);
    vec2 dev = h.xy * (size - 1.0) + 0.5 * h.w;
    gl_Position = vec4(2.0 * dev / size - h.w, 2.0 * h.z - h.w, h.w);
    v_uv = uv;
    v_i = 0.2 * 0.3 + 0.9 * 0.7 * max(dot(vec3(0.0, 1.0, 0.0), -light), 0.0);
}""", """
#version 330
uniform sampler2D tex;
in vec2 v_uv; in float v_i; out vec4 color;
void main() {
    vec3 t = pow(texture(tex, v_uv).rgb, vec3(2.2));
    color = vec4(pow(clamp(t * v_i, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}""")


def grid(n, size=40.0, repeats=8.0):
    """An n x n grid of quads (2 n^2 triangles) on y = 0, x in -size/2..size/2, z in
    0..-size, texture coordinates 0..repeats."""
    t = np.linspace(0.0, 1.0, n + 1)
    x, z = np.meshgrid(t, t)
    verts = np.stack([(x - 0.5) * size, np.zeros_like(x), -z * size], -1).reshape(-1, 3)
    uv = np.stack([x, z], -1).reshape(-1, 2) * repeats
    i = np.arange(n)
    a = (i[:, None] * (n + 1) + i[None, :]).reshape(-1)
    quads = np.stack([a, a + 1, a + n + 2, a + n + 1], 1)
    tris = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    return sl.mesh.Mesh(verts, tris, uv=uv)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--threads", type=int, default=None,
                    help="threads for both sides (default: numba's, every core)")
    ap.add_argument("--repeats", type=int, default=10)
    args = ap.parse_args()
    import numba

    if args.threads is not None:
        numba.set_num_threads(args.threads)
    threads = numba.get_num_threads()
    os.environ["LP_NUM_THREADS"] = str(threads)
    report = Report("texture", quick=args.quick)
    n = 70 if args.quick else 224
    mesh = grid(n)
    texture = sl.texture.marble(512, seed=1, filter="bilinear", wrap="repeat")
    mat = sl.lighting.Material(ka=0.3, kd=0.7, ks=0.0, texture=texture)
    cam = sl.Camera(eye=(0, 2.0, 1.0), target=(0, 0, -8),
                    projection=sl.projection.perspective(fov=math.radians(60), near=0.5,
                                                         far=60))
    light = sl.lighting.DirectionalLight((0.3, -1.0, -0.4), 0.9)
    lights = [sl.lighting.AmbientLight(0.2), light]
    fb = sl.FrameBuffer(W, H)
    work = f"textured grid {2 * n * n // 1000}k bilinear"

    def ours():
        fb.clear()
        sl.render(fb, mesh, cam, materials=mat, lights=lights)
    report.add(work, "scanline", "sl.render(fb, grid, camera, materials=Material(texture=...)), "
               f"{threads} threads", ours, repeats=args.repeats)
    fb.save(os.path.join(os.path.dirname(os.path.abspath(__file__)), "results",
                         "texture-grid.png"))
    ctx, renderer = gl_setup()
    if ctx is not None:
        import moderngl

        tri = mesh.triangulated()
        f = tri.face_indices.reshape(-1, 3)
        data = np.concatenate([mesh.vertices[f], mesh.uv[f]], axis=2)
        prog = ctx.program(vertex_shader=GL_TEXTURED[0], fragment_shader=GL_TEXTURED[1])
        prog["clip"].write(cam.matrix(W, H).T.astype("f4").tobytes())
        prog["size"].value = (W, H)
        prog["light"].value = tuple(light.direction / np.linalg.norm(light.direction))
        # image rows top first; GL's first row is v = 0
        img = np.ascontiguousarray(np.rint(texture.image[::-1] * 255).astype(np.uint8))
        tex = ctx.texture((texture.width, texture.height), 3, img.tobytes())
        tex.filter = (moderngl.LINEAR, moderngl.LINEAR)
        tex.repeat_x = tex.repeat_y = True
        tex.use(0)
        prog["tex"].value = 0
        vbo = ctx.buffer(data.astype("f4").tobytes())
        vao = ctx.vertex_array(prog, [(vbo, "3f 2f", "position", "uv")])
        fbo = ctx.framebuffer(color_attachments=[ctx.renderbuffer((W, H), 4)],
                              depth_attachment=ctx.depth_renderbuffer((W, H)))

        def mesa():
            fbo.use()
            fbo.clear(0.0, 0.0, 0.0, 1.0, depth=1.0)
            ctx.enable(moderngl.DEPTH_TEST)
            vao.render(moderngl.TRIANGLES)
            return fbo.read(components=4)
        report.add(work, "mesa", f"moderngl textured GL_TRIANGLES on {renderer}, GL_LINEAR, "
                   f"clear to read-back, LP_NUM_THREADS={threads}", mesa, repeats=args.repeats)
        report.target(work, "mesa", 1.0, ">= 1.0: at least as fast as Mesa llvmpipe")
        from PIL import Image

        pixels = np.frombuffer(mesa(), np.uint8).reshape(H, W, 4)[::-1, :, :3]
        Image.fromarray(pixels).save(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                  "results", "texture-grid-mesa.png"))
    print(f"  cores: {os.cpu_count()}, threads: scanline {threads}, llvmpipe {threads}")
    report.write()


if __name__ == "__main__":
    main()
