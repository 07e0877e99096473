"""Time scanline against OpenCV, Pillow and scikit-image on the same workloads.

    python benchmarks/run.py                 # full run, writes benchmarks/results/latest.json
    python benchmarks/run.py --quick         # workloads ~10x smaller, a fast check
    python benchmarks/run.py --only circles  # one workload (or: short-lines, long-lines,
                                             # circles, ellipses, polygons, flood-fill;
                                             # comma-separated)

Ratios are peer time / scanline time: above 1 means scanline is faster.  Warm times
are the best (minimum) of ``--repeats`` runs, after a first call on one primitive
(timed and reported apart) and an untimed warm-up; the variants of a workload are run
in turn, one run of each per round, so that their runs share the same stretch of
time.  By default numba's on-disk cache is pointed at an empty temporary folder, so
scanline's first calls are genuine JIT compilations; afterwards a fresh process
(``compile_probe.py``) loads the kernels from that cache, which is what every later
``import scanline`` pays.  ``--use-cache`` keeps numba's normal cache instead (faster
re-runs; first calls may then be cache loads).
See benchmarks/README.md for how to read the output.
"""

import argparse
import datetime as _dt
import gc
import json
import os
import platform
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import report  # noqa: E402
import workloads as wl  # noqa: E402

WORKLOADS = ("short-lines", "long-lines", "circles", "ellipses", "polygons", "flood-fill")
SECTIONS = WORKLOADS

# Full-size workloads (the issue's) and, per workload and variant, the most
# primitives that are timed; slower per-primitive loops are timed on a prefix and
# scaled linearly to the whole workload (said in the output and in the JSON).
# (flood-fill: the side of the maze image; one fill per run)
SIZES = {"short-lines": 1_000_000, "long-lines": 10_000, "circles": 100_000, "ellipses": 100_000,
         "polygons": 10_000, "flood-fill": 4096}
CAPS = {
    ("short-lines", "sk-loop"): 100_000,
    ("circles", "sk-loop"): 25_000,
    ("ellipses", "sk-loop"): 25_000,
}
BUILDERS = {"short-lines": wl.short_lines, "long-lines": wl.long_lines,
            "circles": wl.circles, "ellipses": wl.ellipses, "polygons": wl.polygons,
            "flood-fill": lambda size: wl.flood_fill(size=size)}

# Targets (issue 31, "Every core, and the smallest call"; the long line and the flood
# fill from the issue before it).  "fastest peer loop" = the fastest of OpenCV, Pillow
# and scikit-image called once per primitive in a Python loop.
TARGETS = [
    {"id": "batch-lines-20x", "workload": "short-lines", "threshold": 20.0,
     "what": "sl.draw.lines (1 call) >= 20x faster than the fastest peer's per-primitive loop"},
    {"id": "batch-circles-5x", "workload": "circles", "threshold": 5.0,
     "what": "sl.draw.circles (1 call) >= 5x faster than the fastest peer's per-primitive loop"},
    {"id": "long-line-single-call", "workload": "long-lines", "threshold": 1 / 1.2,
     "what": "one sl.draw.line call on a long line within 1.2x of cv2.line (ratio >= 0.83)"},
    {"id": "polygon-fill-vs-opencv", "workload": "polygons", "threshold": 1.5,
     "what": "sl.draw.polygons (1 call) >= 1.5x faster than a cv2.fillPoly loop"},
    {"id": "flood-fill-vs-opencv", "workload": "flood-fill", "threshold": 1 / 1.5,
     "what": "sl.draw.flood_fill within 1.5x of cv2.floodFill's time (ratio >= 0.67)"},
]


# -- machine --------------------------------------------------------------------------
def _cpuinfo():
    model, physical = None, set()
    try:
        with open("/proc/cpuinfo") as f:
            phys = core = None
            for line in f:
                key, _, value = line.partition(":")
                key, value = key.strip(), value.strip()
                if key == "model name" and model is None:
                    model = value
                elif key == "physical id":
                    phys = value
                elif key == "core id":
                    core = value
                elif not key and phys is not None:
                    physical.add((phys, core))
                    phys = core = None
    except OSError:
        pass
    return model or platform.processor() or "unknown", len(physical) or None


