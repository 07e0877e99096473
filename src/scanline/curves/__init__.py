"""Curves (notes, chapter 5): Bezier, B-spline, NURBS and Hermite-family curves.

Every curve is a :class:`Curve`: ``curve.evaluate(u)`` (or ``curve(u)``) is vectorized
over ``u`` and returns points of shape ``np.shape(u) + (dimension,)``;
``curve.derivative(k)`` is another curve; ``curve.domain`` is the parameter interval;
``curve.flatten(tolerance)`` is a polyline.

>>> import scanline as sl
>>> c = sl.curves.Bezier([(0, 0), (0, 4), (4, 4), (4, 0)])
>>> c.evaluate([0.0, 0.5, 1.0]).tolist()
[[0.0, 0.0], [2.0, 3.0], [4.0, 0.0]]
>>> c.derivative().evaluate(0.0).tolist()
[0.0, 12.0]
"""

from .base import Curve
from .bezier import Bezier, bernstein, bernstein_recursive
from .bspline import BSpline, NURBS, basis, nurbs_circle, open_uniform_knots
from .hermite import (CardinalSpline, CatmullRom, Hermite, KochanekBartels,
                      PiecewisePolynomial, hermite_blending, piecewise_bezier)
from .continuity import Join, continuity
from .matrices import bezier_matrix, bspline_matrix, cardinal_matrix, hermite_matrix
from .surfaces import BezierSurface, BSplineSurface
from .teapot import teapot, teapot_mesh

__all__ = ["Curve", "Bezier", "BSpline", "NURBS", "Hermite", "CardinalSpline", "CatmullRom",
           "KochanekBartels", "PiecewisePolynomial", "piecewise_bezier", "continuity", "Join",
           "bernstein", "bernstein_recursive", "basis", "open_uniform_knots", "nurbs_circle",
           "hermite_blending", "bezier_matrix", "bspline_matrix", "cardinal_matrix",
           "hermite_matrix", "BezierSurface", "BSplineSurface", "teapot", "teapot_mesh"]
