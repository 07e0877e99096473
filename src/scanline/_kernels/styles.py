"""Fill styles: storing a pattern or a hatch through an area mask (see
:mod:`scanline.attributes`).

The area has been scan-converted into ``mask`` (uint8, (h, w, 1), 1 inside), whose
pixel (0, 0) is device pixel (x0, y0) and which lies wholly inside the raster.  Each
masked pixel takes entry ``i`` of ``lut`` (channel values), ``i`` chosen by the style;
``i < 0`` leaves the pixel unchanged.
"""

from ._jit import inline, kernel
from .raster import put


@inline
def hatch_entry(x, y, families, spacing, other):
    """0 when (x, y) lies on a hatch line of one of ``families`` (rows c, s, w:
    ``(c y - s x + w/2) mod spacing < w``), else ``other``."""
    for f in range(families.shape[0]):
        c = families[f, 0]
        s = families[f, 1]
        w = families[f, 2]
        if (c * y - s * x + w / 2) % spacing < w:
            return 0
    return other


@kernel
def paint_styled(buf, layout, hatch, width, height, mask, x0, y0, ax, ay, cells, families,
                 spacing, other, lut):
    """Store ``lut[entry]`` at every masked pixel (``layout`` a layout token); the entry is the tile cell
    ``cells[(y - ay) mod th, (x - ax) mod tw]`` (bottom-up tile) or, for ``hatch``,
    :func:`hatch_entry` of (x - ax, y - ay)."""
    h, w = mask.shape[0], mask.shape[1]
    th, tw = cells.shape[0], cells.shape[1]
    for j in range(h):
        y = y0 + j
        ty = (y - ay) % th
        tx = (x0 - ax) % tw - 1
        for i in range(w):
            tx = 0 if tx == tw - 1 else tx + 1  # (x - ax) mod tw, kept without dividing
            if mask[j, i, 0] == 0:
                continue
            x = x0 + i
            if hatch:
                e = hatch_entry(x - ax, y - ay, families, spacing, other)
            else:
                e = cells[ty, tx]
            if e >= 0:
                put(buf, layout, width, height, x, y, lut[e])

