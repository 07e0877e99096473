"""Correct occlusion for matplotlib's 3-D axes.

matplotlib's ``mplot3d`` paints each polygon whole, ordered by one depth per polygon
(the painter's one-key sort, Hearn & Baker section 13-6: a "2.5D" renderer, as its
maintainers say), and each line and marker collection as one unit among them:
two planes that cross are painted one over the other everywhere, a line through a
surface is drawn wholly in front of it or wholly behind it, interleaved ``bar3d``
bars overlap wrongly.  :func:`render_axes` makes an ``Axes3D`` draw its surfaces,
lines and markers with the visibility scanline computes:

>>> import matplotlib
>>> matplotlib.use("Agg")
>>> import matplotlib.pyplot as plt, numpy as np
>>> import scanline.mpl
>>> fig = plt.figure(figsize=(3, 3))
>>> ax = fig.add_subplot(projection="3d")
>>> X, Y = np.meshgrid([-1, 1], [-1, 1])
>>> _ = ax.plot_surface(X, Y, 0.5 * X, color="tab:blue")
>>> _ = ax.plot_surface(X, Y, -0.5 * X, color="tab:orange")
>>> occlusion = scanline.mpl.render_axes(ax)          # method="vector"
>>> fig.canvas.draw()
>>> occlusion.last.polygons, occlusion.last.pieces       # one plane cut by the other
(2, 3)
>>> plt.close(fig)

**Vector route** (``method="vector"``): the polygons of the 3-D collections
(``plot_surface``, ``plot_trisurf``, ``bar3d``, ``voxels``, ``Poly3DCollection``,
and ``ax.bar``'s patches), with the face and edge colors matplotlib computed (its
colormap and shading), are projected by the axes' own matrix into display
coordinates; polygons that are not convex or not planar are cut into triangles (a
convex one bent out of its plane by at most ``flatness`` of its size is kept whole,
on its plane); the depth-sorting method (:func:`scanline.visible.depth_sort`:
Newell, Newell and Sancha's tests, reordering, and splitting where polygons
intersect or overlap cyclically) orders them back to front, and one 2-D path
collection draws the pieces in that order.  Lines (``plot``, ``Line3DCollection``:
``plot_wireframe``, ``quiver``, ``stem``) are cut where surfaces hide them
(:func:`scanline.visible.hidden_lines`) and only their visible parts drawn; markers
(``scatter``, a line's markers) behind a surface are left out.  The output is
paths: SVG and PDF stay vector.

**Raster route** (``method="raster"``): the polygons are drawn into a z-buffer image
the size of the axes (:func:`scanline.draw.triangles` with a
:class:`~scanline.DepthBuffer`, ``samples`` x ``samples`` per pixel, averaged),
placed in the axes; lines and markers are tested against the depth buffer and drawn
as vector artists over it.  Its time hardly grows with the polygons: for big scenes.

The axes, ticks, panes, labels, legends and other artists are left as they are.
"""

from dataclasses import dataclass
from typing import Iterable, Literal, Optional, Tuple

try:
    from matplotlib.artist import Artist
    from matplotlib.backend_bases import RendererBase
    from mpl_toolkits.mplot3d import Axes3D
except ImportError as e:      # pragma: no cover - matplotlib is an optional dependency
    raise ImportError("scanline.mpl works on matplotlib figures: pip install matplotlib "
                      f"({e})") from e

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError, DepthSortLoopError, ScanlineWarning
from . import _raster, _scene, _sources, _vector
from ._sources import Artist3D

__all__ = ["METHODS", "Occlusion", "Drawn", "render_axes"]

#: The routes of :func:`render_axes`.
METHODS = ("vector", "raster")


