"""Binary space-partitioning trees (Fuchs, Kedem and Naylor 1980; Hearn & Baker,
section 13-7): built once from the world-space polygons, traversed back to front
from any eye.

*Object precision*: polygons are split by planes in world coordinates; the pieces
are painted at image precision.
"""

from typing import TYPE_CHECKING, Any, Optional, Tuple, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._kernels import bsp as k
from .._kernels._jit import call
from ..errors import ArgumentValueError, BSPTooLargeError
from ..screen.meshes import meshes_list
from ..screen.polygons import newell_planes

if TYPE_CHECKING:
    from ..projection import Camera
    from ..screen.polygons import ScreenPolygons

#: Relative tolerance of "on the plane" (times the scene's size).
TOLERANCE = 1e-9

_S = TypeVar("_S", bound=np.generic)


def world_polygons(meshes: Any
                   ) -> Tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]:
    """The faces of ``meshes`` as world polygons: ``(vertices (V, 3), counts (P,),
    face (P,))``, faces numbered across the meshes in order.  Convex faces that are
    not planar (a teapot's bilinear patches) are split into a fan of triangles, each
    keeping its face index.  Vectorized over the faces (a million faces take about a
    second)."""
    verts: list[NDArray[np.float64]] = []
    counts: list[NDArray[np.int64]] = []
    faces: list[NDArray[np.int64]] = []
    base = 0
    for mesh in meshes_list(meshes):
        idx, off = mesh.face_indices, mesh.face_offsets
        sizes = np.diff(off)
        nf = len(sizes)
        owner = np.repeat(np.arange(nf), sizes)
        p = mesh.vertices[idx]
        plane = newell_planes(p, off)
        norm = np.linalg.norm(plane[:, :3], axis=1)
        dist = np.abs(np.einsum("ij,ij->i", p, plane[owner, :3]) + plane[owner, 3])
        off_plane = np.maximum.reduceat(dist, off[:-1]) / np.where(norm > 0, norm, 1.0)
        size = (np.maximum.reduceat(p, off[:-1], axis=0)
                - np.minimum.reduceat(p, off[:-1], axis=0)).max(axis=1)
        flat = (norm > 0) & (off_plane <= 1e-9 * np.where(size > 0, size, 1.0))
        keep = flat[owner]
        verts.append(p[keep])
        counts.append(sizes[flat])
        faces.append(base + np.flatnonzero(flat))
        bent = np.flatnonzero(~flat)
        if len(bent):                    # fans (0, k, k + 1) of the bent faces
            tri = sizes[bent] - 2
            f = np.repeat(bent, tri)
            k = np.arange(int(tri.sum())) - np.repeat(np.cumsum(tri) - tri, tri)
            first = off[f]
            corners = np.stack([first, first + k + 1, first + k + 2], axis=1)
            verts.append(mesh.vertices[idx[corners.reshape(-1)]])
            counts.append(np.full(len(f), 3, np.int64))
            faces.append(base + f)
        base += nf
    return (np.ascontiguousarray(np.concatenate(verts)), np.concatenate(counts).astype(np.int64),
            np.concatenate(faces).astype(np.int64))


