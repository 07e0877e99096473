"""The screen-space scene: what the preparation makes (:func:`scanline.screen.prepare`)
and every visible-surface method and the shading take.

Three kinds of things are numbered in it:

* **faces** (F): the meshes' faces, mesh after mesh -- what a user knows and what
  :class:`scanline.rendering.Rendering` reports;
* **facets** (G): the triangles of each face's fan (:mod:`scanline.screen.meshes`):
  the unit of visibility and of interpolation (a facet is planar, and its
  barycentric coordinates interpolate the face's attributes);
* **triangles** (T): the device triangles left after clipping; a facet the view
  volume cuts becomes a convex polygon, cut again into a fan.  Each knows its
  facet.
"""

import functools
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Optional, Tuple, Union, overload

import numpy as np
from numpy.typing import NDArray

from .polygons import ScreenPolygons, flat_polygons

if TYPE_CHECKING:
    from ..lighting.material import Material
    from ..lighting.model import ViewerAtInfinity
    from ..projection.camera import Camera

F64 = NDArray[np.float64]
I64 = NDArray[np.int64]
Bools = NDArray[np.bool_]


class DevicePolygons(Sequence[F64]):
    """The clipped device polygons (k, 3) of a scene's facets, made on demand: the
    facets left whole are rows of one (W, 3, 3) array (no list of W arrays is built
    unless asked for), followed by the polygons of the facets the volume cut.

    Parameters
    ----------
    whole : numpy.ndarray
        (W, 3, 3): the device triangles (x, y, depth) of the facets left whole.
    cut : sequence of numpy.ndarray
        The (k, 3) device polygons of the facets the view volume cut.

    Examples
    --------
    >>> import numpy as np
    >>> from scanline.screen import DevicePolygons
    >>> whole = np.zeros((2, 3, 3))
    >>> polygons = DevicePolygons(whole, [np.ones((4, 3))])
    >>> len(polygons), polygons[-1].shape, [p.shape for p in polygons[:2]]
    (3, (4, 3), [(3, 3), (3, 3)])
    """

    def __init__(self, whole: F64, cut: Sequence[F64]) -> None:
        self._whole = whole
        self._cut = cut

    def __len__(self) -> int:
        return len(self._whole) + len(self._cut)

    @overload
    def __getitem__(self, i: int) -> F64: ...

    @overload
    def __getitem__(self, i: slice) -> list[F64]: ...

    def __getitem__(self, i: Union[int, slice]) -> Union[F64, list[F64]]:
        if isinstance(i, slice):
            return [self[j] for j in range(*i.indices(len(self)))]
        n = len(self)
        if not -n <= i < n:
            raise IndexError(f"polygon index {i} out of range for {n} polygons")
        i %= n
        return self._whole[i] if i < len(self._whole) else self._cut[i - len(self._whole)]

    def flat(self) -> Tuple[F64, I64]:
        """All the polygons at once: ``(vertices (V, 3), counts (P,))``, in order.

        Returns
        -------
        tuple of numpy.ndarray
            float64 (V, 3) vertices, polygon after polygon, and int64 (P,) counts.

        Examples
        --------
        >>> import numpy as np
        >>> from scanline.screen import DevicePolygons
        >>> vertices, counts = DevicePolygons(np.zeros((2, 3, 3)), [np.ones((4, 3))]).flat()
        >>> vertices.shape, counts.tolist()
        ((10, 3), [3, 3, 4])
        """
        whole = np.asarray(self._whole, np.float64).reshape(-1, 3)
        cut = [np.asarray(p, np.float64) for p in self._cut]
        counts = np.concatenate([np.full(len(self._whole), 3, np.int64),
                                 np.array([len(p) for p in cut], np.int64)])
        return np.concatenate([whole] + cut) if cut else whole, counts