@dataclass(frozen=True)
class Drawn:
    """What the last draw of an :class:`Occlusion` did.

    Parameters
    ----------
    method : str
        The route taken ("vector", or "raster", also when the vector route gave up).
    polygons : int
        matplotlib's polygons drawn (all collections).
    units : int
        The convex planar polygons standing for them (after triangulation).
    pieces : int or None
        The pieces the depth sort drew (vector route), more than ``units`` where
        polygons were split.
    segments : int
        Line segments tested (lines, and outlines of polygons).
    hidden_parts : int
        Parts of segments found hidden (vector route).
    points : int
        Markers tested.
    points_hidden : int
        Those of the ``points`` found hidden.
    image : tuple or None
        The raster route's image size in pixels (width, height).
    fell_back : bool
        The depth sort could not order the polygons in bounded work (a scene of very
        many intersecting polygons) and the raster route drew them instead (with a
        warning).

    Examples
    --------
    Two planes through the x axis, tilted opposite ways (z = x/2 and z = -x/2), cross
    along it: each hides the other on one side, so the depth sort splits one of them
    there and draws 3 pieces for the 2 polygons; no line or marker was drawn:

    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt, numpy as np
    >>> import scanline.mpl
    >>> fig = plt.figure(figsize=(3, 3))
    >>> ax = fig.add_subplot(projection="3d")
    >>> X, Y = np.meshgrid([-1, 1], [-1, 1])
    >>> _ = ax.plot_surface(X, Y, 0.5 * X)
    >>> _ = ax.plot_surface(X, Y, -0.5 * X)
    >>> occlusion = scanline.mpl.render_axes(ax)
    >>> fig.canvas.draw()
    >>> d = occlusion.last
    >>> d.method, d.polygons, d.units, d.pieces, d.segments, d.points, d.fell_back
    ('vector', 2, 2, 3, 0, 0, False)
    >>> plt.close(fig)
    """

    method: str
    polygons: int
    units: int
    pieces: Optional[int]
    segments: int
    hidden_parts: int
    points: int
    points_hidden: int
    image: Optional[Tuple[int, int]]
    fell_back: bool = False


def _hidden(*args: object, **kwargs: object) -> bool:
    """``get_visible`` of an adopted artist: matplotlib neither projects nor draws it
    (its own ``_visible`` flag, which legends copy, stays as it was)."""
    return False


