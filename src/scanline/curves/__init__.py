"""Curves (notes, chapter 5): Bezier, B-spline, NURBS and Hermite-family curves.

Every curve is a :class:`Curve`: ``curve.evaluate(u)`` (or ``curve(u)``) is vectorized
over ``u`` and returns points of shape ``np.shape(u) + (dimension,)``;
``curve.derivative(k)`` is another curve; ``curve.domain`` is the parameter interval;
``curve.flatten(tolerance)`` is a polyline.
"""

from .base import Curve

__all__ = ["Curve"]
