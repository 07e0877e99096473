"""One draw's scene for :mod:`scanline.mpl`: the adopted artists read and projected
into device space (the canvas's display coordinates, depth normalized to 0 .. 1),
and the 2-D matplotlib artists that draw the visible parts of lines and markers.
"""

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Callable, List, Optional, Sequence, Tuple, TypedDict, TypeVar, Union

import numpy as np
from matplotlib.artist import Artist
from matplotlib.collections import Collection, LineCollection, PathCollection
from matplotlib.lines import Line2D
from matplotlib.transforms import IdentityTransform

from ..screen import ScreenPolygons
from . import _geometry as g
from . import _sources as s
from ._geometry import Bools, Floats, Ints
from ._sources import Artist3D, LineStyle

if TYPE_CHECKING:
    from matplotlib.figure import Figure, SubFigure
    from mpl_toolkits.mplot3d import Axes3D

#: The 2-D artists that draw the visible parts.
Drawing = Union[Line2D, Collection]
_A = TypeVar("_A", bound=Artist)
#: What a route's draw did, for :class:`scanline.mpl.Drawn`: both routes count the
#: markers hidden; the vector route its pieces and the parts of lines hidden, the raster
#: route its image (width, height) and samples.
Numbers = TypedDict("Numbers", {"points hidden": int, "segments": int, "pieces": int,
                                "hidden parts": int, "image": Tuple[int, int],
                                "samples": int}, total=False)
#: ``clip(artist)``: the artist set up to draw like the :class:`scanline.mpl.Occlusion`
#: (its figure and clipping), returned.
Clip = Callable[[Collection], Collection]


#: Vertices within this distance (device units: pixels, or points for vector back
#: ends) of the chord of their neighbours are dropped from polygons
#: (:func:`scanline.mpl._geometry.simplify`).
SIMPLIFY = 0.25


@dataclass
class LineSource:
    """Polylines of one artist: ``kind`` "line" (a Line3D: ``artist``), "lines" (a
    Line3DCollection: per-polyline ``color``, ``width``, ``antialiased``, ``style``)
    or "edges" (the outlines of polygons that hide nothing, styled per polygon)."""

    kind: str
    artist: Optional[Artist3D]
    world: List[Floats]
    color: Floats = field(default_factory=lambda: np.empty((0, 4)))
    width: Floats = field(default_factory=lambda: np.empty(0))
    antialiased: Bools = field(default_factory=lambda: np.empty(0, bool))
    style: List[LineStyle] = field(default_factory=list)


@dataclass
class PointSource:
    """Markers of one artist: a Path3DCollection (``kind`` "points", colors as
    matplotlib shades them, in its far-to-near order) or the markers of a Line3D
    (``kind`` "markers")."""

    kind: str
    artist: Artist3D
    world: Floats
    face: Floats = field(default_factory=lambda: np.empty((0, 4)))
    edge: Floats = field(default_factory=lambda: np.empty((0, 4)))
    sizes: Floats = field(default_factory=lambda: np.empty(0))
    widths: Floats = field(default_factory=lambda: np.empty(0))
    device: Floats = field(default_factory=lambda: np.empty((0, 3)))


@dataclass
class Scene:
    """What one draw works on (device: display coordinates of the canvas, y up;
    depth 0 .. 1 over everything drawn, greater farther)."""

    width: int
    height: int
    dev: Floats                # (N, K, 3) polygons, padded
    count: Ints                # (N,)
    face: Floats               # (N, 4) RGBA
    edge: Floats               # (N, 4) RGBA
    edge_width: Floats         # (N,) points
    antialiased: Bools         # (N,) bool
    edge_style: List[LineStyle]  # (N,) matplotlib dash tuples
    sp: ScreenPolygons         # the polygons that hide (face alpha > 0)
    lines: List[LineSource]
    segments: Floats           # (S, 4) device x0, y0, x1, y1
    seg_depth: Floats          # (S, 2)
    seg_line: Ints             # (S,) global polyline
    line_source: Ints          # (L,) index into lines
    line_row: Ints             # (L,) the polyline's row in its source
    points: List[PointSource]
    bent: Floats               # (U,) per unit of sp: depth by which its polygon is bent
    slack: float = 0.0         # lines count as in front within this depth (see collect)

    @property
    def opaque(self) -> Bools:
        """Whether each unit of ``sp`` hides what is behind it wholly (alpha 1)."""
        opaque: Bools = self.face[self.sp.face, 3] >= 1.0
        return opaque


