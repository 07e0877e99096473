"""
Curves
======

Demo figures for curves (notes, chapter 5): de Casteljau's construction, B-spline
blending functions, Hermite-family splines and the NURBS circle."""

import numpy as np

import scanline as sl

from scanline.gallery._plot import side_by_side
from scanline.gallery.primitives import HIGHLIGHT, OCTANT_COLORS, PAPER, PIXEL, SECOND, Figure

POLYGON = "#9aa3b5"


def _markers(fb, points, color, r=3):
    sl.draw.circles(fb, np.hstack([np.round(points), np.full((len(points), 1), r)]), color=color)


def figure_de_casteljau():
    """de Casteljau's construction of a cubic Bezier curve at u = 0.5."""
    P = np.array([(20, 20), (60, 200), (250, 220), (300, 30)], float)
    curve = sl.curves.Bezier(P)
    table = sl.trace.de_casteljau(P, u=0.5)
    fb = sl.FrameBuffer(320, 240, mode="RGB", background=PAPER)
    triangle = curve.de_casteljau(0.5)
    for level, color in zip(triangle[:-1], (POLYGON, HIGHLIGHT, SECOND)):
        sl.draw.polyline(fb, level, color=color)
        _markers(fb, level, color)
    sl.draw.polyline(fb, curve.evaluate(np.linspace(0, 1, 200)), color=PIXEL, width=2)
    _markers(fb, triangle[-1], "red", r=4)
    return Figure(
        "de-casteljau", "de Casteljau's construction at u = 0.5",
        "The control polygon P0..P3 (gray) is cut at u = 0.5 on every leg (orange), the "
        "new legs again (green), and once more: the red point is P(0.5). The blue curve "
        "is the cubic Bezier curve; the first and last points of the levels are the "
        "control points of its two halves (subdivision).",
        "Notes, chapter 5, Q.1; de Casteljau 1959", fb.to_pil(), str(table))


def _plot_functions(u, values, size=(300, 150), margin=10):
    """Draw the columns of ``values`` (each a function of u, 0..1) as colored polylines."""
    fb = sl.FrameBuffer(*size, mode="RGB", background=PAPER)
    x = margin + (u - u[0]) / (u[-1] - u[0]) * (size[0] - 2 * margin)
    sl.draw.line(fb, margin, margin, size[0] - margin, margin, color=POLYGON)
    for k in range(values.shape[1]):
        y = margin + values[:, k] * (size[1] - 2 * margin)
        sl.draw.polyline(fb, np.column_stack([x, y]), color=OCTANT_COLORS[k % 8], width=2)
    return fb.to_pil()


def figure_bspline_blending():
    """Cox–de Boor blending functions: periodic quadratic and open uniform cubic."""
    periodic = np.arange(7.0)                      # n = d = 3, uniform integer knots
    u = np.linspace(0, 6, 400)
    left = _plot_functions(u, sl.curves.basis(periodic, 3, u))
    knots = [0, 0, 0, 0, 1, 2, 2, 2, 2]            # the notes' open uniform, d = 4, n = 4
    u = np.linspace(0, 2, 400)
    right = _plot_functions(u, sl.curves.basis(knots, 4, u))
    table = sl.trace.cox_de_boor(knots, 4, 1.5)
    return Figure(
        "bspline-blending", "B-spline blending functions (Cox–de Boor)",
        "Left: the periodic blending functions B_k,3 for n = d = 3 on the knots 0..6, "
        "shifted copies of one another; they sum to 1 only on the valid range [2, 4]. "
        "Right: the notes' open uniform knots [0 0 0 0 1 2 2 2 2] for d = 4, n = 4: "
        "five cubic functions summing to 1 on all of [0, 2], the first and last equal "
        "to 1 at the ends (the curve starts at P0 and ends at P4).",
        "Notes, chapter 5, Q.2; Cox 1972, de Boor 1972",
        side_by_side([left, right], ["periodic, d = 3", "open uniform, d = 4"]), str(table))


def figure_hermite_family():
    """Catmull–Rom, cardinal and Kochanek–Bartels splines through the same points."""
    P = np.array([(15, 40), (50, 180), (120, 60), (190, 200), (260, 50), (305, 160)], float)
    fb = sl.FrameBuffer(320, 240, mode="RGB", background=PAPER)
    sl.draw.polyline(fb, P, color=POLYGON, dash="dashed")
    u = np.linspace(0, 3, 300)
    for curve, color in ((sl.curves.CatmullRom(P), PIXEL),
                         (sl.curves.CardinalSpline(P, tension=0.6), HIGHLIGHT),
                         (sl.curves.KochanekBartels(P, bias=0.8), SECOND)):
        sl.draw.polyline(fb, curve.evaluate(u), color=color, width=2)
    _markers(fb, P, "black")
    return Figure(
        "hermite-splines", "Hermite-family splines through six points",
        "Each is a chain of Hermite sections P(u) = [u^3 u^2 u 1] M_H [P_k P_k+1 DP_k "
        "DP_k+1]; they differ in the tangents DP_k. Blue: Catmull-Rom, DP_k = (P_k+1 - "
        "P_k-1)/2. Orange: cardinal with tension 0.6 (shorter tangents). Green: "
        "Kochanek-Bartels with bias 0.8 (each tangent leans toward the incoming "
        "chord: overshoot after every point). The first and last points only steer "
        "the end tangents.",
        "Notes, chapter 5, Q.3; Catmull & Rom 1974, Kochanek & Bartels 1984",
        fb.to_pil(), None)


def figure_nurbs_circle():
    """The exact NURBS circle and its nine weighted control points."""
    circle = sl.curves.nurbs_circle(center=(120, 120), radius=90)
    fb = sl.FrameBuffer(240, 240, mode="RGB", background=PAPER)
    sl.draw.polyline(fb, circle.points, color=POLYGON, dash="dashed")
    sl.draw.circle(fb, 120, 120, 90, color=HIGHLIGHT)          # the midpoint circle
    sl.draw.polyline(fb, circle.evaluate(np.linspace(0, 1, 400)), color=PIXEL)
    _markers(fb, circle.points, "black")
    d = np.hypot(*(circle.evaluate(np.linspace(0, 1, 10_001)) - 120).T)
    return Figure(
        "nurbs-circle", "An exact circle as a quadratic NURBS",
        "Nine control points on a square (dashed), corner weights sqrt(2)/2, knots "
        "[0 0 0 1/4 1/4 1/2 1/2 3/4 3/4 1 1 1]. Over 10 001 parameters the distance to "
        f"the center stays within {np.abs(d - 90).max():.1e} of r = 90. Blue: the NURBS "
        "curve; orange: the midpoint circle of chapter 2 under it.",
        "Notes, chapter 5, Q.2 (rational B-splines); Piegl & Tiller 1997", fb.to_pil(), None)


FIGURES = (figure_de_casteljau, figure_bspline_blending, figure_hermite_family,
           figure_nurbs_circle)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
