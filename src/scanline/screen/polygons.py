"""Screen-space polygons: what the object-order and scan-line visible-surface methods
work on (:mod:`scanline.visible`), made from a scene by :mod:`scanline.screen.prepare`
or given by hand (:meth:`ScreenPolygons.from_device`).

A :class:`ScreenPolygons` holds convex polygons in *device space* -- x and y in pixels
of a ``width`` x ``height`` frame buffer, the depth z growing away from the viewer
(0 on the front plane, 1 on the back plane, :doc:`three-d`) -- with, for each
polygon, the source face it comes from and the plane A x + B y + C z + D = 0 of that
face in device space.  After the perspective divide every projector is parallel to
the z axis, so all methods reason about an orthographic view along +z: the viewer
is at z = -infinity (Hearn & Baker, section 13-1: "depth values ... in the normalized
coordinates"; a perspective projection maps planes to planes, so planarity and the
plane tests survive the divide).

Planes are oriented with C > 0: a point with A x + B y + C z + D > 0 lies *behind*
the plane (farther from the viewer), < 0 in front of it, and the depth of the plane
above pixel (x, y) is z = -(A x + B y + D) / C.

Object-order methods (painter, depth sort, BSP) return a :class:`ScreenPolygons`
too: the pieces in drawing order, back to front; a piece split off a face lies in
that face's plane and keeps its face index.
"""

from dataclasses import dataclass
from typing import Any, Optional, Sequence

import numpy as np
from numpy.typing import ArrayLike, DTypeLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError

#: Polygons whose projected area (in square pixels) is at most this cover no pixel
#: center robustly and are dropped (faces seen edge-on).
MIN_AREA = 1e-9


