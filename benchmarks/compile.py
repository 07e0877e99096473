"""The compile-time budget: the first call of every public entry point that reaches a
numba kernel, each in a fresh process with an empty numba cache.

A new user's first call pays numba's compilation of every kernel it reaches; the
kernel layer's rule (``docs/conventions.md``, "Compile time") keeps that within about
3 s per entry point on a 2-core machine.  This script measures it: for every *case*
(one entry point, in one image mode where the mode matters) it starts a fresh
Python process with ``NUMBA_CACHE_DIR`` pointing at a new, empty folder, runs the
case and saves the result, and records

- ``seconds``: from the start of the process to the result written (interpreter
  start, ``import scanline``, the call, the PNG);
- ``specializations``: the compiled specializations the case left in the cache
  (one ``.nbc`` file per specialization of a kernel), and which kernels they are;
- ``slowest``: the kernels whose own compilation took longest (numba's compile
  events).

Command-line cases (``scanline trace ...``, ``scanline render ...``, ``scanline
demo``) are timed as whole commands.  Nothing here is asserted: the targets are
checked by reading the table (and the README shows it).

    python benchmarks/compile.py                  # every case (about 10 minutes)
    python benchmarks/compile.py --only aa        # cases whose name contains "aa"
    python benchmarks/compile.py --list           # the case names
    python benchmarks/compile.py --demo           # also scanline demo, cold and warm

Writes ``benchmarks/results/compile.json`` (a full run) or
``results/compile-partial.json`` (``--only``).
"""

import argparse
import datetime as _dt
import json
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
MODES = ("1", "L", "RGB", "RGBA", "P")

