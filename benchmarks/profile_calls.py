"""Where does one ``sl.draw.line`` call spend its time?  (A diagnostic, not part of
run.py's record.)

    python benchmarks/profile_calls.py [--cprofile]

Times, with timeit (best of 5), the whole call and each of its parts: argument
checks of the API layer, the color lookup, and the numba kernel called directly
(dispatch + drawing), on a short line (overhead-bound) and a long one (pixel-bound),
next to ``cv2.line`` on the same pixels; then one short line, circle and filled
polygon against the matching OpenCV call, as ratios.  The parts are looked up by their current
internal names; a part that has been renamed is reported as missing.
"""

import sys
import timeit

import numpy as np


def best(stmt, number, globs):
    t = min(timeit.repeat(stmt, number=number, repeat=5, globals=globs))
    return t / number * 1e6  # microseconds per call


def main(argv):
    import cv2
    import scanline as sl
    import scanline.draw  # noqa: F401

    W = H = 4096
    fb = sl.FrameBuffer(W, H, mode="RGB")
    img = np.zeros((H, W, 3), np.uint8)
    white = (255, 255, 255)
    globs = {"sl": sl, "fb": fb, "cv2": cv2, "img": img, "white": white, "np": np}

    parts = {}
    try:
        import importlib
        v = importlib.import_module("scanline._validate")
        k = importlib.import_module("scanline._kernels.lines")
        _common = importlib.import_module("scanline.draw._common")
        api = importlib.import_module("scanline.draw.lines")  # the module, not the function
        variants = importlib.import_module("scanline._kernels.variants")
        buf, packed = fb._raster()
        lay = variants.layout(packed)
        color = fb.pixel(white)
        code = api._method("bresenham")
        globs.update(v=v, k=k, _common=_common, api=api, buf=buf, lay=lay, color=color,
                     code=code, W=W, H=H)
        parts = {
            "target(fb)": "_common.target(fb)",
            "_method('bresenham')": "api._method('bresenham')",
            "4 x v.coordinate()": "v.coordinate('x0', 10); v.coordinate('y0', 10); "
                                  "v.coordinate('x1', 30); v.coordinate('y1', 17)",
            "fb.pixel(color) (cached)": "fb.pixel(white)",
        }
    except Exception as exc:  # internal names changed
        print(f"(internal parts not found: {type(exc).__name__}: {exc})")

    def noop(fb, x0, y0, x1, y1, color="white", method="bresenham"):
        return None
    globs["noop"] = noop

    for label, (x0, y0, x1, y1) in (("short line, 21 pixels", (10, 10, 30, 17)),
                                     ("long line, 4001 pixels", (50, 40, 4050, 3900))):
        n = 20000 if label.startswith("short") else 2000
        globs.update(x0=x0, y0=y0, x1=x1, y1=y1, yi0=H - 1 - y0, yi1=H - 1 - y1)
        rows = [
            ("sl.draw.line(fb, x0, y0, x1, y1, color=white)",
             "sl.draw.line(fb, x0, y0, x1, y1, color=white)"),
            ("cv2.line(img, p, q, white, 1, cv2.LINE_8)",
             "cv2.line(img, (x0, yi0), (x1, yi1), white, 1, cv2.LINE_8)"),
            ("empty Python function, same arguments", "noop(fb, x0, y0, x1, y1, color=white)"),
        ]
        rows += [(name, stmt) for name, stmt in parts.items()]
        if "k" in globs:
            rows.append(("kernel k.draw_line(...) called directly",
                         "k.draw_line(buf, lay, W, H, x0, y0, x1, y1, color, code)"))
        print(f"\n{label}: microseconds per call (best of 5 x {n:,})")
        for name, stmt in rows:
            try:
                print(f"  {best(stmt, n, globs):9.3f}  {name}")
            except Exception as exc:
                print(f"  {'missing':>9}  {name} ({type(exc).__name__}: {exc})")

    # the three single calls against OpenCV's (target: at most 2.5x its time)
    # the same vertices in an array, as each library takes them: int32 for OpenCV (in
    # its image rows), float64 for scanline (a list of tuples costs it about 1 us more)
    globs.update(pts=np.array([(10, 10), (40, 12), (30, 40), (12, 30)], np.float64),
                 cpts=[np.array([[10, H - 11], [40, H - 13], [30, H - 41], [12, H - 31]], np.int32)])
    pairs = (("line, 21 pixels", "sl.draw.line(fb, 10, 10, 30, 17, color=white)",
              "cv2.line(img, (10, H - 11), (30, H - 18), white, 1, cv2.LINE_8)"),
             ("circle, r = 10", "sl.draw.circle(fb, 100, 100, 10, color=white)",
              "cv2.circle(img, (100, H - 101), 10, white, 1, cv2.LINE_8)"),
             ("filled quadrilateral", "sl.draw.polygon(fb, pts, color=white)",
              "cv2.fillPoly(img, cpts, white, cv2.LINE_8)"))
    print("\nsingle calls, microseconds (best of 5 x 20,000): scanline, OpenCV, ratio (target <= 2.5)")
    for label, ours, theirs in pairs:
        exec(ours, globs)                       # compiled (or loaded) before timing
        a, b = best(ours, 20000, globs), best(theirs, 20000, globs)
        print(f"  {label:22s} {a:8.3f} {b:8.3f} {a / b:6.2f}x")

    if "--cprofile" in argv:
        import cProfile
        import pstats
        segs = np.random.default_rng(0).integers(0, 2048, (100_000, 4)).tolist()
        prof = cProfile.Profile()
        prof.enable()
        for a, b, c, d in segs:
            sl.draw.line(fb, a, b, c, d, color=white)
        prof.disable()
        print("\ncProfile of 100,000 sl.draw.line calls (random lines on the 4096x4096 buffer):")
        pstats.Stats(prof).sort_stats("tottime").print_stats(12)


if __name__ == "__main__":
    main(sys.argv[1:])
