"""Clipping: scanline's batch clippers vs shapely (GEOS), vectorized.

Workloads (fixed seed):

* ``lines``: 1M random segments with endpoints uniform in [-50, 150]^2 against the
  window (0, 0, 100, 100) (about half cross it).  scanline:
  ``sl.clip.lines(segments, window, method=...)`` for each of Cohen-Sutherland,
  Liang-Barsky and Cyrus-Beck (one compiled call each); shapely:
  ``shapely.clip_by_rect(linestrings, 0, 0, 100, 100)``, vectorized over an array of
  1M LineStrings.
* ``polygons``: 100k random star-shaped (mostly concave) polygons of 5-12 vertices,
  centers uniform in [-20, 120]^2, radii 2-25, against the same window (the few
  draws that shapely finds invalid are dropped from both sides).  scanline:
  ``sl.clip.polygons(vertices, window, counts=counts)`` (Sutherland-Hodgman, one
  compiled call); shapely: ``shapely.intersection(polygons, box)``, vectorized.

Fair peer setup: shapely's geometries (the LineStrings, the Polygons, the box) are
created outside the clock, as scanline's input arrays are; only the clipping is
timed.  Neither side converts its results to anything else.  Ratios are peer time /
scanline time (above 1: scanline is faster).

Run: ``python benchmarks/clip.py [--quick]`` (``--quick``: 10x fewer primitives).
"""

import argparse
import os
import sys

import numpy as np
import shapely

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402

WINDOW = (0.0, 0.0, 100.0, 100.0)


def star_polygons(rng, n):
    """Flat vertices and counts of ``n`` star-shaped polygons."""
    counts = rng.integers(5, 13, n)
    total = int(counts.sum())
    which = np.repeat(np.arange(n), counts)
    ang = rng.uniform(0, 2 * np.pi, total)
    order = np.lexsort((ang, which))
    ang = ang[order]
    rad = rng.uniform(2, 25, total)
    centers = rng.uniform(-20, 120, (n, 2))[which]
    verts = centers + np.stack([rad * np.cos(ang), rad * np.sin(ang)], axis=1)
    return np.ascontiguousarray(verts), counts


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="100k segments, 10k polygons")
    args = parser.parse_args()
    n_lines = 100_000 if args.quick else 1_000_000
    n_polys = 10_000 if args.quick else 100_000
    report = Report("clip", quick=args.quick)
    rng = np.random.default_rng(1984)

    seg = rng.uniform(-50, 150, (n_lines, 4))
    lines = shapely.linestrings(seg.reshape(-1, 2, 2))       # outside the clock
    name = f"{n_lines // 1000}k segments"
    report.add(name, "shapely", "shapely.clip_by_rect(linestrings, *window)",
               lambda: shapely.clip_by_rect(lines, *WINDOW), repeats=2, n=n_lines)
    peer = report.rows[-1]
    for method in ("cohen-sutherland", "liang-barsky", "cyrus-beck"):
        workload = f"{name} {method}"
        report.rows.append(dict(peer, workload=workload))    # the one shapely timing
        report.add(workload, "scanline", f'sl.clip.lines(segments, window, method="{method}")',
                   lambda m=method: sl.clip.lines(seg, WINDOW, method=m), n=n_lines)
        report.target(workload, "shapely", 10.0, ">= 10x faster than shapely.clip_by_rect")

    verts, counts = star_polygons(rng, n_polys)
    polys = shapely.polygons(shapely.linearrings(verts, indices=np.repeat(np.arange(n_polys),
                                                                          counts)))
    valid = shapely.is_valid(polys)       # drop the few self-touching draws, both sides
    polys = polys[valid]
    keep = np.repeat(valid, counts)
    verts, counts = np.ascontiguousarray(verts[keep]), counts[valid]
    box = shapely.box(*WINDOW)
    name = f"{n_polys // 1000}k polygons"
    report.add(name, "shapely", "shapely.intersection(polygons, box)",
               lambda: shapely.intersection(polys, box), repeats=2, n=n_polys)
    report.add(name, "scanline", "sl.clip.polygons(vertices, window, counts=counts)",
               lambda: sl.clip.polygons(verts, WINDOW, counts=counts), n=n_polys)
    report.target(name, "shapely", 5.0, ">= 5x faster than shapely.intersection")
    report.write()


if __name__ == "__main__":
    main()
