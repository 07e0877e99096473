"""Text clipping (notes, chapter 4, Q.1 "text clipping"; Hearn & Baker, section 6-11):
all-or-none string, all-or-none character, and clipping each character's strokes,
outline or pixels."""

import copy
from typing import TYPE_CHECKING, Literal, Sequence

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError
from . import window as w
from .lines import polyline
from .polygons import polygon

if TYPE_CHECKING:
    from ..text.layout import PlacedGlyph

MODES = ("string", "character", "stroke", "pixel")


def _inside(box: tuple[float, float, float, float], ring: NDArray[np.float64]) -> bool:
    """Whether the rectangle ``box`` lies in the convex counterclockwise ``ring``."""
    x0, y0, x1, y1 = box
    return bool(w.contains(ring, np.array([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])).all())


def _pixel_mask(glyph: "PlacedGlyph", ring: NDArray[np.float64]
                ) -> tuple[NDArray[np.bool_], tuple[int, int]]:
    """``(mask, (x0, y0))``: the glyph's pixels whose centers are inside the window, in
    an image whose bottom-left pixel is (x0, y0).  A stroke glyph is rasterized only
    where the window's bounding box meets it (a glyph scaled far beyond the window
    costs no more than the window); only its set pixels' centers are tested."""
    if glyph.strokes is not None:
        from ..text.glyphcache import stroke_bitmap
        box = (*ring.min(0).tolist(), *ring.max(0).tolist())
        mask, (x0, y0) = stroke_bitmap(glyph.strokes, within=box)
    else:
        mask = np.asarray(glyph.bitmap, bool)
        x0, y0 = glyph.bitmap_origin
    rows, cols = np.nonzero(mask)
    centers = np.column_stack([x0 + cols, y0 + (mask.shape[0] - 1 - rows)]).astype(float)
    kept = np.zeros_like(mask)
    kept[rows, cols] = w.contains(ring, centers)
    return kept, (x0, y0)


def text(glyphs: Sequence["PlacedGlyph"], window: w.WindowLike,
         mode: Literal["string", "character", "stroke", "pixel"] = "character"
         ) -> list["PlacedGlyph"]:
    """Clip placed text by a window.

    Parameters
    ----------
    glyphs : list of PlacedGlyph
        The characters placed by :func:`scanline.text.layout`.
    window : (xmin, ymin, xmax, ymax) or convex polygon
        The closed window.
    mode : {"string", "character", "stroke", "pixel"}
        The strategy:

        - ``"string"``: all-or-none string clipping: every glyph if the whole
          string (the union of the character bodies, ``glyph.cell``) is inside the
          window, none otherwise.
        - ``"character"``: all-or-none character clipping: the glyphs whose body
          is inside the window.
        - ``"stroke"``: each character's geometry clipped: the strokes of a stroke
          font (polyline clipping, Liang-Barsky), the contours of an outline or
          bitmap font (Sutherland-Hodgman, contour by contour: fill the result with
          the nonzero rule, as the glyph).
        - ``"pixel"``: each character's pixels (``glyph.bitmap``) kept where the
          pixel center is inside the window.

    Returns
    -------
    list of PlacedGlyph
        The kept glyphs, in order; glyphs with nothing left are dropped.  In modes
        ``"stroke"`` and ``"pixel"`` they are copies whose ``strokes`` /
        ``contours`` (mode ``"stroke"``), ``bitmap`` (both modes: the pixels whose
        centers are inside) and ``box`` hold the clipped geometry.

    Raises
    ------
    TypeError
        ``glyphs`` is not the list :func:`scanline.text.layout` returns.
    ValueError
        An unknown ``mode``, or a window that is degenerate or not convex.

    Notes
    -----
    Notes, chapter 4, Q.1 lists text clipping; the three strategies are Hearn &
    Baker's: all-or-none string (fast: one bounding-box test), all-or-none
    character, and clipping individual characters' components.  Blank glyphs
    (spaces) have no geometry: they are kept by "string" and "character" when
    their body is inside, and dropped by "stroke" and "pixel".

    Examples
    --------
    >>> import scanline as sl
    >>> glyphs = sl.text.layout("CLIP", 0, 0, font="bitmap")
    >>> [g.char for g in sl.clip.text(glyphs, (0, -5, 15, 20))]
    ['C', 'L']
    >>> sl.clip.text(glyphs, (0, -5, 15, 20), mode="string")
    []
    >>> [g.char for g in sl.clip.text(glyphs, (0, -5, 15, 20), mode="stroke")]
    ['C', 'L', 'I']
    """
    chosen = v.choice("mode", mode, MODES)
    if not isinstance(glyphs, (list, tuple)) or not all(
            hasattr(g, "cell") and hasattr(g, "char") for g in glyphs):
        raise ArgumentTypeError(
            f"glyphs must be the list that sl.text.layout(...) returns, got {v._show(glyphs)}")
    ring = w.polygon(window, convex=True, algorithm="text clipping")
    if chosen == "string":
        return list(glyphs) if all(_inside(g.cell, ring) for g in glyphs) else []
    if chosen == "character":
        return [g for g in glyphs if _inside(g.cell, ring)]
    out: list["PlacedGlyph"] = []
    for g in glyphs:
        if g.box is None:
            continue
        c = copy.copy(g)
        if chosen == "pixel":
            mask, (x0, y0) = _pixel_mask(g, ring)
            if not mask.any():
                continue
            c._bitmap = (mask, (x0, y0))
            rows, cols = np.nonzero(mask)
            top = y0 + mask.shape[0] - 1
            c.box = (float(x0 + cols.min()), float(top - rows.max()),
                     float(x0 + cols.max()), float(top - rows.min()))
            out.append(c)
            continue
        if g.strokes is not None:
            parts = [p for s in g.strokes for p in polyline(s, ring, method="cyrus-beck")]
            c.strokes = parts
        else:
            parts = [p for contour in g.contours for p in polygon(contour, ring)]
            c.contours = parts
        if not parts:
            continue
        allpts = np.vstack(parts)
        c.box = tuple(np.concatenate([allpts.min(0), allpts.max(0)]).tolist())
        c._bitmap = _pixel_mask(g, ring)
        out.append(c)
    return out
