"""Three-dimensional viewing: scanline's batch kernels against plain numpy, Pillow and
Mesa's llvmpipe (OpenGL through moderngl), on the same workloads in one run.

Workloads (fixed seed):

* ``project``: 10M random points through a perspective camera to 1920 x 1080 device
  x, y and depth.  scanline: ``camera.project(points, 1920, 1080)`` (one compiled
  pass); numpy: the same arithmetic written as array expressions (the 4x4 product,
  the divide by w, the viewport, NaN where w <= 0).
* ``clip``: 1M random 3-D segments (endpoints uniform in [-5, 15]^3) against the box
  (0, 0, 0)-(10, 10, 10).  scanline: ``sl.clip.lines3d(segments, box, method=...)``
  for Liang-Barsky and Cohen-Sutherland; numpy: Liang-Barsky vectorized over the
  segments (p_k, q_k for the six planes, u1 = max, u2 = min), written here.
* ``wireframe``: a torus tessellated into 500,000 vertices and 1,000,000 edges, seen
  through a perspective camera onto 1920 x 1080 RGB.  scanline:
  ``sl.draw3d.wireframe(fb, mesh, camera)`` -- transform, clip in homogeneous
  coordinates, project and draw, all timed; Pillow: an ``ImageDraw.line`` loop over the
  edges already projected and clipped (by scanline, outside the clock); Mesa llvmpipe:
  ``GL_LINES`` of the same edges through a vertex shader with the camera's matrix
  into a 1920 x 1080 framebuffer, vertex and index buffers uploaded outside the clock,
  timed from the clear to the pixels read back into memory (``fbo.read``).

Ratios are peer time / scanline time (above 1: scanline is faster).

Run: ``python benchmarks/three_d.py [--quick]`` (``--quick``: 10x smaller).
"""

import argparse
import math
import os
import sys

import numpy as np
from PIL import Image, ImageDraw

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report, image_coords  # noqa: E402

import scanline as sl  # noqa: E402

W, H = 1920, 1080


def numpy_project(m, scale, offset, pts):
    """camera.project's arithmetic as numpy array expressions."""
    h = pts @ m[:, :3].T + m[:, 3]
    w = h[:, 3:]
    out = h[:, :3] / w * scale + offset
    out[w[:, 0] <= 0] = np.nan
    return out


def numpy_liang_barsky(seg, lo, hi):
    """Liang-Barsky on N segments (N, 6) at once: (clipped (N, 6), accepted)."""
    p0, d = seg[:, :3], seg[:, 3:] - seg[:, :3]
    u1 = np.zeros(len(seg))
    u2 = np.ones(len(seg))
    ok = np.ones(len(seg), bool)
    with np.errstate(divide="ignore", invalid="ignore"):
        for k in range(3):
            for p, q in ((-d[:, k], p0[:, k] - lo[k]), (d[:, k], hi[k] - p0[:, k])):
                r = q / p
                ok &= ~((p == 0) & (q < 0))
                u1 = np.where(p < 0, np.maximum(u1, r), u1)
                u2 = np.where(p > 0, np.minimum(u2, r), u2)
    ok &= u1 <= u2
    out = np.hstack([p0 + u1[:, None] * d, p0 + u2[:, None] * d])
    return np.where(ok[:, None], out, seg), ok


