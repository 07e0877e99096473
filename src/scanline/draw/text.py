"""Drawing text: ``text`` (notes, syllabus: "Character generation"; Hearn & Baker,
sections 3-14 and 4-5)."""

import numpy as np

from .. import _validate as v
from .._kernels._jit import call
from .._kernels.text import stamp_glyphs, stamp_line
from .._kernels.variants import layout
from ..color.spec import rgba
from ..text import glyphcache
from ..text.layout import codes_of, line_setup, place
from ..text.style import resolve
from ._common import target


_ALPHAS = {}

#: ``sl.draw.text``'s memo: attribute keywords -> [style, resolved style, (LineSetup,
#: glyph images) or False]; cleared when it grows past ``glyphcache.MAX_SIZES``.
_MEMO = {}

_REAL = (int, float)


def _alpha(color):
    """The color's alpha (0..255); integers (gray levels, bits, indices) are opaque."""
    if isinstance(color, (int, np.integer)):
        return 255
    if type(color) is str:
        if color not in _ALPHAS:
            _ALPHAS[color] = rgba(color)[3]
        return _ALPHAS[color]
    return rgba(color)[3]


def _visible(fb, p):
    """Glyph ids and origins of the characters that can touch the frame buffer (the
    others are dropped, which also keeps far-away geometry in the coordinate range)."""
    reach = 1.5 * p.font.reach * max(p.sx, p.sy) + 1
    keep = ((p.ox >= -reach) & (p.ox <= fb.width + reach)
            & (p.oy >= -reach) & (p.oy <= fb.height + reach))
    return p.gids[keep], p.ox[keep], p.oy[keep]


def _strokes(fb, p, color, antialias):
    """Stroke font: every stroke segment of every character in one batch of lines."""
    font = p.font
    gids, ox, oy = _visible(fb, p)
    counts = font.first[gids + 1] - font.first[gids]
    if counts.sum() == 0:
        return
    rows = (np.repeat(font.first[gids] - (np.cumsum(counts) - counts), counts)
            + np.arange(int(counts.sum())))
    segs = font.segments[rows]
    origin = np.repeat(np.column_stack([ox, oy]).astype(float), counts, axis=0)
    m = p.matrix
    a = segs[:, :2] @ m.T + origin
    b = segs[:, 2:] @ m.T + origin
    if antialias:
        from . import antialias as aa
        aa.lines(fb, np.hstack([a, b]), color)
    else:
        from .lines import lines
        lines(fb, np.hstack([a, b]), color=color)


def _filled(fb, p, color, value, antialias):
    """Outline and bitmap fonts: stamp cached glyph images, or fill the contours of
    glyphs too large to cache."""
    cache = glyphcache.images(p.font, p.matrix, antialias, p.tolerance)
    if cache is None:
        shapes = []
        gids, ox, oy = _visible(fb, p)
        for k, gid in enumerate(gids.tolist()):
            contours = glyphcache.device_contours(p.font, gid, p.matrix, p.tolerance)
            if contours:
                shapes.append([c + (ox[k], oy[k]) for c in contours])
        if not shapes:
            return
        if antialias:
            from . import antialias as aa
            aa.fills(fb, shapes, color, "nonzero")
        else:
            from .polygon import polygons
            polygons(fb, shapes, color=color, rule="nonzero")
        return
    mids = cache.ensure(p.gids)
    buf, packed = fb._raster()
    alpha = _alpha(color)
    call(stamp_glyphs, lambda: _glyph_work(cache.masks, len(mids)), buf, layout(packed),
         fb.width, fb.height, cache.atlas, cache.masks, cache.runs, mids, p.ox, p.oy, value,
         alpha, fb.mode == "P", alpha == 255 and not antialias)


def _line(fb, raster, x, y, text, fast, color, value, antialias):
    """Draw one line of upright text (no newline) with one compiled call; False
    when it must be placed the general way (a glyph not cached yet, a code point
    beyond the font's table), with nothing drawn."""
    setup, cache = fast
    buf, packed, width, height = raster
    alpha = _alpha(color)
    font = setup.font
    return call(stamp_line, lambda: _glyph_work(cache.masks, len(text)), buf, layout(packed),
                width, height, cache.atlas, cache.masks, cache.runs, cache.mask_of,
                font._table, font.advances, codes_of(text), float(x), float(y), setup.params,
                value, alpha, fb.mode == "P", alpha == 255 and not antialias) == 0


def _glyph_work(masks, n):
    """Work units of stamping ``n`` glyphs: each at most the largest cached mask."""
    return n * (1 + (int((masks[:, 1] * masks[:, 2]).max()) if len(masks) else 0))


