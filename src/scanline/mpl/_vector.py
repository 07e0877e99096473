"""The vector route of :mod:`scanline.mpl`: the polygons ordered (and split) by the
depth-sorting method and drawn as one 2-D path collection in that order; lines cut
where surfaces hide them (visible-line detection); markers hidden by a surface left
out.  Everything stays a path: SVG and PDF output stay vector."""

from typing import TYPE_CHECKING, Any, Dict, List, Optional, Tuple

import numpy as np
from numpy.typing import NDArray
from matplotlib.backend_bases import RendererBase
from matplotlib.collections import Collection, PathCollection
from matplotlib.path import Path
from matplotlib.transforms import IdentityTransform

from .. import visible
from ..screen import ScreenPolygons
from . import _geometry as g
from . import _scene
from ._geometry import Bools, Floats, Ints
from ._scene import Scene
from ._sources import LineStyle

if TYPE_CHECKING:
    from . import Occlusion

#: Depth (0 .. 1 over the scene) by which a marker may lie behind a polygon's plane and
#: still count as in front of it (besides the polygon's bend).
EPS = 1e-7
#: (segments x polygons) above which the hidden-line test runs on tiles of segments,
#: each against the polygons that overlap its tile.
TILE_WORK = 4_000_000

_MOVETO, _LINETO = Path.MOVETO, Path.LINETO


def _closed_paths(verts: Floats, offsets: Ints, rows: Ints) -> List[Path]:
    """Closed matplotlib paths of the flat polygons ``rows`` (x, y of ``verts``)."""
    counts = np.diff(offsets)[rows]
    out: Dict[int, Path] = {}
    make = getattr(Path, "_fast_from_codes_and_verts", None)
    for k in np.unique(counts):
        sel = np.flatnonzero(counts == k)
        idx = offsets[rows[sel]][:, None] + np.arange(k)[None, :]
        xy = verts[idx][..., :2]
        xy = np.concatenate([xy, xy[:, :1]], axis=1)
        template = Path(xy[0], closed=True)
        if make is None:
            made = [Path(p, template.codes) for p in xy]
        else:
            made = [make(p, template.codes, internals_from=template) for p in xy]
        for i, p in zip(sel.tolist(), made):
            out[i] = p
    return [out[i] for i in range(len(rows))]


def _edge_path(xy: Floats, on: Bools) -> Path:
    """The open path of the runs of ``on`` edges of the polygon ``xy`` (K, 2) (edge i
    from vertex i to i + 1)."""
    k = len(xy)
    if on.all():
        return Path(np.concatenate([xy, xy[:1]]), closed=True)
    start = int(np.flatnonzero(~on)[0]) + 1        # begin after an edge that is off
    verts: List[Floats] = []
    codes: List[np.uint8] = []
    prev = False
    for j in range(start, start + k):
        i = j % k
        if on[i]:
            if not prev:
                verts.append(xy[i])
                codes.append(_MOVETO)
            verts.append(xy[(i + 1) % k])
            codes.append(_LINETO)
        prev = bool(on[i])
    return Path(np.array(verts), np.array(codes, np.uint8))


def pieces_collection(scene: Scene, pieces: ScreenPolygons) -> PathCollection:
    """One PathCollection drawing ``pieces`` in order: each piece filled in its source
    polygon's face color, stroked when matplotlib strokes its polygon in the face's
    color (the stroke then only covers seams), or followed by a path of the parts
    of its outline on its polygon's own outline, stroked in the edge color."""
    n = len(pieces)
    src = pieces.face
    face = scene.face[src]
    edge = scene.edge[src]
    width = scene.edge_width[src]
    stroked = (edge[:, 3] > 0) & (width > 0)
    same = stroked & np.all(np.abs(edge - face) < 1e-12, axis=1)
    apart = np.flatnonzero(stroked & ~same)
    fills = _closed_paths(pieces.vertices, pieces.offsets, np.arange(n))
    paths = list(fills)
    facecolors = face.copy()
    edgecolors = np.where(same[:, None], face, 0.0)
    widths = np.where(same, width, 0.0)
    aa = scene.antialiased[src]
    styles: Optional[List[LineStyle]] = None
    if len(apart):
        styles = [scene.edge_style[i] for i in src]
        on = g.original_edges(pieces.vertices[:, :2], pieces.offsets, src,
                              scene.dev[..., :2], scene.count)
        at = pieces.offsets
        kept: List[int] = []
        extra: List[Path] = []
        for p in apart.tolist():
            flags = on[at[p]:at[p + 1]]
            if flags.all():
                extra.append(fills[p])            # the whole outline: the fill's path
            elif flags.any():
                extra.append(_edge_path(pieces.vertices[at[p]:at[p + 1], :2], flags))
            else:
                continue
            kept.append(p)
        where = np.array(kept, np.int64)
        # each edge path right after its piece: fills at 2 i, edges at 2 p + 1
        order = np.argsort(np.concatenate([2 * np.arange(n), 2 * where + 1]), kind="stable")
        every = fills + extra
        paths = [every[i] for i in order]
        facecolors = np.concatenate([facecolors, np.zeros((len(where), 4))])[order]
        edgecolors = np.concatenate([edgecolors, edge[where]])[order]
        widths = np.concatenate([widths, width[where]])[order]
        aa = np.concatenate([aa, aa[where]])[order]
        styles = [styles[i] if i < n else styles[where[i - n]] for i in order]
    # one value where all agree: matplotlib scales a dash pattern per line width
    widths = widths[0] if len(widths) and (widths == widths[0]).all() else widths
    aa = aa[0] if len(aa) and (aa == aa[0]).all() else aa
    coll = PathCollection(paths, facecolors=facecolors, edgecolors=edgecolors,
                          linewidths=widths, antialiaseds=aa, transform=IdentityTransform())
    # matplotlib's stub omits the (offset, None) of a solid line, which its own
    # collections store and return (get_linestyle)
    if styles is not None and len({str(s) for s in styles}) > 1:
        coll.set_linestyle(styles)  # type: ignore[arg-type]
    elif styles:
        coll.set_linestyle(styles[0])  # type: ignore[arg-type]
    return coll


