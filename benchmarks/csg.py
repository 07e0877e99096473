"""Constructive solid geometry: ray casting CSG trees at 640 x 480 and their volume
by ray casting, beside trimesh's boolean operations (the manifold3d engine) on the
same solids tessellated, in one run.

Solids:

* ``classic``: (box & sphere) - (three cylinders along the axes), H&B 10-16's example;
* ``lens``: two unit spheres whose centers are 1 apart, intersected;
* ``sphere - corner``: a unit sphere less the box [0, 2]^3 (one octant).

Workloads:

* ``render <solid> 640x480``: scanline ``sl.render(fb, tree, cam,
  method="ray-casting", shading="none")`` (every pixel's ray against the exact
  primitives, Roth's interval rules); peer ``manifold+z-buffer``: trimesh's boolean
  (manifold3d) of the tessellated operands (icospheres of 5 subdivisions, 10,242
  vertices; cylinders of 128 sections), then scanline's z-buffer of the mesh it makes
  (``shading="none"``).  Ratio: peer time / scanline time.
* ``volume <solid>``: scanline ``sl.csg.volume(tree, resolution=256)`` (65,536 rays);
  peer ``manifold``: the boolean of the tessellated operands and the volume of the
  mesh it makes.  Both values and the exact volume (where closed-form) are printed.
* ``two blobs, marching cubes 128^3``: scanline ``sl.mesh.blobby`` of two merging
  blobs (the density on the grid, then scikit-image's marching cubes); peer: the union
  of two icospheres by manifold3d, a surface of the same size.

Best of 3 after a first call (which compiles scanline's kernels or loads them from
numba's cache; manifold3d is compiled C++).  Run under ``flock /tmp/bench.lock python
benchmarks/csg.py``.
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402

S = sl.solids


def solids():
    """{name: (CSG tree, exact volume or None)}."""
    cylinders = [S.Cylinder((0, 0, 0), 0.55, 3.2, axis=a) for a in ((1, 0, 0), (0, 1, 0),
                                                                   (0, 0, 1))]
    return {
        "classic": ((S.Box() & S.Sphere(radius=1.35)) - sl.csg.union(*cylinders), None),
        "lens": (S.Sphere() & S.Sphere((1, 0, 0)), math.pi * 5 / 12),
        "sphere - corner": (S.Sphere() - S.Box((0, 0, 0), (2, 2, 2)), 7 / 8 * 4 / 3 * math.pi),
    }


def tessellated(solid):
    """The same solid as a trimesh mesh, the booleans made by manifold3d."""
    import trimesh

    if isinstance(solid, S.Sphere):
        m = trimesh.creation.icosphere(subdivisions=5)
        m.apply_transform(solid.matrix)
        return m
    if isinstance(solid, S.Box):
        return trimesh.creation.box(bounds=[solid.lo, solid.hi])
    if isinstance(solid, S.Cylinder):
        m = trimesh.creation.cylinder(radius=1.0, height=2.0, sections=128)
        m.apply_transform(solid.matrix)
        return m
    op = {"union": trimesh.boolean.union, "intersection": trimesh.boolean.intersection,
          "difference": trimesh.boolean.difference}[solid.op]
    return op([tessellated(solid.left), tessellated(solid.right)], engine="manifold")


def main():
    import manifold3d
    import trimesh

    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    report = Report("csg", quick=args.quick)
    print(f"  cores: {os.cpu_count()}; trimesh {trimesh.__version__}, manifold3d "
          f"{getattr(manifold3d, '__version__', '?')}", flush=True)
    size = (160, 120) if args.quick else (640, 480)
    cam = sl.Camera(eye=(3.2, 2.6, 4.2), target=(0, 0, 0),
                    projection=sl.projection.perspective(fov=math.radians(34), near=0.5))
    fb = sl.FrameBuffer(*size)
    for name, (tree, exact) in solids().items():
        work = f"render {name} {size[0]}x{size[1]}"
        report.add(work, "scanline", "sl.render(tree, method='ray-casting')",
                   lambda: sl.render(fb, tree, cam, method="ray-casting", shading="none"))

        def peer():
            mesh = tessellated(tree)
            sl.render(fb, sl.mesh.Mesh(mesh.vertices, mesh.faces), cam, shading="none")
        report.add(work, "manifold+z-buffer", "trimesh.boolean(engine='manifold') + "
                   "sl.render(method='z-buffer')", peer)
        report.target(work, "manifold+z-buffer", 0.0, "reported beside, no target")
        work = f"volume {name}"
        ours = sl.csg.volume(tree, resolution=256)
        theirs = tessellated(tree).volume
        print(f"  {name}: volume by ray casting {ours:.5f}, manifold {theirs:.5f}, exact "
              f"{'-' if exact is None else f'{exact:.5f}'}", flush=True)
        report.add(work, "scanline", "sl.csg.volume(tree, resolution=256)",
                   lambda: sl.csg.volume(tree, resolution=256))
        report.add(work, "manifold", "trimesh.boolean(engine='manifold').volume",
                   lambda: tessellated(tree).volume)
        report.target(work, "manifold", 0.0, "reported beside, no target")
    # blobby objects (H&B 10-7) are meshed by marching cubes: two blobs merging, beside
    # the union of two spheres where they meet by manifold3d (a surface of the same size)
    res = 32 if args.quick else 128
    work = f"two blobs, marching cubes {res}^3"
    centers = [(-0.6, 0.0, 0.0), (0.6, 0.0, 0.0)]
    report.add(work, "scanline", f"sl.mesh.blobby(two centers, resolution={res})",
               lambda: sl.mesh.blobby(centers, 1.0, resolution=res))

    def spheres():
        balls = []
        for c in centers:
            m = trimesh.creation.icosphere(subdivisions=5, radius=1.0)
            m.apply_translation(c)
            balls.append(m)
        return trimesh.boolean.union(balls, engine="manifold")
    report.add(work, "manifold", "trimesh.boolean.union of two icospheres (manifold)", spheres)
    report.target(work, "manifold", 0.0, "reported beside, no target")
    report.write()


if __name__ == "__main__":
    main()
