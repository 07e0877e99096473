"""Time the first call of scanline drawing functions in a fresh process.

``run.py`` runs this after its workloads, with the numba cache that its own first
calls filled, so the first calls here measure loading compiled kernels from numba's
on-disk cache: what every later process pays.  Run it with an empty
``NUMBA_CACHE_DIR`` to time cold compilation instead.  Prints one JSON object:
``{"import_s": ..., "first_call_s": {call: s}, "second_call_s": {call: s}}``.

    NUMBA_CACHE_DIR=$(mktemp -d) python benchmarks/compile_probe.py sl.draw.lines sl.draw.line
"""

import json
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

CALLS = {
    "sl.draw.line": ("line", (3, 4, 40, 20)),
    "sl.draw.lines": ("lines", ([[3, 4, 40, 20]],)),
    "sl.draw.circle": ("circle", (30, 30, 12)),
    "sl.draw.circles": ("circles", ([[30, 30, 12]],)),
    "sl.draw.ellipse": ("ellipse", (30, 30, 12, 7)),
    "sl.draw.ellipses": ("ellipses", ([[30, 30, 12, 7]],)),
    "sl.draw.polygon": ("polygon", ([[3, 4], [40, 20], [10, 30]],)),
    "sl.draw.polygons": ("polygons", ([[[3, 4], [40, 20], [10, 30]]],)),
    "sl.draw.flood_fill": ("flood_fill", (3, 4)),
}


def main(calls):
    import numpy as np

    t0 = time.perf_counter()
    import scanline as sl
    import scanline.draw  # noqa: F401  (imports numba and the kernel modules)
    out = {"import_s": time.perf_counter() - t0, "first_call_s": {}, "second_call_s": {},
           "cache": {}}
    from workloads import kernel_cache_stats

    fb = sl.FrameBuffer(64, 64, mode="RGB")
    for call in calls:
        name, args = CALLS[call]
        fn = getattr(sl.draw, name, None)
        if fn is None and name == "flood_fill":  # not exported yet: the module's own
            from workloads import flood_fill_available
            fn = flood_fill_available()
        # same argument types as the benchmark: int64 arrays, Python ints
        args = tuple(np.asarray(a, np.int64) if isinstance(a, list) else a for a in args)
        kind = name.rstrip("s")
        variant = "batch" if name.endswith("s") else "loop"
        before = kernel_cache_stats(kind, variant)
        for key in ("first_call_s", "second_call_s"):
            t0 = time.perf_counter()
            fn(fb, *args, color=(255, 255, 255))
            out[key][call] = time.perf_counter() - t0
            if key == "first_call_s":
                after = kernel_cache_stats(kind, variant)
                if before is not None and after is not None:
                    out["cache"][call] = ("cache hit" if after[0] > before[0] else
                                          "compiled" if after[1] > before[1] else
                                          "compiled earlier in this process")
    print(json.dumps(out))


if __name__ == "__main__":
    main(sys.argv[1:] or list(CALLS))
