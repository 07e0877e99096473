"""The compile-time budget: the first call of every public entry point that reaches a
numba kernel, each in a fresh process with an empty numba cache.

A new user's first call pays numba's compilation of every kernel it reaches; the
kernel layer's rule (``docs/conventions.md``, "Compile time") keeps that within about
3 s per entry point on a 2-core machine.  This script measures it: for every *case*
(one call of :data:`scanline.warmup.CALLS`: an entry point, in one image mode
where the mode matters; and the command-line cases below) it starts a fresh
Python process with ``NUMBA_CACHE_DIR`` pointing at a new, empty folder, runs the
case and saves the result, and records

- ``seconds``: from the start of the process to the result written (interpreter
  start, ``import scanline``, the call, the PNG), and ``cpu_s``, the process's CPU
  time to then (less sensitive to other load on the machine);
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

By default the cases run as a new user's do: a small first call runs the kernels'
Python twins (:func:`scanline._kernels._jit.call`) and compiles only what is large;
``--compile`` makes every first call compile, which measures the kernels' own
compile budget.  Writes ``benchmarks/results/compile.json`` (or ``compile-always.json``
with ``--compile``; ``-partial`` with ``--only``).
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

from scanline.warmup import cases

HERE = os.path.dirname(os.path.abspath(__file__))

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
    "trace boundary-fill": ["trace", "boundary-fill", "1", "2"],
    "trace depth-sort": ["trace", "depth-sort", "--scene", "cyclic"],
    "trace floating-horizon": ["trace", "floating-horizon"],
    "trace scan-line-fill": ["trace", "scan-line-fill", "2,1", "15,4", "10,13", "6,6", "1,9"],
    "trace sutherland-hodgman": ["trace", "sutherland-hodgman", "--", "-2,2", "6,-1", "13,6",
                                 "6,13"],
    "explain bresenham": ["explain", "bresenham", "20", "10", "30", "18", "-o", "{out}/b.html"],
    "simulate random": ["simulate", "random", os.path.join(SCENES, "rotation.toml"), "-o",
                        "{out}/r.gif", "--frames", "8", "--refreshes", "1"],
    "animate scene": ["animate", os.path.join(os.path.dirname(HERE), "examples", "scenes",
                                               "bouncing_ball.toml"), "-o", "{out}/a.gif",
                      "--frames", "0:4"],
    "storyboard scene": ["storyboard", os.path.join(os.path.dirname(HERE), "examples",
                                                    "scenes", "bouncing_ball.toml"),
                         "-o", "{out}/b.png"],
    "trace cohen-sutherland-3d": ["trace", "cohen-sutherland-3d", "-5", "2", "5", "15", "22",
                                  "5"],
    "trace liang-barsky-3d": ["trace", "liang-barsky-3d", "0.5", "0.5", "1", "0.5", "0.5",
                              "-3", "--w", "2", "-2"],
    "render perspective scene": ["render", os.path.join(SCENES, "perspective.toml"), "-o",
                                 "{out}/p.png"],
    "draw command": ["draw", "--size", "64x48", "line", "2", "3", "60", "40", "circle", "32", "24",
                     "15", "-o", "{out}/d.png"],
}

#: Run inside the fresh process for a Python case (a call of :mod:`scanline.warmup`):
#: argv = [mode, code, out folder].
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
from scanline.warmup import run_case
mode, code, out = sys.argv[1], sys.argv[2], sys.argv[3]
run_case(mode if mode != "-" else None, code).save(os.path.join(out, "out.png"))
seconds = time.perf_counter() - T0
print(json.dumps({"seconds": seconds, "cpu_s": time.process_time(),
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


def all_cases():
    """Every case as (name, mode, argv), in table order: the calls of
    :data:`scanline.warmup.CALLS`, then the commands."""
    for name, mode, code in cases():
        yield name, mode, [sys.executable, "-c", CHILD, mode or "-", code, "{out}"]
    scanline = [sys.executable, "-m", "scanline"]
    for name, args in CLI_CASES.items():
        yield name, None, scanline + args


def demo_rows(env_extra):
    """``scanline demo`` cold (empty cache) and warm (the cache it filled)."""
    cache = tempfile.mkdtemp(prefix="scanline-numba-")
    out = tempfile.mkdtemp(prefix="scanline-demo-")
    env = dict(os.environ, NUMBA_CACHE_DIR=cache, **env_extra)
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
    parser.add_argument("--compile", action="store_true",
                        help="compile every kernel on its first call (SCANLINE_COMPILE=always): "
                        "the kernels' own compile budget, without the Python first calls")
    parser.add_argument("--output", help="JSON file to write (default results/compile.json)")
    args = parser.parse_args(argv)
    todo = [c for c in all_cases() if not args.only or args.only in c[0]]
    if args.list:
        for name, mode, _ in todo:
            print(name if mode is None else f"{name} [{mode}]")
        return 0
    if not todo:
        print(f"no case matches {args.only!r} (see --list)", file=sys.stderr)
        return 2
    rows = []
    print(f"scanline compile budget: {len(todo)} cases, each in a fresh process with an empty "
          f"numba cache; {platform.processor() or platform.machine()}, "
          f"Python {platform.python_version()}", flush=True)
    env = {"SCANLINE_COMPILE": "always" if args.compile else "auto"}
    for name, mode, child in todo:
        record, stdout = run_case(child, env)
        if child[1] == "-c":
            try:
                report = json.loads(stdout.strip().splitlines()[-1])
            except (ValueError, IndexError):
                report = {}
            record["seconds"] = report.get("seconds")
            record["cpu_s"] = report.get("cpu_s")
            record["slowest"] = report.get("slowest", [])
        else:
            record["seconds"] = record["wall_s"]
        row = {"case": name, "mode": mode, **record}
        rows.append(row)
        slow = ", ".join(f"{k} {s:.1f}s" for s, k in row.get("slowest", [])[:2])
        label = name if mode is None else f"{name} [{mode}]"
        secs = row["seconds"] if row["seconds"] is not None else row["wall_s"]
        cpu = f"{row['cpu_s']:6.2f}" if row.get("cpu_s") is not None else "      "
        print(f"{label:<40} {secs:7.2f} s {cpu} cpu  {row['specializations']:3d} specializations"
              f"{'' if row['ok'] else '  FAILED: ' + row.get('error', '')}  {slow}", flush=True)
    if args.demo:
        rows += demo_rows(env)
    worst = max(rows, key=lambda r: r.get("seconds") or r["wall_s"])
    print(f"worst: {worst['case']} {'[' + worst['mode'] + ']' if worst['mode'] else ''} "
          f"{worst.get('seconds') or worst['wall_s']:.2f} s", flush=True)
    import numba
    import numpy
    record = {
        "date": _dt.date.today().isoformat(),
        "machine": f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores",
        "python": platform.python_version(), "numba": numba.__version__,
        "numpy": numpy.__version__, "compile": env["SCANLINE_COMPILE"], "rows": rows,
    }
    default = ("compile" + ("-always" if args.compile else "")
               + (".json" if not args.only else "-partial.json"))
    path = args.output or os.path.join(HERE, "results", default)
    with open(path, "w") as f:
        json.dump(record, f, indent=1)
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
