"""Step tables: each algorithm run step by step, as the notes tabulate it.

Each function returns a :class:`Table`: ``print(table)`` shows it, ``table.rows`` is a
list of dicts keyed by the notes' column names (``k``, ``p``, ``x``, ``y`` ...),
``table.to_json()`` and ``table.to_csv()`` export it, and ``table.pixels()`` is the set
of pixels the algorithm plots, the same set :mod:`scanline.draw` draws.

The command line gives the same tables: ``scanline trace bresenham 20 10 30 18``.
"""

from .table import Table
from .lines import bresenham, dda
from .conics import midpoint_circle, midpoint_ellipse
from .seedfill import boundary_fill, flood_fill
from .polygon import scan_line_fill
from .curves import de_casteljau, cox_de_boor
from .clip import cohen_sutherland, cyrus_beck, liang_barsky, sutherland_hodgman
from .clip3d import cohen_sutherland_3d, liang_barsky_3d
from .zbuffer import z_buffer
from .visible import depth_sort, floating_horizon
from .raytracing import ray_tracing
from .backface import back_face
from .shading import gouraud, phong
from .bsp import bsp_tree
from .subdivision import warnock
from .scanline_method import scan_line_method
from .raycasting import ray_casting
from .animation import inbetweens, morph_equalize

#: CLI name -> function
ALGORITHMS = {
    "bresenham": bresenham,
    "dda": dda,
    "midpoint-circle": midpoint_circle,
    "midpoint-ellipse": midpoint_ellipse,
    "flood-fill": flood_fill,
    "boundary-fill": boundary_fill,
    "scan-line-fill": scan_line_fill,
    "de-casteljau": de_casteljau,
    "cox-de-boor": cox_de_boor,
    "cohen-sutherland": cohen_sutherland,
    "liang-barsky": liang_barsky,
    "cyrus-beck": cyrus_beck,
    "sutherland-hodgman": sutherland_hodgman,
    "cohen-sutherland-3d": cohen_sutherland_3d,
    "liang-barsky-3d": liang_barsky_3d,
    "z-buffer": z_buffer,
    "depth-sort": depth_sort,
    "floating-horizon": floating_horizon,
    "ray-tracing": ray_tracing,
    "back-face": back_face,
    "gouraud": gouraud,
    "phong": phong,
    "bsp-tree": bsp_tree,
    "warnock": warnock,
    "scan-line-visible": scan_line_method,
    "ray-casting": ray_casting,
    "inbetween-spacing": inbetweens,
    "morph-equalize": morph_equalize,
}

__all__ = ["Table", "bresenham", "dda", "midpoint_circle", "midpoint_ellipse", "flood_fill",
           "boundary_fill", "scan_line_fill", "sutherland_hodgman", "de_casteljau", "cox_de_boor",
           "cohen_sutherland", "liang_barsky", "cyrus_beck",
           "cohen_sutherland_3d", "liang_barsky_3d", "z_buffer", "depth_sort",
           "floating_horizon", "ray_tracing", "back_face", "gouraud", "phong",
           "bsp_tree", "warnock", "scan_line_method", "ray_casting",
           "inbetweens", "morph_equalize",
           "ALGORITHMS"]
