"""Scaling: every parallel workload at 1, 2, 4, ... threads or workers, up to the
machine's cores, in one table with the core count (issue 31, item 5).

Workloads (fixed seeds; the same scenes as the topic benchmarks):

* ``lines``: 200,000 short lines on 2048 x 2048 (``sl.draw.lines``, a batch call
  whose kernel takes every n-th band of rows on each of n threads).
* ``circles``: 50,000 circles on 2048 x 2048 (``sl.draw.circles``).
* ``triangles small`` / ``medium``: 1,000,000 triangles of 1.7 pixels' mean area /
  100,000 of 8.5 pixels (``render.random_triangles`` of size 10 / 50), Gouraud colors,
  depth test, 1920 x 1080
  (``sl.draw.triangles``; as ``render.py``).
* ``teapot phong``: the Utah teapot at 1920 x 1080, Phong-shaded (``sl.render``; as
  ``render.py``).
* ``texture``: a textured grid of 100k triangles, bilinear marble (as ``texture.py``).
* ``ray tracing``: primary rays of 640 x 480 into a 100k-triangle torus through the
  BVH (``BVH.intersect``; as ``raytrace.py``).
* ``frames jobs=N`` / ``frames Dask N``: 100 frames of a 640 x 480 scene of 240
  segments (``animation.py``'s scene, four times the segments), gathered in order
  by ``Animation.images``: ``jobs=N`` worker processes, and a
  ``distributed.LocalCluster`` of N one-thread worker processes (started before the
  clock, as a user's cluster is), with Dask's default settings and again started
  under ``sl.animation.QUIET_WORKERS`` (event-loop tick 1 s, profiler off).

Threads are set with ``numba.set_num_threads(n)`` (the kernels' bands follow it);
the processes and workers render with one thread each.  The thread counts of a
workload are timed in turn, a call at each count per round, 5 x ``--repeats``
rounds after a first call (which compiles) (``common.Report.alternate``: a machine
whose speed changes from moment to moment slows every count alike); a threaded
workload's cell is its median time and its speed-up the median of the rounds'
ratios.  The frames' cell is the best of ``--repeats`` runs (one by default), and
their speed-up the time at 1 over the time at n.  Counts are 1, 2, 4, ... and the
machine's core count (``os.cpu_count()``); figures for more cores than the machine
has are never made.

Run under the benchmark lock: ``flock /tmp/bench.lock python benchmarks/scaling.py
[--quick] [--only NAME ...]`` (``--quick``: a tenth of the triangles and rays, 40
frames, one repeat).  Writes ``results/scaling[-quick].json`` and the Markdown
table ``results/scaling[-quick].md``; other processes on the machine make the
timings noisy, so rerun and compare ranges.
"""

import argparse
import math
import os
import platform
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402

W, H = 1920, 1080


def counts(cores):
    """1, 2, 4, ... below ``cores``, then ``cores``."""
    out, n = [], 1
    while n < cores:
        out.append(n)
        n *= 2
    return out + [cores]


def threads(n):
    """"1 thread", "2 threads" ...: the label of a thread count's row."""
    return f"{n} thread{'s' if n > 1 else ''}"


