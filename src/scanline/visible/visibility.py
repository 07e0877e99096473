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

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Optional

import numpy as np

from ..screen.polygons import ScreenPolygons


@dataclass
class VisibleFaces:
    """What an image-space method sees: the face at each pixel and its depth.

    Attributes
    ----------
    face : ndarray of int64, shape (height, width)
        ``face[y, x]`` is the face visible at pixel (x, y) (row y is scan line y,
        bottom-up like the frame buffer's storage), -1 for the background.
    depth : ndarray, shape (height, width)
        Its depth (inf for the background).
    """

    face: np.ndarray
    depth: np.ndarray


@dataclass(frozen=True, eq=False)
class Layer:
    """The visible triangle and its depth at each pixel of a ``width`` x ``height``
    device (rows bottom-up, as the frame buffer stores them).

    Attributes
    ----------
    ids : ndarray of int64 (H, W)
        The index of the scene's device triangle seen at each pixel, -1 where none.
    depth : ndarray (H, W)
        Its depth (inf where none).
    pieces : ScreenPolygons or None
        For an object-order method, the pieces in drawing order (``face`` holds the
        facet of each): what the method decided, before it was painted.
    """
    ids: np.ndarray
    depth: np.ndarray
    pieces: Optional[ScreenPolygons] = None


@dataclass(frozen=True, eq=False)
class Fragments:
    """Layers of fragments at ``samples`` x ``samples`` points per pixel, front to back:
    ``layers`` yields :class:`Layer` objects of the supersampled size (H s, W s), each
    holding at every sample the nearest fragment behind the previous layer's, until no
    sample has one left or an opaque fragment has been found at every sample."""
    samples: int
    layers: Iterator[Layer]


def plane_depth(scene, facets, xs, ys):
    """The depth of the planes of ``facets`` at device points (``xs``, ``ys``)."""
    a, b, c, d = scene.planes[facets].T
    return -(a * xs + b * ys + d) / c


def facet_layer(scene, facets, depth=None):
    """A :class:`Layer` from a buffer of facets (H, W; -1 none): each facet's stand-in
    triangle (:attr:`~scanline.screen.ScreenScene.facet_triangle`), and the depth
    (default: its plane's at each pixel center)."""
    ids = np.full(facets.shape, -1, np.int64)
    ys, xs = np.nonzero(facets >= 0)
    f = facets[ys, xs]
    ids[ys, xs] = scene.facet_triangle[f]
    if depth is None:
        depth = np.full(facets.shape, np.inf)
        depth[ys, xs] = plane_depth(scene, f, xs, ys)
    return Layer(ids, depth)


def piece_numbers(pieces, numbers=None, first=0):
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


def painted(scene, pieces, numbers=None):
    """The :class:`Layer` of ``pieces`` (:class:`ScreenPolygons` in drawing order,
    ``face`` the facet of each) painted in order (:func:`piece_numbers`, unless
    ``numbers`` holds them already: the depth sort paints beside the sort)."""
    if numbers is None:
        numbers = piece_numbers(pieces)
    facets = np.full(numbers.shape, -1, np.int64)
    seen = numbers >= 0
    facets[seen] = pieces.face[numbers[seen]]
    layer = facet_layer(scene, facets)
    return Layer(layer.ids, layer.depth, pieces)
