"""Adaptive flattening: a curve becomes a polyline within a tolerance.

Raster devices draw straight segments; a curve is drawn (notes, chapter 5) by
replacing it with a polyline that stays within ``tolerance`` of it -- a quarter of
a pixel by default, in device units.

*Bezier form* (Bezier curves, rational or not; Hermite, cardinal, Catmull-Rom and
Kochanek-Bartels splines, section by section; B-splines and NURBS, cut into their
Bezier pieces): recursive subdivision at u = 1/2 by de Casteljau's algorithm until
every control point of a piece lies within ``tolerance`` of the piece's chord.  The
curve lies in the convex hull of its control points (for rational curves: of the
projected control points, the weights being positive) and the distance to a segment
is convex, so **every point of the curve is within** ``tolerance`` **of the
polyline** -- a guaranteed bound.  The polyline's vertices are points of the curve,
both ends included.

``method="wang"`` (plain, non-rational Bezier form only) cuts each piece into equal
parameter steps, as many as Wang's bound asks for (see
:func:`scanline.geometry.flatten.steps`): the same guarantee, fewer points on evenly
bent pieces (the convex-hull test is conservative there), more on pieces with one
tight turn.

*Any other curve* (anything with ``evaluate`` and ``domain``): the domain starts as 16
equal intervals and an interval is halved while one of 7 samples inside it lies
farther than ``tolerance`` from its chord.  The bound holds at the samples; a
feature narrower than an eighth of an interval could slip between them, so this
path documents its bound rather than guaranteeing it.

References
----------
P. de Casteljau, *Outillages methodes calcul*, Citroen, 1959.
J. M. Lane, R. F. Riesenfeld, "A theoretical development for the computer generation
and display of piecewise polynomial surfaces", IEEE PAMI 2(1), 35-46, 1980
(subdivision, the convex-hull flatness test).
W. Boehm, "Inserting new knots into B-spline curves", Computer-Aided Design 12(4),
199-201, 1980 (B-spline -> Bezier pieces).
"""

import math
from typing import Callable, Iterable, Literal, NoReturn, Optional, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from .base import Curve
from .bezier import Bezier as _BEZIER
from .bspline import BSpline as _BSPLINE
from .hermite import PiecewisePolynomial as _PIECEWISE

METHODS = ("subdivision", "wang")

#: Subdivision never goes deeper than this (2**-40 of the parameter range).
MAX_DEPTH = 40

#: Most points one call returns; more means the tolerance is too small for the
#: curve's size.
MAX_POINTS = 1 << 22

#: Most arithmetic steps of one subdivision call: each point of a degree-n segment
#: costs a de Casteljau split, about (n + 1)**2 steps, so a high degree lowers the
#: point budget below :data:`MAX_POINTS` (a few seconds at most).
MAX_WORK = 1 << 33

#: Generic path: initial intervals and samples per interval.
_START = 16
_SAMPLES = np.arange(1, 8) / 8.0


def tolerance_value(tolerance: float) -> float:
    """Check a flattening tolerance: a finite number > 0."""
    t = v.number("tolerance", tolerance)
    if t <= 0:
        raise ArgumentValueError(
            f"tolerance must be > 0 (the largest distance allowed between curve and "
            f"polyline, in the curve's units), got {tolerance!r}"
        )
    return t


def flatten(curve: Curve, tolerance: float = 0.25,
            method: Literal["subdivision", "wang"] = "subdivision") -> NDArray[np.float64]:
    """A polyline within ``tolerance`` of ``curve``.

    Parameters
    ----------
    curve : scanline.curves.Curve
        Any curve: Bezier (rational or not), B-spline, NURBS, Hermite-family splines
        or a curve of your own with ``evaluate`` and ``domain``.
    tolerance : float
        Largest distance from a curve point to the polyline, in the curve's
        coordinates (device units when they are device coordinates).  > 0.
    method : {"subdivision", "wang"}
        Adaptive subdivision (default) or Wang's uniform steps (plain Bezier form
        only).  See the module docstring.

    Returns
    -------
    numpy.ndarray, shape (K, dimension)
        The polyline, from the curve's first point to its last (equal for a closed
        curve), K >= 2, no two consecutive points equal.

    Notes
    -----
    Notes, chapter 5 (Bezier curves, the convex hull property).  The guaranteed
    bound and the sampled one are described in :mod:`scanline.curves.flatten`.

    Examples
    --------
    >>> import scanline as sl
    >>> c = sl.curves.Bezier([(0, 0), (0, 10), (10, 10), (10, 0)])
    >>> p = flatten(c, tolerance=0.5)
    >>> p[0].tolist(), p[-1].tolist(), len(p)
    ([0.0, 0.0], [10.0, 0.0], 9)
    >>> len(flatten(c, tolerance=0.05)) > len(p)
    True
    """
    return _flatten([curve], tolerance, method, lambda i: "curve")[0]


