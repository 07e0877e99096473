"""Character generation and text attributes (notes, syllabus: "Character
generation", "Character attributes. Text attributes"; Hearn & Baker, sections 3-14
and 4-5).

Three kinds of font (:mod:`scanline.text.catalog`): a dot-matrix ``"bitmap"`` font, a
vector ``"stroke"`` font and outline fonts read from TrueType/OpenType files
(``"sans"``, DejaVu Sans, ships with scanline), by path or by the family name of an
installed font (:mod:`scanline.text.system`: ``font="DejaVu Serif"``).  :class:`TextStyle` holds the text
attributes; :func:`layout` and :func:`extents` place text without drawing it;
:func:`scanline.draw.text` draws it.
"""

from .catalog import Font, font, fonts, load_font
from .layout import Extents, PlacedGlyph, extents, layout
from .style import TextStyle
from .system import families, find_font

__all__ = ["Font", "TextStyle", "Extents", "PlacedGlyph", "extents", "families", "find_font",
           "font", "fonts", "layout", "load_font"]
