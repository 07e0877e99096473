"""Timing and reporting shared by the topic benchmarks (``strokes.py``, ``text.py``,
``clip.py``, ``curves.py`` ...).

Each topic script times scanline and its peers on the same workload in one run,
prints one line per variant with the ratio peer time / scanline time, and writes a
JSON record to ``benchmarks/results/<topic>.json``.  Timings are the minimum of
``repeats`` warm runs (the first call, which compiles numba kernels, is reported
apart as ``first_s``); the cyclic garbage collector is off while timing.

Where a machine's speed changes from one moment to the next (a virtual machine
whose host is busy: the project's 2-core AMD EPYC machine ran the same kernel in 21
ms and 35 ms within seconds, 2026-12-07), minima taken one after the other compare
different moments.  :meth:`Report.alternate` then times the variants of a workload
in turn, one call of each per round, and the ratio of a target is the median of the
rounds' ratios: each round's calls ran at nearly the same moment.
"""

import datetime as _dt
import gc
import json
import os
import platform
import statistics
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def image_coords(points, height):
    """Device coordinates (y up, pixel centers at integers) of ``points`` (..., 2) as
    Cairo/Pillow image coordinates (y down, pixel centers at +0.5)."""
    import numpy as np

    out = np.array(points, np.float64)
    out[..., 0] += 0.5
    out[..., 1] = height - 0.5 - out[..., 1]
    return out


def timed(fn, repeats=3):
    """``(first_s, best_s)``: the time of a first call and the best of ``repeats``
    further calls of ``fn()``."""
    gc.collect()
    gc.disable()
    try:
        t0 = time.perf_counter()
        fn()
        first = time.perf_counter() - t0
        best = float("inf")
        for _ in range(repeats):
            t0 = time.perf_counter()
            fn()
            best = min(best, time.perf_counter() - t0)
    finally:
        gc.enable()
    return first, best


def alternated(fns, rounds):
    """``[(first_s, [round times]), ...]`` for the functions ``fns``: each called once
    (its first call, timed apart), then ``rounds`` rounds of one call of each in turn
    (the garbage collector off)."""
    gc.collect()
    gc.disable()
    try:
        out = []
        for fn in fns:
            t0 = time.perf_counter()
            fn()
            out.append((time.perf_counter() - t0, []))
        for _ in range(rounds):
            for fn, (_, times) in zip(fns, out):
                t0 = time.perf_counter()
                fn()
                times.append(time.perf_counter() - t0)
    finally:
        gc.enable()
    return out


class Report:
    """Collects the timings of one topic and prints them as they come.

    >>> r = Report("example", quick=True)            # doctest: +SKIP
    >>> r.add("thick polylines", "scanline", "sl.draw.polylines", fn)   # doctest: +SKIP
    """

    def __init__(self, topic, quick=False):
        self.topic = topic
        self.quick = quick
        self.rows = []
        self.targets = []
        print(f"scanline benchmarks: {topic}  {'(quick) ' if quick else ''}"
              f"{platform.processor() or platform.machine()}, Python {platform.python_version()}",
              flush=True)

    def add(self, workload, library, call, fn, repeats=3, n=None):
        """Time ``fn`` and record it; returns the best time in seconds."""
        first, best = timed(fn, repeats)
        self.rows.append({"workload": workload, "library": library, "call": call,
                          "first_s": first, "best_s": best, "n": n})
        print(f"  {workload:<28} {library:<12} {best * 1e3:10.2f} ms  (first {first * 1e3:.1f} ms)"
              f"  {call}", flush=True)
        return best

    def alternate(self, workload, entries, rounds=15):
        """Time the ``entries`` ``(library, call, fn, n)`` of one workload in turn
        (:func:`alternated`) and record each with its rounds' times."""
        group = len(self.rows)
        for (library, call, _, n), (first, times) in zip(
                entries, alternated([e[2] for e in entries], rounds)):
            best = min(times)
            self.rows.append({"workload": workload, "library": library, "call": call,
                              "first_s": first, "best_s": best, "n": n,
                              "rounds_s": times, "alternated": group})
            print(f"  {workload:<28} {library:<12} {best * 1e3:10.2f} ms  (first "
                  f"{first * 1e3:.1f} ms, median {statistics.median(times) * 1e3:.2f} ms of "
                  f"{rounds} rounds in turn)  {call}", flush=True)

    def _row(self, workload, library):
        return min((r for r in self.rows if r["workload"] == workload
                    and r["library"] == library), key=lambda r: r["best_s"])

    def ratio(self, workload, peer, library="scanline"):
        """peer time / ``library`` time on ``workload``: the median of the rounds'
        ratios where the two were timed in turn (:meth:`alternate`), else the ratio of
        their best times."""
        a, b = self._row(workload, peer), self._row(workload, library)
        if "alternated" in a and a["alternated"] == b.get("alternated"):
            return statistics.median(x / y for x, y in zip(a["rounds_s"], b["rounds_s"]))
        return a["best_s"] / b["best_s"]

    def median(self, workload, library):
        """The median of the rounds of ``library`` on ``workload`` timed in turn
        (:meth:`alternate`)."""
        return statistics.median(self._row(workload, library)["rounds_s"])

    def best(self, workload, library):
        """The best time recorded for ``library`` on ``workload``."""
        return self._row(workload, library)["best_s"]

    def target(self, workload, peer, minimum, text):
        """Record the target "peer time / scanline time >= minimum" and print it."""
        ratio = self.ratio(workload, peer)
        met = ratio >= minimum
        self.targets.append({"workload": workload, "peer": peer, "ratio": ratio,
                             "minimum": minimum, "met": met, "text": text})
        how = (" (median of the rounds in turn; best times "
               f"{self.best(workload, peer) / self.best(workload, 'scanline'):.2f}x)"
               if "alternated" in self._row(workload, peer) else "")
        print(f"  -> {workload}: {peer} time / scanline time = {ratio:.2f}x{how} "
              f"(target {text}: {'met' if met else 'NOT met'})", flush=True)
        return ratio

    def write(self):
        """Write ``results/<topic>[-quick].json`` atomically; return its path."""
        record = {
            "schema": 1, "topic": self.topic, "quick": self.quick,
            "date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
            "command": " ".join([os.path.basename(sys.executable), *sys.argv]),
            "python": platform.python_version(), "machine": platform.machine(),
            "cpu_count": os.cpu_count(), "load_average": list(os.getloadavg()),
            "rows": self.rows, "targets": self.targets,
        }
        folder = os.path.join(HERE, "results")
        os.makedirs(folder, exist_ok=True)
        path = os.path.join(folder, f"{self.topic}{'-quick' if self.quick else ''}.json")
        fd, tmp = tempfile.mkstemp(suffix=".tmp", dir=folder)
        try:
            with os.fdopen(fd, "w") as f:
                json.dump(record, f, indent=1)
                f.write("\n")
            os.chmod(tmp, 0o644)
            os.replace(tmp, path)
        except BaseException:
            os.unlink(tmp)
            raise
        print(f"wrote {path}")
        return path
