"""Animation: parallel rendering, Beier–Neely morphing, and GIF / MP4 writing.

Workloads (fixed seed):

* ``render``: 200 frames of a 640 x 480 animated scene (schema version 2) of 60
  segments with 5 primitives each (300 primitives: filled polygons, circles,
  ellipses, thick polylines), every segment turned and moved by key-frame tracks.
  Rendered by ``Animation.images()`` and gathered in frame order in this process:
  one process (``jobs=1``), two worker processes (``jobs=2``), and a
  ``distributed.LocalCluster`` of two worker processes (one thread each).  The
  targets: jobs=2 at least 1.7x faster than jobs=1, the cluster at least 1.5x.  The
  frames must be identical whichever way they were rendered (checked).  Each jobs=2
  call starts and stops its worker pool, as every render does; the cluster is started
  once before the timings, as a user's cluster runs before a render (the render
  function is still sent to its workers, and the scene's frame plan made there, by
  every call).
* ``beier-neely``: two 1024 x 1024 RGB images, 20 line pairs, t = 0.5:
  ``sl.animation.beier_neely`` (a compiled kernel, one thread) against the same
  field morph vectorized in numpy (written below, 20 passes over the image).  Target:
  at least 5x.
* ``gif`` / ``mp4``: 100 frames of 320 x 240 already rendered, written by
  ``Animation.save`` against matplotlib's ``PillowWriter`` / ``FFMpegWriter`` (the
  frames shown with ``imshow`` on a figure of exactly that many pixels, ffmpeg from
  imageio-ffmpeg).  Reported, target >= 1 (not slower).

Run: ``python benchmarks/animation.py [--quick]`` (``--quick``: 40 frames, 512 x 512
morph).  Timings: best of the repeats after a first call (which compiles).
"""

import argparse
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402


def scene_data(rng, segments=60):
    """A version-2 scene: ``segments`` segments of 5 primitives, each segment turned
    and moved by two tracks."""
    colors = ["crimson", "navy", "teal", "orange", "purple", "olive", "gray", "gold"]
    data = {"version": 2, "canvas": {"width": 640, "height": 480, "background": "white"},
            "segments": [], "animation": {"fps": 25, "duration": 8.0, "tracks": []}}
    for k in range(segments):
        cx, cy = rng.uniform(40, 600), rng.uniform(40, 440)
        c = colors[k % len(colors)]
        star = [[cx + r * np.cos(a), cy + r * np.sin(a)]
                for a, r in zip(np.linspace(0, 2 * np.pi, 10, endpoint=False),
                                np.tile([28.0, 12.0], 5))]
        data["segments"].append({
            "name": f"s{k}",
            "transform": [{"rotate": {"degrees": 0.0, "pivot": [cx, cy]}},
                          {"translate": [0.0, 0.0]}],
            "primitives": [
                {"type": "polygon", "points": star, "color": c},
                {"type": "circle", "center": [cx, cy], "radius": 9.0, "fill": True,
                 "color": "white"},
                {"type": "ellipse", "center": [cx + 20, cy - 18], "rx": 14.0, "ry": 6.0,
                 "color": c},
                {"type": "polyline", "points": [[cx - 30, cy - 30], [cx, cy - 40],
                                                [cx + 30, cy - 30]], "color": "black",
                 "width": 3},
                {"type": "polyline", "points": [[cx - 25, cy + 30], [cx + 25, cy + 30]],
                 "color": c, "width": 2},
            ]})
        spin = float(rng.uniform(-360, 360))
        dx, dy = rng.uniform(-60, 60, 2)
        tracks = data["animation"]["tracks"]
        tracks.append({"target": f"segments[s{k}].transform[0].rotate.degrees",
                       "keys": [{"time": 0.0, "value": 0.0, "ease": "ease-in-out-sine"},
                                {"time": 8.0, "value": spin}]})
        tracks.append({"target": f"segments[s{k}].transform[1].translate",
                       "interpolation": "catmull-rom",
                       "keys": [{"time": 0.0, "value": [0.0, 0.0]},
                                {"time": 4.0, "value": [float(dx), float(dy)]},
                                {"time": 8.0, "value": [0.0, 0.0]}]})
    return data


def numpy_beier_neely(a, b, lines_a, lines_b, t, pa=1.0, pb=2.0, pp=0.5):
    """Beier & Neely's field morph vectorized in numpy (one pass per line pair)."""
    h, w = a.shape[:2]
    y, x = np.mgrid[0:h, 0:w].astype(np.float64)
    lines = lines_a + t * (lines_b - lines_a)
    out = np.zeros(a.shape, np.float64)
    for img, src, weight_t in ((a, lines_a, 1 - t), (b, lines_b, t)):
        sx, sy, total = np.zeros_like(x), np.zeros_like(x), np.zeros_like(x)
        for (px, py, qx, qy), (spx, spy, sqx, sqy) in zip(lines, src):
            dx, dy = qx - px, qy - py
            length = np.hypot(dx, dy)
            u = ((x - px) * dx + (y - py) * dy) / length ** 2
            v = ((x - px) * -dy + (y - py) * dx) / length
            sdx, sdy = sqx - spx, sqy - spy
            slen = np.hypot(sdx, sdy)
            xs = spx + u * sdx - v * sdy / slen
            ys = spy + u * sdy + v * sdx / slen
            dist = np.where(u < 0, np.hypot(x - px, y - py),
                            np.where(u > 1, np.hypot(x - qx, y - qy), np.abs(v)))
            wgt = (length ** pp / (pa + dist)) ** pb
            sx += (xs - x) * wgt
            sy += (ys - y) * wgt
            total += wgt
        xs = np.clip(x + sx / total, 0, w - 1)
        ys = np.clip(y + sy / total, 0, h - 1)
        x0, y0 = np.floor(xs).astype(np.int64), np.floor(ys).astype(np.int64)
        x1, y1 = np.minimum(x0 + 1, w - 1), np.minimum(y0 + 1, h - 1)
        fx, fy = (xs - x0)[..., None], (ys - y0)[..., None]
        top = img[y0, x0] * (1 - fx) + img[y0, x1] * fx
        bottom = img[y1, x0] * (1 - fx) + img[y1, x1] * fx
        out += weight_t * (top * (1 - fy) + bottom * fy)
    return np.clip(np.floor(out + 0.5), 0, 255).astype(np.uint8)


