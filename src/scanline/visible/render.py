"""``sl.visible.render``: one scene by any of the methods of this package, flat
shaded (each face one color)."""

import queue
import threading

import numpy as np

from .. import _validate as v
from .._kernels.variants import layout
from ..draw._common import target
from ..errors import ArgumentValueError
from .bsp import BSPTree, bsp
from .depth_sort import depth_sort
from .painter import painter
from .polygons import ScreenPolygons, VisibleFaces, as_screen, meshes_list, screen_polygons
from .scanline_method import scan_line
from .warnock import area_subdivision

#: Object-order methods: the pieces back to front, painted in order.
OBJECT_ORDER = ("painter", "depth-sort", "bsp")
#: Image-space methods: a visible face per pixel.
IMAGE_SPACE = ("scan-line", "area-subdivision")
METHODS = OBJECT_ORDER + IMAGE_SPACE

#: Face colors of meshes without colors, one per mesh in turn.
PALETTE = ("#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f", "#edc948", "#b07aa1")


def visible(meshes, camera, width, height, method="depth-sort", cull_back_faces=False):
    """What ``method`` makes of the scene: a :class:`ScreenPolygons` in drawing
    order (object-order methods) or a :class:`VisibleFaces` (image space)."""
    v.choice("method", method, METHODS)
    if method == "bsp":
        tree = meshes if isinstance(meshes, BSPTree) else BSPTree(meshes)
        return bsp(tree, camera, width, height, cull_back_faces)
    sp = screen_polygons(meshes, camera, width, height, cull_back_faces)
    return {"painter": painter, "depth-sort": depth_sort, "scan-line": scan_line,
            "area-subdivision": area_subdivision}[method](sp)


def face_colors(fb, meshes, colors=None):
    """Pixel values (F, channels) of every face of ``meshes``: ``colors`` (one per
    face of all meshes, or one per mesh), else each mesh's face colors (the mean of
    its vertex colors for vertex-colored meshes), else :data:`PALETTE`."""
    group = meshes_list(meshes)
    sizes = [m.face_count for m in group]
    total = sum(sizes)
    if colors is not None:
        if isinstance(colors, (str, tuple)):
            colors = [colors] * len(group)
        if len(colors) == len(group) and len(group) != total:
            colors = [c for c, n in zip(colors, sizes) for _ in range(n)]
        if len(colors) != total:
            raise ArgumentValueError(
                f"colors holds {len(colors)} colors; give one per mesh ({len(group)}) or "
                f"one per face ({total})")
        return np.array([fb.pixel(c, f"colors[{i}]") for i, c in enumerate(colors)],
                        np.uint8).reshape(total, -1)
    rows = []
    for i, m in enumerate(group):
        if m.colors is None:
            rows.append(np.repeat(fb.pixel(PALETTE[i % len(PALETTE)])[None], m.face_count, 0))
        elif m.color_on == "face":
            rows.append(np.array([fb.pixel(tuple(int(c) for c in row)) for row in m.colors]))
        else:
            mean = [m.colors[m.face(f)].mean(axis=0).round().astype(int) for f in
                    range(m.face_count)]
            rows.append(np.array([fb.pixel(tuple(int(c) for c in row)) for row in mean]))
    return np.concatenate(rows).astype(np.uint8).reshape(total, -1)


_SCRATCH = threading.local()


def _piece_buffer(height, width):
    """The piece number per pixel that :func:`paint` paints before the colors (int32,
    height x width), kept for the calling thread and reused by its next painting of
    the same size (new megabytes cost more in page faults than the painting)."""
    kept = getattr(_SCRATCH, "ids", None)
    if kept is None or kept.shape != (height, width):
        kept = _SCRATCH.ids = np.empty((height, width), np.int32)
    return kept


def paint(fb, result, values):
    """Paint a method's result: object order piece after piece, later over earlier
    (the convex pieces' spans, sampled as :func:`scanline.draw.polygons` samples);
    image space by coloring each pixel with its face's value (background left as it
    is).  ``values``: pixel values (F, channels) per face."""
    if isinstance(result, ScreenPolygons):
        if len(result):
            from .._kernels._threads import call_in_bands
            from .._kernels.visible import paint_convex

            buf, packed = fb._raster()
            verts = np.ascontiguousarray(result.vertices, np.float64)
            colors = np.ascontiguousarray(values[result.face], np.uint8)
            # work: a frame's worth of pixels and ten units a vertex (the pieces' own
            # areas would cost more to add up than small scenes take to paint)
            call_in_bands(paint_convex, fb.width * fb.height + 10 * len(verts), buf,
                          layout(packed), fb.width, fb.height, verts,
                          np.ascontiguousarray(result.offsets, np.int64), colors,
                          _piece_buffer(fb.height, fb.width))
        return
    face = result.face
    buf, packed = fb._raster()
    seen = face >= 0
    if packed:
        bits = np.unpackbits(buf[:, :, 0], axis=1)[:, :fb.width].astype(bool)
        bits[seen] = values[face[seen], 0] != 0
        buf[:, :, 0] = np.packbits(bits, axis=1)
    else:
        buf[seen] = values[face[seen]]


