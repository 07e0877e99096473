"""Drawing text: ``text`` (notes, syllabus: "Character generation"; Hearn & Baker,
sections 3-14 and 4-5)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Dict, Literal, Optional, Tuple, Union, cast

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .._kernels._jit import call
from .._kernels.text import stamp_glyphs, stamp_line
from .._kernels.variants import layout
from ..color.spec import rgba
from ..text import glyphcache
from ..text.layout import codes_of, line_setup, place
from ..text.style import resolve
from ._common import target

if TYPE_CHECKING:
    from .._typing import Angle, Color
    from ..framebuffer import FrameBuffer
    from ..text.glyphcache import GlyphImages
    from ..text.layout import LineSetup, Placement
    from ..text.style import Align, FontSpec, TextStyle

#: What the one-call path of a resolved style needs (:func:`_fast`), or False.
_Fast = Union[Tuple["LineSetup", "GlyphImages"], Literal[False]]


class _Memo:
    """One entry of :data:`_MEMO`: the style given, the resolved style and its
    :data:`_Fast` (None: not worked out yet)."""

    __slots__ = ("style", "resolved", "fast")

    def __init__(self, style: Optional[TextStyle], resolved: TextStyle) -> None:
        self.style = style
        self.resolved = resolved
        self.fast: Optional[_Fast] = None


_ALPHAS: Dict[str, int] = {}

#: ``sl.draw.text``'s memo: attribute keywords -> :class:`_Memo`; cleared when it
#: grows past ``glyphcache.MAX_SIZES``.
_MEMO: Dict[Tuple[Any, ...], _Memo] = {}

_REAL = (int, float)


def _alpha(color: Color) -> int:
    """The color's alpha (0..255); integers (gray levels, bits, indices) are opaque."""
    if isinstance(color, (int, np.integer)):
        return 255
    if type(color) is str:
        if color not in _ALPHAS:
            _ALPHAS[color] = rgba(color)[3]
        return _ALPHAS[color]
    return rgba(color)[3]


def _visible(fb: FrameBuffer, p: Placement
             ) -> Tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.int64]]:
    """Glyph ids and origins of the characters that can touch the frame buffer (the
    others are dropped, which also keeps far-away geometry in the coordinate range)."""
    reach = 1.5 * p.font.reach * max(p.sx, p.sy) + 1
    keep = ((p.ox >= -reach) & (p.ox <= fb.width + reach)
            & (p.oy >= -reach) & (p.oy <= fb.height + reach))
    return p.gids[keep], p.ox[keep], p.oy[keep]


def _strokes(fb: FrameBuffer, p: Placement, color: Color, antialias: bool) -> None:
    """Stroke font: every stroke segment of every character in one batch of lines."""
    from ..text.stroke import StrokeFont     # loaded already: ``font`` is one

    font = p.font
    assert isinstance(font, StrokeFont)     # the caller checked its kind
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


def _filled(fb: FrameBuffer, p: Placement, color: Color, value: NDArray[np.uint8],
            antialias: bool) -> None:
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


def _line(fb: FrameBuffer, raster: Tuple[NDArray[np.uint8], bool, int, int], x: float,
          y: float, text: str, fast: Tuple[LineSetup, GlyphImages], color: Color,
          value: NDArray[np.uint8], antialias: bool) -> bool:
    """Draw one line of upright text (no newline) with one compiled call; False
    when it must be placed the general way (a glyph not cached yet, a code point
    beyond the font's table), with nothing drawn."""
    setup, cache = fast
    buf, packed, width, height = raster
    alpha = _alpha(color)
    font = setup.font
    return cast(int, call(stamp_line, lambda: _glyph_work(cache.masks, len(text)), buf, layout(packed),
                width, height, cache.atlas, cache.masks, cache.runs, cache.mask_of,
                font._table, font.advances, codes_of(text), float(x), float(y), setup.params,
                value, alpha, fb.mode == "P", alpha == 255 and not antialias)) == 0


def _glyph_work(masks: NDArray[np.int64], n: int) -> int:
    """Work units of stamping ``n`` glyphs: each at most the largest cached mask."""
    return n * (1 + (int((masks[:, 1] * masks[:, 2]).max()) if len(masks) else 0))


def _fast(style: TextStyle) -> _Fast:
    """``(LineSetup, glyph images)`` for the one-call path of a resolved style, or
    False (rotated text, paths up and down, the stroke font, uncached sizes)."""
    setup = line_setup(style)
    if setup is None or setup.font.kind == "stroke":
        return False
    cache = glyphcache.images(setup.font, setup.matrix, style.antialias, setup.tolerance)
    return False if cache is None else (setup, cache)


def text(fb: FrameBuffer, x: float, y: float, text: str, color: Optional[Color] = None,
         font: Optional[FontSpec] = None, height: Optional[float] = None,
         expansion: Optional[float] = None, spacing: Optional[float] = None,
         angle: Optional[Angle] = None, up: Optional[Tuple[float, float]] = None,
         path: Optional[Literal["right", "left", "up", "down"]] = None,
         align: Optional[Align] = None, antialias: Optional[bool] = None,
         style: Optional[TextStyle] = None) -> None:
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

    Raises
    ------
    ArgumentTypeError
        When ``fb`` is not a FrameBuffer, ``text`` not a str, ``style`` not a
        TextStyle, or an attribute of the wrong type.
    ArgumentValueError
        For an attribute value :class:`scanline.TextStyle` refuses, a font that is
        not found, a color that is not one, ``x`` or ``y`` not finite, a string over
        2**20 characters, or a glyph image larger than the memory allows.

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
    key: Optional[Tuple[Any, ...]]
    try:  # (types too: True == 1 and 1.0 == 1, but only one of each pair is valid)
        key = (id(style), font, height, expansion, spacing, angle, up, path, align,
               antialias, type(height), type(expansion), type(spacing), type(angle),
               type(antialias))
        memo = _MEMO.get(key)
    except TypeError:  # an unhashable attribute (a list as align): no memo
        key = memo = None
    if memo is None or memo.style is not style:
        memo = _Memo(style, resolve(style, font=font, height=height, expansion=expansion,
                                    spacing=spacing, angle=angle, up=up, path=path,
                                    align=align, antialias=antialias))
        if key is not None:
            if len(_MEMO) >= glyphcache.MAX_SIZES:
                _MEMO.clear()
            _MEMO[key] = memo
    st = memo.resolved
    raster = target(fb)
    color = color if color is not None else st.color if st.color is not None else fb.foreground
    value = fb.pixel(color)
    if memo.fast is None:
        memo.fast = _fast(st)
    if (memo.fast and type(text) is str and "\n" not in text and type(x) in _REAL
            and type(y) in _REAL and -v.COORD_LIMIT <= x <= v.COORD_LIMIT
            and -v.COORD_LIMIT <= y <= v.COORD_LIMIT):
        if _line(fb, raster, x, y, text, memo.fast, color, value, st.antialias):
            return
        memo.fast = None  # the general path may render into a newer cache of the size
    p = place(text, x, y, st)
    if len(p.gids) == 0:
        return
    if p.font.kind == "stroke":
        _strokes(fb, p, color, st.antialias)
    else:
        _filled(fb, p, color, value, st.antialias)
