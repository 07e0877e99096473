"""Tensor-product surfaces: Bezier and B-spline patches (notes, chapter 5, Q.1 and Q.2).

A tensor-product surface blends an (m + 1) x (n + 1) net of control points with the
products of two curve bases, one per parameter:

    P(u, v) = sum_i sum_j P_ij B_i(u) C_j(v)

(Bernstein polynomials for :class:`BezierSurface`, Cox-de Boor B-spline blending
functions for :class:`BSplineSurface`; positive weights make either rational).
``net[i, j]`` is P_ij: the first index runs with u, the second with v, as in the
notes' B-spline surface formula.  (The notes' Bezier surface formula, eq. 10, pairs
its first index j with v -- a naming choice, not an error: transpose the net to
read it that way.)

Every surface evaluates points and mixed partial derivatives vectorized over
(u, v), gives unit normals S_u x S_v / |S_u x S_v| and tessellates into a triangle
mesh whose triangles wind counterclockwise seen from the normal side.  :func:`weld`
merges the coincident vertices of several meshes and :func:`obj_text` /
:func:`write_obj` export a mesh as Wavefront OBJ.

>>> import numpy as np, scanline as sl
>>> net = np.zeros((2, 2, 3)); net[1, :, 0] = 1; net[:, 1, 1] = 1
>>> s = sl.curves.BezierSurface(net)          # the unit square in the plane z = 0
>>> s.evaluate(0.25, 0.5).tolist(), s.normal(0.25, 0.5).tolist()
([0.25, 0.5, 0.0], [0.0, 0.0, 1.0])
"""

import os
from math import comb, factorial
from typing import Iterable, Optional, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from ..framebuffer import write_atomically
from .base import parameters
from .bezier import bernstein
from .bspline import basis, check_knots, open_uniform_knots

#: A normal is computed from S_u x S_v unless |S_u x S_v| is below this fraction of
#: |S_u| |S_v| (or the partials vanish): at a collapsed edge or corner (the teapot's
#: lid and bottom poles) it is the normal a tiny step inside the patch, see
#: :meth:`Surface.normal`.
DEGENERATE = 1e-10

#: The parameter step (a fraction of the domain) taken toward the patch center at a
#: degenerate point.
NUDGE = 1e-6

#: Most vertices :meth:`Surface.tessellate` builds (each costs about
#: 100 bytes with its normal and triangles): a bigger grid is refused, not a
#: MemoryError half-way.
MAX_VERTICES = 1 << 24

#: A triangle mesh: vertices (K, 3), triangles (T, 3) int64, normals (K, 3).
MeshArrays = tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.float64]]
#: Mixed partials by (order in u, order in v).
Partials = dict[tuple[int, int], NDArray[np.float64]]


def _net(name: str, value: ArrayLike, dims: tuple[int, ...] = (2, 3)) -> NDArray[np.float64]:
    """A control net as a float64 (m + 1, n + 1, dim) array of finite points."""
    try:
        a = np.array(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"{name} must be a grid of control points, an array of shape (m + 1, n + 1, 3), "
            f"got {v._show(value)}"
        ) from None
    if a.ndim != 3 or a.shape[0] < 2 or a.shape[1] < 2 or a.shape[2] not in dims:
        raise ArgumentValueError(
            f"{name} must have shape (m + 1, n + 1, 3) with m, n >= 1 (a grid of 3-D "
            f"control points; 2-D points are accepted too), got shape {a.shape}"
        )
    bad = ~np.isfinite(a)
    if bad.any():
        i, j = (int(x) for x in np.argwhere(bad)[0][:2])
        raise ArgumentValueError(f"{name} must be finite; point [{i}, {j}] is {a[i, j].tolist()}")
    return a


def _weights(name: str, value: Optional[ArrayLike], shape: tuple[int, ...]) -> Optional[NDArray[np.float64]]:
    if value is None:
        return None
    try:
        w = np.array(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"{name} must be an array of numbers, got {v._show(value)}") from None
    if w.shape != shape:
        raise ArgumentValueError(
            f"{name} must hold one weight per control point, shape {shape}, got shape {w.shape}"
        )
    if not (np.isfinite(w).all() and (w > 0).all()):
        raise ArgumentValueError(f"{name} must be finite and > 0, got {v._show(w.tolist())}")
    return w


