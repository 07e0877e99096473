"""The benchmark workloads and the per-library ways of drawing them.

Every library draws the same primitives (same numpy seed, same integer coordinates,
white on a black RGB uint8 canvas).  scanline takes device coordinates (y up); the
peers take image coordinates (row 0 at the top), so they are given y' = H - 1 - y,
which makes ``fb.to_array()`` and the peers' images directly comparable pixel for
pixel.  Coordinate conversions (y flip, Pillow bounding boxes, Python lists for the
loops) are done once, outside the timed region, so each library is timed at its best.

A *variant* is one way of drawing a workload: scanline's batch call, a Python loop
over scanline's single-primitive call, or a Python loop over a peer's call (the
peers have no batch API for these primitives, except ``cv2.polylines`` for lines
and ``cv2.fillPoly`` with many contours for polygons, shown for information).

Two workloads are not batches of primitives: ``polygons`` holds a list of vertex
arrays (one per polygon), and ``flood-fill`` one seed in a maze image, filled once
per run.
"""

from dataclasses import dataclass, field
from typing import Callable

import numpy as np

WHITE = (255, 255, 255)


@dataclass
class Workload:
    name: str
    description: str
    width: int
    height: int
    prims: np.ndarray          # (N, k) int64, scanline device coordinates (y up);
                               # polygons: a list of (K_i, 2) float64 vertex arrays
    kind: str                  # "line" | "circle" | "ellipse" | "polygon" | "flood"
    seed: int
    sanity_n: int              # primitives drawn for the pixel-output sanity check
    params: dict = field(default_factory=dict)
    image: np.ndarray = None   # flood-fill: the (H, W) uint8 maze, 1 = corridor, rows bottom-up

    @property
    def n(self):
        return len(self.prims)

    def image_coords(self, prims):
        """The same primitives in image coordinates (row 0 at the top)."""
        flip = self.height - 1
        if self.kind == "polygon":
            return [np.stack([p[:, 0], flip - p[:, 1]], axis=1) for p in prims]
        out = prims.copy()
        if self.kind == "line":
            out[:, 1] = flip - prims[:, 1]
            out[:, 3] = flip - prims[:, 3]
        else:
            out[:, 1] = flip - prims[:, 1]
        return out


def short_lines(n, seed=1, size=2048, max_len=32):
    rng = np.random.default_rng(seed)
    x0 = rng.integers(0, size, n)
    y0 = rng.integers(0, size, n)
    angle = rng.uniform(0.0, 2.0 * np.pi, n)
    length = rng.uniform(0.0, max_len, n)
    # endpoints stay on the canvas (clipping a coordinate only shortens the line),
    # so skimage.draw.line, which does not clip, can be used as is
    x1 = np.clip(np.rint(x0 + length * np.cos(angle)), 0, size - 1).astype(np.int64)
    y1 = np.clip(np.rint(y0 + length * np.sin(angle)), 0, size - 1).astype(np.int64)
    prims = np.ascontiguousarray(np.stack([x0, y0, x1, y1], axis=1).astype(np.int64))
    return Workload(
        "short-lines", f"{n:,} random lines, length <= {max_len}, on {size}x{size}",
        size, size, prims, "line", seed, sanity_n=min(n, 20_000),
        params={"max_length": max_len})


def long_lines(n, seed=2, size=4096):
    rng = np.random.default_rng(seed)
    prims = np.ascontiguousarray(rng.integers(0, size, (n, 4)).astype(np.int64))
    return Workload(
        "long-lines", f"{n:,} lines, endpoints uniform on {size}x{size}",
        size, size, prims, "line", seed, sanity_n=min(n, 100))


def circles(n, seed=3, size=2048, max_r=64):
    rng = np.random.default_rng(seed)
    prims = np.stack([rng.integers(0, size, n), rng.integers(0, size, n),
                      rng.integers(1, max_r + 1, n)], axis=1).astype(np.int64)
    return Workload(
        "circles", f"{n:,} circles, 1 <= r <= {max_r}, centers on {size}x{size}",
        size, size, np.ascontiguousarray(prims), "circle", seed, sanity_n=min(n, 2_000),
        params={"max_radius": max_r})