def _version(module):
    try:
        mod = __import__(module)
        return getattr(mod, "__version__", "unknown")
    except Exception as exc:  # pragma: no cover - missing peer
        return f"not available ({type(exc).__name__})"


def _git(*args):
    try:
        return subprocess.run(["git", *args], cwd=HERE, capture_output=True, text=True,
                              timeout=10).stdout.strip()
    except Exception:
        return None


def source_fingerprint():
    """sha256 of scanline's Python sources: others may edit the tree while this runs."""
    import hashlib
    import scanline
    root = os.path.dirname(scanline.__file__)
    h = hashlib.sha256()
    for d, dirs, files in sorted(os.walk(root)):
        dirs.sort()
        for f in sorted(files):
            if f.endswith(".py"):
                path = os.path.join(d, f)
                h.update(os.path.relpath(path, root).encode())
                with open(path, "rb") as fh:
                    h.update(fh.read())
    return h.hexdigest()[:16]


def cpu_pressure():
    """Linux PSI: the share of time some task waited for a CPU (10 s, 60 s averages)."""
    try:
        with open("/proc/pressure/cpu") as f:
            fields = dict(kv.split("=") for kv in f.readline().split()[1:])
        return {"some_avg10": float(fields["avg10"]), "some_avg60": float(fields["avg60"])}
    except (OSError, KeyError, ValueError):
        return None


def machine_info():
    model, physical = _cpuinfo()
    try:
        usable = len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - non-Linux
        usable = os.cpu_count()
    mem = None
    try:
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemTotal:"):
                    mem = round(int(line.split()[1]) / 2**20, 1)
    except OSError:
        pass
    info = {
        "cpu_model": model,
        "cpu_count_logical": os.cpu_count(),
        "cpu_count_physical": physical,
        "cpu_count_usable": usable,
        "memory_gib": mem,
        "platform": platform.platform(),
        "python": f"{platform.python_implementation()} {platform.python_version()}",
        "numpy": _version("numpy"),
        "numba": _version("numba"),
        "opencv": _version("cv2"),
        "pillow": _version("PIL"),
        "skimage": _version("skimage"),
        "scanline": _version("scanline"),
        "git_commit": _git("rev-parse", "HEAD"),
        "git_src_dirty": bool(_git("status", "--porcelain", "--", "../src")),
    }
    try:
        import cv2
        info["opencv_threads"] = cv2.getNumThreads()
    except Exception:  # pragma: no cover
        pass
    return info


# -- timing -----------------------------------------------------------------------------
def _timed(fn, *args):
    """Wall time of ``fn(*args)``.  run() switches the cyclic garbage collector off for
    the whole run (as timeit does for its loop), so a collection, which after numba's
    compilations walks a large object graph, cannot land in one library's timing."""
    t0 = time.perf_counter()
    fn(*args)
    return time.perf_counter() - t0


def time_variants(w, vs, repeats, log):
    """Time the variants ``vs`` on workload ``w``: each one's first call and warm-up,
    then ``repeats`` rounds of one run of each in turn, so that every variant's runs
    are spread over the same stretch of time (a machine whose speed changes from one
    moment to the next slows them alike; benchmarks/common.py)."""
    states = [_set_up(w, v, log) for v in vs]
    for _ in range(repeats):
        for state in states:
            if "runs" in state:
                state["canvas"].clear()
                state["runs"].append(_timed(state["v"].draw, state["canvas"], state["data"]))
    return [state["result"] if "result" in state else
            _result(w, state["v"], state["n_timed"], state["first"], state["cache"],
                    state["runs"], state["prepare_s"], log) for state in states]