@dataclass
class ScreenPolygons:
    """Convex polygons in device space.

    Attributes
    ----------
    vertices : ndarray, shape (V, 3)
        Device x, y and depth of every vertex, polygon after polygon.
    offsets : ndarray of int64, shape (P + 1,)
        Polygon ``p`` is ``vertices[offsets[p]:offsets[p + 1]]`` (counterclockwise or
        clockwise as projected; at least three vertices).
    face : ndarray of int64, shape (P,)
        The source face of each polygon (meshes numbered one after another).
    planes : ndarray, shape (P, 4)
        (A, B, C, D) of each polygon's face in device space, C > 0.
    width, height : int
        The device the coordinates belong to.

    Parameters
    ----------
    vertices, offsets, face, planes, width, height
        The attributes above (checked by the methods that take the polygons; build
        checked ones with :meth:`from_device`).

    Examples
    --------
    >>> import scanline as sl
    >>> sp = sl.screen.ScreenPolygons.from_device(
    ...     [[(0, 0, 0.5), (4, 0, 0.5), (0, 4, 0.5)]], 8, 8)
    >>> len(sp), sp.counts.tolist(), sp.face.tolist()
    (1, [3], [0])
    """

    vertices: NDArray[np.float64]
    offsets: NDArray[np.int64]
    face: NDArray[np.int64]
    planes: NDArray[np.float64]
    width: int
    height: int

    def __len__(self) -> int:
        return len(self.offsets) - 1

    def polygon(self, p: int) -> NDArray[np.float64]:
        """The (K, 3) vertices of polygon ``p``.

        Parameters
        ----------
        p : int
            The polygon's number.

        Returns
        -------
        numpy.ndarray
            A view of its (K, 3) device vertices.

        Examples
        --------
        >>> import scanline as sl
        >>> sp = sl.screen.ScreenPolygons.from_device([[(0, 0, 1), (2, 0, 1), (0, 2, 1)]], 4, 4)
        >>> sp.polygon(0).tolist()
        [[0.0, 0.0, 1.0], [2.0, 0.0, 1.0], [0.0, 2.0, 1.0]]
        """
        return self.vertices[self.offsets[p]:self.offsets[p + 1]]

    @property
    def counts(self) -> NDArray[np.int64]:
        """The number of vertices of each polygon, (P,) int64."""
        return np.diff(self.offsets)

    def depth_at(self, p: int, x: ArrayLike, y: ArrayLike) -> Any:
        """Depth of polygon ``p``'s plane above the device point (x, y).

        Parameters
        ----------
        p : int
            The polygon's number.
        x, y : float or array_like
            Device points.

        Returns
        -------
        float or numpy.ndarray
            ``-(A x + B y + D) / C``.

        Examples
        --------
        >>> import scanline as sl
        >>> tri = [(0, 0, 0.0), (4, 0, 1.0), (0, 4, 0.0)]     # depth x / 4
        >>> sp = sl.screen.ScreenPolygons.from_device([tri], 8, 8)
        >>> float(sp.depth_at(0, 2, 1))
        0.5
        """
        a, b, c, d = self.planes[p]
        return -(a * np.asarray(x) + b * np.asarray(y) + d) / c

    def extents(self) -> NDArray[np.float64]:
        """(P, 6) rows xmin, xmax, ymin, ymax, zmin, zmax of each polygon.

        Returns
        -------
        numpy.ndarray
            float64 (P, 6).

        Examples
        --------
        >>> import scanline as sl
        >>> sp = sl.screen.ScreenPolygons.from_device([[(1, 0, 0.5), (4, 2, 0.25), (0, 3, 0.75)]], 8, 8)
        >>> sp.extents().tolist()
        [[0.0, 4.0, 0.0, 3.0, 0.25, 0.75]]
        """
        if not len(self):
            return np.empty((0, 6))
        k = self.offsets[1] - self.offsets[0]
        if len(self.vertices) == k * len(self) and (np.diff(self.offsets) == k).all():
            corners = self.vertices.reshape(len(self), k, 3)  # all of k vertices
            lo, hi = corners[:, 0].copy(), corners[:, 0].copy()  # (elementwise: numpy's
            for j in range(1, k):                           # reductions over a short
                np.minimum(lo, corners[:, j], out=lo)       # axis are slow)
                np.maximum(hi, corners[:, j], out=hi)
            return np.stack([lo[:, 0], hi[:, 0], lo[:, 1], hi[:, 1], lo[:, 2], hi[:, 2]], 1)
        starts = self.offsets[:-1]
        out = np.empty((len(self), 6))
        for axis in range(3):
            col = self.vertices[:, axis]
            out[:, 2 * axis] = np.minimum.reduceat(col, starts)
            out[:, 2 * axis + 1] = np.maximum.reduceat(col, starts)
        return out

    def subset(self, order: ArrayLike) -> "ScreenPolygons":
        """The polygons ``order`` (indices), in that order.

        Parameters
        ----------
        order : array_like of int
            Polygon numbers (repeats allowed).

        Returns
        -------
        ScreenPolygons
            Those polygons, with their faces and planes.

        Examples
        --------
        >>> import scanline as sl
        >>> a = [(0, 0, 0.5), (2, 0, 0.5), (0, 2, 0.5)]
        >>> b = [(4, 4, 0.5), (6, 4, 0.5), (4, 6, 0.5)]
        >>> sp = sl.screen.ScreenPolygons.from_device([a, b], 8, 8, faces=[7, 9])
        >>> sp.subset([1, 0]).face.tolist()
        [9, 7]
        """
        chosen = np.asarray(order, np.int64)
        counts = self.counts[chosen]
        offsets = np.concatenate([[0], np.cumsum(counts)]).astype(np.int64)
        idx = (np.repeat(self.offsets[chosen] - offsets[:-1], counts)
               + np.arange(offsets[-1])) if len(chosen) else np.empty(0, np.int64)
        return ScreenPolygons(self.vertices[idx], offsets, self.face[chosen],
                              self.planes[chosen], self.width, self.height)

    def pieces(self) -> list[tuple[NDArray[np.float64], int]]:
        """A list of ``(vertices (K, 3), face)`` pairs, in order.

        Returns
        -------
        list of (numpy.ndarray, int)
            Each polygon's vertices and face.

        Examples
        --------
        >>> import scanline as sl
        >>> sp = sl.screen.ScreenPolygons.from_device([[(0, 0, 0), (2, 0, 0), (0, 2, 0)]], 4, 4, faces=[5])
        >>> [(len(vertices), face) for vertices, face in sp.pieces()]
        [(3, 5)]
        """
        return [(self.polygon(p), int(self.face[p])) for p in range(len(self))]

    @classmethod
    def from_device(cls, polygons: Any, width: int, height: int,
                    faces: Optional[ArrayLike] = None) -> "ScreenPolygons":
        """Screen polygons from a list of (K, 3) device-space polygons (x, y, depth
        per vertex), each convex and planar; ``faces`` their face indices (default
        0, 1, 2 ...).  Polygons seen edge-on (no area) are dropped.

        Parameters
        ----------
        polygons : sequence of (K, 3) array_like, or (P, K, 3) array_like
            The polygons: device x, y and depth per vertex.
        width, height : int
            The device's size.
        faces : array_like of int, optional
            One face number per polygon.

        Returns
        -------
        ScreenPolygons
            The polygons with area, their planes oriented with C > 0.

        Raises
        ------
        ArgumentValueError
            For a polygon that is not (K, 3) with K >= 3, not finite, not planar or not
            convex, or faces that are not one integer per polygon.

        Examples
        --------
        >>> import scanline as sl
        >>> sp = sl.screen.ScreenPolygons.from_device(
        ...     [[(0, 0, 0.5), (4, 0, 0.5), (0, 4, 0.5)], [(0, 0, 0), (1, 1, 0), (2, 2, 0)]], 8, 8)
        >>> len(sp), sp.planes[0].tolist()         # the edge-on one dropped; plane z = 0.5
        (1, [0.0, 0.0, 16.0, -8.0])
        """
        w = v.positive_int("width", width)
        h = v.positive_int("height", height)
        if isinstance(polygons, (list, tuple)):
            arrays = [v.real_array(f"polygons[{i}]", p, "(K, 3)") if not (
                isinstance(p, np.ndarray) and p.dtype == np.float64) else p
                for i, p in enumerate(polygons)]
        else:
            arrays = list(v.real_array("polygons", polygons, "(P, K, 3)"))
        for i, a in enumerate(arrays):
            if a.ndim != 2 or a.shape[1] != 3 or len(a) < 3:
                raise ArgumentValueError(
                    f"polygons[{i}] must be a (K, 3) array of K >= 3 vertices (x, y, depth), "
                    f"got shape {a.shape}")
        counts = np.array([len(a) for a in arrays], np.int64)
        verts = np.concatenate(arrays).astype(np.float64) if arrays else np.empty((0, 3))
        offsets = np.zeros(len(counts) + 1, np.int64)
        np.cumsum(counts, out=offsets[1:])
        finite = np.isfinite(verts).all(axis=1)
        if not finite.all():
            i = int(np.searchsorted(offsets, np.flatnonzero(~finite)[0], side="right") - 1)
            raise ArgumentValueError(
                f"polygons[{i}] has a non-finite coordinate (NaN or inf): "
                f"{v._show(arrays[i].tolist())}; every vertex must be finite")
        if len(counts):
            with np.errstate(over="ignore", invalid="ignore"):   # huge but finite
                bent = _bent(verts, offsets, counts)
            if bent.any():
                i = int(np.flatnonzero(bent)[0])
                raise ArgumentValueError(
                    f"polygons[{i}] is not planar: {v._show(arrays[i].tolist())}; give "
                    "planar polygons (split a bent one into triangles)")
        numbers = (np.arange(len(counts), dtype=np.int64) if faces is None
                   else np.asarray(faces))
        if numbers.shape != (len(counts),) or (len(counts) and numbers.dtype.kind not in "iu"):
            raise ArgumentValueError(
                f"faces must hold one integer per polygon ({len(counts)}), got "
                f"{v._show(numbers.tolist())}")
        return _assemble(verts, counts, numbers.astype(np.int64), w, h)