def _order(name: str, value: object) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 0:
        raise ArgumentValueError(f"{name} must be an integer >= 0, got {v._show(value)}")
    return int(value)


class Surface:
    """A tensor-product surface P(u, v) = sum_ij H_ij B_i(u) C_j(v), projected.

    Subclasses set ``net`` (m + 1, n + 1, dim), ``weights`` (or None), ``domain``
    ((u_min, u_max), (v_min, v_max)) and implement ``_basis(axis, t, k)``: the k-th
    derivatives of the blending functions of parameter ``axis`` (0 for u, 1 for v) at
    the 1-D parameters ``t``, shape (len(t), m + 1 or n + 1).
    """

    net: NDArray[np.float64]
    weights: Optional[NDArray[np.float64]] = None
    domain: tuple[tuple[float, float], tuple[float, float]] = ((0.0, 1.0), (0.0, 1.0))

    @property
    def dimension(self) -> int:
        """Number of coordinates of each point (3, or 2 for a plane net)."""
        return int(self.net.shape[2])

    @property
    def rational(self) -> bool:
        """True if the surface has weights."""
        return self.weights is not None

    def _basis(self, axis: int, t: NDArray[np.float64], k: int) -> NDArray[np.float64]:  # pragma: no cover - abstract
        raise NotImplementedError

    def homogeneous(self) -> NDArray[np.float64]:
        """The net [w P, w] (plain surfaces: [P, 1]) as an (m + 1, n + 1, dim + 1) array."""
        w = np.ones(self.net.shape[:2]) if self.weights is None else self.weights
        return np.concatenate([self.net * w[..., None], w[..., None]], axis=2)

    # -- evaluation ---------------------------------------------------------------

    def _uv(self, u: ArrayLike, v: ArrayLike) -> tuple[tuple[int, ...], NDArray[np.float64], NDArray[np.float64]]:
        pu = parameters("u", u, self.domain[0])
        pv = parameters("v", v, self.domain[1])
        try:
            bu, bv = np.broadcast_arrays(pu, pv)
        except ValueError:
            raise ArgumentValueError(
                f"u and v must broadcast to one shape, got shapes {pu.shape} and {pv.shape}"
            ) from None
        return bu.shape, bu.ravel(), bv.ravel()

    def _raw(self, u: NDArray[np.float64], v: NDArray[np.float64], k: int, l: int, grid: bool) -> NDArray[np.float64]:
        """The (k, l) mixed partial of the numerator net (homogeneous if rational)."""
        h = self.homogeneous() if self.rational else self.net
        bu = self._basis(0, u, k)
        bv = self._basis(1, v, l)
        raw: NDArray[np.float64] = np.einsum("ai,ijc,bj->abc" if grid else "ai,ijc,aj->ac", bu, h, bv)
        return raw

    def _partials(self, u: NDArray[np.float64], v: NDArray[np.float64], k: int, l: int, grid: bool = False) -> Partials:
        """Every mixed partial (i, j) with i <= k, j <= l, as a dict.

        Rational surfaces: Leibniz's rule on A = w S (Piegl & Tiller, eq. 4.20),
        S^(k,l) = (A^(k,l) - sum_(i,j) != (0,0) C(k,i) C(l,j) w^(i,j) S^(k-i,l-j)) / w.
        """
        raw = {(i, j): self._raw(u, v, i, j, grid) for i in range(k + 1) for j in range(l + 1)}
        if not self.rational:
            return raw
        w = {key: a[..., -1:] for key, a in raw.items()}
        out: Partials = {}
        for i in range(k + 1):
            for j in range(l + 1):
                a = raw[i, j][..., :-1].copy()
                for p in range(i + 1):
                    for q in range(j + 1):
                        if p or q:
                            a -= comb(i, p) * comb(j, q) * w[p, q] * out[i - p, j - q]
                out[i, j] = a / w[0, 0]
        return out

    def evaluate(self, u: ArrayLike, v: ArrayLike) -> NDArray[np.float64]:
        """Points on the surface.

        Parameters
        ----------
        u, v : float or array_like
            Parameters inside ``domain``; broadcast against each other.

        Returns
        -------
        numpy.ndarray
            Shape ``broadcast(u, v).shape + (dimension,)``.
        """
        return self.derivative(u, v, 0, 0)

    __call__ = evaluate

    def derivative(self, u: ArrayLike, v: ArrayLike, du: int = 1, dv: int = 0) -> NDArray[np.float64]:
        """The mixed partial derivative d^(du+dv) P / du^du dv^dv at (u, v).

        ``derivative(u, v, 0, 0)`` is the point, ``(1, 0)`` is S_u, ``(0, 1)`` is S_v.
        Shapes as :meth:`evaluate`.
        """
        k, l = _order("du", du), _order("dv", dv)
        shape, pu, pv = self._uv(u, v)
        out = self._partials(pu, pv, k, l)[k, l]
        return out.reshape(shape + (self.dimension,))

    def partials(self, u: ArrayLike, v: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """(S_u, S_v), the first partial derivatives at (u, v); shapes as :meth:`evaluate`."""
        shape, pu, pv = self._uv(u, v)
        d = self._partials(pu, pv, 1, 1)
        return d[1, 0].reshape(shape + (self.dimension,)), d[0, 1].reshape(shape + (self.dimension,))

    def normal(self, u: ArrayLike, v: ArrayLike) -> NDArray[np.float64]:
        """Unit normals (S_u x S_v) / |S_u x S_v| at (u, v); 3-D surfaces only.

        Where the cross product vanishes -- a collapsed edge (all the control points of
        a boundary row equal, like the teapot's lid and bottom poles) or parallel
        partials -- the normal is taken a step of ``NUDGE`` times the domain toward the
        center of the patch, the limit normal up to O(NUDGE).
        """
        shape, pu, pv = self._uv(u, v)
        return self._normals(pu, pv, grid=False).reshape(shape + (3,))

    def _normals(self, u: NDArray[np.float64], v: NDArray[np.float64], grid: bool) -> NDArray[np.float64]:
        if self.dimension != 3:
            raise ArgumentValueError(
                f"normals need a 3-D surface; this one has {self.dimension}-D control points"
            )
        d = self._partials(u, v, 1, 1, grid)
        n = _unit_normals(d[1, 0], d[0, 1])
        bad = ~np.isfinite(n[..., 0])
        if bad.any():
            uu, vv = (np.meshgrid(u, v, indexing="ij") if grid else (u, v))
            (u0, u1), (v0, v1) = self.domain
            cu, cv = (u0 + u1) / 2, (v0 + v1) / 2
            pu = uu[bad] + NUDGE * (cu - uu[bad])
            pv = vv[bad] + NUDGE * (cv - vv[bad])
            e = self._partials(pu, pv, 1, 1)
            n[bad] = _unit_normals(e[1, 0], e[0, 1])
        return n

    def grid(self, us: ArrayLike, vs: ArrayLike) -> NDArray[np.float64]:
        """Points at every (us[a], vs[b]): shape (len(us), len(vs), dimension)."""
        pu = parameters("us", np.ravel(us), self.domain[0])
        pv = parameters("vs", np.ravel(vs), self.domain[1])
        return self._partials(pu, pv, 0, 0, grid=True)[0, 0]

    # -- meshes -------------------------------------------------------------------

    def tessellate(self, nu: int = 16, nv: int = 16) -> MeshArrays:
        """A triangle mesh of the surface on a uniform (nu x nv) grid of parameters.

        Parameters
        ----------
        nu, nv : int
            Number of intervals in u and in v (>= 1).

        Returns
        -------
        vertices : ndarray, shape ((nu + 1) (nv + 1), 3)
            The points at u_a = u_min + a (u_max - u_min) / nu, v_b likewise; vertex
            ``a * (nv + 1) + b``.
        triangles : ndarray of int64, shape (2 nu nv, 3)
            Two triangles per grid cell, (a, b) (a+1, b) (a+1, b+1) and (a, b)
            (a+1, b+1) (a, b+1): counterclockwise seen from the side the normals
            point to, so (p1 - p0) x (p2 - p0) agrees with S_u x S_v.
        normals : ndarray, shape ((nu + 1) (nv + 1), 3)
            Unit surface normals at the vertices (:meth:`normal`).

        Notes
        -----
        A collapsed edge (a pole) gives zero-area triangles; :func:`weld` merges its
        vertices and drops them.
        """
        nu = v.positive_int("nu", nu)
        nv = v.positive_int("nv", nv)
        if (nu + 1) * (nv + 1) > MAX_VERTICES:
            raise ArgumentValueError(
                f"nu={nu}, nv={nv} ask for {(nu + 1) * (nv + 1)} vertices, more than "
                f"{MAX_VERTICES}; use fewer intervals (or split the surface)")
        if self.dimension != 3:
            raise ArgumentValueError(
                f"tessellate needs a 3-D surface; this one has {self.dimension}-D control points"
            )
        us = np.linspace(*self.domain[0], nu + 1)
        vs = np.linspace(*self.domain[1], nv + 1)
        points = self._partials(us, vs, 0, 0, grid=True)[0, 0].reshape(-1, 3)
        normals = self._normals(us, vs, grid=True).reshape(-1, 3)
        return points, grid_triangles(nu, nv), normals


def _unit_normals(su: NDArray[np.float64], sv: NDArray[np.float64]) -> NDArray[np.float64]:
    """(S_u x S_v) / |S_u x S_v|, NaN rows where it is degenerate."""
    c = np.cross(su, sv)
    length = np.linalg.norm(c, axis=-1)
    scale = np.linalg.norm(su, axis=-1) * np.linalg.norm(sv, axis=-1)
    ok = length > DEGENERATE * scale
    with np.errstate(invalid="ignore", divide="ignore"):
        unit: NDArray[np.float64] = np.where(ok[..., None], c / np.where(ok, length, 1.0)[..., None], np.nan)
    return unit


def grid_triangles(nu: int, nv: int) -> NDArray[np.int64]:
    """The 2 nu nv triangles of an (nu + 1) x (nv + 1) vertex grid (see
    :meth:`Surface.tessellate`), int64 (T, 3)."""
    a, b = np.meshgrid(np.arange(nu), np.arange(nv), indexing="ij")
    v00 = (a * (nv + 1) + b).ravel()
    v10, v01 = v00 + nv + 1, v00 + 1
    v11 = v10 + 1
    first = np.stack([v00, v10, v11], axis=1)
    second = np.stack([v00, v11, v01], axis=1)
    return np.stack([first, second], axis=1).reshape(-1, 3).astype(np.int64)


class BezierSurface(Surface):
    """A Bezier surface P(u, v) = sum_i sum_j P_ij BEZ_(i,m)(u) BEZ_(j,n)(v), 0 <= u, v <= 1.

    Parameters
    ----------
    control_net : array_like, shape (m + 1, n + 1, 3)
        The control points P_ij, m, n >= 1; ``net[i, j]`` goes with BEZ_(i,m)(u) and
        BEZ_(j,n)(v).  2-D points are accepted (no normals then).
    weights : array_like, shape (m + 1, n + 1), optional
        Positive weights: the rational surface sum w_ij P_ij B B / sum w_ij B B.

    Notes
    -----
    Notes, chapter 5, Q.1, eq. 10: two sets of orthogonal Bezier curves.  The
    surface interpolates its four corner control points, lies in the convex hull of
    the net, and its boundary curves are the Bezier curves of the net's boundary
    rows; two patches that share a boundary row meet with C0 continuity (the
    notes' "matching control points at the boundary").  The k-th partial in u uses
    the Bernstein derivative d^k/du^k BEZ_(i,m) = m!/(m-k)! sum_r (-1)^(k-r) C(k,r)
    BEZ_(i-r,m-k).

    References
    ----------
    P. Bezier, *Numerical Control: Mathematics and Applications*, Wiley, 1972.
    M. E. Newell, *The utilization of procedure models in digital image synthesis*,
    PhD thesis, University of Utah, 1975 (the teapot, :func:`scanline.curves.teapot`).

    Examples
    --------
    A saddle, the hyperbolic paraboloid z = (2u - 1)(2v - 1) over the unit square:

    >>> import numpy as np, scanline as sl
    >>> net = np.array([[[x / 2, y / 2, (x - 1) * (y - 1)] for y in range(3)]
    ...                 for x in range(3)], float)
    >>> s = sl.curves.BezierSurface(net)
    >>> s.evaluate(0.75, 0.25).tolist()
    [0.75, 0.25, -0.25]
    >>> s.degree
    (2, 2)
    """

    def __init__(self, control_net: ArrayLike, weights: Optional[ArrayLike] = None) -> None:
        self.net = _net("control_net", control_net)
        self.weights = _weights("weights", weights, self.net.shape[:2])
        self.degree = (self.net.shape[0] - 1, self.net.shape[1] - 1)
        self.domain = ((0.0, 1.0), (0.0, 1.0))

    def _basis(self, axis: int, t: NDArray[np.float64], k: int) -> NDArray[np.float64]:
        n = self.degree[axis]
        if k > n:
            return np.zeros((len(t), n + 1))
        b = bernstein(n - k, t).reshape(len(t), n - k + 1)
        for _ in range(k):  # d/du BEZ_(i,p) = p (BEZ_(i-1,p-1) - BEZ_(i,p-1)), p built up
            pad = np.zeros((len(t), 1))
            b = np.hstack([pad, b]) - np.hstack([b, pad])
        return b * (factorial(n) // factorial(n - k))

    def boundary(self, which: str) -> NDArray[np.float64]:
        """The control points of a boundary curve: ``"u0"``, ``"u1"`` (u fixed, v
        running) or ``"v0"``, ``"v1"`` -- an (n + 1, dim) or (m + 1, dim) array.

        Parameters
        ----------
        which : {"u0", "u1", "v0", "v1"}
            The boundary: u = 0, u = 1, v = 0 or v = 1.

        Returns
        -------
        ndarray of float64, shape (n + 1, dim) or (m + 1, dim)
            The control points of that boundary's Bezier curve (notes, chapter 5,
            Q.1: the boundary curves are the Bezier curves of the net's boundary
            rows).

        Raises
        ------
        ArgumentValueError
            An unknown ``which``.

        Examples
        --------
        >>> import numpy as np, scanline as sl
        >>> net = np.zeros((2, 2, 3)); net[1, :, 0] = 1; net[:, 1, 1] = 1
        >>> sl.curves.BezierSurface(net).boundary("v1").tolist()
        [[0.0, 1.0, 0.0], [1.0, 1.0, 0.0]]
        """
        rows: dict[str, NDArray[np.float64]] = {"u0": self.net[0], "u1": self.net[-1],
                                                "v0": self.net[:, 0], "v1": self.net[:, -1]}
        v.choice("which", which, tuple(rows))
        return rows[which]

    def __repr__(self) -> str:
        kind = "rational " if self.rational else ""
        return f"<{kind}BezierSurface of degree {self.degree}, {self.dimension}-D>"


def _knots(name: str, value: Optional[ArrayLike], count: int, order: int) -> NDArray[np.float64]:
    """The open uniform knot vector by default, else a checked explicit one."""
    if value is None:
        return open_uniform_knots(count, order)
    try:
        return check_knots(value, count, order)
    except ArgumentValueError as e:
        raise ArgumentValueError(f"{name}: {e}") from None
    except ArgumentTypeError as e:
        raise ArgumentTypeError(f"{name}: {e}") from None


def bspline_basis(knots: ArrayLike, order: int, t: ArrayLike, k: int = 0) -> NDArray[np.float64]:
    """The k-th derivatives of the B-spline blending functions B_(i,d)(t), i = 0 .. n.

    The Cox-de Boor values of order d - k (:func:`scanline.curves.basis`), then k
    times the derivative recursion d/du B_(i,d) = (d - 1) (B_(i,d-1)/(u_(i+d-1) - u_i)
    - B_(i+1,d-1)/(u_(i+d) - u_(i+1))), a term with a zero denominator being 0.
    Returns shape (len(t), len(knots) - order).
    """
    kn = np.asarray(knots, np.float64)
    ts = np.asarray(t, np.float64).reshape(-1)
    if k >= order:
        return np.zeros((len(ts), len(kn) - order))
    b = basis(kn, order - k, ts)
    for d in range(order - k + 1, order + 1):
        i = np.arange(len(kn) - d)
        b = (d - 1) * (_ratio(b[:, :-1], kn[i + d - 1] - kn[i])
                       - _ratio(b[:, 1:], kn[i + d] - kn[i + 1]))
    return b


def _ratio(num: NDArray[np.float64], den: NDArray[np.float64]) -> NDArray[np.float64]:
    """num / den with x / 0 = 0 (the Cox-de Boor convention for repeated knots)."""
    d = np.broadcast_to(den, np.broadcast(num, den).shape)
    with np.errstate(divide="ignore", invalid="ignore"):
        q: NDArray[np.float64] = np.where(d != 0, num / np.where(d != 0, d, 1.0), 0.0)
    return q


class BSplineSurface(Surface):
    """A B-spline surface P(u, v) = sum_i sum_j P_ij B_(i,d1)(u) B_(j,d2)(v).

    Parameters
    ----------
    control_net : array_like, shape (n1 + 1, n2 + 1, 3)
        Control points P_ij; ``net[i, j]`` goes with B_(i,d1)(u) B_(j,d2)(v).
    order_u, order_v : int
        The orders d1, d2 (degree + 1), 2 <= d <= number of control points in that
        direction.
    knots_u, knots_v : array_like, optional
        Non-decreasing knot vectors of n1 + d1 + 1 and n2 + d2 + 1 values.  Default:
        open uniform, the ends repeated d times (e.g. [0, 0, 0, 0, 1, 2, 2, 2, 2] for
        d = 4, n = 4, the notes' example), so the surface interpolates the net's
        corners.
    weights : array_like, shape (n1 + 1, n2 + 1), optional
        Positive weights (a NURBS surface).

    Notes
    -----
    Notes, chapter 5, Q.2, "B-spline Surfaces": the Cartesian product of B-spline
    blending functions.  The surface is defined on the valid ranges
    [u_(d1-1), u_(n1+1)] x [v_(d2-1), v_(n2+1)] (``domain``), where the blending
    functions of each parameter sum to 1 (partition of unity).

    References
    ----------
    M. G. Cox, "The numerical evaluation of B-splines", J. Inst. Maths Applics 10,
    134-149, 1972.  C. de Boor, "On calculating with B-splines", J. Approx. Theory 6,
    50-62, 1972.  L. Piegl, W. Tiller, *The NURBS Book*, 2nd ed., Springer, 1997,
    chapter 3.

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> net = np.random.default_rng(1).random((5, 4, 3))
    >>> s = sl.curves.BSplineSurface(net, 3, 2)
    >>> s.domain
    ((0.0, 3.0), (0.0, 3.0))
    >>> bool(np.allclose(s.evaluate(0, 0), net[0, 0]))
    True
    """

    def __init__(self, control_net: ArrayLike, order_u: int, order_v: int,
                 knots_u: Optional[ArrayLike] = None, knots_v: Optional[ArrayLike] = None,
                 weights: Optional[ArrayLike] = None) -> None:
        self.net = _net("control_net", control_net)
        m, n = self.net.shape[:2]
        self.order = (v.positive_int("order_u", order_u, minimum=2),
                      v.positive_int("order_v", order_v, minimum=2))
        for name, d, count in (("order_u", self.order[0], m), ("order_v", self.order[1], n)):
            if d > count:
                raise ArgumentValueError(
                    f"{name}={d} needs at least {d} control points in that direction "
                    f"(2 <= d <= n + 1), the net has {count}"
                )
        self.knots = (_knots("knots_u", knots_u, m, self.order[0]),
                      _knots("knots_v", knots_v, n, self.order[1]))
        self.weights = _weights("weights", weights, self.net.shape[:2])
        (ku, kv), (du, dv) = self.knots, self.order
        self.domain = ((float(ku[du - 1]), float(ku[m])), (float(kv[dv - 1]), float(kv[n])))

    def _basis(self, axis: int, t: NDArray[np.float64], k: int) -> NDArray[np.float64]:
        return bspline_basis(self.knots[axis], self.order[axis], t, k)

    def __repr__(self) -> str:
        kind = "rational " if self.rational else ""
        return f"<{kind}BSplineSurface of order {self.order}, {self.dimension}-D>"


# -- meshes ---------------------------------------------------------------------------


def weld(vertices: ArrayLike, triangles: ArrayLike, normals: Optional[ArrayLike] = None,
         tolerance: float = 1e-9) -> tuple[NDArray[np.float64], NDArray[np.int64], Optional[NDArray[np.float64]]]:
    """Merge vertices closer than ``tolerance`` and drop the triangles that collapse.

    Parameters
    ----------
    vertices : ndarray, shape (K, 3)
    triangles : ndarray of int, shape (T, 3)
    normals : ndarray, shape (K, 3), optional
        Merged vertices get the normalized mean of their normals (a smooth normal
        across patch seams and at poles).
    tolerance : float
        Vertices are merged when they round to the same cell of a grid this fine
        (so two points closer than ``tolerance`` almost always merge, points farther
        than 2 ``tolerance`` apart never do).

    Returns
    -------
    vertices, triangles, normals (None if not given)
    """
    tolerance = v.number("tolerance", tolerance)
    if tolerance <= 0:
        raise ArgumentValueError(f"tolerance must be > 0, got {tolerance}")
    verts = np.asarray(vertices, np.float64)
    keys = np.floor(verts / tolerance + 0.5).astype(np.int64)
    _, first, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.ravel()
    out_v = verts[first]
    tri = inverse[np.asarray(triangles, np.int64)]
    keep = (tri[:, 0] != tri[:, 1]) & (tri[:, 1] != tri[:, 2]) & (tri[:, 0] != tri[:, 2])
    out_n: Optional[NDArray[np.float64]] = None
    if normals is not None:
        out_n = np.zeros_like(out_v)
        np.add.at(out_n, inverse, np.asarray(normals, np.float64))
        out_n /= np.linalg.norm(out_n, axis=1, keepdims=True)
    return out_v, tri[keep], out_n


def merge(meshes: Iterable[MeshArrays]) -> MeshArrays:
    """Concatenate meshes (vertices, triangles, normals) into one, indices offset."""
    verts: list[NDArray[np.float64]] = []
    tris: list[NDArray[np.int64]] = []
    norms: list[NDArray[np.float64]] = []
    offset = 0
    for vs, ts, ns in meshes:
        verts.append(vs)
        tris.append(np.asarray(ts, np.int64) + offset)
        norms.append(ns)
        offset += len(vs)
    return np.concatenate(verts), np.concatenate(tris), np.concatenate(norms)


def obj_text(vertices: ArrayLike, triangles: ArrayLike, normals: Optional[ArrayLike] = None) -> str:
    """A mesh as Wavefront OBJ text (``v``, ``vn`` and 1-based ``f`` lines).

    >>> print(obj_text([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]), end="")
    v 0 0 0
    v 1 0 0
    v 0 1 0
    f 1 2 3
    """
    vs = np.asarray(vertices, np.float64)
    ts = np.asarray(triangles, np.int64)
    if vs.ndim != 2 or vs.shape[1] != 3:
        raise ArgumentValueError(f"vertices must have shape (K, 3), got {vs.shape}")
    if ts.ndim != 2 or ts.shape[1] != 3:
        raise ArgumentValueError(f"triangles must have shape (T, 3), got {ts.shape}")
    if ts.size and (ts.min() < 0 or ts.max() >= len(vs)):
        raise ArgumentValueError(
            f"triangles must index the {len(vs)} vertices (0 .. {len(vs) - 1})"
        )
    lines = ["v %.9g %.9g %.9g" % tuple(p) for p in vs]
    f = ts + 1
    if normals is not None:
        lines += ["vn %.6g %.6g %.6g" % tuple(n) for n in np.asarray(normals, np.float64)]
        lines += ["f %d//%d %d//%d %d//%d" % (a, a, b, b, c, c) for a, b, c in f]
    else:
        lines += ["f %d %d %d" % tuple(t) for t in f]
    return "\n".join(lines) + "\n"


def write_obj(path: Union[str, "os.PathLike[str]"], vertices: ArrayLike, triangles: ArrayLike,
              normals: Optional[ArrayLike] = None) -> None:
    """Write a mesh to ``path`` as Wavefront OBJ, atomically (a failure leaves no file)."""
    text = obj_text(vertices, triangles, normals).encode("ascii")
    write_atomically(path, lambda f: f.write(text))