def machine():
    """The processor's model name (from /proc/cpuinfo where there is one)."""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def threaded(quick):
    """``{name: (call, run)}``: the workloads whose kernels run on numba's threads."""
    from render import random_triangles
    from raytrace import camera_rays, torus_triangles
    from texture import grid

    rng = np.random.default_rng(1)
    scale = 10 if quick else 1
    work = {}

    canvas = sl.FrameBuffer(2048, 2048)
    p0 = rng.integers(0, 2048, (200_000 // scale, 2))
    lines = np.concatenate([p0, p0 + rng.integers(-32, 33, p0.shape)], axis=1)
    circles = np.concatenate([rng.integers(0, 2048, (50_000 // scale, 2)),
                              rng.integers(1, 64, (50_000 // scale, 1))], axis=1)
    work["lines"] = (f"sl.draw.lines(fb, {len(lines) // 1000}k short)",
                     lambda: sl.draw.lines(canvas, lines, color="white"))
    work["circles"] = (f"sl.draw.circles(fb, {len(circles) // 1000}k)",
                       lambda: sl.draw.circles(canvas, circles, color="white"))

    fb = sl.FrameBuffer(W, H)
    depth = sl.DepthBuffer.like(fb)
    for n, size, name in ((1_000_000 // scale, 10, "small"), (100_000 // scale, 50, "medium")):
        tris = random_triangles(rng, n, size)
        colors = rng.uniform(0, 255, size=(n, 3, 3))

        def draw(tris=tris, colors=colors):
            fb.clear()
            depth.clear()
            sl.draw.triangles(fb, tris, colors=colors, depth=depth)
        work[f"triangles {name}"] = (f"sl.draw.triangles, {n // 1000}k of ~{0.17 * size:.1f} "
                                     "px mean area, Gouraud, depth", draw)

    teapot = sl.mesh.teapot(8 if quick else 24).transformed(
        sl.transform3d.rotation(-math.pi / 2, "x"))
    cam = sl.Camera(eye=(0, 2.5, 6.5), target=(0, 0.7, 0),
                    projection=sl.projection.perspective(fov=math.radians(32), near=1, far=30))
    lights = [sl.lighting.AmbientLight(0.2),
              sl.lighting.DirectionalLight((0.45, -0.55, -1.0), 0.9)]
    mat = sl.lighting.Material(ka=0.2, kd=0.7, ks=0.3, shininess=20)
    work["teapot phong"] = ('sl.render(fb, teapot, camera, shading="phong")',
                            lambda: sl.render(fb, teapot, cam, shading="phong", lights=lights,
                                              materials=mat))

    mesh = grid(70 if quick else 224)
    texture = sl.texture.marble(512, seed=1, filter="bilinear", wrap="repeat")
    tmat = sl.lighting.Material(ka=0.3, kd=0.7, ks=0.0, texture=texture)
    tcam = sl.Camera(eye=(0, 2.0, 1.0), target=(0, 0, -8),
                     projection=sl.projection.perspective(fov=math.radians(60), near=0.5,
                                                          far=60))

    def textured():
        fb.clear()
        sl.render(fb, mesh, tcam, materials=tmat, lights=lights)
    work["texture"] = (f"sl.render(fb, grid {mesh.triangulated().face_count // 1000}k, "
                       "textured)", textured)

    tri, _ = torus_triangles()
    tree = sl.raytrace.BVH(tri)
    o, d = camera_rays(*((160, 120) if quick else (640, 480)))
    work["ray tracing"] = (f"BVH.intersect, {len(o) // 1000}k primary rays",
                           lambda: tree.intersect(o, d))
    return work


def frames_workloads(quick):
    """``(render, selection)``: the animated scene and the frames to render."""
    from animation import scene_data

    from scanline.scene import AnimatedScene

    scene = AnimatedScene(scene_data(np.random.default_rng(1), segments=240))
    return sl.animation.Animation(scene, fps=scene.fps), (0, 40 if quick else 100)


def main():
    import numba

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="smaller workloads, one repeat")
    parser.add_argument("--only", nargs="+", help="these workloads (names or 'frames')")
    parser.add_argument("--repeats", type=int, default=None)
    args = parser.parse_args()
    repeats = args.repeats or (1 if args.quick else 3)
    rounds = max(repeats, 3) if args.quick else 5 * repeats    # the counts in turn
    cores = os.cpu_count() or 1
    steps = counts(cores)
    report = Report("scaling", quick=args.quick)
    print(f"  {cores} cores ({machine()}), counts {steps}, load {os.getloadavg()[0]:.2f}",
          flush=True)
    table = {}                                  # name -> (call, {count: seconds})

    def wanted(name):
        return not args.only or any(name.startswith(o) for o in args.only)

    everything = numba.get_num_threads()
    for name, (call, run) in threaded(args.quick).items():
        if not wanted(name):
            continue

        def at(n, run=run):
            def on_n_threads():
                numba.set_num_threads(min(n, everything))
                try:
                    run()
                finally:
                    numba.set_num_threads(everything)
            return on_n_threads
        report.alternate(name, [(threads(n), f"{call}, {threads(n)}", at(n), n)
                                for n in steps], rounds)
        table[name] = (call, {n: report.median(name, threads(n)) for n in steps},
                       {n: report.ratio(name, threads(steps[0]), threads(n)) for n in steps})

    if wanted("frames"):
        from distributed import Client, LocalCluster

        anim, selection = frames_workloads(args.quick)
        repeats = 1                         # a render of 100 frames takes seconds
        name, times = "frames jobs=N", {}
        for n in steps:
            times[n] = report.add(name, "scanline", f"Animation.images(jobs={n})",
                                  lambda n=n: list(anim.images(selection, jobs=n,
                                                               progress=False)),
                                  repeats=repeats, n=n)
        table[name] = (f"{selection[1]} frames 640x480, 240 segments", times, None)
        import dask

        for name, settings in (("frames Dask N", {}),
                               ("frames Dask N, quiet workers", sl.animation.QUIET_WORKERS)):
            times = {}
            # (a worker's event-loop tick and profiler wake while the frame runs: about
            # a fifth of a frame with the defaults; docs/animation.md)
            with dask.config.set(settings):
                for n in steps:
                    with LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                      dashboard_address=None) as cluster, \
                            Client(cluster) as client:
                        times[n] = report.add(name, "scanline", f"LocalCluster({n} workers)",
                                              lambda: list(anim.images(selection, client=client,
                                                                       progress=False)),
                                              repeats=repeats, n=n)
            table[name] = (f"{selection[1]} frames, a LocalCluster of N 1-thread workers"
                           + (", started under sl.animation.QUIET_WORKERS" if settings else ""),
                           times, None)

    markdown = render_table(table, steps, cores)
    print(markdown)
    path = report.write()
    with open(path[:-len(".json")] + ".md", "w") as f:
        f.write(markdown)


def render_table(table, steps, cores):
    """The Markdown table: a row per workload, the time and speed-up at each count."""
    head = (f"Scaling on {cores} cores ({machine()}), load average "
            f"{os.getloadavg()[0]:.2f} at the end; seconds (speed-up over 1; threaded "
            f"workloads: medians of the counts timed in turn)\n\n")
    lines = ["| workload | what | " + " | ".join(f"{n}" for n in steps) + " |",
             "|---|---|" + "---:|" * len(steps)]
    for name, (call, times, speedups) in table.items():
        one = times[steps[0]]
        cells = [f"{times[n]:.3f} ({(speedups[n] if speedups else one / times[n]):.2f}x)"
                 for n in steps]
        lines.append(f"| {name} | {call} | " + " | ".join(cells) + " |")
    return head + "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