def flat_polygons(vertices: ArrayLike, counts: ArrayLike, faces: ArrayLike, width: int,
                  height: int) -> ScreenPolygons:
    """:class:`ScreenPolygons` from device polygons given flat -- ``vertices`` (V, 3),
    ``counts`` (P,), ``faces`` (P,) -- that are planar by construction (clipped
    triangles): checked convex, those without area dropped, their planes found, all at
    once (:meth:`ScreenPolygons.from_device` checks each polygon's input first)."""
    return _assemble(np.ascontiguousarray(vertices, np.float64),
                     np.asarray(counts, np.int64), np.asarray(faces, np.int64),
                     v.positive_int("width", width), v.positive_int("height", height))


def newell_plane(points: NDArray[np.float64]) -> NDArray[np.float64]:
    """Newell's plane (A, B, C, D) of the (K, 3) ``points`` (Hearn & Baker, section
    10-1; exact for planar polygons).

    Parameters
    ----------
    points : numpy.ndarray
        (K, 3) vertices of a polygon.

    Returns
    -------
    numpy.ndarray
        (A, B, C, D), (A, B, C) twice the polygon's vector area.

    Examples
    --------
    >>> import numpy as np
    >>> from scanline.screen import newell_plane
    >>> newell_plane(np.array([(0, 0, 2), (1, 0, 2), (0, 1, 2)], float)).tolist()   # z = 2
    [0.0, 0.0, 1.0, -2.0]
    """
    x, y, z = points[:, 0], points[:, 1], points[:, 2]
    xn, yn, zn = np.roll(x, -1), np.roll(y, -1), np.roll(z, -1)
    a = np.sum((y - yn) * (z + zn))
    b = np.sum((z - zn) * (x + xn))
    c = np.sum((x - xn) * (y + yn))
    centroid = points.mean(axis=0)
    return np.array([a, b, c, -(a * centroid[0] + b * centroid[1] + c * centroid[2])])


