"""Raster animation (notes, chapter 6, Q3; Hearn & Baker §16-3): block transfers with
the 16 raster operations, the xor sprite, rotation of pixel blocks with area coverage,
and color-table animation.

>>> import scanline as sl
>>> sl.raster.OPS[:4]
('clear', 'and', 'and-reverse', 'copy')
"""

from .bitblt import ALIASES, OPS, XorSprite, apply_op, bitblt, op_code
from .colortable import ColorTableAnimation
from .rotate import rotate_block

__all__ = ["ALIASES", "OPS", "ColorTableAnimation", "XorSprite", "apply_op", "bitblt",
           "op_code", "rotate_block"]
