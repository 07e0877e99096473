"""Binary space-partitioning trees (Fuchs, Kedem and Naylor 1980; Hearn & Baker,
section 13-7): built once from the world-space polygons, traversed back to front
from any eye.

*Object precision*: polygons are split by planes in world coordinates; the pieces
are painted at image precision.
"""

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError, BSPTooLargeError
from .polygons import meshes_list, newell_plane, project, world_polygons

#: Relative tolerance of "on the plane" (times the scene's size).
TOLERANCE = 1e-9


class _Store:
    """Polygon pieces in flat arrays with room to grow (splits append)."""

    def __init__(self, verts, counts):
        n = len(counts)
        self.verts = np.empty((max(2 * len(verts), 16), 3))
        self.verts[:len(verts)] = verts
        self.nv = len(verts)
        self.start = np.empty(max(2 * n, 16), np.int64)
        self.count = np.empty(max(2 * n, 16), np.int64)
        self.start[:n] = np.concatenate([[0], np.cumsum(counts)[:-1]]) if n else []
        self.count[:n] = counts
        self.n = n

    def piece(self, p):
        s = self.start[p]
        return self.verts[s:s + self.count[p]]

    def add(self, pts):
        while self.nv + len(pts) > len(self.verts):
            self.verts = np.concatenate([self.verts, np.empty_like(self.verts)])
        if self.n == len(self.start):
            self.start = np.concatenate([self.start, np.empty_like(self.start)])
            self.count = np.concatenate([self.count, np.empty_like(self.count)])
        self.verts[self.nv:self.nv + len(pts)] = pts
        self.start[self.n] = self.nv
        self.count[self.n] = len(pts)
        self.nv += len(pts)
        self.n += 1
        return self.n - 1

    def vertex_index(self, ids):
        """Flat vertex indices of pieces ``ids`` and the start of each in them."""
        counts = self.count[ids]
        first = np.concatenate([[0], np.cumsum(counts)[:-1]])
        idx = np.repeat(self.start[ids] - first, counts) + np.arange(int(counts.sum()))
        return idx, first


def _split(pts, d, eps):
    """The parts of convex polygon ``pts`` in front of (d < 0... > 0: see
    :class:`BSPTree`) and behind a plane, by their vertex distances ``d``."""
    front, back = [], []
    k = len(pts)
    for i in range(k):
        j = (i + 1) % k
        if d[i] >= -eps:
            front.append(pts[i])
        if d[i] <= eps:
            back.append(pts[i])
        if (d[i] > eps and d[j] < -eps) or (d[i] < -eps and d[j] > eps):
            cut = pts[i] + (pts[j] - pts[i]) * (d[i] / (d[i] - d[j]))
            front.append(cut)
            back.append(cut)
    return np.array(front), np.array(back)