class BSPTree:
    """A BSP tree of the faces of some meshes, in world coordinates.

    Parameters
    ----------
    meshes : Mesh or list of Mesh
        The scene's meshes.
    max_pieces : int, optional
        Most polygon pieces the tree may hold after splitting (default 8 P + 10 000):
        a badly chosen order of splitting planes can split quadratically many times;
        beyond the limit :class:`~scanline.errors.BSPTooLargeError` is raised.

    Attributes
    ----------
    planes : ndarray, shape (N, 4)
        The plane (A, B, C, D) of each node, (A, B, C) its face's outward normal
        (unit length): a point with A x + B y + C z + D > 0 is in *front*.
    front, back : ndarray of int64, shape (N,)
        The child nodes (-1: none).
    pieces : list of ndarray
        Per node, the pieces lying in its plane (their store indices).
    splits : int
        How many polygons were split while building.

    Notes
    -----
    Hearn & Baker, section 13-7: a polygon of the set is chosen as the partitioning
    plane (the first of each set, as the book does); the others are classified by
    the signs of their vertices' distances into *front*, *back* and *coplanar*, and
    those that straddle the plane are split into a front and a back piece.  The two
    sets are partitioned in turn, with an explicit stack (no recursion limit), until
    every set is empty (one compiled kernel, :mod:`scanline._kernels.bsp`).  Coplanar
    polygons stay in their node's list, so a million polygons in one plane make one
    node.  Choosing the first polygon, as the book does, makes a chain of the faces
    of a convex object (each lies behind every other's plane): the build then costs
    the square of their number.

    The tree does not depend on the eye: :meth:`order` traverses it back to front
    from any viewpoint -- at each node, the subtree on the side away from the eye,
    then the node's own polygons, then the subtree on the eye's side -- so one tree
    serves every frame of a walk-through.  Object precision.

    References
    ----------
    H. Fuchs, Z. M. Kedem and B. F. Naylor, "On visible surface generation by a
    priori tree structures", SIGGRAPH '80, Computer Graphics 14(3), 124-133.

    Examples
    --------
    Built once, the tree orders the cube's faces for any eye; seen from +z the front
    face (5) comes last.

    >>> import scanline as sl
    >>> tree = sl.visible.BSPTree(sl.mesh.cube(2))
    >>> faces = tree.world_pieces((0, 0, 5))[2]
    >>> sorted(faces.tolist()), int(faces[-1])
    ([0, 1, 2, 3, 4, 5], 5)
    """

    def __init__(self, meshes: Any, max_pieces: Optional[int] = None) -> None:
        self._build(*world_polygons(meshes_list(meshes)), max_pieces)

    @classmethod
    def of_polygons(cls, vertices: ArrayLike, counts: ArrayLike, faces: ArrayLike,
                    max_pieces: Optional[int] = None) -> "BSPTree":
        """The tree of planar convex world polygons given flat (``vertices`` (V, 3),
        ``counts`` (P,)), each labeled with its entry of ``faces`` (P,): what
        :meth:`world_pieces` reports for its pieces.

        Parameters
        ----------
        vertices : array_like (V, 3)
            The polygons' vertices, one polygon after another.
        counts : array_like of int (P,)
            Vertices per polygon.
        faces : array_like of int (P,)
            A label per polygon.
        max_pieces : int, optional
            As the constructor's.

        Returns
        -------
        BSPTree
            The tree.

        Raises
        ------
        BSPTooLargeError
            More pieces than ``max_pieces``.

        Examples
        --------
        Two parallel squares: seen from above, the lower one first.

        >>> import scanline as sl
        >>> squares = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),      # z = 0
        ...            (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]      # z = 1
        >>> tree = sl.visible.BSPTree.of_polygons(squares, [4, 4], [7, 8])
        >>> tree.world_pieces((0, 0, 5))[2].tolist(), tree.world_pieces((0, 0, -5))[2].tolist()
        ([7, 8], [8, 7])
        """
        tree = cls.__new__(cls)
        tree._build(np.ascontiguousarray(vertices, np.float64), np.asarray(counts, np.int64),
                    np.asarray(faces, np.int64), max_pieces)
        return tree

    def _build(self, verts: NDArray[np.float64], counts: NDArray[np.int64],
               faces: NDArray[np.int64], max_pieces: Optional[int]) -> None:
        n = len(counts)
        self.limit = 8 * n + 10_000 if max_pieces is None else v.positive_int(
            "max_pieces", max_pieces)
        size = float(np.ptp(verts, axis=0).max()) if len(verts) else 1.0
        self.eps = TOLERANCE * max(size, 1e-300)
        store = np.empty((2 * len(verts) + 256, 3))
        store[:len(verts)] = verts
        pc = np.empty((2 * n + 64, 3), np.int64)
        pc[:n, 0] = np.cumsum(counts) - counts
        pc[:n, 1] = counts
        pc[:n, 2] = faces
        stack = np.empty((n + 64, 4), np.int64)
        stack[0] = (0, n, -1, 1)
        pool = np.empty(2 * n + 64, np.int64)
        pool[:n] = np.arange(n)
        scratch = np.empty(4 * n + 64, np.int64)
        planes = np.empty((2 * n + 64, 4))
        nodes = np.empty((2 * n + 64, 4), np.int64)
        members = np.empty(2 * n + 64, np.int64)
        st = np.zeros(k.STATE, np.int64)
        st[[k.VERTS, k.PIECES, k.STACK]] = len(verts), n, 1 if n else 0
        while True:
            status = call(k.build, lambda: 4 * float(counts.sum()) * max(np.log2(n + 1), 1.0),
                          store, pc, stack, pool, scratch, planes, nodes, members, st, self.eps,
                          self.limit)
            if status != k.NEED_ROOM:
                break
            which = int(st[k.WHICH])
            if which == k.ROOM_VERTS:
                store = _doubled(store)
            elif which == k.ROOM_PIECES:
                pc = _doubled(pc)
            elif which == k.ROOM_STACK:
                stack = _doubled(stack)
            elif which == k.ROOM_POOL:
                pool, scratch = _doubled(pool), _doubled(scratch)
            elif which == k.ROOM_NODES:
                planes, nodes = _doubled(planes), _doubled(nodes)
            else:
                members = _doubled(members)
        if status == k.TOO_MANY:
            raise BSPTooLargeError(
                f"the BSP tree of {n} polygons needs more than max_pieces={self.limit} "
                "pieces; raise max_pieces or give fewer polygons")
        count = int(st[k.NODES])
        self._verts = store[:st[k.VERTS]]
        self._pieces = pc[:st[k.PIECES]]
        self._members = members[:st[k.MEMBERS]]
        self.splits = int(st[k.SPLITS])
        self.planes = planes[:count].copy()
        self.front = nodes[:count, 0].copy()
        self.back = nodes[:count, 1].copy()
        self._nodes = nodes[:count].copy()
        self.pieces = [self._members[a:a + c] for a, c in self._nodes[:, 2:4].tolist()]

    def __len__(self) -> int:
        return len(self.planes)

    def __repr__(self) -> str:
        return (f"<BSPTree: {len(self)} nodes, {len(self._pieces)} pieces, "
                f"{self.splits} splits>")

    def order(self, eye: ArrayLike) -> NDArray[np.int64]:
        """Store indices of the pieces, back to front as seen from ``eye``: a world
        point (x, y, z), or a homogeneous (x, y, z, w) with w = 0 for a viewer at
        infinity in direction (x, y, z) (a parallel projection).

        Parameters
        ----------
        eye : array_like (3,) or (4,)
            The viewer (w = 0: at infinity).

        Returns
        -------
        ndarray of int64
            The pieces' store indices, back to front (Hearn & Baker 13-7).

        Raises
        ------
        ArgumentValueError
            An eye that is not a finite 3- or 4-vector.

        Examples
        --------
        >>> import scanline as sl
        >>> squares = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),      # z = 0
        ...            (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]      # z = 1
        >>> tree = sl.visible.BSPTree.of_polygons(squares, [4, 4], [7, 8])
        >>> tree.order((0, 0, 5)).tolist(), tree.order((0, 0, -1, 0)).tolist()
        ([0, 1], [1, 0])
        """
        e = np.asarray(eye, np.float64)
        if e.shape == (3,):
            e = np.append(e, 1.0)
        if e.shape != (4,) or not np.isfinite(e).all():
            raise ArgumentValueError(
                f"eye must be a finite point (x, y, z) or (x, y, z, w), got {v._show(eye)}")
        if e[3] < 0:
            e = -e
        out = np.empty(len(self._members), np.int64)
        count = call(k.back_to_front, 4 * len(self) + len(out), self.planes, self._nodes,
                     self._members, e, out, np.empty((2 * len(self) + 2, 2), np.int64))
        return out[:count]

    def world_pieces(self, eye: ArrayLike
                     ) -> Tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]:
        """``(vertices, counts, faces)`` of the pieces back to front from ``eye``.

        Parameters
        ----------
        eye : array_like (3,) or (4,)
            The viewer, as :meth:`order` takes it.

        Returns
        -------
        vertices : ndarray (V, 3)
            The pieces' vertices, back to front.
        counts : ndarray of int64 (K,)
            Vertices per piece.
        faces : ndarray of int64 (K,)
            Each piece's label.

        Examples
        --------
        >>> import scanline as sl
        >>> squares = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),      # z = 0
        ...            (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]      # z = 1
        >>> tree = sl.visible.BSPTree.of_polygons(squares, [4, 4], [7, 8])
        >>> vertices, counts, faces = tree.world_pieces((0, 0, 5))
        >>> counts.tolist(), vertices[0].tolist()                 # the z = 0 square first
        ([4, 4], [0.0, 0.0, 0.0])
        """
        ids = self.order(eye)
        start, counts, faces = self._pieces[ids].T
        first = np.cumsum(counts) - counts
        idx = np.repeat(start - first, counts) + np.arange(int(counts.sum()))
        return self._verts[idx], counts, faces


