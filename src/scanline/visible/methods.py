"""Stage two of the 3-D pipeline: the visible-surface methods as one registry.

Each method takes the prepared :class:`~scanline.screen.ScreenScene` and its
:class:`MethodOptions` and returns what is visible -- a
:class:`~scanline.visible.visibility.Layer` (the triangle seen at each pixel, and for
the object-order methods the pieces in drawing order) or, for the A-buffer,
:class:`~scanline.visible.visibility.Fragments` -- and never colors anything
(:mod:`scanline.shading` does).  :func:`scanline.render` looks methods up here by
name; :func:`register` adds one.

Precision (Hearn & Baker, section 13-1): "image" methods decide visibility per pixel,
"object" methods compare surfaces with one another.
"""

from dataclasses import dataclass, fields
from typing import TYPE_CHECKING, Callable, Optional, Tuple, Union

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from .abuffer import abuffer
from .bsp import BSPTree, camera_eye
from .depth_sort import painted_depth_sort
from .octree import octree
from ..screen.polygons import ScreenPolygons
from .painter import KEYS, painter
from .raycast import raycast
from .scanline_method import scan_line
from .visibility import Fragments, Layer, VisibleFaces, facet_layer, painted
from .warnock import area_subdivision
from .zbuffer import zbuffer

if TYPE_CHECKING:
    from ..screen.scene import ScreenScene


@dataclass(frozen=True)
class MethodOptions:
    """The options of the visible-surface methods (None: the method's default).

    Attributes
    ----------
    samples : int, optional
        A-buffer: samples per pixel side, 1..8 (default 3).
    layers : int, optional
        A-buffer: most layers of fragments peeled, 1..64 (default 8).
    key : {"farthest", "mean"}, optional
        Painter: each polygon's sort key (default "farthest").
    split_cycles : bool, optional
        Depth sort: split polygons that overlap cyclically or intersect (default
        True; False raises :class:`~scanline.errors.DepthSortLoopError` instead).
    max_pieces : int, optional
        Depth sort and BSP: most pieces the splitting may make.
    max_work : int, optional
        Depth sort: the bound of its time, in surfaces compared
        (:func:`scanline.visible.depth_sort.default_work`).
    max_depth : int, optional
        Ray tracing: the most levels of the ray tree, the primary ray's included,
        1..64 (default 5; 1: primary rays and shadow rays only).  Octree: the deepest
        level of the scene's octree (default 10, :mod:`scanline.visible.octree`).
    seed : int, optional
        Ray tracing: the seed of the distributed rays' random numbers, 0..2**63 - 1
        (default 0; the image is the same for the same seed).

    Parameters
    ----------
    samples, layers, key, split_cycles, max_pieces, max_work, max_depth, seed
        As listed under Attributes (None: the method's default).

    Raises
    ------
    ArgumentValueError
        A number outside its range, or an unknown key.
    ArgumentTypeError
        ``split_cycles`` not a bool.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.visible.MethodOptions(samples=4, key="mean").samples
    4
    """
    samples: Optional[int] = None
    layers: Optional[int] = None
    key: Optional[str] = None
    split_cycles: Optional[bool] = None
    max_pieces: Optional[int] = None
    max_work: Optional[int] = None
    max_depth: Optional[int] = None
    seed: Optional[int] = None

    def __post_init__(self) -> None:
        def whole(name: str, low: int, high: int) -> None:
            value = getattr(self, name)
            if value is not None and (not isinstance(value, (int, np.integer))
                                      or isinstance(value, bool) or not low <= value <= high):
                raise ArgumentValueError(f"{name} must be an integer in {low}..{high}, got "
                                         f"{v._show(value)}")
        whole("samples", 1, 8)
        whole("layers", 1, 64)
        whole("max_pieces", 1, 2**40)
        whole("max_work", 1, 2**62)
        whole("max_depth", 1, 64)
        whole("seed", 0, 2**63 - 1)
        if self.key is not None:
            v.choice("key", self.key, KEYS)
        if self.split_cycles is not None and not isinstance(self.split_cycles, bool):
            raise ArgumentTypeError(f"split_cycles must be True or False, got "
                                    f"{v._show(self.split_cycles)}")

    def given(self) -> Tuple[str, ...]:
        """The names of the options that are set (not None).

        Returns
        -------
        tuple of str
            In the order of the fields.

        Examples
        --------
        >>> import scanline as sl
        >>> sl.visible.MethodOptions(key="mean", samples=4).given()
        ('samples', 'key')
        """
        return tuple(f.name for f in fields(self) if getattr(self, f.name) is not None)