def _bent(verts: NDArray[np.float64], offsets: NDArray[np.int64],
          counts: NDArray[np.int64]) -> NDArray[np.bool_]:
    """Whether each flat polygon leaves its Newell plane by more than 1e-9 of its size."""
    plane = newell_planes(verts, offsets)
    norm = np.linalg.norm(plane[:, :3], axis=1)
    owner = np.repeat(np.arange(len(counts)), counts)
    dist = np.abs(np.einsum("ij,ij->i", verts, plane[owner, :3]) + plane[owner, 3])
    size = (np.maximum.reduceat(verts, offsets[:-1], axis=0)
            - np.minimum.reduceat(verts, offsets[:-1], axis=0)).max(axis=1)
    bent: NDArray[np.bool_] = (norm > 0) & (np.maximum.reduceat(dist, offsets[:-1])
                                            > 1e-9 * norm * (size + 1.0))
    return bent


def _following(offsets: NDArray[np.int64]) -> NDArray[np.int64]:
    """For each vertex of the flat polygons ``offsets``, the index of the next vertex
    of its polygon (the last wraps to the first)."""
    nxt = np.arange(1, offsets[-1] + 1)
    nxt[offsets[1:] - 1] = offsets[:-1]
    return nxt


def newell_planes(verts: NDArray[np.float64], offsets: NDArray[np.int64]) -> NDArray[np.float64]:
    """Newell's planes (P, 4) of the flat polygons ``verts[offsets[p]:offsets[p + 1]]``
    (:func:`newell_plane` for all at once).

    Parameters
    ----------
    verts : numpy.ndarray
        (V, 3) vertices of every polygon, one after another.
    offsets : numpy.ndarray
        (P + 1,) int64: polygon ``p`` is ``verts[offsets[p]:offsets[p + 1]]``.

    Returns
    -------
    numpy.ndarray
        (P, 4) planes.

    Examples
    --------
    >>> import numpy as np
    >>> from scanline.screen import newell_planes
    >>> verts = np.array([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 0), (0, 0, 1), (0, 1, 0)], float)
    >>> (newell_planes(verts, np.array([0, 3, 6])) + 0.0).tolist()   # z = 0, then x = 0
    [[0.0, 0.0, 1.0, 0.0], [-1.0, 0.0, 0.0, 0.0]]
    """
    p, q = verts, verts[_following(offsets)]
    starts = offsets[:-1]
    # finite vertices far out (past about 1e150) overflow the products: that polygon's
    # plane is not finite, which its callers test, and numpy's warnings say nothing more
    with np.errstate(over="ignore", invalid="ignore"):
        n = np.add.reduceat(np.stack([(p[:, 1] - q[:, 1]) * (p[:, 2] + q[:, 2]),
                                      (p[:, 2] - q[:, 2]) * (p[:, 0] + q[:, 0]),
                                      (p[:, 0] - q[:, 0]) * (p[:, 1] + q[:, 1])], axis=1),
                            starts, axis=0)
        centroid = np.add.reduceat(p, starts, axis=0) / np.diff(offsets)[:, None]
        return np.concatenate([n, -np.einsum("ij,ij->i", n, centroid)[:, None]], axis=1)