def flatten_all(curves: Iterable[Curve], tolerance: float = 0.25,
                method: Literal["subdivision", "wang"] = "subdivision") -> list[NDArray[np.float64]]:
    """Flatten many curves at once: a list of polylines, as :func:`flatten` gives them.

    The Bezier pieces of all curves of one degree and dimension go through one
    compiled call, so thousands of curves cost little more than their points.

    Examples
    --------
    >>> import scanline as sl
    >>> arcs = [sl.curves.Bezier([(0, 0), (5, 10), (10, 0)]),
    ...         sl.curves.BSpline([(0, 0), (5, 10), (10, 0), (15, 10)], 3)]
    >>> [len(p) for p in flatten_all(arcs, 0.25)]
    [9, 16]
    """
    if isinstance(curves, Curve) or not hasattr(curves, "__iter__"):
        raise ArgumentTypeError(
            f"curves must be a list of scanline.curves.Curve, got {type(curves).__name__}"
        )
    return _flatten(list(curves), tolerance, method, lambda i: f"curves[{i}]")


def _flatten(curves: list[Curve], tolerance: float, method: str, name: Callable[[int], str]
             ) -> list[NDArray[np.float64]]:
    tol = tolerance_value(tolerance)
    v.choice("method", method, METHODS)
    out: list[Optional[NDArray[np.float64]]] = [None] * len(curves)
    groups: dict[tuple[int, ...], list[tuple[int, NDArray[np.float64]]]] = {}
    for i, curve in enumerate(curves):
        if not isinstance(curve, Curve):
            raise ArgumentTypeError(
                f"{name(i)} must be a scanline.curves.Curve (Bezier, BSpline, ...), got "
                f"{type(curve).__name__}"
            )
        pieces, homogeneous = _pieces(curve)
        if pieces is not None:
            groups.setdefault(pieces.shape[1:] + (int(homogeneous),), []).append((i, pieces))
        elif method == "wang":
            raise ArgumentValueError(
                f"method='wang' needs a curve in Bezier form (Bezier, BSpline); "
                f"{name(i)} ({type(curve).__name__}) is flattened by method='subdivision'"
            )
        else:
            out[i] = _distinct(_sampled(curve, tol))
    for key, members in groups.items():
        segments = np.concatenate([pieces for _, pieces in members])
        if method == "wang":
            points, firsts = _wang(segments, bool(key[-1]), tol)
        else:
            points, firsts = subdivide(segments, tol, weighted=bool(key[-1]))
        sizes = np.array([len(pieces) for _, pieces in members])
        polylines = _per_curve(points, firsts[np.cumsum(sizes) - sizes])
        for (i, _), poly in zip(members, polylines):
            out[i] = poly
    return cast("list[NDArray[np.float64]]", out)


def _per_curve(points: NDArray[np.float64], starts: NDArray[np.int64]) -> list[NDArray[np.float64]]:
    """Cut the points of several curves (curve k starts at ``starts[k]``) into one
    polyline each, without repeated consecutive points (the joins of a curve's
    pieces), each at least two points."""
    keep = np.ones(len(points), bool)
    keep[1:] = (points[1:] != points[:-1]).any(axis=1)
    keep[starts] = True
    kept = points[keep]
    new_starts = (np.cumsum(keep) - 1)[starts]
    new_ends = np.append(new_starts[1:], len(kept))
    polylines = [kept[a:b] for a, b in zip(new_starts.tolist(), new_ends.tolist())]
    ends = np.append(starts[1:], len(points))
    for k in np.nonzero(new_ends - new_starts < 2)[0]:
        polylines[k] = _distinct(points[starts[k]:ends[k]])
    return polylines