def bench_render(report, frames, repeats):
    from distributed import Client, LocalCluster

    from scanline.scene import AnimatedScene

    scene = AnimatedScene(scene_data(np.random.default_rng(1)))
    anim = sl.animation.Animation(scene, fps=scene.fps)
    selection = (0, frames)
    results = {}

    def render(**where):
        def run():
            results[tuple(sorted(where))] = [np.asarray(im) for im in
                                             anim.images(selection, progress=False, **where)]
        return run

    name = f"render {frames} frames 640x480, 300 primitives"
    report.add(name, "one process", "Animation.images(jobs=1)", render(), repeats, n=frames)
    report.add(name, "scanline", "Animation.images(jobs=2)", render(jobs=2), repeats, n=frames)
    report.target(name, "one process", 1.7, "jobs=2 at least 1.7x faster than jobs=1")
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        dask = f"{name}, Dask"
        report.rows.append(dict(report.rows[-2], workload=dask))        # the jobs=1 timing
        report.add(dask, "scanline", "Animation.images(client=LocalCluster(2 workers))",
                   render(client=client), repeats, n=frames)
        report.target(dask, "one process", 1.5, "a 2-worker LocalCluster at least 1.5x "
                      "faster than one process")
    serial = results[()]
    for key, frames_ in results.items():
        assert all(np.array_equal(p, q) for p, q in zip(serial, frames_)), key
    print("  frames identical: one process, jobs=2, Dask", flush=True)


def bench_morph(report, size, repeats):
    rng = np.random.default_rng(7)
    a = rng.integers(0, 256, (size, size, 3), dtype=np.uint8)
    b = rng.integers(0, 256, (size, size, 3), dtype=np.uint8)
    la = rng.uniform(0, size, (20, 4))
    lb = la + rng.uniform(-size / 20, size / 20, (20, 4))
    name = f"beier-neely {size}x{size}, 20 lines"
    report.add(name, "numpy", "vectorized numpy field morph",
               lambda: numpy_beier_neely(a[::-1], b[::-1], la, lb, 0.5), 1)
    report.add(name, "scanline", "sl.animation.beier_neely(a, b, la, lb, 0.5)",
               lambda: sl.animation.beier_neely(a, b, la, lb, 0.5), repeats)
    ours = sl.animation.beier_neely(a, b, la, lb, 0.5)
    theirs = numpy_beier_neely(a[::-1], b[::-1], la, lb, 0.5)[::-1]
    print(f"  pixels differing by more than 1 level: "
          f"{int((np.abs(ours.astype(int) - theirs) > 1).sum())}", flush=True)
    report.target(name, "numpy", 5.0, ">= 5x faster than vectorized numpy")


def bench_writers(report, count, repeats):
    import imageio_ffmpeg
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.animation as manimation
    import matplotlib.pyplot as plt

    matplotlib.rcParams["animation.ffmpeg_path"] = imageio_ffmpeg.get_ffmpeg_exe()
    w, h = 320, 240
    frames = []
    for i in range(count):
        fb = sl.FrameBuffer(w, h, background="white")
        sl.draw.fill_circle(fb, 20 + 2.8 * i, 120 + 80 * np.sin(i / 8), 18, color="crimson")
        sl.draw.polyline(fb, [(0, 20), (319, 20 + i)], color="navy", width=3)
        frames.append(np.asarray(fb.to_pil()))
    folder = tempfile.mkdtemp()

    def ours(ext):
        return lambda: sl.animation.Animation(frames, fps=25).save(
            os.path.join(folder, f"ours.{ext}"), progress=False)

    def theirs(writer_class, ext):
        def run():
            fig = plt.figure(figsize=(w / 100, h / 100), dpi=100)
            ax = fig.add_axes([0, 0, 1, 1])
            ax.axis("off")
            shown = ax.imshow(frames[0], interpolation="nearest")
            writer = writer_class(fps=25)
            with writer.saving(fig, os.path.join(folder, f"theirs.{ext}"), dpi=100):
                for f in frames:
                    shown.set_data(f)
                    writer.grab_frame()
            plt.close(fig)
        return run

    for ext, writer, label in (("gif", manimation.PillowWriter, "matplotlib PillowWriter"),
                               ("mp4", manimation.FFMpegWriter, "matplotlib FFMpegWriter")):
        name = f"{ext} {count} frames {w}x{h}"
        report.add(name, label, f"{writer.__name__} + imshow", theirs(writer, ext), repeats)
        report.add(name, "scanline", f"Animation(frames).save('x.{ext}')", ours(ext), repeats)
        report.target(name, label, 1.0, f"not slower than {writer.__name__}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="smaller workloads")
    args = parser.parse_args()
    report = Report("animation", quick=args.quick)
    bench_render(report, 40 if args.quick else 200, 1 if args.quick else 2)
    bench_morph(report, 512 if args.quick else 1024, 2)
    bench_writers(report, 30 if args.quick else 100, 2)
    report.write()


if __name__ == "__main__":
    main()