@dataclass(frozen=True, eq=False)
class ScreenScene:
    """Meshes seen by a camera on a ``width`` x ``height`` device, ready for the
    visible-surface methods.

    Device coordinates: x, y in pixels (centers at integers, y up), depth the NDC
    depth in the camera's viewport range (0 front, 1 back by default).

    Attributes
    ----------
    width, height : int
    camera : Camera
    mapping : (clip (4, 4), scale (3,), offset (3,))
        World to homogeneous clip coordinates, and NDC to device: device = NDC *
        scale + offset per axis.
    eye : 3-vector or ViewerAtInfinity
        The viewer, for the illumination model.
    materials : tuple of Material
        One per mesh.
    face_mesh : ndarray of int64 (F,)
        The mesh (index into the meshes and ``materials``) of each face.
    face_normals, face_centroids : ndarray (F, 3)
        Each face's unit Newell normal and the mean of its vertices (world): where
        constant shading evaluates the illumination model (Hearn & Baker 14-5).
    face_colors : ndarray (F, 3)
        Each face's color S_d, stored values / 255.
    face_planar : ndarray of bool (F,)
        Faces whose vertices lie in one plane and that are convex there.
    facet_face : ndarray of int64 (G,)
        The face of each facet.
    whole : ndarray of bool (G,)
        Facets kept (not culled, not degenerate) that the view volume did not cut: one
        device triangle each.
    world : ndarray (G, 3, 3)
        World coordinates of each facet's vertices.
    normals : ndarray (G, 3)
        Unit outward facet normals (world).
    vertex_normals : ndarray (G, 3, 3)
        Unit normals at each facet's vertices: the mesh's own, else averaged over the
        faces sharing the vertex (Gouraud).
    vertex_colors : ndarray (G, 3, 3)
        Surface color S_d at each facet vertex, stored values / 255.
    front : ndarray of bool (G,)
        The back-face test (Hearn & Baker 13-2): True where the outward normal points
        toward the viewer (V . N < 0).
    culled : ndarray of bool (G,)
        Facets dropped by back-face culling.
    planes : ndarray (G, 4)
        A, B, C, D of each facet's plane in device space (A x + B y + C z + D = 0, C >
        0 for a front facet), NaN for a facet nothing is left of.
    triangles : ndarray (T, 3, 3)
        Device x, y, depth of each vertex of each device triangle.
    inv_w : ndarray (T, 3)
        1 / w of each vertex (w the homogeneous clip coordinate), for perspective-
        correct interpolation.
    bary : ndarray (T, 3, 2)
        Each vertex's barycentric coordinates (lambda_1, lambda_2) in its facet
        (lambda_0 = 1 - lambda_1 - lambda_2).
    facet : ndarray of int64 (T,)
        The facet of each device triangle.
    polygons : DevicePolygons
        The clipped device polygon (x, y, depth) of each facet left, one per entry of
        ``polygon_facet`` (convex).
    polygon_facet : ndarray of int64 (P,)
    uv : ndarray (G, 3, 2) or None
        The texture coordinates (u, v) at each facet's vertices (Hearn & Baker 14-9;
        NaN for the facets of a mesh without them); None when no mesh has them.

    The per-mesh arrays (``world``, ``normals``, ``vertex_normals`` ...) may be
    shared with the meshes' kept arrays and with other scenes: read them, do not
    write them.

    Parameters
    ----------
    width, height, camera, mapping, eye, materials, face_mesh, face_normals
        The attributes above, in this order (:func:`scanline.screen.prepare` makes
        the scene; a hand-made one is not checked).
    face_centroids, face_colors, face_planar, facet_face, whole, world, normals
        The attributes above.
    vertex_normals, vertex_colors, front, culled, planes, triangles, inv_w, bary
        The attributes above.
    facet, polygons, polygon_facet, uv
        The attributes above.

    Examples
    --------
    >>> import scanline as sl
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
    >>> scene = sl.screen.prepare(sl.mesh.cube(), cam, 16, 16)
    >>> scene.face_count, scene.facet_count, int(scene.front.sum())   # one face seen
    (6, 12, 2)
    """
    width: int
    height: int
    camera: "Camera"
    mapping: Tuple[F64, F64, F64]
    eye: Union[NDArray[np.float64], "ViewerAtInfinity"]
    materials: Tuple["Material", ...]
    face_mesh: I64
    face_normals: F64
    face_centroids: F64
    face_colors: F64
    face_planar: Bools
    facet_face: I64
    whole: Bools
    world: F64
    normals: F64
    vertex_normals: F64
    vertex_colors: F64
    front: Bools
    culled: Bools
    planes: F64
    triangles: F64
    inv_w: F64
    bary: F64
    facet: I64
    polygons: DevicePolygons
    polygon_facet: I64
    uv: Optional[F64] = None

    @property
    def face_count(self) -> int:
        """F, the number of faces."""
        return len(self.face_mesh)

    @property
    def facet_count(self) -> int:
        """G, the number of facets."""
        return len(self.facet_face)

    @functools.cached_property
    def facet_mesh(self) -> I64:
        """The mesh of each facet (G,)."""
        return np.ascontiguousarray(self.face_mesh[self.facet_face])

    @functools.cached_property
    def face_first(self) -> Tuple[I64, I64]:
        """The first facet of each face (F,) and the number of its facets (F,)."""
        counts = np.bincount(self.facet_face, minlength=self.face_count)
        return (np.cumsum(counts) - counts).astype(np.int64), counts

    @functools.cached_property
    def joined(self) -> Bools:
        """Per facet: True where its face is taken whole as one polygon by the polygon
        methods (:attr:`units`): a planar convex face whose facets were all kept and none
        cut (so it lies in front of the eye and projects to a convex polygon).  Such a
        face's polygon is labeled with its first facet; :attr:`fans` says how many
        facets it covers."""
        if not self.face_count:
            return np.zeros(self.facet_count, bool)
        first, _ = self.face_first
        out: Bools = np.logical_and.reduceat(self.whole, first) & self.face_planar
        return out[self.facet_face]

    def _face_vertices(self, faces: I64, points: F64, rows: I64) -> Tuple[F64, I64]:
        """The vertices of ``faces`` (whole ones) from their facets' corners: the first
        facet's corners 0 and 1, then corner 1 of each next facet, then corner 2 of the
        last (the fan's order).  ``points[rows[g]]`` holds facet g's corners (device
        triangles, or world facets).  Returns ``(vertices, offsets)``."""
        first, counts = self.face_first
        n = counts[faces]
        k = n + 2
        offsets = np.zeros(len(faces) + 1, np.int64)
        np.cumsum(k, out=offsets[1:])
        owner = np.repeat(np.arange(len(faces)), k)
        pos = np.arange(offsets[-1]) - offsets[:-1][owner]
        facet = first[faces][owner] + np.clip(pos - 1, 0, n[owner] - 1)
        corner = np.where(pos == 0, 0, np.where(pos == k[owner] - 1, 2, 1))
        return points[rows[facet], corner], offsets

    @functools.cached_property
    def units(self) -> Tuple[F64, F64, I64, I64, I64]:
        """The polygons the polygon methods work on: ``(device (V, 3), world (V', 3),
        counts (P,), world counts (P,), labels (P,))``.  A face taken whole
        (:attr:`joined`) is one polygon labeled with its first facet; every other
        facet left is its own (the device polygon the volume clipped, the world
        triangle), labeled with itself.  Taking quadrilaterals whole halves the
        polygons a sphere or a torus gives the depth sort."""
        first, counts = self.face_first
        faces = np.flatnonzero(self.joined[first]) if self.face_count else np.zeros(0, int)
        dev, off = self._face_vertices(faces, self.triangles, self.facet_triangle)
        world, _ = self._face_vertices(faces, self.world, np.arange(self.facet_count))
        rest = np.flatnonzero(~self.joined[self.polygon_facet])
        polys = [self.polygons[int(i)] for i in rest] if len(rest) < len(self.polygon_facet) \
            else list(self.polygons)
        counts_rest = np.array([len(p) for p in polys], np.int64)
        facets = self.polygon_facet[rest]
        device = np.concatenate([dev] + [np.asarray(p, np.float64) for p in polys]) \
            if polys else dev
        return (device, np.concatenate([world, self.world[facets].reshape(-1, 3)]),
                np.concatenate([np.diff(off), counts_rest]),
                np.concatenate([np.diff(off), np.full(len(facets), 3, np.int64)]),
                np.concatenate([first[faces], facets]).astype(np.int64))

    @functools.cached_property
    def screen_polygons(self) -> ScreenPolygons:
        """The polygon methods' :attr:`units` as :class:`ScreenPolygons` whose
        ``face`` is the label (a facet, or the first facet of a face taken whole)."""
        device, _, counts, _, labels = self.units
        return flat_polygons(device, counts, labels, self.width, self.height)

    @functools.cached_property
    def fans(self) -> I64:
        """Per facet: the number of facets of its face when it is the first facet of a
        face taken whole (:attr:`joined`), else 1 (G,): how many facets a polygon
        labeled with it covers (the fan :func:`scanline._kernels.visible.resolve_labels`
        looks a pixel's facet up in)."""
        first, counts = self.face_first
        out = np.ones(self.facet_count, np.int64)
        whole = first[self.joined[first]] if self.face_count else first
        out[whole] = counts[self.facet_face[whole]]
        return out

    @functools.cached_property
    def transparent(self) -> Bools:
        """Per facet: True when its material lets light through (k_t > 0)."""
        kt = np.array([m.transparency for m in self.materials], np.float64)
        out: Bools = kt[self.facet_mesh] > 0 if self.facet_count else np.zeros(0, bool)
        return out

    @functools.cached_property
    def facet_triangle(self) -> I64:
        """Per facet, the device triangle of largest screen area among its own (-1:
        none): the one whose screen-space interpolation functions stand for the
        facet's (all of a facet's triangles lie in its plane and share them)."""
        out = np.full(self.facet_count, -1, np.int64)
        # the whole facets' triangles come first, one each
        n = int(self.whole.sum())
        out[self.facet[:n]] = np.arange(n)
        t = self.triangles[n:]
        if len(t):
            area = np.abs((t[:, 1, 0] - t[:, 0, 0]) * (t[:, 2, 1] - t[:, 0, 1])
                          - (t[:, 2, 0] - t[:, 0, 0]) * (t[:, 1, 1] - t[:, 0, 1]))
            order = np.lexsort((area, self.facet[n:]))       # by facet, largest last
            out[self.facet[n:][order]] = n + order
        return out

    def with_triangles(self, select: Bools) -> "ScreenScene":
        """The scene with only the device triangles and polygons of the facets where
        ``select`` (G,) holds (the facets keep their numbers).

        Parameters
        ----------
        select : numpy.ndarray
            bool (G,): the facets whose triangles stay.

        Returns
        -------
        ScreenScene
            A new scene; every per-facet array is shared.

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
        >>> scene = sl.screen.prepare(sl.mesh.cube(), cam, 16, 16)
        >>> len(scene.with_triangles(np.zeros(scene.facet_count, bool)).triangles)
        0
        """
        keep_t = select[self.facet]
        keep_p = select[self.polygon_facet]
        polys = [p for p, k in zip(self.polygons, keep_p) if k]
        fields = {name: getattr(self, name) for name in self.__dataclass_fields__}
        fields.update(whole=self.whole & select,
                      triangles=np.ascontiguousarray(self.triangles[keep_t]),
                      inv_w=np.ascontiguousarray(self.inv_w[keep_t]),
                      bary=np.ascontiguousarray(self.bary[keep_t]),
                      facet=np.ascontiguousarray(self.facet[keep_t]),
                      polygons=DevicePolygons(np.empty((0, 3, 3)), polys),
                      polygon_facet=self.polygon_facet[keep_p])
        return ScreenScene(**fields)

    def supersampled(self, n: int) -> "ScreenScene":
        """The scene on a device ``n`` times finer in x and y: sample (i, j) of pixel (x,
        y) at x' = n x + (n - 1) / 2 + ..., so that the n x n samples of a pixel lie
        evenly around its center (as the A-buffer places them); device polygons, planes
        and the device's size follow.

        Parameters
        ----------
        n : int
            Samples per pixel along x and along y.

        Returns
        -------
        ScreenScene
            The scene on an ``n * width`` x ``n * height`` device.

        Examples
        --------
        >>> import scanline as sl
        >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
        >>> scene = sl.screen.prepare(sl.mesh.cube(), cam, 16, 16)
        >>> fine = scene.supersampled(2)
        >>> (fine.width, fine.height), bool((fine.triangles[..., :2] == scene.triangles[..., :2] * 2 + 0.5).all())
        ((32, 32), True)
        """
        c = (n - 1) / 2.0

        def scaled(points: Any) -> F64:
            out = np.array(points, np.float64, copy=True)
            out[..., :2] = out[..., :2] * n + c
            return out

        a, b, cc, d = (self.planes[:, i] for i in range(4))
        planes = np.stack([a / n, b / n, cc, d - (a + b) * c / n], axis=1)
        fields = {name: getattr(self, name) for name in self.__dataclass_fields__}
        clip, scale, offset = self.mapping
        grow = np.array([n, n, 1.0])
        fields.update(width=self.width * n, height=self.height * n,
                      mapping=(clip, scale * grow, offset * grow + np.array([c, c, 0.0])),
                      triangles=np.ascontiguousarray(scaled(self.triangles)), planes=planes,
                      polygons=DevicePolygons(scaled(self.polygons._whole),
                                              [scaled(p) for p in self.polygons._cut]))
        return ScreenScene(**fields)

    def __repr__(self) -> str:
        return (f"<ScreenScene {self.width}x{self.height}: {len(self.materials)} mesh(es), "
                f"{self.face_count} faces, {self.facet_count} facets, "
                f"{len(self.triangles)} device triangles>")


__all__ = ["ScreenScene", "DevicePolygons", "ScreenPolygons"]