def ellipses(n, seed=4, size=2048, max_r=64):
    rng = np.random.default_rng(seed)
    prims = np.stack([rng.integers(0, size, n), rng.integers(0, size, n),
                      rng.integers(1, max_r + 1, n), rng.integers(1, max_r + 1, n)],
                     axis=1).astype(np.int64)
    return Workload(
        "ellipses", f"{n:,} axis-aligned ellipses, 1 <= rx, ry <= {max_r}, centers on {size}x{size}",
        size, size, np.ascontiguousarray(prims), "ellipse", seed, sanity_n=min(n, 2_000),
        params={"max_radius": max_r})


def polygons(n, seed=5, size=2048, max_r=64, min_vertices=3, max_vertices=20):
    """Random star-shaped polygons (concave in general): K vertices at sorted random
    angles and random radii in [0.2, 1] x R about a random center; integer vertices."""
    rng = np.random.default_rng(seed)
    k = rng.integers(min_vertices, max_vertices + 1, n)
    centers = rng.uniform(0, size, (n, 2))
    radius = rng.uniform(4, max_r, n)
    prims = []
    for i in range(n):
        ang = np.sort(rng.uniform(0, 2 * np.pi, k[i]))
        r = radius[i] * rng.uniform(0.2, 1.0, k[i])
        p = centers[i] + np.stack([r * np.cos(ang), r * np.sin(ang)], axis=1)
        prims.append(np.rint(p))
    return Workload(
        "polygons", f"{n:,} random concave polygons, {min_vertices}-{max_vertices} vertices, "
        f"radius <= {max_r}, on {size}x{size}", size, size, prims, "polygon", seed,
        sanity_n=min(n, 2_000), params={"max_radius": max_r, "vertices": [min_vertices, max_vertices]})


