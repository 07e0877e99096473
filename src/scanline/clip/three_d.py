"""Three-dimensional clipping: lines and polygons against a convex volume, and
clipping in homogeneous coordinates before the perspective divide (Hearn & Baker,
section 12-5; the kernels are in :mod:`scanline._kernels.clip3d`).

Methods, by name (``method=``):

- ``"cohen-sutherland"``: six-bit region codes, trivial accept and reject,
  intersections with one plane at a time (an endpoint moved onto a plane is put
  exactly on it and keeps that plane's bit cleared, so a segment entering through an
  edge or a corner is not sent back and forth between the two planes);
- ``"liang-barsky"``: the parametric clipper, p_k and q_k for each plane (for a box,
  p1 = -dx, q1 = x0 - xmin, ..., p6 = dz, q6 = zmax - z0);
- ``"cyrus-beck"``: the same parametric test written for any convex polyhedron
  (t = N_k . (P0 - PE_k) / -N_k . D): one code with ``"liang-barsky"`` here, since a
  plane row (a, b, c, d) gives N_k . (P - PE_k) directly.

Polygons are clipped by Sutherland-Hodgman, one plane after another.
"""

from typing import Optional, Sequence, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._typing import ClipMethod
from .._kernels import variants
from .._kernels._jit import call
from ..errors import ArgumentTypeError, ArgumentValueError
from ..transform3d.arrays import finite, real_array
from .volumes import UNIT_CUBE, Volume, volume as as_volume

#: A convex clip volume: a box (lo, hi) or a Volume.
VolumeLike = Union[tuple[Sequence[float], Sequence[float]], Volume]

METHODS = ("liang-barsky", "cohen-sutherland", "cyrus-beck")

#: Cohen-Sutherland's region code has one bit per plane, in a 64-bit integer.
MAX_CODE_PLANES = 64


def method_token(method: str, vol: Optional[Volume] = None) -> tuple[int, ...]:
    """The kernel token of a line-clipping method (for the volume ``vol``: a
    Cohen-Sutherland region code holds at most 64 planes)."""
    from .._kernels import clip3d as k

    v.choice("method", method, METHODS)
    if method == "cohen-sutherland" and vol is not None and len(vol.planes) > MAX_CODE_PLANES:
        raise ArgumentValueError(
            f"method='cohen-sutherland' takes a volume of at most {MAX_CODE_PLANES} planes "
            f"(one region-code bit each), got {len(vol.planes)}; use method='liang-barsky' "
            f"or 'cyrus-beck', which take any number")
    return tuple(variants.token(k.COHEN_SUTHERLAND if method == "cohen-sutherland" else
                          k.LIANG_BARSKY))


def _segments(name: str, segments: ArrayLike, dim: int) -> NDArray[np.float64]:
    """(N, 2 dim) float64 segments (NaN and infinities are left to the kernel, which
    rejects them: see :func:`lines3d`)."""
    a = real_array(name, segments, f"(N, {2 * dim}) or (N, 2, {dim})")
    if a.size == 0:
        a = a.reshape(0, 2 * dim)
    if a.ndim == 3 and a.shape[1:] == (2, dim):
        a = a.reshape(len(a), 2 * dim)
    if a.ndim == 1 and a.size == 2 * dim:
        a = a.reshape(1, 2 * dim)
    if a.ndim != 2 or a.shape[1] != 2 * dim:
        raise ArgumentValueError(
            f"{name} must have shape (N, {2 * dim}) or (N, 2, {dim}), got shape {a.shape}")
    return np.ascontiguousarray(a)


def _clip(segs: NDArray[np.float64], vol: Volume, method: str, dim: int) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    from .._kernels import clip3d as k

    out = np.empty_like(segs)
    accepted = np.empty(len(segs), np.bool_)
    call(k.clip_segments, 3 * len(segs) * len(vol.planes), method_token(method, vol),
         k.dim_token(dim), segs.reshape(-1), vol.planes, out.reshape(-1), accepted)
    return out, accepted