def gl_peer(mesh, camera):
    """A callable drawing the mesh's edges with GL_LINES on Mesa (llvmpipe), or None."""
    try:
        import moderngl

        ctx = moderngl.create_standalone_context(backend="egl")
    except Exception as error:           # no moderngl or no EGL
        print(f"  (moderngl / Mesa EGL unavailable: {error})")
        return None, None
    prog = ctx.program(vertex_shader="""
        #version 330
        uniform mat4 clip;
        uniform vec2 size;
        in vec3 position;
        void main() {
            vec4 h = clip * vec4(position, 1.0);
            vec2 dev = h.xy * (size - 1.0) + 0.5 * h.w;
            gl_Position = vec4(2.0 * dev / size - h.w, 2.0 * h.z - h.w, h.w);
        }""", fragment_shader="""
        #version 330
        out vec4 color;
        void main() { color = vec4(1.0, 1.0, 1.0, 1.0); }""")
    prog["clip"].write(camera.matrix(W, H).T.astype("f4").tobytes())
    prog["size"].value = (W, H)
    vbo = ctx.buffer(mesh.vertices.astype("f4").tobytes())
    ibo = ctx.buffer(mesh.edges.astype("i4").tobytes())
    vao = ctx.vertex_array(prog, [(vbo, "3f", "position")], index_buffer=ibo)
    fbo = ctx.simple_framebuffer((W, H), components=3)
    fbo.use()

    def draw():
        fbo.clear(0.0, 0.0, 0.0)
        vao.render(moderngl.LINES)
        return np.frombuffer(fbo.read(components=3), np.uint8)
    return draw, ctx.info["GL_RENDERER"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="10x smaller workloads")
    args = parser.parse_args()
    scale_down = 10 if args.quick else 1
    report = Report("three_d", quick=args.quick)
    rng = np.random.default_rng(2026)
    cam = sl.Camera(eye=(6, 5, 9), target=(0, 0, 0),
                    projection=sl.projection.perspective(fov=math.radians(50), near=0.5, far=60))

    # -- transform and project ----------------------------------------------------------
    n = 10_000_000 // scale_down
    pts = rng.uniform(-8, 8, (n, 3))
    m = cam.matrix(W, H)
    scale, offset = cam.device(W, H)
    work = f"project {n // 1_000_000}M points" if n >= 1_000_000 else f"project {n // 1000}k"
    report.add(work, "numpy", "h = p @ M[:, :3].T + M[:, 3]; h[:, :3] / w * scale + offset",
               lambda: numpy_project(m, scale, offset, pts), n=n)
    report.add(work, "scanline", "camera.project(points, 1920, 1080)",
               lambda: cam.project(pts, W, H), n=n)
    a, b = numpy_project(m, scale, offset, pts), cam.project(pts, W, H)
    assert np.allclose(a, b, equal_nan=True)
    report.target(work, "numpy", 1.5, ">= 1.5x faster than the same arithmetic in numpy")
    del pts, a, b

    # -- clipping ---------------------------------------------------------------------------
    n = 1_000_000 // scale_down
    seg = rng.uniform(-5, 15, (n, 6))
    lo, hi = (0.0, 0.0, 0.0), (10.0, 10.0, 10.0)
    work = f"clip {n // 1000}k segments"
    report.add(work, "numpy", "Liang-Barsky vectorized over the segments",
               lambda: numpy_liang_barsky(seg, lo, hi), n=n)
    ref, ref_ok = numpy_liang_barsky(seg, lo, hi)
    peer = report.rows[-1]
    for method in ("liang-barsky", "cohen-sutherland"):
        w = f"{work} {method}"
        report.rows.append(dict(peer, workload=w))
        report.add(w, "scanline", f'sl.clip.lines3d(segments, box, method="{method}")',
                   lambda mt=method: sl.clip.lines3d(seg, (lo, hi), method=mt), n=n)
        out, ok = sl.clip.lines3d(seg, (lo, hi), method=method)
        assert (ok == ref_ok).all() and np.allclose(out[ok], ref[ok])
        report.target(w, "numpy", 5.0, ">= 5x faster than a vectorized numpy Liang-Barsky")

    # -- wireframe ----------------------------------------------------------------------------
    nu, nv = (1000, 500) if not args.quick else (316, 158)
    torus = sl.mesh.torus(3.0, 1.2, resolution=(nu, nv))
    edges = torus.edges                                  # the edge table, built once
    work = f"wireframe {len(edges) // 1000}k edges"
    fb = sl.FrameBuffer(W, H)
    report.add(work, "scanline", "sl.draw3d.wireframe(fb, mesh, camera)",
               lambda: sl.draw3d.wireframe(fb, torus, cam), n=len(edges))
    segs = sl.draw3d.wireframe(fb, torus, cam)
    image_segs = image_coords(segs.reshape(-1, 2, 2), H).reshape(-1, 4).tolist()
    img = Image.new("RGB", (W, H))
    draw = ImageDraw.Draw(img)

    def pillow():
        for s in image_segs:
            draw.line(s, fill=(255, 255, 255))
    report.add(work, "pillow", "ImageDraw.line per projected, clipped edge (projection not "
               "timed)", pillow, repeats=2, n=len(edges))
    report.target(work, "pillow", 5.0, ">= 5x faster than a Pillow ImageDraw.line loop")
    gl, renderer = gl_peer(torus, cam)
    if gl is not None:
        report.add(work, "mesa", f"moderngl GL_LINES on {renderer}, clear to read-back", gl,
                   n=len(edges))
        report.target(work, "mesa", 1.0, "report; aim at least as fast as Mesa llvmpipe GL_LINES")
    report.write()


if __name__ == "__main__":
    main()
