"""Text primitives of the display file, drawn as glyph geometry.

The text is laid out by :func:`scanline.text.layout` in device coordinates; each
glyph's strokes (stroke font) or outline contours (outline font) go to the device, so
raster and vector output show the same characters.  Clipping follows the text
primitive's ``clip`` attribute (GKS text precision): ``"string"`` keeps the whole
string or nothing, ``"character"`` keeps the characters whose cells (character
bodies) lie inside, and
``"stroke"`` clips every stroke and outline to the rectangle.
"""

import math

import numpy as np

from . import pipeline
from .primitives import THIN


def _inside(box, window):
    """Whether a box (xmin, ymin, xmax, ymax) lies inside the window."""
    corners = np.array([(box[0], box[1]), (box[2], box[1]), (box[2], box[3]), (box[0], box[3])],
                       np.float64)
    return bool(pipeline.inside(corners, window).all())


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
    """Draw a text primitive clipped to ``window``; return the point arrays drawn."""
    placed = glyphs(prim)
    mode = prim.attributes["clip"]
    if mode == "string" and not all(_inside(gl.cell, window) for gl in placed):
        return []
    if mode == "character":
        placed = [gl for gl in placed if _inside(gl.cell, window)]
    color = prim.attributes["color"]
    strokes, contours = [], []
    for gl in placed:
        for s in getattr(gl, "strokes", None) or ():
            strokes.extend(pipeline.polylines(np.asarray(s, np.float64), False, window)[0])
        cs = [np.asarray(c, np.float64) for c in getattr(gl, "contours", None) or ()]
        if cs:
            contours.extend(pipeline.contours(cs, window))
    if strokes:
        device.stroke(strokes, False, {"color": color, "style": THIN})
    if contours:
        device.fill(contours, {"color": color, "rule": "nonzero", "style": None})
    return strokes + contours
