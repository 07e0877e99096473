"""Fractal-geometry methods (Hearn & Baker, sections 10-18 and 10-19).

- fractal dimension by box counting: :func:`dimension`, :func:`box_counts`;
- deterministic self-similar curves from a generator: :func:`self_similar`,
  :func:`koch`, :func:`dragon`;
- shape grammars and L-systems with a turtle: :class:`LSystem`, :func:`turtle`,
  :func:`hilbert`, :func:`plant`, :data:`~scanline.fractals.lsystem.EXAMPLES`;
- random fractals for terrain: :func:`midpoint_profile`,
  :func:`midpoint_displacement` (Fournier, Fussell & Carpenter 1982),
  :func:`fbm_surface` (spectral synthesis), :func:`height_field`, :func:`terrain`;
- self-squaring fractals: :func:`mandelbrot`, :func:`julia` (compiled escape-time
  kernels, rows in parallel) and :func:`colorize` through a color table;
- affine fractals by iterated function systems: :func:`ifs`, :func:`fern`.

Curves come back as polylines ((N, 2) arrays) for :func:`scanline.draw.polyline`,
surfaces as :class:`~scanline.mesh.Mesh`, the escape-time sets as iteration counts
in image order.  Recursion depths and iteration counts past
:mod:`scanline.fractals.limits` (time) or the memory budget are refused up front.

>>> import scanline as sl
>>> sl.fractals.mandelbrot(1, 1, center=(-1, 0), span=1e-9, max_iterations=100).item()
100
"""

from .curves import DRAGON, KOCH, dragon, koch, self_similar
from .dimension import BoxCounts, box_counts, dimension
from .ifs import FERN, fern, ifs
from .lsystem import EXAMPLES, LSystem, example, hilbert, plant, turtle
from .self_squaring import colorize, default_table, julia, mandelbrot
from .terrain import fbm_surface, height_field, midpoint_displacement, midpoint_profile, terrain

__all__ = ["BoxCounts", "DRAGON", "EXAMPLES", "FERN", "KOCH", "LSystem", "box_counts",
           "colorize", "default_table", "dimension", "dragon", "example", "fbm_surface",
           "fern", "height_field", "hilbert", "ifs", "julia", "koch", "mandelbrot",
           "midpoint_displacement", "midpoint_profile", "plant", "self_similar", "terrain",
           "turtle"]
