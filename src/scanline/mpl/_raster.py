"""The raster route of :mod:`scanline.mpl`: the polygons drawn into a z-buffer image
(:func:`scanline.draw.triangles` with a :class:`~scanline.DepthBuffer`) the size of
the axes in device pixels, ``samples`` x ``samples`` per pixel and averaged; the
image placed in the axes; lines and markers tested against the depth buffer at
image precision and drawn as vector artists over it."""

import math
from typing import TYPE_CHECKING, Callable, List, Tuple

import numpy as np
from matplotlib.backend_bases import RendererBase
from matplotlib.collections import Collection, LineCollection
from matplotlib.transforms import BboxBase
from numpy.typing import NDArray
from PIL import Image

from .. import draw as sl_draw
from ..depthbuffer import DepthBuffer
from ..framebuffer import FrameBuffer
from . import _geometry as g
from . import _scene
from ..screen import ScreenPolygons
from ._geometry import Bools, Floats, Ints
from ._scene import Numbers, Scene

if TYPE_CHECKING:
    from mpl_toolkits.mplot3d import Axes3D

    from . import Occlusion

#: ``hide(x, y, depth)``: whether each device point is hidden.
_Hide = Callable[[Floats, Floats, Floats], Bools]

#: Depth by which a line or a marker may lie behind the depth buffer and still be
#: seen (depths run 0 .. 1 over the scene), besides the 3 x 3 pixels' farthest
#: depth it is compared with.
EPS = 1e-6


def _fan(sp: ScreenPolygons, rows: Ints) -> Tuple[Floats, Ints]:
    """Triangles (T, 3, 3) of the convex polygons ``rows`` of ``sp``, fanned from
    their first vertex, and the polygon of each."""
    poly, counts = g.padded(sp, rows)
    k = poly.shape[1]
    if k == 3:
        return poly, rows
    j = np.arange(1, k - 1)
    tris = poly[:, np.stack([np.zeros_like(j), j, j + 1], axis=1)]     # (R, k-2, 3, 3)
    used = j[None, :] < (counts - 1)[:, None]
    return tris[used], np.repeat(rows, k - 2).reshape(len(rows), k - 2)[used]


class Frame:
    """The image's pixel grid: ``samples`` x ``samples`` device pixels per image pixel,
    image pixel (0, 0) at display (x0, y0) / ``mag``."""

    def __init__(self, bbox: BboxBase, mag: float, samples: int) -> None:
        self.mag, self.s = mag, samples
        self.x0, self.y0 = math.floor(bbox.x0 * mag), math.floor(bbox.y0 * mag)
        self.w = max(1, math.ceil(bbox.x1 * mag) - self.x0)
        self.h = max(1, math.ceil(bbox.y1 * mag) - self.y0)

    def device(self, xy: Floats) -> Floats:
        """Display x, y (..., 2) as device coordinates (pixel centers at integers)."""
        out = np.empty_like(xy)
        out[..., 0] = (xy[..., 0] * self.mag - self.x0) * self.s - 0.5
        out[..., 1] = (xy[..., 1] * self.mag - self.y0) * self.s - 0.5
        return out


def _paint(frame: Frame, sp: ScreenPolygons, rows: Ints, face: Floats,
           depth: DepthBuffer) -> NDArray[np.uint8]:
    """Draw the polygons ``rows`` with a depth test: the RGBA frame buffer's pixels
    (straight alpha, uint8, the top row first)."""
    W, H = frame.w * frame.s, frame.h * frame.s
    fb = FrameBuffer(W, H, mode="RGBA", background=(0, 0, 0, 0))
    if len(rows):
        # the last polygon first: the depth test keeps the first of equal depths, so
        # of coplanar polygons the one matplotlib would paint last is seen
        tris, of = _fan(sp, rows[::-1])
        tris = tris.copy()
        tris[..., :2] = frame.device(tris[..., :2])
        colors = np.clip(np.rint(face[sp.face[of]] * 255), 0, 255).astype(np.uint8)
        sl_draw.triangles(fb, tris, colors=colors, depth=depth)
    return fb.to_array()


def _resolve(rgba: NDArray[np.uint8], s: int) -> NDArray[np.uint8]:
    """The mean of ``s`` x ``s`` blocks of straight-alpha uint8 RGBA, colors weighted
    by alpha (Pillow's box reduction of the premultiplied image, "RGBa")."""
    if s == 1:
        return rgba
    image = Image.fromarray(np.ascontiguousarray(rgba), "RGBA")
    return np.asarray(image.convert("RGBa").reduce(s).convert("RGBA"))