#: Python cases: name -> (code, modes).  The code runs with ``sl``, ``np`` and a
#: 96 x 64 frame buffer ``fb`` (white background, in each mode listed) defined;
#: ``None`` as modes: the case draws nothing into ``fb`` (RGB is used).
TRI = "[(3, 4), (80, 20), (30, 60)]"
STAR = "[(48, 60), (20, 4), (92, 40), (4, 40), (76, 4)]"
PY_CASES = {
    "line": ("sl.draw.line(fb, 3, 4, 90, 50, color='black')", MODES),
    "line dda": ("sl.draw.line(fb, 3, 4, 90, 50, color='black', method='dda')", ("RGB",)),
    "lines": ("sl.draw.lines(fb, np.array([[3, 4, 90, 50], [0, 60, 95, 0]]), color='black')", MODES),
    "line aa": ("sl.draw.line(fb, 3.5, 4, 90, 50.2, color='black', antialias=True)", MODES),
    "lines aa": ("sl.draw.lines(fb, [[3, 4, 90, 50], [0, 60, 95, 0]], color='black', antialias=True)",
                 MODES),
    "line translucent": ("sl.draw.line(fb, 3, 4, 90, 50, color=(255, 0, 0, 128))", ("RGB", "RGBA")),
    "circle": ("sl.draw.circle(fb, 48, 32, 20, color='black')", MODES),
    "circles": ("sl.draw.circles(fb, [[48, 32, 20], [20, 20, 9]], color='black')", MODES),
    "circle aa": ("sl.draw.circle(fb, 48, 32, 20.5, color='black', antialias=True)", MODES),
    "ellipse": ("sl.draw.ellipse(fb, 48, 32, 30, 12, color='black')", MODES),
    "ellipses": ("sl.draw.ellipses(fb, [[48, 32, 30, 12], [20, 20, 9, 4]], color='black')", ("RGB",)),
    "ellipse aa": ("sl.draw.ellipse(fb, 48, 32, 30, 12.5, color='black', antialias=True)", ("RGB",)),
    "circle thick": ("sl.draw.circle(fb, 48, 32, 20, color='black', width=4)", ("RGB",)),
    "circle dashed": ("sl.draw.circle(fb, 48, 32, 20, color='black', dash=(4, 2))", ("RGB",)),
    "polygon": (f"sl.draw.polygon(fb, {STAR}, color='black')", MODES),
    "polygon nonzero": (f"sl.draw.polygon(fb, {STAR}, color='black', rule='nonzero')", ("RGB",)),
    "polygons": (f"sl.draw.polygons(fb, [{STAR}, {TRI}], color='black')", ("RGB",)),
    "polygon aa": (f"sl.draw.polygon(fb, {STAR}, color='black', antialias=True)", MODES),
    "polygons aa": (f"sl.draw.polygons(fb, [{STAR}, {TRI}], color='black', antialias=True)", ("RGB",)),
    "polygon hatch": (f"sl.draw.polygon(fb, {STAR}, color='black', "
                      "style=sl.FillStyle.hatch(angle=0.8, spacing=6, cross=True))", ("RGB",)),
    "polygon translucent": (f"sl.draw.polygon(fb, {STAR}, color=(255, 0, 0, 128))", ("RGB", "RGBA")),
    "fill_circle": ("sl.draw.fill_circle(fb, 48, 32, 20, color='black')", MODES),
    "fill_circles": ("sl.draw.fill_circles(fb, [[48, 32, 20], [20, 20, 9]], color='black')", ("RGB",)),
    "fill_circle aa": ("sl.draw.fill_circle(fb, 48, 32, 20.5, color='black', antialias=True)", MODES),
    "fill_ellipse": ("sl.draw.fill_ellipse(fb, 48, 32, 30, 12, color='black')", ("RGB",)),
    "fill_ellipses aa": ("sl.draw.fill_ellipses(fb, [[48, 32, 30, 12]], color='black', antialias=True)",
                         ("RGB",)),
    "arc": ("sl.draw.arc(fb, 48, 32, 30, 20, 0.2, 2.5, color='black')", ("RGB",)),
    "pie": ("sl.draw.pie(fb, 48, 32, 30, 20, 0.2, 2.5, color='black')", ("RGB",)),
    "chord": ("sl.draw.chord(fb, 48, 32, 30, 20, 0.2, 2.5, color='black')", ("RGB",)),
    "polyline": ("sl.draw.polyline(fb, [(3, 4), (50, 60), (90, 5)], color='black')", ("RGB",)),
    "polyline thick round": ("sl.draw.polyline(fb, [(3, 4), (50, 60), (90, 5)], color='black', "
                             "width=5, cap='round', join='round')", MODES),
    "polyline thick miter": ("sl.draw.polyline(fb, [(3, 4), (50, 60), (90, 5)], color='black', "
                             "width=5, join='miter')", ("RGB",)),
    "polyline dashed": ("sl.draw.polyline(fb, [(3, 4), (50, 60), (90, 5)], color='black', "
                        "dash=(6, 3))", ("RGB",)),
    "polyline dashed thick": ("sl.draw.polyline(fb, [(3, 4), (50, 60), (90, 5)], color='black', "
                              "dash=(6, 3), width=3)", ("RGB",)),
    "polyline mask": ("sl.draw.polyline(fb, [(3, 4), (50, 60), (90, 5)], color='black', "
                      "dash=0b1111000011110000)", ("RGB",)),
    "polyline pen": ("sl.draw.polyline(fb, [(3, 4), (50, 60), (90, 5)], color='black', "
                     "pen='circle', width=3)", ("RGB",)),
    "polyline thick aa": ("sl.draw.polyline(fb, [(3, 4), (50, 60), (90, 5)], color='black', "
                          "width=5, join='round', antialias=True)", MODES),
    "polylines": ("sl.draw.polylines(fb, [[(3, 4), (50, 60)], [(90, 5), (10, 50), (60, 10)]], "
                  "color='black', width=3)", ("RGB",)),
    "flood_fill": ("sl.draw.circle(fb, 48, 32, 20, color='black'); "
                   "sl.draw.flood_fill(fb, 48, 32, 'red')", MODES),
    "flood_fill 8": ("sl.draw.circle(fb, 48, 32, 20, color='black'); "
                     "sl.draw.flood_fill(fb, 48, 32, 'red', connectivity=8)", ("RGB",)),
    "boundary_fill": ("sl.draw.circle(fb, 48, 32, 20, color='black'); "
                      "sl.draw.boundary_fill(fb, 48, 32, 'red', boundary='black')", MODES),
    "soft_fill": ("sl.draw.fill_circle(fb, 48, 32, 20, color='black', antialias=True); "
                  "sl.draw.soft_fill(fb, 48, 32, 'red', 'black', 'white')", ("RGB",)),
    "text outline": ("sl.draw.text(fb, 4, 20, 'Hello', color='black', height=14)", MODES),
    "text outline aa": ("sl.draw.text(fb, 4, 20, 'Hello', color='black', height=14, antialias=True)",
                        ("RGB",)),
    "text outline rotated": ("sl.draw.text(fb, 4, 20, 'Hello', color='black', height=14, angle=0.3)",
                             ("RGB",)),
    "text bitmap": ("sl.draw.text(fb, 4, 20, 'Hello', color='black', font='bitmap')", ("RGB",)),
    "text stroke": ("sl.draw.text(fb, 4, 20, 'Hello', color='black', font='stroke', height=12)",
                    ("RGB",)),
    "curve bezier": ("sl.draw.curve(fb, sl.curves.Bezier([(5, 5), (30, 60), (60, 60), (90, 5)]), "
                     "color='black')", ("RGB",)),
    "curve bspline thick": ("sl.draw.curve(fb, sl.curves.BSpline([(5, 5), (20, 60), (50, 30), "
                            "(70, 60), (90, 5)], order=4), color='black', width=3)", ("RGB",)),
    "curve filled aa": ("sl.draw.curve(fb, sl.curves.nurbs_circle((48, 32), 20), color='black', "
                        "fill=True, antialias=True)", ("RGB",)),
    "dither floyd-steinberg": ("sl.color.dither(np.linspace(0, 255, 96 * 64).reshape(64, 96))",
                               None),
    "dither bayer": ("sl.color.dither(np.linspace(0, 255, 96 * 64).reshape(64, 96), 'bayer4', "
                     "levels=4)", None),
    "dither palette": ("sl.color.dither(np.random.default_rng(0).integers(0, 256, (64, 96, 3)), "
                       "palette=sl.color.web_safe_table())", None),
    "median_cut_table": ("sl.color.median_cut_table(np.random.default_rng(0).integers(0, 256, "
                         "(64, 96, 3)), 16)", None),
    "clip lines cohen-sutherland": ("sl.clip.lines(np.random.default_rng(1).uniform(-50, 150, "
                                    "(100, 4)), (0, 0, 100, 100), method='cohen-sutherland')", None),
    "clip lines liang-barsky": ("sl.clip.lines(np.random.default_rng(1).uniform(-50, 150, (100, 4)), "
                                "(0, 0, 100, 100), method='liang-barsky')", None),
    "clip line cyrus-beck": ("sl.clip.line(-5, 2, 15, 22, [(0, 0), (10, 0), (12, 8), (4, 12)], "
                             "method='cyrus-beck')", None),
    "clip polygon sutherland-hodgman": ("sl.clip.polygon([(0, 0), (10, 0), (10, 10), (5, 2), "
                                        "(0, 10)], (1, 1, 9, 6))", None),
    "clip polygon weiler-atherton": ("sl.clip.polygon([(0, 0), (10, 0), (10, 10), (5, 2), (0, 10)], "
                                     "(1, 1, 9, 6), method='weiler-atherton')", None),
    "clip polygons": ("sl.clip.polygons([[(0, 0), (10, 0), (10, 10)], [(2, 2), (12, 3), (5, 9)]], "
                      "(1, 1, 9, 6))", None),
    "clip ellipse": ("sl.clip.ellipse(5, 5, 8, 3, (0, 0, 10, 10))", None),
    "clip text": ("sl.clip.text(sl.text.layout('Hello', 0, 0, height=10), (0, 0, 20, 20))", None),
    "bezier evaluate": ("sl.curves.Bezier([(0, 0), (1, 3), (4, 3), (5, 0)]).evaluate("
                        "np.linspace(0, 1, 1000))", None),
    "bspline evaluate": ("sl.curves.BSpline([(0, 0), (1, 2), (3, 3), (4, 0), (6, 1)], order=4, "
                         "knots='open').evaluate(np.linspace(0, 1, 1000))", None),
    "curve flatten": ("sl.curves.BSpline([(0, 0), (1, 2), (3, 3), (4, 0), (6, 1)], order=4, "
                      "knots='open').flatten(0.01)", None),
    "surface tessellate": ("sl.curves.teapot_mesh(4)", None),
    "inside": (f"sl.geometry.inside([(32, 30), (5, 5)], {STAR}, rule='nonzero')", None),
    "camera project": ("sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)).project("
                       "np.random.default_rng(0).uniform(-1, 1, (100, 3)), 96, 64)", None),
    "clip lines3d liang-barsky": ("sl.clip.lines3d(np.random.default_rng(1).uniform(-5, 15, "
                                  "(100, 6)), ((0, 0, 0), (10, 10, 10)))", None),
    "clip lines3d cohen-sutherland": ("sl.clip.lines3d(np.random.default_rng(1).uniform(-5, 15, "
                                      "(100, 6)), ((0, 0, 0), (10, 10, 10)), "
                                      "method='cohen-sutherland')", None),
    "clip homogeneous": ("sl.clip.homogeneous([[(1, 1, 1, 2), (1, 1, -3, -2)]])", None),
    "clip polygon3d": ("sl.clip.polygon3d([(-1, 0.5, 0.5), (2, 0.5, 0.5), (0.5, 2, 0.5)], "
                       "((0, 0, 0), (1, 1, 1)))", None),
    "wireframe": ("sl.draw3d.wireframe(fb, sl.mesh.torus(1, 0.3), "
                  "sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)), color='black')", ("RGB",)),
    "wireframe depth cue": ("sl.draw3d.wireframe(fb, sl.mesh.sphere(), "
                            "sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)), color='black', "
                            "depth_cue=True)", ("RGB",)),
    "draw3d polylines thick": ("sl.draw3d.polylines(fb, [[(0, 0, 0), (1, 1, 0), (1, 0, 1)]], "
                               "sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)), color='black', "
                               "width=3)", ("RGB",)),
    "display file": ("df = sl.DisplayFile(); df.set_viewing(window=(0, 0, 100, 100), "
                     "viewport=(0, 0, 1, 1)); df.create_segment('house', priority=1); "
                     "df.polygon([(20, 10), (80, 10), (80, 60), (20, 60)], color='tan', "
                     "edge='brown', width=2); df.text((25, 30), 'HOME', height=8, color='black', "
                     "font='stroke'); df.close_segment(); df.draw(fb)", ("RGB",)),
    "context": ("ctx = sl.Context(fb); ctx.rotate(0.3, pivot=(48, 32)); "
                "ctx.set_line(color='red', width=3); ctx.rectangle(30, 20, 30, 20)", ("RGB",)),
    "four calls": ("sl.draw.line(fb, 3, 4, 90, 50, color='black'); "
                   f"sl.draw.polygon(fb, {STAR}, color='navy', rule='nonzero'); "
                   "sl.draw.text(fb, 4, 20, 'Hello', color='black', height=14); "
                   "sl.draw.circle(fb, 48, 32, 20.5, color='red', antialias=True)", ("RGB",)),
}