def _set_up(w, v, log):
    """Variant ``v`` ready to be timed: its canvas and data, its first call (timed)
    and an untimed warm-up; a variant too slow to repeat is timed once here."""
    n_timed = min(w.n, v.max_timed) if v.max_timed else w.n
    t0 = time.perf_counter()
    canvas = v.canvas(w.width, w.height)
    first_data = v.prepare(w, w.prims[:1])
    warm_data = v.prepare(w, w.prims[:min(n_timed, 1000)])
    data = v.prepare(w, w.prims[:n_timed])
    prepare_s = time.perf_counter() - t0
    before = wl.kernel_cache_stats(w.kind, v.kind) if v.library == "scanline" else None
    if v.single_run:  # too slow to repeat: one run is the first call and the time
        first = _timed(v.draw, canvas, data)
        res = _result(w, v, n_timed, first, None, [first], prepare_s, log)
        if n_timed >= w.sanity_n:  # the sanity check reuses these pixels
            res["_mask"] = canvas.mask()
        return {"v": v, "result": res}
    first = _timed(v.draw, canvas, first_data)
    after = wl.kernel_cache_stats(w.kind, v.kind) if v.library == "scanline" else None
    cache = None
    if before is not None and after is not None:
        hits, misses = after[0] - before[0], after[1] - before[1]
        cache = "cache hit" if hits else "compiled" if misses else "compiled earlier in this run"
    v.draw(canvas, warm_data)
    return {"v": v, "canvas": canvas, "data": data, "n_timed": n_timed, "first": first,
            "cache": cache, "prepare_s": prepare_s, "runs": []}


def _result(w, v, n_timed, first, cache, runs, prepare_s, log):
    scale = w.n / n_timed
    best = min(runs) * scale
    res = {
        "key": v.key, "library": v.library, "call": v.call, "kind": v.kind,
        "info_only": v.info_only, "n": w.n, "n_timed": n_timed, "scale": scale,
        "first_call_s": first, "first_call_cache": cache,
        "runs_s": runs, "warm_s": best, "per_primitive_us": best / w.n * 1e6,
        "prepare_s": prepare_s,
    }
    note = f" (timed on {n_timed:,}, scaled x{scale:g})" if scale != 1 else ""
    if v.single_run:
        note += " (one run)"
    log(f"  {v.library:<12} {v.call:<48} warm {best:9.4f} s{note}")
    return res


def sanity_check(w, vs, done=None):
    """Draw the first ``w.sanity_n`` primitives with every variant on fresh canvases
    and compare the set pixels with scanline's batch call.  ``done`` maps variant
    keys to masks already drawn (the one-run variants)."""
    done = done or {}
    prims = w.prims[:w.sanity_n]
    masks = {}
    for v in vs:
        if v.key in done:
            masks[v.key] = done[v.key]
            continue
        c = v.canvas(w.width, w.height)
        v.draw(c, v.prepare(w, prims))
        masks[v.key] = c.mask()
        del c
    ref = masks["sl-batch"]
    ref_n = int(ref.sum())
    out = {"n_primitives": len(prims), "reference": "sl-batch", "set_pixels": {}, "compare": {}}
    for v in vs:
        m = masks[v.key]
        n = int(m.sum())
        out["set_pixels"][v.key] = n
        if v.key == "sl-batch":
            continue
        inter = int((m & ref).sum())
        union = int((m | ref).sum())
        out["compare"][v.key] = {
            "library": v.library, "call": v.call, "set_pixels": n,
            "count_diff_pct": 100.0 * (n - ref_n) / ref_n if ref_n else 0.0,
            "jaccard": inter / union if union else 1.0,
            "identical": bool(np.array_equal(m, ref)),
        }
    return out


def evaluate_targets(results):
    out = []
    for t in TARGETS:
        r = results.get(t["workload"])
        if r is None:
            continue
        rows = {x["key"]: x for x in r["results"]}
        if t["id"] in ("polygon-fill-vs-opencv", "flood-fill-vs-opencv"):
            if "sl-batch" not in rows:
                continue
            peer, ours = rows["cv2-loop"], rows["sl-batch"]
            value = peer["warm_s"] / ours["warm_s"]
            detail = f"{peer['call']} {peer['warm_s']:.3f} s, {ours['call']} {ours['warm_s']:.3f} s"
            if "sl-loop" in rows:
                detail += (f"; sl.draw.polygon loop {rows['sl-loop']['warm_s']:.3f} s "
                           f"(ratio {peer['warm_s'] / rows['sl-loop']['warm_s']:.2f})")
        elif t["id"] == "long-line-single-call":
            peer, ours = rows["cv2-loop"], rows["sl-loop"]
            value = peer["per_primitive_us"] / ours["per_primitive_us"]
            detail = (f"cv2.line {peer['per_primitive_us']:.1f} us/call, "
                      f"sl.draw.line {ours['per_primitive_us']:.1f} us/call")
        else:
            peers = [x for x in r["results"] if x["library"] != "scanline" and not x["info_only"]]
            fastest = min(peers, key=lambda x: x["warm_s"])
            value = fastest["warm_s"] / rows["sl-batch"]["warm_s"]
            detail = (f"fastest peer loop {fastest['library']} {fastest['warm_s']:.3f} s, "
                      f"{rows['sl-batch']['call']} {rows['sl-batch']['warm_s']:.3f} s")
        out.append({**t, "value": value, "met": value >= t["threshold"], "detail": detail})
    return out