@dataclass(frozen=True)
class Method:
    """A visible-surface method: ``find(scene, options)`` -> Layer or Fragments, its
    precision ("image" or "object"), the options of :class:`MethodOptions` it reads,
    whether it resolves transparency itself (else the renderer adds the nearest
    transparent surface over its result), and whether its hits are colored by the
    recursive ray tracer (:mod:`scanline.raytrace`) instead of the local shading.

    Parameters
    ----------
    name : str
        The name :func:`scanline.render` knows it by.
    find : callable
        ``find(scene, options)`` -> Layer or Fragments.
    precision : {"image", "object"}
        Hearn & Baker 13-1.
    options : tuple of str
        The :class:`MethodOptions` it reads.
    transparency : bool
        Whether it resolves transparency itself.
    traced : bool
        Whether the ray tracer colors its hits.

    Examples
    --------
    >>> import scanline as sl
    >>> m = sl.visible.METHODS["z-buffer"]
    >>> m.name, m.precision, m.transparency
    ('z-buffer', 'image', False)
    """
    name: str
    find: Callable[["ScreenScene", MethodOptions], Union[Layer, Fragments]]
    precision: str
    options: Tuple[str, ...] = ()
    transparency: bool = False
    traced: bool = False


def _image_space(method: Callable[[ScreenPolygons], VisibleFaces]
                 ) -> Callable[["ScreenScene", MethodOptions], Layer]:
    def find(scene: "ScreenScene", options: MethodOptions) -> Layer:
        sp = scene.screen_polygons
        seen = method(sp)
        return facet_layer(scene, seen.polygon, sp.face, seen.depth)
    find.__doc__ = f"The visible triangle at each pixel by :func:`{method.__name__}`."
    return find


def _painter(scene: "ScreenScene", options: MethodOptions) -> Layer:
    """The facets painted back to front by one depth key each (the counter-example)."""
    return painted(scene, painter(scene.screen_polygons, options.key or "farthest"))


def _depth_sort(scene: "ScreenScene", options: MethodOptions) -> Layer:
    """The pieces of the depth-sorting method, painted beside the sort."""
    split = True if options.split_cycles is None else options.split_cycles
    pieces, numbers = painted_depth_sort(scene.screen_polygons, split, options.max_pieces,
                                         options.max_work)
    return painted(scene, pieces, numbers)


def _bsp(scene: "ScreenScene", options: MethodOptions) -> Layer:
    """The scene's polygons back to front by a BSP tree built in world coordinates
    (Fuchs, Kedem and Naylor 1980) from its faces (those taken whole) and facets, and
    traversed from the camera's eye; the pieces clipped and projected as the
    preparation does."""
    from ..screen.prepare import device_polygons

    _, world, _, counts, labels = scene.units
    if not len(labels):
        return painted(scene, scene.screen_polygons.subset([]))
    tree = BSPTree.of_polygons(world, counts, labels, max_pieces=options.max_pieces)
    verts, piece_counts, pieces = tree.world_pieces(camera_eye(scene.camera, scene.width,
                                                               scene.height))
    return painted(scene, device_polygons(verts, piece_counts, pieces, scene.camera,
                                          scene.width, scene.height, scene.mapping))


#: name -> :class:`Method`
METHODS = {m.name: m for m in (
    Method("z-buffer", zbuffer, "image"),
    Method("a-buffer", abuffer, "image", ("samples", "layers"), transparency=True),
    Method("ray-casting", raycast, "image"),
    Method("ray-tracing", raycast, "image", ("max_depth", "seed"), transparency=True,
           traced=True),
    Method("scan-line", _image_space(scan_line), "image"),
    Method("area-subdivision", _image_space(area_subdivision), "image"),
    Method("octree", octree, "image", ("max_depth",)),
    Method("depth-sort", _depth_sort, "object", ("split_cycles", "max_pieces", "max_work")),
    Method("bsp", _bsp, "object", ("max_pieces",)),
    Method("painter", _painter, "object", ("key",)),
)}

#: Each method's precision, "image" or "object".
PRECISION = {name: m.precision for name, m in METHODS.items()}


def register(method: Method) -> None:
    """Add a :class:`Method` to :data:`METHODS` (replacing one of the same name).

    Parameters
    ----------
    method : Method
        The method.

    Raises
    ------
    ArgumentTypeError
        ``method`` not a Method.
    ArgumentValueError
        A precision other than "image" or "object".

    Examples
    --------
    >>> import scanline as sl
    >>> copy = sl.visible.Method("z-buffer copy", sl.visible.METHODS["z-buffer"].find, "image")
    >>> sl.visible.register(copy)
    >>> sl.visible.PRECISION["z-buffer copy"]
    'image'
    >>> del sl.visible.METHODS["z-buffer copy"], sl.visible.PRECISION["z-buffer copy"]
    """
    if not isinstance(method, Method):
        raise ArgumentTypeError(f"method must be a scanline.visible.Method, got "
                                f"{v._show(method)}")
    v.choice("precision", method.precision, ("image", "object"))
    METHODS[method.name] = method
    PRECISION[method.name] = method.precision