#: Command-line cases: name -> argument list (after ``scanline``).
SCENES = os.path.join(os.path.dirname(HERE), "src", "scanline", "data", "scenes")
CLI_CASES = {
    "trace bresenham": ["trace", "bresenham", "20", "10", "30", "18"],
    "trace dda": ["trace", "dda", "2", "3", "9", "7"],
    "trace midpoint-circle": ["trace", "midpoint-circle", "10"],
    "trace midpoint-ellipse": ["trace", "midpoint-ellipse", "8", "6"],
    "trace flood-fill": ["trace", "flood-fill", "1", "2"],
    "trace cohen-sutherland": ["trace", "cohen-sutherland", "-5", "2", "15", "22",
                               "--window", "0", "0", "10", "10"],
    "trace liang-barsky": ["trace", "liang-barsky", "-5", "2", "15", "22"],
    "trace cyrus-beck": ["trace", "cyrus-beck", "-5", "2", "15", "22",
                         "--window-polygon", "0,0,10,0,12,8,4,12"],
    "trace de-casteljau": ["trace", "de-casteljau", "0,0", "0,4", "4,4", "4,0", "--u", "0.5"],
    "trace cox-de-boor": ["trace", "cox-de-boor", "--knots", "0,0,0,0,1,2,2,2,2", "--order", "4",
                          "--u", "1.5"],
    "render rotation scene": ["render", os.path.join(SCENES, "rotation.toml"), "-o", "{out}/r.png"],
    "render clipping scene": ["render", os.path.join(SCENES, "polygon_clipping.toml"),
                              "-o", "{out}/c.png"],
    "trace cohen-sutherland-3d": ["trace", "cohen-sutherland-3d", "-5", "2", "5", "15", "22",
                                  "5"],
    "trace liang-barsky-3d": ["trace", "liang-barsky-3d", "0.5", "0.5", "1", "0.5", "0.5",
                              "-3", "--w", "2", "-2"],
    "render perspective scene": ["render", os.path.join(SCENES, "perspective.toml"), "-o",
                                 "{out}/p.png"],
    "draw command": ["draw", "--size", "64x48", "line", "2", "3", "60", "40", "circle", "32", "24",
                     "15", "-o", "{out}/d.png"],
}