def _doubled(a: NDArray[_S]) -> NDArray[_S]:
    """``a`` with twice the rows, the rows kept."""
    out: NDArray[_S] = np.empty((2 * len(a),) + a.shape[1:], a.dtype)
    out[:len(a)] = a
    return out


def camera_eye(camera: "Camera", width: int, height: int) -> NDArray[np.float64]:
    """The viewer as a homogeneous world point: the center of projection of a
    perspective camera, or (direction, 0) toward the viewer for a parallel one --
    the preimage of the point at z = -infinity of clip space.

    Parameters
    ----------
    camera : Camera
        The viewer.
    width, height : int
        The device it is fitted to.

    Returns
    -------
    ndarray (4,)
        The homogeneous eye, scaled so its largest entry is 1 in magnitude.

    Raises
    ------
    ArgumentValueError
        A projection that cannot be inverted in floating point (the viewer's position
        is then unknown).

    Examples
    --------
    A perspective camera at (0, 0, 5): (0, 0, 5, 1), scaled by 1/5.

    >>> import scanline as sl
    >>> sl.visible.camera_eye(sl.Camera(eye=(0, 0, 5), target=(0, 0, 0)), 32, 32).tolist()
    [0.0, 0.0, 1.0, 0.2]
    """
    clip = camera.mapping(camera._device_box(width, height))[0]
    try:
        with np.errstate(all="ignore"):
            e = np.linalg.solve(clip, np.array([0.0, 0.0, -1.0, 0.0]))
            scale = np.abs(e).max()
            e = e / scale
    except np.linalg.LinAlgError:
        e = np.full(4, np.nan)
    if not np.isfinite(e).all():
        raise ArgumentValueError(
            f"camera: its projection cannot be inverted in floating point (eye "
            f"{v._show(camera.eye)}), so the viewer's position is unknown to the BSP "
            "traversal; place the eye and the target at distances a float can resolve")
    if abs(e[3]) < 1e-12:
        e[3] = 0.0
    return e if e[3] >= 0 else -e


