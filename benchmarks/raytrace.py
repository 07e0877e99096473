"""Ray tracing: primary rays against a 100k-triangle mesh, scanline's BVH against
Embree and trimesh's numpy engine, in one run.

Workload (fixed): a torus of 250 x 200 quads (100,000 triangles, 2 x 250 x 200) seen
by a pinhole camera; one ray per pixel of a 640 x 480 image (307,200 rays, about
60% hitting the mesh), the nearest hit of each.

* scanline: ``sl.raytrace.BVH(triangles)`` (binned SAH, compiled) and
  ``tree.intersect(origins, directions)`` (iterative traversal, Moller-Trumbore).
* Embree (``embreex``) through trimesh's ray interface:
  ``trimesh.ray.ray_pyembree.RayMeshIntersector(mesh).intersects_first(o, d)``
  (float32, rays made unit vectors by trimesh); the build is the creation of its
  Embree scene.  embreex casts the rays one after another in one thread
  (``rtcIntersect1`` in a loop); Embree's scene build may use every core (its own
  thread pool, which embreex does not let us limit): the build times are reported
  side by side, not as a target.
* trimesh's pure-numpy engine: ``trimesh.ray.ray_triangle.RayMeshIntersector(mesh)
  .intersects_first(o, d)`` (an R-tree of the triangles' boxes, then vectorized
  plane tests): on 2,000 of the rays, 100 a call (it is slow, and its candidate
  lists take gigabytes for thousands of rays at once), compared per ray.

Thread counts: the ray casts are compared on ONE thread (numba's threads set to 1,
Embree's ray loop is single-threaded); scanline on all cores is reported beside it.
The rays' nearest triangles are checked to agree with Embree's (float32) for >= 99%
of the rays.  Ratios are rays per second of scanline / of the peer (targets: >= 0.3
x Embree, >= 10 x trimesh's numpy engine).

Also timed, without a peer: ``scanline render --example glass_spheres`` (480 x 320,
mirror, glass and glossy spheres, an area light of 16 shadow rays) on one thread and
on all.

Run: ``python benchmarks/raytrace.py [--quick]`` (``--quick``: a 160 x 120 image).
"""

import argparse
import math
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402


#: Rays per call of trimesh's numpy engine.
BATCH = 100


def torus_triangles():
    """The 100,000 triangles of the workload and the trimesh mesh of them."""
    import trimesh

    m = sl.mesh.torus(2.0, 0.7, resolution=(250, 200)).triangulated()
    return m.vertices[m.faces], trimesh.Trimesh(m.vertices, m.faces, process=False)