#: Run inside the fresh process for a Python case: argv = [mode, code, out folder].
CHILD = r"""
import json, os, sys, time
T0 = time.perf_counter()
from numba.core import event as _event

class _Compiles(_event.Listener):
    def __init__(self):
        self.open = []
        self.done = []
    def on_start(self, event):
        self.open.append(time.perf_counter())
    def on_end(self, event):
        start = self.open.pop()
        if not self.open:     # top-level compilations only: nested ones are inside them
            disp = event.data.get("dispatcher")
            name = getattr(getattr(disp, "py_func", None), "__qualname__", str(disp))
            module = getattr(getattr(disp, "py_func", None), "__module__", "")
            self.done.append((time.perf_counter() - start, module.rsplit(".", 1)[-1] + "." + name))

_rec = _Compiles()
_event.register("numba:compile", _rec)
import numpy as np
import scanline as sl
mode, code, out = sys.argv[1], sys.argv[2], sys.argv[3]
fb = sl.FrameBuffer(96, 64, mode=mode, background="white")
exec(code)
fb.save(os.path.join(out, "out.png"))
seconds = time.perf_counter() - T0
print(json.dumps({"seconds": seconds,
                  "slowest": sorted(_rec.done, reverse=True)[:5]}))
"""


def specializations(cache_dir):
    """{kernel: number of compiled specializations} found in a numba cache folder
    (one ``.nbc`` file per specialization)."""
    counts = {}
    for _root, _dirs, files in os.walk(cache_dir):
        for f in files:
            if f.endswith(".nbc"):
                # "<module>.<function>-<line>.py311.<n>.nbc"
                kernel = f.rsplit("-", 1)[0]
                counts[kernel] = counts.get(kernel, 0) + 1
    return counts