class Occlusion(Artist):
    """The artist that draws an Axes3D's 3-D artists with correct visibility
    (made by :func:`render_axes`; remove it with :meth:`remove` to give them back to
    matplotlib).

    Each draw reads the adopted artists' current data, colors and visibility, the
    axes' current projection and size, and computes what is seen: after the view
    changes (``view_init``, the mouse, new limits) the next draw is right again.
    Its attributes ``method``, ``flatness``, ``samples`` and ``max_pieces`` may be
    changed between draws; :attr:`last` says what the last draw did.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
        The axes whose artists it draws.
    sources : iterable of (artist, str)
        The adopted 3-D artists, each with its kind ("polygons", "lines", "line",
        "points" or "patch"), as :func:`render_axes` collects them.
    method, flatness, samples, max_pieces
        As :func:`render_axes` takes them (checked at each draw).

    Examples
    --------
    Made by :func:`render_axes`, which adopts the axes' 3-D artists; matplotlib's
    own drawing of them is switched off until :meth:`remove`:

    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt, numpy as np
    >>> import scanline.mpl
    >>> fig = plt.figure(figsize=(3, 3))
    >>> ax = fig.add_subplot(projection="3d")
    >>> X, Y = np.meshgrid([-1, 1], [-1, 1])
    >>> surface = ax.plot_surface(X, Y, 0.5 * X)
    >>> occlusion = scanline.mpl.render_axes(ax, method="raster")
    >>> [kind for _, kind in occlusion.sources], surface.get_visible()
    (['polygons'], False)
    >>> plt.close(fig)
    """

    def __init__(self, ax: "Axes3D", sources: Iterable[Tuple[Artist3D, str]],
                 method: Literal["vector", "raster"] = "vector", flatness: float = 0.05,
                 samples: int = 2, max_pieces: Optional[int] = None) -> None:
        super().__init__()
        self.axes = ax
        self.sources = list(sources)
        self.method: str = method
        self.flatness = flatness
        self.samples = samples
        self.max_pieces = max_pieces
        self.last: Optional[Drawn] = None
        self.set_in_layout(False)
        self.set_zorder(max(a.get_zorder() for a in (ax.xaxis, ax.yaxis, ax.zaxis)) + 1)

    def _adopt(self) -> None:
        for artist, _ in self.sources:
            artist.get_visible = _hidden
            artist.stale = True

    def _release(self) -> None:
        for artist, _ in self.sources:
            if artist.__dict__.get("get_visible") is _hidden:
                del artist.get_visible
            artist.stale = True
        self.sources = []

    def remove(self) -> None:
        """Give the artists back to matplotlib (its own drawing) and leave the axes.

        Examples
        --------
        >>> import matplotlib
        >>> matplotlib.use("Agg")
        >>> import matplotlib.pyplot as plt, numpy as np
        >>> import scanline.mpl
        >>> fig = plt.figure(figsize=(3, 3))
        >>> ax = fig.add_subplot(projection="3d")
        >>> X, Y = np.meshgrid([-1, 1], [-1, 1])
        >>> surface = ax.plot_surface(X, Y, 0.5 * X)
        >>> occlusion = scanline.mpl.render_axes(ax)
        >>> occlusion.remove()
        >>> surface.get_visible(), occlusion in ax.get_children()
        (True, False)
        >>> plt.close(fig)
        """
        self._release()
        super().remove()

    def draw(self, renderer: RendererBase) -> None:
        """Draw the adopted artists with the visibility computed for this draw's view
        (and record what was done in :attr:`last`).  matplotlib calls it when the figure
        is drawn.

        Parameters
        ----------
        renderer : matplotlib.backend_bases.RendererBase
            The figure's renderer (Agg, SVG, PDF ...).

        Examples
        --------
        The raster route draws the polygons as one z-buffer image the size of the axes
        (a 3 x 3 inch figure at 100 dpi is 300 x 300 pixels; the axes take part of it):

        >>> import matplotlib
        >>> matplotlib.use("Agg")
        >>> import matplotlib.pyplot as plt, numpy as np
        >>> import scanline.mpl
        >>> fig = plt.figure(figsize=(3, 3), dpi=100)
        >>> ax = fig.add_subplot(projection="3d")
        >>> X, Y = np.meshgrid([-1, 1], [-1, 1])
        >>> _ = ax.plot_surface(X, Y, 0.5 * X)
        >>> occlusion = scanline.mpl.render_axes(ax, method="raster")
        >>> fig.canvas.draw()                      # calls occlusion.draw(renderer)
        >>> w, h = occlusion.last.image
        >>> occlusion.last.method, 0 < w <= 300 and 0 < h <= 300
        ('raster', True)
        >>> plt.close(fig)
        """
        if not self.get_visible():
            return
        method = v.choice("method", self.method, METHODS)
        flatness = _flatness(self.flatness)
        samples = _samples(self.samples)
        max_pieces = (None if self.max_pieces is None
                      else v.positive_int("max_pieces", self.max_pieces))
        ax: "Axes3D" = self.axes
        M = getattr(ax, "M", None)
        if M is None:
            M = ax.get_proj()
        width, height = renderer.get_canvas_width_height()
        scene = _scene.collect(ax, self.sources, M, max(1, int(width)), max(1, int(height)),
                               flatness)
        fell_back = False
        numbers: Optional[_scene.Numbers] = None
        if method == "vector":
            try:
                numbers = _vector.draw(renderer, scene, self, max_pieces)
            except DepthSortLoopError as e:
                import warnings

                warnings.warn(f"scanline.mpl: the vector route gave up ({e}); this draw "
                              "used the raster route", ScanlineWarning, stacklevel=2)
                fell_back = True
        if numbers is None:
            numbers = _raster.draw(renderer, scene, self, samples, scene.slack)
        self.last = Drawn(
            method="raster" if fell_back or method == "raster" else "vector",
            polygons=len(scene.count), units=len(scene.sp), pieces=numbers.get("pieces"),
            segments=len(scene.segments), hidden_parts=numbers.get("hidden parts", 0),
            points=sum(len(p.world) for p in scene.points),
            points_hidden=numbers["points hidden"], image=numbers.get("image"),
            fell_back=fell_back)
        self.stale = False


def _flatness(value: object) -> float:
    x = v.number("flatness", value)
    if x < 0:
        raise ArgumentValueError(f"flatness must be >= 0 (a fraction of a polygon's size), "
                                 f"got {value!r}")
    return x


def _samples(value: object) -> int:
    s = v.positive_int("samples", value)
    if s > 8:
        raise ArgumentValueError(f"samples must be 1 .. 8 (samples x samples per pixel), "
                                 f"got {value!r}")
    return s