def hidden_lines(segments: Floats, depth: Floats, sp: ScreenPolygons
                 ) -> Tuple[Floats, Ints, Floats, Ints]:
    """:func:`scanline.visible.hidden_lines` of ``segments`` against ``sp``, on tiles
    of segments when they and the polygons are many (each tile against the polygons
    overlapping it): ``(visible, visible_of, hidden, hidden_of)`` in segment order."""
    S = len(segments)
    if not S:
        e = np.empty((0, 4))
        return e, np.empty(0, np.int64), e, np.empty(0, np.int64)
    if not len(sp):
        return segments, np.arange(S), np.empty((0, 4)), np.empty(0, np.int64)
    if S * len(sp) <= TILE_WORK:
        vis, hid, vis_of, hid_of = visible.hidden_lines(segments, depth, sp)
        return vis, vis_of, hid, hid_of
    ext = sp.extents()
    lo = np.minimum(segments[:, :2], segments[:, 2:])
    hi = np.maximum(segments[:, :2], segments[:, 2:])
    mid = (lo + hi) / 2
    tiles = int(np.ceil(np.sqrt(S * len(sp) / TILE_WORK)))
    a, b = mid.min(axis=0), mid.max(axis=0)
    cell = np.maximum((b - a) / tiles, 1e-9)
    ij = np.minimum(((mid - a) / cell).astype(np.int64), tiles - 1)
    key = ij[:, 1] * tiles + ij[:, 0]
    out: List[List[NDArray[Any]]] = [[], [], [], []]
    for t in np.unique(key):
        sel = np.flatnonzero(key == t)
        x0, y0 = lo[sel].min(axis=0)
        x1, y1 = hi[sel].max(axis=0)
        near = np.flatnonzero((ext[:, 0] <= x1) & (ext[:, 1] >= x0) & (ext[:, 2] <= y1)
                              & (ext[:, 3] >= y0))
        if not len(near):
            out[0].append(segments[sel])
            out[1].append(sel)
            continue
        vis, hid, vis_of, hid_of = visible.hidden_lines(segments[sel], depth[sel],
                                                        sp.subset(near))
        out[0].append(vis)
        out[1].append(sel[vis_of])
        out[2].append(hid)
        out[3].append(sel[hid_of])
    vis, vis_of = np.concatenate(out[0]), np.concatenate(out[1])
    hid = np.concatenate(out[2]) if out[2] else np.empty((0, 4))
    hid_of = np.concatenate(out[3]) if out[3] else np.empty(0, np.int64)
    o = np.argsort(vis_of, kind="stable")
    h = np.argsort(hid_of, kind="stable")
    return vis[o], vis_of[o], hid[h], hid_of[h]


def margins(scene: Scene, rows: Ints) -> Floats:
    """How far behind each polygon ``rows`` of the scene a line or a marker may lie
    and still count as in front of it: its polygon's bend (a surface drawn on
    planes or triangles is uncertain by that much) plus the depth the polygon's
    plane changes over half a device pixel (positions on the screen are not known
    better than that; a sliver of a surface seen edge-on, thinner than a pixel,
    hides nothing drawn along it)."""
    A, B, C = scene.sp.planes[rows, :3].T
    with np.errstate(invalid="ignore", divide="ignore"):
        slope = np.hypot(A, B) / C
    slope = np.where(np.isfinite(slope), slope, 1e300)
    return EPS + scene.bent[rows] + 0.5 * slope