def run_case(argv, env_extra, timeout=900):
    """Run one command in a fresh process with an empty numba cache; return its
    record (wall time, child's report, specializations)."""
    cache = tempfile.mkdtemp(prefix="scanline-numba-")
    out = tempfile.mkdtemp(prefix="scanline-out-")
    env = dict(os.environ, NUMBA_CACHE_DIR=cache, **env_extra)
    argv = [a.replace("{out}", out) for a in argv]
    t0 = time.perf_counter()
    proc = subprocess.run(argv, env=env, capture_output=True, text=True, timeout=timeout)
    wall = time.perf_counter() - t0
    record = {"wall_s": wall, "ok": proc.returncode == 0}
    if proc.returncode != 0:
        record["error"] = (proc.stderr.strip().splitlines() or ["?"])[-1]
    specs = specializations(cache)
    record["specializations"] = sum(specs.values())
    record["kernels"] = specs
    shutil.rmtree(cache, ignore_errors=True)
    shutil.rmtree(out, ignore_errors=True)
    return record, proc.stdout


def cases(selected):
    """Every case as (name, mode, argv), in table order."""
    for name, (code, modes) in PY_CASES.items():
        for mode in modes or ("RGB",):
            yield name, mode if modes else None, [sys.executable, "-c", CHILD, mode, code, "{out}"]
    scanline = [sys.executable, "-m", "scanline"]
    for name, args in CLI_CASES.items():
        yield name, None, scanline + args


