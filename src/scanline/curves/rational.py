"""Derivatives of rational curves (rational Bezier, NURBS).

A rational curve is C(u) = A(u) / w(u), where [A, w] is a polynomial (non-rational)
curve in homogeneous coordinates, one dimension higher.  Leibniz's rule on A = w·C gives
C⁽ᵏ⁾ = (A⁽ᵏ⁾ − Σᵢ₌₁ᵏ C(k, i) w⁽ⁱ⁾ C⁽ᵏ⁻ⁱ⁾) / w (Piegl & Tiller, *The NURBS Book*, eq. 4.8).
"""

from math import comb
from typing import Optional

import numpy as np
from numpy.typing import NDArray

from .base import Curve


class Weighted:
    """Mixin of curves with control ``points`` and optional ``weights``."""

    points: NDArray[np.float64]
    weights: Optional[NDArray[np.float64]]

    @property
    def rational(self) -> bool:
        """True if the curve has weights (a rational curve)."""
        return self.weights is not None

    def homogeneous(self) -> NDArray[np.float64]:
        """Control points [wₖPₖ, wₖ] (plain curves: [Pₖ, 1]), shape (n + 1, dim + 1)."""
        w = np.ones(len(self.points)) if self.weights is None else self.weights
        return np.hstack([self.points * w[:, None], w[:, None]])


def project(homogeneous: NDArray[np.float64]) -> NDArray[np.float64]:
    """Points (..., dim + 1) in homogeneous coordinates -> (..., dim) Cartesian points."""
    return homogeneous[..., :-1] / homogeneous[..., -1:]


class RationalDerivative(Curve):
    """The k-th derivative of the rational curve whose homogeneous form is ``homogeneous``."""

    def __init__(self, homogeneous: Curve, k: int) -> None:
        self.homogeneous = homogeneous
        self.k = k
        self.domain = homogeneous.domain
        self.dimension = homogeneous.dimension - 1

    def _evaluate(self, u: NDArray[np.float64]) -> NDArray[np.float64]:
        h = [self.homogeneous.derivative(j)._evaluate(u) for j in range(self.k + 1)]
        w = h[0][:, -1:]
        c = [h[0][:, :-1] / w]
        for k in range(1, self.k + 1):
            a = h[k][:, :-1].copy()
            for i in range(1, k + 1):
                a -= comb(k, i) * h[i][:, -1:] * c[k - i]
            c.append(a / w)
        return np.ascontiguousarray(c[self.k])

    def _derivative(self) -> Curve:
        return RationalDerivative(self.homogeneous, self.k + 1)
