"""numba-compiled kernels: arrays and scalars in, arrays out.

Kernels never import from the layers above, raise nothing, hold no globals and write
only inside the arrays they are given: every pixel write goes through
:func:`scanline._kernels.raster.put`, which checks the bounds.  This package is
imported lazily (``import scanline`` does not import numba).
"""