def camera_rays(width, height):
    """One ray per pixel center of a pinhole camera at (0, 3.5, 5) looking at the
    origin, 50 degrees of vertical field: origins and unit directions, (N, 3)."""
    eye = np.array([0.0, 3.5, 5.0])
    forward = -eye / np.linalg.norm(eye)
    right = np.cross(forward, [0.0, 1.0, 0.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    half = math.tan(math.radians(25))
    xs = (np.arange(width) + 0.5) / width * 2 - 1
    ys = (np.arange(height) + 0.5) / height * 2 - 1
    gx, gy = np.meshgrid(xs * half * width / height, ys * half)
    d = forward + gx.reshape(-1, 1) * right + gy.reshape(-1, 1) * up
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    return np.ascontiguousarray(np.broadcast_to(eye, d.shape)), np.ascontiguousarray(d)


def main():
    import numba
    import trimesh.ray.ray_pyembree as embree
    import trimesh.ray.ray_triangle as numpy_engine

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="a 160 x 120 image")
    args = parser.parse_args()
    report = Report("raytrace", quick=args.quick)
    width, height = (160, 120) if args.quick else (640, 480)
    tri, mesh = torus_triangles()
    o, d = camera_rays(width, height)
    n = len(o)
    print(f"  {len(tri):,} triangles, {n:,} rays, {os.cpu_count()} cores", flush=True)

    # the builds
    report.add("BVH build", "scanline", "sl.raytrace.BVH(triangles)",
               lambda: sl.raytrace.BVH(tri), repeats=3, n=len(tri))
    report.add("BVH build", "embree", "RayMeshIntersector(mesh)._scene (all cores)",
               lambda: embree.RayMeshIntersector(mesh)._scene, repeats=3, n=len(tri))

    tree = sl.raytrace.BVH(tri)
    intersector = embree.RayMeshIntersector(mesh)
    intersector._scene                                          # built before the timing
    work = f"primary rays, {len(tri) // 1000}k triangles"
    all_cores = numba.get_num_threads()
    numba.set_num_threads(1)
    try:
        report.add(work, "scanline", "tree.intersect(o, d), 1 thread",
                   lambda: tree.intersect(o, d), repeats=3, n=n)
    finally:
        numba.set_num_threads(all_cores)
    report.add(work, "embree", "RayMeshIntersector.intersects_first(o, d), 1 thread",
               lambda: intersector.intersects_first(o, d), repeats=3, n=n)
    report.add(work + f" ({all_cores} threads)", "scanline",
               f"tree.intersect(o, d), {all_cores} threads", lambda: tree.intersect(o, d),
               repeats=3, n=n)

    ours = tree.intersect(o, d).triangle
    theirs = intersector.intersects_first(o, d)
    agree = float(np.mean(ours == theirs))
    print(f"  nearest triangle agrees with Embree's on {100 * agree:.3f}% of the rays "
          f"({int((ours >= 0).sum()):,} hits)", flush=True)
    assert agree >= 0.99, agree

    # trimesh's numpy engine on a subset, in batches (its candidate lists, every
    # triangle whose box meets a ray's box, take gigabytes for thousands of rays)
    k = min(n, 2_000)
    pick = np.random.default_rng(0).choice(n, k, replace=False)
    slow = numpy_engine.RayMeshIntersector(mesh)
    slow.intersects_first(o[:10], d[:10])                       # its R-tree, built once
    sub = f"primary rays, {len(tri) // 1000}k triangles, {k:,} of them"
    numba.set_num_threads(1)
    try:
        report.add(sub, "scanline", "tree.intersect(o, d), 1 thread",
                   lambda: tree.intersect(o[pick], d[pick]), repeats=3, n=k)
    finally:
        numba.set_num_threads(all_cores)

    def batches():
        return np.concatenate([slow.intersects_first(o[pick[i:i + BATCH]], d[pick[i:i + BATCH]])
                               for i in range(0, k, BATCH)])
    report.add(sub, "trimesh-numpy", f"ray_triangle.RayMeshIntersector.intersects_first, "
               f"{BATCH} rays a call", batches, repeats=1, n=k)
    mine = tree.intersect(o[pick], d[pick]).triangle
    numpy_hits = batches()
    print(f"  nearest triangle agrees with trimesh-numpy's on "
          f"{100 * float(np.mean(mine == numpy_hits)):.3f}% of the rays", flush=True)

    # a whole ray-traced picture (no peer): the example scene, on 1 and all threads
    scene = sl.scene.load(os.path.join(os.path.dirname(sl.__file__), "data", "scenes",
                                       "glass_spheres.toml"))
    pixels = scene.canvas.width * scene.canvas.height
    for threads in sorted({1, all_cores}):
        numba.set_num_threads(threads)
        try:
            report.add(f"glass_spheres {scene.canvas.width} x {scene.canvas.height}",
                       f"scanline-{threads}t", f"sl.render(method='ray-tracing'), {threads} "
                       "thread(s)", scene.raster, repeats=2, n=pixels)
        finally:
            numba.set_num_threads(all_cores)

    for row in report.rows:
        row["rays_per_s"] = (row["n"] / row["best_s"] if row["workload"].startswith("primary")
                             else None)
    report.target(work, "embree", 0.3, ">= 0.3x Embree's rays per second, one thread each")
    report.target(sub, "trimesh-numpy", 10.0, ">= 10x trimesh's numpy engine")
    for row in report.rows:
        if row["rays_per_s"]:
            print(f"  {row['library']:<14} {row['rays_per_s'] / 1e6:8.3f} Mrays/s  "
                  f"{row['workload']}", flush=True)
    report.write()


if __name__ == "__main__":
    t0 = time.perf_counter()
    main()
    print(f"  ({time.perf_counter() - t0:.1f} s in all)")
