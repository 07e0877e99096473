"""The glyph image cache: each glyph scan-converted once per font, size, orientation
and antialiasing, then stamped wherever the character occurs.

Every text engine works this way (FreeType's and Cairo's glyph caches): a page of
text holds a few dozen distinct characters repeated thousands of times.  A glyph
image is made by filling the glyph's contours (flattened outline, or the dot
squares of the bitmap font) with scanline's own scan-line fill
(:func:`scanline.draw.polygon`, nonzero rule) -- or, antialiased, with
:func:`scanline.draw.antialias.fill` -- into a small gray frame buffer.  Because
layout rounds each character origin to a pixel center, the stamped pixels are
exactly the pixels a direct fill of the placed contours would set.

Glyphs taller than :data:`MAX_CACHED` pixels are not cached: their contours are
filled directly in the frame buffer (clipped to it), so huge text costs memory in
proportion to what is visible.
"""

from collections import OrderedDict
from typing import TYPE_CHECKING, Optional

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:
    from ..errors import ArgumentValueError
    from .catalog import Font

#: Tallest glyph image (pixels, the scaled em size) kept in the cache.
MAX_CACHED = 256

#: Largest glyph image (pixels) made for the cache: 2048 x 2048, eight ems at the
#: largest cached size.  A glyph whose outline reaches farther (a hostile font
#: with points at +-32767 units and 16 units per em) is refused, not allocated.
MAX_GLYPH_PIXELS = 1 << 22

#: Largest total of the glyph images of one cache (64 MiB of masks).
MAX_ATLAS_PIXELS = 1 << 26

#: How many (font, size, orientation, antialias) caches are kept (least recently
#: used dropped first).  An entry holds its font too, so a font's id cannot be
#: reused by another font while the entry lives.
MAX_SIZES = 64

_CACHES: "OrderedDict[tuple[int, bytes, bool], tuple[Font, Optional[GlyphImages]]]" = OrderedDict()


def device_contours(font: "Font", gid: int, matrix: NDArray[np.float64], tolerance: float) -> list[NDArray[np.float64]]:
    """Glyph ``gid``'s contours in device units relative to its origin."""
    return [c @ matrix.T for c in font._ink(gid, tolerance)]


def _too_large(font: Optional["Font"], gid: Optional[int], pixels: int, limit: int,
               what: str) -> "ArgumentValueError":
    from ..errors import ArgumentValueError
    if font is None:
        return ArgumentValueError(
            f"text: {what} would take {pixels:,} pixels, more than the {limit:,} scanline "
            "allocates for one glyph; draw the text smaller (a smaller height or scale)")
    names = getattr(font, "_names", None)
    name = names[gid] if names is not None and gid is not None and gid < len(names) else gid
    return ArgumentValueError(
        f"font {getattr(font, 'source', None)!r}: glyph {name!r} would make {what} of {pixels:,} pixels, more "
        f"than the {limit:,} scanline allocates (its outline lies far outside its em "
        "square); use another font or a smaller height")


def _render(contours: list[NDArray[np.float64]], antialias: bool, font: Optional["Font"] = None,
            gid: Optional[int] = None) -> tuple[int, int, int, int, NDArray[np.uint8]]:
    """``(x0, y0, w, h, mask)``: the glyph's pixels as a bottom-up uint8 mask whose
    bottom-left pixel is ``(x0, y0)`` relative to the origin; a mask larger than
    MAX_GLYPH_PIXELS is refused before it is allocated."""
    from ..framebuffer import FrameBuffer
    pts = [c for c in contours if len(c)]
    if not pts:
        return 0, 0, 0, 0, np.zeros(0, np.uint8)
    allp = np.vstack(pts)
    lo, hi = allp.min(0), allp.max(0)
    pad = 1 if antialias else 0
    x0 = int(np.ceil(lo[0])) - pad
    y0 = int(np.floor(lo[1])) + 1 - pad
    w = int(np.ceil(hi[0])) - 1 + pad - x0 + 1
    h = int(np.floor(hi[1])) + pad - y0 + 1
    if w <= 0 or h <= 0:
        return 0, 0, 0, 0, np.zeros(0, np.uint8)
    if w * h > MAX_GLYPH_PIXELS:
        raise _too_large(font, gid, w * h, MAX_GLYPH_PIXELS, "an image")
    fb = FrameBuffer(w, h, mode="L", background=0)
    shifted = [c - (x0, y0) for c in pts]
    if antialias:
        from ..draw import antialias as aa
        aa.fill(fb, shifted, 255, rule="nonzero")
    else:
        from ..draw.polygon import polygon
        polygon(fb, shifted, 255, rule="nonzero")
    mask: NDArray[np.uint8] = fb._raster()[0][:, :, 0].ravel().copy()
    return x0, y0, w, h, mask


def _runs(mask: NDArray[np.uint8]) -> NDArray[np.int64]:
    """The runs of nonzero pixels of a (h, w) mask, one row (row, start, stop) each,
    so that stamping touches only the glyph's pixels."""
    on = np.zeros((mask.shape[0], mask.shape[1] + 2), np.int8)
    on[:, 1:-1] = mask != 0
    rows, cols = np.nonzero(np.diff(on, axis=1))
    runs: NDArray[np.int64] = np.column_stack([rows[0::2], cols[0::2], cols[1::2]]).reshape(-1, 3)
    return runs


