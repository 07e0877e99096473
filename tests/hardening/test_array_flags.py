"""Read-only, strided, negative-stride and Fortran-ordered input arrays reach the
kernels normalized (C-contiguous, writable, one dtype by role), so they never
compile a second specialization (issue 11, item 3: the first
``sl.draw.antialias.lines(fb, read_only)`` cost 67 s)."""

import json
import subprocess
import sys

#: Run in a fresh process: every entry point with every array flavour, then the
#: signatures of every kernel that saw a non-C-contiguous or read-only array.
SCRIPT = r"""
import importlib, json, pkgutil
import numpy as np
from numba.core import types
from numba.core.dispatcher import Dispatcher
import scanline as sl
import scanline._kernels as package

def flavours(a):
    a = np.asarray(a)
    ro = a.copy(); ro.flags.writeable = False
    wide = np.repeat(a, 2, axis=0)[::2]                 # strided rows
    rev = a[::-1].copy()[::-1]                           # negative stride
    fort = np.asfortranarray(a)
    if a.dtype.kind in "iu":
        return [ro, wide, rev, fort, a.astype(np.int32), a.astype(np.uint16)]
    return [ro, wide, rev, fort, a.astype(np.int32), a.astype(np.float32)]

seg = np.array([[1.0, 2.0, 30.0, 20.0], [5.0, 25.0, 35.0, 3.0]])
tri = np.array([[2.0, 2.0], [30.0, 5.0], [12.0, 25.0], [3.0, 20.0]])
seg3 = np.array([[-0.5, -0.5, -0.5, 0.5, 0.4, 0.3], [0.1, 0.2, -2.0, 0.3, 0.1, 2.0]])
cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0), projection=sl.projection.perspective(fov=1.0, aspect=4 / 3, near=0.5, far=20))
cube = sl.mesh.cube()
calls = []
for kind in ("RGB", "L", "1"):
    fb = sl.FrameBuffer(40, 30, mode=kind)
    for s in flavours(seg):
        calls += [lambda s=s: sl.draw.lines(fb, s), lambda s=s: sl.draw.antialias.lines(fb, s),
                  lambda s=s: sl.draw.lines(fb, s, width=3)]
    for p in flavours(tri):
        calls += [lambda p=p: sl.draw.polygon(fb, p), lambda p=p: sl.draw.polygon(fb, p, antialias=True),
                  lambda p=p: sl.draw.polyline(fb, p), lambda p=p: sl.draw.polyline(fb, p, width=4),
                  lambda p=p: sl.draw.polyline(fb, p, antialias=True),
                  lambda p=p: sl.draw.antialias.fills_flat(fb, p, np.array([0, 4]), np.array([0, 1])),
                  lambda p=p: sl.draw.polygons(fb, p, counts=np.array([4], np.int32))]
    for o in flavours(np.array([0, 4])):
        calls += [lambda o=o: sl.draw.antialias.fills_flat(fb, tri, o, np.array([0, 1]))]
    for s in flavours(seg3):
        calls += [lambda s=s: sl.draw3d.lines(fb, s, cam)]
    calls += [lambda: sl.draw3d.wireframe(fb, cube, cam)]
for s in flavours(seg):
    calls += [lambda s=s: sl.clip.lines(s, (0, 0, 20, 20)), lambda s=s: sl.clip.lines(s, (0, 0, 20, 20), method="cohen-sutherland")]
for p in flavours(tri):
    calls += [lambda p=p: sl.clip.polygon(p, (0, 0, 20, 20)), lambda p=p: sl.clip.polygons(p, (0, 0, 20, 20), counts=[4])]
for s in flavours(seg3):
    calls += [lambda s=s: sl.clip.lines3d(s, sl.clip.box((-1, -1, -1), (1, 1, 1)))]
for c in calls:
    c()
bad = {}
for info in pkgutil.iter_modules(package.__path__):
    module = importlib.import_module(f"{package.__name__}.{info.name}")
    for name, obj in vars(module).items():
        if isinstance(obj, Dispatcher) and obj.py_func.__module__ == module.__name__:
            for sig in obj.signatures:
                for t in sig:
                    if isinstance(t, types.Array) and (t.layout != "C" or not t.mutable
                                                         or t.dtype in (types.int32, types.float32)):
                        bad.setdefault(f"{info.name}.{name}", []).append(str(sig))
print(json.dumps(bad))
"""


def test_array_flavours_reach_kernels_normalized():
    out = subprocess.run([sys.executable, "-c", SCRIPT], capture_output=True, text=True,
                         timeout=900, env={**__import__("os").environ, "SCANLINE_COMPILE": "always"})
    assert out.returncode == 0, out.stderr[-3000:]
    bad = json.loads(out.stdout.strip().splitlines()[-1])
    assert bad == {}