def _face_values(values, channels, mode, face):
    """``values`` as a uint8 array (F, ``channels``) with a row for every face in
    ``face``, or a clear error."""
    a = np.asarray(values)
    if (a.ndim != 2 or a.shape[1] != channels or not np.issubdtype(a.dtype, np.integer)
            or (a.size and (a.min() < 0 or a.max() > 255))):
        raise ArgumentValueError(
            f"values must hold one pixel value per face, integers 0-255 of shape (faces, "
            f"{channels}) for a mode {mode!r} frame buffer (fb.pixel(color) gives a row), "
            f"got dtype {a.dtype}, shape {a.shape}")
    if len(face) and a.shape[0] <= int(face.max()):
        raise ArgumentValueError(f"values holds {a.shape[0]} rows, but the polygons name face "
                                 f"{int(face.max())}: give one row per face")
    return a.astype(np.uint8, copy=False)


def paint_depth_sorted(fb, polygons, values, split_cycles=True, max_pieces=None):
    """Depth-sort ``polygons`` (:func:`~scanline.visible.depth_sort.depth_sort`) and
    paint the pieces in order, as :func:`paint` paints them: the same pixels, with
    the painting done on a second thread while the sort goes on.

    The sort hands over each run of pieces as soon as their order is fixed (its
    ``drawn``); a painter thread writes the runs' piece numbers into the per-pixel
    buffer of :func:`paint`, run after run, while the sort orders the next pieces;
    when the last run is in, each pixel takes its piece's color (both cores, in
    bands).  The frame buffer is written only then: on an error of the sort it is
    left as it was.  ``values``: pixel values (F, channels) per face.  Returns the
    pieces in drawing order."""
    from .._kernels._jit import call
    from .._kernels._threads import _submit, call_in_bands
    from .._kernels.visible import color_ids, paint_ids

    target(fb)
    sp = as_screen(polygons)
    buf, packed = fb._raster()
    values = _face_values(values, buf.shape[2], fb.mode, sp.face)
    ids = _piece_buffer(fb.height, fb.width)
    runs = queue.SimpleQueue()
    numbered = [0]

    def painter():
        ids.fill(-1)
        while (run := runs.get()) is not None:
            verts, offsets, first = run
            # work: ten units a vertex, as in paint
            call(paint_ids, 10 * len(verts) + fb.height, fb.width, fb.height, verts,
                 offsets, first, ids)

    def drawn(verts, offsets, face):
        runs.put((verts, offsets, numbered[0]))
        numbered[0] += len(face)

    wait = _submit(painter)
    try:
        pieces = depth_sort(sp, split_cycles, max_pieces=max_pieces, drawn=drawn)
    finally:
        runs.put(None)
        wait()
    if len(pieces):
        call_in_bands(color_ids, fb.width * fb.height, buf, layout(packed), fb.width,
                      fb.height, np.ascontiguousarray(values[pieces.face], np.uint8), ids)
    return pieces


def render(fb, meshes, camera, method="depth-sort", colors=None, cull_back_faces=False):
    """Draw ``meshes`` through ``camera`` with a visible-surface method, one flat
    color per face.

    Parameters
    ----------
    fb : FrameBuffer
    meshes : Mesh, list of Mesh, or a BSPTree (method "bsp")
    camera : Camera
    method : {"painter", "depth-sort", "bsp", "scan-line", "area-subdivision"}
        See each function's docstring: :func:`painter`, :func:`depth_sort`,
        :class:`BSPTree`, :func:`scan_line`, :func:`area_subdivision` (object order
        for the first three, image space for the last two).
    colors : list of colors, optional
        One per mesh or one per face (default: the meshes' face colors, else a
        palette color per mesh).
    cull_back_faces : bool
        Drop faces turned away from the viewer first (Hearn & Baker, section 13-2).

    Returns
    -------
    ScreenPolygons or VisibleFaces
        What the method produced (pieces in drawing order, or the face per pixel).
    """
    target(fb)
    source = meshes._meshes if isinstance(meshes, BSPTree) else meshes
    values = face_colors(fb, source, colors)
    if method == "depth-sort":
        return paint_depth_sorted(fb, screen_polygons(meshes, camera, fb.width, fb.height,
                                                      cull_back_faces), values)
    result = visible(meshes, camera, fb.width, fb.height, method, cull_back_faces)
    paint(fb, result, values)
    return result
