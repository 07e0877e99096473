"""Mesh files: ``sl.mesh.load`` against ``trimesh.load`` on the same 1M-triangle files
in one run.

Workloads (made in a temporary folder, not timed): an icosphere subdivided 8 times
(1,310,720 triangles, 655,362 vertices) written by trimesh as

* ``obj v//vn``: OBJ with vertex normals (``f a//a b//b c//c``, 8 decimals), as
  trimesh exports it;
* ``obj v/vt/vn``: OBJ as Blender writes it -- one normal per face and uv per
  vertex, so that every corner's (v, vt, vn) triple must be split into mesh vertices
  (3.9 M corners, 3.9 M vertices);
* ``glb``: binary glTF, as trimesh exports it.

scanline: ``sl.mesh.load(path)`` (the file read, tokenized by the compiled kernels
or its accessors read, the Mesh built and checked); trimesh: ``trimesh.load(path)``
with its defaults.  Best of 3 after a first call (which compiles scanline's kernels
or loads them from numba's cache).  Ratios are trimesh time / scanline time (above
1: scanline is faster); target >= 1.

Run: ``python benchmarks/meshes.py [--quick]`` (``--quick``: 6 subdivisions, 82k
triangles).
"""

import argparse
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402


def blender_style_obj(mesh, path):
    """OBJ text with per-vertex uv and one normal per face (``f v/vt/vn``)."""
    normals = np.asarray(mesh.face_normals)
    uv = np.asarray(mesh.vertices)[:, :2] * 0.5 + 0.5
    faces = np.asarray(mesh.faces) + 1
    which = np.repeat(np.arange(1, len(faces) + 1), 3).reshape(-1, 3)
    corners = np.stack([faces, faces, which], axis=2).reshape(len(faces), 9)
    with open(path, "w") as f:
        np.savetxt(f, mesh.vertices, fmt="v %.8f %.8f %.8f")
        np.savetxt(f, uv, fmt="vt %.8f %.8f")
        np.savetxt(f, normals, fmt="vn %.8f %.8f %.8f")
        np.savetxt(f, corners, fmt="f %d/%d/%d %d/%d/%d %d/%d/%d")


def main():
    import trimesh

    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    report = Report("meshes", quick=args.quick)
    print(f"  cores: {os.cpu_count()}", flush=True)
    sphere = trimesh.creation.icosphere(subdivisions=6 if args.quick else 8)
    triangles = len(sphere.faces)
    with tempfile.TemporaryDirectory(prefix="scanline-meshes-") as folder:
        files = {"obj v//vn": os.path.join(folder, "sphere.obj"),
                 "obj v/vt/vn": os.path.join(folder, "blender.obj"),
                 "glb": os.path.join(folder, "sphere.glb")}
        with open(files["obj v//vn"], "w") as f:
            f.write(trimesh.exchange.obj.export_obj(sphere, include_normals=True))
        blender_style_obj(sphere, files["obj v/vt/vn"])
        with open(files["glb"], "wb") as f:
            f.write(sphere.export(file_type="glb"))
        for kind, path in files.items():
            size = os.path.getsize(path)
            work = f"{triangles // 1000}k triangles {kind}"
            mesh = sl.mesh.load(path)
            theirs = trimesh.load(path)
            theirs = theirs.to_mesh() if isinstance(theirs, trimesh.Scene) else theirs
            assert mesh.triangulated().face_count == len(theirs.faces) == triangles
            report.add(work, "scanline", f"sl.mesh.load ({size / 1e6:.0f} MB)",
                       lambda: sl.mesh.load(path), n=triangles)
            report.add(work, "trimesh", f"trimesh.load {trimesh.__version__}",
                       lambda: trimesh.load(path), n=triangles)
            report.target(work, "trimesh", 1.0, ">= 1.0: no slower than trimesh.load")
    report.write()


if __name__ == "__main__":
    main()