def add_ratios(res):
    rows = {x["key"]: x for x in res}
    batch = rows["sl-batch"]["warm_s"]
    loop = rows["sl-loop"]["warm_s"] if "sl-loop" in rows else batch  # flood fill: one call
    for x in res:
        x["ratio_vs_sl_batch"] = x["warm_s"] / batch
        x["ratio_vs_sl_loop"] = x["warm_s"] / loop


# -- cached first call -------------------------------------------------------------------
def cache_load(calls, log):
    """First call of each of ``calls`` in a fresh process whose numba cache holds them."""
    probe = os.path.join(HERE, "compile_probe.py")
    p = subprocess.run([sys.executable, probe, *calls], capture_output=True, text=True,
                       timeout=600)
    if p.returncode != 0:
        err = (p.stderr.strip().splitlines() or ["?"])[-1]
        log(f"  compile_probe.py failed: {err}")
        return {"error": err}
    out = json.loads(p.stdout.strip().splitlines()[-1])
    for call, t in out["first_call_s"].items():
        log(f"  {call:<18} first call {t * 1e3:8.1f} ms  ({out['cache'].get(call, '?')})")
    return out


# -- main -----------------------------------------------------------------------------------
def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--quick", action="store_true", help="workloads ~10x smaller")
    p.add_argument("--only", metavar="NAME",
                   help="comma-separated sections: " + ", ".join(SECTIONS))
    p.add_argument("--repeats", type=int, default=3, help="timed runs per variant (default 3)")
    p.add_argument("--use-cache", action="store_true",
                   help="use numba's normal on-disk cache (first calls may be cache loads, "
                        "not compilations)")
    p.add_argument("--output", metavar="PATH",
                   help="JSON record (default: results/latest.json for a full run, "
                        "results/latest-quick.json or results/latest-partial.json otherwise)")
    a = p.parse_args(argv)
    a.sections = SECTIONS
    if a.only:
        a.sections = tuple(s.strip() for s in a.only.split(",") if s.strip())
        bad = [s for s in a.sections if s not in SECTIONS]
        if bad:
            p.error(f"--only: unknown section(s) {', '.join(bad)}; choose from {', '.join(SECTIONS)}")
    if a.repeats < 1:
        p.error("--repeats must be >= 1")
    if a.output is None:
        name = ("latest-quick.json" if a.quick else
                "latest-partial.json" if a.only or a.repeats != 3 or a.use_cache
                else "latest.json")
        a.output = os.path.join(HERE, "results", name)
    return a


def write_json(path, record):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fd, tmp = tempfile.mkstemp(suffix=".tmp", dir=os.path.dirname(os.path.abspath(path)))
    try:
        with os.fdopen(fd, "w") as f:
            json.dump(record, f, indent=1)
            f.write("\n")
        os.chmod(tmp, 0o644)  # mkstemp makes it private
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def main(argv=None):
    a = parse_args(argv)
    # the first call on one primitive measures the kernels' compilation, not the Python
    # twins a new user's small first call runs (benchmarks/compile.py measures that)
    os.environ["SCANLINE_COMPILE"] = "always"
    if a.use_cache:
        return run(a, cache_dir=None)
    # numba reads NUMBA_CACHE_DIR when it is imported, which has not happened yet
    with tempfile.TemporaryDirectory(prefix="scanline-bench-numba-") as cache_dir:
        os.environ["NUMBA_CACHE_DIR"] = cache_dir
        return run(a, cache_dir)