def _dash(artist: Artist3D, n: int) -> List[LineStyle]:
    """The line style of each of ``n`` polygons of a collection or a patch."""
    styles = artist.get_linestyle()
    if isinstance(styles, (str, tuple)):
        return [styles] * n                       # a patch: one style
    return [styles[i % len(styles)] for i in range(n)] if len(styles) else [(0, None)] * n


def collect(ax: "Axes3D", sources: Sequence[Tuple[Artist3D, str]], M: Floats, width: int,
            height: int, flatness: float) -> Scene:
    """Read and project the adopted ``sources`` (visible ones) with the axes' matrix
    ``M``: a :class:`Scene`.

    A bent polygon is drawn on its plane or as triangles, which differ from the
    surface it samples by about the depth its vertices leave that plane: a line or a
    marker lying *on* the surface (the data's own points, a curve along the surface)
    would be hidden here and there by that amount.  A marker counts as in front of
    a polygon within the polygon's own bend; a line within the bend of nine polygons
    in ten (``slack``: one number for the scene, the test of lines taking one)."""
    polys: List[Tuple[Artist3D, s.Polygons]] = []
    lines: List[LineSource] = []
    points: List[PointSource] = []
    for artist, kind in sources:
        if not s.shown(artist) or artist.axes is not ax:      # hidden, or removed
            continue
        if kind in ("polygons", "patch"):
            p = s.polygons(artist) if kind == "polygons" else s.patch(artist)
            if getattr(artist, "_axlim_clip", False) and len(p):
                out = s.outside_limits(ax, p.xyz).any(axis=1)
                if out.any():
                    p = s.Polygons(p.xyz[~out], p.count[~out], p.face[~out], p.edge[~out],
                                   p.width[~out], p.antialiased[~out])
            if len(p):
                polys.append((artist, p))
        elif kind == "line":
            xyz = s.line_data(artist)
            if getattr(artist, "_axlim_clip", False):
                xyz = np.where(s.outside_limits(ax, xyz)[:, None], np.nan, xyz)
            if artist.get_linestyle() not in ("None", " ", "") and len(xyz) > 1:
                lines.append(LineSource("line", artist, [xyz]))
            if artist.get_marker() not in (None, "None", " ", "") and len(xyz):
                points.append(PointSource("markers", artist, xyz[s.markevery(artist, len(xyz))]))
        elif kind == "lines":
            strands = s.collection_lines(artist)
            if getattr(artist, "_axlim_clip", False):
                strands = [np.where(s.outside_limits(ax, w)[:, None], np.nan, w) for w in strands]
            color, lw, aa, style = s.line_colors(artist, len(strands))
            lines.append(LineSource("lines", artist, strands, color, lw, aa, style))
        elif kind == "points":
            xyz, face, edge, sizes, widths = s.points(artist, M)
            if getattr(artist, "_axlim_clip", False):
                within = ~s.outside_limits(ax, xyz)
                xyz, face, edge, sizes, widths = (v[within] for v in (xyz, face, edge, sizes,
                                                                      widths))
            points.append(PointSource("points", artist, xyz, face, edge, sizes, widths))

    # polygons, padded to one vertex count
    k = max([p.xyz.shape[1] for _, p in polys], default=3)
    n = sum(len(p) for _, p in polys)
    world = np.empty((n, k, 3))
    count = np.empty(n, np.int64)
    face, edge = np.empty((n, 4)), np.empty((n, 4))
    edge_width, aa = np.empty(n), np.empty(n, bool)
    edge_style: List[LineStyle] = []
    at = 0
    for artist, p in polys:
        m, kk = len(p), p.xyz.shape[1]
        world[at:at + m, :kk] = p.xyz
        world[at:at + m, kk:] = p.xyz[:, -1:]
        count[at:at + m] = p.count
        face[at:at + m], edge[at:at + m] = p.face, p.edge
        edge_width[at:at + m], aa[at:at + m] = p.width, p.antialiased
        edge_style += _dash(artist, m)
        at += m
    proj = s.project(ax, M, world)

    # the polylines, and the outlines of polygons that hide nothing
    hides = face[:, 3] > 0                      # a polygon with no face hides nothing
    outlined = ~hides & (edge[:, 3] > 0) & (edge_width > 0)
    if outlined.any():
        rows = np.flatnonzero(outlined)
        loops = [np.concatenate([world[i, :count[i]], world[i, :1]]) for i in rows]
        lines.append(LineSource("edges", None, loops, edge[rows], edge_width[rows], aa[rows],
                                [edge_style[i] for i in rows]))
    line_world = [w for src in lines for w in src.world]
    line_source = np.repeat(np.arange(len(lines)), [len(src.world) for src in lines])
    line_row = np.concatenate([np.arange(len(src.world)) for src in lines]) if lines else \
        np.empty(0, np.int64)
    lengths = np.array([len(w) for w in line_world], np.int64)
    lw = np.concatenate(line_world) if line_world else np.empty((0, 3))
    lproj = s.project(ax, M, lw)
    pproj = [s.project(ax, M, pt.world) for pt in points]

    # one depth scale for all
    zs = [proj[..., 2].ravel(), lproj[:, 2]] + [p[:, 2] for p in pproj]
    z = np.concatenate(zs)
    z = z[np.isfinite(z)]
    lo, hi = (float(z.min()), float(z.max())) if len(z) else (0.0, 1.0)
    scale = 1.0 / (hi - lo) if hi > lo else 1.0

    def device(p: Floats) -> Floats:
        d = s.to_display(ax, p)
        d[..., 2] = (d[..., 2] - lo) * scale
        return d

    dev = device(proj)
    dev, proj, count = g.simplify(dev, proj, count, SIMPLIFY)
    verts, counts, owner, bent = g.units(dev, proj, count, flatness)
    sp = g.screen_polygons(verts, counts, owner, width, height)
    if not hides.all():
        keep = np.flatnonzero(hides[sp.face])
        sp, bent = sp.subset(keep), bent[keep]
    rough = bent[bent > 0]
    slack = float(np.percentile(rough, 90)) if len(rough) else 0.0

    ldev = device(lproj)
    ends = np.cumsum(lengths)
    seg_a = np.ones(len(ldev), bool)
    seg_a[ends - 1] = False                      # the last point of a polyline starts none
    a = np.flatnonzero(seg_a)
    if len(a):
        ok = np.isfinite(ldev[a]).all(axis=1) & np.isfinite(ldev[a + 1]).all(axis=1)
        a = a[ok]
    segments = np.concatenate([ldev[a, :2], ldev[a + 1, :2]], axis=1) if len(a) else \
        np.empty((0, 4))
    seg_depth = np.stack([ldev[a, 2], ldev[a + 1, 2]], axis=1) if len(a) else np.empty((0, 2))
    seg_line = np.repeat(np.arange(len(lengths)), lengths)[a] if len(a) else np.empty(0, np.int64)

    for pt, projected in zip(points, pproj):
        pt.device = device(projected)
    return Scene(int(width), int(height), dev, count, face, edge, edge_width, aa, edge_style,
                 sp, lines, segments, seg_depth, seg_line, line_source, line_row, points,
                 bent, slack)