def signed_areas(verts: NDArray[np.float64], offsets: NDArray[np.int64]) -> NDArray[np.float64]:
    """Signed (x, y) areas of the flat polygons (> 0 counterclockwise)."""
    q = verts[_following(offsets)]
    return 0.5 * np.add.reduceat(verts[:, 0] * q[:, 1] - q[:, 0] * verts[:, 1], offsets[:-1])


def convex(verts: NDArray[np.float64], offsets: NDArray[np.int64]) -> NDArray[np.bool_]:
    """Whether each flat polygon's (x, y) projection is convex (collinear vertices
    allowed): the turn of every pair of consecutive edges has
    one sign, within a tolerance relative to the longest edge."""
    nxt = _following(offsets)
    e = verts[nxt, :2] - verts[:, :2]
    f = e[nxt]
    cross = e[:, 0] * f[:, 1] - e[:, 1] * f[:, 0]
    tol = 1e-12 * np.maximum.reduceat(np.abs(e).max(axis=1), offsets[:-1]) ** 2
    starts = offsets[:-1]
    return ((np.minimum.reduceat(cross, starts) >= -tol)
            | (np.maximum.reduceat(cross, starts) <= tol))


def _assemble(verts: NDArray[np.float64], counts: NDArray[np.int64], faces: NDArray[np.int64],
              width: int, height: int, front_only: bool = False) -> ScreenPolygons:
    """Screen polygons from flat device polygons: those without area (and with
    ``front_only`` the clockwise ones) dropped, each checked convex, its plane oriented
    with C > 0."""
    offsets = np.zeros(len(counts) + 1, np.int64)
    np.cumsum(counts, out=offsets[1:])
    if not len(counts):
        return ScreenPolygons(np.empty((0, 3)), offsets, np.empty(0, np.int64),
                              np.empty((0, 4)), width, height)
    with np.errstate(over="ignore", invalid="ignore"):   # huge but finite coordinates
        area = signed_areas(verts, offsets)
        keep = (area > MIN_AREA) if front_only else (np.abs(area) > MIN_AREA)
        bad = keep & ~convex(verts, offsets)
        planes = newell_planes(verts, offsets)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise ArgumentValueError(
            f"polygon {i} (face {int(faces[i])}) is not convex as projected: "
            f"{v._show(verts[offsets[i]:offsets[i + 1]].tolist())}; split it into convex "
            "parts (or triangles) first")
    planes[planes[:, 2] < 0] *= -1.0
    sp = ScreenPolygons(np.ascontiguousarray(verts, np.float64), offsets,
                        np.ascontiguousarray(faces, np.int64), planes, width, height)
    return sp if keep.all() else sp.subset(np.flatnonzero(keep))