def bsp(meshes_or_tree: Any, camera: "Camera", width: int, height: int,
        cull_back_faces: bool = False) -> "ScreenPolygons":
    """The faces of ``meshes_or_tree`` (meshes, or a :class:`BSPTree` built once)
    back to front through ``camera`` by BSP traversal, as
    :class:`~scanline.screen.ScreenPolygons` in drawing order on a ``width`` x
    ``height`` device (the pieces clipped and projected as the preparation clips the
    scene's facets, :func:`scanline.screen.device_polygons`).  ``cull_back_faces``:
    drop the pieces that face away from the viewer (Hearn & Baker, section 13-2:
    clockwise as projected, the faces being counterclockwise seen from outside).
    Object precision.

    Parameters
    ----------
    meshes_or_tree : Mesh, list of Mesh, or BSPTree
        The scene.
    camera : Camera
        The viewer.
    width, height : int
        The device's size.
    cull_back_faces : bool
        Drop the pieces facing away.

    Returns
    -------
    ScreenPolygons
        The pieces in drawing order.

    Raises
    ------
    BSPTooLargeError
        A tree past its piece limit.

    Examples
    --------
    Back-face culling leaves a cube seen head on its front face (5):

    >>> import scanline as sl
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
    >>> sl.visible.bsp(sl.mesh.cube(2), cam, 16, 16, cull_back_faces=True).face.tolist()
    [5]
    """
    from ..screen.prepare import camera_mapping, device_polygons

    camera_mapping(camera, width, height)
    tree = meshes_or_tree if isinstance(meshes_or_tree, BSPTree) else BSPTree(meshes_or_tree)
    verts, counts, faces = tree.world_pieces(camera_eye(camera, width, height))
    sp = device_polygons(verts, counts, faces, camera, width, height)
    if cull_back_faces and len(sp):
        from ..screen.polygons import signed_areas

        sp = sp.subset(np.flatnonzero(signed_areas(sp.vertices, sp.offsets) > 0))
    return sp
