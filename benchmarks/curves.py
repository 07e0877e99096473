"""Curve evaluation: scanline vs scipy (BPoly, BSpline) and the ``bezier`` package.

Workloads (fixed seed; parameters uniformly random in the domain, unsorted):

* ``bezier-cubic-1M``: 1 000 000 points on a 2-D cubic Bezier curve.  scanline:
  ``Bezier(P).evaluate(u)`` (de Casteljau, compiled); scipy:
  ``BPoly(P[:, None, :], [0, 1])(u)`` (Bernstein form); bezier:
  ``bezier.Curve(P.T, 3).evaluate_multi(u)`` (its Horner-type algorithm, Fortran).
* ``bspline-cubic-1M``: 1 000 000 points on a 2-D cubic B-spline with 100 control
  points and open uniform knots.  scanline: ``BSpline(P, 4).evaluate(u)`` (de Boor,
  compiled); scipy: ``scipy.interpolate.BSpline(knots, P, 3)(u)``.
* ``*-sorted``: the same with sorted parameters (a dense polyline), where scanline's
  knot-span search reuses the previous span.

The peers' objects are built outside the clock; scanline's curve is built inside it
(argument checking, and the per-span matrix form that the default method computes
once per curve).  The rows ``scanline-dc`` / ``scanline-db`` time de Casteljau's and
de Boor's algorithms (compiled) for information; the targets use the default
method (the notes' matrix form by Horner's rule).  Ratios are peer time / scanline time (above 1: scanline
is faster).

Run: ``python benchmarks/curves.py [--quick]``.
"""

import argparse
import os
import sys

import bezier
import numpy as np
from scipy.interpolate import BPoly
from scipy.interpolate import BSpline as ScipyBSpline

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import Report  # noqa: E402

import scanline as sl  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="100 000 points instead of 1M")
    args = parser.parse_args()
    n = 100_000 if args.quick else 1_000_000
    rng = np.random.default_rng(1972)
    report = Report("curves", quick=args.quick)
    label = "1M" if n == 1_000_000 else f"{n // 1000}k"

    P = rng.uniform(0, 1000, (4, 2))
    u = rng.uniform(0, 1, n)
    ours = sl.curves.Bezier(P)
    bp = BPoly(P[:, None, :], [0.0, 1.0])
    bz = bezier.Curve(np.asfortranarray(P.T), degree=3)
    np.testing.assert_allclose(ours.evaluate(u[:1000]), bp(u[:1000]), rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(ours.evaluate(u[:1000]), bz.evaluate_multi(u[:1000]).T,
                               rtol=1e-12, atol=1e-9)
    for order_name, uu in (("", u), ("-sorted", np.sort(u))):
        w = f"bezier-cubic-{label}{order_name}"
        report.add(w, "scanline", "Bezier(P).evaluate(u)",
                   lambda: sl.curves.Bezier(P).evaluate(uu), n=n)
        report.add(w, "scanline-dc", "Bezier(P).evaluate(u, method='de-casteljau')",
                   lambda: ours.evaluate(uu, method="de-casteljau"), n=n)
        report.add(w, "scipy", "BPoly(P, [0, 1])(u)", lambda: bp(uu), n=n)
        report.add(w, "bezier", "bezier.Curve(P.T, 3).evaluate_multi(u)",
                   lambda: bz.evaluate_multi(uu), n=n)
        report.target(w, "scipy", 1.0, "at least as fast as scipy")
        report.target(w, "bezier", 1.0, "at least as fast as the bezier package")

    P = rng.uniform(0, 1000, (100, 2))
    ours = sl.curves.BSpline(P, 4)
    sp = ScipyBSpline(ours.knots, P, 3)
    u = rng.uniform(*ours.domain, n)
    np.testing.assert_allclose(ours.evaluate(u[:1000]), sp(u[:1000]), rtol=1e-12, atol=1e-9)
    for order_name, uu in (("", u), ("-sorted", np.sort(u))):
        w = f"bspline-cubic-{label}{order_name}"
        report.add(w, "scanline", "BSpline(P, 4).evaluate(u)",
                   lambda: sl.curves.BSpline(P, 4).evaluate(uu), n=n)
        report.add(w, "scanline-db", "BSpline(P, 4).evaluate(u, method='de-boor')",
                   lambda: ours.evaluate(uu, method="de-boor"), n=n)
        report.add(w, "scipy", "scipy.interpolate.BSpline(t, P, 3)(u)", lambda: sp(uu), n=n)
        report.target(w, "scipy", 1.0, "at least as fast as scipy")
    report.write()


if __name__ == "__main__":
    main()