def _fast(style):
    """``(LineSetup, glyph images)`` for the one-call path of a resolved style, or
    False (rotated text, paths up and down, the stroke font, uncached sizes)."""
    setup = line_setup(style)
    if setup is None or setup.font.kind == "stroke":
        return False
    cache = glyphcache.images(setup.font, setup.matrix, style.antialias, setup.tolerance)
    return False if cache is None else (setup, cache)


def text(fb, x, y, text, color=None, font=None, height=None, expansion=None, spacing=None,
         angle=None, up=None, path=None, align=None, antialias=None, style=None):
    """Draw a string.

    Parameters
    ----------
    fb : FrameBuffer
    x, y : float
        The reference point (device coordinates) that ``align`` places the text on;
        with the default alignment, the left end of the baseline.
    text : str
        Newlines start new lines (new columns for paths up and down).  Characters
        the font lacks are drawn as a box.
    color : color, optional
        Default: the style's color, else the frame buffer's ``foreground``.  A translucent color is
        composited over the frame buffer.
    font : {"sans", "bitmap", "stroke"}, path, family name or Font, optional
        Default ``"sans"`` (DejaVu Sans, also by its family name ``"DejaVu Sans"``);
        an installed font by its family name, ``"DejaVu Serif"``, found by
        fontconfig or matplotlib (:mod:`scanline.text.system`).
    height, expansion, spacing, angle, up, path, align, antialias
        The text attributes, see :class:`scanline.TextStyle`.  ``height`` is the cap
        height in pixels; ``spacing`` a fraction of it; ``angle`` radians.
    style : TextStyle, optional
        Attributes not given as keywords come from it.

    Notes
    -----
    Character generation as in the notes' syllabus and Hearn & Baker, section 3-14:
    a bitmap font's dots are replicated (or stamped as squares); a stroke font's
    polylines are drawn with :func:`scanline.draw.lines` (Wu lines when
    antialiased); an outline font's contours are flattened
    (:mod:`scanline.geometry.flatten`) and filled by the scan-line fill with the
    nonzero rule (antialiased: :func:`scanline.draw.antialias.fill`).  Each
    character's image is made once per font, size and orientation and then
    stamped (:mod:`scanline.text.glyphcache`).  In mode "1" and "P" an antialiased
    pixel is set where the coverage is at least one half.

    References
    ----------
    D. Hearn, M. P. Baker, "Computer Graphics", 2nd ed., Prentice Hall, 1994,
    sections 3-14 (character generation) and 4-5 (character attributes).
    ISO 7942, "Graphical Kernel System (GKS)", 1985: text path, alignment, character
    height, up vector, expansion factor and spacing.
    A. V. Hershey, "Calligraphy for computer display", NWL Report 2101, 1967.
    T. Porter, T. Duff, "Compositing digital images", SIGGRAPH '84, 1984.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(12, 8, mode="1")
    >>> sl.draw.text(fb, 0, 0, "Hi", font="bitmap")
    >>> print(sl.text_image(fb))
    #---#---#---
    #---#-------
    #---#--##---
    #####---#---
    #---#---#---
    #---#---#---
    #---#--###--
    ------------

    The baseline runs through the centers of row ``y``: pixel centers exactly on a
    glyph's bottom edge are outside (the fill's top-left rule), so the letters
    start on row ``y + 1`` and the first row of descenders is row ``y`` itself.
    """
    try:  # (types too: True == 1 and 1.0 == 1, but only one of each pair is valid)
        key = (id(style), font, height, expansion, spacing, angle, up, path, align,
               antialias, type(height), type(expansion), type(spacing), type(angle),
               type(antialias))
        memo = _MEMO.get(key)
    except TypeError:  # an unhashable attribute (a list as align): no memo
        key = memo = None
    if memo is None or memo[0] is not style:
        memo = [style, resolve(style, font=font, height=height, expansion=expansion,
                               spacing=spacing, angle=angle, up=up, path=path, align=align,
                               antialias=antialias), None]
        if key is not None:
            if len(_MEMO) >= glyphcache.MAX_SIZES:
                _MEMO.clear()
            _MEMO[key] = memo
    st = memo[1]
    raster = target(fb)
    color = color if color is not None else st.color if st.color is not None else fb.foreground
    value = fb.pixel(color)
    if memo[2] is None:
        memo[2] = _fast(st)
    if (memo[2] and type(text) is str and "\n" not in text and type(x) in _REAL
            and type(y) in _REAL and -v.COORD_LIMIT <= x <= v.COORD_LIMIT
            and -v.COORD_LIMIT <= y <= v.COORD_LIMIT):
        if _line(fb, raster, x, y, text, memo[2], color, value, st.antialias):
            return
        memo[2] = None  # the general path may render into a newer cache of the size
    p = place(text, x, y, st)
    if len(p.gids) == 0:
        return
    if p.font.kind == "stroke":
        _strokes(fb, p, color, st.antialias)
    else:
        _filled(fb, p, color, value, st.antialias)