def lines3d(segments: ArrayLike, volume: VolumeLike, method: ClipMethod = "liang-barsky"
            ) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """Clip N 3-D segments against a convex volume in one compiled call.

    Parameters
    ----------
    segments : array_like, shape (N, 6) or (N, 2, 3)
        Rows (x0, y0, z0, x1, y1, z1).
    volume : (lo, hi) or Volume
        A box ((xmin, ymin, zmin), (xmax, ymax, zmax)), or a volume of
        :mod:`scanline.clip.volumes` (:func:`~scanline.clip.volumes.frustum`,
        :data:`~scanline.clip.volumes.UNIT_CUBE`,
        :func:`~scanline.clip.volumes.polyhedron`).  Closed: what touches the
        boundary is kept.
    method : {"liang-barsky", "cohen-sutherland", "cyrus-beck"}
        ``"cohen-sutherland"`` takes volumes of at most 64 planes (one region-code
        bit each).  Every method accepts a segment that enters or leaves exactly
        through an edge or a corner.  One that only touches the volume from outside
        (at an edge or a corner) is accepted as that point where its coordinates
        are exact in binary (0.5, 0.25, integers ...); where it touches, or misses,
        only by round-off it may go either way.

    Returns
    -------
    clipped : ndarray, shape (N, 6)
        The visible part of each segment, in the direction given (the segment as
        given where nothing is visible).
    accepted : ndarray of bool, shape (N,)
        Whether any part is visible.  Segments with a NaN or infinite coordinate are
        never accepted.

    Raises
    ------
    TypeError, ValueError
        Segments that are not real numbers of shape (N, 6) or (N, 2, 3), an unknown
        ``method``, or a volume that is neither a box (lo, hi) nor a Volume.

    Notes
    -----
    Hearn & Baker, section 12-5 ("clipping": region codes with six bits, the
    parametric line equations x = x1 + (x2 - x1) u, ...; the Liang-Barsky
    parameters extended to three dimensions).

    References
    ----------
    Y.-D. Liang and B. A. Barsky, "A new concept and method for line clipping", ACM
    Transactions on Graphics 3(1), 1-22, 1984.  M. Cyrus and J. Beck, "Generalized
    two- and three-dimensional clipping", Computers & Graphics 3(1), 23-28, 1978.

    Examples
    --------
    >>> import scanline as sl
    >>> out, ok = sl.clip.lines3d([(-1, 0.5, 0.5, 2, 0.5, 0.5)], ((0, 0, 0), (1, 1, 1)))
    >>> out.tolist(), ok.tolist()
    ([[0.0, 0.5, 0.5, 1.0, 0.5, 0.5]], [True])
    """
    return _clip(_segments("segments", segments, 3), as_volume(volume), method, 3)


def line3d(p0: Sequence[float], p1: Sequence[float], volume: VolumeLike,
           method: ClipMethod = "liang-barsky"
           ) -> Optional[tuple[tuple[float, ...], tuple[float, ...]]]:
    """Clip the segment from ``p0`` to ``p1`` (3-D points): the visible part as a pair
    of points ``((x0, y0, z0), (x1, y1, z1))``, or None.  See :func:`lines3d`.

    Parameters
    ----------
    p0, p1 : (float, float, float)
        The segment's ends.
    volume : (lo, hi) or Volume
        A box or a convex volume (see :func:`lines3d`).
    method : {"liang-barsky", "cohen-sutherland", "cyrus-beck"}
        The algorithm (Hearn & Baker, section 12-5).

    Returns
    -------
    ((float, float, float), (float, float, float)) or None
        The visible part, in the direction given, or None when nothing is visible.

    Raises
    ------
    TypeError, ValueError
        As :func:`lines3d`.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.clip.line3d((-1, 0, 0), (1, 0, 0), ((-0.5, -1, -1), (0.5, 1, 1)),
    ...                method="cohen-sutherland")
    ((-0.5, 0.0, 0.0), (0.5, 0.0, 0.0))
    """
    from ..transform3d.arrays import vector

    seg = [vector("p0", p0) + vector("p1", p1)]
    out, ok = lines3d(seg, volume, method)
    if not ok[0]:
        return None
    r = out[0].tolist()
    return tuple(r[:3]), tuple(r[3:])


