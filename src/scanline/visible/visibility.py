"""What a visible-surface method hands to the shading: what is seen, never a color.

* :class:`Layer`: per pixel (or per sample), the scene's device triangle seen there
  (-1: nothing) and its depth.  Image-space methods find it directly; the object-order
  methods' pieces are painted into one, in drawing order (:func:`painted`), which is the
  raster half of the painter's algorithm.  A triangle stands for its facet: the
  shading finds the barycentric coordinates of the pixel center from the triangle's
  screen-space interpolation functions, which every triangle of the facet shares.
* :class:`Fragments`: for the A-buffer, the layers of fragments behind one another at
  every sample, front to back, made one at a time as the shading composites them.
"""

import functools
from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Optional, Tuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..screen.polygons import ScreenPolygons

if TYPE_CHECKING:
    from ..screen.scene import ScreenScene


class VisibleFaces:
    """What an image-space method sees: the polygon at each pixel and its depth.

    Attributes
    ----------
    polygon : ndarray of int32 or int64, shape (height, width)
        ``polygon[y, x]`` is the number of the polygon visible at pixel (x, y) (row y
        is scan line y, bottom-up like the frame buffer's storage), -1 for the
        background.
    face : ndarray of int, shape (height, width)
        The source face of that polygon (-1 for the background).
    depth : ndarray, shape (height, width)
        Its depth (inf for the background).
    areas : int
        :func:`~scanline.visible.area_subdivision` only: the areas it decided.
    regions : ndarray of int64 (n, 5)
        :func:`~scanline.visible.area_subdivision` only: the regions it recorded.
    compared : int
        :func:`~scanline.visible.scan_line` only: the surfaces it compared.

    Parameters
    ----------
    polygon : ndarray of int32 or int64 (height, width)
        The polygon at each pixel (-1: none).
    depth : ndarray (height, width)
        Its depth.
    faces : ndarray of int64
        The source face of each polygon (empty: the polygons are the faces).

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> seen = sl.visible.VisibleFaces(np.array([[0, -1, 1]]), np.zeros((1, 3)), np.array([7, 9]))
    >>> seen.face.tolist()
    [[7, -1, 9]]
    """

    areas: int
    regions: NDArray[np.int64]
    compared: int

    def __init__(self, polygon: NDArray[np.signedinteger[Any]], depth: NDArray[np.float64],
                 faces: NDArray[np.int64]) -> None:
        self.polygon = polygon
        self.depth = depth
        self._faces = faces

    @functools.cached_property
    def face(self) -> NDArray[np.signedinteger[Any]]:
        if not len(self._faces):
            return self.polygon
        return np.where(self.polygon >= 0, self._faces[np.maximum(self.polygon, 0)], -1)


@dataclass(frozen=True, eq=False)
class Layer:
    """The visible triangle and its depth at each pixel of a ``width`` x ``height``
    device (rows bottom-up, as the frame buffer stores them).

    Attributes
    ----------
    ids : ndarray of int32 (H, W)
        The index of the scene's device triangle seen at each pixel, -1 where none.
    depth : ndarray (H, W)
        Its depth (inf where none).
    pieces : ScreenPolygons or None
        For an object-order method, the pieces in drawing order (``face`` holds the
        facet of each): what the method decided, before it was painted.

    Parameters
    ----------
    ids, depth, pieces
        As listed under Attributes.

    Examples
    --------
    The z-buffer's layer of a 2-cube seen head on: the front face's two device
    triangles (face 5's, numbers 10 and 11: two per face) cover the middle pixels.

    >>> import numpy as np, scanline as sl
    >>> from scanline.screen import prepare
    >>> from scanline.visible.zbuffer import nearest
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> layer = nearest(prepare(sl.mesh.cube(2), cam, 4, 4))
    >>> np.unique(layer.ids).tolist(), int(np.isfinite(layer.depth).sum())
    ([-1, 10, 11], 4)
    """
    ids: NDArray[np.int32]
    depth: NDArray[np.float64]
    pieces: Optional[ScreenPolygons] = None