def figure_of(artist: Artist) -> Union["Figure", "SubFigure"]:
    """The root figure of ``artist`` (matplotlib >= 3.10 distinguishes subfigures)."""
    fig: Union["Figure", "SubFigure", None]
    try:
        fig = artist.get_figure(root=True)
    except TypeError:                              # matplotlib < 3.10
        fig = artist.figure
    assert fig is not None, "an artist being drawn is in a figure"
    return fig


def _like(artist: Artist3D, fig: Union["Figure", "SubFigure"]) -> Line2D:
    """A Line2D drawn in display coordinates with the style of Line3D ``artist``."""
    line = Line2D([], [])
    line.update_from(artist)
    line.set_transform(IdentityTransform())
    line.set_figure(fig)
    line.set_clip_box(artist.clipbox)
    line.set_clip_path(artist.get_clip_path())
    line.set_clip_on(artist.get_clip_on())
    line.set_visible(True)
    return line


def line_artists(scene: Scene, verts: Floats, offsets: Ints, line_of: Ints,
                 fig: Union["Figure", "SubFigure"], clip: Clip) -> List[Drawing]:
    """The 2-D artists drawing the joined polylines ``verts`` / ``offsets`` (of the
    scene's polylines ``line_of``): per Line3D a Line2D (its style, the parts
    separated by NaN), per Line3DCollection and per group of outlines a
    LineCollection (per-polyline colors, widths and styles)."""
    out: List[Drawing] = []
    if not len(line_of):
        return out
    src = scene.line_source[line_of]
    pieces = np.split(verts, offsets[1:-1])
    for i in np.unique(src):
        ls = scene.lines[i]
        sel = np.flatnonzero(src == i)
        if ls.kind == "line":
            data = np.concatenate([np.vstack([pieces[j], [[np.nan, np.nan]]]) for j in sel])
            line = _like(ls.artist, fig)
            line.set_marker("None")
            line.set_data(data[:, 0], data[:, 1])
            out.append(line)
        else:
            rows = scene.line_row[line_of[sel]]
            coll = LineCollection([pieces[j] for j in sel], colors=ls.color[rows],
                                  linewidths=ls.width[rows], antialiaseds=ls.antialiased[rows],
                                  linestyles=[ls.style[r] for r in rows],
                                  transform=IdentityTransform())
            if ls.artist is not None:
                if ls.artist.get_capstyle() is not None:
                    coll.set_capstyle(ls.artist.get_capstyle())
                if ls.artist.get_joinstyle() is not None:
                    coll.set_joinstyle(ls.artist.get_joinstyle())
            clip(coll)
            out.append(coll)
    return out


def point_artists(scene: Scene, shown_of: Sequence[Bools], fig: Union["Figure", "SubFigure"],
                  clip: Clip) -> List[Drawing]:
    """The 2-D artists drawing the markers kept (``shown_of[i]`` a mask over
    ``scene.points[i]``): a PathCollection like the scatter's, or a Line2D of
    markers only like the line's."""
    out: List[Drawing] = []
    for pt, keep in zip(scene.points, shown_of):
        if not keep.any():
            continue
        d = pt.device[keep]
        if pt.kind == "markers":
            line = _like(pt.artist, fig)
            line.set_linestyle("None")
            line.set_markevery(None)              # the markers kept are given as data
            line.set_data(d[:, 0], d[:, 1])
            out.append(line)
            continue
        art = pt.artist
        coll = PathCollection(art.get_paths(), sizes=pt.sizes[keep], offsets=d[:, :2],
                              offset_transform=IdentityTransform(),
                              transform=IdentityTransform(), facecolors=pt.face[keep],
                              edgecolors=pt.edge[keep], linewidths=pt.widths[keep])
        coll.set_figure(fig)
        coll.set_linestyle(art.get_linestyle())
        coll.set_antialiased(art.get_antialiased())
        clip(coll)
        out.append(coll)
    return out