def _over(front: NDArray[np.uint8], back: NDArray[np.uint8]) -> NDArray[np.uint8]:
    """Straight-alpha uint8 ``front`` composited over ``back`` (the nearest veil over
    the opaque surfaces)."""
    f = front.astype(np.float32) / 255
    b = back.astype(np.float32) / 255
    fa, ba = f[..., 3:], b[..., 3:]
    a = fa + ba * (1 - fa)
    with np.errstate(invalid="ignore", divide="ignore"):
        rgb = np.where(a > 0, (f[..., :3] * fa + b[..., :3] * ba * (1 - fa)) / a, 0.0)
    out: NDArray[np.uint8] = np.rint(np.concatenate([rgb, a], axis=2) * 255).astype(np.uint8)
    return out


def _behind(z: Floats, x: Floats, y: Floats, depth: Floats) -> Bools:
    """Whether device points lie behind the depth buffer ``z`` at their pixel by more
    than :data:`EPS`, compared with the farthest depth of the pixel's 3 x 3
    neighbourhood (lines on a surface stay seen where rounding or a neighbouring
    pixel's center would put the surface in front; a line along a silhouette is
    seen)."""
    H, W = z.shape
    ix = np.rint(x).astype(np.int64)
    iy = np.rint(y).astype(np.int64)
    inside = (ix >= 0) & (ix < W) & (iy >= 0) & (iy < H) & np.isfinite(depth)
    out = np.zeros(len(x), bool)
    if not inside.any():
        return out
    ix, iy, d = ix[inside], iy[inside], depth[inside]
    far = np.full(len(ix), -np.inf)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            np.maximum(far, z[np.clip(iy + dy, 0, H - 1), np.clip(ix + dx, 0, W - 1)],
                       out=far)
    out[inside] = d > far + EPS
    return out