def _array(name: str, value: ArrayLike, dtype: DTypeLike,
           shape: Sequence[Optional[int]]) -> NDArray[Any]:
    """``value`` as a C-contiguous array of ``dtype`` and ``shape`` (None: any
    length), or a clear error."""
    a = np.asarray(value)
    if a.ndim != len(shape) or any(s is not None and n != s for n, s in zip(a.shape, shape)):
        want = " x ".join("n" if s is None else str(s) for s in shape)
        raise ArgumentValueError(f"polygons.{name} must have shape ({want}), got {a.shape}")
    kind = "iu" if np.dtype(dtype).kind == "i" else "iuf"
    if a.dtype.kind not in kind:
        raise ArgumentValueError(f"polygons.{name} must hold {'integers' if kind == 'iu' else 'numbers'}"
                                 f", got dtype {a.dtype}")
    return np.ascontiguousarray(a, dtype)


def as_screen(polygons: object) -> ScreenPolygons:
    """``polygons`` checked to be :class:`ScreenPolygons` that the kernels can read
    safely -- a hand-built one too: its arrays of the right shapes and types (copied
    to float64 and int64 where they are not), the offsets starting at 0, ending at the
    vertex count and rising by at least three, every coordinate finite (a plane may
    overflow, for a polygon with coordinates near the largest floats), a face per
    polygon, and the device within the coordinate range and the memory
    budget of its per-pixel buffers."""
    from ..budget import check

    if not isinstance(polygons, ScreenPolygons):
        raise ArgumentTypeError(
            "polygons must be scanline.visible.ScreenPolygons (from "
            "sl.visible.screen_polygons(meshes, camera, width, height) or "
            f"ScreenPolygons.from_device(...)), got {v._show(polygons)}")
    sp = polygons
    w = v.positive_int("polygons.width", sp.width)
    h = v.positive_int("polygons.height", sp.height)
    for name, size in (("width", w), ("height", h)):
        if size > v.COORD_LIMIT:
            raise ArgumentValueError(f"polygons.{name}={size} is larger than the limit "
                                     f"{v.COORD_LIMIT}")
    # the methods' per-pixel buffers: a polygon number and a depth, about 16 bytes
    check(16 * w * h, "polygons.width x polygons.height",
          f"a {w} x {h} device's per-pixel buffers", "use a smaller device")
    verts = _array("vertices", sp.vertices, np.float64, (None, 3))
    offsets = _array("offsets", sp.offsets, np.int64, (None,))
    if len(offsets) < 1 or offsets[0] != 0 or offsets[-1] != len(verts):
        raise ArgumentValueError(
            f"polygons.offsets must start at 0 and end at the vertex count {len(verts)}, got "
            f"{v._show(offsets[:1].tolist())} ... {v._show(offsets[-1:].tolist())}")
    counts = np.diff(offsets)
    if len(counts) and counts.min() < 3:
        i = int(np.argmin(counts))
        raise ArgumentValueError(f"polygons.offsets: polygon {i} has {int(counts[i])} "
                                 "vertices; each needs at least three (offsets rising by 3 or "
                                 "more)")
    n = len(counts)
    face = _array("face", sp.face, np.int64, (n,))
    planes = _array("planes", sp.planes, np.float64, (n, 4))
    if not np.isfinite(verts).all():
        raise ArgumentValueError("polygons.vertices must be finite (no NaN or inf): build the "
                                 "polygons with ScreenPolygons.from_device")
    if all(a is b for a, b in ((verts, sp.vertices), (offsets, sp.offsets), (face, sp.face),
                               (planes, sp.planes))) and (w, h) == (sp.width, sp.height):
        return sp
    return ScreenPolygons(verts, offsets, face, planes, w, h)
