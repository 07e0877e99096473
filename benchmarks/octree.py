"""Octrees: voxelizing a closed mesh at depth 7 (128 voxels a side) against trimesh's
voxelization, and the octree visible-surface method against the z-buffer at 640 x 480
on the same cubes, in one run.

Workloads:

* ``voxelize``: an icosphere subdivided 5 times (20,480 triangles) and a torus
  (trimesh.creation.torus, 4,096 triangles), each made solid at 128 voxels a side.
  scanline: ``sl.octree.Octree.from_mesh(mesh, 7)`` (column ray parity, then the
  bottom-up merge into an octree); trimesh: ``mesh.voxelized(pitch).fill()`` (its
  default surface voxelization by subdivision, then the inside filled), with the pitch
  of the same grid.  The two inside sets are compared before timing (they differ only
  at voxels the surface passes through: trimesh marks every voxel the surface meets,
  scanline those whose centers are inside).
* ``render``: the boundary cubes of the octree (depth 6) of a CSG solid (a sphere less
  a box and a cylinder) drawn into 640 x 480 by ``method="octree"`` and by
  ``method="z-buffer"`` (``shading="none"``, the same pixels); and a mesh scene of the
  icosphere.  Ratio: z-buffer time / octree time.

Best of 3 after a first call (which compiles scanline's kernels or loads them from
numba's cache).  Run under ``flock /tmp/bench.lock python benchmarks/octree.py``.
"""

import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402


def voxelize(report, name, tm, depth):
    import trimesh

    mesh = sl.mesh.Mesh(tm.vertices, tm.faces)
    n = 1 << depth
    tree = sl.octree.Octree.from_mesh(mesh, depth)
    pitch = tree.side / n
    theirs = tm.voxelized(pitch).fill()
    mine = tree.to_voxels()
    print(f"  {name}: scanline {mine.sum()} voxels inside, trimesh {theirs.filled_count} "
          f"(surface voxels included)", flush=True)
    work = f"voxelize {name} {n}^3"
    report.add(work, "scanline", "Octree.from_mesh", lambda: sl.octree.Octree.from_mesh(
        mesh, depth), n=len(tm.faces))
    report.add(work, "trimesh", f"voxelized(pitch).fill() {trimesh.__version__}",
               lambda: tm.voxelized(pitch).fill(), n=len(tm.faces))
    report.target(work, "trimesh", 1.0, ">= 1.0: no slower than trimesh")


def render(report, name, scene, cam):
    work = f"render {name} 640x480"
    fb = sl.FrameBuffer(640, 480)
    for method in ("octree", "z-buffer"):
        report.add(work, "scanline" if method == "octree" else "z-buffer",
                   f"sl.render(method={method!r})",
                   lambda: sl.render(fb, scene, cam, method=method, shading="none"))
    report.target(work, "z-buffer", 0.5, ">= 0.5: within twice the z-buffer's time")


def main():
    import trimesh

    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    report = Report("octree", quick=args.quick)
    print(f"  cores: {os.cpu_count()}", flush=True)
    depth = 5 if args.quick else 7
    sphere = trimesh.creation.icosphere(subdivisions=5)
    voxelize(report, "icosphere", sphere, depth)
    voxelize(report, "torus", trimesh.creation.torus(1.0, 0.35), depth)
    solid = sl.csg.difference(sl.solids.Sphere(radius=1.0),
                              sl.solids.Box((0.0, 0.0, 0.0), (1.1, 1.1, 1.1)),
                              sl.solids.Cylinder(radius=0.35, height=2.2))
    tree = sl.octree.Octree.from_solid(solid, depth - 1)
    print(f"  CSG octree: {tree.node_count} nodes, {len(tree.faces)} boundary faces",
          flush=True)
    cam = sl.Camera(eye=(3.2, 2.4, 2.6), target=(0, 0, 0), up=(0, 0, 1),
                    projection=sl.projection.perspective(fov=math.radians(40), near=0.5))
    render(report, "CSG octree cubes", tree, cam)
    render(report, "icosphere 20k", sl.mesh.Mesh(sphere.vertices, sphere.faces), cam)
    report.write()


if __name__ == "__main__":
    main()