def _segment_parts(frame: Frame, segments: Floats, depth: Floats,
                   hide: _Hide) -> Tuple[Floats, Ints]:
    """The parts of ``segments`` (display) where ``hide(x, y, z)`` (device) is false,
    sampled at every device pixel along each: ``(parts (K, 4) display, of)``."""
    if not len(segments):
        return np.empty((0, 4)), np.empty(0, np.int64)
    a = frame.device(segments[:, :2])
    b = frame.device(segments[:, 2:])
    length = np.hypot(*(b - a).T)
    steps = np.maximum(np.ceil(length), 1).astype(np.int64)
    total = int((steps + 1).sum())
    if total > 20_000_000:                     # very long lines: coarser samples
        steps = np.maximum((steps * 20_000_000 // total), 1)
    n = steps + 1
    seg = np.repeat(np.arange(len(segments)), n)
    k = np.arange(int(n.sum())) - np.repeat(np.cumsum(n) - n, n)
    t = k / steps[seg]
    x = a[seg, 0] + t * (b[seg, 0] - a[seg, 0])
    y = a[seg, 1] + t * (b[seg, 1] - a[seg, 1])
    z = depth[seg, 0] + t * (depth[seg, 1] - depth[seg, 0])
    seen = ~hide(x, y, z)
    first = k == 0
    last = np.concatenate([first[1:], [True]])
    starts = np.flatnonzero(seen & (first | ~np.concatenate([[False], seen[:-1]])))
    ends = np.flatnonzero(seen & (last | ~np.concatenate([seen[1:], [False]])))
    half = 0.5 / steps[seg]
    t0 = np.where(first[starts], 0.0, t[starts] - half[starts])
    t1 = np.where(last[ends], 1.0, t[ends] + half[ends])
    of = seg[starts]
    p, d = segments[of, :2], segments[of, 2:] - segments[of, :2]
    parts = np.concatenate([p + t0[:, None] * d, p + t1[:, None] * d], axis=1)
    return parts, of


def draw(renderer: RendererBase, scene: Scene, owner: "Occlusion", samples: int,
         slack: float) -> Numbers:
    """Draw the scene by the raster route; returns the numbers for the record."""
    fig = _scene.figure_of(owner)
    axes: "Axes3D" = owner.axes
    frame = Frame(axes.bbox, renderer.get_image_magnification(), samples)
    W, H = frame.w * frame.s, frame.h * frame.s
    opaque = scene.opaque
    sp = scene.sp
    depth = DepthBuffer(W, H)
    image = _paint(frame, sp, np.flatnonzero(opaque), scene.face, depth)
    z_opaque = depth.array
    z_veil = None
    if not opaque.all():
        veil_depth = DepthBuffer(W, H)
        veil_depth.array[:] = z_opaque
        veil = _paint(frame, sp, np.flatnonzero(~opaque), scene.face, veil_depth)
        image = _over(veil, image)
        z_veil = np.where(veil_depth.array < z_opaque, veil_depth.array, np.inf)
    im = np.ascontiguousarray(_resolve(image, frame.s)[::-1])   # draw_image: bottom row first

    def clip(artist: Collection) -> Collection:
        artist.set_figure(fig)
        artist.set_clip_on(owner.get_clip_on())
        artist.set_clip_box(owner.get_clip_box())
        artist.set_clip_path(owner.get_clip_path())
        return artist

    zmax, vmax = z_opaque, z_veil
    seg, dep = scene.segments, scene.seg_depth - slack
    # polygon outlines in their own edge color (not the face's: those only hide seams)
    stroked = (scene.edge[:, 3] > 0) & (scene.edge_width > 0) & (scene.face[:, 3] > 0) & ~np.all(
        np.abs(scene.edge - scene.face) < 1e-12, axis=1)
    extra: List[Tuple[Floats, Floats, Ints]] = []
    if stroked.any():
        rows = np.flatnonzero(stroked)
        k = scene.dev.shape[1]
        j = np.arange(k)
        cnt = scene.count[rows]
        valid = j[None, :] < cnt[:, None]
        nxt = np.where(j[None, :] + 1 < cnt[:, None], j[None, :] + 1, 0)
        a = scene.dev[rows[:, None], j[None, :]][valid]
        b = scene.dev[rows[:, None], nxt][valid]
        ok = np.isfinite(a).all(axis=1) & np.isfinite(b).all(axis=1)
        eseg = np.concatenate([a[ok, :2], b[ok, :2]], axis=1)
        edep = np.stack([a[ok, 2], b[ok, 2]], axis=1) - slack
        eof = np.broadcast_to(rows[:, None], valid.shape)[valid][ok]
        extra = [(eseg, edep, eof)]

    def hidden_by(zm: Floats) -> _Hide:
        return lambda x, y, z: _behind(zm, x, y, z)

    seen_parts, seen_of = _segment_parts(frame, seg, dep, hidden_by(zmax))
    hidden = len(seg)
    below = np.empty((0, 4)), np.empty(0, np.int64)
    above = seen_parts, seen_of
    if vmax is not None and len(seen_parts):
        pdep = g.depth_along(seen_parts, seen_of, seg, dep)
        up, up_of = _segment_parts(frame, seen_parts, pdep, hidden_by(vmax))
        down, down_of = _segment_parts(frame, seen_parts, pdep,
                                       lambda x, y, z: ~_behind(vmax, x, y, z))
        above, below = (up, seen_of[up_of]), (down, seen_of[down_of])
    scale = max(scene.width, scene.height)
    under: List[_scene.Drawing] = []
    over: List[_scene.Drawing] = []
    if len(below[0]):
        v, o, lines = g.polylines(below[0], below[1], scene.seg_line, scale)
        under += _scene.line_artists(scene, v, o, lines, fig, clip)
    for eseg, edep, eof in extra:             # outlines first: the lines are data
        parts, of = _segment_parts(frame, eseg, edep, hidden_by(zmax))
        over.append(_edge_collection(scene, parts, eof[of], clip))
    v, o, lines = g.polylines(above[0], above[1], scene.seg_line, scale)
    over += _scene.line_artists(scene, v, o, lines, fig, clip)
    seen: List[Bools] = []
    veiled: List[Bools] = []
    for pt in scene.points:
        d = pt.device
        xy = frame.device(d[:, :2])
        gone = _behind(zmax, xy[:, 0], xy[:, 1], d[:, 2] - slack) | ~np.isfinite(d).all(axis=1)
        behind = (_behind(vmax, xy[:, 0], xy[:, 1], d[:, 2] - slack) if vmax is not None
                  else np.zeros(len(d), bool))
        seen.append(~gone & ~behind)
        veiled.append(~gone & behind)
    under += _scene.point_artists(scene, veiled, fig, clip)
    over += _scene.point_artists(scene, seen, fig, clip)

    for artist in under:
        artist.draw(renderer)
    gc = renderer.new_gc()
    owner._set_gc_clip(gc)  # type: ignore[attr-defined]  # Artist's, absent from its stub
    gc.set_clip_rectangle(axes.bbox.frozen())
    renderer.draw_image(gc, frame.x0 / frame.mag, frame.y0 / frame.mag, im)
    gc.restore()
    for artist in over:
        artist.draw(renderer)
    return {"image": (frame.w, frame.h), "samples": frame.s, "segments": hidden,
            "points hidden": int(sum((~m & ~w).sum() for m, w in zip(seen, veiled)))}


def _edge_collection(scene: Scene, parts: Floats, poly: Ints,
                     clip: _scene.Clip) -> Collection:
    """The seen parts of polygon outlines, each in its polygon's edge style."""
    from matplotlib.transforms import IdentityTransform

    coll = LineCollection(list(parts.reshape(-1, 2, 2)), colors=scene.edge[poly],
                          linewidths=scene.edge_width[poly],
                          antialiaseds=scene.antialiased[poly],
                          transform=IdentityTransform())
    return clip(coll)
