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

import numpy as np

from .. import clip
from .primitives import THIN


def glyphs(prim):
    """The placed glyphs of a text primitive in device coordinates."""
    from .. import text

    g, a = prim.geometry, prim.attributes
    frame = g["frame"]
    height = float(np.hypot(*frame[:, 1]))
    angle = math.atan2(frame[1, 0], frame[0, 0])
    x, y = g["anchor"]
    return text.layout(g["string"], float(x), float(y), font=a["font"], height=height,
                       expansion=a["expansion"], spacing=a["spacing"], angle=angle,
                       path=a["path"], align=a["align"])


def draw(prim, window, device):
    """Draw a text primitive clipped to ``window`` by :func:`scanline.clip.text`;
    return the point arrays drawn."""
    placed = clip.text(glyphs(prim), window, prim.attributes["clip"])
    strokes = [np.asarray(s, np.float64) for g in placed for s in g.strokes or ()]
    contours = [np.asarray(c, np.float64) for g in placed for c in g.contours or ()]
    color = prim.attributes["color"]
    if strokes:
        device.stroke(strokes, False, {"color": color, "style": THIN})
    if contours:
        device.fill(contours, {"color": color, "rule": "nonzero", "style": None})
    return strokes + contours
