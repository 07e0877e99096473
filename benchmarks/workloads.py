"""The benchmark workloads and the per-library ways of drawing them.

Every library draws the same primitives (same numpy seed, same integer coordinates,
white on a black RGB uint8 canvas).  scanline takes device coordinates (y up); the
peers take image coordinates (row 0 at the top), so they are given y' = H - 1 - y,
which makes ``fb.to_array()`` and the peers' images directly comparable pixel for
pixel.  Coordinate conversions (y flip, Pillow bounding boxes, Python lists for the
loops) are done once, outside the timed region, so each library is timed at its best.

A *variant* is one way of drawing a workload: scanline's batch call, a Python loop
over scanline's single-primitive call, or a Python loop over a peer's call (the
peers have no batch API for these primitives, except ``cv2.polylines`` for lines,
shown for information).
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
    prims: np.ndarray          # (N, k) int64, scanline device coordinates (y up)
    kind: str                  # "line" | "circle" | "ellipse"
    seed: int
    sanity_n: int              # primitives drawn for the pixel-output sanity check
    params: dict = field(default_factory=dict)

    @property
    def n(self):
        return len(self.prims)

    def image_coords(self, prims):
        """The same primitives in image coordinates (row 0 at the top)."""
        out = prims.copy()
        flip = self.height - 1
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


_BATCH_NAMES = {"line": "sl.draw.lines", "circle": "sl.draw.circles", "ellipse": "sl.draw.ellipses"}
_SINGLE_NAMES = {"line": "sl.draw.line", "circle": "sl.draw.circle", "ellipse": "sl.draw.ellipse"}
# numba dispatchers behind the API calls, looked up lazily and defensively (internal names)
_KERNELS = {
    ("line", "batch"): ("scanline._kernels.lines", "draw_lines"),
    ("line", "loop"): ("scanline._kernels.lines", "draw_line"),
    ("circle", "batch"): ("scanline._kernels.conics", "draw_circles"),
    ("circle", "loop"): ("scanline._kernels.conics", "draw_circle"),
    ("ellipse", "batch"): ("scanline._kernels.conics", "draw_ellipses"),
    ("ellipse", "loop"): ("scanline._kernels.conics", "draw_ellipse"),
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


def variants(workload, caps):
    """The variants for ``workload``; ``caps`` maps variant key -> max primitives timed."""
    kind = workload.kind
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
    for v in out:
        v.max_timed = caps.get((workload.name, v.key), 0)
    return out