def stroke_bitmap(strokes: list[NDArray[np.float64]],
                  within: Optional[tuple[float, float, float, float]] = None
                  ) -> tuple[NDArray[np.bool_], tuple[int, int]]:
    """``(mask, (x0, y0))``: the pixels :func:`scanline.draw.lines` sets for the
    polylines ``strokes`` (device coordinates), a bool array in image order whose
    bottom-left pixel is ``(x0, y0)``; with ``within`` (xmin, ymin, xmax, ymax), only
    the part of it in that box (the lines clip themselves to the smaller image, so its
    pixels are the whole image's there).  An image over MAX_GLYPH_PIXELS is refused
    before it is allocated."""
    from ..draw.lines import lines
    from ..framebuffer import FrameBuffer
    pts = np.vstack(strokes) if strokes else np.zeros((0, 2))
    if len(pts) == 0:
        return np.zeros((0, 0), bool), (0, 0)
    lo = np.floor(pts.min(0) + 0.5)
    hi = np.floor(pts.max(0) + 0.5)
    if within is not None:
        lo = np.maximum(lo, np.floor(np.asarray(within[:2], float)))
        hi = np.minimum(hi, np.ceil(np.asarray(within[2:], float)))
    w, h = (hi - lo + 1).tolist()
    if w <= 0 or h <= 0:
        return np.zeros((0, 0), bool), (0, 0)
    if w * h > MAX_GLYPH_PIXELS:     # a huge transform: refused like an outline's image
        raise _too_large(None, None, int(min(w * h, 2.0**62)), MAX_GLYPH_PIXELS,
                         "a stroke glyph's image")
    lo, hi = lo.astype(int), hi.astype(int)
    fb = FrameBuffer(int(w), int(h), mode="1")
    segs = np.vstack([np.hstack([s[:-1], s[1:]]) for s in strokes])
    lines(fb, segs - np.tile(lo, 2), color=1)
    bits: NDArray[np.bool_] = fb.to_array()
    return bits, (int(lo[0]), int(lo[1]))


class GlyphImages:
    """The glyph images of one font at one matrix (size, expansion, angle)."""

    def __init__(self, font: "Font", matrix: NDArray[np.float64], antialias: bool, tolerance: float) -> None:
        self.font, self.matrix, self.antialias = font, matrix, antialias
        self.tolerance = tolerance
        self.pixels = 0
        self.mask_of = np.full(len(font.advances), -1, np.int64)
        self._parts: list[NDArray[np.uint8]] = []
        self._meta: list[tuple[int, int, int, int]] = []
        self._runs: list[NDArray[np.int64]] = []
        self.atlas = np.zeros(0, np.uint8)
        #: one row per mask: offset in ``atlas``, width, height, x0, y0, first run in
        #: ``runs``, number of runs
        self.masks = np.zeros((0, 7), np.int64)
        #: runs of nonzero pixels: (row, first column, last column + 1)
        self.runs = np.zeros((0, 3), np.int64)

    def ensure(self, gids: NDArray[np.int64]) -> NDArray[np.int64]:
        """Render the glyphs among ``gids`` not yet cached; return their mask ids."""
        ids: NDArray[np.int64] = self.mask_of[gids]
        if len(ids) == 0 or ids.min() >= 0:
            return ids
        for g in np.unique(gids[ids < 0]):
            x0, y0, w, h, mask = _render(
                device_contours(self.font, int(g), self.matrix, self.tolerance), self.antialias,
                self.font, int(g))
            if self.pixels + w * h > MAX_ATLAS_PIXELS:
                raise _too_large(self.font, int(g), self.pixels + w * h, MAX_ATLAS_PIXELS,
                                 "a glyph cache")
            self.pixels += w * h
            self.mask_of[g] = len(self._meta)
            self._meta.append((x0, y0, w, h))
            self._parts.append(mask)
            self._runs.append(_runs(mask.reshape(h, w)))
        meta = np.array(self._meta, np.int64).reshape(-1, 4)
        sizes = meta[:, 2] * meta[:, 3]
        counts = np.array([len(r) for r in self._runs], np.int64)
        self.masks = np.column_stack([np.cumsum(sizes) - sizes, meta[:, 2], meta[:, 3],
                                      meta[:, 0], meta[:, 1], np.cumsum(counts) - counts,
                                      counts]).astype(np.int64)
        self.atlas = np.concatenate(self._parts)
        self.runs = np.concatenate(self._runs).astype(np.int64)
        found: NDArray[np.int64] = self.mask_of[gids]
        return found

    def bitmap(self, gid: int) -> tuple[int, int, NDArray[np.bool_]]:
        """``(x0, y0, mask)`` of one glyph: ``mask`` a bool array in image order (top
        row first), its bottom-left pixel at ``(x0, y0)`` from the origin."""
        m = int(self.ensure(np.array([gid]))[0])
        off, w, h, x0, y0 = self.masks[m, :5].tolist()
        mask = self.atlas[off:off + w * h].reshape(h, w)
        bits: NDArray[np.bool_] = mask[::-1] > (127 if self.antialias else 0)
        return x0, y0, bits


def images(font: "Font", matrix: NDArray[np.float64], antialias: bool, tolerance: float
           ) -> Optional[GlyphImages]:
    """The cache for ``font`` at ``matrix`` (2 x 2 font units -> pixels), or None
    when its glyphs are too large to cache."""
    key = (id(font), matrix.tobytes(), antialias)
    hit = _CACHES.get(key)
    if hit is not None and hit[0] is font:
        _CACHES.move_to_end(key)
        return hit[1]
    a, b, c, d = matrix.ravel().tolist()
    small = abs(a * d - b * c) * font.units_per_em ** 2 <= MAX_CACHED ** 2
    images = GlyphImages(font, matrix, antialias, tolerance) if small else None
    _CACHES[key] = (font, images)
    if len(_CACHES) > MAX_SIZES:
        _CACHES.popitem(last=False)
    return images