def pushed(scene: Scene, rows: Ints) -> ScreenPolygons:
    """The polygons ``rows`` of the scene, each moved back (away from the viewer) by
    its :func:`margins`: what the hidden-line test compares lines with."""
    sp = scene.sp.subset(rows)
    m = np.minimum(margins(scene, rows), 1e6)
    counts = np.diff(sp.offsets)
    verts = sp.vertices.copy()
    verts[:, 2] += np.repeat(m, counts)
    planes = sp.planes.copy()
    planes[:, 3] -= planes[:, 2] * m
    return visible.ScreenPolygons(verts, sp.offsets, sp.face, planes, sp.width, sp.height)


def line_parts(scene: Scene) -> Tuple[Floats, Ints, Floats, Ints, int]:
    """The parts of the scene's segments in front of every opaque polygon, as
    ``(above, above_of, below, below_of, hidden_count)``: ``below`` those of them behind a
    translucent polygon (drawn before the polygons, so that the polygons veil them),
    ``above`` the rest (each polygon moved back by its :func:`margins`)."""
    seg, dep = scene.segments, scene.seg_depth
    opaque = scene.opaque
    vis, vis_of, hid, _ = hidden_lines(seg, dep, pushed(scene, np.flatnonzero(opaque)))
    if opaque.all() or not len(vis):
        return vis, vis_of, np.empty((0, 4)), np.empty(0, np.int64), len(hid)
    vdep = g.depth_along(vis, vis_of, seg, dep)
    above, a_of, below, b_of = hidden_lines(vis, vdep, pushed(scene, np.flatnonzero(~opaque)))
    return above, vis_of[a_of], below, vis_of[b_of], len(hid)


def point_masks(scene: Scene) -> Tuple[List[Bools], List[Bools]]:
    """For each marker source, the markers seen (not behind an opaque polygon, by more
    than its :func:`margins`) and of them those behind a translucent one."""
    opaque = scene.opaque
    rows_o = np.flatnonzero(opaque)
    sp_o = scene.sp.subset(rows_o)
    rows_t = np.flatnonzero(~opaque)
    sp_t = scene.sp.subset(rows_t) if len(rows_t) else None
    seen: List[Bools] = []
    veiled: List[Bools] = []
    for pt in scene.points:
        d = pt.device
        hid = g.hidden_points(d[:, 0], d[:, 1], d[:, 2], sp_o, margins(scene, rows_o))
        hid |= ~np.isfinite(d).all(axis=1)
        keep = ~hid
        behind = np.zeros(len(d), bool)
        if sp_t is not None and keep.any():
            behind[keep] = g.hidden_points(d[keep, 0], d[keep, 1], d[keep, 2], sp_t,
                                           margins(scene, rows_t))
        seen.append(keep & ~behind)
        veiled.append(keep & behind)
    return seen, veiled


def draw(renderer: RendererBase, scene: Scene, owner: "Occlusion",
         max_pieces: Optional[int] = None) -> _scene.Numbers:
    """Draw the scene by the vector route; returns the numbers for the record."""
    fig = _scene.figure_of(owner)
    pieces = visible.depth_sort(scene.sp, max_pieces=max_pieces)

    def clip(artist: Collection) -> Collection:
        artist.set_figure(fig)
        artist.set_clip_on(owner.get_clip_on())
        artist.set_clip_box(owner.get_clip_box())
        artist.set_clip_path(owner.get_clip_path())
        artist.set_rasterized(owner.get_rasterized())
        return artist

    coll = clip(pieces_collection(scene, pieces))
    if owner.get_gid() is not None:
        coll.set_gid(f"{owner.get_gid()}-pieces")
    above, a_of, below, b_of, hidden = line_parts(scene)
    scale = max(scene.width, scene.height)
    under: List[_scene.Drawing] = []
    if len(below):
        v, o, lines = g.polylines(below, b_of, scene.seg_line, scale)
        under += _scene.line_artists(scene, v, o, lines, fig, clip)
    seen, veiled = point_masks(scene)
    under += _scene.point_artists(scene, veiled, fig, clip)
    v, o, lines = g.polylines(above, a_of, scene.seg_line, scale)
    over = _scene.line_artists(scene, v, o, lines, fig, clip)
    over += _scene.point_artists(scene, seen, fig, clip)
    for artist in under + [coll] + over:
        artist.draw(renderer)
    return {"pieces": len(pieces), "segments": len(scene.segments),
            "hidden parts": hidden, "points hidden": int(sum(
                (~m & ~w).sum() for m, w in zip(seen, veiled)))}
