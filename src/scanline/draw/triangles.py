"""Triangles with depth: the scan conversion of Hearn & Baker's depth-buffer method
(section 13-3) as one batch call, with Gouraud-style color interpolation that is
correct in perspective (the kernel: :mod:`scanline._kernels.raster3d`)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Dict, Optional, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..depthbuffer import depth_argument
from ..errors import ArgumentValueError
from ._common import target

if TYPE_CHECKING:
    from .._typing import Colors
    from ..depthbuffer import DepthBuffer
    from ..framebuffer import FrameBuffer

#: Float64 kernel arrays: triangles (N, 3, 3), 1/w (N, 3), attributes (N, 3, K).
_Rows = Tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]

MODES = ("L", "RGB", "RGBA")


def _vertices(vertices: ArrayLike) -> Tuple[NDArray[np.float64], float]:
    """The (N, 3, 3) float64 kernel array of ``vertices`` and the largest magnitude
    of its values (depths included)."""
    tri = v.real_array("vertices", vertices, "(N, 3, 3)")
    if tri.size == 0:
        tri = tri.reshape(0, 3, 3)
    if tri.ndim != 3 or tri.shape[1] != 3 or tri.shape[2] not in (2, 3):
        raise ArgumentValueError(
            f"vertices must have shape (N, 3, 3): N triangles of three (x, y, depth) "
            f"device points (or (N, 3, 2) without depth), got shape {tri.shape}")
    if tri.shape[2] == 2:
        tri = np.concatenate([tri, np.zeros(tri.shape[:2] + (1,))], axis=2)
    # finite unless the extremes are not: passes over contiguous memory, no temporary
    # (the extremes are NaN where any value is)
    lo, hi = v.extremes(tri) if tri.size else (0.0, 0.0)
    if not (math.isfinite(lo) and math.isfinite(hi)):
        row = int(np.argwhere(~np.isfinite(tri).all(axis=(1, 2)))[0][0])
        raise ArgumentValueError(
            f"vertices[{row}] = {tri[row].tolist()} is not finite; give finite device "
            "coordinates (clip 3-D geometry first: sl.render does, before the divide)")
    return v.kernel_array(tri), max(hi, -lo)


def _far(tri: NDArray[np.float64], q: NDArray[np.float64],
         att: NDArray[np.float64]) -> _Rows:
    """Triangles with a vertex beyond the kernels' exact range clipped to the guard
    square in screen space (:func:`scanline.geometry.guard.triangles`) and cut into
    triangles again; depth, 1/w and the attributes times 1/w are linear on the
    screen, so they are interpolated exactly where an edge is cut (the attributes
    are divided by 1/w again afterwards).  Triangles within the range are kept as
    they are, in their order."""
    from ..geometry import guard

    xy = tri[:, :, :2]
    if max(xy.max(), -xy.min()) <= v.COORD_LIMIT:
        return tri, q, att
    if len(q) == 0:
        q = np.ones((len(tri), 3))
    far = np.abs(xy).max(axis=(1, 2)) > v.COORD_LIMIT
    rows = np.concatenate([tri, q[:, :, None], att * q[:, :, None]], axis=2)
    pieces, owner = guard.triangles(rows[far])
    keep = np.flatnonzero(~far)
    where = np.concatenate([keep, np.flatnonzero(far)[owner]])
    rows = np.concatenate([rows[keep], pieces])[np.argsort(where, kind="stable")]
    q = rows[:, :, 3]
    return (v.kernel_array(rows[:, :, :3]), v.kernel_array(q),
            v.kernel_array(rows[:, :, 4:] / q[:, :, None]))


def _inverse_w(w: Optional[ArrayLike], n: int) -> NDArray[np.float64]:
    """1/w (N, 3) for the kernels; no rows when ``w`` is None (1 everywhere)."""
    if w is None:
        return np.empty((0, 3))
    a = v.real_array("w", w, "(N, 3)")
    if a.shape != (n, 3):
        raise ArgumentValueError(f"w must have shape ({n}, 3): the clip w of each vertex, "
                                 f"got shape {a.shape}")
    if not (np.isfinite(a).all() and (a > 0).all()):
        raise ArgumentValueError("w must be finite and > 0 (the vertices in front of the "
                                 "eye: clip first)")
    return v.kernel_array(1.0 / a)


def _vertex_colors(fb: FrameBuffer, colors: Optional[Union[Colors, NDArray[np.number[Any]]]],
                   n: int) -> NDArray[np.float64]:
    """Per-vertex channel values (N, 3, C) as float64 0..255."""
    channels = fb._raster()[0].shape[2]
    if isinstance(colors, np.ndarray) and colors.dtype.kind in "fiu" and colors.ndim >= 2 \
            and colors.shape[:2] == (n, 3) and (colors.ndim == 3 or channels == 1):
        a = np.asarray(colors, np.float64).reshape(n, 3, -1)
        if channels == 1 and a.shape[2] in (3, 4):          # RGB(A) in mode L: luminance
            a = a[:, :, :3] @ np.array([[0.299], [0.587], [0.114]])
        if a.shape[2] != channels and not (channels == 4 and a.shape[2] == 3):
            raise ArgumentValueError(
                f"per-vertex colors must have {channels} channel(s) for mode {fb.mode!r}, "
                f"got shape {colors.shape}")
        lo, hi = v.extremes(a) if a.size else (0.0, 0.0)
        if not (0 <= lo and hi <= 255):                          # (NaN fails too)
            raise ArgumentValueError("per-vertex colors must be finite values in 0..255")
        if a.shape[2] == 3 and channels == 4:
            a = np.concatenate([a, np.full((n, 3, 1), 255.0)], axis=2)
        return v.kernel_array(a)
    from ._common import colors as face_colors

    per_face = face_colors(fb, "white" if colors is None else colors, n, "colors")
    per_face = np.broadcast_to(per_face, (n, channels)).astype(np.float64)
    return v.kernel_array(np.repeat(per_face[:, None, :], 3, axis=1))


#: The binned triangles: each band's triangles in drawing order, their vertices (E,
#: 3, 3), 1/w (E, 3), attributes (E, 3, K) and ids (E,), where each band starts
#: (bands + 1,) and where its tile-tested triangles start (bands,).
Bins = Tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64], NDArray[np.int64],
             NDArray[np.int64], NDArray[np.int64]]


def bin_bands(tri: NDArray[np.float64], q: NDArray[np.float64], att: NDArray[np.float64],
              ids: NDArray[np.int64], height: int, order: Optional[NDArray[np.int64]] = None,
              first: Optional[int] = None) -> Tuple[Bins, float]:
    """The (N, 3, 3) triangles with their 1/w (N, 3; or no rows: 1 everywhere),
    attributes (N, 3, K) and ids (N,; or none) binned by band of
    :data:`~scanline._kernels.raster3d.BAND` rows for
    :func:`~scanline._kernels.raster3d.raster_triangles`: ``((tri, q, att, ids,
    starts, split), area)``, where entries ``starts[b] .. starts[b + 1] - 1`` of the
    four arrays are the triangles meeting band ``b``, in drawing order (a triangle
    meeting several bands is copied into each), and ``area`` is the work estimate
    (the summed areas of their boxes).  The drawing order is ``order`` (N,), the
    triangles' numbers (default: input order); the triangles from its position
    ``first`` on (default: none) are the tile-tested ones, from ``split[b]`` in
    band ``b``.  A counting sort whose two passes run on every
    core (:func:`~scanline._kernels.raster3d.bin_count`, then
    :func:`~scanline._kernels.raster3d.bin_pack` into the slots the counts give each
    chunk).  The four arrays are kept for the calling thread
    (:func:`scanline._pool.scratch_rows`): valid until its next call."""
    from .._kernels import raster3d as k
    from .._kernels._threads import call_in_chunks
    from .._pool import scratch_rows

    n = len(tri)
    order = np.empty(0, np.int64) if order is None else order
    first = n if first is None else first
    rows: Dict[int, NDArray[np.int64]] = {}
    bands = ((height - 1) >> k.BAND_SHIFT) + 1
    parts = call_in_chunks(k.bin_count, 4 * n, n, lambda lo, hi: (
        tri, order, first, height, lo, hi, rows.setdefault(lo, np.zeros((2, bands), np.int64))))
    both = np.stack([rows[lo] for lo, _ in parts])          # (chunks, 2, bands)
    counts = both[:, 0]
    starts = np.concatenate([[0], np.cumsum(counts.sum(axis=0))])
    split = starts[1:] - both[:, 1].sum(axis=0)
    # a chunk's slot in band b: after the band's triangles of the chunks before it
    fill = {lo: starts[:-1] + np.cumsum(counts, axis=0)[i] - counts[i]
            for i, (lo, _) in enumerate(parts)}
    e = int(starts[-1])
    # kept between calls: new arrays of this size cost their page faults every call
    # (1M small triangles: 12 ms of 138 on 2 cores)
    packed = (scratch_rows("bins.tri", e, (3, 3)),
              scratch_rows("bins.q", e if len(q) else 0, (3,)),
              scratch_rows("bins.att", e, (3, att.shape[2])),
              scratch_rows("bins.ids", e if len(ids) else 0, (), np.int64))
    # flat, one row a triangle (views): a row is then one loop in the kernel
    kk = att.shape[2]
    source = (tri.reshape(n, 9), q, att.reshape(n, 3 * kk), ids, order)
    flat = (packed[0].reshape(e, 9), packed[1], packed[2].reshape(e, 3 * kk), packed[3])
    call_in_chunks(k.bin_pack, (12 + 3 * kk) * n, n,
                   lambda lo, hi: source + (height, lo, hi, fill[lo]) + flat, parts=len(parts))
    return packed + (starts, split), float(sum(a for _, a in parts))


def rasterize(width: int, height: int, tri: NDArray[np.float64], q: NDArray[np.float64],
              att: NDArray[np.float64], ids: NDArray[np.int64],
              zbuf: Optional[NDArray[np.float64]] = None, buf: Optional[NDArray[np.uint8]] = None,
              abuf: Optional[NDArray[np.float64]] = None, idbuf: Optional[NDArray[np.int32]] = None,
              floor: Optional[NDArray[np.float64]] = None, clear: bool = False,
              order: Optional[NDArray[np.int64]] = None, first: Optional[int] = None) -> None:
    """Run the triangle kernel on normalized arrays: ``q`` (N, 3) 1/w, or no rows
    for 1 everywhere; ``ids`` (N,), or none when ``buf`` is given.

    ``order`` (N,): draw the triangles in this order (their numbers), testing those
    from position ``first`` on against the tiles' depths first
    (:func:`~scanline._kernels.raster3d.behind`; default none): for an id buffer
    (``idbuf`` without ``buf``, no ``floor``) whose ``ids`` increase with the
    triangles' numbers and an ``order`` that lists each part in increasing number,
    the pixels are then those of drawing in input order (equal depths go to the
    smaller id, :func:`~scanline._kernels.raster3d.raster_entries`); a ValueError
    for another buffer, which has no ids to break ties with.

    ``buf`` given: the attributes (0..255) are rounded into its bytes; else
    ``abuf`` (H, W, K) float64 and ``idbuf`` (H, W) int32 receive the interpolated
    attributes and ``ids`` (``abuf`` None: ``idbuf`` alone; the attributes are not
    interpolated, and the work estimate does not count them).  ``zbuf`` None: no
    depth test (the input order wins);
    ``floor`` (H, W): depth peeling, only fragments behind ``floor`` and in front of
    ``zbuf`` pass; ``clear``: ``zbuf`` (and ``idbuf``) are cleared to +inf (-1) by
    the kernel first, on every core (their contents before do not matter)."""
    from .._kernels import raster3d as k
    from .._kernels._threads import call_in_bands, threads
    from .._kernels.variants import token

    n = len(tri)
    if order is not None and (idbuf is None or buf is not None or floor is not None):
        raise ValueError("a drawing order needs an id buffer to break depth ties with "
                         "(idbuf, without buf or floor)")
    bins, area = bin_bands(tri, q, att, ids, height, order, first)
    kk = att.shape[2]
    if buf is not None:
        out = token(k.COLOR)
        abuf = np.empty((1, 1, kk))
        idbuf = np.empty((1, 1), np.int32)
    elif abuf is None:
        out = token(k.IDS)
        abuf = np.empty((1, 1, kk))
        buf = np.empty((1, 1, 1), np.uint8)
    else:
        out = token(k.ATTRIBUTES)
        buf = np.empty((1, 1, 1), np.uint8)
    depth = token(k.PEEL if floor is not None else k.CLEAR_TEST if clear else k.TEST)
    if floor is None:
        floor = np.empty((1, 1))
    if zbuf is None:
        depth = token(k.NO_TEST)
        zbuf = np.empty((height, width))
    # work: the rows of each triangle's box times its width
    work = 20 * n + area * (1 + (kk if len(out) != k.IDS else 0))
    setup = (np.empty((threads(), k.SETUP_BATCH, kk + 2, 3)),
             np.empty((threads(), k.SETUP_BATCH), np.bool_),
             np.empty((threads(), 2, k.BAND), np.int64),            # one row a thread
             np.empty((threads(), ((width - 1) >> k.TILE_SHIFT) + 1)))
    call_in_bands(k.raster_triangles, work, out, depth, *bins, order is not None, zbuf, floor,
                  buf, abuf, idbuf, *setup)


def triangles(fb: FrameBuffer, vertices: ArrayLike,
              colors: Optional[Union[Colors, NDArray[np.number[Any]]]] = None,
              depth: Optional[DepthBuffer] = None, *, w: Optional[ArrayLike] = None) -> None:
    """Fill N triangles, with a depth test against ``depth``, in one compiled call.

    Parameters
    ----------
    fb : FrameBuffer
        Modes "L", "RGB" or "RGBA" (the values are stored, not blended).
    vertices : array_like, shape (N, 3, 3)
        Device x, y (pixel centers at integers, y up) and depth of each vertex.
    colors : color, list of colors, or array, optional
        One color for all (default white); one per triangle (a list of color specs,
        (N,) gray levels or an (N, 3|4) integer array); or one per vertex, an
        (N, 3) array in mode "L" or (N, 3, 3|4) in color modes, values 0..255,
        interpolated across each triangle (Gouraud's intensity interpolation).
    depth : DepthBuffer, optional
        Test and update this depth buffer: a pixel is written where the triangle's
        depth is smaller than the stored one.  None: no depth test; later triangles
        cover earlier ones (the order of the list).
    w : array_like, shape (N, 3), optional
        The homogeneous w (clip coordinates) of each vertex: colors are then
        interpolated perspective-correctly (linear in the eye's space, not on the
        screen).  Default: 1 (affine interpolation).

    Raises
    ------
    ArgumentTypeError
        When ``fb`` is not a FrameBuffer, ``depth`` not a DepthBuffer, or a colors
        array of one color per triangle does not hold integers.
    ArgumentValueError
        When ``fb``'s mode is not "L", "RGB" or "RGBA"; ``vertices`` is not (N, 3, 3)
        (or (N, 3, 2)) finite numbers; ``w`` is not (N, 3) finite values > 0;
        ``colors`` has the wrong length, channels or values outside 0..255; or
        ``depth`` is not the frame buffer's size.

    Notes
    -----
    Any finite device coordinates are drawn: a triangle reaching beyond the kernels'
    exact range (+-2**30) is first clipped to a guard square far outside the frame
    buffer, its cut edges found exactly, as the polygon fill does.
    A pixel belongs to a triangle iff its center is inside, a center exactly on an
    edge following the top-left rule of :func:`scanline.draw.polygon`: the kernel
    evaluates the same edge crossings, so a triangle covers exactly the polygon
    fill's pixels and a mesh covers each pixel once.  The depth at each pixel comes
    from the triangle's plane A x + B y + C z + D = 0, incrementally along each scan
    line, ``z' = z - A / C`` (Hearn & Baker, section 13-3); zero-area triangles
    draw nothing.

    References
    ----------
    E. Catmull, "A subdivision algorithm for computer display of curved surfaces",
    PhD thesis, University of Utah, 1974 (the depth buffer).  H. Gouraud,
    "Continuous shading of curved surfaces", IEEE Trans. Computers 20(6), 1971.
    J. F. Blinn, "Hyperbolic interpolation", IEEE CG&A 12(4), 1992.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(8, 4, mode="L")
    >>> sl.draw.triangles(fb, [[(0, 0, 0), (8, 0, 0), (0, 4, 0)]], colors=255)
    >>> print(sl.text_image(fb))
    ##------
    ####----
    ######--
    --------

    (The bottom edge lies on scan line 0: a horizontal edge with the triangle above
    it is a bottom edge, and its centers are outside, as in the polygon fill.)
    """
    target(fb)
    if fb.mode not in MODES:
        raise ArgumentValueError(
            f"sl.draw.triangles draws into modes {', '.join(MODES)}; the frame buffer is "
            f"mode {fb.mode!r} (use sl.draw.polygons for flat fills in any mode)")
    tri, extent = _vertices(vertices)
    n = len(tri)
    q = _inverse_w(w, n)
    att = _vertex_colors(fb, colors, n)
    zbuf = None if depth is None else depth_argument(fb, depth)
    if n == 0:
        return
    if extent > v.COORD_LIMIT:
        # (every value, depths included, in range is the common case: x and y alone,
        # a strided view, took six times as long to check)
        tri, q, att = _far(tri, q, att)
    buf = fb._raster()[0]
    rasterize(fb.width, fb.height, tri, q, att, np.empty(0, np.int64), zbuf=zbuf, buf=buf)