def maze(size, seed):
    """A perfect maze (a spanning tree of a grid of cells) carved by randomized
    depth-first search: corridors and walls 1 px wide, a (size, size) uint8 array with
    1 in the corridors.  Compiled with numba (a Python loop would take ~20 s)."""
    from numba import njit

    @njit(cache=False)
    def carve(cells, seed, img):
        np.random.seed(seed)
        seen = np.zeros((cells, cells), np.bool_)
        stack = np.empty((cells * cells, 2), np.int64)
        steps = np.array([[1, 0], [-1, 0], [0, 1], [0, -1]])
        options = np.empty(4, np.int64)
        stack[0, 0] = 0
        stack[0, 1] = 0
        n = 1
        seen[0, 0] = True
        img[1, 1] = 1
        while n > 0:
            cx = stack[n - 1, 0]
            cy = stack[n - 1, 1]
            k = 0
            for d in range(4):
                nx = cx + steps[d, 0]
                ny = cy + steps[d, 1]
                if 0 <= nx < cells and 0 <= ny < cells and not seen[ny, nx]:
                    options[k] = d
                    k += 1
            if k == 0:
                n -= 1
                continue
            d = options[np.random.randint(k)]
            nx = cx + steps[d, 0]
            ny = cy + steps[d, 1]
            seen[ny, nx] = True
            img[2 * cy + 1 + steps[d, 1], 2 * cx + 1 + steps[d, 0]] = 1
            img[2 * ny + 1, 2 * nx + 1] = 1
            stack[n, 0] = nx
            stack[n, 1] = ny
            n += 1

    img = np.zeros((size, size), np.uint8)
    carve((size - 1) // 2, seed, img)
    return img


def flood_fill(n=1, seed=6, size=4096):
    """One flood fill of a whole maze from a corridor pixel: every corridor pixel is
    reachable (the maze is a tree), about half of the image."""
    img = maze(size, seed)
    prims = np.array([[1, 1]], np.int64)
    return Workload(
        "flood-fill", f"flood fill of a {size}x{size} maze (1 px corridors and walls, "
        f"{int(img.sum()):,} corridor pixels), 4-connected", size, size, prims, "flood",
        seed, sanity_n=1, params={"corridor_pixels": int(img.sum()), "connectivity": 4},
        image=img)


# -- canvases ------------------------------------------------------------------------
class ScanlineCanvas:
    def __init__(self, w, h):
        import scanline as sl
        self.fb = sl.FrameBuffer(w, h, mode="RGB")

    def clear(self):
        self.fb.clear()

    def mask(self):
        return self.fb.to_array().any(axis=2)


class ArrayCanvas:
    def __init__(self, w, h):
        self.img = np.zeros((h, w, 3), np.uint8)

    def clear(self):
        self.img.fill(0)

    def mask(self):
        return self.img.any(axis=2)


class PillowCanvas:
    def __init__(self, w, h):
        from PIL import Image, ImageDraw
        self.size = (w, h)
        self.im = Image.new("RGB", (w, h))
        self.draw = ImageDraw.Draw(self.im)

    def clear(self):
        self.im.paste((0, 0, 0), (0, 0) + self.size)

    def mask(self):
        return np.asarray(self.im).any(axis=2)


FILL = (255, 0, 0)


class _MazeCanvas:
    """A canvas that starts as the maze (white corridors, black walls); clear()
    restores it.  mask() is the pixels painted with the fill color."""
    maze = None

    def _rgb(self):
        return np.repeat(self.maze[::-1, :, None] * np.uint8(255), 3, axis=2)


class MazeScanlineCanvas(_MazeCanvas):
    def __init__(self, w, h):
        import scanline as sl
        self.fb = sl.FrameBuffer.from_array(self._rgb())

    def clear(self):
        buf, _ = self.fb._raster()
        buf[...] = self.maze[:, :, None] * np.uint8(255)

    def mask(self):
        return (self.fb.to_array() == FILL).all(axis=2)


class MazeArrayCanvas(_MazeCanvas):
    def __init__(self, w, h):
        self.img = self._rgb()
        self.cv_mask = np.zeros((h + 2, w + 2), np.uint8)

    def clear(self):
        self.img[...] = self._rgb()
        self.cv_mask.fill(0)

    def mask(self):
        return (self.img == FILL).all(axis=2)


class MazeGrayCanvas(_MazeCanvas):
    """scikit-image's flood_fill works on one channel: the maze as gray levels."""
    def __init__(self, w, h):
        self.img = self.maze[::-1] * np.uint8(255)

    def clear(self):
        self.img[...] = self.maze[::-1] * np.uint8(255)

    def mask(self):
        return self.img == 128


class MazePillowCanvas(_MazeCanvas):
    def __init__(self, w, h):
        from PIL import Image
        self.im = Image.fromarray(self._rgb())

    def clear(self):
        from PIL import Image
        self.im.paste(Image.fromarray(self._rgb()))

    def mask(self):
        return (np.asarray(self.im) == FILL).all(axis=2)


def maze_canvas(cls, image):
    """A canvas class bound to ``image`` (the maze, rows bottom-up)."""
    return type(cls.__name__, (cls,), {"maze": image})


@dataclass
class Variant:
    key: str                 # short id, e.g. "sl-batch"
    library: str             # "scanline", "OpenCV", "Pillow", "scikit-image"
    call: str                # what is timed, e.g. "sl.draw.lines (1 call)"
    kind: str                # "batch" (one call for all) or "loop" (one call per primitive)
    canvas: Callable         # (w, h) -> canvas
    prepare: Callable        # (workload, prims) -> data, outside the timed region
    draw: Callable           # (canvas, data) -> None, the timed region
    max_timed: int = 0       # time at most this many primitives (0: all), scale linearly
    info_only: bool = False  # not a per-primitive loop of a peer: not used for targets
    kernels: tuple = ()      # scanline numba dispatchers behind the call (for cache stats)
    single_run: bool = False  # time one run only (its first call), no warm-up: too slow


# -- scanline ------------------------------------------------------------------------
def _sl_batch(kind):
    import scanline as sl
    fn = {"line": sl.draw.lines, "circle": sl.draw.circles, "ellipse": sl.draw.ellipses}[kind]

    def draw(c, prims):
        fn(c.fb, prims, color=WHITE)
    return draw


def _sl_loop(kind):
    import scanline as sl
    if kind == "line":
        def draw(c, rows, line=sl.draw.line):
            fb = c.fb
            for x0, y0, x1, y1 in rows:
                line(fb, x0, y0, x1, y1, color=WHITE)
    elif kind == "circle":
        def draw(c, rows, circle=sl.draw.circle):
            fb = c.fb
            for x, y, r in rows:
                circle(fb, x, y, r, color=WHITE)
    else:
        def draw(c, rows, ellipse=sl.draw.ellipse):
            fb = c.fb
            for x, y, rx, ry in rows:
                ellipse(fb, x, y, rx, ry, color=WHITE)
    return draw


_BATCH_NAMES = {"line": "sl.draw.lines", "circle": "sl.draw.circles", "ellipse": "sl.draw.ellipses",
                "polygon": "sl.draw.polygons", "flood": "sl.draw.flood_fill"}
_SINGLE_NAMES = {"line": "sl.draw.line", "circle": "sl.draw.circle", "ellipse": "sl.draw.ellipse",
                 "polygon": "sl.draw.polygon", "flood": "sl.draw.flood_fill"}
# numba dispatchers behind the API calls, looked up lazily and defensively (internal names)
_KERNELS = {
    ("line", "batch"): ("scanline._kernels.lines", "draw_lines"),
    ("line", "loop"): ("scanline._kernels.lines", "draw_line"),
    ("circle", "batch"): ("scanline._kernels.conics", "draw_circles"),
    ("circle", "loop"): ("scanline._kernels.conics", "draw_circle"),
    ("ellipse", "batch"): ("scanline._kernels.conics", "draw_ellipses"),
    ("ellipse", "loop"): ("scanline._kernels.conics", "draw_ellipse"),
    ("polygon", "batch"): ("scanline._kernels.polygon", "fill_polygons"),
    ("polygon", "loop"): ("scanline._kernels.polygon", "fill_polygons"),
    ("flood", "batch"): ("scanline._kernels.seedfill", "seed_fill"),
    ("flood_fill", "loop"): ("scanline._kernels.seedfill", "seed_fill"),
}


def batch_name(kind):
    return _BATCH_NAMES[kind]


def single_name(kind):
    return _SINGLE_NAMES[kind]


def kernel_cache_stats(kind, variant_kind):
    """(hits, misses) of numba's on-disk cache for the kernel behind a call, or None."""
    try:
        import importlib
        module, name = _KERNELS[(kind, variant_kind)]
        stats = getattr(importlib.import_module(module), name).stats
        return sum(stats.cache_hits.values()), sum(stats.cache_misses.values())
    except Exception:  # internal API: absent or renamed
        return None


def _as_array(w, prims):
    return prims


def _as_rows(w, prims):
    return prims.tolist()


def _img_rows(w, prims):
    return w.image_coords(prims).tolist()


# -- peers ---------------------------------------------------------------------------
def _cv2_loop(kind):
    import cv2
    line8 = cv2.LINE_8
    if kind == "line":
        def prepare(w, prims):
            return [((a, b), (c, d)) for a, b, c, d in _img_rows(w, prims)]

        def draw(c, rows, line=cv2.line):
            img = c.img
            for p, q in rows:
                line(img, p, q, WHITE, 1, line8)
    elif kind == "circle":
        def prepare(w, prims):
            return [((x, y), r) for x, y, r in _img_rows(w, prims)]

        def draw(c, rows, circle=cv2.circle):
            img = c.img
            for p, r in rows:
                circle(img, p, r, WHITE, 1, line8)
    else:
        def prepare(w, prims):
            return [((x, y), (rx, ry)) for x, y, rx, ry in _img_rows(w, prims)]

        def draw(c, rows, ellipse=cv2.ellipse):
            img = c.img
            for p, axes in rows:
                ellipse(img, p, axes, 0, 0, 360, WHITE, 1, line8)
    return prepare, draw


def _cv2_polylines():
    import cv2

    def prepare(w, prims):
        return np.ascontiguousarray(w.image_coords(prims).astype(np.int32).reshape(-1, 2, 2))

    def draw(c, pts):
        cv2.polylines(c.img, pts, False, WHITE, 1, cv2.LINE_8)
    return prepare, draw


def _pillow_loop(kind):
    if kind == "line":
        def prepare(w, prims):
            return [tuple(r) for r in _img_rows(w, prims)]

        def draw(c, rows):
            line = c.draw.line
            for xy in rows:
                line(xy, fill=WHITE, width=1)
    else:
        def prepare(w, prims):
            rows = w.image_coords(prims)
            if kind == "circle":
                x, y, rx = rows.T
                ry = rx
            else:
                x, y, rx, ry = rows.T
            # ImageDraw.ellipse takes the bounding box; both corners are inclusive
            return [tuple(b) for b in np.stack([x - rx, y - ry, x + rx, y + ry], axis=1).tolist()]

        def draw(c, rows):
            ellipse = c.draw.ellipse
            for box in rows:
                ellipse(box, outline=WHITE, width=1)
    return prepare, draw


def _skimage_loop(kind):
    import skimage.draw as skd
    color = np.array(WHITE, np.uint8)
    if kind == "line":
        def draw(c, rows, line=skd.line):
            img = c.img
            for x0, y0, x1, y1 in rows:      # endpoints are on the canvas (see short_lines)
                rr, cc = line(y0, x0, y1, x1)
                img[rr, cc] = color
    elif kind == "circle":
        def draw(c, rows, perimeter=skd.circle_perimeter):
            img = c.img
            shape = img.shape[:2]
            for x, y, r in rows:
                rr, cc = perimeter(y, x, r, shape=shape)
                img[rr, cc] = color
    else:
        def draw(c, rows, perimeter=skd.ellipse_perimeter):
            img = c.img
            shape = img.shape[:2]
            for x, y, rx, ry in rows:
                rr, cc = perimeter(y, x, ry, rx, shape=shape)
                img[rr, cc] = color
    return _img_rows, draw


_PEER_CALLS = {
    "line": ("cv2.line", "ImageDraw.line", "draw.line + img[rr, cc] = c"),
    "circle": ("cv2.circle", "ImageDraw.ellipse (bbox)", "draw.circle_perimeter + img[rr, cc] = c"),
    "ellipse": ("cv2.ellipse", "ImageDraw.ellipse (bbox)", "draw.ellipse_perimeter + img[rr, cc] = c"),
}


# -- polygons ------------------------------------------------------------------------
def _polygon_variants(w):
    import cv2
    import skimage.draw as skd
    import scanline as sl
    color = np.array(WHITE, np.uint8)

    def sl_flat(w, prims):  # the batch API's flat form, prepared like the peers' inputs
        return np.concatenate(prims), np.array([len(p) for p in prims], np.int64)

    def sl_batch(c, flat, polygons=sl.draw.polygons):
        vertices, counts = flat
        polygons(c.fb, vertices, counts=counts, color=WHITE)

    def sl_loop(c, polys, polygon=sl.draw.polygon):
        fb = c.fb
        for p in polys:
            polygon(fb, p, color=WHITE)

    def cv_prepare(w, prims):
        return [np.ascontiguousarray(p.astype(np.int32)) for p in w.image_coords(prims)]

    def cv_loop(c, polys, fill=cv2.fillPoly, line8=cv2.LINE_8):
        img = c.img
        for p in polys:
            fill(img, [p], WHITE, line8)

    def cv_one_call(c, polys):
        cv2.fillPoly(c.img, polys, WHITE, cv2.LINE_8)

    def pil_prepare(w, prims):
        return [[tuple(v) for v in p.tolist()] for p in w.image_coords(prims)]

    def pil_loop(c, polys):
        polygon = c.draw.polygon
        for xy in polys:
            polygon(xy, fill=WHITE)

    def sk_prepare(w, prims):
        return [(p[:, 1].copy(), p[:, 0].copy()) for p in w.image_coords(prims)]

    def sk_loop(c, polys, polygon=skd.polygon):
        img = c.img
        shape = img.shape[:2]
        for rows, cols in polys:
            rr, cc = polygon(rows, cols, shape=shape)
            img[rr, cc] = color

    def as_list(w, prims):
        return list(prims)

    return [
        Variant("sl-batch", "scanline", "sl.draw.polygons (1 call, flat vertices + counts)",
                "batch", ScanlineCanvas, sl_flat, sl_batch),
        Variant("sl-loop", "scanline", "sl.draw.polygon loop", "loop", ScanlineCanvas,
                as_list, sl_loop),
        Variant("cv2-loop", "OpenCV", "cv2.fillPoly loop", "loop", ArrayCanvas, cv_prepare, cv_loop),
        Variant("pil-loop", "Pillow", "ImageDraw.polygon loop", "loop", PillowCanvas,
                pil_prepare, pil_loop),
        Variant("sk-loop", "scikit-image", "draw.polygon + img[rr, cc] = c loop", "loop",
                ArrayCanvas, sk_prepare, sk_loop),
        Variant("cv2-fillpoly-1call", "OpenCV", "cv2.fillPoly, N contours (1 call, even-odd)",
                "batch", ArrayCanvas, cv_prepare, cv_one_call, info_only=True),
    ]


# -- flood fill ------------------------------------------------------------------------
def flood_fill_available():
    """``sl.draw.flood_fill``, or None when it does not exist yet."""
    try:
        import scanline as sl
        return sl.draw.flood_fill
    except AttributeError:
        try:
            from scanline.draw.seedfill import flood_fill
            return flood_fill
        except ImportError:
            return None


def _flood_variants(w):
    import cv2
    import skimage.segmentation as seg
    from PIL import ImageDraw
    flip = w.height - 1
    fill = flood_fill_available()
    out = []
    if fill is not None:
        def sl_fill(c, seeds):
            for x, y in seeds:
                fill(c.fb, x, y, FILL, connectivity=4)
        out.append(Variant("sl-batch", "scanline", "sl.draw.flood_fill (1 call)", "batch",
                           maze_canvas(MazeScanlineCanvas, w.image), lambda w, s: s.tolist(),
                           sl_fill))

    def img_seeds(w, seeds):
        return [(x, flip - y) for x, y in seeds.tolist()]

    def cv_fill(c, seeds, flood=cv2.floodFill):
        for p in seeds:
            flood(c.img, c.cv_mask, p, FILL, (0, 0, 0), (0, 0, 0), 4)

    def sk_fill(c, seeds, flood=seg.flood_fill):
        for x, y in seeds:
            flood(c.img, (y, x), 128, connectivity=1, in_place=True)

    def pil_fill(c, seeds, flood=ImageDraw.floodfill):
        for p in seeds:
            flood(c.im, p, FILL)

    out += [
        Variant("cv2-loop", "OpenCV", "cv2.floodFill (mask, 4-connected)", "loop",
                maze_canvas(MazeArrayCanvas, w.image), img_seeds, cv_fill),
        Variant("sk-loop", "scikit-image", "segmentation.flood_fill (gray, in place)", "loop",
                maze_canvas(MazeGrayCanvas, w.image), img_seeds, sk_fill),
        Variant("pil-loop", "Pillow", "ImageDraw.floodfill (pure Python; 1 run)", "loop",
                maze_canvas(MazePillowCanvas, w.image), img_seeds, pil_fill, single_run=True),
    ]
    return out


def variants(workload, caps):
    """The variants for ``workload``; ``caps`` maps variant key -> max primitives timed."""
    kind = workload.kind
    if kind == "polygon":
        out = _polygon_variants(workload)
    elif kind == "flood":
        out = _flood_variants(workload)
    else:
        out = _primitive_variants(kind)
    for v in out:
        v.max_timed = caps.get((workload.name, v.key), 0)
    return out


def _primitive_variants(kind):
    """Lines, circles, ellipses: scanline's batch and loop, the peers' loops."""
    out = [
        Variant("sl-batch", "scanline", f"{batch_name(kind)} (1 call)", "batch",
                ScanlineCanvas, _as_array, _sl_batch(kind)),
        Variant("sl-loop", "scanline", f"{single_name(kind)} loop", "loop",
                ScanlineCanvas, _as_rows, _sl_loop(kind)),
    ]
    cv_call, pil_call, sk_call = _PEER_CALLS[kind]
    prepare, draw = _cv2_loop(kind)
    out.append(Variant("cv2-loop", "OpenCV", f"{cv_call} loop", "loop", ArrayCanvas, prepare, draw))
    prepare, draw = _pillow_loop(kind)
    out.append(Variant("pil-loop", "Pillow", f"{pil_call} loop", "loop", PillowCanvas, prepare, draw))
    prepare, draw = _skimage_loop(kind)
    out.append(Variant("sk-loop", "scikit-image", f"{sk_call} loop", "loop", ArrayCanvas, prepare, draw))
    if kind == "line":
        prepare, draw = _cv2_polylines()
        out.append(Variant("cv2-polylines", "OpenCV", "cv2.polylines, N 2-point polylines (1 call)",
                           "batch", ArrayCanvas, prepare, draw, info_only=True))
    return out