@dataclass(frozen=True, eq=False)
class Fragments:
    """Layers of fragments at ``samples`` x ``samples`` points per pixel, front to back,
    band of rows after band of rows: ``bands`` yields ``(y0, rows, layers)``, where
    ``layers`` yields :class:`Layer` objects of the band's supersampled size (rows s,
    W s), each holding at every sample the nearest fragment behind the previous
    layer's, until no sample has one left or an opaque fragment has been found at
    every sample.

    Parameters
    ----------
    samples : int
        Samples per pixel side.
    bands : iterator of (y0, rows, layers)
        The bands, made as they are read.

    Examples
    --------
    >>> import scanline as sl
    >>> empty = sl.visible.Fragments(3, iter([]))
    >>> empty.samples, list(empty.bands)
    (3, [])
    """
    samples: int
    bands: Iterator[Tuple[int, int, Iterator[Layer]]]


def facet_layer(scene: "ScreenScene", polygons: NDArray[np.signedinteger[Any]],
                table: ArrayLike, depth: Optional[NDArray[np.float64]] = None) -> Layer:
    """A :class:`Layer` from a buffer of polygon numbers (H, W int32; -1 none) whose
    labels are ``table`` (the ``face`` of polygons of the scene's
    :attr:`~scanline.screen.ScreenScene.screen_polygons`, or of pieces of them): the
    stand-in triangle (:attr:`~scanline.screen.ScreenScene.facet_triangle`) of the
    facet under each pixel center, and the depth (default: that facet's plane's at the
    pixel center), in one compiled pass
    (:func:`scanline._kernels.visible.resolve_labels`)."""
    from .._kernels._threads import call_in_bands
    from .._kernels.visible import resolve_labels

    h, w = polygons.shape
    ids = np.empty((h, w), np.int32)
    out = np.empty((h, w)) if depth is None else depth
    call_in_bands(resolve_labels, 3 * h * w, np.ascontiguousarray(polygons, np.int32),
                  np.ascontiguousarray(table, np.int64), scene.fans, scene.facet_triangle,
                  np.ascontiguousarray(scene.triangles), np.ascontiguousarray(scene.planes),
                  ids, out, depth is None)
    return Layer(ids, out)


def piece_numbers(pieces: ScreenPolygons, numbers: Optional[NDArray[np.int32]] = None,
                  first: int = 0) -> NDArray[np.int32]:
    """The number of the piece seen at each pixel when ``pieces`` (convex
    :class:`ScreenPolygons`, numbered ``first``, ``first + 1`` ...) are painted one
    after the other, later over earlier, by the spans of the 2-D polygon fill (Hearn
    & Baker 3-11): the raster half of the painter's algorithm.  ``numbers``: the int32
    buffer (height x width) to paint into (default a new one, -1 where no piece is)."""
    from .._kernels._threads import call_in_bands
    from .._kernels.visible import paint_numbers

    w, h = pieces.width, pieces.height
    if numbers is None:
        numbers = np.full((h, w), -1, np.int32)
    if len(pieces):
        verts = np.ascontiguousarray(pieces.vertices, np.float64)
        # work: a frame's worth of pixels and ten units a vertex (the pieces' own
        # areas would cost more to add up than small scenes take to paint)
        call_in_bands(paint_numbers, w * h + 10 * len(verts), w, h, verts,
                      np.ascontiguousarray(pieces.offsets, np.int64), first, numbers)
    return numbers


def painted(scene: "ScreenScene", pieces: ScreenPolygons,
            numbers: Optional[NDArray[np.int32]] = None) -> Layer:
    """The :class:`Layer` of ``pieces`` (:class:`ScreenPolygons` in drawing order,
    ``face`` the label of each, as in the scene's polygons) painted in order
    (:func:`piece_numbers`, unless ``numbers`` holds them already: the depth sort
    paints beside the sort)."""
    if numbers is None:
        numbers = piece_numbers(pieces)
    layer = facet_layer(scene, numbers, pieces.face)
    return Layer(layer.ids, layer.depth, pieces)
