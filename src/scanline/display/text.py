"""Text primitives of the display file, drawn as glyph geometry.

The text is laid out by :func:`scanline.text.layout` in device coordinates and
clipped by :func:`scanline.clip.text`; each glyph's strokes (stroke font) or contours
(outline and bitmap fonts) go to the device, so raster and vector output show the
same characters.  Clipping follows the text primitive's ``clip`` attribute (GKS text
precision): ``"string"`` keeps the whole string or nothing, ``"character"`` keeps the
characters whose cells (character bodies) lie inside, and ``"stroke"`` clips every
stroke and outline to the window.
"""

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .. import clip
from .primitives import THIN, Primitive


def placement(prim: Primitive) -> Any:
    """The characters of a text primitive placed in device coordinates
    (:func:`scanline.text.layout.place`), as arrays."""
    from ..text.layout import place
    from ..text.style import resolve

    g, a = prim.geometry, prim.attributes
    frame = g["frame"]
    height = float(np.hypot(*frame[:, 1]))
    angle = math.atan2(frame[1, 0], frame[0, 0])
    x, y = g["anchor"]
    style = resolve(None, font=a["font"], height=height, expansion=a["expansion"],
                    spacing=a["spacing"], angle=angle, path=a["path"], align=a["align"])
    return place(g["string"], float(x), float(y), style)


def glyphs(prim: Primitive) -> list[Any]:
    """All the placed glyphs of a text primitive in device coordinates."""
    from ..text.layout import glyphs as placed_glyphs

    return placed_glyphs(prim.geometry["string"], placement(prim))


def visible(prim: Primitive, window: Any) -> list[Any]:
    """The placed glyphs of a text primitive that its clip mode can keep in
    ``window``: the character bodies are tested all at once (arrays), and glyph
    objects are made only for the characters that can be drawn, so a long string
    mostly outside the window costs its visible part.  In mode ``"string"`` either
    every glyph (all bodies inside) or none; in ``"character"`` the glyphs whose
    body is inside; in ``"stroke"`` those whose body meets the window's bounding
    box (:func:`scanline.clip.text` then clips their geometry)."""
    from ..clip import window as w
    from ..text.layout import cells, glyphs

    p = placement(prim)
    if len(p.gids) == 0:
        return []
    ring = w.polygon(window, convex=True, algorithm="text clipping")
    boxes = cells(p)
    mode = prim.attributes["clip"]
    if mode == "stroke":
        lo, hi = ring.min(axis=0), ring.max(axis=0)
        select = np.flatnonzero((boxes[:, 2] >= lo[0]) & (boxes[:, 0] <= hi[0])
                                & (boxes[:, 3] >= lo[1]) & (boxes[:, 1] <= hi[1]))
    else:
        corners = boxes[:, [0, 1, 2, 1, 2, 3, 0, 3]].reshape(-1, 2)
        inside = np.zeros(len(boxes), bool)
        for lo in range(0, len(boxes), 1 << 14):   # chunks: corners x ring edges
            part = corners[4 * lo:4 * (lo + (1 << 14))]
            inside[lo:lo + (1 << 14)] = w.contains(ring, part).reshape(-1, 4).all(axis=1)
        if mode == "string":
            select = np.arange(len(boxes)) if inside.all() else np.zeros(0, np.int64)
        else:
            select = np.flatnonzero(inside)
    return glyphs(prim.geometry["string"], p, select)


def draw(prim: Primitive, window: Any, device: Any) -> list[NDArray[np.float64]]:
    """Draw a text primitive clipped to ``window`` by :func:`scanline.clip.text`;
    return the point arrays drawn."""
    placed = clip.text(visible(prim, window), window, prim.attributes["clip"])
    strokes = [np.asarray(s, np.float64) for g in placed for s in g.strokes or ()]
    contours = [np.asarray(c, np.float64) for g in placed for c in g.contours or ()]
    color = prim.attributes["color"]
    if strokes:
        device.stroke(strokes, False, {"color": color, "style": THIN})
    if contours:
        device.fill(contours, {"color": color, "rule": "nonzero", "style": None})
    return strokes + contours