def homogeneous(segments: ArrayLike, volume: VolumeLike = UNIT_CUBE,
                method: ClipMethod = "liang-barsky") -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """Clip segments given in homogeneous coordinates before the perspective divide.

    Each endpoint is (x, y, z, w) -- clip coordinates such as
    ``camera.to_clip(points)`` gives.  The default volume is the unit cube of
    normalized device coordinates, 0 <= x <= w, 0 <= y <= w, 0 <= z <= w; its planes
    are linear in (x, y, z, w), so a segment is clipped exactly where it leaves the
    view volume even when it passes through the eye's plane (w = 0) or ends behind
    the eye (w < 0): the part behind is cut off, never mirrored in front of the
    viewer or sent to infinity, which is what dividing first would do.

    Parameters
    ----------
    segments : array_like, shape (N, 8) or (N, 2, 4)
        Rows of two endpoints (x, y, z, w).
    volume : Volume
        Planes acting on (x, y, z, w).
    method : {"liang-barsky", "cohen-sutherland", "cyrus-beck"}
        The algorithm.

    Returns
    -------
    clipped : ndarray, shape (N, 2, 4)
        Still homogeneous (divide by w for NDC; every accepted endpoint has w > 0
        for the unit cube of a perspective camera).
    accepted : ndarray of bool, shape (N,)
        Whether any part is visible.

    Raises
    ------
    TypeError, ValueError
        As :func:`lines3d`.

    References
    ----------
    J. F. Blinn and M. E. Newell, "Clipping using homogeneous coordinates",
    SIGGRAPH '78, 245-251, 1978.  Hearn & Baker, section 12-5 ("clipping in
    homogeneous coordinates").

    Examples
    --------
    A segment from in front of the eye (w = 2) to behind it (w = -2):

    >>> import scanline as sl
    >>> out, ok = sl.clip.homogeneous([[(1, 1, 1, 2), (1, 1, -3, -2)]])
    >>> out[0].tolist(), ok.tolist()
    ([[1.0, 1.0, 1.0, 2.0], [1.0, 1.0, 0.0, 1.0]], [True])

    It leaves the cube where z/w reaches 0, at t = 1/4; the part behind the eye is
    gone.
    """
    segs = _segments("segments", segments, 4)
    out, ok = _clip(segs, as_volume(volume), method, 4)
    return out.reshape(-1, 2, 4), ok


def _polygon_batch(name: str, polygons: object, counts: Optional[ArrayLike], columns: int
                   ) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """``(verts (V, C), counts (P,))`` from a list of (K_i, C) polygons or the flat
    form with ``counts``."""
    if counts is None:
        if not isinstance(polygons, (list, tuple)):
            polys = real_array(name, polygons, f"(P, K, {columns}) or a list of (K, C)")
            if polys.ndim != 3:
                raise ArgumentValueError(
                    f"{name} must be a list of (K, C) polygons or a (P, K, C) array, got "
                    f"shape {polys.shape}")
            polygons = list(polys)
        assert isinstance(polygons, (list, tuple))
        parts = [real_array(f"{name}[{i}]", p, f"(K, {columns})") for i, p in enumerate(polygons)]
        for i, p in enumerate(parts):
            if p.ndim != 2 or p.shape[1] < columns or p.shape[1] != parts[0].shape[1]:
                raise ArgumentValueError(
                    f"{name}[{i}] must have shape (K, C) with C >= {columns} columns, the same "
                    f"C for every polygon; got shape {p.shape}")
        width = parts[0].shape[1] if parts else columns
        verts = np.concatenate(parts) if parts else np.empty((0, width))
        n = np.array([len(p) for p in parts], np.int64)
    else:
        verts = real_array(name, polygons, f"(V, {columns}+)")
        if verts.ndim != 2 or verts.shape[1] < columns:
            raise ArgumentValueError(f"{name} must have shape (V, C), C >= {columns}, got "
                                     f"shape {verts.shape}")
        n, _ = v.counts("counts", counts, len(verts), name)
    return np.ascontiguousarray(verts), np.ascontiguousarray(n)


