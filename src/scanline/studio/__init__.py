"""The studio: a local web application to step through the algorithms, watch the
display devices of chapter 1 and use the logical input devices on a live display
file (``scanline studio``), and the single-file explorer pages of ``scanline
explain``.

Everything the pages show comes from the public API on the server
(:mod:`scanline.trace`, :mod:`scanline.display`); the pages' JavaScript draws and
sends input, it never runs an algorithm.
"""