class BSPTree:
    """A BSP tree of the faces of some meshes, in world coordinates.

    Parameters
    ----------
    meshes : Mesh or list of Mesh
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
    every set is empty.  Coplanar polygons stay in their node's list, so a million
    polygons in one plane make one node, built in one vectorized pass.

    The tree does not depend on the eye: :meth:`order` traverses it back to front
    from any viewpoint -- at each node, the subtree on the side away from the eye,
    then the node's own polygons, then the subtree on the eye's side -- so one tree
    serves every frame of a walk-through.  Object precision.

    References
    ----------
    H. Fuchs, Z. M. Kedem and B. F. Naylor, "On visible surface generation by a
    priori tree structures", SIGGRAPH '80, Computer Graphics 14(3), 124-133.
    """

    def __init__(self, meshes, max_pieces=None):
        self._meshes = meshes_list(meshes)
        verts, counts, faces = world_polygons(self._meshes)
        n = len(counts)
        self.limit = 8 * n + 10_000 if max_pieces is None else v.positive_int(
            "max_pieces", max_pieces)
        self._store = _Store(verts, counts)
        self._face = list(faces.tolist())
        size = float(np.ptp(verts, axis=0).max()) if len(verts) else 1.0
        self.eps = TOLERANCE * max(size, 1e-300)
        planes, front, back, members = [], [], [], []
        self.splits = 0
        stack = [(np.arange(n, dtype=np.int64), -1, 0)] if n else []
        while stack:
            ids, parent, which = stack.pop()
            node = len(planes)
            if parent >= 0:
                (front if which > 0 else back)[parent] = node
            plane = newell_plane(self._store.piece(ids[0]))
            plane = plane / np.linalg.norm(plane[:3])
            idx, first = self._store.vertex_index(ids)
            d = self._store.verts[idx] @ plane[:3] + plane[3]
            lo = np.minimum.reduceat(d, first)
            hi = np.maximum.reduceat(d, first)
            on = (lo >= -self.eps) & (hi <= self.eps)
            on[0] = True
            ahead = ~on & (lo >= -self.eps)
            behind = ~on & (hi <= self.eps)
            span = ~(on | ahead | behind)
            f_ids, b_ids = [ids[ahead]], [ids[behind]]
            for k in np.flatnonzero(span).tolist():
                p = int(ids[k])
                parts = _split(self._store.piece(p), d[first[k]:first[k] + self._store.count[p]],
                               self.eps)
                if self._store.n + 2 > self.limit:
                    raise BSPTooLargeError(
                        f"the BSP tree of {n} polygons needs more than max_pieces="
                        f"{self.limit} pieces; raise max_pieces or give fewer polygons")
                self.splits += 1
                for part, dest in zip(parts, (f_ids, b_ids)):
                    if len(part) >= 3:
                        dest.append(np.array([self._store.add(part)], np.int64))
                        self._face.append(self._face[p])
            planes.append(plane)
            front.append(-1)
            back.append(-1)
            members.append(ids[on])
            for which_, group in ((1, f_ids), (-1, b_ids)):
                sub = np.concatenate(group)
                if len(sub):
                    stack.append((sub, node, which_))
        self.planes = np.array(planes).reshape(-1, 4)
        self.front = np.array(front, np.int64)
        self.back = np.array(back, np.int64)
        self.pieces = members

    def __len__(self):
        return len(self.planes)

    def __repr__(self):
        return (f"<BSPTree: {len(self)} nodes, {self._store.n} pieces, "
                f"{self.splits} splits>")

    def order(self, eye):
        """Store indices of the pieces, back to front as seen from ``eye``: a world
        point (x, y, z), or a homogeneous (x, y, z, w) with w = 0 for a viewer at
        infinity in direction (x, y, z) (a parallel projection)."""
        e = np.asarray(eye, np.float64)
        if e.shape == (3,):
            e = np.append(e, 1.0)
        if e.shape != (4,) or not np.isfinite(e).all():
            raise v.ArgumentValueError(
                f"eye must be a finite point (x, y, z) or (x, y, z, w), got {v._show(eye)}")
        if e[3] < 0:
            e = -e
        out = []
        stack = [(0, False)] if len(self) else []
        while stack:
            node, expanded = stack.pop()
            if expanded:
                out.append(self.pieces[node])
                continue
            side = float(self.planes[node] @ e)
            near, far = (self.front[node], self.back[node]) if side >= 0 else \
                (self.back[node], self.front[node])
            # pushed in reverse: far subtree first, then the node, then the near one
            if near >= 0:
                stack.append((near, False))
            stack.append((node, True))
            if far >= 0:
                stack.append((far, False))
        return np.concatenate(out) if out else np.empty(0, np.int64)

    def world_pieces(self, eye):
        """``(vertices, counts, faces)`` of the pieces back to front from ``eye``."""
        ids = self.order(eye)
        idx, _ = self._store.vertex_index(ids)
        return (self._store.verts[idx], self._store.count[ids].copy(),
                np.array(self._face, np.int64)[ids])


def camera_eye(camera, width, height):
    """The viewer as a homogeneous world point: the center of projection of a
    perspective camera, or (direction, 0) toward the viewer for a parallel one --
    the preimage of the point at z = -infinity of clip space."""
    clip = camera.mapping(camera._device_box(width, height))[0]
    e = np.linalg.solve(clip, np.array([0.0, 0.0, -1.0, 0.0]))
    scale = np.abs(e).max()
    e = e / scale
    if abs(e[3]) < 1e-12:
        e[3] = 0.0
    return e if e[3] >= 0 else -e


def bsp(meshes_or_tree, camera, width, height, cull_back_faces=False):
    """The faces of ``meshes_or_tree`` (meshes, or a :class:`BSPTree` built once)
    back to front through ``camera`` by BSP traversal, as
    :class:`~scanline.visible.polygons.ScreenPolygons` in drawing order on a
    ``width`` x ``height`` device (the pieces clipped and projected as
    :func:`~scanline.visible.polygons.project` does).  Object precision."""
    from ..projection import Camera

    if not isinstance(camera, Camera):
        raise ArgumentTypeError(f"camera must be a scanline.Camera, got {v._show(camera)}")
    tree = meshes_or_tree if isinstance(meshes_or_tree, BSPTree) else BSPTree(meshes_or_tree)
    verts, counts, faces = tree.world_pieces(camera_eye(camera, width, height))
    return project(verts, counts, faces, camera, width, height, cull_back_faces)