def subdivide(segments: ArrayLike, tolerance: float, weighted: bool = True
              ) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Flatten Bezier segments by recursive subdivision: (S, n + 1, dim + 1) arrays of
    homogeneous control points [w x, w] with w > 0, or (S, n + 1, dim) Cartesian
    control points if not ``weighted``.

    Returns the (K, dim) points (each segment's start, then the end of each of its
    pieces) and the (S,) index of each segment's start point.
    """
    from .._kernels import flatten as k
    from .._kernels._jit import call
    from .._kernels.variants import token

    segs = np.ascontiguousarray(segments, dtype=np.float64)
    if segs.shape[1] < 2:  # degree 0: a point
        start = segs[:, 0, :-1] / segs[:, 0, -1:] if weighted else segs[:, 0]
        return start, np.arange(len(segs))
    kind = token(k.WEIGHTED if weighted else k.PLAIN)
    degree = segs.shape[1] - 1
    budget = point_budget(degree)
    if budget < 64:
        raise ArgumentValueError(
            f"a Bezier segment of degree {degree} costs about {(degree + 1) ** 2:,} steps "
            f"per point flattened; at most {MAX_WORK:,} steps are spent (degree <= "
            f"{math.isqrt(MAX_WORK // 64) - 1}); split the curve into pieces of lower degree")
    # Wang's bound on the Cartesian points (an estimate for rational segments):
    # refuse at once what is far beyond the budget, rather than after the work
    cartesian = segs[..., :-1] / segs[..., -1:] if weighted else segs
    if _wang_estimate(cartesian, tolerance) > 64 * budget:
        _too_many(tolerance, budget)
    # each segment flattens to a few dozen pieces at the usual tolerances
    points, firsts, truncated = call(k.subdivide, 100 * segs.size, segs, kind,
                                     tolerance * tolerance, MAX_DEPTH, budget)
    if truncated:
        _too_many(tolerance, budget)
    return cast("NDArray[np.float64]", points), cast("NDArray[np.int64]", firsts)


def point_budget(degree: int) -> int:
    """Most points :func:`subdivide` makes of segments of ``degree``: MAX_POINTS,
    or fewer for high degrees (:data:`MAX_WORK`)."""
    return int(min(MAX_POINTS, MAX_WORK // (degree + 1) ** 2))


def _wang_estimate(controls: NDArray[np.float64], tolerance: float) -> float:
    """Wang's number of equal steps for all the (S, n + 1, dim) segments together,
    unclipped (inf for non-finite values)."""
    n = controls.shape[1] - 1
    if n < 2:
        return float(len(controls))
    with np.errstate(all="ignore"):
        second = controls[:, :-2] - 2 * controls[:, 1:-1] + controls[:, 2:]
        worst = np.sqrt((second ** 2).sum(axis=2)).max(axis=1)
        m = np.sqrt(n * (n - 1) * worst / (8.0 * tolerance))
    total = float(np.sum(m))
    return total if total == total else math.inf


def _too_many(tolerance: float, budget: int) -> NoReturn:
    raise ArgumentValueError(
        f"tolerance={tolerance!r} is too small for a curve this large: flattening "
        f"would take more than {budget} points; use a larger tolerance")


def _wang(segments: NDArray[np.float64], weighted: bool, tolerance: float) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Wang's equal steps for each plain segment: (points, firsts) as :func:`subdivide`."""
    from ..geometry.flatten import MAX_STEPS, steps
    from .bezier import bernstein

    if weighted:
        raise ArgumentValueError(
            "method='wang' flattens plain (non-rational) curves; this one has weights; "
            "use method='subdivision'"
        )
    ctrl = segments
    n = ctrl.shape[1] - 1
    if n < 1:
        return ctrl[:, 0], np.arange(len(ctrl))
    m = steps(ctrl, tolerance) if n >= 2 else np.ones(len(ctrl), np.int64)
    if (m >= MAX_STEPS).any():
        raise ArgumentValueError(
            f"tolerance={tolerance!r} is too small for a curve this large "
            f"(more than {MAX_STEPS} steps per piece); use a larger tolerance"
        )
    firsts = np.cumsum(m + 1) - (m + 1)
    seg = np.repeat(np.arange(len(ctrl)), m + 1)
    u = (np.arange(int((m + 1).sum())) - firsts[seg]) / m[seg]
    points: NDArray[np.float64] = np.einsum("ak,akc->ac", bernstein(n, u), ctrl[seg])
    return points, firsts


def _distinct(points: NDArray[np.float64]) -> NDArray[np.float64]:
    """Drop points equal to their predecessor (segment joins); keep at least two."""
    if len(points) < 2:
        return np.vstack([points, points])[:2] if len(points) else points
    keep = np.ones(len(points), bool)
    keep[1:] = (points[1:] != points[:-1]).any(axis=1)
    out = points[keep]
    return out if len(out) >= 2 else points[[0, -1]]


# -- Bezier form of the known curve types ---------------------------------------------


