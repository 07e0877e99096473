"""Radiosity of the Cornell box: form factors, the full solution (Gauss-Seidel) and
progressive refinement, in one run.

Workload (fixed): ``sl.radiosity.cornell_box()`` (the published geometry, 19
quadrilaterals), each face cut into 10 x 10 patches: 1,900 patches; hemicubes of
100 x 100 cells (the default).

* form factors: ``sl.radiosity.form_factors(patches)`` by the hemicube (all cores),
  and by ray casting at 2 x 2 points per patch (for comparison);
* the full solution: ``solve(patches, method="gauss-seidel", tolerance=1e-4)``,
  form factors included (the full matrix must exist before the first sweep);
* progressive refinement (Cohen, Chen, Wallace and Greenberg 1988): hemicubes made
  as the shooters shoot, until the energy leaving the surfaces, sum A_i B_i (without
  the ambient term), reaches 95% of the full solution's.  The number of shots is
  found by a first run to convergence; the timed run is ``solve(...,
  method="progressive", max_iterations=shots)``.  Timed twice: with the patches
  shooting in groups of 5 x 5 (``shooting_group=5``: 76 shooters, 2 x 2 per face;
  the 1988 paper's patches and elements, from Cohen et al. 1986) -- the target row
  -- and with each patch shooting alone (for information).

The target: progressive refinement reaches 95% of the energy at least 5x sooner
than the full solution (ratio: full solution time / progressive time).  The RMS
difference of each progressive estimate (with its ambient term) from the full
solution, patch by patch, is recorded beside it.

Run: ``flock /tmp/bench.lock python benchmarks/radiosity.py [--quick]``
(``--quick``: 5 x 5 patches per face, shooting in groups of 2 x 2).
"""

import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402

#: The fraction of the full solution's energy progressive refinement must reach.
ENERGY = 0.95


def rms_difference(pts, estimate, reference):
    """Area-weighted RMS difference over the reflecting patches, relative to the
    reference's RMS."""
    lit = pts.emission.max(axis=1) == 0
    w = pts.area[lit, None]
    return float(np.sqrt((w * (estimate[lit] - reference[lit]) ** 2).sum()
                         / (w * reference[lit] ** 2).sum()))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="5 x 5 patches per face")
    args = parser.parse_args()
    report = Report("radiosity", quick=args.quick)
    box = sl.radiosity.cornell_box()
    n = 5 if args.quick else 10
    pts = sl.radiosity.patches(box["meshes"], n, box["emission"], box["reflectance"])
    p = len(pts)
    print(f"  {p:,} patches, {os.cpu_count()} cores", flush=True)

    report.add(f"form factors, {p:,} patches", "scanline", "form_factors(patches) hemicube 100",
               lambda: sl.radiosity.form_factors(pts), repeats=2, n=p)
    report.add(f"form factors, {p:,} patches", "scanline-ray-casting",
               "form_factors(patches, method='ray-casting', resolution=2)",
               lambda: sl.radiosity.form_factors(pts, method="ray-casting", resolution=2),
               repeats=1, n=p)

    full = sl.radiosity.solve(pts, tolerance=1e-4)
    target = ENERGY * full.power[-1]
    print(f"  full solution: {full.iterations} sweeps; energy {full.power[-1]:.6g}", flush=True)
    rows = []
    block = n // 2                  # 2 x 2 shooters per face
    for group in (block, 1):
        converged = sl.radiosity.solve(pts, method="progressive", tolerance=1e-3,
                                       shooting_group=group)
        shots = int(np.argmax(converged.power >= target)) + 1
        assert converged.power[shots - 1] >= target, "progressive never reached 95%"
        work = f"Cornell box, {p:,} patches, to {ENERGY:.0%} of the energy" + (
            "" if group == block else " (each patch shoots)")
        report.add(work, "gauss-seidel", "solve(patches, tolerance=1e-4), form factors "
                   "included", lambda: sl.radiosity.solve(pts, tolerance=1e-4), repeats=2, n=p)
        report.add(work, "scanline", f"solve(patches, method='progressive', shooting_group="
                   f"{group}, max_iterations={shots})",
                   lambda: sl.radiosity.solve(pts, method="progressive", shooting_group=group,
                                              max_iterations=shots), repeats=3, n=p)
        estimate = sl.radiosity.solve(pts, method="progressive", shooting_group=group,
                                      max_iterations=shots)
        rows.append({"shooting_group": group, "shots": shots,
                     "shots_to_converge_1e-3": converged.iterations,
                     "energy_reached": float(estimate.power[-1] / full.power[-1]),
                     "rms_difference_from_full": rms_difference(pts, estimate.radiosity,
                                                                full.radiosity),
                     "converged_rms_difference_from_full": rms_difference(
                         pts, converged.radiosity, full.radiosity)})
        print(f"  shooting_group={group}: {shots} shots to {ENERGY:.0%} (converged in "
              f"{converged.iterations}); the estimate then differs from the full solution "
              f"by {100 * rows[-1]['rms_difference_from_full']:.1f}% RMS (converged: "
              f"{100 * rows[-1]['converged_rms_difference_from_full']:.1f}%)", flush=True)
        if group == block:
            report.target(work, "gauss-seidel", 5.0, "progressive refinement at 95% of the "
                          "energy >= 5x sooner than the full solution")
        else:
            ratio = report.best(work, "gauss-seidel") / report.best(work, "scanline")
            print(f"  (each patch shooting alone: {ratio:.2f}x, for information)", flush=True)
            rows[-1]["ratio"] = ratio
    for row in report.rows:
        row.setdefault("patches", p)
    report.rows.append({"workload": "progressive refinement details", "library": "scanline",
                        "call": "", "first_s": None, "best_s": None, "n": p, "details": rows})
    report.write()


if __name__ == "__main__":
    t0 = time.perf_counter()
    main()
    print(f"  ({time.perf_counter() - t0:.1f} s in all)")
