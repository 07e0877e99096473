"""The Mandelbrot set by escape time: scanline's compiled kernel (interleaved rows, one
call per thread) against a vectorized numpy version written here, on the same
workload, with the same arithmetic (their counts are compared, pixel for pixel).

Workload (fixed): ``sl.fractals.mandelbrot(1920, 1080, center=(-0.5, 0), span=3.0,
max_iterations=256)``: 2,073,600 pixels.  The numpy version iterates all pixels
still inside at once (the usual vectorization: boolean masks shrink the working set
as pixels escape), 256 steps of array operations.

The target: scanline at least 5x the numpy version (ratio: numpy time / scanline
time).  The kernel is also timed on one thread, so that the ratio can be read per
core; the machine's core count is printed and recorded.

Run: ``flock /tmp/bench.lock python benchmarks/fractals.py [--quick]``
(``--quick``: 480 x 270 pixels).
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402

CENTER, SPAN, ITERATIONS = (-0.5, 0.0), 3.0, 256


def numpy_mandelbrot(width, height, center=CENTER, span=SPAN, max_iterations=ITERATIONS):
    """Iteration counts as :func:`scanline.fractals.mandelbrot` defines them, computed
    with whole-array numpy operations over the pixels not yet escaped."""
    step = span / width
    xs = center[0] + (np.arange(width) + 0.5 - width / 2) * step
    ys = center[1] + (height / 2 - np.arange(height) - 0.5) * step
    cr = np.broadcast_to(xs[None, :], (height, width)).ravel()
    ci = np.broadcast_to(ys[:, None], (height, width)).ravel()
    counts = np.full(cr.shape, max_iterations, np.int64)
    alive = np.arange(cr.size)
    zr = np.zeros(cr.size)
    zi = np.zeros(cr.size)
    c_r, c_i = cr.copy(), ci.copy()
    for n in range(max_iterations):
        zr2 = zr * zr
        zi2 = zi * zi
        out = zr2 + zi2 > 4.0
        if out.any():
            counts[alive[out]] = n
            keep = ~out
            alive, zr, zi, zr2, zi2 = alive[keep], zr[keep], zi[keep], zr2[keep], zi2[keep]
            c_r, c_i = c_r[keep], c_i[keep]
        zi = 2.0 * zr * zi + c_i
        zr = zr2 - zi2 + c_r
    return counts.reshape(height, width)


def main():
    import numba

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="480 x 270 pixels")
    args = parser.parse_args()
    width, height = (480, 270) if args.quick else (1920, 1080)
    report = Report("fractals", quick=args.quick)
    cores = numba.get_num_threads()
    print(f"  cores: os.cpu_count() = {os.cpu_count()}, numba threads = {cores}")
    work = f"mandelbrot {width}x{height} @{ITERATIONS}"
    ours = sl.fractals.mandelbrot(width, height, CENTER, SPAN, ITERATIONS)
    theirs = numpy_mandelbrot(width, height)
    same = bool(np.array_equal(ours, theirs))
    print(f"  counts identical: {same}")
    report.add(work, "scanline", f"sl.fractals.mandelbrot({width}, {height}, max_iterations="
               f"{ITERATIONS}), {cores} threads",
               lambda: sl.fractals.mandelbrot(width, height, CENTER, SPAN, ITERATIONS))
    report.add(work, "numpy", "vectorized escape time with shrinking masks",
               lambda: numpy_mandelbrot(width, height), repeats=2)
    before = numba.get_num_threads()
    numba.set_num_threads(1)
    try:
        report.add(work, "scanline-1-thread", "the same kernel on one thread",
                   lambda: sl.fractals.mandelbrot(width, height, CENTER, SPAN, ITERATIONS))
    finally:
        numba.set_num_threads(before)
    report.target(work, "numpy", 5.0, f"at least 5x a vectorized numpy version ({cores} "
                  "threads)")
    one = report.best(work, "numpy") / report.best(work, "scanline-1-thread")
    print(f"  -> on one thread: numpy time / scanline time = {one:.2f}x")
    report.rows.append({"workload": "details", "library": "scanline", "call": "",
                        "first_s": 0.0, "best_s": 0.0, "n": None, "cores": cores,
                        "counts_identical": same, "one_thread_ratio": one})
    report.write()


if __name__ == "__main__":
    main()