def polygons3d(polygons: Union[ArrayLike, Sequence[ArrayLike]], volume: VolumeLike, counts: Optional[ArrayLike] = None,
               homogeneous: bool = False) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Clip P polygons against a convex volume by Sutherland-Hodgman, in one
    compiled call.

    Parameters
    ----------
    polygons : list of (K_i, C) array_like, or (V, C) with ``counts``
        Vertex rows: (x, y, z) -- or (x, y, z, w) with ``homogeneous=True`` -- followed
        by any attribute columns (colors, normals, texture coordinates, depths ...),
        which are interpolated linearly with the position at every crossing.
    volume : (lo, hi) or Volume
        A box or a convex volume (see :func:`lines3d`).
    counts : array_like of int, optional
        Vertices per polygon, for the flat form.
    homogeneous : bool
        The first four columns are homogeneous clip coordinates (default volume
        then: clip against :data:`~scanline.clip.volumes.UNIT_CUBE`, 0 <= x, y, z
        <= w, before the divide).

    Returns
    -------
    vertices : ndarray, shape (V', C)
    counts : ndarray of int64, shape (P,)
        The vertices of each clipped polygon, one after another (0 where nothing is
        left: fewer than three vertices).

    Raises
    ------
    TypeError, ValueError
        Polygons that are not real arrays of at least 3 (or 4) columns, the same
        for every polygon, attributes that are not finite, counts that do not add
        up, or a volume that is neither a box nor a Volume.

    Notes
    -----
    Hearn & Baker, section 12-5, and section 6-8 for the two-dimensional algorithm:
    each plane in turn, and for each polygon edge S -> P: both inside, output P;
    leaving, output the intersection; entering, the intersection and P; both
    outside, nothing.  A convex polygon stays one convex polygon; a concave one may
    gain edges along the volume's faces.

    References
    ----------
    I. E. Sutherland and G. W. Hodgman, "Reentrant polygon clipping",
    Communications of the ACM 17(1), 32-42, 1974.

    Examples
    --------
    Two triangles against the unit cube: the first covers the whole square
    0 <= x, y <= 1 of the plane z = 0.5 (its hypotenuse x + y = 2 only touches the
    corner (1, 1)), so it is cut to that square; the second lies outside:

    >>> import scanline as sl
    >>> verts, counts = sl.clip.polygons3d(
    ...     [[(0, 0, 0.5), (2, 0, 0.5), (0, 2, 0.5)], [(3, 3, 3), (4, 3, 3), (3, 4, 3)]],
    ...     sl.clip.UNIT_CUBE)
    >>> counts.tolist(), verts.tolist()
    ([4, 0], [[0.0, 1.0, 0.5], [0.0, 0.0, 0.5], [1.0, 0.0, 0.5], [1.0, 1.0, 0.5]])
    """
    from .._kernels import clip3d as k

    dim = 4 if homogeneous else 3
    verts, counts = _polygon_batch("polygons", polygons, counts, dim)
    finite("polygons", verts[:, dim:])  # attributes must be finite; positions may not be
    vol = as_volume(volume)
    most = int(counts.max()) if len(counts) else 0
    cap = most + len(vol.planes) + 1
    scratch = np.empty((2, cap, verts.shape[1]))
    out = np.empty((int(counts.sum()) + len(counts) * len(vol.planes), verts.shape[1]))
    out_counts = np.zeros(len(counts), np.int64)
    used: int = call(k.clip_polygons, 3 * len(verts) * len(vol.planes), k.dim_token(dim), verts,
                counts, vol.planes, out, out_counts, scratch)
    if used < 0:                                  # cannot happen with these sizes
        raise ArgumentValueError("polygons: internal buffer too small")
    return out[:used].copy(), out_counts


def polygon3d(points: ArrayLike, volume: VolumeLike, homogeneous: bool = False) -> NDArray[np.float64]:
    """Clip one polygon (K, C): the clipped vertices (M, C), M = 0 when nothing is
    left.  See :func:`polygons3d`.

    Parameters
    ----------
    points : array_like, shape (K, C)
        Vertex rows (x, y, z) -- or (x, y, z, w) with ``homogeneous`` -- and any
        attribute columns.
    volume : (lo, hi) or Volume
        A box or a convex volume.
    homogeneous : bool
        The first four columns are homogeneous clip coordinates.

    Returns
    -------
    ndarray of float64, shape (M, C)
        The clipped polygon (Sutherland-Hodgman, Hearn & Baker, section 12-5).

    Raises
    ------
    TypeError, ValueError
        As :func:`polygons3d`; an empty polygon.

    Examples
    --------
    >>> import scanline as sl

    A triangle in the plane z = 0.5 that covers the strip 0.5 <= y <= 1 of the unit
    cube's cross-section:

    >>> sl.clip.polygon3d([(-1, 0.5, 0.5), (2, 0.5, 0.5), (0.5, 2, 0.5)],
    ...                   ((0, 0, 0), (1, 1, 1))).tolist()
    [[0.0, 1.0, 0.5], [0.0, 0.5, 0.5], [1.0, 0.5, 0.5], [1.0, 1.0, 0.5]]
    """
    if isinstance(points, (list, tuple)) and not points:
        raise ArgumentTypeError("points must be a polygon of at least three vertices")
    verts, counts = polygons3d([points], volume, homogeneous=homogeneous)
    return verts