def render_axes(ax: "Axes3D", method: Literal["vector", "raster"] = "vector", *,
                flatness: float = 0.05, samples: int = 2,
                max_pieces: Optional[int] = None) -> "Occlusion":
    """Draw a matplotlib 3-D axes with correct visibility, from now on.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
        The axes (``fig.add_subplot(projection="3d")``).  Its polygon collections
        (``plot_surface``, ``plot_trisurf``, ``bar3d``, ``voxels``,
        ``Poly3DCollection``), lines (``plot``, ``Line3D``, ``Line3DCollection``) and
        markers (``scatter``) present now are drawn by scanline; matplotlib keeps
        drawing the rest (axes, panes, ticks, labels, text, legends, 2-D artists,
        patches, ``contourf``'s polygons with holes) as before.
    method : {"vector", "raster"}
        "vector": the polygons ordered and split by the depth-sorting method, drawn
        as paths (SVG, PDF stay vector).  "raster": a z-buffer image of the polygons
        placed in the axes (big scenes).  Lines and markers are vector in both.
    flatness : float
        A convex polygon whose vertices leave its plane by at most this fraction of
        its size is drawn whole (as matplotlib draws it) and sorted on its plane
        (Newell's); one bent more is cut into triangles.  0: every bent polygon is cut
        (exact for the surface of triangles; a fine surface then shows the faint
        seams of antialiasing along the cuts).  Vector route.
    samples : int
        Raster route: ``samples`` x ``samples`` depth-buffer samples per pixel,
        averaged (1 .. 8; 2: antialiased edges).
    max_pieces : int, optional
        Most pieces the depth sort may make (default: its own,
        :func:`scanline.visible.depth_sort`); past it the draw falls back to the
        raster route with a warning.

    Returns
    -------
    Occlusion
        The artist now drawing them: ``.last`` says what the last draw did;
        ``.remove()`` gives the artists back to matplotlib.

    Raises
    ------
    ArgumentTypeError
        ``ax`` is not a 3-D axes.
    ArgumentValueError
        ``method`` is not one of :data:`METHODS`; ``flatness``, ``samples`` or
        ``max_pieces`` out of range.

    Notes
    -----
    The artists stay in the axes (their data, colors and visibility are read at each
    draw; legends show them); matplotlib no longer projects or draws them.  Each draw
    computes visibility for the view of that draw, so rotating the axes
    interactively, ``view_init`` or new limits are drawn right.  Artists added
    after this call are drawn by matplotlib until :func:`render_axes` is called again
    (which adopts them too).

    Polygons are projected with ``ax.M`` (``ax.get_proj()``), the matrix matplotlib
    projects with, through the axes' scales, and mapped to display coordinates by
    ``ax.transData``: x, y in pixels (points for vector back ends), and
    matplotlib's projected depth scaled to 0 .. 1.  A perspective projection maps
    planes to planes, so the device-space plane tests of the depth sort hold.

    Translucent polygons are sorted with the rest, so they are blended back to front
    in the vector route.  Lines and markers behind a translucent polygon (and in
    front of every opaque one) are drawn beneath all polygons, so that the nearest
    veil covers them (a line between two translucent surfaces is veiled by both).
    The raster route keeps the nearest opaque and the nearest translucent surface at
    each pixel.

    Hearn & Baker, section 13-6 (depth sorting), 13-3 (the depth buffer), 13-10
    (visible lines).

    References
    ----------
    M. E. Newell, R. G. Newell and T. L. Sancha, "A solution to the hidden surface
    problem", Proceedings of the ACM Annual Conference, 1972.  E. Catmull, "A
    subdivision algorithm for computer display of curved surfaces", PhD thesis,
    University of Utah, 1974 (the depth buffer).  G. H. Meisters, "Polygons have
    ears", American Mathematical Monthly 82(6), 1975 (ear clipping).

    Examples
    --------
    See the module's example, and docs/mpl.md.
    """
    if not isinstance(ax, Axes3D):
        raise ArgumentTypeError(
            "ax must be a matplotlib 3-D axes (mpl_toolkits.mplot3d.Axes3D, made by "
            f"fig.add_subplot(projection='3d')), got {v._show(ax)}")
    v.choice("method", method, METHODS)
    flatness = _flatness(flatness)
    samples = _samples(samples)
    if max_pieces is not None:
        max_pieces = v.positive_int("max_pieces", max_pieces)
    for child in list(ax.get_children()):
        if isinstance(child, Occlusion):
            child.remove()
    sources = [(a, k) for a in ax.get_children() if (k := _sources.kind_of(a)) is not None]
    occlusion = Occlusion(ax, sources, method, flatness, samples, max_pieces)
    ax.add_artist(occlusion)
    occlusion._adopt()
    occlusion.set_clip_path(ax.patch)
    ax.stale = True
    return occlusion