def _pieces(curve: Curve) -> tuple[Optional[NDArray[np.float64]], bool]:
    """(pieces, homogeneous): the Bezier segments of ``curve``, as Cartesian control
    points (S, n + 1, dim) when it is not rational, else homogeneous; (None, False)
    for a curve without a Bezier form here.

    Bezier curves are one segment; Hermite-family curves (piecewise polynomials) are
    their sections' Bezier forms; a B-spline or NURBS of order d is cut into its
    polynomial pieces, one per non-empty knot span of the valid range (Boehm 1980:
    the pieces' control points are those of the spline with every knot raised to
    multiplicity d - 1; computed here by interpolating d points of each piece, which
    gives the same points up to rounding)."""
    if isinstance(curve, _BEZIER):
        if curve.weights is None:
            return curve.points[None], False
        return curve.homogeneous()[None], True
    if isinstance(curve, _PIECEWISE):
        return np.stack([section.points for section in curve.sections]), False
    if isinstance(curve, _BSPLINE):
        if curve.rational:
            return spline_pieces(curve.homogeneous(), curve.knots, curve.order,
                                 curve.domain), True
        return spline_pieces(curve.points, curve.knots, curve.order, curve.domain), False
    return None, False


def spline_pieces(homogeneous: NDArray[np.float64], knots: NDArray[np.float64], order: int, domain: tuple[float, float]
                  ) -> NDArray[np.float64]:
    """Bezier control points of each polynomial piece of the B-spline with control
    points ``homogeneous`` (n + 1, c) (Cartesian or [w P, w]), knot vector ``knots``
    and ``order`` d, on the non-empty knot spans inside ``domain``: (S, d, c)."""
    from .._kernels import curves as _k
    from .._kernels._jit import call
    from .bezier import bernstein

    lo, hi = domain
    breaks = np.unique(np.clip(knots, lo, hi))
    degree = order - 1
    # Chebyshev points of the first kind on [0, 1]: a well-conditioned collocation
    t = 0.5 - 0.5 * np.cos((2 * np.arange(order) + 1) * np.pi / (2 * order))
    collocation = bernstein(degree, t)  # (d, d): row s = the basis at t_s
    a, b = breaks[:-1], breaks[1:]
    u = (a[:, None] + (b - a)[:, None] * t[None, :]).ravel()
    # de Boor's algorithm: d blending functions per point, not the dense (S d, n + 1)
    # matrix of all of them (298 GiB for 10**5 control points)
    values = np.empty((len(u), homogeneous.shape[1]))
    call(_k.de_boor, len(u) * order ** 2, v.kernel_array(homogeneous), v.kernel_array(knots),
         order, v.kernel_array(u), values)
    return cast("NDArray[np.float64]",
                np.linalg.solve(collocation[None], values.reshape(len(a), order, -1)))


# -- any other curve: sampled -----------------------------------------------------------


def _segment_distance(p: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64]) -> NDArray[np.float64]:
    """Distance from points p (I, k, dim) to the segments a-b (I, dim) each."""
    ab = (b - a)[:, None, :]
    ap = p - a[:, None, :]
    len2 = (ab * ab).sum(axis=2)
    with np.errstate(invalid="ignore", divide="ignore"):
        t = np.where(len2 > 0, (ap * ab).sum(axis=2) / np.where(len2 > 0, len2, 1), 0.0)
    t = np.clip(t, 0.0, 1.0)
    return cast("NDArray[np.float64]", np.linalg.norm(ap - t[..., None] * ab, axis=2))


def _sampled(curve: Curve, tolerance: float) -> NDArray[np.float64]:
    lo, hi = curve.domain
    done: list[NDArray[np.float64]] = []
    edges = np.linspace(lo, hi, _START + 1)
    left, right = edges[:-1], edges[1:]
    for _ in range(MAX_DEPTH):
        if not len(left):
            break
        inner = left[:, None] + (right - left)[:, None] * _SAMPLES[None, :]
        ends = curve.evaluate(np.stack([left, right], axis=1))
        samples = curve.evaluate(inner)
        far = _segment_distance(samples, ends[:, 0], ends[:, 1]).max(axis=1) > tolerance
        done.append(left[~far])
        mid = (left[far] + right[far]) / 2
        left, right = np.concatenate([left[far], mid]), np.concatenate([mid, right[far]])
        if sum(len(d) for d in done) + len(left) > MAX_POINTS:
            raise ArgumentValueError(
                f"tolerance={tolerance!r} is too small for this curve: flattening would "
                f"take more than {MAX_POINTS} points; use a larger tolerance"
            )
    done.append(left)
    breaks = np.sort(np.concatenate(done + [np.array([hi])]))
    return curve.evaluate(breaks)