def run(a, cache_dir):
    start = time.perf_counter()
    gc.disable()  # see _timed(); gc.collect() runs between workloads

    def log(msg):
        print(msg, flush=True)

    t0 = time.perf_counter()
    import scanline.draw  # noqa: F401  (imports numba; not counted in any timing)
    import_s = time.perf_counter() - t0

    record = {
        "schema": 1,
        "date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
        "command": " ".join([os.path.basename(sys.executable), "benchmarks/run.py", *sys.argv[1:]]),
        "quick": a.quick, "sections": list(a.sections), "repeats": a.repeats,
        "machine": machine_info(), "load_average_start": list(os.getloadavg()),
        "cpu_pressure_start": cpu_pressure(),
        "scanline_source_sha256_start": source_fingerprint(),
        "color": "white (255, 255, 255) on black, RGB uint8",
        "workloads": {}, "targets": [],
        "compile": {"numba_cache": "empty temporary folder (first calls compile)"
                    if cache_dir else "numba's normal on-disk cache (--use-cache)",
                    "import_scanline_draw_s": import_s},
    }
    m = record["machine"]
    psi = record["cpu_pressure_start"]
    # CPU pressure reacts within seconds; the 1-minute load average lags behind
    busy = (psi["some_avg10"] > 20.0 if psi else
            record["load_average_start"][0] > 0.5 * (m["cpu_count_usable"] or 1))
    record["machine_busy_at_start"] = busy
    log(f"scanline benchmarks  {record['date']}  {'QUICK (~10x smaller) ' if a.quick else ''}"
        f"min of {a.repeats} warm runs")
    log(f"{m['cpu_model']}, {m['cpu_count_usable']} usable cores; Python {m['python']}; "
        f"numpy {m['numpy']}, numba {m['numba']}, OpenCV {m['opencv']}, Pillow {m['pillow']}, "
        f"scikit-image {m['skimage']}; load average {record['load_average_start'][0]:.2f}")
    if psi:
        log(f"CPU pressure (share of time a task waited for a CPU, last 10 s): "
            f"{psi['some_avg10']:.0f}%")
    if busy:
        log("WARNING: the machine is busy (CPU pressure above 20%, or without /proc/pressure "
            "a load average above half the cores); timings will be slower and noisier than "
            "on an idle machine")

    shrink = 10 if a.quick else 1
    for name in WORKLOADS:
        if name not in a.sections:
            continue
        w = BUILDERS[name](SIZES[name] // shrink)
        caps = {k: c // shrink for k, c in CAPS.items()}
        log(f"\n[{name}] {w.description} (RGB), seed {w.seed}")
        vs = wl.variants(w, caps)
        if not any(v.key == "sl-batch" for v in vs):
            log("  SKIPPED: sl.draw.flood_fill is not available yet (scanline has no flood "
                "fill to time)")
            record.setdefault("skipped", {})[name] = "sl.draw.flood_fill not available"
            continue
        t_w = time.perf_counter()
        res = time_variants(w, vs, a.repeats, log)
        add_ratios(res)
        entry = {"description": w.description, "kind": w.kind, "n": w.n,
                 "canvas": [w.width, w.height], "seed": w.seed, "params": w.params,
                 "results": res}
        done = {r["key"]: r.pop("_mask") for r in res if "_mask" in r}
        entry["sanity"] = sanity_check(w, vs, done)
        entry["elapsed_s"] = time.perf_counter() - t_w
        gc.collect()  # between workloads, untimed
        log(f"  ({entry['elapsed_s']:.0f} s for this workload, including compilation, "
            "data preparation and the sanity check)")
        record["workloads"][name] = entry
        del w, vs

    record["targets"] = evaluate_targets(record["workloads"])

    calls = []
    for entry in record["workloads"].values():
        for c in (wl.batch_name(entry["kind"]), wl.single_name(entry["kind"])):
            if c not in calls:
                calls.append(c)
    if calls:
        log("\n[compile] the same calls in a fresh process, kernels loaded from numba's cache")
        record["compile"]["cache_load"] = cache_load(calls, log)

    record["load_average_end"] = list(os.getloadavg())
    record["cpu_pressure_end"] = cpu_pressure()
    record["scanline_source_sha256_end"] = source_fingerprint()
    if record["scanline_source_sha256_end"] != record["scanline_source_sha256_start"]:
        log("WARNING: scanline's source files changed during the run; the timings may mix "
            "two versions of the kernels")
    record["elapsed_s"] = time.perf_counter() - start
    log("")
    log(report.text(record))
    write_json(a.output, record)
    log(f"\nwrote {os.path.relpath(a.output)} (total {record['elapsed_s']:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