def demo_rows():
    """``scanline demo`` cold (empty cache) and warm (the cache it filled)."""
    cache = tempfile.mkdtemp(prefix="scanline-numba-")
    out = tempfile.mkdtemp(prefix="scanline-demo-")
    env = dict(os.environ, NUMBA_CACHE_DIR=cache)
    rows = []
    for label in ("scanline demo (cold)", "scanline demo (warm)"):
        t0 = time.perf_counter()
        proc = subprocess.run([sys.executable, "-m", "scanline", "demo", "--out", out], env=env,
                              capture_output=True, text=True)
        rows.append({"case": label, "mode": None, "wall_s": time.perf_counter() - t0,
                     "ok": proc.returncode == 0, "specializations": sum(specializations(cache).values())})
        print(f"{label:<40} {rows[-1]['wall_s']:7.2f} s", flush=True)
    shutil.rmtree(cache, ignore_errors=True)
    shutil.rmtree(out, ignore_errors=True)
    return rows


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--only", help="run the cases whose name contains this text")
    parser.add_argument("--list", action="store_true", help="print the case names and stop")
    parser.add_argument("--demo", action="store_true", help="also time scanline demo cold and warm")
    parser.add_argument("--output", help="JSON file to write (default results/compile.json)")
    args = parser.parse_args(argv)
    todo = [c for c in cases(None) if not args.only or args.only in c[0]]
    if args.list:
        for name, mode, _ in todo:
            print(name if mode is None else f"{name} [{mode}]")
        return 0
    rows = []
    print(f"scanline compile budget: {len(todo)} cases, each in a fresh process with an empty "
          f"numba cache; {platform.processor() or platform.machine()}, "
          f"Python {platform.python_version()}", flush=True)
    for name, mode, child in todo:
        record, stdout = run_case(child, {})
        if child[1] == "-c":
            try:
                report = json.loads(stdout.strip().splitlines()[-1])
            except (ValueError, IndexError):
                report = {}
            record["seconds"] = report.get("seconds")
            record["slowest"] = report.get("slowest", [])
        else:
            record["seconds"] = record["wall_s"]
        row = {"case": name, "mode": mode, **record}
        rows.append(row)
        slow = ", ".join(f"{k} {s:.1f}s" for s, k in row.get("slowest", [])[:2])
        label = name if mode is None else f"{name} [{mode}]"
        secs = row["seconds"] if row["seconds"] is not None else row["wall_s"]
        print(f"{label:<40} {secs:7.2f} s  {row['specializations']:3d} specializations"
              f"{'' if row['ok'] else '  FAILED: ' + row.get('error', '')}  {slow}", flush=True)
    if args.demo:
        rows += demo_rows()
    worst = max(rows, key=lambda r: r.get("seconds") or r["wall_s"])
    print(f"worst: {worst['case']} {'[' + worst['mode'] + ']' if worst['mode'] else ''} "
          f"{worst.get('seconds') or worst['wall_s']:.2f} s", flush=True)
    import numba
    import numpy
    record = {
        "date": _dt.date.today().isoformat(),
        "machine": f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores",
        "python": platform.python_version(), "numba": numba.__version__,
        "numpy": numpy.__version__, "rows": rows,
    }
    default = "compile.json" if not args.only else "compile-partial.json"
    path = args.output or os.path.join(HERE, "results", default)
    with open(path, "w") as f:
        json.dump(record, f, indent=1)
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
